// Adhesion between deformable polyhedra (3d cells, fix dpoly3d/cells): adhere_cells, bond_style
// mesophyll/adhesion and fix mesophyll/break with the 3d hub. Every test runs on any number of
// ranks unless it says otherwise; ctest runs this binary on 1, 2 and 4.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using ::testing::HasSubstr;

using namespace test;

namespace {

const int EDGE_SLOTS = 6;
using Bond = std::pair<int, int>;    // (smaller atom ID, larger atom ID)

// Three jittered 42-vertex cells, the first touching the other two (across the periodic boundary
// too): edges of type 1, adhesive bonds of type 2, with the given z rule.
std::string adhesive_cells_commands(const std::string &rule = "bonds",
                                    const std::string &newton_bond = "on")
{
  return "units lj\ndimension 3\natom_style molecular\natom_modify map array\n"
         "boundary p p p\nnewton on " +
      newton_bond +
      "\n"
      "fix Vertices all property/atom d_sigma d_v0 ghost yes\n"
      "fix Edges all property/atom i2_edge 6 ghost yes\n"
      "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
      "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n"
      "bond_style hybrid dpoly3d/edge mesophyll/adhesion z " +
      rule +
      "\nangle_style zero\ndihedral_style dpoly3d/hinge\n"
      "read_data " +
      data_file("cells3d_adhesive.data") +
      " fix Vertices NULL Vertices fix Edges NULL Edges fix EdgeLengths NULL EdgeLengths"
      " fix EdgeAngles NULL EdgeAngles extra/bond/types 1 extra/bond/per/atom 12"
      " extra/special/per/atom 40\n"
      "bond_coeff 1 dpoly3d/edge 1.0\nbond_coeff 2 mesophyll/adhesion 0.8\n"
      "angle_coeff *\ndihedral_coeff * 0.4\n"
      "special_bonds lj 1.0 1.0 1.0\npair_style dpoly3d/contact\npair_coeff * * 1.0\n"
      "comm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v 1.0\n"
      "compute bonds all bond\n"
      "thermo_style custom step pe evdwl ebond edihed f_cells c_bonds[2] press bonds\n"
      "thermo_modify norm no\n";
}

// Bond the overlaps, then pull cells 2 (+x of cell 1) and 3 (+y of it) away from cell 1 and move
// every vertex (random, from the seed and each atom's position, so the same on any number of
// ranks): most adhesive bonds are stretched.
const char *ADHERE_AND_STRETCH = "adhere_cells all 2\n"
                                 "group second molecule 2\ngroup third molecule 3\n"
                                 "displace_atoms second move 0.15 0.0 0.0 units box\n"
                                 "displace_atoms third move 0.0 0.12 0.0 units box\n"
                                 "displace_atoms all random 0.03 0.03 0.03 4711 units box\n"
                                 "run 0 post no\n";

std::unique_ptr<LammpsSession> stretched_cells(const std::string &rule = "bonds",
                                               const std::string &newton_bond = "on",
                                               MPI_Comm comm = MPI_COMM_WORLD)
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(adhesive_cells_commands(rule, newton_bond));
  s->run(ADHERE_AND_STRETCH);
  return s;
}

// The adhesive bonds (type 2) of a data file written by write_data.
std::set<Bond> adhesive_bonds_in(const std::string &path)
{
  std::ifstream in(path);
  std::string line;
  std::set<Bond> bonds;
  bool in_bonds = false;
  while (std::getline(in, line)) {
    if (!line.empty() && std::isalpha((unsigned char) line[0])) {
      in_bonds = line.rfind("Bonds", 0) == 0;
      continue;
    }
    std::istringstream words(line);
    int id, type, a, b;
    if (in_bonds && (words >> id >> type >> a >> b) && type == 2)
      bonds.insert({std::min(a, b), std::max(a, b)});
  }
  return bonds;
}

