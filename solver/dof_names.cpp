#include "dof_names.hpp"

#include <fmt/format.h>

namespace inpact::solver {

std::string node_dof(const AnalysisModel& am, std::int64_t d) {
  const auto node = static_cast<std::int32_t>(d / am.dim);
  const int c = static_cast<int>(d % am.dim);
  const auto& labels = am.model->mesh.nodes.labels;
  for (std::size_t ref = 0; ref < am.rotation_node_of.size(); ++ref)
    if (am.rotation_node_of[ref] == node) return fmt::format("node {} DOF {}", labels[ref], am.dim == 3 ? 4 + c : 6);
  return fmt::format("node {} DOF {}", labels[static_cast<std::size_t>(node)], c + 1);
}

}  // namespace inpact::solver
