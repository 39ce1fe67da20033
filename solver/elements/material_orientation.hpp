#pragma once
/// Local material axes (*ORIENTATION) and the rotation of a stiffness between frames.
///
/// The axes are the rows of Q: v_local = Q v_global. Strains in Voigt order 11 22 33 12 13 23
/// with engineering shear transform as ε_local = T(Q) ε_global, and the energy σ·ε is frame
/// independent, so σ_global = Tᵀ σ_local and
///
///   D_global = T(Q)ᵀ D_local T(Q).
#include <Eigen/Core>

#include "material.hpp"
#include "model/material.hpp"

namespace inpact::solver::elements {

class MaterialOrientation {
 public:
  explicit MaterialOrientation(const model::Orientation& orientation);

  /// Whether the axes depend on the point (cylindrical).
  bool varies() const { return cylindrical_; }
  /// The local axes at `x` (rows of Q), the additional rotation included.
  Eigen::Matrix3d axes_at(const Vec3& x) const;
  /// The axis (0-based) a shell projects onto its surface as material direction 1: Abaqus takes
  /// the second data line's axis as the one nearest the normal and projects the next in the
  /// cycle 1 → 2 → 3 → 1; without that line (CalculiX's decks) axis 1.
  int shell_projected_axis() const { return rotation_given_ ? (axis_ + 1) % 3 : 0; }

 private:
  Eigen::Matrix3d with_rotation(const Eigen::Matrix3d& axes) const;

  bool cylindrical_ = false;
  Eigen::Vector3d a_, b_;
  Eigen::Matrix3d fixed_;  ///< rectangular: the axes
  int axis_ = 0;           ///< 0-based local axis of the additional rotation
  double angle_ = 0.0;     ///< radians
  bool rotation_given_ = false;
};

/// T(Q): the engineering-shear Voigt strain of the frame whose axes are Q's rows, from the
/// global one.
Mat6 strain_rotation(const Eigen::Matrix3d& q);

/// D in the global frame from D in the frame of Q's rows: T(Q)ᵀ D T(Q).
Mat6 rotate_stiffness(const Mat6& d_local, const Eigen::Matrix3d& q);

/// A point's tensor results (S, E, PE) turned into the frame of Q's rows, as Abaqus reports an
/// oriented section's: σ_local = Q σ Qᵀ, the same for the strains (engineering shear kept).
void to_material_axes(const Eigen::Matrix3d& q, PointResult& point);

}  // namespace inpact::solver::elements
