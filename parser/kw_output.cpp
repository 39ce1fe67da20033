/// *OUTPUT with *NODE OUTPUT, *ELEMENT OUTPUT, *CONTACT OUTPUT; *NODE PRINT, *EL PRINT,
/// *CONTACT PRINT; *NODE FILE, *EL FILE, *CONTACT FILE (CalculiX). All are step data; each
/// request becomes one model::OutputRequest. Sources: K16 §3.67 (*CONTACT OUTPUT), [CCX] and
/// Getting Started §8.4, see KEYWORDS.md.
#include <algorithm>

#include <fmt/format.h>

#include "handlers.hpp"
#include "output_variables.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using model::OutputRequest;
using Kind = OutputRequest::Kind;

constexpr std::string_view kOutput = "*OUTPUT";

std::string_view domain_keyword(OutputDomain d) {
  switch (d) {
    case OutputDomain::Node: return "*NODE OUTPUT / *NODE PRINT / *NODE FILE";
    case OutputDomain::Element: return "*ELEMENT OUTPUT / *EL PRINT / *EL FILE";
    case OutputDomain::Contact: return "*CONTACT OUTPUT / *CONTACT PRINT / *CONTACT FILE";
  }
  return "";
}

std::string_view domain_name(OutputDomain d) {
  return d == OutputDomain::Node ? "node" : d == OutputDomain::Element ? "element" : "contact";
}

/// The variable names on the data lines, checked against the identifiers of `domain`.
void read_variables(KeywordContext& ctx, OutputDomain domain, OutputRequest& r, std::span<const Line> lines) {
  std::vector<Field> f;
  for (const Line& line : lines) {
    split_fields(line, f);
    for (const Field& field : f) {
      if (field.empty()) continue;
      const std::string name = canonical_output_name(domain, normalize_name(field.text));
      if (!is_output_variable(domain, name)) {
        std::string hint;
        for (OutputDomain other : {OutputDomain::Node, OutputDomain::Element, OutputDomain::Contact})
          if (other != domain && is_output_variable(other, name))
            hint = fmt::format(" ({} is a{} {} variable: request it with {})", name,
                               other == OutputDomain::Element ? "n" : "", domain_name(other), domain_keyword(other));
        if (hint.empty()) {
          const std::string guess = did_you_mean(name, output_variable_names(domain));
          if (!guess.empty()) hint = fmt::format(" (did you mean {}?)", guess);
        }
        ctx.error(field.loc, fmt::format("unknown {} output variable '{}'{}", domain_name(domain), field.text, hint));
        continue;
      }
      if (std::find(r.variables.begin(), r.variables.end(), name) == r.variables.end()) r.variables.push_back(name);
    }
  }
}

