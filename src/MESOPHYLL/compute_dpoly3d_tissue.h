/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(dpoly3d/tissue,ComputeDPoly3dTissue);
// clang-format on
#else

#ifndef LMP_COMPUTE_DPOLY3D_TISSUE_H
#define LMP_COMPUTE_DPOLY3D_TISSUE_H

#include "compute.h"
#include "dpoly3d_state.h"

#include <vector>

namespace LAMMPS_NS {

// The 3d tissue (doc/Howto_polyhedra.rst, "Observables"): volume fraction, 3d shape parameter
// S^3/(36 pi V^2), contact number from the adhesive bonds, patch volume fraction (the cells
// inflated by their vertex spheres, as the 2d phi_patch), globally and per cell, and the
// flattest face. Volumes and surface areas are the ones fix dpoly3d/cells measured at the last
// force evaluation.
class ComputeDPoly3dTissue : public Compute {
 public:
  ComputeDPoly3dTissue(class LAMMPS *, int, char **);
  ~ComputeDPoly3dTissue() override;
  void init() override;
  void compute_vector() override;
  void compute_array() override;
  double memory_usage() override;
  // the per-cell array's rows, which fix ave/time asks a compute of variable length for
  int lock_length() override;

  // S^3 / (36 pi V^2): 1 for a sphere, larger for any other closed surface
  static double shape_parameter(double surface, double volume);
  // how far a vertex is pushed out for the patch volume, in vertex diameters: sin(pi/3)/2, the
  // 2d phi_patch's push
  static double patch_push();
  // how flat a triangle is: its height over its longest edge, 2 area / longest edge^2
  // (sqrt(3)/2 for an equilateral one, 0 for one whose vertices are collinear)
  static double face_flatness(const double *a, const double *b, const double *c);

 private:
  class FixDPoly3dCells *cells;
  double *values;
  double **per_cell;
  int rows;
  DPoly3d::VertexStateCache vertex_state;

  void find_cells();
  void require_measured_cells();
  struct SurfaceMeasures {
    std::vector<double> patch_volumes;    // per cell
    double flattest_face;                 // the smallest face_flatness() of all cells' faces
  };
  SurfaceMeasures measure_surfaces();
};

}    // namespace LAMMPS_NS

#endif
#endif
