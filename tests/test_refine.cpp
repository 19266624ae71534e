// fix dpoly/refine: long ring segments split at their midpoints, the relaxed ring stays relaxed,
// the topology stays a set of closed rings, and the result does not depend on the ranks.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <map>
#include <memory>

using ::testing::HasSubstr;

using namespace test;

namespace {

// One regular 16-gon (segments about 0.24 long), relaxed at fixed box; with vertex diameter 0.1
// every segment is longer than 3 vertex radii (0.15). refine_fix: the fix line, or none.
std::unique_ptr<LammpsSession> relaxed_ring(const std::string &refine_fix, double sigma = 0.1)
{
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(data_file("single_contacts.data")) + "set group all d_sigma " +
         std::to_string(sigma) + "\ncompute vertex all dpoly/vertex\n" + refine_fix +
         "\nthermo_style custom step pe ebond eangle f_cells fnorm f_cells[2] atoms bonds angles\n"
         "thermo_modify norm no\n"
         "min_style cg\nminimize 0.0 1.0e-13 10000 100000\n");
  return s;
}

// Each cell's ring, walked along column 3 of compute dpoly/vertex (the next vertex's ID).
std::map<int, std::vector<int>> rings_of(LammpsSession &s)
{
  s.run("run 1 post no");    // a new step, so that the gather below computes the compute anew
  const std::vector<double> next = s.gather("c_vertex", 3);
  const std::vector<int> mol = s.gather_int("molecule", 1);
  std::map<int, std::vector<int>> rings;
  const int n = s.natoms();
  std::vector<bool> seen(n + 1, false);
  for (int start = 1; start <= n; start++) {
    if (seen[start]) continue;
    std::vector<int> ring;
    int id = start;
    while (!seen[id] && (int) ring.size() <= n) {
      seen[id] = true;
      ring.push_back(id);
      id = (int) next[3 * (id - 1) + 2];
    }
    EXPECT_EQ(id, start) << "the walk from vertex " << start << " must close on itself";
    EXPECT_TRUE(rings.find(mol[start - 1]) == rings.end()) << "one ring per cell";
    rings[mol[start - 1]] = ring;
  }
  return rings;
}

}    // namespace

TEST(Refine, SplitsEveryLongSegmentAtItsMidpoint)
{
  auto s = relaxed_ring("fix refine all dpoly/refine");
  ASSERT_EQ(s->natoms(), 32) << "the minimization's end splits all 16 segments";
  EXPECT_EQ(s->thermo("f_refine[1]"), 16.0);
  EXPECT_EQ(s->thermo("bonds"), 32.0);
  EXPECT_EQ(s->thermo("angles"), 32.0) << "one angle per vertex";
  const auto rings = rings_of(*s);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings.begin()->second.size(), 32u);

  // new vertices (IDs 17-32) sit halfway between old ones, straight, with the mean diameter
  const std::vector<double> x = s->gather("x", 3), theta0 = s->gather("d_theta0", 1),
                            sigma = s->gather("d_sigma", 1);
  const std::vector<int> &ring = rings.begin()->second;
  for (size_t k = 0; k < ring.size(); k++) {
    const int id = ring[k], before = ring[(k + 31) % 32], after = ring[(k + 1) % 32];
    if (id <= 16) {
      EXPECT_GT(before, 16) << "old and new vertices alternate";
      continue;
    }
    for (int d = 0; d < 2; d++)
      EXPECT_NEAR(x[3 * (id - 1) + d], 0.5 * (x[3 * (before - 1) + d] + x[3 * (after - 1) + d]),
                  1e-12);
    EXPECT_EQ(theta0[id - 1], 0.0);
    EXPECT_EQ(sigma[id - 1], 0.1);
  }
}

