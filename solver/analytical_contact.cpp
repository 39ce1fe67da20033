#include "analytical_contact.hpp"

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "contact/analytical_shape.hpp"

namespace inpact::solver {

namespace {

[[noreturn]] void refuse(const model::Model& m, const model::SourceLoc& loc, const std::string& keyword,
                         const std::string& what) {
  throw AnalysisError(fmt::format("{}: error: {}: {}", m.sources.describe(loc), keyword, what));
}

bool carried(const model::Model& m, std::size_t index) {
  for (const model::RigidBody& b : m.rigid_bodies)
    if (b.analytical_surface == static_cast<std::int32_t>(index)) return true;
  return false;
}

/// Every analytical surface: carried by a body, its shape built for the model's dimension.
void check_shapes(const model::Model& m, int dim) {
  for (std::size_t i = 0; i < m.analytical_surfaces.size(); ++i) {
    const model::AnalyticalSurface& s = m.analytical_surfaces[i];
    if (!carried(m, i))
      refuse(m, s.loc, "*SURFACE",
             fmt::format("analytical surface '{}' moves with nothing: name it on a *RIGID BODY, ANALYTICAL SURFACE=", s.name));
    try {
      (void)contact::AnalyticalShape::build(s, dim);
    } catch (const contact::ProfileError& e) {
      refuse(m, s.segments.at(e.segment).loc, "*SURFACE", fmt::format("analytical surface '{}': {}", s.name, e.what()));
    } catch (const std::invalid_argument& e) {
      refuse(m, s.loc, "*SURFACE", fmt::format("analytical surface '{}': {}", s.name, e.what()));
    }
  }
}

}  // namespace

void check_analytical_surfaces(const AnalysisModel& am) {
  const model::Model& m = *am.model;
  if (m.analytical_surfaces.empty()) return;
  check_shapes(m, am.dim);
  using Kind = model::Surface::Kind;
  for (const contact::ContactInteraction& e : am.contact->rows) {
    const std::string kw = e.general ? "*CONTACT" : "*CONTACT PAIR";
    if (e.master->kind != Kind::Analytical) continue;
    if (e.general) refuse(m, e.pair.loc, kw, "general contact with an analytical surface is not supported yet; use *CONTACT PAIR");
    if (e.pair.adjust_distance || !e.pair.adjust_nset.empty())
      refuse(m, e.pair.adjust_loc, kw, "ADJUST against an analytical surface is not supported yet");
  }
}

}  // namespace inpact::solver
