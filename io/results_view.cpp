#include "results_view.hpp"

#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

namespace inpact::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct CellTypes {
  std::uint8_t vtk;
  std::int32_t xdmf;
  const char* xdmf_name;
};

CellTypes cell_types(const model::ElementTypeInfo& t) {
  // VTK_TRIANGLE 5, VTK_QUAD 9, VTK_TETRA 10, VTK_HEXAHEDRON 12, VTK_WEDGE 13,
  // VTK_QUADRATIC_TRIANGLE 22, VTK_QUADRATIC_QUAD 23, VTK_QUADRATIC_TETRA 24,
  // VTK_QUADRATIC_HEXAHEDRON 25; XDMF numbers from XdmfTopologyType.cpp. Trusses and springs:
  // VTK_VERTEX 1 / VTK_LINE 3 / VTK_QUADRATIC_EDGE 21 (XDMF Polyvertex 1, Polyline 2, Edge_3 34).
  if (model::is_rigid(t) || model::is_shell(t)) {  // R2D2, RAX2: a line; R3D3, R3D4, S3, S4: a triangle, a quad
    switch (t.n_nodes) {
      case 2: return {3, 2, "Polyline"};
      case 3: return {5, 4, "Triangle"};
      case 4: return {9, 5, "Quadrilateral"};
      case 6: return {22, 36, "Triangle_6"};       // S6: corners then midsides, as VTK's
      case 8: return {23, 37, "Quadrilateral_8"};  // S8R, S8: corners then midsides, as VTK's
    }
    return {0, 0, ""};
  }
  if (!model::is_continuum(t)) {
    switch (t.n_nodes) {
      case 1: return {1, 1, "Polyvertex"};
      case 2: return {3, 2, "Polyline"};
      case 3: return {21, 34, "Edge_3"};
    }
    return {0, 0, ""};
  }
  if (t.dim == 3) {
    switch (t.n_nodes) {
      case 4: return {10, 6, "Tetrahedron"};
      case 6: return {13, 8, "Wedge"};
      case 8: return {12, 9, "Hexahedron"};
      case 10: return {24, 38, "Tetrahedron_10"};
      case 20: return {25, 48, "Hexahedron_20"};
    }
  } else {
    switch (t.n_nodes) {
      case 3: return {5, 4, "Triangle"};
      case 4: return {9, 5, "Quadrilateral"};
      case 6: return {22, 36, "Triangle_6"};
      case 8: return {23, 37, "Quadrilateral_8"};
    }
  }
  return {0, 0, ""};
}

// Abaqus tensor component suffix → VTK symmetric tensor slot (XX YY ZZ XY YZ XZ).
int vtk_tensor_slot(const std::string& label, const std::string& key) {
  if (label.size() != key.size() + 2 || label.compare(0, key.size(), key) != 0) return -1;
  const std::string ij = label.substr(key.size());
  if (ij == "11") return 0;
  if (ij == "22") return 1;
  if (ij == "33") return 2;
  if (ij == "12" || ij == "21") return 3;
  if (ij == "23" || ij == "32") return 4;
  if (ij == "13" || ij == "31") return 5;
  return -1;
}

ViewArray nodal_array(const model::Model& model, const FieldData& f, std::size_t n_comp) {
  const std::size_t n_nodes = model.mesh.nodes.size();
  const std::size_t nloc = f.values.size() / n_comp;
  // 2-component nodal vectors (plane models) are padded to 3 so they read as vectors.
  const std::size_t out_comp = n_comp == 2 ? 3 : n_comp;
  ViewArray a{f.key, false, out_comp, std::vector<double>(n_nodes * out_comp, kNaN)};
  for (std::size_t i = 0; i < nloc; ++i) {
    const std::size_t row = f.nodes.empty() ? i : static_cast<std::size_t>(f.nodes[i]);
    double* dst = &a.values[row * out_comp];
    const double* src = &f.values[i * n_comp];
    // A node in several contact pairs keeps the value of largest magnitude.
    if (!f.pair.empty() && !std::isnan(dst[0]) && std::abs(dst[0]) >= std::abs(src[0])) continue;
    for (std::size_t c = 0; c < n_comp; ++c) dst[c] = src[c];
    for (std::size_t c = n_comp; c < out_comp; ++c) dst[c] = 0.0;
  }
  return a;
}

