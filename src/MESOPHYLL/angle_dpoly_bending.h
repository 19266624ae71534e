/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef ANGLE_CLASS
// clang-format off
AngleStyle(dpoly/bending,AngleDPolyBending);
// clang-format on
#else

#ifndef LMP_ANGLE_DPOLY_BENDING_H
#define LMP_ANGLE_DPOLY_BENDING_H

#include "angle.h"
#include "dpoly_laws.h"
#include "dpoly_ring.h"
#include "dpoly_stiffness.h"

namespace LAMMPS_NS {

// Bending term of a deformable polygon: U = (k eps_b/2)(theta - theta0)^2 per vertex, with theta
// the signed turning angle at the angle's middle atom, theta0 that vertex's preferred value and k
// its optional stiffness factor (d_kb, else 1).
class AngleDPolyBending : public DPoly::PerTypeStiffness<Angle> {
 public:
  AngleDPolyBending(class LAMMPS *);
  void init_style() override;
  void compute(int, int) override;
  double equilibrium_angle(int) override;
  double single(int, int, int, int) override;
  void born_matrix(int, int, int, int, double &, double &) override;

  // The bending law in the signed turning angle theta at the local vertex 'centre': U,
  // dU/dtheta and d2U/dtheta2, regular everywhere (born_matrix() is not at straight vertices).
  DPoly::Law turning_law(int type, int centre, double theta);
  DPoly::Law turning_law(const DPoly::VertexState &state, int type, int centre, double theta);

 protected:
  double mean_interior_angle;    // pi - <theta0> when the run started, for equilibrium_angle()
  DPoly::VertexStateCache vertex_state;
};

}    // namespace LAMMPS_NS

#endif
#endif
