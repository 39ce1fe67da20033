#pragma once
/// What the stabilisation tests read from a run: a frame's history values (ALLSE, ALLSD), its
/// CPRESS, and whether the run warned that its stabilised answer may be wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "verification/verification_fixture.hpp"

namespace inpact::stabilization_checks {

inline double history(const solver::Frame& f, const std::string& key) {
  for (const auto& h : f.history)
    if (h.key == key) return h.value;
  ADD_FAILURE() << "no history value " << key;
  return NAN;
}

inline const std::vector<double>& cpress(const solver::Frame& f) {
  const auto* field = verification::field(f, "CPRESS");
  EXPECT_NE(field, nullptr);
  static const std::vector<double> none;
  return field ? field->values : none;
}

inline bool warned(const verification::Run& r) {
  return std::any_of(r.capture.messages.begin(), r.capture.messages.end(), [](const std::string& m) {
    return m.find("the stabilised answer may be wrong") != std::string::npos;
  });
}

}  // namespace inpact::stabilization_checks
