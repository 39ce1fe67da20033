/// The reading loop: lines → keyword blocks → checked against the keyword table → handler.
#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "finalize.hpp"
#include "keyword_spec.hpp"
#include "line_source.hpp"
#include "parameters.hpp"
#include "read_deck.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// "*SURFACE BEHAVIOR" → "SURFACEBEHAVIOR", as keyword lines are normalized.
std::string spec_key(const KeywordSpec& s) { return normalize_name(s.name.substr(1)); }

const KeywordSpec* find_spec(const std::string& normalized) {
  for (const auto& s : keyword_table())
    if (spec_key(s) == normalized) return &s;
  return nullptr;
}

std::string scope_name(unsigned scope) {
  switch (scope) {
    case kPartScope: return "inside *PART";
    case kAssemblyScope: return "inside *ASSEMBLY";
    case kInstanceScope: return "inside *INSTANCE";
    case kStepScope: return "inside *STEP (history data)";
    default: return "in the model data";
  }
}

std::string allowed_scopes(unsigned scopes) {
  std::vector<std::string> names;
  if (scopes & kModelScope) names.push_back("model data");
  if (scopes & kPartScope) names.push_back("*PART");
  if (scopes & kAssemblyScope) names.push_back("*ASSEMBLY");
  if (scopes & kInstanceScope) names.push_back("*INSTANCE");
  if (scopes & kStepScope) names.push_back("*STEP");
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? (i + 1 == names.size() ? " or " : ", ") : "") + names[i];
  return out;
}

/// One keyword with its data lines, being collected.
struct Block {
  KeywordLine keyword;
  const KeywordSpec* spec = nullptr;  ///< nullptr: skip (already reported)
  bool is_parameter = false;
  std::vector<Line> data;
};

class DeckReader {
 public:
  DeckReader(ReadResult& result, const ReadOptions& options)
      : result_(result),
        options_(options),
        parameters_(options.parameters),
        source_(result.model.sources, result.diagnostics, parameters_),
        state_(result.model) {}

  void run(const std::string& path) {
    if (!source_.open(path)) return;
    bool any_keyword = false;
    while (auto line = source_.next()) {
      if (is_keyword_line(line->text)) {
        any_keyword = true;
        std::vector<Line> pieces{*line};
        // A keyword line ending in a comma continues on the next line.
        while (trim(pieces.back().text).ends_with(',')) {
          auto more = source_.next();
          if (!more || is_keyword_line(more->text)) {
            if (more) pending_ = more;
            break;
          }
          pieces.push_back(*more);
        }
        KeywordLine kw = parse_keyword_line(pieces);
        // *INCLUDE switches files without ending the open keyword: an included file may hold
        // the rest of its data lines.
        if (kw.name != "INCLUDE") finish_block();
        start_block(std::move(kw));
        while (pending_) {  // a keyword line that followed a dangling continuation
          Line l = *pending_;
          pending_.reset();
          finish_block();
          start_block(parse_keyword_line({l}));
        }
      } else if (block_) {
        block_->data.push_back(*line);
      } else {
        diags().error(line->loc, "", "data line before the first keyword");
      }
    }
    finish_block();
    if (!any_keyword && !diags().has_errors())
      diags().error({0, 0, 0}, "", "the deck is empty: no keyword lines found");
    finalize_model(state_, diags());
  }

 private:
  Diagnostics& diags() { return result_.diagnostics; }

  void start_block(KeywordLine kw) {
    if (kw.name == "INCLUDE") {
      include(kw);
      return;
    }
    Block b;
    b.keyword = std::move(kw);
    if (b.keyword.name == "PARAMETER") {
      b.is_parameter = true;
      block_ = std::move(b);
      return;
    }
    b.spec = find_spec(b.keyword.name);
    if (!b.spec) {
      report_unknown(b.keyword);
    } else if (!check_scope(*b.spec, b.keyword)) {
      b.spec = nullptr;
    } else {
      // Parameter errors are reported, but the handler still runs (bad values read as absent)
      // so that one typo does not cascade into errors on every keyword after it; only a
      // missing required parameter leaves it nothing to work with.
      if (!check_params(*b.spec, b.keyword)) b.spec = nullptr;
    }
    block_ = std::move(b);
  }

  void include(const KeywordLine& kw) {
    const KeywordParam* input = nullptr;
    for (const auto& p : kw.params) {
      if (p.name == "INPUT") input = &p;
      else diags().error(p.loc, "*INCLUDE", fmt::format("unknown parameter '{}' (expected INPUT=file)", p.name));
    }
    if (!input || !input->value || input->value->empty()) {
      diags().error(kw.loc, "*INCLUDE", "missing required parameter INPUT=file");
      return;
    }
    source_.include(*input->value, input->value_loc, "*INCLUDE");
  }

