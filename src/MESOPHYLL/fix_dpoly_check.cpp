/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_check.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "dpoly3d_surface_check.h"
#include "dpoly_measure.h"
#include "dpoly_overlap.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly_cells.h"
#include "min.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;

namespace {
struct RingPoint {
  tagint tag;
  double x, y;
  double l0;    // preferred length of the segment to the vertex's ring successor
};
}    // namespace

// every vertex of the group at its unwrapped position, on every rank (the rings are whole in
// unwrapped coordinates: fix dpoly/cells checks it)
class FixDPolyCheck::UnwrappedVertices {
 public:
  UnwrappedVertices(Atom *atom, Domain *domain, int groupbit, const double *l0, MPI_Comm world)
  {
    std::vector<RingPoint> mine;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(atom->mask[i] & groupbit)) continue;
      double xu[3];
      domain->unmap(atom->x[i], atom->image[i], xu);
      mine.push_back({atom->tag[i], xu[0], xu[1], l0[i]});
    }
    all = DPoly::gather_on_all_ranks(std::move(mine), world);
    for (const auto &p : all) by_tag[p.tag] = &p;
  }
  const RingPoint &at(tagint tag) const { return *by_tag.at(tag); }
  DPoly::Point point(tagint tag) const
  {
    const RingPoint &p = at(tag);
    return {p.x, p.y};
  }

 private:
  std::vector<RingPoint> all;
  std::unordered_map<tagint, const RingPoint *> by_tag;
};

