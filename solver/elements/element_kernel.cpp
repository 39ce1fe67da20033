#include "element_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "continuum_kinematics.hpp"
#include "hourglass.hpp"
#include "hybrid.hpp"
#include "incompatible_modes.hpp"
#include "line_elements.hpp"
#include "shell_elements.hpp"
#include "material.hpp"
#include "quadrature.hpp"
#include "shape_functions.hpp"

namespace inpact::solver::elements {

using model::ElementFamily;
using model::Integration;

namespace {

struct Mapping {
  Eigen::MatrixXd J;      // J(i, j) = ∂X_i/∂ξ_j
  double det = 0.0;
  Eigen::MatrixX3d grad;  // ∇₀N_a
  double radius = 0.0;    // Σ N_a X_a (the r of CAX)
  Vec3 x{};               // point coordinates
};

Mapping map_point(Shape shape, int dim, const Eigen::MatrixXd& X, const std::array<double, 3>& xi) {
  const ShapeValues sv = evaluate_shape(shape, xi);
  const int n = sv.n_nodes;
  Eigen::MatrixXd dN(n, dim);
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < dim; ++j) dN(a, j) = sv.dN[a][j];
  Mapping m;
  m.J = X.transpose() * dN;
  m.det = m.J.determinant();
  m.grad = Eigen::MatrixX3d::Zero(n, 3);
  if (m.det != 0.0) m.grad.leftCols(dim) = dN * m.J.inverse();  // ∇₀N_aᵀ = ∂N_a/∂ξᵀ J⁻¹
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i) m.x[i] += sv.N[a] * X(a, i);
  m.radius = m.x[0];
  return m;
}

// The measure that turns w·det J into a volume: thickness (plane), 2πr (CAX) or 1 (3D).
double out_of_plane_measure(ElementFamily family, const SectionData& section, double radius) {
  switch (family) {
    case ElementFamily::Axisymmetric: return 2 * std::numbers::pi * radius;
    case ElementFamily::PlaneStrain:
    case ElementFamily::PlaneStress: return section.thickness;
    case ElementFamily::Solid3D:
    case ElementFamily::Truss:  // (line elements take line_elements.cpp's kernels)
    case ElementFamily::Spring:
    case ElementFamily::Beam:
    case ElementFamily::Shell:
    case ElementFamily::Rigid: return 1.0;  // (rigid elements are never integrated)
  }
  return 1.0;
}

struct Assembled {
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  std::vector<PointState> states;
};

/// f and (want_k) K of the points at u, the material evaluated at each from its history.
template <class Law>
Assembled assemble(ElementFamily family, int dim, const Law& law, bool nlgeom, const std::vector<PointData>& pts,
                   const Eigen::VectorXd& u, bool want_k, const ElementHistory& history) {
  Assembled r;
  r.f = Eigen::VectorXd::Zero(u.size());
  if (want_k) r.K = Eigen::MatrixXd::Zero(u.size(), u.size());
  Mat6 scratch;  // the tangent of a material whose tangent varies
  for (std::size_t p = 0; p < pts.size(); ++p) {
    const PointData& pd = pts[p];
    PointState& st = r.states.emplace_back(point_kinematics(family, dim, nlgeom, pd, u));
    const Mat6& D =
        law.update({st.F, st.strain, pd.thermal_strain, &pd.x, nlgeom, pd.temperature}, history.at(p), st.stress, scratch);
    add_point_contribution(family, dim, D, nlgeom, pd, st, &r.f, want_k ? &r.K : nullptr);
  }
  return r;
}

// C3D8 with full 2×2×2 integration on fixed-size matrices: the formulas of
// continuum_kinematics.hpp (small strain and total Lagrangian) without a heap allocation per
// element — the structured-cube benchmark spends most of its assembly here. Point output
// too: the assembly keeps it in the increments that write S or E (Assembler).
using Mat83 = Eigen::Matrix<double, 8, 3>;
using Vec24 = Eigen::Matrix<double, 24, 1>;
using Mat24 = Eigen::Matrix<double, 24, 24>;
using Mat6x24 = Eigen::Matrix<double, 6, 24>;

