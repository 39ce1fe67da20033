#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>

#include <fmt/format.h>

namespace inpact::io {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// How many names a structural message lists before "and N more".
constexpr std::size_t kListed = 5;

std::string listed(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < kListed; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > kListed) s += fmt::format(", and {} more", names.size() - kListed);
  return s;
}

/// Names in `x` missing from `y`.
std::vector<std::string> missing_from(const std::vector<std::string>& x, const std::vector<std::string>& y) {
  const std::set<std::string> ys(y.begin(), y.end());
  std::vector<std::string> out;
  for (const auto& n : x)
    if (!ys.count(n)) out.push_back(n);
  return out;
}

/// The largest finite |value| of frame k of a field.
double frame_max(const ResultsField& f, std::size_t k) {
  double m = 0.0;
  if (k >= f.n_frames) return m;
  for (std::size_t v = k * f.n_loc * f.n_comp; v < (k + 1) * f.n_loc * f.n_comp; ++v)
    if (std::isfinite(f.data[v])) m = std::max(m, std::abs(f.data[v]));
  return m;
}

/// The field whose frame maximum bounds a frame-max scale from below, or null: a closed
/// contact's COPEN (a stuck one's CSLIP) is round-off of the coordinates, 1e-16 whatever the
/// load, and is measured in the units of the motion U; the moment RM and section force SF of a
/// symmetric load are round-off of the forces RF.
const char* scale_partner(const std::string& key) {
  if (key == "COPEN" || key == "CSLIP1" || key == "CSLIP2") return "U";
  if (key == "RM" || key == "SF") return "RF";
  return nullptr;
}

/// The frame-max scale of frame k of field `key` in steps sa and sb (its own largest |value|,
/// at least its partner's).
double frame_scale(const ResultsStep& sa, const ResultsStep& sb, const std::string& key, std::size_t k) {
  double scale = 0.0;
  const char* partner = scale_partner(key);
  for (const ResultsStep* step : {&sa, &sb})
    for (const std::string& name : {key, std::string(partner ? partner : "")})
      if (const ResultsField* f = name.empty() ? nullptr : step->field(name)) scale = std::max(scale, frame_max(*f, k));
  return scale;
}

/// One value pair against one tolerance: (pass, |a−b|, allowed, ratio).
struct PairVerdict {
  bool pass;
  double abs_diff, allowed, ratio;
};

PairVerdict judge(double a, double b, const FieldTolerance& t, double scale) {
  const bool na = std::isnan(a), nb = std::isnan(b);
  if (na || nb) {
    if (na && nb) return {true, 0.0, 0.0, 0.0};  // both absent: the field is missing from this frame in both
    return {false, std::numeric_limits<double>::quiet_NaN(), 0.0, kInf};  // NaN never equals a number
  }
  if (std::isinf(a) || std::isinf(b)) {
    if (a == b) return {true, 0.0, 0.0, 0.0};
    return {false, kInf, 0.0, kInf};
  }
  const double d = std::abs(a - b);
  if (t.exact) return {d == 0.0, d, 0.0, d == 0.0 ? 0.0 : kInf};
  const double s = t.scale_by_frame_max ? scale : 1.0;
  const double floor = t.floor * s;
  const double m = std::max(std::abs(a), std::abs(b));
  const double allowed = std::max(t.atol * s, t.rtol * m);
  if (m <= floor) return {true, d, std::max(allowed, floor), 0.0};
  if (d == 0.0) return {true, 0.0, allowed, 0.0};
  const double ratio = allowed > 0.0 ? d / allowed : kInf;
  return {d <= allowed, d, allowed, ratio};
}

