//! Borodich rescaling, Galanov shapes (`asperity::rescaling`) and the
//! analysis of measured indentation curves (`asperity::indentation`).

use crate::common::{any_err, arg_error, array, real, real_opt, rs, string, to_py_value};
use asperity::indentation as ind;
use asperity::rescaling as rsc;
use pyo3::prelude::*;

/// Rescaling(kappa, d)
///
/// Borodich's self-similar rescaling of indentation by a punch B r^d into a
/// material of hardening index κ (dimensionless, in [0, 10]; 1 linear
/// elastic, 0 perfectly plastic) and bluntness d (in [1, 100]). With a known
/// solution (load P1 N, depth δ1 m, contact radius a1 m) at shape scale B1,
/// ``depth``, ``radius`` and ``load`` give the solution at λ = B/B1.
#[pyclass(module = "asperity", frozen)]
pub struct Rescaling {
    pub inner: rsc::Rescaling,
}

/// KnownSolution(load, depth, radius=1.0)
///
/// A known indentation solution: load P1 (N), depth δ1 (m), contact radius
/// a1 (m; only ``Rescaling.radius`` needs it), all > 0.
#[pyclass(module = "asperity", frozen)]
pub struct KnownSolution {
    pub inner: rsc::KnownSolution,
}

#[pymethods]
impl KnownSolution {
    #[new]
    #[pyo3(signature = (load, depth, radius=None))]
    fn new(
        load: &Bound<'_, PyAny>,
        depth: &Bound<'_, PyAny>,
        radius: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: rsc::KnownSolution::new(
                real(load, "load")?,
                real(depth, "depth")?,
                real_opt(radius, "radius")?.unwrap_or(1.0),
            )
            .map_err(rs)?,
        })
    }
    /// Load P1 (N).
    #[getter]
    fn load(&self) -> f64 {
        self.inner.load
    }
    /// Depth δ1 (m).
    #[getter]
    fn depth(&self) -> f64 {
        self.inner.depth
    }
    /// Contact radius a1 (m).
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius
    }
    fn __repr__(&self) -> String {
        format!(
            "KnownSolution(load={:e}, depth={:e}, radius={:e})",
            self.inner.load, self.inner.depth, self.inner.radius
        )
    }
}

#[pymethods]
impl Rescaling {
    #[new]
    fn new(kappa: &Bound<'_, PyAny>, d: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: rsc::Rescaling::new(real(kappa, "kappa")?, real(d, "d")?).map_err(rs)?,
        })
    }
    /// sphere(kappa) -> Rescaling
    ///
    /// A sphere (d = 2) on a material of hardening index κ.
    #[staticmethod]
    fn sphere(kappa: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: rsc::Rescaling::sphere(real(kappa, "kappa")?).map_err(rs)?,
        })
    }
    /// Hardening index κ (dimensionless).
    #[getter]
    fn kappa(&self) -> f64 {
        self.inner.kappa
    }
    /// Bluntness index d (dimensionless).
    #[getter]
    fn d(&self) -> f64 {
        self.inner.d
    }
    /// s() -> float
    ///
    /// s = 2 + κ(d - 1) (dimensionless).
    fn s(&self) -> f64 {
        self.inner.s()
    }
    /// load_depth_exponent() -> float
    ///
    /// Log-log slope s/d of load against depth at fixed λ.
    fn load_depth_exponent(&self) -> f64 {
        self.inner.load_depth_exponent()
    }
    /// depth_lambda_exponent() -> float
    ///
    /// Exponent (2 - κ)/s of λ in the depth.
    fn depth_lambda_exponent(&self) -> f64 {
        self.inner.depth_lambda_exponent()
    }
    /// radius_lambda_exponent() -> float
    ///
    /// Exponent -κ/s of λ in the contact radius.
    fn radius_lambda_exponent(&self) -> f64 {
        self.inner.radius_lambda_exponent()
    }
    /// load_lambda_exponent() -> float
    ///
    /// Exponent (κ - 2)/d of λ in the load.
    fn load_lambda_exponent(&self) -> f64 {
        self.inner.load_lambda_exponent()
    }
    /// depth(lambda_, load, known) -> float
    ///
    /// Depth δ (m) at load P (N) for shape scale λ = B/B1, from ``known``.
    fn depth(
        &self,
        lambda_: &Bound<'_, PyAny>,
        load: &Bound<'_, PyAny>,
        known: &KnownSolution,
    ) -> PyResult<f64> {
        self.inner
            .depth(real(lambda_, "lambda")?, real(load, "load")?, &known.inner)
            .map_err(rs)
    }
    /// radius(lambda_, load, known) -> float
    ///
    /// Contact radius a (m) at load P (N) for shape scale λ, from ``known``.
    fn radius(
        &self,
        lambda_: &Bound<'_, PyAny>,
        load: &Bound<'_, PyAny>,
        known: &KnownSolution,
    ) -> PyResult<f64> {
        self.inner
            .radius(real(lambda_, "lambda")?, real(load, "load")?, &known.inner)
            .map_err(rs)
    }
    /// load(lambda_, depth, known) -> float
    ///
    /// Load P (N) at depth δ (m) for shape scale λ, from ``known``.
    fn load(
        &self,
        lambda_: &Bound<'_, PyAny>,
        depth: &Bound<'_, PyAny>,
        known: &KnownSolution,
    ) -> PyResult<f64> {
        self.inner
            .load(
                real(lambda_, "lambda")?,
                real(depth, "depth")?,
                &known.inner,
            )
            .map_err(rs)
    }
    fn __repr__(&self) -> String {
        format!("Rescaling(kappa={}, d={})", self.inner.kappa, self.inner.d)
    }
}

