/* pair_style asperity: see pair_asperity.h and ../README.md.
 * Part of the asperity LAMMPS plugin, GPL-2.0-or-later (../LICENSE).
 *
 * This file only translates between LAMMPS and the asperity C ABI: units,
 * the neighbour list, per-contact history and the tangent frame. The
 * physics (normal laws, their reach, energy and pull-off, the friction
 * step) is the library's. */

#include "pair_asperity.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_asperity_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "platform.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

using namespace LAMMPS_NS;

namespace {

enum { LAW_HERTZ, LAW_DMT, LAW_JKR, LAW_MD, LAW_TABLE_MD, LAW_TABLE_LJ, LAW_TABLE_FILE };
const char *const LAW_NAMES[] = {"hertz",   "dmt",      "jkr",       "maugis_dugdale",
                                 "table/maugis_dugdale", "table/lj", "table/file"};
enum { FRICTION_NONE, FRICTION_HOMOGENISED, FRICTION_LUGRE, FRICTION_MAXWELL };

constexpr const char *FIX_ID = "ASPERITY_HISTORY";
constexpr int NORMAL_VALUES = 3;    // AsperityContactState as doubles
constexpr int FRAME_VALUES = 3;     // tangent vector t1
static_assert(sizeof(AsperityContactState) == NORMAL_VALUES * sizeof(double),
              "contact state packs into three doubles");

bool is_law_table(int law)
{
  return law == LAW_TABLE_MD || law == LAW_TABLE_LJ || law == LAW_TABLE_FILE;
}
bool is_adhesive(int law)
{
  return law != LAW_HERTZ;
}

std::string library_message()
{
  char buf[1024];
  asperity_last_error_message(buf, sizeof(buf));
  return std::string(buf);
}

// The Dugdale stress of a Maugis-Dugdale law (Pa): `sigma0` as given, or
// from `lambda` by inverting the Maugis parameter
// lambda = sigma0 (9R/(2 pi w E*^2))^(1/3) (Maugis 1992) at radius R (m).
double dugdale_stress(const PairAsperity::Coeff &c, double e_star, double radius)
{
  if (std::isnan(c.lambda)) return c.sigma0;
  return c.lambda * std::cbrt(2.0 * M_PI * c.w * e_star * e_star / (9.0 * radius));
}

uint64_t bits(double x)
{
  uint64_t u;
  std::memcpy(&u, &x, sizeof(u));
  return u;
}

}    // namespace

PairAsperity::PairAsperity(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 1;
  single_extra = 2;
  svector = new double[single_extra];
  no_virial_fdotr_compute = 1;
  finitecutflag = 1;
  restartinfo = 1;
  writedata = 0;
  nextra = 2;
  pvector = new double[nextra];
  pvector[0] = pvector[1] = 0.0;
  pulloff_control = ASPERITY_CONTROL_DISPLACEMENT;
  maxcontacts = 32;
  len = tim = frc = eng = prs = 1.0;
  ntp = 0;
  built = false;
  any_friction = false;
  nvalues = NORMAL_VALUES;
  fix_history = nullptr;
  friction_work = nullptr;
  batch_law = -1;
  nlocal_ = eflag_ = 0;
  dissipated_run = 0.0;
}

PairAsperity::~PairAsperity()
{
  delete[] pvector;
  delete[] svector;
  free_built();
  asperity_friction_work_free(friction_work);
  if (modify->get_fix_by_id(FIX_ID)) modify->delete_fix(FIX_ID);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairAsperity::free_built()
{
  for (auto &t : tps) {
    if (t.owns_table) asperity_table_free(t.table);
    asperity_friction_free(t.friction);
    t = TypePair();
  }
  laws_.clear();
  built = false;
}

void PairAsperity::allocate()
{
  allocated = 1;
  int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  ntp = (n + 1) * (n + 1);
  coeffs.assign(ntp, Coeff());
  coeff_args.assign(ntp, {});
  tps.assign(ntp, TypePair());
  maxrad.assign(n + 1, 0.0);
}

/* pair_style asperity [pulloff displacement|load] [maxcontacts N] */
void PairAsperity::set_units()
{
  const char *units = update->unit_style;
  if (strcmp(units, "si") == 0) {
    len = tim = frc = eng = prs = 1.0;
  } else if (strcmp(units, "micro") == 0) {
    len = 1e-6; tim = 1e-6; frc = 1e-9; eng = 1e-15; prs = 1e3;
  } else if (strcmp(units, "nano") == 0) {
    len = 1e-9; tim = 1e-9; frc = 1e-12; eng = 1e-21; prs = 1e6;
  } else {
    error->all(FLERR,
               "pair_style asperity supports units si, micro and nano, not '{}': the library "
               "works in SI and the plugin converts only these three exactly",
               units);
  }
}

void PairAsperity::settings(int narg, char **arg)
{
  set_units();
  int iarg = 0;
  while (iarg < narg) {
    std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "pair_style asperity: keyword '{}' needs a value", key);
    std::string val = arg[iarg + 1];
    if (key == "pulloff") {
      if (val == "displacement") pulloff_control = ASPERITY_CONTROL_DISPLACEMENT;
      else if (val == "load") pulloff_control = ASPERITY_CONTROL_LOAD;
      else error->all(FLERR, "pair_style asperity: pulloff must be 'displacement' or 'load', not '{}'", val);
    } else if (key == "maxcontacts") {
      maxcontacts = utils::inumeric(FLERR, val, false, lmp);
      if (maxcontacts < 1 || maxcontacts > 1000)
        error->all(FLERR, "pair_style asperity: maxcontacts must be in [1, 1000], got {}", maxcontacts);
    } else {
      error->all(FLERR, "pair_style asperity: unknown keyword '{}' (pulloff, maxcontacts)", key);
    }
    iarg += 2;
  }
  if (built) free_built();
}

