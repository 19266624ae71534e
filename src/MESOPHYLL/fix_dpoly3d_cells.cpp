/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly3d_cells.h"

#include "angle.h"
#include "atom.h"
#include "atom_vec.h"
#include "bond.h"
#include "comm.h"
#include "dihedral.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "math_extra.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <utility>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathExtra::cross3;
using MathExtra::dot3;

namespace {
const char *STYLE = "Fix dpoly3d/cells";

// What one rank tells the others when the surfaces are checked (whole-system tables, so that
// every rank reaches the same verdict).
struct VertexRecord {
  tagint tag, molecule;
  double diameter, preferred_volume;
};
struct FaceRecord {
  tagint a, b, c;
};
struct HingeRecord {
  tagint a, b, c, d;
};
struct EdgeRecord {
  tagint lo, hi;
};
using Edge = std::pair<tagint, tagint>;    // (lower ID, higher ID)
EdgeRecord edge(tagint u, tagint v)
{
  return u < v ? EdgeRecord{u, v} : EdgeRecord{v, u};
}
// a gathered table of edges as pairs
std::vector<Edge> as_pairs(const std::vector<EdgeRecord> &records)
{
  std::vector<Edge> pairs;
  for (const auto &r : records) pairs.emplace_back(r.lo, r.hi);
  return pairs;
}
}    // namespace

// scalar: the volume energy; vector: number of cells, total volume, total surface area
FixDPoly3dCells::FixDPoly3dCells(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyHub(lmp, narg, arg, "volume"), volume_eps(1.0), volume_energy(0.0)
{
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "eps_v") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix dpoly3d/cells eps_v", error);
      volume_eps = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(volume_eps >= 0.0) || !std::isfinite(volume_eps))
        error->all(FLERR, "Fix dpoly3d/cells eps_v must be finite and >= 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Unknown fix dpoly3d/cells keyword: {}", arg[iarg]);
  }

  comm_reverse = 3;    // volume forces on ghost atoms
}

void FixDPoly3dCells::check_requirements()
{
  if (domain->dimension != 3)
    error->all(FLERR, "{} needs a 3d simulation (dimension 3); 2d cells use fix dpoly/cells",
               STYLE);
  if (!atom->molecule_flag)
    error->all(FLERR, "{} needs molecule IDs (e.g. atom_style molecular): each cell is a molecule",
               STYLE);
  if (!atom->avec->bonds_allow || !atom->avec->angles_allow || !atom->avec->dihedrals_allow)
    error->all(FLERR,
               "{} needs bonds (edges), angles (faces) and dihedrals (hinges), e.g. atom_style "
               "molecular",
               STYLE);
  if (!force->angle_match("zero"))
    error->all(FLERR,
               "{} needs angle_style zero for the faces: a face only bounds the volume and must "
               "carry no energy of its own",
               STYLE);
  if (!force->bond_match("dpoly3d/edge"))
    error->all(FLERR, "{} needs bond_style dpoly3d/edge for the edges", STYLE);
  if (!force->dihedral_match("dpoly3d/hinge"))
    error->all(FLERR, "{} needs dihedral_style dpoly3d/hinge for the hinges", STYLE);
  vertex_state.find(atom, error, STYLE);
  DPoly3d::EdgeValues edges;
  edges.find(atom, error, STYLE);
}

double *FixDPoly3dCells::vertex_diameters()
{
  return vertex_state.get(atom, error, STYLE).diameter;
}

std::vector<tagint> FixDPoly3dCells::surface_neighbours(tagint atom) const
{
  const auto found = edge_partners.find(atom);
  if (found == edge_partners.end()) not_a_vertex(atom);
  return found->second;
}

void FixDPoly3dCells::post_force(int vflag)
{
  measure_cells();
  apply_volume_forces(vflag);
}

/* ----------------------------------------------------------------------
   collective: gather every vertex, face, edge bond, hinge and edge record; check that each cell
   is one closed, consistently oriented surface of sphere topology whose every edge has exactly
   one dpoly3d/edge bond, one hinge on its two faces and one set of preferred values
------------------------------------------------------------------------- */

