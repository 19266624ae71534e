/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly_hessian.h"

#include "angle.h"
#include "atom.h"
#include "bond.h"
#include "bond_mesophyll_adhesion.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_gather.h"
#include "dpoly_ring.h"
#include "error.h"
#include "fix_dpoly_cells.h"
#include "force.h"
#include "pair.h"
#include "update.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>
#include <utility>

using namespace LAMMPS_NS;

namespace {

// What the Hessian needs of a vertex.
struct VertexRecord {
  tagint tag, cell;
  int type, angle_type;
  double x[2], sigma, l0, theta0, a0;
};
// A non-adhesive bond (a ring segment), as held by its owner.
struct SegmentRecord {
  tagint a, b;
  int type;
};

// Dense Hessian of sums of terms, in 2D, rows 2*index + (0: x, 1: y).
class Assembly {
 public:
  Assembly(int nvertices, const Domain *domain) :
      H(Eigen::MatrixXd::Zero(2 * nvertices, 2 * nvertices)), domain(domain)
  {
  }
  Eigen::MatrixXd H;

  // minimum-image difference b - a
  void difference(const double *a, const double *b, double *d) const
  {
    double delta[3] = {b[0] - a[0], b[1] - a[1], 0.0};
    domain->minimum_image(FLERR, delta);
    d[0] = delta[0];
    d[1] = delta[1];
  }

  // U = (k/2)(r/L - 1)^2 on the distance r = |d| between vertices i and j (segments, contacts,
  // adhesion): the 2x2 block U'' u u^T + (U'/r)(I - u u^T) enters with + on ii, jj, - on ij.
  void add_distance_term(int i, int j, const double *d, double k, double L)
  {
    const double r = std::hypot(d[0], d[1]);
    const double u[2] = {d[0] / r, d[1] / r};
    const double first = k / L * (r / L - 1.0), second = k / (L * L);
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2; b++) {
        const double uu = u[a] * u[b];
        const double block = second * uu + first / r * ((a == b ? 1.0 : 0.0) - uu);
        H(2 * i + a, 2 * i + b) += block;
        H(2 * j + a, 2 * j + b) += block;
        H(2 * i + a, 2 * j + b) -= block;
        H(2 * j + a, 2 * i + b) -= block;
      }
  }

  // U = (k/2)(theta - theta0)^2, theta the turning angle at vertex c from d1 = c - p to
  // d2 = n - c: theta = phi(d2) - phi(d1), phi the polar angle; H = k (g g^T + (theta-theta0) T)
  void add_bending(int p, int c, int n, const double *d1, const double *d2, double k, double theta0)
  {
    const double theta = DPoly::turning_angle(d1, d2);
    const double r1 = d1[0] * d1[0] + d1[1] * d1[1], r2 = d2[0] * d2[0] + d2[1] * d2[1];
    const double q1[2] = {-d1[1] / r1, d1[0] / r1}, q2[2] = {-d2[1] / r2, d2[0] / r2};
    const int index[3] = {p, c, n};
    // gradient of theta over (p, c, n)
    const double g[6] = {q1[0], q1[1], -q1[0] - q2[0], -q1[1] - q2[1], q2[0], q2[1]};
    // second derivatives of the polar angle: M(d) = [[2xy, y^2-x^2], [y^2-x^2, -2xy]] / r^4
    auto polar = [](const double *d, double r2, double M[2][2]) {
      M[0][0] = 2 * d[0] * d[1] / (r2 * r2);
      M[1][1] = -M[0][0];
      M[0][1] = M[1][0] = (d[1] * d[1] - d[0] * d[0]) / (r2 * r2);
    };
    double M1[2][2], M2[2][2];
    polar(d1, r1, M1);
    polar(d2, r2, M2);
    // blocks of the Hessian of theta: pp = -M1, cc = M2 - M1, nn = M2, pc = M1, cn = -M2, pn = 0
    auto block = [&](int s, int t, int a, int b) {
      if (s > t) std::swap(s, t);
      if (s == 0 && t == 0) return -M1[a][b];
      if (s == 1 && t == 1) return M2[a][b] - M1[a][b];
      if (s == 2 && t == 2) return M2[a][b];
      if (s == 0 && t == 1) return M1[a][b];
      if (s == 1 && t == 2) return -M2[a][b];
      return 0.0;
    };
    for (int s = 0; s < 3; s++)
      for (int t = 0; t < 3; t++)
        for (int a = 0; a < 2; a++)
          for (int b = 0; b < 2; b++)
            H(2 * index[s] + a, 2 * index[t] + b) +=
                k * (g[2 * s + a] * g[2 * t + b] + (theta - theta0) * block(s, t, a, b));
  }

