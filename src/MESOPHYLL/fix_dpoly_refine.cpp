/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_refine.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_adhesion.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly_cells.h"
#include "force.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

using namespace LAMMPS_NS;

namespace {

// Preferred length of each half of a segment of length l and preferred length l0 such that the
// halves, at length l/2 each, carry the segment's tension (eps_l/l0)(l/l0 - 1): the solution of
// (1/h)(l/(2h) - 1) = (1/l0)(l/l0 - 1) for h. The stiffness eps_l cancels; h = l/2 when l = l0.
double half_preferred_length(double l, double l0)
{
  const double x = l / l0;
  return l / (1.0 + sqrt(1.0 + 2.0 * x * (x - 1.0)));
}

}    // namespace

FixDPolyRefine::FixDPolyRefine(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyStage(lmp, narg, arg, REFINE, 3), radii(3.0), cap(5.0), void_only(1), steps(0),
    added_total(0), added_last(0)
{
  parse_keywords(3, narg, arg, [&](const char *key, const char *value) {
    if (strcmp(key, "length") == 0) {
      radii = utils::numeric(FLERR, value, false, lmp);
      // below 2 radii (one diameter) the halves' vertices would overlap their new neighbours
      if (radii < 2.0)
        error->all(FLERR, "Fix dpoly/refine length must be >= 2 vertex radii, got {}", value);
    } else if (strcmp(key, "cap") == 0) {
      cap = utils::numeric(FLERR, value, false, lmp);
      if (cap < 1.0) error->all(FLERR, "Fix dpoly/refine cap must be >= 1, got {}", value);
    } else if (strcmp(key, "void") == 0)
      void_only = utils::logical(FLERR, value, false, lmp);
    else
      return false;
    return true;
  });
  if (!atom->molecule_flag || !atom->avec->bonds_allow || !atom->avec->angles_allow)
    error->all(FLERR, "Fix dpoly/refine needs an atom style with molecule IDs, bonds and angles");
}

void FixDPolyRefine::init()
{
  FixDPolyStage::init();
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Fix dpoly/refine needs an atom map (atom_modify map array or hash)");
}

/* ----------------------------------------------------------------------
   the hub rebuilds the special lists and ghosts and re-reads the rings afterwards
------------------------------------------------------------------------- */

int FixDPolyRefine::act()
{
  if (initial_vertices.empty())
    for (int c = 0; c < cells->ncells(); c++)
      initial_vertices[cells->cell_id(c)] = cells->vertex_count(c);

  std::vector<Split> splits = find_long_segments();
  choose_within_cap(splits);
  added_last = (int) splits.size();
  steps++;
  if (!splits.empty()) {
    insert_vertices(splits);
    rewire_topology(splits);
    added_total += (bigint) splits.size();
  }
  if (comm->me == 0)
    utils::logmesg(lmp, "fix dpoly/refine: step {}: {} vertices added, {} in all\n", steps,
                   added_last, added_total);
  return splits.empty() ? NOTHING : RINGS;
}

/* ----------------------------------------------------------------------
   every segment longer than 'radii' vertex radii (the mean of its two vertices), with both
   vertices void-facing unless 'void no'; the list is the same on every rank, in ID order
------------------------------------------------------------------------- */

std::vector<FixDPolyRefine::Split> FixDPolyRefine::find_long_segments()
{
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");
  const DPoly::AdhesionCounts &adhesion = DPoly::adhesion_counts(lmp);
  double **x = atom->x;
  std::vector<Split> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const DPoly::RingLinks links = DPoly::ring_links(atom, i);
    if (links.count != 1) continue;
    const int j = DPoly::closest_neighbour(lmp, i, links.next, "Fix dpoly/refine");
    const double length = std::hypot(x[j][0] - x[i][0], x[j][1] - x[i][1]);
    if (length <= radii * 0.25 * (state.diameter[i] + state.diameter[j])) continue;
    if (void_only && !(adhesion.void_facing(atom->tag[i]) && adhesion.void_facing(links.next)))
      continue;
    mine.push_back(
        {atom->tag[i], links.next, atom->molecule[i], 0, length, state.preferred_length[i]});
  }
  std::vector<Split> all = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::sort(all.begin(), all.end(), [](const Split &a, const Split &b) {
    return a.first < b.first;
  });
  return all;
}

/* ----------------------------------------------------------------------
   keep, per cell, the longest segments that fit under the cap; number the new vertices after the
   largest atom ID, in the order of the first vertex of their segments
------------------------------------------------------------------------- */

