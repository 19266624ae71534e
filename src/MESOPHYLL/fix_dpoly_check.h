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
#include <vector>

namespace LAMMPS_NS {

// Checks every minimum the minimizer reports, so that no failure is carried on silently: why it
// stopped, the final force norm, |P - P0|/P0, non-finite energy, pressure, positions or box, and
// geometry no tissue can have. Polygons (fix dpoly/cells): cells with area <= 0, rings that
// cross themselves, cells that interpenetrate, packing fractions outside (0, 1] and ring
// segments not shorter than half the box; where the minimizer did not converge, the ring segment
// shortest relative to its l0 is named too (a collapsed one keeps FIRE from settling). Polyhedra
// (fix dpoly3d/cells, dpoly3d_surface_check.h): cells with volume <= 0, faces turned into their
// cell, a vertex inside another cell, a packing fraction outside (0, 1]. Warns (default) or
// stops with an error that names what failed. The first stage after a minimization: it sees the
// minimum before any other stage changes it.
class FixDPolyCheck : public FixDPolyStage {
 public:
  FixDPolyCheck(class LAMMPS *, int, char **);
  int act() override;
  double compute_vector(int) override;
  bool acts_on_polyhedra() const override { return true; }

 private:
  double target_pressure;    // P0 (negative: a tension); 0: no pressure check
  double pressure_tolerance;
  int stop_on_failure;
  bigint minima;
  bool triclinic_warned = false;
  // the minima checked so far, so that a resumed run numbers its minima on from the restart
  std::vector<double> restart_state() const override;
  bool restore_state(const std::vector<double> &) override;
  // converged, force norm, |P - P0|/P0, inverted cells, tangled cells (3d: cells with faces
  // turned inward), iterations, force evaluations, pairs of interpenetrating cells, minima
  // checked so far (appended last: tools read the others by index)
  double last[9];
  // what the geometry tests found: vector elements 4, 5 and 8, and "; ..." for each problem
  struct Geometry {
    int inverted = 0;    // cells with area (volume) <= 0
    int tangled = 0;     // rings that cross themselves (surfaces with faces turned inward)
    int pairs = 0;       // pairs of cells that interpenetrate
    std::string problems;
    // polygons: ", shortest ring segment ...", appended to "the minimizer stopped without
    // converging (...)": one problem, so that tools read it as non-convergence still
    std::string shortest_segment;
  };
  void check();
  std::string non_finite_state();
  // name_shortest_segment: fill in shortest_segment (only read where the minimizer did not
  // converge); the same on every rank
  Geometry polygon_geometry(bool name_shortest_segment);
  Geometry polyhedron_geometry();
  class UnwrappedVertices;    // every vertex on every rank, gathered once per check
  int tangled_cells(const UnwrappedVertices &vertices, tagint &first);
  DPoly::Interpenetration interpenetrating_cells(const UnwrappedVertices &vertices);
  // ", ..." naming the ring segment shortest relative to its l0 (a diagnosis, not a failure)
  std::string shortest_segment(const UnwrappedVertices &vertices);
  // "; ..." for each impossible geometry, "" if none
  std::string geometry_problems(const UnwrappedVertices &vertices);
};

}    // namespace LAMMPS_NS

#endif
#endif
