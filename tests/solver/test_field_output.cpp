// Output request semantics (solver/field_output.hpp): carry-over between steps and OP=,
// FREQUENCY and the last increment, NUMBER INTERVAL with and without TIME MARKS, NSET/ELSET
// restriction, the PRESELECT set, and that only what is requested is computed.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/dof_map.hpp"
#include "solver/field_output.hpp"

namespace inpact::solver {
namespace {

using Keys = std::set<std::string>;

/// A 2 × 2 × 10 bar of five C3D8 elements along z, fixed axially at z = 0 and pulled by
/// 4 × 250 at z = 10 (uniform σ33 = 1000 / 4 = 250); `steps` is appended after the model.
std::string bar_deck(const std::string& steps) {
  std::string d = "*NODE, NSET=ALLN\n";
  const double xy[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  for (int k = 0; k <= 5; ++k)
    for (int i = 0; i < 4; ++i)
      d += std::to_string(4 * k + i + 1) + ", " + std::to_string(xy[i][0]) + ", " + std::to_string(xy[i][1]) + ", " +
           std::to_string(2.0 * k) + "\n";
  d += "*ELEMENT, TYPE=C3D8, ELSET=BAR\n";
  for (int k = 0; k < 5; ++k) {
    d += std::to_string(k + 1);
    for (int i = 1; i <= 4; ++i) d += ", " + std::to_string(4 * k + i);
    for (int i = 1; i <= 4; ++i) d += ", " + std::to_string(4 * (k + 1) + i);
    d += "\n";
  }
  d += R"(*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=TOP
21, 22, 23, 24
*ELSET, ELSET=TOPEL
5
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
)";
  return d + steps;
}

/// One static step with the bar's supports and load, and `output` before *END STEP.
std::string pull_step(const std::string& output, const std::string& static_line = "1., 1.") {
  return "*STEP\n*STATIC\n" + static_line + "\n*BOUNDARY\nBOTTOM, 3\n1, 1, 2\n2, 2\n*CLOAD\nTOP, 3, 250.\n" + output +
         "*END STEP\n";
}

class Recorder final : public AnalysisObserver {
 public:
  void frame(const Frame& f) override { frames.push_back(f); }
  void print_frame(const PrintFrame& f) override { prints.push_back(f); }
  void message(std::string_view text) override { messages.emplace_back(text); }
  std::vector<Frame> frames;
  std::vector<PrintFrame> prints;
  std::vector<std::string> messages;
};

Keys keys_of(const Frame& f) {
  Keys k;
  for (const auto& field : f.fields) k.insert(field.key);
  return k;
}

const FieldData* field(const Frame& f, const std::string& key) {
  for (const auto& x : f.fields)
    if (x.key == key) return &x;
  return nullptr;
}

class FieldOutput : public ::testing::Test {
 protected:
  model::Model read(const std::string& steps) {
    auto r = dir_.read(bar_deck(steps));
    EXPECT_TRUE(r.ok()) << r.report();
    return std::move(r.model);
  }
  /// The field keys step `index` writes.
  Keys keys(const model::Model& m, std::size_t index) {
    const AnalysisModel am = build_analysis_model(m);
    return StepOutput(am, index).field_keys();
  }
  Recorder run(const model::Model& m) {
    Recorder rec;
    const AnalysisOutcome outcome = run_analysis(m, rec);
    EXPECT_TRUE(outcome.completed) << outcome.message;
    return rec;
  }
  test::DeckDir dir_;
};

// --- Carry-over and OP= ---------------------------------------------------------------

TEST_F(FieldOutput, RequestsCarryOverToTheNextStepAndOpAddAddsToThem) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*NODE OUTPUT\nU\n") +
                      pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\nS\n") + pull_step(""));
  EXPECT_EQ(keys(m, 0), (Keys{"U"}));
  EXPECT_EQ(keys(m, 1), (Keys{"U", "S"}));
  EXPECT_EQ(keys(m, 2), (Keys{"U", "S"}));  // a step without requests keeps them all
}

TEST_F(FieldOutput, OpNewRemovesEveryRequestOfEarlierSteps) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*NODE OUTPUT\nU, RF\n") +
                      pull_step("*OUTPUT, FIELD, OP=NEW\n*ELEMENT OUTPUT\nE\n"));
  EXPECT_EQ(keys(m, 1), (Keys{"E"}));
}

