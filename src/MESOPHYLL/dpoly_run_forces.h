/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// The forces of a run's last step (a minimization's minimum), kept with their atoms while the
// stages act after the run (FixDPolyStage::act_after_run()). A stage that changes bonds or
// per-vertex values has the atoms migrated to the ranks whose subdomains hold them now
// (DPoly::refresh_ghosts()), and LAMMPS moves no forces with migrating atoms: on several ranks
// atom->f would then hold other atoms' forces, or none, and what reads it after the run (thermo
// fnorm and fmax, the minimizer's final force norm in its statistics, a dump of fx) would be
// wrong, while pe, press and the package's computes still describe the minimum. The forces
// travel in an internal fix STORE/ATOM, idle (it moves nothing) outside the stages. A vertex a
// stage added did not exist at the minimum: its force is zero.

#ifndef LMP_DPOLY_RUN_FORCES_H
#define LMP_DPOLY_RUN_FORCES_H

#include "pointers.h"

#include <string>

namespace LAMMPS_NS {
class FixStoreAtom;

namespace DPoly {

  class RunForces : protected Pointers {
   public:
    // from the hub's post_constructor(): the store is a fix named after the hub's ID
    RunForces(class LAMMPS *lmp, const std::string &hub_id);
    ~RunForces() noexcept(false);
    RunForces(const RunForces &) = delete;
    RunForces &operator=(const RunForces &) = delete;

    // collective, before the stages: the owned atoms' forces travel with them from now on
    void keep();
    // collective, after the stages: every owned atom gets its force back
    void put_back();

   private:
    FixStoreAtom *find_store();    // the store, or error->all if it was unfixed
    std::string store_id;
    tagint last_kept_tag;    // the largest atom ID at keep(): larger ones were added since
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
