#pragma once
/// A model the analysis cannot start on (found after parsing: an element turned inside out,
/// 2D and 3D elements mixed, ...). The message cites the deck line; the app exits with 3.
#include <stdexcept>

namespace inpact::solver {

struct AnalysisError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace inpact::solver
