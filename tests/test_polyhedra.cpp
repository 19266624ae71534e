// Cell mechanics of the deformable polyhedra (3d cells): fix dpoly3d/cells (volume), bond
// dpoly3d/edge (edge length) and dihedral dpoly3d/hinge (bending at an edge). Every test runs on
// any number of ranks unless it says otherwise; ctest runs this binary on 1, 2 and 4.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using ::testing::HasSubstr;

using namespace test;

namespace {

const char *CELL_STATE = "fix Vertices all property/atom d_sigma d_v0 ghost yes\n"
                         "fix Edges all property/atom i2_edge 6 ghost yes\n"
                         "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
                         "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n";
const int EDGE_SLOTS = 6;

struct Model {
  std::string newton_bond = "on";
  double eps_v = 1.0, eps_l = 1.0, eps_b = 0.4;
};

std::string setup_commands(const std::string &data, const Model &m = Model())
{
  return "units lj\ndimension 3\natom_style molecular\natom_modify map array\n"
         "boundary p p p\nnewton on " +
      m.newton_bond + "\n" + CELL_STATE +
      "bond_style dpoly3d/edge\nangle_style zero\ndihedral_style dpoly3d/hinge\n"
      "read_data " +
      data +
      " fix Vertices NULL Vertices fix Edges NULL Edges fix EdgeLengths NULL EdgeLengths fix "
      "EdgeAngles NULL EdgeAngles\n" +
      "bond_coeff * " + std::to_string(m.eps_l) + "\nangle_coeff *\ndihedral_coeff * " +
      std::to_string(m.eps_b) + "\ncomm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v " +
      std::to_string(m.eps_v) +
      "\nthermo_style custom step pe ebond edihed f_cells press pxx pyy pzz pxy pxz pyz\n"
      "thermo_modify norm no\n";
}

// Move every vertex off its preferred place (random, but drawn from the seed and each atom's
// position, so the same on any number of ranks) and give each cell its own v0: no term sits at
// its minimum. The data file's jitter already gives every edge its own l0 and theta0.
const char *PERTURB = "displace_atoms all random 0.04 0.04 0.04 4711 units box\n"
                      "variable v0 atom 3.3+0.4*sin(1.9*mol)\nset group all d_v0 v_v0\n";

std::unique_ptr<LammpsSession> deformed_cells(const Model &m = Model(),
                                              MPI_Comm comm = MPI_COMM_WORLD)
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(setup_commands(data_file("cells3d_deformed.data"), m));
  s->run(PERTURB);
  s->run("run 0 post no");
  return s;
}

void check_forces_by_finite_differences(const Model &m)
{
  auto s = deformed_cells(m);
  ASSERT_GT(max_abs(s->gather("f", 3)), 1.0e-3) << "the perturbed cells should not be at rest";
  EXPECT_LT(finite_difference_error_3d(*s), 1.0e-7);
}

// the i2_edge/d2_edge_* columns, all of them, one name at a time
std::vector<std::string> edge_columns()
{
  std::vector<std::string> names;
  for (const char *base : {"d2_edge_l0", "d2_edge_theta0"}) names.emplace_back(base);
  return names;
}

}    // namespace

