#pragma once
/// What an analytical rigid surface (model/analytical_surface.hpp) must be before an analysis:
/// carried by a *RIGID BODY, a profile that builds (contact/analytical_profile.hpp) for the
/// model's dimension, and the master of contact pairs without ADJUST, not of general contact
/// (that it is never a slave: check_contact_supported, contact_problem.hpp).
/// Each violation is a deck error naming the line (AnalysisError), raised by check, as by run.
#include "analysis_model.hpp"

namespace inpact::solver {

/// Throws AnalysisError at the first violation. `am`: its contact table and its interactions of
/// every step resolved.
void check_analytical_surfaces(const AnalysisModel& am);

}  // namespace inpact::solver
