#pragma once
// Helpers of the contact verification tests: run a deck of decks/contact_verification/ with
// *PARAMETER overrides (the enforcement method, its scale factor and tolerance), keep its frames,
// and reduce the last frame to the figures the analytic references speak about. The references
// (Johnson §4.2 for Hertz, Lamé for the interference fit and the spherical seat) are here; the tolerances are at the
// assertions (shared/STYLE.md §11). bench/contact_trade/figures.py computes the same figures from
// a results file.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include "verification/verification_fixture.hpp"

namespace inpact::contact_verification {

using verification::Capture;

// The decks' data (gen_contact_verification.py): one material, E* = E / (2 (1 − ν²)).
constexpr double kE = 210000.0, kNu = 0.3;
constexpr double kEStar = kE / (2.0 * (1.0 - kNu * kNu));
constexpr double kRadius = 20.0;  // Hertz: cylinder and sphere
constexpr double kRingA = 0.5, kRingB = 1.0, kRingC = 2.0, kDelta = 0.01;

/// Lamé interference-fit pressure, same material, plane strain (E' = E/(1−ν²)); b taken at the
/// middle of the overlap: p = E' δ (c² − b²)(b² − a²) / (2 b³ (c² − a²)).
inline double lame_pressure() {
  const double ep = kE / (1.0 - kNu * kNu), a = kRingA, b = kRingB + 0.5 * kDelta, c = kRingC;
  return ep * kDelta * (c * c - b * b) * (b * b - a * a) / (2.0 * b * b * b * (c * c - a * a));
}

// The smoothing decks (issue 5): a ball of radius b + δ in a socket b ≤ r ≤ c; an O-ring of tube
// radius ρ + δ about the circle of radius R (about the y axis) in a sleeve ρ ≤ s ≤ ρ_out.
constexpr double kSeatB = 1.0, kSeatC = 2.0, kSeatDelta = 0.01;
constexpr double kTorusR = 4.0, kTorusRho = 1.0, kTorusDelta = 0.01;

/// Radial displacement of the socket's inner surface r = b under an internal pressure p: the
/// thick-walled sphere (Lamé), u(r) = p b³/(E (c³ − b³)) [(1 − 2ν) r + (1 + ν) c³/(2 r²)].
inline double seat_socket_displacement(double p) {
  const double b = kSeatB, c = kSeatC, b3 = b * b * b, c3 = c * c * c;
  return p * b3 / (kE * (c3 - b3)) * ((1.0 - 2.0 * kNu) * b + (1.0 + kNu) * c3 / (2.0 * b * b));
}

/// The spherical seat's contact pressure, same material, linear elasticity on the undeformed
/// geometry: the interference is taken up by the socket at r = b and the ball (under an external
/// pressure p, u(r) = −p (1 − 2ν) r / E) at r = b + δ:
///   δ = u_socket(b) + p (1 − 2ν)(b + δ) / E.
/// (Evaluating both at the middle of the overlap, as lame_pressure() does for the rings, gives
/// p = 2 E δ (c³ − b³) / (3 (1 − ν) b c³) at b + δ/2: 0.38 % lower.)
inline double seat_pressure() {
  const double per_unit_p = seat_socket_displacement(1.0) + (1.0 - 2.0 * kNu) * (kSeatB + kSeatDelta) / kE;
  return kSeatDelta / per_unit_p;
}

inline std::string deck_path(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/decks/contact_verification/" + name + ".inp";
}

/// The deck `name` at mesh `level`: the committed one for level 1, else generated into the
/// temporary folder (one per test process) by gen_contact_verification.py.
inline std::string deck_at_level(const std::string& name, int level) {
  if (level == 1) return deck_path(name);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("inpact-contact-verification-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string cmd = "python3 " + std::string(INPACT_SOURCE_DIR) +
                          "/decks/contact_verification/gen_contact_verification.py --out " + dir.string() +
                          " --level " + std::to_string(level) + " " + name;
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return (dir / (name + "_l" + std::to_string(level) + ".inp")).string();
}

struct Run {
  parser::ReadResult deck;
  Capture capture;
  solver::AnalysisOutcome outcome;
  double seconds = 0.0;
  int iterations = 0, augmentations = 0, severe = 0;
};

/// Reads `path` with the *PARAMETER overrides `params` and runs it.
inline std::unique_ptr<Run> run(const std::string& path, const std::map<std::string, std::string>& params = {}) {
  auto r = std::make_unique<Run>();
  parser::ReadOptions options;
  options.parameters = params;
  r->deck = parser::read_deck(path, options);
  EXPECT_TRUE(r->deck.ok()) << r->deck.report();
  if (!r->deck.ok()) return r;
  const auto t0 = std::chrono::steady_clock::now();
  r->outcome = solver::run_analysis(r->deck.model, r->capture);
  r->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& row : r->capture.rows) {
    r->iterations += row.total_iters;
    r->augmentations += row.augmentations;
    r->severe += row.severe_discon_iters;
  }
  return r;
}

/// The contact fields of one frame, one entry per slave node, with its reference position.
struct SlaveValues {
  std::vector<std::int64_t> rows;
  std::vector<std::array<double, 3>> x;
  std::vector<double> cpress, copen, cnarea;
};

inline SlaveValues slave_values(const Run& r, const solver::Frame& f) {
  SlaveValues s;
  const auto* cp = verification::field(f, "CPRESS");
  const auto* co = verification::field(f, "COPEN");
  const auto* ca = verification::field(f, "CNAREA");
  if (!cp || !co || !ca) {
    ADD_FAILURE() << "the frame lacks CPRESS, COPEN or CNAREA";
    return s;
  }
  s.rows = cp->nodes;
  s.cpress = cp->values;
  s.copen = co->values;
  s.cnarea = ca->values;
  for (auto row : s.rows) s.x.push_back(verification::coords(r.deck.model, static_cast<std::int32_t>(row)));
  return s;
}

/// What a Hertz run gives and what Johnson §4.2 says for the load it carried.
struct HertzFigures {
  double load = 0.0;      ///< P: per unit length (2-D, both halves) or total (3-D, four quarters)
  double a_ref = 0.0, p0_ref = 0.0;
  double p0 = 0.0;        ///< CPRESS at the slave node on the axis (r = 0)
  double p_max = 0.0;     ///< largest CPRESS
  double a_closed = 0.0;  ///< r of the outermost closed slave node
  double a_open = 0.0;    ///< r of the first open slave node beyond it
  double a_fe = 0.0;      ///< the contact size estimate: (a_closed + a_open) / 2
  double h = 0.0;         ///< slave element size at the contact (the first node spacing)
  double max_penetration = 0.0;
  double balance = 0.0;   ///< |Σ RF (top) + Σ RF (bottom)| / P: the load goes through the contact
};

/// dim 2: line contact, a = √(4PR/(πE*)), p0 = √(PE*/(πR)), P = 2 × the half model's reaction;
/// dim 3: sphere, a = (3PR/(4E*))^(1/3), p0 = 3P/(2πa²), P = 4 × the quarter model's.
inline HertzFigures hertz_figures(const Run& r, int dim) {
  HertzFigures h;
  const solver::Frame& f = r.capture.last();
  const auto& m = r.deck.model;
  double top = 0.0, bottom = 0.0;
  for (auto row : verification::nset(m, "INDENTER_TOP")) top += verification::nodal(f, "RF", row, dim - 1);
  for (auto row : verification::nset(m, "BLOCK_BOTTOM")) bottom += verification::nodal(f, "RF", row, dim - 1);
  const double model_load = -top;  // the indenter is pushed down: its top's reaction points up
  h.balance = std::abs(top + bottom) / std::abs(model_load);
  if (dim == 2) {
    h.load = 2.0 * model_load;
    h.a_ref = std::sqrt(4.0 * h.load * kRadius / (std::numbers::pi * kEStar));
    h.p0_ref = std::sqrt(h.load * kEStar / (std::numbers::pi * kRadius));
  } else {
    h.load = 4.0 * model_load;
    h.a_ref = std::cbrt(3.0 * h.load * kRadius / (4.0 * kEStar));
    h.p0_ref = 3.0 * h.load / (2.0 * std::numbers::pi * h.a_ref * h.a_ref);
  }
  const SlaveValues s = slave_values(r, f);
  std::vector<double> radius;
  for (const auto& x : s.x) radius.push_back(dim == 2 ? std::abs(x[0]) : std::hypot(x[0], x[1]));
  double r_min = 1e300, second = 1e300;
  for (std::size_t i = 0; i < radius.size(); ++i) {
    if (radius[i] < r_min) {
      r_min = radius[i];
      h.p0 = s.cpress[i];
    }
    h.p_max = std::max(h.p_max, s.cpress[i]);
    if (s.cpress[i] > 0.0) {
      h.a_closed = std::max(h.a_closed, radius[i]);
      h.max_penetration = std::max(h.max_penetration, -s.copen[i]);
    }
  }
  for (double rr : radius)
    if (rr > r_min + 1e-12) second = std::min(second, rr);
  h.h = second - r_min;
  h.a_open = 1e300;
  for (std::size_t i = 0; i < radius.size(); ++i)
    if (s.cpress[i] <= 0.0 && radius[i] > h.a_closed) h.a_open = std::min(h.a_open, radius[i]);
  h.a_fe = 0.5 * (h.a_closed + h.a_open);
  return h;
}

/// The interference fit's contact pressure against Lamé.
struct FitFigures {
  double p_ref = 0.0;
  double p_mean = 0.0;  ///< Σ CPRESS·CNAREA / Σ CNAREA (the contact force over the closed area)
  double p_max = 0.0, p_min = 1e300;
  std::size_t n_closed = 0, n_slave = 0;
  double max_penetration = 0.0;
};

inline FitFigures fit_figures(const Run& r, const solver::Frame& f) {
  FitFigures fit;
  fit.p_ref = lame_pressure();
  const SlaveValues s = slave_values(r, f);
  double force = 0.0, area = 0.0;
  for (std::size_t i = 0; i < s.cpress.size(); ++i) {
    force += s.cpress[i] * s.cnarea[i];
    area += s.cnarea[i];
    fit.p_max = std::max(fit.p_max, s.cpress[i]);
    fit.p_min = std::min(fit.p_min, s.cpress[i]);
    if (s.cpress[i] > 0.0) {
      ++fit.n_closed;
      fit.max_penetration = std::max(fit.max_penetration, -s.copen[i]);
    }
  }
  fit.n_slave = s.cpress.size();
  fit.p_mean = area > 0 ? force / area : 0.0;
  return fit;
}

/// "[contact-verification] name = value", greppable like the verification suite's lines.
inline void report(const std::string& name, double value) {
  std::printf("[contact-verification] %-64s = %.6e\n", name.c_str(), value);
  ::testing::Test::RecordProperty(name, std::to_string(value));
}

}  // namespace inpact::contact_verification
