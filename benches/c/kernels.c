/* Hand-written -O3 reference kernels for benches/laws.rs; see kernels.h. */
#include "kernels.h"

#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ------------------------------------------------------------------ Hertz */

void ck_hertz_init(ck_hertz *law, double radius, double e_star)
{
    law->radius = radius;
    law->e_star = e_star;
}

static inline ck_response hertz_at(double radius, double e_star, double delta)
{
    ck_response r = {0.0, 0.0, 0.0};
    if (delta > 0.0) {
        double a = sqrt(radius * delta);
        r.force = (4.0 / 3.0) * e_star * a * delta;
        r.contact_radius = a;
        r.stiffness = 2.0 * e_star * a;
    }
    return r;
}

ck_response ck_hertz_eval(const ck_hertz *law, double delta)
{
    return hertz_at(law->radius, law->e_star, delta);
}

void ck_hertz_batch(const ck_hertz *law, size_t n, const double *delta,
                    double *force, double *contact_radius, double *stiffness)
{
    const double radius = law->radius, e_star = law->e_star;
    for (size_t i = 0; i < n; ++i) {
        ck_response r = hertz_at(radius, e_star, delta[i]);
        force[i] = r.force;
        contact_radius[i] = r.contact_radius;
        stiffness[i] = r.stiffness;
    }
}

/* ----------------------------------------------------------- power punch */

/* Galin's D(d) = sqrt(pi) Gamma(d/2 + 1) / Gamma(d/2 + 1/2); C(d) = 2d/(d+1) D(d). */
void ck_power_punch_init(ck_power_punch *law, double b, double d, double e_star)
{
    double dd = sqrt(M_PI) * exp(lgamma(0.5 * d + 1.0) - lgamma(0.5 * d + 0.5));
    double cc = 2.0 * d / (d + 1.0) * dd;
    law->inv_depth_coefficient = 1.0 / (dd * b);
    law->inv_d = 1.0 / d;
    law->force_factor = cc / dd * e_star;
    law->two_e_star = 2.0 * e_star;
}

static inline ck_response power_punch_at(const ck_power_punch *law, double delta)
{
    ck_response r = {0.0, 0.0, 0.0};
    if (delta > 0.0) {
        double a = pow(delta * law->inv_depth_coefficient, law->inv_d);
        r.force = law->force_factor * a * delta;
        r.contact_radius = a;
        r.stiffness = law->two_e_star * a;
    }
    return r;
}

ck_response ck_power_punch_eval(const ck_power_punch *law, double delta)
{
    return power_punch_at(law, delta);
}

void ck_power_punch_batch(const ck_power_punch *law, size_t n, const double *delta,
                          double *force, double *contact_radius, double *stiffness)
{
    const ck_power_punch l = *law;
    for (size_t i = 0; i < n; ++i) {
        ck_response r = power_punch_at(&l, delta[i]);
        force[i] = r.force;
        contact_radius[i] = r.contact_radius;
        stiffness[i] = r.stiffness;
    }
}

/* ------------------------------------------------------------ flat punch */

void ck_flat_punch_init(ck_flat_punch *law, double radius, double e_star, double no_slip_factor)
{
    law->radius = radius;
    law->stiffness = 2.0 * e_star * radius * no_slip_factor;
}

static inline ck_response flat_punch_at(double radius, double k, double delta)
{
    ck_response r = {0.0, 0.0, 0.0};
    if (delta >= 0.0) {
        r.force = k * delta;
        r.contact_radius = radius;
        r.stiffness = k;
    }
    return r;
}

ck_response ck_flat_punch_eval(const ck_flat_punch *law, double delta)
{
    return flat_punch_at(law->radius, law->stiffness, delta);
}

void ck_flat_punch_batch(const ck_flat_punch *law, size_t n, const double *delta,
                         double *force, double *contact_radius, double *stiffness)
{
    const double radius = law->radius, k = law->stiffness;
    for (size_t i = 0; i < n; ++i) {
        ck_response r = flat_punch_at(radius, k, delta[i]);
        force[i] = r.force;
        contact_radius[i] = r.contact_radius;
        stiffness[i] = r.stiffness;
    }
}

/* ------------------------------------------------------------------- DMT */

void ck_dmt_init(ck_dmt *law, double radius, double e_star, double work_of_adhesion)
{
    law->radius = radius;
    law->e_star = e_star;
    law->adhesive_force = 2.0 * M_PI * work_of_adhesion * radius;
}

static inline ck_response dmt_at(double radius, double e_star, double fa, double delta)
{
    ck_response r = {0.0, 0.0, 0.0};
    if (delta >= 0.0) {
        double a = sqrt(radius * delta);
        r.force = (4.0 / 3.0) * e_star * a * delta - fa;
        r.contact_radius = a;
        r.stiffness = 2.0 * e_star * a;
    }
    return r;
}

ck_response ck_dmt_eval(const ck_dmt *law, double delta)
{
    return dmt_at(law->radius, law->e_star, law->adhesive_force, delta);
}

