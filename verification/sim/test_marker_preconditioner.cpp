// The marker system's preconditioner (sim/coupling/marker_preconditioner.hpp) inverts what it
// claims to.
//  - Faces: its block applied to J_f P_0 S_f x (spreading onto the faces, the solver's projection,
//    interpolation) gives x back, up to the walls' and periodic images' part of L^{-1} that the
//    lattice Green's function leaves out: it falls as (D / L)^2 with the box and is below 1e-3 in a box
//    20 D wide; in a box 5 D wide it is 3.5 % across a periodic side and 14 % for a rim 0.8 h from
//    a wall, whose nearest image the block holds (96 % without it).
//  - Cells: its block applied to J S x gives x back (the block is J S body by body, walls and
//    images included).
//  - A mass-spring rim, which responds in the marker system: under the face constraint its block
//    applied to (D + R) x gives x back, D the diagonal of J_f S_f (measured here by spreading a
//    unit force from one marker and interpolating it there) and R its response through its
//    implicit system; without the rim's implicit system it keeps the identity.
#define BOOST_TEST_MODULE marker_preconditioner
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fluid/threads.hpp"
#include "ibm/ib_operators.hpp"
#include "scene/scene_reader.hpp"
#include "sim/coupling/marker_preconditioner.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"
#include "solid/implicit_euler.hpp"

namespace {

using ibms::Vec2;

// Largest |M^-1 A x - x| / largest |x| for a random x on the markers of falling_wheel.toml's wheel,
// made a rigid disk, placed at `centre` in a box `scale` times as large (cells and length):
// A = J_f P_0 S_f on the faces, J S on the cell centres.
double round_trip_error(const Vec2& centre, bool periodic, bool on_faces, double scale = 1.0) {
  ibms::set_thread_count(1);
  ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL);
  scene.domain.length_x *= scale;
  scene.domain.length_y *= scale;
  scene.domain.cells_x = static_cast<int>(std::lround(scene.domain.cells_x * scale));
  scene.domain.cells_y = static_cast<int>(std::lround(scene.domain.cells_y * scale));
  scene.bodies[0].centre = centre;
  // A rim that does not respond. Prescribed: on the faces its block is J_f P_0 S_f.
  scene.bodies[0].kind = ibms::BodySpec::Kind::prescribed;
  scene.domain.periodic_x = periodic;
  ibms::Simulation sim(scene);
  ibms::advance_one_step(sim, scene.run.time_step);  // markers at t^1
  const ibms::Grid& grid = sim.grid();
  std::vector<ibms::BodyCoupling>& coupling = sim.markers();
  const ibms::BodyCoupling& c = coupling[0];
  const std::size_t n = c.marker.size();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Vec2> x(n), jsx;
  std::vector<double> y(2 * n), z(2 * n);
  for (Vec2& v : x) v = {uniform(random), uniform(random)};
  if (on_faces) {
    ibms::FaceField fx = ibms::FaceField::x_faces(grid), fy = ibms::FaceField::y_faces(grid);
    ibms::CellField cx(grid), cy(grid);
    ibms::spread_to_faces(grid, sim.kernel(), c.marker, x, c.marker_volume, fx, fy);
    ibms::FluidSolver& solver = sim.fluid_solver();
    solver.homogeneous_projection(scene.run.time_step, cx, cy, &fx, &fy);
    ibms::interpolate_faces(grid, sim.kernel(), ibms::WallVelocities{}, solver.projected_face_increment_x(),
                            solver.projected_face_increment_y(), c.marker, jsx);
  } else {
    ibms::CellField fx(grid), fy(grid);
    ibms::spread(grid, sim.kernel(), c.marker, x, c.marker_volume, fx, fy);
    ibms::interpolate(grid, sim.kernel(), ibms::WallVelocities{}, fx, fy, c.marker, jsx);
  }
  for (std::size_t l = 0; l < n; ++l)
    for (int d = 0; d < 2; ++d) y[2 * l + d] = jsx[l][d];
  ibms::MarkerPreconditioner preconditioner;
  preconditioner.reserve(coupling, sim.scene().fluid.density, sim.scene().ibm.preconditioner_drift);
  const ibms::FluidSolver::FaceRange free_faces = sim.fluid_solver().corrected_faces();
  for (ibms::BodyCoupling& body : coupling) ibms::map_face_stencils(grid, sim.kernel(), body.marker, body.face_stencils);
  // Leaks to measure: the cells' blocks once, then kept while nothing moves; none on the faces.
  BOOST_TEST(preconditioner.factorise(grid, sim.kernel(), on_faces, free_faces, coupling) == !on_faces);
  BOOST_TEST(!preconditioner.factorise(grid, sim.kernel(), on_faces, free_faces, coupling));
  std::vector<double> no_leak(2 * n, 0.0);
  preconditioner.set_leaks(coupling, no_leak.data());
  preconditioner.apply(coupling, y.data(), z.data());
  double error = 0.0, size = 0.0;
  for (std::size_t l = 0; l < n; ++l)
    for (int d = 0; d < 2; ++d) {
      error = std::max(error, std::abs(z[2 * l + d] - x[l][d]));
      size = std::max(size, std::abs(x[l][d]));
    }
  return error / size;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_face_block_is_the_projected_operator_but_for_the_far_walls) {
  // Wheel D = 0.2 at the centre of boxes 10 D and 20 D wide (64^2 and 128^2 cells, h = 1/32): what
  // the block leaves out is the far walls' part of L^{-1}, which falls as (D / L)^2.
  const double near = round_trip_error({1.0, 1.0}, false, true, 2.0);
  const double far = round_trip_error({2.0, 2.0}, false, true, 4.0);
  BOOST_TEST_MESSAGE("faces, boxes 10 D and 20 D: " << near << ", " << far << " (ratio " << near / far << ")");
  BOOST_TEST(near / far > 3.5);
  BOOST_TEST(far < 1e-3);
}

