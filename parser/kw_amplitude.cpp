/// *AMPLITUDE: the time variation of load and boundary magnitudes [K16 §1.9].
#include <fmt/format.h>

#include "handlers.hpp"

namespace inpact::parser {

namespace {

/// (time, value) pairs, up to four per line [K16 §1.9: four pairs on every line but the last, or
/// one pair per line; any whole number of pairs up to four is accepted here].
bool amplitude_pairs(KeywordContext& ctx, model::Amplitude& a) {
  std::vector<Field> f;
  bool ok = true;
  const bool strict = a.definition == model::Amplitude::Definition::SmoothStep;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 8, "time, value pairs, up to four per line")) {
      ok = false;
      continue;
    }
    if (f.size() % 2 != 0) {
      ctx.error(f.back().loc, "a time without its value: give (time, value) pairs");
      ok = false;
      continue;
    }
    for (std::size_t i = 0; i < f.size(); i += 2) {
      auto t = ctx.real(f[i], "time");
      auto v = ctx.real(f[i + 1], "amplitude value");
      if (!t || !v) {
        ok = false;
        continue;
      }
      if (!a.points.empty()) {
        const double prev = a.points.back()[0];
        if (*t < prev || (strict && *t == prev)) {
          ctx.error(f[i].loc, fmt::format("time {} comes after time {}: times must {}", *t, prev,
                                          strict ? "increase (SMOOTH STEP)" : "not decrease"));
          ok = false;
          continue;
        }
      }
      a.points.push_back({*t, *v});
    }
  }
  return ok;
}

/// DEFINITION=EQUALLY SPACED: values only, at BEGIN, BEGIN + FIXED INTERVAL, ... — a tabular
/// amplitude with generated times.
bool equally_spaced_values(KeywordContext& ctx, model::Amplitude& a) {
  auto interval = ctx.real_value("FIXED INTERVAL");
  if (!interval || *interval <= 0) {
    ctx.error(ctx.keyword.loc, "DEFINITION=EQUALLY SPACED needs FIXED INTERVAL= a positive time interval");
    return false;
  }
  const double begin = ctx.real_value("BEGIN").value_or(0.0);
  std::vector<Field> f;
  bool ok = true;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 8, "amplitude values, up to eight per line")) {
      ok = false;
      continue;
    }
    for (const Field& field : f) {
      auto v = ctx.real(field, "amplitude value");
      if (!v) {
        ok = false;
        continue;
      }
      a.points.push_back({begin + static_cast<double>(a.points.size()) * *interval, *v});
    }
  }
  return ok;
}

/// Time values scaled then shifted, amplitude values likewise [K16 §1.9 SCALEX, SHIFTX, SCALEY,
/// SHIFTY]; that the scale applies before the shift is UNCONFIRMED (it is the reading that
/// keeps SHIFTX a time).
void scale_and_shift(KeywordContext& ctx, model::Amplitude& a) {
  const double sx = ctx.real_value("SCALEX").value_or(1.0), dx = ctx.real_value("SHIFTX").value_or(0.0);
  const double sy = ctx.real_value("SCALEY").value_or(1.0), dy = ctx.real_value("SHIFTY").value_or(0.0);
  if (sx <= 0) {
    ctx.error_param("SCALEX", fmt::format("SCALEX must be positive, found {}", sx));
    return;
  }
  for (auto& p : a.points) p = {p[0] * sx + dx, p[1] * sy + dy};
}

// *AMPLITUDE, NAME=, DEFINITION=TABULAR|SMOOTH STEP|EQUALLY SPACED, TIME=, VALUE=RELATIVE,
// SCALEX/SCALEY/SHIFTX/SHIFTY [K16 §1.9]. Model or step level; names are global.
void amplitude(KeywordContext& ctx) {
  model::Amplitude a;
  a.name = ctx.param("NAME")->value.value_or("");
  a.loc = ctx.keyword.loc;
  const std::string key = ctx.name_value("NAME");
  if (auto it = ctx.model().amplitudes.find(key); it != ctx.model().amplitudes.end()) {
    ctx.error_param("NAME", fmt::format("amplitude '{}' is defined twice (first at line {})", a.name, it->second.loc.line));
    return;
  }
  const std::string definition = ctx.choice_value("DEFINITION");
  if (ctx.choice_value("TIME") == "TOTALTIME") a.time = model::Amplitude::Time::Total;
  if (ctx.choice_value("VALUE") == "ABSOLUTE") {
    ctx.error_param("VALUE", "VALUE=ABSOLUTE is not supported yet (amplitudes scale the load magnitudes)");
    return;
  }
  // SMOOTH only matters where time derivatives of the amplitude are needed (dynamic steps) and
  // is ignored otherwise [K16]; inpact's static steps never need them.
  if (auto smooth = ctx.real_value("SMOOTH"); smooth && (*smooth < 0 || *smooth > 0.5))
    ctx.error_param("SMOOTH", fmt::format("SMOOTH must lie in [0, 0.5], found {}", *smooth));
  bool ok = false;
  if (definition.empty() || definition == "TABULAR") {
    ok = amplitude_pairs(ctx, a);
  } else if (definition == "SMOOTHSTEP") {
    a.definition = model::Amplitude::Definition::SmoothStep;
    ok = amplitude_pairs(ctx, a);
  } else if (definition == "EQUALLYSPACED") {
    ok = equally_spaced_values(ctx, a);
  } else {
    ctx.error_param("DEFINITION", fmt::format("DEFINITION={} is not supported yet (TABULAR, SMOOTH STEP and EQUALLY "
                                              "SPACED are)", ctx.param("DEFINITION")->value.value_or("")));
  }
  // A faulty amplitude is still defined, so that its references do not add errors of their own.
  if (ok) scale_and_shift(ctx, a);
  ctx.model().amplitudes.emplace(key, std::move(a));
}

}  // namespace

void add_amplitude_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  KeywordSpec amplitude_spec{"*AMPLITUDE", kModelDataScopes | kStepScope,
                             {{"NAME", VK::Required, VT::Text, {}, true},
                              {"DEFINITION", VK::Required, VT::Choice,
                               {"TABULAR", "EQUALLY SPACED", "PERIODIC", "MODULATED", "DECAY", "SMOOTH STEP",
                                "SOLUTION DEPENDENT", "BUBBLE", "USER", "ACTUATOR"}},
                              {"TIME", VK::Required, VT::Choice, {"STEP TIME", "TOTAL TIME"}},
                              {"VALUE", VK::Required, VT::Choice, {"RELATIVE", "ABSOLUTE"}},
                              {"SCALEX", VK::Required, VT::Real}, {"SCALEY", VK::Required, VT::Real},
                              {"SHIFTX", VK::Required, VT::Real}, {"SHIFTY", VK::Required, VT::Real},
                              {"SMOOTH", VK::Required, VT::Real},
                              {"FIXED INTERVAL", VK::Required, VT::Real}, {"BEGIN", VK::Required, VT::Real}},
                             DataLines::Required, amplitude};
  amplitude_spec.input_file = true;
  amplitude_spec.numbers_from = 0;  // (time, value) pairs or values
  t.push_back(std::move(amplitude_spec));
}

}  // namespace inpact::parser
