/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_cells.h"

#include "atom.h"
#include "atom_vec.h"
#include "bond.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly_stage.h"
#include "force.h"
#include "group.h"
#include "math_const.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// What one rank tells the others about each of its vertices when the rings are checked.
struct VertexRecord {
  tagint tag, molecule, prev, next;
  tagint stray_segment;    // partner of a dpoly/segment bond that is no ring segment (0: none)
  int centred_angles;
  int bonds_to_next, bonds_to_prev;    // dpoly/segment bonds stored on this vertex
  double diameter, preferred_length, preferred_angle, preferred_area;
};
}    // namespace

// scalar: the area energy; vector: number of cells, total cell area, cells with area <= 0
FixDPolyCells::FixDPolyCells(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyHub(lmp, narg, arg, "area"), area_eps(1.0), area_energy(0.0), checked_atoms(-1)
{
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "eps_a") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix dpoly/cells eps_a", error);
      area_eps = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (area_eps < 0.0)
        error->all(FLERR, "Fix dpoly/cells eps_a must be >= 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Unknown fix dpoly/cells keyword: {}", arg[iarg]);
  }
}

FixDPolyCells *FixDPolyCells::find(LAMMPS *lmp, const std::string &who)
{
  auto hubs = lmp->modify->get_fix_by_style("^dpoly/cells$");
  if (hubs.empty()) lmp->error->all(FLERR, "{} needs fix dpoly/cells, which keeps the cells", who);
  return dynamic_cast<FixDPolyCells *>(hubs.front());
}

void FixDPolyCells::check_requirements()
{
  if (domain->dimension != 2)
    error->all(FLERR, "Fix dpoly/cells needs a 2d simulation (dimension 2), got dimension {}",
               domain->dimension);
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Fix dpoly/cells needs molecule IDs (e.g. atom_style molecular): "
               "each cell is a molecule");
  if (!atom->avec->angles_allow)
    error->all(FLERR,
               "Fix dpoly/cells needs angles: each vertex is the centre of one angle "
               "(prev, vertex, next) that gives the ring order");
  vertex_state.find(atom, error, "Fix dpoly/cells");
}

double *FixDPolyCells::vertex_diameters()
{
  return vertex_state.get(atom, error, "Fix dpoly/cells").diameter;
}

std::vector<tagint> FixDPolyCells::surface_neighbours(tagint atom) const
{
  const auto found = rings.find(atom);
  if (found == rings.end()) not_a_vertex(atom);
  return {found->second.prev, found->second.next};
}

void FixDPolyCells::post_force(int vflag)
{
  measure_cells();
  apply_area_forces(vflag);
}

// after a stage: the rings are re-read after one that changed them (refinement, which growth
// may follow)
void FixDPolyCells::after_stage(int change)
{
  if (change != FixDPolyStage::NOTHING) checked_atoms = -1;    // the checked ghosts are gone
  if (change & FixDPolyStage::RINGS) refresh_cells();
}

// collective: a ring must run counter-clockwise, so that its area is positive
void FixDPolyCells::check_measured_cells()
{
  check_finite_terms();
  for (int c = 0; c < ncells(); c++)
    if (areas[c] <= 0.0)
      error->all(FLERR,
                 "Fix dpoly/cells: cell {} has area {:.8g} <= 0; a ring must run "
                 "counter-clockwise and must not be inverted",
                 cell_ids[c], areas[c]);
}

/* ----------------------------------------------------------------------
   collective: a preferred area or length far below the actual one makes the strain's square
   overflow (pe = inf, forces nan) without any value being invalid by itself
------------------------------------------------------------------------- */

