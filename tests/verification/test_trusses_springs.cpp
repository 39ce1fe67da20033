// Trusses and springs against closed forms and hand solutions (decks/verification/truss_*.inp,
// spring_*.inp; each deck's heading gives its reference).
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

std::size_t node_row(const Run& r, std::int64_t label) { return static_cast<std::size_t>(*r.model().mesh.nodes.index.find(0, label)); }

/// Component c of point field `key` at element `label`, point `ip` (1-based).
double point(const solver::Frame& f, const std::string& key, std::int64_t label, int ip, int c) {
  const auto* fd = field(f, key);
  if (!fd) throw std::runtime_error("frame has no field " + key);
  const std::size_t n = fd->component_labels.size();
  for (std::size_t i = 0; i < fd->elements.size(); ++i)
    if (fd->elements[i] == label && fd->ip[i] == ip) return fd->values[i * n + static_cast<std::size_t>(c)];
  throw std::runtime_error("no point");
}

// P = 1000 at the apex of bars from (∓3, 0) to (0, 4): sin θ = 0.8, L = 5, E A = 4e5.
// σ = −P/(2 A sin θ) = −312.5; δ = P L/(2 E A sin²θ) = 9.765625e-3. Round-off: 1e-12 relative.
TEST(TrussSpring, TwoBarTrussMatchesTheClosedFormToRoundOff) {
  for (const char* deck : {"truss_two_bar_t2d2.inp", "truss_two_bar_t3d3.inp"}) {
    const auto r = run_deck(deck_path(deck));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const auto& f = r->capture.last();
    const double delta = nodal(f, "U", node_row(*r, 3), 1);
    EXPECT_NEAR(delta, -9.765625e-3, 1e-12 * 9.765625e-3) << deck;
    report(std::string(deck) + ": apex deflection relative error", std::abs(delta / -9.765625e-3 - 1));
    const int points = std::string(deck).find("t3d3") != std::string::npos ? 2 : 1;
    for (std::int64_t e : {1, 2})
      for (int ip = 1; ip <= points; ++ip) {
        EXPECT_NEAR(point(f, "S", e, ip, 0), -312.5, 1e-12 * 312.5) << deck << " element " << e;
        EXPECT_NEAR(point(f, "E", e, ip, 0), -312.5 / 200000.0, 1e-12 * 312.5 / 200000.0) << deck;
        if (points == 1) {
          EXPECT_NEAR(point(f, "SF", e, ip, 0), -625.0, 1e-12 * 625.0) << "SF1 = N";
        }
      }
  }
}

// A truss in parallel with a continuum sharing its nodes: the stiffnesses add up exactly
// (EA/L = 1000 of the ν = 0 block plus 1000 of the trusses): u = 100 / 2000 = 0.05, S = 50 in both.
TEST(TrussSpring, TrussesInParallelWithASolidAddTheirStiffness) {
  struct Case {
    const char* deck;
    int axis;  ///< the loaded direction (0-based)
    std::vector<std::int64_t> top, trusses;
  };
  for (const Case& c : {Case{"truss_parallel_c3d8.inp", 2, {5, 6, 7, 8}, {11, 12, 13, 14}},
                        Case{"truss_parallel_cpe4.inp", 1, {3, 4}, {11, 12}}}) {
    const auto r = run_deck(deck_path(c.deck));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const auto& f = r->capture.last();
    for (std::int64_t n : c.top) EXPECT_NEAR(nodal(f, "U", node_row(*r, n), c.axis), 0.05, 1e-14) << c.deck;
    for (std::int64_t e : c.trusses) EXPECT_NEAR(point(f, "S", e, 1, 0), 50.0, 1e-11) << c.deck;
    EXPECT_NEAR(point(f, "S", 1, 1, c.axis), 50.0, 1e-11) << c.deck;
  }
}

// NLGEOM: N = A λ E (λ² − 1)/2 = 132 at λ = 1.2 (u = 0.4, S11 = N/A = 264, E11 = ln 1.2); then a
// rigid rotation by 90° of the stretched bar keeps the force. Newton's tolerance: 1e-8 relative.
TEST(TrussSpring, NlgeomTrussFollowsTheGreenLagrangeClosedFormAndRotatesWithoutStress) {
  const auto r = run_deck(deck_path("truss_nlgeom_bar.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto step1 = r->capture.of_step(1);
  const auto& f1 = *step1.back();
  EXPECT_NEAR(nodal(f1, "U", 1, 0), 0.4, 1e-8);
  EXPECT_NEAR(point(f1, "S", 1, 1, 0), 264.0, 1e-6);
  EXPECT_NEAR(point(f1, "E", 1, 1, 0), std::log(1.2), 1e-9);
  const auto& f2 = r->capture.last();
  EXPECT_NEAR(point(f2, "S", 1, 1, 0), 264.0, 1e-9);
  // The reaction at node 1 balances N along the rotated axis (0, 1, 0).
  EXPECT_NEAR(nodal(f2, "RF", 0, 1), -132.0, 1e-9);
  EXPECT_NEAR(nodal(f2, "RF", 0, 0), 0.0, 1e-9);
}

// SPRINGA (k = 100) from the held node 1 to node 2, SPRING2 (k = 50, u1 to u1) from node 2 to 3,
// SPRING1 (k = 25, u1) at node 3; 5 at node 2, 10 at node 3:
//   150 u2 − 50 u3 = 5, −50 u2 + 75 u3 = 10  →  u2 = 0.1, u3 = 0.2; forces 10, 5, 5; RF1(1) = −10.
TEST(TrussSpring, SpringChainWithAGroundSpringMatchesTheHandSolution) {
  const auto r = run_deck(deck_path("spring_chain.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  EXPECT_NEAR(nodal(f, "U", 1, 0), 0.1, 1e-15);
  EXPECT_NEAR(nodal(f, "U", 2, 0), 0.2, 1e-15);
  EXPECT_NEAR(nodal(f, "RF", 0, 0), -10.0, 1e-13);
  EXPECT_NEAR(point(f, "S", 1, 1, 0), 10.0, 1e-13);
  EXPECT_NEAR(point(f, "S", 2, 1, 0), 5.0, 1e-13);
  EXPECT_NEAR(point(f, "S", 3, 1, 0), 5.0, 1e-13);
  EXPECT_NEAR(point(f, "E", 3, 1, 0), 0.2, 1e-15);
}

// NONLINEAR tables (0, 0), (10, 1), (30, 2): a force of 20 sits on the second segment, u = 1.5.
TEST(TrussSpring, NonlinearSpringTablesInterpolateTheForce) {
  const auto r = run_deck(deck_path("spring_nonlinear.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  EXPECT_NEAR(nodal(f, "U", 0, 0), 1.5, 1e-12);
  EXPECT_NEAR(nodal(f, "U", 2, 0), 1.5, 1e-12);
  EXPECT_NEAR(point(f, "S", 1, 1, 0), 20.0, 1e-10);
  EXPECT_NEAR(point(f, "S", 2, 1, 0), 20.0, 1e-10);
}

}  // namespace
}  // namespace inpact::verification
