#pragma once
/// A shell section as the shell kernel uses it (shell_elements.hpp): the lamina's elasticity,
/// where the reference surface lies, the section points through the thickness and the
/// transverse shear stiffness. The thickness itself is per element (SectionData::thickness), or
/// per node with *NODAL THICKNESS (SectionData::nodal_thickness, interpolated to the points).
#include <array>
#include <optional>
#include <vector>

#include "model/shell_section.hpp"

namespace inpact::solver::elements {

struct ShellProperties {
  double youngs_modulus = 0.0, poissons_ratio = 0.0;
  double expansion = 0.0;  ///< α: an in-plane thermal strain α·ΔT, uniform through the thickness
  /// The reference surface's position as a fraction of the thickness from the midsurface along
  /// the positive normal (model::ShellSection::offset).
  double offset = 0.0;
  /// The section points ζ ∈ [−1, 1] (−1 = SNEG, +1 = SPOS) and their Simpson weights (sum 2).
  std::vector<double> zeta, weight;
  /// *TRANSVERSE SHEAR STIFFNESS K11, K22 (force per length), else 5/6·G·t: the transverse
  /// shear stress is taken uniform through the thickness, its modulus K/t.
  std::optional<std::array<double, 2>> transverse_shear;

  double shear_modulus() const { return youngs_modulus / (2 * (1 + poissons_ratio)); }
};

/// Simpson's rule with n (odd, ≥ 3) points on [−1, 1].
void simpson_points(int n, std::vector<double>& zeta, std::vector<double>& weight);

/// The properties of a section of an isotropic elastic material. A general section is
/// integrated with 3 points, exact for its linear elastic stiffness.
ShellProperties shell_properties(const model::ShellSection& section, double youngs_modulus, double poissons_ratio,
                                 double expansion);

}  // namespace inpact::solver::elements
