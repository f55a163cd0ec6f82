/*
 * Pull-off force of an adhesive sphere against the Maugis parameter lambda:
 * DMT (lambda -> 0), Maugis-Dugdale, JKR (lambda -> infinity), under load
 * control and displacement control, in units of pi w R; then one
 * Maugis-Dugdale force-approach curve at lambda = 1.
 *
 * For each lambda the Dugdale cohesive stress is chosen as
 *     sigma0 = (lambda / 2) (pi w K^2 / R)^(1/3),  K = 4 E* / 3,
 * and checked against asperity_maugis_parameter.
 *
 * A law that fails is reported and shown as "n/a"; the program goes on with
 * the others and exits with status 1 at the end. Lines "CHECK <name> <value>"
 * and the curve rows ("approach"/"retract") are read by tests/c_examples.rs.
 */
#include "asperity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

#define N_LAMBDA 13

static int failed(int32_t status, const char *what)
{
    char msg[512];
    if (status == ASPERITY_OK) {
        return 0;
    }
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "pull_off_table: %s failed: status %d (%s): %s\n", what, (int)status,
            asperity_status_string(status), msg);
    return 1;
}

/* Evaluate `call`; on failure report it, count it and run `on_fail`. */
#define TRY_OR(call, on_fail)                                                              \
    do {                                                                                   \
        if (failed((call), #call)) {                                                       \
            ++failures;                                                                    \
            on_fail;                                                                       \
        }                                                                                  \
    } while (0)

static void check(const char *name, double value)
{
    printf("CHECK %s %.17g\n", name, value);
}

static void cell(double value, int ok)
{
    if (ok) {
        printf(" %9.4f", value);
    } else {
        printf(" %9s", "n/a");
    }
}

int main(void)
{
    const double radius = 1e-6; /* m */
    const double work = 0.05;   /* J/m^2 */
    const double e_star = 1e9;  /* Pa */
    const double k = 4.0 * e_star / 3.0;
    const double piwr = PI * work * radius;
    const double sigma_unit = cbrt(PI * work * k * k / radius); /* sigma0 = lambda/2 * this */
    /* Reduced approach: Delta = delta (K^2 / (pi^2 w^2 R))^(1/3); contact radius
     * A = a (K / (pi w R^2))^(1/3). */
    const double delta_unit = cbrt(PI * PI * work * work * radius / (k * k));
    const double a_unit = cbrt(PI * work * radius * radius / k);

    int failures = 0;
    int dmt_ok = 1, jkr_ok = 1, i;
    int md_ok[N_LAMBDA];
    double lambda[N_LAMBDA], sigma0[N_LAMBDA], md_load[N_LAMBDA], md_disp[N_LAMBDA];
    double dmt_load = 0.0, dmt_disp = 0.0, jkr_load = 0.0, jkr_disp = 0.0;
    double lambda_err = 0.0;
    AsperityNormalLaw dmt, jkr, md;

    printf("Pull-off force of an adhesive sphere, P_c / (pi w R)\n");
    printf("R = %g m, w = %g J/m^2, E* = %g Pa (library %s)\n", radius, work, e_star,
           asperity_version());
    printf("theory: DMT -2 (both controls); JKR -3/2 (load), -5/6 (displacement)\n\n");

    TRY_OR(asperity_law_dmt(radius, e_star, work, &dmt), dmt_ok = 0);
    if (dmt_ok) {
        TRY_OR(asperity_pull_off_force(&dmt, ASPERITY_CONTROL_LOAD, &dmt_load), dmt_ok = 0);
    }
    if (dmt_ok) {
        TRY_OR(asperity_pull_off_force(&dmt, ASPERITY_CONTROL_DISPLACEMENT, &dmt_disp),
               dmt_ok = 0);
    }
    TRY_OR(asperity_law_jkr(radius, e_star, work, &jkr), jkr_ok = 0);
    if (jkr_ok) {
        TRY_OR(asperity_pull_off_force(&jkr, ASPERITY_CONTROL_LOAD, &jkr_load), jkr_ok = 0);
    }
    if (jkr_ok) {
        TRY_OR(asperity_pull_off_force(&jkr, ASPERITY_CONTROL_DISPLACEMENT, &jkr_disp),
               jkr_ok = 0);
    }

    for (i = 0; i < N_LAMBDA; ++i) {
        double check_lambda = 0.0;
        lambda[i] = pow(10.0, -2.0 + i / 3.0);
        sigma0[i] = 0.5 * lambda[i] * sigma_unit;
        md_ok[i] = 1;
        TRY_OR(asperity_maugis_parameter(radius, work, e_star, sigma0[i], &check_lambda),
               check_lambda = NAN);
        if (fabs(check_lambda / lambda[i] - 1.0) > lambda_err || isnan(check_lambda)) {
            lambda_err = isnan(check_lambda) ? INFINITY : fabs(check_lambda / lambda[i] - 1.0);
        }
        TRY_OR(asperity_law_maugis_dugdale(radius, e_star, work, sigma0[i], &md), md_ok[i] = 0);
        if (md_ok[i]) {
            TRY_OR(asperity_pull_off_force(&md, ASPERITY_CONTROL_LOAD, &md_load[i]),
                   md_ok[i] = 0);
        }
        if (md_ok[i]) {
            TRY_OR(asperity_pull_off_force(&md, ASPERITY_CONTROL_DISPLACEMENT, &md_disp[i]),
                   md_ok[i] = 0);
        }
    }

    printf("%9s %11s | %29s | %29s\n", "", "", "load control", "displacement control");
    printf("%9s %11s | %9s %9s %9s | %9s %9s %9s\n", "lambda", "sigma0 (Pa)", "DMT", "M-D",
           "JKR", "DMT", "M-D", "JKR");
    for (i = 0; i < N_LAMBDA; ++i) {
        printf("%9.4g %11.4e |", lambda[i], sigma0[i]);
        cell(dmt_load / piwr, dmt_ok);
        cell(md_load[i] / piwr, md_ok[i]);
        cell(jkr_load / piwr, jkr_ok);
        printf(" |");
        cell(dmt_disp / piwr, dmt_ok);
        cell(md_disp[i] / piwr, md_ok[i]);
        cell(jkr_disp / piwr, jkr_ok);
        printf("\n");
    }

    /* One Maugis-Dugdale force-approach curve at lambda = 1, displacement control. */
    printf("\nMaugis-Dugdale, lambda = 1: force-approach curve under displacement control\n");
    printf("(reduced units: Delta = delta (K^2/(pi^2 w^2 R))^(1/3), P/(pi w R), "
           "A = a (K/(pi w R^2))^(1/3), C = c likewise)\n");
    {
        int ok = 1, j;
        const double s0 = 0.5 * 1.0 * sigma_unit;
        AsperityContactState old_state, new_state;
        AsperityNormalResponse r;
        double min_force = 0.0;
        TRY_OR(asperity_law_maugis_dugdale(radius, e_star, work, s0, &md), ok = 0);
        memset(&old_state, 0, sizeof old_state);
        if (ok) {
            printf("%-8s %8s %9s %9s %9s %s\n", "phase", "Delta", "P/(piwR)", "A", "C",
                   "in_contact");
        }
        /* 31 steps in: Delta = -1.5 .. 1.5; 31 steps out: 1.45 .. -1.55. */
        for (j = 0; ok && j < 62; ++j) {
            const int in = j < 31;
            const double big_delta = in ? -1.5 + 0.1 * j : 1.45 - 0.1 * (j - 31);
            TRY_OR(asperity_normal_eval(&md, big_delta * delta_unit, &old_state, &new_state,
                                        &r),
                   ok = 0);
            if (!ok) {
                break;
            }
            printf("%-8s %8.4f %9.5f %9.5f %9.5f %d\n", in ? "approach" : "retract", big_delta,
                   r.force / piwr, r.contact_radius / a_unit,
                   new_state.cohesive_radius / a_unit, (int)r.in_contact);
            if (!in && r.force < min_force) {
                min_force = r.force;
            }
            old_state = new_state;
        }
        if (ok) {
            check("md_curve_min_force_over_piwR", min_force / piwr);
        }
    }

    printf("\n");
    check("maugis_parameter_max_rel_err", lambda_err);
    if (dmt_ok) {
        check("dmt_pull_off_load_over_piwR", dmt_load / piwr);
        check("dmt_pull_off_displacement_over_piwR", dmt_disp / piwr);
    }
    if (jkr_ok) {
        check("jkr_pull_off_load_over_piwR", jkr_load / piwr);
        check("jkr_pull_off_displacement_over_piwR", jkr_disp / piwr);
    }
    for (i = 0; i < N_LAMBDA; ++i) {
        if (md_ok[i]) {
            printf("CHECK md_pull_off_load_over_piwR@%.17g %.17g\n", lambda[i],
                   md_load[i] / piwr);
            printf("CHECK md_pull_off_displacement_over_piwR@%.17g %.17g\n", lambda[i],
                   md_disp[i] / piwr);
        }
    }
    if (failures > 0) {
        fprintf(stderr, "pull_off_table: %d call(s) failed\n", failures);
        return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
}
