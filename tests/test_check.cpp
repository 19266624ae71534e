// fix dpoly/check: every minimum is checked and a failure is reported, never carried on silently.
#include "test_helpers.h"

#include "dpoly_overlap.h"
#include "fix_dpoly_stage.h"
#include "lammps.h"
#include "modify.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <regex>

using ::testing::HasSubstr;
using ::testing::Not;

using namespace test;

namespace {

// the bonded lattice of the tests under fix box/relax at P0 = 1e-3, checked after each minimum
std::unique_ptr<LammpsSession> relaxed_tissue(const std::string &check_options,
                                              const std::string &minimize)
{
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(data_file("overlapping.data")) + "fix check all dpoly/check " +
         check_options +
         "\nadhere_cells all 2\n"
         "fix relax all box/relax iso 1.0e-3 vmax 1.0e-3\nmin_style cg\n" +
         minimize);
  return s;
}

}    // namespace

TEST(Check, ConvergedMinimumAtTargetPressurePasses)
{
  auto s = relaxed_tissue("pressure 1.0e-3", "minimize 0.0 1.0e-10 20000 200000");
  EXPECT_EQ(s->thermo("f_check[1]"), 1.0);
  EXPECT_LT(s->thermo("f_check[3]"), 1.0e-6);
  EXPECT_EQ(s->thermo("f_check[4]"), 0.0);
  EXPECT_EQ(s->thermo("f_check[5]"), 0.0);
  EXPECT_LT(s->thermo("f_check[2]"), 1.0e-8);
  EXPECT_EQ(s->thermo("f_check[8]"), 0.0) << "touching cells do not interpenetrate";
}

TEST(Check, WrongPressureIsReported)
{
  auto s = relaxed_tissue("pressure 2.0e-3", "minimize 0.0 1.0e-10 20000 200000");
  EXPECT_NEAR(s->thermo("f_check[3]"), 0.5, 1.0e-6) << "P = 1e-3 against a stated P0 of 2e-3";
}

// A tension target: the error is relative to |P0|, so a minimum at +1e-3 is 2 away from -1e-3 (a
// signed denominator would give -2 and pass the check).
TEST(Check, TensionTargetIsComparedByItsSize)
{
  auto s = relaxed_tissue("pressure -1.0e-3", "minimize 0.0 1.0e-10 20000 200000");
  EXPECT_NEAR(s->thermo("f_check[3]"), 2.0, 1.0e-6);
}

TEST(Check, UnfinishedMinimizationWarnsOrStops)
{
  if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  const std::string log = scratch("unfinished.log");
  auto warned = relaxed_tissue("pressure 1.0e-3", "log " + log + "\nminimize 0.0 1.0e-10 5 50");
  EXPECT_EQ(warned->thermo("f_check[1]"), 0.0);
  EXPECT_EQ(warned->thermo("f_check[6]"), 5.0) << "iterations";
  EXPECT_GE(warned->thermo("f_check[7]"), 5.0) << "force evaluations";
  warned->run("log none");
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // the log line names the failure even after LAMMPS has stopped printing warnings
  EXPECT_THAT(text, HasSubstr("fix dpoly/check: minimum 1 at step 5: max iterations, force norm"));
  EXPECT_THAT(text,
              HasSubstr("; FAILED; the minimizer stopped without converging (max iterations)"));

  LammpsSession s;
  const std::string msg = s.try_run(
      contact_commands(data_file("overlapping.data")) +
      "fix check all dpoly/check pressure 1.0e-3 action error\nadhere_cells all 2\n"
      "fix relax all box/relax iso 1.0e-3 vmax 1.0e-3\nmin_style cg\nminimize 0.0 1.0e-10 5 50");
  EXPECT_THAT(msg,
              HasSubstr("minimum 1 at step 5; the minimizer stopped without converging (max "
                        "iterations)"))
      << msg;
}

// a figure-eight ring with unequal lobes has positive area, so only the crossing test sees it
TEST(Check, RingThatCrossesItselfIsReported)
{
  Tissue t;
  t.cells = {{{{10.0, 10.0}, {13.0, 13.0}, {13.0, 11.0}, {10.0, 14.0}}}};
  LammpsSession s;
  s.run(contact_commands(write_tissue(t, "figure8.data")) +
        "fix check all dpoly/check\n"
        "minimize 0.0 0.0 0 0");
  EXPECT_EQ(s.thermo("f_check[5]"), 1.0);
  EXPECT_EQ(s.thermo("f_check[4]"), 0.0);
}

