#pragma once
/// *BEAM SECTION and *BEAM GENERAL SECTION as the deck gives them. The section's area, moments
/// of inertia and torsion constant are computed for the analysis
/// (solver/elements/beam_section.hpp), not here.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

struct BeamSection {
  /// SECTION=: the library shapes inpact integrates, and GENERAL (*BEAM GENERAL SECTION's
  /// A, I11, I12, I22, J given directly).
  enum class Shape : std::uint8_t { Rect, Circ, Pipe, Box, I, General };
  std::string elset;     ///< upper-case set name
  std::string material;  ///< upper-case material name; empty for a general section (E, G given)
  Shape shape = Shape::Rect;
  /// The first data line: RECT a, b (widths along n1 and n2); CIRC r, or an ellipse's semi-axes
  /// r1, r2 along n1 and n2 (CalculiX's two-number CIRC, read from its full axes); PIPE r (outer), t; BOX
  /// a, b (outer widths along n1 and n2), t1..t4 (the walls at +n1, +n2, −n1, −n2); I l, h, b1,
  /// b2, t1, t2, t3 (the section origin l above the bottom edge, the height along n2, the bottom
  /// and top flanges' widths along n1 and thicknesses, the web's thickness); GENERAL A, I11, I12,
  /// I22, J.
  std::vector<double> dims;
  SourceLoc dims_loc;

  /// CIRC's semi-axes along n1 and n2 (a circle's radius twice).
  std::array<double, 2> circ_semi_axes() const { return {dims[0], dims.size() > 1 ? dims[1] : dims[0]}; }
  /// The approximate n1 direction of the second data line; Abaqus's default (0, 0, −1).
  std::array<double, 3> n1{0.0, 0.0, -1.0};
  SourceLoc n1_loc;
  double youngs_modulus = 0.0, shear_modulus = 0.0;  ///< GENERAL: the third data line
  /// CalculiX's OFFSET1, OFFSET2: where the node line lies across the section, in units of the
  /// section's extent along n1 and n2 from its centre (0.5: on the +n side's surface).
  std::array<double, 2> offset{0.0, 0.0};
  /// *TRANSVERSE SHEAR STIFFNESS: K23, K13 (force units) and the slenderness compensation
  /// factor (Abaqus's default 0.25), each absent when not given.
  std::optional<double> k23, k13, slenderness_compensation;
  /// *SECTION POINTS under a general section: the (x1, x2) of each point where S and E are
  /// output, from the centroid along n1 and n2, numbered in order from 1 (Abaqus: a general
  /// section has no section points of its own).
  std::vector<std::array<double, 2>> section_points;
  SourceLoc loc;
};

/// The shape's SECTION= name.
const char* shape_name(BeamSection::Shape shape);

}  // namespace inpact::model