// A regular icosahedron of circumradius 1: edge a = 1/sin(2 pi/5), volume (5/12)(3 + sqrt 5)a^3,
// bending angle pi - acos(-sqrt(5)/3) at each of its 30 edges.
TEST(Polyhedra, RegularIcosahedronEnergiesAreAnalytic)
{
  LammpsSession s;
  s.run(setup_commands(data_file("icosahedron.data")));
  ASSERT_EQ(s.natoms(), 12);
  const double a = 1.0 / sin(2.0 * PI / 5.0);
  const double volume = 5.0 / 12.0 * (3.0 + sqrt(5.0)) * a * a * a;
  const double theta = PI - acos(-sqrt(5.0) / 3.0);
  const double area = 20.0 * sqrt(3.0) / 4.0 * a * a;

  // at the written geometry every term is at its minimum, the preferred values are exact
  s.run("run 0 post no");
  EXPECT_NEAR(s.thermo("pe"), 0.0, 1.0e-24);
  EXPECT_NEAR(s.equal_variable("f_cells[2]"), volume, 1.0e-12);
  EXPECT_NEAR(s.equal_variable("f_cells[3]"), area, 1.0e-12);
  const std::vector<double> theta0 = s.gather("d2_edge_theta0", EDGE_SLOTS);
  for (double t : theta0)
    if (t != 0.0) EXPECT_NEAR(t, theta, 1.0e-12) << "convex edges bend by a positive angle";

  const double v0 = 2.9, l0 = 0.93, theta0_new = 0.6;
  std::string set = "set group all d_v0 2.9\n";
  for (int k = 1; k <= EDGE_SLOTS; k++)
    set += "set group all d2_edge_l0[" + std::to_string(k) + "] 0.93\nset group all " +
        "d2_edge_theta0[" + std::to_string(k) + "] 0.6\n";
  s.run(set + "run 0 post no");
  const double volume_energy = 0.5 * std::pow(volume / v0 - 1.0, 2);
  const double edge_energy = 30 * 0.5 * std::pow(a / l0 - 1.0, 2);
  const double hinge_energy = 30 * 0.5 * 0.4 * std::pow(theta - theta0_new, 2);
  EXPECT_NEAR(s.thermo("f_cells"), volume_energy, 1.0e-13);
  EXPECT_NEAR(s.thermo("ebond"), edge_energy, 1.0e-13);
  EXPECT_NEAR(s.thermo("edihed"), hinge_energy, 1.0e-13);
  // the volume term's pressure: P = -dU/dV_box = -V U'(V)/V_box at zero temperature
  const double box = s.equal_variable("vol");
  const double slope = (volume / v0 - 1.0) / v0;
  // edge tension: each edge contributes -r dU/dr / (3 V_box)
  const double edge_slope = (a / l0 - 1.0) / l0;
  EXPECT_NEAR(s.thermo("press"), (-volume * slope - 30 * a * edge_slope / 3.0) / box, 1.0e-12);
}

// The generator's preferred values are those of the written (jittered) geometry, every edge its
// own: each term must find its own edge's values, so the cells are at rest.
TEST(Polyhedra, WrittenGeometryIsAtRest)
{
  LammpsSession s;
  s.run(setup_commands(data_file("cells3d_deformed.data")) + "run 0 post no");
  const std::vector<double> l0 = s.gather("d2_edge_l0", EDGE_SLOTS);
  ASSERT_GT(*std::max_element(l0.begin(), l0.end()) -
                *std::min_element(l0.begin(), l0.end(),
                                  [](double a, double b) {
                                    return (a > 0.0 ? a : 1e300) < (b > 0.0 ? b : 1e300);
                                  }),
            0.05)
      << "the edges should have different preferred lengths";
  EXPECT_NEAR(s.thermo("ebond"), 0.0, 1.0e-24);
  EXPECT_NEAR(s.thermo("edihed"), 0.0, 1.0e-24);
  EXPECT_NEAR(s.thermo("f_cells"), 0.0, 1.0e-24);
  EXPECT_LT(max_abs(s.gather("f", 3)), 1.0e-10);
}

// A 642-vertex cell, whose per-edge values fill their data-file lines with full-precision
// numbers, is at rest as written: read_data kept every digit.
TEST(Polyhedra, FinestCellIsAtRest)
{
  LammpsSession s;
  s.run(setup_commands(data_file("icosphere3.data")) + "run 0 post no");
  ASSERT_EQ(s.natoms(), 642);
  EXPECT_NEAR(s.thermo("ebond"), 0.0, 1.0e-24);
  EXPECT_NEAR(s.thermo("edihed"), 0.0, 1.0e-24);
  EXPECT_LT(max_abs(s.gather("f", 3)), 1.0e-10);
}

