/// *SPRING: the behaviour of SPRINGA, SPRING1 and SPRING2 elements [Abaqus Keywords *SPRING], [CCX].
///
/// Abaqus's data lines: a first line that is blank for SPRINGA and holds the DOF at the first
/// (and, for SPRING2, second) node for SPRING1/SPRING2; then the stiffness (linear: stiffness,
/// frequency, temperature) or the table (NONLINEAR: force, relative displacement, temperature).
/// The reader drops blank lines, so — as CalculiX's springs.f decides it — the first line is the
/// DOF line when its first field is an integer (no decimal point or exponent) from 1 to 6 and it
/// has at most two fields; otherwise the data starts at once (SPRINGA, or CalculiX's one-line
/// form `*SPRING, ELSET=E` / `10.`). Which elements need DOFs is checked once the deck is read
/// (finalize.cpp), and a DOF beyond the model's at the analysis.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

bool looks_like_dof_line(const std::vector<Field>& f) {
  if (f.empty() || f.size() > 2 || f[0].empty()) return false;
  const std::string_view t = trim(f[0].text);
  if (t.find_first_of(".eEdD") != std::string_view::npos) return false;
  return t.size() == 1 && t[0] >= '1' && t[0] <= '6';
}

bool read_dofs(KeywordContext& ctx, const Line& line, const std::vector<Field>& f, model::SpringSection& s) {
  s.dof_loc = line.loc;
  auto d1 = ctx.dof(f[0]);
  if (!d1) return false;
  s.dof1 = *d1;
  if (f.size() > 1 && !f[1].empty()) {
    auto d2 = ctx.dof(f[1]);
    if (!d2) return false;
    s.dof2 = *d2;
  }
  return true;
}

/// The temperature column of a stiffness or table line, or nullopt when blank.
std::optional<double> temperature_of(KeywordContext& ctx, const std::vector<Field>& f) {
  if (f.size() < 3 || f[2].empty()) return std::nullopt;
  return ctx.real(f[2], "temperature");
}

bool read_linear(KeywordContext& ctx, std::span<const Line> lines, model::SpringSection& s) {
  std::vector<Field> f;
  split_fields(lines[0], f);
  if (!ctx.check_count(f, lines[0], 1, 8, "spring stiffness[, frequency, temperature]")) return false;
  auto k = ctx.real(f[0], "spring stiffness");
  if (!k) return false;
  if (*k <= 0) {
    ctx.error(f[0].loc, fmt::format("spring stiffness must be positive, found {:g}", *k));
    return false;
  }
  if (lines.size() > 1) {
    ctx.error(lines[1].loc, "a spring stiffness that depends on temperature or frequency is not supported yet "
                            "(expected one stiffness line)");
    return false;
  }
  s.stiffness = *k;
  s.value_loc = lines[0].loc;
  return true;
}

bool read_table(KeywordContext& ctx, std::span<const Line> lines, model::SpringSection& s) {
  std::vector<Field> f;
  std::optional<double> first_temperature;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    split_fields(lines[i], f);
    if (!ctx.check_count(f, lines[i], 2, 8, "force, relative displacement[, temperature]")) return false;
    auto force = ctx.real(f[0], "force");
    auto disp = ctx.real(f[1], "relative displacement");
    if (!force || !disp) return false;
    const auto temp = temperature_of(ctx, f);
    if (i == 0) first_temperature = temp;
    else if (temp != first_temperature) {
      ctx.error(lines[i].loc, "a temperature-dependent nonlinear spring is not supported yet (expected one "
                              "force-displacement table)");
      return false;
    }
    if (!s.table.empty() && *disp <= s.table.back()[1]) {
      ctx.error(f[1].loc, fmt::format("relative displacements must increase down the table ({:g} follows {:g})", *disp,
                                      s.table.back()[1]));
      return false;
    }
    s.table.push_back({*force, *disp});
  }
  if (s.table.size() < 2) {
    ctx.error(lines[0].loc, "a NONLINEAR spring needs at least two (force, relative displacement) points");
    return false;
  }
  s.value_loc = lines[0].loc;
  return true;
}

// *SPRING, ELSET=[, NONLINEAR]: see the file comment for the data lines.
void spring(KeywordContext& ctx) {
  if (ctx.has("ORIENTATION")) {
    ctx.error_param("ORIENTATION", "ORIENTATION is not supported yet (springs act in the global directions)");
    return;
  }
  if (ctx.int_value("DEPENDENCIES").value_or(0) > 0) {
    ctx.error_param("DEPENDENCIES", "field-variable dependence of springs is not supported yet");
    return;
  }
  if (ctx.has("COMPLEX STIFFNESS")) {
    ctx.error_param("COMPLEX STIFFNESS", "COMPLEX STIFFNESS applies to steady-state dynamics, which inpact does not do");
    return;
  }
  model::SpringSection s;
  s.elset = ctx.name_value("ELSET");
  s.loc = ctx.keyword.loc;
  s.dof_loc = ctx.keyword.loc;
  s.nonlinear = ctx.has("NONLINEAR");
  std::span<const Line> lines = ctx.data;
  std::vector<Field> f;
  split_fields(lines[0], f);
  const bool linear_has_more = !s.nonlinear && lines.size() > 1;
  if (looks_like_dof_line(f) && (linear_has_more || s.nonlinear)) {
    if (!read_dofs(ctx, lines[0], f, s)) return;
    lines = lines.subspan(1);
    if (lines.empty()) {
      ctx.error(ctx.data[0].loc, "the DOF line must be followed by the spring stiffness line");
      return;
    }
  }
  if (!(s.nonlinear ? read_table(ctx, lines, s) : read_linear(ctx, lines, s))) return;
  ctx.mesh().springs.push_back(std::move(s));
}

}  // namespace

void add_spring_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*SPRING", kMeshScopes,
               {{"ELSET", ValueKind::Required, ValueType::Text, {}, true},
                {"NONLINEAR"},
                {"ORIENTATION", ValueKind::Required},
                {"DEPENDENCIES", ValueKind::Required, ValueType::Int},
                {"COMPLEX STIFFNESS"},
                {"RTOL", ValueKind::Required, ValueType::Real}},
               DataLines::Required, spring});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
