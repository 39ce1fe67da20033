#include "shell_section.hpp"

#include <stdexcept>

namespace inpact::solver::elements {

void simpson_points(int n, std::vector<double>& zeta, std::vector<double>& weight) {
  if (n < 3 || n % 2 == 0) throw std::invalid_argument("simpson_points: n must be odd and at least 3");
  zeta.resize(static_cast<std::size_t>(n));
  weight.resize(static_cast<std::size_t>(n));
  const double h = 2.0 / (n - 1);
  for (int k = 0; k < n; ++k) {
    zeta[static_cast<std::size_t>(k)] = -1.0 + k * h;
    const double factor = k == 0 || k == n - 1 ? 1.0 : k % 2 == 1 ? 4.0 : 2.0;
    weight[static_cast<std::size_t>(k)] = factor * h / 3.0;
  }
}

ShellProperties shell_properties(const model::ShellSection& section, std::vector<ShellLayerProperties> layers) {
  const bool composite = !section.layers.empty();
  if (layers.size() != (composite ? section.layers.size() : 1))
    throw std::invalid_argument("shell_properties: one lamina per layer");
  ShellProperties p;
  p.layers = std::move(layers);
  p.offset = section.offset;
  double below = 0.0;  // the thickness fraction under the layer
  std::vector<double> zeta, weight;
  for (std::size_t k = 0; k < p.layers.size(); ++k) {
    const double fraction = composite ? section.layers[k].thickness / section.thickness : 1.0;
    const int points = section.general ? 3 : composite ? section.layers[k].section_points : section.section_points;
    simpson_points(points, zeta, weight);
    for (std::size_t i = 0; i < zeta.size(); ++i) {
      // The layer spans ζ ∈ [2·below − 1, 2·(below + fraction) − 1].
      p.zeta.push_back(2 * below - 1 + fraction * (zeta[i] + 1));
      p.weight.push_back(fraction * weight[i]);
      p.layer_of.push_back(static_cast<int>(k));
    }
    below += fraction;
  }
  p.zeta.back() = 1.0;  // SPOS exactly, whatever the fractions' rounding
  if (section.transverse_shear) p.transverse_shear = std::array<double, 2>{(*section.transverse_shear)[0],
                                                                           (*section.transverse_shear)[1]};
  return p;
}

ShellProperties shell_properties(const model::ShellSection& section, double youngs_modulus, double poissons_ratio,
                                 double expansion) {
  ShellLayerProperties layer;
  layer.lamina = isotropic_lamina(youngs_modulus, poissons_ratio, expansion);
  return shell_properties(section, {layer});
}

double section_bending_stiffness(const ShellProperties& section, double thickness) {
  double sum = 0.0;
  for (std::size_t k = 0; k < section.zeta.size(); ++k) {
    const Matrix3x3& q = section.layer_at(k).lamina.in_plane;
    const double z = section.zeta[k] * thickness / 2;
    sum += section.weight[k] * thickness / 2 * z * z * (q[0][0] + q[1][1]) / 2;
  }
  return sum;
}

}  // namespace inpact::solver::elements
