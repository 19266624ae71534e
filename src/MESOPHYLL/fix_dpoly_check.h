/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(dpoly/check,FixDPolyCheck);
// clang-format on
#else

#ifndef LMP_FIX_DPOLY_CHECK_H
#define LMP_FIX_DPOLY_CHECK_H

#include "dpoly_overlap.h"
#include "fix_dpoly_stage.h"

#include <string>

namespace LAMMPS_NS {

// Checks every minimum the minimizer reports, so that no failure is carried on silently: why it
// stopped, the final force norm, |P - P0|/P0, cells with area <= 0, rings that cross themselves,
// cells that interpenetrate, packing fractions outside (0, 1] and ring segments not shorter than
// half the box. Warns (default) or stops with an error that names what failed. The first stage
// after a minimization: it sees the minimum before any other stage changes it.
class FixDPolyCheck : public FixDPolyStage {
 public:
  FixDPolyCheck(class LAMMPS *, int, char **);
  int act() override;
  double compute_vector(int) override;

 private:
  double target_pressure;    // P0 (negative: a tension); 0: no pressure check
  double pressure_tolerance;
  int stop_on_failure;
  bigint minima;
  bool triclinic_warned = false;
  // converged, force norm, |P - P0|/P0, inverted cells, tangled cells, iterations, force
  // evaluations, pairs of interpenetrating cells (appended last: tools read the others by index)
  double last[8];
  int check();                // the number of problems found
  class UnwrappedVertices;    // every vertex on every rank, gathered once per check
  int tangled_cells(const UnwrappedVertices &vertices, tagint &first);
  DPoly::Interpenetration interpenetrating_cells(const UnwrappedVertices &vertices);
  // "; ..." for each impossible geometry, "" if none
  std::string geometry_problems(const UnwrappedVertices &vertices);
};

}    // namespace LAMMPS_NS

#endif
#endif
