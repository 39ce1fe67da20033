#include "assembler.hpp"

#include <cmath>

#include "elements/element_kernel.hpp"

namespace inpact::solver {

void Assembler::element_dofs(std::size_t e, std::vector<std::int64_t>& dofs) const {
  dofs.clear();
  for (std::int32_t node : am_.model->mesh.elements.nodes_of(e))
    for (int c = 0; c < am_.dim; ++c) dofs.push_back(static_cast<std::int64_t>(node) * am_.dim + c);
}

Assembler::Assembler(const AnalysisModel& am, const DofMap& dofs) : am_(am), dofs_(dofs) {
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

AssemblyResult Assembler::assemble(std::span<const double> u, const AssemblyRequest& request, std::span<double> f_int) {
  AssemblyResult result;
  std::fill(f_int.begin(), f_int.end(), 0.0);
  if (request.tangent) tangent_.set_zero();
  const auto& mesh = am_.model->mesh;
  elements::ElementRequest er;
  er.stiffness = request.tangent;
  er.internal_force = true;
  er.nlgeom = request.nlgeom;

  std::vector<std::int64_t> el_dofs;
  std::vector<double> u_el, dt_el;
  double force_sum = 0.0;
  std::size_t force_count = 0;
  bool first = true;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const ElementSetup& setup = am_.elements[e];
    element_dofs(e, el_dofs);
    u_el.resize(el_dofs.size());
    for (std::size_t i = 0; i < el_dofs.size(); ++i) u_el[i] = u[el_dofs[i]];
    dt_el.clear();
    if (!request.delta_t.empty())
      for (std::int32_t node : mesh.elements.nodes_of(e)) dt_el.push_back(request.delta_t[node]);
    const auto coords = am_.coords(e);
    const elements::ElementSystem sys =
        elements::compute_element(*setup.type, coords, u_el, setup.material, setup.section, er, dt_el);
    if (first || sys.min_jacobian < result.min_jacobian) {
      result.min_jacobian = sys.min_jacobian;
      result.min_jacobian_element = static_cast<std::int64_t>(e);
      first = false;
    }
    for (std::size_t i = 0; i < el_dofs.size(); ++i) {
      f_int[el_dofs[i]] += sys.internal_force[i];
      force_sum += std::abs(sys.internal_force[i]);
    }
    force_count += el_dofs.size();
    if (request.tangent) scatter(el_dofs, sys.stiffness);
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