// A ring segment not shorter than half the box at a minimum is reported. No run gets there (fix
// dpoly/cells stops it at the first force evaluation after a segment passes half the box), so
// the segment is drawn out by hand after a minimum, and the check called as after the next one.
TEST(Check, SegmentPastHalfTheBoxIsReported)
{
  Tissue t;    // two cells in a box of 8; segments 5-6 and 7-8 of cell 2 are 3.95 long
  t.cells = {square(1.0, 1.0, 1.0), {{{2.2, 1.0}, {6.15, 1.0}, {6.15, 2.0}, {2.2, 2.0}}}};
  t.adhesive = {{2, 5}, {3, 8}};
  t.box = 8.0;
  LammpsSession s;
  s.run(contact_commands(write_tissue(t, "check_stretched.data")) +
        "comm_modify cutoff 4.5\nfix check all dpoly/check action error\n"
        "minimize 1.0 0.0 10 100");    // converged (energy tolerance 1)
  std::vector<double> x = s.gather("x", 3);
  x[3 * 5] = x[3 * 4] + 4.25;    // vertex 6, 4.25 to the right of vertex 5
  x[3 * 5 + 1] = x[3 * 4 + 1];
  s.scatter("x", 3, x);
  auto *lmp = static_cast<LAMMPS_NS::LAMMPS *>(s.lammps_handle());
  auto *check = dynamic_cast<LAMMPS_NS::FixDPolyStage *>(lmp->modify->get_fix_by_id("check"));
  ASSERT_NE(check, nullptr);
  std::string error;
  try {
    check->act();
  } catch (std::exception &e) {
    error = e.what();
  }
  EXPECT_THAT(error,
              HasSubstr("1 ring segments are not shorter than half the box (first: segment "
                        "5-6 of cell 2, 4.25 long, 4.25 in x, half the box length 4)"));
}

// Where the minimizer stops early, the ring segment shortest relative to its l0 is named (a
// diagnosis: a collapsed segment keeps FIRE from settling). Segment 7-8 of cell 2 is 0.01 long
// for an l0 of 0.5 (2%), all others at their l0, 4-5 of cell 1 too though only 0.008 long; 7-8
// straddles x = 20, where two ranks split the box, so that its vertices lie on different ranks.
// The text is the same on this rank alone.
TEST(Check, UnconvergedMinimumNamesTheShortestSegment)
{
  Tissue t;
  t.cells = {{{{1.0, 1.0}, {2.0, 1.0}, {2.0, 2.0}, {1.008, 2.0}, {1.0, 2.0}}},
             {{{19.0, 5.0}, {19.995, 5.0}, {20.005, 5.0}, {21.0, 5.0}, {21.0, 6.0}, {19.0, 6.0}}}};
  const std::string input = contact_commands(write_tissue(t, "collapsed_segment.data")) +
      "set atom 7 d_l0 0.5\nfix check all dpoly/check action error\n"
      "min_modify dmax 1.0e-3\nminimize 0.0 0.0 3 30";    // dmax: it stays collapsed
  LammpsSession parallel, serial(self_comm());
  const std::string error = parallel.try_run(input);
  EXPECT_EQ(error, serial.try_run(input));
  const std::regex named("the minimizer stopped without converging \\(max iterations\\), shortest "
                         "ring segment relative to its preferred length: (\\d+)-(\\d+) of cell "
                         "(\\d+), ([0-9.e+-]+) long, ([0-9.e+-]+)% of l0 = ([0-9.e+-]+)");
  std::smatch found;
  ASSERT_TRUE(std::regex_search(error, found, named)) << error;
  EXPECT_EQ(found[1].str(), "7");
  EXPECT_EQ(found[2].str(), "8");
  EXPECT_EQ(found[3].str(), "2");
  EXPECT_EQ(found[6].str(), "0.5");
  // the length and percentage of the minimum the check saw (3 significant digits)
  const std::vector<double> x = parallel.gather("x", 3);
  const double r = std::hypot(x[3 * 7] - x[3 * 6], x[3 * 7 + 1] - x[3 * 6 + 1]);
  EXPECT_NEAR(std::stod(found[4].str()), r, 5.0e-3 * r);
  EXPECT_NEAR(std::stod(found[5].str()), 100.0 * r / 0.5, 5.0e-3 * 100.0 * r / 0.5);
  EXPECT_LT(std::stod(found[5].str()), 10.0) << "still collapsed: " << error;
}

