/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_refine.h"

#include "angle.h"
#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
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
using DPoly::RefinePlan;
using DPoly::SegmentSplit;

FixDPolyRefine::FixDPolyRefine(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyStage(lmp, narg, arg, REFINE, 3), rules_name("tension"), steps(0), start(1),
    measure_preferred(false), added_total(0), added_last(0)
{
  DPoly::RefineRules::Settings settings = {3.0, 5.0, true};
  bool void_given = false;
  int timing = -1;    // -1: the rule set's, 0: before growth, 1: after it
  parse_keywords(3, narg, arg, [&](const char *key, const char *value) {
    if (strcmp(key, "rules") == 0) {
      rules_name = value;
      if (!DPoly::RefineRules::create(rules_name, settings))
        error->all(FLERR,
                   "Fix dpoly/refine rules must be 'tension', 'published' or 'consistent', got "
                   "'{}'",
                   value);
    } else if (strcmp(key, "length") == 0) {
      settings.radii = utils::numeric(FLERR, value, false, lmp);
      // below 2 radii (one diameter) the halves' vertices would overlap their new neighbours
      if (settings.radii < 2.0)
        error->all(FLERR, "Fix dpoly/refine length must be >= 2 vertex radii, got {}", value);
    } else if (strcmp(key, "cap") == 0) {
      settings.cap = utils::numeric(FLERR, value, false, lmp);
      if (settings.cap < 1.0) error->all(FLERR, "Fix dpoly/refine cap must be >= 1, got {}", value);
    } else if (strcmp(key, "void") == 0) {
      settings.void_only = utils::logical(FLERR, value, false, lmp);
      void_given = true;
    } else if (strcmp(key, "timing") == 0) {
      timing = one_of(key, value, "before_growth", "after_growth");
    } else if (strcmp(key, "measure") == 0) {
      measure_preferred = one_of(key, value, "actual", "preferred") == 1;
    } else if (strcmp(key, "start") == 0) {
      start = utils::bnumeric(FLERR, value, false, lmp);
      if (start < 1) error->all(FLERR, "Fix dpoly/refine start must be >= 1, got {}", value);
    } else
      return false;
    return true;
  });
  rules = DPoly::RefineRules::create(rules_name, settings);
  if (void_given && rules_name != "tension")
    error->all(FLERR,
               "Fix dpoly/refine void applies to rules tension; rules {} has its own candidates",
               rules_name);
  // segments judged by l0 are worth splitting right after growth has lengthened l0
  if (timing < 0) timing = rules->before_growth() && !measure_preferred ? 0 : 1;
  move_to(timing == 0 ? REFINE_BEFORE_GROWTH : REFINE);
  if (!atom->molecule_flag || !atom->avec->bonds_allow || !atom->avec->angles_allow)
    error->all(FLERR, "Fix dpoly/refine needs an atom style with molecule IDs, bonds and angles");
}

void FixDPolyRefine::init()
{
  FixDPolyStage::init();
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Fix dpoly/refine needs an atom map (atom_modify map array or hash)");
  // the rule sets that scale stiffness per segment or vertex keep it in d_kl and d_kb
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");
  if ((rules->needs_segment_factors() && !state.segment_factor) ||
      (rules->needs_bending_factors() && !state.bending_factor))
    error->all(FLERR,
               "Fix dpoly/refine rules {} keeps the {} stiffness per vertex: define {} with {} "
               "(and set them to 1: set group all d_kl 1.0 ...)",
               rules_name, rules->needs_bending_factors() ? "segment and bending" : "segment",
               rules->needs_bending_factors() ? "d_kl and d_kb" : "d_kl", DPoly::STIFFNESS_HINT);
}

/* ----------------------------------------------------------------------
   the hub rebuilds the special lists and ghosts and re-reads the rings afterwards
------------------------------------------------------------------------- */

int FixDPolyRefine::act()
{
  if (initial_vertices.empty())
    for (int c = 0; c < cells->ncells(); c++)
      initial_vertices[cells->cell_id(c)] = cells->vertex_count(c);

  // passes before 'start' count but add nothing (the published code's first insertion follows
  // the first growth step; the first minimum of a development is the relaxed tissue before it)
  if (steps + 1 < start) {
    steps++;
    added_last = 0;
    if (comm->me == 0)
      utils::logmesg(lmp, "fix dpoly/refine: step {}: none added before step {}, {} in all\n",
                     steps, start, added_total);
    return NOTHING;
  }

  std::vector<DPoly::AdhesiveBond> bonds;
  const DPoly::RefineTable table = gather_table(bonds);
  RefinePlan plan = rules->plan(table, initial_vertices);
  number_new_vertices(plan);
  int added = 0;
  for (const SegmentSplit &s : plan.splits) added += (int) s.added.size();
  added_last = added;
  steps++;
  if (added) {
    insert_vertices(plan);
    rewire_topology(plan.splits);
    added_total += added;
  }
  if (comm->me == 0)
    utils::logmesg(lmp, "fix dpoly/refine: step {}: {} vertices added, {} in all\n", steps,
                   added_last, added_total);
  return added ? RINGS : NOTHING;
}

/* ----------------------------------------------------------------------
   every vertex of the cells as its owner measures it (the segment to the next vertex and the
   turning angle, from the closest images), the rings from the hub, and the adhesive bonds if the
   rule set reads them: the same table on every rank. With measure preferred a segment's length
   is its l0: after growth, the length the next minimum will stretch it towards
------------------------------------------------------------------------- */

DPoly::RefineTable FixDPolyRefine::gather_table(std::vector<DPoly::AdhesiveBond> &bonds)
{
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");
  int dim = 0;
  const double *bending_types =
      force->angle ? static_cast<const double *>(force->angle->extract("eps_b", dim)) : nullptr;
  double **x = atom->x;
  std::vector<DPoly::RefineVertex> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const DPoly::RingLinks links = DPoly::ring_links(atom, i);
    if (links.count != 1) continue;
    const int j = DPoly::closest_neighbour(lmp, i, links.next, "Fix dpoly/refine");
    const int p = DPoly::closest_neighbour(lmp, i, links.prev, "Fix dpoly/refine");
    const double in[2] = {x[i][0] - x[p][0], x[i][1] - x[p][1]};
    const double out[2] = {x[j][0] - x[i][0], x[j][1] - x[i][1]};
    int angle_type = 0;
    for (int m = 0; m < atom->num_angle[i]; m++)
      if (atom->angle_atom2[i][m] == atom->tag[i]) angle_type = atom->angle_type[i][m];
    const double distance = std::hypot(x[j][0] - x[i][0], x[j][1] - x[i][1]);
    mine.push_back({atom->tag[i], atom->molecule[i], state.diameter[i],
                    state.preferred_length[i], state.preferred_angle[i],
                    state.segment_factor_of(i), state.bending_factor_of(i),
                    bending_types && angle_type > 0 ? bending_types[angle_type] : 1.0,
                    DPoly::turning_angle(in, out),
                    measure_preferred ? state.preferred_length[i] : distance});
  }
  std::vector<DPoly::RefineVertex> all = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::sort(all.begin(), all.end(), [](const DPoly::RefineVertex &a, const DPoly::RefineVertex &b) {
    return a.tag < b.tag;
  });

  std::vector<DPoly::RefineTable::Ring> rings;
  for (int c = 0; c < cells->ncells(); c++) rings.push_back({cells->cell_id(c), cells->ring(c)});
  if (rules->needs_adhesive_bonds()) bonds = DPoly::gather_adhesive_bonds(lmp);
  return DPoly::RefineTable(std::move(all), std::move(rings), DPoly::adhesion_counts(lmp), bonds);
}

