// A tour of the C++ bindings: every wrapper of bindings/cpp/asperity.hpp that
// the other examples do not already call, each with inputs whose answer is
// known in closed form (REFERENCE.md) or from the Rust API, so a wrapper that
// passes its arguments in the wrong order or reads the wrong output shows up.
// Inputs are chosen asymmetric for that reason.
//
// Prints "CHECK <name> <value>" lines (and a few text lines) read by
// tests/cpp_bindings.rs, which holds the expected values.
#include <asperity.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

const double pi = std::acos(-1.0);
const double radius = 1e-6;
const double e_star = 1e9;
const double w = 0.05;

void check(const char* name, double value)
{
    std::printf("CHECK %s %.17g\n", name, value);
}

void check_bool(const char* name, bool value)
{
    check(name, value ? 1.0 : 0.0);
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b)
{
    double m = a.size() == b.size() ? 0.0 : std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        m = std::max(m, std::fabs(a[i] - b[i]));
    }
    return m;
}

/// Run `call`, expecting asperity::Error; print its status and whether the
/// message contains `needle`.
template <class Call>
void expect_error(const char* name, const char* needle, Call call)
{
    std::string key(name);
    try {
        call();
        check((key + "_threw").c_str(), 0);
    } catch (const asperity::Error& e) {
        check((key + "_threw").c_str(), 1);
        check((key + "_status").c_str(), e.status());
        check_bool((key + "_names_argument").c_str(),
                   std::string(e.what()).find(needle) != std::string::npos);
    }
}

void version_and_status()
{
    std::printf("version: %s\n", asperity::version());
    std::printf("status_string -4: %s\n", asperity::status_string(ASPERITY_ERR_OUT_OF_DOMAIN));
    std::printf("flag_name 1: %s\n", asperity::indentation_flag_name(1));
    check_bool("flag_name_40_is_null", asperity::indentation_flag_name(40) == nullptr);
}

void laws()
{
    const double delta = 10e-9;
    check("sphere_in_crater_force",
          asperity::normal_eval(asperity::law_sphere_in_crater(radius, 4e-6, e_star), delta)
              .force);

    // Galin example of REFERENCE.md section 8: a = 1 um at P = 2.1566524e-3 N.
    const AsperityNormalResponse galin =
        asperity::normal_eval_at_load(asperity::law_power_punch(1e3, 1.5, e_star), 2.1566524e-3);
    check("power_punch_radius_at_load", galin.contact_radius);
    check("power_punch_delta_at_load", galin.delta);

    const AsperityNormalResponse cone = asperity::normal_eval(asperity::law_cone(1.2, e_star), delta);
    check("cone_force", cone.force);
    check("cone_contact_radius", cone.contact_radius);
    check("cone_in_imprint_force",
          asperity::normal_eval(asperity::law_cone_in_imprint(1.0, 1.3, e_star), delta).force);

    const AsperityNormalResponse flat =
        asperity::normal_eval(asperity::law_flat_punch(2e-6, e_star), 1e-9);
    check("flat_punch_force", flat.force);
    check("flat_punch_stiffness", flat.stiffness);
    check("flat_punch_no_slip_force",
          asperity::normal_eval(asperity::law_flat_punch_no_slip(2e-6, e_star, 0.355), 1e-9)
              .force);

    const AsperityNormalLaw dmt = asperity::law_dmt(radius, e_star, w);
    check("dmt_force", asperity::normal_eval(dmt, delta).force);

    const AsperityNormalLaw jkr = asperity::law_jkr(radius, e_star, w);
    check("jkr_length_scale", asperity::law_length_scale(jkr));
    check("hertz_length_scale", asperity::law_length_scale(asperity::law_hertz(3e-6, e_star)));
    AsperityContactState fresh{};
    AsperityContactState after{};
    const AsperityNormalResponse r = asperity::normal_eval(jkr, delta, &fresh, &after);
    check_bool("jkr_new_state_written", after.in_contact == 1 && after.contact_radius > 0.0);
    check_bool("jkr_old_state_untouched", fresh.in_contact == 0 && fresh.contact_radius == 0.0);
    check_bool("jkr_new_state_radius", after.contact_radius == r.contact_radius);

    const double sphere_b = 1.0 / (2.0 * radius);
    check("jkr_power_punch_pull_off",
          asperity::pull_off_force(asperity::law_jkr_power_punch(sphere_b, 2.0, e_star, w, 0.3, false),
                                   ASPERITY_CONTROL_LOAD));
    check("jkr_power_punch_no_slip_pull_off",
          asperity::pull_off_force(asperity::law_jkr_power_punch(sphere_b, 2.0, e_star, w, 0.355, true),
                                   ASPERITY_CONTROL_LOAD));
    check("kendall_pull_off",
          asperity::pull_off_force(asperity::law_kendall(1e-6, e_star, w, 0.3, false),
                                   ASPERITY_CONTROL_LOAD));
    check("kendall_no_slip_pull_off",
          asperity::pull_off_force(asperity::law_kendall(1e-6, e_star, w, 0.355, true),
                                   ASPERITY_CONTROL_LOAD));

    // From inputs: the member of the union that the kind names; the law
    // keeps them as given.
    AsperityLawParams inputs{};
    inputs.kendall = AsperityKendallParams{1e-6, e_star, w, 0.355, 1, 0};
    const AsperityNormalLaw kendall_in = asperity::law_from_params(ASPERITY_LAW_KENDALL, inputs);
    check("from_params_kendall_no_slip_pull_off",
          asperity::pull_off_force(kendall_in, ASPERITY_CONTROL_LOAD));
    check_bool("from_params_inputs_read_back",
               kendall_in.kind == ASPERITY_LAW_KENDALL && kendall_in.params.kendall.nu == 0.355 &&
                   kendall_in.params.kendall.no_slip == 1 &&
                   kendall_in.params.kendall.radius == 1e-6);
    expect_error("from_params_bad_no_slip", "`no_slip`", [] {
        AsperityLawParams bad{};
        bad.kendall = AsperityKendallParams{1e-6, e_star, w, 0.3, 2, 0};
        (void)asperity::law_from_params(ASPERITY_LAW_KENDALL, bad);
    });

    const AsperityNormalLaw md = asperity::law_maugis_dugdale(radius, e_star, w, 3.27e7);
    check("md_pull_off_load", asperity::pull_off_force(md, ASPERITY_CONTROL_LOAD));
    check("md_length_scale", asperity::law_length_scale(md));

    const AsperityNormalLaw derjaguin =
        asperity::law_derjaguin(radius, w, ASPERITY_SURFACE_LAW_LENNARD_JONES, 0.3e-9);
    check("derjaguin_pull_off", asperity::pull_off_force(derjaguin, ASPERITY_CONTROL_LOAD));
    check("derjaguin_length_scale", asperity::law_length_scale(derjaguin));

    // Batch with states, radii and stiffnesses against the scalar calls.
    const AsperityNormalLaw hertz = asperity::law_hertz(radius, e_star);
    const std::vector<double> deltas{1e-9, 3e-9, 7e-9, 20e-9};
    std::vector<AsperityContactState> states(deltas.size());
    std::vector<double> force(deltas.size());
    std::vector<double> radii(deltas.size());
    std::vector<double> stiffness(deltas.size());
    asperity::normal_eval_batch(hertz, deltas, states, states, force, radii, stiffness);
    bool same = true;
    for (std::size_t i = 0; i < deltas.size(); ++i) {
        const AsperityNormalResponse s = asperity::normal_eval(hertz, deltas[i]);
        same = same && s.force == force[i] && s.contact_radius == radii[i] &&
               s.stiffness == stiffness[i] && states[i].contact_radius == radii[i];
    }
    check_bool("hertz_batch_equals_scalar", same);
    check("hertz_batch_stiffness_3", stiffness[3]);
}

