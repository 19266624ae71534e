/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_stage.h"

#include "comm.h"
#include "compute.h"
#include "dpoly_measure.h"
#include "dpoly_ring.h"
#include "error.h"
#include "group.h"
#include "min.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
// Layout of a stage's restart record: version, number of values, the values.
constexpr int RESTART_VERSION = 1;
}    // namespace

FixDPolyStage::FixDPolyStage(LAMMPS *lmp, int narg, char **arg, Stage stage, int vector_length) :
    Fix(lmp, narg, arg), hub(nullptr), cells(nullptr), after_runs(0), my_stage(stage)
{
  restart_global = 1;
  vector_flag = 1;
  size_vector = vector_length;
  extvector = 0;
  global_freq = 1;
}

// the hub may be defined after this fix, so it attaches itself later in the same init()
void FixDPolyStage::init()
{
  const DPoly::CellHub *found = DPoly::CellHub::find_any(lmp);
  if (!found)
    error->all(FLERR,
               "Fix {} needs fix dpoly/cells{}, which keeps the cells and runs this fix after "
               "every minimization",
               style, acts_on_polyhedra() ? " or fix dpoly3d/cells" : "");
  if (found->cell_dimension() == 3 && !acts_on_polyhedra())
    error->all(FLERR,
               "Fix {} acts on polygons only: it needs fix dpoly/cells, not fix dpoly3d/cells",
               style);
}

std::vector<FixDPolyStage *> FixDPolyStage::attach_all(LAMMPS *lmp, Fix *hub_fix,
                                                       DPoly::CellHub *hub,
                                                       FixDPolyCells *polygons)
{
  std::vector<FixDPolyStage *> stages;
  for (Fix *fix : lmp->modify->get_fix_list())
    if (auto *stage = dynamic_cast<FixDPolyStage *>(fix)) {
      // a stage acts on the hub's cells (rings, adhesive bonds, contact numbers); a stage on
      // another group would see surface neighbours and bonds outside its group
      if (stage->igroup != hub_fix->igroup)
        lmp->error->all(FLERR,
                        "Fix {} {} is defined on group {}, but fix {} {} keeps the cells of "
                        "group {}: a stage acts on all the hub's cells; define it on group {}",
                        stage->style, stage->id, lmp->group->names[stage->igroup],
                        hub_fix->style, hub_fix->id, lmp->group->names[hub_fix->igroup],
                        lmp->group->names[hub_fix->igroup]);
      // also here, not only in init(): 'run N pre no' attaches without a new init()
      if (hub->cell_dimension() == 3 && !stage->acts_on_polyhedra())
        lmp->error->all(FLERR,
                        "Fix {} acts on polygons only: it needs fix dpoly/cells, not fix "
                        "dpoly3d/cells",
                        stage->style);
      stage->attach(hub, polygons);
      stages.push_back(stage);
    }
  std::stable_sort(stages.begin(), stages.end(),
                   [](const FixDPolyStage *a, const FixDPolyStage *b) {
                     return a->stage() < b->stage();
                   });
  return stages;
}

void FixDPolyStage::act_after_run(LAMMPS *lmp, const std::vector<FixDPolyStage *> &stages,
                                  DPoly::RunForces &run_forces,
                                  const std::function<void(int change)> &after_change)
{
  std::vector<FixDPolyStage *> acting;
  for (FixDPolyStage *stage : stages)
    if (stage->acts_after(lmp->update->whichflag)) acting.push_back(stage);
  if (acting.empty()) return;

  std::vector<DPoly::TissueMeasure *> measures;    // the package's computes, in their order
  for (Compute *compute : lmp->modify->get_compute_list())
    if (auto *measure = dynamic_cast<DPoly::TissueMeasure *>(compute)) measures.push_back(measure);
  for (DPoly::TissueMeasure *measure : measures) measure->measure_minimum();

  run_forces.keep();
  int changed = NOTHING;
  for (FixDPolyStage *stage : acting) {
    const int change = stage->act();
    if (change & (BONDS | RINGS))
      DPoly::rebuild_special_and_ghosts(lmp);
    else if (change & STATE)
      DPoly::refresh_ghosts(lmp);
    after_change(change);
    changed |= change;
  }
  run_forces.put_back();
  if (changed == NOTHING) return;
  // Min::cleanup() reads the minimizer's vectors after this: they must cover the atoms as now
  if (lmp->update->whichflag == 2) lmp->update->minimize->reset_vectors();
  for (DPoly::TissueMeasure *measure : measures) measure->forget_values();
}

void FixDPolyStage::parse_keywords(int first, int narg, char **arg, const KeywordReader &keyword)
{
  for (int iarg = first; iarg < narg; iarg += 2) {
    if (iarg + 2 > narg)
      utils::missing_cmd_args(FLERR, fmt::format("fix {} {}", style, arg[iarg]), error);
    const char *key = arg[iarg], *value = arg[iarg + 1];
    if (my_stage != CHECK && strcmp(key, "runs") == 0)
      after_runs = utils::logical(FLERR, value, false, lmp);
    else if (!keyword(key, value))
      error->all(FLERR, "Unknown fix {} keyword: {}", style, key);
  }
}

int FixDPolyStage::one_of(const char *key, const char *value, const char *first, const char *second)
{
  if (strcmp(value, first) == 0) return 0;
  if (strcmp(value, second) != 0)
    error->all(FLERR, "Fix {} {} must be '{}' or '{}', got '{}'", style, key, first, second, value);
  return 1;
}

void FixDPolyStage::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const std::vector<double> state = restart_state();
  const int header[2] = {RESTART_VERSION, (int) state.size()};
  const int size = (int) (sizeof(header) + state.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(header, sizeof(int), 2, fp);
  fwrite(state.data(), sizeof(double), state.size(), fp);
}

// LAMMPS hands every rank the whole record; its size is not passed, so the header carries it
void FixDPolyStage::restart(char *buf)
{
  int header[2];
  memcpy(header, buf, sizeof(header));
  std::vector<double> state(header[1] >= 0 && header[1] < (1 << 26) ? header[1] : 0);
  if (header[0] == RESTART_VERSION && state.size() == (size_t) header[1])
    memcpy(state.data(), buf + sizeof(header), state.size() * sizeof(double));
  if (header[0] != RESTART_VERSION || state.size() != (size_t) header[1] || !restore_state(state))
    error->all(FLERR,
               "Fix {} {}: the restart file holds state this version cannot read (format {}, {} "
               "values); write the restart file again with this version",
               style, id, header[0], header[1]);
}
