/*
 * Hand-written reference kernels for the asperity benchmarks (benches/laws.rs).
 *
 * Plain C99 of the same formulas as the library's closed-form laws, written the
 * way a host-code author would write them inline in an FE/DEM/MD code: a small
 * parameter struct with the constants precomputed once, a scalar function that
 * returns force, contact radius and tangent stiffness, and a batch loop over
 * plain arrays. No argument checks beyond what the formula itself needs.
 *
 * Compiled at -O3 by build.rs (cc crate) and linked into the bench targets
 * only; the library never sees these symbols.
 *
 * Units: SI. delta > 0 is penetration, force > 0 is repulsive.
 */
#ifndef ASPERITY_BENCH_KERNELS_H
#define ASPERITY_BENCH_KERNELS_H

#include <stddef.h>

typedef struct ck_response {
    double force;          /* N   */
    double contact_radius; /* m   */
    double stiffness;      /* N/m */
} ck_response;

/* Per-contact history of the hysteretic kernels (JKR). */
typedef struct ck_state {
    double contact_radius; /* m */
    int in_contact;        /* 0 or 1 */
    int pad;
} ck_state;

/* ---- Hertz sphere: a = sqrt(R delta), P = 4/3 E* a delta, k = 2 E* a ---- */
typedef struct ck_hertz { double radius, e_star; } ck_hertz;
void ck_hertz_init(ck_hertz *law, double radius, double e_star);
ck_response ck_hertz_eval(const ck_hertz *law, double delta);
void ck_hertz_batch(const ck_hertz *law, size_t n, const double *delta,
                    double *force, double *contact_radius, double *stiffness);

/* ---- Galin power punch f = B r^d: a = (delta/(D B))^(1/d), P = (C/D) E* a delta ---- */
typedef struct ck_power_punch {
    double inv_depth_coefficient; /* 1/(D(d) B)   */
    double inv_d;                 /* 1/d          */
    double force_factor;          /* (C/D) E*     */
    double two_e_star;            /* 2 E*         */
} ck_power_punch;
void ck_power_punch_init(ck_power_punch *law, double b, double d, double e_star);
ck_response ck_power_punch_eval(const ck_power_punch *law, double delta);
void ck_power_punch_batch(const ck_power_punch *law, size_t n, const double *delta,
                          double *force, double *contact_radius, double *stiffness);

/* ---- Flat punch: P = k delta, k = 2 E* a (times C_NS when bonded) ---- */
typedef struct ck_flat_punch { double radius, stiffness; } ck_flat_punch;
void ck_flat_punch_init(ck_flat_punch *law, double radius, double e_star, double no_slip_factor);
ck_response ck_flat_punch_eval(const ck_flat_punch *law, double delta);
void ck_flat_punch_batch(const ck_flat_punch *law, size_t n, const double *delta,
                         double *force, double *contact_radius, double *stiffness);

/* ---- DMT: Hertz minus 2 pi w R while delta >= 0 ---- */
typedef struct ck_dmt { double radius, e_star, adhesive_force; } ck_dmt;
void ck_dmt_init(ck_dmt *law, double radius, double e_star, double work_of_adhesion);
ck_response ck_dmt_eval(const ck_dmt *law, double delta);
void ck_dmt_batch(const ck_dmt *law, size_t n, const double *delta,
                  double *force, double *contact_radius, double *stiffness);

/* ---- JKR sphere under displacement control (closed-form Ferrari inversion) ----
 * delta = a^2/R - sqrt(2 pi w a / E*). With y = sqrt(a), k = sqrt(2 pi w/E*):
 * y^4 - kR y - delta R = 0. Contact forms on approach at delta >= 0 and is lost
 * on retraction below delta_c = -(3/4)(pi^2 w^2 R/E*^2)^(1/3). */
typedef struct ck_jkr {
    double radius, e_star;
    double y0;          /* (kR)^(1/3), the scale of y = sqrt(a)          (m^1/2) */
    double delta_scale; /* R / y0^4: delta -> dimensionless quartic term (1/m)  */
    double a0;          /* y0^2                                          (m)    */
    double delta_c;     /* displacement-controlled separation           (m)    */
    double force_scale; /* E* y0^6 / R                                    (N)    */
    double stiff_scale; /* E* a0                                          (N/m)  */
} ck_jkr;
void ck_jkr_init(ck_jkr *law, double radius, double e_star, double work_of_adhesion);
/* Contact radius on the stable branch at overlap delta >= delta_c. */
double ck_jkr_radius(const ck_jkr *law, double delta);
ck_response ck_jkr_eval(const ck_jkr *law, double delta, const ck_state *old_state,
                        ck_state *new_state);
void ck_jkr_batch(const ck_jkr *law, size_t n, const double *delta,
                  const ck_state *old_state, ck_state *new_state,
                  double *force, double *contact_radius, double *stiffness);

#endif
