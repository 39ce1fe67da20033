#include "shell_normals.hpp"

#include <cmath>
#include <numbers>
#include <vector>

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
  for (std::size_t e = 0; e < am.elements.size(); ++e) {
    const ElementSetup& s = am.elements[e];
    if (!s.section.shell || s.rigid) continue;
    std::array<Vec3, 8> normals;
    if (!elements::shell_nodal_normals(*s.type, am.coords(e), normals)) continue;
    const auto nodes = m.mesh.elements.nodes_of(e);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      by_node[static_cast<std::size_t>(nodes[a])].push_back({e, static_cast<int>(a), normals[a]});
  }
  return by_node;
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
  for (std::size_t e = 0; e < am.elements.size(); ++e) {
    if (!changed[e]) continue;
    const std::size_t n = m.mesh.elements.nodes_of(e).size();
    std::array<Vec3, 8>& stored = am.shell_directors.emplace_back(averaged[e]);
    am.elements[e].section.shell_directors = std::span<const Vec3>(stored.data(), n);
  }
}

}  // namespace inpact::solver
