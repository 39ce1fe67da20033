#include "keyword_line.hpp"

#include "text.hpp"

namespace inpact::parser {

bool is_keyword_line(std::string_view text) {
  std::string_view t = trim(text);
  return !t.empty() && t[0] == '*' && (t.size() == 1 || t[1] != '*');
}

KeywordLine parse_keyword_line(const std::vector<Line>& pieces) {
  KeywordLine kw;
  kw.loc = pieces.front().loc;
  std::vector<Field> fields, all;
  for (const Line& piece : pieces) {
    split_fields(piece, fields);
    all.insert(all.end(), fields.begin(), fields.end());
  }
  bool first = true;
  for (const Field& f : all) {
    if (first) {
      std::string_view t = f.text;
      if (!t.empty() && t[0] == '*') t.remove_prefix(1);
      kw.text = "*" + normalize_label(t);
      kw.name = normalize_name(t);
      kw.loc = f.loc;
      first = false;
      continue;
    }
    if (f.text.empty()) continue;
    KeywordParam p;
    p.loc = f.loc;
    const std::size_t eq = f.text.find('=');
    if (eq == std::string_view::npos) {
      p.name = normalize_name(f.text);
    } else {
      p.name = normalize_name(f.text.substr(0, eq));
      std::string_view v = f.text.substr(eq + 1);
      std::size_t lead = 0;
      while (lead < v.size() && (v[lead] == ' ' || v[lead] == '\t')) ++lead;
      v = trim(v);
      if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
      p.value = std::string(v);
      p.value_loc = {f.loc.file, f.loc.line, static_cast<std::uint32_t>(f.loc.col + eq + 1 + lead)};
    }
    kw.params.push_back(std::move(p));
  }
  return kw;
}

}  // namespace inpact::parser
