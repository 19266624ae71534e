/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "pair_dpoly3d_contact.h"

#include "atom.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

static const char *STYLE = "Pair style dpoly3d/contact";

PairDPoly3dContact::PairDPoly3dContact(LAMMPS *lmp) : PairDPolyContact(lmp)
{
  style_name = "dpoly3d/contact";
}

void PairDPoly3dContact::init_style()
{
  if (domain->dimension != 3)
    error->all(FLERR, "{} needs a 3d simulation (dimension 3); 2d cells use dpoly/contact", STYLE);
  if (!atom->molecule_flag)
    error->all(FLERR, "{} needs molecule IDs: each cell is a molecule", STYLE);
  // bonded vertices of different cells must still repel on overlap, so no special pair may be
  // dropped from the neighbor list; the edges of a surface are skipped by this style itself
  for (int k = 1; k <= 3; k++)
    if (force->special_lj[k] != 1.0)
      error->all(FLERR,
                 "{} needs special_bonds lj 1.0 1.0 1.0 (1-{} weight is {}): bonded vertices "
                 "must still repel on overlap",
                 STYLE, k + 1, force->special_lj[k]);

  vertex_state_3d.find(atom, error, STYLE);
  const DPoly3d::VertexState state = vertex_state_3d.get(atom, error, STYLE);
  // the cutoff is the largest sigma: a non-finite one, or one of half the box, is named here
  double limit = HUGE_VAL;
  const double lengths[3] = {domain->xprd, domain->yprd, domain->zprd};
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  for (int d = 0; d < 3; d++)
    if (periodic[d]) limit = std::min(limit, 0.5 * lengths[d]);
  double largest = 0.0;
  tagint bad = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double sigma = state.diameter[i];
    if (!std::isfinite(sigma) || sigma >= limit)
      bad = std::max(bad, atom->tag[i]);
    else
      largest = std::max(largest, sigma);
  }
  tagint bad_any = 0;
  MPI_Allreduce(&bad, &bad_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (bad_any)
    error->all(FLERR,
               "{}: vertex {} has a sigma that is not finite or not below half the box ({}); "
               "check its value in the Vertices section of the data file",
               STYLE, bad_any, limit);
  MPI_Allreduce(&largest, &largest_diameter, 1, MPI_DOUBLE, MPI_MAX, world);
  if (largest_diameter <= 0.0) error->all(FLERR, "{}: no vertex has a diameter sigma > 0", STYLE);
  neighbor->add_request(this);
}

// an edge joins vertices of one cell that are 1-2 special neighbours (their bond); adhesive
// bonds join different cells and do not count
bool PairDPoly3dContact::acts_between(int i, int j) const
{
  if (atom->molecule[i] != atom->molecule[j]) return true;
  if (!self_contact) return false;
  const tagint other = atom->tag[j];
  const tagint *partners = atom->special[i];
  return std::find(partners, partners + atom->nspecial[i][0], other) ==
      partners + atom->nspecial[i][0];
}

bool PairDPoly3dContact::interacts(int i, int j, double rsq, double s) const
{
  if (rsq >= s * s || rsq == 0.0) return false;
  const int owned = (i < atom->nlocal) ? i : j;
  return acts_between(owned, owned == i ? j : i);
}

void PairDPoly3dContact::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const DPoly3d::VertexState state = vertex_state_3d.get(atom, error, STYLE);
  double **x = atom->x;
  double **f = atom->f;
  int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double s = 0.5 * (state.diameter[i] + state.diameter[j]);
      if (rsq >= s * s || !acts_between(i, j)) continue;

      const double r = sqrt(rsq);
      if (r == 0.0)
        error->one(FLERR, "{}: vertices {} and {} coincide", STYLE, atom->tag[i], atom->tag[j]);
      const DPoly::DistanceLaw law = DPoly::contact_law(contact_stiffness[type[i]][type[j]], r, s);
      const double fpair = law.fpair;
      const double evdwl = eflag ? law.energy : 0.0;

      f[i][0] += delx * fpair;
      f[i][1] += dely * fpair;
      f[i][2] += delz * fpair;
      if (newton_pair || j < nlocal) {
        f[j][0] -= delx * fpair;
        f[j][1] -= dely * fpair;
        f[j][2] -= delz * fpair;
      }
      if (evflag) ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, fpair, delx, dely, delz);
    }
  }
  if (vflag_fdotr) virial_fdotr_compute();
}

double PairDPoly3dContact::contact_distance(int i, int j)
{
  const DPoly3d::VertexState state = vertex_state_3d.get(atom, error, STYLE);
  return 0.5 * (state.diameter[i] + state.diameter[j]);
}
