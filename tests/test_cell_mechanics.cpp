// Cell mechanics of the deformable-polygon model: fix dpoly/cells (area), bond dpoly/segment
// (length) and angle dpoly/bending (turning angle). Every test runs on any number of ranks
// unless it says otherwise; ctest runs this binary on 1, 2 and 4.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

using ::testing::HasSubstr;

using namespace test;

namespace {

const char *VERTEX_STATE = "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n";

struct Model {
  std::string newton_bond = "on";
  double eps_a = 1.0, eps_l = 1.0, eps_b = 0.4;
};

std::string setup_commands(const std::string &data, const Model &m = Model())
{
  return "units lj\ndimension 2\natom_style molecular\natom_modify map array\n"
         "boundary p p p\nnewton on " +
      m.newton_bond + "\n" + VERTEX_STATE +
      "bond_style dpoly/segment\nangle_style dpoly/bending\n" + "read_data " + data +
      " fix Vertices NULL Vertices\n" + "bond_coeff * " + std::to_string(m.eps_l) + "\n" +
      "angle_coeff * " + std::to_string(m.eps_b) + "\ncomm_modify cutoff 2.0\n" +
      "fix cells all dpoly/cells eps_a " + std::to_string(m.eps_a) + "\n" +
      "thermo_style custom step pe ebond eangle f_cells press pxx pyy pxy\n"
      "thermo_modify norm no\n";
}

// Give every vertex its own preferred values (deterministic in the atom ID, so the same on any
// number of ranks) and every cell its own a0, so that no term sits at its minimum.
const char *PERTURB_STATE = "variable l0 atom d_l0*(1.0+0.15*sin(3.7*id))\n"
                            "variable th0 atom d_theta0+0.3*cos(2.3*id)\n"
                            "variable a0 atom 1.0+0.4*sin(1.9*mol)\n"
                            "set group all d_l0 v_l0\nset group all d_theta0 v_th0\n"
                            "set group all d_a0 v_a0\n";

std::unique_ptr<LammpsSession> deformed_tissue(const Model &m = Model(),
                                               MPI_Comm comm = MPI_COMM_WORLD)
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(setup_commands(data_file("deformed.data"), m));
  s->run(PERTURB_STATE);
  s->run("run 0 post no");
  return s;
}

// Forces of each term alone, and all together, against central differences of the energy.
void check_forces_by_finite_differences(const Model &m)
{
  auto s = deformed_tissue(m);
  ASSERT_GT(max_abs(s->gather("f", 3)), 1.0e-3) << "the perturbed tissue should not be at rest";
  EXPECT_LT(finite_difference_error(*s), 1.0e-7);
}

}    // namespace

TEST(CellMechanics, RegularPolygonEnergiesAreAnalytic)
{
  LammpsSession s;
  s.run(setup_commands(data_file("single.data")));
  const int n = s.natoms();
  ASSERT_EQ(n, 16);
  const std::vector<double> x = s.gather("x", 3);
  const double radius = std::hypot(x[0] - x[3 * (n / 2)], x[1] - x[3 * (n / 2) + 1]) / 2.0;
  const double area = 0.5 * n * radius * radius * sin(2.0 * PI / n);
  const double length = 2.0 * radius * sin(PI / n);

  // bending is zero at theta0 = 2 pi/n, as the generator sets it
  s.run("run 0 post no");
  EXPECT_NEAR(s.thermo("eangle"), 0.0, 1.0e-20);

  const double a0 = 1.7, l0 = 0.31, dtheta = 0.05;
  s.run("set group all d_a0 1.7\nset group all d_l0 0.31\n"
        "variable th0 atom d_theta0+0.05\nset group all d_theta0 v_th0\nrun 0 post no");
  const double area_energy = 0.5 * std::pow(area / a0 - 1.0, 2);
  const double length_energy = n * 0.5 * std::pow(length / l0 - 1.0, 2);
  const double bending_energy = n * 0.5 * 0.4 * dtheta * dtheta;
  EXPECT_NEAR(s.thermo("f_cells"), area_energy, 1.0e-13);
  EXPECT_NEAR(s.thermo("ebond"), length_energy, 1.0e-13);
  EXPECT_NEAR(s.thermo("eangle"), bending_energy, 1.0e-13);
  EXPECT_NEAR(s.thermo("pe"), area_energy + length_energy + bending_energy, 1.0e-13);
  EXPECT_NEAR(s.equal_variable("f_cells[2]"), area, 1.0e-13);
  EXPECT_EQ(s.equal_variable("f_cells[1]"), 1.0);
}

