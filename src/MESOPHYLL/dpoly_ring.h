/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Shared bookkeeping of deformable-polygon (DP) rings, used by every DP style: ring links, the
// per-vertex state, whole-system tables and the topology refresh after bonds or atoms change.
//
// A cell is a molecule whose vertices form one closed counter-clockwise ring. The ring order is
// read from the angles: each vertex is the centre of exactly one angle (prev, vertex, next), and
// LAMMPS keeps the atom order of an angle as given, so the angle alone fixes the direction.
// Per-vertex state lives in custom per-atom properties, so that it migrates, reaches ghosts and
// goes into restart and data files with LAMMPS's own machinery:
//   fix ID all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes
// Two more are optional, per-vertex factors of the per-type stiffnesses (absent: factor 1), so
// that refinement can keep a ring's stiffness whatever its number of vertices:
//   fix ID2 all property/atom d_kl d_kb ghost yes

#ifndef LMP_DPOLY_RING_H
#define LMP_DPOLY_RING_H

#include "lmptype.h"
#include "math_const.h"

#include <mpi.h>

#include <cmath>
#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
class Atom;
class Error;
class LAMMPS;

namespace DPoly {

  // Ring neighbours of an owned vertex; count = number of angles centred on it (1 in a ring).
  struct RingLinks {
    tagint prev = 0, next = 0;
    int count = 0;
  };
  RingLinks ring_links(const Atom *atom, int i);

  // Local index of the image of atom 'neighbour' closest to local atom i; an error that names
  // 'style' and both atoms if this rank does not hold it (the communication cutoff is short).
  int closest_neighbour(LAMMPS *lmp, int i, tagint neighbour, const char *style);

  // Pointers to the per-vertex state arrays; fetch again after atoms migrate or arrays grow.
  struct VertexState {
    double *diameter;            // sigma: contact diameter of the vertex disk
    double *preferred_length;    // l0 of the segment from this vertex to the next one
    double *preferred_angle;     // theta0: preferred signed turning angle at this vertex
    double *preferred_area;      // a0 of the vertex's cell (the same on all its vertices)
    // Optional factors of the types' eps_l (segment from this vertex to the next) and eps_b
    // (bending at this vertex), d_kl and d_kb; nullptr when the property is not defined.
    double *segment_factor;
    double *bending_factor;
    double segment_factor_of(int i) const { return segment_factor ? segment_factor[i] : 1.0; }
    double bending_factor_of(int i) const { return bending_factor ? bending_factor[i] : 1.0; }
  };
  VertexState vertex_state(Atom *atom, Error *error, const char *style);

  // The vertex state of a style that reads it at every force evaluation: the properties are
  // looked up by name once, in find() (from init_style() or init()), and only their arrays are
  // fetched each time, as atoms that are added or migrate may reallocate them.
  class VertexStateCache {
   public:
    void find(Atom *atom, Error *error, const char *style);
    // find() first if it never ran (single() may come before any run)
    VertexState get(Atom *atom, Error *error, const char *style)
    {
      if (diameter < 0) find(atom, error, style);
      return arrays(atom);
    }

   private:
    int diameter = -1, preferred_length = -1, preferred_angle = -1, preferred_area = -1;
    int segment_factor = -1, bending_factor = -1;    // -1 also when not defined (optional)
    VertexState arrays(const Atom *atom) const;
  };

  // Signed turning angle from segment d_in (into the vertex) to d_out (out of it), in (-pi, pi];
  // positive where a counter-clockwise ring is convex.
  inline double turning_angle(const double *d_in, const double *d_out)
  {
    return atan2(d_in[0] * d_out[1] - d_in[1] * d_out[0], d_in[0] * d_out[0] + d_in[1] * d_out[1]);
  }

  // Shape index p^2/(4 pi a) of a polygon of perimeter p and area a: 1 for a circle.
  inline double shape_index(double perimeter, double area)
  {
    return perimeter * perimeter / (4.0 * MathConst::MY_PI * area);
  }

  // Names of the custom properties, for messages and documentation.
  extern const char *const PROPERTY_HINT;
  extern const char *const STIFFNESS_HINT;

  // The first vertex, in ring order, of the ring segment joining local atoms i and j (one of
  // them owned): i or j, whichever holds the segment's l0 and d_kl; -1 when i and j are not
  // consecutive vertices of one ring.
  int segment_start(const Atom *atom, int i, int j);

  // Collective: an error naming 'style' and a vertex if a defined d_kl or d_kb is not positive
  // and finite on some owned vertex (a fix property/atom starts its values at 0).
  void check_stiffness_factors(LAMMPS *lmp, const VertexState &state, const char *style);
  // Every rank's records, concatenated in rank order, on every rank: the package's decisions
  // that must not depend on the number of ranks (ring checks, contact counts, bond breaking) are
  // taken from such whole-system tables.
  template <typename Record>
  std::vector<Record> gather_on_all_ranks(std::vector<Record> mine, MPI_Comm world)
  {
    static_assert(std::is_trivially_copyable<Record>::value, "records travel as bytes");
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    int nbytes = (int) (mine.size() * sizeof(Record));
    std::vector<int> counts(nprocs), displs(nprocs, 0);
    MPI_Allgather(&nbytes, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
    std::vector<Record> all((displs.back() + counts.back()) / sizeof(Record));
    MPI_Allgatherv(mine.data(), nbytes, MPI_BYTE, all.data(), counts.data(), displs.data(),
                   MPI_BYTE, world);
    return all;
  }

  // Collective, after bonds or atoms changed between runs. Special::build() communicates
  // irregularly and drops the ghost atoms; the minimizer's clean-up still checks bonds against
  // ghosts, so they come back as a run's set-up would bring them (refresh_ghosts()).
  void rebuild_special_and_ghosts(LAMMPS *lmp);
  // Collective: ghost atoms anew, with the owners' current per-vertex state (periodic wrap,
  // exchange, borders), as a run's set-up brings them.
  void refresh_ghosts(LAMMPS *lmp);
}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
