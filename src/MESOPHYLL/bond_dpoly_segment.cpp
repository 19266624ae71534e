/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "bond_dpoly_segment.h"

#include "atom.h"
#include "atom_vec.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "error.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

BondDPolySegment::BondDPolySegment(LAMMPS *lmp) :
    PerTypeStiffness(lmp, "Bond style dpoly/segment", "eps_l", &Atom::nbondtypes),
    longest_preferred(0.0)
{
  born_matrix_enable = 1;
}

void BondDPolySegment::init_style()
{
  if (domain->dimension != 2)
    error->all(FLERR, "Bond style dpoly/segment needs a 2d simulation (dimension 2)");
  if (!atom->avec->angles_allow)
    error->all(FLERR, "Bond style dpoly/segment needs angles: they give each ring its order");
  vertex_state.find(atom, error, "Bond style dpoly/segment");
  const DPoly::VertexState state = vertex_state.get(atom, error, "Bond style dpoly/segment");
  DPoly::check_stiffness_factors(lmp, state, "Bond style dpoly/segment");
  double longest = 0.0;
  for (int i = 0; i < atom->nlocal; i++) longest = std::max(longest, state.preferred_length[i]);
  MPI_Allreduce(&longest, &longest_preferred, 1, MPI_DOUBLE, MPI_MAX, world);
}

int BondDPolySegment::segment_start(int i, int j)
{
  const int start = DPoly::segment_start(atom, i, j);
  if (start >= 0) return start;
  const int owned = (i < atom->nlocal) ? i : j;
  const int centred = DPoly::ring_links(atom, owned).count;
  if (centred != 1)
    error->one(FLERR,
               "Bond style dpoly/segment: vertex {} is the centre of {} angles; a ring "
               "vertex needs exactly one angle (prev, vertex, next)",
               atom->tag[owned], centred);
  error->one(FLERR,
             "Bond style dpoly/segment: bond {}-{} is not a segment of a ring: its atoms "
             "must be consecutive vertices (prev, vertex, next) of the angle centred on "
             "one of them",
             atom->tag[i], atom->tag[j]);
  return -1;
}

// without d_kl the type's eps_l alone, so that forces stay bitwise what they were
DPoly::DistanceLaw BondDPolySegment::segment_law(const DPoly::VertexState &state, int type, int i,
                                                 int j, double r)
{
  const int start = segment_start(i, j);
  const double eps_l = state.segment_factor ? stiffness[type] * state.segment_factor[start]
                                            : stiffness[type];
  return DPoly::segment_law(eps_l, r, state.preferred_length[start]);
}

/* ----------------------------------------------------------------------
   U = (k eps_l/2)(r/l0 - 1)^2 (DPoly::segment_law), F = -dU/dr along the bond
------------------------------------------------------------------------- */

void BondDPolySegment::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const DPoly::VertexState state = vertex_state.get(atom, error, "Bond style dpoly/segment");
  double **x = atom->x;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  double ebond = 0.0;

  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const int type = bondlist[n][2];

    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double rsq = delx * delx + dely * dely + delz * delz;
    const double r = sqrt(rsq);
    if (r == 0.0)
      error->one(FLERR, "Bond style dpoly/segment: vertices {} and {} coincide", atom->tag[i1],
                 atom->tag[i2]);

    const DPoly::DistanceLaw law = segment_law(state, type, i1, i2, r);
    const double fbond = law.fpair;
    if (eflag) ebond = law.energy;

    add_bond_force(i1, i2, ebond, fbond, delx, dely, delz);
  }
}

// l0 is per vertex, not per type: report the largest, as a bound for neighbor and comm checks
double BondDPolySegment::equilibrium_distance(int /*type*/)
{
  return longest_preferred;
}

double BondDPolySegment::single(int type, double rsq, int i, int j, double &fforce)
{
  const DPoly::VertexState state = vertex_state.get(atom, error, "Bond style dpoly/segment");
  const double r = sqrt(rsq);
  const DPoly::DistanceLaw law = segment_law(state, type, i, j, r);
  fforce = (r > 0.0) ? law.fpair : 0.0;
  return law.energy;
}

// du = dU/dr, du2 = d2U/dr2, as in LAMMPS's other bond styles
void BondDPolySegment::born_matrix(int type, double rsq, int i, int j, double &du, double &du2)
{
  const DPoly::VertexState state = vertex_state.get(atom, error, "Bond style dpoly/segment");
  const DPoly::DistanceLaw law = segment_law(state, type, i, j, sqrt(rsq));
  du = law.first;
  du2 = law.second;
}
