#pragma once
/// The deck as a stream of lines: follows *INCLUDE files (relative to the including file,
/// nested, cycles detected), drops comments and blank lines, rejects binary input, and applies
/// *PARAMETER substitution (`<name>`) to every line after the definition.
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "fields.hpp"

namespace inpact::parser {

class LineSource {
 public:
  LineSource(SourceTable& sources, Diagnostics& diags,
             const std::map<std::string, std::string>& parameters);

  /// Opens the deck itself; false (with a diagnostic) when it cannot be read.
  bool open(const std::string& path);
  /// Continues with `path` (relative to the file of `from`) until its end, then resumes.
  void include(std::string_view path, SourceLoc from, const std::string& keyword);
  /// Reads a whole data file for a keyword's INPUT= parameter.
  std::vector<Line> read_data_file(std::string_view path, SourceLoc from, const std::string& keyword);

  /// The next significant line, after parameter substitution; nullopt at the end of the deck.
  std::optional<Line> next();

 private:
  struct OpenFile {
    std::uint32_t id;
    std::string_view text;
    std::size_t pos = 0;
    std::uint32_t line = 0;
  };
  std::optional<std::uint32_t> load(const std::string& path, bool included, SourceLoc from,
                                    const std::string& keyword);
  std::string resolve_relative(std::string_view path, SourceLoc from) const;
  std::string_view substitute(std::string_view text, SourceLoc loc);
  /// The next line of `f` that is not a comment or blank, substituted; nullopt at its end.
  std::optional<Line> next_significant(OpenFile& f);

  SourceTable& sources_;
  Diagnostics& diags_;
  const std::map<std::string, std::string>& parameters_;
  std::vector<OpenFile> stack_;
  std::deque<std::string> storage_;  ///< file texts and substituted lines; stable addresses
};

/// Significant lines of a text: no comments (`**`), no blank lines.
bool is_comment_or_blank(std::string_view line);

}  // namespace inpact::parser
