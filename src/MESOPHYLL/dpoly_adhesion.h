/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Adhesive bonds between cells as a whole-system list, and the contact numbers derived from it.
// Every rank holds the same list, sorted by atom IDs, so that every decision made from it (the
// contact-dependent stiffness, which bond breaks) is the same on any number of ranks.

#ifndef LMP_DPOLY_ADHESION_H
#define LMP_DPOLY_ADHESION_H

#include "lmptype.h"

#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
namespace DPoly {

  struct AdhesiveBond {
    tagint atom1, atom2;    // atom1 < atom2
    tagint cell1, cell2;    // their molecule IDs
    int type;
    double distance, contact;    // r and s = (sigma1 + sigma2)/2 when gathered
    bool operator<(const AdhesiveBond &o) const
    {
      return atom1 < o.atom1 || (atom1 == o.atom1 && atom2 < o.atom2);
    }
  };

  // How a cell's contact number z_mu is counted (model.md section 2).
  enum class ContactRule { BONDS, CELLS };

  // Contact numbers of cells and bond counts of vertices, kept up to date as bonds are removed.
  class AdhesionCounts {
   public:
    void build(const std::vector<AdhesiveBond> &bonds);
    void remove(const AdhesiveBond &bond);

    int vertex_bonds(tagint atom) const { return lookup(per_vertex, atom); }
    int cell_bonds(tagint cell) const { return lookup(per_cell, cell); }
    int cell_contacts(tagint cell) const;
    // the cells bonded to 'cell', each with the number of bonds between them (nullptr: none)
    const std::unordered_map<tagint, int> *bonded_cells(tagint cell) const
    {
      const auto found = between_cells.find(cell);
      return found == between_cells.end() ? nullptr : &found->second;
    }
    double contact_number(tagint cell, ContactRule rule) const
    {
      return rule == ContactRule::BONDS ? cell_bonds(cell) : cell_contacts(cell);
    }
    // z_munu = (z_mu + z_nu)/2 + 1
    double pair_contact_number(tagint cell1, tagint cell2, ContactRule rule) const
    {
      return 0.5 * (contact_number(cell1, rule) + contact_number(cell2, rule)) + 1.0;
    }

   private:
    std::unordered_map<tagint, int> per_vertex, per_cell;
    std::unordered_map<tagint, std::unordered_map<tagint, int>> between_cells;
    static int lookup(const std::unordered_map<tagint, int> &m, tagint key)
    {
      const auto found = m.find(key);
      return found == m.end() ? 0 : found->second;
    }
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
