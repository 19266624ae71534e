/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly3d_slice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

using namespace LAMMPS_NS;
using namespace DPoly3d;

namespace {

// a crossing edge in one plane image: (plane, image along z, lower vertex ID, higher vertex ID)
using EdgeKey = std::tuple<int, int, tagint, tagint>;

// the part of an outline inside one face: from where the surface goes down through the plane
// (in the face's counter-clockwise order) to where it comes up; seen from +z the cell's inside
// is then on the left, so the outline runs counter-clockwise
struct Segment {
  tagint cell;
  EdgeKey end;
  double start[2];
};

EdgeKey edge_key(int plane, int image, tagint u, tagint v)
{
  return EdgeKey(plane, image, std::min(u, v), std::max(u, v));
}

// the point of edge below -> above at height zp: interpolated from the edge's lower end, the
// same numbers whichever face asks
void crossing_point(const double *below, const double *above, double zp, double *out)
{
  const double t = (zp - below[2]) / (above[2] - below[2]);
  out[0] = below[0] + t * (above[0] - below[0]);
  out[1] = below[1] + t * (above[1] - below[1]);
}

double point_segment_distance(const double *p, const double *a, const double *b)
{
  const double ab[2] = {b[0] - a[0], b[1] - a[1]}, ap[2] = {p[0] - a[0], p[1] - a[1]};
  const double length2 = ab[0] * ab[0] + ab[1] * ab[1];
  double t = length2 > 0.0 ? (ap[0] * ab[0] + ap[1] * ab[1]) / length2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1]);
}

double orientation(const double *a, const double *b, const double *c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double segment_distance(const double *a, const double *b, const double *c, const double *d)
{
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
      ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
    return 0.0;    // proper crossing
  return std::min(std::min(point_segment_distance(a, c, d), point_segment_distance(b, c, d)),
                  std::min(point_segment_distance(c, a, b), point_segment_distance(d, a, b)));
}

void measure(Outline &o)
{
  const size_t n = o.x.size();
  o.area = o.perimeter = 0.0;
  o.bounds[0] = o.bounds[2] = std::numeric_limits<double>::infinity();
  o.bounds[1] = o.bounds[3] = -std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < n; k++) {
    const size_t next = (k + 1) % n;
    o.area += 0.5 * (o.x[k] * o.y[next] - o.x[next] * o.y[k]);
    o.perimeter += std::hypot(o.x[next] - o.x[k], o.y[next] - o.y[k]);
    o.bounds[0] = std::min(o.bounds[0], o.x[k]);
    o.bounds[1] = std::max(o.bounds[1], o.x[k]);
    o.bounds[2] = std::min(o.bounds[2], o.y[k]);
    o.bounds[3] = std::max(o.bounds[3], o.y[k]);
  }
}

}    // namespace

std::vector<double> DPoly3d::plane_heights(const SliceBox &box, int count, double offset)
{
  std::vector<double> heights;
  for (int j = 0; j < count; j++) heights.push_back(box.zlo + (j + offset) * box.lz / count);
  return heights;
}

