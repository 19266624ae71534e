/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// LAMMPS's image-flag check (Domain::image_check(), run at the setup of every run and every
// minimization) warns "Inconsistent image flags" when the two atoms of a bond, unwrapped by their
// image flags, lie more than half a box length apart. The adhesive bonds of a tissue cannot all
// pass it: the bonded cells form a network that closes around the periodic box, and no choice of
// image flags makes every bond of a closed loop around the box short. So a development run would
// warn at every one of its minimizations, although every style uses the nearest image and is not
// affected. This class lets LAMMPS warn the first time, says once in the package's own words why,
// and from then on hides the adhesive bonds, and only them, from that check: between the hub's
// setup_pre_exchange() and setup_pre_neighbor(), which bracket the check in Verlet::setup(),
// Min::setup() and their setup_minimal(), their bond types are stored as -(type + nbondtypes),
// below every type LAMMPS itself uses (it marks turned-off bonds by type <= 0, down to
// -nbondtypes), which image_check() and box_too_small_check() skip. Ring segments (surface edges
// in 3d) and every other bond stay in the check, so a cell with inconsistent image flags is still
// reported. Both hubs, fix dpoly/cells and fix dpoly3d/cells, use it through their common base
// (fix_dpoly_hub.h).

#ifndef LMP_DPOLY_IMAGE_CHECK_H
#define LMP_DPOLY_IMAGE_CHECK_H

#include "pointers.h"

#include <vector>

namespace LAMMPS_NS {
namespace DPoly {

  class AdhesiveBondsImageCheck : protected Pointers {
   public:
    explicit AdhesiveBondsImageCheck(class LAMMPS *lmp);

    // Before LAMMPS's check, at the setup of a run or minimization: hide the adhesive bonds
    // from it once the reason has been given. Anywhere else (write_data also calls the fixes'
    // setup_pre_exchange()) nothing is hidden, as no setup_pre_neighbor() would follow.
    void before_check();
    // Right after it, before the neighbour lists are built: give the adhesive bonds their
    // types back. The hub's destructor calls it too.
    void after_check();
    // From the hub's init(), which LAMMPS calls before every setup and in write_data: an error
    // thrown inside the window (e.g. non-finite coordinates in Domain::pbc()) and caught by a
    // library caller leaves the types hidden and LAMMPS's update->setupflag at 1, so write_data's
    // setup_pre_exchange() would look like a setup's. Give the types back, and hide nothing
    // until a setup has ended normally again.
    void init();
    // Collective, after after_check(), until explained(): the first time adhesive bonds are
    // inconsistent, say why LAMMPS warned and hide them from the check from then on.
    // 'unwrapped' holds 3 coordinates per owned and ghost atom, a ghost's as its owner has them.
    void explain_once(const std::vector<double> &unwrapped);
    bool explained() const { return reason_given; }

   private:
    bool reason_given;
    bool hidden;
    bool setup_flag_stale;    // update->setupflag was left at 1 by an error
    // collective: adhesive bonds whose atoms, unwrapped, lie more than half a box apart, and all
    void count_inconsistent(const std::vector<double> &unwrapped, bigint counts[2]);
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
