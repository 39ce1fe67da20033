#include "dof_map.hpp"

#include <map>

#include <fmt/format.h>

#include "analysis_error.hpp"

namespace inpact::solver {

std::span<const MasterTerm> DofMap::masters(std::int64_t d) const {
  return {master_.data() + master_ptr_[d], static_cast<std::size_t>(master_ptr_[d + 1] - master_ptr_[d])};
}

void DofMap::update_dependent(std::vector<double>& u) const {
  for (std::int64_t d = 0; d < n_dof(); ++d) {
    if (kind_[d] != Kind::Dependent) continue;
    double v = 0.0;
    for (const auto& m : masters(d)) v += m.weight * u[m.dof];
    u[d] = v;
  }
}

namespace {

/// *TIE: each tied slave node's translations u_s,c = Σ N_a u_a,c over its master nodes a
/// (contact/tie.hpp resolved which nodes and checked them against boundary conditions, equations
/// and other ties; a slave DOF prescribed anyway stays prescribed).
void add_tie_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind,
                        std::map<std::int64_t, std::vector<MasterTerm>>& dependent) {
  const model::Model& m = *am.model;
  for (const contact::ResolvedTie& r : am.ties)
    for (const contact::TiedNode& n : r.tied)
      for (int c = 0; c < am.dim; ++c) {
        const std::int64_t d = static_cast<std::int64_t>(n.slave) * am.dim + c;
        if (kind[d] == DofMap::Kind::Prescribed) continue;
        if (dependent.count(d))
          throw AnalysisError(fmt::format("{}: error: *TIE: tie {}: slave node {} is already eliminated by another constraint",
                                          m.sources.describe(r.tie->line_loc), r.tie->name, m.mesh.nodes.labels[n.slave]));
        std::vector<MasterTerm> terms;
        for (std::size_t k = 0; k < n.masters.size(); ++k)
          terms.push_back({static_cast<std::int64_t>(n.masters[k]) * am.dim + c, n.weights[k]});
        dependent[d] = std::move(terms);
        kind[d] = DofMap::Kind::Dependent;
      }
}

/// *PRE-TENSION SECTION: each copy of a section node moves with its original plus the normal
/// times the tightening, u_copy,c = u_orig,c + n_c u_P1 (model/loads.hpp); DOF 1 of the
/// pre-tension node P is an unknown (or prescribed) though no element connects P.
void add_pretension_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind,
                               std::map<std::int64_t, std::vector<MasterTerm>>& dependent) {
  for (const model::PretensionSection& s : am.model->pretension_sections) {
    const std::int64_t p = static_cast<std::int64_t>(s.node) * am.dim;
    for (const auto& [orig, copy] : s.node_pairs)
      for (int c = 0; c < am.dim; ++c) {
        const std::int64_t d = static_cast<std::int64_t>(copy) * am.dim + c;
        std::vector<MasterTerm> terms{{static_cast<std::int64_t>(orig) * am.dim + c, 1.0}};
        if (s.normal[c] != 0.0) terms.push_back({p, s.normal[c]});
        dependent[d] = std::move(terms);
        kind[d] = DofMap::Kind::Dependent;
      }
  }
}

}  // namespace

DofMap DofMap::build(const AnalysisModel& am, const std::vector<std::uint8_t>& prescribed) {
  const model::Model& m = *am.model;
  const std::int64_t n = static_cast<std::int64_t>(am.n_dof());
  DofMap map;
  map.kind_.assign(n, Kind::Unused);
  // A DOF is used when an element connects its node.
  for (std::size_t e = 0; e < m.mesh.elements.size(); ++e)
    for (std::int32_t node : m.mesh.elements.nodes_of(e))
      for (int c = 0; c < am.dim; ++c) map.kind_[static_cast<std::int64_t>(node) * am.dim + c] = Kind::Free;
  for (const model::PretensionSection& s : m.pretension_sections)
    map.kind_[static_cast<std::int64_t>(s.node) * am.dim] = Kind::Free;
  for (std::int64_t d = 0; d < n; ++d)
    if (prescribed[d] && map.kind_[d] == Kind::Free) map.kind_[d] = Kind::Prescribed;

  // *EQUATION: the first term's DOF is eliminated: u0 = −Σ_{k≥1} (c_k / c_0) u_k.
  std::map<std::int64_t, std::vector<MasterTerm>> dependent;
  auto dof_of = [&](const model::Equation::Term& t) { return static_cast<std::int64_t>(t.node) * am.dim + (t.dof - 1); };
  for (const auto& eq : m.equations) {
    const std::string where = m.sources.describe(eq.loc);
    for (const auto& t : eq.terms)
      if (t.dof > am.dim)
        throw AnalysisError(fmt::format("{}: error: *EQUATION: degree of freedom {} does not exist in this model (nodes have {})",
                                        where, t.dof, am.dim));
    const std::int64_t d0 = dof_of(eq.terms[0]);
    if (map.kind_[d0] == Kind::Prescribed)
      throw AnalysisError(fmt::format("{}: error: *EQUATION: the first (eliminated) degree of freedom, node {} dof {}, also "
                                      "has a boundary condition; put another DOF first", where,
                                      m.mesh.nodes.labels[eq.terms[0].node], eq.terms[0].dof));
    if (dependent.count(d0))
      throw AnalysisError(fmt::format("{}: error: *EQUATION: node {} dof {} is already eliminated by another equation", where,
                                      m.mesh.nodes.labels[eq.terms[0].node], eq.terms[0].dof));
    std::vector<MasterTerm> terms;
    for (std::size_t k = 1; k < eq.terms.size(); ++k)
      terms.push_back({dof_of(eq.terms[k]), -eq.terms[k].coefficient / eq.terms[0].coefficient});
    dependent[d0] = std::move(terms);
    map.kind_[d0] = Kind::Dependent;
  }
  add_tie_dependents(am, map.kind_, dependent);
  add_pretension_dependents(am, map.kind_, dependent);
  // Substitute dependents into each other until every term is independent (a tie's master node
  // that is itself tied elsewhere, an equation on a tied node: chains resolve here).
  for (auto& [d, terms] : dependent) {
    for (int pass = 0;; ++pass) {
      if (pass > static_cast<int>(dependent.size()))
        throw AnalysisError("*EQUATION / *TIE: the constraints eliminate each other's degrees of freedom in a cycle");
      std::vector<MasterTerm> next;
      bool substituted = false;
      for (const auto& t : terms) {
        auto it = dependent.find(t.dof);
        if (it == dependent.end() || it->first == d) {
          next.push_back(t);
          continue;
        }
        substituted = true;
        for (const auto& s : it->second) next.push_back({s.dof, t.weight * s.weight});
      }
      terms = std::move(next);
      if (!substituted) break;
    }
  }

  map.eq_.assign(n, -1);
  map.master_ptr_.assign(n + 1, 0);
  for (std::int64_t d = 0; d < n; ++d) {
    if (map.kind_[d] == Kind::Free) map.eq_[d] = map.n_eq_++;
    if (map.kind_[d] == Kind::Dependent) {
      for (const auto& t : dependent[d]) map.master_.push_back(t);
    } else if (map.kind_[d] != Kind::Unused) {
      map.master_.push_back({d, 1.0});
    }
    map.master_ptr_[d + 1] = static_cast<std::int64_t>(map.master_.size());
  }
  return map;
}

}  // namespace inpact::solver
