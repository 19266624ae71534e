/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Shared step of the styles that change bonds or atoms between runs (bond breaking, vertex
// insertion): rebuild the special lists and bring the ghost atoms back.

#ifndef LMP_DPOLY_TOPOLOGY_H
#define LMP_DPOLY_TOPOLOGY_H

namespace LAMMPS_NS {
class LAMMPS;

namespace DPoly {

  // Collective. Special::build() communicates irregularly and drops the ghost atoms; the
  // minimizer's clean-up still checks bonds against ghosts, so they come back as a run's set-up
  // would bring them (periodic wrap, exchange, borders).
  void rebuild_special_and_ghosts(LAMMPS *lmp);

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
