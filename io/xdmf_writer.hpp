#pragma once
/// The JOB.xdmf sidecar: an XDMF 3 file whose DataItems point into JOB.h5, with one mixed-
/// topology grid per frame in a temporal collection. ParaView 5.11 (XDMF3 reader), VisIt and
/// meshio's TimeSeriesReader read every frame from it. meshio reads whole datasets only (no
/// HyperSlab), so every DataItem names a complete dataset.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace inpact::io {

struct XdmfAttribute {
  std::string name;
  bool cell = false;  ///< Center="Cell", else "Node"
  std::size_t n_rows = 0;
  std::size_t n_comp = 1;
  std::string h5_path;  ///< dataset path inside the HDF5 file
};

struct XdmfFrame {
  std::string name;
  double time = 0.0;
  std::vector<XdmfAttribute> attributes;
};

struct XdmfMesh {
  std::string h5_file;  ///< file name relative to the .xdmf (both live side by side)
  std::size_t n_nodes = 0;
  std::size_t n_cells = 0;
  std::string coordinates_path;  ///< (n_nodes, 3) float64
  /// "Mixed": topology_path is the mixed array (per cell its XDMF type number, then its nodes)
  /// of topology_length entries; else one cell type ("Hexahedron_20", ...) and topology_path
  /// is an (n_cells, nodes_per_cell) array. meshio reads Mixed only for linear cells.
  std::string topology_type = "Mixed";
  std::size_t topology_length = 0;
  std::size_t nodes_per_cell = 0;
  std::string topology_path;  ///< int64
};

/// The XML text of the sidecar.
std::string xdmf_text(const XdmfMesh& mesh, const std::vector<XdmfFrame>& frames);
/// Writes xdmf_text() to `path`; throws IoError when it cannot.
void write_xdmf(const std::filesystem::path& path, const XdmfMesh& mesh, const std::vector<XdmfFrame>& frames);

}  // namespace inpact::io
