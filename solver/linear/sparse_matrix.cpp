#include "sparse_matrix.hpp"

#include <algorithm>
#include <stdexcept>

namespace inpact::solver {

std::int64_t SparseMatrix::find(std::int64_t row, std::int64_t col) const {
  if (upper_only && row > col) std::swap(row, col);
  const auto begin = row_idx.begin() + col_ptr[col], end = row_idx.begin() + col_ptr[col + 1];
  const auto it = std::lower_bound(begin, end, row);
  return (it != end && *it == row) ? static_cast<std::int64_t>(it - row_idx.begin()) : -1;
}

void SparseMatrix::multiply(std::span<const double> x, std::span<double> y) const {
  std::fill(y.begin(), y.end(), 0.0);
  for (std::int64_t c = 0; c < n; ++c)
    for (std::int64_t k = col_ptr[c]; k < col_ptr[c + 1]; ++k) {
      const std::int64_t r = row_idx[k];
      y[r] += values[k] * x[c];
      if (upper_only && r != c) y[c] += values[k] * x[r];
    }
}

void PatternBuilder::add(std::int64_t row, std::int64_t col) {
  std::vector<std::int64_t>& rows = columns_[col];
  if (rows.size() == rows.capacity() && rows.size() >= 16) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    if (rows.size() > rows.capacity() / 2) rows.reserve(2 * rows.capacity());  // room for half as many again
  }
  rows.push_back(row);
}

void PatternBuilder::add_block(std::span<const std::int64_t> dofs) {
  for (std::int64_t c : dofs) {
    if (c < 0) continue;
    for (std::int64_t r : dofs)
      if (r >= 0 && r <= c) add(r, c);
  }
}

void PatternBuilder::add_pair(std::int64_t row, std::int64_t col) {
  add(std::min(row, col), std::max(row, col));
}

SparseMatrix PatternBuilder::build(bool upper_only) {
  std::size_t nnz = 0;
  for (std::int64_t c = 0; c < n_; ++c) {
    std::vector<std::int64_t>& rows = columns_[c];
    rows.push_back(c);  // the diagonal is always in the pattern (empty rows stay factorable)
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nnz += rows.size();
  }
  SparseMatrix m;
  m.n = n_;
  m.upper_only = true;
  m.col_ptr.assign(n_ + 1, 0);
  m.row_idx.reserve(nnz);
  for (std::int64_t c = 0; c < n_; ++c) {
    m.row_idx.insert(m.row_idx.end(), columns_[c].begin(), columns_[c].end());
    m.col_ptr[c + 1] = static_cast<std::int64_t>(m.row_idx.size());
    std::vector<std::int64_t>().swap(columns_[c]);  // the builder's memory goes as the pattern's grows
  }
  m.values.assign(m.row_idx.size(), 0.0);
  if (upper_only) return m;
  SparseMatrix full;
  mirror_upper(m, full);
  return full;
}

namespace {

/// Walks column c of the merge: calls emit(row, from_kept) for each row of the union, in order.
template <class Emit>
void merge_column(const SparseMatrix& kept, const std::vector<bool>& keep, const SparseMatrix& added, std::int64_t c,
                  Emit&& emit) {
  std::int64_t k = c < kept.n ? kept.col_ptr[c] : 0, k_end = c < kept.n ? kept.col_ptr[c + 1] : 0;
  std::int64_t a = added.col_ptr[c], a_end = added.col_ptr[c + 1];
  while (k < k_end || a < a_end) {
    if (k < k_end && !keep[static_cast<std::size_t>(k)]) {
      ++k;
      continue;
    }
    const bool take_kept = k < k_end && (a == a_end || kept.row_idx[k] <= added.row_idx[a]);
    const std::int64_t row = take_kept ? kept.row_idx[k] : added.row_idx[a];
    if (take_kept && a < a_end && added.row_idx[a] == row) ++a;  // (in both: once, as kept)
    take_kept ? ++k : ++a;
    emit(row, take_kept);
  }
}

}  // namespace

SparseMatrix merge_patterns(const SparseMatrix& kept, const std::vector<bool>& keep, const SparseMatrix& added,
                            std::vector<bool>& from_kept) {
  if (keep.size() != kept.nnz()) throw std::logic_error("merge_patterns: one flag per entry of the kept pattern");
  for (std::int64_t c = added.n; c < kept.n; ++c)
    for (std::int64_t k = kept.col_ptr[c]; k < kept.col_ptr[c + 1]; ++k)
      if (keep[static_cast<std::size_t>(k)]) throw std::logic_error("merge_patterns: a kept entry beyond the columns");
  SparseMatrix m;
  m.n = added.n;
  m.upper_only = true;
  m.col_ptr.assign(static_cast<std::size_t>(m.n) + 1, 0);
  // At most the kept entries and the added ones: over by their overlap (every diagonal, and the
  // added couplings the elements have too), a small part.
  const auto bound = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), true)) + added.nnz();
  m.row_idx.reserve(bound);
  from_kept.clear();
  from_kept.reserve(bound);
  for (std::int64_t c = 0; c < m.n; ++c) {
    merge_column(kept, keep, added, c, [&](std::int64_t row, bool was_kept) {
      m.row_idx.push_back(row);
      from_kept.push_back(was_kept);
    });
    m.col_ptr[c + 1] = static_cast<std::int64_t>(m.row_idx.size());
  }
  return m;
}

void mirror_upper(const SparseMatrix& a, SparseMatrix& full) {
  std::vector<std::int64_t> count(static_cast<std::size_t>(a.n) + 1, 0);
  for (std::int64_t c = 0; c < a.n; ++c)
    for (std::int64_t k = a.col_ptr[c]; k < a.col_ptr[c + 1]; ++k) {
      ++count[c + 1];
      if (a.row_idx[k] != c) ++count[a.row_idx[k] + 1];
    }
  full.n = a.n;
  full.upper_only = false;
  full.col_ptr.assign(static_cast<std::size_t>(a.n) + 1, 0);
  for (std::int64_t c = 0; c < a.n; ++c) full.col_ptr[c + 1] = full.col_ptr[c] + count[c + 1];
  full.row_idx.assign(static_cast<std::size_t>(full.col_ptr[a.n]), 0);
  full.values.assign(static_cast<std::size_t>(full.col_ptr[a.n]), 0.0);
  std::vector<std::int64_t> next(full.col_ptr.begin(), full.col_ptr.end() - 1);
  // Walking the columns in order fills column j first with its own rows (<= j, increasing),
  // then with the mirrored rows c > j in increasing c: every column comes out sorted.
  for (std::int64_t c = 0; c < a.n; ++c)
    for (std::int64_t k = a.col_ptr[c]; k < a.col_ptr[c + 1]; ++k) {
      const std::int64_t r = a.row_idx[k];
      full.row_idx[next[c]] = r;
      full.values[next[c]++] = a.values[k];
      if (r != c) {
        full.row_idx[next[r]] = c;
        full.values[next[r]++] = a.values[k];
      }
    }
}

}  // namespace inpact::solver
