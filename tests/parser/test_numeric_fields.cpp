// Fields of a numeric data line that inpact does not read (KeywordSpec::numbers_from): they
// must be numbers or empty, as Abaqus reads them; names where a keyword takes names stay names.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

namespace {

/// The cube (its *ELASTIC data line is line 15) with `elastic` as that line, `extra` from line
/// 16 on.
std::string cube(const std::string& elastic, const std::string& extra = "") {
  std::string d = one_cube_deck(extra);
  const std::string given = "210000., 0.3\n";
  d.replace(d.find(given), given.size(), elastic + "\n");
  return d;
}

/// The errors reported for `keyword` (a failed *ELASTIC also leaves its material without one).
std::size_t n_errors(const parser::ReadResult& r, const std::string& keyword) {
  const auto& all = r.diagnostics.all();
  return static_cast<std::size_t>(std::count_if(all.begin(), all.end(), [&](const parser::Diagnostic& d) {
    return d.severity == parser::Diagnostic::Severity::Error && d.keyword == keyword;
  }));
}

}  // namespace

// *ELASTIC reads E and ν; the third field (the temperature of a temperature-dependent table)
// is not used, and "abc" there was accepted without a word.
TEST(NumericFields, AWordInAnUnusedFieldOfElasticIsAnError) {
  DeckDir dir;
  auto r = dir.read(cube("210000.0, 0.3, abc"));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(n_errors(r, "*ELASTIC"), 1u) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:15:16: error: *ELASTIC: field 3: expected a number, found 'abc'"))
      << r.report();
}

TEST(NumericFields, NumbersAndEmptyFieldsInUnusedFieldsAreAccepted) {
  DeckDir dir;
  for (const char* line : {"210000., 0.3, 20.", "210000., 0.3, ", "210000., 0.3,", "210000., 0.3, 1.5D1"}) {
    auto r = dir.read(cube(line));
    EXPECT_TRUE(r.ok()) << line << "\n" << r.report();
  }
}

// The same rule on other keywords' unused fields: *DENSITY's temperature, *NODE's fifth to
// seventh fields, *STATIC's fifth (CalculiX's CFD increment), *FRICTION's slip rate, *DLOAD's
// fields after a face pressure; each reported at its field.
TEST(NumericFields, EveryNumericKeywordChecksItsUnusedFields) {
  struct Case {
    std::string extra, keyword, expected;
  };
  const Case cases[] = {
      {"*DENSITY\n7.8e-9, hot\n", "*DENSITY",
       "deck.inp:17:9: error: *DENSITY: field 2: expected a number, found 'hot'"},
      {"*NODE\n9, 0., 0., 2., x\n", "*NODE", "deck.inp:17:16: error: *NODE: normal component: expected a number, found 'x'"},
      {"*SURFACE INTERACTION, NAME=I\n*FRICTION\n0.1, 0., fast\n", "*FRICTION",
       "deck.inp:18:10: error: *FRICTION: field 3: expected a number, found 'fast'"},
      {"*STEP\n*STATIC\n0.1, 1., 1e-5, 1., cfd\n*END STEP\n", "*STATIC",
       "deck.inp:18:20: error: *STATIC: field 5: expected a number, found 'cfd'"},
      {"*STEP\n*STATIC\n*DLOAD\nCUBE, P2, 10., 0., y\n*END STEP\n", "*DLOAD",
       "deck.inp:19:20: error: *DLOAD: field 5: expected a number, found 'y'"},
  };
  DeckDir dir;
  for (const Case& c : cases) {
    auto r = dir.read(cube("210000., 0.3", c.extra));
    EXPECT_FALSE(r.ok()) << c.extra;
    EXPECT_EQ(n_errors(r, c.keyword), 1u) << c.extra << r.report();
    EXPECT_TRUE(has_diagnostic(r, c.expected)) << c.extra << r.report();
  }
}

// Where a keyword takes names (node and element sets, boundary types, load types, surfaces),
// they are not numbers and need not be.
TEST(NumericFields, NamesWhereAKeywordTakesNamesStayNames) {
  DeckDir dir;
  auto r = dir.read(cube("210000., 0.3", "*NSET, NSET=BOT\n1, 2, 3, 4\n*SURFACE, NAME=TOP\nCUBE, S2\n"
                                         "*AMPLITUDE, NAME=RAMP\n0., 0., 1., 1.\n*BOUNDARY\nBOT, ENCASTRE\n"
                                         "*STEP\n*STATIC\n0.5, 1.\n*BOUNDARY\nBOT, 1, 3, 0.\n*CLOAD, AMPLITUDE=RAMP\n"
                                         "ALL, 3, 1.\n*DLOAD\nCUBE, P2, 10.\n*DSLOAD\nTOP, P, 5.\n"
                                         "*TEMPERATURE\nBOT, 20.\n*END STEP\n"));
  EXPECT_TRUE(r.ok()) << r.report();
}

// One error a line: a field the handler reads and reports is not reported again, nor is the
// rest of its line; a keyword the handler refuses on its keyword line gets no field checks.
TEST(NumericFields, OneErrorALineAndNoneOnTheDataOfARefusedKeyword) {
  DeckDir dir;
  auto r = dir.read(cube("210000., nu, abc"));
  EXPECT_EQ(n_errors(r, "*ELASTIC"), 1u) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:15:10: error: *ELASTIC: Poisson's ratio: expected a number, found 'nu'"))
      << r.report();
  std::string refused = one_cube_deck();
  refused.replace(refused.find("*ELASTIC\n"), 9, "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n");
  refused.replace(refused.find("210000., 0.3\n"), 13, "210000., 0.3, abc\n");
  r = dir.read(refused);
  EXPECT_EQ(n_errors(r, "*ELASTIC"), 1u) << r.report();
  // ENGINEERING CONSTANTS is read now: the one error is the short line, not also its 'abc'.
  EXPECT_TRUE(has_diagnostic(r, "*ELASTIC: expected 9 constants")) << r.report();
}
