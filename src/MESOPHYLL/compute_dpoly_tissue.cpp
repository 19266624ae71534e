/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly_tissue.h"

#include "atom.h"
#include "domain.h"
#include "dpoly_adhesion.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly_cells.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

using namespace LAMMPS_NS;

namespace {
enum { PHI, PHI_PATCH, MEAN_SHAPE, MEAN_NEIGHBOURS, BONDS, CELLS, NVALUES };
enum { ID, AREA, PERIMETER, SHAPE, NEIGHBOURS, VOID_FRACTION, NCOLUMNS };
}    // namespace

ComputeDPolyTissue::ComputeDPolyTissue(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), cells(nullptr), list(nullptr), values(nullptr), per_cell(nullptr),
    rows(0)
{
  if (narg != 3) error->all(FLERR, "Compute dpoly/tissue takes no arguments, got {}", narg - 3);
  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 0;
  array_flag = 1;
  size_array_cols = NCOLUMNS;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  memory->create(values, NVALUES, "dpoly/tissue:values");
}

ComputeDPolyTissue::~ComputeDPolyTissue()
{
  memory->destroy(values);
  memory->destroy(per_cell);
}

void ComputeDPolyTissue::init()
{
  cells = FixDPolyCells::find(lmp, "Compute dpoly/tissue");
  if (!force->pair_match("^dpoly/contact", 0))
    error->all(FLERR, "Compute dpoly/tissue needs pair_style dpoly/contact to find contacts");
  neighbor->add_request(this, NeighConst::REQ_OCCASIONAL);
}

void ComputeDPolyTissue::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ----------------------------------------------------------------------
   patch area: each vertex pushed out from its cell's mean vertex position by sin(pi/3) times
   its radius, as in the published analysis; shoelace on unwrapped positions
------------------------------------------------------------------------- */

std::vector<double> ComputeDPolyTissue::patch_areas()
{
  const int n = cells->ncells(), nlocal = atom->nlocal;
  double **x = atom->x;
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Compute dpoly/tissue");
  std::vector<double> local(3 * n, 0.0), centre(3 * n, 0.0);
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = cells->cell_index(atom->molecule[i]);
    if (c < 0) continue;
    double xu[3];
    domain->unmap(x[i], atom->image[i], xu);
    local[3 * c] += xu[0];
    local[3 * c + 1] += xu[1];
    local[3 * c + 2] += 1.0;
  }
  MPI_Allreduce(local.data(), centre.data(), 3 * n, MPI_DOUBLE, MPI_SUM, world);

  const double push = 0.5 * sin(MathConst::MY_PI / 3.0);
  auto pushed = [&](const double *xu, int c, double diameter, double *out) {
    const double mx = centre[3 * c] / centre[3 * c + 2], my = centre[3 * c + 1] / centre[3 * c + 2];
    const double dx = xu[0] - mx, dy = xu[1] - my, r = sqrt(dx * dx + dy * dy);
    out[0] = xu[0] + (r > 0.0 ? push * diameter * dx / r : 0.0);
    out[1] = xu[1] + (r > 0.0 ? push * diameter * dy / r : 0.0);
  };
  std::vector<double> mine(n, 0.0), total(n, 0.0);
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = cells->cell_index(atom->molecule[i]);
    if (c < 0) continue;
    const int j =
        DPoly::closest_neighbour(lmp, i, DPoly::ring_links(atom, i).next, "Compute dpoly/tissue");
    double xi[3], xj[3], pi[2], pj[2];
    domain->unmap(x[i], atom->image[i], xi);
    xj[0] = xi[0] + x[j][0] - x[i][0];
    xj[1] = xi[1] + x[j][1] - x[i][1];
    pushed(xi, c, state.diameter[i], pi);
    pushed(xj, c, state.diameter[j], pj);
    mine[c] += 0.5 * (pi[0] * pj[1] - pi[1] * pj[0]);
  }
  MPI_Allreduce(mine.data(), total.data(), n, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

std::vector<double> ComputeDPolyTissue::void_fractions()
{
  const int n = cells->ncells();
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  std::vector<double> local(n, 0.0), total(n, 0.0);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = cells->cell_index(atom->molecule[i]);
    if (c >= 0 && adhesion.void_facing(atom->tag[i])) local[c] += 1.0;
  }
  MPI_Allreduce(local.data(), total.data(), n, MPI_DOUBLE, MPI_SUM, world);
  for (int c = 0; c < n; c++) total[c] /= cells->vertex_count(c);
  return total;
}

