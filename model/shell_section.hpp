#pragma once
/// *SHELL SECTION and *SHELL GENERAL SECTION as the deck gives them (Abaqus Keywords): the
/// element set, its material, the thickness, the number of section points through it and the
/// offset of the reference surface; the analysis turns them into stiffness
/// (solver/elements/shell_section.hpp).
#include <array>
#include <optional>
#include <string>

#include "source_loc.hpp"

namespace inpact::model {

struct ShellSection {
  std::string elset;
  std::string material;
  double thickness = 0.0;
  /// Simpson's rule through the thickness with this many points (odd; Abaqus's default 5).
  /// Point 1 lies on SNEG, the last on SPOS.
  int section_points = 5;
  /// Where the reference surface (the nodes) lies, as a fraction of the thickness from the
  /// midsurface along the positive normal: SPOS 0.5, SNEG −0.5, MIDDLE 0 (Abaqus's OFFSET).
  double offset = 0.0;
  /// *SHELL GENERAL SECTION: the section is integrated exactly (no section points).
  bool general = false;
  /// NODAL THICKNESS: the nodes' *NODAL THICKNESS, interpolated to the points by the kernel.
  bool nodal_thickness = false;
  /// *TRANSVERSE SHEAR STIFFNESS K11, K22, K12 (force per length); unset: 5/6 G t.
  std::optional<std::array<double, 3>> transverse_shear;
  SourceLoc loc;
};

}  // namespace inpact::model
