// Helpers shared by the MESOPHYLL tests.
#ifndef MESOPHYLL_TESTS_TEST_HELPERS_H
#define MESOPHYLL_TESTS_TEST_HELPERS_H

#include "lammps_session.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
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

// Largest deviation of the forces from central differences of the energy, relative to the
// largest force: on one rank over all three coordinates of every vertex; on several ranks (where
// each energy costs far more) over every 7th coordinate, which still reaches x, y and z of
// vertices of both cells on every rank (7 and 3 are coprime).
inline double finite_difference_error_3d(LammpsSession &s)
{
  const size_t stride = world_size() == 1 ? 1 : 7;
  s.run("run 0 post no");
  const std::vector<double> x0 = s.gather("x", 3);
  const std::vector<double> f = s.gather("f", 3);
  const double h = 1.0e-6;
  std::vector<double> numeric(f.size(), 0.0), checked(f.size(), 0.0);
  for (size_t k = 0; k < x0.size(); k += stride) {
    checked[k] = f[k];
    std::vector<double> x = x0;
    x[k] = x0[k] + h;
    const double up = potential_energy_at(s, x);
    x[k] = x0[k] - h;
    const double down = potential_energy_at(s, x);
    numeric[k] = -(up - down) / (2.0 * h);
  }
  std::vector<double> restored = x0;
  s.scatter("x", 3, restored);
  s.run("run 0 post no");
  return relative_force_error(checked, numeric) * max_abs(checked) / max_abs(f);
}

// Potential energy with the box and the atoms scaled by sx, sy, sz; the box is restored after.
inline double energy_after_scaling_3d(LammpsSession &s, double sx, double sy, double sz)
{
  char cmd[256];
  snprintf(cmd, sizeof(cmd),
           "change_box all x scale %.17g y scale %.17g z scale %.17g remap\nrun 0 post no", sx, sy,
           sz);
  s.run(cmd);
  const double u = s.thermo("pe");
  snprintf(cmd, sizeof(cmd),
           "change_box all x scale %.17g y scale %.17g z scale %.17g remap\nrun 0 post no",
           1.0 / sx, 1.0 / sy, 1.0 / sz);
  s.run(cmd);
  return u;
}

// Hand-made tissues: polygons with chosen adhesive bonds.
struct Polygon {
  std::vector<std::pair<double, double>> corners;    // counter-clockwise
};

struct Tissue {
  std::vector<Polygon> cells;
  std::vector<std::pair<int, int>> adhesive;    // 1-based atom IDs
  double sigma = 0.5;
  double box = 40.0;
};

// A data file in which every cell sits at its preferred area, lengths and angles, so that only
// contacts and adhesion exert forces.
inline std::string write_tissue(const Tissue &t, const std::string &name)
{
  std::vector<std::vector<double>> atoms;    // id mol x y sigma l0 theta0 a0
  std::vector<std::pair<int, int>> segments;
  std::vector<std::vector<int>> angles;
  for (size_t c = 0; c < t.cells.size(); c++) {
    const auto &p = t.cells[c].corners;
    const int n = (int) p.size(), first = (int) atoms.size() + 1;
    double area = 0.0;
    for (int k = 0; k < n; k++)
      area += 0.5 * (p[k].first * p[(k + 1) % n].second - p[(k + 1) % n].first * p[k].second);
    for (int k = 0; k < n; k++) {
      const auto &a = p[(k + n - 1) % n], &b = p[k], &d = p[(k + 1) % n];
      const double d1[2] = {b.first - a.first, b.second - a.second};
      const double d2[2] = {d.first - b.first, d.second - b.second};
      const double theta = atan2(d1[0] * d2[1] - d1[1] * d2[0], d1[0] * d2[0] + d1[1] * d2[1]);
      atoms.push_back({(double) first + k, (double) c + 1, b.first, b.second, t.sigma,
                       std::hypot(d2[0], d2[1]), theta, area});
      segments.push_back({first + k, first + (k + 1) % n});
      angles.push_back({first + (k + n - 1) % n, first + k, first + (k + 1) % n});
    }
  }
  const std::string path = scratch(name);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {    // one writer; the others wait until the file is complete
    MPI_Barrier(MPI_COMM_WORLD);
    return path;
  }
  std::ofstream out(path);
  out.precision(17);
  out << "tissue\n\n"
      << atoms.size() << " atoms\n1 atom types\n"
      << segments.size() + t.adhesive.size() << " bonds\n2 bond types\n"
      << angles.size() << " angles\n1 angle types\n\n0 " << t.box << " xlo xhi\n0 " << t.box
      << " ylo yhi\n-0.5 0.5 zlo zhi\n\nMasses\n\n1 1\n\nAtoms # molecular\n\n";
  for (const auto &a : atoms)
    out << (int) a[0] << " " << (int) a[1] << " 1 " << a[2] << " " << a[3] << " 0\n";
  out << "\nBonds\n\n";
  int id = 1;
  for (const auto &s : segments) out << id++ << " 1 " << s.first << " " << s.second << "\n";
  for (const auto &b : t.adhesive) out << id++ << " 2 " << b.first << " " << b.second << "\n";
  out << "\nAngles\n\n";
  id = 1;
  for (const auto &a : angles) out << id++ << " 1 " << a[0] << " " << a[1] << " " << a[2] << "\n";
  out << "\nVertices\n\n";
  for (const auto &a : atoms)
    out << (int) a[0] << " " << a[4] << " " << a[5] << " " << a[6] << " " << a[7] << "\n";
  out.close();
  MPI_Barrier(MPI_COMM_WORLD);
  return path;
}

