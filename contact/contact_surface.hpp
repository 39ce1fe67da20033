#pragma once
/// A contact surface built from a model::Surface: its facets (element faces in 3D, element edges
/// in 2D, first and second order), the unique nodes it is made of (the slave nodes when it is
/// the slave of a node-to-surface pair) and the nodal areas those slave nodes carry. Geometry is
/// always evaluated on coordinates the caller passes, normally the current ones (reference + u,
/// see current_coordinates()). A node-based surface (*SURFACE, TYPE=NODE) has no facets: it can
/// only be a slave, and its nodal areas are the ones the deck gives (1.0 when not given).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "contact/facet.hpp"
#include "model/model.hpp"

namespace inpact::contact {

struct SurfaceOptions {
  /// Plane strain / plane stress: contact area per unit edge length (the *SURFACE INTERACTION
  /// data line). Axisymmetric surfaces ignore it and use 2π r (the full circumference, like
  /// every axisymmetric force in Abaqus).
  double out_of_plane_thickness = 1.0;
};

class ContactSurface {
 public:
  /// The contact surface of `surface` (a surface of `model`). Throws std::invalid_argument when
  /// its faces mix 2D and 3D elements, or axisymmetric and planar ones.
  static ContactSurface build(const model::Model& model, const model::Surface& surface,
                              const SurfaceOptions& options = {});

  const std::string& name() const { return name_; }
  bool node_based() const { return node_based_; }
  /// 2 or 3: the coordinates (and displacement components) the surface's geometry uses.
  int dim() const { return dim_; }
  bool axisymmetric() const { return axisymmetric_; }

  std::span<const Facet> facets() const { return facets_; }
  /// Unique node rows of the surface, ascending: the slave nodes of node-to-surface contact.
  std::span<const std::int32_t> nodes() const { return nodes_; }
  /// Position of node row `row` in nodes(), or −1.
  std::int32_t local_index(std::int32_t row) const;
  /// Facets (indices into facets()) that touch nodes()[local].
  std::span<const std::int32_t> facets_of_node(std::size_t local) const;

  /// Area each node of nodes() stands for on coordinates `x` (all node rows), Σ = area(x).
  /// First-order facets: the consistent share ∫ N_a dA (all positive). Second-order facets: the
  /// consistent shares are zero (Tri6) or negative (Quad8) at the corners, so a node-to-surface
  /// slave there would carry no or a negative contact force; inpact lumps them by the
  /// Hinton–Rock–Zienkiewicz rule, w_a = A_f ∫N_a² dA / Σ_b ∫N_b² dA — every share positive, the
  /// total exactly the facet area (flat Quad8: corners 3/76, midsides 16/76 of the area; flat
  /// Tri6: corners 1/19, midsides 16/57; straight Line3: 1/6, 2/3, 1/6, the consistent values).
  std::vector<double> nodal_areas(std::span<const Vec3> x) const;
  /// The consistent shares ∫ N_a dA on every facet, also for second-order facets (zero or
  /// negative at their corners): the nodal forces of a uniform unit traction. Node-based: the
  /// given areas.
  std::vector<double> consistent_nodal_areas(std::span<const Vec3> x) const;
  /// Area of one facet (2D: × thickness or × 2π r).
  double facet_area(std::size_t facet, std::span<const Vec3> x) const;
  /// Total area of the surface (node-based: the sum of the given nodal areas).
  double area(std::span<const Vec3> x) const;
  /// The area factor of a 2D edge at a point: thickness, or 2π r for an axisymmetric one; 1 in 3D.
  double area_factor(const Vec3& point) const;

 private:
  // The steps of build().
  /// A node-based surface: its unique node rows (the first area given wins) and the model's dimension.
  void set_nodes(const model::Elements& elements, const model::Surface& surface);
  /// An element-based surface's facets, checked for one dimension and one element family.
  void add_facets(const model::Elements& elements, const model::Surface& surface);
  /// The unique nodes of the facets and the facets around each (compressed rows).
  void index_node_facets();
  /// nodal_areas() (`lumped`) or consistent_nodal_areas().
  std::vector<double> nodal_shares(std::span<const Vec3> x, bool lumped) const;

  std::string name_;
  bool node_based_ = false;
  int dim_ = 3;
  bool axisymmetric_ = false;
  double thickness_ = 1.0;
  std::vector<Facet> facets_;
  std::vector<std::int32_t> nodes_;
  std::vector<double> given_areas_;  ///< node-based surfaces
  std::vector<std::int32_t> node_facet_ptr_, node_facet_;
};

/// Median facet size of a surface on coordinates x (edge length in 2D, √area in 3D); 0 for a
/// node-based surface.
double typical_facet_size(const ContactSurface& s, std::span<const Vec3> x);

/// Current coordinates x = X + u of every node, from the solver's displacement vector laid out
/// as u[row · dim + component] (dim = 2: the third coordinate is copied from the reference).
std::vector<Vec3> current_coordinates(const model::Nodes& nodes, std::span<const double> u, int dim);

/// Reference coordinates of every node.
std::vector<Vec3> reference_coordinates(const model::Nodes& nodes);

}  // namespace inpact::contact
