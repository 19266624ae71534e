/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_stage.h"

#include "comm.h"
#include "error.h"
#include "group.h"
#include "lammps.h"
#include "modify.h"

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
// Layout of a stage's restart record: version, number of values, the values.
constexpr int RESTART_VERSION = 1;
}    // namespace

FixDPolyStage::FixDPolyStage(LAMMPS *lmp, int narg, char **arg, Stage stage, int vector_length) :
    Fix(lmp, narg, arg), cells(nullptr), after_runs(0), my_stage(stage)
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
  if (modify->get_fix_by_style(fmt::format("^{}$", hub_style())).empty())
    error->all(FLERR,
               "Fix {} needs fix {}, which keeps the cells and runs this fix after every "
               "minimization",
               style, hub_style());
}

std::vector<FixDPolyStage *> FixDPolyStage::stages_of(LAMMPS *lmp, Fix *hub)
{
  std::vector<FixDPolyStage *> stages;
  for (Fix *fix : lmp->modify->get_fix_list()) {
    auto *stage = dynamic_cast<FixDPolyStage *>(fix);
    if (!stage || strcmp(stage->hub_style(), hub->style) != 0) continue;
    // a stage acts on the hub's cells (rings or surfaces, adhesive bonds, contact numbers); a
    // stage on another group would see neighbours and bonds outside its group
    if (stage->igroup != hub->igroup)
      lmp->error->all(FLERR,
                      "Fix {} {} is defined on group {}, but fix {} {} keeps the cells of group "
                      "{}: a stage acts on all the hub's cells; define it on group {}",
                      stage->style, stage->id, lmp->group->names[stage->igroup], hub->style,
                      hub->id, lmp->group->names[hub->igroup], lmp->group->names[hub->igroup]);
    stages.push_back(stage);
  }
  std::stable_sort(stages.begin(), stages.end(),
                   [](const FixDPolyStage *a, const FixDPolyStage *b) {
                     return a->stage() < b->stage();
                   });
  return stages;
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
