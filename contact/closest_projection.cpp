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
#include <cmath>
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
  double box = 0.0;    ///< the distance to the box of its control points (the first bound)
  double bound = 0.0;  ///< no point of the facet is closer to the slave point than this
  bool refined = false;  ///< bound includes axis_bound()
  bool projected = false;
  Projection p;
};

/// How far the points P lie from xs along the unit vector u, on the side they lie: no point of
/// their convex hull is closer to xs than this along u (0 when xs is between them).
double separation(std::span<const Vec3> P, const Vec3& xs, const Vec3& u) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& p : P) {
    const double s = dot(u, sub(p, xs));
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return std::max({lo, -hi, 0.0});
}

/// The facet's normal direction from its corners (unit; zero when they are degenerate).
Vec3 corner_normal(const Facet& f, std::span<const Vec3> c) {
  const int nc = facet_n_corners(f.shape);
  Vec3 n{};
  if (nc == 2) n = {c[1][1] - c[0][1], c[0][0] - c[1][0], 0.0};  // 2D: the edge turned in its plane
  else if (nc == 3) n = cross(sub(c[1], c[0]), sub(c[2], c[0]));
  else n = cross(sub(c[2], c[0]), sub(c[3], c[1]));
  const double len = norm(n);
  return len > 0 ? scale(1.0 / len, n) : Vec3{};
}

/// Separating axes: the facet's normal n and, perpendicular to it, the in-plane normal of each
/// corner edge (the edge itself for a 2D facet); with b_n and b_e the separations along n and
/// along the edge axis, |x − xs|² ≥ b_n² + b_e² (the axes are orthonormal).
double axis_bound(const Facet& f, std::span<const Vec3> P, const Vec3& xs) {
  const Vec3 n = corner_normal(f, P);
  if (dot(n, n) == 0.0) return 0.0;
  const int nc = facet_n_corners(f.shape);
  const double b_n = separation(P, xs, n);
  double b_e = 0.0;
  for (int i = 0; i < (nc == 2 ? 1 : nc); ++i) {
    const Vec3 edge = sub(P[static_cast<std::size_t>((i + 1) % nc)], P[static_cast<std::size_t>(i)]);
    const Vec3 w = nc == 2 ? edge : cross(edge, n);
    const double len = norm(w);
    if (len > 0) b_e = std::max(b_e, separation(P, xs, scale(1.0 / len, w)));
  }
  return std::sqrt(b_n * b_n + b_e * b_e);
}

}  // namespace

FacetBox facet_box(const Facet& f, std::span<const Vec3> x) {
  std::array<Vec3, 9> cp;
  const std::span<const Vec3> P(cp.data(), static_cast<std::size_t>(facet_control_points(f, x, cp)));
  FacetBox b{P[0], P[0], facet_size_squared(f, x)};
  for (const Vec3& p : P)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], p[k]);
      b.hi[k] = std::max(b.hi[k], p[k]);
    }
  return b;
}

void facet_boxes(std::span<const Facet> facets, std::span<const Vec3> x, std::vector<FacetBox>& out) {
  out.resize(facets.size());
  for (std::size_t i = 0; i < facets.size(); ++i) out[i] = facet_box(facets[i], x);
}

