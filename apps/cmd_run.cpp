#include <cstdio>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "parser/read_deck.hpp"

namespace inpact::app {

int run_analysis(const RunOptions& options) {
  parser::ReadOptions read_options;
  read_options.parameters = options.parameters;
  const parser::ReadResult result = parser::read_deck(options.deck, read_options);
  std::fputs(result.report().c_str(), stderr);
  if (!result.ok()) {
    std::fprintf(stderr, "%s: %zu error(s); the deck cannot be analysed\n", options.deck.c_str(),
                 result.diagnostics.error_count());
    return kDeckError;
  }
  // The analysis procedures come with the solid mechanics core; until then say so plainly
  // rather than write results that look like an answer.
  std::fprintf(stderr, "%s: the deck is valid, but this build of inpact cannot analyse it yet "
                       "(the solver is not built); nothing was written\n", options.deck.c_str());
  return kAnalysisFailed;
}

}  // namespace inpact::app
