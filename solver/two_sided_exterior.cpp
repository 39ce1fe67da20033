#include "two_sided_exterior.hpp"

#include <numeric>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "model/element_types.hpp"

namespace inpact::solver {

namespace {

/// Shells and rigid elements: two faces, SNEG and SPOS, on the same nodes.
bool two_sided(std::uint8_t type) {
  const model::ElementTypeInfo& t = model::element_type(type);
  return model::is_shell(t) || model::is_rigid(t);
}

/// The bodies of two-sided elements: per element row, a body index (−1 for other elements).
std::vector<std::int32_t> two_sided_bodies(const model::Elements& el, std::size_t n_nodes) {
  std::vector<std::int32_t> parent(n_nodes);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::int32_t a) {
    while (parent[static_cast<std::size_t>(a)] != a) a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  };
  for (std::size_t e = 0; e < el.size(); ++e) {
    if (!two_sided(el.type[e])) continue;
    const auto nodes = el.nodes_of(e);
    for (std::size_t a = 1; a < nodes.size(); ++a) parent[static_cast<std::size_t>(find(nodes[a]))] = find(nodes[0]);
  }
  std::vector<std::int32_t> body(el.size(), -1);
  for (std::size_t e = 0; e < el.size(); ++e)
    if (two_sided(el.type[e])) body[e] = find(el.nodes_of(e)[0]);
  return body;
}

/// The surfaces the deck names for contact: every *CONTACT PAIR's (model and steps) and every
/// named field of a general-contact inclusion.
std::vector<std::string> named_contact_surfaces(const model::Model& m) {
  std::vector<std::string> out;
  for (const model::ContactPair& p : m.contact_pairs) out.insert(out.end(), {p.slave, p.master});
  for (const model::Step& step : m.steps)
    for (const model::ContactPair& p : step.contact_pairs) out.insert(out.end(), {p.slave, p.master});
  for (const auto& inc : m.general_contact.inclusions)
    for (const std::string* name : {&inc.first, &inc.second})
      if (!name->empty()) out.push_back(*name);
  return out;
}

}  // namespace

void check_two_sided_bodies_in_exterior(const model::Model& m) {
  if (!m.general_contact.defined) return;
  const model::GeneralContact::Inclusion* exterior = nullptr;
  for (const auto& inc : m.general_contact.inclusions)
    if (inc.first.empty() || inc.second.empty()) exterior = exterior ? exterior : &inc;
  if (!exterior) return;
  const model::Elements& el = m.mesh.elements;
  const std::vector<std::int32_t> body = two_sided_bodies(el, m.mesh.nodes.size());
  std::set<std::int32_t> covered;
  for (const std::string& name : named_contact_surfaces(m))
    if (auto it = m.mesh.surfaces.find(name); it != m.mesh.surfaces.end())
      for (const model::Face& f : it->second.faces)
        if (body[static_cast<std::size_t>(f.element)] >= 0) covered.insert(body[static_cast<std::size_t>(f.element)]);
  std::int64_t shells = 0, rigid = 0;
  for (std::size_t e = 0; e < el.size(); ++e) {
    if (body[e] < 0 || covered.count(body[e])) continue;
    (model::is_shell(model::element_type(el.type[e])) ? shells : rigid) += 1;
  }
  if (shells == 0 && rigid == 0) return;
  std::vector<std::string> left;
  if (shells > 0) left.push_back(fmt::format("{} shell elements", shells));
  if (rigid > 0) left.push_back(fmt::format("{} rigid elements (R3D3, R3D4, R2D2, RAX2)", rigid));
  const bool all = exterior->first.empty() && exterior->second.empty();
  throw AnalysisError(fmt::format(
      "{}: error: *CONTACT INCLUSIONS: {} would leave out the {} that no *CONTACT PAIR or named inclusion "
      "reaches: general contact with their two-sided faces is not supported yet; name their surfaces in a "
      "*CONTACT PAIR or an inclusion (or, if they touch nothing, name the solids' surfaces instead of the "
      "exterior)",
      m.sources.describe(exterior->loc), all ? "ALL EXTERIOR" : "the exterior surface (an empty field)",
      fmt::join(left, " and ")));
}

}  // namespace inpact::solver