TEST(Polyhedra, AllTermsMatchFiniteDifferences)
{
  check_forces_by_finite_differences(Model());
}

TEST(Polyhedra, VolumeTermMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"on", 1.0, 0.0, 0.0});
}

TEST(Polyhedra, EdgeTermMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"on", 0.0, 1.0, 0.0});
}

TEST(Polyhedra, HingeTermMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"on", 0.0, 0.0, 1.0});
}

TEST(Polyhedra, NewtonBondOffMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"off", 1.0, 1.0, 0.4});
}

// P = -dU/dV for an affine deformation at zero temperature; pxx = -(1/(Ly Lz)) dU/dLx.
TEST(Polyhedra, PressureMatchesBoxDerivative)
{
  auto s = deformed_cells();
  const double lx = s->equal_variable("lx"), ly = s->equal_variable("ly"),
               lz = s->equal_variable("lz");
  const double press = s->thermo("press");
  ASSERT_GT(std::fabs(press), 1.0e-4) << "the perturbed cells should be under stress";
  const double e = 1.0e-5;
  const double iso = -(energy_after_scaling_3d(*s, 1 + e, 1 + e, 1 + e) -
                       energy_after_scaling_3d(*s, 1 - e, 1 - e, 1 - e)) /
      (lx * ly * lz * (std::pow(1 + e, 3) - std::pow(1 - e, 3)));
  EXPECT_NEAR(press, iso, 1.0e-7 * std::fabs(press));
  const char *keys[3] = {"pxx", "pyy", "pzz"};
  for (int d = 0; d < 3; d++) {
    double up[3] = {1, 1, 1}, down[3] = {1, 1, 1};
    up[d] += e;
    down[d] -= e;
    const double numeric = -(energy_after_scaling_3d(*s, up[0], up[1], up[2]) -
                             energy_after_scaling_3d(*s, down[0], down[1], down[2])) /
        (2.0 * e * lx * ly * lz);
    const double analytic = s->thermo(keys[d]);
    EXPECT_NEAR(analytic, numeric, 1.0e-7 * std::fabs(analytic)) << keys[d];
  }
}

// Each term depends only on relative positions and is invariant under rotations.
TEST(Polyhedra, NoNetForceOrTorque)
{
  auto s = deformed_cells();
  s->run("compute unwrapped all property/atom xu yu zu\n"
         "variable tx atom c_unwrapped[2]*fz-c_unwrapped[3]*fy\n"
         "variable ty atom c_unwrapped[3]*fx-c_unwrapped[1]*fz\n"
         "variable tz atom c_unwrapped[1]*fy-c_unwrapped[2]*fx\n"
         "compute net all reduce sum fx fy fz v_tx v_ty v_tz\n"
         "thermo_style custom step pe c_net[*]\nthermo_modify norm no\nrun 0 post no");
  const double scale = max_abs(s->gather("f", 3));
  for (int k = 1; k <= 3; k++)
    EXPECT_NEAR(s->equal_variable("c_net[" + std::to_string(k) + "]"), 0.0, 1.0e-12 * scale);
  for (int k = 4; k <= 6; k++)
    EXPECT_NEAR(s->equal_variable("c_net[" + std::to_string(k) + "]"), 0.0, 1.0e-11 * scale);
}

// The per-atom virial (compute stress/atom, all terms and the hub's volume term) sums to the
// global one: at zero temperature sum(s_xx + s_yy + s_zz) = -3 P V_box.
TEST(Polyhedra, PerAtomVirialSumsToPressure)
{
  for (const std::string newton : {"on", "off"}) {
    auto s = deformed_cells({newton, 1.0, 1.0, 0.4});
    s->run("compute stress all stress/atom NULL virial\n"
           "compute total all reduce sum c_stress[1] c_stress[2] c_stress[3] c_stress[4] "
           "c_stress[5] c_stress[6]\n"
           "thermo_style custom step pe press c_total[*]\nthermo_modify norm no\nrun 0 post no");
    const double volume = s->equal_variable("vol");
    const char *keys[6] = {"pxx", "pyy", "pzz", "pxy", "pxz", "pyz"};
    for (int k = 0; k < 6; k++) {
      const double global = s->thermo(keys[k]);
      EXPECT_NEAR(s->equal_variable("c_total[" + std::to_string(k + 1) + "]"), -global * volume,
                  1.0e-10 * std::fabs(s->thermo("press")) * volume)
          << keys[k] << " newton_bond " << newton;
    }
  }
}

