// Cell-cell contacts: pair dpoly/contact (repulsion), bond mesophyll/adhesion (contact-dependent
// adhesion), adhere_cells (initial bonds) and fix mesophyll/break (breaking between
// minimizations). Runs on any number of ranks unless a test says otherwise.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <utility>

using ::testing::HasSubstr;

using namespace test;

namespace {

// The nine-cell tissue of the tests' data, overlapping, bonded, then opened a little so that
// some bonds are stretched and others still overlap.
std::unique_ptr<LammpsSession>
adhesive_tissue(const Contacts &c = Contacts(), MPI_Comm comm = MPI_COMM_WORLD,
                const std::string &data = data_file("overlapping.data"))
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(contact_commands(data, c));
  s->run("adhere_cells all 2\nchange_box all x scale 1.04 y scale 1.03 remap\n"
         "variable th0 atom d_theta0+0.2*cos(2.3*id)\nset group all d_theta0 v_th0\n"
         "run 0 post no");
  return s;
}

// The adhesive bonds in a written data file, as (smaller ID, larger ID).
std::set<std::pair<int, int>> adhesive_bonds_in(const std::string &path)
{
  std::ifstream in(path);
  std::string line;
  std::set<std::pair<int, int>> bonds;
  bool in_bonds = false;
  while (std::getline(in, line)) {
    if (line.rfind("Bonds", 0) == 0) {
      in_bonds = true;
      continue;
    }
    if (in_bonds && !line.empty() && std::isalpha((unsigned char) line[0])) break;
    std::istringstream words(line);
    int id, type, a, b;
    if (in_bonds && (words >> id >> type >> a >> b) && type == 2)
      bonds.insert({std::min(a, b), std::max(a, b)});
  }
  return bonds;
}

}    // namespace

// ---------------------------------------------------------------------------------------
// Forces and pressure

TEST(Contacts, AdhesiveTissueForcesMatchFiniteDifferences)
{
  for (const char *rule : {"bonds", "cells"}) {
    auto s = adhesive_tissue({rule, "yes", ""});
    ASSERT_GT(s->thermo("epair"), 1.0e-6) << "some vertices should overlap";
    ASSERT_GT(s->thermo("ebond"), 1.0e-6) << "some adhesive bonds should be stretched";
    EXPECT_LT(finite_difference_error(*s), 1.0e-7) << "z rule " << rule;
  }
}

TEST(Contacts, SelfRepulsionMatchesFiniteDifferences)
{
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(data_file("single_contacts.data")) +
         "change_box all x scale 0.3 remap\n"
         "run 0 post no");
  const double with_self = s->thermo("epair");
  ASSERT_GT(with_self, 1.0e-6) << "the squashed ring should touch itself";
  EXPECT_LT(finite_difference_error(*s), 1.0e-7);

  auto off = std::make_unique<LammpsSession>();
  off->run(contact_commands(data_file("single_contacts.data"), {"bonds", "no", ""}) +
           "change_box all x scale 0.3 remap\nrun 0 post no");
  EXPECT_EQ(off->thermo("epair"), 0.0);
}

TEST(Contacts, PressureMatchesBoxDerivative)
{
  auto s = adhesive_tissue();
  const double press = s->thermo("press");
  const double area = s->equal_variable("lx*ly");
  const double e = 1.0e-5;
  auto energy = [&](double scale) {
    return energy_after_scaling(*s, scale, scale);
  };
  const double numeric =
      -(energy(1.0 + e) - energy(1.0 - e)) / (area * ((1 + e) * (1 + e) - (1 - e) * (1 - e)));
  EXPECT_NEAR(press, numeric, 1.0e-7 * std::fabs(press));
}

TEST(Contacts, ParallelRunMatchesSerialRun)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto parallel = adhesive_tissue();
  auto serial = adhesive_tissue(Contacts(), self_comm());
  for (const char *keyword : {"pe", "ebond", "epair", "press"})
    EXPECT_NEAR(parallel->thermo(keyword), serial->thermo(keyword),
                1.0e-12 * std::max(1.0, std::fabs(serial->thermo(keyword))))
        << keyword;
  EXPECT_LT(relative_force_error(serial->gather("f", 3), parallel->gather("f", 3)), 1.0e-12);
}

