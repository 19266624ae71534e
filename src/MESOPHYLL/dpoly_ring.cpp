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

#include <algorithm>
#include <utility>

using namespace LAMMPS_NS;

const char *const DPoly::PROPERTY_HINT =
    "fix ID all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes";
const char *const DPoly::STIFFNESS_HINT = "fix ID2 all property/atom d_kl d_kb ghost yes";

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

static int find_property(Atom *atom, Error *error, const char *style, const char *name,
                         bool optional = false)
{
  int flag, cols, ghost;
  const int index = atom->find_custom_ghost(name, flag, cols, ghost);
  if (optional && index < 0) return -1;
  if (index < 0 || flag != 1 || cols != 0)
    error->all(FLERR, "{} needs the per-atom property d_{}: define it with: {}", style, name,
               optional ? DPoly::STIFFNESS_HINT : DPoly::PROPERTY_HINT);
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
  segment_factor = find_property(atom, error, style, "kl", true);
  bending_factor = find_property(atom, error, style, "kb", true);
}

DPoly::VertexState DPoly::VertexStateCache::arrays(const Atom *atom) const
{
  return {atom->dvector[diameter],
          atom->dvector[preferred_length],
          atom->dvector[preferred_angle],
          atom->dvector[preferred_area],
          segment_factor < 0 ? nullptr : atom->dvector[segment_factor],
          bending_factor < 0 ? nullptr : atom->dvector[bending_factor]};
}

int DPoly::segment_start(const Atom *atom, int i, int j)
{
  // the angle arrays are complete only for owned atoms; look from whichever end is owned
  if (i >= atom->nlocal) std::swap(i, j);
  const RingLinks links = ring_links(atom, i);
  if (links.count != 1) return -1;
  if (links.next == atom->tag[j]) return i;
  if (links.prev == atom->tag[j]) return j;
  return -1;
}

void DPoly::check_stiffness_factors(LAMMPS *lmp, const VertexState &state, const char *style)
{
  Atom *atom = lmp->atom;
  const std::pair<const double *, const char *> factors[] = {{state.segment_factor, "d_kl"},
                                                             {state.bending_factor, "d_kb"}};
  for (const auto &factor : factors) {
    if (!factor.first) continue;
    // the smallest ID of a vertex with a bad factor, on any rank
    tagint bad = MAXTAGINT, bad_all = MAXTAGINT;
    for (int i = 0; i < atom->nlocal; i++)
      if (!(factor.first[i] > 0.0 && std::isfinite(factor.first[i])))
        bad = std::min(bad, atom->tag[i]);
    MPI_Allreduce(&bad, &bad_all, 1, MPI_LMP_TAGINT, MPI_MIN, lmp->world);
    if (bad_all != MAXTAGINT)
      lmp->error->all(FLERR,
                      "{}: {} of vertex {} is not positive; it multiplies the type's stiffness "
                      "(1 keeps it: set group all {} 1.0)",
                      style, factor.second, bad_all, factor.second);
  }
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
