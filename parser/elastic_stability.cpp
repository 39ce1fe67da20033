#include "elastic_stability.hpp"

#include <cmath>
#include <initializer_list>

#include <fmt/format.h>

#include "model/elastic_stiffness.hpp"

namespace inpact::parser {

using model::Elastic;

namespace {

std::optional<ElasticInstability> positive(const std::vector<double>& c, std::initializer_list<std::size_t> which,
                                           const char* const* names) {
  for (std::size_t k : which)
    if (!(c[k] > 0)) return ElasticInstability{fmt::format("{} must be positive, found {}", names[k], c[k]), k};
  return std::nullopt;
}

std::optional<ElasticInstability> engineering_instability(const std::vector<double>& c) {
  static const char* const names[] = {"E1", "E2", "E3", "nu12", "nu13", "nu23", "G12", "G13", "G23"};
  if (auto bad = positive(c, {0, 1, 2, 6, 7, 8}, names)) return bad;
  const double e1 = c[0], e2 = c[1], e3 = c[2], n12 = c[3], n13 = c[4], n23 = c[5];
  const struct { std::size_t k; double limit; const char* text; } bounds[] = {
      {3, std::sqrt(e1 / e2), "|nu12| < sqrt(E1/E2)"}, {4, std::sqrt(e1 / e3), "|nu13| < sqrt(E1/E3)"},
      {5, std::sqrt(e2 / e3), "|nu23| < sqrt(E2/E3)"}};
  for (const auto& b : bounds)
    if (!(std::abs(c[b.k]) < b.limit))
      return ElasticInstability{fmt::format("unstable material: {} is required, found {} (limit {})", b.text, c[b.k], b.limit), b.k};
  const double n21 = n12 * e2 / e1, n32 = n23 * e3 / e2, n31 = n13 * e3 / e1;
  const double det = 1 - n12 * n21 - n23 * n32 - n31 * n13 - 2 * n21 * n32 * n13;
  if (!(det > 0))
    return ElasticInstability{fmt::format("unstable material: 1 - nu12 nu21 - nu23 nu32 - nu31 nu13 - 2 nu21 nu32 nu13 "
                                          "must be positive, found {}", det), 3};
  return std::nullopt;
}

std::optional<ElasticInstability> orthotropic_instability(const std::vector<double>& c) {
  static const char* const names[] = {"D1111", "D1122", "D2222", "D1133", "D2233", "D3333", "D1212", "D1313", "D2323"};
  if (auto bad = positive(c, {0, 2, 5, 6, 7, 8}, names)) return bad;
  const struct { std::size_t k, a, b; const char* text; } bounds[] = {
      {1, 0, 2, "|D1122| < sqrt(D1111 D2222)"}, {3, 0, 5, "|D1133| < sqrt(D1111 D3333)"},
      {4, 2, 5, "|D2233| < sqrt(D2222 D3333)"}};
  for (const auto& b : bounds)
    if (!(std::abs(c[b.k]) < std::sqrt(c[b.a] * c[b.b])))
      return ElasticInstability{fmt::format("unstable material: {} is required, found {}", b.text, c[b.k]), b.k};
  model::Elastic orthotropic;
  orthotropic.type = Elastic::Type::Orthotropic;
  orthotropic.constants = c;
  if (!model::positive_definite(model::material_stiffness(orthotropic)))
    return ElasticInstability{"unstable material: det D > 0 is required (D1111 D2222 D3333 - D1111 D2233^2 - D2222 "
                              "D1133^2 - D3333 D1122^2 + 2 D1122 D2233 D1133 <= 0)", 0};
  return std::nullopt;
}

}  // namespace

std::optional<ElasticInstability> elastic_instability(const Elastic& elastic) {
  const std::vector<double>& c = elastic.constants;
  switch (elastic.type) {
    case Elastic::Type::Isotropic: return std::nullopt;  // the parser checks E > 0, −1 < ν < 0.5
    case Elastic::Type::EngineeringConstants: return engineering_instability(c);
    case Elastic::Type::Orthotropic: return orthotropic_instability(c);
    case Elastic::Type::Anisotropic:
      if (model::positive_definite(model::material_stiffness(elastic))) return std::nullopt;
      return ElasticInstability{"unstable material: the stiffness D is not positive definite", 0};
    case Elastic::Type::Lamina: {
      static const char* const names[] = {"E1", "E2", "nu12", "G12", "G13", "G23"};
      if (auto bad = positive(c, {0, 1, 3, 4, 5}, names)) return bad;
      if (!(std::abs(c[2]) < std::sqrt(c[0] / c[1])))
        return ElasticInstability{fmt::format("unstable material: |nu12| < sqrt(E1/E2) is required, found {}", c[2]), 2};
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace inpact::parser
