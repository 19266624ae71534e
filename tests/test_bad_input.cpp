// Bad input, table-driven: each case is one small change to a valid two-cell tissue (the data
// file's per-vertex values, its topology, its geometry, a keyword) and the exact error or warning
// text it must produce. The minimizer's cases change a setting of the 16-cell tissue's
// minimization at constant pressure instead. One rank: some of the errors are per-atom errors.
//
// The table of doc/stability.md, section "Bad input", is written by this binary:
//   MESOPHYLL_STABILITY_DOC=doc/stability.md build/tests/test_bad_input
// (run from the source tree) replaces the table between its two marker lines with the cases and
// the messages they got in this run.
#include "test_helpers.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using ::testing::HasSubstr;

using namespace test;

namespace {

// ---------------------------------------------------------------------------------------
// The valid tissue: two unit squares 0.2 apart, joined by adhesive bonds 2-5 and 3-8.
// Atoms 1-4 are cell 1, 5-8 cell 2; bonds 1-8 are the ring segments (type 1), 9-10 adhesive.

Tissue two_cells()
{
  Tissue t;
  t.cells = {square(10.0, 10.0, 1.0), square(11.2, 10.0, 1.0)};
  t.adhesive = {{2, 5}, {3, 8}};
  return t;
}

// A regular n-gon of circumradius r around (x, y), counter-clockwise.
Polygon regular_polygon(double x, double y, double r, int n)
{
  Polygon p;
  for (int k = 0; k < n; k++)
    p.corners.push_back({x + r * cos(2.0 * PI * k / n), y + r * sin(2.0 * PI * k / n)});
  return p;
}

// The valid tissue in a box of 8 with cell 2 drawn out along x into a 'length' x 1 rectangle:
// its segments 5-6 and 7-8 come near half the box (4).
Tissue stretched_tissue(double length)
{
  Tissue t;
  t.cells = {square(1.0, 1.0, 1.0),
             {{{2.2, 1.0}, {2.2 + length, 1.0}, {2.2 + length, 2.0}, {2.2, 2.0}}}};
  t.adhesive = {{2, 5}, {3, 8}};
  t.box = 8.0;
  return t;
}

// stretched_tissue() turned on its side: x and y swapped, each ring's order reversed so that it
// stays counter-clockwise. The atom numbering comes out the same: segment 5-6 of cell 2 now runs
// along y, and the adhesive bonds join the same atoms.
Tissue stretched_tissue_along_y(double length)
{
  Tissue t = stretched_tissue(length);
  for (Polygon &cell : t.cells) {
    for (auto &corner : cell.corners) std::swap(corner.first, corner.second);
    std::reverse(cell.corners.begin() + 1, cell.corners.end());
    std::rotate(cell.corners.begin(), cell.corners.begin() + 1, cell.corners.end());
  }
  return t;
}

std::string read_text(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string write_text(const std::string &text, const std::string &name)
{
  const std::string path = scratch(name);
  std::ofstream(path) << text;
  return path;
}

// The lines of a data file section, from after its header to the blank line that ends it.
struct Section {
  size_t begin, end;    // character offsets of the section's body
};

Section find_section(const std::string &text, const std::string &header)
{
  const size_t at = text.find("\n" + header + "\n");
  if (at == std::string::npos) throw std::runtime_error("no section " + header);
  const size_t begin = at + header.size() + 3;    // "\n" header "\n" "\n"
  size_t end = text.find("\n\n", begin);
  end = (end == std::string::npos) ? text.size() : end + 1;
  return {begin, end};
}

// One line of a section whose first word is 'id', as words.
std::vector<std::string> words_of(const std::string &line)
{
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// A data file's text with a change to one section: 'edit' gets each line's words and returns
// the words to keep (empty: drop the line); 'extra' lines are appended to the section.
using LineEdit = std::function<std::vector<std::string>(const std::vector<std::string> &)>;

std::string edit_section(const std::string &text, const std::string &header, const LineEdit &edit,
                         const std::vector<std::string> &extra = {})
{
  const Section s = find_section(text, header);
  std::istringstream body(text.substr(s.begin, s.end - s.begin));
  std::string out;
  for (std::string line; std::getline(body, line);) {
    if (line.empty()) continue;
    const std::vector<std::string> words = edit(words_of(line));
    if (words.empty()) continue;
    for (size_t k = 0; k < words.size(); k++) out += (k ? " " : "") + words[k];
    out += "\n";
  }
  for (const auto &line : extra) out += line + "\n";
  return text.substr(0, s.begin) + out + text.substr(s.end);
}

// Change the count line "<n> <what>" of the header by 'delta'.
std::string change_count(const std::string &text, const std::string &what, int delta)
{
  std::smatch m;
  const std::regex count("\n([0-9]+) " + what + "\n");
  if (!std::regex_search(text, m, count)) throw std::runtime_error("no count of " + what);
  return m.prefix().str() + "\n" + std::to_string(std::stoi(m[1]) + delta) + " " + what + "\n" +
      m.suffix().str();
}

// column of the Vertices section: 1 sigma, 2 l0, 3 theta0, 4 a0
enum VertexColumn { SIGMA = 1, L0 = 2, THETA0 = 3, A0 = 4 };

LineEdit set_word(const std::string &id, int column, const std::string &value)
{
  return [=](const std::vector<std::string> &w) {
    std::vector<std::string> out = w;
    if (w[0] == id) out[column] = value;
    return out;
  };
}

LineEdit drop_line(const std::string &id)
{
  return [=](const std::vector<std::string> &w) {
    return w[0] == id ? std::vector<std::string>() : w;
  };
}

LineEdit keep_lines()
{
  return [](const std::vector<std::string> &w) {
    return w;
  };
}

// The valid tissue's data file with one change applied to its text.
std::string tissue_data(const std::function<std::string(const std::string &)> &change)
{
  const std::string text = read_text(write_tissue(two_cells(), "bad_input_base.data"));
  return write_text(change(text), "bad_input.data");
}

std::string valid_data()
{
  return tissue_data([](const std::string &t) {
    return t;
  });
}

std::string vertex_value(const std::string &id, int column, const std::string &value)
{
  return tissue_data([=](const std::string &t) {
    return edit_section(t, "Vertices", set_word(id, column, value));
  });
}

// the whole input of a case on the valid tissue's commands, with 'lines' after them
std::string on_tissue(const std::string &data, const std::string &lines,
                      const std::string &before = "")
{
  return before + contact_commands(data) + lines;
}

std::string replaced(std::string text, const std::string &from, const std::string &to)
{
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "' to replace");
  return text.replace(at, from.size(), to);
}

const char *RUN = "run 0 post no\n";
const char *MINIMIZE = "min_style fire\nminimize 0.0 1.0e-8 20 200\n";
const char *MINIMIZE_TISSUE = "minimize 0.0 1.0e-10 20000 200000\n";    // tissue16_commands()

// Segment 5-6 of the stretched tissue (3.8 long, l0 raised to 6) grows past half the box (4)
// during a minimization; the communication cutoff (4.5) holds every image of its vertices.
// stretched_tissue_along_y(3.8) gives the same along y.
std::string segment_outgrows_half_box(const Tissue &t = stretched_tissue(3.8),
                                      const std::string &name = "bad_input_stretched.data")
{
  return on_tissue(write_tissue(t, name),
                   "comm_modify cutoff 4.5\nset atom 5 d_l0 6.0\nmin_style fire\n"
                   "minimize 0.0 1.0e-8 5000 50000\n");
}

// ---------------------------------------------------------------------------------------
// The table

enum Outcome { ERROR, WARNING };

struct Case {
  const char *name;      // gtest name
  const char *area;      // data file, topology, geometry, keywords, stages, check, minimizer
  const char *change;    // what the case changes, for the table
  std::function<std::string()> input;
  Outcome outcome;
  std::string message;    // the exact text the error or warning must contain
};

std::vector<Case> cases()
{
  std::vector<Case> c;
  auto vertex_case = [&](const char *name, const char *change, const std::string &id, int column,
                         const std::string &value, const std::string &message) {
    c.push_back({name, "data file", change,
                 [=]() {
                   return on_tissue(vertex_value(id, column, value), RUN);
                 },
                 ERROR, message});
  };

  // --- data file: per-vertex values
  vertex_case("SigmaNegative", "sigma = -1 on vertex 4", "4", SIGMA, "-1",
              "vertex 4 has sigma = -1; it must be finite and > 0");
  vertex_case("SigmaZero", "sigma = 0 on vertex 6", "6", SIGMA, "0",
              "vertex 6 has sigma = 0; it must be finite and > 0");
  vertex_case("SigmaInf", "sigma = inf on vertex 2", "2", SIGMA, "inf",
              "Pair style dpoly/contact: vertex 2 has sigma = inf; its contact diameter (the "
              "pair cutoff) must be finite and below half the box (20)");
  vertex_case("SigmaHuge", "sigma = 25 on vertex 7 (box 40)", "7", SIGMA, "25",
              "Pair style dpoly/contact: vertex 7 has sigma = 25; its contact diameter (the "
              "pair cutoff) must be finite and below half the box (20)");
  vertex_case("SigmaNan", "sigma = nan on vertex 3", "3", SIGMA, "nan",
              "Pair style dpoly/contact: vertex 3 has sigma = nan; its contact diameter (the "
              "pair cutoff) must be finite and below half the box (20)");
  vertex_case("LengthZero", "l0 = 0 on vertex 2", "2", L0, "0",
              "vertex 2 has l0 = 0; it must be finite and > 0");
  vertex_case("LengthNegative", "l0 = -1 on vertex 7", "7", L0, "-1",
              "vertex 7 has l0 = -1; it must be finite and > 0");
  vertex_case("LengthInf", "l0 = inf on vertex 1", "1", L0, "inf",
              "vertex 1 has l0 = inf; it must be finite and > 0");
  vertex_case("LengthNan", "l0 = nan on vertex 5", "5", L0, "nan",
              "vertex 5 has l0 = nan; it must be finite and > 0");
  vertex_case("LengthTiny", "l0 = 1e-300 on vertex 3", "3", L0, "1e-300",
              "vertex 3 has l0 = 1e-300 for a segment of length 1: its length term (r/l0 - 1)^2 "
              "is not finite");
  vertex_case("ThetaNan", "theta0 = nan on vertex 1", "1", THETA0, "nan",
              "vertex 1 has theta0 = nan; a turning angle must be in (-pi, pi]");
  vertex_case("ThetaInf", "theta0 = inf on vertex 8", "8", THETA0, "inf",
              "vertex 8 has theta0 = inf; a turning angle must be in (-pi, pi]");
  vertex_case("ThetaAbovePi", "theta0 = 4 on vertex 2", "2", THETA0, "4",
              "vertex 2 has theta0 = 4; a turning angle must be in (-pi, pi]");
  vertex_case("ThetaBelowMinusPi", "theta0 = -3.5 on vertex 6", "6", THETA0, "-3.5",
              "vertex 6 has theta0 = -3.5; a turning angle must be in (-pi, pi]");
  vertex_case("ThetaMinusPi", "theta0 = -pi on vertex 3", "3", THETA0, "-3.141592653589793",
              "vertex 3 has theta0 = -3.141592653589793; a turning angle must be in "
              "(-pi, pi]");
  vertex_case("AreaNegative", "a0 = -0.5 on vertex 3", "3", A0, "-0.5",
              "vertex 3 has a0 = -0.5; it must be finite and > 0");
  vertex_case("AreaInf", "a0 = inf on vertex 5", "5", A0, "inf",
              "vertex 5 has a0 = inf; it must be finite and > 0");
  vertex_case("AreaNan", "a0 = nan on vertex 1", "1", A0, "nan",
              "vertex 1 has a0 = nan; it must be finite and > 0");
  vertex_case("AreaDiffersInCell", "a0 = 2 on vertex 2 only", "2", A0, "2",
              "cell 1 has different a0 on vertices");
  c.push_back({"AreaTiny", "data file", "a0 = 1e-300 on every vertex of cell 2",
               []() {
                 return on_tissue(valid_data(), "set mol 2 d_a0 1e-300\n" + std::string(RUN));
               },
               ERROR,
               "cell 2 has a0 = 1e-300 for an area of 1: its area term (a/a0 - 1)^2 is not "
               "finite"});
  c.push_back({"MoleculeZero", "data file", "vertex 1 in molecule 0",
               []() {
                 return on_tissue(tissue_data([](const std::string &t) {
                                    return edit_section(t, "Atoms # molecular",
                                                        [](const std::vector<std::string> &w) {
                                                          std::vector<std::string> out = w;
                                                          if (w[0] == "1") out[1] = "0";
                                                          return out;
                                                        });
                                  }),
                                  RUN);
               },
               ERROR, "vertex 1 has molecule ID 0"});

  // --- topology
  auto topology_case = [&](const char *name, const char *change,
                           const std::function<std::string(const std::string &)> &edit,
                           const std::string &message, const std::string &before = "") {
    c.push_back({name, "topology", change,
                 [=]() {
                   return on_tissue(tissue_data(edit), RUN, before);
                 },
                 ERROR, message});
  };
  auto without_bond = [](const std::string &id) {
    return [=](const std::string &t) {
      return change_count(edit_section(t, "Bonds", drop_line(id)), "bonds", -1);
    };
  };
  auto with_bond = [](const std::string &line) {
    return [=](const std::string &t) {
      return change_count(edit_section(t, "Bonds", keep_lines(), {line}), "bonds", 1);
    };
  };
  const char *MISSING_4_1 =
      "ring segment 4-1 of cell 1 has no dpoly/segment bond, so it has no length term";
  const char *TWICE_6_7 =
      "ring segment 6-7 of cell 2 has 2 dpoly/segment bonds, so its length term counts 2 times";
  topology_case("SegmentBondMissing", "ring bond 4-1 left out", without_bond("4"), MISSING_4_1);
  topology_case("SegmentBondMissingNewtonOff", "ring bond 4-1 left out, newton_bond off",
                without_bond("4"), MISSING_4_1, "newton on off\n");
  topology_case("SegmentBondTwice", "ring bond 6-7 given twice", with_bond("11 1 6 7"), TWICE_6_7);
  topology_case("SegmentBondTwiceReversed", "ring bond 6-7 given again as 7-6",
                with_bond("11 1 7 6"), TWICE_6_7);
  topology_case("SegmentBondTwiceNewtonOff", "ring bond 6-7 given twice, newton_bond off",
                with_bond("11 1 6 7"), TWICE_6_7, "newton on off\n");
  topology_case("SegmentBondAcrossRing", "segment bond 1-3 added across cell 1",
                with_bond("11 1 1 3"), "dpoly/segment bond 1-3 is not a segment of a ring");
  topology_case("SegmentBondBetweenCells", "segment-type bond 2-5 between the cells",
                with_bond("11 1 2 5"), "dpoly/segment bond 2-5 is not a segment of a ring");
  topology_case("AdhesiveBondInsideCell", "adhesive bond 1-3 inside cell 1", with_bond("11 2 1 3"),
                "bond 1-3 joins two vertices of cell 1");
  topology_case(
      "VertexWithoutAngle", "angle centred on vertex 6 left out",
      [](const std::string &t) {
        return change_count(edit_section(t, "Angles", drop_line("6")), "angles", -1);
      },
      "vertex 6 is the centre of 0 angles; a ring vertex needs exactly one angle");
  topology_case(
      "VertexWithTwoAngles", "a second angle centred on vertex 2",
      [](const std::string &t) {
        return change_count(edit_section(t, "Angles", keep_lines(), {"9 1 1 2 4"}), "angles", 1);
      },
      "vertex 2 is the centre of 2 angles");
  topology_case(
      "RingSplitBetweenCells", "vertex 4 in molecule 2",
      [](const std::string &t) {
        return edit_section(t, "Atoms # molecular", [](const std::vector<std::string> &w) {
          std::vector<std::string> out = w;
          if (w[0] == "4") out[1] = "2";
          return out;
        });
      },
      "vertex 4 of cell 2 points to vertex 1 as its next, but that is not a vertex of the same "
      "ring pointing back to it");
  topology_case(
      "ClockwiseRing", "cell 2's angles reversed (clockwise ring)",
      [](const std::string &t) {
        return edit_section(t, "Angles", [](const std::vector<std::string> &w) {
          std::vector<std::string> out = w;
          if (std::stoi(w[0]) >= 5) std::swap(out[2], out[4]);
          return out;
        });
      },
      "cell 2 has area -1 <= 0; a ring must run counter-clockwise");
  c.push_back({"AdhereCellsTwice", "topology", "adhere_cells on a tissue that is already bonded",
               []() {
                 return on_tissue(valid_data(), "adhere_cells all 2\n");
               },
               ERROR,
               "adhere_cells: all 2 overlapping pairs of vertices of different cells in group "
               "all are already bonded (adhere_cells ran before?)"});

  // --- geometry
  c.push_back({"RingLargerThanHalfTheBox", "geometry", "box shrunk to 1.5 x 1.5 around a cell",
               []() {
                 Tissue t;
                 t.cells = {square(0.1, 0.1, 1.0)};
                 t.box = 1.5;
                 t.sigma = 0.2;
                 return on_tissue(write_tissue(t, "bad_input_small_box.data"), RUN);
               },
               ERROR,
               "at step 0, ring segment 4-1 of cell 1 is 1 long (1 in y), not shorter than half "
               "the box length in y (0.75)"});
  c.push_back({"CellWiderThanTheBox", "geometry", "one 32-gon 2 wide in a box 1.8 wide",
               []() {
                 Tissue t;
                 t.cells = {regular_polygon(0.9, 0.9, 1.0, 32)};
                 t.box = 1.8;
                 t.sigma = 0.1;
                 return on_tissue(write_tissue(t, "bad_input_wide_cell.data"), RUN);
               },
               ERROR,
               "cell 1 spans 2 in x, not less than the box length 1.8 in x: a cell must fit "
               "inside the periodic box"});
  // cell 2 across the periodic boundary in x, its vertices 5 and 8 0.9 away from it, further
  // than the communication cutoff (0.8, the pair's: sigma 0.5 and skin 0.3)
  c.push_back({"SegmentBeyondTheCutoff", "geometry",
               "the tissue moved across the periodic boundary, comm_modify cutoff 0.5 (0.8 used)",
               []() {
                 return on_tissue(valid_data(),
                                  "comm_modify cutoff 0.5\n"
                                  "displace_atoms all move 27.9 0 0\n" +
                                      std::string(RUN));
               },
               ERROR,
               "at step 0, ring segment 7-8 of cell 2 is 1 long, longer than the communication "
               "cutoff 0.8: the image of vertex 8 that continues the ring is no ghost atom here"});
  c.push_back({"SegmentBeyondTheCutoffDuringRun", "geometry",
               "the tissue moving across the periodic boundary (fix move), comm_modify cutoff "
               "0.5 (0.8 used)",
               []() {
                 return on_tissue(valid_data(),
                                  "comm_modify cutoff 0.5\n"
                                  "displace_atoms all move 27.5 0 0\n"
                                  "fix move all move linear 1 0 0\n"
                                  "run 1000 post no\n");
               },
               ERROR,
               "ring segment 7-8 of cell 2 is 1 long, longer than the communication cutoff 0.8"});
  c.push_back({"SegmentPastHalfTheBoxDuringMinimization", "geometry",
               "segment 5-6 (3.8 long, l0 = 6) grows past half the box (4) in a minimization",
               []() {
                 return segment_outgrows_half_box();
               },
               ERROR,
               "in x), not shorter than half the box length in x (4): the nearest image of vertex "
               "6 no longer continues the ring"});
  // tools/make_cells.py --cells 9 --vertices 3 relaxed as examples/polygons/in.relax_cells does:
  // segments of 1.5 under its communication cutoff of 1.0 (this gave phi < 0 and P < 0)
  c.push_back({"TrianglesBeyondTheCutoff", "geometry",
               "nine triangles of make_cells.py relaxed as in.relax_cells (comm_modify cutoff 1)",
               []() {
                 return "units lj\ndimension 2\natom_style molecular\nboundary p p p\n"
                        "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n"
                        "bond_style dpoly/segment\nangle_style dpoly/bending\n"
                        "read_data " +
                     data_file("triangles.data") +
                     " fix Vertices NULL Vertices\n"
                     "bond_coeff * 1.0\nangle_coeff * 0.4\npair_style soft 0.12\n"
                     "pair_coeff * * 0.002\ncomm_modify cutoff 1.0\nfix cells all dpoly/cells\n"
                     "fix relax all box/relax iso 1.0e-3 vmax 1.0e-3\nmin_style cg\n"
                     "minimize 0.0 1.0e-10 20000 200000\n";
               },
               ERROR, "long, longer than the communication cutoff 1: the image of vertex"});
  c.push_back(
      {"CheckPackingAboveOne", "geometry", "fix dpoly/check on two 32-gons that overlap, phi 1.07",
       []() {
         Tissue t;
         t.cells = {regular_polygon(0.7, 0.7, 0.6, 32), regular_polygon(0.75, 0.72, 0.6, 32)};
         t.box = 1.45;
         t.sigma = 0.1;
         return on_tissue(write_tissue(t, "bad_input_overlap.data"),
                          "fix check all dpoly/check action error\nminimize 0.0 0.0 0 0\n");
       },
       ERROR, "the packing fraction phi is outside (0, 1]: 1.06"});
  c.push_back({"CheckPatchPackingAboveOne", "geometry",
               "fix dpoly/check with compute dpoly/tissue on a 32-gon whose vertex disks "
               "overlap its own images, phi_patch 1.33",
               []() {
                 Tissue t;
                 t.cells = {regular_polygon(0.6, 0.6, 0.6, 32)};
                 t.box = 1.25;
                 return on_tissue(write_tissue(t, "bad_input_patch.data"),
                                  "compute tissue all dpoly/tissue\n"
                                  "fix check all dpoly/check action error\nminimize 0.0 0.0 0 0\n");
               },
               ERROR, "the packing fraction phi_patch of compute tissue is outside (0, 1]: 1.3"});
  c.push_back({"CheckInvertedCell", "geometry",
               "fix dpoly/check after a minimization that pushes a triangle's tip through its "
               "pinned base (fix addforce, fix setforce)",
               []() {
                 Tissue t;
                 t.cells = {{{{10.0, 10.0}, {11.0, 10.0}, {10.5, 10.866}}}};
                 return on_tissue(write_tissue(t, "bad_input_triangle.data"),
                                  "group tip id 3\ngroup base id 1 2\n"
                                  "fix push tip addforce 0.0 -8.0 0.0\n"
                                  "fix pin base setforce 0.0 0.0 0.0\n"
                                  "fix check all dpoly/check action error\n"
                                  "min_style fire\nminimize 0.0 1.0e-8 5000 50000\n");
               },
               ERROR,
               "1 cells have area <= 0 (first: cell 1, area -1.31299); the packing fraction phi "
               "is outside (0, 1]: -0.000820617"});
  c.push_back({"VerticesCoincide", "geometry", "vertex 2 moved onto vertex 1",
               []() {
                 return on_tissue(valid_data(), "set atom 2 x 10 y 10\n" + std::string(RUN));
               },
               ERROR, "vertices 1 and 2 coincide"});

  // --- the stages and the hub: groups
  auto group_case = [&](const char *name, const char *change, const std::string &lines,
                        const std::string &message) {
    c.push_back({name, "groups", change,
                 [=]() {
                   return on_tissue(valid_data(),
                                    "group one molecule 1\ngroup none empty\n" + lines + RUN);
                 },
                 ERROR, message});
  };
  group_case("GrowOnSubgroup", "fix mesophyll/grow on the group of cell 1",
             "fix grow one mesophyll/grow box fixed\n",
             "Fix mesophyll/grow grow is defined on group one, but fix dpoly/cells cells keeps "
             "the cells of group all: a stage acts on all the hub's cells; define it on group "
             "all");
  group_case("GrowOnEmptyGroup", "fix mesophyll/grow on an empty group",
             "fix grow none mesophyll/grow box fixed\n",
             "Fix mesophyll/grow grow is defined on group none, but fix dpoly/cells cells");
  group_case("BreakOnSubgroup", "fix mesophyll/break on the group of cell 1",
             "fix break one mesophyll/break 5\n",
             "Fix mesophyll/break break is defined on group one, but fix dpoly/cells cells");
  group_case("CheckOnSubgroup", "fix dpoly/check on the group of cell 1",
             "fix check one dpoly/check\n",
             "Fix dpoly/check check is defined on group one, but fix dpoly/cells cells");
  group_case("RefineOnSubgroup", "fix dpoly/refine on the group of cell 1",
             "fix refine one dpoly/refine\n",
             "Fix dpoly/refine refine is defined on group one, but fix dpoly/cells cells");
  auto hub_group_case = [&](const char *name, const char *change, const std::string &group,
                            const std::string &break_group, const std::string &message) {
    c.push_back(
        {name, "groups", change,
         [=]() {
           return replaced(
               on_tissue(valid_data(),
                         "fix break " + break_group + " mesophyll/break 5\n" + std::string(RUN)),
               "fix cells all dpoly/cells",
               "group one molecule 1\ngroup none empty\nfix cells " + group + " dpoly/cells");
         },
         ERROR, message});
  };
  hub_group_case("HubOnSubgroup", "fix dpoly/cells and fix mesophyll/break on the group of cell 1",
                 "one", "one",
                 "Fix dpoly/cells cells: vertex 8 of molecule 2 is the centre of a ring angle but "
                 "not in group one; the hub must hold every cell");
  hub_group_case("HubOnSubgroupBreakOnAll",
                 "fix dpoly/cells on the group of cell 1, fix mesophyll/break on all", "one", "all",
                 "Fix mesophyll/break break is defined on group all, but fix dpoly/cells cells "
                 "keeps the cells of group one");
  hub_group_case("HubOnEmptyGroup", "fix dpoly/cells and fix mesophyll/break on an empty group",
                 "none", "none",
                 "vertex 8 of molecule 2 is the centre of a ring angle but not in group none");

  // --- keywords
  auto keyword_case = [&](const char *name, const char *change, const std::string &lines,
                          const std::string &message, Outcome outcome = ERROR) {
    c.push_back({name, "keywords", change,
                 [=]() {
                   return on_tissue(valid_data(), lines + RUN);
                 },
                 outcome, message});
  };
  keyword_case("ThetaMinAbovePi", "fix mesophyll/grow theta0_min 4",
               "fix grow all mesophyll/grow box fixed theta0_min 4\n",
               "Fix mesophyll/grow theta0_min must be a turning angle in (-pi, pi] radians");
  keyword_case("ThetaMinBelowMinusPi", "fix mesophyll/grow theta0_min -3.2",
               "fix grow all mesophyll/grow box fixed theta0_min -3.2\n", "got -3.2");
  keyword_case("ThetaMinPositive", "fix mesophyll/grow theta0_min 0.5",
               "fix grow all mesophyll/grow box fixed theta0_min 0.5\n",
               "Fix mesophyll/grow theta0_min = 0.5 > 0: every void-facing vertex whose theta0 "
               "is below it is raised to it",
               WARNING);
  keyword_case("GrowLengthShare", "fix mesophyll/grow c_L 2",
               "fix grow all mesophyll/grow box fixed c_L 2\n",
               "Fix mesophyll/grow c_L must be in [0, 1], got 2");
  keyword_case("GrowNegativeStep", "fix mesophyll/grow delta_a -1",
               "fix grow all mesophyll/grow box fixed delta_a -1\n",
               "Fix mesophyll/grow delta_a must be >= 0, got -1");
  keyword_case("GrowRules", "fix mesophyll/grow rules authors",
               "fix grow all mesophyll/grow box fixed rules authors\n",
               "rules must be 'code', 'paper' or 'published', got 'authors'");
  keyword_case("FireNphSteer", "min_modify steer speed (fire/nph)",
               "min_style fire/nph\nmin_modify steer speed\n",
               "min_modify steer must be force or mass, got speed");
  keyword_case("FireNphRms", "min_modify rms maybe (fire/nph)",
               "min_style fire/nph\nmin_modify rms maybe\n",
               "Expected boolean parameter instead of 'maybe'");
  keyword_case("GrowBox", "fix mesophyll/grow box free", "fix grow all mesophyll/grow box free\n",
               "box must be 'relax' or 'fixed', got 'free'");
  keyword_case("GrowWithoutBoxRelax", "fix mesophyll/grow without fix box/relax",
               "fix grow all mesophyll/grow\n", "Fix mesophyll/grow grow needs fix box/relax");
  keyword_case("CheckTolerance", "fix dpoly/check tolerance 0",
               "fix check all dpoly/check tolerance 0\n",
               "Fix dpoly/check tolerance must be > 0, got 0");
  keyword_case("CheckAction", "fix dpoly/check action stop",
               "fix check all dpoly/check action stop\n",
               "action must be 'warn' or 'error', got 'stop'");
  keyword_case("BreakThreshold", "fix mesophyll/break threshold 0.5",
               "fix break all mesophyll/break 5 threshold 0.5\n", "must be > 1, got 0.5");
  keyword_case("RefineCap", "fix dpoly/refine cap 0.5", "fix refine all dpoly/refine cap 0.5\n",
               "Fix dpoly/refine cap must be >= 1, got 0.5");

  // --- the minimum's check
  c.push_back({"CheckNonFiniteEnergy", "check",
               "fix dpoly/check after a minimization whose energy is inf (fix addforce energy)",
               []() {
                 return on_tissue(valid_data(),
                                  "variable big atom 1.0e308*10\nvariable zero atom 0.0\n"
                                  "fix push all addforce v_zero 0.0 0.0 energy v_big\n"
                                  "fix_modify push energy yes\n"
                                  "fix check all dpoly/check action error\n" +
                                      std::string(MINIMIZE));
               },
               ERROR, "the energy pe = inf or the force norm"});
  c.push_back({"CheckNonFinitePressure", "check",
               "fix dpoly/check without 'pressure' after a minimization whose P is nan (velocities "
               "inf - inf)",
               []() {
                 return on_tissue(valid_data(),
                                  "variable nan equal 1.0e308*10-1.0e308*10\n"
                                  "velocity all set v_nan 0.0 0.0\n"
                                  "fix check all dpoly/check action error\n"
                                  "min_style cg\nminimize 0.0 1.0e-8 20 200\n");    // fire zeroes v
               },
               ERROR, "nan is not finite"});

  // --- the minimizer: min_style fire/nph stops a minimization that diverges or stalls, and
  // says what diverged, where, and which setting to change. Runs that go wrong on the 16-cell
  // tissue (examples/tissue) under fix box/relax, as in examples/mesophyll/in.mesophyll_short
  auto minimizer_case = [&](const char *name, const char *change,
                            const std::function<std::string()> &input, const std::string &message) {
    c.push_back({name, "minimizer", change, input, ERROR, message});
  };
  minimizer_case(
      "FireNphTimestepHuge", "timestep 100 (the stability limit is about 0.1)",
      []() {
        return tissue16_commands() + "timestep 100\n" + MINIMIZE_TISSUE;
      },
      "were cut short by min_modify dmax (0.1): the timestep 100 is beyond the stability limit "
      "of the stiffest mode (about 2/omega_max); lower it");
  minimizer_case(
      "FireNphRmsNormMax", "min_modify rms yes with norm max",
      []() {
        return tissue16_commands() + "min_modify norm max rms yes\n" + MINIMIZE_TISSUE;
      },
      "min_style fire/nph: min_modify rms yes is a root mean square, which needs min_modify "
      "norm two, not norm max");
  minimizer_case(
      "FireNphBoxMassTiny", "min_modify boxmass 1e-12",
      []() {
        return tissue16_commands() + "min_modify boxmass 1.0e-12\n" + MINIMIZE_TISSUE;
      },
      "the box overshoots, its mass is too small for its force; raise min_modify boxmass "
      "(1e-12), or lower fix box/relax's vmax or its target pressure");
  minimizer_case(
      "FireNphPressureHuge", "fix box/relax iso 1e3 (the cells hold about 1)",
      []() {
        return tissue16_commands("1.0e3") + MINIMIZE_TISSUE;
      },
      "at the start of this minimization: the box collapses (fire/nph stops a box length that "
      "shrinks below 1/4 or grows beyond 4 times it). Fix box/relax's target pressure may be a "
      "compression the system cannot hold");
  minimizer_case(
      "FireNphTension", "fix box/relax iso -50 (a tension the tissue cannot hold)",
      []() {
        return tissue16_commands("-50") + MINIMIZE_TISSUE;
      },
      "the box runs away (fire/nph stops a box length that shrinks below 1/4 or grows beyond 4 "
      "times it). Fix box/relax's target pressure may be a tension the system cannot hold");
  minimizer_case(
      "FireNphGrowthHuge", "fix mesophyll/grow delta_a 5, the minimization after it",
      []() {
        return tissue16_commands() + "fix grow all mesophyll/grow delta_a 5\n" + MINIMIZE_TISSUE +
            MINIMIZE_TISSUE;
      },
      "a force changes faster than even that step resolves (a very stiff or non-smooth term, as "
      "after a change of the system too large for one minimization, e.g. a large growth step). A "
      "collapsed ring or face or a tangled state stays so at any timestep: run fix dpoly/check (or "
      "look at the largest force's cell) first; then lower the timestep (0.01)");
  minimizer_case(
      "FireNphEnergyNotFinite", "an energy of inf (fix addforce energy), at fixed box",
      []() {
        return on_tissue(valid_data(),
                         "variable big atom 1.0e308*10\nvariable zero atom 0.0\n"
                         "fix push all addforce v_zero 0.0 0.0 energy v_big\n"
                         "fix_modify push energy yes\nmin_style fire/nph\n"
                         "minimize 0.0 1.0e-8 20 200\n");
      },
      "min_style fire/nph: the energy is inf at step 1 (iteration 1 of this minimization): "
      "the minimization diverged; lower the timestep");
  minimizer_case(
      "FireNphForceNotFinite", "a force of inf on vertex 3 (fix addforce), at fixed box",
      []() {
        return on_tissue(valid_data(),
                         "variable big equal 1.0e308*10\nvariable zero atom 0.0\ngroup three id 3\n"
                         "fix push three addforce v_big 0.0 0.0 energy v_zero\n"
                         "min_style fire/nph\n"
                         "minimize 0.0 1.0e-8 20 200\n");
      },
      "min_style fire/nph: the force norm is inf at step 0 (iteration 0 of this minimization); "
      "inf on atom 3 (molecule 1): the minimization diverged");
  return c;
}

// LAMMPS's message without its "ERROR: ", the source location and the input line it appends
std::string without_location(const std::string &message)
{
  std::string text = message.substr(0, message.find("\nLast input line:"));
  if (text.rfind("ERROR: ", 0) == 0) text = text.substr(7);
  return std::regex_replace(text, std::regex(R"( \([^()]*\.(cpp|h):[0-9]+\)\s*$)"), "");
}

struct Result {
  std::string error, warnings;
};

Result run_case(const Case &c)
{
  const std::string log = scratch("bad_input.log");
  std::remove(log.c_str());
  Result r;
  {
    LammpsSession s;
    r.error = without_location(s.try_run("log " + log + "\n" + c.input()));
  }
  std::istringstream in(read_text(log));
  for (std::string line; std::getline(in, line);)
    if (line.rfind("WARNING: ", 0) == 0) r.warnings += without_location(line.substr(9)) + "\n";
  return r;
}

// the table's rows, filled as the cases run
std::vector<std::vector<std::string>> &table()
{
  static std::vector<std::vector<std::string>> rows;
  return rows;
}

std::string cell_text(std::string s)
{
  for (size_t at = 0; (at = s.find('|', at)) != std::string::npos; at += 2) s.replace(at, 1, "\\|");
  for (char &ch : s)
    if (ch == '\n') ch = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

class BadInputCase : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override
  {
    if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  }
};

TEST_P(BadInputCase, GetsItsMessage)
{
  const Case &c = GetParam();
  const Result r = run_case(c);
  std::string outcome;
  if (c.outcome == ERROR) {
    EXPECT_THAT(r.error, HasSubstr(c.message));
    outcome = "error: " + r.error;
  } else {
    EXPECT_EQ(r.error, "");
    EXPECT_THAT(r.warnings, HasSubstr(c.message));
    outcome = "warning: " + r.warnings;
  }
  table().push_back({c.name, c.area, c.change, outcome});
}

INSTANTIATE_TEST_SUITE_P(Table, BadInputCase, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case> &info) {
                           return std::string(info.param.name);
                         });

// The valid tissue itself runs, minimizes and passes the check: the cases are changes of it.
TEST(BadInputBase, ValidTissueRunsClean)
{
  if (world_size() > 1) GTEST_SKIP() << "error tests run on one rank";
  const Result r = run_case(
      {"Valid", "", "",
       []() {
         return on_tissue(valid_data(), "fix check all dpoly/check\n" + std::string(MINIMIZE));
       },
       ERROR, ""});
  EXPECT_EQ(r.error, "");
  EXPECT_THAT(r.warnings, ::testing::Not(HasSubstr("FAILED")));
}

// Runs 'input' (a minimization with min_style fire) with the default skin and with a skin so
// large (3) that no list is rebuilt before its error: both must stop at the same step with the
// same words, the large skin without a rebuild (what ran until the error is the hub's reuse of
// recorded images, or its search where it may not reuse them). Returns the error.
std::string same_error_without_reneighbouring(const std::string &input)
{
  LammpsSession default_skin, large_skin;
  const std::string error = without_location(default_skin.try_run(input));
  EXPECT_EQ(error,
            without_location(large_skin.try_run(
                replaced(input, "min_style fire\n", "neighbor 3.0 bin\nmin_style fire\n"))));
  EXPECT_EQ(large_skin.current_step(), default_skin.current_step());
  EXPECT_EQ(large_skin.neighbour_builds(), 0);
  EXPECT_GT(default_skin.neighbour_builds(), 0);
  return error;
}

// Between two reneighbourings the hub reuses the ring neighbours' images of its last ring check
// while they are the nearest ones: the segment that passes half the box is seen all the same.
TEST(BadInputDuringRun, SegmentPastHalfTheBoxIsSeenWithoutReneighbouring)
{
  const std::string error = same_error_without_reneighbouring(segment_outgrows_half_box());
  EXPECT_THAT(error, HasSubstr("not shorter than half the box length in x (4)"));
}

// The same along y: the reuse bounds the distance to a recorded image in y as well as in x.
TEST(BadInputDuringRun, SegmentPastHalfTheBoxInYIsSeenWithoutReneighbouring)
{
  const std::string error = same_error_without_reneighbouring(
      segment_outgrows_half_box(stretched_tissue_along_y(3.8), "bad_input_stretched_y.data"));
  EXPECT_THAT(error, HasSubstr("ring segment 5-6 of cell 2 is "));
  EXPECT_THAT(error, HasSubstr("not shorter than half the box length in y (4)"));
}

// In a triclinic box the nearest image can change before a segment reaches half the box length
// in x or y, so there the hub searches the images at every force evaluation. A segment along
// the diagonal of a box of 8 tilted by 3.9 in xy: the image across the tilted face becomes the
// nearer one when the segment is about 4.7 long (3.3 in x and y, under half the box); with a
// skin so large that no list is rebuilt, the minimization must stop at the same step with the
// same words as with the default skin.
TEST(BadInputDuringRun, NearestImageChangeInATiltedBoxIsSeenWithoutReneighbouring)
{
  const double u = sqrt(0.5), length = 4.4;
  Tissue t;
  t.cells = {{{{3.0, 1.0},
               {3.0 + length * u, 1.0 + length * u},
               {3.0 + (length - 1.0) * u, 1.0 + (length + 1.0) * u},
               {3.0 - u, 1.0 + u}}}};
  t.box = 8.0;
  const std::string data = write_text(replaced(read_text(write_tissue(t, "bad_input_tilt.data")),
                                               "-0.5 0.5 zlo zhi\n",
                                               "-0.5 0.5 zlo zhi\n3.9 0 0 xy xz yz\n"),
                                      "bad_input_tilted.data");
  const std::string error = same_error_without_reneighbouring(
      on_tissue(data, "comm_modify cutoff 6.5\nset atom 1 d_l0 7.0\nmin_style fire\n"
                      "minimize 0.0 1.0e-8 5000 50000\n"));
  EXPECT_THAT(error, HasSubstr("the ring is not whole between vertex 1 and its next vertex"));
}

// The check during a run is collective: on all ranks (on 2, cell 2 lies across the ranks'
// boundary, its vertices 5 and 6 on different ranks) the minimization stops with the message it
// stops with on one rank, at the same step.
TEST(BadInputDuringRun, SegmentPastHalfTheBoxStopsTheMinimization)
{
  const std::string input = segment_outgrows_half_box();
  LammpsSession parallel, serial(self_comm());
  const std::string error = without_location(parallel.try_run(input));
  EXPECT_THAT(error, HasSubstr("Fix dpoly/cells: at step "));
  EXPECT_THAT(error, HasSubstr("ring segment 5-6 of cell 2 is "));
  EXPECT_THAT(error, HasSubstr("not shorter than half the box length in x (4)"));
  EXPECT_EQ(error, without_location(serial.try_run(input)));
}

const char *BEGIN_MARK = "<!-- bad-input table: begin (written by tests/test_bad_input.cpp) -->";
const char *END_MARK = "<!-- bad-input table: end -->";

// After all tests: write the table into doc/stability.md when asked to
// (MESOPHYLL_STABILITY_DOC), and only from a run of every case.
class TableWriter : public ::testing::Environment {
 public:
  void TearDown() override
  {
    const char *doc = getenv("MESOPHYLL_STABILITY_DOC");
    if (!doc || world_size() > 1) return;
    if (table().size() != cases().size()) {
      fprintf(stderr, "bad-input table not written: %zu of %zu cases ran\n", table().size(),
              cases().size());
      return;
    }
    std::string rows = std::string(BEGIN_MARK) + "\n\n| case | area | change | outcome |\n" +
        "|---|---|---|---|\n";
    for (const auto &row : table())
      rows += "| " + cell_text(row[0]) + " | " + cell_text(row[1]) + " | " + cell_text(row[2]) +
          " | " + cell_text(row[3]) + " |\n";
    rows += "\n" + std::string(END_MARK);
    std::string text = read_text(doc);
    const size_t begin = text.find(BEGIN_MARK), end = text.find(END_MARK);
    if (begin == std::string::npos || end == std::string::npos) {
      fprintf(stderr, "%s has no bad-input table markers\n", doc);
      return;
    }
    text.replace(begin, end + std::string(END_MARK).size() - begin, rows);
    std::ofstream(doc) << text;
    fprintf(stderr, "bad-input table of %zu cases written to %s\n", table().size(), doc);
  }
};

::testing::Environment *const table_writer = ::testing::AddGlobalTestEnvironment(new TableWriter);

}    // namespace
