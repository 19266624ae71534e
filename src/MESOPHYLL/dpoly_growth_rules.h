/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// The laws of void-localized growth, written once for the 2d cells (fix mesophyll/grow: rings,
// doc/Howto_mesophyll.rst "Growth") and the 3d cells (fix mesophyll3d/grow: closed surfaces,
// doc/Howto_polyhedra.rst "Growth"), and the keywords both fixes read for them.

#ifndef LMP_DPOLY_GROWTH_RULES_H
#define LMP_DPOLY_GROWTH_RULES_H

#include <algorithm>

namespace LAMMPS_NS {
class LAMMPS;

namespace DPoly {

  // Growth of the preferred length at one void-facing vertex: dl_std/n is the growth per
  // segment (2d) or edge (3d) of isometric growth, 'size' the vertex's void run (its length, 2d)
  // or patch (its area, 3d), 'mean_size' the cell's mean of them and 'total' the cell's
  // perimeter or surface area: lambda (dl_std/n) [(1 - c_L) + c_L (mean - size)/total].
  inline double void_length_growth(double lambda, double dl_std, int n, double c_length,
                                   double mean_size, double size, double total)
  {
    return lambda * dl_std / n * ((1.0 - c_length) + c_length * (mean_size - size) / total);
  }

  // theta0 of a void-facing vertex (2d) or edge (3d) drifts down, not below theta0_min
  inline double drifted_angle(double theta0, double drift, double theta0_min)
  {
    return std::max(theta0_min, theta0 - drift);
  }

  // theta0 relaxed toward its neighbours': 'differences' is the sum over the two ring neighbours
  // (2d) of theta0_neighbour - theta0, or the same weight spread over an edge's neighbours (3d)
  inline double relaxed_angle(double theta0, double rate, double differences)
  {
    return theta0 + rate * differences;
  }

  // The keywords the growth fixes share, read and checked once.
  struct GrowthRates {
    double lambda = 5.0;       // void-localized length growth, in units of isometric growth
    double c_length = 0.5;     // c_L: weight of the run (patch) size term
    double c_bending = 4.0;    // c_B: drift of theta0 at void-facing places
    double theta0_min;         // bound of that drift (default -pi/10)
    bool scale_diameters = true;
    bool need_box_relax = true;

    GrowthRates();
    // reads one keyword/value pair of fix 'style' (e.g. "mesophyll/grow"); false if the keyword
    // is not one of these; an error naming the keyword and value if the value is bad
    bool read(LAMMPS *lmp, const char *style, const char *key, const char *value);
    // the protocol relaxes the box at constant pressure: an error unless fix box/relax is
    // defined or 'box fixed' was given
    void check_box(LAMMPS *lmp, const char *style, const char *id) const;
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
