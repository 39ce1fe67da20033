#include "model_summary.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "contact/contact_surface.hpp"
#include "contact/geometric_correction.hpp"
#include "contact/interaction_table.hpp"
#include "contact/tie.hpp"

namespace inpact::io {

namespace {

using fmt::print;

/// "material M", or a COMPOSITE's "N layers (A 0.1 at 0°, B 0.2 at OR1, …)".
std::string shell_material_text(const model::ShellSection& s) {
  if (s.layers.empty()) return "material " + s.material;
  std::vector<std::string> layers;
  for (const model::ShellLayer& l : s.layers)
    layers.push_back(fmt::format("{} {:g} at {}", l.material, l.thickness,
                                 l.orientation.empty() ? fmt::format("{:g}°", l.angle) : l.orientation));
  return fmt::format("{} layers ({})", s.layers.size(), fmt::join(layers, ", "));
}

void write_mesh(std::ostream& out, const model::Model& m) {
  const auto& mesh = m.mesh;
  print(out, "Nodes      {:>10}\n", mesh.nodes.size());
  print(out, "Elements   {:>10}\n", mesh.elements.size());
  std::map<std::string_view, std::size_t> per_type;
  for (auto t : mesh.elements.type) ++per_type[model::element_type(t).name];
  for (const auto& [name, n] : per_type) print(out, "  {:<8} {:>10}\n", name, n);
  if (m.instances.size() > 1) {
    print(out, "Instances  {:>10}\n", m.instances.size() - 1);
    for (std::size_t i = 1; i < m.instances.size(); ++i) print(out, "  {}\n", m.instances[i]);
  }
  auto write_sets = [&](const char* title, const std::map<std::string, model::Set>& sets) {
    std::size_t shown = 0;
    for (const auto& [k, s] : sets) shown += !s.internal;
    print(out, "{:<10} {:>10}\n", title, shown);
    for (const auto& [k, s] : sets)
      if (!s.internal) print(out, "  {:<32} {:>10}\n", s.name, s.rows.size());
  };
  write_sets("Node sets", mesh.nsets);
  write_sets("Elem sets", mesh.elsets);
  print(out, "Surfaces   {:>10}\n", mesh.surfaces.size());
  for (const auto& [k, s] : mesh.surfaces) {
    if (s.kind == model::Surface::Kind::Element && !s.edges.empty())
      print(out, "  {:<32} {:>10} shell edges\n", s.name, s.edges.size());
    else if (s.kind == model::Surface::Kind::Element)
      print(out, "  {:<32} {:>10} faces\n", s.name, s.faces.size());
    else if (s.kind == model::Surface::Kind::Analytical)
      print(out, "  {:<32} {:>10} segments (analytical)\n", s.name,
            m.analytical_surfaces.at(static_cast<std::size_t>(s.analytical)).segments.size());
    else
      print(out, "  {:<32} {:>10} nodes\n", s.name, s.nodes.size());
  }
}

void write_materials(std::ostream& out, const model::Model& m) {
  print(out, "Materials  {:>10}\n", m.materials.size());
  for (const auto& [k, mat] : m.materials) {
    print(out, "  {}", mat.name);
    if (mat.elastic) print(out, ": E = {:g}, nu = {:g}", mat.elastic->youngs_modulus, mat.elastic->poissons_ratio);
    if (mat.hyperelastic) {
      const auto join = [](const std::vector<double>& v) {
        std::string s;
        for (double x : v) s += fmt::format("{}{:g}", s.empty() ? "" : ", ", x);
        return s;
      };
      print(out, ": hyperelastic {} ({}; D = {})", mat.hyperelastic->name, join(mat.hyperelastic->coefficients),
            join(mat.hyperelastic->d));
    }
    if (mat.density) print(out, ", density = {:g}", *mat.density);
    if (mat.expansion) print(out, ", alpha = {:g} (from {:g})", mat.expansion->alpha, mat.expansion->zero);
    print(out, "\n");
  }
  print(out, "Sections   {:>10}\n", m.mesh.sections.size() + m.mesh.beam_sections.size() + m.mesh.shell_sections.size());
  for (const auto& s : m.mesh.sections)
    print(out, "  solid: elset {} -> material {}{}\n", s.elset, s.material,
          s.thickness != 1.0 ? fmt::format(", thickness {:g}", s.thickness) : "");
  for (const auto& s : m.mesh.beam_sections)
    print(out, "  beam: elset {} -> {} {} {}, n1 ({:g}, {:g}, {:g}){}\n", s.elset,
          s.material.empty() ? fmt::format("E = {:g}, G = {:g},", s.youngs_modulus, s.shear_modulus)
                             : fmt::format("material {},", s.material),
          model::shape_name(s.shape), fmt::format("{}", fmt::join(s.dims, " x ")), s.n1[0], s.n1[1], s.n1[2],
          s.offset != std::array<double, 2>{} ? fmt::format(", offsets {:g}, {:g}", s.offset[0], s.offset[1]) : "");
  for (const auto& s : m.mesh.shell_sections)
    print(out, "  shell: elset {} -> {}, {}, {}{}\n", s.elset, shell_material_text(s),
          s.nodal_thickness ? std::string("nodal thickness") : fmt::format("thickness {:g}", s.thickness),
          s.general ? std::string("general (exact through the thickness)")
                    : fmt::format("{} section points", s.point_count()),
          s.offset != 0.0 ? fmt::format(", offset {:g}", s.offset) : "");
}

const char* discretization_name(model::ContactDiscretization d) {
  return d == model::ContactDiscretization::SurfaceToSurface ? "surface-to-surface" : "node-to-surface";
}

const char* correction_name(model::GeometricCorrection::Kind k) {
  switch (k) {
    case model::GeometricCorrection::Kind::Circumferential: return "CIRCUMFERENTIAL";
    case model::GeometricCorrection::Kind::Spherical: return "SPHERICAL";
    case model::GeometricCorrection::Kind::Toroidal: return "TOROIDAL";
  }
  return "";
}

/// One smoothing line, and how far the correction moves the surface: the largest distance
/// between the faceted and the idealised surface, against the surface's facet size.
void write_correction(std::ostream& out, const model::Model& m, std::span<const contact::Vec3> X,
                      const model::GeometricCorrection& c) {
  print(out, "    {} {} a=({:g}, {:g}, {:g})", c.surface, correction_name(c.kind), c.a[0], c.a[1], c.a[2]);
  if (c.kind != model::GeometricCorrection::Kind::Spherical) print(out, " b=({:g}, {:g}, {:g})", c.b[0], c.b[1], c.b[2]);
  if (c.kind == model::GeometricCorrection::Kind::Toroidal) print(out, " R={:g}", c.radius);
  print(out, "\n");
  auto it = m.mesh.surfaces.find(c.surface);
  if (it == m.mesh.surfaces.end()) return;
  try {
    const contact::SurfaceCorrection sc(c, contact::ContactSurface::build(m, it->second), X, &m);
    const double dev = sc.max_deviation(), l = sc.characteristic_length();
    print(out, "      faceted to idealised: largest distance {:.4g}, characteristic length {:.4g}", dev, l);
    if (l > 0) print(out, " ({:.3g}%)", 100.0 * dev / l);
    print(out, "\n");
  } catch (const std::exception& e) {
    print(out, "      cannot be applied: {}\n", e.what());
  }
}

void write_contact(std::ostream& out, const model::Model& m) {
  print(out, "Interactions {:>8}\n", m.interactions.size());
  for (const auto& [k, i] : m.interactions) {
    print(out, "  {}: ", i.name);
    if (i.friction) print(out, "friction mu = {:g}{}", i.friction->mu, i.friction->rough ? " (ROUGH)" : "");
    else print(out, "frictionless");
    print(out, "\n");
  }
  std::vector<const model::ContactPair*> pairs;
  for (const auto& p : m.contact_pairs) pairs.push_back(&p);
  for (const auto& step : m.steps)
    for (const auto& p : step.contact_pairs) pairs.push_back(&p);
  print(out, "Contact pairs {:>7}\n", pairs.size());
  for (const auto* p : pairs) {
    print(out, "  {} / {}: {}, {} sliding, interaction {}\n", p->slave, p->master, discretization_name(p->type),
          p->small_sliding ? "small" : "finite", p->interaction);
    if (!p->geometric_correction.empty()) print(out, "    smoothing: {}\n", p->geometric_correction);
  }
  for (const auto& note : m.preprocessing_notes) print(out, "  {}\n", note);
  const auto& gc = m.general_contact;
  std::vector<contact::Vec3> X;  // reference coordinates, for the smoothing lines
  if (!gc.geometric_corrections.empty() || !m.surface_smoothings.empty()) X = contact::reference_coordinates(m.mesh.nodes);
  if (gc.defined) {
    print(out, "General contact\n");
    for (const auto& inc : gc.inclusions)
      print(out, "  include {}\n", inc.first.empty() ? std::string("ALL EXTERIOR") : inc.first + ", " + inc.second);
    for (const auto& exc : gc.exclusions) print(out, "  exclude {}, {}\n", exc.first, exc.second);
    for (const auto& pa : gc.property_assignments) {
      print(out, "  property {}: {}\n", pa.first.empty() ? std::string("(global)") : pa.first + ", " + pa.second,
            pa.interaction);
    }
    // What the inclusions expand to (contact/interaction_table.hpp).
    const auto table = contact::interaction_table(m);
    for (const auto& row : table->rows) {
      if (!row.general) continue;
      print(out, "  {} ({} faces) / {} ({} faces): surface to surface, interaction {}\n", row.pair.slave,
            row.slave->faces.size(), row.pair.master, row.master->faces.size(),
            row.pair.interaction.empty() ? std::string("(none: hard, frictionless)") : row.pair.interaction);
    }
    for (const auto& note : table->notes) print(out, "  note: {}\n", note);
    if (!gc.geometric_corrections.empty()) print(out, "  smoothing assignments:\n");
    for (const auto& c : gc.geometric_corrections) write_correction(out, m, X, c);
  }
  for (const auto& [k, sm] : m.surface_smoothings) {
    print(out, "Surface smoothing {}\n", sm.name);
    for (const auto& c : sm.corrections) write_correction(out, m, X, c);
  }
}

const char* procedure_name(const model::Step& s) { return s.static_procedure ? "STATIC" : "(none)"; }

void write_steps(std::ostream& out, const model::Model& m,
                 std::span<const std::vector<contact::ResolvedInteraction>> interactions) {
  print(out, "Steps      {:>10}\n", m.steps.size());
  for (std::size_t k = 0; k < m.steps.size(); ++k) {
    const model::Step& s = m.steps[k];
    print(out, "  {}: {}{}, at most {} increments\n", s.name, procedure_name(s), s.nlgeom_switched_on ? ", NLGEOM (switched on: hyperelastic materials)" : s.nlgeom ? ", NLGEOM" : "",
          s.max_increments);
    if (const auto& p = s.static_procedure) {
      if (p->direct)
        print(out, "    fixed increments of {:g} over a period of {:g}\n", p->initial_increment, p->time_period);
      else
        print(out, "    automatic: initial {:g}, period {:g}, min {:g}, max {:g}\n", p->initial_increment,
              p->time_period, p->min_increment.value_or(std::min(p->initial_increment, 1e-5 * p->time_period)),
              p->max_increment.value_or(p->time_period));
      if (const auto& st = p->stabilize)
        print(out, "    automatic stabilization: {}{}{}\n",
              st->damping_factor ? fmt::format("damping factor {:g}", *st->damping_factor)
                                 : fmt::format("dissipated energy fraction {:g}", st->energy_fraction),
              st->allsdtol ? fmt::format(", adaptive (ALLSDTOL {:g})", *st->allsdtol) : "",
              st->continue_previous ? ", continued from the previous step" : "");
    }
    std::size_t n_bc = 0, n_cl = 0, n_dl = 0, n_t = 0;
    for (const auto& b : s.boundaries) n_bc += b.entries.size();
    for (const auto& b : s.cloads) n_cl += b.entries.size();
    for (const auto& b : s.dloads) n_dl += b.entries.size();
    for (const auto& b : s.temperatures) n_t += b.entries.size();
    print(out, "    {} boundary, {} concentrated load, {} distributed load, {} temperature lines; {} output requests\n",
          n_bc, n_cl, n_dl, n_t, s.output.size());
    for (const auto& c : s.pair_changes)
      print(out, "    *MODEL CHANGE: contact pair {}/{} {}\n", c.slave, c.master,
            c.add ? "reactivated (its slave nodes start open)" : "removed (its contact forces ramp to zero over the step)");
    if (k >= interactions.size()) continue;
    const std::vector<std::string> lines = contact::describe(interactions[k]);
    if (!lines.empty()) print(out, "    contact, as the analysis enforces it:\n");
    for (const std::string& line : lines) print(out, "      {}\n", line);
  }
}

/// Each *TIE as the analysis resolves it (contact/tie.hpp): tolerance, nodes tied and not, the
/// largest move ADJUST made (or, with ADJUST=NO, the largest distance the tie bridges).
void write_ties(std::ostream& out, const model::Model& m) {
  if (m.ties.empty()) return;
  print(out, "Ties       {:>10}\n", m.ties.size());
  std::vector<contact::ResolvedTie> ties;
  try {
    ties = contact::resolve_ties(m);
  } catch (const std::exception& e) {
    print(out, "  cannot be resolved: {}\n", e.what());
    return;
  }
  for (const auto& r : ties) {
    const model::Tie& t = *r.tie;
    print(out, "  {}: {} / {}, {}, position tolerance {:.4g}{}, ADJUST={}\n", t.name, t.slave, t.master,
          t.type == model::Tie::Type::NodeToSurface ? "node to surface" : "surface to surface",
          r.tolerance, r.default_tolerance ? " (default: 5% of the typical master facet diagonal)" : "",
          t.adjust ? "YES" : "NO");
    if (!t.tied_nset.empty()) print(out, "    TIED NSET {}\n", t.tied_nset);
    print(out, "    {} slave node(s) tied, {} not tied", r.tied.size(), r.untied.size());
    if (t.type == model::Tie::Type::SurfaceToSurface)
      print(out, " ({} by mortar segments, {} by their closest point)", r.n_mortar, r.tied.size() - r.n_mortar);
    if (t.adjust) print(out, "; ADJUST moved {} node(s), the largest by {:.4g}\n", t.n_adjusted, t.largest_adjustment);
    else print(out, "; largest slave-to-master distance {:.4g}\n", r.largest_distance);
    if (!r.untied.empty()) print(out, "    not tied (beyond the tolerance): {}\n", contact::first_labels(m, r.untied));
    if (!r.held.empty()) print(out, "    with a *BOUNDARY (it holds the DOFs it prescribes, the tie the others): {}\n", contact::first_labels(m, r.held));
    if (!r.shared.empty()) print(out, "    left out (nodes of the master surface too): {}\n", contact::first_labels(m, r.shared));
    if (t.no_rotation) print(out, "    NO ROTATION: inpact's solid elements have no rotational degrees of freedom to tie\n");
  }
}

/// Each *PRE-TENSION SECTION as the parser cut the mesh: its node, normal, area, the node copies.
void write_pretension_sections(std::ostream& out, const model::Model& m) {
  if (m.pretension_sections.empty()) return;
  print(out, "Pre-tension sections {:>4}\n", m.pretension_sections.size());
  for (const auto& s : m.pretension_sections) {
    const std::string inst = m.instances[m.mesh.nodes.instance[s.node]];
    const std::string what =
        s.element >= 0 ? fmt::format("truss element {}", m.mesh.elements.labels[static_cast<std::size_t>(s.element)])
                       : s.surface;
    print(out, "  {}: pre-tension node {}{}, normal ({:.6g}, {:.6g}, {:.6g}){}, area {:.6g}\n", what,
          inst.empty() ? "" : inst + ".", m.mesh.nodes.labels[s.node], s.normal[0], s.normal[1], s.normal[2],
          s.element >= 0 ? " (the truss's axis)" : s.given_normal ? "" : " (the surface's average)", s.area);
    print(out, "    {} section node(s) copied, {} element(s) on the underlying side use the copies\n", s.node_pairs.size(),
          s.n_rewired_elements);
  }
}

}  // namespace

void write_model_summary(std::ostream& out, const model::Model& m,
                         std::span<const std::vector<contact::ResolvedInteraction>> interactions) {
  if (!m.heading.empty()) print(out, "{}\n\n", m.heading);
  write_mesh(out, m);
  write_materials(out, m);
  write_contact(out, m);
  write_ties(out, m);
  write_pretension_sections(out, m);
  write_steps(out, m, interactions);
}

}  // namespace inpact::io
