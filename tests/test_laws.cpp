// born_matrix() of the package's bond, pair and angle styles against finite differences of their
// own single() energies, so that forces, energies and second derivatives keep telling one law.
#include "test_helpers.h"

#include "angle_dpoly_bending.h"
#include "atom.h"
#include "bond.h"
#include "domain.h"
#include "force.h"
#include "lammps.h"
#include "pair.h"

#include "gtest/gtest.h"

#include <memory>

using namespace test;
using LAMMPS_NS::LAMMPS;

namespace {

// An adhesive tissue, dilated so that the adhesive bonds are stretched (as in test_hessian).
std::unique_ptr<LammpsSession> stretched_tissue()
{
  auto s = std::make_unique<LammpsSession>();
  s->run(contact_commands(data_file("overlapping.data")) +
         "adhere_cells all 2\nchange_box all x scale 1.03 y scale 1.03 remap\nrun 0 post no");
  return s;
}

// Central differences of an energy E(q) at q with step h: (dE/dq, d2E/dq2).
template <typename Energy> std::pair<double, double> differences(Energy energy, double q, double h)
{
  const double plus = energy(q + h), mid = energy(q), minus = energy(q - h);
  return {(plus - minus) / (2 * h), (plus - 2 * mid + minus) / (h * h)};
}

void expect_close(double analytic, double numeric, const std::string &what)
{
  EXPECT_NEAR(analytic, numeric, 1.0e-6 * std::max(1.0, std::fabs(analytic))) << what;
}

double diameter(LAMMPS *lmp, int i)
{
  int flag, cols;
  const int index = lmp->atom->find_custom("sigma", flag, cols);
  return lmp->atom->dvector[index][i];
}

// Local indices (i owned, j its bonded partner) of the first bond of this type.
std::pair<int, int> first_bond(LAMMPS *lmp, int type)
{
  auto *atom = lmp->atom;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++)
      if (atom->bond_type[i][m] == type) return {i, atom->map(atom->bond_atom[i][m])};
  return {-1, -1};
}

// A bond style's du, du2 against its single() at distance r, and its force against -du/r.
void check_bond(LAMMPS_NS::Bond *bond, int type, int i, int j, double r, const std::string &what)
{
  double du, du2, fforce;
  bond->born_matrix(type, r * r, i, j, du, du2);
  auto energy = [&](double q) {
    double unused;
    return bond->single(type, q * q, i, j, unused);
  };
  const auto fd = differences(energy, r, 1.0e-4 * r);
  expect_close(du, fd.first, what + ": dU/dr");
  expect_close(du2, fd.second, what + ": d2U/dr2");
  bond->single(type, r * r, i, j, fforce);
  expect_close(fforce, -du / r, what + ": single()'s force");
}

}    // namespace

TEST(Laws, BondBornMatrixMatchesSingle)
{
  if (world_size() > 1) GTEST_SKIP() << "local indices: runs on one rank";
  auto s = stretched_tissue();
  auto *lmp = static_cast<LAMMPS *>(s->lammps_handle());

  auto *segment = lmp->force->bond_match("dpoly/segment");
  ASSERT_TRUE(segment && segment->born_matrix_enable);
  const auto seg = first_bond(lmp, 1);
  ASSERT_GE(seg.first, 0);
  for (double r : {0.05, 0.2, 0.4}) check_bond(segment, 1, seg.first, seg.second, r, "segment");

  auto *adhesion = lmp->force->bond_match("mesophyll/adhesion");
  ASSERT_TRUE(adhesion && adhesion->born_matrix_enable);
  const auto adh = first_bond(lmp, 2);
  ASSERT_GE(adh.first, 0);
  const double contact = 0.5 * (diameter(lmp, adh.first) + diameter(lmp, adh.second));
  for (double ratio : {1.05, 1.5, 2.5})
    check_bond(adhesion, 2, adh.first, adh.second, ratio * contact, "adhesion, stretched");
  double du = 1.0, du2 = 1.0;
  adhesion->born_matrix(2, 0.81 * contact * contact, adh.first, adh.second, du, du2);
  EXPECT_EQ(du, 0.0) << "overlap belongs to the pair style";
  EXPECT_EQ(du2, 0.0);
}

