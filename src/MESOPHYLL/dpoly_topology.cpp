/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_topology.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "lammps.h"
#include "special.h"

using namespace LAMMPS_NS;

void DPoly::rebuild_special_and_ghosts(LAMMPS *lmp)
{
  Special special(lmp);
  special.build();
  Domain *domain = lmp->domain;
  Atom *atom = lmp->atom;
  if (domain->triclinic) domain->x2lamda(atom->nlocal);
  domain->pbc();
  domain->reset_box();
  lmp->comm->setup();
  lmp->comm->exchange();
  lmp->comm->borders();
  if (domain->triclinic) domain->lamda2x(atom->nlocal + atom->nghost);
}
