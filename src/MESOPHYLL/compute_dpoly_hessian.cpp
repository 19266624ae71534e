/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "compute_dpoly_hessian.h"

#include "angle_dpoly_bending.h"
#include "atom.h"
#include "bond.h"
#include "bond_hybrid.h"
#include "comm.h"
#include "domain.h"
#include "dpoly_laws.h"
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
#include <tuple>
#include <unordered_map>
#include <utility>

using namespace LAMMPS_NS;

namespace {

// What the Hessian needs of a vertex.
struct VertexRecord {
  tagint tag;
  double x[2], a0;
};
// A term in the distance between vertices a < b (a bond, a contact): dU/dr and d2U/dr2, from its
// style's born_matrix().
struct DistanceRecord {
  tagint a, b;
  double first, second;
  bool operator<(const DistanceRecord &o) const
  {
    return std::tie(a, b, first, second) < std::tie(o.a, o.b, o.first, o.second);
  }
};
// A bending term at vertex c, from p to n: dU/dtheta and d2U/dtheta2 of the turning angle.
struct BendingRecord {
  tagint p, c, n;
  double first, second;
  bool operator<(const BendingRecord &o) const { return c < o.c; }
};

// The style of a bond type: bond_style hybrid has no born_matrix() of its own to dispatch with,
// so find the sub-style that holds the type's coefficients.
Bond *bond_style_of(Force *force, int type)
{
  auto *hybrid = dynamic_cast<BondHybrid *>(force->bond);
  if (!hybrid) return force->bond;
  for (int m = 0; m < hybrid->nstyles; m++) {
    Bond *style = hybrid->styles[m];
    if (style && style->allocated && style->setflag[type]) return style;
  }
  return nullptr;
}

// Dense Hessian of sums of terms, in 2D, rows 2*index + (0: x, 1: y). Only the geometry (chain
// rule) is here: the derivatives of each term in its coordinate come from its style.
class Assembly {
 public:
  explicit Assembly(int nvertices) : H(Eigen::MatrixXd::Zero(2 * nvertices, 2 * nvertices)) {}
  Eigen::MatrixXd H;

  // U(r) on the distance r = |d| between vertices i and j, U' = first, U'' = second: the 2x2
  // block U'' u u^T + (U'/r)(I - u u^T) enters with + on ii, jj, - on ij.
  void add_distance_term(int i, int j, const double *d, double first, double second)
  {
    const double r = std::hypot(d[0], d[1]);
    const double u[2] = {d[0] / r, d[1] / r};
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

  // U(theta), theta the turning angle at vertex c from d1 = c - p to d2 = n - c:
  // theta = phi(d2) - phi(d1), phi the polar angle; H = U'' g g^T + U' Hess(theta)
  void add_bending(int p, int c, int n, const double *d1, const double *d2, double first,
                   double second)
  {
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
                second * (g[2 * s + a] * g[2 * t + b]) + first * block(s, t, a, b);
  }

  // The area law of the hub in a = (1/2) sum (X_m Y_m+1 - X_m+1 Y_m) over the ring, positions
  // unwrapped along it: H = U'' g g^T + U' Hess(a).
  void add_area(const std::vector<int> &ring, const std::vector<std::array<double, 2>> &pos,
                double eps_a, double a0)
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
    const DPoly::Law law = DPoly::area_law(eps_a, area, a0);
    for (int s = 0; s < 2 * n; s++)
      for (int t = 0; t < 2 * n; t++)
        H(2 * ring[s / 2] + s % 2, 2 * ring[t / 2] + t % 2) += law.second * (g[s] * g[t]);
    for (int m = 0; m < n; m++) {
      const int i = ring[m], j = ring[(m + 1) % n];
      // d2a/dX_m dY_m+1 = +1/2, d2a/dY_m dX_m+1 = -1/2
      H(2 * i, 2 * j + 1) += 0.5 * law.first;
      H(2 * j + 1, 2 * i) += 0.5 * law.first;
      H(2 * i + 1, 2 * j) -= 0.5 * law.first;
      H(2 * j, 2 * i + 1) -= 0.5 * law.first;
    }
  }
};

// Vertex positions by atom ID, the same on every rank, and minimum-image differences of them:
// every rank measures a term exactly as rank 0 does, whichever images it holds.
class Positions {
 public:
  Positions(std::vector<VertexRecord> all, const Domain *domain) :
      vertices(std::move(all)), domain(domain)
  {
    std::sort(vertices.begin(), vertices.end(), [](const VertexRecord &a, const VertexRecord &b) {
      return a.tag < b.tag;
    });
    for (size_t k = 0; k < vertices.size(); k++) index[vertices[k].tag] = (int) k;
  }
  std::vector<VertexRecord> vertices;    // sorted by atom ID
  std::unordered_map<tagint, int> index;

