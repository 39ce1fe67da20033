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
  const auto x = reference_coordinates(model.mesh.nodes);
  radius_ = std::max(typical_facet_size(master_, x), typical_facet_size(slave_, x));
  if (!(radius_ > 0.0)) radius_ = 1.0;
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
