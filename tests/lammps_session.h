// A LAMMPS instance driven through the library interface, for the MESOPHYLL tests.
#ifndef MESOPHYLL_TESTS_LAMMPS_SESSION_H
#define MESOPHYLL_TESTS_LAMMPS_SESSION_H

#include "mpi.h"

#define LAMMPS_LIB_MPI 1    // lammps_open() with a communicator
#include "library.h"
#include "lammps.h"
#include "neighbor.h"
#include "update.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESOPHYLL_LSAN 1
#endif
#elif defined(__SANITIZE_ADDRESS__)
#define MESOPHYLL_LSAN 1
#endif
#ifdef MESOPHYLL_LSAN
#include <sanitizer/lsan_interface.h>
#endif

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

class LammpsSession {
 public:
  explicit LammpsSession(MPI_Comm comm = MPI_COMM_WORLD)
  {
    const char *args[] = {"mesophyll-test", "-log",    "none", "-echo",
                          "none",           "-screen", "none", "-nocite"};
    handle = lammps_open(8, const_cast<char **>(args), comm, nullptr);
    if (!handle) throw std::runtime_error("could not create a LAMMPS instance");
  }
  ~LammpsSession() { lammps_close(handle); }
  LammpsSession(const LammpsSession &) = delete;
  LammpsSession &operator=(const LammpsSession &) = delete;

  // Run one or more lines; throws with LAMMPS's message if one fails.
  void run(const std::string &lines)
  {
    lammps_commands_string(handle, lines.c_str());
    if (lammps_has_error(handle)) throw std::runtime_error("LAMMPS error: " + last_error());
  }

  // Run lines and return LAMMPS's error message, or "" if they all succeeded. Input that is
  // meant to fail goes here: LAMMPS's Input::execute_command() does not delete a command that
  // stops with an error, so the sanitized build leaves what this input allocates out of its
  // leak check (run() does not call try_run: all other input stays checked).
  // Neighbour list builds since the last run or minimization was initialised.
  int neighbour_builds() const
  {
    return static_cast<LAMMPS_NS::LAMMPS *>(handle)->neighbor->ncalls;
  }

  // The step the last run or minimization reached (also after it stopped with an error).
  long long current_step() const
  {
    return static_cast<LAMMPS_NS::LAMMPS *>(handle)->update->ntimestep;
  }

  std::string try_run(const std::string &lines)
  {
#ifdef MESOPHYLL_LSAN
    __lsan_disable();
#endif
    lammps_commands_string(handle, lines.c_str());
#ifdef MESOPHYLL_LSAN
    __lsan_enable();
#endif
    return lammps_has_error(handle) ? last_error() : "";
  }

  std::string last_error()
  {
    char buffer[2048];
    lammps_get_last_error_message(handle, buffer, sizeof(buffer));
    return buffer;
  }

  // A thermo keyword (pe, press, ...) or a fix, compute or variable reference (f_ID[n], ...).
  double thermo(const std::string &keyword)
  {
    if (keyword.find('_') != std::string::npos) return equal_variable(keyword);
    return lammps_get_thermo(handle, keyword.c_str());
  }

  double equal_variable(const std::string &expression)
  {
    run("variable mesophyll_probe equal " + expression);
    auto *value =
        static_cast<double *>(lammps_extract_variable(handle, "mesophyll_probe", nullptr));
    if (!value) {
      char buffer[2048] = "";
      lammps_get_last_error_message(handle, buffer, sizeof(buffer));
      throw std::runtime_error("cannot evaluate " + expression + ": " + buffer);
    }
    const double result = *value;
    free(value);
    return result;
  }

  // The value of a string-like variable (index, string, ...), "" if there is none.
  std::string string_variable(const std::string &name)
  {
    const char *value =
        static_cast<const char *>(lammps_extract_variable(handle, name.c_str(), nullptr));
    return value ? value : "";
  }

  // A compute's global array, row by row (rows x cols values), on every rank.
  std::vector<double> global_array(const char *compute, int nrows, int ncols)
  {
    auto **rows = static_cast<double **>(
        lammps_extract_compute(handle, compute, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY));
    if (!rows) throw std::runtime_error(std::string("no global array from compute ") + compute);
    std::vector<double> values;
    for (int r = 0; r < nrows; r++) values.insert(values.end(), rows[r], rows[r] + ncols);
    return values;
  }

  int natoms() { return (int) lammps_get_natoms(handle); }

  // The LAMMPS instance itself (a LAMMPS_NS::LAMMPS *), for tests of a style's own methods.
  void *lammps_handle() { return handle; }

  // Per-atom values ordered by atom ID, on every rank.
  std::vector<double> gather(const char *name, int count)
  {
    std::vector<double> data((size_t) natoms() * count);
    lammps_gather(handle, name, 1 /* double */, count, data.data());
    return data;
  }

  // Per-atom integer values (molecule, type, ...) ordered by atom ID, on every rank.
  std::vector<int> gather_int(const char *name, int count)
  {
    std::vector<int> data((size_t) natoms() * count);
    lammps_gather(handle, name, 0 /* int */, count, data.data());
    return data;
  }

  void scatter(const char *name, int count, std::vector<double> &data)
  {
    lammps_scatter(handle, name, 1 /* double */, count, data.data());
  }

 private:
  void *handle;
};

#endif
