// The lattice Green's function of the five-point Laplacian (fluid/lattice_green_function.hpp),
// which the marker preconditioner uses for L^{-1} of the face projection:
//  - on square cells it takes the potential kernel's exact values (Spitzer 1976; McCrea & Whipple
//    1940): G(1,0) - G(0,0) = h^2 / 4 and G(1,1) - G(0,0) = h^2 / pi, and far away its logarithm
//    (h^2 / 2 pi) (ln r + gamma + 3/2 ln 2), with an O(r^-2) remainder;
//  - on cells dx x dy, dx != dy, the five-point Laplacian of the table is the unit impulse at the
//    origin and zero elsewhere (its residual is measured against the table's largest entry).
#define BOOST_TEST_MODULE lattice_green_function
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "fluid/lattice_green_function.hpp"

using ibms::LatticeGreensFunction;
using ibms::pi;

BOOST_AUTO_TEST_CASE(square_cells_take_the_potential_kernels_values) {
  const double h = 0.1;
  LatticeGreensFunction g;
  g.ensure(h, h, 64);
  BOOST_TEST(g(0, 0) == 0.0);
  BOOST_TEST(g(1, 0) / (h * h) == 0.25, boost::test_tools::tolerance(1e-8));
  BOOST_TEST(g(0, -1) / (h * h) == 0.25, boost::test_tools::tolerance(1e-8));
  BOOST_TEST(g(1, 1) / (h * h) == 1.0 / pi, boost::test_tools::tolerance(1e-8));
  const double gamma = 0.57721566490153286;
  for (const auto& [m, n] : {std::pair{40, 0}, std::pair{30, 30}, std::pair{60, 17}}) {
    const double r = std::hypot(m, n);
    const double far = (std::log(r) + gamma + 1.5 * std::log(2.0)) / (2.0 * pi);
    BOOST_TEST_MESSAGE("(" << m << ", " << n << "): " << g(m, n) / (h * h) << " against " << far);
    BOOST_TEST(std::abs(g(m, n) / (h * h) - far) < 0.1 / (r * r));
  }
}

BOOST_AUTO_TEST_CASE(its_laplacian_is_the_unit_impulse_on_unequal_cells) {
  const double dx = 0.02, dy = 0.03;
  const int radius = 40;
  LatticeGreensFunction g;
  g.ensure(dx, dy, radius);
  double largest = 0.0, residual = 0.0;
  for (int n = -radius + 1; n < radius; ++n)
    for (int m = -radius + 1; m < radius; ++m) {
      largest = std::max(largest, std::abs(g(m, n)));
      const double laplacian = (g(m + 1, n) - 2.0 * g(m, n) + g(m - 1, n)) / (dx * dx) +
                               (g(m, n + 1) - 2.0 * g(m, n) + g(m, n - 1)) / (dy * dy);
      residual = std::max(residual, std::abs(laplacian - (m == 0 && n == 0 ? 1.0 : 0.0)));
    }
  BOOST_TEST_MESSAGE("largest |L G - delta| = " << residual << ", largest |G| / dx dy = " << largest / (dx * dy));
  // delta is 1 at the origin; the Laplacian of the table's error is of order error / dx^2.
  BOOST_TEST(residual < 1e-6);
}
