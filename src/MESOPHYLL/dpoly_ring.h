/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Shared bookkeeping of deformable-polygon (DP) rings, used by every DP style.
//
// A cell is a molecule whose vertices form one closed counter-clockwise ring. The ring order is
// read from the angles: each vertex is the centre of exactly one angle (prev, vertex, next), and
// LAMMPS keeps the atom order of an angle as given, so the angle alone fixes the direction.
// Per-vertex state lives in custom per-atom properties, so that it migrates, reaches ghosts and
// goes into restart and data files with LAMMPS's own machinery:
//   fix ID all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes

#ifndef LMP_DPOLY_RING_H
#define LMP_DPOLY_RING_H

#include "lmptype.h"

#include <cmath>

namespace LAMMPS_NS {
class Atom;
class Error;

namespace DPoly {

  // Ring neighbours of an owned vertex; count = number of angles centred on it (1 in a ring).
  struct RingLinks {
    tagint prev = 0, next = 0;
    int count = 0;
  };
  RingLinks ring_links(const Atom *atom, int i);

  // Pointers to the per-vertex state arrays; fetch again after atoms migrate or arrays grow.
  struct VertexState {
    double *diameter;            // sigma: contact diameter of the vertex disk
    double *preferred_length;    // l0 of the segment from this vertex to the next one
    double *preferred_angle;     // theta0: preferred signed turning angle at this vertex
    double *preferred_area;      // a0 of the vertex's cell (the same on all its vertices)
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
    VertexState arrays(const Atom *atom) const;
  };

  // Signed turning angle from segment d_in (into the vertex) to d_out (out of it), in (-pi, pi];
  // positive where a counter-clockwise ring is convex.
  inline double turning_angle(const double *d_in, const double *d_out)
  {
    return atan2(d_in[0] * d_out[1] - d_in[1] * d_out[0], d_in[0] * d_out[0] + d_in[1] * d_out[1]);
  }

  // Names of the custom properties, for messages and documentation.
  extern const char *const PROPERTY_HINT;

  // Preferred length of the ring segment joining local atoms i and j (one of them owned);
  // returns a negative value when i and j are not consecutive vertices of one ring.
  double segment_preferred_length(const Atom *atom, const VertexState &state, int i, int j);
}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
