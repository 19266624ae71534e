/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(dpoly/vertex,ComputeDPolyVertex);
// clang-format on
#else

#ifndef LMP_COMPUTE_DPOLY_VERTEX_H
#define LMP_COMPUTE_DPOLY_VERTEX_H

#include "compute.h"
#include "dpoly_measure.h"

namespace LAMMPS_NS {

// Per vertex: its signed turning angle theta and the length of its segment to the next vertex,
// the current values of what theta0 and l0 prefer (e.g. to set theta0 to the current shape).
class ComputeDPolyVertex : public Compute, public DPoly::TissueMeasure {
 public:
  ComputeDPolyVertex(class LAMMPS *, int, char **);
  ~ComputeDPolyVertex() override;
  void init() override {}
  void compute_peratom() override;
  double memory_usage() override;
  void forget_values() override { DPoly::forget_peratom(this); }

 private:
  int nmax;
  double **values;
};

}    // namespace LAMMPS_NS

#endif
#endif