BOOST_AUTO_TEST_CASE(the_blocks_near_a_wall_and_across_a_periodic_side) {
  // Wheel D = 0.2 on a 32^2 box (h = 1/32): its rim passes 0.025 = 0.8 h from the bottom wall,
  // inside the kernel's reach of the mirror nodes; then 0.02 = 0.64 h from x = 0, periodic, where
  // its stencils wrap to the last columns. Cells: J S exactly; faces: the operator without the
  // images' part of L^{-1}.
  for (const bool periodic : {false, true}) {
    const Vec2 centre = periodic ? Vec2{0.12, 0.5} : Vec2{0.5, 0.125};
    const double cells = round_trip_error(centre, periodic, false);
    const double faces = round_trip_error(centre, periodic, true);
    BOOST_TEST_MESSAGE((periodic ? "periodic side" : "wall") << ": cells " << cells << ", faces " << faces);
    BOOST_TEST(cells < 1e-6);
    BOOST_TEST(faces < (periodic ? 0.05 : 0.2));  // the near wall's image in; without it 0.96
  }
}

BOOST_AUTO_TEST_CASE(a_responding_rim_without_its_implicit_system_keeps_the_identity) {
  ibms::set_thread_count(1);
  const ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL);  // a mass-spring wheel, no_slip
  ibms::Simulation sim(scene);
  ibms::advance_one_step(sim, scene.run.time_step);
  std::vector<ibms::BodyCoupling>& coupling = sim.markers();
  BOOST_TEST_REQUIRE(!coupling[0].body_velocity_change.empty());
  const std::size_t n = 2 * coupling[0].marker.size();
  std::vector<double> v(n), x(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) v[k] = 0.1 * static_cast<double>(k) - 1.0;
  ibms::MarkerPreconditioner preconditioner;
  preconditioner.reserve(coupling, sim.scene().fluid.density, sim.scene().ibm.preconditioner_drift);
  for (ibms::BodyCoupling& body : coupling) ibms::map_face_stencils(sim.grid(), sim.kernel(), body.marker, body.face_stencils);
  preconditioner.factorise(sim.grid(), sim.kernel(), true, sim.fluid_solver().corrected_faces(), coupling);
  preconditioner.set_leaks(coupling, v.data());
  preconditioner.apply(coupling, v.data(), x.data());
  BOOST_TEST(x == v, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_responding_rim_inverts_its_response_and_the_diagonal_of_the_spread) {
  ibms::set_thread_count(1);
  const ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL);  // a mass-spring wheel, no_slip
  ibms::Simulation sim(scene);
  ibms::advance_one_step(sim, scene.run.time_step);
  const ibms::Grid& grid = sim.grid();
  std::vector<ibms::BodyCoupling>& coupling = sim.markers();
  ibms::BodyCoupling& c = coupling[0];
  const ibms::MassSpringBody& body = sim.bodies()[0];
  BOOST_TEST_REQUIRE(c.marker.size() + 1 == static_cast<std::size_t>(body.n_points()));  // markers = rim points
  const std::size_t n = 2 * c.marker.size();
  const double density = sim.scene().fluid.density;
  // The rim's implicit system over the step, as the coupling factorises it (no external force).
  std::vector<ibms::ImplicitSpringSystem> systems(1);
  std::vector<Vec2> no_force(body.n_points(), Vec2{0.0, 0.0});
  systems[0].velocity_change(body, scene.run.time_step, no_force);
  ibms::MarkerPreconditioner preconditioner;
  preconditioner.reserve(coupling, density, sim.scene().ibm.preconditioner_drift);
  preconditioner.attach_rim_systems(&systems);
  for (ibms::BodyCoupling& b : coupling) ibms::map_face_stencils(grid, sim.kernel(), b.marker, b.face_stencils);
  BOOST_TEST(!preconditioner.factorise(grid, sim.kernel(), true, sim.fluid_solver().corrected_faces(), coupling));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> v(n), x(n, 0.0);
  for (double& e : v) e = uniform(random);
  preconditioner.apply(coupling, v.data(), x.data());
  // D: J_f S_f of a unit force at each marker and component, read at that marker.
  std::vector<double> diagonal(n);
  ibms::FaceField fx = ibms::FaceField::x_faces(grid), fy = ibms::FaceField::y_faces(grid);
  std::vector<Vec2> unit(c.marker.size()), at_markers;
  for (std::size_t q = 0; q < n; ++q) {
    std::fill(unit.begin(), unit.end(), Vec2{0.0, 0.0});
    unit[q / 2][q % 2] = 1.0;
    fx.fill(0.0);
    fy.fill(0.0);
    ibms::spread_to_faces(grid, sim.kernel(), c.marker, unit, c.marker_volume, fx, fy);
    ibms::interpolate_faces(grid, sim.kernel(), ibms::WallVelocities{}, fx, fy, c.marker, at_markers);
    diagonal[q] = at_markers[q / 2][q % 2];
  }
  // R x: the rim points' velocity change under the reaction of the impulses x, K^-1 (rho_f dV x)
  // with the sign of the marker system's product (which subtracts the change).
  std::vector<double> response(2 * body.n_points(), 0.0);
  for (std::size_t q = 0; q < n; ++q) response[q] = density * c.marker_volume[q / 2] * x[q];
  systems[0].response(response);
  double error = 0.0, size = 0.0, response_size = 0.0;
  for (std::size_t q = 0; q < n; ++q) {
    error = std::max(error, std::abs(diagonal[q] * x[q] + response[q] - v[q]));
    size = std::max(size, std::abs(v[q]));
    response_size = std::max(response_size, std::abs(response[q]));
  }
  BOOST_TEST_MESSAGE("(D + R) M^-1 v - v: " << error / size << " of v; R M^-1 v up to " << response_size / size);
  BOOST_TEST(error / size < 1e-12);
  BOOST_TEST(response_size / size > 1e-2);  // the response is a part of the block, not a rounding
}

