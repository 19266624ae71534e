/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_growth_rules.h"

#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "math_const.h"
#include "modify.h"
#include "utils.h"

#include <cstring>

using namespace LAMMPS_NS;

DPoly::GrowthRates::GrowthRates() : theta0_min(-MathConst::MY_PI / 10.0) {}

bool DPoly::GrowthRates::read(LAMMPS *lmp, const char *style, const char *key, const char *value)
{
  Error *error = lmp->error;
  auto at_least_zero = [&]() {
    const double v = utils::numeric(FLERR, value, false, lmp);
    if (!(v >= 0.0)) error->all(FLERR, "Fix {} {} must be >= 0, got {}", style, key, value);
    return v;
  };
  if (strcmp(key, "lambda") == 0)
    lambda = at_least_zero();
  else if (strcmp(key, "c_L") == 0) {
    c_length = at_least_zero();
    if (c_length > 1.0) error->all(FLERR, "Fix {} c_L must be in [0, 1], got {}", style, value);
  } else if (strcmp(key, "c_B") == 0)
    c_bending = at_least_zero();
  else if (strcmp(key, "theta0_min") == 0) {
    theta0_min = utils::numeric(FLERR, value, false, lmp);
    // a lower bound for theta0 at void-facing places, which growth lowers toward it: a vertex's
    // turning angle in 2d, in 3d an edge's bending angle, between its faces' outward normals
    // (pi minus the dihedral angle; doc/dihedral_dpoly3d_hinge.rst)
    const bool polygons = lmp->domain->dimension == 2;
    const char *angle = polygons ? "a turning angle"
                                 : "a bending angle between the faces' outward normals (0 = flat)";
    const char *place = polygons ? "vertices" : "edges";
    // -pi/10 is the paper's value in 2d; in 3d it is this package's default
    const char *source = polygons ? "the paper's" : "the default";
    if (!(theta0_min > -MathConst::MY_PI && theta0_min <= MathConst::MY_PI))
      error->all(FLERR,
                 "Fix {} theta0_min must be {} in (-pi, pi] radians (the lower bound of theta0 "
                 "at void-facing {}; {} is -pi/10), got {}",
                 style, angle, place, source, value);
    if (theta0_min > 0.0 && lmp->comm->me == 0)
      error->warning(FLERR,
                     "Fix {} theta0_min = {} > 0: every void-facing {} whose theta0 is below "
                     "it is raised to it (made convex) instead of bounded; use a value <= 0 ({} "
                     "is -pi/10) unless that is meant",
                     style, value, polygons ? "vertex" : "edge", source);
  } else if (strcmp(key, "scale_sigma") == 0)
    scale_diameters = utils::logical(FLERR, value, false, lmp);
  else if (strcmp(key, "box") == 0) {
    if (strcmp(value, "relax") != 0 && strcmp(value, "fixed") != 0)
      error->all(FLERR, "Fix {} box must be 'relax' or 'fixed', got '{}'", style, value);
    need_box_relax = strcmp(value, "relax") == 0;
  } else
    return false;
  return true;
}

void DPoly::GrowthRates::check_box(LAMMPS *lmp, const char *style, const char *id) const
{
  // the protocol minimizes the enthalpy at constant pressure; growing in a fixed box is a
  // different experiment, and must be asked for
  if (need_box_relax && lmp->modify->get_fix_by_style("^box/relax").empty())
    lmp->error->all(FLERR,
                    "Fix {} {} needs fix box/relax (the growth protocol relaxes the box at "
                    "constant pressure); use 'box fixed' to grow in a fixed box",
                    style, id);
}