void FixDPoly3dCells::read_cells()
{
  const DPoly3d::VertexState state = vertex_state.get(atom, error, STYLE);
  DPoly3d::EdgeValues edge_values;
  edge_values.fetch(atom, error, STYLE);
  Bond *edge_style = force->bond_match("dpoly3d/edge");
  Dihedral *hinge_style = force->dihedral_match("dpoly3d/hinge");
  Angle *face_style = force->angle_match("zero");
  const int newton_bond = force->newton_bond;
  tagint energetic_face = 0;    // middle atom of a face whose angle type is not angle_style zero

  std::vector<VertexRecord> vertices;
  std::vector<FaceRecord> faces;
  std::vector<EdgeRecord> bonds, valued;
  std::vector<HingeRecord> hinges;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const tagint self = atom->tag[i];
    vertices.push_back({self, atom->molecule[i], state.diameter[i], state.preferred_volume[i]});
    for (int m = 0; m < atom->num_angle[i]; m++)
      if (atom->angle_atom2[i][m] == self) {
        faces.push_back({atom->angle_atom1[i][m], self, atom->angle_atom3[i][m]});
        const int type = atom->angle_type[i][m];
        if (type <= 0 || !face_style->setflag[type])
          energetic_face = std::max(energetic_face, self);
      }
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      const tagint partner = atom->bond_atom[i][m];
      if (type <= 0 || !edge_style->setflag[type]) continue;
      if (newton_bond || self < partner) bonds.push_back(edge(self, partner));
    }
    for (int m = 0; m < atom->num_dihedral[i]; m++) {
      const int type = atom->dihedral_type[i][m];
      if (type <= 0 || !hinge_style->setflag[type] || atom->dihedral_atom2[i][m] != self) continue;
      hinges.push_back({atom->dihedral_atom1[i][m], self, atom->dihedral_atom3[i][m],
                        atom->dihedral_atom4[i][m]});
    }
    for (int k = 0; k < edge_values.columns(); k++) {
      const tagint partner = edge_values.partner(i, k);
      if (partner == 0) continue;
      if (partner <= self)
        error->one(FLERR,
                   "{}: vertex {} lists {} in its i2_edge columns; an edge's values belong to "
                   "its lower-ID vertex, so a vertex lists only partners with higher IDs",
                   STYLE, self, partner);
      if (!(std::isfinite(edge_values.preferred_length(i, k)) &&
            edge_values.preferred_length(i, k) > 0.0))
        error->one(FLERR, "{}: edge {}-{} has l0 = {}; it must be finite and > 0", STYLE, self,
                   partner, edge_values.preferred_length(i, k));
      if (!std::isfinite(edge_values.preferred_angle(i, k)))
        error->one(FLERR, "{}: edge {}-{} has theta0 = {}; it must be finite", STYLE, self, partner,
                   edge_values.preferred_angle(i, k));
      valued.push_back(edge(self, partner));
    }
  }
  tagint energetic_any = 0;
  MPI_Allreduce(&energetic_face, &energetic_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (energetic_any)
    error->all(FLERR,
               "{}: a face (angle) centred on vertex {} has an angle type of another style than "
               "zero; faces must be angles of angle_style zero (in hybrid: of its zero sub-style)",
               STYLE, energetic_any);
  vertices = DPoly::gather_on_all_ranks(std::move(vertices), world);
  faces = DPoly::gather_on_all_ranks(std::move(faces), world);
  bonds = DPoly::gather_on_all_ranks(std::move(bonds), world);
  hinges = DPoly::gather_on_all_ranks(std::move(hinges), world);
  valued = DPoly::gather_on_all_ranks(std::move(valued), world);
  if (vertices.empty())
    error->all(FLERR, "{}: group {} holds no vertices", STYLE, group->names[igroup]);

  // vertices and cells
  std::map<tagint, tagint> molecule_of;
  std::map<tagint, std::vector<const VertexRecord *>> members;
  const char *hint = "set it in the Vertices section of the data file or with the set command";
  for (const auto &v : vertices) {
    if (v.molecule <= 0)
      error->all(FLERR,
                 "{}: vertex {} has molecule ID {}; each cell must be a molecule with ID > 0",
                 STYLE, v.tag, v.molecule);
    if (!(std::isfinite(v.diameter) && v.diameter > 0.0))
      error->all(FLERR, "{}: vertex {} has sigma = {}; it must be finite and > 0: {}", STYLE, v.tag,
                 v.diameter, hint);
    if (!(std::isfinite(v.preferred_volume) && v.preferred_volume > 0.0))
      error->all(FLERR, "{}: vertex {} has v0 = {}; it must be finite and > 0: {}", STYLE, v.tag,
                 v.preferred_volume, hint);
    molecule_of[v.tag] = v.molecule;
    members[v.molecule].push_back(&v);
  }
  cell_ids.clear();
  vertex_counts.clear();
  preferred_volumes.clear();
  for (const auto &m : members) {
    const VertexRecord *first = m.second.front();
    for (const VertexRecord *v : m.second)
      if (v->preferred_volume != first->preferred_volume)
        error->all(FLERR, "{}: cell {} has different v0 on vertices {} ({}) and {} ({})", STYLE,
                   m.first, first->tag, first->preferred_volume, v->tag, v->preferred_volume);
    cell_ids.push_back(m.first);
    vertex_counts.push_back((int) m.second.size());
    preferred_volumes.push_back(first->preferred_volume);
  }
  index_cells();

  // faces: each directed edge once, with its reverse in another face (closed and oriented)
  std::map<Edge, tagint> opposite;    // directed edge (u, v) of a face -> the face's third vertex
  std::map<tagint, int> face_counts;
  std::set<tagint> on_faces;
  for (const auto &f : faces) {
    const tagint corner[3] = {f.a, f.b, f.c};
    for (tagint t : corner)
      if (!molecule_of.count(t) || molecule_of[t] != molecule_of[f.b])
        error->all(FLERR,
                   "{}: face (angle) {} {} {} joins vertices of different cells or outside group "
                   "{}; a face's three vertices belong to one cell",
                   STYLE, f.a, f.b, f.c, group->names[igroup]);
    for (int k = 0; k < 3; k++) {
      const Edge directed(corner[k], corner[(k + 1) % 3]);
      if (!opposite.emplace(directed, corner[(k + 2) % 3]).second)
        error->all(FLERR,
                   "{}: the edge from vertex {} to {} runs the same way in two faces of cell {}; "
                   "each edge must belong to exactly two faces, ordered counter-clockwise from "
                   "outside",
                   STYLE, directed.first, directed.second, molecule_of[f.b]);
      on_faces.insert(corner[k]);
    }
    face_counts[molecule_of[f.b]]++;
  }
  std::map<tagint, int> edge_counts;
  edge_partners.clear();
  for (const auto &o : opposite) {
    const Edge &d = o.first;
    if (!opposite.count(Edge(d.second, d.first)))
      error->all(FLERR,
                 "{}: the edge {}-{} of cell {} belongs to one face only, or its two faces are "
                 "ordered the same way: a cell's surface must be closed and its faces ordered "
                 "counter-clockwise from outside",
                 STYLE, d.first, d.second, molecule_of[d.first]);
    if (d.first < d.second) edge_counts[molecule_of[d.first]]++;
    edge_partners[d.first].push_back(d.second);    // each directed edge once: both ends
  }
  for (const auto &v : vertices)
    if (!on_faces.count(v.tag))
      error->all(FLERR, "{}: vertex {} of cell {} is on no face (angle)", STYLE, v.tag, v.molecule);
  for (size_t c = 0; c < cell_ids.size(); c++) {
    const int nv = vertex_counts[c], ne = edge_counts[cell_ids[c]], nf = face_counts[cell_ids[c]];
    if (nv - ne + nf != 2)
      error->all(FLERR,
                 "{}: cell {} has {} vertices, {} edges and {} faces: V - E + F = {}, not 2; a "
                 "cell must be one closed surface of sphere topology",
                 STYLE, cell_ids[c], nv, ne, nf, nv - ne + nf);
  }

  // every edge: one dpoly3d/edge bond, one hinge on its two faces, one set of values
  auto check_once = [&](const std::vector<Edge> &found, const char *what, const char *fix) {
    std::map<Edge, int> count;
    for (const Edge &e : found) {
      if (!opposite.count(e))
        error->all(FLERR, "{}: {} {}-{} is not an edge of a face (angle) of a cell", STYLE, what,
                   e.first, e.second);
      count[e]++;
    }
    for (const auto &o : opposite) {
      if (o.first.first > o.first.second) continue;
      const auto n = count.find(o.first);
      const int times = n == count.end() ? 0 : n->second;
      if (times != 1)
        error->all(FLERR, "{}: edge {}-{} of cell {} has {} {}, not one; {}", STYLE, o.first.first,
                   o.first.second, molecule_of[o.first.first], times, what, fix);
    }
  };
  check_once(as_pairs(bonds), "dpoly3d/edge bonds",
             "keep exactly one bond of a dpoly3d/edge type per edge in the Bonds section");
  check_once(as_pairs(valued), "sets of preferred values (i2_edge columns)",
             "the edge's lower-ID vertex lists the other in exactly one i2_edge column");
  std::vector<EdgeRecord> hinge_edges;
  for (const auto &h : hinges) {
    const auto first = opposite.find(Edge(h.b, h.c)), second = opposite.find(Edge(h.c, h.b));
    if (first == opposite.end() || second == opposite.end() || first->second != h.a ||
        second->second != h.d)
      error->all(FLERR,
                 "{}: hinge (dihedral) {} {} {} {} does not join two faces: its faces must be "
                 "the angles ({} {} {}) and ({} {} {}), in any rotation",
                 STYLE, h.a, h.b, h.c, h.d, h.a, h.b, h.c, h.c, h.b, h.d);
    hinge_edges.push_back(edge(h.b, h.c));
  }
  check_once(as_pairs(hinge_edges), "dpoly3d/hinge dihedrals",
             "keep exactly one hinge a b c d per edge b-c in the Dihedrals section");

  volumes.assign(ncells(), 0.0);
  surface_areas.assign(ncells(), 0.0);
  volume_slopes.assign(ncells(), 0.0);
}