TEST(Laws, PairBornMatrixMatchesSingle)
{
  if (world_size() > 1) GTEST_SKIP() << "local indices: runs on one rank";
  auto s = stretched_tissue();
  auto *lmp = static_cast<LAMMPS *>(s->lammps_handle());
  auto *atom = lmp->atom;
  auto *pair = lmp->force->pair;
  ASSERT_TRUE(pair->born_matrix_enable);

  // vertex 0 and a vertex of another cell; vertex 0 and its next ring neighbour
  int other = -1;
  for (int j = 1; j < atom->nlocal && other < 0; j++)
    if (atom->molecule[j] != atom->molecule[0]) other = j;
  ASSERT_GE(other, 0);
  const int type0 = atom->type[0], type1 = atom->type[other];
  const double contact = 0.5 * (diameter(lmp, 0) + diameter(lmp, other));
  for (double ratio : {0.3, 0.7, 0.95}) {
    const double r = ratio * contact;
    double du, du2, fforce;
    pair->born_matrix(0, other, type0, type1, r * r, 1.0, 1.0, du, du2);
    auto energy = [&](double q) {
      double unused;
      return pair->single(0, other, type0, type1, q * q, 1.0, 1.0, unused);
    };
    const auto fd = differences(energy, r, 1.0e-4 * r);
    expect_close(du, fd.first, "contact: dU/dr at r/s = " + std::to_string(ratio));
    expect_close(du2, fd.second, "contact: d2U/dr2 at r/s = " + std::to_string(ratio));
    pair->single(0, other, type0, type1, r * r, 1.0, 1.0, fforce);
    expect_close(fforce, -du / r, "contact: single()'s force");
  }
  double du = 1.0, du2 = 1.0;
  pair->born_matrix(0, other, type0, type1, 1.21 * contact * contact, 1.0, 1.0, du, du2);
  EXPECT_EQ(du, 0.0) << "no force beyond contact";
  EXPECT_EQ(du2, 0.0);

  for (int m = 0; m < atom->num_angle[0]; m++) {
    if (atom->angle_atom2[0][m] != atom->tag[0]) continue;
    const int next = atom->map(atom->angle_atom3[0][m]);
    pair->born_matrix(0, next, type0, atom->type[next], 0.01 * contact * contact, 1.0, 1.0, du,
                      du2);
    EXPECT_EQ(du, 0.0) << "ring neighbours do not repel";
    EXPECT_EQ(du2, 0.0);
  }
}

// The angle: LAMMPS's convention (derivatives in c, the cosine of the interior angle) where it is
// defined, and the turning-angle law the Hessian uses; both against single() as a vertex turns.
TEST(Laws, AngleBornMatrixMatchesSingle)
{
  if (world_size() > 1) GTEST_SKIP() << "local indices: runs on one rank";
  auto s = stretched_tissue();
  auto *lmp = static_cast<LAMMPS *>(s->lammps_handle());
  auto *atom = lmp->atom;
  auto *angle = dynamic_cast<LAMMPS_NS::AngleDPolyBending *>(lmp->force->angle);
  ASSERT_TRUE(angle && angle->born_matrix_enable);

  int centre = 0, m = 0;
  while (atom->angle_atom2[centre][m] != atom->tag[centre]) m++;
  const int type = atom->angle_type[centre][m];
  const int prev = lmp->domain->closest_image(centre, atom->map(atom->angle_atom1[centre][m]));
  const int next = lmp->domain->closest_image(centre, atom->map(atom->angle_atom3[centre][m]));
  double **x = atom->x;
  const double saved[2] = {x[next][0], x[next][1]};
  const double incoming = atan2(x[centre][1] - x[prev][1], x[centre][0] - x[prev][0]);

  auto turn_to = [&](double theta) {    // put the next vertex at turning angle theta
    x[next][0] = x[centre][0] + 0.3 * cos(incoming + theta);
    x[next][1] = x[centre][1] + 0.3 * sin(incoming + theta);
  };
  auto energy_at = [&](double theta) {
    turn_to(theta);
    return angle->single(type, prev, centre, next);
  };
  for (double theta : {-2.0, -0.5, 0.3, 1.2, 2.6}) {
    const std::string at = " at theta = " + std::to_string(theta);
    const auto in_theta = differences(energy_at, theta, 1.0e-4);
    turn_to(theta);
    const LAMMPS_NS::DPoly::Law law = angle->turning_law(type, centre, theta);
    expect_close(law.energy, angle->single(type, prev, centre, next), "U" + at);
    expect_close(law.first, in_theta.first, "dU/dtheta" + at);
    expect_close(law.second, in_theta.second, "d2U/dtheta2" + at);

    // c = cos(interior angle) = -cos(theta), on the branch of theta's sign
    const double sign = theta > 0 ? 1.0 : -1.0;
    auto energy_in_c = [&](double c) {
      return energy_at(sign * acos(-c));
    };
    const auto in_c = differences(energy_in_c, -cos(theta), 1.0e-4);
    turn_to(theta);
    double du, du2;
    angle->born_matrix(type, prev, centre, next, du, du2);
    expect_close(du, in_c.first, "dU/dc" + at);
    EXPECT_NEAR(du2, in_c.second, 1.0e-5 * std::max(1.0, std::fabs(du2))) << "d2U/dc2" << at;
  }
  x[next][0] = saved[0];
  x[next][1] = saved[1];
}

