#include "couplings.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "model/mesh_queries.hpp"
#include "rotation_nodes.hpp"

namespace inpact::parser {

namespace {

constexpr const char* kKeyword = "*COUPLING";

/// The surface's nodes within the influence radius of the reference node, without it.
std::vector<std::int32_t> coupling_nodes(const model::Model& m, const model::Coupling& c) {
  const model::Surface& s = m.mesh.surfaces.at(c.surface);
  std::vector<std::int32_t> nodes = s.nodes;
  for (const model::Face& f : s.faces)
    for (std::int32_t n : model::face_nodes(m.mesh.elements, f)) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto& x = m.mesh.nodes.coords;
  const auto& xr = x[static_cast<std::size_t>(c.ref_node)];
  std::erase_if(nodes, [&](std::int32_t n) {
    if (n == c.ref_node) return true;
    if (c.influence_radius <= 0) return false;
    const auto& xn = x[static_cast<std::size_t>(n)];
    return std::hypot(xn[0] - xr[0], xn[1] - xr[1], xn[2] - xr[2]) > c.influence_radius;
  });
  return nodes;
}

/// *DISTRIBUTING COUPLING's lines, on the complete deck: each a node label or a node set of the
/// model (instance nodes, Part-1-1.12, are not read here yet), every node once, with the line's
/// weight; some weight must be positive. False after an error of its own.
bool resolve_weighted_lines(const model::Model& m, model::Coupling& c, Diagnostics& diags) {
  const char* keyword = c.keyword();
  std::vector<std::uint8_t> seen(m.mesh.nodes.size(), 0);
  bool ok = true;
  for (const model::Coupling::WeightedLine& line : c.weighted_lines) {
    std::vector<std::int32_t> rows;
    std::int64_t label = 0;
    const auto [end, ec] = std::from_chars(line.target.data(), line.target.data() + line.target.size(), label);
    if (ec == std::errc() && end == line.target.data() + line.target.size()) {
      if (const auto row = m.mesh.nodes.index.find(0, label)) {
        rows.push_back(*row);
      } else {
        diags.error(line.loc, keyword, fmt::format("node {} is not defined", label));
        ok = false;
      }
    } else if (const auto it = m.mesh.nsets.find(line.target); it != m.mesh.nsets.end()) {
      rows = it->second.rows;
    } else {
      diags.error(line.loc, keyword, fmt::format("node set '{}' is not defined", line.target));
      ok = false;
    }
    for (std::int32_t row : rows) {
      if (seen[static_cast<std::size_t>(row)]++) {
        diags.error(line.loc, keyword, fmt::format("node {} is listed twice; expected each node once",
                                                   m.mesh.nodes.labels[static_cast<std::size_t>(row)]));
        return false;
      }
      c.nodes.push_back(row);
      c.given_weights.push_back(line.weight);
    }
  }
  if (ok && !c.nodes.empty() && std::all_of(c.given_weights.begin(), c.given_weights.end(), [](double w) { return w == 0; })) {
    diags.error(c.weighted_lines.front().loc, keyword, "every weight is zero; expected at least one positive weight");
    ok = false;
  }
  return ok;
}

/// A reference node serves one constraint: a second coupling or a rigid body on it would give
/// its DOFs two rules.
void check_reference_nodes_distinct(const model::Model& m, Diagnostics& diags) {
  std::set<std::int32_t> taken;
  for (const model::RigidBody& b : m.rigid_bodies) {
    taken.insert(b.ref_node);
    taken.insert(b.nodes.begin(), b.nodes.end());
  }
  for (const model::Coupling& c : m.couplings)
    if (c.ref_node >= 0 && !taken.insert(c.ref_node).second)
      diags.error(c.ref_loc, c.keyword(), fmt::format("coupling '{}': the reference node {} is already a rigid body's node or "
                                                   "another coupling's reference node; give each constraint its own",
                                                   c.name, m.mesh.nodes.labels[static_cast<std::size_t>(c.ref_node)]));
}

}  // namespace

void finalize_couplings(model::Model& m, Diagnostics& diags) {
  if (m.couplings.empty()) return;
  const std::vector<std::uint8_t> on_continuum = continuum_nodes(m);
  for (model::Coupling& c : m.couplings) {
    if (c.kind == model::Coupling::Kind::Unset) {
      diags.error(c.loc, kKeyword, fmt::format("coupling '{}' is followed by neither *KINEMATIC nor *DISTRIBUTING", c.name));
      continue;
    }
    // An unknown reference node or surface is reported already.
    // A surface that is missing or made of shell edges was reported by check_surface.
    if (c.ref_node < 0 || (!c.node_based() && (!m.mesh.surfaces.count(c.surface) ||
                                               !m.mesh.surfaces.at(c.surface).edges.empty())))
      continue;
    if (!c.node_based()) c.nodes = coupling_nodes(m, c);
    else if (!resolve_weighted_lines(m, c, diags)) continue;
    if (std::find(c.nodes.begin(), c.nodes.end(), c.ref_node) != c.nodes.end())
      diags.error(c.ref_loc, c.keyword(), fmt::format("coupling '{}': the reference node {} is one of its coupling nodes",
                                                   c.name, m.mesh.nodes.labels[static_cast<std::size_t>(c.ref_node)]));
    if (c.nodes.empty() && c.node_based())
      diags.error(c.loc, c.keyword(), fmt::format("coupling '{}' has no coupling node: its lines name none (an empty node "
                                                  "set); expected at least one node", c.name));
    else if (c.nodes.empty())
      diags.error(c.surface_loc, kKeyword, fmt::format("coupling '{}' has no coupling node: surface '{}' has no node{}",
                                                       c.name, c.surface,
                                                       c.influence_radius > 0 ? " within the influence radius" : ""));
    check_not_on_continuum(m, on_continuum, c.ref_node, c.ref_loc, c.keyword(), "reference node", diags);
  }
  check_reference_nodes_distinct(m, diags);
  if (diags.has_errors()) return;
  const int dim = model::spatial_dimension(m.mesh.elements);
  for (model::Coupling& c : m.couplings) {
    if (c.needs_rotations(dim)) {
      c.rot_node = add_rotation_node(m, c.ref_node, fmt::format("{} '{}' (line {})", kKeyword, c.name, c.loc.line));
      c.rot_node_added = true;
    }
  }
}

}  // namespace inpact::parser
