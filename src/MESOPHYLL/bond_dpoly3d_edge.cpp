/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "bond_dpoly3d_edge.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

static const char *STYLE = "Bond style dpoly3d/edge";

BondDPoly3dEdge::BondDPoly3dEdge(LAMMPS *lmp) :
    PerTypeStiffness(lmp, STYLE, "eps_l", &Atom::nbondtypes), longest_preferred(0.0)
{
  born_matrix_enable = 1;
}

void BondDPoly3dEdge::init_style()
{
  if (domain->dimension != 3)
    error->all(FLERR, "{} needs a 3d simulation (dimension 3); 2d cells use dpoly/segment", STYLE);
  edges.find(atom, error, STYLE);
  edges.fetch(atom, error, STYLE);
  double longest = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < edges.columns(); k++)
      if (edges.partner(i, k) > 0) longest = std::max(longest, edges.preferred_length(i, k));
  MPI_Allreduce(&longest, &longest_preferred, 1, MPI_DOUBLE, MPI_MAX, world);
}

DPoly::DistanceLaw BondDPoly3dEdge::edge_law(int type, int i, int j, double r)
{
  const DPoly3d::EdgeSlot slot = edges.require(atom, error, STYLE, i, j);
  return DPoly::segment_law(stiffness[type], r, edges.preferred_length(slot));
}

/* ----------------------------------------------------------------------
   U = (eps_l/2)(r/l0 - 1)^2 (DPoly::segment_law), F = -dU/dr along the edge
------------------------------------------------------------------------- */

void BondDPoly3dEdge::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  edges.fetch(atom, error, STYLE);
  double **x = atom->x;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  double ebond = 0.0;

  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1], type = bondlist[n][2];
    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double r = sqrt(delx * delx + dely * dely + delz * delz);
    if (r == 0.0)
      error->one(FLERR, "{}: vertices {} and {} coincide", STYLE, atom->tag[i1], atom->tag[i2]);
    const DPoly::DistanceLaw law = edge_law(type, i1, i2, r);
    if (eflag) ebond = law.energy;
    add_bond_force(i1, i2, ebond, law.fpair, delx, dely, delz);
  }
}

// l0 is per edge, not per type: the largest, as a bound for neighbor and comm checks
double BondDPoly3dEdge::equilibrium_distance(int /*type*/)
{
  return longest_preferred;
}

double BondDPoly3dEdge::single(int type, double rsq, int i, int j, double &fforce)
{
  edges.fetch(atom, error, STYLE);
  const double r = sqrt(rsq);
  const DPoly::DistanceLaw law = edge_law(type, i, j, r);
  fforce = (r > 0.0) ? law.fpair : 0.0;
  return law.energy;
}

void BondDPoly3dEdge::born_matrix(int type, double rsq, int i, int j, double &du, double &du2)
{
  edges.fetch(atom, error, STYLE);
  const DPoly::DistanceLaw law = edge_law(type, i, j, sqrt(rsq));
  du = law.first;
  du2 = law.second;
}
