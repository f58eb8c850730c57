// Boundary conditions of the fluid box (METHOD.md §2.5): periodic directions or no-slip walls
// whose tangential velocity is prescribed and may change in time; the wall-normal velocity is 0.
// Ghost rules: velocity u_g = 2 u_w - u_int (Dirichlet at the face), pressure p_g = p_int
// (zero normal gradient), periodic directions wrap. Ghosts are one cell deep (CellField).
#pragma once
#include <limits>

#include "core/fields.hpp"
#include "core/grid.hpp"

namespace ibms {

// Tangential speed of one wall as a function of time: `speed` until `stop_time`, then 0.
struct WallMotion {
  double speed = 0.0;       // [length/time]; +x on bottom/top walls, +y on left/right walls
  double stop_time = std::numeric_limits<double>::infinity();  // [time]
  double at(double time) const { return time < stop_time ? speed : 0.0; }
  bool is_moving() const { return speed != 0.0; }
};

struct FluidBoundaries {
  bool periodic_x = false, periodic_y = false;
  WallMotion left, right, bottom, top;
};

// Fill the ghost layer of both velocity components with the wall velocities at `time`.
void fill_velocity_ghosts(const Grid& grid, const FluidBoundaries& bc, double time,
                          CellField& velocity_x, CellField& velocity_y);

// Ghost layer of a scalar with zero normal gradient at walls (pressure, phi), periodic wrap.
void fill_neumann_ghosts(const Grid& grid, CellField& scalar);

// Ghost layer of a scalar that is odd about walls (q_g = -q_int), periodic wrap: the
// homogeneous Dirichlet rule of the Helmholtz operator.
void fill_dirichlet_ghosts(const Grid& grid, CellField& scalar);

// Re-apply periodic wrap to face fields: the last face of a periodic direction equals the first.
void sync_periodic_faces(const Grid& grid, FaceField& velocity_face_x, FaceField& velocity_face_y);

}  // namespace ibms
