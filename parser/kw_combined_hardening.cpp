/// *PLASTIC, HARDENING=COMBINED and *CYCLIC HARDENING: Abaqus's nonlinear isotropic/kinematic
/// (Chaboche) hardening. Only DATATYPE=PARAMETERS: Abaqus calibrates C and γ itself from
/// half-cycle or stabilised-cycle data (the default DATATYPE=HALF CYCLE), which inpact does not do
/// yet. CalculiX's HARDENING=COMBINED means something else (its *PLASTIC lines are a linear
/// kinematic table and *CYCLIC HARDENING the isotropic one): such a deck stops here too, at
/// DATATYPE, instead of running a different law.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// Every field of every data line, in order (Abaqus continues a long set on the next lines).
std::vector<Field> all_fields(const KeywordContext& ctx) {
  std::vector<Field> all, line;
  for (const Line& l : ctx.data) {
    split_fields(l, line);
    all.insert(all.end(), line.begin(), line.end());
  }
  return all;
}

/// *CYCLIC HARDENING: σ⁰, ε̄ᵖ[, T] per line, the first at zero plastic strain, strains
/// increasing; with PARAMETERS one line σ|0, Q∞, b[, T].
void cyclic_hardening(KeywordContext& ctx) {
  model::CyclicHardening c;
  c.loc = ctx.keyword.loc;
  std::vector<Field> f;
  if (ctx.has("PARAMETERS")) {
    if (ctx.data.size() > 1) ctx.error(ctx.data[1].loc, "temperature-dependent data (more than one data line) is not supported yet");
    split_fields(ctx.data[0], f);
    if (!ctx.check_count(f, ctx.data[0], 3, 4, "sigma|0, Q_inf, b[, temperature]")) return;
    const auto s0 = ctx.real(f[0], "sigma|0"), q = ctx.real(f[1], "Q_inf"), b = ctx.real(f[2], "b");
    if (!s0 || !q || !b) return;
    if (*s0 <= 0) return ctx.error(f[0].loc, fmt::format("sigma|0 must be positive, found {}", *s0));
    if (*b < 0) return ctx.error(f[2].loc, fmt::format("b must not be negative, found {}", *b));
    c.initial = *s0, c.saturation = *q, c.rate = *b;
  } else {
    for (const Line& line : ctx.data) {
      split_fields(line, f);
      if (!ctx.check_count(f, line, 2, 3, "yield surface size, equivalent plastic strain[, temperature]")) return;
      const auto s = ctx.real(f[0], "yield surface size"), e = ctx.real(f[1], "equivalent plastic strain");
      if (!s || !e) return;
      const bool first = c.table.empty();
      if (first && *e != 0.0) return ctx.error(f[1].loc, fmt::format("the first point must be at zero plastic strain, found {}", *e));
      if (!first && *e <= c.table.back().plastic_strain)
        return ctx.error(f[1].loc, fmt::format("the plastic strains must increase, found {} after {}", *e, c.table.back().plastic_strain));
      if (*s <= 0) return ctx.error(f[0].loc, fmt::format("the yield surface size must be positive, found {}", *s));
      c.table.push_back({*s, *e});
    }
  }
  if (ctx.state.material->cyclic_hardening) return ctx.error(ctx.keyword.loc, "*CYCLIC HARDENING is given twice in this material");
  ctx.state.material->cyclic_hardening = std::move(c);
}

}  // namespace

void combined_plastic(KeywordContext& ctx, model::Plastic& p) {
  const std::string datatype = ctx.choice_value("DATATYPE");
  if (datatype != "PARAMETERS")
    return ctx.error_param("DATATYPE", fmt::format("HARDENING=COMBINED with DATATYPE={} is not supported yet: give "
                                                   "the parameters (DATATYPE=PARAMETERS: sigma|0, C1, gamma1, ...)",
                                                   datatype.empty() ? "HALF CYCLE (the default)" : datatype));
  const std::int64_t n = ctx.int_value("NUMBER BACKSTRESSES").value_or(1);
  if (n < 1 || n > 10) return ctx.error_param("NUMBER BACKSTRESSES", fmt::format("must be 1 to 10, found {}", n));
  const std::vector<Field> f = all_fields(ctx);
  const std::size_t want = 1 + 2 * static_cast<std::size_t>(n);
  if (f.size() > want + 1)
    return ctx.error(f[want + 1].loc, "temperature-dependent combined hardening (more than one set) is not supported yet");
  if (f.size() < want)
    return ctx.error(ctx.data.back().loc, fmt::format("expected {} values (sigma|0 and {} pairs C, gamma), found {}", want, n, f.size()));
  const auto s0 = ctx.real(f[0], "yield stress at zero plastic strain");
  if (!s0) return;
  if (*s0 <= 0) return ctx.error(f[0].loc, fmt::format("the yield stress must be positive, found {}", *s0));
  p.table = {{*s0, 0.0}};
  for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
    const auto C = ctx.real(f[1 + 2 * k], "C"), g = ctx.real(f[2 + 2 * k], "gamma");
    if (!C || !g) return;
    if (*C < 0 || *g < 0) return ctx.error(f[*C < 0 ? 1 + 2 * k : 2 + 2 * k].loc, "C and gamma must not be negative");
    p.backstresses.push_back({*C, *g});
  }
}

void add_combined_hardening_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*CYCLIC HARDENING", kModelScope,
               {{"PARAMETERS"}, {"DEPENDENCIES", ValueKind::Required, ValueType::Int}},
               DataLines::Required, cyclic_hardening, {"*MATERIAL"}});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