/* pair_coeff I J law key value ... [friction model ...] */
void PairAsperity::coeff(int narg, char **arg)
{
  if (narg < 3)
    error->all(FLERR, "pair_coeff for asperity: pair_coeff I J law E value nu value [w value] ...");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  Coeff c;
  std::string law = arg[2];
  for (int k = 0; k < 7; k++)
    if (law == LAW_NAMES[k]) c.law = k;
  if (c.law < 0)
    error->all(FLERR,
               "pair_coeff asperity: unknown law '{}' (hertz, dmt, jkr, maugis_dugdale, "
               "table/maugis_dugdale, table/lj, table/file)",
               law);

  auto number = [&](int k, const char *key) {
    if (k >= narg) error->all(FLERR, "pair_coeff asperity: keyword '{}' needs a value", key);
    return utils::numeric(FLERR, arg[k], false, lmp);
  };
  bool have_e = false, have_nu = false;
  int iarg = 3;
  while (iarg < narg) {
    std::string key = arg[iarg];
    if (key == "friction") break;
    if (key == "E") { c.e = number(iarg + 1, "E") * prs; have_e = true; }
    else if (key == "nu") { c.nu = number(iarg + 1, "nu"); have_nu = true; }
    else if (key == "w") c.w = number(iarg + 1, "w") * eng / (len * len);
    else if (key == "sigma0") c.sigma0 = number(iarg + 1, "sigma0") * prs;
    else if (key == "lambda") c.lambda = number(iarg + 1, "lambda");
    else if (key == "z0") c.z0 = number(iarg + 1, "z0") * len;
    else if (key == "tolerance") c.tolerance = number(iarg + 1, "tolerance");
    else if (key == "grid") c.grid = (int) number(iarg + 1, "grid");
    else if (key == "file") {
      if (iarg + 1 >= narg) error->all(FLERR, "pair_coeff asperity: keyword 'file' needs a path");
      c.file = arg[iarg + 1];
    } else
      error->all(FLERR, "pair_coeff asperity: unknown keyword '{}' for law {}", key, law);
    iarg += 2;
  }

  // What each law needs; the values themselves are checked by the library.
  auto given = [](double v) { return !std::isnan(v); };
  bool table_file = c.law == LAW_TABLE_FILE;
  if (!table_file && !have_e) error->all(FLERR, "pair_coeff asperity: law {} needs E (Young modulus)", law);
  if (!table_file && !have_nu) error->all(FLERR, "pair_coeff asperity: law {} needs nu (Poisson ratio)", law);
  if (is_adhesive(c.law) && !table_file && !given(c.w))
    error->all(FLERR, "pair_coeff asperity: law {} is adhesive and needs w (work of adhesion)", law);
  if (!is_adhesive(c.law) && given(c.w))
    error->all(FLERR, "pair_coeff asperity: law hertz takes no w (use dmt or jkr for adhesion)");
  if ((c.law == LAW_MD || c.law == LAW_TABLE_MD) && given(c.sigma0) == given(c.lambda))
    error->all(FLERR, "pair_coeff asperity: law {} needs exactly one of sigma0 and lambda", law);
  if (c.law == LAW_TABLE_LJ && !given(c.z0))
    error->all(FLERR, "pair_coeff asperity: law table/lj needs z0 (equilibrium separation)");
  if (table_file && c.file.empty())
    error->all(FLERR, "pair_coeff asperity: law table/file needs file <table.json>");
  if (!table_file) {
    // Let the library judge the values now, on a unit sphere, so a bad
    // value stops the input at this line with the library's bound.
    double e_star = 0;
    if (asperity_effective_modulus(c.e, c.nu, c.e, c.nu, &e_star) != ASPERITY_OK)
    {
      std::string m = library_message();
      error->all(FLERR, "pair_coeff asperity: {}: {}", m.find("nu1") != std::string::npos ? "nu" : "E", m);
    }
    AsperityNormalLaw trial;
    int st = ASPERITY_OK;
    const char *key = "w";
    if (c.law == LAW_DMT) st = asperity_law_dmt(1.0, e_star, c.w, &trial);
    else if (c.law == LAW_JKR || c.law == LAW_TABLE_LJ) st = asperity_law_jkr(1.0, e_star, c.w, &trial);
    else if (c.law == LAW_MD || c.law == LAW_TABLE_MD) {
      st = asperity_law_jkr(1.0, e_star, c.w, &trial);
      if (st == ASPERITY_OK && given(c.sigma0)) {
        key = "sigma0";
        st = asperity_law_maugis_dugdale(1.0, e_star, c.w, c.sigma0, &trial);
      }
      if (st == ASPERITY_OK && given(c.lambda) && !(c.lambda > 0 && std::isfinite(c.lambda))) {
        error->all(FLERR, "pair_coeff asperity: lambda = {} must be finite and > 0", c.lambda);
      }
    }
    if (st != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: {}: {}", key, library_message());
    if (c.law == LAW_TABLE_LJ && !(c.z0 > 0 && std::isfinite(c.z0)))
      error->all(FLERR, "pair_coeff asperity: z0 = {} must be finite and > 0", c.z0 / len);
  }

  if (iarg < narg) {    // friction model, to the end of the line
    std::string model = (iarg + 1 < narg) ? arg[iarg + 1] : "";
    iarg += 2;
    if (model == "none") c.friction = FRICTION_NONE;
    else if (model == "homogenised") {
      c.friction = FRICTION_HOMOGENISED;
      if (iarg >= narg) error->all(FLERR, "pair_coeff asperity: friction homogenised needs a law file (JSON)");
      c.friction_file = arg[iarg++];
      while (iarg < narg) {
        std::string key = arg[iarg];
        if (key == "kt") c.kt = number(iarg + 1, "kt") * frc / len;
        else error->all(FLERR, "pair_coeff asperity: unknown keyword '{}' for friction homogenised (kt)", key);
        iarg += 2;
      }
      if (std::isnan(c.kt)) error->all(FLERR, "pair_coeff asperity: friction homogenised needs kt (stick stiffness, force/distance)");
    } else if (model == "lugre") {
      c.friction = FRICTION_LUGRE;
      AsperityLugreParams &p = c.lugre;
      p.mu_coulomb = p.mu_static = NAN;
      p.stribeck_velocity = NAN;
      p.stribeck_exponent = 2.0;
      p.sigma0 = NAN;
      p.sigma1 = 0.0;
      p.damping_velocity = INFINITY;
      p.sigma2 = 0.0;
      while (iarg < narg) {
        std::string key = arg[iarg];
        double v = number(iarg + 1, key.c_str());
        if (key == "mu_c") p.mu_coulomb = v;
        else if (key == "mu_s") p.mu_static = v;
        else if (key == "vs") p.stribeck_velocity = v * len / tim;
        else if (key == "exponent") p.stribeck_exponent = v;
        else if (key == "sigma0") p.sigma0 = v / len;
        else if (key == "sigma1") p.sigma1 = v * tim / len;
        else if (key == "vd") p.damping_velocity = v * len / tim;
        else if (key == "sigma2") p.sigma2 = v * frc * tim / len;
        else error->all(FLERR, "pair_coeff asperity: unknown keyword '{}' for friction lugre (mu_c mu_s vs sigma0 sigma1 vd exponent sigma2)", key);
        iarg += 2;
      }
      if (std::isnan(p.mu_coulomb) || std::isnan(p.mu_static) || std::isnan(p.stribeck_velocity) || std::isnan(p.sigma0))
        error->all(FLERR, "pair_coeff asperity: friction lugre needs mu_c, mu_s, vs and sigma0");
    } else if (model == "maxwell_slip") {
      c.friction = FRICTION_MAXWELL;
      while (iarg < narg) {
        std::string key = arg[iarg];
        if (key == "sigma2") { c.sigma2 = number(iarg + 1, "sigma2") * frc * tim / len; iarg += 2; continue; }
        if (key != "element")
          error->all(FLERR, "pair_coeff asperity: friction maxwell_slip takes 'element k capacity' (k in 1/distance) and 'sigma2', not '{}'", key);
        c.ms_stiffness.push_back(number(iarg + 1, "element stiffness") / len);
        c.ms_capacity.push_back(number(iarg + 2, "element capacity"));
        iarg += 3;
      }
      if (c.ms_stiffness.empty()) error->all(FLERR, "pair_coeff asperity: friction maxwell_slip needs at least one 'element k capacity'");
    } else {
      error->all(FLERR, "pair_coeff asperity: unknown friction model '{}' (none, homogenised, lugre, maxwell_slip)", model);
    }
  }

  if (c.friction == FRICTION_LUGRE || c.friction == FRICTION_MAXWELL) {
    // Let the library judge the friction parameters at this line (the
    // homogenised law's are judged when its file is read, at init).
    AsperityFriction *trial = nullptr;
    int st = c.friction == FRICTION_LUGRE
        ? asperity_friction_lugre_new(&c.lugre, &trial)
        : asperity_friction_maxwell_slip_new(c.ms_stiffness.data(), c.ms_capacity.data(), c.ms_stiffness.size(), c.sigma2, &trial);
    asperity_friction_free(trial);
    if (st != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: friction: {}", library_message());
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      coeffs[i * (atom->ntypes + 1) + j] = c;
      coeff_args[i * (atom->ntypes + 1) + j].assign(arg + 2, arg + narg);
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
  if (built) free_built();
}

/* Build the law handles and friction models of type pair tp (i <= j). */
void PairAsperity::build(int tp)
{
  TypePair &t = tps[tp];
  const Coeff &c = t.c;
  int status = ASPERITY_OK;
  std::string what = LAW_NAMES[c.law];
  if (c.law != LAW_TABLE_FILE && !c.mixed) {
    status = asperity_effective_modulus(c.e, c.nu, c.e, c.nu, &t.e_star);
    if (status != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: {}", library_message());
  }
  if (is_law_table(c.law)) {
    int nt = atom->ntypes + 1;
    int i = tp / nt, j = tp % nt;
    double ri = maxrad[i] * len, rj = maxrad[j] * len;
    if (c.law != LAW_TABLE_FILE && (ri <= 0 || rj <= 0))
      error->all(FLERR, "pair asperity: a table law for types {} {} needs atoms of both types (their radius sets the table's R)", i, j);
    double radius = ri * rj / (ri + rj);
    if (c.law == LAW_TABLE_FILE) {
      std::ifstream in(c.file);
      if (!in) error->all(FLERR, "pair_coeff asperity: cannot read table file {}", c.file);
      std::stringstream ss;
      ss << in.rdbuf();
      std::string json = ss.str();
      status = asperity_table_from_json(json.data(), json.size(), &t.table);
      if (status != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: table file {}: {}", c.file, library_message());
      radius = 0;    // checked against the pairs' radius by its reach only
    } else {
      double sigma0 = dugdale_stress(c, t.e_star, radius);
      // A table with the same parameters (another type pair of the same
      // material and radius) is shared, not built again.
      for (int o = 0; o < tp; o++) {
        const TypePair &u = tps[o];
        const Coeff &d = u.c;
        auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
        if (u.table && u.owns_table && d.law == c.law && u.e_star == t.e_star && u.table_radius == radius &&
            same(d.w, c.w) && same(d.sigma0, c.sigma0) && same(d.lambda, c.lambda) && same(d.z0, c.z0) &&
            d.tolerance == c.tolerance && d.grid == c.grid) {
          t.table = u.table;
          t.owns_table = false;
          t.table_radius = radius;
          return build_friction(tp);
        }
      }
      double t0 = platform::walltime();
      if (c.law == LAW_TABLE_MD)
        status = asperity_table_new_maugis_dugdale(radius, t.e_star, c.w, sigma0, c.tolerance, &t.table);
      else
        status = asperity_table_new_lj(radius, t.e_star, c.w, c.z0, (size_t) c.grid, c.tolerance, &t.table);
      if (status != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: building the {} table: {}", what, library_message());
      if (comm->me == 0)
        utils::logmesg(lmp, "pair asperity: built the {} table for types {} {} (R = {} m) in {:.3} s\n", what, i, j, radius, platform::walltime() - t0);
    }
    t.table_radius = radius;
  }
  build_friction(tp);
}

/* The friction law of type pair tp: one AsperityFriction handle, whatever
   the model, and the doubles of its per-contact state. */
void PairAsperity::build_friction(int tp)
{
  TypePair &t = tps[tp];
  const Coeff &c = t.c;
  int status = ASPERITY_OK;
  if (c.friction == FRICTION_HOMOGENISED) {
    std::ifstream in(c.friction_file);
    if (!in) error->all(FLERR, "pair_coeff asperity: cannot read friction law file {}", c.friction_file);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string json = ss.str();
    AsperityHomogenisedFriction *table = nullptr;
    status = asperity_homogenised_friction_from_json(json.data(), json.size(), &table);
    if (status != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: friction law {}: {}", c.friction_file, library_message());
    // The law: the table (copied) with the stick stiffness kt.
    status = asperity_friction_from_homogenised(table, c.kt, &t.friction);
    asperity_homogenised_friction_free(table);
    if (status != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: friction homogenised {} kt: {}", c.friction_file, library_message());
  } else if (c.friction == FRICTION_LUGRE) {
    status = asperity_friction_lugre_new(&c.lugre, &t.friction);
  } else if (c.friction == FRICTION_MAXWELL) {
    status = asperity_friction_maxwell_slip_new(c.ms_stiffness.data(), c.ms_capacity.data(), c.ms_stiffness.size(), c.sigma2, &t.friction);
  }
  if (status != ASPERITY_OK) error->all(FLERR, "pair_coeff asperity: friction: {}", library_message());
  if (t.friction) {
    size_t n = 0;
    if (asperity_friction_state_size(t.friction, &n) != ASPERITY_OK)
      error->all(FLERR, "pair asperity: friction: {}", library_message());
    t.fstate = (int) n;
  }
}

/* The law of type pair tp at effective radius R (m): index in laws_. */
int PairAsperity::law_for(int tp, double radius)
{
  TypePair &t = tps[tp];
  if (t.last_law >= 0 && laws_[t.last_law].radius == radius) return t.last_law;
  auto it = t.laws.find(bits(radius));
  if (it != t.laws.end()) return t.last_law = it->second;

  const Coeff &c = t.c;
  Law l;
  l.tp = tp;
  l.radius = radius;
  int status = ASPERITY_OK;
  double rel_force = c.tolerance;
  if (t.table) {
    if (t.table_radius > 0 && std::fabs(radius - t.table_radius) > 1e-9 * t.table_radius)
      error->one(FLERR,
                 "pair asperity: a pair of effective radius {} m meets the {} table built for R = {} m: "
                 "tables need one radius per atom type",
                 radius, LAW_NAMES[c.law], t.table_radius);
    l.table = t.table;
    status = asperity_table_reach(t.table, pulloff_control, rel_force, &l.reach);
    if (status == ASPERITY_OK) status = asperity_table_pull_off_force(t.table, ASPERITY_CONTROL_LOAD, &l.pull_off_load);
  } else {
    switch (c.law) {
      case LAW_HERTZ: status = asperity_law_hertz(radius, t.e_star, &l.law); break;
      case LAW_DMT: status = asperity_law_dmt(radius, t.e_star, c.w, &l.law); break;
      case LAW_JKR: status = asperity_law_jkr(radius, t.e_star, c.w, &l.law); break;
      case LAW_MD: {
        status = asperity_law_maugis_dugdale(radius, t.e_star, c.w, dugdale_stress(c, t.e_star, radius), &l.law);
        break;
      }
    }
    if (status == ASPERITY_OK) status = asperity_normal_reach(&l.law, pulloff_control, rel_force, &l.reach);
    if (status == ASPERITY_OK) status = asperity_pull_off_force(&l.law, ASPERITY_CONTROL_LOAD, &l.pull_off_load);
  }
  if (status != ASPERITY_OK)
    error->one(FLERR, "pair asperity: law {} at R = {} m: {}", LAW_NAMES[c.law], radius, library_message());
  laws_.push_back(l);
  int k = (int) laws_.size() - 1;
  t.laws[bits(radius)] = k;
  return t.last_law = k;
}

void PairAsperity::init_style()
{
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "pair_style asperity requires atom_style sphere (radius, omega, torque)");
  if (!atom->tag_enable) error->all(FLERR, "pair_style asperity requires atom IDs");

  int nt = atom->ntypes;
  // Largest radius per type: atoms present, and what fix pour will insert.
  std::vector<double> local(nt + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++) local[atom->type[i]] = std::max(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad.data(), nt + 1, MPI_DOUBLE, MPI_MAX, world);
  for (auto *f : modify->get_fix_by_style("^pour")) {
    for (int i = 1; i <= nt; i++) {
      int itype = i;
      double *r = (double *) f->extract("radius", itype);
      if (r) maxrad[i] = std::max(maxrad[i], *r);
    }
  }

  if (!built) {
    for (auto &t : tps) { t.laws.clear(); t.last_law = -1; }
    laws_.clear();
    for (int i = 1; i <= nt; i++)
      for (int j = i; j <= nt; j++) {
        int tp = i * (nt + 1) + j;
        Coeff c;
        if (setflag[i][j]) {
          c = coeffs[tp];
        } else {
          // Mixing: the same law and friction model; E* of the two materials,
          // geometric means of w and sigma0 (as LAMMPS granular mixes cohesion).
          const Coeff &a = coeffs[i * (nt + 1) + i], &b = coeffs[j * (nt + 1) + j];
          if (!setflag[i][i] || !setflag[j][j])
            error->all(FLERR, "pair asperity: coefficients for types {} {} are not set", i, j);
          if (a.law != b.law || is_law_table(a.law))
            error->all(FLERR, "pair asperity: types {} {} have different laws or table laws: give pair_coeff {} {} explicitly", i, j, i, j);
          if (a.friction != b.friction)
            error->all(FLERR, "pair asperity: types {} {} have different friction models: give pair_coeff {} {} explicitly", i, j, i, j);
          c = a;
          c.mixed = true;
          c.w = std::sqrt(a.w * b.w);    // NaN stays NaN
          c.sigma0 = std::sqrt(a.sigma0 * b.sigma0);
          c.lambda = std::sqrt(a.lambda * b.lambda);
        }
        tps[tp].c = c;
        if (c.mixed) {
          const Coeff &a = coeffs[i * (nt + 1) + i], &b = coeffs[j * (nt + 1) + j];
          if (asperity_effective_modulus(a.e, a.nu, b.e, b.nu, &tps[tp].e_star) != ASPERITY_OK)
            error->all(FLERR, "pair asperity: {}", library_message());
        }
        build(tp);
      }
    built = true;
  }

  any_friction = false;
  int fmax = 0;
  bool homogenised = false;
  for (int i = 1; i <= nt; i++)
    for (int j = i; j <= nt; j++) {
      TypePair &t = tps[i * (nt + 1) + j];
      fmax = std::max(fmax, t.fstate);
      if (t.c.friction != FRICTION_NONE) any_friction = true;
      if (t.c.friction == FRICTION_HOMOGENISED) homogenised = true;
      // One scratch of the friction step for the pair style (the laws here
      // need none; a law that does rebuilds it on first use).
      if (t.friction && !friction_work && asperity_friction_work_new(t.friction, &friction_work) != ASPERITY_OK)
        error->all(FLERR, "pair asperity: friction: {}", library_message());
      // Reach at the largest radius of the pair (the reach of every law
      // grows with R), for the neighbour cutoff.
      double ri = maxrad[i] * len, rj = maxrad[j] * len;
      t.reach_max = 0.0;
      if (ri > 0 && rj > 0) {
        double rmax = ri * rj / (ri + rj);
        if (t.table && t.table_radius > 0) rmax = t.table_radius;
        t.reach_max = laws_[law_for(i * (nt + 1) + j, rmax)].reach;
      } else if (t.table) {
        t.reach_max = laws_[law_for(i * (nt + 1) + j, t.table_radius)].reach;
      }
      // The library has the contact energy in closed form for these laws.
      t.energy = t.c.law == LAW_HERTZ || t.c.law == LAW_DMT || t.c.law == LAW_JKR;
      // Hertz and DMT without friction have no history to keep.
      t.history = !(t.c.law == LAW_HERTZ || t.c.law == LAW_DMT) || t.c.friction != FRICTION_NONE;
    }
  if (any_friction && !comm->ghost_velocity)
    error->all(FLERR, "pair_style asperity with friction requires ghost atoms store velocity: comm_modify vel yes");

  nvalues = NORMAL_VALUES + (fmax > 0 ? FRAME_VALUES + fmax : 0);
  Fix *f = modify->get_fix_by_id(FIX_ID);
  if (f && (static_cast<FixAsperityHistory *>(f)->nvalues != nvalues ||
            static_cast<FixAsperityHistory *>(f)->maxpartner != maxcontacts)) {
    if (comm->me == 0)
      error->warning(FLERR, "pair asperity: the history layout changed (laws or friction models); contact histories are reset");
    modify->delete_fix(FIX_ID);
    f = nullptr;
  }
  // Restart records of the first history format hold homogenised friction
  // states of another layout; the others read as they are.
  if (!f) f = modify->add_fix(fmt::format("{} all asperity/history {} {} {}", FIX_ID, nvalues, maxcontacts, homogenised ? 0 : 1));
  fix_history = static_cast<FixAsperityHistory *>(f);

  // A half list in which every pair with a ghost is on both ranks (newton
  // off whatever the global setting): each rank updates the history of its
  // own atoms, so nothing is communicated back.
  neighbor->add_request(this, NeighConst::REQ_NEWTON_OFF);
}

double PairAsperity::init_one(int i, int j)
{
  int nt = atom->ntypes;
  const TypePair &t = tps[std::min(i, j) * (nt + 1) + std::max(i, j)];
  // Touching distance plus the law's reach beyond touching (distance units).
  double cut = maxrad[i] + maxrad[j] - t.reach_max / len;
  if (t.table && maxrad[i] <= 0) cut = -t.reach_max / len;
  return cut > 0 ? cut : 0.0;
}

/* One pair's normal force for compute pair/local and the like: the force
   from its stored history (nothing is written), fforce = F/r, the energy
   where the library has it; svector = [contact radius (distance units),
   1 in contact / 0 not]. The tangential force is not included: it is the
   outcome of the last step's increment, not a function of the positions. */
double PairAsperity::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                            double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  svector[0] = svector[1] = 0.0;
  int nt = atom->ntypes;
  int tp = std::min(itype, jtype) * (nt + 1) + std::max(itype, jtype);
  const double *radius = atom->radius;
  double radsum = radius[i] + radius[j];
  double r = sqrt(rsq);
  if (r == 0.0) return 0.0;
  double delta = (radsum - r) * len;
  int li = law_for(tp, radius[i] * radius[j] / radsum * len);
  const Law &l = laws_[li];
  if (delta < l.reach) return 0.0;
  AsperityContactState old{};
  FixAsperityHistory *h = fix_history;
  tagint *tag = atom->tag;
  int k = -1;
  const double *src = nullptr;
  if (h && i < atom->nlocal && (k = h->find(i, tag[j])) >= 0) src = &h->values[i][k * nvalues];
  else if (h && j < atom->nlocal && (k = h->find(j, tag[i])) >= 0) src = &h->values[j][k * nvalues];
  if (src) std::memcpy(&old, src, sizeof(old));
  AsperityContactState st;
  AsperityNormalResponse resp;
  int status = l.table ? asperity_table_eval(l.table, delta, &old, &st, &resp)
                       : asperity_normal_eval(&l.law, delta, &old, &st, &resp);
  if (status != ASPERITY_OK) error->one(FLERR, "pair asperity: {}", library_message());
  fforce = resp.force / frc / r;
  svector[0] = resp.contact_radius / len;
  svector[1] = resp.in_contact;
  double u = 0.0;
  if (tps[tp].energy && asperity_normal_energy(&l.law, delta, &old, &u) != ASPERITY_OK) u = 0.0;
  return u / eng;
}

/* Restart: the pair_style settings and, per type pair, the words of its
   pair_coeff, read back through coeff() (so a restart needs the plugin
   loaded before read_restart, and nothing else). Tables are rebuilt. */
void PairAsperity::write_restart_settings(FILE *fp)
{
  int v[2] = {pulloff_control, maxcontacts};
  fwrite(v, sizeof(int), 2, fp);
}

void PairAsperity::read_restart_settings(FILE *fp)
{
  int v[2] = {0, 0};
  if (comm->me == 0) utils::sfread(FLERR, v, sizeof(int), 2, fp, nullptr, error);
  MPI_Bcast(v, 2, MPI_INT, 0, world);
  set_units();
  pulloff_control = v[0];
  maxcontacts = v[1];
}

void PairAsperity::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  int nt = atom->ntypes;
  for (int i = 1; i <= nt; i++)
    for (int j = i; j <= nt; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const auto &words = coeff_args[i * (nt + 1) + j];
      int n = (int) words.size();
      fwrite(&n, sizeof(int), 1, fp);
      for (const auto &w : words) {
        int bytes = (int) w.size() + 1;
        fwrite(&bytes, sizeof(int), 1, fp);
        fwrite(w.c_str(), 1, bytes, fp);
      }
    }
}

void PairAsperity::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  int nt = atom->ntypes;
  int me = comm->me;
  for (int i = 1; i <= nt; i++)
    for (int j = i; j <= nt; j++) {
      int flag = 0;
      if (me == 0) utils::sfread(FLERR, &flag, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&flag, 1, MPI_INT, 0, world);
      if (!flag) continue;
      int n = 0;
      if (me == 0) utils::sfread(FLERR, &n, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&n, 1, MPI_INT, 0, world);
      std::vector<std::string> words(n);
      for (int k = 0; k < n; k++) {
        int bytes = 0;
        if (me == 0) utils::sfread(FLERR, &bytes, sizeof(int), 1, fp, nullptr, error);
        MPI_Bcast(&bytes, 1, MPI_INT, 0, world);
        std::vector<char> buf(bytes);
        if (me == 0) utils::sfread(FLERR, buf.data(), 1, bytes, fp, nullptr, error);
        MPI_Bcast(buf.data(), bytes, MPI_CHAR, 0, world);
        words[k] = std::string(buf.data());
      }
      std::string si = std::to_string(i), sj = std::to_string(j);
      std::vector<char *> argv = {(char *) si.c_str(), (char *) sj.c_str()};
      for (auto &w : words) argv.push_back((char *) w.c_str());
      coeff((int) argv.size(), argv.data());
    }
}

void *PairAsperity::extract(const char *str, int &dim)
{
  dim = 0;
  if (strcmp(str, "dissipation") == 0) return &dissipated_run;
  return nullptr;
}

void PairAsperity::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  eflag_ = eflag;

  double **x = atom->x;
  double *radius = atom->radius;
  int *type = atom->type;
  tagint *tag = atom->tag;
  int nlocal = atom->nlocal;
  nlocal_ = nlocal;
  int nt = atom->ntypes;
  FixAsperityHistory *h = fix_history;

  for (int i = 0; i < nlocal; i++) h->peratom[i][1] = 0.0;
  // visited[i*maxpartner + k]: contact k of atom i was evaluated this step.
  visited.assign((size_t) nlocal * h->maxpartner, 0);

  int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  items.clear();
  batch_law = -1;

  for (int ii = 0; ii < inum; ii++) {
    int i = ilist[ii];
    int itype = type[i];
    int *jlist = firstneigh[i];
    int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj] & NEIGHMASK;
      int jtype = type[j];
      int tp = std::min(itype, jtype) * (nt + 1) + std::max(itype, jtype);
      const TypePair &t = tps[tp];
      // Evaluate in the orientation of the lower atom ID, so the two ranks
      // that hold a pair across a subdomain boundary do the same arithmetic.
      int lo = i, hi = j;
      if (tag[i] > tag[j]) { lo = j; hi = i; }
      double dx = x[lo][0] - x[hi][0], dy = x[lo][1] - x[hi][1], dz = x[lo][2] - x[hi][2];
      double rsq = dx * dx + dy * dy + dz * dz;
      double radsum = radius[lo] + radius[hi];
      // Out of reach (the common case): nothing to do. A contact that was
      // held and is not visited this step is dropped after the loop.
      double reachsum = radsum - t.reach_max / len;
      if (rsq >= reachsum * reachsum) continue;
      double rr = sqrt(rsq);
      double delta = (radsum - rr) * len;
      double R = radius[lo] * radius[hi] / radsum * len;
      int li = law_for(tp, R);
      if (delta < laws_[li].reach) continue;
      if (li != batch_law || items.size() >= 4096) {
        if (!items.empty()) flush(eflag);
        batch_law = li;
      }
      if (rr == 0.0)
        error->one(FLERR, "pair asperity: atoms {} and {} are at the same position", tag[lo], tag[hi]);
      Item it;
      it.i = lo;
      it.j = hi;
      it.slot_i = (t.history && lo < nlocal) ? h->find(lo, tag[hi]) : -1;
      it.slot_j = (t.history && hi < nlocal) ? h->find(hi, tag[lo]) : -1;
      it.delta = delta;
      double rinv = 1.0 / rr;
      it.n[0] = dx * rinv;
      it.n[1] = dy * rinv;
      it.n[2] = dz * rinv;
      it.r = rr;
      items.push_back(it);
    }
  }
  if (!items.empty()) flush(eflag);
  // Contacts not evaluated this step are out of reach: forget them.
  if (!update->setupflag) {
    for (int i = 0; i < nlocal; i++) {
      int n = h->npartner[i];
      if (!n) continue;
      const char *seen = &visited[(size_t) i * h->maxpartner];
      bool drop = false;
      for (int k = 0; k < n; k++)
        if (!seen[k] || h->partner[i][k] == 0) { h->partner[i][k] = 0; drop = true; }
      if (drop) h->compact(i);
    }
  }

  // pvector: [0] friction dissipation this rank since the style was set
  // (compute pair sums it over ranks), [1] contacts held by this rank's atoms.
  pvector[0] = dissipated_run;
  double contacts = 0.0;
  for (int i = 0; i < nlocal; i++) contacts += h->peratom[i][1];
  pvector[1] = 0.5 * contacts;
}

/* Evaluate the batched pairs (one law), then friction, forces, history. */
void PairAsperity::flush(int eflag)
{
  const int n = (int) items.size();
  const Law law = laws_[batch_law];
  const TypePair &t = tps[law.tp];
  FixAsperityHistory *h = fix_history;
  const int nv = nvalues;
  const bool update_history = !update->setupflag;

  scratch_.resize(nv);
  b_delta.resize(n);
  b_force.resize(n);
  b_radius.resize(n);
  b_old.resize(n);
  b_new.resize(n);
  for (int k = 0; k < n; k++) {
    const Item &it = items[k];
    b_delta[k] = it.delta;
    const double *src = nullptr;
    if (it.slot_i >= 0) src = &h->values[it.i][it.slot_i * nv];
    else if (it.slot_j >= 0) src = &h->values[it.j][it.slot_j * nv];
    if (src) std::memcpy(&b_old[k], src, sizeof(AsperityContactState));
    else std::memset(&b_old[k], 0, sizeof(AsperityContactState));
  }
  int status = law.table
      ? asperity_table_eval_batch(law.table, n, b_delta.data(), b_old.data(), b_new.data(), b_force.data(), b_radius.data(), nullptr)
      : asperity_normal_eval_batch(&law.law, n, b_delta.data(), b_old.data(), b_new.data(), b_force.data(), b_radius.data(), nullptr);
  if (status != ASPERITY_OK) error->one(FLERR, "pair asperity: {}", library_message());

  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **omega = atom->omega, **torque = atom->torque;
  double *radius = atom->radius;
  tagint *tag = atom->tag;
  const int nlocal = nlocal_;
  const double dt_si = update_history ? update->dt * tim : 0.0;
  const double adhesion_offset = (t.c.law != LAW_HERTZ) ? -2.0 * law.pull_off_load : 0.0;
  const int fmodel = t.c.friction;

  for (int k = 0; k < n; k++) {
    const Item &it = items[k];
    const int lo = it.i, hi = it.j;
    const AsperityContactState &st = b_new[k];
    bool fresh = st.in_contact == 0 && st.branch == 0 && st.contact_radius == 0 && st.cohesive_radius == 0;
    if (fresh) {
      if (update_history) {
        if (it.slot_i >= 0) h->partner[lo][it.slot_i] = 0;
        if (it.slot_j >= 0) h->partner[hi][it.slot_j] = 0;
      }
      continue;
    }
    // History slots (created on first contact).
    double *hist = nullptr, *hist2 = nullptr;
    double *scratch = scratch_.data();
    if (update_history && t.history) {
      int si = it.slot_i, sj = it.slot_j;
      if (lo < nlocal && si < 0) si = h->add(lo, tag[hi]);
      if (hi < nlocal && sj < 0) sj = h->add(hi, tag[lo]);
      if (si >= 0) { hist = &h->values[lo][si * nv]; visited[(size_t) lo * h->maxpartner + si] = 1; }
      if (sj >= 0) {
        visited[(size_t) hi * h->maxpartner + sj] = 1;
        if (hist) hist2 = &h->values[hi][sj * nv]; else hist = &h->values[hi][sj * nv];
      }
    } else {
      // Setup: forces from the stored history, nothing written back.
      hist = scratch;
      const double *src = it.slot_i >= 0 ? &h->values[lo][it.slot_i * nv]
          : it.slot_j >= 0 ? &h->values[hi][it.slot_j * nv] : nullptr;
      if (src) std::memcpy(scratch, src, sizeof(double) * nv);
      else std::memset(scratch, 0, sizeof(double) * nv);
    }
    std::memcpy(hist, &st, sizeof(AsperityContactState));

    const double *nrm = it.n;
    double fn = b_force[k] / frc;
    double fx = fn * nrm[0], fy = fn * nrm[1], fz = fn * nrm[2];
    double tx = 0, ty = 0, tz = 0;    // tangential force on lo
    double stored = 0.0, dissipated = 0.0;

    if (fmodel != FRICTION_NONE && nv > NORMAL_VALUES) {
      double *t1 = hist + NORMAL_VALUES;
      double *fst = t1 + FRAME_VALUES;
      if (st.in_contact) {
        double rlo = radius[lo], rhi = radius[hi];
        // Relative velocity of lo against hi at the contact point.
        double wx = rlo * omega[lo][0] + rhi * omega[hi][0];
        double wy = rlo * omega[lo][1] + rhi * omega[hi][1];
        double wz = rlo * omega[lo][2] + rhi * omega[hi][2];
        double vx = v[lo][0] - v[hi][0] - (wy * nrm[2] - wz * nrm[1]);
        double vy = v[lo][1] - v[hi][1] - (wz * nrm[0] - wx * nrm[2]);
        double vz = v[lo][2] - v[hi][2] - (wx * nrm[1] - wy * nrm[0]);
        double vn = vx * nrm[0] + vy * nrm[1] + vz * nrm[2];
        vx -= vn * nrm[0]; vy -= vn * nrm[1]; vz -= vn * nrm[2];
        // The tangent frame turns with the contact: t1 projected on the new
        // tangent plane; a new contact takes any unit tangent.
        double p = t1[0] * nrm[0] + t1[1] * nrm[1] + t1[2] * nrm[2];
        double ax = t1[0] - p * nrm[0], ay = t1[1] - p * nrm[1], az = t1[2] - p * nrm[2];
        double an = sqrt(ax * ax + ay * ay + az * az);
        if (an < 1e-6) {
          double ex = 0, ey = 0, ez = 0;
          double mx = fabs(nrm[0]), my = fabs(nrm[1]), mz = fabs(nrm[2]);
          if (mx <= my && mx <= mz) ex = 1; else if (my <= mz) ey = 1; else ez = 1;
          ax = ey * nrm[2] - ez * nrm[1];
          ay = ez * nrm[0] - ex * nrm[2];
          az = ex * nrm[1] - ey * nrm[0];
          an = sqrt(ax * ax + ay * ay + az * az);
        }
        t1[0] = ax / an; t1[1] = ay / an; t1[2] = az / an;
        double t2[3] = {nrm[1] * t1[2] - nrm[2] * t1[1], nrm[2] * t1[0] - nrm[0] * t1[2],
                        nrm[0] * t1[1] - nrm[1] * t1[0]};
        double dts = update_history ? update->dt : 0.0;
        double s1 = (vx * t1[0] + vy * t1[1] + vz * t1[2]) * dts * len;
        double s2 = (vx * t2[0] + vy * t2[1] + vz * t2[2]) * dts * len;
        // Normal force the friction law sees: P, plus twice the pull-off
        // force for adhesive laws (Thornton and Yin 1991, as LAMMPS granular).
        double nf = b_force[k] + adhesion_offset;
        if (nf < 0) nf = 0;
        // One increment of the contact, whatever the law: its nominal area
        // is the contact area (read by the homogenised law only).
        AsperityFrictionIncrement inc;
        inc.normal_force = nf;
        double a = b_radius[k];
        inc.area = a > 0 ? M_PI * a * a : M_PI * law.radius * law.radius * 1e-12;
        inc.slip[0] = s1;
        inc.slip[1] = s2;
        inc.dt = dt_si;
        inc.tangents = 0;
        inc.reserved = 0;
        AsperityFrictionResponse r;
        status = asperity_friction_step_in_place(t.friction, &inc, fst, friction_work, &r);
        if (status != ASPERITY_OK) error->one(FLERR, "pair asperity: friction step of atoms {} {}: {}", tag[lo], tag[hi], library_message());
        dissipated = r.dissipated;
        // The elastic energy the law stores (the stick spring's |F|^2/(2 kt),
        // the bristles' or elements' springs).
        stored = r.stored_energy;
        double F1 = r.force[0] / frc, F2 = r.force[1] / frc;
        tx = F1 * t1[0] + F2 * t2[0];
        ty = F1 * t1[1] + F2 * t2[1];
        tz = F1 * t1[2] + F2 * t2[2];
      } else {
        // Interacting without contact (a cohesive zone): no friction, and
        // the friction history starts afresh at the next contact.
        std::memset(t1, 0, sizeof(double) * (nv - NORMAL_VALUES));
      }
    }
    if (hist2) std::memcpy(hist2, hist, sizeof(double) * nv);

    double Fx = fx + tx, Fy = fy + ty, Fz = fz + tz;
    double rlo = radius[lo], rhi = radius[hi];
    // Torques from the tangential force at the contact point.
    double cx = nrm[1] * tz - nrm[2] * ty, cy = nrm[2] * tx - nrm[0] * tz, cz = nrm[0] * ty - nrm[1] * tx;
    double dlo = dissipated / eng;
    if (lo < nlocal) {
      f[lo][0] += Fx; f[lo][1] += Fy; f[lo][2] += Fz;
      torque[lo][0] -= rlo * cx; torque[lo][1] -= rlo * cy; torque[lo][2] -= rlo * cz;
      if (update_history) h->peratom[lo][0] += 0.5 * dlo;
      if (st.in_contact) h->peratom[lo][1] += 1.0;
    }
    if (hi < nlocal) {
      f[hi][0] -= Fx; f[hi][1] -= Fy; f[hi][2] -= Fz;
      torque[hi][0] -= rhi * cx; torque[hi][1] -= rhi * cy; torque[hi][2] -= rhi * cz;
      if (update_history) h->peratom[hi][0] += 0.5 * dlo;
      if (st.in_contact) h->peratom[hi][1] += 1.0;
    }
    if (update_history) dissipated_run += 0.5 * dlo * ((lo < nlocal) + (hi < nlocal));

    if (evflag) {
      double evdwl = 0.0;
      if (eflag) {
        double u = 0.0;
        if (t.energy) {
          status = asperity_normal_energy(&law.law, it.delta, &b_old[k], &u);
          if (status != ASPERITY_OK) u = 0.0;
        }
        evdwl = (u + stored) / eng;
      }
      ev_tally_xyz(lo, hi, nlocal, 0, evdwl, 0.0, Fx, Fy, Fz, x[lo][0] - x[hi][0], x[lo][1] - x[hi][1], x[lo][2] - x[hi][2]);
    }
  }
  items.clear();
}

double PairAsperity::memory_usage()
{
  return Pair::memory_usage() + items.capacity() * sizeof(Item) +
      b_old.capacity() * 2 * sizeof(AsperityContactState) + b_delta.capacity() * 3 * sizeof(double);
}
