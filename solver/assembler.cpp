#include "assembler.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <thread>

#include <fmt/format.h>

#include "elements/element_kernel.hpp"
#include "elements/material.hpp"
#include "element_partition.hpp"
#include "material_states.hpp"

namespace inpact::solver {

void Assembler::element_dofs(std::size_t e, std::vector<std::int64_t>& dofs) const {
  dofs.clear();
  std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;
  const std::size_t n = am_.element_rows(e, rows);
  for (std::size_t a = 0; a < n; ++a)
    for (int c = 0; c < am_.dim; ++c) dofs.push_back(static_cast<std::int64_t>(rows[a]) * am_.dim + c);
}

Assembler::Assembler(const AnalysisModel& am, const DofMap& dofs, int threads, MaterialStates* states)
    : am_(am), dofs_(dofs), threads_(threads), states_(states), world_(rank_world()) {
  if (world_.distributed()) {
    rank_of_element_ = element_partition(am, world_).rank_of_element;
    for (std::size_t e = 0; e < rank_of_element_.size(); ++e)
      if (rank_of_element_[e] == world_.rank) own_elements_.push_back(e);
    rank_of_node_ = element_partition(am, world_).rank_of_node;
  }
  build_element_pattern();
}

std::string describe_distribution(const AnalysisModel& am, RankWorld world) {
  if (!world.distributed()) return "";
  const std::vector<std::size_t>& counts = element_partition(am, world).counts;
  const auto [fewest, most] = std::minmax_element(counts.begin(), counts.end());
  return fmt::format("distributed run on {} MPI ranks: each evaluates {}-{} of the {} elements (PETSc's "
                     "partitioner on the element graph), holds their part of the system and owns the rows of their "
                     "nodes; contact's slave nodes are shared in compact patches of even cost, constraints and "
                     "output are computed alike on every rank, rank 0 writes the results",
                     world.size, *fewest, *most, am.model->mesh.elements.size());
}

void Assembler::block_equations(std::span<const std::int64_t> block, std::vector<std::int64_t>& eqs) const {
  eqs.clear();
  for (std::int64_t d : block)
    for (const auto& m : dofs_.masters(d))
      if (dofs_.equation(m.dof) >= 0) eqs.push_back(dofs_.equation(m.dof));
}

void Assembler::add_couplings(PatternBuilder& pattern, std::span<const std::int64_t> block, std::int64_t multiplier_eq,
                              std::vector<std::int64_t>& eqs) const {
  block_equations(block, eqs);
  if (multiplier_eq < 0) {
    pattern.add_block(eqs);
    return;
  }
  pattern.add_pair(multiplier_eq, multiplier_eq);
  for (std::int64_t e : eqs) pattern.add_pair(e, multiplier_eq);
}

// Pattern: every pair of equations reached from one element's DOFs through their masters (of
// this rank's elements); every diagonal is in it.
void Assembler::build_element_pattern() {
  tangent_ = SparseMatrix{};
  PatternBuilder pattern(dofs_.n_equations());
  std::vector<std::int64_t> el_dofs, eqs;
  for (std::size_t e = 0; e < am_.model->mesh.elements.size(); ++e) {
    if (!owns(e)) continue;
    element_dofs(e, el_dofs);
    add_couplings(pattern, el_dofs, -1, eqs);
  }
  tangent_ = pattern.build(true);
  element_entry_.assign(tangent_.nnz(), true);
}

void Assembler::set_extra_couplings(const ExtraCouplings& extra) {
  const std::int64_t n_eq = dofs_.n_equations();
  const auto n_mult = static_cast<std::int64_t>(extra.multiplier_dofs.size());
  if (has_exactly(extra)) {  // (contact's nodes changed, not the couplings they make)
    tangent_.set_zero();
    return;
  }
  PatternBuilder pattern(n_eq + n_mult);
  std::vector<std::int64_t> eqs;
  for (const auto& block : extra.dof_blocks) add_couplings(pattern, block, -1, eqs);
  for (std::int64_t m = 0; m < n_mult; ++m) add_couplings(pattern, extra.multiplier_dofs[m], n_eq + m, eqs);
  const SparseMatrix added = pattern.build(true);
  std::vector<double>().swap(tangent_.values);  // (assembled anew; freed before the new pattern grows)
  std::vector<bool> element_entry;
  tangent_ = merge_patterns(tangent_, element_entry_, added, element_entry);
  tangent_.values.assign(tangent_.nnz(), 0.0);
  element_entry_ = std::move(element_entry);
}

/// Whether the pattern is already the elements' and exactly `extra`'s couplings: every entry
/// they make is in it (each column walked once from its first row, as scatter() does), and
/// every entry beyond the elements' is one of them.
bool Assembler::has_exactly(const ExtraCouplings& extra) const {
  const std::int64_t n_eq = dofs_.n_equations();
  if (tangent_.n != n_eq + static_cast<std::int64_t>(extra.multiplier_dofs.size())) return false;
  std::vector<bool> hit(tangent_.nnz(), false);  // (a bit an entry, for this call only)
  const std::int64_t* rows = tangent_.row_idx.data();
  // Marks (r, col) for every r of the ascending `eqs` up to `last`; false where one is missing.
  auto mark_column = [&](std::int64_t col, std::span<const std::int64_t> eqs, std::size_t last) {
    const std::int64_t* p = std::lower_bound(rows + tangent_.col_ptr[col], rows + tangent_.col_ptr[col + 1], eqs[0]);
    const std::int64_t* end = rows + tangent_.col_ptr[col + 1];
    for (std::size_t i = 0; i <= last; ++i) {
      while (p < end && *p < eqs[i]) ++p;
      if (p == end || *p != eqs[i]) return false;
      hit[static_cast<std::size_t>(p - rows)] = true;
    }
    return true;
  };
  std::vector<std::int64_t> eqs;
  auto equations_of = [&](std::span<const std::int64_t> block) {  // (ascending, once each)
    block_equations(block, eqs);
    std::sort(eqs.begin(), eqs.end());
    eqs.erase(std::unique(eqs.begin(), eqs.end()), eqs.end());
  };
  for (const auto& block : extra.dof_blocks) {
    equations_of(block);
    for (std::size_t j = 0; j < eqs.size(); ++j)
      if (!mark_column(eqs[j], eqs, j)) return false;
  }
  for (std::size_t m = 0; m < extra.multiplier_dofs.size(); ++m) {
    equations_of(extra.multiplier_dofs[m]);
    eqs.push_back(n_eq + static_cast<std::int64_t>(m));  // (above every DOF equation)
    if (!mark_column(eqs.back(), eqs, eqs.size() - 1)) return false;
  }
  for (std::size_t k = 0; k < hit.size(); ++k)
    if (!element_entry_[k] && !hit[k]) return false;
  return true;
}

void Assembler::add_diagonal(std::int64_t dof, double value) {
  if (dofs_.kind(dof) != DofMap::Kind::Free || !owns_node(dof / am_.dim)) return;
  tangent_.values[tangent_.find(dofs_.equation(dof), dofs_.equation(dof))] += value;
}

namespace {

/// The positions a of the local unknowns that have an equation (eq[a] >= 0), by ascending
/// equation, into `order`; how many, or −1 when two share an equation (the column walks of
/// scatter() and add_unsymmetric_plain() need each position once).
std::ptrdiff_t order_by_equation(std::span<const std::int64_t> eq, std::span<std::uint16_t> order) {
  std::size_t n_free = 0;
  for (std::size_t a = 0; a < eq.size(); ++a) {
    if (eq[a] < 0) continue;
    std::size_t i = n_free++;
    for (; i > 0 && eq[order[i - 1]] > eq[a]; --i) order[i] = order[i - 1];
    order[i] = static_cast<std::uint16_t>(a);
  }
  for (std::size_t i = 1; i < n_free; ++i)
    if (eq[order[i - 1]] == eq[order[i]]) return -1;
  return static_cast<std::ptrdiff_t>(n_free);
}

}  // namespace

// Positions are found in each column rather than cached: a cache of every element entry's
// position costs ~14 kB per hexahedron (14 GB at a million elements). When no element DOF is
// tied by an *EQUATION (the usual case), the element's equations are sorted once and each
// column is walked once from the first of them (one binary search per column instead of one
// per entry); every entry receives the same addition as before, so the sum is bit-identical.
void Assembler::scatter(std::span<const std::int64_t> el_dofs, std::span<const double> k) {
  const std::size_t n = el_dofs.size();
  bool plain = n <= kMaxLocal;
  for (std::size_t a = 0; plain && a < n; ++a) plain = dofs_.kind(el_dofs[a]) != DofMap::Kind::Dependent;
  std::array<std::int64_t, kMaxLocal> eq;
  std::array<std::uint16_t, kMaxLocal> order;  // local DOFs with an equation, ascending
  std::size_t n_free = 0;
  if (plain) {
    for (std::size_t a = 0; a < n; ++a) eq[a] = dofs_.equation(el_dofs[a]);
    const std::ptrdiff_t sorted = order_by_equation({eq.data(), n}, order);
    plain = sorted >= 0;
    n_free = plain ? static_cast<std::size_t>(sorted) : 0;
  }
  if (plain) {  // (a node listed twice, as in a collapsed brick, takes the general path below)
    if (n_free == 0) return;
    const std::int64_t* rows = tangent_.row_idx.data();
    double* values = tangent_.values.data();
    for (std::size_t j = 0; j < n_free; ++j) {  // column eb, rows ea <= eb: the first j + 1 in order
      const std::size_t b = order[j];
      const std::int64_t eb = eq[b];
      const std::int64_t* p = std::lower_bound(rows + tangent_.col_ptr[eb], rows + tangent_.col_ptr[eb + 1],
                                               eq[order[0]]);
      for (std::size_t i = 0; i <= j; ++i) {
        const std::size_t a = order[i];
        while (*p < eq[a]) ++p;  // the pattern holds every (ea, eb) of the element
        const double kab = k[a * n + b];
        if (kab != 0.0) values[p - rows] += kab;
      }
    }
    return;
  }
  for (std::size_t a = 0; a < n; ++a)
    for (const auto& ma : dofs_.masters(el_dofs[a])) {
      const std::int64_t ea = dofs_.equation(ma.dof);
      if (ea < 0) continue;
      for (std::size_t b = 0; b < n; ++b) {
        const double kab = k[a * n + b];
        if (kab == 0.0) continue;
        for (const auto& mb : dofs_.masters(el_dofs[b])) {
          const std::int64_t eb = dofs_.equation(mb.dof);
          if (eb < ea) continue;  // upper triangle: row <= col
          tangent_.values[tangent_.find(ea, eb)] += ma.weight * mb.weight * kab;
        }
      }
    }
}

void Assembler::compute(std::size_t e, std::span<const double> u, const AssemblyRequest& request,
                        elements::ElementSystem& out) const {
  const auto& mesh = am_.model->mesh;
  const ElementSetup& setup = am_.elements[e];
  elements::ElementRequest er;
  er.stiffness = request.tangent;
  er.internal_force = true;
  er.nlgeom = request.nlgeom;
  er.point_output = request.points;
  if (setup.rigid) {  // no stiffness, no points: its nodes follow the body
    out = elements::ElementSystem{};
    out.min_jacobian = std::numeric_limits<double>::infinity();
    return;
  }
  const auto nodes = mesh.elements.nodes_of(e);
  // Gathered on the stack: no allocation per element (at most 20 nodes × 3 DOFs).
  constexpr std::size_t kMaxNodes = 32;
  if (nodes.size() > kMaxNodes) {
    elements::compute_element(*setup.type, am_.coords(e), std::vector<double>(), *setup.material, setup.section, er,
                              {}, {}, out);  // throws: no element type has this many nodes
    return;
  }
  std::array<elements::Vec3, kMaxNodes> x;
  std::array<double, kMaxNodes * 3> u_el;
  std::array<double, 2 * kMaxNodes> dt_el;  // ΔT, and a shell's gradient change after it
  std::array<double, 2 * kMaxNodes> temperature_el;  // T (and a shell's ∂T/∂n) for temperature-dependent data
  std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;
  const std::size_t n_rows = am_.element_rows(e, rows);  // a beam's rotations follow its nodes
  const std::size_t dim = static_cast<std::size_t>(am_.dim);
  for (std::size_t a = 0; a < nodes.size(); ++a) x[a] = mesh.nodes.coords[static_cast<std::size_t>(nodes[a])];
  const std::size_t n_dt = am_.element_temperature_changes(e, request.delta_t, dt_el);
  if (am_.reads_temperatures(e))
    er.temperature = std::span(temperature_el).first(am_.element_temperatures(e, request.delta_t, temperature_el));
  for (std::size_t a = 0; a < n_rows; ++a)
    for (std::size_t c = 0; c < dim; ++c) u_el[a * dim + c] = u[static_cast<std::size_t>(rows[a]) * dim + c];
  const std::size_t n = nodes.size();
  // *MODEL CHANGE: an inactive element is at zero strain (its output is zero); one reactivated
  // strain free measures its displacement from its reference one, on the original geometry at
  // small strain and from the configuration it was reactivated in under NLGEOM.
  const bool inactive = elements_ && !elements_->is_active(e);
  const std::span<const double> reference = inactive || !references_ ? std::span<const double>() : references_->of(e);
  if (inactive || !reference.empty())
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t c = 0; c < dim; ++c) {
        const double shift = inactive ? u_el[a * dim + c] : reference[a * dim + c];
        if (request.nlgeom) x[a][c] += shift;
        u_el[a * dim + c] -= shift;
      }
  const elements::ElementHistory history = states_ ? states_->assembly_history(e) : elements::ElementHistory{};
  elements::compute_element(*setup.type, std::span(x).first(n), std::span(u_el).first(n_rows * dim), *setup.material,
                            setup.section, er,
                            std::span<const double>(dt_el).first(n_dt),
                            history, out);
}

