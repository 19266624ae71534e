/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "min_fire_nph.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_minimize.h"
#include "force.h"
#include "modify.h"
#include "output.h"
#include "timer.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

// same normalisation of the energy tolerance as LAMMPS's other minimizers
static constexpr double EPS_ENERGY = 1.0e-8;

// FIRE is stalled when it turns uphill this many times at its smallest time step before dt
// grows back to the timestep (a converging run does not reach dtmin at all)
static constexpr bigint STALL_UPHILL_STEPS = 1000;

// within one minimization, a box length may shrink or grow by at most this factor: a larger
// change is a box that collapses or runs away, not a relaxation (vmax already bounds one step)
static constexpr double BOX_CHANGE_LIMIT = 4.0;

// min_modify tmaxadapt: a FIRE whose step cap tmax x timestep lies above what its stiffest mode
// allows turns uphill every few dozen iterations and spends most of its time far below the cap
// (after vertex insertion split a segment twice: 1 uphill step in 19 iterations, mean step 0.35
// of the cap); a converging FIRE turns uphill once in hundreds, at steps near the cap. Judged
// over each window of CAP_WINDOW iterations: more than one uphill step in CAP_UPHILL_SPACING and
// a mean step below CAP_MEAN_FRACTION of the cap lower the cap by CAP_LOWERING, never below the
// timestep (nor tmin x timestep). The cap stays lowered until the minimization ends.
static constexpr bigint CAP_WINDOW = 500;
static constexpr bigint CAP_UPHILL_SPACING = 50;
static constexpr double CAP_MEAN_FRACTION = 0.5;
static constexpr double CAP_LOWERING = 0.8;

/* ---------------------------------------------------------------------- */

MinFireNph::MinFireNph(LAMMPS *lmp) :
    Min(lmp), boxmass_scale(1.0), steer_by_mass(false), rms_tolerance(false),
    adapt_cap(false), velocity(nullptr),
    box_length(nullptr), box_mass(nullptr), box_velocity(nullptr), box_step(nullptr)
{
  // Min::setup() refuses fix box/relax with damped dynamics because FIRE and quickmin ignore
  // the box; this style moves the box itself, so it declares itself box-aware.
  searchflag = 1;
}

/* ---------------------------------------------------------------------- */

MinFireNph::~MinFireNph()
{
  delete[] box_length;
  delete[] box_mass;
  delete[] box_velocity;
  delete[] box_step;
}

/* ---------------------------------------------------------------------- */

int MinFireNph::modify_param(int narg, char **arg)
{
  if (strcmp(arg[0], "boxmass") == 0) {
    if (narg < 2) utils::missing_cmd_args(FLERR, "min_modify boxmass", error);
    boxmass_scale = utils::numeric(FLERR, arg[1], false, lmp);
    if (boxmass_scale <= 0.0)
      error->all(FLERR, "min_modify boxmass value {} must be > 0", boxmass_scale);
    return 2;
  }
  if (strcmp(arg[0], "steer") == 0) {
    if (narg < 2) utils::missing_cmd_args(FLERR, "min_modify steer", error);
    if (strcmp(arg[1], "force") == 0)
      steer_by_mass = false;
    else if (strcmp(arg[1], "mass") == 0)
      steer_by_mass = true;
    else
      error->all(FLERR, "min_modify steer must be force or mass, got {}", arg[1]);
    return 2;
  }
  if (strcmp(arg[0], "rms") == 0) {
    if (narg < 2) utils::missing_cmd_args(FLERR, "min_modify rms", error);
    rms_tolerance = utils::logical(FLERR, arg[1], false, lmp) == 1;
    return 2;
  }
  if (strcmp(arg[0], "tmaxadapt") == 0) {
    if (narg < 2) utils::missing_cmd_args(FLERR, "min_modify tmaxadapt", error);
    adapt_cap = utils::logical(FLERR, arg[1], false, lmp) == 1;
    return 2;
  }
  return 0;
}

/* ---------------------------------------------------------------------- */

void MinFireNph::init()
{
  Min::init();
  if (tmax < tmin) error->all(FLERR, "min_modify tmax {} must be >= tmin {}", tmax, tmin);
  if (dtgrow < 1.0) error->all(FLERR, "min_modify dtgrow {} must be >= 1", dtgrow);
  if (dtshrink > 1.0) error->all(FLERR, "min_modify dtshrink {} must be <= 1", dtshrink);
  if (abcflag) error->all(FLERR, "min_style fire/nph does not support min_modify abcfire yes");
  if (integrator != EULERIMPLICIT)
    error->all(FLERR, "min_style fire/nph supports only min_modify integrator eulerimplicit");
  if (rms_tolerance && normstyle != TWO)
    error->all(FLERR,
               "min_style fire/nph: min_modify rms yes is a root mean square, which needs "
               "min_modify norm two, not norm {}",
               normstyle == MAX ? "max" : "inf");
}

