// Contact search: the tree returns exactly the facets a brute-force box test returns, every
// facet within the search radius and no far one, keeps that guarantee while nodes move less than
// the margin, and asks for a rebuild when they move more.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "contact/projection.hpp"
#include "contact/search.hpp"
#include "contact_test_util.hpp"

using namespace inpact;
using contact::Facet;
using contact::FacetSearch;
using contact::FacetShape;
using contact::SearchOptions;
using contact::Vec3;

namespace {

/// A random cloud of small facets of mixed types (3D), some curved, in the unit box.
struct Cloud {
  std::vector<Facet> facets;
  std::vector<Vec3> x;
};

Cloud random_cloud(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1), d(-0.04, 0.04);
  const FacetShape shapes[] = {FacetShape::Tri3, FacetShape::Quad4, FacetShape::Tri6, FacetShape::Quad8};
  Cloud c;
  for (int i = 0; i < n; ++i) {
    const FacetShape s = shapes[i % 4];
    const Vec3 o{u(rng), u(rng), u(rng)};
    const Vec3 e1{d(rng), d(rng), d(rng)}, e2{d(rng), d(rng), d(rng)}, bulge{d(rng), d(rng), d(rng)};
    const auto pts = test::place(s, [&](double xi, double eta) {
      const double q = contact::facet_is_quadratic(s) ? (1 - xi * xi) : 0.0;
      return Vec3{o[0] + xi * e1[0] + eta * e2[0] + q * bulge[0], o[1] + xi * e1[1] + eta * e2[1] + q * bulge[1],
                  o[2] + xi * e1[2] + eta * e2[2] + q * bulge[2]};
    });
    Facet f = test::make_facet(s, static_cast<std::int32_t>(c.x.size()));
    c.x.insert(c.x.end(), pts.begin(), pts.end());
    c.facets.push_back(f);
  }
  return c;
}

/// The enlarged control-point box test, done facet by facet.
std::vector<std::int32_t> brute_force(const Cloud& c, const Vec3& p, double h) {
  std::vector<std::int32_t> out;
  std::array<Vec3, 9> cp;
  for (std::size_t i = 0; i < c.facets.size(); ++i) {
    const int m = contact::facet_control_points(c.facets[i], c.x, cp);
    bool in = true;
    for (int k = 0; k < 3; ++k) {
      double lo = cp[0][k], hi = cp[0][k];
      for (int j = 1; j < m; ++j) lo = std::min(lo, cp[j][k]), hi = std::max(hi, cp[j][k]);
      in = in && p[k] >= lo - h && p[k] <= hi + h;
    }
    if (in) out.push_back(static_cast<std::int32_t>(i));
  }
  return out;
}

/// Distance from p to facet f; facets are less than 0.35 across, so one whose first node is
/// farther than 0.5 is reported as 1 without projecting (keeps the brute force fast).
double facet_distance(const Cloud& c, std::size_t f, const Vec3& p) {
  if (test::dist(c.x[static_cast<std::size_t>(c.facets[f].nodes[0])], p) > 0.5) return 1.0;
  return contact::project_to_facet(c.facets[f], c.x, p).distance;
}

}  // namespace

TEST(ContactSearch, RebuildRuleComparesDriftWithAFractionOfTheMargin) {
  EXPECT_FALSE(contact::search_needs_rebuild(0.0, 0.1, 0.5));
  EXPECT_FALSE(contact::search_needs_rebuild(0.05, 0.1, 0.5));
  EXPECT_TRUE(contact::search_needs_rebuild(0.0500001, 0.1, 0.5));
  EXPECT_TRUE(contact::search_needs_rebuild(1e-300, 0.0, 1.0));  // no margin: any motion
}

