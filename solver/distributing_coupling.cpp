#include "distributing_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analysis_error.hpp"
#include "constraint_elimination.hpp"
#include "contact/contact_surface.hpp"

namespace inpact::solver {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// The weighting function of WEIGHTING METHOD at ρ = r / r0 [K16 *DISTRIBUTING].
double weighting_function(model::Coupling::Weighting w, double rho) {
  switch (w) {
    case model::Coupling::Weighting::Uniform: return 1.0;
    case model::Coupling::Weighting::Linear: return 1.0 - rho;
    case model::Coupling::Weighting::Quadratic: return 1.0 - rho * rho;
    case model::Coupling::Weighting::Cubic: return 1.0 - 3.0 * rho * rho + 2.0 * rho * rho * rho;
  }
  return 1.0;
}

/// The area each coupling node stands for: its consistent share ∫ N dA of the element faces on the
/// reference coordinates (CalculiX's weights; a force through the coupling then loads the face
/// as a uniform traction would), or the area a node-based surface gives it.
std::vector<double> tributary_areas(const AnalysisModel& am, const model::Coupling& c) {
  const model::Model& m = *am.model;
  const contact::ContactSurface s = contact::ContactSurface::build(m, m.mesh.surfaces.at(c.surface));
  const std::vector<double> shares = s.consistent_nodal_areas(m.mesh.nodes.coords);
  std::vector<double> out;
  for (std::int32_t n : c.nodes) out.push_back(shares[static_cast<std::size_t>(s.local_index(n))]);
  return out;
}

Vector3d position(const model::Model& m, std::int32_t node) {
  const auto& x = m.mesh.nodes.coords[static_cast<std::size_t>(node)];
  return {x[0], x[1], x[2]};
}

/// [a]×: [a]× b = a × b.
Matrix3d skew(const Vector3d& a) {
  Matrix3d s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

std::string where(const AnalysisModel& am, const model::Coupling& c) {
  return fmt::format("{}: error: {}: coupling '{}'", am.model->sources.describe(c.loc), c.keyword(), c.name);
}

/// Σ w u of `terms` over DOFs without a rule: each dependent DOF replaced by its rule, chains
/// followed (a cycle is a deck error).
std::map<std::int64_t, double> without_rules(const std::vector<MasterTerm>& terms,
                                             const std::map<std::int64_t, std::vector<MasterTerm>>& dependent) {
  std::map<std::int64_t, double> current;
  for (const MasterTerm& t : terms) current[t.dof] += t.weight;
  for (std::size_t pass = 0;; ++pass) {
    if (pass > dependent.size())
      throw AnalysisError("*EQUATION / coupling: the constraints eliminate each other's degrees of freedom in a cycle");
    std::map<std::int64_t, double> next;
    bool substituted = false;
    for (const auto& [dof, weight] : current) {
      const auto rule = dependent.find(dof);
      if (rule == dependent.end()) {
        next[dof] += weight;
        continue;
      }
      substituted = true;
      for (const MasterTerm& m : rule->second) next[m.dof] += weight * m.weight;
    }
    current = std::move(next);
    if (!substituted) return current;
  }
}

/// The DOFs *EQUATION eliminates: each equation's first term's.
std::set<std::int64_t> equation_dofs(const AnalysisModel& am) {
  std::set<std::int64_t> out;
  for (const model::Equation& eq : am.model->equations)
    if (const std::int64_t d = am.dof_index(eq.terms[0].node, eq.terms[0].dof); d >= 0) out.insert(d);
  return out;
}

}  // namespace

std::vector<double> distributing_weights(const AnalysisModel& am, const model::Coupling& c) {
  const model::Model& m = *am.model;
  std::vector<double> w = c.given_weights.empty() ? tributary_areas(am, c) : c.given_weights;
  const Vector3d xr = position(m, c.ref_node);
  double r0 = c.influence_radius;
  if (r0 <= 0)
    for (std::int32_t n : c.nodes) r0 = std::max(r0, (position(m, n) - xr).norm());
  double total = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double rho = r0 > 0 ? (position(m, c.nodes[i]) - xr).norm() / r0 : 0.0;
    w[i] *= weighting_function(c.weighting, std::min(rho, 1.0));
    total += w[i];
  }
  if (!(total > 0))
    throw AnalysisError(fmt::format("{} has no weight: every coupling node's weight is zero (a surface of no area, or "
                                    "WEIGHTING METHOD with one coupling node)", where(am, c)));
  for (double& x : w) x /= total;
  return w;
}