void FixDPolyRefine::choose_within_cap(std::vector<Split> &splits)
{
  std::stable_sort(splits.begin(), splits.end(), [](const Split &a, const Split &b) {
    return a.cell != b.cell ? a.cell < b.cell : a.length > b.length;
  });
  std::vector<Split> chosen;
  tagint cell = -1;
  int room = 0;
  for (const Split &s : splits) {
    if (s.cell != cell) {
      cell = s.cell;
      const int index = cells->cell_index(cell);
      const auto initial = initial_vertices.find(cell);
      const int limit = (int) floor(
          cap * (initial == initial_vertices.end() ? cells->vertex_count(index) : initial->second));
      room = limit - cells->vertex_count(index);
    }
    if (room > 0) {
      chosen.push_back(s);
      room--;
    }
  }
  std::sort(chosen.begin(), chosen.end(), [](const Split &a, const Split &b) {
    return a.first < b.first;
  });

  tagint largest = 0;
  for (int i = 0; i < atom->nlocal; i++) largest = std::max(largest, atom->tag[i]);
  tagint largest_all = 0;
  MPI_Allreduce(&largest, &largest_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  for (size_t k = 0; k < chosen.size(); k++) chosen[k].added = largest_all + 1 + (tagint) k;
  splits = chosen;
}

/* ----------------------------------------------------------------------
   the owner of each segment's first vertex creates the new vertex at the midpoint: straight
   (theta0 = 0), the mean diameter, the cell's a0, and with its first vertex the halves' l0
------------------------------------------------------------------------- */

void FixDPolyRefine::insert_vertices(const std::vector<Split> &splits)
{
  struct NewVertex {
    tagint tag, molecule;
    int type, mask;
    imageint image;
    double x[3], diameter, half_length, area;
    int first;    // local index of the segment's first vertex
  };
  // read what is needed from the ghosts before creating atoms overwrites them
  DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");
  double **x = atom->x;
  std::vector<NewVertex> created;
  for (const Split &s : splits) {
    const int i = atom->map(s.first);
    if (i < 0 || i >= atom->nlocal) continue;
    const int j = DPoly::closest_neighbour(lmp, i, s.second, "Fix dpoly/refine");
    NewVertex v;
    v.tag = s.added;
    v.molecule = atom->molecule[i];
    v.type = atom->type[i];
    v.mask = atom->mask[i];
    v.image = atom->image[i];
    for (int d = 0; d < 3; d++) v.x[d] = 0.5 * (x[i][d] + x[j][d]);
    v.diameter = 0.5 * (state.diameter[i] + state.diameter[j]);
    v.half_length = half_preferred_length(s.length, s.preferred_length);
    v.area = state.preferred_area[i];
    v.first = i;
    created.push_back(v);
  }

  // the same steps as create_atoms: clear the map and the ghosts, add, initialise fix values
  atom->map_clear();
  atom->nghost = 0;
  atom->avec->clear_bonus();
  const int nlocal_before = atom->nlocal;
  for (const NewVertex &v : created) atom->avec->create_atom(v.type, const_cast<double *>(v.x));
  atom->data_fix_compute_variable(nlocal_before, atom->nlocal);

  state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");    // the arrays have grown
  for (size_t k = 0; k < created.size(); k++) {
    const NewVertex &v = created[k];
    const int n = nlocal_before + (int) k;
    atom->tag[n] = v.tag;
    atom->molecule[n] = v.molecule;
    atom->mask[n] = v.mask;
    atom->image[n] = v.image;
    atom->v[n][0] = atom->v[n][1] = atom->v[n][2] = 0.0;
    atom->f[n][0] = atom->f[n][1] = atom->f[n][2] = 0.0;    // the minimizer's clean-up reads f
    state.diameter[n] = v.diameter;
    state.preferred_length[n] = v.half_length;    // segment new vertex -> second
    state.preferred_angle[n] = 0.0;
    state.preferred_area[n] = v.area;
    state.preferred_length[v.first] = v.half_length;    // segment first -> new vertex
  }
  const bigint added = (bigint) splits.size();
  atom->natoms += added;
  atom->nbonds += added;     // each split segment becomes two
  atom->nangles += added;    // one angle centred on each new vertex
  atom->map_init();
  atom->map_set();
}

/* ----------------------------------------------------------------------
   segment first-second becomes first-new and new-second; the angles that ran through the
   segment now run through the new vertex, and the new vertex gets its own angle. Every rank
   edits only the atoms it owns; with newton_bond on a bond or angle is stored once, so whoever
   holds the old segment bond keeps one half and the new vertex holds the other.
------------------------------------------------------------------------- */

void FixDPolyRefine::rewire_topology(const std::vector<Split> &splits)
{
  const bool newton_bond = force->newton_bond;
  const int nlocal = atom->nlocal;
  auto owned = [&](tagint tag) {
    const int i = atom->map(tag);
    return (i >= 0 && i < nlocal) ? i : -1;
  };
  // the next free slot in atom i's list of bonds or angles ('what'), or an error naming the room
  auto next_slot = [&](int i, int *count, int capacity, const char *what) {
    if (count[i] == capacity)
      error->one(FLERR,
                 "Fix dpoly/refine: no room for another {} on atom {}; reserve more with "
                 "extra/{}/per/atom",
                 what, atom->tag[i], what);
    return count[i]++;
  };
  auto add_bond = [&](int i, int type, tagint partner) {
    const int m = next_slot(i, atom->num_bond, atom->bond_per_atom, "bond");
    atom->bond_type[i][m] = type;
    atom->bond_atom[i][m] = partner;
  };
  auto add_angle = [&](int i, int type, tagint a1, tagint a2, tagint a3) {
    const int m = next_slot(i, atom->num_angle, atom->angle_per_atom, "angle");
    atom->angle_type[i][m] = type;
    atom->angle_atom1[i][m] = a1;
    atom->angle_atom2[i][m] = a2;
    atom->angle_atom3[i][m] = a3;
  };
  // the bond of i to partner, as its index in i's list, or -1
  auto find_bond = [&](int i, tagint partner) {
    for (int m = 0; m < atom->num_bond[i]; m++)
      if (atom->bond_atom[i][m] == partner) return m;
    return -1;
  };
  auto centred_angle_type = [&](int i) {
    for (int m = 0; m < atom->num_angle[i]; m++)
      if (atom->angle_atom2[i][m] == atom->tag[i]) return atom->angle_type[i][m];
    return 0;
  };

  // Types travel with the split: the holder of the segment bond and the owner of the first
  // vertex (which holds the angle centred on it) tell everyone.
  struct Types {
    tagint first;
    int bond, angle, first_holds_bond;
  };
  std::vector<Types> mine;
  for (const Split &s : splits) {
    Types t = {s.first, 0, 0, 0};
    const int a = owned(s.first), b = owned(s.second);
    if (a >= 0) {
      const int m = find_bond(a, s.second);
      if (m >= 0) t.bond = atom->bond_type[a][m], t.first_holds_bond = 1;
      t.angle = centred_angle_type(a);
    }
    if (b >= 0 && !t.bond) {
      const int m = find_bond(b, s.first);
      if (m >= 0) t.bond = atom->bond_type[b][m];
    }
    if (a >= 0 || (b >= 0 && t.bond)) mine.push_back(t);
  }
  std::unordered_map<tagint, Types> types;
  for (const Types &t : DPoly::gather_on_all_ranks(std::move(mine), world)) {
    Types &known = types[t.first];
    known.first = t.first;
    if (t.bond) known.bond = t.bond;
    if (t.angle) known.angle = t.angle;
    if (t.first_holds_bond) known.first_holds_bond = 1;
  }

  // the old segment's bond now ends at the new vertex
  for (const Split &s : splits) {
    const Types &t = types[s.first];
    if (!t.bond || !t.angle)
      error->all(FLERR, "Fix dpoly/refine: segment {}-{} has no bond or its vertex no angle",
                 s.first, s.second);
    const int a = owned(s.first), b = owned(s.second), n = owned(s.added);
    if (a >= 0) {
      const int m = find_bond(a, s.second);
      if (m >= 0) atom->bond_atom[a][m] = s.added;
    }
    if (b >= 0) {
      const int m = find_bond(b, s.first);
      if (m >= 0) atom->bond_atom[b][m] = s.added;
    }
    if (n >= 0) {
      if (newton_bond)
        add_bond(n, t.bond, t.first_holds_bond ? s.second : s.first);
      else {
        add_bond(n, t.bond, s.first);
        add_bond(n, t.bond, s.second);
      }
      add_angle(n, t.angle, s.first, s.added, s.second);
    }
    if (!newton_bond) {
      if (a >= 0) add_angle(a, t.angle, s.first, s.added, s.second);
      if (b >= 0) add_angle(b, t.angle, s.first, s.added, s.second);
    }
  }

  // angles (p, q, r) with q -> r or p -> q a split segment now run through its new vertex
  std::unordered_map<tagint, const Split *> by_first;
  for (const Split &s : splits) by_first[s.first] = &s;
  auto vertex_between = [&](tagint from, tagint to) -> tagint {
    const auto it = by_first.find(from);
    return (it != by_first.end() && it->second->second == to) ? it->second->added : 0;
  };
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < atom->num_angle[i]; m++) {
      const tagint p = atom->angle_atom1[i][m], q = atom->angle_atom2[i][m],
                   r = atom->angle_atom3[i][m];
      if (const tagint n = vertex_between(q, r)) atom->angle_atom3[i][m] = n;
      if (const tagint n = vertex_between(p, q)) atom->angle_atom1[i][m] = n;
    }
}

// vertices added at the last refinement, in all, refinements
double FixDPolyRefine::compute_vector(int n)
{
  if (n == 0) return added_last;
  if (n == 1) return (double) added_total;
  return (double) steps;
}

// steps, vertices added, then per cell: ID and vertex count at the first refinement
std::vector<double> FixDPolyRefine::restart_state() const
{
  std::vector<double> state = {(double) steps, (double) added_total};
  for (const auto &cell : initial_vertices) {
    state.push_back((double) cell.first);
    state.push_back((double) cell.second);
  }
  return state;
}

bool FixDPolyRefine::restore_state(const std::vector<double> &state)
{
  if (state.size() < 2 || state.size() % 2) return false;
  steps = (bigint) state[0];
  added_total = (bigint) state[1];
  initial_vertices.clear();
  for (size_t k = 2; k < state.size(); k += 2)
    initial_vertices[(tagint) state[k]] = (int) state[k + 1];
  return true;
}
