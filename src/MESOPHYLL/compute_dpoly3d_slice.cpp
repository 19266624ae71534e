/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly3d_slice.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly3d_cells.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>

using namespace LAMMPS_NS;

// |area| / perimeter^2 below which an outline encloses nothing (round-off of a zero area)
static constexpr double DEGENERATE_AREA = 1.0e-12;
using DPoly3d::Outline;

namespace {
const char *STYLE = "Compute dpoly3d/slice";
enum { PHI, MEAN_SHAPE, MEAN_NEIGHBOURS, SECTIONS, HOLES, NVALUES };
enum { PLANE, CELL, AREA, PERIMETER, SHAPE, NEIGHBOURS, NCOLUMNS };

struct VertexRecord {
  DPoly3d::SliceVertex vertex;
  tagint cell;
  double diameter;
};
}    // namespace

constexpr int MAX_PLANES = 1000000;

ComputeDPoly3dSlice::ComputeDPoly3dSlice(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), cells(nullptr), nplanes(1), offset(0.5), contact_factor(1.0),
    values(nullptr), per_section(nullptr), rows(0)
{
  int iarg = 3;
  while (iarg < narg) {
    if (iarg + 2 > narg)
      utils::missing_cmd_args(FLERR, std::string("compute dpoly3d/slice ") + arg[iarg], error);
    const char *value = arg[iarg + 1];
    if (strcmp(arg[iarg], "planes") == 0) {
      nplanes = utils::inumeric(FLERR, value, false, lmp);
      // a fixed bound, not one from the box and the vertex size, which change during a run;
      // 10^6 is far beyond use (200 planes give phi to about 1e-6) and keeps the per-plane
      // arrays small (a count near 2^31 would ask for about 16 GB)
      if (nplanes < 1 || nplanes > MAX_PLANES)
        error->all(FLERR, "{} planes must be in [1, {}], got {}", STYLE, MAX_PLANES, value);
    } else if (strcmp(arg[iarg], "offset") == 0) {
      offset = utils::numeric(FLERR, value, false, lmp);
      if (!(offset >= 0.0 && offset < 1.0))
        error->all(FLERR, "{} offset must be in [0, 1) (a fraction of the plane spacing), got {}",
                   STYLE, value);
    } else if (strcmp(arg[iarg], "contact") == 0) {
      contact_factor = utils::numeric(FLERR, value, false, lmp);
      if (!(contact_factor > 0.0) || !std::isfinite(contact_factor))
        error->all(FLERR, "{} contact must be finite and > 0, got {}", STYLE, value);
    } else
      error->all(FLERR, "Unknown {} keyword: {}", STYLE, arg[iarg]);
    iarg += 2;
  }

  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 0;
  local_flag = 1;
  size_local_cols = NCOLUMNS;
  size_local_rows = 0;
  memory->create(values, NVALUES, "dpoly3d/slice:values");
}

ComputeDPoly3dSlice::~ComputeDPoly3dSlice()
{
  memory->destroy(values);
  memory->destroy(per_section);
}

void ComputeDPoly3dSlice::init()
{
  find_cells();
  if (!domain->xperiodic || !domain->yperiodic || !domain->zperiodic)
    error->all(FLERR, "{} needs a box periodic in x, y and z", STYLE);
  if (domain->triclinic)
    error->all(FLERR, "{} needs an orthogonal box, not a triclinic one", STYLE);
  vertex_state.find(atom, error, STYLE);
}

// looked up at every evaluation, not only in init(): 'run N pre no' skips init(), and a hub
// removed (or replaced) since would leave a dangling pointer
void ComputeDPoly3dSlice::find_cells()
{
  const auto hubs = modify->get_fix_by_style("^dpoly3d/cells$");
  if (hubs.empty())
    error->all(FLERR, "{} needs fix dpoly3d/cells: it knows the cells and checks their surfaces",
               STYLE);
  cells = dynamic_cast<FixDPoly3dCells *>(hubs.front());
}

/* ----------------------------------------------------------------------
   collective: gather every vertex (unwrapped) and face, cut the surfaces, and measure the
   outlines the same way on every rank
------------------------------------------------------------------------- */

