#include "tie.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "model/mesh_queries.hpp"
#include "contact/contact_surface.hpp"
#include "contact/projection.hpp"
#include "contact/search.hpp"
#include "contact/tie_mortar.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

/// Nodes with a *BOUNDARY on a translation, in the model data or in any step.
std::set<std::int32_t> held_nodes(const model::Model& m, int dim) {
  std::set<std::int32_t> out;
  auto add = [&](const std::vector<model::BoundaryBlock>& blocks) {
    for (const auto& b : blocks)
      for (const auto& e : b.entries)
        if (e.first_dof <= dim) out.insert(e.nodes.begin(), e.nodes.end());
  };
  add(m.boundaries);
  for (const auto& s : m.steps) add(s.boundaries);
  return out;
}

/// Nodes whose translation an *EQUATION eliminates (its first term), with the equation.
std::map<std::int32_t, const model::Equation*> equation_dependents(const model::Model& m, int dim) {
  std::map<std::int32_t, const model::Equation*> out;
  for (const auto& eq : m.equations)
    if (!eq.terms.empty() && eq.terms[0].dof <= dim) out.emplace(eq.terms[0].node, &eq);
  return out;
}

/// The median over the facets of the largest corner-to-corner distance.
double typical_facet_diagonal(const ContactSurface& s, std::span<const Vec3> x) {
  std::vector<double> sizes;
  for (const Facet& f : s.facets()) {
    double d2 = 0.0;
    const int nc = facet_n_corners(f.shape);
    for (int a = 0; a < nc; ++a)
      for (int b = a + 1; b < nc; ++b) {
        const Vec3 d = sub(x[f.nodes[a]], x[f.nodes[b]]);
        d2 = std::max(d2, dot(d, d));
      }
    sizes.push_back(std::sqrt(d2));
  }
  if (sizes.empty()) return 0.0;
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
  return sizes[sizes.size() / 2];
}

/// The surface of a tie's side; a slave made of shell edges ties the edges' nodes, as a node-based
/// slave does (the shell's rotations stay free: the junction is a hinge).
ContactSurface build_surface(const model::Model& m, const model::Tie& t, const std::string& name) {
  const model::Surface& surface = m.mesh.surfaces.at(name);
  try {
    if (!surface.edges.empty()) {
      model::Surface nodes;
      nodes.name = surface.name;
      nodes.kind = model::Surface::Kind::Node;
      for (const model::Face& edge : surface.edges)
        for (std::int32_t n : model::edge_nodes(m.mesh.elements, edge)) nodes.nodes.push_back(n);
      std::sort(nodes.nodes.begin(), nodes.nodes.end());
      nodes.nodes.erase(std::unique(nodes.nodes.begin(), nodes.nodes.end()), nodes.nodes.end());
      nodes.node_areas.assign(nodes.nodes.size(), 1.0);
      return ContactSurface::build(m, nodes);
    }
    return ContactSurface::build(m, surface);
  } catch (const std::invalid_argument& e) {
    throw TieError(fmt::format("tie {}: {}", t.name, e.what()), t.line_loc);
  }
}

/// The slave node's tie to the master point p projects it onto.
TiedNode tied_node(std::int32_t row, const Facet& f, const Projection& p) {
  TiedNode n;
  n.slave = row;
  n.distance = p.distance;
  n.on_master = p.x_master;
  std::array<double, 8> N{};
  shape_values(f.shape, p.xi[0], p.xi[1], N);
  for (int a = 0; a < f.n_nodes; ++a) {
    if (std::abs(N[a]) < 1e-14) continue;  // round-off of a node that meets a facet node
    n.masters.push_back(f.nodes[a]);
    n.weights.push_back(N[a]);
  }
  return n;
}

/// Replaces n's closest-point weights by its mortar row, when it has one.
bool use_mortar_row(const std::map<std::int32_t, std::vector<std::pair<std::int32_t, double>>>& mortar, TiedNode& n) {
  const auto it = mortar.find(n.slave);
  if (it == mortar.end()) return false;
  n.masters.clear();
  n.weights.clear();
  for (const auto& [row, w] : it->second) {
    n.masters.push_back(row);
    n.weights.push_back(w);
  }
  return true;
}

/// The closest point among the candidate facets (the lowest index among equally close ones).
Projection closest_point(std::span<const Facet> facets, std::span<const std::int32_t> candidates, std::span<const Vec3> x,
                         const Vec3& xs) {
  Projection best;
  for (std::int32_t k : candidates) {
    const Projection p = project_relative(facets[static_cast<std::size_t>(k)], x, xs, k);
    if (best.facet < 0 || p.distance < best.distance) best = p;
  }
  return best;
}

/// What the tie-wide checks need: nodes held by boundary conditions, eliminated by equations,
/// and already tied (by which tie).
struct TieContext {
  const model::Model& m;
  std::span<const Vec3> x;
  double model_size = 0.0;
  std::set<std::int32_t> held;
  std::map<std::int32_t, const model::Equation*> equations;
  std::map<std::int32_t, const model::Tie*> tied_by;
};

