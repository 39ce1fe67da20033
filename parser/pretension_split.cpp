#include "pretension_split.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "model/beam_section_area.hpp"
#include "model/element_types.hpp"
#include "model/mesh_queries.hpp"
#include "rotation_nodes.hpp"

namespace inpact::parser {

namespace {

using Vec = std::array<double, 3>;
constexpr const char* kKeyword = "*PRE-TENSION SECTION";

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The outward area vector of a face from its corners: a solid's face corners turn into the
/// element (model/element_types.hpp), so the polygon's right-hand area vector is negated; a 2D
/// element's edge has the outward normal of its direction turned clockwise (per unit thickness).
Vec face_area_vector(const model::Mesh& mesh, model::Face face) {
  const auto& info = model::element_type(mesh.elements.type[face.element]);
  const auto nodes = model::face_nodes(mesh.elements, face);
  const int n_corners = info.faces[face.face].n_corners;
  const auto& x = mesh.nodes.coords;
  if (info.dim == 2) {
    const Vec t = sub(x[nodes[1]], x[nodes[0]]);
    return {t[1], -t[0], 0.0};
  }
  Vec a{0, 0, 0};
  for (int i = 0; i < n_corners; ++i) {
    const Vec c = cross(x[nodes[i]], x[nodes[(i + 1) % n_corners]]);
    for (int k = 0; k < 3; ++k) a[k] -= 0.5 * c[k];
  }
  return a;
}

/// A shell's thickness at element e: its section's (1 when no section holds it or a node lacks its
/// *NODAL THICKNESS, which the section checks report).
double shell_thickness_of(const model::Mesh& mesh, std::int32_t e) {
  for (const model::ShellSection& sec : mesh.shell_sections) {
    const auto set = mesh.elsets.find(sec.elset);
    if (set == mesh.elsets.end() || !std::binary_search(set->second.rows.begin(), set->second.rows.end(), e)) continue;
    const auto nodes = mesh.elements.nodes_of(static_cast<std::size_t>(e));
    const bool nodal_given = std::all_of(nodes.begin(), nodes.end(), [&](std::int32_t n) {
      return mesh.nodal_thickness.count(n) > 0;
    });
    return !sec.nodal_thickness || nodal_given ? model::shell_thickness(mesh, sec, static_cast<std::size_t>(e)) : 1.0;
  }
  return 1.0;
}

/// The outward area vector of a shell edge: in the shell's plane, out of the element (the edge's
/// chord × the shell normal), its size the chord's length times the thickness.
Vec edge_area_vector(const model::Mesh& mesh, model::Face edge) {
  const auto& x = mesh.nodes.coords;
  const auto nodes = model::edge_nodes(mesh.elements, edge);
  const auto corners = mesh.elements.nodes_of(static_cast<std::size_t>(edge.element));
  const std::size_t n_corners = model::element_type(mesh.elements.type[edge.element]).edges.size();
  const Vec normal = n_corners == 3 ? cross(sub(x[corners[1]], x[corners[0]]), sub(x[corners[2]], x[corners[0]]))
                                    : cross(sub(x[corners[2]], x[corners[0]]), sub(x[corners[3]], x[corners[1]]));
  const Vec chord = sub(x[nodes[1]], x[nodes[0]]);
  const Vec out = cross(chord, normal);
  const double scale = std::sqrt(dot(chord, chord)) * shell_thickness_of(mesh, edge.element) / std::sqrt(dot(out, out));
  return {out[0] * scale, out[1] * scale, out[2] * scale};
}

/// The outward area vectors of a section's pieces: the surface's faces, or its shell edges.
std::vector<Vec> area_vectors(const model::Mesh& mesh, const model::Surface& surface) {
  std::vector<Vec> out;
  for (const model::Face& f : surface.faces) out.push_back(face_area_vector(mesh, f));
  for (const model::Face& e : surface.edges) out.push_back(edge_area_vector(mesh, e));
  return out;
}

/// The nodes of a section's faces or shell edges.
std::set<std::int32_t> section_nodes_of(const model::Mesh& mesh, const model::Surface& surface) {
  std::set<std::int32_t> out;
  for (const model::Face& f : surface.faces)
    for (std::int32_t n : model::face_nodes(mesh.elements, f)) out.insert(n);
  for (const model::Face& e : surface.edges)
    for (std::int32_t n : model::edge_nodes(mesh.elements, e)) out.insert(n);
  return out;
}

/// The elements a section's pieces belong to.
std::set<std::int32_t> section_elements_of(const model::Surface& surface) {
  std::set<std::int32_t> out;
  for (const auto* pieces : {&surface.faces, &surface.edges})
    for (const model::Face& f : *pieces) out.insert(f.element);
  return out;
}

/// The surface and node checks; false (with the error reported) when the section cannot be cut.
bool check_section(const model::Model& m, Diagnostics& diags, const model::PretensionSection& s,
                   const std::vector<std::uint8_t>& connected) {
  auto it = m.mesh.surfaces.find(s.surface);
  if (it == m.mesh.surfaces.end()) {
    std::vector<std::string> names;
    for (const auto& [name, surface] : m.mesh.surfaces) names.push_back(name);
    const std::string guess = did_you_mean(s.surface, names);
    diags.error(s.surface_loc, kKeyword, fmt::format("surface '{}' is not defined{}", s.surface,
                                                     guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
    return false;
  }
  if (it->second.kind != model::Surface::Kind::Element || (it->second.faces.empty() && it->second.edges.empty())) {
    diags.error(s.surface_loc, kKeyword, fmt::format("surface '{}' is not element based (the section must be made of "
                                                     "element faces or shell edges, *SURFACE, TYPE=ELEMENT)", s.surface));
    return false;
  }
  if (connected[s.node]) {
    diags.error(s.node_loc, kKeyword, fmt::format("the pre-tension node {} belongs to elements; it must be a node no "
                                                  "element uses (define a separate *NODE)",
                                                  m.mesh.nodes.labels[s.node]));
    return false;
  }
  return true;
}

/// The unit normal (given, or the average of the faces' outward normals weighted by their
/// areas) and the section's area normal to it; false when the normal is zero.
bool resolve_normal(const model::Model& m, Diagnostics& diags, model::PretensionSection& s) {
  Vec sum{0, 0, 0};
  double total = 0.0;
  for (const Vec& a : area_vectors(m.mesh, m.mesh.surfaces.at(s.surface))) {
    for (int k = 0; k < 3; ++k) sum[k] += a[k];
    total += std::sqrt(dot(a, a));
  }
  const Vec n = s.given_normal ? *s.given_normal : sum;
  const double length = std::sqrt(dot(n, n));
  if (!(length > 1e-12 * (s.given_normal ? 1.0 : total))) {
    diags.error(s.given_normal ? s.normal_loc : s.loc, kKeyword,
                s.given_normal ? "the normal is zero"
                               : fmt::format("the average normal of surface '{}' is zero (its faces face opposite "
                                             "ways); give the normal on the data line", s.surface));
    return false;
  }
  for (int k = 0; k < 3; ++k) s.normal[k] = n[k] / length;
  s.area = std::abs(dot(sum, s.normal));
  return true;
}

/// The direction out of the underlying elements, which tells the sides apart: the faces' own
/// average (a given normal may point either way), or the given one when the faces cancel out.
Vec outward_direction(const model::Model& m, const model::PretensionSection& s) {
  Vec sum{0, 0, 0};
  double total = 0.0;
  for (const Vec& a : area_vectors(m.mesh, m.mesh.surfaces.at(s.surface))) {
    for (int k = 0; k < 3; ++k) sum[k] += a[k];
    total += std::sqrt(dot(a, a));
  }
  return std::sqrt(dot(sum, sum)) > 1e-12 * total ? sum : s.normal;
}

/// The elements that take the copies: the surface's own and those behind the section.
std::vector<std::int32_t> underlying_elements(const model::Model& m, const model::PretensionSection& s,
                                              const std::set<std::int32_t>& section_nodes) {
  const auto& elements = m.mesh.elements;
  const auto& x = m.mesh.nodes.coords;
  const Vec outward = outward_direction(m, s);
  std::set<std::int32_t> out = section_elements_of(m.mesh.surfaces.at(s.surface));
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto nodes = elements.nodes_of(e);
    Vec centroid{0, 0, 0}, on_section{0, 0, 0};
    int n_on = 0;
    for (std::int32_t n : nodes) {
      for (int k = 0; k < 3; ++k) centroid[k] += x[n][k] / static_cast<double>(nodes.size());
      if (section_nodes.count(n)) {
        ++n_on;
        for (int k = 0; k < 3; ++k) on_section[k] += x[n][k];
      }
    }
    if (n_on == 0) continue;
    for (double& v : on_section) v /= n_on;
    if (dot(sub(centroid, on_section), outward) < 0) out.insert(static_cast<std::int32_t>(e));
  }
  return {out.begin(), out.end()};
}

/// Cuts the mesh (when `cut`): a copy of each section node replaces it in the underlying elements.
/// False (the error reported, the mesh unchanged) when a section node has no element on the other side.
bool split_section(model::Model& m, Diagnostics& diags, model::PretensionSection& s, bool cut) {
  model::Mesh& mesh = m.mesh;
  const std::set<std::int32_t> section_nodes = section_nodes_of(mesh, mesh.surfaces.at(s.surface));
  const std::vector<std::int32_t> rewired = underlying_elements(m, s, section_nodes);
  std::set<std::int32_t> other_side;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (!std::binary_search(rewired.begin(), rewired.end(), static_cast<std::int32_t>(e)))
      for (std::int32_t n : mesh.elements.nodes_of(e))
        if (section_nodes.count(n)) other_side.insert(n);
  for (std::int32_t n : section_nodes)
    if (!other_side.count(n)) {
      diags.error(s.surface_loc, kKeyword, fmt::format("node {} of surface '{}' has no element on the other side of the "
                                                       "section (a pre-tension section must cut through the fastener)",
                                                       mesh.nodes.labels[n], s.surface));
      return false;
    }
  if (!cut) return true;
  std::map<std::int32_t, std::int64_t> largest_label;  // per instance
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    auto [it, fresh] = largest_label.try_emplace(mesh.nodes.instance[n], mesh.nodes.labels[n]);
    if (!fresh) it->second = std::max(it->second, mesh.nodes.labels[n]);
  }
  std::map<std::int32_t, std::int32_t> copy_of;
  for (std::int32_t n : section_nodes) {
    const auto row = static_cast<std::int32_t>(mesh.nodes.size());
    const std::int32_t inst = mesh.nodes.instance[n];
    const std::int64_t label = ++largest_label[inst];
    mesh.nodes.labels.push_back(label);
    mesh.nodes.coords.push_back(mesh.nodes.coords[n]);
    mesh.nodes.instance.push_back(inst);
    mesh.nodes.index.insert(inst, label, row);
    copy_of[n] = row;
    s.node_pairs.push_back({n, row});
    // A shell's copy carries what the deck gave its original: *NODAL THICKNESS and a normal.
    if (auto t = mesh.nodal_thickness.find(n); t != mesh.nodal_thickness.end()) mesh.nodal_thickness[row] = t->second;
    if (auto g = mesh.node_normals.find(n); g != mesh.node_normals.end()) mesh.node_normals[row] = g->second;
  }
  for (std::int32_t e : rewired)
    for (std::int64_t k = mesh.elements.offsets[e]; k < mesh.elements.offsets[e + 1]; ++k)
      if (auto it = copy_of.find(mesh.elements.conn[k]); it != copy_of.end()) mesh.elements.conn[k] = it->second;
  s.n_rewired_elements = rewired.size();
  return true;
}

/// A truss or beam section's normal: element e's axis from its first node to its second (unit).
Vec truss_axis(const model::Mesh& mesh, std::int32_t e) {
  const auto nodes = mesh.elements.nodes_of(static_cast<std::size_t>(e));
  const Vec axis = sub(mesh.nodes.coords[nodes[1]], mesh.nodes.coords[nodes[0]]);
  const double length = std::sqrt(dot(axis, axis));
  return {axis[0] / length, axis[1] / length, axis[2] / length};
}

/// ELEMENT= (a two-node truss or beam, checked): the element is cut at its second node, whose copy it alone uses; the
/// normal is its axis from its first node to its second (the bolt's tension positive). A beam's copy shares the
/// original's rotations (beam_nodes.cpp): the cut opens along the axis only.
void split_truss_section(model::Model& m, model::PretensionSection& s, bool cut) {
  model::Mesh& mesh = m.mesh;
  const auto e = static_cast<std::size_t>(s.element);
  const auto nodes = mesh.elements.nodes_of(e);
  s.normal = truss_axis(mesh, s.element);
  for (const model::SolidSection& sec : mesh.sections)
    if (std::binary_search(mesh.elsets.at(sec.elset).rows.begin(), mesh.elsets.at(sec.elset).rows.end(), s.element))
      s.area = sec.thickness;  // a truss section's area
  for (const model::BeamSection& sec : mesh.beam_sections)
    if (std::binary_search(mesh.elsets.at(sec.elset).rows.begin(), mesh.elsets.at(sec.elset).rows.end(), s.element))
      s.area = model::section_area(sec);
  if (!cut) return;
  const std::int32_t b = nodes[1];
  const std::int32_t row = add_node_beside(mesh, b);
  mesh.elements.conn[static_cast<std::size_t>(mesh.elements.offsets[e] + 1)] = row;
  s.node_pairs.push_back({b, row});
  s.n_rewired_elements = 1;
}

/// ELEMENT= with a data line: the normal given must be the element's axis from its first node
/// to its second (which it is in any case): its cosine with it at least 1 − 1e-6 (within about
/// 1.4e-3 rad).
bool normal_is_the_axis(const model::Model& m, Diagnostics& diags, const model::PretensionSection& s) {
  if (!s.given_normal) return true;
  const Vec axis = truss_axis(m.mesh, s.element);
  const Vec& n = *s.given_normal;
  const double cosine = dot(axis, n) / std::sqrt(dot(n, n));
  if (cosine >= 1.0 - 1e-6) return true;
  diags.error(s.normal_loc, kKeyword,
              fmt::format("the normal ({:g}, {:g}, {:g}) is not the axis of element {} from its first node to its second "
                          "({:g}, {:g}, {:g}), which is a truss or beam section's normal (or give no data line)",
                          n[0], n[1], n[2], m.mesh.elements.labels[static_cast<std::size_t>(s.element)], axis[0], axis[1],
                          axis[2]));
  return false;
}

}  // namespace

void split_pretension_sections(model::Model& m, Diagnostics& diags) {
  if (m.pretension_sections.empty()) return;
  std::vector<std::uint8_t> connected(m.mesh.nodes.size(), 0);
  for (std::int32_t n : m.mesh.elements.conn) connected[n] = 1;
  std::set<std::int32_t> pretension_nodes;
  for (model::PretensionSection& s : m.pretension_sections) {
    if (s.element >= 0) {
      const auto& type = model::element_type(m.mesh.elements.type[static_cast<std::size_t>(s.element)]);
      const bool line = type.family == model::ElementFamily::Truss || model::is_beam(type);
      if (!line || type.n_nodes != 2) {
        diags.error(s.surface_loc, kKeyword,
                    fmt::format("element {} is a {}; ELEMENT= takes a two-node truss or beam (T2D2, T3D2, B31), a "
                                "solid fastener is cut with SURFACE=",
                                m.mesh.elements.labels[static_cast<std::size_t>(s.element)], type.name));
        continue;
      }
      if (!pretension_nodes.insert(s.node).second || connected[s.node]) {
        diags.error(s.node_loc, kKeyword, fmt::format("the pre-tension node {} must be a node of its own (no element, no "
                                                      "other section)", m.mesh.nodes.labels[s.node]));
        continue;
      }
      if (!normal_is_the_axis(m, diags, s)) continue;
      split_truss_section(m, s, !diags.has_errors());
      continue;
    }
    if (!check_section(m, diags, s, connected)) continue;
    if (!pretension_nodes.insert(s.node).second) {
      diags.error(s.node_loc, kKeyword, fmt::format("the pre-tension node {} serves another section already; each "
                                                    "section needs its own node", m.mesh.nodes.labels[s.node]));
      continue;
    }
    // With errors elsewhere the section is checked but the mesh left as read.
    if (resolve_normal(m, diags, s)) split_section(m, diags, s, !diags.has_errors());
  }
}

}  // namespace inpact::parser
