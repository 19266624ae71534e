/* -*- c++ -*- ----------------------------------------------------------
   MESOPHYLL package for LAMMPS. Distributed under the GNU General Public
   License, version 2 or later, like LAMMPS itself.
------------------------------------------------------------------------- */

// Base of the DP bond and angle styles that have one stiffness per type (eps_l of dpoly/segment,
// eps_c of mesophyll/adhesion, eps_b of dpoly/bending): the coefficient table, coeff() with its
// error texts, restart and data-file output and extract(). Style is Bond or Angle; the derived
// style holds only its law.

#ifndef LMP_DPOLY_STIFFNESS_H
#define LMP_DPOLY_STIFFNESS_H

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "utils.h"

#include <cstring>
#include <string>

namespace LAMMPS_NS {
namespace DPoly {

  template <class Style> class PerTypeStiffness : public Style {
   public:
    // label: how messages name the style ("Bond style dpoly/segment"); name: the coefficient's
    // name ("eps_l"); ntypes: &Atom::nbondtypes or &Atom::nangletypes
    PerTypeStiffness(LAMMPS *lmp, const char *label, const char *name, int Atom::*ntypes) :
        Style(lmp), stiffness(nullptr), label(label), name(name), ntypes(ntypes)
    {
    }
    ~PerTypeStiffness() override
    {
      if (this->allocated) {
        this->memory->destroy(this->setflag);
        this->memory->destroy(stiffness);
      }
    }

    void coeff(int narg, char **arg) override
    {
      if (narg != 2)
        this->error->all(FLERR, "{} takes one coefficient ({}), got {}", label, name, narg - 1);
      if (!this->allocated) allocate();
      int ilo, ihi;
      utils::bounds(FLERR, arg[0], 1, count(), ilo, ihi, this->error);
      const double value = utils::numeric(FLERR, arg[1], false, this->lmp);
      if (value < 0.0) this->error->all(FLERR, "{} {} must be >= 0, got {}", label, name, arg[1]);
      for (int i = ilo; i <= ihi; i++) {
        stiffness[i] = value;
        this->setflag[i] = 1;
      }
    }

    // the style's settings, then every type's value and whether it is set (a style in hybrid
    // sets only some types)
    void write_restart(FILE *fp) override
    {
      this->write_restart_settings(fp);
      fwrite(&stiffness[1], sizeof(double), count(), fp);
      fwrite(&this->setflag[1], sizeof(int), count(), fp);
    }
    void read_restart(FILE *fp) override
    {
      this->read_restart_settings(fp);
      allocate();
      if (this->comm->me == 0) {
        utils::sfread(FLERR, &stiffness[1], sizeof(double), count(), fp, nullptr, this->error);
        utils::sfread(FLERR, &this->setflag[1], sizeof(int), count(), fp, nullptr, this->error);
      }
      MPI_Bcast(&stiffness[1], count(), MPI_DOUBLE, 0, this->world);
      MPI_Bcast(&this->setflag[1], count(), MPI_INT, 0, this->world);
    }
    void write_data(FILE *fp) override
    {
      for (int i = 1; i <= count(); i++)
        if (this->setflag[i]) fprintf(fp, "%d %.15g\n", i, stiffness[i]);
    }
    void *extract(const char *str, int &dim) override
    {
      dim = 1;
      return strcmp(str, name.c_str()) == 0 ? (void *) stiffness : nullptr;
    }

    double type_stiffness(int type) const { return stiffness[type]; }

   protected:
    double *stiffness;    // per type, from 1

    // bond styles: the central force fpair (x1 - x2) on atom 1 and its opposite on atom 2, where
    // this rank holds them, with the energy and virial
    void add_bond_force(int i1, int i2, double energy, double fpair, double delx, double dely,
                        double delz)
    {
      double **f = this->atom->f;
      const int nlocal = this->atom->nlocal, newton_bond = this->force->newton_bond;
      if (newton_bond || i1 < nlocal) {
        f[i1][0] += delx * fpair;
        f[i1][1] += dely * fpair;
        f[i1][2] += delz * fpair;
      }
      if (newton_bond || i2 < nlocal) {
        f[i2][0] -= delx * fpair;
        f[i2][1] -= dely * fpair;
        f[i2][2] -= delz * fpair;
      }
      if (this->evflag)
        this->ev_tally(i1, i2, nlocal, newton_bond, energy, fpair, delx, dely, delz);
    }

   private:
    std::string label, name;
    int Atom::*ntypes;
    int count() const { return this->atom->*ntypes; }
    void allocate()
    {
      this->allocated = 1;
      this->memory->create(stiffness, count() + 1, "dpoly:stiffness");
      this->memory->create(this->setflag, count() + 1, "dpoly:setflag");
      for (int i = 1; i <= count(); i++) this->setflag[i] = 0;
    }
  };

}    // namespace DPoly
}    // namespace LAMMPS_NS

#endif
