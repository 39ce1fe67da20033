#pragma once
/// How a distributed run shares a contact pair's slave nodes (solver/contact_problem.hpp): each
/// rank measures, linearises and assembles its own share of them, a compact patch of the
/// surface (recursive coordinate bisection of the nodes' reference positions) of even cost, so
/// that the search and projection, contact's cost, are divided whatever the element partition
/// (which may well leave a whole slave surface on one rank: two bodies touching only through
/// contact are two components of the element graph). The patch's terms go into rows other
/// ranks may own; PETSc's assembly sends them there. What the status rules read of a node
/// (its measure without the linearisations, its friction state) is then gathered to every
/// rank: every rank holds the same contact state and takes the same decisions, as the
/// analysis's control flow requires. On one rank every node is its own and nothing moves.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "linear/petsc_module.hpp"

namespace inpact::solver {

class SlaveNodeShare {
 public:
  /// One rank: every node owned.
  SlaveNodeShare() = default;
  /// The share of the slave nodes at `points` (their reference positions, in the surface's node
  /// order) over `world`'s ranks, each rank's `cost` (per slave node) as even as can be. The
  /// same on every rank given the same arguments.
  SlaveNodeShare(RankWorld world, std::span<const std::array<double, 3>> points, std::span<const double> cost);

  bool shared() const { return !owner_.empty(); }
  /// Slave nodes per rank (empty on one rank).
  std::span<const long> count_of_rank() const { return count_of_rank_; }
  /// Does this rank own slave node i (its position in the surface's node list)?
  bool owns(std::size_t i) const { return owner_.empty() || owner_[i] == world_.rank; }
  /// Per slave node, 1 where this rank owns it (PairKinematics::set_measured_nodes); empty on one rank.
  std::vector<char> owned_mask() const;

  /// Every rank's owned entries of `items` (one per slave node) copied into every rank's
  /// `items`, through `pack` (item → trivially copyable Record) and `unpack` (Record, item&).
  template <class Record, class Item, class Pack, class Unpack>
  void gather(std::vector<Item>& items, Pack pack, Unpack unpack) const {
    static_assert(std::is_trivially_copyable_v<Record>);
    if (!shared()) return;
    std::vector<Record> mine;
    mine.reserve(static_cast<std::size_t>(count_of_rank_[static_cast<std::size_t>(world_.rank)]));
    for (std::size_t i = 0; i < items.size(); ++i)
      if (owns(i)) mine.push_back(pack(items[i]));
    std::vector<Record> all(items.size());
    world_.gather(std::as_bytes(std::span(mine)), std::as_writable_bytes(std::span(all)), sizeof(Record),
                  count_of_rank_);
    // Rank r's records follow those of the ranks before it, in slave node order.
    std::vector<long> next = first_of_rank();
    for (std::size_t i = 0; i < items.size(); ++i)
      unpack(all[static_cast<std::size_t>(next[static_cast<std::size_t>(owner_[i])]++)], items[i]);
  }
  /// The same with the items themselves as records.
  template <class Item>
  void gather(std::vector<Item>& items) const {
    gather<Item>(items, [](const Item& item) { return item; }, [](const Item& r, Item& item) { item = r; });
  }

 private:
  /// Per rank, the position of its first record in the gathered list.
  std::vector<long> first_of_rank() const;

  RankWorld world_;
  std::vector<int> owner_;           ///< per slave node, its rank (empty on one rank)
  std::vector<long> count_of_rank_;  ///< slave nodes per rank
};

}  // namespace inpact::solver