TEST(CellMechanics, AllTermsMatchFiniteDifferences)
{
  check_forces_by_finite_differences(Model());
}

TEST(CellMechanics, AreaTermMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"on", 1.0, 0.0, 0.0});
}

TEST(CellMechanics, SegmentTermMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"on", 0.0, 1.0, 0.0});
}

TEST(CellMechanics, BendingTermMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"on", 0.0, 0.0, 1.0});
}

TEST(CellMechanics, NewtonBondOffMatchesFiniteDifferences)
{
  check_forces_by_finite_differences({"off", 1.0, 1.0, 0.4});
}

// single() of the bond and angle styles, summed over all bonds and angles, equals compute()
namespace {
void expect_single_sums_match_compute(LammpsSession &s)
{
  s.run("compute segments all bond/local engpot\ncompute bends all angle/local eng\n"
        "compute esum all reduce sum c_segments inputs local\n"
        "compute asum all reduce sum c_bends inputs local\n"
        "thermo_style custom step ebond eangle c_esum c_asum\nthermo_modify norm no\n"
        "run 0 post no");
  EXPECT_NEAR(s.thermo("c_esum"), s.thermo("ebond"), 1.0e-12 * s.thermo("ebond"));
  EXPECT_NEAR(s.thermo("c_asum"), s.thermo("eangle"), 1.0e-12 * s.thermo("eangle"));
}
}    // namespace

TEST(CellMechanics, SingleMatchesCompute)
{
  expect_single_sums_match_compute(*deformed_tissue());
}

// P = -dU/dA for an affine deformation at zero temperature; pxx = -(1/Ly) dU/dLx.
TEST(CellMechanics, PressureMatchesBoxDerivative)
{
  auto s = deformed_tissue();
  const double press = s->thermo("press"), pxx = s->thermo("pxx"), pyy = s->thermo("pyy");
  const double lx = s->equal_variable("lx"), ly = s->equal_variable("ly");
  ASSERT_GT(std::fabs(press), 1.0e-4) << "the perturbed tissue should be under stress";

  const double e = 1.0e-5;
  auto scale_energy = [&](double sx, double sy) {
    return energy_after_scaling(*s, sx, sy);
  };

  const double iso_up = scale_energy(1.0 + e, 1.0 + e), iso_down = scale_energy(1.0 - e, 1.0 - e);
  const double area_up = lx * ly * (1.0 + e) * (1.0 + e),
               area_down = lx * ly * (1.0 - e) * (1.0 - e);
  const double p_numeric = -(iso_up - iso_down) / (area_up - area_down);
  EXPECT_NEAR(press, p_numeric, 1.0e-7 * std::fabs(press));

  const double x_up = scale_energy(1.0 + e, 1.0), x_down = scale_energy(1.0 - e, 1.0);
  const double pxx_numeric = -(x_up - x_down) / (2.0 * e * lx * ly);
  EXPECT_NEAR(pxx, pxx_numeric, 1.0e-7 * std::fabs(pxx));

  const double y_up = scale_energy(1.0, 1.0 + e), y_down = scale_energy(1.0, 1.0 - e);
  const double pyy_numeric = -(y_up - y_down) / (2.0 * e * lx * ly);
  EXPECT_NEAR(pyy, pyy_numeric, 1.0e-7 * std::fabs(pyy));
}

