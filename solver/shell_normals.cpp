#include "shell_normals.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "elements/shell_elements.hpp"

namespace inpact::solver {

namespace {

using elements::Vec3;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// One element's own normal at one of its nodes.
struct NodeNormal {
  std::size_t element;
  int local;  ///< the node's place in the element
  Vec3 normal;
};

/// Each element's own normals at its nodes, gathered per mesh node; elements without a normal
/// (degenerate: the kernel reports them) are left out.
std::vector<std::vector<NodeNormal>> normals_by_node(const model::Model& m, const AnalysisModel& am) {
  std::vector<std::vector<NodeNormal>> by_node(m.mesh.nodes.size());
  // A shell cut by a pre-tension section: a copy and its original turn together, so they average
  // one director over both sides of the cut.
  std::vector<std::int32_t> node_of(m.mesh.nodes.size());
  for (std::size_t n = 0; n < node_of.size(); ++n) node_of[n] = static_cast<std::int32_t>(n);
  for (const model::PretensionSection& s : m.pretension_sections)
    for (const auto& [original, copy] : s.node_pairs) node_of[static_cast<std::size_t>(copy)] = original;
  for (std::size_t e = 0; e < am.elements.size(); ++e) {
    const ElementSetup& s = am.elements[e];
    if (!s.section.shell || s.rigid) continue;
    std::array<Vec3, 8> normals;
    if (!elements::shell_nodal_normals(*s.type, am.coords(e), normals)) continue;
    const auto nodes = m.mesh.elements.nodes_of(e);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      by_node[static_cast<std::size_t>(node_of[static_cast<std::size_t>(nodes[a])])].push_back(
          {e, static_cast<int>(a), normals[a]});
  }
  return by_node;
}

/// A director the deck gives (*NORMAL, or *NODE's normal) replaces the averaged one at that
/// element's node. Abaqus warns when it lies more than 20° from the element's own normal, and
/// takes one given more than 160° from it reversed, without a warning (Analysis User's Guide,
/// "Defining nodal normals").
class GivenDirectors {
 public:
  GivenDirectors(const model::Model& m, AnalysisModel& am, std::vector<std::array<Vec3, 8>>& directors,
                 std::vector<bool>& changed)
      : m_(m), am_(am), directors_(directors), changed_(changed) {}

  void set(std::size_t e, int local, const model::Mesh::GivenNormal& given, const char* keyword) {
    std::array<Vec3, 8> own;
    if (!elements::shell_nodal_normals(*am_.elements[e].type, am_.coords(e), own)) return;  // degenerate: reported
    const auto& g = given.direction;
    const double length = std::sqrt(dot(g, g));
    Vec3 unit{g[0] / length, g[1] / length, g[2] / length};
    const double cosine = dot(unit, own[static_cast<std::size_t>(local)]);
    if (cosine < kReverse)
      for (double& c : unit) c = -c;
    else if (cosine < kWarn)
      am_.warnings.push_back(fmt::format(
          "{} at {}: the normal of element {} at node {} lies {:.1f}° from the element's own normal", keyword,
          m_.sources.describe(given.loc), m_.mesh.elements.labels[e],
          m_.mesh.nodes.labels[static_cast<std::size_t>(m_.mesh.elements.nodes_of(e)[static_cast<std::size_t>(local)])],
          std::acos(cosine) * 180.0 / std::numbers::pi));
    directors_[e][static_cast<std::size_t>(local)] = unit;
    changed_[e] = true;
  }

 private:
  static inline const double kWarn = std::cos(20.0 * std::numbers::pi / 180.0);
  static inline const double kReverse = std::cos(160.0 * std::numbers::pi / 180.0);
  const model::Model& m_;
  AnalysisModel& am_;
  std::vector<std::array<Vec3, 8>>& directors_;
  std::vector<bool>& changed_;
};

/// *NODE's normals at every shell node they are given for, then *NORMAL's, which take precedence.
void apply_given_normals(const model::Model& m, AnalysisModel& am, std::vector<std::array<Vec3, 8>>& directors,
                         std::vector<bool>& changed) {
  GivenDirectors given(m, am, directors, changed);
  if (!m.mesh.node_normals.empty())
    for (std::size_t e = 0; e < am.elements.size(); ++e) {
      if (!am.elements[e].section.shell || am.elements[e].rigid) continue;
      const auto nodes = m.mesh.elements.nodes_of(e);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        if (auto it = m.mesh.node_normals.find(nodes[a]); it != m.mesh.node_normals.end())
          given.set(e, static_cast<int>(a), it->second, "*NODE");
    }
  for (const model::Mesh::GivenNormal& n : m.mesh.normals)
    if (!am.elements[static_cast<std::size_t>(n.element)].rigid)
      given.set(static_cast<std::size_t>(n.element), n.local, n, "*NORMAL");
}

}  // namespace

void average_shell_normals(const model::Model& m, AnalysisModel& am) {
  const double within = std::cos(kNormalAveragingDegrees * std::numbers::pi / 180.0);
  std::vector<std::array<Vec3, 8>> averaged(am.elements.size());
  std::vector<bool> changed(am.elements.size(), false);
  for (const std::vector<NodeNormal>& at_node : normals_by_node(m, am))
    for (const NodeNormal& own : at_node) {
      Vec3 sum{};
      for (const NodeNormal& other : at_node)
        if (dot(own.normal, other.normal) >= within)
          for (int i = 0; i < 3; ++i) sum[i] += other.normal[i];
      const double length = std::sqrt(dot(sum, sum));  // ≥ 1: `own` is within of itself
      Vec3& director = averaged[own.element][static_cast<std::size_t>(own.local)];
      for (int i = 0; i < 3; ++i) director[i] = sum[i] / length;
      if (1.0 - dot(director, own.normal) > 1e-14) changed[own.element] = true;
    }
  apply_given_normals(m, am, averaged, changed);
  for (std::size_t e = 0; e < am.elements.size(); ++e) {
    if (!changed[e]) continue;
    const std::size_t n = m.mesh.elements.nodes_of(e).size();
    std::array<Vec3, 8>& stored = am.shell_directors.emplace_back(averaged[e]);
    am.elements[e].section.shell_directors = std::span<const Vec3>(stored.data(), n);
  }
}

}  // namespace inpact::solver