// FIRE's state at the start of a minimization: at every Min::setup(), so that callers that set
// up and run several minimizations after one init() (prd, tad, hyper) start each afresh too
void MinFireNph::start_afresh()
{
  dt = update->dt;
  dtmax = tmax * dt;
  dtmin = tmin * dt;
  alpha = alpha0;
  last_drift_time = 0.0;
  last_negative = update->ntimestep;
  stall = StallRecord();
  run_record = RunRecord();
  cap_window_start = run_record;
}

/* ----------------------------------------------------------------------
   called by Min::setup() once nextra_global is known, before any force
------------------------------------------------------------------------- */

void MinFireNph::setup_style()
{
  start_afresh();
  fix_minimize->add_vector(3);

  if (nextra_atom) error->all(FLERR, "min_style fire/nph does not support per-atom extra dof");
  if (nextra_global != 0 && nextra_global != 1 && nextra_global != 3)
    error->all(FLERR,
               "min_style fire/nph needs fix box/relax iso, aniso, x, y, z or couple; "
               "{} box degrees of freedom (tilt?) are not supported",
               nextra_global);

  // fix box/relax changes box length i by q_i = ds_i * L_i, L_i the length at this setup.
  // Kinetic mass of q: that of an affine dilation of uniformly spread atoms, M L_i^2/12 per
  // dilated direction over L_i^2, i.e. M/12 each (iso dilates all directions at once).

  double mass_local = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    mass_local += atom_mass(i);
  const double mass_total = global_sum(mass_local);
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};

  delete[] box_length;
  delete[] box_mass;
  delete[] box_velocity;
  delete[] box_step;
  box_length = new double[std::max(nextra_global, 1)];
  box_mass = new double[std::max(nextra_global, 1)];
  box_velocity = new double[std::max(nextra_global, 1)];
  box_step = new double[std::max(nextra_global, 1)];

  // FIRE starts at rest, the box too (its velocity was read uninitialized before the first step)
  for (int k = 0; k < nextra_global; k++) {
    box_length[k] = prd[k];
    box_velocity[k] = box_step[k] = 0.0;
    if (nextra_global == 1) {
      double sum = 0.0;
      for (int d = 0; d < domain->dimension; d++) sum += (prd[d] / prd[0]) * (prd[d] / prd[0]);
      box_mass[k] = boxmass_scale * mass_total * sum / 12.0;
    } else {
      box_mass[k] = boxmass_scale * mass_total / 12.0;
    }
  }

  // FIRE starts at rest; atom->v stays zero so the pressure has no kinetic part
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++) v[i][0] = v[i][1] = v[i][2] = 0.0;

  if (comm->me == 0)
    utils::logmesg(lmp,
                   "  Parameters for fire/nph: dmax {} delaystep {} dtgrow {} dtshrink {} "
                   "alpha0 {} alphashrink {} tmax {} tmin {} tmaxadapt {} halfstepback {} "
                   "box dof {} boxmass {} steer {} rms {}\n",
                   dmax, delaystep, dtgrow, dtshrink, alpha0, alphashrink, tmax, tmin,
                   adapt_cap ? "yes" : "no", halfstepback_flag ? "yes" : "no", nextra_global,
                   boxmass_scale, steer_by_mass ? "mass" : "force", rms_tolerance ? "yes" : "no");
}

/* ----------------------------------------------------------------------
   set current vector lengths and pointers; called after atoms migrated
------------------------------------------------------------------------- */

void MinFireNph::reset_vectors()
{
  nvec = 3 * atom->nlocal;
  if (nvec) xvec = atom->x[0];
  if (nvec) fvec = atom->f[0];
  velocity = fix_minimize->request_vector(0);
}

/* ---------------------------------------------------------------------- */

double MinFireNph::global_sum(double local) const
{
  double all = 0.0;
  MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return all;
}

/* ----------------------------------------------------------------------
   power v.f over atoms and box; the box force on q_k is -dH/dq_k = fextra_k / L_k
------------------------------------------------------------------------- */