namespace {

/// The distance from xs to the box (a lower bound of |x − xs| over the facet, which lies in the
/// convex hull of the control points it boxes). `magnitude` grows to the largest coordinate met
/// (the scale of the round-off in the bound and in the projected distance).
double box_bound(const FacetBox& b, const Vec3& xs, double& magnitude) {
  Vec3 outside{};
  for (int k = 0; k < 3; ++k) {
    outside[k] = std::max({b.lo[k] - xs[k], 0.0, xs[k] - b.hi[k]});
    magnitude = std::max({magnitude, std::abs(b.lo[k]), std::abs(b.hi[k]), std::abs(xs[k])});
  }
  return norm(outside);
}

/// A bound never NaN: a NaN one is −∞ (the candidate is then projected).
double usable(double bound) { return std::isnan(bound) ? -std::numeric_limits<double>::infinity() : bound; }

/// The candidates of one slave point, projected on demand.
class CandidateSet {
 public:
  CandidateSet(std::span<const Facet> facets, std::span<const std::int32_t> candidates, std::span<const Vec3> x,
               const Vec3& xs, const ProjectionHint* hint, std::span<const FacetBox> boxes,
               std::vector<Candidate>& storage, const Projection* known)
      : facets_(facets), x_(x), xs_(xs), hint_(hint), known_(known), all_(storage) {
    all_.resize(candidates.size());
    double size2 = 0.0, magnitude = 0.0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const auto fi = static_cast<std::size_t>(candidates[i]);
      const FacetBox b = boxes.empty() ? facet_box(facets[fi], x) : boxes[fi];
      Candidate& c = all_[i];
      c.index = candidates[i];
      c.box = c.bound = usable(box_bound(b, xs, magnitude));
      c.refined = c.projected = false;
      size2 = std::max(size2, b.size2);
    }
    tol_ = on_surface_tol(std::sqrt(size2));  // (the largest facet_size())
    // (the bound and the projected distance each carry round-off of the coordinates' size;
    // 1e-12 of it is thousands of times that)
    slack_ = tol_ + 1e-12 * magnitude;
  }
  double tol() const { return tol_; }
  double slack() const { return slack_; }
  std::size_t size() const { return all_.size(); }
  /// No candidate but `chosen` is closer to the point than this (+∞ when there is no other; NaN
  /// when a distance is): the distance bounds, refined by the separating axes, and the projected
  /// distance where it is the facet's least for certain (a straight edge or a flat triangle: a
  /// curved facet's Newton finds a local least, which a later start may undercut).
  /// The separating axes refine only the candidates whose box bound is the lowest so far, until
  /// the lowest is final.
  double others_bound(std::int32_t chosen) {
    for (;;) {
      double lowest = std::numeric_limits<double>::infinity();
      std::size_t at = all_.size();
      for (std::size_t i = 0; i < all_.size(); ++i) {
        const Candidate& c = all_[i];
        if (c.index == chosen) continue;
        const FacetShape shape = facets_[static_cast<std::size_t>(c.index)].shape;
        const bool exact = c.projected && (shape == FacetShape::Tri3 || shape == FacetShape::Line2);
        const double d = exact ? c.p.distance : c.bound;
        if (std::isnan(d)) return d;
        if (d < lowest) lowest = d, at = exact ? all_.size() : i;
      }
      if (at == all_.size() || all_[at].refined) return lowest;
      refine(at);
    }
  }

  const Projection& projected(std::size_t i) {
    Candidate& c = all_[i];
    if (!c.projected)
      c.p = known_ && known_->facet == c.index
                ? *known_
                : project_to_facet(facets_[static_cast<std::size_t>(c.index)], x_, xs_, c.index,
                                   hint_ && hint_->facet == c.index ? &hint_->xi : nullptr);
    c.projected = true;
    return c.p;
  }
  /// Candidate i is farther than distance d + tol for certain (never for a NaN d). The box
  /// bound first, the separating axes when it does not decide.
  bool beyond(std::size_t i, double d) {
    Candidate& c = all_[i];
    if (c.bound - slack_ > d + tol_) return true;
    if (c.refined) return false;
    refine(i);
    return c.bound - slack_ > d + tol_;
  }
  /// Candidate i's bound with the separating axes' (once).
  void refine(std::size_t i) {
    Candidate& c = all_[i];
    if (c.refined) return;
    c.refined = true;
    std::array<Vec3, 9> cp;
    const Facet& f = facets_[static_cast<std::size_t>(c.index)];
    const std::size_t m = static_cast<std::size_t>(facet_control_points(f, x_, cp));
    c.bound = std::max(c.bound, usable(axis_bound(f, std::span<const Vec3>(cp.data(), m), xs_)));
  }
  /// Closest facet; among ties at the same point: interior before edge before vertex, then the
  /// lowest facet index.
  bool better(const Projection& a, const Projection& b) const {
    if (a.distance < b.distance - tol_) return true;
    if (a.distance > b.distance + tol_) return false;
    if (a.region != b.region) return a.region < b.region;
    return a.facet < b.facet;
  }
  std::size_t select();
  /// n̄: the facet normals of every candidate sharing the closest point `best`, in candidate order.
  Vec3 shared_normal(const Projection& best);

 private:
  std::size_t select_from(std::size_t ib, std::size_t begin, std::size_t end);
  std::span<const Facet> facets_;
  std::span<const Vec3> x_;
  Vec3 xs_;
  const ProjectionHint* hint_;
  const Projection* known_;
  std::vector<Candidate>& all_;
  double tol_ = 0.0, slack_ = 0.0;
};