// ---------------------------------------------------------------------------------------
// Two cells: the force-extension law and the threshold stretch r* = (1 + sqrt 2) s

namespace {

// Two unit squares facing each other across a gap; 'bonds' vertex pairs of the facing sides
// are bonded (1: lower corners, 2: both).
std::unique_ptr<LammpsSession> two_cells(double gap, int bonds, const std::string &z_rule,
                                         const std::string &break_options = "")
{
  Tissue t;
  t.cells = {square(10.0, 10.0, 1.0), square(11.0 + gap, 10.0, 1.0)};
  t.adhesive = {{2, 5}};
  if (bonds == 2) t.adhesive.push_back({3, 8});
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(write_tissue(t, "two_cells.data"), {z_rule, "yes", break_options}) +
         "group right molecule 2\ncompute pull right reduce sum fx\n"
         "thermo_style custom step pe ebond epair c_pull\nthermo_modify norm no\nrun 0 post no");
  return s;
}

}    // namespace

TEST(Contacts, TwoCellForceExtensionIsAnalytic)
{
  const double s = 0.5;    // contact distance of two vertices of diameter 0.5
  for (int bonds : {1, 2})
    for (const char *rule : {"bonds", "cells"}) {
      // z_mu counts bonds or neighbour cells; z_munu = (z_mu + z_nu)/2 + 1
      const double z = (std::string(rule) == "bonds" ? bonds : 1) + 1.0;
      for (double r : {0.55, 0.8, 1.0, 1.15}) {
        auto cells = two_cells(r, bonds, rule);
        const double expected = -bonds * (1.0 / z) * (r / s - 1.0) / s;
        EXPECT_NEAR(cells->thermo("c_pull"), expected, 1.0e-12)
            << bonds << " bonds, z rule " << rule << ", r = " << r;
        EXPECT_NEAR(cells->thermo("ebond"), bonds * 0.5 / z * std::pow(r / s - 1.0, 2), 1.0e-12);
      }
    }
  // overlap: no adhesion, the pair style repels with (eps_c/2)(1 - r/s)^2
  auto pressed = two_cells(0.3, 1, "bonds");
  EXPECT_EQ(pressed->thermo("ebond"), 0.0);
  EXPECT_NEAR(pressed->thermo("epair"), 2 * 0.5 * std::pow(1.0 - 0.3 / s, 2), 1.0e-12);
  EXPECT_NEAR(pressed->thermo("c_pull"), 2 * (1.0 - 0.3 / s) / s, 1.0e-12);
}

TEST(Contacts, BondBreaksAtThresholdStretch)
{
  const double s = 0.5, r_star = (1.0 + std::sqrt(2.0)) * s;
  // beta so large that the stochastic branch never fires this close to the barrier
  auto below = two_cells(0.999 * r_star, 1, "bonds", "4242 beta 1.0e9 runs yes");
  EXPECT_EQ(below->thermo("f_break[1]") + below->thermo("f_break[2]"), 0.0);
  EXPECT_EQ(below->thermo("f_break[3]"), 1.0);

  auto above = two_cells(1.001 * r_star, 1, "bonds", "4242 beta 1.0e9 runs yes");
  EXPECT_EQ(above->thermo("f_break[1]"), 1.0);
  EXPECT_EQ(above->thermo("f_break[3]"), 0.0);
  // the local output lists it: atoms 2 and 5, break step 1, stretch r/s, 1 = threshold
  above->run("compute listed all reduce sum f_break[1] f_break[2] f_break[3] f_break[4] "
             "f_break[5] inputs local\nthermo_style custom step c_listed[*]\nrun 0 post no");
  EXPECT_EQ(above->thermo("c_listed[1]"), 2.0);
  EXPECT_EQ(above->thermo("c_listed[2]"), 5.0);
  EXPECT_EQ(above->thermo("c_listed[3]"), 1.0);
  EXPECT_NEAR(above->thermo("c_listed[4]"), 1.001 * r_star / s, 1.0e-12);
  EXPECT_EQ(above->thermo("c_listed[5]"), 1.0);
  above->run("run 0 post no");
  EXPECT_EQ(above->thermo("ebond"), 0.0) << "the broken bond must be gone";
}