ResolvedTie resolve_one(TieContext& c, const model::Tie& t) {
  const model::Model& m = c.m;
  const ContactSurface slave = build_surface(m, t, t.slave);
  const ContactSurface master = build_surface(m, t, t.master);
  ResolvedTie r;
  r.tie = &t;
  r.default_tolerance = !t.position_tolerance && t.tied_nset.empty();
  r.tolerance = t.position_tolerance ? *t.position_tolerance : 0.05 * typical_facet_diagonal(master, c.x);
  const bool by_set = !t.tied_nset.empty();
  std::set<std::int32_t> in_set;
  if (by_set) in_set.insert(m.mesh.nsets.at(t.tied_nset).rows.begin(), m.mesh.nsets.at(t.tied_nset).rows.end());
  // TIED NSET ties its nodes at any distance: every facet is a candidate then.
  SearchOptions options;
  options.radius = by_set ? c.model_size : r.tolerance;
  FacetSearch search;
  search.build(master.facets(), c.x, options);
  // Surface to surface: the dual-mortar rows of the slave nodes the master covers (tie_mortar.hpp).
  std::map<std::int32_t, std::vector<std::pair<std::int32_t, double>>> mortar;
  if (t.type == model::Tie::Type::SurfaceToSurface) mortar = mortar_tie_weights(slave, master, c.x, r.tolerance);
  std::vector<std::int32_t> candidates;
  for (std::int32_t row : slave.nodes()) {
    if (by_set && !in_set.count(row)) continue;
    if (master.local_index(row) >= 0) {
      r.shared.push_back(row);
      continue;
    }
    candidates.clear();
    search.query(c.x[row], candidates);
    std::sort(candidates.begin(), candidates.end());  // the result does not depend on the tree's order
    const Projection p = closest_point(master.facets(), candidates, c.x, c.x[row]);
    if (p.facet < 0 || (!by_set && p.distance > r.tolerance)) {
      r.untied.push_back(row);
      continue;
    }
    if (c.held.count(row)) r.held.push_back(row);
    const std::int32_t label = m.mesh.nodes.labels[row];
    if (auto it = c.equations.find(row); it != c.equations.end())
      throw TieError(fmt::format("tie {}: slave node {} is also the eliminated (first) degree of freedom of the *EQUATION at "
                                 "{}; a node can depend on one constraint only", t.name, label, m.sources.describe(it->second->loc)),
                     t.line_loc);
    if (auto it = c.tied_by.find(row); it != c.tied_by.end())
      throw TieError(fmt::format("tie {}: slave node {} is already a slave node of tie {} ({}); a node can be tied once only",
                                 t.name, label, it->second->name, m.sources.describe(it->second->line_loc)),
                     t.line_loc);
    r.tied.push_back(tied_node(row, master.facets()[static_cast<std::size_t>(p.facet)], p));
    r.n_mortar += use_mortar_row(mortar, r.tied.back());
    r.largest_distance = std::max(r.largest_distance, p.distance);
  }
  for (const TiedNode& n : r.tied) c.tied_by[n.slave] = &t;
  if (r.tied.empty() && !r.untied.empty())
    throw TieError(fmt::format("tie {}: no node of the slave surface {} lies within the position tolerance {:.4g} of the master "
                               "surface {} ({} slave node(s), e.g. {}); give a larger POSITION TOLERANCE or check the surfaces",
                               t.name, t.slave, r.tolerance, t.master, r.untied.size(), first_labels(m, r.untied, 3)),
                   t.line_loc);
  return r;
}

}  // namespace

Projection project_relative(const Facet& f, std::span<const Vec3> x, const Vec3& xs, std::int32_t index) {
  const Vec3 origin = x[static_cast<std::size_t>(f.nodes[0])];
  std::array<Vec3, 8> local{};
  Facet g = f;
  for (int a = 0; a < f.n_nodes; ++a) {
    local[a] = sub(x[static_cast<std::size_t>(f.nodes[a])], origin);
    g.nodes[a] = a;
  }
  Projection p = project_to_facet(g, std::span<const Vec3>(local.data(), static_cast<std::size_t>(f.n_nodes)), sub(xs, origin), index);
  p.x_master = add(p.x_master, origin);
  return p;
}

std::string first_labels(const model::Model& m, const std::vector<std::int32_t>& rows, std::size_t n) {
  std::vector<std::int32_t> labels;
  for (std::int32_t r : rows) labels.push_back(m.mesh.nodes.labels[r]);
  std::sort(labels.begin(), labels.end());
  std::string out;
  for (std::size_t i = 0; i < labels.size() && i < n; ++i) out += fmt::format("{}{}", i ? ", " : "", labels[i]);
  if (labels.size() > n) out += fmt::format(" and {} more", labels.size() - n);
  return out;
}

std::vector<ResolvedTie> resolve_ties(const model::Model& m) {
  std::vector<ResolvedTie> out;
  if (m.ties.empty()) return out;
  const auto x = reference_coordinates(m.mesh.nodes);
  const int dim = model::spatial_dimension(m.mesh.elements);
  TieContext c{m, x, 0.0, held_nodes(m, dim), equation_dependents(m, dim), {}};
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3& p : x)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  c.model_size = 2.0 * norm(sub(hi, lo)) + 1.0;
  for (const model::Tie& t : m.ties) out.push_back(resolve_one(c, t));
  return out;
}

std::vector<std::string> tie_warnings(const model::Model& m, const std::vector<ResolvedTie>& ties) {
  std::vector<std::string> out;
  for (const ResolvedTie& r : ties) {
    const model::Tie& t = *r.tie;
    const std::string where = m.sources.describe(t.line_loc);
    if (!r.untied.empty())
      out.push_back(fmt::format("{}: *TIE {}: {} slave node(s) of {} lie farther than the position tolerance {:.4g} from {} "
                                "and are not tied: {}", where, t.name, r.untied.size(), t.slave, r.tolerance, t.master,
                                first_labels(m, r.untied)));
    if (!r.held.empty())
      out.push_back(fmt::format("{}: *TIE {}: {} tied slave node(s) also have a *BOUNDARY: in a step that prescribes one of "
                                "their degrees of freedom the boundary condition holds it and the tie only the others "
                                "(the overconstraint is removed, as Abaqus/Standard does): {}", where, t.name, r.held.size(),
                                first_labels(m, r.held)));
  }
  return out;
}

}  // namespace inpact::contact
