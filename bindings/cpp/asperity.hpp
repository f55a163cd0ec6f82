/*
 * asperity.hpp: header-only C++17 bindings over the C ABI of asperity
 * (include/asperity.h).
 *
 * - Every C function `asperity_<name>` has a counterpart: a free function
 *   `asperity::<name>` or, for the opaque handles, a member of the handle's
 *   class (`asperity_table_eval` is `asperity::Table::eval`). Results are
 *   returned instead of written through out-pointers.
 * - A failed call throws `asperity::Error`, a `std::runtime_error` carrying
 *   the status code (`status()`, one of `ASPERITY_ERR_*`) and the library's
 *   message naming the argument and its bound (`what()`).
 * - Opaque handles are RAII classes (`Table`, `GwEmpirical`, `Bora`,
 *   `HomogenisedFriction`, `SliderGeometry`, `Slider`, `Friction`,
 *   `FrictionWork`):
 *   move-only, `noexcept` moves, the destructor calls `asperity_<thing>_free`;
 *   `get()` gives the C pointer for mixing with C calls and `release()` gives
 *   up ownership.
 * - The plain `repr(C)` structs of the C header (`AsperityNormalLaw`,
 *   `AsperityContactState`, `AsperityFrictionIncrement`, ...) and the
 *   `ASPERITY_*` constants are used as they are.
 * - Arrays are passed as `asperity::span<T>`, a pointer and a size built
 *   implicitly from a `std::vector`, a `std::array`, a C array or
 *   `{pointer, size}`; an empty span stands for a NULL optional array.
 *   Output arrays need room for the values written; a span that is too short
 *   throws `asperity::Error` with `ASPERITY_ERR_INVALID_ARGUMENT` before the
 *   library is called.
 *
 * Units are SI throughout (m, N, Pa, J, J/m^2), as in asperity.h. Thread
 * safety is the C library's: the handles are immutable after construction and
 * their const members may be called from several threads at once.
 *
 * Compile with `-I <asperity>/include -I <asperity>/bindings/cpp` (C++17) and
 * link `-lasperity` as for C.
 */
#ifndef ASPERITY_HPP
#define ASPERITY_HPP

#include "asperity.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace asperity {

// ---------------------------------------------------------------------------
// Errors

/// A failed library call: the status code (`ASPERITY_ERR_*`) and the message
/// of `asperity_last_error_message` (or, for a span that is too short, the
/// C++ layer's own message naming the argument).
class Error : public std::runtime_error {
public:
    /// An error with status `status` and message `message`.
    Error(std::int32_t status, const std::string& message)
        : std::runtime_error(message), status_(status)
    {
    }

    /// The status code, one of `ASPERITY_ERR_*`.
    [[nodiscard]] std::int32_t status() const noexcept { return status_; }

    /// `asperity_status_string` of the status ("invalid argument", ...).
    [[nodiscard]] const char* status_string() const noexcept
    {
        return asperity_status_string(status_);
    }

private:
    std::int32_t status_;
};

/// `asperity_last_error_message`: the message of the last failed call on this
/// thread (empty before the first failure), queried for its size and copied.
[[nodiscard]] inline std::string last_error_message()
{
    std::string text(asperity_last_error_message(nullptr, 0) + 1, '\0');
    const std::size_t length = asperity_last_error_message(&text[0], text.size());
    text.resize(length < text.size() ? length : text.size() - 1);
    return text;
}

/// Throw `asperity::Error` with `status` and `last_error_message()` unless
/// `status` is `ASPERITY_OK`.
inline void check(std::int32_t status)
{
    if (status != ASPERITY_OK) {
        throw Error(status, last_error_message());
    }
}

/// `asperity_status_string`: a static description of a status code
/// ("unknown status" for a value that is not one). Do not free.
[[nodiscard]] inline const char* status_string(std::int32_t status) noexcept
{
    return asperity_status_string(status);
}

/// `asperity_version`: the library's version, "MAJOR.MINOR.PATCH" (static
/// storage). Compare with `ASPERITY_VERSION_*` of the header you compiled
/// against, or use `version_matches_header()`.
[[nodiscard]] inline const char* version() noexcept { return asperity_version(); }

/// True when the linked library (`asperity_version`) is the version of the
/// header this program was compiled with.
[[nodiscard]] inline bool version_matches_header()
{
    const std::string header = std::to_string(ASPERITY_VERSION_MAJOR) + "." +
                               std::to_string(ASPERITY_VERSION_MINOR) + "." +
                               std::to_string(ASPERITY_VERSION_PATCH);
    return header == asperity_version();
}

/// Size and alignment in bytes of a `repr(C)` type of the header.
struct TypeLayout {
    std::size_t size;
    std::size_t align;
};

/// `asperity_type_layout`: the library's size and alignment of the struct or
/// union whose C name is `name` (e.g. "AsperityNormalLaw"), to check a
/// binding's own copies against the library it is linked to.
[[nodiscard]] inline TypeLayout type_layout(const std::string& name)
{
    TypeLayout l{0, 0};
    check(asperity_type_layout(name.c_str(), &l.size, &l.align));
    return l;
}

/// `asperity_type_count`: the number of types `type_layout` knows.
[[nodiscard]] inline std::size_t type_count() noexcept { return asperity_type_count(); }

/// `asperity_type_name`: the C name of type `index` (< `type_count()`).
[[nodiscard]] inline std::string type_name(std::size_t index)
{
    std::size_t needed = 0;
    check(asperity_type_name(index, nullptr, 0, &needed));
    std::string text(needed + 1, '\0');
    check(asperity_type_name(index, &text[0], text.size(), &needed));
    text.resize(needed);
    return text;
}

// ---------------------------------------------------------------------------
// Arrays

/// A view of `size()` contiguous `T` at `data()` (`std::span` for C++17).
/// Built implicitly from a `std::vector`, a `std::array`, any contiguous
/// container with `data()` and `size()`, a C array, or `{pointer, size}`.
template <class T>
class span {
public:
    using element_type = T;
    using value_type = typename std::remove_cv<T>::type;
    using size_type = std::size_t;
    using pointer = T*;
    using iterator = T*;

    /// The empty view (NULL for optional arrays).
    constexpr span() noexcept = default;

    /// `size` values at `data`.
    constexpr span(T* data, std::size_t size) noexcept : data_(data), size_(size) {}

    /// A C array.
    template <std::size_t N>
    constexpr span(T (&array)[N]) noexcept : data_(array), size_(N)
    {
    }

    /// A contiguous container (`std::vector`, `std::array`, another span);
    /// a temporary only for a view of const elements (an input argument).
    template <class Container,
              class = typename std::enable_if<
                  (std::is_lvalue_reference<Container>::value || std::is_const<T>::value) &&
                  std::is_convertible<decltype(std::declval<Container&>().data()), T*>::value &&
                  std::is_convertible<decltype(std::declval<Container&>().size()),
                                      std::size_t>::value>::type>
    constexpr span(Container&& container) noexcept(noexcept(container.data()))
        : data_(container.data()), size_(container.size())
    {
    }

