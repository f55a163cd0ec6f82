/*
 * A toy explicit FE loop over a one-dimensional strip of contact points, with
 * the homogenised friction law as the interface law (the call shape of an
 * Abaqus/Explicit VFRIC user subroutine).
 *
 * Each of the 64 points is a mass m on a spring k_s (with a dashpot c) to a
 * base driven at constant speed v along x; the point rests on a rigid
 * counter-surface under a normal force N_i rising along the strip
 * (10 .. 200 MPa on 1 mm^2). Every increment:
 *
 *   a_i = (k_s (x_base - x_i) + c (v - u_i) + F_i) / m    (forces at t_n)
 *   u_i += dt a_i;  dx_i = dt u_i;  x_i += dx_i            (symplectic Euler)
 *   asperity_friction_step_block_in_place(dx)  ->  F_i at t_{n+1}
 *
 * with the per-point states (asperity_friction_state_size doubles each)
 * stepped in place. The friction law is the homogenised law of a table built
 * in C from five copper-like samples (mu 1.10 .. 0.90 over 10 .. 200 MPa)
 * with a stick stiffness, one AsperityFriction handle. The strip sticks
 * while the springs load, then slides; in steady sliding the total friction
 * force is sum mu(p_i)(N_i + A_i).
 *
 * Prints the friction force history every 1000 increments and lines
 * "CHECK <name> <value>" read by tests/c_examples.rs.
 */
#include "asperity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NP 64
#define STEPS 30000
#define PRINT_EVERY 1000

static const double AREA = 1e-6;   /* nominal area per point (m^2) */
static const double MASS = 1e-3;   /* kg */
static const double K_SPRING = 1e6; /* N/m */
static const double K_STICK = 1e8; /* regularised stick stiffness (N/m) */
static const double SPEED = 0.01;  /* base speed (m/s) */
static const double DT = 1e-6;     /* s */

