/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Surfaces no state of the polyhedron model can have, for fix dpoly/check under fix
// dpoly3d/cells: cells whose volume is <= 0 (inverted) or zero to round-off, V <= 1e-10 S^(3/2)
// with S the surface area (collapsed flat), cells with a face that
// points into the cell (a surface folded through itself: the outward normal of a face a b c,
// (b - a) x (c - a), points away from the cell's vertex centroid as seen from the face's centre;
// a star-shaped cell has none), and pairs of cells where a vertex of one lies inside the closed
// surface of the other (its winding number about that surface, the sum of the faces' solid
// angles over 4 pi, is above 1/2). Every rank gathers every vertex and face, so the verdict
// does not depend on the number of ranks. The cells must be whole in unwrapped coordinates,
// which fix dpoly3d/cells checks at every re-neighbouring.

#ifndef LMP_DPOLY3D_SURFACE_CHECK_H
#define LMP_DPOLY3D_SURFACE_CHECK_H

#include "lmptype.h"

namespace LAMMPS_NS {
class LAMMPS;
namespace DPoly {
  class CellHub;
}

namespace DPoly3d {

  struct SurfaceProblems {
    double total_volume = 0.0;    // of all cells
    int collapsed = 0;    // cells with V <= 0 (or 0 to round-off), the first (lowest ID), its V
    tagint first_collapsed = 0;
    double first_volume = 0.0;
    int folded = 0;    // cells with a face that points inward, the first and that face
    tagint first_folded = 0;
    tagint first_face[3] = {0, 0, 0};
    int pairs = 0;                    // pairs of cells, a vertex of one inside the other
    tagint first_pair[2] = {0, 0};    // the pair with the lowest IDs
    tagint first_vertex = 0;          // its lowest vertex inside the other cell
    tagint first_vertex_cell = 0;     // the cell of that vertex
  };

  // Collective: the vertices of group 'groupbit' are the hub's cells; their volumes are
  // measured here, on the positions tested.
  SurfaceProblems check_surfaces(LAMMPS *lmp, const DPoly::CellHub &hub, int groupbit);

  // Winding number of the closed, outward-oriented triangles (a b c, 9 coordinates each) about
  // point p: 1 inside, 0 outside.
  double winding_number(const double *p, const double *triangles, int ntriangles);

}    // namespace DPoly3d
}    // namespace LAMMPS_NS

#endif
