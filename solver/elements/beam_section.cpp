#include "beam_section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "beam_section_points.hpp"
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

/// The section's widths along n1 and n2, the unit of CalculiX's OFFSET1 and OFFSET2.
std::array<double, 2> section_extent(const model::BeamSection& s) {
  const auto& d = s.dims;
  switch (s.shape) {
    case model::BeamSection::Shape::Rect:
    case model::BeamSection::Shape::Box: return {d[0], d[1]};
    case model::BeamSection::Shape::Circ: return {2 * s.circ_semi_axes()[0], 2 * s.circ_semi_axes()[1]};
    case model::BeamSection::Shape::Pipe: return {2 * d[0], 2 * d[0]};
    case model::BeamSection::Shape::I: return {std::max(d[2], d[3]), d[1]};
    case model::BeamSection::Shape::General: return {0.0, 0.0};
  }
  return {0.0, 0.0};
}

/// A hollow rectangle a × b with walls t1 (+n1), t2 (+n2), t3 (−n1), t4 (−n2): the outer
/// rectangle less the inner, whose centre is ((t3 − t1)/2, (t4 − t2)/2) from the outer's.
void box_properties(const std::vector<double>& d, BeamProperties& p) {
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3], t3 = d[4], t4 = d[5];
  const double ai = a - t1 - t3, bi = b - t2 - t4, inner = ai * bi, area = a * b - inner;
  const double c1 = (t3 - t1) / 2, c2 = (t4 - t2) / 2;  // the inner rectangle's centre
  const double x1 = -inner * c1 / area, x2 = -inner * c2 / area;  // the centroid
  p.i11 = a * b * b * b / 12 - (ai * bi * bi * bi / 12 + inner * c2 * c2) - area * x2 * x2;
  p.i22 = b * a * a * a / 12 - (bi * ai * ai * ai / 12 + inner * c1 * c1) - area * x1 * x1;
  // Bredt: J = 4 A_m² / ∮ ds/t over the walls' midline.
  const double am = a - (t1 + t3) / 2, bm = b - (t2 + t4) / 2;
  p.torsion = 4 * am * am * bm * bm / (bm / t1 + bm / t3 + am / t2 + am / t4);
  p.centroid = {x1, x2};
}

/// Abaqus's I: the bottom flange b1 × t1 from x2 = −l, the top flange b2 × t2 ending at h − l,
/// the web t3 between them, all centred on x1 = 0.
void i_properties(const std::vector<double>& d, BeamProperties& p) {
  const double l = d[0], h = d[1], b1 = d[2], b2 = d[3], t1 = d[4], t2 = d[5], t3 = d[6];
  const double web = h - t1 - t2;
  const std::array<double, 3> area{b1 * t1, b2 * t2, web * t3};
  const std::array<double, 3> mid{-l + t1 / 2, h - l - t2 / 2, -l + t1 + web / 2};  // x2 of each part
  const std::array<double, 3> own{b1 * t1 * t1 * t1 / 12, b2 * t2 * t2 * t2 / 12, t3 * web * web * web / 12};
  const double total = area[0] + area[1] + area[2];
  const double x2 = (area[0] * mid[0] + area[1] * mid[1] + area[2] * mid[2]) / total;
  p.i11 = 0.0;
  for (int k = 0; k < 3; ++k) p.i11 += own[k] + area[k] * (mid[k] - x2) * (mid[k] - x2);
  p.i22 = (t1 * b1 * b1 * b1 + t2 * b2 * b2 * b2 + web * t3 * t3 * t3) / 12;
  p.torsion = (b1 * t1 * t1 * t1 + b2 * t2 * t2 * t2 + web * t3 * t3 * t3) / 3;
  p.centroid = {0.0, x2};
}

}  // namespace

double shear_factor(model::BeamSection::Shape shape) {
  using Shape = model::BeamSection::Shape;
  switch (shape) {
    case Shape::Rect: return 0.85;
    case Shape::Circ: return 0.89;
    case Shape::Pipe: return 0.53;
    case Shape::Box: return 0.44;
    case Shape::I: return 1.0;  // beam_properties gives the I its own shear areas
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
    case Shape::Circ: {  // an ellipse of semi-axes a (n1), b (n2); a circle when a = b
      const auto [a, b] = section.circ_semi_axes();
      p.i11 = pi * a * b * b * b / 4.0;
      p.i22 = pi * a * a * a * b / 4.0;
      p.torsion = pi * a * a * a * b * b * b / (a * a + b * b);
      break;
    }
    case Shape::Pipe: {
      const double inner = d[0] - d[1];
      p.i11 = p.i22 = pi * (std::pow(d[0], 4) - std::pow(inner, 4)) / 4.0;
      p.torsion = 2.0 * p.i11;
      break;
    }
    case Shape::Box: box_properties(d, p); break;
    case Shape::I: i_properties(d, p); break;
    case Shape::General:
      p.i11 = d[1];
      p.i22 = d[3];
      p.torsion = d[4];
      p.youngs_modulus = section.youngs_modulus;
      p.shear_modulus = section.shear_modulus;
      break;
  }
  const double kga = shear_factor(section.shape) * p.shear_modulus * p.area;
  double k13 = kga, k23 = kga;
  if (section.shape == Shape::I) {
    k13 = 5.0 / 6 * p.shear_modulus * (d[2] * d[4] + d[3] * d[5]);
    k23 = p.shear_modulus * d[6] * (d[1] - (d[4] + d[5]) / 2);  // the web between the flanges' midlines
  }
  p.k13 = section.k13.value_or(k13);
  p.k23 = section.k23.value_or(k23);
  p.output_points = beam_output_points(section, p);  // from the shape's centroid, before any offset
  const std::array<double, 2> extent = section_extent(section);
  for (int k = 0; k < 2; ++k) p.centroid[k] -= section.offset[k] * extent[k];
  p.slenderness_compensation = section.slenderness_compensation.value_or(0.25);
  return p;
}

}  // namespace inpact::solver::elements
