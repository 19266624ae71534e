/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_mesophyll_break.h"

#include "atom.h"
#include "bond_mesophyll_adhesion.h"
#include "comm.h"
#include "dpoly_laws.h"
#include "error.h"
#include "memory.h"

#include <Random123/philox.h>

#include <cmath>
#include <cstdint>
#include <cstring>

using namespace LAMMPS_NS;
using DPoly::AdhesiveBond;

FixMesophyllBreak::FixMesophyllBreak(LAMMPS *lmp, int narg, char **arg) :
    FixDPolyStage(lmp, narg, arg, BREAK, 5), beta(100.0), threshold(1.0 + sqrt(2.0)), edges_only(1),
    break_step(0), start(1), broken_total(0), broken_threshold(0), broken_stochastic(0),
    bonds_left(0), local_rows(nullptr), adhesion(nullptr)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix mesophyll/break", error);
  seed = utils::inumeric(FLERR, arg[3], false, lmp);
  if (seed <= 0) error->all(FLERR, "Fix mesophyll/break seed must be > 0, got {}", arg[3]);
  parse_keywords(4, narg, arg, [&](const char *key, const char *value) {
    if (strcmp(key, "beta") == 0) {
      beta = utils::numeric(FLERR, value, false, lmp);
      if (beta <= 0.0) error->all(FLERR, "Fix mesophyll/break beta must be > 0, got {}", value);
    } else if (strcmp(key, "threshold") == 0) {
      threshold = utils::numeric(FLERR, value, false, lmp);
      if (threshold <= 1.0)
        error->all(FLERR,
                   "Fix mesophyll/break threshold (breaking stretch r*/s) must be > 1, got {}",
                   value);
    } else if (strcmp(key, "edges") == 0) {
      edges_only = utils::logical(FLERR, value, false, lmp);
    } else if (strcmp(key, "start") == 0) {
      start = utils::bnumeric(FLERR, value, false, lmp);
      if (start < 1) error->all(FLERR, "Fix mesophyll/break start must be >= 1, got {}", value);
    } else
      return false;
    return true;
  });

  local_flag = 1;
  size_local_cols = 5;
  local_freq = 1;
  size_local_rows = 0;
}

FixMesophyllBreak::~FixMesophyllBreak()
{
  memory->destroy(local_rows);
}

void FixMesophyllBreak::init()
{
  FixDPolyStage::init();
  adhesion = BondMesophyllAdhesion::find(lmp, "Fix mesophyll/break");
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

// at the edge of a junction: a surface neighbour (ring neighbour in 2d, edge partner in 3d) of
// either bonded vertex has no adhesive bond, i.e. faces air
bool FixMesophyllBreak::at_junction_edge(const AdhesiveBond &b,
                                         const DPoly::AdhesionCounts &counts) const
{
  for (tagint atom : {b.atom1, b.atom2})
    for (tagint neighbour : hub->surface_neighbours(atom))
      if (counts.vertex_bonds(neighbour) == 0) return true;
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
    const double z = adhesion->contact_number(counts, b.cell1, b.cell2);
    const double energy =
        DPoly::adhesion_law(adhesion->type_stiffness(b.type), z, b.distance, b.contact).energy;
    // the law depends on r/s only: the barrier is its energy at r/s = threshold
    const double barrier =
        DPoly::adhesion_law(adhesion->type_stiffness(b.type), z, threshold, 1.0).energy;
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

// after a minimization, never inside one (or after an MD run, with 'runs yes')
int FixMesophyllBreak::act()
{
  break_step++;
  const std::vector<AdhesiveBond> bonds = adhesion->gather_bonds();
  // passes before 'start' count (the random stream's step) but break nothing: the published
  // code's first breaking pass follows its first growth step, and a development's first
  // minimum is the relaxed tissue before it
  const std::vector<Broken> broken = break_step < start ? std::vector<Broken>() : decide(bonds);

  broken_threshold = broken_stochastic = 0;
  for (const auto &k : broken) (k.stochastic ? broken_stochastic : broken_threshold)++;
  broken_total += (bigint) broken.size();
  bonds_left = (bigint) (bonds.size() - broken.size());

  store_local_output(broken);
  if (!broken.empty()) {
    std::vector<AdhesiveBond> gone;
    for (const auto &k : broken) gone.push_back(k.bond);
    adhesion->remove_bonds(gone);
  }
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "fix mesophyll/break: step {}: {} bonds broke ({} at threshold, {} "
                   "stochastic{}), {} adhesive bonds left\n",
                   break_step, broken.size(), broken_threshold, broken_stochastic,
                   break_step < start ? fmt::format("; none before step {}", start) : "",
                   bonds_left);
  return broken.empty() ? NOTHING : BONDS;
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
  const double values[] = {(double) broken_threshold, (double) broken_stochastic,
                           (double) bonds_left, (double) broken_total, (double) break_step};
  return values[n];
}

std::vector<double> FixMesophyllBreak::restart_state() const
{
  return {(double) break_step, (double) broken_total, (double) bonds_left};
}

bool FixMesophyllBreak::restore_state(const std::vector<double> &state)
{
  if (state.size() != 3) return false;
  break_step = (bigint) state[0];
  broken_total = (bigint) state[1];
  bonds_left = (bigint) state[2];
  return true;
}
