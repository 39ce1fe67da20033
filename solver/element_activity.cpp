#include "element_activity.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "analysis_model.hpp"

namespace inpact::solver {

StepElements step_elements(const model::Model& model, std::size_t step) {
  StepElements out;
  const std::size_t n = model.mesh.elements.size();
  std::vector<std::uint8_t> before(n, 1), now(n, 1);
  std::vector<std::uint8_t> with_strain(n, 0);
  bool any = false;
  for (std::size_t s = 0; s <= step && s < model.steps.size(); ++s) {
    before = now;
    std::fill(with_strain.begin(), with_strain.end(), 0);
    for (const model::ElementChange& c : model.steps[s].element_changes) {
      any = true;
      for (std::int32_t e : c.elements) {
        now[static_cast<std::size_t>(e)] = c.add ? 1 : 0;
        with_strain[static_cast<std::size_t>(e)] = c.with_strain ? 1 : 0;
      }
    }
  }
  if (!any) return out;
  for (std::size_t e = 0; e < n; ++e) {
    const auto row = static_cast<std::int32_t>(e);
    if (before[e] && !now[e]) out.removed.push_back(row);
    if (!before[e] && now[e]) {
      out.added.push_back(row);
      if (!with_strain[e]) out.strain_free.push_back(row);
    }
  }
  out.active = std::move(now);
  return out;
}

namespace {

/// The element rows under a face of any contact surface (pairs and general contact).
std::vector<std::uint8_t> under_contact(const AnalysisModel& am) {
  std::vector<std::uint8_t> under(am.model->mesh.elements.size(), 0);
  if (!am.contact) return under;
  for (const contact::ContactInteraction& row : am.contact->rows)
    for (const model::Surface* s : {row.slave, row.master})
      if (s)
        for (const model::Face& f : s->faces) under[static_cast<std::size_t>(f.element)] = 1;
  return under;
}

}  // namespace

void check_element_changes(const AnalysisModel& am) {
  const model::Model& m = *am.model;
  std::vector<std::uint8_t> contact;
  std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;
  for (const model::Step& step : m.steps)
    for (const model::ElementChange& c : step.element_changes)
      for (std::int32_t row : c.elements) {
        const auto e = static_cast<std::size_t>(row);
        const model::ElementTypeInfo& t = *am.elements[e].type;
        const auto fail = [&](std::string_view why) {
          throw AnalysisError(fmt::format("{}: error: *MODEL CHANGE: element {} ({}) {}", m.sources.describe(c.loc),
                                          m.mesh.elements.labels[e], t.name, why));
        };
        if (model::is_rigid(t)) fail("is a rigid element: removing one is not supported");
        if (am.element_rows(e, rows) != m.mesh.elements.nodes_of(e).size())
          fail("has rotations (a beam or a shell): removing or reactivating it is not supported yet");
        if (contact.empty()) contact = under_contact(am);
        if (contact[e]) fail("lies under a contact surface: removing or reactivating it is not supported yet");
      }
}

void ElementReferences::begin_step(const AnalysisModel& am, const StepElements& elements, std::span<const double> u) {
  for (std::int32_t e : elements.removed) reference_.erase(static_cast<std::size_t>(e));
  for (std::int32_t e : elements.added) reference_.erase(static_cast<std::size_t>(e));
  const std::size_t dim = static_cast<std::size_t>(am.dim);
  std::array<std::int32_t, AnalysisModel::kMaxElementRows> rows;
  for (std::int32_t e : elements.strain_free) {
    const std::size_t n_rows = am.element_rows(static_cast<std::size_t>(e), rows);
    std::vector<double>& ref = reference_[static_cast<std::size_t>(e)];
    ref.resize(n_rows * dim);
    for (std::size_t a = 0; a < n_rows; ++a)
      for (std::size_t c = 0; c < dim; ++c) ref[a * dim + c] = u[static_cast<std::size_t>(rows[a]) * dim + c];
  }
}

std::span<const double> ElementReferences::of(std::size_t e) const {
  const auto it = reference_.find(e);
  return it == reference_.end() ? std::span<const double>() : std::span<const double>(it->second);
}

}  // namespace inpact::solver