// every face is visited once, on the rank that owns its middle vertex b, with a and c at the
// images nearest to b
template <typename Visit> void FixDPoly3dCells::for_each_face(int i, Visit &&visit)
{
  for (int m = 0; m < atom->num_angle[i]; m++) {
    if (atom->angle_atom2[i][m] != atom->tag[i]) continue;
    const tagint a = atom->angle_atom1[i][m], c = atom->angle_atom3[i][m];
    const int ja = domain->closest_image(i, atom->map(a));
    const int jc = domain->closest_image(i, atom->map(c));
    if (ja < 0 || jc < 0)
      error->one(FLERR,
                 "{}: vertex {} of the face {} {} {} is not on this rank: set comm_modify cutoff "
                 "above the longest edge",
                 STYLE, ja < 0 ? a : c, a, atom->tag[i], c);
    visit(ja, jc);
  }
}

/* ----------------------------------------------------------------------
   collective: a face's wing vertices, at the images nearest to its middle vertex, must be where
   the image flags put them, or the volume (on unwrapped positions) and the forces (on nearest
   images) describe different surfaces
------------------------------------------------------------------------- */

void FixDPoly3dCells::check_nearest_images()
{
  double **x = atom->x;
  const double tolerance = 1.0e-8 * (domain->xprd + domain->yprd + domain->zprd);
  tagint broken = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for_each_face(i, [&](int ja, int jc) {
      for (int j : {ja, jc})
        for (int d = 0; d < 3; d++)
          if (fabs(unwrapped[3 * i + d] + x[j][d] - x[i][d] - unwrapped[3 * j + d]) > tolerance)
            broken = std::max(broken, atom->tag[i]);
    });
  }
  tagint broken_any = 0;
  MPI_Allreduce(&broken, &broken_any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (broken_any)
    error->all(FLERR,
               "{}: at step {}, a face around vertex {} is not whole: a neighbour's nearest image "
               "is not where its image flags put it. Keep edges shorter than half the box and the "
               "communication cutoff, and give each cell consistent image flags",
               STYLE, update->ntimestep, broken_any);
}