  void report_unknown(const KeywordLine& kw) {
    if (is_unsupported_abaqus_keyword(kw.name)) {
      diags().error(kw.loc, kw.text,
                    "this Abaqus keyword is not supported by inpact yet; the deck cannot be analysed");
      return;
    }
    std::vector<std::string> names;
    for (const auto& s : keyword_table()) names.push_back(spec_key(s));
    std::string guess = did_you_mean(kw.name, names);
    if (!guess.empty())
      if (const auto* s = find_spec(guess)) guess = std::string(s->name);
    diags().error(kw.loc, "", fmt::format("unknown keyword '{}'{}", kw.text,
                                          guess.empty() ? "" : fmt::format(" (did you mean {}?)", guess)));
  }

  bool check_scope(const KeywordSpec& spec, const KeywordLine& kw) {
    // Abaqus reads all model data before the first step: after one, only steps may follow.
    if (state_.scope == kModelScope && !state_.model.steps.empty() && spec.name != "*STEP" &&
        (spec.scopes & kModelScope)) {
      diags().error(kw.loc, std::string(spec.name), "model data must come before the first *STEP");
      return false;
    }
    if (!(spec.scopes & state_.scope)) {
      diags().error(kw.loc, std::string(spec.name),
                    fmt::format("not allowed {}; it belongs in {}", scope_name(state_.scope),
                                allowed_scopes(spec.scopes)));
      return false;
    }
    if (!spec.parents.empty()) {
      const bool ok = std::any_of(spec.parents.begin(), spec.parents.end(),
                                  [&](std::string_view p) { return p == state_.open_parent; });
      if (!ok) {
        std::string list;
        for (std::size_t i = 0; i < spec.parents.size(); ++i) list += (i ? " or " : "") + std::string(spec.parents[i]);
        diags().error(kw.loc, std::string(spec.name), fmt::format("must follow {}", list));
        return false;
      }
    } else {
      state_.open_parent.clear();  // any other keyword closes the open parent
    }
    return true;
  }

  /// Reports every parameter problem; false when a required parameter is missing.
  bool check_params(const KeywordSpec& spec, const KeywordLine& kw) {
    bool required_present = true;
    const std::string name(spec.name);
    for (const auto& p : kw.params) {
      const ParamSpec* ps = nullptr;
      for (const auto& candidate : spec.params)
        if (normalize_name(candidate.name) == p.name) ps = &candidate;
      if (!ps && spec.input_file && p.name == "INPUT") {
        if (!p.value || p.value->empty()) diags().error(p.loc, name, "INPUT needs a file name: INPUT=file");
        continue;
      }
      if (!ps) {
        std::vector<std::string> names;
        for (const auto& c : spec.params) names.push_back(normalize_name(c.name));
        std::string guess = did_you_mean(p.name, names);
        for (const auto& c : spec.params)
          if (normalize_name(c.name) == guess) guess = std::string(c.name);
        std::string accepted;
        for (const auto& c : spec.params) accepted += (accepted.empty() ? "" : ", ") + std::string(c.name);
        diags().error(p.loc, name,
                      fmt::format("unknown parameter '{}'{}", p.name,
                                  !guess.empty() ? fmt::format(" (did you mean {}?)", guess)
                                  : accepted.empty() ? std::string(" (this keyword takes no parameters)")
                                                     : fmt::format(" (expected one of {})", accepted)));
        continue;
      }
      check_value(*ps, p, name);
    }
    for (const auto& ps : spec.params) {
      if (!ps.required) continue;
      const std::string key = normalize_name(ps.name);
      if (std::none_of(kw.params.begin(), kw.params.end(), [&](const auto& p) { return p.name == key && p.value; })) {
        diags().error(kw.loc, name, fmt::format("missing required parameter {}", ps.name));
        required_present = false;
      }
    }
    return required_present;
  }

