// Momentum of fluid plus bodies in a periodic box without walls or gravity:
// a wheel launched at (1, 0.5) into fluid at rest. Every force is internal: springs cancel in
// pairs, spreading conserves the total force (sum f h^2 = sum F dV), the fluid reaction is its
// negative, and the periodic predictor and projection conserve sum u h^2. So
//   variant A: P = sum rho_f u h^2 + sum M U            is conserved to round-off;
//   variant K: P_K = P - rho_f sum_T I_T                 is (the grid's inner fluid is fictitious;
//              the Reynolds-transport increments of F_int telescope, sim/coupling/inner_fluid_inertia.hpp),
//              while P itself changes by rho_f (I^{n+1} - I^n) per step (logged, not asserted).
// Checks docs/method.md §1.1, §1.6, §1.7: the mass points move by M_i dU_i/dt = F_s + F_f (§1.1),
// the fluid force on them the negative of the force spread, rho_f F_l dV_l (§1.6), and variant K's
// inner-fluid force the change of the grid's inner momentum (§1.7).
#define BOOST_TEST_MODULE momentum_conservation
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "scene/scene_schema.hpp"
#include "sim/coupling/inner_fluid_inertia.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"
#include "sim_scenes.hpp"

using namespace ibms;
using test::body_momentum;
using test::fluid_momentum;

namespace {

struct Drift { double conserved, plain, initial; };

// Largest drift over n_steps of the conserved combination and of the plain sum P.
Drift run_and_measure(const std::string& variant, int n_steps) {
  Scene scene = test::one_body_scene(/*n=*/64, /*periodic=*/true, /*diameter=*/0.25, /*density=*/1.5,
                                     /*stiffness=*/1e4);
  scene.bodies[0].velocity = {1.0, 0.5};
  scene.ibm.inner_fluid_inertia = scene_schema::parse_choice<IbmSpec::InnerFluidInertia>(variant).value();
  Simulation sim(scene);
  auto totals = [&] {
    const Vec2 pf = fluid_momentum(sim), pb = body_momentum(sim);
    const Vec2 inner = inner_fluid_momentum(sim.fluid_density(), sim.markers());
    return std::array<Vec2, 2>{Vec2{pf[0] + pb[0] - inner[0], pf[1] + pb[1] - inner[1]},
                               Vec2{pf[0] + pb[0], pf[1] + pb[1]}};
  };
  const auto start = totals();
  Drift drift{0.0, 0.0, std::hypot(start[1][0], start[1][1])};
  const double dt = 2e-3;  // CFL 0.13 at |U| = 1.1, marker travel 0.14 h
  for (int n = 0; n < n_steps; ++n) {
    advance_one_step(sim, dt);
    const auto now = totals();
    drift.conserved = std::max(drift.conserved, std::hypot(now[0][0] - start[0][0], now[0][1] - start[0][1]));
    drift.plain = std::max(drift.plain, std::hypot(now[1][0] - start[1][0], now[1][1] - start[1][1]));
  }
  const Vec2 ub = body_momentum(sim);
  BOOST_TEST_MESSAGE(variant << ": body momentum after " << n_steps << " steps (" << ub[0] << ", " << ub[1]
                             << ") of initial " << drift.initial);
  return drift;
}

}  // namespace

BOOST_AUTO_TEST_CASE(fluid_plus_body_momentum_is_conserved_in_a_periodic_box) {
  const int n_steps = 200;
  const Drift a = run_and_measure("none", n_steps);
  const Drift k = run_and_measure("kempe", n_steps);
  const Drift km = run_and_measure("kempe_by_mass", n_steps);
  BOOST_TEST_MESSAGE("variant  max|P_conserved(t) - P(0)|/|P(0)|  max|P_plain(t) - P(0)|/|P(0)|");
  BOOST_TEST_MESSAGE("A        " << a.conserved / a.initial << "  " << a.plain / a.initial);
  BOOST_TEST_MESSAGE("K        " << k.conserved / k.initial << "  " << k.plain / k.initial);
  BOOST_TEST_MESSAGE("K, mass  " << km.conserved / km.initial << "  " << km.plain / km.initial);
  // Round-off: ~64^2 cell sums and ~10^2 sub-steps per step accumulate eps ~ 1e-16 relative errors
  // over 200 steps; 1e-12 leaves a margin of ~10^2 over that and is far below any real leak
  // (a missing reaction or a dropped pass would show up at O(1e-3) after the first step).
  BOOST_TEST(a.conserved / a.initial < 1e-12);
  BOOST_TEST(k.conserved / k.initial < 1e-12);
  BOOST_TEST(km.conserved / km.initial < 1e-12);
}

