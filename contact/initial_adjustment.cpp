#include "initial_adjustment.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "model/mesh_queries.hpp"
#include "contact/node_to_surface.hpp"
#include "contact/tie.hpp"

namespace inpact::contact {

namespace {

/// *TIE, ADJUST=YES: every tied slave node onto its master point (before the contact pairs'
/// ADJUST). A tie the model contradicts is left alone here: the analysis reports it.
void adjust_ties(model::Model& m) {
  std::vector<ResolvedTie> ties;
  try {
    ties = resolve_ties(m);
  } catch (const TieError&) {
    return;
  }
  for (const ResolvedTie& r : ties) {
    model::Tie& t = m.ties[static_cast<std::size_t>(r.tie - m.ties.data())];
    if (!t.adjust) continue;
    for (const TiedNode& n : r.tied) {
      m.mesh.nodes.coords[static_cast<std::size_t>(n.slave)] = n.on_master;
      if (n.distance > 0.0) ++t.n_adjusted;
      t.largest_adjustment = std::max(t.largest_adjustment, n.distance);
    }
  }
}

}  // namespace

std::vector<AdjustedNode> adjusted_nodes(const model::Model& m, std::vector<std::string>& notes) {
  std::vector<AdjustedNode> out;
  std::set<std::int32_t> done;
  const auto x = reference_coordinates(m.mesh.nodes);
  for (const model::ContactPair& p : m.contact_pairs) {
    if (!p.adjust_distance && p.adjust_nset.empty()) continue;
    const model::Surface& slave = m.mesh.surfaces.at(p.slave);
    const model::Surface& master = m.mesh.surfaces.at(p.master);
    if (master.kind != model::Surface::Kind::Element) continue;  // refused by the analysis
    NodeToSurfacePair geometry(m, slave, master, model::spatial_dimension(m.mesh.elements), 1.0);
    std::vector<SlaveKinematics> kin;
    geometry.update(x, kin);
    std::set<std::int32_t> in_set;
    if (!p.adjust_nset.empty()) {
      const auto& rows = m.mesh.nsets.at(p.adjust_nset).rows;
      in_set.insert(rows.begin(), rows.end());
    }
    std::size_t count = 0;
    double largest = 0.0;
    for (const SlaveKinematics& k : kin) {
      if (!k.found || done.count(k.node)) continue;
      const bool wanted = p.adjust_distance ? k.projection.gap <= *p.adjust_distance : in_set.count(k.node) > 0;
      if (!wanted) continue;
      AdjustedNode a;
      a.row = k.node;
      a.to = k.projection.x_master;
      a.moved = std::abs(k.projection.gap);
      out.push_back(a);
      done.insert(k.node);
      ++count;
      largest = std::max(largest, a.moved);
    }
    notes.push_back(fmt::format("{}: ADJUST moved {} slave node(s) of {}/{} onto the master, the largest by {:.4g}",
                                m.sources.describe(p.loc), count, p.slave, p.master, largest));
  }
  return out;
}

std::vector<std::string> apply_adjust(model::Model& m) {
  adjust_ties(m);
  std::vector<std::string> notes;
  const auto moves = adjusted_nodes(m, notes);
  for (const AdjustedNode& a : moves) m.mesh.nodes.coords[static_cast<std::size_t>(a.row)] = a.to;
  m.adjusted = true;
  m.preprocessing_notes.insert(m.preprocessing_notes.end(), notes.begin(), notes.end());
  return notes;
}

}  // namespace inpact::contact
