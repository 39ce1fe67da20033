// The keyword language itself: comments, case and blanks, continuation, includes, parameters.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "parser/fields.hpp"
#include "parser/keyword_line.hpp"
#include "parser/parameters.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

TEST(Fields, SplitKeepsColumnsAndDropsTrailingComma) {
  parser::Line line{" 12, 1.5 ,,3,", {0, 7, 0}};
  std::vector<parser::Field> f;
  parser::split_fields(line, f);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0].text, "12");
  EXPECT_EQ(f[0].loc.col, 2u);
  EXPECT_EQ(f[1].text, "1.5");
  EXPECT_EQ(f[1].loc.col, 6u);
  EXPECT_TRUE(f[2].empty());
  EXPECT_EQ(f[3].text, "3");
}

TEST(Fields, NumbersInFortranAndAbaqusForms) {
  EXPECT_DOUBLE_EQ(*parser::parse_real("1.5D3"), 1500.0);
  EXPECT_DOUBLE_EQ(*parser::parse_real("+.5"), 0.5);
  EXPECT_DOUBLE_EQ(*parser::parse_real("2.E-3"), 2e-3);
  EXPECT_DOUBLE_EQ(*parser::parse_real("210000."), 210000.0);
  EXPECT_FALSE(parser::parse_real("nan"));
  EXPECT_FALSE(parser::parse_real("inf"));
  EXPECT_FALSE(parser::parse_real("1.5x"));
  EXPECT_FALSE(parser::parse_real(""));
  EXPECT_EQ(*parser::parse_int("+42"), 42);
  EXPECT_FALSE(parser::parse_int("4.2"));
}

TEST(KeywordLine, NamesAreCaseAndBlankInsensitive) {
  auto kw = parser::parse_keyword_line({{"*end   Step", {0, 1, 0}}});
  EXPECT_EQ(kw.name, "ENDSTEP");
  auto kw2 = parser::parse_keyword_line({{"*Surface Behavior, pressure-overclosure = hard, Penalty", {0, 3, 0}}});
  EXPECT_EQ(kw2.name, "SURFACEBEHAVIOR");
  ASSERT_EQ(kw2.params.size(), 2u);
  EXPECT_EQ(kw2.params[0].name, "PRESSURE-OVERCLOSURE");
  EXPECT_EQ(*kw2.params[0].value, "hard");
  EXPECT_EQ(kw2.params[0].value_loc.col, 43u);  // where 'hard' starts
  EXPECT_EQ(kw2.params[1].name, "PENALTY");
  EXPECT_FALSE(kw2.params[1].value);
}

TEST(Parameters, ArithmeticAndReferences) {
  std::map<std::string, std::string> defined{{"L", "2.5"}};
  std::string err;
  EXPECT_EQ(*parser::evaluate_parameter("2*L + 1", defined, err), "6");
  EXPECT_EQ(*parser::evaluate_parameter("L**2 / (1 - 0.5)", defined, err), "12.5");
  EXPECT_EQ(*parser::evaluate_parameter("-L", defined, err), "-2.5");
  EXPECT_FALSE(parser::evaluate_parameter("2*M", defined, err));
  EXPECT_NE(err.find("'M' is not defined"), std::string::npos);
  err.clear();
  EXPECT_FALSE(parser::evaluate_parameter("1/0", defined, err));
  EXPECT_NE(err.find("division by zero"), std::string::npos);
}

TEST(Deck, CommentsBlankLinesAndKeywordContinuation) {
  DeckDir dir;
  auto r = dir.read("** a comment\n\n" + one_cube_deck() +
                    "*NSET,\n  NSET=CORNER\n1\n**\n*ELSET, ELSET = Both ,\n  GENERATE\n1, 1\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.nsets.at("CORNER").rows.size(), 1u);
  EXPECT_EQ(r.model.mesh.elsets.at("BOTH").rows.size(), 1u);
}

TEST(Deck, ParameterSubstitutionAndCommandLineOverride) {
  DeckDir dir;
  const std::string deck = "*PARAMETER\nE = 100.\nnu = 0.25\n" + one_cube_deck() +
                           "*MATERIAL, NAME=P\n*ELASTIC\n<E>, <nu>\n";
  auto r = dir.read(deck);
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_DOUBLE_EQ(r.model.materials.at("P").elastic->youngs_modulus, 100.0);
  parser::ReadOptions opts;
  opts.parameters["e"] = "7";
  auto r2 = dir.read(deck, opts);
  ASSERT_TRUE(r2.ok()) << r2.report();
  EXPECT_DOUBLE_EQ(r2.model.materials.at("P").elastic->youngs_modulus, 7.0);
  EXPECT_DOUBLE_EQ(r2.model.materials.at("P").elastic->poissons_ratio, 0.25);
}

TEST(Deck, UndefinedParameterIsAnErrorAtItsColumn) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*MATERIAL, NAME=P\n*ELASTIC\n1., <nu>\n"));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:5: error: parameter <nu> is not defined")) << r.report();
}

