/// UMFPACK unsymmetric multifrontal LU, for indefinite (Lagrange multiplier) and unsymmetric
/// (friction) systems. A matrix stored as its upper triangle is expanded to the full pattern.
#include <umfpack.h>

#include <stdexcept>

#include "linear_solver.hpp"

namespace inpact::solver {

namespace {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() { umfpack_dl_defaults(control_); }
  ~UmfpackSolver() override { release(); }

  FactorStatus factorize(const SparseMatrix& a) override {
    const SparseMatrix& full = a.upper_only ? expand(a) : a;
    if (!symbolic_ || full.col_ptr != col_ptr_ || full.row_idx != row_idx_) {
      release();
      const int s = umfpack_dl_symbolic(full.n, full.n, full.col_ptr.data(), full.row_idx.data(),
                                        full.values.data(), &symbolic_, control_, info_);
      if (s == UMFPACK_ERROR_out_of_memory) return FactorStatus::OutOfMemory;
      if (s != UMFPACK_OK) throw std::runtime_error("UMFPACK symbolic analysis failed with status " + std::to_string(s));
      col_ptr_ = full.col_ptr;
      row_idx_ = full.row_idx;
      ++analyses_;
    }
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    const int s = umfpack_dl_numeric(full.col_ptr.data(), full.row_idx.data(), full.values.data(), symbolic_,
                                     &numeric_, control_, info_);
    values_ = full.values;
    if (s == UMFPACK_ERROR_out_of_memory) return FactorStatus::OutOfMemory;
    if (s == UMFPACK_WARNING_singular_matrix) return FactorStatus::Singular;
    if (s != UMFPACK_OK) throw std::runtime_error("UMFPACK factorisation failed with status " + std::to_string(s));
    return FactorStatus::Ok;
  }

  void solve(std::span<const double> b, std::span<double> x) override {
    const int s = umfpack_dl_solve(UMFPACK_A, col_ptr_.data(), row_idx_.data(), values_.data(), x.data(), b.data(),
                                   numeric_, control_, info_);
    if (s != UMFPACK_OK && s != UMFPACK_WARNING_singular_matrix)
      throw std::runtime_error("UMFPACK solve failed with status " + std::to_string(s));
  }

  std::string name() const override { return "UMFPACK"; }
  int analyses() const override { return analyses_; }
  std::int64_t failed_equation() const override { return -1; }

 private:
  /// The full pattern and values of a matrix stored as its upper triangle.
  const SparseMatrix& expand(const SparseMatrix& a) {
    mirror_upper(a, expanded_);
    return expanded_;
  }

  void release() {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
    numeric_ = symbolic_ = nullptr;
  }

  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::vector<std::int64_t> col_ptr_, row_idx_;
  std::vector<double> values_;
  SparseMatrix expanded_;
  int analyses_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace inpact::solver