constexpr int kVi[6] = {0, 1, 2, 0, 0, 1};
constexpr int kVj[6] = {0, 1, 2, 1, 2, 2};

struct Hex8Rule {
  std::array<Mat83, 8> dN;  ///< ∂N_a/∂ξ_j at each point
  std::array<std::array<double, 8>, 8> N;
  std::array<double, 8> weight{};
};

bool is_full_hex8(const model::ElementTypeInfo& type) {
  return type.family == ElementFamily::Solid3D && type.dim == 3 && type.n_nodes == 8 &&
         type.integration == Integration::Full && !type.hybrid;  // 2×2×2 Gauss points (quadrature.hpp)
}

const Hex8Rule& hex8_rule(const model::ElementTypeInfo& type) {
  static const Hex8Rule rule = [&type] {
    Hex8Rule r;
    const std::vector<QuadraturePoint> q = element_rule(type);
    if (q.size() != 8) throw std::logic_error("hex8_rule: C3D8 needs the 2x2x2 rule");
    for (std::size_t p = 0; p < 8; ++p) {
      const ShapeValues sv = evaluate_shape(Shape::Hex8, q[p].xi);
      for (int a = 0; a < 8; ++a) {
        r.N[p][a] = sv.N[a];
        for (int j = 0; j < 3; ++j) r.dN[p](a, j) = sv.dN[a][j];
      }
      r.weight[p] = q[p].weight;
    }
    return r;
  }();
  return rule;
}

/// The points' gradients ∇₀N_a and volumes; returns the smallest det J.
struct Hex8Geometry {
  Mat83 X;
  std::array<Mat83, 8> grad;
  std::array<double, 8> dv{};
};

double hex8_geometry(const Hex8Rule& rule, std::span<const Vec3> coords, Hex8Geometry& geo) {
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) geo.X(a, i) = coords[a][i];
  double min_jacobian = std::numeric_limits<double>::infinity();
  for (int p = 0; p < 8; ++p) {
    const Eigen::Matrix3d J = geo.X.transpose() * rule.dN[p];
    const double det = J.determinant();
    min_jacobian = std::min(min_jacobian, det);
    geo.grad[p] = det != 0.0 ? Mat83(rule.dN[p] * J.inverse()) : Mat83::Zero();
    geo.dv[p] = rule.weight[p] * det;
  }
  return min_jacobian;
}

/// B(k, a·3 + i) = ∂E_k/∂u_ai at a point with gradients g (F = I for small strain).
Mat6x24 hex8_b(const Eigen::Matrix3d& Fb, const Mat83& g) {
  Mat6x24 B;
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) {
      auto col = B.col(a * 3 + i);
      for (int k = 0; k < 3; ++k) col(k) = Fb(i, k) * g(a, k);
      for (int k = 3; k < 6; ++k) col(k) = Fb(i, kVi[k]) * g(a, kVj[k]) + Fb(i, kVj[k]) * g(a, kVi[k]);
    }
  return B;
}

/// The hex8 point's output: Cauchy stress and strain at its reference coordinates.
void hex8_output(const Hex8Geometry& geo, int p, const Vec3& x, const Material& law, bool nlgeom,
                 const Eigen::Matrix3d& F, const Vec6& strain, const Vec6& stress, ElementSystem& sys) {
  PointData pd;  // point_output reads the volume (and the thermal strain only in plane stress)
  pd.dv = geo.dv[p];
  PointState st;
  st.F = F;
  st.strain = strain;
  st.stress = stress;
  PointResult& out = sys.points.emplace_back();
  point_output(ElementFamily::Solid3D, law, nlgeom, pd, st, out, {});
  out.coords = x;
}