void lennard_jones()
{
    // REFERENCE.md section 6, K = 1/40: mu = 0.020, pull-off near 2 pi R w.
    check("lj_pull_off", asperity::lj_sphere_pull_off(110e-9, 4.075403e11, 7.40923e-3, 1.65e-10, 64));

    // mu = 0.1 with R = 1 um, w = 0.05 J/m^2, z0 = 0.3 nm.
    const double z0 = 0.3e-9;
    const double e_mu01 = std::sqrt(radius * w * w / (0.001 * z0 * z0 * z0));
    const AsperityFidelityAdvice advice =
        asperity::fidelity_advise(radius, e_mu01, w, z0, 0.01 * pi * radius * w);
    check("fidelity_tabor", advice.tabor);
    check("fidelity_reference_pull_off", advice.reference_pull_off);
    bool ordered = true;
    for (int i = 0; i < 6; ++i) {
        ordered = ordered && advice.assessments[i].law == i;
    }
    check_bool("fidelity_assessments_ordered", ordered);
    check("fidelity_choice", advice.choice);

    // A tabulated Lennard-Jones sphere at mu = 0.5 on a 48-cell grid.
    const double e_mu05 = std::sqrt(radius * w * w / (z0 * z0 * z0)) / std::pow(0.5, 1.5);
    const asperity::Table table = asperity::Table::lennard_jones(radius, e_mu05, w, z0, 48, 1e-3);
    check("lj_table_tolerance", table.max_error());
    check("lj_table_pull_off", table.pull_off_force(ASPERITY_CONTROL_LOAD));
}

void tables()
{
    const asperity::Table table = asperity::Table::maugis_dugdale(radius, e_star, w, 3.27e7);
    check("md_table_at_zero_load_delta", table.eval_at_load(0.0).delta);
    // The batch with states against the scalar calls, through an approach
    // and retraction with hysteresis.
    std::vector<double> delta;
    for (int i = 0; i <= 30; ++i) {
        delta.push_back(-2e-9 + 0.5e-9 * i);
    }
    for (int i = 30; i >= 0; --i) {
        delta.push_back(-4e-9 + 0.5e-9 * i);
    }
    bool same = true;
    AsperityContactState scalar_state{};
    AsperityContactState batch_state{};
    for (double d : delta) {
        double force = 0.0;
        double a = 0.0;
        double k = 0.0;
        const AsperityContactState old_state = batch_state;
        table.eval_batch({&d, 1}, {&old_state, 1}, {&batch_state, 1}, {&force, 1}, {&a, 1},
                         {&k, 1});
        const AsperityNormalResponse s = table.eval(d, scalar_state);
        same = same && s.force == force && s.contact_radius == a && s.stiffness == k &&
               batch_state.branch == scalar_state.branch;
    }
    check_bool("md_table_batch_equals_scalar", same);
}

