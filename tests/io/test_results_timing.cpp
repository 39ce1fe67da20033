// How long a frame of a 100k-node model takes to write, with and without the per-frame flush.
// Disabled by default (a measurement, not a check): run with
//   test_io --gtest_also_run_disabled_tests --gtest_filter='ResultsTiming.*'
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "io/results_writer.hpp"
#include "io_fixture.hpp"

using namespace inpact;

namespace {

/// A structured C3D8 block of n × n × n elements ((n+1)³ nodes), built directly.
model::Model block_model(int n) {
  model::Model m;
  auto& nodes = m.mesh.nodes;
  const int np = n + 1;
  for (int k = 0; k < np; ++k)
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) {
        const auto row = static_cast<std::int32_t>(nodes.labels.size());
        nodes.labels.push_back(row + 1);
        nodes.coords.push_back({double(i), double(j), double(k)});
        nodes.instance.push_back(0);
        nodes.index.insert(0, row + 1, row);
      }
  auto& el = m.mesh.elements;
  const auto hex = model::element_type_index(*model::find_element_type("C3D8"));
  auto id = [&](int i, int j, int k) { return static_cast<std::int32_t>((k * np + j) * np + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto row = static_cast<std::int32_t>(el.labels.size());
        el.type.push_back(hex);
        el.labels.push_back(row + 1);
        el.instance.push_back(0);
        for (auto c : {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                       id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)})
          el.conn.push_back(c);
        el.offsets.push_back(static_cast<std::int64_t>(el.conn.size()));
        el.loc.push_back({});
        el.index.insert(0, row + 1, row);
      }
  m.steps.push_back({});
  m.steps[0].name = "Step-1";
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST(ResultsTiming, DISABLED_FramesOfAHundredThousandNodeModel) {
  const model::Model m = block_model(45);  // 97,336 nodes, 91,125 C3D8
  const std::size_t n_nodes = m.mesh.nodes.size(), n_el = m.mesh.elements.size();
  io::FieldData u;
  u.key = "U";
  u.component_labels = {"U1", "U2", "U3"};
  u.values.assign(n_nodes * 3, 0.001);
  io::FieldData s;
  s.key = "S";
  s.position = io::Position::IntegrationPoint;
  s.component_labels = {"S11", "S22", "S33", "S12", "S13", "S23"};
  for (std::size_t e = 0; e < n_el; ++e)
    for (int ip = 1; ip <= 8; ++ip) {
      s.elements.push_back(m.mesh.elements.labels[e]);
      s.ip.push_back(ip);
    }
  s.values.assign(n_el * 8 * 6, 1.0);
  constexpr int kFrames = 5;

  for (bool with_s : {false, true})
    for (bool flush : {true, false}) {
      test::TempDir dir;
      io::ResultsOptions options;
      options.flush_each_frame = flush;
      auto t0 = std::chrono::steady_clock::now();
      auto w = io::ResultsWriter::create(dir / "job.h5", m, "sha", "v", options);
      const double t_create = seconds_since(t0);
      w.begin_step(m.steps[0]);
      t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < kFrames; ++k) {
        io::Frame f;
        f.step_time = f.total_time = k + 1.0;
        f.increment = k + 1;
        f.fields.push_back(u);
        if (with_s) f.fields.push_back(s);
        w.write_frame(f);
      }
      const double t_frame = seconds_since(t0) / kFrames;
      t0 = std::chrono::steady_clock::now();
      w.finish(io::RunStatus::Completed);
      const double t_finish = seconds_since(t0);
      std::printf("%zu nodes, %zu C3D8, fields U%s, flush %s: create %.3f s, %.3f s per frame, finish %.3f s, "
                  "file %.1f MB\n",
                  n_nodes, n_el, with_s ? "+S(8 ip)" : "", flush ? "on " : "off", t_create, t_frame, t_finish,
                  static_cast<double>(std::filesystem::file_size(dir / "job.h5")) / 1e6);
    }
}
