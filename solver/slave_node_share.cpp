#include "slave_node_share.hpp"

#include <algorithm>

namespace inpact::solver {

namespace {

/// Recursive coordinate bisection: `items` (indices into `points`) shared over the ranks
/// [first, first + ranks), each rank's cost as even as can be and its nodes a compact patch.
/// Each cut goes across the longest side of the items' box; ties go by index, so that every
/// rank computes the same share.
void bisect(std::span<const std::array<double, 3>> points, std::span<const double> cost, std::span<std::size_t> items,
            int first, int ranks, std::vector<int>& owner) {
  if (ranks == 1 || items.size() <= 1) {
    for (std::size_t i : items) owner[i] = first;
    return;
  }
  std::array<double, 3> lo = points[items[0]], hi = lo;
  for (std::size_t i : items)
    for (std::size_t c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], points[i][c]);
      hi[c] = std::max(hi[c], points[i][c]);
    }
  std::size_t axis = 0;
  for (std::size_t c = 1; c < 3; ++c)
    if (hi[c] - lo[c] > hi[axis] - lo[axis]) axis = c;
  std::sort(items.begin(), items.end(), [&](std::size_t a, std::size_t b) {
    return points[a][axis] < points[b][axis] || (points[a][axis] == points[b][axis] && a < b);
  });
  const int left = ranks / 2;
  double total = 0.0;
  for (std::size_t i : items) total += cost[i];
  const double target = total * left / ranks;
  std::size_t cut = 0;
  for (double sum = 0.0; cut < items.size() && sum + 0.5 * cost[items[cut]] < target; ++cut) sum += cost[items[cut]];
  cut = std::clamp<std::size_t>(cut, 1, items.size() - 1);  // (each side gets a node; one costly node may still leave a rank none)
  bisect(points, cost, items.first(cut), first, left, owner);
  bisect(points, cost, items.subspan(cut), first + left, ranks - left, owner);
}

}  // namespace

SlaveNodeShare::SlaveNodeShare(RankWorld world, std::span<const std::array<double, 3>> points,
                               std::span<const double> cost)
    : world_(world) {
  if (!world.distributed()) return;
  owner_.assign(points.size(), 0);
  std::vector<std::size_t> items(points.size());
  for (std::size_t i = 0; i < items.size(); ++i) items[i] = i;
  bisect(points, cost, items, 0, world.size, owner_);
  count_of_rank_.assign(static_cast<std::size_t>(world.size), 0);
  for (int r : owner_) ++count_of_rank_[static_cast<std::size_t>(r)];
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
