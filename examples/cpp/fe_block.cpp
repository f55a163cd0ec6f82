// The homogenised friction law in an FE-like increment loop, through the C++
// bindings: a host code with 16 contact points under normal pressures of
// 20 .. 120 MPa prescribes their slip each increment (forward along a
// direction at 30 degrees, then back), calls Friction::step_block_in_place
// once per increment (the homogenised law as an asperity::Friction) with the
// per-point states stepped in place, and reads the tangential forces and the
// dissipated energy.
//
// Every point sticks (elastic, stiffness k) until its force reaches the slip
// limit mu(p)(N + A), then slides; on reversal it unloads elastically through
// 2 mu(N + A)/k and slides the other way. With constant N the dissipation of
// a point is its slip limit times its plastic slip path 2D - 3 limit/k.
//
// Prints "CHECK <name> <value>" lines read by tests/cpp_bindings.rs.
#include <asperity.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

static void check(const char* name, double value)
{
    std::printf("CHECK %s %.17g\n", name, value);
}

static AsperityHomogenisedSample sample(double p_mpa, double mu, double adhesion_mpa,
                                        double fraction, double chemical, double vdw,
                                        double elastic)
{
    AsperityHomogenisedSample s{};
    s.pressure = p_mpa * 1e6;
    s.cof = mu;
    s.adhesion_pressure = adhesion_mpa * 1e6;
    s.contact_fraction = fraction;
    s.shares.chemical = chemical;
    s.shares.van_der_waals = vdw;
    s.shares.elastic = elastic;
    s.shares.plastic = 1.0 - chemical - vdw - elastic;
    return s;
}

