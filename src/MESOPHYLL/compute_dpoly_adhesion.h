/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(dpoly/adhesion,ComputeDPolyAdhesion);
// clang-format on
#else

#ifndef LMP_COMPUTE_DPOLY_ADHESION_H
#define LMP_COMPUTE_DPOLY_ADHESION_H

#include "compute.h"
#include "dpoly_cell_hub.h"
#include "dpoly_measure.h"

namespace LAMMPS_NS {

// Adhesive bonds as the cell-adhesion bond style last counted them: per vertex (0 = void-facing),
// and per cell (cell ID, adhesive bonds, distinct cells bonded to it) as a global array; for
// polygons (fix dpoly/cells) and polyhedra (fix dpoly3d/cells) alike.
class ComputeDPolyAdhesion : public Compute, public DPoly::TissueMeasure {
 public:
  ComputeDPolyAdhesion(class LAMMPS *, int, char **);
  ~ComputeDPolyAdhesion() override;
  void init() override;
  void compute_array() override;
  void compute_peratom() override;
  double memory_usage() override;
  void measure_minimum() override { DPoly::evaluate_global(this); }
  void forget_values() override { DPoly::forget_peratom(this); }

 private:
  DPoly::CellHub *cells;    // fix dpoly/cells or fix dpoly3d/cells
  double **per_cell;
  double *per_vertex;
  int nmax;
};

}    // namespace LAMMPS_NS

#endif
#endif
