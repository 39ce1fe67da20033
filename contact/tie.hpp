#pragma once
/// *TIE resolved on the reference geometry: which slave nodes are tied, to which master nodes,
/// with which weights ([IG Mesh tie constraints, 35.3.1]).
///
/// Every node of the slave surface (element based: the nodes of its faces; node based: its
/// nodes) is projected onto the master facets, closest point (contact/projection.hpp). It is
/// tied when its distance d to the master is within the position tolerance (TIED NSET: when it
/// is in the set, at any distance); then its translations follow the master point,
///   u_s = Σ_a N_a(ξ) u_a   over the nodes a of the facet it projects onto,
/// which the DOF map eliminates as it does an *EQUATION (solver/dof_map.hpp). A linear field
/// on the master is carried exactly onto the slave nodes, so a uniform stress crosses the tie
/// unchanged (the patch test) whatever the two meshes.
///
/// TYPE=NODE TO SURFACE ties each slave node to its own closest point as above. TYPE=SURFACE TO
/// SURFACE (Abaqus's default) enforces the constraint in an average sense over the slave faces
/// around each node, as Abaqus describes its surface-to-surface ties: inpact's weights are the
/// dual mortar ones (contact/tie_mortar.hpp), u_s = Σ W_sl u_l, exact for a linear master field
/// and passing a uniform traction on exactly, so a uniform stress crosses a non-matching tie
/// unchanged (the patch test). The closest-point weights pass linear displacements but not the
/// consistent forces: the node-to-surface tie is not patch-test exact. Slave nodes the mortar
/// segments do not cover (node-based slave surfaces, 2-D and second-order facets, the master's
/// edge) fall back to their closest point.
///
/// Defaults and exclusions, as Abaqus has them where it says so:
///  - position tolerance: 5 % of the typical master facet diagonal (the median over the master
///    facets of the largest corner-to-corner distance); Abaqus bases its default on "the typical
///    element size of the master surface" and gives 5 % of the master facet diagonal for the
///    node-to-surface formulation;
///  - a slave node that is also a node of the master surface is already joined: it is left out
///    (a note says how many);
///  - a tied slave node with a *BOUNDARY on a translation (model data or any step): in each step
///    the DOFs the step prescribes keep their boundary condition and only the others are tied
///    (the DOF map skips prescribed DOFs); Abaqus/Standard's overconstraint checks likewise remove
///    the tie where a boundary condition conflicts with it. A warning names the nodes;
///  - a slave node that no master point lies within the tolerance of is not tied (a warning
///    lists the first ones); a tie that ties no node at all is a deck error naming the tie.
/// Deck errors (TieError, with the data line): no node tied; a slave node tied by two ties; a
/// slave node whose translation is the eliminated DOF of an *EQUATION.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/facet.hpp"
#include "contact/projection.hpp"
#include "model/model.hpp"

namespace inpact::contact {

struct TieError : std::runtime_error {
  TieError(const std::string& what, model::SourceLoc where) : std::runtime_error(what), loc(where) {}
  model::SourceLoc loc;
};

/// One tied slave node: u(slave) = Σ weight_k u(masters_k), per translation component.
struct TiedNode {
  std::int32_t slave = -1;
  std::vector<std::int32_t> masters;  ///< node rows of the master facet (terms with N = 0 dropped)
  std::vector<double> weights;        ///< N_a(ξ) of the projection, Σ = 1
  double distance = 0.0;              ///< |x_s − x_m| on the coordinates resolved on
  Vec3 on_master{};                   ///< x_m: where ADJUST moves the node
};

struct ResolvedTie {
  const model::Tie* tie = nullptr;
  double tolerance = 0.0;    ///< the position tolerance used (the default when the deck gives none)
  bool default_tolerance = false;
  std::vector<TiedNode> tied;
  std::vector<std::int32_t> untied;       ///< slave nodes beyond the tolerance (or not in TIED NSET)
  std::vector<std::int32_t> held;         ///< tied slave nodes that also have a *BOUNDARY
  std::vector<std::int32_t> shared;       ///< slave nodes that are master nodes too
  double largest_distance = 0.0;          ///< over the tied nodes
  std::size_t n_mortar = 0;               ///< tied nodes with surface-to-surface (mortar) weights
};

/// Every *TIE of `model` on its current reference coordinates, in deck order. Throws TieError.
std::vector<ResolvedTie> resolve_ties(const model::Model& model);

/// The warnings resolve_ties' results call for (untied nodes, nodes left out for a boundary
/// condition), each `file:line:col: *TIE NAME: ...`.
std::vector<std::string> tie_warnings(const model::Model& model, const std::vector<ResolvedTie>& ties);

/// project_to_facet() on coordinates relative to the facet's first node. Its Newton iteration
/// stops on an absolute step of 1e-14 in ξ, which the round-off of coordinates far from the
/// origin (|x| / facet size ≳ 30) keeps it from reaching even for a point on a flat facet; then
/// it reports converged = false and the facet's edge. Relative coordinates keep that round-off
/// at the facet's own scale.
Projection project_relative(const Facet& f, std::span<const Vec3> x, const Vec3& xs, std::int32_t index = 0);

/// "101, 102, 103 and 4 more": the first `n` labels of node rows.
std::string first_labels(const model::Model& model, const std::vector<std::int32_t>& rows, std::size_t n = 5);

}  // namespace inpact::contact
