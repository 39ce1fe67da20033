#pragma once
/// Geometric correction (surface smoothing of [AX] §38.1.3): a faceted contact surface is replaced,
/// for the contact geometry only (gap, normal, contact point), by the idealised circle, surface of
/// revolution, sphere or torus it approximates.
///
/// The idealised surface. Every kind is "a radius about a centre": for a point p,
///   CIRCUMFERENTIAL  c(p) = the foot of p on the axis through a and b;
///   SPHERICAL        c(p) = a, the centre;
///   TOROIDAL         c(p) = the point of the arc-centre circle (radius R about the axis, in the
///                    plane through a normal to the axis, as [AX] requires) in p's meridional plane;
///   e(p) = (p − c)/|p − c| the radial direction, r(p) = |p − c|.
/// The idealised surface passes through the surface's nodes: each node keeps its own radius
/// r_a = r(X_a) on the reference coordinates X (for TOROIDAL r_a is the tube radius: the distance
/// from the node to the arc-centre circle). At a point X_f(ξ) = Σ N_a(ξ) X_a of a facet, the radius
/// is interpolated, r̃(ξ) = Σ N_a(ξ) r_a, and the idealised point is
///   X̃(ξ) = c(X_f) + r̃(ξ) e(X_f).
/// The idealised normal ñ(ξ) points out of the body like the facet's outward normal n:
///   SPHERICAL, TOROIDAL: ñ = s e(X_f), s = ±1 per facet, the sign of e·n over the facet (+1 on a
///     ball, −1 in a socket). Sphere and torus are fully determined by the data line.
///   CIRCUMFERENTIAL: only the hoop direction is idealised; the meridian (the profile along the
///     axis) is the mesh's own, so the surface may be a cylinder, a cone (the hole of [AX]'s pin
///     example) or an end face. ñ is the normal of X̃(ξ) with its hoop component removed: in the
///     meridional plane of the point, e on a cylinder, tilted by the cone angle on a cone (exact for
///     a cone whose nodes lie on it), ±axis on a flat end face.
/// A surface that is not exactly circular (the elliptical pin of [AX]) is thus corrected toward a
/// circle of the local radius: the nodes stay where they are (X̃ = X_a at a node), a facet midpoint
/// moves out to the radius of its nodes, and the normal is the idealised one (radial on a
/// cylinder: the slight tilt of the ellipse is not kept), continuous from facet to facet around
/// the circumference (a CIRCUMFERENTIAL profile keeps the mesh's kinks along the axis). On a
/// circle of radius R meshed by N straight edges, a midpoint at R cos(π/N) moves to R exactly.
///
/// How the correction follows the deformation. The offset d(ξ) = X̃(ξ) − X_f(ξ) and the normal
/// ñ(ξ) are computed once, on the reference coordinates ("comparisons between the initial faceted
/// geometry and a more idealized initial geometry", [AX]), and carried by the facet: on current
/// coordinates x they are rotated by the facet's own rotation at ξ, Q(ξ) = [t1 t2 n]_x [t1 t2 n]_Xᵀ
/// (t1 = a_1/|a_1|, n the facet normal, t2 = n × t1), and the offset is added to the current facet
/// point:
///   x̃ = x_f(ξ) + Q d(ξ),   ñ = Q ñ(ξ).
/// Why rotate with the facet rather than measure the normal from the fixed axis or centre: the
/// axis and centre of the data line are fixed in space, but the bodies move — a pin is pushed
/// into its hole, a ball rolls in its seat. A normal taken from the fixed centre at the current
/// point turns wrongly under any rigid motion of the body (for a sphere, by the displacement over
/// the radius); carried by the facet it is exact under every rigid motion (translation: x̃ and ñ
/// move with the body; rotation: they turn with it), and for the small strains of an interference
/// fit it is the radial normal at the current point (a uniform radial expansion turns no facet).
/// What it does not do: it does not stretch the offset with the facet (under a uniform expansion
/// λ the offset stays d instead of λd, an error (λ − 1)|d|, second order in the strain times the
/// faceting error), and where neighbouring facets rotate differently the normal at their shared
/// node differs by that relative rotation (zero on the reference, where it is exactly continuous).
///
/// 2D models (ContactSurface::dim() == 2):
///   plane (strain/stress): CIRCUMFERENTIAL is a circle in the x–y plane about (Xa, Ya); its axis
///     must be the out-of-plane direction (the 2D data line `surf, CIRCUMFERENTIAL, Xc, Yc` gives
///     exactly that); an axis not along z is an error, because the section of a cylinder by the
///     model plane is then not a circle. SPHERICAL is the circle about (Xa, Ya) — the section of
///     the sphere by the model plane is centred there whatever Za is; Za is ignored. TOROIDAL is
///     an error (use SPHERICAL about the arc centre: that is the section of the torus).
///   axisymmetric (r = x, axial = y, the symmetry axis is x = 0): the axis of CIRCUMFERENTIAL and
///     TOROIDAL, and the centre of SPHERICAL, must lie on the symmetry axis (else an error).
///     CIRCUMFERENTIAL surfaces are already exact in the hoop direction and straight in the r–z
///     plane: no correction (x̃ = x_f, ñ = n). SPHERICAL is the circle about (0, Ya) in the r–z
///     plane; TOROIDAL the circle about (R, Ya).
/// First- and second-order facets alike (Line2/3, Tri3/6, Quad4/8): r̃ uses the facet's own shape
/// functions, so a Line3 whose midside node lies on the circle has its nodes on the circle and
/// deviates between them by far less than a chord (N = 8 edges: 0.95% of the chord's deviation).
///
/// Degenerate data: a surface node on the axis (CIRCUMFERENTIAL, TOROIDAL), at the centre
/// (SPHERICAL) or on the arc-centre circle (TOROIDAL) has no radial direction: CorrectionError,
/// with the data line's location; so are a zero-length axis and R ≤ 0, which the parser rejects
/// already in decks.
/// A point inside a facet on the axis (a facet spanning it) is left uncorrected.
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "contact/contact_surface.hpp"
#include "contact/facet.hpp"
#include "contact/projection.hpp"
#include "model/model.hpp"

