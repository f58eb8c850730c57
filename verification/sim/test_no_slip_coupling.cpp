// The no_slip coupling (sim/coupling/no_slip_system.hpp) holds what it claims: after every step the
// velocity interpolated at the markers equals the forcing target within ibm.slip_tolerance U_ref,
// measured here independently of the coupling's own bookkeeping, for rigid and prescribed bodies
// with contacts, and for mass-spring bodies with contacts and swelling, whose target is the rim
// velocity at the end of the step (the body's response solved with the constraint); a stiff wheel
// then moves as the rigid disk. The papers' coupling leaves a slip
// far above that tolerance on the same scenes, so the check can tell the two apart. With
// ibm.constrained_velocity = "faces" the same holds of the face velocities J_f U_f^{n+1}, checked on
// a fixed cylinder in a channel. The faces stay divergence-free to round-off after the corrections,
// which are applied with the potentials of the marker system's own products (no Poisson solve of
// their own, docs/method.md §3.7): a wrong combination of those potentials would leave a divergence
// of the order of the corrections, (slip) / h.
// Checks docs/method.md §3.5 too: the papers' coupling (ibm.coupling = "uhlmann") leaves a slip at
// the end of the step, asserted above 10 times the no_slip tolerance on the same scenes.
#define BOOST_TEST_MODULE no_slip_coupling
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <exception>
#include <cmath>
#include <string>
#include <vector>

#include "fluid/operators.hpp"
#include "fluid/threads.hpp"
#include "scene/scene_reader.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

namespace {

struct SlipRecord {
  double largest = 0.0;            // largest slip / U_ref of any marker after any step
  double largest_reported = 0.0;   // largest BodyCoupling::slip_max
  double largest_mismatch = 0.0;   // |independent - reported| over bodies and steps
  double largest_divergence = 0.0; // max |D U_f| h / U_ref over the steps
  long products = 0;               // GMRES products over the run
  std::size_t most_markers = 0;    // the most markers of one body at any step
};

SlipRecord slip_over_steps(const char* scene_path, const std::vector<std::string>& overrides, int steps,
                           bool faces = false) {
  ibms::set_thread_count(1);
  const ibms::Scene scene = ibms::read_scene_file(scene_path, overrides);
  ibms::Simulation sim(scene);
  const double dt = scene.run.time_step;
  SlipRecord record;
  std::vector<std::array<double, 2>> at_markers;
  for (int k = 0; k < steps; ++k) {
    ibms::advance_one_step(sim, dt);
    double u_ref = 0.0;
    for (const ibms::BodyCoupling& c : sim.markers()) u_ref = std::max(u_ref, c.slip_reference_speed);
    record.largest_divergence =
        std::max(record.largest_divergence, ibms::max_abs_divergence(sim.grid(), sim.fluid().velocity_face_x,
                                                                     sim.fluid().velocity_face_y) *
                                                std::min(sim.grid().dx(), sim.grid().dy()) / u_ref);
    // The markers and targets of the step are those of t^n (the bodies have moved since).
    const ibms::WallVelocities walls = ibms::wall_velocities_at(sim.boundaries(), sim.fluid().time);
    for (const ibms::BodyCoupling& c : sim.markers()) {
      record.most_markers = std::max(record.most_markers, c.marker.size());
      if (faces)
        ibms::interpolate_faces(sim.grid(), sim.kernel(), walls, sim.fluid().velocity_face_x, sim.fluid().velocity_face_y,
                                c.marker, at_markers);
      else
        ibms::interpolate(sim.grid(), sim.kernel(), walls, sim.fluid().velocity_x, sim.fluid().velocity_y, c.marker,
                          at_markers);
      // A responding (mass-spring) body's target is its rim velocity at the end of the step.
      const auto change = [&](std::size_t l, int d) {
        return c.body_velocity_change.empty() ? 0.0 : c.body_velocity_change[l][d];
      };
      double body_largest = 0.0;
      for (std::size_t l = 0; l < c.marker.size(); ++l)
        body_largest = std::max(body_largest, std::hypot(at_markers[l][0] - c.target_velocity[l][0] - change(l, 0),
                                                         at_markers[l][1] - c.target_velocity[l][1] - change(l, 1)));
      body_largest /= c.slip_reference_speed;
      record.largest = std::max(record.largest, body_largest);
      const double reported = faces ? c.face_slip_max : c.slip_max;
      record.largest_reported = std::max(record.largest_reported, reported);
      record.largest_mismatch = std::max(record.largest_mismatch, std::abs(body_largest - reported));
    }
  }
  record.products = sim.stats().total_coupling_iterations;
  return record;
}

const std::vector<std::string> no_slip{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-4"};

}  // namespace

BOOST_AUTO_TEST_CASE(sub_markers_on_mass_spring_wheels_keep_no_slip_on_the_faces) {
  // The same wheels with sub-markers between their rim points (docs/method.md §3.6): each marker's
  // force and the rim's response go to and from its edge's end points, and the target of every
  // marker, sub-markers included, is the rim's velocity at the end of the step.
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                          "ibm.constrained_velocity=\"faces\"", "ibm.sub_markers=true"};
  const SlipRecord coupled = slip_over_steps(IBMS_SCENE_MASS_SPRING, on_faces, 300, /*faces=*/true);
  BOOST_TEST_MESSAGE("no_slip on faces, sub-markers: largest face slip " << coupled.largest << ", GMRES products "
                                                                           << coupled.products << ", markers of a rim up to "
                                                                           << coupled.most_markers);
  BOOST_TEST(coupled.most_markers >= 2 * 16u);  // 16 rim points 1.26 h apart: two markers an edge
  BOOST_TEST(coupled.largest <= 1e-3);
  BOOST_TEST(coupled.largest_mismatch <= 1e-12);
  BOOST_TEST(coupled.largest_divergence <= 1e-10);
}

