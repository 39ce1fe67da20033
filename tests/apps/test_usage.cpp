// The help text of the `inpact` executable names the program, and a subcommand's help its whole
// command: "Usage: inpact run [OPTIONS] deck". The options are defined in apps/main.cpp, so the
// test runs the executable itself (INPACT_EXECUTABLE, set by tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace {

struct Output {
  std::string text;  ///< stdout and stderr together
  int exit_code = -1;
};

Output run_inpact(const std::string& args) {
  Output out;
  const std::string command = "\"" + std::string(INPACT_EXECUTABLE) + "\" " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.text.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) out.exit_code = WEXITSTATUS(status);
  return out;
}

TEST(Usage, HelpNamesTheProgramAndTheSubcommand) {
  const std::pair<const char*, const char*> cases[] = {
      {"--help", "Usage: inpact [OPTIONS] SUBCOMMAND\n"},
      {"run --help", "Usage: inpact run [OPTIONS] deck\n"},
      {"check --help", "Usage: inpact check [OPTIONS] deck\n"},
      {"compare --help", "Usage: inpact compare [OPTIONS] a b\n"},
      {"study run-case --help", "Usage: inpact study run-case [OPTIONS] id\n"},
  };
  for (const auto& [args, usage] : cases) {
    const Output out = run_inpact(args);
    EXPECT_EQ(out.exit_code, 0) << args << ":\n" << out.text;
    EXPECT_NE(out.text.find(usage), std::string::npos) << args << ":\n" << out.text;
  }
}

}  // namespace
