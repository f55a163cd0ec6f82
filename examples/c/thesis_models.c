/*
 * The models of thesis 5.3.7 and 5.4.3, the Hurst estimate and the map
 * analysis through the C ABI.
 *
 *   thesis_models
 *
 * 1. Borodich-Kryukova's block on a belt on flat layers: the layers are a
 *    spring 2*a*eps, so the weight rests at y* = -M g/(2 a eps), and a block
 *    sliding from rest follows x(t) = x*(1 - cos(w t)), x* = mu M g/k_x,
 *    w = sqrt(k_x/M) (asperity_borodich_kryukova_normal_force, _run into a
 *    caller-owned array).
 * 2. Schmittbuhl's renormalisation with Coulomb friction (mu_s = mu_k, no
 *    weakening): every generation keeps mu (asperity_schmittbuhl_default,
 *    _run).
 * 3. The Hurst estimate of a generated self-affine profile (H = 0.7): H, its
 *    standard error and the band in wavelengths
 *    (asperity_profile_hurst_estimate).
 * 4. A map with a cosine at the cut-off wavelength: the ISO 16610-61 mean
 *    surface keeps half its amplitude (asperity_map_gaussian_filter), and
 *    the radial PSD peaks at its wavenumber (asperity_map_psd_radial).
 *
 * Lines "CHECK <name> <value>" are read by tests/c_examples.rs.
 */
#include "asperity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const double PI = 3.14159265358979323846;

static void check(const char *name, double value)
{
    printf("CHECK %s %.17g\n", name, value);
}

static int ok(int32_t status, const char *what)
{
    if (status != ASPERITY_OK) {
        char msg[256];
        asperity_last_error_message(msg, sizeof msg);
        fprintf(stderr, "%s failed (%d): %s\n", what, status, msg);
        return 0;
    }
    return 1;
}

static int belt(void)
{
    AsperityBorodichKryukova bk = {0};
    bk.half_length = 0.01;
    bk.mass = 1.0;
    bk.belt_speed = 0.1;
    bk.spring_stiffness = 1e3;
    bk.layer_stiffness = 5e8;
    bk.friction_coefficient = 0.3;
    bk.gravity = 9.81;
    bk.sign_speed = 1e-4;
    bk.slider_wavelength = 1e-3;
    bk.belt_wavelength = 1e-3;
    bk.nodes = 20; /* flat layers: any number of cells is exact */
    const double weight = bk.mass * bk.gravity;
    const double y_rest = -weight / (2.0 * bk.half_length * bk.layer_stiffness);
    double force = 0.0;
    if (!ok(asperity_borodich_kryukova_normal_force(&bk, 0.0, y_rest, 0.0, &force),
            "asperity_borodich_kryukova_normal_force")) {
        return 0;
    }
    check("bk_rest_force_over_weight", force / weight);

    enum { STEPS = 30000, EVERY = 100, SAMPLES = STEPS / EVERY + 1 };
    AsperityBorodichKryukovaSample *s = malloc(SAMPLES * sizeof *s);
    if (s == NULL) {
        return 0;
    }
    AsperityBorodichKryukovaState start = {0};
    start.y = y_rest;
    size_t written = 0;
    const int run_ok = ok(asperity_borodich_kryukova_run(&bk, &start, 1e-5, STEPS, EVERY, SAMPLES,
                                                         s, &written),
                          "asperity_borodich_kryukova_run");
    if (run_ok) {
        const double x_star = bk.friction_coefficient * weight / bk.spring_stiffness;
        const double w = sqrt(bk.spring_stiffness / bk.mass);
        double worst = 0.0;
        for (size_t i = 0; i < written; ++i) {
            const double want = x_star * (1.0 - cos(w * s[i].state.time));
            worst = fmax(worst, fabs(s[i].state.x - want));
        }
        check("bk_samples", (double)written);
        check("bk_end_time", s[written - 1].state.time);
        check("bk_x_max_error", worst);
        check("bk_x_star", x_star);
    }
    /* Room for one sample fewer: refused, naming the capacity. */
    const int32_t st =
        asperity_borodich_kryukova_run(&bk, &start, 1e-5, STEPS, EVERY, SAMPLES - 1, s, &written);
    check("bk_short_capacity_status", (double)st);
    free(s);
    return run_ok;
}

