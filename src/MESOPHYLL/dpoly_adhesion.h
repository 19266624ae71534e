/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Adhesive bonds between cells as a whole-system list, the bond counts derived from it, and the
// interface through which the generic DP styles read them from whichever bond style adheres
// cells (bond_style mesophyll/adhesion implements it). Every rank holds the same list, sorted by
// atom IDs, so that every decision made from it is the same on any number of ranks.

#ifndef LMP_DPOLY_ADHESION_H
#define LMP_DPOLY_ADHESION_H

#include "lmptype.h"

#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;

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

  // Bonds per vertex and per cell and the cells bonded to each cell, kept up to date as bonds
  // are removed.
  class AdhesionCounts {
   public:
    void build(const std::vector<AdhesiveBond> &bonds);
    void remove(const AdhesiveBond &bond);

    int vertex_bonds(tagint atom) const { return lookup(per_vertex, atom); }
    // a vertex without adhesive bonds faces air: growth and refinement act there
    bool void_facing(tagint atom) const { return vertex_bonds(atom) == 0; }
    int cell_bonds(tagint cell) const { return lookup(per_cell, cell); }
    int cell_contacts(tagint cell) const;    // number of distinct cells bonded to 'cell'
    // the cells bonded to 'cell', each with the number of bonds between them (nullptr: none)
    const std::unordered_map<tagint, int> *bonded_cells(tagint cell) const
    {
      const auto found = between_cells.find(cell);
      return found == between_cells.end() ? nullptr : &found->second;
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

  // What a bond style that adheres cells offers the generic styles: its current counts, a
  // collective recount from the bonds (fix dpoly/cells asks for it whenever it re-reads cells),
  // and the bonds themselves.
  class CellAdhesion {
   public:
    virtual ~CellAdhesion() noexcept(false) {}    // as LAMMPS styles: they may throw
    virtual const AdhesionCounts &counts() const = 0;
    virtual void recount() = 0;
    // Collective: every adhesive bond of the system at its current length, sorted by IDs.
    virtual std::vector<AdhesiveBond> gather_bonds() = 0;
    // Whether bonds of this bond type are adhesive bonds of this style.
    virtual bool is_adhesive_type(int type) const = 0;
  };

  // The cell-adhesion bond style of this LAMMPS instance, alone or in bond_style hybrid, or
  // nullptr if there is none.
  CellAdhesion *find_cell_adhesion(LAMMPS *lmp);
  // Its counts, or empty counts (every vertex void-facing) if there is no such style.
  const AdhesionCounts &adhesion_counts(LAMMPS *lmp);
  // Collective: its bonds, or none if there is no such style.
  std::vector<AdhesiveBond> gather_adhesive_bonds(LAMMPS *lmp);

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