/// shape_scale_from_points(rescaling, known, load, depth) -> float
///
/// The shape scale λ = B/B1 (dimensionless) that carries the known point
/// (P1 N, δ1 m) into (load N, depth m) on the same material.
#[pyfunction]
fn shape_scale_from_points(
    rescaling: &Rescaling,
    known: &KnownSolution,
    load: &Bound<'_, PyAny>,
    depth: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    rsc::shape_scale_from_points(
        &rescaling.inner,
        &known.inner,
        real(load, "load")?,
        real(depth, "depth")?,
    )
    .map_err(rs)
}

/// zhuravlev_prefactor(rescaling, lambda_, known) -> float
///
/// λ^((κ-2)/d) P1/δ1^q (N·m^-q), the prefactor of the Zhuravlev-type load
/// of power-law asperities.
#[pyfunction]
fn zhuravlev_prefactor(
    rescaling: &Rescaling,
    lambda_: &Bound<'_, PyAny>,
    known: &KnownSolution,
) -> PyResult<f64> {
    rsc::zhuravlev_prefactor(&rescaling.inner, real(lambda_, "lambda")?, &known.inner).map_err(rs)
}

crate::scalar_fn!(lambda_spheres, rsc::lambda_spheres, "lambda_spheres(known_radius, radius) -> float\n\nShape scale λ = R1/R (dimensionless) between spheres of radii known_radius and radius (m).", (known_radius, radius));
crate::scalar_fn!(lambda_cones, rsc::lambda_cones, "lambda_cones(known_half_angle, half_angle) -> float\n\nShape scale λ = tan γ1 / tan γ (dimensionless) between cones of half-angles in rad.", (known_half_angle, half_angle));
crate::scalar_fn!(galanov_unloading_radius, rsc::galanov_unloading_radius, "galanov_unloading_radius(r1, p1, delta1, p2, delta2) -> float\n\nGalanov effective radius R2 = R1 (P2/P1)² (δ1/δ2)³ (m) of the unloading branch: radius r1 (m), loads p1, p2 (N), depths delta1, delta2 (m).", (r1, p1, delta1, p2, delta2));
crate::scalar_fn!(hertz_effective_radius, rsc::hertz_effective_radius, "hertz_effective_radius(e_star, load, elastic_depth) -> float\n\nThe sphere radius (m) whose Hertz contact carries load P (N) at the elastic depth (m) for contact modulus E* (Pa).", (e_star, load, elastic_depth));
crate::scalar_fn!(medium_radius, rsc::medium_radius, "medium_radius(radius, unloading_radius) -> float\n\nRadius (m) of the crater left in the medium, from the indenter radius and the effective unloading radius (m).", (radius, unloading_radius));
crate::scalar_fn!(unloading_radius, rsc::unloading_radius, "unloading_radius(radius, medium_radius) -> float\n\nEffective unloading radius (m) of a sphere of radius R (m) in a crater of radius medium_radius (m).", (radius, medium_radius));
crate::scalar_fn!(galanov_cone_coefficient, rsc::galanov_cone_coefficient, "galanov_cone_coefficient(indenter_half_angle, imprint_half_angle) -> float\n\nGalanov's effective cone coefficient B1 = cot γi - cot γf (dimensionless), half-angles in rad.", (indenter_half_angle, imprint_half_angle));
crate::scalar_fn!(galanov_imprint_half_angle, rsc::galanov_imprint_half_angle, "galanov_imprint_half_angle(indenter_half_angle, effective_b) -> float\n\nThe imprint half-angle (rad) whose Galanov coefficient is effective_b (dimensionless), indenter half-angle in rad.", (indenter_half_angle, effective_b));
crate::scalar_fn!(loading_slope, rsc::loading_slope, "loading_slope(kappa, d) -> float\n\nLog-log slope (2 + κ(d-1))/d of the loading curve (dimensionless).", (kappa, d));
crate::scalar_fn!(unloading_slope, rsc::unloading_slope, "unloading_slope(d) -> float\n\nLog-log slope (d+1)/d of the elastic unloading curve (dimensionless).", (d));
crate::scalar_fn!(d_from_unloading_slope, rsc::d_from_unloading_slope, "d_from_unloading_slope(unloading_slope) -> float\n\nBluntness d = 1/(slope - 1) from the unloading log-log slope.", (unloading_slope));
crate::scalar_fn!(kappa_from_loading_slope, rsc::kappa_from_loading_slope, "kappa_from_loading_slope(loading_slope, d) -> float\n\nHardening index κ from the loading log-log slope and d.", (loading_slope, d));
crate::scalar_fn!(d_from_loading_slope, rsc::d_from_loading_slope, "d_from_loading_slope(loading_slope, kappa) -> float\n\nBluntness d from the loading log-log slope and κ.", (loading_slope, kappa));
crate::scalar_fn!(zhuravlev_exponent, rsc::zhuravlev_exponent, "zhuravlev_exponent(kappa, d) -> float\n\nExponent q = (2 + κ(d-1))/d of the Zhuravlev-type integrand (dimensionless).", (kappa, d));
crate::scalar_fn!(zhuravlev_integral_linear, rsc::zhuravlev_integral_linear, "zhuravlev_integral_linear(q, x, alpha1, alpha2) -> float\n\nThe Zhuravlev double integral for linear summit densities n_i(ξ) = alpha_i ξ (m^-2 each) at interference x (m), exponent q.", (q, x, alpha1, alpha2));

