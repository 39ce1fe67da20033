#pragma once
/// *SHELL SECTION and *SHELL GENERAL SECTION as the deck gives them (Abaqus Keywords): the
/// element set, its material, the thickness, the number of section points through it and the
/// offset of the reference surface; the analysis turns them into stiffness
/// (solver/elements/shell_section.hpp).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// One layer (ply) of a COMPOSITE section, from SNEG up: its data line's thickness, number of
/// section points (Simpson, odd; Abaqus's default 3), material, and orientation: the name of an
/// *ORIENTATION or an angle in degrees about the normal from the section's material directions.
struct ShellLayer {
  double thickness = 0.0;
  int section_points = 3;
  std::string material;     ///< upper-case
  std::string orientation;  ///< upper-case *ORIENTATION name; empty: `angle`
  double angle = 0.0;       ///< degrees
  std::string ply;          ///< as written (output only)
  SourceLoc loc;            ///< the material's field
  SourceLoc orientation_loc;
};

struct ShellSection {
  std::string elset;
  std::string material;  ///< upper-case; empty for COMPOSITE (each layer names its own)
  /// ORIENTATION=: the section's material directions (upper-case *ORIENTATION name); empty:
  /// the shell's local axes.
  std::string orientation;
  SourceLoc orientation_loc;
  /// COMPOSITE: the layers from SNEG to SPOS (their thicknesses add up to `thickness`); empty:
  /// one layer of `material` through the whole thickness.
  std::vector<ShellLayer> layers;
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

  /// The section points through the thickness: `section_points`, or the layers' sum.
  int point_count() const {
    if (layers.empty()) return section_points;
    int n = 0;
    for (const ShellLayer& l : layers) n += l.section_points;
    return n;
  }
};

}  // namespace inpact::model
