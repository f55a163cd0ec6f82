/* fix asperity/history: see fix_asperity_history.h.
 * Part of the asperity LAMMPS plugin, GPL-2.0-or-later (../LICENSE). */

#include "fix_asperity_history.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "utils.h"

#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// The format of the restart records. 1: [length, nvalues, npartner, ...],
// with the homogenised friction state of the old per-model ABI (8 doubles);
// 2: [length, -2, nvalues, npartner, ...], every friction state the
// library's flat state of asperity_friction_state_size doubles.
constexpr int RESTART_FORMAT = 2;
}    // namespace

// fix ID group asperity/history nvalues maxpartner [legacy]
// legacy (default 1): whether restart records of format 1 may be read as
// they are (0 when a homogenised friction law is in use: its state changed).
FixAsperityHistory::FixAsperityHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), npartner(nullptr), partner(nullptr), values(nullptr),
    peratom(nullptr)
{
  if (narg != 5 && narg != 6) error->all(FLERR, "Illegal fix asperity/history command: it is created by pair_style asperity");
  nvalues = utils::inumeric(FLERR, arg[3], false, lmp);
  maxpartner = utils::inumeric(FLERR, arg[4], false, lmp);
  legacy = narg == 6 ? utils::inumeric(FLERR, arg[5], false, lmp) != 0 : true;
  if (nvalues < 1 || maxpartner < 1)
    error->all(FLERR, "fix asperity/history: nvalues and maxpartner must be >= 1");

  restart_peratom = 1;
  create_attribute = 1;
  peratom_flag = 1;
  size_peratom_cols = 2;
  peratom_freq = 1;
  scalar_flag = 1;
  extscalar = 1;
  global_freq = 1;
  maxexchange = 1 + maxpartner * (1 + nvalues) + 2;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixAsperityHistory::~FixAsperityHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  memory->destroy(partner);
  memory->destroy(values);
  memory->destroy(peratom);
}

int FixAsperityHistory::setmask()
{
  return 0;
}

// Total energy dissipated by friction (energy units).
double FixAsperityHistory::compute_scalar()
{
  double local = 0.0, total = 0.0;
  for (int i = 0; i < atom->nlocal; i++) local += peratom[i][0];
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

int FixAsperityHistory::add(int i, tagint tag)
{
  int k = npartner[i];
  if (k >= maxpartner)
    error->one(FLERR,
               "pair asperity: atom {} has more than {} contacts; raise pair_style asperity "
               "maxcontacts",
               atom->tag[i], maxpartner);
  partner[i][k] = tag;
  std::memset(&values[i][k * nvalues], 0, sizeof(double) * nvalues);
  npartner[i] = k + 1;
  return k;
}

void FixAsperityHistory::compact(int i)
{
  int n = npartner[i], m = 0;
  for (int k = 0; k < n; k++) {
    if (partner[i][k] == 0) continue;
    if (m != k) {
      partner[i][m] = partner[i][k];
      std::memmove(&values[i][m * nvalues], &values[i][k * nvalues], sizeof(double) * nvalues);
    }
    m++;
  }
  npartner[i] = m;
}

void FixAsperityHistory::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "asperity/history:npartner");
  memory->grow(partner, nmax, maxpartner, "asperity/history:partner");
  memory->grow(values, nmax, maxpartner * nvalues, "asperity/history:values");
  memory->grow(peratom, nmax, 2, "asperity/history:peratom");
  array_atom = peratom;
}

void FixAsperityHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  npartner[j] = npartner[i];
  std::memcpy(partner[j], partner[i], sizeof(tagint) * npartner[i]);
  std::memcpy(values[j], values[i], sizeof(double) * npartner[i] * nvalues);
  peratom[j][0] = peratom[i][0];
  peratom[j][1] = peratom[i][1];
}

void FixAsperityHistory::set_arrays(int i)
{
  npartner[i] = 0;
  peratom[i][0] = peratom[i][1] = 0.0;
}

int FixAsperityHistory::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    for (int v = 0; v < nvalues; v++) buf[m++] = values[i][k * nvalues + v];
  }
  buf[m++] = peratom[i][0];
  buf[m++] = peratom[i][1];
  return m;
}

int FixAsperityHistory::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  npartner[nlocal] = static_cast<int>(buf[m++]);
  for (int k = 0; k < npartner[nlocal]; k++) {
    partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
    for (int v = 0; v < nvalues; v++) values[nlocal][k * nvalues + v] = buf[m++];
  }
  peratom[nlocal][0] = buf[m++];
  peratom[nlocal][1] = buf[m++];
  return m;
}

// Restart record of an atom: [length, -RESTART_FORMAT, nvalues, npartner,
// (tag, values)..., dissipation, contacts]; the format and nvalues are
// checked on reading.
int FixAsperityHistory::pack_restart(int i, double *buf)
{
  int m = 1;
  buf[m++] = -RESTART_FORMAT;
  buf[m++] = nvalues;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    for (int v = 0; v < nvalues; v++) buf[m++] = values[i][k * nvalues + v];
  }
  buf[m++] = peratom[i][0];
  buf[m++] = peratom[i][1];
  buf[0] = m;
  return m;
}

void FixAsperityHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  // Format 1 has no marker: its second value is nvalues (>= 1).
  double first = extra[nlocal][m++];
  int nv = 0;
  if (first > 0) {
    if (!legacy)
      error->one(FLERR,
                 "pair asperity: the restart file was written by an older asperity plugin "
                 "(history format 1), whose homogenised friction states have another layout: "
                 "run the input that wrote it again with this plugin");
    nv = static_cast<int>(first);
  } else {
    if (static_cast<int>(-first) != RESTART_FORMAT)
      error->one(FLERR, "pair asperity: the restart file holds contact histories of format {}, "
                 "this plugin reads formats 1 and {}", -first, RESTART_FORMAT);
    nv = static_cast<int>(extra[nlocal][m++]);
  }
  if (nv != nvalues)
    error->one(FLERR,
               "pair asperity: the restart file holds {} history values per contact, this "
               "pair_coeff setup needs {}: use the same laws and friction models as the run that "
               "wrote it",
               nv, nvalues);
  npartner[nlocal] = static_cast<int>(extra[nlocal][m++]);
  if (npartner[nlocal] > maxpartner)
    error->one(FLERR, "pair asperity: restart atom has {} contacts, maxcontacts is {}",
               npartner[nlocal], maxpartner);
  for (int k = 0; k < npartner[nlocal]; k++) {
    partner[nlocal][k] = (tagint) ubuf(extra[nlocal][m++]).i;
    for (int v = 0; v < nvalues; v++) values[nlocal][k * nvalues + v] = extra[nlocal][m++];
  }
  peratom[nlocal][0] = extra[nlocal][m++];
  peratom[nlocal][1] = extra[nlocal][m++];
}

int FixAsperityHistory::size_restart(int i)
{
  return 4 + npartner[i] * (1 + nvalues) + 2;
}

int FixAsperityHistory::maxsize_restart()
{
  return 4 + maxpartner * (1 + nvalues) + 2;
}

double FixAsperityHistory::memory_usage()
{
  double n = atom->nmax;
  return n * (sizeof(int) + maxpartner * (sizeof(tagint) + nvalues * sizeof(double)) +
              2 * sizeof(double));
}
