/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_DPOLY_STAGE_H
#define LMP_FIX_DPOLY_STAGE_H

#include "dpoly_cell_hub.h"
#include "dpoly_run_forces.h"
#include "fix.h"

#include <functional>
#include <vector>

namespace LAMMPS_NS {

// Base of the fixes that act on the tissue between two minimizations: checking the minimum,
// breaking bonds, growing cells, refining rings. Such a fix declares its stage and does its work
// in act(); the hub (fix dpoly/cells, or fix dpoly3d/cells for the stages that act on polyhedra)
// calls the defined stages after every minimization in the protocol's fixed order (the order of
// the stages below, whatever the order of the fix commands), and after an MD run only those given
// 'runs yes'. Refinement has two places, before growth (where the published code inserts
// vertices, at the radii of the minimum) and after it. The base class holds what every stage
// shares: the hub, the 'runs' keyword, its global vector, and versioned, size-checked global
// restart data; and, for both hubs, how the stages are found and run.
class FixDPolyStage : public Fix {
 public:
  enum Stage { CHECK, BREAK, REFINE_BEFORE_GROWTH, GROW, REFINE };
  // what act() changed, so that the hub can bring LAMMPS's topology and its cells up to date
  // (STATE: per-vertex values, whose ghost copies the next stage may read)
  enum Change { NOTHING = 0, STATE = 1, BONDS = 2, RINGS = 4 };

  // every stage reports what it did as a global, intensive vector of this many values
  FixDPolyStage(class LAMMPS *, int, char **, Stage, int vector_length);
  int setmask() override { return 0; }    // acts only when fix dpoly/cells calls it
  void init() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  Stage stage() const { return my_stage; }
  // the hub hands itself to its stages when it initializes, before any act(); 'polygons' is
  // the same hub when it is fix dpoly/cells, nullptr when it keeps polyhedra
  void attach(DPoly::CellHub *cell_hub, class FixDPolyCells *polygons)
  {
    hub = cell_hub;
    cells = polygons;
  }
  bool acts_after(int whichflag) const { return whichflag == 2 || (after_runs && whichflag == 1); }
  // Collective: act on the current state; returns the Change flags.
  virtual int act() = 0;
  // whether this stage acts on polyhedra (fix dpoly3d/cells) as well as on polygons
  virtual bool acts_on_polyhedra() const { return false; }

  // The stage fixes of the hub 'hub_fix' (also 'hub') in the order they act, attached to it; an
  // error if one is defined on another group than the hub's. Found again at every use, as
  // 'unfix' between runs (with 'run pre no', which skips init()) may have deleted one.
  static std::vector<FixDPolyStage *> attach_all(class LAMMPS *lmp, Fix *hub_fix,
                                                 DPoly::CellHub *hub,
                                                 class FixDPolyCells *polygons);
  // Collective, from a hub's post_run(): the stages that act after this run (minimization, or MD
  // for 'runs yes'), in order. A stage that changed bonds or atoms gets the special lists and
  // ghost atoms rebuilt, one that changed per-vertex values its ghost atoms, before the next
  // stage reads them; then 'after_change' (the hub's own bookkeeping) sees its Change flags.
  // The package's computes take the minimum's values first and drop what the stages made stale
  // (dpoly_measure.h); the forces of the run's last step go with their atoms through the stages
  // (dpoly_run_forces.h); the minimizer's vectors are reset if anything changed.
  static void act_after_run(class LAMMPS *lmp, const std::vector<FixDPolyStage *> &stages,
                            DPoly::RunForces &run_forces,
                            const std::function<void(int change)> &after_change);

 protected:
  DPoly::CellHub *hub;           // the hub that calls act()
  class FixDPolyCells *cells;    // the same hub if it keeps polygons, else nullptr
  int after_runs;                // also act after MD runs, not only after minimizations

  // Reads the keyword/value pairs arg[first..narg): 'runs' here (not for the check, which reads
  // the minimizer), the stage's own through 'keyword', which returns false for one it does not
  // know. An odd word or an unknown keyword is an error that names it.
  using KeywordReader = std::function<bool(const char *key, const char *value)>;
  void parse_keywords(int first, int narg, char **arg, const KeywordReader &keyword);
  // 0 if value is the word 'first', 1 if it is 'second'; otherwise an error naming key and value
  int one_of(const char *key, const char *value, const char *first, const char *second);
  // a stage whose place depends on its keywords takes it after parsing them
  void move_to(Stage stage) { my_stage = stage; }

  // The global state a stage keeps in restart files, and how it takes it back; restore()
  // returns false if the values cannot be this fix's (their number, for example).
  virtual std::vector<double> restart_state() const { return {}; }
  virtual bool restore_state(const std::vector<double> &) { return true; }

 private:
  Stage my_stage;
};

}    // namespace LAMMPS_NS

#endif
