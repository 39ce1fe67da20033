#include "mpi_launch.hpp"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace inpact::solver {

namespace {

/// The environment variable as a non-negative integer, or -1 when absent or not a number.
int env_int(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return -1;
  int value = -1;
  const char* end = text + std::strlen(text);
  const auto [at, ec] = std::from_chars(text, end, value);
  return ec == std::errc() && at == end && value >= 0 ? value : -1;
}

}  // namespace

LaunchRanks launch_ranks() {
  for (const auto& [rank_var, size_var] : {std::pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                                           std::pair{"PMI_RANK", "PMI_SIZE"}}) {
    const int rank = env_int(rank_var), size = env_int(size_var);
    if (size >= 1 && rank >= 0 && rank < size) return {rank, size};
  }
  return {};
}

}  // namespace inpact::solver