  // U = (k/2)(a/a0 - 1)^2 with a = (1/2) sum (X_m Y_m+1 - X_m+1 Y_m) over the ring, positions
  // unwrapped along it: H = (k/a0^2) g g^T + (k/a0)(a/a0 - 1) Hess(a).
  void add_area(const std::vector<int> &ring, const std::vector<std::array<double, 2>> &pos,
                double k, double a0)
  {
    const int n = (int) ring.size();
    double area = 0.0;
    for (int m = 0; m < n; m++) {
      const auto &p = pos[m], &q = pos[(m + 1) % n];
      area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
    std::vector<double> g(2 * n);
    for (int m = 0; m < n; m++) {
      const auto &next = pos[(m + 1) % n], &prev = pos[(m + n - 1) % n];
      g[2 * m] = 0.5 * (next[1] - prev[1]);
      g[2 * m + 1] = 0.5 * (prev[0] - next[0]);
    }
    const double outer = k / (a0 * a0), slope = k / a0 * (area / a0 - 1.0);
    for (int s = 0; s < 2 * n; s++)
      for (int t = 0; t < 2 * n; t++)
        H(2 * ring[s / 2] + s % 2, 2 * ring[t / 2] + t % 2) += outer * g[s] * g[t];
    for (int m = 0; m < n; m++) {
      const int i = ring[m], j = ring[(m + 1) % n];
      // d2a/dX_m dY_m+1 = +1/2, d2a/dY_m dX_m+1 = -1/2
      H(2 * i, 2 * j + 1) += 0.5 * slope;
      H(2 * j + 1, 2 * i) += 0.5 * slope;
      H(2 * i + 1, 2 * j) -= 0.5 * slope;
      H(2 * j, 2 * i + 1) -= 0.5 * slope;
    }
  }

 private:
  const Domain *domain;
};

}    // namespace

