// The parameter sets of potentials/ and the command that reads them, mesophyll_parameters.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cstdlib>
#include <fstream>

using ::testing::HasSubstr;

using namespace test;

namespace {

std::string shipped_sets()
{
  const char *dir = getenv("MESOPHYLL_EXAMPLES");
  return std::string(dir ? dir : "examples") + "/../potentials/arabidopsis.mesophyll";
}

std::string sets_file(const std::string &name, const std::string &units, const std::string &body)
{
  const std::string path = scratch(name);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    std::ofstream out(path);
    out << "# DATE: 2026-11-22 UNITS: " << units << " CONTRIBUTOR: test\n" << body;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return path;
}

}    // namespace

TEST(Parameters, DefaultSetIsTableOne)
{
  LammpsSession s;
  s.run("units lj\nmesophyll_parameters " + shipped_sets() + " default");
  const std::pair<const char *, double> table1[] = {
      {"eps_a", 1.0},          {"eps_l", 1.0}, {"eps_b", 0.4}, {"eps_c", 1.0}, {"delta_a", 0.5},
      {"lambda", 5},           {"c_L", 0.5},   {"c_B", 4},     {"beta", 100},  {"P0", 1.0e-3},
      {"theta0_min", -PI / 10}};
  for (const auto &p : table1)
    EXPECT_DOUBLE_EQ(std::stod(s.string_variable(p.first)), p.second) << p.first;
  EXPECT_EQ(s.string_variable("rules"), "code");
  EXPECT_EQ(s.string_variable("z"), "bonds");
}

TEST(Parameters, EachSensitivitySetChangesOneThingOfTheDefault)
{
  const std::pair<const char *, std::vector<std::pair<std::string, std::string>>> sets[] = {
      {"beta30", {{"beta", "30"}}},
      {"beta300", {{"beta", "300"}}},
      {"soft_bending", {{"eps_b", "0.03"}}},
      {"slow_growth", {{"delta_a", "0.01"}}},
      {"slowest_growth", {{"delta_a", "0.002"}, {"lambda", "2"}}},
      {"low_pressure", {{"P0", "1.0e-7"}}},
      {"high_pressure", {{"P0", "5.0e-2"}}},
      {"paper", {{"z", "cells"}, {"rules", "paper"}}}};
  LammpsSession reference;
  reference.run("units lj\nmesophyll_parameters " + shipped_sets() + " default");
  const char *names[] = {"eps_a", "eps_l", "eps_b",      "eps_c", "delta_a", "lambda", "c_L",
                         "c_B",   "beta",  "theta0_min", "P0",    "z",       "rules"};
  for (const auto &set : sets) {
    LammpsSession s;
    s.run("units lj\nmesophyll_parameters " + shipped_sets() + " " + set.first);
    for (const char *name : names) {
      std::string expected = reference.string_variable(name);
      for (const auto &change : set.second)
        if (change.first == name) expected = change.second;
      EXPECT_EQ(s.string_variable(name), expected) << set.first << ": " << name;
    }
  }
}

TEST(Parameters, AnEarlierVariableWins)
{
  LammpsSession s;
  s.run("units lj\nvariable beta index 30\nmesophyll_parameters " + shipped_sets() + " default");
  EXPECT_EQ(s.string_variable("beta"), "30");
  EXPECT_EQ(s.string_variable("eps_b"), "0.4");
}

TEST(Parameters, SetsAddUpOverLines)
{
  const std::string file = sets_file("two_lines.mesophyll", "lj",
                                     "mine eps_b 0.1\nother eps_b 9\nmine beta 20 # comment\n");
  LammpsSession s;
  s.run("units lj\nmesophyll_parameters " + file + " mine");
  EXPECT_EQ(s.string_variable("eps_b"), "0.1");
  EXPECT_EQ(s.string_variable("beta"), "20");
}

class BadParameters : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank (file errors are per rank)";
  }
  static std::string error_of(const std::string &units, const std::string &args)
  {
    LammpsSession s;
    return s.try_run("units " + units + "\nmesophyll_parameters " + args);
  }
};

TEST_F(BadParameters, SaysWhatIsWrong)
{
  EXPECT_THAT(error_of("lj", shipped_sets()), HasSubstr("needs a file and a set name"));
  EXPECT_THAT(error_of("lj", shipped_sets() + " nosuchset"), HasSubstr("no set 'nosuchset'"));
  const std::string unknown = sets_file("unknown.mesophyll", "lj", "s eps_b 0.1 gamma 3\n");
  EXPECT_THAT(error_of("lj", unknown + " s"), HasSubstr("unknown parameter 'gamma'"));
  const std::string text = sets_file("text.mesophyll", "lj", "s eps_b soft\n");
  EXPECT_THAT(error_of("lj", text + " s"), HasSubstr("eps_b = 'soft'"));
  const std::string twice = sets_file("twice.mesophyll", "lj", "s beta 1\ns beta 2\n");
  EXPECT_THAT(error_of("lj", twice + " s"), HasSubstr("beta given twice"));
  const std::string dangling = sets_file("dangling.mesophyll", "lj", "s beta\n");
  EXPECT_THAT(error_of("lj", dangling + " s"), HasSubstr("has no value"));
  const std::string msg = error_of("real", shipped_sets() + " default");
  EXPECT_THAT(msg, HasSubstr("units"));
}
