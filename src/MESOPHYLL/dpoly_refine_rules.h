/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// The rule sets of fix dpoly/refine: which ring segments split, how many times, and the values
// of the new vertices and of the vertices next to them. A rule set reads a whole-system table of
// the tissue at the minimum, the same on every rank, and returns a plan; fix dpoly/refine
// gathers the table and carries the plan out (atoms, bonds, angles). One class per rule set
// (doc/fix_dpoly_refine.rst):
//   tension     the package's first rule: long void segments split once, halves keep the tension
//   published   the published code's meso2D::addMesophyllCellMaterial() and addVertex()
//   consistent  the published candidates split once, with the ring's stretching and bending
//               stiffness kept as the number of vertices grows

#ifndef LMP_DPOLY_REFINE_RULES_H
#define LMP_DPOLY_REFINE_RULES_H

#include "dpoly_adhesion.h"
#include "lmptype.h"

#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
namespace DPoly {

  // What refinement reads of a vertex, measured by its owner where fix dpoly/refine acts.
  struct RefineVertex {
    tagint tag, cell;
    double diameter, preferred_length, preferred_angle;
    double segment_factor, bending_factor;    // d_kl and d_kb, 1 where they are not defined
    double type_bending;                      // eps_b of the vertex's angle type
    double turning_angle;                     // theta, from the previous to the next vertex
    double length;    // of the segment to the next vertex, or its l0 (measure preferred)
  };

  // The tissue as the rule sets see it: every vertex by ID, every cell's ring, adhesive bonds.
  class RefineTable {
   public:
    struct Ring {
      tagint cell;
      std::vector<tagint> vertices;    // counter-clockwise
    };
    RefineTable(std::vector<RefineVertex> vertices, std::vector<Ring> rings,
                const AdhesionCounts &counts, const std::vector<AdhesiveBond> &bonds);

    const std::vector<Ring> &rings() const { return ring_list; }
    const RefineVertex &vertex(tagint tag) const { return vertex_list[index.at(tag)]; }
    tagint previous(tagint tag) const { return before.at(tag); }    // in its ring
    bool void_facing(tagint tag) const { return counts.void_facing(tag); }
    // the cell of the vertex's closest bonded partner (at the minimum), 0 if it has none
    tagint closest_partner_cell(tagint tag) const;

   private:
    std::vector<RefineVertex> vertex_list;
    std::unordered_map<tagint, int> index;
    std::vector<Ring> ring_list;
    const AdhesionCounts &counts;
    std::unordered_map<tagint, tagint> before, partner_cell;
  };

  // Values of a new vertex; its l0 and d_kl are those of its segment to the next vertex.
  struct NewVertex {
    tagint tag;    // given by fix dpoly/refine
    double diameter, preferred_length, preferred_angle, segment_factor, bending_factor;
  };
  // Segment first -> second becomes first -> added[0] -> added[1] ... -> second; each new vertex
  // sits at the midpoint of the vertex before it and 'second'.
  struct SegmentSplit {
    tagint first, second, cell;
    double length;
    std::vector<NewVertex> added;
  };
  // New values of an existing vertex.
  struct VertexUpdate {
    tagint tag;
    double preferred_length, preferred_angle, segment_factor, bending_factor;
  };
  struct RefinePlan {
    std::vector<SegmentSplit> splits;    // in the order of their first vertex's ID
    std::vector<VertexUpdate> updates;
  };

  class RefineRules {
   public:
    struct Settings {
      double radii;    // segment length threshold, in vertex radii
      double cap;      // vertex-count cap, a multiple of the initial count
      bool void_only;
    };
    explicit RefineRules(const Settings &settings) : settings(settings) {}
    virtual ~RefineRules() = default;
    // initial: the vertex count of each cell at the first refinement
    virtual RefinePlan plan(const RefineTable &table,
                            const std::map<tagint, int> &initial) const = 0;
    virtual bool needs_adhesive_bonds() const { return false; }
    virtual bool needs_segment_factors() const { return false; }
    virtual bool needs_bending_factors() const { return false; }
    // whether the rule set splits before growth by default (at the radii of the minimum)
    virtual bool before_growth() const { return false; }

    // 'tension', 'published' or 'consistent'; nullptr for another name
    static std::unique_ptr<RefineRules> create(const std::string &name, const Settings &settings);

   protected:
    Settings settings;
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