FixDPolyCheck::FixDPolyCheck(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyStage(lmp, narg, arg, CHECK, 9), target_pressure(0.0), pressure_tolerance(1.0e-6),
    stop_on_failure(0), minima(0), last{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}
{
  parse_keywords(3, narg, arg, [&](const char *key, const char *value) {
    if (strcmp(key, "pressure") == 0) {
      target_pressure = utils::numeric(FLERR, value, false, lmp);
      if (target_pressure == 0.0)    // the check is relative to |P0|
        error->all(FLERR, "Fix dpoly/check pressure must be nonzero, got {}", value);
    } else if (strcmp(key, "tolerance") == 0) {
      pressure_tolerance = utils::numeric(FLERR, value, false, lmp);
      if (pressure_tolerance <= 0.0)
        error->all(FLERR, "Fix dpoly/check tolerance must be > 0, got {}", value);
    } else if (strcmp(key, "action") == 0)
      stop_on_failure = one_of(key, value, "warn", "error");
    else
      return false;
    return true;
  });
}

// only after minimizations: it reads the minimizer's stop condition and force norm
int FixDPolyCheck::act()
{
  check();
  return NOTHING;
}

void FixDPolyCheck::check()
{
  minima++;
  Min *min = update->minimize;
  const int stop = min->stop_condition;
  const bool converged = (stop == Min::ETOL || stop == Min::FTOL || stop == Min::ZEROFORCE);
  const double force_norm = sqrt(min->fnorm_sqr());

  // P is read whenever the virial was tallied at this step (a minimizer's last step tallies it
  // for the thermo output), so that a non-finite P is flagged with or without 'pressure'
  double pressure_error = 0.0, pressure_value = 0.0;
  Compute *pressure = modify->get_compute_by_id("thermo_press");
  if (target_pressure != 0.0 && !pressure)
    error->all(FLERR, "Fix dpoly/check: no thermo_press compute to measure P");
  const bool pressure_known =
      pressure && (target_pressure != 0.0 || update->vflag_global == update->ntimestep);
  if (pressure_known) pressure_value = pressure->compute_scalar();
  if (target_pressure != 0.0)
    pressure_error = fabs(pressure_value - target_pressure) / fabs(target_pressure);
  // nan or inf in the energy means the state is meaningless, whatever else holds (a minimizer
  // always tallies the global energy, so thermo_pe can be read at its last step)
  Compute *pe = modify->get_compute_by_id("thermo_pe");
  const double energy = pe ? pe->compute_scalar() : 0.0;

  // a state with non-finite coordinates has no geometry to test (and the tests would not end)
  const std::string not_finite = non_finite_state();
  Geometry geometry;
  if (not_finite.empty()) geometry = cells ? polygon_geometry(!converged) : polyhedron_geometry();

  last[0] = converged ? 1.0 : 0.0;
  last[1] = force_norm;
  last[2] = pressure_error;
  last[3] = geometry.inverted;
  last[4] = geometry.tangled;
  last[5] = min->niter;
  last[6] = min->neval;
  last[7] = geometry.pairs;
  last[8] = minima;

  std::string problems;
  if (!std::isfinite(energy) || !std::isfinite(force_norm))
    problems +=
        fmt::format("; the energy pe = {} or the force norm {} is not finite", energy, force_norm);
  if (!std::isfinite(pressure_value))
    problems += fmt::format("; the pressure P = {} is not finite", pressure_value);
  problems += not_finite;
  if (!converged)
    problems += fmt::format("; the minimizer stopped without converging ({}){}", min->stopstr,
                            geometry.shortest_segment);
  if (std::isfinite(pressure_error) && pressure_error > pressure_tolerance)
    problems +=
        fmt::format("; |P - P0|/P0 = {:.3g} exceeds {:.3g}", pressure_error, pressure_tolerance);
  problems += geometry.problems;

  // the log line carries the problems too: LAMMPS stops printing warnings after its limit
  if (comm->me == 0)
    utils::logmesg(lmp, "fix dpoly/check: minimum {} at step {}: {}, force norm {:.6g}{}{}\n",
                   minima, update->ntimestep, min->stopstr, force_norm,
                   target_pressure != 0.0 ? fmt::format(", |P - P0|/P0 {:.3g}", pressure_error)
                                          : "",
                   problems.empty() ? "" : "; FAILED" + problems);
  if (problems.empty()) return;
  const std::string message =
      fmt::format("Fix dpoly/check: minimum {} at step {}{}", minima, update->ntimestep, problems);
  if (stop_on_failure) error->all(FLERR, message);
  if (comm->me == 0) error->warning(FLERR, message);
}

/* ----------------------------------------------------------------------
   collective: vertices (of the group) at non-finite positions, a non-finite box; "" if none
------------------------------------------------------------------------- */

std::string FixDPolyCheck::non_finite_state()
{
  std::string problems;
  const double box[6] = {domain->boxlo[0], domain->boxlo[1], domain->boxlo[2],
                         domain->boxhi[0], domain->boxhi[1], domain->boxhi[2]};
  bool box_finite = true;
  for (double b : box) box_finite = box_finite && std::isfinite(b);
  if (!box_finite)
    problems += fmt::format("; the box is not finite: {} {} {} to {} {} {}", box[0], box[1], box[2],
                            box[3], box[4], box[5]);
  bigint count = 0, count_all = 0;
  tagint first = MAXTAGINT, first_all = MAXTAGINT;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    if (std::isfinite(atom->x[i][0]) && std::isfinite(atom->x[i][1]) &&
        std::isfinite(atom->x[i][2]))
      continue;
    count++;
    first = std::min(first, atom->tag[i]);
  }
  MPI_Allreduce(&count, &count_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&first, &first_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (count_all)
    problems += fmt::format("; {} vertices have non-finite positions (first: vertex {})", count_all,
                            first_all);
  return problems;
}

/* ----------------------------------------------------------------------
   polygons: inverted cells, rings that cross themselves, interpenetrating cells, impossible
   packing fractions and segments
------------------------------------------------------------------------- */

FixDPolyCheck::Geometry FixDPolyCheck::polygon_geometry(bool name_shortest_segment)
{
  Geometry found;
  tagint first_inverted = 0;
  for (int c = 0; c < cells->ncells(); c++)
    if (cells->area(c) <= 0.0) {
      if (!found.inverted) first_inverted = cells->cell_id(c);
      found.inverted++;
    }
  tagint first_tangled = 0;
  const UnwrappedVertices vertices(
      atom, domain, cells->groupbit,
      DPoly::vertex_state(atom, error, "Fix dpoly/check").preferred_length, world);
  found.tangled = tangled_cells(vertices, first_tangled);
  const DPoly::Interpenetration overlapping = interpenetrating_cells(vertices);
  found.pairs = overlapping.pairs;

  if (found.inverted)
    found.problems +=
        fmt::format("; {} cells have area <= 0 (first: cell {}, area {:.6g})", found.inverted,
                    first_inverted, cells->area(cells->cell_index(first_inverted)));
  if (found.tangled)
    found.problems +=
        fmt::format("; {} rings cross themselves (first: cell {})", found.tangled, first_tangled);
  if (overlapping.pairs) {
    const tagint *pair = overlapping.first;
    found.problems +=
        fmt::format("; {} pairs of cells interpenetrate (first: {})", overlapping.pairs,
                    pair[0] == pair[1] ? fmt::format("cell {} and its periodic image", pair[0])
                                       : fmt::format("cells {} and {}", pair[0], pair[1]));
  }
  found.problems += geometry_problems(vertices);
  if (name_shortest_segment) found.shortest_segment = shortest_segment(vertices);
  return found;
}

/* ----------------------------------------------------------------------
   polyhedra (dpoly3d_surface_check.h): cells with volume <= 0, with faces that point inward,
   with a vertex inside another cell, and a packing fraction outside (0, 1]
------------------------------------------------------------------------- */

FixDPolyCheck::Geometry FixDPolyCheck::polyhedron_geometry()
{
  const DPoly3d::SurfaceProblems surfaces = DPoly3d::check_surfaces(lmp, *hub, groupbit);
  Geometry found;
  found.inverted = surfaces.collapsed;
  found.tangled = surfaces.folded;
  found.pairs = surfaces.pairs;
  if (surfaces.collapsed)
    found.problems +=
        fmt::format("; {} cells have volume <= 0 or are flat (first: cell {}, volume {:.6g})",
                    surfaces.collapsed, surfaces.first_collapsed, surfaces.first_volume);
  if (surfaces.folded)
    found.problems += fmt::format(
        "; {} cells have faces that point into the cell (first: cell {}, face {} {} {})",
        surfaces.folded, surfaces.first_folded, surfaces.first_face[0], surfaces.first_face[1],
        surfaces.first_face[2]);
  if (surfaces.pairs)
    found.problems += fmt::format(
        "; {} pairs of cells interpenetrate (first: cells {} and {}, vertex {} of cell {} inside "
        "the other)",
        surfaces.pairs, surfaces.first_pair[0], surfaces.first_pair[1], surfaces.first_vertex,
        surfaces.first_vertex_cell);
  // the box is the tissue's container only where it is periodic
  if (domain->xperiodic && domain->yperiodic && domain->zperiodic) {
    const double phi = surfaces.total_volume / (domain->xprd * domain->yprd * domain->zprd);
    if (!(phi > 0.0 && phi <= 1.0))
      found.problems += fmt::format("; the packing fraction phi is outside (0, 1]: {:.6g}", phi);
  }
  return found;
}

/* ----------------------------------------------------------------------
   rings that cross themselves: any two non-adjacent segments of one ring that intersect
------------------------------------------------------------------------- */

int FixDPolyCheck::tangled_cells(const UnwrappedVertices &vertices, tagint &first)
{
  int tangled = 0;
  first = 0;
  for (int cell = 0; cell < cells->ncells(); cell++) {
    const std::vector<tagint> &ring = cells->ring(cell);
    const int n = (int) ring.size();
    bool crossed = false;
    for (int i = 0; i < n && !crossed; i++)
      for (int j = i + 2; j < n && !crossed; j++) {
        if (i == 0 && j == n - 1) continue;    // neighbours through the closing segment
        crossed = DPoly::segments_cross(vertices.point(ring[i]), vertices.point(ring[(i + 1) % n]),
                                        vertices.point(ring[j]), vertices.point(ring[(j + 1) % n]));
      }
    if (crossed) {
      if (!tangled) first = cells->cell_id(cell);
      tangled++;
    }
  }
  return tangled;
}

/* ----------------------------------------------------------------------
   the ring segment shortest relative to its l0, named where a minimizer stopped early: where one
   had collapsed to a small fraction of l0, its segment and bending forces changed faster than
   FIRE's steps resolved (Fig 6 at high pressure). Ties: the lowest vertex ID (every rank holds
   every vertex here, so every rank finds the same segment).
------------------------------------------------------------------------- */

std::string FixDPolyCheck::shortest_segment(const UnwrappedVertices &vertices)
{
  double shortest = INFINITY, length = 0.0, l0 = 0.0;
  tagint first = 0, next = 0, cell_id = 0;
  for (int cell = 0; cell < cells->ncells(); cell++) {
    const std::vector<tagint> &ring = cells->ring(cell);
    const int n = (int) ring.size();
    for (int i = 0; i < n; i++) {
      const RingPoint &a = vertices.at(ring[i]), &b = vertices.at(ring[(i + 1) % n]);
      const double r = std::hypot(b.x - a.x, b.y - a.y);
      const double ratio = r / a.l0;
      if (!(ratio < shortest || (ratio == shortest && a.tag < first))) continue;    // nan too
      shortest = ratio;
      length = r;
      l0 = a.l0;
      first = a.tag;
      next = b.tag;
      cell_id = cells->cell_id(cell);
    }
  }
  if (!first) return "";
  return fmt::format(", shortest ring segment relative to its preferred length: {}-{} of cell "
                     "{}, {:.3g} long, {:.3g}% of l0 = {:.3g}",
                     first, next, cell_id, length, 100.0 * shortest, l0);
}

/* ----------------------------------------------------------------------
   cells whose outlines (the polygons through their vertex centres) overlap, across the periodic
   boundary too. Every rank holds every vertex here and finds the same pairs.
------------------------------------------------------------------------- */

DPoly::Interpenetration FixDPolyCheck::interpenetrating_cells(const UnwrappedVertices &vertices)
{
  std::vector<DPoly::Outline> outlines(cells->ncells());
  for (int cell = 0; cell < cells->ncells(); cell++) {
    outlines[cell].cell = cells->cell_id(cell);
    for (tagint tag : cells->ring(cell)) outlines[cell].corners.push_back(vertices.point(tag));
  }
  // the binned search shifts images along x and y only: a tilted box is not searched (said once)
  if (domain->triclinic) {
    if (!triclinic_warned && comm->me == 0)
      error->warning(FLERR,
                     "Fix {} {}: interpenetrating cells are not looked for in a triclinic box",
                     style, id);
    triclinic_warned = true;
    return {};
  }
  const DPoly::Box box{{domain->xprd, domain->yprd},
                       {domain->xperiodic != 0, domain->yperiodic != 0}};
  return DPoly::interpenetrating_cells(outlines, box);
}

/* ----------------------------------------------------------------------
   geometry no tissue can have. Cells that neither overlap nor invert fill a fraction in (0, 1]
   of the box, and so do their patches (compute dpoly/tissue's phi_patch) while vertex disks
   overlap by less than 1 - sin(pi/3) of their diameter. A segment not shorter than half the box
   has another image of its next vertex nearer; fix dpoly/cells stops a run at the first force
   evaluation with one, so this sees one only where that check was bypassed.
------------------------------------------------------------------------- */

std::string FixDPolyCheck::geometry_problems(const UnwrappedVertices &vertices)
{
  std::string problems;
  auto outside_unit_interval = [](double phi) {
    return !(phi > 0.0 && phi <= 1.0);    // nan too
  };
  double cell_area = 0.0;
  for (int c = 0; c < cells->ncells(); c++) cell_area += cells->area(c);
  // the box is the tissue's container only where it is periodic
  const bool container = domain->xperiodic && domain->yperiodic;
  const double phi = cell_area / (domain->xprd * domain->yprd);
  if (container && outside_unit_interval(phi))
    problems += fmt::format("; the packing fraction phi is outside (0, 1]: {:.6g}", phi);
  for (Compute *tissue : modify->get_compute_by_style("^dpoly/tissue$")) {
    DPoly::evaluate_global(tissue);    // the hub has, before the stages: then no work here
    const double phi_patch = tissue->vector[1];    // its vector element 2
    if (container && outside_unit_interval(phi_patch))
      problems += fmt::format("; the packing fraction phi_patch of compute {} is outside (0, 1]: "
                              "{:.6g}",
                              tissue->id, phi_patch);
  }

  const double half_box[2] = {0.5 * domain->xprd, 0.5 * domain->yprd};
  const int periodic[2] = {domain->xperiodic, domain->yperiodic};
  int too_long = 0;
  tagint first = 0, first_next = 0, first_cell = 0;
  double first_d[2] = {0.0, 0.0};
  for (int cell = 0; cell < cells->ncells(); cell++) {
    const std::vector<tagint> &ring = cells->ring(cell);
    const int n = (int) ring.size();
    for (int i = 0; i < n; i++) {
      const RingPoint &a = vertices.at(ring[i]), &b = vertices.at(ring[(i + 1) % n]);
      const double d[2] = {b.x - a.x, b.y - a.y};
      if (!((periodic[0] && fabs(d[0]) >= half_box[0]) ||
            (periodic[1] && fabs(d[1]) >= half_box[1])))
        continue;
      too_long++;
      if (!first || a.tag < first) {    // the lowest vertex ID: the same on any number of ranks
        first = a.tag;
        first_next = b.tag;
        first_cell = cells->cell_id(cell);
        first_d[0] = d[0];
        first_d[1] = d[1];
      }
    }
  }
  if (too_long) {
    const int dim = (periodic[0] && fabs(first_d[0]) >= half_box[0]) ? 0 : 1;
    problems +=
        fmt::format("; {} ring segments are not shorter than half the box (first: "
                    "segment {}-{} of cell {}, {:.6g} long, {:.6g} in {}, half the box "
                    "length {:.6g})",
                    too_long, first, first_next, first_cell, std::hypot(first_d[0], first_d[1]),
                    fabs(first_d[dim]), "xy"[dim], half_box[dim]);
  }
  return problems;
}

double FixDPolyCheck::compute_vector(int n)
{
  return last[n];
}

std::vector<double> FixDPolyCheck::restart_state() const
{
  return {(double) minima};
}

bool FixDPolyCheck::restore_state(const std::vector<double> &state)
{
  if (state.size() != 1 || !(state[0] >= 0.0)) return false;
  minima = (bigint) state[0];
  last[8] = minima;
  return true;
}
