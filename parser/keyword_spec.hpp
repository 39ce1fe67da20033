#pragma once
/// The contract between the reader and the keyword handlers: each keyword declares its
/// parameters (spelling, value type, choices, required), where it may appear and whether it
/// takes data lines; the reader checks all of that before the handler runs, so handlers only
/// interpret. The one table of keywords is in keyword_table.cpp.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "build_state.hpp"
#include "diagnostics.hpp"
#include "keyword_line.hpp"

namespace inpact::parser {

enum class ValueKind : std::uint8_t {
  None,      ///< a bare flag: `NLGEOM`
  Required,  ///< `NAME=value`
  Optional   ///< either: `PENALTY` or `PENALTY=NONLINEAR`
};

enum class ValueType : std::uint8_t {
  Text,         ///< anything (names, file paths)
  Int,
  Real,
  Choice,       ///< one of `choices` (compared without case and blanks)
  RealOrChoice  ///< a number or one of `choices` (`STIFFNESS SCALE FACTOR=USER ADAPTIVE`)
};

struct ParamSpec {
  std::string_view name;  ///< canonical spelling, e.g. "PRESSURE-OVERCLOSURE"
  ValueKind value = ValueKind::None;
  ValueType type = ValueType::Text;
  std::vector<std::string_view> choices = {};
  bool required = false;
};

enum class DataLines : std::uint8_t { None, Optional, Required };

struct KeywordContext;
using Handler = void (*)(KeywordContext&);

struct KeywordSpec {
  std::string_view name;  ///< canonical spelling with the star: "*SURFACE BEHAVIOR"
  unsigned scopes = kAnyScope;
  std::vector<ParamSpec> params;
  DataLines data = DataLines::None;
  Handler handler = nullptr;
  /// Non-empty: a sub-option that must follow one of these parent keywords (or its siblings).
  std::vector<std::string_view> parents = {};
  /// True for keywords whose data may come from a file (`INPUT=`).
  bool input_file = false;
  /// Set for keywords whose data lines hold numbers from this field (0-based) on: a field there
  /// that the handler does not read (a temperature column, an Abaqus/Explicit or CalculiX
  /// extra) must still be a number or empty, as Abaqus reads it as one; the reader checks that
  /// after the handler (KeywordContext::check_numeric_fields). The fields before it are the
  /// handler's to check: names and labels (*BOUNDARY's node set, *DLOAD's load type) or numbers
  /// it reads anyway. Unset where names mix in at no fixed place (sets, surfaces, *EQUATION) or
  /// where the field count is exact and every field is read (*ELEMENT).
  std::optional<std::uint8_t> numbers_from = std::nullopt;
};

/// `value` (normalized) matched against `choices`: exact, or the prefix of exactly one choice
/// (Abaqus accepts unambiguous abbreviations). Returns the normalized choice, or "" if none.
std::string match_choice(const std::string& value, const std::vector<std::string_view>& choices);

/// The table: every keyword inpact understands.
std::span<const KeywordSpec> keyword_table();
/// Abaqus keywords that inpact knows but cannot honour yet (a clear error, not "unknown").
bool is_unsupported_abaqus_keyword(std::string_view normalized_name);

/// What a handler gets: its keyword line (checked), its data lines, the model and diagnostics.
struct KeywordContext {
  const KeywordSpec& spec;
  const KeywordLine& keyword;
  std::span<const Line> data;
  BuildState& state;
  Diagnostics& diags;
  /// The instance plain labels in data lines refer to (INSTANCE= on *NSET/*ELSET; else 0).
  std::int32_t label_instance = 0;

  model::Model& model() { return state.model; }
  model::Mesh& mesh() { return state.mesh(); }
  const std::string kw() const { return std::string(spec.name); }

  // --- parameters (already validated against the spec) ---
  const KeywordParam* param(std::string_view canonical) const;
  bool has(std::string_view canonical) const { return param(canonical) != nullptr; }
  /// Upper-case name value ("" when absent).
  std::string name_value(std::string_view canonical) const;
  /// The normalized choice ("NODETOSURFACE"), "" when absent or a bare flag. An abbreviation
  /// that is the prefix of exactly one declared choice (Abaqus accepts `TYPE=ISO`) is expanded.
  std::string choice_value(std::string_view canonical) const;
  std::optional<double> real_value(std::string_view canonical) const;
  std::optional<std::int64_t> int_value(std::string_view canonical) const;

  // --- diagnostics, prefixed with the keyword ---
  void error(model::SourceLoc loc, std::string message);
  void warning(model::SourceLoc loc, std::string message);
  void error_param(std::string_view canonical, std::string message);
  /// Where a parameter is written: its value if it has one, else its name (the keyword line if
  /// the parameter is absent). error_param reports there.
  model::SourceLoc param_loc(std::string_view canonical) const;

  // --- data fields; each conversion reports its own error and returns nullopt ---
  std::optional<double> real(const Field& f, std::string_view what);
  std::optional<std::int64_t> integer(const Field& f, std::string_view what);
  /// Checks the field count of a data line: `layout` says what was expected.
  bool check_count(const std::vector<Field>& fields, const Line& line, std::size_t min,
                   std::size_t max, std::string_view layout);
  /// A 1-based DOF number in [1, max].
  std::optional<int> dof(const Field& f, int max = 6);
  /// Run by the reader after the handler: on every data line, the fields from
  /// spec.numbers_from on are numbers or empty. A line the handler reported an error on is left
  /// alone (one error a line), and so is every line of a keyword the handler refused (an error on
  /// the keyword line). `n_diagnostics_before`: the diagnostics count before the handler ran.
  void check_numeric_fields(std::size_t n_diagnostics_before);

  // --- references in data lines ---
  /// A node label (`12`), an instance node (`Part-1-1.12`) or a node set name → node rows.
  std::optional<std::vector<std::int32_t>> nodes(const Field& f);
  /// Same for elements and element sets.
  std::optional<std::vector<std::int32_t>> elements(const Field& f);
  /// The node a parameter names (`REF NODE=12`, `NODE=PT`: a label or a set of exactly one
  /// node), or −1 after an error that calls it the `role` ("pre-tension node").
  std::int32_t single_node(std::string_view canonical, std::string_view role);
};

}  // namespace inpact::parser
