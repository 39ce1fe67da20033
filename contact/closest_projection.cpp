// closest_projection(): the closest of a slave point's candidate facets (projection.hpp).
//
// Most candidates of a point are plainly farther than the closest one, and projecting each of
// them (a Newton iteration, then the minimum over the domain's edges when it converges outside)
// is nearly all the time of a contact update. A facet lies in the convex hull of its control
// points, so a distance bound from them is cheap; a facet whose bound exceeds the distance of
// the best facet so far by more than the tie tolerance cannot win, nor share the closest point,
// and is not projected. The candidates are still compared in the order given: the tie rule
// (within tol, interior before edge before vertex, then the lowest index) depends on that
// order, and skipping only facets that could not change a comparison keeps the chosen facet,
// and every number, exactly what projecting every candidate gives.
#include <algorithm>
#include <limits>
#include <vector>

#include "projection.hpp"
#include "projection_tolerance.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

/// A candidate facet, projected when its distance bound does not rule it out.
struct Candidate {
  std::int32_t index = -1;
  double bound = 0.0;  ///< no point of the facet is closer to the slave point than this
  bool projected = false;
  Projection p;
};

/// A lower bound of |x − xs| over every point x of facet f, which lies in the convex hull of its
/// control points P_a: the distance from xs to their bounding box, and min_a v·(P_a − xs) with v
/// the unit vector from xs towards their centroid. `magnitude` grows to the largest coordinate
/// met (the scale of the round-off in the bound and in the projected distance).
double distance_bound(const Facet& f, std::span<const Vec3> x, const Vec3& xs, double& magnitude) {
  std::array<Vec3, 9> cp;
  const int m = facet_control_points(f, x, cp);
  Vec3 lo = cp[0], hi = cp[0], centre{};
  for (int a = 0; a < m; ++a) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], cp[a][k]);
      hi[k] = std::max(hi[k], cp[a][k]);
      magnitude = std::max({magnitude, std::abs(cp[a][k]), std::abs(xs[k])});
    }
    centre = axpy(1.0 / m, cp[a], centre);
  }
  Vec3 outside{};
  for (int k = 0; k < 3; ++k) outside[k] = std::max({lo[k] - xs[k], 0.0, xs[k] - hi[k]});
  double bound = norm(outside);
  const Vec3 v = sub(centre, xs);
  const double len = norm(v);
  if (len > 0) {
    double along = std::numeric_limits<double>::infinity();
    for (int a = 0; a < m; ++a) along = std::min(along, dot(v, sub(cp[a], xs)) / len);
    bound = std::max(bound, along);
  }
  return bound;
}

}  // namespace

Projection closest_projection(std::span<const Facet> facets, std::span<const std::int32_t> candidates,
                              std::span<const Vec3> x, const Vec3& xs) {
  Projection best;
  if (candidates.empty()) return best;
  std::vector<Candidate> all(candidates.size());
  double size = 0.0, magnitude = 0.0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Facet& f = facets[static_cast<std::size_t>(candidates[i])];
    all[i].index = candidates[i];
    all[i].bound = distance_bound(f, x, xs, magnitude);
    size = std::max(size, facet_size(f, x));
  }
  const double tol = on_surface_tol(size);
  // (the bound and the projected distance each carry round-off of the coordinates' size; 1e-12
  // of it is thousands of times that)
  const double slack = tol + 1e-12 * magnitude;
  auto projected = [&](Candidate& c) -> const Projection& {
    if (!c.projected) c.p = project_to_facet(facets[static_cast<std::size_t>(c.index)], x, xs, c.index);
    c.projected = true;
    return c.p;
  };
  // Farther than distance d + tol for certain (false for a NaN bound or distance: projected then).
  auto beyond = [&](const Candidate& c, double d) { return c.bound - slack > d + tol; };
  // Closest facet; among ties at the same point: interior before edge before vertex, then the
  // lowest facet index.
  auto better = [&](const Projection& a, const Projection& b) {
    if (a.distance < b.distance - tol) return true;
    if (a.distance > b.distance + tol) return false;
    if (a.region != b.region) return a.region < b.region;
    return a.facet < b.facet;
  };
  std::size_t ib = 0;
  projected(all[0]);
  for (std::size_t i = 1; i < all.size(); ++i)
    if (!beyond(all[i], all[ib].p.distance) && better(projected(all[i]), all[ib].p)) ib = i;
  best = all[ib].p;

  // n̄: the facet normals of every candidate sharing the closest point.
  Vec3 nbar{};
  for (Candidate& c : all) {
    if (beyond(c, best.distance)) continue;
    const Projection& q = projected(c);
    if (std::abs(q.distance - best.distance) <= tol && norm(sub(q.x_master, best.x_master)) <= tol)
      nbar = add(nbar, q.facet_normal);
  }
  const double len = norm(nbar);
  const int dim = facet_param_dim(facets[static_cast<std::size_t>(best.facet)].shape) == 1 ? 2 : 3;
  const Vec3 r = sub(xs, best.x_master);
  if (best.distance <= tol) {
    // On the surface to round-off at an edge or vertex: the averaged normal, and the signed
    // distance along it (not 0: under a stiff penalty p/k can be below this tolerance, and a
    // node on a vertex must still carry its force).
    if (len > 0) best.normal = scale(1.0 / len, nbar);
    best.gap = dot(r, best.normal);
  } else if (best.region != ProjectionRegion::Interior) {
    const double s = dot(r, nbar) < 0 ? -1.0 : 1.0;
    best.normal = scale(s / best.distance, r);
    best.gap = s * best.distance;
  }
  tangent_basis(best.normal, dim, best.t1, best.t2);
  return best;
}

}  // namespace inpact::contact
