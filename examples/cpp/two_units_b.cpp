// The second translation unit of the two-unit program (see two_units_a.cpp).
// It includes asperity.hpp as well, instantiates the same inline functions,
// templates and handle classes, and hands a Table and an exception to the
// other unit.
#include <asperity.hpp>

#include <cstdint>
#include <vector>

namespace two_units {

/// The DMT pull-off force (N) of a sphere, computed in this unit.
double dmt_pull_off(double radius, double e_star, double w)
{
    return asperity::pull_off_force(asperity::law_dmt(radius, e_star, w), ASPERITY_CONTROL_LOAD);
}

/// A tabulated Maugis-Dugdale law built here and returned by value.
asperity::Table make_table(double radius, double e_star, double w, double sigma0)
{
    return asperity::Table::maugis_dugdale(radius, e_star, w, sigma0, 1e-4);
}

/// Throws asperity::Error from this unit (a negative E*).
void bad_call()
{
    (void)asperity::law_jkr(1e-6, -1.0, 0.05);
}

/// Zhuravlev's quadrature with a function object in this unit.
struct Linear {
    double alpha;
    double operator()(double xi) const { return alpha * xi; }
};

double zhuravlev_load(const AsperityZhuravlev& model, double alpha, double approach)
{
    return asperity::zhuravlev_eval(model, approach, Linear{alpha}, Linear{alpha}, 32).load;
}

/// Hertz forces of a batch, through the span overloads.
std::vector<double> hertz_batch(double radius, double e_star, const std::vector<double>& delta)
{
    std::vector<double> force(delta.size());
    asperity::normal_eval_batch(asperity::law_hertz(radius, e_star), delta, {}, {}, force);
    return force;
}

} // namespace two_units