/// Point p's share of f and K (and its output): state F = I + ∇₀u, strain, the material's stress.
template <class Law>
void hex8_point(const Hex8Rule& rule, const Hex8Geometry& geo, int p, std::span<const double> u, const Law& law,
                const ElementRequest& request, std::span<const double> delta_t, const PointHistory& history,
                Vec24& f, Mat24& K, ElementSystem& sys) {
  const Mat83& g = geo.grad[p];
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) H.row(i) += u[a * 3 + i] * g.row(a);
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + H;
  Vec6 strain;
  if (request.nlgeom) {
    sys.min_volume_ratio = std::min(sys.min_volume_ratio, F.determinant());
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    strain << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(0, 2), 2 * E(1, 2);
  } else {
    strain << H(0, 0), H(1, 1), H(2, 2), H(0, 1) + H(1, 0), H(0, 2) + H(2, 0), H(1, 2) + H(2, 1);
  }
  double temperature = 0.0;
  for (std::size_t a = 0; a < request.temperature.size(); ++a) temperature += rule.N[p][a] * request.temperature[a];
  double thermal_strain = 0.0;
  if (!delta_t.empty()) {
    double dt = 0.0;
    for (int a = 0; a < 8; ++a) dt += rule.N[p][a] * delta_t[a];
    thermal_strain = law.thermal_strain(temperature, dt);
  }
  Vec3 x{};  // the point's reference coordinates
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) x[i] += rule.N[p][a] * geo.X(a, i);
  Vec6 stress;
  Mat6 scratch;
  const Mat6& D = law.update({F, strain, thermal_strain, &x, request.nlgeom, temperature}, history, stress, scratch);
  const Mat6x24 B = hex8_b(request.nlgeom ? F : Eigen::Matrix3d::Identity(), g);
  f.noalias() += (B.transpose() * stress) * geo.dv[p];
  if (request.point_output) {
    hex8_output(geo, p, x, law, request.nlgeom, F, strain, stress, sys);
    if (!history.trial.empty()) law.plastic_output(history.trial, sys.points.back());
  }
  if (!request.stiffness) return;
  const Mat6x24 DB = (D * geo.dv[p]) * B;
  K.noalias() += B.transpose() * DB;
  if (!request.nlgeom) return;
  Eigen::Matrix3d S;  // geometric (initial-stress) stiffness
  S << stress(0), stress(3), stress(4), stress(3), stress(1), stress(5), stress(4), stress(5), stress(2);
  const Eigen::Matrix<double, 8, 8> G = g * S * g.transpose() * geo.dv[p];
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int i = 0; i < 3; ++i) K(a * 3 + i, b * 3 + i) += G(a, b);
}

template <class Law>
void compute_hex8(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                  const Law& law, const ElementRequest& request, std::span<const double> delta_t,
                  const ElementHistory& history, ElementSystem& sys) {
  const Hex8Rule& rule = hex8_rule(type);
  sys.n_dof = 24;
  sys.local_iterations = 0;
  sys.points.clear();
  sys.min_volume_ratio = 1.0;
  Hex8Geometry geo;
  sys.min_jacobian = hex8_geometry(rule, coords, geo);
  if (sys.min_jacobian <= 0.0) {  // the caller reports the distorted element
    sys.internal_force.clear();
    sys.stiffness.clear();
    return;
  }
  Vec24 f = Vec24::Zero();
  Mat24 K;
  if (request.stiffness) K.setZero();
  for (int p = 0; p < 8; ++p) hex8_point(rule, geo, p, u, law, request, delta_t, history.at(p), f, K, sys);
  if (request.internal_force) sys.internal_force.assign(f.data(), f.data() + 24);
  else sys.internal_force.clear();
  if (request.stiffness) {
    sys.stiffness.resize(24 * 24);
    Eigen::Map<Eigen::Matrix<double, 24, 24, Eigen::RowMajor>>(sys.stiffness.data()) = K;
  } else {
    sys.stiffness.clear();
  }
}

/// Reference data of a generic element's points: coordinates, the centre's mapping (for the
/// incompatible modes and the hourglass control), the points' data and the smallest det J.
struct ElementGeometry {
  Eigen::MatrixXd X;
  Mapping centre;
  std::vector<PointData> pts;
  std::vector<Vec3> point_coords;
  double min_jacobian = std::numeric_limits<double>::infinity();
};