void FixDPolyCells::check_finite_terms()
{
  for (int c = 0; c < ncells(); c++)
    if (!std::isfinite(DPoly::area_law(1.0, areas[c], preferred_areas[c]).energy))
      error->all(FLERR,
                 "Fix dpoly/cells: cell {} has a0 = {} for an area of {:.8g}: its area term "
                 "(a/a0 - 1)^2 is not finite; give a0 a value of the order of the cell's area",
                 cell_ids[c], preferred_areas[c], areas[c]);
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/cells");
  tagint worst = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double r = std::hypot(to_next[2 * i], to_next[2 * i + 1]);
    if (!std::isfinite(DPoly::segment_law(1.0, r, state.preferred_length[i]).energy))
      worst = std::max(worst, atom->tag[i]);
  }
  tagint worst_any = 0;
  MPI_Allreduce(&worst, &worst_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (!worst_any) return;
  double values[2] = {0.0, 0.0}, values_any[2];
  const int i = atom->map(worst_any);
  if (worst == worst_any && i >= 0 && i < atom->nlocal) {
    values[0] = state.preferred_length[i];
    values[1] = std::hypot(to_next[2 * i], to_next[2 * i + 1]);
  }
  MPI_Allreduce(values, values_any, 2, MPI_DOUBLE, MPI_SUM, world);
  error->all(FLERR,
             "Fix dpoly/cells: vertex {} has l0 = {} for a segment of length {:.8g}: its length "
             "term (r/l0 - 1)^2 is not finite; give l0 a value of the order of the segment",
             worst_any, values_any[0], values_any[1]);
}

/* ----------------------------------------------------------------------
   collective: gather every vertex's ring links and state, check that each cell is one closed
   ring with valid values, index the cells
------------------------------------------------------------------------- */

