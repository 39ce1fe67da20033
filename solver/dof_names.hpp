#pragma once
/// How messages name a global degree of freedom: the deck's node label and Abaqus's DOF number.
#include <cstdint>
#include <string>

#include "analysis_model.hpp"

namespace inpact::solver {

/// "node 262 DOF 5" for global DOF d (a part instance's node as `instance.262`); a rotation
/// node's DOFs are its reference node's 4–6 (6 in 2D).
std::string node_dof(const AnalysisModel& am, std::int64_t d);

}  // namespace inpact::solver