std::set<Bond> adhesive_bonds(LammpsSession &s, const std::string &name)
{
  const std::string path = scratch(name);
  s.run("write_data " + path);
  return adhesive_bonds_in(path);
}

// What the test knows of the system, gathered in atom-ID order.
struct Snapshot {
  std::vector<double> x, sigma;
  std::vector<int> molecule;
  double box[3];
  explicit Snapshot(LammpsSession &s) :
      x(s.gather("x", 3)), sigma(s.gather("d_sigma", 1)), molecule(s.gather_int("molecule", 1)),
      box{s.equal_variable("lx"), s.equal_variable("ly"), s.equal_variable("lz")}
  {
  }
  int natoms() const { return (int) sigma.size(); }
  // nearest-image distance of atoms with IDs a and b
  double distance(int a, int b) const
  {
    double rsq = 0.0;
    for (int d = 0; d < 3; d++) {
      double dx = x[3 * (a - 1) + d] - x[3 * (b - 1) + d];
      dx -= box[d] * std::round(dx / box[d]);
      rsq += dx * dx;
    }
    return std::sqrt(rsq);
  }
  double contact(int a, int b) const { return 0.5 * (sigma[a - 1] + sigma[b - 1]); }
  int cell(int a) const { return molecule[a - 1]; }
};

}    // namespace

// adhere_cells bonds exactly the overlapping pairs (3d distance, nearest image) of different
// cells, and the three cells have different numbers of bonds.
TEST(Adhesion3d, AdhereBondsTheOverlapsOfDifferentCells)
{
  LammpsSession s;
  s.run(adhesive_cells_commands() + "run 0 post no");
  const Snapshot snap(s);
  std::set<Bond> expected;
  std::map<int, int> per_cell;
  for (int a = 1; a <= snap.natoms(); a++)
    for (int b = a + 1; b <= snap.natoms(); b++)
      if (snap.cell(a) != snap.cell(b) && snap.distance(a, b) < snap.contact(a, b)) {
        expected.insert({a, b});
        per_cell[snap.cell(a)]++;
        per_cell[snap.cell(b)]++;
      }
  ASSERT_EQ(per_cell.size(), 3u) << "every cell should touch another";
  ASSERT_NE(per_cell[1], per_cell[2]);
  ASSERT_NE(per_cell[2], per_cell[3]);

  s.run("adhere_cells all 2\nrun 0 post no");
  EXPECT_EQ(adhesive_bonds(s, "adhered3d.data"), expected);
  // all in contact or overlapping: no adhesive force yet
  EXPECT_EQ(s.thermo("c_bonds[2]"), 0.0);
}

// U = sum over stretched bonds of eps_c/(2 z)(1 - r/s)^2, z = (z_mu + z_nu)/2 + 1, z_mu counted
// per cell in 3d: its adhesive bonds (z bonds) or the distinct cells bonded to it (z cells).
TEST(Adhesion3d, EnergyCountsContactsPerCell)
{
  for (const std::string rule : {"bonds", "cells"}) {
    auto s = stretched_cells(rule);
    const std::set<Bond> bonds = adhesive_bonds(*s, "stretched3d.data");
    const Snapshot snap(*s);
    std::map<int, int> cell_bonds;
    std::map<int, std::set<int>> partners;
    for (const Bond &b : bonds) {
      const int c1 = snap.cell(b.first), c2 = snap.cell(b.second);
      cell_bonds[c1]++;
      cell_bonds[c2]++;
      partners[c1].insert(c2);
      partners[c2].insert(c1);
    }
    auto z_of = [&](int cell) {
      return rule == "bonds" ? (double) cell_bonds[cell] : (double) partners[cell].size();
    };
    double energy = 0.0;
    int stretched = 0;
    for (const Bond &b : bonds) {
      const double r = snap.distance(b.first, b.second), sc = snap.contact(b.first, b.second);
      if (r <= sc) continue;
      stretched++;
      const double z = 0.5 * (z_of(snap.cell(b.first)) + z_of(snap.cell(b.second))) + 1.0;
      energy += 0.8 / (2.0 * z) * std::pow(1.0 - r / sc, 2);
    }
    ASSERT_GT(stretched, 10) << "the widened box should stretch bonds";
    EXPECT_NEAR(s->thermo("c_bonds[2]"), energy, 1.0e-12 * energy) << "z " << rule;
  }
}

