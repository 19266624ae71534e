/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(mesophyll/grow,FixMesophyllGrow);
// clang-format on
#else

#ifndef LMP_FIX_MESOPHYLL_GROW_H
#define LMP_FIX_MESOPHYLL_GROW_H

#include "dpoly_growth_rules.h"
#include "fix_dpoly_stage.h"

#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

// Void-localized growth between minimizations (doc/Howto_mesophyll.rst, "Growth"): every cell's a0 grows by
// delta_a, vertex diameters scale with sqrt(a0), preferred segment lengths grow only around
// void-facing vertices, and their preferred angles drift negative, then are smoothed.
class FixMesophyllGrow : public FixDPolyStage {
 public:
  FixMesophyllGrow(class LAMMPS *, int, char **);
  void init() override;
  int act() override;    // one growth step
  double compute_vector(int) override;

 private:
  // What every rank needs of a vertex to find the void runs of its ring.
  struct VertexGrowth {
    tagint tag;
    double segment;            // current length of the segment to the next vertex
    double preferred_angle;    // theta0 before this step
  };
  void grow_ring(int cell, std::unordered_map<tagint, const VertexGrowth *> &vertex,
                 std::unordered_map<tagint, double> &length_growth,
                 std::unordered_map<tagint, double> &new_angle);

  void record_packing();
  std::vector<double> restart_state() const override;
  bool restore_state(const std::vector<double> &) override;

  DPoly::GrowthRates rates;    // lambda, c_L, c_B, theta0_min, scale_sigma, box
  double delta_a, shape_max;
  int grow_above_max;    // above shape_max: isometric growth (authors' code) or none (paper)
  int as_published;      // rules published: the published code's run lengths, drift, smoothing
  bigint steps;
  int void_vertices, cells_above_max;
  double packing_last;    // phi at the last minimum (-1 before the first)
  double compaction;      // delta_phi_plus
};

}    // namespace LAMMPS_NS

#endif
#endif
