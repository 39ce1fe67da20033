#pragma once
/// Deck errors and warnings: collected (several before stopping), each citing file:line:col,
/// the keyword and what was expected, with the chain of *INCLUDE files that led there.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/source_loc.hpp"

namespace inpact::parser {

using model::SourceLoc;
using model::SourceTable;

struct Diagnostic {
  enum class Severity { Error, Warning } severity;
  SourceLoc loc;
  std::string keyword;  ///< "*SURFACE BEHAVIOR", or empty
  std::string message;
};

/// Thrown to stop reading once too many errors were collected (or on an unrecoverable one).
struct StopReading : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Diagnostics {
 public:
  explicit Diagnostics(std::size_t max_errors = 50) : max_errors_(max_errors) {}

  void error(SourceLoc loc, std::string keyword, std::string message);
  void warning(SourceLoc loc, std::string keyword, std::string message);

  std::size_t error_count() const { return n_errors_; }
  bool has_errors() const { return n_errors_ > 0; }
  const std::vector<Diagnostic>& all() const { return items_; }

  /// `deck.inp:157:12: error: *SURFACE BEHAVIOR: unknown parameter ...` plus include chain lines.
  std::string format(const Diagnostic& d, const SourceTable& sources) const;
  std::string format_all(const SourceTable& sources) const;

 private:
  std::vector<Diagnostic> items_;
  std::size_t n_errors_ = 0;
  std::size_t max_errors_;
};

/// "file:line:col" for a location.
std::string describe(SourceLoc loc, const SourceTable& sources);

/// The closest candidate by edit distance, if it is close enough to be a plausible typo.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace inpact::parser
