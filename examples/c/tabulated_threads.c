/*
 * A tabulated Maugis-Dugdale law in an MD-style loop, on several threads.
 *
 * One table is built once (asperity_table_new_maugis_dugdale) and shared,
 * read-only, by every thread. Each of N_PAIRS sphere pairs follows its own
 * sinusoidal approach history for N_STEPS steps, from far apart through
 * jump-in, deep contact and back through jump-out; the host owns one
 * AsperityContactState per pair and keeps old and new states apart.
 *
 * The loop runs twice: single-threaded with scalar calls
 * (asperity_table_eval), then on N_THREADS pthreads, each over its own block
 * of pairs with one batch call per step (asperity_table_eval_batch). The
 * results must be bitwise identical. A subset of pairs is also run with the
 * closed-form Maugis-Dugdale law (asperity_normal_eval): same branches, same
 * in-contact sequence, forces within the table's stated tolerance.
 *
 * Lines "CHECK <name> <value>" are read by tests/c_examples.rs.
 */
#define _POSIX_C_SOURCE 200112L

#include "asperity.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N_PAIRS 10000
#define N_STEPS 100
#define N_THREADS 4
#define MD_EVERY 20

static const double PI = 3.14159265358979323846;

/* Sphere: R = 1 um, E* = 1 GPa, w = 0.05 J/m^2, Maugis parameter 2. */
static const double R = 1e-6, E_STAR = 1e9, W = 0.05, LAMBDA = 2.0;