void slider()
{
    AsperityNanoAsperities nano{};
    nano.h_vdw = 20e-9;
    nano.w_vdw = 430e-9;
    nano.h_chem = 2e-9;
    nano.w_chem = 161e-9;
    nano.spacing = 1.3e-6;
    nano.per_rod = 100;
    const asperity::SliderGeometry uniform = asperity::SliderGeometry::uniform(13.5e-6, 3, nano);
    const AsperityNanoAsperities back = uniform.nano();
    check_bool("uniform_nano_round_trip",
               back.h_vdw == nano.h_vdw && back.w_vdw == nano.w_vdw &&
                   back.h_chem == nano.h_chem && back.w_chem == nano.w_chem &&
                   back.spacing == nano.spacing && back.per_rod == nano.per_rod);
    check("uniform_levels", static_cast<double>(uniform.level_count()));
    check("uniform_rods", static_cast<double>(uniform.rod_count(0)));
    check("uniform_rod_width", uniform.rod_width(0));
    const std::vector<double> flat = uniform.rod_heights(0);
    check("uniform_rod_heights_max_abs", max_abs_diff(flat, std::vector<double>(3, 0.0)));

    // The profiles of tests/ffi_slider_geometry.rs: a 10-point micro profile
    // at 1 um, a square-wave nano profile at 10 nm; two nested levels.
    const double nm = 1e-9;
    const double um = 1e-6;
    std::vector<double> micro;
    for (double h : {1.0, 3.0, -1.0, 5.0, 0.0, 2.0, 4.0, -2.0, 1.0, 3.0}) {
        micro.push_back(h * nm);
    }
    const double period[8] = {3.0, 3.0, 1.0, 1.0, -2.0, -2.0, -2.0, -2.0};
    std::vector<double> nano_profile;
    for (int j = 0; j < 32; ++j) {
        nano_profile.push_back(period[j % 8] * nm);
    }
    const std::array<double, 2> widths{5.0 * um, 2.5 * um};
    const asperity::SliderGeometry g(micro, um, nano_profile, 10.0 * nm, widths);
    check("profile_levels", static_cast<double>(g.level_count()));
    for (std::size_t level = 0; level < g.level_count(); ++level) {
        const std::string l = std::to_string(level);
        check(("profile_rod_count_" + l).c_str(), static_cast<double>(g.rod_count(level)));
        check(("profile_rod_width_" + l).c_str(), g.rod_width(level));
        check(("profile_rod_origin_" + l).c_str(), g.rod_origin(level));
        const std::vector<double> h = g.rod_heights(level);
        for (std::size_t k = 0; k < h.size(); ++k) {
            check(("profile_rod_height_" + l + "_" + std::to_string(k)).c_str(), h[k]);
        }
    }
    const AsperityNanoAsperities gn = g.nano();
    check("profile_nano_h_vdw", gn.h_vdw);
    check("profile_nano_w_vdw", gn.w_vdw);
    check("profile_nano_spacing", gn.spacing);
    check("profile_nano_per_rod", static_cast<double>(gn.per_rod));
    expect_error("rod_heights_short", "`len`", [&g] {
        std::vector<double> room(1);
        g.rod_heights(1, room);
    });

    // A slider from structs: the uniform rods over a sine counter-surface,
    // copper, the default options at 10 mN; one step of 1 um.
    const AsperityFrictionMaterial copper = asperity::friction_material_copper();
    check("copper_yield_stress", copper.yield_stress);
    check("copper_work_of_adhesion", copper.work_of_adhesion);
    AsperitySliderOptions options = asperity::slider_options_default();
    check_bool("options_default",
               options.control == ASPERITY_SLIDER_CONTROL_LOAD &&
                   options.mechanisms == ASPERITY_MECHANISM_ALL &&
                   options.cof_form == ASPERITY_COF_DERJAGUIN &&
                   options.plastic == ASPERITY_PLASTIC_NEAREST_NEIGHBOURS &&
                   options.solver == ASPERITY_ROD_SOLVER_SWEEP && options.depth == 0.0 &&
                   options.root_margin < 0.0 && options.periodic == 0);
    options.normal_force = 0.01;
    std::vector<double> counter(64);
    for (std::size_t i = 0; i < counter.size(); ++i) {
        counter[i] = 2e-7 * std::sin(0.7 * static_cast<double>(i));
    }
    const asperity::Slider from_structs(uniform, copper, counter, um, options);
    // Stepped as a friction law under the options' load (10 mN).
    const asperity::Friction law = asperity::Friction::from_slider(from_structs);
    asperity::FrictionWork work(law);
    std::vector<double> state(law.state_size(), 0.0);
    AsperityFrictionIncrement step{};
    step.normal_force = options.normal_force;
    step.slip[0] = um;
    const AsperityFrictionResponse r = law.step_in_place(step, state, &work);
    check("structs_friction_force", r.force_magnitude);
    check("structs_cof", r.cof);
    // The full record of the step: the exact count of nano-asperities in
    // contact and the rest, beyond the response. The step seated the fresh
    // state, then slid 1 um from position 0.
    const AsperitySliderRecord record = work.slider_record();
    check("structs_nano_contacts", static_cast<double>(record.nano_contacts));
    check("structs_adhesive_contacts", static_cast<double>(record.adhesive_contacts));
    check("structs_rods_in_contact", static_cast<double>(record.rods_in_contact));
    check("structs_yielded_rods", static_cast<double>(record.yielded_rods));
    check("structs_adhesion_area_share", record.adhesion_area_share);
    check("structs_position", record.position);
    check("structs_rod_position", record.rod_position);
    check("structs_seated", record.seated);
    check_bool("structs_position_matches_state",
               record.position == state[ASPERITY_SLIDER_STATE_POSITION]);
    // The true contact area is N_c w_vdW^2.
    check("structs_true_contact_area_rel_diff",
          std::fabs(r.true_contact_area -
                    static_cast<double>(record.nano_contacts) * nano.w_vdw * nano.w_vdw) /
              r.true_contact_area);
    // A second step: nothing seated, one more micrometre.
    (void)law.step_in_place(step, state, &work);
    const AsperitySliderRecord second = work.slider_record();
    check("structs_second_seated", second.seated);
    check("structs_second_position", second.position);
    // A scratch that holds no slider record names `work`: empty (NULL), or
    // a LuGre law's.
    expect_error("record_null_work", "`work`", [] {
        const asperity::FrictionWork empty;
        (void)empty.slider_record();
    });
    expect_error("record_lugre_work", "`work`", [] {
        AsperityLugreParams p{};
        p.mu_coulomb = 0.3;
        p.mu_static = 0.5;
        p.stribeck_velocity = 1e-3;
        p.stribeck_exponent = 2.0;
        p.sigma0 = 1e5;
        p.sigma1 = 1000.0;
        p.damping_velocity = 1e-3;
        const asperity::FrictionWork lugre_work = asperity::Friction::lugre(p).work();
        (void)lugre_work.slider_record();
    });
    options.plastic = 7;
    expect_error("structs_bad_plastic", "`options.plastic`", [&] {
        const asperity::Slider bad(uniform, copper, counter, um, options);
    });
}