inline Polygon square(double x, double y, double side)
{
  return {{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}};
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

// Polyhedra of a data file of tools/make_cells3d.py with the 3d styles (edges, faces, hinges,
// the hub with eps_v 1): no contacts, no stages.
inline std::string polyhedra_commands(const std::string &data)
{
  return "units lj\ndimension 3\natom_style molecular\natom_modify map array\nboundary p p p\n"
         "fix Vertices all property/atom d_sigma d_v0 ghost yes\n"
         "fix Edges all property/atom i2_edge 6 ghost yes\n"
         "fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes\n"
         "fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes\n"
         "bond_style dpoly3d/edge\nangle_style zero\ndihedral_style dpoly3d/hinge\n"
         "read_data " +
      data +
      " fix Vertices NULL Vertices fix Edges NULL Edges fix EdgeLengths NULL EdgeLengths fix "
      "EdgeAngles NULL EdgeAngles\n"
      "bond_coeff * 1.0\nangle_coeff *\ndihedral_coeff * 0.4\ncomm_modify cutoff 2.0\n"
      "fix cells all dpoly3d/cells eps_v 1.0\nthermo_modify norm no\n";
}

// The 16-cell confluent tissue of examples/tissue at P0 under fix box/relax, minimized by
// min_style fire/nph with the settings of examples/mesophyll/in.mesophyll; no stages.
inline std::string tissue16_commands(const std::string &P0 = "1.0e-3")
{
  const char *dir = getenv("MESOPHYLL_EXAMPLES");
  return "units lj\ndimension 2\natom_style molecular\nboundary p p p\n"
         "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
         "bond_style hybrid dpoly/segment mesophyll/adhesion z bonds\n"
         "angle_style dpoly/bending\nread_data " +
      std::string(dir ? dir : "examples") +
      "/tissue/tissue_N16.data fix Vertices NULL Vertices extra/special/per/atom 40\n"
      "bond_coeff 1 dpoly/segment 1.0\nbond_coeff 2 mesophyll/adhesion 1.0\n"
      "angle_coeff * 0.4\npair_style dpoly/contact\npair_coeff * * 1.0\n"
      "special_bonds lj 1.0 1.0 1.0\ncomm_modify cutoff 4.0\n"
      "fix cells all dpoly/cells eps_a 1.0\n"
      "fix relax all box/relax iso " +
      P0 +
      " vmax 1.0e-3\n"
      "thermo_style custom step pe press lx\nthermo_modify norm no\n"
      "min_style fire/nph\ntimestep 0.01\nmin_modify tmax 5\n";
}

// Resume a tissue of contact_commands() from a restart file: what the restart file does not hold
// (the vertex properties' fix, the hybrid bond coefficients, the cells' hub) is given again.
inline std::string resume_commands(const std::string &restart)
{
  return "read_restart " + restart +
      "\nfix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
      "bond_coeff 1 dpoly/segment 1.0\nbond_coeff 2 mesophyll/adhesion 1.0\n"
      "comm_modify cutoff 3.0\nfix cells all dpoly/cells eps_a 1.0\n";
}

// Fixture of the bad-input tests: they run on one rank, as some errors are per-atom ones.
class ErrorTest : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  }
  // the error text of running 'commands' ("" if they run)
  static std::string error_of(const std::string &commands)
  {
    LammpsSession s;
    return s.try_run(commands);
  }
  // for each (commands, error): base + commands fails with a message that holds error
  static void expect_errors(const std::string &base,
                            const std::vector<std::pair<std::string, std::string>> &cases)
  {
    for (const auto &c : cases)
      EXPECT_THAT(error_of(base + c.first), ::testing::HasSubstr(c.second)) << c.first;
  }
};

// The same commands on all ranks and on this rank alone, for the tests that compare the two.
struct ParallelAndSerial {
  LammpsSession parallel, serial;
  explicit ParallelAndSerial(const std::string &commands) : serial(self_comm())
  {
    parallel.run(commands);
    serial.run(commands);
  }
};

}    // namespace test

#endif
