#pragma once
/// The elastic properties of a beam cross-section as the beam kernel uses them: area, second
/// moments about the section's axes n1 and n2, the torsion constant and the transverse shear
/// stiffness, from a *BEAM SECTION shape or a *BEAM GENERAL SECTION.
///
/// Axes: t along the beam, n1 and n2 across it, t = n1 × n2 (Abaqus's local beam system).
/// I11 = ∫ x2² dA (bending about n1), I22 = ∫ x1² dA (bending about n2).
#include <array>
#include <optional>

#include "model/beam_section.hpp"

namespace inpact::solver::elements {

struct BeamProperties {
  double area = 0.0;
  double i11 = 0.0, i22 = 0.0;  ///< second moments about n1 and n2
  double torsion = 0.0;         ///< St. Venant torsion constant J
  double youngs_modulus = 0.0, shear_modulus = 0.0;
  /// Transverse shear stiffness before the slenderness compensation: k·G·A with Abaqus's shear
  /// factor k of the shape (RECT 0.85, CIRC 0.89, PIPE 0.53, BOX 0.44, GENERAL 1), or the deck's
  /// K13, K23.
  double k13 = 0.0;  ///< shear along n1
  double k23 = 0.0;  ///< shear along n2
  /// Abaqus's slenderness compensation factor (SCF, 0.25 unless given): the shear stiffness
  /// of an element of length l is scaled by 1 / (1 + ξ·SCF·l²A/(12 I)), ξ = 1 for linear and
  /// 1e-4 for quadratic elements, so that slender linear beams do not lock.
  double slenderness_compensation = 0.25;
  std::array<double, 3> n1{0.0, 0.0, -1.0};  ///< the section's approximate n1 direction
};

/// The shear factor k Abaqus uses for a shape (Abaqus Analysis User's Guide, "Choosing a beam
/// element": transverse shear stiffness), after Cowper (1966).
double shear_factor(model::BeamSection::Shape shape);

/// A, I11, I22 and J of the shape's dimensions (model::BeamSection::dims); E and G from the
/// material (library shapes) or the section's own line (GENERAL). RECT's J is St. Venant's
/// series solution, CIRC's and PIPE's the exact polar moment of the (hollow) disc, BOX's Bredt's
/// thin-walled one on the walls' midline (A and I are the exact hollow rectangle's).
BeamProperties beam_properties(const model::BeamSection& section, double youngs_modulus, double poissons_ratio);

}  // namespace inpact::solver::elements
