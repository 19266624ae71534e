// Growth of 3d cells, fix mesophyll3d/grow (doc/Howto_polyhedra.rst, section "Growth"), on cells
// whose growth is known by hand: a regular icosahedron (every vertex void-facing: every edge
// grows alike, theta0 drifts alike, smoothing leaves it so), one edge's theta0 set apart (the
// smoothing moves it and exactly its four neighbours), v0 and sigma; adhesive cells, whose
// bonded vertices do not grow; restart across a growth step; 1 against several ranks; the void
// patches of a hand-made surface graph; bad input.
#include "test_helpers.h"

#include "dpoly3d_void_patches.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using ::testing::HasSubstr;

using namespace test;

namespace {

const int COLUMNS = 6;    // i2_edge, d2_edge_l0, d2_edge_theta0 columns

// one growth step after a zero-step run (the stage acts after MD runs with 'runs yes')
const char *GROW_ONCE = "run 0 post no\n";

struct EdgeState {
  std::vector<int> partner;
  std::vector<double> l0, theta0, v0, sigma;
};

EdgeState state_of(LammpsSession &s)
{
  return {s.gather_int("i2_edge", COLUMNS), s.gather("d2_edge_l0", COLUMNS),
          s.gather("d2_edge_theta0", COLUMNS), s.gather("d_v0", 1), s.gather("d_sigma", 1)};
}

// A regular icosahedron of circumradius 1: edge a, volume V, 30 edges of total length 30 a.
const double EDGE = 1.0 / sin(2.0 * PI / 5.0);
const double VOLUME = 5.0 / 12.0 * (3.0 + sqrt(5.0)) * EDGE * EDGE * EDGE;

// dl_std / E of the icosahedron: (L/V) delta_V / 3 over E = 30 edges
double isometric_edge_growth(double delta_volume)
{
  return 30.0 * EDGE / VOLUME * delta_volume / 3.0 / 30.0;
}

}    // namespace

// No adhesion: every vertex faces air, one patch per cell (the whole surface, so the c_L term
// vanishes): every edge grows by 2 lambda (1 - c_L) dl_std/E, every theta0 drops by
// c_B dl_std/E, v0 by delta_V, sigma by cbrt(v0'/v0).
TEST(Growth3d, IcosahedronGrowsEveryEdgeAlike)
{
  LammpsSession s;
  s.run(polyhedra_commands(data_file("icosahedron.data")));
  const EdgeState before = state_of(s);
  const double delta_volume = 0.3, lambda = 3.0, c_length = 0.25, c_bending = 2.0;
  s.run("fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.3 lambda 3 c_L 0.25 c_B 2 "
        "theta0_min -1\n" +
        std::string(GROW_ONCE));
  const EdgeState after = state_of(s);
  const double step = isometric_edge_growth(delta_volume);
  int edges = 0;
  for (size_t k = 0; k < before.partner.size(); k++) {
    if (before.partner[k] == 0) continue;
    edges++;
    EXPECT_NEAR(after.l0[k] - before.l0[k], 2.0 * lambda * (1.0 - c_length) * step, 1.0e-12);
    EXPECT_NEAR(after.theta0[k] - before.theta0[k], -c_bending * step, 1.0e-12);
  }
  EXPECT_EQ(edges, 30);
  for (size_t i = 0; i < before.v0.size(); i++) {
    EXPECT_DOUBLE_EQ(after.v0[i], before.v0[i] + delta_volume);
    EXPECT_DOUBLE_EQ(after.sigma[i],
                     before.sigma[i] * cbrt((before.v0[i] + delta_volume) / before.v0[i]));
  }
  EXPECT_EQ(s.thermo("f_grow[1]"), 1.0);     // growth steps
  EXPECT_EQ(s.thermo("f_grow[2]"), 12.0);    // void-facing vertices
  EXPECT_EQ(s.thermo("f_grow[3]"), 30.0);    // void-facing edges
  // the hub reads the new v0 when the next run starts: U = (eps_v/2)(V/v0' - 1)^2
  s.run("unfix grow\nrun 0 post no");
  const double strain = VOLUME / (before.v0[0] + delta_volume) - 1.0;
  EXPECT_NEAR(s.thermo("f_cells"), 0.5 * strain * strain, 1.0e-12);
}

