/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "pair_dpoly_contact.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

PairDPolyContact::PairDPolyContact(LAMMPS *lmp) :
    Pair(lmp), contact_stiffness(nullptr), self_contact(1), largest_diameter(0.0)
{
  writedata = 1;
  born_matrix_enable = 1;
}

PairDPolyContact::~PairDPolyContact()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(contact_stiffness);
  }
}

void PairDPolyContact::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  memory->create(cutsq, np1, np1, "pair:cutsq");
  memory->create(contact_stiffness, np1, np1, "pair:contact_stiffness");
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) setflag[i][j] = 0;
}

void PairDPolyContact::settings(int narg, char **arg)
{
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "self") == 0) {
      if (iarg + 2 > narg)
        utils::missing_cmd_args(FLERR, "pair_style " + style_name + " self", error);
      self_contact = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else
      error->all(FLERR, "Unknown pair_style {} keyword: {}", style_name, arg[iarg]);
  }
}

void PairDPolyContact::coeff(int narg, char **arg)
{
  if (narg != 3)
    error->all(FLERR, "Pair style {} takes one coefficient (eps_c), got {}", style_name, narg - 2);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double eps_c = utils::numeric(FLERR, arg[2], false, lmp);
  if (eps_c < 0.0)
    error->all(FLERR, "Pair style {} eps_c must be >= 0, got {}", style_name, arg[2]);

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      contact_stiffness[i][j] = eps_c;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0)
    error->all(FLERR, "Pair style {}: no type pair in {} {}", style_name, arg[0], arg[1]);
}

void PairDPolyContact::init_style()
{
  if (domain->dimension != 2)
    error->all(FLERR, "Pair style dpoly/contact needs a 2d simulation (dimension 2)");
  if (!atom->molecule_flag)
    error->all(FLERR, "Pair style dpoly/contact needs molecule IDs: each cell is a molecule");
  // Bonded vertices of different cells must still repel on overlap, so no special pair may be
  // dropped from the neighbor list; ring neighbours are skipped by this style itself.
  for (int k = 1; k <= 3; k++)
    if (force->special_lj[k] != 1.0)
      error->all(FLERR,
                 "Pair style dpoly/contact needs special_bonds lj 1.0 1.0 1.0 (1-{} weight "
                 "is {}): bonded vertices must still repel on overlap",
                 k + 1, force->special_lj[k]);

  vertex_state.find(atom, error, "Pair style dpoly/contact");
  const DPoly::VertexState state = vertex_state.get(atom, error, "Pair style dpoly/contact");
  // the cutoff is the largest sigma: a non-finite one, or one near the box size, would only
  // show up as LAMMPS's neighbor-bin error, so name the vertex first
  double limit = -1.0;    // half the shortest periodic box length; none if nothing is periodic
  if (domain->xperiodic) limit = 0.5 * domain->xprd;
  if (domain->yperiodic)
    limit = (limit < 0.0) ? 0.5 * domain->yprd : std::min(limit, 0.5 * domain->yprd);
  double largest = 0.0;
  tagint bad = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double sigma = state.diameter[i];
    if (!std::isfinite(sigma) || (limit > 0.0 && sigma >= limit))
      bad = std::max(bad, atom->tag[i]);
    else
      largest = std::max(largest, sigma);
  }
  tagint bad_any = 0;
  MPI_Allreduce(&bad, &bad_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (bad_any) {
    double value = 0.0, value_any = 0.0;
    const int i = atom->map(bad_any);
    if (bad == bad_any && i >= 0 && i < atom->nlocal) value = state.diameter[i];
    MPI_Allreduce(&value, &value_any, 1, MPI_DOUBLE, MPI_SUM, world);
    error->all(FLERR,
               "Pair style dpoly/contact: vertex {} has sigma = {}; its contact diameter (the "
               "pair cutoff) must be finite and below half the box ({}): check its value in the "
               "Vertices section of the data file",
               bad_any, value_any, limit);
  }
  MPI_Allreduce(&largest, &largest_diameter, 1, MPI_DOUBLE, MPI_MAX, world);
  if (largest_diameter <= 0.0)
    error->all(FLERR, "Pair style dpoly/contact: no vertex has a diameter sigma > 0");
  neighbor->add_request(this);
}

// the contact distance s never exceeds the largest vertex diameter
double PairDPolyContact::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair style {}: coefficient for types {} {} is not set", style_name, i, j);
  contact_stiffness[j][i] = contact_stiffness[i][j];
  return largest_diameter;
}