    [[nodiscard]] constexpr T* data() const noexcept { return data_; }
    [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
    [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
    [[nodiscard]] constexpr T& operator[](std::size_t i) const noexcept { return data_[i]; }
    [[nodiscard]] constexpr T* begin() const noexcept { return data_; }
    [[nodiscard]] constexpr T* end() const noexcept { return data_ + size_; }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

namespace detail {

[[noreturn]] inline void size_error(const char* function, const char* argument,
                                    std::size_t size, const char* bound, std::size_t needed)
{
    throw Error(ASPERITY_ERR_INVALID_ARGUMENT,
                std::string("invalid argument `") + argument + "` = " + std::to_string(size) +
                    " values: must be " + bound + " " + std::to_string(needed) + " (" + function +
                    ")");
}

/// A non-NULL pointer for an array the library requires: the span's data, or
/// for an empty span a dummy that is never read or written (the library
/// then sees a count of 0 and reports that instead of a NULL pointer).
template <class T>
T* required(span<T> s) noexcept
{
    static typename std::remove_const<T>::type dummy{};
    return s.data() != nullptr ? s.data() : &dummy;
}

/// An array the library requires, with room for at least `needed` values.
template <class T>
T* at_least(span<T> s, std::size_t needed, const char* function, const char* argument)
{
    if (s.size() < needed) {
        size_error(function, argument, s.size(), "at least", needed);
    }
    return required(s);
}

/// An optional array: NULL when empty, otherwise room for `needed` values.
template <class T>
T* optional(span<T> s, std::size_t needed, const char* function, const char* argument)
{
    if (s.empty()) {
        return nullptr;
    }
    return at_least(s, needed, function, argument);
}

/// An input array that must hold exactly `needed` values.
template <class T>
T* exactly(span<T> s, std::size_t needed, const char* function, const char* argument)
{
    if (s.size() != needed) {
        size_error(function, argument, s.size(), "exactly", needed);
    }
    return required(s);
}

/// Text from a "query the size, then copy" C function `fetch(buf, len,
/// &needed)`.
template <class Fetch>
std::string text(Fetch fetch)
{
    std::size_t needed = 0;
    check(fetch(nullptr, 0, &needed));
    std::string out;
    for (;;) {
        out.assign(needed + 1, '\0');
        std::size_t written = 0;
        check(fetch(&out[0], out.size(), &written));
        if (written < out.size()) {
            out.resize(written);
            return out;
        }
        needed = written;
    }
}

/// Owns one opaque handle; `Free::free` releases it (and accepts NULL).
template <class T, class Free>
class unique_handle {
public:
    using element_type = T;

    /// An empty handle.
    unique_handle() noexcept = default;
    /// Take ownership of `owned` (from an `asperity_<thing>_new...` call).
    explicit unique_handle(T* owned) noexcept : handle_(owned) {}
    unique_handle(const unique_handle&) = delete;
    unique_handle& operator=(const unique_handle&) = delete;
    unique_handle(unique_handle&& other) noexcept : handle_(other.release()) {}
    unique_handle& operator=(unique_handle&& other) noexcept
    {
        reset(other.release());
        return *this;
    }
    ~unique_handle() { Free::free(handle_); }

    /// The C pointer, still owned by this object (NULL when empty).
    [[nodiscard]] T* get() const noexcept { return handle_; }
    /// Give up ownership: the caller frees the returned pointer.
    [[nodiscard]] T* release() noexcept
    {
        T* p = handle_;
        handle_ = nullptr;
        return p;
    }
    /// Free the current handle and own `owned` instead.
    void reset(T* owned = nullptr) noexcept
    {
        T* old = handle_;
        handle_ = owned;
        Free::free(old);
    }
    /// True unless empty.
    explicit operator bool() const noexcept { return handle_ != nullptr; }

private:
    T* handle_ = nullptr;
};

/// `asperity_table_free`, called by the destructor of `asperity::Table`.
struct free_table {
    static void free(AsperityTable* p) noexcept { asperity_table_free(p); }
};
/// `asperity_gw_empirical_free`, called by the destructor of
/// `asperity::GwEmpirical`.
struct free_gw_empirical {
    static void free(AsperityGwEmpirical* p) noexcept { asperity_gw_empirical_free(p); }
};
/// `asperity_bora_free`, called by the destructor of `asperity::Bora`.
struct free_bora {
    static void free(AsperityBora* p) noexcept { asperity_bora_free(p); }
};
/// `asperity_homogenised_friction_free`, called by the destructor of
/// `asperity::HomogenisedFriction`.
struct free_homogenised_friction {
    static void free(AsperityHomogenisedFriction* p) noexcept
    {
        asperity_homogenised_friction_free(p);
    }
};
/// `asperity_slider_geometry_free`, called by the destructor of
/// `asperity::SliderGeometry`.
struct free_slider_geometry {
    static void free(AsperitySliderGeometry* p) noexcept { asperity_slider_geometry_free(p); }
};
/// `asperity_slider_free`, called by the destructor of `asperity::Slider`.
struct free_slider {
    static void free(AsperitySlider* p) noexcept { asperity_slider_free(p); }
};
/// `asperity_friction_free`, called by the destructor of
/// `asperity::Friction`.
struct free_friction {
    static void free(AsperityFriction* p) noexcept { asperity_friction_free(p); }
};
/// `asperity_friction_work_free`, called by the destructor of
/// `asperity::FrictionWork`.
struct free_friction_work {
    static void free(AsperityFrictionWork* p) noexcept { asperity_friction_work_free(p); }
};

/// Calls a C++ callable from a C callback; an exception is kept and rethrown
/// after the library returns (NaN makes the library stop and fail).
template <class F>
struct density_callback {
    F* function;
    std::exception_ptr error;

    static double call(double xi, void* data) noexcept
    {
        auto* self = static_cast<density_callback*>(data);
        if (!self->error) {
            try {
                return static_cast<double>((*self->function)(xi));
            } catch (...) {
                self->error = std::current_exception();
            }
        }
        return std::numeric_limits<double>::quiet_NaN();
    }
};

} // namespace detail

// ---------------------------------------------------------------------------
// Single-asperity normal laws (AsperityNormalLaw by value)

/// `asperity_law_from_params`: the law of kind `kind` (`ASPERITY_LAW_*`) from
/// its inputs, the member of `params` that `kind` names (`params.jkr`, ...).
[[nodiscard]] inline AsperityNormalLaw law_from_params(std::int32_t kind,
                                                       const AsperityLawParams& params)
{
    AsperityNormalLaw law{};
    check(asperity_law_from_params(kind, &params, &law));
    return law;
}

/// `asperity_law_hertz`: Hertz sphere, radius R (m), contact modulus E* (Pa).
[[nodiscard]] inline AsperityNormalLaw law_hertz(double radius, double e_star)
{
    AsperityNormalLaw law{};
    check(asperity_law_hertz(radius, e_star, &law));
    return law;
}

/// `asperity_law_sphere_in_crater`: Galanov effective sphere of radius
/// `radius` (m) in a crater of radius `medium_radius` (m, INFINITY: flat).
[[nodiscard]] inline AsperityNormalLaw law_sphere_in_crater(double radius, double medium_radius,
                                                            double e_star)
{
    AsperityNormalLaw law{};
    check(asperity_law_sphere_in_crater(radius, medium_radius, e_star, &law));
    return law;
}

/// `asperity_law_power_punch`: Galin punch `f(r) = b r^d`, 1 <= d <= 100.
[[nodiscard]] inline AsperityNormalLaw law_power_punch(double b, double d, double e_star)
{
    AsperityNormalLaw law{};
    check(asperity_law_power_punch(b, d, e_star, &law));
    return law;
}

/// `asperity_law_cone`: cone of half-angle `half_angle` (rad).
[[nodiscard]] inline AsperityNormalLaw law_cone(double half_angle, double e_star)
{
    AsperityNormalLaw law{};
    check(asperity_law_cone(half_angle, e_star, &law));
    return law;
}

/// `asperity_law_cone_in_imprint`: Galanov effective cone, indenter half-angle
/// in an imprint of a larger half-angle (rad).
[[nodiscard]] inline AsperityNormalLaw law_cone_in_imprint(double indenter_half_angle,
                                                           double imprint_half_angle,
                                                           double e_star)
{
    AsperityNormalLaw law{};
    check(asperity_law_cone_in_imprint(indenter_half_angle, imprint_half_angle, e_star, &law));
    return law;
}

/// `asperity_law_flat_punch`: frictionless flat punch of radius a (m).
[[nodiscard]] inline AsperityNormalLaw law_flat_punch(double radius, double e_star)
{
    AsperityNormalLaw law{};
    check(asperity_law_flat_punch(radius, e_star, &law));
    return law;
}

/// `asperity_law_flat_punch_no_slip`: bonded flat punch on a half-space of
/// Poisson's ratio `nu`.
[[nodiscard]] inline AsperityNormalLaw law_flat_punch_no_slip(double radius, double e_star,
                                                              double nu)
{
    AsperityNormalLaw law{};
    check(asperity_law_flat_punch_no_slip(radius, e_star, nu, &law));
    return law;
}

/// `asperity_law_dmt`: DMT sphere, radius (m), E* (Pa), work of adhesion
/// (J/m^2).
[[nodiscard]] inline AsperityNormalLaw law_dmt(double radius, double e_star,
                                               double work_of_adhesion)
{
    AsperityNormalLaw law{};
    check(asperity_law_dmt(radius, e_star, work_of_adhesion, &law));
    return law;
}

/// `asperity_law_jkr`: JKR sphere, radius (m), E* (Pa), work of adhesion
/// (J/m^2).
[[nodiscard]] inline AsperityNormalLaw law_jkr(double radius, double e_star,
                                               double work_of_adhesion)
{
    AsperityNormalLaw law{};
    check(asperity_law_jkr(radius, e_star, work_of_adhesion, &law));
    return law;
}

/// `asperity_law_jkr_power_punch`: JKR power-law punch (Borodich 2014),
/// bonded to a half-space of Poisson's ratio `nu` when `no_slip`.
[[nodiscard]] inline AsperityNormalLaw law_jkr_power_punch(double b, double d, double e_star,
                                                           double work_of_adhesion, double nu,
                                                           bool no_slip)
{
    AsperityNormalLaw law{};
    check(asperity_law_jkr_power_punch(b, d, e_star, work_of_adhesion, nu, no_slip ? 1 : 0,
                                       &law));
    return law;
}

/// `asperity_law_kendall`: Kendall adhesive flat punch of radius a (m),
/// bonded (no-slip) on a half-space of Poisson's ratio `nu` when `no_slip`.
[[nodiscard]] inline AsperityNormalLaw law_kendall(double radius, double e_star,
                                                   double work_of_adhesion, double nu,
                                                   bool no_slip)
{
    AsperityNormalLaw law{};
    check(asperity_law_kendall(radius, e_star, work_of_adhesion, nu, no_slip ? 1 : 0, &law));
    return law;
}

/// `asperity_law_maugis_dugdale`: Maugis-Dugdale sphere, radius (m), E* (Pa),
/// work of adhesion (J/m^2), Dugdale cohesive stress sigma0 (Pa).
[[nodiscard]] inline AsperityNormalLaw law_maugis_dugdale(double radius, double e_star,
                                                          double work_of_adhesion, double sigma0)
{
    AsperityNormalLaw law{};
    check(asperity_law_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, &law));
    return law;
}

/// `asperity_law_derjaguin`: rigid sphere with a surface-force law
/// (`ASPERITY_SURFACE_LAW_*`) whose second parameter is `parameter`.
[[nodiscard]] inline AsperityNormalLaw law_derjaguin(double radius, double work_of_adhesion,
                                                     std::int32_t surface_law, double parameter)
{
    AsperityNormalLaw law{};
    check(asperity_law_derjaguin(radius, work_of_adhesion, surface_law, parameter, &law));
    return law;
}

/// `asperity_normal_eval`: `law` at the overlap `delta` (m) from the history
/// `old_state` (NULL: fresh), writing the new history to `new_state` (NULL:
/// discarded; may equal `old_state`).
[[nodiscard]] inline AsperityNormalResponse normal_eval(
    const AsperityNormalLaw& law, double delta, const AsperityContactState* old_state = nullptr,
    AsperityContactState* new_state = nullptr)
{
    AsperityNormalResponse out{};
    check(asperity_normal_eval(&law, delta, old_state, new_state, &out));
    return out;
}

/// `asperity_normal_eval` with the history `state` updated in place.
inline AsperityNormalResponse normal_eval(const AsperityNormalLaw& law, double delta,
                                          AsperityContactState& state)
{
    return normal_eval(law, delta, &state, &state);
}

/// `asperity_normal_eval_batch`: `law` for `delta.size()` contacts. `force`
/// needs room for them; `old_state` (fresh when empty), `new_state`,
/// `contact_radius` and `stiffness` are empty or as long. Inputs and outputs
/// may be the same memory (pass one vector of states twice to update it in
/// place).
inline void normal_eval_batch(const AsperityNormalLaw& law, span<const double> delta,
                              span<const AsperityContactState> old_state,
                              span<AsperityContactState> new_state, span<double> force,
                              span<double> contact_radius = {}, span<double> stiffness = {})
{
    const char* f = "asperity::normal_eval_batch";
    const std::size_t n = delta.size();
    check(asperity_normal_eval_batch(&law, n, detail::required(delta),
                                     detail::optional(old_state, n, f, "old_state"),
                                     detail::optional(new_state, n, f, "new_state"),
                                     detail::at_least(force, n, f, "force"),
                                     detail::optional(contact_radius, n, f, "contact_radius"),
                                     detail::optional(stiffness, n, f, "stiffness")));
}

/// `asperity_normal_eval_at_load`: equilibrium at the prescribed force
/// `force` (N) on the stable branch; `.delta` is the overlap.
[[nodiscard]] inline AsperityNormalResponse normal_eval_at_load(const AsperityNormalLaw& law,
                                                                double force)
{
    AsperityNormalResponse out{};
    check(asperity_normal_eval_at_load(&law, force, &out));
    return out;
}

/// `asperity_pull_off_force`: the separation force (N, <= 0 for adhesive
/// laws) under `control` (`ASPERITY_CONTROL_LOAD` or
/// `ASPERITY_CONTROL_DISPLACEMENT`).
[[nodiscard]] inline double pull_off_force(const AsperityNormalLaw& law, std::int32_t control)
{
    double force = 0.0;
    check(asperity_pull_off_force(&law, control, &force));
    return force;
}

/// `asperity_normal_reach`: the overlap (m, <= 0) below which the force of
/// `law` is zero from any history when the contact separates under
/// `control` (`ASPERITY_CONTROL_*`), or below which |force| < `rel_force`
/// x |load pull-off force| for laws with an infinite tail; `rel_force` in
/// (0, 1).
[[nodiscard]] inline double normal_reach(const AsperityNormalLaw& law, std::int32_t control,
                                         double rel_force = 1e-6)
{
    double delta = 0.0;
    check(asperity_normal_reach(&law, control, rel_force, &delta));
    return delta;
}

/// `asperity_normal_energy`: the energy (J) of the equilibrium of `law` at
/// the overlap `delta` (m) reached from `old_state` (NULL: fresh), with
/// dU/ddelta = P along the branch; 0 for a separated contact.
[[nodiscard]] inline double normal_energy(const AsperityNormalLaw& law, double delta,
                                          const AsperityContactState* old_state = nullptr)
{
    double energy = 0.0;
    check(asperity_normal_energy(&law, delta, old_state, &energy));
    return energy;
}

/// `asperity_law_length_scale`: a characteristic overlap of `law` (m).
[[nodiscard]] inline double law_length_scale(const AsperityNormalLaw& law)
{
    double length = 0.0;
    check(asperity_law_length_scale(&law, &length));
    return length;
}

/// `asperity_fidelity_advise`: the cheapest adhesive-sphere model within
/// `force_tolerance` (N) of the converged Lennard-Jones sphere. Runs the
/// Lennard-Jones solver: not for a hot path.
[[nodiscard]] inline AsperityFidelityAdvice fidelity_advise(double radius, double e_star,
                                                            double work_of_adhesion, double z0,
                                                            double force_tolerance)
{
    AsperityFidelityAdvice out{};
    check(asperity_fidelity_advise(radius, e_star, work_of_adhesion, z0, force_tolerance, &out));
    return out;
}

/// `asperity_lj_sphere_pull_off`: load-controlled pull-off force (N,
/// negative) of the numerical Lennard-Jones sphere on `n_grid` cells (0: the
/// converged default).
[[nodiscard]] inline double lj_sphere_pull_off(double radius, double e_star,
                                               double work_of_adhesion, double z0,
                                               std::size_t n_grid = 0)
{
    double force = 0.0;
    check(asperity_lj_sphere_pull_off(radius, e_star, work_of_adhesion, z0, n_grid, &force));
    return force;
}

// ---------------------------------------------------------------------------
// Tabulated laws

/// An immutable tabulated contact law (`AsperityTable`), safe to share
/// between threads. Build it with `Table::maugis_dugdale`,
/// `Table::lennard_jones` or `Table::from_json`.
class Table : public detail::unique_handle<AsperityTable, detail::free_table> {
public:
    using unique_handle::unique_handle;

    /// `asperity_table_new_maugis_dugdale`: the table of a Maugis-Dugdale
    /// sphere with relative `tolerance` in [1e-10, 0.1].
    [[nodiscard]] static Table maugis_dugdale(double radius, double e_star,
                                              double work_of_adhesion, double sigma0,
                                              double tolerance = 1e-4)
    {
        AsperityTable* p = nullptr;
        check(asperity_table_new_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0,
                                                tolerance, &p));
        return Table(p);
    }

    /// `asperity_table_new_lj`: the table of a Lennard-Jones sphere solved on
    /// `n_grid` cells (0: the converged default), relative `tolerance`.
    [[nodiscard]] static Table lennard_jones(double radius, double e_star,
                                             double work_of_adhesion, double z0,
                                             std::size_t n_grid = 0, double tolerance = 1e-4)
    {
        AsperityTable* p = nullptr;
        check(asperity_table_new_lj(radius, e_star, work_of_adhesion, z0, n_grid, tolerance, &p));
        return Table(p);
    }

    /// `asperity_table_from_json`: a table from the text of `to_json()`
    /// (validated).
    [[nodiscard]] static Table from_json(std::string_view json)
    {
        AsperityTable* p = nullptr;
        check(asperity_table_from_json(json.data(), json.size(), &p));
        return Table(p);
    }

    /// `asperity_table_to_json`: the table as JSON text.
    [[nodiscard]] std::string to_json() const
    {
        AsperityTable* t = get();
        return detail::text([t](char* buf, std::size_t len, std::size_t* needed) {
            return asperity_table_to_json(t, buf, len, needed);
        });
    }

    /// `asperity_table_eval`: the table at the overlap `delta` (m) from
    /// `old_state` (NULL: fresh) into `new_state` (NULL: discarded; may equal
    /// `old_state`).
    [[nodiscard]] AsperityNormalResponse eval(double delta,
                                              const AsperityContactState* old_state = nullptr,
                                              AsperityContactState* new_state = nullptr) const
    {
        AsperityNormalResponse out{};
        check(asperity_table_eval(get(), delta, old_state, new_state, &out));
        return out;
    }

    /// `asperity_table_eval` with the history `state` updated in place.
    AsperityNormalResponse eval(double delta, AsperityContactState& state) const
    {
        return eval(delta, &state, &state);
    }

    /// `asperity_table_eval_batch`: as `asperity::normal_eval_batch`.
    void eval_batch(span<const double> delta, span<const AsperityContactState> old_state,
                    span<AsperityContactState> new_state, span<double> force,
                    span<double> contact_radius = {}, span<double> stiffness = {}) const
    {
        const char* f = "asperity::Table::eval_batch";
        const std::size_t n = delta.size();
        check(asperity_table_eval_batch(get(), n, detail::required(delta),
                                        detail::optional(old_state, n, f, "old_state"),
                                        detail::optional(new_state, n, f, "new_state"),
                                        detail::at_least(force, n, f, "force"),
                                        detail::optional(contact_radius, n, f, "contact_radius"),
                                        detail::optional(stiffness, n, f, "stiffness")));
    }

    /// `asperity_table_eval_at_load`: equilibrium at the prescribed force
    /// `force` (N) on the load-controlled stable branch.
    [[nodiscard]] AsperityNormalResponse eval_at_load(double force) const
    {
        AsperityNormalResponse out{};
        check(asperity_table_eval_at_load(get(), force, &out));
        return out;
    }

    /// `asperity_table_pull_off_force`: the pull-off force (N) under
    /// `control` (`ASPERITY_CONTROL_*`).
    [[nodiscard]] double pull_off_force(std::int32_t control) const
    {
        double force = 0.0;
        check(asperity_table_pull_off_force(get(), control, &force));
        return force;
    }

    /// `asperity_table_reach`: the overlap (m) below which the table's force
    /// is zero from any history under `control` (`ASPERITY_CONTROL_*`), or
    /// below which |force| < `rel_force` x |load pull-off force| with a
    /// Lennard-Jones far tail; `rel_force` in (0, 1).
    [[nodiscard]] double reach(std::int32_t control, double rel_force = 1e-6) const
    {
        double delta = 0.0;
        check(asperity_table_reach(get(), control, rel_force, &delta));
        return delta;
    }

    /// `asperity_table_max_error`: the stated maximum relative error (the
    /// tolerance).
    [[nodiscard]] double max_error() const
    {
        double stated = 0.0;
        check(asperity_table_max_error(get(), &stated, nullptr));
        return stated;
    }

    /// `asperity_table_max_error`: the largest error measured at
    /// construction.
    [[nodiscard]] double measured_error() const
    {
        double stated = 0.0;
        double measured = 0.0;
        check(asperity_table_max_error(get(), &stated, &measured));
        return measured;
    }
};

// ---------------------------------------------------------------------------
// Hierarchical friction: slider geometry

/// The slider of the hierarchical friction model (`AsperitySliderGeometry`):
/// nested levels of micro-rods and the nano-asperities on the finest rods.
/// Immutable; safe to share between threads.
class SliderGeometry
    : public detail::unique_handle<AsperitySliderGeometry, detail::free_slider_geometry> {
public:
    using unique_handle::unique_handle;
    SliderGeometry() noexcept = default;

    /// `asperity_slider_geometry_new`: a slider from a profilometer profile
    /// (`micro_heights`, m, spacing `micro_dx`) cut into rods of the nested
    /// `rod_widths` (m, coarsest first) and an AFM profile (`nano_heights`,
    /// spacing `nano_dx`) giving the nano-asperities.
    SliderGeometry(span<const double> micro_heights, double micro_dx,
                   span<const double> nano_heights, double nano_dx,
                   span<const double> rod_widths)
    {
        AsperitySliderGeometry* p = nullptr;
        check(asperity_slider_geometry_new(detail::required(micro_heights), micro_heights.size(),
                                           micro_dx, detail::required(nano_heights),
                                           nano_heights.size(), nano_dx,
                                           detail::required(rod_widths), rod_widths.size(), &p));
        reset(p);
    }

    /// `asperity_slider_geometry_new_uniform`: one level of `rods` flat rods
    /// of `rod_width` (m), each carrying `nano.per_rod` nano-asperities.
    [[nodiscard]] static SliderGeometry uniform(double rod_width, std::size_t rods,
                                                const AsperityNanoAsperities& nano)
    {
        AsperitySliderGeometry* p = nullptr;
        check(asperity_slider_geometry_new_uniform(rod_width, rods, &nano, &p));
        return SliderGeometry(p);
    }

    /// `asperity_slider_geometry_nano`: the nano-asperity parameters.
    [[nodiscard]] AsperityNanoAsperities nano() const
    {
        AsperityNanoAsperities out{};
        check(asperity_slider_geometry_nano(get(), &out));
        return out;
    }

    /// `asperity_slider_geometry_level_count`: the number of rod levels.
    [[nodiscard]] std::size_t level_count() const
    {
        std::size_t count = 0;
        check(asperity_slider_geometry_level_count(get(), &count));
        return count;
    }

    /// `asperity_slider_geometry_rod_count`: the number of rods of `level`
    /// (0 = coarsest).
    [[nodiscard]] std::size_t rod_count(std::size_t level) const
    {
        std::size_t count = 0;
        check(asperity_slider_geometry_rod_count(get(), level, &count));
        return count;
    }

    /// `asperity_slider_geometry_rod_width`: the rod width (m) of `level`.
    [[nodiscard]] double rod_width(std::size_t level) const
    {
        double width = 0.0;
        check(asperity_slider_geometry_rod_width(get(), level, &width, nullptr));
        return width;
    }

    /// `asperity_slider_geometry_rod_width`: the left side (m) of rod 0 of
    /// `level`; rod k spans [origin + k width, origin + (k+1) width].
    [[nodiscard]] double rod_origin(std::size_t level) const
    {
        double width = 0.0;
        double origin = 0.0;
        check(asperity_slider_geometry_rod_width(get(), level, &width, &origin));
        return origin;
    }

    /// `asperity_slider_geometry_rod_heights`: the rod heights (m) of `level`
    /// into `heights` (at least `rod_count(level)` values).
    void rod_heights(std::size_t level, span<double> heights) const
    {
        check(asperity_slider_geometry_rod_heights(get(), level, detail::required(heights),
                                                   heights.size()));
    }

    /// `asperity_slider_geometry_rod_heights`: the rod heights (m) of `level`.
    [[nodiscard]] std::vector<double> rod_heights(std::size_t level) const
    {
        std::vector<double> heights(rod_count(level));
        rod_heights(level, heights);
        return heights;
    }
};

// ---------------------------------------------------------------------------
// Homogenised friction law of FE integration points

/// The homogenised friction table (`AsperityHomogenisedFriction`): mu(p),
/// adhesion, contact fraction and dissipation shares over the nominal
/// pressure. Immutable; safe to share between threads. Stepped as a
/// friction law through `Friction::from_homogenised`.
class HomogenisedFriction
    : public detail::unique_handle<AsperityHomogenisedFriction,
                                   detail::free_homogenised_friction> {
public:
    using unique_handle::unique_handle;
    HomogenisedFriction() noexcept = default;

    /// `asperity_homogenised_friction_new`: the law from samples at strictly
    /// increasing nominal pressures (cof read as the Derjaguin F/(N + A)).
    explicit HomogenisedFriction(span<const AsperityHomogenisedSample> samples)
    {
        AsperityHomogenisedFriction* p = nullptr;
        check(asperity_homogenised_friction_new(detail::required(samples), samples.size(), &p));
        reset(p);
    }

    /// `asperity_homogenised_friction_from_json`: a law from JSON text
    /// (validated).
    [[nodiscard]] static HomogenisedFriction from_json(std::string_view json)
    {
        AsperityHomogenisedFriction* p = nullptr;
        check(asperity_homogenised_friction_from_json(json.data(), json.size(), &p));
        return HomogenisedFriction(p);
    }

    /// `asperity_homogenised_friction_to_json`: the law as JSON text.
    [[nodiscard]] std::string to_json() const
    {
        AsperityHomogenisedFriction* h = get();
        return detail::text([h](char* buf, std::size_t len, std::size_t* needed) {
            return asperity_homogenised_friction_to_json(h, buf, len, needed);
        });
    }
};

// ---------------------------------------------------------------------------
// The hierarchical slider (thesis chapter 6)

/// `asperity_friction_material_copper`: the thesis's Cu–Cu friction
/// material (REFERENCE.md §5).
[[nodiscard]] inline AsperityFrictionMaterial friction_material_copper()
{
    AsperityFrictionMaterial out{};
    check(asperity_friction_material_copper(&out));
    return out;
}

/// `asperity_slider_options_default`: the library's default slider options
/// (fixed load 0 N: set `normal_force`).
[[nodiscard]] inline AsperitySliderOptions slider_options_default()
{
    AsperitySliderOptions out{};
    check(asperity_slider_options_default(&out));
    return out;
}

/// The full hierarchical slider against its counter-surface
/// (`AsperitySlider`). Immutable; safe to share between threads. Stepped as
/// the friction law of a surface patch through `Friction::from_slider`
/// (state layout: the `ASPERITY_SLIDER_STATE_*` indices).
class Slider : public detail::unique_handle<AsperitySlider, detail::free_slider> {
public:
    using unique_handle::unique_handle;
    Slider() noexcept = default;