namespace inpact::contact {

/// Data of a geometric correction that the mesh contradicts (a node on the axis, an axis not
/// normal to a plane model, ...). what() is the message without a location; loc is the data line,
/// for the caller to report as `m.sources.describe(loc): error: KEYWORD: what()`. keyword is set
/// by validate_corrections() (*SURFACE PROPERTY ASSIGNMENT or *SURFACE SMOOTHING), else empty.
struct CorrectionError : std::runtime_error {
  CorrectionError(const std::string& what, model::SourceLoc where, std::string kw = {})
      : std::runtime_error(what), loc(where), keyword(std::move(kw)) {}
  model::SourceLoc loc;
  std::string keyword;
};

/// A point of the idealised surface.
struct CorrectedPoint {
  Vec3 x{};               ///< the point on the idealised surface
  Vec3 normal{};          ///< its unit normal, outward like the facet's
  bool corrected = false; ///< false: no correction applies here; x and normal are the facet's own
};

/// Where a point's ray projection onto the idealised surface (SurfaceCorrection::project) ended
/// last: its master facet, ξ, and the Jacobian of the ray that Broyden's iteration had learned
/// there. Started from it, the next projection of the same point takes near-Newton steps at once.
struct RayMemo {
  std::int32_t facet = -1;                     ///< −1: none (a cold start)
  std::array<double, 2> xi{0, 0};
  std::array<std::array<double, 3>, 3> jacobian{};  ///< rows: components; columns: ξ_α…, g
  bool learned = false;                        ///< jacobian holds a learned one
  int corrections = 0;  ///< corrections the last projection evaluated (what a warm start saves)
};

/// Derivatives of the idealised point x̃ and normal ñ at ξ of one facet (what the gap's
/// linearisation needs).
///   x_node[a][j], n_node[a][j]: ∂x̃/∂x_aj and ∂ñ/∂x_aj at fixed ξ, for facet node a (facet order)
///     and component j: through the facet point (N_a e_j) and the facet's rotation Q (its frame
///     (t1, t2, n) moves with the tangents a_α, ∂a_α/∂x_aj = N_a,α e_j); exact.
///   x_xi[α], n_xi[α]: ∂x̃/∂ξ_α and ∂ñ/∂ξ_α, central differences in ξ with step kCorrectionXiStep
///     (the reference offset d(ξ) and normal ñ(ξ) vary with ξ too; error ~1e-10 of a facet size).
struct CorrectionDerivatives {
  int n_nodes = 0;
  int param_dim = 1;
  std::array<std::array<Vec3, 3>, 8> x_node{}, n_node{};
  std::array<Vec3, 2> x_xi{}, n_xi{};
};
/// The step of the central differences in ξ of CorrectionDerivatives (the domain is O(1)).
inline constexpr double kCorrectionXiStep = 1e-5;

/// One geometric-correction data line applied to the facets of its surface.
class SurfaceCorrection {
 public:
  /// The correction `c` of `surface` (the contact surface of c.surface) on reference coordinates
  /// `X` (all node rows). `model`, when given, names nodes in error messages by label.
  /// Throws CorrectionError for degenerate data (see above).
  SurfaceCorrection(const model::GeometricCorrection& c, const ContactSurface& surface, std::span<const Vec3> X,
                    const model::Model* model = nullptr);

