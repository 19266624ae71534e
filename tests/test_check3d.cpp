// fix dpoly/check under fix dpoly3d/cells: hand-made failures of polyhedra are reported (an
// inverted icosahedron, a flattened one, a vertex pushed through its own cell's surface, a
// non-finite position, a vertex of one cell inside another), sound cells pass, and the winding
// number that decides "inside" is 1 inside a closed surface and 0 outside.
#include "test_helpers.h"

#include "dpoly3d_surface_check.h"
#include "fix_dpoly_stage.h"
#include "lammps.h"
#include "modify.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using ::testing::HasSubstr;
using ::testing::Not;

using namespace test;

namespace {

// A checked minimum, near the cells of the data file.
std::string checked(const std::string &data, const std::string &options = "")
{
  return polyhedra_commands(data_file(data)) + "fix check all dpoly/check " + options +
      "\nmin_style fire\nminimize 0.0 1.0e-3 1000 10000\n";
}

// A checked minimum of the cells of a data file, whose positions a test then moves by hand.
class Check3d : public ::testing::Test {
 protected:
  LammpsSession s;
  std::vector<double> x;    // the positions at the minimum, in ID order, for a test to move

  void minimize(const std::string &data, const std::string &options = "action error")
  {
    s.run(checked(data, options));
    x = s.gather("x", 3);
  }

  // the mean of the positions of atoms first..last (IDs) at the minimum
  std::vector<double> centroid(int first, int last) const
  {
    std::vector<double> c(3, 0.0);
    for (int id = first; id <= last; id++)
      for (int d = 0; d < 3; d++) c[d] += x[3 * (id - 1) + d] / (last - first + 1);
    return c;
  }

  // The check called on the moved positions, as after the next minimization: "" if it passes,
  // else its error ('action error').
  std::string check_moved()
  {
    s.scatter("x", 3, x);
    auto *lmp = static_cast<LAMMPS_NS::LAMMPS *>(s.lammps_handle());
    auto *check = dynamic_cast<LAMMPS_NS::FixDPolyStage *>(lmp->modify->get_fix_by_id("check"));
    if (!check) throw std::runtime_error("no fix check");
    try {
      check->act();
    } catch (std::exception &e) {
      return e.what();
    }
    return "";
  }
};

// A regular icosahedron of circumradius 1 (tools/make_cells3d.py): its volume.
const double ICOSAHEDRON_VOLUME = 5.0 / 12.0 * (3.0 + sqrt(5.0)) * pow(1.0 / sin(0.4 * PI), 3);

// the check's words for one cell of volume <= 0, its volume written as the check writes it
std::string collapsed_cell(double volume)
{
  char text[128];
  snprintf(text, sizeof(text),
           "; 1 cells have volume <= 0 or are flat (first: cell 1, volume %.6g)", volume);
  return text;
}

}    // namespace

TEST_F(Check3d, SoundIcosahedronPasses)
{
  minimize("icosahedron.data");
  EXPECT_EQ(s.thermo("f_check[1]"), 1.0) << "converged (no iterations, zero tolerances)";
  EXPECT_EQ(s.thermo("f_check[4]"), 0.0);
  EXPECT_EQ(s.thermo("f_check[5]"), 0.0);
  EXPECT_EQ(s.thermo("f_check[8]"), 0.0);
}

// Every vertex reflected through the centre: the same points, the opposite orientation, so the
// volume is -V and every face points into the cell.
TEST_F(Check3d, InvertedIcosahedronIsReported)
{
  minimize("icosahedron.data");
  const std::vector<double> c = centroid(1, 12);
  for (int i = 0; i < 12; i++)
    for (int d = 0; d < 3; d++) x[3 * i + d] = 2.0 * c[d] - x[3 * i + d];
  const std::string error = check_moved();
  EXPECT_THAT(error, HasSubstr(collapsed_cell(-ICOSAHEDRON_VOLUME)));
  EXPECT_THAT(error,
              HasSubstr("; 1 cells have faces that point into the cell (first: cell 1, "
                        "face "));
  EXPECT_THAT(error, Not(HasSubstr("interpenetrate")));
  EXPECT_EQ(s.thermo("f_check[4]"), 1.0);
  EXPECT_EQ(s.thermo("f_check[5]"), 1.0);
}

