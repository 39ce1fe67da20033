// The .dat print file (io/dat_report.hpp): Abaqus's number format and table layout, and a
// uniaxial bar run end to end (solver::run_analysis → DatReport) whose printed values are
// checked against the hand solution σ = F/A, u = σL/E, ΣRF = −F, MISES = |σ|.
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "io/dat_report.hpp"
#include "io_fixture.hpp"
#include "solver/analysis.hpp"

namespace inpact::io {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

TEST(DatReport, NumbersAreFortran1PG12Point4AsAbaqusPrintsThem) {
  EXPECT_EQ(fortran_g(7.3531e-4, 12, 4), "  7.3531E-04");
  EXPECT_EQ(fortran_g(-4.66977e-3, 12, 4), " -4.6698E-03");
  EXPECT_EQ(fortran_g(2.9412e8, 12, 4), "  2.9412E+08");
  EXPECT_EQ(fortran_g(5000.0, 12, 4), "   5000.    ");
  EXPECT_EQ(fortran_g(-1000.0, 12, 4), "  -1000.    ");
  EXPECT_EQ(fortran_g(250.0, 12, 4), "   250.0    ");
  EXPECT_EQ(fortran_g(0.25, 12, 4), "  0.2500    ");
  EXPECT_EQ(fortran_g(0.0, 12, 4), "   0.000    ");
  EXPECT_EQ(fortran_g(9999.6, 12, 4), "  9.9996E+03");  // rounds past 10^4 in F: E instead
  EXPECT_EQ(fortran_g(0.099, 12, 4), "  9.9000E-02");
  // The increment summary's 1PG10.3 (Getting Started: "COMPLETED   1.00", "2.220E-16").
  EXPECT_EQ(fortran_g(1.0, 10, 3), "  1.00    ");
  EXPECT_EQ(fortran_g(2.22e-16, 10, 3), " 2.220E-16");
}

TEST(DatReport, NodeTableHasAbaqusColumnsSummaryAndTotalsAndLeavesZeroRowsOut) {
  PrintTable t;
  t.domain = PrintTable::Domain::Node;
  t.set = "BASE";
  t.columns = {"RF1", "RF2"};
  t.labels = {103, 101, 102};
  t.values = {0.0, 5000.0, -9.0949e-13, 5000.0, 1e-30, 0.0};  // node 102's 1e-30 is round-off
  t.totals = true;
  const auto lines = lines_of(format_print_table(t));
  const std::vector<std::string> expected = {
      "   THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET BASE",
      "",
      "       NODE FOOT-  RF1         RF2     ",
      "            NOTE",
      "",
      "        101     -9.0949E-13   5000.    ",
      "        103       0.000       5000.    ",
      "",
      " MAXIMUM          0.000       5000.    ",
      " AT NODE               102         101 ",
      "",
      " MINIMUM        -9.0949E-13   0.000    ",
      " AT NODE               101         102 ",
      "",
      " TOTAL          -9.0949E-13  1.0000E+04",
      "",
  };
  EXPECT_EQ(lines, expected);
}

TEST(DatReport, ElementTableIsPrintedPerTypeAtTheIntegrationPoints) {
  PrintTable t;
  t.domain = PrintTable::Domain::Element;
  t.element_type = "C3D8";
  t.columns = {"S11", "MISES"};
  t.labels = {7, 7};
  t.ip = {2, 1};
  t.values = {-1.0, 1.0, 2.0, 2.0};
  t.summary = false;
  const auto lines = lines_of(format_print_table(t));
  ASSERT_GE(lines.size(), 7u);
  EXPECT_EQ(lines[0], "   THE FOLLOWING TABLE IS PRINTED FOR ALL ELEMENTS WITH TYPE C3D8 AT THE INTEGRATION POINTS");
  EXPECT_EQ(lines[2], "    ELEMENT  PT FOOT-       S11         MISES   ");
  EXPECT_EQ(lines[3], "                NOTE");
  EXPECT_EQ(lines[5], "           7   1           2.000       2.000    ");  // sorted by point
  EXPECT_EQ(lines[6], "           7   2          -1.000       1.000    ");
  EXPECT_EQ(lines.size(), 8u);  // SUMMARY=NO: no MAXIMUM/MINIMUM
}

// A beam's stresses are at its section points: a SEC PT column after PT, rows sorted by element,
// point and section point.
TEST(DatReport, BeamTableHasASectionPointColumn) {
  PrintTable t;
  t.domain = PrintTable::Domain::Element;
  t.element_type = "B31";
  t.columns = {"S11", "S12"};
  t.labels = {3, 3, 3};
  t.ip = {1, 1, 1};
  t.at_section_points = true;
  t.section_point = {25, 1, 5};
  t.values = {-1.0, 0.5, 1.0, 0.5, 2.0, 0.5};
  t.summary = false;
  const auto lines = lines_of(format_print_table(t));
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[2], "    ELEMENT  PT SEC FOOT-   S11         S12     ");
  EXPECT_EQ(lines[3], "                 PT NOTE");
  EXPECT_EQ(lines[5], "           3   1   1       1.000      0.5000    ");
  EXPECT_EQ(lines[6], "           3   1   5       2.000      0.5000    ");
  EXPECT_EQ(lines[7], "           3   1  25      -1.000      0.5000    ");
}