void ck_dmt_batch(const ck_dmt *law, size_t n, const double *delta,
                  double *force, double *contact_radius, double *stiffness)
{
    const double radius = law->radius, e_star = law->e_star, fa = law->adhesive_force;
    for (size_t i = 0; i < n; ++i) {
        ck_response r = dmt_at(radius, e_star, fa, delta[i]);
        force[i] = r.force;
        contact_radius[i] = r.contact_radius;
        stiffness[i] = r.stiffness;
    }
}

/* ------------------------------------------------------------------- JKR */

/*
 * Scaled with y0 = (kR)^(1/3), Y = sqrt(a)/y0 solves the depressed quartic
 *     Y^4 - Y - D = 0,   D = delta R / y0^4.
 * Ferrari: Y^4 - Y - D = (Y^2 + u)^2 - (2u Y^2 + Y + u^2 + D), and the bracket is
 * a perfect square when u solves the resolvent cubic u^3 + D u - 1/8 = 0. On the
 * JKR branch (D >= D_c) that cubic has one real root (its discriminant
 * 1/256 + D^3/27 >= 0, zero exactly at D_c), taken by Cardano in a form free of
 * cancellation: with t = cbrt(1/16 + sqrt(disc)) and s = -D/(3t) the other cube
 * root, u = t + s = (t^3 + s^3)/(t^2 - t s + s^2) = (1/8)/(t^2 + D/3 + s^2).
 * With v = sqrt(2u) the quartic factors into Y^2 -+ vY + u +- 1/(2v); the stable
 * (larger) root is Y = (v + sqrt(2/v - v^2))/2.
 */
void ck_jkr_init(ck_jkr *law, double radius, double e_star, double work_of_adhesion)
{
    double k = sqrt(2.0 * M_PI * work_of_adhesion / e_star);
    double y0 = cbrt(k * radius);
    double y04 = y0 * y0 * y0 * y0;
    law->radius = radius;
    law->e_star = e_star;
    law->y0 = y0;
    law->delta_scale = radius / y04;
    law->a0 = y0 * y0;
    /* D_c = -(3/4) 4^(-1/3), where dD/dY = 4Y^3 - 1 = 0. */
    law->delta_c = -0.75 * cbrt(0.25) * y04 / radius;
    law->force_scale = e_star * y04 * y0 * y0 / radius;
    law->stiff_scale = e_star * law->a0;
}

static inline double jkr_scaled_root(double d)
{
    double disc = 1.0 / 256.0 + d * d * d * (1.0 / 27.0);
    if (disc < 0.0) disc = 0.0; /* rounding at D_c */
    double t = cbrt(1.0 / 16.0 + sqrt(disc));
    double s = d / (3.0 * t);
    double u = 0.125 / (t * t + d * (1.0 / 3.0) + s * s);
    double v = sqrt(2.0 * u);
    double w = 2.0 / v - v * v;
    if (w < 0.0) w = 0.0;
    return 0.5 * (v + sqrt(w));
}

double ck_jkr_radius(const ck_jkr *law, double delta)
{
    double y = jkr_scaled_root(delta * law->delta_scale);
    return law->a0 * y * y;
}

static inline ck_response jkr_at(const ck_jkr *law, double delta, int was_in_contact,
                                 int *in_contact)
{
    ck_response r = {0.0, 0.0, 0.0};
    /* Approach: contact forms at delta = 0 (jump-in). Retraction: it holds down to delta_c. */
    if (delta >= (was_in_contact ? law->delta_c : 0.0)) {
        double y = jkr_scaled_root(delta * law->delta_scale);
        double y2 = y * y, y3 = y2 * y;
        /* P = E* y0^6/R (4/3 Y^6 - 2 Y^3); dP/ddelta = E* a0 Y^2 (8Y^3 - 6)/(4Y^3 - 1). */
        r.force = law->force_scale * y3 * ((4.0 / 3.0) * y3 - 2.0);
        r.contact_radius = law->a0 * y2;
        r.stiffness = law->stiff_scale * y2 * (8.0 * y3 - 6.0) / (4.0 * y3 - 1.0);
        *in_contact = 1;
    } else {
        *in_contact = 0;
    }
    return r;
}

ck_response ck_jkr_eval(const ck_jkr *law, double delta, const ck_state *old_state,
                        ck_state *new_state)
{
    int in_contact;
    ck_response r = jkr_at(law, delta, old_state ? old_state->in_contact : 0, &in_contact);
    if (new_state) {
        new_state->contact_radius = r.contact_radius;
        new_state->in_contact = in_contact;
        new_state->pad = 0;
    }
    return r;
}

void ck_jkr_batch(const ck_jkr *law, size_t n, const double *delta,
                  const ck_state *old_state, ck_state *new_state,
                  double *force, double *contact_radius, double *stiffness)
{
    const ck_jkr l = *law;
    for (size_t i = 0; i < n; ++i) {
        int in_contact;
        ck_response r = jkr_at(&l, delta[i], old_state[i].in_contact, &in_contact);
        force[i] = r.force;
        contact_radius[i] = r.contact_radius;
        stiffness[i] = r.stiffness;
        new_state[i].contact_radius = r.contact_radius;
        new_state[i].in_contact = in_contact;
        new_state[i].pad = 0;
    }
}
