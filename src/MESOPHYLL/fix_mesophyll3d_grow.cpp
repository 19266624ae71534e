/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_mesophyll3d_grow.h"

#include "atom.h"
#include "domain.h"
#include "dpoly3d_void_patches.h"
#include "dpoly_adhesion.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly3d_cells.h"
#include "math_extra.h"
#include "modify.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace {
const char *STYLE = "Fix mesophyll3d/grow";
using Edge = std::pair<tagint, tagint>;    // (lower ID, higher ID)
}    // namespace

FixMesophyll3dGrow::FixMesophyll3dGrow(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyStage(lmp, narg, arg, GROW, 3), cells3d(nullptr), delta_volume(-1.0), steps(0),
    void_vertices(0), void_edges(0)
{
  parse_keywords(3, narg, arg, [&](const char *key, const char *value) {
    if (strcmp(key, "delta_V") == 0) {
      delta_volume = utils::numeric(FLERR, value, false, lmp);
      if (!(delta_volume >= 0.0) || !std::isfinite(delta_volume))
        error->all(FLERR, "{} delta_V must be finite and >= 0, got {}", STYLE, value);
      return true;
    }
    return rates.read(lmp, style, key, value);
  });
  // a cell's volume has no natural unit as the 2d model's a0 = 1 does, so the step is explicit
  if (delta_volume < 0.0)
    error->all(FLERR,
               "{} needs delta_V, the volume added to every cell's v0 per growth step (the 2d "
               "protocol's delta_a = 0.5 is half the initial a0; half the initial v0 is its "
               "counterpart)",
               STYLE);
}

void FixMesophyll3dGrow::init()
{
  // before the base's check, which would accept the 2d hub too
  const auto hubs = modify->get_fix_by_style("^dpoly3d/cells$");
  if (hubs.empty())
    error->all(FLERR,
               "{} grows polyhedra: it needs fix dpoly3d/cells (2d cells grow with fix "
               "mesophyll/grow)",
               STYLE);
  FixDPolyStage::init();
  rates.check_box(lmp, style, id);
  bind(dynamic_cast<DPoly::CellHub *>(hubs.front()));
}

// the 3d hub and the per-vertex and per-edge state this fix reads and writes
void FixMesophyll3dGrow::bind(DPoly::CellHub *cell_hub)
{
  cells3d = dynamic_cast<FixDPoly3dCells *>(cell_hub);
  if (!cells3d)
    error->all(FLERR,
               "{} grows polyhedra: it needs fix dpoly3d/cells (2d cells grow with fix "
               "mesophyll/grow)",
               STYLE);
  vertex_state.find(atom, error, STYLE);
  edge_values.find(atom, error, STYLE);
}

/* ----------------------------------------------------------------------
   collective: every edge (on its lower-ID vertex) with its current length and theta0, and every
   face with its area, on every rank, sorted by IDs so that sums run in the same order on any
   number of ranks
------------------------------------------------------------------------- */

void FixMesophyll3dGrow::gather_surfaces(std::vector<EdgeGrowth> &edges,
                                         std::vector<FaceArea> &faces)
{
  double **x = atom->x;
  edge_values.fetch(atom, error, STYLE);
  auto image_of = [&](int i, tagint partner) {
    const int j = domain->closest_image(i, atom->map(partner));
    if (j < 0)
      error->one(FLERR,
                 "{}: vertex {}, a neighbour of vertex {}, is not on this rank: set "
                 "comm_modify cutoff above the longest edge",
                 STYLE, partner, atom->tag[i]);
    return j;
  };
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const tagint self = atom->tag[i];
    for (int k = 0; k < edge_values.columns(); k++) {
      const tagint partner = edge_values.partner(i, k);
      if (partner == 0) continue;
      const int j = image_of(i, partner);
      double d[3];
      for (int m = 0; m < 3; m++) d[m] = x[j][m] - x[i][m];
      edges.push_back({self, partner, atom->molecule[i], sqrt(MathExtra::dot3(d, d)),
                       edge_values.preferred_angle(i, k)});
    }
    for (int m = 0; m < atom->num_angle[i]; m++) {
      if (atom->angle_atom2[i][m] != self) continue;    // a face once, on its middle vertex
      const tagint a = atom->angle_atom1[i][m], c = atom->angle_atom3[i][m];
      const int ja = image_of(i, a), jc = image_of(i, c);
      double u[3], w[3], n[3];
      for (int d = 0; d < 3; d++) {
        u[d] = x[ja][d] - x[i][d];
        w[d] = x[jc][d] - x[i][d];
      }
      MathExtra::cross3(u, w, n);
      faces.push_back({a, self, c, 0.5 * sqrt(MathExtra::dot3(n, n))});
    }
  }
  edges = DPoly::gather_on_all_ranks(std::move(edges), world);
  faces = DPoly::gather_on_all_ranks(std::move(faces), world);
  std::sort(edges.begin(), edges.end(), [](const EdgeGrowth &p, const EdgeGrowth &q) {
    return std::tie(p.lo, p.hi) < std::tie(q.lo, q.hi);
  });
  std::sort(faces.begin(), faces.end(), [](const FaceArea &p, const FaceArea &q) {
    return std::tie(p.a, p.b, p.c) < std::tie(q.a, q.b, q.c);
  });
}

