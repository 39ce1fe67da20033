#pragma once
/// The model summary `inpact check` prints (Abaqus's datacheck): what the deck defines, how
/// contact will be enforced, and what each step does — what a user wants to see before a long run.
#include <ostream>
#include <span>
#include <vector>

#include "contact/resolved_interaction.hpp"
#include "model/model.hpp"

namespace inpact::io {

/// `interactions`: per step, the contact rows as the analysis resolved them
/// (solver::AnalysisModel::interactions); each step lists them with contact::describe().
void write_model_summary(std::ostream& out, const model::Model& model,
                         std::span<const std::vector<contact::ResolvedInteraction>> interactions = {});

}  // namespace inpact::io
