#include "transforms.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "model/reference_nodes.hpp"
#include "rotation_nodes.hpp"

namespace inpact::parser {

namespace {

constexpr const char* kKeyword = "*TRANSFORM";

/// How the deck refers to a node's translations (DOFs 1–3) or its rotations (4–6).
struct NodeReferences {
  std::vector<std::uint8_t> used;  ///< a *BOUNDARY, *CLOAD or *EQUATION names one
  /// Only boundary conditions name them, each to zero, all three in all: the node is held in
  /// every direction, in any axes alike.
  std::vector<std::uint8_t> held_at_zero;
};

NodeReferences referenced_nodes(const model::Model& m, int first_dof) {
  const int last_dof = first_dof + 2;
  const auto in_range = [&](int d) { return d >= first_dof && d <= last_dof; };
  const std::size_t n = m.mesh.nodes.size();
  std::vector<std::uint8_t> used(n, 0), dofs(n, 0), not_zero(n, 0);
  auto boundaries = [&](const std::vector<model::BoundaryBlock>& blocks) {
    for (const model::BoundaryBlock& b : blocks)
      for (const model::BoundaryEntry& e : b.entries)
        if (e.first_dof <= last_dof && e.last_dof >= first_dof)
          for (std::int32_t node : e.nodes) {
            used[static_cast<std::size_t>(node)] = 1;
            for (int d = std::max(e.first_dof, first_dof); d <= std::min(e.last_dof, last_dof); ++d)
              dofs[static_cast<std::size_t>(node)] |= 1u << (d - first_dof);
            if (e.value != 0.0 || b.fixed) not_zero[static_cast<std::size_t>(node)] = 1;
          }
  };
  boundaries(m.boundaries);
  for (const model::Step& s : m.steps) {
    boundaries(s.boundaries);
    for (const model::CloadBlock& c : s.cloads)
      for (const model::CloadEntry& e : c.entries)
        if (in_range(e.dof))
          for (std::int32_t node : e.nodes) used[static_cast<std::size_t>(node)] = not_zero[static_cast<std::size_t>(node)] = 1;
  }
  for (const model::Equation& eq : m.equations)
    for (const auto& t : eq.terms)
      if (in_range(t.dof)) used[static_cast<std::size_t>(t.node)] = not_zero[static_cast<std::size_t>(t.node)] = 1;
  NodeReferences r{used, std::vector<std::uint8_t>(n, 0)};
  for (std::size_t i = 0; i < n; ++i) r.held_at_zero[i] = used[i] && dofs[i] == 7 && !not_zero[i];
  return r;
}

/// Beam nodes whose rotations the deck refers to in a transform's axes: inpact has no local
/// rotations yet, and applying them in global axes would be silently wrong.
void check_no_local_rotations(const model::Model& m, const std::vector<std::int32_t>& transform_of, Diagnostics& diags) {
  if (m.node_rotations.empty()) return;
  const NodeReferences rotations = referenced_nodes(m, 4);
  for (const model::NodeRotation& b : m.node_rotations) {
    const auto n = static_cast<std::size_t>(b.node);
    const std::int32_t t = transform_of[n];
    if (t < 0 || !rotations.used[n] || rotations.held_at_zero[n]) continue;
    diags.error(m.transforms[static_cast<std::size_t>(t)].loc, kKeyword,
                fmt::format("beam node {} is in this system and a boundary condition, moment or equation refers to its "
                            "rotations (DOFs 4-6), which have no local system in inpact yet",
                            m.mesh.nodes.labels[n]));
    return;
  }
}

/// Node n, referred to in its transform's axes, can have them: not a reference node (its
/// rotations are not transformed) and not on a cylindrical system's axis. Reports otherwise.
bool can_be_local(const model::Model& m, std::int32_t n, const model::NodalTransform& t, Diagnostics& diags) {
  const auto label = m.mesh.nodes.labels[static_cast<std::size_t>(n)];
  if (model::is_reference_node(m, n)) {
    diags.error(t.loc, kKeyword, fmt::format("node {} is the reference node of a rigid body or coupling; its rotations "
                                             "have no local system in inpact yet", label));
    return false;
  }
  std::array<std::array<double, 3>, 3> axes;
  if (model::local_axes(t, m.mesh.nodes.coords[static_cast<std::size_t>(n)], axes)) return true;
  diags.error(t.loc, kKeyword,
              t.type == model::NodalTransform::Type::Cylindrical
                  ? fmt::format("node {} lies on the cylindrical system's axis, and a boundary condition, load or "
                                "equation refers to its local directions: it has no radial one", label)
                  : std::string("points a and b do not define a system (a is zero, or b on the line through a)"));
  return false;
}

}  // namespace

void finalize_transforms(model::Model& m, Diagnostics& diags) {
  if (m.transforms.empty()) return;
  const auto& labels = m.mesh.nodes.labels;
  std::vector<std::int32_t> transform_of(m.mesh.nodes.size(), -1);
  for (std::size_t t = 0; t < m.transforms.size(); ++t)
    for (std::int32_t n : m.transforms[t].nodes) {
      auto& owner = transform_of[static_cast<std::size_t>(n)];
      if (owner >= 0 && owner != static_cast<std::int32_t>(t)) {
        diags.error(m.transforms[t].loc, kKeyword,
                    fmt::format("node {} is in the *TRANSFORM at line {} already; a node has one local system",
                                labels[static_cast<std::size_t>(n)], m.transforms[static_cast<std::size_t>(owner)].loc.line));
        return;
      }
      owner = static_cast<std::int32_t>(t);
    }
  check_no_local_rotations(m, transform_of, diags);
  const NodeReferences refs = referenced_nodes(m, 1);
  std::vector<std::size_t> added(m.transforms.size(), 0);
  const std::size_t n_nodes = m.mesh.nodes.size();
  for (std::size_t n = 0; n < n_nodes; ++n) {
    const std::int32_t t = transform_of[n];
    // A node held at zero in all three directions is held so in any axes: it needs none (and a
    // node on a cylindrical axis, which has none, may be one).
    if (t < 0 || !refs.used[n] || refs.held_at_zero[n] ||
        !can_be_local(m, static_cast<std::int32_t>(n), m.transforms[static_cast<std::size_t>(t)], diags))
      continue;
    const std::int32_t local = add_node_beside(m.mesh, static_cast<std::int32_t>(n));
    m.transformed_nodes.push_back({static_cast<std::int32_t>(n), local, t});
    ++added[static_cast<std::size_t>(t)];
  }
  for (std::size_t t = 0; t < m.transforms.size(); ++t)
    if (added[t] > 0)
      m.preprocessing_notes.push_back(fmt::format(
          "{} (line {}): {} node(s) added to hold the local components of the nodes of {} that boundary conditions, "
          "loads or equations refer to (their U and RF are the local ones)",
          kKeyword, m.transforms[t].loc.line, added[t], m.transforms[t].nset));
}

}  // namespace inpact::parser
