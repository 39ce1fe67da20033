#pragma once
/// *PARAMETER: `name = expression` data lines. Expressions are the arithmetic subset of the
/// Python that Abaqus evaluates: numbers, earlier parameters, + - * / ** and parentheses, and
/// quoted strings. Values are kept as the text substituted for `<name>`.
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace inpact::parser {

/// Evaluates `expr` against the parameters defined so far. On failure returns nullopt and
/// sets `error` to what is wrong.
std::optional<std::string> evaluate_parameter(std::string_view expr,
                                              const std::map<std::string, std::string>& defined,
                                              std::string& error);

/// Formats a number the way it is substituted: integral values without a decimal point.
std::string format_parameter_number(double v);

}  // namespace inpact::parser
