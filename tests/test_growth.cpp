// Growth rules of fix mesophyll/grow (doc/Howto_mesophyll.rst, section "Growth") on hand-made
// rings whose void runs are known: exact changes of l0, theta0, a0 and sigma, the clamp at
// theta0_min, and both calA_max rules. Runs on any number of ranks.
#include "test_helpers.h"

#include "fix.h"
#include "lammps.h"
#include "modify.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cstring>
#include <memory>
#include <vector>

using ::testing::HasSubstr;

using namespace test;

namespace {

// Cell 1: a regular octagon of circumradius 1 (vertices 1-8), bonded at vertices 2, 3 and 6, so
// its void runs are {4, 5} and {7, 8, 1}. Cell 2: a unit square (vertices 9-12) bonded at 9, 10,
// 11: one void run {12}. Bonds are long, but no minimization runs here.
std::string octagon_and_square()
{
  Tissue t;
  Polygon octagon;
  for (int k = 0; k < 8; k++)
    octagon.corners.push_back({10.0 + cos(2 * PI * k / 8), 10.0 + sin(2 * PI * k / 8)});
  t.cells = {octagon, square(20.0, 10.0, 1.0)};
  t.adhesive = {{2, 9}, {3, 10}, {6, 11}};
  t.sigma = 0.3;
  return write_tissue(t, "growth.data");
}

std::unique_ptr<LammpsSession> grown(const std::string &options, MPI_Comm comm = MPI_COMM_WORLD)
{
  auto s = std::make_unique<LammpsSession>(comm);
  s->run(contact_commands(octagon_and_square()) +
         "fix grow all mesophyll/grow runs yes box fixed " + options + "\nrun 0 post no");
  return s;
}

struct Ring {
  std::vector<bool> is_void;
  std::vector<double> run;    // run length of each void vertex
  double segment, perimeter, area;
};

// the octagon and the square as the test knows them
Ring octagon_ring()
{
  const double l = 2.0 * sin(PI / 8);
  return {{true, false, false, true, true, false, true, true},
          {3 * l, 0, 0, 2 * l, 2 * l, 0, 3 * l, 3 * l},
          l,
          8 * l,
          2.0 * sqrt(2.0)};
}

Ring square_ring()
{
  return {{false, false, false, true}, {0, 0, 0, 1.0}, 1.0, 4.0, 1.0};
}

struct Expected {
  std::vector<double> l0, theta0;
};

// the growth rules (doc/Howto_mesophyll.rst, section "Growth") written out for one ring
Expected expected_growth(const Ring &r, double theta_start, double delta_a, double lambda,
                         double c_l, double c_b, double theta_min, double above_factor,
                         bool below_max)
{
  const int n = (int) r.is_void.size();
  const double dl_std = 0.5 * r.perimeter / r.area * delta_a;
  double mean_run = 0.0, runs = 0.0;
  for (int k = 0; k < n; k++)    // each run counted once: at its first vertex
    if (r.is_void[k] && !r.is_void[(k + n - 1) % n]) {
      mean_run += r.run[k];
      runs += 1.0;
    }
  mean_run /= runs;
  std::vector<double> dl(n, 0.0), angle(n, theta_start);
  for (int k = 0; k < n; k++) {
    if (!r.is_void[k]) continue;
    dl[k] = below_max
        ? lambda * dl_std / n * ((1 - c_l) + c_l * (mean_run - r.run[k]) / r.perimeter)
        : above_factor * dl_std / n;
    angle[k] = std::max(theta_min, theta_start - c_b * dl_std / n);
  }
  Expected e;
  for (int k = 0; k < n; k++) {
    const int before = (k + n - 1) % n, after = (k + 1) % n;
    e.l0.push_back(r.segment + dl[k] + dl[after]);
    e.theta0.push_back(angle[k] + dl_std / n * (angle[after] + angle[before] - 2 * angle[k]));
  }
  return e;
}

void expect_ring(const std::vector<double> &l0, const std::vector<double> &theta0, int first,
                 const Expected &e, const char *what)
{
  for (size_t k = 0; k < e.l0.size(); k++) {
    EXPECT_NEAR(l0[first + k], e.l0[k], 1e-13) << what << " vertex " << first + k + 1;
    EXPECT_NEAR(theta0[first + k], e.theta0[k], 1e-13) << what << " vertex " << first + k + 1;
  }
}

}    // namespace