TEST(CellMechanics, NoNetForceOrTorque)
{
  auto s = deformed_tissue();
  s->run("compute unwrapped all property/atom xu yu\n"
         "variable torque atom c_unwrapped[1]*fy-c_unwrapped[2]*fx\ncompute net all reduce sum fx "
         "fy v_torque\n"
         "thermo_style custom step pe c_net[*]\nrun 0 post no");
  const double scale = max_abs(s->gather("f", 3));
  EXPECT_NEAR(s->equal_variable("c_net[1]"), 0.0, 1.0e-12 * scale);
  EXPECT_NEAR(s->equal_variable("c_net[2]"), 0.0, 1.0e-12 * scale);
  EXPECT_NEAR(s->equal_variable("c_net[3]"), 0.0, 1.0e-11 * scale);
}

TEST(CellMechanics, NewtonBondOnAndOffAgree)
{
  auto on = deformed_tissue({"on", 1.0, 1.0, 0.4});
  auto off = deformed_tissue({"off", 1.0, 1.0, 0.4});
  EXPECT_NEAR(on->thermo("pe"), off->thermo("pe"), 1.0e-13 * std::fabs(on->thermo("pe")));
  EXPECT_NEAR(on->thermo("press"), off->thermo("press"), 1.0e-12 * std::fabs(on->thermo("press")));
  EXPECT_LT(relative_force_error(on->gather("f", 3), off->gather("f", 3)), 1.0e-13);
}

// On several ranks: each rank also runs the same system alone, as the reference.
TEST(CellMechanics, ParallelRunMatchesSerialRun)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto parallel = deformed_tissue();
  auto serial = deformed_tissue(Model(), self_comm());
  for (const char *keyword : {"pe", "ebond", "eangle", "f_cells", "press", "pxx", "pyy", "pxy"})
    EXPECT_NEAR(parallel->thermo(keyword), serial->thermo(keyword),
                1.0e-12 * std::max(1.0, std::fabs(serial->thermo(keyword))))
        << keyword;
  EXPECT_LT(relative_force_error(serial->gather("f", 3), parallel->gather("f", 3)), 1.0e-12);
}

TEST(CellMechanics, RestartPreservesStateAndEnergy)
{
  const std::string restart = scratch("cells.restart");
  auto before = deformed_tissue();
  before->run("write_restart " + restart);

  LammpsSession after;
  after.run("read_restart " + restart + "\n" + VERTEX_STATE +
            "comm_modify cutoff 2.0\nfix cells all dpoly/cells eps_a 1.0\n"
            "thermo_style custom step pe ebond eangle f_cells press\nthermo_modify norm no\n"
            "run 0 post no");
  for (const char *name : {"x", "d_sigma", "d_l0", "d_theta0", "d_a0"}) {
    const int count = std::string(name) == "x" ? 3 : 1;
    EXPECT_EQ(before->gather(name, count), after.gather(name, count)) << name;
  }
  for (const char *keyword : {"pe", "ebond", "eangle", "f_cells", "press"})
    EXPECT_EQ(before->thermo(keyword), after.thermo(keyword)) << keyword;
  if (world_size() == 1) remove(restart.c_str());
}

TEST(CellMechanics, DataFileRoundTripPreservesStateAndEnergy)
{
  const std::string data = scratch("cells.data");
  auto before = deformed_tissue();
  before->run("write_data " + data);

  LammpsSession after;
  after.run(setup_commands(data) + "run 0 post no");
  for (const char *name : {"x", "d_sigma", "d_l0", "d_theta0", "d_a0"}) {
    const int count = std::string(name) == "x" ? 3 : 1;
    EXPECT_EQ(before->gather(name, count), after.gather(name, count)) << name;
  }
  for (const char *keyword : {"pe", "ebond", "eangle", "f_cells", "press"})
    EXPECT_EQ(before->thermo(keyword), after.thermo(keyword)) << keyword;
}