// Passes before 'start' count (the random stream's step) but break nothing, also after a restart.
TEST(Contacts, BreakStartSkipsTheFirstPasses)
{
  const double s = 0.5, r_star = (1.0 + std::sqrt(2.0)) * s;
  const std::string options = "4242 beta 1.0e9 runs yes start 2";
  auto held = two_cells(1.001 * r_star, 1, "bonds", options);
  EXPECT_EQ(held->thermo("f_break[1]"), 0.0) << "the first pass breaks nothing";
  EXPECT_EQ(held->thermo("f_break[3]"), 1.0);
  EXPECT_EQ(held->thermo("f_break[5]"), 1.0) << "but counts";
  const std::string restart = scratch("break_start.restart");
  held->run("write_restart " + restart);
  held->run("run 0 post no");
  EXPECT_EQ(held->thermo("f_break[1]"), 1.0) << "the second pass breaks the bond beyond r*";

  LammpsSession resumed;
  resumed.run(resume_commands(restart) + "fix break all mesophyll/break " + options +
              "\nthermo_style custom step pe\nrun 0 post no");
  EXPECT_EQ(resumed.thermo("f_break[5]"), 2.0);
  EXPECT_EQ(resumed.thermo("f_break[1]"), 1.0) << "a resumed run knows the first pass is done";
}

// ---------------------------------------------------------------------------------------
// Breaking statistics and rules

namespace {

// 'pairs' pairs of squares, each held by one adhesive bond of length r (contact s = 0.5).
std::unique_ptr<LammpsSession> bonded_pairs(int pairs, double r, const std::string &break_options)
{
  Tissue t;
  t.box = 200.0;
  const int per_row = 20;
  for (int k = 0; k < pairs; k++) {
    const double x = 2.0 + (k % per_row) * 8.0, y = 2.0 + (k / per_row) * 4.0;
    t.cells.push_back(square(x, y, 1.0));
    t.cells.push_back(square(x + 1.0 + r, y, 1.0));
    t.adhesive.push_back({8 * k + 2, 8 * k + 5});
  }
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(write_tissue(t, "pairs.data"), {"bonds", "yes", break_options}) +
         "run 0 post no");
  return s;
}

}    // namespace

// Identical bonds at one stretch break with frequency exp(-beta dU): two stretches, chi-square
// with 2 degrees of freedom below its 0.1% critical value 13.8.
TEST(Breaking, StochasticFrequencyMatchesBoltzmannFactor)
{
  const int pairs = 400;
  const double s = 0.5, z = 2.0, barrier = 0.5 / z * 2.0;
  double chi2 = 0.0;
  for (double r : {0.9, 1.0}) {
    const double energy = 0.5 / z * std::pow(r / s - 1.0, 2);
    const double beta = std::log(1.0 / 0.3) / (barrier - energy);    // p = 0.3
    char options[128];
    snprintf(options, sizeof(options), "98765 beta %.17g runs yes", beta);
    auto t = bonded_pairs(pairs, r, options);
    const double p = std::exp(-beta * (barrier - energy));
    const double broken = t->thermo("f_break[2]");
    EXPECT_EQ(t->thermo("f_break[1]"), 0.0);
    chi2 += std::pow(broken - pairs * p, 2) / (pairs * p * (1.0 - p));
  }
  EXPECT_LT(chi2, 13.8);
}

TEST(Breaking, CompressedBondsNeverBreak)
{
  auto t = bonded_pairs(100, 0.3, "98765 beta 1.0e-6 runs yes");
  EXPECT_EQ(t->thermo("f_break[1]") + t->thermo("f_break[2]"), 0.0);
  EXPECT_EQ(t->thermo("f_break[3]"), 100.0);
}