BOOST_AUTO_TEST_CASE(mass_spring_wheels_with_contacts_and_swelling_keep_no_slip_on_the_faces) {
  // The two wheels of restart_scene.toml (density 2, k_s = 200, D/h = 6.4, one swelling, wall and
  // wheel-wheel contacts), 300 steps to t = 1.2. With the forces solved without the rim's response,
  // one of these wheels alone blows up within 2-36 steps (docs/method.md §3.7).
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                          "ibm.constrained_velocity=\"faces\""};
  const SlipRecord coupled = slip_over_steps(IBMS_SCENE_MASS_SPRING, on_faces, 300, /*faces=*/true);
  BOOST_TEST_MESSAGE("no_slip on faces, mass-spring wheels: largest face slip " << coupled.largest
                                                                                << ", GMRES products " << coupled.products);
  BOOST_TEST(coupled.largest <= 1e-3);
  BOOST_TEST(coupled.largest_mismatch <= 1e-12);
  BOOST_TEST(coupled.largest_divergence <= 1e-10);
  const SlipRecord papers = slip_over_steps(IBMS_SCENE_MASS_SPRING, {}, 300, /*faces=*/true);
  BOOST_TEST_MESSAGE("uhlmann: largest face slip " << papers.largest);
  BOOST_TEST(papers.largest > 10 * 1e-3);
}

namespace {

// Body 0's centre-of-mass velocity every 50 steps of falling_wheel.toml, as a mass-spring wheel or
// as the rigid disk of the same size and density.
std::vector<std::array<double, 2>> falling_velocities(bool rigid) {
  ibms::set_thread_count(1);
  ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL);
  if (rigid) scene.bodies[0].kind = ibms::BodySpec::Kind::rigid;
  // The marker system solved far below the differences compared: at the scene's 1e-3 U the two
  // velocities move by up to 0.9 % with the GMRES's stopping point alone.
  scene.ibm.slip_tolerance = 1e-5;
  ibms::Simulation sim(scene);
  std::vector<std::array<double, 2>> velocities;
  const int steps = static_cast<int>(std::lround(scene.run.end_time / scene.run.time_step));
  for (int k = 1; k <= steps; ++k) {
    ibms::advance_one_step(sim, scene.run.time_step);
    if (k % 50 != 0) continue;
    const ibms::MassSpringBody& body = sim.bodies()[0];
    std::array<double, 2> v{0.0, 0.0};
    for (int p = 0; p < body.n_points(); ++p)
      for (int d = 0; d < 2; ++d) v[d] += body.mass[p] * body.velocity[p][d] / body.total_mass();
    velocities.push_back(v);
  }
  return velocities;
}

}  // namespace

