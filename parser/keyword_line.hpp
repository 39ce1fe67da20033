#pragma once
/// A keyword line (`*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, PENALTY`) split into the
/// keyword and its parameters, each with its column.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fields.hpp"

namespace inpact::parser {

struct KeywordParam {
  std::string name;               ///< normalized (upper case, no blanks)
  std::optional<std::string> value;  ///< as written, trimmed, quotes removed
  model::SourceLoc loc;           ///< column of the parameter name
  model::SourceLoc value_loc;     ///< column of the value
};

struct KeywordLine {
  std::string name;  ///< normalized: "SURFACEBEHAVIOR"
  std::string text;  ///< as written (first word), for messages
  std::vector<KeywordParam> params;
  model::SourceLoc loc;
};

/// Is this a keyword line (starts with one `*`)? Comments were dropped before.
bool is_keyword_line(std::string_view text);

/// Parses one keyword line, possibly joined from continuation lines (a keyword line ending in a
/// comma continues on the next). `pieces` are the physical lines.
KeywordLine parse_keyword_line(const std::vector<Line>& pieces);

}  // namespace inpact::parser
