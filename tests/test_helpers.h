// Helpers shared by the MESOPHYLL tests.
#ifndef MESOPHYLL_TESTS_TEST_HELPERS_H
#define MESOPHYLL_TESTS_TEST_HELPERS_H

#include "lammps_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace test {

const double PI = 3.14159265358979323846;

inline std::string data_file(const std::string &name)
{
  const char *dir = getenv("MESOPHYLL_TEST_DATA");
  return std::string(dir ? dir : "data") + "/" + name;
}

inline int world_size()
{
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

// Scratch file name that all ranks agree on and that differs between test binaries runs.
inline std::string scratch(const std::string &name)
{
  return "scratch." + std::to_string(world_size()) + "." + name;
}

// A communicator of this rank alone (LAMMPS's serial MPI stubs have no MPI_COMM_SELF, and there
// the world is one rank anyway).
inline MPI_Comm self_comm()
{
#ifdef MPI_COMM_SELF
  return MPI_COMM_SELF;
#else
  return MPI_COMM_WORLD;
#endif
}

inline double max_abs(const std::vector<double> &v)
{
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// Largest force difference over the largest force.
inline double relative_force_error(const std::vector<double> &a, const std::vector<double> &b)
{
  double diff = 0.0;
  for (size_t k = 0; k < a.size(); k++) diff = std::max(diff, std::fabs(a[k] - b[k]));
  return diff / std::max(max_abs(a), 1.0e-12);
}

inline double potential_energy_at(LammpsSession &s, std::vector<double> x)
{
  s.scatter("x", 3, x);
  s.run("run 0 post no");
  return s.thermo("pe");
}

// Potential energy with the box (and the atoms) scaled by sx, sy; the box is restored after.
inline double energy_after_scaling(LammpsSession &s, double sx, double sy)
{
  char cmd[256];
  snprintf(cmd, sizeof(cmd), "change_box all x scale %.17g y scale %.17g remap\nrun 0 post no", sx,
           sy);
  s.run(cmd);
  const double u = s.thermo("pe");
  snprintf(cmd, sizeof(cmd), "change_box all x scale %.17g y scale %.17g remap\nrun 0 post no",
           1.0 / sx, 1.0 / sy);
  s.run(cmd);
  return u;
}

// Largest deviation of the forces from central differences of the total energy, relative to
// the largest force: every force term at once, in whatever state the session is.
inline double finite_difference_error(LammpsSession &s)
{
  s.run("run 0 post no");
  const std::vector<double> x0 = s.gather("x", 3);
  const std::vector<double> f = s.gather("f", 3);

  // central differences err by O(h^2) times the third derivative; with contact distances near
  // 0.2 that is about 3e-7 at h = 1e-5 and 3e-9 at h = 1e-6 (measured), far below the tolerance
  const double h = 1.0e-6;
  std::vector<double> numeric(f.size(), 0.0);
  for (int k = 0; k < s.natoms(); k++)
    for (int d = 0; d < 2; d++) {
      std::vector<double> x = x0;
      x[3 * k + d] = x0[3 * k + d] + h;
      const double up = potential_energy_at(s, x);
      x[3 * k + d] = x0[3 * k + d] - h;
      const double down = potential_energy_at(s, x);
      numeric[3 * k + d] = -(up - down) / (2.0 * h);
    }
  std::vector<double> restored = x0;
  s.scatter("x", 3, restored);
  s.run("run 0 post no");
  return relative_force_error(f, numeric);
}

// A tissue with contacts and adhesion: segment + adhesion bonds (types 1, 2), bending, the
// contact pair style, the hub, optionally the breaking fix.
struct Contacts {
  std::string z_rule = "bonds";
  std::string self = "yes";
  std::string break_options = "";    // empty: no fix mesophyll/break
};

inline std::string contact_commands(const std::string &data, const Contacts &c = Contacts())
{
  std::string cmds = "units lj\ndimension 2\natom_style molecular\natom_modify map array\n"
                     "boundary p p p\n"
                     "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
                     "bond_style hybrid dpoly/segment mesophyll/adhesion z " +
      c.z_rule +
      "\n"
      "angle_style dpoly/bending\n"
      "read_data " +
      data +
      " fix Vertices NULL Vertices extra/bond/per/atom 6 "
      "extra/special/per/atom 40\n"
      "bond_coeff 1 dpoly/segment 1.0\nbond_coeff 2 mesophyll/adhesion 1.0\n"
      "angle_coeff * 0.4\npair_style dpoly/contact self " +
      c.self +
      "\n"
      "pair_coeff * * 1.0\nspecial_bonds lj 1.0 1.0 1.0\ncomm_modify cutoff 3.0\n"
      "fix cells all dpoly/cells eps_a 1.0\n";
  if (!c.break_options.empty()) cmds += "fix break all mesophyll/break " + c.break_options + "\n";
  return cmds +
      "thermo_style custom step pe ebond eangle epair f_cells press pxx pyy\n"
      "thermo_modify norm no\n";
}

}    // namespace test

#endif
