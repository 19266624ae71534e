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

// 'start 2' skips the first minimum (a development's relaxed tissue, before any growth), counts
// it, and splits from the second on; the count travels with restart files.
TEST(Refine, StartSkipsTheFirstPasses)
{
  auto s = relaxed_ring("fix refine all dpoly/refine start 2");
  EXPECT_EQ(s->natoms(), 16) << "the first pass adds nothing";
  EXPECT_EQ(s->thermo("f_refine[3]"), 1.0) << "but counts";
  const std::string restart = scratch("refine_start.restart");
  s->run("write_restart " + restart);
  s->run("minimize 0.0 1.0e-13 10000 100000");
  EXPECT_EQ(s->natoms(), 32) << "the second pass splits all 16 segments";

  LammpsSession resumed;
  resumed.run(resume_commands(restart) +
              "fix refine all dpoly/refine start 2\nthermo_style custom step pe\n"
              "thermo_modify norm no\nminimize 0.0 1.0e-13 10000 100000");
  EXPECT_EQ(resumed.natoms(), 32) << "a resumed run knows the first pass is done";
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

// ---------------------------------------------------------------------------------------
// rules published and consistent on hand-made rings: cell 1 is the ring
//   1 (5,5)  2 (6,5)  3 (7,5)  4 (7,6)  5 (7,7)  6 (6,7)  7 (5,7)  8 (5,6)
// with unit segments; 1 and 2 are bonded to cell 2 (below them), 3 to cell 3 (below it); 6 and
// 7 have diameter 0.8 (3 radii = 1.2: too short to split from), the others 0.5 (0.75); cells 2
// and 3 have diameter 2 and no candidates. theta0 is 0 on cell 1 but 0.3 at 4 and 1.0 at 5, and
// d_kb is 2 at 4. The published code's meso2D::addMesophyllCellMaterial() run on this ring
// (checked once against the code itself) makes the splits and values expected below.

namespace {

const char *STIFFNESS = "fix Stiffness all property/atom d_kl d_kb ghost yes\n"
                        "set group all d_kl 1.0\nset group all d_kb 1.0\n";

std::string hand_made_ring(bool bond_at_2)
{
  Tissue t;
  auto shift = [](std::vector<std::pair<double, double>> p) {
    for (auto &c : p) c = {c.first + 5.0, c.second + 5.0};
    return Polygon{p};
  };
  t.cells = {shift({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}),
             shift({{0, -1.1}, {1, -1.1}, {1, -0.1}, {0, -0.1}}),
             shift({{1.1, -1.1}, {2.1, -1.1}, {2.1, -0.1}, {1.1, -0.1}})};
  t.adhesive = {{1, 12}, {3, 15}};
  if (bond_at_2) t.adhesive.push_back({2, 11});
  t.sigma = 0.5;
  return contact_commands(write_tissue(t, bond_at_2 ? "ring_a.data" : "ring_b.data")) + STIFFNESS +
      "set atom 6*7 d_sigma 0.8\nset mol 2*3 d_sigma 2.0\n" +
      (bond_at_2 ? "" : "set atom 2 d_sigma 0.8\n") +
      "set mol 1 d_theta0 0.0\nset atom 4 d_theta0 0.3\nset atom 5 d_theta0 1.0\n"
      "set atom 4 d_kb 2.0\ncompute vertex all dpoly/vertex\n";
}

// What a vertex of cell 1 should be after the refinement, in ring order from vertex 1.
struct Expected {
  double x, y, l0, kl, kb, theta0, sigma;
};

void expect_ring(LammpsSession &s, const std::vector<Expected> &expected)
{
  const auto rings = rings_of(s);
  const std::vector<int> &ring = rings.at(1);
  ASSERT_EQ(ring.size(), expected.size());
  const std::vector<double> x = s.gather("x", 3), l0 = s.gather("d_l0", 1),
                            kl = s.gather("d_kl", 1), kb = s.gather("d_kb", 1),
                            theta0 = s.gather("d_theta0", 1), sigma = s.gather("d_sigma", 1);
  for (size_t k = 0; k < ring.size(); k++) {
    const int i = ring[k] - 1;
    const Expected &e = expected[k];
    SCOPED_TRACE("vertex " + std::to_string(ring[k]) + " (ring position " + std::to_string(k) +
                 ")");
    EXPECT_NEAR(x[3 * i], e.x, 1e-12);
    EXPECT_NEAR(x[3 * i + 1], e.y, 1e-12);
    EXPECT_NEAR(l0[i], e.l0, 1e-12);
    EXPECT_NEAR(kl[i], e.kl, 1e-12);
    EXPECT_NEAR(kb[i], e.kb, 1e-12);
    EXPECT_NEAR(theta0[i], e.theta0, 1e-12);
    EXPECT_NEAR(sigma[i], e.sigma, 1e-12);
  }
}

// theta0 of meso2D::addVertex(): minus the kb-weighted mean deviation at the segment's ends
double published_theta0(double k1, double d1, double k2, double d2)
{
  return -(k1 * d1 + k2 * d2) / (k1 + k2);
}

}    // namespace

// Every rule of the published insertion on one ring: the junction 2-3 (partners on cells 2 and
// 3) splits whatever its length, 1-2 (both partners on cell 2) does not; 3-4 has one bonded end
// and splits once, from 4; 4-5 is queued from both ends and split twice (l0/2, l0/4, l0/4);
// 5-6 and 7-8 are queued from one end only (6 and 7 are large), 6-7 from neither; 8-1 from 8.
namespace {

void expect_published_ring(LammpsSession &s)
{
  EXPECT_EQ(s.thermo("f_cells[1]"), 3.0);
  EXPECT_EQ(s.natoms(), 16 + 7);
  const double w = 0.4, corner = PI / 2;    // eps_b; the turning angle at a corner
  const double at_34 = published_theta0(w, corner, 2 * w, -0.3);
  const double first_45 = published_theta0(2 * w, -0.3, w, corner - 1.0);
  const double second_45 = published_theta0(1.5 * w, -first_45, w, corner - 1.0);
  expect_ring(s,
              {{5, 5, 1, 1, 1, 0, 0.5},
               {6, 5, 0.5, 0.5, 1, 0, 0.5},
               {6.5, 5, 0.5, 0.5, 1, published_theta0(w, 0, w, corner), 0.5},
               {7, 5, 0.5, 0.5, 1, 0, 0.5},
               {7, 5.5, 0.5, 0.5, 1.5, at_34, 0.5},
               {7, 6, 0.5, 0.5, 2, 0.3, 0.5},
               {7, 6.5, 0.25, 0.25, 1.5, first_45, 0.5},
               {7, 6.75, 0.25, 0.25, 1.25, second_45, 0.5},
               {7, 7, 0.5, 0.5, 1, 1.0, 0.5},
               {6.5, 7, 0.5, 0.5, 1, published_theta0(w, corner - 1.0, w, 0), 0.5},
               {6, 7, 1, 1, 1, 0, 0.8},
               {5, 7, 0.5, 0.5, 1, 0, 0.8},
               {5, 6.5, 0.5, 0.5, 1, published_theta0(w, corner, w, 0), 0.8},
               {5, 6, 0.5, 0.5, 1, 0, 0.5},
               {5, 5.5, 0.5, 0.5, 1, published_theta0(w, 0, w, corner), 0.5}});
  EXPECT_NEAR(at_34, -0.3235987755982988, 1e-15) << "meso2D::addVertex() on this ring";
  EXPECT_NEAR(second_45, -0.22247779607693796, 1e-15) << "meso2D::addVertex() on this ring";
  // cells 2 and 3 keep their rings; every vertex has one angle, every segment one bond
  EXPECT_EQ(s.thermo("angles"), 23.0);
  EXPECT_EQ(s.thermo("bonds"), 23.0 + 3) << "segments and the three adhesive bonds";
}

}    // namespace

TEST(RefinePublished, EachRuleOnAHandMadeRing)
{
  for (const char *newton_bond : {"on", "off"}) {
    SCOPED_TRACE(std::string("newton_bond ") + newton_bond);
    // newton_bond off keeps every angle on all its atoms: the old vertices need room for more
    std::string commands = std::string("newton on ") + newton_bond + "\n" + hand_made_ring(true);
    commands.replace(commands.find("extra/special/per/atom 40"), 25,
                     "extra/special/per/atom 40 extra/angle/per/atom 4");
    LammpsSession s;
    s.run(commands +
          "fix refine all dpoly/refine rules published runs yes\nrun 0 post no\nunfix refine");
    expect_published_ring(s);
  }
}

// The published code's third candidate (an unbonded vertex between two bonded ones whose
// partners lie on different cells) is unreachable there: vertex 2, unbonded and large between 1
// (cell 2) and 3 (cell 3), splits neither of its segments.
TEST(RefinePublished, NoRuleForAnUnbondedVertexBetweenJunctions)
{
  LammpsSession s;
  s.run(hand_made_ring(false) +
        "fix refine all dpoly/refine rules published runs yes\n"
        "run 0 post no\nunfix refine");
  EXPECT_EQ(s.natoms(), 16 + 6);
  const std::vector<int> ring = rings_of(s).at(1);
  EXPECT_EQ(ring[1], 2);
  EXPECT_EQ(ring[2], 3) << "1-2 and 2-3 stay whole";
}

// The cap counts the whole tissue before the step, as NVTOT < NVMAX does: a 16-gon with cap 1.5
// (24 vertices) splits all 16 segments twice in one step, and then stops.
TEST(RefinePublished, CapIsForTheWholeTissueBeforeTheStep)
{
  auto s = relaxed_ring(std::string(STIFFNESS), 0.02);
  s->run("fix refine all dpoly/refine rules published cap 1.5 runs yes\nrun 0 post no");
  EXPECT_EQ(s->natoms(), 48) << "each segment split twice";
  s->run("run 0 post no");
  EXPECT_EQ(s->natoms(), 48);
}

namespace {

// The relaxed 16-gon with vertex diameter sigma, minimized again with growth (delta_a 0.5) and
// rules published with the given options: refinement and growth act at the end of it.
std::unique_ptr<LammpsSession> grown_and_refined(double sigma, const std::string &options)
{
  auto s = relaxed_ring(std::string(STIFFNESS), sigma);
  s->run("fix grow all mesophyll/grow delta_a 0.5 box fixed\n"
         "fix refine all dpoly/refine rules published " +
         options + "\nminimize 0.0 1.0e-13 10000 100000");
  return s;
}

}    // namespace

// The published code inserts between breaking and the next growth, with the radii of the
// minimum. A 16-gon whose segments (0.223) exceed 3 radii (0.21) before growth scales the
// diameters by sqrt(1.5) (0.257 after) splits with timing before_growth, not after; and growth
// then acts on the refined ring, so all 32 vertices grow alike.
TEST(RefinePublished, DecidesBeforeGrowth)
{
  const double l0 = relaxed_ring("")->gather("d_l0", 1)[0];
  auto before = grown_and_refined(0.14, ""), after = grown_and_refined(0.14, "timing after_growth");
  EXPECT_EQ(before->natoms(), 48);
  EXPECT_EQ(after->natoms(), 16);
  // pieces l0/2 (old vertices), l0/4 (new ones), each grown by the same amount
  const std::vector<double> grown = before->gather("d_l0", 1);
  const double growth = grown[0] - 0.5 * l0;
  EXPECT_GT(growth, 0.0);
  for (int k = 0; k < 48; k++)
    EXPECT_NEAR(grown[k] - (k < 16 ? 0.5 : 0.25) * l0, growth, 1e-12) << "vertex " << k + 1;
}

// measure preferred reads each segment's l0 where the rule sets read its length: in the relaxed
// 16-gon (segments 0.238, at their l0) with diameters 0.16 (3 radii: 0.24) no segment is long
// enough, until vertices 1, 5 and 9 get l0 0.3; then their segments to the next vertex split
// (new vertices 17, 18 and 19 after them), before any minimization has stretched them, and the
// halves take l0/2 (rules tension at l = l0). Measured by length, the same ring splits nothing.
TEST(Refine, MeasurePreferredSplitsOnPreferredLengths)
{
  auto split_with = [](const std::string &measure) {
    auto s = relaxed_ring("", 0.16);
    s->run("group long id 1 5 9\nset group long d_l0 0.3\n"
           "fix refine all dpoly/refine runs yes measure " +
           measure + "\nrun 0 post no");
    return s;
  };
  const double l0 = relaxed_ring("", 0.16)->gather("d_l0", 1)[0];
  ASSERT_LT(l0, 0.24) << "no segment longer than 3 radii before l0 is set";
  EXPECT_EQ(split_with("actual")->natoms(), 16);
  auto preferred = split_with("preferred");
  ASSERT_EQ(preferred->natoms(), 19);
  const std::vector<int> ring = rings_of(*preferred).at(1);
  const std::vector<double> l0s = preferred->gather("d_l0", 1);
  for (size_t k = 0; k < ring.size(); k++) {
    const int id = ring[k], next = ring[(k + 1) % ring.size()];
    const bool split = id == 1 || id == 5 || id == 9;
    if (split) EXPECT_EQ(next, 17 + (id - 1) / 4) << "the new vertex follows vertex " << id;
    EXPECT_NEAR(l0s[id - 1], split || id > 16 ? 0.15 : l0, 1e-12) << "vertex " << id;
  }
}

// measure preferred judges the segments by l0 and acts after growth unless told otherwise: the
// relaxed 16-gon of diameters 0.16 (segments 0.238 < 3 radii 0.24) grows (l0 0.503, 3 radii
// 0.294) and, judged by l0, splits every segment twice (48 vertices, the first piece l0/2)
// before the minimum; judged by l0 before growth, or by length, it splits none.
TEST(RefinePublished, MeasurePreferredSplitsGrownSegmentsAfterGrowth)
{
  auto step = [](const std::string &options) { return grown_and_refined(0.16, options); };
  auto unrefined = step("");
  ASSERT_EQ(unrefined->natoms(), 16);
  const double grown = unrefined->gather("d_l0", 1)[0];
  ASSERT_GT(grown, 1.5 * unrefined->gather("d_sigma", 1)[0]) << "grown l0 above 3 radii";
  auto after = step("measure preferred");
  ASSERT_EQ(after->natoms(), 48);
  EXPECT_NEAR(after->gather("d_l0", 1)[0], 0.5 * grown, 1e-12);
  EXPECT_EQ(step("measure preferred timing before_growth")->natoms(), 16);
}

// rules consistent on the same ring: the published candidates, each split once; halves take
// half of l0 and d_kl; each vertex keeps B = kb lbar and kappa0 = theta0/lbar, lbar the mean l0
// of its two segments; the new vertex takes the mean B and kappa0 of its neighbours.
TEST(RefineConsistent, EachCandidateSplitsOnceAndKeepsTheModulus)
{
  LammpsSession s;
  s.run(hand_made_ring(true) +
        "fix refine all dpoly/refine rules consistent runs yes\n"
        "run 0 post no\nunfix refine");
  EXPECT_EQ(s.natoms(), 16 + 6);
  // lbar 1 -> 0.75 where one of two unit segments splits, 1 -> 0.5 where both do
  const double one = 1.0 / 0.75, both = 2.0;
  expect_ring(s,
              {{5, 5, 1, 1, one, 0, 0.5},
               {6, 5, 0.5, 0.5, one, 0, 0.5},
               {6.5, 5, 0.5, 0.5, 2 * (0.5 * (1 + 1)), 0.5 * 0.5 * (0 + 0), 0.5},
               {7, 5, 0.5, 0.5, both, 0, 0.5},
               {7, 5.5, 0.5, 0.5, 2 * 0.5 * (1 + 2), 0.5 * 0.5 * (0 + 0.3), 0.5},
               {7, 6, 0.5, 0.5, 2 * both, 0.3 / both, 0.5},
               {7, 6.5, 0.5, 0.5, 2 * 0.5 * (2 + 1), 0.5 * 0.5 * (0.3 + 1.0), 0.5},
               {7, 7, 0.5, 0.5, both, 1.0 / both, 0.5},
               {6.5, 7, 0.5, 0.5, 2 * 0.5 * (1 + 1), 0.5 * 0.5 * (1.0 + 0), 0.65},
               {6, 7, 1, 1, one, 0, 0.8},
               {5, 7, 0.5, 0.5, one, 0, 0.8},
               {5, 6.5, 0.5, 0.5, 2 * 0.5 * (1 + 1), 0, 0.65},
               {5, 6, 0.5, 0.5, both, 0, 0.5},
               {5, 5.5, 0.5, 0.5, 2 * 0.5 * (1 + 1), 0, 0.5}});
}

namespace {

// A 16-gon relaxed with a0 = 1.6 (stretched segments) and theta0 = pi/16 (half its curvature),
// refined everywhere 'times' times by 'rules', relaxed again: its energy, the tension of its
// segments and the area term's slope dU/da.
struct RingState {
  double energy, tension, pressure;
  int vertices;
};

RingState refined_relaxed_ring(const std::string &rules, int times)
{
  LammpsSession s;
  s.run(contact_commands(data_file("single_contacts.data")) + STIFFNESS +
        "set group all d_sigma 0.02\nset group all d_a0 1.6\nset group all d_theta0 " +
        std::to_string(PI / 16) +
        "\ncompute vertex all dpoly/vertex\nmin_style cg\nminimize 0.0 1.0e-14 20000 200000\n");
  for (int k = 0; k < times; k++)
    s.run("fix refine all dpoly/refine rules " + rules +
          " runs yes\nrun 0 post no\nunfix refine\nminimize 0.0 1.0e-14 20000 200000");
  s.run("run 1 post no");
  const std::vector<double> length = s.gather("c_vertex", 3), l0 = s.gather("d_l0", 1),
                            kl = s.gather("d_kl", 1);
  double tension = 0.0;    // the mean over the segments of k eps_l (l/l0 - 1)/l0
  for (int i = 0; i < s.natoms(); i++)
    tension += kl[i] * (length[3 * i + 1] / l0[i] - 1.0) / l0[i] / s.natoms();
  const double area = s.thermo("f_cells[2]");
  return {s.thermo("pe"), tension, (area / 1.6 - 1.0) / 1.6, s.natoms()};
}

}    // namespace

// The continuum limit: refined with rules consistent, the relaxed ring keeps its energy,
// tension and pressure to the polygon's discretisation error, which falls as 1/n^2 (measured:
// from 16 to 32 vertices the energy moves by 1.1%, the tension by 1.7%, the pressure by 2.6%;
// from 32 to 64 each by a quarter of that). The published rule (vertex bending stiffness kept,
// theta0 of a new vertex from its neighbours' deviations, long segments split twice) moves the
// energy by 150%, rules tension (series stiffness doubled, theta0 = 0) by 40%.
TEST(RefineConsistent, RelaxedRingTendsToItsContinuumLimit)
{
  // five relaxations of up to 64 vertices: one rank (the rules' rank-independence is tested above)
  if (world_size() > 1) GTEST_SKIP() << "runs on one rank";
  const RingState n16 = refined_relaxed_ring("consistent", 0);
  const RingState n32 = refined_relaxed_ring("consistent", 1);
  const RingState n64 = refined_relaxed_ring("consistent", 2);
  ASSERT_EQ(n32.vertices, 32);
  ASSERT_EQ(n64.vertices, 64);
  auto change = [](double a, double b) {
    return std::fabs(b - a) / std::fabs(a);
  };
  EXPECT_LT(change(n16.energy, n32.energy), 0.02);
  EXPECT_LT(change(n16.tension, n32.tension), 0.03);
  EXPECT_LT(change(n16.pressure, n32.pressure), 0.04);
  // second order: a quarter per doubling (first order would halve it)
  EXPECT_LT(change(n32.energy, n64.energy), 0.35 * change(n16.energy, n32.energy));
  EXPECT_LT(change(n32.tension, n64.tension), 0.35 * change(n16.tension, n32.tension));
  EXPECT_LT(change(n32.pressure, n64.pressure), 0.35 * change(n16.pressure, n32.pressure));

  const RingState published = refined_relaxed_ring("published", 1);
  const RingState tension = refined_relaxed_ring("tension", 1);
  ASSERT_EQ(published.vertices, 48);
  ASSERT_EQ(tension.vertices, 32);
  EXPECT_GT(change(n16.energy, published.energy), 0.1);
  EXPECT_GT(change(n16.energy, tension.energy), 0.1);
}

// At the split itself the polygon stays: the area term, the segment term (each half has the
// segment's strain and half its energy) and each segment's tension are unchanged to round-off.
TEST(RefineConsistent, SplitKeepsAreaSegmentEnergyAndTension)
{
  auto s = relaxed_ring(std::string(STIFFNESS) + "set group all d_a0 1.6", 0.02);
  s->run("run 0 post no");
  const double area_energy = s->thermo("f_cells"), segments = s->thermo("ebond");
  const std::vector<double> length = s->gather("c_vertex", 3), l0 = s->gather("d_l0", 1);
  s->run("fix refine all dpoly/refine rules consistent runs yes\nrun 0 post no\nunfix refine\n"
         "run 0 post no");
  ASSERT_EQ(s->natoms(), 32);
  EXPECT_NEAR(s->thermo("f_cells"), area_energy, 1e-14 * area_energy);
  EXPECT_NEAR(s->thermo("ebond"), segments, 1e-13 * segments);
  const std::vector<double> after = s->gather("c_vertex", 3), l0_after = s->gather("d_l0", 1),
                            kl = s->gather("d_kl", 1);
  for (int i = 0; i < 16; i++) {    // old vertex i: its half, of factor 1/2 and l0/2
    const double was = (length[3 * i + 1] / l0[i] - 1.0) / l0[i];
    EXPECT_NEAR(kl[i] * (after[3 * i + 1] / l0_after[i] - 1.0) / l0_after[i], was, 1e-12);
  }
}

// Rank-independence of the published and consistent rules on an adhesive tissue (junctions,
// void runs, rings across the periodic boundary).
TEST(RefinePublished, SameOnAnyNumberOfRanks)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  for (const char *rules : {"published", "consistent"}) {
    SCOPED_TRACE(rules);
    const std::string commands = contact_commands(data_file("overlapping.data")) + STIFFNESS +
        "set group all d_sigma 0.1\nadhere_cells all 2\nset group all d_sigma 0.05\n"
        "fix refine all dpoly/refine rules " +
        rules + " runs yes\nrun 0\nrun 0\n";
    ParallelAndSerial runs(commands);
    LammpsSession &parallel = runs.parallel, &serial = runs.serial;
    ASSERT_EQ(parallel.natoms(), serial.natoms());
    ASSERT_GT(serial.natoms(), 144);
    for (const char *name : {"x", "d_l0", "d_theta0", "d_sigma", "d_kl", "d_kb"}) {
      const int count = std::string(name) == "x" ? 3 : 1;
      EXPECT_EQ(parallel.gather(name, count), serial.gather(name, count)) << name;
    }
    EXPECT_EQ(parallel.gather_int("molecule", 1), serial.gather_int("molecule", 1));
    EXPECT_NEAR(parallel.thermo("pe"), serial.thermo("pe"), 1e-12 * serial.thermo("pe"));
  }
}

