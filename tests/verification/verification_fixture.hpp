#pragma once
// Shared helpers of the verification suite: read a deck, run it, keep every frame, and look up
// nodal and integration-point values by position. Each test states its analytic reference and
// tolerance next to the assertion (shared/STYLE.md §11).
#include <gtest/gtest.h>
#include <unistd.h>

#include "contact/initial_adjustment.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/element_types.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis.hpp"
#include "solver/elements/element_kernel.hpp"

namespace inpact::verification {

inline std::string deck_path(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/decks/verification/" + name;
}

/// A verification deck with its lines edited (each line replaced by the lines `edit` returns),
/// written to the temporary folder under `tag`; the caller removes it.
inline std::filesystem::path edited_deck(const std::string& name, const std::string& tag,
                                         const std::function<std::vector<std::string>(const std::string&)>& edit) {
  std::ifstream in(deck_path(name));
  const auto path = std::filesystem::temp_directory_path() / ("inpact-" + tag + "-" + std::to_string(::getpid()) + ".inp");
  std::ofstream out(path);
  for (std::string line; std::getline(in, line);)
    for (const std::string& l : edit(line)) out << l << "\n";
  return path;
}

/// Where decks generated at test time go: the test's working directory (ctest runs it in the
/// build tree).
inline std::filesystem::path generated_dir() {
  auto dir = std::filesystem::current_path() / "verification_decks";
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs decks/verification/gen_verification.py with `args`; fails the test when it fails.
inline void generate(const std::string& args) {
  const std::string cmd = "python3 " + deck_path("gen_verification.py") + " --out " + generated_dir().string() + " " + args;
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

/// Observer keeping every frame, the status rows and the messages.
struct Capture : solver::AnalysisObserver {
  struct StepFrame {
    int step;
    solver::Frame frame;
  };
  std::vector<StepFrame> frames;
  std::vector<solver::StatusRow> rows;
  std::vector<std::string> messages;
  std::vector<solver::PrintFrame> prints;  ///< the printed output (*NODE / *EL / *CONTACT PRINT)
  int current_step = 0;
  int iterations = 0;  ///< Newton iterations over the run (equilibrium iterations of converged attempts + failed)

  void step_started(const model::Step&, int n) override { current_step = n; }
  void attempt_finished(const solver::StatusRow& row) override {
    rows.push_back(row);
    iterations += row.total_iters;
  }
  void frame(const solver::Frame& f) override { frames.push_back({current_step, f}); }
  void message(std::string_view text) override { messages.emplace_back(text); }
  void print_frame(const solver::PrintFrame& p) override { prints.push_back(p); }

  const solver::Frame& last() const { return frames.back().frame; }
  /// Frames of step `step` (1-based).
  std::vector<const solver::Frame*> of_step(int step) const {
    std::vector<const solver::Frame*> out;
    for (const auto& f : frames)
      if (f.step == step) out.push_back(&f.frame);
    return out;
  }
};

/// A deck read, analysed and captured.
struct Run {
  parser::ReadResult deck;
  Capture capture;
  solver::AnalysisOutcome outcome;
  double seconds = 0.0;

  const model::Model& model() const { return deck.model; }
  int dim() const {
    return model::element_type(deck.model.mesh.elements.type[0]).dim;
  }
};

inline std::unique_ptr<Run> run_deck(const std::string& path) {
  auto r = std::make_unique<Run>();
  r->deck = parser::read_deck(path);
  EXPECT_TRUE(r->deck.ok()) << r->deck.report();
  contact::apply_adjust(r->deck.model);  // as `inpact run` does after reading
  const auto t0 = std::chrono::steady_clock::now();
  r->outcome = solver::run_analysis(r->deck.model, r->capture);
  r->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

/// What a run of the deck at `path` stops with: "completed", the outcome's message, or the deck
/// error the analysis throws (for tests of refusals); the deck file is removed afterwards.
/// The last "displacements (vx,vy,vz) for set `set`" table of a CalculiX .dat: label → u (empty
/// when the file or the table is missing).
inline std::map<std::int64_t, std::array<double, 3>> ccx_displacements(const std::string& path, const std::string& set) {
  std::map<std::int64_t, std::array<double, 3>> u;
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (!f) return u;
  char line[512];
  bool in_table = false;
  const std::string header = "displacements (vx,vy,vz) for set " + set + " ";
  while (std::fgets(line, sizeof line, f)) {
    if (std::string(line).find(header) != std::string::npos) {
      u.clear();
      in_table = true;
      continue;
    }
    long long label = 0;
    double v[3];
    if (in_table && std::sscanf(line, "%lld %lf %lf %lf", &label, &v[0], &v[1], &v[2]) == 4)
      u[label] = {v[0], v[1], v[2]};
    else if (in_table && !u.empty())
      in_table = false;
  }
  std::fclose(f);
  return u;
}

inline std::string stop_message(const std::filesystem::path& path) {
  std::string message;
  try {
    const auto r = run_deck(path.string());
    message = r->outcome.completed ? "completed" : r->outcome.message;
  } catch (const std::exception& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

inline const solver::FieldData* field(const solver::Frame& f, const std::string& key) {
  for (const auto& fd : f.fields)
    if (fd.key == key) return &fd;
  return nullptr;
}

/// Value of nodal field `key` (component c, 0-based) at node row `row`.
inline double nodal(const solver::Frame& f, const std::string& key, std::size_t row, int c) {
  const auto* fd = field(f, key);
  if (!fd) throw std::runtime_error("frame has no field " + key);
  const std::size_t ncomp = fd->component_labels.size();
  std::size_t loc = row;
  if (!fd->nodes.empty()) {
    auto it = std::find(fd->nodes.begin(), fd->nodes.end(), static_cast<std::int64_t>(row));
    if (it == fd->nodes.end()) throw std::runtime_error("node row not in field " + key);
    loc = static_cast<std::size_t>(it - fd->nodes.begin());
  }
  return fd->values[loc * ncomp + c];
}

/// Node rows of the named node set.
inline std::vector<std::int32_t> nset(const model::Model& m, const std::string& name) {
  return m.mesh.nsets.at(name).rows;
}

inline std::array<double, 3> coords(const model::Model& m, std::int32_t row) {
  const auto& x = m.mesh.nodes.coords[row];
  return {x[0], x[1], x[2]};
}

/// Σ RF over every node, per direction.
inline std::array<double, 3> sum_rf(const Run& r, const solver::Frame& f) {
  std::array<double, 3> s{0, 0, 0};
  const int dim = r.dim();
  for (std::size_t n = 0; n < r.model().mesh.nodes.size(); ++n)
    for (int c = 0; c < dim; ++c) s[c] += nodal(f, "RF", n, c);
  return s;
}

/// Σ |RF| over every node, for the scale of the balance check.
inline double sum_abs_rf(const Run& r, const solver::Frame& f) {
  double s = 0;
  for (std::size_t n = 0; n < r.model().mesh.nodes.size(); ++n)
    for (int c = 0; c < r.dim(); ++c) s += std::abs(nodal(f, "RF", n, c));
  return s;
}

/// Integration-point stress/strain with the point's reference coordinates (from the element
/// kernel: the frame gives element label and point number only).
struct PointValue {
  std::int64_t element;
  int ip;
  std::array<double, 3> x{};  ///< the point's reference coordinates (0 for a shell's or beam's)
  std::vector<double> s;  ///< components as in the frame (4 in 2D, 6 in 3D)
};

inline std::vector<PointValue> point_values(const Run& r, const solver::Frame& f, const std::string& key = "S") {
  const auto& mesh = r.model().mesh;
  const auto* fd = field(f, key);
  if (!fd) throw std::runtime_error("frame has no field " + key);
  const std::size_t ncomp = fd->component_labels.size();
  // Coordinates of each element's points, by element label.
  std::map<std::int64_t, std::vector<solver::elements::Vec3>> pts;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& type = model::element_type(mesh.elements.type[e]);
    if (!model::is_continuum(type)) continue;  // shells, beams: x stays 0
    std::vector<solver::elements::Vec3> x;
    for (std::int32_t n : mesh.elements.nodes_of(e)) {
      const auto& c = mesh.nodes.coords[n];
      x.push_back({c[0], c[1], c[2]});
    }
    std::vector<double> u(static_cast<std::size_t>(type.n_nodes) * type.dim, 0.0);
    solver::elements::ElasticConstants mat{1.0, 0.0, 0.0};
    solver::elements::ElementRequest req;
    req.stiffness = false;
    req.point_output = true;
    const auto sys = solver::elements::compute_element(type, x, u, mat, {}, req);
    auto& v = pts[mesh.elements.labels[e]];
    for (const auto& p : sys.points) v.push_back(p.coords);
  }
  std::vector<PointValue> out;
  for (std::size_t i = 0; i < fd->elements.size(); ++i) {
    PointValue p;
    p.element = fd->elements[i];
    p.ip = fd->ip[i];
    if (const auto at = pts.find(p.element); at != pts.end()) {
      const auto& c = at->second.at(static_cast<std::size_t>(p.ip - 1));
      p.x = {c[0], c[1], c[2]};
    }
    p.s.assign(fd->values.begin() + static_cast<std::ptrdiff_t>(i * ncomp),
               fd->values.begin() + static_cast<std::ptrdiff_t>((i + 1) * ncomp));
    out.push_back(std::move(p));
  }
  return out;
}

/// Largest |component| of a point field.
inline double max_abs(const std::vector<PointValue>& v) {
  double m = 0;
  for (const auto& p : v)
    for (double s : p.s) m = std::max(m, std::abs(s));
  return m;
}

/// Prints one measured figure in a greppable form: "[verification] name = value".
inline void report(const std::string& name, double value) {
  std::printf("[verification] %-58s = %.6e\n", name.c_str(), value);
  ::testing::Test::RecordProperty(name, std::to_string(value));
}

/// Checks Σ RF + Σ applied = 0 per direction (case 5 of the suite): |imbalance| ≤ tol × scale,
/// scale = Σ|applied| + Σ|RF| (the forces that must cancel). Reports the worst relative imbalance.
inline double expect_balance(const Run& r, const solver::Frame& f, std::array<double, 3> applied, double tol,
                             const std::string& what, std::array<bool, 3> check = {true, true, true}) {
  const auto rf = sum_rf(r, f);
  const double scale = std::abs(applied[0]) + std::abs(applied[1]) + std::abs(applied[2]) + sum_abs_rf(r, f);
  double worst = 0;
  for (int c = 0; c < r.dim(); ++c) {
    if (!check[c]) continue;
    const double imbalance = rf[c] + applied[c];
    worst = std::max(worst, std::abs(imbalance) / scale);
    EXPECT_LE(std::abs(imbalance), tol * scale)
        << what << ": direction " << c + 1 << ": sum RF = " << rf[c] << ", applied = " << applied[c];
  }
  report(what + ": |sum RF + sum F| / scale", worst);
  return worst;
}

/// Least-squares slope of log(e) against log(h).
inline double loglog_slope(const std::vector<double>& h, const std::vector<double>& e) {
  const std::size_t n = h.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = std::log(h[i]), y = std::log(e[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace inpact::verification
