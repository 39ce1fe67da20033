#pragma once
/// *MATERIAL and its options.
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// *ELASTIC, TYPE=ISOTROPIC: E, ν (temperature dependence not yet supported).
struct Elastic {
  double youngs_modulus = 0.0;
  double poissons_ratio = 0.0;
  SourceLoc loc;
};

/// *EXPANSION, TYPE=ISO: α, measured from the reference temperature ZERO (Abaqus default 0).
struct Expansion {
  double alpha = 0.0;
  double zero = 0.0;
  SourceLoc loc;
};

struct Material {
  std::string name;  ///< as written
  std::optional<Elastic> elastic;
  std::optional<double> density;  ///< kept for later procedures; static steps ignore it
  std::optional<Expansion> expansion;
  SourceLoc loc;
};

}  // namespace inpact::model
