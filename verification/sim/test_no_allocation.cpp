// No allocation inside the step (docs/design.md §9): after a warm-up, during which work
// arrays reach their size (contacts have begun, triangle overlaps settled), further fluid steps with
// bodies, swelling, DEM contacts, rigid and prescribed bodies call operator new zero times, and so
// does the run loop's control-volume force of every body around each step. The global operator new
// of this test program counts the calls while `counting` is set.
#define BOOST_TEST_MODULE no_allocation
#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "fluid/threads.hpp"
#include "scene/scene_reader.hpp"
#include "sim/checks/control_volume_monitor.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

namespace {
bool counting = false;
long n_allocations = 0;
}  // namespace

void* operator new(std::size_t size) {
  if (counting) ++n_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

// One thread: the OpenMP runtime's worker threads make their own thread-local scratch when they
// first take a body group, which with dynamic scheduling may happen after any warm-up.
// With control_volumes, every step is wrapped as in the run loop (sim/run/run.cpp): the control-volume
// balance after the step and at the start of the next one.
long allocations_in_steps(const char* scene_path, int warm_up, int counted,
                          const std::vector<std::string>& overrides = {}, bool control_volumes = false) {
  ibms::set_thread_count(1);
  const ibms::Scene scene = ibms::read_scene_file(scene_path, overrides);
  ibms::Simulation sim(scene);
  ibms::ControlVolumeMonitor monitor(sim);
  const double dt = scene.run.time_step;
  const auto step = [&]() {
    ibms::advance_one_step(sim, dt);
    if (control_volumes) {
      monitor.end_step(sim, dt);
      monitor.begin_step(sim);
    }
  };
  if (control_volumes) monitor.begin_step(sim);
  for (int k = 0; k < warm_up; ++k) step();
  n_allocations = 0;
  counting = true;
  for (int k = 0; k < counted; ++k) step();
  counting = false;
  BOOST_TEST_MESSAGE(scene_path << ": " << n_allocations << " allocations in steps " << warm_up << " to "
                                << warm_up + counted << ", contact pairs last step "
                                << sim.stats().last_contact_stats.n_active_pairs << ", wall contacts "
                                << sim.stats().last_contact_stats.n_wall_contacts);
  return n_allocations;
}

}  // namespace

BOOST_AUTO_TEST_CASE(mass_spring_bodies_with_swelling_and_contacts_step_without_allocating) {
  // Wheel-wheel contact from step 34, wheel-wall from step 70 (restart_scene.toml).
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, /*warm_up=*/100, /*counted=*/150) == 0);
}

BOOST_AUTO_TEST_CASE(implicit_springs_and_global_substeps_step_without_allocating) {
  // The same scene with the springs' implicit step (its LDL^T storage is made once per body) and
  // with global sub-steps (run.solid_substeps = "global").
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150,
                                  {"bodies.0.spring_integrator=implicit", "bodies.1.spring_integrator=implicit"}) == 0);
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150, {"run.solid_substeps=global"}) == 0);
}

BOOST_AUTO_TEST_CASE(collision_time_contacts_step_without_allocating) {
  // The same scene with contact.model = "collision_time" (k per contact, docs/method.md §5.5), in
  // the inner loop (the default) and with the shared sub-step.
  const std::vector<std::string> collision_time{"contact.model=\"collision_time\"", "contact.stiffness=0"};
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150, collision_time) == 0);
  std::vector<std::string> shared = collision_time;
  shared.push_back("contact.time_stepping=\"shared\"");
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150, shared) == 0);
}

BOOST_AUTO_TEST_CASE(rigid_and_prescribed_bodies_with_contacts_step_without_allocating) {
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_RIGID, /*warm_up=*/60, /*counted=*/140) == 0);
}

BOOST_AUTO_TEST_CASE(control_volume_forces_around_the_steps_allocate_nothing) {
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150, {}, /*control_volumes=*/true) == 0);
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_RIGID, 60, 140, {}, /*control_volumes=*/true) == 0);
}

BOOST_AUTO_TEST_CASE(no_slip_coupling_steps_without_allocating) {
  // ibm.coupling = "no_slip" (rigid and prescribed bodies): GMRES storage is reserved for the largest marker count, the force
  // fields on cells and faces are made once, the previous forces keep their capacity.
  const std::vector<std::string> no_slip{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-4"};
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_RIGID, 60, 140, no_slip) == 0);
  // The constraint on the face velocities (interpolate_faces fills the markers' velocity in place).
  const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                          "ibm.constrained_velocity=\"faces\""};
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_FIXED_CYLINDER, 60, 140, on_faces) == 0);
  // A prescribed body that moves: its own operator is rebuilt and factorised in place every step.
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_RIGID, 60, 140, on_faces) == 0);
  // Mass-spring bodies under it (swelling, contacts): the rim's response is factorised in storage
  // made at the first step, its work vectors sized when the Simulation is built.
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150, on_faces) == 0);
  // With sub-markers and the rims' preconditioner block: the markers come and go within the
  // capacity reserved for the swollen rims, and the block's work is sized by the body points.
  const std::vector<std::string> sub_markers{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-3",
                                             "ibm.constrained_velocity=\"faces\"", "ibm.sub_markers=true",
                                             "ibm.rim_preconditioner=\"response\""};
  BOOST_TEST(allocations_in_steps(IBMS_SCENE_MASS_SPRING, 100, 150, sub_markers) == 0);
}
