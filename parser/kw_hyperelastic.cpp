/// *HYPERELASTIC: the strain-energy forms with their coefficients given directly (no test data),
/// isotropic, one temperature. Data lines as Abaqus lays them out (eight values a line, the
/// temperature after the last coefficient):
///   NEO HOOKE              C10, D1
///   MOONEY-RIVLIN          C10, C01, D1
///   POLYNOMIAL, N=1        C10, C01, D1             N=2: C10, C01, C20, C11, C02, D1, D2
///   REDUCED POLYNOMIAL, N  C10[, C20[, C30]], D1[, D2[, D3]]
///   YEOH                   C10, C20, C30, D1, D2, D3
///   ARRUDA-BOYCE           μ, λm, D
///   OGDEN, N               μ1, α1[, μ2, α2[, μ3, α3]], D1[, D2[, D3]] (N = 3: D3 on a second line)
/// POLYNOMIAL (N = 1) is the default form, as in Abaqus. D = 0 everywhere: incompressible.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using Form = model::Hyperelastic::Form;

struct FormSpec {
  std::string_view flag;  ///< the parameter, canonical
  Form form;
  int max_order;  ///< N allowed up to this (0: N is fixed at the form's own)
  int fixed_order;
};

constexpr FormSpec kForms[] = {
    {"NEO HOOKE", Form::ReducedPolynomial, 0, 1}, {"MOONEY-RIVLIN", Form::Polynomial, 0, 1},
    {"POLYNOMIAL", Form::Polynomial, 2, 1},       {"REDUCED POLYNOMIAL", Form::ReducedPolynomial, 3, 1},
    {"YEOH", Form::ReducedPolynomial, 0, 3},      {"ARRUDA-BOYCE", Form::ArrudaBoyce, 0, 1},
    {"OGDEN", Form::Ogden, 3, 1},
};

/// Coefficients (without the D's) a record of this form and order holds.
std::size_t coefficient_count(Form form, int n) {
  switch (form) {
    case Form::Polynomial: return n == 1 ? 2 : 5;
    case Form::ReducedPolynomial: return static_cast<std::size_t>(n);
    case Form::ArrudaBoyce: return 2;
    case Form::Ogden: return 2 * static_cast<std::size_t>(n);
  }
  return 0;
}

/// The form flag given (POLYNOMIAL when none), or nullptr after an error.
const FormSpec* chosen_form(KeywordContext& ctx) {
  for (std::string_view unsupported : {"MARLOW", "VAN DER WAALS", "USER", "TEST DATA INPUT", "POISSON"})
    if (ctx.has(unsupported)) {
      ctx.error_param(unsupported, fmt::format("{} is not supported yet (give the coefficients of NEO HOOKE, "
                                               "MOONEY-RIVLIN, POLYNOMIAL, REDUCED POLYNOMIAL, YEOH, ARRUDA-BOYCE "
                                               "or OGDEN)", unsupported));
      return nullptr;
    }
  if (ctx.choice_value("TYPE") == "ANISOTROPIC") {
    ctx.error_param("TYPE", "TYPE=ANISOTROPIC is not supported yet (only ISOTROPIC)");
    return nullptr;
  }
  const FormSpec* chosen = nullptr;
  for (const FormSpec& f : kForms)
    if (ctx.has(f.flag)) {
      if (chosen) {
        ctx.error_param(f.flag, fmt::format("two strain-energy forms given ({} and {})", chosen->flag, f.flag));
        return nullptr;
      }
      chosen = &f;
    }
  return chosen ? chosen : &kForms[2];
}

/// N of the form: the parameter (checked against the form's range) or the form's own.
std::optional<int> chosen_order(KeywordContext& ctx, const FormSpec& f) {
  const auto n = ctx.int_value("N");
  if (!n) return f.fixed_order;
  if (f.max_order == 0 && *n != f.fixed_order) {
    ctx.error_param("N", fmt::format("{} takes no N (its order is {})", f.flag, f.fixed_order));
    return std::nullopt;
  }
  if (f.max_order != 0 && (*n < 1 || *n > f.max_order)) {
    ctx.error_param("N", fmt::format("N={} is not supported for {} (1 to {})", *n, f.flag, f.max_order));
    return std::nullopt;
  }
  return static_cast<int>(*n);
}