// one rank: forces of every term (edges, hinges, volume, contacts, adhesion) against central
// differences; AdhesionPressureAndRanks compares several ranks with one
TEST(Adhesion3d, ForcesMatchFiniteDifferences)
{
  if (world_size() > 1) GTEST_SKIP() << "checked on one rank, compared across ranks below";
  for (const std::string newton_bond : {"on", "off"}) {
    auto s = stretched_cells("bonds", newton_bond);
    ASSERT_GT(s->thermo("c_bonds[2]"), 1.0e-4);
    EXPECT_LT(finite_difference_error_3d(*s), 1.0e-7) << "newton_bond " << newton_bond;
  }
}

TEST(Adhesion3d, AdhesionPressureAndRanks)
{
  auto on = stretched_cells("bonds", "on");
  auto off = stretched_cells("bonds", "off");
  EXPECT_NEAR(on->thermo("c_bonds[2]"), off->thermo("c_bonds[2]"),
              1.0e-13 * on->thermo("c_bonds[2]"));
  EXPECT_NEAR(on->thermo("press"), off->thermo("press"), 1.0e-12 * std::fabs(on->thermo("press")));
  EXPECT_LT(relative_force_error(on->gather("f", 3), off->gather("f", 3)), 1.0e-13);

  // the pressure is -dU/dV under a finite isotropic deformation of the box
  const double volume = on->equal_variable("vol");
  const double e = 1.0e-5;
  const double iso = -(energy_after_scaling_3d(*on, 1 + e, 1 + e, 1 + e) -
                       energy_after_scaling_3d(*on, 1 - e, 1 - e, 1 - e)) /
      (volume * (std::pow(1 + e, 3) - std::pow(1 - e, 3)));
  ASSERT_GT(std::fabs(iso), 1.0e-4);
  EXPECT_NEAR(on->thermo("press"), iso, 1.0e-7 * std::fabs(iso));

  if (world_size() > 1) {
    auto serial = stretched_cells("bonds", "on", self_comm());
    for (const char *keyword : {"pe", "c_bonds[2]", "press"})
      EXPECT_NEAR(on->thermo(keyword), serial->thermo(keyword),
                  1.0e-12 * std::max(1.0, std::fabs(serial->thermo(keyword))))
          << keyword;
    EXPECT_LT(relative_force_error(serial->gather("f", 3), on->gather("f", 3)), 1.0e-12);
  }
}

// With a huge beta only the threshold breaks bonds: exactly those stretched to r/s >= r*/s go,
// whatever their contact numbers, and the counts follow.
TEST(Adhesion3d, BreakingTakesTheBondsStretchedPastTheThreshold)
{
  auto s = stretched_cells();
  const std::set<Bond> before = adhesive_bonds(*s, "break_before3d.data");
  const Snapshot snap(*s);
  std::vector<double> stretch;
  for (const Bond &b : before)
    stretch.push_back(snap.distance(b.first, b.second) / snap.contact(b.first, b.second));
  std::vector<double> sorted = stretch;
  std::sort(sorted.begin(), sorted.end());
  // a threshold halfway between two stretches, in the upper half of the stretched bonds
  const size_t k = sorted.size() - sorted.size() / 4;
  ASSERT_GT(sorted[k - 1], 1.0);
  ASSERT_GT(sorted[k] - sorted[k - 1], 1.0e-6);
  const double threshold = 0.5 * (sorted[k - 1] + sorted[k]);
  std::set<Bond> kept;
  size_t n = 0;
  for (const Bond &b : before)
    if (stretch[n++] < threshold) kept.insert(b);
  ASSERT_LT(kept.size(), before.size());

  char cmd[200];
  snprintf(cmd, sizeof(cmd),
           "fix break all mesophyll/break 5 beta 1.0e9 threshold %.17g runs yes\nrun 0 post no\n",
           threshold);
  s->run(cmd);
  EXPECT_EQ(s->equal_variable("f_break[1]"), (double) (before.size() - kept.size()));
  EXPECT_EQ(s->equal_variable("f_break[2]"), 0.0);
  EXPECT_EQ(s->equal_variable("f_break[3]"), (double) kept.size());
  EXPECT_EQ(adhesive_bonds(*s, "break_after3d.data"), kept);
}

