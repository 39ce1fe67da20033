#include "surface_to_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "mortar_segments.hpp"
#include "parallel_for.hpp"
#include "projection_tolerance.hpp"
#include "smoothed_gap.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

/// Popp et al.'s α for the transformed quadratic basis.
constexpr double kAlpha = 0.2;

/// A point overlaps the master when the distance direction is within 45° of the master facet's
/// normal (cos 45°): beyond a free edge of the master it turns tangential; and when the slave
/// face there is within 45° of facing it (a side face meeting the interface at a corner does not).
constexpr double kOverlapCosine = 0.7071;

/// Position of node row `row` in `nodes`, appended when absent.
std::size_t slot(std::vector<std::int32_t>& nodes, std::int32_t row) {
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i] == row) return i;
  nodes.push_back(row);
  return nodes.size() - 1;
}

/// The position of node row `row` in facet `f` (it must be one of its nodes).
std::size_t local_node(const Facet& f, std::int32_t row) {
  std::size_t a = 0;
  while (f.nodes[a] != row) ++a;
  return a;
}

/// A point's unknowns expanded onto the union's nodes: (union slot, factor, point-local unknown).
struct ExpandedTerms {
  struct Term {
    std::size_t slot, local;
    double factor;
  };
  std::array<Term, 17> t;  // (at most 8 slave nodes for x_q, then 8 master nodes)
  std::size_t n = 0;
  void add(std::size_t slot, double factor, std::size_t local) { t[n++] = {slot, local, factor}; }
};

/// L.hessian += c Eᵀ ∂²g_q E for one point, E its expansion `terms`: every entry gets
/// ((c f1) f2) ∂²g_q, terms in expansion order (row, then column, then components).
void add_point_hessian(const ExpandedTerms& terms, double c, const GapLinearization& q, GapLinearization& L) {
  const std::size_t d = static_cast<std::size_t>(L.dim), nd = static_cast<std::size_t>(L.n_dof);
  const std::size_t qn = q.gradient.size();
  for (std::size_t a = 0; a < terms.n; ++a)
    for (std::size_t b = 0; b < terms.n; ++b) {
      const auto& t1 = terms.t[a];
      const auto& t2 = terms.t[b];
      const double cf = c * t1.factor * t2.factor;
      double* H = &L.hessian[t1.slot * d * nd + t2.slot * d];
      const double* Q = &q.hessian[t1.local * d * qn + t2.local * d];
      for (std::size_t i = 0; i < d; ++i)
        for (std::size_t j = 0; j < d; ++j) H[i * nd + j] += cf * Q[i * qn + j];
    }
}

}  // namespace

int plain_rule_points(FacetShape shape, bool quadratic_master) {
  if (facet_param_dim(shape) == 1) return 6;
  return facet_is_quadratic(shape) || quadratic_master ? 4 : 3;
}

std::array<double, 8> weighting_functions(FacetShape shape, const std::array<double, 8>& N) {
  if (shape != FacetShape::Tri6 && shape != FacetShape::Quad8) return N;
  const int nc = facet_n_corners(shape);
  std::array<double, 8> W{};
  for (int m = 0; m < nc; ++m) {
    const double nm = N[static_cast<std::size_t>(nc + m)];  // midside m lies between corners m and m+1
    W[static_cast<std::size_t>(nc + m)] = (1 - 2 * kAlpha) * nm;
    W[static_cast<std::size_t>(m)] += kAlpha * nm;
    W[static_cast<std::size_t>((m + 1) % nc)] += kAlpha * nm;
  }
  for (int c = 0; c < nc; ++c) W[static_cast<std::size_t>(c)] += N[static_cast<std::size_t>(c)];
  return W;
}

SurfaceToSurfacePair::SurfaceToSurfacePair(const model::Model& model, const model::Surface& slave, const model::Surface& master, int dim,
                                           double out_of_plane_thickness)
    : PairKinematics(model, slave, master, dim, out_of_plane_thickness) {
  if (slave_.node_based())
    throw std::invalid_argument("surface-to-surface contact needs an element-based slave surface; '" + slave_.name() +
                                "' is node based (use TYPE=NODE TO SURFACE)");
  points_.resize(slave_.facets().size());
  node_area_ = slave_.nodal_areas(reference_coordinates(model.mesh.nodes));
}