void Assembler::multiply(std::span<const std::int64_t> el_dofs, const elements::ElementSystem& sys,
                         const AssemblyRequest& request, PerField& moved) const {
  const std::size_t n = el_dofs.size();
  const std::span<const double> k = sys.stiffness;
  for (std::size_t a = 0; a < n; ++a) {
    double sum = 0.0;
    for (std::size_t b = 0; b < n; ++b) sum += k[a * n + b] * request.multiply[static_cast<std::size_t>(el_dofs[b])];
    request.product[static_cast<std::size_t>(el_dofs[a])] += sum;
    moved[dofs_.field(el_dofs[a])] += std::abs(sys.internal_force[a] + sum);
  }
}

AssemblyResult Assembler::assemble(std::span<const double> u, const AssemblyRequest& request, std::span<double> f_int) {
  const ScopedSeconds clock(seconds_.element_assembly, &seconds_.element_assemblies);
  AssemblyResult result;
  std::fill(f_int.begin(), f_int.end(), 0.0);
  if (request.tangent) tangent_.set_zero();
  const std::size_t n_el = am_.model->mesh.elements.size();
  // Points are kept for every element; otherwise a distributed run's rank evaluates its own.
  const bool partitioned = world_.distributed() && !request.points;
  const std::size_t n_listed = partitioned ? own_elements_.size() : n_el;
  const auto element_at = [&](std::size_t i) { return partitioned ? own_elements_[i] : i; };

  // Element systems are computed in parallel chunk by chunk and added in element order by one
  // thread, so the assembled numbers do not depend on the thread count.
  const std::size_t n_threads = static_cast<std::size_t>(std::max(threads_, 1));
  const std::size_t chunk = n_threads == 1 ? 1 : 512 * n_threads;
  std::vector<elements::ElementSystem> systems(std::min(chunk, n_listed));
  std::vector<std::int64_t> el_dofs;
  if (request.points) {
    have_points_ = false;  // until every element is in
    points_.offset.assign(1, 0);
    points_.points.clear();
  }
  FieldSums sums;
  for (std::size_t begin = 0; begin < n_listed; begin += chunk) {
    const std::size_t end = std::min(begin + chunk, n_listed);
    auto work = [&](std::size_t t) {
      for (std::size_t i = begin + t; i < end; i += n_threads) compute(element_at(i), u, request, systems[i - begin]);
    };
    if (n_threads == 1) {
      work(0);
    } else {
      std::vector<std::jthread> pool;
      for (std::size_t t = 1; t < n_threads; ++t) pool.emplace_back(work, t);
      work(0);
    }
    for (std::size_t at = begin; at < end; ++at) {
      const std::size_t e = element_at(at);
      const elements::ElementSystem& sys = systems[at - begin];
      result.jacobian.offer(sys.min_jacobian, static_cast<std::int64_t>(e));
      if (request.nlgeom) result.volume_ratio.offer(sys.min_volume_ratio, static_cast<std::int64_t>(e));
      if (request.points) {
        points_.points.insert(points_.points.end(), sys.points.begin(), sys.points.end());
        points_.offset.push_back(points_.points.size());
      }
      if (elements_ && !elements_->is_active(e)) continue;
      element_dofs(e, el_dofs);
      if (sys.internal_force.size() != el_dofs.size()) continue;  // inverted: reported by min_jacobian
      for (std::size_t i = 0; i < el_dofs.size(); ++i) {
        f_int[el_dofs[i]] += sys.internal_force[i];
        const Field field = dofs_.field(el_dofs[i]);
        sums.force[field] += std::abs(sys.internal_force[i]);
        sums.count[field] += 1.0;
      }
      if (request.tangent && owns(e)) scatter(el_dofs, sys.stiffness);
      if (request.tangent && !request.multiply.empty()) multiply(el_dofs, sys, request, sums.moved);
    }
  }
  if (partitioned) sum_over_ranks(request, f_int, sums, result);
  for (std::size_t field = 0; field < kFields; ++field) {
    const double count = sums.count[field];
    result.average_force[field] = count > 0 ? sums.force[field] / count : 0.0;
    result.n_force_entries[field] = static_cast<std::size_t>(count);
    result.moved_average_force[field] = count > 0 ? sums.moved[field] / count : 0.0;
  }
  if (request.points) {
    points_u_.assign(u.begin(), u.end());
    points_delta_t_.assign(request.delta_t.begin(), request.delta_t.end());
    points_nlgeom_ = request.nlgeom;
    have_points_ = true;
  }
  return result;
}

