// LAMMPS's image-flag check and the adhesive bonds (src/MESOPHYLL/dpoly_image_check.h): three
// cells, A at the left edge of the periodic box, B at its right edge and C right of A; A and B
// adhere across the boundary by two bonds whose atoms, unwrapped by their image flags (all 0),
// lie a box length apart; A and C by one ordinary bond. LAMMPS warns "Inconsistent image flags"
// at the first minimization only, the package says why once, right after it, other warnings
// stay, the adhesive bonds keep their types (in the forces and in write_data), and ring
// segments with inconsistent image flags are still reported.
#include "test_helpers.h"

#include "gtest/gtest.h"

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

using namespace test;

namespace {

const std::string WARNING = "WARNING: Inconsistent image flags";
const std::string REASON = "MESOPHYLL: LAMMPS's image-flag check warns";
// a warning of LAMMPS's that every minimization under fix box/relax prints
const std::string OTHER_WARNING = "WARNING: Energy due to 1 extra global DOFs";
const std::string MINIMIZE = "minimize 0.0 1.0e-8 10 100\n";

std::string three_cells()
{
  Tissue t;
  t.box = 40.0;
  t.cells = {square(0.2, 10.0, 1.0), square(38.8, 10.0, 1.0), square(1.6, 10.0, 1.0)};
  // A: atoms 1-4, B: 5-8, C: 9-12 (corners from the lower left, counter-clockwise)
  t.adhesive = {{1, 6}, {4, 7}, {2, 9}};
  return write_tissue(t, "image_flags.data");
}

std::string read_text(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int count(const std::string &text, const std::string &what)
{
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) n++;
  return n;
}

// a session on the three cells that logs to 'log'
std::unique_ptr<LammpsSession> three_cell_session(const std::string &log)
{
  auto s = std::make_unique<LammpsSession>();
  s->run("log " + log + "\n" + contact_commands(three_cells()) +
         "fix relax all box/relax iso 0.0 vmax 1.0e-4\n"
         "compute tissue all dpoly/tissue\nthermo 1000\n");
  return s;
}

// the log so far, on every rank (rank 0 writes it)
std::string close_log(LammpsSession &s, const std::string &log)
{
  s.run("log none");
  MPI_Barrier(MPI_COMM_WORLD);
  return read_text(log);
}

// the Bonds section of a data file of the three cells: 12 ring segments (type 1) and the 3
// adhesive bonds (type 2), no other type
void expect_bond_types_of_three_cells(const std::string &data)
{
  std::istringstream in(read_text(data));
  std::string line;
  while (std::getline(in, line) && line.rfind("Bonds", 0) != 0) continue;
  std::getline(in, line);
  int adhesive = 0, segments = 0, other = 0;
  while (std::getline(in, line) && !line.empty()) {
    int id = 0, type = 0;
    std::istringstream(line) >> id >> type;
    (type == 2 ? adhesive : type == 1 ? segments : other)++;
  }
  EXPECT_EQ(adhesive, 3);
  EXPECT_EQ(segments, 12);
  EXPECT_EQ(other, 0) << "bond types in " << data << " other than 1 and 2";
}

}    // namespace

TEST(ImageFlags, LammpsWarnsOnceThePackageSaysWhyOnceOtherWarningsStay)
{
  const std::string log = scratch("image_flags_once.log");
  auto s = three_cell_session(log);
  for (int k = 0; k < 3; k++) s->run(MINIMIZE);
  const std::string text = close_log(*s, log);
  EXPECT_EQ(count(text, WARNING), 1) << text;
  EXPECT_EQ(count(text, REASON), 1) << text;
  EXPECT_EQ(count(text, OTHER_WARNING), 3) << "a warning that is not this one is hidden";
  // the reason follows LAMMPS's warning and counts the bonds across the boundary
  EXPECT_LT(text.find(WARNING), text.find(REASON));
  EXPECT_NE(text.find("for 2 of the 3 adhesive bonds"), std::string::npos) << text;
}

TEST(ImageFlags, HiddenBondsGetTheirTypesBack)
{
  const std::string log = scratch("image_flags_types.log");
  auto s = three_cell_session(log);
  s->run(MINIMIZE);    // LAMMPS warns, the reason is given: from now on the bonds are hidden
  s->run("run 0 post no");
  const double bonds = s->thermo("c_tissue[5]");
  const double energy = s->thermo("pe");
  EXPECT_EQ(bonds, 3.0) << "the adhesive bonds must be back after the check";
  s->run("run 0 post no");
  EXPECT_DOUBLE_EQ(s->thermo("pe"), energy);

  // write_data also calls the fixes' setup_pre_exchange(), with no check to follow: nothing
  // may be hidden there
  const std::string data = scratch("image_flags_written.data");
  s->run("write_data " + data);
  const std::string text = close_log(*s, log);
  expect_bond_types_of_three_cells(data);
  s->run("run 0 post no");
  EXPECT_DOUBLE_EQ(s->thermo("pe"), energy);
  EXPECT_EQ(count(text, WARNING), 1);
}

// An error inside the window (here Domain::pbc()'s check of non-finite coordinates, thrown
// after the hub has hidden the bonds and caught by the library interface) must not leave the
// adhesive bonds hidden: the next init() gives them back, before write_data writes them.
TEST(ImageFlags, AnErrorInsideTheCheckLeavesNoBondHidden)
{
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  // Domain::pbc() stops with error->one on the rank that owns the atom: one rank only
  if (nprocs > 1) GTEST_SKIP() << "error->one inside a collective setup needs one rank";
  const std::string log = scratch("image_flags_error.log");
  auto s = three_cell_session(log);
  s->run(MINIMIZE);    // the reason is given: from now on the bonds are hidden at each setup
  std::vector<double> x = s->gather("x", 3);
  const double x1 = x[0];
  x[0] = std::nan("");
  s->scatter("x", 3, x);
  const std::string error = s->try_run(MINIMIZE);
  EXPECT_NE(error.find("Non-numeric atom coords"), std::string::npos) << error;
  x[0] = x1;
  s->scatter("x", 3, x);
  const std::string data = scratch("image_flags_after_error.data");
  s->run("write_data " + data);
  close_log(*s, log);
  expect_bond_types_of_three_cells(data);
}

TEST(ImageFlags, RingWithInconsistentImageFlagsIsStillReported)
{
  const std::string log = scratch("image_flags_ring.log");
  auto s = three_cell_session(log);
  s->run(MINIMIZE);
  // vertex 2 of cell A one box length to the right: its two ring segments are inconsistent
  s->run("set atom 2 image 1 0 0");
  const std::string error = s->try_run(MINIMIZE);
  const std::string text = close_log(*s, log);
  EXPECT_EQ(count(text, WARNING), 2) << "the ring segments must stay in LAMMPS's check\n" << text;
  EXPECT_NE(error.find("Fix dpoly/cells"), std::string::npos) << error;
}
