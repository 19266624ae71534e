// Observables of the 3d tissue: compute dpoly3d/tissue (volume fraction, S^3/(36 pi V^2), z) and
// compute dpoly3d/slice (paradermal cross-sections) on cells whose answers are known exactly.
// Every test runs on any number of ranks unless it says otherwise; ctest runs this binary on 1,
// 2 and 4.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cmath>
#include <fstream>
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

std::string read_cells(const std::string &data, const std::string &newton_bond = "on")
{
  return std::string("units lj\ndimension 3\natom_style molecular\natom_modify map array\n"
                     "boundary p p p\nnewton on ") +
      newton_bond + "\n" + CELL_STATE +
      "bond_style dpoly3d/edge\nangle_style zero\ndihedral_style dpoly3d/hinge\nread_data " + data +
      " fix Vertices NULL Vertices fix Edges NULL Edges fix EdgeLengths NULL EdgeLengths fix "
      "EdgeAngles NULL EdgeAngles\nbond_coeff * 1.0\nangle_coeff *\ndihedral_coeff * 0.4\n"
      "comm_modify cutoff 3.0\n";
}

const char *HUB = "fix cells all dpoly3d/cells eps_v 1.0\n";

// the cells of a data file with the hub, the tissue compute and a slice compute of the given
// keywords (and a sum of its per-section areas and perimeters), measured by run 0
std::unique_ptr<LammpsSession> measured(const std::string &data, const std::string &slice = "",
                                        MPI_Comm comm = MPI_COMM_WORLD,
                                        const std::string &newton_bond = "on")
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(read_cells(data_file(data), newton_bond) + HUB + "compute tissue all dpoly3d/tissue\n" +
         "compute slice all dpoly3d/slice " + slice + "\n" +
         "compute sections all reduce sum c_slice[3] c_slice[4] inputs local\nrun 0 post no");
  return s;
}

double value(LammpsSession &s, const std::string &compute, int k)
{
  return s.equal_variable("c_" + compute + "[" + std::to_string(k) + "]");
}

enum { PHI = 1, SHAPE, NEIGHBOURS, BONDS_OR_SECTIONS, CELLS_OR_HOLES, PHI_PATCH, FLATTEST_FACE };

}    // namespace

// A regular icosahedron of circumradius 1 in a box of 4: S = 5 sqrt(3) a^2,
// V = (5/12)(3 + sqrt 5) a^3, so S^3/(36 pi V^2) = 1.2066... whatever its size.
TEST(Tissue3d, IcosahedronShapeParameterIsAnalytic)
{
  auto s = measured("icosahedron.data");
  const double a = 1.0 / sin(2.0 * PI / 5.0);
  const double volume = 5.0 / 12.0 * (3.0 + sqrt(5.0)) * a * a * a;
  const double surface = 5.0 * sqrt(3.0) * a * a;
  const double shape = std::pow(surface, 3) / (36.0 * PI * volume * volume);
  ASSERT_NEAR(shape, 1.2066, 1.0e-4);
  EXPECT_NEAR(value(*s, "tissue", PHI), volume / 64.0, 1.0e-14);
  EXPECT_NEAR(value(*s, "tissue", SHAPE), shape, 1.0e-13);
  EXPECT_EQ(value(*s, "tissue", NEIGHBOURS), 0.0) << "no adhesion style: no bonded neighbours";
  EXPECT_EQ(value(*s, "tissue", BONDS_OR_SECTIONS), 0.0);
  EXPECT_EQ(value(*s, "tissue", CELLS_OR_HOLES), 1.0);
  // the per-cell row: ID, V, S, S^3/(36 pi V^2), z, bonds, patch volume
  const std::vector<double> row = s->global_array("tissue", 1, 7);
  EXPECT_EQ(row[0], 1.0);
  EXPECT_NEAR(row[1], volume, 1.0e-13);
  EXPECT_NEAR(row[2], surface, 1.0e-13);
  EXPECT_NEAR(row[3], shape, 1.0e-13);
  EXPECT_EQ(row[4], 0.0);
  EXPECT_EQ(row[5], 0.0);
  // patch volume: every vertex pushed out radially by sin(pi/3) sigma/2 (sigma = a here), which
  // for a regular polyhedron about its centre is the same polyhedron scaled by 1 + push/R
  const double scale = 1.0 + 0.5 * sin(PI / 3.0) * a;
  EXPECT_NEAR(row[6], volume * scale * scale * scale, 1.0e-13);
  EXPECT_NEAR(value(*s, "tissue", PHI_PATCH), row[6] / 64.0, 1.0e-15);
}