namespace {
// Two icosahedra, the second the first moved by 1.26 = 1.2 sigma in x (vertex i + 12 is vertex
// i's counterpart), bonded counterpart to counterpart over vertex 1 and its five edge partners.
std::unique_ptr<LammpsSession> bonded_patch(std::set<Bond> &patch)
{
  auto s = std::make_unique<LammpsSession>();
  s->run("units lj\ndimension 3\natom_style molecular\natom_modify map array\nboundary p p p\n"
         "fix Vertices all property/atom d_sigma d_v0 ghost yes\n"
         "fix Edges all property/atom i2_edge 6 ghost yes\n"
         "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
         "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n"
         "bond_style hybrid dpoly3d/edge mesophyll/adhesion\n"
         "angle_style zero\ndihedral_style dpoly3d/hinge\nread_data " +
         data_file("two_icosahedra.data") +
         " fix Vertices NULL Vertices fix Edges NULL Edges fix EdgeLengths NULL EdgeLengths"
         " fix EdgeAngles NULL EdgeAngles extra/bond/types 1 extra/bond/per/atom 12"
         " extra/special/per/atom 40\n"
         "bond_coeff 1 dpoly3d/edge 1.0\nbond_coeff 2 mesophyll/adhesion 0.8\n"
         "angle_coeff *\ndihedral_coeff * 0.4\ncomm_modify cutoff 2.0\n"
         "fix cells all dpoly3d/cells eps_v 1.0\n");
  // vertex 1's edge partners: it is the lowest ID, so its own i2_edge columns list them all
  const std::vector<int> columns = s->gather_int("i2_edge", 6);
  std::vector<int> vertices = {1};
  for (int k = 0; k < 6; k++)
    if (columns[k] > 0) vertices.push_back(columns[k]);
  std::string bonds;
  for (int v : vertices) {
    bonds += "create_bonds single/bond 2 " + std::to_string(v) + " " + std::to_string(v + 12) +
        "\n";
    patch.insert({v, v + 12});
  }
  s->run(bonds);
  return s;
}
}    // namespace

// The junction-edge rule in 3d ('edges yes'): a bond below the threshold is tested, and can
// break, only if an edge partner of one of its vertices has no adhesive bond. In the bonded patch
// above, 1-13 is interior (every edge partner of 1 and of 13 is bonded) and the five other bonds
// are at the edge of the junction. All six are stretched alike (r/s = 1.2, below the threshold)
// and beta is so small that a bond tested breaks (the draw is below exp(-1e-12 dE) for every
// seed): with 'edges yes' the five edge bonds break and 1-13 stays (bonds are taken in ID order,
// so 1-13 is decided first, while its neighbours are still bonded); with 'edges no' all six go.
TEST(Adhesion3d, JunctionEdgeRuleSparesTheInteriorBond)
{
  for (const char *edges : {"yes", "no"}) {
    std::set<Bond> patch;
    auto s = bonded_patch(patch);
    ASSERT_EQ(patch.size(), 6u) << "an icosahedron vertex has five edge partners";
    ASSERT_EQ(adhesive_bonds(*s, "junction_before3d.data"), patch);
    s->run(std::string("fix break all mesophyll/break 3 beta 1.0e-12 runs yes edges ") + edges +
           "\nrun 0 post no\n");
    const std::set<Bond> left = adhesive_bonds(*s, "junction_after3d.data");
    const bool edge_only = std::string(edges) == "yes";
    const std::set<Bond> interior = {{1, 13}}, none;
    EXPECT_EQ(left, edge_only ? interior : none) << "edges " << edges;
    EXPECT_EQ(s->equal_variable("f_break[1]"), 0.0) << "none reached the threshold";
    EXPECT_EQ(s->equal_variable("f_break[2]"), edge_only ? 5.0 : 6.0);
  }
}