/// The product K·v (request.product, zero before the assembly) is summed with the forces.
void Assembler::sum_over_ranks(const AssemblyRequest& request, std::span<double> f_int, FieldSums& sums,
                               AssemblyResult& result) const {
  world_.sum(f_int);
  if (request.tangent && !request.multiply.empty()) world_.sum(request.product);
  world_.sum(sums.force);
  world_.sum(sums.moved);
  world_.sum(sums.count);
  smallest_over_ranks(result.jacobian);
  smallest_over_ranks(result.volume_ratio);
}

/// The smallest value over the ranks and the lowest element row that has it (a rank without
/// elements offers none; none anywhere stays none).
void Assembler::smallest_over_ranks(SmallestAtElement& smallest) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const double local = smallest.element < 0 ? kNone : smallest.value;
  const double value = world_.min(local);
  const double candidate = local == value ? static_cast<double>(smallest.element) : kNone;
  const double element = world_.min(candidate);
  smallest = value == kNone ? SmallestAtElement{} : SmallestAtElement{value, static_cast<std::int64_t>(element)};
}

void Assembler::complete_states(std::span<const double> u, const AssemblyRequest& request) {
  if (!world_.distributed()) return;
  AssemblyRequest everywhere{.tangent = false, .nlgeom = request.nlgeom, .delta_t = request.delta_t, .points = true};
  std::vector<double> f_int(u.size());
  assemble(u, everywhere, f_int);
}

