// The linearly implicit Euler step of the springs (solid/implicit_euler.hpp).
// Claims, each a test that a wrong step would fail:
//  - energy: for one linear spring moving along its axis, each step multiplies the oscillator
//    energy by exactly 1 / (1 + (omega dt)^2) (backward Euler's factor), stretched or compressed,
//    for omega dt from 0.1 to 1000; so it never grows and stiff modes die out;
//  - the undamped wheel's energy never increases from one step to the next, at omega_max dt ~ 300;
//  - internal forces only: the total momentum is kept to round-off;
//  - a uniform force field (gravity) accelerates a stiff wheel as a rigid body: centre-of-mass
//    velocity F t / M to round-off, the wheel undeformed;
//  - explicit and implicit agree where both resolve the springs (omega_max dt << 1): positions
//    after a deformed wheel's release agree to O(dt);
//  - rebound: stiff wheels (springs 1e3 and 1e5 k_Dn) stepped at the contact sub-step only, with
//    implicit springs, rebound with e within 0.03 of e_D = 0.5 and 0.9, as the explicit test
//    (test_wheel_restitution) asks of explicit stiff wheels.
#define BOOST_TEST_MODULE implicit_springs
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "solid/implicit_euler.hpp"
#include "solid/spring_forces.hpp"
#include "solid/stable_substep.hpp"
#include "solid/symplectic_euler.hpp"
#include "wheel_collision.hpp"

using namespace ibms;
using namespace ibms::test;

namespace {

using Forces = std::vector<std::array<double, 2>>;

// Two points of mass m joined by one undamped spring of stiffness k and natural length 1.
MassSpringBody dumbbell(double m, double k, double stretch) {
  MassSpringBody body;
  body.position = {{0.0, 0.0}, {1.0 + stretch, 0.0}};
  body.velocity = {{0.0, 0.0}, {0.0, 0.0}};
  body.mass = {m, m};
  body.mass_fraction = {0.5, 0.5};
  body.springs = {{0, 1, k, 0.0, 1.0}};
  body.n_surface = 1;
  body.diameter0 = body.diameter = 1.0;
  return body;
}

double total_energy(const MassSpringBody& body) { return kinetic_energy(body) + spring_energy(body, 1.0); }

Forces zero_forces(const MassSpringBody& body) { return Forces(body.n_points(), {0.0, 0.0}); }

}  // namespace

BOOST_AUTO_TEST_CASE(one_spring_loses_exactly_the_backward_euler_factor_per_step) {
  const double m = 2.0, k = 50.0;
  const double omega = std::sqrt(k / (0.5 * m));  // reduced mass m/2
  for (double stretch : {0.1, -0.1})
    for (double omega_dt : {0.1, 1.0, 30.0, 1000.0}) {
      MassSpringBody body = dumbbell(m, k, stretch);
      ImplicitSpringSystem implicit;
      const double dt = omega_dt / omega;
      const double initial = total_energy(body);
      // Steps while the oscillation is far above round-off (positions ~ 1, energy ~ stretch^2):
      // below E ~ 1e-10 E_0 the stretch is ~ 1e-6 of the initial one and its rounding shows.
      for (int n = 0; n < 5 && total_energy(body) > 1e-10 * initial; ++n) {
        const double before = total_energy(body);
        Forces force = zero_forces(body);
        implicit.advance(body, dt, force);
        const double ratio = total_energy(body) / before;
        BOOST_TEST(ratio == 1.0 / (1.0 + omega_dt * omega_dt), boost::test_tools::tolerance(1e-8));
        BOOST_TEST(std::abs(body.position[0][1]) + std::abs(body.position[1][1]) == 0.0);  // stays on its axis
      }
    }
}

BOOST_AUTO_TEST_CASE(undamped_wheel_energy_never_increases_and_momentum_is_kept) {
  const MassSpringBody initial = make_wheel({0.0, 0.0}, {0.3, -0.2}, /*stiffness_ratio=*/400.0);  // k_s = 4e6
  MassSpringBody body = initial;
  // Deform it: squeeze the rim by 2 % along x and spin it.
  for (int p = 0; p < body.n_surface; ++p) {
    body.position[p][0] *= 0.98;
    body.velocity[p][0] += -0.5 * body.position[p][1];
    body.velocity[p][1] += 0.5 * body.position[p][0];
  }
  const double explicit_substep = stable_substep(body);
  const double dt = 300.0 * explicit_substep;  // what "auto" would hand to the implicit step
  const auto momentum = [](const MassSpringBody& b) {
    std::array<double, 2> p{0.0, 0.0};
    for (int k = 0; k < b.n_points(); ++k)
      for (int c = 0; c < 2; ++c) p[c] += b.mass[k] * b.velocity[k][c];
    return p;
  };
  const std::array<double, 2> p0 = momentum(body);
  ImplicitSpringSystem implicit;
  double previous = total_energy(body);
  const double initial_energy = previous;
  for (int n = 0; n < 200; ++n) {
    Forces force = zero_forces(body);
    implicit.advance(body, dt, force);
    const double energy = total_energy(body);
    BOOST_TEST(energy <= previous * (1.0 + 1e-12));
    previous = energy;
    const std::array<double, 2> p = momentum(body);
    BOOST_TEST(std::hypot(p[0] - p0[0], p[1] - p0[1]) <= 1e-12 * (1.0 + std::hypot(p0[0], p0[1])));
  }
  // The stiff modes are gone: what is left is (close to) the rigid motion's energy.
  BOOST_TEST(spring_energy(body, 1.0) < 1e-3 * initial_energy);
}

