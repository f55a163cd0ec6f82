/*
 * The full hierarchical slider as the friction law of a few FE surface
 * patches (thesis chapter 6; issue 6 section 4 (a)): each patch is one
 * slider of the chapter-6 scene (90 micro-rods of 1.5 um x 13.5 um carrying
 * nano-asperities) against the counter-surface profile, with its own
 * caller-owned state, normal force and slip direction.
 *
 * The program reads examples/scenes/chapter6_copper.json (or the scene given
 * as the first argument), builds the slider once and its friction law (one
 * AsperityFriction handle, asperity_friction_from_slider), and steps four
 * patches with asperity_friction_step_block (the call shape of an
 * Abaqus/Explicit VFRIC user subroutine) for 60 increments of
 * |slip| = 1.5 um:
 *
 *   patch  normal force           slip direction   start on the track
 *   0      0.05 x capacity        +x               0
 *   1      0.10 x capacity        30 degrees       45 um
 *   2      0.20 x capacity        +y               0
 *   3      0.35 x capacity        -x               0
 *
 * The states start all-zero (fresh: the first call seats each patch) and are
 * stepped in place. After each block the work holds the full record of its
 * last point's step (asperity_slider_record: positions, counts of contacts,
 * whether the step seated a fresh state), read and checked against the
 * state. Then one scalar step with tangents (its record printed for the
 * test to compare with the Rust API), a re-evaluation of an increment from
 * the same old state, a zero-slip increment and the error cases.
 *
 * Prints a row per patch and lines "CHECK <name> <value>" read by
 * tests/c_examples.rs.
 */
#include "asperity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NP 4
#define STEPS 60

static const double STEP = 1.5e-6; /* slip per increment (m) */
static const double DT = 1e-5;     /* time increment (s), unused by the law */