    /// `asperity_slider_new`: a slider from structs: the rods and
    /// nano-asperities of `geometry` (copied), the friction `material`, the
    /// rigid counter-surface `counter` (heights from its mean line, m)
    /// sampled at `counter_dx` (m), and `options`.
    Slider(const SliderGeometry& geometry, const AsperityFrictionMaterial& material,
           span<const double> counter, double counter_dx, const AsperitySliderOptions& options)
    {
        AsperitySlider* p = nullptr;
        check(asperity_slider_new(geometry.get(), &material, detail::required(counter),
                                  counter.size(), counter_dx, &options, &p));
        reset(p);
    }

    /// `asperity_slider_from_scene_json`: a slider from the scene JSON text
    /// `json` (the format of `examples/scenes/*.json`); relative file paths
    /// in the scene are resolved against `base_dir` (NULL: the current
    /// directory). A JSON or field error throws `ASPERITY_ERR_PARSE` with the
    /// line, column and field.
    [[nodiscard]] static Slider from_scene_json(std::string_view json,
                                                const char* base_dir = nullptr)
    {
        AsperitySlider* p = nullptr;
        check(asperity_slider_from_scene_json(json.data(), json.size(), base_dir, &p));
        return Slider(p);
    }

    /// `asperity_slider_from_scene_json` with the scene's directory
    /// `base_dir`.
    [[nodiscard]] static Slider from_scene_json(std::string_view json,
                                                const std::string& base_dir)
    {
        return from_scene_json(json, base_dir.c_str());
    }

