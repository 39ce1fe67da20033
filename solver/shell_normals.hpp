#pragma once
/// The directors of conventional shells, as Abaqus defines them without *NORMAL: at a node where
/// several shell elements meet, each takes the average of its own normal there and those of the
/// others within 20° of it, so a faceted curved surface bends as a smooth one; a fold sharper than
/// 20° keeps each side's own normal. Only the elements whose directors change this way get the
/// averaged ones (SectionData::shell_directors); the others keep their own. A director the deck
/// gives, by *NORMAL at an element's node or after a node's coordinates on *NODE, replaces the
/// averaged one (*NORMAL's first).
#include "analysis_model.hpp"

namespace inpact::solver {

/// The angle within which normals at a node are averaged (Abaqus's default, 20°).
constexpr double kNormalAveragingDegrees = 20.0;

/// Sets SectionData::shell_directors of the shells (am.elements with a shell section) whose
/// averaged or given (*NORMAL) nodal normals differ from their own; a given normal far from the
/// element's own adds a warning to am.warnings.
void average_shell_normals(const model::Model& m, AnalysisModel& am);

}  // namespace inpact::solver
