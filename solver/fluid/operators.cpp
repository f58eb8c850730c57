// Finite-volume operators of METHOD.md §2.2 (compact Laplacian, conservative convection with face
// velocities, wide centre gradient, face divergence). Loops run x fastest over contiguous rows;
// rows are shared among the OpenMP threads (fluid/threads.hpp), each cell written by one thread.
#include "fluid/operators.hpp"
#include "fluid/threads.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

void laplacian(const Grid& grid, const CellField& q, CellField& out) {
  const double inv_dx2 = 1.0 / (grid.dx() * grid.dx()), inv_dy2 = 1.0 / (grid.dy() * grid.dy());
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      out(i, j) = (q(i - 1, j) - 2.0 * q(i, j) + q(i + 1, j)) * inv_dx2 +
                  (q(i, j - 1) - 2.0 * q(i, j) + q(i, j + 1)) * inv_dy2;
}

void convection(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y,
                const CellField& q, CellField& out) {
  const double inv_dx = 1.0 / grid.dx(), inv_dy = 1.0 / grid.dy();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      // METHOD.md §2.2: (1/h)[U_{i+1/2} (q_{i+1}+q_i)/2 - U_{i-1/2} (q_i+q_{i-1})/2 + y-faces]
      const double flux_east = velocity_face_x(i + 1, j) * 0.5 * (q(i + 1, j) + q(i, j));
      const double flux_west = velocity_face_x(i, j) * 0.5 * (q(i, j) + q(i - 1, j));
      const double flux_north = velocity_face_y(i, j + 1) * 0.5 * (q(i, j + 1) + q(i, j));
      const double flux_south = velocity_face_y(i, j) * 0.5 * (q(i, j) + q(i, j - 1));
      out(i, j) = (flux_east - flux_west) * inv_dx + (flux_north - flux_south) * inv_dy;
    }
}

void centre_gradient(const Grid& grid, const CellField& p, CellField& grad_x, CellField& grad_y) {
  const double half_inv_dx = 0.5 / grid.dx(), half_inv_dy = 0.5 / grid.dy();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      grad_x(i, j) = (p(i + 1, j) - p(i - 1, j)) * half_inv_dx;
      grad_y(i, j) = (p(i, j + 1) - p(i, j - 1)) * half_inv_dy;
    }
}

void divergence(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y,
                double scale, double* out) {
  const double sx = scale / grid.dx(), sy = scale / grid.dy();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      out[grid.index(i, j)] = (velocity_face_x(i + 1, j) - velocity_face_x(i, j)) * sx +
                              (velocity_face_y(i, j + 1) - velocity_face_y(i, j)) * sy;
}

double max_abs_divergence(const Grid& grid, const FaceField& velocity_face_x,
                          const FaceField& velocity_face_y) {
  double result = 0.0;
  const double inv_dx = 1.0 / grid.dx(), inv_dy = 1.0 / grid.dy();
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      result = std::max(result, std::abs((velocity_face_x(i + 1, j) - velocity_face_x(i, j)) * inv_dx +
                                         (velocity_face_y(i, j + 1) - velocity_face_y(i, j)) * inv_dy));
  return result;
}

void vorticity(const Grid& grid, const CellField& velocity_x, const CellField& velocity_y, CellField& out) {
  const double half_inv_dx = 0.5 / grid.dx(), half_inv_dy = 0.5 / grid.dy();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      out(i, j) = (velocity_y(i + 1, j) - velocity_y(i - 1, j)) * half_inv_dx -
                  (velocity_x(i, j + 1) - velocity_x(i, j - 1)) * half_inv_dy;
}

}  // namespace ibms
