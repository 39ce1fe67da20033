#pragma once
/// Abaqus's stability checks of *ELASTIC constants (the deck errors of the *ELASTIC handler).
#include <cstddef>
#include <optional>
#include <string>

#include "model/material.hpp"

namespace inpact::parser {

/// What is unstable about the constants, and which constant the message points at.
struct ElasticInstability {
  std::string what;
  std::size_t constant = 0;  ///< index into Elastic::constants
};

/// Abaqus's stability conditions (Abaqus Analysis User's Guide, "Linear elastic behavior"):
/// engineering constants: E's and G's positive, |ν12| < √(E1/E2), |ν13| < √(E1/E3),
/// |ν23| < √(E2/E3), 1 − ν12ν21 − ν23ν32 − ν31ν13 − 2ν21ν32ν13 > 0; orthotropic: the diagonal
/// D's positive, |D1122| < √(D1111 D2222) (and 1133, 2233 likewise), det D > 0; anisotropic: D
/// positive definite; lamina: E1, E2, G's positive, |ν12| < √(E1/E2). Empty when stable.
std::optional<ElasticInstability> elastic_instability(const model::Elastic& elastic);

}  // namespace inpact::parser
