#include <algorithm>

#include <fmt/format.h>

#include "keyword_spec.hpp"
#include "text.hpp"

namespace inpact::parser {

const KeywordParam* KeywordContext::param(std::string_view canonical) const {
  const std::string key = normalize_name(canonical);
  for (const auto& p : keyword.params)
    if (p.name == key) return &p;
  return nullptr;
}

std::string KeywordContext::name_value(std::string_view canonical) const {
  const KeywordParam* p = param(canonical);
  return p && p->value ? normalize_label(*p->value) : std::string();
}

std::string match_choice(const std::string& value, const std::vector<std::string_view>& choices) {
  std::string prefix_match;
  int n_prefix = 0;
  for (std::string_view c : choices) {
    const std::string n = normalize_name(c);
    if (n == value) return n;
    if (!value.empty() && n.starts_with(value)) {
      prefix_match = n;
      ++n_prefix;
    }
  }
  return n_prefix == 1 ? prefix_match : std::string();
}

std::string KeywordContext::choice_value(std::string_view canonical) const {
  const KeywordParam* p = param(canonical);
  if (!p || !p->value) return {};
  const std::string v = normalize_name(*p->value);
  for (const auto& ps : spec.params)
    if (normalize_name(ps.name) == p->name && !ps.choices.empty()) {
      std::string m = match_choice(v, ps.choices);
      return m.empty() ? v : m;
    }
  return v;
}

std::optional<double> KeywordContext::real_value(std::string_view canonical) const {
  const KeywordParam* p = param(canonical);
  if (!p || !p->value) return std::nullopt;
  return parse_real(*p->value);
}

std::optional<std::int64_t> KeywordContext::int_value(std::string_view canonical) const {
  const KeywordParam* p = param(canonical);
  if (!p || !p->value) return std::nullopt;
  return parse_int(*p->value);
}

void KeywordContext::error(model::SourceLoc loc, std::string message) {
  diags.error(loc, kw(), std::move(message));
}

void KeywordContext::warning(model::SourceLoc loc, std::string message) {
  diags.warning(loc, kw(), std::move(message));
}

model::SourceLoc KeywordContext::param_loc(std::string_view canonical) const {
  const KeywordParam* p = param(canonical);
  return p ? (p->value ? p->value_loc : p->loc) : keyword.loc;
}

void KeywordContext::error_param(std::string_view canonical, std::string message) {
  error(param_loc(canonical), std::move(message));
}

namespace {
/// A field's text quoted for a message: `'1.O'`, or cut after 60 characters
/// (`'xxxx...' (1000000 characters)`) so that a field a megabyte long cannot flood the report.
std::string quoted(std::string_view text) {
  constexpr std::size_t kMax = 60;
  if (text.size() <= kMax) return fmt::format("'{}'", text);
  return fmt::format("'{}...' ({} characters)", text.substr(0, kMax), text.size());
}
}  // namespace

std::optional<double> KeywordContext::real(const Field& f, std::string_view what) {
  auto v = parse_real(f.text);
  if (!v)
    error(f.loc, f.text.empty() ? fmt::format("{} is missing: expected a number", what)
                                : fmt::format("{}: expected a number, found {}", what, quoted(f.text)));
  return v;
}

std::optional<std::int64_t> KeywordContext::integer(const Field& f, std::string_view what) {
  auto v = parse_int(f.text);
  if (!v)
    error(f.loc, f.text.empty() ? fmt::format("{} is missing: expected an integer", what)
                                : fmt::format("{}: expected an integer, found {}", what, quoted(f.text)));
  return v;
}

bool KeywordContext::check_count(const std::vector<Field>& fields, const Line& line,
                                 std::size_t min, std::size_t max, std::string_view layout) {
  if (fields.size() >= min && fields.size() <= max) return true;
  const std::string expected = min == max ? fmt::format("{}", min)
                               : max == SIZE_MAX ? fmt::format("at least {}", min)
                                                 : fmt::format("{} to {}", min, max);
  error(fields.empty() ? line.loc : fields.back().loc,
        fmt::format("data line has {} field{}, expected {} ({})", fields.size(),
                    fields.size() == 1 ? "" : "s", expected, layout));
  return false;
}

std::optional<int> KeywordContext::dof(const Field& f, int max) {
  auto v = integer(f, "degree of freedom");
  if (!v) return std::nullopt;
  if (*v < 1 || *v > max) {
    error(f.loc, fmt::format("degree of freedom {} is out of range 1..{}", *v, max));
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

void KeywordContext::check_numeric_fields(std::size_t n_diagnostics_before) {
  if (!spec.numbers_from) return;
  const std::size_t first = *spec.numbers_from;
  // The lines the handler reported an error on (usually none).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> reported;
  const auto& all = diags.all();
  for (std::size_t i = n_diagnostics_before; i < all.size(); ++i) {
    if (all[i].severity != Diagnostic::Severity::Error) continue;
    if (all[i].loc.file == keyword.loc.file && all[i].loc.line == keyword.loc.line) return;
    reported.emplace_back(all[i].loc.file, all[i].loc.line);
  }
  std::vector<Field> f;
  for (const Line& line : data) {
    // Fewer commas than `first`: no field from `first` on (the common case of *NODE).
    if (static_cast<std::size_t>(std::count(line.text.begin(), line.text.end(), ',')) < first) continue;
    const std::pair at{line.loc.file, line.loc.line};
    if (std::find(reported.begin(), reported.end(), at) != reported.end()) continue;
    split_fields(line, f);
    for (std::size_t i = first; i < f.size(); ++i)
      if (!f[i].empty() && !parse_real(f[i].text)) {
        error(f[i].loc, fmt::format("field {}: expected a number, found {} (a field inpact does not use must "
                                    "still be a number or empty)", i + 1, quoted(f[i].text)));
        break;
      }
  }
}

namespace {

/// Splits `Instance.label` into instance index and label when the text has that form.
std::optional<std::pair<std::int32_t, std::int64_t>> instance_label(const model::Model& m,
                                                                     std::string_view text) {
  const std::size_t dot = text.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  auto label = parse_int(text.substr(dot + 1));
  if (!label) return std::nullopt;
  const std::string inst = normalize_label(text.substr(0, dot));
  for (std::size_t i = 1; i < m.instances.size(); ++i)
    if (normalize_label(m.instances[i]) == inst)
      return std::make_pair(static_cast<std::int32_t>(i), *label);
  return std::nullopt;
}

template <class Lookup>
std::optional<std::vector<std::int32_t>> resolve(KeywordContext& ctx, const Field& f,
                                                  const std::map<std::string, model::Set>& sets,
                                                  const model::LabelMap& index, const char* what,
                                                  Lookup&& names) {
  if (f.text.empty()) {
    ctx.error(f.loc, fmt::format("{} label or set name is missing", what));
    return std::nullopt;
  }
  if (auto label = parse_int(f.text)) {
    if (auto row = index.find(ctx.label_instance, *label)) return std::vector<std::int32_t>{*row};
    ctx.error(f.loc, fmt::format("{} {} is not defined", what, *label));
    return std::nullopt;
  }
  const std::string key = normalize_label(f.text);
  if (auto it = sets.find(key); it != sets.end()) return it->second.rows;
  if (auto il = instance_label(ctx.model(), f.text)) {
    if (auto row = index.find(il->first, il->second)) return std::vector<std::int32_t>{*row};
    ctx.error(f.loc, fmt::format("{} {} is not defined", what, f.text));
    return std::nullopt;
  }
  const std::string guess = did_you_mean(key, names());
  ctx.error(f.loc, fmt::format("{} set '{}' is not defined{}", what, f.text,
                               guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
  return std::nullopt;
}

std::vector<std::string> keys_of(const std::map<std::string, model::Set>& sets) {
  std::vector<std::string> out;
  for (const auto& [k, v] : sets) out.push_back(k);
  return out;
}

}  // namespace

std::int32_t KeywordContext::single_node(std::string_view canonical, std::string_view role) {
  const KeywordParam* p = param(canonical);
  auto rows = nodes(Field{*p->value, p->value_loc});
  if (!rows) return -1;
  if (rows->size() != 1) {
    error(p->value_loc, fmt::format("{}='{}' holds {} nodes; the {} must be exactly one node", canonical, *p->value,
                                    rows->size(), role));
    return -1;
  }
  return rows->front();
}

std::optional<std::vector<std::int32_t>> KeywordContext::nodes(const Field& f) {
  const auto& sets = mesh().nsets;
  return resolve(*this, f, sets, mesh().nodes.index, "node", [&] { return keys_of(sets); });
}

std::optional<std::vector<std::int32_t>> KeywordContext::elements(const Field& f) {
  const auto& sets = mesh().elsets;
  return resolve(*this, f, sets, mesh().elements.index, "element", [&] { return keys_of(sets); });
}

}  // namespace inpact::parser
