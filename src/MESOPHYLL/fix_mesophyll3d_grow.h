/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(mesophyll3d/grow,FixMesophyll3dGrow);
// clang-format on
#else

#ifndef LMP_FIX_MESOPHYLL3D_GROW_H
#define LMP_FIX_MESOPHYLL3D_GROW_H

#include "dpoly3d_state.h"
#include "dpoly_growth_rules.h"
#include "fix_dpoly_stage.h"

#include <vector>

namespace LAMMPS_NS {

// Void-localized growth of 3d cells between minimizations (doc/Howto_polyhedra.rst, "Growth"):
// every cell's v0 grows by delta_V, vertex diameters scale with cbrt(v0), preferred edge lengths
// grow only at void-facing vertices, and the preferred angles of void-facing edges drift
// negative, then are smoothed. The 3d counterpart of fix mesophyll/grow, with its laws.
class FixMesophyll3dGrow : public FixDPolyStage {
 public:
  FixMesophyll3dGrow(class LAMMPS *, int, char **);
  bool acts_on_polyhedra() const override { return true; }
  void init() override;
  int act() override;    // one growth step
  double compute_vector(int) override;

  // What every rank needs of an edge and a face (whole-system tables, so that the patches and
  // the smoothing are the same on any number of ranks).
  struct EdgeGrowth {
    tagint lo, hi, cell;
    double length;             // current length
    double preferred_angle;    // theta0 before this step
  };
  struct FaceArea {
    tagint a, b, c;
    double area;
  };

 private:
  class FixDPoly3dCells *cells3d;    // the hub, fix dpoly3d/cells
  DPoly3d::VertexStateCache vertex_state;
  DPoly3d::EdgeValues edge_values;
  DPoly::GrowthRates rates;    // lambda, c_L, c_B, theta0_min, scale_sigma, box
  double delta_volume;         // delta_V
  bigint steps;
  int void_vertices, void_edges;

  void bind(DPoly::CellHub *cell_hub);
  void gather_surfaces(std::vector<EdgeGrowth> &edges, std::vector<FaceArea> &faces);
  std::vector<double> restart_state() const override;
  bool restore_state(const std::vector<double> &) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
