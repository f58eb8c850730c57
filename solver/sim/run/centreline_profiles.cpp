// Centre-line profiles of the velocity (the cavity cases' output, docs/design.md §5).
#include "sim/run/centreline_profiles.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

CentrelineProfiles centreline_profiles(const Simulation& sim) {
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  const double t = f.time;
  const FluidBoundaries& bc = sim.boundaries();
  CentrelineProfiles p;
  // Vertical line x = mid: cells i0, i0 + 1 around it, weight w on i0 + 1.
  const double x_mid = g.origin_x + 0.5 * g.length_x, y_mid = g.origin_y + 0.5 * g.length_y;
  const double si = (x_mid - g.origin_x) / g.dx() - 0.5, sj = (y_mid - g.origin_y) / g.dy() - 0.5;
  const int i0 = std::clamp(static_cast<int>(std::floor(si)), 0, g.nx - 2);
  const int j0 = std::clamp(static_cast<int>(std::floor(sj)), 0, g.ny - 2);
  const double wi = si - i0, wj = sj - j0;
  // End points on the sides where the velocity is given (walls, inflows); none at an outflow.
  const double x1 = g.origin_x + g.length_x, y1 = g.origin_y + g.length_y;
  const auto given = [&](Side s) { return bc.kind(g, s) == SideKind::wall || bc.kind(g, s) == SideKind::inflow; };
  if (given(Side::bottom)) { p.y.push_back(g.origin_y); p.u.push_back(bc.velocity_at(g, Side::bottom, x_mid, g.origin_y, t)[0]); }
  for (int j = 0; j < g.ny; ++j) {
    p.y.push_back(g.y_centre(j));
    p.u.push_back((1 - wi) * f.velocity_x(i0, j) + wi * f.velocity_x(i0 + 1, j));
  }
  if (given(Side::top)) { p.y.push_back(y1); p.u.push_back(bc.velocity_at(g, Side::top, x_mid, y1, t)[0]); }
  if (given(Side::left)) { p.x.push_back(g.origin_x); p.v.push_back(bc.velocity_at(g, Side::left, g.origin_x, y_mid, t)[1]); }
  for (int i = 0; i < g.nx; ++i) {
    p.x.push_back(g.x_centre(i));
    p.v.push_back((1 - wj) * f.velocity_y(i, j0) + wj * f.velocity_y(i, j0 + 1));
  }
  if (given(Side::right)) { p.x.push_back(x1); p.v.push_back(bc.velocity_at(g, Side::right, x1, y_mid, t)[1]); }
  return p;
}

}  // namespace ibms
