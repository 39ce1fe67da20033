/// *STEP *STATIC *END STEP *CONTROLS: a step, its procedure and its solution controls.
/// Sources: K16 §18.36 (*STEP), §18.31 (*STATIC), §3.75 (*CONTROLS), see parser/KEYWORDS.md.
#include <cmath>

#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// A flag that may also be written YES/NO (`NLGEOM`, `NLGEOM=YES`, `NLGEOM=NO`); the reader has
/// already checked that the value, if any, is YES or NO.
bool yes_flag(const KeywordContext& ctx, std::string_view name) {
  const KeywordParam* p = ctx.param(name);
  return p && (!p->value || normalize_name(*p->value) != "NO");
}

/// NLGEOM once on stays on in every later step (Abaqus; CalculiX too, "it remains active in all
/// subsequent static calculations"). CalculiX's NLGEOM=NO after it turns it off; Abaqus keeps it
/// on, and so does inpact, with a warning that names the difference.
bool step_nlgeom(KeywordContext& ctx, const std::vector<model::Step>& earlier) {
  const bool on_before = !earlier.empty() && earlier.back().nlgeom;
  if (!ctx.has("NLGEOM")) return on_before;
  const bool on = yes_flag(ctx, "NLGEOM");
  if (on_before && !on)
    ctx.warning(ctx.param("NLGEOM")->loc, "NLGEOM=NO after a step with NLGEOM: geometric nonlinearity stays on once "
                                          "switched on (Abaqus); CalculiX would turn it off here");
  return on || on_before;
}

// *STEP, NAME=, NLGEOM, INC=, UNSYMM, AMPLITUDE=, EXTRAPOLATION=, CONVERT SDI=.
void step(KeywordContext& ctx) {
  auto& steps = ctx.model().steps;
  model::Step s;
  s.loc = ctx.keyword.loc;
  // Abaqus names unnamed steps "Step-1", "Step-2", ... by position.
  s.name = ctx.has("NAME") ? ctx.param("NAME")->value.value_or("") : fmt::format("Step-{}", steps.size() + 1);
  for (const auto& other : steps)
    if (normalize_label(other.name) == normalize_label(s.name)) {
      ctx.error_param("NAME", fmt::format("step '{}' is defined twice (first at line {})", s.name, other.loc.line));
      break;
    }
  s.nlgeom = step_nlgeom(ctx, steps);
  s.unsymm = yes_flag(ctx, "UNSYMM");
  if (auto inc = ctx.int_value("INC")) {
    if (*inc < 1) ctx.error_param("INC", fmt::format("INC must be at least 1, found {}", *inc));
    else s.max_increments = static_cast<int>(*inc);
  }
  // RAMP is the default for *STATIC, the only procedure inpact has [K16 *STEP].
  if (ctx.choice_value("AMPLITUDE") == "STEP") s.amplitude = model::Step::DefaultAmplitude::Step;
  const std::string extrapolation = ctx.choice_value("EXTRAPOLATION");
  if (extrapolation == "PARABOLIC") s.extrapolation = model::Step::Extrapolation::Parabolic;
  else if (extrapolation == "NO") s.extrapolation = model::Step::Extrapolation::None;
  else if (extrapolation == "VELOCITYPARABOLIC")
    ctx.error_param("EXTRAPOLATION", "EXTRAPOLATION=VELOCITY PARABOLIC applies to dynamic steps; use LINEAR, PARABOLIC or NO");
  s.convert_sdi = ctx.choice_value("CONVERT SDI") != "NO";
  if (ctx.has("PERTURBATION"))
    ctx.error_param("PERTURBATION", "linear perturbation steps are not supported yet (only general static steps)");
  for (const Line& line : ctx.data) {
    if (!s.description.empty()) s.description += '\n';
    s.description += std::string(trim(line.text));
  }
  steps.push_back(std::move(s));
  ctx.state.step = &steps.back();
  ctx.state.scope = kStepScope;
}

void end_step(KeywordContext& ctx) {
  ctx.state.step = nullptr;
  ctx.state.scope = kModelScope;
}

/// An optional positive number in field `i` of `f` (nullopt when blank; error when not positive).
std::optional<double> positive_field(KeywordContext& ctx, const std::vector<Field>& f, std::size_t i,
                                     std::string_view what, bool& ok) {
  if (i >= f.size() || f[i].empty()) return std::nullopt;
  auto v = ctx.real(f[i], what);
  if (!v) {
    ok = false;
    return std::nullopt;
  }
  if (*v <= 0) {
    ctx.error(f[i].loc, fmt::format("{} must be positive, found {}", what, *v));
    ok = false;
    return std::nullopt;
  }
  return v;
}

