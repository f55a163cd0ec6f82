/*
 * JKR sphere under displacement control: approach, then retraction.
 *
 * The host code owns the per-contact history (AsperityContactState) and keeps
 * the state at the start of the step ("old") apart from the state at its end
 * ("new"); it accepts a step by copying new -> old. On approach the contact
 * forms at delta = 0 with a jump to a finite radius (jump-in); on retraction it
 * stays stuck down to the negative critical approach delta_c and then snaps off
 * (jump-out). Between delta_c and 0 the force depends on the history: that is
 * the adhesion hysteresis.
 *
 * Numbers: the worked example of REFERENCE.md section 8,
 * R = 1 um, w = 0.05 J/m^2, E* = 1 GPa.
 *
 * Lines "CHECK <name> <value>" are read by tests/c_examples.rs, as are the
 * table rows starting with "approach" or "retract".
 */
#include "asperity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* Report a failed call with the library's message; 0 when `status` is OK. */
static int failed(int32_t status, const char *what)
{
    char msg[512];
    if (status == ASPERITY_OK) {
        return 0;
    }
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "jkr_hysteresis: %s failed: status %d (%s): %s\n", what, (int)status,
            asperity_status_string(status), msg);
    return 1;
}

#define TRY(call)                                                                          \
    do {                                                                                   \
        if (failed((call), #call)) {                                                       \
            return EXIT_FAILURE;                                                           \
        }                                                                                  \
    } while (0)

static void check(const char *name, double value)
{
    printf("CHECK %s %.17g\n", name, value);
}

static void row(const char *phase, double delta, double abs_dc, double force, double piwr,
                const AsperityNormalResponse *r, const char *mark)
{
    printf("%-8s % .6e % 8.4f % .6e % 8.4f % .6e %d%s\n", phase, delta, delta / abs_dc, force,
           force / piwr, r->contact_radius, (int)r->in_contact, mark);
}

int main(void)
{
    const double radius = 1e-6; /* m */
    const double work = 0.05;   /* J/m^2 */
    const double e_star = 1e9;  /* Pa */
    const double piwr = PI * work * radius;
    /* Closed forms (REFERENCE.md section 1). */
    const double delta_c = -0.75 * cbrt(PI * PI * work * work * radius / (e_star * e_star));
    const double abs_dc = fabs(delta_c);
    const double a_jump = cbrt(2.0 * PI * work * radius * radius / e_star);
    const double h = abs_dc / 20.0; /* approach step */
    const int n_approach_lo = -20, n_approach_hi = 40;
    const int n_retract = 62;

    AsperityNormalLaw law;
    AsperityContactState old_state, new_state, saved;
    AsperityNormalResponse r, r2;
    double p_load, p_disp, min_force = 0.0;
    double jump_in_delta = NAN, last_contact = NAN, first_free = NAN;
    int old_unchanged = 1, reeval_identical = 1;
    int i;

    TRY(asperity_law_jkr(radius, e_star, work, &law));

    printf("JKR sphere: R = %g m, w = %g J/m^2, E* = %g Pa, library %s\n", radius, work, e_star,
           asperity_version());
    printf("pi w R = %.6e N, critical approach delta_c = %.6e m, jump-in radius %.6e m\n\n",
           piwr, delta_c, a_jump);

    /* Pull-off under both controls. */
    TRY(asperity_pull_off_force(&law, ASPERITY_CONTROL_LOAD, &p_load));
    TRY(asperity_pull_off_force(&law, ASPERITY_CONTROL_DISPLACEMENT, &p_disp));
    printf("pull-off, load control:         %.6e N = %.6f pi w R (theory -3/2)\n", p_load,
           p_load / piwr);
    printf("pull-off, displacement control: %.6e N = %.6f pi w R (theory -5/6)\n\n", p_disp,
           p_disp / piwr);

    printf("%-8s %13s %8s %13s %8s %13s %s\n", "phase", "delta (m)", "d/|d_c|", "force (N)",
           "P/(piwR)", "a (m)", "in_contact");

    /* Approach from out of range, accepting every step. */
    memset(&old_state, 0, sizeof old_state); /* all-zero: never touched */
    for (i = n_approach_lo; i <= n_approach_hi; ++i) {
        const double delta = i * h;
        const char *mark = "";
        saved = old_state;
        TRY(asperity_normal_eval(&law, delta, &old_state, &new_state, &r));
        if (memcmp(&saved, &old_state, sizeof saved) != 0) {
            old_unchanged = 0;
        }
        if (!old_state.in_contact && new_state.in_contact) {
            mark = "   <- jump-in";
            if (isnan(jump_in_delta)) {
                jump_in_delta = delta;
            }
        }
        row("approach", delta, abs_dc, r.force, piwr, &r, mark);
        old_state = new_state; /* accept the step */
    }

    /* Retraction, on a grid offset by h/2 so that delta_c falls between points. */
    for (i = 0; i < n_retract; ++i) {
        const double delta = (n_approach_hi - 0.5 - i) * h;
        const char *mark = "";
        saved = old_state;
        TRY(asperity_normal_eval(&law, delta, &old_state, &new_state, &r));
        if (memcmp(&saved, &old_state, sizeof saved) != 0) {
            old_unchanged = 0;
        }
        /* A host may re-evaluate (cut back) a step: same old state, same answer. */
        TRY(asperity_normal_eval(&law, delta, &old_state, &saved, &r2));
        if (memcmp(&r, &r2, sizeof r) != 0 || memcmp(&saved, &new_state, sizeof saved) != 0) {
            reeval_identical = 0;
        }
        if (old_state.in_contact && !new_state.in_contact) {
            mark = "   <- jump-out";
            if (isnan(first_free)) {
                first_free = delta;
            }
        }
        if (new_state.in_contact) {
            last_contact = delta;
        }
        if (r.force < min_force) {
            min_force = r.force;
        }
        row("retract", delta, abs_dc, r.force, piwr, &r, mark);
        old_state = new_state;
    }

    /* Jump-in from a fresh state just past delta = 0. */
    memset(&old_state, 0, sizeof old_state);
    TRY(asperity_normal_eval(&law, -1e-9 * abs_dc, &old_state, &new_state, &r));
    check("jkr_fresh_just_outside_in_contact", r.in_contact);
    TRY(asperity_normal_eval(&law, 1e-9 * abs_dc, &old_state, &new_state, &r));
    printf("\njump-in at delta = 0+: a = %.6e m (theory %.6e m), P = %.6f pi w R (theory "
           "-4/3)\n",
           r.contact_radius, a_jump, r.force / piwr);
    printf("jump-out between delta = %.6e m and %.6e m (theory delta_c = %.6e m)\n",
           last_contact, first_free, delta_c);
    printf("most adhesive force on retraction: %.6f pi w R (theory -3/2)\n\n", min_force / piwr);

    check("jkr_delta_c_m", delta_c);
    check("jkr_pull_off_load_N", p_load);
    check("jkr_pull_off_load_over_piwR", p_load / piwr);
    check("jkr_pull_off_displacement_over_piwR", p_disp / piwr);
    check("jkr_jump_in_delta_over_abs_delta_c", jump_in_delta / abs_dc);
    check("jkr_jump_in_radius_over_theory", r.contact_radius / a_jump);
    check("jkr_jump_in_force_over_piwR", r.force / piwr);
    check("jkr_jump_in_in_contact", r.in_contact);
    check("jkr_last_contact_delta_over_abs_delta_c", last_contact / abs_dc);
    check("jkr_first_free_delta_over_abs_delta_c", first_free / abs_dc);
    check("jkr_min_force_retraction_over_piwR", min_force / piwr);
    check("jkr_old_state_unchanged", old_unchanged);
    check("jkr_reeval_identical", reeval_identical);
    return EXIT_SUCCESS;
}
