// Markers, direct forcing and fluid reaction of the bodies (see body_coupling.hpp).
#include "sim/coupling/body_coupling.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "fluid/threads.hpp"
#include "ibm/direct_forcing.hpp"
#include "ibm/marker_weights.hpp"

namespace ibms {

namespace {

// Marker arrays sized n (within the capacity reserved at construction).
void resize_markers(BodyCoupling& c, std::size_t n) {
  c.marker.resize(n);
  c.marker_edge.resize(n);
  c.marker_fraction.resize(n);
  c.marker_volume.resize(n);
  c.target_velocity.resize(n);
  c.interpolated_velocity.resize(n);
  c.pass_force.resize(n);
  c.pass_increment.resize(n);
  c.forcing_sum.resize(n);
}

// The face-to-cell mean A at cell (i, j), the one rule of average_faces_to_cells and
// cell_forces_from_faces: x from the faces i and i + 1, y from the faces j and j + 1.
inline double face_mean_x(const FaceField& face_x, int i, int j) { return 0.5 * (face_x(i, j) + face_x(i + 1, j)); }
inline double face_mean_y(const FaceField& face_y, int i, int j) { return 0.5 * (face_y(i, j) + face_y(i, j + 1)); }

// The value at marker l of a quantity given per body point (the point velocities, or their
// change): linear along the marker's rim edge, and, for a retracted marker, its part relative to
// the centre point scaled by the marker's radial factor (exact for a rigid motion and a dilation).
inline double marker_value(const std::vector<Vec2>& point, const Vec2& centre, const BodyCoupling& c, std::size_t l,
                           int n_rim, int d) {
  const double f = c.marker_fraction_work[l];
  const double rim = rim_to_marker(c, l, n_rim, point, d);
  return f == 1.0 ? rim : centre[d] + f * (rim - centre[d]);
}

}  // namespace

BodyCoupling::BodyCoupling(const MassSpringBody& body, std::size_t max_markers)
    : fluid_force(body.n_points()), inner_fluid_force(body.n_points()), external_force(body.n_points()),
      triangle_cells(body.n_surface), triangle_momentum(body.n_surface) {
  const std::size_t capacity = std::max<std::size_t>(max_markers, body.n_surface);
  for (auto* v : {&marker, &target_velocity, &interpolated_velocity, &pass_force, &pass_increment, &forcing_sum,
                  &previous_force})
    v->reserve(capacity);
  marker_edge.reserve(capacity);
  marker_fraction.reserve(capacity);
  marker_volume.reserve(capacity);
  marker_fraction_work.reserve(capacity);
  rigid_arm.reserve(capacity);
  resize_markers(*this, body.n_surface);
  for (int l = 0; l < body.n_surface; ++l) {
    marker_edge[l] = l;
    marker_fraction[l] = 0.0;
  }
}

std::size_t max_sub_marker_count(double diameter, int n_surface, double h) {
  // Edge of a regular n-gon inscribed in the diameter, with 50 % slack for deformation.
  const double edge = 1.5 * diameter * std::sin(pi / n_surface);
  return static_cast<std::size_t>(n_surface) * static_cast<std::size_t>(std::ceil(edge / h));
}

WallVelocities wall_velocities_at(const FluidBoundaries& boundaries, double time) {
  return {boundaries.left.at(time), boundaries.right.at(time), boundaries.bottom.at(time),
          boundaries.top.at(time)};
}

void prepare_markers(const std::vector<MassSpringBody>& bodies,
                     const std::vector<SwellingSchedule>& swelling, double time, double previous_dt,
                     const Grid& grid, bool sub_markers, std::vector<BodyCoupling>& coupling,
                     double retraction) {
  const double h = grid.dx();  // square cells (checked when the Simulation is built)
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const MassSpringBody& body = bodies[b];
    BodyCoupling& c = coupling[b];
    const int n_rim = body.n_surface;
    if (!sub_markers) {
      for (int l = 0; l < n_rim; ++l) c.marker[l] = body.position[l];
    } else {
      // docs/method.md §3.6: split each rim edge into ceil(|e|/h) pieces, so marker spacing <= h.
      // An edge longer than the reserved capacity allows (8 x the nominal swollen edge) means the
      // body has exploded (in a periodic box nothing else catches it before the size overflows).
      const double max_pieces = 8.0 * static_cast<double>(c.marker.capacity()) / n_rim;
      std::size_t n_markers = 0;
      for (int e = 0; e < n_rim; ++e) {
        const Vec2& a = body.position[e];
        const Vec2& z = body.position[(e + 1) % n_rim];
        const double pieces = std::ceil(std::hypot(z[0] - a[0], z[1] - a[1]) / h);
        if (!(pieces <= max_pieces))
          throw BlowUpError("body " + std::to_string(b) + ": rim edge " + std::to_string(e) + " stretched to " +
                            std::to_string(pieces) + " cells (sub-markers; more than 8x its swollen length)");
        n_markers += static_cast<std::size_t>(std::max(1.0, pieces));
      }
      resize_markers(c, n_markers);
      std::size_t m = 0;
      for (int e = 0; e < n_rim; ++e) {
        const Vec2& a = body.position[e];
        const Vec2& z = body.position[(e + 1) % n_rim];
        const int pieces = static_cast<int>(std::max(1.0, std::ceil(std::hypot(z[0] - a[0], z[1] - a[1]) / h)));
        for (int j = 0; j < pieces; ++j, ++m) {
          const double w = static_cast<double>(j) / pieces;
          c.marker_edge[m] = e;
          c.marker_fraction[m] = w;
          c.marker[m] = {rim_to_marker(c, m, n_rim, body.position, 0), rim_to_marker(c, m, n_rim, body.position, 1)};
        }
      }
    }
    const Vec2 x_c = centre_of_mass(body);
    std::vector<double>& radial_factor = c.marker_fraction_work;
    radial_factor.assign(c.marker.size(), 1.0);  // capacity reserved: no allocation after the first step
    if (retraction > 0.0)
      for (std::size_t l = 0; l < c.marker.size(); ++l) {
        const double rx = c.marker[l][0] - x_c[0], ry = c.marker[l][1] - x_c[1], r = std::hypot(rx, ry);
        if (!(r > retraction))
          throw BlowUpError("body " + std::to_string(b) + ": marker " + std::to_string(l) + " lies " + std::to_string(r) +
                            " from the centre, within ibm.marker_retraction's " + std::to_string(retraction));
        radial_factor[l] = (r - retraction) / r;
        c.marker[l] = {x_c[0] + radial_factor[l] * rx, x_c[1] + radial_factor[l] * ry};
      }
    marker_weights(c.marker, h, c.marker_volume);  // dV_l = h s_l, docs/method.md §3.6 (in place)
    // docs/method.md §1.8: the fluid is forced towards the marker velocity minus the swelling
    // part (s'/s)(X_l - X_c), so a swelling body absorbs fluid instead of pushing it away.
    // s'/s [1/time] over the step that produced U^n: the marker velocities at t^n are the end of
    // the previous step's sub-steps, so the dilation they carry is that step's, ln(s^n/s^{n-1})/dt^{n-1}
    // (the instantaneous rate at t^n would mismatch U^n by the full D'/2 at the schedule's kinks).
    const double growth = previous_dt > 0.0
        ? std::log(swelling[b].length_scale(time) / swelling[b].length_scale(time - previous_dt)) / previous_dt
        : swelling[b].relative_growth_rate(time);
    const Vec2 v_c = body.velocity[body.centre_index()];
    // U_target is linear in (U, X), so a sub-marker's target is the linear interpolation of its
    // edge end points' targets; a retracted marker's velocity relative to the centre point is
    // scaled by its radial factor.
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d)
        c.target_velocity[l][d] =
            marker_value(body.velocity, v_c, c, l, n_rim, d) - growth * (c.marker[l][d] - x_c[d]);
  }
}

