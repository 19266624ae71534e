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
#include "dpoly_cell_hub.h"
#include "dpoly_stiffness.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// Contact-dependent adhesion between vertices of two cells (Treado et al., eq. 2 and S2):
//   U = eps_c/(2 z_munu) (1 - r/s)^2 for a stretched bond (r > s), 0 otherwise,
// z_munu = (z_mu + z_nu)/2 + 1. Overlap (r < s) is left to pair dpoly/contact, so that no pair
// is counted twice. The style owns the table of adhesive bonds per vertex and per cell: it is
// recounted whenever the hub (fix dpoly/cells or fix dpoly3d/cells) re-reads the cells (every
// run start) and is fixed during a run; bonds leave it only through remove_bonds(). The same law
// joins polygons and polyhedra: r is the distance in the simulation's dimension.
class BondMesophyllAdhesion : public DPoly::PerTypeStiffness<Bond>, public DPoly::CellAdhesion {
 public:
  BondMesophyllAdhesion(class LAMMPS *);
  void settings(int, char **) override;
  void init_style() override;
  void compute(int, int) override;
  double equilibrium_distance(int) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double single(int, double, int, int, double &) override;
  void born_matrix(int, double, int, int, double &, double &) override;

  // The style of this LAMMPS instance (alone or in hybrid); an error names 'who' if none.
  static BondMesophyllAdhesion *find(class LAMMPS *lmp, const std::string &who);

  // Collective: every adhesive bond of the system with its current stretch, sorted by IDs.
  std::vector<DPoly::AdhesiveBond> gather_bonds() override;
  bool is_adhesive_type(int type) const override { return allocated && type > 0 && setflag[type]; }

  // The current bond counts, and a collective recount from the bonds (DPoly::CellAdhesion).
  const DPoly::AdhesionCounts &counts() const override { return contacts; }
  void recount() override;
  // Collective: delete these bonds (a whole-system list, the same on every rank) from the atoms
  // and from the counts. The caller rebuilds the special lists.
  void remove_bonds(const std::vector<DPoly::AdhesiveBond> &gone);

  // The paper's contact number of a bonded pair of cells under the chosen z rule (eq. S2):
  // z_munu = (z_mu + z_nu)/2 + 1, z_mu = bonds of the cell (z bonds) or cells bonded to it
  // (z cells), counted in 'from'.
  double contact_number(const DPoly::AdhesionCounts &from, tagint cell1, tagint cell2) const;

 protected:
  enum class ContactRule { BONDS, CELLS };
  ContactRule rule;
  DPoly::AdhesionCounts contacts;
  double *vertex_diameters();
  double contact_number(int i, int j);
};

}    // namespace LAMMPS_NS

#endif
#endif
