/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dihedral_dpoly3d_hinge.h"

#include "atom.h"
#include "domain.h"
#include "dpoly_laws.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "math_extra.h"
#include "neighbor.h"

#include <cmath>

using namespace LAMMPS_NS;
using MathExtra::cross3;
using MathExtra::dot3;

static const char *STYLE = "Dihedral style dpoly3d/hinge";

DihedralDPoly3dHinge::DihedralDPoly3dHinge(LAMMPS *lmp) :
    PerTypeStiffness(lmp, STYLE, "eps_b", &Atom::ndihedraltypes)
{
  writedata = 1;
}

void DihedralDPoly3dHinge::init_style()
{
  if (domain->dimension != 3)
    error->all(FLERR, "{} needs a 3d simulation (dimension 3); 2d cells use dpoly/bending", STYLE);
  edges.find(atom, error, STYLE);
}

/* ----------------------------------------------------------------------
   With F = x1 - x2, G = x2 - x3, H = x4 - x3, A = F x G is the outward normal of face (1, 2, 3)
   and -B = -(H x G) that of face (3, 2, 4). The dihedral angle phi = atan2((B x A).G/|G|, A.B)
   has the gradient of Blondel and Karplus (J. Comput. Chem. 17, 1132 (1996)); the angle between
   the outward normals is theta = phi - pi, so it has the same gradient, and
   theta = atan2(-(B x A).G/|G|, -A.B) is 0 for coplanar faces and positive where convex.
   U = (eps_b/2) wrap(theta - theta0)^2 (DPoly::bending_law), wrap into [-pi, pi].
------------------------------------------------------------------------- */

void DihedralDPoly3dHinge::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  edges.fetch(atom, error, STYLE);
  double **x = atom->x;
  double **f = atom->f;
  int **dihedrallist = neighbor->dihedrallist;
  const int ndihedrallist = neighbor->ndihedrallist;
  const int nlocal = atom->nlocal, newton_bond = force->newton_bond;
  double edihedral = 0.0;

  for (int n = 0; n < ndihedrallist; n++) {
    const int i1 = dihedrallist[n][0], i2 = dihedrallist[n][1], i3 = dihedrallist[n][2],
              i4 = dihedrallist[n][3], type = dihedrallist[n][4];
    double F[3], G[3], H[3], A[3], B[3], BxA[3];
    for (int d = 0; d < 3; d++) {
      F[d] = x[i1][d] - x[i2][d];
      G[d] = x[i2][d] - x[i3][d];
      H[d] = x[i4][d] - x[i3][d];
    }
    cross3(F, G, A);
    cross3(H, G, B);
    const double a2 = dot3(A, A), b2 = dot3(B, B), g = sqrt(dot3(G, G));
    if (a2 == 0.0 || b2 == 0.0 || g == 0.0)
      error->one(FLERR, "{}: hinge {} {} {} {} has a face of zero area", STYLE, atom->tag[i1],
                 atom->tag[i2], atom->tag[i3], atom->tag[i4]);
    cross3(B, A, BxA);
    const double theta = atan2(-dot3(BxA, G) / g, -dot3(A, B));

    const DPoly3d::EdgeSlot slot = edges.require(atom, error, STYLE, i2, i3);
    const double theta0 = edges.preferred_angle(slot);
    const double wrapped = std::remainder(theta - theta0, MathConst::MY_2PI);
    const DPoly::Law law = DPoly::bending_law(stiffness[type], theta0 + wrapped, theta0);
    if (eflag) edihedral = law.energy;

    // f_k = -dU/dtheta dtheta/dx_k, with dtheta/dx1 = -|G| A/|A|^2, dtheta/dx4 = |G| B/|B|^2,
    // dtheta/dx2 = -dtheta/dx1 + (F.G/(|A|^2|G|)) A - (H.G/(|B|^2|G|)) B, and x3 the rest
    const double fg = dot3(F, G) / (a2 * g), hg = dot3(H, G) / (b2 * g);
    const double ca = -law.first * g / a2, cb = law.first * g / b2;
    double f1[3], f2[3], f3[3], f4[3];
    for (int d = 0; d < 3; d++) {
      f1[d] = -ca * A[d];
      f4[d] = -cb * B[d];
      f2[d] = ca * A[d] - law.first * (fg * A[d] - hg * B[d]);
      f3[d] = cb * B[d] + law.first * (fg * A[d] - hg * B[d]);
    }
    if (newton_bond || i1 < nlocal)
      for (int d = 0; d < 3; d++) f[i1][d] += f1[d];
    if (newton_bond || i2 < nlocal)
      for (int d = 0; d < 3; d++) f[i2][d] += f2[d];
    if (newton_bond || i3 < nlocal)
      for (int d = 0; d < 3; d++) f[i3][d] += f3[d];
    if (newton_bond || i4 < nlocal)
      for (int d = 0; d < 3; d++) f[i4][d] += f4[d];

    if (evflag)
      ev_tally(i1, i2, i3, i4, nlocal, newton_bond, edihedral, f1, f3, f4, x[i1][0] - x[i2][0],
               x[i1][1] - x[i2][1], x[i1][2] - x[i2][2], x[i3][0] - x[i2][0], x[i3][1] - x[i2][1],
               x[i3][2] - x[i2][2], x[i4][0] - x[i3][0], x[i4][1] - x[i3][1], x[i4][2] - x[i3][2]);
  }
}
