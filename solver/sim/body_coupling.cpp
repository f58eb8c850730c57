// Markers, direct forcing and fluid reaction of the bodies (see body_coupling.hpp).
#include "sim/body_coupling.hpp"

#include <cmath>

#include "ibm/direct_forcing.hpp"
#include "ibm/marker_weights.hpp"

namespace ibms {

BodyCoupling::BodyCoupling(const MassSpringBody& body)
    : marker(body.n_surface), marker_volume(body.n_surface), target_velocity(body.n_surface),
      interpolated_velocity(body.n_surface), pass_force(body.n_surface), pass_increment(body.n_surface),
      forcing_sum(body.n_surface), fluid_force(body.n_points()), inner_fluid_force(body.n_points()),
      external_force(body.n_points()), triangle_cells(body.n_surface), triangle_momentum(body.n_surface) {}

WallVelocities wall_velocities_at(const FluidBoundaries& boundaries, double time) {
  return {boundaries.left.at(time), boundaries.right.at(time), boundaries.bottom.at(time),
          boundaries.top.at(time)};
}

void prepare_markers(const std::vector<MassSpringBody>& bodies,
                     const std::vector<SwellingSchedule>& swelling, double time, double previous_dt,
                     const Grid& grid, std::vector<BodyCoupling>& coupling) {
  const double h = grid.dx();  // square cells (checked when the Simulation is built)
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const MassSpringBody& body = bodies[b];
    BodyCoupling& c = coupling[b];
    for (int l = 0; l < body.n_surface; ++l) c.marker[l] = body.position[l];
    c.marker_volume = marker_weights(c.marker, h);  // dV_l = h s_l, METHOD.md §3.6
    // METHOD.md §1.8: the fluid is forced towards the marker velocity minus the swelling
    // part (s'/s)(X_l - X_c), so a swelling body absorbs fluid instead of pushing it away.
    // s'/s [1/time] over the step that produced U^n: the marker velocities at t^n are the end of
    // the previous step's sub-steps, so the dilation they carry is that step's, ln(s^n/s^{n-1})/dt^{n-1}
    // (the instantaneous rate at t^n would mismatch U^n by the full D'/2 at the schedule's kinks).
    const double growth = previous_dt > 0.0
        ? std::log(swelling[b].length_scale(time) / swelling[b].length_scale(time - previous_dt)) / previous_dt
        : swelling[b].relative_growth_rate(time);
    const Vec2 x_c = centre_of_mass(body);
    for (int l = 0; l < body.n_surface; ++l)
      for (int d = 0; d < 2; ++d)
        c.target_velocity[l][d] = body.velocity[l][d] - growth*(body.position[l][d] - x_c[d]);
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
    for (BodyCoupling& c : coupling) {
      interpolate(grid, kernel, walls, velocity_star_x, velocity_star_y, c.marker, c.interpolated_velocity);
      direct_forcing(c.target_velocity, c.interpolated_velocity, dt, c.pass_force);  // Uhlmann eq. (14)
    }
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

void compute_fluid_reaction(double fluid_density, std::vector<BodyCoupling>& coupling) {
  for (BodyCoupling& c : coupling) {
    const std::size_t n_rim = c.marker.size();
    // METHOD.md §1.6: F_f,l = -rho_f (sum_m F_l^(m)) dV_l, a force per unit depth.
    for (std::size_t l = 0; l < n_rim; ++l)
      for (int d = 0; d < 2; ++d) c.fluid_force[l][d] = -fluid_density * c.forcing_sum[l][d] * c.marker_volume[l];
    for (std::size_t p = n_rim; p < c.fluid_force.size(); ++p) c.fluid_force[p] = {0.0, 0.0};  // centre
  }
}

}  // namespace ibms
