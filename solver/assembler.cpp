#include "assembler.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "elements/element_kernel.hpp"

namespace inpact::solver {

void Assembler::element_dofs(std::size_t e, std::vector<std::int64_t>& dofs) const {
  dofs.clear();
  for (std::int32_t node : am_.model->mesh.elements.nodes_of(e))
    for (int c = 0; c < am_.dim; ++c) dofs.push_back(static_cast<std::int64_t>(node) * am_.dim + c);
}

Assembler::Assembler(const AnalysisModel& am, const DofMap& dofs, int threads) : am_(am), dofs_(dofs), threads_(threads) {
  const std::size_t n_el = am.model->mesh.elements.size();
  // Pattern: every pair of equations reached from one element's DOFs through their masters.
  PatternBuilder pattern(dofs.n_equations());
  std::vector<std::int64_t> el_dofs, eqs;
  for (std::size_t e = 0; e < n_el; ++e) {
    element_dofs(e, el_dofs);
    eqs.clear();
    for (std::int64_t d : el_dofs)
      for (const auto& m : dofs.masters(d))
        if (dofs.equation(m.dof) >= 0) eqs.push_back(dofs.equation(m.dof));
    pattern.add_block(eqs);
  }
  tangent_ = pattern.build(true);

}

// Positions are found by binary search in each column rather than cached: a cache of every
// element entry's position costs ~14 kB per hexahedron (14 GB at a million elements), while the
// search is cheap next to computing the element matrix.
void Assembler::scatter(std::span<const std::int64_t> el_dofs, std::span<const double> k) {
  const std::size_t n = el_dofs.size();
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

elements::ElementSystem Assembler::compute(std::size_t e, std::span<const double> u, const AssemblyRequest& request) const {
  const auto& mesh = am_.model->mesh;
  const ElementSetup& setup = am_.elements[e];
  elements::ElementRequest er;
  er.stiffness = request.tangent;
  er.internal_force = true;
  er.nlgeom = request.nlgeom;
  const auto nodes = mesh.elements.nodes_of(e);
  std::vector<double> u_el, dt_el;
  u_el.reserve(nodes.size() * am_.dim);
  for (std::int32_t node : nodes) {
    for (int c = 0; c < am_.dim; ++c) u_el.push_back(u[static_cast<std::size_t>(node) * am_.dim + c]);
    if (!request.delta_t.empty()) dt_el.push_back(request.delta_t[node]);
  }
  return elements::compute_element(*setup.type, am_.coords(e), u_el, setup.material, setup.section, er, dt_el);
}

AssemblyResult Assembler::assemble(std::span<const double> u, const AssemblyRequest& request, std::span<double> f_int) {
  AssemblyResult result;
  std::fill(f_int.begin(), f_int.end(), 0.0);
  if (request.tangent) tangent_.set_zero();
  const std::size_t n_el = am_.model->mesh.elements.size();

  // Element systems are computed in parallel chunk by chunk and added in element order by one
  // thread, so the assembled numbers do not depend on the thread count.
  const std::size_t n_threads = static_cast<std::size_t>(std::max(threads_, 1));
  const std::size_t chunk = n_threads == 1 ? 1 : 512 * n_threads;
  std::vector<elements::ElementSystem> systems(std::min(chunk, n_el));
  std::vector<std::int64_t> el_dofs;
  double force_sum = 0.0;
  std::size_t force_count = 0;
  for (std::size_t begin = 0; begin < n_el; begin += chunk) {
    const std::size_t end = std::min(begin + chunk, n_el);
    auto work = [&](std::size_t t) {
      for (std::size_t e = begin + t; e < end; e += n_threads) systems[e - begin] = compute(e, u, request);
    };
    if (n_threads == 1) {
      work(0);
    } else {
      std::vector<std::jthread> pool;
      for (std::size_t t = 1; t < n_threads; ++t) pool.emplace_back(work, t);
      work(0);
    }
    for (std::size_t e = begin; e < end; ++e) {
      const elements::ElementSystem& sys = systems[e - begin];
      if (result.min_jacobian_element < 0 || sys.min_jacobian < result.min_jacobian) {
        result.min_jacobian = sys.min_jacobian;
        result.min_jacobian_element = static_cast<std::int64_t>(e);
      }
      element_dofs(e, el_dofs);
      for (std::size_t i = 0; i < el_dofs.size(); ++i) {
        f_int[el_dofs[i]] += sys.internal_force[i];
        force_sum += std::abs(sys.internal_force[i]);
      }
      force_count += el_dofs.size();
      if (request.tangent) scatter(el_dofs, sys.stiffness);
    }
  }
  result.average_force = force_count ? force_sum / static_cast<double>(force_count) : 0.0;
  result.n_force_entries = force_count;
  return result;
}

void Assembler::reduce(std::span<const double> full, std::span<double> reduced) const {
  std::fill(reduced.begin(), reduced.end(), 0.0);
  for (std::int64_t d = 0; d < dofs_.n_dof(); ++d)
    for (const auto& m : dofs_.masters(d)) {
      const std::int64_t eq = dofs_.equation(m.dof);
      if (eq >= 0) reduced[eq] += m.weight * full[d];
    }
}

}  // namespace inpact::solver