void SurfaceToSurfacePair::update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) {
  refresh_search(x);
  const auto facets = slave_.facets();
  const auto nodes = slave_.nodes();
  out.assign(nodes.size(), {});
  facet_boxes(master_.facets(), x, master_boxes_);
  centre_normals(master_.facets(), x, master_normals_);
  track_master_motion(x);
  // A measured node needs every facet around it (set_measured_nodes).
  const std::vector<char> facet_measured =
      measured_.empty() ? std::vector<char>(facets.size(), 1) : facets_around(measured_);
  parallel_for(facets.size(), threads_, 2, [&](std::size_t fi) {
    if (facet_measured[fi]) measure_facet(x, fi);
  });
  // The sums over each node's points, facet after facet and point after point: the same order
  // whatever the thread count, so the same bits.
  std::vector<double> weighted_gap(nodes.size(), 0.0);
  std::vector<Vec3> weighted_normal(nodes.size(), Vec3{});
  for (std::size_t fi = 0; fi < facets.size(); ++fi) {
    if (!facet_measured[fi]) continue;
    const Facet& f = facets[fi];
    for (const Point& pt : points_[fi]) {
      if (!pt.overlaps) continue;
      for (int a = 0; a < f.n_nodes; ++a) {
        const auto i = static_cast<std::size_t>(slave_.local_index(f.nodes[a]));
        const double w = pt.W[static_cast<std::size_t>(a)] * pt.da;
        out[i].area += w;
        weighted_gap[i] += w * pt.projection.gap;
        weighted_normal[i] = axpy(w, pt.projection.normal, weighted_normal[i]);
      }
    }
  }
  parallel_for(nodes.size(), threads_, 32, [&](std::size_t i) {
    SlaveKinematics& k = out[i];
    k.node = nodes[i];
    if (!measures(i)) return;  // (unfound)
    project_node(x, k);
    const double len = norm(weighted_normal[i]);
    k.found = k.area > 0.0 && len > 0.0;
    if (!k.found) {
      k.area = 0.0;
      return;
    }
    k.projection.gap = weighted_gap[i] / k.area;
    if (node_area_[i] > 0.0) k.overlap = std::min(1.0, k.area / node_area_[i]);
    k.area *= area_weight_;
    k.projection.normal = scale(1.0 / len, weighted_normal[i]);
    tangent_basis(k.projection.normal, dim_, k.projection.t1, k.projection.t2);
  });
}

std::span<const QuadPoint> SurfaceToSurfacePair::facet_points(std::span<const Vec3> x, const Facet& f) const {
  thread_local std::vector<std::int32_t> near;
  thread_local std::vector<QuadPoint> layout;
  const FacetBox box = facet_box(f, x);
  near.clear();
  search_.query_box(box.lo, box.hi, near);
  if (self_contact_) drop_neighbours(master_.facets(), f.node_rows(), near);
  const bool quadratic_master = std::any_of(near.begin(), near.end(), [&](std::int32_t m) {
    return facet_is_quadratic(master_.facets()[static_cast<std::size_t>(m)].shape);
  });
  const int plain = plain_rule_points(f.shape, quadratic_master);
  bool ambiguous = false;
  if (mortar_rule(f, master_.facets(), near, x, plain, layout, master_normals_, &ambiguous)) return layout;
  return facet_rule(f.shape, ambiguous ? kAmbiguousRulePoints : plain);
}

void SurfaceToSurfacePair::measure_facet(std::span<const Vec3> x, std::size_t fi) {
  const Facet& f = slave_.facets()[fi];
  const auto rule = facet_points(x, f);
  auto& pts = points_[fi];
  if (pts.size() != rule.size()) relayout(pts, rule);
  for (std::size_t q = 0; q < rule.size(); ++q) {
    Point& pt = pts[q];
    if (pt.param[0] == rule[q].xi && pt.param[1] == rule[q].eta) continue;
    pt.param = {rule[q].xi, rule[q].eta};
    pt.N = eval_shape(f.shape, rule[q].xi, rule[q].eta).N;
    pt.W = weighting_functions(f.shape, pt.N);
  }
  thread_local std::vector<std::int32_t> candidates;
  for (std::size_t q = 0; q < rule.size(); ++q) {
    Point& pt = pts[q];
    // The point on the slave's idealised surface (its own where none applies), and the facet's
    // own geometry there, which the area element is of.
    FacetGeometry g;
    const CorrectedPoint c = slave_correction_.correct(f, {rule[q].xi, rule[q].eta}, x, &g);
    pt.da = rule[q].weight * g.jacobian * slave_.area_factor(g.x);
    g.x = c.x;
    g.n = c.normal;
    pt.x = g.x;
    pt.lin_valid = pt.smoothed_valid = false;
    pt.projection = search_point(x, f, g, pt, candidates);
    const Projection& pr = pt.projection;
    pt.hint = {pr.region == ProjectionRegion::Interior && pr.converged ? pr.facet : -1, pr.xi};
    // (judged on the faceted projection: beyond the master's free edge the idealised one
    // would look orthogonal too)
    pt.overlaps = pr.facet >= 0 && dot(g.n, pr.normal) <= -kOverlapCosine && projects_orthogonally(pr);
    if (!pt.overlaps) continue;
    pt.master_corrected = correct_master(x, g.x, pt.projection, &pt.ray_memo);
  }
}

