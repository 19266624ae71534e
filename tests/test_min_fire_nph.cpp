// min_style fire/nph (doc/min_fire_nph.rst): FIRE with the box of fix box/relax as degrees of
// freedom. Its checks of bad settings are cases of test_bad_input ("minimizer").
#include "test_helpers.h"

#include "gtest/gtest.h"

#include <cctype>
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
  long caps_lowered = 0;    // min_modify tmaxadapt: times the cap was lowered, and to what
  double lowered_cap = -1.0;
  bool converged = false;    // LAMMPS's stopping criterion was the force tolerance
  // the record's place: how many such lines, and whether the last lies after the thermo table's
  // last row and before "Loop time"
  int records = 0;
  bool after_table = false;
};

RunRecord run_record(const std::string &log)
{
  std::ifstream in(log);
  RunRecord r;
  bool in_table = false, row_since_record = false;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "Step") in_table = true;
    if (first == "Loop") {
      in_table = false;
      r.after_table = r.records > 0 && !row_since_record;
    }
    if (in_table && !first.empty() && std::isdigit(static_cast<unsigned char>(first[0])))
      row_since_record = true;
    if (line.rfind("  fire/nph: ", 0) == 0) {
      r.records++;
      row_since_record = false;
    }
    sscanf(line.c_str(),
           "  fire/nph: %ld iterations, %ld uphill (velocities zeroed; the atoms' power negative "
           "in %ld, the box's in %ld), mean time step %lf (tmax x timestep = %lf)",
           &r.iterations, &r.uphill, &r.atoms_uphill, &r.box_uphill, &r.mean_dt, &r.dtmax);
    const size_t lowered = line.find(", lowered ");
    if (line.rfind("  fire/nph: ", 0) == 0 && lowered != std::string::npos)
      sscanf(line.c_str() + lowered, ", lowered %ld times to %lf by tmaxadapt)", &r.caps_lowered,
             &r.lowered_cap);
    sscanf(line.c_str(), "  Iterations, force evaluations = %ld", &r.lammps_iterations);
    if (line.find("Stopping criterion = force tolerance") != std::string::npos)
      r.converged = true;
  }
  return r;
}

// min_modify tmaxadapt as given ("yes" or "no"), at most maxiter iterations
RunRecord minimize_with_timestep(const std::string &name, const std::string &timestep,
                                 const std::string &tmaxadapt = "no", int maxiter = 2000)
{
  const std::string log = scratch(name);
  {
    LammpsSession s;
    s.run("log " + log + "\n" + tissue16_commands() + "timestep " + timestep +
          "\nmin_modify tmaxadapt " + tmaxadapt + "\nminimize 0.0 1.0e-10 " +
          std::to_string(maxiter) + " " + std::to_string(10 * maxiter) + "\n");
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
    EXPECT_EQ(r.records, 1);
    EXPECT_TRUE(r.after_table) << "the record must follow the thermo table's last row";
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

// min_modify tmaxadapt yes: where FIRE keeps restarting from rest far below its cap,
// the cap comes down until it does not; where it converges normally, nothing changes. Below the
// 16-cell tissue's limit (cap 0.05) the minimization is the same, iteration for iteration, as
// without it; beyond (cap 0.15) the cap is lowered below the stable step (about 0.09) and the
// minimization converges where without it FIRE crawls to the iteration limit.
TEST(FireNph, TmaxAdaptLowersTheCapOnlyWhereFireKeepsRestarting)
{
  const RunRecord below_fixed =
      minimize_with_timestep("fire_nph_adapt_below_fixed.log", "0.01", "no");
  const RunRecord below = minimize_with_timestep("fire_nph_adapt_below.log", "0.01", "yes");
  ASSERT_GT(below.iterations, 1000) << "the case needs windows of 500 iterations to judge";
  EXPECT_TRUE(below.converged);
  EXPECT_EQ(below.caps_lowered, 0);
  EXPECT_EQ(below.iterations, below_fixed.iterations);
  EXPECT_EQ(below.uphill, below_fixed.uphill);
  EXPECT_DOUBLE_EQ(below.mean_dt, below_fixed.mean_dt);

  // seen on 1 rank: without tmaxadapt 15949 iterations (857 uphill, mean step 0.025); with it
  // 3527 (138 uphill), the cap lowered 5 times to 0.049
  const int maxiter = 8000;
  const RunRecord fixed =
      minimize_with_timestep("fire_nph_adapt_beyond_fixed.log", "0.03", "no", maxiter);
  const RunRecord adapted =
      minimize_with_timestep("fire_nph_adapt_beyond.log", "0.03", "yes", maxiter);
  ASSERT_GT(adapted.iterations, 0) << "no fire/nph line in the log";
  EXPECT_FALSE(fixed.converged) << "without tmaxadapt: " << fixed.iterations << " iterations";
  EXPECT_EQ(fixed.caps_lowered, 0);
  EXPECT_TRUE(adapted.converged) << adapted.iterations << " iterations, cap lowered "
                                 << adapted.caps_lowered << " times to " << adapted.lowered_cap;
  ASSERT_GE(adapted.caps_lowered, 1);
  EXPECT_DOUBLE_EQ(adapted.dtmax, 0.15);    // the line names the cap it started from
  const double expected = 0.15 * std::pow(0.8, adapted.caps_lowered);
  EXPECT_NEAR(adapted.lowered_cap, expected, 1.0e-3 * expected);    // printed to 4 digits
  EXPECT_LT(adapted.lowered_cap, 0.09);
}

// The floor: with the timestep 0.08, itself near the stable step, and the cap 5 x 0.08 = 0.4, the
// cap comes down by 0.8 per window to 0.4 x 0.8^7 = 0.084, then to the timestep, and stays there.
TEST(FireNph, TmaxAdaptStopsAtTheTimestep)
{
  const RunRecord r = minimize_with_timestep("fire_nph_adapt_floor.log", "0.08", "yes", 8000);
  ASSERT_GT(r.iterations, 0) << "no fire/nph line in the log";
  EXPECT_DOUBLE_EQ(r.dtmax, 0.4);
  EXPECT_EQ(r.caps_lowered, 8);
  EXPECT_DOUBLE_EQ(r.lowered_cap, 0.08);
}
