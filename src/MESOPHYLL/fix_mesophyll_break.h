/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(mesophyll/break,FixMesophyllBreak);
// clang-format on
#else

#ifndef LMP_FIX_MESOPHYLL_BREAK_H
#define LMP_FIX_MESOPHYLL_BREAK_H

#include "dpoly_adhesion.h"
#include "fix_dpoly_stage.h"

#include <vector>

namespace LAMMPS_NS {

// Breaks adhesive bonds once after each energy minimization, never during one (Treado et al.,
// S2): a stretched bond breaks when U_c >= U0, otherwise with probability exp(-beta (U0 - U_c)).
// Bonds are visited in the order of their atom IDs and every random number is a function of
// (seed, break step, the two atom IDs), so the outcome does not depend on the number of ranks.
// The same rule breaks bonds between polygons (fix dpoly/cells) and polyhedra (fix dpoly3d/cells).
class FixMesophyllBreak : public FixDPolyStage {
 public:
  FixMesophyllBreak(class LAMMPS *, int, char **);
  ~FixMesophyllBreak() override;
  void init() override;
  int act() override;
  bool acts_on_polyhedra() const override { return true; }
  double compute_vector(int) override;

  // The uniform number in (0,1) drawn for a bond at a break step (public for the tests).
  static double uniform(int seed, bigint step, tagint atom1, tagint atom2);

 private:
  int seed;
  double beta;          // inverse temperature of stochastic breaking
  double threshold;     // breaking stretch r*/s; U0 = eps_c/(2 z) (r*/s - 1)^2
  int edges_only;       // stochastic test only at the edges of junctions
  bigint break_step;    // number of breaking steps so far: the random stream's step
  bigint start;         // the first breaking step that may break bonds
  bigint broken_total;
  int broken_threshold, broken_stochastic;
  bigint bonds_left;

  struct Broken {
    DPoly::AdhesiveBond bond;
    int stochastic;
  };
  std::vector<Broken> decide(const std::vector<DPoly::AdhesiveBond> &bonds);
  bool at_junction_edge(const DPoly::AdhesiveBond &b, const DPoly::AdhesionCounts &counts) const;
  void store_local_output(const std::vector<Broken> &broken);
  std::vector<double> restart_state() const override;
  bool restore_state(const std::vector<double> &) override;
  double **local_rows;
  class BondMesophyllAdhesion *adhesion;
};

}    // namespace LAMMPS_NS

#endif
#endif