TEST(Growth, VoidRunsGrowLengthsAndTurnAngles)
{
  auto s = grown("delta_a 0.5 lambda 5 c_L 0.5 c_B 4");
  const std::vector<double> l0 = s->gather("d_l0", 1), theta0 = s->gather("d_theta0", 1);
  expect_ring(l0, theta0, 0,
              expected_growth(octagon_ring(), 2 * PI / 8, 0.5, 5, 0.5, 4, -PI / 10, 1, true),
              "octagon");
  expect_ring(l0, theta0, 8,
              expected_growth(square_ring(), PI / 2, 0.5, 5, 0.5, 4, -PI / 10, 1, true), "square");
  EXPECT_EQ(s->thermo("f_grow[1]"), 1.0);
  EXPECT_EQ(s->thermo("f_grow[2]"), 6.0) << "5 void vertices in the octagon, 1 in the square";
}

TEST(Growth, AreaGrowsAndDiametersFollow)
{
  auto s = grown("delta_a 0.25");
  const std::vector<double> a0 = s->gather("d_a0", 1), sigma = s->gather("d_sigma", 1);
  for (int k = 0; k < 8; k++) {
    EXPECT_NEAR(a0[k], 2 * sqrt(2.0) + 0.25, 1e-13);
    EXPECT_NEAR(sigma[k], 0.3 * sqrt((2 * sqrt(2.0) + 0.25) / (2 * sqrt(2.0))), 1e-13);
  }
  EXPECT_NEAR(a0[8], 1.25, 1e-13);
  EXPECT_NEAR(sigma[8], 0.3 * sqrt(1.25), 1e-13);

  auto fixed = grown("delta_a 0.25 scale_sigma no");
  EXPECT_EQ(fixed->gather("d_sigma", 1)[0], 0.3);
}

TEST(Growth, PreferredAnglesStopAtTheirMinimum)
{
  auto s = grown("theta0_min 0.7");
  const std::vector<double> l0 = s->gather("d_l0", 1), theta0 = s->gather("d_theta0", 1);
  expect_ring(l0, theta0, 0,
              expected_growth(octagon_ring(), 2 * PI / 8, 0.5, 5, 0.5, 4, 0.7, 1, true),
              "octagon clamped");
}

// calA of the octagon is 1.055 and of the square 1.273: calA_max 1 puts both above it
TEST(Growth, AboveShapeLimitGrowthIsIsometricOrNone)
{
  auto code = grown("calA_max 1.0 rules code");
  expect_ring(code->gather("d_l0", 1), code->gather("d_theta0", 1), 0,
              expected_growth(octagon_ring(), 2 * PI / 8, 0.5, 5, 0.5, 4, -PI / 10, 1, false),
              "code rule");
  EXPECT_EQ(code->thermo("f_grow[3]"), 2.0);

  auto paper = grown("calA_max 1.0 rules paper");
  expect_ring(paper->gather("d_l0", 1), paper->gather("d_theta0", 1), 0,
              expected_growth(octagon_ring(), 2 * PI / 8, 0.5, 5, 0.5, 4, -PI / 10, 0, false),
              "paper rule");
}