std::vector<Outline> DPoly3d::slice_surfaces(const std::vector<SliceVertex> &vertices,
                                             const std::vector<SliceFace> &faces,
                                             const SliceBox &box,
                                             const std::vector<double> &heights)
{
  std::unordered_map<tagint, const SliceVertex *> vertex;
  for (const auto &v : vertices) {
    if (!(std::isfinite(v.x[0]) && std::isfinite(v.x[1]) && std::isfinite(v.x[2])))
      throw std::runtime_error("vertex " + std::to_string(v.tag) + " has a non-finite position");
    vertex[v.tag] = &v;
  }

  std::map<EdgeKey, Segment> segments;    // by the edge where each one starts
  for (const auto &f : faces) {
    const tagint corner[3] = {f.a, f.b, f.c};
    const double *p[3];
    for (int k = 0; k < 3; k++) {
      const auto found = vertex.find(corner[k]);
      if (found == vertex.end())
        throw std::runtime_error("vertex " + std::to_string(corner[k]) + " of a face of cell " +
                                 std::to_string(f.cell) + " is missing");
      p[k] = found->second->x;
    }
    const double zmin = std::min({p[0][2], p[1][2], p[2][2]});
    const double zmax = std::max({p[0][2], p[1][2], p[2][2]});
    for (size_t j = 0; j < heights.size(); j++) {
      // images k with zmin < z_j + k lz <= zmax, one wider on each side against rounding; the
      // exact comparisons below decide
      const int first = (int) std::floor((zmin - heights[j]) / box.lz);
      const int last = (int) std::floor((zmax - heights[j]) / box.lz) + 1;
      for (int image = first; image <= last; image++) {
        const double zp = heights[j] + image * box.lz;
        bool above[3];
        for (int k = 0; k < 3; k++) above[k] = p[k][2] >= zp;
        if (above[0] == above[1] && above[1] == above[2]) continue;
        int down = -1, up = -1;    // edges k -> k+1 that go above -> below and below -> above
        for (int k = 0; k < 3; k++) {
          const int next = (k + 1) % 3;
          if (above[k] && !above[next]) down = k;
          if (!above[k] && above[next]) up = k;
        }
        Segment s;
        s.cell = f.cell;
        s.end = edge_key((int) j, image, corner[up], corner[(up + 1) % 3]);
        crossing_point(p[(down + 1) % 3], p[down], zp, s.start);
        const EdgeKey start = edge_key((int) j, image, corner[down], corner[(down + 1) % 3]);
        if (!segments.emplace(start, s).second)
          throw std::runtime_error("the edge " + std::to_string(std::get<2>(start)) + "-" +
                                   std::to_string(std::get<3>(start)) + " of cell " +
                                   std::to_string(f.cell) +
                                   " starts two outline segments: its surface is not closed "
                                   "and consistently oriented");
      }
    }
  }

  // chain the segments: each ends at the edge where the next one starts
  std::vector<Outline> outlines;
  std::map<EdgeKey, bool> used;
  for (const auto &first : segments) {
    if (used.count(first.first)) continue;
    Outline o;
    o.cell = first.second.cell;
    o.plane = std::get<0>(first.first);
    EdgeKey at = first.first;
    do {
      const auto found = segments.find(at);
      if (found == segments.end() || used.count(at))
        throw std::runtime_error("an outline of cell " + std::to_string(o.cell) +
                                 " does not close at the edge " + std::to_string(std::get<2>(at)) +
                                 "-" + std::to_string(std::get<3>(at)) +
                                 ": its surface is not closed and consistently oriented");
      used[at] = true;
      o.x.push_back(found->second.start[0]);
      o.y.push_back(found->second.start[1]);
      at = found->second.end;
    } while (at != first.first);
    measure(o);
    outlines.push_back(std::move(o));
  }
  std::stable_sort(outlines.begin(), outlines.end(), [](const Outline &a, const Outline &b) {
    return a.plane < b.plane || (a.plane == b.plane && a.cell < b.cell);
  });
  return outlines;
}

double DPoly3d::outline_distance(const Outline &a, const Outline &b, const SliceBox &box)
{
  // b's nearest periodic image by the centres of the bounds, then its neighbours
  double d[2] = {0.5 * (b.bounds[0] + b.bounds[1] - a.bounds[0] - a.bounds[1]),
                 0.5 * (b.bounds[2] + b.bounds[3] - a.bounds[2] - a.bounds[3])};
  const double nx = std::round(d[0] / box.lx), ny = std::round(d[1] / box.ly);
  double best = std::numeric_limits<double>::infinity();
  for (int i = -1; i <= 1; i++)
    for (int j = -1; j <= 1; j++) {
      const double shift[2] = {-(nx + i) * box.lx, -(ny + j) * box.ly};
      // a lower bound from the bounds, to skip far images
      const double gx = std::max(
          {0.0, a.bounds[0] - (b.bounds[1] + shift[0]), (b.bounds[0] + shift[0]) - a.bounds[1]});
      const double gy = std::max(
          {0.0, a.bounds[2] - (b.bounds[3] + shift[1]), (b.bounds[2] + shift[1]) - a.bounds[3]});
      if (std::hypot(gx, gy) >= best) continue;
      const size_t na = a.x.size(), nb = b.x.size();
      for (size_t k = 0; k < na; k++) {
        const double p[2] = {a.x[k], a.y[k]}, q[2] = {a.x[(k + 1) % na], a.y[(k + 1) % na]};
        for (size_t m = 0; m < nb; m++) {
          const double r[2] = {b.x[m] + shift[0], b.y[m] + shift[1]};
          const double s[2] = {b.x[(m + 1) % nb] + shift[0], b.y[(m + 1) % nb] + shift[1]};
          best = std::min(best, segment_distance(p, q, r, s));
        }
      }
    }
  return best;
}
