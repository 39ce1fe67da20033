#include "beam_section.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "model/beam_section_area.hpp"

namespace inpact::solver::elements {

namespace {

/// St. Venant's torsion constant of a solid a × b rectangle (Timoshenko & Goodier §109):
/// J = a b³/3 (1 − 192 b/(π⁵ a) Σ_{n odd} tanh(nπa/(2b))/n⁵) with b the shorter side. The series
/// converges like n⁻⁵: 20 terms leave < 1e-12.
double rectangle_torsion(double a, double b) {
  if (b > a) std::swap(a, b);
  double sum = 0.0;
  for (int n = 1; n < 40; n += 2) sum += std::tanh(n * std::numbers::pi * a / (2 * b)) / std::pow(n, 5);
  return a * b * b * b / 3.0 * (1.0 - 192.0 * b / (std::pow(std::numbers::pi, 5) * a) * sum);
}

}  // namespace

double shear_factor(model::BeamSection::Shape shape) {
  using Shape = model::BeamSection::Shape;
  switch (shape) {
    case Shape::Rect: return 0.85;
    case Shape::Circ: return 0.89;
    case Shape::Pipe: return 0.53;
    case Shape::Box: return 0.44;
    case Shape::General: return 1.0;
  }
  return 1.0;
}

BeamProperties beam_properties(const model::BeamSection& section, double youngs_modulus, double poissons_ratio) {
  using Shape = model::BeamSection::Shape;
  const auto& d = section.dims;
  BeamProperties p;
  p.n1 = section.n1;
  p.youngs_modulus = youngs_modulus;
  p.shear_modulus = youngs_modulus / (2.0 * (1.0 + poissons_ratio));
  const double pi = std::numbers::pi;
  p.area = model::section_area(section);
  switch (section.shape) {
    case Shape::Rect:
      p.i11 = d[0] * d[1] * d[1] * d[1] / 12.0;
      p.i22 = d[1] * d[0] * d[0] * d[0] / 12.0;
      p.torsion = rectangle_torsion(d[0], d[1]);
      break;
    case Shape::Circ:
      p.i11 = p.i22 = pi * std::pow(d[0], 4) / 4.0;
      p.torsion = 2.0 * p.i11;
      break;
    case Shape::Pipe: {
      const double inner = d[0] - d[1];
      p.i11 = p.i22 = pi * (std::pow(d[0], 4) - std::pow(inner, 4)) / 4.0;
      p.torsion = 2.0 * p.i11;
      break;
    }
    case Shape::Box: {
      // Opposite walls alike (the parser's rule): the centroid is the box's centre.
      const double a = d[0], b = d[1], side = d[2], top = d[3];  // t1 = t3, t2 = t4
      const double ai = a - 2 * side, bi = b - 2 * top;
      p.i11 = (a * b * b * b - ai * bi * bi * bi) / 12.0;
      p.i22 = (b * a * a * a - bi * ai * ai * ai) / 12.0;
      // Bredt: J = 4 A_m² / ∮ ds/t over the walls' midline.
      const double am = (a - side) * (b - top);
      p.torsion = 4.0 * am * am / (2.0 * (a - side) / top + 2.0 * (b - top) / side);
      break;
    }
    case Shape::General:
      p.i11 = d[1];
      p.i22 = d[3];
      p.torsion = d[4];
      p.youngs_modulus = section.youngs_modulus;
      p.shear_modulus = section.shear_modulus;
      break;
  }
  const double kga = shear_factor(section.shape) * p.shear_modulus * p.area;
  p.k13 = section.k13.value_or(kga);
  p.k23 = section.k23.value_or(kga);
  p.slenderness_compensation = section.slenderness_compensation.value_or(0.25);
  return p;
}

}  // namespace inpact::solver::elements
