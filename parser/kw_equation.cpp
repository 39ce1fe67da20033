/// *EQUATION: linear constraints between nodal DOFs [K16], [CCX].
#include <algorithm>

#include <fmt/format.h>

#include "handlers.hpp"
#include "model/mesh_queries.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// One term as read: its node rows (one, or a set's nodes in label order), DOF and coefficient.
struct RawTerm {
  std::vector<std::int32_t> nodes;
  int dof;
  double coefficient;
};

/// Nodes of a set in ascending (instance, label) order, the order Abaqus matches set members in.
void sort_by_label(const model::Nodes& nodes, std::vector<std::int32_t>& rows) {
  std::sort(rows.begin(), rows.end(), [&](std::int32_t a, std::int32_t b) {
    return std::pair(nodes.instance[a], nodes.labels[a]) < std::pair(nodes.instance[b], nodes.labels[b]);
  });
}

/// Expands the terms of one equation: a set term gives one equation per node of the set; every
/// set with more than one node must have the same size, and single nodes appear in each.
void add_equations(KeywordContext& ctx, const std::vector<RawTerm>& terms, model::SourceLoc loc) {
  std::size_t n = 1;
  for (const RawTerm& t : terms) {
    if (t.nodes.size() == 1) continue;
    if (n != 1 && t.nodes.size() != n) {
      ctx.error(loc, fmt::format("the node sets of an equation must have the same number of nodes ({} and {})", n,
                                 t.nodes.size()));
      return;
    }
    n = t.nodes.size();
  }
  const model::Nodes& nodes = ctx.mesh().nodes;
  for (std::size_t k = 0; k < n; ++k) {
    model::Equation eq;
    eq.loc = loc;
    for (const RawTerm& t : terms) {
      const std::int32_t node = t.nodes.size() == 1 ? t.nodes[0] : t.nodes[k];
      for (const auto& prev : eq.terms)
        if (prev.node == node && prev.dof == t.dof) {
          ctx.error(loc, fmt::format("node {} DOF {} appears twice in one equation", nodes.labels[node], t.dof));
          return;
        }
      eq.terms.push_back({node, t.dof, t.coefficient});
    }
    ctx.model().equations.push_back(std::move(eq));
  }
}

// *EQUATION: line 1 the number of terms N; then N terms `node|set, dof, coefficient`, four per
// line, continued on as many lines as needed; then the next equation [CCX], [K16].
// Σ coefficient·u = 0, and the first term's DOF is the one eliminated, so its coefficient must
// not be zero.
void equation(KeywordContext& ctx) {
  std::vector<Field> f;
  std::size_t i = 0;
  while (i < ctx.data.size()) {
    const Line& head = ctx.data[i++];
    split_fields(head, f);
    if (!ctx.check_count(f, head, 1, 1, "the number of terms of the equation")) return;
    const model::SourceLoc count_loc = f[0].loc;  // errors about the whole equation point here
    auto count = ctx.integer(f[0], "number of terms");
    if (!count) return;
    if (*count < 1) {
      ctx.error(f[0].loc, fmt::format("the number of terms must be at least 1, found {}", *count));
      return;
    }
    std::vector<RawTerm> terms;
    bool ok = true;
    while (terms.size() < static_cast<std::size_t>(*count) && i < ctx.data.size()) {
      const Line& line = ctx.data[i++];
      split_fields(line, f);
      const std::size_t left = static_cast<std::size_t>(*count) - terms.size();
      const std::size_t max_fields = 3 * std::min<std::size_t>(left, 4);
      if (!ctx.check_count(f, line, 3, max_fields,
                           fmt::format("node or node set, DOF, coefficient: up to four terms per line, {} term{} "
                                       "still due", left, left == 1 ? "" : "s")))
        return;  // the line structure is lost: the rest cannot be read reliably
      if (f.size() % 3 != 0) {
        ctx.error(f.back().loc, "each term needs three fields: node or node set, DOF, coefficient");
        return;
      }
      for (std::size_t k = 0; k < f.size(); k += 3) {
        auto nodes = ctx.nodes(f[k]);
        auto dof = ctx.dof(f[k + 1]);
        auto c = ctx.real(f[k + 2], "coefficient");
        if (!nodes || !dof || !c) {
          ok = false;
          terms.push_back({});
          continue;
        }
        if (terms.empty() && *c == 0) {
          ctx.error(f[k + 2].loc, "the first coefficient cannot be zero: its DOF is the one the equation eliminates");
          ok = false;
        }
        if (nodes->size() > 1) sort_by_label(ctx.mesh().nodes, *nodes);
        terms.push_back({std::move(*nodes), *dof, *c});
      }
    }
    if (terms.size() < static_cast<std::size_t>(*count)) {
      ctx.error(count_loc, fmt::format("the equation has {} terms, expected {} (the number on its first line)",
                                      terms.size(), *count));
      return;
    }
    if (ok) add_equations(ctx, terms, count_loc);
  }
}