TEST_F(FieldOutput, OpReplaceReplacesTheRequestsOfTheSameKindOnly) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*NODE OUTPUT\nU\n*ELEMENT OUTPUT\nS\n") +
                      pull_step("*OUTPUT, FIELD, OP=REPLACE\n*NODE OUTPUT\nRF\n"));
  EXPECT_EQ(keys(m, 1), (Keys{"RF", "S"}));
}

TEST_F(FieldOutput, FirstStepWithoutFieldRequestsWritesThePreselectedVariables) {
  const auto m = read(pull_step("*NODE PRINT\nU\n"));
  EXPECT_EQ(keys(m, 0), (Keys{"U", "RF", "S", "E"}));
  const auto in_force = requests_in_force(m, 0);
  ASSERT_EQ(in_force.size(), 2u);
  EXPECT_EQ(in_force[0].kind, model::OutputRequest::Kind::ModelField);
  EXPECT_TRUE(in_force[0].preselect);
}

TEST_F(FieldOutput, PreselectIsWhatInpactComputesOfAbaqusStaticPreselection) {
  const auto m = read(pull_step("*OUTPUT, FIELD, VARIABLE=PRESELECT\n") +
                      pull_step("*OUTPUT, FIELD, OP=NEW\n*NODE OUTPUT, VARIABLE=PRESELECT\n") +
                      pull_step("*OUTPUT, FIELD, OP=NEW\n*NODE OUTPUT, VARIABLE=ALL\n"));
  EXPECT_EQ(keys(m, 0), (Keys{"U", "RF", "S", "E"}));
  EXPECT_EQ(keys(m, 1), (Keys{"U", "RF"}));
  EXPECT_EQ(keys(m, 2), (Keys{"U", "RF", "COORD"}));
}

TEST_F(FieldOutput, PrintRequestOfAKindReplacesThoseOfEarlierSteps) {
  const auto m = read(pull_step("*NODE PRINT, NSET=TOP\nU\n*EL PRINT\nS\n") + pull_step("*NODE PRINT\nRF\n") +
                      pull_step(""));
  const AnalysisModel am = build_analysis_model(m);
  auto columns = [&](std::size_t step) {
    std::vector<std::vector<std::string>> c;
    const StepOutput output(am, step);
    for (const auto& a : output.print_requests()) c.push_back(a.variables);
    return c;
  };
  using C = std::vector<std::vector<std::string>>;
  EXPECT_EQ(columns(0), (C{{"U1", "U2", "U3"}, {"S11", "S22", "S33", "S12", "S13", "S23"}}));
  EXPECT_EQ(columns(1), (C{{"S11", "S22", "S33", "S12", "S13", "S23"}, {"RF1", "RF2", "RF3"}}));
  EXPECT_EQ(columns(2), columns(1));
}

TEST_F(FieldOutput, CalculixFileRequestsAreFieldOutputAndReplaceTheirKind) {
  const auto m = read(pull_step("*NODE FILE\nU\n*EL FILE\nS\n") + pull_step("*NODE FILE\nRF\n"));
  EXPECT_EQ(keys(m, 0), (Keys{"U", "S"}));  // a file request suppresses the preselected default
  EXPECT_EQ(keys(m, 1), (Keys{"RF", "S"}));
}

// --- Timing ---------------------------------------------------------------------------

