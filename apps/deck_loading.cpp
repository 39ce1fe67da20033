#include "deck_loading.hpp"

#include <cstdio>

#include "contact/initial_adjustment.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::app {

std::optional<parser::ReadResult> load_analysable_deck(const std::string& deck,
                                                       const std::map<std::string, std::string>& parameters) {
  parser::ReadOptions read_options;
  read_options.parameters = parameters;
  parser::ReadResult result = parser::read_deck(deck, read_options);
  // Warnings and errors go to stderr, each `file:line:col: error: *KEYWORD: message`.
  std::fputs(result.report().c_str(), stderr);
  if (!result.ok()) {
    std::fprintf(stderr, "%s: %zu error(s); the deck cannot be analysed\n", deck.c_str(),
                 result.diagnostics.error_count());
    return std::nullopt;
  }
  try {
    contact::apply_adjust(result.model);  // ADJUST: slave nodes onto their masters, strain-free
    const solver::AnalysisModel am = solver::build_analysis_model(result.model);
    for (const auto& w : am.warnings) std::fprintf(stderr, "%s: warning: %s\n", deck.c_str(), w.c_str());
    // What only a step's conditions and DOF map find, before any step is analysed.
    solver::check_step_setup(am);
  } catch (const solver::AnalysisError& e) {
    std::fprintf(stderr, "%s\n%s: the deck cannot be analysed\n", e.what(), deck.c_str());
    return std::nullopt;
  }
  return result;
}

}  // namespace inpact::app