void add_point_velocity_change(const MassSpringBody& body, const std::vector<Vec2>& change, BodyCoupling& c) {
  const Vec2& centre = change[body.centre_index()];
  for (std::size_t l = 0; l < c.marker.size(); ++l)
    for (int d = 0; d < 2; ++d) c.target_velocity[l][d] += marker_value(change, centre, c, l, body.n_surface, d);
}

void rigid_arms(const MassSpringBody& body, const BodyCoupling& c, std::vector<Vec2>& arm) {
  const int n_rim = body.n_surface;
  const Vec2& x_c = body.position[body.centre_index()];
  arm.resize(c.marker.size());  // capacity reserved: no allocation after the first step
  for (std::size_t l = 0; l < c.marker.size(); ++l)
    arm[l] = {rim_to_marker(c, l, n_rim, body.position, 0) - x_c[0], rim_to_marker(c, l, n_rim, body.position, 1) - x_c[1]};
}

void rigid_response(double fluid_density, const BodyCoupling& c, const std::vector<Vec2>& arm,
                    const std::vector<double>& marker_volume, const std::vector<double>& radial_factor,
                    const std::vector<Vec2>& impulse, std::vector<Vec2>& change) {
  Vec2 momentum{0.0, 0.0};
  double angular = 0.0;
  for (std::size_t l = 0; l < arm.size(); ++l) {
    const Vec2& r = arm[l];
    const Vec2 p{-fluid_density * marker_volume[l] * impulse[l][0], -fluid_density * marker_volume[l] * impulse[l][1]};
    momentum[0] += p[0];
    momentum[1] += p[1];
    angular += r[0] * p[1] - r[1] * p[0];
  }
  const Vec2 du{momentum[0] / c.response_mass, momentum[1] / c.response_mass};
  const double dw = angular / c.response_inertia;
  for (std::size_t l = 0; l < arm.size(); ++l) {
    const Vec2& r = arm[l];
    const double f = radial_factor[l];
    change[l] = {du[0] - f * dw * r[1], du[1] + f * dw * r[0]};
  }
}