// A junction of three bonds: the outer two overlap, the middle one is stretched. Its ring
// neighbours all hold bonds, so it is interior and must not break stochastically while the
// edge rule is on; with the rule off it breaks (beta tiny, so p is nearly 1).
TEST(Breaking, JunctionInteriorBondsNeedTheEdgeRuleOff)
{
  Tissue t;
  t.cells = {{{{9.0, 9.0}, {10.0, 9.0}, {10.0, 10.0}, {10.0, 11.0}, {9.0, 11.0}}},
             {{{10.4, 11.0}, {10.9, 10.0}, {10.4, 9.0}, {11.4, 9.0}, {11.4, 11.0}}}};
  t.adhesive = {{2, 8}, {3, 7}, {4, 6}};
  const std::string data = write_tissue(t, "junction.data");
  for (const char *edges : {"yes", "no"}) {
    LammpsSession s;
    s.run(contact_commands(
              data, {"bonds", "yes", std::string("555 beta 1.0e-3 runs yes edges ") + edges}) +
          "run 0 post no");
    EXPECT_EQ(s.thermo("f_break[2]"), std::string(edges) == "yes" ? 0.0 : 1.0) << "edges " << edges;
  }
}

// ---------------------------------------------------------------------------------------
// The same broken bonds on any number of ranks, for any atom order, across a restart

namespace {

// Open the tissue step by step; a break step follows every minimization.
void pull(LammpsSession &s, int steps)
{
  for (int k = 0; k < steps; k++)
    s.run("change_box all x scale 1.08 remap\nminimize 0.0 1.0e-8 2000 20000");
}

std::set<std::pair<int, int>> surviving_bonds(LammpsSession &s, const std::string &name)
{
  const std::string path = scratch(name);
  s.run("write_data " + path + " nocoeff");
  return adhesive_bonds_in(path);
}

std::unique_ptr<LammpsSession> pulled_tissue(MPI_Comm comm, const std::string &data, int steps)
{
  auto s = adhesive_tissue({"bonds", "yes", "31337 beta 30"}, comm, data);
  s->run("min_style cg\nthermo 1000");
  pull(*s, steps);
  return s;
}

}    // namespace

TEST(Breaking, SameBondsBreakOnAnyNumberOfRanks)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto parallel = pulled_tissue(MPI_COMM_WORLD, data_file("overlapping.data"), 4);
  auto serial = pulled_tissue(self_comm(), data_file("overlapping.data"), 4);
  EXPECT_GT(parallel->thermo("f_break[4]"), 0.0) << "some bonds should have broken";
  EXPECT_EQ(parallel->thermo("f_break[4]"), serial->thermo("f_break[4]"));
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  EXPECT_EQ(surviving_bonds(*parallel, "parallel.data"),
            surviving_bonds(*serial, "serial." + std::to_string(rank) + ".data"));
}

TEST(Breaking, SameBondsBreakForAnyAtomOrder)
{
  auto sorted = pulled_tissue(MPI_COMM_WORLD, data_file("overlapping.data"), 4);
  auto shuffled = pulled_tissue(MPI_COMM_WORLD, data_file("overlapping_shuffled.data"), 4);
  EXPECT_GT(sorted->thermo("f_break[4]"), 0.0);
  EXPECT_EQ(surviving_bonds(*sorted, "sorted.data"), surviving_bonds(*shuffled, "shuffled.data"));
}

