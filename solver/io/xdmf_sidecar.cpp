// Hand-written XDMF 3 sidecar for the HDF5 snapshots (xdmf_sidecar.hpp). Dimensions are listed
// slowest first, as HDF5 stores them: grid fields (ny, nx), the corner mesh (ny+1, nx+1).
#include "io/xdmf_sidecar.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace ibms {

namespace {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// <DataItem> pointing at one dataset of the .h5 file.
std::string hdf_item(const std::string& h5_basename, const std::string& dataset, const std::string& dims,
                     const char* indent) {
  return fmt::format("{}<DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">{}:{}</DataItem>\n",
                     indent, dims, xml_escaped(h5_basename), xml_escaped(dataset));
}

void append_fluid_grid(std::string& out, const std::string& h5, const Grid& grid, const XdmfSnapshot& snapshot) {
  out += "        <Grid Name=\"fluid\" GridType=\"Uniform\">\n";
  out += fmt::format("          <Time Value=\"{}\"/>\n", snapshot.time);
  out += fmt::format("          <Topology TopologyType=\"2DRectMesh\" Dimensions=\"{} {}\"/>\n", grid.ny + 1, grid.nx + 1);
  out += "          <Geometry GeometryType=\"VXVY\">\n";
  out += hdf_item(h5, "/grid/x_faces", std::to_string(grid.nx + 1), "            ");
  out += hdf_item(h5, "/grid/y_faces", std::to_string(grid.ny + 1), "            ");
  out += "          </Geometry>\n";
  for (const std::string& name : snapshot.cell_arrays) {
    out += fmt::format("          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n", xml_escaped(name));
    out += hdf_item(h5, snapshot.group + "/" + name, fmt::format("{} {}", grid.ny, grid.nx), "            ");
    out += "          </Attribute>\n";
  }
  out += "        </Grid>\n";
}

void append_bodies_grid(std::string& out, const std::string& h5, const XdmfSnapshot& snapshot) {
  const std::string group = snapshot.group + "/bodies";
  const std::string n = std::to_string(snapshot.n_body_points);
  out += "        <Grid Name=\"bodies\" GridType=\"Uniform\">\n";
  out += fmt::format("          <Time Value=\"{}\"/>\n", snapshot.time);
  // One polygon per body through its rim points in order: the closed rim.
  out += fmt::format("          <Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\">\n", snapshot.n_bodies);
  out += fmt::format("            <DataItem Dimensions=\"{}\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">{}:{}/topology</DataItem>\n",
                     snapshot.topology_size, xml_escaped(h5), xml_escaped(group));
  out += "          </Topology>\n";
  out += "          <Geometry GeometryType=\"X_Y\">\n";
  out += hdf_item(h5, group + "/x", n, "            ");
  out += hdf_item(h5, group + "/y", n, "            ");
  out += "          </Geometry>\n";
  out += "          <Attribute Name=\"body\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
  out += hdf_item(h5, group + "/body", std::to_string(snapshot.n_bodies), "            ");
  out += "          </Attribute>\n";
  for (const std::string& name : snapshot.body_node_arrays) {
    out += fmt::format("          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n", xml_escaped(name));
    out += hdf_item(h5, group + "/" + name, n, "            ");
    out += "          </Attribute>\n";
  }
  out += "        </Grid>\n";
}

}  // namespace

std::string xdmf_text(const std::string& h5_basename, const Grid& grid, const std::vector<XdmfSnapshot>& snapshots) {
  std::string out =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"snapshots\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfSnapshot& snapshot : snapshots) {
    out += fmt::format("      <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n",
                       xml_escaped(snapshot.group));
    out += fmt::format("        <Time Value=\"{}\"/>\n", snapshot.time);
    append_fluid_grid(out, h5_basename, grid, snapshot);
    if (snapshot.n_bodies > 0) append_bodies_grid(out, h5_basename, snapshot);
    out += "      </Grid>\n";
  }
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out;
}

void write_xdmf_sidecar(const std::string& xmf_path, const std::string& h5_basename, const Grid& grid,
                        const std::vector<XdmfSnapshot>& snapshots) {
  const std::string temporary = xmf_path + ".tmp";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw OutputError(fmt::format("{}: cannot create XDMF sidecar: {}", temporary, std::strerror(errno)));
    errno = 0;
    file << xdmf_text(h5_basename, grid, snapshots);
    file.close();
    if (!file) {
      const int reason = errno;
      std::remove(temporary.c_str());  // no stray temporary; the previous sidecar stays as it was
      throw OutputError(fmt::format("{}: cannot write XDMF sidecar: {}", temporary,
                                    reason != 0 ? std::strerror(reason) : "write failed"));
    }
  }
  if (std::rename(temporary.c_str(), xmf_path.c_str()) != 0) {
    const int reason = errno;
    std::remove(temporary.c_str());
    throw OutputError(fmt::format("{}: cannot replace XDMF sidecar: {}", xmf_path, std::strerror(reason)));
  }
}

}  // namespace ibms
