/// *PLASTIC, HARDENING=COMBINED and *CYCLIC HARDENING: Abaqus's nonlinear isotropic/kinematic
/// (Chaboche) hardening, with temperature-dependent data.
///  - DATATYPE=HALF CYCLE (the default): the rows (σ, ε̄ᵖ[, T]) of a half-cycle test, from which
///    the analysis fits C and γ of one backstress per temperature. CalculiX reads the same rows
///    as a linear kinematic hardening table (its COMBINED is linear kinematic plus the
///    isotropic *CYCLIC HARDENING table); inpact follows Abaqus and says so where it fits.
///  - DATATYPE=PARAMETERS: σ|0, C1, γ1[, C2, γ2 …], T per set, a set per temperature.
///  - DATATYPE=STABILIZED (data from several stabilised cycles): not supported yet.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// A set's temperature field (empty: 0), which must exceed the previous set's.
bool set_temperature(KeywordContext& ctx, const std::vector<Field>& f, std::size_t at, const double* previous,
                     double& temperature) {
  temperature = 0.0;
  if (f.size() > at && !f[at].empty()) {
    const auto t = ctx.real(f[at], "temperature");
    if (!t) return false;
    temperature = *t;
  }
  if (previous && temperature <= *previous) {
    ctx.error(f.size() > at ? f[at].loc : f.back().loc,
              fmt::format("the temperatures must increase from set to set, found {} after {}", temperature, *previous));
    return false;
  }
  return true;
}

/// One set of DATATYPE=PARAMETERS: σ|0, C1, γ1 … C_n, γ_n[, T].
bool parameter_set(KeywordContext& ctx, model::Plastic& p, std::size_t n, const std::vector<Field>& f) {
  const std::size_t want = 1 + 2 * n;
  if (f.size() > want + 1) {
    ctx.error(f[want + 1].loc, fmt::format("expected {} values (sigma|0, {} pairs C, gamma[, temperature]), found {}",
                                           want, n, f.size()));
    return false;
  }
  const auto s0 = ctx.real(f[0], "yield stress at zero plastic strain");
  if (!s0) return false;
  if (*s0 <= 0) {
    ctx.error(f[0].loc, fmt::format("the yield stress must be positive, found {}", *s0));
    return false;
  }
  double t = 0.0;
  if (!set_temperature(ctx, f, want, p.table.empty() ? nullptr : &p.table.back().temperature, t)) return false;
  p.table.push_back({*s0, 0.0, t});
  for (std::size_t k = 0; k < n; ++k) {
    const auto C = ctx.real(f[1 + 2 * k], "C"), g = ctx.real(f[2 + 2 * k], "gamma");
    if (!C || !g) return false;
    if (*C < 0 || *g < 0) {
      ctx.error(f[*C < 0 ? 1 + 2 * k : 2 + 2 * k].loc, "C and gamma must not be negative");
      return false;
    }
    p.backstresses.push_back({*C, *g});
  }
  return true;
}

/// DATATYPE=PARAMETERS: a set per temperature. A set fills eight values a line and goes on on
/// the next line until it has its 2n + 1 values (a trailing comma continues it too).
void combined_parameters(KeywordContext& ctx, model::Plastic& p, std::size_t n) {
  p.combined_data = model::Plastic::CombinedData::Parameters;
  std::vector<Field> set, line;
  for (const Line& l : ctx.data) {
    split_fields(l, line);
    while (!line.empty() && line.back().empty()) line.pop_back();
    set.insert(set.end(), line.begin(), line.end());
    if (set.size() < 1 + 2 * n) continue;
    if (!parameter_set(ctx, p, n, set)) return;
    set.clear();
  }
  if (!set.empty() || p.table.empty())
    ctx.error(ctx.data.back().loc, fmt::format("expected {} values (sigma|0 and {} pairs C, gamma), found {}", 1 + 2 * n,
                                               n, set.size()));
}

/// *CYCLIC HARDENING, PARAMETERS: σ|0, Q∞, b[, T] per line, a line per temperature.
void cyclic_parameters(KeywordContext& ctx, model::CyclicHardening& c) {
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 4, "sigma|0, Q_inf, b[, temperature]")) return;
    const auto s0 = ctx.real(f[0], "sigma|0"), q = ctx.real(f[1], "Q_inf"), b = ctx.real(f[2], "b");
    if (!s0 || !q || !b) return;
    if (*s0 <= 0) return ctx.error(f[0].loc, fmt::format("sigma|0 must be positive, found {}", *s0));
    if (*b < 0) return ctx.error(f[2].loc, fmt::format("b must not be negative, found {}", *b));
    double t = 0.0;
    if (!set_temperature(ctx, f, 3, c.parameters.empty() ? nullptr : &c.parameters.back().temperature, t)) return;
    c.parameters.push_back({*s0, *q, *b, t});
  }
}

/// *CYCLIC HARDENING: σ⁰, ε̄ᵖ[, T] per line in blocks of one temperature, each from zero plastic
/// strain (as *PLASTIC's table); with PARAMETERS one line σ|0, Q∞, b[, T] per temperature.
void cyclic_hardening(KeywordContext& ctx) {
  model::CyclicHardening c;
  c.loc = ctx.keyword.loc;
  const std::size_t n_errors = ctx.diags.error_count();
  if (ctx.has("PARAMETERS")) {
    cyclic_parameters(ctx, c);
  } else {
    model::Plastic rows;
    if (plastic_table(ctx, rows)) c.table = std::move(rows.table);
  }
  if (ctx.diags.error_count() > n_errors) return;
  if (ctx.state.material->cyclic_hardening) return ctx.error(ctx.keyword.loc, "*CYCLIC HARDENING is given twice in this material");
  ctx.state.material->cyclic_hardening = std::move(c);
}

}  // namespace

void combined_plastic(KeywordContext& ctx, model::Plastic& p) {
  const std::string datatype = ctx.choice_value("DATATYPE");
  const std::int64_t n = ctx.int_value("NUMBER BACKSTRESSES").value_or(1);
  if (n < 1 || n > 10) return ctx.error_param("NUMBER BACKSTRESSES", fmt::format("must be 1 to 10, found {}", n));
  if (datatype == "PARAMETERS") return combined_parameters(ctx, p, static_cast<std::size_t>(n));
  if (datatype == "STABILIZED")
    return ctx.error_param("DATATYPE", "DATATYPE=STABILIZED (data from stabilised cycles) is not supported yet: give "
                                       "half-cycle data (DATATYPE=HALF CYCLE) or the parameters (DATATYPE=PARAMETERS)");
  if (n > 1)
    return ctx.error_param("NUMBER BACKSTRESSES", fmt::format("inpact fits one backstress to half-cycle data; {} are "
                                                              "not supported yet (give DATATYPE=PARAMETERS)", n));
  p.combined_data = model::Plastic::CombinedData::HalfCycle;
  plastic_table(ctx, p);
}

void add_combined_hardening_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*CYCLIC HARDENING", kModelScope,
               {{"PARAMETERS"}, {"DEPENDENCIES", ValueKind::Required, ValueType::Int}},
               DataLines::Required, cyclic_hardening, {"*MATERIAL"}});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
