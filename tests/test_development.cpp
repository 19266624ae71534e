// The growth protocol end to end (doc/Howto_mesophyll.rst, sections "Growth" and "Enthalpy
// minimization"): the 16-cell confluent tissue of examples/tissue grows for three steps, each
// minimized at constant pressure with fix box/relax and min_style fire/nph, as
// examples/mesophyll/in.mesophyll does.
#include "test_helpers.h"

#include "gtest/gtest.h"

#include <cstdlib>
#include <memory>

using namespace test;

namespace {

const double P0 = 1.0e-3;

std::string tissue_file()
{
  const char *dir = getenv("MESOPHYLL_EXAMPLES");
  return std::string(dir ? dir : "examples") + "/tissue/tissue_N16.data";
}

const std::string CHECK = "fix check all dpoly/check pressure 1.0e-3\n";
const std::string BREAK = "fix break all mesophyll/break 20261122 beta 100\n";
const std::string GROW = "fix grow all mesophyll/grow delta_a 0.5 lambda 5 c_L 0.5 c_B 4\n";
const std::string REFINE = "fix refine all dpoly/refine length 3\n";

// Everything after the styles: the same in a fresh start and after read_restart.
std::string protocol_fixes(const std::string &stages = CHECK + BREAK + GROW)
{
  return "bond_coeff 1 dpoly/segment 1.0\nbond_coeff 2 mesophyll/adhesion 1.0\n"
         "comm_modify cutoff 3.0\n"
         "fix cells all dpoly/cells eps_a 1.0\n" +
      stages +
      "fix relax all box/relax iso 1.0e-3 vmax 1.0e-3\n"
      "compute tissue all dpoly/tissue\n"
      "thermo_style custom step pe press c_tissue[1]\nthermo_modify norm no\nthermo 100000\n"
      "min_style fire/nph\ntimestep 0.01\nmin_modify tmax 5\n";
}

// extra: commands after the protocol's fixes; stages: the stage fixes, in the order given
std::unique_ptr<LammpsSession> tissue(MPI_Comm comm = MPI_COMM_WORLD, const std::string &extra = "",
                                      const std::string &stages = CHECK + BREAK + GROW)
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run("units lj\ndimension 2\natom_style molecular\nboundary p p p\n"
         "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
         "bond_style hybrid dpoly/segment mesophyll/adhesion z bonds\n"
         "angle_style dpoly/bending\n"
         "read_data " +
         tissue_file() +
         " fix Vertices NULL Vertices extra/special/per/atom 40 extra/bond/per/atom 2 "
         "extra/angle/per/atom 2\n"
         "angle_coeff * 0.4\npair_style dpoly/contact\npair_coeff * * 1.0\n"
         "special_bonds lj 1.0 1.0 1.0\n" +
         protocol_fixes(stages) + extra);
  return s;
}

// What the protocol records at a minimum.
struct Minimum {
  double converged, pressure_error, phi, phi_patch, shape, contacts, bonds, compaction;
};

std::vector<Minimum> develop(LammpsSession &s, int steps)
{
  std::vector<Minimum> minima;
  for (int k = 0; k < steps; k++) {
    s.run("minimize 0.0 1.0e-10 200000 2000000");
    minima.push_back({s.thermo("f_check[1]"), s.thermo("f_check[3]"), s.thermo("c_tissue[1]"),
                      s.thermo("c_tissue[2]"), s.thermo("c_tissue[3]"), s.thermo("c_tissue[4]"),
                      s.thermo("c_tissue[5]"), s.thermo("f_grow[5]")});
  }
  return minima;
}

// Two developments that reach the same minima, up to the round-off of a different summation
// order amplified by a few thousand FIRE steps; bond counts exactly.
void expect_same_minima(const std::vector<Minimum> &a, const std::vector<Minimum> &b,
                        const std::string &what)
{
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); k++) {
    EXPECT_NEAR(a[k].phi, b[k].phi, 1e-7 * b[k].phi) << what << ", step " << k + 1;
    EXPECT_NEAR(a[k].phi_patch, b[k].phi_patch, 1e-7 * b[k].phi_patch)
        << what << ", step " << k + 1;
    EXPECT_NEAR(a[k].shape, b[k].shape, 1e-7 * b[k].shape) << what << ", step " << k + 1;
    EXPECT_EQ(a[k].contacts, b[k].contacts) << what << ", step " << k + 1;
    EXPECT_EQ(a[k].bonds, b[k].bonds) << what << ", step " << k + 1;
  }
}

// The same development on rank 0 alone, its minima sent to every rank (one serial copy per rank
// would crowd the cores).
std::vector<Minimum> serial_development(int steps, const std::string &extra = "")
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<Minimum> minima(steps);
  if (rank == 0) minima = develop(*tissue(self_comm(), extra), steps);
  MPI_Bcast(minima.data(), (int) (minima.size() * sizeof(Minimum)), MPI_BYTE, 0, MPI_COMM_WORLD);
  return minima;
}

}    // namespace