TEST(Check, BadInput)
{
  if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  auto error_of = [](const std::string &line) {
    LammpsSession s;
    return s.try_run(contact_commands(data_file("overlapping.data")) + line + "\nrun 0 post no");
  };
  EXPECT_THAT(error_of("fix c all dpoly/check pressure 0"),
              HasSubstr("pressure must be nonzero, got 0"));
  EXPECT_THAT(error_of("fix c all dpoly/check action shout"),
              HasSubstr("must be 'warn' or 'error'"));
}

/* ----------------------------------------------------------------------
   cells that interpenetrate: the polygons through the vertex centres of two cells overlap
------------------------------------------------------------------------- */

namespace {

struct Interpenetration {
  double pairs;           // fix dpoly/check's vector element 8
  std::string message;    // the error of the same check with 'action error'
};

// hand-made cells checked where they stand: a minimization of no iterations
Interpenetration interpenetration_of(const Tissue &t, const std::string &name)
{
  const std::string data = write_tissue(t, name);
  LammpsSession warned, stopped;
  warned.run(contact_commands(data) + "fix check all dpoly/check\nminimize 0.0 0.0 0 0");
  const std::string error = stopped.try_run(contact_commands(data) +
                                            "fix check all dpoly/check action error\n"
                                            "minimize 0.0 0.0 0 0");
  return {warned.thermo("f_check[8]"), error};
}

}    // namespace

// a corner of cell 2 pushed through the top of cell 1, whose right side cuts cell 2's bottom
TEST(Check, CellsThatInterpenetrateAreReported)
{
  Tissue t;
  t.cells = {square(1.0, 1.0, 1.0), square(1.6, 1.3, 1.0)};
  const Interpenetration found = interpenetration_of(t, "interpenetrating.data");
  EXPECT_EQ(found.pairs, 1.0);
  EXPECT_THAT(found.message, HasSubstr("1 pairs of cells interpenetrate (first: cells 1 and 2)"))
      << found.message;
}

// Vertex disks of neighbouring cells overlap by design; only the polygons through the vertex
// centres must not. Cells 1-2: adhering squares 0.1 apart (disks of diameter 0.5); 3-4: a vertex
// 0.05 from the other cell's side; 5-6: one side on the line of the other's (a touch, not an
// overlap); 7-8: 0.1 apart across the periodic boundary in x; 9-10 in y.
TEST(Check, CellsThatTouchOrAdherePass)
{
  Tissue t;
  t.box = 12.0;
  t.cells = {square(1.0, 1.0, 1.0),  square(2.1, 1.0, 1.0),
             square(5.0, 1.0, 1.0),  {{{6.05, 1.5}, {6.6, 0.8}, {7.4, 1.5}, {6.6, 2.2}}},
             square(1.0, 4.0, 1.0),  square(2.0, 4.5, 1.0),
             square(10.9, 7.0, 1.0), square(0.0, 7.0, 1.0),
             square(8.5, 10.9, 1.0), square(8.5, 0.0, 1.0)};
  t.adhesive = {{2, 5}, {3, 8}, {26, 29}, {27, 32}};
  const Interpenetration found = interpenetration_of(t, "touching.data");
  EXPECT_EQ(found.pairs, 0.0);
  EXPECT_THAT(found.message, Not(HasSubstr("interpenetrate"))) << found.message;
}

// Cell 2's tip (x = -0.3) crosses the boundary in x and enters cell 1 (x 6.9 to 7.9) through its
// image (7.7); cells 3 and 4 touch across the same boundary and must not count.
TEST(Check, CellsThatInterpenetrateAcrossTheBoundaryAreReported)
{
  Tissue t;
  t.box = 8.0;
  t.cells = {square(6.9, 3.0, 1.0),
             {{{0.0, 3.0}, {1.0, 3.0}, {1.0, 4.0}, {0.0, 4.0}, {-0.3, 3.5}}},
             square(6.9, 5.5, 1.0),
             square(0.0, 5.5, 1.0)};
  const Interpenetration found = interpenetration_of(t, "interpenetrating_periodic.data");
  EXPECT_EQ(found.pairs, 1.0);
  EXPECT_THAT(found.message, HasSubstr("1 pairs of cells interpenetrate (first: cells 1 and 2)"))
      << found.message;
}

