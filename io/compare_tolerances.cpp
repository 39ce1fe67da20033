/// Per-field tolerances of `inpact compare --tolerances FILE`: a small subset of TOML and of
/// YAML, enough for one flat table of settings per field. Our own ~150 lines rather than a
/// TOML or YAML library (toml11, toml++, yaml-cpp are all packaged in Debian): the file holds
/// a handful of numbers and we want every error to name file:line and the expected keys.
///
///   TOML                              YAML
///   [default]                         default:
///   rtol = 1e-6                         rtol: 1e-6
///   [CPRESS]      # or [fields.CPRESS]  CPRESS:
///   atol = 1e-6                         atol: 1e-6
///   scale = "frame-max"                 scale: frame-max
///   [CSTATUS]                         CSTATUS:
///   allowed_mismatches = 2              allowed_mismatches: 2
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "compare.hpp"

namespace inpact::io {

namespace {

struct Setting {
  std::string table, key, value;
  int line;
};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

/// Drops a `#` comment that is not inside quotes.
std::string strip_comment(const std::string& line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#') {
      return line.substr(0, i);
    }
  }
  return line;
}

std::string unquote(std::string v) {
  if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front()) return v.substr(1, v.size() - 2);
  return v;
}

std::vector<Setting> parse_toml(const std::string& text, const std::string& name) {
  std::vector<Setting> out;
  std::istringstream in(text);
  std::string raw, table = "default";
  for (int line = 1; std::getline(in, raw); ++line) {
    const std::string s = trim(strip_comment(raw));
    if (s.empty()) continue;
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3) throw std::invalid_argument(fmt::format("{}:{}: malformed table header '{}'", name, line, s));
      table = unquote(trim(s.substr(1, s.size() - 2)));
      if (table.rfind("fields.", 0) == 0) table = unquote(table.substr(7));
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw std::invalid_argument(fmt::format("{}:{}: expected key = value, got '{}'", name, line, s));
    out.push_back({table, trim(s.substr(0, eq)), unquote(trim(s.substr(eq + 1))), line});
  }
  return out;
}

std::vector<Setting> parse_yaml(const std::string& text, const std::string& name) {
  std::vector<Setting> out;
  std::istringstream in(text);
  std::string raw, table;
  for (int line = 1; std::getline(in, raw); ++line) {
    const std::string content = strip_comment(raw);
    const std::string s = trim(content);
    if (s.empty() || s == "---") continue;
    const bool indented = content.find_first_not_of(" \t") > 0;
    const auto colon = s.find(':');
    if (colon == std::string::npos) throw std::invalid_argument(fmt::format("{}:{}: expected key: value, got '{}'", name, line, s));
    const std::string key = unquote(trim(s.substr(0, colon)));
    const std::string value = unquote(trim(s.substr(colon + 1)));
    if (!indented) {
      if (key == "fields" && value.empty()) continue;  // `fields:` wrapping the field tables
      if (!value.empty()) {
        out.push_back({"default", key, value, line});  // a top-level setting is a default
        continue;
      }
      table = key;
      continue;
    }
    if (value.empty()) {  // a field table nested under `fields:`
      table = key;
      continue;
    }
    if (table.empty()) throw std::invalid_argument(fmt::format("{}:{}: '{}' is not inside a field table", name, line, key));
    out.push_back({table, key, value, line});
  }
  return out;
}

double number(const Setting& s, const std::string& name) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s.value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.value.size() || v < 0)
    throw std::invalid_argument(fmt::format("{}:{}: {}: expected a number >= 0, got '{}'", name, s.line, s.key, s.value));
  return v;
}

void apply(FieldTolerance& t, const Setting& s, const std::string& name) {
  if (s.key == "rtol") t.rtol = number(s, name);
  else if (s.key == "atol") t.atol = number(s, name);
  else if (s.key == "floor") t.floor = number(s, name);
  else if (s.key == "allowed_mismatches") t.allowed_mismatches = static_cast<std::int64_t>(number(s, name));
  else if (s.key == "scale") {
    if (s.value == "frame-max" || s.value == "frame_max") t.scale_by_frame_max = true;
    else if (s.value == "none") t.scale_by_frame_max = false;
    else throw std::invalid_argument(fmt::format("{}:{}: scale: expected \"frame-max\" or \"none\", got '{}'", name, s.line, s.value));
  } else if (s.key == "exact") {
    if (s.value == "true") t.exact = true;
    else if (s.value == "false") t.exact = false;
    else throw std::invalid_argument(fmt::format("{}:{}: exact: expected true or false, got '{}'", name, s.line, s.value));
  } else {
    throw std::invalid_argument(fmt::format(
        "{}:{}: unknown setting '{}' (expected rtol, atol, floor, scale, exact, allowed_mismatches)", name, s.line, s.key));
  }
}

}  // namespace

Tolerances parse_tolerances(const std::string& text, const std::string& format, const std::string& name) {
  const std::vector<Setting> settings = format == "toml" ? parse_toml(text, name) : parse_yaml(text, name);
  Tolerances t = default_tolerances();
  // The default table first (it changes the fallback), then the fields, which start from their
  // built-in tolerance (CPRESS stays scaled unless the file says otherwise) or the fallback.
  for (const Setting& s : settings)
    if (s.table == "default") apply(t.fallback, s, name);
  for (const Setting& s : settings) {
    if (s.table == "default") continue;
    auto it = t.fields.find(s.table);
    if (it == t.fields.end()) it = t.fields.emplace(s.table, t.fallback).first;
    apply(it->second, s, name);
  }
  return t;
}

Tolerances read_tolerances(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path, "cannot read the tolerance file");
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string ext = path.extension().string();
  std::string format;
  if (ext == ".toml") format = "toml";
  else if (ext == ".yaml" || ext == ".yml") format = "yaml";
  else throw std::invalid_argument(path.string() + ": tolerance file must end in .toml, .yaml or .yml");
  return parse_tolerances(buf.str(), format, path.string());
}

}  // namespace inpact::io
