#pragma once
// The contact patch test of decks/contact/patch_2d_*.inp (gen_contact_decks.py) and its checks,
// shared by the node-to-surface and surface-to-surface analyses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "verification/verification_fixture.hpp"

namespace inpact::test {

using verification::Run;

/// The whole text of file `path`.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string contact_deck(const std::string& name) { return std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + name; }

inline const solver::FieldData& contact_field(const solver::Frame& f, const std::string& key) {
  const auto* fd = verification::field(f, key);
  if (!fd) throw std::runtime_error("frame has no field " + key);
  return *fd;
}

/// The patch-test reference: p = 10 on a 2 × 1 (unit thickness) top, uniaxial strain.
constexpr double kP = 10.0, kWidth = 2.0;
constexpr double kE = 1000.0, kNu = 0.3;
constexpr double kM = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));  // constrained modulus
constexpr double kSlaveElementHeight = 0.5, kSlaveFacet = 0.5;

struct PatchFigures {
  double max_cpress_error = 0.0;   ///< max |CPRESS − p| / p
  double max_penetration = 0.0;    ///< max −COPEN over closed nodes
  double min_penetration = 1e300;
  int augmentations = 0, severe = 0, iterations = 0;
};

inline PatchFigures check_patch(const Run& r, const std::string& label) {
  EXPECT_TRUE(r.outcome.completed) << r.outcome.message;
  PatchFigures fig;
  if (r.capture.frames.empty()) return fig;
  const solver::Frame& f = r.capture.last();
  const auto& cpress = contact_field(f, "CPRESS");
  const auto& copen = contact_field(f, "COPEN");
  const auto& cstatus = contact_field(f, "CSTATUS");
  const auto& cfn = contact_field(f, "CFN");
  EXPECT_EQ(cpress.nodes.size(), 5u);  // slave nodes of the 4-element edge
  EXPECT_EQ(cpress.pair.size(), cpress.nodes.size());
  double sum_cfn_y = 0.0;
  for (std::size_t i = 0; i < cpress.nodes.size(); ++i) {
    fig.max_cpress_error = std::max(fig.max_cpress_error, std::abs(cpress.values[i] - kP) / kP);
    fig.max_penetration = std::max(fig.max_penetration, -copen.values[i]);
    fig.min_penetration = std::min(fig.min_penetration, -copen.values[i]);
    EXPECT_EQ(cstatus.values[i], 2.0) << "closed, frictionless: slipping";
    sum_cfn_y += cfn.values[i * 3 + 1];
  }
  // Reactions balance the applied load to round-off: Σ RF_y = p · width; Σ RF_x = 0.
  const auto rf = verification::sum_rf(r, f);
  EXPECT_NEAR(rf[1], kP * kWidth, 1e-8 * kP * kWidth) << label;
  EXPECT_NEAR(rf[0], 0.0, 1e-8 * kP * kWidth) << label;
  // The normal contact forces on the slave carry the whole load.
  EXPECT_NEAR(sum_cfn_y, kP * kWidth, 1e-6 * kP * kWidth) << label;
  for (const auto& row : r.capture.rows) {
    fig.augmentations += row.augmentations;
    fig.severe += row.severe_discon_iters;
    fig.iterations += row.total_iters;
  }
  std::printf("[contact] %s: max |CPRESS - p|/p = %.3e, penetration %.3e .. %.3e, iterations %d (severe %d), "
              "augmentations %d\n", label.c_str(), fig.max_cpress_error, fig.min_penetration, fig.max_penetration,
              fig.iterations, fig.severe, fig.augmentations);
  return fig;
}

}  // namespace inpact::test
