#pragma once
/// Contact of a slave surface with an analytical rigid surface (analytical_shape.hpp) carried by
/// the reference node R of its *RIGID BODY: x = x_R + Q(θ)(X − X_R) for every point X of the
/// surface in its reference placement, θ the rotation vector the body's rotation node holds.
/// The placement is the exact rotation Q(θ) (model/rigid_motion.hpp, finite) in every step: the
/// surface has no nodes whose small-rotation motion it would have to agree with, and an exact
/// rotation keeps it rigid.
///
/// A slave point x_s is taken into the body frame, X_s = X_R + Qᵀ(x_s − x_R), measured there
/// (exact, no facets, no search) and the result turned back: the gap g, the normal n = Q N at the
/// closest point x_c. Its linearisation over the unknowns [x_s; u_R; θ] (the slave node, the
/// reference node, the rotation node):
///   ∂g = [n; −n; −(∂(Q r)/∂θ_k)·n],  r = X_c − X_R,
/// and for finite sliding the curvature of the distance field in x_s, H = Q ∇²g Qᵀ, in the
/// [x_s; u_R] blocks as [H, −H; −H, H] (the rotation's second-order terms are left out).
///
/// Node to surface measures each slave node; surface to surface weights the gap of the slave
/// faces' integration points with the node's shape function, g_a = ∫ N_a g dA / ∫ N_a dA, over
/// the faces around it (its gradient: the points' gradients weighted alike; the change of the
/// weights with the slave's own shape is left out, it vanishes with the gap).
/// Friction acts at the slave node's own closest point (both discretisations): its zero-shear
/// point is a material point of the surface, kept in the body frame (material_point()), and
/// friction_motion() gives the slave's motion from it and its derivative over [x_s; u_R; θ].
#include <cstdint>
#include <span>
#include <vector>

#include "contact/analytical_shape.hpp"
#include "contact/pair_kinematics.hpp"

namespace inpact::contact {

class AnalyticalPair final : public PairKinematics {
 public:
  /// `master` is an analytical surface of `model` named by a *RIGID BODY (its reference node).
  /// Throws std::invalid_argument when it is not, or its shape cannot be built.
  AnalyticalPair(const model::Model& model, const model::Surface& slave, const model::Surface& master, int dim,
                 double out_of_plane_thickness, bool surface_to_surface);

  /// Node to surface: EXTENSION ZONE, the fraction of an end piece's length by which the
  /// profile goes on straight beyond its free ends (Profile::closest; default 0.1, Abaqus's).
  void set_extension_zone(double zone) { extension_zone_ = zone; }

  void update(std::span<const Vec3> x, std::vector<SlaveKinematics>& out) override;
  void linearize(std::span<const Vec3> x, SlaveKinematics& k, bool finite_sliding) const override;

  /// Slave node `local`'s own closest point at the last update, in the body frame (X_c).
  Vec3 material_point(std::size_t local) const;
  /// Friction kinematics of slave node `local` at the last update: dx = x_s − x(anchor), the
  /// anchor (a body-frame point) placed with the body, and D = ∂Δx/∂u (3 × 3 dim, row-major) over
  /// [x_s; u_R; θ] with the material point under the slave standing for the anchor (as for facets,
  /// friction.hpp): [I, −I, −∂(Q r)/∂θ].
  void friction_motion(std::span<const Vec3> x, std::size_t local, const Vec3& anchor, Vec3& dx,
                       std::vector<double>& D) const;

 private:
  /// The rigid body's placement on coordinates x: x_R, θ and Q(θ).
  void place(std::span<const Vec3> x);
  /// The shape's closest point to current point xs, turned into the current placement; `r` gets
  /// its body-frame offset X_c − X_R. `extension`: how far the profile goes on beyond its free
  /// ends (Profile::closest).
  ShapePoint measure(const Vec3& xs, Vec3& r, double extension = 0.0) const;
  /// The gap gradient of one measured point over [x_s; u_R; θ] (3 dim entries).
  void point_gradient(const ShapePoint& sp, const Vec3& r, std::span<double> out) const;
  void update_nodes(std::span<const Vec3> x, std::vector<SlaveKinematics>& out);
  void update_weighted(std::span<const Vec3> x, std::vector<SlaveKinematics>& out);

  AnalyticalShape shape_;
  std::int32_t ref_ = -1, rot_ = -1;
  Vec3 ref_X_{}, rot_X_{};  ///< reference coordinates of the reference and rotation nodes
  bool surface_to_surface_ = false;
  double extension_zone_ = 0.1;
  // The placement of the last update().
  Vec3 x_R_{}, theta_{};
  std::array<Vec3, 3> Q_{};  ///< columns Q e_k
  /// Per slave node, from the last update(): node to surface, its point's curvature (current
  /// frame) and body-frame offset; surface to surface, the weighted gradient over the node
  /// list of k.lin.
  struct NodeCache {
    ShapePoint point;
    Vec3 r{};
    ShapePoint own;  ///< surface to surface: the node's own closest point (friction acts there)
    Vec3 own_r{};
    std::vector<std::int32_t> nodes;
    std::vector<double> gradient;
  };
  std::vector<NodeCache> cache_;
};

}  // namespace inpact::contact
