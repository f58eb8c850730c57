// Interpolation and spreading with wall mirroring, docs/method.md §3.1, §4 (see ib_operators.hpp).
// Per marker and direction the kernel weights are computed once (kernel_stencil) and each node
// is mapped to the interior cell it reads/writes, with the side of the wall it mirrors across.
#include "ibm/ib_operators.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ibms {
namespace {

// The nodes a stencil maps onto in one direction: the cell centres 0..n-1 (centre m at
// origin + (m + 1/2) spacing) or the faces 0..n normal to it (face m at origin + m spacing).
enum class Nodes { centres, faces };

// Marker coordinate -> stencil over the nodes of one direction. Beyond a wall, centre ghost -1-m
// mirrors centre m and n+m mirrors n-1-m; face -k mirrors face k and n+k mirrors n-k (ghost_side
// -1 / +1: the linear part of the ghost rule is odd about the wall). Periodic nodes wrap to 0..n-1.
MappedStencil map_stencil(KernelKind kernel, double coordinate, double origin, double spacing,
                          int n_cells, bool periodic, const char* axis, Nodes nodes = Nodes::centres) {
  const double length = spacing * n_cells;
  if (!std::isfinite(coordinate))
    throw std::invalid_argument(std::string("IB marker has a non-finite ") + axis + " coordinate");
  if (!periodic && (coordinate < origin || coordinate > origin + length))
    throw std::invalid_argument(std::string("IB marker outside the box in ") + axis + ": " +
                                std::to_string(coordinate));
  if (!periodic && n_cells < kernel_support(kernel))
    throw std::invalid_argument(std::string("fewer cells than the kernel support in ") + axis);
  // Node m sits at xi = m; a centre's mirror index is one lower than a face's.
  const int shift = nodes == Nodes::centres ? 1 : 0;
  const double xi = (coordinate - origin) / spacing - 0.5 * shift;
  const KernelStencil stencil = kernel_stencil(kernel, xi);
  MappedStencil mapped;
  mapped.n_nodes = stencil.n_nodes;
  for (int k = 0; k < stencil.n_nodes; ++k) {
    int node = stencil.first + k;
    int side = 0;
    if (periodic) {
      node = ((node % n_cells) + n_cells) % n_cells;
    } else if (node < 0) {
      node = -shift - node;
      side = -1;
    } else if (node > n_cells - shift) {
      node = 2*n_cells - shift - node;
      side = +1;
    }
    mapped.cell[k] = node;
    mapped.weight[k] = stencil.weight[k];
    mapped.ghost_side[k] = side;
  }
  return mapped;
}

FaceStencils face_stencils(const Grid& grid, KernelKind kernel, const std::array<double, 2>& marker) {
  return {map_stencil(kernel, marker[0], grid.origin_x, grid.dx(), grid.nx, grid.periodic_x, "x"),
          map_stencil(kernel, marker[1], grid.origin_y, grid.dy(), grid.ny, grid.periodic_y, "y"),
          map_stencil(kernel, marker[0], grid.origin_x, grid.dx(), grid.nx, grid.periodic_x, "x", Nodes::faces),
          map_stencil(kernel, marker[1], grid.origin_y, grid.dy(), grid.ny, grid.periodic_y, "y", Nodes::faces)};
}

void check_field(const Grid& grid, const CellField& field, const char* name) {
  if (field.nx() != grid.nx || field.ny() != grid.ny)
    throw std::invalid_argument(std::string(name) + " does not match the grid");
}

void check_faces(const Grid& grid, const FaceField& face_x, const FaceField& face_y, const char* who) {
  if (face_x.ni() != grid.nx + 1 || face_x.nj() != grid.ny || face_y.ni() != grid.nx || face_y.nj() != grid.ny + 1)
    throw std::invalid_argument(std::string(who) + ": face fields do not match the grid");
}

// One marker's force onto the faces (spread_to_faces).
void spread_marker_to_faces(const FaceStencils& stencils, double ax, double ay, FaceField& face_x, FaceField& face_y) {
  const auto& [cx, cy, fx, fy] = stencils;
  // Each reflection is a factor -1, as for the cell centres: the normal component is odd about
  // a wall's faces, the tangential one odd about the wall between the mirrored cells.
  for (int ky = 0; ky < cy.n_nodes; ++ky)
    for (int kx = 0; kx < fx.n_nodes; ++kx) {
      const double sign = (fx.ghost_side[kx] != 0) == (cy.ghost_side[ky] != 0) ? 1.0 : -1.0;
      face_x(fx.cell[kx], cy.cell[ky]) += sign * fx.weight[kx] * cy.weight[ky] * ax;
    }
  for (int ky = 0; ky < fy.n_nodes; ++ky)
    for (int kx = 0; kx < cx.n_nodes; ++kx) {
      const double sign = (cx.ghost_side[kx] != 0) == (fy.ghost_side[ky] != 0) ? 1.0 : -1.0;
      face_y(cx.cell[kx], fy.cell[ky]) += sign * cx.weight[kx] * fy.weight[ky] * ay;
    }
}

// A periodic direction's last face equals its first.
void close_periodic_faces(const Grid& grid, FaceField& face_x, FaceField& face_y) {
  if (grid.periodic_x)
    for (int j = 0; j < grid.ny; ++j) face_x(grid.nx, j) = face_x(0, j);
  if (grid.periodic_y)
    for (int i = 0; i < grid.nx; ++i) face_y(i, grid.ny) = face_y(i, 0);
}

// (J_f U)(X_l) of one marker (interpolate_faces).
std::array<double, 2> interpolate_marker_faces(const FaceStencils& stencils, const WallVelocities& walls,
                                               const FaceField& face_x, const FaceField& face_y) {
  const auto& [cx, cy, fx, fy] = stencils;
  // The transpose of spread_to_faces, plus the affine part of the tangential ghost rule
  // u_g = 2 u_wall - u_mirror (the normal component is odd about a wall).
  double u_sum = 0.0, v_sum = 0.0;
  for (int ky = 0; ky < cy.n_nodes; ++ky) {
    const bool ghost_y = cy.ghost_side[ky] != 0;
    const double u_wall = cy.ghost_side[ky] < 0 ? walls.bottom : walls.top;
    for (int kx = 0; kx < fx.n_nodes; ++kx) {
      const double s_x = fx.ghost_side[kx] != 0 ? -1.0 : 1.0;
      const double value = ghost_y ? 2.0 * u_wall - face_x(fx.cell[kx], cy.cell[ky]) : face_x(fx.cell[kx], cy.cell[ky]);
      u_sum += fx.weight[kx] * cy.weight[ky] * s_x * value;
    }
  }
  for (int ky = 0; ky < fy.n_nodes; ++ky) {
    const double s_y = fy.ghost_side[ky] != 0 ? -1.0 : 1.0;
    for (int kx = 0; kx < cx.n_nodes; ++kx) {
      const bool ghost_x = cx.ghost_side[kx] != 0;
      const double v_wall = cx.ghost_side[kx] < 0 ? walls.left : walls.right;
      const double value = ghost_x ? 2.0 * v_wall - face_y(cx.cell[kx], fy.cell[ky]) : face_y(cx.cell[kx], fy.cell[ky]);
      v_sum += cx.weight[kx] * fy.weight[ky] * s_y * value;
    }
  }
  return {u_sum, v_sum};
}

}  // namespace

