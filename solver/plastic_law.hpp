#pragma once
/// The Mises law of a material with *PLASTIC, for solids and shells alike: one rule for which
/// hardening model and which strain measure a section's points take.
#include <memory>
#include <string>
#include <vector>

#include "elements/material.hpp"
#include "model/model.hpp"

namespace inpact::solver {

/// The Mises material of `mat`'s *PLASTIC for elements of `family`, with elastic constants `c`.
/// Small strain: MisesPlasticity (isotropic or linear kinematic, with its own plane stress
/// iteration) or CombinedPlasticity (HARDENING=COMBINED, and KINEMATIC with several
/// temperatures). `finite_strain` (a continuum under NLGEOM): isotropic hardening in the
/// exponential-map law, kinematic and combined hardening through the Lagrangian logarithmic
/// strain. Plane stress takes the 3D laws through PlaneStressCondensation (σ33 = 0 at each
/// point). What the fit of half-cycle data found goes into `warnings`.
std::shared_ptr<elements::Material> plastic_law(const model::Model& m, const model::Material& mat,
                                                model::ElementFamily family, const elements::ElasticConstants& c,
                                                bool finite_strain, std::vector<std::string>& warnings);

}  // namespace inpact::solver