// Across an insertion: a restart file and a data file carry the new vertices with their d_kl
// and d_kb, and the next insertion goes on as if nothing had happened.
TEST(RefinePublished, RestartAndDataFileAcrossAnInsertion)
{
  const std::string restart = scratch("published.restart"), data = scratch("published.data");
  const std::string refine = "fix refine all dpoly/refine rules published cap 4 runs yes\n";
  auto first = relaxed_ring(std::string(STIFFNESS) + refine, 0.02);
  ASSERT_EQ(first->natoms(), 48);
  first->run("write_restart " + restart + "\nwrite_data " + data + " nocoeff");

  LammpsSession restarted;
  restarted.run(resume_commands(restart) + "fix Stiffness all property/atom d_kl d_kb ghost yes\n" +
                refine);
  std::string read = contact_commands(data);
  read.replace(read.find("read_data"), 0, "fix Stiffness all property/atom d_kl d_kb ghost yes\n");
  read.replace(read.find(" fix Vertices NULL Vertices"), 0, " fix Stiffness NULL Stiffness");
  LammpsSession reread;
  reread.run(read);
  for (LammpsSession *after : {&restarted, &reread}) {
    EXPECT_EQ(after->natoms(), 48);
    for (const char *name : {"x", "d_l0", "d_theta0", "d_sigma", "d_kl", "d_kb"}) {
      const int count = std::string(name) == "x" ? 3 : 1;
      EXPECT_EQ(after->gather(name, count), first->gather(name, count)) << name;
    }
  }

  // one more insertion each (the data file does not hold the fix's counts: it starts anew)
  first->run("run 0");
  restarted.run("run 0");
  EXPECT_EQ(restarted.thermo("f_refine[2]"), first->thermo("f_refine[2]"));
  for (const char *name : {"x", "d_l0", "d_theta0", "d_kl", "d_kb"}) {
    const int count = std::string(name) == "x" ? 3 : 1;
    EXPECT_EQ(restarted.gather(name, count), first->gather(name, count)) << name;
  }
  if (world_size() == 1) remove(restart.c_str());
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
  EXPECT_THAT(error_of("fix r all dpoly/refine rules code"),
              HasSubstr("rules must be 'tension', 'published' or 'consistent', got 'code'"));
  EXPECT_THAT(error_of("fix r all dpoly/refine rules published void no"),
              HasSubstr("void applies to rules tension"));
  EXPECT_THAT(error_of("fix r all dpoly/refine start 0"), HasSubstr("start must be >= 1, got 0"));
  EXPECT_THAT(error_of("fix r all dpoly/refine timing early"),
              HasSubstr("timing must be 'before_growth' or 'after_growth'"));
  EXPECT_THAT(error_of("fix r all dpoly/refine measure l0"),
              HasSubstr("measure must be 'actual' or 'preferred', got 'l0'"));
  EXPECT_THAT(error_of("fix r all dpoly/refine rules published"), HasSubstr("define d_kl with"));
  EXPECT_THAT(error_of("fix s all property/atom d_kl ghost yes\nset group all d_kl 1.0\n"
                       "fix r all dpoly/refine rules consistent"),
              HasSubstr("define d_kl and d_kb"));
  LammpsSession s;
  std::string cmds = contact_commands(data_file("single_contacts.data"));
  cmds.replace(cmds.find("fix cells all dpoly/cells eps_a 1.0\n"), 36, "");
  cmds.replace(cmds.find(" f_cells"), 8, "");
  const std::string msg = s.try_run(cmds + "fix r all dpoly/refine\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("needs fix dpoly/cells"));
}
