#include "parameters.hpp"

#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "fields.hpp"
#include "text.hpp"

namespace inpact::parser {

std::string format_parameter_number(double v) {
  if (std::nearbyint(v) == v && std::fabs(v) < 1e15) return fmt::format("{}", static_cast<long long>(v));
  return fmt::format("{}", v);  // shortest representation that round-trips
}

namespace {

struct ExprParser {
  std::string_view s;
  const std::map<std::string, std::string>& defined;
  std::string& error;
  std::size_t i = 0;

  void skip() {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  }
  bool fail(std::string msg) {
    if (error.empty()) error = std::move(msg);
    return false;
  }
  // expr := term (('+'|'-') term)*
  bool expr(double& v) {
    if (!term(v)) return false;
    for (;;) {
      skip();
      if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
        char op = s[i++];
        double r;
        if (!term(r)) return false;
        v = op == '+' ? v + r : v - r;
      } else {
        return true;
      }
    }
  }
  // term := power (('*'|'/') power)*
  bool term(double& v) {
    if (!power(v)) return false;
    for (;;) {
      skip();
      if (i < s.size() && (s[i] == '*' || s[i] == '/') && !(s[i] == '*' && i + 1 < s.size() && s[i + 1] == '*')) {
        char op = s[i++];
        double r;
        if (!power(r)) return false;
        if (op == '/' && r == 0.0) return fail("division by zero");
        v = op == '*' ? v * r : v / r;
      } else {
        return true;
      }
    }
  }
  // power := unary ('**' power)?
  bool power(double& v) {
    if (!unary(v)) return false;
    skip();
    if (i + 1 < s.size() && s[i] == '*' && s[i + 1] == '*') {
      i += 2;
      double r;
      if (!power(r)) return false;
      v = std::pow(v, r);
    }
    return true;
  }
  bool unary(double& v) {
    skip();
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) {
      char op = s[i++];
      if (!unary(v)) return false;
      if (op == '-') v = -v;
      return true;
    }
    return primary(v);
  }
  bool primary(double& v) {
    skip();
    if (i >= s.size()) return fail("expression ends too early");
    if (s[i] == '(') {
      ++i;
      if (!expr(v)) return false;
      skip();
      if (i >= s.size() || s[i] != ')') return fail("missing ')'");
      ++i;
      return true;
    }
    if (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.') {
      std::size_t b = i;
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '.' ||
                              ((s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
        ++i;
      auto r = parse_real(s.substr(b, i - b));
      if (!r) return fail(fmt::format("'{}' is not a number", s.substr(b, i - b)));
      v = *r;
      return true;
    }
    if (std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_') {
      std::size_t b = i;
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
      const std::string name = normalize_name(s.substr(b, i - b));
      auto it = defined.find(name);
      if (it == defined.end()) return fail(fmt::format("parameter '{}' is not defined", s.substr(b, i - b)));
      auto r = parse_real(it->second);
      if (!r) return fail(fmt::format("parameter '{}' is not a number", s.substr(b, i - b)));
      v = *r;
      return true;
    }
    return fail(fmt::format("unexpected '{}'", s[i]));
  }
};

}  // namespace

std::optional<std::string> evaluate_parameter(std::string_view expr,
                                              const std::map<std::string, std::string>& defined,
                                              std::string& error) {
  std::string_view t = trim(expr);
  if (t.size() >= 2 && (t.front() == '"' || t.front() == '\'') && t.back() == t.front())
    return std::string(t.substr(1, t.size() - 2));
  ExprParser p{t, defined, error};
  double v = 0;
  if (!p.expr(v)) return std::nullopt;
  p.skip();
  if (p.i != t.size()) {
    error = fmt::format("unexpected '{}' after the expression", t.substr(p.i));
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    error = "the value is not finite";
    return std::nullopt;
  }
  return format_parameter_number(v);
}

}  // namespace inpact::parser
