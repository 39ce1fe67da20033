/// *MATERIAL with *ELASTIC, *PLASTIC, *DENSITY, *EXPANSION; *SOLID SECTION (ORIENTATION= names an
/// *ORIENTATION, kw_orientation.cpp; parser/finalize.cpp checks that it exists).
#include <algorithm>

#include <fmt/format.h>

#include "elastic_stability.hpp"
#include "handlers.hpp"
#include "model/elastic_stiffness.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

constexpr std::string_view kMaterial = "*MATERIAL";

void material(KeywordContext& ctx) {
  const std::string key = ctx.name_value("NAME");
  auto [it, inserted] = ctx.model().materials.try_emplace(key);
  if (!inserted) ctx.error_param("NAME", fmt::format("material '{}' is defined twice", key));
  it->second.name = ctx.param("NAME")->value.value_or(key);
  it->second.loc = ctx.keyword.loc;
  ctx.state.material = &it->second;
  ctx.state.open_parent = kMaterial;
}

/// The temperature in field k of a material table's line. A table of one line may leave it out
/// (0); with several lines every line needs it, strictly above the line before (Abaqus
/// interpolates between consecutive lines). nullopt after an error.
std::optional<double> table_temperature(KeywordContext& ctx, const std::vector<Field>& f, std::size_t k,
                                        std::optional<double> previous) {
  if (f.size() <= k || f[k].empty()) {
    if (ctx.data.size() == 1) return 0.0;
    ctx.error(f.size() > k ? f[k].loc : f.back().loc,  // where it is missing, as check_count reports
              fmt::format("field {} (the temperature) is required on every data line when there are several", k + 1));
    return std::nullopt;
  }
  const auto t = ctx.real(f[k], fmt::format("field {}", k + 1));  // "field 3: expected a number", as elsewhere
  if (t && previous && *t <= *previous) {
    ctx.error(f[k].loc, fmt::format("the temperatures must increase strictly from line to line, found {} after {}", *t,
                                    *previous));
    return std::nullopt;
  }
  return t;
}

/// One *ELASTIC, TYPE=ISOTROPIC line: E, ν[, temperature]; nullopt when a field is unusable.
std::optional<model::Elastic::IsotropicRow> isotropic_row(KeywordContext& ctx, const Line& line,
                                                          std::optional<double> previous_temperature) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 2, 3, "Young's modulus, Poisson's ratio[, temperature]")) return std::nullopt;
  auto e = ctx.real(f[0], "Young's modulus");
  auto nu = ctx.real(f[1], "Poisson's ratio");
  if (!e || !nu) return std::nullopt;
  if (*e <= 0) ctx.error(f[0].loc, fmt::format("Young's modulus must be positive, found {}", *e));
  // ν = 0.5 makes the bulk modulus infinite; Abaqus/Standard rejects it for these elements too.
  if (*nu <= -1.0 || *nu >= 0.5)
    ctx.error(f[1].loc, fmt::format("Poisson's ratio must lie in (-1, 0.5), found {}", *nu));
  const auto t = table_temperature(ctx, f, 2, previous_temperature);
  if (!t) return std::nullopt;
  return model::Elastic::IsotropicRow{*e, *nu, *t};
}

// *ELASTIC, TYPE=ISOTROPIC: E, ν[, temperature], one line per temperature.
void isotropic_elastic(KeywordContext& ctx) {
  model::Elastic el;
  for (const Line& line : ctx.data) {
    std::optional<double> previous;
    if (!el.temperature_table.empty()) previous = el.temperature_table.back().temperature;
    const auto row = isotropic_row(ctx, line, previous);
    if (!row) break;  // reported; the rows before it keep the material from a second error
    el.temperature_table.push_back(*row);
  }
  if (el.temperature_table.empty()) return;
  el.youngs_modulus = el.temperature_table.front().youngs_modulus;
  el.poissons_ratio = el.temperature_table.front().poissons_ratio;
  el.loc = ctx.keyword.loc;  // the *ELASTIC line, as *PLASTIC's: what the solver refuses cites it
  ctx.state.material->elastic = std::move(el);
}

/// The constants of the other types, as Abaqus lays them out (8 to a line) and what they are.
struct ElasticLayout {
  model::Elastic::Type type;
  const char* expected;
};