ElementGeometry element_geometry(const model::ElementTypeInfo& type, std::span<const Vec3> coords, const Material& law,
                                 const SectionData& section, std::span<const double> delta_t,
                                 std::span<const double> temperature) {
  const int dim = type.dim, n = type.n_nodes;
  const ElementFamily family = type.family;
  const Shape shape = element_shape(type);
  const bool incompatible = type.integration == Integration::IncompatibleModes;
  const bool hourglass = type.integration == Integration::Reduced && type.order == 1;
  const int n_modes = incompatible ? n_incompatible_modes(dim) : 0;
  const int n_total = n + n_modes;
  ElementGeometry geo;
  geo.X.resize(n, dim);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i) geo.X(a, i) = coords[a][i];
  if (incompatible || hourglass) geo.centre = map_point(shape, dim, geo.X, {0, 0, 0});
  Eigen::MatrixXd J0_inv_t;
  double j0 = 0.0;
  if (incompatible) {
    J0_inv_t = geo.centre.J.inverse().transpose();
    j0 = geo.centre.det * (family == ElementFamily::Axisymmetric ? geo.centre.radius : 1.0);
  }
  for (const QuadraturePoint& q : element_rule(type)) {
    const Mapping m = map_point(shape, dim, geo.X, q.xi);
    geo.min_jacobian = std::min(geo.min_jacobian, m.det);
    const ShapeValues sv = evaluate_shape(shape, q.xi);
    PointData pd;
    pd.N = Eigen::VectorXd::Zero(n_total);
    for (int a = 0; a < n; ++a) pd.N(a) = sv.N[a];
    pd.grad = Eigen::MatrixX3d::Zero(n_total, 3);
    pd.grad.topRows(n) = m.grad;
    pd.radius = m.radius;
    pd.x = m.x;
    pd.dv = q.weight * m.det * out_of_plane_measure(family, section, m.radius);
    if (incompatible) {
      const double j = m.det * (family == ElementFamily::Axisymmetric ? m.radius : 1.0);
      pd.grad.bottomRows(n_modes) = incompatible_mode_gradients(dim, q.xi.data(), J0_inv_t, j0, j);
    }
    for (std::size_t a = 0; a < temperature.size(); ++a) pd.temperature += sv.N[a] * temperature[a];
    if (!delta_t.empty()) {
      double dt = 0.0;
      for (int a = 0; a < n; ++a) dt += sv.N[a] * delta_t[a];
      pd.thermal_strain = law.thermal_strain(pd.temperature, dt);
    }
    geo.pts.push_back(std::move(pd));
    geo.point_coords.push_back(m.x);
  }
  return geo;
}

/// The smallest det F over the points, from their states; a hybrid element's hold F̄, whose
/// determinant is the interpolated volume ratio, not the point's own: its F is formed again.
double min_volume_ratio(const model::ElementTypeInfo& type, const std::vector<PointData>& pts,
                        const std::vector<PointState>& states, const Eigen::VectorXd& u) {
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < pts.size(); ++p) {
    const double det = type.hybrid ? point_kinematics(type.family, type.dim, true, pts[p], u).F.determinant()
                                   : states[p].F.determinant();
    smallest = std::min(smallest, det);
  }
  return smallest;
}

/// Incompatible modes: solves f_α(u, α) = 0 for the internal modes (one step when linear,
/// Newton with NLGEOM or a material with state, whose stress is nonlinear in the strain) and
/// condenses them out of f and K.
template <class Law>
void condense_modes(const model::ElementTypeInfo& type, const Law& law, const ElementRequest& request,
                    const std::vector<PointData>& pts, const ElementHistory& history, Eigen::VectorXd& uf,
                    Assembled& as, Eigen::VectorXd& f, Eigen::MatrixXd& K, ElementSystem& sys) {
  const int n_dof = type.n_nodes * type.dim;
  const int na = n_incompatible_modes(type.dim) * type.dim;
  const double ref = std::max(as.f.norm(), 1e-300);
  const bool linear = !request.nlgeom && law.state_size() == 0;
  for (int it = 0; it < 30; ++it) {
    const Eigen::VectorXd fa = as.f.tail(na);
    if (it > 0 && (linear || fa.norm() <= 1e-13 * ref)) break;
    const Eigen::MatrixXd Kaa = as.K.bottomRightCorner(na, na);
    uf.tail(na) -= Kaa.ldlt().solve(fa);
    as = assemble(type.family, type.dim, law, request.nlgeom, pts, uf, true, history);
    sys.local_iterations = it + 1;
  }
  const Eigen::MatrixXd Kaa = as.K.bottomRightCorner(na, na);
  const Eigen::MatrixXd Kua = as.K.topRightCorner(n_dof, na);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(Kaa);
  f = as.f.head(n_dof) - Kua * ldlt.solve(as.f.tail(na));
  if (request.stiffness) K = as.K.topLeftCorner(n_dof, n_dof) - Kua * ldlt.solve(Kua.transpose());
}

