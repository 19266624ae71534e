// compute dpoly/hessian: the analytic Hessian against finite differences of LAMMPS's own forces,
// and the zero modes of cases whose count is known.
#include "test_helpers.h"

#include "gtest/gtest.h"

using namespace test;

namespace {

// The Hessian of the session's tissue against -dF_a/dx_b by central differences, h = 1e-6.
void expect_hessian_matches_forces(LammpsSession &s)
{
  s.run("compute hessian all dpoly/hessian\nrun 0 post no");
  const int n = s.natoms(), ndof = 2 * n;
  const std::vector<double> H = s.global_array("hessian", ndof, ndof);

  std::vector<double> x0 = s.gather("x", 3);
  const double h = 1.0e-6;
  double worst = 0.0, largest = 0.0;
  for (int b = 0; b < ndof; b++) {
    const int atom = b / 2, dim = b % 2;
    std::vector<double> x = x0;
    x[3 * atom + dim] = x0[3 * atom + dim] + h;
    s.scatter("x", 3, x);
    s.run("run 0 post no");
    const std::vector<double> plus = s.gather("f", 3);
    x[3 * atom + dim] = x0[3 * atom + dim] - h;
    s.scatter("x", 3, x);
    s.run("run 0 post no");
    const std::vector<double> minus = s.gather("f", 3);
    for (int a = 0; a < ndof; a++) {
      const double fd = -(plus[3 * (a / 2) + a % 2] - minus[3 * (a / 2) + a % 2]) / (2 * h);
      worst = std::max(worst, std::fabs(fd - H[(size_t) a * ndof + b]));
      largest = std::max(largest, std::fabs(H[(size_t) a * ndof + b]));
    }
  }
  s.scatter("x", 3, x0);
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 1.0e-6 * largest) << "largest entry " << largest;
  for (int a = 0; a < ndof; a++)
    for (int b = 0; b < a; b++)
      ASSERT_EQ(H[(size_t) a * ndof + b], H[(size_t) b * ndof + a]) << "symmetric";
}

}    // namespace

// Every term at once: deformed rings (area, segments, bending), overlaps (contacts) and, after a
// 3% dilation, stretched adhesive bonds.
TEST(Hessian, MatchesFiniteDifferencesOfTheForces)
{
  // 576 force evaluations: too many for 4 ranks on a 2-core machine; ranks are covered below
  if (world_size() > 2) GTEST_SKIP() << "runs on 1 and 2 ranks";
  LammpsSession s;
  s.run(contact_commands(data_file("overlapping.data")) +
        "adhere_cells all 2\nchange_box all x scale 1.03 y scale 1.03 remap\n");
  expect_hessian_matches_forces(s);
}

// The same with per-vertex factors of eps_l and eps_b (d_kl, d_kb) that differ from vertex to
// vertex, on four small rings away from their preferred shapes.
TEST(Hessian, StiffnessFactorsMatchFiniteDifferences)
{
  LammpsSession s;
  s.run("units lj\ndimension 2\natom_style molecular\natom_modify map array\nboundary p p p\n"
        "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
        "fix Stiffness all property/atom d_kl d_kb ghost yes\n"
        "bond_style dpoly/segment\nangle_style dpoly/bending\nread_data " +
        data_file("deformed.data") +
        " fix Vertices NULL Vertices\nbond_coeff * 1.0\nangle_coeff * 0.4\n"
        "comm_modify cutoff 2.0\nfix cells all dpoly/cells eps_a 1.0\n"
        "variable l0 atom d_l0*(1.0+0.15*sin(3.7*id))\nset group all d_l0 v_l0\n"
        "variable th0 atom d_theta0+0.3*cos(2.3*id)\nset group all d_theta0 v_th0\n"
        "variable kl atom 1.0+0.6*sin(2.1*id)\nvariable kb atom 1.0+0.5*cos(1.3*id)\n"
        "set group all d_kl v_kl\nset group all d_kb v_kb\n");
  expect_hessian_matches_forces(s);
}

// Assembled on rank 0 from records sorted by atom ID: the same matrix on any number of ranks.
TEST(Hessian, SameOnAnyNumberOfRanks)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  const std::string commands = contact_commands(data_file("overlapping.data")) +
      "adhere_cells all 2\nchange_box all x scale 1.03 y scale 1.03 remap\n"
      "compute hessian all dpoly/hessian\nrun 0 post no";
  ParallelAndSerial runs(commands);
  LammpsSession &parallel = runs.parallel, &serial = runs.serial;
  const int ndof = 2 * serial.natoms();
  EXPECT_EQ(parallel.global_array("hessian", ndof, ndof),
            serial.global_array("hessian", ndof, ndof));
}

// A relaxed regular ring alone in a periodic box: besides the two translations, one zero mode,
// the rotation; everything else is stiff.
TEST(Hessian, RelaxedRingHasOnlyItsRotationAsZeroMode)
{
  LammpsSession s;
  s.run(contact_commands(data_file("single_contacts.data")) +
        "compute hessian all dpoly/hessian modes 4\nmin_style cg\n"
        "minimize 0.0 1.0e-13 10000 100000\nrun 0 post no");
  EXPECT_EQ(s.thermo("c_hessian"), 1.0);
  EXPECT_LT(std::fabs(s.thermo("c_hessian[3]")), 1e-8);
  EXPECT_GT(s.thermo("c_hessian[4]"), 1e-4) << "the lowest shape mode is stiff";
}

// Two relaxed rings that do not touch: each moves and turns freely, so 6 rigid modes less the two
// global translations.
TEST(Hessian, TwoFreeRingsHaveFourZeroModes)
{
  Tissue t;
  for (double cx : {10.0, 15.0}) {
    Polygon ring;
    for (int k = 0; k < 12; k++)
      ring.corners.push_back({cx + cos(2 * PI * k / 12), 10.0 + sin(2 * PI * k / 12)});
    t.cells.push_back(ring);
  }
  t.sigma = 0.3;
  LammpsSession s;
  s.run(contact_commands(write_tissue(t, "two_free_rings.data")) +
        "compute hessian all dpoly/hessian modes 7\nrun 0 post no");
  EXPECT_EQ(s.thermo("c_hessian"), 4.0);
  EXPECT_GT(s.thermo("c_hessian[7]"), 1e-4);
}

TEST(Hessian, BadInput)
{
  if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  auto error_of = [](const std::string &line) {
    LammpsSession s;
    return s.try_run(contact_commands(data_file("single_contacts.data")) + line +
                     "\nrun 0 post no\nvariable probe equal c_h");
  };
  EXPECT_NE(error_of("compute h all dpoly/hessian modes 0").find("modes must be >= 1, got 0"),
            std::string::npos);
  EXPECT_NE(error_of("compute h all dpoly/hessian shift 2").find("keyword: shift"),
            std::string::npos);
  EXPECT_NE(error_of("group some id 1 2\ncompute h some dpoly/hessian").find("needs group all"),
            std::string::npos);
  LammpsSession s;
  const std::string msg =
      s.try_run(contact_commands(data_file("single_contacts.data")) +
                "compute h all dpoly/hessian max_dof 10\nrun 0 post no\nprint \"$(c_h)\"");
  EXPECT_NE(msg.find("32 degrees of freedom exceed max_dof 10"), std::string::npos) << msg;
}