static int failed(int32_t status, const char *what)
{
    char msg[512];
    if (status == ASPERITY_OK) {
        return 0;
    }
    asperity_last_error_message(msg, sizeof msg);
    fprintf(stderr, "slider_patch: %s failed: status %d (%s): %s\n", what, (int)status,
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

/* The whole file at `path`, NUL-terminated, its length in *len; NULL on
 * failure. */
static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *text;
    long size;
    if (f == NULL) {
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    text = (char *)malloc((size_t)size + 1);
    if (text == NULL || fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        fclose(f);
        return NULL;
    }
    fclose(f);
    text[size] = '\0';
    *len = (size_t)size;
    return text;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "examples/scenes/chapter6_copper.json";
    static const double fraction[NP] = {0.05, 0.10, 0.20, 0.35};
    static const double start[NP] = {0.0, 45e-6, 0.0, 0.0};
    double direction[NP][2];
    double normal[NP], slip[2 * NP], force[2 * NP], diss[NP];
    double work_done[NP], dissipated[NP], force_sum[NP];
    double min_diss = 0.0, max_misalignment = 0.0;
    int opposes = 1;
    /* The record of the block's last point (patch NP - 1) after each block. */
    int record_seated_ok = 1, record_position_ok = 1, record_counts_ok = 1;
    double record_max_advance_diff = 0.0;
    AsperitySliderRecord rec;
    AsperitySlider *slider = NULL;
    AsperityFriction *law = NULL;
    AsperityFrictionWork *work = NULL;
    AsperitySliderInfo info;
    double *states, *copy, *a, *b;
    size_t m = 0, len = 0;
    char *json;
    int i, n;

    json = read_file(path, &len);
    if (json == NULL) {
        fprintf(stderr, "slider_patch: cannot read %s (run from the crate root or pass a path)\n",
                path);
        return EXIT_FAILURE;
    }
    /* The scene names no files; a scene that does would pass its directory
     * as base_dir. */
    TRY(asperity_slider_from_scene_json(json, len, NULL, &slider));
    free(json);
    TRY(asperity_slider_info(slider, &info));
    /* The slider as the friction law of a patch: the increment's normal
     * force is the fixed load. */
    TRY(asperity_friction_from_slider(slider, &law));
    TRY(asperity_friction_state_size(law, &m));
    TRY(asperity_friction_work_new(law, &work));
    check("state_size", (double)m);
    check("state_size_matches_info", m == info.state_size);
    check("rods", (double)info.rods);
    check("capacity", info.capacity);
    printf("# slider: %zu rods of %.2f um x %.2f um, nominal area %.4e m^2, capacity %.6f N\n",
           info.rods, info.rod_width * 1e6, info.depth * 1e6, info.nominal_area, info.capacity);

    states = (double *)calloc(NP * m, sizeof(double)); /* all-zero: fresh */
    copy = (double *)malloc(NP * m * sizeof(double));
    a = (double *)malloc(m * sizeof(double));
    b = (double *)malloc(m * sizeof(double));
    if (states == NULL || copy == NULL || a == NULL || b == NULL) {
        return EXIT_FAILURE;
    }
    direction[0][0] = 1.0;
    direction[0][1] = 0.0;
    direction[1][0] = sqrt(3.0) / 2.0;
    direction[1][1] = 0.5;
    direction[2][0] = 0.0;
    direction[2][1] = 1.0;
    direction[3][0] = -1.0;
    direction[3][1] = 0.0;
    for (i = 0; i < NP; ++i) {
        normal[i] = fraction[i] * info.capacity;
        slip[2 * i] = STEP * direction[i][0];
        slip[2 * i + 1] = STEP * direction[i][1];
        /* A fresh state starts at its position: stagger the patches. */
        states[i * m + ASPERITY_SLIDER_STATE_POSITION] = start[i];
        work_done[i] = 0.0;
        dissipated[i] = 0.0;
        force_sum[i] = 0.0;
    }

    for (n = 0; n < STEPS; ++n) {
        const double before = states[(NP - 1) * m + ASPERITY_SLIDER_STATE_POSITION];
        TRY(asperity_friction_step_block(law, NP, normal, NULL, slip, DT, states, states, force,
                                         diss, work));
        /* The work holds the record of the last point stepped: patch 3.
         * Seated (fresh state) on the first block only; the slider advanced
         * along its track by |slip|, to the state's position; counts that
         * nest: adhesive contacts among the nano contacts, yielded rods among
         * the rods in contact, among the slider's rods. */
        TRY(asperity_slider_record(work, &rec));
        if (n == 0) {
            check("record_first_seated", rec.seated);
            check("record_first_position", rec.position);
        } else if (n == 1) {
            check("record_second_seated", rec.seated);
            check("record_second_position", rec.position);
        }
        if (rec.seated != (n == 0)) {
            record_seated_ok = 0;
        }
        if (rec.position != states[(NP - 1) * m + ASPERITY_SLIDER_STATE_POSITION] ||
            memcmp(&rec.rod_position, &states[(NP - 1) * m + ASPERITY_SLIDER_STATE_ROD_POSITION],
                   sizeof(double)) != 0) {
            record_position_ok = 0;
        }
        if (fabs(rec.position - before - STEP) > record_max_advance_diff) {
            record_max_advance_diff = fabs(rec.position - before - STEP);
        }
        if (!(rec.nano_contacts > 0 && rec.adhesive_contacts <= rec.nano_contacts &&
              rec.rods_in_contact > 0 && rec.rods_in_contact <= info.rods &&
              rec.yielded_rods <= rec.rods_in_contact && rec.adhesion_area_share >= 0.0 &&
              rec.adhesion_area_share <= 1.0 && rec.reserved == 0)) {
            record_counts_ok = 0;
        }
        for (i = 0; i < NP; ++i) {
            const double fx = force[2 * i], fy = force[2 * i + 1];
            const double sx = slip[2 * i], sy = slip[2 * i + 1];
            const double fm = hypot(fx, fy);
            const double dot = fx * sx + fy * sy;
            work_done[i] += -dot;
            dissipated[i] += diss[i];
            force_sum[i] += fm;
            if (diss[i] < min_diss) {
                min_diss = diss[i];
            }
            if (!(dot < 0.0)) {
                opposes = 0;
            }
            if (fm > 0.0 && fabs(fx * sy - fy * sx) / (fm * STEP) > max_misalignment) {
                max_misalignment = fabs(fx * sy - fy * sx) / (fm * STEP);
            }
        }
    }

    printf("# patch  normal_N  mean_friction_N  friction_over_load  dissipation_J  slip_path_m\n");
    for (i = 0; i < NP; ++i) {
        const double *s = states + i * m;
        const double *d = s + ASPERITY_SLIDER_STATE_MECHANISMS;
        const double acc = d[0] + d[1] + d[2] + d[3];
        char name[64];
        printf("patch %d %.6e %.9e %.6f %.9e %.6e\n", i, normal[i], force_sum[i] / STEPS,
               force_sum[i] / STEPS / normal[i], dissipated[i],
               s[ASPERITY_FRICTION_STATE_SLIP_PATH]);
        sprintf(name, "patch%d_mean_friction_force", i);
        check(name, force_sum[i] / STEPS);
        sprintf(name, "patch%d_dissipation", i);
        check(name, dissipated[i]);
        /* The work of the friction force is the dissipated energy. */
        sprintf(name, "patch%d_work_dissipation_rel_diff", i);
        check(name, rel_diff(work_done[i], dissipated[i]));
        /* The state's ledgers sum the increments: by mechanism, and the
         * total. */
        sprintf(name, "patch%d_state_dissipation_rel_diff", i);
        check(name, rel_diff(acc, dissipated[i]));
        sprintf(name, "patch%d_state_total_dissipation_rel_diff", i);
        check(name, rel_diff(s[ASPERITY_FRICTION_STATE_DISSIPATION], dissipated[i]));
        sprintf(name, "patch%d_slip_path", i);
        check(name, s[ASPERITY_FRICTION_STATE_SLIP_PATH]);
        sprintf(name, "patch%d_position", i);
        check(name, s[ASPERITY_SLIDER_STATE_POSITION]);
        sprintf(name, "patch%d_chemical_share", i);
        check(name, d[0] / acc);
    }
    check("min_increment_dissipation", min_diss);
    check("max_misalignment", max_misalignment);
    check("opposes_slip", opposes);
    check("record_seated_ok", record_seated_ok);
    check("record_position_matches_state", record_position_ok);
    check("record_max_advance_diff", record_max_advance_diff);
    check("record_counts_consistent", record_counts_ok);
    printf("# record of patch 3's last step: X = %.6e m, b = %.6e m, %llu nano contacts "
           "(%llu adhesive), %llu rods in contact (%llu yielded)\n",
           rec.position, rec.rod_position, (unsigned long long)rec.nano_contacts,
           (unsigned long long)rec.adhesive_contacts, (unsigned long long)rec.rods_in_contact,
           (unsigned long long)rec.yielded_rods);

    /* One scalar step of patch 0 with both tangents. */
    {
        AsperityFrictionIncrement inc;
        AsperityFrictionResponse r, r2;
        AsperitySliderRecord rec2;
        memset(&inc, 0, sizeof inc);
        inc.normal_force = normal[0];
        inc.slip[0] = STEP;
        inc.slip[1] = 0.0;
        inc.dt = DT;
        inc.tangents = ASPERITY_FRICTION_TANGENT_NORMAL | ASPERITY_FRICTION_TANGENT_SLIP;
        TRY(asperity_friction_step(law, &inc, states, a, work, &r));
        check("tangent_friction_force", r.force_magnitude);
        check("tangent_dfdn", r.dforce_dnormal[0]);
        check("tangent_dfds_along", r.dforce_dslip[0][0]);
        /* Across the slip the force turns with it: -F_t/|slip|. */
        check("tangent_transverse_rel_diff",
              rel_diff(r.dforce_dslip[1][1], -r.force_magnitude / STEP));
        check("tangents_flag", r.tangents);
        /* The step's own record (not a tangent evaluation's), compared by
         * the test with the Rust step's. */
        TRY(asperity_slider_record(work, &rec));
        check("tangent_record_position", rec.position);
        check("tangent_record_advance", rec.position - states[ASPERITY_SLIDER_STATE_POSITION]);
        check("tangent_record_position_matches_state",
              rec.position == a[ASPERITY_SLIDER_STATE_POSITION]);
        check("tangent_record_rod_position", rec.rod_position);
        check("tangent_record_adhesion_area_share", rec.adhesion_area_share);
        check("tangent_record_nano_contacts", (double)rec.nano_contacts);
        check("tangent_record_adhesive_contacts", (double)rec.adhesive_contacts);
        check("tangent_record_rods_in_contact", (double)rec.rods_in_contact);
        check("tangent_record_yielded_rods", (double)rec.yielded_rods);
        check("tangent_record_seated", rec.seated);
        /* Re-evaluating the increment from the same old state (a cut-back)
         * gives identical results, the record included. */
        TRY(asperity_friction_step(law, &inc, states, b, work, &r2));
        TRY(asperity_slider_record(work, &rec2));
        check("reevaluation_identical",
              memcmp(&r, &r2, sizeof r) == 0 && memcmp(a, b, m * sizeof(double)) == 0);
        check("record_reevaluation_identical", memcmp(&rec, &rec2, sizeof rec) == 0);
        /* A zero slip increment: stick, no force, nothing dissipated. */
        inc.slip[0] = 0.0;
        inc.tangents = 0;
        TRY(asperity_friction_step(law, &inc, states, a, work, &r));
        check("zero_slip_force", fabs(r.force[0]) + fabs(r.force[1]));
        check("zero_slip_dissipated", r.dissipated);
        check("zero_slip_regime", r.regime);
        /* The rods re-seated where the slider stands: no advance. */
        TRY(asperity_slider_record(work, &rec));
        check("zero_slip_record_advance", rec.position - states[ASPERITY_SLIDER_STATE_POSITION]);
        check("zero_slip_record_seated", rec.seated);
    }

    /* Errors: a normal force above the capacity at element 2 names the
     * element and the argument; elements before are written, the rest
     * untouched. */
    {
        char msg[512];
        int32_t st;
        memcpy(copy, states, NP * m * sizeof(double));
        normal[2] = 2.0 * info.capacity;
        st = asperity_friction_step_block(law, NP, normal, NULL, slip, DT, states, states, force,
                                          diss, work);
        asperity_last_error_message(msg, sizeof msg);
        check("bad_load_status", st);
        check("bad_load_names_element", strstr(msg, "element 2") != NULL);
        check("bad_load_names_normal_force", strstr(msg, "`normal_force`") != NULL);
        check("bad_load_before_written", memcmp(copy, states, 2 * m * sizeof(double)) != 0);
        check("bad_load_rest_untouched",
              memcmp(copy + 2 * m, states + 2 * m, 2 * m * sizeof(double)) == 0);
        st = asperity_friction_step_block(NULL, NP, normal, NULL, slip, DT, states, states, force,
                                          diss, work);
        check("null_handle_status", st);
        /* A NULL work has no record; the message names `work`. */
        st = asperity_slider_record(NULL, &rec);
        asperity_last_error_message(msg, sizeof msg);
        check("record_null_work_status", st);
        check("record_null_work_names_work", strstr(msg, "`work`") != NULL);
    }

    free(states);
    free(copy);
    free(a);
    free(b);
    asperity_friction_work_free(work);
    asperity_friction_free(law);
    asperity_slider_free(slider);
    asperity_slider_free(NULL);
    return EXIT_SUCCESS;
}