// At the split the polygon, hence the area term, and every turning angle are unchanged; each
// half takes over the segment's tension, which fixes its l0 and its energy exactly.
TEST(Refine, KeepsAreaAnglesAndTension)
{
  auto s = relaxed_ring("");    // no split yet
  s->run("run 0 post no");
  const double area = s->thermo("f_cells[2]"), area_energy = s->thermo("f_cells");
  const double bending = s->thermo("eangle");
  const std::vector<double> l0 = s->gather("d_l0", 1), length = s->gather("c_vertex", 3);
  double expected_segments = 0.0, tension = 0.0;
  for (int k = 0; k < 16; k++) {
    const double l = length[3 * k + 1], x = l / l0[k];
    const double h = l / (1.0 + sqrt(1.0 + 2.0 * x * (x - 1.0)));
    expected_segments += 2 * 0.5 * (l / (2 * h) - 1) * (l / (2 * h) - 1);
    tension = (x - 1) / l0[k];
    EXPECT_NEAR((l / (2 * h) - 1) / h, tension, 1e-12) << "the halves carry the same tension";
  }
  s->run("fix refine all dpoly/refine runs yes\nrun 0");
  ASSERT_EQ(s->natoms(), 32);
  s->run("run 0 post no");
  EXPECT_NEAR(s->thermo("f_cells[2]"), area, 1e-13);
  EXPECT_NEAR(s->thermo("f_cells"), area_energy, 1e-15);
  EXPECT_NEAR(s->thermo("eangle"), bending, 1e-15);
  EXPECT_NEAR(s->thermo("ebond"), expected_segments, 1e-14);
}

// The new vertices feel the cell's pressure, which a straight segment does not balance, so the
// ring relaxes a little after a split: its shape stays, its energy moves by little.
TEST(Refine, RelaxedRingStaysNearItsMinimum)
{
  auto s = relaxed_ring("fix refine all dpoly/refine");
  s->run("run 0 post no");
  const double energy = s->thermo("pe");
  const std::vector<double> x = s->gather("x", 3);
  s->run("unfix refine\nminimize 0.0 1.0e-13 10000 100000");
  const std::vector<double> relaxed = s->gather("x", 3);
  double moved = 0.0;
  for (int i = 0; i < 16 * 3; i++) moved = std::max(moved, std::fabs(relaxed[i] - x[i]));
  EXPECT_LT(moved, 0.01 * 0.12) << "old vertices move by less than 1% of a half segment";
  EXPECT_LT(std::fabs(s->thermo("pe") - energy), 1e-3 * energy);
}

TEST(Refine, CapLimitsEachCell)
{
  auto s = relaxed_ring("fix refine all dpoly/refine cap 1.5");
  EXPECT_EQ(s->natoms(), 24) << "1.5 x 16 vertices at most";
  rings_of(*s);
  s->run("minimize 0.0 1.0e-13 10000 100000");
  EXPECT_EQ(s->natoms(), 24) << "the cap holds over later refinements";
}

// Only segments between two void-facing vertices split (default); 'void no' splits any.
TEST(Refine, VoidRuleSparesBondedVertices)
{
  // small disks bond only where rings come close
  const std::string setup = contact_commands(data_file("overlapping.data")) +
      "set group all d_sigma 0.1\nadhere_cells all 2\n"
      "compute bonds all dpoly/adhesion\ncompute vertex all dpoly/vertex\n";
  LammpsSession s;
  s.run(setup + "run 0 post no");
  const std::vector<double> bonds = s.gather("c_bonds", 1), next = s.gather("c_vertex", 3);
  int void_segments = 0;
  for (int i = 0; i < s.natoms(); i++)
    if (bonds[i] == 0 && bonds[(int) next[3 * i + 2] - 1] == 0) void_segments++;
  ASSERT_GT(void_segments, 0);
  ASSERT_LT(void_segments, s.natoms());
  s.run("fix refine all dpoly/refine runs yes\nrun 0");
  EXPECT_EQ(s.thermo("f_refine[1]"), void_segments);

  LammpsSession any;
  any.run(setup + "fix refine all dpoly/refine runs yes void no\nrun 0");
  EXPECT_EQ(any.thermo("f_refine[1]"), 144.0) << "every segment of the nine 16-gons";
  rings_of(any);
}

