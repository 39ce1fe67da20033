#include "slave_node_share.hpp"

namespace inpact::solver {

SlaveNodeShare::SlaveNodeShare(RankWorld world, std::span<const int> rank_of_node,
                               std::span<const std::int32_t> slave_nodes)
    : world_(world) {
  if (!world.distributed()) return;
  count_of_rank_.assign(static_cast<std::size_t>(world.size), 0);
  owner_.reserve(slave_nodes.size());
  for (std::int32_t row : slave_nodes) {
    owner_.push_back(rank_of_node[static_cast<std::size_t>(row)]);
    ++count_of_rank_[static_cast<std::size_t>(owner_.back())];
  }
}

std::vector<char> SlaveNodeShare::owned_mask() const {
  std::vector<char> mask;
  if (!shared()) return mask;
  mask.reserve(owner_.size());
  for (int r : owner_) mask.push_back(r == world_.rank ? 1 : 0);
  return mask;
}

std::vector<long> SlaveNodeShare::first_of_rank() const {
  std::vector<long> first(count_of_rank_.size(), 0);
  for (std::size_t r = 1; r < first.size(); ++r) first[r] = first[r - 1] + count_of_rank_[r - 1];
  return first;
}

}  // namespace inpact::solver
