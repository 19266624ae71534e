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
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "dpoly_stiffness.h"

namespace LAMMPS_NS {

// Length term of a deformable polygon: U = (k eps_l/2)(l/l0 - 1)^2 per ring segment, where l0
// and the optional factor k (d_kl, else 1) belong to the segment's first vertex in ring order.
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
  // the segment's first vertex in ring order (an error if i-j is not a ring segment)
  int segment_start(int i, int j);
  // the segment law of bond type 'type' between local atoms i and j at distance r
  DPoly::DistanceLaw segment_law(const DPoly::VertexState &state, int type, int i, int j, double r);
};

}    // namespace LAMMPS_NS

#endif
#endif
