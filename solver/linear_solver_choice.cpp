#include "linear_solver_choice.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "linear/mpi_launch.hpp"
#include "linear/petsc_module.hpp"
#include "model/element_types.hpp"
#include "model/mesh_queries.hpp"

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

std::int64_t petsc_from_dofs(int dim, bool solids) {
  if (dim == 2) return kPetscFromDofs2d;
  return solids ? kPetscFromDofs : kPetscFromDofsShells;
}

namespace {

/// Whether at least half the model's nodes (rotation nodes counted: their DOFs are the model's
/// too) belong to 3D continuum elements, whose matrix has a volume's sparsity. A shell model with
/// a few solid bolts keeps the shells' crossover.
bool mostly_solid(const model::Model& model) {
  const auto& elements = model.mesh.elements;
  std::vector<char> on_solid(model.mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const model::ElementTypeInfo& t = model::element_type(elements.type[e]);
    if (!(model::is_continuum(t) && t.dim == 3)) continue;
    for (std::int32_t node : elements.nodes_of(e)) on_solid[static_cast<std::size_t>(node)] = 1;
  }
  const auto solid_nodes = static_cast<std::size_t>(std::count(on_solid.begin(), on_solid.end(), 1));
  return 2 * solid_nodes >= on_solid.size() && solid_nodes > 0;
}

}  // namespace

SolverChoice resolve_linear_solver(SolverRequest request, const model::Model& model, int ranks) {
  SolverChoice choice;
  choice.requested = request;
  choice.dim = model::model_dimension(model.mesh.elements);
  choice.model_dofs = static_cast<std::int64_t>(model.mesh.nodes.size()) * choice.dim;
  choice.solids = choice.dim == 3 && mostly_solid(model);
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
  const bool petsc = distributed || request == SolverRequest::Petsc ||
                     (request == SolverRequest::Auto && petsc_built() &&
                      choice.model_dofs >= petsc_from_dofs(choice.dim, choice.solids));
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
    const std::int64_t from = petsc_from_dofs(c.dim, c.solids);
    const char* kind = c.dim == 2 ? "2D" : c.solids ? "3D" : "3D, mostly shells or beams";
    why = !petsc_built() ? "auto: built without PETSc"
                         : fmt::format("auto: {}, {} DOF {} {}", kind, c.model_dofs, c.model_dofs >= from ? ">=" : "<", from);
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