namespace {

// |J_f U_f^{n+1} - U_l^{n+1}| / U_ref, largest over the markers, at each of steps 1..steps of
// falling_wheel.toml's wheel made a rigid disk: the face velocity the constraint held against the
// velocity the body's rim points reached at the end of the same step (the marker system solved to
// 1e-7 U_ref).
std::vector<double> rim_lag(const std::vector<std::string>& overrides, int steps) {
  ibms::set_thread_count(1);
  ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL, overrides);
  scene.bodies[0].kind = ibms::BodySpec::Kind::rigid;
  scene.ibm.slip_tolerance = 1e-7;
  ibms::Simulation sim(scene);
  std::vector<std::array<double, 2>> held;
  std::vector<double> lag;
  for (int k = 1; k <= steps; ++k) {
    ibms::advance_one_step(sim, scene.run.time_step);
    const ibms::BodyCoupling& c = sim.markers()[0];  // the markers of the step, at X^n
    ibms::interpolate_faces(sim.grid(), sim.kernel(), ibms::WallVelocities{}, sim.fluid().velocity_face_x,
                            sim.fluid().velocity_face_y, c.marker, held);
    const ibms::MassSpringBody& body = sim.bodies()[0];
    double largest = 0.0;
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      largest = std::max(largest, std::hypot(held[l][0] - body.velocity[l][0], held[l][1] - body.velocity[l][1]));
    lag.push_back(largest / c.slip_reference_speed);
  }
  return lag;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_rigid_body_answers_its_force_within_the_step) {
  // ibm.rigid_response = "implicit": the marker system holds the rim at the velocity the body reaches
  // at the end of the step (docs/method.md §3.7, "Rigid bodies"). The disk (density 2) is launched
  // at 0.3 into fluid at rest.
  //  - Without the inner-fluid term the response is the body's own: face and rim velocities agree
  //    to the marker system's tolerance at every step, the launch included.
  //  - With it (variant K) the response takes the inner fluid as moving with the body; the launch
  //    sets the inner fluid moving over several steps, and the difference, which the next step's
  //    target takes up, falls by rho_f / rho_s = 1/2 a step.
  //  - "virtual_mass" answers one step late: the difference is the step's velocity change.
  const std::vector<double> own = rim_lag({"ibm.inner_fluid_inertia=\"none\""}, 10);
  const std::vector<double> inner = rim_lag({}, 10);
  const std::vector<double> late = rim_lag({"ibm.rigid_response=\"virtual_mass\""}, 10);
  for (std::size_t k = 0; k < own.size(); ++k) {
    BOOST_TEST_MESSAGE("step " << k + 1 << ": |J_f U_f - U_rim| / U_ref implicit " << own[k] << ", with the inner fluid "
                               << inner[k] << ", virtual mass " << late[k]);
    BOOST_TEST(own[k] < 1e-6);
    if (k > 0 && k < 8) BOOST_TEST(inner[k] / inner[k - 1] < 0.55);
  }
  BOOST_TEST(late[0] > 0.1);
}

BOOST_AUTO_TEST_CASE(a_stiff_mass_spring_wheel_falls_as_the_rigid_disk_under_the_face_constraint) {
  // k_s = 5000: sqrt(k_s / M_i) dt ~ 4.6, so a force on one rim point moves the whole wheel within
  // the step; the response solved with the constraint carries that (under the papers' coupling this
  // wheel's body guard stops the run at step 287). Measured with the marker system solved to 1e-5 U,
  // both responding in it: the wheel falls 0.16, 0.43 and 0.68 % faster than the disk at steps 100,
  // 150 and 200 (0.56-0.63 % when the disk answered one step late, with its virtual mass; that gap
  // was the wheel's own compliance, not the step's error: it grew to 0.79 % at dt / 2 and 0.98 % at
  // dt / 4, where backward Euler damps the wheel's spring modes less).
  const auto wheel = falling_velocities(false);
  const auto disk = falling_velocities(true);
  BOOST_TEST_REQUIRE(wheel.size() == 4u);
  for (std::size_t k = 1; k < wheel.size(); ++k) {  // from step 100 on: after the launch transient
    BOOST_TEST_MESSAGE("step " << 50 * (k + 1) << ": wheel " << wheel[k][1] << ", rigid disk " << disk[k][1]);
    BOOST_TEST(std::abs(wheel[k][1] / disk[k][1] - 1.0) <= 0.01);
    BOOST_TEST(std::abs(wheel[k][0]) <= 1e-4);  // falls straight
  }
}

