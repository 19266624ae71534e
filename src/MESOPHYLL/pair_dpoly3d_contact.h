/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(dpoly3d/contact,PairDPoly3dContact);
// clang-format on
#else

#ifndef LMP_PAIR_DPOLY3D_CONTACT_H
#define LMP_PAIR_DPOLY3D_CONTACT_H

#include "dpoly3d_state.h"
#include "pair_dpoly_contact.h"

namespace LAMMPS_NS {

// Repulsion between overlapping vertex spheres of deformable polyhedra: the 2d style's law,
// coefficients and restart (pair_dpoly_contact.h), U = (eps_c/2)(1 - r/s)^2 for r < s,
// s = (sigma_i + sigma_j)/2, in three dimensions. Acts between vertices of different cells,
// bonded or not, and between vertices of one cell that no edge joins (switchable); never across
// an edge of a cell's surface.
class PairDPoly3dContact : public PairDPolyContact {
 public:
  PairDPoly3dContact(class LAMMPS *);
  void compute(int, int) override;
  void init_style() override;

 protected:
  // single() and born_matrix() are the 2d style's, with these two answers of this style
  double contact_distance(int i, int j) override;
  // as acts_between() for local atoms i and j, one of them owned, that overlap
  bool interacts(int i, int j, double rsq, double s) const override;

 private:
  DPoly3d::VertexStateCache vertex_state_3d;
  // whether owned atom i and local atom j interact at all (not across an edge of one cell)
  bool acts_between(int i, int j) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