    /// `asperity_slider_info`: sizes and capacities (SI).
    [[nodiscard]] AsperitySliderInfo info() const
    {
        AsperitySliderInfo out{};
        check(asperity_slider_info(get(), &out));
        return out;
    }
};

// ---------------------------------------------------------------------------
// The friction step: one handle for every per-increment friction law

class Friction;

/// The scratch of a friction step (`AsperityFrictionWork`): one per thread,
/// built once with `FrictionWork(law)` (or `law.work()`); one made for
/// another law is rebuilt on its first use. Not shared: a step writes into
/// it.
class FrictionWork
    : public detail::unique_handle<AsperityFrictionWork, detail::free_friction_work> {
public:
    using unique_handle::unique_handle;
    FrictionWork() noexcept = default;

    /// `asperity_friction_work_new`: the scratch of a step with `law`.
    explicit FrictionWork(const Friction& law);

    /// `asperity_slider_record`: the full record of the last step this
    /// scratch took with a slider law (`Friction::from_slider`): positions
    /// (m), the adhesion area share, the counts of contacts and whether the
    /// step seated a fresh state (`seated` 1); all zero for a scratch made
    /// for a slider law that has not stepped yet. Throws (naming `work`) for
    /// an empty scratch or one of another law.
    [[nodiscard]] AsperitySliderRecord slider_record() const
    {
        AsperitySliderRecord out{};
        check(asperity_slider_record(get(), &out));
        return out;
    }
};

/// A friction law stepped once per time increment (`AsperityFriction`):
/// the homogenised law, the slider as a patch law, or a chapter-5 dynamic
/// model (LuGre, Maxwell-slip, bristles, Prandtl-Tomlinson with one or two
/// springs, Burridge-Knopoff). Immutable; safe to share between threads,
/// each thread stepping with its own `FrictionWork`.
///
/// Per-point states are caller-owned arrays of `state_size()` doubles
/// (all-zero = fresh): `[ASPERITY_FRICTION_STATE_DISSIPATION]` the
/// accumulated dissipation (J), `[ASPERITY_FRICTION_STATE_SLIP_PATH]` the
/// slip path (m), then the law's own from `ASPERITY_FRICTION_STATE_MODEL`.
/// The old and new states are separate (a host can re-evaluate or cut back
/// an increment); the `_in_place` forms update one state. Sign convention:
/// the slip increment is the motion of the point relative to the
/// counter-surface, the force is the force on the point and opposes slip.
/// `work` may be null: a scratch is then built for the call (the slider's
/// allocates).
class Friction : public detail::unique_handle<AsperityFriction, detail::free_friction> {
public:
    using unique_handle::unique_handle;
    Friction() noexcept = default;

    /// `asperity_friction_from_homogenised`: the homogenised law of `table`
    /// (copied) with the stick stiffness `stick_stiffness` (N/m, >= 0; 0:
    /// rigid-plastic). Increments need the nominal `area` > 0.
    [[nodiscard]] static Friction from_homogenised(const HomogenisedFriction& table,
                                                   double stick_stiffness = 0.0)
    {
        AsperityFriction* p = nullptr;
        check(asperity_friction_from_homogenised(table.get(), stick_stiffness, &p));
        return Friction(p);
    }

    /// `asperity_friction_from_slider`: the slider (copied) as the law of a
    /// surface patch; the increment's normal force is the fixed load (<= the
    /// capacity), its area is unused.
    [[nodiscard]] static Friction from_slider(const Slider& slider)
    {
        AsperityFriction* p = nullptr;
        check(asperity_friction_from_slider(slider.get(), &p));
        return Friction(p);
    }

    /// `asperity_friction_lugre_new`: the LuGre model of `params`.
    [[nodiscard]] static Friction lugre(const AsperityLugreParams& params)
    {
        AsperityFriction* p = nullptr;
        check(asperity_friction_lugre_new(&params, &p));
        return Friction(p);
    }

    /// `asperity_friction_maxwell_slip_new`: Maxwell-slip elements of
    /// stiffnesses `stiffness` (1/m per unit normal force) and break-away
    /// coefficients `capacity` (one per element), viscous `sigma2` (N s/m).
    [[nodiscard]] static Friction maxwell_slip(span<const double> stiffness,
                                               span<const double> capacity, double sigma2 = 0.0)
    {
        const std::size_t n = stiffness.size();
        AsperityFriction* p = nullptr;
        check(asperity_friction_maxwell_slip_new(
            detail::required(stiffness),
            detail::at_least(capacity, n, "asperity::Friction::maxwell_slip", "capacity"), n,
            sigma2, &p));
        return Friction(p);
    }

    /// `asperity_friction_generalized_maxwell_slip_new`: the generalised
    /// Maxwell-slip model, elements of stiffnesses `stiffness` (1/m per unit
    /// normal force) and weights `weight` (one per element) attracted to the
    /// Stribeck curve of `params`. One-dimensional, rate dependent.
    [[nodiscard]] static Friction
    generalized_maxwell_slip(span<const double> stiffness, span<const double> weight,
                             const AsperityGeneralizedMaxwellSlipParams& params)
    {
        const std::size_t n = stiffness.size();
        AsperityFriction* p = nullptr;
        check(asperity_friction_generalized_maxwell_slip_new(
            detail::required(stiffness),
            detail::at_least(weight, n, "asperity::Friction::generalized_maxwell_slip", "weight"),
            n, &params, &p));
        return Friction(p);
    }

    /// `asperity_friction_bristles_new`: bristles of stiffnesses `stiffness`
    /// (1/m per unit normal force) and break deflections `break_deflection`
    /// (m, one per bristle), viscous `sigma2` (N s/m). One-dimensional.
    [[nodiscard]] static Friction bristles(span<const double> stiffness,
                                           span<const double> break_deflection,
                                           double sigma2 = 0.0)
    {
        const std::size_t n = stiffness.size();
        AsperityFriction* p = nullptr;
        check(asperity_friction_bristles_new(
            detail::required(stiffness),
            detail::at_least(break_deflection, n, "asperity::Friction::bristles",
                             "break_deflection"),
            n, sigma2, &p));
        return Friction(p);
    }

    /// `asperity_friction_prandtl_tomlinson_new`: a tip in a lattice
    /// potential of amplitude `amplitude` (J) and period `period` (m) pulled
    /// through a spring `stiffness` (N/m), mass `mass` (kg), damping
    /// `damping` (kg/s), integration tolerance `tolerance`.
    [[nodiscard]] static Friction prandtl_tomlinson(double amplitude, double period,
                                                    double stiffness, double mass, double damping,
                                                    double tolerance = 1e-9)
    {
        AsperityFriction* p = nullptr;
        check(asperity_friction_prandtl_tomlinson_new(amplitude, period, stiffness, mass, damping,
                                                      tolerance, &p));
        return Friction(p);
    }

    /// `asperity_friction_prandtl_tomlinson_two_spring_new`: the
    /// tip-cantilever Prandtl-Tomlinson model of `params` (the tip spring
    /// and the cantilever spring in series; state size 7).
    [[nodiscard]] static Friction
    prandtl_tomlinson_two_spring(const AsperityPrandtlTomlinsonTwoSpringParams& params)
    {
        AsperityFriction* p = nullptr;
        check(asperity_friction_prandtl_tomlinson_two_spring_new(&params, &p));
        return Friction(p);
    }

    /// `asperity_friction_burridge_knopoff_new`: the Burridge-Knopoff block
    /// chain of `params` (state size 3 + 2 x blocks; the force is the leaf
    /// springs' pull on the driver).
    [[nodiscard]] static Friction burridge_knopoff(const AsperityBurridgeKnopoffParams& params)
    {
        AsperityFriction* p = nullptr;
        check(asperity_friction_burridge_knopoff_new(&params, &p));
        return Friction(p);
    }

    /// `asperity_friction_state_size`: doubles of one point's state.
    [[nodiscard]] std::size_t state_size() const
    {
        std::size_t n = 0;
        check(asperity_friction_state_size(get(), &n));
        return n;
    }

    /// A new scratch for steps with this law (`FrictionWork(*this)`).
    [[nodiscard]] FrictionWork work() const;

    /// `asperity_friction_step`: one increment of one point from
    /// `old_state` into `new_state` (each at least `state_size()` doubles;
    /// the same array for both steps in place). The same old state and
    /// increment give bit-identical results. On failure `new_state` is
    /// untouched.
    [[nodiscard]] AsperityFrictionResponse step(const AsperityFrictionIncrement& increment,
                                                span<const double> old_state,
                                                span<double> new_state,
                                                FrictionWork* work = nullptr) const
    {
        const char* f = "asperity::Friction::step";
        const std::size_t m = state_size();
        const double* old_p = detail::at_least(old_state, m, f, "old_state");
        double* new_p = detail::at_least(new_state, m, f, "new_state");
        AsperityFrictionResponse out{};
        check(asperity_friction_step(get(), &increment, old_p, new_p, scratch(work), &out));
        return out;
    }

    /// `asperity_friction_step_in_place`: one increment of one point with
    /// its `state` updated in place (untouched on failure).
    AsperityFrictionResponse step_in_place(const AsperityFrictionIncrement& increment,
                                           span<double> state, FrictionWork* work = nullptr) const
    {
        double* p = detail::at_least(state, state_size(), "asperity::Friction::step_in_place",
                                     "state");
        AsperityFrictionResponse out{};
        check(asperity_friction_step_in_place(get(), &increment, p, scratch(work), &out));
        return out;
    }

