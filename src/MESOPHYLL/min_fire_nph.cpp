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

/* ---------------------------------------------------------------------- */

MinFireNph::MinFireNph(LAMMPS *lmp) :
    Min(lmp), boxmass_scale(1.0), velocity(nullptr), box_length(nullptr), box_mass(nullptr),
    box_velocity(nullptr), box_step(nullptr)
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

  dt = update->dt;
  dtmax = tmax * dt;
  dtmin = tmin * dt;
  alpha = alpha0;
  last_drift_time = 0.0;
  last_negative = update->ntimestep;
}

/* ----------------------------------------------------------------------
   called by Min::setup() once nextra_global is known, before any force
------------------------------------------------------------------------- */

void MinFireNph::setup_style()
{
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
    mass_local += atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
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
                   "alpha0 {} alphashrink {} tmax {} tmin {} halfstepback {} box dof {} "
                   "boxmass {}\n",
                   dmax, delaystep, dtgrow, dtshrink, alpha0, alphashrink, tmax, tmin,
                   halfstepback_flag ? "yes" : "no", nextra_global, boxmass_scale);
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

double MinFireNph::vdotf() const
{
  double local = 0.0;
  for (int i = 0; i < nvec; i++) local += velocity[i] * fvec[i];
  double power = global_sum(local);
  for (int k = 0; k < nextra_global; k++) power += box_velocity[k] * fextra[k] / box_length[k];
  return power;
}

/* ---------------------------------------------------------------------- */

void MinFireNph::zero_velocities()
{
  for (int i = 0; i < nvec; i++) velocity[i] = 0.0;
  for (int k = 0; k < nextra_global; k++) box_velocity[k] = 0.0;
}

/* ----------------------------------------------------------------------
   FIRE's steering: v <- (1 - alpha) v + alpha |v| f/|f|, norms over atoms and box together
------------------------------------------------------------------------- */

void MinFireNph::mix_velocities()
{
  double local[2] = {0.0, 0.0};
  for (int i = 0; i < nvec; i++) {
    local[0] += velocity[i] * velocity[i];
    local[1] += fvec[i] * fvec[i];
  }
  double all[2];
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < nextra_global; k++) {
    const double fq = fextra[k] / box_length[k];
    all[0] += box_velocity[k] * box_velocity[k];
    all[1] += fq * fq;
  }
  if (all[1] <= 0.0) return;
  const double keep = 1.0 - alpha;
  const double steer = alpha * sqrt(all[0] / all[1]);
  for (int i = 0; i < nvec; i++) velocity[i] = keep * velocity[i] + steer * fvec[i];
  for (int k = 0; k < nextra_global; k++)
    box_velocity[k] = keep * box_velocity[k] + steer * fextra[k] / box_length[k];
}

/* ----------------------------------------------------------------------
   time to move this step: dt, shortened so that no atom moves more than dmax, no box length
   by more than dmax, and no box strain beyond fix box/relax's vmax
------------------------------------------------------------------------- */

double MinFireNph::displacement_time() const
{
  double vmax_local = 0.0;
  for (int i = 0; i < nvec; i++) vmax_local = std::max(vmax_local, fabs(velocity[i]));
  double vmax_all = 0.0;
  MPI_Allreduce(&vmax_local, &vmax_all, 1, MPI_DOUBLE, MPI_MAX, world);
  for (int k = 0; k < nextra_global; k++) vmax_all = std::max(vmax_all, fabs(box_velocity[k]));

  double time = dt;
  if (vmax_all * time > dmax) time = dmax / vmax_all;
  if (nextra_global) {
    bool moving = false;
    for (int k = 0; k < nextra_global; k++) {
      box_step[k] = box_velocity[k] / box_length[k];
      if (box_step[k] != 0.0) moving = true;
    }
    if (moving) time = std::min(time, modify->max_alpha(box_step));
  }
  return time;
}

/* ----------------------------------------------------------------------
   advance atoms and box by time * velocity (negative time steps back)
------------------------------------------------------------------------- */

void MinFireNph::move(double time)
{
  for (int i = 0; i < nvec; i++) xvec[i] += time * velocity[i];
  if (nextra_global) {
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
    if (vdotf() > 0.0) {
      if (ntimestep - last_negative > delaystep) {
        dt = std::min(dt * dtgrow, dtmax);
        alpha *= alphashrink;
      }
    } else {
      last_negative = ntimestep;
      if (!(delaystep_start_flag && ntimestep - update->firststep <= delaystep)) {
        dt = std::max(dt * dtshrink, dtmin);
        alpha = alpha0;
      }
      // the step back undoes at most half of the drift it corrects: a drift that dmax or vmax
      // shortened must not be reversed by the full half time step
      if (halfstepback_flag) move(-0.5 * std::min(dt, last_drift_time));
      zero_velocities();
    }

    // semi-implicit Euler: kick with the current forces, steer, then drift
    const int *type = atom->type;
    const double *rmass = atom->rmass;
    const double *mass = atom->mass;
    for (int i = 0; i < nvec; i++) {
      const int atom_index = i / 3;
      const double m = rmass ? rmass[atom_index] : mass[type[atom_index]];
      velocity[i] += dt * ftm2v * fvec[i] / m;
    }
    for (int k = 0; k < nextra_global; k++)
      box_velocity[k] += dt * ftm2v * fextra[k] / box_length[k] / box_mass[k];
    mix_velocities();
    last_drift_time = displacement_time();
    move(last_drift_time);

    eprevious = ecurrent;
    ecurrent = energy_force(0);
    neval++;
    alpha_final = alpha;

    if (update->etol > 0.0 && ntimestep - last_negative > delaystep &&
        fabs(ecurrent - eprevious) <
            update->etol * 0.5 * (fabs(ecurrent) + fabs(eprevious) + EPS_ENERGY))
      return ETOL;

    if (update->ftol > 0.0) {
      double fdotf;
      if (normstyle == MAX)
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
