/// Loads libinpact_petsc.so on the first use of the PETSc solver. The executable does not link
/// PETSc: its hundred shared libraries (MPI, hypre, MUMPS, ...) would cost every process start
/// 44 ms, a run that never uses them included (a study starts one process per case).
#include "petsc_module.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace inpact::solver {

namespace {

struct Module {
  void* handle = nullptr;
  decltype(&inpact_petsc_create) create = nullptr;
  decltype(&inpact_petsc_finish) finish = nullptr;
  decltype(&inpact_mpi_world) world = nullptr;
  decltype(&inpact_mpi_allreduce) allreduce = nullptr;
  decltype(&inpact_mpi_allgather_records) allgather = nullptr;
  decltype(&inpact_mpi_abort) abort = nullptr;
  decltype(&inpact_partition_elements) partition = nullptr;
  std::string error;  ///< why it could not be started
};

/// Where the module may be: $INPACT_PETSC_MODULE, beside the executable, where the build put it.
std::vector<std::string> module_candidates() {
  std::vector<std::string> out;
  if (const char* env = std::getenv("INPACT_PETSC_MODULE"); env && *env) out.emplace_back(env);
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back((exe.parent_path() / "libinpact_petsc.so").string());
#ifdef INPACT_PETSC_MODULE_PATH
  out.emplace_back(INPACT_PETSC_MODULE_PATH);
#endif
  return out;
}

void finish_at_exit();

/// Set once PETSc runs: rank_world() then asks it, and never loads the module itself.
std::atomic<bool>& petsc_started() {
  static std::atomic<bool> started{false};
  return started;
}

Module& module() {
  static Module m;
  static std::once_flag once;
  std::call_once(once, [] {
    if (!petsc_built()) {
      m.error = "this inpact was built without PETSc (configure found no pkg-config PETSc)";
      return;
    }
    std::string tried;
    for (const auto& path : module_candidates()) {
      // RTLD_GLOBAL: Open MPI loads its own components later, and they look for libmpi's symbols.
      m.handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
      if (m.handle) break;
      tried += "\n  " + std::string(dlerror());
    }
    if (!m.handle) {
      m.error = "cannot load the PETSc module libinpact_petsc.so:" + tried;
      return;
    }
    auto start = reinterpret_cast<decltype(&inpact_petsc_start)>(dlsym(m.handle, "inpact_petsc_start"));
    m.create = reinterpret_cast<decltype(&inpact_petsc_create)>(dlsym(m.handle, "inpact_petsc_create"));
    m.finish = reinterpret_cast<decltype(&inpact_petsc_finish)>(dlsym(m.handle, "inpact_petsc_finish"));
    m.world = reinterpret_cast<decltype(&inpact_mpi_world)>(dlsym(m.handle, "inpact_mpi_world"));
    m.allreduce = reinterpret_cast<decltype(&inpact_mpi_allreduce)>(dlsym(m.handle, "inpact_mpi_allreduce"));
    m.allgather = reinterpret_cast<decltype(&inpact_mpi_allgather_records)>(dlsym(m.handle, "inpact_mpi_allgather_records"));
    m.abort = reinterpret_cast<decltype(&inpact_mpi_abort)>(dlsym(m.handle, "inpact_mpi_abort"));
    m.partition = reinterpret_cast<decltype(&inpact_partition_elements)>(dlsym(m.handle, "inpact_partition_elements"));
    if (!start || !m.create || !m.finish || !m.world || !m.allreduce || !m.allgather || !m.abort || !m.partition) {
      m.error = "the PETSc module lacks its entry points";
      m.create = nullptr;
      return;
    }
    if (start() != 0) {
      m.error = "PetscInitialize failed";
      m.create = nullptr;
      return;
    }
    std::atexit(finish_at_exit);
    petsc_started().store(true);
  });
  return m;
}

void finish_at_exit() {
  if (module().finish) module().finish();
}

}  // namespace

bool petsc_built() {
#ifdef INPACT_HAVE_PETSC
  return true;
#else
  return false;
#endif
}

std::string petsc_build_version() {
#ifdef INPACT_PETSC_VERSION
  return std::string("PETSc ") + INPACT_PETSC_VERSION;
#else
  return "";
#endif
}

void start_petsc() {
  if (!module().create) throw std::runtime_error(module().error);
}

RankWorld rank_world() {
  RankWorld world;
  if (petsc_started().load()) module().world(&world.rank, &world.size);
  return world;
}

void RankWorld::sum(std::span<double> values) const {
  if (distributed()) module().allreduce(values.data(), static_cast<long>(values.size()), 0);
}

void RankWorld::abort(int code) const {
  if (distributed()) module().abort(code);
}

void RankWorld::gather(std::span<const std::byte> mine, std::span<std::byte> all, std::size_t record_bytes,
                       std::span<const long> count_of_rank) const {
  if (distributed())
    module().allgather(mine.data(), static_cast<long>(mine.size() / record_bytes), static_cast<long>(record_bytes),
                       all.data(), count_of_rank.data());
  else std::copy(mine.begin(), mine.end(), all.begin());
}

double RankWorld::min(double value) const {
  if (distributed()) module().allreduce(&value, 1, 1);
  return value;
}

std::vector<int> partition_graph(std::span<const long> xadj, std::span<const long> adjacency) {
  const long n = static_cast<long>(xadj.size()) - 1;
  std::vector<int> rank(static_cast<std::size_t>(std::max(n, 0L)), 0);
  if (!petsc_started().load() || n <= 0) return rank;
  std::string error;
  if (module().partition(n, xadj.data(), adjacency.data(), rank.data(), &error) != 0)
    throw std::runtime_error("the elements could not be partitioned: " + error);
  return rank;
}

std::unique_ptr<LinearSolver> make_petsc_solver(const EquationPoints& points) {
  start_petsc();
  std::string error;
  std::unique_ptr<LinearSolver> solver(module().create(&points, &error));
  if (!solver) throw std::runtime_error("the PETSc solver could not be created: " + error);
  return solver;
}

}  // namespace inpact::solver
