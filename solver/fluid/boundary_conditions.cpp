// Ghost-cell fills for the collocated grid (docs/method.md §2.5; walls as CaNS src/bound.f90; open sides
// docs/open-boundaries.md). Rules in boundary_conditions.hpp.
#include "fluid/boundary_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/constants.hpp"

namespace ibms {
namespace {

// How a scalar's ghost follows from the interior next to a side.
enum class GhostRule { even, odd, quadratic };

GhostRule pressure_rule(SideKind kind) {
  if (kind == SideKind::outflow) return GhostRule::odd;
  if (kind == SideKind::inflow) return GhostRule::quadratic;
  return GhostRule::even;
}

GhostRule correction_rule(SideKind kind) { return kind == SideKind::outflow ? GhostRule::odd : GhostRule::even; }

double ghost(GhostRule rule, double first, double second, double third) {
  switch (rule) {
    case GhostRule::even: return first;
    case GhostRule::odd: return -first;
    case GhostRule::quadratic: return 3.0 * first - 3.0 * second + third;
  }
  return first;
}

// Scalar ghosts by a rule per side; x first over the interior rows, then y over the padded width.
template <typename RuleOf>
void fill_scalar(const Grid& g, const FluidBoundaries& bc, CellField& q, RuleOf rule_of) {
  const int nx = g.nx, ny = g.ny;
  if (g.periodic_x) {
    for (int j = 0; j < ny; ++j) { q(-1, j) = q(nx - 1, j); q(nx, j) = q(0, j); }
  } else {
    const GhostRule low = rule_of(bc.left.kind), high = rule_of(bc.right.kind);
    for (int j = 0; j < ny; ++j) {
      q(-1, j) = ghost(low, q(0, j), q(1, j), q(2, j));  // the scene has >= 4 cells per direction
      q(nx, j) = ghost(high, q(nx - 1, j), q(nx - 2, j), q(nx - 3, j));
    }
  }
  if (g.periodic_y) {
    for (int i = -1; i <= nx; ++i) { q(i, -1) = q(i, ny - 1); q(i, ny) = q(i, 0); }
  } else {
    const GhostRule low = rule_of(bc.bottom.kind), high = rule_of(bc.top.kind);
    for (int i = -1; i <= nx; ++i) {
      q(i, -1) = ghost(low, q(i, 0), q(i, 1), q(i, 2));
      q(i, ny) = ghost(high, q(i, ny - 1), q(i, ny - 2), q(i, ny - 3));
    }
  }
}

Side opposite_side(Side s) {
  switch (s) {
    case Side::left: return Side::right;
    case Side::right: return Side::left;
    case Side::bottom: return Side::top;
    case Side::top: return Side::bottom;
  }
  return s;
}

}  // namespace

const char* side_kind_name(SideKind kind) { return option_name(kind).data(); }

double TimeFactor::at(double time) const {
  switch (kind) {
    case Kind::constant: return 1.0;
    case Kind::ramp: return std::min(std::max(time, 0.0) / ramp_time, 1.0);
    case Kind::sinusoidal: return offset + amplitude * std::sin(2.0 * pi * time / period);
  }
  return 1.0;
}

double InflowProfile::at(double s, double side_length, double time) const {
  double shape_value = 1.0;
  if (shape == Shape::parabolic) {
    const double c = std::clamp(s, 0.0, side_length);
    shape_value = 4.0 * c * (side_length - c) / (side_length * side_length);
  }
  return velocity * shape_value * factor.at(time);
}

double InflowProfile::mean_at(double time) const {
  return velocity * (shape == Shape::parabolic ? 2.0 / 3.0 : 1.0) * factor.at(time);
}

double InflowProfile::peak() const {
  double f = 1.0;
  if (factor.kind == TimeFactor::Kind::sinusoidal) f = std::abs(factor.offset) + std::abs(factor.amplitude);
  return std::abs(velocity) * f;
}

const BoundarySide& FluidBoundaries::side(Side s) const {
  switch (s) {
    case Side::left: return left;
    case Side::right: return right;
    case Side::bottom: return bottom;
    case Side::top: return top;
  }
  return left;
}

BoundarySide& FluidBoundaries::side(Side s) { return const_cast<BoundarySide&>(std::as_const(*this).side(s)); }

SideKind FluidBoundaries::kind(const Grid& grid, Side s) const {
  const bool along_x = s == Side::left || s == Side::right;
  if (along_x ? grid.periodic_x : grid.periodic_y) return SideKind::periodic;
  return side(s).kind;
}

std::array<double, 2> FluidBoundaries::velocity_at(const Grid& grid, Side s, double x, double y,
                                                   double time) const {
  const BoundarySide& b = side(s);
  if (b.prescribed) return b.prescribed(x, y, time);
  const bool x_side = s == Side::left || s == Side::right;  // the side is normal to x
  if (b.kind == SideKind::inflow) {
    const double along = x_side ? y - grid.origin_y : x - grid.origin_x;
    const double length = x_side ? grid.length_y : grid.length_x;
    const double into = b.inflow.at(along, length, time);
    const double sign = (s == Side::left || s == Side::bottom) ? 1.0 : -1.0;
    return x_side ? std::array<double, 2>{sign * into, 0.0} : std::array<double, 2>{0.0, sign * into};
  }
  const double tangential = b.at(time);  // walls; 0 elsewhere (the scene refuses a speed there)
  return x_side ? std::array<double, 2>{0.0, tangential} : std::array<double, 2>{tangential, 0.0};
}

bool FluidBoundaries::has_open_side(const Grid& grid) const {
  for (const Side s : all_sides) {
    const SideKind k = kind(grid, s);
    if (k == SideKind::inflow || k == SideKind::outflow) return true;
  }
  return false;
}

SideCells side_cells(const Grid& g, Side s) {
  switch (s) {
    case Side::left: return {true, g.ny, 0, 1, 0, g.origin_x, g.dx(), g.dy()};
    case Side::right: return {true, g.ny, g.nx - 1, -1, g.nx, g.origin_x + g.length_x, g.dx(), g.dy()};
    case Side::bottom: return {false, g.nx, 0, 1, 0, g.origin_y, g.dy(), g.dx()};
    case Side::top: return {false, g.nx, g.ny - 1, -1, g.ny, g.origin_y + g.length_y, g.dy(), g.dx()};
  }
  return {};
}

std::array<double, 2> side_point(const Grid& g, Side s, int n) {
  const SideCells c = side_cells(g, s);
  if (c.normal_to_x) return {c.position, std::clamp(g.y_centre(n), g.origin_y, g.origin_y + g.length_y)};
  return {std::clamp(g.x_centre(n), g.origin_x, g.origin_x + g.length_x), c.position};
}

void fill_velocity_ghosts(const Grid& g, const FluidBoundaries& bc, double time, CellField& u, CellField& v) {
  // Left and right over the interior rows first, then bottom and top over the padded width, so
  // that the corner ghosts follow from the left and right ghosts.
  for (const Side s : all_sides) {
    const SideCells c = side_cells(g, s);
    const SideKind kind = bc.kind(g, s);
    const SideCells opposite = side_cells(g, opposite_side(s));
    const int first = c.normal_to_x ? 0 : -1, last = c.normal_to_x ? g.ny - 1 : g.nx;
    for (int n = first; n <= last; ++n) {
      const int gi = c.i(n, -1), gj = c.j(n, -1), i = c.i(n, 0), j = c.j(n, 0);
      if (kind == SideKind::periodic) {  // the opposite side's interior cell
        u(gi, gj) = u(opposite.i(n, 0), opposite.j(n, 0));
        v(gi, gj) = v(opposite.i(n, 0), opposite.j(n, 0));
      } else if (kind == SideKind::wall || kind == SideKind::inflow) {  // q_g = 2 q_b - q_int
        const std::array<double, 2> at = side_point(g, s, n);
        const std::array<double, 2> b = bc.velocity_at(g, s, at[0], at[1], time);
        u(gi, gj) = 2.0 * b[0] - u(i, j);
        v(gi, gj) = 2.0 * b[1] - v(i, j);
      } else {  // outflow: q_g = q_int
        u(gi, gj) = u(i, j);
        v(gi, gj) = v(i, j);
      }
    }
  }
}

void fill_pressure_ghosts(const Grid& grid, const FluidBoundaries& bc, CellField& pressure) {
  fill_scalar(grid, bc, pressure, pressure_rule);
}

void fill_correction_ghosts(const Grid& grid, const FluidBoundaries& bc, CellField& scalar) {
  fill_scalar(grid, bc, scalar, correction_rule);
}

void fill_neumann_ghosts(const Grid& grid, CellField& scalar) {
  fill_scalar(grid, FluidBoundaries{}, scalar, [](SideKind) { return GhostRule::even; });
}

void sync_periodic_faces(const Grid& grid, FaceField& velocity_face_x, FaceField& velocity_face_y) {
  if (grid.periodic_x)
    for (int j = 0; j < grid.ny; ++j) velocity_face_x(grid.nx, j) = velocity_face_x(0, j);
  if (grid.periodic_y)
    for (int i = 0; i < grid.nx; ++i) velocity_face_y(i, grid.ny) = velocity_face_y(i, 0);
}

double side_inflow(const Grid& g, Side s, const FaceField& fx, const FaceField& fy) {
  const SideCells c = side_cells(g, s);
  const FaceField& faces = c.normal_to_x ? fx : fy;
  double sum = 0.0;
  for (int n = 0; n < c.count; ++n) sum += c.inward * faces(c.face_i(n), c.face_j(n));  // into the box
  return sum * c.tangential_spacing;
}

double net_inflow(const Grid& g, const FaceField& fx, const FaceField& fy) {
  double sum = 0.0;
  if (!g.periodic_x) sum += side_inflow(g, Side::left, fx, fy) + side_inflow(g, Side::right, fx, fy);
  if (!g.periodic_y) sum += side_inflow(g, Side::bottom, fx, fy) + side_inflow(g, Side::top, fx, fy);
  return sum;
}

}  // namespace ibms
