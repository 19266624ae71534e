/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(dpoly/contact,PairDPolyContact);
// clang-format on
#else

#ifndef LMP_PAIR_DPOLY_CONTACT_H
#define LMP_PAIR_DPOLY_CONTACT_H

#include "dpoly_ring.h"
#include "pair.h"

#include <string>

namespace LAMMPS_NS {

// Repulsion between overlapping vertex disks: U = (eps_c/2)(1 - r/s)^2 for r < s, with
// s = (sigma_i + sigma_j)/2 from the per-vertex diameters. Acts between vertices of different
// cells, bonded or not, and between non-adjacent vertices of one cell (switchable); never
// between ring neighbours.
class PairDPolyContact : public Pair {
 public:
  PairDPolyContact(class LAMMPS *);
  ~PairDPolyContact() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void born_matrix(int, int, int, int, double, double, double, double &, double &) override;
  void *extract(const char *, int &) override;

 protected:
  double **contact_stiffness;    // eps_c per type pair
  int self_contact;              // repel non-adjacent vertices of the same cell
  double largest_diameter;       // max sigma when the run started: the cutoff
  DPoly::VertexStateCache vertex_state;
  std::string style_name = "dpoly/contact";    // as messages name the style
  void allocate();
  bool skip(int i, int j, tagint prev, tagint next) const;
  // the contact distance s = (sigma_i + sigma_j)/2 of local atoms i and j, and whether they
  // interact at r^2 = rsq: what single() and born_matrix() ask (the 3d style answers for itself)
  virtual double contact_distance(int i, int j);
  virtual bool interacts(int i, int j, double rsq, double s) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
