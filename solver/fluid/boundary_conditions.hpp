// Boundary conditions of the fluid box (docs/method.md §2.5; open sides: docs/open-boundaries.md). Each side of the
// box is one of
//   wall      no-slip: normal velocity 0, tangential velocity prescribed (may change in time);
//   inflow    both velocity components prescribed: the normal one from a profile (uniform or
//             parabolic) times a time factor, the tangential one 0;
//   outflow   zero normal gradient of both velocity components, pressure 0 at the side;
//   periodic  the opposite side's values (both sides of the axis; Grid::periodic_x/y).
// Ghost rules (cells one deep, CellField), b the side's value:
//   velocity  Dirichlet (wall, inflow) q_g = 2 q_b - q_int; outflow q_g = q_int;
//   pressure  wall q_g = q_int; inflow q_g = 2 q_int - q_int2 (linear: the projection fixes the
//             inflow flux, so the pressure's normal gradient there is the flow's own, not 0; the
//             zero-gradient ghost would halve the cell-centre gradient of the first cell, and plane
//             Poiseuille flow could not be a discrete steady state); outflow q_g = -q_int (p = 0);
//   phi       (SMAC pressure correction) wall and inflow q_g = q_int (the face flux is given),
//             outflow q_g = -q_int.
#pragma once
#include <array>
#include <functional>
#include <limits>

#include "core/fields.hpp"
#include "core/grid.hpp"
#include "core/options.hpp"

namespace ibms {

// Tangential speed of one wall as a function of time: `speed` until `stop_time`, then 0.
struct WallMotion {
  double speed = 0.0;       // [length/time]; +x on bottom/top walls, +y on left/right walls
  double stop_time = std::numeric_limits<double>::infinity();  // [time]
  double at(double time) const { return time < stop_time ? speed : 0.0; }
  bool is_moving() const { return speed != 0.0; }
};

const char* side_kind_name(SideKind kind);  // its scene name (core/options.hpp)

// Time factor of an inflow: 1; min(t / ramp_time, 1); or offset + amplitude sin(2 pi t / period).
struct TimeFactor {
  using Kind = TimeFactorKind;
  Kind kind = Kind::constant;
  double ramp_time = 1.0;   // [time]
  double offset = 0.0;      // [-]
  double amplitude = 1.0;   // [-]
  double period = 1.0;      // [time]
  double at(double time) const;
};

// Normal velocity of an inflow side, into the box: `velocity` times the shape times the factor.
// Shape along the side (s in [0, L] from its low end): uniform 1, parabolic 4 s (L - s) / L^2
// (then `velocity` is the peak; the mean is 2/3 of it).
struct InflowProfile {
  using Shape = InflowShape;
  Shape shape = Shape::uniform;
  double velocity = 0.0;  // [length/time], > 0 into the box
  TimeFactor factor;
  double at(double s, double side_length, double time) const;
  double mean_at(double time) const;  // mean over the side [length/time]
  double peak() const;                // largest |velocity| over the side and time [length/time]
};

enum class Side { left = 0, right = 1, bottom = 2, top = 3 };
constexpr std::array<Side, 4> all_sides = {Side::left, Side::right, Side::bottom, Side::top};

// One side of the box as index arithmetic, so that a boundary rule is written once for the four
// sides. Position n runs along the side (j on left and right, i on bottom and top); depth 0 is the
// interior cell beside the side, 1 the next one inward, -1 the ghost beyond it.
struct SideCells {
  bool normal_to_x;          // left and right
  int count;                 // cells along the side: ny on left and right, nx on bottom and top
  int first;                 // cell index across the side at depth 0: 0 on left and bottom, nx - 1 or ny - 1 opposite
  int inward;                // +1 on left and bottom, -1 on right and top
  int face;                  // index of the side's faces in the normal face field: 0, nx or ny
  double position;           // x of a left or right side, y of a bottom or top side [length]
  double normal_spacing;     // cell size across the side: dx on left and right, dy on bottom and top [length]
  double tangential_spacing; // cell size along the side [length]

  int i(int n, int depth) const { return normal_to_x ? first + depth * inward : n; }
  int j(int n, int depth) const { return normal_to_x ? n : first + depth * inward; }
  int face_i(int n) const { return normal_to_x ? face : n; }
  int face_j(int n) const { return normal_to_x ? n : face; }
};
SideCells side_cells(const Grid& grid, Side s);
// The point of side s at position n: the centre of its face there; a position beyond an end of
// the side (a corner ghost) takes the end.
std::array<double, 2> side_point(const Grid& grid, Side s, int n);

struct BoundarySide : WallMotion {
  SideKind kind = SideKind::wall;
  InflowProfile inflow;
  // Verification hook: velocity (u, v) on this side as a function of (x, y, t), used instead of the
  // wall or inflow rule on a Dirichlet side (manufactured solutions with open sides).
  std::function<std::array<double, 2>(double, double, double)> prescribed;
  bool is_dirichlet() const { return kind == SideKind::wall || kind == SideKind::inflow; }
};

struct FluidBoundaries {
  bool periodic_x = false, periodic_y = false;
  BoundarySide left, right, bottom, top;

  const BoundarySide& side(Side s) const;
  BoundarySide& side(Side s);
  // Side kind, periodic when the grid direction is periodic.
  SideKind kind(const Grid& grid, Side s) const;
  // Velocity (u, v) on a Dirichlet side at the point (x, y) of the side and time t.
  std::array<double, 2> velocity_at(const Grid& grid, Side s, double x, double y, double time) const;
  bool has_open_side(const Grid& grid) const;  // an inflow or outflow side
};

// Fill the ghost layer of both velocity components with the boundary values at `time`.
void fill_velocity_ghosts(const Grid& grid, const FluidBoundaries& bc, double time,
                          CellField& velocity_x, CellField& velocity_y);

// Ghost layer of the pressure (rules above).
void fill_pressure_ghosts(const Grid& grid, const FluidBoundaries& bc, CellField& pressure);

// Ghost layer of the pressure correction phi and of scalars with the same rule (rules above).
void fill_correction_ghosts(const Grid& grid, const FluidBoundaries& bc, CellField& scalar);

// Ghost layer of a scalar with zero normal gradient at every non-periodic side, periodic wrap.
void fill_neumann_ghosts(const Grid& grid, CellField& scalar);

// Re-apply periodic wrap to face fields: the last face of a periodic direction equals the first.
void sync_periodic_faces(const Grid& grid, FaceField& velocity_face_x, FaceField& velocity_face_y);

// Net volume flux into the box through its non-periodic sides, from the face velocities
// [length^2/time] (0 to round-off after a projection).
double net_inflow(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y);
// Volume flux through one side, positive into the box [length^2/time].
double side_inflow(const Grid& grid, Side s, const FaceField& velocity_face_x, const FaceField& velocity_face_y);

}  // namespace ibms
