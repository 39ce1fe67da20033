#include "deck_fixture.hpp"

#include <atomic>
#include <fstream>
#include <unistd.h>

namespace inpact::test {

namespace fs = std::filesystem;

DeckDir::DeckDir() {
  static std::atomic<int> counter{0};
  dir_ = fs::temp_directory_path() /
         ("inpact-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
  fs::create_directories(dir_);
}

DeckDir::~DeckDir() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

std::string DeckDir::write(const std::string& name, const std::string& text) const {
  const fs::path p = dir_ / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

parser::ReadResult DeckDir::read(const std::string& text, const parser::ReadOptions& options) const {
  return parser::read_deck(write("deck.inp", text), options);
}

std::string one_cube_deck(const std::string& extra) {
  return R"(*NODE, NSET=ALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
)" + extra;
}

bool has_diagnostic(const parser::ReadResult& r, const std::string& needle) {
  return r.report().find(needle) != std::string::npos;
}

}  // namespace inpact::test