void FixDPolyCells::read_cells()
{
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/cells");
  // bond types of bond_style dpoly/segment (alone or in hybrid): its sub-style has their coeffs
  Bond *segment_style = force->bond_match("dpoly/segment");
  auto is_segment_type = [&](int type) {
    return segment_style && segment_style->allocated && type > 0 && type <= atom->nbondtypes &&
        segment_style->setflag[type];
  };
  std::vector<VertexRecord> mine;
  tagint outside = 0, outside_molecule = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    const DPoly::RingLinks links = DPoly::ring_links(atom, i);
    if (!(atom->mask[i] & groupbit)) {
      if (links.count > 0 && atom->tag[i] > outside) {
        outside = atom->tag[i];
        outside_molecule = atom->molecule[i];
      }
      continue;
    }
    VertexRecord v{atom->tag[i],
                   atom->molecule[i],
                   links.prev,
                   links.next,
                   0,
                   links.count,
                   0,
                   0,
                   state.diameter[i],
                   state.preferred_length[i],
                   state.preferred_angle[i],
                   state.preferred_area[i]};
    if (atom->avec->bonds_allow)
      for (int m = 0; m < atom->num_bond[i]; m++) {
        if (!is_segment_type(atom->bond_type[i][m])) continue;
        const tagint partner = atom->bond_atom[i][m];
        if (partner == links.next)
          v.bonds_to_next++;
        else if (partner == links.prev)
          v.bonds_to_prev++;
        else if (!v.stray_segment)
          v.stray_segment = partner;
      }
    mine.push_back(v);
  }
  tagint outside_any = 0;
  MPI_Allreduce(&outside, &outside_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (outside_any) {
    tagint molecule = (outside == outside_any) ? outside_molecule : 0, molecule_any = 0;
    MPI_Allreduce(&molecule, &molecule_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
    error->all(FLERR,
               "Fix dpoly/cells {}: vertex {} of molecule {} is the centre of a ring angle but "
               "not in group {}; the hub must hold every cell (rings, segments and adhesive "
               "bonds reach across cells): define fix dpoly/cells on a group of all ring "
               "vertices, usually all",
               id, outside_any, molecule_any, group->names[igroup]);
  }

  // the whole ring table on every rank, so every rank reaches the same verdict
  std::vector<VertexRecord> all = DPoly::gather_on_all_ranks(std::move(mine), world);
  if (all.empty())
    error->all(FLERR, "Fix dpoly/cells: group {} holds no vertices", group->names[igroup]);

  std::unordered_map<tagint, const VertexRecord *> by_tag;
  for (const auto &v : all) {
    if (v.centred_angles != 1)
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} is the centre of {} angles; a ring vertex "
                 "needs exactly one angle (prev, vertex, next)",
                 v.tag, v.centred_angles);
    if (v.molecule <= 0)
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} has molecule ID {}; each cell must be a "
                 "molecule with ID > 0",
                 v.tag, v.molecule);
    // NaN fails every comparison and inf passes every '> 0': test for finite values first
    const char *hint = "set it in the Vertices section of the data file or with the set command";
    if (!(std::isfinite(v.diameter) && v.diameter > 0.0))
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} has sigma = {}; it must be finite and > 0: {} "
                 "(the vertex is in cell {})",
                 v.tag, v.diameter, hint, v.molecule);
    if (!(std::isfinite(v.preferred_length) && v.preferred_length > 0.0))
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} has l0 = {}; it must be finite and > 0: {} "
                 "(the vertex is in cell {})",
                 v.tag, v.preferred_length, hint, v.molecule);
    if (!(std::isfinite(v.preferred_area) && v.preferred_area > 0.0))
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} has a0 = {}; it must be finite and > 0: {} "
                 "(the vertex is in cell {})",
                 v.tag, v.preferred_area, hint, v.molecule);
    if (!(v.preferred_angle > -MathConst::MY_PI && v.preferred_angle <= MathConst::MY_PI))
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} has theta0 = {}; a turning angle must be in "
                 "(-pi, pi] (radians): {} (the vertex is in cell {})",
                 v.tag, v.preferred_angle, hint, v.molecule);
    by_tag[v.tag] = &v;
  }

  std::unordered_map<tagint, std::vector<const VertexRecord *>> members;
  for (const auto &v : all) {
    const auto next = by_tag.find(v.next);
    if (next == by_tag.end() || next->second->molecule != v.molecule || next->second->prev != v.tag)
      error->all(FLERR,
                 "Fix dpoly/cells: vertex {} of cell {} points to vertex {} as its next, "
                 "but that is not a vertex of the same ring pointing back to it",
                 v.tag, v.molecule, v.next);
    members[v.molecule].push_back(&v);
  }
  rings.clear();
  for (const auto &v : all) rings[v.tag] = {v.prev, v.next};

  cell_ids.clear();
  for (const auto &m : members) cell_ids.push_back(m.first);
  std::sort(cell_ids.begin(), cell_ids.end());
  const int n = ncells();
  vertex_counts.assign(n, 0);
  preferred_areas.assign(n, 0.0);
  ring_order.assign(n, {});

  for (int c = 0; c < n; c++) {
    const auto &ring = members[cell_ids[c]];
    const int count = (int) ring.size();
    if (count < 3)
      error->all(FLERR, "Fix dpoly/cells: cell {} has {} vertices; a ring needs at least 3",
                 cell_ids[c], count);
    const VertexRecord *start = ring.front();
    int steps = 0;
    const VertexRecord *v = start;
    do {
      ring_order[c].push_back(v->tag);
      if (v->preferred_area != start->preferred_area)
        error->all(FLERR,
                   "Fix dpoly/cells: cell {} has different a0 on vertices {} ({}) and {} ({})",
                   cell_ids[c], start->tag, start->preferred_area, v->tag, v->preferred_area);
      v = by_tag[v->next];
      steps++;
    } while (v != start && steps <= count);
    if (steps != count)
      error->all(FLERR,
                 "Fix dpoly/cells: cell {} is not one closed ring: following the ring "
                 "from vertex {} returns after {} of its {} vertices",
                 cell_ids[c], start->tag, steps, count);
    vertex_counts[c] = count;
    preferred_areas[c] = start->preferred_area;
  }

  // every ring segment needs exactly one dpoly/segment bond, or its term vanishes or counts
  // twice; with newton_bond on a bond is stored once, on either atom, with off on both
  if (segment_style) {
    for (const auto &v : all)
      if (v.stray_segment)
        error->all(FLERR,
                   "Fix dpoly/cells: dpoly/segment bond {}-{} is not a segment of a ring: its "
                   "atoms must be consecutive vertices (prev, vertex, next) of the angle "
                   "centred on one of them; remove it or give it a bond type of another style",
                   std::min(v.tag, v.stray_segment), std::max(v.tag, v.stray_segment));
    for (const auto &v : all) {
      const int count = force->newton_bond ? v.bonds_to_next + by_tag[v.next]->bonds_to_prev
                                           : v.bonds_to_next;
      if (count == 0)
        error->all(FLERR,
                   "Fix dpoly/cells: ring segment {}-{} of cell {} has no dpoly/segment bond, so "
                   "it has no length term; add the bond {} {} to the Bonds section",
                   v.tag, v.next, v.molecule, v.tag, v.next);
      if (count > 1)
        error->all(FLERR,
                   "Fix dpoly/cells: ring segment {}-{} of cell {} has {} dpoly/segment bonds, so "
                   "its length term counts {} times; keep exactly one bond per segment in the "
                   "Bonds section",
                   v.tag, v.next, v.molecule, count, count);
    }
  }

  index_cells();
  areas.assign(n, 0.0);
  perimeters.assign(n, 0.0);
  area_slopes.assign(n, 0.0);
}