/// A set named by NSET= or ELSET= must exist (sets are model data, defined before any step).
std::string checked_set(KeywordContext& ctx, std::string_view param, bool nodes) {
  if (!ctx.has(param)) return {};
  const std::string key = ctx.name_value(param);
  const auto& sets = nodes ? ctx.mesh().nsets : ctx.mesh().elsets;
  if (!sets.count(key)) {
    std::vector<std::string> names;
    for (const auto& [k, s] : sets) names.push_back(k);
    const std::string guess = did_you_mean(key, names);
    ctx.error_param(param, fmt::format("{} set '{}' is not defined{}", nodes ? "node" : "element", key,
                                       guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
  }
  return key;
}

/// A surface named by SLAVE=/MASTER=/SURFACE= (or MAIN/SECONDARY) must exist.
std::string checked_surface(KeywordContext& ctx, std::string_view param) {
  if (!ctx.has(param)) return {};
  const std::string key = ctx.name_value(param);
  const auto& surfaces = ctx.mesh().surfaces;
  if (!surfaces.count(key)) {
    std::vector<std::string> names;
    for (const auto& [k, s] : surfaces) names.push_back(k);
    const std::string guess = did_you_mean(key, names);
    ctx.error_param(param, fmt::format("surface '{}' is not defined{}", key,
                                       guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
  }
  return key;
}

/// SLAVE=/SECONDARY= (2022+ spelling) or SURFACE=, and MASTER=/MAIN=: the contact restriction.
void contact_surfaces(KeywordContext& ctx, OutputRequest& r) {
  if (ctx.has("SLAVE") && ctx.has("SECONDARY")) ctx.error_param("SECONDARY", "SECONDARY is SLAVE's newer name: give one");
  if (ctx.has("MASTER") && ctx.has("MAIN")) ctx.error_param("MAIN", "MAIN is MASTER's newer name: give one");
  for (std::string_view p : {"SLAVE", "SECONDARY", "SURFACE"})
    if (ctx.has(p)) r.surface = checked_surface(ctx, p);
  for (std::string_view p : {"MASTER", "MAIN"})
    if (ctx.has(p)) r.master = checked_surface(ctx, p);
}

OutputRequest::Position position_of(const KeywordContext& ctx) {
  const std::string p = ctx.choice_value("POSITION");
  if (p == "INTEGRATIONPOINTS") return OutputRequest::Position::IntegrationPoints;
  if (p == "CENTROIDAL") return OutputRequest::Position::Centroidal;
  if (p == "NODES") return OutputRequest::Position::Nodes;
  if (p == "AVERAGEDATNODES") return OutputRequest::Position::AveragedAtNodes;
  return OutputRequest::Position::Default;
}

/// FREQUENCY=n (0 = no output but the last increment's, where the keyword allows it).
int frequency_of(KeywordContext& ctx) {
  auto f = ctx.int_value("FREQUENCY");
  if (!f) return 1;
  if (*f < 0) {
    ctx.error_param("FREQUENCY", fmt::format("FREQUENCY cannot be negative, found {}", *f));
    return 1;
  }
  return static_cast<int>(*f);
}

/// Parameters that select output inpact cannot produce: each one given is an error.
void reject_params(KeywordContext& ctx, std::initializer_list<std::string_view> names) {
  for (std::string_view p : names)
    if (ctx.has(p)) ctx.error_param(p, fmt::format("{} is not supported yet", p));
}

/// CalculiX debugging output (LAST ITERATIONS, CONTACT ELEMENTS) that inpact does not write.
void warn_ignored(KeywordContext& ctx, std::initializer_list<std::string_view> names) {
  for (std::string_view p : names)
    if (ctx.has(p)) ctx.warning(ctx.param(p)->loc, fmt::format("{} is ignored: inpact does not write it", p));
}

// *OUTPUT, FIELD|HISTORY, FREQUENCY=|NUMBER INTERVAL=, TIME MARKS=, VARIABLE=, OP=: opens the
// block its *NODE/*ELEMENT/*CONTACT OUTPUT sub-options belong to. With VARIABLE= it is itself
// a request for the model's preselected (or all) variables.
void output(KeywordContext& ctx) {
  BuildState& s = ctx.state;
  const bool field = ctx.has("FIELD"), history = ctx.has("HISTORY");
  if (field == history) ctx.error(ctx.keyword.loc, "give exactly one of FIELD and HISTORY");
  reject_params(ctx, {"TIME INTERVAL", "TIME POINTS"});
  s.open_parent = kOutput;
  s.output_is_history = history && !field;
  s.output_frequency = frequency_of(ctx);
  s.output_number_interval.reset();
  if (auto n = ctx.int_value("NUMBER INTERVAL")) {
    if (*n < 1) ctx.error_param("NUMBER INTERVAL", fmt::format("NUMBER INTERVAL must be at least 1, found {}", *n));
    else s.output_number_interval = static_cast<int>(*n);
    if (ctx.has("FREQUENCY")) ctx.error_param("NUMBER INTERVAL", "give FREQUENCY or NUMBER INTERVAL, not both");
  }
  s.output_time_marks = ctx.choice_value("TIME MARKS") == "YES";
  if (s.output_time_marks && !s.output_number_interval)
    ctx.error_param("TIME MARKS", "TIME MARKS goes with NUMBER INTERVAL");
  const std::string op = ctx.choice_value("OP");
  s.output_op = op == "NEW" ? OutputRequest::Op::New : op == "REPLACE" ? OutputRequest::Op::Replace
                                                                       : OutputRequest::Op::Add;
  if (!ctx.has("VARIABLE")) return;
  OutputRequest r;
  r.kind = s.output_is_history ? Kind::ModelHistory : Kind::ModelField;
  r.preselect = ctx.choice_value("VARIABLE") == "PRESELECT";
  r.all = !r.preselect;
  r.frequency = s.output_frequency;
  r.number_interval = s.output_number_interval;
  r.time_marks = s.output_time_marks;
  r.op = s.output_op;
  r.loc = ctx.keyword.loc;
  s.step->output.push_back(std::move(r));
}

/// What *NODE/*ELEMENT/*CONTACT OUTPUT share: the kind from the open *OUTPUT, its frequency,
/// VARIABLE=, and the variables on the data lines (`lines`: all of them unless a line before
/// names something else).
OutputRequest sub_request(KeywordContext& ctx, Kind field_kind, Kind history_kind, OutputDomain domain,
                          std::span<const Line> lines) {
  const BuildState& s = ctx.state;
  OutputRequest r;
  r.kind = s.output_is_history ? history_kind : field_kind;
  r.frequency = s.output_frequency;
  r.number_interval = s.output_number_interval;
  r.time_marks = s.output_time_marks;
  r.op = s.output_op;
  r.loc = ctx.keyword.loc;
  const std::string variable = ctx.choice_value("VARIABLE");
  r.preselect = variable == "PRESELECT";
  r.all = variable == "ALL";
  // Abaqus: without VARIABLE= the variables must be listed on data lines.
  if (variable.empty() && lines.empty())
    ctx.error(ctx.keyword.loc, "list the output variables on data lines, or give VARIABLE=PRESELECT or ALL");
  read_variables(ctx, domain, r, lines);
  return r;
}

/// Whether a data line holds numbers only: *ELEMENT OUTPUT's section-point line (no output
/// variable's name is a number).
bool numbers_only(const Line& line) {
  std::vector<Field> f;
  split_fields(line, f);
  bool any = false;
  for (const Field& field : f) {
    if (field.empty()) continue;
    if (!parse_int(field.text) && !parse_real(field.text)) return false;
    any = true;
  }
  return any;
}

/// *ELEMENT OUTPUT's first data line when it lists section points (Abaqus: up to 16 numbers, a
/// shell's from 1 = SNEG up through its layers, a beam's as its section numbers them): sorted.
std::vector<int> section_point_line(KeywordContext& ctx, const Line& line) {
  std::vector<Field> f;
  split_fields(line, f);
  std::vector<int> out;
  int given = 0;
  for (const Field& field : f) {
    if (field.empty()) continue;
    if (++given == 17)
      ctx.error(field.loc, "at most 16 section points on a line (give another *ELEMENT OUTPUT for the rest)");
    const auto n = parse_int(field.text);
    if (!n || *n < 1) {
      ctx.error(field.loc, fmt::format("a section point is a positive integer, found '{}'", field.text));
      continue;
    }
    out.push_back(static_cast<int>(*n));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void node_output(KeywordContext& ctx) {
  OutputRequest r = sub_request(ctx, Kind::NodeField, Kind::NodeHistory, OutputDomain::Node, ctx.data);
  r.set = checked_set(ctx, "NSET", true);
  ctx.state.step->output.push_back(std::move(r));
}

void element_output(KeywordContext& ctx) {
  const bool with_points = !ctx.data.empty() && numbers_only(ctx.data.front());
  OutputRequest r = sub_request(ctx, Kind::ElementField, Kind::ElementHistory, OutputDomain::Element,
                                ctx.data.subspan(with_points ? 1 : 0));
  if (with_points) r.section_points = section_point_line(ctx, ctx.data.front());
  r.set = checked_set(ctx, "ELSET", false);
  r.position = position_of(ctx);
  reject_params(ctx, {"EXTERIOR", "REBAR", "SECTION POINTS"});
  ctx.state.step->output.push_back(std::move(r));
}

void contact_output(KeywordContext& ctx) {
  OutputRequest r = sub_request(ctx, Kind::ContactField, Kind::ContactHistory, OutputDomain::Contact, ctx.data);
  contact_surfaces(ctx, r);
  r.set = checked_set(ctx, "NSET", true);
  ctx.state.step->output.push_back(std::move(r));
}

/// *NODE PRINT / *EL PRINT / *CONTACT PRINT and the CalculiX *... FILE keywords: a request of
/// its own (no *OUTPUT block), with FREQUENCY, SUMMARY and TOTALS for the printed tables.
OutputRequest print_request(KeywordContext& ctx, Kind kind, OutputDomain domain) {
  reject_params(ctx, {"TIME POINTS"});
  warn_ignored(ctx, {"LAST ITERATIONS", "CONTACT ELEMENTS"});
  // GLOBAL=YES prints a transformed node's values in the global axes, NO (the default) in its
  // *TRANSFORM's. OUTPUT=2D|3D chooses how CalculiX expands 2D elements for its .frd file;
  // inpact writes 2D elements as they are.
  OutputRequest r;
  r.kind = kind;
  r.frequency = frequency_of(ctx);
  r.loc = ctx.keyword.loc;
  const std::string totals = ctx.choice_value("TOTALS");
  r.totals = totals == "YES" || totals == "ONLY";
  r.totals_only = totals == "ONLY";
  r.summary = ctx.choice_value("SUMMARY") != "NO";
  r.global = ctx.choice_value("GLOBAL") == "YES";
  r.preselect = ctx.data.empty();  // *CONTACT PRINT without data lines prints its defaults
  read_variables(ctx, domain, r, ctx.data);
  return r;
}

void node_print(KeywordContext& ctx, Kind kind) {
  OutputRequest r = print_request(ctx, kind, OutputDomain::Node);
  r.set = checked_set(ctx, "NSET", true);
  ctx.state.step->output.push_back(std::move(r));
}

void element_print(KeywordContext& ctx, Kind kind) {
  OutputRequest r = print_request(ctx, kind, OutputDomain::Element);
  r.set = checked_set(ctx, "ELSET", false);
  r.position = position_of(ctx);
  if (ctx.has("SECTION FORCES"))
    ctx.warning(ctx.param("SECTION FORCES")->loc, "SECTION FORCES is ignored: it applies to shells and beams");
  ctx.state.step->output.push_back(std::move(r));
}

void contact_print(KeywordContext& ctx, Kind kind) {
  OutputRequest r = print_request(ctx, kind, OutputDomain::Contact);
  contact_surfaces(ctx, r);
  r.set = checked_set(ctx, "NSET", true);
  ctx.state.step->output.push_back(std::move(r));
}

// *SECTION PRINT, SURFACE=, NAME= (Abaqus's integrated output section, CalculiX's section
// forces SOF, SOM, ...): read so that the deck runs, not written yet.
void section_print(KeywordContext& ctx) {
  ctx.warning(ctx.keyword.loc, "section output (SOF, SOM, SOAREA, ...) is not written yet; the request is ignored");
}

// *ENERGY OUTPUT (whole-model or element-set energies as history output: ALLSE, ALLWK, ...):
// read so that the deck runs, not written yet.
void energy_output(KeywordContext& ctx) {
  ctx.warning(ctx.keyword.loc, "energy history output (ALLSE, ALLWK, ...) is not written yet; the request is "
                               "ignored (ALLSD and ALLSE of a stabilised step are in the results file)");
}

}  // namespace

void add_output_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  const std::vector<std::string_view> parent{kOutput};
  const ParamSpec variable{"VARIABLE", VK::Required, VT::Choice, {"PRESELECT", "ALL"}};
  const ParamSpec frequency{"FREQUENCY", VK::Required, VT::Int};
  const ParamSpec yes_no_summary{"SUMMARY", VK::Required, VT::Choice, {"YES", "NO"}};
  const ParamSpec totals{"TOTALS", VK::Required, VT::Choice, {"YES", "NO", "ONLY"}};
  const ParamSpec global{"GLOBAL", VK::Required, VT::Choice, {"YES", "NO"}};
  const ParamSpec time_points{"TIME POINTS", VK::Required};
  const ParamSpec position{"POSITION", VK::Required, VT::Choice,
                           {"INTEGRATION POINTS", "CENTROIDAL", "NODES", "AVERAGED AT NODES"}};
  const std::vector<ParamSpec> surfaces{{"SLAVE", VK::Required}, {"MASTER", VK::Required}, {"SECONDARY", VK::Required},
                                        {"MAIN", VK::Required}, {"NSET", VK::Required}};

  t.push_back({"*OUTPUT", kStepScope,
               {{"FIELD", VK::None}, {"HISTORY", VK::None}, frequency,
                {"NUMBER INTERVAL", VK::Required, VT::Int}, {"TIME INTERVAL", VK::Required, VT::Real}, time_points,
                {"TIME MARKS", VK::Required, VT::Choice, {"YES", "NO"}}, variable,
                {"OP", VK::Required, VT::Choice, {"ADD", "NEW", "REPLACE"}}},
               DataLines::None, output});
  t.push_back({"*NODE OUTPUT", kStepScope, {{"NSET", VK::Required}, variable, global}, DataLines::Optional,
               node_output, parent});
  t.push_back({"*ELEMENT OUTPUT", kStepScope,
               {{"ELSET", VK::Required}, variable, position, {"DIRECTIONS", VK::Required, VT::Choice, {"YES", "NO"}},
                {"EXTERIOR", VK::None}, {"REBAR", VK::Optional}, {"SECTION POINTS", VK::Required}},
               DataLines::Optional, element_output, parent});
  t.push_back({"*ENERGY OUTPUT", kStepScope, {{"ELSET", VK::Required}, variable}, DataLines::Optional, energy_output,
               parent});
  std::vector<ParamSpec> contact_output_params = surfaces;
  contact_output_params.push_back({"SURFACE", VK::Required});
  contact_output_params.push_back(variable);
  t.push_back({"*CONTACT OUTPUT", kStepScope, contact_output_params, DataLines::Optional, contact_output, parent});

  const std::vector<ParamSpec> calculix_file{frequency, time_points, global, {"OUTPUT", VK::Required, VT::Choice, {"2D", "3D"}},
                                             {"LAST ITERATIONS", VK::None}, {"CONTACT ELEMENTS", VK::None},
                                             {"FREQUENCYF", VK::Required, VT::Int}};
  auto with = [](std::vector<ParamSpec> a, const std::vector<ParamSpec>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  t.push_back({"*NODE PRINT", kStepScope, {{"NSET", VK::Required}, frequency, yes_no_summary, totals, global, time_points},
               DataLines::Required, [](KeywordContext& c) { node_print(c, Kind::NodePrint); }});
  t.push_back({"*EL PRINT", kStepScope,
               {{"ELSET", VK::Required}, frequency, position, yes_no_summary, totals, global, time_points},
               DataLines::Required, [](KeywordContext& c) { element_print(c, Kind::ElementPrint); }});
  t.push_back({"*CONTACT PRINT", kStepScope, with(surfaces, {frequency, yes_no_summary, totals, time_points}),
               DataLines::Optional, [](KeywordContext& c) { contact_print(c, Kind::ContactPrint); }});
  t.push_back({"*SECTION PRINT", kStepScope,
               {{"SURFACE", VK::Required, VT::Text, {}, true}, {"NAME", VK::Required}, {"AXES", VK::Required},
                {"UPDATE", VK::Required}, frequency, time_points},
               DataLines::Required, section_print});
  t.push_back({"*NODE FILE", kStepScope, with({{"NSET", VK::Required}}, calculix_file), DataLines::Required,
               [](KeywordContext& c) { node_print(c, Kind::NodeFile); }});
  t.push_back({"*EL FILE", kStepScope,
               with({{"ELSET", VK::Required}, position, {"SECTION FORCES", VK::None}}, calculix_file),
               DataLines::Required, [](KeywordContext& c) { element_print(c, Kind::ElementFile); }});
  t.push_back({"*CONTACT FILE", kStepScope, with(surfaces, calculix_file), DataLines::Required,
               [](KeywordContext& c) { contact_print(c, Kind::ContactFile); }});
}

}  // namespace inpact::parser
