/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(dpoly/segment,BondDPolySegment);
// clang-format on
#else

#ifndef LMP_BOND_DPOLY_SEGMENT_H
#define LMP_BOND_DPOLY_SEGMENT_H

#include "bond.h"
#include "dpoly_ring.h"
#include "dpoly_stiffness.h"

namespace LAMMPS_NS {

// Length term of a deformable polygon: U = (eps_l/2)(l/l0 - 1)^2 per ring segment, where l0 is
// the per-vertex preferred length held by the segment's first vertex in ring order.
class BondDPolySegment : public DPoly::PerTypeStiffness<Bond> {
 public:
  BondDPolySegment(class LAMMPS *);
  void init_style() override;
  void compute(int, int) override;
  double equilibrium_distance(int) override;
  double single(int, double, int, int, double &) override;
  void born_matrix(int, double, int, int, double &, double &) override;

 protected:
  double longest_preferred;    // largest l0 when the run started, for equilibrium_distance()
  DPoly::VertexStateCache vertex_state;
  double preferred_length(const DPoly::VertexState &state, int i, int j);
};

}    // namespace LAMMPS_NS

#endif
#endif
