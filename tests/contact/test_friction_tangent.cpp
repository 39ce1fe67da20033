// The friction tangent of one slave node (contact/friction.hpp: the local block the solver
// scatters, solver/contact_problem.cpp) against central differences of the friction force
// over every unknown of the node and its master facet, at fixed pressure, in stick and slip,
// 2D and 3D, on a master facet that is held and on one that moves (turned and stretched).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/friction.hpp"
#include "contact/projection.hpp"
#include "contact_test_util.hpp"

namespace inpact::test {
namespace {

constexpr double kMu = 0.3, kPressure = 10.0, kGammaCrit = 0.0025;

struct Node {
  contact::Facet facet;
  std::vector<contact::Vec3> x;  ///< slave node first, then the facet's nodes
  int dim = 2;
  contact::FrictionAnchor anchor{0, {0, 0}};
  contact::FrictionLaw law{kMu, false, kGammaCrit, 0.0, false};

  contact::FrictionPoint eval(const std::vector<contact::Vec3>& y) const {
    const auto pr = contact::project_to_facet(facet, y, y[0]);
    const auto lin = contact::linearize_gap(facet, y, y[0], pr, dim, 0);
    return contact::friction_point(law, facet, pr, lin, facet, anchor, {0, 0, 0}, kPressure, y);
  }
  /// Largest |tangent − central difference| over the unknowns, relative to the largest entry;
  /// `master_free`: the facet's nodes are unknowns too (else only the slave node's).
  double worst_error(bool master_free, bool& slipping) const {
    const auto f0 = eval(x);
    slipping = f0.slipping;
    const std::size_t n = static_cast<std::size_t>(f0.n_dof), d = static_cast<std::size_t>(dim);
    const std::size_t columns = master_free ? n : d;
    const double h = 1e-7;
    double worst = 0.0, largest = 0.0;
    for (std::size_t j = 0; j < columns; ++j) {
      auto yp = x, ym = x;
      yp[j / d][j % d] += h;
      ym[j / d][j % d] -= h;
      const auto fp = eval(yp), fm = eval(ym);
      for (std::size_t i = 0; i < n; ++i) {
        const double fd = (fp.force[i] - fm.force[i]) / (2 * h);
        worst = std::max(worst, std::abs(f0.tangent[i * n + j] - fd));
        largest = std::max({largest, std::abs(fd), std::abs(f0.tangent[i * n + j])});
      }
    }
    return worst / largest;
  }
};

/// A Line2 master from (0, 0) to (1, 0) (held) or turned by 0.2 rad and stretched by 1.1
/// (moving); the slave 0.01 above it, moved `slide` along it from the anchor at ξ0 = −0.2.
Node line_case(bool moved, double slide) {
  Node t;
  t.dim = 2;
  t.facet = make_facet(contact::FacetShape::Line2, 1);
  const double c = moved ? 1.1 * std::cos(0.2) : 1.0, s = moved ? 1.1 * std::sin(0.2) : 0.0;
  const contact::Vec3 a{0.0, 0.0, 0.0}, b{c, s, 0.0};
  const double along = 0.4 + slide;  // anchor at ξ0 = −0.2: 0.4 of the way
  const double len = std::hypot(c, s);
  t.x = {{along * c - 0.01 * s / len, along * s + 0.01 * c / len, 0.0}, a, b};
  t.anchor = {0, {-0.2, 0.0}};
  return t;
}

/// A Quad4 master on [0,1]² (held) or turned about x and y and sheared (moving); the slave 0.01
/// above it, moved `slide` diagonally from the anchor at ξ0 = (−0.2, 0.1).
Node quad_case(bool moved, double slide) {
  Node t;
  t.dim = 3;
  t.facet = make_facet(contact::FacetShape::Quad4, 1);
  auto map = [&](double u, double v) -> contact::Vec3 {
    if (!moved) return {u, v, 0.0};
    return {1.05 * u + 0.1 * v, 0.02 * u + 0.95 * v, 0.15 * u - 0.1 * v + 0.03 * u * v};
  };
  const auto nodes = place(contact::FacetShape::Quad4, [&](double xi, double eta) {
    return map(0.5 * (xi + 1), 0.5 * (eta + 1));
  });
  const double u0 = 0.4 + slide, v0 = 0.55 + 0.5 * slide;
  // 0.01 off the facet along its normal there.
  const double e = 1e-6;
  const contact::Vec3 p0 = map(u0, v0), pu = map(u0 + e, v0), pv = map(u0, v0 + e);
  contact::Vec3 nrm{(pu[1] - p0[1]) * (pv[2] - p0[2]) - (pu[2] - p0[2]) * (pv[1] - p0[1]),
                    (pu[2] - p0[2]) * (pv[0] - p0[0]) - (pu[0] - p0[0]) * (pv[2] - p0[2]),
                    (pu[0] - p0[0]) * (pv[1] - p0[1]) - (pu[1] - p0[1]) * (pv[0] - p0[0])};
  const double ln = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
  contact::Vec3 xs = p0;
  for (int c = 0; c < 3; ++c) xs[c] += 0.01 * nrm[c] / ln;
  t.x = {xs};
  for (const auto& p : nodes) t.x.push_back(p);
  t.anchor = {0, {-0.2, 0.1}};
  return t;
}

void report_and_check(const char* what, const Node& t, bool expect_slip) {
  for (bool master_free : {false, true}) {
    bool slipping = false;
    const double e = t.worst_error(master_free, slipping);
    std::printf("[friction tangent] %s, %s: %s, worst relative error %.3e\n", what,
                master_free ? "slave and master unknowns" : "slave unknowns", slipping ? "slip" : "stick", e);
    EXPECT_EQ(slipping, expect_slip) << what;
    EXPECT_LT(e, 1e-6) << what << (master_free ? " (master free)" : "");
  }
}

TEST(FrictionTangent, LineOnAHeldMasterStickAndSlip) {
  report_and_check("2D held, stick", line_case(false, 0.001), false);
  report_and_check("2D held, slip", line_case(false, 0.01), true);
}

TEST(FrictionTangent, QuadOnAHeldMasterStickAndSlip) {
  report_and_check("3D held, stick", quad_case(false, 0.001), false);
  report_and_check("3D held, slip", quad_case(false, 0.01), true);
}

TEST(FrictionTangent, LineOnAMovingMasterStickAndSlip) {
  report_and_check("2D moving, stick", line_case(true, 0.001), false);
  report_and_check("2D moving, slip", line_case(true, 0.01), true);
}

TEST(FrictionTangent, QuadOnAMovingMasterStickAndSlip) {
  report_and_check("3D moving, stick", quad_case(true, 0.001), false);
  report_and_check("3D moving, slip", quad_case(true, 0.01), true);
}

}  // namespace
}  // namespace inpact::test