void compare_field(const ResultsStep& sa, const ResultsStep& sb, const ResultsField& fa, const ResultsField& fb,
                   const Tolerances& tol,
                   FieldDifference& diff, std::vector<std::string>& structure) {
  const std::string where = fmt::format("step '{}', field {}", sa.name, fa.key);
  if (fa.position != fb.position) {
    structure.push_back(fmt::format("{}: position {} in A, {} in B", where, fa.position, fb.position));
    return;
  }
  if (fa.components != fb.components) {
    structure.push_back(fmt::format("{}: components [{}] in A, [{}] in B", where, fmt::join(fa.components, " "),
                                    fmt::join(fb.components, " ")));
    return;
  }
  // Locations by name (label and instance, pair for contact fields), never by row.
  std::unordered_map<std::string, std::size_t> rows_b;
  rows_b.reserve(fb.n_loc);
  for (std::size_t i = 0; i < fb.locations.size(); ++i) rows_b.emplace(fb.locations[i], i);
  std::vector<std::pair<std::size_t, std::size_t>> matched;
  std::vector<std::string> only_a;
  matched.reserve(fa.n_loc);
  for (std::size_t i = 0; i < fa.locations.size(); ++i) {
    auto it = rows_b.find(fa.locations[i]);
    if (it == rows_b.end()) only_a.push_back(fa.locations[i]);
    else matched.emplace_back(i, it->second);
  }
  if (!only_a.empty())
    structure.push_back(fmt::format("{}: {} location(s) of A not in B: {}", where, only_a.size(), listed(only_a)));
  if (auto only_b = missing_from(fb.locations, fa.locations); !only_b.empty())
    structure.push_back(fmt::format("{}: {} location(s) of B not in A: {}", where, only_b.size(), listed(only_b)));

  const FieldTolerance& t = tol.of(fa.key);
  const std::size_t n_frames = std::min({fa.n_frames, fb.n_frames, sa.n_frames()});
  for (std::size_t k = 0; k < n_frames; ++k) {
    const double scale = t.scale_by_frame_max ? frame_scale(sa, sb, fa.key, k) : 0.0;
    for (const auto& [ia, ib] : matched)
      for (std::size_t c = 0; c < fa.n_comp; ++c) {
        const double a = fa.value(k, ia, c), b = fb.value(k, ib, c);
        const PairVerdict v = judge(a, b, t, scale);
        ++diff.n_compared;
        if (!v.pass) ++diff.n_failed;
        if (!diff.has_worst || v.ratio > diff.ratio) {
          diff.has_worst = true;
          diff.step = sa.name;
          diff.frame = k;
          diff.location = fa.locations[ia];
          diff.component = c < fa.components.size() ? fa.components[c] : std::to_string(c + 1);
          diff.a = a;
          diff.b = b;
          diff.abs_diff = v.abs_diff;
          diff.allowed = v.allowed;
          diff.ratio = v.ratio;
        }
      }
  }
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) out += fmt::format("\\u{:04x}", c);
        else out += ch;
    }
  }
  return out + "\"";
}

/// JSON has no NaN or infinity: null for those.
std::string json_number(double v) { return std::isfinite(v) ? fmt::format("{}", v) : "null"; }

std::string json_tolerance(const FieldTolerance& t) {
  return fmt::format(R"({{"rtol": {}, "atol": {}, "floor": {}, "scale": "{}", "exact": {}, "allowed_mismatches": {}}})",
                     json_number(t.rtol), json_number(t.atol), json_number(t.floor),
                     t.scale_by_frame_max ? "frame-max" : "none", t.exact ? "true" : "false", t.allowed_mismatches);
}

}  // namespace

const FieldTolerance& Tolerances::of(const std::string& key) const {
  auto it = fields.find(key);
  return it == fields.end() ? fallback : it->second;
}

Tolerances default_tolerances() {
  Tolerances t;  // fallback: rtol 1e-6, atol 1e-12, floor 1e-12, absolute
  FieldTolerance scaled;
  scaled.scale_by_frame_max = true;
  scaled.atol = 1e-9;
  scaled.floor = 1e-10;
  for (const char* key : {"S", "E", "RF", "CPRESS", "COPEN", "CSHEAR1", "CSHEAR2", "CSLIP1", "CSLIP2", "CFN", "CNAREA"})
    t.fields[key] = scaled;
  FieldTolerance exact;
  exact.exact = true;
  t.fields["CSTATUS"] = exact;
  return t;
}

bool CompareResult::same() const {
  if (!structure.empty()) return false;
  return std::all_of(fields.begin(), fields.end(), [](const FieldDifference& f) { return f.pass; });
}

