/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_cell_hub.h"

#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

using namespace LAMMPS_NS;
using DPoly::CellHub;

CellHub *CellHub::find_any(LAMMPS *lmp)
{
  for (Fix *fix : lmp->modify->get_fix_list())
    if (auto *hub = dynamic_cast<CellHub *>(fix)) return hub;
  return nullptr;
}

CellHub *CellHub::find(LAMMPS *lmp, const std::string &who)
{
  CellHub *hub = find_any(lmp);
  if (!hub)
    lmp->error->all(FLERR,
                    "{} needs fix dpoly/cells (polygons) or fix dpoly3d/cells (polyhedra), which "
                    "keeps the cells",
                    who);
  return hub;
}
