// Finite-volume operators of docs/method.md §2.2 (compact Laplacian, conservative convection with face
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
      // docs/method.md §2.2: (1/h)[U_{i+1/2} (q_{i+1}+q_i)/2 - U_{i-1/2} (q_i+q_{i-1})/2 + y-faces]
      const double flux_east = velocity_face_x(i + 1, j) * 0.5 * (q(i + 1, j) + q(i, j));
      const double flux_west = velocity_face_x(i, j) * 0.5 * (q(i, j) + q(i - 1, j));
      const double flux_north = velocity_face_y(i, j + 1) * 0.5 * (q(i, j + 1) + q(i, j));
      const double flux_south = velocity_face_y(i, j) * 0.5 * (q(i, j) + q(i, j - 1));
      out(i, j) = (flux_east - flux_west) * inv_dx + (flux_north - flux_south) * inv_dy;
    }
}

namespace {

// Upwind-biased face value of the kappa family between cells a (lower index) and b = a + 1 along
// one direction, given the cells a - 1 and b + 1 (valid: inside the ghost layer or wrapped) and the
// face velocity: q_up + (1 - kappa)/4 (q_up - q_upup) + (1 + kappa)/4 (q_down - q_up).
inline double upwind_biased_face(double kappa, double velocity, double q_aa, double q_a, double q_b, double q_bb,
                                 bool has_aa, bool has_bb) {
  const double behind = 0.25 * (1.0 - kappa), ahead = 0.25 * (1.0 + kappa);
  if (velocity > 0.0 && has_aa) return q_a + behind * (q_a - q_aa) + ahead * (q_b - q_a);
  if (velocity < 0.0 && has_bb) return q_b + behind * (q_b - q_bb) + ahead * (q_a - q_b);
  return 0.5 * (q_a + q_b);
}

}  // namespace

void convection_upwind_biased(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y,
                              const CellField& q, CellField& out, double kappa) {
  const double inv_dx = 1.0 / grid.dx(), inv_dy = 1.0 / grid.dy();
  const int nx = grid.nx, ny = grid.ny;
  // Cell k along a direction of n cells: wrapped when periodic; valid if in [-1, n] (ghost layer).
  const auto index = [](int k, int n, bool periodic) { return periodic ? ((k % n) + n) % n : k; };
  const auto valid = [](int k, int n, bool periodic) { return periodic || (k >= -1 && k <= n); };
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double flux[4];  // west, east, south, north: U_f q_f
      for (int side = 0; side < 2; ++side) {  // x-faces i (west, a = i - 1) and i + 1 (east, a = i)
        const int a = i - 1 + side;
        const double velocity = velocity_face_x(a + 1, j);
        const bool px = grid.periodic_x;
        const double q_aa = valid(a - 1, nx, px) ? q(index(a - 1, nx, px), j) : 0.0;
        const double q_bb = valid(a + 2, nx, px) ? q(index(a + 2, nx, px), j) : 0.0;
        flux[side] = velocity * upwind_biased_face(kappa, velocity, q_aa, q(a, j), q(a + 1, j), q_bb,
                                                   valid(a - 1, nx, px), valid(a + 2, nx, px));
      }
      for (int side = 0; side < 2; ++side) {  // y-faces j (south) and j + 1 (north)
        const int a = j - 1 + side;
        const double velocity = velocity_face_y(i, a + 1);
        const bool py = grid.periodic_y;
        const double q_aa = valid(a - 1, ny, py) ? q(i, index(a - 1, ny, py)) : 0.0;
        const double q_bb = valid(a + 2, ny, py) ? q(i, index(a + 2, ny, py)) : 0.0;
        flux[2 + side] = velocity * upwind_biased_face(kappa, velocity, q_aa, q(i, a), q(i, a + 1), q_bb,
                                                       valid(a - 1, ny, py), valid(a + 2, ny, py));
      }
      out(i, j) = (flux[1] - flux[0]) * inv_dx + (flux[3] - flux[2]) * inv_dy;
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
