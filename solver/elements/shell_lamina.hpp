#pragma once
/// A shell layer's elastic lamina: plane stress in its material axes, and its turn into the
/// shell's local axes at a point (shell_elements.hpp).
///
/// In the material axes (1 along the fibre, 2 across it in the surface, 3 the normal):
///   (σ11, σ22, τ12) = Q (ε11, ε22, γ12),  (τ13, τ23) = G (γ13, γ23).
/// Material axis 1 lies at θ from the shell's local e1, turned about the normal. With c = cos θ,
/// s = sin θ the strains turn as ε_material = T ε_local,
///   T = [[c², s², cs], [s², c², −cs], [−2cs, 2cs, c² − s²]],  (γ13, γ23)_m = R (γ13, γ23)_l,
///   R = [[c, s], [−s, c]],
/// so the energy gives Q_local = Tᵀ Q T and G_local = Rᵀ G R.
#include <array>
#include <optional>

#include "material.hpp"
#include "material_orientation.hpp"
#include "model/elastic_stiffness.hpp"

namespace inpact::solver::elements {

using Matrix3x3 = std::array<std::array<double, 3>, 3>;
using Matrix2x2 = std::array<std::array<double, 2>, 2>;

struct ShellLamina {
  Matrix3x3 in_plane{};  ///< Q on (11, 22, 12)
  Matrix2x2 shear{};     ///< G on (13, 23)
  double expansion = 0.0;  ///< α, isotropic: the thermal strain α ΔT on ε11 and ε22
};

/// E, ν: Q = E/(1 − ν²) [[1, ν, 0], [ν, 1, 0], [0, 0, (1 − ν)/2]], G13 = G23 = E/(2(1 + ν)).
ShellLamina isotropic_lamina(double youngs_modulus, double poissons_ratio, double expansion);

/// From an *ELASTIC stiffness in the material axes (model::material_stiffness). A 3D stiffness
/// is condensed for σ33 = 0: Q = (S_pp)⁻¹ over p = 11, 22, 12 and G = (S_tt)⁻¹ over t = 13, 23,
/// S = D⁻¹ (its couplings between the in-plane and transverse shear terms are left out: zero for
/// an orthotropic material in its axes). `lamina` (TYPE=LAMINA): Q and G as given.
ShellLamina condensed_lamina(const model::Stiffness& d, bool lamina, double expansion);

/// The lamina in the shell's local axes when its material axis 1 lies at θ from e1.
ShellLamina turned_lamina(const ShellLamina& l, double theta);

/// Local engineering strains (ε11, ε22, γ12, γ13, γ23) in the material axes at θ.
std::array<double, 5> strains_in_material_axes(const std::array<double, 5>& local, double theta);

/// Local stresses (σ11, σ22, τ12, τ13, τ23) in the material axes at θ (a tensor's turn).
std::array<double, 5> stresses_in_material_axes(const std::array<double, 5>& local, double theta);

/// A layer of a shell section: its lamina and where its material axis 1 lies.
struct ShellLayerProperties {
  ShellLamina lamina;
  /// The *ORIENTATION giving the reference direction (its axis 1 projected on the surface at each
  /// point); none: the shell's local e1.
  std::optional<MaterialOrientation> orientation;
  double angle = 0.0;  ///< radians about the normal from the reference direction
  /// A COMPOSITE layer's own law at its section points (plastic, or elastic with temperature
  /// tables; ShellProperties::layer_laws); null: its lamina's constants.
  const Material* law = nullptr;
};

/// θ of the layer at a point with local shell axes `axes` (e1, e2, normal) and reference
/// coordinates x: the orientation's projected axis (MaterialOrientation::shell_projected_axis)
/// on the surface, or, where that axis lies within 0.1° of the normal, the next axis's
/// projection turned back by 90°.
double material_angle(const ShellLayerProperties& layer, const std::array<Vec3, 3>& axes, const Vec3& x);
/// The same for an orientation alone (none: 0), the axes of an oriented section's SF and SM.
double orientation_angle(const std::optional<MaterialOrientation>& orientation, const std::array<Vec3, 3>& axes,
                         const Vec3& x);

}  // namespace inpact::solver::elements
