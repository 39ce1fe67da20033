// `inpact job=NAME input=FILE [cpus=N] [datacheck]` as Abaqus users type it.
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "apps/abaqus_args.hpp"

using inpact::app::translate_abaqus_args;
using Args = std::vector<std::string>;

TEST(AbaqusArgs, JobInputAndCpusBecomeARun) {
  EXPECT_EQ(*translate_abaqus_args({"job=beam", "input=deck.inp", "cpus=2", "interactive"}),
            (Args{"run", "deck.inp", "-j", "beam", "--threads", "2"}));
}

TEST(AbaqusArgs, InputDefaultsToTheJobAndTheExtensionMayBeLeftOff) {
  const auto dir = std::filesystem::temp_directory_path() / "inpact-abaqus-args";
  std::filesystem::create_directories(dir);
  const std::string base = (dir / "plate").string();
  std::ofstream(base + ".inp") << "*HEADING\n";
  EXPECT_EQ(*translate_abaqus_args({"job=" + base}), (Args{"run", base + ".inp", "-j", base}));
  EXPECT_EQ(*translate_abaqus_args({"input=" + base, "datacheck"}), (Args{"check", base + ".inp"}));
  std::filesystem::remove_all(dir);
}

TEST(AbaqusArgs, SubcommandFormIsLeftAlone) {
  EXPECT_FALSE(translate_abaqus_args({"run", "deck.inp"}));
  EXPECT_FALSE(translate_abaqus_args({}));
}

TEST(AbaqusArgs, AnUnknownWordIsAUsageError) {
  EXPECT_THROW(translate_abaqus_args({"job=a", "oldjob=b"}), std::invalid_argument);
  EXPECT_THROW(translate_abaqus_args({"job="}), std::invalid_argument);
}
