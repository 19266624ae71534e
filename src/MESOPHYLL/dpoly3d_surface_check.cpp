/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly3d_surface_check.h"

#include "atom.h"
#include "domain.h"
#include "dpoly_cell_hub.h"
#include "dpoly_ring.h"
#include "error.h"
#include "lammps.h"
#include "math_const.h"
#include "math_extra.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using MathExtra::cross3;
using MathExtra::dot3;
using MathExtra::len3;

namespace {
// V / S^(3/2) at or below which a cell counts as collapsed (a sphere has 0.094)
constexpr double COLLAPSED = 1.0e-10;
// how far outside a face its point tested for being inside the cell lies, over sqrt(its area)
constexpr double OFF_FACE = 1.0e-4;

struct VertexRecord {
  tagint tag, molecule;
  double x[3];    // unwrapped
};
struct FaceRecord {
  tagint a, b, c;    // counter-clockwise from outside
};

// a cell's vertices and faces as coordinates, with its vertex centroid and the largest distance
// of a vertex from it (a point farther away is outside)
struct Cell {
  tagint id = 0;
  std::vector<const VertexRecord *> vertices;
  std::vector<FaceRecord> faces;
  std::vector<double> triangles;    // 9 coordinates per face
  double centroid[3] = {0.0, 0.0, 0.0};
  double reach = 0.0;
};
}    // namespace

double DPoly3d::winding_number(const double *p, const double *triangles, int ntriangles)
{
  // solid angle of a triangle seen from p (Van Oosterom and Strackee's formula)
  double total = 0.0;
  for (int t = 0; t < ntriangles; t++) {
    double r[3][3], len[3];
    for (int k = 0; k < 3; k++) {
      for (int d = 0; d < 3; d++) r[k][d] = triangles[9 * t + 3 * k + d] - p[d];
      len[k] = len3(r[k]);
    }
    double bc[3];
    cross3(r[1], r[2], bc);
    const double numerator = dot3(r[0], bc);
    const double denominator = len[0] * len[1] * len[2] + dot3(r[0], r[1]) * len[2] +
        dot3(r[0], r[2]) * len[1] + dot3(r[1], r[2]) * len[0];
    total += 2.0 * atan2(numerator, denominator);
  }
  return total / (4.0 * MathConst::MY_PI);
}

