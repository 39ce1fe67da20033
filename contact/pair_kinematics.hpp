#pragma once
/// What a contact discretisation gives the enforcement, per slave node of a contact pair: a
/// gap, the area it stands for, a contact normal and the gap's linearisation over the nodes it
/// depends on. The enforcement (penalty force −A p(−g) ∇g, a multiplier row A ∇g, friction) is
/// the solver's (solver/contact_problem.hpp) and does not care how the gap was measured:
///   node to surface     (node_to_surface.hpp)    g is the slave node's own closest-point gap;
///   surface to surface  (surface_to_surface.hpp) g is the slave faces' gap averaged with the
///                                                node's weighting function around it.
#include <cstdint>
#include <span>
#include <vector>

#include "contact/contact_surface.hpp"
#include "contact/projection.hpp"
#include "contact/search.hpp"
#include "contact/vec3.hpp"
#include "model/model.hpp"

namespace inpact::contact {

/// One slave node against the master surface.
struct SlaveKinematics {
  std::int32_t node = -1;    ///< slave node row
  bool found = false;        ///< the node faces the master within the search radius
  /// The contact geometry at the node. Node to surface: the node's own projection. Surface to
  /// surface: gap = the weighted gap, normal = the weighted normal (with its tangent basis);
  /// facet and ξ are those of the node's own projection (what friction anchors to).
  Projection projection;
  double area = 0.0;         ///< the slave node's share of the contact area
  /// Surface to surface: how much of the node's facets overlaps the master — `area` (before the
  /// pair's area weight) over the node's nodal area on the reference coordinates, at most 1; 1
  /// for node to surface.
  double overlap = 1.0;
  GapLinearization lin;      ///< of `projection.gap`; filled by linearize() only
  /// Surface to surface only: the node's own closest-point projection and its linearisation
  /// (friction acts there); `friction_found` false when the node itself does not project.
  bool friction_found = false;
  GapLinearization friction_lin;
};

/// The search radius of a pair: the larger median facet size of its two surfaces (a slave
/// point farther than that from the master is open without doubt); 1 when neither has facets.
double search_radius(const ContactSurface& slave, const ContactSurface& master, std::span<const Vec3> x);
/// The same for surfaces of `model` on its reference coordinates.
double pair_search_radius(const model::Model& model, const model::Surface& slave, const model::Surface& master,
                          double out_of_plane_thickness);

/// A contact pair's discretisation: its two surfaces and the search over the master's facets,
/// shared by both discretisations; what they measure is theirs.
class PairKinematics {
 public:
  virtual ~PairKinematics() = default;
  const ContactSurface& slave() const { return slave_; }
  const ContactSurface& master() const { return master_; }
  /// Largest distance at which a master facet is guaranteed to be found (a facet size).
  double search_radius() const { return radius_; }
  /// Searches and measures every slave node (set_measured_nodes: those measured) on coordinates
  /// `x` (all node rows); `out` gets one entry per slave node, in slave().nodes() order (an
  /// unmeasured node's: unfound, the rest of it meaningless).
  virtual void update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) = 0;
  /// Fills k.lin (the gradient; the Hessian too when `finite_sliding`) on coordinates `x`, for
  /// the state of the last update(); surface to surface also k.friction_lin.
  virtual void linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const = 0;
  /// linearize() of kin[i] for every i of `nodes` (ascending slave node positions), on the
  /// pair's threads; the same bits whatever their number.
  void linearize_nodes(std::span<const Vec3> x, std::span<SlaveKinematics> kin, std::span<const std::size_t> nodes,
                       bool finite_sliding);

  /// Scales every slave area update() reports (not the gaps or their gradients): ½ for each of
  /// the two rows of a balanced master-slave interaction (interaction_table.hpp).
  void set_area_weight(double w) { area_weight_ = w; }
  double area_weight() const { return area_weight_; }

  /// Self-contact (slave and master the same surface): a slave point ignores the master facets
  /// that share a node with it (its own neighbourhood), and counts a projection only where it
  /// faces the master (normals within 45° of opposite) and projects orthogonally (within 45°).
  void set_self_contact(bool self) { self_contact_ = self; }

  /// Threads update() may run on (its results do not depend on how many).
  void set_threads(int threads) { threads_ = threads; }

  /// A distributed run: the slave nodes this rank measures, per slave node (empty: every one).
  /// update() fills the entries of these and leaves the others unfound; linearize() is asked
  /// for these only. While the set stays the same, a measured node gets the bits it gets when
  /// every node is measured (its facets' points keep their history). A rigid analytical
  /// master measures every node (its measure costs no search).
  void set_measured_nodes(std::vector<char> measured) { measured_ = std::move(measured); }
  bool measures(std::size_t i) const { return measured_.empty() || measured_[i] != 0; }

 protected:
  /// The pair's surfaces from `model`, and their search_radius().
  PairKinematics(const model::Model& model, const model::Surface& slave, const model::Surface& master, int dim,
                 double out_of_plane_thickness);
  /// Rebuilds the search tree when the master moved more than its margin since the last build.
  void refresh_search(std::span<const Vec3> x);
  /// Before linearize() runs on several threads: fills whatever it caches and shares between
  /// slave nodes (surface to surface: its points' gradients), for the slave nodes `nodes`.
  virtual void prepare_linearization(std::span<const Vec3> x, std::span<const std::size_t> nodes,
                                     bool finite_sliding) {}

  int dim_;
  ContactSurface slave_, master_;
  FacetSearch search_;
  double radius_ = 0.0;
  bool built_ = false;
  std::vector<std::int32_t> candidates_;  ///< scratch for search queries
  double area_weight_ = 1.0;
  bool self_contact_ = false;
  int threads_ = 1;
  std::vector<char> measured_;  ///< set_measured_nodes() (empty: every node)
};

/// Self-contact: drops from `candidates` every facet that has a node of `own` (a facet's rows).
inline void drop_neighbours(std::span<const Facet> facets, std::span<const std::int32_t> own,
                            std::vector<std::int32_t>& candidates) {
  std::erase_if(candidates, [&](std::int32_t c) {
    for (std::int32_t r : facets[static_cast<std::size_t>(c)].node_rows())
      for (std::int32_t o : own)
        if (r == o) return true;
    return false;
  });
}

/// Does the point project onto the master within 45° of the facet's normal? Beyond a free edge
/// or end of the master the distance turns tangential: a point beside it does not face the
/// master, and the sign of its gap would be round-off (the same rule in both discretisations).
inline bool projects_orthogonally(const Projection& p) {
  constexpr double kCos45 = 0.7071;
  return p.region == ProjectionRegion::Interior || p.gap == 0.0 || std::abs(dot(p.normal, p.facet_normal)) >= kCos45;
}

/// Self-contact: does a slave point with outward normal `n_slave` see projection `p` across the
/// gap (facing it, orthogonally), rather than along its own surface?
inline bool faces_across(const Vec3& n_slave, const Projection& p) {
  constexpr double kCos45 = 0.7071;
  return dot(n_slave, p.normal) <= -kCos45 && projects_orthogonally(p);
}

}  // namespace inpact::contact
