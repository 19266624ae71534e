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
#include "dpoly_cell_hub.h"
#include "fix.h"

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
namespace DPoly {
  class AdhesiveBondsImageCheck;
  class RunForces;
}    // namespace DPoly

// Hub of the deformable-polyhedron model (3d cells): knows the cells (molecules whose faces,
// LAMMPS angles a b c counter-clockwise from outside, close one surface), checks their surfaces,
// edges and hinges when a run starts, and adds the per-cell volume term
//   U_volume = (eps_v/2) (V/V0 - 1)^2
// to forces, energy and virial. As fix dpoly/cells, it has the cell-adhesion bond style recount
// its bonds when a run starts and runs the stage fixes that act on polyhedra (fix
// mesophyll/break) after every minimization (DPoly::CellHub).
class FixDPoly3dCells : public Fix, public DPoly::CellHub {
 public:
  FixDPoly3dCells(class LAMMPS *, int, char **);
  ~FixDPoly3dCells() override;

  void post_constructor() override;
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void setup_pre_neighbor() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void min_setup(int) override;
  void pre_force(int) override {}
  void min_pre_force(int) override {}
  void pre_neighbor() override;
  void min_pre_neighbor() override;
  void post_force(int) override;
  void min_post_force(int) override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // Per-cell values, identical on every rank, current after the last force evaluation.
  int ncells() const override { return (int) cell_ids.size(); }
  tagint cell_id(int cell) const override { return cell_ids[cell]; }    // the cell's molecule ID
  int cell_index(tagint molecule) const;    // -1 if the molecule is not a cell
  double volume(int cell) const { return volumes[cell]; }
  double surface_area(int cell) const { return surface_areas[cell]; }
  double preferred_volume(int cell) const { return preferred_volumes[cell]; }

  // DPoly::CellHub: sigma, the edge partners, dimension 3
  double *vertex_diameters() override;
  std::vector<tagint> surface_neighbours(tagint atom) const override;
  int cell_dimension() const override { return 3; }

 private:
  double volume_eps;    // eps_v
  double volume_energy;
  DPoly3d::VertexStateCache vertex_state;

  std::vector<tagint> cell_ids;    // sorted molecule IDs of the cells
  std::unordered_map<tagint, int> cell_of_molecule;
  std::vector<int> vertex_counts;
  // every vertex's edge partners (whole system, from the last surface check)
  std::unordered_map<tagint, std::vector<tagint>> edge_partners;
  std::vector<double> preferred_volumes, volumes, surface_areas, volume_slopes;    // dU/dV

  std::vector<double> unwrapped;        // owned and ghost atoms' unwrapped positions
  std::vector<double> volume_forces;    // owned and ghost atoms, reverse-communicated
  // keeps the adhesive bonds out of LAMMPS's image-flag check once it has said why
  std::unique_ptr<DPoly::AdhesiveBondsImageCheck> image_check;
  // the last step's forces, kept with their atoms through the stages
  std::unique_ptr<DPoly::RunForces> run_forces;

  void refresh_cells();
  std::vector<class FixDPolyStage *> find_stages();
  void check_surfaces();
  void share_unwrapped_positions();
  void check_whole_faces();
  void check_finite_terms();
  void measure_cells();
  void apply_volume_forces(int vflag);
  // local indices of the images of a face's wing atoms nearest to its owned middle atom i
  void face_wings(int i, tagint a, tagint c, int &ja, int &jc);
};

}    // namespace LAMMPS_NS

#endif
#endif
