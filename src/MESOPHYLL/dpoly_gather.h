/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Every rank's records, concatenated in rank order, on every rank: the package's decisions that
// must not depend on the number of ranks (ring checks, contact counts, bond breaking) are taken
// from such whole-system tables.

#ifndef LMP_DPOLY_GATHER_H
#define LMP_DPOLY_GATHER_H

#include <mpi.h>

#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
namespace DPoly {

  template <typename Record>
  std::vector<Record> gather_on_all_ranks(std::vector<Record> mine, MPI_Comm world)
  {
    static_assert(std::is_trivially_copyable<Record>::value, "records travel as bytes");
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    int nbytes = (int) (mine.size() * sizeof(Record));
    std::vector<int> counts(nprocs), displs(nprocs, 0);
    MPI_Allgather(&nbytes, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
    std::vector<Record> all((displs.back() + counts.back()) / sizeof(Record));
    MPI_Allgatherv(mine.data(), nbytes, MPI_BYTE, all.data(), counts.data(), displs.data(),
                   MPI_BYTE, world);
    return all;
  }

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
