#include "material.hpp"

#include <algorithm>

namespace inpact::solver::elements {

using model::ElementFamily;

void Material::initial_state(std::span<double> state) const { std::fill(state.begin(), state.end(), 0.0); }

void Material::plastic_output(std::span<const double>, PointResult&) const {}

bool Material::set_plastic_strain(std::span<double>, const Vec6&) const { return false; }

bool Material::increment_too_large(std::span<const double>, std::span<const double>) const { return false; }

double Material::plane_stress_thickness_strain(const Vec3&, const Vec6& e, const Vec6&, double eth, double temperature,
                                               std::span<const double>) const {
  const double nu = elastic_at(temperature).poissons_ratio;
  return -nu / (1 - nu) * (e(0) + e(1) - 2 * eth) + eth;
}

IsotropicElastic::IsotropicElastic(ElementFamily family, const ElasticConstants& constants)
    : family_(family), constants_(constants), D_(elasticity_matrix(family, constants)) {}

IsotropicElastic::IsotropicElastic(ElementFamily family, const ElasticConstants& constants,
                                   std::optional<ElasticTable> elastic_table,
                                   std::optional<ExpansionTable> expansion_table)
    : IsotropicElastic(family, constants) {
  elastic_table_ = std::move(elastic_table);
  expansion_table_ = std::move(expansion_table);
}

ElasticConstants IsotropicElastic::elastic_at(double temperature) const {
  return elastic_table_ ? elastic_constants_at(*elastic_table_, temperature, constants_) : constants_;
}

double IsotropicElastic::thermal_strain(double temperature, double temperature_change) const {
  if (!expansion_table_) return constants_.expansion * temperature_change;
  // Tᴵ = T − ΔT: both interpolated from the nodes with the same shape functions.
  return elements::thermal_strain(*expansion_table_, temperature, temperature - temperature_change);
}

const Mat6& IsotropicElastic::stiffness_at(double temperature, Mat6& scratch) const {
  scratch = elasticity_matrix(family_, elastic_at(temperature));
  return scratch;
}

Mat6 elasticity_matrix(ElementFamily family, const ElasticConstants& m) {
  const double E = m.youngs_modulus, nu = m.poissons_ratio;
  const double mu = E / (2 * (1 + nu));
  Mat6 D = Mat6::Zero();
  if (family == ElementFamily::PlaneStress) {
    const double c = E / (1 - nu * nu);
    D(0, 0) = D(1, 1) = c;
    D(0, 1) = D(1, 0) = c * nu;
    D(3, 3) = mu;
    return D;
  }
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = lambda;
    D(i, i) = lambda + 2 * mu;
    D(i + 3, i + 3) = mu;
  }
  return D;
}

}  // namespace inpact::solver::elements
