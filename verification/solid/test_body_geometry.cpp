// The geometric diagnostics the cavity checks rely on (solid/body_geometry.hpp), each against a
// configuration with a known answer:
//   - deformation parameter: 0 for the regular wheel, (a - b)/(a + b) for rim points on an
//     ellipse with semi-axes a, b (N divisible by 4, so both axes carry points), at any rotation;
//   - separation: two wheels D = 0.2 whose centres are 0.25 apart along x, rim point 0 of each on
//     the joining line, are 0.05 apart; no point is inside the other; the wall distance is the
//     smallest of the rim extents to the box; rim points inside the other body and crossing rim
//     edges are counted; periodic directions use the minimum image (bodies across the seam);
//   - self-crossings: a regular rim has none; a rim with two points swapped (a bow tie in it)
//     has exactly one pair of crossing edges, counted for one body as for several; a rigid
//     body's rim is not examined;
//   - the broad phase (pairs from hashed boxes) gives exactly what every pair of bodies and points
//     gives, on scattered, overlapping wheels, dense and sparse, with walls and periodic.
#define BOOST_TEST_MODULE body_geometry
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/constants.hpp"
#include "solid/body_geometry.hpp"
#include "solid/mass_spring_body.hpp"

using namespace ibms;

namespace {

MassSpringBody wheel(std::array<double, 2> centre, double diameter, int n) {
  BodyParameters spec;
  spec.centre = centre;
  spec.diameter = diameter;
  spec.n_surface_points = n;
  spec.density = 1.0;
  spec.spring_stiffness = 1.0;
  return build_wheel(spec);
}

}  // namespace

BOOST_AUTO_TEST_CASE(deformation_parameter_of_circle_and_ellipse) {
  MassSpringBody body = wheel({0.3, 0.7}, 0.2, 24);
  BOOST_TEST(deformation_parameter(body) < 1e-14);
  const double a = 0.13, b = 0.07;
  for (double angle : {0.0, 0.4, 1.3}) {
    for (int l = 0; l < body.n_surface; ++l) {
      const double phi = 2 * pi * l / body.n_surface;
      const double x = a * std::cos(phi), y = b * std::sin(phi);
      body.position[l] = {0.3 + std::cos(angle) * x - std::sin(angle) * y,
                          0.7 + std::sin(angle) * x + std::cos(angle) * y};
    }
    BOOST_TEST(deformation_parameter(body) == (a - b) / (a + b), boost::test_tools::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(separation_between_bodies_and_from_walls) {
  // Point 0 of build_wheel sits at angle 0 (on +x from the centre): check, then mirror body B so
  // that its point n/2 faces body A.
  std::vector<MassSpringBody> bodies{wheel({0.3, 0.5}, 0.2, 20), wheel({0.55, 0.5}, 0.2, 20)};
  BOOST_TEST(bodies[0].position[0][0] == 0.4, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(bodies[0].position[0][1] == 0.5, boost::test_tools::tolerance(1e-14));
  const BodySeparation s = body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {false, false});
  BOOST_TEST(s.min_rim_distance == 0.05, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s.n_points_inside_others == 0);
  BOOST_TEST(s.min_wall_distance == 0.2, boost::test_tools::tolerance(1e-12));  // body A's left point x = 0.2
  // Periodic in x: only the y walls count (rims reach y = 0.4 and 0.6).
  BOOST_TEST(body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {true, false}).min_wall_distance == 0.4,
             boost::test_tools::tolerance(1e-12));
  // Push A's point 0 to (0.5, 0.5), inside B: it is counted, and so is B's point facing A,
  // (0.45, 0.5), now inside A's spike; the rim distance shrinks.
  bodies[0].position[0] = {0.5, 0.5};
  const BodySeparation pushed = body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {false, false});
  BOOST_TEST(pushed.n_points_inside_others == 2);
  BOOST_TEST(pushed.min_rim_distance < 0.05);
  BOOST_TEST(s.n_edge_crossings == 0);
  BOOST_TEST(pushed.n_edge_crossings > 0);  // A's spike crosses B's rim
  // A point outside the box has a negative wall distance.
  bodies[1].position[0] = {1.01, 0.5};
  BOOST_TEST(body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {false, false}).min_wall_distance < 0.0);
}

BOOST_AUTO_TEST_CASE(separation_uses_the_minimum_image_in_periodic_directions) {
  // Wheels at x = 0.05 and 0.90 (D = 0.1) in a box periodic in x: 0.05 apart across the seam
  // (rims at x = 0.0 and 0.95 -> 0.05 through x = 1 = 0), 0.75 apart without the image.
  std::vector<MassSpringBody> bodies{wheel({0.05, 0.5}, 0.1, 20), wheel({0.90, 0.5}, 0.1, 20)};
  const BodySeparation periodic = body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {true, false});
  const BodySeparation walled = body_separation(bodies, {-1.0, 0.0}, {2.0, 1.0}, {false, false});
  BOOST_TEST(periodic.min_rim_distance == 0.05, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(walled.min_rim_distance == 0.75, boost::test_tools::tolerance(1e-12));
  // Overlap across the seam: move the second wheel to x = 0.97 (0.08 from the first's centre
  // through the seam, rims overlapping by 0.02): points inside and edges crossing are found.
  for (auto& x : bodies[1].position) x[0] += 0.07;
  const BodySeparation overlap = body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {true, false});
  BOOST_TEST(overlap.n_points_inside_others > 0);
  BOOST_TEST(overlap.n_edge_crossings > 0);
  // Fully periodic: no walls.
  BOOST_TEST(std::isinf(body_separation(bodies, {0.0, 0.0}, {1.0, 1.0}, {true, true}).min_wall_distance));
}