// The stage acts after every minimization, after MD runs only with 'runs yes'.
TEST(Growth3d, GrowsAfterMinimizations)
{
  LammpsSession s;
  s.run(polyhedra_commands(data_file("icosahedron.data")));
  const EdgeState before = state_of(s);
  s.run("fix grow all mesophyll3d/grow box fixed delta_V 0.5\nrun 0 post no");
  EXPECT_EQ(state_of(s).v0, before.v0);
  EXPECT_EQ(s.thermo("f_grow[1]"), 0.0);
  s.run("min_style fire\nminimize 0 0 1 1");
  EXPECT_DOUBLE_EQ(state_of(s).v0[0], before.v0[0] + 0.5);
  EXPECT_EQ(s.thermo("f_grow[1]"), 1.0);
}

// defined after a first run and reached by 'run N pre no', which skips init(): the fix takes the
// hub and the state from the hub that attaches it (was a null dereference)
TEST(Growth3d, GrowsWhenARunSkipsInit)
{
  LammpsSession s;
  s.run(polyhedra_commands(data_file("icosahedron.data")) + "run 0 post no");
  const EdgeState before = state_of(s);
  s.run("fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.5\nrun 0 pre no post no");
  EXPECT_DOUBLE_EQ(state_of(s).v0[0], before.v0[0] + 0.5);
  EXPECT_EQ(s.thermo("f_grow[1]"), 1.0);
}

namespace {
// The icosahedron moved so that a vertex lies 0.014 inside each processor boundary through the
// box centre (x, y or z = 2, however the ranks split the box), with v0 = 1.5 V and soft edges:
// relaxing, it swells, those vertices cross to the next rank's subdomain (by 0.047), and the
// skin of 1 keeps the minimizer from re-neighbouring, so the atoms migrate only when the growth
// stage brings the ghosts up to date after the minimum.
std::string swelling_icosahedron(bool grow)
{
  return polyhedra_commands(data_file("icosahedron.data")) +
      "neighbor 1.0 bin\nbond_coeff * 0.05\ndisplace_atoms all move 0.54 0.54 0.54 units box\n"
      "set group all d_v0 3.8\nthermo_style custom step pe fnorm fmax\nmin_style fire\n" +
      (grow ? "fix grow all mesophyll3d/grow box fixed delta_V 0.1\n" : "") +
      "minimize 0.0 1.0e-8 10000 100000\n";
}
}    // namespace

// After the stages, atom->f (thermo fnorm and fmax, the minimizer's final force norm, a dump's
// fx) still holds the minimum's forces, each on its own atom: LAMMPS migrates no forces, so the
// stage's re-neighbouring used to leave other atoms' forces, or none, on several ranks (the
// same minimization without a stage is the reference: stages act only after it).
TEST(Growth3d, ForcesAfterTheStagesAreTheMinimums)
{
  LammpsSession grown, plain;
  grown.run(swelling_icosahedron(true));
  plain.run(swelling_icosahedron(false));
  ASSERT_EQ(grown.thermo("f_grow[1]"), 1.0) << "the stage acted";
  const std::vector<double> f_grown = grown.gather("f", 3), f_plain = plain.gather("f", 3);
  EXPECT_EQ(f_grown, f_plain);
  // the same forces, summed in another order where atoms migrated
  EXPECT_NEAR(grown.thermo("fnorm"), plain.thermo("fnorm"), 1.0e-12 * plain.thermo("fnorm"));
  EXPECT_EQ(grown.thermo("fmax"), plain.thermo("fmax"));
  EXPECT_LT(plain.thermo("fnorm"), 1.0e-7) << "converged on ftol";
}

