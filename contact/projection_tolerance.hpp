#pragma once
/// What projection.cpp and closest_projection.cpp share (internal to contact/; not its API):
/// a facet's size and the distance below which a point lies on it.
#include <algorithm>
#include <cmath>
#include <span>

#include "contact/facet.hpp"
#include "vec3.hpp"

namespace inpact::contact {

/// The square of the largest distance of a facet node from its node 0, on coordinates `x`.
inline double facet_size_squared(const Facet& f, std::span<const Vec3> x) {
  const Vec3& x0 = x[static_cast<std::size_t>(f.nodes[0])];
  double size2 = 0.0;
  for (int a = 1; a < f.n_nodes; ++a) {
    const Vec3 d = sub(x[static_cast<std::size_t>(f.nodes[a])], x0);
    size2 = std::max(size2, dot(d, d));
  }
  return size2;
}

/// The largest distance of a facet node from its node 0 (√ is monotonic and correctly rounded,
/// so this is the largest of the distances themselves, to the bit).
inline double facet_size(const Facet& f, std::span<const Vec3> x) { return std::sqrt(facet_size_squared(f, x)); }

/// Distance below which a slave point counts as lying on a facet of this size.
// Points closer than this to a facet are on it (gap 0, shared-point normal averaged). Far below
// any penetration tolerance (1e-3 of the interface length), far above the round-off of the
// local Newton projection, which differs between optimisation levels near facet edges.
inline double on_surface_tol(double size) { return 1e-8 * size; }

}  // namespace inpact::contact
