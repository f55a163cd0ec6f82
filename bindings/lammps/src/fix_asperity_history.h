/* fix asperity/history: per-contact history of pair_style asperity.
 *
 * Part of the asperity LAMMPS plugin (bindings/lammps/), GPL-2.0-or-later:
 * it includes LAMMPS headers. See ../LICENSE.
 *
 * Each owned atom keeps a list of the partners it is in contact with (their
 * atom IDs) and, per partner, the pair's history as `nvalues` doubles (the
 * library's normal contact state, the tangent frame and the friction
 * law's flat state of asperity_friction_state_size doubles). The list
 * moves with the atom between MPI ranks (pack_exchange) and is written to
 * and read from restart files (pack_restart, with a format number), so a
 * contact's hysteresis and friction state survive migration and restarts.
 * Both atoms of a pair hold the same values: pair_style asperity evaluates
 * every pair in the orientation of the lower atom ID.
 *
 * It also keeps, per atom, the energy dissipated by friction in the
 * atom's contacts (half of each contact's dissipation, energy units) and
 * the atom's current number of contacts, as a per-atom array
 * (f_ID[1], f_ID[2]); its global scalar is the total dissipation.
 *
 * The pair style creates it (ID ASPERITY_HISTORY); users do not. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(asperity/history,FixAsperityHistory);
// clang-format on
#else

#ifndef LMP_FIX_ASPERITY_HISTORY_H
#define LMP_FIX_ASPERITY_HISTORY_H

#include "fix.h"

namespace LAMMPS_NS {

class FixAsperityHistory : public Fix {
 public:
  FixAsperityHistory(class LAMMPS *, int, char **);
  ~FixAsperityHistory() override;
  int setmask() override;
  double compute_scalar() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  int nvalues;        // doubles of history per contact
  int maxpartner;     // contacts an atom can hold
  bool legacy;        // restart records of format 1 may be read
  int *npartner;      // contacts held by each atom
  tagint **partner;   // partner[i][k]: atom ID of contact k of atom i
  double **values;    // values[i][k*nvalues ...]: its history
  double **peratom;   // [i][0]: dissipated energy, [i][1]: contacts

  // The slot of partner `tag` in atom i's list, or -1.
  int find(int i, tagint tag) const
  {
    const tagint *p = partner[i];
    for (int k = 0, n = npartner[i]; k < n; k++)
      if (p[k] == tag) return k;
    return -1;
  }
  // Append partner `tag` to atom i's list (values zeroed); its slot.
  int add(int i, tagint tag);
  // Drop the slots of atom i whose partner ID was set to 0.
  void compact(int i);
};

}    // namespace LAMMPS_NS

#endif
#endif
