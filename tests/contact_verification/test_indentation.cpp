// Elastic–plastic indentation (issue 15's contact scene): a rigid-like cylinder (E_tool = 100 E)
// pressed 0.1 into a Mises block (σ_y = 600 + 3000 ε̄ᵖ), plane strain, the block the slave
// (decks/contact_verification/indentation_2d.inp, gen_indentation.py), small strain and NLGEOM.
// No closed form: the reference is CalculiX 2.20 on the same mesh, extruded into a C3D8 slab
// with U3 = 0 and linear penalty contact (K = 10 k_e), DIRECT incrementation in ten increments
// (bench/plastic_ccx/indentation.py, level 1; its table is bench/results/plastic_indentation.md).
// The forces below are ccx's indenter reactions per unit thickness at t = 0.1 … 1.0.
// Tolerances: 1 % against ccx (measured: 0.14 % small strain, 0.29 % NLGEOM with direct
// contact; the difference is mostly ccx's penalty compliance), every method within 1 % of direct,
// and the load balanced through the contact to the residual tolerance (R_n = 0.005).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>

#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

using Params = std::map<std::string, std::string>;

/// CalculiX's indenter reaction (RF2 of INDENTER_TOP) per unit thickness at t = 0.1, 0.2, …, 1.0
/// (level 1).
constexpr std::array<double, 10> kCcxSmall = {-397.406, -763, -1071.37, -1302, -1559.43, -1785.39, -1956.51, -2156.74, -2310.21, -2440.9};
constexpr std::array<double, 10> kCcxNlgeom = {-397.341, -762.966, -1070.82, -1301.55, -1564.85, -1786.8, -1965.86, -2160.1, -2323.62, -2445.28};

double set_sum(const Run& r, const solver::Frame& f, const std::string& set, int c) {
  double s = 0;
  for (std::int32_t n : verification::nset(r.deck.model, set)) s += verification::nodal(f, "RF", static_cast<std::size_t>(n), c);
  return s;
}

struct Curve {
  std::map<int, double> force;  ///< the indenter's reaction at step time k/10 (k = 1 … 10), where an increment ends
  int iterations = 0;
  double worst_balance = 0;   ///< max |Σ RF top + Σ RF bottom| / |F|
  double cfn_error = 0;       ///< max |Σ CFN₂ − F| / |F| at the last increment
  double peeq_max = 0;
};

Curve curve_of(const Params& p) {
  const auto r = run(deck_path("indentation_2d"), p);
  Curve c;
  EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
  if (!r->outcome.completed) return c;
  for (const auto* f : r->capture.of_step(1)) {
    const double top = set_sum(*r, *f, "INDENTER_TOP", 1), bottom = set_sum(*r, *f, "BLOCK_BOTTOM", 1);
    const double k = std::round(f->step_time * 10);
    if (std::abs(f->step_time * 10 - k) < 1e-9) c.force[static_cast<int>(k)] = top;
    c.worst_balance = std::max(c.worst_balance, std::abs(top + bottom) / std::abs(top));
  }
  const auto& last = *r->capture.of_step(1).back();
  double cfn = 0;
  const auto* fd = verification::field(last, "CFN");
  for (std::size_t i = 0; fd && i < fd->nodes.size(); ++i) cfn += fd->values[i * fd->component_labels.size() + 1];
  c.cfn_error = std::abs(std::abs(cfn) - std::abs(c.force.at(10))) / std::abs(c.force.at(10));
  c.iterations = r->iterations;
  for (const auto& pv : verification::field(last, "PEEQ")->values) c.peeq_max = std::max(c.peeq_max, pv);
  return c;
}

double worst_against(const Curve& c, const std::array<double, 10>& ref) {
  double worst = 0;
  for (const auto& [k, f] : c.force) worst = std::max(worst, std::abs(f - ref[static_cast<std::size_t>(k - 1)]) / std::abs(ref.back()));
  return worst;
}

void check_against_ccx(const char* nlgeom, const std::array<double, 10>& ref) {
  SCOPED_TRACE(std::string("NLGEOM=") + nlgeom);
  const Curve direct = curve_of({{"nlgeom", nlgeom}});
  ASSERT_EQ(direct.force.size(), 10u);  // ten increments, none cut back
  EXPECT_GT(direct.peeq_max, 0.02);  // the block yields well beyond first yield
  EXPECT_LE(direct.worst_balance, 5e-3);
  EXPECT_LE(direct.cfn_error, 5e-3);
  const double d = worst_against(direct, ref);
  EXPECT_LE(d, 0.01);
  std::printf("[indentation] NLGEOM=%s direct: F = %.2f (ccx %.2f), worst |F - F_ccx| / F_ccx = %.3e, "
              "balance %.1e, PEEQ max %.4f\n", nlgeom, direct.force.at(10), ref.back(), d, direct.worst_balance,
              direct.peeq_max);
  for (const char* method : {"PENALTY", "AUGMENTED LAGRANGE"}) {
    const Curve c = curve_of({{"nlgeom", nlgeom}, {"method", method}});
    ASSERT_TRUE(c.force.count(10)) << method;
    double worst = 0;
    for (const auto& [k, f] : c.force) worst = std::max(worst, std::abs(f - direct.force.at(k)) / std::abs(direct.force.at(10)));
    EXPECT_LE(worst, 0.01) << method;
    std::printf("[indentation] NLGEOM=%s %s: worst |F - F_direct| / F = %.3e at the tenths both reach; "
                "%d Newton iterations (direct %d)\n", nlgeom, method, worst, c.iterations, direct.iterations);
  }
}

}  // namespace

TEST(PlasticIndentation, SmallStrainMatchesCalculixAndEveryMethodAgrees) { check_against_ccx("NO", kCcxSmall); }

TEST(PlasticIndentation, NlgeomMatchesCalculixAndEveryMethodAgrees) { check_against_ccx("YES", kCcxNlgeom); }

}  // namespace inpact::contact_verification