/// Per cell, the sum and count of a field's values at its locations.
struct CellSums {
  std::size_t n_comp;
  std::vector<double> sum;
  std::vector<std::int32_t> count;
  CellSums(std::size_t n_cells, std::size_t comp) : n_comp(comp), sum(n_cells * comp, 0.0), count(n_cells, 0) {}
  /// `slot`: where each of the n values goes (tensor components in VTK's order); null: in order.
  void add(std::size_t cell, const double* values, std::size_t n, const int* slot) {
    ++count[cell];
    for (std::size_t c = 0; c < n; ++c) sum[cell * n_comp + (slot ? static_cast<std::size_t>(slot[c]) : c)] += values[c];
  }
};

/// The cells' means as the array `name` (NaN where a cell has no location); for a stress tensor
/// also `name`_Mises, the von Mises stress of the mean.
void push_cell_array(const std::string& name, const CellSums& s, bool tensor, std::vector<ViewArray>& out) {
  const std::size_t n_cells = s.count.size();
  ViewArray a{name, true, s.n_comp, std::vector<double>(n_cells * s.n_comp, kNaN)};
  for (std::size_t e = 0; e < n_cells; ++e)
    if (s.count[e])
      for (std::size_t c = 0; c < s.n_comp; ++c) a.values[e * s.n_comp + c] = s.sum[e * s.n_comp + c] / s.count[e];
  const bool stress = tensor && (name == "S" || name.rfind("S_SP", 0) == 0);
  if (!stress) {
    out.push_back(std::move(a));
    return;
  }
  ViewArray mises{name + "_Mises", true, 1, std::vector<double>(n_cells, kNaN)};
  for (std::size_t e = 0; e < n_cells; ++e) {
    if (!s.count[e]) continue;
    const double* v = &a.values[e * 6];
    const double d = (v[0] - v[1]) * (v[0] - v[1]) + (v[1] - v[2]) * (v[1] - v[2]) + (v[2] - v[0]) * (v[2] - v[0]);
    mises.values[e] = std::sqrt(0.5 * d + 3.0 * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5]));
  }
  out.push_back(std::move(a));
  out.push_back(std::move(mises));
}

void element_arrays(const model::Model& model, const FieldData& f, std::size_t n_comp,
                    const std::filesystem::path& path, std::vector<ViewArray>& out) {
  const auto& elements = model.mesh.elements;
  const std::size_t n_cells = elements.size();
  const std::size_t nloc = f.values.size() / n_comp;

  // Tensor fields (S11 S22 ... / E11 ...) become 6-component VTK symmetric tensors.
  std::vector<int> slot(n_comp, -1);
  bool tensor = n_comp >= 3;
  for (std::size_t c = 0; c < n_comp && tensor; ++c) {
    slot[c] = vtk_tensor_slot(f.component_labels[c], f.key);
    tensor = slot[c] >= 0;
  }
  const std::size_t out_comp = tensor ? 6 : n_comp;
  // The cell's mean over its locations; a shell's section points apart, one array each
  // (<key>_SP<k>, k from SNEG = 1 up), as a shell's S varies through its thickness.
  CellSums whole(n_cells, out_comp);
  std::map<std::int32_t, CellSums> by_section_point;
  std::size_t row_of_point = 0;
  for (std::size_t i = 0; i < nloc; ++i) {
    const std::int32_t inst = f.instance.empty() ? 0 : f.instance[i];
    // The points of one element follow each other: look its row up once. A whole-model field
    // lists the elements in row order: try the next row before the label table.
    const bool same = i > 0 && f.elements[i] == f.elements[i - 1] && (f.instance.empty() || inst == f.instance[i - 1]);
    if (!same) {
      const std::size_t next = i > 0 ? row_of_point + 1 : 0;
      const bool in_order = next < n_cells && elements.labels[next] == f.elements[i] &&
                            (elements.instance.empty() ? 0 : elements.instance[next]) == inst;
      if (in_order) {
        row_of_point = next;
      } else {
        const auto row = elements.index.find(inst, f.elements[i]);
        if (!row)
          throw IoError(path, fmt::format("field {}: element {} (instance {}) is not in the model", f.key,
                                          f.elements[i], inst));
        row_of_point = static_cast<std::size_t>(*row);
      }
    }
    const std::size_t e = row_of_point;
    CellSums* target = &whole;
    if (!f.section_point.empty() && f.section_point[i] > 0) {
      // A beam's S varies across its section, and its average would hide the bending: its cell
      // is left empty (SF and SM show the section's state).
      if (!model::is_shell(model::element_type(elements.type[e]))) continue;
      target = &by_section_point.try_emplace(f.section_point[i], n_cells, out_comp).first->second;
    }
    target->add(e, &f.values[i * n_comp], n_comp, tensor ? slot.data() : nullptr);
  }
  push_cell_array(f.key, whole, tensor, out);
  for (const auto& [number, sums] : by_section_point)
    push_cell_array(fmt::format("{}_SP{}", f.key, number), sums, tensor, out);
}

