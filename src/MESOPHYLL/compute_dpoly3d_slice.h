/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(dpoly3d/slice,ComputeDPoly3dSlice);
// clang-format on
#else

#ifndef LMP_COMPUTE_DPOLY3D_SLICE_H
#define LMP_COMPUTE_DPOLY3D_SLICE_H

#include "compute.h"
#include "dpoly3d_slice.h"
#include "dpoly3d_state.h"

#include <vector>

namespace LAMMPS_NS {

// Paradermal slices of the 3d tissue (doc/Howto_polyhedra.rst, "Observables"): the cells'
// cross-sections by evenly spaced planes z = const, measured as the 2d model measures its cells
// (packing fraction, p^2/(4 pi a), contact number); globally and per cross-section.
class ComputeDPoly3dSlice : public Compute {
 public:
  ComputeDPoly3dSlice(class LAMMPS *, int, char **);
  ~ComputeDPoly3dSlice() override;
  void init() override;
  void compute_vector() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  class FixDPoly3dCells *cells;
  DPoly3d::VertexStateCache vertex_state;
  int nplanes;
  double offset;            // of the first plane, in plane spacings
  double contact_factor;    // cross-sections touch within this times the mean contact distance
  double *values;
  double **per_section;
  int rows;

  struct Section {
    int plane;
    tagint cell;
    double area, perimeter;
    int neighbours;
  };
  struct Slices {
    std::vector<Section> sections;    // outer outlines
    double area;                      // of all outlines, holes negative
    int holes;
  };
  void find_cells();
  Slices slice();
};

}    // namespace LAMMPS_NS

#endif
#endif
