// Surface-to-surface contact (contact/surface_to_surface.hpp): the weighting functions, and the
// contact patch test on offset meshes in 2D and 3D, where node to surface is 8 % off.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "contact/facet.hpp"
#include "contact/patch_test.hpp"
#include "contact/surface_to_surface.hpp"

namespace inpact::test {
namespace {

using contact::FacetShape;

/// ∫ W_a dξ over a flat facet's parametric domain, as a fraction of its area.
std::array<double, 8> weight_shares(FacetShape shape) {
  std::array<double, 8> share{};
  double area = 0.0;
  for (const auto& q : contact::facet_rule(shape, 4)) {
    const auto e = contact::eval_shape(shape, q.xi, q.eta);
    const auto w = contact::weighting_functions(shape, e.N);
    for (int a = 0; a < e.n; ++a) share[static_cast<std::size_t>(a)] += q.weight * w[static_cast<std::size_t>(a)];
    area += q.weight;
  }
  for (double& s : share) s /= area;
  return share;
}

TEST(SurfaceToSurfaceWeights, QuadraticFacesGetPositiveSharesThatSumToOne) {
  // Flat Quad8: consistent shares are −1/12 (corners) and 1/3 (midsides); with α = 1/5 they
  // become 1/20 and 1/5 (hand: −1/12 + 2α/3, (1 − 2α)/3).
  const auto q8 = weight_shares(FacetShape::Quad8);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(q8[static_cast<std::size_t>(a)], 1.0 / 20.0, 1e-13);
  for (int a = 4; a < 8; ++a) EXPECT_NEAR(q8[static_cast<std::size_t>(a)], 1.0 / 5.0, 1e-13);
  // Flat Tri6: 0 and 1/3 become 2/15 and 1/5.
  const auto t6 = weight_shares(FacetShape::Tri6);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(t6[static_cast<std::size_t>(a)], 2.0 / 15.0, 1e-13);
  for (int a = 3; a < 6; ++a) EXPECT_NEAR(t6[static_cast<std::size_t>(a)], 1.0 / 5.0, 1e-13);
  // First-order faces and Line3 keep N: Quad4 1/4 each, Line3 1/6, 1/6, 2/3.
  const auto q4 = weight_shares(FacetShape::Quad4);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(q4[static_cast<std::size_t>(a)], 0.25, 1e-13);
  const auto l3 = weight_shares(FacetShape::Line3);
  EXPECT_NEAR(l3[0], 1.0 / 6.0, 1e-13);
  EXPECT_NEAR(l3[2], 2.0 / 3.0, 1e-13);
}

TEST(SurfaceToSurfaceWeights, AreAPartitionOfUnityEverywhere) {
  for (FacetShape s : {FacetShape::Tri6, FacetShape::Quad8, FacetShape::Quad4, FacetShape::Line3})
    for (const auto& q : contact::facet_rule(s, 3)) {
      const auto e = contact::eval_shape(s, q.xi, q.eta);
      const auto w = contact::weighting_functions(s, e.N);
      EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-14);
    }
}

// Offset meshes (3 and 4 elements across, 3 × 3 and 4 × 4 in 3D): the master's shape functions
// kink inside the slave facets. Surface to surface transfers the consistent nodal forces of a
// uniform pressure; with the slave facets cut at the master's facet edges (mortar_segments.hpp)
// measured here: max |CPRESS − p|/p 2e-14 … 6e-10 (4.4e-4 … 8.8e-4 with a 6-point rule across
// the kinks), against 8 % for node to surface on the same 2D meshes (test_contact_analysis.cpp).
TEST(SurfaceToSurfacePatchTest, TwoDimensionalOffsetMeshesGiveUniformPressureForEveryMethod) {
  const double k = 10.0 * kM / kSlaveElementHeight;  // linear penalty: 10 k_e
  for (const char* m : {"direct", "penalty", "augmented", "nonlinear_penalty"}) {
    auto r = verification::run_deck(contact_deck(std::string("patch_2d_s2s_") + m + ".inp"));
    const auto fig = check_patch(*r, std::string("surface to surface, ") + m);
    EXPECT_LE(fig.max_cpress_error, 0.01) << m;  // the 1 % everywhere
    EXPECT_LE(fig.max_cpress_error, 1e-8) << m;  // what it does (see above; nonlinear: Newton's tolerance)
    const std::string method = m;
    if (method == "direct") {
      EXPECT_LE(std::max(std::abs(fig.max_penetration), std::abs(fig.min_penetration)), 1e-12);
    } else if (method == "penalty") {
      EXPECT_NEAR(fig.max_penetration, kP / k, 0.01 * kP / k);  // penetration = p / k
      EXPECT_NEAR(fig.min_penetration, kP / k, 0.01 * kP / k);
    } else if (method == "augmented") {
      // Finite-sliding surface to surface: default tolerance 5 % of the characteristic length
      // (0.5) [AX p.782]; k = 1000 penetrates p/k = 0.01 < 0.025, so no augmentation is needed.
      EXPECT_LE(fig.max_penetration, 0.05 * kSlaveFacet);
      EXPECT_EQ(fig.augmentations, 0);
    }
  }
}

TEST(SurfaceToSurfacePatchTest, ThreeDimensionalOffsetMeshesGiveUniformPressureForEveryMethod) {
  for (const char* m : {"direct", "penalty", "augmented", "nonlinear_penalty"}) {
    auto r = verification::run_deck(contact_deck(std::string("patch_3d_s2s_") + m + ".inp"));
    ASSERT_TRUE(r->outcome.completed) << m << ": " << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    const auto& cpress = contact_field(f, "CPRESS");
    const auto& copen = contact_field(f, "COPEN");
    const auto& cnarea = contact_field(f, "CNAREA");
    ASSERT_EQ(cpress.nodes.size(), 25u);  // 5 × 5 slave nodes
    double worst = 0.0, max_pen = 0.0, area = 0.0;
    for (std::size_t i = 0; i < cpress.values.size(); ++i) {
      worst = std::max(worst, std::abs(cpress.values[i] - kP) / kP);
      max_pen = std::max(max_pen, std::abs(copen.values[i]));
      area += cnarea.values[i];
    }
    EXPECT_LE(worst, 0.01) << m;
    EXPECT_LE(worst, 1e-8) << m;  // (nonlinear penalty: Newton's tolerance, 6e-10)
    EXPECT_NEAR(area, 4.0, 1e-9) << m;  // the nodal areas tile the 2 × 2 interface
    const auto rf = verification::sum_rf(*r, f);
    EXPECT_NEAR(rf[2], kP * 4.0, 1e-8 * kP * 4.0) << m;  // reactions balance p × 2 × 2
    if (std::string(m) == "direct") {
      EXPECT_LE(max_pen, 1e-9);
    } else if (std::string(m) == "penalty") {
      EXPECT_NEAR(max_pen, kP / (10.0 * kM / kSlaveElementHeight), 0.01 * max_pen);
    }
    std::printf("[contact] 3D surface to surface, %s: max |CPRESS - p|/p = %.3e, max |COPEN| = %.3e\n", m, worst,
                max_pen);
  }
}

// Second-order faces (CPE8, Line3 edges): node to surface on nested meshes (the slave nodes on
// the master's corner and midside nodes; HRZ nodal areas 1/6, 2/3, 1/6) and surface to surface
// on offset ones (3 and 4 elements across). Measured: exact (6e-14) and 1e-13 (4.0e-3 before the
// segment-based integration).
TEST(SecondOrderPatchTest, Cpe8FacesCarryTheUniformPressure) {
  for (const char* deck : {"patch_2d_cpe8_n2s_direct.inp", "patch_2d_cpe8_s2s_direct.inp"}) {
    auto r = verification::run_deck(contact_deck(deck));
    ASSERT_TRUE(r->outcome.completed) << deck << ": " << r->outcome.message;
    const auto& f = r->capture.last();
    const auto& cpress = contact_field(f, "CPRESS");
    const auto& copen = contact_field(f, "COPEN");
    ASSERT_EQ(cpress.values.size(), 9u);  // 4 Line3 edges: 5 corners + 4 midside nodes
    double worst = 0.0;
    for (std::size_t i = 0; i < cpress.values.size(); ++i) {
      worst = std::max(worst, std::abs(cpress.values[i] - kP) / kP);
      EXPECT_LE(std::abs(copen.values[i]), 1e-12) << deck;  // direct: no penetration
    }
    EXPECT_LE(worst, 1e-9) << deck;
    const auto rf = verification::sum_rf(*r, f);
    EXPECT_NEAR(rf[1], kP * kWidth, 1e-8 * kP * kWidth) << deck;
    std::printf("[contact] %s: max |CPRESS - p|/p = %.3e\n", deck, worst);
  }
}

// A coarse slave on a fine master (decks/contact/patch_*_coarse_*: 4 elements across below, 2
// above (nested) or 3 (not nested)), pair and general contact, 2D and 3D, direct and penalty:
// the slave facets are cut at the master's facet edges (contact/mortar_segments.hpp), so every
// integrand is a polynomial on its piece and is integrated exactly: every closed node (of the slave,
// or of both bodies with general contact's two balanced rows) carries p to round-off.
// Before the segmentation (a 6-point rule across the master's kinks): 2–6 % with general contact.
TEST(SurfaceToSurfacePatchTest, CoarseSlaveOnFineMasterCarriesTheUniformPressureAtEveryNode) {
  for (int dim : {2, 3})
    for (const char* nesting : {"nested", "offset"})
      for (const char* disc : {"s2s", "general"})
        for (const char* method : {"direct", "penalty"}) {
          const std::string deck = "patch_" + std::to_string(dim) + "d_coarse_" + nesting + "_" + disc + "_" + method + ".inp";
          auto r = verification::run_deck(contact_deck(deck));
          ASSERT_TRUE(r->outcome.completed) << deck << ": " << r->outcome.message;
          const solver::Frame& f = r->capture.last();
          const auto& cpress = contact_field(f, "CPRESS");
          const auto& copen = contact_field(f, "COPEN");
          const auto& cnarea = contact_field(f, "CNAREA");
          const bool general = std::string(disc) == "general", penalty = std::string(method) == "penalty";
          // closed nodes: the slave's (2 or 3 across); general penalty both bodies' (+ 4 across);
          // general direct one row, the finer lower block the slave
          const int n_upper = std::string(nesting) == "nested" ? 2 : 3;
          auto across = [&](int n) { return dim == 2 ? n + 1 : (n + 1) * (n + 1); };
          const int expected = !general ? across(n_upper) : penalty ? across(n_upper) + across(4) : across(4);
          int closed = 0;
          double worst = 0.0, area = 0.0, max_pen = 0.0, min_pen = 1e300;
          for (std::size_t i = 0; i < cpress.values.size(); ++i) {
            if (cpress.values[i] <= 0.0) continue;
            ++closed;
            worst = std::max(worst, std::abs(cpress.values[i] - kP) / kP);
            area += cnarea.values[i];
            max_pen = std::max(max_pen, -copen.values[i]);
            min_pen = std::min(min_pen, -copen.values[i]);
          }
          const double interface = dim == 2 ? kWidth : kWidth * kWidth;
          EXPECT_EQ(closed, expected) << deck;
          EXPECT_LE(worst, 1e-9) << deck;
          EXPECT_NEAR(area, interface, 1e-9 * interface) << deck;
          const auto rf = verification::sum_rf(*r, f);
          EXPECT_NEAR(rf[static_cast<std::size_t>(dim - 1)], kP * interface, 1e-8 * kP * interface) << deck;
          const double k = 10.0 * kM / kSlaveElementHeight;  // both blocks: k_e = M / 0.5
          if (penalty && !general) {
            EXPECT_NEAR(max_pen, kP / k, 1e-9 * kP / k) << deck;
            EXPECT_NEAR(min_pen, kP / k, 1e-9 * kP / k) << deck;
          } else if (penalty) {  // k_e: the median over every exterior facet (the sides too)
            EXPECT_NEAR(max_pen, min_pen, 1e-9 * max_pen) << deck;
          } else {
            EXPECT_LE(std::max(std::abs(max_pen), std::abs(min_pen)), 1e-12) << deck;
          }
          std::printf("[contact] %s: max |CPRESS - p|/p = %.3e over %d nodes\n", deck.c_str(), worst, closed);
        }
}

}  // namespace
}  // namespace inpact::test
