/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly_adhesion.h"

#include "atom.h"
#include "dpoly_adhesion.h"
#include "dpoly_cell_hub.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;

ComputeDPolyAdhesion::ComputeDPolyAdhesion(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), cells(nullptr), per_cell(nullptr), per_vertex(nullptr), nmax(0)
{
  if (narg != 3) error->all(FLERR, "Compute dpoly/adhesion takes no arguments, got {}", narg - 3);
  array_flag = 1;
  size_array_cols = 3;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputeDPolyAdhesion::~ComputeDPolyAdhesion()
{
  memory->destroy(per_cell);
  memory->destroy(per_vertex);
}

void ComputeDPolyAdhesion::init()
{
  cells = DPoly::CellHub::find(lmp, "Compute dpoly/adhesion");
}

void ComputeDPolyAdhesion::compute_array()
{
  invoked_array = update->ntimestep;
  // again, not only in init(): 'run N pre no' skips init(), and a hub removed (or replaced)
  // since would leave a dangling pointer
  cells = DPoly::CellHub::find(lmp, "Compute dpoly/adhesion");
  const int n = cells->ncells();
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  memory->destroy(per_cell);
  memory->create(per_cell, std::max(n, 1), 3, "dpoly/adhesion:per_cell");
  for (int c = 0; c < n; c++) {
    const tagint id = cells->cell_id(c);
    per_cell[c][0] = id;
    per_cell[c][1] = adhesion.cell_bonds(id);
    per_cell[c][2] = adhesion.cell_contacts(id);
  }
  size_array_rows = n;
  array = per_cell;
}

void ComputeDPolyAdhesion::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(per_vertex);
    memory->create(per_vertex, nmax, "dpoly/adhesion:per_vertex");
    vector_atom = per_vertex;
  }
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  for (int i = 0; i < atom->nlocal; i++)
    per_vertex[i] = (atom->mask[i] & groupbit) ? adhesion.vertex_bonds(atom->tag[i]) : 0.0;
}

double ComputeDPolyAdhesion::memory_usage()
{
  return sizeof(double) * (nmax + 3.0 * size_array_rows);
}
