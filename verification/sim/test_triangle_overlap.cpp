// The exact triangle-cell overlaps of ibm/triangle_cell_overlap (used for the inner-fluid
// momentum of docs/method.md §1.7, variant K): for every triangle the overlaps add up to its area,
// and over a fan (c, l, l+1) to the polygon's area, to round-off, in the interior, across a
// periodic boundary and for both orientations.
#define BOOST_TEST_MODULE triangle_overlap
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "ibm/triangle_cell_overlap.hpp"

using namespace ibms;

namespace {

double triangle_area(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return 0.5 * std::abs((b[0] - a[0])*(c[1] - a[1]) - (b[1] - a[1])*(c[0] - a[0]));
}

// Largest relative error of sum(overlaps) against the exact areas, per triangle and for the fan.
double fan_error(const Grid& grid, double cx, double cy, double radius, int n, bool clockwise) {
  const std::array<double, 2> centre{cx, cy};
  std::vector<std::array<double, 2>> rim(n);
  for (int l = 0; l < n; ++l) {
    const double angle = (clockwise ? -1 : 1) * 2*pi*l / n + 0.3;
    rim[l] = {cx + radius*std::cos(angle) * (1 + 0.1*std::sin(3*angle)), cy + radius*std::sin(angle)};
  }
  double worst = 0.0, fan_sum = 0.0, fan_exact = 0.0;
  std::vector<CellOverlap> cells;
  for (int l = 0; l < n; ++l) {
    cells.clear();
    add_triangle_cell_overlaps(grid, centre, rim[l], rim[(l + 1) % n], cells);
    double sum = 0.0;
    for (const CellOverlap& o : cells) sum += o.area;
    const double exact = triangle_area(centre, rim[l], rim[(l + 1) % n]);
    worst = std::max(worst, std::abs(sum - exact) / exact);
    fan_sum += sum;
    fan_exact += exact;
  }
  return std::max(worst, std::abs(fan_sum - fan_exact) / fan_exact);
}

}  // namespace

BOOST_AUTO_TEST_CASE(triangle_overlaps_sum_to_triangle_and_polygon_area) {
  const Grid walls(64, 64, 1.0, 1.0);
  const Grid periodic(64, 64, 1.0, 1.0, true, true);
  const double interior = fan_error(walls, 0.5, 0.5, 0.125, 48, false);
  const double reversed = fan_error(walls, 0.503, 0.49, 0.125, 48, true);
  const double wrapped = fan_error(periodic, 0.98, 0.02, 0.125, 48, false);  // straddles both periodic seams
  BOOST_TEST_MESSAGE("relative area error: interior " << interior << ", clockwise " << reversed
                                                     << ", across periodic seams " << wrapped);
  // Each overlap is a shoelace sum of O(h^2) terms; ~10^2 cells per triangle give a few
  // 1e-16 relative error; 1e-13 is round-off with margin.
  BOOST_TEST(interior < 1e-13);
  BOOST_TEST(reversed < 1e-13);
  BOOST_TEST(wrapped < 1e-13);
}
