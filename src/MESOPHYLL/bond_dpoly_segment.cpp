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
  double longest = 0.0;
  for (int i = 0; i < atom->nlocal; i++) longest = std::max(longest, state.preferred_length[i]);
  MPI_Allreduce(&longest, &longest_preferred, 1, MPI_DOUBLE, MPI_MAX, world);
}

double BondDPolySegment::preferred_length(const DPoly::VertexState &state, int i, int j)
{
  const double l0 = DPoly::segment_preferred_length(atom, state, i, j);
  if (l0 >= 0.0) return l0;
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
  return -1.0;
}

/* ----------------------------------------------------------------------
   U = (eps_l/2)(r/l0 - 1)^2 (DPoly::segment_law), F = -dU/dr along the bond
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

    const double l0 = preferred_length(state, i1, i2);
    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double rsq = delx * delx + dely * dely + delz * delz;
    const double r = sqrt(rsq);
    if (r == 0.0)
      error->one(FLERR, "Bond style dpoly/segment: vertices {} and {} coincide", atom->tag[i1],
                 atom->tag[i2]);

    const DPoly::DistanceLaw law = DPoly::segment_law(stiffness[type], r, l0);
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
  const DPoly::DistanceLaw law =
      DPoly::segment_law(stiffness[type], r, preferred_length(state, i, j));
  fforce = (r > 0.0) ? law.fpair : 0.0;
  return law.energy;
}

// du = dU/dr, du2 = d2U/dr2, as in LAMMPS's other bond styles
void BondDPolySegment::born_matrix(int type, double rsq, int i, int j, double &du, double &du2)
{
  const DPoly::VertexState state = vertex_state.get(atom, error, "Bond style dpoly/segment");
  const DPoly::DistanceLaw law =
      DPoly::segment_law(stiffness[type], sqrt(rsq), preferred_length(state, i, j));
  du = law.first;
  du2 = law.second;
}