MinFireNph::Power MinFireNph::vdotf() const
{
  double local = 0.0;
  for (int i = 0; i < nvec; i++) local += velocity[i] * fvec[i];
  Power power = {0.0, global_sum(local), 0.0};
  power.total = power.atoms;
  for (int k = 0; k < nextra_global; k++) {
    const double box_power = box_velocity[k] * fextra[k] / box_length[k];
    power.total += box_power;
    power.box += box_power;
  }
  return power;
}

/* ----------------------------------------------------------------------
   mean square force per degree of freedom: atom coordinates (dimension per atom) and box
   lengths, the box's force being that on its length, -dH/dq_k = fextra_k / L_k. Unlike the
   2-norm it does not grow with the system: a tissue copied k x k times has the same value
------------------------------------------------------------------------- */

double MinFireNph::rms_force_sqr() const
{
  double local = 0.0;
  for (int i = 0; i < nvec; i++) local += fvec[i] * fvec[i];
  double sum = global_sum(local);
  for (int k = 0; k < nextra_global; k++) {
    const double fq = fextra[k] / box_length[k];
    sum += fq * fq;
  }
  const double dof = domain->dimension * static_cast<double>(atom->natoms) + nextra_global;
  return dof > 0.0 ? sum / dof : 0.0;
}

/* ---------------------------------------------------------------------- */

void MinFireNph::zero_velocities()
{
  for (int i = 0; i < nvec; i++) velocity[i] = 0.0;
  for (int k = 0; k < nextra_global; k++) box_velocity[k] = 0.0;
}

/* ----------------------------------------------------------------------
   FIRE's steering: v <- (1 - alpha) v + alpha |v| f/|f|, norms over atoms and box together;
   returns |f|^2, which the divergence check reuses
------------------------------------------------------------------------- */

double MinFireNph::atom_mass(int i) const
{
  return atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
}

double MinFireNph::mix_velocities()
{
  // steer mass: FIRE in the coordinates sqrt(m) x, in which every degree of freedom has unit
  // mass (velocity sqrt(m) v, force f/sqrt(m)); the published code's NPH-FIRE steers its box
  // area, of unit mass, so. steer force: v and f as they are, a heavy box steered like an atom.
  double local[2] = {0.0, 0.0};
  for (int i = 0; i < nvec; i++) {
    const double m = steer_by_mass ? atom_mass(i / 3) : 1.0;
    local[0] += m * velocity[i] * velocity[i];
    local[1] += fvec[i] * fvec[i] / m;
  }
  double all[2];
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < nextra_global; k++) {
    const double fq = fextra[k] / box_length[k];
    const double m = steer_by_mass ? box_mass[k] : 1.0;
    all[0] += m * box_velocity[k] * box_velocity[k];
    all[1] += fq * fq / m;
  }
  if (!(all[1] > 0.0)) return all[1];
  const double keep = 1.0 - alpha;
  const double steer = alpha * sqrt(all[0] / all[1]);
  for (int i = 0; i < nvec; i++) {
    const double m = steer_by_mass ? atom_mass(i / 3) : 1.0;
    velocity[i] = keep * velocity[i] + steer * fvec[i] / m;
  }
  for (int k = 0; k < nextra_global; k++) {
    const double m = steer_by_mass ? box_mass[k] : 1.0;
    box_velocity[k] = keep * box_velocity[k] + steer * fextra[k] / box_length[k] / m;
  }
  return all[1];
}

/* ----------------------------------------------------------------------
   time to move this step: dt, shortened so that no atom moves more than dmax, no box length
   by more than dmax, and no box strain beyond fix box/relax's vmax
------------------------------------------------------------------------- */

MinFireNph::Drift MinFireNph::displacement_time() const
{
  double atom_speed_local = 0.0;
  for (int i = 0; i < nvec; i++) atom_speed_local = std::max(atom_speed_local, fabs(velocity[i]));
  double atom_speed = 0.0;
  MPI_Allreduce(&atom_speed_local, &atom_speed, 1, MPI_DOUBLE, MPI_MAX, world);
  double box_speed = 0.0;
  for (int k = 0; k < nextra_global; k++) box_speed = std::max(box_speed, fabs(box_velocity[k]));

  Drift drift = {dt, atom_speed * dt > dmax, box_speed * dt > dmax};
  const double speed = std::max(atom_speed, box_speed);
  if (speed * dt > dmax) drift.time = dmax / speed;
  if (nextra_global) {
    bool moving = false;
    for (int k = 0; k < nextra_global; k++) {
      box_step[k] = box_velocity[k] / box_length[k];
      if (box_step[k] != 0.0) moving = true;
    }
    if (moving) {
      const double box_time = modify->max_alpha(box_step);
      if (box_time < dt) drift.box_limited = true;
      drift.time = std::min(drift.time, box_time);
    }
  }
  return drift;
}

