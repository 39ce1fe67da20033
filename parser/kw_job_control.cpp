/// Job-control keywords that every Abaqus/CAE input file carries and that ask nothing of the
/// analysis inpact can do: `*PREPRINT` (what the .dat echoes of the input) and `*RESTART`
/// (restart files). Abaqus/CAE writes `*Preprint, echo=NO, model=NO, history=NO, contact=NO`
/// after the heading and `*Restart, write, frequency=0` in each step's output requests.
///
/// *PREPRINT [Abaqus Keywords]: ECHO, MODEL, HISTORY, CONTACT, MASSPROPERTIES (YES/NO, default
/// NO), PARSUBSTITUTION, PARVALUES. inpact's .dat prints none of these tables: NO is what it
/// does, YES is read with a warning that the table is not printed.
///
/// *RESTART [Abaqus Keywords; CCX]: READ (continue from another job's restart files) or WRITE
/// (write them, every FREQUENCY increments, or NUMBER INTERVAL times a step; FREQUENCY=0 and no
/// NUMBER INTERVAL write nothing). inpact has no restart files: a WRITE that asks for none is
/// read silently, one that asks for some is read with a warning, READ is a deck error (the
/// analysis would start from a state inpact cannot load).
///
/// *MONITOR, NODE=, DOF= [Abaqus Keywords]: the .sta shows that DOF each increment; inpact's .sta
/// does not (a warning). *PRINT [Abaqus Keywords]: what the message file prints; inpact writes
/// no message file (YES is a warning). *FILE FORMAT: the format of the .fil file, which inpact
/// does not write (its results file is JOB.h5); read silently.
#include <array>
#include <string>

#include "handlers.hpp"

namespace inpact::parser {

namespace {

constexpr std::array<std::string_view, 5> kPreprintTables{"ECHO", "MODEL", "HISTORY", "CONTACT", "MASSPROPERTIES"};

void preprint(KeywordContext& ctx) {
  for (std::string_view table : kPreprintTables)
    if (ctx.choice_value(table) == "YES")
      ctx.warning(ctx.param_loc(table), std::string(table) + "=YES: inpact's .dat does not print this table; ignored");
}

void restart(KeywordContext& ctx) {
  const bool read = ctx.has("READ"), write = ctx.has("WRITE");
  if (read) {
    ctx.error(ctx.param_loc("READ"), "READ (a restart analysis from another job's restart files) is not supported: "
                                     "inpact writes no restart files; run the whole history in one deck");
    return;
  }
  if (!write) {
    ctx.error(ctx.keyword.loc, "expected READ or WRITE");
    return;
  }
  const bool asks = ctx.int_value("FREQUENCY").value_or(0) != 0 || ctx.int_value("NUMBER INTERVAL").value_or(0) != 0 ||
                    ctx.choice_value("TIME MARKS") == "YES";
  if (asks) ctx.warning(ctx.keyword.loc, "inpact writes no restart files; the request is ignored");
}

void monitor(KeywordContext& ctx) {
  if (ctx.single_node("NODE", "monitored node") < 0) return;
  if (const auto dof = ctx.int_value("DOF"); !dof || *dof < 1 || *dof > 6) {
    ctx.error_param("DOF", "expected a degree of freedom from 1 to 6");
    return;
  }
  ctx.warning(ctx.keyword.loc, "inpact's .sta does not show a monitored degree of freedom; the request is ignored");
}

constexpr std::array<std::string_view, 7> kPrintTables{"ADAPTIVE MESH", "ALLKE", "CONTACT", "MODEL CHANGE",
                                                       "PLASTICITY", "RESIDUAL", "SOLVE"};

void print(KeywordContext& ctx) {
  for (std::string_view table : kPrintTables)
    if (ctx.choice_value(table) == "YES")
      ctx.warning(ctx.param_loc(table), std::string(table) + "=YES: inpact writes no message file; ignored");
}

}  // namespace

void add_job_control_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  const std::vector<std::string_view> yes_no{"YES", "NO"};
  std::vector<ParamSpec> preprint_params;
  for (std::string_view table : kPreprintTables) preprint_params.push_back({table, VK::Required, VT::Choice, yes_no});
  preprint_params.push_back({"PARSUBSTITUTION", VK::Required, VT::Choice, yes_no});
  preprint_params.push_back({"PARVALUES", VK::Required, VT::Choice, yes_no});
  t.push_back({"*PREPRINT", kModelScope, preprint_params, DataLines::None, preprint});
  t.push_back({"*RESTART", kModelDataScopes | kStepScope,
               {{"READ", VK::None}, {"WRITE", VK::None}, {"FREQUENCY", VK::Required, VT::Int},
                {"NUMBER INTERVAL", VK::Required, VT::Int}, {"OVERLAY", VK::None},
                {"TIME MARKS", VK::Required, VT::Choice, yes_no}, {"STEP", VK::Required}, {"INC", VK::Required},
                {"ITERATION", VK::Required}, {"END STEP", VK::None}},
               DataLines::None, restart});
  t.push_back({"*MONITOR", kStepScope,
               {{"NODE", VK::Required, VT::Text, {}, true}, {"DOF", VK::Required, VT::Int, {}, true},
                {"FREQUENCY", VK::Required, VT::Int}},
               DataLines::None, monitor});
  std::vector<ParamSpec> print_params{{"FREQUENCY", VK::Required, VT::Int},
                                      {"PARSUBSTITUTION", VK::Required, VT::Choice, yes_no}};
  for (std::string_view table : kPrintTables) print_params.push_back({table, VK::Required, VT::Choice, yes_no});
  t.push_back({"*PRINT", kStepScope, print_params, DataLines::None, print});
  t.push_back({"*FILE FORMAT", kModelScope | kStepScope,
               {{"ASCII", VK::None}, {"BINARY", VK::None}, {"ZERO INCREMENT", VK::None}}, DataLines::None,
               [](KeywordContext&) {}});
}

}  // namespace inpact::parser