static int failed(int32_t status, const char *what)
{
    char msg[512];
    if (status == ASPERITY_OK) {
        return 0;
    }
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "tabulated_threads: %s failed: status %d (%s): %s\n", what, (int)status,
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

/* Approach of pair i at step s (m): a sinusoid around a pair-dependent mean,
 * spanning far separation to a few overlap units of compression. */
static double approach(int i, int s, double unit)
{
    double mean = (0.5 + 1.5 * (double)(i % 97) / 97.0) * unit;
    double amp = (2.5 + 2.0 * (double)(i % 89) / 89.0) * unit;
    double phase = 2.0 * PI * (double)(i % 101) / 101.0;
    double period = 25.0 + (double)(i % 13);
    return mean + amp * sin(2.0 * PI * (double)s / period + phase);
}

struct work {
    const AsperityTable *table;
    double unit;
    int first, last;
    double *force;   /* [N_STEPS][N_PAIRS] */
    double *radius;  /* [N_STEPS][N_PAIRS] */
    AsperityContactState *state; /* [N_PAIRS], updated in place */
    int status;
};

static void *run_block(void *arg)
{
    struct work *w = (struct work *)arg;
    int n = w->last - w->first;
    double *delta = (double *)malloc((size_t)n * sizeof *delta);
    int s, i;
    w->status = delta ? ASPERITY_OK : -100;
    for (s = 0; s < N_STEPS && w->status == ASPERITY_OK; ++s) {
        size_t row = (size_t)s * N_PAIRS + (size_t)w->first;
        for (i = 0; i < n; ++i) {
            delta[i] = approach(w->first + i, s, w->unit);
        }
        /* Old and new states may alias: the step is accepted at once. */
        w->status = asperity_table_eval_batch(w->table, (size_t)n, delta, w->state + w->first,
                                              w->state + w->first, w->force + row,
                                              w->radius + row, NULL);
    }
    free(delta);
    return NULL;
}

int main(void)
{
    AsperityTable *table = NULL, *loaded = NULL;
    AsperityNormalLaw md;
    AsperityNormalResponse r, rc;
    AsperityContactState old_s, new_s;
    double k = 4.0 * E_STAR / 3.0;
    double sigma0 = 0.5 * LAMBDA * cbrt(PI * W * k * k / R);
    double unit, tol, measured, pc_table, pc_md, pd_table, pd_md, a_c, f_floor, a_floor;
    size_t total = (size_t)N_PAIRS * N_STEPS, needed = 0;
    double *f1 = (double *)malloc(total * sizeof *f1), *a1 = (double *)malloc(total * sizeof *a1);
    double *f2 = (double *)malloc(total * sizeof *f2), *a2 = (double *)malloc(total * sizeof *a2);
    AsperityContactState *st1 = (AsperityContactState *)calloc(N_PAIRS, sizeof *st1);
    AsperityContactState *st2 = (AsperityContactState *)calloc(N_PAIRS, sizeof *st2);
    struct work w[N_THREADS];
    pthread_t th[N_THREADS];
    char *json;
    int i, s, t, identical;
    long jumps_in = 0, jumps_out = 0, branch_mismatch = 0, contact_mismatch = 0, compared = 0;
    double max_err = 0.0, max_rad_err = 0.0;

    if (!f1 || !a1 || !f2 || !a2 || !st1 || !st2) {
        fprintf(stderr, "tabulated_threads: out of memory\n");
        return EXIT_FAILURE;
    }
    TRY(asperity_table_new_maugis_dugdale(R, E_STAR, W, sigma0, 1e-4, &table));
    TRY(asperity_law_maugis_dugdale(R, E_STAR, W, sigma0, &md));
    TRY(asperity_law_length_scale(&md, &unit));
    TRY(asperity_table_max_error(table, &tol, &measured));
    check("table_tolerance", tol);
    check("table_measured_error", measured);

    /* Pull-off forces: exact from the curve. */
    TRY(asperity_table_pull_off_force(table, ASPERITY_CONTROL_LOAD, &pc_table));
    TRY(asperity_pull_off_force(&md, ASPERITY_CONTROL_LOAD, &pc_md));
    TRY(asperity_table_pull_off_force(table, ASPERITY_CONTROL_DISPLACEMENT, &pd_table));
    TRY(asperity_pull_off_force(&md, ASPERITY_CONTROL_DISPLACEMENT, &pd_md));
    check("pull_off_load_rel_diff", fabs(pc_table - pc_md) / fabs(pc_md));
    check("pull_off_displacement_rel_diff", fabs(pd_table - pd_md) / fabs(pd_md));
    TRY(asperity_normal_eval_at_load(&md, pc_md, &r));
    a_c = r.contact_radius;
    f_floor = 1e-3 * fabs(pc_md);
    a_floor = 1e-3 * a_c;

    /* 1. Single-threaded, scalar calls. */
    for (s = 0; s < N_STEPS; ++s) {
        for (i = 0; i < N_PAIRS; ++i) {
            size_t j = (size_t)s * N_PAIRS + (size_t)i;
            TRY(asperity_table_eval(table, approach(i, s, unit), &st1[i], &new_s, &r));
            if (new_s.branch > st1[i].branch) {
                ++jumps_in;
            } else if (new_s.branch < st1[i].branch) {
                ++jumps_out;
            }
            st1[i] = new_s;
            f1[j] = r.force;
            a1[j] = r.contact_radius;
        }
    }

    /* 2. The same loop on N_THREADS threads sharing the table, batch calls. */
    for (t = 0; t < N_THREADS; ++t) {
        w[t].table = table;
        w[t].unit = unit;
        w[t].first = t * N_PAIRS / N_THREADS;
        w[t].last = (t + 1) * N_PAIRS / N_THREADS;
        w[t].force = f2;
        w[t].radius = a2;
        w[t].state = st2;
        w[t].status = -100;
        if (pthread_create(&th[t], NULL, run_block, &w[t]) != 0) {
            fprintf(stderr, "tabulated_threads: pthread_create failed\n");
            return EXIT_FAILURE;
        }
    }
    for (t = 0; t < N_THREADS; ++t) {
        pthread_join(th[t], NULL);
        TRY(w[t].status);
    }
    identical = memcmp(f1, f2, total * sizeof *f1) == 0 &&
                memcmp(a1, a2, total * sizeof *a1) == 0 &&
                memcmp(st1, st2, N_PAIRS * sizeof *st1) == 0;
    check("threads_identical", identical);
    check("jumps_in", (double)jumps_in);
    check("jumps_out", (double)jumps_out);

    /* 3. Every MD_EVERY-th pair with the closed-form law. */
    for (i = 0; i < N_PAIRS; i += MD_EVERY) {
        AsperityContactState sm, stt;
        memset(&sm, 0, sizeof sm);
        memset(&stt, 0, sizeof stt);
        for (s = 0; s < N_STEPS; ++s) {
            double d = approach(i, s, unit), e;
            TRY(asperity_normal_eval(&md, d, &sm, &old_s, &rc));
            TRY(asperity_table_eval(table, d, &stt, &new_s, &r));
            branch_mismatch += old_s.branch != new_s.branch;
            contact_mismatch += rc.in_contact != r.in_contact || old_s.in_contact != new_s.in_contact;
            e = fabs(r.force - rc.force) / fmax(fabs(rc.force), f_floor);
            if (e > max_err) {
                max_err = e;
            }
            e = fabs(r.contact_radius - rc.contact_radius) / fmax(rc.contact_radius, a_floor);
            if (e > max_rad_err) {
                max_rad_err = e;
            }
            sm = old_s;
            stt = new_s;
            ++compared;
        }
    }
    check("md_compared", (double)compared);
    check("md_branch_mismatches", (double)branch_mismatch);
    check("md_in_contact_mismatches", (double)contact_mismatch);
    check("md_max_rel_force_error", max_err);
    check("md_max_rel_radius_error", max_rad_err);

    /* 4. Store and load: the loaded table evaluates bit-identically. */
    TRY(asperity_table_to_json(table, NULL, 0, &needed));
    json = (char *)malloc(needed + 1);
    if (!json) {
        return EXIT_FAILURE;
    }
    TRY(asperity_table_to_json(table, json, needed + 1, &needed));
    TRY(asperity_table_from_json(json, needed, &loaded));
    identical = 1;
    for (i = 0; i < N_PAIRS; i += 7) {
        memset(&old_s, 0, sizeof old_s);
        memset(&new_s, 0, sizeof new_s);
        for (s = 0; s < N_STEPS; ++s) {
            double d = approach(i, s, unit);
            TRY(asperity_table_eval(table, d, &old_s, &old_s, &r));
            TRY(asperity_table_eval(loaded, d, &new_s, &new_s, &rc));
            identical &= memcmp(&r, &rc, sizeof r) == 0 && memcmp(&old_s, &new_s, sizeof old_s) == 0;
        }
    }
    check("json_bytes", (double)needed);
    check("json_roundtrip_identical", identical);
    asperity_table_free(loaded);
    loaded = NULL;
    /* A damaged text is refused with a message, not loaded. */
    json[needed / 2] = '}';
    check("json_corrupt_status", asperity_table_from_json(json, needed, &loaded));
    check("json_corrupt_out_is_null", loaded == NULL);

    free(json);
    asperity_table_free(table);
    asperity_table_free(NULL);
    free(f1);
    free(a1);
    free(f2);
    free(a2);
    free(st1);
    free(st2);
    printf("tabulated_threads: %d pairs x %d steps on %d threads\n", N_PAIRS, N_STEPS, N_THREADS);
    return EXIT_SUCCESS;
}
