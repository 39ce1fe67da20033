#pragma once
/// A shell section as the shell kernel uses it (shell_elements.hpp): its layers' elastic laminae
/// (one layer through the whole thickness unless COMPOSITE), where the reference surface lies,
/// the section points through the thickness and the transverse shear stiffness. The thickness
/// itself is per element (SectionData::thickness), or per node with *NODAL THICKNESS
/// (SectionData::nodal_thickness, interpolated to the points); the layers keep their fractions
/// of it.
#include <array>
#include <optional>
#include <vector>

#include "model/shell_section.hpp"
#include "shell_lamina.hpp"

namespace inpact::solver::elements {

struct ShellProperties {
  std::vector<ShellLayerProperties> layers;  ///< from SNEG up
  /// The reference surface's position as a fraction of the thickness from the midsurface along
  /// the positive normal (model::ShellSection::offset).
  double offset = 0.0;
  /// The section points ζ ∈ [−1, 1] (−1 = SNEG, +1 = SPOS), numbered from SNEG up through the
  /// layers as Abaqus numbers them; their Simpson weights within their layer (sum 2) and layer.
  std::vector<double> zeta, weight;
  std::vector<int> layer_of;
  /// *TRANSVERSE SHEAR STIFFNESS K11, K22 (force per length): the transverse shear stress is
  /// taken uniform through the thickness, its modulus K/t. Unset: 5/6 of each layer's own G at
  /// its section points (5/6 Σ G_k t_k in all, the thickness-weighted mean of the layers').
  std::optional<std::array<double, 2>> transverse_shear;
  /// The section's *ORIENTATION (ORIENTATION=): the axes SF and SM are reported in (Abaqus
  /// outputs a shell's element variables in its local directions); none: the shell's default.
  std::optional<MaterialOrientation> orientation;
  /// Each layer's points take their layer's law (ShellLayerProperties::law; a COMPOSITE with a
  /// plastic or tabulated layer); false: the element's material law, if any, at every point.
  bool layer_laws = false;
  /// Some layer's law reads temperatures (a table), whatever the element's law does.
  bool layer_temperatures = false;

  const ShellLayerProperties& layer_at(std::size_t point) const {
    return layers[static_cast<std::size_t>(layer_of[point])];
  }
  /// The law at section point k: its layer's with layer_laws, else the element's (null: the
  /// layer's elastic constants).
  const Material* law_at(std::size_t point, const Material* element_law) const {
    return layer_laws ? layer_at(point).law : element_law;
  }
};

/// Simpson's rule with n (odd, ≥ 3) points on [−1, 1].
void simpson_points(int n, std::vector<double>& zeta, std::vector<double>& weight);

/// The section of `layers` (one per model layer, or one for a section that is not COMPOSITE)
/// with Simpson's points in each: the section's number (Abaqus's default 5) for one layer, each
/// layer's own (default 3) for COMPOSITE; a general section is integrated with 3 points a layer,
/// exact for its linear elastic stiffness.
ShellProperties shell_properties(const model::ShellSection& section, std::vector<ShellLayerProperties> layers);

/// One isotropic elastic layer (E, ν, α): the plain section.
ShellProperties shell_properties(const model::ShellSection& section, double youngs_modulus, double poissons_ratio,
                                 double expansion);

/// A bending stiffness per unit width of the section of thickness t about its midsurface,
/// Σ_points w (t/2) z² (Q11 + Q22)/2: E t³/(12(1 − ν²)) for an isotropic one. It sizes the
/// drilling spring.
double section_bending_stiffness(const ShellProperties& section, double thickness);

}  // namespace inpact::solver::elements
