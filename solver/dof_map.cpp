#include "dof_map.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "distributing_coupling.hpp"
#include "dof_names.hpp"
#include "oriented_coupling.hpp"
#include "model/rigid_motion.hpp"

namespace inpact::solver {

namespace {

using Dependents = std::map<std::int64_t, std::vector<MasterTerm>>;
using model::rigid_motion;
using model::RigidMotion;
using model::Vec3d;

/// The rotation vector a rotation node holds (θ3 in [0] in 2D).
Vec3d rotation_of(const std::vector<double>& u, std::int32_t rot, int dim) {
  Vec3d theta{0, 0, 0};
  for (int k = 0; k < dim; ++k) theta[k] = u[static_cast<std::size_t>(rot) * dim + k];
  if (dim == 2) theta[1] = 0.0;  // a 2D rotation node's second DOF is not a rotation
  return theta;
}

}  // namespace

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
  if (!has_finite_rotations()) return;
  // u = u_R + (R(θ) − I) r is not linear in θ: the weights are its derivatives only.
  const int dim = dim_;
  for (const RigidNode& n : rigid_) {
    const RigidMotion motion = rigid_motion(rotation_of(u, n.rot, dim), n.r, dim, true);
    for (int c = 0; c < dim; ++c)
      if (kind_[static_cast<std::int64_t>(n.node) * dim + c] == Kind::Dependent)
        u[static_cast<std::int64_t>(n.node) * dim + c] = u[static_cast<std::int64_t>(n.ref) * dim + c] + motion.offset[c];
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

/// The nodes that follow rigid bodies and kinematic couplings, with their offsets from the
/// reference nodes.
std::vector<DofMap::RigidNode> rigid_nodes(const AnalysisModel& am) {
  const auto& coords = am.model->mesh.nodes.coords;
  std::vector<DofMap::RigidNode> out;
  auto add = [&](std::int32_t n, std::int32_t ref, std::int32_t rot, std::array<bool, 3> follows) {
    std::array<double, 3> r;
    for (int c = 0; c < 3; ++c) r[c] = coords[n][c] - coords[ref][c];
    out.push_back({n, ref, rot, r, follows});
  };
  for (const model::RigidBody& b : am.model->rigid_bodies)
    for (std::int32_t n : b.nodes) add(n, b.ref_node, b.rot_node, {true, true, true});
  for (const model::Coupling& c : am.model->couplings)
    if (c.kind == model::Coupling::Kind::Kinematic && !is_oriented_kinematic(c, am.dim))
      for (std::int32_t n : c.nodes) add(n, c.ref_node, c.rot_node, {c.dofs[0], c.dofs[1], c.dofs[2]});
  return out;
}

/// The reference-node DOFs a rigid node's followed translations use: u_R,c and the rotations
/// with a non-zero weight at θ = 0. A coupling's other reference DOFs stay unused (no rule, no
/// stiffness); a rigid body's are all used.
void mark_reference_dofs_used(int dim, std::span<const DofMap::RigidNode> nodes, std::vector<DofMap::Kind>& kind) {
  const int n_rot = dim == 3 ? 3 : 1;
  for (const DofMap::RigidNode& n : nodes) {
    const RigidMotion motion = rigid_motion({0, 0, 0}, n.r, dim, false);
    for (int c = 0; c < dim; ++c) {
      if (!n.follows[c]) continue;
      kind[static_cast<std::size_t>(n.ref) * dim + c] = DofMap::Kind::Free;
      for (int k = 0; k < n_rot; ++k)
        if (motion.d_dtheta[k][c] != 0.0) kind[static_cast<std::size_t>(n.rot) * dim + k] = DofMap::Kind::Free;
    }
  }
}

/// *RIGID BODY: u_c = u_R,c + Σ_k ∂(R r)_c/∂θ_k θ_k (small rotations: exactly the motion). Every
/// rotation term is kept, zero weights too, so that finite rotations keep the same masters.
void add_rigid_dependents(const AnalysisModel& am, std::span<const DofMap::RigidNode> nodes, const std::vector<double>* u,
                          bool finite, std::vector<DofMap::Kind>& kind, Dependents& dependent) {
  const model::Model& m = *am.model;
  const int n_rot = am.dim == 3 ? 3 : 1;
  for (const DofMap::RigidNode& n : nodes) {
    const Vec3d theta = u ? rotation_of(*u, n.rot, am.dim) : Vec3d{0, 0, 0};
    const RigidMotion motion = rigid_motion(theta, n.r, am.dim, finite);
    for (int c = 0; c < am.dim; ++c) {
      if (!n.follows[c]) continue;
      const std::int64_t d = static_cast<std::int64_t>(n.node) * am.dim + c;
      if (kind[d] == DofMap::Kind::Prescribed || dependent.count(d))
        throw AnalysisError(fmt::format("error: *RIGID BODY: node {} follows a rigid body and also has a boundary "
                                        "condition or another constraint; constrain the body at its reference node {}",
                                        m.mesh.nodes.labels[n.node], m.mesh.nodes.labels[n.ref]));
      std::vector<MasterTerm> terms{{static_cast<std::int64_t>(n.ref) * am.dim + c, 1.0}};
      for (int k = 0; k < n_rot; ++k)
        if (kind[static_cast<std::size_t>(n.rot) * am.dim + k] != DofMap::Kind::Unused)
          terms.push_back({static_cast<std::int64_t>(n.rot) * am.dim + k, motion.d_dtheta[k][c]});
      dependent[d] = std::move(terms);
      kind[d] = DofMap::Kind::Dependent;
    }
  }
}

/// One rotation DOF of a beam or shell node that turns with a rigid body (not pinned) or a
/// kinematic coupling that lists it: θ_node,k = θ_body,k. Equal rotations have equal rotation
/// vectors, so the rule is exact with finite rotations too.
struct RotationFollower {
  std::int64_t dof, body_dof;
  std::int32_t node, ref;
};

std::vector<RotationFollower> rotation_followers(const AnalysisModel& am) {
  const model::Model& m = *am.model;
  std::vector<RotationFollower> out;
  auto add = [&](std::int32_t node, std::int32_t ref, std::int32_t body_rot, std::array<bool, 3> listed) {
    const std::int32_t rot = am.rotation_node_of[static_cast<std::size_t>(node)];
    if (rot < 0) return;
    for (int k = 0; k < (am.dim == 3 ? 3 : 1); ++k)
      if (listed[static_cast<std::size_t>(am.dim == 3 ? k : 2)])
        out.push_back({static_cast<std::int64_t>(rot) * am.dim + k, static_cast<std::int64_t>(body_rot) * am.dim + k,
                       node, ref});
  };
  for (const model::RigidBody& b : m.rigid_bodies)
    for (std::int32_t n : b.nodes)
      if (b.ties_rotation(n)) add(n, b.ref_node, b.rot_node, {true, true, true});
  for (const model::Coupling& c : m.couplings) {
    if (c.kind != model::Coupling::Kind::Kinematic) continue;
    const std::array<bool, 3> listed{c.dofs[3], c.dofs[4], c.dofs[5]};
    const bool all_listed = am.dim == 3 ? listed[0] && listed[1] && listed[2] : listed[2];
    for (std::int32_t n : c.nodes) {
      if (!c.orientation.empty() && !all_listed && am.rotation_node_of[static_cast<std::size_t>(n)] >= 0)
        throw AnalysisError(fmt::format("{}: error: *COUPLING: coupling '{}' with ORIENTATION lists some rotations of "
                                        "node {}, a beam or shell node: local rotation subsets are not supported yet "
                                        "(list all of DOFs 4–6 or none)",
                                        m.sources.describe(c.loc), c.name, m.mesh.nodes.labels[static_cast<std::size_t>(n)]));
      add(n, c.ref_node, c.rot_node, listed);
    }
  }
  return out;
}

/// The body rotations that beam and shell nodes follow are unknowns of the system.
void mark_followed_rotations_used(std::span<const RotationFollower> followers, std::vector<DofMap::Kind>& kind) {
  for (const RotationFollower& f : followers)
    if (kind[static_cast<std::size_t>(f.dof)] != DofMap::Kind::Unused) kind[static_cast<std::size_t>(f.body_dof)] = DofMap::Kind::Free;
}

void add_rotation_dependents(const AnalysisModel& am, std::span<const RotationFollower> followers,
                             std::vector<DofMap::Kind>& kind, Dependents& dependent) {
  const auto& labels = am.model->mesh.nodes.labels;
  for (const RotationFollower& f : followers) {
    if (kind[static_cast<std::size_t>(f.dof)] == DofMap::Kind::Unused) continue;
    if (kind[static_cast<std::size_t>(f.dof)] == DofMap::Kind::Prescribed || dependent.count(f.dof))
      throw AnalysisError(fmt::format("error: node {} turns with the rigid body, rigid beam or kinematic coupling of "
                                      "reference node {} and also has a boundary condition or another constraint on "
                                      "its rotations; constrain the reference node {}",
                                      labels[static_cast<std::size_t>(f.node)], labels[static_cast<std::size_t>(f.ref)],
                                      labels[static_cast<std::size_t>(f.ref)]));
    dependent[f.dof] = {{f.body_dof, 1.0}};
    kind[static_cast<std::size_t>(f.dof)] = DofMap::Kind::Dependent;
  }
}

/// A distributing coupling's coupled reference DOFs get a rule (distributing_coupling.hpp): they
/// take part though no element connects them. Its rotations are linear in u, so a step with
/// NLGEOM refuses them.
void mark_distributing_reference_dofs(const AnalysisModel& am, bool finite_rotations, std::vector<DofMap::Kind>& kind) {
  const model::Model& m = *am.model;
  for (const model::Coupling& c : m.couplings) {
    if (c.kind != model::Coupling::Kind::Distributing) continue;
    if (finite_rotations && c.needs_rotations(am.dim))
      throw AnalysisError(fmt::format("{}: error: *COUPLING: coupling '{}' distributes rotations, which inpact does for "
                                      "small rotations only; with NLGEOM couple the translations only (DOFs 1–{})",
                                      m.sources.describe(c.loc), c.name, am.dim));
    for (int k = 0; k < am.dim; ++k)
      if (c.dofs[static_cast<std::size_t>(k)]) kind[static_cast<std::size_t>(c.ref_node) * am.dim + k] = DofMap::Kind::Free;
    for (int k = 0; k < 3; ++k)
      if ((am.dim == 3 || k == 2) && c.dofs[static_cast<std::size_t>(3 + k)])
        kind[static_cast<std::size_t>(c.rot_node) * am.dim + (am.dim == 3 ? k : 0)] = DofMap::Kind::Free;
  }
}

/// Substitutes dependents into each other until every term is independent (a tie's master node
/// that is itself tied elsewhere, an equation on a tied node: chains resolve here).
void substitute_chains(const AnalysisModel& am, Dependents& dependent) {
  for (auto& [d, terms] : dependent) {
    for (int pass = 0;; ++pass) {
      if (pass > static_cast<int>(dependent.size()))
        throw AnalysisError(fmt::format("error: *EQUATION / *TIE / *MPC / coupling: the constraints on {} lead into "
                                        "a cycle of degrees of freedom eliminating each other (expected each dependent "
                                        "DOF to lead to independent ones)", node_dof(am, d)));
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
    // A chain that leads back to d would leave u_d a master of itself, which no equation holds.
    if (std::any_of(terms.begin(), terms.end(), [&](const MasterTerm& t) { return t.dof == d; }))
      throw AnalysisError(fmt::format("error: *EQUATION / *TIE / *MPC / coupling: the constraints make {} depend on "
                                      "itself (a chain of them leads back to it)", node_dof(am, d)));
  }
}

/// Finite rotations move a rigid node nonlinearly in θ (update_dependent sets it from R(θ)): a
/// constraint built on such a node would need its chain re-evaluated, which is not done yet.
void check_no_chain_through_rigid_nodes(const AnalysisModel& am, std::span<const DofMap::RigidNode> nodes,
                                        const Dependents& dependent) {
  std::vector<std::uint8_t> rigid(am.n_dof(), 0);
  for (const auto& n : nodes)
    for (int c = 0; c < am.dim; ++c) rigid[static_cast<std::size_t>(n.node) * am.dim + c] = n.follows[c];
  for (const auto& [d, terms] : dependent) {
    if (rigid[static_cast<std::size_t>(d)]) continue;
    for (const auto& t : terms)
      if (rigid[static_cast<std::size_t>(t.dof)])
        throw AnalysisError(fmt::format(
            "error: *RIGID BODY: with NLGEOM, node {} of a rigid body is the master of another constraint (*TIE, "
            "*EQUATION); constraints on the nodes of a finitely rotating body are not supported yet",
            am.model->mesh.nodes.labels[static_cast<std::size_t>(t.dof / am.dim)]));
  }
}

/// *TRANSFORM: a node's global translations from its local node's, u_c = Σ_k (e_k)_c u_local,k
/// (model/transform.hpp), before every other rule: a deck's constraints on the node name its
/// local DOFs (AnalysisModel::dof_index).
void add_transform_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind, Dependents& dependent) {
  for (const model::TransformedNode& t : am.model->transformed_nodes) {
    std::array<std::array<double, 3>, 3> e;
    if (!am.local_axes(t.node, e)) throw AnalysisError("internal error: a transformed node without local axes");
    for (int c = 0; c < 3; ++c) {
      const std::int64_t d = static_cast<std::int64_t>(t.node) * 3 + c;
      if (kind[d] == DofMap::Kind::Unused) continue;
      std::vector<MasterTerm> terms;
      for (int k = 0; k < 3; ++k) terms.push_back({static_cast<std::int64_t>(t.local) * 3 + k, e[k][c]});
      dependent[d] = std::move(terms);
      kind[d] = DofMap::Kind::Dependent;
    }
  }
}

/// Per DOF, whether it is in the rotation field (DofMap::field); empty without beams and shells.
std::vector<std::uint8_t> rotation_field(const AnalysisModel& am) {
  const bool structural = std::any_of(am.elements.begin(), am.elements.end(),
                                      [](const ElementSetup& s) { return model::has_rotations(*s.type); });
  if (!structural) return {};
  std::vector<std::uint8_t> rotation(am.n_dof(), 0);
  for (std::int32_t rot : am.rotation_node_of)
    if (rot >= 0)
      for (int c = 0; c < am.dim; ++c) rotation[static_cast<std::size_t>(rot) * am.dim + c] = 1;
  return rotation;
}

}  // namespace

DofMap::Dependents DofMap::dependents(const AnalysisModel& am, const std::vector<double>* u) {
  const model::Model& m = *am.model;
  Dependents dependent;
  add_transform_dependents(am, kind_, dependent);
  // *EQUATION: the first term's DOF is eliminated: u0 = −Σ_{k≥1} (c_k / c_0) u_k.
  for (const auto& eq : m.equations) {
    const std::string where = m.sources.describe(eq.loc);
    auto dof_of = [&](const model::Equation::Term& t) {
      const std::int64_t d = am.dof_index(t.node, t.dof);
      if (d < 0)
        throw AnalysisError(fmt::format("{}: error: *EQUATION: node {} has no degree of freedom {} in this model (nodes "
                                        "have {}; rotations only at reference, beam and shell nodes)",
                                        where, m.mesh.nodes.labels[t.node], t.dof, am.dim));
      return d;
    };
    for (const auto& t : eq.terms) dof_of(t);
    const std::int64_t d0 = dof_of(eq.terms[0]);
    if (kind_[d0] == Kind::Prescribed)
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
    kind_[d0] = Kind::Dependent;
  }
  add_tie_dependents(am, kind_, dependent);
  add_pretension_dependents(am, kind_, dependent);
  add_rigid_dependents(am, rigid_, u, finite_rotations_, kind_, dependent);
  add_rotation_dependents(am, rotation_followers(am), kind_, dependent);
  if (has_finite_rotations()) check_no_chain_through_rigid_nodes(am, rigid_, dependent);
  add_oriented_kinematic_dependents(am, kind_, dependent);
  add_distributing_dependents(am, kind_, dependent);
  substitute_chains(am, dependent);
  return dependent;
}

void DofMap::lay_out(const Dependents& dependent) {
  const std::int64_t n = n_dof();
  eq_.assign(n, -1);
  master_ptr_.assign(n + 1, 0);
  master_.clear();
  n_eq_ = 0;
  for (std::int64_t d = 0; d < n; ++d) {
    if (kind_[d] == Kind::Free) eq_[d] = n_eq_++;
    if (kind_[d] == Kind::Dependent) {
      for (const auto& t : dependent.at(d)) master_.push_back(t);
    } else if (kind_[d] != Kind::Unused) {
      master_.push_back({d, 1.0});
    }
    master_ptr_[d + 1] = static_cast<std::int64_t>(master_.size());
  }
}

namespace {

/// An *EQUATION connects its DOFs: where one of them is used, every one is (a node that only an
/// equation names, as a coupling's reference node tied to a loaded node, carries its load).
void mark_equation_dofs_used(const AnalysisModel& am, std::vector<DofMap::Kind>& kind) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const model::Equation& eq : am.model->equations) {
      const auto used = [&](const model::Equation::Term& t) {
        const std::int64_t d = am.dof_index(t.node, t.dof);
        return d >= 0 && kind[static_cast<std::size_t>(d)] != DofMap::Kind::Unused;
      };
      if (!std::any_of(eq.terms.begin(), eq.terms.end(), used)) continue;
      for (const model::Equation::Term& t : eq.terms)
        if (const std::int64_t d = am.dof_index(t.node, t.dof); d >= 0 && !used(t)) {
          kind[static_cast<std::size_t>(d)] = DofMap::Kind::Free;
          changed = true;
        }
    }
  }
}

}  // namespace

