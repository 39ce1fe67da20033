#pragma once
/// Where a thing was written in the deck: every model entity that a later check may need to
/// blame keeps one, so solver errors can cite `file:line` too.
#include <cstdint>
#include <string>
#include <vector>

namespace inpact::model {

struct SourceLoc {
  std::uint32_t file = 0;  ///< index into SourceTable::files
  std::uint32_t line = 0;  ///< 1-based; 0 = unknown
  std::uint32_t col = 0;   ///< 1-based; 0 = whole line
};

/// The files a deck was read from, and which line of which file included each one.
struct SourceTable {
  struct File {
    std::string path;
    bool included = false;   ///< false for the deck itself
    SourceLoc included_from; ///< the *INCLUDE line, when included
  };
  std::vector<File> files;

  std::uint32_t add(std::string path, bool included, SourceLoc from) {
    files.push_back({std::move(path), included, from});
    return static_cast<std::uint32_t>(files.size() - 1);
  }

  /// "file:line:col" ("file:line" without a column, "file" without a line).
  std::string describe(SourceLoc loc) const {
    std::string out = loc.file < files.size() ? files[loc.file].path : std::string("<unknown>");
    if (loc.line == 0) return out;
    out += ":" + std::to_string(loc.line);
    if (loc.col != 0) out += ":" + std::to_string(loc.col);
    return out;
  }
};

}  // namespace inpact::model