std::optional<ElasticLayout> elastic_layout(const std::string& type) {
  using T = model::Elastic::Type;
  if (type == "ENGINEERINGCONSTANTS")
    return ElasticLayout{T::EngineeringConstants, "E1, E2, E3, nu12, nu13, nu23, G12, G13 / G23[, temperature]"};
  if (type == "ORTHOTROPIC")
    return ElasticLayout{T::Orthotropic, "D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313 / D2323[, temperature]"};
  if (type == "ANISOTROPIC")
    return ElasticLayout{T::Anisotropic, "21 stiffnesses D1111 ... D2323, 8 to a line, [, temperature]"};
  if (type == "LAMINA") return ElasticLayout{T::Lamina, "E1, E2, nu12, G12, G13, G23[, temperature]"};
  return std::nullopt;
}

// *ELASTIC, TYPE=ENGINEERING CONSTANTS | ORTHOTROPIC | ANISOTROPIC | LAMINA: the constants of one
// temperature over as many lines as they need (a line holds 8), then an optional temperature;
// an empty field is 0, as in Abaqus. A second temperature is not supported yet (as ISOTROPIC).
void directional_elastic(KeywordContext& ctx, const ElasticLayout& layout) {
  model::Elastic el;
  el.type = layout.type;
  el.loc = ctx.keyword.loc;  // the analysis cites the keyword (a data line has no column)
  const std::size_t n = model::elastic_constant_count(layout.type);
  std::vector<Field> fields, line_fields;
  for (const Line& line : ctx.data) {
    split_fields(line, line_fields);
    fields.insert(fields.end(), line_fields.begin(), line_fields.end());
  }
  if (fields.size() < n) {
    const model::SourceLoc where = fields.empty() ? ctx.data.back().loc : fields.back().loc;  // after the last one
    ctx.error(where, fmt::format("expected {} constants ({}), found {}", n, layout.expected, fields.size()));
    return;
  }
  if (fields.size() > n + 1) {
    ctx.error(fields[n + 1].loc, "temperature-dependent data (more than one set of constants) is not supported yet");
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (fields[k].empty()) {
      el.constants.push_back(0.0);
      continue;
    }
    auto v = ctx.real(fields[k], "elastic constant");
    if (!v) return;
    el.constants.push_back(*v);
  }
  if (auto bad = elastic_instability(el)) {
    ctx.error(fields[bad->constant].loc, bad->what);
    return;
  }
  ctx.state.material->elastic = std::move(el);
}

void elastic(KeywordContext& ctx) {
  const std::string type = ctx.choice_value("TYPE");
  if (type.empty() || type == "ISOTROPIC" || type == "ISO") {
    isotropic_elastic(ctx);
    return;
  }
  const auto layout = elastic_layout(type);
  if (!layout) {
    ctx.error_param("TYPE", fmt::format("TYPE={} is not supported yet (ISOTROPIC, ENGINEERING CONSTANTS, ORTHOTROPIC, "
                                        "ANISOTROPIC or LAMINA)", type));
    return;
  }
  directional_elastic(ctx, *layout);
}

/// One *PLASTIC data line: yield stress, plastic strain[, temperature], with where the strain
/// and the temperature are written (for the errors about the table).
struct PlasticLine {
  model::Plastic::Point point;
  std::optional<double> temperature;
  model::SourceLoc strain_loc, temperature_loc;
};

std::optional<PlasticLine> plastic_line(KeywordContext& ctx, const Line& line) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 1, 3, "yield stress[, plastic strain[, temperature]]")) return std::nullopt;
  auto sy = ctx.real(f[0], "yield stress");
  if (!sy) return std::nullopt;
  PlasticLine out;
  out.strain_loc = f.size() > 1 ? f[1].loc : line.loc;
  out.temperature_loc = f.size() > 2 ? f[2].loc : line.loc;
  if (f.size() > 1 && !f[1].empty()) {
    auto v = ctx.real(f[1], "plastic strain");
    if (!v) return std::nullopt;
    out.point.plastic_strain = *v;
  }
  if (f.size() > 2 && !f[2].empty()) {
    out.temperature = ctx.real(f[2], "temperature");
    if (!out.temperature) return std::nullopt;
  }
  if (*sy <= 0) {
    ctx.error(f[0].loc, fmt::format("the yield stress must be positive, found {}", *sy));
    return std::nullopt;
  }
  out.point.yield_stress = *sy;
  return out;
}

}  // namespace

