#include "xdmf_writer.hpp"

#include <fstream>

#include <fmt/format.h>

#include "io_error.hpp"

namespace inpact::io {

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
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

const char* attribute_type(std::size_t n_comp) {
  switch (n_comp) {
    case 1: return "Scalar";
    case 3: return "Vector";
    case 6: return "Tensor6";
    case 9: return "Tensor";
    default: return "Matrix";
  }
}

std::string data_item(const std::string& dims, const char* number_type, const XdmfMesh& mesh,
                      const std::string& path) {
  return fmt::format(R"(<DataItem Dimensions="{}" NumberType="{}" Precision="8" Format="HDF">{}:{}</DataItem>)",
                     dims, number_type, xml_escape(mesh.h5_file), xml_escape(path));
}

}  // namespace

std::string xdmf_text(const XdmfMesh& mesh, const std::vector<XdmfFrame>& frames) {
  // Topology and geometry are repeated in every frame grid (a few lines each) instead of
  // xi:include, which not every reader resolves.
  const bool mixed = mesh.topology_type == "Mixed";
  const std::string topology_dims = mixed ? std::to_string(mesh.topology_length)
                                          : fmt::format("{} {}", mesh.n_cells, mesh.nodes_per_cell);
  // XDMF's poly cells of one type need their size (a mixed topology gives it per cell).
  const bool poly = mesh.topology_type == "Polyline" || mesh.topology_type == "Polyvertex";
  const std::string size = poly ? fmt::format(" NodesPerElement=\"{}\"", mesh.nodes_per_cell) : "";
  const std::string topology = fmt::format(
      "        <Topology TopologyType=\"{}\" NumberOfElements=\"{}\"{}>\n          {}\n        </Topology>\n"
      "        <Geometry GeometryType=\"XYZ\">\n          {}\n        </Geometry>\n",
      mesh.topology_type, mesh.n_cells, size, data_item(topology_dims, "Int", mesh, mesh.topology_path),
      data_item(fmt::format("{} 3", mesh.n_nodes), "Float", mesh, mesh.coordinates_path));

  std::string out = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n";
  out += "    <Grid Name=\"frames\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfFrame& f : frames) {
    out += fmt::format("      <Grid Name=\"{}\" GridType=\"Uniform\">\n", xml_escape(f.name));
    out += fmt::format("        <Time Value=\"{:.17g}\"/>\n", f.time);
    out += topology;
    for (const XdmfAttribute& a : f.attributes) {
      const std::string dims = a.n_comp == 1 ? std::to_string(a.n_rows) : fmt::format("{} {}", a.n_rows, a.n_comp);
      out += fmt::format("        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">\n          {}\n"
                         "        </Attribute>\n",
                         xml_escape(a.name), attribute_type(a.n_comp), a.cell ? "Cell" : "Node",
                         data_item(dims, "Float", mesh, a.h5_path));
    }
    out += "      </Grid>\n";
  }
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out;
}

void write_xdmf(const std::filesystem::path& path, const XdmfMesh& mesh, const std::vector<XdmfFrame>& frames) {
  std::ofstream out(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out) throw IoError(path, "cannot create the XDMF sidecar");
  out << xdmf_text(mesh, frames);
  out.close();
  if (!out) throw IoError(path, "cannot write the XDMF sidecar");
}

}  // namespace inpact::io