TEST(Growth3d, ThetaZeroStopsAtItsBound)
{
  LammpsSession s;
  s.run(polyhedra_commands(data_file("icosahedron.data")));
  const EdgeState before = state_of(s);
  // the drift c_B dl_std/E = 4 x 0.0691... would take theta0 from 0.7297 to about 0.45
  s.run("fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.5 theta0_min 0.6\n" +
        std::string(GROW_ONCE));
  ASSERT_GT(4.0 * isometric_edge_growth(0.5), before.theta0[0] - 0.6);
  const EdgeState after = state_of(s);
  for (size_t k = 0; k < before.partner.size(); k++)
    if (before.partner[k]) EXPECT_NEAR(after.theta0[k], 0.6, 1.0e-12);
  // lambda 0: the void edges keep their l0
  s.run("unfix grow\nfix grow all mesophyll3d/grow runs yes box fixed delta_V 0.5 lambda 0\n" +
        std::string(GROW_ONCE));
  const EdgeState again = state_of(s);
  EXPECT_EQ(again.l0, after.l0);
}

// One edge's theta0 apart from the others' and no drift (c_B 0): smoothing moves that edge by
// 2 (dl_std/E)(theta_n - theta_e) (four neighbours, weight 2/4 each) and each of the four edges
// of its two faces by (dl_std/E)(2/4)(theta_e - theta_n); every other edge keeps its theta0.
TEST(Growth3d, SmoothingReachesTheFourEdgesOfTheTwoFaces)
{
  LammpsSession s;
  s.run(polyhedra_commands(data_file("icosahedron.data")));
  EdgeState before = state_of(s);
  const int lo = 1, hi = before.partner[0];    // vertex 1's first edge
  ASSERT_GT(hi, lo);
  const double others = before.theta0[0], odd = others - 0.3;
  before.theta0[0] = odd;
  s.scatter("d2_edge_theta0", COLUMNS, before.theta0);
  s.run("fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.5 c_B 0\n" +
        std::string(GROW_ONCE));
  const EdgeState after = state_of(s);
  const double step = isometric_edge_growth(0.5);

  // the wing vertices: the two common neighbours of vertices lo and hi
  std::vector<std::set<int>> neighbours(13);
  for (size_t k = 0; k < before.partner.size(); k++)
    if (before.partner[k]) {
      const int i = (int) (k / COLUMNS) + 1, j = before.partner[k];
      neighbours[i].insert(j);
      neighbours[j].insert(i);
    }
  std::set<int> wings;
  for (int w : neighbours[lo])
    if (neighbours[hi].count(w)) wings.insert(w);
  ASSERT_EQ(wings.size(), 2u);

  int moved = 0;
  for (size_t k = 0; k < before.partner.size(); k++) {
    if (!before.partner[k]) continue;
    const int i = (int) (k / COLUMNS) + 1, j = before.partner[k];
    const bool neighbour = (wings.count(i) && (j == lo || j == hi)) ||
        (wings.count(j) && (i == lo || i == hi));
    if (k == 0)
      EXPECT_NEAR(after.theta0[k], odd + 2.0 * step * (others - odd), 1.0e-12);
    else if (neighbour) {
      EXPECT_NEAR(after.theta0[k], others + 0.5 * step * (odd - others), 1.0e-12);
      moved++;
    } else
      EXPECT_NEAR(after.theta0[k], others, 1.0e-12) << i << "-" << j;
  }
  EXPECT_EQ(moved, 4);
}

namespace {
std::string jittered_cells()
{
  return polyhedra_commands(data_file("cells3d_deformed.data")) +
      "displace_atoms all random 0.04 0.04 0.04 4711 units box\n";
}
const char *GROW_JITTERED = "fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.4\n";
}    // namespace

