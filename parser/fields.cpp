#include "fields.hpp"

#include <charconv>
#include <cmath>

namespace inpact::parser {

namespace {

/// Appends the field t[start, end): blanks around it trimmed, its column where its text starts
/// (after leading blanks and tabs). A trailing comma does not make an empty last field.
void add_field(const Line& line, std::size_t start, std::size_t end, std::vector<Field>& out) {
  const std::string_view t = line.text;
  std::size_t b = start;
  while (b < end && (t[b] == ' ' || t[b] == '\t')) ++b;
  const auto col = static_cast<std::uint32_t>(b + 1);
  while (b < end && (t[b] == ' ' || t[b] == '\t' || t[b] == '\r')) ++b;
  std::size_t e = end;
  while (e > b && (t[e - 1] == ' ' || t[e - 1] == '\t' || t[e - 1] == '\r')) --e;
  if (end == t.size() && e == b && !out.empty()) return;
  out.push_back({t.substr(b, e - b), {line.loc.file, line.loc.line, col}});
}

}  // namespace

void split_fields(const Line& line, std::vector<Field>& out) {
  out.clear();
  const std::string_view t = line.text;
  std::size_t start = 0;
  if (t.find('"') == std::string_view::npos) {
    // The common case, no quotes: jump from comma to comma.
    for (;;) {
      const std::size_t comma = t.find(',', start);
      if (comma == std::string_view::npos) break;
      add_field(line, start, comma, out);
      start = comma + 1;
    }
    add_field(line, start, t.size(), out);
    return;
  }
  // Commas inside double quotes do not separate fields.
  bool in_quotes = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '"') in_quotes = !in_quotes;
    if (t[i] == ',' && !in_quotes) {
      add_field(line, start, i, out);
      start = i + 1;
    }
  }
  add_field(line, start, t.size(), out);
}

std::optional<std::int64_t> parse_int(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  // Fast path for what almost every label is: up to 18 plain digits (cannot overflow).
  // Unsigned, because the value is accumulated before the digit test is known to pass.
  if (!s.empty() && s.size() <= 18) {
    std::uint64_t v = 0;
    bool digits = true;
    for (char c : s) {
      digits &= c >= '0' && c <= '9';
      v = v * 10 + static_cast<unsigned char>(c - '0');
    }
    if (digits) return static_cast<std::int64_t>(v);
  }
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
