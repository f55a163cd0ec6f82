// A tour of the C++ bindings (bindings/cpp/asperity.hpp).
//
// A material, the Hertz, JKR and DMT laws of a 1 um sphere, a tabulated
// Maugis-Dugdale law owned by an RAII handle, and a failed call caught as
// asperity::Error with its status and message.
//
// Build (after `cargo build --release`):
//   c++ -std=c++17 -I include -I bindings/cpp examples/cpp/tour.cpp
//       -L target/release -lasperity -Wl,-rpath,target/release -o tour
//
// Prints "CHECK <name> <value>" lines read by tests/cpp_bindings.rs.
#include <asperity.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

static void check(const char* name, double value)
{
    std::printf("CHECK %s %.17g\n", name, value);
}

int main()
{
    try {
        // Two identical bodies, E = 1.82 GPa and nu = 0.3: E* = E/(2(1 - nu^2))
        // = 1 GPa; surface energies 0.025 J/m^2: w = 2 sqrt(g1 g2) = 0.05 J/m^2.
        const double radius = 1e-6;
        const double e_star = asperity::effective_modulus(1.82e9, 0.3, 1.82e9, 0.3);
        const double w =
            asperity::pair_work_of_adhesion(0.025, 0.025, ASPERITY_PAIR_GEOMETRIC_MEAN);
        check("e_star", e_star);
        check("work_of_adhesion", w);
        check("version_matches_header", asperity::version_matches_header() ? 1.0 : 0.0);

        // Laws are plain structs: build once, copy freely.
        const AsperityNormalLaw hertz = asperity::law_hertz(radius, e_star);
        const AsperityNormalResponse h = asperity::normal_eval(hertz, 10e-9);
        check("hertz_force", h.force);
        check("hertz_contact_radius", h.contact_radius);
        check("hertz_stiffness", h.stiffness);

        const AsperityNormalLaw jkr = asperity::law_jkr(radius, e_star, w);
        const AsperityNormalLaw dmt = asperity::law_dmt(radius, e_star, w);
        check("jkr_pull_off_load", asperity::pull_off_force(jkr, ASPERITY_CONTROL_LOAD));
        check("jkr_pull_off_displacement",
              asperity::pull_off_force(jkr, ASPERITY_CONTROL_DISPLACEMENT));
        check("dmt_pull_off_load", asperity::pull_off_force(dmt, ASPERITY_CONTROL_LOAD));
        const AsperityNormalResponse at_1un = asperity::normal_eval_at_load(jkr, 1e-6);
        check("jkr_radius_at_1uN", at_1un.contact_radius);

        // Per-contact history is a plain struct the caller owns (all-zero =
        // fresh). JKR hysteresis: at delta = -1 nm a fresh contact is open,
        // one retracted from 20 nm still sticks.
        AsperityContactState state{};
        const AsperityNormalResponse fresh = asperity::normal_eval(jkr, -1e-9, state);
        check("jkr_fresh_in_contact", fresh.in_contact);
        (void)asperity::normal_eval(jkr, 20e-9, state);
        const AsperityNormalResponse back = asperity::normal_eval(jkr, -1e-9, state);
        check("jkr_retracted_in_contact", back.in_contact);
        check("jkr_retracted_force", back.force);
        check("jkr_retracted_contact_radius", back.contact_radius);
        check("jkr_state_radius_matches", state.contact_radius == back.contact_radius);

        // Many contacts at once, into the caller's arrays.
        const std::vector<double> delta{1e-9, 2e-9, 5e-9, 10e-9};
        std::vector<double> force(delta.size());
        asperity::normal_eval_batch(hertz, delta, {}, {}, force);
        check("hertz_batch_force_3", force[3]);

        // A tabulated Maugis-Dugdale law: an RAII handle, freed when it goes
        // out of scope. Build once, share between threads.
        const double sigma0 = 3.27e7;
        check("maugis_lambda", asperity::maugis_parameter(radius, w, e_star, sigma0));
        asperity::Table table = asperity::Table::maugis_dugdale(radius, e_star, w, sigma0, 1e-4);
        check("table_tolerance", table.max_error());
        check("table_measured_error", table.measured_error());
        check("table_pull_off_load", table.pull_off_force(ASPERITY_CONTROL_LOAD));
        check("table_pull_off_displacement", table.pull_off_force(ASPERITY_CONTROL_DISPLACEMENT));

        // Save and reload: the same law.
        const std::string json = table.to_json();
        const asperity::Table reloaded = asperity::Table::from_json(json);
        check("json_bytes", static_cast<double>(json.size()));
        AsperityContactState s1{};
        AsperityContactState s2{};
        int identical = 1;
        for (int i = 0; i <= 40; ++i) {
            const double d = 10e-9 - 0.5e-9 * i;
            const AsperityNormalResponse a = table.eval(d, s1);
            const AsperityNormalResponse b = reloaded.eval(d, s2);
            identical &= a.force == b.force && a.contact_radius == b.contact_radius &&
                         a.in_contact == b.in_contact;
        }
        check("json_roundtrip_identical", identical);

        // Handles move, never copy; release() hands the pointer back to C.
        asperity::Table moved = std::move(table);
        check("moved_from_is_empty", !table && table.get() == nullptr);
        check("moved_to_holds_table", moved ? 1.0 : 0.0);
        AsperityTable* raw = moved.release();
        double raw_pull_off = 0.0;
        asperity::check(asperity_table_pull_off_force(raw, ASPERITY_CONTROL_LOAD, &raw_pull_off));
        check("raw_pull_off_load", raw_pull_off);
        asperity_table_free(raw);

        // A failed call throws asperity::Error: the status and the message
        // naming the argument and its bound.
        try {
            (void)asperity::law_hertz(-1e-6, e_star);
            check("bad_radius_threw", 0);
        } catch (const asperity::Error& e) {
            const std::string message = e.what();
            check("bad_radius_threw", 1);
            check("bad_radius_status", e.status());
            check("bad_radius_names_radius", message.find("`radius`") != std::string::npos);
            check("bad_radius_message_is_last_error",
                  message == asperity::last_error_message());
            check("bad_radius_status_string_ok",
                  std::string(e.status_string()) == "invalid argument");
            std::printf("message: %s\n", e.what());
        }
        // Too short an output array is caught before the library is called.
        try {
            std::vector<double> short_force(2);
            asperity::normal_eval_batch(hertz, delta, {}, {}, short_force);
            check("short_array_threw", 0);
        } catch (const asperity::Error& e) {
            check("short_array_threw", 1);
            check("short_array_status", e.status());
            check("short_array_names_force",
                  std::string(e.what()).find("`force`") != std::string::npos);
        }
    } catch (const asperity::Error& e) {
        std::fprintf(stderr, "tour: status %d (%s): %s\n", static_cast<int>(e.status()),
                     e.status_string(), e.what());
        return 1;
    }
    return 0;
}