int main()
{
    constexpr std::size_t points = 16;
    constexpr int forward = 500;    // increments forward, then as many back
    const double area = 1e-6;       // m^2 per point
    const double k = 1e7;           // stick stiffness (N/m)
    const double ds = 1e-7;         // slip increment magnitude (m)
    const double dt = 1e-5;         // s (unused by this rate-independent law)
    const double pi = std::acos(-1.0);
    const double ex = std::cos(pi / 6.0);
    const double ey = std::sin(pi / 6.0);

    try {
        const std::vector<AsperityHomogenisedSample> samples{
            sample(20.0, 1.05, 2.0, 0.02, 0.93, 0.06, 0.005),
            sample(70.0, 0.98, 6.0, 0.07, 0.92, 0.065, 0.01),
            sample(120.0, 0.92, 10.0, 0.12, 0.90, 0.07, 0.02),
        };
        const asperity::HomogenisedFriction table(samples);
        // The friction law: the table with the stick stiffness k.
        const asperity::Friction law = asperity::Friction::from_homogenised(table, k);
        asperity::FrictionWork work = law.work();
        const std::size_t m = law.state_size();
        // The state: dissipation, slip path, stick force (x, y), plastic slip
        // path, dissipation by mechanism (4).
        check("state_size_matches", m == ASPERITY_HOMOGENISED_STATE_MECHANISMS + 4);
        check("points", static_cast<double>(points));

        // The host's arrays: normal forces, areas, interleaved slips and
        // forces, one state of m doubles per point (all-zero: fresh).
        std::vector<double> normal(points);
        std::vector<double> areas(points, area);
        std::vector<double> slip(2 * points);
        std::vector<double> force(2 * points);
        std::vector<double> dissipated(points);
        std::vector<double> states(points * m);
        for (std::size_t i = 0; i < points; ++i) {
            const double p = 20e6 + 100e6 * static_cast<double>(i) / (points - 1);
            normal[i] = p * area;
        }

        double total_dissipation = 0.0;
        double min_increment_dissipation = 0.0;
        long first_slip_point0 = -1;
        double along_end_forward = 0.0;
        int scalar_equals_block = 1;
        for (int n = 1; n <= 2 * forward; ++n) {
            const double sign = n <= forward ? 1.0 : -1.0;
            for (std::size_t i = 0; i < points; ++i) {
                slip[2 * i] = sign * ds * ex;
                slip[2 * i + 1] = sign * ds * ey;
            }
            // Once, the scalar step on copies of the states must give the
            // block's forces bit for bit.
            std::vector<double> copies;
            if (n == forward / 2) {
                copies = states;
            }
            law.step_block_in_place(normal, areas, slip, dt, states, force, dissipated, &work);
            if (n == forward / 2) {
                for (std::size_t i = 0; i < points; ++i) {
                    AsperityFrictionIncrement inc{};
                    inc.normal_force = normal[i];
                    inc.area = area;
                    inc.slip[0] = slip[2 * i];
                    inc.slip[1] = slip[2 * i + 1];
                    inc.dt = dt;
                    const AsperityFrictionResponse r =
                        law.step_in_place(inc, {&copies[i * m], m}, &work);
                    scalar_equals_block &= r.force[0] == force[2 * i] &&
                                           r.force[1] == force[2 * i + 1] &&
                                           r.dissipated == dissipated[i];
                }
            }
            double along = 0.0;
            for (std::size_t i = 0; i < points; ++i) {
                along += force[2 * i] * ex + force[2 * i + 1] * ey;
                total_dissipation += dissipated[i];
                min_increment_dissipation = std::min(min_increment_dissipation, dissipated[i]);
            }
            if (first_slip_point0 < 0 && dissipated[0] > 0.0) {
                first_slip_point0 = n;
            }
            if (n == forward) {
                along_end_forward = along;
            }
            if (n % 100 == 0) {
                std::printf("history %4d  slip_x_um %8.3f  force_along_N %12.6f\n", n,
                            1e6 * ds * ex * (n <= forward ? n : 2 * forward - n), along);
            }
            if (n == 2 * forward) {
                check("force_along_end_forward", along_end_forward);
                check("force_along_end_backward", along);
            }
        }
        check("first_slip_increment_point0", static_cast<double>(first_slip_point0));
        check("scalar_equals_block", scalar_equals_block);
        check("total_dissipation", total_dissipation);
        check("min_increment_dissipation", min_increment_dissipation);
        // The states' ledgers: the dissipation by mechanism, and the slip
        // path, which every increment of every point adds |slip| to.
        double ledger = 0.0;
        double slip_path = 0.0;
        for (std::size_t i = 0; i < points; ++i) {
            const double* s = &states[i * m];
            for (std::size_t j = 0; j < 4; ++j) {
                ledger += s[ASPERITY_HOMOGENISED_STATE_MECHANISMS + j];
            }
            slip_path += s[ASPERITY_FRICTION_STATE_SLIP_PATH];
        }
        check("ledger_total", ledger);
        check("slip_path_total", slip_path);
        check("slip_increment", ds);
        check("stick_stiffness", k);
        check("forward_increments", forward);

        // The law saved and reloaded steps identically.
        const asperity::Friction reloaded = asperity::Friction::from_homogenised(
            asperity::HomogenisedFriction::from_json(table.to_json()), k);
        AsperityFrictionIncrement inc{};
        inc.normal_force = normal[5];
        inc.area = area;
        inc.slip[0] = 3e-6;
        const std::vector<double> fresh(m);
        std::vector<double> scratch(m);
        const AsperityFrictionResponse r1 = law.step(inc, fresh, scratch);
        const AsperityFrictionResponse r2 = reloaded.step(inc, fresh, scratch);
        check("json_roundtrip_identical", r1.force[0] == r2.force[0] && r1.cof == r2.cof);

        // A bad value in the host's arrays: the library names the element.
        areas[3] = -1.0;
        try {
            law.step_block_in_place(normal, areas, slip, dt, states, force);
            check("bad_area_threw", 0);
        } catch (const asperity::Error& e) {
            const std::string message = e.what();
            check("bad_area_threw", 1);
            check("bad_area_status", e.status());
            check("bad_area_names_element", message.find("element 3") != std::string::npos);
            check("bad_area_names_area", message.find("area") != std::string::npos);
        }
        // Arrays of the wrong length: the C++ layer names the argument.
        areas.resize(points - 1);
        try {
            law.step_block_in_place(normal, areas, slip, dt, states, force);
            check("short_areas_threw", 0);
        } catch (const asperity::Error& e) {
            check("short_areas_threw", 1);
            check("short_areas_status", e.status());
            check("short_areas_names_areas",
                  std::string(e.what()).find("`areas`") != std::string::npos);
        }
    } catch (const asperity::Error& e) {
        std::fprintf(stderr, "fe_block: status %d (%s): %s\n", static_cast<int>(e.status()),
                     e.status_string(), e.what());
        return 1;
    }
    return 0;
}
