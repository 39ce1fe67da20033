#include "fields.hpp"

#include <charconv>
#include <cmath>

#include "text.hpp"

namespace inpact::parser {

void split_fields(const Line& line, std::vector<Field>& out) {
  out.clear();
  const std::string_view t = line.text;
  std::size_t start = 0;
  bool in_quotes = false;
  for (std::size_t i = 0; i <= t.size(); ++i) {
    if (i < t.size() && t[i] == '"') in_quotes = !in_quotes;
    if (i == t.size() || (t[i] == ',' && !in_quotes)) {
      std::string_view raw = t.substr(start, i - start);
      std::size_t lead = 0;
      while (lead < raw.size() && (raw[lead] == ' ' || raw[lead] == '\t')) ++lead;
      std::string_view field = trim(raw);
      const bool last = i == t.size();
      if (!(last && field.empty() && !out.empty()))
        out.push_back({field, {line.loc.file, line.loc.line,
                               static_cast<std::uint32_t>(start + lead + 1)}});
      start = i + 1;
    }
  }
}

std::optional<std::int64_t> parse_int(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  std::int64_t v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

std::optional<double> parse_real(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || s.size() > 64) return std::nullopt;
  double v = 0.0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc() && p == s.data() + s.size()) {
    if (!std::isfinite(v)) return std::nullopt;  // "inf", "nan" are not numbers in a deck
    return v;
  }
  // Fortran exponent letters (1.5D3, 1.5d-3) and a bare trailing dot with exponent.
  char buf[65];
  std::size_t n = 0;
  for (char c : s) buf[n++] = (c == 'D' || c == 'd') ? 'e' : c;
  auto [p2, ec2] = std::from_chars(buf, buf + n, v);
  if (ec2 != std::errc() || p2 != buf + n || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace inpact::parser
