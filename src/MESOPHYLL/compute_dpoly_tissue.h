/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(dpoly/tissue,ComputeDPolyTissue);
// clang-format on
#else

#ifndef LMP_COMPUTE_DPOLY_TISSUE_H
#define LMP_COMPUTE_DPOLY_TISSUE_H

#include "compute.h"
#include "dpoly_measure.h"

#include <vector>

namespace LAMMPS_NS {

// What the paper reports of a tissue (doc/Howto_mesophyll.rst, "Observables"): packing fractions, shape parameters,
// contact numbers, void-facing vertices; globally and per cell.
class ComputeDPolyTissue : public Compute, public DPoly::TissueMeasure {
 public:
  ComputeDPolyTissue(class LAMMPS *, int, char **);
  ~ComputeDPolyTissue() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void compute_vector() override;
  void compute_array() override;
  double memory_usage() override;
  void measure_minimum() override { DPoly::evaluate_global(this); }

 private:
  class FixDPolyCells *cells;
  class NeighList *list;
  double *values;
  double **per_cell;
  int rows;

  struct Measures {
    std::vector<double> patch_area, void_fraction;
    std::vector<int> neighbours;
  };
  Measures measure();
  std::vector<double> patch_areas();
  std::vector<double> void_fractions();
  std::vector<int> neighbour_counts();
};

}    // namespace LAMMPS_NS

#endif
#endif
