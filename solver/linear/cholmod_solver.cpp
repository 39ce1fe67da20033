/// CHOLMOD supernodal Cholesky on the upper triangle, wrapping our arrays without copying.
#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "linear_solver.hpp"

namespace inpact::solver {

namespace {

static_assert(sizeof(SuiteSparse_long) == sizeof(std::int64_t), "CHOLMOD's long indices must be 64-bit");

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    cholmod_l_start(&common_);
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.print = 0;  // statuses are reported through FactorStatus, not printed
    common_.error_handler = nullptr;
  }
  ~CholmodSolver() override {
    if (factor_) cholmod_l_free_factor(&factor_, &common_);
    cholmod_l_finish(&common_);
  }

  FactorStatus factorize(const SparseMatrix& a) override {
    if (!a.upper_only) throw std::logic_error("CHOLMOD needs the upper triangle of a symmetric matrix");
    cholmod_sparse view = wrap(a);
    if (!factor_ || a.col_ptr != col_ptr_ || a.row_idx != row_idx_) {
      if (factor_) cholmod_l_free_factor(&factor_, &common_);
      factor_ = cholmod_l_analyze(&view, &common_);
      if (!factor_) return FactorStatus::OutOfMemory;
      col_ptr_ = a.col_ptr;
      row_idx_ = a.row_idx;
      ++analyses_;
    }
    failed_ = -1;
    cholmod_l_factorize(&view, factor_, &common_);
    if (common_.status == CHOLMOD_OUT_OF_MEMORY) return FactorStatus::OutOfMemory;
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      // factor_->minor is the column (in the permuted order) where the pivot was not positive.
      const auto k = static_cast<std::int64_t>(factor_->minor);
      const auto* perm = static_cast<const SuiteSparse_long*>(factor_->Perm);
      failed_ = (perm && k < a.n) ? perm[k] : k;
      return FactorStatus::NotPositiveDefinite;
    }
    return FactorStatus::Ok;
  }

  void solve(std::span<const double> b, std::span<double> x) override {
    cholmod_dense rhs{};
    rhs.nrow = b.size();
    rhs.ncol = 1;
    rhs.nzmax = b.size();
    rhs.d = b.size();
    rhs.x = const_cast<double*>(b.data());  // CHOLMOD reads the right-hand side only
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* sol = cholmod_l_solve(CHOLMOD_A, factor_, &rhs, &common_);
    if (!sol) throw std::runtime_error("CHOLMOD solve failed (out of memory)");
    std::memcpy(x.data(), sol->x, x.size() * sizeof(double));
    cholmod_l_free_dense(&sol, &common_);
  }

  std::string name() const override { return "CHOLMOD"; }
  int analyses() const override { return analyses_; }
  std::int64_t failed_equation() const override { return failed_; }

 private:
  static cholmod_sparse wrap(const SparseMatrix& a) {
    cholmod_sparse s{};
    s.nrow = s.ncol = static_cast<std::size_t>(a.n);
    s.nzmax = a.nnz();
    s.p = const_cast<std::int64_t*>(a.col_ptr.data());
    s.i = const_cast<std::int64_t*>(a.row_idx.data());
    s.x = const_cast<double*>(a.values.data());
    s.stype = 1;  // upper triangle stored
    s.itype = CHOLMOD_LONG;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  std::vector<std::int64_t> col_ptr_, row_idx_;  ///< pattern of the current analysis
  int analyses_ = 0;
  std::int64_t failed_ = -1;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace inpact::solver