crate::scalar_fn!(brinell_hardness, ind::brinell_hardness, "brinell_hardness(load, ball_diameter, imprint_diameter) -> float\n\nBrinell hardness (Pa) from load (N), ball and imprint diameters (m).", (load, ball_diameter, imprint_diameter));
crate::scalar_fn!(meyer_hardness, ind::meyer_hardness, "meyer_hardness(load, imprint_diameter) -> float\n\nMeyer hardness P/(π d²/4) (Pa), load N, imprint diameter m.", (load, imprint_diameter));
crate::scalar_fn!(ludwik_hardness, ind::ludwik_hardness, "ludwik_hardness(load, imprint_diameter) -> float\n\nLudwik hardness (Pa), load N, imprint diameter m.", (load, imprint_diameter));
crate::scalar_fn!(vickers_hardness, ind::vickers_hardness, "vickers_hardness(load, mean_diagonal) -> float\n\nVickers hardness 1.8544 P/d² (Pa), load N, mean diagonal m.", (load, mean_diagonal));
crate::scalar_fn!(reduced_modulus_from_stiffness, ind::reduced_modulus_from_stiffness, "reduced_modulus_from_stiffness(stiffness, area, beta) -> float\n\nReduced modulus E_r = √π S/(2β√A) (Pa): unloading stiffness S (N/m), projected area A (m²), β (dimensionless).", (stiffness, area, beta));

/// sample_modulus(reduced_modulus, nu_sample, e_indenter=1141e9, nu_indenter=0.07) -> float
///
/// The sample's Young's modulus E (Pa) from the reduced modulus E_r (Pa),
/// the sample's Poisson ratio and the indenter's modulus (Pa) and ratio
/// (defaults: diamond).
#[pyfunction]
#[pyo3(signature = (reduced_modulus, nu_sample, e_indenter=None, nu_indenter=None))]
fn sample_modulus(
    reduced_modulus: &Bound<'_, PyAny>,
    nu_sample: &Bound<'_, PyAny>,
    e_indenter: Option<&Bound<'_, PyAny>>,
    nu_indenter: Option<&Bound<'_, PyAny>>,
) -> PyResult<f64> {
    ind::sample_modulus(
        real(reduced_modulus, "reduced_modulus")?,
        real(nu_sample, "nu_sample")?,
        real_opt(e_indenter, "e_indenter")?.unwrap_or(1141e9),
        real_opt(nu_indenter, "nu_indenter")?.unwrap_or(0.07),
    )
    .map_err(rs)
}