    /// `asperity_friction_step_block`: `normal_forces.size()` points at once
    /// (Abaqus VFRIC shape), no tangents (`step_block_responses` gives them). `areas` is empty (0 for every
    /// point; refused by the homogenised law) or one per point (m^2);
    /// `slip_increments` and `tangential_forces` hold two values per point
    /// (x, y interleaved), `old_states` and `new_states` `state_size()` per
    /// point (the same vector for both steps in place), `dissipation` is
    /// empty (not wanted) or one per point (J). On an error at point i, the
    /// points before i are written and the message names element i.
    void step_block(span<const double> normal_forces, span<const double> areas,
                    span<const double> slip_increments, double dt,
                    span<const double> old_states, span<double> new_states,
                    span<double> tangential_forces, span<double> dissipation = {},
                    FrictionWork* work = nullptr) const
    {
        const char* f = "asperity::Friction::step_block";
        const std::size_t n = normal_forces.size();
        const std::size_t m = state_size();
        // Checked in the C order, so the first short array is the one named.
        const double* area_p = detail::optional(areas, n, f, "areas");
        const double* slip_p = detail::at_least(slip_increments, 2 * n, f, "slip_increments");
        const double* old_p = detail::at_least(old_states, n * m, f, "old_states");
        double* new_p = detail::at_least(new_states, n * m, f, "new_states");
        double* force_p = detail::at_least(tangential_forces, 2 * n, f, "tangential_forces");
        double* diss_p = detail::optional(dissipation, n, f, "dissipation");
        check(asperity_friction_step_block(get(), n, detail::required(normal_forces), area_p,
                                           slip_p, dt, old_p, new_p, force_p, diss_p,
                                           scratch(work)));
    }

    /// `asperity_friction_step_block_responses`: `step_block` with each
    /// point's full response in `responses` (one per point: the force (N),
    /// the dissipated and stored energies (J), the regime, and the tangents
    /// asked by `tangents`, 0 or `ASPERITY_FRICTION_TANGENT_NORMAL` |
    /// `ASPERITY_FRICTION_TANGENT_SLIP` for every point: dF/dN and
    /// dF/d(slip) (N/m) for an implicit host's Jacobian), as `step` gives
    /// them point by point. `old_states` and `new_states` may be the same
    /// vector (in place). On an error at point i, the points before i are
    /// written and the message names element i.
    void step_block_responses(span<const double> normal_forces, span<const double> areas,
                              span<const double> slip_increments, double dt,
                              std::int32_t tangents, span<const double> old_states,
                              span<double> new_states, span<AsperityFrictionResponse> responses,
                              FrictionWork* work = nullptr) const
    {
        const char* f = "asperity::Friction::step_block_responses";
        const std::size_t n = normal_forces.size();
        const std::size_t m = state_size();
        const double* area_p = detail::optional(areas, n, f, "areas");
        const double* slip_p = detail::at_least(slip_increments, 2 * n, f, "slip_increments");
        const double* old_p = detail::at_least(old_states, n * m, f, "old_states");
        double* new_p = detail::at_least(new_states, n * m, f, "new_states");
        AsperityFrictionResponse* resp_p = detail::at_least(responses, n, f, "responses");
        check(asperity_friction_step_block_responses(get(), n, detail::required(normal_forces),
                                                     area_p, slip_p, dt, tangents, old_p, new_p,
                                                     resp_p, scratch(work)));
    }

