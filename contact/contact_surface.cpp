#include "contact_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "model/mesh_queries.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

std::string where(const model::Surface& s) { return "contact surface '" + s.name + "'"; }

}  // namespace

ContactSurface ContactSurface::build(const model::Model& model, const model::Surface& surface,
                                     const SurfaceOptions& options) {
  ContactSurface cs;
  cs.name_ = surface.name;
  cs.thickness_ = options.out_of_plane_thickness;
  if (surface.kind == model::Surface::Kind::Node) {
    cs.set_nodes(model.mesh.elements, surface);
    return cs;
  }
  cs.add_facets(model.mesh.elements, surface);
  cs.index_node_facets();
  return cs;
}

void ContactSurface::set_nodes(const model::Elements& elements, const model::Surface& surface) {
  node_based_ = true;
  // The dimension of the model's elements (3 when there are none or any is 3D).
  dim_ = 3;
  if (elements.size() > 0) {
    dim_ = 2;
    for (std::size_t e = 0; e < elements.size(); ++e)
      if (model::element_type(elements.type[e]).dim == 3) dim_ = 3;
  }
  std::vector<std::pair<std::int32_t, double>> rows;
  for (std::size_t i = 0; i < surface.nodes.size(); ++i)
    rows.emplace_back(surface.nodes[i], i < surface.node_areas.size() ? surface.node_areas[i] : 1.0);
  std::sort(rows.begin(), rows.end());
  for (const auto& [row, area] : rows) {
    if (!nodes_.empty() && nodes_.back() == row) continue;  // first area given wins
    nodes_.push_back(row);
    given_areas_.push_back(area);
  }
  node_facet_ptr_.assign(nodes_.size() + 1, 0);
}

void ContactSurface::add_facets(const model::Elements& elements, const model::Surface& surface) {
  bool first = true;
  for (const model::Face& face : surface.faces) {
    const model::ElementTypeInfo& info = model::element_type(elements.type[static_cast<std::size_t>(face.element)]);
    if (face.face >= info.faces.size())
      throw std::invalid_argument(where(surface) + ": element face S" + std::to_string(face.face + 1) +
                                  " does not exist on " + std::string(info.name));
    const bool axi = model::is_axisymmetric(info);
    if (first) {
      dim_ = info.dim;
      axisymmetric_ = axi;
      first = false;
    } else if (dim_ != info.dim || axisymmetric_ != axi) {
      throw std::invalid_argument(where(surface) + " mixes " + (dim_ == 3 ? "3-D" : axisymmetric_ ? "axisymmetric" : "planar") +
                                  " and " + std::string(info.name) + " element faces");
    }
    const model::FaceDef& def = info.faces[face.face];
    Facet f;
    f.shape = facet_shape_of(info.dim, def.n_nodes, def.n_corners);
    f.n_nodes = def.n_nodes;
    const auto rows = model::face_nodes(elements, face);
    std::copy(rows.begin(), rows.end(), f.nodes.begin());
    f.element = face.element;
    f.face = face.face;
    facets_.push_back(f);
  }
}

void ContactSurface::index_node_facets() {
  for (const Facet& f : facets_)
    for (std::int32_t r : f.node_rows()) nodes_.push_back(r);
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  node_facet_ptr_.assign(nodes_.size() + 1, 0);
  for (const Facet& f : facets_)
    for (std::int32_t r : f.node_rows()) ++node_facet_ptr_[static_cast<std::size_t>(local_index(r)) + 1];
  for (std::size_t i = 0; i < nodes_.size(); ++i) node_facet_ptr_[i + 1] += node_facet_ptr_[i];
  node_facet_.resize(static_cast<std::size_t>(node_facet_ptr_.back()));
  std::vector<std::int32_t> fill(node_facet_ptr_.begin(), node_facet_ptr_.end() - 1);
  for (std::size_t fi = 0; fi < facets_.size(); ++fi)
    for (std::int32_t r : facets_[fi].node_rows())
      node_facet_[static_cast<std::size_t>(fill[static_cast<std::size_t>(local_index(r))]++)] =
          static_cast<std::int32_t>(fi);
}

std::int32_t ContactSurface::local_index(std::int32_t row) const {
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), row);
  return it != nodes_.end() && *it == row ? static_cast<std::int32_t>(it - nodes_.begin()) : -1;
}