void apply_direct_forcing(const Grid& grid, KernelKind kernel, const WallVelocities& walls, double dt,
                          int n_passes, std::vector<BodyCoupling>& coupling, CellField& velocity_star_x,
                          CellField& velocity_star_y) {
  for (BodyCoupling& c : coupling)
    for (Vec2& f : c.forcing_sum) f = {0.0, 0.0};
  for (int pass = 0; pass < n_passes; ++pass) {
    // All markers of all bodies see the same u~ within one pass (Uhlmann 2005, step 2), then
    // every body spreads (step 4); later passes correct what the earlier ones left (Luo et al. 2007).
    for_each_body(coupling.size(), [&](std::size_t b) {
      BodyCoupling& c = coupling[b];
      interpolate(grid, kernel, walls, velocity_star_x, velocity_star_y, c.marker, c.interpolated_velocity);
      direct_forcing(c.target_velocity, c.interpolated_velocity, dt, c.pass_force);  // Uhlmann eq. (14)
    });
    for (BodyCoupling& c : coupling) {
      // u~ += dt f with f = S F: spreading dt F directly adds dt f (spread is linear).
      for (std::size_t l = 0; l < c.marker.size(); ++l)
        for (int d = 0; d < 2; ++d) {
          c.pass_increment[l][d] = dt * c.pass_force[l][d];
          c.forcing_sum[l][d] += c.pass_force[l][d];
        }
      spread(grid, kernel, c.marker, c.pass_increment, c.marker_volume, velocity_star_x, velocity_star_y);
    }
  }
}

bool spread_previous_forces(const Grid& grid, double dt, std::vector<BodyCoupling>& coupling,
                            CellField& velocity_star_x, CellField& velocity_star_y) {
  for (const BodyCoupling& c : coupling)
    if (c.previous_force.size() != c.marker.size()) return false;
  for (BodyCoupling& c : coupling) {
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) {
        c.forcing_sum[l][d] = c.previous_force[l][d];
        c.pass_increment[l][d] = dt * c.previous_force[l][d];
      }
    spread(grid, c.face_stencils, c.pass_increment, c.marker_volume, velocity_star_x, velocity_star_y);
  }
  return true;
}

namespace {

// The slip of each body from its interpolated_velocity, max and RMS over the markers / U_ref, into
// (slip_max, slip_rms) or (face_slip_max, face_slip_rms); pass_increment = U_target - J u.
double slip_of_interpolated(std::vector<BodyCoupling>& coupling, bool faces) {
  double largest = 0.0;
  for (BodyCoupling& c : coupling) {
    double max2 = 0.0, sum2 = 0.0;
    for (std::size_t l = 0; l < c.marker.size(); ++l) {
      for (int d = 0; d < 2; ++d) c.pass_increment[l][d] = c.target_velocity[l][d] - c.interpolated_velocity[l][d];
      if (!c.body_velocity_change.empty())
        for (int d = 0; d < 2; ++d) c.pass_increment[l][d] += c.body_velocity_change[l][d];
      const double r2 = c.pass_increment[l][0] * c.pass_increment[l][0] + c.pass_increment[l][1] * c.pass_increment[l][1];
      max2 = std::max(max2, r2);
      sum2 += r2;
    }
    const double largest_here = std::sqrt(max2) / c.slip_reference_speed;
    const double rms = c.marker.empty() ? 0.0 : std::sqrt(sum2 / static_cast<double>(c.marker.size())) / c.slip_reference_speed;
    (faces ? c.face_slip_max : c.slip_max) = largest_here;
    (faces ? c.face_slip_rms : c.slip_rms) = rms;
    largest = std::max(largest, largest_here);
  }
  return largest;
}

}  // namespace

double measure_slip(const Grid& grid, KernelKind kernel, const WallVelocities& walls, const CellField& velocity_x,
                    const CellField& velocity_y, std::vector<BodyCoupling>& coupling) {
  for_each_body(coupling.size(), [&](std::size_t b) {
    interpolate(grid, kernel, walls, velocity_x, velocity_y, coupling[b].marker, coupling[b].interpolated_velocity);
  });
  return slip_of_interpolated(coupling, false);
}