/// A hybrid element's points (hybrid.hpp): the pressure condensed, its f, K and states.
Assembled assemble_hybrid_points(const model::ElementTypeInfo& type, const Material& law, const ElementRequest& request,
                                 const std::vector<PointData>& pts, const Eigen::VectorXd& u,
                                 const ElementHistory& history) {
  std::vector<std::array<double, 3>> xi;
  for (const QuadraturePoint& q : element_rule(type)) xi.push_back(q.xi);
  HybridSystem h = assemble_hybrid(type, law, request.nlgeom, pts, pressure_basis(type, xi), u, request.stiffness,
                                   history);
  return {std::move(h.f), std::move(h.K), std::move(h.states)};
}

/// Every element but the full-integration C3D8: dynamic sizes, incompatible modes, hourglass
/// control of the reduced first-order elements.
template <class Law>
ElementSystem compute_generic(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                              std::span<const double> u, const Law& law, const SectionData& section,
                              const ElementRequest& request, std::span<const double> delta_t,
                              const ElementHistory& history) {
  const int dim = type.dim;
  const int n_dof = type.n_nodes * dim;
  const bool incompatible = type.integration == Integration::IncompatibleModes;
  const bool hourglass = type.integration == Integration::Reduced && type.order == 1;
  const int n_total = type.n_nodes + (incompatible ? n_incompatible_modes(dim) : 0);
  ElementSystem sys;
  sys.n_dof = n_dof;
  const ElementGeometry geo = element_geometry(type, coords, law, section, delta_t, request.temperature);
  sys.min_jacobian = geo.min_jacobian;
  if (sys.min_jacobian <= 0.0) return sys;  // the caller reports the distorted element

  Eigen::VectorXd uf = Eigen::VectorXd::Zero(n_total * dim);
  for (int k = 0; k < n_dof; ++k) uf(k) = u[k];
  const bool want_k = request.stiffness || incompatible;
  Assembled as = type.hybrid ? assemble_hybrid_points(type, law, request, geo.pts, uf, history)
                             : assemble(type.family, dim, law, request.nlgeom, geo.pts, uf, want_k, history);
  Eigen::VectorXd f = as.f.head(n_dof);
  Eigen::MatrixXd K;
  if (incompatible) {
    condense_modes(type, law, request, geo.pts, history, uf, as, f, K, sys);
  } else {
    f = as.f;
    if (request.stiffness) K = std::move(as.K);
  }
  if (request.nlgeom) sys.min_volume_ratio = min_volume_ratio(type, geo.pts, as.states, uf);
  if (hourglass) {
    const PointData& centre = geo.pts.front();  // the one-point rule integrates the whole element
    const Eigen::MatrixXd b = geo.centre.grad.leftCols(dim);
    const double shear_modulus = law.elastic_at(centre.temperature).shear_modulus();
    const Eigen::MatrixXd Khg = hourglass_stiffness(dim, geo.X, b, centre.dv, shear_modulus, section.hourglass_scale);
    f += Khg * uf.head(n_dof);
    if (request.stiffness) K += Khg;
  }
  if (request.internal_force) sys.internal_force.assign(f.data(), f.data() + n_dof);
  if (request.stiffness) {
    sys.stiffness.resize(static_cast<std::size_t>(n_dof) * n_dof);
    for (int i = 0; i < n_dof; ++i)
      for (int j = 0; j < n_dof; ++j) sys.stiffness[static_cast<std::size_t>(i) * n_dof + j] = K(i, j);
  }
  if (request.point_output) {
    sys.points.resize(geo.pts.size());
    for (std::size_t p = 0; p < geo.pts.size(); ++p) {
      const PointHistory h = history.at(p);
      point_output(type.family, law, request.nlgeom, geo.pts[p], as.states[p], sys.points[p], h.trial);
      sys.points[p].coords = geo.point_coords[p];
      if (!h.trial.empty()) law.plastic_output(h.trial, sys.points[p]);
    }
  }
  return sys;
}

