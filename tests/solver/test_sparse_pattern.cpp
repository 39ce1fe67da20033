// The pattern of the reduced tangent: merge_patterns() keeps the flagged entries of one pattern
// and adds another's; the Assembler rebuilds its extra (contact) couplings that way, so that a
// change of them leaves the elements' couplings and drops the stale extra ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/dof_map.hpp"
#include "solver/linear/sparse_matrix.hpp"
#include "solver/step_conditions.hpp"

namespace solver = inpact::solver;
using Entries = std::set<std::pair<std::int64_t, std::int64_t>>;  // (row, column)

namespace {

Entries entries_of(const solver::SparseMatrix& m) {
  Entries out;
  for (std::int64_t c = 0; c < m.n; ++c)
    for (std::int64_t k = m.col_ptr[c]; k < m.col_ptr[c + 1]; ++k) out.insert({m.row_idx[k], c});
  return out;
}

bool columns_sorted(const solver::SparseMatrix& m) {
  for (std::int64_t c = 0; c < m.n; ++c)
    for (std::int64_t k = m.col_ptr[c] + 1; k < m.col_ptr[c + 1]; ++k)
      if (m.row_idx[k - 1] >= m.row_idx[k]) return false;
  return true;
}

solver::SparseMatrix pattern(std::int64_t n, const std::vector<std::vector<std::int64_t>>& blocks) {
  solver::PatternBuilder b(n);
  for (const auto& block : blocks) b.add_block(block);
  return b.build(true);
}

TEST(MergePatterns, KeepsTheFlaggedEntriesAndAddsTheOthersColumnsIncluded) {
  const solver::SparseMatrix kept = pattern(4, {{0, 1}, {2, 3}});  // (0,0) (0,1) (1,1) (2,2) (2,3) (3,3)
  std::vector<bool> keep(kept.nnz(), true);
  keep[static_cast<std::size_t>(kept.find(2, 3))] = false;  // a stale coupling
  const solver::SparseMatrix added = pattern(5, {{1, 4}, {0, 1}});  // (1,4) in a new column, (0,1) again
  std::vector<bool> from_kept;
  const solver::SparseMatrix m = solver::merge_patterns(kept, keep, added, from_kept);
  EXPECT_EQ(m.n, 5);
  EXPECT_TRUE(m.upper_only);
  EXPECT_TRUE(columns_sorted(m));
  EXPECT_EQ(entries_of(m), (Entries{{0, 0}, {0, 1}, {1, 1}, {2, 2}, {3, 3}, {1, 4}, {4, 4}}));
  ASSERT_EQ(from_kept.size(), m.nnz());
  EXPECT_TRUE(m.values.empty());  // (the caller's, once the kept pattern is gone)
  for (std::int64_t c = 0; c < m.n; ++c)
    for (std::int64_t k = m.col_ptr[c]; k < m.col_ptr[c + 1]; ++k) {
      const bool was_kept = c < kept.n && kept.find(m.row_idx[k], c) >= 0 && !(m.row_idx[k] == 2 && c == 3);
      EXPECT_EQ(from_kept[static_cast<std::size_t>(k)], was_kept) << m.row_idx[k] << "," << c;
    }
}

TEST(MergePatterns, RefusesFlagsThatDoNotFitOrAKeptEntryBeyondTheColumns) {
  const solver::SparseMatrix kept = pattern(3, {{0, 2}});
  const solver::SparseMatrix narrower = pattern(2, {{0, 1}});
  std::vector<bool> from_kept;
  EXPECT_THROW(solver::merge_patterns(kept, std::vector<bool>(kept.nnz() + 1, true), narrower, from_kept),
               std::logic_error);
  EXPECT_THROW(solver::merge_patterns(kept, std::vector<bool>(kept.nnz(), true), narrower, from_kept), std::logic_error);
  std::vector<bool> only_first(kept.nnz(), false);
  only_first[static_cast<std::size_t>(kept.find(0, 0))] = true;
  const solver::SparseMatrix m = solver::merge_patterns(kept, only_first, narrower, from_kept);
  EXPECT_EQ(entries_of(m), (Entries{{0, 0}, {0, 1}, {1, 1}}));  // column 2 dropped with its stale entries
}

/// Two unit cubes side by side (nodes 1-8 and 9-16), node 1 held: the elements' couplings never
/// join the cubes; extra couplings do.
struct TwoCubes {
  TwoCubes()
      : read(dir.read(deck())), am(solver::build_analysis_model(read.model)),
        conditions(am, read.model.steps[0], solver::initial_history(am), 0.0),
        dofs(solver::DofMap::build(am, conditions.prescribed())) {}
  static std::string deck() {
    return "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
           "9,3,0,0\n10,4,0,0\n11,4,1,0\n12,3,1,0\n13,3,0,1\n14,4,0,1\n15,4,1,1\n16,3,1,1\n"
           "*ELEMENT, TYPE=C3D8, ELSET=E\n1,1,2,3,4,5,6,7,8\n2,9,10,11,12,13,14,15,16\n"
           "*SOLID SECTION, ELSET=E, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n"
           "*BOUNDARY\n1, 1, 3\n9, 1, 3\n*STEP\n*STATIC\n*END STEP\n";
  }
  inpact::test::DeckDir dir;
  inpact::parser::ReadResult read;
  solver::AnalysisModel am;
  solver::StepConditions conditions;
  solver::DofMap dofs;
};

/// Global DOF (node label − 1) × 3 + component.
std::int64_t dof(int node, int component) { return (node - 1) * 3 + component; }

TEST(AssemblerPattern, NewExtraCouplingsReplaceTheOldOnesAndKeepTheElements) {
  TwoCubes m;
  ASSERT_TRUE(m.read.ok()) << m.read.report();
  solver::Assembler assembler(m.am, m.dofs);
  const Entries elements = entries_of(assembler.tangent());
  const std::int64_t n_eq = m.dofs.n_equations();

  solver::ExtraCouplings first;  // node 7 with node 10, and one multiplier on node 3's x
  first.dof_blocks.push_back({dof(7, 0), dof(7, 1), dof(7, 2), dof(10, 0), dof(10, 1), dof(10, 2)});
  first.multiplier_dofs.push_back({dof(3, 0)});
  assembler.set_extra_couplings(first);
  const auto eq = [&](int node, int c) { return m.dofs.equation(dof(node, c)); };
  const Entries with_first = entries_of(assembler.tangent());
  EXPECT_EQ(assembler.n_equations(), n_eq + 1);
  EXPECT_TRUE(with_first.count({eq(7, 0), eq(10, 2)}));
  EXPECT_TRUE(with_first.count({eq(3, 0), n_eq}));
  EXPECT_TRUE(with_first.count({n_eq, n_eq}));

  solver::ExtraCouplings second;  // node 6 with node 15 instead, no multiplier
  second.dof_blocks.push_back({dof(6, 0), dof(6, 1), dof(6, 2), dof(15, 0), dof(15, 1), dof(15, 2)});
  assembler.set_extra_couplings(second);
  const Entries with_second = entries_of(assembler.tangent());
  EXPECT_EQ(assembler.n_equations(), n_eq);
  EXPECT_FALSE(with_second.count({eq(7, 0), eq(10, 2)}));  // the stale coupling is gone
  EXPECT_TRUE(with_second.count({eq(6, 1), eq(15, 0)}));
  EXPECT_TRUE(columns_sorted(assembler.tangent()));
  EXPECT_EQ(assembler.tangent().values.size(), assembler.tangent().nnz());

  // The same as elements plus those couplings built at once, and as a fresh assembler given them.
  Entries expected = elements;
  for (int a : {6, 15})
    for (int b : {6, 15})
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (eq(a, i) <= eq(b, j)) expected.insert({eq(a, i), eq(b, j)});
  EXPECT_EQ(with_second, expected);
  solver::Assembler fresh(m.am, m.dofs);
  fresh.set_extra_couplings(second);
  EXPECT_EQ(entries_of(fresh.tangent()), with_second);

  assembler.set_extra_couplings({});
  EXPECT_EQ(entries_of(assembler.tangent()), elements);
}

// The same couplings given again, listed otherwise (contact's nodes change, not what they
// couple), keep the pattern and zero its values; a subset of them is a change (the stale
// entries go).
TEST(AssemblerPattern, TheSameCouplingsListedOtherwiseKeepThePattern) {
  TwoCubes m;
  ASSERT_TRUE(m.read.ok()) << m.read.report();
  solver::Assembler assembler(m.am, m.dofs);
  const Entries elements = entries_of(assembler.tangent());
  solver::ExtraCouplings extra;
  extra.dof_blocks.push_back({dof(7, 0), dof(7, 1), dof(7, 2), dof(10, 0), dof(10, 1), dof(10, 2)});
  extra.dof_blocks.push_back({dof(6, 0), dof(10, 0)});
  extra.multiplier_dofs.push_back({dof(3, 0), dof(11, 1)});
  assembler.set_extra_couplings(extra);
  const Entries with_extra = entries_of(assembler.tangent());
  const std::vector<std::int64_t> row_idx = assembler.tangent().row_idx;
  const std::int64_t* rows_kept = assembler.tangent().row_idx.data();  // (a rebuild makes new ones)
  const std::int64_t n_equations = assembler.n_equations();
  std::fill(assembler.tangent().values.begin(), assembler.tangent().values.end(), 1.0);

  solver::ExtraCouplings again;  // the blocks in another order, their DOFs too, one repeated
  again.dof_blocks.push_back({dof(10, 0), dof(6, 0)});
  again.dof_blocks.push_back({dof(10, 2), dof(7, 1), dof(10, 1), dof(7, 0), dof(10, 0), dof(7, 2)});
  again.dof_blocks.push_back({dof(6, 0), dof(10, 0)});
  again.multiplier_dofs.push_back({dof(11, 1), dof(3, 0)});
  assembler.set_extra_couplings(again);
  EXPECT_EQ(assembler.tangent().row_idx.data(), rows_kept);
  EXPECT_EQ(assembler.tangent().row_idx, row_idx);
  EXPECT_EQ(assembler.n_equations(), n_equations);
  for (double v : assembler.tangent().values) ASSERT_EQ(v, 0.0);

  solver::ExtraCouplings fewer = again;  // without node 6's block: its coupling is stale
  fewer.dof_blocks.erase(fewer.dof_blocks.begin());
  fewer.dof_blocks.pop_back();
  assembler.set_extra_couplings(fewer);
  const auto eq = [&](int node, int c) { return m.dofs.equation(dof(node, c)); };
  const Entries with_fewer = entries_of(assembler.tangent());
  EXPECT_TRUE(with_extra.count({eq(6, 0), eq(10, 0)}));
  EXPECT_FALSE(with_fewer.count({eq(6, 0), eq(10, 0)}));
  solver::Assembler fresh(m.am, m.dofs);
  fresh.set_extra_couplings(fewer);
  EXPECT_EQ(entries_of(fresh.tangent()), with_fewer);
  EXPECT_NE(with_fewer, elements);
}

// An unsymmetric local matrix (friction's) whose unknowns each feed one equation, in no order,
// one of them none (a held DOF): its symmetric part lands in the upper triangle and its skew
// part in the list, each entry exactly ½(k_ab ± k_ba), as the general path adds it.
TEST(AssemblerUnsymmetric, PlainUnknownsGetTheSymmetricAndSkewPartsExactly) {
  TwoCubes m;
  ASSERT_TRUE(m.read.ok()) << m.read.report();
  solver::Assembler assembler(m.am, m.dofs);
  const std::vector<std::int64_t> block{dof(10, 2), dof(7, 0), dof(1, 0), dof(10, 0), dof(7, 2), dof(7, 1)};
  solver::ExtraCouplings extra;
  extra.dof_blocks.push_back(block);
  assembler.set_extra_couplings(extra);
  solver::Assembler::LocalEquations eqs(block.size());
  for (std::size_t a = 0; a < block.size(); ++a) {
    if (const std::int64_t e = m.dofs.equation(block[a]); e >= 0) eqs[a].push_back({e, 1.0});
  }
  ASSERT_TRUE(eqs[2].empty());  // (node 1 is held)
  const std::size_t n = block.size();
  std::vector<double> k(n * n);
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = 0.37 * static_cast<double>(i % 7) - 0.11 * static_cast<double>(i);
  std::vector<solver::Assembler::SkewEntry> skew;
  assembler.add_unsymmetric_matrix(eqs, k, skew);
  const solver::SparseMatrix& t = assembler.tangent();
  std::size_t skew_checked = 0;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (eqs[a].empty() || eqs[b].empty()) continue;
      const std::int64_t ea = eqs[a][0].first, eb = eqs[b][0].first;
      const double sym = a == b ? k[a * n + a] : 0.5 * (k[a * n + b] + k[b * n + a]);
      if (ea <= eb) {
        EXPECT_EQ(t.values[static_cast<std::size_t>(t.find(ea, eb))], sym) << a << "," << b;
      }
      if (a == b) continue;
      const double skw = 0.5 * (k[a * n + b] - k[b * n + a]);
      const auto it = std::find_if(skew.begin(), skew.end(), [&](const auto& s) { return s.row == ea && s.col == eb; });
      ASSERT_NE(it, skew.end()) << a << "," << b;
      EXPECT_EQ(it->value, skw) << a << "," << b;
      ++skew_checked;
    }
  EXPECT_EQ(skew.size(), skew_checked);  // (one entry per position: none twice, none beyond)

  // The general path (taken when an unknown feeds two equations; here the second with weight
  // 0, which adds nothing) gives the same bits.
  solver::Assembler general(m.am, m.dofs);
  general.set_extra_couplings(extra);
  solver::Assembler::LocalEquations twice = eqs;
  twice[0].push_back({eqs[1][0].first, 0.0});
  std::vector<solver::Assembler::SkewEntry> general_skew;
  general.add_unsymmetric_matrix(twice, k, general_skew);
  EXPECT_EQ(general.tangent().values, t.values);
  std::map<std::pair<std::int64_t, std::int64_t>, double> plain_sums, general_sums;
  for (const auto& e : skew) plain_sums[{e.row, e.col}] += e.value;
  for (const auto& e : general_skew)
    if (e.value != 0.0) general_sums[{e.row, e.col}] += e.value;
  EXPECT_EQ(general_sums, plain_sums);
}

}  // namespace
