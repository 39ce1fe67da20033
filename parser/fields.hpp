#pragma once
/// Data lines split into comma-separated fields, each with the column it starts at, and the
/// number conversions Abaqus decks need (Fortran `1.5D3` exponents, leading `+`, `.5`).
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "model/source_loc.hpp"

namespace inpact::parser {

/// One physical line of the deck (comments and blank lines never reach the handlers).
struct Line {
  std::string_view text;
  model::SourceLoc loc;  ///< col = 0
};

struct Field {
  std::string_view text;  ///< trimmed
  model::SourceLoc loc;   ///< col = where the field starts
  bool empty() const { return text.empty(); }
};

/// Splits `line` into fields. A trailing comma does not make an empty last field (Abaqus
/// decks often end data lines with one); `a,,b` gives an empty middle field.
void split_fields(const Line& line, std::vector<Field>& out);

std::optional<std::int64_t> parse_int(std::string_view s);
std::optional<double> parse_real(std::string_view s);

}  // namespace inpact::parser