void dynamic_friction()
{
    // LuGre: one long increment at 2 mm/s reaches the Stribeck curve.
    AsperityLugreParams p{};
    p.mu_coulomb = 0.3;
    p.mu_static = 0.5;
    p.stribeck_velocity = 1e-3;
    p.stribeck_exponent = 2.0;
    p.sigma0 = 1e5;
    p.sigma1 = 1000.0;
    p.damping_velocity = 1e-3;
    p.sigma2 = 0.4;
    const asperity::Friction lugre = asperity::Friction::lugre(p);
    std::vector<double> state(lugre.state_size(), 0.0);
    AsperityFrictionIncrement inc{};
    inc.normal_force = 3.0;
    inc.dt = 1.0;
    inc.slip[0] = 2e-3;
    const AsperityFrictionResponse r = lugre.step_in_place(inc, state);
    check("lugre_state_size", static_cast<double>(state.size()));
    check("lugre_steady_force", -r.force[0]);
    check("lugre_dissipation", state[ASPERITY_FRICTION_STATE_DISSIPATION]);
    // Maxwell-slip: two elements, loaded 3 um then back 2 um (Masing).
    const std::array<double, 2> k{1e5, 2e4};
    const std::array<double, 2> mu{0.2, 0.3};
    const asperity::Friction ms = asperity::Friction::maxwell_slip(k, mu);
    std::vector<double> states(2 * ms.state_size(), 0.0);
    const std::array<double, 2> normal{1.0, 2.0};
    std::array<double, 4> forces{};
    std::array<double, 2> dissipation{};
    // Old and new states separate, then in place.
    std::vector<double> loaded(states.size(), 0.0);
    ms.step_block(normal, {}, std::array<double, 4>{3e-6, 0.0, 3e-6, 0.0}, 0.0, states, loaded,
                  forces, dissipation);
    ms.step_block_in_place(normal, {}, std::array<double, 4>{-2e-6, 0.0, -2e-6, 0.0}, 0.0, loaded,
                           forces, dissipation);
    check("maxwell_force_0", forces[0]);
    check("maxwell_force_1", forces[2]);
    check("maxwell_dissipation_1", dissipation[1]);
    // The loading again from rest, with every point's response and
    // tangents (old == new: in place).
    std::vector<double> again(states.size(), 0.0);
    std::array<AsperityFrictionResponse, 2> responses{};
    ms.step_block_responses(normal, {}, std::array<double, 4>{3e-6, 0.0, 3e-6, 0.0}, 0.0,
                            ASPERITY_FRICTION_TANGENT_NORMAL | ASPERITY_FRICTION_TANGENT_SLIP,
                            again, again, responses);
    check("maxwell_responses_force_1", responses[1].force[0]);
    check("maxwell_responses_regime_1", static_cast<double>(responses[1].regime));
    check("maxwell_responses_dslip_1", responses[1].dforce_dslip[0][0]);
    check("maxwell_responses_dnormal_1", responses[1].dforce_dnormal[0]);
    check("maxwell_responses_stored_1", responses[1].stored_energy);
    expect_error("maxwell_bad", "`stiffness`", [] {
        const std::array<double, 1> k0{-1.0};
        const std::array<double, 1> m0{0.1};
        (void)asperity::Friction::maxwell_slip(k0, m0);
    });
    // Two-spring Prandtl-Tomlinson: tip and cantilever springs of 2 N/m in
    // series on a 0.3 nm lattice; one increment of 10 pm in 1 us.
    AsperityPrandtlTomlinsonTwoSpringParams t{};
    t.amplitude = 3e-21;
    t.period = 3e-10;
    t.tip_stiffness = 2.0;
    t.tip_mass = 1e-12;
    t.tip_damping = 1e-6;
    t.cantilever_stiffness = 2.0;
    t.cantilever_mass = 1e-12;
    t.cantilever_damping = 1e-6;
    t.tolerance = 1e-9;
    const asperity::Friction pt =
        asperity::Friction::prandtl_tomlinson_two_spring(t);
    std::vector<double> pt_state(pt.state_size(), 0.0);
    AsperityFrictionIncrement pt_inc{};
    pt_inc.normal_force = 1.0;
    pt_inc.slip[0] = 1e-11;
    pt_inc.dt = 1e-6;
    check("two_spring_state_size", static_cast<double>(pt_state.size()));
    asperity::FrictionWork pt_work = pt.work();
    check("two_spring_force", pt.step(pt_inc, pt_state, pt_state, &pt_work).force[0]);
    // Burridge-Knopoff: four blocks, all stuck after a 10 um pull (below
    // the static reach mu_s (N/M)/k_p = 0.5 mm): F = -4 k_p slip.
    AsperityBurridgeKnopoffParams b{};
    b.blocks = 4;
    b.mass = 1e-5;
    b.coupling_stiffness = 1e3;
    b.pulling_stiffness = 1e3;
    b.mu_static = 0.5;
    b.mu_kinetic = 0.3;
    b.weakening_velocity = 0.05;
    b.damping = 0.0;
    b.tolerance = 1e-9;
    const asperity::Friction bk = asperity::Friction::burridge_knopoff(b);
    std::vector<double> bk_state(bk.state_size(), 0.0);
    AsperityFrictionIncrement bk_inc{};
    bk_inc.normal_force = 4.0;
    bk_inc.slip[0] = 1e-5;
    bk_inc.dt = 1e-3;
    check("burridge_knopoff_state_size", static_cast<double>(bk_state.size()));
    check("burridge_knopoff_stuck_force", bk.step_in_place(bk_inc, bk_state).force[0]);
    expect_error("burridge_knopoff_bad", "`params.mu_kinetic`", [] {
        AsperityBurridgeKnopoffParams bad{};
        bad.blocks = 2;
        bad.mass = 1.0;
        bad.pulling_stiffness = 1.0;
        bad.mu_static = 0.3;
        bad.mu_kinetic = 0.5;
        bad.weakening_velocity = 1.0;
        bad.tolerance = 1e-9;
        (void)asperity::Friction::burridge_knopoff(bad);
    });
    // The homogenised law: one sample (mu 0.5, no adhesion) with a stick
    // stiffness of 1e6 N/m; a 1 mm slip at 1 N on 1 mm^2 slides at mu N.
    AsperityHomogenisedSample sample{};
    sample.pressure = 1e6;
    sample.cof = 0.5;
    sample.contact_fraction = 0.01;
    sample.shares.chemical = 1.0;
    const asperity::HomogenisedFriction table(
        asperity::span<const AsperityHomogenisedSample>{&sample, 1});
    const asperity::Friction homog = asperity::Friction::from_homogenised(table, 1e6);
    std::vector<double> h_state(homog.state_size(), 0.0);
    AsperityFrictionIncrement h_inc{};
    h_inc.normal_force = 1.0;
    h_inc.area = 1e-6;
    h_inc.slip[0] = 1e-3;
    const AsperityFrictionResponse h = homog.step_in_place(h_inc, h_state);
    check("homogenised_state_size", static_cast<double>(h_state.size()));
    check("homogenised_force", h.force[0]);
    check("homogenised_regime", h.regime);
    check("homogenised_dissipated", h.dissipated);
    // The homogenised law needs the nominal area of the point.
    expect_error("homogenised_no_area", "`area`", [&] {
        h_inc.area = 0.0;
        (void)homog.step_in_place(h_inc, h_state);
    });
}

