/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_run_forces.h"

#include "atom.h"
#include "error.h"
#include "fix_store_atom.h"
#include "modify.h"

#include <algorithm>

using namespace LAMMPS_NS;
using DPoly::RunForces;

RunForces::RunForces(LAMMPS *lmp, const std::string &hub_id) :
    Pointers(lmp), store_id(hub_id + "_RUN_FORCES"), last_kept_tag(0)
{
  modify->add_fix(store_id + " all STORE/ATOM 3 0 0 0");
  find_store()->disable = 1;    // idle: runs migrate their atoms without it
}

// Modify deletes the fixes in order when LAMMPS ends, so the store (added after the hub) is
// normally still there; it is not if the user unfixed it
RunForces::~RunForces() noexcept(false)
{
  if (modify && modify->nfix) {
    const int index = modify->find_fix(store_id);
    if (index >= 0) modify->delete_fix(index);
  }
}

// looked up each time, not kept: a user can unfix the store, and a kept pointer would dangle
FixStoreAtom *RunForces::find_store()
{
  auto *store = dynamic_cast<FixStoreAtom *>(modify->get_fix_by_id(store_id));
  if (!store)
    error->all(FLERR,
               "Internal fix {} (the forces stages keep with their atoms) is gone: it must not be "
               "unfixed",
               store_id);
  return store;
}

void RunForces::keep()
{
  FixStoreAtom *store = find_store();
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
  FixStoreAtom *store = find_store();
  double **f = atom->f, **kept = store->astore;
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom->tag[i] > last_kept_tag)
      std::fill(f[i], f[i] + 3, 0.0);
    else
      std::copy(kept[i], kept[i] + 3, f[i]);
  }
  store->disable = 1;
}
