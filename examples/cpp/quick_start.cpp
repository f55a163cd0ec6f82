// Quick start (README): a JKR sphere and a tabulated Maugis-Dugdale law from C++.
#include <asperity.hpp>

#include <cmath>
#include <cstdio>

int main()
try {
    const double pi = 3.14159265358979323846;
    // R = 1 um, E* = 1 GPa, w = 0.05 J/m^2 (SI units throughout).
    const AsperityNormalLaw jkr = asperity::law_jkr(1e-6, 1e9, 0.05);
    AsperityContactState state{};  // caller-owned history, all-zero = fresh
    const AsperityNormalResponse r = asperity::normal_eval(jkr, 2e-9, state);
    const double pull_off = asperity::pull_off_force(jkr, ASPERITY_CONTROL_LOAD);
    std::printf("delta = 2 nm: force %.4g N, contact radius %.4g m\n", r.force, r.contact_radius);
    std::printf("pull-off (load control) %.6g N = %.6f pi w R\n", pull_off,
                pull_off / (pi * 0.05 * 1e-6));
    // A table is an RAII handle, freed at the end of its scope.
    asperity::Table table = asperity::Table::maugis_dugdale(1e-6, 1e9, 0.05, 3.27e7, 1e-4);
    std::printf("tabulated Maugis-Dugdale pull-off %.6g N\n",
                table.pull_off_force(ASPERITY_CONTROL_LOAD));
    try {
        (void)asperity::law_jkr(-1e-6, 1e9, 0.05);
        return 1;
    } catch (const asperity::Error& e) {  // status and the library's message
        std::printf("negative radius: status %d: %s\n", static_cast<int>(e.status()), e.what());
    }
    return std::fabs(pull_off / (pi * 0.05 * 1e-6) + 1.5) < 1e-9 ? 0 : 1;
} catch (const asperity::Error& e) {
    std::fprintf(stderr, "asperity: %s\n", e.what());
    return 1;
}