TEST(Polyhedra, NewtonBondOnAndOffAgree)
{
  auto on = deformed_cells({"on", 1.0, 1.0, 0.4});
  auto off = deformed_cells({"off", 1.0, 1.0, 0.4});
  EXPECT_NEAR(on->thermo("pe"), off->thermo("pe"), 1.0e-13 * std::fabs(on->thermo("pe")));
  EXPECT_NEAR(on->thermo("press"), off->thermo("press"), 1.0e-12 * std::fabs(on->thermo("press")));
  EXPECT_LT(relative_force_error(on->gather("f", 3), off->gather("f", 3)), 1.0e-13);
}

// On several ranks: each rank also runs the same system alone, as the reference.
TEST(Polyhedra, ParallelRunMatchesSerialRun)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto parallel = deformed_cells();
  auto serial = deformed_cells(Model(), self_comm());
  for (const char *keyword :
       {"pe", "ebond", "edihed", "f_cells", "press", "pxx", "pyy", "pzz", "pxy", "pxz", "pyz"})
    EXPECT_NEAR(parallel->thermo(keyword), serial->thermo(keyword),
                1.0e-12 * std::max(1.0, std::fabs(serial->thermo(keyword))))
        << keyword;
  EXPECT_LT(relative_force_error(serial->gather("f", 3), parallel->gather("f", 3)), 1.0e-12);
}

namespace {
// positions, per-vertex and per-edge state and every energy term agree exactly
void expect_same_state(LammpsSession &before, LammpsSession &after)
{
  EXPECT_EQ(before.gather("x", 3), after.gather("x", 3));
  EXPECT_EQ(before.gather("d_sigma", 1), after.gather("d_sigma", 1));
  EXPECT_EQ(before.gather("d_v0", 1), after.gather("d_v0", 1));
  EXPECT_EQ(before.gather_int("i2_edge", EDGE_SLOTS), after.gather_int("i2_edge", EDGE_SLOTS));
  for (const std::string &name : edge_columns())
    EXPECT_EQ(before.gather(name.c_str(), EDGE_SLOTS), after.gather(name.c_str(), EDGE_SLOTS))
        << name;
  for (const char *keyword : {"pe", "ebond", "edihed", "f_cells", "press"})
    EXPECT_EQ(before.thermo(keyword), after.thermo(keyword)) << keyword;
}
}    // namespace

TEST(Polyhedra, RestartPreservesStateAndEnergy)
{
  const std::string restart = scratch("cells3d.restart");
  auto before = deformed_cells();
  before->run("write_restart " + restart);

  LammpsSession after;
  after.run("read_restart " + restart + "\n" + CELL_STATE +
            "comm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v 1.0\n"
            "thermo_style custom step pe ebond edihed f_cells press\nthermo_modify norm no\n"
            "run 0 post no");
  expect_same_state(*before, after);
  if (world_size() == 1) remove(restart.c_str());
}

TEST(Polyhedra, DataFileRoundTripPreservesStateAndEnergy)
{
  const std::string data = scratch("cells3d.data");
  auto before = deformed_cells();
  before->run("write_data " + data);

  LammpsSession after;
  after.run(setup_commands(data) + "run 0 post no");
  expect_same_state(*before, after);
}

