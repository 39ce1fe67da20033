#include "analytical_pair.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/rigid_motion.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

constexpr double kOverlapCosine = 0.7071;

/// The rigid body carrying analytical surface `index`.
const model::RigidBody& carrier(const model::Model& m, const model::Surface& s) {
  for (const model::RigidBody& b : m.rigid_bodies)
    if (s.kind == model::Surface::Kind::Analytical && b.analytical_surface == s.analytical) return b;
  throw std::invalid_argument("surface '" + s.name + "' is not an analytical surface of a *RIGID BODY");
}

/// Q v from Q's columns.
Vec3 turn(const std::array<Vec3, 3>& q, const Vec3& v) {
  return add(add(scale(v[0], q[0]), scale(v[1], q[1])), scale(v[2], q[2]));
}
/// Qᵀ v.
Vec3 turn_back(const std::array<Vec3, 3>& q, const Vec3& v) { return {dot(q[0], v), dot(q[1], v), dot(q[2], v)}; }

/// Position of `row` in `nodes`, appended when absent.
std::size_t slot(std::vector<std::int32_t>& nodes, std::int32_t row) {
  const auto it = std::find(nodes.begin(), nodes.end(), row);
  if (it != nodes.end()) return static_cast<std::size_t>(it - nodes.begin());
  nodes.push_back(row);
  return nodes.size() - 1;
}

}  // namespace

AnalyticalPair::AnalyticalPair(const model::Model& model, const model::Surface& slave, const model::Surface& master,
                               int dim, double out_of_plane_thickness, bool surface_to_surface)
    : PairKinematics(model, slave, master, dim, out_of_plane_thickness), surface_to_surface_(surface_to_surface) {
  const model::RigidBody& body = carrier(model, master);
  shape_ = AnalyticalShape::build(model.analytical_surfaces.at(static_cast<std::size_t>(master.analytical)), dim);
  ref_ = body.ref_node;
  rot_ = body.rot_node;
  ref_X_ = model.mesh.nodes.coords[static_cast<std::size_t>(ref_)];
  rot_X_ = model.mesh.nodes.coords[static_cast<std::size_t>(rot_)];
}

void AnalyticalPair::place(std::span<const Vec3> x) {
  x_R_ = x[static_cast<std::size_t>(ref_)];
  const Vec3& xr = x[static_cast<std::size_t>(rot_)];
  theta_ = dim_ == 3 ? sub(xr, rot_X_) : Vec3{xr[0] - rot_X_[0], 0.0, 0.0};
  for (int k = 0; k < 3; ++k) {
    Vec3 e{0, 0, 0};
    e[static_cast<std::size_t>(k)] = 1.0;
    Q_[static_cast<std::size_t>(k)] = add(e, model::rigid_motion(theta_, e, dim_, true).offset);
  }
}

ShapePoint AnalyticalPair::measure(const Vec3& xs, Vec3& r, double extension) const {
  ShapePoint sp = shape_.closest(add(ref_X_, turn_back(Q_, sub(xs, x_R_))), extension);
  r = sub(sp.x, ref_X_);
  sp.x = add(x_R_, turn(Q_, r));
  sp.n = turn(Q_, sp.n);
  sp.surface_n = turn(Q_, sp.surface_n);
  // H → Q H Qᵀ.
  std::array<double, 9> h{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) h[3 * i + j] += Q_[a][i] * sp.hessian[3 * a + b] * Q_[b][j];
  sp.hessian = h;
  return sp;
}

void AnalyticalPair::point_gradient(const ShapePoint& sp, const Vec3& r, std::span<double> out) const {
  const std::size_t d = static_cast<std::size_t>(dim_);
  const model::RigidMotion motion = model::rigid_motion(theta_, r, dim_, true);
  for (std::size_t c = 0; c < d; ++c) {
    out[c] = sp.n[c];
    out[d + c] = -sp.n[c];
    out[2 * d + c] = 0.0;
  }
  const int n_rot = dim_ == 3 ? 3 : 1;
  for (int k = 0; k < n_rot; ++k) out[2 * d + static_cast<std::size_t>(k)] = -dot(motion.d_dtheta[k], sp.n);
}