// A regular ring with theta0 = 2 pi/n, uniform l0 and a0 above its area stays regular and
// settles at the circumradius R that minimizes
//   U(R) = (eps_a/2)(a(R)/a0 - 1)^2 + n (eps_l/2)(l(R)/l0 - 1)^2,
//   a(R) = (n/2) R^2 sin(2 pi/n),  l(R) = 2 R sin(pi/n).
TEST(CellMechanics, SingleCellRelaxesToAnalyticState)
{
  LammpsSession s;
  s.run(setup_commands(data_file("single.data")));
  const int n = s.natoms();
  const double a0 = 1.6, l0 = s.gather("d_l0", 1)[0];
  s.run("set group all d_a0 1.6\nmin_style cg\nminimize 0.0 1.0e-13 20000 200000");

  const double ca = 0.5 * n * sin(2.0 * PI / n), cl = 2.0 * sin(PI / n);
  auto slope = [&](double r) {
    return (ca * r * r / a0 - 1.0) * 2.0 * ca * r / a0 + n * (cl * r / l0 - 1.0) * cl / l0;
  };
  double lo = 0.1, hi = 3.0;
  for (int it = 0; it < 200; it++) {
    const double mid = 0.5 * (lo + hi);
    (slope(mid) > 0.0 ? hi : lo) = mid;
  }
  const double radius = 0.5 * (lo + hi);

  EXPECT_NEAR(s.equal_variable("f_cells[2]"), ca * radius * radius, 1.0e-8);
  const std::vector<double> x = s.gather("x", 3);
  for (int k = 0; k < n; k++) {
    const int next = (k + 1) % n;
    EXPECT_NEAR(std::hypot(x[3 * next] - x[3 * k], x[3 * next + 1] - x[3 * k + 1]), cl * radius,
                1.0e-8);
  }
  EXPECT_NEAR(s.thermo("eangle"), 0.0, 1.0e-14);
}

// ---------------------------------------------------------------------------------------
// Per-vertex stiffness factors d_kl (segment to the next vertex) and d_kb (bending at the vertex)
// multiply the types' eps_l and eps_b; without them every factor is 1.

namespace {

const char *STIFFNESS_STATE = "fix Stiffness all property/atom d_kl d_kb ghost yes\n";
// factors that differ from vertex to vertex, deterministic in the atom ID
const char *VARIED_FACTORS = "variable kl atom 1.0+0.6*sin(2.1*id)\n"
                             "variable kb atom 1.0+0.5*cos(1.3*id)\n"
                             "set group all d_kl v_kl\nset group all d_kb v_kb\n";

std::unique_ptr<LammpsSession> deformed_tissue_with_factors(const Model &m = Model())
{
  auto s = std::make_unique<LammpsSession>();
  s->run(setup_commands(data_file("deformed.data"), m));
  s->run(std::string(PERTURB_STATE) + STIFFNESS_STATE + VARIED_FACTORS + "run 0 post no");
  return s;
}

}    // namespace

TEST(CellMechanics, StiffnessFactorsMatchFiniteDifferences)
{
  for (const Model &m : {Model(), Model{"on", 0.0, 1.0, 0.0}, Model{"on", 0.0, 0.0, 1.0},
                         Model{"off", 1.0, 1.0, 0.4}}) {
    SCOPED_TRACE("eps_l " + std::to_string(m.eps_l) + ", eps_b " + std::to_string(m.eps_b) +
                 ", newton_bond " + m.newton_bond);
    auto s = deformed_tissue_with_factors(m);
    EXPECT_LT(finite_difference_error(*s), 1.0e-7);
  }
}