std::vector<double> Assembler::element_forces(std::span<const std::int32_t> rows, std::span<const double> u,
                                             const AssemblyRequest& request) {
  std::vector<double> f(u.size(), 0.0);
  elements::ElementSystem sys;
  std::vector<std::int64_t> el_dofs;
  AssemblyRequest forces_only = request;
  forces_only.tangent = false;
  forces_only.points = false;
  for (std::int32_t row : rows) {
    const auto e = static_cast<std::size_t>(row);
    compute(e, u, forces_only, sys);
    element_dofs(e, el_dofs);
    if (sys.internal_force.size() != el_dofs.size()) continue;
    for (std::size_t i = 0; i < el_dofs.size(); ++i) f[static_cast<std::size_t>(el_dofs[i])] += sys.internal_force[i];
  }
  return f;
}

const ElementPoints* Assembler::points_at(std::span<const double> u, std::span<const double> delta_t,
                                          bool nlgeom) const {
  if (!have_points_ || nlgeom != points_nlgeom_ || !std::ranges::equal(u, points_u_) ||
      !std::ranges::equal(delta_t, points_delta_t_))
    return nullptr;
  return &points_;
}

void Assembler::reduce(std::span<const double> full, std::span<double> reduced) const {
  std::fill(reduced.begin(), reduced.end(), 0.0);
  for (std::int64_t d = 0; d < dofs_.n_dof(); ++d)
    for (const auto& m : dofs_.masters(d)) {
      const std::int64_t eq = dofs_.equation(m.dof);
      if (eq >= 0) reduced[eq] += m.weight * full[d];
    }
}