TEST(Deck, NestedIncludesRelativeToTheIncludingFile) {
  DeckDir dir;
  dir.write("mesh/nodes.inp", "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*INCLUDE, INPUT=more.inp\n");
  dir.write("mesh/more.inp", "5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n");
  auto r = dir.read("*INCLUDE, INPUT=mesh/nodes.inp\n*ELEMENT, TYPE=C3D8, ELSET=E\n1,1,2,3,4,5,6,7,8\n"
                    "*SOLID SECTION, ELSET=E, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.nodes.size(), 8u);
  EXPECT_EQ(r.model.sources.files.size(), 3u);
}

TEST(Deck, MissingAndCyclicIncludesCiteTheIncludeLine) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*INCLUDE, INPUT=nothere.inp\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:16:17: error: *INCLUDE: cannot open")) << r.report();

  dir.write("a.inp", "*INCLUDE, INPUT=b.inp\n");
  dir.write("b.inp", "*INCLUDE, INPUT=a.inp\n");
  auto r2 = dir.read(one_cube_deck("*INCLUDE, INPUT=a.inp\n"));
  EXPECT_TRUE(has_diagnostic(r2, "include cycle")) << r2.report();
  EXPECT_TRUE(has_diagnostic(r2, "b.inp:1:")) << r2.report();
  EXPECT_TRUE(has_diagnostic(r2, "included from")) << r2.report();
}

TEST(Deck, EmptyDeckBinaryGarbageAndLongLines) {
  DeckDir dir;
  auto empty = dir.read("** nothing but a comment\n");
  EXPECT_TRUE(has_diagnostic(empty, "the deck is empty")) << empty.report();

  std::string garbage = "*NODE\n1, 0, 0, 0\n";
  garbage += std::string("\x7f\x45\x4c\x46\x02\x01\x01\x00\x00", 9);
  auto bin = dir.read(garbage);
  EXPECT_TRUE(has_diagnostic(bin, "deck.inp:3: error: binary data")) << bin.report();

  // A 200 000-character line is read, and its bad field is found at the right column.
  std::string long_line = "1, 2, 3, 4, 5, 6, 7, 8" + std::string(200000, ' ') + ", x";
  auto longr = dir.read("*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                        "*ELEMENT, TYPE=C3D8\n" + long_line + "\n");
  EXPECT_TRUE(has_diagnostic(longr, "deck.inp:11:200025: error: *ELEMENT: node label: expected an integer, found 'x'")) << longr.report();
}

TEST(Deck, UnknownKeywordAndParameterSuggestTheSpelling) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*ELASTIK\n1., 0.3\n*NSET, NSTE=A\n1\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:16:1: error: unknown keyword '*ELASTIK' (did you mean *ELASTIC?)")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:8: error: *NSET: unknown parameter 'NSTE' (did you mean NSET?)")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "missing required parameter NSET")) << r.report();
}

TEST(Deck, UnsupportedAbaqusKeywordSaysSo) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*HYPERFOAM, N=1\n1., 2., 0.\n"));
  EXPECT_TRUE(has_diagnostic(r, "*HYPERFOAM: this Abaqus keyword is not supported by inpact yet")) << r.report();
}

TEST(Deck, ErrorsAreCollectedUpToTheLimit) {
  DeckDir dir;
  std::string deck = "*NODE\n";
  for (int i = 1; i <= 100; ++i) deck += std::to_string(i) + ", x, 0, 0\n";
  parser::ReadOptions opts;
  opts.max_errors = 10;
  auto r = dir.read(deck, opts);
  EXPECT_EQ(r.diagnostics.error_count(), 10u);
}