/* ----------------------------------------------------------------------
   collective: the rings as the styles see them (each vertex joined to the nearest image of its
   next vertex) must be the rings of the unwrapped positions, which the shoelace area uses.
   They part when a segment is not shorter than half the box (another image is nearer), when it
   is longer than the ghost cutoff (its own image may be no ghost of this rank), or when image
   flags do not keep a ring whole. Ghosts only change at reneighbouring, so a check at run start
   and at every reneighbouring sees a wrong image before any force uses it. A segment that
   outgrows half the box between two reneighbourings makes another image the nearest one, which
   measure_cells() notices against the images recorded here.
------------------------------------------------------------------------- */

void FixDPolyCells::check_nearest_images()
{
  double **x = atom->x;
  const double tolerance = 1.0e-8 * (domain->xprd + domain->yprd);
  checked_rings.assign(atom->nlocal, {0, 0, 0, -1, -1});
  checked_atoms = atom->nlocal + atom->nghost;
  tagint broken = 0;    // largest vertex ID whose next vertex is not where its ring continues
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const DPoly::RingLinks links = DPoly::ring_links(atom, i);
    const int j = domain->closest_image(i, atom->map(links.next));
    checked_rings[i] = {atom->tag[i], links.prev, links.next,
                        domain->closest_image(i, atom->map(links.prev)), j};
    bool whole = j >= 0;
    for (int d = 0; d < 2 && whole; d++)
      whole = fabs(unwrapped[3 * i + d] + x[j][d] - x[i][d] - unwrapped[3 * j + d]) <= tolerance;
    if (!whole) broken = std::max(broken, atom->tag[i]);
  }
  tagint broken_any = 0;
  MPI_Allreduce(&broken, &broken_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (!broken_any) return;

  // its owner tells every rank the segment between the unwrapped positions, and the cell
  const tagint next = rings.at(broken_any).next;
  double found[4] = {0.0, 0.0, 0.0, 0.0}, found_any[4];    // dx, dy, cell, next held
  const int i = atom->map(broken_any);
  if (broken == broken_any && i >= 0 && i < atom->nlocal) {
    const int j = atom->map(next);
    if (j >= 0) {
      found[0] = unwrapped[3 * j] - unwrapped[3 * i];
      found[1] = unwrapped[3 * j + 1] - unwrapped[3 * i + 1];
      found[3] = 1.0;
    }
    found[2] = (double) atom->molecule[i];
  }
  MPI_Allreduce(found, found_any, 4, MPI_DOUBLE, MPI_SUM, world);
  const double length = std::hypot(found_any[0], found_any[1]);
  const auto cell = (tagint) found_any[2];
  const double half_box[2] = {0.5 * domain->xprd, 0.5 * domain->yprd};
  const int periodic[2] = {domain->xperiodic, domain->yperiodic};
  // the ghost cutoff is a length only in an orthogonal box
  const double cutoff = domain->triclinic ? 0.0 : std::min(comm->cutghost[0], comm->cutghost[1]);

  for (int d = 0; d < 2; d++)
    if (found_any[3] > 0.0 && periodic[d] && fabs(found_any[d]) >= half_box[d])
      error->all(FLERR,
                 "Fix dpoly/cells: at step {}, ring segment {}-{} of cell {} is {:.8g} long "
                 "({:.8g} in {}), not shorter than half the box length in {} ({:.8g}): the "
                 "nearest image of vertex {} no longer continues the ring, so the cell's area "
                 "and forces would be wrong; keep segments shorter than half the box (fix "
                 "dpoly/refine splits long ones) and image flags that keep each ring whole",
                 update->ntimestep, broken_any, next, cell, length, fabs(found_any[d]), "xy"[d],
                 "xy"[d], half_box[d], next);
  if (found_any[3] > 0.0 && cutoff > 0.0 && length > cutoff)
    error->all(FLERR,
               "Fix dpoly/cells: at step {}, ring segment {}-{} of cell {} is {:.8g} long, "
               "longer than the communication cutoff {:.8g}: the image of vertex {} that "
               "continues the ring is no ghost atom here, and a farther image would take its "
               "place in the cell's area and forces; set comm_modify cutoff above the longest "
               "segment",
               update->ntimestep, broken_any, next, cell, length, cutoff, next);
  error->all(FLERR,
             "Fix dpoly/cells: the ring is not whole between vertex {} and its next "
             "vertex: give the ring consistent image flags, keep its segments shorter "
             "than half the box, and make sure the next vertex is within the "
             "communication cutoff",
             broken_any);
}

