/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly_vertex.h"

#include "atom.h"
#include "dpoly_ring.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

ComputeDPolyVertex::ComputeDPolyVertex(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), values(nullptr)
{
  if (narg != 3) error->all(FLERR, "Compute dpoly/vertex takes no arguments, got {}", narg - 3);
  if (!atom->molecule_flag) error->all(FLERR, "Compute dpoly/vertex needs molecule IDs and angles");
  peratom_flag = 1;
  size_peratom_cols = 3;    // turning angle, segment length, ID of the next vertex
}

ComputeDPolyVertex::~ComputeDPolyVertex()
{
  memory->destroy(values);
}

void ComputeDPolyVertex::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(values);
    nmax = atom->nmax;
    memory->create(values, nmax, size_peratom_cols, "dpoly/vertex:values");
    array_atom = values;
  }
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; i++) {
    values[i][0] = values[i][1] = values[i][2] = 0.0;
    if (!(atom->mask[i] & groupbit)) continue;
    const DPoly::RingLinks links = DPoly::ring_links(atom, i);
    if (links.count != 1) continue;    // not a ring vertex
    const int jp = DPoly::closest_neighbour(lmp, i, links.prev, "Compute dpoly/vertex");
    const int jn = DPoly::closest_neighbour(lmp, i, links.next, "Compute dpoly/vertex");
    const double in[2] = {x[i][0] - x[jp][0], x[i][1] - x[jp][1]};
    const double out[2] = {x[jn][0] - x[i][0], x[jn][1] - x[i][1]};
    values[i][0] = DPoly::turning_angle(in, out);
    values[i][1] = sqrt(out[0] * out[0] + out[1] * out[1]);
    values[i][2] = (double) links.next;    // lets a dump list each ring in order
  }
}

double ComputeDPolyVertex::memory_usage()
{
  return sizeof(double) * size_peratom_cols * nmax;
}
