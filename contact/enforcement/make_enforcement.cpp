// The one mapping from a resolved interaction to its enforcement type.
#include "contact/enforcement/direct.hpp"
#include "contact/enforcement/law_multipliers.hpp"
#include "contact/enforcement/penalty.hpp"
#include "contact/resolved_interaction.hpp"

namespace inpact::contact {

std::unique_ptr<Enforcement> make_enforcement(const ResolvedInteraction& r) {
  switch (r.enforcement) {
    case EnforcementKind::DirectMultipliers: return std::make_unique<DirectMultipliers>(r.no_separation);
    case EnforcementKind::LawWithMultipliers:
      return std::make_unique<LawWithMultipliers>(*r.law, r.no_separation, r.augmented, r.l_char, r.ke);
    case EnforcementKind::PenaltyLaw:
    case EnforcementKind::AugmentedLagrange: break;
  }
  PenaltyOptions options;
  options.augmented = r.augmented;
  options.tied_law = r.tied_law;
  options.user_adaptive = r.user_adaptive;
  return std::make_unique<PenaltyLaw>(*r.law, options);
}

}  // namespace inpact::contact
