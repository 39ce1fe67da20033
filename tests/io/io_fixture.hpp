#pragma once
/// A temporary folder and the small model the io tests write: three bodies (C3D8 cube, C3D4
/// tet on its top, C3D6 wedge beside it) with sets, element and node surfaces, a contact pair
/// and two static steps.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "parser/read_deck.hpp"

namespace inpact::test {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           ("inpact-io-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    if (!std::getenv("INPACT_KEEP_TEST_FILES")) std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return dir_; }
  std::filesystem::path operator/(const std::string& name) const { return dir_ / name; }

  parser::ReadResult read(const std::string& deck) const {
    const auto p = dir_ / "deck.inp";
    std::ofstream(p, std::ios::binary) << deck;
    return parser::read_deck(p.string());
  }

 private:
  std::filesystem::path dir_;
};

inline const char* kThreeBodyDeck = R"(*HEADING
io test model
*NODE, NSET=ALL_N
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 1, 0.5, 2
10, 2, 0, 0
11, 3, 0, 0
12, 2, 1, 0
13, 2, 0, 1
14, 3, 0, 1
15, 2, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*ELEMENT, TYPE=C3D4, ELSET=TET
2, 5, 6, 7, 9
*ELEMENT, TYPE=C3D6, ELSET=WEDGE
7, 10, 11, 12, 13, 14, 15
*ELSET, ELSET=ALL_E
CUBE, TET, WEDGE
*NSET, NSET=TIP
9
*SURFACE, NAME=MASTER_S, TYPE=ELEMENT
CUBE, S4
*SURFACE, NAME=SLAVE_S, TYPE=ELEMENT
WEDGE, S5
*SURFACE, NAME=TIPS, TYPE=NODE
TIP
*SOLID SECTION, ELSET=ALL_E, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SURFACE INTERACTION, NAME=FRIC
*FRICTION
0.2
*CONTACT PAIR, INTERACTION=FRIC
SLAVE_S, MASTER_S
*STEP, NAME=Load, NLGEOM
*STATIC
0.5, 1.0
*END STEP
*STEP, NAME=Unload
*STATIC
1.0, 2.0
*END STEP
)";

}  // namespace inpact::test
