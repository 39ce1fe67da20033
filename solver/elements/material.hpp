#pragma once
/// The material behind an integration point: strain (and deformation) and the point's
/// committed state in → stress, tangent and the trial state out.
///
///   stress = σ(strain, committed state),  tangent = ∂stress/∂strain,  trial state
///
/// The strain is the element's measure: ε = sym(F − I) for small strain, E = ½(FᵀF − I) with
/// NLGEOM (total Lagrangian; the stress is then S, the second Piola–Kirchhoff stress, and the
/// element adds the geometric stiffness itself). Voigt order 11, 22, 33, 12, 13, 23 with
/// engineering shear strains.
///
/// State contract (see solver/material_states.hpp): a material with state_size() > 0 reads the
/// committed state of the point — the state of the last converged increment — and writes the
/// trial state for the strain it is given; it never writes the committed state. Evaluations
/// may be repeated at any strain (Newton iterations, cut-back attempts, output): each one starts
/// from the same committed state, so the trial state depends only on it and the strain.
/// A stateless material (state_size() = 0) gets empty spans and no storage at all.
#include <cstddef>
#include <optional>
#include <span>

#include <Eigen/Core>

#include "element_kernel.hpp"
#include "temperature_tables.hpp"

namespace inpact::solver::elements {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// What an integration point hands its material.
struct MaterialPointInput {
  const Eigen::Matrix3d& F;  ///< deformation gradient I + ∇₀u (CAX: F33 = 1 + u_r/R)
  const Vec6& strain;        ///< ε, or E with NLGEOM
  double thermal_strain;     ///< ε_th at the point (isotropic, on the diagonal; Material::thermal_strain)
  /// Reference coordinates of the point, for a material whose axes depend on where the point is
  /// (a cylindrical *ORIENTATION); null where no element is behind the call (unit tests).
  const Vec3* position = nullptr;
  bool nlgeom = false;       ///< the element is total Lagrangian: strain is E, the stress wanted S
  /// The temperature at the point (0 where the model has none); read only by a material whose
  /// temperature_dependent() says so, for whom the elements interpolate it.
  double temperature = 0.0;
};

class IsotropicElastic;

class Material {
 public:
  virtual ~Material() = default;

  /// Doubles of history each integration point carries; 0: stateless.
  virtual std::size_t state_size() const { return 0; }
  /// The state of a point before the first increment (state_size() values).
  virtual void initial_state(std::span<double> state) const;
  /// Writes the stress at `in` into `stress` and returns the tangent: a matrix the material
  /// owns (a constant tangent), or `scratch` filled with it. Writes `point.trial` from
  /// `point.committed` (both empty when stateless).
  virtual const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                             Mat6& scratch) const = 0;
  /// The elastic constants, for what is not the stress: the expansion α, the hourglass
  /// control's shear modulus, the plane-stress thickness strain in the output.
  virtual const ElasticConstants& elastic() const = 0;
  /// The plastic strain (PE, engineering shear) and the equivalent plastic strain (PEEQ) of a
  /// point's state, for output; a material without plasticity leaves them zero.
  virtual void plastic_output(std::span<const double> state, PointResult& out) const;
  /// Sets the plastic strain (engineering shear) of a point's initial state; false when the
  /// material has no plastic strain (*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN).
  virtual bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const;
  /// Whether a point's step from `committed` to `trial` is too large to accept (plasticity: an
  /// equivalent plastic strain increment above fifty times the strain of first yield); the
  /// increment is then cut back.
  virtual bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const;
  /// Plane stress: the thickness strain ε33 (E33 with NLGEOM) that makes σ33 = 0 at a point of
  /// in-plane `strain` and `stress` and temperature T, for output; `state` is the point's
  /// (trial) state, empty when stateless. The default is the isotropic one of elastic_at(T),
  /// ε33 = −ν/(1−ν)(ε11 + ε22 − 2ε_th) + ε_th.
  virtual double plane_stress_thickness_strain(const Vec3& position, const Vec6& strain, const Vec6& stress,
                                               double thermal_strain, double temperature,
                                               std::span<const double> state) const;
  /// Whether the material reads MaterialPointInput::temperature (temperature-dependent data).
  virtual bool temperature_dependent() const { return false; }
  /// The isotropic constants at temperature T (the hourglass control's shear modulus, the plane
  /// stress thickness strain); elastic() unless the material's E or ν depend on temperature.
  virtual ElasticConstants elastic_at(double /*temperature*/) const { return elastic(); }
  /// The thermal strain of a point at temperature T that changed by ΔT = T − Tᴵ since its
  /// initial condition: α ΔT with the α of elastic(), unless α depends on temperature
  /// (IsotropicElastic with an *EXPANSION table).
  virtual double thermal_strain(double /*temperature*/, double temperature_change) const {
    return elastic().expansion * temperature_change;
  }
  /// The element kernels' fast path: this material when it is isotropic linear elastic.
  virtual const IsotropicElastic* as_isotropic_elastic() const { return nullptr; }
};