/// The winner of the comparisons "candidate i against the best so far" for i in [begin, end),
/// starting from the best `ib` (projected): a candidate beyond the best's distance cannot win.
std::size_t CandidateSet::select_from(std::size_t ib, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i)
    if (!beyond(i, all_[ib].p.distance) && better(projected(i), all_[ib].p)) ib = i;
  return ib;
}

/// The candidate the comparisons in candidate order choose, as if every one were projected.
/// First the candidates are projected in the order of their box bounds until the bounds rule
/// out coming within 3 tol of the closest distance D found: the rest are farther than D + 3 tol.
/// Then in candidate order: the unprojected candidates before the first projected one (the
/// head) need not be projected when that one is closer than all of them by more than tol (it
/// then beats whichever of them would have been the best); otherwise the head is compared too.
std::size_t CandidateSet::select() {
  thread_local std::vector<std::size_t> by_box;
  by_box.resize(all_.size());
  for (std::size_t i = 0; i < by_box.size(); ++i) by_box[i] = i;
  std::sort(by_box.begin(), by_box.end(), [&](std::size_t a, std::size_t b) { return all_[a].box < all_[b].box; });
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i : by_box) {
    if (all_[i].box - slack_ > closest + 3 * tol_) break;  // and so are all that follow
    if (!beyond(i, closest + 2 * tol_)) closest = std::min(closest, projected(i).distance);
  }
  std::size_t first = 0;  // the first projected candidate
  double head_bound = std::numeric_limits<double>::infinity();
  while (!all_[first].projected) head_bound = std::min(head_bound, all_[first++].bound);
  std::size_t ib = first;
  if (first > 0 && !(all_[first].p.distance < head_bound - slack_ - tol_)) {
    projected(0);
    ib = select_from(0, 1, first);
    if (better(all_[first].p, all_[ib].p)) ib = first;
  }
  return select_from(ib, first + 1, all_.size());
}

Vec3 CandidateSet::shared_normal(const Projection& best) {
  Vec3 nbar{};
  for (std::size_t i = 0; i < all_.size(); ++i) {
    if (beyond(i, best.distance)) continue;
    const Projection& q = projected(i);
    if (std::abs(q.distance - best.distance) <= tol_ && norm(sub(q.x_master, best.x_master)) <= tol_)
      nbar = add(nbar, q.facet_normal);
  }
  return nbar;
}

}  // namespace

namespace {

/// The chosen projection `best` finished: its shared normal from n̄ (the facet normals of the
/// candidates sharing its point), and on an edge or vertex the normal and gap of the distance.
Projection finish(Projection best, const Vec3& nbar, double tol, const Vec3& xs, const Facet& f) {
  const double len = norm(nbar);
  const int dim = facet_param_dim(f.shape) == 1 ? 2 : 3;
  const Vec3 r = sub(xs, best.x_master);
  best.shared_normal = len > 0 ? scale(1.0 / len, nbar) : best.facet_normal;
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

}  // namespace

Projection closest_projection(std::span<const Facet> facets, std::span<const std::int32_t> candidates,
                              std::span<const Vec3> x, const Vec3& xs, const ProjectionHint* hint,
                              std::span<const FacetBox> boxes, ClosestMargin* margin, const Projection* known) {
  if (candidates.empty()) return {};
  thread_local std::vector<Candidate> storage;  // (no allocation per point)
  CandidateSet set(facets, candidates, x, xs, hint, boxes, storage, known);
  const Projection best = set.projected(set.select());
  const Vec3 nbar = set.shared_normal(best);
  if (margin) *margin = {set.others_bound(best.facet), set.slack()};
  return finish(best, nbar, set.tol(), xs, facets[static_cast<std::size_t>(best.facet)]);
}

Projection sole_projection(std::span<const Facet> facets, std::int32_t index, std::span<const Vec3> x, const Vec3& xs,
                           const ProjectionHint* hint, double tol, Projection* raw) {
  const Facet& f = facets[static_cast<std::size_t>(index)];
  const Projection best = project_to_facet(f, x, xs, index, hint && hint->facet == index ? &hint->xi : nullptr);
  if (raw) *raw = best;
  return finish(best, add(Vec3{}, best.facet_normal), tol, xs, f);
}

}  // namespace inpact::contact
