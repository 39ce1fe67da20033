// Case 7: *EQUATION ties (u_dependent − u_master = 0), against the hand solution of springs in
// series. Unit cubes, ν = 0 (uniaxial), EA/L = 1000 (A, C) and 2000 (B).
//  - Block B's x = 1.5 face tied in u1 to block A's x = 1 face; 100 at B's far face:
//    u1(A, x = 1) = u1(B, x = 1.5) = 100/1000 = 0.1, u1(B, x = 2.5) = 0.1 + 100/2000 = 0.15.
//  - Block C's x = −0.5 face tied in u1 to A's held x = 0 face; −50 at C's far face:
//    u1(C, x = −1.5) = −0.05. The held face's reactions carry both: −100 (from A) + 50 (from C
//    through the equations) = −50.
#include "fixtures/deck_fixture.hpp"
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

double face_u1(const Run& r, const solver::Frame& f, double x) {
  double s = 0;
  int k = 0;
  for (std::size_t n = 0; n < r.model().mesh.nodes.size(); ++n)
    if (std::abs(coords(r.model(), static_cast<std::int32_t>(n))[0] - x) < 1e-9) {
      s += nodal(f, "U", n, 0);
      ++k;
    }
  return s / k;
}

TEST(Equation, TiedBlocksActAsSpringsInSeriesAndTiesToSupportsCarryReactions) {
  const auto r = run_deck(deck_path("equation_tie.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  const double tol = 1e-12;
  struct Expect {
    double x, u;
  };
  double worst = 0;
  for (const Expect& e : {Expect{1.0, 0.1}, Expect{1.5, 0.1}, Expect{2.5, 0.15}, Expect{-0.5, 0.0}, Expect{-1.5, -0.05}}) {
    const double u = face_u1(*r, f, e.x);
    worst = std::max(worst, std::abs(u - e.u));
    EXPECT_NEAR(u, e.u, tol) << "u1 at x = " << e.x;
  }
  report("equation tie: worst |u1 - hand value|", worst);
  double rf_left = 0;
  for (std::int32_t n : nset(r->model(), "LEFT")) rf_left += nodal(f, "RF", static_cast<std::size_t>(n), 0);
  report("equation tie: RF1 on the held face (hand value -50)", rf_left);
  EXPECT_NEAR(rf_left, -50.0, 1e-9);
  expect_balance(*r, f, {100.0 - 50.0, 0, 0}, 1e-12, "equation tie");
}

// Two equations that make u1 of nodes 7 and 8 each other's master leave node 7 depending on
// itself: a deck error that names the node and DOF (the DOF map keeps no deck line per rule).
TEST(Equation, ACycleOfEquationsNamesTheNodeItLeadsBackTo) {
  const std::string deck =
      "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n5, 0., 0., 1.\n6, 1., 0., 1.\n"
      "7, 1., 1., 1.\n8, 0., 1., 1.\n*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n"
      "*EQUATION\n2\n7, 1, 1., 8, 1, -1.\n2\n8, 1, 1., 7, 1, -1.\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n4, 3\n"
      "*STEP\n*STATIC\n*CLOAD\n6, 1, 1.\n*END STEP\n";
  const test::DeckDir dir;
  const std::string message = stop_message(dir.write("cycle.inp", deck));
  EXPECT_NE(message.find("the constraints make node 7 DOF 1 depend on itself (a chain of them leads back to it)"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace inpact::verification