/* ----------------------------------------------------------------------
   advance atoms and box by time * velocity (negative time steps back)
------------------------------------------------------------------------- */

void MinFireNph::move(double time)
{
  for (int i = 0; i < nvec; i++) xvec[i] += time * velocity[i];
  if (nextra_global) {
    check_box_move(time);
    for (int k = 0; k < nextra_global; k++) box_step[k] = box_velocity[k] / box_length[k];
    modify->min_store();
    modify->min_step(time, box_step);
  }
}

/* ---------------------------------------------------------------------- */

int MinFireNph::iterate(int maxiter)
{
  alpha_final = 0.0;
  const double ftm2v = force->ftm2v;

  for (int iter = 0; iter < maxiter; iter++) {
    if (timer->check_timeout(niter)) return TIMEOUT;
    const bigint ntimestep = ++update->ntimestep;
    niter++;

    // FIRE: keep going downhill and speed up; on an uphill step stop, step back, slow down
    const Power power = vdotf();
    if (power.total > 0.0) {
      if (ntimestep - last_negative > delaystep) {
        dt = std::min(dt * dtgrow, dtmax);
        alpha *= alphashrink;
      }
      // recovered: dt is back at the timestep (or at tmax x timestep, if that is lower)
      if (dt > dtmin && dt >= std::min(update->dt, dtmax)) stall = StallRecord();
    } else {
      run_record.uphill++;
      if (power.atoms < 0.0) run_record.atoms_uphill++;
      if (power.box < 0.0) run_record.box_uphill++;
      last_negative = ntimestep;
      if (!(delaystep_start_flag && ntimestep - update->firststep <= delaystep)) {
        dt = std::max(dt * dtshrink, dtmin);
        alpha = alpha0;
      }
      if (dt <= dtmin) record_stall_uphill(power);
      // the step back undoes at most half of the drift it corrects: a drift that dmax or vmax
      // shortened must not be reversed by the full half time step
      if (halfstepback_flag) move(-0.5 * std::min(dt, last_drift_time));
      zero_velocities();
    }

    run_record.steps++;
    run_record.dt_sum += dt;
    if (adapt_cap && run_record.steps - cap_window_start.steps == CAP_WINDOW) judge_step_cap();

    // semi-implicit Euler: kick with the current forces, steer, then drift
    for (int i = 0; i < nvec; i++) velocity[i] += dt * ftm2v * fvec[i] / atom_mass(i / 3);
    for (int k = 0; k < nextra_global; k++)
      box_velocity[k] += dt * ftm2v * fextra[k] / box_length[k] / box_mass[k];
    check_force_norm(mix_velocities());
    const Drift drift = displacement_time();
    if (dt <= dtmin) record_stall_drift(drift);
    last_drift_time = drift.time;
    move(last_drift_time);

    eprevious = ecurrent;
    ecurrent = energy_force(0);
    neval++;
    check_energy();
    alpha_final = alpha;

    if (update->etol > 0.0 && ntimestep - last_negative > delaystep &&
        fabs(ecurrent - eprevious) <
            update->etol * 0.5 * (fabs(ecurrent) + fabs(eprevious) + EPS_ENERGY))
      return ETOL;

    if (update->ftol > 0.0) {
      double fdotf;
      if (rms_tolerance)
        fdotf = rms_force_sqr();
      else if (normstyle == MAX)
        fdotf = fnorm_max();
      else if (normstyle == INF)
        fdotf = fnorm_inf();
      else
        fdotf = fnorm_sqr();
      if (fdotf < update->ftol * update->ftol) return FTOL;
    }

    if (output->next == ntimestep) {
      timer->stamp();
      output->write(ntimestep);
      timer->stamp(Timer::OUTPUT);
    }
  }
  return MAXITER;
}

// the run record goes after the thermo table, whose last line Min::run() writes after iterate()
void MinFireNph::run(int n)
{
  Min::run(n);
  log_run_record();
}

/* ----------------------------------------------------------------------
   min_modify tmaxadapt: at the end of each window, lower the step cap if FIRE kept restarting
   from rest at steps far below it (see CAP_WINDOW); the sums are the same on every rank
------------------------------------------------------------------------- */

