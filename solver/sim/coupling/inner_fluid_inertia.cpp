// Inner-fluid inertia, docs/method.md §1.7 variant K (Reynolds-transport form) and variant A.
#include "sim/coupling/inner_fluid_inertia.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "fluid/threads.hpp"

namespace ibms {
namespace {

// I_T = sum over the triangle's cells of area * u [length^3/time per unit depth].
Vec2 triangle_momentum(const std::vector<CellOverlap>& cells, const FluidState& fluid) {
  Vec2 momentum{0.0, 0.0};
  for (const CellOverlap& o : cells) {
    momentum[0] += o.area * fluid.velocity_x(o.i, o.j);
    momentum[1] += o.area * fluid.velocity_y(o.i, o.j);
  }
  return momentum;
}

// Offset of a cell centre from `centre` along one direction, the nearest periodic image.
double offset_from(double cell_centre, double centre, double length, bool periodic) {
  double r = cell_centre - centre;
  if (periodic) r -= length * std::round(r / length);
  return r;
}

// sum over the triangle's cells of area (x_ij - centre) x u_ij [length^4/time per unit depth].
double triangle_angular_momentum(const Grid& grid, const std::vector<CellOverlap>& cells,
                                 const FluidState& fluid, const Vec2& centre) {
  double moment = 0.0;
  for (const CellOverlap& o : cells) {
    const double rx = offset_from(grid.x_centre(o.i), centre[0], grid.length_x, grid.periodic_x);
    const double ry = offset_from(grid.y_centre(o.j), centre[1], grid.length_y, grid.periodic_y);
    moment += o.area * (rx * fluid.velocity_y(o.i, o.j) - ry * fluid.velocity_x(o.i, o.j));
  }
  return moment;
}

// A body whose points move together (rigid, prescribed) takes its rim polygon as one region.
bool whole_polygon(const MassSpringBody& body) { return body.kind != BodyKind::mass_spring; }

// Cells of each fan triangle (c, l, l+1) at the body's current positions; of the rim polygon, in
// triangle_cells[0], for a body whose points move together.
void locate_triangles(const Grid& grid, const MassSpringBody& body, BodyCoupling& c) {
  if (whole_polygon(body)) {
    c.triangle_cells[0].clear();
    add_polygon_cell_overlaps(grid, body.position.data(), static_cast<std::size_t>(body.n_surface),
                              c.triangle_cells[0], c.polygon_work);
    return;
  }
  const Vec2& centre = body.position[body.centre_index()];
  for (int l = 0; l < body.n_surface; ++l) {
    c.triangle_cells[l].clear();  // keeps its capacity: no allocation after the first steps
    add_triangle_cell_overlaps(grid, centre, body.position[l], body.position[(l + 1) % body.n_surface],
                               c.triangle_cells[l]);
  }
}

}  // namespace

void sample_inner_fluid_momentum(const Grid& grid, const FluidState& fluid,
                                 const std::vector<MassSpringBody>& bodies,
                                 std::vector<BodyCoupling>& coupling) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    BodyCoupling& c = coupling[b];
    locate_triangles(grid, bodies[b], c);
    // Room for the triangles' cells as the body moves and turns (their count changes by a few
    // cells), so that the step loop does not reallocate them.
    for (auto& cells : c.triangle_cells) cells.reserve(2 * cells.size() + 16);
    for (auto* v : {&c.polygon_work.partial, &c.polygon_work.full}) v->reserve(2 * v->size() + 64);
    c.inner_reference_centre = bodies[b].position[bodies[b].centre_index()];
    c.inner_angular_momentum = 0.0;
    const int regions = whole_polygon(bodies[b]) ? 1 : bodies[b].n_surface;
    for (Vec2& m : c.triangle_momentum) m = {0.0, 0.0};
    for (int l = 0; l < regions; ++l) {
      c.triangle_momentum[l] = triangle_momentum(c.triangle_cells[l], fluid);
      c.inner_angular_momentum +=
          triangle_angular_momentum(grid, c.triangle_cells[l], fluid, c.inner_reference_centre);
    }
  }
}