TEST(OutputTiming, FrequencyWritesEveryNthIncrementAndTheLast) {
  model::OutputRequest r;
  r.kind = model::OutputRequest::Kind::NodeField;
  r.frequency = 3;
  OutputTiming timing(r, 1.0);
  std::vector<int> due;
  for (int inc = 1; inc <= 7; ++inc)
    if (timing.due(inc, inc / 7.0, inc == 7)) due.push_back(inc);
  EXPECT_EQ(due, (std::vector<int>{3, 6, 7}));
}

TEST(OutputTiming, FrequencyZeroWritesNothingNotEvenTheLastIncrement) {
  model::OutputRequest r;
  r.kind = model::OutputRequest::Kind::NodePrint;
  r.frequency = 0;
  OutputTiming timing(r, 1.0);
  EXPECT_FALSE(timing.due(1, 0.5, false));
  EXPECT_FALSE(timing.due(2, 1.0, true));
}

TEST(OutputTiming, NumberIntervalWithoutTimeMarksWritesAtTheFirstIncrementAfterEachMark) {
  model::OutputRequest r;
  r.kind = model::OutputRequest::Kind::NodeField;
  r.number_interval = 4;  // marks 0.5, 1.0, 1.5, 2.0 in a step of 2
  OutputTiming timing(r, 2.0);
  const std::vector<double> t = {0.6, 0.9, 1.0, 1.2, 1.8, 2.0};
  std::vector<double> written;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (timing.due(static_cast<int>(i + 1), t[i], i + 1 == t.size())) written.push_back(t[i]);
  EXPECT_EQ(written, (std::vector<double>{0.6, 1.0, 1.8, 2.0}));
  EXPECT_FALSE(timing.next_mark(0.0));  // no time marks: increments are not cut
}

TEST(OutputTiming, TimeMarksGiveTheNextMarkToEndTheIncrementOn) {
  model::OutputRequest r;
  r.kind = model::OutputRequest::Kind::NodeField;
  r.number_interval = 4;
  r.time_marks = true;
  OutputTiming timing(r, 1.0);
  EXPECT_DOUBLE_EQ(*timing.next_mark(0.0), 0.25);
  EXPECT_DOUBLE_EQ(*timing.next_mark(0.25), 0.5);
  EXPECT_TRUE(timing.due(1, 0.25, false));
  EXPECT_FALSE(timing.due(2, 0.4, false));
  EXPECT_DOUBLE_EQ(*timing.next_mark(0.4), 0.5);
}

TEST(OutputTiming, WouldBeDueAnswersAsDueWithoutPassingTheMarks) {
  model::OutputRequest r;
  r.kind = model::OutputRequest::Kind::NodeField;
  r.number_interval = 2;  // marks 0.5, 1.0
  OutputTiming timing(r, 1.0);
  EXPECT_FALSE(timing.would_be_due(1, 0.3, false));
  EXPECT_TRUE(timing.would_be_due(2, 0.6, false));
  EXPECT_TRUE(timing.would_be_due(2, 0.6, false));  // asking again: the mark is still ahead
  EXPECT_TRUE(timing.due(2, 0.6, false));
  EXPECT_FALSE(timing.would_be_due(3, 0.8, false));  // now it is passed
  EXPECT_TRUE(timing.would_be_due(4, 1.0, true));
}

TEST_F(FieldOutput, PointsAreDueWhenAnIncrementWouldWriteElementValues) {
  const auto m = read(pull_step("*OUTPUT, FIELD, FREQUENCY=2\n*ELEMENT OUTPUT\nS\n*OUTPUT, FIELD\n*NODE OUTPUT\nU\n") +
                      pull_step("*OUTPUT, FIELD, OP=NEW\n*NODE OUTPUT\nU\n") +
                      pull_step("*EL PRINT, FREQUENCY=3\nMISES\n"));
  const AnalysisModel am = build_analysis_model(m);
  const StepOutput s0(am, 0), s1(am, 1), s2(am, 2);
  EXPECT_FALSE(s0.points_due(1, 0.25, false));  // U only at odd increments
  EXPECT_TRUE(s0.points_due(2, 0.5, false));
  EXPECT_TRUE(s0.points_due(3, 1.0, true));  // the last increment writes
  EXPECT_FALSE(s1.points_due(2, 1.0, true));   // U alone needs no element values
  EXPECT_TRUE(s2.points_due(3, 0.5, false));   // *EL PRINT
  EXPECT_FALSE(s2.points_due(1, 0.5, false));
}

