/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_mesophyll_grow.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_adhesion.h"
#include "dpoly_growth_rules.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly_cells.h"
#include "modify.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;

FixMesophyllGrow::FixMesophyllGrow(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyStage(lmp, narg, arg, GROW, 5), delta_a(0.5), shape_max(2.5), grow_above_max(1),
    as_published(0), steps(0), void_vertices(0), cells_above_max(0), packing_last(-1.0),
    compaction(0.0)
{
  bool shape_max_given = false;
  parse_keywords(3, narg, arg, [&](const char *key, const char *value) {
    auto number = [&](double lo, bool lo_open) {
      const double v = utils::numeric(FLERR, value, false, lmp);
      if (lo_open ? !(v > lo) : !(v >= lo))
        error->all(FLERR, "Fix mesophyll/grow {} must be {} {}, got {}", key,
                   lo_open ? ">" : ">=", lo, value);
      return v;
    };
    if (strcmp(key, "delta_a") == 0)
      delta_a = number(0.0, false);
    else if (strcmp(key, "calA_max") == 0) {
      shape_max = number(0.0, true);
      shape_max_given = true;
    } else if (strcmp(key, "rules") == 0) {
      // code: isometric growth above calA_max 2.5; paper: none above 3; published: code, with
      // the published code's run lengths, drift past theta0_min and in-place smoothing
      const bool paper = strcmp(value, "paper") == 0;
      as_published = strcmp(value, "published") == 0;
      if (!paper && !as_published && strcmp(value, "code") != 0)
        error->all(FLERR,
                   "Fix mesophyll/grow rules must be 'code', 'paper' or 'published', got '{}'",
                   value);
      grow_above_max = paper ? 0 : 1;
      if (!shape_max_given) shape_max = paper ? 3.0 : 2.5;
    } else
      return rates.read(lmp, style, key, value);
    return true;
  });
}

void FixMesophyllGrow::init()
{
  FixDPolyStage::init();
  rates.check_box(lmp, style, id);
}

/* ----------------------------------------------------------------------
   the Howto's growth rule (paper S3), with dl_std = (p/a) delta_a / 2 from the current p and a:
   void-facing vertex i (no adhesive bond), in a void run of length b_v, cell mean run length
   <b_v>:  dl_i = (lambda dl_std / n) [(1 - c_L) + c_L (<b_v> - b_v)/p]   if calA < calA_max,
           dl_i = dl_std/n (rules code) or 0 (rules paper)                 otherwise;
   dl_i is added to the l0 of both segments at i. A run's length is the boundary it exposes: each
   of its vertices contributes half of each of its two segments. theta0 of void vertices drops by
   c_B dl_std/n, not below theta0_min; then every theta0 relaxes toward its ring neighbours by
   (dl_std/n) times the two differences, all from the values before smoothing. rules published
   (isometric above calA_max, as code) changes three things to the published code's forms, in
   grow_ring(): run lengths, the drift at theta0_min, and an in-place smoothing sweep.
------------------------------------------------------------------------- */

int FixMesophyllGrow::act()
{
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix mesophyll/grow");
  const int nlocal = atom->nlocal;
  double **x = atom->x;

  std::vector<VertexGrowth> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int j =
        DPoly::closest_neighbour(lmp, i, DPoly::ring_links(atom, i).next, "Fix mesophyll/grow");
    mine.push_back(
        {atom->tag[i], std::hypot(x[j][0] - x[i][0], x[j][1] - x[i][1]), state.preferred_angle[i]});
  }
  const std::vector<VertexGrowth> all = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::unordered_map<tagint, const VertexGrowth *> vertex;
  for (const auto &v : all) vertex[v.tag] = &v;

  record_packing();

  std::unordered_map<tagint, double> length_growth, new_angle;
  void_vertices = cells_above_max = 0;
  for (int c = 0; c < cells->ncells(); c++) grow_ring(c, vertex, length_growth, new_angle);

  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const tagint t = atom->tag[i];
    state.preferred_length[i] += length_growth[t];
    state.preferred_angle[i] = new_angle[t];
    const double a0 = state.preferred_area[i];
    if (rates.scale_diameters) state.diameter[i] *= sqrt((a0 + delta_a) / a0);
    state.preferred_area[i] = a0 + delta_a;
  }
  steps++;
  return STATE;    // preferred values and diameters change, the topology does not
}