// A regular icosahedron with its own bending angles as theta0, uniform l0 and v0 != V stays
// regular (its symmetry) and settles at the scale s that minimizes
//   U(s) = (eps_v/2)(s^3 V/v0 - 1)^2 + 30 (eps_l/2)(s a/l0 - 1)^2.
// With eps_l = 0 it reaches v0 exactly.
TEST(Polyhedra, SingleCellRelaxesToAnalyticState)
{
  const double a = 1.0 / sin(2.0 * PI / 5.0);
  const double volume = 5.0 / 12.0 * (3.0 + sqrt(5.0)) * a * a * a;
  for (const double eps_l : {1.0, 0.0}) {
    LammpsSession s;
    s.run(setup_commands(data_file("icosahedron.data"), {"on", 1.0, eps_l, 0.4}));
    const double v0 = 3.5, l0 = a;
    s.run("set group all d_v0 3.5\nmin_style cg\nminimize 0.0 1.0e-14 20000 200000");
    auto slope = [&](double x) {
      return (x * x * x * volume / v0 - 1.0) * 3.0 * x * x * volume / v0 +
          eps_l * 30.0 * (x * a / l0 - 1.0) * a / l0;
    };
    double lo = 0.5, hi = 2.0;
    for (int it = 0; it < 200; it++) {
      const double mid = 0.5 * (lo + hi);
      (slope(mid) > 0.0 ? hi : lo) = mid;
    }
    const double scale = 0.5 * (lo + hi);
    EXPECT_NEAR(s.equal_variable("f_cells[2]"), std::pow(scale, 3) * volume, 1.0e-8) << eps_l;
    if (eps_l == 0.0) EXPECT_NEAR(s.equal_variable("f_cells[2]"), v0, 1.0e-8);
    EXPECT_NEAR(s.thermo("edihed"), 0.0, 1.0e-14) << eps_l;
  }
}

// ---------------------------------------------------------------------------------------
// Contacts: pair_style dpoly3d/contact between overlapping vertex spheres.

namespace {

std::string contact_commands(const std::string &self, const std::string &newton_pair)
{
  std::string cmds = setup_commands(data_file("cells3d_touching.data"));
  cmds.replace(cmds.find("newton on on"), 12, "newton " + newton_pair + " on");
  return cmds + "special_bonds lj 1.0 1.0 1.0\npair_style dpoly3d/contact self " + self +
      "\npair_coeff * * 1.0\nthermo_style custom step pe evdwl ebond edihed f_cells press\n"
      "thermo_modify norm no\n";
}

std::unique_ptr<LammpsSession> touching_cells(const std::string &self = "yes",
                                              const std::string &newton_pair = "on",
                                              MPI_Comm comm = MPI_COMM_WORLD)
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(contact_commands(self, newton_pair));
  s->run(PERTURB);
  s->run("run 0 post no");
  return s;
}

}    // namespace

// The contact energy is the sum over every overlapping pair (nearest images) of different cells,
// and with 'self yes' of one cell unless an edge joins them, of (1/2)(1 - r/s)^2.
TEST(Polyhedra, ContactEnergyIsTheSumOverOverlaps)
{
  for (const std::string self : {"yes", "no"}) {
    auto s = touching_cells(self);
    const int n = s->natoms();
    const std::vector<double> x = s->gather("x", 3), sigma = s->gather("d_sigma", 1);
    const std::vector<int> molecule = s->gather_int("molecule", 1);
    const std::vector<int> partners = s->gather_int("i2_edge", EDGE_SLOTS);
    const double box = s->equal_variable("lx");
    double energy = 0.0;
    int between = 0, within = 0;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++) {
        bool edge = false;
        for (int k = 0; k < EDGE_SLOTS; k++) edge |= partners[EDGE_SLOTS * i + k] == j + 1;
        if (molecule[i] == molecule[j] && (edge || self == "no")) continue;
        double rsq = 0.0;
        for (int d = 0; d < 3; d++) {
          double dx = x[3 * i + d] - x[3 * j + d];
          dx -= box * std::round(dx / box);
          rsq += dx * dx;
        }
        const double contact = 0.5 * (sigma[i] + sigma[j]), r = std::sqrt(rsq);
        if (r >= contact) continue;
        energy += 0.5 * std::pow(1.0 - r / contact, 2);
        (molecule[i] == molecule[j] ? within : between)++;
      }
    ASSERT_GT(between, 10) << "the cells should overlap";
    if (self == "yes") ASSERT_GT(within, 10) << "vertices across a face should overlap";
    EXPECT_NEAR(s->thermo("evdwl"), energy, 1.0e-12 * energy) << "self " << self;
  }
}

