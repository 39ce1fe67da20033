#include "pair_kinematics.hpp"

#include <algorithm>

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

}  // namespace inpact::contact