void indentation()
{
    const AsperityIndentationOptions d = asperity::indentation_default_options();
    check_bool("default_options",
               d.indenter == ASPERITY_INDENTER_BERKOVICH && d.anchor == ASPERITY_ANCHOR_MAX_POINT &&
                   d.use_labels == 1 && d.epsilon == 0.75 && d.nu_sample == 0.3 &&
                   d.e_indenter == 1141e9 && d.nu_indenter == 0.07 &&
                   d.loading_window[0] == 0.1 && d.loading_window[1] == 1.0 &&
                   d.unloading_window[0] == 0.2 && d.unloading_window[1] == 0.98);

    // A synthetic curve with kappa = 0.3, d = 2 and E_r = 70 GPa on the area
    // 24.5 h_c^2 (as tests/indentation.rs builds it): loading, hold,
    // elastic unloading.
    const double kappa = 0.3;
    const double dd = 2.0;
    const double er = 70e9;
    const double c0 = 24.5;
    const int n = 400;
    const double h1 = 1e-6;
    const double p1 = 0.1;
    const double ml = (2.0 + kappa * (dd - 1.0)) / dd;
    const double m = (dd + 1.0) / dd;
    double s = 2.0 * er * std::sqrt(c0 * h1 * h1 / pi);
    for (int i = 0; i < 200; ++i) {
        const double hc = h1 - 0.75 * p1 / s;
        s = 2.0 * er * std::sqrt(c0 * hc * hc / pi);
    }
    const double h_f = h1 - m * p1 / s;
    const double alpha = p1 / std::pow(h1 - h_f, m);
    std::vector<double> depth;
    std::vector<double> load;
    std::vector<std::int32_t> segments;
    for (int i = 1; i <= n; ++i) {
        const double h = h1 * i / n;
        depth.push_back(h);
        load.push_back(p1 * std::pow(h / h1, ml));
        segments.push_back(ASPERITY_SEGMENT_LOADING);
    }
    for (int i = 0; i < 5; ++i) {
        depth.push_back(h1);
        load.push_back(p1);
        segments.push_back(ASPERITY_SEGMENT_HOLD);
    }
    for (int i = 1; i <= n; ++i) {
        const double pp = p1 * (1.0 - 0.95 * i / n);
        depth.push_back(h_f + std::pow(pp / alpha, 1.0 / m));
        load.push_back(pp);
        segments.push_back(ASPERITY_SEGMENT_UNLOADING);
    }
    AsperityIndentationOptions o = asperity::indentation_default_options();
    o.n_area_coefficients = 1;
    o.area_coefficients[0] = c0;
    o.beta = 1.0;
    o.e_indenter = std::numeric_limits<double>::infinity();
    const AsperityIndentationResult r = asperity::indentation_fit(depth, load, segments, &o);
    check("fit_kappa", r.kappa);
    check("fit_d", r.d);
    check("fit_reduced_modulus", r.reduced_modulus);
    check("fit_sample_modulus", r.sample_modulus);
    check("fit_final_depth", r.final_depth);
    check("fit_expected_final_depth", h_f);
    check("fit_segments_from_labels", r.segments_from_labels);
    const AsperityIndentationResult u = asperity::indentation_fit(depth, load, {}, &o);
    check("fit_unlabelled_d", u.d);
    check("fit_unlabelled_segments_from_labels", u.segments_from_labels);
    const AsperityIndentationResult defaults = asperity::indentation_fit(depth, load);
    // The defaults: the ideal Berkovich area (24.5 h_c^2 as above) with
    // beta = 1.034 (King 1987), so E_r comes out 1.034 times smaller.
    check("fit_defaults_reduced_modulus", defaults.reduced_modulus);
    check("fit_defaults_kappa", defaults.kappa);
    expect_error("fit_load_length", "`load`", [&depth] {
        const std::vector<double> short_load(3, 1.0);
        (void)asperity::indentation_fit(depth, short_load);
    });
}

