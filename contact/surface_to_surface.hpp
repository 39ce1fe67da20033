#pragma once
/// Surface-to-surface contact kinematics of one contact pair (*CONTACT PAIR, TYPE=SURFACE TO
/// SURFACE): the contact condition of each slave node is enforced "in an average sense over
/// regions nearby slave nodes rather than only at individual slave nodes" (Abaqus §38.1.1).
///
/// inpact's discretisation (a mortar-type weighted gap, integrated on the slave faces):
///   every slave facet carries integration points (segment-based, contact/mortar_segments.hpp: its
///   parametric domain cut where master facets begin and end, a Gauss rule per piece;
///   plain_rule_points() per direction where no master facet edge crosses it); each point x_q is projected onto
///   the master (closest point, projection.hpp) giving g_q, n_q. A point
///   overlaps the master when it projects orthogonally (or nearly: the distance direction within
///   45° of the master facet's normal, so that points beyond the master's free edge drop out)
///   and the slave face there faces the master (n_slave · n_q ≤ −cos 45°).
///   Per slave node a, over the overlapping points of the facets around it, with the weighting
///   function W_a and dA the current area element (× thickness or 2π r in 2D):
///     A_a = Σ_q W_a(q) dA_q                     the area the node stands for (CNAREA)
///     g_a = Σ_q W_a(q) g_q dA_q / A_a           the weighted gap (COPEN)
///     n_a = Σ_q W_a(q) n_q dA_q, normalised     the node's contact normal
///   and, since A_a is held fixed in the linearisation, with x_q = Σ_b N_b(q) x_b,
///     ∂g_a/∂x_b (slave) = Σ_q W_a N_b n_q dA_q / A_a,   ∂g_a/∂x_m (master) = −Σ_q W_a N_m n_q dA_q / A_a.
///   A pressure p_a then gives the forces −Σ_a p_a A_a ∂g_a/∂u = −∫ p_h N n dA with
///   p_h = Σ_a W_a p_a: consistent nodal forces on both sides, so a uniform pressure passes
///   between non-matching meshes (the contact patch test), which node-to-surface contact does not.
///   W_a = N_a on first-order faces and edges and on Line3. On Tri6 and Quad8 faces ∫N_a dA is
///   zero or negative at the corners, so W is the transformed basis of Popp et al. (2012,
///   "Dual quadratic mortar finite element methods for 3D finite deformation contact"):
///     W_corner = N_corner + α Σ_{adjacent midside} N_mid,  W_mid = (1 − 2α) N_mid,  α = 1/5,
///   a partition of unity with every ∫W_a dA > 0 (flat Quad8: corners 1/20, midsides 1/5 of A).
///   The Hessian (finite sliding) is Σ_q W_a dA_q/A_a × the point's ∂²g_q mapped to the nodes.
///   The contact direction is the master's normal at each point (Abaqus uses the slave normal;
///   the two agree where the surfaces touch and the difference is of the order of the gap).
///
/// The points' layout depends on the configuration: it is recomputed at every update() from the
/// current coordinates (the master corners' projections onto each slave facet). The linearisation
/// holds it fixed: the motion of the cuts (the pieces' ∂ξ_q/∂u and ∂w_q/∂u) is neglected, as
/// segment-based mortar codes usually do (Puso & Laursen 2004; Popp et al. 2010 linearise it).
/// By Leibniz's rule the neglected term is the jump of the integrand across a cut times the cut's
/// speed: across a master facet edge the gap, N_m and W are continuous, so the term vanishes; it
/// does not where a piece ends at the master's free edge (W g jumps to 0 there).
/// A facet whose point count changes between updates gives each new point the faceted hint and
/// search memo of the nearest old one (below).
///
/// Each point's projection onto the master facet it projected into at the last update starts
/// from the ξ found then (ProjectionHint) instead of a grid search, and its geometric correction
/// on the same facet from the corrected ξ and the ray's Jacobian of then (RayMemo): the same
/// points to round-off where the rays converge (the default job's CPRESS within 5e-10 of its
/// largest value). Where a ray does not converge — open points far from the master, whose rays
/// stop on a facet's edge — the point found depends on the start, so on the updates before
/// (the default job's far-open COPEN moved up to 2.5e-5 when the Jacobian was first kept).
/// The slave facets' points are projected on PairKinematics::set_threads() threads (each facet
/// on one thread); the sums over a node's points then run facet after facet on one thread, so
/// the results do not depend on the thread count.
///
/// Friction acts at the slave node's own closest-point projection (node to surface) with the
/// pressure of its weighted gap: SlaveKinematics::friction_lin.
///
/// Geometric correction (smoothing, contact/geometric_correction.hpp; *SURFACE SMOOTHING named
/// by the pair, or general contact's *SURFACE PROPERTY ASSIGNMENT): every integration point is
/// first moved onto the slave's idealised surface, x̃_q; its faceted closest point on the master
/// is then refined onto the master's idealised surface along the idealised normal
/// (SurfaceCorrections::project), giving x̃_m, ñ and g_q = (x̃_q − x̃_m)·ñ. The gradient keeps
/// the form [ñ; −N ñ] (the corrections' own derivatives are left out, and so is the Hessian):
/// the answer is the corrected one. The gradient of a smoothed pair's gap is exact
/// (contact/smoothed_gap.hpp: the corrections' rotation with their facets, the slide of the
/// ray's point over the master, the change of each point's weight W da / Σ W da); its Hessian is
/// left out (the geometric stiffness A c ∇²g, of the order of the pressure over the facet size).
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

