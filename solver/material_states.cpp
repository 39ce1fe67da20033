#include "material_states.hpp"

#include <algorithm>

#include "elements/material.hpp"
#include "elements/quadrature.hpp"
#include "elements/shell_section.hpp"

namespace inpact::solver {

MaterialStates::MaterialStates(const AnalysisModel& am) {
  const std::size_t n_el = am.elements.size();
  const bool any = std::any_of(am.elements.begin(), am.elements.end(),
                               [](const ElementSetup& s) { return s.material && s.material->state_size() > 0; });
  if (!any) return;  // nothing at all for stateless models
  offset_.assign(n_el + 1, 0);
  per_point_.assign(n_el, 0);
  for (std::size_t e = 0; e < n_el; ++e) {
    const ElementSetup& s = am.elements[e];
    const std::size_t size = s.material ? s.material->state_size() : 0;
    per_point_[e] = static_cast<std::uint32_t>(size);
    offset_[e + 1] = offset_[e] + (size ? size * elements::material_points(*s.type, s.section) : 0);
  }
  committed_.assign(offset_.back(), 0.0);
  for (std::size_t e = 0; e < n_el; ++e)
    for (std::size_t p = offset_[e]; p < offset_[e + 1]; p += per_point_[e])
      am.elements[e].material->initial_state(std::span(committed_).subspan(p, per_point_[e]));
  if (am.model) apply_initial_plastic_strains(am);
  trial_ = committed_;
}

void MaterialStates::apply_initial_plastic_strains(const AnalysisModel& am) {
  for (const model::InitialPlasticStrain& ic : am.model->initial_plastic_strains) {
    const elements::Vec6 pe = Eigen::Map<const elements::Vec6>(ic.components);
    for (std::int32_t e : ic.elements) {
      const auto n = static_cast<std::size_t>(e);
      const std::size_t size = per_point_[n];
      if (size == 0) continue;  // build_analysis_model refused elements without plasticity
      const std::size_t points = (offset_[n + 1] - offset_[n]) / size;
      for (std::size_t p = 0; p < points; ++p)
        if (ic.point == 0 || static_cast<std::size_t>(ic.point) == p + 1)
          am.elements[n].material->set_plastic_strain(std::span(committed_).subspan(offset_[n] + p * size, size), pe);
    }
  }
}

void MaterialStates::reset(const AnalysisModel& am, std::size_t e) {
  if (empty() || per_point_[e] == 0) return;
  for (std::size_t p = offset_[e]; p < offset_[e + 1]; p += per_point_[e])
    am.elements[e].material->initial_state(std::span(committed_).subspan(p, per_point_[e]));
  std::copy(committed_.begin() + static_cast<std::ptrdiff_t>(offset_[e]),
            committed_.begin() + static_cast<std::ptrdiff_t>(offset_[e + 1]),
            trial_.begin() + static_cast<std::ptrdiff_t>(offset_[e]));
}

std::size_t MaterialStates::bytes() const {
  return offset_.size() * sizeof(std::size_t) + per_point_.size() * sizeof(std::uint32_t) +
         (committed_.size() + trial_.size()) * sizeof(double);
}

std::span<const double> MaterialStates::slice(const std::vector<double>& v, std::size_t e) const {
  if (empty()) return {};
  return std::span(v).subspan(offset_[e], offset_[e + 1] - offset_[e]);
}

elements::ElementHistory MaterialStates::assembly_history(std::size_t e) {
  if (empty() || per_point_[e] == 0) return {};
  const std::size_t n = offset_[e + 1] - offset_[e];
  return {std::span<const double>(committed_).subspan(offset_[e], n), std::span(trial_).subspan(offset_[e], n),
          per_point_[e]};
}

elements::ElementHistory MaterialStates::output_history(std::size_t e, std::vector<double>& scratch) const {
  if (empty() || per_point_[e] == 0) return {};
  const std::span<const double> committed = slice(committed_, e);
  scratch.assign(committed.begin(), committed.end());
  return {committed, scratch, per_point_[e]};
}

std::size_t MaterialStates::points_with_too_large_increments(const AnalysisModel& am) const {
  std::size_t count = 0;
  for (std::size_t e = 0; e < per_point_.size(); ++e) {
    const std::size_t size = per_point_[e];
    if (size == 0) continue;
    const ElementSetup& s = am.elements[e];
    for (std::size_t p = offset_[e], point = 0; p < offset_[e + 1]; p += size, ++point) {
      // A COMPOSITE's point answers to its layer's law, which keeps the first part of the slot.
      const elements::Material* law =
          s.section.shell ? s.section.shell->law_at(point % s.section.shell->zeta.size(), s.material) : s.material;
      const std::size_t own = law ? std::min(size, law->state_size()) : 0;
      if (own > 0 && law->increment_too_large(std::span(committed_).subspan(p, own), std::span(trial_).subspan(p, own)))
        ++count;
    }
  }
  return count;
}

void MaterialStates::commit() { std::copy(trial_.begin(), trial_.end(), committed_.begin()); }

void MaterialStates::discard() { std::copy(committed_.begin(), committed_.end(), trial_.begin()); }

}  // namespace inpact::solver
