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

ShellProperties shell_properties(const model::ShellSection& section, double youngs_modulus, double poissons_ratio,
                                 double expansion) {
  ShellProperties p;
  p.youngs_modulus = youngs_modulus;
  p.poissons_ratio = poissons_ratio;
  p.expansion = expansion;
  p.offset = section.offset;
  simpson_points(section.general ? 3 : section.section_points, p.zeta, p.weight);
  if (section.transverse_shear) p.transverse_shear = std::array<double, 2>{(*section.transverse_shear)[0],
                                                                           (*section.transverse_shear)[1]};
  return p;
}

}  // namespace inpact::solver::elements