void Assembler::add_unsymmetric_matrix(const LocalEquations& eqs, std::span<const double> k,
                                       std::vector<SkewEntry>& skew) {
  if (add_unsymmetric_plain(eqs, k, skew)) return;
  const std::size_t n = eqs.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a; b < n; ++b) {
      const double sym = a == b ? k[a * n + a] : 0.5 * (k[a * n + b] + k[b * n + a]);
      const double skw = a == b ? 0.0 : 0.5 * (k[a * n + b] - k[b * n + a]);
      if (sym == 0.0 && skw == 0.0) continue;
      for (const auto& [ea, wa] : eqs[a])
        for (const auto& [eb, wb] : eqs[b]) {
          // Entry (ea, eb) gets w (sym + skw), entry (eb, ea) w (sym − skw); when a ≠ b both land
          // in the upper triangle's one position for the symmetric part.
          const double w = wa * wb;
          if (sym != 0.0) {
            const std::int64_t pos = tangent_.find(std::min(ea, eb), std::max(ea, eb));
            if (pos >= 0) tangent_.values[pos] += (ea == eb && a != b ? 2.0 : 1.0) * w * sym;
          }
          if (skw != 0.0 && ea != eb) {
            skew.push_back({ea, eb, w * skw});
            skew.push_back({eb, ea, -w * skw});
          }
        }
    }
}