  int row(tagint tag) const { return index.at(tag); }
  // minimum-image difference of vertices b - a
  void difference(tagint a, tagint b, double *d) const
  {
    difference(vertices[row(a)].x, vertices[row(b)].x, d);
  }
  void difference(const double *a, const double *b, double *d) const
  {
    double delta[3] = {b[0] - a[0], b[1] - a[1], 0.0};
    domain->minimum_image(FLERR, delta);
    d[0] = delta[0];
    d[1] = delta[1];
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
  vertex_state.find(atom, error, "Compute dpoly/hessian");
  if (domain->triclinic) error->all(FLERR, "Compute dpoly/hessian needs an orthogonal box");
  // every term must give its second derivatives (a bond type of no style has no term)
  for (int type = 1; type <= atom->nbondtypes; type++) {
    const Bond *style = force->bond ? bond_style_of(force, type) : nullptr;
    if (style && !style->born_matrix_enable)
      error->all(FLERR,
                 "Compute dpoly/hessian: the bond style of bond type {} has no born_matrix()",
                 type);
  }
  const auto *bending = dynamic_cast<AngleDPolyBending *>(force->angle_match("dpoly/bending"));
  for (int type = 1; type <= atom->nangletypes; type++)
    if (!bending || !bending->setflag[type])
      error->all(FLERR, "Compute dpoly/hessian: angle type {} is not of angle_style dpoly/bending",
                 type);
}

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
   the stages changed the tissue after the last evaluation: the next one measures the new tissue
   (a dense Hessian at every minimum would be too costly to take in advance)
------------------------------------------------------------------------- */

void ComputeDPolyHessian::forget_values()
{
  invoked_flag = 0;
  invoked_scalar = invoked_vector = invoked_array = -1;
  diagonalized_once = false;
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
   the Hessian, on rank 0 (empty elsewhere), column-major = row-major as it is symmetric.
   Each rank takes the derivatives of the terms of its owned atoms from their styles, at the
   distances and angles measured from the gathered positions; rank 0 sorts them and assembles.
------------------------------------------------------------------------- */

std::vector<double> ComputeDPolyHessian::assemble()
{
  FixDPolyCells *cells = FixDPolyCells::find(lmp, "Compute dpoly/hessian");
  const DPoly::VertexState state = vertex_state.get(atom, error, "Compute dpoly/hessian");
  const bigint ndof = 2 * atom->natoms;
  if (ndof > max_dof)
    error->all(FLERR,
               "Compute dpoly/hessian: {} degrees of freedom exceed max_dof {} (a dense matrix of "
               "{:.0f} MB on rank 0)",
               ndof, max_dof, 8.0 * ndof * ndof / 1.0e6);

  const int nlocal = atom->nlocal;
  tagint *tag = atom->tag;
  std::vector<VertexRecord> mine;
  for (int i = 0; i < nlocal; i++)
    mine.push_back({tag[i], {atom->x[i][0], atom->x[i][1]}, state.preferred_area[i]});
  const Positions positions(DPoly::gather_on_all_ranks(std::move(mine), world), domain);

  auto partner_of = [&](tagint partner, tagint self) {
    const int j = atom->map(partner);
    if (j < 0)
      error->one(FLERR,
                 "Compute dpoly/hessian: atom {}, bonded to {}, is missing on this rank; "
                 "increase the communication cutoff",
                 partner, self);
    return j;
  };

  // bonds: segments and adhesion, each once (on one end with newton_bond off)
  std::vector<DistanceRecord> my_distances;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      const tagint partner = atom->bond_atom[i][m];
      if (type <= 0 || (!force->newton_bond && partner < tag[i])) continue;
      Bond *style = bond_style_of(force, type);
      if (!style) continue;    // bond_style hybrid with 'none' for this type: no term
      const tagint a = std::min(tag[i], partner), b = std::max(tag[i], partner);
      double d[2], first, second;
      positions.difference(a, b, d);
      style->born_matrix(type, d[0] * d[0] + d[1] * d[1], i, partner_of(partner, tag[i]), first,
                         second);
      if (first != 0.0 || second != 0.0) my_distances.push_back({a, b, first, second});
    }

  // contacts: every pair of an owned vertex with a vertex of higher ID that overlaps it
  auto *contact = force->pair_match("dpoly/contact", 1);
  if (contact) {
    if (!contact->born_matrix_enable)
      error->all(FLERR, "Compute dpoly/hessian: pair style dpoly/contact has no born_matrix()");
    for (int i = 0; i < nlocal; i++)
      for (size_t k = positions.row(tag[i]) + 1; k < positions.vertices.size(); k++) {
        const tagint b = positions.vertices[k].tag;
        const int j = atom->map(b);
        if (j < 0) continue;    // beyond the ghost cutoff, so beyond the pair cutoff
        double d[2], first, second;
        positions.difference(tag[i], b, d);
        const double rsq = d[0] * d[0] + d[1] * d[1];
        if (rsq >= contact->cutsq[atom->type[i]][atom->type[j]]) continue;
        contact->born_matrix(i, j, atom->type[i], atom->type[j], rsq, 1.0, 1.0, first, second);
        if (first != 0.0 || second != 0.0) my_distances.push_back({tag[i], b, first, second});
      }
  }

  // bending at every owned vertex, in the turning angle (born_matrix()'s cos is singular there)
  auto *bending = dynamic_cast<AngleDPolyBending *>(force->angle_match("dpoly/bending"));
  std::vector<BendingRecord> my_bending;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < atom->num_angle[i]; m++) {
      const int type = atom->angle_type[i][m];
      if (type <= 0 || atom->angle_atom2[i][m] != tag[i]) continue;
      const tagint p = atom->angle_atom1[i][m], n = atom->angle_atom3[i][m];
      double d1[2], d2[2];
      positions.difference(p, tag[i], d1);
      positions.difference(tag[i], n, d2);
      const DPoly::Law law = bending->turning_law(type, i, DPoly::turning_angle(d1, d2));
      my_bending.push_back({p, tag[i], n, law.first, law.second});
    }

