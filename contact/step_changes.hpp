#pragma once
/// What the step-wise contact changes leave in force in a step: the one place that applies
/// *CHANGE FRICTION, *CHANGE SURFACE BEHAVIOR and *MODEL CHANGE, TYPE=CONTACT PAIR (model::Step),
/// used by resolve_interactions (contact/resolved_interaction.hpp), hence by `inpact check` and
/// the run alike.
///   - A surface interaction in step s: the model data's, with the friction of the latest
///     *CHANGE FRICTION of steps 0..s (RESET: the model data's again) and the surface behaviour of
///     the latest *CHANGE SURFACE BEHAVIOR of steps 0..s.
///   - A *CONTACT PAIR in step s: removed when the latest *MODEL CHANGE of steps 0..s naming it
///     (slave, master) is REMOVE.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "contact/interaction_table.hpp"
#include "model/model.hpp"

namespace inpact::contact {

/// The *SURFACE INTERACTION `name` as step `step` (0-based) has it; nullopt when the model data
/// does not define it.
std::optional<model::SurfaceInteraction> interaction_in_step(const model::Model& m, const std::string& name,
                                                             std::size_t step);

/// The *CHANGE FRICTION step `step` makes to interaction `name` (its last one), or null.
const model::FrictionChange* friction_change_in(const model::Model& m, const std::string& name, std::size_t step);

/// The *CHANGE SURFACE BEHAVIOR (with its *SURFACE BEHAVIOR) in force for `name` in step `step`
/// (the latest of steps 0..step), or null when the model data's behaviour holds.
const model::SurfaceBehaviorChange* behavior_change_for(const model::Model& m, const std::string& name,
                                                        std::size_t step);

/// Does the latest *MODEL CHANGE of steps 0..step remove the *CONTACT PAIR slave/master?
bool pair_removed(const model::Model& m, const std::string& slave, const std::string& master, std::size_t step);

/// The rows of `table` (its *CONTACT PAIRs) in force in step `step` − 1 that *MODEL CHANGE removes
/// in step `step`: their contact forces are released over `step`. Empty for step 0.
std::vector<std::size_t> rows_removed_in(const model::Model& m, const InteractionTable& table, std::size_t step);

}  // namespace inpact::contact
