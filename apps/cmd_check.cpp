#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/model_summary.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::app {

int run_check(const CheckOptions& options) {
  parser::ReadOptions read_options;
  read_options.parameters = options.parameters;
  const parser::ReadResult result = parser::read_deck(options.deck, read_options);
  // Warnings and errors go to stderr, each `file:line:col: error: *KEYWORD: message`.
  std::fputs(result.report().c_str(), stderr);
  if (!result.ok()) {
    std::fprintf(stderr, "%s: %zu error(s); the deck cannot be analysed\n", options.deck.c_str(),
                 result.diagnostics.error_count());
    return kDeckError;
  }
  // What only the analysis can see (element kinds mixed, features not analysed yet) is part of
  // the datacheck too.
  try {
    solver::build_analysis_model(result.model);
  } catch (const solver::AnalysisError& e) {
    std::fprintf(stderr, "%s\n%s: the deck cannot be analysed\n", e.what(), options.deck.c_str());
    return kDeckError;
  }
  io::write_model_summary(std::cout, result.model);
  std::cout << "\n" << options.deck << ": the deck is valid\n";
  return kOk;
}

}  // namespace inpact::app