// the new vertices' IDs follow the largest, in the order of the split segments' first vertices
void FixDPolyRefine::number_new_vertices(RefinePlan &plan)
{
  tagint largest = 0;
  for (int i = 0; i < atom->nlocal; i++) largest = std::max(largest, atom->tag[i]);
  tagint next = 0;
  MPI_Allreduce(&largest, &next, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  for (SegmentSplit &s : plan.splits)
    for (DPoly::NewVertex &v : s.added) v.tag = ++next;
}

/* ----------------------------------------------------------------------
   the owner of each segment's first vertex creates its new vertices, each at the midpoint of the
   vertex before it and the segment's second vertex, with the cell's a0 and the plan's values;
   every owner takes the plan's new values of its existing vertices
------------------------------------------------------------------------- */

void FixDPolyRefine::insert_vertices(const RefinePlan &plan)
{
  struct Created {
    const DPoly::NewVertex *values;
    tagint molecule;
    int type, mask;
    imageint image;
    double x[3], area;
  };
  // read what is needed from the ghosts before creating atoms overwrites them
  DPoly::VertexState state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");
  double **x = atom->x;
  std::vector<Created> created;
  for (const SegmentSplit &s : plan.splits) {
    const int i = atom->map(s.first);
    if (i < 0 || i >= atom->nlocal) continue;
    const int j = DPoly::closest_neighbour(lmp, i, s.second, "Fix dpoly/refine");
    const double *before = x[i];
    for (const DPoly::NewVertex &v : s.added) {
      Created c = {&v, atom->molecule[i],      atom->type[i], atom->mask[i], atom->image[i],
                   {}, state.preferred_area[i]};
      for (int d = 0; d < 3; d++) c.x[d] = 0.5 * (before[d] + x[j][d]);
      created.push_back(c);
      before = created.back().x;
    }
  }

  // the same steps as create_atoms: clear the map and the ghosts, add, initialise fix values
  atom->map_clear();
  atom->nghost = 0;
  atom->avec->clear_bonus();
  const int nlocal_before = atom->nlocal;
  for (const Created &c : created) atom->avec->create_atom(c.type, const_cast<double *>(c.x));
  atom->data_fix_compute_variable(nlocal_before, atom->nlocal);

  state = DPoly::vertex_state(atom, error, "Fix dpoly/refine");    // the arrays have grown
  for (size_t k = 0; k < created.size(); k++) {
    const Created &c = created[k];
    const int n = nlocal_before + (int) k;
    atom->tag[n] = c.values->tag;
    atom->molecule[n] = c.molecule;
    atom->mask[n] = c.mask;
    atom->image[n] = c.image;
    atom->v[n][0] = atom->v[n][1] = atom->v[n][2] = 0.0;
    atom->f[n][0] = atom->f[n][1] = atom->f[n][2] = 0.0;    // the minimizer's clean-up reads f
    state.diameter[n] = c.values->diameter;
    state.preferred_length[n] = c.values->preferred_length;
    state.preferred_angle[n] = c.values->preferred_angle;
    state.preferred_area[n] = c.area;
    if (state.segment_factor) state.segment_factor[n] = c.values->segment_factor;
    if (state.bending_factor) state.bending_factor[n] = c.values->bending_factor;
  }
  bigint added = 0;
  for (const SegmentSplit &s : plan.splits) added += (bigint) s.added.size();
  atom->natoms += added;
  atom->nbonds += added;     // each new vertex adds one segment
  atom->nangles += added;    // and one angle, centred on it
  atom->map_init();
  atom->map_set();

  for (const DPoly::VertexUpdate &u : plan.updates) {
    const int i = atom->map(u.tag);
    if (i < 0 || i >= atom->nlocal) continue;
    state.preferred_length[i] = u.preferred_length;
    state.preferred_angle[i] = u.preferred_angle;
    if (state.segment_factor) state.segment_factor[i] = u.segment_factor;
    if (state.bending_factor) state.bending_factor[i] = u.bending_factor;
  }
}

/* ----------------------------------------------------------------------
   segment first-second becomes the chain first-new...-second; the angles that ran through the
   segment now run through its new vertices, and each new vertex gets its own angle. Every rank
   edits only the atoms it owns; with newton_bond on a bond is stored once, so whoever holds the
   old segment bond keeps the chain's link at its own end and each new vertex holds the link to
   its successor (or, at the far end, to its predecessor); an angle is stored by its centre.
------------------------------------------------------------------------- */

void FixDPolyRefine::rewire_topology(const std::vector<SegmentSplit> &splits)
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
  for (const SegmentSplit &s : splits) {
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

  for (const SegmentSplit &s : splits) {
    const Types &t = types[s.first];
    if (!t.bond || !t.angle)
      error->all(FLERR, "Fix dpoly/refine: segment {}-{} has no bond or its vertex no angle",
                 s.first, s.second);
    // the chain: first, the new vertices, second
    std::vector<tagint> chain = {s.first};
    for (const DPoly::NewVertex &v : s.added) chain.push_back(v.tag);
    chain.push_back(s.second);
    const int last = (int) chain.size() - 1;

    // the old segment's bond now ends at the nearest new vertex
    const int a = owned(s.first), b = owned(s.second);
    if (a >= 0) {
      const int m = find_bond(a, s.second);
      if (m >= 0) atom->bond_atom[a][m] = chain[1];
    }
    if (b >= 0) {
      const int m = find_bond(b, s.first);
      if (m >= 0) atom->bond_atom[b][m] = chain[last - 1];
    }
    for (int k = 1; k < last; k++) {
      const int n = owned(chain[k]);
      if (n < 0) continue;
      if (!newton_bond) {
        add_bond(n, t.bond, chain[k - 1]);
        add_bond(n, t.bond, chain[k + 1]);
      } else if (t.first_holds_bond)
        add_bond(n, t.bond, chain[k + 1]);
      else
        add_bond(n, t.bond, chain[k - 1]);
    }
    // an angle centred on each new vertex, on its centre (and, newton_bond off, its ends)
    for (int k = 1; k < last; k++)
      for (int end = -1; end <= 1; end++) {
        if (newton_bond && end != 0) continue;
        const int i = owned(chain[k + end]);
        if (i >= 0) add_angle(i, t.angle, chain[k - 1], chain[k], chain[k + 1]);
      }
  }

  // angles (p, q, r) with q -> r or p -> q a split segment now run through its new vertices;
  // the new angles above join no split segment and are left as they are
  std::unordered_map<tagint, const SegmentSplit *> by_first;
  for (const SegmentSplit &s : splits) by_first[s.first] = &s;
  auto split_of = [&](tagint from, tagint to) -> const SegmentSplit * {
    const auto it = by_first.find(from);
    return (it != by_first.end() && it->second->second == to) ? it->second : nullptr;
  };
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < atom->num_angle[i]; m++) {
      const tagint p = atom->angle_atom1[i][m], q = atom->angle_atom2[i][m],
                   r = atom->angle_atom3[i][m];
      if (const SegmentSplit *s = split_of(q, r)) atom->angle_atom3[i][m] = s->added.front().tag;
      if (const SegmentSplit *s = split_of(p, q)) atom->angle_atom1[i][m] = s->added.back().tag;
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
