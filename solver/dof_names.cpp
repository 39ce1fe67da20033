#include "dof_names.hpp"

#include <fmt/format.h>

namespace inpact::solver {

namespace {

/// A node's label as the deck writes it: `instance.label` for a node of a part instance.
std::string node_label(const AnalysisModel& am, std::size_t node) {
  const auto& nodes = am.model->mesh.nodes;
  const std::string& instance = am.model->instances[static_cast<std::size_t>(nodes.instance[node])];
  return instance.empty() ? fmt::format("{}", nodes.labels[node]) : fmt::format("{}.{}", instance, nodes.labels[node]);
}

}  // namespace

std::string node_dof(const AnalysisModel& am, std::int64_t d) {
  const auto node = static_cast<std::int32_t>(d / am.dim);
  const int c = static_cast<int>(d % am.dim);
  for (std::size_t ref = 0; ref < am.rotation_node_of.size(); ++ref)
    if (am.rotation_node_of[ref] == node) return fmt::format("node {} DOF {}", node_label(am, ref), am.dim == 3 ? 4 + c : 6);
  for (std::size_t ref = 0; ref < am.local_node_of.size(); ++ref)
    if (am.local_node_of[ref] == node) return fmt::format("node {} DOF {} (in its *TRANSFORM axes)", node_label(am, ref), c + 1);
  return fmt::format("node {} DOF {}", node_label(am, static_cast<std::size_t>(node)), c + 1);
}

}  // namespace inpact::solver
