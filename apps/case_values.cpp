#include "case_values.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "io/results_reader.hpp"
#include "solver/results_frame.hpp"

namespace inpact::app::study {

namespace {

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

std::string format_value(double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : ""; }

/// The field a spec names: the one whose key it is, else the first with a component of that
/// name (and which component); null when none.
const KeptField* find_field(const std::vector<KeptField>& fields, const std::string& var, int& component) {
  component = -1;
  for (const auto& f : fields)
    if (f.key == var) return &f;
  for (const auto& f : fields)
    for (std::size_t c = 0; c < f.components.size(); ++c)
      if (f.components[c] == var) {
        component = static_cast<int>(c);
        return &f;
      }
  return nullptr;
}

std::string evaluate(const std::vector<KeptField>& fields, const CollectSpec& spec, const NodeSetRows& nsets) {
  int component = -1;
  const KeptField* field = find_field(fields, spec.var, component);
  if (!field || field->components.empty() || field->values.empty()) return "";
  std::optional<std::set<std::int64_t>> rows;
  if (!spec.nset.empty()) {
    rows = nsets(upper(spec.nset));
    if (!rows) return "";
  }
  const std::size_t n_comp = field->components.size();
  const std::size_t n_loc = field->values.size() / n_comp;
  double acc = spec.op == "sum" ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  bool any = false;
  for (std::size_t i = 0; i < n_loc; ++i) {
    if (rows && (i >= field->node_rows.size() || !rows->count(field->node_rows[i]))) continue;
    for (std::size_t c = 0; c < n_comp; ++c) {
      if (component >= 0 && static_cast<int>(c) != component) continue;
      double v = field->values[i * n_comp + c];
      if (std::isnan(v)) continue;
      if (spec.negate) v = -v;
      if (spec.op == "maxabs") v = std::abs(v);
      if (spec.op == "sum") acc += v;
      else if (!any) acc = v;
      else if (spec.op == "min") acc = std::min(acc, v);
      else acc = std::max(acc, v);
      any = true;
    }
  }
  return any ? format_value(acc) : "";
}

}  // namespace

std::map<std::string, std::string> evaluate_values(const std::vector<KeptField>& fields, const AttemptTotals& totals,
                                                   const std::vector<std::string>& specs, const NodeSetRows& nsets) {
  std::map<std::string, std::string> v;
  v["increments"] = std::to_string(totals.increments);
  v["iterations"] = std::to_string(totals.iterations);
  v["cutbacks"] = std::to_string(totals.cutbacks);
  for (const auto& s : specs) v[s] = evaluate(fields, parse_collect(s), nsets);
  return v;
}

CaseValueRecorder::CaseValueRecorder(std::vector<std::string> specs) : specs_(std::move(specs)) {
  for (const auto& s : specs_) vars_.insert(parse_collect(s).var);
}

void CaseValueRecorder::frame(const solver::Frame& frame) {
  fields_.clear();
  for (const auto& f : frame.fields) {
    bool wanted = vars_.count(f.key) > 0;
    for (const auto& c : f.component_labels) wanted = wanted || vars_.count(c) > 0;
    if (!wanted) continue;
    KeptField k{f.key, f.component_labels, f.values, {}};
    if (f.position == solver::Position::Nodal) {
      if (f.nodes.empty()) {
        const std::size_t n_loc = f.component_labels.empty() ? 0 : f.values.size() / f.component_labels.size();
        k.node_rows.resize(n_loc);
        for (std::size_t i = 0; i < n_loc; ++i) k.node_rows[i] = static_cast<std::int64_t>(i);
      } else {
        k.node_rows = f.nodes;
      }
    }
    fields_.push_back(std::move(k));
  }
}

void CaseValueRecorder::attempt(const solver::StatusRow& row) {
  if (row.cut_back) ++totals_.cutbacks;
  else ++totals_.increments;
  totals_.iterations += row.total_iters;
}

std::map<std::string, std::string> CaseValueRecorder::values(const NodeSetRows& nsets) const {
  return evaluate_values(fields_, totals_, specs_, nsets);
}

std::string format_values(const std::map<std::string, std::string>& values) {
  std::string s;
  for (const auto& [k, v] : values) {
    std::string one_line = v;
    std::replace(one_line.begin(), one_line.end(), '\n', ' ');
    s += k + "=" + one_line + "\n";
  }
  return s;
}

std::map<std::string, std::string> parse_values(const std::string& text) {
  std::map<std::string, std::string> v;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (const auto eq = line.find('='); eq != std::string::npos) v[line.substr(0, eq)] = line.substr(eq + 1);
  return v;
}

std::map<std::string, std::string> collect_values(const std::filesystem::path& h5, const std::vector<std::string>& specs) {
  io::ReadResultsOptions read;
  for (const auto& s : specs) read.data_for.insert(parse_collect(s).var);  // only these fields' values
  read.with_data = !read.data_for.empty();
  read.names = false;  // values by row: no node, element or location names
  read.allow_incomplete = false;
  const io::ResultsFile r = io::read_results(h5, read);
  // The last frame of the last step that has frames; a field absent from that frame is NaN there.
  std::vector<KeptField> fields;
  const io::ResultsStep* step = nullptr;
  for (const auto& s : r.steps)
    if (s.n_frames() > 0) step = &s;
  if (step)
    for (const auto& f : step->fields) {
      KeptField k{f.key, f.components, {}, f.node_rows};
      if (f.n_frames > 0 && !f.data.empty()) {
        const auto first = f.data.begin() + static_cast<std::ptrdiff_t>((f.n_frames - 1) * f.n_loc * f.n_comp);
        k.values.assign(first, first + static_cast<std::ptrdiff_t>(f.n_loc * f.n_comp));
      }
      fields.push_back(std::move(k));
    }
  AttemptTotals totals;
  totals.increments = static_cast<long>(r.totals.increments);
  totals.iterations = static_cast<long>(r.totals.iterations);
  totals.cutbacks = static_cast<long>(r.totals.cut_backs);
  return evaluate_values(fields, totals, specs, [&](const std::string& name) -> std::optional<std::set<std::int64_t>> {
    auto it = r.nsets.find(name);
    if (it == r.nsets.end()) return std::nullopt;
    return std::set<std::int64_t>(it->second.begin(), it->second.end());
  });
}

}  // namespace inpact::app::study
