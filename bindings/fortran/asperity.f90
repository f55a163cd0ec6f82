!> Fortran 2008 bindings of asperity, physics of dry contact between rough
!> surfaces, over the C ABI of `include/asperity.h` (see bindings/README.md).
!>
!>     use asperity
!>     type(asperity_normal_law) :: law
!>     type(asperity_normal_response) :: r
!>     call asperity_law_jkr(1e-6_c_double, 1e9_c_double, 0.05_c_double, law)
!>     call asperity_normal_eval(law, 1e-9_c_double, r)
!>
!> Link with `-lasperity` (shared) or `libasperity.a` plus the system
!> libraries the Rust runtime needs (`-lgcc_s -lutil -lrt -lpthread -lm -ldl`
!> on Linux); see bindings/README.md.
!>
!> The module has two layers.
!>
!> * The raw layer: one `bind(c)` interface per C function, named `c_` plus
!>   the C name (`c_asperity_law_jkr`), returning the C status. Scalars are
!>   passed by value, arrays as `x(*)` with their length in an
!>   `integer(c_size_t), value` argument, structs as the `type, bind(c)`
!>   mirrors below, opaque handles and arguments the C function accepts as
!>   NULL as `type(c_ptr), value` (pass `c_loc(x)` or `c_null_ptr`). It is
!>   the C ABI exactly, for hosts that want nothing in between.
!>
!> * The friendly layer: one procedure per C function, named as the C
!>   function (`asperity_law_jkr`). The arguments are the C arguments in the C
!>   order, except that array lengths are taken from the arrays (`size`),
!>   arguments the C function accepts as NULL are `optional` and come last
!>   (in C order), and an `optional, intent(out) :: status` ends every list.
!>   With `status` present a failure returns its (negative) code and
!>   `asperity_last_error_message()` says why; without it a failure prints
!>   the message to `error_unit` and stops the program (`error stop`).
!>   Opaque objects are handle types (`asperity_table`, ...) holding a
!>   `type(c_ptr)`; text comes and goes as `character(len=*)` and
!>   `character(len=:), allocatable`. Procedures that step a caller-owned
!>   history also take `state` (or `states`): the old and the new history in
!>   one variable, updated in place (Fortran forbids passing one variable as
!>   both `old_state` and `new_state`); the friction step has its own
!>   `_in_place` procedures for that, as in C.
!>
!> Types: `type, bind(c) :: asperity_<snake_case>` mirrors the C struct
!> `Asperity<CamelCase>` field by field, with the C field names; the
!> components default to zero, so a declared state is a fresh state. C arrays
!> of two become Fortran arrays (1:2); `dforce_dslip[i][j]` is
!> `dforce_dslip(j+1, i+1)`; `AsperityFidelityAdvice.assessments` is indexed
!> `(0:5)` by `ASPERITY_FIDELITY_*` and
!> `AsperityIndentationOptions.area_coefficients` `(0:7)` by the NanoSuite
!> coefficient number. The C union `AsperityLawParams` is its storage
!> `raw(16)`; read a law's inputs with `transfer`, e.g.
!> `jkr = transfer(law%params, jkr)` for a `type(asperity_jkr_params) :: jkr`.
!> `asperity_type_layout` gives the size the library has for each C type;
!> tests/fortran_bindings.rs checks `c_sizeof` of every mirror against it.
!>
!> Indices the C API takes (rod levels, `asperity_type_name`) keep their C
!> meaning: 0 is the first. Counts given to the friendly layer (`n_grid`,
!> `rods`, `order`, `level`) are default integers.
!>
!> Handles own their object: create them with the `..._new...`/`..._from_json`
!> procedures and release them with `call h%free()` (or `asperity_free(h)`,
!> or the C-named `asperity_table_free(h)`); a handle that is finalised
!> (deallocated, or going out of scope on compilers that finalise locals) frees its
!> object too. Do not copy a live handle with `=` (both copies would free the
!> same object): assignment of a non-null handle to another variable stops
!> the program; pass handles as arguments, or use pointers.
!>
!> Thread safety is that of the C ABI: every call is reentrant, the laws
!> and handles are immutable and may be shared by threads, and the error
!> message is per thread. The friendly layer's own argument checks (array
!> sizes) keep their message in a module variable marked `threadprivate`
!> for OpenMP.
module asperity
  use, intrinsic :: iso_c_binding, only: c_double, c_int32_t, c_int64_t, c_size_t, c_char, &
      c_ptr, c_funptr, c_null_ptr, c_null_char, c_loc, c_funloc, c_associated, c_f_pointer
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  private

  ! The kinds a caller needs with this module.
  public :: c_double, c_int32_t, c_int64_t, c_size_t

  ! ------------------------------------------------------------------------
  ! Constants: every `#define ASPERITY_*` of the header.

  integer(c_int32_t), parameter, public :: ASPERITY_VERSION_MAJOR = 0
  integer(c_int32_t), parameter, public :: ASPERITY_VERSION_MINOR = 2
  integer(c_int32_t), parameter, public :: ASPERITY_VERSION_PATCH = 0
  ! The law kinds `ASPERITY_LAW_<NAME>` of the header are `ASPERITY_LAW_KIND_<NAME>` here:
  ! Fortran names are case-insensitive, and `ASPERITY_LAW_JKR` would be the
  ! constructor `asperity_law_jkr`.
  !> Law kind: not a law (an all-zero `AsperityNormalLaw`).
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_NONE = 0
  !> Law kind: Hertz sphere.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_HERTZ = 1
  !> Law kind: Galin power-law punch (cones included).
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_POWER_PUNCH = 2
  !> Law kind: flat punch (Boussinesq), frictionless or no-slip.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_FLAT_PUNCH = 3
  !> Law kind: DMT sphere.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_DMT = 4
  !> Law kind: JKR sphere.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_JKR = 5
  !> Law kind: JKR power-law punch (Borodich 2014), frictionless or no-slip.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_JKR_POWER_PUNCH = 6
  !> Law kind: Kendall adhesive flat punch.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_KENDALL = 7
  !> Law kind: Maugis–Dugdale sphere.
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_MAUGIS_DUGDALE = 8
  !> Law kind: rigid sphere with a surface-force law (Derjaguin approximation).
  integer(c_int32_t), parameter, public :: ASPERITY_LAW_KIND_DERJAGUIN = 9
  !> Control mode: prescribed force (soft machine).
  integer(c_int32_t), parameter, public :: ASPERITY_CONTROL_LOAD = 0
  !> Control mode: prescribed approach (rigid machine, fixed grips).
  integer(c_int32_t), parameter, public :: ASPERITY_CONTROL_DISPLACEMENT = 1
  !> Surface law of `asperity_law_derjaguin`: Lennard-Jones 3-9, `range` = z₀.
  integer(c_int32_t), parameter, public :: ASPERITY_SURFACE_LAW_LENNARD_JONES = 1
  !> Surface law: Dugdale step, `range` = σ₀ (Pa), the cohesive stress.
  integer(c_int32_t), parameter, public :: ASPERITY_SURFACE_LAW_DUGDALE = 2
  !> Surface law: exponential, `range` = decay length ℓ (m).
  integer(c_int32_t), parameter, public :: ASPERITY_SURFACE_LAW_EXPONENTIAL = 3
  !> Fidelity: DMT.
  integer(c_int32_t), parameter, public :: ASPERITY_FIDELITY_DMT = 0
  !> Fidelity: tabulated Maugis–Dugdale.
  integer(c_int32_t), parameter, public :: ASPERITY_FIDELITY_TABULATED_MAUGIS_DUGDALE = 1
  !> Fidelity: tabulated Lennard-Jones sphere.
  integer(c_int32_t), parameter, public :: ASPERITY_FIDELITY_TABULATED_LENNARD_JONES = 2
  !> Fidelity: JKR.
  integer(c_int32_t), parameter, public :: ASPERITY_FIDELITY_JKR = 3
  !> Fidelity: Maugis–Dugdale (λ = 1.157 μ).
  integer(c_int32_t), parameter, public :: ASPERITY_FIDELITY_MAUGIS_DUGDALE = 4
  !> Fidelity: the full numerical Lennard-Jones sphere.
  integer(c_int32_t), parameter, public :: ASPERITY_FIDELITY_LENNARD_JONES = 5
  !> `asperity_friction_increment%tangents` bit: compute dF/dN.
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_TANGENT_NORMAL = 1
  !> `asperity_friction_increment%tangents` bit: compute dF/d(slip).
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_TANGENT_SLIP = 2
  ! The friction state indices are C's, from 0: in Fortran the accumulated
  ! dissipation is `state(ASPERITY_FRICTION_STATE_DISSIPATION + 1)`.
  !> Index (from 0) in a friction state of the accumulated dissipation (J).
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_STATE_DISSIPATION = 0
  !> Index (from 0) in a friction state of the accumulated slip path sum |ds| (m).
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_STATE_SLIP_PATH = 1
  !> Index (from 0) in a friction state of the law's first own variable (see
  !  `ASPERITY_FRICTION_STATE_MODEL` in asperity.h for each law's layout).
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_STATE_MODEL = 2
  !> `asperity_friction_response%regime`: no slip (inside the slip cone, zero slip, every
  !  element stuck).
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_STICK = 0
  !> `asperity_friction_response%regime`: partial slip (pre-sliding: some elements or bristles
  !  slipping).
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_PARTIAL_SLIP = 1
  !> `asperity_friction_response%regime`: gross sliding.
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_SLIP = 2
  !> `asperity_friction_response%regime`: no normal force and no adhesion; no friction.
  integer(c_int32_t), parameter, public :: ASPERITY_FRICTION_NO_CONTACT = 3
  !> Segment label: not assigned.
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_UNKNOWN = 0
  !> Segment label: approach (before contact).
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_APPROACH = 1
  !> Segment label: loading.
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_LOADING = 2
  !> Segment label: hold at peak.
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_HOLD = 3
  !> Segment label: unloading from the peak.
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_UNLOADING = 4
  !> Segment label: thermal-drift hold.
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_DRIFT_HOLD = 5
  !> Segment label: final unloading after the drift hold.
  integer(c_int32_t), parameter, public :: ASPERITY_SEGMENT_FINAL_UNLOADING = 6
  !> Indenter: Berkovich pyramid (ideal area 24.5 h_c², β = 1.034).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENTER_BERKOVICH = 1
  !> Indenter: Vickers pyramid (ideal area 24.5 h_c², β = 1.012).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENTER_VICKERS = 2
  !> Indenter: cube corner (ideal area 2.598 h_c², β = 1.034).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENTER_CUBE_CORNER = 3
  !> Indenter: cone of half-angle `cone_half_angle` (rad), β = 1.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENTER_CONE = 4
  !> Indenter: sphere of radius `sphere_radius` (m), d = 2, β = 1.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENTER_SPHERE = 5
  !> Indenter: not documented (Berkovich area and β assumed, flagged).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENTER_UNKNOWN = 6
  !> Loading-fit anchor: the maximum point of loading (thesis §3.6.1).
  integer(c_int32_t), parameter, public :: ASPERITY_ANCHOR_MAX_POINT = 0
  !> Loading-fit anchor: the point `anchor_index`.
  integer(c_int32_t), parameter, public :: ASPERITY_ANCHOR_INDEX = 1
  !> Loading-fit anchor: none (two-parameter regression).
  integer(c_int32_t), parameter, public :: ASPERITY_ANCHOR_FREE = 2
  !> Flag bit: κ < 0 (outside the rescaling assumptions).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_KAPPA_NEGATIVE = 1
  !> Flag bit: κ > 1 (only densifying or hardening materials).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_KAPPA_ABOVE_ONE = 2
  !> Flag bit: d > 3 (implausibly blunt).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_D_ABOVE_THREE = 4
  !> Flag bit: d < 1 (sharper than a cone).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_D_BELOW_ONE = 8
  !> Flag bit: indenter and specimen both deformable with different κ.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_BOTH_DEFORMABLE = 16
  !> Flag bit: sharp indenter, outside the Hertz assumptions.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_SHARP_INDENTER = 32
  !> Flag bit: no usable unloading branch (no modulus, no hardness).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_NO_UNLOADING = 64
  !> Flag bit: few points in the fits.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_FEW_POINTS = 128
  !> Flag bit: loading branch not a power law (R² < 0.99).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_POOR_LOADING_FIT = 256
  !> Flag bit: unloading branch not a power law (R² < 0.99).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_POOR_UNLOADING_FIT = 512
  !> Flag bit: indenter undocumented, ideal Berkovich area assumed.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_AREA_FUNCTION_ASSUMED = 1024
  !> Flag bit: se(κ) > 0.25.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_KAPPA_POORLY_CONSTRAINED = 2048
  !> Flag bit: se(d) > d/4.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_D_POORLY_CONSTRAINED = 4096
  !> Flag bit: E_r not below the indenter's modulus (no sample modulus).
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_MODULUS_EXCEEDS_INDENTER = 8192
  !> Flag bit: the unloading stiffness moves by more than its standard error as the fit
  !> window's lower bound moves from 0.2 to 0.8 of P_max.
  integer(c_int32_t), parameter, public :: ASPERITY_INDENT_FLAG_WINDOW_DEPENDENT_STIFFNESS = 16384
  !> AFM model selector: fit every model and recommend one.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_MODEL_AUTO = 0
  !> AFM model selector: Hertz.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_MODEL_HERTZ = 1
  !> AFM model selector: DMT.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_MODEL_DMT = 2
  !> AFM model selector: JKR.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_MODEL_JKR = 3
  !> AFM model selector: Maugis–Dugdale with the Lennard-Jones stress.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_MODEL_MAUGIS_DUGDALE = 4
  !> AFM model selector: the numerical Lennard-Jones sphere (tabulated).
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_MODEL_LJ = 5
  !> AFM input signal: force (N, positive repulsive).
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_INPUT_FORCE = 0
  !> AFM input signal: deflection (m); force = k · deflection.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_INPUT_DEFLECTION = 1
  !> AFM flag bit: no tip radius; the fits give E*·√R and w·R.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_RADIUS_UNKNOWN = 1
  !> AFM flag bit: no jump-in on the approach.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_NO_JUMP_IN = 2
  !> AFM flag bit: the pull-off is within the noise of the baseline.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_NO_ADHESION = 4
  !> AFM flag bit: a free part shorter than 20 points.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_SHORT_BASELINE = 8
  !> AFM flag bit: approach and retract baselines differ (drag, drift).
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_BASELINE_MISMATCH = 16
  !> AFM flag bit: E* of the recommended fit is undetermined.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_E_STAR_UNRESOLVED = 32
  !> AFM flag bit: a model could not be fitted or did not converge.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_FIT_FAILED = 64
  !> AFM flag bit: the recommended model lies outside its Tabor range.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_MODEL_OUTSIDE_TABOR_RANGE = 128
  !> AFM flag bit: fewer than 10 retract points fitted.
  integer(c_int32_t), parameter, public :: ASPERITY_AFM_FLAG_FEW_FIT_POINTS = 256
  !> Weir surface energy prefactor `K = 1/((m−2)(n−2))` (the default).
  integer(c_int32_t), parameter, public :: ASPERITY_WEIR_PLANE_SUM = 0
  !> Weir surface energy prefactor `K = 3/(mn)` (reproduces seed 001's 8.6 nN).
  integer(c_int32_t), parameter, public :: ASPERITY_WEIR_THREE_OVER_MN = 1
  !> Pair rule: Dupré with geometric-mean interfacial energy, `w = 2√(γ₁γ₂)`.
  integer(c_int32_t), parameter, public :: ASPERITY_PAIR_GEOMETRIC_MEAN = 0
  !> Pair rule of seed 001: `Δγ = (√γ₁ − √γ₂)²`.
  integer(c_int32_t), parameter, public :: ASPERITY_PAIR_SEED001_DIFFERENCE = 1
  !> `asperity_slider_info%scene_control`, `asperity_slider_options%control`: a fixed load (N).
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_CONTROL_LOAD = 1
  !> `asperity_slider_info%scene_control`, `asperity_slider_options%control`: a fixed gap, the
  !  slider's mean line at the gap (m) above the counter-surface's mean line.
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_CONTROL_GAP = 2
  !> `asperity_slider_options%mechanisms` bit: breaking of chemical bonds (4.1).
  integer(c_int32_t), parameter, public :: ASPERITY_MECHANISM_CHEMICAL = 1
  !> `asperity_slider_options%mechanisms` bit: breaking of van der Waals bonds (4.2).
  integer(c_int32_t), parameter, public :: ASPERITY_MECHANISM_VAN_DER_WAALS = 2
  !> `asperity_slider_options%mechanisms` bit: elastic strain energy released by unloading
  !  rods (4-15).
  integer(c_int32_t), parameter, public :: ASPERITY_MECHANISM_ELASTIC = 4
  !> `asperity_slider_options%mechanisms` bit: plastic work of yielding rods (4-16).
  integer(c_int32_t), parameter, public :: ASPERITY_MECHANISM_PLASTIC = 8
  !> `asperity_slider_options%mechanisms`: every mechanism (the default).
  integer(c_int32_t), parameter, public :: ASPERITY_MECHANISM_ALL = 15
  !> `asperity_slider_options%cof_form`: Derjaguin, mu = F/(N + A) (4-3), the default.
  integer(c_int32_t), parameter, public :: ASPERITY_COF_DERJAGUIN = 0
  !> `asperity_slider_options%cof_form`: Amontons, mu = F/N (1-1).
  integer(c_int32_t), parameter, public :: ASPERITY_COF_AMONTONS = 1
  !> `asperity_slider_options%cof_form`: Coulomb, mu = (F - A)/N (1-2).
  integer(c_int32_t), parameter, public :: ASPERITY_COF_COULOMB = 2
  !> `asperity_slider_options%cof_form`: mu = F/(N + 2A), not the thesis's stated form but the
  !  arithmetic of its Tables 6-1 and 6-2 (THESIS.md).
  integer(c_int32_t), parameter, public :: ASPERITY_COF_DERJAGUIN_DOUBLE_ADHESION = 3
  !> `asperity_slider_options%plastic`: the volume of a yielded rod goes in halves to the
  !  nearest non-yielded rod on each side (thesis 6.2.3), the default.
  integer(c_int32_t), parameter, public :: ASPERITY_PLASTIC_NEAREST_NEIGHBOURS = 0
  !> `asperity_slider_options%plastic`: Gaussian weights of width `plastic_width` over the
  !  non-yielded rods (the chapter-6 scenes use 20 um).
  integer(c_int32_t), parameter, public :: ASPERITY_PLASTIC_GAUSSIAN = 1
  !> `asperity_slider_options%plastic`: yielded rods shorten, no pile-up.
  integer(c_int32_t), parameter, public :: ASPERITY_PLASTIC_SHORTEN_ONLY = 2
  !> `asperity_slider_options%solver`: exact O(n log n) sweep, warm-started (the default).
  integer(c_int32_t), parameter, public :: ASPERITY_ROD_SOLVER_SWEEP = 0
  !> `asperity_slider_options%solver`: the thesis's dense formulation (reference).
  integer(c_int32_t), parameter, public :: ASPERITY_ROD_SOLVER_DENSE = 1
  !> The largest Burridge-Knopoff chain (blocks).
  integer(c_int32_t), parameter, public :: ASPERITY_DYNAMIC_MAX_BLOCKS = 256
  ! The slider's and the homogenised law's state indices are C's, from 0: in
  ! Fortran the slider position is `state(ASPERITY_SLIDER_STATE_POSITION + 1)`.
  !> Index (from 0) in a slider's friction state of its flag: 0 fresh, 1 stepped.
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_STATE_FLAG = 2
  !> Index (from 0) in a slider's friction state of the slider position X along its track (m).
  !  A fresh state (flag 0) starts there: set it to place patches at different points of the
  !  counter-surface.
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_STATE_POSITION = 3
  !> Index (from 0) in a slider's friction state of the rod-bed position b of the last
  !  equilibrium (m; NaN: none).
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_STATE_ROD_POSITION = 4
  !> Index (from 0) in a slider's friction state of the accumulated dissipation by mechanism
  !  (J), 4 values: chemical, van der Waals, elastic, plastic.
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_STATE_MECHANISMS = 5
  !> Index (from 0) in a slider's friction state of the rod heights (m, one per rod), followed
  !  by the rods' stored elastic energies (J, one per rod).
  integer(c_int32_t), parameter, public :: ASPERITY_SLIDER_STATE_HEIGHTS = 9
  !> Index (from 0) in a homogenised friction state of the stick force (N, x and y).
  integer(c_int32_t), parameter, public :: ASPERITY_HOMOGENISED_STATE_FORCE = 2
  !> Index (from 0) in a homogenised friction state of the accumulated plastic slip path (m).
  integer(c_int32_t), parameter, public :: ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH = 4
  !> Index (from 0) in a homogenised friction state of the accumulated dissipation by
  !  mechanism (J), 4 values: chemical, van der Waals, elastic, plastic.
  integer(c_int32_t), parameter, public :: ASPERITY_HOMOGENISED_STATE_MECHANISMS = 5
  !> Summit heights: Gaussian of zero mean and standard deviation σ.
  integer(c_int32_t), parameter, public :: ASPERITY_HEIGHTS_GAUSSIAN = 1
  !> Archard's hierarchy with Hertzian spheres of equal height at every generation.
  integer(c_int32_t), parameter, public :: ASPERITY_ARCHARD_UNIFORM = 0
  !> Archard's hierarchy whose finest protuberances stand at distributed heights.
  integer(c_int32_t), parameter, public :: ASPERITY_ARCHARD_NON_UNIFORM = 1
  !> Summit heights: exponential tail shifted to zero mean, standard deviation (decay length) σ.
  integer(c_int32_t), parameter, public :: ASPERITY_HEIGHTS_EXPONENTIAL = 2
  !> Spring heights for `asperity_sergienko_bukharov_run`: the listed heights.
  integer(c_int32_t), parameter, public :: ASPERITY_HEIGHTS_LIST = 0
  !> Deformation regime of a plasticity index ψ < 0.6: elastic.
  integer(c_int32_t), parameter, public :: ASPERITY_REGIME_ELASTIC = 0
  !> Deformation regime 0.6 ≤ ψ ≤ 1: transitional.
  integer(c_int32_t), parameter, public :: ASPERITY_REGIME_TRANSITIONAL = 1
  !> Deformation regime ψ > 1: plastic even at light loads.
  integer(c_int32_t), parameter, public :: ASPERITY_REGIME_PLASTIC = 2
  !> Success.
  integer(c_int32_t), parameter, public :: ASPERITY_OK = 0
  !> A required pointer argument was NULL.
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_NULL_POINTER = -1
  !> An argument is outside its documented domain (NaN, ±∞ where not allowed, negative radius, ν >
  !  0.5, an unknown selector value, …).
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_INVALID_ARGUMENT = -2
  !> An iterative method did not reach its tolerance.
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_NOT_CONVERGED = -3
  !> Valid arguments, but no such state for this law (for example a load below the pull-off
  !  force).
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_OUT_OF_DOMAIN = -4
  !> A bug in the library (a caught panic). The message says where.
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_INTERNAL = -5
  !> A file could not be read (not found, no permission, not text).
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_IO = -6
  !> A text file or buffer does not have the expected format; the message gives the line.
  integer(c_int32_t), parameter, public :: ASPERITY_ERR_PARSE = -7
  !> Form removal before analysis: none (the heights as given; the mean line is still their mean).
  integer(c_int32_t), parameter, public :: ASPERITY_FORM_NONE = 0
  !> Form removal: the mean height.
  integer(c_int32_t), parameter, public :: ASPERITY_FORM_MEAN = 1
  !> Form removal: the least-squares straight line (tilt).
  integer(c_int32_t), parameter, public :: ASPERITY_FORM_LINEAR = 2
  !> Form removal: the least-squares parabola (tilt and curvature).
  integer(c_int32_t), parameter, public :: ASPERITY_FORM_QUADRATIC = 3
  !> Gaussian filter ends: drop λc/2 at each end (ISO 4288 run-in/run-out).
  integer(c_int32_t), parameter, public :: ASPERITY_FILTER_ENDS_DISCARD = 0
  !> Gaussian filter ends: keep every sample, kernel renormalised at the ends (ISO 16610-28).
  integer(c_int32_t), parameter, public :: ASPERITY_FILTER_ENDS_KEEP = 1
  !> PSD data window: none (rectangular; Parseval exact, m₀ = Rq²).
  integer(c_int32_t), parameter, public :: ASPERITY_WINDOW_RECTANGULAR = 0
  !> PSD data window: periodic Hann, normalised by its mean square.
  integer(c_int32_t), parameter, public :: ASPERITY_WINDOW_HANN = 1

  ! ------------------------------------------------------------------------
  ! Mirrors of the C structs (`type, bind(c)`), in header order.

  !> `AsperityHertzParams`
  type, bind(c), public :: asperity_hertz_params
    !> Radius of curvature R of the sphere, or the effective radius `1/R = 1/R₁ + 1/R₂` of two
    !  spheres (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
  end type asperity_hertz_params

  !> `AsperityPowerPunchParams`
  type, bind(c), public :: asperity_power_punch_params
    !> Shape coefficient B (m^{1−d}, > 0) of the profile `f(r) = B r^d`.
    real(c_double) :: b = 0.0_c_double
    !> Shape exponent d (1 ≤ d ≤ 100).
    real(c_double) :: d = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
  end type asperity_power_punch_params

  !> `AsperityFlatPunchParams`
  type, bind(c), public :: asperity_flat_punch_params
    !> Punch radius a (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Poisson's ratio ν of the half-space (0 ≤ ν ≤ 0.5): gives the no-slip factor when `no_slip` =
    !  1; range-checked only when 0.
    real(c_double) :: nu = 0.0_c_double
    !> 1 for a punch bonded to the half-space (no slip), 0 frictionless.
    integer(c_int32_t) :: no_slip = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_flat_punch_params

  !> `AsperityDmtParams`
  type, bind(c), public :: asperity_dmt_params
    !> Sphere radius R (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Work of adhesion w (J/m², ≥ 0).
    real(c_double) :: work_of_adhesion = 0.0_c_double
  end type asperity_dmt_params

  !> `AsperityJkrParams`
  type, bind(c), public :: asperity_jkr_params
    !> Sphere radius R (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Work of adhesion w (J/m², ≥ 0).
    real(c_double) :: work_of_adhesion = 0.0_c_double
  end type asperity_jkr_params

  !> `AsperityJkrPowerPunchParams`
  type, bind(c), public :: asperity_jkr_power_punch_params
    !> Shape coefficient B (m^{1−d}, > 0) of the profile `f(r) = B r^d`.
    real(c_double) :: b = 0.0_c_double
    !> Shape exponent d (1 ≤ d ≤ 100).
    real(c_double) :: d = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Work of adhesion w (J/m², ≥ 0).
    real(c_double) :: work_of_adhesion = 0.0_c_double
    !> Poisson's ratio ν of the half-space (0 ≤ ν ≤ 0.5): gives C_NS and k*(d) when `no_slip` = 1;
    !  range-checked only when 0.
    real(c_double) :: nu = 0.0_c_double
    !> 1 for a punch bonded to the half-space (no slip), 0 frictionless.
    integer(c_int32_t) :: no_slip = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_jkr_power_punch_params

  !> `AsperityKendallParams`
  type, bind(c), public :: asperity_kendall_params
    !> Punch radius a (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Work of adhesion w (J/m², ≥ 0).
    real(c_double) :: work_of_adhesion = 0.0_c_double
    !> Poisson's ratio ν of the half-space (0 ≤ ν ≤ 0.5): gives the no-slip factor when `no_slip` =
    !  1; range-checked only when 0.
    real(c_double) :: nu = 0.0_c_double
    !> 1 for a punch bonded to the half-space (no slip), 0 frictionless.
    integer(c_int32_t) :: no_slip = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_kendall_params

  !> `AsperityMaugisDugdaleParams`
  type, bind(c), public :: asperity_maugis_dugdale_params
    !> Sphere radius R (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Work of adhesion w (J/m², > 0).
    real(c_double) :: work_of_adhesion = 0.0_c_double
    !> Dugdale cohesive stress σ₀ (Pa, > 0).
    real(c_double) :: cohesive_stress = 0.0_c_double
  end type asperity_maugis_dugdale_params

  !> `AsperityDerjaguinParams`
  type, bind(c), public :: asperity_derjaguin_params
    !> Sphere radius R (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Work of adhesion w (J/m², > 0).
    real(c_double) :: work_of_adhesion = 0.0_c_double
    !> The surface law's second parameter: the equilibrium separation z₀ (m) for Lennard-Jones, the
    !  cohesive stress σ₀ (Pa) for Dugdale, the decay length ℓ (m) for the exponential law (> 0).
    real(c_double) :: parameter = 0.0_c_double
    !> Surface law selector: 1 Lennard-Jones, 2 Dugdale, 3 exponential (`ASPERITY_SURFACE_LAW_*`).
    integer(c_int32_t) :: surface_law = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_derjaguin_params

  !> `AsperityLawParams`: Fortran has no unions; view a member with `transfer`, e.g.
  !  `jkr = transfer(law%params, jkr)` for a `type(asperity_jkr_params) :: jkr`, and fill one with
  !  `params%raw(1:3) = transfer(jkr, params%raw(1:3))`.
  type, bind(c), public :: asperity_law_params
    !> Storage: the inputs, then the library's private derived values.
    real(c_double) :: raw(16) = 0.0_c_double
  end type asperity_law_params

  !> `AsperityNormalLaw`
  type, bind(c), public :: asperity_normal_law
    !> One of `ASPERITY_LAW_*`.
    integer(c_int32_t) :: kind = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
    !> The inputs of `kind` (and the library's derived values).
    type(asperity_law_params) :: params
  end type asperity_normal_law

  !> `AsperityContactState`
  type, bind(c), public :: asperity_contact_state
    !> Contact radius a at the end of the step (m).
    real(c_double) :: contact_radius = 0.0_c_double
    !> Outer radius c of the cohesive (adhesive) zone at the end of the step (m); 0 when the law
    !  has none.
    real(c_double) :: cohesive_radius = 0.0_c_double
    !> 1 when the surfaces are in contact (or, for laws with a cohesive zone, interacting) at
    !  the end of the step, 0 otherwise.
    integer(c_int32_t) :: in_contact = 0_c_int32_t
    !> Law-specific index of the equilibrium branch the contact is on; 0 for a fresh state.
    integer(c_int32_t) :: branch = 0_c_int32_t
  end type asperity_contact_state

  !> `AsperityNormalResponse`
  type, bind(c), public :: asperity_normal_response
    !> Normal force P (N), positive when repulsive.
    real(c_double) :: force = 0.0_c_double
    !> Overlap δ (m) of this equilibrium (the input under displacement control).
    real(c_double) :: delta = 0.0_c_double
    !> Contact radius a (m); 0 out of contact.
    real(c_double) :: contact_radius = 0.0_c_double
    !> Tangent stiffness dP/dδ (N/m) along the branch the contact is on.
    real(c_double) :: stiffness = 0.0_c_double
    !> 1 in contact, 0 otherwise.
    integer(c_int32_t) :: in_contact = 0_c_int32_t
    !> Reserved, always 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_normal_response

  !> `AsperityFidelityAssessment`
  type, bind(c), public :: asperity_fidelity_assessment
    !> One of `ASPERITY_FIDELITY_*`.
    integer(c_int32_t) :: law = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
    !> |P_c,model − P_c,LJ| (N), load-controlled pull-off.
    real(c_double) :: pull_off_error = 0.0_c_double
    !> Largest force difference over a displacement-controlled approach and retraction (N).
    real(c_double) :: curve_error = 0.0_c_double
    !> Time per evaluation on this machine (s).
    real(c_double) :: cost_per_call = 0.0_c_double
    !> One-time construction time (s).
    real(c_double) :: build_time = 0.0_c_double
  end type asperity_fidelity_assessment

  !> `AsperityFidelityAdvice`
  type, bind(c), public :: asperity_fidelity_advice
    !> The cheapest model within the tolerance (`ASPERITY_FIDELITY_*`).
    integer(c_int32_t) :: choice = 0_c_int32_t
    !> Reference grid size of the Lennard-Jones solution.
    integer(c_int32_t) :: reference_grid = 0_c_int32_t
    !> Tabor parameter μ.
    real(c_double) :: tabor = 0.0_c_double
    !> Load-controlled pull-off of the reference (N, negative).
    real(c_double) :: reference_pull_off = 0.0_c_double
    !> Every model, cheapest first (index = `ASPERITY_FIDELITY_*`).
    type(asperity_fidelity_assessment) :: assessments(0:5)
  end type asperity_fidelity_advice

  !> `AsperityNanoAsperities`
  type, bind(c), public :: asperity_nano_asperities
    !> Height of the van der Waals body h_vdW (m), > 0: the RMS of the AFM profile (thesis
    !  5-15).
    real(c_double) :: h_vdw = 0.0_c_double
    !> Width of the van der Waals interaction domain w_vdW (m), > 0 (6-2).
    real(c_double) :: w_vdw = 0.0_c_double
    !> Height of the chemical tip on the body h_chem (m), >= 0.
    real(c_double) :: h_chem = 0.0_c_double
    !> Width of the chemical interaction domain w_chem (m), in [0, w_vdW].
    real(c_double) :: w_chem = 0.0_c_double
    !> Distance between nano-asperities (m), >= w_vdW (6-3).
    real(c_double) :: spacing = 0.0_c_double
    !> Nano-asperities on one square tip of the finest rods, >= 1, with per_rod * spacing^2 <=
    !  (rod width)^2.
    integer(c_size_t) :: per_rod = 0_c_size_t
  end type asperity_nano_asperities

  !> `AsperityDissipation`
  type, bind(c), public :: asperity_dissipation
    !> Energy of broken chemical bonds (J), (4-7).
    real(c_double) :: chemical = 0.0_c_double
    !> Energy of broken van der Waals bonds (J), (4-9).
    real(c_double) :: van_der_waals = 0.0_c_double
    !> Elastic strain energy released by unloading rods (J), (4-15).
    real(c_double) :: elastic = 0.0_c_double
    !> Plastic work of yielding rods (J), (4-16).
    real(c_double) :: plastic = 0.0_c_double
  end type asperity_dissipation

  !> `AsperityHomogenisedSample`
  type, bind(c), public :: asperity_homogenised_sample
    !> Nominal contact pressure p = N/A_n (Pa), finite and ≥ 0.
    real(c_double) :: pressure = 0.0_c_double
    !> Coefficient of friction μ at this pressure, finite and ≥ 0, in the table's [`CofForm`]
    !  (Derjaguin μ = F/(N + A), thesis (4-3), by default).
    real(c_double) :: cof = 0.0_c_double
    !> Adhesive holding force per nominal area (Pa), finite and ≥ 0: the adhesive force A of the
    !  thesis (4.2, 4.4) divided by A_n.
    real(c_double) :: adhesion_pressure = 0.0_c_double
    !> True contact area over nominal area (dimensionless), in [0, 1].
    real(c_double) :: contact_fraction = 0.0_c_double
    !> Fractions of the dissipation due to each mechanism (dimensionless, each in [0, 1],
    !  summing to 1 within 1e-9), held in a [`Dissipation`] value: a step's dissipation ΔD is
    !  split as ΔD·shares.
    type(asperity_dissipation) :: shares
  end type asperity_homogenised_sample

  !> `AsperityFrictionIncrement`: one increment of a contact point (SI).
  type, bind(c), public :: asperity_friction_increment
    !> Normal force N on the point (N), finite and ≥ 0 (compressive), constant over the
    !  increment.
    real(c_double) :: normal_force = 0.0_c_double
    !> Nominal area A_n the point represents (m²), finite and ≥ 0; > 0 for laws that depend on
    !  the nominal pressure N/A_n (the homogenised law), unused by the others.
    real(c_double) :: area = 0.0_c_double
    !> Slip increment Δs of the point relative to the counter-surface (m), two finite
    !  components in the caller's tangent basis; a track uses `slip(2) = 0`.
    real(c_double) :: slip(2) = 0.0_c_double
    !> Time increment Δt (s), finite and ≥ 0; > 0 when the slip is not zero and the law is rate
    !  dependent.
    real(c_double) :: dt = 0.0_c_double
    !> Tangents wanted: 0, or `ASPERITY_FRICTION_TANGENT_NORMAL` +
    !  `ASPERITY_FRICTION_TANGENT_SLIP`.
    integer(c_int32_t) :: tangents = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_friction_increment

  !> `AsperityFrictionResponse`: the response of one increment (SI).
  type, bind(c), public :: asperity_friction_response
    !> Tangential force F on the point from the counter-surface at the end of the increment
    !  (N), in the basis of the slip; opposes slip.
    real(c_double) :: force(2) = 0.0_c_double
    !> |F| (N).
    real(c_double) :: force_magnitude = 0.0_c_double
    !> Normal force N (N): as given, or what the law carries.
    real(c_double) :: normal_force = 0.0_c_double
    !> Coefficient of friction of the increment in the law's form; 0 when undefined (no
    !  contact).
    real(c_double) :: cof = 0.0_c_double
    !> Adhesive holding force A (N) of laws that model adhesion, else 0.
    real(c_double) :: adhesion = 0.0_c_double
    !> True contact area (m²) of laws that model it, else 0.
    real(c_double) :: true_contact_area = 0.0_c_double
    !> Energy dissipated in the increment ΔD (J), ≥ 0.
    real(c_double) :: dissipated = 0.0_c_double
    !> ΔD by mechanism (J) for laws built on the mechanisms of thesis chapter 4 (homogenised,
    !  slider); all 0 for the others.
    type(asperity_dissipation) :: dissipation
    !> Elastic energy stored in the law at the end of the increment (J).
    real(c_double) :: stored_energy = 0.0_c_double
    !> dF/dN (dimensionless) at fixed slip increment and old state, when asked for.
    real(c_double) :: dforce_dnormal(2) = 0.0_c_double
    !> dF_i/dΔs_j (N/m), `dforce_dslip[i][j]` is `dforce_dslip(j+1, i+1)`, at fixed N, Δt and
    !  old state, when asked for.
    real(c_double) :: dforce_dslip(2,2) = 0.0_c_double
    !> `ASPERITY_FRICTION_STICK`, `_PARTIAL_SLIP`, `_SLIP` or `_NO_CONTACT`.
    integer(c_int32_t) :: regime = 0_c_int32_t
    !> The tangents computed, as `ASPERITY_FRICTION_TANGENT_*` bits (a law may compute more
    !  than was asked for).
    integer(c_int32_t) :: tangents = 0_c_int32_t
  end type asperity_friction_response

  !> `AsperityIndentationOptions`
  type, bind(c), public :: asperity_indentation_options
    !> One of `ASPERITY_INDENTER_*`.
    integer(c_int32_t) :: indenter = 0_c_int32_t
    !> One of `ASPERITY_ANCHOR_*`.
    integer(c_int32_t) :: anchor = 0_c_int32_t
    !> Nonzero: use the segment labels when given (default 1).
    integer(c_int32_t) :: use_labels = 0_c_int32_t
    !> Number of NanoSuite area coefficients in `area_coefficients` (0: the indenter's ideal
    !  area function).
    integer(c_int32_t) :: n_area_coefficients = 0_c_int32_t
    !> NanoSuite area coefficients, `A = C0 h_c² + C1 h_c + C2 h_c^{1/2} + …` with h_c in nm and
    !  A in nm².
    real(c_double) :: area_coefficients(0:7) = 0.0_c_double
    !> Sphere radius (m), for `ASPERITY_INDENTER_SPHERE`.
    real(c_double) :: sphere_radius = 0.0_c_double
    !> Cone half-angle (rad), for `ASPERITY_INDENTER_CONE`.
    real(c_double) :: cone_half_angle = 0.0_c_double
    !> Nonzero: `known_d` is given (otherwise d is fitted; a sphere's d = 2).
    integer(c_int32_t) :: has_known_d = 0_c_int32_t
    !> Nonzero: `known_kappa` is given.
    integer(c_int32_t) :: has_known_kappa = 0_c_int32_t
    !> Known bluntness index d.
    real(c_double) :: known_d = 0.0_c_double
    !> Known hardening index κ.
    real(c_double) :: known_kappa = 0.0_c_double
    !> Anchor index, for `ASPERITY_ANCHOR_INDEX`.
    integer(c_size_t) :: anchor_index = 0_c_size_t
    !> Indenter Young's modulus (Pa; default 1141e9, INFINITY for rigid).
    real(c_double) :: e_indenter = 0.0_c_double
    !> Indenter Poisson's ratio (default 0.07).
    real(c_double) :: nu_indenter = 0.0_c_double
    !> Sample Poisson's ratio (default 0.3).
    real(c_double) :: nu_sample = 0.0_c_double
    !> β (0: the indenter's, King 1987: 1.034 Berkovich and cube corner, 1.012 Vickers, 1 axisymmetric).
    real(c_double) :: beta = 0.0_c_double
    !> ε of the contact depth (default 0.75).
    real(c_double) :: epsilon = 0.0_c_double
    !> Loading-fit load window, fractions of the anchor load (default 0.1, 1).
    real(c_double) :: loading_window(2) = 0.0_c_double
    !> Unloading-fit load window, fractions of P_max (default 0.2, 0.98).
    real(c_double) :: unloading_window(2) = 0.0_c_double
  end type asperity_indentation_options

  !> `AsperityIndentationResult`
  type, bind(c), public :: asperity_indentation_result
    !> Hardening index κ.
    real(c_double) :: kappa = 0.0_c_double
    !> Standard error of κ.
    real(c_double) :: kappa_stderr = 0.0_c_double
    !> Bluntness index d.
    real(c_double) :: d = 0.0_c_double
    !> Standard error of d.
    real(c_double) :: d_stderr = 0.0_c_double
    !> Loading log–log slope m_l.
    real(c_double) :: loading_slope = 0.0_c_double
    !> Standard error of m_l.
    real(c_double) :: loading_slope_stderr = 0.0_c_double
    !> R² of the loading fit (in ln P).
    real(c_double) :: loading_r_squared = 0.0_c_double
    !> Unloading exponent m of `P = α(h − h_f)^m`.
    real(c_double) :: unloading_exponent = 0.0_c_double
    !> Standard error of m.
    real(c_double) :: unloading_exponent_stderr = 0.0_c_double
    !> Final depth h_f (m).
    real(c_double) :: final_depth = 0.0_c_double
    !> Standard error of h_f (m).
    real(c_double) :: final_depth_stderr = 0.0_c_double
    !> R² of the unloading fit (in P).
    real(c_double) :: unloading_r_squared = 0.0_c_double
    !> Peak load at the start of unloading (N).
    real(c_double) :: peak_load = 0.0_c_double
    !> Depth at the start of unloading (m).
    real(c_double) :: peak_depth = 0.0_c_double
    !> Unloading stiffness S (N/m).
    real(c_double) :: stiffness = 0.0_c_double
    !> Standard error of S (N/m).
    real(c_double) :: stiffness_stderr = 0.0_c_double
    !> Contact depth h_c (m).
    real(c_double) :: contact_depth = 0.0_c_double
    !> Projected contact area (m²).
    real(c_double) :: contact_area = 0.0_c_double
    !> Reduced modulus E_r (Pa), Oliver–Pharr with β.
    real(c_double) :: reduced_modulus = 0.0_c_double
    !> Standard error of E_r (Pa).
    real(c_double) :: reduced_modulus_stderr = 0.0_c_double
    !> BASh reduced modulus (β = 1) (Pa).
    real(c_double) :: reduced_modulus_bash = 0.0_c_double
    !> Sample Young's modulus (Pa).
    real(c_double) :: sample_modulus = 0.0_c_double
    !> Standard error of the sample modulus (Pa).
    real(c_double) :: sample_modulus_stderr = 0.0_c_double
    !> Hardness P_max/A (Pa).
    real(c_double) :: hardness = 0.0_c_double
    !> Standard error of H (Pa).
    real(c_double) :: hardness_stderr = 0.0_c_double
    !> Points in the loading fit.
    integer(c_size_t) :: n_loading_points = 0_c_size_t
    !> Points in the unloading fit.
    integer(c_size_t) :: n_unloading_points = 0_c_size_t
    !> Loading segment `[start, end)`.
    integer(c_size_t) :: loading_range(2) = 0_c_size_t
    !> Unloading segment `[start, end)`.
    integer(c_size_t) :: unloading_range(2) = 0_c_size_t
    !> `ASPERITY_INDENT_FLAG_*` bits.
    integer(c_int32_t) :: flags = 0_c_int32_t
    !> 1 when the unloading branch was analysed.
    integer(c_int32_t) :: has_unloading = 0_c_int32_t
    !> 1 when a sample modulus could be computed.
    integer(c_int32_t) :: has_sample_modulus = 0_c_int32_t
    !> 1 when the segments came from the labels.
    integer(c_int32_t) :: segments_from_labels = 0_c_int32_t
  end type asperity_indentation_result

  !> `AsperityAfmFit`: one fitted model (SI; 0 where not determined).
  type, bind(c), public :: asperity_afm_fit
    !> One of `ASPERITY_AFM_MODEL_*` (never AUTO).
    integer(c_int32_t) :: model = 0_c_int32_t
    !> 1 when the least-squares iteration converged.
    integer(c_int32_t) :: converged = 0_c_int32_t
    !> Contact modulus E* (Pa), for the given tip radius.
    real(c_double) :: e_star = 0.0_c_double
    !> Standard error of E* (Pa).
    real(c_double) :: e_star_stderr = 0.0_c_double
    !> E*·√R (Pa·m^½).
    real(c_double) :: e_star_times_sqrt_radius = 0.0_c_double
    !> Standard error of E*·√R.
    real(c_double) :: e_star_times_sqrt_radius_stderr = 0.0_c_double
    !> Work of adhesion w (J/m²), for the given tip radius.
    real(c_double) :: work_of_adhesion = 0.0_c_double
    !> Standard error of w (J/m²).
    real(c_double) :: work_of_adhesion_stderr = 0.0_c_double
    !> w·R (J/m).
    real(c_double) :: work_of_adhesion_times_radius = 0.0_c_double
    !> Standard error of w·R (J/m).
    real(c_double) :: work_of_adhesion_times_radius_stderr = 0.0_c_double
    !> Tabor parameter μ of the fit (z₀ = 0.3 nm).
    real(c_double) :: tabor_parameter = 0.0_c_double
    !> The law's load-controlled pull-off force (N).
    real(c_double) :: pull_off_force = 0.0_c_double
    !> Position of zero overlap (m).
    real(c_double) :: zero_overlap_position = 0.0_c_double
    !> Root-mean-square effective-variance residual (N).
    real(c_double) :: rms_residual = 0.0_c_double
    !> Points fitted.
    integer(c_size_t) :: points = 0_c_size_t
  end type asperity_afm_fit

  !> `AsperityAfmResult`: result of `asperity_afm_analyze` (SI, never NaN).
  type, bind(c), public :: asperity_afm_result
    !> Pull-off force (N, negative), from the retract baseline.
    real(c_double) :: pull_off_force = 0.0_c_double
    !> Position of the pull-off (m).
    real(c_double) :: pull_off_position = 0.0_c_double
    !> Jump-in distance (m), 0 without jump-in.
    real(c_double) :: jump_in_distance = 0.0_c_double
    !> Force at the bottom of the jump-in dip (N).
    real(c_double) :: jump_in_force = 0.0_c_double
    !> Adhesion energy (J).
    real(c_double) :: adhesion_energy = 0.0_c_double
    !> Retract baseline: force (N) at the contact point.
    real(c_double) :: baseline_offset = 0.0_c_double
    !> Retract baseline: tilt (N/m).
    real(c_double) :: baseline_slope = 0.0_c_double
    !> Retract baseline: noise (N).
    real(c_double) :: baseline_noise = 0.0_c_double
    !> Approach baseline: force (N) at the contact point.
    real(c_double) :: approach_baseline_offset = 0.0_c_double
    !> Approach baseline: tilt (N/m).
    real(c_double) :: approach_baseline_slope = 0.0_c_double
    !> Contact point (m).
    real(c_double) :: contact_point = 0.0_c_double
    !> Spring constant used (N/m).
    real(c_double) :: spring_constant = 0.0_c_double
    !> +1 when the position grows towards the sample, −1 otherwise.
    real(c_double) :: direction = 0.0_c_double
    !> Tabor parameter of the recommended fit (0 when none).
    real(c_double) :: tabor_parameter = 0.0_c_double
    !> First and last index fitted (0-based).
    integer(c_size_t) :: fit_range(2) = 0_c_size_t
    !> 1 when a tip radius was given.
    integer(c_int32_t) :: radius_known = 0_c_int32_t
    !> The recommended model (`ASPERITY_AFM_MODEL_*`), 0 when none.
    integer(c_int32_t) :: recommended_model = 0_c_int32_t
    !> Its 0-based index in `fits`, −1 when none.
    integer(c_int32_t) :: recommended_index = 0_c_int32_t
    !> Number of entries of `fits` in use.
    integer(c_int32_t) :: n_fits = 0_c_int32_t
    !> `ASPERITY_AFM_FLAG_*` bits.
    integer(c_int32_t) :: flags = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
    !> The fitted models, cheapest first.
    type(asperity_afm_fit) :: fits(4)
  end type asperity_afm_result

  !> `AsperityLugreParams`: the LuGre model's parameters (SI).
  type, bind(c), public :: asperity_lugre_params
    !> Coulomb coefficient mu_c, >= 0.
    real(c_double) :: mu_coulomb = 0.0_c_double
    !> Static coefficient mu_s, >= 0.
    real(c_double) :: mu_static = 0.0_c_double
    !> Stribeck velocity v_s (m/s), > 0.
    real(c_double) :: stribeck_velocity = 0.0_c_double
    !> Stribeck exponent delta, > 0 (2: Gaussian).
    real(c_double) :: stribeck_exponent = 0.0_c_double
    !> Bristle stiffness per unit normal force sigma_0 (1/m), > 0.
    real(c_double) :: sigma0 = 0.0_c_double
    !> Bristle damping per unit normal force sigma_1 (s/m), >= 0, within the passivity bound.
    real(c_double) :: sigma1 = 0.0_c_double
    !> Velocity v_d (m/s) of the damping's decay, > 0 (+infinity only when sigma_1 = 0).
    real(c_double) :: damping_velocity = 0.0_c_double
    !> Viscous coefficient sigma_2 (N s/m), >= 0.
    real(c_double) :: sigma2 = 0.0_c_double
  end type asperity_lugre_params

  !> `AsperityGeneralizedMaxwellSlipParams`: the generalised Maxwell-slip model's Stribeck
  !> curve and rates (SI).
  type, bind(c), public :: asperity_generalized_maxwell_slip_params
    !> Coulomb coefficient mu_c of the Stribeck curve, > 0.
    real(c_double) :: mu_coulomb = 0.0_c_double
    !> Static coefficient mu_s of the Stribeck curve, > 0.
    real(c_double) :: mu_static = 0.0_c_double
    !> Stribeck velocity v_s (m/s), > 0.
    real(c_double) :: stribeck_velocity = 0.0_c_double
    !> Stribeck exponent delta, > 0 (2: Gaussian).
    real(c_double) :: stribeck_exponent = 0.0_c_double
    !> Attraction rate C (1/s), > 0; +infinity for the instantaneous limit.
    real(c_double) :: attraction = 0.0_c_double
    !> Viscous coefficient sigma_2 (N s/m), >= 0.
    real(c_double) :: sigma2 = 0.0_c_double
  end type asperity_generalized_maxwell_slip_params

  !> `AsperityCantorProfile`: a Cantor profile (SI; q = 1 Cantor-Liu, q < 1 Cantor-Borodich).
  type, bind(c), public :: asperity_cantor_profile
    !> Descendants p of every block, in [2, 64].
    integer(c_int32_t) :: descendants = 0_c_int32_t
    !> Generations n above the base, in [1, 200].
    integer(c_int32_t) :: generations = 0_c_int32_t
    !> Width ratio r of a descendant to its parent, p r < 1.
    real(c_double) :: width_ratio = 0.0_c_double
    !> Height ratio q of a descendant's step to its parent's, in (0, 1].
    real(c_double) :: height_ratio = 0.0_c_double
    !> Width w0 of the base block (m).
    real(c_double) :: base_width = 0.0_c_double
    !> Height h0 of the base block's step (m).
    real(c_double) :: base_height = 0.0_c_double
  end type asperity_cantor_profile

  !> `AsperityCantorContact`: a Cantor profile's contact at one depth, per unit length.
  type, bind(c), public :: asperity_cantor_contact
    !> Depth below the highest tips (m).
    real(c_double) :: depth = 0.0_c_double
    !> Contact width (m).
    real(c_double) :: width = 0.0_c_double
    !> Load on the Winkler foundation (N/m).
    real(c_double) :: winkler_load = 0.0_c_double
    !> Load on the rigid-plastic foundation (N/m).
    real(c_double) :: plastic_load = 0.0_c_double
  end type asperity_cantor_contact

  !> `AsperitySchmittbuhl`
  type, bind(c), public :: asperity_schmittbuhl
    !> Static coefficient of a generation-0 block (finite, ≥ 0).
    real(c_double) :: mu_static = 0.0_c_double
    !> Kinetic coefficient at the onset of slip (in [0, mu_static]).
    real(c_double) :: mu_kinetic = 0.0_c_double
    !> Weakening velocity v_c (m/s, > 0; +infinity: none).
    real(c_double) :: weakening_velocity = 0.0_c_double
    !> Mass of a generation-0 block (kg, > 0).
    real(c_double) :: mass = 0.0_c_double
    !> Coupling spring between generation-0 blocks (N/m, ≥ 0).
    real(c_double) :: coupling_stiffness = 0.0_c_double
    !> Spring from a generation-0 block to its parent (N/m, > 0).
    real(c_double) :: pulling_stiffness = 0.0_c_double
    !> Normal force on a generation-0 block (N, > 0).
    real(c_double) :: normal_force = 0.0_c_double
    !> Plate velocity V (m/s, > 0).
    real(c_double) :: velocity = 0.0_c_double
    !> Pre-stress disorder (in [0, 1)).
    real(c_double) :: disorder = 0.0_c_double
    !> Blocks per chain N, in [2, 64].
    integer(c_int32_t) :: ratio = 0_c_int32_t
    !> Generations G above generation 0, in [1, 12].
    integer(c_int32_t) :: generations = 0_c_int32_t
    !> Dimension of the elastic continuum, 2 or 3.
    integer(c_int32_t) :: dimension = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_schmittbuhl

  !> `AsperitySchmittbuhlGeneration`
  type, bind(c), public :: asperity_schmittbuhl_generation
    !> Block size relative to generation 0.
    real(c_double) :: size = 0.0_c_double
    !> Block mass (kg).
    real(c_double) :: mass = 0.0_c_double
    !> Coupling spring (N/m).
    real(c_double) :: coupling_stiffness = 0.0_c_double
    !> Pulling spring (N/m).
    real(c_double) :: pulling_stiffness = 0.0_c_double
    !> Normal force on a block (N).
    real(c_double) :: normal_force = 0.0_c_double
    !> Static coefficient.
    real(c_double) :: mu_static = 0.0_c_double
    !> Kinetic coefficient at the onset of slip.
    real(c_double) :: mu_kinetic = 0.0_c_double
    !> Weakening velocity (m/s).
    real(c_double) :: weakening_velocity = 0.0_c_double
    !> mu_kinetic / mu_static (1 when mu_static = 0).
    real(c_double) :: kinetic_to_static = 0.0_c_double
    !> The generation (0: the imposed law).
    integer(c_int32_t) :: index = 0_c_int32_t
    !> Slip events of the chain run that gave this law.
    integer(c_int32_t) :: events = 0_c_int32_t
  end type asperity_schmittbuhl_generation

  !> `AsperityPrandtlTomlinsonTwoSpringParams`: the tip-cantilever Prandtl-Tomlinson model (SI).
  type, bind(c), public :: asperity_prandtl_tomlinson_two_spring_params
    !> Lattice potential amplitude U0 (J), > 0.
    real(c_double) :: amplitude = 0.0_c_double
    !> Lattice period a (m), > 0.
    real(c_double) :: period = 0.0_c_double
    !> Tip (contact) spring k_t to the cantilever body (N/m), > 0.
    real(c_double) :: tip_stiffness = 0.0_c_double
    !> Tip mass m_t (kg), > 0.
    real(c_double) :: tip_mass = 0.0_c_double
    !> Tip damping (kg/s), >= 0.
    real(c_double) :: tip_damping = 0.0_c_double
    !> Cantilever lateral spring k_c to the support (N/m), > 0.
    real(c_double) :: cantilever_stiffness = 0.0_c_double
    !> Cantilever body mass m_c (kg), > 0.
    real(c_double) :: cantilever_mass = 0.0_c_double
    !> Cantilever damping (kg/s), >= 0.
    real(c_double) :: cantilever_damping = 0.0_c_double
    !> Relative tolerance of the integration, in [1e-13, 1e-2].
    real(c_double) :: tolerance = 0.0_c_double
  end type asperity_prandtl_tomlinson_two_spring_params

  !> `AsperityBurridgeKnopoffParams`: the Burridge-Knopoff block chain (SI).
  type, bind(c), public :: asperity_burridge_knopoff_params
    !> Number of blocks M, in [1, `ASPERITY_DYNAMIC_MAX_BLOCKS`]; each carries N/M.
    integer(c_size_t) :: blocks = 0_c_size_t
    !> Mass of each block (kg), > 0.
    real(c_double) :: mass = 0.0_c_double
    !> Coupling spring between neighbours (N/m), >= 0.
    real(c_double) :: coupling_stiffness = 0.0_c_double
    !> Leaf spring from the driver to each block (N/m), > 0.
    real(c_double) :: pulling_stiffness = 0.0_c_double
    !> Static coefficient mu_s, >= 0.
    real(c_double) :: mu_static = 0.0_c_double
    !> Kinetic coefficient mu_k at the onset of slip, in [0, mu_s].
    real(c_double) :: mu_kinetic = 0.0_c_double
    !> Weakening velocity v_c (m/s) of mu_k / (1 + v/v_c), > 0 (+infinity: none).
    real(c_double) :: weakening_velocity = 0.0_c_double
    !> Viscous damping of each block (kg/s), >= 0.
    real(c_double) :: damping = 0.0_c_double
    !> Relative tolerance of the integration, in [1e-13, 1e-2].
    real(c_double) :: tolerance = 0.0_c_double
  end type asperity_burridge_knopoff_params

  !> `AsperitySliderOptions`: how `asperity_slider_new` builds a slider (SI units). Start from
  !  `asperity_slider_options_default`, then set the loading.
  type, bind(c), public :: asperity_slider_options
    !> Fixed load (N), finite, >= 0 and <= the capacity; read when `control` is
    !  `ASPERITY_SLIDER_CONTROL_LOAD`.
    real(c_double) :: normal_force = 0.0_c_double
    !> Fixed gap: the slider's mean line this far above the counter-surface's mean line (m);
    !  read when `control` is `ASPERITY_SLIDER_CONTROL_GAP`.
    real(c_double) :: gap = 0.0_c_double
    !> Width of the Gaussian pile-up weights (m), > 0; read when `plastic` is
    !  `ASPERITY_PLASTIC_GAUSSIAN`.
    real(c_double) :: plastic_width = 0.0_c_double
    !> Rod depth across the track (m), > 0 and at least the nano-asperity spacing; 0 = square
    !  rods.
    real(c_double) :: depth = 0.0_c_double
    !> Margin of the rod roots below the deepest rod (m), >= 0; negative = the rod width.
    real(c_double) :: root_margin = 0.0_c_double
    !> `ASPERITY_SLIDER_CONTROL_LOAD` (1) or `ASPERITY_SLIDER_CONTROL_GAP` (2).
    integer(c_int32_t) :: control = 0_c_int32_t
    !> `ASPERITY_MECHANISM_*` bits: the mechanisms computed.
    integer(c_int32_t) :: mechanisms = 0_c_int32_t
    !> `ASPERITY_COF_DERJAGUIN` (default), `_AMONTONS` or `_COULOMB`.
    integer(c_int32_t) :: cof_form = 0_c_int32_t
    !> `ASPERITY_PLASTIC_NEAREST_NEIGHBOURS` (default), `_GAUSSIAN` or `_SHORTEN_ONLY`.
    integer(c_int32_t) :: plastic = 0_c_int32_t
    !> `ASPERITY_ROD_SOLVER_SWEEP` (default) or `_DENSE`.
    integer(c_int32_t) :: solver = 0_c_int32_t
    !> 1: the counter-surface repeats; 0 (default): running past its end is an error.
    integer(c_int32_t) :: periodic = 0_c_int32_t
  end type asperity_slider_options

  !> `AsperityFrictionMaterial`: the material constants of the friction model (thesis
  !  chapter 4), SI. `asperity_friction_material_copper` gives the thesis's Cu-Cu values.
  type, bind(c), public :: asperity_friction_material
    !> Yield stress sigma_y of the micro-rods (Pa), > 0.
    real(c_double) :: yield_stress = 0.0_c_double
    !> Young's modulus E of the slider (Pa), > 0.
    real(c_double) :: youngs_modulus = 0.0_c_double
    !> Poisson's ratio of the slider, in [0, 0.5].
    real(c_double) :: poisson_ratio = 0.0_c_double
    !> Young's modulus of the counter-surface (Pa), > 0.
    real(c_double) :: counter_youngs_modulus = 0.0_c_double
    !> Poisson's ratio of the counter-surface, in [0, 0.5].
    real(c_double) :: counter_poisson_ratio = 0.0_c_double
    !> Diameter of the metallic bond D_chem (m), > 0.
    real(c_double) :: bond_diameter = 0.0_c_double
    !> Energy dissipated by breaking one chemical bond (J), >= 0.
    real(c_double) :: chemical_bond_energy = 0.0_c_double
    !> Energy dissipated by breaking one van der Waals bond (J), >= 0.
    real(c_double) :: vdw_bond_energy = 0.0_c_double
    !> Work of adhesion W12 (J/m^2), >= 0.
    real(c_double) :: work_of_adhesion = 0.0_c_double
    !> Thickness of the adhesive layer (m), > 0 (5 nm in the thesis).
    real(c_double) :: adhesive_layer = 0.0_c_double
    !> Threshold strain of the nano-asperity law, in (0, 1) (0.10 in the thesis).
    real(c_double) :: threshold_strain = 0.0_c_double
    !> Areal density of surface atoms N_A (1/m^2), > 0.
    real(c_double) :: areal_density = 0.0_c_double
  end type asperity_friction_material

  !> `AsperitySliderInfo` (read with `asperity_slider_get_info`: the name `asperity_slider_info`
  !  is this type's).
  type, bind(c), public :: asperity_slider_info
    !> Doubles per patch state of its friction law (9 + 2 x rods).
    integer(c_size_t) :: state_size = 0_c_size_t
    !> Number of rods (micro-asperities of the finest level).
    integer(c_size_t) :: rods = 0_c_size_t
    !> Nano-asperities per rod.
    integer(c_size_t) :: nano_per_rod = 0_c_size_t
    !> Samples of the counter-surface profile.
    integer(c_size_t) :: counter_samples = 0_c_size_t
    !> Rod width along the track (m).
    real(c_double) :: rod_width = 0.0_c_double
    !> Rod depth across the track (m).
    real(c_double) :: depth = 0.0_c_double
    !> Nominal area of the patch, rods x width x depth (m^2).
    real(c_double) :: nominal_area = 0.0_c_double
    !> Load capacity of the rods, n sigma_y A (N): the largest normal force.
    real(c_double) :: capacity = 0.0_c_double
    !> Counter-surface sample spacing (m).
    real(c_double) :: counter_dx = 0.0_c_double
    !> The scene's loading value: its load (N) or gap (m), per `scene_control`.
    real(c_double) :: scene_loading = 0.0_c_double
    !> The scene's loading: `ASPERITY_SLIDER_CONTROL_LOAD` or `_GAP`.
    integer(c_int32_t) :: scene_control = 0_c_int32_t
    !> 1 when the counter-surface repeats past its end, 0 when running past it is an error.
    integer(c_int32_t) :: periodic = 0_c_int32_t
  end type asperity_slider_info

  !> `AsperitySliderRecord`: the full record of a slider patch's last step (SI), beyond the
  !  friction response (read with `asperity_slider_get_record`: the name `asperity_slider_record`
  !  is this type's). The counts are `uint64_t` in C, `integer(c_int64_t)` here.
  type, bind(c), public :: asperity_slider_record
    !> Slider position X along the track after the increment (m).
    real(c_double) :: position = 0.0_c_double
    !> Rod-bed position b: height of the slider's mean line above the counter-surface's mean
    !  line (m).
    real(c_double) :: rod_position = 0.0_c_double
    !> Fraction of the nano-asperities in contact touching only thanks to adhesion, in [0, 1].
    real(c_double) :: adhesion_area_share = 0.0_c_double
    !> Nano-asperities in contact N_c.
    integer(c_int64_t) :: nano_contacts = 0_c_int64_t
    !> Of those, in contact only thanks to adhesion.
    integer(c_int64_t) :: adhesive_contacts = 0_c_int64_t
    !> Rods carrying force.
    integer(c_int64_t) :: rods_in_contact = 0_c_int64_t
    !> Rods at the yield force.
    integer(c_int64_t) :: yielded_rods = 0_c_int64_t
    !> 1 when the step seated a fresh state first, else 0.
    integer(c_int32_t) :: seated = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_slider_record

  !> `AsperityGwParams`
  type, bind(c), public :: asperity_gw_params
    !> `ASPERITY_HEIGHTS_GAUSSIAN` or `ASPERITY_HEIGHTS_EXPONENTIAL`.
    integer(c_int32_t) :: distribution = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
    !> Number of summits N on the nominal area (summit density η times the nominal area A_n;
    !  dimensionless, > 0).
    real(c_double) :: summit_count = 0.0_c_double
    !> Summit radius R (m, > 0).
    real(c_double) :: radius = 0.0_c_double
    !> Standard deviation σ of the summit heights (m, > 0).
    real(c_double) :: sigma = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
  end type asperity_gw_params

  !> `AsperityGwResponse`
  type, bind(c), public :: asperity_gw_response
    !> Total normal load P (N), ≥ 0, (1-29).
    real(c_double) :: load = 0.0_c_double
    !> Real contact area A (m²), ≥ 0, (1-30).
    real(c_double) :: area = 0.0_c_double
    !> Expected number of summits in contact (dimensionless).
    real(c_double) :: contacts = 0.0_c_double
    !> Normal stiffness −dP/dd (N/m), ≥ 0.
    real(c_double) :: stiffness = 0.0_c_double
  end type asperity_gw_response

  !> `AsperitySeparation`
  type, bind(c), public :: asperity_separation
    !> Separation d (m).
    real(c_double) :: separation = 0.0_c_double
    !> |P(d)/P_target − 1| at `separation` (dimensionless).
    real(c_double) :: relative_residual = 0.0_c_double
    !> Newton/bisection iterations spent after bracketing.
    integer(c_int32_t) :: iterations = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_separation

  !> `AsperityBgtParams`
  type, bind(c), public :: asperity_bgt_params
    !> Mean-square height m₀ = σ² (m², > 0).
    real(c_double) :: m0 = 0.0_c_double
    !> Mean-square profile slope m₂ (dimensionless, > 0).
    real(c_double) :: m2 = 0.0_c_double
    !> Mean-square profile curvature m₄ (m⁻², > 0).
    real(c_double) :: m4 = 0.0_c_double
    !> Contact modulus E* (Pa, > 0).
    real(c_double) :: e_star = 0.0_c_double
    !> Nominal contact area A₀ (m², > 0).
    real(c_double) :: nominal_area = 0.0_c_double
  end type asperity_bgt_params

  !> `AsperityBgtResponse`
  type, bind(c), public :: asperity_bgt_response
    !> Total normal load P (N), ≥ 0.
    real(c_double) :: load = 0.0_c_double
    !> Real contact area A (m²), ≥ 0.
    real(c_double) :: area = 0.0_c_double
    !> Expected number of summits in contact (dimensionless).
    real(c_double) :: contacts = 0.0_c_double
    !> Normal stiffness −dP/dd (N/m), ≥ 0.
    real(c_double) :: stiffness = 0.0_c_double
  end type asperity_bgt_response

  !> `AsperityBoraResponse`
  type, bind(c), public :: asperity_bora_response
    !> Total load P (N), ≥ 0.
    real(c_double) :: load = 0.0_c_double
    !> Real contact area (m²): loaded springs times the cell area Δ².
    real(c_double) :: area = 0.0_c_double
    !> Normal stiffness −dP/dd (N/m), ≥ 0.
    real(c_double) :: stiffness = 0.0_c_double
    !> Number of loaded springs.
    integer(c_int64_t) :: contacts = 0_c_int64_t
    !> Conjugate-gradient iterations spent.
    integer(c_int32_t) :: iterations = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_bora_response

  !> `AsperityBorodichKryukova`
  type, bind(c), public :: asperity_borodich_kryukova
    !> Half-length a of the block (m, > 0).
    real(c_double) :: half_length = 0.0_c_double
    !> Mass M (kg, > 0).
    real(c_double) :: mass = 0.0_c_double
    !> Belt speed U (m/s, finite).
    real(c_double) :: belt_speed = 0.0_c_double
    !> Horizontal spring stiffness k_x (N/m, > 0).
    real(c_double) :: spring_stiffness = 0.0_c_double
    !> Layer stiffness ε (N/m², > 0).
    real(c_double) :: layer_stiffness = 0.0_c_double
    !> Friction coefficient μ (finite, ≥ 0).
    real(c_double) :: friction_coefficient = 0.0_c_double
    !> Gravity g (m/s², finite, ≥ 0).
    real(c_double) :: gravity = 0.0_c_double
    !> Smoothing speed v_s of the friction sign (m/s, > 0).
    real(c_double) :: sign_speed = 0.0_c_double
    !> Amplitude of the block's profile (m, ≥ 0).
    real(c_double) :: slider_amplitude = 0.0_c_double
    !> Wavelength of the block's profile (m, > 0).
    real(c_double) :: slider_wavelength = 0.0_c_double
    !> Amplitude of the belt's profile (m, ≥ 0).
    real(c_double) :: belt_amplitude = 0.0_c_double
    !> Wavelength of the belt's profile (m, > 0).
    real(c_double) :: belt_wavelength = 0.0_c_double
    !> Midpoint cells along the block (1..=100000).
    integer(c_int32_t) :: nodes = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_borodich_kryukova

  !> `AsperityBorodichKryukovaState`
  type, bind(c), public :: asperity_borodich_kryukova_state
    !> Time t (s).
    real(c_double) :: time = 0.0_c_double
    !> Horizontal position x (m).
    real(c_double) :: x = 0.0_c_double
    !> Horizontal velocity (m/s).
    real(c_double) :: vx = 0.0_c_double
    !> Distance y between the profiles' mean lines (m).
    real(c_double) :: y = 0.0_c_double
    !> Vertical velocity (m/s).
    real(c_double) :: vy = 0.0_c_double
  end type asperity_borodich_kryukova_state

  !> `AsperityBorodichKryukovaSample`
  type, bind(c), public :: asperity_borodich_kryukova_sample
    !> The state.
    type(asperity_borodich_kryukova_state) :: state
    !> Elastic normal force F_el,y of the layers (N).
    real(c_double) :: normal_force = 0.0_c_double
    !> Friction force F_fr,x on the block (N).
    real(c_double) :: friction_force = 0.0_c_double
  end type asperity_borodich_kryukova_sample
  !> `AsperitySergienkoBukharovParams`
  type, bind(c), public :: asperity_sergienko_bukharov_params
    !> `ASPERITY_HEIGHTS_LIST`, `ASPERITY_HEIGHTS_GAUSSIAN` or `ASPERITY_HEIGHTS_EXPONENTIAL`.
    integer(c_int32_t) :: distribution = 0_c_int32_t
    !> Periods skipped before averaging.
    integer(c_int32_t) :: transient_periods = 0_c_int32_t
    !> Periods averaged over (>= 1).
    integer(c_int32_t) :: average_periods = 0_c_int32_t
    !> Least steps per natural period of the stiffest state reached (16..100000).
    integer(c_int32_t) :: steps_per_natural_period = 0_c_int32_t
    !> Number of springs N (> 0); for a list, 0 means one spring per height.
    real(c_double) :: rod_count = 0.0_c_double
    !> Standard deviation of parametric heights (m, > 0).
    real(c_double) :: sigma = 0.0_c_double
    !> Stiffness k of one spring (N/m, > 0).
    real(c_double) :: rod_stiffness = 0.0_c_double
    !> Cross-section of one spring (m², > 0).
    real(c_double) :: rod_area = 0.0_c_double
    !> Mass m of the body (kg, > 0).
    real(c_double) :: mass = 0.0_c_double
    !> Normal load N₀ (N, > 0).
    real(c_double) :: load = 0.0_c_double
    !> Damping ratio ζ (>= 0).
    real(c_double) :: damping_ratio = 0.0_c_double
    !> Friction coefficient μ (> 0).
    real(c_double) :: friction_coefficient = 0.0_c_double
    !> Specific attractive force p₀ (Pa, >= 0).
    real(c_double) :: attractive_pressure = 0.0_c_double
    !> Amplitude F₀ of the normal force F₀ sin ωt (N, >= 0).
    real(c_double) :: force_amplitude = 0.0_c_double
    !> Angular frequency ω (rad/s).
    real(c_double) :: frequency = 0.0_c_double
    !> Tangential impulse J at t = 0 (N·s, >= 0).
    real(c_double) :: tangential_impulse = 0.0_c_double
    !> Flank slope tan θ (>= 0).
    real(c_double) :: slope = 0.0_c_double
    !> Start position relative to the static equilibrium (m).
    real(c_double) :: initial_offset = 0.0_c_double
    !> Most time steps (0: 5e7).
    integer(c_int64_t) :: max_steps = 0_c_int64_t
  end type asperity_sergienko_bukharov_params

  !> `AsperitySergienkoBukharovResult`
  type, bind(c), public :: asperity_sergienko_bukharov_result
    !> Static separation d_s (m).
    real(c_double) :: static_separation = 0.0_c_double
    !> Springs in contact at rest.
    real(c_double) :: static_contacts = 0.0_c_double
    !> Static friction (N).
    real(c_double) :: static_friction = 0.0_c_double
    !> Mean separation (m).
    real(c_double) :: mean_separation = 0.0_c_double
    !> Dynamic lift, mean minus static separation (m).
    real(c_double) :: lift = 0.0_c_double
    !> Half the peak-to-peak range of the separation (m).
    real(c_double) :: separation_amplitude = 0.0_c_double
    !> Mean number of contacting springs.
    real(c_double) :: mean_contacts = 0.0_c_double
    !> Mean over static contacts.
    real(c_double) :: contact_ratio = 0.0_c_double
    !> Mean spring load (N).
    real(c_double) :: mean_load = 0.0_c_double
    !> Mean friction force (N).
    real(c_double) :: mean_friction = 0.0_c_double
    !> Mean over static friction.
    real(c_double) :: friction_ratio = 0.0_c_double
    !> Fraction of the averaged time off the springs.
    real(c_double) :: lift_off_fraction = 0.0_c_double
    !> Damping coefficient c (N·s/m).
    real(c_double) :: damping = 0.0_c_double
    !> Averaging period T (s).
    real(c_double) :: period = 0.0_c_double
    !> Time step (s).
    real(c_double) :: time_step = 0.0_c_double
    !> Steps per natural period of the stiffest state reached.
    real(c_double) :: resolution = 0.0_c_double
    !> Steps taken.
    integer(c_int64_t) :: steps = 0_c_int64_t
  end type asperity_sergienko_bukharov_result

  !> `AsperityZhuravlev`
  type, bind(c), public :: asperity_zhuravlev
    !> Cap radius R of both surfaces (m, > 0), or 0.
    real(c_double) :: cap_radius = 0.0_c_double
    !> Effective radius of a pair of caps (m, > 0), or 0.
    real(c_double) :: effective_radius = 0.0_c_double
    !> Contact modulus E* (Pa, > 0; E/(2(1−ν²)) for identical materials).
    real(c_double) :: e_star = 0.0_c_double
    !> Summit count N (> 0) that normalises the meeting probability.
    real(c_double) :: summit_count = 0.0_c_double
  end type asperity_zhuravlev

  !> `AsperityZhuravlevResponse`
  type, bind(c), public :: asperity_zhuravlev_response
    !> Total normal load P (N), (1-23).
    real(c_double) :: load = 0.0_c_double
    !> Real contact area S (m²), (1-24).
    real(c_double) :: area = 0.0_c_double
    !> Expected number of contacting pairs (dimensionless).
    real(c_double) :: contacts = 0.0_c_double
  end type asperity_zhuravlev_response

  !> `AsperityZhuravlevFriction`
  type, bind(c), public :: asperity_zhuravlev_friction
    !> Approach x (m) that carries the load.
    real(c_double) :: approach = 0.0_c_double
    !> The load P (N).
    real(c_double) :: load = 0.0_c_double
    !> Real contact area S (m²).
    real(c_double) :: area = 0.0_c_double
    !> Friction force F = τS (N).
    real(c_double) :: friction_force = 0.0_c_double
    !> Coefficient of friction μ = F/P (dimensionless).
    real(c_double) :: coefficient = 0.0_c_double
  end type asperity_zhuravlev_friction

  !> `AsperityRoughness`
  type, bind(c), public :: asperity_roughness
    !> Maximum profile peak height Rp (m), averaged over sampling lengths.
    real(c_double) :: rp = 0.0_c_double
    !> Maximum profile valley depth Rv (m).
    real(c_double) :: rv = 0.0_c_double
    !> Maximum height Rz = Rp + Rv within a sampling length (m).
    real(c_double) :: rz = 0.0_c_double
    !> Mean height of profile elements Rc (m); meaningful only when `has_rc` is 1 (0 otherwise).
    real(c_double) :: rc = 0.0_c_double
    !> Total height Rt over the evaluation length (m); Rt ≥ Rz.
    real(c_double) :: rt = 0.0_c_double
    !> Arithmetic mean deviation Ra (m).
    real(c_double) :: ra = 0.0_c_double
    !> Root-mean-square deviation Rq (m), thesis (1-5).
    real(c_double) :: rq = 0.0_c_double
    !> Skewness Rsk (dimensionless).
    real(c_double) :: rsk = 0.0_c_double
    !> Kurtosis Rku (dimensionless; 3 for a Gaussian, 1.5 for a sine).
    real(c_double) :: rku = 0.0_c_double
    !> Mean width of profile elements RSm (m); meaningful only when `has_rsm` is 1 (0
    !  otherwise).
    real(c_double) :: rsm = 0.0_c_double
    !> Root-mean-square slope RΔq (dimensionless), seven-point slopes.
    real(c_double) :: rdq = 0.0_c_double
    !> Hurst exponent H of the power-law fit PSD ∝ q^{−(1+2H)} over the default band; meaningful
    !  only when `has_psd_hurst_exponent` is 1 (0 otherwise: fewer than 128 samples, or the
    !  spectrum is not a power law with r² ≥ 0.9 and 0 ≤ H ≤ 1 there).
    real(c_double) :: psd_hurst_exponent = 0.0_c_double
    !> Spectral moment m₀ = ∫G dq (m²) of the evaluated profile (rectangular window): the height
    !  variance, Rq² when there is one sampling length.
    real(c_double) :: m0 = 0.0_c_double
    !> Spectral moment m₂ = ∫q²G dq (dimensionless): the slope variance.
    real(c_double) :: m2 = 0.0_c_double
    !> Spectral moment m₄ = ∫q⁴G dq (m⁻²): the curvature variance.
    real(c_double) :: m4 = 0.0_c_double
    !> Nayak's bandwidth parameter α = m₀m₄/m₂² (dimensionless).
    real(c_double) :: nayak_alpha = 0.0_c_double
    !> Sampling length used (m).
    real(c_double) :: sampling_length = 0.0_c_double
    !> Number of sampling lengths averaged.
    integer(c_size_t) :: sampling_lengths = 0_c_size_t
    !> Number of samples of the evaluated profile (fewer than `n` when the Gaussian filter
    !  discarded its ends).
    integer(c_size_t) :: n_evaluated = 0_c_size_t
    !> Index in the input of the first evaluated sample.
    integer(c_size_t) :: first_index = 0_c_size_t
    !> 1 when `rc` holds a value (a complete profile element was found).
    integer(c_int32_t) :: has_rc = 0_c_int32_t
    !> 1 when `rsm` holds a value.
    integer(c_int32_t) :: has_rsm = 0_c_int32_t
    !> 1 when `psd_hurst_exponent` holds a value.
    integer(c_int32_t) :: has_psd_hurst_exponent = 0_c_int32_t
    !> Reserved, 0.
    integer(c_int32_t) :: reserved = 0_c_int32_t
  end type asperity_roughness

  !> `AsperityHurstFit`
  type, bind(c), public :: asperity_hurst_fit
    !> Hurst exponent H = −(s + 1)/2 (dimensionless).
    real(c_double) :: hurst = 0.0_c_double
    !> Fitted log–log slope s (dimensionless).
    real(c_double) :: slope = 0.0_c_double
    !> Prefactor A (m³·(rad/m)^{−s}).
    real(c_double) :: prefactor = 0.0_c_double
    !> Coefficient of determination r² of the log–log fit.
    real(c_double) :: r_squared = 0.0_c_double
    !> Lower end of the fit band (rad/m).
    real(c_double) :: q_min = 0.0_c_double
    !> Upper end of the fit band (rad/m).
    real(c_double) :: q_max = 0.0_c_double
    !> Number of populated log bins fitted (10 per decade).
    integer(c_size_t) :: bins = 0_c_size_t
  end type asperity_hurst_fit

  !> `AsperityHurstEstimate`
  type, bind(c), public :: asperity_hurst_estimate
    !> Hurst exponent H = −(s + 1)/2 (dimensionless).
    real(c_double) :: hurst = 0.0_c_double
    !> Standard error of H (one standard deviation, statistical).
    real(c_double) :: hurst_uncertainty = 0.0_c_double
    !> Fitted log–log slope s.
    real(c_double) :: slope = 0.0_c_double
    !> Standard error of s.
    real(c_double) :: slope_uncertainty = 0.0_c_double
    !> Prefactor A (m³·(rad/m)^{−s}).
    real(c_double) :: prefactor = 0.0_c_double
    !> Coefficient of determination r² of the weighted log–log fit.
    real(c_double) :: r_squared = 0.0_c_double
    !> χ²/ν of the fit.
    real(c_double) :: chi2_per_dof = 0.0_c_double
    !> Lowest wavenumber fitted (rad/m).
    real(c_double) :: q_min = 0.0_c_double
    !> Highest wavenumber fitted (rad/m).
    real(c_double) :: q_max = 0.0_c_double
    !> Shortest wavelength of the band, 2π/q_max (m).
    real(c_double) :: wavelength_min = 0.0_c_double
    !> Longest wavelength of the band, 2π/q_min (m).
    real(c_double) :: wavelength_max = 0.0_c_double
    !> Number of populated log bins fitted.
    integer(c_int64_t) :: bins = 0_c_int64_t
  end type asperity_hurst_estimate

  !> `AsperityPeakStatistics`
  type, bind(c), public :: asperity_peak_statistics
    !> Number of peaks found.
    integer(c_size_t) :: count = 0_c_size_t
    !> Peaks per metre of profile (1/m).
    real(c_double) :: density = 0.0_c_double
    !> Mean peak height above the mean line (m).
    real(c_double) :: mean_height = 0.0_c_double
    !> Standard deviation of the peak heights (m).
    real(c_double) :: height_std = 0.0_c_double
    !> Mean peak curvature (1/m); a mean radius is about 1/this.
    real(c_double) :: mean_curvature = 0.0_c_double
  end type asperity_peak_statistics


  ! ------------------------------------------------------------------------
  ! Handles of the opaque C objects.

  !> Handle of `AsperityTable`: a tabulated contact law (`asperity_table_new_*`, `asperity_table_from_json`).
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_table
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_table_free
    procedure, private :: asperity_table_assign
    generic :: assignment(=) => asperity_table_assign
    final :: asperity_table_final
  end type asperity_table

  !> Handle of `AsperityGwEmpirical`: a Greenwood-Williamson surface over listed summits (`asperity_gw_empirical_new`).
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_gw_empirical
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_gw_empirical_free
    procedure, private :: asperity_gw_empirical_assign
    generic :: assignment(=) => asperity_gw_empirical_assign
    final :: asperity_gw_empirical_final
  end type asperity_gw_empirical

  !> Handle of `AsperityBora`: the Bora et al. interface on a measured height map (`asperity_bora_new`).
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_bora
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_bora_free
    procedure, private :: asperity_bora_assign
    generic :: assignment(=) => asperity_bora_assign
    final :: asperity_bora_final
  end type asperity_bora

  !> Handle of `AsperityHomogenisedFriction`: the homogenised friction table of FE points (`asperity_homogenised_friction_new`, `..._from_json`), stepped through `asperity_friction_from_homogenised`.
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_homogenised_friction
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_homogenised_friction_free
    procedure, private :: asperity_homogenised_friction_assign
    generic :: assignment(=) => asperity_homogenised_friction_assign
    final :: asperity_homogenised_friction_final
  end type asperity_homogenised_friction

  !> Handle of `AsperitySliderGeometry`: the slider of the hierarchical friction model (`asperity_slider_geometry_new*`).
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_slider_geometry
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_slider_geometry_free
    procedure, private :: asperity_slider_geometry_assign
    generic :: assignment(=) => asperity_slider_geometry_assign
    final :: asperity_slider_geometry_final
  end type asperity_slider_geometry

  !> Handle of `AsperitySlider`: the hierarchical slider (`asperity_slider_new`, `asperity_slider_from_scene_json`), stepped as the friction law of a surface patch through `asperity_friction_from_slider`.
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_slider
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_slider_free
    procedure, private :: asperity_slider_assign
    generic :: assignment(=) => asperity_slider_assign
    final :: asperity_slider_final
  end type asperity_slider

  !> Handle of `AsperityFriction`: a friction law stepped once per increment, the homogenised
  !> law, the slider or a chapter-5 dynamic model (`asperity_friction_from_*`,
  !> `asperity_friction_*_new`).
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_friction
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_friction_free
    procedure, private :: asperity_friction_assign
    generic :: assignment(=) => asperity_friction_assign
    final :: asperity_friction_final
  end type asperity_friction

  !> Handle of `AsperityFrictionWork`: the scratch of a friction step, one per thread
  !> (`asperity_friction_work_new`).
  !> `ptr` is the C pointer (NULL when empty) for the raw layer.
  type, public :: asperity_friction_work
    type(c_ptr) :: ptr = c_null_ptr
  contains
    !> Release the object (nothing when empty); the handle becomes empty.
    procedure :: free => asperity_friction_work_free
    procedure, private :: asperity_friction_work_assign
    generic :: assignment(=) => asperity_friction_work_assign
    final :: asperity_friction_work_final
  end type asperity_friction_work

  abstract interface
    !> A summit density per unit depth n(xi) (1/m) at depth `xi` (m, >= 0)
    !> below the highest summit, for `asperity_zhuravlev_eval`; `user_data` is
    !> passed through. It must return a finite value >= 0.
    function asperity_summit_density(xi, user_data) result(density) bind(c)
      import :: c_double, c_ptr
      implicit none
      real(c_double), value :: xi
      type(c_ptr), value :: user_data
      real(c_double) :: density
    end function asperity_summit_density
  end interface
  public :: asperity_summit_density

  !> Release any handle: `call asperity_free(h)`.
  interface asperity_free
    module procedure asperity_table_free, asperity_gw_empirical_free, asperity_bora_free, &
        asperity_homogenised_friction_free, asperity_slider_geometry_free, asperity_slider_free, &
        asperity_friction_free, asperity_friction_work_free
  end interface asperity_free
  public :: asperity_free

  ! ------------------------------------------------------------------------
  ! The raw layer: the C functions as they are.

  interface
    !> The library version, "MAJOR.MINOR.PATCH", from `Cargo.toml`. Static storage; do not free.
    function c_asperity_version() result(r) bind(c, name="asperity_version")
      import
      implicit none
      type(c_ptr) :: r
    end function c_asperity_version

    !> Copy the message of the last failed call on this thread into `buf` (at most `len − 1`
    !  bytes plus a terminating NUL) and return the message's full length in bytes (without the
    !  NUL), so a caller can size a buffer with `asperity_last_error_message(NULL, 0)`.
    !  Successful calls leave the message unchanged; it is empty before the first failure.
    function c_asperity_last_error_message(buf, len) result(r) bind(c, &
        name="asperity_last_error_message")
      import
      implicit none
      type(c_ptr), value :: buf
      integer(c_size_t), value :: len
      integer(c_size_t) :: r
    end function c_asperity_last_error_message

    !> The size `*size` and alignment `*align` in bytes of the `repr(C)` type whose C name is
    !  the NUL-terminated `name` (e.g. `"AsperityNormalLaw"`; structs and unions of this header
    !  with a body, not the opaque handles). An unknown name gives
    !  `ASPERITY_ERR_INVALID_ARGUMENT` naming `name`; `asperity_type_count` and
    !  `asperity_type_name` list the known ones.
    function c_asperity_type_layout(name, size, align) result(r) bind(c, &
        name="asperity_type_layout")
      import
      implicit none
      character(kind=c_char), intent(in) :: name(*)
      integer(c_size_t), intent(out) :: size
      integer(c_size_t), intent(out) :: align
      integer(c_int32_t) :: r
    end function c_asperity_type_layout

    !> The number of types `asperity_type_layout` knows (indices `0 .. asperity_type_count()` of
    !  `asperity_type_name`).
    function c_asperity_type_count() result(r) bind(c, name="asperity_type_count")
      import
      implicit none
      integer(c_size_t) :: r
    end function c_asperity_type_count

    !> Copy the C name of type `index` (< `asperity_type_count()`) into `buf` (at most `len − 1`
    !  bytes and a NUL) and write its full length in bytes (without the NUL) to `*needed`, so
    !  `asperity_type_name(i, NULL, 0, &n)` sizes the buffer. The name is complete only when
    !  `*needed < len`; `needed` is required.
    function c_asperity_type_name(index, buf, len, needed) result(r) bind(c, &
        name="asperity_type_name")
      import
      implicit none
      integer(c_size_t), value :: index
      type(c_ptr), value :: buf
      integer(c_size_t), value :: len
      integer(c_size_t), intent(out) :: needed
      integer(c_int32_t) :: r
    end function c_asperity_type_name

    !> The law of kind `kind` (`ASPERITY_LAW_*`) from its inputs: the member of `params` that
    !  `kind` names, validated as by the kind's `asperity_law_*` constructor.
    function c_asperity_law_from_params(kind, params, out) result(r) bind(c, &
        name="asperity_law_from_params")
      import
      implicit none
      integer(c_int32_t), value :: kind
      type(asperity_law_params), intent(in) :: params
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_from_params

    !> Hertz sphere: radius R (m), contact modulus E* (Pa).
    function c_asperity_law_hertz(radius, e_star, out) result(r) bind(c, &
        name="asperity_law_hertz")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_hertz

    !> Galanov effective sphere: a sphere of radius `radius` (m) in a spherical crater (the
    !  deformed medium) of radius `medium_radius` (m, INFINITY for a flat), `1/R = 1/R_s −
    !  1/R_medium` (thesis (2-19), (3-23)).
    function c_asperity_law_sphere_in_crater(radius, medium_radius, e_star, out) result(r) &
        bind(c, name="asperity_law_sphere_in_crater")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: medium_radius
      real(c_double), value :: e_star
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_sphere_in_crater

    !> Galin power-law punch `f(r) = b r^d`: b (m^(1−d)), 1 ≤ d ≤ 100, E* (Pa).
    function c_asperity_law_power_punch(b, d, e_star, out) result(r) bind(c, &
        name="asperity_law_power_punch")
      import
      implicit none
      real(c_double), value :: b
      real(c_double), value :: d
      real(c_double), value :: e_star
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_power_punch

    !> Cone of half-angle `half_angle` (rad, in (0, π/2)); a power punch with d = 1, b =
    !  cot(half_angle).
    function c_asperity_law_cone(half_angle, e_star, out) result(r) bind(c, &
        name="asperity_law_cone")
      import
      implicit none
      real(c_double), value :: half_angle
      real(c_double), value :: e_star
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_cone

    !> Galanov effective cone: indenter half-angle γ_i in an imprint of half-angle γ_f > γ_i
    !  (rad), `b = cot γ_i − cot γ_f` (thesis (2-18)).
    function c_asperity_law_cone_in_imprint(indenter_half_angle, imprint_half_angle, e_star, &
        out) result(r) bind(c, name="asperity_law_cone_in_imprint")
      import
      implicit none
      real(c_double), value :: indenter_half_angle
      real(c_double), value :: imprint_half_angle
      real(c_double), value :: e_star
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_cone_in_imprint

    !> Frictionless flat punch of radius a (m): `P = 2E*aδ`.
    function c_asperity_law_flat_punch(radius, e_star, out) result(r) bind(c, &
        name="asperity_law_flat_punch")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_flat_punch

    !> Bonded (no-slip) flat punch: `P = 2E*aδ·C_NS(ν)`.
    function c_asperity_law_flat_punch_no_slip(radius, e_star, nu, out) result(r) bind(c, &
        name="asperity_law_flat_punch_no_slip")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: nu
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_flat_punch_no_slip

    !> DMT sphere: radius (m), E* (Pa), work of adhesion (J/m²).
    function c_asperity_law_dmt(radius, e_star, work_of_adhesion, out) result(r) bind(c, &
        name="asperity_law_dmt")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_dmt

    !> JKR sphere: radius (m), E* (Pa), work of adhesion (J/m²).
    function c_asperity_law_jkr(radius, e_star, work_of_adhesion, out) result(r) bind(c, &
        name="asperity_law_jkr")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_jkr

    !> JKR power-law punch (Borodich 2014): `f(r) = b r^d`, E* (Pa), work of adhesion (J/m²);
    !  `no_slip` = 1 for a punch bonded to a half-space of Poisson's ratio `nu` (thesis (1-39),
    !  (1-40)), 0 for frictionless (then `nu` is only range-checked).
    function c_asperity_law_jkr_power_punch(b, d, e_star, work_of_adhesion, nu, no_slip, &
        out) result(r) bind(c, name="asperity_law_jkr_power_punch")
      import
      implicit none
      real(c_double), value :: b
      real(c_double), value :: d
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: nu
      integer(c_int32_t), value :: no_slip
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_jkr_power_punch

    !> Kendall adhesive flat punch of radius a (m); `no_slip` = 1 for a bonded punch on a half-
    !  space of Poisson's ratio `nu`.
    function c_asperity_law_kendall(radius, e_star, work_of_adhesion, nu, no_slip, out) &
        result(r) bind(c, name="asperity_law_kendall")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: nu
      integer(c_int32_t), value :: no_slip
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_kendall

    !> Maugis–Dugdale sphere: radius (m), E* (Pa), work of adhesion (J/m²), Dugdale cohesive
    !  stress σ₀ (Pa).
    function c_asperity_law_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, out) &
        result(r) bind(c, name="asperity_law_maugis_dugdale")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: sigma0
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_maugis_dugdale

    !> Rigid sphere of radius (m) with a surface-force law between flats (Derjaguin
    !  approximation). `surface_law` is one of `ASPERITY_SURFACE_LAW_*` and `parameter` its
    !  second parameter: z₀ (m) for Lennard-Jones, σ₀ (Pa) for Dugdale, ℓ (m) for exponential.
    function c_asperity_law_derjaguin(radius, work_of_adhesion, surface_law, parameter, out) &
        result(r) bind(c, name="asperity_law_derjaguin")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: work_of_adhesion
      integer(c_int32_t), value :: surface_law
      real(c_double), value :: parameter
      type(asperity_normal_law), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_law_derjaguin

    !> Evaluate `law` at the overlap `delta` (m; > 0 penetration) from the history `old_state`,
    !  writing the history after the step to `new_state` and the response to `out`. `old_state`
    !  may be NULL (a fresh contact) and `new_state` NULL (history discarded); they may point to
    !  the same struct. `law` and `out` are required.
    function c_asperity_normal_eval(law, delta, old_state, new_state, out) result(r) bind(c, &
        name="asperity_normal_eval")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      real(c_double), value :: delta
      type(c_ptr), value :: old_state
      type(c_ptr), value :: new_state
      type(asperity_normal_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_normal_eval

    !> Evaluate `law` for `n` contacts: `delta[i]` (m), `old_state[i]` → `new_state[i]`, writing
    !  `force[i]` (N), `contact_radius[i]` (m) and `stiffness[i]` (N/m). `delta` and `force` are
    !  required; the other arrays may be NULL (fresh states / not wanted). Input and output
    !  arrays may be the same memory. On an error at element i, elements before i are written,
    !  the status is returned and the message names i.
    function c_asperity_normal_eval_batch(law, n, delta, old_state, new_state, force, &
        contact_radius, stiffness) result(r) bind(c, name="asperity_normal_eval_batch")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: delta(*)
      type(c_ptr), value :: old_state
      type(c_ptr), value :: new_state
      real(c_double), intent(inout) :: force(*)
      type(c_ptr), value :: contact_radius
      type(c_ptr), value :: stiffness
      integer(c_int32_t) :: r
    end function c_asperity_normal_eval_batch

    !> Equilibrium of `law` at the prescribed force `force` (N) on the stable branch (largest
    !  contact radius); `out->delta` is the overlap. `ASPERITY_ERR_OUT_OF_DOMAIN` below the
    !  load-controlled pull-off force.
    function c_asperity_normal_eval_at_load(law, force, out) result(r) bind(c, &
        name="asperity_normal_eval_at_load")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      real(c_double), value :: force
      type(asperity_normal_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_normal_eval_at_load

    !> The force (N, ≤ 0 for adhesive laws) at which the contact separates under `control`
    !  (`ASPERITY_CONTROL_LOAD` or `ASPERITY_CONTROL_DISPLACEMENT`).
    function c_asperity_pull_off_force(law, control, force) result(r) bind(c, &
        name="asperity_pull_off_force")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      integer(c_int32_t), value :: control
      real(c_double), intent(out) :: force
      integer(c_int32_t) :: r
    end function c_asperity_pull_off_force

    !> The reach of `law` under `control` (`ASPERITY_CONTROL_LOAD` or
    !  `ASPERITY_CONTROL_DISPLACEMENT`): the overlap δ_r (m, ≤ 0) below which the force is zero
    !  from any history, or below which |force| < `rel_force` × |load pull-off force| for laws
    !  with an infinite tail; `rel_force` finite and in (0, 1).
    function c_asperity_normal_reach(law, control, rel_force, delta) result(r) bind(c, &
        name="asperity_normal_reach")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      integer(c_int32_t), value :: control
      real(c_double), value :: rel_force
      real(c_double), intent(out) :: delta
      integer(c_int32_t) :: r
    end function c_asperity_normal_reach

    !> The energy (J) of the equilibrium of `law` at the overlap `delta` (m) reached from the
    !  history `old_state` (NULL: fresh), with dU/dδ = P along the branch; 0 when separated.
    function c_asperity_normal_energy(law, delta, old_state, energy) result(r) bind(c, &
        name="asperity_normal_energy")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      real(c_double), value :: delta
      type(c_ptr), value :: old_state
      real(c_double), intent(out) :: energy
      integer(c_int32_t) :: r
    end function c_asperity_normal_energy

    !> A characteristic overlap of `law` (m), for non-dimensionalising host-code tolerances.
    function c_asperity_law_length_scale(law, length) result(r) bind(c, &
        name="asperity_law_length_scale")
      import
      implicit none
      type(asperity_normal_law), intent(in) :: law
      real(c_double), intent(out) :: length
      integer(c_int32_t) :: r
    end function c_asperity_law_length_scale

    !> The cheapest adhesive-sphere model whose pull-off and force–approach errors against the
    !  converged Lennard-Jones sphere are within `force_tolerance` (N): radius R (m), contact
    !  modulus E* (Pa), work of adhesion w (J/m²), equilibrium separation z₀ (m). Runs the
    !  Lennard-Jones solver (milliseconds to seconds); not for a hot path.
    function c_asperity_fidelity_advise(radius, e_star, work_of_adhesion, z0, &
        force_tolerance, out) result(r) bind(c, name="asperity_fidelity_advise")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: z0
      real(c_double), value :: force_tolerance
      type(asperity_fidelity_advice), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_fidelity_advise

    !> Build a slider from two measured profiles, heights from their mean lines (remove form
    !  first): `micro_n` heights (m) of a profilometer profile sampled at `micro_dx` (m), cut
    !  into rods by thesis (6-1), and `nano_n` heights (m) of an AFM profile sampled at
    !  `nano_dx` (m), giving the nano-asperities (5-15, 6-2, 6-3). `rod_widths` holds `n_levels`
    !  rod widths (m), coarsest first, each the previous divided by an integer >= 2 (nested
    !  levels); one level is `n_levels` = 1. Writes a new handle to `*out` (NULL on failure).
    !  Errors: NULL pointers, fewer than 8 heights, non-finite values, widths that are not
    !  positive, wider than the micro profile or do not nest, constant profiles, finest rods
    !  narrower than the nano-asperity spacing.
    function c_asperity_slider_geometry_new(micro_heights, micro_n, micro_dx, nano_heights, &
        nano_n, nano_dx, rod_widths, n_levels, out) result(r) bind(c, &
        name="asperity_slider_geometry_new")
      import
      implicit none
      real(c_double), intent(in) :: micro_heights(*)
      integer(c_size_t), value :: micro_n
      real(c_double), value :: micro_dx
      real(c_double), intent(in) :: nano_heights(*)
      integer(c_size_t), value :: nano_n
      real(c_double), value :: nano_dx
      real(c_double), intent(in) :: rod_widths(*)
      integer(c_size_t), value :: n_levels
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_new

    !> Build a single-level slider from numbers: `rods` flat rods of `rod_width` (m) at height
    !  0, carrying `nano->per_rod` nano-asperities each with the parameters `*nano` (the hand
    !  calculation of thesis 4.4: one 13.5 µm rod, 100 nano-asperities, w_vdW = 430 nm, w_chem =
    !  161 nm). Writes a new handle to `*out` (NULL on failure).
    function c_asperity_slider_geometry_new_uniform(rod_width, rods, nano, out) result(r) &
        bind(c, name="asperity_slider_geometry_new_uniform")
      import
      implicit none
      real(c_double), value :: rod_width
      integer(c_size_t), value :: rods
      type(asperity_nano_asperities), intent(in) :: nano
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_new_uniform

    !> Release a geometry; NULL is accepted and ignored.
    subroutine c_asperity_slider_geometry_free(geometry) bind(c, &
        name="asperity_slider_geometry_free")
      import
      implicit none
      type(c_ptr), value :: geometry
    end subroutine c_asperity_slider_geometry_free

    !> The nano-asperity parameters of `geometry` and their number per rod tip.
    function c_asperity_slider_geometry_nano(geometry, out) result(r) bind(c, &
        name="asperity_slider_geometry_nano")
      import
      implicit none
      type(c_ptr), value :: geometry
      type(asperity_nano_asperities), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_nano

    !> The number of rod levels of `geometry` (>= 1; level 0 is the coarsest, the last carries
    !  the nano-asperities).
    function c_asperity_slider_geometry_level_count(geometry, count) result(r) bind(c, &
        name="asperity_slider_geometry_level_count")
      import
      implicit none
      type(c_ptr), value :: geometry
      integer(c_size_t), intent(out) :: count
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_level_count

    !> The number of rods of `level` (0 = coarsest).
    function c_asperity_slider_geometry_rod_count(geometry, level, count) result(r) bind(c, &
        name="asperity_slider_geometry_rod_count")
      import
      implicit none
      type(c_ptr), value :: geometry
      integer(c_size_t), value :: level
      integer(c_size_t), intent(out) :: count
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_rod_count

    !> The rod width (m) of `level` and, if `origin` is not NULL, the position of the left side
    !  of its rod 0 (m); rod k spans [origin + k*width, origin + (k+1)*width].
    function c_asperity_slider_geometry_rod_width(geometry, level, width, origin) result(r) &
        bind(c, name="asperity_slider_geometry_rod_width")
      import
      implicit none
      type(c_ptr), value :: geometry
      integer(c_size_t), value :: level
      real(c_double), intent(out) :: width
      type(c_ptr), value :: origin
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_rod_width

    !> Copy the rod heights (m, from the micro profile's mean line, thesis 6-1) of `level` into
    !  `heights`, which holds `len` values; `len` must be at least the level's rod count
    !  (`asperity_slider_geometry_rod_count`).
    function c_asperity_slider_geometry_rod_heights(geometry, level, heights, len) result(r) &
        bind(c, name="asperity_slider_geometry_rod_heights")
      import
      implicit none
      type(c_ptr), value :: geometry
      integer(c_size_t), value :: level
      real(c_double), intent(inout) :: heights(*)
      integer(c_size_t), value :: len
      integer(c_int32_t) :: r
    end function c_asperity_slider_geometry_rod_heights

    !> Build the law from `n` >= 1 samples at strictly increasing nominal pressures (Pa), their
    !  `cof` read as the Derjaguin coefficient F/(N + A) (thesis (4-3); other forms through
    !  JSON). Writes a new handle to `*out` (NULL on failure). Errors: NULL `samples` or `out`,
    !  `n` = 0, non-finite or negative values, fractions outside [0, 1], shares not summing to
    !  1, pressures not increasing.
    function c_asperity_homogenised_friction_new(samples, n, out) result(r) bind(c, &
        name="asperity_homogenised_friction_new")
      import
      implicit none
      type(asperity_homogenised_sample), intent(in) :: samples(*)
      integer(c_size_t), value :: n
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_homogenised_friction_new

    !> Load a law from `len` bytes of JSON text at `json` (from
    !  `asperity_homogenised_friction_to_json`, or written by hand; no NUL needed). The law is
    !  validated; a corrupted text gives `ASPERITY_ERR_INVALID_ARGUMENT`. Writes a new handle to
    !  `*out` (NULL on failure).
    function c_asperity_homogenised_friction_from_json(json, len, out) result(r) bind(c, &
        name="asperity_homogenised_friction_from_json")
      import
      implicit none
      character(kind=c_char), intent(in) :: json(*)
      integer(c_size_t), value :: len
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_homogenised_friction_from_json

    !> Write the JSON text of `friction` into `buf` (at most `len − 1` bytes and a NUL) and its
    !  full length in bytes (without the NUL) to `*needed`, so
    !  `asperity_homogenised_friction_to_json(f, NULL, 0, &n)` sizes the buffer. The text is
    !  complete only when `*needed < len`; `needed` is required.
    function c_asperity_homogenised_friction_to_json(friction, buf, len, needed) result(r) &
        bind(c, name="asperity_homogenised_friction_to_json")
      import
      implicit none
      type(c_ptr), value :: friction
      type(c_ptr), value :: buf
      integer(c_size_t), value :: len
      integer(c_size_t), intent(out) :: needed
      integer(c_int32_t) :: r
    end function c_asperity_homogenised_friction_to_json

    !> Release a law; NULL is accepted and ignored.
    subroutine c_asperity_homogenised_friction_free(friction) bind(c, &
        name="asperity_homogenised_friction_free")
      import
      implicit none
      type(c_ptr), value :: friction
    end subroutine c_asperity_homogenised_friction_free

    !> Fill `options` with the defaults: Berkovich, ideal area, anchor at the maximum point,
    !  labels used, diamond indenter (1141 GPa, 0.07), sample ν = 0.3, β by indenter, ε = 0.75,
    !  windows 0.1–1 (loading) and 0.2–0.98 (unloading).
    function c_asperity_indentation_default_options(options) result(r) bind(c, &
        name="asperity_indentation_default_options")
      import
      implicit none
      type(asperity_indentation_options), intent(inout) :: options
      integer(c_int32_t) :: r
    end function c_asperity_indentation_default_options

    !> Fit a measured load–depth curve: `n` points of `depth` (m) and `load` (N), optional
    !  `segments` (`ASPERITY_SEGMENT_*` per point, NULL to detect them), `options` (NULL for the
    !  defaults). Writes κ, d with standard errors, the Oliver–Pharr modulus and hardness and
    !  the validity flags into `result` (see `indentation::analyze`). Errors: NULL pointers, n <
    !  3, non-finite values, unknown labels or selectors, no loading branch, d or κ not
    !  identifiable (`ASPERITY_ERR_OUT_OF_DOMAIN`, with a message).
    function c_asperity_indentation_fit(n, depth, load, segments, options, result) result(r) &
        bind(c, name="asperity_indentation_fit")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: depth(*)
      real(c_double), intent(in) :: load(*)
      type(c_ptr), value :: segments
      type(c_ptr), value :: options
      type(asperity_indentation_result), intent(inout) :: result
      integer(c_int32_t) :: r
    end function c_asperity_indentation_fit

    !> The code of flag bit `bit` (0-based, e.g. `"kappa_above_one"` for bit 1) as a static NUL-
    !  terminated string; NULL for a bit without a flag. Do not free.
    function c_asperity_indentation_flag_name(bit) result(r) bind(c, &
        name="asperity_indentation_flag_name")
      import
      implicit none
      integer(c_int32_t), value :: bit
      type(c_ptr) :: r
    end function c_asperity_indentation_flag_name

    !> Analyse an AFM force–distance curve of `n` points: `position` (m), `signal` (force N or
    !  deflection m, as `input_kind` says), approach first and retract from `retract_start` (0:
    !  the turning point); `spring_constant` (N/m), `tip_radius` (m, 0 = unknown), `model`
    !  (`ASPERITY_AFM_MODEL_*`). See `afm::analyze`.
    function c_asperity_afm_analyze(n, position, signal, input_kind, retract_start, &
        spring_constant, tip_radius, model, result) result(r) bind(c, name="asperity_afm_analyze")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: position(*)
      real(c_double), intent(in) :: signal(*)
      integer(c_int32_t), value :: input_kind
      integer(c_size_t), value :: retract_start
      real(c_double), value :: spring_constant
      real(c_double), value :: tip_radius
      integer(c_int32_t), value :: model
      type(asperity_afm_result), intent(inout) :: result
      integer(c_int32_t) :: r
    end function c_asperity_afm_analyze

    !> The code of AFM flag bit `bit` (0-based) as a static NUL-terminated string; NULL for a
    !  bit without a flag. Do not free.
    function c_asperity_afm_flag_name(bit) result(r) bind(c, name="asperity_afm_flag_name")
      import
      implicit none
      integer(c_int32_t), value :: bit
      type(c_ptr) :: r
    end function c_asperity_afm_flag_name

    !> Depth (m) at load `load` (N) by Borodich rescaling (3-13): `δ = λ^{(2−κ)/s} (P/P₁)^{d/s}
    !  δ₁`, `s = 2 + κ(d − 1)`, from the known point (P₁, δ₁); λ = B/B₁ (spheres R₁/R, cones tan
    !  γ₁/tan γ).
    function c_asperity_rescaling_depth(kappa, d, lambda, load, known_load, known_depth, &
        depth) result(r) bind(c, name="asperity_rescaling_depth")
      import
      implicit none
      real(c_double), value :: kappa
      real(c_double), value :: d
      real(c_double), value :: lambda
      real(c_double), value :: load
      real(c_double), value :: known_load
      real(c_double), value :: known_depth
      real(c_double), intent(out) :: depth
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_depth

    !> Contact radius (m) at load `load` (N) by rescaling (3-14): `a = λ^{−κ/s} (P/P₁)^{1/s}
    !  a₁`.
    function c_asperity_rescaling_radius(kappa, d, lambda, load, known_load, known_radius, &
        radius) result(r) bind(c, name="asperity_rescaling_radius")
      import
      implicit none
      real(c_double), value :: kappa
      real(c_double), value :: d
      real(c_double), value :: lambda
      real(c_double), value :: load
      real(c_double), value :: known_load
      real(c_double), value :: known_radius
      real(c_double), intent(out) :: radius
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_radius

    !> Load (N) at depth `depth` (m) by rescaling (3-24): `P = λ^{(κ−2)/d} (δ/δ₁)^{s/d} P₁`.
    function c_asperity_rescaling_load(kappa, d, lambda, depth, known_load, known_depth, &
        load) result(r) bind(c, name="asperity_rescaling_load")
      import
      implicit none
      real(c_double), value :: kappa
      real(c_double), value :: d
      real(c_double), value :: lambda
      real(c_double), value :: depth
      real(c_double), value :: known_load
      real(c_double), value :: known_depth
      real(c_double), intent(out) :: load
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_load

    !> λ for spheres, `R₁/R` (3-15).
    function c_asperity_rescaling_lambda_spheres(known_radius, radius, lambda) result(r) &
        bind(c, name="asperity_rescaling_lambda_spheres")
      import
      implicit none
      real(c_double), value :: known_radius
      real(c_double), value :: radius
      real(c_double), intent(out) :: lambda
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_lambda_spheres

    !> λ for cones, `tan γ₁/tan γ` (3-16), half-angles in rad.
    function c_asperity_rescaling_lambda_cones(known_half_angle, half_angle, lambda) &
        result(r) bind(c, name="asperity_rescaling_lambda_cones")
      import
      implicit none
      real(c_double), value :: known_half_angle
      real(c_double), value :: half_angle
      real(c_double), intent(out) :: lambda
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_lambda_cones

    !> κ from the loading log–log slope and d: `κ = (d m_l − 2)/(d − 1)` ((3-20), (3-26)); out
    !  of domain for a cone (d = 1).
    function c_asperity_rescaling_kappa_from_slope(loading_slope, d, kappa) result(r) &
        bind(c, name="asperity_rescaling_kappa_from_slope")
      import
      implicit none
      real(c_double), value :: loading_slope
      real(c_double), value :: d
      real(c_double), intent(out) :: kappa
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_kappa_from_slope

    !> d from the elastic unloading slope: `d = 1/(m_u − 1)`, m_u > 1.
    function c_asperity_rescaling_d_from_unloading_slope(unloading_slope, d) result(r) &
        bind(c, name="asperity_rescaling_d_from_unloading_slope")
      import
      implicit none
      real(c_double), value :: unloading_slope
      real(c_double), intent(out) :: d
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_d_from_unloading_slope

    !> d from the loading slope and a known κ: `d = (2 − κ)/(m_l − κ)`.
    function c_asperity_rescaling_d_from_loading_slope(loading_slope, kappa, d) result(r) &
        bind(c, name="asperity_rescaling_d_from_loading_slope")
      import
      implicit none
      real(c_double), value :: loading_slope
      real(c_double), value :: kappa
      real(c_double), intent(out) :: d
      integer(c_int32_t) :: r
    end function c_asperity_rescaling_d_from_loading_slope

    !> Galanov effective unloading radius (3-22): `R₂ = R₁ (P₂/P₁)² (δ₁/δ₂)³`.
    function c_asperity_galanov_unloading_radius(r1, p1, delta1, p2, delta2, r2) result(r) &
        bind(c, name="asperity_galanov_unloading_radius")
      import
      implicit none
      real(c_double), value :: r1
      real(c_double), value :: p1
      real(c_double), value :: delta1
      real(c_double), value :: p2
      real(c_double), value :: delta2
      real(c_double), intent(out) :: r2
      integer(c_int32_t) :: r
    end function c_asperity_galanov_unloading_radius

    !> Radius of the deformed medium (3-23): `R_medium = R R₂/(R₂ − R)`, R₂ > R.
    function c_asperity_galanov_medium_radius(radius, unloading_radius, medium_radius) &
        result(r) bind(c, name="asperity_galanov_medium_radius")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: unloading_radius
      real(c_double), intent(out) :: medium_radius
      integer(c_int32_t) :: r
    end function c_asperity_galanov_medium_radius

    !> Brinell hardness (2-7), `2P/(πD(D − √(D² − d²)))` (Pa).
    function c_asperity_hardness_brinell(load, ball_diameter, imprint_diameter, hardness) &
        result(r) bind(c, name="asperity_hardness_brinell")
      import
      implicit none
      real(c_double), value :: load
      real(c_double), value :: ball_diameter
      real(c_double), value :: imprint_diameter
      real(c_double), intent(out) :: hardness
      integer(c_int32_t) :: r
    end function c_asperity_hardness_brinell

    !> Meyer hardness (2-8), `4P/(πd²)` (Pa).
    function c_asperity_hardness_meyer(load, imprint_diameter, hardness) result(r) bind(c, &
        name="asperity_hardness_meyer")
      import
      implicit none
      real(c_double), value :: load
      real(c_double), value :: imprint_diameter
      real(c_double), intent(out) :: hardness
      integer(c_int32_t) :: r
    end function c_asperity_hardness_meyer

    !> Ludwik hardness (2-10), `4P/(√2 π d²)` (Pa).
    function c_asperity_hardness_ludwik(load, imprint_diameter, hardness) result(r) bind(c, &
        name="asperity_hardness_ludwik")
      import
      implicit none
      real(c_double), value :: load
      real(c_double), value :: imprint_diameter
      real(c_double), intent(out) :: hardness
      integer(c_int32_t) :: r
    end function c_asperity_hardness_ludwik

    !> Vickers hardness (2-12), `2P sin 68°/d²` (Pa), mean diagonal d.
    function c_asperity_hardness_vickers(load, mean_diagonal, hardness) result(r) bind(c, &
        name="asperity_hardness_vickers")
      import
      implicit none
      real(c_double), value :: load
      real(c_double), value :: mean_diagonal
      real(c_double), intent(out) :: hardness
      integer(c_int32_t) :: r
    end function c_asperity_hardness_vickers

    !> Load-controlled pull-off force (N, negative: tensile) of an elastic sphere of radius
    !  `radius` (m) and contact modulus `e_star` (Pa) under the Lennard-Jones 3-9 surface law
    !  with work of adhesion `work_of_adhesion` (J/m²) and equilibrium separation `z0` (m), from
    !  the full numerical solution on `n_grid` radial cells (0 = the library's converged
    !  default). Writes `*force`; returns `ASPERITY_ERR_NOT_CONVERGED` when the solver does not
    !  converge or the grid does not resolve the edge zone.
    function c_asperity_lj_sphere_pull_off(radius, e_star, work_of_adhesion, z0, n_grid, &
        force) result(r) bind(c, name="asperity_lj_sphere_pull_off")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: z0
      integer(c_size_t), value :: n_grid
      real(c_double), intent(out) :: force
      integer(c_int32_t) :: r
    end function c_asperity_lj_sphere_pull_off

    !> Contact modulus `1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂` (Pa). `E = INFINITY` marks a rigid body.
    !  See `material::effective_modulus`.
    function c_asperity_effective_modulus(e1, nu1, e2, nu2, e_star) result(r) bind(c, &
        name="asperity_effective_modulus")
      import
      implicit none
      real(c_double), value :: e1
      real(c_double), value :: nu1
      real(c_double), value :: e2
      real(c_double), value :: nu2
      real(c_double), intent(out) :: e_star
      integer(c_int32_t) :: r
    end function c_asperity_effective_modulus

    !> Effective modulus of two rods end to end, `1/E = 1/E₁ + 1/E₂` (Pa), thesis (6-8).
    function c_asperity_rod_effective_modulus(e1, e2, e_eff) result(r) bind(c, &
        name="asperity_rod_effective_modulus")
      import
      implicit none
      real(c_double), value :: e1
      real(c_double), value :: e2
      real(c_double), intent(out) :: e_eff
      integer(c_int32_t) :: r
    end function c_asperity_rod_effective_modulus

    !> No-slip factor `C_NS = (1−ν) ln(3−4ν)/(1−2ν)`, continuous to 1 at ν = 1/2.
    function c_asperity_no_slip_factor(nu, c_ns) result(r) bind(c, &
        name="asperity_no_slip_factor")
      import
      implicit none
      real(c_double), value :: nu
      real(c_double), intent(out) :: c_ns
      integer(c_int32_t) :: r
    end function c_asperity_no_slip_factor

    !> Tabor parameter `μ = (R w²/(E*² z₀³))^{1/3}`.
    function c_asperity_tabor_parameter(radius, work_of_adhesion, e_star, &
        equilibrium_separation, mu) result(r) bind(c, name="asperity_tabor_parameter")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: e_star
      real(c_double), value :: equilibrium_separation
      real(c_double), intent(out) :: mu
      integer(c_int32_t) :: r
    end function c_asperity_tabor_parameter

    !> Maugis parameter `λ = 2σ₀ (R/(π w K²))^{1/3}`, `K = 4E*/3`.
    function c_asperity_maugis_parameter(radius, work_of_adhesion, e_star, cohesive_stress, &
        lambda) result(r) bind(c, name="asperity_maugis_parameter")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: e_star
      real(c_double), value :: cohesive_stress
      real(c_double), intent(out) :: lambda
      integer(c_int32_t) :: r
    end function c_asperity_maugis_parameter

    !> Weir's surface energy `γ = a·B/((m−2)(n−2))` (J/m²), `a = (M/ρ)^{1/3}`, `B =
    !  E/(3(1−2ν))`: `atomic_mass` in kg per atom, `density` kg/m³, `youngs_modulus` Pa,
    !  `poisson_ratio` in [0, 0.5), exponents 2 < m < n.
    function c_asperity_weir_surface_energy(atomic_mass, density, youngs_modulus, &
        poisson_ratio, m, n, gamma) result(r) bind(c, &
        name="asperity_weir_surface_energy")
      import
      implicit none
      real(c_double), value :: atomic_mass
      real(c_double), value :: density
      real(c_double), value :: youngs_modulus
      real(c_double), value :: poisson_ratio
      real(c_double), value :: m
      real(c_double), value :: n
      real(c_double), intent(out) :: gamma
      integer(c_int32_t) :: r
    end function c_asperity_weir_surface_energy

    !> [`asperity_weir_surface_energy`] with the prefactor chosen by `prefactor`
    !  (`ASPERITY_WEIR_PLANE_SUM` or `ASPERITY_WEIR_THREE_OVER_MN`).
    function c_asperity_weir_surface_energy_with(atomic_mass, density, youngs_modulus, &
        poisson_ratio, m, n, prefactor, gamma) result(r) bind(c, &
        name="asperity_weir_surface_energy_with")
      import
      implicit none
      real(c_double), value :: atomic_mass
      real(c_double), value :: density
      real(c_double), value :: youngs_modulus
      real(c_double), value :: poisson_ratio
      real(c_double), value :: m
      real(c_double), value :: n
      integer(c_int32_t), value :: prefactor
      real(c_double), intent(out) :: gamma
      integer(c_int32_t) :: r
    end function c_asperity_weir_surface_energy_with

    !> Work of adhesion (J/m²) of a pair of surface energies (J/m²) under `rule`
    !  (`ASPERITY_PAIR_GEOMETRIC_MEAN` or `ASPERITY_PAIR_SEED001_DIFFERENCE`).
    function c_asperity_pair_work_of_adhesion(gamma1, gamma2, rule, work_of_adhesion) &
        result(r) bind(c, name="asperity_pair_work_of_adhesion")
      import
      implicit none
      real(c_double), value :: gamma1
      real(c_double), value :: gamma2
      integer(c_int32_t), value :: rule
      real(c_double), intent(out) :: work_of_adhesion
      integer(c_int32_t) :: r
    end function c_asperity_pair_work_of_adhesion

    !> Work of adhesion `A/(12πD₀²)` (J/m²) from a Hamaker constant (J) and a separation D₀ (m).
    function c_asperity_hamaker_work_of_adhesion(hamaker, separation, work_of_adhesion) &
        result(r) bind(c, name="asperity_hamaker_work_of_adhesion")
      import
      implicit none
      real(c_double), value :: hamaker
      real(c_double), value :: separation
      real(c_double), intent(out) :: work_of_adhesion
      integer(c_int32_t) :: r
    end function c_asperity_hamaker_work_of_adhesion

    !> The homogenised law of `table` with the stick stiffness `stick_stiffness` (N/m, finite
    !  and >= 0; 0: rigid-plastic) of its regularised stick. The law copies the table. Writes a
    !  new handle to `*out` (NULL on failure).
    function c_asperity_friction_from_homogenised(table, stick_stiffness, out) result(r) &
        bind(c, name="asperity_friction_from_homogenised")
      import
      implicit none
      type(c_ptr), value :: table
      real(c_double), value :: stick_stiffness
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_from_homogenised

    !> The hierarchical slider as the friction law of a surface patch (the increment's normal
    !  force is the fixed load, at most the slider's capacity; its area is unused). The law
    !  copies the slider. Writes a new handle to `*out` (NULL on failure).
    function c_asperity_friction_from_slider(slider, out) result(r) &
        bind(c, name="asperity_friction_from_slider")
      import
      implicit none
      type(c_ptr), value :: slider
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_from_slider

    !> Build a LuGre model from `*params`. Writes a new handle to `*out` (NULL on failure).
    function c_asperity_friction_lugre_new(params, out) result(r) &
        bind(c, name="asperity_friction_lugre_new")
      import
      implicit none
      type(asperity_lugre_params), intent(in) :: params
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_lugre_new

    !> Build `n` >= 1 bristles (Haessig-Friedland). Writes a new handle to `*out`.
    function c_asperity_friction_bristles_new(stiffness, break_deflection, n, sigma2, out) &
        result(r) bind(c, name="asperity_friction_bristles_new")
      import
      implicit none
      real(c_double), intent(in) :: stiffness(*)
      real(c_double), intent(in) :: break_deflection(*)
      integer(c_size_t), value :: n
      real(c_double), value :: sigma2
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_bristles_new

    !> Build `n` >= 1 Maxwell-slip elements in parallel. Writes a new handle to `*out`.
    function c_asperity_friction_maxwell_slip_new(stiffness, capacity, n, sigma2, out) &
        result(r) bind(c, name="asperity_friction_maxwell_slip_new")
      import
      implicit none
      real(c_double), intent(in) :: stiffness(*)
      real(c_double), intent(in) :: capacity(*)
      integer(c_size_t), value :: n
      real(c_double), value :: sigma2
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_maxwell_slip_new

    !> Build the generalised Maxwell-slip model (`n` >= 1 elements). Writes a new handle to `*out`.
    function c_asperity_friction_generalized_maxwell_slip_new(stiffness, weight, n, params, out) &
        result(r) bind(c, name="asperity_friction_generalized_maxwell_slip_new")
      import
      implicit none
      real(c_double), intent(in) :: stiffness(*)
      real(c_double), intent(in) :: weight(*)
      integer(c_size_t), value :: n
      type(asperity_generalized_maxwell_slip_params), intent(in) :: params
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_generalized_maxwell_slip_new

    !> The exponent of Archard's A ~ W^a for `model` and `generations` radii.
    function c_asperity_archard_exponent(model, generations, out) &
        result(r) bind(c, name="asperity_archard_exponent")
      import
      implicit none
      integer(c_int32_t), value :: model
      integer(c_size_t), value :: generations
      real(c_double), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_archard_exponent

    !> Archard's real contact areas (m^2) under `n` loads (N).
    function c_asperity_archard_area_batch(model, radii, densities, generations, &
        contact_modulus, n, load, area) result(r) bind(c, name="asperity_archard_area_batch")
      import
      implicit none
      integer(c_int32_t), value :: model
      real(c_double), intent(in) :: radii(*)
      real(c_double), intent(in) :: densities(*)
      integer(c_size_t), value :: generations
      real(c_double), value :: contact_modulus
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: load(*)
      real(c_double), intent(inout) :: area(*)
      integer(c_int32_t) :: r
    end function c_asperity_archard_area_batch

    !> The contact of a Cantor profile at `n` depths (m).
    function c_asperity_cantor_contact_batch(profile, stiffness, hardness, n, depth, out) &
        result(r) bind(c, name="asperity_cantor_contact_batch")
      import
      implicit none
      type(asperity_cantor_profile), intent(in) :: profile
      real(c_double), value :: stiffness
      real(c_double), value :: hardness
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: depth(*)
      type(asperity_cantor_contact), intent(inout) :: out(*)
      integer(c_int32_t) :: r
    end function c_asperity_cantor_contact_batch

    !> A Cantor profile's fractal dimension and contact exponents (outputs may be NULL).
    function c_asperity_cantor_exponents(profile, fractal_dimension, width_exponent, &
        load_area_exponent) result(r) bind(c, name="asperity_cantor_exponents")
      import
      implicit none
      type(asperity_cantor_profile), intent(in) :: profile
      real(c_double), intent(out) :: fractal_dimension
      real(c_double), intent(out) :: width_exponent
      real(c_double), intent(out) :: load_area_exponent
      integer(c_int32_t) :: r
    end function c_asperity_cantor_exponents

    !> The renormalised friction laws of generations 0..G of `model` into `out` (room for
    !  `capacity`); the number written to `written` unless NULL.
    function c_asperity_schmittbuhl_run(model, capacity, out, written) result(r) bind(c, &
        name="asperity_schmittbuhl_run")
      import
      implicit none
      type(asperity_schmittbuhl), intent(in) :: model
      integer(c_size_t), value :: capacity
      type(asperity_schmittbuhl_generation), intent(inout) :: out(*)
      integer(c_size_t), intent(inout) :: written
      integer(c_int32_t) :: r
    end function c_asperity_schmittbuhl_run

    !> The library's default Schmittbuhl model.
    function c_asperity_schmittbuhl_default(out) result(r) bind(c, &
        name="asperity_schmittbuhl_default")
      import
      implicit none
      type(asperity_schmittbuhl), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_schmittbuhl_default

    !> The layers' elastic normal force (N) of a Borodich-Kryukova slider at `x` (m), `y` (m),
    !  `time` (s).
    function c_asperity_borodich_kryukova_normal_force(bk, x, y, time, out) result(r) bind(c, &
        name="asperity_borodich_kryukova_normal_force")
      import
      implicit none
      type(asperity_borodich_kryukova), intent(in) :: bk
      real(c_double), value :: x
      real(c_double), value :: y
      real(c_double), value :: time
      real(c_double), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_borodich_kryukova_normal_force

    !> Runge-Kutta 4 of a Borodich-Kryukova slider from `start`: steps/every + 1 samples into
    !  `samples` (room for `capacity`); the number written to `written` unless NULL.
    function c_asperity_borodich_kryukova_run(bk, start, dt, steps, every, capacity, samples, &
        written) result(r) bind(c, name="asperity_borodich_kryukova_run")
      import
      implicit none
      type(asperity_borodich_kryukova), intent(in) :: bk
      type(asperity_borodich_kryukova_state), intent(in) :: start
      real(c_double), value :: dt
      integer(c_int32_t), value :: steps
      integer(c_int32_t), value :: every
      integer(c_size_t), value :: capacity
      type(asperity_borodich_kryukova_sample), intent(inout) :: samples(*)
      integer(c_size_t), intent(inout) :: written
      integer(c_int32_t) :: r
    end function c_asperity_borodich_kryukova_run

    !> Build a Prandtl-Tomlinson tip (one-dimensional). Writes a new handle to `*out`.
    function c_asperity_friction_prandtl_tomlinson_new(amplitude, period, stiffness, mass, &
        damping, tolerance, out) result(r) bind(c, name="asperity_friction_prandtl_tomlinson_new")
      import
      implicit none
      real(c_double), value :: amplitude
      real(c_double), value :: period
      real(c_double), value :: stiffness
      real(c_double), value :: mass
      real(c_double), value :: damping
      real(c_double), value :: tolerance
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_prandtl_tomlinson_new

    !> Build a two-spring (tip-cantilever) Prandtl-Tomlinson model from `*params`.
    function c_asperity_friction_prandtl_tomlinson_two_spring_new(params, out) result(r) &
        bind(c, name="asperity_friction_prandtl_tomlinson_two_spring_new")
      import
      implicit none
      type(asperity_prandtl_tomlinson_two_spring_params), intent(in) :: params
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_prandtl_tomlinson_two_spring_new

    !> Build a Burridge-Knopoff block chain from `*params`.
    function c_asperity_friction_burridge_knopoff_new(params, out) result(r) &
        bind(c, name="asperity_friction_burridge_knopoff_new")
      import
      implicit none
      type(asperity_burridge_knopoff_params), intent(in) :: params
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_burridge_knopoff_new

    !> Release a law; NULL is accepted and ignored.
    subroutine c_asperity_friction_free(law) bind(c, name="asperity_friction_free")
      import
      implicit none
      type(c_ptr), value :: law
    end subroutine c_asperity_friction_free

    !> Write the number of doubles of one point's state to `*n` (homogenised: 9; slider:
    !  9 + 2 x rods; LuGre: 4; Maxwell-slip: 2 + 2 x elements; bristles: 2 + bristles;
    !  Prandtl-Tomlinson: 5, with two springs 7; Burridge-Knopoff: 3 + 2 x blocks).
    function c_asperity_friction_state_size(law, n) result(r) &
        bind(c, name="asperity_friction_state_size")
      import
      implicit none
      type(c_ptr), value :: law
      integer(c_size_t), intent(out) :: n
      integer(c_int32_t) :: r
    end function c_asperity_friction_state_size

    !> Build the scratch of a step with `law` and write the handle to `*out` (NULL on failure).
    !  Use one per thread; a scratch made for another law is rebuilt on first use.
    function c_asperity_friction_work_new(law, out) result(r) &
        bind(c, name="asperity_friction_work_new")
      import
      implicit none
      type(c_ptr), value :: law
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_work_new

    !> Release a scratch; NULL is accepted and ignored.
    subroutine c_asperity_friction_work_free(work) bind(c, name="asperity_friction_work_free")
      import
      implicit none
      type(c_ptr), value :: work
    end subroutine c_asperity_friction_work_free

    !> One increment of one point: `*increment` from the state `old_state`
    !  (`asperity_friction_state_size` doubles; all-zero = fresh) into `new_state` (same size;
    !  may equal `old_state`, must not partially overlap it) and the response into `*out`. The
    !  same old state and increment give bit-identical results (cut-backs). `work` may be NULL.
    !  On failure `new_state` and `*out` are untouched. The states are addresses (`c_loc`), so
    !  that one array may be passed as both.
    function c_asperity_friction_step(law, increment, old_state, new_state, work, out) &
        result(r) bind(c, name="asperity_friction_step")
      import
      implicit none
      type(c_ptr), value :: law
      type(asperity_friction_increment), intent(in) :: increment
      type(c_ptr), value :: old_state
      type(c_ptr), value :: new_state
      type(c_ptr), value :: work
      type(asperity_friction_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_step

    !> `asperity_friction_step` with the state `state` updated in place (on failure it is
    !  untouched).
    function c_asperity_friction_step_in_place(law, increment, state, work, out) result(r) &
        bind(c, name="asperity_friction_step_in_place")
      import
      implicit none
      type(c_ptr), value :: law
      type(asperity_friction_increment), intent(in) :: increment
      real(c_double), intent(inout) :: state(*)
      type(c_ptr), value :: work
      type(asperity_friction_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_step_in_place

    !> Step `n` points at once, in the shape of Abaqus/Explicit VFRIC: normal forces
    !  `normal_forces[i]` (N), nominal areas `areas[i]` (m^2; NULL: 0 for every point, refused
    !  by laws that need them), slip increments `slip_increments[2i]`, `[2i+1]` (m,
    !  interleaved), one `dt` (s), the states `old_states[i*m .. (i+1)*m]` -> `new_states[...]`
    !  (m = `asperity_friction_state_size`; `new_states` may equal `old_states`, must not
    !  partially overlap it), tangential forces out in `tangential_forces[2i]`, `[2i+1]` (N)
    !  and the dissipated energy of the increment in `dissipation[i]` (J; may be NULL). No
    !  tangents. `work` may be NULL. On an error at point i, the points before i are written,
    !  those from i on untouched, and the message names i. The states are addresses (`c_loc`),
    !  so that one array may be passed as both.
    function c_asperity_friction_step_block(law, n, normal_forces, areas, slip_increments, dt, &
        old_states, new_states, tangential_forces, dissipation, work) result(r) &
        bind(c, name="asperity_friction_step_block")
      import
      implicit none
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: normal_forces(*)
      type(c_ptr), value :: areas
      real(c_double), intent(in) :: slip_increments(*)
      real(c_double), value :: dt
      type(c_ptr), value :: old_states
      type(c_ptr), value :: new_states
      real(c_double), intent(inout) :: tangential_forces(*)
      type(c_ptr), value :: dissipation
      type(c_ptr), value :: work
      integer(c_int32_t) :: r
    end function c_asperity_friction_step_block

    !> `asperity_friction_step_block` with each point's full response: the states
    !  `old_states[i*m .. (i+1)*m]` -> `new_states[...]` (m = `asperity_friction_state_size`;
    !  `new_states` may equal `old_states`, must not partially overlap it) of the points with
    !  normal forces `normal_forces[i]` (N), nominal areas `areas[i]` (m^2; NULL: 0 for every
    !  point, refused by laws that need them), slip increments `slip_increments[2i]`,
    !  `[2i+1]` (m, interleaved) and one `dt` (s), and `responses[i]` (n, required) as
    !  `asperity_friction_step` gives it for the increment of point i with `tangents` (0, or
    !  `ASPERITY_FRICTION_TANGENT_NORMAL` | `ASPERITY_FRICTION_TANGENT_SLIP`, for every point).
    !  `work` may be NULL. On an error at point i, the points before i are written, those from
    !  i on untouched, and the message names i. The states are addresses (`c_loc`), so that
    !  one array may be passed as both.
    function c_asperity_friction_step_block_responses(law, n, normal_forces, areas, &
        slip_increments, dt, tangents, old_states, new_states, responses, work) result(r) &
        bind(c, name="asperity_friction_step_block_responses")
      import
      implicit none
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: normal_forces(*)
      type(c_ptr), value :: areas
      real(c_double), intent(in) :: slip_increments(*)
      real(c_double), value :: dt
      integer(c_int32_t), value :: tangents
      type(c_ptr), value :: old_states
      type(c_ptr), value :: new_states
      type(asperity_friction_response), intent(inout) :: responses(*)
      type(c_ptr), value :: work
      integer(c_int32_t) :: r
    end function c_asperity_friction_step_block_responses

    !> `asperity_friction_step_block` with the states `states` stepped in place.
    function c_asperity_friction_step_block_in_place(law, n, normal_forces, areas, &
        slip_increments, dt, states, tangential_forces, dissipation, work) result(r) &
        bind(c, name="asperity_friction_step_block_in_place")
      import
      implicit none
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: normal_forces(*)
      type(c_ptr), value :: areas
      real(c_double), intent(in) :: slip_increments(*)
      real(c_double), value :: dt
      real(c_double), intent(inout) :: states(*)
      real(c_double), intent(inout) :: tangential_forces(*)
      type(c_ptr), value :: dissipation
      type(c_ptr), value :: work
      integer(c_int32_t) :: r
    end function c_asperity_friction_step_block_in_place

    !> Write the library's default slider options to `*out` (fixed load 0 N: set
    !  `normal_force`).
    function c_asperity_slider_options_default(out) result(r) &
        bind(c, name="asperity_slider_options_default")
      import
      implicit none
      type(asperity_slider_options), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_options_default

    !> Write the thesis's Cu-Cu friction material (REFERENCE.md §5) to `*out`.
    function c_asperity_friction_material_copper(out) result(r) &
        bind(c, name="asperity_friction_material_copper")
      import
      implicit none
      type(asperity_friction_material), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_friction_material_copper

    !> Build a slider from structs: the rods and nano-asperities of `geometry` (copied), the
    !  friction `material`, the rigid counter-surface `counter` (`n_counter` >= 2 heights, m)
    !  sampled at `counter_dx` (m), and `options`. Writes a new handle to `*out` (NULL on
    !  failure).
    function c_asperity_slider_new(geometry, material, counter, n_counter, counter_dx, options, &
        out) result(r) bind(c, name="asperity_slider_new")
      import
      implicit none
      type(c_ptr), value :: geometry
      type(asperity_friction_material), intent(in) :: material
      real(c_double), intent(in) :: counter(*)
      integer(c_size_t), value :: n_counter
      real(c_double), value :: counter_dx
      type(asperity_slider_options), intent(in) :: options
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_new

    !> Build a slider from the scene JSON text of `len` bytes at `json` (UTF-8, no NUL needed;
    !  the format of `examples/scenes/*.json`). Relative file paths in the scene are resolved
    !  against `base_dir` (a NUL-terminated UTF-8 directory path), or against the current
    !  directory when `base_dir` is NULL. The scene's `sliding` and `outputs` are validated but
    !  unused by the step. Writes a new handle to `*out` (NULL on failure). Errors: NULL `json`
    !  or `out`; invalid UTF-8 (`json`, `base_dir`); `ASPERITY_ERR_PARSE` for a JSON or field
    !  error (the message gives line, column and the field); the scene's value errors naming the
    !  field; a file the scene names that cannot be read (`ASPERITY_ERR_IO`).
    function c_asperity_slider_from_scene_json(json, len, base_dir, out) result(r) bind(c, &
        name="asperity_slider_from_scene_json")
      import
      implicit none
      character(kind=c_char), intent(in) :: json(*)
      integer(c_size_t), value :: len
      type(c_ptr), value :: base_dir
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_from_scene_json

    !> Release a slider; NULL is accepted and ignored.
    subroutine c_asperity_slider_free(slider) bind(c, name="asperity_slider_free")
      import
      implicit none
      type(c_ptr), value :: slider
    end subroutine c_asperity_slider_free

    !> Write the sizes and capacities of `slider` to `*info`.
    function c_asperity_slider_info(slider, info) result(r) bind(c, name="asperity_slider_info")
      import
      implicit none
      type(c_ptr), value :: slider
      type(asperity_slider_info), intent(inout) :: info
      integer(c_int32_t) :: r
    end function c_asperity_slider_info

    !> Write the record of the last step taken with `work` by a slider law
    !  (`asperity_friction_from_slider`) to `*out`; all zero for a work made for a slider law
    !  that has not stepped yet. Errors: NULL, or a work of another law (`work`).
    function c_asperity_slider_record(work, out) result(r) &
        bind(c, name="asperity_slider_record")
      import
      implicit none
      type(c_ptr), value :: work
      type(asperity_slider_record), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_slider_record

    !> Greenwood–Williamson load, real area, number of contacts and stiffness at `separation` d
    !  (m, finite) (thesis (1-29), (1-30)).
    function c_asperity_gw_eval(gw, separation, out) result(r) bind(c, &
        name="asperity_gw_eval")
      import
      implicit none
      type(asperity_gw_params), intent(in) :: gw
      real(c_double), value :: separation
      type(asperity_gw_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_gw_eval

    !> Bush–Gibson–Thomas load, real area, number of contacts and stiffness at `separation` d
    !  (m, finite; the flat's height above the mean plane of the surface).
    function c_asperity_bgt_eval(bgt, separation, out) result(r) bind(c, &
        name="asperity_bgt_eval")
      import
      implicit none
      type(asperity_bgt_params), intent(in) :: bgt
      real(c_double), value :: separation
      type(asperity_bgt_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_bgt_eval

    !> `asperity_bgt_eval` for `n` separations (see `asperity_gw_eval_batch`).
    function c_asperity_bgt_eval_batch(bgt, n, separation, load, area, contacts, stiffness) &
        result(r) bind(c, name="asperity_bgt_eval_batch")
      import
      implicit none
      type(asperity_bgt_params), intent(in) :: bgt
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: separation(*)
      real(c_double), intent(inout) :: load(*)
      type(c_ptr), value :: area
      type(c_ptr), value :: contacts
      type(c_ptr), value :: stiffness
      integer(c_int32_t) :: r
    end function c_asperity_bgt_eval_batch

    !> The separation (m) at which the surface carries `load` (N, finite and > 0).
    function c_asperity_bgt_separation_at_load(bgt, load, out) result(r) bind(c, &
        name="asperity_bgt_separation_at_load")
      import
      implicit none
      type(asperity_bgt_params), intent(in) :: bgt
      real(c_double), value :: load
      type(asperity_separation), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_bgt_separation_at_load

    !> Nayak's summit density (m⁻²) and the small-load limit of A/P (m²/N); either output may
    !  be NULL.
    function c_asperity_bgt_properties(bgt, summit_density, area_per_load) result(r) bind(c, &
        name="asperity_bgt_properties")
      import
      implicit none
      type(asperity_bgt_params), intent(in) :: bgt
      type(c_ptr), value :: summit_density
      type(c_ptr), value :: area_per_load
      integer(c_int32_t) :: r
    end function c_asperity_bgt_properties

    !> A Bora et al. interface on `nx` × `ny` heights (m, row-major, copied), grid spacing (m),
    !  spring stiffness (N/m), substrate contact modulus (Pa; 0: rigid). Writes a new handle.
    function c_asperity_bora_new(nx, ny, spacing, heights, spring_stiffness, contact_modulus, &
        out) result(r) bind(c, name="asperity_bora_new")
      import
      implicit none
      integer(c_size_t), value :: nx
      integer(c_size_t), value :: ny
      real(c_double), value :: spacing
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: spring_stiffness
      real(c_double), value :: contact_modulus
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_bora_new

    !> Release a Bora interface; NULL is accepted.
    subroutine c_asperity_bora_free(bora) bind(c, name="asperity_bora_free")
      import
      implicit none
      type(c_ptr), value :: bora
    end subroutine c_asperity_bora_free

    !> The equilibrium at `separation` (m); the nx·ny spring forces (N) to `forces` unless NULL.
    function c_asperity_bora_solve(bora, separation, out, forces) result(r) bind(c, &
        name="asperity_bora_solve")
      import
      implicit none
      type(c_ptr), value :: bora
      real(c_double), value :: separation
      type(asperity_bora_response), intent(inout) :: out
      type(c_ptr), value :: forces
      integer(c_int32_t) :: r
    end function c_asperity_bora_solve

    !> The separation (m) at which the interface carries `load` (N, finite and > 0).
    function c_asperity_bora_separation_at_load(bora, load, out) result(r) bind(c, &
        name="asperity_bora_separation_at_load")
      import
      implicit none
      type(c_ptr), value :: bora
      real(c_double), value :: load
      type(asperity_separation), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_bora_separation_at_load

    !> Run the Sergienko–Bukharov model `params` on `n_heights` spring-top heights (m; read only
    !  for `ASPERITY_HEIGHTS_LIST`) and write the averages to `out`.
    function c_asperity_sergienko_bukharov_run(params, heights, n_heights, out) result(r) &
        bind(c, name="asperity_sergienko_bukharov_run")
      import
      implicit none
      type(asperity_sergienko_bukharov_params), intent(in) :: params
      real(c_double), intent(in) :: heights(*)
      integer(c_size_t), value :: n_heights
      type(asperity_sergienko_bukharov_result), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_sergienko_bukharov_run

    !> `asperity_gw_eval` for `n` separations `separation[i]` (m), writing `load[i]` (N) and,
    !  where the array is not NULL, `area[i]` (m²), `contacts[i]` and `stiffness[i]` (N/m).
    !  `separation` and `load` are required (unless n = 0); inputs and outputs may be the same
    !  memory. On an error at element i, elements before i are written and the message names i.
    function c_asperity_gw_eval_batch(gw, n, separation, load, area, contacts, stiffness) &
        result(r) bind(c, name="asperity_gw_eval_batch")
      import
      implicit none
      type(asperity_gw_params), intent(in) :: gw
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: separation(*)
      real(c_double), intent(inout) :: load(*)
      type(c_ptr), value :: area
      type(c_ptr), value :: contacts
      type(c_ptr), value :: stiffness
      integer(c_int32_t) :: r
    end function c_asperity_gw_eval_batch

    !> The separation (m) at which the surface carries `load` (N, finite, > 0): the inverse of
    !  (1-29) by safeguarded Newton iteration.
    function c_asperity_gw_separation_at_load(gw, load, out) result(r) bind(c, &
        name="asperity_gw_separation_at_load")
      import
      implicit none
      type(asperity_gw_params), intent(in) :: gw
      real(c_double), value :: load
      type(asperity_separation), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_gw_separation_at_load

    !> Plasticity index ψ = (E*/H)√(σ/R) (1-31) of the surface `gw` for the hardness `hardness`
    !  H (Pa, > 0).
    function c_asperity_gw_plasticity_index(gw, hardness, psi) result(r) bind(c, &
        name="asperity_gw_plasticity_index")
      import
      implicit none
      type(asperity_gw_params), intent(in) :: gw
      real(c_double), value :: hardness
      real(c_double), intent(out) :: psi
      integer(c_int32_t) :: r
    end function c_asperity_gw_plasticity_index

    !> Plasticity index of Greenwood & Williamson (1966), thesis (1-31): ψ = (E*/H)√(σ/R) from
    !  the contact modulus `e_star` (Pa), the hardness `hardness` (Pa), the standard deviation
    !  of the summit heights `sigma` (m) and the summit radius `radius` (m), all finite and > 0.
    function c_asperity_plasticity_index(e_star, hardness, sigma, radius, psi) result(r) &
        bind(c, name="asperity_plasticity_index")
      import
      implicit none
      real(c_double), value :: e_star
      real(c_double), value :: hardness
      real(c_double), value :: sigma
      real(c_double), value :: radius
      real(c_double), intent(out) :: psi
      integer(c_int32_t) :: r
    end function c_asperity_plasticity_index

    !> The deformation regime (`ASPERITY_REGIME_*`) of a plasticity index `psi` (finite, ≥ 0):
    !  elastic below 0.6, plastic above 1 (GW 1966).
    function c_asperity_deformation_regime(psi, regime) result(r) bind(c, &
        name="asperity_deformation_regime")
      import
      implicit none
      real(c_double), value :: psi
      integer(c_int32_t), intent(out) :: regime
      integer(c_int32_t) :: r
    end function c_asperity_deformation_regime

    !> A Greenwood–Williamson surface over `n` ≥ 1 listed summits: heights `heights[i]` (m,
    !  finite, any order, in the frame of the separations) and, unless `radii` is NULL, each
    !  summit's radius `radii[i]` (m, > 0; then they replace `radius` in the load, area and
    !  stiffness), `summit_count` N (> 0; each listed summit stands for N/n), `radius` R (m, >
    !  0) and the contact modulus `e_star` (Pa, > 0). The arrays are copied. Writes a new handle
    !  to `*out` (NULL on failure).
    function c_asperity_gw_empirical_new(summit_count, radius, e_star, n, heights, radii, &
        out) result(r) bind(c, name="asperity_gw_empirical_new")
      import
      implicit none
      real(c_double), value :: summit_count
      real(c_double), value :: radius
      real(c_double), value :: e_star
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      type(c_ptr), value :: radii
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_gw_empirical_new

    !> Release an empirical Greenwood–Williamson surface; NULL is accepted.
    subroutine c_asperity_gw_empirical_free(gw) bind(c, name="asperity_gw_empirical_free")
      import
      implicit none
      type(c_ptr), value :: gw
    end subroutine c_asperity_gw_empirical_free

    !> `asperity_gw_eval` for an empirical surface.
    function c_asperity_gw_empirical_eval(gw, separation, out) result(r) bind(c, &
        name="asperity_gw_empirical_eval")
      import
      implicit none
      type(c_ptr), value :: gw
      real(c_double), value :: separation
      type(asperity_gw_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_gw_empirical_eval

    !> `asperity_gw_eval_batch` for an empirical surface.
    function c_asperity_gw_empirical_eval_batch(gw, n, separation, load, area, contacts, &
        stiffness) result(r) bind(c, name="asperity_gw_empirical_eval_batch")
      import
      implicit none
      type(c_ptr), value :: gw
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: separation(*)
      real(c_double), intent(inout) :: load(*)
      type(c_ptr), value :: area
      type(c_ptr), value :: contacts
      type(c_ptr), value :: stiffness
      integer(c_int32_t) :: r
    end function c_asperity_gw_empirical_eval_batch

    !> `asperity_gw_separation_at_load` for an empirical surface.
    function c_asperity_gw_empirical_separation_at_load(gw, load, out) result(r) bind(c, &
        name="asperity_gw_empirical_separation_at_load")
      import
      implicit none
      type(c_ptr), value :: gw
      real(c_double), value :: load
      type(asperity_separation), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_gw_empirical_separation_at_load

    !> `asperity_gw_plasticity_index` for an empirical surface (σ of the listed heights, the
    !  model's `radius`).
    function c_asperity_gw_empirical_plasticity_index(gw, hardness, psi) result(r) bind(c, &
        name="asperity_gw_empirical_plasticity_index")
      import
      implicit none
      type(c_ptr), value :: gw
      real(c_double), value :: hardness
      real(c_double), intent(out) :: psi
      integer(c_int32_t) :: r
    end function c_asperity_gw_empirical_plasticity_index

    !> Zhuravlev's model with summit densities linear in depth, n_i(ξ) = α_i ξ (`alpha1`,
    !  `alpha2` in m⁻², > 0), at the approach `approach` x (m, ≥ 0): the closed forms P ∝
    !  x^{11/2} (1-25), S ∝ x⁵ (1-26), pairs ∝ x⁴.
    function c_asperity_zhuravlev_linear(model, alpha1, alpha2, approach, out) result(r) &
        bind(c, name="asperity_zhuravlev_linear")
      import
      implicit none
      type(asperity_zhuravlev), intent(in) :: model
      real(c_double), value :: alpha1
      real(c_double), value :: alpha2
      real(c_double), value :: approach
      type(asperity_zhuravlev_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_zhuravlev_linear

    !> The approach x (m) that carries `load` (N, ≥ 0) with linear densities: the inverse of
    !  (1-25).
    function c_asperity_zhuravlev_approach_at_load_linear(model, alpha1, alpha2, load, &
        approach) result(r) bind(c, name="asperity_zhuravlev_approach_at_load_linear")
      import
      implicit none
      type(asperity_zhuravlev), intent(in) :: model
      real(c_double), value :: alpha1
      real(c_double), value :: alpha2
      real(c_double), value :: load
      real(c_double), intent(out) :: approach
      integer(c_int32_t) :: r
    end function c_asperity_zhuravlev_approach_at_load_linear

    !> Friction of Zhuravlev's model at `load` (N, > 0) with linear densities and interfacial
    !  shear strength `shear_strength` τ (Pa, ≥ 0): F = τS (1-27), F ∝ P^{10/11} (1-28), μ =
    !  F/P.
    function c_asperity_zhuravlev_friction_linear(model, alpha1, alpha2, load, &
        shear_strength, out) result(r) bind(c, &
        name="asperity_zhuravlev_friction_linear")
      import
      implicit none
      type(asperity_zhuravlev), intent(in) :: model
      real(c_double), value :: alpha1
      real(c_double), value :: alpha2
      real(c_double), value :: load
      real(c_double), value :: shear_strength
      type(asperity_zhuravlev_friction), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_zhuravlev_friction_linear

    !> Zhuravlev's model for any summit densities `n1`, `n2` (1/m, callbacks called with the
    !  depth ξ ≥ 0 and `n1_data` / `n2_data`) at the approach `approach` (m, ≥ 0), by
    !  Gauss–Legendre quadrature of `order` (4..=64) points per dimension ((1-23), (1-24)). A
    !  callback value that is not finite gives `ASPERITY_ERR_INVALID_ARGUMENT` naming `n1` or
    !  `n2`; a negative integral `ASPERITY_ERR_OUT_OF_DOMAIN`. The callbacks are called on the
    !  calling thread only.
    function c_asperity_zhuravlev_eval(model, approach, n1, n1_data, n2, n2_data, order, &
        out) result(r) bind(c, name="asperity_zhuravlev_eval")
      import
      implicit none
      type(asperity_zhuravlev), intent(in) :: model
      real(c_double), value :: approach
      type(c_funptr), value :: n1
      type(c_ptr), value :: n1_data
      type(c_funptr), value :: n2
      type(c_ptr), value :: n2_data
      integer(c_size_t), value :: order
      type(asperity_zhuravlev_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_zhuravlev_eval

    !> A static, NUL-terminated description of a status code; "unknown status" for a value that
    !  is not one. Do not free.
    function c_asperity_status_string(status) result(r) bind(c, &
        name="asperity_status_string")
      import
      implicit none
      integer(c_int32_t), value :: status
      type(c_ptr) :: r
    end function c_asperity_status_string

    !> ISO 4287 parameters of the profile `heights` (`n` values, m) sampled at `dx` (m):  1.
    !  `form` (one of `ASPERITY_FORM_*`) is removed by least squares; 2. when `cutoff` λc (m) is
    !  not 0, the ISO 16610-21 Gaussian filter keeps the roughness profile and drops λc/2 at
    !  each end (λc ≥ 5·dx and shorter than the profile); 3. the parameters are computed over
    !  sampling lengths of `sampling_length` (m; 0 = the whole evaluated profile is one; ISO
    !  4288 takes λc), with the ISO 4287 default discriminations (10 % of Rz, 1 % of the
    !  sampling length); m₀, m₂, m₄ and α over the whole evaluated profile; the Hurst exponent
    !  where a power law applies.  Errors: NULL `heights` or `out`; fewer than 8 evaluated
    !  samples, non-finite heights, `dx` not finite and > 0 (`ASPERITY_ERR_INVALID_ARGUMENT`,
    !  the message names the argument); an unknown `form`; a bad `cutoff` or `sampling_length`;
    !  constant heights (`ASPERITY_ERR_OUT_OF_DOMAIN`).
    function c_asperity_roughness_parameters(n, heights, dx, form, cutoff, sampling_length, &
        out) result(r) bind(c, name="asperity_roughness_parameters")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: dx
      integer(c_int32_t), value :: form
      real(c_double), value :: cutoff
      real(c_double), value :: sampling_length
      type(asperity_roughness), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_roughness_parameters

    !> `heights` (`n` values, m) minus their least-squares `form` (`ASPERITY_FORM_*`; NONE
    !  copies), written to `out` (`n` values, m; may be `heights` itself). Errors: NULL arrays,
    !  too few points for the form, non-finite heights, an unknown `form`.
    function c_asperity_profile_remove_form(n, heights, form, out) result(r) bind(c, &
        name="asperity_profile_remove_form")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      integer(c_int32_t), value :: form
      real(c_double), intent(inout) :: out(*)
      integer(c_int32_t) :: r
    end function c_asperity_profile_remove_form

    !> ISO 16610-21 Gaussian filter of `heights` (`n` values, m, spacing `dx` m) with cut-off
    !  `cutoff` λc (m): writes the roughness profile to `roughness` and, if not NULL, the mean
    !  line to `mean_line` (each needs room for `n` values; either may be `heights` itself), the
    !  number of samples written to `*n_out` and the index of the first one in the input to
    !  `*first_index` (may be NULL). `ends` is `ASPERITY_FILTER_ENDS_DISCARD` (λc/2 dropped at
    !  each end: `*n_out` is about n − λc/dx) or `ASPERITY_FILTER_ENDS_KEEP` (`*n_out` = n).
    !  Errors: as `asperity_roughness_parameters` for `cutoff`.
    function c_asperity_profile_gaussian_filter(n, heights, dx, cutoff, ends, roughness, &
        mean_line, n_out, first_index) result(r) bind(c, &
        name="asperity_profile_gaussian_filter")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: dx
      real(c_double), value :: cutoff
      integer(c_int32_t), value :: ends
      real(c_double), intent(inout) :: roughness(*)
      type(c_ptr), value :: mean_line
      integer(c_size_t), intent(out) :: n_out
      type(c_ptr), value :: first_index
      integer(c_int32_t) :: r
    end function c_asperity_profile_gaussian_filter

    !> ISO 16610-61 areal Gaussian filter of the `nx` × `ny` map `heights` (m, x fastest):
    !  roughness (and, unless NULL, mean) surface on the retained grid, its size, and (unless
    !  NULL) the input indices of its first point.
    function c_asperity_map_gaussian_filter(nx, ny, dx, dy, heights, cutoff, ends, roughness, &
        mean_surface, nx_out, ny_out, first_x, first_y) result(r) bind(c, &
        name="asperity_map_gaussian_filter")
      import
      implicit none
      integer(c_size_t), value :: nx
      integer(c_size_t), value :: ny
      real(c_double), value :: dx
      real(c_double), value :: dy
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: cutoff
      integer(c_int32_t), value :: ends
      real(c_double), intent(inout) :: roughness(*)
      type(c_ptr), value :: mean_surface
      integer(c_size_t), intent(out) :: nx_out
      integer(c_size_t), intent(out) :: ny_out
      type(c_ptr), value :: first_x
      type(c_ptr), value :: first_y
      integer(c_int32_t) :: r
    end function c_asperity_map_gaussian_filter

    !> Radially averaged 2-D PSD of the `nx` × `ny` map `heights` (m, x fastest): per annulus
    !  the mean |q| (rad/m; `q` may be NULL), the mean PSD (m⁴) and the point count (`count`
    !  may be NULL); room for `capacity` (min(nx, ny)/2 + 1 suffices); the number to `written`.
    function c_asperity_map_psd_radial(nx, ny, dx, dy, heights, window, capacity, q, psd, &
        count, written) result(r) bind(c, name="asperity_map_psd_radial")
      import
      implicit none
      integer(c_size_t), value :: nx
      integer(c_size_t), value :: ny
      real(c_double), value :: dx
      real(c_double), value :: dy
      real(c_double), intent(in) :: heights(*)
      integer(c_int32_t), value :: window
      integer(c_size_t), value :: capacity
      type(c_ptr), value :: q
      real(c_double), intent(inout) :: psd(*)
      type(c_ptr), value :: count
      integer(c_size_t), intent(out) :: written
      integer(c_int32_t) :: r
    end function c_asperity_map_psd_radial

    !> The material-ratio (Abbott–Firestone) curve of `heights` (`n` values, m) at `n_points` ≥
    !  2 equally spaced ratios Rmr = i/(n_points − 1): `ratio[i]` (dimensionless, 0 … 1; may be
    !  NULL) and `level[i]`, the height c(Rmr) above the mean line (m; the highest peak at 0,
    !  the deepest valley at 1). Errors: NULL `heights` or `level`, `n_points` < 2, no or non-
    !  finite heights.
    function c_asperity_material_ratio_curve(n, heights, n_points, ratio, level) result(r) &
        bind(c, name="asperity_material_ratio_curve")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      integer(c_size_t), value :: n_points
      type(c_ptr), value :: ratio
      real(c_double), intent(inout) :: level(*)
      integer(c_int32_t) :: r
    end function c_asperity_material_ratio_curve

    !> One-sided PSD G(q) (thesis 1-7; ∫G dq = Rq² for the rectangular window) of `heights` (`n`
    !  ≥ 4 values, m, spacing `dx` m, mean removed) with `window` (`ASPERITY_WINDOW_*`). Length
    !  rule: `n_q` must equal n/2 + 1 (integer division); `q[k]` = k·2π/(n·dx) (rad/m; may be
    !  NULL) and `g[k]` (m³).
    function c_asperity_profile_psd(n, heights, dx, window, n_q, q, g) result(r) bind(c, &
        name="asperity_profile_psd")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: dx
      integer(c_int32_t), value :: window
      integer(c_size_t), value :: n_q
      type(c_ptr), value :: q
      real(c_double), intent(inout) :: g(*)
      integer(c_int32_t) :: r
    end function c_asperity_profile_psd

    !> Power-law fit of the Hann-windowed PSD of `heights` (`n` values, m, spacing `dx` m) over
    !  `q_min ≤ q ≤ q_max` (rad/m); `q_min` = `q_max` = 0 selects the default band (wavelengths
    !  from n·dx/4 down to 8·dx). Errors: as `asperity_profile_psd`, a bad band, fewer than 3
    !  populated bins (`ASPERITY_ERR_OUT_OF_DOMAIN`).
    function c_asperity_profile_hurst_fit(n, heights, dx, q_min, q_max, out) result(r) &
        bind(c, name="asperity_profile_hurst_fit")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: dx
      real(c_double), value :: q_min
      real(c_double), value :: q_max
      type(asperity_hurst_fit), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_profile_hurst_fit

    !> `asperity_profile_hurst_fit` with H's standard error, χ²/ν and the band in rad/m and m.
    function c_asperity_profile_hurst_estimate(n, heights, dx, q_min, q_max, out) result(r) &
        bind(c, name="asperity_profile_hurst_estimate")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: dx
      real(c_double), value :: q_min
      real(c_double), value :: q_max
      type(asperity_hurst_estimate), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_profile_hurst_estimate

    !> Statistics of the peaks (3-point maxima, heights from the mean line, curvature −z″) of
    !  `heights` (`n` ≥ 3 values, m, spacing `dx` m); the density is per profile length n·dx.
    function c_asperity_profile_peak_statistics(n, heights, dx, out) result(r) bind(c, &
        name="asperity_profile_peak_statistics")
      import
      implicit none
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: heights(*)
      real(c_double), value :: dx
      type(asperity_peak_statistics), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_profile_peak_statistics

    !> A seeded Gaussian self-affine profile by Fourier filtering: `n` ≥ 4 samples at spacing
    !  `dx` (m) written to `heights`, Hurst exponent `hurst` in [0, 1], root-mean-square height
    !  `rq` (m, matched to rounding), `roll_off_wavelength` (m; 0 = none: a power law down to
    !  the lowest harmonic) and `cutoff_wavelength` (m; 0 = none; shorter than the roll-off).
    !  The same arguments and `seed` give the same heights (see `surface::generate`).
    function c_asperity_generate_self_affine(hurst, rq, roll_off_wavelength, &
        cutoff_wavelength, dx, seed, n, heights) result(r) bind(c, &
        name="asperity_generate_self_affine")
      import
      implicit none
      real(c_double), value :: hurst
      real(c_double), value :: rq
      real(c_double), value :: roll_off_wavelength
      real(c_double), value :: cutoff_wavelength
      real(c_double), value :: dx
      integer(c_int64_t), value :: seed
      integer(c_size_t), value :: n
      real(c_double), intent(inout) :: heights(*)
      integer(c_int32_t) :: r
    end function c_asperity_generate_self_affine

    !> The Weierstrass–Mandelbrot profile with random phases from `seed`: `n` ≥ 4 samples at
    !  spacing `dx` (m) written to `heights`, fractal dimension `fractal_dimension` in (1, 2),
    !  frequency ratio `gamma` > 1, amplitude of the longest term `amplitude` (m).
    function c_asperity_generate_weierstrass_mandelbrot(fractal_dimension, gamma, amplitude, &
        dx, seed, n, heights) result(r) bind(c, &
        name="asperity_generate_weierstrass_mandelbrot")
      import
      implicit none
      real(c_double), value :: fractal_dimension
      real(c_double), value :: gamma
      real(c_double), value :: amplitude
      real(c_double), value :: dx
      integer(c_int64_t), value :: seed
      integer(c_size_t), value :: n
      real(c_double), intent(inout) :: heights(*)
      integer(c_int32_t) :: r
    end function c_asperity_generate_weierstrass_mandelbrot

    !> The Cantor–Borodich profile: `descendants` m = 2 (Borodich) or 3 (Warren–Krajcinovic; any
    !  m ≥ 2 is accepted), horizontal ratio `alpha` in (0, 1/m), vertical ratio `beta` in (1/m,
    !  1), first step `height` (m), `levels` generations in 1..=40, sampled at `n` ≥ 2 points
    !  x_j = j·length/n over [0, `length`) (m), written to `heights`.
    function c_asperity_generate_cantor_borodich(descendants, alpha, beta, height, levels, &
        length, n, heights) result(r) bind(c, name="asperity_generate_cantor_borodich")
      import
      implicit none
      integer(c_int32_t), value :: descendants
      real(c_double), value :: alpha
      real(c_double), value :: beta
      real(c_double), value :: height
      integer(c_int32_t), value :: levels
      real(c_double), value :: length
      integer(c_size_t), value :: n
      real(c_double), intent(inout) :: heights(*)
      integer(c_int32_t) :: r
    end function c_asperity_generate_cantor_borodich

    !> Build the table of a Maugis–Dugdale sphere: radius (m), E* (Pa), work of adhesion (J/m²),
    !  Dugdale stress σ₀ (Pa), relative `tolerance` in [1e-10, 0.1] (1e-4 is the default of the
    !  Rust API) in the error measure of the documentation (relative to max(|P|, 1e-3·|pull-
    !  off|)). Writes a new handle to `*out` (NULL on failure).
    function c_asperity_table_new_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, &
        tolerance, out) result(r) bind(c, name="asperity_table_new_maugis_dugdale")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: sigma0
      real(c_double), value :: tolerance
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_table_new_maugis_dugdale

    !> Build the table of a Lennard-Jones sphere (the numerical solver with `n_grid` cells; 0 =
    !  the converged default grid): radius R (m), E* (Pa), work of adhesion Δγ (J/m²),
    !  equilibrium separation z₀ (m), all finite and positive with Tabor parameter μ in (0,
    !  100], relative `tolerance` in [1e-10, 0.1] (1e-4 is the default of the Rust API) in the
    !  error measure of the documentation (relative to max(|P|, 1e-3·|pull-off|)) against the
    !  solver on the same grid. The overlap δ of the table is the rigid approach α (0 where the
    !  undeformed apex sits at z₀). Takes about 0.2–0.5 s at `n_grid` = 128 in an optimised
    !  build (μ ≤ 1). Writes a new handle to `*out` (NULL on failure).
    function c_asperity_table_new_lj(radius, e_star, work_of_adhesion, z0, n_grid, &
        tolerance, out) result(r) bind(c, name="asperity_table_new_lj")
      import
      implicit none
      real(c_double), value :: radius
      real(c_double), value :: e_star
      real(c_double), value :: work_of_adhesion
      real(c_double), value :: z0
      integer(c_size_t), value :: n_grid
      real(c_double), value :: tolerance
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_table_new_lj

    !> Release a table; NULL is accepted and ignored.
    subroutine c_asperity_table_free(table) bind(c, name="asperity_table_free")
      import
      implicit none
      type(c_ptr), value :: table
    end subroutine c_asperity_table_free

    !> Evaluate `table` at the overlap `delta` (m) from the history `old_state` (NULL: fresh),
    !  writing the history after the step to `new_state` (may be NULL, may equal `old_state`)
    !  and the response to `out`.
    function c_asperity_table_eval(table, delta, old_state, new_state, out) result(r) &
        bind(c, name="asperity_table_eval")
      import
      implicit none
      type(c_ptr), value :: table
      real(c_double), value :: delta
      type(c_ptr), value :: old_state
      type(c_ptr), value :: new_state
      type(asperity_normal_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_table_eval

    !> Evaluate `table` for `n` contacts, as `asperity_normal_eval_batch`: `delta[i]` (m),
    !  `old_state[i]` → `new_state[i]`, `force[i]` (N), `contact_radius[i]` (m), `stiffness[i]`
    !  (N/m). `delta` and `force` are required, the others may be NULL; inputs and outputs may
    !  alias. On an error at element i, elements before i are written and the message names i.
    function c_asperity_table_eval_batch(table, n, delta, old_state, new_state, force, &
        contact_radius, stiffness) result(r) bind(c, name="asperity_table_eval_batch")
      import
      implicit none
      type(c_ptr), value :: table
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: delta(*)
      type(c_ptr), value :: old_state
      type(c_ptr), value :: new_state
      real(c_double), intent(inout) :: force(*)
      type(c_ptr), value :: contact_radius
      type(c_ptr), value :: stiffness
      integer(c_int32_t) :: r
    end function c_asperity_table_eval_batch

    !> Equilibrium at the prescribed force `force` (N) on the load-controlled stable branch;
    !  `out->delta` is the overlap.
    function c_asperity_table_eval_at_load(table, force, out) result(r) bind(c, &
        name="asperity_table_eval_at_load")
      import
      implicit none
      type(c_ptr), value :: table
      real(c_double), value :: force
      type(asperity_normal_response), intent(inout) :: out
      integer(c_int32_t) :: r
    end function c_asperity_table_eval_at_load

    !> The pull-off force (N) of `table` under `control` (`ASPERITY_CONTROL_LOAD` or
    !  `ASPERITY_CONTROL_DISPLACEMENT`).
    function c_asperity_table_pull_off_force(table, control, force) result(r) bind(c, &
        name="asperity_table_pull_off_force")
      import
      implicit none
      type(c_ptr), value :: table
      integer(c_int32_t), value :: control
      real(c_double), intent(out) :: force
      integer(c_int32_t) :: r
    end function c_asperity_table_pull_off_force

    !> The reach of `table` under `control`, as `asperity_normal_reach`: the overlap (m) below
    !  which the force is zero from any history, or below which |force| < `rel_force` ×
    !  |load pull-off force| with a Lennard-Jones far tail.
    function c_asperity_table_reach(table, control, rel_force, delta) result(r) bind(c, &
        name="asperity_table_reach")
      import
      implicit none
      type(c_ptr), value :: table
      integer(c_int32_t), value :: control
      real(c_double), value :: rel_force
      real(c_double), intent(out) :: delta
      integer(c_int32_t) :: r
    end function c_asperity_table_reach

    !> The stated maximum relative error of `table` (its tolerance) and, if `measured` is not
    !  NULL, the largest error measured at construction.
    function c_asperity_table_max_error(table, max_error, measured) result(r) bind(c, &
        name="asperity_table_max_error")
      import
      implicit none
      type(c_ptr), value :: table
      real(c_double), intent(out) :: max_error
      type(c_ptr), value :: measured
      integer(c_int32_t) :: r
    end function c_asperity_table_max_error

    !> Write the JSON text of `table` into `buf` (at most `len − 1` bytes and a NUL) and its
    !  full length in bytes (without the NUL) to `*needed`, so `asperity_table_to_json(t, NULL,
    !  0, &n)` sizes the buffer. The text is complete only when `*needed < len`; `needed` is
    !  required.
    function c_asperity_table_to_json(table, buf, len, needed) result(r) bind(c, &
        name="asperity_table_to_json")
      import
      implicit none
      type(c_ptr), value :: table
      type(c_ptr), value :: buf
      integer(c_size_t), value :: len
      integer(c_size_t), intent(out) :: needed
      integer(c_int32_t) :: r
    end function c_asperity_table_to_json

    !> Load a table from `len` bytes of JSON text at `json` (from `asperity_table_to_json`; no
    !  NUL needed). The table is validated; a corrupted text gives
    !  `ASPERITY_ERR_INVALID_ARGUMENT`. Writes a new handle to `*out` (NULL on failure).
    function c_asperity_table_from_json(json, len, out) result(r) bind(c, &
        name="asperity_table_from_json")
      import
      implicit none
      character(kind=c_char), intent(in) :: json(*)
      integer(c_size_t), value :: len
      type(c_ptr), intent(out) :: out
      integer(c_int32_t) :: r
    end function c_asperity_table_from_json
  end interface


  interface
    function c_strlen(s) result(n) bind(c, name="strlen")
      import :: c_ptr, c_size_t
      implicit none
      type(c_ptr), value :: s
      integer(c_size_t) :: n
    end function c_strlen
  end interface

  public :: c_asperity_version
  public :: c_asperity_last_error_message
  public :: c_asperity_type_layout
  public :: c_asperity_type_count
  public :: c_asperity_type_name
  public :: c_asperity_law_from_params
  public :: c_asperity_law_hertz
  public :: c_asperity_law_sphere_in_crater
  public :: c_asperity_law_power_punch
  public :: c_asperity_law_cone
  public :: c_asperity_law_cone_in_imprint
  public :: c_asperity_law_flat_punch
  public :: c_asperity_law_flat_punch_no_slip
  public :: c_asperity_law_dmt
  public :: c_asperity_law_jkr
  public :: c_asperity_law_jkr_power_punch
  public :: c_asperity_law_kendall
  public :: c_asperity_law_maugis_dugdale
  public :: c_asperity_law_derjaguin
  public :: c_asperity_normal_eval
  public :: c_asperity_normal_eval_batch
  public :: c_asperity_normal_eval_at_load
  public :: c_asperity_pull_off_force
  public :: c_asperity_normal_reach
  public :: c_asperity_normal_energy
  public :: c_asperity_law_length_scale
  public :: c_asperity_fidelity_advise
  public :: c_asperity_slider_geometry_new
  public :: c_asperity_slider_geometry_new_uniform
  public :: c_asperity_slider_geometry_free
  public :: c_asperity_slider_geometry_nano
  public :: c_asperity_slider_geometry_level_count
  public :: c_asperity_slider_geometry_rod_count
  public :: c_asperity_slider_geometry_rod_width
  public :: c_asperity_slider_geometry_rod_heights
  public :: c_asperity_homogenised_friction_new
  public :: c_asperity_homogenised_friction_from_json
  public :: c_asperity_homogenised_friction_to_json
  public :: c_asperity_homogenised_friction_free
  public :: c_asperity_indentation_default_options
  public :: c_asperity_indentation_fit
  public :: c_asperity_indentation_flag_name
  public :: c_asperity_afm_analyze
  public :: c_asperity_afm_flag_name
  public :: c_asperity_rescaling_depth
  public :: c_asperity_rescaling_radius
  public :: c_asperity_rescaling_load
  public :: c_asperity_rescaling_lambda_spheres
  public :: c_asperity_rescaling_lambda_cones
  public :: c_asperity_rescaling_kappa_from_slope
  public :: c_asperity_rescaling_d_from_unloading_slope
  public :: c_asperity_rescaling_d_from_loading_slope
  public :: c_asperity_galanov_unloading_radius
  public :: c_asperity_galanov_medium_radius
  public :: c_asperity_hardness_brinell
  public :: c_asperity_hardness_meyer
  public :: c_asperity_hardness_ludwik
  public :: c_asperity_hardness_vickers
  public :: c_asperity_lj_sphere_pull_off
  public :: c_asperity_effective_modulus
  public :: c_asperity_rod_effective_modulus
  public :: c_asperity_no_slip_factor
  public :: c_asperity_tabor_parameter
  public :: c_asperity_maugis_parameter
  public :: c_asperity_weir_surface_energy
  public :: c_asperity_weir_surface_energy_with
  public :: c_asperity_pair_work_of_adhesion
  public :: c_asperity_hamaker_work_of_adhesion
  public :: c_asperity_friction_lugre_new
  public :: c_asperity_friction_maxwell_slip_new
  public :: c_asperity_friction_generalized_maxwell_slip_new
  public :: c_asperity_archard_exponent
  public :: c_asperity_archard_area_batch
  public :: c_asperity_cantor_contact_batch
  public :: c_asperity_cantor_exponents
  public :: c_asperity_schmittbuhl_run
  public :: c_asperity_schmittbuhl_default
  public :: c_asperity_borodich_kryukova_normal_force
  public :: c_asperity_borodich_kryukova_run
  public :: c_asperity_friction_bristles_new
  public :: c_asperity_friction_prandtl_tomlinson_new
  public :: c_asperity_friction_prandtl_tomlinson_two_spring_new
  public :: c_asperity_friction_burridge_knopoff_new
  public :: c_asperity_friction_from_homogenised
  public :: c_asperity_friction_from_slider
  public :: c_asperity_friction_free
  public :: c_asperity_friction_state_size
  public :: c_asperity_friction_work_new
  public :: c_asperity_friction_work_free
  public :: c_asperity_friction_step
  public :: c_asperity_friction_step_in_place
  public :: c_asperity_friction_step_block
  public :: c_asperity_friction_step_block_in_place
  public :: c_asperity_friction_step_block_responses
  public :: c_asperity_slider_options_default
  public :: c_asperity_friction_material_copper
  public :: c_asperity_slider_new
  public :: c_asperity_slider_from_scene_json
  public :: c_asperity_slider_free
  public :: c_asperity_slider_info
  public :: c_asperity_slider_record
  public :: c_asperity_gw_eval
  public :: c_asperity_bgt_eval
  public :: c_asperity_bgt_eval_batch
  public :: c_asperity_bgt_separation_at_load
  public :: c_asperity_bgt_properties
  public :: c_asperity_bora_new
  public :: c_asperity_bora_free
  public :: c_asperity_bora_solve
  public :: c_asperity_bora_separation_at_load
  public :: c_asperity_sergienko_bukharov_run
  public :: c_asperity_gw_eval_batch
  public :: c_asperity_gw_separation_at_load
  public :: c_asperity_gw_plasticity_index
  public :: c_asperity_plasticity_index
  public :: c_asperity_deformation_regime
  public :: c_asperity_gw_empirical_new
  public :: c_asperity_gw_empirical_free
  public :: c_asperity_gw_empirical_eval
  public :: c_asperity_gw_empirical_eval_batch
  public :: c_asperity_gw_empirical_separation_at_load
  public :: c_asperity_gw_empirical_plasticity_index
  public :: c_asperity_zhuravlev_linear
  public :: c_asperity_zhuravlev_approach_at_load_linear
  public :: c_asperity_zhuravlev_friction_linear
  public :: c_asperity_zhuravlev_eval
  public :: c_asperity_status_string
  public :: c_asperity_roughness_parameters
  public :: c_asperity_profile_remove_form
  public :: c_asperity_profile_gaussian_filter
  public :: c_asperity_material_ratio_curve
  public :: c_asperity_profile_psd
  public :: c_asperity_profile_hurst_fit
  public :: c_asperity_profile_hurst_estimate
  public :: c_asperity_map_gaussian_filter
  public :: c_asperity_map_psd_radial
  public :: c_asperity_profile_peak_statistics
  public :: c_asperity_generate_self_affine
  public :: c_asperity_generate_weierstrass_mandelbrot
  public :: c_asperity_generate_cantor_borodich
  public :: c_asperity_table_new_maugis_dugdale
  public :: c_asperity_table_new_lj
  public :: c_asperity_table_free
  public :: c_asperity_table_eval
  public :: c_asperity_table_eval_batch
  public :: c_asperity_table_eval_at_load
  public :: c_asperity_table_pull_off_force
  public :: c_asperity_table_reach
  public :: c_asperity_table_max_error
  public :: c_asperity_table_to_json
  public :: c_asperity_table_from_json

  ! The friendly layer.
  public :: asperity_version
  public :: asperity_last_error_message
  public :: asperity_status_string
  public :: asperity_type_layout
  public :: asperity_type_count
  public :: asperity_type_name
  public :: asperity_law_from_params
  public :: asperity_law_hertz
  public :: asperity_law_sphere_in_crater
  public :: asperity_law_power_punch
  public :: asperity_law_cone
  public :: asperity_law_cone_in_imprint
  public :: asperity_law_flat_punch
  public :: asperity_law_flat_punch_no_slip
  public :: asperity_law_dmt
  public :: asperity_law_jkr
  public :: asperity_law_jkr_power_punch
  public :: asperity_law_kendall
  public :: asperity_law_maugis_dugdale
  public :: asperity_law_derjaguin
  public :: asperity_normal_eval
  public :: asperity_normal_eval_batch
  public :: asperity_normal_eval_at_load
  public :: asperity_pull_off_force
  public :: asperity_normal_reach
  public :: asperity_normal_energy
  public :: asperity_law_length_scale
  public :: asperity_fidelity_advise
  public :: asperity_slider_geometry_new
  public :: asperity_slider_geometry_new_uniform
  public :: asperity_friction_lugre_new
  public :: asperity_friction_maxwell_slip_new
  public :: asperity_friction_generalized_maxwell_slip_new
  public :: asperity_archard_exponent
  public :: asperity_archard_area_batch
  public :: asperity_cantor_contact_batch
  public :: asperity_cantor_exponents
  public :: asperity_schmittbuhl_run
  public :: asperity_schmittbuhl_default
  public :: asperity_borodich_kryukova_normal_force
  public :: asperity_borodich_kryukova_run
  public :: asperity_friction_bristles_new
  public :: asperity_friction_prandtl_tomlinson_new
  public :: asperity_friction_prandtl_tomlinson_two_spring_new
  public :: asperity_friction_burridge_knopoff_new
  public :: asperity_friction_from_homogenised
  public :: asperity_friction_from_slider
  public :: asperity_friction_state_size
  public :: asperity_friction_work_new
  public :: asperity_friction_step
  public :: asperity_friction_step_in_place
  public :: asperity_friction_step_block
  public :: asperity_friction_step_block_in_place
  public :: asperity_friction_step_block_responses
  public :: asperity_slider_options_default
  public :: asperity_friction_material_copper
  public :: asperity_slider_new
  public :: asperity_slider_geometry_nano
  public :: asperity_slider_geometry_level_count
  public :: asperity_slider_geometry_rod_count
  public :: asperity_slider_geometry_rod_width
  public :: asperity_slider_geometry_rod_heights
  public :: asperity_homogenised_friction_new
  public :: asperity_homogenised_friction_from_json
  public :: asperity_homogenised_friction_to_json
  public :: asperity_slider_from_scene_json
  public :: asperity_slider_get_info
  public :: asperity_slider_get_record
  public :: asperity_indentation_default_options
  public :: asperity_indentation_fit
  public :: asperity_indentation_flag_name
  public :: asperity_afm_analyze
  public :: asperity_afm_flag_name
  public :: asperity_rescaling_depth
  public :: asperity_rescaling_radius
  public :: asperity_rescaling_load
  public :: asperity_rescaling_lambda_spheres
  public :: asperity_rescaling_lambda_cones
  public :: asperity_rescaling_kappa_from_slope
  public :: asperity_rescaling_d_from_unloading_slope
  public :: asperity_rescaling_d_from_loading_slope
  public :: asperity_galanov_unloading_radius
  public :: asperity_galanov_medium_radius
  public :: asperity_hardness_brinell
  public :: asperity_hardness_meyer
  public :: asperity_hardness_ludwik
  public :: asperity_hardness_vickers
  public :: asperity_lj_sphere_pull_off
  public :: asperity_effective_modulus
  public :: asperity_rod_effective_modulus
  public :: asperity_no_slip_factor
  public :: asperity_tabor_parameter
  public :: asperity_maugis_parameter
  public :: asperity_weir_surface_energy
  public :: asperity_weir_surface_energy_with
  public :: asperity_pair_work_of_adhesion
  public :: asperity_hamaker_work_of_adhesion
  public :: asperity_gw_eval
  public :: asperity_bgt_eval
  public :: asperity_bgt_eval_batch
  public :: asperity_bgt_separation_at_load
  public :: asperity_bgt_properties
  public :: asperity_bora_new
  public :: asperity_bora_free
  public :: asperity_bora_solve
  public :: asperity_bora_separation_at_load
  public :: asperity_sergienko_bukharov_run
  public :: asperity_gw_eval_batch
  public :: asperity_gw_separation_at_load
  public :: asperity_gw_plasticity_index
  public :: asperity_plasticity_index
  public :: asperity_deformation_regime
  public :: asperity_gw_empirical_new
  public :: asperity_gw_empirical_eval
  public :: asperity_gw_empirical_eval_batch
  public :: asperity_gw_empirical_separation_at_load
  public :: asperity_gw_empirical_plasticity_index
  public :: asperity_zhuravlev_linear
  public :: asperity_zhuravlev_approach_at_load_linear
  public :: asperity_zhuravlev_friction_linear
  public :: asperity_zhuravlev_eval
  public :: asperity_roughness_parameters
  public :: asperity_profile_remove_form
  public :: asperity_profile_gaussian_filter
  public :: asperity_material_ratio_curve
  public :: asperity_profile_psd
  public :: asperity_profile_hurst_fit
  public :: asperity_profile_hurst_estimate
  public :: asperity_map_gaussian_filter
  public :: asperity_map_psd_radial
  public :: asperity_profile_peak_statistics
  public :: asperity_generate_self_affine
  public :: asperity_generate_weierstrass_mandelbrot
  public :: asperity_generate_cantor_borodich
  public :: asperity_table_new_maugis_dugdale
  public :: asperity_table_new_lj
  public :: asperity_table_eval
  public :: asperity_table_eval_batch
  public :: asperity_table_eval_at_load
  public :: asperity_table_pull_off_force
  public :: asperity_table_reach
  public :: asperity_table_max_error
  public :: asperity_table_to_json
  public :: asperity_table_from_json
  public :: asperity_table_free
  public :: asperity_gw_empirical_free
  public :: asperity_homogenised_friction_free
  public :: asperity_slider_geometry_free
  public :: asperity_slider_free
  public :: asperity_friction_free
  public :: asperity_friction_work_free

  ! The friendly layer's own argument errors (per thread under OpenMP).
  logical :: fortran_error_set = .false.
  character(len=:), allocatable :: fortran_error
  !$omp threadprivate(fortran_error_set, fortran_error)

contains

  ! ------------------------------------------------------------------------
  ! Friendly layer: helpers (private).

  !> Record the outcome `st` of the C call `what`: into `status` when present,
  !> otherwise stop the program with the library's message on failure.
  subroutine check(st, what, status)
    integer(c_int32_t), intent(in) :: st
    character(len=*), intent(in) :: what
    integer(c_int32_t), intent(out), optional :: status
    if (st /= ASPERITY_OK) fortran_error_set = .false.
    if (present(status)) then
      status = st
    else if (st /= ASPERITY_OK) then
      call stop_on(what, st, asperity_last_error_message())
    end if
  end subroutine check

  !> An argument error found by the friendly layer itself (array sizes):
  !> `ASPERITY_ERR_INVALID_ARGUMENT` with `message`, like a library error.
  subroutine local_error(what, message, status)
    character(len=*), intent(in) :: what, message
    integer(c_int32_t), intent(out), optional :: status
    fortran_error = message
    fortran_error_set = .true.
    if (present(status)) then
      status = ASPERITY_ERR_INVALID_ARGUMENT
    else
      call stop_on(what, ASPERITY_ERR_INVALID_ARGUMENT, message)
    end if
  end subroutine local_error

  subroutine stop_on(what, st, message)
    character(len=*), intent(in) :: what, message
    integer(c_int32_t), intent(in) :: st
    write (error_unit, '(a)') 'asperity: '//what//' failed: status '//itoa(int(st, c_int64_t)) &
        //' ('//asperity_status_string(st)//'): '//message
    flush (error_unit)
    error stop 'asperity: a call without a status argument failed (message above)'
  end subroutine stop_on

  !> True (and the error reported) when an array of `got` elements is given
  !> where `need` are needed.
  logical function too_small(what, arg, got, need, ref, status)
    character(len=*), intent(in) :: what, arg, ref
    integer, intent(in) :: got, need
    integer(c_int32_t), intent(out), optional :: status
    too_small = got < need
    if (too_small) then
      call local_error(what, 'invalid argument `'//arg//'` of size '//itoa(int(got, c_int64_t)) &
          //': must hold at least '//itoa(int(need, c_int64_t))//' elements ('//ref//')', status)
    end if
  end function too_small

  !> True (and the error reported) when `in_place` is given together with
  !> `old_state` or `new_state`.
  logical function state_clash(what, in_place, old_or_new, status)
    character(len=*), intent(in) :: what
    logical, intent(in) :: in_place, old_or_new
    integer(c_int32_t), intent(out), optional :: status
    state_clash = in_place .and. old_or_new
    if (state_clash) then
      call local_error(what, 'invalid argument `state`: must not be given with `old_state` or '// &
          '`new_state` (it is both)', status)
    end if
  end function state_clash

  pure function itoa(i) result(s)
    integer(c_int64_t), intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function itoa

  !> The NUL-terminated C string at `p` ('' for NULL).
  function c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = chars(i)
    end do
  end function c_string

  !> The first `n` characters of `buf`.
  function from_chars(buf, n) result(s)
    character(kind=c_char), intent(in) :: buf(:)
    integer, intent(in) :: n
    character(len=:), allocatable :: s
    integer :: i
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = buf(i)
    end do
  end function from_chars

  ! Addresses of optional arguments for the raw layer: c_loc, or NULL when
  ! absent or empty.
  function loc_d(x) result(p)
    real(c_double), optional, target, contiguous :: x(:)
    type(c_ptr) :: p
    p = c_null_ptr
    if (present(x)) then
      if (size(x) > 0) p = c_loc(x)
    end if
  end function loc_d

  function loc_d0(x) result(p)
    real(c_double), optional, target :: x
    type(c_ptr) :: p
    p = c_null_ptr
    if (present(x)) p = c_loc(x)
  end function loc_d0

  function loc_i(x) result(p)
    integer(c_int32_t), optional, target, contiguous :: x(:)
    type(c_ptr) :: p
    p = c_null_ptr
    if (present(x)) then
      if (size(x) > 0) p = c_loc(x)
    end if
  end function loc_i

  function loc_contact(x) result(p)
    type(asperity_contact_state), optional, target :: x
    type(c_ptr) :: p
    p = c_null_ptr
    if (present(x)) p = c_loc(x)
  end function loc_contact

  function loc_contacts(x) result(p)
    type(asperity_contact_state), optional, target, contiguous :: x(:)
    type(c_ptr) :: p
    p = c_null_ptr
    if (present(x)) then
      if (size(x) > 0) p = c_loc(x)
    end if
  end function loc_contacts

  !> The C pointer of an optional scratch handle (NULL when absent).
  function loc_work(work) result(p)
    type(asperity_friction_work), intent(in), optional :: work
    type(c_ptr) :: p
    p = c_null_ptr
    if (present(work)) p = work%ptr
  end function loc_work

  !> Check the optional state arrays of a batch call of `n` contacts and give
  !> the old and new pointers for the raw call.
  subroutine contact_states(what, n, old_state, new_state, states, p_old, p_new, bad, status)
    character(len=*), intent(in) :: what
    integer, intent(in) :: n
    type(asperity_contact_state), optional, target, contiguous :: old_state(:), new_state(:), &
        states(:)
    type(c_ptr), intent(out) :: p_old, p_new
    logical, intent(out) :: bad
    integer(c_int32_t), intent(out), optional :: status
    p_old = c_null_ptr
    p_new = c_null_ptr
    bad = state_clash(what, present(states), present(old_state) .or. present(new_state), status)
    if (bad) return
    if (present(states)) then
      bad = too_small(what, 'states', size(states), n, 'one per contact', status)
      p_old = loc_contacts(states)
      p_new = p_old
      return
    end if
    if (present(old_state)) then
      bad = too_small(what, 'old_state', size(old_state), n, 'one per contact', status)
      if (bad) return
      p_old = loc_contacts(old_state)
    end if
    if (present(new_state)) then
      bad = too_small(what, 'new_state', size(new_state), n, 'one per contact', status)
      p_new = loc_contacts(new_state)
    end if
  end subroutine contact_states

  ! ------------------------------------------------------------------------
  ! Handles: free, assignment guard, finalisation.

  subroutine stop_copy(what)
    character(len=*), intent(in) :: what
    write (error_unit, '(a)') 'asperity: a live '//what//' handle cannot be copied with `=` '// &
        '(both copies would free the same object); pass it as an argument or use a pointer'
    flush (error_unit)
    error stop 'asperity: handle copied'
  end subroutine stop_copy

  !> Release `table` (an empty handle is accepted); `table` becomes empty.
  subroutine asperity_table_free(table)
    class(asperity_table), intent(inout) :: table
    call c_asperity_table_free(table%ptr)
    table%ptr = c_null_ptr
  end subroutine asperity_table_free

  subroutine asperity_table_assign(lhs, rhs)
    class(asperity_table), intent(inout) :: lhs
    type(asperity_table), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_table')
    end if
    call asperity_table_free(lhs)
  end subroutine asperity_table_assign

  impure elemental subroutine asperity_table_final(table)
    type(asperity_table), intent(inout) :: table
    call asperity_table_free(table)
  end subroutine asperity_table_final

  !> Release `gw` (an empty handle is accepted); `gw` becomes empty.
  subroutine asperity_gw_empirical_free(gw)
    class(asperity_gw_empirical), intent(inout) :: gw
    call c_asperity_gw_empirical_free(gw%ptr)
    gw%ptr = c_null_ptr
  end subroutine asperity_gw_empirical_free

  subroutine asperity_gw_empirical_assign(lhs, rhs)
    class(asperity_gw_empirical), intent(inout) :: lhs
    type(asperity_gw_empirical), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_gw_empirical')
    end if
    call asperity_gw_empirical_free(lhs)
  end subroutine asperity_gw_empirical_assign

  impure elemental subroutine asperity_gw_empirical_final(gw)
    type(asperity_gw_empirical), intent(inout) :: gw
    call asperity_gw_empirical_free(gw)
  end subroutine asperity_gw_empirical_final

  !> Release `bora` (an empty handle is accepted); `bora` becomes empty.
  subroutine asperity_bora_free(bora)
    class(asperity_bora), intent(inout) :: bora
    call c_asperity_bora_free(bora%ptr)
    bora%ptr = c_null_ptr
  end subroutine asperity_bora_free

  subroutine asperity_bora_assign(lhs, rhs)
    class(asperity_bora), intent(inout) :: lhs
    type(asperity_bora), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_bora')
    end if
    call asperity_bora_free(lhs)
  end subroutine asperity_bora_assign

  impure elemental subroutine asperity_bora_final(bora)
    type(asperity_bora), intent(inout) :: bora
    call asperity_bora_free(bora)
  end subroutine asperity_bora_final

  !> Release `friction` (an empty handle is accepted); `friction` becomes empty.
  subroutine asperity_homogenised_friction_free(friction)
    class(asperity_homogenised_friction), intent(inout) :: friction
    call c_asperity_homogenised_friction_free(friction%ptr)
    friction%ptr = c_null_ptr
  end subroutine asperity_homogenised_friction_free

  subroutine asperity_homogenised_friction_assign(lhs, rhs)
    class(asperity_homogenised_friction), intent(inout) :: lhs
    type(asperity_homogenised_friction), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_homogenised_friction')
    end if
    call asperity_homogenised_friction_free(lhs)
  end subroutine asperity_homogenised_friction_assign

  impure elemental subroutine asperity_homogenised_friction_final(friction)
    type(asperity_homogenised_friction), intent(inout) :: friction
    call asperity_homogenised_friction_free(friction)
  end subroutine asperity_homogenised_friction_final

  !> Release `geometry` (an empty handle is accepted); `geometry` becomes empty.
  subroutine asperity_slider_geometry_free(geometry)
    class(asperity_slider_geometry), intent(inout) :: geometry
    call c_asperity_slider_geometry_free(geometry%ptr)
    geometry%ptr = c_null_ptr
  end subroutine asperity_slider_geometry_free

  subroutine asperity_slider_geometry_assign(lhs, rhs)
    class(asperity_slider_geometry), intent(inout) :: lhs
    type(asperity_slider_geometry), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_slider_geometry')
    end if
    call asperity_slider_geometry_free(lhs)
  end subroutine asperity_slider_geometry_assign

  impure elemental subroutine asperity_slider_geometry_final(geometry)
    type(asperity_slider_geometry), intent(inout) :: geometry
    call asperity_slider_geometry_free(geometry)
  end subroutine asperity_slider_geometry_final

  !> Release `slider` (an empty handle is accepted); `slider` becomes empty.
  subroutine asperity_slider_free(slider)
    class(asperity_slider), intent(inout) :: slider
    call c_asperity_slider_free(slider%ptr)
    slider%ptr = c_null_ptr
  end subroutine asperity_slider_free

  subroutine asperity_slider_assign(lhs, rhs)
    class(asperity_slider), intent(inout) :: lhs
    type(asperity_slider), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_slider')
    end if
    call asperity_slider_free(lhs)
  end subroutine asperity_slider_assign

  impure elemental subroutine asperity_slider_final(slider)
    type(asperity_slider), intent(inout) :: slider
    call asperity_slider_free(slider)
  end subroutine asperity_slider_final

  !> Release `law` (an empty handle is accepted); `law` becomes empty.
  subroutine asperity_friction_free(law)
    class(asperity_friction), intent(inout) :: law
    call c_asperity_friction_free(law%ptr)
    law%ptr = c_null_ptr
  end subroutine asperity_friction_free

  subroutine asperity_friction_assign(lhs, rhs)
    class(asperity_friction), intent(inout) :: lhs
    type(asperity_friction), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_friction')
    end if
    call asperity_friction_free(lhs)
  end subroutine asperity_friction_assign

  impure elemental subroutine asperity_friction_final(law)
    type(asperity_friction), intent(inout) :: law
    call asperity_friction_free(law)
  end subroutine asperity_friction_final

  !> Release `work` (an empty handle is accepted); `work` becomes empty.
  subroutine asperity_friction_work_free(work)
    class(asperity_friction_work), intent(inout) :: work
    call c_asperity_friction_work_free(work%ptr)
    work%ptr = c_null_ptr
  end subroutine asperity_friction_work_free

  subroutine asperity_friction_work_assign(lhs, rhs)
    class(asperity_friction_work), intent(inout) :: lhs
    type(asperity_friction_work), intent(in) :: rhs
    if (c_associated(rhs%ptr)) then
      if (c_associated(lhs%ptr, rhs%ptr)) return
      call stop_copy('asperity_friction_work')
    end if
    call asperity_friction_work_free(lhs)
  end subroutine asperity_friction_work_assign

  impure elemental subroutine asperity_friction_work_final(work)
    type(asperity_friction_work), intent(inout) :: work
    call asperity_friction_work_free(work)
  end subroutine asperity_friction_work_final

  ! ------------------------------------------------------------------------
  ! Friendly layer: version, errors, layouts.

  !> The library version, "MAJOR.MINOR.PATCH".
  function asperity_version() result(version)
    character(len=:), allocatable :: version
    version = c_string(c_asperity_version())
  end function asperity_version

  !> The message of the last failed call on this thread ('' before the
  !> first failure): the library's, or the friendly layer's own when it
  !> rejected the arguments itself.
  function asperity_last_error_message() result(message)
    character(len=:), allocatable :: message
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n
    if (fortran_error_set) then
      message = fortran_error
      return
    end if
    n = c_asperity_last_error_message(c_null_ptr, 0_c_size_t)
    allocate (buf(n + 1))
    n = c_asperity_last_error_message(c_loc(buf), n + 1)
    message = from_chars(buf, int(min(n, size(buf, kind=c_size_t) - 1)))
  end function asperity_last_error_message

  !> A description of a status code ("unknown status" for a value that is
  !> not one).
  function asperity_status_string(status) result(text)
    integer(c_int32_t), intent(in) :: status
    character(len=:), allocatable :: text
    text = c_string(c_asperity_status_string(status))
  end function asperity_status_string

  !> Size and alignment (bytes) of the C type `name` (e.g. "AsperityNormalLaw").
  subroutine asperity_type_layout(name, size, align, status)
    character(len=*), intent(in) :: name
    integer(c_size_t), intent(out) :: size
    integer(c_size_t), intent(out), optional :: align
    integer(c_int32_t), intent(out), optional :: status
    integer(c_size_t) :: a
    size = 0
    a = 0
    call check(c_asperity_type_layout(trim(name)//c_null_char, size, a), &
        'asperity_type_layout', status)
    if (present(align)) align = a
  end subroutine asperity_type_layout

  !> The number of C types `asperity_type_layout` knows.
  function asperity_type_count() result(count)
    integer(c_size_t) :: count
    count = c_asperity_type_count()
  end function asperity_type_count

  !> The C name of type `index` (0-based, < `asperity_type_count()`).
  subroutine asperity_type_name(index, name, status)
    integer(c_size_t), intent(in) :: index
    character(len=:), allocatable, intent(out) :: name
    integer(c_int32_t), intent(out), optional :: status
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n, cap
    integer(c_int32_t) :: st
    name = ''
    n = 0
    st = c_asperity_type_name(index, c_null_ptr, 0_c_size_t, n)
    if (st == ASPERITY_OK) then
      cap = n + 1
      allocate (buf(cap))
      st = c_asperity_type_name(index, c_loc(buf), cap, n)
      if (st == ASPERITY_OK) name = from_chars(buf, int(n))
    end if
    call check(st, 'asperity_type_name', status)
  end subroutine asperity_type_name

  ! ------------------------------------------------------------------------
  ! Friendly layer: single-asperity normal laws (contact.rs).

  !> The law of kind `kind` (`ASPERITY_LAW_KIND_*`) from its inputs `params` (the member of
  !  the C union that `kind` names, filled with `transfer`).
  subroutine asperity_law_from_params(kind, params, law, status)
    integer(c_int32_t), intent(in) :: kind
    type(asperity_law_params), intent(in) :: params
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_from_params(kind, params, law), 'asperity_law_from_params', status)
  end subroutine asperity_law_from_params

  !> Hertz sphere: radius R (m), contact modulus E* (Pa).
  subroutine asperity_law_hertz(radius, e_star, law, status)
    real(c_double), intent(in) :: radius, e_star
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_hertz(radius, e_star, law), 'asperity_law_hertz', status)
  end subroutine asperity_law_hertz

  !> Galanov effective sphere in a crater of radius `medium_radius` (m).
  subroutine asperity_law_sphere_in_crater(radius, medium_radius, e_star, law, status)
    real(c_double), intent(in) :: radius, medium_radius, e_star
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_sphere_in_crater(radius, medium_radius, e_star, law), &
        'asperity_law_sphere_in_crater', status)
  end subroutine asperity_law_sphere_in_crater

  !> Galin power-law punch `f(r) = b r^d`.
  subroutine asperity_law_power_punch(b, d, e_star, law, status)
    real(c_double), intent(in) :: b, d, e_star
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_power_punch(b, d, e_star, law), 'asperity_law_power_punch', status)
  end subroutine asperity_law_power_punch

  !> Cone of half-angle `half_angle` (rad).
  subroutine asperity_law_cone(half_angle, e_star, law, status)
    real(c_double), intent(in) :: half_angle, e_star
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_cone(half_angle, e_star, law), 'asperity_law_cone', status)
  end subroutine asperity_law_cone

  !> Galanov effective cone in an imprint.
  subroutine asperity_law_cone_in_imprint(indenter_half_angle, imprint_half_angle, e_star, law, &
      status)
    real(c_double), intent(in) :: indenter_half_angle, imprint_half_angle, e_star
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_cone_in_imprint(indenter_half_angle, imprint_half_angle, e_star, &
        law), 'asperity_law_cone_in_imprint', status)
  end subroutine asperity_law_cone_in_imprint

  !> Frictionless flat punch of radius a (m).
  subroutine asperity_law_flat_punch(radius, e_star, law, status)
    real(c_double), intent(in) :: radius, e_star
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_flat_punch(radius, e_star, law), 'asperity_law_flat_punch', status)
  end subroutine asperity_law_flat_punch

  !> Bonded (no-slip) flat punch.
  subroutine asperity_law_flat_punch_no_slip(radius, e_star, nu, law, status)
    real(c_double), intent(in) :: radius, e_star, nu
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_flat_punch_no_slip(radius, e_star, nu, law), &
        'asperity_law_flat_punch_no_slip', status)
  end subroutine asperity_law_flat_punch_no_slip

  !> DMT sphere.
  subroutine asperity_law_dmt(radius, e_star, work_of_adhesion, law, status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_dmt(radius, e_star, work_of_adhesion, law), 'asperity_law_dmt', &
        status)
  end subroutine asperity_law_dmt

  !> JKR sphere.
  subroutine asperity_law_jkr(radius, e_star, work_of_adhesion, law, status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_jkr(radius, e_star, work_of_adhesion, law), 'asperity_law_jkr', &
        status)
  end subroutine asperity_law_jkr

  !> JKR power-law punch (Borodich 2014); `no_slip` = 1 for a bonded punch.
  subroutine asperity_law_jkr_power_punch(b, d, e_star, work_of_adhesion, nu, no_slip, law, &
      status)
    real(c_double), intent(in) :: b, d, e_star, work_of_adhesion, nu
    integer(c_int32_t), intent(in) :: no_slip
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_jkr_power_punch(b, d, e_star, work_of_adhesion, nu, no_slip, law), &
        'asperity_law_jkr_power_punch', status)
  end subroutine asperity_law_jkr_power_punch

  !> Kendall adhesive flat punch; `no_slip` = 1 for a bonded punch.
  subroutine asperity_law_kendall(radius, e_star, work_of_adhesion, nu, no_slip, law, status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion, nu
    integer(c_int32_t), intent(in) :: no_slip
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_kendall(radius, e_star, work_of_adhesion, nu, no_slip, law), &
        'asperity_law_kendall', status)
  end subroutine asperity_law_kendall

  !> Maugis-Dugdale sphere with Dugdale cohesive stress `sigma0` (Pa).
  subroutine asperity_law_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, law, status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion, sigma0
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, law), &
        'asperity_law_maugis_dugdale', status)
  end subroutine asperity_law_maugis_dugdale

  !> Rigid sphere with a surface-force law (`ASPERITY_SURFACE_LAW_*`).
  subroutine asperity_law_derjaguin(radius, work_of_adhesion, surface_law, parameter, law, status)
    real(c_double), intent(in) :: radius, work_of_adhesion, parameter
    integer(c_int32_t), intent(in) :: surface_law
    type(asperity_normal_law), intent(out) :: law
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_law_derjaguin(radius, work_of_adhesion, surface_law, parameter, law), &
        'asperity_law_derjaguin', status)
  end subroutine asperity_law_derjaguin

  !> Evaluate `law` at the overlap `delta` (m) into `out`. History: `old_state`
  !> (absent: fresh) to `new_state` (absent: discarded), or `state` in place.
  subroutine asperity_normal_eval(law, delta, out, old_state, new_state, state, status)
    type(asperity_normal_law), intent(in) :: law
    real(c_double), intent(in) :: delta
    type(asperity_normal_response), intent(out) :: out
    type(asperity_contact_state), intent(in), optional, target :: old_state
    type(asperity_contact_state), intent(inout), optional, target :: new_state
    type(asperity_contact_state), intent(inout), optional, target :: state
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_normal_eval'
    if (state_clash(what, present(state), present(old_state) .or. present(new_state), status)) &
        return
    if (present(state)) then
      call check(c_asperity_normal_eval(law, delta, c_loc(state), c_loc(state), out), what, &
          status)
    else
      call check(c_asperity_normal_eval(law, delta, loc_contact(old_state), &
          loc_contact(new_state), out), what, status)
    end if
  end subroutine asperity_normal_eval

  !> Evaluate `law` for `size(delta)` contacts: `force(i)` (N) and, when
  !> given, `contact_radius(i)` (m), `stiffness(i)` (N/m); histories
  !> `old_state(i)` to `new_state(i)`, or `states(i)` in place.
  subroutine asperity_normal_eval_batch(law, delta, force, old_state, new_state, contact_radius, &
      stiffness, states, status)
    type(asperity_normal_law), intent(in) :: law
    real(c_double), intent(in) :: delta(:)
    real(c_double), intent(inout) :: force(:)
    type(asperity_contact_state), intent(in), optional, target, contiguous :: old_state(:)
    type(asperity_contact_state), intent(inout), optional, target, contiguous :: new_state(:)
    real(c_double), intent(inout), optional, target, contiguous :: contact_radius(:), stiffness(:)
    type(asperity_contact_state), intent(inout), optional, target, contiguous :: states(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_normal_eval_batch'
    type(c_ptr) :: p_old, p_new
    logical :: bad
    integer :: n
    n = size(delta)
    if (too_small(what, 'force', size(force), n, 'the size of `delta`', status)) return
    if (present(contact_radius)) then
      if (too_small(what, 'contact_radius', size(contact_radius), n, 'the size of `delta`', &
          status)) return
    end if
    if (present(stiffness)) then
      if (too_small(what, 'stiffness', size(stiffness), n, 'the size of `delta`', status)) return
    end if
    call contact_states(what, n, old_state, new_state, states, p_old, p_new, bad, status)
    if (bad) return
    call check(c_asperity_normal_eval_batch(law, int(n, c_size_t), delta, p_old, p_new, force, &
        loc_d(contact_radius), loc_d(stiffness)), what, status)
  end subroutine asperity_normal_eval_batch

  !> Equilibrium of `law` at the prescribed force `force` (N).
  subroutine asperity_normal_eval_at_load(law, force, out, status)
    type(asperity_normal_law), intent(in) :: law
    real(c_double), intent(in) :: force
    type(asperity_normal_response), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_normal_eval_at_load(law, force, out), 'asperity_normal_eval_at_load', &
        status)
  end subroutine asperity_normal_eval_at_load

  !> Pull-off force (N) under `control` (`ASPERITY_CONTROL_*`).
  subroutine asperity_pull_off_force(law, control, force, status)
    type(asperity_normal_law), intent(in) :: law
    integer(c_int32_t), intent(in) :: control
    real(c_double), intent(out) :: force
    integer(c_int32_t), intent(out), optional :: status
    force = 0
    call check(c_asperity_pull_off_force(law, control, force), 'asperity_pull_off_force', status)
  end subroutine asperity_pull_off_force

  !> Reach (m, ≤ 0) of `law` under `control` (`ASPERITY_CONTROL_*`): no force
  !> below it from any history (below `rel_force` × |pull-off| for infinite tails).
  subroutine asperity_normal_reach(law, control, rel_force, delta, status)
    type(asperity_normal_law), intent(in) :: law
    integer(c_int32_t), intent(in) :: control
    real(c_double), intent(in) :: rel_force
    real(c_double), intent(out) :: delta
    integer(c_int32_t), intent(out), optional :: status
    delta = 0
    call check(c_asperity_normal_reach(law, control, rel_force, delta), &
        'asperity_normal_reach', status)
  end subroutine asperity_normal_reach

  !> Energy (J) of the equilibrium at `delta` (m) from `old_state` (absent: fresh).
  subroutine asperity_normal_energy(law, delta, energy, old_state, status)
    type(asperity_normal_law), intent(in) :: law
    real(c_double), intent(in) :: delta
    real(c_double), intent(out) :: energy
    type(asperity_contact_state), intent(in), optional, target :: old_state
    integer(c_int32_t), intent(out), optional :: status
    energy = 0
    call check(c_asperity_normal_energy(law, delta, loc_contact(old_state), energy), &
        'asperity_normal_energy', status)
  end subroutine asperity_normal_energy

  !> A characteristic overlap of `law` (m).
  subroutine asperity_law_length_scale(law, length, status)
    type(asperity_normal_law), intent(in) :: law
    real(c_double), intent(out) :: length
    integer(c_int32_t), intent(out), optional :: status
    length = 0
    call check(c_asperity_law_length_scale(law, length), 'asperity_law_length_scale', status)
  end subroutine asperity_law_length_scale

  !> The cheapest adhesive-sphere model within `force_tolerance` (N).
  subroutine asperity_fidelity_advise(radius, e_star, work_of_adhesion, z0, force_tolerance, out, &
      status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion, z0, force_tolerance
    type(asperity_fidelity_advice), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_fidelity_advise(radius, e_star, work_of_adhesion, z0, force_tolerance, &
        out), 'asperity_fidelity_advise', status)
  end subroutine asperity_fidelity_advise

  ! ------------------------------------------------------------------------
  ! Friendly layer: the slider of the hierarchical friction model.

  !> A slider from a profilometer profile (`micro_heights`, spacing
  !> `micro_dx` m), an AFM profile (`nano_heights`, `nano_dx`) and nested rod
  !> widths `rod_widths` (m, coarsest first). An object `geometry` held is
  !> freed first.
  subroutine asperity_slider_geometry_new(micro_heights, micro_dx, nano_heights, nano_dx, &
      rod_widths, geometry, status)
    real(c_double), intent(in) :: micro_heights(:), nano_heights(:), rod_widths(:)
    real(c_double), intent(in) :: micro_dx, nano_dx
    type(asperity_slider_geometry), intent(inout) :: geometry
    integer(c_int32_t), intent(out), optional :: status
    call geometry%free()
    call check(c_asperity_slider_geometry_new(micro_heights, size(micro_heights, kind=c_size_t), &
        micro_dx, nano_heights, size(nano_heights, kind=c_size_t), nano_dx, rod_widths, &
        size(rod_widths, kind=c_size_t), geometry%ptr), 'asperity_slider_geometry_new', status)
  end subroutine asperity_slider_geometry_new

  !> A single-level slider of `rods` flat rods of `rod_width` (m) carrying
  !> `nano%per_rod` nano-asperities each.
  subroutine asperity_slider_geometry_new_uniform(rod_width, rods, nano, geometry, status)
    real(c_double), intent(in) :: rod_width
    integer, intent(in) :: rods
    type(asperity_nano_asperities), intent(in) :: nano
    type(asperity_slider_geometry), intent(inout) :: geometry
    integer(c_int32_t), intent(out), optional :: status
    call geometry%free()
    call check(c_asperity_slider_geometry_new_uniform(rod_width, int(rods, c_size_t), nano, &
        geometry%ptr), 'asperity_slider_geometry_new_uniform', status)
  end subroutine asperity_slider_geometry_new_uniform

  !> The nano-asperity parameters of `geometry`.
  subroutine asperity_slider_geometry_nano(geometry, out, status)
    type(asperity_slider_geometry), intent(in) :: geometry
    type(asperity_nano_asperities), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_slider_geometry_nano(geometry%ptr, out), &
        'asperity_slider_geometry_nano', status)
  end subroutine asperity_slider_geometry_nano

  !> The number of rod levels of `geometry`.
  subroutine asperity_slider_geometry_level_count(geometry, count, status)
    type(asperity_slider_geometry), intent(in) :: geometry
    integer, intent(out) :: count
    integer(c_int32_t), intent(out), optional :: status
    integer(c_size_t) :: c
    c = 0
    call check(c_asperity_slider_geometry_level_count(geometry%ptr, c), &
        'asperity_slider_geometry_level_count', status)
    count = int(c)
  end subroutine asperity_slider_geometry_level_count

  !> The number of rods of `level` (0 = coarsest).
  subroutine asperity_slider_geometry_rod_count(geometry, level, count, status)
    type(asperity_slider_geometry), intent(in) :: geometry
    integer, intent(in) :: level
    integer, intent(out) :: count
    integer(c_int32_t), intent(out), optional :: status
    integer(c_size_t) :: c
    c = 0
    call check(c_asperity_slider_geometry_rod_count(geometry%ptr, int(level, c_size_t), c), &
        'asperity_slider_geometry_rod_count', status)
    count = int(c)
  end subroutine asperity_slider_geometry_rod_count

  !> The rod width (m) of `level` and the left side of its rod 0 (m).
  subroutine asperity_slider_geometry_rod_width(geometry, level, width, origin, status)
    type(asperity_slider_geometry), intent(in) :: geometry
    integer, intent(in) :: level
    real(c_double), intent(out) :: width
    real(c_double), intent(out), optional, target :: origin
    integer(c_int32_t), intent(out), optional :: status
    width = 0
    call check(c_asperity_slider_geometry_rod_width(geometry%ptr, int(level, c_size_t), width, &
        loc_d0(origin)), 'asperity_slider_geometry_rod_width', status)
  end subroutine asperity_slider_geometry_rod_width

  !> The rod heights (m) of `level` into `heights` (at least the rod count).
  subroutine asperity_slider_geometry_rod_heights(geometry, level, heights, status)
    type(asperity_slider_geometry), intent(in) :: geometry
    integer, intent(in) :: level
    real(c_double), intent(inout) :: heights(:)
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_slider_geometry_rod_heights(geometry%ptr, int(level, c_size_t), &
        heights, size(heights, kind=c_size_t)), 'asperity_slider_geometry_rod_heights', status)
  end subroutine asperity_slider_geometry_rod_heights

  ! ------------------------------------------------------------------------
  ! Friendly layer: the homogenised friction law of FE points.

  !> The law from `samples` at strictly increasing nominal pressures.
  !> An object `friction` held is freed first.
  subroutine asperity_homogenised_friction_new(samples, friction, status)
    type(asperity_homogenised_sample), intent(in) :: samples(:)
    type(asperity_homogenised_friction), intent(inout) :: friction
    integer(c_int32_t), intent(out), optional :: status
    call friction%free()
    call check(c_asperity_homogenised_friction_new(samples, size(samples, kind=c_size_t), &
        friction%ptr), 'asperity_homogenised_friction_new', status)
  end subroutine asperity_homogenised_friction_new

  !> The law from its JSON text. An object `friction` held is freed first.
  subroutine asperity_homogenised_friction_from_json(json, friction, status)
    character(len=*, kind=c_char), intent(in) :: json
    type(asperity_homogenised_friction), intent(inout) :: friction
    integer(c_int32_t), intent(out), optional :: status
    call friction%free()
    call check(c_asperity_homogenised_friction_from_json(json, len(json, kind=c_size_t), &
        friction%ptr), 'asperity_homogenised_friction_from_json', status)
  end subroutine asperity_homogenised_friction_from_json

  !> The JSON text of `friction`.
  subroutine asperity_homogenised_friction_to_json(friction, json, status)
    type(asperity_homogenised_friction), intent(in) :: friction
    character(len=:), allocatable, intent(out) :: json
    integer(c_int32_t), intent(out), optional :: status
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n, cap
    integer(c_int32_t) :: st
    json = ''
    n = 0
    st = c_asperity_homogenised_friction_to_json(friction%ptr, c_null_ptr, 0_c_size_t, n)
    if (st == ASPERITY_OK) then
      cap = n + 1
      allocate (buf(cap))
      st = c_asperity_homogenised_friction_to_json(friction%ptr, c_loc(buf), cap, n)
      if (st == ASPERITY_OK) json = from_chars(buf, int(n))
    end if
    call check(st, 'asperity_homogenised_friction_to_json', status)
  end subroutine asperity_homogenised_friction_to_json

  ! ------------------------------------------------------------------------
  ! Friendly layer: the hierarchical slider.

  !> The library's default slider options (fixed load 0 N: set `normal_force`).
  subroutine asperity_slider_options_default(options, status)
    type(asperity_slider_options), intent(out) :: options
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_slider_options_default(options), 'asperity_slider_options_default', &
        status)
  end subroutine asperity_slider_options_default

  !> The thesis's Cu-Cu friction material (REFERENCE.md §5).
  subroutine asperity_friction_material_copper(material, status)
    type(asperity_friction_material), intent(out) :: material
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_friction_material_copper(material), &
        'asperity_friction_material_copper', status)
  end subroutine asperity_friction_material_copper

  !> A slider from structs into `slider`: the rods of `geometry` (copied), `material`, the
  !> counter-surface heights `counter` (m) at spacing `counter_dx` (m), and `options`. An
  !> object `slider` held is freed first.
  subroutine asperity_slider_new(geometry, material, counter, counter_dx, options, slider, status)
    type(asperity_slider_geometry), intent(in) :: geometry
    type(asperity_friction_material), intent(in) :: material
    real(c_double), intent(in) :: counter(:)
    real(c_double), intent(in) :: counter_dx
    type(asperity_slider_options), intent(in) :: options
    type(asperity_slider), intent(inout) :: slider
    integer(c_int32_t), intent(out), optional :: status
    call slider%free()
    call check(c_asperity_slider_new(geometry%ptr, material, counter, &
        size(counter, kind=c_size_t), counter_dx, options, slider%ptr), 'asperity_slider_new', &
        status)
  end subroutine asperity_slider_new

  !> A slider from the scene JSON text `json` (the format of
  !> `examples/scenes/*.json`); relative file paths in the scene are resolved
  !> against `base_dir` (absent: the current directory). A JSON or field
  !> error is `ASPERITY_ERR_PARSE`, its message giving the line, column and
  !> field. An object `slider` held is freed first.
  subroutine asperity_slider_from_scene_json(json, slider, base_dir, status)
    character(len=*, kind=c_char), intent(in) :: json
    type(asperity_slider), intent(inout) :: slider
    character(len=*), intent(in), optional :: base_dir
    integer(c_int32_t), intent(out), optional :: status
    character(kind=c_char), allocatable, target :: dir(:)
    type(c_ptr) :: p_dir
    integer :: i, n
    call slider%free()
    p_dir = c_null_ptr
    if (present(base_dir)) then
      n = len_trim(base_dir)
      allocate (dir(n + 1))
      do i = 1, n
        dir(i) = base_dir(i:i)
      end do
      dir(n + 1) = c_null_char
      p_dir = c_loc(dir)
    end if
    call check(c_asperity_slider_from_scene_json(json, len(json, kind=c_size_t), p_dir, &
        slider%ptr), 'asperity_slider_from_scene_json', status)
  end subroutine asperity_slider_from_scene_json

  !> The sizes and capacities of `slider` into `info` (C: `asperity_slider_info`; in Fortran
  !> that name is the type of `info`, and a type and a procedure cannot share a name).
  subroutine asperity_slider_get_info(slider, info, status)
    type(asperity_slider), intent(in) :: slider
    type(asperity_slider_info), intent(out) :: info
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_slider_info(slider%ptr, info), 'asperity_slider_info', status)
  end subroutine asperity_slider_get_info

  !> The full record of the last step `work` took with a slider law
  !> (`asperity_friction_from_slider`) into `record`: the positions (m), the
  !> adhesion area share, the counts of contacts and `seated` (1 when the
  !> step seated a fresh state first); all zero for a work made for a slider
  !> law that has not stepped yet. An empty work, or one of another law, is
  !> an error naming `work`. (C: `asperity_slider_record`; in Fortran that
  !> name is the type of `record`.)
  subroutine asperity_slider_get_record(work, record, status)
    type(asperity_friction_work), intent(in) :: work
    type(asperity_slider_record), intent(out) :: record
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_slider_record(work%ptr, record), 'asperity_slider_record', status)
  end subroutine asperity_slider_get_record

  ! ------------------------------------------------------------------------
  ! Friendly layer: the friction step, one handle for every friction law.

  !> The homogenised law of `table` (copied) with the stick stiffness `stick_stiffness` (N/m,
  !> >= 0; 0: rigid-plastic) into `law`; its increments need the nominal `area` > 0. An object
  !> `law` held is freed first.
  subroutine asperity_friction_from_homogenised(table, stick_stiffness, law, status)
    type(asperity_homogenised_friction), intent(in) :: table
    real(c_double), intent(in) :: stick_stiffness
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    call law%free()
    call check(c_asperity_friction_from_homogenised(table%ptr, stick_stiffness, law%ptr), &
        'asperity_friction_from_homogenised', status)
  end subroutine asperity_friction_from_homogenised

  !> The slider (copied) as the friction law of a surface patch into `law`: the increment's
  !> normal force is the fixed load (at most the capacity), its area is unused. An object `law`
  !> held is freed first.
  subroutine asperity_friction_from_slider(slider, law, status)
    type(asperity_slider), intent(in) :: slider
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    call law%free()
    call check(c_asperity_friction_from_slider(slider%ptr, law%ptr), &
        'asperity_friction_from_slider', status)
  end subroutine asperity_friction_from_slider

  !> A LuGre model from `params` into `law` (an object held is freed first).
  subroutine asperity_friction_lugre_new(params, law, status)
    type(asperity_lugre_params), intent(in) :: params
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    call law%free()
    call check(c_asperity_friction_lugre_new(params, law%ptr), 'asperity_friction_lugre_new', &
        status)
  end subroutine asperity_friction_lugre_new

  !> Maxwell-slip elements of stiffnesses `stiffness` (1/m per unit normal force) and
  !> break-away coefficients `capacity` (same size), viscous `sigma2` (N s/m), into `law`.
  subroutine asperity_friction_maxwell_slip_new(stiffness, capacity, sigma2, law, status)
    real(c_double), intent(in) :: stiffness(:)
    real(c_double), intent(in) :: capacity(:)
    real(c_double), intent(in) :: sigma2
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_maxwell_slip_new'
    call law%free()
    if (too_small(what, 'capacity', size(capacity), size(stiffness), 'size(stiffness)', status)) &
        return
    call check(c_asperity_friction_maxwell_slip_new(stiffness, capacity, &
        size(stiffness, kind=c_size_t), sigma2, law%ptr), what, status)
  end subroutine asperity_friction_maxwell_slip_new

  !> The generalised Maxwell-slip model: elements of stiffnesses `stiffness` (1/m per unit
  !> normal force) and weights `weight` (same size) attracted to the Stribeck curve of
  !> `params`, into `law`. One-dimensional, rate dependent.
  subroutine asperity_friction_generalized_maxwell_slip_new(stiffness, weight, params, law, &
      status)
    real(c_double), intent(in) :: stiffness(:)
    real(c_double), intent(in) :: weight(:)
    type(asperity_generalized_maxwell_slip_params), intent(in) :: params
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_generalized_maxwell_slip_new'
    call law%free()
    if (too_small(what, 'weight', size(weight), size(stiffness), 'size(stiffness)', status)) &
        return
    call check(c_asperity_friction_generalized_maxwell_slip_new(stiffness, weight, &
        size(stiffness, kind=c_size_t), params, law%ptr), what, status)
  end subroutine asperity_friction_generalized_maxwell_slip_new

  !> The exponent `a` of Archard's A ~ W^a for `model` (`ASPERITY_ARCHARD_UNIFORM` or
  !> `ASPERITY_ARCHARD_NON_UNIFORM`) with `generations` sphere radii.
  subroutine asperity_archard_exponent(model, generations, a, status)
    integer(c_int32_t), intent(in) :: model
    integer, intent(in) :: generations
    real(c_double), intent(out) :: a
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_archard_exponent(model, int(generations, c_size_t), a), &
        'asperity_archard_exponent', status)
  end subroutine asperity_archard_exponent

  !> Archard's real contact areas `area` (m^2, size(load)) under `load` (N) for the sphere
  !> radii `radii` (m, decreasing), densities `densities` (1/m^2, size(radii) - 1) and
  !> contact modulus `contact_modulus` (Pa).
  subroutine asperity_archard_area_batch(model, radii, densities, contact_modulus, load, area, &
      status)
    integer(c_int32_t), intent(in) :: model
    real(c_double), intent(in) :: radii(:)
    real(c_double), intent(in), target :: densities(:)
    real(c_double), intent(in) :: contact_modulus
    real(c_double), intent(in) :: load(:)
    real(c_double), intent(inout) :: area(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_archard_area_batch'
    real(c_double) :: none(1)
    if (too_small(what, 'area', size(area), size(load), 'size(load)', status)) return
    if (size(densities) == 0) then
      none = 0.0_c_double
      call check(c_asperity_archard_area_batch(model, radii, none, &
          size(radii, kind=c_size_t), contact_modulus, size(load, kind=c_size_t), load, area), &
          what, status)
    else
      call check(c_asperity_archard_area_batch(model, radii, densities, &
          size(radii, kind=c_size_t), contact_modulus, size(load, kind=c_size_t), load, area), &
          what, status)
    end if
  end subroutine asperity_archard_area_batch

  !> The contact `out` (size(depth)) of the Cantor profile `profile` at the depths `depth` (m)
  !> on a Winkler foundation of stiffness `stiffness` (Pa/m) and a rigid-plastic one of
  !> hardness `hardness` (Pa).
  subroutine asperity_cantor_contact_batch(profile, stiffness, hardness, depth, out, status)
    type(asperity_cantor_profile), intent(in) :: profile
    real(c_double), intent(in) :: stiffness, hardness
    real(c_double), intent(in) :: depth(:)
    type(asperity_cantor_contact), intent(inout) :: out(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_cantor_contact_batch'
    if (too_small(what, 'out', size(out), size(depth), 'size(depth)', status)) return
    call check(c_asperity_cantor_contact_batch(profile, stiffness, hardness, &
        size(depth, kind=c_size_t), depth, out), what, status)
  end subroutine asperity_cantor_contact_batch

  !> The Cantor profile's fractal dimension, width exponent beta and load-area exponent
  !> beta/(1 + beta).
  subroutine asperity_cantor_exponents(profile, fractal_dimension, width_exponent, &
      load_area_exponent, status)
    type(asperity_cantor_profile), intent(in) :: profile
    real(c_double), intent(out) :: fractal_dimension, width_exponent, load_area_exponent
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_cantor_exponents(profile, fractal_dimension, width_exponent, &
        load_area_exponent), 'asperity_cantor_exponents', status)
  end subroutine asperity_cantor_exponents

  !> The renormalised friction laws of generations 0..`model%generations` into `laws` (at least
  !> generations + 1 elements); `written` receives the number written.
  subroutine asperity_schmittbuhl_run(model, laws, written, status)
    type(asperity_schmittbuhl), intent(in) :: model
    type(asperity_schmittbuhl_generation), intent(inout) :: laws(:)
    integer(c_size_t), intent(out) :: written
    integer(c_int32_t), intent(out), optional :: status
    written = 0
    call check(c_asperity_schmittbuhl_run(model, size(laws, kind=c_size_t), laws, written), &
        'asperity_schmittbuhl_run', status)
  end subroutine asperity_schmittbuhl_run

  !> The library's default Schmittbuhl model (mu_s 0.5, mu_k 0.3, v_c 0.05 m/s, N 3, G 3, d 3).
  subroutine asperity_schmittbuhl_default(model, status)
    type(asperity_schmittbuhl), intent(out) :: model
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_schmittbuhl_default(model), 'asperity_schmittbuhl_default', status)
  end subroutine asperity_schmittbuhl_default

  !> The layers' elastic normal force `force` (N) of the Borodich-Kryukova slider `bk` at
  !> position `x` (m), mean-line distance `y` (m) and time `time` (s).
  subroutine asperity_borodich_kryukova_normal_force(bk, x, y, time, force, status)
    type(asperity_borodich_kryukova), intent(in) :: bk
    real(c_double), intent(in) :: x, y, time
    real(c_double), intent(out) :: force
    integer(c_int32_t), intent(out), optional :: status
    force = 0
    call check(c_asperity_borodich_kryukova_normal_force(bk, x, y, time, force), &
        'asperity_borodich_kryukova_normal_force', status)
  end subroutine asperity_borodich_kryukova_normal_force

  !> Runge-Kutta 4 of the slider `bk` from `start` for `steps` steps of `dt` (s), the start and
  !> every `every`-th step into `samples` (at least steps/every + 1 elements); `written`
  !> receives the number written.
  subroutine asperity_borodich_kryukova_run(bk, start, dt, steps, every, samples, written, &
      status)
    type(asperity_borodich_kryukova), intent(in) :: bk
    type(asperity_borodich_kryukova_state), intent(in) :: start
    real(c_double), intent(in) :: dt
    integer(c_int32_t), intent(in) :: steps, every
    type(asperity_borodich_kryukova_sample), intent(inout) :: samples(:)
    integer(c_size_t), intent(out) :: written
    integer(c_int32_t), intent(out), optional :: status
    written = 0
    call check(c_asperity_borodich_kryukova_run(bk, start, dt, steps, every, &
        size(samples, kind=c_size_t), samples, written), 'asperity_borodich_kryukova_run', &
        status)
  end subroutine asperity_borodich_kryukova_run

  !> Bristles of stiffnesses `stiffness` (1/m per unit normal force) and break
  !> deflections `break_deflection` (m, same size), viscous `sigma2` (N s/m), into `law`.
  subroutine asperity_friction_bristles_new(stiffness, break_deflection, sigma2, law, status)
    real(c_double), intent(in) :: stiffness(:)
    real(c_double), intent(in) :: break_deflection(:)
    real(c_double), intent(in) :: sigma2
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_bristles_new'
    call law%free()
    if (too_small(what, 'break_deflection', size(break_deflection), size(stiffness), &
        'size(stiffness)', status)) return
    call check(c_asperity_friction_bristles_new(stiffness, break_deflection, &
        size(stiffness, kind=c_size_t), sigma2, law%ptr), what, status)
  end subroutine asperity_friction_bristles_new

  !> A Prandtl-Tomlinson tip into `law`: lattice amplitude `amplitude` (J) and period
  !> `period` (m), spring `stiffness` (N/m), `mass` (kg), `damping` (kg/s), integration
  !> `tolerance`.
  subroutine asperity_friction_prandtl_tomlinson_new(amplitude, period, stiffness, mass, &
      damping, tolerance, law, status)
    real(c_double), intent(in) :: amplitude, period, stiffness, mass, damping, tolerance
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    call law%free()
    call check(c_asperity_friction_prandtl_tomlinson_new(amplitude, period, stiffness, mass, &
        damping, tolerance, law%ptr), 'asperity_friction_prandtl_tomlinson_new', status)
  end subroutine asperity_friction_prandtl_tomlinson_new

  !> A two-spring (tip-cantilever) Prandtl-Tomlinson model of `params` into `law` (state
  !> size 7).
  subroutine asperity_friction_prandtl_tomlinson_two_spring_new(params, law, status)
    type(asperity_prandtl_tomlinson_two_spring_params), intent(in) :: params
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    call law%free()
    call check(c_asperity_friction_prandtl_tomlinson_two_spring_new(params, law%ptr), &
        'asperity_friction_prandtl_tomlinson_two_spring_new', status)
  end subroutine asperity_friction_prandtl_tomlinson_two_spring_new

  !> A Burridge-Knopoff block chain of `params` into `law` (state size 3 + 2 blocks).
  subroutine asperity_friction_burridge_knopoff_new(params, law, status)
    type(asperity_burridge_knopoff_params), intent(in) :: params
    type(asperity_friction), intent(inout) :: law
    integer(c_int32_t), intent(out), optional :: status
    call law%free()
    call check(c_asperity_friction_burridge_knopoff_new(params, law%ptr), &
        'asperity_friction_burridge_knopoff_new', status)
  end subroutine asperity_friction_burridge_knopoff_new

  !> The number of doubles `n` of one point's state of `law`.
  subroutine asperity_friction_state_size(law, n, status)
    type(asperity_friction), intent(in) :: law
    integer, intent(out) :: n
    integer(c_int32_t), intent(out), optional :: status
    integer(c_size_t) :: c
    c = 0
    call check(c_asperity_friction_state_size(law%ptr, c), 'asperity_friction_state_size', &
        status)
    n = int(c)
  end subroutine asperity_friction_state_size

  !> The scratch of a step with `law` into `work`: one per thread (a scratch
  !> made for another law is rebuilt on first use). An object `work` held is
  !> freed first.
  subroutine asperity_friction_work_new(law, work, status)
    type(asperity_friction), intent(in) :: law
    type(asperity_friction_work), intent(inout) :: work
    integer(c_int32_t), intent(out), optional :: status
    call work%free()
    call check(c_asperity_friction_work_new(law%ptr, work%ptr), 'asperity_friction_work_new', &
        status)
  end subroutine asperity_friction_work_new

  !> The state size of `law` for the size checks of `what`; -1 (and the
  !> library's error reported) when the library cannot give it.
  function friction_state_len(law, what, status) result(m)
    type(asperity_friction), intent(in) :: law
    character(len=*), intent(in) :: what
    integer(c_int32_t), intent(out), optional :: status
    integer :: m
    integer(c_size_t) :: c
    integer(c_int32_t) :: st
    c = 0
    st = c_asperity_friction_state_size(law%ptr, c)
    m = int(c)
    if (st /= ASPERITY_OK) then
      m = -1
      call check(st, what, status)
    end if
  end function friction_state_len

  !> One increment of one point into `out`: `old_state` to `new_state` (each
  !> at least `asperity_friction_state_size` values; all-zero = fresh), with
  !> this thread's `work` (absent: a scratch per call, which the slider
  !> allocates). The same old state and increment give bit-identical
  !> results, so an increment can be re-evaluated or cut back. On failure
  !> `new_state` is untouched.
  subroutine asperity_friction_step(law, increment, old_state, new_state, out, work, status)
    type(asperity_friction), intent(in) :: law
    type(asperity_friction_increment), intent(in) :: increment
    real(c_double), intent(in), target, contiguous :: old_state(:)
    real(c_double), intent(inout), target, contiguous :: new_state(:)
    type(asperity_friction_response), intent(out) :: out
    type(asperity_friction_work), intent(inout), optional :: work
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_step'
    integer :: m
    m = friction_state_len(law, what, status)
    if (m < 0) return
    if (too_small(what, 'old_state', size(old_state), m, 'the state size', status)) return
    if (too_small(what, 'new_state', size(new_state), m, 'the state size', status)) return
    call check(c_asperity_friction_step(law%ptr, increment, c_loc(old_state), &
        c_loc(new_state), loc_work(work), out), what, status)
  end subroutine asperity_friction_step

  !> `asperity_friction_step` with the point's `state` updated in place (on
  !> failure it is untouched).
  subroutine asperity_friction_step_in_place(law, increment, state, out, work, status)
    type(asperity_friction), intent(in) :: law
    type(asperity_friction_increment), intent(in) :: increment
    real(c_double), intent(inout) :: state(:)
    type(asperity_friction_response), intent(out) :: out
    type(asperity_friction_work), intent(inout), optional :: work
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_step_in_place'
    integer :: m
    m = friction_state_len(law, what, status)
    if (m < 0) return
    if (too_small(what, 'state', size(state), m, 'the state size', status)) return
    call check(c_asperity_friction_step_in_place(law%ptr, increment, state, loc_work(work), &
        out), what, status)
  end subroutine asperity_friction_step_in_place

  !> True (and the error reported) unless the arrays of a block of `n`
  !> points with states of `m` values fit: `slip_increments` and
  !> `tangential_forces` (2, n), `areas` and `dissipation` (n) when given.
  logical function bad_block(what, n, slip_increments, tangential_forces, areas, dissipation, &
      status)
    character(len=*), intent(in) :: what
    integer, intent(in) :: n
    real(c_double), intent(in) :: slip_increments(:, :), tangential_forces(:, :)
    real(c_double), intent(in), optional :: areas(:), dissipation(:)
    integer(c_int32_t), intent(out), optional :: status
    bad_block = .true.
    if (present(areas)) then
      if (too_small(what, 'areas', size(areas), n, 'the size of `normal_forces`', status)) return
    end if
    if (size(slip_increments, 1) /= 2) then
      call local_error(what, 'invalid argument `slip_increments`: the first dimension must be '// &
          '2 (x and y), not '//itoa(int(size(slip_increments, 1), c_int64_t)), status)
      return
    end if
    if (size(tangential_forces, 1) /= 2) then
      call local_error(what, 'invalid argument `tangential_forces`: the first dimension must '// &
          'be 2 (x and y), not '//itoa(int(size(tangential_forces, 1), c_int64_t)), status)
      return
    end if
    if (too_small(what, 'slip_increments', size(slip_increments, 2), n, &
        'columns, the size of `normal_forces`', status)) return
    if (too_small(what, 'tangential_forces', size(tangential_forces, 2), n, &
        'columns, the size of `normal_forces`', status)) return
    if (present(dissipation)) then
      if (too_small(what, 'dissipation', size(dissipation), n, 'the size of `normal_forces`', &
          status)) return
    end if
    bad_block = .false.
  end function bad_block

  !> True (and the error reported) unless the states `x` of argument `arg`
  !> are columns of the state size `m`, at least `n` of them.
  logical function bad_states(what, arg, x, m, n, status)
    character(len=*), intent(in) :: what, arg
    real(c_double), intent(in) :: x(:, :)
    integer, intent(in) :: m, n
    integer(c_int32_t), intent(out), optional :: status
    bad_states = .true.
    if (size(x, 1) /= m) then
      call local_error(what, 'invalid argument `'//arg//'`: the first dimension must be '// &
          'the state size '//itoa(int(m, c_int64_t))//', not '// &
          itoa(int(size(x, 1), c_int64_t)), status)
      return
    end if
    bad_states = too_small(what, arg, size(x, 2), n, 'columns, one per point', status)
  end function bad_states

  !> Step `size(normal_forces)` points at once (the call of an Abaqus VFRIC):
  !> normal forces `normal_forces(i)` (N), slip increments
  !> `slip_increments(1:2, i)` (m), one `dt` (s), the states `old_states(:, i)`
  !> to `new_states(:, i)` (columns of `asperity_friction_state_size`
  !> values), tangential forces out in `tangential_forces(1:2, i)` (N,
  !> opposing slip); when given, the nominal areas `areas(i)` (m^2; the
  !> homogenised law needs them) and the dissipated energy out in
  !> `dissipation(i)` (J); this thread's `work` (absent: a scratch per call).
  !> No tangents (`asperity_friction_step_block_responses` gives them). On
  !> an error at C's element i (Fortran's point i + 1), the points before it
  !> are written and the rest untouched.
  subroutine asperity_friction_step_block(law, normal_forces, slip_increments, dt, old_states, &
      new_states, tangential_forces, areas, dissipation, work, status)
    type(asperity_friction), intent(in) :: law
    real(c_double), intent(in) :: normal_forces(:), slip_increments(:, :)
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), target, contiguous :: old_states(:, :)
    real(c_double), intent(inout), target, contiguous :: new_states(:, :)
    real(c_double), intent(inout) :: tangential_forces(:, :)
    real(c_double), intent(in), optional, target, contiguous :: areas(:)
    real(c_double), intent(inout), optional, target, contiguous :: dissipation(:)
    type(asperity_friction_work), intent(inout), optional :: work
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_step_block'
    type(c_ptr) :: p_old, p_new
    integer :: n, m
    n = size(normal_forces)
    if (bad_block(what, n, slip_increments, tangential_forces, areas, dissipation, status)) &
        return
    m = friction_state_len(law, what, status)
    if (m < 0) return
    if (bad_states(what, 'old_states', old_states, m, n, status)) return
    if (bad_states(what, 'new_states', new_states, m, n, status)) return
    p_old = c_null_ptr
    p_new = c_null_ptr
    if (n > 0) then
      p_old = c_loc(old_states)
      p_new = c_loc(new_states)
    end if
    call check(c_asperity_friction_step_block(law%ptr, int(n, c_size_t), normal_forces, &
        loc_d(areas), slip_increments, dt, p_old, p_new, tangential_forces, loc_d(dissipation), &
        loc_work(work)), what, status)
  end subroutine asperity_friction_step_block

  !> `asperity_friction_step_block` with each point's full response (an
  !> implicit host's call): the states `old_states(:, i)` to
  !> `new_states(:, i)` of the points with normal forces `normal_forces(i)` (N), slip increments
  !> `slip_increments(1:2, i)` (m) and one `dt` (s), and `responses(i)` as
  !> `asperity_friction_step` gives it with the tangents `tangents` (0, or
  !> `ASPERITY_FRICTION_TANGENT_NORMAL` + `ASPERITY_FRICTION_TANGENT_SLIP`,
  !> for every point): the force (N), the dissipated and stored energies
  !> (J), the regime, dF/dN and dF/d(slip) (N/m); when given, the nominal
  !> areas `areas(i)` (m^2); this thread's `work` (absent: a scratch per
  !> call). On an error at C's element i (Fortran's point i + 1), the points
  !> before it are written and the rest untouched. In place: the raw
  !> `c_asperity_friction_step_block_responses` with `c_loc` of one array
  !> as both states (Fortran forbids one actual argument twice here).
  subroutine asperity_friction_step_block_responses(law, normal_forces, slip_increments, dt, &
      tangents, old_states, new_states, responses, areas, work, status)
    type(asperity_friction), intent(in) :: law
    real(c_double), intent(in) :: normal_forces(:), slip_increments(:, :)
    real(c_double), intent(in) :: dt
    integer(c_int32_t), intent(in) :: tangents
    real(c_double), intent(in), target, contiguous :: old_states(:, :)
    real(c_double), intent(inout), target, contiguous :: new_states(:, :)
    type(asperity_friction_response), intent(inout) :: responses(:)
    real(c_double), intent(in), optional, target, contiguous :: areas(:)
    type(asperity_friction_work), intent(inout), optional :: work
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_step_block_responses'
    type(c_ptr) :: p_old, p_new
    integer :: n, m
    n = size(normal_forces)
    if (present(areas)) then
      if (too_small(what, 'areas', size(areas), n, 'the size of `normal_forces`', status)) return
    end if
    if (size(slip_increments, 1) /= 2) then
      call local_error(what, 'invalid argument `slip_increments`: the first dimension must be '// &
          '2 (x and y), not '//itoa(int(size(slip_increments, 1), c_int64_t)), status)
      return
    end if
    if (too_small(what, 'slip_increments', size(slip_increments, 2), n, &
        'columns, the size of `normal_forces`', status)) return
    if (too_small(what, 'responses', size(responses), n, 'the size of `normal_forces`', status)) &
        return
    m = friction_state_len(law, what, status)
    if (m < 0) return
    if (bad_states(what, 'old_states', old_states, m, n, status)) return
    if (bad_states(what, 'new_states', new_states, m, n, status)) return
    p_old = c_null_ptr
    p_new = c_null_ptr
    if (n > 0) then
      p_old = c_loc(old_states)
      p_new = c_loc(new_states)
    end if
    call check(c_asperity_friction_step_block_responses(law%ptr, int(n, c_size_t), &
        normal_forces, loc_d(areas), slip_increments, dt, tangents, p_old, p_new, responses, &
        loc_work(work)), what, status)
  end subroutine asperity_friction_step_block_responses

  !> `asperity_friction_step_block` with the states `states(:, i)` stepped in
  !> place.
  subroutine asperity_friction_step_block_in_place(law, normal_forces, slip_increments, dt, &
      states, tangential_forces, areas, dissipation, work, status)
    type(asperity_friction), intent(in) :: law
    real(c_double), intent(in) :: normal_forces(:), slip_increments(:, :)
    real(c_double), intent(in) :: dt
    real(c_double), intent(inout) :: states(:, :)
    real(c_double), intent(inout) :: tangential_forces(:, :)
    real(c_double), intent(in), optional, target, contiguous :: areas(:)
    real(c_double), intent(inout), optional, target, contiguous :: dissipation(:)
    type(asperity_friction_work), intent(inout), optional :: work
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_friction_step_block_in_place'
    integer :: n, m
    n = size(normal_forces)
    if (bad_block(what, n, slip_increments, tangential_forces, areas, dissipation, status)) &
        return
    m = friction_state_len(law, what, status)
    if (m < 0) return
    if (bad_states(what, 'states', states, m, n, status)) return
    call check(c_asperity_friction_step_block_in_place(law%ptr, int(n, c_size_t), normal_forces, &
        loc_d(areas), slip_increments, dt, states, tangential_forces, loc_d(dissipation), &
        loc_work(work)), what, status)
  end subroutine asperity_friction_step_block_in_place

  ! ------------------------------------------------------------------------
  ! Friendly layer: indentation, rescaling, hardness (indentation.rs).

  !> The default options of `asperity_indentation_fit`.
  subroutine asperity_indentation_default_options(options, status)
    type(asperity_indentation_options), intent(out) :: options
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_indentation_default_options(options), &
        'asperity_indentation_default_options', status)
  end subroutine asperity_indentation_default_options

  !> Fit a load-depth curve of `size(depth)` points; `segments`
  !> (`ASPERITY_SEGMENT_*` per point) and `options` are optional.
  subroutine asperity_indentation_fit(depth, load, result, segments, options, status)
    real(c_double), intent(in) :: depth(:), load(:)
    type(asperity_indentation_result), intent(out) :: result
    integer(c_int32_t), intent(in), optional, target, contiguous :: segments(:)
    type(asperity_indentation_options), intent(in), optional, target :: options
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_indentation_fit'
    type(c_ptr) :: p_options
    integer :: n
    n = size(depth)
    if (too_small(what, 'load', size(load), n, 'the size of `depth`', status)) return
    if (present(segments)) then
      if (too_small(what, 'segments', size(segments), n, 'the size of `depth`', status)) return
    end if
    p_options = c_null_ptr
    if (present(options)) p_options = c_loc(options)
    call check(c_asperity_indentation_fit(int(n, c_size_t), depth, load, loc_i(segments), &
        p_options, result), what, status)
  end subroutine asperity_indentation_fit

  !> The code of flag bit `bit` ('' for a bit without a flag).
  function asperity_indentation_flag_name(bit) result(name)
    integer(c_int32_t), intent(in) :: bit
    character(len=:), allocatable :: name
    name = c_string(c_asperity_indentation_flag_name(bit))
  end function asperity_indentation_flag_name

  !> Analyse an AFM force–distance curve of `size(position)` points: `signal` is the force (N)
  !> or, with `input_kind = ASPERITY_AFM_INPUT_DEFLECTION`, the deflection (m); `tip_radius`
  !> (m, default 0 = unknown), `model` (default AUTO) and `retract_start` (default 0: the
  !> turning point) are optional.
  subroutine asperity_afm_analyze(position, signal, spring_constant, result, tip_radius, model, &
      input_kind, retract_start, status)
    real(c_double), intent(in) :: position(:), signal(:)
    real(c_double), intent(in) :: spring_constant
    type(asperity_afm_result), intent(out) :: result
    real(c_double), intent(in), optional :: tip_radius
    integer(c_int32_t), intent(in), optional :: model, input_kind
    integer(c_size_t), intent(in), optional :: retract_start
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_afm_analyze'
    real(c_double) :: r
    integer(c_int32_t) :: m, k
    integer(c_size_t) :: rs
    integer :: n
    n = size(position)
    if (too_small(what, 'signal', size(signal), n, 'the size of `position`', status)) return
    r = 0.0_c_double
    if (present(tip_radius)) r = tip_radius
    m = ASPERITY_AFM_MODEL_AUTO
    if (present(model)) m = model
    k = ASPERITY_AFM_INPUT_FORCE
    if (present(input_kind)) k = input_kind
    rs = 0_c_size_t
    if (present(retract_start)) rs = retract_start
    call check(c_asperity_afm_analyze(int(n, c_size_t), position, signal, k, rs, &
        spring_constant, r, m, result), what, status)
  end subroutine asperity_afm_analyze

  !> The code of AFM flag bit `bit` ('' for a bit without a flag).
  function asperity_afm_flag_name(bit) result(name)
    integer(c_int32_t), intent(in) :: bit
    character(len=:), allocatable :: name
    name = c_string(c_asperity_afm_flag_name(bit))
  end function asperity_afm_flag_name

  !> Depth (m) at `load` (N) by Borodich rescaling (3-13).
  subroutine asperity_rescaling_depth(kappa, d, lambda, load, known_load, known_depth, depth, &
      status)
    real(c_double), intent(in) :: kappa, d, lambda, load, known_load, known_depth
    real(c_double), intent(out) :: depth
    integer(c_int32_t), intent(out), optional :: status
    depth = 0
    call check(c_asperity_rescaling_depth(kappa, d, lambda, load, known_load, known_depth, &
        depth), 'asperity_rescaling_depth', status)
  end subroutine asperity_rescaling_depth

  !> Contact radius (m) at `load` (N) by rescaling (3-14).
  subroutine asperity_rescaling_radius(kappa, d, lambda, load, known_load, known_radius, radius, &
      status)
    real(c_double), intent(in) :: kappa, d, lambda, load, known_load, known_radius
    real(c_double), intent(out) :: radius
    integer(c_int32_t), intent(out), optional :: status
    radius = 0
    call check(c_asperity_rescaling_radius(kappa, d, lambda, load, known_load, known_radius, &
        radius), 'asperity_rescaling_radius', status)
  end subroutine asperity_rescaling_radius

  !> Load (N) at `depth` (m) by rescaling (3-24).
  subroutine asperity_rescaling_load(kappa, d, lambda, depth, known_load, known_depth, load, &
      status)
    real(c_double), intent(in) :: kappa, d, lambda, depth, known_load, known_depth
    real(c_double), intent(out) :: load
    integer(c_int32_t), intent(out), optional :: status
    load = 0
    call check(c_asperity_rescaling_load(kappa, d, lambda, depth, known_load, known_depth, load), &
        'asperity_rescaling_load', status)
  end subroutine asperity_rescaling_load

  !> Lambda for spheres, R1/R (3-15).
  subroutine asperity_rescaling_lambda_spheres(known_radius, radius, lambda, status)
    real(c_double), intent(in) :: known_radius, radius
    real(c_double), intent(out) :: lambda
    integer(c_int32_t), intent(out), optional :: status
    lambda = 0
    call check(c_asperity_rescaling_lambda_spheres(known_radius, radius, lambda), &
        'asperity_rescaling_lambda_spheres', status)
  end subroutine asperity_rescaling_lambda_spheres

  !> Lambda for cones, tan(g1)/tan(g) (3-16).
  subroutine asperity_rescaling_lambda_cones(known_half_angle, half_angle, lambda, status)
    real(c_double), intent(in) :: known_half_angle, half_angle
    real(c_double), intent(out) :: lambda
    integer(c_int32_t), intent(out), optional :: status
    lambda = 0
    call check(c_asperity_rescaling_lambda_cones(known_half_angle, half_angle, lambda), &
        'asperity_rescaling_lambda_cones', status)
  end subroutine asperity_rescaling_lambda_cones

  !> Kappa from the loading log-log slope and d ((3-20), (3-26)).
  subroutine asperity_rescaling_kappa_from_slope(loading_slope, d, kappa, status)
    real(c_double), intent(in) :: loading_slope, d
    real(c_double), intent(out) :: kappa
    integer(c_int32_t), intent(out), optional :: status
    kappa = 0
    call check(c_asperity_rescaling_kappa_from_slope(loading_slope, d, kappa), &
        'asperity_rescaling_kappa_from_slope', status)
  end subroutine asperity_rescaling_kappa_from_slope

  !> d from the elastic unloading slope.
  subroutine asperity_rescaling_d_from_unloading_slope(unloading_slope, d, status)
    real(c_double), intent(in) :: unloading_slope
    real(c_double), intent(out) :: d
    integer(c_int32_t), intent(out), optional :: status
    d = 0
    call check(c_asperity_rescaling_d_from_unloading_slope(unloading_slope, d), &
        'asperity_rescaling_d_from_unloading_slope', status)
  end subroutine asperity_rescaling_d_from_unloading_slope

  !> d from the loading slope and a known kappa.
  subroutine asperity_rescaling_d_from_loading_slope(loading_slope, kappa, d, status)
    real(c_double), intent(in) :: loading_slope, kappa
    real(c_double), intent(out) :: d
    integer(c_int32_t), intent(out), optional :: status
    d = 0
    call check(c_asperity_rescaling_d_from_loading_slope(loading_slope, kappa, d), &
        'asperity_rescaling_d_from_loading_slope', status)
  end subroutine asperity_rescaling_d_from_loading_slope

  !> Galanov effective unloading radius (3-22).
  subroutine asperity_galanov_unloading_radius(r1, p1, delta1, p2, delta2, r2, status)
    real(c_double), intent(in) :: r1, p1, delta1, p2, delta2
    real(c_double), intent(out) :: r2
    integer(c_int32_t), intent(out), optional :: status
    r2 = 0
    call check(c_asperity_galanov_unloading_radius(r1, p1, delta1, p2, delta2, r2), &
        'asperity_galanov_unloading_radius', status)
  end subroutine asperity_galanov_unloading_radius

  !> Radius of the deformed medium (3-23).
  subroutine asperity_galanov_medium_radius(radius, unloading_radius, medium_radius, status)
    real(c_double), intent(in) :: radius, unloading_radius
    real(c_double), intent(out) :: medium_radius
    integer(c_int32_t), intent(out), optional :: status
    medium_radius = 0
    call check(c_asperity_galanov_medium_radius(radius, unloading_radius, medium_radius), &
        'asperity_galanov_medium_radius', status)
  end subroutine asperity_galanov_medium_radius

  !> Brinell hardness (2-7) (Pa).
  subroutine asperity_hardness_brinell(load, ball_diameter, imprint_diameter, hardness, status)
    real(c_double), intent(in) :: load, ball_diameter, imprint_diameter
    real(c_double), intent(out) :: hardness
    integer(c_int32_t), intent(out), optional :: status
    hardness = 0
    call check(c_asperity_hardness_brinell(load, ball_diameter, imprint_diameter, hardness), &
        'asperity_hardness_brinell', status)
  end subroutine asperity_hardness_brinell

  !> Meyer hardness (2-8) (Pa).
  subroutine asperity_hardness_meyer(load, imprint_diameter, hardness, status)
    real(c_double), intent(in) :: load, imprint_diameter
    real(c_double), intent(out) :: hardness
    integer(c_int32_t), intent(out), optional :: status
    hardness = 0
    call check(c_asperity_hardness_meyer(load, imprint_diameter, hardness), &
        'asperity_hardness_meyer', status)
  end subroutine asperity_hardness_meyer

  !> Ludwik hardness (2-10) (Pa).
  subroutine asperity_hardness_ludwik(load, imprint_diameter, hardness, status)
    real(c_double), intent(in) :: load, imprint_diameter
    real(c_double), intent(out) :: hardness
    integer(c_int32_t), intent(out), optional :: status
    hardness = 0
    call check(c_asperity_hardness_ludwik(load, imprint_diameter, hardness), &
        'asperity_hardness_ludwik', status)
  end subroutine asperity_hardness_ludwik

  !> Vickers hardness (2-12) (Pa).
  subroutine asperity_hardness_vickers(load, mean_diagonal, hardness, status)
    real(c_double), intent(in) :: load, mean_diagonal
    real(c_double), intent(out) :: hardness
    integer(c_int32_t), intent(out), optional :: status
    hardness = 0
    call check(c_asperity_hardness_vickers(load, mean_diagonal, hardness), &
        'asperity_hardness_vickers', status)
  end subroutine asperity_hardness_vickers

  !> Load-controlled pull-off force (N) of the Lennard-Jones sphere on
  !> `n_grid` cells (0: the converged default).
  subroutine asperity_lj_sphere_pull_off(radius, e_star, work_of_adhesion, z0, n_grid, force, &
      status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion, z0
    integer, intent(in) :: n_grid
    real(c_double), intent(out) :: force
    integer(c_int32_t), intent(out), optional :: status
    force = 0
    call check(c_asperity_lj_sphere_pull_off(radius, e_star, work_of_adhesion, z0, &
        int(n_grid, c_size_t), force), 'asperity_lj_sphere_pull_off', status)
  end subroutine asperity_lj_sphere_pull_off

  ! ------------------------------------------------------------------------
  ! Friendly layer: materials (material.rs).

  !> Contact modulus (Pa); a modulus of IEEE +infinity
  !> (`ieee_value(e, ieee_positive_inf)`) marks a rigid body.
  subroutine asperity_effective_modulus(e1, nu1, e2, nu2, e_star, status)
    real(c_double), intent(in) :: e1, nu1, e2, nu2
    real(c_double), intent(out) :: e_star
    integer(c_int32_t), intent(out), optional :: status
    e_star = 0
    call check(c_asperity_effective_modulus(e1, nu1, e2, nu2, e_star), &
        'asperity_effective_modulus', status)
  end subroutine asperity_effective_modulus

  !> Effective modulus of two rods end to end (Pa), (6-8).
  subroutine asperity_rod_effective_modulus(e1, e2, e_eff, status)
    real(c_double), intent(in) :: e1, e2
    real(c_double), intent(out) :: e_eff
    integer(c_int32_t), intent(out), optional :: status
    e_eff = 0
    call check(c_asperity_rod_effective_modulus(e1, e2, e_eff), &
        'asperity_rod_effective_modulus', status)
  end subroutine asperity_rod_effective_modulus

  !> No-slip factor C_NS(nu).
  subroutine asperity_no_slip_factor(nu, c_ns, status)
    real(c_double), intent(in) :: nu
    real(c_double), intent(out) :: c_ns
    integer(c_int32_t), intent(out), optional :: status
    c_ns = 0
    call check(c_asperity_no_slip_factor(nu, c_ns), 'asperity_no_slip_factor', status)
  end subroutine asperity_no_slip_factor

  !> Tabor parameter mu.
  subroutine asperity_tabor_parameter(radius, work_of_adhesion, e_star, equilibrium_separation, &
      mu, status)
    real(c_double), intent(in) :: radius, work_of_adhesion, e_star, equilibrium_separation
    real(c_double), intent(out) :: mu
    integer(c_int32_t), intent(out), optional :: status
    mu = 0
    call check(c_asperity_tabor_parameter(radius, work_of_adhesion, e_star, &
        equilibrium_separation, mu), 'asperity_tabor_parameter', status)
  end subroutine asperity_tabor_parameter

  !> Maugis parameter lambda.
  subroutine asperity_maugis_parameter(radius, work_of_adhesion, e_star, cohesive_stress, lambda, &
      status)
    real(c_double), intent(in) :: radius, work_of_adhesion, e_star, cohesive_stress
    real(c_double), intent(out) :: lambda
    integer(c_int32_t), intent(out), optional :: status
    lambda = 0
    call check(c_asperity_maugis_parameter(radius, work_of_adhesion, e_star, cohesive_stress, &
        lambda), 'asperity_maugis_parameter', status)
  end subroutine asperity_maugis_parameter

  !> Weir's surface energy (J/m^2).
  subroutine asperity_weir_surface_energy(atomic_mass, density, youngs_modulus, poisson_ratio, m, &
      n, gamma, status)
    real(c_double), intent(in) :: atomic_mass, density, youngs_modulus, poisson_ratio, m, n
    real(c_double), intent(out) :: gamma
    integer(c_int32_t), intent(out), optional :: status
    gamma = 0
    call check(c_asperity_weir_surface_energy(atomic_mass, density, youngs_modulus, &
        poisson_ratio, m, n, gamma), 'asperity_weir_surface_energy', status)
  end subroutine asperity_weir_surface_energy

  !> Weir's surface energy with the prefactor `ASPERITY_WEIR_*`.
  subroutine asperity_weir_surface_energy_with(atomic_mass, density, youngs_modulus, &
      poisson_ratio, m, n, prefactor, gamma, status)
    real(c_double), intent(in) :: atomic_mass, density, youngs_modulus, poisson_ratio, m, n
    integer(c_int32_t), intent(in) :: prefactor
    real(c_double), intent(out) :: gamma
    integer(c_int32_t), intent(out), optional :: status
    gamma = 0
    call check(c_asperity_weir_surface_energy_with(atomic_mass, density, youngs_modulus, &
        poisson_ratio, m, n, prefactor, gamma), 'asperity_weir_surface_energy_with', status)
  end subroutine asperity_weir_surface_energy_with

  !> Work of adhesion (J/m^2) of two surface energies under `rule`
  !> (`ASPERITY_PAIR_*`).
  subroutine asperity_pair_work_of_adhesion(gamma1, gamma2, rule, work_of_adhesion, status)
    real(c_double), intent(in) :: gamma1, gamma2
    integer(c_int32_t), intent(in) :: rule
    real(c_double), intent(out) :: work_of_adhesion
    integer(c_int32_t), intent(out), optional :: status
    work_of_adhesion = 0
    call check(c_asperity_pair_work_of_adhesion(gamma1, gamma2, rule, work_of_adhesion), &
        'asperity_pair_work_of_adhesion', status)
  end subroutine asperity_pair_work_of_adhesion

  !> Work of adhesion A/(12 pi D0^2) (J/m^2).
  subroutine asperity_hamaker_work_of_adhesion(hamaker, separation, work_of_adhesion, status)
    real(c_double), intent(in) :: hamaker, separation
    real(c_double), intent(out) :: work_of_adhesion
    integer(c_int32_t), intent(out), optional :: status
    work_of_adhesion = 0
    call check(c_asperity_hamaker_work_of_adhesion(hamaker, separation, work_of_adhesion), &
        'asperity_hamaker_work_of_adhesion', status)
  end subroutine asperity_hamaker_work_of_adhesion

  ! ------------------------------------------------------------------------
  ! Friendly layer: multi-asperity statistics (statistics.rs).

  !> Greenwood-Williamson load, area, contacts and stiffness at `separation` (m).
  subroutine asperity_gw_eval(gw, separation, out, status)
    type(asperity_gw_params), intent(in) :: gw
    real(c_double), intent(in) :: separation
    type(asperity_gw_response), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_gw_eval(gw, separation, out), 'asperity_gw_eval', status)
  end subroutine asperity_gw_eval

  !> `asperity_gw_eval` for `size(separation)` separations: `load(i)` (N)
  !> and, when given, `area(i)` (m^2), `contacts(i)`, `stiffness(i)` (N/m).
  subroutine asperity_gw_eval_batch(gw, separation, load, area, contacts, stiffness, status)
    type(asperity_gw_params), intent(in) :: gw
    real(c_double), intent(in) :: separation(:)
    real(c_double), intent(inout) :: load(:)
    real(c_double), intent(inout), optional, target, contiguous :: area(:), contacts(:), &
        stiffness(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_gw_eval_batch'
    if (gw_batch_sizes_bad(what, size(separation), load, area, contacts, stiffness, status)) &
        return
    call check(c_asperity_gw_eval_batch(gw, size(separation, kind=c_size_t), separation, load, &
        loc_d(area), loc_d(contacts), loc_d(stiffness)), what, status)
  end subroutine asperity_gw_eval_batch

  logical function gw_batch_sizes_bad(what, n, load, area, contacts, stiffness, status) result(bad)
    character(len=*), intent(in) :: what
    integer, intent(in) :: n
    real(c_double), intent(in) :: load(:)
    real(c_double), intent(in), optional :: area(:), contacts(:), stiffness(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: ref = 'the size of `separation`'
    bad = too_small(what, 'load', size(load), n, ref, status)
    if (bad) return
    if (present(area)) then
      bad = too_small(what, 'area', size(area), n, ref, status)
      if (bad) return
    end if
    if (present(contacts)) then
      bad = too_small(what, 'contacts', size(contacts), n, ref, status)
      if (bad) return
    end if
    if (present(stiffness)) bad = too_small(what, 'stiffness', size(stiffness), n, ref, status)
  end function gw_batch_sizes_bad

  !> Bush-Gibson-Thomas load, area, contacts and stiffness at `separation` (m).
  subroutine asperity_bgt_eval(bgt, separation, out, status)
    type(asperity_bgt_params), intent(in) :: bgt
    real(c_double), intent(in) :: separation
    type(asperity_bgt_response), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_bgt_eval(bgt, separation, out), 'asperity_bgt_eval', status)
  end subroutine asperity_bgt_eval

  !> `asperity_bgt_eval` for `size(separation)` separations: `load(i)` (N)
  !> and, when given, `area(i)` (m^2), `contacts(i)`, `stiffness(i)` (N/m).
  subroutine asperity_bgt_eval_batch(bgt, separation, load, area, contacts, stiffness, status)
    type(asperity_bgt_params), intent(in) :: bgt
    real(c_double), intent(in) :: separation(:)
    real(c_double), intent(inout) :: load(:)
    real(c_double), intent(inout), optional, target, contiguous :: area(:), contacts(:), &
        stiffness(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_bgt_eval_batch'
    if (gw_batch_sizes_bad(what, size(separation), load, area, contacts, stiffness, status)) &
        return
    call check(c_asperity_bgt_eval_batch(bgt, size(separation, kind=c_size_t), separation, &
        load, loc_d(area), loc_d(contacts), loc_d(stiffness)), what, status)
  end subroutine asperity_bgt_eval_batch

  !> The separation (m) at which the BGT surface carries `load` (N).
  subroutine asperity_bgt_separation_at_load(bgt, load, out, status)
    type(asperity_bgt_params), intent(in) :: bgt
    real(c_double), intent(in) :: load
    type(asperity_separation), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_bgt_separation_at_load(bgt, load, out), &
        'asperity_bgt_separation_at_load', status)
  end subroutine asperity_bgt_separation_at_load

  !> Nayak's summit density (1/m^2) and the small-load limit of A/P (m^2/N).
  subroutine asperity_bgt_properties(bgt, summit_density, area_per_load, status)
    type(asperity_bgt_params), intent(in) :: bgt
    real(c_double), intent(out), target :: summit_density, area_per_load
    integer(c_int32_t), intent(out), optional :: status
    summit_density = 0
    area_per_load = 0
    call check(c_asperity_bgt_properties(bgt, c_loc(summit_density), c_loc(area_per_load)), &
        'asperity_bgt_properties', status)
  end subroutine asperity_bgt_properties

  !> A Bora et al. interface on `nx` x `ny` `heights` (m, x fastest), grid
  !> `spacing` (m), `spring_stiffness` (N/m), substrate `contact_modulus`
  !> (Pa; 0: rigid). An object `bora` held is freed first.
  subroutine asperity_bora_new(nx, ny, spacing, heights, spring_stiffness, contact_modulus, &
      bora, status)
    integer, intent(in) :: nx, ny
    real(c_double), intent(in) :: spacing, spring_stiffness, contact_modulus
    real(c_double), intent(in) :: heights(:)
    type(asperity_bora), intent(inout) :: bora
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_bora_new'
    call bora%free()
    if (too_small(what, 'heights', size(heights), nx * ny, 'nx*ny', status)) return
    call check(c_asperity_bora_new(int(nx, c_size_t), int(ny, c_size_t), spacing, heights, &
        spring_stiffness, contact_modulus, bora%ptr), what, status)
  end subroutine asperity_bora_new

  !> The equilibrium of `bora` at `separation` (m); the spring forces (N)
  !> to `forces` when given (room for nx*ny).
  subroutine asperity_bora_solve(bora, separation, out, forces, status)
    type(asperity_bora), intent(in) :: bora
    real(c_double), intent(in) :: separation
    type(asperity_bora_response), intent(out) :: out
    real(c_double), intent(inout), optional, target, contiguous :: forces(:)
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_bora_solve(bora%ptr, separation, out, loc_d(forces)), &
        'asperity_bora_solve', status)
  end subroutine asperity_bora_solve

  !> The separation (m) at which `bora` carries `load` (N).
  subroutine asperity_bora_separation_at_load(bora, load, out, status)
    type(asperity_bora), intent(in) :: bora
    real(c_double), intent(in) :: load
    type(asperity_separation), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_bora_separation_at_load(bora%ptr, load, out), &
        'asperity_bora_separation_at_load', status)
  end subroutine asperity_bora_separation_at_load

  !> One Sergienko–Bukharov run of `params` (thesis 5.3.5, the library's formulation) on the
  !> spring-top `heights` (m; read for `ASPERITY_HEIGHTS_LIST`, any size otherwise): the
  !> dynamic lift and the friction ratio averaged over whole periods, to `out`.
  subroutine asperity_sergienko_bukharov_run(params, heights, out, status)
    type(asperity_sergienko_bukharov_params), intent(in) :: params
    real(c_double), intent(in) :: heights(:)
    type(asperity_sergienko_bukharov_result), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_sergienko_bukharov_run(params, heights, int(size(heights), c_size_t), &
        out), 'asperity_sergienko_bukharov_run', status)
  end subroutine asperity_sergienko_bukharov_run

  !> The separation (m) that carries `load` (N), with the solver's report.
  subroutine asperity_gw_separation_at_load(gw, load, out, status)
    type(asperity_gw_params), intent(in) :: gw
    real(c_double), intent(in) :: load
    type(asperity_separation), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_gw_separation_at_load(gw, load, out), &
        'asperity_gw_separation_at_load', status)
  end subroutine asperity_gw_separation_at_load

  !> Plasticity index of the surface `gw` for the hardness `hardness` (Pa).
  subroutine asperity_gw_plasticity_index(gw, hardness, psi, status)
    type(asperity_gw_params), intent(in) :: gw
    real(c_double), intent(in) :: hardness
    real(c_double), intent(out) :: psi
    integer(c_int32_t), intent(out), optional :: status
    psi = 0
    call check(c_asperity_gw_plasticity_index(gw, hardness, psi), &
        'asperity_gw_plasticity_index', status)
  end subroutine asperity_gw_plasticity_index

  !> Plasticity index psi = (E*/H) sqrt(sigma/R) (1-31).
  subroutine asperity_plasticity_index(e_star, hardness, sigma, radius, psi, status)
    real(c_double), intent(in) :: e_star, hardness, sigma, radius
    real(c_double), intent(out) :: psi
    integer(c_int32_t), intent(out), optional :: status
    psi = 0
    call check(c_asperity_plasticity_index(e_star, hardness, sigma, radius, psi), &
        'asperity_plasticity_index', status)
  end subroutine asperity_plasticity_index

  !> The deformation regime (`ASPERITY_REGIME_*`) of a plasticity index.
  subroutine asperity_deformation_regime(psi, regime, status)
    real(c_double), intent(in) :: psi
    integer(c_int32_t), intent(out) :: regime
    integer(c_int32_t), intent(out), optional :: status
    regime = 0
    call check(c_asperity_deformation_regime(psi, regime), 'asperity_deformation_regime', status)
  end subroutine asperity_deformation_regime

  !> A Greenwood-Williamson surface over listed summits `heights` (m) and,
  !> when given, their radii `radii` (m). An object `gw` held is freed first.
  subroutine asperity_gw_empirical_new(summit_count, radius, e_star, heights, gw, radii, status)
    real(c_double), intent(in) :: summit_count, radius, e_star
    real(c_double), intent(in) :: heights(:)
    type(asperity_gw_empirical), intent(inout) :: gw
    real(c_double), intent(in), optional, target, contiguous :: radii(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_gw_empirical_new'
    call gw%free()
    if (present(radii)) then
      if (too_small(what, 'radii', size(radii), size(heights), 'the size of `heights`', status)) &
          return
    end if
    call check(c_asperity_gw_empirical_new(summit_count, radius, e_star, &
        size(heights, kind=c_size_t), heights, loc_d(radii), gw%ptr), what, status)
  end subroutine asperity_gw_empirical_new

  !> `asperity_gw_eval` for an empirical surface.
  subroutine asperity_gw_empirical_eval(gw, separation, out, status)
    type(asperity_gw_empirical), intent(in) :: gw
    real(c_double), intent(in) :: separation
    type(asperity_gw_response), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_gw_empirical_eval(gw%ptr, separation, out), &
        'asperity_gw_empirical_eval', status)
  end subroutine asperity_gw_empirical_eval

  !> `asperity_gw_eval_batch` for an empirical surface.
  subroutine asperity_gw_empirical_eval_batch(gw, separation, load, area, contacts, stiffness, &
      status)
    type(asperity_gw_empirical), intent(in) :: gw
    real(c_double), intent(in) :: separation(:)
    real(c_double), intent(inout) :: load(:)
    real(c_double), intent(inout), optional, target, contiguous :: area(:), contacts(:), &
        stiffness(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_gw_empirical_eval_batch'
    if (gw_batch_sizes_bad(what, size(separation), load, area, contacts, stiffness, status)) &
        return
    call check(c_asperity_gw_empirical_eval_batch(gw%ptr, size(separation, kind=c_size_t), &
        separation, load, loc_d(area), loc_d(contacts), loc_d(stiffness)), what, status)
  end subroutine asperity_gw_empirical_eval_batch

  !> `asperity_gw_separation_at_load` for an empirical surface.
  subroutine asperity_gw_empirical_separation_at_load(gw, load, out, status)
    type(asperity_gw_empirical), intent(in) :: gw
    real(c_double), intent(in) :: load
    type(asperity_separation), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_gw_empirical_separation_at_load(gw%ptr, load, out), &
        'asperity_gw_empirical_separation_at_load', status)
  end subroutine asperity_gw_empirical_separation_at_load

  !> `asperity_gw_plasticity_index` for an empirical surface.
  subroutine asperity_gw_empirical_plasticity_index(gw, hardness, psi, status)
    type(asperity_gw_empirical), intent(in) :: gw
    real(c_double), intent(in) :: hardness
    real(c_double), intent(out) :: psi
    integer(c_int32_t), intent(out), optional :: status
    psi = 0
    call check(c_asperity_gw_empirical_plasticity_index(gw%ptr, hardness, psi), &
        'asperity_gw_empirical_plasticity_index', status)
  end subroutine asperity_gw_empirical_plasticity_index

  !> Zhuravlev's model with linear summit densities at the approach (m).
  subroutine asperity_zhuravlev_linear(model, alpha1, alpha2, approach, out, status)
    type(asperity_zhuravlev), intent(in) :: model
    real(c_double), intent(in) :: alpha1, alpha2, approach
    type(asperity_zhuravlev_response), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_zhuravlev_linear(model, alpha1, alpha2, approach, out), &
        'asperity_zhuravlev_linear', status)
  end subroutine asperity_zhuravlev_linear

  !> The approach (m) that carries `load` (N) with linear densities.
  subroutine asperity_zhuravlev_approach_at_load_linear(model, alpha1, alpha2, load, approach, &
      status)
    type(asperity_zhuravlev), intent(in) :: model
    real(c_double), intent(in) :: alpha1, alpha2, load
    real(c_double), intent(out) :: approach
    integer(c_int32_t), intent(out), optional :: status
    approach = 0
    call check(c_asperity_zhuravlev_approach_at_load_linear(model, alpha1, alpha2, load, &
        approach), 'asperity_zhuravlev_approach_at_load_linear', status)
  end subroutine asperity_zhuravlev_approach_at_load_linear

  !> Friction of Zhuravlev's model at `load` (N) with shear strength (Pa).
  subroutine asperity_zhuravlev_friction_linear(model, alpha1, alpha2, load, shear_strength, out, &
      status)
    type(asperity_zhuravlev), intent(in) :: model
    real(c_double), intent(in) :: alpha1, alpha2, load, shear_strength
    type(asperity_zhuravlev_friction), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_zhuravlev_friction_linear(model, alpha1, alpha2, load, shear_strength, &
        out), 'asperity_zhuravlev_friction_linear', status)
  end subroutine asperity_zhuravlev_friction_linear

  !> Zhuravlev's model for summit densities `n1`, `n2` (`bind(c)` functions
  !> of the interface `asperity_summit_density`, called with `n1_data`,
  !> `n2_data`, or `c_null_ptr` when absent) by Gauss-Legendre quadrature of
  !> `order` points.
  subroutine asperity_zhuravlev_eval(model, approach, n1, n2, order, out, n1_data, n2_data, status)
    type(asperity_zhuravlev), intent(in) :: model
    real(c_double), intent(in) :: approach
    procedure(asperity_summit_density) :: n1, n2
    integer, intent(in) :: order
    type(asperity_zhuravlev_response), intent(out) :: out
    type(c_ptr), intent(in), optional :: n1_data, n2_data
    integer(c_int32_t), intent(out), optional :: status
    type(c_ptr) :: d1, d2
    d1 = c_null_ptr
    d2 = c_null_ptr
    if (present(n1_data)) d1 = n1_data
    if (present(n2_data)) d2 = n2_data
    call check(c_asperity_zhuravlev_eval(model, approach, c_funloc(n1), d1, c_funloc(n2), d2, &
        int(order, c_size_t), out), 'asperity_zhuravlev_eval', status)
  end subroutine asperity_zhuravlev_eval

  ! ------------------------------------------------------------------------
  ! Friendly layer: profiles (surface.rs).

  !> ISO 4287 parameters of the profile `heights` (m) sampled at `dx` (m).
  subroutine asperity_roughness_parameters(heights, dx, form, cutoff, sampling_length, out, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(in) :: dx, cutoff, sampling_length
    integer(c_int32_t), intent(in) :: form
    type(asperity_roughness), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_roughness_parameters(size(heights, kind=c_size_t), heights, dx, form, &
        cutoff, sampling_length, out), 'asperity_roughness_parameters', status)
  end subroutine asperity_roughness_parameters

  !> `heights` minus their least-squares `form` (`ASPERITY_FORM_*`) into
  !> `out` (for in place, call the raw `c_asperity_profile_remove_form`
  !> with the same array twice).
  subroutine asperity_profile_remove_form(heights, form, out, status)
    real(c_double), intent(in) :: heights(:)
    integer(c_int32_t), intent(in) :: form
    real(c_double), intent(inout) :: out(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_profile_remove_form'
    if (too_small(what, 'out', size(out), size(heights), 'the size of `heights`', status)) return
    call check(c_asperity_profile_remove_form(size(heights, kind=c_size_t), heights, form, out), &
        what, status)
  end subroutine asperity_profile_remove_form

  !> ISO 16610-21 Gaussian filter: the roughness profile into `roughness`
  !> (room for `size(heights)`), its length into `n_out` and, when given, the
  !> mean line into `mean_line` and the index (0-based) of the first sample
  !> kept into `first_index`.
  subroutine asperity_profile_gaussian_filter(heights, dx, cutoff, ends, roughness, n_out, &
      mean_line, first_index, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(in) :: dx, cutoff
    integer(c_int32_t), intent(in) :: ends
    real(c_double), intent(inout) :: roughness(:)
    integer, intent(out) :: n_out
    real(c_double), intent(inout), optional, target, contiguous :: mean_line(:)
    integer, intent(out), optional :: first_index
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_profile_gaussian_filter'
    integer(c_size_t), target :: c_n_out, c_first
    integer :: n
    n = size(heights)
    n_out = 0
    if (present(first_index)) first_index = 0
    if (too_small(what, 'roughness', size(roughness), n, 'the size of `heights`', status)) return
    if (present(mean_line)) then
      if (too_small(what, 'mean_line', size(mean_line), n, 'the size of `heights`', status)) return
    end if
    c_n_out = 0
    c_first = 0
    call check(c_asperity_profile_gaussian_filter(int(n, c_size_t), heights, dx, cutoff, ends, &
        roughness, loc_d(mean_line), c_n_out, c_loc(c_first)), what, status)
    n_out = int(c_n_out)
    if (present(first_index)) first_index = int(c_first)
  end subroutine asperity_profile_gaussian_filter

  !> The material-ratio curve at `size(level)` ratios: `level(i)` (m) and,
  !> when given, `ratio(i)`.
  subroutine asperity_material_ratio_curve(heights, level, ratio, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(inout) :: level(:)
    real(c_double), intent(inout), optional, target, contiguous :: ratio(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_material_ratio_curve'
    if (present(ratio)) then
      if (too_small(what, 'ratio', size(ratio), size(level), 'the size of `level`', status)) return
    end if
    call check(c_asperity_material_ratio_curve(size(heights, kind=c_size_t), heights, &
        size(level, kind=c_size_t), loc_d(ratio), level), what, status)
  end subroutine asperity_material_ratio_curve

  !> One-sided PSD `g(k)` (m^3) of `heights`; `size(g)` must be
  !> `size(heights)/2 + 1`; the wavenumbers (rad/m) into `q` when given.
  subroutine asperity_profile_psd(heights, dx, window, g, q, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(in) :: dx
    integer(c_int32_t), intent(in) :: window
    real(c_double), intent(inout) :: g(:)
    real(c_double), intent(inout), optional, target, contiguous :: q(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_profile_psd'
    if (present(q)) then
      if (too_small(what, 'q', size(q), size(g), 'the size of `g`', status)) return
    end if
    call check(c_asperity_profile_psd(size(heights, kind=c_size_t), heights, dx, window, &
        size(g, kind=c_size_t), loc_d(q), g), what, status)
  end subroutine asperity_profile_psd

  !> Power-law fit of the PSD over `q_min`..`q_max` (rad/m; 0, 0: default).
  subroutine asperity_profile_hurst_fit(heights, dx, q_min, q_max, out, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(in) :: dx, q_min, q_max
    type(asperity_hurst_fit), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_profile_hurst_fit(size(heights, kind=c_size_t), heights, dx, q_min, &
        q_max, out), 'asperity_profile_hurst_fit', status)
  end subroutine asperity_profile_hurst_fit

  !> `asperity_profile_hurst_fit` with H's standard error, chi^2/dof and the band in rad/m and m
  !> (`q_min` = `q_max` = 0: the band chosen from the data).
  subroutine asperity_profile_hurst_estimate(heights, dx, q_min, q_max, out, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(in) :: dx, q_min, q_max
    type(asperity_hurst_estimate), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_profile_hurst_estimate(size(heights, kind=c_size_t), heights, dx, &
        q_min, q_max, out), 'asperity_profile_hurst_estimate', status)
  end subroutine asperity_profile_hurst_estimate

  !> ISO 16610-61 areal Gaussian filter of the map `heights(nx, ny)` (m, x fastest; spacings
  !> `dx`, `dy` in m) at `cutoff` (m) with `ends` (`ASPERITY_FILTER_ENDS_*`): the roughness
  !> surface of the retained `nx_out` x `ny_out` grid in `roughness(1:nx_out*ny_out)` (x
  !> fastest; room for size(heights)), and when given the mean surface likewise and the
  !> (0-based) input indices of the retained grid's first point.
  subroutine asperity_map_gaussian_filter(heights, dx, dy, cutoff, ends, roughness, nx_out, &
      ny_out, mean_surface, first_x, first_y, status)
    real(c_double), intent(in), contiguous :: heights(:, :)
    real(c_double), intent(in) :: dx, dy, cutoff
    integer(c_int32_t), intent(in) :: ends
    real(c_double), intent(inout) :: roughness(:)
    integer, intent(out) :: nx_out, ny_out
    real(c_double), intent(inout), optional, target, contiguous :: mean_surface(:)
    integer, intent(out), optional :: first_x, first_y
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_map_gaussian_filter'
    integer(c_size_t), target :: c_nx, c_ny, c_fx, c_fy
    integer :: n
    n = size(heights)
    nx_out = 0
    ny_out = 0
    if (present(first_x)) first_x = 0
    if (present(first_y)) first_y = 0
    if (too_small(what, 'roughness', size(roughness), n, 'the size of `heights`', status)) return
    if (present(mean_surface)) then
      if (too_small(what, 'mean_surface', size(mean_surface), n, 'the size of `heights`', &
          status)) return
    end if
    c_nx = 0
    c_ny = 0
    c_fx = 0
    c_fy = 0
    call check(c_asperity_map_gaussian_filter(size(heights, 1, kind=c_size_t), &
        size(heights, 2, kind=c_size_t), dx, dy, heights, cutoff, ends, roughness, &
        loc_d(mean_surface), c_nx, c_ny, c_loc(c_fx), c_loc(c_fy)), what, status)
    nx_out = int(c_nx)
    ny_out = int(c_ny)
    if (present(first_x)) first_x = int(c_fx)
    if (present(first_y)) first_y = int(c_fy)
  end subroutine asperity_map_gaussian_filter

  !> Radially averaged 2-D PSD of the map `heights(nx, ny)` (m, x fastest; spacings `dx`,
  !> `dy` in m) with `window` (`ASPERITY_WINDOW_*`): `written` annuli, their mean PSD (m^4)
  !> in `psd` and, when given, their mean |q| (rad/m) in `q` (as long as `psd`; min(nx, ny)/2
  !> + 1 elements always suffice).
  subroutine asperity_map_psd_radial(heights, dx, dy, window, psd, written, q, status)
    real(c_double), intent(in), contiguous :: heights(:, :)
    real(c_double), intent(in) :: dx, dy
    integer(c_int32_t), intent(in) :: window
    real(c_double), intent(inout) :: psd(:)
    integer, intent(out) :: written
    real(c_double), intent(inout), optional, target, contiguous :: q(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_map_psd_radial'
    integer(c_size_t) :: c_written
    written = 0
    if (present(q)) then
      if (too_small(what, 'q', size(q), size(psd), 'the size of `psd`', status)) return
    end if
    c_written = 0
    call check(c_asperity_map_psd_radial(size(heights, 1, kind=c_size_t), &
        size(heights, 2, kind=c_size_t), dx, dy, heights, window, size(psd, kind=c_size_t), &
        loc_d(q), psd, c_null_ptr, c_written), what, status)
    written = int(c_written)
  end subroutine asperity_map_psd_radial

  !> Statistics of the peaks of `heights`.
  subroutine asperity_profile_peak_statistics(heights, dx, out, status)
    real(c_double), intent(in) :: heights(:)
    real(c_double), intent(in) :: dx
    type(asperity_peak_statistics), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_profile_peak_statistics(size(heights, kind=c_size_t), heights, dx, out), &
        'asperity_profile_peak_statistics', status)
  end subroutine asperity_profile_peak_statistics

  !> A seeded Gaussian self-affine profile into `heights` (`size(heights)`
  !> samples at `dx` m).
  subroutine asperity_generate_self_affine(hurst, rq, roll_off_wavelength, cutoff_wavelength, dx, &
      seed, heights, status)
    real(c_double), intent(in) :: hurst, rq, roll_off_wavelength, cutoff_wavelength, dx
    integer(c_int64_t), intent(in) :: seed
    real(c_double), intent(inout) :: heights(:)
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_generate_self_affine(hurst, rq, roll_off_wavelength, cutoff_wavelength, &
        dx, seed, size(heights, kind=c_size_t), heights), 'asperity_generate_self_affine', status)
  end subroutine asperity_generate_self_affine

  !> The Weierstrass-Mandelbrot profile into `heights`.
  subroutine asperity_generate_weierstrass_mandelbrot(fractal_dimension, gamma, amplitude, dx, &
      seed, heights, status)
    real(c_double), intent(in) :: fractal_dimension, gamma, amplitude, dx
    integer(c_int64_t), intent(in) :: seed
    real(c_double), intent(inout) :: heights(:)
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_generate_weierstrass_mandelbrot(fractal_dimension, gamma, amplitude, &
        dx, seed, size(heights, kind=c_size_t), heights), &
        'asperity_generate_weierstrass_mandelbrot', status)
  end subroutine asperity_generate_weierstrass_mandelbrot

  !> The Cantor-Borodich profile into `heights` (`size(heights)` points over
  !> [0, `length`)).
  subroutine asperity_generate_cantor_borodich(descendants, alpha, beta, height, levels, length, &
      heights, status)
    integer(c_int32_t), intent(in) :: descendants, levels
    real(c_double), intent(in) :: alpha, beta, height, length
    real(c_double), intent(inout) :: heights(:)
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_generate_cantor_borodich(descendants, alpha, beta, height, levels, &
        length, size(heights, kind=c_size_t), heights), 'asperity_generate_cantor_borodich', &
        status)
  end subroutine asperity_generate_cantor_borodich

  ! ------------------------------------------------------------------------
  ! Friendly layer: tabulated laws (tabulated.rs).

  !> The table of a Maugis-Dugdale sphere. An object `table` held is freed first.
  subroutine asperity_table_new_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, &
      tolerance, table, status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion, sigma0, tolerance
    type(asperity_table), intent(inout) :: table
    integer(c_int32_t), intent(out), optional :: status
    call table%free()
    call check(c_asperity_table_new_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, &
        tolerance, table%ptr), 'asperity_table_new_maugis_dugdale', status)
  end subroutine asperity_table_new_maugis_dugdale

  !> The table of a Lennard-Jones sphere on `n_grid` cells (0: default).
  !> An object `table` held is freed first.
  subroutine asperity_table_new_lj(radius, e_star, work_of_adhesion, z0, n_grid, tolerance, table, &
      status)
    real(c_double), intent(in) :: radius, e_star, work_of_adhesion, z0, tolerance
    integer, intent(in) :: n_grid
    type(asperity_table), intent(inout) :: table
    integer(c_int32_t), intent(out), optional :: status
    call table%free()
    call check(c_asperity_table_new_lj(radius, e_star, work_of_adhesion, z0, &
        int(n_grid, c_size_t), tolerance, table%ptr), 'asperity_table_new_lj', status)
  end subroutine asperity_table_new_lj

  !> Evaluate `table` at `delta` (m), as `asperity_normal_eval`.
  subroutine asperity_table_eval(table, delta, out, old_state, new_state, state, status)
    type(asperity_table), intent(in) :: table
    real(c_double), intent(in) :: delta
    type(asperity_normal_response), intent(out) :: out
    type(asperity_contact_state), intent(in), optional, target :: old_state
    type(asperity_contact_state), intent(inout), optional, target :: new_state
    type(asperity_contact_state), intent(inout), optional, target :: state
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_table_eval'
    if (state_clash(what, present(state), present(old_state) .or. present(new_state), status)) &
        return
    if (present(state)) then
      call check(c_asperity_table_eval(table%ptr, delta, c_loc(state), c_loc(state), out), what, &
          status)
    else
      call check(c_asperity_table_eval(table%ptr, delta, loc_contact(old_state), &
          loc_contact(new_state), out), what, status)
    end if
  end subroutine asperity_table_eval

  !> Evaluate `table` for `size(delta)` contacts, as `asperity_normal_eval_batch`.
  subroutine asperity_table_eval_batch(table, delta, force, old_state, new_state, contact_radius, &
      stiffness, states, status)
    type(asperity_table), intent(in) :: table
    real(c_double), intent(in) :: delta(:)
    real(c_double), intent(inout) :: force(:)
    type(asperity_contact_state), intent(in), optional, target, contiguous :: old_state(:)
    type(asperity_contact_state), intent(inout), optional, target, contiguous :: new_state(:)
    real(c_double), intent(inout), optional, target, contiguous :: contact_radius(:), stiffness(:)
    type(asperity_contact_state), intent(inout), optional, target, contiguous :: states(:)
    integer(c_int32_t), intent(out), optional :: status
    character(len=*), parameter :: what = 'asperity_table_eval_batch'
    type(c_ptr) :: p_old, p_new
    logical :: bad
    integer :: n
    n = size(delta)
    if (too_small(what, 'force', size(force), n, 'the size of `delta`', status)) return
    if (present(contact_radius)) then
      if (too_small(what, 'contact_radius', size(contact_radius), n, 'the size of `delta`', &
          status)) return
    end if
    if (present(stiffness)) then
      if (too_small(what, 'stiffness', size(stiffness), n, 'the size of `delta`', status)) return
    end if
    call contact_states(what, n, old_state, new_state, states, p_old, p_new, bad, status)
    if (bad) return
    call check(c_asperity_table_eval_batch(table%ptr, int(n, c_size_t), delta, p_old, p_new, &
        force, loc_d(contact_radius), loc_d(stiffness)), what, status)
  end subroutine asperity_table_eval_batch

  !> Equilibrium of `table` at the prescribed force `force` (N).
  subroutine asperity_table_eval_at_load(table, force, out, status)
    type(asperity_table), intent(in) :: table
    real(c_double), intent(in) :: force
    type(asperity_normal_response), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: status
    call check(c_asperity_table_eval_at_load(table%ptr, force, out), &
        'asperity_table_eval_at_load', status)
  end subroutine asperity_table_eval_at_load

  !> The pull-off force (N) of `table` under `control`.
  subroutine asperity_table_pull_off_force(table, control, force, status)
    type(asperity_table), intent(in) :: table
    integer(c_int32_t), intent(in) :: control
    real(c_double), intent(out) :: force
    integer(c_int32_t), intent(out), optional :: status
    force = 0
    call check(c_asperity_table_pull_off_force(table%ptr, control, force), &
        'asperity_table_pull_off_force', status)
  end subroutine asperity_table_pull_off_force

  !> The reach (m) of `table` under `control`: no force below it from any
  !> history (below `rel_force` × |pull-off| with a Lennard-Jones tail).
  subroutine asperity_table_reach(table, control, rel_force, delta, status)
    type(asperity_table), intent(in) :: table
    integer(c_int32_t), intent(in) :: control
    real(c_double), intent(in) :: rel_force
    real(c_double), intent(out) :: delta
    integer(c_int32_t), intent(out), optional :: status
    delta = 0
    call check(c_asperity_table_reach(table%ptr, control, rel_force, delta), &
        'asperity_table_reach', status)
  end subroutine asperity_table_reach

  !> The stated maximum relative error of `table` and, when given, the
  !> largest error measured at construction.
  subroutine asperity_table_max_error(table, max_error, measured, status)
    type(asperity_table), intent(in) :: table
    real(c_double), intent(out) :: max_error
    real(c_double), intent(out), optional, target :: measured
    integer(c_int32_t), intent(out), optional :: status
    max_error = 0
    call check(c_asperity_table_max_error(table%ptr, max_error, loc_d0(measured)), &
        'asperity_table_max_error', status)
  end subroutine asperity_table_max_error

  !> The JSON text of `table`.
  subroutine asperity_table_to_json(table, json, status)
    type(asperity_table), intent(in) :: table
    character(len=:), allocatable, intent(out) :: json
    integer(c_int32_t), intent(out), optional :: status
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n, cap
    integer(c_int32_t) :: st
    json = ''
    n = 0
    st = c_asperity_table_to_json(table%ptr, c_null_ptr, 0_c_size_t, n)
    if (st == ASPERITY_OK) then
      cap = n + 1
      allocate (buf(cap))
      st = c_asperity_table_to_json(table%ptr, c_loc(buf), cap, n)
      if (st == ASPERITY_OK) json = from_chars(buf, int(n))
    end if
    call check(st, 'asperity_table_to_json', status)
  end subroutine asperity_table_to_json

  !> A table from its JSON text. An object `table` held is freed first.
  subroutine asperity_table_from_json(json, table, status)
    character(len=*, kind=c_char), intent(in) :: json
    type(asperity_table), intent(inout) :: table
    integer(c_int32_t), intent(out), optional :: status
    call table%free()
    call check(c_asperity_table_from_json(json, len(json, kind=c_size_t), table%ptr), &
        'asperity_table_from_json', status)
  end subroutine asperity_table_from_json

end module asperity