void rescaling_and_hardness()
{
    // Taljat A533-B (REFERENCE.md sections 2, 8), and lambda != 1 to place it.
    check("rescaling_load", asperity::rescaling_load(0.112, 2.0, 1.0, 0.1e-3, 2310.0, 0.224e-3));
    check("rescaling_load_lambda", asperity::rescaling_load(0.112, 2.0, 1.3, 0.1e-3, 2310.0, 0.224e-3));
    check("rescaling_depth", asperity::rescaling_depth(0.112, 2.0, 1.3, 985.71, 2310.0, 0.224e-3));
    check("rescaling_radius", asperity::rescaling_radius(0.112, 2.0, 1.3, 985.71, 2310.0, 0.3e-3));
    check("lambda_spheres", asperity::rescaling_lambda_spheres(0.788e-3, 1.2e-3));
    check("lambda_cones", asperity::rescaling_lambda_cones(1.2, 1.0));
    check("kappa_from_slope", asperity::rescaling_kappa_from_slope(1.43, 4.17));
    check("d_from_unloading_slope", asperity::rescaling_d_from_unloading_slope(1.24));
    check("d_from_loading_slope", asperity::rescaling_d_from_loading_slope(1.43, 1.25));
    check("galanov_unloading_radius",
          asperity::galanov_unloading_radius(1e-3, 100.0, 2e-6, 50.0, 1.5e-6));
    check("galanov_medium_radius", asperity::galanov_medium_radius(0.788e-3, 62.882e-3));
    check("hardness_brinell", asperity::hardness_brinell(1000.0, 10e-3, 3e-3));
    check("hardness_meyer", asperity::hardness_meyer(1000.0, 3e-3));
    check("hardness_ludwik", asperity::hardness_ludwik(1000.0, 3e-3));
    check("hardness_vickers", asperity::hardness_vickers(1000.0, 3e-3));
    expect_error("cone_kappa", "`d`", [] { (void)asperity::rescaling_kappa_from_slope(1.2, 1.0); });
}

void material()
{
    check("effective_modulus", asperity::effective_modulus(200e9, 0.3, 70e9, 0.22));
    check("rod_effective_modulus", asperity::rod_effective_modulus(200e9, 70e9));
    check("no_slip_factor", asperity::no_slip_factor(0.355));
    check("tabor_parameter", asperity::tabor_parameter(radius, w, e_star, 0.3e-9));
    check("maugis_parameter", asperity::maugis_parameter(radius, w, e_star, 1.710667e8));
    const double diamond = asperity::weir_surface_energy(1.99e-26, 3500.0, 1164e9, 0.079, 6.0, 12.0);
    const double wc = asperity::weir_surface_energy(3.25e-25, 15250.0, 600e9, 0.2, 6.0, 12.0);
    check("weir_diamond", diamond);
    check("weir_wc", wc);
    check("weir_diamond_three_over_mn",
          asperity::weir_surface_energy_with(1.99e-26, 3500.0, 1164e9, 0.079, 6.0, 12.0,
                                             ASPERITY_WEIR_THREE_OVER_MN));
    check("pair_seed001", asperity::pair_work_of_adhesion(diamond, wc, ASPERITY_PAIR_SEED001_DIFFERENCE));
    check("hamaker_work_of_adhesion", asperity::hamaker_work_of_adhesion(2.7e-19, 2.56e-10));
    expect_error("bad_poisson", "`nu1`", [] { (void)asperity::effective_modulus(1e9, 0.7, 1e9, 0.3); });
}

// Zhuravlev densities as a C callback: n(xi) = alpha xi, alpha in *data.
double linear_density(double xi, void* data)
{
    return *static_cast<const double*>(data) * xi;
}