// The factor of a segment is its first vertex's, the factor of a bending term its centre's:
// one segment and one vertex of a regular 16-gon differ from the rest.
TEST(CellMechanics, StiffnessFactorsBelongToTheSegmentsFirstVertex)
{
  LammpsSession s;
  s.run(setup_commands(data_file("single.data")) + STIFFNESS_STATE +
        "set group all d_kl 1.0\nset group all d_kb 1.0\n"
        "set group all d_l0 0.31\nset atom 1 d_l0 0.5\nset atom 1 d_kl 3.0\nset atom 16 d_kl 0.2\n"
        "variable th0 atom d_theta0+0.05\nset group all d_theta0 v_th0\n"
        "set atom 1 d_theta0 0.1\nset atom 1 d_kb 2.5\nset atom 2 d_kb 0.5\nrun 0 post no");
  const int n = s.natoms();
  const std::vector<double> x = s.gather("x", 3);
  const double length = std::hypot(x[3] - x[0], x[4] - x[1]);
  auto segment = [&](double l0) {
    return 0.5 * std::pow(length / l0 - 1.0, 2);
  };
  // segment 1 -> 2 has l0 0.5 and factor 3, segment 16 -> 1 factor 0.2, the rest factor 1
  EXPECT_NEAR(s.thermo("ebond"), 3.0 * segment(0.5) + (0.2 + n - 2) * segment(0.31), 1.0e-13);
  // vertex 1: theta - theta0 = 2 pi/n - 0.1, factor 2.5; vertex 2: 0.05, factor 0.5
  const double bend = 0.5 * 0.4 * 0.05 * 0.05, first = 2.0 * PI / n - 0.1;
  EXPECT_NEAR(s.thermo("eangle"), 2.5 * 0.5 * 0.4 * first * first + (0.5 + n - 2) * bend, 1.0e-13);
}

// Factors of 1 change nothing, to the last bit: inputs without d_kl and d_kb are the same model.
TEST(CellMechanics, UnitStiffnessFactorsChangeNothing)
{
  auto plain = deformed_tissue();
  auto ones = deformed_tissue();
  ones->run(std::string(STIFFNESS_STATE) +
            "set group all d_kl 1.0\nset group all d_kb 1.0\n"
            "run 0 post no");
  EXPECT_EQ(ones->gather("f", 3), plain->gather("f", 3));
  for (const char *keyword : {"pe", "ebond", "eangle", "press"})
    EXPECT_EQ(ones->thermo(keyword), plain->thermo(keyword)) << keyword;
}

TEST(CellMechanics, StiffnessFactorsInSingle)
{
  expect_single_sums_match_compute(*deformed_tissue_with_factors());
}

TEST(CellMechanics, StiffnessFactorsSurviveRestartAndDataFile)
{
  const std::string restart = scratch("factors.restart"), data = scratch("factors.data");
  auto before = deformed_tissue_with_factors();
  before->run("write_restart " + restart + "\nwrite_data " + data);

  LammpsSession restarted;
  restarted.run("read_restart " + restart + "\n" + VERTEX_STATE + STIFFNESS_STATE +
                "comm_modify cutoff 2.0\nfix cells all dpoly/cells eps_a 1.0\n"
                "thermo_style custom step pe ebond eangle f_cells press\nthermo_modify norm no\n"
                "run 0 post no");
  // the data file holds the factors as a section named after their fix
  std::string read = setup_commands(data);
  read.replace(read.find("read_data"), 0, STIFFNESS_STATE);
  read.replace(read.find(" fix Vertices NULL Vertices"), 0, " fix Stiffness NULL Stiffness");
  LammpsSession reread;
  reread.run(read + "run 0 post no");
  for (LammpsSession *after : {&restarted, &reread}) {
    for (const char *name : {"x", "d_l0", "d_theta0", "d_kl", "d_kb"}) {
      const int count = std::string(name) == "x" ? 3 : 1;
      EXPECT_EQ(before->gather(name, count), after->gather(name, count)) << name;
    }
    for (const char *keyword : {"pe", "ebond", "eangle", "press"})
      EXPECT_EQ(before->thermo(keyword), after->thermo(keyword)) << keyword;
  }
  if (world_size() == 1) remove(restart.c_str());
}

// ---------------------------------------------------------------------------------------
// Bad input: each gets an error that names the problem. Single rank: some are per-atom errors.