/// Isotropic linear elasticity (*ELASTIC) with isotropic expansion (*EXPANSION):
/// stress = D (strain − ε_th I), D the isotropic matrix of the element family (plane stress
/// condensed for σ33 = 0, see elasticity_matrix). With NLGEOM this is St. Venant–Kirchhoff,
/// S = D E. Stateless: no storage, one matrix shared by every point of the section.
/// Temperature tables (temperature_tables.hpp): D(T) from E(T), ν(T) at the point's
/// temperature, and ε_th = α(T)(T − T⁰) − α(Tᴵ)(Tᴵ − T⁰); elastic() then holds the first rows.
/// The stress is the total form σ = D(T)(ε − ε_th) of Abaqus's temperature-dependent elasticity.
class IsotropicElastic final : public Material {
 public:
  IsotropicElastic(model::ElementFamily family, const ElasticConstants& constants);
  /// With E, ν and/or α as functions of temperature (an absent table: that datum is constant).
  IsotropicElastic(model::ElementFamily family, const ElasticConstants& constants,
                   std::optional<ElasticTable> elastic_table, std::optional<ExpansionTable> expansion_table);

  const Mat6& update(const MaterialPointInput& in, const PointHistory&, Vec6& stress, Mat6& scratch) const override {
    Vec6 eth = Vec6::Zero();
    eth.head<3>().setConstant(in.thermal_strain);
    const Mat6& D = elastic_table_ ? stiffness_at(in.temperature, scratch) : D_;
    stress = D * (in.strain - eth);
    return D;
  }
  const ElasticConstants& elastic() const override { return constants_; }
  const IsotropicElastic* as_isotropic_elastic() const override { return this; }
  bool temperature_dependent() const override { return elastic_table_ || expansion_table_; }
  ElasticConstants elastic_at(double temperature) const override;
  double thermal_strain(double temperature, double temperature_change) const override;

  /// The elasticity matrix (of the first rows when E, ν depend on temperature).
  const Mat6& D() const { return D_; }

 private:
  /// D(T) into `scratch`.
  const Mat6& stiffness_at(double temperature, Mat6& scratch) const;

  model::ElementFamily family_;
  ElasticConstants constants_;
  Mat6 D_;
  std::optional<ElasticTable> elastic_table_;
  std::optional<ExpansionTable> expansion_table_;
};

/// The elasticity matrix in Voigt order 11, 22, 33, 12, 13, 23 (engineering shear):
/// 3D/plane strain/axisymmetric: the isotropic 3D matrix (λ + 2μ on the diagonal, μ for shear);
/// plane stress: the in-plane matrix condensed for σ33 = 0, E/(1−ν²)[[1, ν], [ν, 1]] and μ for 12,
/// zero rows/columns for 33, 13, 23.
Mat6 elasticity_matrix(model::ElementFamily family, const ElasticConstants& m);

}  // namespace inpact::solver::elements
