#pragma once
/// The elastic properties of a beam cross-section as the beam kernel uses them: area, second
/// moments about the section's axes n1 and n2, the torsion constant and the transverse shear
/// stiffness, from a *BEAM SECTION shape or a *BEAM GENERAL SECTION.
///
/// Axes: t along the beam, n1 and n2 across it, t = n1 × n2 (Abaqus's local beam system).
/// I11 = ∫ x2² dA (bending about n1), I22 = ∫ x1² dA (bending about n2).
#include <array>
#include <optional>
#include <vector>

#include "model/beam_section.hpp"

namespace inpact::solver::elements {

/// A point of the section where S and E are output (beam_section_points.hpp): its number, its
/// place from the centroid along n1 and n2, and its torsion arm c (S12 = G κ3 c).
struct BeamSectionPoint {
  int number = 1;
  double x1 = 0.0, x2 = 0.0;
  double torsion_arm = 0.0;
};

struct BeamProperties {
  double area = 0.0;
  double i11 = 0.0, i22 = 0.0;  ///< second moments about n1 and n2
  double torsion = 0.0;         ///< St. Venant torsion constant J
  double youngs_modulus = 0.0, shear_modulus = 0.0;
  /// Transverse shear stiffness before the slenderness compensation: k·G·A with Abaqus's shear
  /// factor k of the shape (RECT 0.85, CIRC 0.89, PIPE 0.53, BOX 0.44, GENERAL 1), or the deck's
  /// K13, K23. An I shears along n2 through its web (G t3 times the web's height between the
  /// flanges' midlines) and along n1 through its flanges (5/6 G of their area).
  double k13 = 0.0;  ///< shear along n1
  double k23 = 0.0;  ///< shear along n2
  /// Abaqus's slenderness compensation factor (SCF, 0.25 unless given): the shear stiffness
  /// of an element of length l is scaled by 1 / (1 + ξ·SCF·l²A/(12 I)), ξ = 1 for linear and
  /// 1e-4 for quadratic elements, so that slender linear beams do not lock.
  double slenderness_compensation = 0.25;
  std::array<double, 3> n1{0.0, 0.0, -1.0};  ///< the section's approximate n1 direction
  /// Where the section's centroid lies from the node line, along n1 and n2: an I's origin off its
  /// centroid, a BOX's unequal walls, CalculiX's OFFSET1/OFFSET2. The kernel ties the centroid's
  /// line to the nodes rigidly (beam_elements.hpp); A and I above are about the centroid.
  std::array<double, 2> centroid{0.0, 0.0};
  /// Where S and E are reported (beam_section_points.hpp); empty: the section has none.
  std::vector<BeamSectionPoint> output_points;
};

/// The shear factor k Abaqus uses for a shape (Abaqus Analysis User's Guide, "Choosing a beam
/// element": transverse shear stiffness), after Cowper (1966).
double shear_factor(model::BeamSection::Shape shape);

/// A, I11, I22 and J of the shape's dimensions (model::BeamSection::dims) about its centroid, and
/// the centroid's place; E and G from the material (library shapes) or the section's own line
/// (GENERAL). RECT's J is St. Venant's series solution, CIRC's and PIPE's the exact polar moment
/// of the (hollow) disc, BOX's Bredt's thin-walled one on the walls' midline (A and I are the
/// exact hollow rectangle's), I's the open thin-walled Σ b t³/3. The shear centre is taken at
/// the centroid: exact for the doubly symmetric shapes, an approximation for an I with unequal
/// flanges (its twist and bending do not couple here). The output section points come with them
/// (beam_output_points).
BeamProperties beam_properties(const model::BeamSection& section, double youngs_modulus, double poissons_ratio);

}  // namespace inpact::solver::elements