// Per-edge l0 and theta0, v0, sigma and the step count survive a restart written between two
// growth steps: the second step gives the same values with and without it.
TEST(Growth3d, RestartAcrossAGrowthStep)
{
  const std::string restart = scratch("grow3d.restart");
  LammpsSession straight;
  straight.run(jittered_cells() + GROW_JITTERED + GROW_ONCE + "write_restart " + restart + "\n" +
               GROW_ONCE);
  LammpsSession resumed;
  resumed.run("read_restart " + restart +
              "\nfix Vertices all property/atom d_sigma d_v0 ghost yes\n"
              "fix Edges all property/atom i2_edge 6 ghost yes\n"
              "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
              "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n"
              "comm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v 1.0\n" +
              GROW_JITTERED + GROW_ONCE);
  const EdgeState a = state_of(straight), b = state_of(resumed);
  EXPECT_EQ(a.l0, b.l0);
  EXPECT_EQ(a.theta0, b.theta0);
  EXPECT_EQ(a.v0, b.v0);
  EXPECT_EQ(a.sigma, b.sigma);
  EXPECT_EQ(resumed.thermo("f_grow[1]"), 2.0);
  // the second step changed something, so the comparison is not of two untouched states
  LammpsSession once;
  once.run(jittered_cells() + GROW_JITTERED + GROW_ONCE);
  EXPECT_NE(state_of(once).l0, a.l0);
  if (world_size() == 1) remove(restart.c_str());
}

// Two growth steps of jittered cells across the periodic boundary on all ranks and on this
// rank alone: the same per-edge values (the volumes are summed over ranks in another order).
TEST(Growth3d, ParallelGrowthMatchesSerial)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  ParallelAndSerial runs(jittered_cells() + GROW_JITTERED + GROW_ONCE + GROW_ONCE);
  const EdgeState p = state_of(runs.parallel), s = state_of(runs.serial);
  ASSERT_EQ(p.partner, s.partner);
  double largest = 0.0;
  for (size_t k = 0; k < p.l0.size(); k++) {
    largest = std::max(largest, std::fabs(p.l0[k] - s.l0[k]));
    largest = std::max(largest, std::fabs(p.theta0[k] - s.theta0[k]));
  }
  EXPECT_LT(largest, 1.0e-13);
  EXPECT_EQ(p.v0, s.v0);
  EXPECT_EQ(p.sigma, s.sigma);
}

namespace {
// Three jittered 42-vertex cells that touch (tests/make_test_data3d.py), bonded where their
// vertex spheres overlap (adhere_cells): the vertices with adhesive bonds do not face air.
std::string adhesive_cells()
{
  return "units lj\ndimension 3\natom_style molecular\natom_modify map array\nboundary p p p\n"
         "fix Vertices all property/atom d_sigma d_v0 ghost yes\n"
         "fix Edges all property/atom i2_edge 6 ghost yes\n"
         "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
         "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n"
         "bond_style hybrid dpoly3d/edge mesophyll/adhesion z bonds\n"
         "angle_style zero\ndihedral_style dpoly3d/hinge\nread_data " +
      data_file("cells3d_adhesive.data") +
      " fix Vertices NULL Vertices fix Edges NULL Edges fix EdgeLengths NULL EdgeLengths fix "
      "EdgeAngles NULL EdgeAngles extra/bond/types 1 extra/bond/per/atom 12 "
      "extra/special/per/atom 40\n"
      "bond_coeff 1 dpoly3d/edge 1.0\nbond_coeff 2 mesophyll/adhesion 0.8\nangle_coeff *\n"
      "dihedral_coeff * 0.4\nspecial_bonds lj 1.0 1.0 1.0\npair_style dpoly3d/contact\n"
      "pair_coeff * * 1.0\ncomm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v 1.0\n"
      "thermo_modify norm no\nadhere_cells all 2\nrun 0 post no\n";
}

// the atoms with an adhesive bond (type 2), from a data file the session writes
std::set<int> bonded_vertices(LammpsSession &s)
{
  const std::string path = scratch("grow3d_bonds.data");
  s.run("write_data " + path);
  std::ifstream in(path);
  std::set<int> bonded;
  bool bonds = false;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && std::isalpha((unsigned char) line[0])) {
      bonds = line.rfind("Bonds", 0) == 0;
      continue;
    }
    std::istringstream words(line);
    int id, type, a, b;
    if (bonds && (words >> id >> type >> a >> b) && type == 2) bonded.insert({a, b});
  }
  return bonded;
}
}    // namespace

