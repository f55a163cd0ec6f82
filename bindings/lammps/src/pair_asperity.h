/* pair_style asperity: the asperity library's contact laws and friction
 * step as a LAMMPS granular pair style.
 *
 * Part of the asperity LAMMPS plugin (bindings/lammps/), GPL-2.0-or-later:
 * it includes LAMMPS headers. See ../LICENSE and ../README.md. */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(asperity,PairAsperity);
// clang-format on
#else

#ifndef LMP_PAIR_ASPERITY_H
#define LMP_PAIR_ASPERITY_H

#include "pair.h"

#include "asperity.h"

#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

class PairAsperity : public Pair {
 public:
  PairAsperity(class LAMMPS *);
  ~PairAsperity() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double memory_usage() override;

  // What pair_coeff said for one type pair (values in SI units).
  struct Coeff {
    int law = -1;                  // LAW_*
    double e = 0, nu = 0;          // Young modulus (Pa), Poisson ratio
    // NaN: not given.
    double w = NAN;                // work of adhesion (J/m^2)
    double sigma0 = NAN;           // Dugdale stress (Pa)
    double lambda = NAN;           // Maugis parameter
    double z0 = NAN;               // LJ equilibrium separation (m)
    double tolerance = 1e-4;       // table tolerance
    int grid = 0;                  // LJ solver cells (0: library default)
    std::string file;              // table JSON file
    int friction = 0;              // FRICTION_*
    std::string friction_file;     // homogenised table JSON
    double kt = NAN;               // stick stiffness (N/m)
    AsperityLugreParams lugre{};
    std::vector<double> ms_stiffness, ms_capacity;    // Maxwell-slip
    double sigma2 = 0;             // viscous term (N s/m)
    bool mixed = false;            // filled by mixing in init_one
  };

  // One normal law at one effective radius, with its reach.
  struct Law {
    AsperityNormalLaw law;           // closed-form laws
    AsperityTable *table = nullptr;  // tabulated laws (owned by the type pair)
    double radius = 0;               // effective radius R (m)
    double reach = 0;                // overlap (m, <= 0) below which the force is 0
    double pull_off_load = 0;        // load-controlled pull-off force (N, <= 0)
    int tp = 0;                      // type pair index
  };

  // Per type pair, everything built at init.
  struct TypePair {
    Coeff c;
    double e_star = 0;                          // Pa
    AsperityTable *table = nullptr;
    bool owns_table = true;                     // false: shared with another type pair
    double table_radius = 0;                    // R the table was built for (m)
    AsperityFriction *friction = nullptr;       // the friction law (any model)
    int fstate = 0;                             // its state: doubles per contact
    double reach_max = 0;                       // reach at the largest R (m)
    bool energy = false;                        // library gives its energy
    bool history = true;                        // contacts keep a history
    std::unordered_map<uint64_t, int> laws;     // R bits -> index in laws_
    int last_law = -1;
  };

 protected:
  void allocate();
  void set_units();
  void free_built();
  void build(int tp);
  void build_friction(int tp);
  int law_for(int tp, double radius);
  void flush(int eflag);

  int pulloff_control;      // ASPERITY_CONTROL_*
  int maxcontacts;
  double len, frc, eng, prs, tim;    // one unit of the unit style in SI
  int ntp;                           // (ntypes+1)^2
  std::vector<Coeff> coeffs;         // by tp = i*(ntypes+1)+j
  std::vector<std::vector<std::string>> coeff_args;    // pair_coeff words after I J, by tp
  std::vector<TypePair> tps;
  std::vector<Law> laws_;
  std::vector<double> maxrad;        // per type, distance units
  bool built;
  bool any_friction;
  int nvalues;                       // history doubles per contact
  class FixAsperityHistory *fix_history;
  AsperityFrictionWork *friction_work;   // scratch of the friction step

  // A batch of pairs sharing one law.
  struct Item {
    int i, j;         // local indices (lo = i after canonical ordering)
    int slot_i, slot_j;
    double delta;     // SI
    double n[3];      // unit normal from j to i
    double r;         // distance units
  };
  std::vector<Item> items;
  std::vector<double> b_delta, b_force, b_radius;
  std::vector<AsperityContactState> b_old, b_new;
  std::vector<char> visited;
  std::vector<double> scratch_;
  int batch_law;
  int nlocal_, eflag_;
  double dissipated_run;   // energy units, this rank
};

}    // namespace LAMMPS_NS

#endif
#endif
