// Initial gaps and overclosures: ADJUST (contact/initial_adjustment.hpp) moves slave nodes onto
// the master strain-free; *CLEARANCE sets the reference gap (solver/contact_problem.cpp).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "contact/patch_test.hpp"
#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {
namespace {

bool has_message(const Run& r, const std::string& needle) {
  for (const auto& m : r.capture.messages)
    if (m.find(needle) != std::string::npos) return true;
  return false;
}

// The upper block starts 0.001 above the lower one under a pressure load: nothing holds it
// until contact closes, so the direct method (a node closes when it touches) stops at once —
// in the first attempt (no cutback holds a body its contact never touched), naming the pair
// and its nearest slave node.
TEST(InitialGap, WithoutAdjustAFloatingBlockStopsWithTheRigidBodyDiagnostic) {
  auto r = verification::run_deck(contact_deck("patch_2d_gap_direct.inp"));
  EXPECT_FALSE(r->outcome.completed);
  EXPECT_NE(r->outcome.message.find("rigid body"), std::string::npos) << r->outcome.message;
  EXPECT_NE(r->outcome.message.find("contact pair SLAVE_S/MASTER_S touches nowhere at the start"), std::string::npos)
      << r->outcome.message;
  EXPECT_NE(r->outcome.message.find("the nearest, node 101, is 0.001 away"), std::string::npos) << r->outcome.message;
  ASSERT_EQ(r->capture.rows.size(), 1u);
  EXPECT_EQ(r->capture.rows.front().total_iters, 0);
}

// ADJUST=0.002 moves the five slave nodes down by 0.001 onto the master (and ADJUST=YES the
// overclosed ones up by 0.001), strain-free: the patch test then holds exactly, with no
// interference stress.
TEST(InitialGap, AdjustMovesTheSlaveNodesOntoTheMasterStrainFree) {
  for (const char* deck : {"patch_2d_gap_adjust.inp", "patch_2d_overclosed_adjust.inp"}) {
    auto r = verification::run_deck(contact_deck(deck));
    const auto fig = check_patch(*r, deck);
    EXPECT_LE(fig.max_cpress_error, 1e-12) << deck;
    EXPECT_LE(std::max(std::abs(fig.max_penetration), std::abs(fig.min_penetration)), 1e-12) << deck;
    EXPECT_TRUE(has_message(*r, "ADJUST moved 5 slave node(s) of SLAVE_S/MASTER_S onto the master, the largest by 0.001"))
        << deck;
    // The slave nodes (labels 101..105, the upper block's bottom row) now lie on y = 1; the
    // rest of the upper block keeps its deck coordinates.
    const auto& nodes = r->deck.model.mesh.nodes;
    for (std::int64_t label = 101; label <= 105; ++label)
      EXPECT_NEAR(nodes.coords[static_cast<std::size_t>(*nodes.index.find(0, label))][1], 1.0, 1e-15) << deck << " node " << label;
    const double y_row_above = nodes.coords[static_cast<std::size_t>(*nodes.index.find(0, 106))][1];
    EXPECT_NEAR(std::abs(y_row_above - 1.5), 0.001, 1e-15) << deck;
  }
}

/// The lift-off deck's first step: the top of the upper block pushed down by d = 0.005, the
/// blocks (height 1 each, uniaxial strain) in series: with an initial gap c, the pressure is
/// M (d − c) / 2 at every slave node.
std::string push_deck(const std::string& clearance) {
  std::string s = read_text(contact_deck("lift_off_2d_direct.inp"));
  s.erase(s.find("*STEP, NAME=LIFT"));
  const std::string pair = "SLAVE_S, MASTER_S\n";
  s.insert(s.find(pair) + pair.size(), clearance);
  return s;
}

TEST(InitialClearance, ClearanceSetsTheReferenceGap) {
  const DeckDir dir;
  constexpr double d = 0.005;
  for (const double c : {0.0, 0.001, -0.001}) {
    const std::string clearance =
        c == 0.0 ? "" : "*CLEARANCE, SLAVE=SLAVE_S, MASTER=MASTER_S, VALUE=" + std::to_string(c) + "\n";
    auto r = verification::run_deck(dir.write("push.inp", push_deck(clearance)));
    ASSERT_TRUE(r->outcome.completed) << c << ": " << r->outcome.message;
    const auto& cpress = contact_field(r->capture.last(), "CPRESS");
    const auto& copen = contact_field(r->capture.last(), "COPEN");
    const double expected = kM * (d - c) / 2.0;
    for (std::size_t i = 0; i < cpress.values.size(); ++i) {
      EXPECT_NEAR(cpress.values[i], expected, 1e-9 * expected) << "clearance " << c;
      EXPECT_NEAR(copen.values[i], 0.0, 1e-12) << "clearance " << c;
    }
  }
}

// TABULAR clearances per node: a clearance at one end node only tilts nothing here (the
// blocks are held laterally) but that node carries a different pressure: check that the
// per-node value is taken (larger clearance, lower pressure) and the others keep c = 0.
TEST(InitialClearance, TabularValuesApplyPerNode) {
  const DeckDir dir;
  auto r = verification::run_deck(
      dir.write("push.inp", push_deck("*CLEARANCE, SLAVE=SLAVE_S, MASTER=MASTER_S, TABULAR\n103, 0.001\n")));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& cpress = contact_field(r->capture.last(), "CPRESS");
  const auto& nodes = r->deck.model.mesh.nodes;
  double p_middle = 0.0, p_end = 0.0;
  for (std::size_t i = 0; i < cpress.values.size(); ++i) {
    const std::int64_t label = nodes.labels[static_cast<std::size_t>(cpress.nodes[i])];
    if (label == 103) p_middle = cpress.values[i];
    if (label == 101) p_end = cpress.values[i];
  }
  EXPECT_GT(p_end, 0.0);
  EXPECT_LT(p_middle, p_end);  // the node given a clearance is pressed less
}

// NO SEPARATION and TIED: the lift-off deck pushes the top down by 0.005, then pulls it up to
// +0.01 above its start. With surfaces that never separate the two blocks (height 1 each,
// uniaxial strain) are stretched together: CPRESS = −M · 0.01 / 2 at every slave node, COPEN 0.
TEST(NoSeparation, ClosedNodesStayClosedUnderTension) {
  const DeckDir dir;
  std::string no_sep = read_text(contact_deck("lift_off_2d_direct.inp"));
  const std::string inter = "*SURFACE INTERACTION, NAME=SMOOTH\n";
  no_sep.insert(no_sep.find(inter) + inter.size(), "*SURFACE BEHAVIOR, NO SEPARATION\n");
  std::string tied = read_text(contact_deck("lift_off_2d_direct.inp"));
  const std::string pair = "TYPE=NODE TO SURFACE";
  tied.insert(tied.find(pair) + pair.size(), ", ADJUST=0., TIED");
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"NO SEPARATION", no_sep}, {"TIED", tied}}) {
    auto r = verification::run_deck(dir.write("bonded.inp", text));
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const auto& cpress = contact_field(r->capture.last(), "CPRESS");
    const auto& copen = contact_field(r->capture.last(), "COPEN");
    const double expected = -kM * 0.01 / 2.0;
    for (std::size_t i = 0; i < cpress.values.size(); ++i) {
      EXPECT_NEAR(cpress.values[i], expected, 1e-9 * std::abs(expected)) << name;
      EXPECT_NEAR(copen.values[i], 0.0, 1e-12) << name;
    }
  }
}

