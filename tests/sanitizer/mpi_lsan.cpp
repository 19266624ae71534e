// Linked into lmp and the tests of the sanitized build (cmake -DMESOPHYLL_SANITIZE=ON) only.
// Open MPI 4.1 keeps what MPI_Init allocates until exit and unloads its plugins in MPI_Finalize,
// before LeakSanitizer looks, so its blocks would be reported with frames no suppression can
// name. Through MPI's profiling interface, what MPI_Init and MPI_Finalize allocate on this thread
// is left out of the leak check, and dlclose() keeps the plugins loaded so that what Open MPI's
// own threads allocate still names its library (tests/sanitizer/lsan.supp). Everything else,
// LAMMPS and MESOPHYLL included, stays checked.
#include <mpi.h>
#include <sanitizer/lsan_interface.h>

extern "C" {
int dlclose(void *) { return 0; }

int MPI_Init(int *argc, char ***argv)
{
  __lsan_disable();
  const int result = PMPI_Init(argc, argv);
  __lsan_enable();
  return result;
}

int MPI_Init_thread(int *argc, char ***argv, int required, int *provided)
{
  __lsan_disable();
  const int result = PMPI_Init_thread(argc, argv, required, provided);
  __lsan_enable();
  return result;
}

int MPI_Finalize()
{
  __lsan_disable();
  const int result = PMPI_Finalize();
  __lsan_enable();
  return result;
}
}
