/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(dpoly3d/edge,BondDPoly3dEdge);
// clang-format on
#else

#ifndef LMP_BOND_DPOLY3D_EDGE_H
#define LMP_BOND_DPOLY3D_EDGE_H

#include "bond.h"
#include "dpoly3d_state.h"
#include "dpoly_laws.h"
#include "dpoly_stiffness.h"

namespace LAMMPS_NS {

// Edge term of a deformable polyhedron: U = (eps_l/2)(l/l0 - 1)^2 per edge, the 2d segment law
// (DPoly::segment_law) with l0 per edge, kept on the edge's lower-ID vertex (dpoly3d_state.h).
class BondDPoly3dEdge : public DPoly::PerTypeStiffness<Bond> {
 public:
  BondDPoly3dEdge(class LAMMPS *);
  void init_style() override;
  void compute(int, int) override;
  double equilibrium_distance(int) override;
  double single(int, double, int, int, double &) override;
  void born_matrix(int, double, int, int, double &, double &) override;

 private:
  double longest_preferred;    // largest l0 when the run started, for equilibrium_distance()
  DPoly3d::EdgeValues edges;
  DPoly::DistanceLaw edge_law(int type, int i, int j, double r);
};

}    // namespace LAMMPS_NS

#endif
#endif
