// Uniform Cartesian grid of a rectangular 2D box: cell counts, spacings, cell-centre and face
// coordinates, and which directions are periodic (docs/method.md §2.2). No physics here.
// Cells are indexed (i, j), x fastest; cell (i, j) spans [x0 + i dx, x0 + (i+1) dx] x [...].
#pragma once
#include <cstddef>

namespace ibms {

struct Grid {
  int nx = 0, ny = 0;          // cell counts [-]
  double length_x = 1.0;       // box size in x [length]
  double length_y = 1.0;       // box size in y [length]
  double origin_x = 0.0;       // lower-left corner [length]
  double origin_y = 0.0;
  bool periodic_x = false;     // x direction periodic (otherwise walls at both ends)
  bool periodic_y = false;

  Grid() = default;
  Grid(int n_x, int n_y, double lx, double ly, bool per_x = false, bool per_y = false,
       double x0 = 0.0, double y0 = 0.0)
      : nx(n_x), ny(n_y), length_x(lx), length_y(ly), origin_x(x0), origin_y(y0),
        periodic_x(per_x), periodic_y(per_y) {}

  double dx() const { return length_x / nx; }  // cell width [length]
  double dy() const { return length_y / ny; }  // cell height [length]
  double cell_area() const { return dx() * dy(); }
  std::size_t n_cells() const { return static_cast<std::size_t>(nx) * ny; }
  double x_centre(int i) const { return origin_x + (i + 0.5) * dx(); }
  double y_centre(int j) const { return origin_y + (j + 0.5) * dy(); }
  double x_face(int i) const { return origin_x + i * dx(); }  // left face of cell i
  double y_face(int j) const { return origin_y + j * dy(); }  // bottom face of cell j
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j; }
};

}  // namespace ibms
