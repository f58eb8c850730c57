// Claims of the marker retraction (docs/method.md §3.4) and of multi-direct forcing
// (docs/method.md §3.3), asserted on one 48-point disk of diameter 0.25 in a 64^2 box (h = 1/64):
//   §3.4: with ibm.marker_retraction = r, every marker moves towards the body's centre of mass by
//   r h along its own radius; its velocity relative to the centre is scaled by the same radial
//   factor, so that the target is exact for a rigid motion (translation and rotation) and for a
//   uniform dilation; its volume dV_l = h s_l comes from the moved markers' spacing. A retraction
//   that reaches the centre is refused with a message naming the key.
//   §3.3: with ibm.forcing_passes = m the force is the sum of the passes' forces, each pass
//   F = (U_target - J u~)/dt on the velocity the earlier passes forced, so the sum of two passes
//   equals one pass plus a second computed here from the first pass's forced field; more passes
//   leave less slip at the markers (fluid at rest, a moving body).
#define BOOST_TEST_MODULE marker_retraction_and_passes
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "ibm/ib_operators.hpp"
#include "ibm/marker_weights.hpp"
#include "sim/simulation.hpp"
#include "sim_scenes.hpp"

using namespace ibms;

namespace {

Scene disk_scene() {
  Scene scene = test::one_body_scene(/*n=*/64, /*periodic=*/true, /*diameter=*/0.25, /*density=*/1.5,
                                     /*stiffness=*/1e4);
  scene.ibm.inner_fluid_inertia = IbmSpec::InnerFluidInertia::none;
  return scene;
}

// Point velocities U_p = U + w x (X_p - X_c) + g (X_p - X_c) of the body (translation, rotation, dilation).
void set_motion(MassSpringBody& body, Vec2 translation, double rotation, double dilation) {
  const Vec2 x_c = centre_of_mass(body);
  for (int p = 0; p < body.n_points(); ++p) {
    const double rx = body.position[p][0] - x_c[0], ry = body.position[p][1] - x_c[1];
    body.velocity[p] = {translation[0] - rotation * ry + dilation * rx, translation[1] + rotation * rx + dilation * ry};
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(retracted_markers_move_inward_by_r_h_and_keep_rigid_and_dilating_targets) {
  Simulation sim(disk_scene());
  const double h = sim.grid().dx(), r = 0.3;
  MassSpringBody& body = sim.bodies()[0];
  const Vec2 x_c = centre_of_mass(body);
  const Vec2 translation{0.7, -0.4};
  const double rotation = 2.5, dilation = 0.8;
  set_motion(body, translation, rotation, dilation);
  prepare_markers(sim.bodies(), sim.swelling(), 0.0, 0.0, sim.grid(), false, sim.markers(), r * h);
  const BodyCoupling& c = sim.markers()[0];
  BOOST_TEST(c.marker.size() == static_cast<std::size_t>(body.n_surface));
  double radius_error = 0.0, direction_error = 0.0, target_error = 0.0;
  for (std::size_t l = 0; l < c.marker.size(); ++l) {
    const double px = body.position[l][0] - x_c[0], py = body.position[l][1] - x_c[1];
    const double mx = c.marker[l][0] - x_c[0], my = c.marker[l][1] - x_c[1];
    radius_error = std::max(radius_error, std::abs(std::hypot(mx, my) - (std::hypot(px, py) - r * h)));
    direction_error = std::max(direction_error, std::abs(px * my - py * mx) / std::hypot(px, py));  // parallel
    // The rigid and dilating motion evaluated at the moved marker itself.
    const Vec2 exact{translation[0] - rotation * my + dilation * mx, translation[1] + rotation * mx + dilation * my};
    target_error = std::max(target_error, std::hypot(c.target_velocity[l][0] - exact[0], c.target_velocity[l][1] - exact[1]));
  }
  BOOST_TEST_MESSAGE("radius error " << radius_error << ", direction error " << direction_error << ", target error "
                                     << target_error);
  BOOST_TEST(radius_error <= 1e-14);
  BOOST_TEST(direction_error <= 1e-14);
  BOOST_TEST(target_error <= 1e-13);
  // dV_l from the moved markers: h times half the two adjacent spacings, computed here.
  double volume_error = 0.0, moved_sum = 0.0, unmoved_sum = 0.0;
  const std::size_t n = c.marker.size();
  for (std::size_t l = 0; l < n; ++l) {
    const Vec2& a = c.marker[(l + n - 1) % n];
    const Vec2& m = c.marker[l];
    const Vec2& z = c.marker[(l + 1) % n];
    const double expected = h * 0.5 * (std::hypot(m[0] - a[0], m[1] - a[1]) + std::hypot(z[0] - m[0], z[1] - m[1]));
    volume_error = std::max(volume_error, std::abs(c.marker_volume[l] - expected) / expected);
    moved_sum += c.marker_volume[l];
    const Vec2& pa = body.position[(l + n - 1) % n];
    const Vec2& pm = body.position[l];
    const Vec2& pz = body.position[(l + 1) % n];
    unmoved_sum += h * 0.5 * (std::hypot(pm[0] - pa[0], pm[1] - pa[1]) + std::hypot(pz[0] - pm[0], pz[1] - pm[1]));
  }
  BOOST_TEST(volume_error <= 1e-13);
  // On a regular polygon the moved ring is the same polygon scaled by (R - r h) / R.
  const double radius = std::hypot(body.position[0][0] - x_c[0], body.position[0][1] - x_c[1]);
  BOOST_TEST(std::abs(moved_sum / unmoved_sum - (radius - r * h) / radius) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(a_retraction_that_reaches_the_centre_is_refused_naming_the_key) {
  Simulation sim(disk_scene());
  std::string message;
  try {
    prepare_markers(sim.bodies(), sim.swelling(), 0.0, 0.0, sim.grid(), false, sim.markers(), 0.2);  // > radius 0.125
  } catch (const std::exception& e) {
    message = e.what();
  }
  BOOST_TEST(message.find("ibm.marker_retraction") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_force_of_several_passes_is_the_sum_of_the_passes_and_each_pass_lowers_the_slip) {
  const double dt = 1e-3;
  const auto forced = [&](int passes, std::vector<Vec2>& force, CellField& u, CellField& v) {
    Simulation sim(disk_scene());
    set_motion(sim.bodies()[0], {1.0, 0.5}, 3.0, 0.0);
    prepare_markers(sim.bodies(), sim.swelling(), 0.0, 0.0, sim.grid(), false, sim.markers());
    u = sim.fluid().velocity_x;  // fluid at rest
    v = sim.fluid().velocity_y;
    for (BodyCoupling& c : sim.markers()) std::fill(c.forcing_sum.begin(), c.forcing_sum.end(), Vec2{0.0, 0.0});
    apply_direct_forcing(sim.grid(), sim.kernel(), {}, dt, passes, sim.markers(), u, v);
    force = sim.markers()[0].forcing_sum;
    // The slip left at the markers, largest over them, relative to the largest target speed.
    std::vector<Vec2> at;
    interpolate(sim.grid(), sim.kernel(), {}, u, v, sim.markers()[0].marker, at);
    double slip = 0.0, speed = 0.0;
    const BodyCoupling& c = sim.markers()[0];
    for (std::size_t l = 0; l < at.size(); ++l) {
      slip = std::max(slip, std::hypot(at[l][0] - c.target_velocity[l][0], at[l][1] - c.target_velocity[l][1]));
      speed = std::max(speed, std::hypot(c.target_velocity[l][0], c.target_velocity[l][1]));
    }
    return slip / speed;
  };
  std::vector<Vec2> one, two, three;
  CellField u1, v1, u2, v2, u3, v3;
  const double slip1 = forced(1, one, u1, v1);
  const double slip2 = forced(2, two, u2, v2);
  const double slip3 = forced(3, three, u3, v3);
  BOOST_TEST_MESSAGE("slip after 1 / 2 / 3 passes: " << slip1 << " / " << slip2 << " / " << slip3);
  BOOST_TEST(slip2 < 0.7 * slip1);
  BOOST_TEST(slip3 < 0.7 * slip2);
  // The second pass computed here from the first pass's forced field: F2 = (U_target - J u1) / dt.
  Simulation sim(disk_scene());
  set_motion(sim.bodies()[0], {1.0, 0.5}, 3.0, 0.0);
  prepare_markers(sim.bodies(), sim.swelling(), 0.0, 0.0, sim.grid(), false, sim.markers());
  const BodyCoupling& c = sim.markers()[0];
  std::vector<Vec2> at;
  interpolate(sim.grid(), sim.kernel(), {}, u1, v1, c.marker, at);
  double sum_error = 0.0, scale = 0.0;
  for (std::size_t l = 0; l < at.size(); ++l)
    for (int d = 0; d < 2; ++d) {
      const double second = (c.target_velocity[l][d] - at[l][d]) / dt;
      sum_error = std::max(sum_error, std::abs(two[l][d] - (one[l][d] + second)));
      scale = std::max(scale, std::abs(two[l][d]));
    }
  BOOST_TEST_MESSAGE("largest |F(2 passes) - F1 - F2| / max |F| " << sum_error / scale);
  BOOST_TEST(sum_error <= 1e-12 * scale);
}