// The rule looks at both ends of a bond. Edge partner p of vertex 1 is bonded to a vertex q of
// the second cell instead of its counterpart p + 12 (q: the nearest to p that is neither 13 nor
// an edge partner of 13): every edge partner of 1 is still bonded, but p + 12, an edge partner of
// 13, is not, so 1-13 is at the edge of the junction and breaks. Then the mirror image: p + 12
// bonded to q - 12 instead of p, so that 1 has the unbonded partner and 13 has none.
TEST(Adhesion3d, JunctionEdgeRuleLooksAtBothEnds)
{
  for (const bool mirrored : {false, true}) {
    std::set<Bond> patch;
    auto s = bonded_patch(patch);
    const std::vector<int> columns = s->gather_int("i2_edge", 6);
    const std::vector<double> x = s->gather("x", 3);
    std::set<int> taken = {13};
    for (int k = 0; k < 6; k++)
      if (columns[k] > 0) taken.insert(columns[k] + 12);
    const int p = columns[0];
    int q = 0;
    double nearest = 1.0e300;
    for (int v = 13; v <= 24; v++) {
      if (taken.count(v)) continue;
      double r2 = 0.0;
      for (int d = 0; d < 3; d++) r2 += pow(x[3 * (v - 1) + d] - x[3 * (p - 1) + d], 2);
      if (r2 < nearest) {
        nearest = r2;
        q = v;
      }
    }
    ASSERT_GT(q, 0);
    ASSERT_LT(sqrt(nearest), 2.0) << "within the ghost cutoff";
    const std::string moved = mirrored
        ? std::to_string(p + 12) + " " + std::to_string(q - 12)
        : std::to_string(p) + " " + std::to_string(q);
    // the bond p - (p + 12) goes: its two atoms are the only ones of the group
    s->run("group counterparts id " + std::to_string(p) + " " + std::to_string(p + 12) +
           "\ndelete_bonds counterparts bond 2 remove special\n");
    s->run("create_bonds single/bond 2 " + moved +
           "\nfix break all mesophyll/break 3 beta 1.0e-12 runs yes edges yes\nrun 0 post no\n");
    const std::set<Bond> left = adhesive_bonds(*s, "junction_after3d.data");
    EXPECT_EQ(left.count({1, 13}), 0u) << (mirrored ? "1" : "13") << " has an unbonded partner";
  }
}

// Stochastic breaking at the edges of junctions (a bonded vertex with an edge partner that has no
// adhesive bond) draws from the seed and the atom IDs: the same bonds break on any number of
// ranks, and some break without reaching the threshold.
TEST(Adhesion3d, StochasticBreakingIsRankIndependent)
{
  const std::string commands = adhesive_cells_commands() + ADHERE_AND_STRETCH +
      "fix break all mesophyll/break 11 beta 2000 threshold 1.2 runs yes\nrun 0 post no\n";
  ParallelAndSerial runs(commands);
  EXPECT_GT(runs.serial.equal_variable("f_break[2]"), 0.0) << "some should break by chance";
  EXPECT_GT(runs.serial.equal_variable("f_break[3]"), 0.0) << "some should stay";
  for (int k = 1; k <= 3; k++) {
    const std::string value = "f_break[" + std::to_string(k) + "]";
    EXPECT_EQ(runs.parallel.equal_variable(value), runs.serial.equal_variable(value)) << value;
  }
  const std::string serial_file = "serial_break3d." + std::to_string(world_size()) + ".data";
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  runs.serial.run("write_data " + scratch("rank" + std::to_string(rank) + "." + serial_file));
  EXPECT_EQ(adhesive_bonds(runs.parallel, "parallel_break3d.data"),
            adhesive_bonds_in(scratch("rank" + std::to_string(rank) + "." + serial_file)));
}

