/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef MINIMIZE_CLASS
// clang-format off
MinimizeStyle(fire/nph,MinFireNph);
// clang-format on
#else

#ifndef LMP_MIN_FIRE_NPH_H
#define LMP_MIN_FIRE_NPH_H

#include "min.h"

#include <string>

namespace LAMMPS_NS {

// FIRE damped dynamics in which the box lengths that fix box/relax exposes are dynamical
// degrees of freedom too (the NPH-FIRE of Treado et al., S3). It minimizes the enthalpy
// U + P0 V from forces alone, so it keeps converging where line searches on the enthalpy stall
// at round-off. Without fix box/relax it is plain FIRE at fixed box.
class MinFireNph : public Min {
 public:
  MinFireNph(class LAMMPS *);
  ~MinFireNph() override;

  void init() override;
  void setup_style() override;
  void reset_vectors() override;
  int iterate(int) override;
  void run(int) override;
  int modify_param(int, char **) override;

 private:
  double boxmass_scale;    // box mass relative to that of an affine dilation
  bool steer_by_mass;      // FIRE's steering in mass-weighted coordinates (min_modify steer mass)
  bool rms_tolerance;      // ftol bounds the force per degree of freedom (min_modify rms yes)
  bool adapt_cap;          // lower the step cap when FIRE keeps restarting (min_modify tmaxadapt)

  double dt, dtmax, dtmin, alpha;
  double last_drift_time;    // time of the last drift, after dmax and vmax shortened it
  bigint last_negative;
  double *velocity;    // per-atom FIRE velocities, kept by fix_minimize so they migrate

  // box degrees of freedom, as changes q of the box lengths (a length, like the atom dof)
  double *box_length;      // box length each dof dilates, at setup
  double *box_mass;        // kinetic mass of each dof
  double *box_velocity;    // dq/dt
  double *box_step;        // scratch: dq/box_length, what fix box/relax min_step() takes

  // a stall: FIRE keeps turning uphill at its smallest time step. Counted since dt was last
  // back at the timestep:
  struct StallRecord {
    bigint uphill;           // uphill steps at dt = dtmin
    bigint atoms_uphill;     // ... in which the atoms' own power was negative
    bigint box_uphill;       // ... in which the box's own power was negative
    bigint drifts;           // drifts at dt = dtmin
    bigint atoms_at_dmax;    // ... in which an atom would have moved beyond dmax
    bigint box_limited;      // ... shortened for the box (dmax or fix box/relax's vmax)
  } stall;

  // this minimization so far, for the line it logs at its end: how often FIRE turned uphill (and
  // so restarted from rest) and its mean time step; a FIRE that restarts every few steps moves
  // its soft modes as steepest descent does, by far slower than with momentum
  struct RunRecord {
    bigint steps;          // iterations
    bigint uphill;         // uphill steps (velocities zeroed)
    bigint atoms_uphill;   // ... in which the atoms' own power was negative
    bigint box_uphill;     // ... in which the box's own power was negative
    double dt_sum;         // sum of FIRE's time step over the iterations
    int caps_lowered;      // times the step cap was lowered (min_modify tmaxadapt)
  } run_record;
  void log_run_record() const;

  // the run record when the step cap was last judged (min_modify tmaxadapt judges the window since)
  RunRecord cap_window_start;
  void judge_step_cap();

  struct Power {
    double total, atoms, box;
  };
  struct Drift {
    double time;
    bool atoms_at_dmax;    // an atom would have moved beyond dmax in dt
    bool box_limited;      // the box would have moved beyond dmax or vmax in dt
  };

  void start_afresh();
  double global_sum(double) const;
  Power vdotf() const;
  double rms_force_sqr() const;
  void zero_velocities();
  double mix_velocities();
  // mass of owned atom i (per-atom rmass or per-type mass)
  double atom_mass(int i) const;
  Drift displacement_time() const;
  void move(double);

  void check_energy() const;
  void check_force_norm(double) const;
  void check_box_move(double) const;
  void record_stall_uphill(const Power &);
  void record_stall_drift(const Drift &);
  std::string largest_force() const;
  std::string what_to_change() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