/* ----------------------------------------------------------------------
   collective: a preferred volume far below the actual one makes (V/V0 - 1)^2 overflow; a cell
   whose faces run clockwise from outside encloses a negative volume
------------------------------------------------------------------------- */

void FixDPoly3dCells::check_measured_cells()
{
  for (int c = 0; c < ncells(); c++)
    if (!std::isfinite(DPoly::area_law(volume_eps, volumes[c], preferred_volumes[c]).energy))
      error->all(FLERR,
                 "{}: cell {} has v0 = {} for a volume of {:.8g}: its volume term (V/V0 - 1)^2 "
                 "is not finite; give v0 a value of the order of the cell's volume",
                 STYLE, cell_ids[c], preferred_volumes[c], volumes[c]);
  for (int c = 0; c < ncells(); c++)
    if (!(volumes[c] > 0.0))
      error->all(FLERR,
                 "{}: cell {} encloses the volume {:.8g} <= 0; its faces (angles a b c) must run "
                 "counter-clockwise seen from outside the cell",
                 STYLE, cell_ids[c], volumes[c]);
}

/* ----------------------------------------------------------------------
   collective: V = (1/6) sum over faces (a, b, c) of x_a . (x_b x x_c) and the surface area, each
   face once, on the rank that owns its middle vertex b, with b unwrapped and a and c at the
   images nearest to b (divergence theorem; independent of the origin for a closed surface)
------------------------------------------------------------------------- */