/* ----------------------------------------------------------------------
   collective: a cell must fit inside the periodic box. A ring narrower than the box in x and in
   y cannot meet its own periodic images (any translate by box vectors leaves its x or its y
   range); a wider one can overlap them, and its area then counts more than once.
------------------------------------------------------------------------- */

void FixDPolyCells::check_cell_extents()
{
  const int n = ncells();
  // per cell, the largest x, y, -x and -y of its vertices' unwrapped positions
  std::vector<double> local(4 * (size_t) n, -HUGE_VAL), global(4 * (size_t) n);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = cell_index(atom->molecule[i]);
    if (c < 0) continue;
    for (int d = 0; d < 2; d++) {
      local[4 * c + d] = std::max(local[4 * c + d], unwrapped[3 * i + d]);
      local[4 * c + 2 + d] = std::max(local[4 * c + 2 + d], -unwrapped[3 * i + d]);
    }
  }
  MPI_Allreduce(local.data(), global.data(), 4 * n, MPI_DOUBLE, MPI_MAX, world);
  const double box[2] = {domain->xprd, domain->yprd};
  const int periodic[2] = {domain->xperiodic, domain->yperiodic};
  for (int c = 0; c < n; c++)
    for (int d = 0; d < 2; d++) {
      const double extent = global[4 * c + d] + global[4 * c + 2 + d];
      if (periodic[d] && extent >= box[d])
        error->all(FLERR,
                   "Fix dpoly/cells: cell {} spans {:.8g} in {}, not less than the box length "
                   "{:.8g} in {}: a cell must fit inside the periodic box, or it can overlap its "
                   "own periodic images and its area counts more than once in the packing "
                   "fraction; use a larger box or smaller cells",
                   cell_ids[c], extent, "xy"[d], box[d], "xy"[d]);
    }
}

/* ----------------------------------------------------------------------
   the ring neighbours' images of owned vertex i recorded by the last ring check, if they are
   still its ring neighbours' nearest images: then they are what DPoly::closest_neighbour()
   would find, without its search of every image of both atoms at every force evaluation. In an
   orthogonal box an image nearer than half the box length in every periodic direction is the
   nearest of all images; in a triclinic box the search always runs.
------------------------------------------------------------------------- */

// the last ring check recorded the images of every owned vertex of the present atom numbering
bool FixDPolyCells::images_recorded() const
{
  return (int) checked_rings.size() == atom->nlocal &&
      checked_atoms == atom->nlocal + atom->nghost;
}

FixDPolyCells::NearestImageBounds FixDPolyCells::nearest_image_bounds() const
{
  NearestImageBounds bounds;
  bounds.recorded = images_recorded();
  bounds.usable = !domain->triclinic && bounds.recorded;
  bounds.half_box[0] = domain->xperiodic ? 0.5 * domain->xprd : INFINITY;
  bounds.half_box[1] = domain->yperiodic ? 0.5 * domain->yprd : INFINITY;
  return bounds;
}

bool FixDPolyCells::checked_images_hold(int i, const NearestImageBounds &bounds, int &prev_image,
                                        int &next_image) const
{
  if (!bounds.usable) return false;
  const CheckedRing &ring = checked_rings[i];
  const tagint *tag = atom->tag;
  const int jp = ring.prev_image, jn = ring.next_image;
  // indices below the atom count of the ring check are still indices of atoms
  if (ring.self != tag[i] || jp < 0 || jn < 0 || tag[jp] != ring.prev || tag[jn] != ring.next)
    return false;
  double **x = atom->x;
  const double *hb = bounds.half_box;
  if (!(fabs(x[jp][0] - x[i][0]) < hb[0] && fabs(x[jp][1] - x[i][1]) < hb[1] &&
        fabs(x[jn][0] - x[i][0]) < hb[0] && fabs(x[jn][1] - x[i][1]) < hb[1]))
    return false;
  prev_image = jp;
  next_image = jn;
  return true;
}