// With c_L 0 every void-facing vertex gets the same dl = lambda dl_std/E of its cell, so within a
// cell an edge grows by dl times the number of its void-facing ends: 0 between two bonded
// vertices, dl with one bonded end, 2 dl between two void-facing ones. With c_L 0.5 the
// patch term changes dl from patch to patch, but an edge between bonded vertices still keeps
// its l0.
TEST(Growth3d, BondedVerticesDoNotGrow)
{
  LammpsSession s;
  s.run(adhesive_cells());
  const std::set<int> bonded = bonded_vertices(s);
  ASSERT_FALSE(bonded.empty());
  const EdgeState before = state_of(s);
  const std::vector<int> cell = s.gather_int("molecule", 1);
  s.run("fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.4 c_L 0\n" +
        std::string(GROW_ONCE));
  const EdgeState after = state_of(s);
  EXPECT_EQ(s.thermo("f_grow[2]"), (double) (before.v0.size() - bonded.size()));
  std::map<int, double> per_void_end;    // cell -> dl
  std::map<int, int> counted;            // number of void ends -> edges
  for (size_t k = 0; k < before.partner.size(); k++) {
    if (!before.partner[k]) continue;
    const int i = (int) (k / COLUMNS) + 1, j = before.partner[k];
    const int void_ends = (int) !bonded.count(i) + (int) !bonded.count(j);
    const double growth = after.l0[k] - before.l0[k];
    counted[void_ends]++;
    if (void_ends == 0) {
      EXPECT_EQ(growth, 0.0) << i << "-" << j;
      continue;
    }
    const int c = cell[i - 1];
    if (!per_void_end.count(c)) per_void_end[c] = growth / void_ends;
    EXPECT_NEAR(growth, void_ends * per_void_end[c], 1.0e-12 * per_void_end[c]) << i << "-" << j;
  }
  for (int ends : {0, 1, 2}) EXPECT_GT(counted[ends], 0) << ends << " void-facing ends";
  for (const auto &c : per_void_end) EXPECT_GT(c.second, 0.0);

  // the default c_L: patch sizes differ, edges between bonded vertices still do not grow
  LammpsSession patches;
  patches.run(adhesive_cells() + "fix grow all mesophyll3d/grow runs yes box fixed delta_V 0.4\n" +
              GROW_ONCE);
  const EdgeState grown = state_of(patches);
  for (size_t k = 0; k < before.partner.size(); k++)
    if (before.partner[k] && bonded.count((int) (k / COLUMNS) + 1) &&
        bonded.count(before.partner[k]))
      EXPECT_EQ(grown.l0[k], before.l0[k]);
  if (world_size() == 1) remove(scratch("grow3d_bonds.data").c_str());
}

// Patches on a hand-made graph: cell 1 has vertices 1-6 in a ring of edges, 1, 2 and 5
// void-facing (areas 1, 2, 4): patches {1, 2} and {5}; cell 2 one void vertex 7.
TEST(Growth3d, VoidPatchesAreJoinedByVoidEdgesOnly)
{
  for (bool reversed : {false, true}) {
    LAMMPS_NS::DPoly3d::VoidPatches patches;
    patches.add_vertex(5, 1, 4.0);
    patches.add_vertex(1, 1, 1.0);
    patches.add_vertex(2, 1, 2.0);
    patches.add_vertex(7, 2, 0.5);
    const int ring[][2] = {{1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 1}};
    for (int e = 0; e < 6; e++) {
      const auto &edge = ring[reversed ? 5 - e : e];
      patches.add_edge(reversed ? edge[1] : edge[0], reversed ? edge[0] : edge[1]);
    }
    EXPECT_EQ(patches.patch_area(1), 3.0);
    EXPECT_EQ(patches.patch_area(2), 3.0);
    EXPECT_EQ(patches.patch_area(5), 4.0);
    EXPECT_EQ(patches.patch_area(3), 0.0);    // bonded: in no patch
    EXPECT_EQ(patches.patches(1), 2);
    EXPECT_EQ(patches.mean_patch_area(1), 3.5);
    EXPECT_EQ(patches.patches(2), 1);
    EXPECT_EQ(patches.mean_patch_area(2), 0.5);
    // an edge between two void vertices joins their patches
    patches.add_edge(1, 5);
    EXPECT_EQ(patches.patch_area(2), 7.0);
    EXPECT_EQ(patches.patches(1), 1);
  }
}

