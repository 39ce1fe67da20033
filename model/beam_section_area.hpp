#pragma once
/// The cross-section area of a *BEAM SECTION's dimensions: the one formula the beam kernel's
/// section properties (solver/elements/beam_section.hpp) and a pre-tension section's summary use.
#include "beam_section.hpp"

namespace inpact::model {

double section_area(const BeamSection& section);

}  // namespace inpact::model
