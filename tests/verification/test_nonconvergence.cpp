// Case 8: a deck that cannot converge. Step 1 holds and loads a bar; step 2 removes every
// support (*BOUNDARY, OP=NEW without data lines) while the load stays: the stiffness is
// singular (rigid-body modes). The analysis must stop with completed == false and a message
// naming the step, the increment and why; through the executable: exit code 4, and step 1's
// converged frames readable in the results file, whose status is ABORTED.
#include "verification_fixture.hpp"

#include <sys/wait.h>

namespace inpact::verification {
namespace {

TEST(NonConvergence, RigidBodyModeStopsWithAMessageNamingStepIncrementAndCause) {
  const auto r = run_deck(deck_path("rigid_mode_abort.inp"));
  EXPECT_FALSE(r->outcome.completed);
  const std::string& msg = r->outcome.message;
  std::printf("[verification] outcome message: %s\n", msg.c_str());
  EXPECT_NE(msg.find("step 2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("LETGO"), std::string::npos) << msg;
  EXPECT_NE(msg.find("increment 1"), std::string::npos) << msg;
  // Why: the rigid-body mode is named (a semidefinite stiffness may factorise on round-off
  // pivots; the absurd correction gives it away), and the step stops at once: no smaller
  // increment removes a rigid-body mode, so there is no cutback.
  EXPECT_NE(msg.find("singular"), std::string::npos) << msg;
  EXPECT_NE(msg.find("rigid body"), std::string::npos) << msg;
  EXPECT_NE(msg.find("attempt 1,"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("gave up after"), std::string::npos) << msg;
  // Step 1 converged and handed out its frame.
  ASSERT_EQ(r->capture.of_step(1).size(), 1u);
  EXPECT_TRUE(r->capture.of_step(2).empty());
  // Case 5 on the converged step: 10 applied at x = 2 (4 × 2.5).
  expect_balance(*r, *r->capture.of_step(1).front(), {10.0, 0, 0}, 1e-12, "rigid mode step 1");
}

/// The executable beside this test in the build tree (tests/ and apps/ share the build root).
std::filesystem::path inpact_executable() {
  for (const auto& p : {std::filesystem::current_path() / ".." / "apps" / "inpact",
                        std::filesystem::current_path() / "apps" / "inpact"})
    if (std::filesystem::exists(p)) return p;
  return {};
}

TEST(NonConvergence, ExecutableExitsWithFourAndKeepsEarlierFramesInAnAbortedResultsFile) {
  const auto exe = inpact_executable();
  if (exe.empty()) GTEST_SKIP() << "apps/inpact is not built beside the tests";
  const auto out = generated_dir() / "rigid_mode_abort";
  std::filesystem::remove_all(out);
  const std::string cmd = exe.string() + " run " + deck_path("rigid_mode_abort.inp") + " -j abort -o " + out.string() +
                          " --quiet > " + (generated_dir() / "rigid_mode_abort.log").string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status)) << cmd;
  EXPECT_EQ(WEXITSTATUS(status), 4) << cmd;
  const auto h5 = out / "abort.h5";
  ASSERT_TRUE(std::filesystem::exists(h5)) << "no results file " << h5;
  // Read it back with h5py (the reader users have); skipped where h5py is missing (exit 77).
  const std::string py =
      "import sys\n"
      "try:\n import h5py\nexcept ImportError:\n sys.exit(77)\n"
      "f = h5py.File(sys.argv[1], 'r')\n"
      "s = f.attrs['status']; s = s.decode() if isinstance(s, bytes) else s\n"
      "assert s == 'ABORTED', s\n"
      "fr = f['steps/HOLD/frames/step_time'][:]\n"
      "assert len(fr) == 1 and abs(fr[0] - 1.0) < 1e-12, fr\n"
      "u = f['steps/HOLD/fieldOutputs/U/data'][:]\n"
      "assert u.shape[0] == 1 and abs(u[0, :, 0].max() - 2 * 10.0 / 1000.0) < 1e-9, u[0, :, 0].max()\n"
      "print('h5 ok', s, len(fr), u[0, :, 0].max())\n";
  const auto script = generated_dir() / "check_abort_h5.py";
  {
    std::FILE* fp = std::fopen(script.string().c_str(), "w");
    ASSERT_NE(fp, nullptr);
    std::fputs(py.c_str(), fp);
    std::fclose(fp);
  }
  const int py_status = std::system(("/usr/bin/python3 " + script.string() + " " + h5.string()).c_str());
  ASSERT_TRUE(WIFEXITED(py_status));
  if (WEXITSTATUS(py_status) == 77) GTEST_SKIP() << "h5py is not installed";
  EXPECT_EQ(WEXITSTATUS(py_status), 0) << "results file check failed for " << h5;
}

}  // namespace
}  // namespace inpact::verification
