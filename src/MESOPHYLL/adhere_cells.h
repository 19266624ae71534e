/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(adhere_cells,AdhereCells);
// clang-format on
#else

#ifndef LMP_ADHERE_CELLS_H
#define LMP_ADHERE_CELLS_H

#include "command.h"

namespace LAMMPS_NS {

// adhere_cells group-ID btype: bond every overlapping pair of vertices (r < s) that belong to
// different cells, with an adhesive bond of type btype: the initial bonds of the Howto's
// "Contact repulsion and adhesion". Polygons and polyhedra alike (r in the simulation's dimension).
class AdhereCells : public Command {
 public:
  AdhereCells(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
