// contact_search_bench [N ...]: build and query times of the contact search tree
// (contact/search.hpp) on a wavy structured master surface of N Quad4 facets (default 10^4,
// 10^5, 10^6), queried by N slave points of an offset grid; search radius half a facet, margin a
// quarter. Prints a markdown table (median of 3 runs per figure). Measures only; asserts nothing.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "contact/search.hpp"

using namespace inpact::contact;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<long> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atol(argv[i]));
  if (sizes.empty()) sizes = {10000, 100000, 1000000};

  std::printf("| facets | build [s] | queries | query total [s] | per query [µs] | candidates/query | drift check [s] | tree nodes |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (long n : sizes) {
    const int m = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
    const double h = 1.0 / m;
    std::vector<Vec3> x;
    x.reserve(static_cast<std::size_t>(m + 1) * (m + 1));
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i)
        x.push_back({i * h, j * h, 0.05 * std::sin(6.0 * i * h) * std::cos(4.0 * j * h)});
    std::vector<Facet> facets;
    facets.reserve(static_cast<std::size_t>(m) * m);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        Facet f;
        f.shape = FacetShape::Quad4;
        f.n_nodes = 4;
        const int a = i + (m + 1) * j;
        f.nodes = {a, a + 1, a + m + 2, a + m + 1};
        facets.push_back(f);
      }
    std::vector<Vec3> slaves;
    slaves.reserve(facets.size());
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        slaves.push_back({(i + 0.37) * h, (j + 0.61) * h, 0.05 * std::sin(6.0 * (i + 0.37) * h) * std::cos(4.0 * (j + 0.61) * h) + 0.02 * h});

    SearchOptions opt;
    opt.radius = 0.5 * h;
    opt.margin = 0.25 * h;
    std::vector<double> t_build, t_query, t_drift;
    std::size_t candidates = 0;
    FacetSearch s;
    std::vector<std::int32_t> out;
    out.reserve(64);
    for (int run = 0; run < 3; ++run) {
      auto t0 = std::chrono::steady_clock::now();
      s.build(facets, x, opt);
      t_build.push_back(seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      candidates = 0;
      for (const Vec3& p : slaves) {
        out.clear();
        s.query(p, out);
        candidates += out.size();
      }
      t_query.push_back(seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      volatile bool rebuild = s.needs_rebuild(facets, x);
      (void)rebuild;
      t_drift.push_back(seconds_since(t0));
    }
    const double tq = median(t_query);
    std::printf("| %zu | %.4f | %zu | %.4f | %.3f | %.2f | %.4f | %zu |\n", facets.size(), median(t_build), slaves.size(),
                tq, 1e6 * tq / static_cast<double>(slaves.size()),
                static_cast<double>(candidates) / static_cast<double>(slaves.size()), median(t_drift), s.n_tree_nodes());
    std::fflush(stdout);
  }
  return 0;
}
