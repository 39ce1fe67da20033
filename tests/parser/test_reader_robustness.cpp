// Input the fuzzer (tests/fuzz) found the reader mishandling: each case is kept here so that
// it stays fixed in every build, not only in the fuzz build.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

// An element dropped for a bad node field must not leave its label in the index: the label
// would point at the next element's row, and a second definition read past the end of a table.
TEST(ReaderRobustness, DroppedElementLeavesNoLabelBehind) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*ELEMENT, TYPE=C3D8, ELSET=MORE\n"
                                  "2, 1, x, 3, 4, 5, 6, 7, 8\n"
                                  "2, 1, 2, 3, 4, 5, 6, 7, 8\n"
                                  "3, 1, 2, 3, 4, 5, 6, 7, 8\n"
                                  "*SOLID SECTION, ELSET=MORE, MATERIAL=STEEL\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:17:7: error: *ELEMENT: node label: expected an integer, found 'x'"))
      << r.report();
  EXPECT_FALSE(has_diagnostic(r, "defined twice")) << r.report();
  const auto& el = r.model.mesh.elements;
  ASSERT_EQ(el.size(), 3u);
  EXPECT_EQ(el.labels[*el.index.find(0, 2)], 2);
  EXPECT_EQ(el.labels[*el.index.find(0, 3)], 3);
}

TEST(ReaderRobustness, DuplicateElementCitesTheFirstDefinition) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:17:1: error: *ELEMENT: element 1 is defined twice (first at line 11)"))
      << r.report();
}

// A device or a pipe as an include would be read forever (/dev/zero) or block (a FIFO).
TEST(ReaderRobustness, IncludeOfADeviceOrPipeIsRefused) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*INCLUDE, INPUT=/dev/zero\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:16:17: error: *INCLUDE: '/dev/zero' is not a regular file")) << r.report();
  const std::string fifo = (dir.path() / "pipe.inp").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  auto r2 = dir.read(one_cube_deck("*INCLUDE, INPUT=pipe.inp\n"));
  EXPECT_TRUE(has_diagnostic(r2, "'" + fifo + "' is not a regular file")) << r2.report();
}
