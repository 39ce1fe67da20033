// Case 1: cantilever bending under mesh refinement, with the observed convergence rate.
//
// Reference: the Timoshenko & Goodier plane-stress cantilever (Theory of Elasticity, §21):
// parabolic shear load P at x = 0, built-in end x = L where the exact displacements are
// prescribed on every node, so the discrete problem converges to the exact solution and the
// error is the discretisation error alone. The tip deflection of the centre line is
//   v(0, 0) = PL³/(3EI) + PLc²/(2IG)  (Euler–Bernoulli + the shear deflection 3PL/(2GA)).
// With ν = 0 the solution is exact in 3D as well (w = 0), so the same reference holds for the
// hexahedra and tetrahedra. Meshes: three levels, h halved each time (decks generated at test
// time by decks/verification/gen_verification.py; level 1 of each is committed).
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

struct Level {
  int nx, ny, nz;
};

struct Study {
  const char* type;
  std::vector<Level> levels;
  double nu;
  double min_rate;           ///< the observed log-log slope must reach this
  double finest_tolerance;   ///< relative error of the finest mesh
};

double tip_deflection(const Run& r) {
  const auto tip = nset(r.model(), "TIPLINE");
  double v = 0;
  for (std::int32_t n : tip) v += nodal(r.capture.last(), "U", static_cast<std::size_t>(n), 1);
  return v / static_cast<double>(tip.size());
}

void run_study(const Study& s) {
  const double L = 8.0, c = 0.5, b = 1.0, E = 1.0e5, P = 10.0;
  const double I = 2 * b * c * c * c / 3, G = E / (2 * (1 + s.nu));
  const double exact = P * L * L * L / (3 * E * I) + P * L * c * c / (2 * I * G);
  generate(std::string("--cantilever-levels ") + s.type);
  std::vector<double> h, err;
  for (const Level& lv : s.levels) {
    char name[128];
    std::snprintf(name, sizeof name, "cantilever_%s_%dx%dx%d.inp", s.type, lv.nx, lv.ny, lv.nz);
    std::string file = name;
    std::transform(file.begin(), file.end(), file.begin(), [](unsigned char ch) { return std::tolower(ch); });
    const auto r = run_deck((generated_dir() / file).string());
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const double v = tip_deflection(*r);
    h.push_back(L / lv.nx);
    err.push_back(std::abs(v - exact) / exact);
    const std::string tag = std::string(s.type) + " " + std::to_string(lv.nx) + "x" + std::to_string(lv.ny) + "x" +
                            std::to_string(lv.nz);
    report(tag + ": tip deflection relative error", err.back());
    report(tag + ": Newton iterations", r->capture.iterations);
    report(tag + ": solve seconds", r->seconds);
    // Case 5: the reactions at the built-in end carry the applied load P (in y) and nothing else.
    expect_balance(*r, r->capture.last(), {0.0, P, 0.0}, 1e-9, tag);
  }
  const double rate = loglog_slope(h, err);
  report(std::string(s.type) + ": observed rate (log-log slope of tip error vs h)", rate);
  EXPECT_GE(rate, s.min_rate) << s.type;
  EXPECT_LE(err.back(), s.finest_tolerance) << s.type;
  // Monotone convergence: every refinement lowers the error.
  for (std::size_t i = 1; i < err.size(); ++i) EXPECT_LT(err[i], err[i - 1]) << s.type << " level " << i;
}

// Quadratic plane-stress elements, reduced integration. Theory: energy norm O(h²), the
// deflection (a point value of a quadratic field) O(h³) or better. Measured 2.92 (1.4e-6,
// 1.9e-7, 2.4e-8): required ≥ 2.7, finest error ≤ 1e-7.
TEST(CantileverConvergence, Cps8rTipDeflectionConvergesAtSecondOrderToTimoshenkoGoodier) {
  run_study({"CPS8R", {{8, 2, 1}, {16, 4, 1}, {32, 8, 1}}, 0.3, 2.7, 1e-7});
}

// Incompatible-mode hexahedra: bending without shear locking, error O(h²). Measured 2.00
// (3.8e-3, 9.6e-4, 2.4e-4): required ≥ 1.9, finest error ≤ 5e-4.
TEST(CantileverConvergence, C3d8iTipDeflectionConvergesAtSecondOrderToTimoshenkoGoodier) {
  run_study({"C3D8I", {{8, 2, 1}, {16, 4, 2}, {32, 8, 4}}, 0.0, 1.9, 5e-4});
}

// Quadratic tetrahedra (six per brick): displacement error O(h³) in L², the point value
// O(h³)–O(h⁴). Measured 3.51 (7.5e-3, 7.5e-4, 5.8e-5): required ≥ 3.0, finest error ≤ 1.5e-4.
TEST(CantileverConvergence, C3d10TipDeflectionConvergesAtSecondOrderToTimoshenkoGoodier) {
  run_study({"C3D10", {{4, 2, 2}, {8, 4, 4}, {16, 8, 8}}, 0.0, 3.0, 1.5e-4});
}

}  // namespace
}  // namespace inpact::verification