bool PairDPolyContact::skip(int i, int j, tagint prev, tagint next) const
{
  if (atom->molecule[i] != atom->molecule[j]) return false;
  if (!self_contact) return true;
  return atom->tag[j] == prev || atom->tag[j] == next;
}

void PairDPolyContact::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const DPoly::VertexState state = vertex_state.get(atom, error, "Pair style dpoly/contact");
  double **x = atom->x;
  double **f = atom->f;
  int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const DPoly::RingLinks links = DPoly::ring_links(atom, i);
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double rsq = delx * delx + dely * dely;
      const double s = 0.5 * (state.diameter[i] + state.diameter[j]);
      if (rsq >= s * s || skip(i, j, links.prev, links.next)) continue;

      const double r = sqrt(rsq);
      if (r == 0.0)
        error->one(FLERR, "Pair style dpoly/contact: vertices {} and {} coincide", atom->tag[i],
                   atom->tag[j]);
      const DPoly::DistanceLaw law = DPoly::contact_law(contact_stiffness[type[i]][type[j]], r, s);
      const double fpair = law.fpair;
      const double evdwl = eflag ? law.energy : 0.0;

      f[i][0] += delx * fpair;
      f[i][1] += dely * fpair;
      if (newton_pair || j < nlocal) {
        f[j][0] -= delx * fpair;
        f[j][1] -= dely * fpair;
      }
      if (evflag) ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, fpair, delx, dely, 0.0);
    }
  }
  if (vflag_fdotr) virial_fdotr_compute();
}

// whether local atoms i and j (one of them owned) at distance^2 rsq overlap and are not skipped
bool PairDPolyContact::interacts(int i, int j, double rsq, double s) const
{
  if (rsq >= s * s || rsq == 0.0) return false;
  const int owned = (i < atom->nlocal) ? i : j, other = (owned == i) ? j : i;
  const DPoly::RingLinks links = DPoly::ring_links(atom, owned);
  return !skip(owned, other, links.prev, links.next);
}

double PairDPolyContact::contact_distance(int i, int j)
{
  const DPoly::VertexState state = vertex_state.get(atom, error, "Pair style dpoly/contact");
  return 0.5 * (state.diameter[i] + state.diameter[j]);
}

double PairDPolyContact::single(int i, int j, int itype, int jtype, double rsq,
                                double /*factor_coul*/, double /*factor_lj*/, double &fforce)
{
  const double s = contact_distance(i, j);
  fforce = 0.0;
  if (!interacts(i, j, rsq, s)) return 0.0;
  const DPoly::DistanceLaw law = DPoly::contact_law(contact_stiffness[itype][jtype], sqrt(rsq), s);
  fforce = law.fpair;
  return law.energy;
}

// du = dU/dr, du2 = d2U/dr2 (0 for ring neighbours and beyond contact; the special weights are
// 1, see init_style()); du2 jumps from eps_c/s^2 to 0 at contact
void PairDPolyContact::born_matrix(int i, int j, int itype, int jtype, double rsq,
                                   double /*factor_coul*/, double /*factor_lj*/, double &du,
                                   double &du2)
{
  const double s = contact_distance(i, j);
  du = du2 = 0.0;
  if (!interacts(i, j, rsq, s)) return;
  const DPoly::DistanceLaw law = DPoly::contact_law(contact_stiffness[itype][jtype], sqrt(rsq), s);
  du = law.first;
  du2 = law.second;
}

void PairDPolyContact::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) fwrite(&contact_stiffness[i][j], sizeof(double), 1, fp);
    }
}

void PairDPolyContact::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        if (comm->me == 0)
          utils::sfread(FLERR, &contact_stiffness[i][j], sizeof(double), 1, fp, nullptr, error);
        MPI_Bcast(&contact_stiffness[i][j], 1, MPI_DOUBLE, 0, world);
      }
    }
}

void PairDPolyContact::write_restart_settings(FILE *fp)
{
  fwrite(&self_contact, sizeof(int), 1, fp);
}

void PairDPolyContact::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) utils::sfread(FLERR, &self_contact, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&self_contact, 1, MPI_INT, 0, world);
}

void PairDPolyContact::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) fprintf(fp, "%d %.15g\n", i, contact_stiffness[i][i]);
}

void PairDPolyContact::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fprintf(fp, "%d %d %.15g\n", i, j, contact_stiffness[i][j]);
}

void *PairDPolyContact::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "eps_c") == 0) return (void *) contact_stiffness;
  dim = 0;
  if (strcmp(str, "self") == 0) return (void *) &self_contact;
  return nullptr;
}