/// Another layout of a facet's points (a master edge moved across it): each new point starts
/// from the state of the old point nearest to it on the facet (its faceted hint and its search
/// memo). The memo stays valid: it holds where that point was, and reproject() bounds the new
/// point's distance from there like any motion. The ray memo is not carried: started from
/// another point's ξ and Jacobian, rays that end on a facet's edge end elsewhere on it (the
/// default job's CPRESS then moved by 6e-7 of its largest, against 1e-10 without).
void SurfaceToSurfacePair::relayout(std::vector<Point>& pts, std::span<const QuadPoint> rule) {
  thread_local std::vector<Point> old;
  old.swap(pts);
  pts.assign(rule.size(), Point{});  // (a cold ray from each point's faceted ξ: see above)
  if (old.empty()) return;
  for (std::size_t q = 0; q < rule.size(); ++q) {
    auto distance2 = [&](const Point& o) {
      const double d0 = o.param[0] - rule[q].xi, d1 = o.param[1] - rule[q].eta;
      return d0 * d0 + d1 * d1;
    };
    const auto nearest = std::min_element(old.begin(), old.end(),
                                          [&](const Point& a, const Point& b) { return distance2(a) < distance2(b); });
    pts[q].hint = nearest->hint;
    pts[q].memo = nearest->memo;
  }
  old.clear();  // (their linearisations' storage goes now, not when the thread ends)
}

Projection SurfaceToSurfacePair::search_point(std::span<const Vec3> x, const Facet& f, const FacetGeometry& g, Point& pt,
                                              std::vector<std::int32_t>& candidates) const {
  Projection memo_facet;  // (its projection, when reproject() made one: not made again)
  if (reproject(x, f, g, pt, memo_facet)) return pt.projection;
  candidates.clear();
  search_.query(g.x, candidates);
  if (self_contact_) drop_neighbours(master_.facets(), f.node_rows(), candidates);
  ClosestMargin margin;
  Projection p = closest_projection(master_.facets(), candidates, x, g.x, pt.hint.facet >= 0 ? &pt.hint : nullptr,
                                    master_boxes_, &margin, memo_facet.facet >= 0 ? &memo_facet : nullptr);
  // (a facet left out of the candidates lies beyond the search radius, or is the point's own
  // neighbour in self contact, which never competes)
  pt.memo = {p.facet, std::min(margin.others, search_radius()) - margin.slack, g.x, master_shift_, master_motion_,
             memo_generation_};
  if (p.facet >= 0 && dot(g.n, p.normal) > -kOverlapCosine) {
    project_onto_facing(x, g, candidates, p);
    pt.memo.facet = -1;  // (p is no longer the closest facet's)
  }
  return p;
}