void interpolate(const Grid& grid, KernelKind kernel, const WallVelocities& walls,
                 const CellField& velocity_x, const CellField& velocity_y,
                 const std::vector<std::array<double, 2>>& markers,
                 std::vector<std::array<double, 2>>& velocity_out) {
  check_field(grid, velocity_x, "interpolate: velocity_x");
  check_field(grid, velocity_y, "interpolate: velocity_y");
  velocity_out.assign(markers.size(), {0.0, 0.0});
  for (std::size_t l = 0; l < markers.size(); ++l) {
    const MappedStencil sx = map_stencil(kernel, markers[l][0], grid.origin_x, grid.dx(), grid.nx,
                                         grid.periodic_x, "x");
    const MappedStencil sy = map_stencil(kernel, markers[l][1], grid.origin_y, grid.dy(), grid.ny,
                                         grid.periodic_y, "y");
    double u_sum = 0.0, v_sum = 0.0;
    for (int ky = 0; ky < sy.n_nodes; ++ky) {
      const int j = sy.cell[ky];
      // Tangential (u) wall speed of the bottom/top wall this row mirrors across.
      const double u_wall = sy.ghost_side[ky] < 0 ? walls.bottom : walls.top;
      for (int kx = 0; kx < sx.n_nodes; ++kx) {
        const int i = sx.cell[kx];
        const double w = sx.weight[kx] * sy.weight[ky];  // delta_h dx dy
        const double v_wall = sx.ghost_side[kx] < 0 ? walls.left : walls.right;
        const bool ghost_x = sx.ghost_side[kx] != 0, ghost_y = sy.ghost_side[ky] != 0;
        // Both ghost rules have linear part -u_mirror; reflect in x, then in y:
        // value = a_x + s_x (a_y + s_y u_mirror).
        const double s_x = ghost_x ? -1.0 : 1.0, s_y = ghost_y ? -1.0 : 1.0;
        // u: normal to the x-walls (a_x = 0), tangential to the y-walls (a_y = 2 u_wall).
        const double u_ghost = s_x * ((ghost_y ? 2.0*u_wall : 0.0) + s_y * velocity_x(i, j));
        // v: tangential to the x-walls (a_x = 2 v_wall), normal to the y-walls (a_y = 0).
        const double v_ghost = (ghost_x ? 2.0*v_wall : 0.0) + s_x * s_y * velocity_y(i, j);
        u_sum += w * u_ghost;
        v_sum += w * v_ghost;
      }
    }
    velocity_out[l] = {u_sum, v_sum};
  }
}