/// A positive real parameter value, or an error naming it.
std::optional<double> positive_param(KeywordContext& ctx, std::string_view name) {
  const std::optional<double> v = ctx.real_value(name);
  if (v && *v <= 0) {
    ctx.error_param(name, fmt::format("{} must be positive, found {}", name, *v));
    return std::nullopt;
  }
  return v;
}

// STABILIZE[=f], FACTOR=c, ALLSDTOL=tol, CONTINUE=YES|NO [K16 *STATIC] (Abaqus "Automatic
// stabilization of static problems"): f is the dissipated energy fraction (default 2e-4); FACTOR
// gives the damping factor c itself and needs STABILIZE; ALLSDTOL makes it adaptive (inpact:
// only when given, and only lowering c; bare ALLSDTOL = 0.05; 0 = constant). CONTINUE=YES carries c over from the
// previous step. Returns nothing when STABILIZE is absent.
std::optional<model::Stabilization> stabilization(KeywordContext& ctx) {
  const bool continued = ctx.choice_value("CONTINUE") == "YES";
  if (!ctx.has("STABILIZE")) {
    for (std::string_view p : {"FACTOR", "ALLSDTOL"})
      if (ctx.has(p)) ctx.error_param(p, fmt::format("{} needs STABILIZE", p));
    if (continued) ctx.error_param("CONTINUE", "CONTINUE=YES needs STABILIZE");
    return std::nullopt;
  }
  model::Stabilization s;
  if (auto f = positive_param(ctx, "STABILIZE")) s.energy_fraction = *f;
  s.damping_factor = positive_param(ctx, "FACTOR");
  // ALLSDTOL without a value: the accuracy tolerance 0.05 of Abaqus's adaptive stabilization.
  if (ctx.has("ALLSDTOL") && !ctx.param("ALLSDTOL")->value) s.allsdtol = 0.05;
  if (auto tol = ctx.real_value("ALLSDTOL")) {
    if (*tol < 0) ctx.error_param("ALLSDTOL", fmt::format("ALLSDTOL cannot be negative, found {}", *tol));
    else if (*tol > 0) s.allsdtol = tol;
  }
  s.continue_previous = continued;
  return s;
}

/// Parameters of *STATIC that select analyses inpact does not have (stabilization, Riks,
/// viscoelastic long-term response, ...): each is an error rather than a silent plain solve.
constexpr std::string_view kStaticUnsupported[] = {"RIKS", "LONG TERM",
                                                   "ADIABATIC", "FULLY PLASTIC", "TIME RESET",
                                                   "TOTAL TIME AT START", "EXPLICIT"};

// *STATIC, DIRECT[=NO STOP]: data line `initial, period, min, max` [K16 §18.31], [K66 p.463].
// Defaults (Abaqus): period 1; initial = the period (one increment if it converges [INC]) —
// inpact's choice when only a smaller maximum is given: initial = that maximum, so the line stays
// consistent; min = min(initial, 1e-5·period); max = the period (Abaqus has no upper limit, and
// an increment never exceeds the period).
void static_step(KeywordContext& ctx) {
  model::Step& step = *ctx.state.step;
  if (step.static_procedure) {
    ctx.error(ctx.keyword.loc, fmt::format("step '{}' already has a procedure (*STATIC at line {})", step.name,
                                           step.static_procedure->loc.line));
    return;
  }
  for (std::string_view p : kStaticUnsupported)
    if (ctx.has(p)) ctx.error_param(p, fmt::format("{} is not supported yet", p));
  if (ctx.has("SOLVER"))
    ctx.warning(ctx.param("SOLVER")->loc, "SOLVER is ignored: inpact chooses its own sparse solver (CHOLMOD or UMFPACK)");

  model::StaticProcedure proc;
  proc.loc = ctx.keyword.loc;
  proc.direct = ctx.has("DIRECT");
  proc.direct_no_stop = ctx.choice_value("DIRECT") == "NOSTOP";
  proc.stabilize = stabilization(ctx);
  std::vector<Field> f;
  bool ok = true;
  std::optional<double> initial, period, min, max;
  if (!ctx.data.empty()) {
    if (ctx.data.size() > 1) ctx.error(ctx.data[1].loc, "expected one data line (initial increment, period, minimum, maximum)");
    split_fields(ctx.data[0], f);
    // A fifth field is CalculiX's initial CFD increment: irrelevant to a structural step.
    if (!ctx.check_count(f, ctx.data[0], 0, 5, "initial increment, time period, minimum increment, maximum increment"))
      return;
    initial = positive_field(ctx, f, 0, "initial time increment", ok);
    period = positive_field(ctx, f, 1, "time period", ok);
    min = positive_field(ctx, f, 2, "minimum time increment", ok);
    max = positive_field(ctx, f, 3, "maximum time increment", ok);
  }
  if (!ok) return;
  proc.time_period = period.value_or(1.0);
  proc.initial_increment = initial.value_or(std::min(proc.time_period, max.value_or(proc.time_period)));
  proc.min_increment = min.value_or(std::min(proc.initial_increment, 1e-5 * proc.time_period));
  proc.max_increment = max.value_or(proc.time_period);
  auto at = [&](std::size_t i) { return i < f.size() && !f[i].empty() ? f[i].loc : ctx.keyword.loc; };
  if (*proc.min_increment > proc.initial_increment)
    ctx.error(at(2), fmt::format("the minimum time increment {} is larger than the initial increment {}",
                                 *proc.min_increment, proc.initial_increment));
  if (proc.initial_increment > *proc.max_increment)
    ctx.error(at(0), fmt::format("the initial time increment {} is larger than the maximum increment {}",
                                 proc.initial_increment, *proc.max_increment));
  if (proc.initial_increment > proc.time_period)
    ctx.error(at(0), fmt::format("the initial time increment {} is larger than the time period {}",
                                 proc.initial_increment, proc.time_period));
  if (*proc.max_increment > proc.time_period)
    ctx.warning(at(3), fmt::format("the maximum time increment {} is larger than the time period {}: no increment "
                                   "will exceed the period", *proc.max_increment, proc.time_period));
  if (proc.direct) {
    // DIRECT takes fixed increments: the step needs period/initial of them, within INC.
    const double n = std::ceil(proc.time_period / proc.initial_increment * (1 - 1e-12));
    if (n > step.max_increments)
      ctx.error(at(0), fmt::format("DIRECT needs {} increments of {} to cover the period {}, more than INC={} on *STEP "
                                   "allows", n, proc.initial_increment, proc.time_period, step.max_increments));
  }
  step.static_procedure = proc;
}

