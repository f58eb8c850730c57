// XDMF 3 sidecar so ParaView opens the HDF5 snapshots directly (docs/design.md §5), written by hand
// (libxdmf drags in the MPI build of HDF5). One temporal collection; per snapshot a spatial
// collection holding a 2DRectMesh on the cell corners (VXVY from /grid/x_faces, /grid/y_faces)
// with cell-centred attributes, and each body's points as a closed polyline (X_Y geometry).
// DataItems name the .h5 file by its basename so the pair can be moved together.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/grid.hpp"

namespace ibms {

struct XdmfBody {
  std::string group;                     // "body_000"
  std::size_t n_points = 0;
  std::vector<std::string> node_arrays;  // other arrays of the body (n), e.g. "vx"
};

struct XdmfSnapshot {
  std::string group;                     // "/snapshots/000010"
  double time = 0.0;
  std::vector<std::string> cell_arrays;  // arrays with dims (ny, nx), e.g. "u"
  std::vector<XdmfBody> bodies;          // body groups with x and y arrays
};

// The XML text of the sidecar.
std::string xdmf_text(const std::string& h5_basename, const Grid& grid,
                      const std::vector<XdmfSnapshot>& snapshots);

// Writes xdmf_text to `xmf_path` via a temporary file and a rename, so a reader never sees half
// a file. Throws InputError naming the path on failure.
void write_xdmf_sidecar(const std::string& xmf_path, const std::string& h5_basename, const Grid& grid,
                        const std::vector<XdmfSnapshot>& snapshots);

}  // namespace ibms
