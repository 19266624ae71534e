/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "bond_mesophyll_adhesion.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <utility>

using namespace LAMMPS_NS;
using DPoly::AdhesiveBond;

BondMesophyllAdhesion::BondMesophyllAdhesion(LAMMPS *lmp) :
    PerTypeStiffness(lmp, "Bond style mesophyll/adhesion", "eps_c", &Atom::nbondtypes),
    rule(ContactRule::BONDS)
{
  born_matrix_enable = 1;
}

void BondMesophyllAdhesion::settings(int narg, char **arg)
{
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "z") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "bond_style mesophyll/adhesion z", error);
      if (strcmp(arg[iarg + 1], "bonds") == 0)
        rule = ContactRule::BONDS;
      else if (strcmp(arg[iarg + 1], "cells") == 0)
        rule = ContactRule::CELLS;
      else
        error->all(FLERR, "Bond style mesophyll/adhesion z must be 'bonds' or 'cells', got '{}'",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Unknown bond_style mesophyll/adhesion keyword: {}", arg[iarg]);
  }
}

BondMesophyllAdhesion *BondMesophyllAdhesion::find(LAMMPS *lmp, const std::string &who)
{
  auto *adhesion =
      dynamic_cast<BondMesophyllAdhesion *>(lmp->force->bond_match("mesophyll/adhesion"));
  if (!adhesion)
    lmp->error->all(FLERR, "{} needs bond_style mesophyll/adhesion (alone or in hybrid)", who);
  return adhesion;
}

// the hub recounts the contacts at every run start: without it they would never be counted
void BondMesophyllAdhesion::init_style()
{
  DPoly::CellHub::find(lmp, "Bond style mesophyll/adhesion");
}

// looked up at every call, not kept: single() and born_matrix() may come before any run, or
// after 'unfix' of the hub without a new init
double *BondMesophyllAdhesion::vertex_diameters()
{
  return DPoly::CellHub::find(lmp, "Bond style mesophyll/adhesion")->vertex_diameters();
}

double BondMesophyllAdhesion::contact_number(const DPoly::AdhesionCounts &from, tagint cell1,
                                             tagint cell2) const
{
  auto z = [&](tagint cell) -> double {
    return rule == ContactRule::BONDS ? from.cell_bonds(cell) : from.cell_contacts(cell);
  };
  return 0.5 * (z(cell1) + z(cell2)) + 1.0;
}

double BondMesophyllAdhesion::contact_number(int i, int j)
{
  return contact_number(contacts, atom->molecule[i], atom->molecule[j]);
}

void BondMesophyllAdhesion::recount()
{
  contacts.build(gather_bonds());
}

/* ----------------------------------------------------------------------
   U = eps_c/(2 z) (1 - r/s)^2 for r > s (DPoly::adhesion_law): F = -dU/dr, attractive
------------------------------------------------------------------------- */

void BondMesophyllAdhesion::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const double *diameter = vertex_diameters();
  double **x = atom->x;
  tagint *molecule = atom->molecule;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;

  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const int type = bondlist[n][2];
    if (molecule[i1] == molecule[i2])
      error->one(FLERR,
                 "Bond style mesophyll/adhesion: bond {}-{} joins two vertices of cell {}; "
                 "adhesive bonds join different cells",
                 atom->tag[i1], atom->tag[i2], molecule[i1]);

    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double r = sqrt(delx * delx + dely * dely + delz * delz);
    const double s = 0.5 * (diameter[i1] + diameter[i2]);
    if (r <= s) continue;    // overlap belongs to the pair style

    const DPoly::DistanceLaw law =
        DPoly::adhesion_law(stiffness[type], contact_number(i1, i2), r, s);
    const double fbond = law.fpair;
    const double ebond = eflag ? law.energy : 0.0;

    add_bond_force(i1, i2, ebond, fbond, delx, dely, delz);
  }
}