ComputeDPoly3dSlice::Slices ComputeDPoly3dSlice::slice()
{
  find_cells();
  if (cells->ncells() == 0)
    error->all(FLERR,
               "{} {}: fix dpoly3d/cells has not checked the cells yet; evaluate it after a run "
               "(run 0 will do)",
               STYLE, id);
  const DPoly3d::VertexState state = vertex_state.get(atom, error, STYLE);
  std::vector<VertexRecord> mine;
  std::vector<DPoly3d::SliceFace> my_faces;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & cells->groupbit)) continue;
    const tagint self = atom->tag[i];
    VertexRecord r;
    r.vertex.tag = self;
    domain->unmap(atom->x[i], atom->image[i], r.vertex.x);
    r.cell = atom->molecule[i];
    r.diameter = state.diameter[i];
    mine.push_back(r);
    for (int m = 0; m < atom->num_angle[i]; m++)
      if (atom->angle_atom2[i][m] == self)
        my_faces.push_back(
            {atom->molecule[i], atom->angle_atom1[i][m], self, atom->angle_atom3[i][m]});
  }
  std::vector<VertexRecord> records = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::vector<DPoly3d::SliceFace> faces = DPoly::gather_on_all_ranks(std::move(my_faces), world);
  // ID order, so that the cells' mean diameters are the same sums on any number of ranks (the
  // faces' order does not matter: the outlines are chained through a map of edges)
  std::sort(records.begin(), records.end(), [](const VertexRecord &a, const VertexRecord &b) {
    return a.vertex.tag < b.vertex.tag;
  });

  std::vector<DPoly3d::SliceVertex> vertices;
  std::map<tagint, std::pair<double, int>> diameters;    // per cell: sum, count
  for (const auto &r : records) {
    vertices.push_back(r.vertex);
    diameters[r.cell].first += r.diameter;
    diameters[r.cell].second++;
  }
  const DPoly3d::SliceBox box = {domain->boxlo[2], domain->xprd, domain->yprd, domain->zprd};
  std::vector<Outline> outlines;
  try {
    outlines =
        DPoly3d::slice_surfaces(vertices, faces, box, DPoly3d::plane_heights(box, nplanes, offset));
  } catch (std::runtime_error &e) {
    error->all(FLERR, "{} {} at step {}: {}", STYLE, id, update->ntimestep, e.what());
  }

  Slices result;
  result.area = 0.0;
  result.holes = 0;
  std::vector<const Outline *> outer;
  for (const auto &o : outlines) {
    if (!std::isfinite(o.area) || !std::isfinite(o.perimeter))
      error->all(FLERR, "{} {} at step {}: a cross-section of cell {} has a non-finite size", STYLE,
                 id, update->ntimestep, o.cell);
    // a plane through a cell's top vertex or along its top edge touches the surface without
    // cutting it: the outline encloses nothing (zero area up to round-off) and is neither a
    // cross-section nor a hole
    if (std::fabs(o.area) <= DEGENERATE_AREA * o.perimeter * o.perimeter) continue;
    result.area += o.area;
    if (o.area > 0.0)
      outer.push_back(&o);
    else
      result.holes++;
  }
  // contact: outlines of different cells in one plane closer than the vertex spheres' contact
  // distance, from each cell's mean vertex diameter
  auto mean_diameter = [&](tagint cell) {
    const auto &d = diameters[cell];
    return d.first / d.second;
  };
  std::vector<std::set<tagint>> touching(outer.size());
  for (size_t a = 0; a < outer.size(); a++)
    for (size_t b = a + 1; b < outer.size() && outer[b]->plane == outer[a]->plane; b++) {
      if (outer[a]->cell == outer[b]->cell) continue;
      const double reach =
          contact_factor * 0.5 * (mean_diameter(outer[a]->cell) + mean_diameter(outer[b]->cell));
      if (DPoly3d::outline_distance(*outer[a], *outer[b], box) < reach) {
        touching[a].insert(outer[b]->cell);
        touching[b].insert(outer[a]->cell);
      }
    }
  for (size_t a = 0; a < outer.size(); a++)
    result.sections.push_back({outer[a]->plane, outer[a]->cell, outer[a]->area, outer[a]->perimeter,
                               (int) touching[a].size()});
  return result;
}

void ComputeDPoly3dSlice::compute_vector()
{
  invoked_vector = update->ntimestep;
  const Slices s = slice();
  double shape = 0.0, neighbours = 0.0;
  for (const auto &c : s.sections) {
    shape += DPoly::shape_index(c.perimeter, c.area);
    neighbours += c.neighbours;
  }
  const int n = (int) s.sections.size();
  values[PHI] = s.area / (nplanes * domain->xprd * domain->yprd);
  values[MEAN_SHAPE] = n ? shape / n : 0.0;
  values[MEAN_NEIGHBOURS] = n ? neighbours / n : 0.0;
  values[SECTIONS] = n;
  values[HOLES] = s.holes;
  vector = values;
}

// one row per cross-section, all on rank 0
void ComputeDPoly3dSlice::compute_local()
{
  invoked_local = update->ntimestep;
  const Slices s = slice();
  rows = comm->me == 0 ? (int) s.sections.size() : 0;
  memory->destroy(per_section);
  memory->create(per_section, std::max(rows, 1), NCOLUMNS, "dpoly3d/slice:per_section");
  for (int k = 0; k < rows; k++) {
    const Section &c = s.sections[k];
    per_section[k][PLANE] = c.plane + 1;
    per_section[k][CELL] = c.cell;
    per_section[k][AREA] = c.area;
    per_section[k][PERIMETER] = c.perimeter;
    per_section[k][SHAPE] = DPoly::shape_index(c.perimeter, c.area);
    per_section[k][NEIGHBOURS] = c.neighbours;
  }
  size_local_rows = rows;
  array_local = per_section;
}

double ComputeDPoly3dSlice::memory_usage()
{
  return sizeof(double) * (NVALUES + (double) NCOLUMNS * rows);
}
