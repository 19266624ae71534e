/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Paradermal slices of deformable polyhedra: where the triangulated cell surfaces meet the
// planes z = const of a periodic box, as closed outlines (doc/Howto_polyhedra.rst, "Observables").
// Pure geometry on whole-system tables, so that every rank finds the same outlines.

#ifndef LMP_DPOLY3D_SLICE_H
#define LMP_DPOLY3D_SLICE_H

#include "lmptype.h"

#include <vector>

namespace LAMMPS_NS {
namespace DPoly3d {

  struct SliceVertex {
    tagint tag;
    double x[3];    // unwrapped: every cell whole
  };
  struct SliceFace {
    tagint cell, a, b, c;    // counter-clockwise seen from outside the cell
  };

  // The periodic orthogonal box as the slices see it.
  struct SliceBox {
    double zlo, lx, ly, lz;
  };

  // 'count' planes z_j = zlo + (j + offset) lz / count, j = 0 .. count-1
  std::vector<double> plane_heights(const SliceBox &box, int count, double offset);

  // One closed outline, counter-clockwise seen from +z.
  struct Outline {
    tagint cell;
    int plane;
    std::vector<double> x, y;
    double area;    // signed: > 0 an outer outline, < 0 a hole in a cross-section
    double perimeter;
    double bounds[4];    // xmin, xmax, ymin, ymax
  };

  // Every outline of every cell in every plane, sorted by plane, cell and first edge. A vertex
  // at a plane's height counts as above it, so a plane through vertices, along an edge or in a
  // face gives each crossing once. Throws std::runtime_error (with the reason) if a surface is
  // not closed or a position is not finite.
  std::vector<Outline> slice_surfaces(const std::vector<SliceVertex> &vertices,
                                      const std::vector<SliceFace> &faces, const SliceBox &box,
                                      const std::vector<double> &heights);

  // Shortest distance between two outlines, over the periodic images in the plane.
  double outline_distance(const Outline &a, const Outline &b, const SliceBox &box);

}    // namespace DPoly3d
}    // namespace LAMMPS_NS

#endif
