// Contiguous field storage on a Grid (x fastest): cell-centred fields with one ghost layer,
// and face-normal fields on x-faces ((nx+1) x ny) and y-faces (nx x (ny+1)).
// Ghost values are filled by fluid/boundary_conditions.hpp; everything else reads interior cells.
#pragma once
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

#include "core/grid.hpp"

namespace ibms {

// Cell-centred scalar with one ghost layer: valid indices i in [-1, nx], j in [-1, ny].
class CellField {
 public:
  CellField() = default;
  CellField(int nx, int ny, double value = 0.0)
      : nx_(nx), ny_(ny), data_(static_cast<std::size_t>(nx + 2) * (ny + 2), value) {}
  explicit CellField(const Grid& grid, double value = 0.0) : CellField(grid.nx, grid.ny, value) {}

  double& operator()(int i, int j) { return data_[offset(i, j)]; }
  double operator()(int i, int j) const { return data_[offset(i, j)]; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int stride() const { return nx_ + 2; }  // distance between rows j and j+1
  double* data() { return data_.data(); }
  const double* data() const { return data_.data(); }
  void fill(double value) { std::fill(data_.begin(), data_.end(), value); }

  // Interior values, row-major (ny, nx), into/out of a contiguous buffer of nx*ny.
  void copy_interior_to(double* out) const {
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) out[i + static_cast<std::size_t>(nx_) * j] = (*this)(i, j);
  }
  void copy_interior_from(const double* in) {
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) (*this)(i, j) = in[i + static_cast<std::size_t>(nx_) * j];
  }

 private:
  std::size_t offset(int i, int j) const {
    assert(i >= -1 && i <= nx_ && j >= -1 && j <= ny_);
    return static_cast<std::size_t>(i + 1) + static_cast<std::size_t>(nx_ + 2) * (j + 1);
  }
  int nx_ = 0, ny_ = 0;
  std::vector<double> data_;
};

// Face-normal scalar on faces of one orientation: n_i x n_j values, x fastest.
// x-faces: n_i = nx + 1 (face i is the left face of cell i), n_j = ny.
// y-faces: n_i = nx, n_j = ny + 1 (face j is the bottom face of cell j).
// In a periodic direction the last face duplicates the first; both are kept equal.
class FaceField {
 public:
  FaceField() = default;
  FaceField(int n_i, int n_j, double value = 0.0)
      : ni_(n_i), nj_(n_j), data_(static_cast<std::size_t>(n_i) * n_j, value) {}
  static FaceField x_faces(const Grid& g) { return FaceField(g.nx + 1, g.ny); }
  static FaceField y_faces(const Grid& g) { return FaceField(g.nx, g.ny + 1); }

  double& operator()(int i, int j) { return data_[offset(i, j)]; }
  double operator()(int i, int j) const { return data_[offset(i, j)]; }
  int ni() const { return ni_; }
  int nj() const { return nj_; }
  void fill(double value) { std::fill(data_.begin(), data_.end(), value); }
  const std::vector<double>& values() const { return data_; }
  std::vector<double>& values() { return data_; }

 private:
  std::size_t offset(int i, int j) const {
    assert(i >= 0 && i < ni_ && j >= 0 && j < nj_);
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni_) * j;
  }
  int ni_ = 0, nj_ = 0;
  std::vector<double> data_;
};

}  // namespace ibms
