/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_run_forces.h"

#include "atom.h"
#include "fix_store_atom.h"
#include "modify.h"

#include <algorithm>

using namespace LAMMPS_NS;
using DPoly::RunForces;

RunForces::RunForces(LAMMPS *lmp, const std::string &hub_id) :
    Pointers(lmp), store_id(hub_id + "_RUN_FORCES"), store(nullptr), last_kept_tag(0)
{
  store = dynamic_cast<FixStoreAtom *>(modify->add_fix(store_id + " all STORE/ATOM 3 0 0 0"));
  store->disable = 1;    // idle: runs migrate their atoms without it
}

// Modify deletes every fix when LAMMPS ends, the hub first: then the store may be gone already
RunForces::~RunForces() noexcept(false)
{
  if (modify && modify->nfix) {
    const int index = modify->find_fix(store_id);
    if (index >= 0) modify->delete_fix(index);
  }
}

void RunForces::keep()
{
  double **f = atom->f, **kept = store->astore;
  tagint largest = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    std::copy(f[i], f[i] + 3, kept[i]);
    largest = std::max(largest, atom->tag[i]);
  }
  MPI_Allreduce(&largest, &last_kept_tag, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  store->disable = 0;    // from now on exchange() moves them with their atoms
}

void RunForces::put_back()
{
  double **f = atom->f, **kept = store->astore;
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom->tag[i] > last_kept_tag)
      std::fill(f[i], f[i] + 3, 0.0);
    else
      std::copy(kept[i], kept[i] + 3, f[i]);
  }
  store->disable = 1;
}