void MinFireNph::judge_step_cap()
{
  const bigint steps = run_record.steps - cap_window_start.steps;
  const bigint uphill = run_record.uphill - cap_window_start.uphill;
  const double dt_sum = run_record.dt_sum - cap_window_start.dt_sum;
  const bool restarting = uphill * CAP_UPHILL_SPACING > steps;
  const bool far_below_cap = dt_sum < CAP_MEAN_FRACTION * dtmax * steps;
  const double lowered = std::max({CAP_LOWERING * dtmax, update->dt, dtmin});
  if (restarting && far_below_cap && lowered < dtmax) {
    dtmax = lowered;
    dt = std::min(dt, dtmax);
    run_record.caps_lowered++;
  }
  cap_window_start = run_record;
}

void MinFireNph::log_run_record() const
{
  if (comm->me != 0 || run_record.steps == 0) return;
  std::string cap = fmt::format("tmax x timestep = {:.4g}", tmax * update->dt);
  if (run_record.caps_lowered)
    cap += fmt::format(", lowered {} times to {:.4g} by tmaxadapt", run_record.caps_lowered, dtmax);
  utils::logmesg(lmp,
                 "  fire/nph: {} iterations, {} uphill (velocities zeroed; the atoms' power "
                 "negative in {}, the box's in {}), mean time step {:.4g} ({})\n",
                 run_record.steps, run_record.uphill, run_record.atoms_uphill,
                 run_record.box_uphill, run_record.dt_sum / (double) run_record.steps, cap);
}

/* ----------------------------------------------------------------------
   divergence: stop with what diverged, where, and what to change, before a NaN spreads or
   fix box/relax meets a negative box length
------------------------------------------------------------------------- */

// the settings that bound FIRE's steps, for the messages
std::string MinFireNph::what_to_change() const
{
  std::string cap = fmt::format("tmax x timestep = {}", tmax * update->dt);
  if (run_record.caps_lowered) cap = fmt::format("{}, lowered by tmaxadapt from {}", dtmax, cap);
  std::string advice = fmt::format("lower the timestep ({}; FIRE's steps grow to {}) or "
                                   "min_modify dmax ({})",
                                   update->dt, cap, dmax);
  if (nextra_global)
    advice += fmt::format("; for the box: raise min_modify boxmass ({}), lower fix box/relax's "
                          "vmax, or check its target pressure",
                          boxmass_scale);
  return advice;
}

void MinFireNph::check_energy() const
{
  if (std::isfinite(ecurrent)) return;
  error->all(FLERR,
             "min_style fire/nph: the energy{} is {} at step {} (iteration {} of this "
             "minimization): the minimization diverged; {}",
             nextra_global ? " (enthalpy U + P0 V)" : "", ecurrent, update->ntimestep, niter,
             what_to_change());
}

// force_norm_sqr: |f|^2 over atoms and box, of the forces at the previous step
void MinFireNph::check_force_norm(double force_norm_sqr) const
{
  if (std::isfinite(force_norm_sqr)) return;
  error->all(FLERR,
             "min_style fire/nph: the force norm is {} at step {} (iteration {} of this "
             "minimization); {}: the minimization diverged; {}",
             sqrt(force_norm_sqr), update->ntimestep - 1, niter - 1, largest_force(),
             what_to_change());
}

/* ----------------------------------------------------------------------
   the box lengths that moving by 'time' would give: each must stay finite and within
   BOX_CHANGE_LIMIT of its length at the start of the minimization (q is the change of length)
------------------------------------------------------------------------- */

void MinFireNph::check_box_move(double time) const
{
  const char *axis = "xyz";
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};
  for (int k = 0; k < nextra_global; k++) {
    if (box_velocity[k] == 0.0 && std::isfinite(prd[k])) continue;
    const double length = prd[k] + time * box_velocity[k];
    const double change = length / box_length[k];
    if (std::isfinite(length) && change >= 1.0 / BOX_CHANGE_LIMIT && change <= BOX_CHANGE_LIMIT)
      continue;
    if (!std::isfinite(length))
      error->all(FLERR,
                 "min_style fire/nph: step {} would make box length {} {} (it is {}, box "
                 "velocity {}): the box diverged; {}",
                 update->ntimestep, axis[k], length, prd[k], box_velocity[k], what_to_change());
    const bool shrinks = change < 1.0;
    error->all(FLERR,
               "min_style fire/nph: step {} would take box length {} to {}, {:.3g} times its "
               "length {} at the start of this minimization: the box {} (fire/nph stops a box "
               "length that shrinks below 1/{} or grows beyond {} times it). Fix box/relax's "
               "target pressure may be {} the system cannot hold, or the box dynamics diverged: "
               "{}. For a large change that is meant, minimize in stages",
               update->ntimestep, axis[k], length, change, box_length[k],
               shrinks ? "collapses" : "runs away", BOX_CHANGE_LIMIT, BOX_CHANGE_LIMIT,
               shrinks ? "a compression" : "a tension", what_to_change());
  }
}

