#include "finalize.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "couplings.hpp"
#include "pretension_split.hpp"
#include "rigid_bodies.hpp"
#include "transforms.hpp"
#include "text.hpp"

namespace inpact::parser {

void resolve_pending_nodes(MeshBuild& build, Diagnostics& diags) {
  auto& conn = build.mesh.elements.conn;
  for (const PendingNode& p : build.pending) {
    if (auto row = build.mesh.nodes.index.find(p.instance, p.label))
      conn[p.conn_index] = *row;
    else
      diags.error(p.loc, "*ELEMENT", fmt::format("node {} is not defined", p.label));
  }
  build.pending.clear();
}

namespace {

template <class Map>
std::vector<std::string> keys(const Map& m) {
  std::vector<std::string> out;
  for (const auto& [k, v] : m) out.push_back(k);
  return out;
}

template <class Map>
bool check_defined(Diagnostics& diags, const Map& map, const std::string& name, model::SourceLoc loc,
                   const char* keyword, const char* what) {
  if (map.count(name)) return true;
  const std::string guess = did_you_mean(name, keys(map));
  diags.error(loc, keyword, fmt::format("{} '{}' is not defined{}", what, name,
                                        guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
  return false;
}

void check_scopes_closed(BuildState& s, Diagnostics& diags) {
  if (s.instance) diags.error(s.instance->loc, "*INSTANCE", "missing *END INSTANCE");
  else if (s.part) diags.error(s.part->loc, "*PART", "missing *END PART");
  if (s.scope == kAssemblyScope) diags.error({0, 0, 0}, "*ASSEMBLY", "missing *END ASSEMBLY before the end of the deck");
  if (s.step) diags.error(s.step->loc, "*STEP", fmt::format("step '{}' has no *END STEP", s.step->name));
}

/// A material of a section: elastic (*ELASTIC, with *PLASTIC or *EXPANSION if any) or
/// hyperelastic (*HYPERELASTIC alone: no expansion or plasticity on top of it yet).
void check_material(const model::Material& mat, Diagnostics& diags) {
  if (!mat.elastic && !mat.hyperelastic) {
    diags.error(mat.loc, "*MATERIAL", fmt::format("material '{}' has no *ELASTIC or *HYPERELASTIC definition, which a "
                                                  "static analysis needs", mat.name));
    return;
  }
  if (!mat.hyperelastic) return;
  if (mat.elastic)
    diags.error(mat.hyperelastic->loc, "*HYPERELASTIC",
                fmt::format("material '{}' has both *ELASTIC and *HYPERELASTIC (give one)", mat.name));
  if (mat.plastic)
    diags.error(mat.plastic->loc, "*PLASTIC", fmt::format("plasticity on a hyperelastic material ('{}') is not "
                                                          "supported yet", mat.name));
  if (mat.expansion)
    diags.error(mat.expansion->loc, "*EXPANSION", fmt::format("thermal expansion of a hyperelastic material ('{}') is "
                                                              "not supported yet", mat.name));
}

/// Hyperelastic materials need NLGEOM: a step without it gets it, with a note, as Abaqus does
/// ("NLGEOM is switched on because the model contains hyperelastic materials").
void switch_on_nlgeom_for_hyperelasticity(model::Model& m) {
  bool hyperelastic = false;
  for (const auto& sec : m.mesh.sections)
    if (auto it = m.materials.find(sec.material); it != m.materials.end() && it->second.hyperelastic)
      hyperelastic = true;
  if (!hyperelastic) return;
  for (model::Step& step : m.steps)
    if (!step.nlgeom) step.nlgeom = step.nlgeom_switched_on = true;
}

/// A *SOLID SECTION on beams or shells: their sections are *BEAM SECTION and *SHELL SECTION (or
/// the GENERAL forms), in CalculiX decks too. The first such element of each family is reported.
void check_no_solid_section_on_beams_or_shells(const model::Model& m, Diagnostics& diags) {
  const auto& el = m.mesh.elements;
  for (const model::SolidSection& sec : m.mesh.sections) {
    auto set = m.mesh.elsets.find(sec.elset);
    if (set == m.mesh.elsets.end()) continue;
    for (const bool beams : {true, false}) {
      const auto wrong = std::find_if(set->second.rows.begin(), set->second.rows.end(), [&](std::int32_t e) {
        const auto& type = model::element_type(el.type[static_cast<std::size_t>(e)]);
        return beams ? model::is_beam(type) : model::is_shell(type);
      });
      if (wrong == set->second.rows.end()) continue;
      const char* family = beams ? "BEAM" : "SHELL";
      diags.error(sec.loc, "*SOLID SECTION", fmt::format("element {} is a {} element: its section is a *{} SECTION or *{} "
                                                         "GENERAL SECTION", el.labels[*wrong], beams ? "beam" : "shell",
                                                         family, family));
    }
  }
}

void check_sections(model::Model& m, Diagnostics& diags) {
  std::vector<std::uint8_t> has_section(m.mesh.elements.size(), 0);
  for (const auto& sec : m.mesh.sections) {
    const bool elset_ok = check_defined(diags, m.mesh.elsets, sec.elset, sec.loc, "*SOLID SECTION", "element set");
    if (check_defined(diags, m.materials, sec.material, sec.loc, "*SOLID SECTION", "material")) {
      const model::Material& mat = m.materials.at(sec.material);
      check_material(mat, diags);
    }
    if (!sec.orientation.empty())
      check_defined(diags, m.orientations, sec.orientation, sec.loc, "*SOLID SECTION", "orientation");
    if (!elset_ok) continue;
    for (auto e : m.mesh.elsets.at(sec.elset).rows) {
      if (has_section[e]) {
        diags.error(sec.loc, "*SOLID SECTION", fmt::format("element {} already has a section", m.mesh.elements.labels[e]));
        break;
      }
      has_section[e] = 1;
    }
  }
  check_line_element_sections(m, diags, has_section);
  check_no_solid_section_on_beams_or_shells(m, diags);
  check_beam_sections(m, diags, has_section);
  check_shell_sections(m, diags, has_section);
  // Elements without a section cannot be analysed: report the first few by their own line.
  int reported = 0;
  std::size_t missing = 0;
  for (std::size_t e = 0; e < has_section.size(); ++e) {
    if (model::is_rigid(model::element_type(m.mesh.elements.type[e]))) {
      if (has_section[e])
        diags.error(m.mesh.elements.loc[e], "*ELEMENT", fmt::format("element {} is a rigid element and takes no "
                                                                     "section (its *RIGID BODY defines it)",
                                                                     m.mesh.elements.labels[e]));
      continue;
    }
    if (has_section[e]) continue;
    ++missing;
    if (reported < 3) {
      const auto& type = model::element_type(m.mesh.elements.type[e]);
      const bool spring = type.family == model::ElementFamily::Spring;
      diags.error(m.mesh.elements.loc[e], "*ELEMENT",
                  fmt::format("element {} has no {} (assign one with {})", m.mesh.elements.labels[e],
                              spring ? "spring behaviour" : "section",
                              spring                 ? "*SPRING"
                              : model::is_beam(type)  ? "*BEAM SECTION"
                              : model::is_shell(type) ? "*SHELL SECTION"
                                                      : "*SOLID SECTION"));
      ++reported;
    }
  }
  if (missing > 3)
    diags.error({0, 0, 0}, "*SOLID SECTION", fmt::format("{} elements in all have no section", missing));
}

/// A surface named by contact, *TIE or *COUPLING: defined, and made of faces or nodes (shell edges
/// serve a tie's slave side, *DSLOAD and *PRE-TENSION SECTION only).
void check_surface(const model::Model& m, Diagnostics& diags, const std::string& name, model::SourceLoc loc,
                   const char* keyword, bool shell_edges_allowed = false) {
  if (name.empty() || !check_defined(diags, m.mesh.surfaces, name, loc, keyword, "surface")) return;
  const model::Surface& s = m.mesh.surfaces.at(name);
  if (!s.edges.empty() && !shell_edges_allowed)
    diags.error(loc, keyword, fmt::format("surface '{}' is made of shell edges, which serve *DSLOAD, *PRE-TENSION "
                                          "SECTION and a *TIE's slave only; {} needs element faces (SPOS, SNEG, S1, ...)",
                                          s.name, keyword));
}

void check_contact(model::Model& m, Diagnostics& diags) {
  auto check_pair = [&](const model::ContactPair& p) {
    check_surface(m, diags, p.slave, p.loc, "*CONTACT PAIR");
    check_surface(m, diags, p.master, p.loc, "*CONTACT PAIR");
    // Names given as parameters are reported where the keyword line writes them.
    check_defined(diags, m.interactions, p.interaction, p.interaction_loc, "*CONTACT PAIR", "surface interaction");
    if (!p.geometric_correction.empty())
      check_defined(diags, m.surface_smoothings, p.geometric_correction, p.geometric_correction_loc, "*CONTACT PAIR",
                    "surface smoothing");
    if (!p.adjust_nset.empty())
      check_defined(diags, m.mesh.nsets, p.adjust_nset, p.adjust_loc, "*CONTACT PAIR", "node set");
  };
  for (const auto& p : m.contact_pairs) check_pair(p);
  for (const auto& step : m.steps)
    for (const auto& p : step.contact_pairs) check_pair(p);
  const auto& gc = m.general_contact;
  for (const auto& inc : gc.inclusions) {
    check_surface(m, diags, inc.first, inc.loc, "*CONTACT INCLUSIONS");
    check_surface(m, diags, inc.second, inc.loc, "*CONTACT INCLUSIONS");
  }
  for (const auto& inc : gc.exclusions) {
    check_surface(m, diags, inc.first, inc.loc, "*CONTACT EXCLUSIONS");
    check_surface(m, diags, inc.second, inc.loc, "*CONTACT EXCLUSIONS");
  }
  for (const auto& pa : gc.property_assignments) {
    check_surface(m, diags, pa.first, pa.loc, "*CONTACT PROPERTY ASSIGNMENT");
    check_surface(m, diags, pa.second, pa.loc, "*CONTACT PROPERTY ASSIGNMENT");
    check_defined(diags, m.interactions, pa.interaction, pa.interaction_loc, "*CONTACT PROPERTY ASSIGNMENT",
                  "surface interaction");
  }
  for (const auto& gcorr : gc.geometric_corrections)
    check_surface(m, diags, gcorr.surface, gcorr.loc, "*SURFACE PROPERTY ASSIGNMENT");
  for (const auto& [name, sm] : m.surface_smoothings)
    for (const auto& c : sm.corrections) check_surface(m, diags, c.surface, c.loc, "*SURFACE SMOOTHING");
  // A clearance belongs to an existing pair [K16 §3.21].
  auto has_pair = [&](const std::string& slave, const std::string& master) {
    return std::any_of(m.contact_pairs.begin(), m.contact_pairs.end(),
                       [&](const model::ContactPair& p) { return p.slave == slave && p.master == master; });
  };
  for (const auto& c : m.clearances) {
    check_surface(m, diags, c.slave, c.loc, "*CLEARANCE");
    check_surface(m, diags, c.master, c.loc, "*CLEARANCE");
    if (!has_pair(c.slave, c.master))
      diags.error(c.loc, "*CLEARANCE", fmt::format("no *CONTACT PAIR has slave '{}' and master '{}'", c.slave, c.master));
  }
  for (const auto& step : m.steps)
    for (const auto& cc : step.contact_controls) {
      check_surface(m, diags, cc.slave, cc.loc, "*CONTACT CONTROLS");
      check_surface(m, diags, cc.master, cc.loc, "*CONTACT CONTROLS");
    }
  for (const auto& step : m.steps)
    for (const auto& cs : step.contact_stabilizations)
      for (std::size_t i = 0; i < cs.surfaces.size(); ++i) {
        check_surface(m, diags, cs.surfaces[i].first, cs.surface_locs[2 * i], "*CONTACT STABILIZATION");
        if (cs.surfaces[i].second != cs.surfaces[i].first)
          check_surface(m, diags, cs.surfaces[i].second, cs.surface_locs[2 * i + 1], "*CONTACT STABILIZATION");
      }
}

/// *TIE: both surfaces defined, the master made of element faces (a node set has no facets to
/// project onto), TIED NSET defined.
void check_ties(const model::Model& m, Diagnostics& diags) {
  std::map<std::string, const model::Tie*> first_of_name;  // the data lines of one *TIE share its name
  for (const auto& t : m.ties) {
    const auto [it, fresh] = first_of_name.emplace(t.name, &t);
    if (!fresh && (it->second->loc.line != t.loc.line || it->second->loc.file != t.loc.file))
      diags.error(t.loc, "*TIE", fmt::format("tie name '{}' is used already (line {})", t.name, it->second->loc.line));
    check_surface(m, diags, t.slave, t.line_loc, "*TIE", true);  // a shell edge ties its nodes
    check_surface(m, diags, t.master, t.master_loc, "*TIE");
    if (const auto master = m.mesh.surfaces.find(t.master);
        master != m.mesh.surfaces.end() && master->second.kind != model::Surface::Kind::Element)
      diags.error(t.master_loc, "*TIE", fmt::format("tie {}: the master surface '{}' is node based; a master surface must be "
                                                  "made of element faces", t.name, t.master));
    if (!t.tied_nset.empty()) check_defined(diags, m.mesh.nsets, t.tied_nset, t.loc, "*TIE", "node set");
  }
}

void check_amplitude(const model::Model& m, Diagnostics& diags, const std::string& name, model::SourceLoc loc,
                     const char* keyword) {
  if (!name.empty()) check_defined(diags, m.amplitudes, name, loc, keyword, "amplitude");
}

/// GRAV, CENTRIF and ROTA loads act through the density: every element they load needs a material
/// with *DENSITY (without one the load would silently be zero).
/// The *DLOAD label of a load that acts through the density.
const char* density_load_label(model::DloadEntry::Kind kind) {
  if (kind == model::DloadEntry::Kind::Gravity) return "GRAV";
  return kind == model::DloadEntry::Kind::Centrifugal ? "CENTRIF" : "ROTA";
}

/// The material whose density a shell section's density loads need: its own, or a COMPOSITE's
/// first layer without *DENSITY (its first layer when all have one).
const std::string& density_material(const model::Model& m, const model::ShellSection& sec) {
  if (sec.layers.empty()) return sec.material;
  for (const model::ShellLayer& layer : sec.layers)
    if (auto mat = m.materials.find(layer.material); mat != m.materials.end() && !mat->second.density)
      return layer.material;
  return sec.layers.front().material;
}

void check_density_loads(const model::Model& m, Diagnostics& diags) {
  std::vector<const model::Material*> material_of;  // element row → material, built on first need
  for (const auto& step : m.steps)
    for (const auto& b : step.dloads)
      for (const auto& e : b.entries) {
        if (!model::scales_with_density(e.kind)) continue;
        const char* label = density_load_label(e.kind);
        if (material_of.empty()) {
          material_of.assign(m.mesh.elements.size(), nullptr);
          for (const auto& sec : m.mesh.sections) {
            auto set = m.mesh.elsets.find(sec.elset);
            auto mat = m.materials.find(sec.material);
            if (set == m.mesh.elsets.end() || mat == m.materials.end()) continue;  // reported above
            for (std::int32_t row : set->second.rows) material_of[row] = &mat->second;
          }
          for (const auto& sec : m.mesh.shell_sections) {
            auto set = m.mesh.elsets.find(sec.elset);
            auto mat = m.materials.find(density_material(m, sec));
            if (set == m.mesh.elsets.end() || mat == m.materials.end()) continue;  // reported above
            for (std::int32_t row : set->second.rows) material_of[row] = &mat->second;
          }
        }
        for (std::int32_t row : e.elements)
          if (const model::Material* mat = material_of[row]; mat && !mat->density) {
            diags.error(e.loc, "*DLOAD", fmt::format("{} needs the density of material '{}' (add *DENSITY to it)",
                                                     label, mat->name));
            break;
          }
      }
}

/// *CHANGE FRICTION / *CHANGE SURFACE BEHAVIOR take effect through the option that follows them
/// ("must be followed by a *FRICTION card to become effective" [CCX]): without it nothing changes.
void check_contact_changes(const model::Model& m, Diagnostics& diags, const model::Step& step) {
  for (const auto& c : step.friction_changes) {
    check_amplitude(m, diags, c.amplitude, c.amplitude_loc, "*CHANGE FRICTION");
    if (!c.reset && !c.friction)
      diags.warning(c.loc, "*CHANGE FRICTION",
                    fmt::format("no *FRICTION follows (nor RESET): the friction of '{}' is not changed", c.interaction));
  }
  for (const auto& c : step.contact_stabilizations)
    check_amplitude(m, diags, c.amplitude, c.amplitude_loc, "*CONTACT STABILIZATION");
  for (const auto& c : step.behavior_changes)
    if (!c.behavior)
      diags.warning(c.loc, "*CHANGE SURFACE BEHAVIOR",
                    fmt::format("no *SURFACE BEHAVIOR follows: the surface behavior of '{}' is not changed", c.interaction));
}

void check_steps(model::Model& m, Diagnostics& diags) {
  for (const auto& b : m.boundaries) check_amplitude(m, diags, b.amplitude, b.loc, "*BOUNDARY");
  for (const auto& step : m.steps) {
    if (!step.static_procedure)
      diags.error(step.loc, "*STEP", fmt::format("step '{}' has no procedure (expected *STATIC)", step.name));
    for (const auto& b : step.boundaries) check_amplitude(m, diags, b.amplitude, b.loc, "*BOUNDARY");
    for (const auto& b : step.cloads) check_amplitude(m, diags, b.amplitude, b.loc, "*CLOAD");
    for (const auto& b : step.dloads)
      check_amplitude(m, diags, b.amplitude, b.loc, b.surface_load ? "*DSLOAD" : "*DLOAD");
    for (const auto& b : step.temperatures) check_amplitude(m, diags, b.amplitude, b.loc, "*TEMPERATURE");
    check_contact_changes(m, diags, step);
  }
  check_density_loads(m, diags);
}

}  // namespace

void finalize_model(BuildState& state, Diagnostics& diags) {
  check_scopes_closed(state, diags);
  resolve_pending_nodes(state.model_mesh, diags);
  state.model.mesh = std::move(state.model_mesh.mesh);
  model::Model& m = state.model;
  if (m.mesh.elements.size() == 0 && !diags.has_errors())
    diags.error({0, 0, 0}, "*ELEMENT", "the model has no elements");
  check_sections(m, diags);
  check_contact(m, diags);
  check_ties(m, diags);
  check_steps(m, diags);
  split_pretension_sections(m, diags);
  finalize_rigid_bodies(m, diags);
  for (const model::Coupling& c : m.couplings) {
    if (!c.node_based()) check_surface(m, diags, c.surface, c.surface_loc, "*COUPLING");
    if (!c.orientation.empty())
      check_defined(diags, m.orientations, c.orientation, c.orientation_loc, "*COUPLING", "orientation");
  }
  finalize_couplings(m, diags);
  if (!diags.has_errors()) add_rotation_nodes(m);
  if (!diags.has_errors()) tie_mpc_rotations(m);
  if (!diags.has_errors()) finalize_transforms(m, diags);
  switch_on_nlgeom_for_hyperelasticity(m);
}

}  // namespace inpact::parser
