// Inner-fluid inertia, METHOD.md §1.7 variant K (Reynolds-transport form) and variant A.
#include "sim/inner_fluid_inertia.hpp"

#include <stdexcept>
#include <string>

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

// Cells of each fan triangle (c, l, l+1) at the body's current positions.
void locate_triangles(const Grid& grid, const MassSpringBody& body, BodyCoupling& c) {
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
    locate_triangles(grid, bodies[b], coupling[b]);
    for (int l = 0; l < bodies[b].n_surface; ++l)
      coupling[b].triangle_momentum[l] = triangle_momentum(coupling[b].triangle_cells[l], fluid);
  }
}

void kempe_inner_fluid_inertia(const Grid& grid, double fluid_density, const FluidState& fluid,
                               const std::vector<MassSpringBody>& bodies, double dt,
                               std::vector<BodyCoupling>& coupling) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const MassSpringBody& body = bodies[b];
    BodyCoupling& c = coupling[b];
    locate_triangles(grid, body, c);  // region at X^n
    for (Vec2& f : c.inner_fluid_force) f = {0.0, 0.0};
    for (int l = 0; l < body.n_surface; ++l) {
      const Vec2 momentum_np1 = triangle_momentum(c.triangle_cells[l], fluid);  // I_T(X^n, u^{n+1})
      // METHOD.md §1.7 step 3 (Reynolds-transport form) and step 4 (a third to each vertex).
      const int vertex[3] = {body.centre_index(), l, (l + 1) % body.n_surface};
      for (int d = 0; d < 2; ++d) {
        const double force = fluid_density * (momentum_np1[d] - c.triangle_momentum[l][d]) / dt;
        for (int v : vertex) c.inner_fluid_force[v][d] += force / 3.0;
      }
      c.triangle_momentum[l] = momentum_np1;
    }
  }
}

void no_inner_fluid_inertia(const Grid&, double, const FluidState&, const std::vector<MassSpringBody>&, double,
                            std::vector<BodyCoupling>& coupling) {
  for (BodyCoupling& c : coupling)
    for (Vec2& f : c.inner_fluid_force) f = {0.0, 0.0};
}

InnerFluidInertia inner_fluid_inertia_from_name(const std::string& name) {
  if (name == "kempe") return &kempe_inner_fluid_inertia;
  if (name == "none") return &no_inner_fluid_inertia;
  throw std::invalid_argument("unknown ibm.inner_fluid_inertia '" + name + "' (kempe | none)");
}

Vec2 inner_fluid_momentum(double fluid_density, const std::vector<BodyCoupling>& coupling) {
  Vec2 total{0.0, 0.0};
  for (const BodyCoupling& c : coupling)
    for (const Vec2& m : c.triangle_momentum)
      for (int d = 0; d < 2; ++d) total[d] += fluid_density * m[d];
  return total;
}

}  // namespace ibms
