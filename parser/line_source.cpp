#include "line_source.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "text.hpp"

namespace inpact::parser {

namespace fs = std::filesystem;

LineSource::LineSource(SourceTable& sources, Diagnostics& diags,
                       const std::map<std::string, std::string>& parameters)
    : sources_(sources), diags_(diags), parameters_(parameters) {}

bool is_comment_or_blank(std::string_view line) {
  std::string_view t = trim(line);
  return t.empty() || (t.size() >= 2 && t[0] == '*' && t[1] == '*');
}

namespace {

/// The position of the first byte that cannot be in a text deck (a control character other
/// than tab, CR, LF and FF), or npos. Tested in blocks without an early exit so that the
/// compiler vectorises it: it runs over every byte of every deck.
std::size_t first_control_byte(std::string_view text) {
  // Bitwise & rather than &&: no branch per byte.
  auto is_bad = [](char ch) -> unsigned {
    const auto c = static_cast<unsigned char>(ch);
    return (c < 0x20) & (c != '\n') & (c != '\r') & (c != '\t') & (c != '\f');
  };
  constexpr std::size_t kBlock = 64;
  std::size_t i = 0;
  for (; i + kBlock <= text.size(); i += kBlock) {
    unsigned n_bad = 0;
    for (std::size_t k = 0; k < kBlock; ++k) n_bad += is_bad(text[i + k]);
    if (n_bad) break;
  }
  for (; i < text.size(); ++i)
    if (is_bad(text[i])) return i;
  return std::string_view::npos;
}

}  // namespace

std::optional<std::uint32_t> LineSource::load(const std::string& path, bool included,
                                              SourceLoc from, const std::string& keyword) {
  std::error_code ec;
  const std::string canonical = fs::weakly_canonical(path, ec).string();
  for (const auto& open : stack_) {
    if (fs::weakly_canonical(sources_.files[open.id].path, ec).string() == canonical) {
      diags_.error(from, keyword, fmt::format("'{}' includes itself (include cycle)", path));
      return std::nullopt;
    }
  }
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) {
    diags_.error(from, keyword, fmt::format("'{}' is a directory, not an input file", path));
    return std::nullopt;
  }
  // A device or a pipe would never end (/dev/zero) or block forever (a FIFO without a writer).
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    diags_.error(from, keyword, fmt::format("'{}' is not a regular file (a device or pipe cannot be an input file)", path));
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    diags_.error(from, keyword, fmt::format("cannot open '{}'", path));
    return std::nullopt;
  }
  // A regular file: read it whole in one go, at its size.
  std::string text(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)), '\0');
  in.seekg(0);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  storage_.push_back(std::move(text));
  const std::uint32_t id = sources_.add(path, included, from);
  const std::string& stored = storage_.back();
  // A NUL byte or a run of control characters means this is not a text deck at all: stop at
  // the first one rather than report a thousand meaningless keyword errors.
  const std::size_t bad = first_control_byte(stored);
  if (bad != std::string::npos) {
    const auto line = static_cast<std::uint32_t>(1 + std::count(stored.begin(), stored.begin() + bad, '\n'));
    diags_.error({id, line, 0}, "",
                 fmt::format("binary data (byte 0x{:02x}): this is not a text input deck",
                             static_cast<unsigned char>(stored[bad])));
    throw StopReading("binary input");
  }
  return id;
}

std::string LineSource::resolve_relative(std::string_view path, SourceLoc from) const {
  fs::path p{std::string(path)};
  if (p.is_absolute() || from.file >= sources_.files.size()) return p.string();
  return (fs::path(sources_.files[from.file].path).parent_path() / p).lexically_normal().string();
}

bool LineSource::open(const std::string& path) {
  auto id = load(path, false, {}, "");
  if (!id) return false;
  stack_.push_back({*id, storage_.back()});
  return true;
}

void LineSource::include(std::string_view path, SourceLoc from, const std::string& keyword) {
  if (stack_.size() >= 32) {
    diags_.error(from, keyword, "includes nested more than 32 deep");
    return;
  }
  auto id = load(resolve_relative(path, from), true, from, keyword);
  if (id) stack_.push_back({*id, storage_.back()});
}

std::vector<Line> LineSource::read_data_file(std::string_view path, SourceLoc from,
                                             const std::string& keyword) {
  std::vector<Line> lines;
  auto id = load(resolve_relative(path, from), true, from, keyword);
  if (!id) return lines;
  OpenFile f{*id, storage_.back()};
  while (auto line = next_significant(f)) lines.push_back(*line);
  return lines;
}

std::optional<Line> LineSource::next_significant(OpenFile& f) {
  while (f.pos < f.text.size()) {
    std::size_t end = f.text.find('\n', f.pos);
    if (end == std::string_view::npos) end = f.text.size();
    std::string_view raw = f.text.substr(f.pos, end - f.pos);
    f.pos = end + 1;
    ++f.line;
    if (is_comment_or_blank(raw)) continue;
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    SourceLoc loc{f.id, f.line, 0};
    return Line{substitute(raw, loc), loc};
  }
  return std::nullopt;
}

std::optional<Line> LineSource::next() {
  while (!stack_.empty()) {
    if (auto line = next_significant(stack_.back())) return line;
    stack_.pop_back();  // this file is done: back to the one that included it
  }
  return std::nullopt;
}

std::string_view LineSource::substitute(std::string_view text, SourceLoc loc) {
  if (text.find('<') == std::string_view::npos) return text;
  std::string out;
  std::size_t i = 0;
  bool changed = false;
  while (i < text.size()) {
    std::size_t open = text.find('<', i);
    if (open == std::string_view::npos) break;
    std::size_t close = text.find('>', open + 1);
    if (close == std::string_view::npos) break;
    const std::string name = normalize_name(text.substr(open + 1, close - open - 1));
    auto it = parameters_.find(name);
    out.append(text.substr(i, open - i));
    if (it == parameters_.end()) {
      diags_.error({loc.file, loc.line, static_cast<std::uint32_t>(open + 1)}, "",
                   fmt::format("parameter <{}> is not defined (define it with *PARAMETER or -P)",
                               text.substr(open + 1, close - open - 1)));
      out.append(text.substr(open, close - open + 1));
    } else {
      out.append(it->second);
      changed = true;
    }
    i = close + 1;
  }
  if (!changed) return text;
  out.append(text.substr(i));
  storage_.push_back(std::move(out));
  return storage_.back();
}

}  // namespace inpact::parser