/// Gauss points per parametric direction of a slave facet's plain rule (no master facet edge
/// crosses it), and the budget mortar_rule() shares out among a cut facet's cells (at least 3,
/// 4 with a quadratic side; contact/mortar_segments.hpp). `quadratic_master`: a master facet
/// near the slave facet is quadratic.
/// Edges (2D): 6. Faces: 3 between linear faces, which integrates W_a × N_m times the area
/// element of a flat quadrilateral exactly (degree 4 per direction at most), 4 with a quadratic
/// side on either (degree 6). Smoothed and
/// curved faces make the integrand no polynomial, so the choice is measured: 4 × 4 gave the
/// contact verification figures of a 6 × 6 rule to 1e-6 of their value with the same Newton
/// counts (C3D8 decks; the 3D sphere meshed with C3D20 agreed to 2.6e-5 of its largest CPRESS),
/// nodal values to 4e-5; 3 × 3 on linear faces gave those of 4 × 4 with the same Newton counts
/// (the 3D sphere with each method, pushed and under a force, peak CPRESS to 1.1e-10; the
/// spherical seats to 5e-8; the default job, smoothed, to 1.5e-5 of its largest CPRESS). On 2D
/// edges a 4-point rule did not (spherical_seat_axi_smoothed: its worst node 2.13 % from the
/// thick sphere, over the test's 2 % bound).
int plain_rule_points(FacetShape shape, bool quadratic_master = false);
/// A face's plain rule where mortar_rule() found its cells ambiguous (two master layers, a folded
/// cell: master edges cross the face, and N_m's kinks fall between the points; 6 per direction
/// is 2 % off over a hat function, 4 is 4.3 % off), or the slave facet degenerate.
inline constexpr int kAmbiguousRulePoints = 6;

/// Tests: every projection a point keeps without a search (SurfaceToSurfacePair) is checked
/// against the search's own, to the bit; a difference throws std::logic_error.
inline bool projection_self_check = false;

/// The weighting function values W_a at a point of a facet of `shape`, from its shape
/// functions N (see the header comment: W = N except on Tri6 and Quad8).
std::array<double, 8> weighting_functions(FacetShape shape, const std::array<double, 8>& N);

class SurfaceToSurfacePair final : public PairKinematics {
 public:
  /// The pair's surfaces from `model`; both must be element based (std::invalid_argument otherwise).
  SurfaceToSurfacePair(const model::Model& model, const model::Surface& slave, const model::Surface& master, int dim, double out_of_plane_thickness);