// one rank: the law's gradient; ContactPressureAndRanks compares several ranks with one
TEST(Polyhedra, ContactMatchesFiniteDifferences)
{
  if (world_size() > 1) GTEST_SKIP() << "checked on one rank, compared across ranks below";
  for (const std::string newton_pair : {"on", "off"}) {
    auto s = touching_cells("yes", newton_pair);
    ASSERT_GT(s->thermo("evdwl"), 1.0e-3);
    EXPECT_LT(finite_difference_error_3d(*s), 1.0e-7) << "newton_pair " << newton_pair;
  }
}

TEST(Polyhedra, ContactPressureAndRanks)
{
  auto on = touching_cells("yes", "on");
  auto off = touching_cells("yes", "off");
  EXPECT_NEAR(on->thermo("evdwl"), off->thermo("evdwl"), 1.0e-13 * on->thermo("evdwl"));
  EXPECT_NEAR(on->thermo("press"), off->thermo("press"), 1.0e-12 * std::fabs(on->thermo("press")));
  EXPECT_LT(relative_force_error(on->gather("f", 3), off->gather("f", 3)), 1.0e-13);

  const double lx = on->equal_variable("lx"), ly = on->equal_variable("ly"),
               lz = on->equal_variable("lz");
  const double e = 1.0e-5;
  const double iso = -(energy_after_scaling_3d(*on, 1 + e, 1 + e, 1 + e) -
                       energy_after_scaling_3d(*on, 1 - e, 1 - e, 1 - e)) /
      (lx * ly * lz * (std::pow(1 + e, 3) - std::pow(1 - e, 3)));
  EXPECT_NEAR(on->thermo("press"), iso, 1.0e-7 * std::fabs(iso));

  if (world_size() > 1) {
    auto serial = touching_cells("yes", "on", self_comm());
    for (const char *keyword : {"pe", "evdwl", "press"})
      EXPECT_NEAR(on->thermo(keyword), serial->thermo(keyword),
                  1.0e-12 * std::max(1.0, std::fabs(serial->thermo(keyword))))
          << keyword;
    EXPECT_LT(relative_force_error(serial->gather("f", 3), on->gather("f", 3)), 1.0e-12);
  }
}

TEST(Polyhedra, ContactRestartAndSingle)
{
  const std::string restart = scratch("touching3d.restart");
  auto before = touching_cells();
  before->run("compute pairs all pair/local eng\ncompute psum all reduce sum c_pairs inputs local\n"
              "thermo_style custom step pe evdwl c_psum\nthermo_modify norm no\nrun 0 post no");
  EXPECT_NEAR(before->thermo("c_psum"), before->thermo("evdwl"), 1.0e-12 * before->thermo("evdwl"));
  before->run("write_restart " + restart);
  LammpsSession after;
  after.run("read_restart " + restart + "\n" + CELL_STATE +
            "comm_modify cutoff 2.0\nfix cells all dpoly3d/cells eps_v 1.0\n"
            "thermo_style custom step pe evdwl\nthermo_modify norm no\nrun 0 post no");
  EXPECT_EQ(before->thermo("evdwl"), after.thermo("evdwl"));
  EXPECT_EQ(before->thermo("pe"), after.thermo("pe"));
  if (world_size() == 1) remove(restart.c_str());
}