void FixDPoly3dCells::measure_cells()
{
  double **x = atom->x;
  std::vector<double> local(2 * (size_t) ncells(), 0.0), global(2 * (size_t) ncells(), 0.0);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = cell_index(atom->molecule[i]);
    if (c < 0)
      error->one(FLERR,
                 "{}: vertex {} belongs to molecule {}, which was not a cell when the run "
                 "started",
                 STYLE, atom->tag[i], atom->molecule[i]);
    double pb[3];
    domain->unmap(x[i], atom->image[i], pb);
    for_each_face(i, [&](int ja, int jc) {
      double u[3], w[3], n[3];
      for (int d = 0; d < 3; d++) {
        u[d] = x[ja][d] - x[i][d];
        w[d] = x[jc][d] - x[i][d];
      }
      cross3(w, u, n);    // x_a . (x_b x x_c) = x_b . ((x_c - x_b) x (x_a - x_b))
      local[2 * c] += dot3(pb, n) / 6.0;
      local[2 * c + 1] += 0.5 * sqrt(dot3(n, n));
    });
  }
  MPI_Allreduce(local.data(), global.data(), 2 * ncells(), MPI_DOUBLE, MPI_SUM, world);
  for (int c = 0; c < ncells(); c++) {
    volumes[c] = global[2 * c];
    surface_areas[c] = global[2 * c + 1];
  }
}

/* ----------------------------------------------------------------------
   U = (eps_v/2)(V/V0 - 1)^2 per cell (the law of the 2d area term, DPoly::area_law, in V).
   dV/dx_a = (x_b x x_c)/6 and cyclically, added to owned and ghost atoms and summed onto the
   owners by a reverse communication. Under a deformation of the box V scales with its
   determinant, so the cell's virial is -V dU/dV on the diagonal (shared among its vertices).
------------------------------------------------------------------------- */

void FixDPoly3dCells::apply_volume_forces(int vflag)
{
  v_init(vflag);
  volume_energy = 0.0;
  for (int c = 0; c < ncells(); c++) {
    const DPoly::Law law = DPoly::area_law(volume_eps, volumes[c], preferred_volumes[c]);
    volume_energy += law.energy;
    volume_slopes[c] = law.first;
  }

  double **x = atom->x;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  volume_forces.assign(3 * (size_t) nall, 0.0);
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double scale = -volume_slopes[cell_index(atom->molecule[i])] / 6.0;
    double pb[3];
    domain->unmap(x[i], atom->image[i], pb);
    for_each_face(i, [&](int ja, int jc) {
      double pa[3], pc[3], fa[3], fb[3], fc[3];
      for (int d = 0; d < 3; d++) {
        pa[d] = pb[d] + x[ja][d] - x[i][d];
        pc[d] = pb[d] + x[jc][d] - x[i][d];
      }
      cross3(pb, pc, fa);
      cross3(pc, pa, fb);
      cross3(pa, pb, fc);
      for (int d = 0; d < 3; d++) {
        volume_forces[3 * ja + d] += scale * fa[d];
        volume_forces[3 * i + d] += scale * fb[d];
        volume_forces[3 * jc + d] += scale * fc[d];
      }
    });
  }
  comm->reverse_comm(this);

  double **f = atom->f;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int d = 0; d < 3; d++) f[i][d] += volume_forces[3 * i + d];
    if (evflag) {
      const int c = cell_index(atom->molecule[i]);
      const double w = -volumes[c] * volume_slopes[c] / vertex_counts[c];
      double v[6] = {w, w, w, 0.0, 0.0, 0.0};
      v_tally(i, v);
    }
  }
}

double FixDPoly3dCells::compute_scalar()
{
  return volume_energy;
}

double FixDPoly3dCells::compute_vector(int n)
{
  if (n == 0) return ncells();
  double total = 0.0;
  for (double value : (n == 1 ? volumes : surface_areas)) total += value;
  return total;
}

int FixDPoly3dCells::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) buf[m++] = volume_forces[3 * i + d];
  return m;
}

void FixDPoly3dCells::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) volume_forces[3 * list[k] + d] += buf[m++];
}

double FixDPoly3dCells::memory_usage()
{
  return sizeof(double) * (unwrapped.capacity() + volume_forces.capacity()) +
      (sizeof(double) * 4 + sizeof(int) + sizeof(tagint)) * cell_ids.capacity();
}