    /// `asperity_friction_step_block_in_place`: `step_block` with the
    /// `states` (`state_size()` doubles per point) stepped in place.
    void step_block_in_place(span<const double> normal_forces, span<const double> areas,
                             span<const double> slip_increments, double dt, span<double> states,
                             span<double> tangential_forces, span<double> dissipation = {},
                             FrictionWork* work = nullptr) const
    {
        const char* f = "asperity::Friction::step_block_in_place";
        const std::size_t n = normal_forces.size();
        const std::size_t m = state_size();
        const double* area_p = detail::optional(areas, n, f, "areas");
        const double* slip_p = detail::at_least(slip_increments, 2 * n, f, "slip_increments");
        double* states_p = detail::at_least(states, n * m, f, "states");
        double* force_p = detail::at_least(tangential_forces, 2 * n, f, "tangential_forces");
        double* diss_p = detail::optional(dissipation, n, f, "dissipation");
        check(asperity_friction_step_block_in_place(get(), n, detail::required(normal_forces),
                                                    area_p, slip_p, dt, states_p, force_p, diss_p,
                                                    scratch(work)));
    }

private:
    static AsperityFrictionWork* scratch(FrictionWork* work) noexcept
    {
        return work != nullptr ? work->get() : nullptr;
    }
};

inline FrictionWork::FrictionWork(const Friction& law)
{
    AsperityFrictionWork* p = nullptr;
    check(asperity_friction_work_new(law.get(), &p));
    reset(p);
}

inline FrictionWork Friction::work() const
{
    return FrictionWork(*this);
}

// ---------------------------------------------------------------------------
// Indentation and rescaling

/// `asperity_indentation_default_options`: the default fit options
/// (Berkovich, ideal area, anchor at the maximum, diamond indenter).
[[nodiscard]] inline AsperityIndentationOptions indentation_default_options()
{
    AsperityIndentationOptions options{};
    check(asperity_indentation_default_options(&options));
    return options;
}

/// `asperity_indentation_fit`: fit a measured load-depth curve, `depth` (m)
/// and `load` (N) of equal length, optional `segments` (`ASPERITY_SEGMENT_*`
/// per point; empty: detected) and `options` (NULL: the defaults).
[[nodiscard]] inline AsperityIndentationResult indentation_fit(
    span<const double> depth, span<const double> load, span<const std::int32_t> segments = {},
    const AsperityIndentationOptions* options = nullptr)
{
    const char* f = "asperity::indentation_fit";
    const std::size_t n = depth.size();
    AsperityIndentationResult result{};
    check(asperity_indentation_fit(n, detail::required(depth), detail::exactly(load, n, f, "load"),
                                   segments.empty() ? nullptr
                                                    : detail::exactly(segments, n, f, "segments"),
                                   options, &result));
    return result;
}

/// `asperity_indentation_flag_name`: the code of flag bit `bit` (0-based) as
/// a static string, or NULL for a bit without a flag.
[[nodiscard]] inline const char* indentation_flag_name(std::uint32_t bit) noexcept
{
    return asperity_indentation_flag_name(bit);
}

/// `asperity_afm_analyze`: analyse an AFM force-distance curve, `position`
/// (m) and `signal` (force N or deflection m, as `input_kind` says) of equal
/// length, approach first and retract from `retract_start` (0: the turning
/// point); `spring_constant` (N/m), `tip_radius` (m, 0 = unknown), `model`
/// (`ASPERITY_AFM_MODEL_*`).
[[nodiscard]] inline AsperityAfmResult afm_analyze(
    span<const double> position, span<const double> signal, double spring_constant,
    double tip_radius = 0.0, std::int32_t model = ASPERITY_AFM_MODEL_AUTO,
    std::int32_t input_kind = ASPERITY_AFM_INPUT_FORCE, std::size_t retract_start = 0)
{
    const char* f = "asperity::afm_analyze";
    const std::size_t n = position.size();
    AsperityAfmResult result{};
    check(asperity_afm_analyze(n, detail::required(position),
                               detail::exactly(signal, n, f, "signal"), input_kind, retract_start,
                               spring_constant, tip_radius, model, &result));
    return result;
}

/// `asperity_afm_flag_name`: the code of AFM flag bit `bit` (0-based) as a
/// static string, or NULL for a bit without a flag.
[[nodiscard]] inline const char* afm_flag_name(std::uint32_t bit) noexcept
{
    return asperity_afm_flag_name(bit);
}

/// `asperity_rescaling_depth`: depth (m) at `load` (N) by Borodich
/// rescaling (3-13) from the known point (`known_load`, `known_depth`).
[[nodiscard]] inline double rescaling_depth(double kappa, double d, double lambda, double load,
                                            double known_load, double known_depth)
{
    double depth = 0.0;
    check(asperity_rescaling_depth(kappa, d, lambda, load, known_load, known_depth, &depth));
    return depth;
}

/// `asperity_rescaling_radius`: contact radius (m) at `load` (N) by
/// rescaling (3-14).
[[nodiscard]] inline double rescaling_radius(double kappa, double d, double lambda, double load,
                                             double known_load, double known_radius)
{
    double radius = 0.0;
    check(asperity_rescaling_radius(kappa, d, lambda, load, known_load, known_radius, &radius));
    return radius;
}

/// `asperity_rescaling_load`: load (N) at `depth` (m) by rescaling (3-24).
[[nodiscard]] inline double rescaling_load(double kappa, double d, double lambda, double depth,
                                           double known_load, double known_depth)
{
    double load = 0.0;
    check(asperity_rescaling_load(kappa, d, lambda, depth, known_load, known_depth, &load));
    return load;
}

/// `asperity_rescaling_lambda_spheres`: lambda = R1/R (3-15).
[[nodiscard]] inline double rescaling_lambda_spheres(double known_radius, double radius)
{
    double lambda = 0.0;
    check(asperity_rescaling_lambda_spheres(known_radius, radius, &lambda));
    return lambda;
}

/// `asperity_rescaling_lambda_cones`: lambda = tan(g1)/tan(g) (3-16).
[[nodiscard]] inline double rescaling_lambda_cones(double known_half_angle, double half_angle)
{
    double lambda = 0.0;
    check(asperity_rescaling_lambda_cones(known_half_angle, half_angle, &lambda));
    return lambda;
}

/// `asperity_rescaling_kappa_from_slope`: kappa = (d m_l - 2)/(d - 1).
[[nodiscard]] inline double rescaling_kappa_from_slope(double loading_slope, double d)
{
    double kappa = 0.0;
    check(asperity_rescaling_kappa_from_slope(loading_slope, d, &kappa));
    return kappa;
}

/// `asperity_rescaling_d_from_unloading_slope`: d = 1/(m_u - 1).
[[nodiscard]] inline double rescaling_d_from_unloading_slope(double unloading_slope)
{
    double d = 0.0;
    check(asperity_rescaling_d_from_unloading_slope(unloading_slope, &d));
    return d;
}

/// `asperity_rescaling_d_from_loading_slope`: d = (2 - kappa)/(m_l - kappa).
[[nodiscard]] inline double rescaling_d_from_loading_slope(double loading_slope, double kappa)
{
    double d = 0.0;
    check(asperity_rescaling_d_from_loading_slope(loading_slope, kappa, &d));
    return d;
}

/// `asperity_galanov_unloading_radius`: R2 = R1 (P2/P1)^2 (delta1/delta2)^3
/// (3-22).
[[nodiscard]] inline double galanov_unloading_radius(double r1, double p1, double delta1,
                                                     double p2, double delta2)
{
    double r2 = 0.0;
    check(asperity_galanov_unloading_radius(r1, p1, delta1, p2, delta2, &r2));
    return r2;
}

/// `asperity_galanov_medium_radius`: R_medium = R R2/(R2 - R) (3-23).
[[nodiscard]] inline double galanov_medium_radius(double radius, double unloading_radius)
{
    double medium_radius = 0.0;
    check(asperity_galanov_medium_radius(radius, unloading_radius, &medium_radius));
    return medium_radius;
}

/// `asperity_hardness_brinell`: Brinell hardness (Pa) (2-7).
[[nodiscard]] inline double hardness_brinell(double load, double ball_diameter,
                                             double imprint_diameter)
{
    double hardness = 0.0;
    check(asperity_hardness_brinell(load, ball_diameter, imprint_diameter, &hardness));
    return hardness;
}

/// `asperity_hardness_meyer`: Meyer hardness 4P/(pi d^2) (Pa) (2-8).
[[nodiscard]] inline double hardness_meyer(double load, double imprint_diameter)
{
    double hardness = 0.0;
    check(asperity_hardness_meyer(load, imprint_diameter, &hardness));
    return hardness;
}

/// `asperity_hardness_ludwik`: Ludwik hardness 4P/(sqrt(2) pi d^2) (Pa)
/// (2-10).
[[nodiscard]] inline double hardness_ludwik(double load, double imprint_diameter)
{
    double hardness = 0.0;
    check(asperity_hardness_ludwik(load, imprint_diameter, &hardness));
    return hardness;
}

/// `asperity_hardness_vickers`: Vickers hardness 2P sin 68deg/d^2 (Pa)
/// (2-12).
[[nodiscard]] inline double hardness_vickers(double load, double mean_diagonal)
{
    double hardness = 0.0;
    check(asperity_hardness_vickers(load, mean_diagonal, &hardness));
    return hardness;
}

// ---------------------------------------------------------------------------
// Material

/// `asperity_effective_modulus`: the contact modulus E* (Pa); E = INFINITY
/// marks a rigid body.
[[nodiscard]] inline double effective_modulus(double e1, double nu1, double e2, double nu2)
{
    double e_star = 0.0;
    check(asperity_effective_modulus(e1, nu1, e2, nu2, &e_star));
    return e_star;
}

/// `asperity_rod_effective_modulus`: 1/E = 1/E1 + 1/E2 (Pa) (6-8).
[[nodiscard]] inline double rod_effective_modulus(double e1, double e2)
{
    double e_eff = 0.0;
    check(asperity_rod_effective_modulus(e1, e2, &e_eff));
    return e_eff;
}

/// `asperity_no_slip_factor`: C_NS = (1 - nu) ln(3 - 4 nu)/(1 - 2 nu).
[[nodiscard]] inline double no_slip_factor(double nu)
{
    double c_ns = 0.0;
    check(asperity_no_slip_factor(nu, &c_ns));
    return c_ns;
}

/// `asperity_tabor_parameter`: mu = (R w^2/(E*^2 z0^3))^(1/3).
[[nodiscard]] inline double tabor_parameter(double radius, double work_of_adhesion,
                                            double e_star, double equilibrium_separation)
{
    double mu = 0.0;
    check(asperity_tabor_parameter(radius, work_of_adhesion, e_star, equilibrium_separation,
                                   &mu));
    return mu;
}

/// `asperity_maugis_parameter`: lambda = 2 sigma0 (R/(pi w K^2))^(1/3),
/// K = 4E*/3.
[[nodiscard]] inline double maugis_parameter(double radius, double work_of_adhesion,
                                             double e_star, double cohesive_stress)
{
    double lambda = 0.0;
    check(asperity_maugis_parameter(radius, work_of_adhesion, e_star, cohesive_stress,
                                    &lambda));
    return lambda;
}

/// `asperity_weir_surface_energy`: Weir's surface energy (J/m^2) with the
/// default prefactor 1/((m-2)(n-2)).
[[nodiscard]] inline double weir_surface_energy(double atomic_mass, double density,
                                                double youngs_modulus, double poisson_ratio,
                                                double m, double n)
{
    double gamma = 0.0;
    check(asperity_weir_surface_energy(atomic_mass, density, youngs_modulus, poisson_ratio, m, n,
                                       &gamma));
    return gamma;
}

/// `asperity_weir_surface_energy_with`: Weir's surface energy (J/m^2) with
/// `prefactor` (`ASPERITY_WEIR_*`).
[[nodiscard]] inline double weir_surface_energy_with(double atomic_mass, double density,
                                                     double youngs_modulus,
                                                     double poisson_ratio, double m, double n,
                                                     std::int32_t prefactor)
{
    double gamma = 0.0;
    check(asperity_weir_surface_energy_with(atomic_mass, density, youngs_modulus, poisson_ratio,
                                            m, n, prefactor, &gamma));
    return gamma;
}

/// `asperity_pair_work_of_adhesion`: work of adhesion (J/m^2) of two surface
/// energies under `rule` (`ASPERITY_PAIR_*`).
[[nodiscard]] inline double pair_work_of_adhesion(double gamma1, double gamma2,
                                                  std::int32_t rule)
{
    double work_of_adhesion = 0.0;
    check(asperity_pair_work_of_adhesion(gamma1, gamma2, rule, &work_of_adhesion));
    return work_of_adhesion;
}

/// `asperity_hamaker_work_of_adhesion`: A/(12 pi D0^2) (J/m^2).
[[nodiscard]] inline double hamaker_work_of_adhesion(double hamaker, double separation)
{
    double work_of_adhesion = 0.0;
    check(asperity_hamaker_work_of_adhesion(hamaker, separation, &work_of_adhesion));
    return work_of_adhesion;
}

// ---------------------------------------------------------------------------
// Multi-asperity statistics

/// `asperity_gw_eval`: Greenwood-Williamson load, area, contacts and
/// stiffness at `separation` (m).
[[nodiscard]] inline AsperityGwResponse gw_eval(const AsperityGwParams& gw, double separation)
{
    AsperityGwResponse out{};
    check(asperity_gw_eval(&gw, separation, &out));
    return out;
}

/// `asperity_gw_eval_batch`: `gw_eval` for `separation.size()` separations;
/// `load` needs room for them, `area`, `contacts` and `stiffness` are empty
/// (not wanted) or as long.
inline void gw_eval_batch(const AsperityGwParams& gw, span<const double> separation,
                          span<double> load, span<double> area = {}, span<double> contacts = {},
                          span<double> stiffness = {})
{
    const char* f = "asperity::gw_eval_batch";
    const std::size_t n = separation.size();
    check(asperity_gw_eval_batch(&gw, n, detail::required(separation),
                                 detail::at_least(load, n, f, "load"),
                                 detail::optional(area, n, f, "area"),
                                 detail::optional(contacts, n, f, "contacts"),
                                 detail::optional(stiffness, n, f, "stiffness")));
}

/// `asperity_gw_separation_at_load`: the separation that carries `load` (N),
/// with the solver's report.
[[nodiscard]] inline AsperitySeparation gw_separation_at_load(const AsperityGwParams& gw,
                                                              double load)
{
    AsperitySeparation out{};
    check(asperity_gw_separation_at_load(&gw, load, &out));
    return out;
}

/// `asperity_gw_plasticity_index`: psi = (E*/H) sqrt(sigma/R) of `gw` for
/// the hardness `hardness` (Pa).
[[nodiscard]] inline double gw_plasticity_index(const AsperityGwParams& gw, double hardness)
{
    double psi = 0.0;
    check(asperity_gw_plasticity_index(&gw, hardness, &psi));
    return psi;
}

/// `asperity_plasticity_index`: psi = (E*/H) sqrt(sigma/R) (1-31).
[[nodiscard]] inline double plasticity_index(double e_star, double hardness, double sigma,
                                             double radius)
{
    double psi = 0.0;
    check(asperity_plasticity_index(e_star, hardness, sigma, radius, &psi));
    return psi;
}

/// `asperity_deformation_regime`: `ASPERITY_REGIME_*` of a plasticity index.
[[nodiscard]] inline std::int32_t deformation_regime(double psi)
{
    std::int32_t regime = 0;
    check(asperity_deformation_regime(psi, &regime));
    return regime;
}

/// A Greenwood-Williamson surface over listed summits (`AsperityGwEmpirical`).
/// Immutable; safe to share between threads.
class GwEmpirical
    : public detail::unique_handle<AsperityGwEmpirical, detail::free_gw_empirical> {
public:
    using unique_handle::unique_handle;
    GwEmpirical() noexcept = default;

    /// `asperity_gw_empirical_new`: `heights` (m) of the listed summits,
    /// their `radii` (m; empty: all `radius`), standing for `summit_count`
    /// summits, against a flat of contact modulus `e_star` (Pa). The arrays
    /// are copied.
    GwEmpirical(double summit_count, double radius, double e_star, span<const double> heights,
                span<const double> radii = {})
    {
        AsperityGwEmpirical* p = nullptr;
        const std::size_t n = heights.size();
        check(asperity_gw_empirical_new(
            summit_count, radius, e_star, n, detail::required(heights),
            radii.empty() ? nullptr
                          : detail::exactly(radii, n, "asperity::GwEmpirical", "radii"),
            &p));
        reset(p);
    }

    /// `asperity_gw_empirical_eval`: load, area, contacts and stiffness at
    /// `separation` (m).
    [[nodiscard]] AsperityGwResponse eval(double separation) const
    {
        AsperityGwResponse out{};
        check(asperity_gw_empirical_eval(get(), separation, &out));
        return out;
    }

    /// `asperity_gw_empirical_eval_batch`: as `asperity::gw_eval_batch`.
    void eval_batch(span<const double> separation, span<double> load, span<double> area = {},
                    span<double> contacts = {}, span<double> stiffness = {}) const
    {
        const char* f = "asperity::GwEmpirical::eval_batch";
        const std::size_t n = separation.size();
        check(asperity_gw_empirical_eval_batch(get(), n, detail::required(separation),
                                               detail::at_least(load, n, f, "load"),
                                               detail::optional(area, n, f, "area"),
                                               detail::optional(contacts, n, f, "contacts"),
                                               detail::optional(stiffness, n, f, "stiffness")));
    }

    /// `asperity_gw_empirical_separation_at_load`: the separation that
    /// carries `load` (N).
    [[nodiscard]] AsperitySeparation separation_at_load(double load) const
    {
        AsperitySeparation out{};
        check(asperity_gw_empirical_separation_at_load(get(), load, &out));
        return out;
    }

    /// `asperity_gw_empirical_plasticity_index`: psi for the hardness
    /// `hardness` (Pa), sigma of the listed heights.
    [[nodiscard]] double plasticity_index(double hardness) const
    {
        double psi = 0.0;
        check(asperity_gw_empirical_plasticity_index(get(), hardness, &psi));
        return psi;
    }
};

/// `asperity_bgt_eval`: Bush-Gibson-Thomas load, area, contacts and
/// stiffness at `separation` (m, above the surface's mean plane).
[[nodiscard]] inline AsperityBgtResponse bgt_eval(const AsperityBgtParams& bgt, double separation)
{
    AsperityBgtResponse out{};
    check(asperity_bgt_eval(&bgt, separation, &out));
    return out;
}

/// `asperity_bgt_eval_batch`: `bgt_eval` for `separation.size()`
/// separations; `load` needs room for them, `area`, `contacts` and
/// `stiffness` are empty (not wanted) or as long.
inline void bgt_eval_batch(const AsperityBgtParams& bgt, span<const double> separation,
                           span<double> load, span<double> area = {}, span<double> contacts = {},
                           span<double> stiffness = {})
{
    const char* f = "asperity::bgt_eval_batch";
    const std::size_t n = separation.size();
    check(asperity_bgt_eval_batch(&bgt, n, detail::required(separation),
                                  detail::at_least(load, n, f, "load"),
                                  detail::optional(area, n, f, "area"),
                                  detail::optional(contacts, n, f, "contacts"),
                                  detail::optional(stiffness, n, f, "stiffness")));
}

/// `asperity_bgt_separation_at_load`: the separation that carries `load`
/// (N), with the solver's report.
[[nodiscard]] inline AsperitySeparation bgt_separation_at_load(const AsperityBgtParams& bgt,
                                                               double load)
{
    AsperitySeparation out{};
    check(asperity_bgt_separation_at_load(&bgt, load, &out));
    return out;
}

/// `asperity_bgt_properties`: Nayak's summit density (1/m^2) and the
/// small-load limit of A/P (m^2/N), as a pair.
[[nodiscard]] inline std::pair<double, double> bgt_properties(const AsperityBgtParams& bgt)
{
    double density = 0.0, area_per_load = 0.0;
    check(asperity_bgt_properties(&bgt, &density, &area_per_load));
    return {density, area_per_load};
}

/// The Bora et al. interface on a measured height map (`AsperityBora`).
/// Immutable; safe to share between threads.
class Bora : public detail::unique_handle<AsperityBora, detail::free_bora> {
public:
    using unique_handle::unique_handle;
    Bora() noexcept = default;