// The rows of *PLASTIC (but COMBINED's parameters) into p.table: blocks of equal temperature,
// temperatures increasing, each block from zero plastic strain with strains increasing.
bool plastic_table(KeywordContext& ctx, model::Plastic& p) {
  for (std::size_t i = 0; i < ctx.data.size(); ++i) {
    const auto line = plastic_line(ctx, ctx.data[i]);
    if (!line) return false;
    model::Plastic::Point point = line->point;
    point.temperature = line->temperature.value_or(0.0);
    const bool new_block = i == 0 || point.temperature != p.table.back().temperature;
    if (new_block && i > 0 && point.temperature < p.table.back().temperature) {
      ctx.error(line->temperature_loc, fmt::format("the temperatures must increase from block to block, found {} "
                                                   "after {}", point.temperature, p.table.back().temperature));
      return false;
    }
    const double ep = point.plastic_strain;
    if (new_block && ep != 0.0) {
      ctx.error(line->strain_loc, fmt::format("the first yield stress {}must be given at zero plastic strain, found {}",
                                              i == 0 ? "" : fmt::format("at temperature {} ", point.temperature), ep));
      return false;
    }
    if (!new_block && ep <= p.table.back().plastic_strain) {
      ctx.error(line->strain_loc, fmt::format("the plastic strains must increase, found {} after {}", ep,
                                              p.table.back().plastic_strain));
      return false;
    }
    p.table.push_back(point);
  }
  return true;
}

namespace {

// *PLASTIC, HARDENING=ISOTROPIC (default) | KINEMATIC: yield stress, equivalent plastic strain
// [, temperature] per line, in blocks of one temperature (plastic_table).
void plastic(KeywordContext& ctx) {
  const std::string hardening = ctx.choice_value("HARDENING");
  model::Plastic p;
  if (hardening == "KINEMATIC") {
    p.hardening = model::Plastic::Hardening::Kinematic;
  } else if (hardening == "COMBINED") {
    p.hardening = model::Plastic::Hardening::Combined;
  } else if (!hardening.empty() && hardening != "ISOTROPIC") {
    ctx.error_param("HARDENING", fmt::format("HARDENING={} is not supported yet (ISOTROPIC, KINEMATIC or COMBINED)", hardening));
    return;
  }
  if (ctx.has("DEPENDENCIES") || ctx.has("RATE")) {
    ctx.error(ctx.keyword.loc, "field-variable and rate dependence (DEPENDENCIES, RATE) are not supported yet");
    return;
  }
  const std::size_t n_errors = ctx.diags.error_count();
  if (p.hardening == model::Plastic::Hardening::Combined) combined_plastic(ctx, p);
  else if (!plastic_table(ctx, p)) return;
  if (ctx.diags.error_count() > n_errors) return;
  if (ctx.state.material->plastic) ctx.error(ctx.keyword.loc, "*PLASTIC is given twice in this material");
  p.loc = ctx.keyword.loc;
  ctx.state.material->plastic = std::move(p);
}

// *DENSITY: ρ[, temperature]. Kept for gravity loads and later procedures, which take one
// density: several lines must repeat it (CalculiX decks write it per temperature).
void density(KeywordContext& ctx) {
  std::optional<double> rho;
  for (const Line& line : ctx.data) {
    std::vector<Field> f;
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 2, "density[, temperature]")) return;
    const auto value = ctx.real(f[0], "density");
    if (!value) return;
    if (rho && *value != *rho) {
      ctx.error(f[0].loc, fmt::format("a temperature-dependent density (here {} after {}) is not supported yet", *value,
                                      *rho));
      return;
    }
    rho = value;
  }
  ctx.state.material->density = *rho;
}

// *EXPANSION, TYPE=ISO, ZERO=: α[, temperature], one line per temperature (the secant
// coefficient from the reference temperature ZERO).
void expansion(KeywordContext& ctx) {
  const std::string type = ctx.choice_value("TYPE");
  if (!type.empty() && type != "ISO") {
    ctx.error_param("TYPE", fmt::format("TYPE={} is not supported yet (only ISO)", type));
    return;
  }
  model::Expansion ex;
  for (const Line& line : ctx.data) {
    std::vector<Field> f;
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 2, "expansion coefficient[, temperature]")) return;
    const auto alpha = ctx.real(f[0], "expansion coefficient");
    if (!alpha) return;
    std::optional<double> previous;
    if (!ex.temperature_table.empty()) previous = ex.temperature_table.back().temperature;
    const auto t = table_temperature(ctx, f, 1, previous);
    if (!t) return;
    ex.temperature_table.push_back({*alpha, *t});
  }
  ex.alpha = ex.temperature_table.front().alpha;
  ex.zero = ctx.real_value("ZERO").value_or(0.0);
  ex.loc = ctx.keyword.loc;
  ctx.state.material->expansion = std::move(ex);
}

/// True when the element set `elset` (already defined) holds truss elements: its data line is
/// then the cross-section area, not a thickness.
bool holds_trusses(KeywordContext& ctx, const std::string& elset) {
  auto it = ctx.mesh().elsets.find(elset);
  if (it == ctx.mesh().elsets.end()) return false;
  const auto& el = ctx.mesh().elements;
  return std::any_of(it->second.rows.begin(), it->second.rows.end(), [&](std::int32_t e) {
    return model::element_type(el.type[static_cast<std::size_t>(e)]).family == model::ElementFamily::Truss;
  });
}

