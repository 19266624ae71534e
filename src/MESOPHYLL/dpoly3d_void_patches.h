/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// The void patches of 3d cells: a patch is a largest set of void-facing vertices of one cell
// joined by edges whose two ends are void-facing (the surface counterpart of a 2d void run).
// Its size is the surface it exposes: each of its vertices contributes a third of the area of
// every face around it (as each vertex of a 2d run contributes half of its two segments).

#ifndef LMP_DPOLY3D_VOID_PATCHES_H
#define LMP_DPOLY3D_VOID_PATCHES_H

#include "lmptype.h"

#include <unordered_map>

namespace LAMMPS_NS {
namespace DPoly3d {

  class VoidPatches {
   public:
    // a void-facing vertex of cell 'cell' and the surface it exposes
    void add_vertex(tagint vertex, tagint cell, double area);
    // an edge between two vertices; it joins their patches if both were added (void-facing)
    void add_edge(tagint u, tagint v);
    // the area of the patch of an added vertex; 0 for a vertex that was not added
    double patch_area(tagint vertex);
    // the mean area of the patches of 'cell'; 0 if it has none
    double mean_patch_area(tagint cell);
    int patches(tagint cell);    // how many patches 'cell' has

   private:
    struct Member {
      tagint parent, cell;
      double area;     // the vertex's own
      double patch;    // on a patch's root: the patch's area
    };
    struct CellPatches {
      int count = 0;
      double area = 0.0;
    };
    std::unordered_map<tagint, Member> members;
    std::unordered_map<tagint, CellPatches> cells;
    bool totalled = false;
    tagint root(tagint vertex);
    void total();    // sums the areas on the roots, once all vertices and edges are in
  };

}    // namespace DPoly3d
}    // namespace LAMMPS_NS

#endif
