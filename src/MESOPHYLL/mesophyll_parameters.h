/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(mesophyll_parameters,MesophyllParameters);
// clang-format on
#else

#ifndef LMP_MESOPHYLL_PARAMETERS_H
#define LMP_MESOPHYLL_PARAMETERS_H

#include "command.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

// mesophyll_parameters file set-name: reads one named parameter set from a LAMMPS potential file
// (metadata line with UNITS, checked) and defines each of its parameters as an index-style
// variable, so the input refers to ${eps_b}, ${delta_a}, ... and a -var on the command line or
// an earlier variable command still wins.
class MesophyllParameters : public Command {
 public:
  MesophyllParameters(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;

 private:
  std::vector<std::pair<std::string, std::string>> read_set(const std::string &file,
                                                            const std::string &set);
};

}    // namespace LAMMPS_NS

#endif
#endif