DofMap DofMap::build(const AnalysisModel& am, const std::vector<std::uint8_t>& prescribed, bool finite_rotations,
                     std::span<const std::uint8_t> active) {
  const model::Model& m = *am.model;
  const std::int64_t n = static_cast<std::int64_t>(am.n_dof());
  DofMap map;
  map.dim_ = am.dim;
  map.finite_rotations_ = finite_rotations;
  map.rigid_ = rigid_nodes(am);
  map.rotation_ = rotation_field(am);
  map.kind_.assign(n, Kind::Unused);
  // A DOF is used when an element connects its node.
  std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;
  for (std::size_t e = 0; e < m.mesh.elements.size(); ++e)
    for (std::size_t a = 0, n_rows = active.empty() || active[e] ? am.element_rows(e, rows) : 0; a < n_rows; ++a)
      for (int c = 0; c < am.dim; ++c) map.kind_[static_cast<std::int64_t>(rows[a]) * am.dim + c] = Kind::Free;
  for (const model::PretensionSection& s : m.pretension_sections)
    map.kind_[static_cast<std::int64_t>(s.node) * am.dim] = Kind::Free;
  // A transformed node's local DOFs are its unknowns (add_transform_dependents).
  for (const model::TransformedNode& t : m.transformed_nodes)
    for (int c = 0; c < am.dim; ++c)
      if (map.kind_[static_cast<std::int64_t>(t.node) * am.dim + c] != Kind::Unused)
        for (int k = 0; k < am.dim; ++k) map.kind_[static_cast<std::int64_t>(t.local) * am.dim + k] = Kind::Free;
  // A rigid body's reference node and its rotations are unknowns though no element connects them.
  for (const model::RigidBody& b : m.rigid_bodies)
    for (int c = 0; c < am.dim; ++c) {
      map.kind_[static_cast<std::int64_t>(b.ref_node) * am.dim + c] = Kind::Free;
      if (c == 0 || am.dim == 3) map.kind_[static_cast<std::int64_t>(b.rot_node) * am.dim + c] = Kind::Free;
    }
  mark_reference_dofs_used(am.dim, map.rigid_, map.kind_);
  mark_followed_rotations_used(rotation_followers(am), map.kind_);
  mark_distributing_reference_dofs(am, finite_rotations, map.kind_);
  mark_oriented_reference_dofs(am, finite_rotations, map.kind_);
  mark_equation_dofs_used(am, map.kind_);
  for (std::int64_t d = 0; d < n; ++d)
    if (prescribed[d] && map.kind_[d] == Kind::Free) map.kind_[d] = Kind::Prescribed;
  map.lay_out(map.dependents(am, nullptr));
  return map;
}

void DofMap::relinearize(const AnalysisModel& am, const std::vector<double>& u) {
  if (!has_finite_rotations()) return;
  const std::vector<MasterTerm> before = master_;
  lay_out(dependents(am, &u));
  // Same masters in the same order (the assembler's pattern holds); only the weights change.
  if (master_.size() != before.size()) throw AnalysisError("internal error: a rigid body's masters changed");
}

}  // namespace inpact::solver