// cell 2's tip crosses only the segment that closes cell 1's ring (from its last vertex to its
// first: the left side), and no vertex of either cell lies inside the other's bounding box
TEST(Check, CrossingOfTheClosingSegmentIsReported)
{
  Tissue t;
  t.cells = {square(3.0, 1.0, 1.0), {{{1.9, 1.0}, {2.8, 1.0}, {3.2, 1.5}, {2.8, 2.0}, {1.9, 2.0}}}};
  EXPECT_EQ(interpenetration_of(t, "closing_segment.data").pairs, 1.0);
}

// no segments cross when one cell lies wholly inside another; two such pairs, the lower IDs named
TEST(Check, CellInsideAnotherIsReported)
{
  Tissue t;
  t.cells = {square(10.0, 10.0, 0.5), square(1.0, 1.0, 3.0), square(2.0, 2.0, 0.5),
             square(5.0, 1.0, 3.0), square(6.0, 2.0, 0.5)};
  const Interpenetration found = interpenetration_of(t, "nested.data");
  EXPECT_EQ(found.pairs, 2.0);
  EXPECT_THAT(found.message, HasSubstr("2 pairs of cells interpenetrate (first: cells 2 and 3)"))
      << found.message;
}

/* ----------------------------------------------------------------------
   the binned search against every pair of cells, every image and every pair of segments
------------------------------------------------------------------------- */