TEST_F(FieldOutput, OutputFromThePointsTheAssemblyKeptEqualsComputingThem) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\nS, E\n*EL PRINT\nS11, MISES\n"));
  const AnalysisModel am = build_analysis_model(m);
  const DofMap dofs = DofMap::build(am, std::vector<std::uint8_t>(am.n_dof(), 0));
  Assembler assembler(am, dofs);
  std::vector<double> u(am.n_dof()), f(am.n_dof()), dt(am.model->mesh.nodes.size());
  for (std::size_t d = 0; d < u.size(); ++d) u[d] = 1e-4 * std::sin(0.7 * static_cast<double>(d));
  for (std::size_t n = 0; n < dt.size(); ++n) dt[n] = 3.0 * static_cast<double>(n);
  AssemblyRequest request;
  request.points = true;
  request.delta_t = dt;
  assembler.assemble(u, request, f);
  const ElementPoints* kept = assembler.points_at(u, dt, false);
  ASSERT_NE(kept, nullptr);
  EXPECT_EQ(kept->points.size(), 5u * 8u);
  EXPECT_EQ(assembler.points_at(u, dt, true), nullptr);  // another state: not these points
  EXPECT_EQ(assembler.points_at(u, {}, false), nullptr);
  std::vector<double> u2 = u;
  u2[7] += 1e-9;
  EXPECT_EQ(assembler.points_at(u2, dt, false), nullptr);

  StepOutput output(am, 0);
  const OutputDue due = output.due(1, 1.0, true);
  const std::vector<double> rf(am.n_dof(), 0.0);
  const OutputValues fresh = compute_output(am, output, due, u, rf, false, dt, nullptr, nullptr);
  const OutputValues reused = compute_output(am, output, due, u, rf, false, dt, nullptr, kept);
  ASSERT_EQ(fresh.fields.size(), 2u);
  ASSERT_EQ(reused.fields.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(reused.fields[i].key, fresh.fields[i].key);
    EXPECT_EQ(reused.fields[i].elements, fresh.fields[i].elements);
    EXPECT_EQ(reused.fields[i].values, fresh.fields[i].values);  // the same kernel at the same state
  }
  ASSERT_EQ(fresh.tables.size(), 1u);
  ASSERT_EQ(reused.tables.size(), 1u);
  EXPECT_EQ(reused.tables[0].values, fresh.tables[0].values);
}

TEST_F(FieldOutput, FrequencyAndTheLastIncrementDecideWhichIncrementsWriteAFrame) {
  // DIRECT: five fixed increments of 0.2; FREQUENCY=2 writes increments 2, 4 and the last, 5.
  const auto m = read(
      "*STEP\n*STATIC, DIRECT\n0.2, 1.\n*BOUNDARY\nBOTTOM, 3\n1, 1, 2\n2, 2\n*CLOAD\nTOP, 3, 250.\n"
      "*OUTPUT, FIELD, FREQUENCY=2\n*NODE OUTPUT\nU\n*NODE PRINT, FREQUENCY=3\nU3\n*END STEP\n");
  const Recorder rec = run(m);
  std::vector<int> frames, prints;
  for (const auto& f : rec.frames) frames.push_back(f.increment);
  for (const auto& p : rec.prints) prints.push_back(p.increment);
  EXPECT_EQ(frames, (std::vector<int>{2, 4, 5}));
  EXPECT_EQ(prints, (std::vector<int>{3, 5}));
}

