// The state contract of the increment loop, with a toy stateful material in a real analysis:
// a trial state is committed only when its increment converges, and a cut-back attempt leaves
// the committed state as the last converged increment left it.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_model.hpp"
#include "solver/elements/material.hpp"
#include "solver/material_states.hpp"

using namespace inpact;
using namespace inpact::solver;
using namespace inpact::solver::elements;

namespace {

/// Elastic, with two history values per point: the converged increments it has been through
/// (trial = committed + 1) and the strain ε33 of the last of them. It cannot take a strain step
/// larger than 0.004 in one increment: beyond it the stress is NaN, so the attempt fails and the
/// increment is cut back (like a return mapping that does not converge).
class StepLimitedMaterial final : public Material {
 public:
  explicit StepLimitedMaterial(const ElasticConstants& c) : elastic_(model::ElementFamily::Solid3D, c) {}
  std::size_t state_size() const override { return 2; }
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override {
    point.trial[0] = point.committed[0] + 1;
    point.trial[1] = in.strain(2);
    const Mat6& D = elastic_.update(in, {}, stress, scratch);
    if (std::abs(in.strain(2) - point.committed[1]) > 0.004) stress.setConstant(std::nan(""));
    return D;
  }
  const ElasticConstants& elastic() const override { return elastic_.elastic(); }

 private:
  IsotropicElastic elastic_;
};

/// What the history of the element's first point was when each attempt finished (before the
/// loop commits or discards it).
struct HistoryWatch : AnalysisObserver {
  struct Seen {
    StatusRow row;
    double committed_count, committed_strain, trial_count;
  };
  explicit HistoryWatch(const MaterialStates& s) : states(s) {}
  void attempt_finished(const StatusRow& row) override {
    seen.push_back({row, states.committed(0)[0], states.committed(0)[1], states.trial(0)[0]});
  }
  const MaterialStates& states;
  std::vector<Seen> seen;
};

// A unit cube, bottom face held in z (and just enough in x, y), top face pulled to ε33 = 0.01
// in one step with an initial increment of the whole period.
const char* kSteps = R"(*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*STEP
*STATIC
1.0, 1.0
*BOUNDARY
BOTTOM, 3, 3, 0.0
1, 1, 2, 0.0
2, 2, 2, 0.0
TOP, 3, 3, 0.01
*END STEP
)";

}  // namespace

TEST(MaterialHistory, TrialStateIsCommittedOnlyWhenTheIncrementConverges) {
  test::DeckDir dir;
  const auto r = dir.read(test::one_cube_deck(kSteps));
  ASSERT_TRUE(r.ok()) << r.report();
  AnalysisModel am = build_analysis_model(r.model);
  auto law = std::make_shared<StepLimitedMaterial>(am.elements[0].material->elastic());
  am.materials.push_back(law);
  am.elements[0].material = law.get();
  MaterialStates states(am);
  // One element: 2 offsets, 1 size, 8 points × 2 values, committed and trial.
  EXPECT_EQ(states.bytes(), 2 * sizeof(std::size_t) + sizeof(std::uint32_t) + 2 * 8 * 2 * sizeof(double));
  HistoryWatch watch(states);
  const AnalysisOutcome outcome = run_steps(am, states, watch);
  ASSERT_TRUE(outcome.completed) << outcome.message;

  // Increment 1: Δε33 = 0.01 fails, cut back to 0.25 (Δε33 = 0.0025) converges; then 0.25 three
  // more times (no growth right after a cutback; the fourth is the period's rest).
  ASSERT_EQ(watch.seen.size(), 5u);
  const auto& cut = watch.seen[0];
  EXPECT_TRUE(cut.row.cut_back);
  EXPECT_EQ(cut.trial_count, 1.0);      // the failed attempt wrote its trial state...
  EXPECT_EQ(cut.committed_count, 0.0);  // ...which is not committed
  EXPECT_EQ(cut.committed_strain, 0.0);
  const auto& retry = watch.seen[1];
  EXPECT_EQ(retry.row.increment, 1);
  EXPECT_EQ(retry.row.attempt, 2);
  EXPECT_FALSE(retry.row.cut_back);
  EXPECT_EQ(retry.committed_count, 0.0);  // the cut-back attempt left the committed state untouched
  EXPECT_EQ(retry.committed_strain, 0.0);
  for (std::size_t i = 1; i < watch.seen.size(); ++i) {
    const auto& s = watch.seen[i];
    // Each increment starts from one commit per converged increment before it.
    EXPECT_EQ(s.committed_count, static_cast<double>(s.row.increment - 1)) << "increment " << s.row.increment;
    EXPECT_NEAR(s.committed_strain, 0.0025 * (s.row.increment - 1), 1e-15) << "increment " << s.row.increment;
    EXPECT_EQ(s.trial_count, static_cast<double>(s.row.increment));
  }
  // After the step: four commits at every point, at the final strain.
  const auto committed = states.committed(0);
  for (std::size_t p = 0; p < 8; ++p) {
    EXPECT_EQ(committed[2 * p], 4.0) << "point " << p;
    EXPECT_NEAR(committed[2 * p + 1], 0.01, 1e-15) << "point " << p;
  }
}
