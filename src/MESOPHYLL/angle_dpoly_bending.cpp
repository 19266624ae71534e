/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "angle_dpoly_bending.h"

#include "atom.h"
#include "domain.h"
#include "dpoly_ring.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "neighbor.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

AngleDPolyBending::AngleDPolyBending(LAMMPS *lmp) :
    PerTypeStiffness(lmp, "Angle style dpoly/bending", "eps_b", &Atom::nangletypes),
    mean_interior_angle(MathConst::MY_PI)
{
  born_matrix_enable = 1;
}

void AngleDPolyBending::init_style()
{
  if (domain->dimension != 2)
    error->all(FLERR, "Angle style dpoly/bending needs a 2d simulation (dimension 2)");
  vertex_state.find(atom, error, "Angle style dpoly/bending");
  const DPoly::VertexState state = vertex_state.get(atom, error, "Angle style dpoly/bending");
  DPoly::check_stiffness_factors(lmp, state, "Angle style dpoly/bending");
  double local[2] = {0.0, (double) atom->nlocal}, global[2];
  for (int i = 0; i < atom->nlocal; i++) local[0] += state.preferred_angle[i];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, world);
  if (global[1] > 0.0) mean_interior_angle = MathConst::MY_PI - global[0] / global[1];
}

/* ----------------------------------------------------------------------
   theta = atan2(d1 x d2, d1 . d2) with d1 = x2 - x1, d2 = x3 - x2, so
   dtheta/dd1 = (d1y, -d1x)/|d1|^2 and dtheta/dd2 = (-d2y, d2x)/|d2|^2
------------------------------------------------------------------------- */

void AngleDPolyBending::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const DPoly::VertexState state = vertex_state.get(atom, error, "Angle style dpoly/bending");
  double **x = atom->x;
  double **f = atom->f;
  int **anglelist = neighbor->anglelist;
  const int nanglelist = neighbor->nanglelist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  double eangle = 0.0;

  for (int n = 0; n < nanglelist; n++) {
    const int i1 = anglelist[n][0];
    const int i2 = anglelist[n][1];
    const int i3 = anglelist[n][2];
    const int type = anglelist[n][3];

    const double d1[2] = {x[i2][0] - x[i1][0], x[i2][1] - x[i1][1]};
    const double d2[2] = {x[i3][0] - x[i2][0], x[i3][1] - x[i2][1]};
    const double rsq1 = d1[0] * d1[0] + d1[1] * d1[1];
    const double rsq2 = d2[0] * d2[0] + d2[1] * d2[1];
    if (rsq1 == 0.0 || rsq2 == 0.0)
      error->one(FLERR, "Angle style dpoly/bending: vertex {} coincides with a ring neighbour",
                 atom->tag[i2]);

    const DPoly::Law law = turning_law(state, type, i2, DPoly::turning_angle(d1, d2));
    const double torque = law.first;
    if (eflag) eangle = law.energy;

    double f1[3] = {torque * d1[1] / rsq1, -torque * d1[0] / rsq1, 0.0};
    double f3[3] = {torque * d2[1] / rsq2, -torque * d2[0] / rsq2, 0.0};

    if (newton_bond || i1 < nlocal) {
      f[i1][0] += f1[0];
      f[i1][1] += f1[1];
    }
    if (newton_bond || i2 < nlocal) {
      f[i2][0] -= f1[0] + f3[0];
      f[i2][1] -= f1[1] + f3[1];
    }
    if (newton_bond || i3 < nlocal) {
      f[i3][0] += f3[0];
      f[i3][1] += f3[1];
    }
    if (evflag)
      ev_tally(i1, i2, i3, nlocal, newton_bond, eangle, f1, f3, -d1[0], -d1[1], 0.0, d2[0], d2[1],
               0.0);
  }
}

// theta0 is per vertex, not per type: report the mean interior angle pi - <theta0>
double AngleDPolyBending::equilibrium_angle(int /*type*/)
{
  return mean_interior_angle;
}

double AngleDPolyBending::single(int type, int i1, int i2, int i3)
{
  double **x = atom->x;
  i1 = domain->closest_image(i2, i1);
  i3 = domain->closest_image(i2, i3);
  const double d1[2] = {x[i2][0] - x[i1][0], x[i2][1] - x[i1][1]};
  const double d2[2] = {x[i3][0] - x[i2][0], x[i3][1] - x[i2][1]};
  return turning_law(type, i2, DPoly::turning_angle(d1, d2)).energy;
}

DPoly::Law AngleDPolyBending::turning_law(int type, int centre, double theta)
{
  return turning_law(vertex_state.get(atom, error, "Angle style dpoly/bending"), type, centre,
                     theta);
}

// without d_kb the type's eps_b alone, so that forces stay bitwise what they were
DPoly::Law AngleDPolyBending::turning_law(const DPoly::VertexState &state, int type, int centre,
                                          double theta)
{
  const double eps_b = state.bending_factor ? stiffness[type] * state.bending_factor[centre]
                                            : stiffness[type];
  return DPoly::bending_law(eps_b, theta, state.preferred_angle[centre]);
}

/* ----------------------------------------------------------------------
   LAMMPS's convention: du = dU/dc, du2 = d2U/dc^2 in c = cos of the interior angle between
   x1 - x2 and x3 - x2. Here c = -cos(theta), so dtheta/dc = 1/sin(theta) and
     du = U'/sin(theta),  du2 = (U'' sin(theta) - U' cos(theta)) / sin(theta)^3.
   U is not a function of c where sin(theta) = 0 (theta and -theta have the same c): at straight
   or folded vertices these diverge (inf or nan at exactly 0 or pi), as angle_style harmonic's
   do at its own singular angles.
------------------------------------------------------------------------- */

void AngleDPolyBending::born_matrix(int type, int i1, int i2, int i3, double &du, double &du2)
{
  double **x = atom->x;
  i1 = domain->closest_image(i2, i1);
  i3 = domain->closest_image(i2, i3);
  const double d1[2] = {x[i2][0] - x[i1][0], x[i2][1] - x[i1][1]};
  const double d2[2] = {x[i3][0] - x[i2][0], x[i3][1] - x[i2][1]};
  const double theta = DPoly::turning_angle(d1, d2);
  const DPoly::Law law = turning_law(type, i2, theta);
  const double sine = sin(theta), cosine = cos(theta);
  du = law.first / sine;
  du2 = (law.second * sine - law.first * cosine) / (sine * sine * sine);
}
