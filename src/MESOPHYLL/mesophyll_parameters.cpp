/* ----------------------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

#include "mesophyll_parameters.h"

#include "comm.h"
#include "error.h"
#include "input.h"
#include "potential_file_reader.h"
#include "tokenizer.h"
#include "variable.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {

// every parameter a set may name, and whether its value is a number
struct Known {
  const char *name;
  bool numeric;
};
const Known KNOWN[] = {{"eps_a", true},      {"eps_l", true},  {"eps_b", true},    {"eps_c", true},
                       {"delta_a", true},    {"lambda", true}, {"c_L", true},      {"c_B", true},
                       {"theta0_min", true}, {"rules", false}, {"calA_max", true}, {"z", false},
                       {"beta", true},       {"P0", true}};

const Known *known(const std::string &name)
{
  for (const Known &k : KNOWN)
    if (name == k.name) return &k;
  return nullptr;
}

}    // namespace

void MesophyllParameters::command(int narg, char **arg)
{
  if (narg != 2)
    error->all(FLERR, "mesophyll_parameters needs a file and a set name, got {} arguments", narg);
  const std::string file = arg[0], set = arg[1];

  // rank 0 reads the file; every rank defines the same variables
  std::string text;
  if (comm->me == 0)
    for (const auto &kv : read_set(file, set)) text += kv.first + " " + kv.second + "\n";
  int size = (int) text.size();
  MPI_Bcast(&size, 1, MPI_INT, 0, world);
  text.resize(size);
  MPI_Bcast(&text[0], size, MPI_CHAR, 0, world);
  if (size == 0) error->all(FLERR, "mesophyll_parameters: no set '{}' in {}", set, file);

  std::string taken, kept;
  for (const auto &line : utils::split_lines(text)) {
    const std::vector<std::string> words = utils::split_words(line);
    if (words.size() != 2) continue;
    if (input->variable->find(words[0].c_str()) >= 0) {
      kept += " " + words[0];
      continue;
    }
    input->variable->set(words[0] + " index " + words[1]);
    taken += " " + words[0] + "=" + words[1];
  }
  if (comm->me == 0) {
    utils::logmesg(lmp, "mesophyll_parameters: set '{}' of {}:{}\n", set, file, taken);
    if (!kept.empty()) utils::logmesg(lmp, "  already defined, kept as they were:{}\n", kept);
  }
}

/* ----------------------------------------------------------------------
   the (name, value) pairs of one set: every line whose first word is the set name adds its
   "name value" pairs; a later line may not repeat a name
------------------------------------------------------------------------- */

std::vector<std::pair<std::string, std::string>>
MesophyllParameters::read_set(const std::string &file, const std::string &set)
{
  std::vector<std::pair<std::string, std::string>> values;
  PotentialFileReader reader(lmp, file, "mesophyll parameters");
  while (const char *line = reader.next_line()) {
    ValueTokenizer words(line);
    if (words.next_string() != set) continue;
    while (words.has_next()) {
      const std::string name = words.next_string();
      const Known *k = known(name);
      if (!k)
        error->one(FLERR, "mesophyll_parameters: unknown parameter '{}' in set '{}' of {}", name,
                   set, file);
      if (!words.has_next())
        error->one(FLERR, "mesophyll_parameters: parameter '{}' in set '{}' of {} has no value",
                   name, set, file);
      const std::string value = words.next_string();
      if (k->numeric && !utils::is_double(value))
        error->one(FLERR, "mesophyll_parameters: {} = '{}' in set '{}' of {} is not a number", name,
                   value, set, file);
      for (const auto &kv : values)
        if (kv.first == name)
          error->one(FLERR, "mesophyll_parameters: {} given twice in set '{}' of {}", name, set,
                     file);
      values.emplace_back(name, value);
    }
  }
  return values;
}
