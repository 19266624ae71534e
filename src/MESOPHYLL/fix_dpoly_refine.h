/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(dpoly/refine,FixDPolyRefine);
// clang-format on
#else

#ifndef LMP_FIX_DPOLY_REFINE_H
#define LMP_FIX_DPOLY_REFINE_H

#include "dpoly_refine_rules.h"
#include "fix_dpoly_stage.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

// Resolution control of the deformable polygons (doc/Howto_mesophyll.rst, "Vertex insertion"):
// after each minimization, split long ring segments by new vertices, so that growing rings do not
// get coarse. Which segments split and how is a rule set (dpoly_refine_rules.h); this fix gathers
// what the rule set reads, and adds the atoms, bonds and angles of its plan.
class FixDPolyRefine : public FixDPolyStage {
 public:
  FixDPolyRefine(class LAMMPS *, int, char **);
  void init() override;
  int act() override;    // split the segments the rule set chooses
  double compute_vector(int) override;

 private:
  DPoly::RefineTable gather_table(std::vector<DPoly::AdhesiveBond> &bonds);
  void number_new_vertices(DPoly::RefinePlan &plan);
  void insert_vertices(const DPoly::RefinePlan &plan);
  void rewire_topology(const std::vector<DPoly::SegmentSplit> &splits);
  std::vector<double> restart_state() const override;
  bool restore_state(const std::vector<double> &) override;

  std::string rules_name;
  std::unique_ptr<DPoly::RefineRules> rules;
  bigint steps;          // refinement passes so far
  bigint start;          // the first pass that may add vertices
  bool measure_preferred;    // segments measured by their preferred length l0, not their length
  bigint added_total;    // vertices added in all
  int added_last;
  std::map<tagint, int> initial_vertices;    // per cell, at the first refinement
};

}    // namespace LAMMPS_NS

#endif
#endif