class BadGrowth3d : public ErrorTest {};

TEST_F(BadGrowth3d, ArgumentsAndSetUp)
{
  const std::string base = polyhedra_commands(data_file("icosahedron.data"));
  const char *grow = "fix grow all mesophyll3d/grow runs yes box fixed ";
  expect_errors(
      base,
      {{std::string(grow) + "\n", "Fix mesophyll3d/grow needs delta_V"},
       {std::string(grow) + "delta_V -1\n", "delta_V must be finite and >= 0, got -1"},
       {std::string(grow) + "delta_V 0.1 lambda -1\n",
        "Fix mesophyll3d/grow lambda must be >= 0, got -1"},
       {std::string(grow) + "delta_V 0.1 c_L 2\n",
        "Fix mesophyll3d/grow c_L must be in [0, 1], got 2"},
       // in 3d theta0 is an edge's bending angle (a turning angle is a 2d ring's)
       {std::string(grow) + "delta_V 0.1 theta0_min 4\n",
        "Fix mesophyll3d/grow theta0_min must be a bending angle between the faces' outward "
        "normals (0 = flat) in (-pi, pi] radians (the lower bound of theta0 at void-facing "
        "edges; the default is -pi/10), got 4"},
       // 1e400 would be inf: LAMMPS's reader (utils::numeric) refuses it, naming the value
       {std::string(grow) + "delta_V 1e400\n",
        "Floating point number 1e400 in input script or data file is out of range"},
       {std::string(grow) + "delta_V 0.1 lambda 1e400\n",
        "Floating point number 1e400 in input script or data file is out of range"},
       {std::string(grow) + "delta_V 0.1 c_L -1e400\n",
        "Floating point number -1e400 in input script or data file is out of range"},
       {std::string(grow) + "delta_V 0.1 c_B 1e400\n",
        "Floating point number 1e400 in input script or data file is out of range"},
       {std::string(grow) + "delta_V 0.1 theta0_min -1e400\n",
        "Floating point number -1e400 in input script or data file is out of range"},
       {std::string(grow) + "delta_V 0.1 box free\n",
        "Fix mesophyll3d/grow box must be 'relax' or 'fixed', got 'free'"},
       {std::string(grow) + "delta_V 0.1 speed 2\n", "Unknown fix mesophyll3d/grow keyword: speed"},
       {std::string(grow) + "delta_V\n", "fix mesophyll3d/grow delta_V"},
       {"fix grow all mesophyll3d/grow delta_V 0.1\nrun 0 post no\n",
        "Fix mesophyll3d/grow grow needs fix box/relax"},
       {"group one id 1\nfix grow one mesophyll3d/grow runs yes box fixed delta_V "
        "0.1\nrun 0 post no\n",
        "Fix mesophyll3d/grow grow is defined on group one, but fix dpoly3d/cells "
        "cells keeps the cells of group all"},
       {"unfix cells\n" + std::string(grow) + "delta_V 0.1\nrun 0 post no\n",
        "Fix mesophyll3d/grow grows polyhedra: it needs fix dpoly3d/cells"},
       // the hub's internal force store, unfixed by hand: a minimum with a stage stops, naming
       // it (the hub kept a pointer to it and crashed)
       {"unfix cells_RUN_FORCES\n" + std::string(grow) + "delta_V 0.1\nminimize 0 0 1 1\n",
        "Internal fix cells_RUN_FORCES (the forces stages keep with their atoms) is gone"}});
}
