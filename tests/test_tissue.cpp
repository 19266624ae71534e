// Tissue observables of compute dpoly/tissue against analytic values and against the other
// styles' own counts. Runs on any number of ranks.
#include "test_helpers.h"

#include "gtest/gtest.h"

#include <memory>

using namespace test;

// One regular 16-gon alone: phi, patch phi, shape parameter, no neighbours, all vertices void.
TEST(TissueObservables, RegularPolygonIsAnalytic)
{
  LammpsSession s;
  s.run(contact_commands(data_file("single_contacts.data")) +
        "compute tissue all dpoly/tissue\nthermo_style custom step pe c_tissue[*]\n"
        "run 0 post no");
  const int n = s.natoms();
  const std::vector<double> x = s.gather("x", 3);
  const double radius = std::hypot(x[0] - x[3 * (n / 2)], x[1] - x[3 * (n / 2) + 1]) / 2.0;
  const double sigma = s.gather("d_sigma", 1)[0];
  const double box = s.equal_variable("lx*ly");
  const double pushed = radius + 0.5 * sin(PI / 3.0) * sigma;

  EXPECT_NEAR(s.thermo("c_tissue[1]"), 0.5 * n * radius * radius * sin(2 * PI / n) / box, 1e-13);
  EXPECT_NEAR(s.thermo("c_tissue[2]"), 0.5 * n * pushed * pushed * sin(2 * PI / n) / box, 1e-13);
  EXPECT_NEAR(s.thermo("c_tissue[3]"), n * tan(PI / n) / PI, 1e-12);
  EXPECT_EQ(s.thermo("c_tissue[4]"), 0.0);
  EXPECT_EQ(s.thermo("c_tissue[5]"), 0.0);
  EXPECT_EQ(s.thermo("c_tissue[6]"), 1.0);
  s.run("thermo_style custom step c_tissue[1][6]\nrun 0 post no");
  EXPECT_EQ(s.thermo("c_tissue[1][6]"), 1.0) << "with no bonds every vertex faces the void";
}

// A 3x3 periodic lattice of touching cells: each touches its four lattice neighbours, before
// and after bonding; the bond count is adhere_cells' count; the void fraction matches the
// per-vertex bond counts of compute dpoly/adhesion.
TEST(TissueObservables, LatticeNeighboursBondsAndVoids)
{
  LammpsSession s;
  s.run(contact_commands(data_file("overlapping.data")) +
        "compute tissue all dpoly/tissue\ncompute adhesion all dpoly/adhesion\n"
        "variable void atom c_adhesion==0\ncompute voids all reduce sum v_void\n"
        "thermo_style custom step c_tissue[*] c_voids\nrun 0 post no");
  EXPECT_EQ(s.thermo("c_tissue[4]"), 4.0);
  EXPECT_EQ(s.thermo("c_tissue[6]"), 9.0);
  s.run("adhere_cells all 2\nrun 0 post no");
  EXPECT_EQ(s.thermo("c_tissue[4]"), 4.0);
  EXPECT_EQ(s.thermo("c_tissue[5]"), s.thermo("bonds") - s.natoms());
  double void_fraction_sum = 0.0;
  s.run("thermo_style custom step c_tissue[*][6] c_voids\nrun 0 post no");
  for (int row = 1; row <= 9; row++)
    void_fraction_sum += s.thermo("c_tissue[" + std::to_string(row) + "][6]");
  // every cell has 16 vertices
  EXPECT_NEAR(void_fraction_sum * 16.0, s.thermo("c_voids"), 1e-9);
  EXPECT_GT(s.thermo("c_voids"), 0.0);
  EXPECT_LT(s.thermo("c_voids"), s.natoms());
}

TEST(TissueObservables, ParallelRunMatchesSerialRun)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto observe = [](MPI_Comm comm) {
    auto s = std::make_unique<LammpsSession>(comm);
    s->run(contact_commands(data_file("overlapping.data")) +
           "adhere_cells all 2\ncompute tissue all dpoly/tissue\n"
           "thermo_style custom step c_tissue[*]\nrun 0 post no");
    std::vector<double> values;
    for (int k = 1; k <= 6; k++) values.push_back(s->thermo("c_tissue[" + std::to_string(k) + "]"));
    return values;
  };
  const std::vector<double> parallel = observe(MPI_COMM_WORLD), serial = observe(self_comm());
  for (int k = 0; k < 6; k++)
    EXPECT_NEAR(parallel[k], serial[k], 1e-12 * std::fabs(serial[k])) << k;
}