/// Since the memo, the point moved |x − memo.x| and no master facet point more than the motion
/// added to master_motion_, so no other facet is closer than memo.others less both. When that
/// still exceeds the memo facet's distance now by the search's tolerances (bounded above by
/// those of the largest master facet and coordinate), the search would choose the memo facet
/// alone, and project onto it just as sole_projection() does. A point whose projection does not
/// face it is searched again (project_onto_facing() needs the candidates).
bool SurfaceToSurfacePair::reproject(std::span<const Vec3> x, const Facet& f, const FacetGeometry& g, Point& pt,
                                     Projection& raw) const {
  raw = {};
  const Point::SearchMemo& m = pt.memo;
  if (m.facet < 0) return false;
  if (m.generation != memo_generation_) return false;
  const double drift = norm(sub(sub(g.x, m.x), sub(master_shift_, m.shift))) + (master_motion_ - m.motion);
  const double tol = on_surface_tol(largest_master_facet_);
  const double slack = tol + 1e-12 * std::max({master_magnitude_, std::abs(g.x[0]), std::abs(g.x[1]), std::abs(g.x[2])});
  const double others = m.others - drift - slack;
  if (!(others > 2 * tol)) return false;
  const Projection p =
      sole_projection(master_.facets(), m.facet, x, g.x, pt.hint.facet >= 0 ? &pt.hint : nullptr, tol, &raw);
  // (beyond tol the search's own tolerance, whatever it is now, leaves the normal unaveraged)
  if (!(p.distance > tol && others > p.distance + tol) || dot(g.n, p.normal) > -kOverlapCosine) return false;
  if (projection_self_check) {  // (tests: the search's own answer, to the bit)
    Point searched = pt;
    searched.memo.facet = -1;
    std::vector<std::int32_t> candidates;
    const Projection full = search_point(x, f, g, searched, candidates);
    auto same = [](const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    const bool equal = full.facet == p.facet && same(full.xi, p.xi) && full.region == p.region &&
                       same(full.x_master, p.x_master) && same(full.distance, p.distance) && same(full.gap, p.gap) &&
                       same(full.normal, p.normal) && same(full.facet_normal, p.facet_normal) &&
                       same(full.shared_normal, p.shared_normal) && same(full.t1, p.t1) && same(full.t2, p.t2) &&
                       full.converged == p.converged && full.extended == p.extended;
    if (!equal)
      throw std::logic_error("surface to surface: a kept projection differs from the search's");
  }
  pt.projection = p;
  return true;
}

void SurfaceToSurfacePair::track_master_motion(std::span<const Vec3> x) {
  const auto rows = master_.nodes();
  const bool first = master_x_.size() != rows.size();
  master_x_.resize(rows.size());
  // The shift: the middle of the nodes' displacements, component by component; the motion
  // beyond it, the largest distance of a node's displacement from it.
  Vec3 lo{}, hi{};
  for (std::size_t i = 0; i < rows.size() && !first; ++i) {
    const Vec3 d = sub(x[static_cast<std::size_t>(rows[i])], master_x_[i]);
    for (int k = 0; k < 3; ++k) {
      lo[k] = i == 0 ? d[k] : std::min(lo[k], d[k]);
      hi[k] = i == 0 ? d[k] : std::max(hi[k], d[k]);
    }
  }
  const Vec3 shift = scale(0.5, add(lo, hi));
  double largest = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Vec3& now = x[static_cast<std::size_t>(rows[i])];
    const double d = norm(sub(sub(now, master_x_[i]), shift));
    if (!(d <= largest)) largest = d;  // (a NaN stays, and drops every memo below)
    master_x_[i] = now;
  }
  master_shift_ = add(master_shift_, shift);
  bool quadratic = false;
  largest_master_facet_ = master_magnitude_ = 0.0;
  for (std::size_t i = 0; i < master_boxes_.size(); ++i) {
    quadratic = quadratic || facet_is_quadratic(master_.facets()[i].shape);
    largest_master_facet_ = std::max(largest_master_facet_, std::sqrt(master_boxes_[i].size2));
    for (int k = 0; k < 3; ++k)
      master_magnitude_ = std::max({master_magnitude_, std::abs(master_boxes_[i].lo[k]), std::abs(master_boxes_[i].hi[k])});
  }
  if (first) return;
  if (!std::isfinite(largest) || !std::isfinite(norm(shift))) {  // (NaN coordinates: no memo holds)
    master_motion_ = 0.0;
    master_shift_ = {};
    ++memo_generation_;
    return;
  }
  master_motion_ += (quadratic ? 3.0 : 1.0) * largest;
}

/// A point that has gone into the other body near one of its edges can lie closer to a side
/// face than to the face it went through (general contact's bodies have both): the closest
/// master facet that faces the point then replaces the closest one, when the point lies behind
/// it by less than half its size (a penetration, not the far side of the body: a thin strip's
/// upper face must not find the bottom of the block it rests on). Otherwise `p` stays.
void SurfaceToSurfacePair::project_onto_facing(std::span<const Vec3> x, const FacetGeometry& g,
                                               std::span<const std::int32_t> candidates, Projection& p) const {
  thread_local std::vector<std::int32_t> facing;
  facing.clear();
  for (std::int32_t c : candidates)
    if (dot(g.n, master_normals_[static_cast<std::size_t>(c)]) <= -kOverlapCosine) facing.push_back(c);
  if (facing.empty()) return;
  const Projection q = closest_projection(master_.facets(), facing, x, g.x, nullptr, master_boxes_);
  if (q.facet < 0 || q.region != ProjectionRegion::Interior || dot(g.n, q.normal) > -kOverlapCosine) return;
  const double half_size2 = 0.25 * master_boxes_[static_cast<std::size_t>(q.facet)].size2;
  if (q.gap < 0.0 && q.gap * q.gap < half_size2) p = q;
}