CompareResult compare_results(const ResultsFile& a, const ResultsFile& b, const Tolerances& tolerances) {
  CompareResult r;
  r.a = a.path;
  r.b = b.path;
  // The model: node and element labels (with instance), in any order.
  if (auto m = missing_from(a.node_names, b.node_names); !m.empty())
    r.structure.push_back(fmt::format("model: {} node(s) of A not in B: {}", m.size(), listed(m)));
  if (auto m = missing_from(b.node_names, a.node_names); !m.empty())
    r.structure.push_back(fmt::format("model: {} node(s) of B not in A: {}", m.size(), listed(m)));
  if (auto m = missing_from(a.element_names, b.element_names); !m.empty())
    r.structure.push_back(fmt::format("model: {} element(s) of A not in B: {}", m.size(), listed(m)));
  if (auto m = missing_from(b.element_names, a.element_names); !m.empty())
    r.structure.push_back(fmt::format("model: {} element(s) of B not in A: {}", m.size(), listed(m)));

  // Steps in order, by name.
  std::vector<std::string> names_a, names_b;
  for (const auto& s : a.steps) names_a.push_back(s.name);
  for (const auto& s : b.steps) names_b.push_back(s.name);
  if (names_a != names_b)
    r.structure.push_back(fmt::format("steps: A has [{}], B has [{}]", fmt::join(names_a, ", "), fmt::join(names_b, ", ")));

  std::map<std::string, std::size_t> field_index;
  for (const ResultsStep& sa : a.steps) {
    const ResultsStep* sb = b.step(sa.name);
    if (!sb) continue;
    if (sa.n_frames() != sb->n_frames())
      r.structure.push_back(fmt::format("step '{}': {} frame(s) in A, {} in B (the first {} compared)", sa.name,
                                        sa.n_frames(), sb->n_frames(), std::min(sa.n_frames(), sb->n_frames())));
    for (std::size_t k = 0; k < std::min(sa.n_frames(), sb->n_frames()); ++k) {
      const double ta = sa.step_time[k], tb = sb->step_time[k];
      if (std::abs(ta - tb) > 1e-9 * std::max({1.0, std::abs(ta), std::abs(tb)})) {
        r.structure.push_back(fmt::format("step '{}' frame {}: step time {} in A, {} in B (increments differ)",
                                          sa.name, k, ta, tb));
        break;
      }
    }
    std::vector<std::string> keys_a, keys_b;
    for (const auto& f : sa.fields) keys_a.push_back(f.key);
    for (const auto& f : sb->fields) keys_b.push_back(f.key);
    if (auto m = missing_from(keys_a, keys_b); !m.empty())
      r.structure.push_back(fmt::format("step '{}': field(s) of A not in B: {}", sa.name, listed(m)));
    if (auto m = missing_from(keys_b, keys_a); !m.empty())
      r.structure.push_back(fmt::format("step '{}': field(s) of B not in A: {}", sa.name, listed(m)));
    for (const ResultsField& fa : sa.fields) {
      const ResultsField* fb = sb->field(fa.key);
      if (!fb) continue;
      auto [it, fresh] = field_index.emplace(fa.key, r.fields.size());
      if (fresh) {
        r.fields.emplace_back();
        r.fields.back().key = fa.key;
      }
      compare_field(sa, *sb, fa, *fb, tolerances, r.fields[it->second], r.structure);
    }
  }
  for (FieldDifference& f : r.fields) f.pass = f.n_failed <= tolerances.of(f.key).allowed_mismatches;
  return r;
}

std::string format_summary(const CompareResult& r) {
  std::string s = fmt::format("A: {}\nB: {}\n", r.a.string(), r.b.string());
  for (const auto& m : r.structure) s += "structure: " + m + "\n";
  for (const FieldDifference& f : r.fields) {
    s += fmt::format("{:<8} {:<4} {:>9} values, {:>6} outside tolerance", f.key, f.pass ? "ok" : "DIFF", f.n_compared,
                     f.n_failed);
    if (f.has_worst && (f.abs_diff > 0 || std::isnan(f.abs_diff)))
      s += fmt::format("; worst |a-b| {:.3e} (allowed {:.3e}) at step '{}' frame {} {} {}: A {:.9g} B {:.9g}",
                       f.abs_diff, f.allowed, f.step, f.frame, f.location, f.component, f.a, f.b);
    s += "\n";
  }
  const std::size_t n_diff = std::count_if(r.fields.begin(), r.fields.end(), [](const auto& f) { return !f.pass; });
  if (r.same()) s += fmt::format("SAME: {} field(s) within tolerance\n", r.fields.size());
  else s += fmt::format("DIFFERENT: {} structural mismatch(es), {} field(s) outside tolerance\n", r.structure.size(), n_diff);
  return s;
}

std::string format_json(const CompareResult& r, const Tolerances& tol) {
  std::string s = "{\n";
  s += fmt::format("  \"a\": {},\n  \"b\": {},\n  \"same\": {},\n", json_string(r.a.string()), json_string(r.b.string()),
                   r.same() ? "true" : "false");
  s += "  \"structure\": [";
  for (std::size_t i = 0; i < r.structure.size(); ++i) s += (i ? ",\n    " : "\n    ") + json_string(r.structure[i]);
  s += r.structure.empty() ? "],\n" : "\n  ],\n";
  s += "  \"fields\": [";
  for (std::size_t i = 0; i < r.fields.size(); ++i) {
    const FieldDifference& f = r.fields[i];
    s += i ? ",\n    " : "\n    ";
    s += fmt::format(R"({{"field": {}, "pass": {}, "compared": {}, "failed": {}, "tolerance": {})", json_string(f.key),
                     f.pass ? "true" : "false", f.n_compared, f.n_failed, json_tolerance(tol.of(f.key)));
    if (f.has_worst)
      s += fmt::format(R"(, "worst": {{"step": {}, "frame": {}, "location": {}, "component": {}, "a": {}, "b": {}, )"
                       R"("abs_diff": {}, "allowed": {}}})",
                       json_string(f.step), f.frame, json_string(f.location), json_string(f.component), json_number(f.a),
                       json_number(f.b), json_number(f.abs_diff), json_number(f.allowed));
    s += "}";
  }
  s += r.fields.empty() ? "],\n" : "\n  ],\n";
  s += "  \"default_tolerance\": " + json_tolerance(tol.fallback) + "\n}\n";
  return s;
}

}  // namespace inpact::io
