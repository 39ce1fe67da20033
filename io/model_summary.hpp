#pragma once
/// The model summary `inpact check` prints (Abaqus's datacheck): what the deck defines, how
/// contact will be enforced, and what each step does — what a user wants to see before a long run.
#include <ostream>

#include "model/model.hpp"

namespace inpact::io {

void write_model_summary(std::ostream& out, const model::Model& model);

}  // namespace inpact::io
