#include "linear_solver_choice.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "linear/mpi_launch.hpp"
#include "linear/petsc_module.hpp"

namespace inpact::solver {

std::optional<SolverRequest> parse_solver_request(std::string_view text) {
  if (text == "direct") return SolverRequest::Direct;
  if (text == "petsc") return SolverRequest::Petsc;
  if (text == "auto") return SolverRequest::Auto;
  if (text.empty()) return SolverRequest::Default;
  return std::nullopt;
}

const char* request_name(SolverRequest request) {
  switch (request) {
    case SolverRequest::Direct: return "direct";
    case SolverRequest::Petsc: return "petsc";
    case SolverRequest::Auto: return "auto";
    case SolverRequest::Default: return "default";
  }
  return "?";
}

const char* kind_name(SolverKind kind) { return kind == SolverKind::Petsc ? "petsc" : "direct"; }

/// auto's memory rule: the direct solver's estimate above half the memory available (known).
static bool direct_memory_too_large(const SolverChoice& c) {
  return c.available_memory > 0.0 && c.direct_memory > 0.5 * c.available_memory;
}

/// The model's dimension: its first element type's (2 for plane and axisymmetric models).
static int model_dim(const model::Model& model) {
  const auto& el = model.mesh.elements;
  return el.size() > 0 ? model::element_type(el.type[0]).dim : 3;
}

std::int64_t petsc_from_dofs(int dim) { return dim == 2 ? kPetscFromDofs2d : kPetscFromDofs; }

/// The memory unit of the bench's figures (/usr/bin/time's kB / 1024²) and of describe().
constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

double direct_memory_estimate(std::int64_t dofs, int dim) {
  const double d = static_cast<double>(dofs);
  if (dim == 2) return 0.90 * kGiB * (d / 500'000.0);
  return 1.07 * kGiB * std::pow(d / 98'304.0, 1.33);
}

/// The first number of the file (bytes), or -1 when it cannot be read or says "max".
static double read_bytes(const char* path) {
  std::ifstream in(path);
  double v = -1.0;
  return in >> v ? v : -1.0;
}

double available_memory() {
  double available = -1.0;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kb = 0.0;
    if (key == "MemAvailable:" && meminfo >> kb) {
      available = kb * 1024.0;
      break;
    }
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  // A container's limit (cgroup v2) can be far below the machine's free memory.
  const double limit = read_bytes("/sys/fs/cgroup/memory.max"), used = read_bytes("/sys/fs/cgroup/memory.current");
  if (limit > 0 && used >= 0) available = available < 0 ? limit - used : std::min(available, limit - used);
  return std::max(available, 0.0);
}

SolverChoice resolve_linear_solver(SolverRequest request, const model::Model& model, int ranks) {
  return resolve_linear_solver(request, model, ranks, request == SolverRequest::Auto ? available_memory() : 0.0);
}

SolverChoice resolve_linear_solver(SolverRequest request, const model::Model& model, int ranks,
                                   double available_bytes) {
  SolverChoice choice;
  choice.requested = request;
  choice.dim = model_dim(model);
  choice.model_dofs = static_cast<std::int64_t>(model.mesh.nodes.size()) * choice.dim;
  choice.ranks = ranks;
  const bool distributed = ranks > 1;
  if (distributed && !petsc_built())
    throw std::invalid_argument(fmt::format("a run on {} MPI ranks solves with PETSc, and this inpact was built without "
                                            "it (pkg-config PETSc was not found when it was configured, or "
                                            "INPACT_PETSC=OFF)", ranks));
  if (distributed && request == SolverRequest::Direct)
    throw std::invalid_argument(fmt::format("--solver direct: the direct solvers run on one process, and this run has "
                                            "{} MPI ranks; use --solver petsc (or none), or run without mpirun", ranks));
  if (request == SolverRequest::Petsc && !petsc_built())
    throw std::invalid_argument("--solver petsc: this inpact was built without PETSc "
                                "(PETSc, pkg-config PETSc, was not found when it was configured, or INPACT_PETSC=OFF)");
  bool petsc = distributed || request == SolverRequest::Petsc;
  if (request == SolverRequest::Auto && petsc_built()) {
    choice.direct_memory = direct_memory_estimate(choice.model_dofs, choice.dim);
    choice.available_memory = available_bytes;
    petsc = petsc || choice.model_dofs >= petsc_from_dofs(choice.dim) || direct_memory_too_large(choice);
  }
  choice.kind = petsc ? SolverKind::Petsc : SolverKind::Direct;
  return choice;
}

SolverChoice resolve_linear_solver(std::string_view request, const model::Model& model) {
  const auto parsed = parse_solver_request(request);
  if (!parsed) throw std::invalid_argument(fmt::format("--solver {}: expected direct, petsc or auto", request));
  return resolve_linear_solver(*parsed, model, launch_ranks().size);
}

std::string describe(const SolverChoice& c) {
  const std::string what = c.kind == SolverKind::Petsc
                               ? "petsc (CG or GMRES with GAMG; MUMPS for contact multipliers)"
                               : "direct (CHOLMOD; UMFPACK for contact multipliers and friction)";
  std::string why = c.requested == SolverRequest::Default ? "default" : "requested";
  if (c.ranks > 1) {
    why = fmt::format("{} MPI ranks", c.ranks);
  } else if (c.requested == SolverRequest::Auto) {
    const std::int64_t from = petsc_from_dofs(c.dim);
    why = !petsc_built() ? "auto: built without PETSc"
                         : fmt::format("auto: {}D, {} DOF {} {}", c.dim, c.model_dofs, c.model_dofs >= from ? ">=" : "<", from);
    // (the memory only where it decided: the line is the same for check and run otherwise)
    if (petsc_built() && c.model_dofs < from && direct_memory_too_large(c))
      why += fmt::format(", but direct would take about {:.1f} GB, more than half the {:.1f} GB available",
                         c.direct_memory / kGiB, c.available_memory / kGiB);
  }
  return fmt::format("LINEAR SOLVER: {}; {}", what, why);
}

void start_linear_solver(const SolverChoice& choice) {
  if (choice.kind == SolverKind::Petsc) start_petsc();
}

std::string petsc_availability() {
  if (!petsc_built()) return "PETSc: not built (--solver petsc unavailable)";
  return petsc_build_version() + " (--solver petsc|auto available; mpirun -np N inpact run: a distributed run)";
}

}  // namespace inpact::solver
