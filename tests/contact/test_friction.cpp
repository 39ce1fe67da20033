// Coulomb friction (contact/friction.hpp, solver/contact_problem.hpp): the return mapping of one
// slave node against a hand computation and a finite-difference tangent, and the block-sliding
// decks of decks/contact/ (friction_*.inp) end to end. Tolerances are stated at each assertion.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/friction.hpp"
#include "contact/projection.hpp"
#include "contact_test_util.hpp"
#include "solver/analysis_model.hpp"
#include "solver/contact_problem.hpp"
#include "verification/verification_fixture.hpp"

namespace inpact::test {
namespace {

using verification::Run;

constexpr double kMu = 0.3, kP = 10.0, kN = 10.0;  // p on a unit top: N = 10
constexpr double kGammaCrit = 0.005 * 0.5;          // SLIP TOLERANCE 0.005 × facet 0.5

std::string contact_deck(const std::string& name) { return std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + name; }

const solver::FieldData& fd(const solver::Frame& f, const std::string& key) {
  const auto* p = verification::field(f, key);
  if (!p) throw std::runtime_error("frame has no field " + key);
  return *p;
}

/// Σ RF over the node set TOP (the pushed top of the block).
std::array<double, 3> top_reaction(const Run& r, const solver::Frame& f) {
  std::array<double, 3> s{0, 0, 0};
  for (std::int32_t n : verification::nset(r.model(), "TOP"))
    for (int c = 0; c < r.dim(); ++c) s[c] += verification::nodal(f, "RF", static_cast<std::size_t>(n), c);
  return s;
}

struct Counts {
  int increments = 0, iterations = 0, severe = 0, max_per_increment = 0;
};
Counts counts(const Run& r, int step) {
  Counts c;
  for (const auto& row : r.capture.rows)
    if (row.step == step && !row.cut_back) {
      ++c.increments;
      c.iterations += row.total_iters;
      c.severe += row.severe_discon_iters;
      c.max_per_increment = std::max(c.max_per_increment, row.total_iters);
    }
  return c;
}

// --- The kernel ------------------------------------------------------------------------

/// A slave node over a Line2 master facet from (0,0) to (1,0), in 2D.
struct OneNode {
  contact::Facet facet = make_facet(contact::FacetShape::Line2, 1);
  std::vector<contact::Vec3> x{{0.4, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  contact::FrictionLaw law{kMu, false, kGammaCrit, 0.0, false};

  contact::FrictionPoint eval(double ux, const contact::FrictionAnchor& anchor, double p) {
    auto y = x;
    y[0][0] += ux;
    const auto pr = contact::project_to_facet(facet, y, y[0]);
    const auto lin = contact::linearize_gap(facet, y, y[0], pr, 2, 0);
    return contact::friction_point(law, facet, pr, lin, facet, anchor, {0, 0, 0}, p, y);
  }
};

TEST(FrictionKernel, StickBelowTheLimitSlipOnIt) {
  OneNode t;
  const contact::FrictionAnchor anchor{0, {-0.2, 0.0}};  // ξ = −0.2: x = 0.4, under the node
  // Stick: Δs = 0.001 < γ_crit: τ = (μ p / γ_crit) Δs exactly.
  auto st = t.eval(0.001, anchor, kP);
  EXPECT_FALSE(st.slipping);
  EXPECT_NEAR(st.traction[0], kMu * kP / kGammaCrit * 0.001, 1e-12);
  // Slip: Δs = 0.01 > γ_crit: |τ| = μ p, elastic slip γ_crit.
  auto sl = t.eval(0.01, anchor, kP);
  EXPECT_TRUE(sl.slipping);
  EXPECT_NEAR(sl.traction[0], kMu * kP, 1e-12);
  EXPECT_NEAR(sl.elastic_slip[0], kGammaCrit, 1e-15);
  EXPECT_NEAR(sl.slip_increment[0], 0.01, 1e-15);
  // Action = reaction: the force on the slave and the master nodes sums to zero.
  EXPECT_NEAR(sl.force[0] + sl.force[2] + sl.force[4], 0.0, 1e-12);
}

TEST(FrictionKernel, TangentMatchesFiniteDifferencesOfTheSlaveForce) {
  // d(force)/d(u_s,x) against central differences, in stick and in slip, at fixed pressure,
  // and the pressure coupling against d(force)/dp. Relative error 1e-6 (flat fixed facet: B is
  // exact there).
  OneNode t;
  const contact::FrictionAnchor anchor{0, {-0.2, 0.0}};
  for (double ux : {0.001, 0.01}) {
    const double h = 1e-7;
    const auto f0 = t.eval(ux, anchor, kP);
    const auto fp = t.eval(ux + h, anchor, kP), fm = t.eval(ux - h, anchor, kP);
    const double fd_k = (fp.force[0] - fm.force[0]) / (2 * h);
    const double k = f0.tangent[0 * f0.n_dof + 0];
    EXPECT_NEAR(k, fd_k, 1e-6 * std::abs(fd_k) + 1e-9) << "u = " << ux;
    const double dp = 1e-6;
    const double fd_c = (t.eval(ux, anchor, kP + dp).force[0] - t.eval(ux, anchor, kP - dp).force[0]) / (2 * dp);
    EXPECT_NEAR(f0.coupling[0], fd_c, 1e-6 * std::abs(fd_c)) << "u = " << ux;
  }
}

TEST(FrictionKernel, RoughNeverSlips) {
  OneNode t;
  t.law = contact::FrictionLaw{0.0, true, kGammaCrit, 1000.0, false};
  auto r = t.eval(0.5, {0, {-0.2, 0.0}}, kP);
  EXPECT_FALSE(r.slipping);
  EXPECT_NEAR(r.traction[0], 1000.0 * 0.5, 1e-9);
  EXPECT_NEAR(r.coupling[0], 0.0, 0.0);  // no pressure coupling: the tangent stays symmetric
}

TEST(FrictionLawResolution, AbaqusDefaults) {
  model::Friction f;
  f.mu = 0.2;
  auto law = contact::resolve_friction(&f, 2.0, 100.0);
  ASSERT_TRUE(law);
  EXPECT_DOUBLE_EQ(law->gamma_crit, 0.01);  // SLIP TOLERANCE 0.005 × l_char
  EXPECT_DOUBLE_EQ(law->stiffness(5.0), 0.2 * 5.0 / 0.01);  // k_s = μ p / γ_crit
  f.elastic_slip = 0.003;
  EXPECT_DOUBLE_EQ(contact::resolve_friction(&f, 2.0, 100.0)->gamma_crit, 0.003);  // ELASTIC SLIP wins
  f.mu = 0.0;
  EXPECT_FALSE(contact::resolve_friction(&f, 2.0, 100.0));  // μ = 0: frictionless
  EXPECT_FALSE(contact::resolve_friction(nullptr, 2.0, 100.0));
}

// --- The frictionless path ---------------------------------------------------------------

TEST(FrictionCost, FrictionlessPathBuildsNoTangentialTerms) {
  // The 2D patch deck (no *FRICTION) through a whole analysis leaves no friction state, and a
  // ContactProblem on it evaluates no return mapping and keeps no skew part.
  auto r = verification::run_deck(contact_deck("patch_2d_direct.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  EXPECT_EQ(verification::field(r->capture.last(), "CSHEAR1"), nullptr);  // not requested, not written
  const auto am = solver::build_analysis_model(r->model());
  solver::ContactProblem problem(am, 0);
  EXPECT_FALSE(problem.has_friction());
  solver::ContactState state;
  problem.begin_attempt(state, 1, 1, std::vector<double>(am.n_dof(), 0.0));
  for (const auto& f : state.friction) EXPECT_TRUE(f.empty());
  EXPECT_EQ(problem.friction_evaluations(), 0);
  EXPECT_FALSE(problem.unsymmetric());
  // The same with friction: its state exists.
  auto rf = verification::run_deck(contact_deck("friction_slide_2d_direct.inp"));
  const auto am_f = solver::build_analysis_model(rf->model());
  solver::ContactProblem with_friction(am_f, 0);
  EXPECT_TRUE(with_friction.has_friction());
  solver::ContactState fs;
  with_friction.begin_attempt(fs, 1, 1, std::vector<double>(am_f.n_dof(), 0.0));
  ASSERT_FALSE(fs.friction.empty());
  EXPECT_EQ(fs.friction[0].size(), 3u);
}

// --- The block decks -----------------------------------------------------------------------

/// Slipping block: every slave node slips with CSHEAR = μ CPRESS, the pushed top carries μ N.
void check_sliding(const std::string& deck, const std::string& label) {
  auto r = verification::run_deck(contact_deck(deck));
  ASSERT_TRUE(r->outcome.completed) << label << ": " << r->outcome.message;
  // No attempt is cut back. The push turns the outer nodes' slip around (the press spread them
  // outwards); before Newton stopped such a turn at the stick zone (newton.cpp's
  // limit_correction), LAGRANGE's first push increment cycled between slipping either way and
  // was cut back five times (162 iterations; 25 now).
  int cut_backs = 0;
  for (const auto& row : r->capture.rows) cut_backs += row.cut_back ? 1 : 0;
  EXPECT_EQ(cut_backs, 0) << label;
  const auto push = r->capture.of_step(2);
  ASSERT_FALSE(push.empty());
  const solver::Frame& f = *push.back();
  const auto& cpress = fd(f, "CPRESS");
  const auto& cstatus = fd(f, "CSTATUS");
  const auto& cs1 = fd(f, "CSHEAR1");
  const auto& cs2 = fd(f, "CSHEAR2");
  const auto& sl1 = fd(f, "CSLIP1");
  const auto& sl2 = fd(f, "CSLIP2");
  const auto& cfs = fd(f, "CFS");
  const auto& cfn = fd(f, "CFN");
  // The push tips the block: its trailing edge may lift off (open, no shear); every closed
  // node slips.
  double worst = 0.0, fs[3] = {0, 0, 0}, fs_sum_abs = 0.0, fn = 0.0;
  int n_closed = 0;
  const int up = r->dim() - 1;
  for (std::size_t i = 0; i < cpress.values.size(); ++i) {
    const double tau = std::hypot(cs1.values[i], cs2.values[i]);
    if (cpress.values[i] <= 0.0) {
      EXPECT_EQ(cstatus.values[i], 0.0) << label << " node " << i << ": open";
      EXPECT_EQ(tau, 0.0) << label;
      continue;
    }
    ++n_closed;
    EXPECT_EQ(cstatus.values[i], 2.0) << label << " node " << i << ": slipping";
    worst = std::max(worst, std::abs(tau - kMu * cpress.values[i]) / (kMu * kP));
    // The stress on the slave opposes its slip: CSHEAR · CSLIP < 0.
    EXPECT_LT(cs1.values[i] * sl1.values[i] + cs2.values[i] * sl2.values[i], 0.0) << label;
    for (int c = 0; c < 3; ++c) fs[c] += cfs.values[i * 3 + c];
    fs_sum_abs += std::hypot(cfs.values[i * 3], cfs.values[i * 3 + 1], cfs.values[i * 3 + 2]);
    fn += cfn.values[i * 3 + up];
  }
  EXPECT_GE(n_closed, r->dim() == 2 ? 2 : 6) << label;
  EXPECT_LE(worst, 1e-9) << label;  // |CSHEAR| = μ CPRESS at every slipping node, to round-off
  // Friction force = μ N: Σ|CFS| against μ Σ CFN (exact while all closed nodes slip), |Σ CFS|
  // and the pushed top's reaction against μ N within the equilibrium tolerance (Abaqus's
  // R_n = 0.5 % of the average force: 1e-3 of μ N here; in 3D the nodes' slip directions
  // differ slightly, so |Σ CFS| < Σ |CFS|).
  const double friction = std::hypot(fs[0], fs[1], fs[2]);
  EXPECT_NEAR(fs_sum_abs, kMu * fn, 1e-9 * kMu * kN) << label;
  EXPECT_NEAR(friction, kMu * kN, 1e-3 * kMu * kN) << label;
  EXPECT_NEAR(fn, kN, 1e-3 * kN) << label;
  const auto rf = top_reaction(*r, f);
  double rt = 0.0;
  for (int c = 0; c < up; ++c) rt += rf[c] * rf[c];
  rt = std::sqrt(rt);
  EXPECT_NEAR(rt, kMu * kN, 1e-3 * kMu * kN) << label;
  const Counts c = counts(*r, 2);
  std::printf("[friction] %s: friction force %.6f (mu N = %.6f), top reaction %.6f, max ||CSHEAR| - mu CPRESS|/(mu p) "
              "= %.2e; push step: %d increments, %d iterations (%d severe), at most %d per increment\n",
              label.c_str(), friction, kMu * fn, rt, worst, c.increments, c.iterations, c.severe,
              c.max_per_increment);
  // Unsymmetric tangent solved by UMFPACK: a converged increment in a few iterations.
  EXPECT_LE(c.max_per_increment, 8) << label;
}

TEST(FrictionBlock2D, SlidingBlockCarriesMuTimesTheNormalForceDirect) {
  check_sliding("friction_slide_2d_direct.inp", "2D direct");
}

TEST(FrictionBlock2D, SlidingBlockCarriesMuTimesTheNormalForcePenalty) {
  check_sliding("friction_slide_2d_penalty.inp", "2D penalty");
}

TEST(FrictionBlock3D, SlidingBlockCarriesMuTimesTheNormalForceInTheDirectionPushed) {
  check_sliding("friction_slide_3d_direct.inp", "3D direct");
  // Isotropy: the friction force points against the push (0.04, 0.03).
  auto r = verification::run_deck(contact_deck("friction_slide_3d_direct.inp"));
  ASSERT_TRUE(r->outcome.completed);
  const auto rf = top_reaction(*r, r->capture.last());
  EXPECT_NEAR(rf[1] / rf[0], 0.03 / 0.04, 0.02);  // direction within 2 % (the block also shears)
}

/// Sticking block: every slave node sticks, the tangential force stays below μ N and the
/// relative slip is elastic only, |CSLIP| ≤ γ_crit.
void check_sticking(const std::string& deck, const std::string& label, double gamma_crit = kGammaCrit) {
  auto r = verification::run_deck(contact_deck(deck));
  ASSERT_TRUE(r->outcome.completed) << label << ": " << r->outcome.message;
  const solver::Frame& f = r->capture.last();
  const auto& cstatus = fd(f, "CSTATUS");
  const auto& cpress = fd(f, "CPRESS");
  const auto& cs1 = fd(f, "CSHEAR1");
  const auto& cs2 = fd(f, "CSHEAR2");
  const auto& sl1 = fd(f, "CSLIP1");
  const auto& sl2 = fd(f, "CSLIP2");
  double max_slip = 0.0, max_ratio = 0.0;
  for (std::size_t i = 0; i < cstatus.values.size(); ++i) {
    EXPECT_EQ(cstatus.values[i], 1.0) << label << " node " << i << ": sticking";
    max_slip = std::max(max_slip, std::hypot(sl1.values[i], sl2.values[i]));
    max_ratio = std::max(max_ratio, std::hypot(cs1.values[i], cs2.values[i]) / (kMu * cpress.values[i]));
  }
  EXPECT_LE(max_slip, gamma_crit * (1 + 1e-9)) << label;  // elastic slip only
  EXPECT_LT(max_ratio, 1.0) << label;
  const auto rf = top_reaction(*r, f);
  const double rt = std::hypot(rf[0], r->dim() == 3 ? rf[1] : 0.0);
  EXPECT_LT(rt, kMu * kN) << label;
  EXPECT_GT(rt, 0.0) << label;
  const Counts c = counts(*r, 2);
  std::printf("[friction] %s: tangential force %.6f < mu N = %.6f, max |CSLIP| %.3e <= gamma_crit %.3e, max |CSHEAR|/"
              "(mu CPRESS) %.3f; push step: %d increments, %d iterations\n",
              label.c_str(), rt, kMu * kN, max_slip, gamma_crit, max_ratio, c.increments, c.iterations);
}

TEST(FrictionBlock2D, BlockSticksBelowTheLimit) { check_sticking("friction_stick_2d_direct.inp", "2D direct stick"); }

TEST(FrictionBlock3D, BlockSticksBelowTheLimit) { check_sticking("friction_stick_3d_penalty.inp", "3D penalty stick"); }

// *FRICTION, LAGRANGE: Abaqus sticks exactly (multipliers); inpact keeps elastic slip with an
// allowable slip of 1e-6 of the characteristic length (contact/friction.hpp): the sticking block
// slips at most 5e-7, the sliding block carries μ N as with the default. It costs iterations:
// the 2D sliding push takes 29 increments (156 iterations) against 6 (18) by default.
TEST(FrictionLagrange, SticksToAMillionthOfTheLengthAndSlidesAtMuN) {
  check_sliding("friction_slide_2d_lagrange.inp", "2D LAGRANGE slide");
  // The block pushed by 1e-5: pressing already let the edge nodes slip (Poisson expansion
  // against near-exact sticking: CSHEAR = μ CPRESS there); every node still sticking at the
  // end of the push moved by at most twice the allowable elastic slip during it.
  auto r = verification::run_deck(contact_deck("friction_stick_2d_lagrange.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto pressed = r->capture.of_step(1), pushed = r->capture.of_step(2);
  ASSERT_FALSE(pressed.empty());
  ASSERT_FALSE(pushed.empty());
  const auto& s0 = fd(*pressed.back(), "CSLIP1");
  const auto& s1 = fd(*pushed.back(), "CSLIP1");
  const auto& st = fd(*pushed.back(), "CSTATUS");
  const double gamma = contact::kLagrangeSlipFraction * 0.5;  // × the facet size 0.5
  int sticking = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < st.values.size(); ++i) {
    if (st.values[i] != 1.0) continue;
    ++sticking;
    worst = std::max(worst, std::abs(s1.values[i] - s0.values[i]));
  }
  EXPECT_GE(sticking, 1);
  EXPECT_LE(worst, 2.0 * gamma * (1 + 1e-9));
  std::printf("[friction] 2D LAGRANGE stick: %d sticking nodes moved by at most %.3e during the push (gamma %.1e)\n",
              sticking, worst, gamma);
}

}  // namespace
}  // namespace inpact::test
