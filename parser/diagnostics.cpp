#include "diagnostics.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace inpact::parser {

void Diagnostics::error(SourceLoc loc, std::string keyword, std::string message) {
  items_.push_back({Diagnostic::Severity::Error, loc, std::move(keyword), std::move(message)});
  if (++n_errors_ >= max_errors_)
    throw StopReading(fmt::format("stopped after {} errors", n_errors_));
}

void Diagnostics::warning(SourceLoc loc, std::string keyword, std::string message) {
  items_.push_back({Diagnostic::Severity::Warning, loc, std::move(keyword), std::move(message)});
}

std::string describe(SourceLoc loc, const SourceTable& sources) { return sources.describe(loc); }

std::string Diagnostics::format(const Diagnostic& d, const SourceTable& sources) const {
  std::string out = fmt::format("{}: {}: ", describe(d.loc, sources),
                                d.severity == Diagnostic::Severity::Error ? "error" : "warning");
  if (!d.keyword.empty()) out += d.keyword + ": ";
  out += d.message;
  // The include chain, innermost first, as compilers print it.
  std::uint32_t file = d.loc.file;
  for (int depth = 0; depth < 64 && file < sources.files.size() && sources.files[file].included;
       ++depth) {
    const SourceLoc from = sources.files[file].included_from;
    out += fmt::format("\n  included from {}", describe({from.file, from.line, 0}, sources));
    file = from.file;
  }
  return out;
}

std::string Diagnostics::format_all(const SourceTable& sources) const {
  std::string out;
  for (const auto& d : items_) out += format(d, sources) + "\n";
  return out;
}

namespace {
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}
}  // namespace

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

}  // namespace inpact::parser