std::vector<CouplingRow> distributing_rows(const AnalysisModel& am, const model::Coupling& c) {
  const model::Model& m = *am.model;
  const int dim = am.dim;
  const std::vector<double> w = distributing_weights(am, c);
  Vector3d centroid = Vector3d::Zero();
  for (std::size_t i = 0; i < w.size(); ++i) centroid += w[i] * position(m, c.nodes[i]);
  // The coupled rotations (2D: about the third axis only), as a projection P.
  Matrix3d P = Matrix3d::Zero();
  for (int k = 0; k < 3; ++k) P(k, k) = (dim == 3 || k == 2) && c.dofs[static_cast<std::size_t>(3 + k)] ? 1.0 : 0.0;
  Matrix3d J = Matrix3d::Zero();
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Vector3d r = position(m, c.nodes[i]) - centroid;
    J += w[i] * (r.squaredNorm() * Matrix3d::Identity() - r * r.transpose());
  }
  // Pseudo-inverse: nodes on one line define no rotation about it, which is fine unless coupled.
  const Eigen::CompleteOrthogonalDecomposition<Matrix3d> cod(J.cwiseAbs().maxCoeff() > 0 ? J : Matrix3d::Identity());
  const Matrix3d J_inv = J.cwiseAbs().maxCoeff() > 0 ? Matrix3d(cod.pseudoInverse()) : Matrix3d::Zero();
  if ((P * (Matrix3d::Identity() - J * J_inv)).cwiseAbs().maxCoeff() > 1e-8)
    throw AnalysisError(fmt::format("{} couples a rotation its nodes cannot define (they lie on one line through "
                                    "their centroid, or there is one); couple the translations only (DOFs 1–{})",
                                    where(am, c), dim));
  // u_R = ū + θ × d with the whole rotation θ = J⁻¹ Σ ŵ r × u: a force at a reference node off
  // the centroid is carried with its moment about it even where the rotations are released.
  // *DISTRIBUTING COUPLING (node-based, CalculiX's meaning): u_R = ū, the force alone.
  Matrix3d all_rotations = Matrix3d::Identity();
  if (dim == 2) all_rotations(0, 0) = all_rotations(1, 1) = 0.0;
  if (c.node_based()) all_rotations.setZero();
  const Matrix3d moment_arm = -skew(position(m, c.ref_node) - centroid) * all_rotations;  // −[d]×
  const Vector3d d = position(m, c.ref_node) - centroid;
  Matrix3d translations = Matrix3d::Identity();  // the force components there are (2D: in-plane)
  if (dim == 2) translations(2, 2) = 0.0;
  if ((all_rotations * (Matrix3d::Identity() - J * J_inv) * skew(d) * translations).cwiseAbs().maxCoeff() >
      1e-8 * d.norm())
    throw AnalysisError(fmt::format("{}: its reference node lies off the line of its coupling nodes, so a force there "
                                    "has a moment about that line which the nodes cannot carry; put the reference node "
                                    "on the line", where(am, c)));
  std::vector<CouplingRow> rows;
  for (int k = 0; k < dim; ++k)
    if (c.dofs[static_cast<std::size_t>(k)]) rows.push_back({static_cast<std::int64_t>(c.ref_node) * dim + k, {}});
  const std::size_t n_translation_rows = rows.size();
  std::vector<int> rotation_of_row;
  for (int k = 0; k < 3; ++k)
    if (P(k, k) > 0) {
      rows.push_back({static_cast<std::int64_t>(c.rot_node) * dim + (dim == 3 ? k : 0), {}});
      rotation_of_row.push_back(k);
    }
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Matrix3d G = w[i] * J_inv * skew(position(m, c.nodes[i]) - centroid);  // ∂θ/∂u_i
    const Matrix3d T = w[i] * Matrix3d::Identity() + moment_arm * G;             // ∂u_R/∂u_i
    for (int l = 0; l < dim; ++l) {
      const std::int64_t dof = static_cast<std::int64_t>(c.nodes[i]) * dim + l;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const bool translation = r < n_translation_rows;
        const int row_index = translation ? static_cast<int>(rows[r].ref_dof % dim) : rotation_of_row[r - n_translation_rows];
        const double a = translation ? T(row_index, l) : G(row_index, l);
        if (a != 0.0) rows[r].terms.push_back({dof, a});
      }
    }
  }
  return rows;
}