  void update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) override;
  void linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const override;
  void prepare_linearization(std::span<const Vec3> x, std::span<const std::size_t> nodes,
                             bool finite_sliding) override;

  /// Smoothing of the master and slave surfaces (empty sets: none).
  void set_geometric_correction(SurfaceCorrections master, SurfaceCorrections slave);
  bool smoothed() const { return !master_correction_.empty() || !slave_correction_.empty(); }

 private:
  /// One integration point of a slave facet at the last update.
  struct Point {
    double da = 0.0;                 ///< weight × area element
    std::array<double, 2> param{2.0, 2.0};  ///< its parametric point on the slave facet (N, W are of it)
    std::array<double, 8> N{}, W{};  ///< shape and weighting functions of the slave facet
    Vec3 x{};
    Projection projection;
    ProjectionHint hint;  ///< the faceted projection's facet and ξ when inside it: the next start
    RayMemo ray_memo;  ///< the corrected projection's facet, ξ and ray Jacobian: the next one's start
    /// The last full search: its closest facet, how close any other facet then came (less the
    /// round-off of those bounds), where the point was and the master's motion then.
    struct SearchMemo {
      std::int32_t facet = -1;  ///< −1: none to reuse
      double others = 0.0;
      Vec3 x{};
      Vec3 shift{};
      double motion = 0.0;
      unsigned generation = 0;  ///< memo_generation_ then
    } memo;
    bool overlaps = false;
    bool master_corrected = false;  ///< the projection was moved onto the master's idealised surface
    /// The point's gap linearised against its master facet: computed by the first linearize()
    /// of a slave node that needs it after an update(), and kept for the other nodes of the
    /// facet (on the coordinates of the last update(); filled by prepare_linearization() before
    /// linearize() runs on several threads).
    mutable GapLinearization lin;
    mutable bool lin_valid = false;
    mutable bool lin_hessian = false;  ///< lin has the Hessian (else the gradient only)
    /// Smoothed pairs: the point's exact gap gradient over [slave facet nodes; master facet nodes]
    /// and ∂(ln da) over the slave facet's nodes, kept for the other nodes of the facet as `lin`.
    mutable std::vector<double> smoothed_gradient, log_area_gradient;
    mutable bool smoothed_valid = false;
  };
  /// The point's linearisation; with the Hessian when `hessian`.
  const GapLinearization& point_linearization(std::span<const Vec3> x, const Point& pt, bool hessian) const;
  /// A smoothed pair: pt.smoothed_gradient and pt.log_area_gradient, unless valid.
  void smoothed_point_gradient(std::span<const Vec3> x, const Facet& sf, const Point& pt) const;
  /// Per slave facet, 1 where it has a node of `node_mask` (per slave node).
  std::vector<char> facets_around(std::span<const char> node_mask) const;
  /// Fills the caches above of every point of slave facet fi that a found node of `linearised`
  /// weighs (W da ≠ 0): those its linearize() reads.
  void fill_point_caches(std::span<const Vec3> x, std::size_t fi, std::span<const char> linearised,
                         bool finite_sliding) const;
  /// Projects the integration points of slave facet fi (points_[fi]; one thread per facet).
  void measure_facet(std::span<const Vec3> x, std::size_t fi);
  /// `pts` resized to the layout `rule`, each point with the faceted hint and search memo of the
  /// nearest old one.
  static void relayout(std::vector<Point>& pts, std::span<const QuadPoint> rule);
  /// The integration points of slave facet f on x: the mortar rule against the master facets near
  /// it, or the plain rule (mortar_segments.hpp). Valid until the thread's next call.
  std::span<const QuadPoint> facet_points(std::span<const Vec3> x, const Facet& f) const;
  void project_node(std::span<const Vec3> x, SlaveKinematics& k) const;
  /// The point's faceted projection onto the closest master facet, from its memo when no other
  /// facet can have come within the tie tolerance of the one it found last (the same numbers
  /// as the full search: sole_projection()), else by the search (`candidates` then filled).
  Projection search_point(std::span<const Vec3> x, const Facet& f, const FacetGeometry& g, Point& pt,
                          std::vector<std::int32_t>& candidates) const;
  /// Projects onto pt.memo's facet alone when that gives the search's result; false otherwise,
  /// with `raw` the memo facet's projection when it was made (raw.facet −1 when not).
  bool reproject(std::span<const Vec3> x, const Facet& f, const FacetGeometry& g, Point& pt, Projection& raw) const;
  /// Adds to master_motion_ how far the master moved since the last update (master_x_, updated).
  void track_master_motion(std::span<const Vec3> x);
  /// Replaces a point's projection `p` that does not face it by the closest facing one.
  void project_onto_facing(std::span<const Vec3> x, const FacetGeometry& g, std::span<const std::int32_t> candidates,
                           Projection& p) const;
  std::vector<std::vector<Point>> points_;  ///< per slave facet
  std::vector<double> node_area_;           ///< per slave node: its nodal area on the reference coordinates
  std::vector<FacetBox> master_boxes_;      ///< of the master facets, at the last update
  std::vector<Vec3> master_normals_;        ///< their centre normals (mortar_segments.hpp), then
  /// How far a point of any master facet can have moved beyond master_shift_ since the first
  /// update, summed over the updates: each update's largest node displacement less its shift,
  /// × 3 on quadratic facets (a facet point moves Σ N_a δ_a, and Σ |N_a| is at most 3 on Quad8,
  /// 5/3 on Tri6, 1 on linear facets; Σ N_a = 1 carries the shift unchanged).
  double master_motion_ = 0.0;
  /// Bumped when a motion is not finite (NaN coordinates): every memo of before is dropped.
  unsigned memo_generation_ = 0;
  /// The master's common translation, summed over the updates (of each: the middle of its
  /// nodes' displacements, component by component). A master that moves as a body (a pushed
  /// pin) then keeps its points' memos: only the motion relative to the point counts.
  Vec3 master_shift_{};
  std::vector<Vec3> master_x_;  ///< the master nodes' coordinates at the last update
  double largest_master_facet_ = 0.0;       ///< the largest master facet's facet_size() at the last update
  double master_magnitude_ = 0.0;  ///< the largest coordinate of the master's boxes then
  SurfaceCorrections master_correction_, slave_correction_;
  /// Moves p onto the master's idealised surface for the slave point xs; whether it was corrected.
  /// `memo`: the point's last ray projection (correct_projection()), updated.
  bool correct_master(std::span<const Vec3> x, const Vec3& xs, Projection& p, RayMemo* memo = nullptr) const;
  /// linearize()'s gradient for a smoothed pair: every point's exact gap gradient
  /// (smoothed_gap.hpp) and the change of its weight W da / Σ W da, into k.lin.
  void linearize_smoothed(std::span<const Vec3> x, SlaveKinematics& k) const;
  /// k.lin's nodes (the slave facets around slave node `local`, their points' master facets), its
  /// gradient and Hessian zeroed.
  void gather_nodes(std::size_t local, GapLinearization& L) const;
};

}  // namespace inpact::contact
