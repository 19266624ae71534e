/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// The energy laws of the deformable-polygon model, each written once. Forces (compute()),
// single(), born_matrix(), the Hessian and the breaking barrier all evaluate these functions.
// The operations are those the styles' compute() always did, in the same order, so that forces
// and energies stay bitwise what they were.

#ifndef LMP_DPOLY_LAWS_H
#define LMP_DPOLY_LAWS_H

namespace LAMMPS_NS {
namespace DPoly {

  // A term U(q) in one coordinate q (a distance, an area, an angle) at the given q.
  struct Law {
    double energy;    // U
    double first;     // dU/dq
    double second;    // d2U/dq2
  };

  // A term in a distance r, with what compute() scales the separation vector by: the force on
  // the first atom is fpair * (x1 - x2), fpair = -(dU/dr)/r.
  struct DistanceLaw : Law {
    double fpair;
  };

  // Segment: U = (eps_l/2)(r/l0 - 1)^2.
  inline DistanceLaw segment_law(double eps_l, double r, double l0)
  {
    const double strain = r / l0 - 1.0;
    return {{0.5 * eps_l * strain * strain, eps_l * strain / l0, eps_l / (l0 * l0)},
            -eps_l * strain / (l0 * r)};
  }

  // Contact overlap: U = (eps_c/2)(1 - r/s)^2 for r < s, 0 beyond contact.
  inline DistanceLaw contact_law(double eps_c, double r, double s)
  {
    if (r >= s) return {{0.0, 0.0, 0.0}, 0.0};
    const double overlap = 1.0 - r / s;
    return {{0.5 * eps_c * overlap * overlap, -eps_c * overlap / s, eps_c / (s * s)},
            eps_c * overlap / (s * r)};
  }

  // Adhesion, stretched branch: U = eps_c/(2 z) (1 - r/s)^2 for r > s, 0 up to contact (the
  // overlap belongs to the contact law). It depends on r/s only: U(r, s) = U(r/s, 1).
  inline DistanceLaw adhesion_law(double eps_c, double z, double r, double s)
  {
    if (r <= s) return {{0.0, 0.0, 0.0}, 0.0};
    const double scaled = eps_c / z;
    const double stretch = r / s - 1.0;
    return {{0.5 * scaled * stretch * stretch, scaled * stretch / s, scaled / (s * s)},
            -scaled * stretch / (s * r)};
  }

  // Area of a cell: U = (eps_a/2)(a/a0 - 1)^2, as a function of the area a.
  inline Law area_law(double eps_a, double a, double a0)
  {
    const double strain = a / a0 - 1.0;
    return {0.5 * eps_a * strain * strain, eps_a * strain / a0, eps_a / (a0 * a0)};
  }

  // Bending: U = (eps_b/2)(theta - theta0)^2 in the signed turning angle theta.
  inline Law bending_law(double eps_b, double theta, double theta0)
  {
    const double dtheta = theta - theta0;
    const double torque = eps_b * dtheta;
    return {0.5 * torque * dtheta, torque, eps_b};
  }

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