// VTK's wedge has its base (0,1,2) turning away from the top face (3,4,5) by the right-hand
// rule; Abaqus's C3D6 face S1 (1,2,3) turns into the element. Swapping the second and third node
// of both triangles maps one onto the other (VTK's vtkCellValidator pins this in tests/io).
constexpr std::uint8_t kWedgeToVtk[] = {0, 2, 1, 3, 5, 4};
// T3D3 is end, middle, end; VTK's quadratic edge (and XDMF's Edge_3) end, end, middle.
constexpr std::uint8_t kEdge3ToVtk[] = {0, 2, 1};

}  // namespace

std::span<const std::uint8_t> vtk_node_order(const model::ElementTypeInfo& type) {
  if (model::is_rigid(type) || model::is_shell(type)) return {};
  if (!model::is_continuum(type)) return type.n_nodes == 3 ? std::span<const std::uint8_t>(kEdge3ToVtk)
                                                          : std::span<const std::uint8_t>();
  if (type.dim == 3 && type.n_nodes == 6) return kWedgeToVtk;
  return {};
}

std::uint8_t vtk_cell_type(const model::ElementTypeInfo& type) { return cell_types(type).vtk; }
std::int32_t xdmf_cell_type(const model::ElementTypeInfo& type) { return cell_types(type).xdmf; }
const char* xdmf_topology_name(const model::ElementTypeInfo& type) { return cell_types(type).xdmf_name; }

ViewTopology build_view_topology(const model::Mesh& mesh) {
  const auto& el = mesh.elements;
  ViewTopology t;
  t.vtk_types.reserve(el.size());
  t.vtk_offsets.reserve(el.size() + 1);
  t.vtk_offsets.push_back(0);
  t.vtk_connectivity.reserve(el.conn.size());
  t.xdmf_mixed.reserve(el.conn.size() + el.size());
  for (std::size_t e = 0; e < el.size(); ++e) {
    const auto& type = model::element_type(el.type[e]);
    const CellTypes ct = cell_types(type);
    t.vtk_types.push_back(ct.vtk);
    t.xdmf_mixed.push_back(ct.xdmf);
    if (ct.xdmf == 1 || ct.xdmf == 2) t.xdmf_mixed.push_back(type.n_nodes);  // XDMF's poly cells give their size
    // Abaqus node order is VTK's (and XDMF's) for every supported type but the wedge and T3D3.
    const auto nodes = el.nodes_of(e);
    const auto order = vtk_node_order(type);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const std::int32_t n = nodes[order.empty() ? i : order[i]];
      t.vtk_connectivity.push_back(n);
      t.xdmf_mixed.push_back(n);
    }
    t.vtk_offsets.push_back(static_cast<std::int64_t>(t.vtk_connectivity.size()));
  }
  return t;
}

std::vector<ViewArray> build_view_arrays(const model::Model& model, const Frame& frame,
                                         const std::filesystem::path& path) {
  std::vector<ViewArray> out;
  for (const FieldData& f : frame.fields) {
    const std::size_t n_comp = f.component_labels.size();
    if (n_comp == 0) continue;
    if (f.position == Position::Nodal)
      out.push_back(nodal_array(model, f, n_comp));
    else
      element_arrays(model, f, n_comp, path, out);
  }
  return out;
}

}  // namespace inpact::io