/// add_unsymmetric_matrix() where each unknown feeds one equation of its own with weight 1 (no
/// constraint masters, none repeated): the symmetric part by the sorted column walk of
/// scatter(), one addition per entry as in the general path (the same sums, to the bit). False,
/// with nothing added, otherwise.
bool Assembler::add_unsymmetric_plain(const LocalEquations& eqs, std::span<const double> k,
                                      std::vector<SkewEntry>& skew) {
  const std::size_t n = eqs.size();
  if (n > kMaxLocal) return false;
  std::array<std::int64_t, kMaxLocal> eq;
  std::array<std::uint16_t, kMaxLocal> order;  // local unknowns with an equation, ascending
  for (std::size_t a = 0; a < n; ++a) {
    if (eqs[a].size() > 1 || (eqs[a].size() == 1 && eqs[a][0].second != 1.0)) return false;
    eq[a] = eqs[a].empty() ? -1 : eqs[a][0].first;
  }
  const std::ptrdiff_t sorted = order_by_equation({eq.data(), n}, order);
  if (sorted < 0) return false;
  const auto n_free = static_cast<std::size_t>(sorted);
  const std::int64_t* rows = tangent_.row_idx.data();
  double* values = tangent_.values.data();
  for (std::size_t j = 0; j < n_free; ++j) {  // column eq[b], rows up to it: the first j + 1 in order
    const std::size_t b = order[j];
    const std::int64_t* p = std::lower_bound(rows + tangent_.col_ptr[eq[b]], rows + tangent_.col_ptr[eq[b] + 1],
                                             eq[order[0]]);
    const std::int64_t* end = rows + tangent_.col_ptr[eq[b] + 1];
    for (std::size_t i = 0; i <= j; ++i) {
      const std::size_t a = order[i];
      const double sym = a == b ? k[a * n + a] : 0.5 * (k[a * n + b] + k[b * n + a]);
      const double skw = a == b ? 0.0 : 0.5 * (k[a * n + b] - k[b * n + a]);
      while (p < end && *p < eq[a]) ++p;
      if (sym != 0.0 && p < end && *p == eq[a]) values[p - rows] += sym;
      // The skew pairs in another order than the general path's, each position once a call: the
      // same sums (unsymmetric_tangent adds them position by position in list order).
      if (skw != 0.0) {
        const std::size_t lo = std::min(a, b), hi = std::max(a, b);
        const double v = lo == a ? skw : -skw;  // ½(k_lo,hi − k_hi,lo)
        skew.push_back({eq[lo], eq[hi], v});
        skew.push_back({eq[hi], eq[lo], -v});
      }
    }
  }
  return true;
}

void Assembler::add_multiplier_column(std::int64_t row, std::span<const std::int64_t> dofs, double scale,
                                      std::span<const double> gradient, double diagonal) {
  if (diagonal != 0.0)
    if (const std::int64_t pos = tangent_.find(row, row); pos >= 0) tangent_.values[pos] += diagonal;
  for (std::size_t a = 0; a < dofs.size(); ++a)
    for (const auto& ma : dofs_.masters(dofs[a])) {
      const std::int64_t ea = dofs_.equation(ma.dof);
      if (ea < 0) continue;
      const std::int64_t pos = tangent_.find(ea, row);
      if (pos >= 0) tangent_.values[pos] += ma.weight * scale * gradient[a];
    }
}

}  // namespace inpact::solver
