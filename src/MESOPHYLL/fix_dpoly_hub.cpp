/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "fix_dpoly_hub.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_adhesion.h"
#include "dpoly_image_check.h"
#include "dpoly_run_forces.h"
#include "error.h"
#include "fix_dpoly_stage.h"
#include "group.h"
#include "modify.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixDPolyHub::FixDPolyHub(LAMMPS *lmp, int narg, char **arg, const char *term) :
    Fix(lmp, narg, arg), term(term), image_check(new DPoly::AdhesiveBondsImageCheck(lmp))
{
  scalar_flag = 1;    // the energy of the per-cell term
  extscalar = 1;
  vector_flag = 1;    // the number of cells and two of their totals (the hub's page)
  size_vector = 3;
  extvector = 0;
  global_freq = 1;
  energy_global_flag = 1;
  virial_global_flag = virial_peratom_flag = 1;
  // The per-cell term is part of the potential: the minimizer's objective and the pressure that
  // fix box/relax drives must both see it, so both are on by default (init() insists).
  thermo_energy = thermo_virial = 1;
  comm_forward = 3;    // unwrapped positions
  dynamic_group_allow = 0;
}

// the adhesive bonds get their types back if an error left them hidden (dpoly_image_check.h)
FixDPolyHub::~FixDPolyHub()
{
  image_check->after_check();
}

// the store of the forces is a fix of its own, made once the hub is one
void FixDPolyHub::post_constructor()
{
  run_forces = std::make_unique<DPoly::RunForces>(lmp, id);
}

int FixDPolyHub::setmask()
{
  // PRE_EXCHANGE only for setup_pre_exchange(): pre_exchange() itself does nothing
  return PRE_FORCE | MIN_PRE_FORCE | POST_FORCE | MIN_POST_FORCE | PRE_NEIGHBOR | MIN_PRE_NEIGHBOR |
      PRE_EXCHANGE | MIN_PRE_EXCHANGE;
}

void FixDPolyHub::init()
{
  image_check->init();    // types hidden by a setup that an error cut short
  check_requirements();
  if (modify->get_fix_by_style("^" + std::string(style) + "$").size() > 1)
    error->all(FLERR, "Only one fix {} may be defined", style);
  if (!thermo_energy || !thermo_virial)
    error->all(FLERR,
               "Fix {} {}: the {} term must count in both energy and virial; do not use "
               "fix_modify energy no or virial no with it",
               style, id, term);
  find_stages();
}

std::vector<FixDPolyStage *> FixDPolyHub::find_stages()
{
  return FixDPolyStage::attach_all(lmp, this, this, polygons());
}

void FixDPolyHub::not_a_vertex(tagint atom) const
{
  error->all(FLERR,
             "Fix {} {}: atom {} is not a vertex of its cells (group {}), but an adhesive bond "
             "reaches it: bond only vertices of the hub's group",
             style, id, atom, group->names[igroup]);
}

/* ----------------------------------------------------------------------
   these two bracket LAMMPS's image-flag check at the setup of a run or minimization: the
   adhesive bonds, whose network closes around the periodic box, are left out of it once the
   reason for its warning has been given (dpoly_image_check.h)
------------------------------------------------------------------------- */

void FixDPolyHub::setup_pre_exchange()
{
  image_check->before_check();
}

void FixDPolyHub::setup_pre_neighbor()
{
  image_check->after_check();
  if (image_check->explained()) return;
  share_unwrapped_positions();
  image_check->explain_once(unwrapped);
}

// before the first force evaluation of a run, so that every style sees current, checked cells
void FixDPolyHub::setup_pre_force(int /*vflag*/)
{
  refresh_cells();
}

void FixDPolyHub::setup(int vflag)
{
  post_force(vflag);
}

void FixDPolyHub::min_setup(int vflag)
{
  setup(vflag);
}

void FixDPolyHub::min_post_force(int vflag)
{
  post_force(vflag);
}

/* ----------------------------------------------------------------------
   at every reneighbouring, once atoms are wrapped and exchanged and the ghosts are new: a
   segment or edge that grew past half the box or the ghost cutoff would silently join the
   wrong image of its other vertex
------------------------------------------------------------------------- */

void FixDPolyHub::pre_neighbor()
{
  share_unwrapped_positions();
  check_nearest_images();
}

void FixDPolyHub::min_pre_neighbor()
{
  pre_neighbor();
}

/* ----------------------------------------------------------------------
   after a minimization (or an MD run, for stages with 'runs yes'): the stages in the protocol's
   order (FixDPolyStage::act_after_run()), the hub's own bookkeeping after each
------------------------------------------------------------------------- */

void FixDPolyHub::post_run()
{
  FixDPolyStage::act_after_run(lmp, find_stages(), *run_forces, [&](int change) {
    after_stage(change);
  });
}

void FixDPolyHub::refresh_cells()
{
  read_cells();
  share_unwrapped_positions();
  check_nearest_images();
  check_cell_extents();
  if (DPoly::CellAdhesion *adhesion = DPoly::find_cell_adhesion(lmp)) adhesion->recount();
  measure_cells();
  check_measured_cells();
}

void FixDPolyHub::index_cells()
{
  // molecule ID -> cell: a plain table when the IDs are dense, as they usually are
  const int n = ncells();
  dense_index.clear();
  sparse_index.clear();
  if (n > 0 && cell_ids.back() <= 4 * (tagint) n + 1024) {
    dense_index.assign(cell_ids.back() + 1, -1);
    for (int c = 0; c < n; c++) dense_index[cell_ids[c]] = c;
  } else {
    for (int c = 0; c < n; c++) sparse_index[cell_ids[c]] = c;
  }
}

int FixDPolyHub::cell_index(tagint molecule) const
{
  if (!dense_index.empty())
    return (molecule >= 0 && molecule < (tagint) dense_index.size()) ? dense_index[molecule] : -1;
  const auto found = sparse_index.find(molecule);
  return found == sparse_index.end() ? -1 : found->second;
}

void FixDPolyHub::share_unwrapped_positions()
{
  const int nlocal = atom->nlocal;
  unwrapped.resize(3 * (size_t) (nlocal + atom->nghost));
  for (int i = 0; i < nlocal; i++) domain->unmap(atom->x[i], atom->image[i], &unwrapped[3 * i]);
  comm->forward_comm(this);
}

int FixDPolyHub::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) buf[m++] = unwrapped[3 * list[k] + d];
  return m;
}

void FixDPolyHub::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) unwrapped[3 * i + d] = buf[m++];
}
