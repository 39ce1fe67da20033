#pragma once
/// Contact search: a bounding-volume tree over master facets, queried per slave point for the
/// facets it may touch.
///
/// Each facet is boxed by the axis-aligned box of its control points (facet_control_points(),
/// which contain the facet even when it is quadratic and curved), enlarged by
/// h = radius + margin, on the coordinates the tree was built on. query(p) returns every facet
/// whose enlarged box contains p.
///
/// Guarantee: every facet whose current distance to p is ≤ radius is returned, as long as no
/// control point of any facet moved more than `margin` since the build (a facet point is a
/// convex combination of its control points, so it moved no more than they did). drift()
/// measures that largest movement; needs_rebuild() compares it with rebuild_fraction × margin.
/// Returned facets lie within (radius + margin)·√3 + their box diagonal of p: candidates, to be
/// projected (projection.hpp) and filtered by the caller.
#include <cstdint>
#include <span>
#include <vector>

#include "contact/facet.hpp"

namespace inpact::contact {

struct SearchOptions {
  double radius = 0.0;            ///< facets within this distance of a point are always found
  double margin = 0.0;            ///< how far control points may move before a rebuild
  double rebuild_fraction = 1.0;  ///< rebuild when drift > rebuild_fraction × margin (≤ 1 keeps the guarantee)
  int leaf_size = 4;              ///< facets per leaf of the tree
};

/// The rebuild rule: true when the largest control-point displacement since the last build
/// (`max_displacement`) exceeds `fraction` × `margin`. A margin of 0 rebuilds on any motion.
bool search_needs_rebuild(double max_displacement, double margin, double fraction);

class FacetSearch {
 public:
  /// Builds the tree over `facets` on coordinates `x` (all node rows). O(n log n).
  void build(std::span<const Facet> facets, std::span<const Vec3> x, const SearchOptions& options);

  /// Appends to `out` the indices (into the facets given to build()) of the candidate facets
  /// of point `p`, in no particular order.
  void query(const Vec3& p, std::vector<std::int32_t>& out) const;
  /// Appends the facets whose enlarged box meets the box [lo, hi] (every facet within radius of
  /// some point of it, under the same guarantee), in no particular order.
  void query_box(const Vec3& lo, const Vec3& hi, std::vector<std::int32_t>& out) const;

  /// Largest control-point displacement of any facet between the build and `x`.
  double drift(std::span<const Facet> facets, std::span<const Vec3> x) const;
  /// search_needs_rebuild(drift(facets, x), margin, rebuild_fraction).
  bool needs_rebuild(std::span<const Facet> facets, std::span<const Vec3> x) const;

  std::size_t n_facets() const { return perm_.size(); }
  std::size_t n_tree_nodes() const { return tree_.size(); }
  const SearchOptions& options() const { return options_; }

 private:
  struct Box {
    double lo[3], hi[3];
  };
  struct TreeNode {
    Box box;
    std::int32_t first;  // leaf: first index into perm_; inner: index of the right child (left = this + 1)
    std::int32_t count;  // leaf: number of facets; inner: 0
  };
  std::int32_t build_node(std::int32_t first, std::int32_t count, std::vector<Box>& boxes,
                          const std::vector<Vec3>& centres);

  SearchOptions options_;
  std::vector<TreeNode> tree_;
  std::vector<std::int32_t> perm_;  ///< facet indices in leaf order
  std::vector<Box> leaf_boxes_;     ///< enlarged facet boxes in leaf order
  std::vector<Vec3> x_build_;       ///< coordinates at the build
};

}  // namespace inpact::contact
