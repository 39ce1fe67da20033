#include <iostream>

#include "commands.hpp"
#include "deck_loading.hpp"
#include "exit_codes.hpp"
#include "io/model_summary.hpp"

namespace inpact::app {

int run_check(const CheckOptions& options) {
  const auto result = load_analysable_deck(options.deck, options.parameters);
  if (!result) return kDeckError;
  io::write_model_summary(std::cout, result->model);
  std::cout << "\n" << options.deck << ": the deck is valid\n";
  return kOk;
}

}  // namespace inpact::app
