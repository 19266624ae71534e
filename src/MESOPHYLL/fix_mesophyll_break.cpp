/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_mesophyll_break.h"

#include "atom.h"
#include "bond_mesophyll_adhesion.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "dpoly_topology.h"
#include "error.h"
#include "fix_dpoly_cells.h"
#include "force.h"
#include "memory.h"
#include "update.h"

#include <Random123/philox.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <utility>

using namespace LAMMPS_NS;
using namespace FixConst;
using DPoly::AdhesiveBond;

FixMesophyllBreak::FixMesophyllBreak(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), beta(100.0), threshold(1.0 + sqrt(2.0)), edges_only(1), after_runs(0),
    break_step(0), broken_total(0), broken_threshold(0), broken_stochastic(0), bonds_left(0),
    local_rows(nullptr), adhesion(nullptr), cells(nullptr)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix mesophyll/break", error);
  seed = utils::inumeric(FLERR, arg[3], false, lmp);
  if (seed <= 0) error->all(FLERR, "Fix mesophyll/break seed must be > 0, got {}", arg[3]);
  int iarg = 4;
  while (iarg < narg) {
    if (iarg + 2 > narg)
      utils::missing_cmd_args(FLERR, std::string("fix mesophyll/break ") + arg[iarg], error);
    if (strcmp(arg[iarg], "beta") == 0) {
      beta = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (beta <= 0.0)
        error->all(FLERR, "Fix mesophyll/break beta must be > 0, got {}", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "threshold") == 0) {
      threshold = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (threshold <= 1.0)
        error->all(FLERR,
                   "Fix mesophyll/break threshold (breaking stretch r*/s) must be > 1, "
                   "got {}",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "edges") == 0) {
      edges_only = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    } else if (strcmp(arg[iarg], "runs") == 0) {
      after_runs = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    } else
      error->all(FLERR, "Unknown fix mesophyll/break keyword: {}", arg[iarg]);
    iarg += 2;
  }

  vector_flag = 1;
  size_vector = 5;
  extvector = 0;
  global_freq = 1;
  local_flag = 1;
  size_local_cols = 5;
  local_freq = 1;
  size_local_rows = 0;
  restart_global = 1;
}

FixMesophyllBreak::~FixMesophyllBreak()
{
  memory->destroy(local_rows);
}

int FixMesophyllBreak::setmask()
{
  return 0;    // acts in post_run(), which every fix receives
}

void FixMesophyllBreak::init()
{
  adhesion = dynamic_cast<BondMesophyllAdhesion *>(force->bond_match("mesophyll/adhesion"));
  if (!adhesion)
    error->all(FLERR,
               "Fix mesophyll/break needs bond_style mesophyll/adhesion (alone or in hybrid)");
  cells = FixDPolyCells::find(lmp, "Fix mesophyll/break");
}

// after a minimization (update->whichflag == 2), never inside one
void FixMesophyllBreak::post_run()
{
  if (update->whichflag == 2 || (after_runs && update->whichflag == 1)) break_bonds();
}

double FixMesophyllBreak::uniform(int seed, bigint step, tagint atom1, tagint atom2)
{
  using Philox = r123::Philox4x32;
  const auto a1 = (uint64_t) atom1, a2 = (uint64_t) atom2, st = (uint64_t) step;
  const Philox::ctr_type counter = {
      {(uint32_t) st, (uint32_t) a1, (uint32_t) a2,
       (uint32_t) (st >> 32) ^ (uint32_t) (a1 >> 32) ^ ((uint32_t) (a2 >> 32) << 16)}};
  const Philox::key_type key = {{(uint32_t) seed, 0x4d455350u}};    // "MESP": this use only
  const Philox::ctr_type bits = Philox()(counter, key);
  return (bits[0] + 0.5) * (1.0 / 4294967296.0);
}

bool FixMesophyllBreak::at_junction_edge(const AdhesiveBond &b,
                                         const DPoly::AdhesionCounts &counts) const
{
  for (tagint atom : {b.atom1, b.atom2}) {
    const auto &ring = cells->ring_neighbours(atom);
    if (counts.vertex_bonds(ring.prev) == 0 || counts.vertex_bonds(ring.next) == 0) return true;
  }
  return false;
}

