#pragma once
/// A sparse matrix in compressed-column form with 64-bit indices (what CHOLMOD's and
/// UMFPACK's `_l` interfaces take without copying), and the builder of its pattern.
#include <cstdint>
#include <span>
#include <vector>

namespace inpact::solver {

struct SparseMatrix {
  std::int64_t n = 0;                  ///< square: n × n
  std::vector<std::int64_t> col_ptr;   ///< n + 1
  std::vector<std::int64_t> row_idx;   ///< sorted within each column
  std::vector<double> values;
  bool upper_only = false;             ///< symmetric, only entries with row <= col stored

  std::size_t nnz() const { return row_idx.size(); }
  void set_zero() { std::fill(values.begin(), values.end(), 0.0); }
  /// Position of entry (row, col) in `values`, or -1 when it is not in the pattern.
  std::int64_t find(std::int64_t row, std::int64_t col) const;
  /// y = A x (the full matrix when upper_only).
  void multiply(std::span<const double> x, std::span<double> y) const;
};

/// The union of two upper-triangle patterns of added.n columns: the entries of `kept` flagged in
/// `keep` (all of them in its first added.n columns) and every entry of `added`, each column
/// sorted; no values (the caller sizes them, once `kept` is gone). `from_kept` gets the result's
/// flags: whether an entry came from `kept`'s kept ones.
SparseMatrix merge_patterns(const SparseMatrix& kept, const std::vector<bool>& keep, const SparseMatrix& added,
                            std::vector<bool>& from_kept);

/// The full (both triangles) matrix of a symmetric one stored as its upper triangle, into
/// `full` (its buffers reused). Every column comes out sorted.
void mirror_upper(const SparseMatrix& upper, SparseMatrix& full);

/// Collects the couplings of dense blocks (element DOF lists, constraint rows) and builds the
/// compressed pattern once; the values are then assembled into it iteration after iteration.
/// Couplings are symmetric: it keeps each column's rows above the diagonal, and compacts a
/// column (sort, unique) when it fills its storage, since neighbouring element blocks repeat
/// each coupling (a brick's node is in up to eight): memory stays near the pattern's own.
class PatternBuilder {
 public:
  explicit PatternBuilder(std::int64_t n) : n_(n), columns_(n) {}
  /// Every pair of these (global, >= 0) DOFs couples; negative entries are skipped.
  void add_block(std::span<const std::int64_t> dofs);
  /// Couples row with col (and col with row).
  void add_pair(std::int64_t row, std::int64_t col);
  /// The pattern, its upper triangle (upper_only) or both; every diagonal entry is in it. Once:
  /// the builder gives its memory up as it goes.
  SparseMatrix build(bool upper_only);

 private:
  void add(std::int64_t row, std::int64_t col);  ///< row <= col
  std::int64_t n_;
  std::vector<std::vector<std::int64_t>> columns_;
};

}  // namespace inpact::solver
