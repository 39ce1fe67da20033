#pragma once
// The deck error build_analysis_model raises for a deck's text: what check and run both report.
#include <gtest/gtest.h>

#include <string>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {

/// The AnalysisError message building the analysis model of `deck` raises ("" when none).
inline std::string analysis_error(const std::string& deck) {
  const DeckDir dir;
  const auto r = dir.read(deck);
  EXPECT_TRUE(r.ok()) << r.report();
  try {
    (void)solver::build_analysis_model(r.model);
  } catch (const solver::AnalysisError& e) {
    return e.what();
  }
  return "";
}

}  // namespace inpact::test
