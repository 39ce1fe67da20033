#pragma once
/// Label → row lookup for nodes and elements. Abaqus labels are usually dense, so a direct
/// table is used while it stays small relative to the count; sparse labels fall back to a hash.
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace inpact::model {

class LabelMap {
 public:
  /// Maps (instance, label) to row. Returns false when the pair was already present.
  bool insert(std::int32_t instance, std::int64_t label, std::int32_t row);
  std::optional<std::int32_t> find(std::int32_t instance, std::int64_t label) const;
  std::size_t size() const { return count_; }
  void clear();

 private:
  static constexpr std::int32_t kEmpty = -1;
  // Per instance: a dense table indexed by label while labels stay below a bound, else hash.
  struct PerInstance {
    std::vector<std::int32_t> dense;
    std::unordered_map<std::int64_t, std::int32_t> sparse;
  };
  std::vector<PerInstance> instances_;
  std::size_t count_ = 0;
};

}  // namespace inpact::model