namespace {

// force += F_l phi phi / (dx dy) dV_l of one marker on the cell centres (sx, sy: its cell stencils);
// a ghost-cell share goes to its mirror with the transpose of the linear ghost rule, (-1) per
// reflection (the affine part has no transpose).
void spread_marker(const MappedStencil& sx, const MappedStencil& sy, double fx, double fy, CellField& force_x,
                   CellField& force_y) {
  for (int ky = 0; ky < sy.n_nodes; ++ky) {
    const int j = sy.cell[ky];
    for (int kx = 0; kx < sx.n_nodes; ++kx) {
      const int i = sx.cell[kx];
      const double sign = (sx.ghost_side[kx] != 0) == (sy.ghost_side[ky] != 0) ? 1.0 : -1.0;
      const double w = sign * sx.weight[kx] * sy.weight[ky];
      force_x(i, j) += w * fx;
      force_y(i, j) += w * fy;
    }
  }
}

}  // namespace

void spread(const Grid& grid, KernelKind kernel, const std::vector<std::array<double, 2>>& markers,
            const std::vector<std::array<double, 2>>& marker_force,
            const std::vector<double>& marker_volume, CellField& force_x, CellField& force_y) {
  check_field(grid, force_x, "spread: force_x");
  check_field(grid, force_y, "spread: force_y");
  if (marker_force.size() != markers.size() || marker_volume.size() != markers.size())
    throw std::invalid_argument("spread: markers, forces and volumes differ in length");
  const double inverse_cell_area = 1.0 / (grid.dx() * grid.dy());
  for (std::size_t l = 0; l < markers.size(); ++l) {
    const MappedStencil sx = map_stencil(kernel, markers[l][0], grid.origin_x, grid.dx(), grid.nx,
                                         grid.periodic_x, "x");
    const MappedStencil sy = map_stencil(kernel, markers[l][1], grid.origin_y, grid.dy(), grid.ny,
                                         grid.periodic_y, "y");
    spread_marker(sx, sy, marker_force[l][0] * marker_volume[l] * inverse_cell_area,
                  marker_force[l][1] * marker_volume[l] * inverse_cell_area, force_x, force_y);
  }
}

void spread(const Grid& grid, const std::vector<FaceStencils>& stencils,
            const std::vector<std::array<double, 2>>& marker_force, const std::vector<double>& marker_volume,
            CellField& force_x, CellField& force_y) {
  check_field(grid, force_x, "spread: force_x");
  check_field(grid, force_y, "spread: force_y");
  if (marker_force.size() != stencils.size() || marker_volume.size() != stencils.size())
    throw std::invalid_argument("spread: markers, forces and volumes differ in length");
  const double inverse_cell_area = 1.0 / (grid.dx() * grid.dy());
  for (std::size_t l = 0; l < stencils.size(); ++l)
    spread_marker(stencils[l].cx, stencils[l].cy, marker_force[l][0] * marker_volume[l] * inverse_cell_area,
                  marker_force[l][1] * marker_volume[l] * inverse_cell_area, force_x, force_y);
}