BOOST_AUTO_TEST_CASE(rigid_and_prescribed_bodies_keep_no_slip_at_the_end_of_every_step) {
  const SlipRecord coupled = slip_over_steps(IBMS_SCENE_RIGID, no_slip, 200);
  BOOST_TEST_MESSAGE("no_slip: largest slip " << coupled.largest << ", GMRES products " << coupled.products);
  BOOST_TEST(coupled.largest <= 1e-4);
  BOOST_TEST(coupled.largest_mismatch <= 1e-12);
  const SlipRecord papers = slip_over_steps(IBMS_SCENE_RIGID, {}, 200);
  BOOST_TEST_MESSAGE("uhlmann: largest slip " << papers.largest);
  BOOST_TEST(papers.largest > 10 * 1e-4);
}

BOOST_AUTO_TEST_CASE(constrained_face_velocities_keep_no_slip_at_the_end_of_every_step_on_a_fixed_cylinder) {
  // On the faces the marker system is nearly singular: a divergence-free field cannot carry a net
  // flux through the closed rim, and J_f of it leaves that part of the target unreachable, at
  // 2.1e-4 U_ref on this D/h = 8 grid. The check holds the 1e-3 U_ref (docs/method.md §3.7).
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                          "ibm.constrained_velocity=\"faces\""};
  const SlipRecord coupled = slip_over_steps(IBMS_SCENE_FIXED_CYLINDER, on_faces, 200, /*faces=*/true);
  BOOST_TEST_MESSAGE("no_slip on faces: largest face slip " << coupled.largest << ", GMRES products " << coupled.products);
  BOOST_TEST(coupled.largest <= 1e-3);
  BOOST_TEST(coupled.largest_mismatch <= 1e-12);
  BOOST_TEST(coupled.largest_divergence <= 1e-10);
  // The cell constraint and the papers' coupling leave the faces slipping on the same scene.
  const SlipRecord cells = slip_over_steps(IBMS_SCENE_FIXED_CYLINDER, no_slip, 200, /*faces=*/true);
  const SlipRecord papers = slip_over_steps(IBMS_SCENE_FIXED_CYLINDER, {}, 200, /*faces=*/true);
  BOOST_TEST_MESSAGE("face slip under no_slip on cells " << cells.largest << ", under uhlmann " << papers.largest);
  BOOST_TEST(cells.largest > 10 * 1e-3);
  BOOST_TEST(papers.largest > 10 * 1e-3);
}

BOOST_AUTO_TEST_CASE(a_fixed_face_term_time_scale_keeps_no_slip_and_divergence_free_faces) {
  // fluid.interpolation_time (docs/method.md §2.3) at twice and at the step: the products and the
  // corrections then project with the mixed operator, and the constraint and the faces' divergence
  // hold as with the step's own time scale.
  for (const char* tau : {"fluid.interpolation_time=0.01", "fluid.interpolation_time=0.005"}) {
    const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                            "ibm.constrained_velocity=\"faces\"", tau};
    const SlipRecord coupled = slip_over_steps(IBMS_SCENE_FIXED_CYLINDER, on_faces, 200, /*faces=*/true);
    BOOST_TEST_MESSAGE(tau << ": largest face slip " << coupled.largest << ", divergence " << coupled.largest_divergence
                           << ", GMRES products " << coupled.products);
    BOOST_TEST(coupled.largest <= 1e-3);
    BOOST_TEST(coupled.largest_mismatch <= 1e-12);
    BOOST_TEST(coupled.largest_divergence <= 1e-10);
  }
}

BOOST_AUTO_TEST_CASE(moving_rigid_and_prescribed_bodies_keep_no_slip_on_the_faces_at_the_end_of_every_step) {
  // A rigid disk launched at an oscillating prescribed disk (contacts, gravity), D/h = 6.4.
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                          "ibm.constrained_velocity=\"faces\""};
  const SlipRecord coupled = slip_over_steps(IBMS_SCENE_RIGID, on_faces, 200, /*faces=*/true);
  BOOST_TEST_MESSAGE("no_slip on faces, moving bodies: largest face slip " << coupled.largest << ", GMRES products "
                                                                           << coupled.products);
  BOOST_TEST(coupled.largest <= 1e-3);
  BOOST_TEST(coupled.largest_mismatch <= 1e-12);
  BOOST_TEST(coupled.largest_divergence <= 1e-10);
}