namespace {

// One cell of four vertices; 'angles' lists (prev, vertex, next) per line.
const char *RING_BONDS = "1 1 1 2\n2 1 2 3\n3 1 3 4\n4 1 4 1\n";

std::string square_data(const std::string &angles, int nangles = 4,
                        const std::string &bonds = RING_BONDS)
{
  const std::string path = scratch("square.data");
  FILE *fp = fopen(path.c_str(), "w");
  fprintf(fp,
          "square\n\n4 atoms\n1 atom types\n4 bonds\n1 bond types\n%d angles\n1 angle types\n\n"
          "0 4 xlo xhi\n0 4 ylo yhi\n-0.5 0.5 zlo zhi\n\nMasses\n\n1 1\n\nAtoms # molecular\n\n"
          "1 1 1 1 1 0\n2 1 1 2 1 0\n3 1 1 2 2 0\n4 1 1 1 2 0\n\n"
          "Bonds\n\n%s\nAngles\n\n%s\n"
          "Vertices\n\n1 1 1 1.5708 1\n2 1 1 1.5708 1\n3 1 1 1.5708 1\n4 1 1 1.5708 1\n",
          nangles, bonds.c_str(), angles.c_str());
  fclose(fp);
  return path;
}

const char *CCW_ANGLES = "1 1 4 1 2\n2 1 1 2 3\n3 1 2 3 4\n4 1 3 4 1\n";

}    // namespace

class BadInput : public ErrorTest {};

TEST_F(BadInput, StiffnessFactors)
{
  const std::string base = setup_commands(square_data(CCW_ANGLES)) + STIFFNESS_STATE;
  // a new fix property/atom holds zeros: a factor must be set
  EXPECT_THAT(error_of(base + "set group all d_kb 1.0\nrun 0 post no"),
              HasSubstr("d_kl of vertex 1 is not positive"));
  EXPECT_THAT(error_of(base +
                       "set group all d_kl 1.0\nset group all d_kb 1.0\n"
                       "set atom 3 d_kb -2\nrun 0 post no"),
              HasSubstr("d_kb of vertex 3 is not positive"));
  std::string no_ghosts = base + "set group all d_kl 1.0\nset group all d_kb 1.0\nrun 0 post no";
  no_ghosts.replace(no_ghosts.find("d_kl d_kb ghost yes"), 19, "d_kl d_kb");
  EXPECT_THAT(error_of(no_ghosts), HasSubstr("needs d_kl on ghost atoms too"));
}

TEST_F(BadInput, ValidSquareIsAccepted)
{
  EXPECT_EQ(error_of(setup_commands(square_data(CCW_ANGLES)) + "run 0 post no"), "");
}

TEST_F(BadInput, ThreeDimensions)
{
  std::string cmds = setup_commands(square_data(CCW_ANGLES)) + "run 0 post no";
  cmds.replace(cmds.find("dimension 2"), 11, "dimension 3");
  EXPECT_THAT(error_of(cmds), HasSubstr("needs a 2d simulation"));
}

TEST_F(BadInput, VertexStateWithoutGhosts)
{
  std::string cmds = setup_commands(square_data(CCW_ANGLES)) + "run 0 post no";
  cmds.replace(cmds.find(" ghost yes"), 10, "");
  const std::string msg = error_of(cmds);
  EXPECT_THAT(msg, HasSubstr("on ghost atoms too"));
}