void check_sizes(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                 std::span<const double> delta_t) {
  if (!model::is_continuum(type)) return;  // line_elements.cpp checks its own sizes
  const int n = type.n_nodes;
  if (static_cast<int>(coords.size()) != n || static_cast<int>(u.size()) != n * type.dim ||
      (!delta_t.empty() && static_cast<int>(delta_t.size()) != n))
    throw std::invalid_argument("compute_element: coordinate, displacement or temperature count mismatch");
}

/// The kernel for `law`: the fixed-size C3D8 one where it applies, the generic one otherwise.
template <class Law>
void compute_with(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                  const Law& law, const SectionData& section, const ElementRequest& request,
                  std::span<const double> delta_t, const ElementHistory& history, ElementSystem& out) {
  if (model::is_shell(type)) {
    if (!section.shell) throw std::invalid_argument("compute_element: a shell without its section");
    ShellMaterial material;  // none: the section's elastic laminae of constants
    if (law.state_size() > 0 || law.temperature_dependent()) material = {&law, history};
    const ShellNodeData at_nodes(section.thickness, section.nodal_thickness, section.shell_directors);
    compute_shell(type, coords, u, *section.shell, at_nodes, request, delta_t, material, out);
    return;
  }
  if (!model::is_continuum(type)) {
    compute_line_element(type, coords, u, law.elastic(), section, request, delta_t, out);
    return;
  }
  if (!request.temperature.empty() && request.temperature.size() != coords.size())
    throw std::invalid_argument("compute_element: nodal temperature count mismatch");
  if (is_full_hex8(type) && coords.size() == 8 && u.size() == 24 && (delta_t.empty() || delta_t.size() == 8)) {
    compute_hex8(type, coords, u, law, request, delta_t, history, out);
    return;
  }
  check_sizes(type, coords, u, delta_t);
  out = compute_generic(type, coords, u, law, section, request, delta_t, history);
}

}  // namespace

std::size_t material_points(const model::ElementTypeInfo& type, const SectionData& section) {
  if (model::is_shell(type) && section.shell) return shell_material_points(type, *section.shell);
  return element_rule(type).size();
}

void compute_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                     const Material& material, const SectionData& section, const ElementRequest& request,
                     std::span<const double> delta_t, const ElementHistory& history, ElementSystem& out) {
  if (const IsotropicElastic* elastic = material.as_isotropic_elastic()) {
    compute_with(type, coords, u, *elastic, section, request, delta_t, ElementHistory{}, out);
    return;
  }
  const std::size_t per_point = material.state_size();
  if (per_point == 0 || history.per_point == per_point) {
    compute_with(type, coords, u, material, section, request, delta_t, history, out);
    return;
  }
  // No history given for a material with state: its initial state, the trial state discarded.
  const std::size_t n = material_points(type, section) * per_point;
  std::vector<double> committed(n), trial(n);
  for (std::size_t p = 0; p < n; p += per_point) material.initial_state(std::span(committed).subspan(p, per_point));
  compute_with(type, coords, u, material, section, request, delta_t, ElementHistory{committed, trial, per_point}, out);
}

void compute_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                     const ElasticConstants& material, const SectionData& section, const ElementRequest& request,
                     std::span<const double> delta_t, ElementSystem& out) {
  compute_with(type, coords, u, IsotropicElastic(type.family, material), section, request, delta_t, ElementHistory{},
               out);
}

ElementSystem compute_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                              std::span<const double> u, const ElasticConstants& material,
                              const SectionData& section, const ElementRequest& request,
                              std::span<const double> delta_t) {
  check_sizes(type, coords, u, delta_t);
  ElementSystem sys;
  compute_with(type, coords, u, IsotropicElastic(type.family, material), section, request, delta_t, ElementHistory{},
               sys);
  return sys;
}

}  // namespace inpact::solver::elements
