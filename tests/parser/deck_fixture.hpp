#pragma once
/// Writes small decks to a temporary folder and reads them, for parser tests.
#include <filesystem>
#include <string>

#include "parser/read_deck.hpp"

namespace inpact::test {

class DeckDir {
 public:
  DeckDir();
  ~DeckDir();
  /// Writes `text` to `name` inside the folder; returns the path.
  std::string write(const std::string& name, const std::string& text) const;
  /// Writes `text` as `deck.inp` and reads it.
  parser::ReadResult read(const std::string& text, const parser::ReadOptions& options = {}) const;
  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

/// A unit cube of one C3D8 element with a section and material: the smallest valid model.
std::string one_cube_deck(const std::string& extra = "");

/// True when some diagnostic's formatted text contains `needle`.
bool has_diagnostic(const parser::ReadResult& r, const std::string& needle);

}  // namespace inpact::test