/* ----------------------------------------------------------------------
   collective: area (shoelace on unwrapped positions) and perimeter of every cell. A nearest
   image of a next vertex other than the one of the last ring check (the ghosts are the same
   until the next reneighbouring) means a segment just passed half the box: the ring check
   names it before any step is taken with the wrong image.
------------------------------------------------------------------------- */

void FixDPolyCells::measure_cells()
{
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  to_prev.assign(2 * (size_t) nlocal, 0.0);
  to_next.assign(2 * (size_t) nlocal, 0.0);
  const int moved = 2 * ncells();    // slot of the count of next vertices with another image
  std::vector<double> local(moved + 1, 0.0), global(moved + 1, 0.0);
  const NearestImageBounds bounds = nearest_image_bounds();

  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    int jp, jn;
    if (!checked_images_hold(i, bounds, jp, jn)) {
      const DPoly::RingLinks links = DPoly::ring_links(atom, i);
      jp = DPoly::closest_neighbour(lmp, i, links.prev, "Fix dpoly/cells");
      jn = DPoly::closest_neighbour(lmp, i, links.next, "Fix dpoly/cells");
      if (bounds.recorded && jn != checked_rings[i].next_image) local[moved] += 1.0;
    }
    const int c = cell_index(atom->molecule[i]);
    if (c < 0)
      error->one(FLERR,
                 "Fix dpoly/cells: vertex {} belongs to molecule {}, which was not a cell "
                 "when the run started",
                 atom->tag[i], atom->molecule[i]);
    double *dp = &to_prev[2 * i], *dn = &to_next[2 * i];
    dp[0] = x[i][0] - x[jp][0];
    dp[1] = x[i][1] - x[jp][1];
    dn[0] = x[jn][0] - x[i][0];
    dn[1] = x[jn][1] - x[i][1];
    double xu[3];
    domain->unmap(x[i], atom->image[i], xu);
    local[2 * c] += 0.5 * (xu[0] * dn[1] - xu[1] * dn[0]);
    local[2 * c + 1] += sqrt(dn[0] * dn[0] + dn[1] * dn[1]);
  }
  MPI_Allreduce(local.data(), global.data(), moved + 1, MPI_DOUBLE, MPI_SUM, world);
  for (int c = 0; c < ncells(); c++) {
    areas[c] = global[2 * c];
    perimeters[c] = global[2 * c + 1];
  }
  if (global[moved] > 0.0) {
    share_unwrapped_positions();
    check_nearest_images();
  }
}

/* ----------------------------------------------------------------------
   U = (eps_a/2)(a/a0 - 1)^2 per cell (DPoly::area_law). With D = x_next - x_prev,
   da/dx_i = (D_y, -D_x)/2.
   Under a deformation of the box a scales with its determinant, so the cell's virial is
   -a dU/da on the diagonal (shared equally among its vertices for the per-atom virial).
------------------------------------------------------------------------- */

void FixDPolyCells::apply_area_forces(int vflag)
{
  v_init(vflag);
  area_energy = 0.0;
  for (int c = 0; c < ncells(); c++) {
    const DPoly::Law law = DPoly::area_law(area_eps, areas[c], preferred_areas[c]);
    area_energy += law.energy;
    area_slopes[c] = law.first;
  }

  double **f = atom->f;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = cell_index(atom->molecule[i]);
    const double slope = area_slopes[c];
    const double dx = to_prev[2 * i] + to_next[2 * i];
    const double dy = to_prev[2 * i + 1] + to_next[2 * i + 1];
    f[i][0] -= 0.5 * slope * dy;
    f[i][1] += 0.5 * slope * dx;
    if (evflag) {
      const double w = -areas[c] * slope / vertex_counts[c];
      double v[6] = {w, w, 0.0, 0.0, 0.0, 0.0};
      v_tally(i, v);
    }
  }
}

double FixDPolyCells::compute_scalar()
{
  return area_energy;
}

double FixDPolyCells::compute_vector(int n)
{
  if (n == 0) return ncells();
  if (n == 1) {
    double total = 0.0;
    for (double a : areas) total += a;
    return total;
  }
  return (double) std::count_if(areas.begin(), areas.end(), [](double a) {
    return a <= 0.0;
  });
}

double FixDPolyCells::memory_usage()
{
  return sizeof(double) * (to_prev.capacity() + to_next.capacity() + unwrapped.capacity()) +
      (sizeof(double) * 4 + sizeof(int) * 2 + sizeof(tagint)) * cell_ids.capacity();
}
