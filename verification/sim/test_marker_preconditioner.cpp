// The marker system's preconditioner (sim/coupling/marker_preconditioner.hpp) inverts what it
// claims to: for a body whose markers reach into a wall's mirror nodes, and for one that wraps a
// periodic side, its block applied to J S x (spreading then interpolation, on the faces and on the
// cell centres) gives x back, so the block is J S body by body, walls and images included; a
// mass-spring rim, which responds in the marker system, keeps the identity.
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

namespace {

using ibms::Vec2;

// Largest |M^-1 J S x - x| / largest |x| for a random x on the markers of falling_wheel.toml's wheel,
// made a rigid disk, placed at `centre`.
double round_trip_error(const Vec2& centre, bool periodic, bool on_faces) {
  ibms::set_thread_count(1);
  ibms::Scene scene = ibms::read_scene_file(IBMS_SCENE_FALLING_WHEEL);
  scene.bodies[0].centre = centre;
  scene.bodies[0].kind = ibms::BodySpec::Kind::rigid;  // a rim that does not respond: its block is J S
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
    ibms::spread_to_faces(grid, sim.kernel(), c.marker, x, c.marker_volume, fx, fy);
    ibms::interpolate_faces(grid, sim.kernel(), ibms::WallVelocities{}, fx, fy, c.marker, jsx);
  } else {
    ibms::CellField fx(grid), fy(grid);
    ibms::spread(grid, sim.kernel(), c.marker, x, c.marker_volume, fx, fy);
    ibms::interpolate(grid, sim.kernel(), ibms::WallVelocities{}, fx, fy, c.marker, jsx);
  }
  for (std::size_t l = 0; l < n; ++l)
    for (int d = 0; d < 2; ++d) y[2 * l + d] = jsx[l][d];
  ibms::MarkerPreconditioner preconditioner;
  preconditioner.reserve(coupling);
  BOOST_TEST(preconditioner.factorise(grid, sim.kernel(), on_faces, coupling));
  BOOST_TEST(!preconditioner.factorise(grid, sim.kernel(), on_faces, coupling));  // kept: nothing moved
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

BOOST_AUTO_TEST_CASE(the_block_inverts_spreading_then_interpolation_by_a_wall) {
  // Wheel D = 0.2 on a 32^2 box (h = 1/32): its rim passes 0.025 = 0.8 h from the bottom wall,
  // inside the kernel's reach of the mirror nodes.
  for (const bool faces : {true, false}) {
    const double error = round_trip_error({0.5, 0.125}, false, faces);
    BOOST_TEST_MESSAGE((faces ? "faces" : "cells") << ": " << error);
    BOOST_TEST(error < 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(the_block_inverts_spreading_then_interpolation_across_a_periodic_side) {
  // The rim passes 0.02 = 0.64 h from x = 0: its stencils wrap to the last columns.
  for (const bool faces : {true, false}) {
    const double error = round_trip_error({0.12, 0.5}, true, faces);
    BOOST_TEST_MESSAGE((faces ? "faces" : "cells") << ": " << error);
    BOOST_TEST(error < 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(a_responding_rim_keeps_the_identity) {
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
  preconditioner.reserve(coupling);
  preconditioner.factorise(sim.grid(), sim.kernel(), true, coupling);
  preconditioner.set_leaks(coupling, v.data());
  preconditioner.apply(coupling, v.data(), x.data());
  BOOST_TEST(x == v, boost::test_tools::per_element());
}
