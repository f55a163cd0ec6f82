// The full hierarchical slider as the friction law of a few FE surface
// patches, through the C++ bindings (examples/c/slider_patch.c in C++): each
// patch is one slider of the chapter-6 scene (90 micro-rods of 1.5 um x
// 13.5 um carrying nano-asperities) against the counter-surface profile, with
// its own caller-owned state, normal force and slip direction.
//
// The program reads examples/scenes/chapter6_copper.json (or the scene given
// as the first argument; without an argument and run from elsewhere than the
// crate root it uses an inline copy of that scene), builds an
// asperity::Slider once, its friction law asperity::Friction::from_slider
// and one asperity::FrictionWork, and steps four patches with
// Friction::step_block_in_place (the call shape of an Abaqus/Explicit VFRIC
// user subroutine) for 60 increments of |slip| = 1.5 um:
//
//   patch  normal force           slip direction   start on the track
//   0      0.05 x capacity        +x               0
//   1      0.10 x capacity        30 degrees       45 um
//   2      0.20 x capacity        +y               0
//   3      0.35 x capacity        -x               0
//
// The states start all-zero (fresh: the first call seats each patch) and are
// stepped in place. Copies of the states are stepped alongside, one patch at
// a time with Friction::step_in_place, and must agree bit for bit. After each
// block, FrictionWork::slider_record() gives the full record of its last
// point's step (positions, counts of contacts, whether the step seated a
// fresh state), checked against the state. Then one scalar step with
// tangents (its record printed for tests/cpp_bindings.rs to compare with the
// Rust API), a re-evaluation of an increment from the same old state, a
// zero-slip increment and errors caught as asperity::Error.
//
// The program checks itself: it prints "CHECK <name> <value>" lines, and
// every failed expectation on stderr, and exits non-zero when one failed.
#include <asperity.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

constexpr std::size_t NP = 4;
constexpr int STEPS = 60;
constexpr double STEP = 1.5e-6; // slip per increment (m)
constexpr double DT = 1e-5;     // time increment (s), unused by the law

// examples/scenes/chapter6_copper.json, for runs outside the crate root.
const char* const INLINE_SCENE = R"({
  "material": { "preset": "copper" },
  "surfaces": {
    "slider": {
      "self_affine": { "hurst": 0.8, "rq": 5e-7, "roll_off_wavelength": 1e-4,
                       "points": 91, "dx": 1.5e-6, "seed": 6 }
    },
    "counter": {
      "self_affine": { "hurst": 0.8, "rq": 5e-7, "roll_off_wavelength": 1e-4,
                       "points": 241, "dx": 1.5e-6, "seed": 7 }
    },
    "nano": {
      "asperities": { "h_vdw": 6e-9, "w_vdw": 4.3e-7, "h_chem": 2.2e-9, "w_chem": 1.61e-7,
                      "spacing": 1.35e-6 }
    }
  },
  "rods": { "widths": [1.5e-6], "depth": 1.35e-5 },
  "mechanisms": { "chemical": true, "van_der_waals": true, "elastic": true, "plastic": true },
  "cof_form": "Derjaguin",
  "loading": { "fixed_load": { "load": 0.18 } },
  "sliding": { "distance": 1.5e-4, "step": 1.5e-6 },
  "outputs": { "csv": true, "svg": true }
})";

int failures = 0;

void check(const std::string& name, double value)
{
    std::printf("CHECK %s %.17g\n", name.c_str(), value);
}

/// Record an expectation; a failure is reported on stderr and counted.
void expect(const std::string& name, bool ok, const std::string& detail)
{
    if (!ok) {
        ++failures;
        std::fprintf(stderr, "slider_patch: FAILED %s: %s\n", name.c_str(), detail.c_str());
    }
}

double rel_diff(double got, double want)
{
    const double scale = std::fabs(want) > 0.0 ? std::fabs(want) : 1.0;
    return std::fabs(got - want) / scale;
}

/// Check `value` against `[lo, hi]`, print it and record the outcome.
void within(const std::string& name, double value, double lo, double hi)
{
    check(name, value);
    expect(name, value >= lo && value <= hi,
           std::to_string(value) + " outside [" + std::to_string(lo) + ", " +
               std::to_string(hi) + "]");
}

bool same_bits(const void* a, const void* b, std::size_t bytes)
{
    return std::memcmp(a, b, bytes) == 0;
}

bool read_file(const char* path, std::string& text)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return false;
    }
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

