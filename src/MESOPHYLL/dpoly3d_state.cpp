/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly3d_state.h"

#include "atom.h"
#include "error.h"

#include <cstring>

using namespace LAMMPS_NS;

const char *const DPoly3d::VERTEX_HINT = "fix Vertices all property/atom d_sigma d_v0 ghost yes";
const char *const DPoly3d::EDGE_HINT =
    "fix Edges all property/atom i2_edge 6 ghost yes; fix EdgeLengths all property/atom "
    "d2_edge_l0 6 ghost yes; fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes";

// index of a custom property of the given kind (flag: 0 int, 1 double; cols: 0 a vector, -1 any
// number of columns), with ghost atoms; an error that says how to define it otherwise
static int find_property(Atom *atom, Error *error, const char *style, const char *name, int kind,
                         bool array, const char *hint)
{
  int flag, cols, ghost;
  // LAMMPS keeps a property's name without its i_, d_, i2_ or d2_ prefix
  const char *bare = strchr(name, '_') + 1;
  const int index = atom->find_custom_ghost(bare, flag, cols, ghost);
  if (index < 0 || flag != kind || (array ? cols < 1 : cols != 0))
    error->all(FLERR, "{} needs the per-atom property {}: define it with: {}", style, name, hint);
  if (!ghost)
    error->all(FLERR, "{} needs {} on ghost atoms too: add 'ghost yes' to its fix property/atom",
               style, name);
  return index;
}

void DPoly3d::VertexStateCache::find(Atom *atom, Error *error, const char *style)
{
  diameter = find_property(atom, error, style, "d_sigma", 1, false, VERTEX_HINT);
  preferred_volume = find_property(atom, error, style, "d_v0", 1, false, VERTEX_HINT);
}

DPoly3d::VertexState DPoly3d::VertexStateCache::get(Atom *atom, Error *error, const char *style)
{
  if (diameter < 0) find(atom, error, style);
  return {atom->dvector[diameter], atom->dvector[preferred_volume]};
}

void DPoly3d::EdgeValues::find(Atom *atom, Error *error, const char *style)
{
  partner_index = find_property(atom, error, style, "i2_edge", 0, true, EDGE_HINT);
  length_index = find_property(atom, error, style, "d2_edge_l0", 1, true, EDGE_HINT);
  angle_index = find_property(atom, error, style, "d2_edge_theta0", 1, true, EDGE_HINT);
  ncolumns = atom->icols[partner_index];
  if (atom->dcols[length_index] != ncolumns || atom->dcols[angle_index] != ncolumns)
    error->all(FLERR,
               "{}: i2_edge, d2_edge_l0 and d2_edge_theta0 must have the same number of columns, "
               "got {}, {} and {}",
               style, ncolumns, atom->dcols[length_index], atom->dcols[angle_index]);
  // read_data reads at most 255 characters of a line and drops the rest without a word: one
  // vertex's line of more than 9 full-precision values would lose digits in a data file
  if (ncolumns > MAX_EDGE_COLUMNS)
    error->all(FLERR,
               "{}: i2_edge, d2_edge_l0 and d2_edge_theta0 have {} columns, at most {} fit in a "
               "line that read_data reads whole",
               style, ncolumns, MAX_EDGE_COLUMNS);
}

void DPoly3d::EdgeValues::fetch(Atom *atom, Error *error, const char *style)
{
  if (partner_index < 0) find(atom, error, style);
  partners = atom->iarray[partner_index];
  lengths = atom->darray[length_index];
  angles = atom->darray[angle_index];
}

DPoly3d::EdgeSlot DPoly3d::EdgeValues::slot(const Atom *atom, int i, int j) const
{
  const bool i_first = atom->tag[i] < atom->tag[j];
  const int owner = i_first ? i : j;
  const tagint other = i_first ? atom->tag[j] : atom->tag[i];
  for (int k = 0; k < ncolumns; k++)
    if (partners[owner][k] == other) return {owner, k};
  return {owner, -1};
}

DPoly3d::EdgeSlot DPoly3d::EdgeValues::require(const Atom *atom, Error *error, const char *style,
                                               int i, int j) const
{
  const EdgeSlot s = slot(atom, i, j);
  if (s.column < 0) {
    const tagint lo = atom->tag[s.owner], hi = atom->tag[s.owner == i ? j : i];
    error->one(FLERR,
               "{}: edge {}-{} has no preferred values: vertex {} (the edge's lower ID) must "
               "list {} in one of its i2_edge columns, with d2_edge_l0 and d2_edge_theta0 in "
               "the same column",
               style, lo, hi, lo, hi);
  }
  return s;
}
