// inpact study: case expansion, shards, collect specs, the manifest and per-case outcomes
// (apps/study_cases.hpp, apps/study_runner.hpp). Studies run end to end, with worker processes,
// a resume, a failing case and GNU parallel, in tests/decks/compare_study.cmake.
#include <gtest/gtest.h>

#include <stdexcept>

#include "apps/study_cases.hpp"
#include "apps/study_runner.hpp"

namespace inpact::app::study {
namespace {

TEST(StudyCases, grids_expand_to_their_product_with_the_first_grid_varying_slowest) {
  const auto cases = expand_cases({parse_grid("LOAD=1,2"), parse_grid("MU = 0.1, 0.2, 0.3")}, {});
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[0].id, "c0001");
  EXPECT_EQ(cases[5].id, "c0006");
  EXPECT_EQ(cases[1].parameters, (Parameters{{"LOAD", "1"}, {"MU", "0.2"}}));
  EXPECT_EQ(cases[3].parameters, (Parameters{{"LOAD", "2"}, {"MU", "0.1"}}));
}

TEST(StudyCases, samples_rows_are_cases_and_combine_with_grids) {
  const auto rows = parse_samples("# header next\nE,NU\n100,0.3\n200,\"0.25\"\n", "s.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1], (Parameters{{"E", "200"}, {"NU", "0.25"}}));
  EXPECT_EQ(expand_cases({parse_grid("LOAD=1,2,3")}, rows).size(), 6u);
  EXPECT_THROW(parse_samples("E,NU\n1\n", "s.csv"), std::invalid_argument);
  EXPECT_THROW(expand_cases({parse_grid("E=1")}, rows), std::invalid_argument);  // E in both
}

TEST(StudyCases, malformed_grid_shard_and_collect_are_usage_errors) {
  EXPECT_THROW(parse_grid("LOAD"), std::invalid_argument);
  EXPECT_THROW(parse_grid("LOAD=1,,2"), std::invalid_argument);
  EXPECT_THROW(expand_cases({parse_grid("A=1"), parse_grid("A=2")}, {}), std::invalid_argument);
  EXPECT_THROW(parse_shard("3/2"), std::invalid_argument);
  EXPECT_THROW(parse_shard("0/2"), std::invalid_argument);
  EXPECT_THROW(parse_shard("1-2"), std::invalid_argument);
  EXPECT_THROW(parse_collect("CPRESS"), std::invalid_argument);
  EXPECT_THROW(parse_collect("avg:CPRESS"), std::invalid_argument);
}

TEST(StudyCases, shards_split_the_cases_without_overlap) {
  const Shard a = parse_shard("1/2"), b = parse_shard("2/2");
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NE(a.contains(k), b.contains(k)) << k;
  EXPECT_TRUE(a.contains(0));
  EXPECT_TRUE(b.contains(1));
}

TEST(StudyCases, collect_spec_reads_operation_negation_and_node_set) {
  const CollectSpec c = parse_collect("max:-COPEN");
  EXPECT_EQ(c.op, "max");
  EXPECT_EQ(c.var, "COPEN");
  EXPECT_TRUE(c.negate);
  const CollectSpec rf = parse_collect("sum:RF2@BOTTOM");
  EXPECT_EQ(rf.var, "RF2");
  EXPECT_EQ(rf.nset, "BOTTOM");
  EXPECT_FALSE(rf.negate);
}

TEST(StudyManifest, round_trips_through_its_text) {
  Manifest m;
  m.deck = "/decks/with,comma.inp";
  m.cases = expand_cases({parse_grid("LOAD=1,2")}, {});
  m.parameter_names = {"LOAD"};
  m.collect = {"max:CPRESS", "sum:RF2@TOP"};
  const std::string text = format_manifest(m);
  EXPECT_NE(text.find("c0002,\"/decks/with,comma.inp\",cases/c0002/c0002.h5,2"), std::string::npos) << text;
  const Manifest back = parse_manifest(text, "manifest.csv");
  EXPECT_EQ(back.deck, m.deck);
  EXPECT_EQ(back.collect, m.collect);
  ASSERT_EQ(back.cases.size(), 2u);
  EXPECT_EQ(back.cases[1].parameters, m.cases[1].parameters);
  EXPECT_EQ(format_manifest(back), text);
  EXPECT_THROW(parse_manifest("id,deck\n", "x.csv"), std::invalid_argument);
}

TEST(StudyOutcome, round_trips_and_the_table_marks_failed_and_pending_cases) {
  CaseOutcome o;
  o.id = "c0001";
  o.status = "failed";
  o.exit_code = 3;
  o.wall_time = 0.25;
  o.message = "deck.inp:83:11: error: *DSLOAD: magnitude: expected a number,\nfound 'bad'";
  const CaseOutcome back = parse_outcome(format_outcome(o));
  EXPECT_EQ(back.status, "failed");
  EXPECT_EQ(back.exit_code, 3);
  EXPECT_DOUBLE_EQ(back.wall_time, 0.25);
  EXPECT_EQ(back.message.find('\n'), std::string::npos);

  Manifest m;
  m.cases = expand_cases({parse_grid("LOAD=1,bad")}, {});
  m.parameter_names = {"LOAD"};
  m.collect = {"max:CPRESS"};
  CaseOutcome done;
  done.id = "c0001";
  done.status = "completed";
  done.exit_code = 0;
  done.wall_time = 1.0;
  done.values = {{"max:CPRESS", "10"}, {"iterations", "4"}};
  CaseOutcome pending;
  pending.id = "c0002";
  const std::string table = format_table(m, {done, pending});
  EXPECT_NE(table.find("id,LOAD,status,exit_code,wall_time_s,increments,iterations,cutbacks,max:CPRESS,message"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("c0001,1,completed,0,1.000,,4,,10,"), std::string::npos) << table;
  EXPECT_NE(table.find("c0002,bad,pending,"), std::string::npos) << table;
}

}  // namespace
}  // namespace inpact::app::study
