#pragma once
// Helpers shared by the contact geometry tests: hand-made facets and one-element models.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact/facet.hpp"
#include "model/element_types.hpp"
#include "model/model.hpp"

namespace inpact::test {

using contact::Facet;
using contact::FacetShape;
using contact::Vec3;

/// A facet of `shape` on node rows first, first+1, …
inline Facet make_facet(FacetShape shape, std::int32_t first = 0) {
  Facet f;
  f.shape = shape;
  f.n_nodes = static_cast<std::uint8_t>(contact::facet_n_nodes(shape));
  for (int a = 0; a < f.n_nodes; ++a) f.nodes[a] = first + a;
  return f;
}

/// Node coordinates of `shape` placed by map(ξ, η) at its nodes' parametric points.
template <class Map>
std::vector<Vec3> place(FacetShape shape, Map map) {
  std::vector<Vec3> x;
  for (int a = 0; a < contact::facet_n_nodes(shape); ++a) {
    const auto p = contact::facet_node_param(shape, a);
    x.push_back(map(p[0], p[1]));
  }
  return x;
}

/// A model of elements of one type on the given nodes (rows = labels − 1), with a surface
/// "S" made of `faces` (element row, face index 0 = S1).
inline model::Model elements_model(const char* type, const std::vector<Vec3>& coords,
                                   const std::vector<std::vector<std::int32_t>>& connectivity,
                                   const std::vector<model::Face>& faces) {
  model::Model m;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    m.mesh.nodes.labels.push_back(static_cast<std::int64_t>(i + 1));
    m.mesh.nodes.coords.push_back(coords[i]);
    m.mesh.nodes.instance.push_back(0);
  }
  const auto t = model::element_type_index(*model::find_element_type(type));
  for (std::size_t e = 0; e < connectivity.size(); ++e) {
    for (std::int32_t r : connectivity[e]) m.mesh.elements.conn.push_back(r);
    m.mesh.elements.type.push_back(t);
    m.mesh.elements.labels.push_back(static_cast<std::int64_t>(e + 1));
    m.mesh.elements.instance.push_back(0);
    m.mesh.elements.offsets.push_back(static_cast<std::int64_t>(m.mesh.elements.conn.size()));
    m.mesh.elements.loc.push_back({});
  }
  model::Surface s;
  s.name = "S";
  s.faces = faces;
  m.mesh.surfaces["S"] = s;
  return m;
}

inline double dist(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace inpact::test
