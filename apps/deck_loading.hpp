#pragma once
/// Reading a deck for a command: diagnostics to stderr, and the checks only the analysis can
/// make (element kinds mixed, features not analysed yet), so `check` and `run` agree on what
/// a valid deck is.
#include <map>
#include <optional>
#include <string>

#include "parser/read_deck.hpp"

namespace inpact::app {

/// The model of `deck`, or nullopt after printing why it cannot be analysed (exit code 3).
std::optional<parser::ReadResult> load_analysable_deck(const std::string& deck,
                                                       const std::map<std::string, std::string>& parameters);

}  // namespace inpact::app
