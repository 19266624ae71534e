/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "dpoly_refine_rules.h"

#include <algorithm>
#include <cmath>
#include <utility>

using namespace LAMMPS_NS;
using namespace DPoly;

RefineTable::RefineTable(std::vector<RefineVertex> vertices, std::vector<Ring> rings,
                         const AdhesionCounts &counts, const std::vector<AdhesiveBond> &bonds) :
    vertex_list(std::move(vertices)),
    ring_list(std::move(rings)), counts(counts)
{
  for (size_t k = 0; k < vertex_list.size(); k++) index[vertex_list[k].tag] = (int) k;
  for (const Ring &ring : ring_list)
    for (size_t k = 0; k < ring.vertices.size(); k++)
      before[ring.vertices[(k + 1) % ring.vertices.size()]] = ring.vertices[k];
  // the closest partner of each bonded vertex; equal distances: the partner of lower ID
  std::unordered_map<tagint, std::pair<double, tagint>> closest;
  auto offer = [&](tagint atom, tagint partner, tagint cell, double distance) {
    const auto found = closest.find(atom);
    if (found != closest.end() && std::make_pair(distance, partner) >= found->second) return;
    closest[atom] = {distance, partner};
    partner_cell[atom] = cell;
  };
  for (const AdhesiveBond &b : bonds) {
    offer(b.atom1, b.atom2, b.cell2, b.distance);
    offer(b.atom2, b.atom1, b.cell1, b.distance);
  }
}

tagint RefineTable::closest_partner_cell(tagint tag) const
{
  const auto found = partner_cell.find(tag);
  return found == partner_cell.end() ? 0 : found->second;
}

namespace {

using Ring = RefineTable::Ring;

// A ring segment, by its two vertices in ring order.
struct Segment {
  const RefineVertex &first, &second;
};

template <typename Visit> void for_each_segment(const RefineTable &table, Visit visit)
{
  for (const Ring &ring : table.rings()) {
    const int n = (int) ring.vertices.size();
    for (int k = 0; k < n; k++)
      visit(ring,
            Segment{table.vertex(ring.vertices[k]), table.vertex(ring.vertices[(k + 1) % n])});
  }
}

VertexUpdate unchanged(const RefineVertex &v)
{
  return {v.tag, v.preferred_length, v.preferred_angle, v.segment_factor, v.bending_factor};
}

/* ----------------------------------------------------------------------
   tension: a segment longer than 'radii' times the mean radius of its two vertices, both
   void-facing unless void no, splits once at its midpoint. The new vertex is straight
   (theta0 = 0) with the mean diameter; each half takes the preferred length h at which it carries
   the segment's tension with the segment's stiffness, (1/h)(l/2h - 1) = (1/l0)(l/l0 - 1). At
   most cap times the vertices a cell had at the first refinement; the longest split first.
------------------------------------------------------------------------- */

class TensionRules : public RefineRules {
 public:
  using RefineRules::RefineRules;
  RefinePlan plan(const RefineTable &table, const std::map<tagint, int> &initial) const override;

 private:
  static double half_preferred_length(double l, double l0)
  {
    const double x = l / l0;
    return l / (1.0 + sqrt(1.0 + 2.0 * x * (x - 1.0)));
  }
};

RefinePlan TensionRules::plan(const RefineTable &table, const std::map<tagint, int> &initial) const
{
  std::vector<SegmentSplit> candidates;
  std::map<tagint, int> vertices;    // per cell, now
  for (const Ring &ring : table.rings()) vertices[ring.cell] = (int) ring.vertices.size();
  for_each_segment(table, [&](const Ring &ring, const Segment &s) {
    const double length = s.first.length;
    if (length <= settings.radii * 0.25 * (s.first.diameter + s.second.diameter)) return;
    if (settings.void_only && !(table.void_facing(s.first.tag) && table.void_facing(s.second.tag)))
      return;
    const double h = half_preferred_length(length, s.first.preferred_length);
    const NewVertex added = {0,
                             0.5 * (s.first.diameter + s.second.diameter),
                             h,
                             0.0,
                             s.first.segment_factor,
                             0.5 * (s.first.bending_factor + s.second.bending_factor)};
    candidates.push_back({s.first.tag, s.second.tag, ring.cell, length, {added}});
  });

  // per cell, the longest that fit under the cap
  std::sort(candidates.begin(), candidates.end(), [](const SegmentSplit &a, const SegmentSplit &b) {
    return a.first < b.first;
  });
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const SegmentSplit &a, const SegmentSplit &b) {
                     return a.cell != b.cell ? a.cell < b.cell : a.length > b.length;
                   });
  RefinePlan plan;
  tagint cell = -1;
  int room = 0;
  for (const SegmentSplit &s : candidates) {
    if (s.cell != cell) {
      cell = s.cell;
      const auto first = initial.find(cell);
      const int count = vertices[cell];
      room = (int) floor(settings.cap * (first == initial.end() ? count : first->second)) - count;
    }
    if (room > 0) {
      plan.splits.push_back(s);
      room--;
    }
  }
  std::sort(plan.splits.begin(), plan.splits.end(),
            [](const SegmentSplit &a, const SegmentSplit &b) {
              return a.first < b.first;
            });
  for (const SegmentSplit &s : plan.splits) {
    VertexUpdate first = unchanged(table.vertex(s.first));
    first.preferred_length = s.added[0].preferred_length;
    plan.updates.push_back(first);
  }
  return plan;
}