  const model::GeometricCorrection& data() const { return data_; }
  /// Index of `f` among this correction's facets (matched by its node rows), or −1.
  std::int32_t find(const Facet& f) const;
  /// The idealised point and normal at ξ of facet `f` on coordinates `x` (all node rows).
  /// Throws std::invalid_argument when `f` is not a facet of this correction's surface.
  CorrectedPoint correct(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x) const;
  /// The same for this correction's own facet number `facet`; `geometry`, when given, gets the
  /// facet's own geometry at ξ on x (computed on the way).
  CorrectedPoint correct(std::int32_t facet, std::array<double, 2> xi, std::span<const Vec3> x,
                         FacetGeometry* geometry = nullptr) const;
  /// The point of the idealised surface over facet `f` whose normal passes through `xs`: `xi`,
  /// on entry a start (the closest point of the faceted surface), is refined by Broyden's
  /// iteration on x̃(ξ) + g ñ(ξ) = x_s for (ξ, g) (at most 10 + 10 iterations), kept inside the
  /// facet's domain, and returned. On a circle this puts x̃ on the ray from the centre through
  /// x_s, so the gap (x_s − x̃)·ñ is the difference of radii; at the faceted closest point it
  /// would be off by about half the square of the angle between the two rays.
  /// `memo`, when given: its Jacobian, when `learned`, starts the iteration (else the facet's
  /// tangents and the normal do); where that does not converge, the iteration reruns from the
  /// tangents, from the same ξ. On return the memo holds the Jacobian learned and the count of
  /// corrections (facet and ξ are the caller's to set); unchanged when the point at the start
  /// is not corrected.
  CorrectedPoint project(const Facet& f, std::array<double, 2>& xi, std::span<const Vec3> x, const Vec3& xs,
                         RayMemo* memo = nullptr) const;
  /// correct(f, xi, x) with its derivatives in `d` (the ξ derivatives only when `with_xi`).
  CorrectedPoint derivatives(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x,
                             CorrectionDerivatives& d, bool with_xi = true) const;
  /// The idealised radius of surface node row `row` (−1 when it is not on the surface).
  double nodal_radius(std::int32_t row) const;

  /// Largest distance between the faceted and the idealised surface on the reference
  /// coordinates, sampled on each facet: its 3-point Gauss rule, and a grid of spacing 1/8 of
  /// the domain (9 points on a line, 9 × 9 on a quadrilateral, 45 on a triangle, plus its
  /// centroid): nodes, edge midpoints and centres included.
  double max_deviation() const;
  /// Median facet size on the reference coordinates (edge length in 2D, √area in 3D).
  double characteristic_length() const { return l_char_; }
  std::size_t n_facets() const { return facets_.size(); }