void statistics()
{
    AsperityGwParams gw{};
    gw.distribution = ASPERITY_HEIGHTS_GAUSSIAN;
    gw.summit_count = 1000.0;
    gw.radius = 50e-6;
    gw.sigma = 1e-6;
    gw.e_star = 1e11;
    const AsperityGwResponse at_sigma = asperity::gw_eval(gw, 1e-6);
    check("gw_load", at_sigma.load);
    check("gw_area", at_sigma.area);
    check("gw_contacts", at_sigma.contacts);
    const std::vector<double> sep{-0.5e-6, 0.0, 0.7e-6, 1.5e-6, 2.5e-6};
    std::vector<double> load(sep.size());
    std::vector<double> area(sep.size());
    std::vector<double> contacts(sep.size());
    std::vector<double> stiffness(sep.size());
    asperity::gw_eval_batch(gw, sep, load, area, contacts, stiffness);
    bool same = true;
    for (std::size_t i = 0; i < sep.size(); ++i) {
        const AsperityGwResponse s = asperity::gw_eval(gw, sep[i]);
        same = same && s.load == load[i] && s.area == area[i] && s.contacts == contacts[i] &&
               s.stiffness == stiffness[i];
    }
    check_bool("gw_batch_equals_scalar", same);
    const AsperitySeparation found = asperity::gw_separation_at_load(gw, at_sigma.load);
    check("gw_separation", found.separation);
    check("gw_separation_residual", found.relative_residual);
    check("gw_plasticity_index", asperity::gw_plasticity_index(gw, 2e9));
    check("plasticity_index", asperity::plasticity_index(1e11, 2e9, 1e-6, 50e-6));
    check("regime_0_5", asperity::deformation_regime(0.5));
    check("regime_0_8", asperity::deformation_regime(0.8));
    check("regime_1_5", asperity::deformation_regime(1.5));

    // Listed summits (um), standing for 500 summits of radius 40 um; then
    // with a radius each.
    const std::vector<double> heights{0.3e-6, -0.2e-6, 0.9e-6, 0.1e-6, -0.5e-6, 0.6e-6};
    const std::vector<double> radii{30e-6, 45e-6, 20e-6, 60e-6, 35e-6, 50e-6};
    const asperity::GwEmpirical listed(500.0, 40e-6, 1e11, heights);
    const AsperityGwResponse e = listed.eval(0.2e-6);
    check("gwe_load", e.load);
    check("gwe_area", e.area);
    check("gwe_contacts", e.contacts);
    check("gwe_separation", listed.separation_at_load(e.load).separation);
    check("gwe_plasticity_index", listed.plasticity_index(2e9));
    std::vector<double> eload(sep.size());
    std::vector<double> estiff(sep.size());
    listed.eval_batch(sep, eload, {}, {}, estiff);
    same = true;
    for (std::size_t i = 0; i < sep.size(); ++i) {
        const AsperityGwResponse s = listed.eval(sep[i]);
        same = same && s.load == eload[i] && s.stiffness == estiff[i];
    }
    check_bool("gwe_batch_equals_scalar", same);
    const asperity::GwEmpirical with_radii(500.0, 40e-6, 1e11, heights, radii);
    const AsperityGwResponse er = with_radii.eval(0.2e-6);
    check("gwe_radii_load", er.load);
    check("gwe_radii_area", er.area);
    expect_error("gwe_radii_length", "`radii`", [&heights] {
        const std::vector<double> two{1e-6, 2e-6};
        const asperity::GwEmpirical bad(500.0, 40e-6, 1e11, heights, two);
    });

    // Zhuravlev with linear densities: closed forms, the inverse, friction.
    const AsperityZhuravlev model{0.0, 0.5e-6, 1e9, 1000.0};
    double alpha1 = 1e14;
    double alpha2 = 2e14;
    const double x = 50e-9;
    const AsperityZhuravlevResponse z = asperity::zhuravlev_linear(model, alpha1, alpha2, x);
    check("zh_load", z.load);
    check("zh_area", z.area);
    check("zh_contacts", z.contacts);
    check("zh_approach", asperity::zhuravlev_approach_at_load_linear(model, alpha1, alpha2, z.load));
    const AsperityZhuravlevFriction f =
        asperity::zhuravlev_friction_linear(model, alpha1, alpha2, z.load, 1e8);
    check("zh_friction_approach", f.approach);
    check("zh_friction_force", f.friction_force);
    check("zh_friction_coefficient", f.coefficient);
    // The same by quadrature through C callbacks with user data.
    const AsperityZhuravlevResponse q =
        asperity::zhuravlev_eval(model, x, &linear_density, &alpha1, &linear_density, &alpha2, 24);
    check("zh_callback_load_rel_diff", std::fabs(q.load / z.load - 1.0));
    // And through lambdas: n(xi) = beta xi^2, closed form in the test.
    const double beta = 1e22;
    const AsperityZhuravlevResponse qq = asperity::zhuravlev_eval(
        model, x, [beta](double xi) { return beta * xi * xi; },
        [beta](double xi) { return beta * xi * xi; }, 32);
    check("zh_quadratic_load", qq.load);
    check("zh_quadratic_area", qq.area);
    // An exception thrown by a density reaches the caller unchanged.
    try {
        (void)asperity::zhuravlev_eval(
            model, x, [](double xi) -> double {
                if (xi > 1e-9) {
                    throw std::runtime_error("density exploded");
                }
                return xi;
            },
            [](double xi) { return xi; }, 16);
        check("zh_exception_propagated", 0);
    } catch (const asperity::Error&) {
        check("zh_exception_propagated", 0);
    } catch (const std::runtime_error& e) {
        check_bool("zh_exception_propagated", std::strcmp(e.what(), "density exploded") == 0);
    }
}

