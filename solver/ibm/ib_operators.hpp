// Interpolation J (grid -> markers) and spreading S = J* (markers -> grid) of the direct-forcing
// IB method, docs/method.md §3.1 steps 2 and 4 and §4 ("Weights, adjointness, conservation"):
//   U_l = sum_x u(x) delta_h(x - X_l) dx dy,   f(x) += sum_l F_l delta_h(x - X_l) dV_l,
// on cell-centred (collocated) velocity components; only interior cell values are read/written.
// Walls: stencil cells beyond a wall are mirrored onto interior cells with the no-slip ghost
// rule u_g = 2 u_wall - u_mirror (tangential) and u_g = -u_mirror (normal), reflecting in x
// then y at corners; spreading adds the transpose of the linear part, so with zero wall
// speeds <S F, u>_{dx dy} = <F, J u>_{dV} to round-off. Periodic directions wrap.
#pragma once
#include <array>
#include <vector>

#include "core/fields.hpp"
#include "core/grid.hpp"
#include "ibm/delta_kernel.hpp"

namespace ibms {

// Tangential wall speeds [length/time]: v on the left/right walls, u on the bottom/top walls.
// Ignored in periodic directions.
struct WallVelocities {
  double left = 0, right = 0, bottom = 0, top = 0;
};

// U_out[l] = (J u, J v)(X_l) [length/time]. Markers must lie inside the box in wall directions
// (anywhere in periodic ones), otherwise std::invalid_argument.
void interpolate(const Grid& grid, KernelKind kernel, const WallVelocities& walls,
                 const CellField& velocity_x, const CellField& velocity_y,
                 const std::vector<std::array<double, 2>>& markers,
                 std::vector<std::array<double, 2>>& velocity_out);

// force_x/y(cell) += sum_l F_l delta_h(x_cell - X_l) dV_l  (adds; does not clear).
// F [force per unit mass, i.e. length/time^2], dV [length^2 per unit depth],
// f [length/time^2]. Same marker checks as interpolate.
void spread(const Grid& grid, KernelKind kernel, const std::vector<std::array<double, 2>>& markers,
            const std::vector<std::array<double, 2>>& marker_force,
            const std::vector<double>& marker_volume, CellField& force_x, CellField& force_y);

// The same spreading onto the face-normal components: F_x onto the x-faces (x_{i-1/2}, y_j), F_y
// onto the y-faces (x_i, y_{j-1/2}), with the kernel centred at the faces; adds. Shares beyond a wall
// go to the mirrored face with a factor -1 per reflection; a periodic direction's last face is set
// equal to its first. Used where a force must enter the face velocities as the pressure gradient
// does (balanced momentum interpolation, fluid/fluid_solver.hpp).
void spread_to_faces(const Grid& grid, KernelKind kernel, const std::vector<std::array<double, 2>>& markers,
                     const std::vector<std::array<double, 2>>& marker_force, const std::vector<double>& marker_volume,
                     FaceField& face_x, FaceField& face_y);

// (J_f U)(X_l): the face-normal components interpolated from their own faces, u from the x-faces
// and v from the y-faces, the kernel centred at the faces: the transpose of spread_to_faces with
// the tangential wall speeds' affine part, so <S_f F, U>_{dx dy} = <F, J_f U>_{dV} with walls at
// rest. The faces carry the divergence-free velocity of the projection (fluid/fluid_solver.hpp).
void interpolate_faces(const Grid& grid, KernelKind kernel, const WallVelocities& walls, const FaceField& face_x,
                       const FaceField& face_y, const std::vector<std::array<double, 2>>& markers,
                       std::vector<std::array<double, 2>>& velocity_out);

// One marker's kernel stencil in one direction, mapped onto the interior nodes it reads and writes.
struct MappedStencil {
  int n_nodes = 0;
  std::array<int, 6> cell{};        // interior node index each stencil node reads/writes
  std::array<double, 6> weight{};   // phi of the node [-]
  std::array<int, 6> ghost_side{};  // 0: interior or periodic image; -1: beyond the low wall; +1: high
};
// A marker's stencils for the face components: over the cell centres (cx, cy) and the faces (fx, fy)
// of each direction; u lives on (fx, cy), v on (cx, fy).
struct FaceStencils {
  MappedStencil cx, cy, fx, fy;
};
// The face stencils of markers that stay put over several spreads and interpolations (the products
// of the no-slip marker system): mapped once, then used by the overloads below, which give the
// same bits as the (kernel, markers) forms. Replaces `out`; same marker checks as interpolate.
void map_face_stencils(const Grid& grid, KernelKind kernel, const std::vector<std::array<double, 2>>& markers,
                       std::vector<FaceStencils>& out);
void spread_to_faces(const Grid& grid, const std::vector<FaceStencils>& stencils,
                     const std::vector<std::array<double, 2>>& marker_force, const std::vector<double>& marker_volume,
                     FaceField& face_x, FaceField& face_y);
// spread onto the cell centres with the markers' cell stencils (cx, cy) of the mapped stencils.
void spread(const Grid& grid, const std::vector<FaceStencils>& stencils,
            const std::vector<std::array<double, 2>>& marker_force, const std::vector<double>& marker_volume,
            CellField& force_x, CellField& force_y);
void interpolate_faces(const Grid& grid, const std::vector<FaceStencils>& stencils, const WallVelocities& walls,
                       const FaceField& face_x, const FaceField& face_y,
                       std::vector<std::array<double, 2>>& velocity_out);

// One node that a marker touches: its index in the component's field (i + j ni) and the signed
// weight phi phi (-1 per wall reflection), so that spreading adds weight F dV / (dx dy) to the node
// and the linear part of interpolation sums weight * value.
struct NodeWeight {
  int node = 0;
  double weight = 0.0;
};

// The nodes of velocity component `component` (0: u, 1: v) that marker X touches, on the cell
// centres (interpolate / spread) or on that component's faces (interpolate_faces / spread_to_faces),
// sorted by node with the mirrored shares of one node summed. Replaces `out`.
void marker_node_weights(const Grid& grid, KernelKind kernel, const std::array<double, 2>& marker, bool on_faces,
                         int component, std::vector<NodeWeight>& out);
// The same from the marker's mapped stencils (map_face_stencils).
void marker_node_weights(const Grid& grid, const FaceStencils& stencils, bool on_faces, int component,
                         std::vector<NodeWeight>& out);

}  // namespace ibms
