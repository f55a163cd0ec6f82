/* Quick start (README): a JKR sphere from C, one loading step and the pull-off. */
#include "asperity.h"
#include <math.h>
#include <stdio.h>

int main(void)
{
    AsperityNormalLaw law;
    AsperityContactState old_state = {0}, new_state; /* all-zero: never touched */
    AsperityNormalResponse r;
    double pull_off;
    char msg[256];
    /* R = 1 µm, E* = 1 GPa, w = 0.05 J/m² (SI units throughout). */
    if (asperity_law_jkr(1e-6, 1e9, 0.05, &law) != ASPERITY_OK ||
        asperity_normal_eval(&law, 2e-9, &old_state, &new_state, &r) != ASPERITY_OK ||
        asperity_pull_off_force(&law, ASPERITY_CONTROL_LOAD, &pull_off) != ASPERITY_OK) {
        asperity_last_error_message(msg, sizeof msg);
        fprintf(stderr, "asperity: %s\n", msg);
        return 1;
    }
    printf("delta = 2 nm: force %.4g N, contact radius %.4g m\n", r.force, r.contact_radius);
    printf("pull-off (load control) %.6g N = %.6f pi w R\n", pull_off,
           pull_off / (3.14159265358979323846 * 0.05 * 1e-6));
    /* A bad argument is refused with a message naming it. */
    if (asperity_law_jkr(-1e-6, 1e9, 0.05, &law) == ASPERITY_OK) {
        return 1;
    }
    asperity_last_error_message(msg, sizeof msg);
    printf("negative radius: %s\n", msg);
    return fabs(pull_off / (3.14159265358979323846 * 0.05 * 1e-6) + 1.5) < 1e-9 ? 0 : 1;
}
