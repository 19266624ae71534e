/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// What the styles that join and part cells (bond_style mesophyll/adhesion, adhere_cells,
// fix mesophyll/break) need from the hub that keeps the cells, whichever model it is: polygons
// (fix dpoly/cells, 2d) or polyhedra (fix dpoly3d/cells, 3d). In both a cell is a molecule, every
// vertex a soft disk or sphere of diameter sigma, and the hub has the cell-adhesion bond style
// recount its bonds whenever it re-reads the cells (every run start) and runs the stage fixes
// after every minimization.

#ifndef LMP_DPOLY_CELL_HUB_H
#define LMP_DPOLY_CELL_HUB_H

#include "lmptype.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;

namespace DPoly {

  class CellHub {
   public:
    virtual ~CellHub() noexcept(false) {}    // as LAMMPS styles: they may throw

    // the cells (molecule IDs, sorted), identical on every rank, as the hub last read them
    virtual int ncells() const = 0;
    virtual tagint cell_id(int cell) const = 0;
    // sigma of the owned and ghost vertices; fetch again after atoms migrate
    virtual double *vertex_diameters() = 0;
    // IDs of the vertices joined to vertex 'atom' by its cell's surface: its ring predecessor
    // and successor in 2d, its edge partners in 3d (every rank knows all, from the last time the
    // hub read the cells)
    virtual std::vector<tagint> surface_neighbours(tagint atom) const = 0;
    // 2 for polygons, 3 for polyhedra
    virtual int cell_dimension() const = 0;

    // The hub of this LAMMPS instance, or nullptr if there is none.
    static CellHub *find_any(LAMMPS *lmp);
    // As find_any(), but an error that names 'who' if there is none.
    static CellHub *find(LAMMPS *lmp, const std::string &who);
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
