#include "label_map.hpp"

#include <algorithm>

namespace inpact::model {

namespace {
// A label may go into the direct table while the table stays within this many slots per
// stored entry (plus a fixed allowance): keeps memory linear in the count for any numbering.
// The allowance is small (256 kB of table): a small deck that numbers a second part from
// 1,000,001 would otherwise fill and page in a 4 MB table per map, which cost more than
// reading its few thousand elements (bench/study_overhead.py).
constexpr std::int64_t kDenseSlack = 1 << 16;
constexpr std::int64_t kDenseFactor = 4;
}  // namespace

bool LabelMap::insert(std::int32_t instance, std::int64_t label, std::int32_t row) {
  if (instance >= static_cast<std::int32_t>(instances_.size())) instances_.resize(instance + 1);
  PerInstance& p = instances_[instance];
  const std::int64_t bound = kDenseFactor * static_cast<std::int64_t>(count_ + 1) + kDenseSlack;
  if (label >= 0 && label < bound && !p.sparse.count(label)) {
    if (label >= static_cast<std::int64_t>(p.dense.size())) {
      std::size_t grow = std::max<std::size_t>(label + 1, p.dense.size() * 2);
      grow = std::min<std::size_t>(grow, static_cast<std::size_t>(bound));
      p.dense.resize(std::max<std::size_t>(grow, label + 1), kEmpty);
    }
    if (p.dense[label] != kEmpty) return false;
    p.dense[label] = row;
  } else {
    if (label >= 0 && label < static_cast<std::int64_t>(p.dense.size()) && p.dense[label] != kEmpty)
      return false;
    if (!p.sparse.emplace(label, row).second) return false;
  }
  ++count_;
  return true;
}

std::optional<std::int32_t> LabelMap::find(std::int32_t instance, std::int64_t label) const {
  if (instance < 0 || instance >= static_cast<std::int32_t>(instances_.size())) return std::nullopt;
  const PerInstance& p = instances_[instance];
  if (label >= 0 && label < static_cast<std::int64_t>(p.dense.size()) && p.dense[label] != kEmpty)
    return p.dense[label];
  if (p.sparse.empty()) return std::nullopt;
  auto it = p.sparse.find(label);
  if (it == p.sparse.end()) return std::nullopt;
  return it->second;
}

void LabelMap::clear() {
  instances_.clear();
  count_ = 0;
}

}  // namespace inpact::model
