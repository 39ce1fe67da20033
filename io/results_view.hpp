#pragma once
/// The visualisation view of the results (internal to io/): VTK cells and XDMF mixed topology
/// for the mesh, and per frame the arrays ParaView and friends colour by — nodal fields
/// scattered to every node, element fields averaged per element into cell values, S and E as
/// VTK-ordered symmetric tensors, and S_Mises.
#include <cstdint>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "results_writer.hpp"

namespace inpact::io {

struct ViewTopology {
  std::vector<std::uint8_t> vtk_types;      ///< per element row
  std::vector<std::int64_t> vtk_offsets;    ///< n_cells + 1
  std::vector<std::int64_t> vtk_connectivity;
  std::vector<std::int64_t> xdmf_mixed;     ///< per cell: XDMF type number, then its nodes
};

ViewTopology build_view_topology(const model::Mesh& mesh);

struct ViewArray {
  std::string name;
  bool cell = false;  ///< cell data (per element row), else point data (per node row)
  std::size_t n_comp = 1;
  std::vector<double> values;  ///< n_rows × n_comp; NaN where the field has no value
};

/// The view arrays of one frame. Throws IoError (naming `path`) when an element label of a
/// field does not exist in the model.
std::vector<ViewArray> build_view_arrays(const model::Model& model, const Frame& frame,
                                         const std::filesystem::path& path);

}  // namespace inpact::io