/// The data lines of *CONTROLS as positional fields; blanks stay unset (Abaqus default).
std::vector<model::ControlFields> control_lines(KeywordContext& ctx, std::size_t max_lines, std::string_view what) {
  std::vector<model::ControlFields> lines;
  std::vector<Field> f;
  for (std::size_t i = 0; i < ctx.data.size(); ++i) {
    if (i == max_lines) {
      ctx.error(ctx.data[i].loc, fmt::format("{} takes at most {} data line{}", what, max_lines, max_lines == 1 ? "" : "s"));
      break;
    }
    split_fields(ctx.data[i], f);
    if (!ctx.check_count(f, ctx.data[i], 1, 16, "control values, blank for the default")) continue;
    model::ControlFields values;
    for (const Field& field : f) {
      if (field.empty()) {
        values.emplace_back();
        continue;
      }
      auto v = ctx.real(field, "control value");
      if (v && *v < 0) ctx.error(field.loc, fmt::format("control values cannot be negative, found {}", *v));
      values.push_back(v);
    }
    lines.push_back(std::move(values));
  }
  lines.resize(std::max(lines.size(), max_lines));
  return lines;
}

// *CONTROLS, PARAMETERS=|ANALYSIS=DISCONTINUOUS|RESET [K16 §3.75]. Every given field is kept
// by position; the solver applies its defaults to the blank ones.
void controls(KeywordContext& ctx) {
  model::Controls& c = ctx.state.step->controls;
  if (ctx.has("TYPE")) {
    ctx.error_param("TYPE", "*CONTROLS, TYPE= (FSI, direct cyclic, VCCT) is not supported");
    return;
  }
  const std::string params = ctx.choice_value("PARAMETERS");
  if (!ctx.has("RESET") && !ctx.has("ANALYSIS") && params.empty()) {
    ctx.error(ctx.keyword.loc, "expected PARAMETERS=, ANALYSIS=DISCONTINUOUS or RESET");
    return;
  }
  if (ctx.has("RESET")) {
    c = model::Controls{};
    c.reset = true;
  }
  if (ctx.has("ANALYSIS")) c.analysis_discontinuous = true;
  if (ctx.has("FIELD") && params != "FIELD") ctx.error_param("FIELD", "FIELD= goes with PARAMETERS=FIELD");
  if (params.empty()) {
    if (!ctx.data.empty()) ctx.error(ctx.data.front().loc, "data lines need PARAMETERS=");
    return;
  }
  if (ctx.data.empty()) {
    ctx.error(ctx.keyword.loc, fmt::format("PARAMETERS={} needs data lines", ctx.param("PARAMETERS")->value.value_or("")));
    return;
  }
  if (params == "TIMEINCREMENTATION") {
    auto lines = control_lines(ctx, 4, "PARAMETERS=TIME INCREMENTATION");
    c.time_incrementation = model::TimeIncrementationControls{lines[0], lines[1], lines[2], lines[3], ctx.keyword.loc};
  } else if (params == "FIELD") {
    const std::string field = ctx.has("FIELD") ? ctx.choice_value("FIELD") : "GLOBAL";
    if (field != "GLOBAL" && field != "DISPLACEMENT") {
      ctx.warning(ctx.param("FIELD")->value_loc,
                  fmt::format("FIELD={} is ignored: inpact solves for displacements only", field));
      return;
    }
    // FIELD=DISPLACEMENT is the more specific setting: it wins over GLOBAL whatever the order.
    if (c.field && c.field->field == "DISPLACEMENT" && field == "GLOBAL") return;
    auto lines = control_lines(ctx, 2, "PARAMETERS=FIELD");
    c.field = model::FieldControls{field, lines[0], lines[1], ctx.keyword.loc};
  } else if (params == "LINESEARCH") {
    auto lines = control_lines(ctx, 1, "PARAMETERS=LINE SEARCH");
    c.line_search = model::LineSearchControls{lines[0], ctx.keyword.loc};
  } else {
    // CONSTRAINTS tolerances serve Lagrange-multiplier constraints that inpact eliminates exactly;
    // CONTACT is CalculiX's own contact tuning, which inpact's contact does not share.
    ctx.warning(ctx.param("PARAMETERS")->value_loc,
                fmt::format("PARAMETERS={} is ignored by inpact", ctx.param("PARAMETERS")->value.value_or("")));
  }
}

