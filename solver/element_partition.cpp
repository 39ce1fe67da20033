#include "element_partition.hpp"

#include <algorithm>
#include <array>
#include <mutex>

namespace inpact::solver {

namespace {

/// The elements' dual graph in CSR form: the elements sharing a node with each, sorted.
void dual_graph(const model::Mesh& mesh, std::vector<long>& xadj, std::vector<long>& adjacency) {
  const std::size_t n_el = mesh.elements.size(), n_nodes = mesh.nodes.size();
  std::vector<long> node_ptr(n_nodes + 1, 0), node_elements;
  for (std::size_t e = 0; e < n_el; ++e)
    for (const auto node : mesh.elements.nodes_of(e)) ++node_ptr[static_cast<std::size_t>(node) + 1];
  for (std::size_t v = 0; v < n_nodes; ++v) node_ptr[v + 1] += node_ptr[v];
  node_elements.resize(static_cast<std::size_t>(node_ptr[n_nodes]));
  std::vector<long> next(node_ptr.begin(), node_ptr.end() - 1);
  for (std::size_t e = 0; e < n_el; ++e)
    for (const auto node : mesh.elements.nodes_of(e))
      node_elements[static_cast<std::size_t>(next[static_cast<std::size_t>(node)]++)] = static_cast<long>(e);
  xadj.assign(n_el + 1, 0);
  adjacency.clear();
  std::vector<long> seen_by(n_el, -1);
  for (std::size_t e = 0; e < n_el; ++e) {
    const auto first = static_cast<std::ptrdiff_t>(adjacency.size());
    for (const auto node : mesh.elements.nodes_of(e)) {
      const auto v = static_cast<std::size_t>(node);
      for (long k = node_ptr[v]; k < node_ptr[v + 1]; ++k) {
        const long f = node_elements[static_cast<std::size_t>(k)];
        if (f == static_cast<long>(e) || seen_by[static_cast<std::size_t>(f)] == static_cast<long>(e)) continue;
        seen_by[static_cast<std::size_t>(f)] = static_cast<long>(e);
        adjacency.push_back(f);
      }
    }
    std::sort(adjacency.begin() + first, adjacency.end());
    xadj[e + 1] = static_cast<long>(adjacency.size());
  }
}

/// The rank owning each node's rows (ElementPartition::rank_of_node).
std::vector<int> node_ranks(const AnalysisModel& am, const std::vector<int>& rank_of_element, int ranks) {
  std::vector<int> rank(am.model->mesh.nodes.size(), ranks - 1);
  std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;  // a beam's or shell's rotation nodes too
  for (std::size_t e = 0; e < rank_of_element.size(); ++e) {
    const std::size_t n_rows = am.element_rows(e, rows);
    for (std::size_t a = 0; a < n_rows; ++a) {
      int& owner = rank[static_cast<std::size_t>(rows[a])];
      owner = std::min(owner, rank_of_element[e]);
    }
  }
  return rank;
}

}  // namespace

const ElementPartition& element_partition(const AnalysisModel& am, RankWorld world) {
  static std::mutex guard;
  static const model::Model* model = nullptr;
  static int ranks = 0;
  static ElementPartition partition;
  const std::lock_guard lock(guard);
  const std::size_t n_el = am.model->mesh.elements.size();
  if (model == am.model && ranks == world.size && partition.rank_of_element.size() == n_el) return partition;
  partition = ElementPartition{};
  if (world.distributed()) {
    std::vector<long> xadj, adjacency;
    dual_graph(am.model->mesh, xadj, adjacency);
    partition.rank_of_element = partition_graph(xadj, adjacency);
  } else {
    partition.rank_of_element.assign(n_el, 0);
  }
  partition.counts.assign(static_cast<std::size_t>(world.size), 0);
  for (int r : partition.rank_of_element) ++partition.counts[static_cast<std::size_t>(r)];
  partition.rank_of_node = node_ranks(am, partition.rank_of_element, world.size);
  model = am.model;
  ranks = world.size;
  return partition;
}

}  // namespace inpact::solver