TEST_F(FieldOutput, TimeMarksCutIncrementsToLandOnTheOutputTimes) {
  // Increments of 0.3 would pass 0.25, 0.5, 0.75 without landing on them.
  const auto m = read(pull_step("*OUTPUT, FIELD, NUMBER INTERVAL=4, TIME MARKS=YES\n*NODE OUTPUT\nU\n",
                                "0.3, 1., , 0.3"));
  const Recorder rec = run(m);
  std::vector<double> times;
  for (const auto& f : rec.frames) times.push_back(f.step_time);
  ASSERT_EQ(times.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(times[k], 0.25 * (k + 1), 1e-12);
}

TEST_F(FieldOutput, NumberIntervalWithoutTimeMarksWritesAfterTheMarks) {
  const auto m = read(pull_step("*OUTPUT, FIELD, NUMBER INTERVAL=2\n*NODE OUTPUT\nU\n", "0.3, 1., , 0.3"));
  const Recorder rec = run(m);
  std::vector<double> times;
  for (const auto& f : rec.frames) times.push_back(f.step_time);
  // Increments end at 0.3, 0.6, 0.9, 1.0: the first at or after 0.5 is 0.6, then the last.
  ASSERT_EQ(times.size(), 2u);
  EXPECT_NEAR(times[0], 0.6, 1e-12);
  EXPECT_NEAR(times[1], 1.0, 1e-12);
}

// --- What a frame holds ---------------------------------------------------------------

TEST_F(FieldOutput, OnlyTheRequestedFieldsAreComputed) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*NODE OUTPUT\nU\n"));
  const Recorder rec = run(m);
  ASSERT_FALSE(rec.frames.empty());
  for (const auto& f : rec.frames) EXPECT_EQ(keys_of(f), (Keys{"U"}));  // no S, E, RF
}

TEST_F(FieldOutput, NsetAndElsetRestrictTheLocationsWritten) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*NODE OUTPUT, NSET=TOP\nU\n*ELEMENT OUTPUT, ELSET=TOPEL\nS\n"));
  const Recorder rec = run(m);
  ASSERT_FALSE(rec.frames.empty());
  const Frame& last = rec.frames.back();
  const FieldData* u = field(last, "U");
  ASSERT_NE(u, nullptr);
  EXPECT_EQ(u->nodes, (std::vector<std::int64_t>{20, 21, 22, 23}));  // rows of nodes 21..24
  EXPECT_EQ(u->region, "TOP");
  ASSERT_EQ(u->values.size(), 12u);
  for (int n = 0; n < 4; ++n) EXPECT_NEAR(u->values[3 * n + 2], 250.0 * 10.0 / 200000.0, 1e-12);  // σL/E
  const FieldData* s = field(last, "S");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->elements, std::vector<std::int64_t>(8, 5));  // element 5's eight points only
  EXPECT_EQ(s->region, "TOPEL");
  for (std::size_t p = 0; p < 8; ++p) EXPECT_NEAR(s->values[6 * p + 2], 250.0, 1e-9);
}

TEST_F(FieldOutput, AFieldAskedForOnSeveralSetsIsWrittenOnTheirUnionEveryFrame) {
  const auto m = read(
      "*STEP\n*STATIC, DIRECT\n0.5, 1.\n*BOUNDARY\nBOTTOM, 3\n1, 1, 2\n2, 2\n*CLOAD\nTOP, 3, 250.\n"
      "*OUTPUT, FIELD\n*NODE OUTPUT, NSET=TOP\nU\n*OUTPUT, FIELD, FREQUENCY=2\n*NODE OUTPUT, NSET=BOTTOM\nU\n"
      "*END STEP\n");
  const Recorder rec = run(m);
  ASSERT_EQ(rec.frames.size(), 2u);
  for (const auto& f : rec.frames)
    EXPECT_EQ(field(f, "U")->nodes, (std::vector<std::int64_t>{0, 1, 2, 3, 20, 21, 22, 23}));
}

