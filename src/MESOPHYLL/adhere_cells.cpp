/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "adhere_cells.h"

#include "atom.h"
#include "atom_vec.h"
#include "bond_mesophyll_adhesion.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_cell_hub.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "special.h"

#include <algorithm>
#include <vector>

using namespace LAMMPS_NS;

void AdhereCells::command(int narg, char **arg)
{
  if (domain->box_exist == 0)
    error->all(FLERR, "adhere_cells before the simulation box is defined");
  if (narg != 2) error->all(FLERR, "adhere_cells takes 2 arguments (group-ID btype), got {}", narg);
  if (!atom->molecule_flag || !atom->avec->bonds_allow)
    error->all(FLERR, "adhere_cells needs an atom style with molecule IDs and bonds");
  const int igroup = group->find(arg[0]);
  if (igroup < 0) error->all(FLERR, "adhere_cells: group {} does not exist", arg[0]);
  const int groupbit = group->bitmask[igroup];
  const int btype = utils::inumeric(FLERR, arg[1], false, lmp);
  if (btype < 1 || btype > atom->nbondtypes)
    error->all(FLERR, "adhere_cells: bond type {} is not between 1 and {}", btype,
               atom->nbondtypes);
  auto *adhesion = dynamic_cast<BondMesophyllAdhesion *>(force->bond_match("mesophyll/adhesion"));
  if (!adhesion || !adhesion->is_adhesive_type(btype))
    error->all(FLERR,
               "adhere_cells: bond type {} is not a bond type of bond_style "
               "mesophyll/adhesion (set its bond_coeff first)",
               btype);
  if (!force->pair_match("^dpoly/contact", 0) && !force->pair_match("^dpoly3d/contact", 0))
    error->all(FLERR,
               "adhere_cells needs pair_style dpoly/contact (polygons) or dpoly3d/contact "
               "(polyhedra), whose cutoff covers every contact distance");

  // a full neighbor list of the contact pair style's range, built once, as create_bonds does
  neighbor->add_request(this, "adhere_cells", NeighConst::REQ_FULL);
  lmp->init();
  domain->pbc();
  domain->reset_box();
  comm->setup();
  if (neighbor->style) neighbor->setup_bins();
  comm->exchange();
  comm->borders();
  neighbor->build(1);
  NeighList *list = neighbor->find_list(this);
  neighbor->build_one(list);

  const double *diameter = DPoly::CellHub::find(lmp, "adhere_cells")->vertex_diameters();
  const bool in_3d = domain->dimension == 3;    // a 2d z is 0: leave it out, as always
  double **x = atom->x;
  tagint *tag = atom->tag, *molecule = atom->molecule;
  int *mask = atom->mask;
  const int newton_bond = force->newton_bond;

  // first pass: which bonds each owned atom will store, so that overflow is a clean error
  std::vector<std::vector<tagint>> partners(atom->nlocal);
  bigint found_local = 0, cells_local = 0, already_local = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    if (molecule[i] > 0) cells_local++;
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      if (!(mask[j] & groupbit) || molecule[i] == molecule[j] || tag[i] == tag[j]) continue;
      // the same arithmetic on both owners, so that both see the same verdict
      const int lo = tag[i] < tag[j] ? i : j, hi = (lo == i) ? j : i;
      const double dx = x[lo][0] - x[hi][0], dy = x[lo][1] - x[hi][1];
      const double dz = in_3d ? x[lo][2] - x[hi][2] : 0.0;
      const double s = 0.5 * (diameter[i] + diameter[j]);
      if (dx * dx + dy * dy + dz * dz >= s * s) continue;
      bool bonded = false;
      for (int m = 0; m < atom->num_bond[i]; m++)
        if (atom->bond_atom[i][m] == tag[j] && adhesion->is_adhesive_type(atom->bond_type[i][m]))
          bonded = true;
      if (bonded) {
        if (tag[i] < tag[j]) already_local++;
        continue;
      }
      if (tag[i] < tag[j]) found_local++;
      if (!newton_bond || tag[i] < tag[j]) partners[i].push_back(tag[j]);
    }
  }

  bigint cells_total = 0, found = 0, already = 0;
  MPI_Allreduce(&cells_local, &cells_total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&found_local, &found, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&already_local, &already, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (cells_total == 0)
    error->all(FLERR, "adhere_cells: group {} holds no vertex with a molecule ID", arg[0]);
  if (found == 0 && already > 0)
    error->all(FLERR,
               "adhere_cells: all {} overlapping pairs of vertices of different cells in group {} "
               "are already bonded (adhere_cells ran before?); there is nothing to add: run it "
               "once per tissue",
               already, arg[0]);
  if (found == 0)
    error->all(FLERR, "adhere_cells: no vertices of different cells overlap in group {}", arg[0]);

  int needed_local = 0, needed = 0;
  for (int i = 0; i < atom->nlocal; i++)
    needed_local = std::max(needed_local, atom->num_bond[i] + (int) partners[i].size());
  MPI_Allreduce(&needed_local, &needed, 1, MPI_INT, MPI_MAX, world);
  if (needed > atom->bond_per_atom)
    error->all(FLERR,
               "adhere_cells needs room for {} bonds on one atom, but only {} were "
               "reserved: add 'extra/bond/per/atom {}' to read_data",
               needed, atom->bond_per_atom, needed - atom->bond_per_atom);

  for (int i = 0; i < atom->nlocal; i++)
    for (tagint partner : partners[i]) {
      atom->bond_type[i][atom->num_bond[i]] = btype;
      atom->bond_atom[i][atom->num_bond[i]] = partner;
      atom->num_bond[i]++;
    }
  atom->nbonds += found;

  Special special(lmp);
  special.build();
  if (comm->me == 0)
    utils::logmesg(lmp, "adhere_cells: created {} adhesive bonds of type {}, total bonds {}\n",
                   found, btype, atom->nbonds);
}
