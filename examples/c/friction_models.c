/* One track through every per-increment friction model: the same slip
 * history (out 20 um at 1 mm/s, back 30 um, out 15 um; 1 um increments of
 * 1 ms; normal force 2 N on a 1 mm^2 point) stepped through
 *   - LuGre (bristles with Stribeck weakening, exact per increment),
 *   - Maxwell-slip (four elements: pre-sliding hysteresis),
 *   - the homogenised energy-dissipation law (mu = 1.05, the chapter-6
 *     copper figure, with a stick stiffness),
 * printing the friction force histories side by side ("row" lines: slip
 * position, then each model's force on the point along x, in N) and each
 * model's total dissipation ("CHECK" lines).
 */
#include <asperity.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define STEPS 65
#define N_MAX 16

static int fail(const char *what, int32_t status) {
    char msg[512];
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "%s failed: %s (%s)\n", what, asperity_status_string(status), msg);
    return 1;
}

int main(void) {
    const double normal = 2.0, area = 1e-6, dt = 1e-3, h = 1e-6;
    AsperityLugreParams p;
    AsperityDynamicFriction *lugre = NULL, *maxwell = NULL;
    AsperityHomogenisedFriction *homog = NULL;
    const double k[4] = {4e5, 1e5, 2.5e4, 6.25e3};
    const double mu[4] = {0.3, 0.3, 0.25, 0.2};
    AsperityHomogenisedSample sample;
    double s_lugre[N_MAX] = {0}, s_maxwell[N_MAX] = {0};
    AsperityFrictionPointState s_homog;
    double x = 0.0, d_homog = 0.0;
    size_t n_lugre = 0, n_maxwell = 0;
    int32_t st;
    int i;

    p.mu_coulomb = 0.8;
    p.mu_static = 1.05;
    p.stribeck_velocity = 2e-4;
    p.stribeck_exponent = 2.0;
    p.sigma0 = 2e5;
    p.sigma1 = 0.0;
    p.damping_velocity = INFINITY;
    p.sigma2 = 0.0;
    if ((st = asperity_dynamic_lugre_new(&p, &lugre)) != ASPERITY_OK) return fail("lugre", st);
    if ((st = asperity_dynamic_maxwell_slip_new(k, mu, 4, 0.0, &maxwell)) != ASPERITY_OK)
        return fail("maxwell", st);
    memset(&sample, 0, sizeof sample);
    sample.pressure = normal / area;
    sample.cof = 1.05;
    sample.contact_fraction = 0.01;
    sample.shares.chemical = 1.0;
    if ((st = asperity_homogenised_friction_new(&sample, 1, &homog)) != ASPERITY_OK)
        return fail("homogenised", st);
    if ((st = asperity_dynamic_friction_state_size(lugre, &n_lugre)) != ASPERITY_OK ||
        (st = asperity_dynamic_friction_state_size(maxwell, &n_maxwell)) != ASPERITY_OK)
        return fail("state size", st);
    if (n_lugre > N_MAX || n_maxwell > N_MAX) return fail("state size", ASPERITY_ERR_INTERNAL);
    memset(&s_homog, 0, sizeof s_homog);

    printf("# x_um lugre_N maxwell_N homogenised_N\n");
    for (i = 0; i < STEPS; ++i) {
        const double dx = i < 20 ? h : (i < 50 ? -h : h);
        AsperityDynamicIncrement inc;
        AsperityDynamicResponse r_lugre, r_maxwell;
        AsperityFrictionIncrement hinc;
        AsperityFrictionResponse r_homog;
        memset(&inc, 0, sizeof inc);
        inc.normal_force = normal;
        inc.slip[0] = dx;
        inc.dt = dt;
        if ((st = asperity_dynamic_friction_step(lugre, &inc, s_lugre, s_lugre, &r_lugre)) !=
            ASPERITY_OK)
            return fail("lugre step", st);
        if ((st = asperity_dynamic_friction_step(maxwell, &inc, s_maxwell, s_maxwell,
                                                 &r_maxwell)) != ASPERITY_OK)
            return fail("maxwell step", st);
        memset(&hinc, 0, sizeof hinc);
        hinc.normal_force = normal;
        hinc.area = area;
        hinc.slip[0] = dx;
        hinc.dt = dt;
        hinc.stick_stiffness = 2e5 * normal;
        if ((st = asperity_homogenised_friction_step(homog, &hinc, &s_homog, &s_homog, &r_homog)) !=
            ASPERITY_OK)
            return fail("homogenised step", st);
        d_homog += r_homog.dissipated;
        x += dx;
        printf("row %.1f %.9e %.9e %.9e\n", x * 1e6, r_lugre.force[0], r_maxwell.force[0],
               r_homog.force[0]);
    }
    printf("CHECK lugre_dissipation %.17g\n", s_lugre[ASPERITY_DYNAMIC_STATE_DISSIPATION]);
    printf("CHECK maxwell_dissipation %.17g\n", s_maxwell[ASPERITY_DYNAMIC_STATE_DISSIPATION]);
    printf("CHECK homogenised_dissipation %.17g\n", d_homog);
    printf("CHECK slip_path_um %.17g\n", s_lugre[ASPERITY_DYNAMIC_STATE_SLIP_PATH] * 1e6);
    asperity_dynamic_friction_free(lugre);
    asperity_dynamic_friction_free(maxwell);
    asperity_homogenised_friction_free(homog);
    return 0;
}
