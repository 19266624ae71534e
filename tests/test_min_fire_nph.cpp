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

namespace {

// The line fire/nph logs at the end of a minimization, and LAMMPS's own iteration count.
struct RunRecord {
  long iterations = -1, uphill = -1, atoms_uphill = -1, box_uphill = -1, lammps_iterations = -2;
  double mean_dt = -1.0, dtmax = -1.0;
};

RunRecord run_record(const std::string &log)
{
  std::ifstream in(log);
  RunRecord r;
  for (std::string line; std::getline(in, line);) {
    sscanf(line.c_str(),
           "  fire/nph: %ld iterations, %ld uphill (velocities zeroed; the atoms' power negative "
           "in %ld, the box's in %ld), mean time step %lf (tmax x timestep = %lf)",
           &r.iterations, &r.uphill, &r.atoms_uphill, &r.box_uphill, &r.mean_dt, &r.dtmax);
    sscanf(line.c_str(), "  Iterations, force evaluations = %ld", &r.lammps_iterations);
  }
  return r;
}

RunRecord minimize_with_timestep(const std::string &name, const std::string &timestep)
{
  const std::string log = scratch(name);
  {
    LammpsSession s;
    s.run("log " + log + "\n" + tissue16_commands() + "timestep " + timestep +
          "\nminimize 0.0 1.0e-10 2000 20000\n");
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return run_record(log);
}

}    // namespace

// The closing line of a minimization says how often FIRE turned uphill and its mean time step:
// what tells a slow minimization whose largest step, tmax x timestep, is beyond the stable step
// 2/omega_max of the stiffest mode (FIRE restarts from rest again and again, its soft modes then
// crawl) from one with a genuinely slow mode. The 16-cell tissue's stiffest mode allows about
// 0.09 (Hessian eigenvalue about 500): tmax x timestep = 0.05 is below it, 0.15 beyond.
TEST(FireNph, LogsUphillStepsAndMeanTimeStep)
{
  const RunRecord below = minimize_with_timestep("fire_nph_record_below.log", "0.01");
  const RunRecord beyond = minimize_with_timestep("fire_nph_record_beyond.log", "0.03");
  for (const RunRecord &r : {below, beyond}) {
    ASSERT_GT(r.iterations, 0) << "no fire/nph line in the log";
    EXPECT_EQ(r.iterations, r.lammps_iterations);
    EXPECT_LE(r.atoms_uphill, r.uphill);
    EXPECT_LE(r.box_uphill, r.uphill);
    EXPECT_GT(r.mean_dt, 0.0);
    EXPECT_LE(r.mean_dt, r.dtmax * (1.0 + 1.0e-12));
  }
  EXPECT_DOUBLE_EQ(below.dtmax, 0.05);
  EXPECT_DOUBLE_EQ(beyond.dtmax, 0.15);
  // below the limit (seen: 5 uphill in 1240 iterations, mean step 0.047) few restarts, steps near
  // the cap; beyond it (seen: 109 in 2000, not converged, mean step 0.025) restarts every few
  // dozen steps and steps far below the cap
  EXPECT_LT(below.uphill * 100, below.iterations) << below.uphill << " of " << below.iterations;
  EXPECT_GT(below.mean_dt, 0.7 * below.dtmax);
  EXPECT_GT(beyond.uphill * 40, beyond.iterations) << beyond.uphill << " of " << beyond.iterations;
  EXPECT_GT(beyond.atoms_uphill * 2, beyond.uphill);
  EXPECT_LT(beyond.mean_dt, 0.5 * beyond.dtmax);
}