TEST_F(FieldOutput, RequestedButNotComputedVariablesAreReportedOncePerStep) {
  const auto m = read(pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\nS, TRESCA\n*EL PRINT\nTRESCA, MISES\n") +
                      pull_step(""));
  const Recorder rec = run(m);
  const auto count = std::count_if(rec.messages.begin(), rec.messages.end(),
                                   [](const std::string& s) { return s.find("TRESCA") != std::string::npos; });
  EXPECT_EQ(count, 2);  // once in each step (carried over), not per request or increment
}

TEST_F(FieldOutput, PrintTablesHoldTheRequestedColumnsForTheSet) {
  const auto m = read(pull_step("*NODE PRINT, NSET=BOTTOM, TOTALS=YES\nRF3\n*EL PRINT, ELSET=TOPEL\nS33, MISES\n"));
  const Recorder rec = run(m);
  ASSERT_EQ(rec.prints.size(), 1u);  // the single increment
  const auto& tables = rec.prints[0].tables;
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_EQ(tables[0].columns, (std::vector<std::string>{"RF3"}));
  EXPECT_EQ(tables[0].labels, (std::vector<std::int64_t>{1, 2, 3, 4}));
  double sum = 0.0;
  for (double v : tables[0].values) sum += v;
  EXPECT_NEAR(sum, -1000.0, 1e-8);
  EXPECT_TRUE(tables[0].totals);
  EXPECT_EQ(tables[1].element_type, "C3D8");
  EXPECT_EQ(tables[1].columns, (std::vector<std::string>{"S33", "MISES"}));
  ASSERT_EQ(tables[1].values.size(), 16u);
  for (std::size_t p = 0; p < 8; ++p) {
    EXPECT_NEAR(tables[1].values[2 * p], 250.0, 1e-9);
    EXPECT_NEAR(tables[1].values[2 * p + 1], 250.0, 1e-9);
  }
}

TEST(VonMises, IsTheUniaxialStressAndRootThreeTimesThePureShear) {
  EXPECT_DOUBLE_EQ(von_mises(std::array<double, 6>{0, 0, -250, 0, 0, 0}), 250.0);
  EXPECT_NEAR(von_mises(std::array<double, 6>{0, 0, 0, 10, 0, 0}), 10.0 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(von_mises(std::array<double, 6>{5, 5, 5, 0, 0, 0}), 0.0, 1e-12);  // hydrostatic
}

}  // namespace
}  // namespace inpact::solver

// --- Plasticity output (PE, PEEQ, PEMAG) -----------------------------------------------

