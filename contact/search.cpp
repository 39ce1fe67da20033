#include "search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vec3.hpp"

namespace inpact::contact {

bool search_needs_rebuild(double max_displacement, double margin, double fraction) {
  return max_displacement > fraction * margin;
}

void FacetSearch::build(std::span<const Facet> facets, std::span<const Vec3> x, const SearchOptions& options) {
  options_ = options;
  options_.leaf_size = std::max(1, options.leaf_size);
  x_build_.assign(x.begin(), x.end());
  const std::size_t n = facets.size();
  const double h = options.radius + options.margin;

  std::vector<Box> boxes(n);
  std::vector<Vec3> centres(n);
  std::array<Vec3, 9> cp;
  for (std::size_t i = 0; i < n; ++i) {
    const int m = facet_control_points(facets[i], x, cp);
    Box& b = boxes[i];
    for (int k = 0; k < 3; ++k) b.lo[k] = b.hi[k] = cp[0][k];
    for (int j = 1; j < m; ++j)
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], cp[j][k]);
        b.hi[k] = std::max(b.hi[k], cp[j][k]);
      }
    for (int k = 0; k < 3; ++k) {
      b.lo[k] -= h;
      b.hi[k] += h;
      centres[i][k] = 0.5 * (b.lo[k] + b.hi[k]);
    }
  }
  perm_.resize(n);
  for (std::size_t i = 0; i < n; ++i) perm_[i] = static_cast<std::int32_t>(i);
  tree_.clear();
  tree_.reserve(n > 0 ? 2 * (n / static_cast<std::size_t>(options_.leaf_size) + 1) : 0);
  if (n > 0) build_node(0, static_cast<std::int32_t>(n), boxes, centres);
  leaf_boxes_.resize(n);
  for (std::size_t i = 0; i < n; ++i) leaf_boxes_[i] = boxes[static_cast<std::size_t>(perm_[i])];
}

std::int32_t FacetSearch::build_node(std::int32_t first, std::int32_t count, std::vector<Box>& boxes,
                                     const std::vector<Vec3>& centres) {
  const std::int32_t self = static_cast<std::int32_t>(tree_.size());
  tree_.push_back({});
  Box box;
  double clo[3], chi[3];
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = clo[k] = std::numeric_limits<double>::infinity();
    box.hi[k] = chi[k] = -std::numeric_limits<double>::infinity();
  }
  for (std::int32_t i = first; i < first + count; ++i) {
    const std::size_t f = static_cast<std::size_t>(perm_[static_cast<std::size_t>(i)]);
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::min(box.lo[k], boxes[f].lo[k]);
      box.hi[k] = std::max(box.hi[k], boxes[f].hi[k]);
      clo[k] = std::min(clo[k], centres[f][k]);
      chi[k] = std::max(chi[k], centres[f][k]);
    }
  }
  tree_[static_cast<std::size_t>(self)].box = box;
  if (count <= options_.leaf_size) {
    tree_[static_cast<std::size_t>(self)].first = first;
    tree_[static_cast<std::size_t>(self)].count = count;
    return self;
  }
  // Split at the median centre along the longest extent of the centres.
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
  const std::int32_t half = count / 2;
  auto begin = perm_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](std::int32_t a, std::int32_t b) {
    return centres[static_cast<std::size_t>(a)][axis] < centres[static_cast<std::size_t>(b)][axis];
  });
  build_node(first, half, boxes, centres);
  const std::int32_t right = build_node(first + half, count - half, boxes, centres);
  tree_[static_cast<std::size_t>(self)].first = right;
  tree_[static_cast<std::size_t>(self)].count = 0;
  return self;
}

namespace {

template <class B>
bool contains(const B& b, const Vec3& p) {
  return p[0] >= b.lo[0] && p[0] <= b.hi[0] && p[1] >= b.lo[1] && p[1] <= b.hi[1] && p[2] >= b.lo[2] &&
         p[2] <= b.hi[2];
}

template <class B>
bool meets(const B& b, const Vec3& lo, const Vec3& hi) {
  return lo[0] <= b.hi[0] && hi[0] >= b.lo[0] && lo[1] <= b.hi[1] && hi[1] >= b.lo[1] && lo[2] <= b.hi[2] &&
         hi[2] >= b.lo[2];
}

}  // namespace

void FacetSearch::query_box(const Vec3& lo, const Vec3& hi, std::vector<std::int32_t>& out) const {
  if (tree_.empty()) return;
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const TreeNode& node = tree_[static_cast<std::size_t>(stack[--top])];
    if (!meets(node.box, lo, hi)) continue;
    if (node.count > 0) {
      for (std::int32_t i = node.first; i < node.first + node.count; ++i)
        if (meets(leaf_boxes_[static_cast<std::size_t>(i)], lo, hi)) out.push_back(perm_[static_cast<std::size_t>(i)]);
    } else {
      const std::int32_t self = static_cast<std::int32_t>(&node - tree_.data());
      stack[top++] = node.first;  // right child
      stack[top++] = self + 1;    // left child
    }
  }
}

void FacetSearch::query(const Vec3& p, std::vector<std::int32_t>& out) const {
  if (tree_.empty()) return;
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const TreeNode& node = tree_[static_cast<std::size_t>(stack[--top])];
    if (!contains(node.box, p)) continue;
    if (node.count > 0) {
      for (std::int32_t i = node.first; i < node.first + node.count; ++i)
        if (contains(leaf_boxes_[static_cast<std::size_t>(i)], p)) out.push_back(perm_[static_cast<std::size_t>(i)]);
    } else {
      const std::int32_t self = static_cast<std::int32_t>(&node - tree_.data());
      stack[top++] = node.first;  // right child
      stack[top++] = self + 1;    // left child
    }
  }
}

double FacetSearch::drift(std::span<const Facet> facets, std::span<const Vec3> x) const {
  // Control points are linear in the nodes, so their displacement is the difference of the
  // control points on the two sets of coordinates.
  double worst2 = 0.0;
  std::array<Vec3, 9> now, then;
  for (const Facet& f : facets) {
    const int m = facet_control_points(f, x, now);
    facet_control_points(f, x_build_, then);
    for (int j = 0; j < m; ++j) {
      const Vec3 d = sub(now[j], then[j]);
      worst2 = std::max(worst2, dot(d, d));
    }
  }
  return std::sqrt(worst2);
}

bool FacetSearch::needs_rebuild(std::span<const Facet> facets, std::span<const Vec3> x) const {
  return search_needs_rebuild(drift(facets, x), options_.margin, options_.rebuild_fraction);
}

}  // namespace inpact::contact
