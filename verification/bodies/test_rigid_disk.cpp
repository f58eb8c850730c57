// Rigid bodies in two flows whose answer is known:
//  (1) a neutrally buoyant rigid disk at rest in fluid at rest, with gravity, stays at rest: the
//      buoyancy-corrected weight is zero and nothing else may move it (round-off tolerance;
//      docs/method.md §2.6: gravity acts on the bodies only, as M (1 - rho_f / rho_s) g, with no
//      hydrostatic pressure in the fluid to stir it);
//  (2) a neutrally buoyant rigid disk (D = 0.2), started at rest at the centre of a prescribed
//      cylinder (D = 0.8) turning at Omega, ends co-rotating with the fluid's rigid rotation
//      (the steady Navier-Stokes solution inside the cylinder): its rotation rate approaches Omega
//      and its centre does not drift. Tolerance 1 % of Omega on the finest grid, and the error
//      shrinks with the grid (a direct-forcing boundary is first order: test_circular_couette).
#define BOOST_TEST_MODULE rigid_disk
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "body_scenes.hpp"

using namespace ibms;

BOOST_AUTO_TEST_CASE(neutrally_buoyant_disk_at_rest_stays_at_rest) {
  Scene scene;
  scene.source_file = "(rigid disk at rest)";
  scene.domain = {1.0, 1.0, 64, 64, false, false};
  scene.fluid.gravity = {0.0, -9.81};
  scene.bodies.push_back(test::rigid_disk({0.437, 0.561}, 0.25, 1.0 / 64, /*density=*/1.0));
  Simulation sim(scene);
  for (int k = 0; k < 200; ++k) advance_one_step(sim, 1e-3);
  const RigidState& s = sim.rigid()[0].state;
  BOOST_TEST_MESSAGE("after 200 steps: V = (" << s.velocity[0] << ", " << s.velocity[1] << "), Omega = "
                                              << s.angular_velocity);
  // Exactly zero forces give exactly zero motion; allow round-off of sums of O(1) terms.
  BOOST_TEST(std::hypot(s.velocity[0], s.velocity[1]) < 1e-13);
  BOOST_TEST(std::abs(s.angular_velocity) < 1e-12);
  BOOST_TEST(std::hypot(s.centre[0] - 0.437, s.centre[1] - 0.561) < 1e-15);
}

namespace {

struct SpinUp {
  double rotation_error = 0.0;  // |omega_disk / Omega - 1| at the end [-]
  double drift = 0.0;           // |X_c(T) - X_c(0)| / D [-]
};

SpinUp spin_up(int n) {
  constexpr double omega = 1.0, nu = 0.05;
  const std::array<double, 2> centre{0.5, 0.5};
  Scene scene;
  scene.source_file = "(rigid disk spin-up)";
  scene.domain = {1.0, 1.0, n, n, false, false};
  scene.fluid.kinematic_viscosity = nu;
  const double h = 1.0 / n;
  scene.bodies.push_back(test::prescribed_cylinder(centre, 0.8, h, omega));
  scene.bodies.push_back(test::rigid_disk(centre, 0.2, h, /*density=*/1.0));
  Simulation sim(scene);
  // Fluid in rigid rotation inside the container (the state it keeps), the disk at rest.
  const Grid& g = sim.grid();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double rx = g.x_centre(i) - centre[0], ry = g.y_centre(j) - centre[1];
      const bool inside = std::hypot(rx, ry) < 0.4;
      sim.fluid().velocity_x(i, j) = inside ? -omega * ry : 0.0;
      sim.fluid().velocity_y(i, j) = inside ? omega * rx : 0.0;
    }
  sim.fluid_solver().initialise_faces(sim.fluid());
  sim.inner_fluid_inertia()(sim.grid(), 1.0, sim.fluid(), sim.bodies(), 1.0, sim.markers());  // I^0
  // Spin-up of the gap (0.3 wide) decays like exp(-nu pi^2 t / 0.3^2): t = 3 leaves e^-16.
  test::run_to(sim, 3.0, std::min(0.5 * h / (omega * 0.4), 0.5 * h * h / nu));
  const RigidState& s = sim.rigid()[1].state;
  return {std::abs(s.angular_velocity / omega - 1.0), std::hypot(s.centre[0] - centre[0], s.centre[1] - centre[1]) / 0.2};
}

}  // namespace

BOOST_AUTO_TEST_CASE(neutrally_buoyant_disk_in_rigid_rotation_co_rotates) {
  const SpinUp coarse = spin_up(48), fine = spin_up(96);
  BOOST_TEST_MESSAGE("N = 48: |omega/Omega - 1| = " << coarse.rotation_error << ", drift/D = " << coarse.drift);
  BOOST_TEST_MESSAGE("N = 96: |omega/Omega - 1| = " << fine.rotation_error << ", drift/D = " << fine.drift);
  BOOST_TEST(fine.rotation_error < 0.01);
  BOOST_TEST(fine.rotation_error < coarse.rotation_error);
  BOOST_TEST(fine.drift < 1e-3);
}
