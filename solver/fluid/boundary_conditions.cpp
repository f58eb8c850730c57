// Ghost-cell fills for the collocated grid (METHOD.md §2.5; same logic as CaNS src/bound.f90).
#include "fluid/boundary_conditions.hpp"

namespace ibms {
namespace {

// Fill x-ghosts (i = -1, nx) for rows j in [-1, ny]: periodic wrap or
// q_g = sign_low * q(0) + value_low (left) and q_g = sign_high * q(nx-1) + value_high (right).
void fill_x(const Grid& g, CellField& q, double sign, double value_left, double value_right) {
  for (int j = 0; j < g.ny; ++j) {
    if (g.periodic_x) {
      q(-1, j) = q(g.nx - 1, j);
      q(g.nx, j) = q(0, j);
    } else {
      q(-1, j) = sign * q(0, j) + value_left;
      q(g.nx, j) = sign * q(g.nx - 1, j) + value_right;
    }
  }
}

// y-ghosts over the full padded row width so corners are filled consistently (x first, then y).
void fill_y(const Grid& g, CellField& q, double sign, double value_bottom, double value_top) {
  for (int i = -1; i <= g.nx; ++i) {
    if (g.periodic_y) {
      q(i, -1) = q(i, g.ny - 1);
      q(i, g.ny) = q(i, 0);
    } else {
      q(i, -1) = sign * q(i, 0) + value_bottom;
      q(i, g.ny) = sign * q(i, g.ny - 1) + value_top;
    }
  }
}

}  // namespace

void fill_velocity_ghosts(const Grid& grid, const FluidBoundaries& bc, double time,
                          CellField& velocity_x, CellField& velocity_y) {
  // u: normal to left/right walls (u_w = 0), tangential to bottom/top (u_w = wall speed).
  fill_x(grid, velocity_x, -1.0, 0.0, 0.0);
  fill_y(grid, velocity_x, -1.0, 2.0 * bc.bottom.at(time), 2.0 * bc.top.at(time));
  // v: tangential to left/right walls, normal to bottom/top walls.
  fill_x(grid, velocity_y, -1.0, 2.0 * bc.left.at(time), 2.0 * bc.right.at(time));
  fill_y(grid, velocity_y, -1.0, 0.0, 0.0);
}

void fill_neumann_ghosts(const Grid& grid, CellField& scalar) {
  fill_x(grid, scalar, 1.0, 0.0, 0.0);
  fill_y(grid, scalar, 1.0, 0.0, 0.0);
}

void fill_dirichlet_ghosts(const Grid& grid, CellField& scalar) {
  fill_x(grid, scalar, -1.0, 0.0, 0.0);
  fill_y(grid, scalar, -1.0, 0.0, 0.0);
}

void sync_periodic_faces(const Grid& grid, FaceField& velocity_face_x, FaceField& velocity_face_y) {
  if (grid.periodic_x)
    for (int j = 0; j < grid.ny; ++j) velocity_face_x(grid.nx, j) = velocity_face_x(0, j);
  if (grid.periodic_y)
    for (int i = 0; i < grid.nx; ++i) velocity_face_y(i, grid.ny) = velocity_face_y(i, 0);
}

}  // namespace ibms