  void check_value(const ParamSpec& ps, const KeywordParam& p, const std::string& kw) {
    if (ps.value == ValueKind::None && p.value) {
      // Abaqus accepts YES/NO on some flags (NLGEOM=YES).
      const std::string v = normalize_name(*p.value);
      if (v != "YES" && v != "NO")
        diags().error(p.value_loc, kw, fmt::format("{} is a flag and takes no value", ps.name));
      return;
    }
    if (ps.value == ValueKind::Required && (!p.value || p.value->empty())) {
      diags().error(p.loc, kw, fmt::format("{} needs a value: {}=...", ps.name, ps.name));
      return;
    }
    if (!p.value) return;
    const std::string& v = *p.value;
    auto in_choices = [&] { return !match_choice(normalize_name(v), ps.choices).empty(); };
    auto choice_list = [&] {
      std::string s;
      for (std::size_t i = 0; i < ps.choices.size(); ++i) s += (i ? ", " : "") + std::string(ps.choices[i]);
      return s;
    };
    switch (ps.type) {
      case ValueType::Text: break;
      case ValueType::Int:
        if (!parse_int(v)) diags().error(p.value_loc, kw, fmt::format("{}: expected an integer, found '{}'", ps.name, v));
        break;
      case ValueType::Real:
        if (!parse_real(v)) diags().error(p.value_loc, kw, fmt::format("{}: expected a number, found '{}'", ps.name, v));
        break;
      case ValueType::Choice:
        if (!in_choices())
          diags().error(p.value_loc, kw, fmt::format("{}: '{}' is not one of {}", ps.name, v, choice_list()));
        break;
      case ValueType::RealOrChoice:
        if (!parse_real(v) && !in_choices())
          diags().error(p.value_loc, kw, fmt::format("{}: expected a number or one of {}, found '{}'", ps.name, choice_list(), v));
        break;
    }
  }

  void finish_block() {
    if (!block_) return;
    Block b = std::move(*block_);
    block_.reset();
    if (b.is_parameter) {
      define_parameters(b);
      return;
    }
    if (!b.spec) return;
    if (const KeywordParam* input = find_input(b)) {
      if (!b.data.empty())
        diags().error(b.data.front().loc, std::string(b.spec->name), "data lines given both in INPUT= file and inline");
      b.data = source_.read_data_file(*input->value, input->value_loc, std::string(b.spec->name));
    }
    if (b.spec->data == DataLines::None && !b.data.empty()) {
      diags().error(b.data.front().loc, std::string(b.spec->name), "this keyword takes no data lines");
      return;
    }
    if (b.spec->data == DataLines::Required && b.data.empty()) {
      diags().error(b.keyword.loc, std::string(b.spec->name), "data lines are missing");
      return;
    }
    KeywordContext ctx{*b.spec, b.keyword, b.data, state_, diags()};
    const std::size_t n_diagnostics = diags().all().size();
    b.spec->handler(ctx);
    ctx.check_numeric_fields(n_diagnostics);
  }

  const KeywordParam* find_input(const Block& b) const {
    if (!b.spec->input_file) return nullptr;
    for (const auto& p : b.keyword.params)
      if (p.name == "INPUT" && p.value && !p.value->empty()) return &p;
    return nullptr;
  }

  void define_parameters(const Block& b) {
    for (const auto& p : b.keyword.params)
      diags().error(p.loc, "*PARAMETER", fmt::format("unknown parameter '{}' (this keyword takes no parameters)", p.name));
    for (const Line& line : b.data) {
      const std::size_t eq = line.text.find('=');
      if (eq == std::string_view::npos) {
        diags().error(line.loc, "*PARAMETER", "expected 'name = expression'");
        continue;
      }
      const std::string name = normalize_name(line.text.substr(0, eq));
      if (name.empty()) {
        diags().error(line.loc, "*PARAMETER", "the parameter name is missing before '='");
        continue;
      }
      if (options_.parameters.count(name)) continue;  // -P on the command line wins
      std::string error;
      auto value = evaluate_parameter(line.text.substr(eq + 1), parameters_, error);
      if (!value) {
        diags().error({line.loc.file, line.loc.line, static_cast<std::uint32_t>(eq + 2)}, "*PARAMETER",
                      fmt::format("cannot evaluate '{}': {}", trim(line.text.substr(eq + 1)), error));
        continue;
      }
      parameters_[name] = *value;
    }
  }

  ReadResult& result_;
  const ReadOptions& options_;
  std::map<std::string, std::string> parameters_;
  LineSource source_;
  BuildState state_;
  std::optional<Block> block_;
  std::optional<Line> pending_;
};

}  // namespace

ReadResult read_deck(const std::string& path, const ReadOptions& options) {
  ReadResult result{model::Model{}, Diagnostics(options.max_errors)};
  std::map<std::string, std::string> normalized;
  for (const auto& [k, v] : options.parameters) normalized[normalize_name(k)] = v;
  ReadOptions opts = options;
  opts.parameters = normalized;
  try {
    DeckReader reader(result, opts);
    reader.run(path);
  } catch (const StopReading&) {
    // Too many errors, or binary input: what was collected is the report.
  }
  return result;
}

}  // namespace inpact::parser