// distinct neighbour cells: overlapping vertices (r < s) or at least one adhesive bond
std::vector<int> ComputeDPolyTissue::neighbour_counts()
{
  neighbor->build_one(list);
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Compute dpoly/tissue");
  double **x = atom->x;
  tagint *molecule = atom->molecule;
  std::set<std::pair<tagint, tagint>> touching;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      if (molecule[i] == molecule[j] || molecule[i] <= 0 || molecule[j] <= 0) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1];
      const double s = 0.5 * (state.diameter[i] + state.diameter[j]);
      if (dx * dx + dy * dy < s * s)
        touching.insert({std::min(molecule[i], molecule[j]), std::max(molecule[i], molecule[j])});
    }
  }
  struct CellPair {
    tagint first, second;
  };
  std::vector<CellPair> mine;
  for (const auto &p : touching) mine.push_back({p.first, p.second});
  const std::vector<CellPair> all = DPoly::gather_on_all_ranks(std::move(mine), world);

  const int n = cells->ncells();
  std::vector<std::set<tagint>> partners(n);
  for (const auto &p : all) {
    const int a = cells->cell_index(p.first), b = cells->cell_index(p.second);
    if (a >= 0 && b >= 0) {
      partners[a].insert(p.second);
      partners[b].insert(p.first);
    }
  }
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  std::vector<int> counts(n);
  for (int c = 0; c < n; c++) {
    if (const auto *bonded = adhesion.bonded_cells(cells->cell_id(c)))
      for (const auto &other : *bonded) partners[c].insert(other.first);
    counts[c] = (int) partners[c].size();
  }
  return counts;
}

ComputeDPolyTissue::Measures ComputeDPolyTissue::measure()
{
  // the hub again, not only in init(): 'run N pre no' skips init(), and a hub removed (or
  // replaced) since would leave a dangling pointer
  cells = FixDPolyCells::find(lmp, "Compute dpoly/tissue");
  return {patch_areas(), void_fractions(), neighbour_counts()};
}

void ComputeDPolyTissue::compute_vector()
{
  invoked_vector = update->ntimestep;
  const Measures m = measure();
  const int n = cells->ncells();
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  double area = 0.0, patch = 0.0, shape = 0.0, neighbours = 0.0, bonds = 0.0;
  for (int c = 0; c < n; c++) {
    area += cells->area(c);
    patch += m.patch_area[c];
    shape += DPoly::shape_index(cells->perimeter(c), cells->area(c));
    neighbours += m.neighbours[c];
    bonds += adhesion.cell_bonds(cells->cell_id(c));
  }
  const double box = domain->xprd * domain->yprd;
  values[PHI] = area / box;
  values[PHI_PATCH] = patch / box;
  values[MEAN_SHAPE] = n ? shape / n : 0.0;
  values[MEAN_NEIGHBOURS] = n ? neighbours / n : 0.0;
  values[BONDS] = 0.5 * bonds;    // each bond joins two cells
  values[CELLS] = n;
  vector = values;
}

void ComputeDPolyTissue::compute_array()
{
  invoked_array = update->ntimestep;
  const Measures m = measure();
  rows = cells->ncells();
  memory->destroy(per_cell);
  memory->create(per_cell, std::max(rows, 1), NCOLUMNS, "dpoly/tissue:per_cell");
  for (int c = 0; c < rows; c++) {
    const double a = cells->area(c), p = cells->perimeter(c);
    per_cell[c][ID] = cells->cell_id(c);
    per_cell[c][AREA] = a;
    per_cell[c][PERIMETER] = p;
    per_cell[c][SHAPE] = DPoly::shape_index(p, a);
    per_cell[c][NEIGHBOURS] = m.neighbours[c];
    per_cell[c][VOID_FRACTION] = m.void_fraction[c];
  }
  size_array_rows = rows;
  array = per_cell;
}

double ComputeDPolyTissue::memory_usage()
{
  return sizeof(double) * (NVALUES + (double) NCOLUMNS * rows);
}