// compute dpoly/vertex on a regular polygon made from the molecule template of
// tools/make_cells.py: every turning angle is 2 pi/n, every segment the same, the area is a0.
TEST(VertexObservables, RegularPolygonFromMoleculeTemplate)
{
  LammpsSession s;
  s.run("units lj\ndimension 2\natom_style molecular\natom_modify map array\nboundary p p p\n"
        "region box block 0 6 0 6 -0.5 0.5\n"
        "create_box 1 box bond/types 1 angle/types 1 extra/bond/per/atom 2 "
        "extra/angle/per/atom 1 extra/special/per/atom 10\nmass 1 1.0\n"
        "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
        "molecule ring " +
        data_file("ring12.mol") +
        "\n"
        "create_atoms 0 single 3 3 0 mol ring 1\n"
        "set group all d_sigma 0.3\nset group all d_l0 0.3\nset group all d_theta0 0.5\n"
        "set group all d_a0 1.0\nbond_style dpoly/segment\nbond_coeff * 1\n"
        "angle_style dpoly/bending\nangle_coeff * 1\ncomm_modify cutoff 2.0\n"
        "fix cells all dpoly/cells\ncompute vertex all dpoly/vertex\n"
        "compute theta all reduce max c_vertex[1]\ncompute theta_min all reduce min c_vertex[1]\n"
        "compute length all reduce max c_vertex[2]\n"
        "variable next_error atom abs(c_vertex[3]-((id%12)+1))\n"    // the template runs CCW
        "compute next_error all reduce max v_next_error\n"
        "thermo_style custom step pe c_theta c_theta_min c_length f_cells[2] c_next_error\n"
        "run 0 post no");
  const int n = 12;
  const double radius = sqrt(2.0 / (n * sin(2 * PI / n)));
  EXPECT_NEAR(s.thermo("c_theta"), 2 * PI / n, 1e-12);
  EXPECT_NEAR(s.thermo("c_theta_min"), 2 * PI / n, 1e-12);
  EXPECT_NEAR(s.thermo("c_length"), 2 * radius * sin(PI / n), 1e-12);
  EXPECT_NEAR(s.thermo("f_cells[2]"), 1.0, 1e-12);
  EXPECT_EQ(s.thermo("c_next_error"), 0.0) << "column 3 names the next vertex along the ring";
}

// Molecule IDs far above the cell count (10000 + k, beyond 4 n + 1024) take the hub's sparse
// molecule -> cell index; every cell must still be found: the same energy, pressure and tissue
// observables as with the original IDs 1..16, at the start and after 50 iterations.
TEST(TissueObservables, SparseMoleculeIdsGiveTheSameTissue)
{
  auto observe = [](const std::string &renumber) {
    LammpsSession s;
    s.run(tissue16_commands() + renumber +
          "compute tissue all dpoly/tissue\n"
          "thermo_style custom step pe press lx c_tissue[*]\nrun 0 post no");
    std::vector<double> values;
    auto record = [&]() {
      for (const char *name : {"pe", "press", "lx"}) values.push_back(s.thermo(name));
      for (int k = 1; k <= 6; k++) values.push_back(s.thermo("c_tissue[" + std::to_string(k) + "]"));
    };
    record();
    s.run("minimize 0.0 1.0e-8 50 500");
    record();
    return values;
  };
  const std::vector<double> dense = observe("");
  const std::vector<double> sparse =
      observe("variable sparse_mol atom mol+10000\nset group all mol v_sparse_mol\n");
  ASSERT_EQ(dense.size(), sparse.size());
  for (size_t k = 0; k < dense.size(); k++)
    EXPECT_NEAR(sparse[k], dense[k], 1e-12 * std::fabs(dense[k]) + 1e-15) << "value " << k;
}