TEST(ContactSearch, TreeMatchesBruteForceOnARandomCloud) {
  const Cloud c = random_cloud(3000, 7);
  SearchOptions opt;
  opt.radius = 0.03;
  opt.margin = 0.01;
  FacetSearch s;
  s.build(c.facets, c.x, opt);
  EXPECT_EQ(s.n_facets(), c.facets.size());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 1.05);
  std::size_t total = 0;
  for (int q = 0; q < 200; ++q) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    std::vector<std::int32_t> got;
    s.query(p, got);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, brute_force(c, p, opt.radius + opt.margin)) << q;
    total += got.size();
    // Every facet within the radius is there; none of those returned is far.
    for (std::size_t f = 0; f < c.facets.size(); ++f) {
      const double dist = facet_distance(c, f, p);
      const bool found = std::binary_search(got.begin(), got.end(), static_cast<std::int32_t>(f));
      if (dist <= opt.radius) {
        EXPECT_TRUE(found) << q << " facet " << f;
      }
      // Facets are at most 0.04·(2+2+1)·√3 across; candidates lie within (r + m)√3 + that.
      if (found) {
        EXPECT_LE(dist, (opt.radius + opt.margin) * std::sqrt(3.0) + 0.35) << q << " facet " << f;
      }
    }
  }
  EXPECT_GT(total, 0u);
}

TEST(ContactSearch, MotionBelowTheMarginKeepsEveryCloseFacetAndLargerMotionAsksForARebuild) {
  Cloud c = random_cloud(2000, 3);
  SearchOptions opt;
  opt.radius = 0.02;
  opt.margin = 0.02;
  FacetSearch s;
  s.build(c.facets, c.x, opt);
  const Cloud built = c;
  // Move every node by less than margin/7 (Quad8 centre control point: Σ|coefficients| = 7,
  // so control points move by less than the margin).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  for (auto& p : c.x) {
    Vec3 v{d(rng), d(rng), d(rng)};
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k) p[k] += opt.margin / 7.5 * v[k] / l;
  }
  EXPECT_LE(s.drift(c.facets, c.x), opt.margin);
  EXPECT_FALSE(s.needs_rebuild(c.facets, c.x));
  std::uniform_real_distribution<double> u(0, 1);
  for (int q = 0; q < 150; ++q) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    std::vector<std::int32_t> got;
    s.query(p, got);
    std::sort(got.begin(), got.end());
    for (std::size_t f = 0; f < c.facets.size(); ++f) {
      if (facet_distance(c, f, p) <= opt.radius) {
        EXPECT_TRUE(std::binary_search(got.begin(), got.end(), static_cast<std::int32_t>(f))) << q << " " << f;
      }
    }
  }
  // A rigid translation by 1.5 × margin: drift = 1.5 margin → rebuild.
  c = built;
  for (auto& p : c.x) p[0] += 1.5 * opt.margin;
  EXPECT_NEAR(s.drift(c.facets, c.x), 1.5 * opt.margin, 1e-15);
  EXPECT_TRUE(s.needs_rebuild(c.facets, c.x));
  s.build(c.facets, c.x, opt);
  EXPECT_FALSE(s.needs_rebuild(c.facets, c.x));
}

TEST(ContactSearch, QuadraticFacetBoxContainsItsBulge) {
  // A Line3 from (−1, 0) to (1, 0) whose midside node sits at (0.8, 0.1): x(ξ) = ξ + 0.8 (1 − ξ²)
  // reaches 1.1125 at ξ = 0.625, beyond the nodes' own box. A point 0.04 beyond that bulge is
  // within the radius 0.05 and must be found (the control points' box contains the curve).
  const std::vector<Vec3> x = {{-1, 0, 0}, {1, 0, 0}, {0.8, 0.1, 0}};
  const std::vector<Facet> f{test::make_facet(FacetShape::Line3)};
  FacetSearch s;
  s.build(f, x, {0.05, 0.0, 1.0, 4});
  const Vec3 bulge = contact::facet_geometry(f[0], x, 0.625).x;
  ASSERT_NEAR(bulge[0], 1.1125, 1e-14);
  const Vec3 p{bulge[0] + 0.04, bulge[1], 0};
  ASSERT_LE(contact::project_to_facet(f[0], x, p).distance, 0.05);
  std::vector<std::int32_t> got;
  s.query(p, got);
  EXPECT_EQ(got.size(), 1u);
}