// All vertices on the plane z = centre: volume 0 (collapsed), and no face points inward (their
// normals lie in the plane), so only the volume test sees it.
TEST_F(Check3d, FlattenedIcosahedronIsReported)
{
  minimize("icosahedron.data");
  const std::vector<double> c = centroid(1, 12);
  for (int i = 0; i < 12; i++) x[3 * i + 2] = c[2];
  const std::string error = check_moved();
  EXPECT_THAT(error, HasSubstr("; 1 cells have volume <= 0 or are flat (first: cell 1, volume "));
  EXPECT_THAT(error, Not(HasSubstr("point into the cell")));
  EXPECT_EQ(s.thermo("f_check[4]"), 1.0);
  EXPECT_EQ(s.thermo("f_check[5]"), 0.0);
}

// Vertex 1 pushed into the cell, past the centre: a dented cell, not star-shaped (the centroid is
// on the outer side of the five faces around vertex 1), but sound: its surface does not cross
// itself, so it passes.
TEST_F(Check3d, DentedCellPasses)
{
  minimize("icosahedron.data");
  const std::vector<double> c = centroid(1, 12);
  for (int d = 0; d < 3; d++) x[d] = c[d] - 0.3 * (x[d] - c[d]);
  EXPECT_EQ(check_moved(), "");
  EXPECT_EQ(s.thermo("f_check[4]"), 0.0);
  EXPECT_EQ(s.thermo("f_check[5]"), 0.0);
}

// Vertex 1 pushed through the cell and out of the far side (to 2 circumradii beyond the centre):
// the spike comes out through the faces at the far side, and just outside them lies the spike,
// inside the cell (winding number -1): they are reported (the one named is the face, an angle
// a b c, with the lowest middle atom b); the volume stays positive.
TEST_F(Check3d, VertexPushedThroughItsCellIsReported)
{
  minimize("icosahedron.data");
  const std::vector<double> c = centroid(1, 12);
  for (int d = 0; d < 3; d++) x[d] = c[d] - 2.0 * (x[d] - c[d]);
  const std::string error = check_moved();
  EXPECT_THAT(error,
              HasSubstr("; 1 cells have faces that point into the cell (first: cell 1, "
                        "face "));
  EXPECT_THAT(error, Not(HasSubstr("volume <= 0")));
  EXPECT_EQ(s.thermo("f_check[4]"), 0.0);
  EXPECT_EQ(s.thermo("f_check[5]"), 1.0);
}

// LAMMPS stops a run with non-finite coordinates itself; a state that has one anyway (set by
// hand here) is named, and its geometry is not tested.
TEST_F(Check3d, NonFinitePositionIsReported)
{
  minimize("icosahedron.data");
  x[3 * 4 + 1] = std::numeric_limits<double>::quiet_NaN();    // vertex 5
  EXPECT_THAT(check_moved(), HasSubstr("; 1 vertices have non-finite positions (first: vertex 5)"));
  EXPECT_EQ(s.thermo("f_check[5]"), 0.0);
}

namespace {
// two jittered 42-vertex cells (IDs 1-42, 43-84) apart, across the periodic boundary
// (tests/make_test_data3d.py)
const char *TWO_CELLS = "cells3d_deformed.data";
}    // namespace

TEST_F(Check3d, SeparateCellsPass)
{
  minimize(TWO_CELLS);
  EXPECT_EQ(s.thermo("f_check[4]"), 0.0);
  EXPECT_EQ(s.thermo("f_check[5]"), 0.0);
  EXPECT_EQ(s.thermo("f_check[8]"), 0.0);
}