// The cube of side 2 (vertices sqrt 3 from its centre, sigma 0.4): pushed by sin(pi/3) 0.2 =
// 0.1 sqrt 3, it is the cube of side 2.2; across the periodic boundary it is measured whole.
TEST(Tissue3d, CubePatchVolumeIsAnalytic)
{
  const double patch = 2.2 * 2.2 * 2.2;
  auto cube = measured("cube.data");
  EXPECT_NEAR(value(*cube, "tissue", PHI_PATCH), patch / 1000.0, 1.0e-15);
  EXPECT_NEAR(cube->global_array("tissue", 1, 7)[6], patch, 1.0e-12);
  cube->run("displace_atoms all move 5.0 5.0 5.0 units box\nrun 0 post no");
  const std::vector<int> image = cube->gather_int("image", 1);
  ASSERT_NE(*std::max_element(image.begin(), image.end()),
            *std::min_element(image.begin(), image.end()))
      << "the cube should be split by the periodic boundaries";
  EXPECT_NEAR(value(*cube, "tissue", PHI_PATCH), patch / 1000.0, 1.0e-15);
}

// The flattest face, height over longest edge: sqrt(3)/2 for the icosahedron's equilateral
// faces, 1/2 for the cube's right isosceles ones; a vertex of the icosahedron moved towards the
// midpoint of the edge opposite it in one of its faces, to a fraction t of its height, makes
// that face's ratio t sqrt(3)/2 (its longest edge is still the opposite one).
TEST(Tissue3d, FlattestFaceIsAnalytic)
{
  EXPECT_NEAR(value(*measured("cube.data"), "tissue", FLATTEST_FACE), 0.5, 1.0e-15);
  auto s = measured("icosahedron.data");
  EXPECT_NEAR(value(*s, "tissue", FLATTEST_FACE), sqrt(3.0) / 2.0, 1.0e-14);

  const std::vector<double> x = s->gather("x", 3);
  auto distance = [&](int i, int j) {
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) d2 += (x[3 * i + k] - x[3 * j + k]) * (x[3 * i + k] - x[3 * j + k]);
    return sqrt(d2);
  };
  const double edge = 1.0 / sin(2.0 * PI / 5.0);    // circumradius 1
  int j = -1, k = -1;    // two neighbours of atom 1 (index 0) that are neighbours of each other
  for (int a = 1; a < 12 && k < 0; a++)
    for (int b = a + 1; b < 12 && k < 0; b++)
      if (fabs(distance(0, a) - edge) < 1.0e-9 && fabs(distance(0, b) - edge) < 1.0e-9 &&
          fabs(distance(a, b) - edge) < 1.0e-9) {
        j = a;
        k = b;
      }
  ASSERT_GE(k, 0) << "no face found around atom 1";
  const double t = 1.0e-3;
  double moved[3];
  for (int d = 0; d < 3; d++) {
    const double midpoint = 0.5 * (x[3 * j + d] + x[3 * k + d]);
    moved[d] = midpoint + t * (x[d] - midpoint);
  }
  std::ostringstream move;
  move.precision(17);
  move << "set atom 1 x " << moved[0] << " y " << moved[1] << " z " << moved[2]
       << "\nrun 0 post no";
  s->run(move.str());
  EXPECT_NEAR(value(*s, "tissue", FLATTEST_FACE), t * sqrt(3.0) / 2.0, 1.0e-12);
}

// A cube (S^3/(36 pi V^2) = 6/pi) and finer icospheres, which approach the sphere's 1 from above.
TEST(Tissue3d, CubeIsAnalyticAndFinerSpheresApproachOne)
{
  auto cube = measured("cube.data");
  EXPECT_NEAR(value(*cube, "tissue", SHAPE), 6.0 / PI, 1.0e-13);
  EXPECT_NEAR(value(*cube, "tissue", PHI), 8.0 / 1000.0, 1.0e-15);
  auto coarse = measured("icosahedron.data");
  auto fine = measured("icosphere3.data");
  const double shape_fine = value(*fine, "tissue", SHAPE);
  EXPECT_GT(shape_fine, 1.0);
  EXPECT_LT(shape_fine - 1.0, 0.1 * (value(*coarse, "tissue", SHAPE) - 1.0));
}

