/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_DPOLY_HUB_H
#define LMP_FIX_DPOLY_HUB_H

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

// Base of the two hubs, fix dpoly/cells (polygons, 2d) and fix dpoly3d/cells (polyhedra, 3d):
// the course of a run around a hub's own geometry and energy term, written once.
//  - At the setup of every run and minimization: LAMMPS's image-flag check bracketed so that the
//    adhesive bonds leave it once it has been said why (dpoly_image_check.h), then the cells
//    re-read (refresh_cells(): read and checked, their nearest images checked, the adhesive
//    bonds recounted, measured), then the first force evaluation.
//  - At every reneighbouring: the nearest images checked against the image flags.
//  - After every minimization (and MD run, for stages with 'runs yes'): the stage fixes, with
//    the forces of the run's last step kept with their atoms (fix_dpoly_stage.h,
//    dpoly_run_forces.h).
// A concrete hub reads its cells, measures them and adds its per-cell term (area or volume) to
// forces, energy (the fix's scalar) and virial; it also says what it needs of LAMMPS.
class FixDPolyHub : public Fix, public DPoly::CellHub {
 public:
  // 'term': the name of the per-cell energy term, for messages ("area", "volume")
  FixDPolyHub(class LAMMPS *, int, char **, const char *term);
  ~FixDPolyHub() override;

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
  void min_post_force(int) override;
  void post_run() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

  // The cells, identical on every rank, as the hub last read them.
  int ncells() const override { return (int) cell_ids.size(); }
  tagint cell_id(int cell) const override { return cell_ids[cell]; }    // the cell's molecule ID
  int cell_index(tagint molecule) const;    // -1 if the molecule is not a cell

  // Collective: re-read the cells and have the cell-adhesion bond style recount its bonds. Runs
  // by itself at the start of every run and minimize, and after a stage that changed the cells.
  void refresh_cells();

 protected:
  std::vector<tagint> cell_ids;     // sorted molecule IDs of the cells, set by read_cells()
  std::vector<double> unwrapped;    // owned and ghost atoms' unwrapped positions

  // At the end of read_cells(): the index of the molecule IDs in cell_ids (for cell_index()).
  void index_cells();
  // The unwrapped positions of the owned atoms, and of every ghost as its owner has them: the
  // cells as their image flags make them, whichever images this rank holds.
  void share_unwrapped_positions();
  // The error for an atom that an adhesive bond reaches but that is no vertex of the cells.
  [[noreturn]] void not_a_vertex(tagint atom) const;

  // What a concrete hub does. From init(): the dimension, atom style, styles and per-atom
  // values it needs.
  virtual void check_requirements() = 0;
  // The rest in the order refresh_cells() calls them.
  // collective: gather and check the whole system's cells (every rank reaches the same verdict)
  // and set cell_ids, calling index_cells()
  virtual void read_cells() = 0;
  // collective, also at every reneighbouring: the nearest images that the forces use are the
  // ones where the image flags put them (needs share_unwrapped_positions())
  virtual void check_nearest_images() = 0;
  // collective, when the cells are read: whether each fits in the periodic box
  virtual void check_cell_extents() {}
  // collective: the per-cell sizes of the current positions
  virtual void measure_cells() = 0;
  // collective, when the cells are read and measured: their terms are finite, their sizes > 0
  virtual void check_measured_cells() = 0;
  // after each stage that acted after a run, with its FixDPolyStage::Change flags
  virtual void after_stage(int /*change*/) {}
  // the hub itself if it keeps polygons (the stages that act on polygons only use it); virtual,
  // as a dynamic_cast in FixDPolyStage::attach_all would make fix_dpoly_stage.cpp include
  // fix_dpoly_cells.h, which includes fix_dpoly_stage.h: an include cycle
  virtual class FixDPolyCells *polygons() { return nullptr; }

  std::vector<class FixDPolyStage *> find_stages();

 private:
  std::string term;
  std::vector<int> dense_index;                    // molecule ID -> cell, when IDs are dense
  std::unordered_map<tagint, int> sparse_index;    // otherwise
  // keeps the adhesive bonds out of LAMMPS's image-flag check once it has said why
  std::unique_ptr<DPoly::AdhesiveBondsImageCheck> image_check;
  // the last step's forces, kept with their atoms through the stages
  std::unique_ptr<DPoly::RunForces> run_forces;
};

}    // namespace LAMMPS_NS

#endif
