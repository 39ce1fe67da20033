#include "oriented_coupling.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "analysis_error.hpp"
#include "constraint_elimination.hpp"
#include "elements/material_orientation.hpp"

namespace inpact::solver {

namespace {

/// One coupling node's rows, e_k · u_i = e_k · u_R + (r_i × e_k) · θ for the listed local k.
std::vector<LinearRow> node_rows(const AnalysisModel& am, const model::Coupling& c,
                                 const elements::MaterialOrientation& axes, std::int32_t node) {
  const int dim = am.dim;
  const auto& x = am.model->mesh.nodes.coords;
  const auto& xn = x[static_cast<std::size_t>(node)];
  const auto& xr = x[static_cast<std::size_t>(c.ref_node)];
  const Eigen::Vector3d r(xn[0] - xr[0], xn[1] - xr[1], xn[2] - xr[2]);
  const Eigen::Matrix3d q = axes.axes_at(xn);
  std::vector<LinearRow> rows;
  for (int k = 0; k < dim; ++k) {
    if (!c.dofs[static_cast<std::size_t>(k)]) continue;
    const Eigen::Vector3d e = q.row(k).transpose();
    const Eigen::Vector3d lever = r.cross(e);  // (r × e) · θ = e · (θ × r)
    LinearRow row;
    for (int comp = 0; comp < dim; ++comp) {
      if (e[comp] == 0.0) continue;
      row.lhs.push_back({static_cast<std::int64_t>(node) * dim + comp, e[comp]});
      row.rhs.push_back({static_cast<std::int64_t>(c.ref_node) * dim + comp, e[comp]});
    }
    for (int m = 0; m < 3; ++m) {
      if (dim == 2 && m != 2) continue;  // a plane model turns about the third axis only
      if (lever[m] != 0.0) row.rhs.push_back({static_cast<std::int64_t>(c.rot_node) * dim + (dim == 3 ? m : 0), lever[m]});
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string where(const AnalysisModel& am, const model::Coupling& c) {
  return fmt::format("{}: error: *COUPLING: coupling '{}'", am.model->sources.describe(c.loc), c.name);
}

}  // namespace

bool is_oriented_kinematic(const model::Coupling& c, int dim) {
  if (c.kind != model::Coupling::Kind::Kinematic || c.orientation.empty()) return false;
  for (int k = 0; k < dim; ++k)
    if (!c.dofs[static_cast<std::size_t>(k)]) return true;
  return false;
}

void mark_oriented_reference_dofs(const AnalysisModel& am, bool finite_rotations, std::vector<DofMap::Kind>& kind) {
  for (const model::Coupling& c : am.model->couplings) {
    if (!is_oriented_kinematic(c, am.dim)) continue;
    if (finite_rotations)
      throw AnalysisError(fmt::format("{} couples local DOFs of its ORIENTATION, which inpact does for small rotations "
                                      "only; with NLGEOM couple all three translations, or none of the orientation",
                                      where(am, c)));
    const elements::MaterialOrientation axes(am.model->orientations.at(c.orientation));
    for (std::int32_t n : c.nodes)
      for (const LinearRow& row : node_rows(am, c, axes, n))
        for (const MasterTerm& t : row.rhs) kind[static_cast<std::size_t>(t.dof)] = DofMap::Kind::Free;
  }
}

void add_oriented_kinematic_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind,
                                       std::map<std::int64_t, std::vector<MasterTerm>>& dependent) {
  for (const model::Coupling& c : am.model->couplings) {
    if (!is_oriented_kinematic(c, am.dim)) continue;
    const elements::MaterialOrientation axes(am.model->orientations.at(c.orientation));
    for (std::int32_t n : c.nodes)
      eliminate_rows(node_rows(am, c, axes, n), kind, dependent,
                     fmt::format("{}: coupling node {} is held already (a boundary condition or another constraint) "
                                 "in the directions the coupling constrains",
                                 where(am, c), am.model->mesh.nodes.labels[static_cast<std::size_t>(n)]));
  }
}

}  // namespace inpact::solver
