// Input the fuzzer (tests/fuzz) found the reader mishandling: each case is kept here so that
// it stays fixed in every build, not only in the fuzz build.
#include <sys/stat.h>

#include <cstdint>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "parser/fields.hpp"

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

// GENERATE over a range far wider than the mesh must not walk it label by label, nor overflow
// near the int64 limit.
TEST(ReaderRobustness, GenerateRangesAtTheLimitsOfInt64) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*NSET, NSET=HUGE, GENERATE\n1, 9223372036854775807, 2\n"
                                  "*NSET, NSET=TOP, GENERATE\n9223372036854775800, 9223372036854775807, 5\n"
                                  "*ELSET, ELSET=EVERY, GENERATE\n-9223372036854775807, 9223372036854775807, 4611686018427387904\n"
                                  "*NSET, NSET=SMALL, GENERATE\n2, 8, 3\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& m = r.model.mesh;
  auto labels_of = [&](const std::string& name) {
    std::vector<std::int64_t> out;
    for (auto row : m.nsets.at(name).rows) out.push_back(m.nodes.labels[row]);
    return out;
  };
  EXPECT_EQ(labels_of("HUGE"), (std::vector<std::int64_t>{1, 3, 5, 7}));
  EXPECT_TRUE(m.nsets.at("TOP").rows.empty());
  EXPECT_EQ(labels_of("SMALL"), (std::vector<std::int64_t>{2, 5, 8}));
  ASSERT_EQ(m.elsets.at("EVERY").rows.size(), 1u);  // -(2^63 - 1) + 2·2^62 = 1
  EXPECT_EQ(m.elements.labels[m.elsets.at("EVERY").rows[0]], 1);
}

// parse_int's fast path for plain digits must neither overflow on 18 non-digits nor change
// what the general path accepts.
TEST(ReaderRobustness, IntegersAtTheEdges) {
  EXPECT_FALSE(parser::parse_int("~~~~~~~~~~~~~~~~~~"));
  EXPECT_FALSE(parser::parse_int("12345678901234567x"));
  EXPECT_FALSE(parser::parse_int("+"));
  EXPECT_FALSE(parser::parse_int("++1"));
  EXPECT_EQ(*parser::parse_int("007"), 7);
  EXPECT_EQ(*parser::parse_int("999999999999999999"), 999999999999999999);
  EXPECT_EQ(*parser::parse_int("9223372036854775807"), INT64_MAX);
  EXPECT_EQ(*parser::parse_int("-9223372036854775808"), INT64_MIN);
  EXPECT_FALSE(parser::parse_int("9223372036854775808"));
}

// A field a megabyte long is quoted in part: the report stays readable.
TEST(ReaderRobustness, HugeFieldIsQuotedInPart) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*NODE\n9, " + std::string(1000000, 'x') + ", 0., 0.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:17:4: error: *NODE: coordinate 1: expected a number, found '" +
                                    std::string(60, 'x') + "...' (1000000 characters)"))
      << r.report().substr(0, 2000);
  EXPECT_LT(r.report().size(), 1000u);
}
