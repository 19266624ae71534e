/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Plane geometry of cell outlines for fix dpoly/check: whether two segments cross, whether a
// point lies inside a polygon, and which cells interpenetrate. An outline is the polygon through
// a cell's vertex centres. Vertex disks of neighbouring cells overlap by design (contact
// repulsion, adhesion), but two outlines never cross in a state of the model: a vertex of one
// cell would have to pass between two ring neighbours of another, whose disks seal the ring.
// No LAMMPS state: the caller hands in the outlines and the box.

#ifndef LMP_DPOLY_OVERLAP_H
#define LMP_DPOLY_OVERLAP_H

#include "lmptype.h"

#include <array>
#include <vector>

namespace LAMMPS_NS {
namespace DPoly {

  using Point = std::array<double, 2>;

  // Segments ab and cd cross at a point inside both; segments that only touch (an end on the
  // other segment) or lie on one line do not count, so that exact contact is not an overlap.
  bool segments_cross(const Point &a, const Point &b, const Point &c, const Point &d);

  // p lies inside the closed polygon (even-odd rule: either orientation, inverted rings too).
  bool inside_polygon(const Point &p, const std::vector<Point> &polygon);

  struct Outline {
    tagint cell;                   // the cell's ID, to name it
    std::vector<Point> corners;    // its ring in order, whole (unwrapped coordinates)
  };

  struct Box {
    double length[2];    // box lengths in x and y
    bool periodic[2];
  };

  struct Interpenetration {
    bigint pairs = 0;            // pairs of cells whose outlines overlap
    tagint first[2] = {0, 0};    // the pair with the lowest IDs (equal: a cell and its image)
  };

  // Cells whose outlines overlap: a segment of one crosses a segment of the other, or a vertex or
  // segment midpoint of one lies strictly inside the other (points on its outline are skipped). Every periodic image of the second cell whose bounding box meets the
  // first's is tried (the nearest image and, in small boxes, others), a cell against its own
  // images too. Cells are binned by bounding box, so only neighbouring cells are compared, and
  // within a pair only the segments inside both boxes: the cost grows with the number of cells.
  Interpenetration interpenetrating_cells(const std::vector<Outline> &outlines, const Box &box);

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