// Restart and data files keep the adhesive bonds and the z rule: the same energies after reading
// (under bond_style hybrid LAMMPS restores the styles and their settings, not the coefficients).
TEST(Adhesion3d, RestartAndDataRoundTrips)
{
  auto before = stretched_cells("cells");
  const std::string restart = scratch("adhesive3d.restart"), data = scratch("adhesive3d.data");
  before->run("write_restart " + restart + "\nwrite_data " + data + " nocoeff");

  LammpsSession restarted;
  restarted.run("read_restart " + restart +
                "\nfix Vertices all property/atom d_sigma d_v0 ghost yes\n"
                "fix Edges all property/atom i2_edge 6 ghost yes\n"
                "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
                "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n"
                "bond_coeff 1 dpoly3d/edge 1.0\nbond_coeff 2 mesophyll/adhesion 0.8\n"
                "comm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v 1.0\n"
                "compute bonds all bond\n"
                "thermo_style custom step pe c_bonds[2]\nthermo_modify norm no\nrun 0 post no");
  EXPECT_EQ(restarted.thermo("c_bonds[2]"), before->thermo("c_bonds[2]"));
  EXPECT_EQ(restarted.thermo("pe"), before->thermo("pe"));

  // the data file: the same bonds and energy (coordinates at write_data's precision)
  std::string commands = adhesive_cells_commands("cells");
  commands.replace(commands.find(data_file("cells3d_adhesive.data")),
                   data_file("cells3d_adhesive.data").size(), data);
  commands.replace(commands.find(" extra/bond/types 1"), 19, "");
  LammpsSession reread;
  reread.run(commands + "run 0 post no");
  EXPECT_EQ(adhesive_bonds(reread, "reread3d.data"), adhesive_bonds_in(data));
  EXPECT_NEAR(reread.thermo("c_bonds[2]"), before->thermo("c_bonds[2]"),
              1.0e-12 * before->thermo("c_bonds[2]"));
  EXPECT_NEAR(reread.thermo("pe"), before->thermo("pe"), 1.0e-12 * before->thermo("pe"));
}

// ---------------------------------------------------------------------------------------
// Bad input: each gets an error that names the problem. Single rank.

class BadInputAdhesion3d : public ErrorTest {};

TEST_F(BadInputAdhesion3d, ErrorsNameTheProblem)
{
  const std::string base = adhesive_cells_commands();
  expect_errors(base,
                {// atoms 1 and 2 are vertices of cell 1
                 {"create_bonds single/bond 2 1 2\nrun 0 post no",
                  "joins two vertices of cell 1; adhesive bonds join different cells"},
                 {"adhere_cells all 1", "bond type 1 is not a bond type of bond_style "
                                        "mesophyll/adhesion"},
                 {"adhere_cells all 2\nadhere_cells all 2", "are already bonded"},
                 {"fix grow all mesophyll/grow delta_a 0.5\nrun 0 post no",
                  "acts on polygons only: it needs fix dpoly/cells, not fix dpoly3d/cells"},
                 // 'pre no' skips init(): the stage runner itself must refuse the 2d stage
                 {"run 0 post no\nfix grow all mesophyll/grow delta_a 0.5 runs yes\n"
                  "run 1 pre no post no",
                  "acts on polygons only: it needs fix dpoly/cells, not fix dpoly3d/cells"},
                 {"unfix cells\nrun 0 post no",
                  "needs fix dpoly/cells (polygons) or fix dpoly3d/cells (polyhedra)"}});
}
