#pragma once
/// Linear elasticity with a general stiffness (*ELASTIC, TYPE=ENGINEERING CONSTANTS |
/// ORTHOTROPIC | ANISOTROPIC | LAMINA) in local material axes (*ORIENTATION; none: the global
/// axes), with isotropic expansion:
///
///   σ = D(x) (ε − α ΔT I),   D(x) = T(Q(x))ᵀ D_material T(Q(x))   (material_orientation.hpp)
///
/// D_material is model::material_stiffness. The stress, the strain and the tangent are global:
/// the orientation only turns the stiffness (field_output.cpp turns the reported S, E and PE into
/// the material axes, for every oriented section). A rectangular
/// orientation turns it once; a cylindrical one at each point, from the point's reference
/// coordinates (the axes do not follow the deformation with NLGEOM: S = D E, St. Venant–Kirchhoff
/// in the reference frame, as the isotropic law). Stateless.
///
/// Families: 3D, plane strain and axisymmetric use the 3D D (ε33 = 0 resp. the hoop strain
/// comes in the strain; σ13, σ23 of a coupled D are reported but do no work). Plane stress
/// condenses the compliance for σ33 = σ13 = σ23 = 0: D_ps = (S_pp)⁻¹ on 11, 22, 12 with
/// S = D⁻¹, zero rows and columns for 33, 13, 23, as elasticity_matrix has them; the output
/// thickness strain is ε33 = S_3p σ_p + ε_th. LAMINA gives no out-of-plane constants: plane
/// stress only, its D_ps taken as given, ε33 = ε_th reported.
#include <optional>

#include "material.hpp"
#include "material_orientation.hpp"

namespace inpact::solver::elements {

class AnisotropicElastic final : public Material {
 public:
  /// `d_material`: the 3D stiffness in the material axes (for a lamina: the plane-stress one in
  /// the 11, 22, 12 rows, zero 33 row); `lamina` for TYPE=LAMINA; `expansion` α.
  AnisotropicElastic(model::ElementFamily family, const Mat6& d_material, double expansion,
                     std::optional<MaterialOrientation> orientation, bool lamina = false);

  const Mat6& update(const MaterialPointInput& in, const PointHistory&, Vec6& stress, Mat6& scratch) const override;
  /// Isotropic stand-ins for what needs E, ν, G (hourglass control, the locking warning): the
  /// Voigt averages of D, K = Σᵢⱼ≤₃ Dᵢⱼ / 9, G = (D11 + D22 + D33 − D12 − D13 − D23 + 3(D44 + D55
  /// + D66)) / 15, which are frame independent and exact for an isotropic D. α as given.
  const ElasticConstants& elastic() const override { return constants_; }
  double plane_stress_thickness_strain(const Vec3& position, const Vec6& strain, const Vec6& stress,
                                       double thermal_strain, double temperature,
                                       std::span<const double> state) const override;

  /// The tangent (and stiffness) at a point at `x`, in the global frame, for the family.
  Mat6 stiffness_at(const Vec3& x) const;

 private:
  Mat6 family_stiffness(const Mat6& d_global) const;

  model::ElementFamily family_;
  Mat6 d_material_;
  std::optional<MaterialOrientation> orientation_;
  bool lamina_ = false;
  ElasticConstants constants_;
  Mat6 d_fixed_;  ///< the tangent when the axes do not vary with the point
};

}  // namespace inpact::solver::elements