TEST(Breaking, RestartGivesTheSameLaterBreaks)
{
  auto straight = pulled_tissue(MPI_COMM_WORLD, data_file("overlapping.data"), 4);

  const std::string restart = scratch("break.restart");
  auto first = pulled_tissue(MPI_COMM_WORLD, data_file("overlapping.data"), 2);
  first->run("write_restart " + restart);
  LammpsSession second;
  second.run(resume_commands(restart) +
             "fix break all mesophyll/break 31337 beta 30\nmin_style cg\nthermo 1000\n"
             "thermo_style custom step pe\nthermo_modify norm no\n"
             "run 0 post no\n");    // LAMMPS allows change_box only after a first run here
  pull(second, 2);
  EXPECT_EQ(second.thermo("f_break[5]"), 4.0) << "the break step count must survive the restart";
  EXPECT_EQ(second.thermo("f_break[4]"), straight->thermo("f_break[4]"));
  EXPECT_EQ(surviving_bonds(*straight, "straight.data"), surviving_bonds(second, "restarted.data"));
}

// ---------------------------------------------------------------------------------------
// Bad input (one rank: some of these are per-atom errors)

class BadContacts : public ErrorTest {};

TEST_F(BadContacts, Settings)
{
  const std::string data = data_file("overlapping.data");
  std::string cmds = contact_commands(data);
  cmds.replace(cmds.find("z bonds"), 7, "z neighbours");
  EXPECT_THAT(error_of(cmds), HasSubstr("z must be 'bonds' or 'cells', got 'neighbours'"));
  expect_errors(contact_commands(data),
                {{"fix b all mesophyll/break 5 beta 0", "beta must be > 0, got 0"},
                 {"fix b all mesophyll/break 5 threshold 1", "must be > 1, got 1"},
                 {"fix b all mesophyll/break -5", "seed must be > 0, got -5"},
                 {"fix b all mesophyll/break 5 gamma 2", "keyword: gamma"},
                 {"pair_coeff * * -1", "eps_c must be >= 0, got -1"},
                 {"bond_coeff 2 mesophyll/adhesion -1", "eps_c must be >= 0, got -1"}});
}

TEST_F(BadContacts, AdhesiveBondInsideOneCell)
{
  Tissue t;
  t.cells = {square(10.0, 10.0, 1.0)};
  t.adhesive = {{1, 3}};
  const std::string msg =
      error_of(contact_commands(write_tissue(t, "inside.data")) + "run 0 post no");
  EXPECT_THAT(msg, HasSubstr("bond 1-3 joins two vertices of cell 1"));
}

TEST_F(BadContacts, AdhereCellsRefusesNonsense)
{
  const std::string overlapping = contact_commands(data_file("overlapping.data"));
  expect_errors(overlapping,
                {{"adhere_cells all 3", "bond type 3 is not between 1 and 2"},
                 {"adhere_cells all 1", "bond type 1 is not a bond type of"},
                 {"adhere_cells nogroup 2", "group nogroup does not exist"}});
  Tissue apart;
  apart.cells = {square(10.0, 10.0, 1.0), square(15.0, 10.0, 1.0)};
  EXPECT_THAT(error_of(contact_commands(write_tissue(apart, "apart.data")) + "adhere_cells all 2"),
              HasSubstr("no vertices of different cells overlap"));
  std::string tight = overlapping;
  tight.replace(tight.find("extra/bond/per/atom 6"), 21, "extra/bond/per/atom 0");
  EXPECT_THAT(error_of(tight + "adhere_cells all 2"), HasSubstr("add 'extra/bond/per/atom"));
}

TEST_F(BadContacts, OverlapsMustNotHideBehindSpecialBonds)
{
  const std::string msg = error_of(contact_commands(data_file("overlapping.data")) +
                                   "special_bonds lj 0.0 1.0 1.0\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("needs special_bonds lj 1.0 1.0 1.0 (1-2 weight is 0)"));
}

TEST_F(BadContacts, BreakingNeedsTheAdhesionStyle)
{
  const std::string msg =
      error_of("units lj\ndimension 2\natom_style molecular\nboundary p p p\n"
               "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
               "bond_style dpoly/segment\nangle_style dpoly/bending\n"
               "read_data " +
               data_file("single.data") +
               " fix Vertices NULL Vertices\n"
               "bond_coeff * 1\nangle_coeff * 1\nfix cells all dpoly/cells\n"
               "fix b all mesophyll/break 7\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("needs bond_style mesophyll/adhesion"));
}
