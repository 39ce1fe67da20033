#pragma once
/// The output variable identifiers inpact accepts in output requests, by where they live: the
/// Abaqus names (Abaqus Analysis User's Guide, "Abaqus/Standard output variable identifiers")
/// and the CalculiX keys of *NODE FILE, *EL FILE, *CONTACT FILE and the print keywords [CCX].
/// Knowing a name does not mean inpact computes it: the solver says what it writes.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace inpact::parser {

enum class OutputDomain : std::uint8_t { Node, Element, Contact };

/// True when `name` (upper case) is a variable of `domain`, or one component of one: U1, UR3,
/// S12, SDV4 (history and print requests may ask for single components).
bool is_output_variable(OutputDomain domain, std::string_view name);

/// The name an output request stores for `name` (upper case): itself, except that CalculiX
/// reads only the first four letters of its contact keys, so CSTRE is CSTR and CDISP... is
/// CDIS unless it is an Abaqus name (CSTRESS, CDISP stay as they are).
std::string canonical_output_name(OutputDomain domain, std::string_view name);

/// Every variable name of a domain (without components), for "did you mean" suggestions.
std::vector<std::string> output_variable_names(OutputDomain domain);

}  // namespace inpact::parser