 private:
  enum class Mode : std::uint8_t { Identity, Axis, Centre, Ring };
  struct Radial {
    Vec3 c{}, e{};
    double r = 0.0;
    bool ok = false;
  };
  Radial radial(const Vec3& p) const;
  // Construction steps, in the constructor's order (each throws CorrectionError on bad data).
  void set_idealised_shape(const ContactSurface& surface);  ///< a_, k_, R_, mode_ from the data line
  void set_plane_shape();                                    ///< ... in a plane model
  void set_axisymmetric_shape();                             ///< ... in an axisymmetric model
  void set_node_radii(const ContactSurface& surface, std::span<const Vec3> X, const model::Model* model);
  [[noreturn]] void fail_no_radial_direction(const Vec3& p, const std::string& node) const;
  void set_facets(const ContactSurface& surface, std::span<const Vec3> X);
  /// Sets sign_[f] (the sign of ∫ e·n over facet f) and returns the facet's reference area.
  double orient_facet(std::size_t f);
  /// Reference offset d(ξ) and normal ñ(ξ) of facet `i`, and its reference geometry gX there;
  /// false where the point has no radial direction.
  bool reference_ideal(std::size_t i, std::array<double, 2> xi, Vec3& offset, Vec3& normal, FacetGeometry& gX) const;
  /// The same from the shape functions at ξ, sh = eval_shape(facet's shape, ξ).
  bool reference_ideal(std::size_t i, const ShapeEval& sh, Vec3& offset, Vec3& normal, FacetGeometry& gX) const;
  /// What correct_at() computes on the way, which node_derivatives() differentiates: the current
  /// and reference geometry at ξ, their frames, and the reference offset d and normal ñ.
  struct Parts {
    FacetGeometry gx, gX;
    std::array<Vec3, 3> qx{}, qX{};
    Vec3 offset{}, normal{};
    bool framed = false;   ///< qx is the current frame (the facet is not degenerate there)
    bool rotated = false;  ///< the point is x_f + Q d, ñ = Q ñ_ref (a correction other than Identity)
  };
  /// correct(facet, xi, x), with the facet's current geometry at ξ in `gx`.
  CorrectedPoint correct_at(std::size_t i, std::array<double, 2> xi, std::span<const Vec3> x, FacetGeometry& gx) const;
  /// The same from sh = eval_shape(facet's shape, ξ), with everything it computed in `parts`.
  CorrectedPoint correct_at(std::size_t i, const ShapeEval& sh, std::span<const Vec3> x, Parts& parts) const;
  /// correct_at() with the node derivatives of CorrectionDerivatives (correction_derivatives.cpp).
  CorrectedPoint node_derivatives(std::size_t i, std::array<double, 2> xi, std::span<const Vec3> x,
                                  CorrectionDerivatives& d) const;
  /// The ξ derivatives of CorrectionDerivatives by central differences around ξ.
  void xi_derivatives(std::size_t i, std::array<double, 2> xi, std::span<const Vec3> x, CorrectionDerivatives& d) const;