double measure_face_slip(const Grid& grid, KernelKind kernel, const WallVelocities& walls, const FaceField& face_x,
                         const FaceField& face_y, std::vector<BodyCoupling>& coupling) {
  for_each_body(coupling.size(), [&](std::size_t b) {
    map_face_stencils(grid, kernel, coupling[b].marker, coupling[b].face_stencils);
  });
  return measure_face_slip(grid, walls, face_x, face_y, coupling);
}

double measure_face_slip(const Grid& grid, const WallVelocities& walls, const FaceField& face_x, const FaceField& face_y,
                         std::vector<BodyCoupling>& coupling) {
  for_each_body(coupling.size(), [&](std::size_t b) {
    interpolate_faces(grid, coupling[b].face_stencils, walls, face_x, face_y, coupling[b].interpolated_velocity);
  });
  return slip_of_interpolated(coupling, true);
}

void spread_slip_correction(const Grid& grid, KernelKind kernel, double dt, std::vector<BodyCoupling>& coupling,
                            CellField& increment_x, CellField& increment_y) {
  for (BodyCoupling& c : coupling) {
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) c.forcing_sum[l][d] += c.pass_increment[l][d] / dt;
    spread(grid, kernel, c.marker, c.pass_increment, c.marker_volume, increment_x, increment_y);
  }
}

void spread_step_forces(const Grid& grid, double dt, std::vector<BodyCoupling>& coupling,
                        CellField& force_cell_x, CellField& force_cell_y, FaceField& force_face_x, FaceField& force_face_y) {
  force_cell_x.fill(0.0);
  force_cell_y.fill(0.0);
  force_face_x.fill(0.0);
  force_face_y.fill(0.0);
  for (BodyCoupling& c : coupling) {
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) c.pass_increment[l][d] = dt * c.forcing_sum[l][d];
    spread(grid, c.face_stencils, c.pass_increment, c.marker_volume, force_cell_x, force_cell_y);
    spread_to_faces(grid, c.face_stencils, c.pass_increment, c.marker_volume, force_face_x, force_face_y);
  }
}

void average_faces_to_cells(const Grid& grid, const FaceField& face_x, const FaceField& face_y, CellField& cell_x,
                            CellField& cell_y) {
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      cell_x(i, j) = face_mean_x(face_x, i, j);
      cell_y(i, j) = face_mean_y(face_y, i, j);
    }
}

void cell_forces_from_faces(const Grid& grid, const FaceField& force_face_x, const FaceField& force_face_y,
                            CellField& force_cell_x, CellField& force_cell_y, CellField& velocity_star_x,
                            CellField& velocity_star_y) {
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double fx = face_mean_x(force_face_x, i, j);
      const double fy = face_mean_y(force_face_y, i, j);
      velocity_star_x(i, j) += fx - force_cell_x(i, j);
      velocity_star_y(i, j) += fy - force_cell_y(i, j);
      force_cell_x(i, j) = fx;
      force_cell_y(i, j) = fy;
    }
}

void keep_forces(std::vector<BodyCoupling>& coupling) {
  for (BodyCoupling& c : coupling) c.previous_force.assign(c.forcing_sum.begin(), c.forcing_sum.end());
}

void compute_fluid_reaction(double fluid_density, std::vector<BodyCoupling>& coupling) {
  for (BodyCoupling& c : coupling) {
    for (Vec2& f : c.fluid_force) f = {0.0, 0.0};  // the centre point gets none
    const int n_rim = static_cast<int>(c.triangle_momentum.size());
    // docs/method.md §1.6: F_f,l = -rho_f (sum_m F_l^(m)) dV_l, a force per unit depth; a sub-marker's
    // share goes to its edge's end points with weights (1 - w, w) (§3.6).
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d)
        marker_to_rim(c, l, n_rim, -fluid_density * c.forcing_sum[l][d] * c.marker_volume[l], d, c.fluid_force);
  }
}

void compute_hydrodynamic_loads(const std::vector<MassSpringBody>& bodies, std::vector<BodyCoupling>& coupling) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const MassSpringBody& body = bodies[b];
    BodyCoupling& c = coupling[b];
    const Vec2& x_c = body.position[body.centre_index()];
    Vec2 force{0.0, 0.0};
    double torque = c.inner_fluid_torque;
    for (int p = 0; p < body.n_points(); ++p) {
      const Vec2& f = c.fluid_force[p];
      for (int d = 0; d < 2; ++d) force[d] += f[d] + c.inner_fluid_force[p][d];
      torque += (body.position[p][0] - x_c[0]) * f[1] - (body.position[p][1] - x_c[1]) * f[0];
    }
    c.hydrodynamic_force = force;
    c.hydrodynamic_torque = torque;
  }
}

}  // namespace ibms
