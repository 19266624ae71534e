/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly3d_void_patches.h"

#include <map>

using namespace LAMMPS_NS;
using namespace DPoly3d;

void VoidPatches::add_vertex(tagint vertex, tagint cell, double area)
{
  members[vertex] = {vertex, cell, area, 0.0};
  totalled = false;
}

// union-find: the root of a patch is the lowest ID among its vertices, whatever the order of
// the edges, so that the patches are the same on any number of ranks
tagint VoidPatches::root(tagint vertex)
{
  tagint r = vertex;
  while (members[r].parent != r) r = members[r].parent;
  while (members[vertex].parent != r) {
    const tagint next = members[vertex].parent;
    members[vertex].parent = r;
    vertex = next;
  }
  return r;
}

void VoidPatches::add_edge(tagint u, tagint v)
{
  if (!members.count(u) || !members.count(v)) return;
  const tagint ru = root(u), rv = root(v);
  if (ru == rv) return;
  if (ru < rv)
    members[rv].parent = ru;
  else
    members[ru].parent = rv;
  totalled = false;
}

// sums in ID order, so that the areas are the same bits on any number of ranks
void VoidPatches::total()
{
  if (totalled) return;
  std::map<tagint, Member *> ordered;
  for (auto &m : members) {
    m.second.patch = 0.0;
    ordered[m.first] = &m.second;
  }
  for (auto &m : ordered) members[root(m.first)].patch += m.second->area;
  cells.clear();
  for (auto &m : ordered)
    if (m.second->parent == m.first) {
      CellPatches &c = cells[m.second->cell];
      c.count++;
      c.area += m.second->patch;
    }
  totalled = true;
}

double VoidPatches::patch_area(tagint vertex)
{
  if (!members.count(vertex)) return 0.0;
  total();
  return members[root(vertex)].patch;
}

double VoidPatches::mean_patch_area(tagint cell)
{
  total();
  const auto found = cells.find(cell);
  return found == cells.end() ? 0.0 : found->second.area / found->second.count;
}

int VoidPatches::patches(tagint cell)
{
  total();
  const auto found = cells.find(cell);
  return found == cells.end() ? 0 : found->second.count;
}