static int chain(void)
{
    AsperitySchmittbuhl m;
    if (!ok(asperity_schmittbuhl_default(&m), "asperity_schmittbuhl_default")) {
        return 0;
    }
    check("schmittbuhl_default_ratio", (double)m.ratio);
    m.mu_static = 0.4;
    m.mu_kinetic = 0.4;
    m.weakening_velocity = INFINITY;
    m.ratio = 2;
    m.generations = 2;
    AsperitySchmittbuhlGeneration g[3];
    size_t written = 0;
    if (!ok(asperity_schmittbuhl_run(&m, 3, g, &written), "asperity_schmittbuhl_run")) {
        return 0;
    }
    double worst = 0.0;
    for (size_t i = 0; i < written; ++i) {
        worst = fmax(worst, fabs(g[i].mu_static / 0.4 - 1.0));
        worst = fmax(worst, fabs(g[i].mu_kinetic / 0.4 - 1.0));
    }
    check("schmittbuhl_generations", (double)written);
    check("schmittbuhl_coulomb_max_rel_error", worst);
    check("schmittbuhl_top_size", g[written - 1].size);
    return 1;
}

static int hurst(void)
{
    enum { N = 1 << 16 };
    const double dx = 1e-7;
    double *z = malloc(N * sizeof *z);
    if (z == NULL) {
        return 0;
    }
    AsperityHurstEstimate e;
    const int good =
        ok(asperity_generate_self_affine(0.7, 1e-7, 0.0, 0.0, dx, 11, N, z),
           "asperity_generate_self_affine") &&
        ok(asperity_profile_hurst_estimate(N, z, dx, 0.0, 0.0, &e),
           "asperity_profile_hurst_estimate");
    free(z);
    if (!good) {
        return 0;
    }
    check("hurst", e.hurst);
    check("hurst_uncertainty", e.hurst_uncertainty);
    check("hurst_band_decades", log10(e.wavelength_max / e.wavelength_min));
    check("hurst_wavelength_min_times_q_max", e.wavelength_min * e.q_max);
    return 1;
}

static int map(void)
{
    enum { NX = 256, NY = 96 };
    const double d = 1e-6, lc = 32e-6;
    double *h = malloc(NX * NY * sizeof *h);
    double *r = malloc(NX * NY * sizeof *r);
    double *m = malloc(NX * NY * sizeof *m);
    double q[NY / 2 + 1], g[NY / 2 + 1];
    int good = h != NULL && r != NULL && m != NULL;
    if (good) {
        for (size_t j = 0; j < NY; ++j) {
            for (size_t i = 0; i < NX; ++i) {
                h[i + NX * j] = 1e-6 * cos(2.0 * PI * (double)i * d / lc);
            }
        }
        size_t mx = 0, my = 0, fx = 0, fy = 0;
        good = ok(asperity_map_gaussian_filter(NX, NY, d, d, h, lc, ASPERITY_FILTER_ENDS_DISCARD, r,
                                               m, &mx, &my, &fx, &fy),
                  "asperity_map_gaussian_filter");
        if (good) {
            double sum = 0.0;
            for (size_t k = 0; k < mx * my; ++k) {
                sum += m[k] * m[k];
            }
            check("map_nx_out", (double)mx);
            check("map_first_x", (double)fx);
            check("map_mean_amplitude_ratio", sqrt(2.0 * sum / (double)(mx * my)) / 1e-6);
        }
        size_t annuli = 0;
        good = good && ok(asperity_map_psd_radial(NX, NY, d, d, h, ASPERITY_WINDOW_RECTANGULAR,
                                                  NY / 2 + 1, q, g, NULL, &annuli),
                          "asperity_map_psd_radial");
        if (good) {
            size_t top = 0;
            for (size_t k = 1; k < annuli; ++k) {
                if (g[k] > g[top]) {
                    top = k;
                }
            }
            check("map_psd_peak_q_over_wave_q", q[top] / (2.0 * PI / lc));
        }
    }
    free(h);
    free(r);
    free(m);
    return good;
}

int main(void)
{
    const int good = belt() & chain() & hurst() & map();
    return good ? EXIT_SUCCESS : EXIT_FAILURE;
}
