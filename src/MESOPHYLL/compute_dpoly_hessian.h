/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(dpoly/hessian,ComputeDPolyHessian);
// clang-format on
#else

#ifndef LMP_COMPUTE_DPOLY_HESSIAN_H
#define LMP_COMPUTE_DPOLY_HESSIAN_H

#include "compute.h"
#include "dpoly_measure.h"
#include "dpoly_ring.h"

#include <vector>

namespace LAMMPS_NS {

// Mechanical stability of a deformable-polygon tissue: the Hessian of the total energy (area,
// segment, bending, contact and adhesion terms) over the vertex positions at fixed box,
// assembled analytically and diagonalized with Eigen (dense). Gives its lowest eigenvalues and
// the number of zero modes besides the two global translations.
class ComputeDPolyHessian : public Compute, public DPoly::TissueMeasure {
 public:
  ComputeDPolyHessian(class LAMMPS *, int, char **);
  ~ComputeDPolyHessian() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_array() override;    // the Hessian itself, on every rank
  void forget_values() override;

 private:
  int nmodes;           // eigenvalues reported
  double zero_level;    // |eigenvalue| below this is a zero mode
  int max_dof;          // largest matrix diagonalized (dense)
  double zero_modes;    // of the last diagonalization, translations excluded
  bigint last_diagonalized;
  bool diagonalized_once;
  std::vector<double> matrix;    // storage of the global array
  std::vector<double *> rows;
  DPoly::VertexStateCache vertex_state;
  std::vector<double> assemble();
  void diagonalize();
};

}    // namespace LAMMPS_NS

#endif
#endif
