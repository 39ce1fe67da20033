// *TIE verification (decks/verification/tie_*.inp, made by gen_tie.py; contact/tie.hpp):
//  - patch test: two non-matching C3D8 meshes tied at a flat interface under uniform tension
//    give S = (1, 0, 0, 0, 0, 0) at every point (the linear field is in the tied space), 1e-8;
//  - a chain (a tie's master nodes tied by another tie) resolved by the DOF map: the same;
//  - ADJUST: a slave interface 0.004 short of the master (tolerance 0.0354) is moved onto it and
//    gives the zero-offset answer (U to 1e-12 of its largest value);
//  - a cantilever of two non-matching C3D8I meshes tied across its span: tip deflection within
//    0.5 % of the single 20x4x2 mesh, within 2 % of beam theory (4 + 0.024, shear included).
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

/// Largest |S − (1, 0, 0, 0, 0, 0)| over every point.
double patch_stress_error(const Run& r) {
  double worst = 0.0;
  for (const PointValue& p : point_values(r, r.capture.last()))
    for (std::size_t c = 0; c < p.s.size(); ++c) worst = std::max(worst, std::abs(p.s[c] - (c == 0 ? 1.0 : 0.0)));
  return worst;
}

/// Σ RF1 over the x = 2 face: the force the tension takes, σ A = 1.
double right_face_force(const Run& r) {
  double s = 0.0;
  for (std::int32_t n : nset(r.model(), "RIGHT")) s += nodal(r.capture.last(), "RF", static_cast<std::size_t>(n), 0);
  return s;
}

TEST(Tie, UniformStressCrossesANonMatchingTieExactly) {
  const auto r = run_deck(deck_path("tie_patch_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double err = patch_stress_error(*r);
  report("tie patch: max |S - (1,0,0,0,0,0)|", err);
  EXPECT_LE(err, 1e-8);
  EXPECT_NEAR(right_face_force(*r), 1.0, 1e-9);
  expect_balance(*r, r->capture.last(), {0, 0, 0}, 1e-12, "tie patch");
  // The tied nodes' U is the master field there: u1 = 0.001 x exactly, u2 = −0.3·0.001 y.
  double worst_u = 0.0;
  for (std::size_t n = 0; n < r->model().mesh.nodes.size(); ++n) {
    const auto x = coords(r->model(), static_cast<std::int32_t>(n));
    worst_u = std::max({worst_u, std::abs(nodal(r->capture.last(), "U", n, 0) - 1e-3 * x[0]),
                        std::abs(nodal(r->capture.last(), "U", n, 1) + 3e-4 * x[1]),
                        std::abs(nodal(r->capture.last(), "U", n, 2) + 3e-4 * x[2])});
  }
  report("tie patch: max |U - exact|", worst_u);
  EXPECT_LE(worst_u, 1e-12);
}

TEST(Tie, AChainOfTiesResolvesThroughTheDofMap) {
  const auto r = run_deck(deck_path("tie_patch_chain_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double err = patch_stress_error(*r);
  report("tie chain patch: max |S - (1,0,0,0,0,0)|", err);
  EXPECT_LE(err, 1e-8);
  EXPECT_NEAR(right_face_force(*r), 2.0, 1e-9);  // x = 2 face of B and C: area 2
}

TEST(Tie, AdjustMovesTheSlaveOntoTheMasterAndGivesTheZeroOffsetAnswer) {
  const auto zero = run_deck(deck_path("tie_patch_c3d8.inp"));
  const auto moved = run_deck(deck_path("tie_patch_adjust_c3d8.inp"));
  ASSERT_TRUE(zero->outcome.completed && moved->outcome.completed);
  const auto& mz = zero->model();
  const auto& mm = moved->model();
  ASSERT_EQ(mz.mesh.nodes.size(), mm.mesh.nodes.size());
  EXPECT_EQ(mm.ties[0].n_adjusted, 16u);
  EXPECT_NEAR(mm.ties[0].largest_adjustment, 0.004, 1e-15);
  double dx = 0.0, du = 0.0, umax = 0.0;
  for (std::size_t n = 0; n < mz.mesh.nodes.size(); ++n)
    for (int c = 0; c < 3; ++c) {
      dx = std::max(dx, std::abs(mz.mesh.nodes.coords[n][c] - mm.mesh.nodes.coords[n][c]));
      const double a = nodal(zero->capture.last(), "U", n, c), b = nodal(moved->capture.last(), "U", n, c);
      du = std::max(du, std::abs(a - b));
      umax = std::max(umax, std::abs(a));
    }
  report("tie adjust: max |X_adjusted - X_zero offset|", dx);
  report("tie adjust: max |U - U_zero offset| / max |U|", du / umax);
  EXPECT_LE(dx, 1e-15);
  EXPECT_LE(du, 1e-12 * umax);
  EXPECT_LE(patch_stress_error(*moved), 1e-8);
}

/// Mean u2 over the tip face.
double tip_deflection(const Run& r) {
  double s = 0.0;
  const auto tip = nset(r.model(), "TIP");
  for (std::int32_t n : tip) s += nodal(r.capture.last(), "U", static_cast<std::size_t>(n), 1);
  return s / static_cast<double>(tip.size());
}

void expect_cantilever(const std::string& deck, const std::string& what) {
  const auto tied = run_deck(deck_path(deck));
  const auto single = run_deck(deck_path("tie_cantilever_single_c3d8i.inp"));
  ASSERT_TRUE(tied->outcome.completed && single->outcome.completed);
  const double v_tied = -tip_deflection(*tied), v_single = -tip_deflection(*single);
  const double v_beam = 4.0 + 0.024;  // PL³/3EI + PL/(κGA), κ = 5/6
  report(what + ": tip deflection, tied", v_tied);
  report(what + ": tip deflection, single mesh", v_single);
  report(what + ": tied / single - 1", v_tied / v_single - 1.0);
  report(what + ": tied / beam theory - 1", v_tied / v_beam - 1.0);
  EXPECT_LE(std::abs(v_tied / v_single - 1.0), 5e-3);
  EXPECT_LE(std::abs(v_tied / v_beam - 1.0), 2e-2);
  expect_balance(*tied, tied->capture.last(), {0, -1.0, 0}, 1e-10, what);
}

TEST(Tie, CantileverOfTwoTiedMeshesBendsAsTheSingleMesh) {
  expect_cantilever("tie_cantilever_c3d8i.inp", "tie cantilever, node to surface");
  expect_cantilever("tie_cantilever_s2s_c3d8i.inp", "tie cantilever, surface to surface");
}

}  // namespace
}  // namespace inpact::verification