    /// `asperity_bora_new`: `nx` x `ny` `heights` (m, row-major, copied),
    /// grid `spacing` (m), `spring_stiffness` (N/m), substrate
    /// `contact_modulus` (Pa; 0: rigid).
    Bora(std::size_t nx, std::size_t ny, double spacing, span<const double> heights,
         double spring_stiffness, double contact_modulus)
    {
        AsperityBora* p = nullptr;
        check(asperity_bora_new(nx, ny, spacing,
                                detail::exactly(heights, nx * ny, "asperity::Bora", "heights"),
                                spring_stiffness, contact_modulus, &p));
        reset(p);
    }

    /// `asperity_bora_solve`: the equilibrium at `separation` (m); `forces`
    /// empty (not wanted) or room for nx*ny spring forces (N).
    [[nodiscard]] AsperityBoraResponse solve(double separation, span<double> forces = {}) const
    {
        AsperityBoraResponse out{};
        check(asperity_bora_solve(get(), separation, &out,
                                  forces.empty() ? nullptr : forces.data()));
        return out;
    }

    /// `asperity_bora_separation_at_load`: the separation that carries
    /// `load` (N).
    [[nodiscard]] AsperitySeparation separation_at_load(double load) const
    {
        AsperitySeparation out{};
        check(asperity_bora_separation_at_load(get(), load, &out));
        return out;
    }
};

/// `asperity_sergienko_bukharov_run`: one run of the Sergienko-Bukharov
/// model `params` (thesis 5.3.5, the library's formulation) on the
/// spring-top `heights` (m; read for `ASPERITY_HEIGHTS_LIST`, may be empty
/// otherwise): the dynamic lift and the friction ratio, averaged over whole
/// periods.
[[nodiscard]] inline AsperitySergienkoBukharovResult sergienko_bukharov_run(
    const AsperitySergienkoBukharovParams& params, span<const double> heights = {})
{
    AsperitySergienkoBukharovResult out{};
    check(asperity_sergienko_bukharov_run(&params, heights.empty() ? nullptr : heights.data(),
                                          heights.size(), &out));
    return out;
}

/// `asperity_zhuravlev_linear`: Zhuravlev's model with summit densities
/// alpha_i xi at the approach `approach` (m).
[[nodiscard]] inline AsperityZhuravlevResponse zhuravlev_linear(const AsperityZhuravlev& model,
                                                                double alpha1, double alpha2,
                                                                double approach)
{
    AsperityZhuravlevResponse out{};
    check(asperity_zhuravlev_linear(&model, alpha1, alpha2, approach, &out));
    return out;
}

/// `asperity_zhuravlev_approach_at_load_linear`: the approach (m) that
/// carries `load` (N) with linear densities.
[[nodiscard]] inline double zhuravlev_approach_at_load_linear(const AsperityZhuravlev& model,
                                                              double alpha1, double alpha2,
                                                              double load)
{
    double approach = 0.0;
    check(asperity_zhuravlev_approach_at_load_linear(&model, alpha1, alpha2, load, &approach));
    return approach;
}

/// `asperity_zhuravlev_friction_linear`: friction of Zhuravlev's model at
/// `load` (N) with shear strength `shear_strength` (Pa).
[[nodiscard]] inline AsperityZhuravlevFriction zhuravlev_friction_linear(
    const AsperityZhuravlev& model, double alpha1, double alpha2, double load,
    double shear_strength)
{
    AsperityZhuravlevFriction out{};
    check(asperity_zhuravlev_friction_linear(&model, alpha1, alpha2, load, shear_strength, &out));
    return out;
}

/// `asperity_zhuravlev_eval`: Zhuravlev's model for summit densities given
/// as C callbacks, by Gauss-Legendre quadrature of `order` (4..64) points.
[[nodiscard]] inline AsperityZhuravlevResponse zhuravlev_eval(const AsperityZhuravlev& model,
                                                              double approach,
                                                              AsperitySummitDensity n1,
                                                              void* n1_data,
                                                              AsperitySummitDensity n2,
                                                              void* n2_data, std::size_t order)
{
    AsperityZhuravlevResponse out{};
    check(asperity_zhuravlev_eval(&model, approach, n1, n1_data, n2, n2_data, order, &out));
    return out;
}

/// `asperity_zhuravlev_eval` for any C++ callables `n1(xi)`, `n2(xi)` (1/m,
/// depth xi in m): lambdas, function objects. An exception thrown by a
/// callable stops the quadrature and is rethrown here.
template <class N1, class N2>
[[nodiscard]] inline AsperityZhuravlevResponse zhuravlev_eval(const AsperityZhuravlev& model,
                                                              double approach, N1&& n1, N2&& n2,
                                                              std::size_t order)
{
    using C1 = detail::density_callback<typename std::remove_reference<N1>::type>;
    using C2 = detail::density_callback<typename std::remove_reference<N2>::type>;
    C1 c1{&n1, nullptr};
    C2 c2{&n2, nullptr};
    AsperityZhuravlevResponse out{};
    const std::int32_t status =
        asperity_zhuravlev_eval(&model, approach, &C1::call, &c1, &C2::call, &c2, order, &out);
    if (c1.error) {
        std::rethrow_exception(c1.error);
    }
    if (c2.error) {
        std::rethrow_exception(c2.error);
    }
    check(status);
    return out;
}

// ---------------------------------------------------------------------------
// Surfaces: ISO 4287 parameters, filters, spectra, generators

/// `asperity_roughness_parameters`: ISO 4287 parameters of `heights` (m)
/// sampled at `dx` (m) after removing `form` (`ASPERITY_FORM_*`), with the
/// Gaussian filter at `cutoff` (m; 0: none) over sampling lengths of
/// `sampling_length` (m; 0: one).
[[nodiscard]] inline AsperityRoughness roughness_parameters(span<const double> heights, double dx,
                                                            std::int32_t form, double cutoff = 0.0,
                                                            double sampling_length = 0.0)
{
    AsperityRoughness out{};
    check(asperity_roughness_parameters(heights.size(), detail::required(heights), dx, form,
                                        cutoff, sampling_length, &out));
    return out;
}

/// `asperity_profile_remove_form`: `heights` minus their least-squares
/// `form` into `out` (at least as long; may be `heights` itself).
inline void profile_remove_form(span<const double> heights, std::int32_t form, span<double> out)
{
    const std::size_t n = heights.size();
    check(asperity_profile_remove_form(
        n, detail::required(heights), form,
        detail::at_least(out, n, "asperity::profile_remove_form", "out")));
}

/// `asperity_profile_remove_form`: `heights` minus their least-squares
/// `form`.
[[nodiscard]] inline std::vector<double> profile_remove_form(span<const double> heights,
                                                             std::int32_t form)
{
    std::vector<double> out(heights.size());
    profile_remove_form(heights, form, out);
    return out;
}

/// `asperity_profile_gaussian_filter`: the ISO 16610-21 Gaussian filter of
/// `heights` (m, spacing `dx`) at `cutoff` (m) with `ends`
/// (`ASPERITY_FILTER_ENDS_*`): the roughness profile into `roughness` and,
/// unless empty, the mean line into `mean_line` (each at least as long as
/// `heights`); the index of the first sample kept into `*first_index` (may
/// be NULL). Returns the number of samples written.
inline std::size_t profile_gaussian_filter(span<const double> heights, double dx, double cutoff,
                                           std::int32_t ends, span<double> roughness,
                                           span<double> mean_line = {},
                                           std::size_t* first_index = nullptr)
{
    const char* f = "asperity::profile_gaussian_filter";
    const std::size_t n = heights.size();
    std::size_t n_out = 0;
    check(asperity_profile_gaussian_filter(n, detail::required(heights), dx, cutoff, ends,
                                           detail::at_least(roughness, n, f, "roughness"),
                                           detail::optional(mean_line, n, f, "mean_line"), &n_out,
                                           first_index));
    return n_out;
}

/// The result of `asperity::profile_gaussian_filter` in vectors.
struct FilteredProfile {
    /// The roughness profile (m).
    std::vector<double> roughness;
    /// The mean line (m).
    std::vector<double> mean_line;
    /// Index in the input of `roughness[0]`.
    std::size_t first_index;
};

/// `asperity_profile_gaussian_filter`: the roughness profile and mean line,
/// sized to the samples kept.
[[nodiscard]] inline FilteredProfile profile_gaussian_filter(span<const double> heights,
                                                             double dx, double cutoff,
                                                             std::int32_t ends)
{
    FilteredProfile out{std::vector<double>(heights.size()), std::vector<double>(heights.size()),
                        0};
    const std::size_t n_out = profile_gaussian_filter(heights, dx, cutoff, ends, out.roughness,
                                                      out.mean_line, &out.first_index);
    out.roughness.resize(n_out);
    out.mean_line.resize(n_out);
    return out;
}

/// `asperity_material_ratio_curve`: the Abbott-Firestone curve of `heights`
/// at `level.size()` equally spaced ratios: `ratio[i]` (empty: not wanted)
/// and `level[i]` (m above the mean line).
inline void material_ratio_curve(span<const double> heights, span<double> ratio,
                                 span<double> level)
{
    const std::size_t n_points = level.size();
    check(asperity_material_ratio_curve(
        heights.size(), detail::required(heights), n_points,
        detail::optional(ratio, n_points, "asperity::material_ratio_curve", "ratio"),
        detail::required(level)));
}

/// The result of `asperity::material_ratio_curve` in vectors.
struct MaterialRatioCurve {
    /// Material ratio Rmr (0 ... 1).
    std::vector<double> ratio;
    /// Height c(Rmr) above the mean line (m).
    std::vector<double> level;
};

/// `asperity_material_ratio_curve`: the curve at `n_points` ratios.
[[nodiscard]] inline MaterialRatioCurve material_ratio_curve(span<const double> heights,
                                                             std::size_t n_points)
{
    MaterialRatioCurve out{std::vector<double>(n_points), std::vector<double>(n_points)};
    material_ratio_curve(heights, out.ratio, out.level);
    return out;
}

/// `asperity_profile_psd`: the one-sided PSD of `heights` (m, spacing `dx`)
/// with `window` (`ASPERITY_WINDOW_*`): `g.size()` must be n/2 + 1; `q`
/// (rad/m) is empty (not wanted) or as long.
inline void profile_psd(span<const double> heights, double dx, std::int32_t window,
                        span<double> q, span<double> g)
{
    const std::size_t n_q = g.size();
    check(asperity_profile_psd(heights.size(), detail::required(heights), dx, window, n_q,
                               detail::optional(q, n_q, "asperity::profile_psd", "q"),
                               detail::required(g)));
}

/// The result of `asperity::profile_psd` in vectors.
struct Psd {
    /// Wavenumbers q[k] = k 2 pi/(n dx) (rad/m).
    std::vector<double> q;
    /// One-sided PSD G(q[k]) (m^3).
    std::vector<double> g;
};

/// `asperity_profile_psd`: the one-sided PSD at the n/2 + 1 wavenumbers.
[[nodiscard]] inline Psd profile_psd(span<const double> heights, double dx, std::int32_t window)
{
    Psd out{std::vector<double>(heights.size() / 2 + 1),
            std::vector<double>(heights.size() / 2 + 1)};
    profile_psd(heights, dx, window, out.q, out.g);
    return out;
}

/// `asperity_profile_hurst_fit`: power-law fit of the Hann-windowed PSD over
/// `q_min <= q <= q_max` (rad/m; both 0: the default band).
[[nodiscard]] inline AsperityHurstFit profile_hurst_fit(span<const double> heights, double dx,
                                                        double q_min = 0.0, double q_max = 0.0)
{
    AsperityHurstFit out{};
    check(asperity_profile_hurst_fit(heights.size(), detail::required(heights), dx, q_min, q_max,
                                     &out));
    return out;
}

/// `asperity_profile_hurst_estimate`: `profile_hurst_fit` with H's standard
/// error, the fit's chi^2/dof and the band in rad/m and in m, over
/// `q_min <= q <= q_max` (rad/m; both 0: the band chosen from the data).
[[nodiscard]] inline AsperityHurstEstimate profile_hurst_estimate(span<const double> heights,
                                                                  double dx, double q_min = 0.0,
                                                                  double q_max = 0.0)
{
    AsperityHurstEstimate out{};
    check(asperity_profile_hurst_estimate(heights.size(), detail::required(heights), dx, q_min,
                                          q_max, &out));
    return out;
}

/// The result of `asperity::map_gaussian_filter`: the retained grid,
/// row-major (`roughness[i + nx*j]`).
struct FilteredMap {
    /// The roughness (S-L) surface (m).
    std::vector<double> roughness;
    /// The Gaussian mean surface (m).
    std::vector<double> mean_surface;
    /// Points of the retained grid along x and y.
    std::size_t nx;
    std::size_t ny;
    /// Input indices of the retained grid's first point.
    std::size_t first_x;
    std::size_t first_y;
};

/// `asperity_map_gaussian_filter`: the ISO 16610-61 areal Gaussian filter
/// of the `nx` x `ny` map `heights` (m, row-major, spacings `dx`, `dy`) at
/// `cutoff` (m) with `ends` (`ASPERITY_FILTER_ENDS_*`).
[[nodiscard]] inline FilteredMap map_gaussian_filter(std::size_t nx, std::size_t ny, double dx,
                                                     double dy, span<const double> heights,
                                                     double cutoff, std::int32_t ends)
{
    const char* f = "asperity::map_gaussian_filter";
    const double* h = detail::exactly(heights, nx * ny, f, "heights");
    FilteredMap out{std::vector<double>(nx * ny), std::vector<double>(nx * ny), 0, 0, 0, 0};
    check(asperity_map_gaussian_filter(nx, ny, dx, dy, h, cutoff, ends, out.roughness.data(),
                                       out.mean_surface.data(), &out.nx, &out.ny, &out.first_x,
                                       &out.first_y));
    out.roughness.resize(out.nx * out.ny);
    out.mean_surface.resize(out.nx * out.ny);
    return out;
}

/// The result of `asperity::map_psd_radial`, one element per annulus.
struct RadialPsd {
    /// Mean |q| of the annulus (rad/m).
    std::vector<double> q;
    /// Mean PSD over the annulus (m^4).
    std::vector<double> psd;
    /// Grid points in the annulus.
    std::vector<std::size_t> count;
};

/// `asperity_map_psd_radial`: the radially averaged 2-D PSD of the `nx` x
/// `ny` map `heights` (m, row-major, spacings `dx`, `dy`) with `window`
/// (`ASPERITY_WINDOW_*`).
[[nodiscard]] inline RadialPsd map_psd_radial(std::size_t nx, std::size_t ny, double dx, double dy,
                                              span<const double> heights, std::int32_t window)
{
    const char* f = "asperity::map_psd_radial";
    const double* h = detail::exactly(heights, nx * ny, f, "heights");
    const std::size_t cap = (nx < ny ? nx : ny) / 2 + 1;
    RadialPsd out{std::vector<double>(cap), std::vector<double>(cap),
                  std::vector<std::size_t>(cap)};
    std::size_t m = 0;
    check(asperity_map_psd_radial(nx, ny, dx, dy, h, window, cap, out.q.data(), out.psd.data(),
                                  out.count.data(), &m));
    out.q.resize(m);
    out.psd.resize(m);
    out.count.resize(m);
    return out;
}

/// `asperity_profile_peak_statistics`: statistics of the 3-point peaks of
/// `heights` (m, spacing `dx`).
[[nodiscard]] inline AsperityPeakStatistics profile_peak_statistics(span<const double> heights,
                                                                    double dx)
{
    AsperityPeakStatistics out{};
    check(asperity_profile_peak_statistics(heights.size(), detail::required(heights), dx, &out));
    return out;
}

/// `asperity_generate_self_affine`: a seeded Gaussian self-affine profile
/// into `heights` (`heights.size()` samples at spacing `dx`).
inline void generate_self_affine(double hurst, double rq, double roll_off_wavelength,
                                 double cutoff_wavelength, double dx, std::uint64_t seed,
                                 span<double> heights)
{
    check(asperity_generate_self_affine(hurst, rq, roll_off_wavelength, cutoff_wavelength, dx,
                                        seed, heights.size(), detail::required(heights)));
}

/// `asperity_generate_self_affine`: `n` samples of a seeded Gaussian
/// self-affine profile.
[[nodiscard]] inline std::vector<double> generate_self_affine(double hurst, double rq,
                                                              double roll_off_wavelength,
                                                              double cutoff_wavelength,
                                                              double dx, std::uint64_t seed,
                                                              std::size_t n)
{
    std::vector<double> heights(n);
    generate_self_affine(hurst, rq, roll_off_wavelength, cutoff_wavelength, dx, seed, heights);
    return heights;
}

/// `asperity_generate_weierstrass_mandelbrot`: the Weierstrass-Mandelbrot
/// profile into `heights`.
inline void generate_weierstrass_mandelbrot(double fractal_dimension, double gamma,
                                            double amplitude, double dx, std::uint64_t seed,
                                            span<double> heights)
{
    check(asperity_generate_weierstrass_mandelbrot(fractal_dimension, gamma, amplitude, dx, seed,
                                                   heights.size(), detail::required(heights)));
}

/// `asperity_generate_weierstrass_mandelbrot`: `n` samples of the
/// Weierstrass-Mandelbrot profile.
[[nodiscard]] inline std::vector<double> generate_weierstrass_mandelbrot(
    double fractal_dimension, double gamma, double amplitude, double dx, std::uint64_t seed,
    std::size_t n)
{
    std::vector<double> heights(n);
    generate_weierstrass_mandelbrot(fractal_dimension, gamma, amplitude, dx, seed, heights);
    return heights;
}

/// `asperity_generate_cantor_borodich`: the Cantor-Borodich profile into
/// `heights` (`heights.size()` points over [0, `length`)).
inline void generate_cantor_borodich(std::uint32_t descendants, double alpha, double beta,
                                     double height, std::uint32_t levels, double length,
                                     span<double> heights)
{
    check(asperity_generate_cantor_borodich(descendants, alpha, beta, height, levels, length,
                                            heights.size(), detail::required(heights)));
}

/// `asperity_generate_cantor_borodich`: `n` samples of the Cantor-Borodich
/// profile.
[[nodiscard]] inline std::vector<double> generate_cantor_borodich(std::uint32_t descendants,
                                                                  double alpha, double beta,
                                                                  double height,
                                                                  std::uint32_t levels,
                                                                  double length, std::size_t n)
{
    std::vector<double> heights(n);
    generate_cantor_borodich(descendants, alpha, beta, height, levels, length, heights);
    return heights;
}

/// `asperity_archard_exponent`: the exponent a of Archard's A ~ W^a for
/// `model` (`ASPERITY_ARCHARD_UNIFORM` or `_NON_UNIFORM`) and `generations`
/// sphere radii.
[[nodiscard]] inline double archard_exponent(std::int32_t model, std::size_t generations)
{
    double a = 0.0;
    check(asperity_archard_exponent(model, generations, &a));
    return a;
}

/// `asperity_archard_area_batch`: Archard's real contact areas `area` (m^2)
/// under `load` (N) for the sphere radii `radii` (m, decreasing) and the
/// densities `densities` (1/m^2, one fewer), contact modulus (Pa).
inline void archard_area(std::int32_t model, span<const double> radii,
                         span<const double> densities, double contact_modulus,
                         span<const double> load, span<double> area)
{
    const char* f = "asperity::archard_area";
    const std::size_t n = load.size();
    const std::size_t g = radii.size();
    check(asperity_archard_area_batch(
        model, detail::required(radii),
        g > 1 ? detail::at_least(densities, g - 1, f, "densities") : detail::required(densities),
        g,
        contact_modulus, n, detail::required(load), detail::at_least(area, n, f, "area")));
}

/// `asperity_cantor_contact_batch`: the contact of the Cantor profile
/// `profile` at the depths `depth` (m) on a Winkler foundation of stiffness
/// `stiffness` (Pa/m) and a rigid-plastic one of hardness `hardness` (Pa).
[[nodiscard]] inline std::vector<AsperityCantorContact>
cantor_contact(const AsperityCantorProfile& profile, double stiffness, double hardness,
               span<const double> depth)
{
    std::vector<AsperityCantorContact> out(depth.size());
    check(asperity_cantor_contact_batch(&profile, stiffness, hardness, depth.size(),
                                        detail::required(depth), out.data()));
    return out;
}

/// `asperity_cantor_exponents`: the fractal dimension, beta of
/// width ~ depth^beta and beta/(1 + beta) of width ~ load^(...) of `profile`.
struct CantorExponents {
    double fractal_dimension;
    double width_exponent;
    double load_area_exponent;
};

/// `asperity_cantor_exponents`: see `CantorExponents`.
[[nodiscard]] inline CantorExponents cantor_exponents(const AsperityCantorProfile& profile)
{
    CantorExponents e{};
    check(asperity_cantor_exponents(&profile, &e.fractal_dimension, &e.width_exponent,
                                    &e.load_area_exponent));
    return e;
}

/// `asperity_borodich_kryukova_normal_force`: the layers' elastic normal
/// force (N) of the Borodich-Kryukova slider `bk` at position `x` (m),
/// mean-line distance `y` (m) and time `time` (s).
[[nodiscard]] inline double borodich_kryukova_normal_force(const AsperityBorodichKryukova& bk,
                                                           double x, double y, double time = 0.0)
{
    double f = 0.0;
    check(asperity_borodich_kryukova_normal_force(&bk, x, y, time, &f));
    return f;
}

/// `asperity_borodich_kryukova_run`: Runge-Kutta 4 from `start` for `steps`
/// steps of `dt` (s), the start and every `every`-th step recorded
/// (steps/every + 1 samples).
[[nodiscard]] inline std::vector<AsperityBorodichKryukovaSample>
borodich_kryukova_run(const AsperityBorodichKryukova& bk,
                      const AsperityBorodichKryukovaState& start, double dt, std::uint32_t steps,
                      std::uint32_t every = 1)
{
    // every = 0: the library reports it (naming `every`).
    std::vector<AsperityBorodichKryukovaSample> out(every == 0 ? 1
                                                               : std::size_t(steps / every) + 1);
    std::size_t written = 0;
    check(asperity_borodich_kryukova_run(&bk, &start, dt, steps, every, out.size(), out.data(),
                                         &written));
    out.resize(written);
    return out;
}

/// `asperity_schmittbuhl_default`: the library's default Schmittbuhl model.
[[nodiscard]] inline AsperitySchmittbuhl schmittbuhl_default()
{
    AsperitySchmittbuhl out{};
    check(asperity_schmittbuhl_default(&out));
    return out;
}

/// `asperity_schmittbuhl_run`: the renormalised friction laws of
/// generations 0 to `model.generations`.
[[nodiscard]] inline std::vector<AsperitySchmittbuhlGeneration>
schmittbuhl_run(const AsperitySchmittbuhl& model)
{
    std::vector<AsperitySchmittbuhlGeneration> out(std::size_t(model.generations) + 1);
    std::size_t written = 0;
    check(asperity_schmittbuhl_run(&model, out.size(), out.data(), &written));
    out.resize(written);
    return out;
}

} // namespace asperity

#endif /* ASPERITY_HPP */