// --- A uniaxial bar run end to end ------------------------------------------------------

/// 2 × 2 × 10 bar of five C3D8 along z, E = 200000, ν = 0.3, z = 0 held axially (and against
/// rigid motion only), F = 4 × 250 = 1000 at z = 10: σ33 = F/A = 250, u3(top) = σL/E = 0.0125.
std::string bar_deck() {
  std::string d = "*HEADING\nUniaxial bar\n*NODE, NSET=ALLN\n";
  const int xy[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  for (int k = 0; k <= 5; ++k)
    for (int i = 0; i < 4; ++i) d += fmt::format("{}, {}, {}, {}\n", 4 * k + i + 1, xy[i][0], xy[i][1], 2 * k);
  d += "*ELEMENT, TYPE=C3D8, ELSET=BAR\n";
  for (int k = 0; k < 5; ++k)
    d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", k + 1, 4 * k + 1, 4 * k + 2, 4 * k + 3, 4 * k + 4,
                     4 * k + 5, 4 * k + 6, 4 * k + 7, 4 * k + 8);
  return d + R"(*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=TOP
21, 22, 23, 24
*ELSET, ELSET=TOPEL
5
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*STEP, NAME=Pull
*STATIC, DIRECT
0.5, 1.
*BOUNDARY
BOTTOM, 3
1, 1, 2
2, 2
*CLOAD
TOP, 3, 250.
*NODE PRINT, NSET=TOP, FREQUENCY=0
COORD
*NODE PRINT, NSET=TOP, SUMMARY=NO
U
*NODE PRINT, NSET=BOTTOM, TOTALS=YES
RF
*EL PRINT, ELSET=TOPEL, FREQUENCY=2
S33, MISES
*END STEP
)";
}

class DatObserver final : public solver::AnalysisObserver {
 public:
  explicit DatObserver(DatReport& dat) : dat_(dat) {}
  void step_started(const model::Step& step, int number) override { dat_.begin_step(step, number); }
  void print_frame(const solver::PrintFrame& frame) override { dat_.write(frame); }

 private:
  DatReport& dat_;
};

/// The rows of the table titled `title` in the last increment that printed it: label →
/// values (element tables: label*100 + point).
std::map<long, std::vector<double>> rows_of(const std::vector<std::string>& lines, const std::string& title,
                                            std::vector<std::string>* summary = nullptr) {
  std::size_t start = lines.size();
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i] == title) start = i;
  std::map<long, std::vector<double>> rows;
  if (start == lines.size()) return rows;
  const bool element = title.find("ELEMENT") != std::string::npos;
  std::size_t i = start + 5;
  for (; i < lines.size() && !lines[i].empty(); ++i) {
    auto w = words(lines[i]);
    const long key = element ? std::stol(w[0]) * 100 + std::stol(w[1]) : std::stol(w[0]);
    std::vector<double> v;
    for (std::size_t k = element ? 2 : 1; k < w.size(); ++k) v.push_back(std::stod(w[k]));
    rows[key] = v;
  }
  // The summary lines under the rows, up to whatever follows the table.
  auto is_summary = [](const std::string& l) {
    for (const char* p : {" MAXIMUM", " MINIMUM", " AT NODE", " ELEMENT", " TOTAL"})
      if (l.rfind(p, 0) == 0) return true;
    return false;
  };
  for (++i; summary && i < lines.size() && (lines[i].empty() || is_summary(lines[i])); ++i)
    if (!lines[i].empty()) summary->push_back(lines[i]);
  return rows;
}

