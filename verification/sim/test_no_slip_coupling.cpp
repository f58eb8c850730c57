// The no_slip coupling (sim/no_slip_coupling.hpp) holds what it claims: after every step the
// velocity interpolated at the markers equals the forcing target within ibm.slip_tolerance U_ref,
// measured here independently of the coupling's own bookkeeping, for rigid and prescribed bodies
// with contacts. Mass-spring bodies are refused under it (scene/scene_checks.cpp says why). The papers' coupling leaves a slip
// far above that tolerance on the same scenes, so the check can tell the two apart. With
// ibm.constrained_velocity = "faces" the same holds of the face velocities J_f U_f^{n+1}, checked on
// a fixed cylinder in a channel.
#define BOOST_TEST_MODULE no_slip_coupling
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <exception>
#include <cmath>
#include <string>
#include <vector>

#include "fluid/threads.hpp"
#include "scene/scene_reader.hpp"
#include "sim/simulation.hpp"

namespace {

struct SlipRecord {
  double largest = 0.0;            // largest slip / U_ref of any marker after any step
  double largest_reported = 0.0;   // largest BodyCoupling::slip_max
  double largest_mismatch = 0.0;   // |independent - reported| over bodies and steps
  long products = 0;               // GMRES products over the run
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
    // The markers and targets of the step are those of t^n (the bodies have moved since).
    const ibms::WallVelocities walls = ibms::wall_velocities_at(sim.boundaries(), sim.fluid().time);
    for (const ibms::BodyCoupling& c : sim.coupling()) {
      if (faces)
        ibms::interpolate_faces(sim.grid(), sim.kernel(), walls, sim.fluid().velocity_face_x, sim.fluid().velocity_face_y,
                                c.marker, at_markers);
      else
        ibms::interpolate(sim.grid(), sim.kernel(), walls, sim.fluid().velocity_x, sim.fluid().velocity_y, c.marker,
                          at_markers);
      double body_largest = 0.0;
      for (std::size_t l = 0; l < c.marker.size(); ++l)
        body_largest = std::max(body_largest, std::hypot(at_markers[l][0] - c.target_velocity[l][0],
                                                         at_markers[l][1] - c.target_velocity[l][1]));
      body_largest /= c.slip_reference_speed;
      record.largest = std::max(record.largest, body_largest);
      const double reported = faces ? c.face_slip_max : c.slip_max;
      record.largest_reported = std::max(record.largest_reported, reported);
      record.largest_mismatch = std::max(record.largest_mismatch, std::abs(body_largest - reported));
    }
  }
  record.products = sim.total_coupling_iterations;
  return record;
}

const std::vector<std::string> no_slip{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-4"};

}  // namespace

BOOST_AUTO_TEST_CASE(a_mass_spring_body_under_the_no_slip_coupling_is_refused_naming_the_key) {
  try {
    ibms::read_scene_file(IBMS_SCENE_MASS_SPRING, no_slip);
    BOOST_FAIL("a mass_spring body with ibm.coupling = \"no_slip\" was accepted");
  } catch (const std::exception& e) {
    const std::string message = e.what();
    BOOST_TEST_MESSAGE(message);
    BOOST_TEST(message.find("ibm.coupling") != std::string::npos);
    BOOST_TEST(message.find("mass_spring") != std::string::npos);
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
  // The cell constraint and the papers' coupling leave the faces slipping on the same scene.
  const SlipRecord cells = slip_over_steps(IBMS_SCENE_FIXED_CYLINDER, no_slip, 200, /*faces=*/true);
  const SlipRecord papers = slip_over_steps(IBMS_SCENE_FIXED_CYLINDER, {}, 200, /*faces=*/true);
  BOOST_TEST_MESSAGE("face slip under no_slip on cells " << cells.largest << ", under uhlmann " << papers.largest);
  BOOST_TEST(cells.largest > 10 * 1e-3);
  BOOST_TEST(papers.largest > 10 * 1e-3);
}

BOOST_AUTO_TEST_CASE(moving_bodies_under_the_face_constraint_are_refused_naming_the_key) {
  try {
    ibms::read_scene_file(IBMS_SCENE_RIGID, {"ibm.coupling=\"no_slip\"", "ibm.constrained_velocity=\"faces\""});
    BOOST_FAIL("moving bodies with ibm.constrained_velocity = \"faces\" were accepted");
  } catch (const std::exception& e) {
    const std::string message = e.what();
    BOOST_TEST_MESSAGE(message);
    BOOST_TEST(message.find("ibm.constrained_velocity") != std::string::npos);
  }
}
