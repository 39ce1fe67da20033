#include "constraint_elimination.hpp"

#include <algorithm>

#include <Eigen/Dense>

#include "analysis_error.hpp"

namespace inpact::solver {

namespace {

/// A DOF the rows may eliminate: free, or dependent from an earlier layout of the same rules
/// (DofMap::relinearize lays the rules out again; the same rows pick the same pivots).
bool eligible(DofMap::Kind k) { return k == DofMap::Kind::Free || k == DofMap::Kind::Dependent; }

}  // namespace

void eliminate_rows(const std::vector<LinearRow>& rows, std::vector<DofMap::Kind>& kind,
                    std::map<std::int64_t, std::vector<MasterTerm>>& dependent, const std::string& no_pivot) {
  std::vector<std::int64_t> candidates;
  for (const LinearRow& row : rows)
    for (const MasterTerm& t : row.lhs)
      if (eligible(kind[static_cast<std::size_t>(t.dof)]) && !dependent.count(t.dof)) candidates.push_back(t.dof);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  const auto n_rows = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n_rows, static_cast<Eigen::Index>(candidates.size()));
  for (Eigen::Index r = 0; r < n_rows; ++r)
    for (const MasterTerm& t : rows[static_cast<std::size_t>(r)].lhs)
      if (auto it = std::lower_bound(candidates.begin(), candidates.end(), t.dof); it != candidates.end() && *it == t.dof)
        A(r, it - candidates.begin()) += t.weight;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (lu.rank() < n_rows) throw AnalysisError(no_pivot);
  // u_P = B⁻¹ (Σ b u − Σ_{lhs ∖ P} a u), B the rows' columns at the pivots P.
  std::vector<std::int64_t> pivots;
  Eigen::MatrixXd B(n_rows, n_rows);
  for (Eigen::Index j = 0; j < n_rows; ++j) {
    const Eigen::Index col = lu.permutationQ().indices()[j];
    pivots.push_back(candidates[static_cast<std::size_t>(col)]);
    B.col(j) = A.col(col);
  }
  const Eigen::MatrixXd B_inv = B.inverse();
  for (Eigen::Index j = 0; j < n_rows; ++j) {
    std::map<std::int64_t, double> rule;
    for (Eigen::Index r = 0; r < n_rows; ++r) {
      const LinearRow& row = rows[static_cast<std::size_t>(r)];
      for (const MasterTerm& t : row.rhs) rule[t.dof] += B_inv(j, r) * t.weight;
      for (const MasterTerm& t : row.lhs)
        if (std::find(pivots.begin(), pivots.end(), t.dof) == pivots.end()) rule[t.dof] -= B_inv(j, r) * t.weight;
    }
    std::vector<MasterTerm> terms;
    for (const auto& [dof, weight] : rule)
      if (weight != 0.0) terms.push_back({dof, weight});
    const std::int64_t pivot = pivots[static_cast<std::size_t>(j)];
    dependent[pivot] = std::move(terms);
    kind[static_cast<std::size_t>(pivot)] = DofMap::Kind::Dependent;
  }
}

}  // namespace inpact::solver