void AnalyticalPair::update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) {
  place(x);
  if (surface_to_surface_) update_weighted(x, out);
  else update_nodes(x, out);
}

namespace {

Projection projection_of(const ShapePoint& sp, int dim) {
  Projection p;
  p.region = sp.corner ? ProjectionRegion::Vertex : ProjectionRegion::Interior;
  p.x_master = sp.x;
  p.distance = sp.distance;
  p.gap = sp.gap;
  p.normal = p.facet_normal = sp.n;
  tangent_basis(sp.n, dim, p.t1, p.t2);
  return p;
}

}  // namespace

void AnalyticalPair::update_nodes(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) {
  const auto areas = slave_.nodal_areas(x);
  const auto nodes = slave_.nodes();
  out.assign(nodes.size(), {});
  cache_.assign(nodes.size(), {});
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    SlaveKinematics& k = out[i];
    k.node = nodes[i];
    k.area = area_weight_ * areas[i];
    NodeCache& c = cache_[i];
    c.point = measure(x[static_cast<std::size_t>(nodes[i])], c.r, extension_zone_);
    k.found = c.point.distance <= radius_ && AnalyticalShape::faces(c.point);
    k.projection = projection_of(c.point, dim_);
  }
}

void AnalyticalPair::update_weighted(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) {
  const auto areas = slave_.nodal_areas(x);
  const auto nodes = slave_.nodes();
  const std::size_t d = static_cast<std::size_t>(dim_);
  out.assign(nodes.size(), {});
  cache_.assign(nodes.size(), {});
  std::vector<double> weight(nodes.size(), 0.0), gap(nodes.size(), 0.0);
  std::vector<Vec3> normal(nodes.size(), Vec3{0, 0, 0});
  std::vector<double> g(3 * d);
  for (const Facet& f : slave_.facets()) {
    for (const QuadPoint& q : facet_rule(f.shape, facet_is_quadratic(f.shape) ? 3 : 2)) {
      const ShapeEval e = eval_shape(f.shape, q.xi, q.eta);
      const FacetGeometry fg = facet_geometry(f, x, e);
      Vec3 r;
      const ShapePoint sp = measure(fg.x, r);
      // The point overlaps the surface where it faces it, and its face faces the surface within
      // 45° (surface_to_surface.cpp's rule: a side face meeting the interface does not).
      if (sp.distance > radius_ || !AnalyticalShape::faces(sp) || dot(fg.n, sp.n) > -kOverlapCosine) continue;
      point_gradient(sp, r, g);
      const double da = fg.jacobian * q.weight * slave_.area_factor(fg.x);
      for (int a = 0; a < f.n_nodes; ++a) {
        const std::int32_t la = slave_.local_index(f.nodes[static_cast<std::size_t>(a)]);
        const double wa = e.N[static_cast<std::size_t>(a)] * da;
        NodeCache& c = cache_[static_cast<std::size_t>(la)];
        weight[la] += wa;
        gap[la] += wa * sp.gap;
        normal[la] = axpy(wa, sp.n, normal[la]);
        // ∂g_q/∂x_b = N_b n over the facet's nodes, then the reference and rotation nodes.
        auto add_to = [&](std::int32_t row, double s, std::size_t from) {
          const std::size_t at = slot(c.nodes, row);
          c.gradient.resize(c.nodes.size() * d, 0.0);
          for (std::size_t k = 0; k < d; ++k) c.gradient[at * d + k] += s * g[from + k];
        };
        for (int b = 0; b < f.n_nodes; ++b) add_to(f.nodes[static_cast<std::size_t>(b)], wa * e.N[static_cast<std::size_t>(b)], 0);
        add_to(ref_, wa, d);
        add_to(rot_, wa, 2 * d);
      }
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    SlaveKinematics& k = out[i];
    k.node = nodes[i];
    k.area = area_weight_ * areas[i];
    NodeCache& c = cache_[i];
    c.own = measure(x[static_cast<std::size_t>(nodes[i])], c.own_r);
    const ShapePoint& own = c.own;
    k.found = weight[i] > 0.0 && norm(normal[i]) > 0.0;
    k.projection = projection_of(own, dim_);
    // The node's own closest point stays in x_master and facet_normal: what the initial contact
    // status measures a touching node by (its weighted gap is positive where the faces around
    // it open), and where friction acts (linearize(): friction_lin).
    k.friction_found = own.distance <= radius_ && AnalyticalShape::faces(own);
    if (!k.found) continue;
    for (double& v : c.gradient) v /= weight[i];
    k.projection.gap = gap[i] / weight[i];
    k.projection.normal = scale(1.0 / norm(normal[i]), normal[i]);
    tangent_basis(k.projection.normal, dim_, k.projection.t1, k.projection.t2);
  }
}

Vec3 AnalyticalPair::material_point(std::size_t local) const {
  const NodeCache& c = cache_[local];
  return add(ref_X_, surface_to_surface_ ? c.own_r : c.r);
}

void AnalyticalPair::friction_motion(std::span<const Vec3> x, std::size_t local, const Vec3& anchor, Vec3& dx,
                                     std::vector<double>& D) const {
  const std::size_t d = static_cast<std::size_t>(dim_), n = 3 * d;
  const Vec3& xs = x[static_cast<std::size_t>(slave_.nodes()[local])];
  dx = sub(xs, add(x_R_, turn(Q_, sub(anchor, ref_X_))));
  const NodeCache& c = cache_[local];
  const model::RigidMotion motion = model::rigid_motion(theta_, surface_to_surface_ ? c.own_r : c.r, dim_, true);
  D.assign(3 * n, 0.0);
  const int n_rot = dim_ == 3 ? 3 : 1;
  for (std::size_t r = 0; r < d; ++r) {
    D[r * n + r] = 1.0;
    D[r * n + d + r] = -1.0;
    for (int k = 0; k < n_rot; ++k) D[r * n + 2 * d + static_cast<std::size_t>(k)] = -motion.d_dtheta[k][r];
  }
}

void AnalyticalPair::linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const {
  const std::size_t d = static_cast<std::size_t>(dim_);
  const NodeCache& c = cache_[static_cast<std::size_t>(slave_.local_index(k.node))];
  GapLinearization& lin = k.lin;
  lin.dim = dim_;
  lin.dxi = {};
  if (surface_to_surface_) {
    lin.nodes = c.nodes;
    lin.gradient = c.gradient;
    // Friction's kinematics: the node's own point, over [x_s; u_R; θ].
    GapLinearization& f = k.friction_lin;
    f.dim = dim_;
    f.dxi = {};
    f.nodes = {k.node, ref_, rot_};
    f.n_dof = static_cast<int>(3 * d);
    f.gradient.assign(3 * d, 0.0);
    point_gradient(c.own, c.own_r, f.gradient);
    f.hessian.assign(9 * d * d, 0.0);
  } else {
    lin.nodes = {k.node, ref_, rot_};
    lin.gradient.assign(3 * d, 0.0);
    point_gradient(c.point, c.r, lin.gradient);
  }
  lin.n_dof = static_cast<int>(lin.nodes.size() * d);
  const std::size_t n = static_cast<std::size_t>(lin.n_dof);
  lin.hessian.assign(n * n, 0.0);
  lin.hessian_defined = true;
  // A corner's curvature 1/g blows up as the node reaches it: flat within 1e-3 of a facet size.
  const bool near_corner = c.point.corner && c.point.distance < 1e-3 * radius_;
  if (surface_to_surface_ || !finite_sliding || near_corner) return;
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t j = 0; j < d; ++j) {
      const double h = c.point.hessian[3 * i + j];
      lin.hessian[i * n + j] += h;
      lin.hessian[(d + i) * n + d + j] += h;
      lin.hessian[i * n + d + j] -= h;
      lin.hessian[(d + i) * n + j] -= h;
    }
}

}  // namespace inpact::contact