/* ----------------------------------------------------------------------
   one growth step (doc/Howto_polyhedra.rst, "Growth"). Per cell, from its current volume V,
   total edge length L and E edges, dl_std = (L/V) delta_V/3: the growth of L under isometric
   growth of the volume by delta_V (dl_std/E per edge), as the 2d dl_std = (p/a) delta_a/2 is
   that of the perimeter. A void-facing vertex i, in a void patch of area A_i (cell mean <A>,
   surface S), grows every edge at it by
     dl_i = (lambda dl_std/E) [(1 - c_L) + c_L (<A> - A_i)/S]
   so an edge grows by dl_i + dl_j (the 2d rule, where each void vertex grows both its
   segments). theta0 of an edge whose two ends are void-facing drops by c_B dl_std/E, not below
   theta0_min; then every theta0 relaxes toward the four edges of its two faces by
   (dl_std/E) (2/4) times the sum of their differences (the weight of the 2d ring's two
   neighbours), all from the drifted values. Then v0 += delta_V and sigma *= cbrt(v0'/v0).
------------------------------------------------------------------------- */

int FixMesophyll3dGrow::act()
{
  // the hub that attached this stage, not the one init() found: 'run N pre no' skips init()
  bind(hub);
  std::vector<EdgeGrowth> edges;
  std::vector<FaceArea> faces;
  gather_surfaces(edges, faces);

  const int ncells = cells3d->ncells();
  std::vector<double> edge_length(ncells, 0.0), surface(ncells, 0.0), dl_std(ncells, 0.0);
  std::vector<int> edge_count(ncells, 0);
  std::map<tagint, int> cell_of;    // vertex -> cell index
  std::map<Edge, int> edge_index;
  for (size_t e = 0; e < edges.size(); e++) {
    const int c = cells3d->cell_index(edges[e].cell);
    if (c < 0)
      error->all(FLERR, "{}: vertex {} belongs to molecule {}, which is not a cell of fix {}",
                 STYLE, edges[e].lo, edges[e].cell, cells3d->id);
    edge_length[c] += edges[e].length;
    edge_count[c]++;
    cell_of[edges[e].lo] = cell_of[edges[e].hi] = c;
    edge_index[Edge(edges[e].lo, edges[e].hi)] = (int) e;
  }
  std::map<tagint, double> exposed;    // a third of the area of each face at a vertex
  for (const auto &f : faces) {
    for (tagint t : {f.a, f.b, f.c}) exposed[t] += f.area / 3.0;
    surface[cell_of.at(f.b)] += f.area;
  }
  for (int c = 0; c < ncells; c++) {
    const double volume = cells3d->volume(c);
    // a tangled or inverted cell has no isometric growth to measure against
    if (!(volume > 0.0) || !std::isfinite(volume) || !std::isfinite(edge_length[c]))
      error->all(FLERR,
                 "{}: cell {} encloses the volume {} with edges of total length {}: growth "
                 "needs a positive, finite volume",
                 STYLE, cells3d->cell_id(c), volume, edge_length[c]);
    dl_std[c] = edge_length[c] / volume * delta_volume / 3.0;
  }

  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  DPoly3d::VoidPatches patches;
  for (const auto &v : exposed)
    if (adhesion.void_facing(v.first))
      patches.add_vertex(v.first, cells3d->cell_id(cell_of.at(v.first)), v.second);
  for (const auto &e : edges) patches.add_edge(e.lo, e.hi);

  std::map<tagint, double> vertex_growth;    // dl_i of every void-facing vertex
  for (const auto &v : exposed) {
    if (!adhesion.void_facing(v.first)) continue;
    const int c = cell_of.at(v.first);
    vertex_growth[v.first] = DPoly::void_length_growth(
        rates.lambda, dl_std[c], edge_count[c], rates.c_length,
        patches.mean_patch_area(cells3d->cell_id(c)), patches.patch_area(v.first), surface[c]);
  }
  void_vertices = (int) vertex_growth.size();

  // theta0: drift at void-facing edges, then smoothing over the edges of each edge's two faces
  std::vector<double> angle(edges.size());
  void_edges = 0;
  for (size_t e = 0; e < edges.size(); e++) {
    angle[e] = edges[e].preferred_angle;
    if (vertex_growth.count(edges[e].lo) && vertex_growth.count(edges[e].hi)) {
      const int c = cell_of.at(edges[e].lo);
      angle[e] = DPoly::drifted_angle(angle[e], rates.c_bending * dl_std[c] / edge_count[c],
                                      rates.theta0_min);
      void_edges++;
    }
  }
  std::vector<std::vector<int>> neighbours(edges.size());
  for (const auto &f : faces) {
    const tagint corner[3] = {f.a, f.b, f.c};
    int side[3];
    for (int k = 0; k < 3; k++) {
      const tagint u = corner[k], v = corner[(k + 1) % 3];
      side[k] = edge_index.at(u < v ? Edge(u, v) : Edge(v, u));
    }
    for (int k = 0; k < 3; k++)
      for (int other = 1; other < 3; other++) neighbours[side[k]].push_back(side[(k + other) % 3]);
  }
  std::vector<double> new_angle(edges.size());
  for (size_t e = 0; e < edges.size(); e++) {
    const int c = cell_of.at(edges[e].lo);
    double differences = 0.0;
    for (int f : neighbours[e]) differences += angle[f] - angle[e];
    new_angle[e] = DPoly::relaxed_angle(angle[e], dl_std[c] / edge_count[c],
                                        2.0 / neighbours[e].size() * differences);
  }

  // the owned vertices' values; the hub sends them to the ghost atoms
  const DPoly3d::VertexState state = vertex_state.get(atom, error, STYLE);
  edge_values.fetch(atom, error, STYLE);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const tagint self = atom->tag[i];
    for (int k = 0; k < edge_values.columns(); k++) {
      const tagint partner = edge_values.partner(i, k);
      if (partner == 0) continue;
      const int e = edge_index.at(Edge(self, partner));
      double growth = 0.0;
      for (tagint end : {self, partner}) {
        const auto found = vertex_growth.find(end);
        if (found != vertex_growth.end()) growth += found->second;
      }
      edge_values.set_preferred_length(i, k, edge_values.preferred_length(i, k) + growth);
      edge_values.set_preferred_angle(i, k, new_angle[e]);
    }
    const double v0 = state.preferred_volume[i];
    if (rates.scale_diameters) state.diameter[i] *= cbrt((v0 + delta_volume) / v0);
    state.preferred_volume[i] = v0 + delta_volume;
  }
  steps++;
  return STATE;    // preferred values and diameters change, the topology does not
}

// growth steps, void-facing vertices, void-facing edges (both ends void-facing)
double FixMesophyll3dGrow::compute_vector(int n)
{
  const double values[] = {(double) steps, (double) void_vertices, (double) void_edges};
  return values[n];
}

std::vector<double> FixMesophyll3dGrow::restart_state() const
{
  return {(double) steps};
}

bool FixMesophyll3dGrow::restore_state(const std::vector<double> &state)
{
  if (state.size() != 1) return false;
  steps = (bigint) state[0];
  return true;
}
