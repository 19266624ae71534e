// min_style fire/nph (doc/min_fire_nph.rst): FIRE with the box of fix box/relax as degrees of
// freedom. Its checks of bad settings are cases of test_bad_input ("minimizer").
#include "test_helpers.h"

#include "gtest/gtest.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace test;

namespace {

const double VMAX = 1.0e-3;    // fix box/relax vmax of tissue16_commands()

// The box length lx at every step of the thermo table of a minimization written to 'log'.
std::vector<double> box_lengths(const std::string &log)
{
  std::ifstream in(log);
  std::vector<double> lengths;
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "Step") {
      in_table = true;
    } else if (first == "Loop") {
      in_table = false;
    } else if (in_table) {
      double pe, press, lx;
      if (words >> pe >> press >> lx) lengths.push_back(lx);
    }
  }
  return lengths;
}

}    // namespace

// After an uphill step FIRE steps back by half a time step; when dmax or vmax shortened the
// drift before it, the step back must undo at most half of that drift, not half of
// dt x velocity. A box of tiny mass has a huge velocity and turns uphill at almost every
// step: each step then moves it by at most vmax (the drift) plus half of that (the step back).
TEST(FireNph, StepBackUndoesAtMostHalfOfTheDrift)
{
  const std::string log = scratch("fire_nph_step_back.log");
  {
    LammpsSession s;    // closed before the log is read
    s.run("log " + log + "\n" + tissue16_commands() +
          "min_modify boxmass 1.0e-9\nthermo 1\nthermo_modify format float %.17g\n"
          "minimize 0.0 1.0e-10 300 3000\n");
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const std::vector<double> lx = box_lengths(log);
  ASSERT_GT(lx.size(), 100u);
  const double bound = 1.5 * VMAX * lx.front() * (1.0 + 1.0e-9);
  int reversals = 0;
  for (size_t k = 1; k < lx.size(); k++) {
    EXPECT_LE(std::fabs(lx[k] - lx[k - 1]), bound) << "step " << k;
    if (k > 1 && (lx[k] - lx[k - 1]) * (lx[k - 1] - lx[k - 2]) < 0.0) reversals++;
  }
  EXPECT_GT(reversals, 10) << "the box must turn back: the test needs uphill steps";
}