// The inner fluid's load on the points (docs/method.md §1.7 step 4). The inner fluid of a wheel at
// rest is set moving at once, uniformly at U or as a solid-body rotation at Omega about the wheel's
// centre, so rho_f dI/dt = rho_f A U / dt and rho_f dL/dt = rho_f J Omega / dt. "kempe" lays a third
// of each fan triangle's force on each vertex: the centre point, 1/(N_l + 1) of the mass and no
// marker, takes a third of the body's force, (N_l + 1)/3 = 16.3 times its share of a uniform
// acceleration (the hub-mode drive of the 256-particle cavity, validation/cavity_swelling_particles).
// "kempe_by_mass" lays the same force and torque (about X_c) on the points as the load of a rigid
// motion of their masses: every point the same acceleration from a uniform one of the inner fluid.
BOOST_AUTO_TEST_CASE(inner_fluid_load_is_a_rigid_motion_of_the_masses) {
  Scene scene = test::one_body_scene(/*n=*/64, /*periodic=*/true, /*diameter=*/0.25, /*density=*/1.5,
                                     /*stiffness=*/1e4);
  Simulation sim(scene);
  const Grid& g = sim.grid();
  FluidState& fluid = sim.fluid();
  const MassSpringBody& body = sim.bodies()[0];
  const int centre = body.centre_index();
  const double dt = 2e-3, rho = sim.fluid_density();
  const Vec2 x_c = body.position[centre];
  double mass = 0.0;
  for (double m : body.mass) mass += m;
  // Force and torque about X_c the points take, and the largest |f_p / m_p - a_p| over the points
  // for the rigid motion a_p = A + alpha z x (x_p - x_c) that the body's force and torque give.
  struct Load { Vec2 force; double torque, rigid_misfit, centre_share_x; };
  const auto load = [&](InnerFluidInertia inertia, double ux, double omega) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) fluid.velocity_x(i, j) = fluid.velocity_y(i, j) = 0.0;
    sample_inner_fluid_momentum(g, fluid, sim.bodies(), sim.markers());
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        fluid.velocity_x(i, j) = ux - omega * (g.y_centre(j) - x_c[1]);
        fluid.velocity_y(i, j) = omega * (g.x_centre(i) - x_c[0]);
      }
    inertia(g, rho, fluid, sim.bodies(), dt, sim.markers());
    const std::vector<Vec2>& f = sim.markers()[0].inner_fluid_force;
    Load out{{0.0, 0.0}, 0.0, 0.0, 0.0};
    double inertia_c = 0.0;
    for (int p = 0; p < body.n_points(); ++p) {
      const double rx = body.position[p][0] - x_c[0], ry = body.position[p][1] - x_c[1];
      out.force[0] += f[p][0];
      out.force[1] += f[p][1];
      out.torque += rx * f[p][1] - ry * f[p][0];
      inertia_c += body.mass[p] * (rx * rx + ry * ry);
    }
    const double alpha = out.torque / inertia_c;  // the wheel is symmetric: x_G = x_c
    for (int p = 0; p < body.n_points(); ++p) {
      const double rx = body.position[p][0] - x_c[0], ry = body.position[p][1] - x_c[1];
      const double ax = out.force[0] / mass - alpha * ry, ay = out.force[1] / mass + alpha * rx;
      out.rigid_misfit = std::max(out.rigid_misfit, std::hypot(f[p][0] / body.mass[p] - ax, f[p][1] / body.mass[p] - ay));
    }
    out.centre_share_x = f[centre][0] / out.force[0];
    return out;
  };
  for (const auto& [ux, omega] : {std::pair{1.0, 0.0}, std::pair{0.0, 4.0}, std::pair{1.0, 4.0}}) {
    const Load thirds = load(&kempe_inner_fluid_inertia, ux, omega);
    const Load by_mass = load(&kempe_inner_fluid_inertia_by_mass, ux, omega);
    const double scale = std::hypot(thirds.force[0], thirds.force[1]) / mass + std::abs(thirds.torque) * 0.125 /
                         (mass * 0.125 * 0.125);  // |A| + |alpha| R with the torque's R^2 M scale
    BOOST_TEST_MESSAGE("U = " << ux << ", Omega = " << omega << ": force " << thirds.force[0] << ", "
                              << thirds.force[1] << "; torque thirds " << thirds.torque << ", by mass "
                              << by_mass.torque << " (inner fluid " << sim.markers()[0].inner_fluid_torque
                              << "); rigid-motion misfit thirds " << thirds.rigid_misfit / scale << ", by mass "
                              << by_mass.rigid_misfit / scale << "; centre point's share of F_x thirds "
                              << thirds.centre_share_x);
    // The same force (the sum of the triangles'), and the torque rho_f dL/dt about X_c.
    BOOST_TEST(std::abs(by_mass.force[0] - thirds.force[0]) <= 1e-12 * std::abs(thirds.force[0]) + 1e-12);
    BOOST_TEST(std::abs(by_mass.force[1] - thirds.force[1]) <= 1e-12 * std::abs(thirds.force[0]) + 1e-12);
    BOOST_TEST(std::abs(by_mass.torque - sim.markers()[0].inner_fluid_torque) <=
               1e-12 * std::abs(sim.markers()[0].inner_fluid_torque) + 1e-14);
    BOOST_TEST(by_mass.rigid_misfit / scale < 1e-12);
    if (ux > 0.0 && omega == 0.0) {
      // A uniform acceleration of the inner fluid: the thirds load is far from a rigid motion, its
      // centre point takes a third of the force (the rigid motion's share is 1/(N_l + 1)).
      BOOST_TEST(std::abs(thirds.centre_share_x - 1.0 / 3.0) < 1e-12);
      BOOST_TEST(thirds.rigid_misfit / scale > 1.0);
      BOOST_TEST(std::abs(by_mass.centre_share_x - body.mass[centre] / mass) < 1e-12);
    }
  }
}