/* ----------------------------------------------------------------------
   stall: uphill again and again at dt = dtmin. Whether the drifts ran into dmax or vmax, and
   whether the atoms or only the box turned uphill, tells which setting is too bold
------------------------------------------------------------------------- */

void MinFireNph::record_stall_drift(const Drift &drift)
{
  stall.drifts++;
  if (drift.atoms_at_dmax) stall.atoms_at_dmax++;
  if (drift.box_limited) stall.box_limited++;
}

void MinFireNph::record_stall_uphill(const Power &power)
{
  stall.uphill++;
  if (power.atoms < 0.0) stall.atoms_uphill++;
  if (power.box < 0.0) stall.box_uphill++;
  if (stall.uphill < STALL_UPHILL_STEPS) return;

  std::string cause;
  if (nextra_global && 2 * stall.box_uphill > stall.uphill)
    cause = fmt::format("The box turned uphill in {} of them, and {} of the {} drifts at that "
                        "step size were cut short for the box (by dmax or fix box/relax's "
                        "vmax): the box overshoots, its mass is too small for its force; raise "
                        "min_modify boxmass ({}), or lower fix box/relax's vmax or its target "
                        "pressure",
                        stall.box_uphill, stall.box_limited, stall.drifts, boxmass_scale);
  else if (2 * stall.atoms_at_dmax > stall.drifts)
    cause = fmt::format("The atoms turned uphill in {} of them, and {} of the {} drifts at that "
                        "step size were cut short by min_modify dmax ({}): the timestep {} is "
                        "beyond the stability limit of the stiffest mode (about 2/omega_max); "
                        "lower it",
                        stall.atoms_uphill, stall.atoms_at_dmax, stall.drifts, dmax, update->dt);
  else
    cause = fmt::format("The atoms turned uphill in {} of them, though only {} of the {} drifts "
                        "at that step size ran into min_modify dmax: a force changes faster than "
                        "even that step resolves (a very stiff or non-smooth term, as after a "
                        "change of the system too large for one minimization, e.g. a large "
                        "growth step). A collapsed ring or face or a tangled state stays so at "
                        "any timestep: run fix dpoly/check (or look at the largest force's "
                        "cell) first; then lower the timestep ({}) or make the change in "
                        "smaller steps",
                        stall.atoms_uphill, stall.atoms_at_dmax, stall.drifts, update->dt);
  error->all(FLERR,
             "min_style fire/nph: at step {} (iteration {} of this minimization) FIRE has turned "
             "uphill {} times at its smallest time step, tmin x timestep = {}, without "
             "recovering: the minimization cannot settle. {}. The largest force is {}",
             update->ntimestep, niter, stall.uphill, dtmin, cause, largest_force());
}

// "<value> on atom <id> (molecule <m>)", the largest (or a non-finite) force; collective
std::string MinFireNph::largest_force() const
{
  struct {
    double value;
    int rank;
  } mine = {-1.0, comm->me}, largest;
  int owner = -1;
  for (int i = 0; i < atom->nlocal; i++) {
    const double *f = atom->f[i];
    double value = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (!std::isfinite(value)) value = INFINITY;
    if (value > mine.value) {
      mine.value = value;
      owner = i;
    }
  }
  MPI_Allreduce(&mine, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  tagint ids[2] = {0, 0};
  if (comm->me == largest.rank && owner >= 0) {
    ids[0] = atom->tag[owner];
    ids[1] = atom->molecule ? atom->molecule[owner] : 0;
  }
  MPI_Bcast(ids, 2, MPI_LMP_TAGINT, largest.rank, world);
  if (largest.value < 0.0) return "on no atom";
  std::string where = fmt::format("{} on atom {}", largest.value, ids[0]);
  if (atom->molecule) where += fmt::format(" (molecule {})", ids[1]);
  return where;
}