namespace {

// Largest |V^{n+1} - 2 V^n + V^{n-1}| of body 0's velocity over steps first..last: the step-to-step
// oscillation of an explicitly coupled body (docs/method.md §3.7, virtual mass).
double velocity_alternation(const std::vector<std::string>& overrides, int first, int last) {
  ibms::set_thread_count(1);
  const ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_RIGID, overrides);
  ibms::Simulation sim(scene);
  std::vector<std::array<double, 2>> v;
  double largest = 0.0;
  for (int k = 1; k <= last; ++k) {
    ibms::advance_one_step(sim, scene.run.time_step);
    v.push_back(sim.rigid()[0].state.velocity);
    const std::size_t n = v.size();
    if (n >= 3 && k >= first)
      for (int d = 0; d < 2; ++d) largest = std::max(largest, std::abs(v[n - 1][d] - 2.0 * v[n - 2][d] + v[n - 3][d]));
    if (!(largest < 1e3)) break;
  }
  return largest;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_rigid_body_under_the_face_constraint_does_not_oscillate_from_step_to_step) {
  // Answering its force one step late (ibm.rigid_response = "virtual_mass") without the virtual mass,
  // the constraint force carries the fluid's added mass one step late and the disk (density 2)
  // oscillates from step to step with a growing amplitude (x1.15 per step measured; the body guard
  // of the run loop stops it at step 16). With C_V = 1 the launch into the fluid at rest rings down
  // within 6 steps (largest second difference 0.32 at step 3, 0.003 at step 6). Answering it in the
  // marker system (the default "implicit"), the body needs no virtual mass.
  // All from step 8 to 25, before the disks touch (the contact's own velocity jump would count).
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.constrained_velocity=\"faces\""};
  std::vector<std::string> late = on_faces;
  late.push_back("ibm.rigid_response=\"virtual_mass\"");
  std::vector<std::string> without = late;
  without.push_back("ibm.virtual_mass_coefficient=0");
  const double unstable = velocity_alternation(without, 8, 16);
  const double stable = velocity_alternation(late, 8, 25);
  const double implicit = velocity_alternation(on_faces, 8, 25);
  BOOST_TEST_MESSAGE("largest step-to-step velocity oscillation: one step late, C_V = 0 "
                     << unstable << " (steps 8-16), C_V = 1 " << stable << " (steps 8-25); implicit " << implicit
                     << " (steps 8-25)");
  BOOST_TEST(unstable > 1.0);
  BOOST_TEST(stable < 0.01);
  BOOST_TEST(implicit < 0.01);
}

namespace {

// c_D = 2 F_x / (rho U_ref^2 D) of the fixed cylinder (U_ref = 1) at t = 2 with the step dt.
double drag_at_two(const std::vector<std::string>& overrides, double dt) {
  ibms::set_thread_count(1);
  std::vector<std::string> all = overrides;
  all.push_back("run.time_step=" + std::to_string(dt));
  const ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FIXED_CYLINDER, all);
  ibms::Simulation sim(scene);
  const int steps = static_cast<int>(std::lround(2.0 / dt));
  for (int k = 0; k < steps; ++k) ibms::advance_one_step(sim, dt);
  return 2.0 * sim.markers()[0].hydrodynamic_force[0] / (scene.fluid.density * 1.0 * scene.bodies[0].diameter);  // U_ref = 1
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_drag_under_the_face_constraint_does_not_depend_on_the_time_step) {
  // The fixed cylinder (D/h = 8, Re 12.5) at t = 2 with dt = 0.005 and 0.00125: the forces of the
  // face constraint enter the cells as the mean of their face values, like the pressure gradient, so
  // the cell and face velocities differ by no dt-proportional flux through the body (§3.7). Measured:
  // +0.10 % under "faces", +3.0 % under the papers' coupling.
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-4",
                                          "ibm.constrained_velocity=\"faces\""};
  const double coarse = drag_at_two(on_faces, 0.005), fine = drag_at_two(on_faces, 0.00125);
  const double papers_coarse = drag_at_two({}, 0.005), papers_fine = drag_at_two({}, 0.00125);
  const double change = std::abs(fine / coarse - 1.0), papers_change = std::abs(papers_fine / papers_coarse - 1.0);
  BOOST_TEST_MESSAGE("c_D at dt 0.005 / 0.00125: faces " << coarse << " / " << fine << " (" << 100 * change
                                                          << " %), uhlmann " << papers_coarse << " / " << papers_fine
                                                          << " (" << 100 * papers_change << " %)");
  BOOST_TEST(change <= 0.0025);
  BOOST_TEST(papers_change > 0.02);
}
