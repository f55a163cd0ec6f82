/* One track through every per-increment friction model: the same slip
 * history (out 20 um at 1 mm/s, back 30 um, out 15 um; 1 um increments of
 * 1 ms; normal force 2 N on a 1 mm^2 point) stepped through
 *   - LuGre (bristles with Stribeck weakening, exact per increment),
 *   - Maxwell-slip (four elements: pre-sliding hysteresis),
 *   - the homogenised energy-dissipation law (mu = 1.05, the chapter-6
 *     copper figure, with a stick stiffness),
 *   - Prandtl-Tomlinson, one spring: a 1 g slider in a periodic potential
 *     of period 5 um (an asperity spacing) whose largest force is 2 N,
 *     pulled through a spring at Tomlinson parameter 3 (stick-slip),
 *   - Prandtl-Tomlinson, two springs: the same with the spring split into
 *     a tip and a cantilever spring in series (same effective stiffness),
 *   - Burridge-Knopoff: eight 0.1 g blocks, 0.25 N each, mu_s = 1.05,
 *     mu_k = 0.8 weakening on 5 cm/s, coupled and pulled by springs
 *     (static reach 10 um), lightly damped, the fourth block set 1 um
 *     behind the others at the start,
 * printing the friction force histories side by side ("row" lines: slip
 * position, then each model's force on the point along x, in N) and each
 * model's total dissipation ("CHECK" lines).
 *
 * Every model is one AsperityFriction handle stepped by the same call,
 * asperity_friction_step, each with its own state of
 * asperity_friction_state_size doubles (all-zero = fresh) and scratch.
 */
#include <asperity.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define STEPS 65
#define N_MAX 32
#define MODELS 7
#define HOMOGENISED 6

static int fail(const char *what, int32_t status) {
    char msg[512];
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "%s failed: %s (%s)\n", what, asperity_status_string(status), msg);
    return 1;
}