// Vertex 50 of cell 2 moved to cell 1's centre, shifted by one box length in x (the check
// takes the nearest image): one pair, named with the vertex.
TEST_F(Check3d, VertexInsideAnotherCellIsReported)
{
  minimize(TWO_CELLS);
  const std::vector<double> c = centroid(1, 42);
  const double lx = s.equal_variable("lx");
  x[3 * 49] = c[0] + lx;
  x[3 * 49 + 1] = c[1];
  x[3 * 49 + 2] = c[2];
  const std::string error = check_moved();
  EXPECT_THAT(error,
              HasSubstr("; 1 pairs of cells interpenetrate (first: cells 1 and 2, "
                        "vertex 50 of cell 2 inside the other)"))
      << error;
  EXPECT_EQ(s.thermo("f_check[8]"), 1.0);
}

// The warning (default 'action warn') lets the run go on and still fills the vector.
TEST_F(Check3d, WarnsByDefault)
{
  minimize("icosahedron.data", "");
  const std::vector<double> c = centroid(1, 12);
  for (int i = 0; i < 12; i++)
    for (int d = 0; d < 3; d++) x[3 * i + d] = 2.0 * c[d] - x[3 * i + d];
  EXPECT_EQ(check_moved(), "");
  EXPECT_EQ(s.thermo("f_check[4]"), 1.0);
}

// Solid angles of a closed, outward-oriented surface (a unit cube's 12 triangles) sum to 4 pi
// inside and to 0 outside, also just outside a face and near a corner.
TEST(Check3dGeometry, WindingNumberOfACube)
{
  const double corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // faces counter-clockwise from outside: bottom, top, front, back, left, right
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  std::vector<double> triangles;
  for (const auto &q : quads) {
    const int halves[2][3] = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
    for (const auto &t : halves)
      for (int k = 0; k < 3; k++) triangles.insert(triangles.end(), corner[t[k]], corner[t[k]] + 3);
  }
  auto w = [&](double x, double y, double z) {
    const double p[3] = {x, y, z};
    return LAMMPS_NS::DPoly3d::winding_number(p, triangles.data(), 12);
  };
  EXPECT_NEAR(w(0.5, 0.5, 0.5), 1.0, 1.0e-12);
  EXPECT_NEAR(w(0.99, 0.01, 0.5), 1.0, 1.0e-12);
  EXPECT_NEAR(w(1.01, 0.5, 0.5), 0.0, 1.0e-12);
  EXPECT_NEAR(w(-0.2, -0.2, -0.2), 0.0, 1.0e-12);
  EXPECT_NEAR(w(3.0, 0.5, 0.5), 0.0, 1.0e-12);
}

// The numeric keywords and coefficients of the 3d styles refuse values that would be inf or nan:
// LAMMPS's reader (utils::numeric) stops with the value named, before a style sees it.
class NonFiniteInput3d : public ErrorTest {};

TEST_F(NonFiniteInput3d, IsRefusedWithItsName)
{
  const std::string base = polyhedra_commands(data_file("icosahedron.data"));
  expect_errors(base,
                {{"fix more all dpoly3d/cells eps_v 1e400",
                  "Floating point number 1e400 in input script or data file is out of range"},
                 {"bond_coeff * 1e400",
                  "Floating point number 1e400 in input script or data file is out of range"},
                 {"dihedral_coeff * -1e400",
                  "Floating point number -1e400 in input script or data file is out of range"},
                 {"pair_style dpoly3d/contact\npair_coeff * * 1e400",
                  "Floating point number 1e400 in input script or data file is out of range"},
                 {"fix check all dpoly/check pressure 1e400",
                  "Floating point number 1e400 in input script or data file is out of range"},
                 {"fix check all dpoly/check tolerance inf",
                  "Expected floating point parameter instead of 'inf' in input script"},
                 {"fix more all dpoly3d/cells eps_v nan",
                  "Expected floating point parameter instead of 'nan' in input script"},
                 {"fix check all dpoly/check tolerance 1e400",
                  "Floating point number 1e400 in input script or data file is out of range"}});
}