BOOST_AUTO_TEST_CASE(a_uniform_force_field_accelerates_a_stiff_wheel_as_a_rigid_body) {
  MassSpringBody body = make_wheel({0.0, 0.0}, {0.0, 0.0}, 400.0);
  const double g = -9.81;
  const double dt = 1e-3;
  ImplicitSpringSystem implicit;
  const MassSpringBody start = body;
  for (int n = 0; n < 100; ++n) {
    Forces force(body.n_points());
    for (int p = 0; p < body.n_points(); ++p) force[p] = {0.0, body.mass[p] * g};
    implicit.advance(body, dt, force);
  }
  const std::array<double, 2> v = centre_of_mass_velocity(body);
  BOOST_TEST(std::abs(v[0]) <= 1e-12);
  BOOST_TEST(v[1] == g * 100 * dt, boost::test_tools::tolerance(1e-12));
  // Undeformed: every point moved by the same amount.
  const double shift = body.position[0][1] - start.position[0][1];
  for (int p = 0; p < body.n_points(); ++p) {
    BOOST_TEST(std::abs(body.position[p][0] - start.position[p][0]) <= 1e-12);
    BOOST_TEST(std::abs(body.position[p][1] - start.position[p][1] - shift) <= 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(implicit_and_explicit_agree_where_both_resolve_the_springs) {
  // A soft wheel released from a 5 % squeeze; both integrators at dt = explicit limit / 8, and
  // the implicit one again at half that step: its difference from the explicit run halves (first order).
  MassSpringBody start = make_wheel({0.0, 0.0}, {0.0, 0.0}, 0.01);  // k_s = 100
  for (int p = 0; p < start.n_surface; ++p) start.position[p][0] *= 0.95;
  const double dt = stable_substep(start) / 8.0;
  const double duration = 200 * dt;
  const auto run = [&](bool implicit_step, double step) {
    MassSpringBody body = start;
    ImplicitSpringSystem implicit;
    const int n = static_cast<int>(std::lround(duration / step));
    for (int k = 0; k < n; ++k) {
      Forces force = zero_forces(body);
      if (implicit_step) implicit.advance(body, step, force);
      else advance_symplectic_euler_in_place(body, step, force);
    }
    return body;
  };
  const MassSpringBody reference = run(false, dt / 16.0);  // explicit, well resolved
  const auto difference = [&](const MassSpringBody& b) {
    double largest = 0.0;
    for (int p = 0; p < b.n_points(); ++p)
      largest = std::max(largest, std::hypot(b.position[p][0] - reference.position[p][0],
                                             b.position[p][1] - reference.position[p][1]));
    return largest;
  };
  const double coarse = difference(run(true, dt));
  const double fine = difference(run(true, dt / 2.0));
  BOOST_TEST_MESSAGE("implicit vs resolved explicit: " << coarse << " at dt, " << fine << " at dt/2");
  BOOST_TEST(coarse < 0.05 * 0.05);  // well below the 5 % squeeze (D = 1)
  BOOST_TEST(coarse / fine > 1.7);   // first order: 2 expected
  BOOST_TEST(coarse / fine < 2.3);
}

BOOST_AUTO_TEST_CASE(stiff_wheels_with_implicit_springs_rebound_with_the_contact_restitution) {
  const WallBox open_box{{-10.0, -10.0}, {20.0, 20.0}, {false, false}};
  for (double ratio : {1e3, 1e5})
    for (double restitution : {0.5, 0.9}) {
      const double half_gap = 0.5 + 0.05 + 0.05;
      const CollisionRecord record =
          collide(make_contact_model(restitution), open_box,
                  {make_wheel({-half_gap, 0.0}, {0.5 * impact_speed, 0.0}, ratio),
                   make_wheel({half_gap, 0.0}, {-0.5 * impact_speed, 0.0}, ratio)},
                  /*implicit_springs=*/true);
      const double e = measured_restitution(record);
      BOOST_TEST_MESSAGE("k_s/k_Dn = " << ratio << ", e_D = " << restitution << ": e = " << e << " with "
                                      << record.contact_time / record.substep << " sub-steps in contact");
      BOOST_TEST(std::abs(e - restitution) <= 0.03);
      BOOST_TEST(record.max_momentum_drift <= 1e-12);
    }
}
