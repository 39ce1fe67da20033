#pragma once
/// `inpact job=NAME input=FILE [cpus=N] [datacheck]`, as Abaqus users type it, rewritten into
/// the subcommand form `inpact run FILE -j NAME --threads N` (or `check FILE`).
#include <optional>
#include <string>
#include <vector>

namespace inpact::app {

/// The rewritten argument list (without argv[0]), or nullopt when `args` is not in the Abaqus
/// form. Throws std::invalid_argument for an Abaqus-form line that cannot be understood.
std::optional<std::vector<std::string>> translate_abaqus_args(const std::vector<std::string>& args);

}  // namespace inpact::app