void kempe_inner_fluid_inertia(const Grid& grid, double fluid_density, const FluidState& fluid,
                               const std::vector<MassSpringBody>& bodies, double dt,
                               std::vector<BodyCoupling>& coupling) {
  // Body by body on the loop threads: each writes only its own arrays.
  for_each_body(bodies.size(), [&](std::size_t b) {
    const MassSpringBody& body = bodies[b];
    BodyCoupling& c = coupling[b];
    locate_triangles(grid, body, c);  // region at X^n
    for (Vec2& f : c.inner_fluid_force) f = {0.0, 0.0};
    // Torque about the centre X_c^n held fixed over the step: rho_f (L^{n+1} - L^n) / dt with both
    // moments about X_c^n; the stored L^n is about X_ref = X_c^{n-1}, and moving the point by
    // dX = X_c^n - X_ref changes it by -dX x I^n (I^n = sum_T I_T of the stored triangles).
    const Vec2& x_c = body.position[body.centre_index()];
    Vec2 momentum_n{0.0, 0.0};
    for (const Vec2& m : c.triangle_momentum)
      for (int d = 0; d < 2; ++d) momentum_n[d] += m[d];
    const double shift_x = x_c[0] - c.inner_reference_centre[0], shift_y = x_c[1] - c.inner_reference_centre[1];
    const double angular_n = c.inner_angular_momentum - (shift_x * momentum_n[1] - shift_y * momentum_n[0]);
    double angular_np1 = 0.0;
    if (whole_polygon(body)) {  // one region: its force on the centre point (a sum is all the body takes)
      const Vec2 momentum_np1 = triangle_momentum(c.triangle_cells[0], fluid);
      angular_np1 = triangle_angular_momentum(grid, c.triangle_cells[0], fluid, x_c);
      for (int d = 0; d < 2; ++d)
        c.inner_fluid_force[body.centre_index()][d] = fluid_density * (momentum_np1[d] - momentum_n[d]) / dt;
      for (Vec2& m : c.triangle_momentum) m = {0.0, 0.0};
      c.triangle_momentum[0] = momentum_np1;
    }
    for (int l = 0; l < (whole_polygon(body) ? 0 : body.n_surface); ++l) {
      const Vec2 momentum_np1 = triangle_momentum(c.triangle_cells[l], fluid);  // I_T(X^n, u^{n+1})
      angular_np1 += triangle_angular_momentum(grid, c.triangle_cells[l], fluid, x_c);
      // docs/method.md §1.7 step 3 (Reynolds-transport form) and step 4 (a third to each vertex).
      const int vertex[3] = {body.centre_index(), l, (l + 1) % body.n_surface};
      for (int d = 0; d < 2; ++d) {
        const double force = fluid_density * (momentum_np1[d] - c.triangle_momentum[l][d]) / dt;
        for (int v : vertex) c.inner_fluid_force[v][d] += force / 3.0;
      }
      c.triangle_momentum[l] = momentum_np1;
    }
    c.inner_fluid_torque = fluid_density * (angular_np1 - angular_n) / dt;
    c.inner_angular_momentum = angular_np1;
    c.inner_reference_centre = x_c;
  });
}

void kempe_inner_fluid_inertia_by_mass(const Grid& grid, double fluid_density, const FluidState& fluid,
                                       const std::vector<MassSpringBody>& bodies, double dt,
                                       std::vector<BodyCoupling>& coupling) {
  kempe_inner_fluid_inertia(grid, fluid_density, fluid, bodies, dt, coupling);
  for_each_body(bodies.size(), [&](std::size_t b) {
    const MassSpringBody& body = bodies[b];
    if (whole_polygon(body)) return;  // all on the centre point already: its points move together
    BodyCoupling& c = coupling[b];
    // The body's force F = sum of the triangles' and its torque about X_c^n (rho_f dI/dt, rho_f dL/dt).
    Vec2 force{0.0, 0.0};
    for (int p = 0; p < body.n_points(); ++p)
      for (int d = 0; d < 2; ++d) force[d] += c.inner_fluid_force[p][d];
    const double mass = body.total_mass();
    const std::array<double, 2> x_g = ibms::centre_of_mass(body);
    // The load of a rigid motion: f_p = m_p (A + alpha z x r_p), r_p = x_p - x_G, with
    // M A = F and J_G alpha = T_G, the torque about the centre of mass x_G.
    const Vec2& x_c = body.position[body.centre_index()];
    const double torque = c.inner_fluid_torque + (x_c[0] - x_g[0]) * force[1] -
                          (x_c[1] - x_g[1]) * force[0];
    double inertia = 0.0;
    for (int p = 0; p < body.n_points(); ++p) {
      const double rx = body.position[p][0] - x_g[0], ry = body.position[p][1] - x_g[1];
      inertia += body.mass[p] * (rx * rx + ry * ry);
    }
    const double alpha = inertia > 0.0 ? torque / inertia : 0.0;
    for (int p = 0; p < body.n_points(); ++p) {
      const double rx = body.position[p][0] - x_g[0], ry = body.position[p][1] - x_g[1];
      c.inner_fluid_force[p][0] = body.mass[p] * (force[0] / mass - alpha * ry);
      c.inner_fluid_force[p][1] = body.mass[p] * (force[1] / mass + alpha * rx);
    }
  });
}

void no_inner_fluid_inertia(const Grid&, double, const FluidState&, const std::vector<MassSpringBody>&, double,
                            std::vector<BodyCoupling>& coupling) {
  for (BodyCoupling& c : coupling) {
    for (Vec2& f : c.inner_fluid_force) f = {0.0, 0.0};
    c.inner_fluid_torque = 0.0;
  }
}

InnerFluidInertia inner_fluid_inertia_of(IbmSpec::InnerFluidInertia variant) {
  switch (variant) {
    case IbmSpec::InnerFluidInertia::kempe: return &kempe_inner_fluid_inertia;
    case IbmSpec::InnerFluidInertia::none: return &no_inner_fluid_inertia;
    case IbmSpec::InnerFluidInertia::kempe_by_mass: return &kempe_inner_fluid_inertia_by_mass;
  }
  throw std::invalid_argument("unknown ibm.inner_fluid_inertia");
}

Vec2 inner_fluid_momentum(double fluid_density, const std::vector<BodyCoupling>& coupling) {
  Vec2 total{0.0, 0.0};
  for (const BodyCoupling& c : coupling)
    for (const Vec2& m : c.triangle_momentum)
      for (int d = 0; d < 2; ++d) total[d] += fluid_density * m[d];
  return total;
}

}  // namespace ibms