TEST(Development, EveryMinimumIsAtP0AndTheTissueOpens)
{
  auto s = tissue();
  s->run("run 0 post no");
  const double phi_start = s->thermo("c_tissue[1]");
  const std::vector<Minimum> minima = develop(*s, 3);
  double phi_before = phi_start;
  for (size_t k = 0; k < minima.size(); k++) {
    EXPECT_EQ(minima[k].converged, 1.0) << "minimum " << k + 1;
    EXPECT_LT(minima[k].pressure_error, 1e-6) << "minimum " << k + 1;
    if (k > 0) EXPECT_LT(minima[k].phi, phi_before) << "phi must fall, step " << k + 1;
    phi_before = minima[k].phi;
  }
  EXPECT_EQ(minima.back().compaction, 0.0) << "phi never rose, so delta_phi_plus stays 0";
  EXPECT_LT(minima.back().bonds, minima.front().bonds) << "growth stretches bonds until some break";
}

TEST(Development, SameOnOneAndSeveralRanks)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto parallel = tissue();
  const std::vector<Minimum> minima = develop(*parallel, 3);
  expect_same_minima(minima, serial_development(3), "ranks");
}

TEST(Development, RestartAfterTheFirstStepReproducesTheRest)
{
  const std::string restart = scratch("development.restart");
  auto straight = tissue();
  std::vector<Minimum> reference = develop(*straight, 1);
  straight->run("write_restart " + restart);
  for (const Minimum &m : develop(*straight, 2)) reference.push_back(m);

  LammpsSession resumed;
  resumed.run("read_restart " + restart +
              "\nfix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n" +
              protocol_fixes());
  EXPECT_EQ(resumed.thermo("f_grow[1]"), 1.0) << "the growth step count survives";
  EXPECT_NEAR(resumed.thermo("f_grow[4]"), reference[0].phi, 1e-14) << "and phi at the minimum";
  EXPECT_EQ(resumed.thermo("f_check[9]"), 1.0) << "the count of checked minima survives";
  const std::vector<Minimum> rest = develop(resumed, 2);
  expect_same_minima(rest, {reference[1], reference[2]}, "restart");
  EXPECT_EQ(resumed.thermo("f_check[9]"), straight->thermo("f_check[9]"))
      << "the resumed run numbers its minima on, as the straight run";
}

TEST(Development, WithVertexInsertionStaysAtP0OnAnyRankCount)
{
  auto s = tissue(MPI_COMM_WORLD, REFINE);
  const std::vector<Minimum> minima = develop(*s, 3);
  for (size_t k = 0; k < minima.size(); k++) {
    EXPECT_EQ(minima[k].converged, 1.0) << "minimum " << k + 1;
    EXPECT_LT(minima[k].pressure_error, 1e-6) << "minimum " << k + 1;
  }
  const double added = s->thermo("f_refine[2]");
  EXPECT_GT(added, 0.0) << "three growth steps stretch void segments past 3 radii";
  EXPECT_EQ(s->thermo("atoms"), 512.0 + added) << "each insertion adds one vertex";
  if (world_size() > 1)
    expect_same_minima(minima, serial_development(3, REFINE), "ranks, with insertion");
}

// fix dpoly/cells runs check, break, grow, refine after each minimum, whatever the order of the
// fix commands: the reversed order gives the very same development (bonds break after the
// first minima, so growing before breaking would see other void-facing vertices)
TEST(Development, StagesActInTheProtocolOrderWhateverTheOrderOfTheFixCommands)
{
  const std::vector<Minimum> in_order =
      develop(*tissue(MPI_COMM_WORLD, "", CHECK + BREAK + GROW + REFINE), 3);
  const std::vector<Minimum> reversed =
      develop(*tissue(MPI_COMM_WORLD, "", REFINE + GROW + BREAK + CHECK), 3);
  ASSERT_EQ(in_order.size(), reversed.size());
  for (size_t k = 0; k < in_order.size(); k++) {
    EXPECT_EQ(in_order[k].phi, reversed[k].phi) << "step " << k + 1;
    EXPECT_EQ(in_order[k].shape, reversed[k].shape) << "step " << k + 1;
    EXPECT_EQ(in_order[k].contacts, reversed[k].contacts) << "step " << k + 1;
    EXPECT_EQ(in_order[k].bonds, reversed[k].bonds) << "step " << k + 1;
    EXPECT_EQ(in_order[k].converged, 1.0) << "step " << k + 1;
  }
  EXPECT_LT(in_order.back().bonds, in_order.front().bonds) << "bonds broke on the way";
}