std::vector<AdhesiveBond> BondMesophyllAdhesion::gather_bonds()
{
  const double *diameter = vertex_diameters();
  const bool in_3d = domain->dimension == 3;    // a 2d z is 0: leave it out, as always
  double **x = atom->x;
  tagint *tag = atom->tag;
  std::vector<AdhesiveBond> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      const tagint partner = atom->bond_atom[i][m];
      if (!is_adhesive_type(type)) continue;
      if (!force->newton_bond && partner < tag[i]) continue;    // stored twice: count once
      const int j = domain->closest_image(i, atom->map(partner));
      if (j < 0)
        error->one(FLERR,
                   "Bond style mesophyll/adhesion: atom {} of bond {}-{} is missing on "
                   "this rank; increase the communication cutoff",
                   partner, tag[i], partner);
      const double dz = in_3d ? x[i][2] - x[j][2] : 0.0;
      const double r = sqrt((x[i][0] - x[j][0]) * (x[i][0] - x[j][0]) +
                            (x[i][1] - x[j][1]) * (x[i][1] - x[j][1]) + dz * dz);
      AdhesiveBond b{std::min(tag[i], partner),
                     std::max(tag[i], partner),
                     0,
                     0,
                     type,
                     r,
                     0.5 * (diameter[i] + diameter[j])};
      b.cell1 = (tag[i] < partner) ? atom->molecule[i] : atom->molecule[j];
      b.cell2 = (tag[i] < partner) ? atom->molecule[j] : atom->molecule[i];
      mine.push_back(b);
    }
  }

  std::vector<AdhesiveBond> all = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::sort(all.begin(), all.end());
  for (const auto &b : all)
    if (b.cell1 == b.cell2)
      error->all(FLERR,
                 "Bond style mesophyll/adhesion: bond {}-{} joins two vertices of cell {}; "
                 "adhesive bonds join different cells",
                 b.atom1, b.atom2, b.cell1);
  return all;
}

void BondMesophyllAdhesion::remove_bonds(const std::vector<AdhesiveBond> &gone)
{
  auto key = [](tagint a, tagint b) {
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  std::set<std::pair<tagint, tagint>> removed;
  for (const auto &b : gone) {
    removed.insert(key(b.atom1, b.atom2));
    contacts.remove(b);
  }
  for (int i = 0; i < atom->nlocal; i++) {
    int m = 0;
    while (m < atom->num_bond[i]) {
      if (is_adhesive_type(atom->bond_type[i][m]) &&
          removed.count(key(atom->tag[i], atom->bond_atom[i][m]))) {
        const int last = --atom->num_bond[i];
        atom->bond_type[i][m] = atom->bond_type[i][last];
        atom->bond_atom[i][m] = atom->bond_atom[i][last];
      } else
        m++;
    }
  }
  atom->nbonds -= (bigint) gone.size();
}

// the bond pulls only beyond contact, and the contact distance is per vertex pair
double BondMesophyllAdhesion::equilibrium_distance(int /*type*/)
{
  return 0.0;
}

void BondMesophyllAdhesion::write_restart_settings(FILE *fp)
{
  const int rule_id = (rule == ContactRule::BONDS) ? 0 : 1;
  fwrite(&rule_id, sizeof(int), 1, fp);
}

void BondMesophyllAdhesion::read_restart_settings(FILE *fp)
{
  int rule_id = 0;
  if (comm->me == 0) utils::sfread(FLERR, &rule_id, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&rule_id, 1, MPI_INT, 0, world);
  rule = rule_id ? ContactRule::CELLS : ContactRule::BONDS;
}

double BondMesophyllAdhesion::single(int type, double rsq, int i, int j, double &fforce)
{
  const double *diameter = vertex_diameters();
  const double r = sqrt(rsq);
  const double s = 0.5 * (diameter[i] + diameter[j]);
  fforce = 0.0;
  if (r <= s) return 0.0;
  const DPoly::DistanceLaw law = DPoly::adhesion_law(stiffness[type], contact_number(i, j), r, s);
  fforce = law.fpair;
  return law.energy;
}

// du = dU/dr, du2 = d2U/dr2 with this bond's contact number; both 0 up to contact, where the
// second derivative jumps from 0 to eps_c/(z s^2)
void BondMesophyllAdhesion::born_matrix(int type, double rsq, int i, int j, double &du, double &du2)
{
  const double *diameter = vertex_diameters();
  const double r = sqrt(rsq);
  const double s = 0.5 * (diameter[i] + diameter[j]);
  du = du2 = 0.0;
  if (r <= s) return;
  const DPoly::DistanceLaw law = DPoly::adhesion_law(stiffness[type], contact_number(i, j), r, s);
  du = law.first;
  du2 = law.second;
}