// With the per-vertex factors d_kl and d_kb, born_matrix(), single() and the turning law (which
// the Hessian reads) scale with the factor of the segment's first vertex and of the centre.
TEST(Laws, StiffnessFactorsEnterEveryLaw)
{
  if (world_size() > 1) GTEST_SKIP() << "local indices: runs on one rank";
  auto s = stretched_tissue();
  auto *lmp = static_cast<LAMMPS *>(s->lammps_handle());
  auto *atom = lmp->atom;
  auto *segment = lmp->force->bond_match("dpoly/segment");
  auto *angle = dynamic_cast<LAMMPS_NS::AngleDPolyBending *>(lmp->force->angle);
  ASSERT_TRUE(segment && angle);
  const auto seg = first_bond(lmp, 1);
  ASSERT_GE(seg.first, 0);
  const double r = 0.3;
  double du1, du2_1, f1;
  segment->born_matrix(1, r * r, seg.first, seg.second, du1, du2_1);
  const double e1 = segment->single(1, r * r, seg.first, seg.second, f1);
  const LAMMPS_NS::DPoly::Law bend1 = angle->turning_law(1, 0, 0.7);

  // the first vertex of the segment: the one whose next ring neighbour is the other
  const bool forward = LAMMPS_NS::DPoly::ring_links(atom, seg.first).next == atom->tag[seg.second];
  const int start = forward ? seg.first : seg.second, end = forward ? seg.second : seg.first;
  s->run("fix Stiffness all property/atom d_kl d_kb ghost yes\nset group all d_kl 1.0\n"
         "set group all d_kb 1.0\nset atom " +
         std::to_string(atom->tag[start]) + " d_kl 2.5\nset atom " +
         std::to_string(atom->tag[end]) + " d_kl 7.0\nset atom " + std::to_string(atom->tag[0]) +
         " d_kb 3.0\nrun 0 post no");
  double du, du2, f;
  segment->born_matrix(1, r * r, seg.first, seg.second, du, du2);
  EXPECT_DOUBLE_EQ(du, 2.5 * du1);
  EXPECT_DOUBLE_EQ(du2, 2.5 * du2_1);
  EXPECT_DOUBLE_EQ(segment->single(1, r * r, seg.first, seg.second, f), 2.5 * e1);
  EXPECT_DOUBLE_EQ(f, 2.5 * f1);
  check_bond(segment, 1, seg.first, seg.second, r, "segment with a factor");
  const LAMMPS_NS::DPoly::Law bend = angle->turning_law(1, 0, 0.7);
  EXPECT_DOUBLE_EQ(bend.energy, 3.0 * bend1.energy);
  EXPECT_DOUBLE_EQ(bend.first, 3.0 * bend1.first);
  EXPECT_DOUBLE_EQ(bend.second, 3.0 * bend1.second);
}
