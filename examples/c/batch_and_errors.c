/*
 * Batch evaluation and error handling through the C ABI.
 *
 * 1. asperity_normal_eval_batch over arrays of contacts (a Hertz and a DMT
 *    sphere), compared with the scalar call and the closed forms.
 * 2. A bad call (negative radius): its status, asperity_status_string, and
 *    asperity_last_error_message, sized with (NULL, 0) first.
 * 3. A batch with a bad element: the message names the element, earlier
 *    outputs are written.
 *
 * Lines "CHECK <name> <value>" are read by tests/c_examples.rs.
 */
#include "asperity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

#define N 8

static int failed(int32_t status, const char *what)
{
    char msg[512];
    if (status == ASPERITY_OK) {
        return 0;
    }
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "batch_and_errors: %s failed: status %d (%s): %s\n", what, (int)status,
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

static double rel_err(double got, double want)
{
    const double scale = fabs(want) > 0.0 ? fabs(want) : 1.0;
    return fabs(got - want) / scale;
}

/* Run a batch and the scalar calls; return the largest difference between them. */
static int batch_vs_scalar(const AsperityNormalLaw *law, const double *delta, double *force,
                           double *radius, double *stiffness, double *max_diff)
{
    AsperityContactState old_state[N], new_state[N];
    int i;
    memset(old_state, 0, sizeof old_state);
    *max_diff = 0.0;
    if (failed(asperity_normal_eval_batch(law, N, delta, old_state, new_state, force, radius,
                                          stiffness),
               "asperity_normal_eval_batch")) {
        return 1;
    }
    for (i = 0; i < N; ++i) {
        AsperityNormalResponse r;
        if (failed(asperity_normal_eval(law, delta[i], &old_state[i], NULL, &r),
                   "asperity_normal_eval")) {
            return 1;
        }
        *max_diff = fmax(*max_diff, fabs(r.force - force[i]));
        *max_diff = fmax(*max_diff, fabs(r.contact_radius - radius[i]));
        *max_diff = fmax(*max_diff, fabs(r.stiffness - stiffness[i]));
        if (new_state[i].in_contact != r.in_contact) {
            *max_diff = INFINITY;
        }
    }
    return 0;
}

int main(void)
{
    const double radius = 1e-6, e_star = 1e9, work = 0.05;
    const double delta[N] = {-2e-9, -1e-10, 0.0, 1e-10, 5e-10, 1e-9, 5e-9, 2e-8};
    double force[N], a[N], k[N], diff, err_f = 0.0, err_a = 0.0, err_k = 0.0;
    AsperityNormalLaw hertz, dmt, bad;
    int32_t status;
    size_t len, got;
    char *msg;
    char small[16];
    int i;

    printf("asperity %s (header %d.%d.%d)\n", asperity_version(), ASPERITY_VERSION_MAJOR,
           ASPERITY_VERSION_MINOR, ASPERITY_VERSION_PATCH);
    {
        char v[64];
        sprintf(v, "%d.%d.%d", ASPERITY_VERSION_MAJOR, ASPERITY_VERSION_MINOR,
                ASPERITY_VERSION_PATCH);
        check("version_matches_header", strcmp(v, asperity_version()) == 0);
    }

    /* 1. Batches. */
    TRY(asperity_law_hertz(radius, e_star, &hertz));
    TRY(asperity_law_dmt(radius, e_star, work, &dmt));

    if (batch_vs_scalar(&hertz, delta, force, a, k, &diff)) {
        return EXIT_FAILURE;
    }
    printf("\nHertz sphere R = %g m, E* = %g Pa\n", radius, e_star);
    printf("%12s %14s %14s %14s\n", "delta (m)", "force (N)", "a (m)", "dP/ddelta (N/m)");
    for (i = 0; i < N; ++i) {
        const double d = delta[i] > 0.0 ? delta[i] : 0.0;
        const double a_ref = sqrt(radius * d);
        printf("%12.4e %14.6e %14.6e %14.6e\n", delta[i], force[i], a[i], k[i]);
        err_f = fmax(err_f, rel_err(force[i], 4.0 / 3.0 * e_star * sqrt(radius) * pow(d, 1.5)));
        err_a = fmax(err_a, rel_err(a[i], a_ref));
        err_k = fmax(err_k, rel_err(k[i], 2.0 * e_star * a_ref));
    }
    check("hertz_batch_vs_scalar_max_abs_diff", diff);
    check("hertz_batch_force_max_rel_err", err_f);
    check("hertz_batch_radius_max_rel_err", err_a);
    check("hertz_batch_stiffness_max_rel_err", err_k);

    if (batch_vs_scalar(&dmt, delta, force, a, k, &diff)) {
        return EXIT_FAILURE;
    }
    err_f = 0.0;
    printf("\nDMT sphere R = %g m, E* = %g Pa, w = %g J/m^2 (pull-off -2 pi w R = %.6e N)\n",
           radius, e_star, work, -2.0 * PI * work * radius);
    printf("%12s %14s %14s\n", "delta (m)", "force (N)", "a (m)");
    for (i = 0; i < N; ++i) {
        double want = 0.0;
        if (delta[i] >= 0.0) {
            want = 4.0 / 3.0 * e_star * sqrt(radius) * pow(delta[i], 1.5) -
                   2.0 * PI * work * radius;
        }
        printf("%12.4e %14.6e %14.6e\n", delta[i], force[i], a[i]);
        err_f = fmax(err_f, rel_err(force[i], want));
    }
    check("dmt_batch_vs_scalar_max_abs_diff", diff);
    check("dmt_batch_force_max_rel_err", err_f);

    /* In-place batch: the force array is also the delta array. */
    {
        double inout[N];
        memcpy(inout, delta, sizeof inout);
        TRY(asperity_normal_eval_batch(&hertz, N, inout, NULL, NULL, inout, NULL, NULL));
        diff = 0.0;
        for (i = 0; i < N; ++i) {
            const double d = delta[i] > 0.0 ? delta[i] : 0.0;
            diff = fmax(diff, rel_err(inout[i], 4.0 / 3.0 * e_star * sqrt(radius) * pow(d, 1.5)));
        }
        check("hertz_in_place_force_max_rel_err", diff);
    }

    /* 2. A bad call: negative radius. */
    printf("\nerror handling\n");
    status = asperity_law_hertz(-1e-6, e_star, &bad);
    printf("asperity_law_hertz(-1e-6, ...) -> %d (%s)\n", (int)status,
           asperity_status_string(status));
    check("bad_radius_status", status);
    check("bad_radius_status_is_invalid_argument", status == ASPERITY_ERR_INVALID_ARGUMENT);
    len = asperity_last_error_message(NULL, 0);
    msg = malloc(len + 1);
    if (msg == NULL) {
        fprintf(stderr, "batch_and_errors: out of memory\n");
        return EXIT_FAILURE;
    }
    got = asperity_last_error_message(msg, len + 1);
    printf("message: %s\n", msg);
    check("message_length", (double)len);
    check("message_length_consistent", got == len && strlen(msg) == len);
    check("message_names_radius", strstr(msg, "radius") != NULL);
    /* A buffer that is too small: truncated, NUL-terminated, full length returned. */
    got = asperity_last_error_message(small, sizeof small);
    printf("truncated to %d bytes: \"%s\"\n", (int)sizeof small, small);
    check("truncated_strlen", (double)strlen(small));
    check("truncated_returns_full_length", got == len);
    check("truncated_is_prefix", strncmp(small, msg, sizeof small - 1) == 0);
    free(msg);

    /* A NULL out pointer. */
    status = asperity_law_hertz(radius, e_star, NULL);
    printf("asperity_law_hertz(..., NULL) -> %d (%s)\n", (int)status,
           asperity_status_string(status));
    check("null_out_status", status);

    /* Every status code has a description. */
    for (i = ASPERITY_OK; i >= ASPERITY_ERR_INTERNAL; --i) {
        printf("status %2d: %s\n", i, asperity_status_string(i));
    }
    printf("status %2d: %s\n", 42, asperity_status_string(42));

    /* 3. A batch with a bad element: NaN at element 5. */
    {
        double d[N], f[N];
        memcpy(d, delta, sizeof d);
        for (i = 0; i < N; ++i) {
            f[i] = -1.0; /* sentinel */
        }
        d[5] = NAN;
        status = asperity_normal_eval_batch(&hertz, N, d, NULL, NULL, f, NULL, NULL);
        len = asperity_last_error_message(NULL, 0);
        msg = malloc(len + 1);
        if (msg == NULL) {
            fprintf(stderr, "batch_and_errors: out of memory\n");
            return EXIT_FAILURE;
        }
        asperity_last_error_message(msg, len + 1);
        printf("batch with NaN at element 5 -> %d (%s): %s\n", (int)status,
               asperity_status_string(status), msg);
        check("batch_error_status", status);
        check("batch_error_names_element", strstr(msg, "element 5") != NULL);
        {
            int written = 0;
            for (i = 0; i < 5; ++i) {
                written += f[i] >= 0.0;
            }
            check("batch_error_outputs_written_before", written);
            check("batch_error_sentinel_after", f[6] == -1.0 && f[7] == -1.0);
        }
        free(msg);
    }
    return EXIT_SUCCESS;
}
