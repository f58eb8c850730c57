// XDMF 3 sidecar so ParaView opens the HDF5 snapshots directly (docs/design.md §5), written by hand
// (libxdmf drags in the MPI build of HDF5). One temporal collection; per snapshot a spatial
// collection holding a 2DRectMesh on the cell corners (VXVY from /grid/x_faces, /grid/y_faces)
// with cell-centred attributes, and the rims of all bodies as one grid of polygons (X_Y geometry,
// a Mixed topology of one polygon per body).
// DataItems name the .h5 file by its basename so the pair can be moved together.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/grid.hpp"

namespace ibms {

struct XdmfSnapshot {
  std::string group;                     // "/snapshots/000010"
  double time = 0.0;
  std::vector<std::string> cell_arrays;  // arrays with dims (ny, nx), e.g. "u"
  // The bodies: <group>/bodies/x, y (n_body_points), the Mixed topology <group>/bodies/topology
  // (topology_size), the cell attribute <group>/bodies/body (n_bodies) and node arrays of n_body_points.
  std::size_t n_bodies = 0;
  std::size_t n_body_points = 0;
  std::size_t topology_size = 0;
  std::vector<std::string> body_node_arrays;  // e.g. "u"
};

// The XML text of the sidecar.
std::string xdmf_text(const std::string& h5_basename, const Grid& grid,
                      const std::vector<XdmfSnapshot>& snapshots);

// Writes xdmf_text to `xmf_path` via a temporary file and a rename, so a reader never sees half
// a file. Throws InputError naming the path on failure.
void write_xdmf_sidecar(const std::string& xmf_path, const std::string& h5_basename, const Grid& grid,
                        const std::vector<XdmfSnapshot>& snapshots);

}  // namespace ibms
