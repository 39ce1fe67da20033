#include "interaction_table.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include <fmt/format.h>

#include "contact/contact_surface.hpp"
#include "contact/normal_behavior.hpp"
#include "model/mesh_queries.hpp"

namespace inpact::contact {

namespace {

/// Union-find over node rows.
struct Components {
  std::vector<std::int32_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t a) {
    while (parent[static_cast<std::size_t>(a)] != a) a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  }
  void join(std::int32_t a, std::int32_t b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

struct Body {
  std::int32_t root;
  std::int64_t first_label;
  model::Surface exterior;
};

/// The model's bodies (elements connected through nodes) with their exterior faces.
std::vector<Body> bodies(const model::Model& m) {
  const auto& el = m.mesh.elements;
  Components comp(m.mesh.nodes.size());
  for (std::size_t e = 0; e < el.size(); ++e) {
    const auto nodes = el.nodes_of(e);
    for (std::size_t a = 1; a < nodes.size(); ++a) comp.join(nodes[0], nodes[a]);
  }
  std::vector<std::int32_t> all(el.size());
  std::iota(all.begin(), all.end(), 0);
  std::map<std::int32_t, Body> by_root;
  for (const model::Face& f : model::exterior_faces(el, all)) {
    const std::int32_t root = comp.find(el.nodes_of(static_cast<std::size_t>(f.element))[0]);
    auto [it, fresh] = by_root.try_emplace(root, Body{root, el.labels[static_cast<std::size_t>(f.element)], {}});
    it->second.first_label = std::min(it->second.first_label, el.labels[static_cast<std::size_t>(f.element)]);
    it->second.exterior.faces.push_back(f);
  }
  std::vector<Body> out;
  for (auto& [root, b] : by_root) out.push_back(std::move(b));
  std::sort(out.begin(), out.end(), [](const Body& a, const Body& b) { return a.first_label < b.first_label; });
  // Names: the instance's when the body is all of one named instance, else BODY-k.
  std::map<std::int32_t, int> bodies_per_instance;
  std::vector<std::int32_t> instance_of(out.size(), -1);
  for (std::size_t k = 0; k < out.size(); ++k) {
    std::set<std::int32_t> inst;
    for (const model::Face& f : out[k].exterior.faces) inst.insert(el.instance[static_cast<std::size_t>(f.element)]);
    if (inst.size() == 1 && !m.instances[static_cast<std::size_t>(*inst.begin())].empty()) {
      instance_of[k] = *inst.begin();
      ++bodies_per_instance[*inst.begin()];
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const bool own = instance_of[k] >= 0 && bodies_per_instance[instance_of[k]] == 1;
    out[k].exterior.name = own ? m.instances[static_cast<std::size_t>(instance_of[k])] + ".EXTERIOR"
                               : fmt::format("BODY-{}", k + 1);
    out[k].exterior.loc = m.general_contact.loc;
  }
  return out;
}

const model::SurfaceInteraction* assigned_interaction(const model::Model& m, const std::string& a, const std::string& b,
                                                      std::string& name) {
  const model::GeneralContact::PropertyAssignment* global = nullptr;
  for (const auto& pa : m.general_contact.property_assignments) {
    if (pa.first.empty() && pa.second.empty()) global = &pa;
    else if ((pa.first == a && pa.second == b) || (pa.first == b && pa.second == a)) {
      name = pa.interaction;
      return &m.interactions.at(pa.interaction);
    }
  }
  if (!global) return nullptr;
  name = global->interaction;
  return &m.interactions.at(global->interaction);
}

bool excluded(const model::Model& m, const std::string& a, const std::string& b) {
  return std::any_of(m.general_contact.exclusions.begin(), m.general_contact.exclusions.end(), [&](const auto& e) {
    return (e.first == a && e.second == b) || (e.first == b && e.second == a);
  });
}

bool shares_faces(const model::Surface& s, const model::Surface& body) {
  std::set<std::pair<std::int32_t, std::uint8_t>> faces;
  for (const auto& f : body.faces) faces.insert({f.element, f.face});
  return std::any_of(s.faces.begin(), s.faces.end(), [&](const auto& f) { return faces.count({f.element, f.face}) > 0; });
}

double facet_size(const model::Model& m, const model::Surface& s) {
  if (s.kind != model::Surface::Kind::Element) return 0.0;
  const ContactSurface cs = ContactSurface::build(m, s);
  return typical_facet_size(cs, reference_coordinates(m.mesh.nodes));
}

/// Adds the row(s) of one general-contact interaction between surfaces a and b.
void add_general(const model::Model& m, InteractionTable& t, const model::Surface* a, const model::Surface* b) {
  if (excluded(m, a->name, b->name)) return;
  std::string interaction;
  const model::SurfaceInteraction* inter = assigned_interaction(m, a->name, b->name, interaction);
  const ResolvedNormalBehavior r =
      resolve_normal_behavior(inter, model::ContactDiscretization::SurfaceToSurface, false, true);
  auto row = [&](const model::Surface* slave, const model::Surface* master, double weight) {
    ContactInteraction ci;
    ci.pair.slave = slave->name;
    ci.pair.master = master->name;
    ci.pair.interaction = interaction;
    ci.pair.type = model::ContactDiscretization::SurfaceToSurface;
    ci.pair.loc = m.general_contact.loc;
    ci.slave = slave;
    ci.master = master;
    ci.general = true;
    ci.weight = weight;
    t.rows.push_back(std::move(ci));
  };
  if (!general_contact_one_row(r.method)) {
    row(a, b, 0.5);
    row(b, a, 0.5);
  } else if (facet_size(m, *b) < facet_size(m, *a)) {
    row(b, a, 1.0);
  } else {
    row(a, b, 1.0);
  }
}

/// The *CONTACT PAIR rows: the model's, then each step's (flagged as step data).
void add_contact_pairs(const model::Model& m, InteractionTable& t) {
  auto add_pair = [&](const model::ContactPair& p, std::size_t step) {
    ContactInteraction ci;
    ci.pair = p;
    ci.slave = &m.mesh.surfaces.at(p.slave);
    ci.master = &m.mesh.surfaces.at(p.master);
    ci.first_step = step;
    // Self-contact: every contact is seen from both sides, like a balanced two-row interaction.
    if (p.slave == p.master) ci.weight = 0.5;
    // A node-based slave has no faces to integrate over: Abaqus/Standard discretizes such a pair
    // node to surface whatever TYPE says (Abaqus/CAE writes picked slave nodes as a node-based
    // surface under TYPE=SURFACE TO SURFACE).
    if (p.type == model::ContactDiscretization::SurfaceToSurface && ci.slave->kind == model::Surface::Kind::Node) {
      ci.pair.type = model::ContactDiscretization::NodeToSurface;
      t.notes.push_back(fmt::format("{}: *CONTACT PAIR {}/{}: the slave surface is node based: node to surface, as "
                                    "Abaqus/Standard discretizes it",
                                    m.sources.describe(p.loc), p.slave, p.master));
    }
    t.rows.push_back(std::move(ci));
  };
  auto add_step_pair = [&](const model::ContactPair& p, std::size_t step) {
    add_pair(p, step);
    t.rows.back().step_data = true;
  };
  for (const auto& p : m.contact_pairs) add_pair(p, 0);
  for (std::size_t s = 0; s < m.steps.size(); ++s)
    for (const auto& p : m.steps[s].contact_pairs) add_step_pair(p, s);
}

/// The bodies' exterior surfaces, kept in the table (only when an inclusion names the
/// all-inclusive exterior surface: finding the bodies costs a pass over the mesh).
std::vector<const model::Surface*> add_body_surfaces(const model::Model& m, InteractionTable& t) {
  const auto& inclusions = m.general_contact.inclusions;
  const bool needs_bodies = std::any_of(inclusions.begin(), inclusions.end(),
                                        [](const auto& inc) { return inc.first.empty() || inc.second.empty(); });
  std::vector<const model::Surface*> body_surfaces;
  if (needs_bodies)
    for (Body& b : bodies(m)) {
      t.surfaces.push_back(std::move(b.exterior));  // (a deque: the pointers stay valid)
      body_surfaces.push_back(&t.surfaces.back());
    }
  return body_surfaces;
}

/// General contact's rows, each (unordered) pair of surfaces once.
struct GeneralRows {
  const model::Model& m;
  InteractionTable& t;
  std::set<std::pair<std::string, std::string>> done;

  bool first_time(const std::string& a, const std::string& b) {
    auto key = std::minmax(a, b);
    return done.insert({key.first, key.second}).second;
  }
  void once(const model::Surface* a, const model::Surface* b) {
    if (!first_time(a->name, b->name)) return;
    add_general(m, t, a, b);
  }
};

/// ALL EXTERIOR: every two bodies, and a note that self-contact within a body is not searched.
void add_all_exterior(GeneralRows& g, const model::GeneralContact::Inclusion& inc,
                      const std::vector<const model::Surface*>& body_surfaces) {
  for (std::size_t i = 0; i < body_surfaces.size(); ++i)
    for (std::size_t j = i + 1; j < body_surfaces.size(); ++j) g.once(body_surfaces[i], body_surfaces[j]);
  std::vector<std::string> names;
  for (auto* s : body_surfaces) names.push_back(s->name);
  g.t.notes.push_back(fmt::format("{}: general contact: self-contact within a body is not searched ({} bodies: {})",
                                  g.m.sources.describe(inc.loc), body_surfaces.size(), fmt::join(names, ", ")));
  // Beams have no faces, and shells' are not taken yet: Abaqus's general contact includes both.
  // (A model with shells gets here only when a *CONTACT PAIR is on them: check_contact_supported.)
  const auto& types = g.m.mesh.elements.type;
  auto count = [&](bool (*of_kind)(const model::ElementTypeInfo&)) {
    return std::count_if(types.begin(), types.end(), [&](std::uint8_t t) { return of_kind(model::element_type(t)); });
  };
  if (const auto beams = count(model::is_beam); beams > 0)
    g.t.notes.push_back(fmt::format("{}: general contact: the {} beam elements are not in ALL EXTERIOR (they have no "
                                    "faces here); their contact needs a *CONTACT PAIR with a node-based slave surface",
                                    g.m.sources.describe(inc.loc), beams));
  if (const auto shells = count(model::is_shell); shells > 0)
    g.t.notes.push_back(fmt::format("{}: general contact: the {} shell elements are not in ALL EXTERIOR (general "
                                    "contact with shells is not supported yet); their contact is that of the *CONTACT PAIRs and named "
                                    "inclusions on them",
                                    g.m.sources.describe(inc.loc), shells));
  if (const auto rigid = count(model::is_rigid); rigid > 0)
    g.t.notes.push_back(fmt::format("{}: general contact: the {} rigid elements are not in ALL EXTERIOR (their two "
                                    "faces are not taken yet); their contact is that of the *CONTACT PAIRs and named "
                                    "inclusions on them",
                                    g.m.sources.describe(inc.loc), rigid));
}

/// Self-contact of a named surface: one row, weight ½.
void add_self_contact(GeneralRows& g, const model::GeneralContact::Inclusion& inc) {
  const model::Surface* s = &g.m.mesh.surfaces.at(inc.first);
  if (!g.first_time(s->name, s->name) || excluded(g.m, s->name, s->name)) return;
  std::string interaction;
  assigned_interaction(g.m, s->name, s->name, interaction);
  ContactInteraction ci;
  ci.pair.slave = ci.pair.master = s->name;
  ci.pair.interaction = interaction;
  ci.pair.type = model::ContactDiscretization::SurfaceToSurface;
  ci.pair.loc = inc.loc;
  ci.slave = ci.master = s;
  ci.general = true;
  ci.weight = 0.5;
  g.t.rows.push_back(std::move(ci));
}

}  // namespace

std::shared_ptr<const InteractionTable> interaction_table(const model::Model& m) {
  auto t = std::make_shared<InteractionTable>();
  add_contact_pairs(m, *t);
  const model::GeneralContact& gc = m.general_contact;
  if (!gc.defined) return t;
  const std::vector<const model::Surface*> body_surfaces = add_body_surfaces(m, *t);
  GeneralRows g{m, *t, {}};
  for (const auto& inc : gc.inclusions) {
    if (inc.first.empty() && inc.second.empty()) {  // ALL EXTERIOR
      add_all_exterior(g, inc, body_surfaces);
    } else if (inc.first.empty() || inc.second.empty()) {  // the exterior against one surface
      const model::Surface& s = m.mesh.surfaces.at(inc.first.empty() ? inc.second : inc.first);
      for (const auto* body : body_surfaces)
        if (!shares_faces(s, *body)) g.once(&s, body);
    } else if (inc.first == inc.second) {
      add_self_contact(g, inc);
    } else {
      g.once(&m.mesh.surfaces.at(inc.first), &m.mesh.surfaces.at(inc.second));
    }
  }
  return t;
}

}  // namespace inpact::contact