/// The slave node's own closest-point projection (for friction), kept in k.projection's facet,
/// ξ and master point; the gap and normal are overwritten with the weighted ones by update().
void SurfaceToSurfacePair::project_node(std::span<const Vec3> x, SlaveKinematics& k) const {
  thread_local std::vector<std::int32_t> candidates;
  candidates.clear();
  search_.query(x[static_cast<std::size_t>(k.node)], candidates);
  const std::int32_t own[1] = {k.node};
  if (self_contact_) drop_neighbours(master_.facets(), own, candidates);
  k.projection = closest_projection(master_.facets(), candidates, x, x[static_cast<std::size_t>(k.node)], nullptr,
                                    master_boxes_);
  // Friction acts where the node itself faces the master: beyond a free edge its closest point is
  // the edge, seen sideways (the distance turns tangential), and a slip measured there runs the
  // wrong way (a node whose faces overlap the master by a sliver got μ p against the slide).
  const Projection& pr = k.projection;
  k.friction_found = pr.facet >= 0 && projects_orthogonally(pr);
  if (k.friction_found) correct_master(x, x[static_cast<std::size_t>(k.node)], k.projection);
}

void SurfaceToSurfacePair::set_geometric_correction(SurfaceCorrections master, SurfaceCorrections slave) {
  master_correction_ = std::move(master);
  slave_correction_ = std::move(slave);
}

bool SurfaceToSurfacePair::correct_master(std::span<const Vec3> x, const Vec3& xs, Projection& p, RayMemo* memo) const {
  return correct_projection(master_correction_, master_.facets(), x, xs, dim_, p, memo);
}

const GapLinearization& SurfaceToSurfacePair::point_linearization(std::span<const Vec3> x, const Point& pt,
                                                                   bool hessian) const {
  if (!pt.lin_valid || (hessian && !pt.lin_hessian)) {
    const Facet& mf = master_.facets()[static_cast<std::size_t>(pt.projection.facet)];
    pt.lin = hessian ? linearize_gap(mf, x, pt.x, pt.projection, dim_, -1) : gap_gradient(mf, pt.projection, dim_, -1);
    pt.lin_valid = true;
    pt.lin_hessian = hessian;
  }
  return pt.lin;
}

void SurfaceToSurfacePair::smoothed_point_gradient(std::span<const Vec3> x, const Facet& sf, const Point& pt) const {
  if (pt.smoothed_valid) return;
  const Facet& mf = master_.facets()[static_cast<std::size_t>(pt.projection.facet)];
  // (the point's own ξ on its facet: the layout is the facet's cut cells, or the plain rule)
  const SmoothedPoint sp{&sf, pt.param, &mf, &pt.projection, pt.x, pt.master_corrected};
  smoothed_gap_gradient(slave_correction_, master_correction_, sp, x, dim_, pt.smoothed_gradient);
  area_element_log_gradient(sf, pt.param, x, dim_, slave_.axisymmetric(), pt.log_area_gradient);
  pt.smoothed_valid = true;
}

std::vector<char> SurfaceToSurfacePair::facets_around(std::span<const char> node_mask) const {
  std::vector<char> around(slave_.facets().size(), 0);
  for (std::size_t i = 0; i < node_mask.size(); ++i)
    if (node_mask[i])
      for (std::int32_t fi : slave_.facets_of_node(i)) around[static_cast<std::size_t>(fi)] = 1;
  return around;
}

