#include "step_changes.hpp"

namespace inpact::contact {

const model::FrictionChange* friction_change_in(const model::Model& m, const std::string& name, std::size_t step) {
  if (step >= m.steps.size()) return nullptr;
  const model::FrictionChange* out = nullptr;
  for (const auto& c : m.steps[step].friction_changes)
    if (c.interaction == name && (c.reset || c.friction)) out = &c;
  return out;
}

const model::SurfaceBehaviorChange* behavior_change_for(const model::Model& m, const std::string& name,
                                                        std::size_t step) {
  const model::SurfaceBehaviorChange* out = nullptr;
  for (std::size_t s = 0; s <= step && s < m.steps.size(); ++s)
    for (const auto& c : m.steps[s].behavior_changes)
      if (c.interaction == name && c.behavior) out = &c;
  return out;
}

std::optional<model::SurfaceInteraction> interaction_in_step(const model::Model& m, const std::string& name,
                                                             std::size_t step) {
  const auto it = m.interactions.find(name);
  if (it == m.interactions.end()) return std::nullopt;
  model::SurfaceInteraction inter = it->second;
  for (std::size_t s = 0; s <= step && s < m.steps.size(); ++s)
    if (const model::FrictionChange* c = friction_change_in(m, name, s))
      inter.friction = c->reset ? it->second.friction : c->friction;
  if (const model::SurfaceBehaviorChange* c = behavior_change_for(m, name, step)) inter.behavior = c->behavior;
  return inter;
}

bool pair_removed(const model::Model& m, const std::string& slave, const std::string& master, std::size_t step) {
  bool removed = false;
  for (std::size_t s = 0; s <= step && s < m.steps.size(); ++s)
    for (const auto& c : m.steps[s].pair_changes)
      if (c.slave == slave && c.master == master) removed = !c.add;
  return removed;
}

std::vector<std::size_t> rows_removed_in(const model::Model& m, const InteractionTable& table, std::size_t step) {
  std::vector<std::size_t> out;
  if (step == 0) return out;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const ContactInteraction& e = table.rows[row];
    if (e.general || e.first_step >= step) continue;
    if (pair_removed(m, e.pair.slave, e.pair.master, step) && !pair_removed(m, e.pair.slave, e.pair.master, step - 1))
      out.push_back(row);
  }
  return out;
}

}  // namespace inpact::contact
