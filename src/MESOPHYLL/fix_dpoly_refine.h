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

#include "fix_dpoly_stage.h"

#include <map>
#include <vector>

namespace LAMMPS_NS {

// Resolution control of the deformable polygons (doc/Howto_mesophyll.rst, "Vertex insertion"): after each
// minimization, split every ring segment longer than a given number of vertex radii by a new
// vertex at its midpoint, so that growing rings do not get coarse. The relaxed ring stays
// relaxed: the new vertex is straight (theta0 = 0) and the two halves keep the segment's tension.
class FixDPolyRefine : public FixDPolyStage {
 public:
  FixDPolyRefine(class LAMMPS *, int, char **);
  void init() override;
  int act() override;    // split the long segments
  double compute_vector(int) override;

 private:
  // A segment to split, as every rank sees it.
  struct Split {
    tagint first, second;    // its vertices, in ring order
    tagint cell;
    tagint added;    // ID of the new vertex
    double length, preferred_length;
  };
  std::vector<Split> find_long_segments();
  void choose_within_cap(std::vector<Split> &splits);
  void insert_vertices(const std::vector<Split> &splits);
  void rewire_topology(const std::vector<Split> &splits);
  std::vector<double> restart_state() const override;
  bool restore_state(const std::vector<double> &) override;

  double radii;     // split segments longer than this many vertex radii
  double cap;       // at most cap x the vertex count a cell had at the first refinement
  int void_only;    // split only segments between two vertices without adhesive bonds
  bigint steps, added_total;
  int added_last;
  std::map<tagint, int> initial_vertices;    // per cell, at the first refinement
};

}    // namespace LAMMPS_NS

#endif
#endif