/// Run `call`, which must throw asperity::Error with `status` and a message
/// containing each of `words`.
template <class Call>
void expect_error(const std::string& name, std::int32_t status,
                  const std::vector<std::string>& words, Call call)
{
    try {
        call();
        expect(name, false, "no asperity::Error thrown");
    } catch (const asperity::Error& e) {
        const std::string message = e.what();
        check(name + "_status", e.status());
        expect(name, e.status() == status,
               "status " + std::to_string(e.status()) + ", expected " + std::to_string(status) +
                   " (" + message + ")");
        for (const std::string& w : words) {
            expect(name, message.find(w) != std::string::npos,
                   "message `" + message + "` lacks `" + w + "`");
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    const char* path = argc > 1 ? argv[1] : "examples/scenes/chapter6_copper.json";
    std::string json;
    if (!read_file(path, json)) {
        if (argc > 1) {
            std::fprintf(stderr, "slider_patch: cannot read %s\n", path);
            return 1;
        }
        std::printf("# %s not found from here: the inline copy of the scene\n", path);
        json = INLINE_SCENE;
    }

    try {
        // The scene names no files; a scene that does would pass its
        // directory as base_dir.
        const asperity::Slider slider = asperity::Slider::from_scene_json(json);
        const asperity::Friction law = asperity::Friction::from_slider(slider);
        asperity::FrictionWork work(law);
        const AsperitySliderInfo info = slider.info();
        const std::size_t m = law.state_size();
        check("state_size", static_cast<double>(m));
        check("rods", static_cast<double>(info.rods));
        check("capacity", info.capacity);
        expect("state_size",
               m == info.state_size && m == ASPERITY_SLIDER_STATE_HEIGHTS + 2 * info.rods,
               std::to_string(m) + " doubles, info says " + std::to_string(info.state_size) +
                   " for " + std::to_string(info.rods) + " rods");
        expect("capacity", info.capacity > 0.0 && std::isfinite(info.capacity),
               std::to_string(info.capacity));
        std::printf("# slider: %zu rods of %.2f um x %.2f um, nominal area %.4e m^2, "
                    "capacity %.6f N\n",
                    info.rods, info.rod_width * 1e6, info.depth * 1e6, info.nominal_area,
                    info.capacity);

        const double fraction[NP] = {0.05, 0.10, 0.20, 0.35};
        const double start[NP] = {0.0, 45e-6, 0.0, 0.0};
        const double direction[NP][2] = {
            {1.0, 0.0}, {std::sqrt(3.0) / 2.0, 0.5}, {0.0, 1.0}, {-1.0, 0.0}};
        std::vector<double> normal(NP), slip(2 * NP), force(2 * NP), diss(NP);
        std::vector<double> states(NP * m, 0.0); // all-zero: fresh
        std::vector<double> work_done(NP, 0.0), dissipated(NP, 0.0), force_sum(NP, 0.0);
        for (std::size_t i = 0; i < NP; ++i) {
            normal[i] = fraction[i] * info.capacity;
            slip[2 * i] = STEP * direction[i][0];
            slip[2 * i + 1] = STEP * direction[i][1];
            // A fresh state starts at its position: stagger the patches.
            states[i * m + ASPERITY_SLIDER_STATE_POSITION] = start[i];
        }
        // The same patches stepped one at a time with Friction::step_in_place.
        std::vector<double> scalar = states;
        double min_diss = 0.0;
        double max_misalignment = 0.0;
        bool opposes = true;
        bool block_equals_scalar = true;
        // The record of the block's last point (patch NP - 1) after each block.
        bool record_seated = true;
        bool record_matches_state = true;
        bool record_counts = true;
        double record_max_advance_diff = 0.0;
        AsperitySliderRecord last{};
        const std::size_t lp = (NP - 1) * m; // the last patch's state

        for (int n = 0; n < STEPS; ++n) {
            const double before = states[lp + ASPERITY_SLIDER_STATE_POSITION];
            law.step_block_in_place(normal, {}, slip, DT, states, force, diss, &work);
            // Read before the scalar steps below reuse the work. Seated (fresh
            // state) on the first block only; the slider advanced along its
            // track by |slip|, to the state's position; the counts nest.
            last = work.slider_record();
            if (n < 2) {
                check("record_block" + std::to_string(n) + "_seated", last.seated);
                check("record_block" + std::to_string(n) + "_position", last.position);
            }
            record_seated = record_seated && last.seated == (n == 0 ? 1 : 0);
            record_matches_state =
                record_matches_state &&
                last.position == states[lp + ASPERITY_SLIDER_STATE_POSITION] &&
                same_bits(&last.rod_position, &states[lp + ASPERITY_SLIDER_STATE_ROD_POSITION],
                          sizeof(double));
            record_max_advance_diff =
                std::fmax(record_max_advance_diff, std::fabs(last.position - before - STEP));
            record_counts = record_counts && last.nano_contacts > 0 &&
                            last.adhesive_contacts <= last.nano_contacts &&
                            last.rods_in_contact > 0 && last.rods_in_contact <= info.rods &&
                            last.yielded_rods <= last.rods_in_contact &&
                            last.adhesion_area_share >= 0.0 && last.adhesion_area_share <= 1.0 &&
                            last.reserved == 0;
            for (std::size_t i = 0; i < NP; ++i) {
                AsperityFrictionIncrement inc{};
                inc.normal_force = normal[i];
                inc.slip[0] = slip[2 * i];
                inc.slip[1] = slip[2 * i + 1];
                inc.dt = DT;
                const asperity::span<double> one{scalar.data() + i * m, m};
                const AsperityFrictionResponse r = law.step_in_place(inc, one, &work);
                block_equals_scalar = block_equals_scalar &&
                                      same_bits(r.force, &force[2 * i], sizeof r.force) &&
                                      same_bits(&r.dissipated, &diss[i], sizeof(double));

                const double fx = force[2 * i];
                const double fy = force[2 * i + 1];
                const double sx = slip[2 * i];
                const double sy = slip[2 * i + 1];
                const double fm = std::hypot(fx, fy);
                const double dot = fx * sx + fy * sy;
                work_done[i] += -dot;
                dissipated[i] += diss[i];
                force_sum[i] += fm;
                min_diss = std::fmin(min_diss, diss[i]);
                opposes = opposes && dot < 0.0;
                if (fm > 0.0) {
                    max_misalignment =
                        std::fmax(max_misalignment, std::fabs(fx * sy - fy * sx) / (fm * STEP));
                }
            }
        }
        block_equals_scalar =
            block_equals_scalar && same_bits(states.data(), scalar.data(), NP * m * sizeof(double));
        check("block_equals_scalar", block_equals_scalar);
        expect("block_equals_scalar", block_equals_scalar,
               "Friction::step_block_in_place and Friction::step_in_place differ on the same "
               "increments");

        std::printf(
            "# patch  normal_N  mean_friction_N  friction_over_load  dissipation_J  slip_path_m\n");
        for (std::size_t i = 0; i < NP; ++i) {
            const double* s = states.data() + i * m;
            const double* d = s + ASPERITY_SLIDER_STATE_MECHANISMS;
            const double acc = d[0] + d[1] + d[2] + d[3];
            const double mean = force_sum[i] / STEPS;
            const std::string p = "patch" + std::to_string(i) + "_";
            std::printf("patch %zu %.6e %.9e %.6f %.9e %.6e\n", i, normal[i], mean,
                        mean / normal[i], dissipated[i], s[ASPERITY_FRICTION_STATE_SLIP_PATH]);
            check(p + "mean_friction_force", mean);
            check(p + "dissipation", dissipated[i]);
            expect(p + "dissipation", dissipated[i] > 0.0, std::to_string(dissipated[i]));
            // The work of the friction force is the dissipated energy.
            within(p + "work_dissipation_rel_diff", rel_diff(work_done[i], dissipated[i]), 0.0,
                   1e-12);
            // The state's ledgers sum the increments: by mechanism, and the
            // total.
            within(p + "state_dissipation_rel_diff", rel_diff(acc, dissipated[i]), 0.0, 1e-12);
            within(p + "state_total_dissipation_rel_diff",
                   rel_diff(s[ASPERITY_FRICTION_STATE_DISSIPATION], dissipated[i]), 0.0, 1e-12);
            // The slider advances along its track by |slip| per increment.
            within(p + "slip_path_rel_diff",
                   rel_diff(s[ASPERITY_FRICTION_STATE_SLIP_PATH], STEPS * STEP), 0.0, 1e-12);
            within(p + "position_rel_diff",
                   rel_diff(s[ASPERITY_SLIDER_STATE_POSITION], start[i] + STEPS * STEP), 0.0,
                   1e-12);
            // Chemical bonds dominate (thesis 6.5.2).
            within(p + "chemical_share", d[0] / acc, 0.5, 1.0);
        }
        within("min_increment_dissipation", min_diss, 0.0, 0.0);
        within("max_misalignment", max_misalignment, 0.0, 1e-15);
        check("opposes_slip", opposes);
        expect("opposes_slip", opposes, "a tangential force did not oppose the slip");
        check("record_seated_ok", record_seated);
        expect("record_seated_ok", record_seated,
               "the record says seated other than on the first step of a fresh state");
        check("record_position_matches_state", record_matches_state);
        expect("record_position_matches_state", record_matches_state,
               "the record's positions differ from the state's");
        within("record_max_advance_diff", record_max_advance_diff, 0.0, 1e-18);
        check("record_counts_consistent", record_counts);
        expect("record_counts_consistent", record_counts,
               "adhesive > nano contacts, yielded > rods in contact, or no contact");
        std::printf("# record of patch %zu's last step: X = %.6e m, b = %.6e m, %llu nano "
                    "contacts (%llu adhesive), %llu rods in contact (%llu yielded)\n",
                    NP - 1, last.position, last.rod_position,
                    static_cast<unsigned long long>(last.nano_contacts),
                    static_cast<unsigned long long>(last.adhesive_contacts),
                    static_cast<unsigned long long>(last.rods_in_contact),
                    static_cast<unsigned long long>(last.yielded_rods));

        // One scalar step of patch 0 with both tangents, from its state.
        {
            AsperityFrictionIncrement inc{};
            inc.normal_force = normal[0];
            inc.slip[0] = STEP;
            inc.dt = DT;
            inc.tangents = ASPERITY_FRICTION_TANGENT_NORMAL | ASPERITY_FRICTION_TANGENT_SLIP;
            const asperity::span<const double> old{states.data(), m};
            std::vector<double> a(m), b(m);
            const AsperityFrictionResponse r = law.step(inc, old, a, &work);
            check("tangent_friction_force", r.force_magnitude);
            check("tangent_dfdn", r.dforce_dnormal[0]);
            check("tangent_dfds_along", r.dforce_dslip[0][0]);
            within("tangents_flag", r.tangents, 3.0, 3.0);
            // Across the slip the force turns with it: -F_t/|slip|.
            within("tangent_transverse_rel_diff",
                   rel_diff(r.dforce_dslip[1][1], -r.force_magnitude / STEP), 0.0, 1e-12);
            // Force along -x for slip along +x; F_t |slip| is the dissipation.
            within("tangent_force_rel_diff", rel_diff(r.force[0], -r.force_magnitude), 0.0, 0.0);
            within("tangent_work_rel_diff", rel_diff(r.force_magnitude * STEP, r.dissipated), 0.0,
                   1e-12);
            // The step's own record, not a tangent evaluation's: one |slip|
            // further than the old state, at the new state's position.
            const AsperitySliderRecord rec = work.slider_record();
            check("tangent_record_position", rec.position);
            within("tangent_record_advance_diff",
                   std::fabs(rec.position - old[ASPERITY_SLIDER_STATE_POSITION] - STEP), 0.0,
                   1e-18);
            const bool rec_state = rec.position == a[ASPERITY_SLIDER_STATE_POSITION] &&
                                   same_bits(&rec.rod_position,
                                             &a[ASPERITY_SLIDER_STATE_ROD_POSITION],
                                             sizeof(double));
            check("tangent_record_matches_state", rec_state);
            expect("tangent_record_matches_state", rec_state,
                   "the record's positions differ from the new state's");
            check("tangent_record_rod_position", rec.rod_position);
            check("tangent_record_adhesion_area_share", rec.adhesion_area_share);
            check("tangent_record_nano_contacts", static_cast<double>(rec.nano_contacts));
            check("tangent_record_adhesive_contacts",
                  static_cast<double>(rec.adhesive_contacts));
            check("tangent_record_rods_in_contact", static_cast<double>(rec.rods_in_contact));
            check("tangent_record_yielded_rods", static_cast<double>(rec.yielded_rods));
            within("tangent_record_seated", rec.seated, 0.0, 0.0);
            // Re-evaluating the increment from the same old state (a
            // cut-back) gives identical results; the old state is untouched.
            const std::vector<double> before(old.begin(), old.end());
            const AsperityFrictionResponse r2 = law.step(inc, old, b, &work);
            const AsperitySliderRecord rec2 = work.slider_record();
            const bool identical = same_bits(&r, &r2, sizeof r) &&
                                   same_bits(&rec, &rec2, sizeof rec) &&
                                   same_bits(a.data(), b.data(), m * sizeof(double)) &&
                                   same_bits(before.data(), states.data(), m * sizeof(double));
            check("reevaluation_identical", identical);
            expect("reevaluation_identical", identical, "re-evaluating an increment differed");
            // A zero slip increment: stick, no force, nothing dissipated.
            inc.slip[0] = 0.0;
            inc.tangents = 0;
            const AsperityFrictionResponse z = law.step(inc, old, a, &work);
            within("zero_slip_force", std::fabs(z.force[0]) + std::fabs(z.force[1]), 0.0, 0.0);
            within("zero_slip_dissipated", z.dissipated, 0.0, 0.0);
            within("zero_slip_regime", z.regime, ASPERITY_FRICTION_STICK,
                   ASPERITY_FRICTION_STICK);
            // The rods re-seated where the slider stands: no advance.
            const AsperitySliderRecord zr = work.slider_record();
            within("zero_slip_record_advance", zr.position - old[ASPERITY_SLIDER_STATE_POSITION],
                   0.0, 0.0);
            within("zero_slip_record_seated", zr.seated, 0.0, 0.0);
        }

        // Errors. A normal force above the capacity at element 2 names the
        // element and the argument; elements before are written, the rest
        // untouched.
        {
            const std::vector<double> copy = states;
            std::vector<double> bad = normal;
            bad[2] = 2.0 * info.capacity;
            expect_error("bad_load", ASPERITY_ERR_OUT_OF_DOMAIN, {"element 2", "`normal_force`"},
                         [&] {
                             law.step_block_in_place(bad, {}, slip, DT, states, force, diss,
                                                     &work);
                         });
            const bool before_written =
                !same_bits(copy.data(), states.data(), 2 * m * sizeof(double));
            const bool rest_untouched =
                same_bits(copy.data() + 2 * m, states.data() + 2 * m, 2 * m * sizeof(double));
            check("bad_load_before_written", before_written);
            check("bad_load_rest_untouched", rest_untouched);
            expect("bad_load_before_written", before_written, "patches 0 and 1 not stepped");
            expect("bad_load_rest_untouched", rest_untouched, "patches 2 and 3 changed");
        }
        // States too short for the patches: the C++ layer names the
        // argument before calling the library; nothing is written.
        {
            std::vector<double> short_states(NP * m - 1, 0.0);
            const std::vector<double> copy = short_states;
            expect_error("short_states", ASPERITY_ERR_INVALID_ARGUMENT, {"`old_states`"}, [&] {
                law.step_block(normal, {}, slip, DT, short_states, short_states, force, {},
                               &work);
            });
            expect("short_states_untouched", copy == short_states, "short states were written");
        }
        // An unknown tangents bit names `tangents`.
        expect_error("bad_tangents", ASPERITY_ERR_INVALID_ARGUMENT, {"`tangents`"}, [&] {
            AsperityFrictionIncrement inc{};
            inc.tangents = 8;
            std::vector<double> st(m, 0.0);
            (void)law.step_in_place(inc, st, &work);
        });
        // An empty handle is a NULL pointer named `slider` (`law` for the
        // friction law).
        expect_error("null_handle", ASPERITY_ERR_NULL_POINTER, {"`slider`"}, [&] {
            const asperity::Slider empty;
            (void)empty.info();
        });
        expect_error("null_law", ASPERITY_ERR_NULL_POINTER, {"`law`"}, [&] {
            const asperity::Friction empty;
            (void)empty.state_size();
        });
        // An empty work has no record: a NULL pointer named `work`.
        expect_error("record_null_work", ASPERITY_ERR_NULL_POINTER, {"`work`"}, [&] {
            const asperity::FrictionWork empty;
            (void)empty.slider_record();
        });
        // A scene with a wrong field type is a parse error.
        expect_error("bad_scene", ASPERITY_ERR_PARSE, {"`json`"}, [] {
            (void)asperity::Slider::from_scene_json(R"({ "material": 3 })");
        });
        // With a base directory for the files a scene names (this one names
        // none): the same slider.
        {
            const std::string dir = ".";
            const asperity::Slider again = asperity::Slider::from_scene_json(json, dir);
            const AsperitySliderInfo info2 = again.info();
            const bool same_info = same_bits(&info, &info2, sizeof info);
            check("base_dir_same_slider", same_info);
            expect("base_dir_same_slider", same_info, "a slider built with base_dir differs");
        }
        // A work built for this slider, moved: the moved-from one is empty.
        {
            asperity::FrictionWork moved = std::move(work);
            expect("work_moved", moved && !work, "moving a FrictionWork did not transfer it");
        }
    } catch (const asperity::Error& e) {
        std::fprintf(stderr, "slider_patch: unexpected error: status %d (%s): %s\n",
                     static_cast<int>(e.status()), e.status_string(), e.what());
        return 1;
    }

    if (failures != 0) {
        std::fprintf(stderr, "slider_patch: %d check(s) failed\n", failures);
        return 1;
    }
    std::printf("# all checks passed\n");
    return 0;
}
