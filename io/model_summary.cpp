#include "model_summary.hpp"

#include <map>

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace inpact::io {

namespace {

using fmt::print;

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
    if (s.kind == model::Surface::Kind::Element)
      print(out, "  {:<32} {:>10} faces\n", s.name, s.faces.size());
    else
      print(out, "  {:<32} {:>10} nodes\n", s.name, s.nodes.size());
  }
}

void write_materials(std::ostream& out, const model::Model& m) {
  print(out, "Materials  {:>10}\n", m.materials.size());
  for (const auto& [k, mat] : m.materials) {
    print(out, "  {}", mat.name);
    if (mat.elastic) print(out, ": E = {:g}, nu = {:g}", mat.elastic->youngs_modulus, mat.elastic->poissons_ratio);
    if (mat.density) print(out, ", density = {:g}", *mat.density);
    if (mat.expansion) print(out, ", alpha = {:g} (from {:g})", mat.expansion->alpha, mat.expansion->zero);
    print(out, "\n");
  }
  print(out, "Sections   {:>10}\n", m.mesh.sections.size());
  for (const auto& s : m.mesh.sections)
    print(out, "  solid: elset {} -> material {}{}\n", s.elset, s.material,
          s.thickness != 1.0 ? fmt::format(", thickness {:g}", s.thickness) : "");
}

const char* procedure_name(const model::Step& s) { return s.static_procedure ? "STATIC" : "(none)"; }

void write_steps(std::ostream& out, const model::Model& m) {
  print(out, "Steps      {:>10}\n", m.steps.size());
  for (const auto& s : m.steps) {
    print(out, "  {}: {}{}, at most {} increments\n", s.name, procedure_name(s), s.nlgeom ? ", NLGEOM" : "",
          s.max_increments);
    if (const auto& p = s.static_procedure) {
      if (p->direct)
        print(out, "    fixed increments of {:g} over a period of {:g}\n", p->initial_increment, p->time_period);
      else
        print(out, "    automatic: initial {:g}, period {:g}, min {:g}, max {:g}\n", p->initial_increment,
              p->time_period, p->min_increment.value_or(std::min(p->initial_increment, 1e-5 * p->time_period)),
              p->max_increment.value_or(p->time_period));
    }
    std::size_t n_bc = 0, n_cl = 0, n_dl = 0, n_t = 0;
    for (const auto& b : s.boundaries) n_bc += b.entries.size();
    for (const auto& b : s.cloads) n_cl += b.entries.size();
    for (const auto& b : s.dloads) n_dl += b.entries.size();
    for (const auto& b : s.temperatures) n_t += b.entries.size();
    print(out, "    {} boundary, {} concentrated load, {} distributed load, {} temperature lines; {} output requests\n",
          n_bc, n_cl, n_dl, n_t, s.output.size());
  }
}

}  // namespace

void write_model_summary(std::ostream& out, const model::Model& m) {
  if (!m.heading.empty()) print(out, "{}\n\n", m.heading);
  write_mesh(out, m);
  write_materials(out, m);
  write_steps(out, m);
}

}  // namespace inpact::io
