/// Reading benchmark: times read_deck on one deck (median of several runs) and reports the
/// process's peak resident memory. One deck per process, so the peak belongs to that deck.
///
///     read_deck_bench DECK.inp [RUNS]
///
/// Prints one line: `elements nodes median_s min_s max_s peak_rss_mb file_mb` (and the deck's
/// first diagnostics on stderr if it is not clean, with exit code 1).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "parser/read_deck.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: read_deck_bench DECK.inp [RUNS]\n");
    return 2;
  }
  const std::string path = argv[1];
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  std::vector<double> seconds;
  std::size_t n_elements = 0, n_nodes = 0;
  bool ok = true;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    auto result = inpact::parser::read_deck(path);
    const auto t1 = std::chrono::steady_clock::now();
    seconds.push_back(std::chrono::duration<double>(t1 - t0).count());
    n_elements = result.model.mesh.elements.size();
    n_nodes = result.model.mesh.nodes.size();
    if (!result.ok() && ok) {
      ok = false;
      const std::string report = result.report();
      std::fprintf(stderr, "%.2000s", report.c_str());
    }
  }  // the model is freed after each run: the peak is one model plus the reader's temporaries
  std::vector<double> sorted = seconds;
  std::sort(sorted.begin(), sorted.end());
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);  // ru_maxrss: kilobytes on Linux
  const double file_mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::printf("%zu %zu %.3f %.3f %.3f %.0f %.0f\n", n_elements, n_nodes, sorted[sorted.size() / 2],
              sorted.front(), sorted.back(), static_cast<double>(usage.ru_maxrss) / 1024.0, file_mb);
  return ok ? 0 : 1;
}