/// The first record's `count` numbers (over as many data lines as it takes) and whether the data
/// hold more (another temperature).
std::optional<std::vector<double>> first_record(KeywordContext& ctx, std::size_t count) {
  std::vector<double> values;
  std::vector<Field> f;
  std::size_t line = 0;
  for (; line < ctx.data.size() && values.size() < count; ++line) {
    split_fields(ctx.data[line], f);
    const std::size_t take = std::min(f.size(), count - values.size());
    for (std::size_t k = 0; k < take; ++k) {
      if (f[k].empty()) {
        values.push_back(0.0);  // an empty field is zero, as Abaqus reads it
        continue;
      }
      auto v = ctx.real(f[k], "coefficient");
      if (!v) return std::nullopt;
      values.push_back(*v);
    }
    if (f.size() < 8 && values.size() < count) break;  // a short line ends the record
  }
  if (values.size() < count) {
    ctx.error(ctx.data.empty() ? ctx.keyword.loc : ctx.data[std::min(line, ctx.data.size() - 1)].loc,
              fmt::format("expected {} coefficients (with the D's), found {}", count, values.size()));
    return std::nullopt;
  }
  if (line < ctx.data.size()) {
    ctx.error(ctx.data[line].loc, "temperature-dependent data (more than one set of coefficients) is not supported yet");
    return std::nullopt;
  }
  return values;
}

void hyperelastic(KeywordContext& ctx) {
  const FormSpec* spec = chosen_form(ctx);
  if (!spec) return;
  const auto n = chosen_order(ctx, *spec);
  if (!n) return;
  model::Hyperelastic h;
  h.form = spec->form;
  h.order = *n;
  h.name = spec->max_order ? fmt::format("{}, N={}", spec->flag, *n) : std::string(spec->flag);
  h.loc = ctx.keyword.loc;
  const std::size_t nc = coefficient_count(h.form, h.order);
  const std::size_t nd = h.form == Form::ArrudaBoyce ? 1 : static_cast<std::size_t>(h.order);
  const auto values = first_record(ctx, nc + nd);
  if (!values) return;
  h.coefficients.assign(values->begin(), values->begin() + static_cast<std::ptrdiff_t>(nc));
  h.d.assign(values->begin() + static_cast<std::ptrdiff_t>(nc), values->end());
  for (double d : h.d)
    if (d < 0) {
      ctx.error(ctx.data[0].loc, fmt::format("the compressibility coefficients D must not be negative, found {}", d));
      return;
    }
  if (h.form == Form::ArrudaBoyce && (h.coefficients[0] <= 0 || h.coefficients[1] <= 0)) {
    ctx.error(ctx.data[0].loc, "ARRUDA-BOYCE needs a positive modulus and locking stretch");
    return;
  }
  if (ctx.state.material->hyperelastic) ctx.error(ctx.keyword.loc, "*HYPERELASTIC is given twice in this material");
  ctx.state.material->hyperelastic = std::move(h);
}

}  // namespace

void add_hyperelastic_keyword(std::vector<KeywordSpec>& t) {
  std::vector<ParamSpec> params;
  for (const FormSpec& f : kForms) params.push_back({f.flag});
  for (std::string_view other : {"MARLOW", "VAN DER WAALS", "USER", "TEST DATA INPUT", "POISSON"})
    params.push_back({other, ValueKind::Optional, ValueType::Text});
  params.push_back({"N", ValueKind::Required, ValueType::Int});
  params.push_back({"TYPE", ValueKind::Required, ValueType::Choice, {"ISOTROPIC", "ANISOTROPIC"}});
  params.push_back({"MODULI", ValueKind::Required, ValueType::Choice, {"LONG TERM", "INSTANTANEOUS"}});
  params.push_back({"PROPERTIES", ValueKind::Required, ValueType::Int});
  t.push_back({"*HYPERELASTIC", kModelScope, std::move(params), DataLines::Required, hyperelastic, {"*MATERIAL"}});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
