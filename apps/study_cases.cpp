#include "study_cases.hpp"

#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <unistd.h>

namespace inpact::app::study {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestMagic = "# inpact study manifest 1";

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

bool valid_name(const std::string& n) {
  if (n.empty()) return false;
  for (char c : n)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
  return true;
}

}  // namespace

std::pair<std::string, std::vector<std::string>> parse_grid(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("--grid: expected name=v1,v2,..., got '" + text + "'");
  const std::string name = trim(text.substr(0, eq));
  if (!valid_name(name)) throw std::invalid_argument("--grid: '" + name + "' is not a parameter name");
  std::vector<std::string> values;
  std::stringstream in(text.substr(eq + 1));
  for (std::string v; std::getline(in, v, ',');) {
    v = trim(v);
    if (v.empty()) throw std::invalid_argument("--grid " + name + ": empty value in '" + text + "'");
    values.push_back(v);
  }
  if (values.empty()) throw std::invalid_argument("--grid " + name + ": no values");
  return {name, values};
}

std::vector<Parameters> parse_samples(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  std::vector<Parameters> rows;
  for (int n = 1; std::getline(in, line); ++n) {
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    auto fields = split_csv_line(line);
    for (auto& f : fields) f = trim(f);
    if (header.empty()) {
      for (const auto& h : fields)
        if (!valid_name(h)) throw std::invalid_argument(fmt::format("{}:{}: '{}' is not a parameter name", name, n, h));
      header = fields;
      continue;
    }
    if (fields.size() != header.size())
      throw std::invalid_argument(fmt::format("{}:{}: {} values, the header names {} parameters", name, n, fields.size(),
                                              header.size()));
    Parameters p;
    for (std::size_t i = 0; i < header.size(); ++i) p.emplace_back(header[i], fields[i]);
    rows.push_back(std::move(p));
  }
  if (rows.empty()) throw std::invalid_argument(name + ": no sample rows");
  return rows;
}

std::vector<Parameters> read_samples(const fs::path& path) { return parse_samples(read_text(path), path.string()); }

std::vector<Case> expand_cases(const std::vector<std::pair<std::string, std::vector<std::string>>>& grids,
                               const std::vector<Parameters>& samples) {
  std::set<std::string> seen;
  for (const auto& [name, values] : grids)
    if (!seen.insert(name).second) throw std::invalid_argument("--grid " + name + " given twice");
  if (!samples.empty())
    for (const auto& [name, value] : samples.front())
      if (seen.count(name)) throw std::invalid_argument("parameter " + name + " is both in a --grid and in the samples");

  std::vector<Parameters> combos{Parameters{}};
  for (const auto& [name, values] : grids) {
    std::vector<Parameters> next;
    for (const auto& c : combos)
      for (const auto& v : values) {
        Parameters p = c;
        p.emplace_back(name, v);
        next.push_back(std::move(p));
      }
    combos = std::move(next);
  }
  if (!samples.empty()) {
    std::vector<Parameters> next;
    for (const auto& c : combos)
      for (const auto& s : samples) {
        Parameters p = c;
        p.insert(p.end(), s.begin(), s.end());
        next.push_back(std::move(p));
      }
    combos = std::move(next);
  }
  const int width = std::max<int>(4, static_cast<int>(std::to_string(combos.size()).size()));
  std::vector<Case> cases;
  for (std::size_t i = 0; i < combos.size(); ++i) cases.push_back({fmt::format("c{:0{}}", i + 1, width), combos[i]});
  return cases;
}

Shard parse_shard(const std::string& text) {
  Shard s;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> s.index >> slash >> s.count) || slash != '/' || !in.eof() || s.count < 1 || s.index < 1 || s.index > s.count)
    throw std::invalid_argument("--shard: expected i/n with 1 <= i <= n, got '" + text + "'");
  return s;
}

CollectSpec parse_collect(const std::string& text) {
  CollectSpec c;
  c.text = text;
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("--collect: expected OP:VAR[@NSET] (e.g. max:CPRESS, sum:RF2@TOP), got '" + text + "'");
  c.op = text.substr(0, colon);
  if (c.op != "max" && c.op != "min" && c.op != "maxabs" && c.op != "sum")
    throw std::invalid_argument("--collect " + text + ": unknown operation '" + c.op + "' (max, min, maxabs, sum)");
  std::string rest = text.substr(colon + 1);
  if (const auto at = rest.find('@'); at != std::string::npos) {
    c.nset = rest.substr(at + 1);
    rest = rest.substr(0, at);
    if (c.nset.empty()) throw std::invalid_argument("--collect " + text + ": empty node set after '@'");
  }
  if (!rest.empty() && rest[0] == '-') {
    c.negate = true;
    rest = rest.substr(1);
  }
  if (!valid_name(rest)) throw std::invalid_argument("--collect " + text + ": '" + rest + "' is not a field or component");
  c.var = rest;
  return c;
}

fs::path Manifest::results_path(const std::string& id) { return fs::path("cases") / id / (id + ".h5"); }

const Case* Manifest::find(const std::string& id) const {
  for (const auto& c : cases)
    if (c.id == id) return &c;
  return nullptr;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(std::move(cur));
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(std::move(cur));
  return out;
}

std::string format_manifest(const Manifest& m) {
  std::string s = std::string(kManifestMagic) + "\n";
  s += "# deck: " + m.deck + "\n";
  s += "# collect:";
  for (const auto& c : m.collect) s += " " + c;
  s += "\nid,deck,results";
  for (const auto& n : m.parameter_names) s += "," + csv_field(n);
  s += "\n";
  for (const Case& c : m.cases) {
    s += c.id + "," + csv_field(m.deck) + "," + csv_field(Manifest::results_path(c.id).string());
    for (const auto& [name, value] : c.parameters) s += "," + csv_field(value);
    s += "\n";
  }
  return s;
}

Manifest parse_manifest(const std::string& text, const std::string& name) {
  Manifest m;
  std::istringstream in(text);
  std::string line;
  bool header = false;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == 1 && line != kManifestMagic) throw std::invalid_argument(name + ": not an inpact study manifest");
    if (line.rfind("# deck: ", 0) == 0) {
      m.deck = line.substr(8);
      continue;
    }
    if (line.rfind("# collect:", 0) == 0) {
      std::istringstream specs(line.substr(10));
      for (std::string s; specs >> s;) m.collect.push_back(s);
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    const auto fields = split_csv_line(line);
    if (!header) {
      if (fields.size() < 3 || fields[0] != "id") throw std::invalid_argument(fmt::format("{}:{}: expected the header id,deck,results,...", name, n));
      m.parameter_names.assign(fields.begin() + 3, fields.end());
      header = true;
      continue;
    }
    if (fields.size() != 3 + m.parameter_names.size())
      throw std::invalid_argument(fmt::format("{}:{}: {} fields, expected {}", name, n, fields.size(), 3 + m.parameter_names.size()));
    Case c{fields[0], {}};
    for (std::size_t i = 0; i < m.parameter_names.size(); ++i) c.parameters.emplace_back(m.parameter_names[i], fields[3 + i]);
    m.cases.push_back(std::move(c));
  }
  if (!header) throw std::invalid_argument(name + ": no header line");
  return m;
}

void write_atomically(const fs::path& path, const std::string& text) {
  // The temporary name holds the pid: two shards writing the same file do not collide.
  fs::path tmp = path;
  tmp += fmt::format(".tmp{}", getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error(tmp.string() + ": cannot write");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot rename " + tmp.filename().string() + ": " + ec.message());
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::ostringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

}  // namespace inpact::app::study
