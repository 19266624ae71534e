/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(dpoly3d/cells,FixDPoly3dCells);
// clang-format on
#else

#ifndef LMP_FIX_DPOLY3D_CELLS_H
#define LMP_FIX_DPOLY3D_CELLS_H

#include "dpoly3d_state.h"
#include "fix_dpoly_hub.h"

#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

// Hub of the deformable-polyhedron model (3d cells): knows the cells (molecules whose faces,
// LAMMPS angles a b c counter-clockwise from outside, close one surface), checks their surfaces,
// edges and hinges when a run starts, and adds the per-cell volume term
//   U_volume = (eps_v/2) (V/V0 - 1)^2
// to forces, energy and virial. As fix dpoly/cells (the course of a run: fix_dpoly_hub.h), it
// has the cell-adhesion bond style recount its bonds when a run starts and runs the stage fixes
// that act on polyhedra (fix mesophyll/break) after every minimization.
class FixDPoly3dCells : public FixDPolyHub {
 public:
  FixDPoly3dCells(class LAMMPS *, int, char **);

  void post_force(int) override;
  double compute_scalar() override;
  double compute_vector(int) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // Per-cell values, identical on every rank, current after the last force evaluation.
  double volume(int cell) const { return volumes[cell]; }
  double surface_area(int cell) const { return surface_areas[cell]; }
  double preferred_volume(int cell) const { return preferred_volumes[cell]; }

  // DPoly::CellHub: sigma, the edge partners, dimension 3
  double *vertex_diameters() override;
  std::vector<tagint> surface_neighbours(tagint atom) const override;
  int cell_dimension() const override { return 3; }

 protected:
  void check_requirements() override;
  // every vertex, face, edge bond, hinge and edge's values
  void read_cells() override;
  void check_nearest_images() override;    // every face whole
  void measure_cells() override;
  void check_measured_cells() override;

 private:
  double volume_eps;    // eps_v
  double volume_energy;
  DPoly3d::VertexStateCache vertex_state;

  std::vector<int> vertex_counts;
  // every vertex's edge partners (whole system, from the last surface check)
  std::unordered_map<tagint, std::vector<tagint>> edge_partners;
  std::vector<double> preferred_volumes, volumes, surface_areas, volume_slopes;    // dU/dV

  std::vector<double> volume_forces;    // owned and ghost atoms, reverse-communicated

  void apply_volume_forces(int vflag);
  // visit(ja, jc) for every face (angle a b c) centred on the owned atom i = b: the local
  // indices of the images of a and c nearest to it (an error if one is not on this rank)
  template <typename Visit> void for_each_face(int i, Visit &&visit);
};

}    // namespace LAMMPS_NS

#endif
#endif