// CalculiX's PRESSURE-OVERCLOSURE=TIED (slope k, stick slope on *FRICTION): a spring from the
// initial gap, tension included. Blocks and spring in series: σ = d / (2/M + 1/k), pushed by
// d = −0.005, then pulled to +0.01: CPRESS = −σ(+0.01) in tension.
TEST(CalculixTied, BondsEachSlaveNodeWithASpringFromItsInitialGap) {
  const DeckDir dir;
  std::string text = read_text(contact_deck("lift_off_2d_direct.inp"));
  const std::string inter = "*SURFACE INTERACTION, NAME=SMOOTH\n";
  text.insert(text.find(inter) + inter.size(), "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1.e6\n*FRICTION\n0., 1.e5\n");
  auto r = verification::run_deck(dir.write("tied.inp", text));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double k = 1e6;
  for (const auto& [step, d] : {std::pair<int, double>{1, -0.005}, {2, 0.01}}) {
    const auto frames = r->capture.of_step(step);
    ASSERT_FALSE(frames.empty());
    const auto& cpress = contact_field(*frames.back(), "CPRESS");
    const auto& cstatus = contact_field(*frames.back(), "CSTATUS");
    const double expected = -d / (2.0 / kM + 1.0 / k);
    for (std::size_t i = 0; i < cpress.values.size(); ++i) {
      EXPECT_NEAR(cpress.values[i], expected, 1e-8 * std::abs(expected)) << "step " << step;
      EXPECT_NE(cstatus.values[i], 0.0) << "step " << step;  // closed (sticking), in tension too
    }
  }
}

TEST(NoSeparation, WithPenaltyEnforcementIsRefused) {
  const DeckDir dir;
  std::string text = read_text(contact_deck("patch_2d_penalty.inp"));
  text.replace(text.find("*SURFACE BEHAVIOR, PENALTY"), 26, "*SURFACE BEHAVIOR, PENALTY, NO SEPARATION");
  auto deck = dir.read(text);
  ASSERT_TRUE(deck.ok()) << deck.report();
  EXPECT_THROW(
      {
        try {
          solver::build_analysis_model(deck.model);
        } catch (const solver::AnalysisError& e) {
          EXPECT_NE(std::string(e.what()).find("NO SEPARATION is analysed with direct hard contact only"), std::string::npos)
              << e.what();
          throw;
        }
      },
      solver::AnalysisError);
}

}  // namespace
}  // namespace inpact::test