// *SOLUTION TECHNIQUE, TYPE=FULL NEWTON | QUASI-NEWTON | SEPARATED [K16]: how Abaqus/Standard
// iterates to equilibrium, not what equilibrium is. inpact always uses full Newton: the
// converged answer is the same (to the tolerances), the iteration count is its own.
void solution_technique(KeywordContext& ctx) {
  const std::string type = ctx.choice_value("TYPE");
  if (!type.empty() && type != "FULLNEWTON")
    ctx.warning(ctx.param_loc("TYPE"), fmt::format("TYPE={}: inpact iterates with full Newton; the converged answer is "
                                                   "the same, the iterations are not",
                                                   ctx.param("TYPE")->value.value_or("")));
}

}  // namespace

void add_step_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  t.push_back({"*STEP", kModelScope,
               {{"NAME", VK::Required},
                {"NLGEOM", VK::None},
                {"INC", VK::Required, VT::Int},
                {"UNSYMM", VK::None},
                {"AMPLITUDE", VK::Required, VT::Choice, {"RAMP", "STEP"}},
                {"EXTRAPOLATION", VK::Required, VT::Choice, {"LINEAR", "PARABOLIC", "NO", "VELOCITY PARABOLIC"}},
                {"CONVERT SDI", VK::Required, VT::Choice, {"YES", "NO"}},
                {"PERTURBATION", VK::None}},
               DataLines::Optional, step});
  t.push_back({"*STATIC", kStepScope,
               {{"DIRECT", VK::Optional, VT::Choice, {"NO STOP"}},
                {"STABILIZE", VK::Optional, VT::Real},
                {"ALLSDTOL", VK::Optional, VT::Real},
                {"FACTOR", VK::Required, VT::Real},
                {"CONTINUE", VK::Required, VT::Choice, {"YES", "NO"}},
                {"RIKS", VK::None},
                {"LONG TERM", VK::None},
                {"ADIABATIC", VK::None},
                {"FULLY PLASTIC", VK::Required},
                {"SOLVER", VK::Required},
                {"TIME RESET", VK::None},
                {"TOTAL TIME AT START", VK::Required, VT::Real},
                {"EXPLICIT", VK::Optional}},
               DataLines::Optional, static_step});
  t.back().numbers_from = 0;
  t.push_back({"*END STEP", kStepScope, {}, DataLines::None, end_step});
  t.push_back({"*SOLUTION TECHNIQUE", kStepScope,
               {{"TYPE", VK::Required, VT::Choice, {"FULL NEWTON", "QUASI-NEWTON", "SEPARATED", "CONTACT ITERATIONS"}},
                {"REFORM KERNEL", VK::Required, VT::Int}},
               DataLines::None, solution_technique});
  t.push_back({"*CONTROLS", kStepScope,
               {{"PARAMETERS", VK::Required, VT::Choice, {"FIELD", "TIME INCREMENTATION", "LINE SEARCH", "CONSTRAINTS", "CONTACT"}},
                {"ANALYSIS", VK::Required, VT::Choice, {"DISCONTINUOUS"}},
                {"RESET", VK::None},
                {"FIELD", VK::Required, VT::Choice,
                 {"GLOBAL", "DISPLACEMENT", "ROTATION", "TEMPERATURE", "HYDROSTATIC FLUID PRESSURE", "PORE FLUID PRESSURE",
                  "ELECTRICAL POTENTIAL", "CONCENTRATION", "CONSTRAINT FORCE", "MOMENT"}},
                {"TYPE", VK::Required}},
               DataLines::Optional, controls});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
