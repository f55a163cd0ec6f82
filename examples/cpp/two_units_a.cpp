// A program of two translation units that both include asperity.hpp
// (two_units_a.cpp and two_units_b.cpp, compiled separately and linked
// together): a header-only binding must not define anything twice. Handles,
// exceptions and template instantiations cross between the units.
//
// Prints "CHECK <name> <value>" lines read by tests/cpp_bindings.rs.
#include <asperity.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace two_units {
double dmt_pull_off(double radius, double e_star, double w);
asperity::Table make_table(double radius, double e_star, double w, double sigma0);
void bad_call();
double zhuravlev_load(const AsperityZhuravlev& model, double alpha, double approach);
std::vector<double> hertz_batch(double radius, double e_star, const std::vector<double>& delta);
} // namespace two_units

static void check(const char* name, double value)
{
    std::printf("CHECK %s %.17g\n", name, value);
}

int main()
{
    const double radius = 1e-6;
    const double e_star = 1e9;
    const double w = 0.05;
    try {
        check("dmt_pull_off_from_b", two_units::dmt_pull_off(radius, e_star, w));
        check("jkr_pull_off_from_a",
              asperity::pull_off_force(asperity::law_jkr(radius, e_star, w),
                                       ASPERITY_CONTROL_LOAD));

        // A handle built in unit b, used and destroyed in unit a.
        const asperity::Table table = two_units::make_table(radius, e_star, w, 3.27e7);
        check("table_from_b_pull_off_load", table.pull_off_force(ASPERITY_CONTROL_LOAD));

        // An exception thrown in unit b, caught here.
        try {
            two_units::bad_call();
            check("error_from_b_caught", 0);
        } catch (const asperity::Error& e) {
            check("error_from_b_caught", 1);
            check("error_from_b_status", e.status());
            check("error_from_b_names_e_star",
                  std::string(e.what()).find("`e_star`") != std::string::npos);
        }

        // The same template with different callables in each unit.
        const AsperityZhuravlev model{0.0, 0.5e-6, e_star, 1000.0};
        const double alpha = 1e14;
        const double x = 50e-9;
        const double load_a =
            asperity::zhuravlev_eval(
                model, x, [alpha](double xi) { return alpha * xi; },
                [alpha](double xi) { return alpha * xi; }, 32)
                .load;
        const double load_b = two_units::zhuravlev_load(model, alpha, x);
        const double closed = asperity::zhuravlev_linear(model, alpha, alpha, x).load;
        check("zhuravlev_a_rel_diff_closed", std::fabs(load_a / closed - 1.0));
        check("zhuravlev_b_rel_diff_closed", std::fabs(load_b / closed - 1.0));

        // Span instantiations in both units.
        const std::vector<double> delta{2e-9, 4e-9, 8e-9};
        const std::vector<double> from_b = two_units::hertz_batch(radius, e_star, delta);
        std::vector<double> from_a(delta.size());
        asperity::normal_eval_batch(asperity::law_hertz(radius, e_star), delta, {}, {}, from_a);
        check("hertz_batch_a_equals_b", from_a == from_b);
        check("hertz_batch_force_2", from_a[2]);
    } catch (const asperity::Error& e) {
        std::fprintf(stderr, "two_units: status %d (%s): %s\n", static_cast<int>(e.status()),
                     e.status_string(), e.what());
        return 1;
    }
    return 0;
}