ComputeDPolyHessian::ComputeDPolyHessian(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmodes(10), zero_level(1.0e-8), max_dof(4000), zero_modes(0.0),
    last_diagonalized(-1), diagonalized_once(false)
{
  int iarg = 3;
  while (iarg < narg) {
    if (iarg + 2 > narg)
      utils::missing_cmd_args(FLERR, std::string("compute dpoly/hessian ") + arg[iarg], error);
    if (strcmp(arg[iarg], "modes") == 0) {
      nmodes = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (nmodes < 1)
        error->all(FLERR, "Compute dpoly/hessian modes must be >= 1, got {}", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "zero") == 0) {
      zero_level = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (zero_level <= 0.0)
        error->all(FLERR, "Compute dpoly/hessian zero must be > 0, got {}", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "max_dof") == 0) {
      max_dof = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (max_dof < 2)
        error->all(FLERR, "Compute dpoly/hessian max_dof must be >= 2, got {}", arg[iarg + 1]);
    } else
      error->all(FLERR, "Unknown compute dpoly/hessian keyword: {}", arg[iarg]);
    iarg += 2;
  }
  if (igroup != 0)
    error->all(FLERR, "Compute dpoly/hessian needs group all: the Hessian is of the whole tissue");
  if (domain->dimension != 2) error->all(FLERR, "Compute dpoly/hessian is for 2d systems");
  scalar_flag = vector_flag = array_flag = 1;
  size_vector = nmodes;
  size_array_rows = size_array_cols = (int) (2 * atom->natoms);
  size_array_rows_variable = 1;    // vertex insertion changes it
  extscalar = extvector = extarray = 0;
  vector = new double[nmodes];
}

ComputeDPolyHessian::~ComputeDPolyHessian()
{
  delete[] vector;
}

void ComputeDPolyHessian::init()
{
  FixDPolyCells::find(lmp, "Compute dpoly/hessian");
  if (domain->triclinic) error->all(FLERR, "Compute dpoly/hessian needs an orthogonal box");
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   global array: the Hessian, 2N x 2N, rows and columns in atom-ID order, x then y of each atom
------------------------------------------------------------------------- */

void ComputeDPolyHessian::compute_array()
{
  invoked_array = update->ntimestep;
  matrix = assemble();
  const int ndof = (int) (2 * atom->natoms);
  matrix.resize((size_t) ndof * ndof);
  MPI_Bcast(matrix.data(), ndof * ndof, MPI_DOUBLE, 0, world);
  rows.resize(ndof);
  for (int r = 0; r < ndof; r++) rows[r] = matrix.data() + (size_t) r * ndof;
  array = rows.data();
  size_array_rows = size_array_cols = ndof;
}

double ComputeDPolyHessian::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  diagonalize();
  scalar = zero_modes;
  return scalar;
}

void ComputeDPolyHessian::compute_vector()
{
  invoked_vector = update->ntimestep;
  diagonalize();
}

/* ----------------------------------------------------------------------
   eigenvalues on rank 0 (Eigen's dense self-adjoint solver), the lowest to every rank; zero
   modes: |lambda| below the zero level, less the two translations of a periodic tissue
------------------------------------------------------------------------- */

void ComputeDPolyHessian::diagonalize()
{
  if (last_diagonalized == update->ntimestep && diagonalized_once) return;
  const std::vector<double> matrix = assemble();
  const int ndof = (int) (2 * atom->natoms);
  std::vector<double> lowest(nmodes + 1, 0.0);
  if (comm->me == 0) {
    Eigen::Map<const Eigen::MatrixXd> H(matrix.data(), ndof, ndof);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(H, Eigen::EigenvaluesOnly);
    if (solver.info() != Eigen::Success)
      error->one(FLERR, "Compute dpoly/hessian: the eigenvalue solver did not converge");
    const Eigen::VectorXd &values = solver.eigenvalues();
    int zeros = 0;
    for (int k = 0; k < ndof; k++)
      if (std::fabs(values[k]) < zero_level) zeros++;
    lowest[nmodes] = zeros - 2;
    for (int k = 0; k < nmodes; k++) lowest[k] = k < ndof ? values[k] : 0.0;
  }
  MPI_Bcast(lowest.data(), nmodes + 1, MPI_DOUBLE, 0, world);
  for (int k = 0; k < nmodes; k++) vector[k] = lowest[k];
  zero_modes = lowest[nmodes];
  last_diagonalized = update->ntimestep;
  diagonalized_once = true;
}

/* ----------------------------------------------------------------------
   the Hessian, on rank 0 (empty elsewhere), column-major = row-major as it is symmetric
------------------------------------------------------------------------- */

std::vector<double> ComputeDPolyHessian::assemble()
{
  FixDPolyCells *cells = FixDPolyCells::find(lmp, "Compute dpoly/hessian");
  const DPoly::VertexState state = DPoly::vertex_state(atom, error, "Compute dpoly/hessian");
  const bigint ndof = 2 * atom->natoms;
  if (ndof > max_dof)
    error->all(FLERR,
               "Compute dpoly/hessian: {} degrees of freedom exceed max_dof {} (a dense matrix of "
               "{:.0f} MB on rank 0)",
               ndof, max_dof, 8.0 * ndof * ndof / 1.0e6);

  // every vertex and every ring segment, on every rank
  std::vector<VertexRecord> mine;
  std::vector<SegmentRecord> my_segments;
  auto *adhesion = dynamic_cast<BondMesophyllAdhesion *>(force->bond_match("mesophyll/adhesion"));
  for (int i = 0; i < atom->nlocal; i++) {
    VertexRecord v = {atom->tag[i],
                      atom->molecule[i],
                      atom->type[i],
                      0,
                      {atom->x[i][0], atom->x[i][1]},
                      state.diameter[i],
                      state.preferred_length[i],
                      state.preferred_angle[i],
                      state.preferred_area[i]};
    for (int m = 0; m < atom->num_angle[i]; m++)
      if (atom->angle_atom2[i][m] == atom->tag[i]) v.angle_type = atom->angle_type[i][m];
    mine.push_back(v);
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      if (type <= 0 || (adhesion && adhesion->is_adhesive_type(type))) continue;
      my_segments.push_back({atom->tag[i], atom->bond_atom[i][m], type});
    }
  }
  std::vector<VertexRecord> vertices = DPoly::gather_on_all_ranks(std::move(mine), world);
  std::vector<SegmentRecord> segments = DPoly::gather_on_all_ranks(std::move(my_segments), world);
  std::vector<DPoly::AdhesiveBond> bonds;
  if (adhesion) bonds = adhesion->gather_bonds();

  std::vector<double> result;
  if (comm->me == 0) {
    std::sort(vertices.begin(), vertices.end(), [](const VertexRecord &a, const VertexRecord &b) {
      return a.tag < b.tag;
    });
    std::unordered_map<tagint, int> index;
    for (size_t k = 0; k < vertices.size(); k++) index[vertices[k].tag] = (int) k;

    int dim = 0;
    auto *segment_style = force->bond_match("dpoly/segment");
    auto *bending_style = force->angle_match("dpoly/bending");
    auto *contact_style = force->pair_match("dpoly/contact", 1);
    const double *eps_l = segment_style ? (const double *) segment_style->extract("eps_l", dim)
                                        : nullptr;
    const double *eps_b = bending_style ? (const double *) bending_style->extract("eps_b", dim)
                                        : nullptr;
    double **eps_c = contact_style ? (double **) contact_style->extract("eps_c", dim) : nullptr;
    const int *self = contact_style ? (const int *) contact_style->extract("self", dim) : nullptr;

    Assembly h((int) vertices.size(), domain);

    // area term of every cell, positions unwrapped along its ring
    for (int c = 0; c < cells->ncells(); c++) {
      const std::vector<tagint> &ring = cells->ring(c);
      std::vector<int> rows;
      std::vector<std::array<double, 2>> pos;
      for (tagint t : ring) {
        const VertexRecord &v = vertices[index.at(t)];
        if (pos.empty())
          pos.push_back({v.x[0], v.x[1]});
        else {
          double d[2];
          h.difference(vertices[rows.back()].x, v.x, d);
          pos.push_back({pos.back()[0] + d[0], pos.back()[1] + d[1]});
        }
        rows.push_back(index.at(t));
      }
      h.add_area(rows, pos, cells->area_stiffness(), vertices[rows[0]].a0);
    }

    // segments (l0 on the first vertex in ring order) and bending (theta0 on the middle vertex)
    auto key = [](tagint a, tagint b) {
      return std::make_pair(std::min(a, b), std::max(a, b));
    };
    std::map<std::pair<tagint, tagint>, int> types;
    for (const auto &s : segments) types[key(s.a, s.b)] = s.type;
    for (int c = 0; c < cells->ncells(); c++) {
      const std::vector<tagint> &ring = cells->ring(c);
      const int n = (int) ring.size();
      for (int m = 0; m < n; m++) {
        const int p = index.at(ring[(m + n - 1) % n]), i = index.at(ring[m]),
                  j = index.at(ring[(m + 1) % n]);
        double d1[2], d2[2];
        h.difference(vertices[p].x, vertices[i].x, d1);
        h.difference(vertices[i].x, vertices[j].x, d2);
        const auto t = types.find(key(ring[m], ring[(m + 1) % n]));
        if (eps_l && t != types.end())
          h.add_distance_term(i, j, d2, eps_l[t->second], vertices[i].l0);
        if (eps_b && vertices[i].angle_type > 0)
          h.add_bending(p, i, j, d1, d2, eps_b[vertices[i].angle_type], vertices[i].theta0);
      }
    }

    // contacts: every overlapping pair but ring neighbours (same cell only with self yes)
    if (eps_c) {
      for (size_t a = 0; a < vertices.size(); a++)
        for (size_t b = a + 1; b < vertices.size(); b++) {
          const VertexRecord &u = vertices[a], &v = vertices[b];
          if (u.cell == v.cell) {
            if (!(self && *self)) continue;
            const auto &links = cells->ring_neighbours(u.tag);
            if (links.prev == v.tag || links.next == v.tag) continue;
          }
          double d[2];
          h.difference(u.x, v.x, d);
          const double s = 0.5 * (u.sigma + v.sigma);
          if (d[0] * d[0] + d[1] * d[1] >= s * s) continue;
          h.add_distance_term((int) a, (int) b, d, eps_c[u.type][v.type], s);
        }
    }

    // adhesive bonds, stretched branch only: (eps_c/(2 z)) (1 - r/s)^2
    for (const auto &bond : bonds) {
      const VertexRecord &u = vertices[index.at(bond.atom1)], &v = vertices[index.at(bond.atom2)];
      double d[2];
      h.difference(u.x, v.x, d);
      const double s = 0.5 * (u.sigma + v.sigma);
      if (d[0] * d[0] + d[1] * d[1] <= s * s) continue;
      const double z = adhesion->contact_number(adhesion->counts(), bond.cell1, bond.cell2);
      h.add_distance_term(index.at(bond.atom1), index.at(bond.atom2), d,
                          adhesion->stiffness(bond.type) / z, s);
    }
    result.assign(h.H.data(), h.H.data() + h.H.size());
  }
  return result;
}