  model::GeometricCorrection data_;
  Mode mode_ = Mode::Axis;
  Vec3 a_{}, k_{};
  double R_ = 0.0;
  std::vector<Facet> facets_;                  ///< the surface's facets, global node rows
  std::vector<std::array<Vec3, 8>> X_;         ///< their reference node coordinates
  std::vector<std::array<double, 8>> radius_;  ///< their nodes' idealised radii
  std::vector<double> sign_;                   ///< ±1: ñ = sign · e
  struct KeyHash {
    std::size_t operator()(const std::array<std::int32_t, 8>& k) const noexcept;
  };
  std::unordered_map<std::array<std::int32_t, 8>, std::int32_t, KeyHash> index_;  ///< facet node rows → facet
  std::vector<std::int32_t> node_rows_;        ///< sorted surface node rows
  std::vector<double> node_radius_;
  double l_char_ = 0.0;
  double tol_ = 0.0;  ///< 1e-8 × the surface's size: "on the axis", "at the centre"
};

/// The corrections that apply to one contact surface: each facet takes the last one (in deck
/// order) whose surface contains it, as where assignments overlap the last one wins ([AX]);
/// facets no correction covers stay faceted.
class SurfaceCorrections {
 public:
  void add(SurfaceCorrection c) { list_.push_back(std::move(c)); }
  bool empty() const { return list_.empty(); }
  std::span<const SurfaceCorrection> list() const { return list_; }
  /// The correction that applies to facet `f`, or nullptr.
  const SurfaceCorrection* find(const Facet& f) const;
  /// The idealised point and normal at ξ of `f` on coordinates `x`; where no correction applies,
  /// the facet's own point and normal (corrected = false). `geometry`, when given, gets the
  /// facet's own geometry there, facet_geometry(f, x, ξ) (computed on the way).
  CorrectedPoint correct(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x,
                         FacetGeometry* geometry = nullptr) const;
  /// SurfaceCorrection::project() with the correction that applies to `f`; where none does, the
  /// facet's own point and normal at `xi` (unchanged).
  CorrectedPoint project(const Facet& f, std::array<double, 2>& xi, std::span<const Vec3> x, const Vec3& xs,
                         RayMemo* memo = nullptr) const;
  /// SurfaceCorrection::derivatives() with the correction that applies to `f`; where none does,
  /// the facet's own point, normal and their derivatives.
  CorrectedPoint derivatives(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x,
                             CorrectionDerivatives& d, bool with_xi = true) const;

 private:
  std::vector<SurfaceCorrection> list_;
};

/// Moves projection `p` of the slave point `xs` (a faceted closest point on master facet
/// `facets[p.facet]`) onto the master's idealised surface: ξ refined by `master.project()`, the
/// idealised point, normal and tangents, gap = (xs − x̃_m)·ñ. Unchanged where no correction
/// applies. `dim`: 2 or 3 (the tangent basis). Both discretisations measure this way.
/// `memo`: the point's last ray projection; when it was onto p.facet, the refinement starts from
/// its ξ and Jacobian instead of p.xi. Updated to this one; cleared (a cold start next time)
/// when this one is not corrected.
/// Returns whether it was corrected.
bool correct_projection(const SurfaceCorrections& master, std::span<const Facet> facets, std::span<const Vec3> x,
                        const Vec3& xs, int dim, Projection& p, RayMemo* memo = nullptr);

/// Solves J (Δξ, Δg) = rhs for the ray x̃(ξ) + g ñ(ξ) through a point, J its Jacobian at gap g
/// from `d`'s ξ derivatives (columns x̃_,α + g ñ_,α and ñ; an edge: the x–y rows). out = (Δξ…, Δg);
/// false when J is singular.
bool ray_jacobian_solve(const CorrectionDerivatives& d, const Vec3& normal, double gap, const Vec3& rhs,
                        std::array<double, 3>& out);

/// The geometric-correction data lines that apply to the contact surface `surface` (a surface
/// of `m`; empty: general contact's all-inclusive exterior surface, to which every assignment
/// applies), in deck order: those whose surface shares at least one element face with it —
/// the pin-in-hole of [AX] assigns PIN_TIP and PIN_BODY, regions of the contact surface PIN.
/// With `pair`: the lines of the *SURFACE SMOOTHING its GEOMETRIC CORRECTION names (none when it
/// names none); without: general contact's *SURFACE PROPERTY ASSIGNMENT lines.
std::vector<const model::GeometricCorrection*> corrections_for(const model::Model& m, std::string_view surface,
                                                               const model::ContactPair* pair = nullptr);

/// corrections_for() built on the reference coordinates of `m`. Throws CorrectionError.
SurfaceCorrections build_corrections(const model::Model& m, std::string_view surface,
                                     const model::ContactPair* pair = nullptr);

/// Builds every correction of the model (general contact's and every *SURFACE SMOOTHING's) once,
/// to report degenerate data before an analysis. Throws CorrectionError for the first bad line.
void validate_corrections(const model::Model& m);

}  // namespace inpact::contact
