/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_adhesion.h"

#include "bond.h"
#include "bond_hybrid.h"
#include "force.h"
#include "lammps.h"

using namespace LAMMPS_NS;
using namespace DPoly;

void AdhesionCounts::build(const std::vector<AdhesiveBond> &bonds)
{
  per_vertex.clear();
  per_cell.clear();
  between_cells.clear();
  for (const auto &b : bonds) {
    per_vertex[b.atom1]++;
    per_vertex[b.atom2]++;
    per_cell[b.cell1]++;
    per_cell[b.cell2]++;
    between_cells[b.cell1][b.cell2]++;
    between_cells[b.cell2][b.cell1]++;
  }
}

void AdhesionCounts::remove(const AdhesiveBond &b)
{
  per_vertex[b.atom1]--;
  per_vertex[b.atom2]--;
  per_cell[b.cell1]--;
  per_cell[b.cell2]--;
  if (--between_cells[b.cell1][b.cell2] == 0) between_cells[b.cell1].erase(b.cell2);
  if (--between_cells[b.cell2][b.cell1] == 0) between_cells[b.cell2].erase(b.cell1);
}

int AdhesionCounts::cell_contacts(tagint cell) const
{
  const auto found = between_cells.find(cell);
  return found == between_cells.end() ? 0 : (int) found->second.size();
}

CellAdhesion *DPoly::find_cell_adhesion(LAMMPS *lmp)
{
  Bond *bond = lmp->force->bond;
  if (auto *hybrid = dynamic_cast<BondHybrid *>(bond)) {
    for (int m = 0; m < hybrid->nstyles; m++)
      if (auto *adhesion = dynamic_cast<CellAdhesion *>(hybrid->styles[m])) return adhesion;
    return nullptr;
  }
  return dynamic_cast<CellAdhesion *>(bond);
}

const AdhesionCounts &DPoly::adhesion_counts(LAMMPS *lmp)
{
  static const AdhesionCounts none;
  const CellAdhesion *adhesion = find_cell_adhesion(lmp);
  return adhesion ? adhesion->counts() : none;
}

std::vector<AdhesiveBond> DPoly::gather_adhesive_bonds(LAMMPS *lmp)
{
  CellAdhesion *adhesion = find_cell_adhesion(lmp);
  return adhesion ? adhesion->gather_bonds() : std::vector<AdhesiveBond>();
}
