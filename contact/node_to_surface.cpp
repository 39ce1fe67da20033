#include "node_to_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vec3.hpp"

namespace inpact::contact {

NodeToSurfacePair::NodeToSurfacePair(const model::Model& model, const model::Surface& slave, const model::Surface& master, int dim,
                                     double out_of_plane_thickness)
    : PairKinematics(model, slave, master, dim, out_of_plane_thickness) {}

void NodeToSurfacePair::update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) {
  refresh_search(x);
  const auto areas = slave_.nodal_areas(x);
  const auto nodes = slave_.nodes();
  out.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    SlaveKinematics& k = out[i];
    k.node = nodes[i];
    if (!measures(i)) {
      k.found = false;
      continue;
    }
    k.area = area_weight_ * areas[i];
    candidates_.clear();
    search_.query(x[nodes[i]], candidates_);
    const std::int32_t own[1] = {nodes[i]};
    if (self_contact_) drop_neighbours(master_.facets(), own, candidates_);
    k.projection = closest_projection(master_.facets(), candidates_, x, x[nodes[i]]);
    k.found = k.projection.facet >= 0 && (!at_free_edge(k.projection) || extend_master(x, x[nodes[i]], k.projection));
    if (k.found && self_contact_) {
      // The node's outward normal: the sum of its facets' normals there.
      Vec3 n{};
      for (std::int32_t f : slave_.facets_of_node(i)) {
        const Facet& sf = slave_.facets()[static_cast<std::size_t>(f)];
        for (int a = 0; a < sf.n_nodes; ++a)
          if (sf.nodes[static_cast<std::size_t>(a)] == nodes[i]) {
            const auto xi = facet_node_param(sf.shape, a);
            n = add(n, facet_geometry(sf, x, xi[0], xi[1]).n);
          }
      }
      const double len = norm(n);
      k.found = len > 0.0 && faces_across(scale(1.0 / len, n), k.projection);
    }
    if (k.found && !master_correction_.empty()) correct(x, i, k.projection);
  }
}

bool NodeToSurfacePair::at_free_edge(const Projection& p) {
  constexpr double kSameNormal = 1.0 - 1e-9;
  return p.region != ProjectionRegion::Interior && dot(p.shared_normal, p.facet_normal) >= kSameNormal;
}

bool NodeToSurfacePair::extend_master(std::span<const Vec3> x, const Vec3& xs, Projection& p) const {
  const Facet& f = master_.facets()[static_cast<std::size_t>(p.facet)];
  const Vec3 r = sub(xs, p.x_master);
  const double gap = dot(r, p.facet_normal);
  const double beside = norm(axpy(-gap, p.facet_normal, r));
  if (beside > extension_zone_ * std::sqrt(facet_box(f, x).size2)) return false;
  p.normal = p.facet_normal;
  p.gap = gap;
  p.extended = true;
  tangent_basis(p.normal, dim_, p.t1, p.t2);
  return true;
}

void NodeToSurfacePair::set_geometric_correction(SurfaceCorrections master, SurfaceCorrections slave) {
  master_correction_ = std::move(master);
  slave_correction_ = std::move(slave);
}

void NodeToSurfacePair::correct(std::span<const Vec3> x, std::size_t slave, Projection& p) const {
  const std::int32_t node = slave_.nodes()[slave];
  Vec3 xs = x[node];
  // The slave node on its idealised surface: itself, up to rounding.
  if (const auto fs = slave_.facets_of_node(slave); !slave_correction_.empty() && !fs.empty()) {
    const Facet& sf = slave_.facets()[static_cast<std::size_t>(fs.front())];
    for (int a = 0; a < sf.n_nodes; ++a)
      if (sf.nodes[a] == node) xs = slave_correction_.correct(sf, facet_node_param(sf.shape, a), x).x;
  }
  correct_projection(master_correction_, master_.facets(), x, xs, dim_, p);
}

void NodeToSurfacePair::linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const {
  const Facet& f = master_.facets()[static_cast<std::size_t>(k.projection.facet)];
  k.lin = linearize_gap(f, x, x[k.node], k.projection, dim_, k.node);
  // At a facet edge or vertex the gap is a distance to a point, whose curvature 1/d blows up
  // as the slave node reaches the surface (a closed node sits there): within 1e-3 of a facet
  // size of it, the corner is taken as flat (no curvature term), as away from corners.
  // On the extended plane beyond a free edge the gap is not a distance to the edge: no
  // curvature either.
  const bool corner_contact = k.projection.region != ProjectionRegion::Interior &&
                              (k.projection.distance < 1e-3 * radius_ || k.projection.extended);
  if (!finite_sliding || corner_contact || !master_correction_.empty())
    std::fill(k.lin.hessian.begin(), k.lin.hessian.end(), 0.0);
}

}  // namespace inpact::contact
