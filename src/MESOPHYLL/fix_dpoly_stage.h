/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_DPOLY_STAGE_H
#define LMP_FIX_DPOLY_STAGE_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

// Base of the fixes that act on the tissue between two minimizations: checking the minimum,
// breaking bonds, growing cells, refining rings. Such a fix declares its stage and does its work
// in act(); fix dpoly/cells calls the defined stages after every minimization in the protocol's
// fixed order (the order of the stages below, whatever the order of the fix commands), and after
// an MD run only those given 'runs yes'. The base class holds what every stage shares: the hub,
// the 'runs' keyword, and versioned, size-checked global restart data.
class FixDPolyStage : public Fix {
 public:
  enum Stage { CHECK, BREAK, GROW, REFINE };
  // what act() changed, so that the hub can bring LAMMPS's topology and its cells up to date
  enum Change { NOTHING = 0, BONDS = 1, RINGS = 2 };

  FixDPolyStage(class LAMMPS *, int, char **, Stage);
  int setmask() override { return 0; }    // acts only when fix dpoly/cells calls it
  void init() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  Stage stage() const { return my_stage; }
  bool acts_after(int whichflag) const { return whichflag == 2 || (after_runs && whichflag == 1); }
  // Collective: act on the current state; returns the Change flags.
  virtual int act() = 0;

 protected:
  class FixDPolyCells *cells;    // set by init()
  int after_runs;                // also act after MD runs, not only after minimizations

  // Parses a keyword all stages share at arg[iarg]; returns the words it took (0: not one).
  int parse_stage_keyword(int iarg, int narg, char **arg);

  // The global state a stage keeps in restart files, and how it takes it back; restore()
  // returns false if the values cannot be this fix's (their number, for example).
  virtual std::vector<double> restart_state() const { return {}; }
  virtual bool restore_state(const std::vector<double> &) { return true; }

 private:
  Stage my_stage;
};

}    // namespace LAMMPS_NS

#endif
