/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// State of the deformable polyhedra (3d cells), kept in custom per-atom properties so that it
// migrates, reaches ghost atoms and goes into restart and data files with LAMMPS's own
// machinery (doc/Howto_polyhedra.rst, "Topology and per-edge state"):
//   fix Vertices all property/atom d_sigma d_v0 ghost yes
//   fix Edges all property/atom i2_edge K ghost yes
//   fix EdgeLengths all property/atom d2_edge_l0 K ghost yes
//   fix EdgeAngles all property/atom d2_edge_theta0 K ghost yes
// (three fixes, so that each data-file line stays within read_data's 255 characters)
// Every edge's preferred length and bending angle sit on its lower-ID vertex, in the column whose
// i2_edge holds the other vertex's ID (0: unused column).

#ifndef LMP_DPOLY3D_STATE_H
#define LMP_DPOLY3D_STATE_H

#include "lmptype.h"

namespace LAMMPS_NS {
class Atom;
class Error;

namespace DPoly3d {

  extern const char *const VERTEX_HINT;
  extern const char *const EDGE_HINT;

  // Per-vertex arrays; fetch again after atoms migrate or arrays grow.
  struct VertexState {
    double *diameter;            // sigma
    double *preferred_volume;    // v0 of the vertex's cell
  };

  class VertexStateCache {
   public:
    void find(Atom *atom, Error *error, const char *style);
    VertexState get(Atom *atom, Error *error, const char *style);

   private:
    int diameter = -1, preferred_volume = -1;
  };

  // Where an edge's values are: column 'column' of local atom 'owner' (its lower-ID vertex).
  struct EdgeSlot {
    int owner, column;
  };

  // The per-edge values of local atoms (owned or ghost).
  class EdgeValues {
   public:
    static constexpr int MAX_EDGE_COLUMNS = 9;
    void find(Atom *atom, Error *error, const char *style);
    // fetch the arrays for this force evaluation (after find())
    void fetch(Atom *atom, Error *error, const char *style);
    int columns() const { return ncolumns; }

    // the slot of the edge joining local atoms i and j; column -1 if it has none
    EdgeSlot slot(const Atom *atom, int i, int j) const;
    // as slot(), but an error (naming 'style' and both vertices) if the edge has no values
    EdgeSlot require(const Atom *atom, Error *error, const char *style, int i, int j) const;

    double preferred_length(EdgeSlot s) const { return lengths[s.owner][s.column]; }
    double preferred_angle(EdgeSlot s) const { return angles[s.owner][s.column]; }
    int partner(int i, int column) const { return partners[i][column]; }
    double preferred_length(int i, int column) const { return lengths[i][column]; }
    double preferred_angle(int i, int column) const { return angles[i][column]; }
    // growth changes an owned vertex's values (fix mesophyll3d/grow)
    void set_preferred_length(int i, int column, double l0) { lengths[i][column] = l0; }
    void set_preferred_angle(int i, int column, double theta0) { angles[i][column] = theta0; }

   private:
    int partner_index = -1, length_index = -1, angle_index = -1, ncolumns = 0;
    int **partners = nullptr;
    double **lengths = nullptr, **angles = nullptr;
  };

}    // namespace DPoly3d
}    // namespace LAMMPS_NS

#endif
