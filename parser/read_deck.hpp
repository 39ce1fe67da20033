#pragma once
/// The parser's one entry point: a deck file in, a model database and diagnostics out.
#include <map>
#include <string>

#include "diagnostics.hpp"
#include "model/model.hpp"

namespace inpact::parser {

struct ReadOptions {
  /// `-P name=value`: overrides *PARAMETER definitions of the same name.
  std::map<std::string, std::string> parameters;
  std::size_t max_errors = 50;
};

struct ReadResult {
  model::Model model;
  Diagnostics diagnostics;
  bool ok() const { return !diagnostics.has_errors(); }
  /// Every diagnostic formatted `file:line:col: error: *KEYWORD: message`.
  std::string report() const { return diagnostics.format_all(model.sources); }
};

ReadResult read_deck(const std::string& path, const ReadOptions& options = {});

}  // namespace inpact::parser