std::span<const std::int32_t> ContactSurface::facets_of_node(std::size_t local) const {
  return {node_facet_.data() + node_facet_ptr_[local],
          static_cast<std::size_t>(node_facet_ptr_[local + 1] - node_facet_ptr_[local])};
}

double ContactSurface::area_factor(const Vec3& point) const {
  if (dim_ == 3) return 1.0;
  return axisymmetric_ ? 2 * std::numbers::pi * point[0] : thickness_;
}

namespace {

/// Enough Gauss points for N² × (curved) Jacobian × r on quadratic facets.
int rule_points(FacetShape s) { return facet_is_quadratic(s) ? 6 : 4; }

}  // namespace

double ContactSurface::facet_area(std::size_t facet, std::span<const Vec3> x) const {
  const Facet& f = facets_[facet];
  double area = 0.0;
  for (const QuadPoint& q : facet_rule(f.shape, rule_points(f.shape))) {
    const FacetGeometry g = facet_geometry(f, x, q.xi, q.eta);
    area += q.weight * g.jacobian * area_factor(g.x);
  }
  return area;
}

double ContactSurface::area(std::span<const Vec3> x) const {
  double total = 0.0;
  if (node_based_) {
    for (double a : given_areas_) total += a;
    return total;
  }
  for (std::size_t f = 0; f < facets_.size(); ++f) total += facet_area(f, x);
  return total;
}

std::vector<double> ContactSurface::nodal_areas(std::span<const Vec3> x) const { return nodal_shares(x, true); }

std::vector<double> ContactSurface::consistent_nodal_areas(std::span<const Vec3> x) const {
  return nodal_shares(x, false);
}

std::vector<double> ContactSurface::nodal_shares(std::span<const Vec3> x, bool lumped) const {
  if (node_based_) return given_areas_;
  std::vector<double> out(nodes_.size(), 0.0);
  for (const Facet& f : facets_) {
    const bool hrz = lumped && facet_is_quadratic(f.shape);
    std::array<double, 8> share{};
    double area = 0.0, sum = 0.0;
    for (const QuadPoint& q : facet_rule(f.shape, rule_points(f.shape))) {
      const ShapeEval e = eval_shape(f.shape, q.xi, q.eta);
      const FacetGeometry g = facet_geometry(f, x, q.xi, q.eta);
      const double da = q.weight * g.jacobian * area_factor(g.x);
      area += da;
      for (int a = 0; a < e.n; ++a) share[a] += (hrz ? e.N[a] * e.N[a] : e.N[a]) * da;
    }
    for (int a = 0; a < f.n_nodes; ++a) sum += share[a];
    // Consistent shares already sum to the area; HRZ shares are scaled to it.
    const double s = hrz && sum > 0 ? area / sum : 1.0;
    for (int a = 0; a < f.n_nodes; ++a) out[static_cast<std::size_t>(local_index(f.nodes[a]))] += s * share[a];
  }
  return out;
}

/// Median facet size of a surface on coordinates x (edge length in 2D, √area in 3D).
double typical_facet_size(const ContactSurface& s, std::span<const Vec3> x) {
  std::vector<double> sizes;
  for (std::size_t f = 0; f < s.facets().size(); ++f) {
    const double a = s.facet_area(f, x);
    // 2D facet areas carry the thickness or 2πr: divide it back out at the facet's first node.
    const double factor = s.dim() == 2 ? s.area_factor(x[s.facets()[f].nodes[0]]) : 1.0;
    sizes.push_back(s.dim() == 2 ? (factor > 0 ? a / factor : 0.0) : std::sqrt(a));
  }
  if (sizes.empty()) return 0.0;
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
  return sizes[sizes.size() / 2];
}

std::vector<Vec3> current_coordinates(const model::Nodes& nodes, std::span<const double> u, int dim) {
  std::vector<Vec3> x(nodes.coords.begin(), nodes.coords.end());
  const std::size_t d = static_cast<std::size_t>(dim);
  for (std::size_t i = 0; i < x.size() && (i + 1) * d <= u.size(); ++i)
    for (std::size_t k = 0; k < d; ++k) x[i][k] += u[i * d + k];
  return x;
}

std::vector<Vec3> reference_coordinates(const model::Nodes& nodes) {
  return {nodes.coords.begin(), nodes.coords.end()};
}

}  // namespace inpact::contact
