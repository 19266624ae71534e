/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_overlap.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace LAMMPS_NS {
namespace DPoly {

  bool segments_cross(const Point &a, const Point &b, const Point &c, const Point &d)
  {
    // the sign of the cross product: on which side of pq the point r lies
    auto side = [](const Point &p, const Point &q, const Point &r) {
      return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    };
    const double s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
    return ((s1 > 0) != (s2 > 0)) && ((s3 > 0) != (s4 > 0)) && s1 != 0 && s2 != 0 && s3 != 0 &&
        s4 != 0;
  }

  bool inside_polygon(const Point &p, const std::vector<Point> &polygon)
  {
    // count the edges that a ray from p in +x crosses
    bool inside = false;
    const int n = (int) polygon.size();
    for (int i = 0, j = n - 1; i < n; j = i++) {
      const Point &u = polygon[i], &v = polygon[j];
      if ((u[1] > p[1]) == (v[1] > p[1])) continue;
      const double x = u[0] + (p[1] - u[1]) * (v[0] - u[0]) / (v[1] - u[1]);
      if (p[0] < x) inside = !inside;
    }
    return inside;
  }

  namespace {

    // p on the segment uv (exactly: collinear and between its ends)
    bool on_segment(const Point &p, const Point &u, const Point &v)
    {
      const double cross = (v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]);
      return cross == 0.0 && p[0] >= std::min(u[0], v[0]) && p[0] <= std::max(u[0], v[0]) &&
          p[1] >= std::min(u[1], v[1]) && p[1] <= std::max(u[1], v[1]);
    }

    // a vertex or segment midpoint of outline a (moved by shift) strictly inside polygon b:
    // points on b's outline say nothing (outlines may touch), the others decide
    bool holds_a_point_of(const std::vector<Point> &b, const std::vector<Point> &a,
                          const Point &shift)
    {
      const int na = (int) a.size(), nb = (int) b.size();
      for (int i = 0; i < na; i++) {
        const Point &u = a[i], &v = a[(i + 1) % na];
        for (const Point &p : {Point{u[0] + shift[0], u[1] + shift[1]},
                               Point{0.5 * (u[0] + v[0]) + shift[0],
                                     0.5 * (u[1] + v[1]) + shift[1]}}) {
          bool on_outline = false;
          for (int j = 0; j < nb && !on_outline; j++)
            on_outline = on_segment(p, b[j], b[(j + 1) % nb]);
          if (!on_outline && inside_polygon(p, b)) return true;
        }
      }
      return false;
    }

    struct Bounds {
      Point lo, hi;
      bool meets(const Bounds &o) const
      {
        return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1];
      }
      Bounds shifted(const Point &s) const
      {
        return {{lo[0] + s[0], lo[1] + s[1]}, {hi[0] + s[0], hi[1] + s[1]}};
      }
      bool finite() const
      {
        return std::isfinite(lo[0]) && std::isfinite(lo[1]) && std::isfinite(hi[0]) &&
            std::isfinite(hi[1]);
      }
    };

    Bounds bounds_of(const Point &a, const Point &b)
    {
      return {{std::min(a[0], b[0]), std::min(a[1], b[1])},
              {std::max(a[0], b[0]), std::max(a[1], b[1])}};
    }

    Bounds bounds_of(const std::vector<Point> &ring)
    {
      Bounds b{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
      for (const Point &p : ring)
        for (int d = 0; d < 2; d++) {
          b.lo[d] = std::min(b.lo[d], p[d]);
          b.hi[d] = std::max(b.hi[d], p[d]);
        }
      return b;
    }

    // Cells binned by the lower corner of their bounding box, each bin at least as wide as the
    // widest box: two boxes that meet (under some periodic image) then lie in the same or in
    // neighbouring bins.
    class CellGrid {
     public:
      CellGrid(const std::vector<Bounds> &cells, const std::vector<int> &binned, const Box &box)
      {
        // at most about 4 bins per cell, however small the cells are in the box
        const int cap = 2 * (int) std::ceil(std::sqrt((double) binned.size())) + 1;
        for (int d = 0; d < 2; d++) {
          double widest = 0.0, lowest = INFINITY, highest = -INFINITY;
          for (int c : binned) {
            widest = std::max(widest, cells[c].hi[d] - cells[c].lo[d]);
            lowest = std::min(lowest, cells[c].lo[d]);
            highest = std::max(highest, cells[c].lo[d]);
          }
          widest *= 1.0 + 1.0e-9;    // rounding at a bin edge must not skip a bin
          periodic[d] = box.periodic[d];
          if (periodic[d]) {
            nbins[d] = std::clamp((int) std::floor(box.length[d] / widest), 1, cap);
            origin[d] = 0.0;
            width[d] = box.length[d] / nbins[d];
          } else {
            const double range = binned.empty() ? 0.0 : highest - lowest;
            width[d] = std::max({widest, range / cap, 1.0e-300});
            nbins[d] = std::min(cap, (int) std::floor(range / width[d]) + 1);
            origin[d] = binned.empty() ? 0.0 : lowest;
          }
        }
        bins.resize((size_t) nbins[0] * nbins[1]);
        bin_of_cell.assign(cells.size(), -1);
        for (int c : binned) {
          int index[2];
          for (int d = 0; d < 2; d++) index[d] = slot(cells[c].lo[d], d);
          bin_of_cell[c] = index[0] + nbins[0] * index[1];
          bins[bin_of_cell[c]].push_back(c);
        }
      }

      // the bins next to cell c's and its own, each once (a periodic grid of 1 or 2 bins wraps
      // onto itself)
      std::vector<int> bins_around(int c) const
      {
        const int ix = bin_of_cell[c] % nbins[0], iy = bin_of_cell[c] / nbins[0];
        std::vector<int> around;
        for (int dy = -1; dy <= 1; dy++)
          for (int dx = -1; dx <= 1; dx++) {
            int jx = ix + dx, jy = iy + dy;
            if (!wrap(jx, 0) || !wrap(jy, 1)) continue;
            around.push_back(jx + nbins[0] * jy);
          }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        return around;
      }
      const std::vector<int> &cells_in(int bin) const { return bins[bin]; }

     private:
      int nbins[2];
      bool periodic[2];
      double origin[2], width[2];
      std::vector<std::vector<int>> bins;
      std::vector<int> bin_of_cell;

      int slot(double coordinate, int d) const
      {
        double t = (coordinate - origin[d]) / width[d];
        if (periodic[d]) t -= nbins[d] * std::floor(t / nbins[d]);
        return std::clamp((int) std::floor(t), 0, nbins[d] - 1);
      }
      bool wrap(int &index, int d) const
      {
        if (periodic[d]) {
          index = (index % nbins[d] + nbins[d]) % nbins[d];
          return true;
        }
        return index >= 0 && index < nbins[d];
      }
    };

    // the segments (by first vertex) of a ring, moved by shift, that reach into the window
    std::vector<int> segments_within(const std::vector<Point> &ring, const Point &shift,
                                     const Bounds &window)
    {
      std::vector<int> inside;
      const int n = (int) ring.size();
      for (int i = 0; i < n; i++) {
        const Point &a = ring[i], &b = ring[(i + 1) % n];
        if (bounds_of({a[0] + shift[0], a[1] + shift[1]}, {b[0] + shift[0], b[1] + shift[1]})
                .meets(window))
          inside.push_back(i);
      }
      return inside;
    }

    // outline a against outline b moved by shift
    bool outlines_overlap(const Outline &a, const Bounds &box_a, const Outline &b,
                          const Bounds &box_b, const Point &shift)
    {
      const Bounds moved_b = box_b.shifted(shift);
      const Bounds window{
          {std::max(box_a.lo[0], moved_b.lo[0]), std::max(box_a.lo[1], moved_b.lo[1])},
          {std::min(box_a.hi[0], moved_b.hi[0]), std::min(box_a.hi[1], moved_b.hi[1])}};
      const std::vector<int> near_a = segments_within(a.corners, {0.0, 0.0}, window);
      const std::vector<int> near_b = segments_within(b.corners, shift, window);
      const int na = (int) a.corners.size(), nb = (int) b.corners.size();
      for (int i : near_a)
        for (int j : near_b) {
          const Point &c = b.corners[j], &d = b.corners[(j + 1) % nb];
          if (segments_cross(a.corners[i], a.corners[(i + 1) % na],
                             {c[0] + shift[0], c[1] + shift[1]},
                             {d[0] + shift[0], d[1] + shift[1]}))
            return true;
        }
      // no side crosses another: the outlines still overlap where one holds the other whole, or
      // where they share sides (exactly collinear, e.g. lattice-made cells) and yet one reaches
      // into the other; either way some vertex or segment midpoint lies strictly inside
      return holds_a_point_of(b.corners, a.corners, {-shift[0], -shift[1]}) ||
          holds_a_point_of(a.corners, b.corners, shift);
    }

    // the image shifts k L (k integer) along d that bring [lo_b, hi_b] onto [lo_a, hi_a]
    std::pair<long, long> image_range(const Bounds &a, const Bounds &b, const Box &box, int d)
    {
      if (!box.periodic[d]) return {0, 0};
      return {(long) std::ceil((a.lo[d] - b.hi[d]) / box.length[d]),
              (long) std::floor((a.hi[d] - b.lo[d]) / box.length[d])};
    }

  }    // namespace

  Interpenetration interpenetrating_cells(const std::vector<Outline> &outlines, const Box &box)
  {
    const int ncells = (int) outlines.size();
    std::vector<Bounds> bounds(ncells);
    std::vector<int> binned;    // cells with corners and finite coordinates
    for (int c = 0; c < ncells; c++) {
      bounds[c] = bounds_of(outlines[c].corners);
      if (!outlines[c].corners.empty() && bounds[c].finite()) binned.push_back(c);
    }
    const CellGrid grid(bounds, binned, box);

    Interpenetration found;
    auto record = [&found](tagint one, tagint other) {
      const std::pair<tagint, tagint> pair = std::minmax(one, other);
      if (!found.pairs || pair < std::make_pair(found.first[0], found.first[1])) {
        found.first[0] = pair.first;
        found.first[1] = pair.second;
      }
      found.pairs++;
    };
    for (int a : binned)
      for (int bin : grid.bins_around(a))
        for (int b : grid.cells_in(bin)) {
          if (b < a) continue;    // each pair once, a cell with its own images too
          const auto kx = image_range(bounds[a], bounds[b], box, 0);
          const auto ky = image_range(bounds[a], bounds[b], box, 1);
          bool overlap = false;
          for (long i = kx.first; i <= kx.second && !overlap; i++)
            for (long j = ky.first; j <= ky.second && !overlap; j++) {
              if (a == b && i == 0 && j == 0) continue;    // a ring against itself: not here
              const Point shift{i * box.length[0], j * box.length[1]};
              if (!bounds[a].meets(bounds[b].shifted(shift))) continue;
              overlap = outlines_overlap(outlines[a], bounds[a], outlines[b], bounds[b], shift);
            }
          if (overlap) record(outlines[a].cell, outlines[b].cell);
        }
    return found;
  }

}    // namespace DPoly
}    // namespace LAMMPS_NS
