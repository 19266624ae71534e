/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly3d_tissue.h"

#include "atom.h"
#include "domain.h"
#include "dpoly_adhesion.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly3d_cells.h"
#include "math_const.h"
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <array>
#include <cmath>

using namespace LAMMPS_NS;

namespace {
const char *STYLE = "Compute dpoly3d/tissue";
enum { PHI, MEAN_SHAPE, MEAN_NEIGHBOURS, BONDS, CELLS, PHI_PATCH, FLATTEST_FACE, NVALUES };
enum { ID, VOLUME, SURFACE, SHAPE, NEIGHBOURS, CELL_BONDS, PATCH_VOLUME, NCOLUMNS };

struct PatchVertex {
  tagint tag, cell;
  double x[3];    // unwrapped: every cell whole
  double diameter;
};
struct PatchFace {
  tagint a, b, c;    // counter-clockwise seen from outside the cell
};
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
  vertex_state.find(atom, error, STYLE);
}

double ComputeDPoly3dTissue::shape_parameter(double surface, double volume)
{
  return surface * surface * surface / (36.0 * MathConst::MY_PI * volume * volume);
}

double ComputeDPoly3dTissue::patch_push()
{
  return 0.5 * sin(MathConst::MY_PI / 3.0);
}

double ComputeDPoly3dTissue::face_flatness(const double *a, const double *b, const double *c)
{
  double ab[3], bc[3], ca[3], normal[3];
  for (int k = 0; k < 3; k++) {
    ab[k] = b[k] - a[k];
    bc[k] = c[k] - b[k];
    ca[k] = a[k] - c[k];
  }
  MathExtra::cross3(ab, bc, normal);
  const double longest =
      std::max({MathExtra::lensq3(ab), MathExtra::lensq3(bc), MathExtra::lensq3(ca)});
  return longest > 0.0 ? MathExtra::len3(normal) / longest : 0.0;    // 2 area / longest^2
}

/* ----------------------------------------------------------------------
   collective: per cell, the volume of its surface with every vertex pushed out radially, from
   the mean of the cell's vertices, by sin(pi/3) times its radius (the 2d phi_patch's rule one
   dimension up: the cell's body reaches past the vertex centres by the vertex spheres); the
   divergence theorem over the pushed faces. And the flattest face of all cells, on the vertex
   centres. From whole-system tables in ID order, so the same values on any number of ranks.
------------------------------------------------------------------------- */

ComputeDPoly3dTissue::SurfaceMeasures ComputeDPoly3dTissue::measure_surfaces()
{
  const DPoly3d::VertexState state = vertex_state.get(atom, error, STYLE);
  std::vector<PatchVertex> mine;
  std::vector<PatchFace> my_faces;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & cells->groupbit)) continue;
    const tagint self = atom->tag[i];
    PatchVertex v;
    v.tag = self;
    v.cell = atom->molecule[i];
    domain->unmap(atom->x[i], atom->image[i], v.x);
    v.diameter = state.diameter[i];
    mine.push_back(v);
    for (int m = 0; m < atom->num_angle[i]; m++)
      if (atom->angle_atom2[i][m] == self)
        my_faces.push_back({atom->angle_atom1[i][m], self, atom->angle_atom3[i][m]});
  }
  std::vector<PatchVertex> vertices = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::vector<PatchFace> faces = DPoly::gather_on_all_ranks(std::move(my_faces), world);
  std::sort(vertices.begin(), vertices.end(), [](const PatchVertex &p, const PatchVertex &q) {
    return p.tag < q.tag;
  });
  std::sort(faces.begin(), faces.end(), [](const PatchFace &p, const PatchFace &q) {
    return std::array<tagint, 3>{p.b, p.a, p.c} < std::array<tagint, 3>{q.b, q.a, q.c};
  });

  const int n = cells->ncells();
  std::vector<std::array<double, 4>> centre(n, {0.0, 0.0, 0.0, 0.0});    // sum x, y, z; count
  for (const auto &v : vertices) {
    const int c = cells->cell_index(v.cell);
    if (c < 0) continue;
    for (int k = 0; k < 3; k++) centre[c][k] += v.x[k];
    centre[c][3] += 1.0;
  }
  std::vector<std::array<double, 3>> pushed(vertices.size());
  for (size_t i = 0; i < vertices.size(); i++) {
    const int c = cells->cell_index(vertices[i].cell);
    double d[3] = {0.0, 0.0, 0.0}, r2 = 0.0;
    if (c >= 0)
      for (int k = 0; k < 3; k++) {
        d[k] = vertices[i].x[k] - centre[c][k] / centre[c][3];
        r2 += d[k] * d[k];
      }
    const double scale = r2 > 0.0 ? patch_push() * vertices[i].diameter / sqrt(r2) : 0.0;
    for (int k = 0; k < 3; k++) pushed[i][k] = vertices[i].x[k] + scale * d[k];
  }
  auto row_of = [&](tagint tag) {
    auto it =
        std::lower_bound(vertices.begin(), vertices.end(), tag, [](const PatchVertex &p, tagint t) {
          return p.tag < t;
        });
    if (it == vertices.end() || it->tag != tag)
      error->all(FLERR, "{} {}: face vertex {} is not in the cells' group", STYLE, id, tag);
    return (size_t) (it - vertices.begin());
  };
  SurfaceMeasures measures;
  std::vector<double> &volume = measures.patch_volumes;
  volume.assign(n, 0.0);
  measures.flattest_face = INFINITY;
  for (const auto &f : faces) {
    const size_t ra = row_of(f.a), rb = row_of(f.b), rc = row_of(f.c);
    const auto &a = pushed[ra], &b = pushed[rb], &c = pushed[rc];
    const int cell = cells->cell_index(vertices[rb].cell);
    if (cell < 0) continue;
    measures.flattest_face = std::min(
        measures.flattest_face, face_flatness(vertices[ra].x, vertices[rb].x, vertices[rc].x));
    volume[cell] += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                     a[2] * (b[0] * c[1] - b[1] * c[0])) /
        6.0;
  }
  // no face of a hub cell: report 0 rather than carry an infinity into the output
  if (!std::isfinite(measures.flattest_face)) measures.flattest_face = 0.0;
  for (int c = 0; c < n; c++)
    if (!std::isfinite(volume[c]))
      error->all(FLERR, "{} {} at step {}: the patch volume of cell {} is not finite", STYLE, id,
                 update->ntimestep, cells->cell_id(c));
  return measures;
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
  const SurfaceMeasures surfaces = measure_surfaces();
  double patch_sum = 0.0;
  for (int c = 0; c < n; c++) patch_sum += surfaces.patch_volumes[c];
  values[PHI_PATCH] = patch_sum / (domain->xprd * domain->yprd * domain->zprd);
  values[FLATTEST_FACE] = surfaces.flattest_face;
  vector = values;
}

void ComputeDPoly3dTissue::compute_array()
{
  invoked_array = update->ntimestep;
  require_measured_cells();
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  rows = cells->ncells();
  const std::vector<double> patch = measure_surfaces().patch_volumes;
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
    per_cell[c][PATCH_VOLUME] = patch[c];
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