TEST_F(BadInput, NonPositiveStateValues)
{
  const std::string base = setup_commands(square_data(CCW_ANGLES));
  std::string msg = error_of(base + "set atom 3 d_a0 -0.5\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("a0 = -0.5"));
  msg = error_of(base + "set group all d_a0 0\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("a0 = 0;")) << msg;
  msg = error_of(base + "set atom 2 d_l0 0\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("vertex 2 has l0 = 0"));
  msg = error_of(base + "set atom 4 d_sigma -1\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("vertex 4 has sigma = -1"));
}

// Rings and vertex state the hub refuses, each with the error that names the fault.
TEST_F(BadInput, RingsTheHubRefuses)
{
  const struct {
    const char *fault, *angles;
    int nangles;
    const char *bonds, *commands, *error;
  } cases[] = {
      {"no vertex state", CCW_ANGLES, 4, RING_BONDS, "unfix Vertices\n",
       "needs the per-atom property d_sigma"},
      {"a0 differs within a cell", CCW_ANGLES, 4, RING_BONDS, "set atom 2 d_a0 2.0\n",
       "cell 1 has different a0"},
      {"a vertex with two angles", "1 1 4 1 2\n2 1 1 2 3\n3 1 2 3 4\n4 1 3 4 1\n5 1 1 2 4\n", 5,
       RING_BONDS, "", "vertex 2 is the centre of 2 angles"},
      // vertex 4 points back to 3 instead of on to 1
      {"a ring that does not close", "1 1 4 1 2\n2 1 1 2 3\n3 1 2 3 4\n4 1 1 4 3\n", 4, RING_BONDS,
       "", "not a vertex of the same ring pointing back"},
      {"a ring split between two cells", CCW_ANGLES, 4, RING_BONDS, "set atom 3*4 mol 2\n",
       "not a vertex of the same ring"},
      {"a clockwise ring", "1 1 2 1 4\n2 1 3 2 1\n3 1 4 3 2\n4 1 1 4 3\n", 4, RING_BONDS, "",
       "cell 1 has area -1 <= 0"},
      {"a bond across the ring", CCW_ANGLES, 4, "1 1 1 2\n2 1 2 3\n3 1 3 4\n4 1 1 3\n", "",
       "bond 1-3 is not a segment of a ring"},
  };
  for (const auto &c : cases) {
    SCOPED_TRACE(c.fault);
    EXPECT_THAT(error_of(setup_commands(square_data(c.angles, c.nangles, c.bonds)) + c.commands +
                         "run 0 post no"),
                HasSubstr(c.error));
  }
}

TEST_F(BadInput, RingOfTwoVertices)
{
  const std::string path = scratch("pair.data");
  if (world_size() == 1) {
    FILE *fp = fopen(path.c_str(), "w");
    fprintf(fp,
            "two\n\n2 atoms\n1 atom types\n1 bonds\n1 bond types\n2 angles\n1 angle types\n\n"
            "0 4 xlo xhi\n0 4 ylo yhi\n-0.5 0.5 zlo zhi\n\nMasses\n\n1 1\n\n"
            "Atoms # molecular\n\n1 1 1 1 1 0\n2 1 1 2 1 0\n\nBonds\n\n1 1 1 2\n\n"
            "Angles\n\n1 1 2 1 2\n2 1 1 2 1\n\nVertices\n\n1 1 1 0 1\n2 1 1 0 1\n");
    fclose(fp);
  }
  // a ring of two needs angles that repeat an atom, which LAMMPS refuses when reading them
  const std::string msg = error_of(setup_commands(path) + "run 0 post no");
  EXPECT_THAT(msg, HasSubstr("Invalid atom ID in Angles section"));
}

TEST_F(BadInput, BadCoefficientsAndKeywords)
{
  expect_errors(setup_commands(square_data(CCW_ANGLES)),
                {{"bond_coeff 1 -2", "eps_l must be >= 0, got -2"},
                 {"bond_coeff 1 1 2", "takes one coefficient"},
                 {"angle_coeff 1 -0.1", "eps_b must be >= 0, got -0.1"},
                 {"fix more all dpoly/cells eps_a -3", "eps_a must be >= 0, got -3"},
                 {"fix more all dpoly/cells stiff 3", "keyword: stiff"},
                 {"fix more all dpoly/cells\nrun 0", "Only one fix dpoly/cells"},
                 {"fix_modify cells energy no\nrun 0", "must count in both"}});
}

TEST_F(BadInput, BoxRelaxNeedsLineSearchAndPeriodicBox)
{
  const std::string base = setup_commands(square_data(CCW_ANGLES));
  std::string msg =
      error_of(base + "fix relax all box/relax iso 0.001\nmin_style fire\nminimize 0 1e-8 10 10");
  EXPECT_THAT(msg, HasSubstr("Cannot use a damped dynamics min style with fix box/relax"));
  std::string fixed = base + "fix relax all box/relax iso 0.001\nminimize 0 1e-8 10 10";
  fixed.replace(fixed.find("boundary p p p"), 14, "boundary f p p");
  msg = error_of(fixed);
  EXPECT_THAT(msg, HasSubstr("non-periodic x dimension"));
}
