// inpact study: case expansion, shards, collect specs, the manifest and per-case outcomes
// (apps/study_cases.hpp, apps/study_runner.hpp) and the worker processes (apps/study_workers.hpp).
// Studies run end to end, with a resume, a failing case and GNU parallel, in
// tests/decks/compare_study.cmake.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "apps/study_cases.hpp"
#include "apps/study_runner.hpp"
#include "apps/study_workers.hpp"

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
  o.started = 1.5;
  o.message = "deck.inp:83:11: error: *DSLOAD: magnitude: expected a number,\nfound 'bad'";
  const CaseOutcome back = parse_outcome(format_outcome(o));
  EXPECT_EQ(back.status, "failed");
  EXPECT_EQ(back.exit_code, 3);
  EXPECT_DOUBLE_EQ(back.wall_time, 0.25);
  EXPECT_DOUBLE_EQ(back.started, 1.5);
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

// One worker runs the cases one after another; a case that kills its worker and a case that
// fails each end theirs, the next case gets a new one, and how each case ended is reported.
TEST(StudyWorkers, a_worker_runs_cases_until_one_fails_or_kills_it) {
  const auto dir = std::filesystem::temp_directory_path() / ("inpact_test_workers_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  WorkerPool pool(1, [&](std::size_t k) {
    std::ofstream(dir / std::to_string(k)) << getpid();
    if (k == 2) kill(getpid(), SIGKILL);
    return k == 4 ? 3 : 0;
  });
  std::map<std::size_t, int> status;
  for (std::size_t k = 0; k < 6; ++k) {
    ASSERT_TRUE(pool.has_idle());
    pool.start(k);
    EXPECT_FALSE(pool.has_idle());
    const WorkerPool::Ended e = pool.wait();
    EXPECT_EQ(e.k, k);
    EXPECT_GE(e.wall, 0.0);
    status[k] = e.wait_status;
  }
  EXPECT_EQ(pool.running(), 0u);
  auto pid = [&](std::size_t k) {
    std::string text;
    std::ifstream(dir / std::to_string(k)) >> text;
    return text;
  };
  for (std::size_t k : {0u, 1u, 3u, 5u}) EXPECT_TRUE(WIFEXITED(status[k]) && WEXITSTATUS(status[k]) == 0) << k;
  EXPECT_TRUE(WIFSIGNALED(status[2]) && WTERMSIG(status[2]) == SIGKILL);
  EXPECT_TRUE(WIFEXITED(status[4]) && WEXITSTATUS(status[4]) == 3);
  EXPECT_NE(getpid(), std::stoi(pid(0)));  // cases run in a worker, not in the study
  EXPECT_EQ(pid(0), pid(1));               // the same worker for consecutive cases
  EXPECT_EQ(pid(1), pid(2));
  EXPECT_NE(pid(2), pid(3));  // a new worker after the one that was killed
  EXPECT_EQ(pid(3), pid(4));
  EXPECT_NE(pid(4), pid(5));  // and after the one whose case failed
  std::filesystem::remove_all(dir);
}

// A worker killed while it waits for its next case: the case goes to a new worker.
TEST(StudyWorkers, a_worker_killed_between_cases_is_replaced) {
  const auto dir = std::filesystem::temp_directory_path() / ("inpact_test_idle_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  WorkerPool pool(1, [&](std::size_t k) {
    std::ofstream(dir / std::to_string(k)) << getpid();
    return 0;
  });
  pool.start(0);
  ASSERT_TRUE(WIFEXITED(pool.wait().wait_status));
  pid_t first = 0;
  std::ifstream(dir / "0") >> first;
  ASSERT_GT(first, 0);
  ASSERT_EQ(kill(first, SIGKILL), 0);
  // Until it is a zombie: then handing it a case cannot succeed.
  for (int i = 0; i < 1000; ++i) {
    std::ifstream stat("/proc/" + std::to_string(first) + "/stat");
    std::string text;
    std::getline(stat, text);
    if (text.empty() || text.find(") Z") != std::string::npos) break;
    usleep(1000);
  }
  pool.start(1);
  const WorkerPool::Ended e = pool.wait();
  EXPECT_EQ(e.k, 1u);
  EXPECT_TRUE(WIFEXITED(e.wait_status) && WEXITSTATUS(e.wait_status) == 0);
  pid_t second = 0;
  std::ifstream(dir / "1") >> second;
  EXPECT_GT(second, 0);
  EXPECT_NE(second, first);
  std::filesystem::remove_all(dir);
}

// Two workers run two cases at once.
TEST(StudyWorkers, two_workers_run_two_cases_at_once) {
  int go[2];
  ASSERT_EQ(pipe(go), 0);
  WorkerPool pool(2, [&](std::size_t k) {
    // Case 0 waits until case 1 has run: only possible if both run at the same time.
    if (k == 0) {
      char c;
      return read(go[0], &c, 1) == 1 ? 0 : 1;
    }
    return write(go[1], "x", 1) == 1 ? 0 : 1;
  });
  pool.start(0);
  pool.start(1);
  EXPECT_FALSE(pool.has_idle());
  int ended = 0;
  for (int i = 0; i < 2; ++i) {
    const WorkerPool::Ended e = pool.wait();
    EXPECT_TRUE(WIFEXITED(e.wait_status) && WEXITSTATUS(e.wait_status) == 0) << e.k;
    ++ended;
  }
  EXPECT_EQ(ended, 2);
  close(go[0]);
  close(go[1]);
}

}  // namespace
}  // namespace inpact::app::study
