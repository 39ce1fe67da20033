#include "beam_section_points.hpp"

#include <cmath>

namespace inpact::solver::elements {

namespace {

using Shape = model::BeamSection::Shape;

/// RECT a × b: the corners of Abaqus's 5 × 5 grid; St. Venant's shear vanishes there.
std::vector<BeamSectionPoint> rect_points(double a, double b) {
  return {{1, -a / 2, -b / 2, 0.0}, {5, a / 2, -b / 2, 0.0}, {21, -a / 2, b / 2, 0.0}, {25, a / 2, b / 2, 0.0}};
}

/// CIRC, semi-axes a (n1) and b (n2): the surface on the axes, counterclockwise from +n1. The
/// ellipse's torsional shear there is 2T/(π a² b) at (±a, 0) and 2T/(π a b²) at (0, ±b), T = G J
/// κ3 with J = π a³b³/(a² + b²): arms 2ab²/(a² + b²) and 2a²b/(a² + b²), r for a circle.
std::vector<BeamSectionPoint> circ_points(double a, double b) {
  const double on_n1 = 2 * a * b * b / (a * a + b * b), on_n2 = 2 * a * a * b / (a * a + b * b);
  return {{3, a, 0.0, on_n1}, {7, 0.0, b, on_n2}, {11, -a, 0.0, on_n1}, {15, 0.0, -b, on_n2}};
}

/// PIPE of outer radius r: eight points on the outer surface, every 45° from +n1.
std::vector<BeamSectionPoint> pipe_points(double r) {
  std::vector<BeamSectionPoint> out;
  const double c = r / std::sqrt(2.0);
  const double x1[8] = {r, c, 0.0, -c, -r, -c, 0.0, c}, x2[8] = {0.0, c, r, c, 0.0, -c, -r, -c};
  for (int k = 0; k < 8; ++k) out.push_back({k + 1, x1[k], x2[k], r});
  return out;
}

/// BOX a × b, walls t1 (+n1), t2 (+n2), t3 (−n1), t4 (−n2): the corners of the walls' midline,
/// each with the Bredt arm of the wall that starts there (walking t1, t2, t3, t4).
std::vector<BeamSectionPoint> box_points(const std::vector<double>& d, double torsion) {
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3], t3 = d[4], t4 = d[5];
  const double right = a / 2 - t1 / 2, left = -a / 2 + t3 / 2, top = b / 2 - t2 / 2, bottom = -b / 2 + t4 / 2;
  const double enclosed = (right - left) * (top - bottom);  // A_m
  auto arm = [&](double t) { return torsion / (2.0 * enclosed * t); };
  return {{1, right, bottom, arm(t1)}, {5, right, top, arm(t2)}, {9, left, top, arm(t3)}, {13, left, bottom, arm(t4)}};
}

/// I (l, h, b1, b2, t1, t2, t3): the flange tips on the flanges' midlines, from the origin; the
/// open wall's torsional shear at its faces, G κ3 t.
std::vector<BeamSectionPoint> i_points(const std::vector<double>& d) {
  const double l = d[0], h = d[1], b1 = d[2], b2 = d[3], t1 = d[4], t2 = d[5];
  const double bottom = -l + t1 / 2, top = h - l - t2 / 2;
  return {{1, -b1 / 2, bottom, t1}, {5, b1 / 2, bottom, t1}, {11, -b2 / 2, top, t2}, {15, b2 / 2, top, t2}};
}

}  // namespace

std::vector<BeamSectionPoint> beam_output_points(const model::BeamSection& section, const BeamProperties& properties) {
  const auto& d = section.dims;
  std::vector<BeamSectionPoint> points;
  switch (section.shape) {
    case Shape::Rect: points = rect_points(d[0], d[1]); break;
    case Shape::Circ: points = circ_points(section.circ_semi_axes()[0], section.circ_semi_axes()[1]); break;
    case Shape::Pipe: points = pipe_points(d[0]); break;
    case Shape::Box: points = box_points(d, properties.torsion); break;
    case Shape::I: points = i_points(d); break;
    case Shape::General:
      for (std::size_t k = 0; k < section.section_points.size(); ++k)
        points.push_back({static_cast<int>(k + 1), section.section_points[k][0], section.section_points[k][1], 0.0});
      return points;  // given from the centroid; axial output only
  }
  for (BeamSectionPoint& p : points) {  // from the shape's reference to its centroid
    p.x1 -= properties.centroid[0];
    p.x2 -= properties.centroid[1];
  }
  return points;
}

void beam_section_point_results(const BeamProperties& section, const PointResult& at, std::vector<PointResult>& out) {
  // The section strains' slots (beam_elements.hpp): ε, γ2, γ1, κ1, κ2, κ3.
  const double axial = at.strain[0], k1 = at.strain[3], k2 = at.strain[4], k3 = at.strain[5];
  for (const BeamSectionPoint& q : section.output_points) {
    PointResult r;
    r.coords = at.coords;
    r.volume = at.volume;  // weights the integration points alike when they are averaged
    r.section = at.section;
    r.strain[0] = axial + k1 * q.x2 - k2 * q.x1;
    r.strain[3] = k3 * q.torsion_arm;
    r.stress[0] = section.youngs_modulus * r.strain[0];
    r.stress[3] = section.shear_modulus * r.strain[3];
    out.push_back(r);
  }
}

}  // namespace inpact::solver::elements