DPoly3d::SurfaceProblems DPoly3d::check_surfaces(LAMMPS *lmp, const DPoly::CellHub &hub,
                                                 int groupbit)
{
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  std::vector<VertexRecord> my_vertices;
  std::vector<FaceRecord> my_faces;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    VertexRecord v = {atom->tag[i], atom->molecule[i], {0.0, 0.0, 0.0}};
    domain->unmap(atom->x[i], atom->image[i], v.x);
    my_vertices.push_back(v);
    for (int m = 0; m < atom->num_angle[i]; m++)    // a face is an angle, kept by its middle
      if (atom->angle_atom2[i][m] == atom->tag[i])
        my_faces.push_back({atom->angle_atom1[i][m], atom->tag[i], atom->angle_atom3[i][m]});
  }
  const std::vector<VertexRecord> vertices =
      DPoly::gather_on_all_ranks(std::move(my_vertices), lmp->world);
  const std::vector<FaceRecord> faces = DPoly::gather_on_all_ranks(std::move(my_faces), lmp->world);

  std::unordered_map<tagint, const VertexRecord *> by_tag;
  std::vector<Cell> cells(hub.ncells());
  std::unordered_map<tagint, int> cell_of_molecule;
  for (int c = 0; c < hub.ncells(); c++) {
    cells[c].id = hub.cell_id(c);
    cell_of_molecule[cells[c].id] = c;
  }
  auto cell_of = [&](tagint molecule) {
    const auto found = cell_of_molecule.find(molecule);
    return found == cell_of_molecule.end() ? -1 : found->second;
  };
  for (const VertexRecord &v : vertices) {
    by_tag[v.tag] = &v;
    const int c = cell_of(v.molecule);
    if (c >= 0) cells[c].vertices.push_back(&v);
  }
  // every rank holds all records, so every rank stops here alike
  auto corner_of = [&](const FaceRecord &f, tagint corner) {
    const auto found = by_tag.find(corner);
    if (found == by_tag.end())
      lmp->error->all(FLERR,
                      "Fix dpoly/check: face {} {} {} (an angle) has atom {} outside the fix's "
                      "group: the group must hold whole cells",
                      f.a, f.b, f.c, corner);
    return found->second;
  };
  for (const FaceRecord &f : faces) {
    const int c = cell_of(corner_of(f, f.b)->molecule);
    if (c < 0) continue;
    cells[c].faces.push_back(f);
    for (tagint corner : {f.a, f.b, f.c}) {
      const VertexRecord *v = corner_of(f, corner);
      cells[c].triangles.insert(cells[c].triangles.end(), v->x, v->x + 3);
    }
  }
  for (Cell &cell : cells) {
    if (cell.vertices.empty()) continue;
    for (const VertexRecord *v : cell.vertices)
      for (int d = 0; d < 3; d++) cell.centroid[d] += v->x[d] / cell.vertices.size();
    for (const VertexRecord *v : cell.vertices) {
      double r[3];
      for (int d = 0; d < 3; d++) r[d] = v->x[d] - cell.centroid[d];
      cell.reach = std::max(cell.reach, len3(r));
    }
  }

  SurfaceProblems found;
  // cells are in ID order, so the first one found has the lowest ID
  for (int c = 0; c < hub.ncells(); c++) {
    // V = (1/6) sum over faces of x_a . (x_b x x_c), as the hub measures it, here on the
    // positions tested (a state made by hand after the last force evaluation too), taken from
    // the cell's centroid: from the origin, the round-off would grow with the cell's distance
    // from it squared and could hide a flat cell far from the origin
    double volume = 0.0, area = 0.0;
    for (size_t k = 0; k < cells[c].faces.size(); k++) {
      const double *x = &cells[c].triangles[9 * k];
      double r[3][3];
      for (int m = 0; m < 3; m++)
        for (int d = 0; d < 3; d++) r[m][d] = x[3 * m + d] - cells[c].centroid[d];
      double bc[3], ab[3], ac[3], normal[3];
      cross3(r[1], r[2], bc);
      volume += dot3(r[0], bc) / 6.0;
      for (int d = 0; d < 3; d++) {
        ab[d] = x[3 + d] - x[d];
        ac[d] = x[6 + d] - x[d];
      }
      cross3(ab, ac, normal);
      area += 0.5 * len3(normal);
    }
    found.total_volume += volume;
    // a flat cell has V = 0 only up to the round-off of the sum, which scales as S^(3/2)
    if (!(volume > COLLAPSED * area * sqrt(area))) {
      if (!found.collapsed) {
        found.first_collapsed = cells[c].id;
        found.first_volume = volume;
      }
      found.collapsed++;
    }
    // A face pointing into its cell: the point just off its centre on its outer side is
    // enclosed by the cell's own surface, winding number +1 where the surface folds back over
    // itself, -1 where it is turned inside out (a sound cell has 0 there, lobed or dented too:
    // the centroid's side of the face plane says nothing for cells that are not star-shaped).
    // Of several, the one with the lowest (middle, first, last) IDs.
    const FaceRecord *inward = nullptr;
    for (size_t k = 0; k < cells[c].faces.size(); k++) {
      const double *x = &cells[c].triangles[9 * k];
      double ab[3], ac[3], normal[3];
      for (int d = 0; d < 3; d++) {
        ab[d] = x[3 + d] - x[d];
        ac[d] = x[6 + d] - x[d];
      }
      cross3(ab, ac, normal);
      const double twice_area = len3(normal);
      if (!(twice_area > 0.0)) continue;    // no direction: a flat cell is the volume test's
      // off the face by a small fraction of its size: nearer than any other part of the surface
      const double step = OFF_FACE * sqrt(0.5 * twice_area) / twice_area;
      double p[3];
      for (int d = 0; d < 3; d++) p[d] = (x[d] + x[3 + d] + x[6 + d]) / 3.0 + step * normal[d];
      const double w =
          winding_number(p, cells[c].triangles.data(), (int) cells[c].faces.size());
      if (std::fabs(w) < 0.5) continue;
      const FaceRecord &f = cells[c].faces[k];
      if (!inward || std::tie(f.b, f.a, f.c) < std::tie(inward->b, inward->a, inward->c))
        inward = &f;
    }
    if (inward) {
      if (!found.folded) {
        found.first_folded = cells[c].id;
        found.first_face[0] = inward->a;
        found.first_face[1] = inward->b;
        found.first_face[2] = inward->c;
      }
      found.folded++;
    }
  }

  // a vertex inside another cell: tested against every image of that cell whose centroid is
  // within the cell's reach of the vertex. Two such images are less than 2 reach apart, so
  // from the nearest image the others lie at most 2 reach / width box lengths along each
  // periodic direction (one more for minimum_image_big's approximation in triclinic boxes);
  // a cell as long as half the box, as in a narrow periodic box, has several.
  const double *h = domain->h;
  double a_vec[3] = {h[0], 0.0, 0.0}, b_vec[3] = {h[5], h[1], 0.0}, c_vec[3] = {h[4], h[3], h[2]};
  double bc[3], ca[3], ab[3];
  cross3(b_vec, c_vec, bc);
  cross3(c_vec, a_vec, ca);
  cross3(a_vec, b_vec, ab);
  const double box_volume = dot3(a_vec, bc);
  // the distance between opposite faces of the box, along each lattice vector
  const double width[3] = {box_volume / len3(bc), box_volume / len3(ca), box_volume / len3(ab)};
  std::map<std::pair<tagint, tagint>, std::pair<tagint, tagint>> inside;    // -> vertex, cell
  for (const Cell &host : cells) {
    if (host.faces.empty()) continue;
    int shifts[3];
    for (int k = 0; k < 3; k++)
      shifts[k] = domain->periodicity[k] ? (int) (2.0 * host.reach / width[k]) + 1 : 0;
    for (const Cell &guest : cells) {
      if (&guest == &host) continue;
      for (const VertexRecord *v : guest.vertices) {
        double nearest[3];
        for (int k = 0; k < 3; k++) nearest[k] = v->x[k] - host.centroid[k];
        domain->minimum_image_big(FLERR, nearest);
        bool enclosed = false;
        for (int i = -shifts[0]; i <= shifts[0] && !enclosed; i++)
          for (int j = -shifts[1]; j <= shifts[1] && !enclosed; j++)
            for (int l = -shifts[2]; l <= shifts[2] && !enclosed; l++) {
              double d[3];
              for (int k = 0; k < 3; k++)
                d[k] = nearest[k] + i * a_vec[k] + j * b_vec[k] + l * c_vec[k];
              if (!(len3(d) < host.reach)) continue;
              double p[3];
              for (int k = 0; k < 3; k++) p[k] = host.centroid[k] + d[k];
              enclosed = winding_number(p, host.triangles.data(), (int) host.faces.size()) > 0.5;
            }
        if (!enclosed) continue;
        const std::pair<tagint, tagint> pair(std::min(host.id, guest.id),
                                             std::max(host.id, guest.id));
        const auto known = inside.find(pair);
        if (known == inside.end() || v->tag < known->second.first)
          inside[pair] = {v->tag, guest.id};
      }
    }
  }
  found.pairs = (int) inside.size();
  if (!inside.empty()) {
    const auto &first = *inside.begin();
    found.first_pair[0] = first.first.first;
    found.first_pair[1] = first.first.second;
    found.first_vertex = first.second.first;
    found.first_vertex_cell = first.second.second;
  }
  return found;
}
