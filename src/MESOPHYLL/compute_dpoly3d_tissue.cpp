/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly3d_tissue.h"

#include "domain.h"
#include "dpoly_adhesion.h"
#include "error.h"
#include "fix_dpoly3d_cells.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace {
const char *STYLE = "Compute dpoly3d/tissue";
enum { PHI, MEAN_SHAPE, MEAN_NEIGHBOURS, BONDS, CELLS, NVALUES };
enum { ID, VOLUME, SURFACE, SHAPE, NEIGHBOURS, CELL_BONDS, NCOLUMNS };
}    // namespace

ComputeDPoly3dTissue::ComputeDPoly3dTissue(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), cells(nullptr), values(nullptr), per_cell(nullptr), rows(0)
{
  if (narg != 3) error->all(FLERR, "{} takes no arguments, got {}", STYLE, narg - 3);
  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 0;
  array_flag = 1;
  size_array_cols = NCOLUMNS;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  memory->create(values, NVALUES, "dpoly3d/tissue:values");
}

ComputeDPoly3dTissue::~ComputeDPoly3dTissue()
{
  memory->destroy(values);
  memory->destroy(per_cell);
}

void ComputeDPoly3dTissue::init()
{
  find_cells();
}

// looked up at every evaluation, not only in init(): 'run N pre no' skips init(), and a hub
// removed (or replaced) since would leave a dangling pointer
void ComputeDPoly3dTissue::find_cells()
{
  const auto hubs = modify->get_fix_by_style("^dpoly3d/cells$");
  if (hubs.empty())
    error->all(FLERR, "{} needs fix dpoly3d/cells: it measures the cells' volumes and surfaces",
               STYLE);
  cells = dynamic_cast<FixDPoly3dCells *>(hubs.front());
}

double ComputeDPoly3dTissue::shape_parameter(double surface, double volume)
{
  return surface * surface * surface / (36.0 * MathConst::MY_PI * volume * volume);
}

// the hub knows its cells from the first force evaluation of a run on
void ComputeDPoly3dTissue::require_measured_cells()
{
  find_cells();
  if (cells->ncells() == 0)
    error->all(FLERR,
               "{} {}: fix dpoly3d/cells has not measured the cells yet; evaluate it after a run "
               "(run 0 will do)",
               STYLE, id);
}

void ComputeDPoly3dTissue::compute_vector()
{
  invoked_vector = update->ntimestep;
  require_measured_cells();
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  const int n = cells->ncells();
  double volume = 0.0, shape = 0.0, neighbours = 0.0, bond_ends = 0.0;
  for (int c = 0; c < n; c++) {
    volume += cells->volume(c);
    shape += shape_parameter(cells->surface_area(c), cells->volume(c));
    neighbours += adhesion.cell_contacts(cells->cell_id(c));
    bond_ends += adhesion.cell_bonds(cells->cell_id(c));
  }
  values[PHI] = volume / (domain->xprd * domain->yprd * domain->zprd);
  values[MEAN_SHAPE] = shape / n;
  values[MEAN_NEIGHBOURS] = neighbours / n;
  values[BONDS] = 0.5 * bond_ends;    // each bond joins two cells
  values[CELLS] = n;
  vector = values;
}

void ComputeDPoly3dTissue::compute_array()
{
  invoked_array = update->ntimestep;
  require_measured_cells();
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  rows = cells->ncells();
  memory->destroy(per_cell);
  memory->create(per_cell, std::max(rows, 1), NCOLUMNS, "dpoly3d/tissue:per_cell");
  for (int c = 0; c < rows; c++) {
    const tagint cell = cells->cell_id(c);
    per_cell[c][ID] = cell;
    per_cell[c][VOLUME] = cells->volume(c);
    per_cell[c][SURFACE] = cells->surface_area(c);
    per_cell[c][SHAPE] = shape_parameter(cells->surface_area(c), cells->volume(c));
    per_cell[c][NEIGHBOURS] = adhesion.cell_contacts(cell);
    per_cell[c][CELL_BONDS] = adhesion.cell_bonds(cell);
  }
  size_array_rows = rows;
  array = per_cell;
}

int ComputeDPoly3dTissue::lock_length()
{
  const auto hubs = modify->get_fix_by_style("^dpoly3d/cells$");
  return hubs.empty() ? 0 : dynamic_cast<FixDPoly3dCells *>(hubs.front())->ncells();
}

double ComputeDPoly3dTissue::memory_usage()
{
  return sizeof(double) * (NVALUES + (double) NCOLUMNS * rows);
}
