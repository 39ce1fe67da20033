// Newton's rate with smoothing and with friction: a smoothed deck (a ball in a spherical seat,
// axisymmetric, penalty) and a frictional one (a block sliding on a held base, direct), run with
// Newton's tolerances tightened (*CONTROLS, PARAMETERS=FIELD 1e-12, 1e-10) so that every
// increment iterates to the round-off floor. Residuals r_k relative to the average force, from
// the second iteration of each increment (the contact status settled):
//   while r_k > `quadratic_above`: r_{k+1} ≤ C r_k² (quadratic);
//   below it, down to the floor: r_{k+1} ≤ L r_k.
// The bounds from the measured sequences (printed; bench/newton_rate/measure.py):
//   ball in its seat: 6.9e-2 → 7.5e-6 → 9.3e-9 (round-off floor ~1e-8): r_{k+1}/r_k² = 1.6e-3 above
//     1e-5, bound C = 0.05; then 1.2e-3 r_k, bound L = 1e-2.
//   sliding block: e.g. 4.2e-1 → 3.3e-3 → 1.5e-5 → 1.4e-9: r_{k+1}/r_k² ≤ 3.1 above 1e-4, bound
//     C = 10; below 1e-4 the rate turns linear at 0.5e-4 … 1.8e-4 (bound L = 1e-3): a term the
//     tangent leaves out, of that order (not identified; the slave node's area, which
//     solver/contact_problem.hpp holds fixed in the linearisation, is a candidate).
// A linear rate at the old tangents' error would fail the quadratic bounds: the ball's
// 6.9e-2 → 7.5e-6 in one step needs a contraction under 1.1e-4.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "verification/verification_fixture.hpp"

namespace inpact::test {
namespace {

/// Capture with every Newton iteration's residual ratio.
struct RateCapture : verification::Capture {
  std::vector<solver::IterationRecord> records;
  void iteration(const solver::IterationRecord& r) override { records.push_back(r); }
};

/// `deck` (under decks/) with Newton's tolerances tightened and `from` replaced by `to`,
/// written into the test's working directory.
std::string tightened(const std::string& deck, const std::string& from, const std::string& to) {
  std::ifstream in(std::string(INPACT_SOURCE_DIR) + "/decks/" + deck);
  std::stringstream text;
  std::string line;
  bool after_static = false;
  while (std::getline(in, line)) {
    if (!from.empty() && line.find(from) != std::string::npos) line.replace(line.find(from), from.size(), to);
    text << line << '\n';
    if (after_static) {
      text << "*CONTROLS, PARAMETERS=FIELD\n1e-12, 1e-10\n";
      after_static = false;
    }
    if (line.rfind("*STATIC", 0) == 0) after_static = true;
  }
  const auto path = verification::generated_dir() / ("rate_" + std::filesystem::path(deck).filename().string());
  std::ofstream(path) << text.str();
  return path.string();
}

struct Rate {
  double quadratic = 0.0;  ///< the largest r_{k+1} / r_k² with r_k above quadratic_above
  double linear = 0.0;     ///< the largest r_{k+1} / r_k below it (r_{k+1} above the floor)
  int quadratic_pairs = 0, linear_pairs = 0;
};

Rate measure(const RateCapture& c, double quadratic_above, double floor) {
  Rate out;
  for (std::size_t i = 1; i < c.records.size(); ++i) {
    const auto& a = c.records[i - 1];
    const auto& b = c.records[i];
    if (b.iteration != a.iteration + 1 || a.iteration == 0 || b.residual_ratio <= floor) continue;
    const double r0 = a.residual_ratio, r1 = b.residual_ratio;
    std::printf("  inc %d iter %d: %.3e -> %.3e (r1/r0^2 %.3e, r1/r0 %.3e)\n", a.increment, a.iteration, r0, r1,
                r1 / (r0 * r0), r1 / r0);
    if (r0 > quadratic_above) {
      out.quadratic = std::max(out.quadratic, r1 / (r0 * r0));
      ++out.quadratic_pairs;
    } else {
      out.linear = std::max(out.linear, r1 / r0);
      ++out.linear_pairs;
    }
  }
  return out;
}

Rate run_rate(const std::string& deck, const std::string& from, const std::string& to, double quadratic_above,
              double floor) {
  RateCapture capture;
  auto read = parser::read_deck(tightened(deck, from, to));
  EXPECT_TRUE(read.ok()) << read.report();
  contact::apply_adjust(read.model);
  const solver::AnalysisOutcome outcome = solver::run_analysis(read.model, capture);
  EXPECT_TRUE(outcome.completed) << outcome.message;
  return measure(capture, quadratic_above, floor);
}

TEST(NewtonRate, SmoothedBallInItsSeatConvergesQuadratically) {
  const Rate r = run_rate("contact_verification/spherical_seat_axi_smoothed.inp", "method = \"DIRECT\"",
                          "method = \"PENALTY\"", 1e-5, 1e-12);
  std::printf("[newton rate] spherical_seat_axi_smoothed penalty: worst r_k+1/r_k^2 %.3e (%d pairs), r_k+1/r_k %.3e\n",
              r.quadratic, r.quadratic_pairs, r.linear);
  EXPECT_GE(r.quadratic_pairs, 1);
  EXPECT_LT(r.quadratic, 0.05);
  EXPECT_LT(r.linear, 1e-2);
}

TEST(NewtonRate, SlidingBlockWithFrictionConvergesQuadratically) {
  const Rate r = run_rate("contact/friction_slide_2d_direct.inp", "", "", 1e-4, 1e-12);
  std::printf("[newton rate] friction_slide_2d_direct: worst r_k+1/r_k^2 %.3e (%d pairs), r_k+1/r_k %.3e (%d)\n",
              r.quadratic, r.quadratic_pairs, r.linear, r.linear_pairs);
  EXPECT_GE(r.quadratic_pairs, 12);
  EXPECT_LT(r.quadratic, 10.0);
  EXPECT_LT(r.linear, 1e-3);
}

}  // namespace
}  // namespace inpact::test
