#pragma once
/// Where a beam reports its stresses: the section points of its cross-section, and S and E there
/// from the section strains of an integration point.
///
/// inpact's sections are elastic and integrated once (beam_section.hpp), so, as for Abaqus's
/// general sections, section points are output locations only. At a point (x1, x2) from the
/// centroid (x along n1 and n2), with the section strains ε, κ1, κ2, κ3 (beam_elements.hpp):
///   E11 = ε + κ1 x2 − κ2 x1,  S11 = E · E11       (a plane section turns rigidly)
///   E12 = κ3 c,               S12 = G · E12       (St. Venant's torsional shear)
/// with c the point's torsion arm: r on a solid or hollow circle's surface; J/(2 A_m t) in a
/// closed thin wall (Bredt); t, the wall's face, in an open one (the I); 0 at a rectangle's
/// corners. S12 is the shear along the section's surface or wall, positive with the torque;
/// transverse shear is reported as SF only (Abaqus does the same).
///
/// The points output, per shape (Abaqus's default output points where the manual states them):
///  - RECT: 1, 5, 21, 25 of its 5 × 5 grid, the corners (−a/2, −b/2), (a/2, −b/2), (−a/2, b/2),
///    (a/2, b/2). Stated by Abaqus: 25 points, output at 1, 5, 21, 25; the grid numbered along
///    n1 first from the (−, −) corner is inpact's reading of the manual's figure.
///  - CIRC: 3, 7, 11, 15, on the surface at +n1, +n2, −n1, −n2 (Abaqus: 17 points, output at 3,
///    7, 11, 15, "on the intersection of the surface with the 1- and 2-axes"; the order around is
///    inpact's reading).
///  - PIPE: 8 points on the outer surface, counterclockwise from +n1 every 45°, numbered 1..8
///    (inpact's numbering; Abaqus's is not confirmed).
///  - BOX: the corners of the walls' midline, 1 at (+, −), 5 at (+, +), 9 at (−, +), 13 at (−, −),
///    the numbers of a 16-point walk around the walls (inpact's numbering, not confirmed).
///  - I: the flange tips on the flanges' midlines, 1 and 5 the bottom flange's (−n1, +n1), 11
///    and 15 the top flange's (inpact's numbering of a 15-point I, not confirmed).
///  - GENERAL: the points of *SECTION POINTS, numbered in order; S11 and E11 only (Abaqus:
///    "axial stress and axial strain output"); none without *SECTION POINTS.
#include <vector>

#include "beam_section.hpp"
#include "element_kernel.hpp"

namespace inpact::solver::elements {

/// The section points `section` reports S and E at (above), their places from its centroid.
std::vector<BeamSectionPoint> beam_output_points(const model::BeamSection& section, const BeamProperties& properties);

/// S and E at each of the section's output points from the integration point `at` (its section
/// strains, beam_elements.hpp): one result each, in the section's order, with S11 and S12 in the
/// stress's slots 0 and 3, E11 and E12 (engineering) in the strain's, and `at`'s coordinates and
/// section forces.
void beam_section_point_results(const BeamProperties& section, const PointResult& at, std::vector<PointResult>& out);

}  // namespace inpact::solver::elements
