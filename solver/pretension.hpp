#pragma once
/// The force a *PRE-TENSION SECTION carries, for the output of its pre-tension node.
#include <span>
#include <vector>

#include "analysis_model.hpp"

namespace inpact::solver {

/// N = Σ_copies n · (f_int − f_ext) at the copies of the section nodes: the force the underlying
/// elements transmit across the cut, along the normal (positive = tension). At equilibrium it
/// equals the load on DOF 1 of the pre-tension node while that DOF is free, and the reaction plus
/// that load while it is prescribed.
double pretension_force(const AnalysisModel& am, const model::PretensionSection& s, std::span<const double> f_int,
                        std::span<const double> f_ext);

/// Writes each section's N into `rf` at DOF 1 of its pre-tension node: the RF reported there is the
/// bolt force in every step (Abaqus's TF = RF + CF at that node; CalculiX's RF), whether the load
/// or a boundary condition drives the node.
void report_pretension_forces(const AnalysisModel& am, std::span<const double> f_int, std::span<const double> f_ext,
                              std::vector<double>& rf);

}  // namespace inpact::solver