// ibm.rim_preconditioner reaches the coupling: the run's stage description names the rims' block
// the scene chose (the identity by default).
BOOST_AUTO_TEST_CASE(the_scene_chooses_the_rims_block) {
  const auto description = [](const std::string& choice) {
    const std::vector<std::string> set = choice.empty() ? std::vector<std::string>{}
                                                        : std::vector<std::string>{"ibm.rim_preconditioner=" + choice};
    const ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL, set);
    const ibms::Simulation sim(scene);
    for (const std::string& stage : sim.stage_names())
      if (stage.find("mass-spring rims by") != std::string::npos) return stage;
    return std::string("(no stage names the rims' block)");
  };
  BOOST_TEST(description("").find("mass-spring rims by the identity") != std::string::npos);
  BOOST_TEST(description("\"identity\"").find("mass-spring rims by the identity") != std::string::npos);
  BOOST_TEST(description("\"response\"").find("mass-spring rims by their response") != std::string::npos);
}

// ibm.preconditioner_drift = "auto" keeps the moving bodies' own blocks within 0.1 cell when their
// unknowns, the sum of (2 n_b)^2, outnumber the grid's cells, and builds them at every move
// otherwise; a number given in the scene is taken as it is. The run's stage description says which.
BOOST_AUTO_TEST_CASE(automatic_drift_keeps_blocks_only_where_they_outnumber_the_cells) {
  const auto description = [](int cells, const std::string& drift) {
    ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL, {"ibm.preconditioner_drift=" + drift});
    scene.bodies[0].kind = ibms::BodySpec::Kind::prescribed;  // a body with its own block
    scene.domain.cells_x = scene.domain.cells_y = cells;
    const ibms::Simulation sim(scene);
    for (const std::string& stage : sim.stage_names())
      if (stage.find("drift") != std::string::npos) return stage;
    return std::string("(no stage names the drift)");
  };
  // One disk of 16 markers: (2 x 16)^2 = 1024 unknowns^2 against 32 x 32 = 1024 and 24 x 24 = 576 cells.
  BOOST_TEST(description(32, "\"auto\"").find("drift 0 cells") != std::string::npos);
  BOOST_TEST(description(24, "\"auto\"").find("drift 0.1 cells") != std::string::npos);
  BOOST_TEST(description(24, "0").find("drift 0 cells") != std::string::npos);
  BOOST_TEST(description(32, "0.25").find("drift 0.25 cells") != std::string::npos);
}
