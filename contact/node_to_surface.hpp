#pragma once
/// Node-to-surface contact kinematics of one contact pair: every slave node is searched for and
/// projected onto the master surface on the coordinates given (the current ones, every
/// iteration: finite and small sliding are treated alike for now), giving its gap, contact
/// normal, nodal area and the gap's linearisation (projection.hpp):
///   g = (x_s − x_m)·n,   ∇g = [n; −N_a n],   ∇²g (finite sliding).
/// What the enforcement does with them (penalty force A p ∇g, multiplier rows A ∇g) is the
/// solver's (solver/contact_problem.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "contact/contact_surface.hpp"
#include "contact/geometric_correction.hpp"
#include "contact/pair_kinematics.hpp"
#include "contact/projection.hpp"
#include "contact/search.hpp"
#include "model/model.hpp"

namespace inpact::contact {

class NodeToSurfacePair final : public PairKinematics {
 public:
  /// The pair's surfaces from `model` (their names must exist; the master must be element
  /// based). `dim`: 2 or 3, the model's DOFs per node.
  NodeToSurfacePair(const model::Model& model, const model::Surface& slave, const model::Surface& master, int dim, double out_of_plane_thickness);

  /// *CONTACT PAIR, EXTENSION ZONE (default 0.1): a slave node beside a free edge or end of the
  /// master, within this fraction of the facet's size of it, meets the facet's plane extended,
  /// in front or behind (Abaqus extends the master so that a node at its edge does not drop out
  /// of contact as it bulges past it, nor get pushed sideways by the edge). Farther beside it,
  /// the node does not face the master: not found.
  void set_extension_zone(double zone) { extension_zone_ = zone; }

  /// Searches and projects every slave node on coordinates `x` (all node rows); `out` has one
  /// entry per slave node, in slave().nodes() order. Rebuilds the search tree when the master
  /// moved more than its margin since the last build.
  void update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) override;
  /// Fills k.lin (gradient, and the Hessian when `finite_sliding`) on coordinates `x`.
  void linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const override;

  /// Geometric correction of the master and slave surfaces (contact/geometric_correction.hpp;
  /// empty sets: none). update() then measures on the idealised surfaces: ξ refined on the
  /// projected facet (SurfaceCorrections::project), x_master = x̃_m, normal = ñ,
  /// gap = (x̃_s − x̃_m)·ñ, with x̃_s = x_s (a node lies on its idealised surface). linearize()
  /// keeps the gradient [ñ; −N_a ñ] and drops the faceted Hessian, which describes the facets,
  /// not the corrected surface. Not reachable from decks (Abaqus smooths surface-to-surface pairs
  /// and general contact only); for tests and the surface-to-surface code.
  void set_geometric_correction(SurfaceCorrections master, SurfaceCorrections slave = {});

 private:
  /// Replaces p's point, normal and gap by those of the corrected surfaces (slave node `slave`).
  void correct(std::span<const Vec3> x, std::size_t slave, Projection& p) const;

  /// The closest point is on an edge or vertex that no other facet shares (no other normal
  /// there): a free edge or end of the master, where a convex corner's rounding does not apply.
  static bool at_free_edge(const Projection& p);
  /// The extension zone's rule beside a free edge: true, with p's normal and gap those of the
  /// facet's plane extended, when the node lies within the zone beside the edge.
  bool extend_master(std::span<const Vec3> x, const Vec3& xs, Projection& p) const;

  SurfaceCorrections master_correction_, slave_correction_;
  double extension_zone_ = 0.1;
};

}  // namespace inpact::contact