void surfaces()
{
    // A sine of amplitude A = 1 um and wavelength 64 samples (dx = 1 um) over
    // 64 whole periods.
    const std::size_t n = 4096;
    const double dx = 1e-6;
    const double amplitude = 1e-6;
    std::vector<double> sine(n);
    for (std::size_t i = 0; i < n; ++i) {
        sine[i] = amplitude * std::sin(2.0 * pi * static_cast<double>(i) / 64.0);
    }
    // Four sampling lengths of 1024 samples: the ISO width discrimination
    // (1 % of a sampling length) stays below a half period.
    const AsperityRoughness r =
        asperity::roughness_parameters(sine, dx, ASPERITY_FORM_NONE, 0.0, 1024 * dx);
    check("sine_sampling_lengths", static_cast<double>(r.sampling_lengths));
    check("sine_has_rsm", r.has_rsm);
    check("sine_ra", r.ra);
    check("sine_rq", r.rq);
    check("sine_rsk", r.rsk);
    check("sine_rku", r.rku);
    check("sine_rsm", r.rsm);
    check("sine_rdq", r.rdq);
    check("sine_m0", r.m0);
    check("sine_n_evaluated", static_cast<double>(r.n_evaluated));
    const AsperityRoughness filtered =
        asperity::roughness_parameters(sine, dx, ASPERITY_FORM_LINEAR, 512 * dx, 0.0);
    check("sine_filtered_first_index", static_cast<double>(filtered.first_index));
    check("sine_filtered_rq", filtered.rq);

    // Form removal: a tilted line is all form; the mean of a line.
    std::vector<double> line(100);
    for (std::size_t i = 0; i < line.size(); ++i) {
        line[i] = 3e-6 + 2e-8 * static_cast<double>(i);
    }
    const std::vector<double> detrended = asperity::profile_remove_form(line, ASPERITY_FORM_LINEAR);
    check("line_linear_residual", max_abs_diff(detrended, std::vector<double>(line.size(), 0.0)));
    std::vector<double> centred = line;
    asperity::profile_remove_form(centred, ASPERITY_FORM_MEAN, centred);
    check("line_mean_removed_first", centred.front());
    check("line_mean_removed_last", centred.back());

    // Gaussian filter: the two parts add up to the input.
    const asperity::FilteredProfile kept =
        asperity::profile_gaussian_filter(sine, dx, 512 * dx, ASPERITY_FILTER_ENDS_KEEP);
    check("filter_keep_n_out", static_cast<double>(kept.roughness.size()));
    check("filter_keep_first_index", static_cast<double>(kept.first_index));
    std::vector<double> rough(n);
    std::vector<double> mean_line(n);
    std::size_t first = 0;
    const std::size_t n_out = asperity::profile_gaussian_filter(
        sine, dx, 512 * dx, ASPERITY_FILTER_ENDS_DISCARD, rough, mean_line, &first);
    check("filter_discard_n_out", static_cast<double>(n_out));
    check("filter_discard_first_index", static_cast<double>(first));
    double sum_err = 0.0;
    double rough_max = 0.0;
    for (std::size_t j = 0; j < n_out; ++j) {
        sum_err = std::max(sum_err, std::fabs(rough[j] + mean_line[j] - sine[first + j]));
        rough_max = std::max(rough_max, std::fabs(rough[j]));
    }
    check("filter_parts_sum_max_err", sum_err);
    check("filter_roughness_amplitude", rough_max);

    // Material ratio: peak at 0, deepest valley at 1.
    const asperity::MaterialRatioCurve curve = asperity::material_ratio_curve(sine, 11);
    check("ratio_5", curve.ratio[5]);
    check("level_first", curve.level.front());
    check("level_last", curve.level.back());
    std::vector<double> level_only(11);
    asperity::material_ratio_curve(sine, {}, level_only);
    check("level_span_equals_vector", max_abs_diff(level_only, curve.level));

    // PSD: one line at q = 2 pi/(64 dx); Parseval.
    const asperity::Psd psd = asperity::profile_psd(sine, dx, ASPERITY_WINDOW_RECTANGULAR);
    const std::size_t peak = static_cast<std::size_t>(
        std::max_element(psd.g.begin(), psd.g.end()) - psd.g.begin());
    check("psd_len", static_cast<double>(psd.g.size()));
    check("psd_q1", psd.q[1]);
    check("psd_peak_q", psd.q[peak]);
    const double dq = psd.q[1];
    check("psd_integral", dq * std::accumulate(psd.g.begin(), psd.g.end(), 0.0));
    expect_error("psd_wrong_length", "n_q", [&sine, dx] {
        std::vector<double> g(10);
        asperity::profile_psd(sine, dx, ASPERITY_WINDOW_HANN, {}, g);
    });

    // Peaks of the sine: one per period, at the amplitude.
    const AsperityPeakStatistics peaks = asperity::profile_peak_statistics(sine, dx);
    check("peak_count", static_cast<double>(peaks.count));
    check("peak_density", peaks.density);
    check("peak_mean_height", peaks.mean_height);
    check("peak_mean_curvature", peaks.mean_curvature);

    // Generators: the same seeds through the Rust API in the test.
    const std::vector<double> sa =
        asperity::generate_self_affine(0.7, 1e-6, 1e-3, 8e-6, dx, 42, n);
    std::vector<double> sa_span(n);
    asperity::generate_self_affine(0.7, 1e-6, 1e-3, 8e-6, dx, 42, sa_span);
    check("sa_span_equals_vector", max_abs_diff(sa, sa_span));
    check("sa_0", sa[0]);
    check("sa_1000", sa[1000]);
    check("sa_4095", sa[4095]);
    const AsperityHurstFit fit = asperity::profile_hurst_fit(
        asperity::generate_self_affine(0.7, 1e-6, 0.0, 0.0, dx, 7, n), dx);
    check("hurst_fit", fit.hurst);
    check("hurst_fit_slope", fit.slope);
    const std::vector<double> wm = asperity::generate_weierstrass_mandelbrot(1.5, 1.5, 1e-7, dx, 7, 1024);
    check("wm_0", wm[0]);
    check("wm_517", wm[517]);
    const std::vector<double> cb = asperity::generate_cantor_borodich(2, 0.25, 0.6, 1e-6, 5, 1e-3, 512);
    check("cb_100", cb[100]);
    check("cb_300", cb[300]);
    check("cb_max", *std::max_element(cb.begin(), cb.end()));
}

// The layout query against the compiler's own sizes of the header's structs.
void layouts()
{
    const asperity::TypeLayout l = asperity::type_layout("AsperityNormalResponse");
    check("layout_normal_response_size_matches", l.size == sizeof(AsperityNormalResponse));
    check("layout_normal_response_align_matches", l.align == alignof(AsperityNormalResponse));
    bool found = false;
    for (std::size_t i = 0; i < asperity::type_count(); ++i) {
        found = found || asperity::type_name(i) == "AsperityNormalLaw";
    }
    check("layout_names_include_normal_law", found);
    try {
        (void)asperity::type_layout("NoSuchType");
        check("layout_unknown_name_throws", 0);
    } catch (const asperity::Error& e) {
        check("layout_unknown_name_throws", e.status() == ASPERITY_ERR_INVALID_ARGUMENT);
    }
}

} // namespace

int main()
{
    try {
        version_and_status();
        layouts();
        laws();
        lennard_jones();
        tables();
        slider();
        dynamic_friction();
        indentation();
        rescaling_and_hardness();
        material();
        statistics();
        surfaces();
    } catch (const asperity::Error& e) {
        std::fprintf(stderr, "every_function: status %d (%s): %s\n", static_cast<int>(e.status()),
                     e.status_string(), e.what());
        return 1;
    }
    return 0;
}