TEST(Refine, SameOnAnyNumberOfRanks)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  // rings that cross the periodic boundary, split twice at a fixed configuration
  const std::string commands = contact_commands(data_file("overlapping.data")) +
      "set group all d_sigma 0.02\nfix refine all dpoly/refine runs yes void no\n"
      "run 0\nrun 0\n";
  ParallelAndSerial runs(commands);
  LammpsSession &parallel = runs.parallel, &serial = runs.serial;
  ASSERT_EQ(parallel.natoms(), serial.natoms());
  for (const char *name : {"x", "d_l0", "d_theta0", "d_sigma"}) {
    const int count = std::string(name) == "x" ? 3 : 1;
    EXPECT_EQ(parallel.gather(name, count), serial.gather(name, count)) << name;
  }
  EXPECT_EQ(parallel.gather_int("molecule", 1), serial.gather_int("molecule", 1));
  // energies are sums in rank order: equal to round-off
  EXPECT_NEAR(parallel.thermo("pe"), serial.thermo("pe"), 1e-12 * serial.thermo("pe"));
}

TEST(Refine, RestartCarriesTheNewVerticesAndTheCounts)
{
  const std::string restart = scratch("refine.restart");
  // diameter 0.02: segments would split from 0.24 to 0.12 to 0.06, but the cap stops at 48
  auto first = relaxed_ring("fix refine all dpoly/refine cap 3 runs yes", 0.02);
  ASSERT_EQ(first->natoms(), 32);
  first->run("write_restart " + restart);
  LammpsSession second;
  second.run(resume_commands(restart) +
             "fix refine all dpoly/refine cap 3 runs yes\nthermo_style custom step pe\n"
             "thermo_modify norm no");
  EXPECT_EQ(second.natoms(), 32);
  for (const char *name : {"d_l0", "d_theta0", "d_sigma"})
    EXPECT_EQ(second.gather(name, 1), first->gather(name, 1)) << name;

  // one more refinement each: the cap counts from the vertices at the first refinement
  first->run("run 0");
  second.run("run 0");
  EXPECT_EQ(first->natoms(), 48);
  EXPECT_EQ(second.natoms(), 48);
  EXPECT_EQ(second.thermo("f_refine[2]"), 32.0) << "vertices added in all";
  EXPECT_EQ(second.thermo("f_refine[3]"), 2.0) << "refinements in all";
  for (const char *name : {"x", "d_l0", "d_theta0", "d_sigma"}) {
    const int count = std::string(name) == "x" ? 3 : 1;
    EXPECT_EQ(second.gather(name, count), first->gather(name, count)) << name;
  }
  second.run("run 0");
  EXPECT_EQ(second.natoms(), 48) << "the cap holds";
}

class BadRefine : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  }
};

TEST_F(BadRefine, SaysWhatIsWrong)
{
  auto error_of = [](const std::string &fix_line) {
    LammpsSession s;
    return s.try_run(contact_commands(data_file("single_contacts.data")) + fix_line +
                     "\nrun 0 post no");
  };
  EXPECT_THAT(error_of("fix r all dpoly/refine length 1"),
              HasSubstr("length must be >= 2 vertex radii"));
  EXPECT_THAT(error_of("fix r all dpoly/refine cap 0.5"), HasSubstr("cap must be >= 1, got 0.5"));
  EXPECT_THAT(error_of("fix r all dpoly/refine depth 2"), HasSubstr("keyword: depth"));
  EXPECT_THAT(error_of("fix r all dpoly/refine cap"), HasSubstr("fix dpoly/refine cap"));
  LammpsSession s;
  std::string cmds = contact_commands(data_file("single_contacts.data"));
  cmds.replace(cmds.find("fix cells all dpoly/cells eps_a 1.0\n"), 36, "");
  cmds.replace(cmds.find(" f_cells"), 8, "");
  const std::string msg = s.try_run(cmds + "fix r all dpoly/refine\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("needs fix dpoly/cells"));
}
