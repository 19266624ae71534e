/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef DIHEDRAL_CLASS
// clang-format off
DihedralStyle(dpoly3d/hinge,DihedralDPoly3dHinge);
// clang-format on
#else

#ifndef LMP_DIHEDRAL_DPOLY3D_HINGE_H
#define LMP_DIHEDRAL_DPOLY3D_HINGE_H

#include "dihedral.h"
#include "dpoly3d_state.h"
#include "dpoly_stiffness.h"

namespace LAMMPS_NS {

// Bending term of a deformable polyhedron: U = (eps_b/2)(theta - theta0)^2 per edge, theta the
// signed angle between the outward normals of the edge's two faces (positive where the surface is
// convex), theta0 per edge on the edge's lower-ID vertex (dpoly3d_state.h). A hinge is the
// dihedral a b c d of the faces (a, b, c) and (c, b, d), both counter-clockwise from outside.
class DihedralDPoly3dHinge : public DPoly::PerTypeStiffness<Dihedral> {
 public:
  DihedralDPoly3dHinge(class LAMMPS *);
  void init_style() override;
  void compute(int, int) override;

 private:
  DPoly3d::EdgeValues edges;
};

}    // namespace LAMMPS_NS

#endif
#endif