void SurfaceToSurfacePair::fill_point_caches(std::span<const Vec3> x, std::size_t fi, std::span<const char> linearised,
                                             bool finite_sliding) const {
  const Facet& sf = slave_.facets()[fi];
  std::array<bool, 8> node_linearised{};
  for (int a = 0; a < sf.n_nodes; ++a)
    node_linearised[static_cast<std::size_t>(a)] =
        linearised[static_cast<std::size_t>(slave_.local_index(sf.nodes[static_cast<std::size_t>(a)]))] != 0;
  for (const Point& pt : points_[fi]) {
    if (!pt.overlaps) continue;
    bool weighed = false;
    for (int a = 0; a < sf.n_nodes && !weighed; ++a)
      weighed = node_linearised[static_cast<std::size_t>(a)] && pt.W[static_cast<std::size_t>(a)] * pt.da != 0.0;
    if (!weighed) continue;
    if (smoothed()) smoothed_point_gradient(x, sf, pt);
    else point_linearization(x, pt, finite_sliding);
  }
}

void SurfaceToSurfacePair::prepare_linearization(std::span<const Vec3> x, std::span<const std::size_t> nodes,
                                                 bool finite_sliding) {
  std::vector<char> linearised(slave_.nodes().size(), 0);
  for (std::size_t i : nodes) linearised[i] = 1;
  const std::vector<char> around = facets_around(linearised);
  std::vector<std::size_t> facets;
  for (std::size_t fi = 0; fi < around.size(); ++fi)
    if (around[fi]) facets.push_back(fi);
  parallel_for(facets.size(), threads_, 2, [&](std::size_t n) { fill_point_caches(x, facets[n], linearised, finite_sliding); });
}

void SurfaceToSurfacePair::linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const {
  GapLinearization& L = k.lin;
  L = {};
  L.dim = dim_;
  if (k.friction_found) {
    // Friction's kinematics: the node against the facet it projects onto (node to surface).
    // (k.projection holds the node's own facet and ξ with the weighted normal: friction's tangent plane.)
    const Facet& f = master_.facets()[static_cast<std::size_t>(k.projection.facet)];
    k.friction_lin = linearize_gap(f, x, x[static_cast<std::size_t>(k.node)], k.projection, dim_, k.node);
  }
  if (!k.found) return;
  if (smoothed()) return linearize_smoothed(x, k);
  const auto local = static_cast<std::size_t>(slave_.local_index(k.node));
  const auto facets = slave_.facets();
  const std::size_t d = static_cast<std::size_t>(dim_);
  gather_nodes(local, L);
  std::vector<std::size_t> map;  // point-local node (0: the point x_q, then master facet nodes) → union slot
  for (std::int32_t fi : slave_.facets_of_node(local)) {
    const Facet& sf = facets[static_cast<std::size_t>(fi)];
    int a_local = 0;
    while (sf.nodes[static_cast<std::size_t>(a_local)] != k.node) ++a_local;
    std::array<std::size_t, 8> slave_slot{};
    for (int b = 0; b < sf.n_nodes; ++b) slave_slot[static_cast<std::size_t>(b)] = slot(L.nodes, sf.nodes[static_cast<std::size_t>(b)]);
    for (const Point& pt : points_[static_cast<std::size_t>(fi)]) {
      if (!pt.overlaps) continue;
      const double c = pt.W[static_cast<std::size_t>(a_local)] * pt.da * area_weight_ / k.area;
      if (c == 0.0) continue;
      const Facet& mf = master_.facets()[static_cast<std::size_t>(pt.projection.facet)];
      const GapLinearization& q = point_linearization(x, pt, finite_sliding && !smoothed());
      // The point's unknowns: x_q (slot 0, = Σ_b N_b x_b over the slave facet), then mf's nodes.
      const std::size_t nq = static_cast<std::size_t>(mf.n_nodes) + 1;
      map.assign(nq, 0);
      for (std::size_t m = 1; m < nq; ++m) map[m] = slot(L.nodes, mf.nodes[m - 1]);
      // Expanded: each point-local unknown as a list of (union slot, factor).
      auto expand = [&](std::size_t m, auto&& fn) {
        if (m == 0) {
          for (int b = 0; b < sf.n_nodes; ++b)
            if (const double nb = pt.N[static_cast<std::size_t>(b)]; nb != 0.0) fn(slave_slot[static_cast<std::size_t>(b)], nb);
        } else {
          fn(map[m], 1.0);
        }
      };
      for (std::size_t m = 0; m < nq; ++m)
        expand(m, [&](std::size_t s, double f) {
          for (std::size_t i = 0; i < d; ++i) L.gradient[s * d + i] += c * f * q.gradient[m * d + i];
        });
      const bool corner = pt.projection.region != ProjectionRegion::Interior && pt.projection.distance < 1e-3 * radius_;
      if (!finite_sliding || corner || !q.hessian_defined || smoothed()) continue;
      ExpandedTerms terms;
      for (std::size_t m = 0; m < nq; ++m) expand(m, [&](std::size_t s, double f) { terms.add(s, f, m); });
      add_point_hessian(terms, c, q, L);
    }
  }
}

