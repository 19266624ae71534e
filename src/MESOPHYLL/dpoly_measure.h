/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// What a compute of the package measures when it is evaluated after a run whose stages
// (fix dpoly/cells: break, grow, refine) changed the tissue at the run's last step.
//
// LAMMPS keeps a compute's value until the next output clears its "invoked" flags, so without
// help a value printed after such a run would be the minimum's when the thermo output had
// evaluated the compute there, and the changed tissue's when it had not. fix dpoly/cells makes
// the answer depend on the compute only: before the stages act it lets each measure take the
// values that describe the minimum, and after they changed the tissue it tells each measure
// to drop the values that no longer describe anything.

#ifndef LMP_DPOLY_MEASURE_H
#define LMP_DPOLY_MEASURE_H

#include "compute.h"

namespace LAMMPS_NS {
namespace DPoly {

  class TissueMeasure {
   public:
    // collective; the run has ended and the stages have not acted yet
    virtual void measure_minimum() {}
    // the stages changed the tissue: values kept from before are not current any more
    virtual void forget_values() {}

   protected:
    ~TissueMeasure() = default;    // computes are deleted as computes, never through this
  };

  // evaluate a compute's global outputs unless the thermo output has at this step
  inline void evaluate_global(Compute *c)
  {
    if (c->vector_flag && !(c->invoked_flag & Compute::INVOKED_VECTOR)) {
      c->compute_vector();
      c->invoked_flag |= Compute::INVOKED_VECTOR;
    }
    if (c->array_flag && !(c->invoked_flag & Compute::INVOKED_ARRAY)) {
      c->compute_array();
      c->invoked_flag |= Compute::INVOKED_ARRAY;
    }
  }

  // make the next use of a compute's per-atom values compute them again (the atoms may have
  // changed, so values indexed by local atom would be another atom's)
  inline void forget_peratom(Compute *c)
  {
    c->invoked_flag &= ~Compute::INVOKED_PERATOM;
    c->invoked_peratom = -1;
  }

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