// The same sequential pass on every rank; contact numbers change as bonds break, as in the
// authors' code.
std::vector<FixMesophyllBreak::Broken>
FixMesophyllBreak::decide(const std::vector<AdhesiveBond> &bonds)
{
  DPoly::AdhesionCounts counts;
  counts.build(bonds);
  std::vector<Broken> broken;
  for (const auto &b : bonds) {
    if (b.distance <= b.contact) continue;    // compressed or touching: tension only
    const double z = counts.pair_contact_number(b.cell1, b.cell2, adhesion->contact_rule());
    const double energy =
        DPoly::adhesion_law(adhesion->stiffness(b.type), z, b.distance, b.contact).energy;
    // the law depends on r/s only: the barrier is its energy at r/s = threshold
    const double barrier =
        DPoly::adhesion_law(adhesion->stiffness(b.type), z, threshold, 1.0).energy;
    bool breaks = false;
    int stochastic = 0;
    if (energy >= barrier)
      breaks = true;
    else if (!edges_only || at_junction_edge(b, counts)) {
      breaks = uniform(seed, break_step, b.atom1, b.atom2) < exp(-beta * (barrier - energy));
      stochastic = 1;
    }
    if (breaks) {
      counts.remove(b);
      broken.push_back({b, stochastic});
    }
  }
  return broken;
}

void FixMesophyllBreak::break_bonds()
{
  if (!adhesion || !cells) init();
  break_step++;
  const std::vector<AdhesiveBond> bonds = adhesion->gather_bonds();
  const std::vector<Broken> broken = decide(bonds);

  broken_threshold = broken_stochastic = 0;
  for (const auto &k : broken) (k.stochastic ? broken_stochastic : broken_threshold)++;
  broken_total += (bigint) broken.size();
  bonds_left = (bigint) (bonds.size() - broken.size());

  store_local_output(broken);    // before Special, whose communication drops the ghost atoms
  if (!broken.empty()) {
    remove_bonds(broken);
    DPoly::rebuild_special_and_ghosts(lmp);
  }
  std::vector<AdhesiveBond> survivors;
  size_t next_broken = 0;
  for (const auto &b : bonds) {    // both lists are in bond order
    if (next_broken < broken.size() && broken[next_broken].bond.atom1 == b.atom1 &&
        broken[next_broken].bond.atom2 == b.atom2)
      next_broken++;
    else
      survivors.push_back(b);
  }
  cells->set_adhesion(survivors);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "fix mesophyll/break: step {}: {} bonds broke ({} at threshold, {} "
                   "stochastic), {} adhesive bonds left\n",
                   break_step, broken.size(), broken_threshold, broken_stochastic, bonds_left);
}

void FixMesophyllBreak::remove_bonds(const std::vector<Broken> &broken)
{
  auto key = [](tagint a, tagint b) {
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  std::set<std::pair<tagint, tagint>> gone;
  for (const auto &k : broken) gone.insert(key(k.bond.atom1, k.bond.atom2));

  for (int i = 0; i < atom->nlocal; i++) {
    int m = 0;
    while (m < atom->num_bond[i]) {
      const int type = atom->bond_type[i][m];
      if (adhesion->is_adhesive_type(type) &&
          gone.count(key(atom->tag[i], atom->bond_atom[i][m]))) {
        const int last = --atom->num_bond[i];
        atom->bond_type[i][m] = atom->bond_type[i][last];
        atom->bond_atom[i][m] = atom->bond_atom[i][last];
      } else
        m++;
    }
  }
  atom->nbonds -= (bigint) broken.size();
}

// Each rank lists the broken bonds whose first atom it owns: atom1, atom2, step, r/s, how.
void FixMesophyllBreak::store_local_output(const std::vector<Broken> &broken)
{
  int rows = 0;
  for (const auto &k : broken)
    if (atom->map(k.bond.atom1) >= 0 && atom->map(k.bond.atom1) < atom->nlocal) rows++;
  memory->destroy(local_rows);
  memory->create(local_rows, std::max(rows, 1), size_local_cols, "mesophyll/break:local_rows");
  int n = 0;
  for (const auto &k : broken) {
    const int i = atom->map(k.bond.atom1);
    if (i < 0 || i >= atom->nlocal) continue;
    local_rows[n][0] = k.bond.atom1;
    local_rows[n][1] = k.bond.atom2;
    local_rows[n][2] = break_step;
    local_rows[n][3] = k.bond.distance / k.bond.contact;
    local_rows[n][4] = k.stochastic ? 2 : 1;
    n++;
  }
  size_local_rows = rows;
  array_local = local_rows;
}

double FixMesophyllBreak::compute_vector(int n)
{
  switch (n) {
    case 0:
      return broken_threshold;
    case 1:
      return broken_stochastic;
    case 2:
      return bonds_left;
    case 3:
      return broken_total;
    default:
      return break_step;
  }
}

void FixMesophyllBreak::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  double state[3] = {(double) break_step, (double) broken_total, (double) bonds_left};
  int size = sizeof(state);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(state, sizeof(double), 3, fp);
}

void FixMesophyllBreak::restart(char *buf)
{
  auto *state = (double *) buf;
  break_step = (bigint) state[0];
  broken_total = (bigint) state[1];
  bonds_left = (bigint) state[2];
}