// Two cells of two molecule IDs: one row each, sorted by ID, and the mean over both.
TEST(Tissue3d, PerCellRowsAndMeans)
{
  auto s = measured("cells3d_deformed.data");
  const std::vector<double> rows = s->global_array("tissue", 2, 7);
  EXPECT_EQ(rows[0], 1.0);
  EXPECT_EQ(rows[7], 2.0);
  EXPECT_NEAR(value(*s, "tissue", SHAPE), 0.5 * (rows[3] + rows[10]), 1.0e-14);
  EXPECT_NEAR(rows[1] + rows[8], s->equal_variable("f_cells[2]"), 1.0e-12);
  EXPECT_NEAR(value(*s, "tissue", PHI), (rows[1] + rows[8]) / s->equal_variable("vol"), 1.0e-15);
  EXPECT_NEAR(value(*s, "tissue", PHI_PATCH), (rows[6] + rows[13]) / s->equal_variable("vol"),
              1.0e-15);
  // a deformed cell's patch is larger than the cell and smaller than every vertex pushed out by
  // its whole diameter would make it
  EXPECT_GT(rows[6], rows[1]);
  EXPECT_GT(rows[13], rows[8]);
  EXPECT_EQ(value(*s, "tissue", CELLS_OR_HOLES), 2.0);
  // fix ave/time writes the rows too (it asks the compute how many there are)
  const std::string file = scratch("percell3d.txt");
  s->run("fix percell all ave/time 1 1 1 c_tissue[2] mode vector file " + file +
         "\nrun 0 post no\nunfix percell");
  MPI_Barrier(MPI_COMM_WORLD);
  std::ifstream in(file);
  std::string line;
  std::vector<double> written;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') {
      std::istringstream words(line);
      double first, second;
      if (words >> first >> second) written.push_back(second);
    }
  ASSERT_EQ(written.size(), 3u) << "a header row (step, rows) and one row per cell";
  EXPECT_EQ(written[0], 2.0);
  EXPECT_NEAR(written[2], rows[8], 1.0e-5 * rows[8]);
}

// The cube of side 2 cut through its middle: a square of area 4 and perimeter 8, although its
// triangulation puts a diagonal edge across every side.
TEST(Slice3d, CubeCrossSectionIsExact)
{
  auto s = measured("cube.data");
  EXPECT_NEAR(value(*s, "sections", 1), 4.0, 1.0e-13);
  EXPECT_NEAR(value(*s, "sections", 2), 8.0, 1.0e-13);
  EXPECT_NEAR(value(*s, "slice", PHI), 4.0 / 100.0, 1.0e-15);
  EXPECT_NEAR(value(*s, "slice", SHAPE), 4.0 / PI, 1.0e-13);
  EXPECT_EQ(value(*s, "slice", BONDS_OR_SECTIONS), 1.0);
  EXPECT_EQ(value(*s, "slice", CELLS_OR_HOLES), 0.0);
  EXPECT_EQ(value(*s, "slice", NEIGHBOURS), 0.0);
}

// Turned by 30 degrees about x, the cube's middle cross-section is a 2 x 2/cos(30) rectangle.
TEST(Slice3d, TiltedCubeCrossSectionIsExact)
{
  auto s = measured("cube_tilted.data");
  const double width = 2.0 / cos(PI / 6.0);
  EXPECT_NEAR(value(*s, "sections", 1), 2.0 * width, 1.0e-13);
  EXPECT_NEAR(value(*s, "sections", 2), 4.0 + 2.0 * width, 1.0e-13);
  const double calA = std::pow(4.0 + 2.0 * width, 2) / (4.0 * PI * 2.0 * width);
  EXPECT_NEAR(value(*s, "slice", SHAPE), calA, 1.0e-13);
}