static int failed(int32_t status, const char *what)
{
    char msg[512];
    if (status == ASPERITY_OK) {
        return 0;
    }
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "fe_strip_friction: %s failed: status %d (%s): %s\n", what, (int)status,
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

static double rel_diff(double got, double want)
{
    const double scale = fabs(want) > 0.0 ? fabs(want) : 1.0;
    return fabs(got - want) / scale;
}

static AsperityHomogenisedSample sample(double p_mpa, double mu, double adh_mpa, double fraction,
                                        double chemical, double vdw, double elastic)
{
    AsperityHomogenisedSample s;
    s.pressure = p_mpa * 1e6;
    s.cof = mu;
    s.adhesion_pressure = adh_mpa * 1e6;
    s.contact_fraction = fraction;
    s.shares.chemical = chemical;
    s.shares.van_der_waals = vdw;
    s.shares.elastic = elastic;
    s.shares.plastic = 1.0 - chemical - vdw - elastic;
    return s;
}

int main(void)
{
    AsperityHomogenisedSample samples[5];
    AsperityHomogenisedFriction *table = NULL;
    AsperityFriction *law = NULL;
    AsperityFrictionWork *work = NULL;
    double *state, *fresh, *scratch;
    static double normal[NP], area[NP], slip[2 * NP], force[2 * NP], diss[NP];
    static double x[NP], u[NP], limit[NP];
    double expected = 0.0, steady = 0.0, d_steps = 0.0, d_states = 0.0, d_limit_path = 0.0;
    double min_diss = 0.0, stick_balance = 0.0, path0 = 0.0;
    size_t m = 0;
    long first_slip = -1, all_sliding_from = -1;
    int stick_below_limit = 1;
    int i;
    long n;

    samples[0] = sample(10.0, 1.10, 0.90, 0.010, 0.930, 0.067, 0.002);
    samples[1] = sample(50.0, 1.02, 4.50, 0.050, 0.925, 0.066, 0.006);
    samples[2] = sample(100.0, 0.97, 9.00, 0.100, 0.920, 0.064, 0.010);
    samples[3] = sample(150.0, 0.93, 13.5, 0.150, 0.910, 0.062, 0.018);
    samples[4] = sample(200.0, 0.90, 18.0, 0.200, 0.900, 0.060, 0.025);
    TRY(asperity_homogenised_friction_new(samples, 5, &table));
    /* The friction law: the table with the stick stiffness. */
    TRY(asperity_friction_from_homogenised(table, K_STICK, &law));
    TRY(asperity_friction_work_new(law, &work));
    TRY(asperity_friction_state_size(law, &m));

    /* The state: dissipation, slip path, stick force (x, y), plastic slip
     * path, dissipation by mechanism (4). */
    check("state_size_matches", m == ASPERITY_HOMOGENISED_STATE_MECHANISMS + 4);
    state = (double *)calloc(NP * m, sizeof(double)); /* all-zero: fresh */
    fresh = (double *)calloc(m, sizeof(double));
    scratch = (double *)calloc(m, sizeof(double));
    if (state == NULL || fresh == NULL || scratch == NULL) {
        return EXIT_FAILURE;
    }

    /* The strip, and each point's slip limit from a scalar step (a large slip
     * from a fresh state slides: |F| = mu (N + A)). */
    for (i = 0; i < NP; ++i) {
        AsperityFrictionIncrement inc;
        AsperityFrictionResponse r;
        const double p = 10e6 + 190e6 * (double)i / (double)(NP - 1);
        normal[i] = p * AREA;
        area[i] = AREA;
        x[i] = 0.0;
        u[i] = 0.0;
        force[2 * i] = 0.0;
        force[2 * i + 1] = 0.0;
        memset(&inc, 0, sizeof inc);
        inc.normal_force = normal[i];
        inc.area = AREA;
        inc.slip[0] = 1.0;
        inc.slip[1] = 0.0;
        inc.dt = DT;
        TRY(asperity_friction_step(law, &inc, fresh, scratch, work, &r));
        limit[i] = r.cof * (r.normal_force + r.adhesion);
        expected += limit[i];
    }
    printf("# strip of %d points, N = %.1f .. %.1f N, sum mu (N + A) = %.6f N\n", NP, normal[0],
           normal[NP - 1], expected);
    printf("# increment  time_s  base_m  friction_force_N  sliding_points  dissipation_J\n");

    {
        const double c = 2.0 * 0.5 * sqrt(K_SPRING * MASS); /* damping ratio 0.5 */
        for (n = 1; n <= STEPS; ++n) {
            const double base_old = SPEED * DT * (double)(n - 1);
            double total = 0.0, d = 0.0, sum_spring = 0.0;
            int sliding = 0;
            for (i = 0; i < NP; ++i) {
                const double a =
                    (K_SPRING * (base_old - x[i]) + c * (SPEED - u[i]) + force[2 * i]) / MASS;
                u[i] += DT * a;
                slip[2 * i] = DT * u[i];
                slip[2 * i + 1] = 0.0;
                x[i] += slip[2 * i];
            }
            path0 += fabs(slip[0]);
            TRY(asperity_friction_step_block_in_place(law, NP, normal, area, slip, DT, state,
                                                      force, diss, work));
            for (i = 0; i < NP; ++i) {
                total += force[2 * i];
                d += diss[i];
                if (diss[i] < min_diss) {
                    min_diss = diss[i];
                }
                if (diss[i] > 0.0) {
                    ++sliding;
                }
                if (first_slip < 0 && fabs(force[2 * i]) >= limit[i] * (1.0 + 1e-12)) {
                    stick_below_limit = 0;
                }
                sum_spring += K_SPRING * (SPEED * DT * (double)n - x[i]) + c * (SPEED - u[i]);
            }
            d_steps += d;
            if (sliding > 0 && first_slip < 0) {
                first_slip = n;
            }
            if (sliding == NP && all_sliding_from < 0) {
                all_sliding_from = n;
            } else if (sliding < NP) {
                all_sliding_from = -1;
            }
            if (n == 5000) {
                /* Quasi-static stick: friction balances spring and dashpot. */
                stick_balance = rel_diff(-total, sum_spring);
            }
            if (n % PRINT_EVERY == 0) {
                printf("history %6ld %.6e %.6e %.9e %3d %.9e\n", n, DT * (double)n,
                       SPEED * DT * (double)n, total, sliding, d_steps);
            }
            if (n == STEPS) {
                steady = -total;
            }
        }
    }

    for (i = 0; i < NP; ++i) {
        const double *s = state + i * m;
        const double *a = s + ASPERITY_HOMOGENISED_STATE_MECHANISMS;
        const double di = a[0] + a[1] + a[2] + a[3];
        d_states += di;
        d_limit_path += limit[i] * s[ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH];
    }

    check("points", NP);
    check("expected_steady_force", expected);
    check("steady_force", steady);
    check("steady_force_rel_diff", rel_diff(steady, expected));
    check("first_slip_increment", (double)first_slip);
    check("all_sliding_from", (double)all_sliding_from);
    check("stick_below_limit", stick_below_limit);
    check("stick_balance_rel_diff", stick_balance);
    check("total_dissipation", d_steps);
    check("min_increment_dissipation", min_diss);
    check("dissipation_states_rel_diff", rel_diff(d_states, d_steps));
    check("dissipation_limit_path_rel_diff", rel_diff(d_limit_path, d_steps));
    {
        const double *a = state + (NP / 2) * m + ASPERITY_HOMOGENISED_STATE_MECHANISMS;
        check("chemical_share", a[0] / (a[0] + a[1] + a[2] + a[3]));
    }
    /* Every increment is booked: point 0's slip path is the sum of |dx|. */
    check("slip_path_booked_rel_diff", rel_diff(state[ASPERITY_FRICTION_STATE_SLIP_PATH], path0));

    /* JSON round trip: the reloaded law steps bit-identically. */
    {
        size_t needed = 0;
        char *json;
        AsperityHomogenisedFriction *copy = NULL;
        AsperityFriction *copy_law = NULL;
        AsperityFrictionIncrement inc;
        AsperityFrictionResponse r1, r2;
        TRY(asperity_homogenised_friction_to_json(table, NULL, 0, &needed));
        json = (char *)malloc(needed + 1);
        if (json == NULL) {
            return EXIT_FAILURE;
        }
        TRY(asperity_homogenised_friction_to_json(table, json, needed + 1, &needed));
        TRY(asperity_homogenised_friction_from_json(json, needed, &copy));
        TRY(asperity_friction_from_homogenised(copy, K_STICK, &copy_law));
        memset(&inc, 0, sizeof inc);
        inc.normal_force = 77.7;
        inc.area = AREA;
        inc.slip[0] = 3e-7;
        inc.slip[1] = -1e-7;
        inc.dt = DT;
        TRY(asperity_friction_step(law, &inc, state + 3 * m, scratch, work, &r1));
        TRY(asperity_friction_step(copy_law, &inc, state + 3 * m, scratch, work, &r2));
        check("json_roundtrip_identical", memcmp(&r1, &r2, sizeof r1) == 0);
        asperity_friction_free(copy_law);
        asperity_homogenised_friction_free(copy);
        free(json);
    }

    /* Errors: a negative area in the block names the element; NULL handle. */
    {
        char msg[512];
        int32_t st;
        area[9] = -1.0;
        st = asperity_friction_step_block_in_place(law, NP, normal, area, slip, DT, state, force,
                                                   diss, work);
        asperity_last_error_message(msg, sizeof msg);
        check("bad_area_status", st);
        check("bad_area_names_element", strstr(msg, "element 9") != NULL);
        check("bad_area_names_area", strstr(msg, "`area`") != NULL);
        area[9] = AREA;
        st = asperity_friction_step_block_in_place(NULL, NP, normal, area, slip, DT, state, force,
                                                   diss, work);
        check("null_handle_status", st);
    }

    free(state);
    free(fresh);
    free(scratch);
    asperity_friction_work_free(work);
    asperity_friction_free(law);
    asperity_friction_free(NULL);
    asperity_homogenised_friction_free(table);
    asperity_homogenised_friction_free(NULL);
    return EXIT_SUCCESS;
}