// ---------------------------------------------------------------------------------------
// Bad input: each gets an error that names the problem. Single rank.

namespace {

using LineEdit = std::function<std::string(const std::string &, int)>;

// a copy of the icosahedron's data file with each line of a section passed through its edit
// (the header is the section "MESOPHYLL", the first word of its title line)
std::string edited_data(const std::map<std::string, LineEdit> &edits)
{
  std::ifstream in(data_file("icosahedron.data"));
  const std::string path = scratch("edited3d.data");
  std::ofstream out(path);
  std::string line, current;
  int index = 0;
  while (std::getline(in, line)) {
    if (!line.empty() && std::isalpha((unsigned char) line[0])) {
      current = line.substr(0, line.find(' '));
      index = 0;
    } else if (!line.empty() && edits.count(current)) {
      line = edits.at(current)(line, index++);
    }
    out << line << "\n";
  }
  return path;
}

// the set-up commands with room for more bonds per atom
std::string with_room_for_bonds(std::string commands)
{
  commands.replace(commands.find(" fix Vertices NULL"), 0, " extra/bond/per/atom 2");
  return commands;
}

std::vector<std::string> words(const std::string &line)
{
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

}    // namespace

class BadInput3d : public ErrorTest {};

TEST_F(BadInput3d, ValidIcosahedronIsAccepted)
{
  EXPECT_EQ(error_of(setup_commands(data_file("icosahedron.data")) + "run 0 post no"), "");
}

TEST_F(BadInput3d, StylesAndState)
{
  const std::string base = setup_commands(data_file("icosahedron.data"));
  // a 2d box (z straddles 0) read in 2d
  auto flat = [](const std::string &line, int) {
    return line.find("zlo zhi") == std::string::npos ? line : std::string("-0.5 0.5 zlo zhi");
  };
  auto in_plane = [](const std::string &line, int) {
    auto w = words(line);
    return w[0] + " " + w[1] + " " + w[2] + " " + w[3] + " " + w[4] + " 0 " + w[6] + " " + w[7] +
        " 0";
  };
  std::string two_d = setup_commands(edited_data({{"MESOPHYLL", flat}, {"Atoms", in_plane}}));
  two_d.replace(two_d.find("dimension 3"), 11, "dimension 2");
  EXPECT_THAT(error_of(two_d + "run 0 post no"), HasSubstr("needs a 3d simulation"));
  std::string no_ghosts = base;
  no_ghosts.replace(no_ghosts.find("d2_edge_theta0 6 ghost yes"), 26, "d2_edge_theta0 6");
  ASSERT_EQ(no_ghosts.find("d2_edge_theta0 6 ghost yes"), std::string::npos);
  EXPECT_THAT(error_of(no_ghosts + "run 0 post no"), HasSubstr("on ghost atoms too"));
  // ten columns: a data file's line of them would be longer than read_data reads
  const std::string ten_columns = base +
      "unfix Edges\nunfix EdgeLengths\nunfix EdgeAngles\n"
      "fix Edges all property/atom i2_edge 10 ghost yes\n"
      "fix EdgeLengths all property/atom d2_edge_l0 10 ghost yes\n"
      "fix EdgeAngles all property/atom d2_edge_theta0 10 ghost yes\n";
  EXPECT_THAT(error_of(ten_columns + "run 0 post no"), HasSubstr("have 10 columns, at most 9"));
  expect_errors(
      base,
      {
          {"fix bad all dpoly3d/cells eps_v -1", "eps_v must be finite and >= 0, got -1"},
          {"fix bad all dpoly3d/cells eps_v", "Illegal fix dpoly3d/cells eps_v"},
          {"fix bad all dpoly3d/cells volume 1", "Unknown fix dpoly3d/cells keyword: volume"},
          {"fix bad all dpoly3d/cells\nrun 0 post no", "Only one fix dpoly3d/cells"},
          {"angle_style harmonic\nangle_coeff * 1.0 60\nrun 0 post no",
           "needs angle_style zero for the faces"},
          {"set atom 5 d_v0 0\nrun 0 post no", "vertex 5 has v0 = 0"},
          {"set atom 5 d_v0 2\nrun 0 post no", "different v0"},
          {"set atom 5 d_sigma -1\nrun 0 post no", "vertex 5 has sigma = -1"},
          {"set group all d_v0 1e-200\nrun 0 post no",
           "has v0 = 1e-200 for a volume of 2.5361507: its volume term (V/V0 - 1)^2 is not finite"},
          {"set atom 1 i2_edge[1] 0\nrun 0 post no", "sets of preferred values"},
          {"set atom 1 d2_edge_l0[1] 0\nrun 0 post no", "l0 = 0"},
      });
}

TEST_F(BadInput3d, Topology)
{
  auto flip_first = [](const std::string &line, int index) {
    if (index != 0) return line;
    const auto w = words(line);
    return w[0] + " " + w[1] + " " + w[2] + " " + w[4] + " " + w[3];
  };
  auto flip_all = [](const std::string &line, int) {
    const auto w = words(line);
    return w[0] + " " + w[1] + " " + w[2] + " " + w[4] + " " + w[3];
  };
  // the hinges of the inside-out faces: a b c d becomes d b c a
  auto swap_wings = [](const std::string &line, int) {
    const auto w = words(line);
    return w[0] + " " + w[1] + " " + w[5] + " " + w[3] + " " + w[4] + " " + w[2];
  };
  auto wrong_wing = [](const std::string &line, int index) {
    if (index != 0) return line;
    const auto w = words(line);
    return w[0] + " " + w[1] + " " + w[5] + " " + w[3] + " " + w[4] + " " + w[2];
  };
  EXPECT_THAT(error_of(setup_commands(edited_data({{"Angles", flip_first}})) + "run 0 post no"),
              HasSubstr("runs the same way in two faces"));
  EXPECT_THAT(
      error_of(setup_commands(edited_data({{"Angles", flip_all}, {"Dihedrals", swap_wings}})) +
               "run 0 post no"),
      HasSubstr("encloses the volume"));
  EXPECT_THAT(error_of(setup_commands(edited_data({{"Dihedrals", wrong_wing}})) + "run 0 post no"),
              HasSubstr("does not join two faces"));
  // one face of a second angle type, of angle_style harmonic in a hybrid
  auto two_types = [](const std::string &line, int) {
    return line == "1 angle types" ? std::string("2 angle types") : line;
  };
  auto second_type = [](const std::string &line, int index) {
    if (index != 0) return line;
    const auto w = words(line);
    return w[0] + " 2 " + w[2] + " " + w[3] + " " + w[4];
  };
  std::string hybrid =
      setup_commands(edited_data({{"MESOPHYLL", two_types}, {"Angles", second_type}}));
  hybrid.replace(hybrid.find("angle_style zero"), 16, "angle_style hybrid zero harmonic");
  hybrid.replace(hybrid.find("angle_coeff *\n"), 14,
                 "angle_coeff 1 zero\nangle_coeff 2 harmonic 1.0 60\n");
  EXPECT_THAT(error_of(hybrid + "run 0 post no"),
              HasSubstr("has an angle type of another style than zero"));
  // a bond between vertices 1 and 3, which share no face, and a second bond on edge 1-12
  EXPECT_THAT(error_of(with_room_for_bonds(setup_commands(data_file("icosahedron.data"))) +
                       "create_bonds single/bond 1 1 3 special no\nrun 0 post no"),
              HasSubstr("dpoly3d/edge bonds 1-3 is not an edge"));
  EXPECT_THAT(error_of(with_room_for_bonds(setup_commands(data_file("icosahedron.data"))) +
                       "create_bonds single/bond 1 1 12 special no\nrun 0 post no"),
              HasSubstr("edge 1-12 of cell 1 has 2 dpoly3d/edge bonds"));
}
