#include "normal_behavior.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "model/elastic_stiffness.hpp"
#include "model/element_types.hpp"
#include "model/mesh_queries.hpp"

namespace inpact::contact {

namespace {

using model::EnforcementMethod;
using model::PressureOverclosure;

/// [AX p.784]: Lagrange multipliers switch on above this multiple of k_e.
constexpr double kLagrangeLimit = 1000.0;
/// A stiffness that is 1000 k_e by construction (100 × 10 k_e) must not cross the limit by
/// round-off.
constexpr double kRoundOff = 1e-12;

bool penalty_type(EnforcementMethod m) {
  return m == EnforcementMethod::PenaltyLinear || m == EnforcementMethod::PenaltyNonlinear ||
         m == EnforcementMethod::AugmentedLagrange;
}

/// The method Abaqus/Standard picks when the deck names none (KEYWORDS.md Part C d, [IG]).
void choose_default_method(ResolvedNormalBehavior& r, model::ContactDiscretization discretization,
                           bool small_sliding, bool general_contact, bool self_contact_3d) {
  auto set = [&](EnforcementMethod m, const char* why) {
    r.method = m;
    r.method_reason = why;
  };
  if (r.law != PressureOverclosure::Hard) set(EnforcementMethod::Direct, "softened laws are enforced directly");
  else if (general_contact) set(EnforcementMethod::PenaltyLinear, "Abaqus default for general contact");
  else if (small_sliding) set(EnforcementMethod::Direct, "Abaqus default for small-sliding pairs");
  else if (discretization == model::ContactDiscretization::SurfaceToSurface)
    set(EnforcementMethod::PenaltyLinear, "Abaqus default for finite-sliding surface-to-surface pairs");
  else if (self_contact_3d)
    set(EnforcementMethod::AugmentedLagrange, "Abaqus default for 3-D node-to-surface self-contact (inpact's in 2-D too)");
  else set(EnforcementMethod::Direct, "Abaqus default for node-to-surface pairs");
}

}  // namespace

ResolvedNormalBehavior resolve_normal_behavior(const model::SurfaceInteraction* interaction,
                                               model::ContactDiscretization discretization,
                                               bool small_sliding, bool general_contact,
                                               const NormalBehaviorOptions& options) {
  ResolvedNormalBehavior r;
  if (interaction && interaction->behavior) r.deck = *interaction->behavior;
  r.law = r.deck.pressure_overclosure;
  if (r.deck.method != EnforcementMethod::Default) {
    r.method = r.deck.method;
    r.method_is_default = false;
    r.method_reason = "given in *SURFACE BEHAVIOR";
  } else {
    choose_default_method(r, discretization, small_sliding, general_contact, options.self_contact_3d);
  }

  const model::ContactControls* cc = options.controls;
  if (cc) r.user_adaptive_stiffness = cc->user_adaptive_stiffness;
  if (!penalty_type(r.method)) return r;

  // Default stiffness multiples of k_e: linear penalty 10 [IG "Linear Penalty Method"],
  // nonlinear final stiffness 100 [IG], augmented Lagrange 1000 [AX p.782]. The step's
  // STIFFNESS SCALE FACTOR multiplies the behaviour's own factor [AX p.781].
  r.default_factor = r.method == EnforcementMethod::PenaltyLinear      ? 10.0
                     : r.method == EnforcementMethod::PenaltyNonlinear ? 100.0
                                                                       : 1000.0;
  r.given_stiffness = r.deck.penalty_stiffness;
  r.scale_factor = r.deck.stiffness_scale_factor * (cc && cc->stiffness_scale_factor ? *cc->stiffness_scale_factor : 1.0);
  r.initial_final_ratio = r.deck.initial_final_stiffness_ratio.value_or(r.initial_final_ratio);
  r.upper_quadratic_limit = r.deck.upper_quadratic_limit_scale_factor.value_or(r.upper_quadratic_limit);
  r.lower_quadratic_ratio = r.deck.lower_quadratic_limit_ratio.value_or(r.lower_quadratic_ratio);

  if (r.method != EnforcementMethod::AugmentedLagrange) return r;
  // Penetration tolerance [AX p.782-783]: 0.1 % of the characteristic interface length, 5 % for
  // finite-sliding surface-to-surface (general contact in Abaqus/Standard is that formulation),
  // the default scaled by 1/√f_k when f_k < 1 (f_k: both scale factors together, since [AX]
  // names "the interface discussed below", which is both); a given tolerance is never scaled.
  if (cc && cc->absolute_penetration_tolerance) {
    r.tolerance = *cc->absolute_penetration_tolerance;
    r.tolerance_is_absolute = true;
    r.tolerance_is_default = false;
  } else if (cc && cc->relative_penetration_tolerance) {
    r.tolerance = *cc->relative_penetration_tolerance;
    r.tolerance_is_default = false;
  } else {
    const bool finite_sts =
        general_contact || (discretization == model::ContactDiscretization::SurfaceToSurface && !small_sliding);
    double t = finite_sts ? 0.05 : 0.001;
    if (r.scale_factor < 1.0) t /= std::sqrt(r.scale_factor);
    r.tolerance = t;
  }
  return r;
}

double penalty_stiffness(const ResolvedNormalBehavior& r, double ke) {
  if (!penalty_type(r.method)) return 0.0;
  return (r.given_stiffness ? *r.given_stiffness : r.default_factor * ke) * r.scale_factor;
}

bool uses_lagrange_multipliers(const ResolvedNormalBehavior& r, double ke, double slope) {
  if (r.law != PressureOverclosure::Hard) return slope > kLagrangeLimit * ke * (1.0 + kRoundOff);
  if (penalty_type(r.method)) return penalty_stiffness(r, ke) > kLagrangeLimit * ke * (1.0 + kRoundOff);
  return true;  // direct hard contact: always
}

std::optional<double> penetration_tolerance(const ResolvedNormalBehavior& r, double l_char) {
  if (!r.tolerance) return std::nullopt;
  return r.tolerance_is_absolute ? *r.tolerance : *r.tolerance * l_char;
}

// ---------------------------------------------------------------------------------------------
// Mesh scales.
//
// k_e: Abaqus does not publish its "representative underlying element stiffness" (KEYWORDS.md
// Part C a). inpact takes, per slave facet, the stiffness of its element against a pressure on
// that facet, per unit area — the units of a penalty stiffness and of a softened law's slope
// (pressure per overclosure), so k_pen and k_e compare directly:
//     k_f = M / h,   h = V_e / A_f  (3-D; 2-D: element area / edge length)
// where h is the element's thickness normal to the facet (exact for a brick or a prism, a third
// of the height for a tetrahedron) and M the constrained (P-wave) modulus
//     M = E (1 − ν) / ((1 + ν)(1 − 2ν))   (3-D, plane strain, axisymmetric)
//     M = E / (1 − ν²)                     (plane stress)
// because the layer under a contact patch is held laterally by the material around it, so it
// deforms in uniaxial strain, not uniaxial stress. k_e is the median over the facets: robust to
// a few distorted or tiny elements, and O(n) with nth_element. A pair of two materials takes
// the softer one's M over the slave's h (softer_element_stiffness).
// Characteristic length: the median facet size, √A_f in 3-D and the edge length in 2-D — the
// "typical facet size" the manuals name (the averaging rule is not published either).
// Only corner nodes are used (straight-sided elements): an estimate, and cheap.

namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

/// Area of a 3-D facet from its corners (a quadrilateral through its diagonals: exact when
/// planar, the projected area when warped).
double facet_area(const std::vector<Vec>& c) {
  if (c.size() == 3) return 0.5 * norm(cross(sub(c[1], c[0]), sub(c[2], c[0])));
  return 0.5 * norm(cross(sub(c[2], c[0]), sub(c[3], c[1])));
}

std::vector<Vec> corners(const model::Model& m, std::size_t e, const model::FaceDef& f) {
  auto nodes = m.mesh.elements.nodes_of(e);
  std::vector<Vec> out(f.n_corners);
  for (int i = 0; i < f.n_corners; ++i) out[i] = m.mesh.nodes.coords[nodes[f.nodes[i]]];
  return out;
}

/// Volume of a 3-D element by the divergence theorem over its faces, split into triangles.
double element_volume(const model::Model& m, std::size_t e) {
  const model::ElementTypeInfo& info = model::element_type(m.mesh.elements.type[e]);
  double six_v = 0.0;
  for (const model::FaceDef& f : info.faces) {
    const auto c = corners(m, e, f);
    for (std::size_t i = 1; i + 1 < c.size(); ++i) six_v += dot(c[0], cross(c[i], c[i + 1]));
  }
  return std::abs(six_v) / 6.0;
}

/// Area of a 2-D element (shoelace over its corners, which are its first nodes in order).
double element_area(const model::Model& m, std::size_t e) {
  const model::ElementTypeInfo& info = model::element_type(m.mesh.elements.type[e]);
  auto nodes = m.mesh.elements.nodes_of(e);
  const std::size_t n = info.faces.size();  // a 2-D element has as many corners as edges
  double twice = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec& a = m.mesh.nodes.coords[nodes[i]];
    const Vec& b = m.mesh.nodes.coords[nodes[(i + 1) % n]];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return std::abs(twice) / 2.0;
}

/// The modulus that scales a face's contact stiffness: isotropic, E(1 − ν)/((1 + ν)(1 − 2ν)), or
/// E/(1 − ν²) in plane stress; another type, the mean of its stiffness's direct terms D11, D22,
/// D33 (D33 = 0 for a lamina: D11, D22).
double constrained_modulus(const model::Elastic& el, model::ElementFamily family) {
  if (el.type != model::Elastic::Type::Isotropic) {
    const model::Stiffness d = model::material_stiffness(el);
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (d[7 * i] > 0.0) sum += d[7 * i], ++n;
    return n > 0 ? sum / n : 0.0;
  }
  const double e = el.youngs_modulus, nu = el.poissons_ratio;
  if (family == model::ElementFamily::PlaneStress) return e / (1.0 - nu * nu);
  return e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

/// The elastic constants of every element (null where no section or no *ELASTIC), and each
/// shell's thickness (0 for other elements).
struct ElementElasticity {
  std::vector<const model::Elastic*> elastic;
  std::vector<double> shell_thickness;
};

/// The material that stands for a shell section's stiffness in contact: its own, or a COMPOSITE's
/// thickest layer's (the first of equals).
const std::string& shell_contact_material(const model::ShellSection& sec) {
  if (sec.layers.empty()) return sec.material;
  const model::ShellLayer* thickest = &sec.layers.front();
  for (const model::ShellLayer& layer : sec.layers)
    if (layer.thickness > thickest->thickness) thickest = &layer;
  return thickest->material;
}

ElementElasticity element_elasticity(const model::Model& m) {
  ElementElasticity out{std::vector<const model::Elastic*>(m.mesh.elements.size(), nullptr),
                        std::vector<double>(m.mesh.elements.size(), 0.0)};
  auto assign = [&](const std::string& elset, const std::string& material) -> const std::vector<std::int32_t>* {
    auto set = m.mesh.elsets.find(elset);
    auto mat = m.materials.find(material);
    if (set == m.mesh.elsets.end() || mat == m.materials.end() || !mat->second.elastic) return nullptr;
    for (std::int32_t e : set->second.rows) out.elastic[e] = &*mat->second.elastic;
    return &set->second.rows;
  };
  for (const model::SolidSection& sec : m.mesh.sections) assign(sec.elset, sec.material);
  for (const model::ShellSection& sec : m.mesh.shell_sections)
    if (const auto* rows = assign(sec.elset, shell_contact_material(sec)))
      for (std::int32_t e : *rows) out.shell_thickness[e] = model::shell_thickness(m.mesh, sec, static_cast<std::size_t>(e));
  return out;
}

double median(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

}  // namespace

std::optional<SurfaceScales> surface_scales(const model::Model& m, const model::Surface& surface) {
  if (surface.kind != model::Surface::Kind::Element) return std::nullopt;
  const auto [elastic, shell_thickness] = element_elasticity(m);
  std::vector<double> stiffness, size, modulus;
  stiffness.reserve(surface.faces.size());
  size.reserve(surface.faces.size());
  modulus.reserve(surface.faces.size());
  for (const model::Face& face : surface.faces) {
    const std::size_t e = static_cast<std::size_t>(face.element);
    if (!elastic[e]) continue;
    const model::ElementTypeInfo& info = model::element_type(m.mesh.elements.type[e]);
    const auto c = corners(m, e, info.faces[face.face]);
    double facet = 0.0, thickness = 0.0;
    if (model::is_shell(info)) {  // the face is the element: its depth is the shell's thickness
      facet = std::sqrt(facet_area(c));
      thickness = shell_thickness[e];
    } else if (info.dim == 3) {
      const double area = facet_area(c);
      facet = std::sqrt(area);
      thickness = area > 0 ? element_volume(m, e) / area : 0.0;
    } else {
      facet = norm(sub(c[1], c[0]));
      thickness = facet > 0 ? element_area(m, e) / facet : 0.0;
    }
    if (thickness <= 0) continue;  // a degenerate element says nothing about stiffness
    modulus.push_back(constrained_modulus(*elastic[e], info.family));
    stiffness.push_back(modulus.back() / thickness);
    size.push_back(facet);
  }
  if (stiffness.empty()) return std::nullopt;
  SurfaceScales s;
  s.n_facets = stiffness.size();
  s.element_stiffness = median(stiffness);
  s.characteristic_length = median(size);
  s.modulus = median(modulus);
  return s;
}

double softer_element_stiffness(const SurfaceScales& own, const SurfaceScales& other) {
  if (!(other.modulus < own.modulus)) return own.element_stiffness;
  return own.element_stiffness * (other.modulus / own.modulus);
}

}  // namespace inpact::contact