namespace {

// Every pair of bodies and every pair of their points: the oracle of the broad phase.
BodySeparation all_pairs(const std::vector<MassSpringBody>& bodies, std::array<double, 2> lower,
                         std::array<double, 2> upper, std::array<bool, 2> periodic) {
  using Vec = std::array<double, 2>;
  const auto image = [&](Vec d) {
    for (int c = 0; c < 2; ++c)
      if (periodic[c]) d[c] -= (upper[c] - lower[c]) * std::round(d[c] / (upper[c] - lower[c]));
    return d;
  };
  const auto inside = [](const MassSpringBody& body, const Vec& p) {
    bool in = false;
    for (int a = 0, b = body.n_surface - 1; a < body.n_surface; b = a++) {
      const auto& pa = body.position[a];
      const auto& pb = body.position[b];
      if ((pa[1] > p[1]) != (pb[1] > p[1]) && p[0] < (pb[0] - pa[0]) * (p[1] - pa[1]) / (pb[1] - pa[1]) + pa[0]) in = !in;
    }
    return in;
  };
  BodySeparation s;
  s.min_rim_distance = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (a == b) continue;
      const MassSpringBody& A = bodies[a];
      const MassSpringBody& B = bodies[b];
      // B brought next to A by the image of their first points' offset (bodies smaller than half a period).
      const Vec offset{B.position[0][0] - A.position[0][0], B.position[0][1] - A.position[0][1]};
      const Vec im = image(offset);
      const Vec shift{im[0] - offset[0], im[1] - offset[1]};
      for (int l = 0; l < A.n_surface; ++l) {
        const Vec& p = A.position[l];
        if (inside(B, {p[0] - shift[0], p[1] - shift[1]})) ++s.n_points_inside_others;
        if (b < a) continue;
        for (int m = 0; m < B.n_surface; ++m) {
          const Vec q{B.position[m][0] + shift[0], B.position[m][1] + shift[1]};
          s.min_rim_distance = std::min(s.min_rim_distance, std::hypot(q[0] - p[0], q[1] - p[1]));
          const Vec& p1 = A.position[(l + 1) % A.n_surface];
          const Vec q1{B.position[(m + 1) % B.n_surface][0] + shift[0], B.position[(m + 1) % B.n_surface][1] + shift[1]};
          const auto o = [](const Vec& u, const Vec& v, const Vec& w) {
            return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0]);
          };
          const double o1 = o(p, p1, q), o2 = o(p, p1, q1), o3 = o(q, q1, p), o4 = o(q, q1, p1);
          if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
            ++s.n_edge_crossings;
        }
      }
    }
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_broad_phase_finds_what_every_pair_finds) {
  // 200 wheels of two sizes scattered at random in a unit box, many overlapping, some across the
  // periodic seams; dense (nearest pair within a box side) and sparse (the fallback) scenes.
  std::mt19937 random(11);
  for (const double spread : {1.0, 8.0}) {
    for (const bool wrap : {false, true}) {
      std::uniform_real_distribution<double> position(0.0, spread);
      std::vector<MassSpringBody> bodies;
      for (int k = 0; k < (spread > 1.0 ? 40 : 200); ++k)
        bodies.push_back(wheel({position(random) + (wrap && k % 7 == 0 ? 2.0 * spread : 0.0), position(random)},
                               k % 3 == 0 ? 0.06 : 0.04, 12 + k % 5));  // some periods away
      const std::array<bool, 2> periodic{wrap, wrap};
      const BodySeparation fast = body_separation(bodies, {0.0, 0.0}, {spread, spread}, periodic);
      const BodySeparation oracle = all_pairs(bodies, {0.0, 0.0}, {spread, spread}, periodic);
      BOOST_TEST_MESSAGE("spread " << spread << (wrap ? " periodic" : " walls") << ": rim distance "
                                   << fast.min_rim_distance << ", inside " << fast.n_points_inside_others
                                   << ", crossings " << fast.n_edge_crossings);
      BOOST_TEST(fast.min_rim_distance == oracle.min_rim_distance);
      BOOST_TEST(fast.n_points_inside_others == oracle.n_points_inside_others);
      BOOST_TEST(fast.n_edge_crossings == oracle.n_edge_crossings);
      if (spread == 1.0) BOOST_TEST(oracle.n_edge_crossings > 0);
    }
  }
}

BOOST_AUTO_TEST_CASE(rim_folded_through_itself_is_counted) {
  MassSpringBody body = wheel({0.5, 0.5}, 0.2, 16);
  const std::array<double, 2> lower{0.0, 0.0}, upper{1.0, 1.0};
  BOOST_TEST(body_separation({body}, lower, upper, {false, false}).n_self_crossings == 0);
  // Swapping points 3 and 4 makes edges 2-4' and 3'-5 (the points' new order 2, 4, 3, 5) cross
  // once: a rim folded over itself between neighbours.
  std::swap(body.position[3], body.position[4]);
  BOOST_TEST(body_separation({body}, lower, upper, {false, false}).n_self_crossings == 1);
  MassSpringBody other = wheel({0.2, 0.2}, 0.2, 16);
  BOOST_TEST(body_separation({body, other}, lower, upper, {false, false}).n_self_crossings == 1);
  body.kind = BodyKind::rigid;  // a rigid rim does not fold: not examined
  BOOST_TEST(body_separation({body}, lower, upper, {false, false}).n_self_crossings == 0);
}