/// The (dependent, independent) node pairs of an *MPC line: sets matched in label order, or
/// every dependent node with a single independent one. Empty after an error.
std::vector<std::pair<std::int32_t, std::int32_t>> mpc_pairs(KeywordContext& ctx, std::vector<std::int32_t> dependent,
                                                             std::vector<std::int32_t> independent, const Field& at) {
  sort_by_label(ctx.mesh().nodes, dependent);
  sort_by_label(ctx.mesh().nodes, independent);
  if (independent.size() != 1 && independent.size() != dependent.size()) {
    ctx.error(at.loc, fmt::format("the independent nodes ({}) must be one node or as many as the dependent ones ({})",
                                  independent.size(), dependent.size()));
    return {};
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (std::size_t k = 0; k < dependent.size(); ++k) {
    const std::int32_t b = independent.size() == 1 ? independent[0] : independent[k];
    if (dependent[k] == b) {
      ctx.error(at.loc, fmt::format("node {} is both the dependent and the independent node",
                                    ctx.mesh().nodes.labels[static_cast<std::size_t>(b)]));
      return {};
    }
    pairs.emplace_back(dependent[k], b);
  }
  return pairs;
}

/// MPC BEAM: a rigid beam from the independent node b to each dependent node a, u_a and θ_a
/// following b's rigid motion. The lines that share b form one rigid body with b as its
/// reference node (one rotation for b); finalize_rigid_bodies checks it with the *RIGID BODYs.
void add_rigid_beam(KeywordContext& ctx, std::int32_t a, std::int32_t b, const Line& line, const Field& b_field) {
  auto& bodies = ctx.model().rigid_bodies;
  auto it = std::find_if(bodies.begin(), bodies.end(), [&](const model::RigidBody& r) { return r.mpc_beam && r.ref_node == b; });
  if (it == bodies.end()) {
    model::RigidBody body;
    body.ref_node = b;
    body.loc = line.loc;
    body.ref_loc = b_field.loc;
    body.mpc_beam = true;
    it = bodies.insert(bodies.end(), std::move(body));
  }
  it->nodes.push_back(a);
}

}  // namespace

// *MPC: one constraint a data line, `type, dependent node|set, independent node|set` [K16 *MPC].
//  - TIE: all the active DOFs equal. The translations are *EQUATIONs u_dep − u_ind = 0 whose
//    first, eliminated term is the dependent node's; the rotations where both nodes have them.
//  - PIN: the translations only.
//  - BEAM: a rigid beam (add_rigid_beam).
// The other types are refused; CalculiX's PLANE, STRAIGHT and BEAM mean other things.
void mpc(KeywordContext& ctx) {
  if (ctx.has("USER")) {
    ctx.error_param("USER", "user subroutine MPCs (USER) are not supported");
    return;
  }
  const int dim = model::spatial_dimension(ctx.mesh().elements);
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 3, "MPC type, dependent node or node set, independent node or node set")) continue;
    const std::string type = normalize_name(f[0].text);
    if (type != "TIE" && type != "PIN" && type != "BEAM") {
      ctx.error(f[0].loc, fmt::format("MPC type '{}' is not supported yet (TIE, PIN and BEAM are; CalculiX's PLANE, "
                                      "STRAIGHT and MEANROT mean other things)",
                                      f[0].text));
      continue;
    }
    auto dependent = ctx.nodes(f[1]);
    auto independent = ctx.nodes(f[2]);
    if (!dependent || !independent) continue;
    const auto pairs = mpc_pairs(ctx, std::move(*dependent), std::move(*independent), f[2]);
    for (const auto& [a, b] : pairs) {
      if (type == "BEAM") {
        add_rigid_beam(ctx, a, b, line, f[2]);
        continue;
      }
      for (int dof = 1; dof <= dim; ++dof) add_equations(ctx, {{{a}, dof, 1.0}, {{b}, dof, -1.0}}, line.loc);
      if (type == "TIE") ctx.model().mpc_ties.push_back({a, b, line.loc});
    }
  }
}

void add_equation_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*EQUATION", kModelDataScopes, {}, DataLines::Required, equation});
  t.push_back({"*MPC", kModelDataScopes, {{"USER", ValueKind::None}, {"MODE", ValueKind::Required}}, DataLines::Required,
               mpc});
}

}  // namespace inpact::parser