void SurfaceToSurfacePair::gather_nodes(std::size_t local, GapLinearization& L) const {
  // The nodes involved: the slave facets around the node, their points' master facets.
  for (std::int32_t fi : slave_.facets_of_node(local)) {
    const Facet& sf = slave_.facets()[static_cast<std::size_t>(fi)];
    for (std::int32_t r : sf.node_rows()) slot(L.nodes, r);
    for (const Point& pt : points_[static_cast<std::size_t>(fi)])
      if (pt.overlaps)
        for (std::int32_t r : master_.facets()[static_cast<std::size_t>(pt.projection.facet)].node_rows()) slot(L.nodes, r);
  }
  L.n_dof = static_cast<int>(L.nodes.size() * static_cast<std::size_t>(dim_));
  const std::size_t nd = static_cast<std::size_t>(L.n_dof);
  L.gradient.assign(nd, 0.0);
  L.hessian.assign(nd * nd, 0.0);
}

void SurfaceToSurfacePair::linearize_smoothed(std::span<const Vec3> x, SlaveKinematics& k) const {
  // g = Σ_q c_q g_q with c_q = W_q da_q / Σ W da over the points of the node's facets:
  //   ∂g = Σ_q c_q ∂g_q + Σ_q c_q (g_q − g) ∂(ln da_q).
  GapLinearization& L = k.lin;
  const auto local = static_cast<std::size_t>(slave_.local_index(k.node));
  const auto facets = slave_.facets();
  const std::size_t d = static_cast<std::size_t>(dim_);
  gather_nodes(local, L);
  // The node's own weighted gap (without the pair's offsets, which update()'s caller adds).
  double sum_w = 0.0, sum_wg = 0.0;
  for (std::int32_t fi : slave_.facets_of_node(local)) {
    const Facet& sf = facets[static_cast<std::size_t>(fi)];
    const std::size_t a = local_node(sf, k.node);
    for (const Point& pt : points_[static_cast<std::size_t>(fi)])
      if (pt.overlaps) {
        sum_w += pt.W[a] * pt.da;
        sum_wg += pt.W[a] * pt.da * pt.projection.gap;
      }
  }
  if (!(sum_w > 0.0)) return;
  const double g_node = sum_wg / sum_w;
  for (std::int32_t fi : slave_.facets_of_node(local)) {
    const Facet& sf = facets[static_cast<std::size_t>(fi)];
    const std::size_t a = local_node(sf, k.node);
    std::array<std::size_t, 8> slave_slot{};
    for (int b = 0; b < sf.n_nodes; ++b) slave_slot[static_cast<std::size_t>(b)] = slot(L.nodes, sf.nodes[static_cast<std::size_t>(b)]);
    const auto& pts = points_[static_cast<std::size_t>(fi)];
    for (std::size_t q = 0; q < pts.size(); ++q) {
      const Point& pt = pts[q];
      if (!pt.overlaps) continue;
      const double c = pt.W[a] * pt.da / sum_w;
      if (c == 0.0) continue;
      const Facet& mf = master_.facets()[static_cast<std::size_t>(pt.projection.facet)];
      smoothed_point_gradient(x, sf, pt);  // (once per point after an update(), for every node of the facet)
      const std::vector<double>& grad = pt.smoothed_gradient;
      const std::vector<double>& dlnda = pt.log_area_gradient;
      const double cw = c * (pt.projection.gap - g_node);
      const std::size_t ns = sf.n_nodes;
      for (std::size_t b = 0; b < ns; ++b)
        for (std::size_t j = 0; j < d; ++j)
          L.gradient[slave_slot[b] * d + j] += c * grad[b * d + j] + cw * dlnda[b * d + j];
      for (std::size_t m = 0; m < static_cast<std::size_t>(mf.n_nodes); ++m) {
        const std::size_t s = slot(L.nodes, mf.nodes[m]);
        for (std::size_t j = 0; j < d; ++j) L.gradient[s * d + j] += c * grad[(ns + m) * d + j];
      }
    }
  }
}

}  // namespace inpact::contact
