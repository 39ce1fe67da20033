/// The solver benchmark's floor: what one linear static solve cannot avoid, measured on the
/// deck's own matrix with the solver's own code.
///
///     solver_floor DECK.inp [THREADS]
///
/// Reads the deck (not timed), sets up the first step's conditions, DOF map and assembler (the
/// pattern build, timed as `setup`), then times
///   assembly  one assembly of the reduced tangent and the internal forces at the step-end BCs,
///   residual  one assembly of the internal forces only (what a convergence check costs),
///   analyse / factor / solve  CHOLMOD, with the settings of solver/linear/cholmod_solver.cpp.
/// floor = assembly + analyse + factor + solve. THREADS sets the assembler's threads and
/// OpenBLAS's, as `inpact run --threads` does. Prints one line of `key=value` pairs, including
/// the tip-independent check max|u| and the process's peak resident memory.
#include <cholmod.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "parser/read_deck.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/blas_info.hpp"
#include "solver/dof_map.hpp"
#include "solver/step_conditions.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace inpact;
  if (argc < 2) {
    std::fprintf(stderr, "usage: solver_floor DECK.inp [THREADS]\n");
    return 2;
  }
  const int threads = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
  const parser::ReadResult deck = parser::read_deck(argv[1]);
  if (!deck.ok() || deck.model.steps.empty()) {
    std::fprintf(stderr, "%s", deck.report().c_str());
    return 1;
  }
  solver::set_blas_threads(threads);
  const solver::AnalysisModel am = solver::build_analysis_model(deck.model);
  const model::Step& step = deck.model.steps.front();

  auto t0 = std::chrono::steady_clock::now();
  const solver::StepConditions conditions(am, step, solver::initial_history(am), 0.0);
  const solver::DofMap dofs = solver::DofMap::build(am, conditions.prescribed());
  solver::Assembler assembler(am, dofs, threads);
  const double t_setup = seconds_since(t0);

  const std::size_t n = am.n_dof();
  const std::size_t n_eq = static_cast<std::size_t>(dofs.n_equations());
  const double t_end = step.static_procedure->time_period;
  std::vector<double> zero(n, 0.0), u(n, 0.0), f_int(n), f_ext(n, 0.0), r_full(n), r(n_eq), x(n_eq);
  conditions.apply_prescribed(t_end, zero, u);
  dofs.update_dependent(u);
  conditions.external_force(t_end, f_ext);
  const std::vector<double> delta_t = conditions.temperature_change(t_end);

  solver::AssemblyRequest request;
  request.tangent = true;
  request.nlgeom = step.nlgeom;
  request.delta_t = delta_t;
  t0 = std::chrono::steady_clock::now();
  assembler.assemble(u, request, f_int);
  const double t_assembly = seconds_since(t0);
  for (std::size_t d = 0; d < n; ++d) r_full[d] = f_ext[d] - f_int[d];
  assembler.reduce(r_full, r);

  solver::AssemblyRequest residual_only = request;
  residual_only.tangent = false;
  std::vector<double> f_check(n);
  t0 = std::chrono::steady_clock::now();
  assembler.assemble(u, residual_only, f_check);
  const double t_residual = seconds_since(t0);

  // CHOLMOD as solver/linear/cholmod_solver.cpp drives it: supernodal, upper triangle, wrapped.
  const solver::SparseMatrix& k = assembler.tangent();
  cholmod_common common;
  cholmod_l_start(&common);
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.print = 0;
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<std::size_t>(k.n);
  a.nzmax = k.nnz();
  a.p = const_cast<std::int64_t*>(k.col_ptr.data());
  a.i = const_cast<std::int64_t*>(k.row_idx.data());
  a.x = const_cast<double*>(k.values.data());
  a.stype = 1;
  a.itype = CHOLMOD_LONG;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  t0 = std::chrono::steady_clock::now();
  cholmod_factor* factor = cholmod_l_analyze(&a, &common);
  const double t_analyse = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  cholmod_l_factorize(&a, factor, &common);
  const double t_factor = seconds_since(t0);
  if (common.status != CHOLMOD_OK) {
    std::fprintf(stderr, "solver_floor: CHOLMOD status %d\n", common.status);
    return 1;
  }
  const double factor_nnz = common.lnz;
  const double flops = common.fl;
  cholmod_dense b{};
  b.nrow = b.nzmax = b.d = n_eq;
  b.ncol = 1;
  b.x = r.data();
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  t0 = std::chrono::steady_clock::now();
  cholmod_dense* sol = cholmod_l_solve(CHOLMOD_A, factor, &b, &common);
  const double t_solve = seconds_since(t0);
  std::memcpy(x.data(), sol->x, n_eq * sizeof(double));
  cholmod_l_free_dense(&sol, &common);
  cholmod_l_free_factor(&factor, &common);
  cholmod_l_finish(&common);

  double max_u = 0.0;
  for (double v : x) max_u = std::max(max_u, std::abs(v));
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf(
      "dof=%zu equations=%zu nnz=%zu threads=%d setup=%.4f assembly=%.4f residual=%.4f analyse=%.4f factor=%.4f "
      "solve=%.4f floor=%.4f factor_nnz=%.0f gflop=%.2f max_u=%.6e peak_mb=%.0f\n",
      n, n_eq, k.nnz(), threads, t_setup, t_assembly, t_residual, t_analyse, t_factor, t_solve,
      t_assembly + t_analyse + t_factor + t_solve, factor_nnz, flops / 1e9, max_u,
      static_cast<double>(usage.ru_maxrss) / 1024.0);
  return 0;
}