namespace {

using LAMMPS_NS::DPoly::Box;
using LAMMPS_NS::DPoly::Outline;
using LAMMPS_NS::DPoly::Point;

// star-shaped (so simple) polygons of 3 to 24 corners at random places, in unwrapped coordinates
std::vector<Outline> random_cells(int count, double length, double largest, unsigned seed)
{
  std::mt19937 draw(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Outline> cells(count);
  for (int c = 0; c < count; c++) {
    cells[c].cell = 100 + 7 * c;    // IDs not in step with the order
    const double centre[2] = {length * unit(draw), length * unit(draw)};
    const double radius = largest * (0.2 + 0.8 * unit(draw));
    const int n = 3 + (int) (22 * unit(draw));
    std::vector<double> angles(n);
    for (double &a : angles) a = 2.0 * PI * unit(draw);
    std::sort(angles.begin(), angles.end());
    for (double a : angles) {
      const double r = radius * (0.5 + 0.5 * unit(draw));
      cells[c].corners.push_back({centre[0] + r * cos(a), centre[1] + r * sin(a)});
    }
  }
  return cells;
}

bool overlap_brute_force(const Outline &a, const Outline &b, const Point &shift)
{
  std::vector<Point> moved = b.corners;
  for (Point &p : moved) p = {p[0] + shift[0], p[1] + shift[1]};
  const int na = (int) a.corners.size(), nb = (int) moved.size();
  for (int i = 0; i < na; i++)
    for (int j = 0; j < nb; j++)
      if (LAMMPS_NS::DPoly::segments_cross(a.corners[i], a.corners[(i + 1) % na], moved[j],
                                           moved[(j + 1) % nb]))
        return true;
  return LAMMPS_NS::DPoly::inside_polygon(a.corners[0], moved) ||
      LAMMPS_NS::DPoly::inside_polygon(moved[0], a.corners);
}

struct BruteForce {
  long pairs = 0, with_own_image = 0;
  std::pair<LAMMPS_NS::tagint, LAMMPS_NS::tagint> first{0, 0};
};

BruteForce brute_force(const std::vector<Outline> &cells, const Box &box, double largest)
{
  BruteForce found;
  // corners lie within 'largest' of a centre in the box: farther images cannot reach
  const int images = 1 + (int) std::ceil(4.0 * largest / box.length[0]);
  const int reach[2] = {box.periodic[0] ? images : 0, box.periodic[1] ? images : 0};
  for (size_t a = 0; a < cells.size(); a++)
    for (size_t b = a; b < cells.size(); b++) {
      bool overlap = false;
      for (int i = -reach[0]; i <= reach[0] && !overlap; i++)
        for (int j = -reach[1]; j <= reach[1] && !overlap; j++)
          if (a != b || i != 0 || j != 0)
            overlap =
                overlap_brute_force(cells[a], cells[b], {i * box.length[0], j * box.length[1]});
      if (!overlap) continue;
      const std::pair<LAMMPS_NS::tagint, LAMMPS_NS::tagint> pair =
          std::minmax(cells[a].cell, cells[b].cell);
      if (!found.pairs || pair < found.first) found.first = pair;
      found.pairs++;
      found.with_own_image += (a == b);
    }
  return found;
}

}    // namespace

// Tissues of random polygons, many of them overlapping: in a periodic box, in a box periodic in
// x only, and in a box so small that cells overlap their own images.
TEST(Check, BinnedSearchFindsWhatBruteForceFinds)
{
  // a function of its arguments alone (no LAMMPS, no MPI): one rank tests it
  if (world_size() > 1) GTEST_SKIP() << "the geometry is tested on one rank";
  struct Case {
    int cells;
    double length, largest;
    bool periodic_y;
  };
  for (const Case &c : {Case{60, 8.0, 0.6, true}, Case{60, 8.0, 0.6, false},
                        Case{12, 2.5, 1.8, true}, Case{80, 9.0, 0.5, true}}) {
    long with_own_image = 0;
    for (unsigned seed = 1; seed <= 5; seed++) {
      const std::vector<Outline> cells = random_cells(c.cells, c.length, c.largest, seed);
      const Box box{{c.length, c.length}, {true, c.periodic_y}};
      const BruteForce expected = brute_force(cells, box, c.largest);
      const LAMMPS_NS::DPoly::Interpenetration found =
          LAMMPS_NS::DPoly::interpenetrating_cells(cells, box);
      SCOPED_TRACE(::testing::Message()
                   << c.cells << " cells in a box of " << c.length << ", seed " << seed);
      // not a vacuous comparison: some pairs overlap, most do not
      EXPECT_GT(expected.pairs, 0);
      EXPECT_LT(expected.pairs, (long) c.cells * (c.cells + 1) / 2);
      EXPECT_EQ(found.pairs, expected.pairs);
      EXPECT_EQ(found.first[0], expected.first.first);
      EXPECT_EQ(found.first[1], expected.first.second);
      with_own_image += expected.with_own_image;
    }
    // cells wider than the box meet their own images: some must overlap them
    if (2.0 * c.largest > c.length) EXPECT_GT(with_own_image, 0);
  }
}

// Outlines in exact coordinates (as cells made on a lattice have): sides on one line and vertices
// on the other's side are contact, not overlap, whatever vertex the ring starts at; cells that
// share sides and still reach into each other, or hold the other with a vertex on its side,
// overlap.
TEST(Check, ExactContactIsNotOverlapExactOverlapIs)
{
  if (world_size() > 1) GTEST_SKIP() << "the geometry is tested on one rank";
  const Box open_box{{10.0, 10.0}, {false, false}};
  auto pairs = [&](std::vector<Point> a, std::vector<Point> b, int rotate) {
    std::rotate(b.begin(), b.begin() + rotate % b.size(), b.end());
    std::vector<Outline> cells(2);
    cells[0].cell = 1;
    cells[0].corners = a;
    cells[1].cell = 2;
    cells[1].corners = b;
    return LAMMPS_NS::DPoly::interpenetrating_cells(cells, open_box).pairs;
  };
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Point> big_square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const std::vector<Point> ell{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (int r = 0; r < 4; r++) {
    SCOPED_TRACE(::testing::Message() << "second ring rotated by " << r);
    EXPECT_EQ(pairs(square, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}, r), 0) << "side by side";
    EXPECT_EQ(pairs(ell, {{1, 1}, {2, 1}, {2, 2}, {1, 2}}, r), 0) << "square in the L's notch";
    EXPECT_EQ(pairs(square, {{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}}, r), 1)
        << "half of one square over the other, sides on one line";
    EXPECT_EQ(pairs(big_square, {{2, 1}, {1, 0.5}, {1, 1.5}}, r), 1)
        << "triangle inside, one vertex on the square's side";
  }
}
