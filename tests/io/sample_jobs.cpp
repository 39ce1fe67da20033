#include "sample_jobs.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include <fmt/format.h>

namespace inpact::test {

namespace {

// Slave nodes of the three-body contact pair: labels 10, 12, 13, 15 (rows 9, 11, 12, 14).
constexpr std::array<std::int64_t, 4> kSlaveRows = {9, 11, 12, 14};

io::FieldData field(std::string key, io::Position position, std::vector<std::string> labels,
                    std::string region = "") {
  io::FieldData f;
  f.key = std::move(key);
  f.position = position;
  f.component_labels = std::move(labels);
  f.region = std::move(region);
  return f;
}


}  // namespace

io::StatusRow status_row(int inc, int att, bool cut, int severe, int equil, double time, double dt, int aug) {
  io::StatusRow r;
  r.step = 1;
  r.increment = inc;
  r.attempt = att;
  r.cut_back = cut;
  r.severe_discon_iters = severe;
  r.equil_iters = equil;
  r.total_iters = severe + equil;
  r.total_time = r.step_time = time;
  r.inc_of_time = dt;
  r.augmentations = aug;
  return r;
}

double u_value(int k, std::size_t n, int c) { return 0.001 * (k + 1) * static_cast<double>(n + 1) + 0.1 * c; }
double rf_value(int k, std::size_t n, int c) { return -(k + 1.0) * static_cast<double>(n + 1) - 10.0 * c; }
double s_value(int k, std::size_t loc, int c) { return 100.0 * k + 10.0 * c + static_cast<double>(loc); }
double cpress_value(int k, std::size_t j) { return 1000.0 * (k + 1) + static_cast<double>(j); }

io::Frame three_body_frame(const model::Model& model, int k) {
  static constexpr double kStepTime[] = {0.5, 1.0, 1.0, 2.0};
  static constexpr double kTotalTime[] = {0.5, 1.0, 2.0, 3.0};
  io::Frame f;
  f.step_time = kStepTime[k];
  f.total_time = kTotalTime[k];
  f.increment = k % 2 + 1;

  io::FieldData u = field("U", io::Position::Nodal, {"U1", "U2", "U3"});
  for (std::size_t n = 0; n < model.mesh.nodes.size(); ++n)
    for (int c = 0; c < 3; ++c) u.values.push_back(u_value(k, n, c));
  f.fields.push_back(u);

  if (k != 3) {  // frame 3 has no RF: its row must read NaN
    io::FieldData rf = field("RF", io::Position::Nodal, {"RF1", "RF2", "RF3"}, "ALL_N");
    rf.nodes = {0, 1, 2, 3};
    for (std::size_t n = 0; n < 4; ++n)
      for (int c = 0; c < 3; ++c) rf.values.push_back(rf_value(k, n, c));
    f.fields.push_back(rf);
  }

  // S at integration points: cube (label 1) 8 points, tet (2) 1, wedge (7) 2.
  io::FieldData s = field("S", io::Position::IntegrationPoint, {"S11", "S22", "S33", "S12", "S13", "S23"});
  const std::array<std::pair<std::int64_t, int>, 3> elements = {{{1, 8}, {2, 1}, {7, 2}}};
  for (const auto& [label, n_ip] : elements)
    for (int ip = 1; ip <= n_ip; ++ip) {
      s.elements.push_back(label);
      s.ip.push_back(ip);
    }
  for (std::size_t i = 0; i < s.elements.size(); ++i)
    for (int c = 0; c < 6; ++c) s.values.push_back(s_value(k, i, c));
  f.fields.push_back(s);

  io::FieldData cp = field("CPRESS", io::Position::Nodal, {"CPRESS"}, "SLAVE_S/MASTER_S");
  for (std::size_t j = 0; j < kSlaveRows.size(); ++j) {
    cp.nodes.push_back(kSlaveRows[j]);
    cp.pair.push_back(0);
    cp.values.push_back(cpress_value(k, j));
  }
  f.fields.push_back(cp);
  return f;
}

void write_three_body_job(const std::filesystem::path& h5, const model::Model& model) {
  auto w = io::ResultsWriter::create(h5, model, std::string(64, 'a'), "0.1.0-test");
  for (int step = 0; step < 2; ++step) {
    w.begin_step(model.steps.at(static_cast<std::size_t>(step)));
    for (int k = 2 * step; k < 2 * step + 2; ++k) w.write_frame(three_body_frame(model, k));
  }
  const std::vector<io::StatusRow> rows = {status_row(1, 1, true, 12, 0, 0.0, 1.0, 0),
                                           status_row(1, 2, false, 2, 3, 0.5, 0.5, 1),
                                           status_row(2, 1, false, 0, 2, 1.0, 0.5, 2)};

  w.append_status(rows);
  w.finish(io::RunStatus::Completed);
}

std::string all_types_deck(const std::vector<std::string>& only) {
  using P = std::array<double, 3>;
  struct Elem {
    const char* type;
    std::vector<P> corners;
    std::vector<std::array<int, 2>> mid_edges;  // 1-based corner pairs, in Abaqus midside order
  };
  const std::vector<P> hex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<P> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<P> wedge = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  const std::vector<P> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<P> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Elem> elems = {
      {"C3D8", hex, {}},
      {"C3D20", hex, {{1, 2}, {2, 3}, {3, 4}, {4, 1}, {5, 6}, {6, 7}, {7, 8}, {8, 5}, {1, 5}, {2, 6}, {3, 7}, {4, 8}}},
      {"C3D4", tet, {}},
      {"C3D10", tet, {{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 4}, {3, 4}}},
      {"C3D6", wedge, {}},
      {"CPS4", quad, {}},
      {"CPS8", quad, {{1, 2}, {2, 3}, {3, 4}, {4, 1}}},
      {"CPS3", tri, {}},
      {"CPS6", tri, {{1, 2}, {2, 3}, {3, 1}}},
  };
  if (!only.empty())
    std::erase_if(elems, [&](const Elem& e) { return std::find(only.begin(), only.end(), e.type) == only.end(); });
  std::string nodes = "*NODE, NSET=ALL_N\n", elements;
  int node = 0;
  for (std::size_t e = 0; e < elems.size(); ++e) {
    const double dx = 2.0 * static_cast<double>(e);
    std::vector<P> pts = elems[e].corners;
    for (const auto& [a, b] : elems[e].mid_edges) {
      const P& p = elems[e].corners[static_cast<std::size_t>(a - 1)];
      const P& q = elems[e].corners[static_cast<std::size_t>(b - 1)];
      pts.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    }
    std::string conn;
    for (const P& p : pts) {
      ++node;
      nodes += fmt::format("{}, {}, {}, {}\n", node, p[0] + dx, p[1], p[2]);
      conn += fmt::format(", {}", node);
    }
    elements += fmt::format("*ELEMENT, TYPE={}, ELSET=E{}\n{}{}\n", elems[e].type, e + 1, e + 1, conn);
  }
  std::string deck = "*HEADING\none element of each type\n" + nodes + elements + "*ELSET, ELSET=ALL_E\n";
  for (std::size_t e = 0; e < elems.size(); ++e) deck += fmt::format("E{}\n", e + 1);
  deck += "*SOLID SECTION, ELSET=ALL_E, MATERIAL=STEEL\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
          "*STEP, NAME=Step-1\n*STATIC\n0.5, 1.0\n*END STEP\n";
  return deck;
}

void write_all_types_job(const std::filesystem::path& h5, const model::Model& model) {
  auto w = io::ResultsWriter::create(h5, model, std::string(64, 'b'), "0.1.0-test");
  w.begin_step(model.steps.at(0));
  for (int k = 0; k < 2; ++k) {
    io::Frame f;
    f.step_time = f.total_time = 0.5 * (k + 1);
    f.increment = k + 1;
    io::FieldData u = field("U", io::Position::Nodal, {"U1", "U2", "U3"});
    for (const auto& x : model.mesh.nodes.coords)
      for (int c = 0; c < 3; ++c) u.values.push_back(0.01 * (k + 1) * x[static_cast<std::size_t>(c)]);
    io::FieldData s = field("S", io::Position::Centroid, {"S11", "S22", "S33", "S12", "S13", "S23"});
    for (std::size_t e = 0; e < model.mesh.elements.size(); ++e) {
      s.elements.push_back(model.mesh.elements.labels[e]);
      const double s11 = static_cast<double>(e + 1) * (k + 1);
      s.values.insert(s.values.end(), {s11, 0.0, 0.0, 0.0, 0.0, 0.0});
    }
    f.fields = {u, s};
    w.write_frame(f);
  }
  w.finish(io::RunStatus::Completed);
}

}  // namespace inpact::test
