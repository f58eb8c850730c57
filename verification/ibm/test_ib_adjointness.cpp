// Spreading is the adjoint of interpolation, docs/method.md §4 ("S = J*"): with zero wall speeds
// sum_cells (f.u) dx dy == sum_l dV_l F_l.(J u)_l, for random fields, forces and volumes, in
// the interior, 0.3h from each wall, in the corners, and in periodic boxes (all four kernels).
#define BOOST_TEST_MODULE ib_adjointness
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "ibm/ib_operators.hpp"

using namespace ibms;
using Points = std::vector<std::array<double, 2>>;

namespace {

// Both sides are sums of ~1e3 products of O(1) random numbers; 1e-13 relative to the sum of
// |terms| is ~100 ulp, what round-off of such sums can reach.
constexpr double round_off = 1e-13;

// |<S F, u> - <F, J u>| / (sum of |terms|) for random u, v, F, dV at the given markers.
double adjoint_mismatch(const Grid& grid, KernelKind kernel, const Points& markers, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  CellField u(grid), v(grid), fx(grid), fy(grid);
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) { u(i, j) = uniform(rng); v(i, j) = uniform(rng); }
  // Poison the ghost layer: the operators must not read it.
  for (int i = -1; i <= grid.nx; ++i) { u(i, -1) = v(i, grid.ny) = 1e30; }
  Points force(markers.size());
  std::vector<double> volume(markers.size());
  for (std::size_t l = 0; l < markers.size(); ++l) {
    force[l] = {uniform(rng), uniform(rng)};
    volume[l] = grid.dx() * grid.dy() * (1.0 + 0.5*uniform(rng));
  }
  Points interpolated;
  interpolate(grid, kernel, WallVelocities{}, u, v, markers, interpolated);
  spread(grid, kernel, markers, force, volume, fx, fy);
  double eulerian = 0.0, lagrangian = 0.0, scale = 0.0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double term = (fx(i, j)*u(i, j) + fy(i, j)*v(i, j)) * grid.dx() * grid.dy();
      eulerian += term;
      scale += std::abs(term);
    }
  for (std::size_t l = 0; l < markers.size(); ++l)
    lagrangian += volume[l] * (force[l][0]*interpolated[l][0] + force[l][1]*interpolated[l][1]);
  return std::abs(eulerian - lagrangian) / scale;
}

Points random_markers(const Grid& grid, double margin, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(grid.origin_x + margin, grid.origin_x + grid.length_x - margin);
  std::uniform_real_distribution<double> uy(grid.origin_y + margin, grid.origin_y + grid.length_y - margin);
  Points markers(n);
  for (auto& x : markers) x = {ux(rng), uy(rng)};
  return markers;
}

// Markers 0.3h from each wall (interior along it), in each corner, and on the walls themselves.
Points wall_markers(const Grid& grid) {
  const double x0 = grid.origin_x, y0 = grid.origin_y, x1 = x0 + grid.length_x, y1 = y0 + grid.length_y;
  const double hx = 0.3 * grid.dx(), hy = 0.3 * grid.dy();
  const double xm = x0 + 0.43*grid.length_x, ym = y0 + 0.57*grid.length_y;
  return {{x0 + hx, ym}, {x1 - hx, ym}, {xm, y0 + hy}, {xm, y1 - hy},            // walls
          {x0 + hx, y0 + hy}, {x1 - hx, y0 + hy}, {x0 + hx, y1 - hy}, {x1 - hx, y1 - hy},  // corners
          {x0, ym}, {xm, y1}, {x1, y0}};                                          // on the walls
}

}  // namespace

BOOST_AUTO_TEST_CASE(spread_is_adjoint_of_interpolate_in_the_interior) {
  const Grid grid(24, 20, 1.2, 0.9);  // dx != dy to catch swapped directions
  BOOST_TEST_MESSAGE("kernel    relative mismatch");
  for (KernelKind kernel : all_kernel_kinds) {
    const double mismatch = adjoint_mismatch(grid, kernel, random_markers(grid, 0.25, 40, 1), 2);
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << mismatch);
    BOOST_TEST(mismatch <= round_off);
  }
}

BOOST_AUTO_TEST_CASE(spread_is_adjoint_of_interpolate_next_to_walls_and_in_corners) {
  const Grid grid(16, 12, 1.0, 0.8, false, false, -0.3, 0.2);
  BOOST_TEST_MESSAGE("kernel    relative mismatch");
  for (KernelKind kernel : all_kernel_kinds) {
    const double mismatch = adjoint_mismatch(grid, kernel, wall_markers(grid), 3);
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << mismatch);
    BOOST_TEST(mismatch <= round_off);
  }
}

BOOST_AUTO_TEST_CASE(spread_is_adjoint_of_interpolate_in_periodic_boxes) {
  BOOST_TEST_MESSAGE("kernel    fully periodic    periodic x, walls in y");
  for (KernelKind kernel : all_kernel_kinds) {
    const Grid periodic(16, 12, 1.0, 0.8, true, true);
    // Periodic markers may sit anywhere, also outside the box.
    Points markers = random_markers(periodic, 0.0, 20, 4);
    markers.push_back({-0.01, 0.79});
    markers.push_back({1.37, -0.55});
    const double m1 = adjoint_mismatch(periodic, kernel, markers, 5);
    const Grid channel(16, 12, 1.0, 0.8, true, false);
    Points near_walls = wall_markers(channel);
    near_walls.push_back({-0.2, 0.01});
    const double m2 = adjoint_mismatch(channel, kernel, near_walls, 6);
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << m1 << "    " << m2);
    BOOST_TEST(m1 <= round_off);
    BOOST_TEST(m2 <= round_off);
  }
}

BOOST_AUTO_TEST_CASE(interpolation_reproduces_a_moving_wall_next_to_it) {
  // u = U_top, v = 0 everywhere: the ghost rule 2 U_top - u_mirror gives U_top again, so markers
  // near the top wall (away from the side walls) see exactly (U_top, 0), up to round-off.
  const Grid grid(16, 16, 1.0, 1.0);
  WallVelocities walls;
  walls.top = 1.3;
  CellField u(grid, walls.top), v(grid, 0.0);
  const Points markers = {{0.5, 1.0 - 0.3/16}, {0.41, 1.0}, {0.6, 0.97}};
  BOOST_TEST_MESSAGE("kernel    max|U - U_top|");
  for (KernelKind kernel : all_kernel_kinds) {
    Points interpolated;
    interpolate(grid, kernel, walls, u, v, markers, interpolated);
    double worst = 0.0;
    for (const auto& U : interpolated) worst = std::max({worst, std::abs(U[0] - walls.top), std::abs(U[1])});
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << worst);
    BOOST_TEST(worst <= 1e-14);  // a sum of <= 36 weights times O(1): round-off
  }
}

BOOST_AUTO_TEST_CASE(markers_outside_a_walled_box_are_rejected) {
  const Grid grid(8, 8, 1.0, 1.0, true, false);
  CellField u(grid), v(grid);
  Points out;
  BOOST_CHECK_THROW(interpolate(grid, KernelKind::roma3, {}, u, v, {{0.5, 1.01}}, out),
                    std::invalid_argument);
  BOOST_CHECK_NO_THROW(interpolate(grid, KernelKind::roma3, {}, u, v, {{-3.5, 0.5}}, out));
}