// phi at each growth step is the packing at the minimum just reached; delta_phi_plus sums its
// rises. The box changes without moving the cells, so only phi changes.
TEST(Growth, CompactionSumsOnlyTheRisesOfPhi)
{
  const double cell_area = 2.0 * sqrt(2.0) + 1.0;    // octagon + square
  auto s = grown("");
  const double phi1 = cell_area / s->thermo("vol");
  EXPECT_NEAR(s->thermo("f_grow[4]"), phi1, 1e-14);
  EXPECT_EQ(s->thermo("f_grow[5]"), 0.0);

  s->run("change_box all x scale 0.9 y scale 0.9\nrun 0 post no");
  const double phi2 = phi1 / 0.81;
  EXPECT_NEAR(s->thermo("f_grow[4]"), phi2, 1e-13);
  EXPECT_NEAR(s->thermo("f_grow[5]"), phi2 - phi1, 1e-13);

  s->run("change_box all x scale 1.5 y scale 1.5\nrun 0 post no");
  EXPECT_NEAR(s->thermo("f_grow[4]"), phi2 / 2.25, 1e-13);
  EXPECT_NEAR(s->thermo("f_grow[5]"), phi2 - phi1, 1e-13) << "a fall of phi adds nothing";
}

TEST(Growth, ParallelRunMatchesSerialRun)
{
  if (world_size() == 1) GTEST_SKIP() << "needs more than one MPI rank";
  auto parallel = grown("");
  auto serial = grown("", self_comm());
  for (const char *name : {"d_l0", "d_theta0", "d_a0", "d_sigma"})
    EXPECT_EQ(parallel->gather(name, 1), serial->gather(name, 1)) << name;
}

class BadGrowth : public ErrorTest {
 protected:
  // the error of one fix command on a small tissue
  static std::string error_of(const std::string &fix_line)
  {
    return ErrorTest::error_of(contact_commands(octagon_and_square()) + fix_line +
                               "\nrun 0 post no");
  }
};

