#include "mesh_queries.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "element_types.hpp"

namespace inpact::model {

int spatial_dimension(const Elements& elements) {
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (element_type(elements.type[e]).dim == 3) return 3;
  return 2;
}

std::size_t kind_element(const Elements& elements) {
  const auto takes_the_models = [](const ElementTypeInfo& t) { return t.family == ElementFamily::Spring || is_rigid(t); };
  std::size_t first = 0;
  while (first + 1 < elements.size() && takes_the_models(element_type(elements.type[first]))) ++first;
  return first;
}

int model_dimension(const Elements& elements) {
  if (elements.size() == 0) return 3;
  const int dim = element_type(elements.type[kind_element(elements)]).dim;
  return dim ? dim : 3;
}

std::vector<std::int32_t> face_nodes(const Elements& elements, Face face) {
  const ElementTypeInfo& info = element_type(elements.type[face.element]);
  const FaceDef& def = info.faces[face.face];
  auto nodes = elements.nodes_of(face.element);
  std::vector<std::int32_t> out(def.n_nodes);
  for (int i = 0; i < def.n_nodes; ++i) out[i] = nodes[def.nodes[i]];
  return out;
}

std::vector<std::int32_t> edge_nodes(const Elements& elements, Face edge) {
  const FaceDef& def = element_type(elements.type[edge.element]).edges[edge.face];
  auto nodes = elements.nodes_of(edge.element);
  std::vector<std::int32_t> out(def.n_nodes);
  for (int i = 0; i < def.n_nodes; ++i) out[i] = nodes[def.nodes[i]];
  return out;
}

namespace {

/// A face keyed by its sorted corner nodes (up to 4), so that the two elements sharing it agree.
struct FaceKey {
  std::array<std::int32_t, 4> n{-1, -1, -1, -1};
  bool operator==(const FaceKey&) const = default;
};

struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::size_t h = 1469598103934665603ull;
    for (auto v : k.n) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
    return h;
  }
};

FaceKey key_of(const Elements& elements, Face face) {
  const FaceDef& def = element_type(elements.type[face.element]).faces[face.face];
  auto nodes = elements.nodes_of(face.element);
  FaceKey k;
  for (int i = 0; i < def.n_corners; ++i) k.n[i] = nodes[def.nodes[i]];
  // Insertion sort of at most four corners (std::sort here trips a false -Warray-bounds in
  // GCC 12's sanitizer builds).
  for (int i = 1; i < def.n_corners; ++i)
    for (int j = i; j > 0 && k.n[j] < k.n[j - 1]; --j) std::swap(k.n[j], k.n[j - 1]);
  return k;
}

}  // namespace

std::vector<Face> exterior_faces(const Elements& elements, std::span<const std::int32_t> subset) {
  // Count how often each face occurs over the whole mesh; a face seen once is exterior.
  std::unordered_map<FaceKey, int, FaceKeyHash> count;
  count.reserve(elements.size() * 4);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& info = element_type(elements.type[e]);
    for (std::size_t f = 0; f < info.faces.size(); ++f)
      ++count[key_of(elements, {static_cast<std::int32_t>(e), static_cast<std::uint8_t>(f)})];
  }
  std::vector<Face> out;
  for (std::int32_t e : subset) {
    const auto& info = element_type(elements.type[e]);
    for (std::size_t f = 0; f < info.faces.size(); ++f) {
      Face face{e, static_cast<std::uint8_t>(f)};
      if (count[key_of(elements, face)] == 1) out.push_back(face);
    }
  }
  return out;
}

double shell_thickness(const Mesh& mesh, const ShellSection& section, std::size_t element) {
  if (!section.nodal_thickness) return section.thickness;
  const auto nodes = mesh.elements.nodes_of(element);
  double sum = 0.0;
  for (std::int32_t n : nodes) sum += mesh.nodal_thickness.at(n);
  return sum / static_cast<double>(nodes.size());
}

}  // namespace inpact::model