fn indenter(obj: &Bound<'_, PyAny>) -> PyResult<ind::Indenter> {
    let s = string(obj, "indenter")?;
    let spec = s.replace("radius=", "").replace("half_angle=", "");
    ind::Indenter::parse(&spec).ok_or_else(|| {
        arg_error(
            "indenter",
            format!("unknown indenter {s:?}: must be \"sphere:radius=R\" (m) | \"cone:half_angle=DEG\" | \"berkovich\" | \"vickers\" | \"cube-corner\" | \"unknown\""),
        )
    })
}

/// analyze_indentation(source=None, *, depth=None, load=None, indenter="berkovich", area=None, e_indenter=1141e9, nu_indenter=0.07, nu_sample=0.3, detect_segments=False, known_d=None, known_kappa=None, beta=None, epsilon=0.75, unloading_window=(0.2, 0.98)) -> dict
///
/// Analyse a measured indentation curve as ``asperity indent --json`` does:
/// segments, the loading log-log fit, Oliver–Pharr on the unloading branch,
/// κ and d with standard errors, reduced modulus E_r (Pa), sample modulus E
/// (Pa), hardness H (Pa) and the validity flags. The curve is a file
/// (``source``: CSV ``time_s,depth_m,load_N,segment`` or two columns depth m,
/// load N) or the arrays ``depth`` (m) and ``load`` (N). ``indenter``:
/// ``"berkovich"``, ``"vickers"``, ``"cube-corner"``, ``"sphere:radius=R"``
/// (m), ``"cone:half_angle=DEG"``, ``"unknown"``; ``area``: NanoSuite
/// coefficients C0, C1, … (h_c in nm, A in nm²), default the indenter's
/// ideal area. ``beta`` (None: the indenter's), ``epsilon`` and
/// ``unloading_window`` (the Oliver–Pharr fit's load range, fractions of
/// P_max) are the CLI's ``--beta``, ``--epsilon`` and ``--fit-window``.
/// Returns the dict of the CLI's JSON (keys ``kappa``, ``kappa_stderr``,
/// ``d``, ``d_stderr``, ``reduced_modulus``, ``sample_modulus``,
/// ``hardness``, ``window_sensitivity``, ``flags``, …).
#[pyfunction]
#[pyo3(signature = (source=None, *, depth=None, load=None, indenter=None, area=None, e_indenter=None, nu_indenter=None, nu_sample=None, detect_segments=false, known_d=None, known_kappa=None, beta=None, epsilon=None, unloading_window=None))]
#[allow(clippy::too_many_arguments)]
fn analyze_indentation(
    py: Python<'_>,
    source: Option<std::path::PathBuf>,
    depth: Option<&Bound<'_, PyAny>>,
    load: Option<&Bound<'_, PyAny>>,
    indenter: Option<&Bound<'_, PyAny>>,
    area: Option<&Bound<'_, PyAny>>,
    e_indenter: Option<&Bound<'_, PyAny>>,
    nu_indenter: Option<&Bound<'_, PyAny>>,
    nu_sample: Option<&Bound<'_, PyAny>>,
    detect_segments: bool,
    known_d: Option<&Bound<'_, PyAny>>,
    known_kappa: Option<&Bound<'_, PyAny>>,
    beta: Option<&Bound<'_, PyAny>>,
    epsilon: Option<&Bound<'_, PyAny>>,
    unloading_window: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let curve = match (source, depth, load) {
        (Some(p), None, None) => {
            ind::Curve::read(&p).map_err(|e| any_err(format!("{}: {e}", p.display())))?
        }
        (None, Some(d), Some(l)) => {
            let d = array(d, "depth")?;
            let l = array(l, "load")?;
            ind::Curve::new(d.as_slice()?.to_vec(), l.as_slice()?.to_vec()).map_err(rs)?
        }
        _ => {
            return Err(arg_error(
                "source",
                "give a file path, or both depth= (m) and load= (N) arrays",
            ))
        }
    };
    let defaults = ind::IndentationOptions::default();
    let options = ind::IndentationOptions {
        indenter: match indenter {
            Some(i) => self::indenter(i)?,
            None => defaults.indenter,
        },
        area: match area {
            Some(a) if !a.is_none() => Some(ind::AreaFunction::NanoSuite {
                coefficients: array(a, "area")?.as_slice()?.to_vec(),
            }),
            _ => None,
        },
        e_indenter: real_opt(e_indenter, "e_indenter")?.unwrap_or(defaults.e_indenter),
        nu_indenter: real_opt(nu_indenter, "nu_indenter")?.unwrap_or(defaults.nu_indenter),
        nu_sample: real_opt(nu_sample, "nu_sample")?.unwrap_or(defaults.nu_sample),
        known_d: real_opt(known_d, "known_d")?,
        known_kappa: real_opt(known_kappa, "known_kappa")?,
        beta: real_opt(beta, "beta")?,
        epsilon: real_opt(epsilon, "epsilon")?.unwrap_or(defaults.epsilon),
        unloading_window: match unloading_window {
            Some(w) if !w.is_none() => {
                let a = array(w, "unloading_window")?;
                match a.as_slice()? {
                    &[lo, hi] => [lo, hi],
                    other => {
                        return Err(arg_error(
                            "unloading_window",
                            format!(
                                "must be two fractions (lo, hi) of P_max, got {} values",
                                other.len()
                            ),
                        ))
                    }
                }
            }
            _ => defaults.unloading_window,
        },
        use_labels: !detect_segments,
        ..defaults
    };
    let r = py.detach(|| ind::analyze(&curve, &options)).map_err(rs)?;
    crate::common::json_value(py, &r.to_json())
}