TEST_F(BadGrowth, RefusesNonsense)
{
  EXPECT_THAT(error_of("fix g all mesophyll/grow delta_a -0.5"),
              HasSubstr("delta_a must be >= 0, got -0.5"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow lambda -1"),
              HasSubstr("lambda must be >= 0, got -1"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow c_B -4"), HasSubstr("c_B must be >= 0, got -4"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow c_L 1.5"),
              HasSubstr("c_L must be in [0, 1], got 1.5"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow c_L -0.1"),
              HasSubstr("c_L must be >= 0, got -0.1"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow rules mine"),
              HasSubstr("rules must be 'code', 'paper' or 'published', got 'mine'"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow speed 2"), HasSubstr("keyword: speed"));
  EXPECT_THAT(error_of("fix g all mesophyll/grow box open"),
              HasSubstr("box must be 'relax' or 'fixed'"));
}

TEST_F(BadGrowth, NeedsBoxRelaxUnlessToldTheBoxIsFixed)
{
  const std::string msg = error_of("fix g all mesophyll/grow");
  EXPECT_THAT(msg, HasSubstr("needs fix box/relax"));
  EXPECT_EQ(error_of("fix g all mesophyll/grow box fixed"), "");
}

TEST_F(BadGrowth, NeedsTheCells)
{
  LammpsSession s;
  std::string cmds = contact_commands(octagon_and_square());
  cmds.replace(cmds.find("fix cells all dpoly/cells eps_a 1.0\n"), 36, "");
  cmds.replace(cmds.find(" f_cells"), 8, "");
  const std::string msg = s.try_run(cmds + "fix g all mesophyll/grow\nrun 0 post no");
  EXPECT_THAT(msg, HasSubstr("needs fix dpoly/cells"));
}

// A stage's restart record carries its format version and its number of values, so that a record
// of another format is refused with a message instead of being read as numbers.
TEST_F(BadGrowth, RestartRecordOfAnotherFormatIsRefused)
{
  LammpsSession s;
  s.run(contact_commands(octagon_and_square()) + "fix g all mesophyll/grow box fixed\n");
  auto *lmp = static_cast<LAMMPS_NS::LAMMPS *>(s.lammps_handle());
  LAMMPS_NS::Fix *grow = lmp->modify->get_fix_by_id("g");
  ASSERT_NE(grow, nullptr);
  auto record = [](int version, int count) {
    std::vector<char> buf(2 * sizeof(int) + 3 * sizeof(double), 0);
    const int header[2] = {version, count};
    memcpy(buf.data(), header, sizeof(header));
    return buf;
  };
  for (const auto &header : {std::make_pair(7, 3), std::make_pair(1, 2)}) {
    std::vector<char> buf = record(header.first, header.second);
    std::string message;
    try {
      grow->restart(buf.data());
    } catch (std::exception &e) {
      message = e.what();
    }
    EXPECT_THAT(message, HasSubstr("holds state this version cannot read")) << header.first;
  }
  std::vector<char> good = record(1, 3);
  EXPECT_NO_THROW(grow->restart(good.data())) << "version 1 with its 3 values is read";
}

// The hub finds its stages at every use: a stage removed between runs, with 'run pre no' (which
// skips init()), is not called (the sanitizer build sees a use after free if it were)
TEST(Growth, StageRemovedBetweenRunsIsNotCalled)
{
  LammpsSession s;
  s.run(contact_commands(octagon_and_square()) +
        "fix g all mesophyll/grow box fixed runs yes\nrun 0 post no\n");
  const double a0 = s.gather("d_a0", 1)[0];
  s.run("unfix g\nrun 0 pre no post no\n");
  EXPECT_EQ(s.gather("d_a0", 1)[0], a0) << "no growth after the fix is gone";
}

// compute dpoly/tissue looks the hub up at every evaluation: after the hub was removed, 'run N
// pre no' (which skips init()) gets an error naming it, not a read of the deleted fix (the
// sanitized build reports a heap-use-after-free otherwise). The thermo output holds only the
// compute: LAMMPS's own pe would read the deleted fix first.
TEST(Growth, TissueComputeAfterHubRemovedNamesTheHub)
{
  LammpsSession s;
  s.run(contact_commands(octagon_and_square()) +
        "compute tissue all dpoly/tissue\nthermo_style custom step c_tissue[1]\nrun 0 post no\n");
  EXPECT_THAT(s.try_run("unfix cells\nrun 1 pre no post no\n"),
              HasSubstr("Compute dpoly/tissue needs fix dpoly/cells"));
}

// What a value printed after a run whose growth changed the tissue describes does not depend on
// whether the thermo output evaluated the compute at the run's last step: compute dpoly/tissue
// gives the tissue before growth acted (the minimum; phi_patch moves with sigma, which growth
// scales), compute dpoly/hessian the tissue as it is (l0, theta0 and a0 have grown).
TEST(Growth, ComputesAfterTheRunDoNotDependOnTheThermoOutput)
{
  const std::string tissue = contact_commands(octagon_and_square()) +
      "compute tissue all dpoly/tissue\ncompute hessian all dpoly/hessian modes 4\n";
  const std::string grow = "fix grow all mesophyll/grow runs yes box fixed\n";
  auto values_now = [](LammpsSession &s) {
    return std::vector<double>{s.equal_variable("c_tissue[2]"), s.equal_variable("c_hessian[4]")};
  };
  LammpsSession before, grown;
  before.run(tissue + "run 0 post no\n");
  const std::vector<double> minimum = values_now(before);
  grown.run(tissue + grow + "run 0 post no\nunfix grow\nrun 0 post no\n");
  const std::vector<double> after_growth = values_now(grown);
  ASSERT_NE(minimum[0], after_growth[0]) << "growth moves phi_patch";
  ASSERT_NE(minimum[1], after_growth[1]) << "growth moves the Hessian";

  for (const bool in_thermo : {true, false}) {
    LammpsSession s;
    s.run(tissue + (in_thermo ? "thermo_style custom step c_tissue[2] c_hessian[4]\n" : "") + grow +
          "run 0 post no\n");
    const std::vector<double> printed = values_now(s);
    EXPECT_EQ(printed[0], minimum[0]) << "phi_patch, compute in thermo: " << in_thermo;
    EXPECT_NEAR(printed[1], after_growth[1], 1e-12 * std::fabs(after_growth[1]))
        << "Hessian, compute in thermo: " << in_thermo;
  }
}