void FixMesophyllGrow::grow_ring(int c, std::unordered_map<tagint, const VertexGrowth *> &vertex,
                                 std::unordered_map<tagint, double> &length_growth,
                                 std::unordered_map<tagint, double> &new_angle)
{
  // rules published sweeps each ring in place from its smallest ID (the published code's first
  // vertex of the cell, in the order tools convert tissues), whatever vertex the hub starts at
  std::vector<tagint> ring = cells->ring(c);
  if (as_published)
    std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
  const int n = (int) ring.size();
  const double p = cells->perimeter(c), a = cells->area(c);
  const double dl_std = 0.5 * (p / a) * delta_a;
  const double shape = DPoly::shape_index(p, a);
  if (shape >= shape_max) cells_above_max++;
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  auto is_void = [&](int k) {
    return adhesion.void_facing(ring[k]);
  };
  auto segment = [&](int k) {
    return vertex[ring[(k + n) % n]]->segment;
  };

  // void runs, each with the boundary length it exposes; a fully void ring is one run of length p
  std::vector<double> run_length(n, 0.0), runs;
  int first_bonded = 0;
  while (first_bonded < n && is_void(first_bonded)) first_bonded++;
  if (first_bonded == n) {
    run_length.assign(n, p);
    runs.push_back(p);
  } else {
    for (int step = 1; step <= n;) {
      const int k = (first_bonded + step) % n;
      if (!is_void(k)) {
        step++;
        continue;
      }
      std::vector<int> members;
      for (int m = k; is_void(m); m = (m + 1) % n) members.push_back(m);
      // the published code counts the two segments that end the run in full
      double length = as_published ? segment(members.front() - 1) : 0.0;
      for (int q : members)
        length += as_published ? segment(q) : 0.5 * (segment(q - 1) + segment(q));
      for (int q : members) run_length[q] = length;
      runs.push_back(length);
      step += (int) members.size();
    }
  }
  double mean_run = 0.0;
  for (double r : runs) mean_run += r / runs.size();
  // The published code measures a vertex's run by walking forward from the bonded vertex before
  // it while this vertex or the next is void-facing (meso2D::voidPerimeterSegment()): that walk
  // goes on across a single bonded vertex into the next run, so runs one bonded vertex apart
  // count as one there (but not in the mean, meso2D::totalVoidPerimeter()).
  if (as_published && first_bonded < n)
    for (int k = 0; k < n; k++) {
      if (!is_void(k)) continue;
      int start = k;
      while (is_void(start)) start = (start + n - 1) % n;
      double length = 0.0;
      int g = start;
      do {
        length += segment(g);
        g = (g + 1) % n;
      } while ((is_void((g + 1) % n) || is_void(g)) && g != start);
      run_length[k] = length;
    }

  std::vector<double> dl(n, 0.0), angle(n);
  for (int k = 0; k < n; k++) angle[k] = vertex[ring[k]]->preferred_angle;
  const double theta0_min = rates.theta0_min;
  const double drift = rates.c_bending * dl_std / n, smoothing = dl_std / n;
  auto drift_down = [&](int k) {
    if (!as_published)
      angle[k] = DPoly::drifted_angle(angle[k], drift, theta0_min);
    else    // the published code: the full step from above the bound, to the bound from below
      angle[k] = angle[k] > theta0_min ? angle[k] - drift : theta0_min;
  };
  // theta0 at k relaxed toward its ring neighbours' current values
  auto relaxed = [&](int k) {
    const int before = (k + n - 1) % n, after = (k + 1) % n;
    return DPoly::relaxed_angle(angle[k], smoothing,
                                (angle[after] - angle[k]) + (angle[before] - angle[k]));
  };
  for (int k = 0; k < n; k++) {
    if (is_void(k)) {
      void_vertices++;
      if (shape < shape_max)
        dl[k] = DPoly::void_length_growth(rates.lambda, dl_std, n, rates.c_length, mean_run,
                                          run_length[k], p);
      else
        dl[k] = grow_above_max ? dl_std / n : 0.0;
      drift_down(k);
    }
    // the published code smooths in place, vertex by vertex in ring order from the cell's first
    // (smallest ID): the next vertex is still undrifted, the previous one done (but at the ends)
    if (as_published) angle[k] = relaxed(k);
  }
  // otherwise all from the drifted values (angle is not changed below)
  for (int k = 0; k < n; k++) {
    length_growth[ring[k]] = dl[k] + dl[(k + 1) % n];    // segment k -> k+1 touches both
    new_angle[ring[k]] = as_published ? angle[k] : relaxed(k);
  }
}

/* ----------------------------------------------------------------------
   packing fraction phi = sum of cell areas / box area at the minimum just reached, and the
   cumulative compaction delta_phi_plus = sum of the increases of phi from minimum to minimum
------------------------------------------------------------------------- */

void FixMesophyllGrow::record_packing()
{
  double cell_area = 0.0;
  for (int c = 0; c < cells->ncells(); c++) cell_area += cells->area(c);
  const double packing = cell_area / (domain->xprd * domain->yprd);
  if (packing_last >= 0.0) compaction += std::max(0.0, packing - packing_last);
  packing_last = packing;
}

// growth steps, void-facing vertices, cells at or above calA_max, phi at the last minimum,
// cumulative compaction delta_phi_plus
double FixMesophyllGrow::compute_vector(int n)
{
  const double values[] = {(double) steps, (double) void_vertices, (double) cells_above_max,
                           packing_last, compaction};
  return values[n];
}

std::vector<double> FixMesophyllGrow::restart_state() const
{
  return {(double) steps, packing_last, compaction};
}

bool FixMesophyllGrow::restore_state(const std::vector<double> &state)
{
  if (state.size() != 3) return false;
  steps = (bigint) state[0];
  packing_last = state[1];
  compaction = state[2];
  return true;
}
