// The exact triangle-cell overlaps of ibm/triangle_cell_overlap (used for the inner-fluid
// momentum of docs/method.md §1.7, variant K): for every triangle the overlaps add up to its area,
// and over a fan (c, l, l+1) to the polygon's area, to round-off, in the interior, across a
// periodic boundary and for both orientations; and cell by cell they equal the overlaps found by
// clipping each cell square with the triangle (verification/oracles/clipped_cell_overlaps), on
// random triangles, thin fan triangles and triangles whose vertices and edges lie on grid lines.
#define BOOST_TEST_MODULE triangle_overlap
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "ibm/triangle_cell_overlap.hpp"
#include "oracles/clipped_cell_overlaps.hpp"

#include <map>
#include <random>
#include <utility>

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
  // Each overlap is a sum of O(h^2) terms; ~10^2 cells per triangle give a few 1e-16 relative
  // error; 1e-13 is round-off with margin.
  BOOST_TEST(interior < 1e-13);
  BOOST_TEST(reversed < 1e-13);
  BOOST_TEST(wrapped < 1e-13);
}

namespace {

// Largest |overlap - oracle| of any cell over the cell area (a cell that one side lists and the
// other does not counts with its whole overlap).
double worst_cell_difference(const Grid& grid, const std::array<double, 2>& a, const std::array<double, 2>& b,
                             const std::array<double, 2>& c) {
  std::vector<CellOverlap> mine;
  add_triangle_cell_overlaps(grid, a, b, c, mine);
  const std::vector<CellOverlap> oracle = oracle::clipped_cell_overlaps(grid, a, b, c);
  const double cell = grid.dx() * grid.dy();
  std::map<std::pair<int, int>, double> difference;
  for (const CellOverlap& o : mine) difference[{o.i, o.j}] += o.area;
  for (const CellOverlap& o : oracle) difference[{o.i, o.j}] -= o.area;
  double worst = 0.0;
  for (const auto& [ij, d] : difference) worst = std::max(worst, std::abs(d) / cell);
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(triangle_overlaps_equal_clipping_cell_by_cell) {
  const Grid walls(40, 30, 1.0, 0.75);  // dx = dy = 0.025
  const Grid periodic(40, 30, 1.0, 0.75, true, true);
  std::mt19937 random(20261206);
  std::uniform_real_distribution<double> anywhere(-0.05, 1.05), near(-0.06, 0.06), along(0.0, 1.0);
  double worst = 0.0;
  int triangles = 0;
  const auto check = [&](const Grid& g, const std::array<double, 2>& a, const std::array<double, 2>& b,
                         const std::array<double, 2>& c) {
    worst = std::max(worst, worst_cell_difference(g, a, b, c));
    ++triangles;
  };
  for (int k = 0; k < 300; ++k) {  // random triangles of every size and shape, partly outside the box
    const std::array<double, 2> a{anywhere(random), 0.75 * anywhere(random)};
    const std::array<double, 2> b{a[0] + 4 * near(random), a[1] + 4 * near(random)};
    const std::array<double, 2> c{a[0] + near(random), a[1] + near(random)};
    check(k % 2 ? walls : periodic, a, b, c);
  }
  for (int l = 0; l < 63; ++l) {  // thin fan triangles of a disk of D = 16 h, as the bodies make them
    const double t0 = 2 * pi * l / 63, t1 = 2 * pi * (l + 1) / 63;
    check(walls, {0.5013, 0.3771}, {0.5013 + 0.2 * std::cos(t0), 0.3771 + 0.2 * std::sin(t0)},
          {0.5013 + 0.2 * std::cos(t1), 0.3771 + 0.2 * std::sin(t1)});
  }
  // Vertices on grid nodes and edges along grid lines (horizontal and vertical), both orientations.
  const double h = 0.025;
  for (int k = 0; k < 40; ++k) {
    const double x = h * (3 + static_cast<int>(30 * along(random))), y = h * (3 + static_cast<int>(20 * along(random)));
    const int m = 1 + k % 5, n = 1 + (k / 5) % 4;
    check(walls, {x, y}, {x + m * h, y}, {x, y + n * h});
    check(walls, {x, y}, {x, y + n * h}, {x + m * h, y + 0.5 * h});
    check(periodic, {x, y}, {x - m * h, y - n * h}, {x + 0.37 * h, y - n * h});
  }
  BOOST_TEST_MESSAGE(triangles << " triangles: largest cell difference from clipping " << worst
                               << " of a cell's area");
  BOOST_TEST(worst < 1e-12);
}

namespace {

// Largest |polygon overlap - sum of its fan triangles' overlaps| of any cell over the cell area, for
// the rim `rim` around `centre`.
double polygon_against_fan(const Grid& grid, const std::array<double, 2>& centre,
                           const std::vector<std::array<double, 2>>& rim) {
  std::vector<CellOverlap> polygon, fan;
  PolygonOverlapWork work;
  add_polygon_cell_overlaps(grid, rim.data(), rim.size(), polygon, work);
  for (std::size_t l = 0; l < rim.size(); ++l) add_triangle_cell_overlaps(grid, centre, rim[l], rim[(l + 1) % rim.size()], fan);
  std::map<std::pair<int, int>, double> difference;
  for (const CellOverlap& o : polygon) difference[{o.i, o.j}] += o.area;
  for (const CellOverlap& o : fan) difference[{o.i, o.j}] -= o.area;
  double worst = 0.0;
  for (const auto& [ij, d] : difference) worst = std::max(worst, std::abs(d) / (grid.dx() * grid.dy()));
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(polygon_overlaps_equal_their_fan_triangles_cell_by_cell) {
  // The rigid bodies' inner-fluid momentum takes the rim polygon's overlaps in one pass: the same
  // cells and areas as its fan triangles, for a disk of D = 16 h with 50 rim points, a wavy
  // (non-convex) rim, both orientations, rims on grid lines, across periodic seams and by a wall.
  const Grid walls(64, 64, 1.0, 1.0);
  const Grid periodic(64, 64, 1.0, 1.0, true, true);
  const auto rim = [](double cx, double cy, double radius, int n, bool clockwise, double wave) {
    std::vector<std::array<double, 2>> points(n);
    for (int l = 0; l < n; ++l) {
      const double angle = (clockwise ? -1 : 1) * 2 * pi * l / n + 0.3;
      const double r = radius * (1 + wave * std::sin(5 * angle));
      points[l] = {cx + r * std::cos(angle), cy + r * std::sin(angle)};
    }
    return points;
  };
  double worst = 0.0;
  for (const bool clockwise : {false, true}) {
    worst = std::max(worst, polygon_against_fan(walls, {0.5013, 0.3771}, rim(0.5013, 0.3771, 0.125, 50, clockwise, 0.0)));
    worst = std::max(worst, polygon_against_fan(walls, {0.5, 0.5}, rim(0.5, 0.5, 0.125, 48, clockwise, 0.0)));  // on grid lines
    worst = std::max(worst, polygon_against_fan(walls, {0.41, 0.63}, rim(0.41, 0.63, 0.15, 64, clockwise, 0.15)));
    worst = std::max(worst, polygon_against_fan(periodic, {0.98, 0.02}, rim(0.98, 0.02, 0.125, 50, clockwise, 0.05)));
    worst = std::max(worst, polygon_against_fan(walls, {0.5, 0.13}, rim(0.5, 0.13, 0.125, 50, clockwise, 0.0)));  // 0.005 from the wall
  }
  BOOST_TEST_MESSAGE("largest cell difference, polygon against its fan: " << worst << " of a cell's area");
  BOOST_TEST(worst < 1e-12);
}
