#pragma once
/// What projection.cpp and closest_projection.cpp share (internal to contact/; not its API):
/// a facet's size and the distance below which a point lies on it.
#include <algorithm>
#include <span>

#include "contact/facet.hpp"
#include "vec3.hpp"

namespace inpact::contact {

/// The largest distance of a facet node from its node 0, on coordinates `x` (all node rows).
inline double facet_size(const Facet& f, std::span<const Vec3> x) {
  const Vec3& x0 = x[static_cast<std::size_t>(f.nodes[0])];
  double size = 0.0;
  for (int a = 1; a < f.n_nodes; ++a) size = std::max(size, norm(sub(x[static_cast<std::size_t>(f.nodes[a])], x0)));
  return size;
}

/// Distance below which a slave point counts as lying on a facet of this size.
// Points closer than this to a facet are on it (gap 0, shared-point normal averaged). Far below
// any penetration tolerance (1e-3 of the interface length), far above the round-off of the
// local Newton projection, which differs between optimisation levels near facet edges.
inline double on_surface_tol(double size) { return 1e-8 * size; }

}  // namespace inpact::contact
