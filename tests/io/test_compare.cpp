// inpact compare: the value rule, structure by label, tolerance files (io/compare.hpp).
// Real runs compared through the command line are in tests/decks/compare_study.cmake.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/compare.hpp"

namespace inpact::io {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// One step, one frame, one field over the given locations (one component each).
ResultsFile one_field(const std::string& key, const std::vector<std::string>& locations, const std::vector<double>& values) {
  ResultsFile r;
  r.path = key + ".h5";
  r.status = "COMPLETED";
  ResultsStep s;
  s.name = "LOAD";
  s.step_time = {1.0};
  s.total_time = {1.0};
  s.increment = {1};
  ResultsField f;
  f.key = key;
  f.position = "NODAL";
  f.components = {key};
  f.n_frames = 1;
  f.n_loc = locations.size();
  f.n_comp = 1;
  f.data = values;
  f.locations = locations;
  f.node_rows.assign(locations.size(), -1);
  s.fields.push_back(f);
  r.steps.push_back(s);
  return r;
}

CompareResult compare_values(const std::string& key, std::vector<double> a, std::vector<double> b,
                             const Tolerances& t = default_tolerances()) {
  std::vector<std::string> locs;
  for (std::size_t i = 0; i < a.size(); ++i) locs.push_back("node " + std::to_string(i + 1));
  return compare_results(one_field(key, locs, a), one_field(key, locs, b), t);
}

TEST(CompareValues, equal_within_relative_tolerance_passes_and_beyond_it_fails) {
  EXPECT_TRUE(compare_values("U", {1.0, -2.0}, {1.0 + 1e-7, -2.0}).same());
  const CompareResult r = compare_values("U", {1.0, -2.0}, {1.0, -2.0 * (1 + 1e-5)});
  EXPECT_FALSE(r.same());
  ASSERT_EQ(r.fields.size(), 1u);
  EXPECT_EQ(r.fields[0].n_failed, 1);
  EXPECT_EQ(r.fields[0].location, "node 2");
  EXPECT_EQ(r.fields[0].step, "LOAD");
  EXPECT_EQ(r.fields[0].component, "U");
}

TEST(CompareValues, nan_never_equals_a_number_but_two_nans_are_both_absent) {
  EXPECT_FALSE(compare_values("U", {kNaN}, {0.0}).same());
  EXPECT_FALSE(compare_values("U", {0.0}, {kNaN}).same());
  EXPECT_TRUE(compare_values("U", {kNaN}, {kNaN}).same());
}

TEST(CompareValues, values_under_the_floor_pass_and_absolute_floor_is_used_for_unscaled_fields) {
  EXPECT_TRUE(compare_values("U", {1e-13}, {-5e-13}).same());
  EXPECT_FALSE(compare_values("U", {1e-9}, {2e-9}).same());
}

// Interference fit, every node closed: COPEN is round-off (±1e-16) in both runs, and its own
// frame maximum is round-off too; measured against the motion U (1e-3) the runs agree.
TEST(CompareValues, a_closed_contacts_gap_is_measured_in_the_units_of_the_motion) {
  const std::vector<std::string> locs = {"node 1", "node 2"};
  const auto with_motion = [&](std::vector<double> copen) {
    ResultsFile r = one_field("COPEN", locs, copen);
    ResultsField u = one_field("U", locs, {1e-3, -5e-4}).steps[0].fields[0];
    r.steps[0].fields.push_back(u);
    return r;
  };
  EXPECT_TRUE(compare_results(with_motion({-1.1e-16, 2e-17}), with_motion({1.1e-16, 0.0}), default_tolerances()).same());
  EXPECT_FALSE(compare_values("COPEN", {-1.1e-16, 2e-17}, {1.1e-16, 0.0}).same());  // no U: its own scale
  // An open gap that differs by 1e-5 of itself still fails.
  EXPECT_FALSE(compare_results(with_motion({1e-4, 0.0}), with_motion({1e-4 + 1e-9, 0.0}), default_tolerances()).same());
}

TEST(CompareValues, frame_max_scaling_lets_near_zero_stress_differ_by_round_off) {
  // S scaled by the frame's largest value (1e6): 1e-5 differences at near-zero points pass.
  EXPECT_TRUE(compare_values("S", {1e6, 1e-5}, {1e6, 2e-5}).same());
  Tolerances unscaled = default_tolerances();
  unscaled.fields["S"].scale_by_frame_max = false;
  EXPECT_FALSE(compare_values("S", {1e6, 1e-5}, {1e6, 2e-5}, unscaled).same());
}

TEST(CompareValues, cstatus_is_exact_with_an_allowed_count_of_mismatches) {
  EXPECT_FALSE(compare_values("CSTATUS", {2, 0, 2}, {2, 1, 2}).same());
  Tolerances t = parse_tolerances("[CSTATUS]\nallowed_mismatches = 1\n", "toml", "t.toml");
  EXPECT_TRUE(compare_values("CSTATUS", {2, 0, 2}, {2, 1, 2}, t).same());
  EXPECT_FALSE(compare_values("CSTATUS", {2, 0, 0}, {2, 1, 2}, t).same());
}

TEST(CompareStructure, locations_are_matched_by_label_not_by_row) {
  const ResultsFile a = one_field("U", {"node 1", "node 2", "node 3"}, {1, 2, 3});
  const ResultsFile b = one_field("U", {"node 3", "node 1", "node 2"}, {3, 1, 2});
  EXPECT_TRUE(compare_results(a, b, default_tolerances()).same());
}

TEST(CompareStructure, a_missing_location_step_or_field_is_named) {
  const ResultsFile a = one_field("U", {"node 1", "node 2"}, {1, 2});
  const ResultsFile b = one_field("U", {"node 1", "node 7"}, {1, 2});
  const CompareResult r = compare_results(a, b, default_tolerances());
  ASSERT_FALSE(r.same());
  ASSERT_EQ(r.structure.size(), 2u);
  EXPECT_NE(r.structure[0].find("location(s) of A not in B: node 2"), std::string::npos) << r.structure[0];
  EXPECT_NE(r.structure[1].find("node 7"), std::string::npos) << r.structure[1];

  ResultsFile c = a;
  c.steps[0].name = "OTHER";
  EXPECT_NE(format_summary(compare_results(a, c, default_tolerances())).find("steps: A has [LOAD], B has [OTHER]"),
            std::string::npos);
  ResultsFile d = a;
  d.steps[0].fields[0].key = "RF";
  EXPECT_NE(compare_results(a, d, default_tolerances()).structure.at(0).find("field(s) of A not in B: U"), std::string::npos);
}

TEST(CompareReport, json_names_the_worst_location_and_writes_null_for_nan) {
  const CompareResult r = compare_values("CPRESS", {10, 0}, {12, kNaN});
  const std::string json = format_json(r, default_tolerances());
  EXPECT_NE(json.find("\"same\": false"), std::string::npos);
  EXPECT_NE(json.find("\"field\": \"CPRESS\""), std::string::npos);
  EXPECT_NE(json.find("\"b\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"scale\": \"frame-max\""), std::string::npos);
}

TEST(CompareTolerances, toml_and_yaml_subsets_give_the_same_tolerances) {
  const std::string toml = R"(# tolerances
[default]
rtol = 1e-4
[fields.CPRESS]
atol = 1e-3   # of the frame's largest pressure
scale = "frame-max"
[U]
floor = 1e-8
exact = false
)";
  const std::string yaml = R"(default:
  rtol: 1e-4
fields:
  CPRESS:
    atol: 1e-3
    scale: frame-max
  U:
    floor: 1e-8
)";
  for (const auto& t : {parse_tolerances(toml, "toml", "t.toml"), parse_tolerances(yaml, "yaml", "t.yaml")}) {
    EXPECT_DOUBLE_EQ(t.fallback.rtol, 1e-4);
    EXPECT_DOUBLE_EQ(t.of("CPRESS").atol, 1e-3);
    EXPECT_TRUE(t.of("CPRESS").scale_by_frame_max);
    EXPECT_DOUBLE_EQ(t.of("CPRESS").rtol, 1e-6);  // built-in CPRESS default kept
    EXPECT_DOUBLE_EQ(t.of("U").floor, 1e-8);
    EXPECT_DOUBLE_EQ(t.of("U").rtol, 1e-4);  // a new field starts from the file's default
    EXPECT_TRUE(t.of("CSTATUS").exact);
  }
}

TEST(CompareTolerances, errors_cite_file_and_line) {
  try {
    parse_tolerances("[U]\nrtol = 1e-6\nrtoll = 2\n", "toml", "t.toml");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("t.toml:3: unknown setting 'rtoll'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_tolerances("U:\n  scale: maybe\n", "yaml", "t.yaml"), std::invalid_argument);
  EXPECT_THROW(parse_tolerances("[U]\nrtol = -1\n", "toml", "t.toml"), std::invalid_argument);
}

}  // namespace
}  // namespace inpact::io
