/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(dpoly/cells,FixDPolyCells);
// clang-format on
#else

#ifndef LMP_FIX_DPOLY_CELLS_H
#define LMP_FIX_DPOLY_CELLS_H

#include "dpoly_ring.h"
#include "fix_dpoly_hub.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

// Hub of the deformable-polygon model: knows the cells (molecules whose vertices form one
// counter-clockwise ring), checks them, and adds the per-cell area term
//   U_area = (eps_a/2) (a/a0 - 1)^2
// to forces, energy and virial. After every minimization it runs the stage fixes (check, break,
// refine before growth, grow, refine: see fix_dpoly_stage.h) in that order, and re-reads the
// rings after a stage that changed them (the course of a run: fix_dpoly_hub.h). Companion
// styles find it with find(); the styles that also adhere polyhedra find it as a DPoly::CellHub.
class FixDPolyCells : public FixDPolyHub {
 public:
  FixDPolyCells(class LAMMPS *, int, char **);

  void post_force(int) override;
  double compute_scalar() override;
  double compute_vector(int) override;
  double memory_usage() override;

  // The hub of this LAMMPS instance, for the companion styles; an error names 'who' if none.
  static FixDPolyCells *find(class LAMMPS *lmp, const std::string &who);

  // Per-cell values, identical on every rank, current after the last force evaluation.
  double area(int cell) const { return areas[cell]; }
  double perimeter(int cell) const { return perimeters[cell]; }
  double preferred_area(int cell) const { return preferred_areas[cell]; }
  double area_stiffness() const { return area_eps; }
  int vertex_count(int cell) const { return vertex_counts[cell]; }

  // Ring neighbours of any vertex of the group, by atom ID (every rank knows all of them).
  struct RingNeighbours {
    tagint prev, next;
  };
  const RingNeighbours &ring_neighbours(tagint atom) const { return rings.at(atom); }
  // A cell's vertex IDs in ring order (counter-clockwise), as found when the rings were checked.
  const std::vector<tagint> &ring(int cell) const { return ring_order[cell]; }

  // DPoly::CellHub: sigma, the ring neighbours, dimension 2
  double *vertex_diameters() override;
  std::vector<tagint> surface_neighbours(tagint atom) const override;
  int cell_dimension() const override { return 2; }

 protected:
  void check_requirements() override;
  void read_cells() override;    // cells, ring order and preferred areas
  void check_nearest_images() override;
  void check_cell_extents() override;
  void measure_cells() override;
  void check_measured_cells() override;
  void after_stage(int change) override;
  FixDPolyCells *polygons() override { return this; }

 private:
  double area_eps;    // eps_a
  double area_energy;

  std::unordered_map<tagint, RingNeighbours> rings;
  std::vector<std::vector<tagint>> ring_order;
  std::vector<int> vertex_counts;
  std::vector<double> preferred_areas, areas, perimeters, area_slopes;    // area_slope = dU/da

  // per owned vertex, minimum-image vectors to the previous and next ring vertex
  std::vector<double> to_prev, to_next;
  // per owned vertex at the last ring check: its ID, its ring neighbours' IDs and the local
  // indices of their nearest images (local indices hold until the next reneighbouring); and
  // the number of owned and ghost atoms then
  struct CheckedRing {
    tagint self, prev, next;
    int prev_image, next_image;
  };
  std::vector<CheckedRing> checked_rings;
  int checked_atoms;
  DPoly::VertexStateCache vertex_state;

  void check_finite_terms();
  // where a recorded image is still the nearest one: closer than these in x and y
  struct NearestImageBounds {
    bool recorded;    // the last ring check recorded the images of the present atom numbering
    bool usable;      // false: search the images (triclinic box, or not recorded)
    double half_box[2];    // half the box length in a periodic direction, else infinity
  };
  bool images_recorded() const;
  NearestImageBounds nearest_image_bounds() const;
  bool checked_images_hold(int i, const NearestImageBounds &bounds, int &prev_image,
                           int &next_image) const;
  void apply_area_forces(int vflag);
};

}    // namespace LAMMPS_NS

#endif
#endif
