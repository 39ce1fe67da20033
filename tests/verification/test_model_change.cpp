// *MODEL CHANGE, TYPE=ELEMENT on decks/verification/model_change_bar_c3d8.inp: two C3D8 in series
// along x in uniaxial strain (E = 1000, ν = 0: S11 = 1000 ε), the far end pulled by d = 0.01.
// Closed forms at every frame (the deck's heading derives them); CalculiX 2.20 agrees at the
// ends of the steps it runs (the removal and the unloaded bar).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "fixtures/deck_fixture.hpp"
#include "verification_fixture.hpp"

namespace inpact::test {
namespace {

using verification::nodal;
using verification::Run;

constexpr double kD = 0.01;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// u1 at x = 1 (node 5, row 4) and S11 at the first point of E1 and E2, frame by frame.
struct BarFrame {
  double u_mid, s_e1, s_e2;
};

std::vector<BarFrame> bar_frames(const Run& r) {
  std::vector<BarFrame> out;
  for (const auto& sf : r.capture.frames) {
    const auto s = verification::point_values(r, sf.frame);
    BarFrame b{nodal(sf.frame, "U", 4, 0), 0.0, 0.0};
    for (const auto& p : s)
      if (p.ip == 1) (p.element == 1 ? b.s_e1 : b.s_e2) = p.s[0];
    out.push_back(b);
  }
  return out;
}

void expect_frames(const std::vector<BarFrame>& got, const std::vector<BarFrame>& want, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].u_mid, want[i].u_mid, 1e-12) << what << " frame " << i;
    EXPECT_NEAR(got[i].s_e1, want[i].s_e1, 1e-9) << what << " frame " << i;
    EXPECT_NEAR(got[i].s_e2, want[i].s_e2, 1e-9) << what << " frame " << i;
  }
}

// Pull (u = d/2, S = 5); remove E2 over two increments (its force at x = 1 ramps down: d/4 at
// half the step, 0 at its end; E2's output 0); reactivate strain free (nothing moves); pull the
// end to 2d (E2 measures from d: u = d/2, S = 5 again).
TEST(ModelChange, RemovalRampsDownAndStrainFreeReactivationStartsUnstressed) {
  const auto r = verification::run_deck(verification::deck_path("model_change_bar_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  expect_frames(bar_frames(*r),
                {{kD / 2, 5, 5}, {kD / 4, 2.5, 0}, {0, 0, 0}, {0, 0, 0}, {kD / 2, 5, 5}}, "STRAIN FREE");
}

// ADD=WITH STRAIN: E2's strain from the original configuration, d at once, shared with E1
// (u = d/2, S = 5); pulled to 2d: u = d, S = 10.
TEST(ModelChange, ReactivationWithStrainMeasuresFromTheOriginalConfiguration) {
  std::string text = read_text(verification::deck_path("model_change_bar_c3d8.inp"));
  const std::string add = "*MODEL CHANGE, TYPE=ELEMENT, ADD\n";
  text.replace(text.find(add), add.size(), "*MODEL CHANGE, TYPE=ELEMENT, ADD=WITH STRAIN\n");
  const DeckDir dir;
  const auto r = verification::run_deck(dir.write("with_strain.inp", text));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  expect_frames(bar_frames(*r),
                {{kD / 2, 5, 5}, {kD / 4, 2.5, 0}, {0, 0, 0}, {kD / 2, 5, 5}, {kD, 10, 10}}, "WITH STRAIN");
}

}  // namespace
}  // namespace inpact::test