// Degenerate planes. Through the octahedron's equator, a plane holds four vertices and four
// edges: one square of area 2 R^2 and perimeter 4 sqrt(2) R. Planes in the cube's bottom and top
// faces (z = 4 and 6 of planes 5 offset 0): a vertex on a plane counts as above it, so the
// bottom face gives nothing and the top face one square; nothing is counted twice.
TEST(Slice3d, PlanesThroughVerticesEdgesAndFaces)
{
  auto octahedron = measured("octahedron.data");
  const double r = 1.5;
  EXPECT_NEAR(value(*octahedron, "sections", 1), 2.0 * r * r, 1.0e-13);
  EXPECT_NEAR(value(*octahedron, "sections", 2), 4.0 * sqrt(2.0) * r, 1.0e-13);
  EXPECT_EQ(value(*octahedron, "slice", BONDS_OR_SECTIONS), 1.0);
  // through the top vertex (z = 6.5): the plane touches the cell without cutting it, so neither
  // a cross-section nor a hole
  auto apex = measured("octahedron.data", "planes 1 offset 0.65");
  EXPECT_EQ(value(*apex, "slice", BONDS_OR_SECTIONS), 0.0);
  EXPECT_EQ(value(*apex, "slice", CELLS_OR_HOLES), 0.0);
  EXPECT_EQ(value(*apex, "slice", PHI), 0.0);

  auto faces = measured("cube.data", "planes 5 offset 0.0");
  EXPECT_EQ(value(*faces, "slice", BONDS_OR_SECTIONS), 1.0);
  EXPECT_NEAR(value(*faces, "sections", 1), 4.0, 1.0e-13);
  EXPECT_NEAR(value(*faces, "sections", 2), 8.0, 1.0e-13);
  EXPECT_NEAR(value(*faces, "slice", PHI), 4.0 / 500.0, 1.0e-15);
}

// A cup: a 4 x 4 x 2 block with a 2 x 2 well 1 deep in its top. V = 28, S = 72. Cut through the
// well (z = 5.5) it is one cross-section, the 4 x 4 square, with one hole, the well's 2 x 2
// square: phi counts 16 - 4, the cross-section's row and calA its outline alone.
TEST(Slice3d, CupGivesACrossSectionWithAHole)
{
  auto s = measured("cup.data", "offset 0.55");
  EXPECT_NEAR(value(*s, "tissue", PHI), 28.0 / 1000.0, 1.0e-15);
  EXPECT_NEAR(value(*s, "tissue", SHAPE), std::pow(72.0, 3) / (36.0 * PI * 28.0 * 28.0), 1.0e-12);
  EXPECT_NEAR(value(*s, "slice", PHI), 12.0 / 100.0, 1.0e-15);
  EXPECT_EQ(value(*s, "slice", BONDS_OR_SECTIONS), 1.0);
  EXPECT_EQ(value(*s, "slice", CELLS_OR_HOLES), 1.0);
  EXPECT_NEAR(value(*s, "sections", 1), 16.0, 1.0e-13);
  EXPECT_NEAR(value(*s, "sections", 2), 16.0, 1.0e-13);
  EXPECT_NEAR(value(*s, "slice", SHAPE), 4.0 / PI, 1.0e-13);
}

// Several planes: phi is the cut area over all planes' box cross-sections; 10 planes at
// z = 0.5, 1.5, ... cut the cube (4 < z < 6) twice.
TEST(Slice3d, SeveralPlanesAreAveraged)
{
  auto s = measured("cube.data", "planes 10");
  EXPECT_EQ(value(*s, "slice", BONDS_OR_SECTIONS), 2.0);
  EXPECT_NEAR(value(*s, "slice", PHI), 8.0 / 1000.0, 1.0e-15);
  EXPECT_NEAR(value(*s, "slice", SHAPE), 4.0 / PI, 1.0e-13);
}

// Moved by half the box in x, y and z, the cube straddles every periodic boundary; cut by the
// plane z = 0 (its image at z = 10 passes through the cube's middle) it is the same square.
TEST(Slice3d, CellAcrossThePeriodicBoundary)
{
  auto s = measured("cube.data", "offset 0.0");
  s->run("displace_atoms all move 5.0 5.0 5.0 units box\nrun 0 post no");
  const std::vector<int> image = s->gather_int("image", 1);
  ASSERT_NE(*std::max_element(image.begin(), image.end()),
            *std::min_element(image.begin(), image.end()))
      << "the cube should be split by the periodic boundaries";
  EXPECT_NEAR(value(*s, "sections", 1), 4.0, 1.0e-13);
  EXPECT_NEAR(value(*s, "sections", 2), 8.0, 1.0e-13);
  EXPECT_NEAR(value(*s, "tissue", PHI), 8.0 / 1000.0, 1.0e-15);
  EXPECT_NEAR(value(*s, "tissue", SHAPE), 6.0 / PI, 1.0e-13);
}

