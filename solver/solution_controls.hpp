#pragma once
/// The numbers that steer incrementation and Newton convergence, with Abaqus/Standard's
/// defaults ("Commonly used control parameters", *CONTROLS), overridden per step by
/// *CONTROLS, PARAMETERS=FIELD and PARAMETERS=TIME INCREMENTATION.
#include "model/step.hpp"

namespace inpact::solver {

struct SolutionControls {
  // PARAMETERS=FIELD, line 1.
  double residual_tolerance = 0.005;    ///< R_n: largest residual ≤ R_n · time-averaged force
  double correction_tolerance = 0.01;   ///< C_n: largest correction ≤ C_n · largest increment of u
  double linear_tolerance = 1e-8;       ///< R_l: a residual this small is accepted outright
  double zero_force = 1e-5;             ///< ε_nl: forces below ε_nl · the step's first force are "zero"
  // PARAMETERS=TIME INCREMENTATION, line 1.
  int divergence_check_after = 4;  ///< I_0: iterations before the residual may be judged diverging
  int max_iterations = 16;         ///< I_C: equilibrium iterations in one attempt
  int easy_iterations = 4;         ///< I_G: two increments this easy in a row grow the next one
  int max_cutbacks = 5;            ///< I_A: attempts of one increment beyond the first
  // Line 2.
  double cutback_factor = 0.25;  ///< D_f: after a failed attempt
  double growth_factor = 1.5;    ///< D_D: after two easy increments
  // Line 1, field 13 (augmented Lagrange, see model::TimeIncrementationControls).
  int max_augmentations = 50;
};

/// The controls in force in `step` (its *CONTROLS over the defaults).
SolutionControls solution_controls(const model::Step& step);

}  // namespace inpact::solver