TEST(DatReport, UniaxialBarPrintsTheHandComputedValues) {
  test::TempDir dir;
  const parser::ReadResult r = dir.read(bar_deck());
  ASSERT_TRUE(r.ok()) << r.report();
  {
    DatReport dat(dir / "bar.dat", "test", r.model.heading);
    DatObserver observer(dat);
    const auto outcome = solver::run_analysis(r.model, observer);
    ASSERT_TRUE(outcome.completed) << outcome.message;
    dat.finish(true);
  }
  std::ifstream in(dir / "bar.dat");
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  const auto lines = lines_of(text);

  const double sigma = 1000.0 / 4.0, E = 200000.0, nu = 0.3, L = 10.0;
  // Two increments of 0.5: U and RF both times, S at the second (FREQUENCY=2, also the last).
  EXPECT_NE(text.find("                                INCREMENT     1 SUMMARY"), std::string::npos);
  EXPECT_NE(text.find(" STEP TIME COMPLETED        1.00    ,  TOTAL TIME COMPLETED         1.00    "), std::string::npos);
  EXPECT_NE(text.find("S T E P       1     S T A T I C   A N A L Y S I S"), std::string::npos);
  EXPECT_EQ(text.find("COORD1"), std::string::npos);  // FREQUENCY=0 prints nothing
  std::size_t element_blocks = 0, pos = 0;
  while ((pos = text.find("E L E M E N T   O U T P U T", pos)) != std::string::npos) ++element_blocks, ++pos;
  EXPECT_EQ(element_blocks, 1u);

  // U at the top: u3 = σL/E; u1 = −νσ/E · x at x = 2 (node 22), 0 at x = 0 (node 21).
  std::vector<std::string> u_summary;
  const auto u = rows_of(lines, "   THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET TOP", &u_summary);
  ASSERT_EQ(u.size(), 4u);
  for (const auto& [node, v] : u) EXPECT_NEAR(v[2], sigma * L / E, 1e-6) << node;
  EXPECT_NEAR(u.at(22)[0], -nu * sigma / E * 2.0, 1e-8);
  EXPECT_NEAR(u.at(21)[0], 0.0, 1e-12);
  EXPECT_TRUE(u_summary.empty());  // SUMMARY=NO
  EXPECT_NE(text.find("       NODE FOOT-  U1          U2          U3      \n"), std::string::npos);
  EXPECT_NE(text.find("  1.2500E-02"), std::string::npos);

  // Reactions at the bottom: ΣRF3 = −F on the TOTAL line; each corner −F/4.
  std::vector<std::string> rf_summary;
  const auto rf =
      rows_of(lines, "   THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET BOTTOM", &rf_summary);
  ASSERT_EQ(rf.size(), 4u);
  for (const auto& [node, v] : rf) EXPECT_NEAR(v[2], -sigma, 1e-3) << node;
  ASSERT_EQ(rf_summary.size(), 5u);  // MAXIMUM, AT NODE, MINIMUM, AT NODE, TOTAL
  EXPECT_EQ(rf_summary[0].rfind(" MAXIMUM", 0), 0u);
  EXPECT_EQ(rf_summary[1].rfind(" AT NODE", 0), 0u);
  EXPECT_EQ(rf_summary[2].rfind(" MINIMUM", 0), 0u);
  const auto total = words(rf_summary[4]);
  ASSERT_EQ(total.size(), 4u);
  EXPECT_EQ(total[0], "TOTAL");
  EXPECT_NEAR(std::stod(total[3]), -1000.0, 1e-9);
  EXPECT_EQ(total[3], "-1000.");

  // Stress in the top element: S33 = F/A and MISES = |F/A| at all eight points.
  std::vector<std::string> s_summary;
  const auto s = rows_of(
      lines, "   THE FOLLOWING TABLE IS PRINTED AT THE INTEGRATION POINTS FOR ELEMENT TYPE C3D8 AND ELEMENT SET TOPEL",
      &s_summary);
  ASSERT_EQ(s.size(), 8u);
  for (const auto& [point, v] : s) {
    EXPECT_NEAR(v[0], sigma, 1e-9) << point;
    EXPECT_NEAR(v[1], sigma, 1e-9) << point;
  }
  EXPECT_NE(text.find("    ELEMENT  PT FOOT-       S33         MISES   \n"), std::string::npos);
  ASSERT_EQ(s_summary.size(), 4u);
  EXPECT_EQ(s_summary[0], " MAXIMUM                   250.0       250.0    ");
  EXPECT_EQ(s_summary[1].rfind(" ELEMENT", 0), 0u);
  EXPECT_EQ(words(s_summary[1]), (std::vector<std::string>{"ELEMENT", "5", "5"}));

  EXPECT_NE(text.find("THE ANALYSIS HAS BEEN COMPLETED"), std::string::npos);
}

TEST(DatReport, UnwritablePathThrowsIoError) {
  EXPECT_THROW(DatReport("/nonexistent-dir/x/job.dat", "test"), IoError);
}

TEST(DatReport, StepHeaderListsTheContactInteractionsAsEnforced) {
  test::TempDir dir;
  {
    DatReport dat(dir / "job.dat", "test");
    model::Step step;
    step.name = "PRESS";
    dat.begin_step(step, 1);
    dat.contact_interactions({"contact pair A/B: node to surface", "general contact C/D: surface to surface"});
    dat.contact_interactions({});  // a step without contact prints nothing
    dat.finish(true);
  }
  std::ifstream in(dir / "job.dat");
  std::stringstream buf;
  buf << in.rdbuf();
  const auto lines = lines_of(buf.str());
  const auto title = std::find(lines.begin(), lines.end(), "          CONTACT INTERACTIONS, AS ENFORCED IN THIS STEP");
  ASSERT_NE(title, lines.end()) << buf.str();
  ASSERT_GE(lines.end() - title, 4);
  EXPECT_EQ(title[2], "     contact pair A/B: node to surface");
  EXPECT_EQ(title[3], "     general contact C/D: surface to surface");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), *title), 1);
}

}  // namespace
}  // namespace inpact::io
