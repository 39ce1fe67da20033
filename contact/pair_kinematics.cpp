#include "pair_kinematics.hpp"

#include <algorithm>

#include "parallel_for.hpp"

namespace inpact::contact {

PairKinematics::PairKinematics(const model::Model& model, const model::Surface& slave, const model::Surface& master,
                               int dim, double out_of_plane_thickness)
    : dim_(dim) {
  SurfaceOptions options;
  options.out_of_plane_thickness = out_of_plane_thickness;
  slave_ = ContactSurface::build(model, slave, options);
  master_ = ContactSurface::build(model, master, options);
  radius_ = contact::search_radius(slave_, master_, reference_coordinates(model.mesh.nodes));
}

double search_radius(const ContactSurface& slave, const ContactSurface& master, std::span<const Vec3> x) {
  const double r = std::max(typical_facet_size(master, x), typical_facet_size(slave, x));
  return r > 0.0 ? r : 1.0;
}

double pair_search_radius(const model::Model& model, const model::Surface& slave, const model::Surface& master,
                          double out_of_plane_thickness) {
  SurfaceOptions options;
  options.out_of_plane_thickness = out_of_plane_thickness;
  return search_radius(ContactSurface::build(model, slave, options), ContactSurface::build(model, master, options),
                       reference_coordinates(model.mesh.nodes));
}

void PairKinematics::refresh_search(std::span<const Vec3> x) {
  if (built_ && !search_.needs_rebuild(master_.facets(), x)) return;
  SearchOptions o;
  o.radius = radius_;
  o.margin = 0.5 * radius_;
  search_.build(master_.facets(), x, o);
  built_ = true;
}

void PairKinematics::linearize_nodes(std::span<const Vec3> x, std::span<SlaveKinematics> kin,
                                     std::span<const std::size_t> nodes, bool finite_sliding) {
  if (threads_ > 1) {  // (what nodes share is filled first; one thread fills it as it goes)
    std::vector<std::size_t> found;
    for (std::size_t i : nodes)
      if (kin[i].found) found.push_back(i);
    prepare_linearization(x, found, finite_sliding);
  }
  parallel_for(nodes.size(), threads_, 8, [&](std::size_t n) { linearize(x, kin[nodes[n]], finite_sliding); });
}

}  // namespace inpact::contact