void add_distributing_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind,
                                 std::map<std::int64_t, std::vector<MasterTerm>>& dependent) {
  const std::set<std::int64_t> by_equation = equation_dofs(am);
  for (const model::Coupling& c : am.model->couplings) {
    if (c.kind != model::Coupling::Kind::Distributing) continue;
    // A reference DOF held by a *BOUNDARY, or eliminated by an *EQUATION (CalculiX's pret3 ties
    // a beam's end to it so), keeps that rule: Σ a u = u_ref is solved for other DOFs of the
    // row (the coupling nodes', or a free DOF the equation names).
    std::vector<LinearRow> rows_on_coupling_nodes;
    std::vector<CouplingRow> held_by_equation;
    for (CouplingRow& row : distributing_rows(am, c)) {
      const auto d = static_cast<std::size_t>(row.ref_dof);
      if (dependent.count(row.ref_dof) && !by_equation.count(row.ref_dof))
        throw AnalysisError(fmt::format("{}: the reference node's DOF is already eliminated by another constraint (a "
                                        "tie, rigid body or coupling makes it dependent); expected the reference node "
                                        "free of other constraints",
                                        where(am, c)));
      if (dependent.count(row.ref_dof)) {
        held_by_equation.push_back(std::move(row));  // once the coupling's other rows have their rules
        continue;
      }
      if (kind[d] == DofMap::Kind::Prescribed) {
        rows_on_coupling_nodes.push_back({std::move(row.terms), {{row.ref_dof, 1.0}}});
        continue;
      }
      dependent[row.ref_dof] = std::move(row.terms);
      kind[d] = DofMap::Kind::Dependent;
    }
    // Σ a u − (the equation's rule for u_ref) = 0 over DOFs without a rule (chains followed),
    // one term a DOF: the equation may name a coupling node or another reference DOF, which must
    // not become its own pivot's master.
    for (const CouplingRow& row : held_by_equation) {
      std::map<std::int64_t, double> merged = without_rules(row.terms, dependent);
      for (const auto& [dof, weight] : without_rules(dependent.at(row.ref_dof), dependent)) merged[dof] -= weight;
      std::vector<MasterTerm> lhs;
      for (const auto& [dof, weight] : merged)
        if (weight != 0.0) lhs.push_back({dof, weight});
      rows_on_coupling_nodes.push_back({std::move(lhs), {}});
    }
    if (rows_on_coupling_nodes.empty()) continue;
    eliminate_rows(rows_on_coupling_nodes, kind, dependent,
                   fmt::format("{}: the boundary conditions or *EQUATIONs on reference node {} leave no free "
                               "coupling-node degree of freedom to satisfy them (the coupling nodes are held already)",
                               where(am, c), am.model->mesh.nodes.labels[static_cast<std::size_t>(c.ref_node)]));
  }
}

}  // namespace inpact::solver