// Two cubes 0.3 apart, vertex diameter 0.4: their cross-sections touch when the gap is below
// contact times 0.4: inside the box, with both cubes moved across its boundary (unwrapped, still
// side by side), and with the cubes moved apart so that they face each other only through the
// periodic boundary (x in [0.15, 2.15] and [7.85, 9.85]; the second one's unwrapped positions
// two boxes further on).
TEST(Slice3d, ContactDistanceDecidesNeighbours)
{
  const std::vector<std::string> moves = {"", "displace_atoms all move 4.0 0 0 units box\n",
                                          "group first molecule 1\ngroup second molecule 2\n"
                                          "displace_atoms first move -2.7 0 0 units "
                                          "box\ndisplace_atoms second move 22.7 0 0 units box\n"};
  for (const std::string &move : moves) {
    for (const auto &c :
         {std::make_pair("1.0", 1.0), std::make_pair("0.8", 1.0), std::make_pair("0.7", 0.0)}) {
      auto s = measured("two_cubes.data", std::string("contact ") + c.first);
      s->run(move + "run 0 post no");
      EXPECT_EQ(value(*s, "slice", NEIGHBOURS), c.second) << "contact " << c.first << ", " << move;
      EXPECT_EQ(value(*s, "slice", BONDS_OR_SECTIONS), 2.0);
    }
  }
}

// Cavalieri: the cut areas of many evenly spaced planes average to the volume fraction (midpoint
// rule on the piecewise smooth area of the cut; 200 planes agree to about 1e-6 here).
TEST(Slice3d, ManyPlanesGiveTheVolumeFraction)
{
  auto s = measured("cells3d_deformed.data", "planes 200");
  const double phi = value(*s, "tissue", PHI);
  EXPECT_NEAR(value(*s, "slice", PHI), phi, 1.0e-4 * phi);
}

// On several ranks: the same cells on this rank alone give the same values (the slices are cut
// from whole-system tables in ID order, so exactly; the volumes are summed over ranks).
TEST(Observables3d, ParallelMatchesSerial)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  const std::string keywords = "planes 7 offset 0.3 contact 4.0";
  const std::string perturb = "displace_atoms all random 0.05 0.05 0.05 4711 units box\n"
                              "run 0 post no";
  auto parallel = measured("cells3d_deformed.data", keywords);
  auto serial = measured("cells3d_deformed.data", keywords, self_comm());
  parallel->run(perturb);
  serial->run(perturb);
  ASSERT_GT(value(*serial, "slice", NEIGHBOURS), 0.0) << "the slices should see contacts";
  for (int k = 1; k <= 5; k++) {
    EXPECT_EQ(value(*parallel, "slice", k), value(*serial, "slice", k)) << "slice " << k;
    EXPECT_NEAR(value(*parallel, "tissue", k), value(*serial, "tissue", k),
                1.0e-13 * std::max(1.0, std::fabs(value(*serial, "tissue", k))))
        << "tissue " << k;
  }
  // the patch volumes come from whole-system tables in ID order: exactly the same
  EXPECT_EQ(value(*parallel, "tissue", PHI_PATCH), value(*serial, "tissue", PHI_PATCH));
  EXPECT_EQ(value(*parallel, "sections", 1), value(*serial, "sections", 1));
}

// With newton_bond off LAMMPS keeps every face on all three of its atoms' ranks: each still
// counts once.
TEST(Observables3d, NewtonBondOffGivesTheSameValues)
{
  const std::string keywords = "planes 5 contact 4.0";
  auto on = measured("cells3d_deformed.data", keywords);
  auto off = measured("cells3d_deformed.data", keywords, MPI_COMM_WORLD, "off");
  ASSERT_GT(value(*on, "slice", BONDS_OR_SECTIONS), 2.0);
  for (int k = 1; k <= 5; k++) {
    EXPECT_EQ(value(*on, "slice", k), value(*off, "slice", k)) << "slice " << k;
    EXPECT_NEAR(value(*on, "tissue", k), value(*off, "tissue", k),
                1.0e-13 * std::max(1.0, std::fabs(value(*on, "tissue", k))))
        << "tissue " << k;
  }
  EXPECT_EQ(value(*on, "tissue", PHI_PATCH), value(*off, "tissue", PHI_PATCH));
}