/* ----------------------------------------------------------------------
   The candidates of the published code (meso2D::addMesophyllCellMaterial()): how many times the
   segment first -> second is queued. A void-facing vertex queues each of its two segments that is
   longer than 'radii' of its own radii, so a long segment between two void vertices is queued
   twice; a segment between two bonded vertices whose closest bonded partners lie on different
   cells (a junction) is queued once, whatever its length. (The code's third rule, an unbonded
   vertex between two bonded ones, sits in a branch that the first rule always takes first.)
------------------------------------------------------------------------- */

int published_requests(const RefineTable &table, const Segment &s, double radii)
{
  const bool first_void = table.void_facing(s.first.tag);
  const bool second_void = table.void_facing(s.second.tag);
  if (!first_void && !second_void)
    return table.closest_partner_cell(s.first.tag) != table.closest_partner_cell(s.second.tag) ? 1
                                                                                               : 0;
  const double length = s.first.length;
  return (first_void && length > radii * 0.5 * s.first.diameter ? 1 : 0) +
      (second_void && length > radii * 0.5 * s.second.diameter ? 1 : 0);
}

// The published cap: no insertion once the tissue holds cap times its initial vertex count;
// below it, every queued split of the step is made.
bool below_total_cap(const RefineTable &table, const std::map<tagint, int> &initial, double cap)
{
  double now = 0.0, first = 0.0;
  for (const Ring &ring : table.rings()) {
    now += (double) ring.vertices.size();
    const auto found = initial.find(ring.cell);
    first += found == initial.end() ? (double) ring.vertices.size() : (double) found->second;
  }
  return now < cap * first;
}

/* ----------------------------------------------------------------------
   published: meso2D::addVertex() once per queued request. The new vertex sits at the segment's
   midpoint with the first vertex's radius; the two halves get half the segment's l0 and half its
   stiffness factor; its bending stiffness is the mean of the two vertices' and its theta0
     theta0 = -[kb_1 (theta_1 - theta0_1) + kb_2 (theta_2 - theta0_2)] / (kb_1 + kb_2)
   from the deviations at the segment's ends (kb = eps_b d_kb). A second request splits the second
   half again the same way (pieces l0/2, l0/4, l0/4), the first new vertex being straight.
------------------------------------------------------------------------- */

class PublishedRules : public RefineRules {
 public:
  using RefineRules::RefineRules;
  RefinePlan plan(const RefineTable &table, const std::map<tagint, int> &initial) const override;
  bool needs_adhesive_bonds() const override { return true; }
  bool needs_segment_factors() const override { return true; }
  bool before_growth() const override { return true; }
};

// theta0 of a vertex put between two with bending stiffness k1, k2 and angle deviations d1, d2
double published_preferred_angle(double k1, double d1, double k2, double d2)
{
  if (k1 + k2 == 0.0) return -0.5 * (d1 + d2);    // no stiffness: equal weights
  return -(k1 * d1 + k2 * d2) / (k1 + k2);
}

RefinePlan PublishedRules::plan(const RefineTable &table,
                                const std::map<tagint, int> &initial) const
{
  RefinePlan plan;
  if (!below_total_cap(table, initial, settings.cap)) return plan;
  for_each_segment(table, [&](const Ring &ring, const Segment &s) {
    const int requests = published_requests(table, s, settings.radii);
    if (requests == 0) return;
    const RefineVertex &a = s.first, &b = s.second;
    const double second_deviation = b.turning_angle - b.preferred_angle;
    SegmentSplit split = {a.tag, b.tag, ring.cell, a.length, {}};

    // the vertex before the next new one: its l0, factors, and deviation from theta0
    double l0 = a.preferred_length, kl = a.segment_factor, kb = a.bending_factor;
    double deviation = a.turning_angle - a.preferred_angle;
    for (int r = 0; r < requests; r++) {
      const double kb_new = 0.5 * (kb + b.bending_factor);
      const double theta0 = published_preferred_angle(
          a.type_bending * kb, deviation, b.type_bending * b.bending_factor, second_deviation);
      l0 *= 0.5;
      kl *= 0.5;
      if (r > 0) {    // the previous new vertex's own segment is halved
        split.added.back().preferred_length = l0;
        split.added.back().segment_factor = kl;
      }
      split.added.push_back({0, a.diameter, l0, theta0, kl, kb_new});
      kb = kb_new;
      deviation = 0.0 - theta0;    // the new vertex is straight
    }
    plan.splits.push_back(split);
    VertexUpdate first = unchanged(a);
    first.preferred_length = 0.5 * a.preferred_length;
    first.segment_factor = 0.5 * a.segment_factor;
    plan.updates.push_back(first);
  });
  std::sort(plan.splits.begin(), plan.splits.end(),
            [](const SegmentSplit &x, const SegmentSplit &y) {
              return x.first < y.first;
            });
  return plan;
}

