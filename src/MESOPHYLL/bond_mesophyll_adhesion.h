/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(mesophyll/adhesion,BondMesophyllAdhesion);
// clang-format on
#else

#ifndef LMP_BOND_MESOPHYLL_ADHESION_H
#define LMP_BOND_MESOPHYLL_ADHESION_H

#include "bond.h"
#include "dpoly_adhesion.h"
#include "dpoly_ring.h"

#include <vector>

namespace LAMMPS_NS {

// Contact-dependent adhesion between vertices of two cells (Treado et al., eq. 2 and S2):
//   U = eps_c/(2 z_munu) (1 - r/s)^2 for a stretched bond (r > s), 0 otherwise,
// z_munu = (z_mu + z_nu)/2 + 1. Overlap (r < s) is left to pair dpoly/contact, so that no pair
// is counted twice. The contact numbers are those of fix dpoly/cells, fixed during a run.
class BondMesophyllAdhesion : public Bond {
 public:
  BondMesophyllAdhesion(class LAMMPS *);
  ~BondMesophyllAdhesion() override;
  void settings(int, char **) override;
  void init_style() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void born_matrix(int, double, int, int, double &, double &) override;
  void *extract(const char *, int &) override;

  // Collective: every adhesive bond of the system with its current stretch, sorted by IDs.
  std::vector<DPoly::AdhesiveBond> gather_bonds();
  bool is_adhesive_type(int type) const { return allocated && type > 0 && setflag[type]; }
  double stiffness(int type) const { return contact_stiffness[type]; }
  DPoly::ContactRule contact_rule() const { return rule; }

 protected:
  double *contact_stiffness;    // eps_c per bond type
  DPoly::ContactRule rule;
  class FixDPolyCells *cells;
  DPoly::VertexStateCache vertex_state;
  void allocate();
  double contact_number(int i, int j);
};

}    // namespace LAMMPS_NS

#endif
#endif
