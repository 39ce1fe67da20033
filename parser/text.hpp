#pragma once
/// Small text helpers shared by the reader and the keyword handlers.
#include <string>
#include <string_view>

namespace inpact::parser {

std::string_view trim(std::string_view s);
/// Upper case with every blank removed: how Abaqus compares keyword and parameter names
/// (`*END STEP` = `*ENDSTEP`, `small sliding` = `SMALLSLIDING`).
std::string normalize_name(std::string_view s);
/// Upper case, blanks at the ends removed, quotes stripped: how set, surface and material names
/// are compared (Abaqus names are case-insensitive).
std::string normalize_label(std::string_view s);

}  // namespace inpact::parser