/// read_indentation_curve(path) -> dict
///
/// A measured indentation curve as arrays: ``depth`` (m), ``load`` (N),
/// ``time`` (s, or None) and ``segments`` (labels, or None).
#[pyfunction]
fn read_indentation_curve(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Py<PyAny>> {
    let c = ind::Curve::read(&path).map_err(|e| any_err(format!("{}: {e}", path.display())))?;
    let d = pyo3::types::PyDict::new(py);
    d.set_item("depth", numpy::PyArray1::from_vec(py, c.depth))?;
    d.set_item("load", numpy::PyArray1::from_vec(py, c.load))?;
    d.set_item("time", c.time.map(|t| numpy::PyArray1::from_vec(py, t)))?;
    d.set_item(
        "segments",
        c.segments.map(|s| {
            s.iter()
                .map(|x| format!("{x:?}").to_lowercase())
                .collect::<Vec<_>>()
        }),
    )?;
    let _ = to_py_value::<f64>;
    Ok(d.into_any().unbind())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Rescaling>()?;
    m.add_class::<KnownSolution>()?;
    for f in [
        wrap_pyfunction!(shape_scale_from_points, m)?,
        wrap_pyfunction!(zhuravlev_prefactor, m)?,
        wrap_pyfunction!(lambda_spheres, m)?,
        wrap_pyfunction!(lambda_cones, m)?,
        wrap_pyfunction!(galanov_unloading_radius, m)?,
        wrap_pyfunction!(hertz_effective_radius, m)?,
        wrap_pyfunction!(medium_radius, m)?,
        wrap_pyfunction!(unloading_radius, m)?,
        wrap_pyfunction!(galanov_cone_coefficient, m)?,
        wrap_pyfunction!(galanov_imprint_half_angle, m)?,
        wrap_pyfunction!(loading_slope, m)?,
        wrap_pyfunction!(unloading_slope, m)?,
        wrap_pyfunction!(d_from_unloading_slope, m)?,
        wrap_pyfunction!(kappa_from_loading_slope, m)?,
        wrap_pyfunction!(d_from_loading_slope, m)?,
        wrap_pyfunction!(zhuravlev_exponent, m)?,
        wrap_pyfunction!(zhuravlev_integral_linear, m)?,
        wrap_pyfunction!(brinell_hardness, m)?,
        wrap_pyfunction!(meyer_hardness, m)?,
        wrap_pyfunction!(ludwik_hardness, m)?,
        wrap_pyfunction!(vickers_hardness, m)?,
        wrap_pyfunction!(reduced_modulus_from_stiffness, m)?,
        wrap_pyfunction!(sample_modulus, m)?,
        wrap_pyfunction!(analyze_indentation, m)?,
        wrap_pyfunction!(read_indentation_curve, m)?,
    ] {
        m.add_function(f)?;
    }
    Ok(())
}