  std::vector<DistanceRecord> distances =
      DPoly::gather_on_all_ranks(std::move(my_distances), world);
  std::vector<BendingRecord> bends = DPoly::gather_on_all_ranks(std::move(my_bending), world);

  std::vector<double> result;
  if (comm->me == 0) {
    const std::vector<VertexRecord> &vertices = positions.vertices;
    Assembly h((int) vertices.size());

    // area term of every cell, positions unwrapped along its ring
    for (int c = 0; c < cells->ncells(); c++) {
      const std::vector<tagint> &ring = cells->ring(c);
      std::vector<int> rows;
      std::vector<std::array<double, 2>> pos;
      for (tagint t : ring) {
        const VertexRecord &v = vertices[positions.row(t)];
        if (pos.empty())
          pos.push_back({v.x[0], v.x[1]});
        else {
          double d[2];
          positions.difference(vertices[rows.back()].x, v.x, d);
          pos.push_back({pos.back()[0] + d[0], pos.back()[1] + d[1]});
        }
        rows.push_back(positions.row(t));
      }
      h.add_area(rows, pos, cells->area_stiffness(), vertices[rows[0]].a0);
    }

    std::sort(distances.begin(), distances.end());
    for (const auto &t : distances) {
      double d[2];
      positions.difference(t.a, t.b, d);
      h.add_distance_term(positions.row(t.a), positions.row(t.b), d, t.first, t.second);
    }

    std::sort(bends.begin(), bends.end());
    for (const auto &t : bends) {
      double d1[2], d2[2];
      positions.difference(t.p, t.c, d1);
      positions.difference(t.c, t.n, d2);
      h.add_bending(positions.row(t.p), positions.row(t.c), positions.row(t.n), d1, d2, t.first,
                    t.second);
    }
    result.assign(h.H.data(), h.H.data() + h.H.size());
  }
  return result;
}