namespace inpact::solver {
namespace {

// The bar with *PLASTIC: σ_y = 200 + 1000 ε̄ᵖ; the uniform σ33 = 250 gives ε̄ᵖ = 0.05, PE33 = 0.05,
// PE11 = PE22 = −0.025 (isochoric flow) and PEMAG = √(2/3 εᵖ:εᵖ) = 0.05 (uniaxial: PEMAG = PEEQ).
const char* kPlastic = "*PLASTIC\n200., 0.\n300., 0.1\n";

TEST_F(FieldOutput, PreselectBringsPlasticStrainsOnlyWhenASectionIsPlastic) {
  EXPECT_EQ(keys(read(kPlastic + pull_step("")), 0), (Keys{"U", "RF", "S", "E", "PE", "PEEQ", "PEMAG"}));
  EXPECT_EQ(keys(read(pull_step("")), 0), (Keys{"U", "RF", "S", "E"}));  // elastic: as before
  EXPECT_EQ(keys(read(kPlastic + pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\nPE22, PEEQ\n")), 0), (Keys{"PE", "PEEQ"}));
}

TEST_F(FieldOutput, PlasticStrainsInTheResultsAndInElPrint) {
  // σ_y = 200 + 1250 ε̄ᵖ: σ33 = 250 gives ε̄ᵖ = 0.04 in one increment, clear of the cut-back at
  // fifty times the yield strain (50 · 200 / 200000 = 0.05), which round-off would decide for
  // the table above (exactly 0.05).
  const std::string plastic = "*PLASTIC\n200., 0.\n325., 0.1\n";
  const auto m = read(plastic + pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT, ELSET=TOPEL\nPE, PEEQ, PEMAG\n"
                                          "*EL PRINT, ELSET=TOPEL\nPEEQ, PE33, PE11, PEMAG\n"));
  const Recorder rec = run(m);
  ASSERT_EQ(rec.frames.size(), 1u);
  const Frame& f = rec.frames.back();
  for (const auto& fd : f.fields) {
    ASSERT_EQ(fd.elements.size(), 8u) << fd.key;  // TOPEL's 8 points
    if (fd.key == "PE") {
      EXPECT_EQ(fd.component_labels, (std::vector<std::string>{"PE11", "PE22", "PE33", "PE12", "PE13", "PE23"}));
      EXPECT_NEAR(fd.values[2], 0.04, 1e-9);
      EXPECT_NEAR(fd.values[0], -0.02, 1e-9);
    } else {
      EXPECT_EQ(fd.component_labels, (std::vector<std::string>{fd.key}));
      ASSERT_EQ(fd.values.size(), 8u);
      for (double v : fd.values) EXPECT_NEAR(v, 0.04, 1e-9) << fd.key;
    }
  }
  ASSERT_EQ(rec.prints.size(), 1u);
  const auto& t = rec.prints.back().tables.at(0);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"PEEQ", "PE33", "PE11", "PEMAG"}));
  ASSERT_EQ(t.values.size(), 32u);
  for (std::size_t p = 0; p < 8; ++p) {
    EXPECT_NEAR(t.values[4 * p], 0.04, 1e-9);
    EXPECT_NEAR(t.values[4 * p + 1], 0.04, 1e-9);
    EXPECT_NEAR(t.values[4 * p + 2], -0.02, 1e-9);
    EXPECT_NEAR(t.values[4 * p + 3], 0.04, 1e-9);
  }
}

// LE (Abaqus's logarithmic strain under NLGEOM) is the strain E holds, under its own name, in the
// results file and in *EL PRINT.
TEST_F(FieldOutput, LogarithmicStrainLeIsTheStrainUnderItsOwnName) {
  auto steps = pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\nE, LE\n*EL PRINT\nLE11, LE33\n");
  steps.replace(steps.find("*STEP\n"), 6, "*STEP, NLGEOM\n");
  const Recorder rec = run(read(steps));
  ASSERT_EQ(rec.frames.size(), 1u);
  const FieldData* e = field(rec.frames[0], "E");
  const FieldData* le = field(rec.frames[0], "LE");
  ASSERT_TRUE(e && le);
  EXPECT_EQ(le->values, e->values);
  EXPECT_EQ(le->component_labels.front(), "LE11");
  ASSERT_EQ(rec.prints.size(), 1u);
  EXPECT_EQ(rec.prints[0].tables.at(0).columns, (std::vector<std::string>{"LE11", "LE33"}));
}

// Kinematic hardening under NLGEOM runs through the logarithmic strain (log_strain_plasticity.hpp)
// and reports its plastic strain like the small-strain law.
TEST_F(FieldOutput, KinematicHardeningWithNlgeomReportsPlasticStrain) {
  auto steps = std::string("*PLASTIC, HARDENING=KINEMATIC\n200., 0.\n300., 0.1\n") +
               pull_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\nPEEQ\n");
  steps.replace(steps.find("*STEP\n"), 6, "*STEP, NLGEOM\n");
  const Recorder rec = run(read(steps));
  ASSERT_FALSE(rec.frames.empty());
  const FieldData* peeq = field(rec.frames.back(), "PEEQ");
  ASSERT_TRUE(peeq);
  EXPECT_GE(*std::min_element(peeq->values.begin(), peeq->values.end()), 0.0);
}

}  // namespace
}  // namespace inpact::solver
