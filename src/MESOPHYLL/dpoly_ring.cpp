/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_ring.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "special.h"

#include <utility>

using namespace LAMMPS_NS;

const char *const DPoly::PROPERTY_HINT =
    "fix ID all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes";

DPoly::RingLinks DPoly::ring_links(const Atom *atom, int i)
{
  RingLinks links;
  const tagint self = atom->tag[i];
  for (int m = 0; m < atom->num_angle[i]; m++) {
    if (atom->angle_atom2[i][m] != self) continue;
    links.prev = atom->angle_atom1[i][m];
    links.next = atom->angle_atom3[i][m];
    links.count++;
  }
  return links;
}

int DPoly::closest_neighbour(LAMMPS *lmp, int i, tagint neighbour, const char *style)
{
  Atom *atom = lmp->atom;
  const int j = lmp->domain->closest_image(i, atom->map(neighbour));
  if (j < 0)
    lmp->error->one(FLERR,
                    "{}: ring neighbour {} of vertex {} is missing on this rank; increase the "
                    "communication cutoff (comm_modify cutoff)",
                    style, neighbour, atom->tag[i]);
  return j;
}

static int find_property(Atom *atom, Error *error, const char *style, const char *name)
{
  int flag, cols, ghost;
  const int index = atom->find_custom_ghost(name, flag, cols, ghost);
  if (index < 0 || flag != 1 || cols != 0)
    error->all(FLERR, "{} needs the per-atom property d_{}: define the vertex state with: {}",
               style, name, DPoly::PROPERTY_HINT);
  if (!ghost)
    error->all(FLERR, "{} needs d_{} on ghost atoms too: add 'ghost yes' to its fix property/atom",
               style, name);
  return index;
}

DPoly::VertexState DPoly::vertex_state(Atom *atom, Error *error, const char *style)
{
  VertexStateCache cache;
  cache.find(atom, error, style);
  return cache.get(atom, error, style);
}

void DPoly::VertexStateCache::find(Atom *atom, Error *error, const char *style)
{
  diameter = find_property(atom, error, style, "sigma");
  preferred_length = find_property(atom, error, style, "l0");
  preferred_angle = find_property(atom, error, style, "theta0");
  preferred_area = find_property(atom, error, style, "a0");
}

DPoly::VertexState DPoly::VertexStateCache::arrays(const Atom *atom) const
{
  return {atom->dvector[diameter], atom->dvector[preferred_length], atom->dvector[preferred_angle],
          atom->dvector[preferred_area]};
}

double DPoly::segment_preferred_length(const Atom *atom, const VertexState &state, int i, int j)
{
  // the angle arrays are complete only for owned atoms; look from whichever end is owned
  if (i >= atom->nlocal) std::swap(i, j);
  const RingLinks links = ring_links(atom, i);
  if (links.count != 1) return -1.0;
  if (links.next == atom->tag[j]) return state.preferred_length[i];
  if (links.prev == atom->tag[j]) return state.preferred_length[j];
  return -1.0;
}

void DPoly::rebuild_special_and_ghosts(LAMMPS *lmp)
{
  Special special(lmp);
  special.build();
  refresh_ghosts(lmp);
}

void DPoly::refresh_ghosts(LAMMPS *lmp)
{
  Domain *domain = lmp->domain;
  Atom *atom = lmp->atom;
  if (domain->triclinic) domain->x2lamda(atom->nlocal);
  domain->pbc();
  domain->reset_box();
  lmp->comm->setup();
  lmp->comm->exchange();
  lmp->comm->borders();
  if (domain->triclinic) domain->lamda2x(atom->nlocal + atom->nghost);
}
