#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "commands.hpp"
#include "deck_loading.hpp"
#include "exit_codes.hpp"
#include "io/model_summary.hpp"
#include "solver/analysis_model.hpp"
#include "solver/linear_solver_choice.hpp"

namespace inpact::app {

int run_check(const CheckOptions& options) {
  const auto result = load_analysable_deck(options.deck, options.parameters);
  if (!result) return kDeckError;
  solver::SolverChoice choice;
  try {
    choice = solver::resolve_linear_solver(options.solver, result->model);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "inpact: error: %s\n", e.what());
    return kUsage;
  }
  // The analysis model resolves every contact interaction per step: the summary prints what the
  // run will enforce, from the same records (load_analysable_deck has validated it already).
  const solver::AnalysisModel am = solver::build_analysis_model(result->model);
  io::write_model_summary(std::cout, result->model, am.interactions);
  // What contact leaves out or decides for the deck (the run prints the same notes).
  for (const auto& note : am.contact->notes) std::cout << "\n" << note << "\n";
  std::cout << "\n" << solver::describe(choice) << "\n";
  std::cout << "\n" << options.deck << ": the deck is valid\n";
  return kOk;
}

}  // namespace inpact::app