TEST(Observables3d, BadInputGivesClearErrors)
{
  struct Case {
    std::string commands, message;
  };
  const std::vector<Case> cases = {
      {"compute t all dpoly3d/tissue 1\n", "Compute dpoly3d/tissue takes no arguments, got 1"},
      {"compute s all dpoly3d/slice planes 0\n",
       "Compute dpoly3d/slice planes must be in [1, 1000000], got 0"},
      // far too many planes: refused before anything is allocated for them
      {"compute s all dpoly3d/slice planes 2000000000\n",
       "Compute dpoly3d/slice planes must be in [1, 1000000], got 2000000000"},
      {"compute s all dpoly3d/slice planes 2.5\n", "Expected integer parameter instead of '2.5'"},
      {"compute s all dpoly3d/slice offset 1.0\n",
       "Compute dpoly3d/slice offset must be in [0, 1) (a fraction of the plane spacing), got 1.0"},
      {"compute s all dpoly3d/slice contact -1\n",
       "Compute dpoly3d/slice contact must be finite and > 0, got -1"},
      {"compute s all dpoly3d/slice contact\n", "compute dpoly3d/slice contact"},
      {"compute s all dpoly3d/slice thickness 2\n",
       "Unknown Compute dpoly3d/slice keyword: thickness"},
      {"unfix cells\ncompute t all dpoly3d/tissue\nthermo_style custom c_t[1]\nrun 0 post no\n",
       "Compute dpoly3d/tissue needs fix dpoly3d/cells"},
      {"unfix cells\ncompute s all dpoly3d/slice\nthermo_style custom c_s[1]\nrun 0 post no\n",
       "Compute dpoly3d/slice needs fix dpoly3d/cells"},
      {"compute s all dpoly3d/slice\nchange_box all triclinic\nthermo_style custom c_s[1]\n"
       "run 0 post no\n",
       "Compute dpoly3d/slice needs an orthogonal box"},
      {"compute t all dpoly3d/tissue\nvariable phi equal c_t[1]\nprint ${phi}\n",
       "cannot be invoked before initialization by a run"},
  };
  for (const auto &c : cases) {
    LammpsSession s;
    s.run(read_cells(data_file("cube.data")) + HUB);
    EXPECT_THAT(s.try_run(c.commands), HasSubstr(c.message)) << c.commands;
  }
}

// The computes look the hub up at every evaluation: 'run N pre no' skips init(), so after the
// hub was removed (or replaced) they name the missing (or unmeasured) hub instead of reading
// the deleted fix (a heap-use-after-free that the sanitized build reports). The thermo output
// holds only the compute: LAMMPS's own pe would read the deleted fix first.
TEST(Observables3d, HubRemovedBeforeRunPreNoIsNamed)
{
  struct Case {
    std::string compute, keyword, removed, replaced;
  };
  const std::vector<Case> cases = {
      {"compute t all dpoly3d/tissue\n", "c_t[1]", "Compute dpoly3d/tissue needs fix dpoly3d/cells",
       "fix dpoly3d/cells has not measured the cells yet"},
      {"compute s all dpoly3d/slice\n", "c_s[1]", "Compute dpoly3d/slice needs fix dpoly3d/cells",
       "fix dpoly3d/cells has not checked the cells yet"},
      {"compute a all dpoly/adhesion\n", "c_a[1][1]",
       "Compute dpoly/adhesion needs fix dpoly/cells (polygons) or fix dpoly3d/cells", ""},
  };
  for (const auto &c : cases) {
    for (const bool replace : {false, true}) {
      if (replace && c.replaced.empty()) continue;
      LammpsSession s;
      s.run(read_cells(data_file("cube.data")) + HUB + c.compute + "thermo_style custom step " +
            c.keyword + "\nrun 0 post no");
      const std::string error =
          s.try_run(std::string("unfix cells\n") + (replace ? HUB : "") + "run 1 pre no post no");
      EXPECT_THAT(error, HasSubstr(replace ? c.replaced : c.removed)) << c.compute << replace;
    }
  }
}
