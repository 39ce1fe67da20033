#include "sparse_matrix.hpp"

#include <algorithm>

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

void PatternBuilder::add_block(std::span<const std::int64_t> dofs) {
  for (std::int64_t c : dofs) {
    if (c < 0) continue;
    auto& col = columns_[c];
    for (std::int64_t r : dofs)
      if (r >= 0) col.push_back(r);
  }
}

void PatternBuilder::add_pair(std::int64_t row, std::int64_t col) {
  columns_[col].push_back(row);
  columns_[row].push_back(col);
  columns_[row].push_back(row);
  columns_[col].push_back(col);
}

SparseMatrix PatternBuilder::build(bool upper_only) const {
  SparseMatrix m;
  m.n = n_;
  m.upper_only = upper_only;
  m.col_ptr.assign(n_ + 1, 0);
  std::vector<std::int64_t> col;
  for (std::int64_t c = 0; c < n_; ++c) {
    col = columns_[c];
    col.push_back(c);  // the diagonal is always in the pattern (empty rows stay factorable)
    std::sort(col.begin(), col.end());
    col.erase(std::unique(col.begin(), col.end()), col.end());
    for (std::int64_t r : col)
      if (!upper_only || r <= c) m.row_idx.push_back(r);
    m.col_ptr[c + 1] = static_cast<std::int64_t>(m.row_idx.size());
  }
  m.values.assign(m.row_idx.size(), 0.0);
  return m;
}

}  // namespace inpact::solver