/* ----------------------------------------------------------------------
   consistent: the published candidates and cap, each segment split once at its midpoint, so
   that the ring tends to a continuous elastic curve as vertices are added.
   Stretching: U = (k eps_l/2)(l/l0 - 1)^2 is a spring of constant k eps_l/l0^2. Halves with l0/2
   and k/2 are springs of twice that constant, which in series give the segment's again; at the
   midpoint each half has the segment's strain, tension and half its energy, so the ring's
   stretching energy and forces do not change.
   Bending: a curve of bending modulus B and curvature kappa has energy (B/2) kappa^2 ds; at a
   vertex with turning angle theta = kappa lbar, lbar = (l0_prev + l0_next)/2 the length it
   stands for, that is (B/lbar)(theta - kappa0 lbar)^2/2. So each vertex keeps its B = kb lbar
   and kappa0 = theta0/lbar: where a split shortens lbar, kb grows and theta0 shrinks by the
   ratio; the new vertex takes the mean B and kappa0 of the segment's two vertices.
------------------------------------------------------------------------- */

class ConsistentRules : public RefineRules {
 public:
  using RefineRules::RefineRules;
  RefinePlan plan(const RefineTable &table, const std::map<tagint, int> &initial) const override;
  bool needs_adhesive_bonds() const override { return true; }
  bool needs_segment_factors() const override { return true; }
  bool needs_bending_factors() const override { return true; }
  bool before_growth() const override { return true; }
};

RefinePlan ConsistentRules::plan(const RefineTable &table,
                                 const std::map<tagint, int> &initial) const
{
  RefinePlan plan;
  if (!below_total_cap(table, initial, settings.cap)) return plan;
  std::unordered_map<tagint, double> halved;    // 0.5 where the vertex's segment splits, else 1
  for_each_segment(table, [&](const Ring &ring, const Segment &s) {
    const bool splits = published_requests(table, s, settings.radii) > 0;
    halved[s.first.tag] = splits ? 0.5 : 1.0;
    if (splits) plan.splits.push_back({s.first.tag, s.second.tag, ring.cell, s.first.length, {}});
  });

  // the length lbar a vertex stands for, before and after the splits, from its two segments' l0
  auto represented = [&](const RefineVertex &prev, const RefineVertex &v, bool after) {
    return after
        ? 0.5 * (halved[prev.tag] * prev.preferred_length + halved[v.tag] * v.preferred_length)
        : 0.5 * (prev.preferred_length + v.preferred_length);
  };
  for (const Ring &ring : table.rings()) {
    const int n = (int) ring.vertices.size();
    for (int k = 0; k < n; k++) {
      const RefineVertex &prev = table.vertex(ring.vertices[(k + n - 1) % n]);
      const RefineVertex &v = table.vertex(ring.vertices[k]);
      const double was = represented(prev, v, false), now = represented(prev, v, true);
      if (was == now) continue;
      // the same B = kb lbar and kappa0 = theta0/lbar on less of the ring
      plan.updates.push_back({v.tag, halved[v.tag] * v.preferred_length,
                              v.preferred_angle * now / was, halved[v.tag] * v.segment_factor,
                              v.bending_factor * was / now});
    }
  }

  // the new vertex: the mean B and kappa0 of the segment's ends, on half the segment
  for (SegmentSplit &split : plan.splits) {
    const RefineVertex &a = table.vertex(split.first), &b = table.vertex(split.second);
    const RefineVertex &before_a = table.vertex(table.previous(a.tag));
    const double lbar_a = represented(before_a, a, false), lbar_b = represented(a, b, false);
    const double lbar = 0.5 * a.preferred_length;
    const double modulus = 0.5 * (a.bending_factor * lbar_a + b.bending_factor * lbar_b);
    const double curvature = 0.5 * (a.preferred_angle / lbar_a + b.preferred_angle / lbar_b);
    split.added.push_back({0, 0.5 * (a.diameter + b.diameter), 0.5 * a.preferred_length,
                           curvature * lbar, 0.5 * a.segment_factor, modulus / lbar});
  }
  std::sort(plan.splits.begin(), plan.splits.end(),
            [](const SegmentSplit &x, const SegmentSplit &y) {
              return x.first < y.first;
            });
  return plan;
}

}    // namespace

std::unique_ptr<RefineRules> RefineRules::create(const std::string &name, const Settings &settings)
{
  if (name == "tension") return std::unique_ptr<RefineRules>(new TensionRules(settings));
  if (name == "published") return std::unique_ptr<RefineRules>(new PublishedRules(settings));
  if (name == "consistent") return std::unique_ptr<RefineRules>(new ConsistentRules(settings));
  return nullptr;
}