// *SOLID SECTION, ELSET=, MATERIAL=[, OFFSET=]: data line (optional) = thickness for plane
// elements, cross-section area for trusses. OFFSET (CalculiX reads it for shells and beams)
// positions a section off its reference surface or line: a solid or truss section has none, so
// only 0 is accepted (a non-zero value would be silently ignored otherwise).
void solid_section(KeywordContext& ctx) {
  model::SolidSection sec;
  sec.elset = ctx.name_value("ELSET");
  sec.material = ctx.name_value("MATERIAL");
  sec.orientation = ctx.name_value("ORIENTATION");
  sec.loc = ctx.keyword.loc;
  sec.value_loc = ctx.keyword.loc;
  if (auto offset = ctx.real_value("OFFSET"); offset && *offset != 0.0)
    ctx.error_param("OFFSET", fmt::format("OFFSET={:g} has no meaning for a solid or truss section (offsets position "
                                          "shell and beam sections; expected 0 or no OFFSET)", *offset));
  const bool truss = holds_trusses(ctx, sec.elset);
  const char* what = truss ? "cross-section area" : "thickness";
  if (!ctx.data.empty()) {
    std::vector<Field> f;
    split_fields(ctx.data[0], f);
    if (!f.empty() && !f[0].empty()) {
      auto t = ctx.real(f[0], what);
      if (t && *t <= 0) ctx.error(f[0].loc, fmt::format("{} must be positive, found {}", what, *t));
      else if (t) sec.thickness = *t, sec.value_given = true, sec.value_loc = f[0].loc;
    }
    if (ctx.data.size() > 1) ctx.error(ctx.data[1].loc, fmt::format("expected at most one data line ({})", what));
  }
  ctx.mesh().sections.push_back(std::move(sec));
}

}  // namespace

void add_material_keywords(std::vector<KeywordSpec>& t) {
  const std::vector<std::string_view> parent{kMaterial};
  t.push_back({"*MATERIAL", kModelScope, {{"NAME", ValueKind::Required, ValueType::Text, {}, true}}, DataLines::None, material});
  t.push_back({"*ELASTIC", kModelScope,
               {{"TYPE", ValueKind::Required, ValueType::Choice, {"ISOTROPIC", "ISO", "ORTHOTROPIC", "ENGINEERING CONSTANTS", "LAMINA", "ANISOTROPIC"}},
                {"MODULI", ValueKind::Required, ValueType::Choice, {"LONG TERM", "INSTANTANEOUS"}},
                {"DEPENDENCIES", ValueKind::Required, ValueType::Int}},
               DataLines::Required, elastic, parent});
  t.back().numbers_from = 0;
  t.push_back({"*PLASTIC", kModelScope,
               {{"HARDENING", ValueKind::Required, ValueType::Choice, {"ISOTROPIC", "KINEMATIC", "COMBINED", "JOHNSON COOK", "USER"}},
                {"DEPENDENCIES", ValueKind::Required, ValueType::Int},
                {"RATE", ValueKind::Required, ValueType::Real},
                {"DATATYPE", ValueKind::Required, ValueType::Choice, {"HALF CYCLE", "STABILIZED", "PARAMETERS"}},
                {"NUMBER BACKSTRESSES", ValueKind::Required, ValueType::Int}},
               DataLines::Required, plastic, parent});
  t.back().numbers_from = 0;
  add_hyperelastic_keyword(t);
  t.push_back({"*DENSITY", kModelScope, {{"DEPENDENCIES", ValueKind::Required, ValueType::Int}}, DataLines::Required, density, parent});
  t.back().numbers_from = 0;
  t.push_back({"*EXPANSION", kModelScope,
               {{"TYPE", ValueKind::Required, ValueType::Choice, {"ISO", "ORTHO", "ANISO"}},
                {"ZERO", ValueKind::Required, ValueType::Real},
                {"DEPENDENCIES", ValueKind::Required, ValueType::Int}},
               DataLines::Required, expansion, parent});
  t.back().numbers_from = 0;
  t.push_back({"*SOLID SECTION", kMeshScopes,
               {{"ELSET", ValueKind::Required, ValueType::Text, {}, true},
                {"MATERIAL", ValueKind::Required, ValueType::Text, {}, true},
                {"ORIENTATION", ValueKind::Required}, {"CONTROLS", ValueKind::Required},
                {"OFFSET", ValueKind::Required, ValueType::Real}},
               DataLines::Optional, solid_section});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
