// fix dpoly/check: every minimum is checked and a failure is reported, never carried on silently.
#include "test_helpers.h"

#include "fix_dpoly_stage.h"
#include "lammps.h"
#include "modify.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <fstream>
#include <iterator>
#include <memory>

using ::testing::HasSubstr;

using namespace test;

namespace {

// the bonded lattice of the tests under fix box/relax at P0 = 1e-3, checked after each minimum
std::unique_ptr<LammpsSession> relaxed_tissue(const std::string &check_options,
                                              const std::string &minimize)
{
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(data_file("overlapping.data")) + "fix check all dpoly/check " +
         check_options +
         "\nadhere_cells all 2\n"
         "fix relax all box/relax iso 1.0e-3 vmax 1.0e-3\nmin_style cg\n" +
         minimize);
  return s;
}

}    // namespace

TEST(Check, ConvergedMinimumAtTargetPressurePasses)
{
  auto s = relaxed_tissue("pressure 1.0e-3", "minimize 0.0 1.0e-10 20000 200000");
  EXPECT_EQ(s->thermo("f_check[1]"), 1.0);
  EXPECT_LT(s->thermo("f_check[3]"), 1.0e-6);
  EXPECT_EQ(s->thermo("f_check[4]"), 0.0);
  EXPECT_EQ(s->thermo("f_check[5]"), 0.0);
  EXPECT_LT(s->thermo("f_check[2]"), 1.0e-8);
}

TEST(Check, WrongPressureIsReported)
{
  auto s = relaxed_tissue("pressure 2.0e-3", "minimize 0.0 1.0e-10 20000 200000");
  EXPECT_NEAR(s->thermo("f_check[3]"), 0.5, 1.0e-6) << "P = 1e-3 against a stated P0 of 2e-3";
}

// A tension target: the error is relative to |P0|, so a minimum at +1e-3 is 2 away from -1e-3 (a
// signed denominator would give -2 and pass the check).
TEST(Check, TensionTargetIsComparedByItsSize)
{
  auto s = relaxed_tissue("pressure -1.0e-3", "minimize 0.0 1.0e-10 20000 200000");
  EXPECT_NEAR(s->thermo("f_check[3]"), 2.0, 1.0e-6);
}

TEST(Check, UnfinishedMinimizationWarnsOrStops)
{
  if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  const std::string log = scratch("unfinished.log");
  auto warned = relaxed_tissue("pressure 1.0e-3", "log " + log + "\nminimize 0.0 1.0e-10 5 50");
  EXPECT_EQ(warned->thermo("f_check[1]"), 0.0);
  EXPECT_EQ(warned->thermo("f_check[6]"), 5.0) << "iterations";
  EXPECT_GE(warned->thermo("f_check[7]"), 5.0) << "force evaluations";
  warned->run("log none");
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // the log line names the failure even after LAMMPS has stopped printing warnings
  EXPECT_THAT(text, HasSubstr("fix dpoly/check: minimum 1 at step 5: max iterations, force norm"));
  EXPECT_THAT(text,
              HasSubstr("; FAILED; the minimizer stopped without converging (max iterations)"));

  LammpsSession s;
  const std::string msg = s.try_run(
      contact_commands(data_file("overlapping.data")) +
      "fix check all dpoly/check pressure 1.0e-3 action error\nadhere_cells all 2\n"
      "fix relax all box/relax iso 1.0e-3 vmax 1.0e-3\nmin_style cg\nminimize 0.0 1.0e-10 5 50");
  EXPECT_THAT(msg,
              HasSubstr("minimum 1 at step 5; the minimizer stopped without converging (max "
                        "iterations)"))
      << msg;
}

// a figure-eight ring with unequal lobes has positive area, so only the crossing test sees it
TEST(Check, RingThatCrossesItselfIsReported)
{
  Tissue t;
  t.cells = {{{{10.0, 10.0}, {13.0, 13.0}, {13.0, 11.0}, {10.0, 14.0}}}};
  LammpsSession s;
  s.run(contact_commands(write_tissue(t, "figure8.data")) +
        "fix check all dpoly/check\n"
        "minimize 0.0 0.0 0 0");
  EXPECT_EQ(s.thermo("f_check[5]"), 1.0);
  EXPECT_EQ(s.thermo("f_check[4]"), 0.0);
}

// A ring segment not shorter than half the box at a minimum is reported. No run gets there (fix
// dpoly/cells stops it at the first force evaluation after a segment passes half the box), so
// the segment is drawn out by hand after a minimum, and the check called as after the next one.
TEST(Check, SegmentPastHalfTheBoxIsReported)
{
  Tissue t;    // two cells in a box of 8; segments 5-6 and 7-8 of cell 2 are 3.95 long
  t.cells = {square(1.0, 1.0, 1.0), {{{2.2, 1.0}, {6.15, 1.0}, {6.15, 2.0}, {2.2, 2.0}}}};
  t.adhesive = {{2, 5}, {3, 8}};
  t.box = 8.0;
  LammpsSession s;
  s.run(contact_commands(write_tissue(t, "check_stretched.data")) +
        "comm_modify cutoff 4.5\nfix check all dpoly/check action error\n"
        "minimize 1.0 0.0 10 100");    // converged (energy tolerance 1)
  std::vector<double> x = s.gather("x", 3);
  x[3 * 5] = x[3 * 4] + 4.25;    // vertex 6, 4.25 to the right of vertex 5
  x[3 * 5 + 1] = x[3 * 4 + 1];
  s.scatter("x", 3, x);
  auto *lmp = static_cast<LAMMPS_NS::LAMMPS *>(s.lammps_handle());
  auto *check = dynamic_cast<LAMMPS_NS::FixDPolyStage *>(lmp->modify->get_fix_by_id("check"));
  ASSERT_NE(check, nullptr);
  std::string error;
  try {
    check->act();
  } catch (std::exception &e) {
    error = e.what();
  }
  EXPECT_THAT(error,
              HasSubstr("1 ring segments are not shorter than half the box (first: segment "
                        "5-6 of cell 2, 4.25 long, 4.25 in x, half the box length 4)"));
}

TEST(Check, BadInput)
{
  if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  auto error_of = [](const std::string &line) {
    LammpsSession s;
    return s.try_run(contact_commands(data_file("overlapping.data")) + line + "\nrun 0 post no");
  };
  EXPECT_THAT(error_of("fix c all dpoly/check pressure 0"),
              HasSubstr("pressure must be nonzero, got 0"));
  EXPECT_THAT(error_of("fix c all dpoly/check action shout"),
              HasSubstr("must be 'warn' or 'error'"));
}