void spread_to_faces(const Grid& grid, KernelKind kernel, const std::vector<std::array<double, 2>>& markers,
                     const std::vector<std::array<double, 2>>& marker_force, const std::vector<double>& marker_volume,
                     FaceField& face_x, FaceField& face_y) {
  thread_local std::vector<FaceStencils> stencils;  // kept between calls: no allocation once grown
  map_face_stencils(grid, kernel, markers, stencils);
  spread_to_faces(grid, stencils, marker_force, marker_volume, face_x, face_y);
}

void spread_to_faces(const Grid& grid, const std::vector<FaceStencils>& stencils,
                     const std::vector<std::array<double, 2>>& marker_force, const std::vector<double>& marker_volume,
                     FaceField& face_x, FaceField& face_y) {
  check_faces(grid, face_x, face_y, "spread_to_faces");
  if (marker_force.size() != stencils.size() || marker_volume.size() != stencils.size())
    throw std::invalid_argument("spread_to_faces: markers, forces and volumes differ in length");
  const double inverse_cell_area = 1.0 / (grid.dx() * grid.dy());
  for (std::size_t l = 0; l < stencils.size(); ++l)
    spread_marker_to_faces(stencils[l], marker_force[l][0] * marker_volume[l] * inverse_cell_area,
                           marker_force[l][1] * marker_volume[l] * inverse_cell_area, face_x, face_y);
  close_periodic_faces(grid, face_x, face_y);
}

void interpolate_faces(const Grid& grid, KernelKind kernel, const WallVelocities& walls, const FaceField& face_x,
                       const FaceField& face_y, const std::vector<std::array<double, 2>>& markers,
                       std::vector<std::array<double, 2>>& velocity_out) {
  thread_local std::vector<FaceStencils> stencils;
  map_face_stencils(grid, kernel, markers, stencils);
  interpolate_faces(grid, stencils, walls, face_x, face_y, velocity_out);
}

void interpolate_faces(const Grid& grid, const std::vector<FaceStencils>& stencils, const WallVelocities& walls,
                       const FaceField& face_x, const FaceField& face_y,
                       std::vector<std::array<double, 2>>& velocity_out) {
  check_faces(grid, face_x, face_y, "interpolate_faces");
  velocity_out.resize(stencils.size());
  for (std::size_t l = 0; l < stencils.size(); ++l)
    velocity_out[l] = interpolate_marker_faces(stencils[l], walls, face_x, face_y);
}

void map_face_stencils(const Grid& grid, KernelKind kernel, const std::vector<std::array<double, 2>>& markers,
                       std::vector<FaceStencils>& out) {
  out.resize(markers.size());
  for (std::size_t l = 0; l < markers.size(); ++l) out[l] = face_stencils(grid, kernel, markers[l]);
}

void marker_node_weights(const Grid& grid, KernelKind kernel, const std::array<double, 2>& marker, bool on_faces,
                         int component, std::vector<NodeWeight>& out) {
  marker_node_weights(grid, face_stencils(grid, kernel, marker), on_faces, component, out);
}

void marker_node_weights(const Grid& grid, const FaceStencils& stencils, bool on_faces, int component,
                         std::vector<NodeWeight>& out) {
  const auto& [cx, cy, fx, fy] = stencils;
  // u on (fx, cy) and v on (cx, fy) for the faces; both on (cx, cy) for the centres.
  const MappedStencil& sx = on_faces && component == 0 ? fx : cx;
  const MappedStencil& sy = on_faces && component == 1 ? fy : cy;
  const int ni = on_faces && component == 0 ? grid.nx + 1 : grid.nx;
  out.clear();
  for (int ky = 0; ky < sy.n_nodes; ++ky)
    for (int kx = 0; kx < sx.n_nodes; ++kx) {
      const double sign = (sx.ghost_side[kx] != 0) == (sy.ghost_side[ky] != 0) ? 1.0 : -1.0;
      out.push_back({sx.cell[kx] + ni * sy.cell[ky], sign * sx.weight[kx] * sy.weight[ky]});
    }
  std::sort(out.begin(), out.end(), [](const NodeWeight& a, const NodeWeight& b) { return a.node < b.node; });
  std::size_t kept = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (kept > 0 && out[kept - 1].node == out[k].node)
      out[kept - 1].weight += out[k].weight;
    else
      out[kept++] = out[k];
  }
  out.resize(kept);
}

}  // namespace ibms
