/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_image_check.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_adhesion.h"
#include "force.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace DPoly;

AdhesiveBondsImageCheck::AdhesiveBondsImageCheck(LAMMPS *lmp) :
    Pointers(lmp), reason_given(false), hidden(false), setup_flag_stale(false)
{
}

void AdhesiveBondsImageCheck::init()
{
  after_check();
  setup_flag_stale = update->setupflag != 0;
}

void AdhesiveBondsImageCheck::before_check()
{
  if (!reason_given || hidden || setup_flag_stale || !update->setupflag ||
      !atom->avec->bonds_allow)
    return;
  const CellAdhesion *adhesion = find_cell_adhesion(lmp);
  if (!adhesion) return;
  const int ntypes = atom->nbondtypes;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      int &type = atom->bond_type[i][m];
      if (adhesion->is_adhesive_type(type)) type = -(type + ntypes);
    }
  hidden = true;
}

void AdhesiveBondsImageCheck::after_check()
{
  if (!hidden) return;
  // atoms may have changed ranks in between: every hidden bond is recognised by its type alone
  const int ntypes = atom->nbondtypes;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      int &type = atom->bond_type[i][m];
      if (type < -ntypes) type = -type - ntypes;
    }
  hidden = false;
}

// the criterion of Domain::image_check(), on the adhesive bonds alone
void AdhesiveBondsImageCheck::count_inconsistent(const std::vector<double> &unwrapped,
                                                 bigint counts[2])
{
  bigint mine[2] = {0, 0};    // inconsistent, all
  const CellAdhesion *adhesion = find_cell_adhesion(lmp);
  if (adhesion && atom->avec->bonds_allow) {
    const double half[3] = {0.5 * domain->xprd, 0.5 * domain->yprd, 0.5 * domain->zprd};
    const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
    for (int i = 0; i < atom->nlocal; i++)
      for (int m = 0; m < atom->num_bond[i]; m++) {
        if (!adhesion->is_adhesive_type(atom->bond_type[i][m])) continue;
        const tagint partner = atom->bond_atom[i][m];
        if (!force->newton_bond && partner < atom->tag[i]) continue;    // stored twice
        mine[1]++;
        const int k = atom->map(partner);
        if (k < 0) continue;    // LAMMPS's own check reports a missing bond atom
        bool inconsistent = false;
        for (int d = 0; d < domain->dimension; d++)
          if (periodic[d] && std::fabs(unwrapped[3 * i + d] - unwrapped[3 * k + d]) > half[d])
            inconsistent = true;
        if (inconsistent) mine[0]++;
      }
  }
  MPI_Allreduce(mine, counts, 2, MPI_LMP_BIGINT, MPI_SUM, world);
}

void AdhesiveBondsImageCheck::explain_once(const std::vector<double> &unwrapped)
{
  if (reason_given) return;
  bigint counts[2];
  count_inconsistent(unwrapped, counts);
  if (counts[0] == 0) return;
  reason_given = true;
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "MESOPHYLL: LAMMPS's image-flag check warns 'Inconsistent image flags' for "
                   "{} of the {} adhesive bonds:\n"
                   "  their atoms, unwrapped by their image flags, lie more than half a box "
                   "apart. In a tissue the bonded\n"
                   "  cells form a network that closes around the periodic box, and no image "
                   "flags make every bond of a\n"
                   "  loop around the box short. Harmless: every style uses the nearest image, "
                   "and {} stops\n"
                   "  the run if a {} is not whole. From now on adhesive bonds are left out of "
                   "that check; every other\n"
                   "  bond is still checked.\n",
                   counts[0], counts[1],
                   domain->dimension == 3 ? "fix dpoly3d/cells" : "fix dpoly/cells",
                   domain->dimension == 3 ? "face" : "ring");
}