int main(void) {
    const double normal = 2.0, area = 1e-6, dt = 1e-3, h = 1e-6;
    const double pi = 3.14159265358979323846;
    /* Prandtl-Tomlinson: period a, amplitude U0 from the largest lattice
     * force 2 pi U0 / a = 2 N, spring from eta = 4 pi^2 U0/(k a^2) = 3,
     * damping ratio 0.5 at 1 g. */
    const double a = 5e-6, u0 = 2.0 * a / (2.0 * pi);
    const double k_pt = 4.0 * pi * pi * u0 / (3.0 * a * a), m_pt = 1e-3;
    const char *names[MODELS] = {"lugre",      "maxwell",          "prandtl_tomlinson",
                                 "two_spring", "burridge_knopoff", "bristles",
                                 "homogenised"};
    AsperityLugreParams p;
    AsperityPrandtlTomlinsonTwoSpringParams t;
    AsperityBurridgeKnopoffParams b;
    AsperityFriction *models[MODELS] = {NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    AsperityFrictionWork *works[MODELS] = {NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    AsperityHomogenisedFriction *homog = NULL;
    const double k[4] = {4e5, 1e5, 2.5e4, 6.25e3};
    const double mu[4] = {0.3, 0.3, 0.25, 0.2};
    /* Bristles: 1e5 /m per unit normal force, break deflections 3..12 um. */
    const double kb[4] = {1e5, 1e5, 1e5, 1e5};
    const double db[4] = {3e-6, 5.5e-6, 8e-6, 12e-6};
    AsperityHomogenisedSample sample;
    double states[MODELS][N_MAX];
    double x = 0.0, d_homog = 0.0;
    int32_t st;
    int i, j;

    p.mu_coulomb = 0.8;
    p.mu_static = 1.05;
    p.stribeck_velocity = 2e-4;
    p.stribeck_exponent = 2.0;
    p.sigma0 = 2e5;
    p.sigma1 = 0.0;
    p.damping_velocity = INFINITY;
    p.sigma2 = 0.0;
    t.amplitude = u0;
    t.period = a;
    t.tip_stiffness = 2.0 * k_pt;
    t.tip_mass = 0.5 * m_pt;
    t.tip_damping = sqrt(2.0 * k_pt * 0.5 * m_pt);
    t.cantilever_stiffness = 2.0 * k_pt;
    t.cantilever_mass = 0.5 * m_pt;
    t.cantilever_damping = sqrt(2.0 * k_pt * 0.5 * m_pt);
    t.tolerance = 1e-9;
    b.blocks = 8;
    b.mass = 1e-4;
    b.coupling_stiffness = 1e4;
    b.pulling_stiffness = 2.6e4;
    b.mu_static = 1.05;
    b.mu_kinetic = 0.8;
    b.weakening_velocity = 5e-2;
    b.damping = 0.3;
    b.tolerance = 1e-9;
    if ((st = asperity_friction_lugre_new(&p, &models[0])) != ASPERITY_OK)
        return fail("lugre", st);
    if ((st = asperity_friction_maxwell_slip_new(k, mu, 4, 0.0, &models[1])) != ASPERITY_OK)
        return fail("maxwell", st);
    if ((st = asperity_friction_prandtl_tomlinson_new(u0, a, k_pt, m_pt, sqrt(k_pt * m_pt), 1e-9,
                                                      &models[2])) != ASPERITY_OK)
        return fail("prandtl_tomlinson", st);
    if ((st = asperity_friction_prandtl_tomlinson_two_spring_new(&t, &models[3])) != ASPERITY_OK)
        return fail("two_spring", st);
    if ((st = asperity_friction_burridge_knopoff_new(&b, &models[4])) != ASPERITY_OK)
        return fail("burridge_knopoff", st);
    if ((st = asperity_friction_bristles_new(kb, db, 4, 0.0, &models[5])) != ASPERITY_OK)
        return fail("bristles", st);
    memset(&sample, 0, sizeof sample);
    sample.pressure = normal / area;
    sample.cof = 1.05;
    sample.contact_fraction = 0.01;
    sample.shares.chemical = 1.0;
    if ((st = asperity_homogenised_friction_new(&sample, 1, &homog)) != ASPERITY_OK)
        return fail("homogenised", st);
    /* The homogenised law: the table with a stick stiffness. */
    if ((st = asperity_friction_from_homogenised(homog, 2e5 * normal, &models[HOMOGENISED])) !=
        ASPERITY_OK)
        return fail("homogenised law", st);
    for (j = 0; j < MODELS; ++j) {
        size_t n = 0;
        if ((st = asperity_friction_state_size(models[j], &n)) != ASPERITY_OK)
            return fail("state size", st);
        if (n > N_MAX) return fail("state size", ASPERITY_ERR_INTERNAL);
        if ((st = asperity_friction_work_new(models[j], &works[j])) != ASPERITY_OK)
            return fail("work", st);
        memset(states[j], 0, sizeof states[j]);
    }
    /* The state layout: block i's x_i - x_d at ASPERITY_FRICTION_STATE_MODEL + 2 i. */
    states[4][ASPERITY_FRICTION_STATE_MODEL + 2 * 3] = -1e-6;

    printf("# x_um lugre_N maxwell_N homogenised_N prandtl_tomlinson_N two_spring_N "
           "burridge_knopoff_N bristles_N\n");
    for (i = 0; i < STEPS; ++i) {
        const double dx = i < 20 ? h : (i < 50 ? -h : h);
        AsperityFrictionIncrement inc;
        AsperityFrictionResponse r[MODELS];
        /* One increment for every model; the area is read by the
         * homogenised law only. */
        memset(&inc, 0, sizeof inc);
        inc.normal_force = normal;
        inc.area = area;
        inc.slip[0] = dx;
        inc.dt = dt;
        for (j = 0; j < MODELS; ++j)
            if ((st = asperity_friction_step(models[j], &inc, states[j], states[j], works[j],
                                             &r[j])) != ASPERITY_OK)
                return fail(names[j], st);
        d_homog += r[HOMOGENISED].dissipated;
        x += dx;
        printf("row %.1f %.9e %.9e %.9e %.9e %.9e %.9e %.9e\n", x * 1e6, r[0].force[0],
               r[1].force[0], r[HOMOGENISED].force[0], r[2].force[0], r[3].force[0],
               r[4].force[0], r[5].force[0]);
    }
    for (j = 0; j < HOMOGENISED; ++j)
        printf("CHECK %s_dissipation %.17g\n", names[j],
               states[j][ASPERITY_FRICTION_STATE_DISSIPATION]);
    printf("CHECK homogenised_dissipation %.17g\n", d_homog);
    printf("CHECK slip_path_um %.17g\n", states[0][ASPERITY_FRICTION_STATE_SLIP_PATH] * 1e6);
    for (j = 0; j < MODELS; ++j) {
        asperity_friction_work_free(works[j]);
        asperity_friction_free(models[j]);
    }
    asperity_homogenised_friction_free(homog);
    return 0;
}
