//! Profiles and maps (`asperity::surface`): ISO 4287 / 25178 parameters with
//! the keys of `asperity profile --json`, PSD, ACF, power-law fits, form
//! removal, the Gaussian filter, peaks, generators and readers.

use crate::common::{
    any_err, arg_error, array, count, real, real_opt, rs, seed, string, to_py_value,
};
use asperity::surface as s;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::{json, Value};

#[derive(Clone, Copy)]
enum Detrend {
    None,
    Mean,
    Linear,
    Quadratic,
}

impl Detrend {
    fn parse(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let Some(o) = obj else {
            return Ok(Detrend::Linear);
        };
        if o.is_none() {
            return Ok(Detrend::None);
        }
        match string(o, "detrend")?.as_str() {
            "none" => Ok(Detrend::None),
            "mean" => Ok(Detrend::Mean),
            "linear" => Ok(Detrend::Linear),
            "quadratic" => Ok(Detrend::Quadratic),
            x => Err(arg_error(
                "detrend",
                format!("must be \"none\", \"mean\", \"linear\" or \"quadratic\", got {x:?}"),
            )),
        }
    }
    fn name(self) -> &'static str {
        match self {
            Detrend::None => "none",
            Detrend::Mean => "mean",
            Detrend::Linear => "linear",
            Detrend::Quadratic => "quadratic",
        }
    }
}

/// The `convention` keyword: "iso21920" (default) or "iso4287".
fn convention(obj: Option<&Bound<'_, PyAny>>) -> PyResult<s::Convention> {
    let Some(o) = obj.filter(|o| !o.is_none()) else {
        return Ok(s::Convention::Iso21920);
    };
    match string(o, "convention")?.as_str() {
        "iso21920" => Ok(s::Convention::Iso21920),
        "iso4287" => Ok(s::Convention::Iso4287),
        x => Err(arg_error(
            "convention",
            format!("must be \"iso21920\" or \"iso4287\", got {x:?}"),
        )),
    }
}

fn err_text(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// The CLI's analysis of a line scan (src/bin/asperity/profile.rs,
/// `analyse_line` and the JSON of `line_scan`), without `file` and `plots`.
fn line_json(
    raw: &s::Profile,
    detrend: Detrend,
    cutoff: Option<f64>,
    convention: s::Convention,
) -> Result<Value, String> {
    let detrended = match detrend {
        Detrend::None => raw.clone(),
        Detrend::Mean => raw.remove_form(s::Form::Mean).map_err(err_text)?,
        Detrend::Linear => raw.remove_form(s::Form::Linear).map_err(err_text)?,
        Detrend::Quadratic => raw.remove_form(s::Form::Quadratic).map_err(err_text)?,
    };
    let analysed = match cutoff {
        None => detrended,
        Some(lc) => {
            let f = detrended
                .gaussian_filter(lc, s::FilterEnds::Discard)
                .map_err(|e| {
                    format!("cutoff {lc:e} m (profile length {:e} m): {e}", raw.length())
                })?;
            if f.roughness.length() < lc {
                return Err(format!(
                    "invalid argument `cutoff` = {lc:e}: too long for this profile ({:e} m): after discarding \
                     λc/2 at each end {:e} m remain, less than one sampling length λc; the profile must be \
                     at least 2λc long",
                    raw.length(),
                    f.roughness.length()
                ));
            }
            f.roughness
        }
    };
    let options = s::ParameterOptions {
        sampling_length: cutoff,
        convention,
        ..s::ParameterOptions::default()
    };
    let p = analysed.parameters(&options).map_err(err_text)?;
    let dx = analysed.dx();
    let evaluated = p.sampling_lengths * (p.sampling_length / dx).round() as usize;
    let k = s::material_ratio_parameters(&analysed.heights()[..evaluated]).map_err(err_text)?;
    // Moments from the derivatives; the rectangular-window ones (the end
    // jump of a non-periodic scan) only under names that say so.
    let moments = s::spectral_moments(analysed.heights(), dx).map_err(err_text)?;
    let rectangular = analysed.psd().map_err(err_text)?.moments();
    let correlation_length = analysed
        .acf()
        .map_err(err_text)?
        .correlation_length(std::f64::consts::E.recip())
        .map_err(err_text)?;
    let estimate = s::hurst_estimate(analysed.heights(), dx).map_err(err_text)?;
    let fit = estimate.fit;
    let elements_reason = p.profile_elements_reason();
    let mut v = serde_json::to_value(p).map_err(err_text)?;
    if let (Some(o), Value::Object(k)) = (
        v.as_object_mut(),
        serde_json::to_value(k).map_err(err_text)?,
    ) {
        o.extend(k);
    }
    let extra = json!({
        "kind": "profile",
        "detrend": detrend.name(),
        "cutoff": cutoff,
        "points_read": raw.len(),
        "points": analysed.len(),
        "dx": analysed.dx(),
        "x0": analysed.x0(),
        "length": analysed.length(),
        "evaluation_length": p.sampling_length * p.sampling_lengths as f64,
        "spacing_deviation": raw.spacing_deviation(),
        "moments_from": "derivatives (seven-point slopes, three-point second differences)",
        "m0": moments.m0,
        "m2": moments.m2,
        "m4": moments.m4,
        "nayak_alpha": moments.nayak_alpha(),
        "m0_rectangular_window": rectangular.m0,
        "m2_rectangular_window": rectangular.m2,
        "m4_rectangular_window": rectangular.m4,
        "nayak_alpha_rectangular_window": rectangular.nayak_alpha(),
        "correlation_length_1e": correlation_length,
        "psd_hurst_uncertainty": fit.map(|f| f.hurst_uncertainty),
        "psd_fit": fit,
        "psd_fit_reason": estimate.reason,
        "profile_elements_reason": elements_reason,
    });
    if let (Some(o), Value::Object(extra)) = (v.as_object_mut(), extra) {
        o.extend(extra);
    }
    Ok(v)
}

/// The CLI's analysis of a map, without `file` and `plots`.
fn map_json(t: s::Topography, detrend: Detrend, cutoff: Option<f64>) -> Result<Value, String> {
    let t = match detrend {
        Detrend::None => t,
        Detrend::Mean => t.remove_form(s::MapForm::Mean).map_err(err_text)?,
        Detrend::Linear => t.remove_form(s::MapForm::Plane).map_err(err_text)?,
        Detrend::Quadratic => t.remove_form(s::MapForm::Quadratic).map_err(err_text)?,
    };
    let (t, first) = match cutoff {
        None => (t, None),
        Some(lc) => {
            let f = s::areal_gaussian_filter(&t, lc, s::FilterEnds::Discard)
                .map_err(|e| format!("cutoff {lc:e} m: {e}"))?;
            (f.roughness, Some(f.first_index))
        }
    };
    let p = t.parameters().map_err(err_text)?;
    let psd_radial = s::psd_2d(&t, s::Window::Hann).map_err(err_text)?.radial();
    let acf_radial = s::acf_2d(&t).map_err(err_text)?.radial();
    let iso = s::isotropy(&t, 0.2).map_err(err_text)?;
    let scale = s::scale_dependent_map(&t).map_err(err_text)?;
    let f = s::functional_parameters(&t).map_err(err_text)?;
    let mut v = serde_json::to_value(p).map_err(err_text)?;
    if let (Some(o), Value::Object(f)) = (
        v.as_object_mut(),
        serde_json::to_value(f).map_err(err_text)?,
    ) {
        o.extend(f);
    }
    let extra = json!({
        "kind": "map",
        "detrend": detrend.name(),
        "points": t.heights().len(),
        "nx": t.nx(),
        "ny": t.ny(),
        "dx": t.dx(),
        "dy": t.dy(),
        "cutoff": cutoff,
        "first_index": first,
        "isotropy": iso,
        "scale_dependent": scale,
        "psd_radial": {"window": "hann", "q": psd_radial.r, "c": psd_radial.value},
        "acf_radial": {"lag": acf_radial.r, "r": acf_radial.value},
    });
    if let (Some(o), Value::Object(extra)) = (v.as_object_mut(), extra) {
        o.extend(extra);
    }
    Ok(v)
}

fn profile_arg(x: &Bound<'_, PyAny>, z: &Bound<'_, PyAny>) -> PyResult<s::Profile> {
    let zs = array(z, "z")?.as_slice()?.to_vec();
    if x.is_instance_of::<pyo3::types::PyFloat>() || x.is_instance_of::<pyo3::types::PyInt>() {
        return s::Profile::new(real(x, "x")?, zs).map_err(|e| {
            rs(crate::common::renamed(
                crate::common::renamed(e, "dx", "x"),
                "heights",
                "z",
            ))
        });
    }
    let xa = array(x, "x")?;
    s::profile_from_positions(xa.as_slice()?, zs, s::Spacing::Tolerant).map_err(|e| {
        rs(crate::common::renamed(
            crate::common::renamed(e, "heights", "z"),
            "heights.len()",
            "z",
        ))
    })
}

fn json_to_py(py: Python<'_>, v: &Value) -> PyResult<Py<PyAny>> {
    crate::common::json_value(py, &v.to_string())
}

/// profile_parameters(x, z, detrend="linear", cutoff=None) -> dict
///
/// ISO 4287 parameters of a line scan, computed as ``asperity profile
/// --json`` does, with its keys (SI: m, m², m⁻², rad/m): ``Rp Rv Rz Rc Rt
/// Ra Rq Rsk Rku RSm RDq`` (``Rc``, ``RSm`` None without a complete profile
/// element), ``psd_hurst_exponent``, ``sampling_length``,
/// ``sampling_lengths``, ``evaluation_length``, ``kind``, ``detrend``,
/// ``cutoff``, ``points_read``, ``points``, ``dx``, ``x0``, ``length``,
/// ``spacing_deviation``, ``m0 m2 m4``, ``nayak_alpha``,
/// ``correlation_length_1e``, ``psd_fit``. ``x``: positions (m, 1-D array,
/// uniform to within half a spacing) or the spacing dx (m, float); ``z``:
/// heights (m). ``detrend``: ``"none"``, ``"mean"``, ``"linear"`` (ISO) or
/// ``"quadratic"``; ``cutoff``: the Gaussian cut-off λc (m) or None;
/// ``convention``: ``"iso21920"`` (ISO 21920-2, default: Ra, Rq, Rsk, Rku,
/// RΔq, Rc, RSm over the evaluation length) or ``"iso4287"`` (averaged over
/// the sampling lengths), named by the ``convention`` key. Also ``Rk Rpk Rvk
/// Mr1 Mr2`` (ISO 13565-2, ratios as fractions).
#[pyfunction]
#[pyo3(signature = (x, z, detrend=None, cutoff=None, convention=None))]
fn profile_parameters(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    z: &Bound<'_, PyAny>,
    detrend: Option<&Bound<'_, PyAny>>,
    cutoff: Option<&Bound<'_, PyAny>>,
    convention: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let d = Detrend::parse(detrend)?;
    let c = real_opt(cutoff, "cutoff")?;
    let k = self::convention(convention)?;
    let p = profile_arg(x, z)?;
    let v = py.detach(|| line_json(&p, d, c, k)).map_err(any_err)?;
    json_to_py(py, &v)
}

/// map_parameters(z, dx, dy=None, detrend="linear") -> dict
///
/// ISO 25178-2 height parameters of a height map, as ``asperity profile
/// --json`` on a map: ``Sa Sq Ssk Sku Sp Sv Sz Sdq`` with ``kind``,
/// ``detrend``, ``points``, ``nx``, ``ny``, ``dx``, ``dy``, ``cutoff``,
/// ``first_index``, ``isotropy``, ``scale_dependent``, ``psd_radial``,
/// ``acf_radial``. ``z``: heights (m), a C-contiguous 2-D float64 array
/// indexed [y, x]; dx, dy: spacings (m, dy defaults to dx). ``detrend``:
/// ``"none"``, ``"mean"``, ``"linear"`` (a plane) or ``"quadratic"`` (a
/// quadric). ``cutoff`` (m): analyse the roughness surface of the ISO
/// 16610-61 areal Gaussian filter (λc/2 dropped at every edge).
#[pyfunction]
#[pyo3(signature = (z, dx, dy=None, detrend=None, cutoff=None))]
fn map_parameters(
    py: Python<'_>,
    z: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
    detrend: Option<&Bound<'_, PyAny>>,
    cutoff: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let d = Detrend::parse(detrend)?;
    let t = topography_arg(z, dx, dy)?;
    let c = real_opt(cutoff, "cutoff")?;
    let v = py.detach(|| map_json(t, d, c)).map_err(any_err)?;
    json_to_py(py, &v)
}

fn topography_arg(
    z: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
) -> PyResult<s::Topography> {
    let dxv = real(dx, "dx")?;
    let dyv = real_opt(dy, "dy")?.unwrap_or(dxv);
    let a = z.cast::<PyArray2<f64>>().map_err(|_| {
        arg_error(
            "z",
            "must be a 2-D float64 array (heights indexed [y, x], m)",
        )
    })?;
    if !a.is_c_contiguous() {
        return Err(arg_error(
            "z",
            "must be a C-contiguous array (got a strided view; use numpy.ascontiguousarray)",
        ));
    }
    let shape = a.shape().to_vec();
    let ro = a.try_readonly().map_err(|e| arg_error("z", e))?;
    let h = ro.as_slice()?.to_vec();
    s::Topography::new(shape[1], shape[0], dxv, dyv, h).map_err(|e| {
        rs(crate::common::renamed(
            crate::common::renamed(e, "heights", "z"),
            "heights.len()",
            "z",
        ))
    })
}

/// analyze_profile_file(path, detrend="linear", cutoff=None, convention="iso21920") -> dict
///
/// ``asperity profile FILE --json`` without plots: reads an instrument file
/// (X3P, Nanoscope, Dektak CSV, Hommel .hfm) or plain text (a line scan,
/// two columns x z in m, or a map: grid with ``# dx_m=`` metadata, or x y z
/// triplets) and returns the same dict as ``profile_parameters`` /
/// ``map_parameters`` with ``file`` (the path as given) and ``plots`` ([]).
#[pyfunction]
#[pyo3(signature = (path, detrend=None, cutoff=None, convention=None))]
fn analyze_profile_file(
    py: Python<'_>,
    path: std::path::PathBuf,
    detrend: Option<&Bound<'_, PyAny>>,
    cutoff: Option<&Bound<'_, PyAny>>,
    convention: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let d = Detrend::parse(detrend)?;
    let c = real_opt(cutoff, "cutoff")?;
    let k = self::convention(convention)?;
    let v = py
        .detach(|| -> Result<Value, String> {
            let m = s::read_measurement(&path, s::Spacing::Tolerant)
                .map_err(|e| format!("{}: {e}", path.display()))?;
            let mut v = match m.surface {
                s::Surface::Map(t) => map_json(t, d, c)?,
                s::Surface::Profile(p) => line_json(&p, d, c, k)?,
            };
            if let Some(o) = v.as_object_mut() {
                o.insert("format".into(), Value::String(m.format.name().into()));
                o.insert("channel".into(), json!(m.channel));
            }
            if let Some(o) = v.as_object_mut() {
                o.insert("file".into(), Value::String(path.display().to_string()));
                o.insert("plots".into(), Value::Array(vec![]));
            }
            Ok(v)
        })
        .map_err(any_err)?;
    json_to_py(py, &v)
}

/// read_profile(path) -> dict
///
/// A line scan from a text file (two columns x z, m; tolerant spacing):
/// ``x`` (m, the uniform grid), ``z`` (m), ``dx`` (m), ``x0`` (m),
/// ``spacing_deviation`` (of the file's positions, in units of dx).
#[pyfunction]
fn read_profile<'py>(py: Python<'py>, path: std::path::PathBuf) -> PyResult<Bound<'py, PyDict>> {
    let p = s::read_profile(&path, s::Spacing::Tolerant)
        .map_err(|e| any_err(format!("{}: {e}", path.display())))?;
    let d = PyDict::new(py);
    let x: Vec<f64> = (0..p.len()).map(|j| p.x(j)).collect();
    d.set_item("x", PyArray1::from_vec(py, x))?;
    d.set_item("z", PyArray1::from_slice(py, p.heights()))?;
    d.set_item("dx", p.dx())?;
    d.set_item("x0", p.x0())?;
    d.set_item("spacing_deviation", p.spacing_deviation())?;
    Ok(d)
}

/// read_topography(path) -> dict
///
/// A height map from a text file: ``z`` (m, 2-D array indexed [y, x]),
/// ``dx``, ``dy`` (m).
#[pyfunction]
fn read_topography<'py>(py: Python<'py>, path: std::path::PathBuf) -> PyResult<Bound<'py, PyDict>> {
    let t = s::read_topography(&path, s::Spacing::Tolerant)
        .map_err(|e| any_err(format!("{}: {e}", path.display())))?;
    let d = PyDict::new(py);
    let z = PyArray1::from_slice(py, t.heights()).reshape([t.ny(), t.nx()])?;
    d.set_item("z", z)?;
    d.set_item("dx", t.dx())?;
    d.set_item("dy", t.dy())?;
    Ok(d)
}

fn heights<'py>(z: &Bound<'py, PyAny>) -> PyResult<numpy::PyReadonlyArray1<'py, f64>> {
    array(z, "z")
}

fn rz(e: asperity::Error) -> PyErr {
    rs(crate::common::renamed(
        crate::common::renamed(e, "heights", "z"),
        "heights.len()",
        "z",
    ))
}

/// psd(z, dx, window="rectangular") -> dict
///
/// One-sided power spectral density of heights ``z`` (m) sampled every
/// ``dx`` (m): ``q`` (rad/m), ``psd`` G(q) (m³), ``dq`` (rad/m), the
/// q^p moments of this PSD under names that say which window gave them,
/// ``m0_rectangular_window`` (m²), ``m2_…``, ``m4_…`` (m⁻²),
/// ``nayak_alpha_…`` (or ``…_hann_window``): for a non-periodic profile the
/// rectangular ones measure the jump between its ends; ``spectral_moments``
/// gives the profile's slope and curvature variances.
/// ``window``: ``"rectangular"`` (exact Parseval) or ``"hann"``.
#[pyfunction]
#[pyo3(signature = (z, dx, window=None))]
fn psd<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
    window: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let w = match window {
        None => s::Window::Rectangular,
        Some(w) => match string(w, "window")?.as_str() {
            "rectangular" | "none" => s::Window::Rectangular,
            "hann" => s::Window::Hann,
            x => {
                return Err(arg_error(
                    "window",
                    format!("must be \"rectangular\" or \"hann\", got {x:?}"),
                ))
            }
        },
    };
    let h = heights(z)?;
    let hs = h.as_slice()?;
    let dx = real(dx, "dx")?;
    let p = py.detach(|| s::psd_windowed(hs, dx, w)).map_err(rz)?;
    let m = p.moments();
    let d = PyDict::new(py);
    d.set_item("dq", p.dq)?;
    d.set_item("q", PyArray1::from_vec(py, p.q))?;
    d.set_item("psd", PyArray1::from_vec(py, p.c))?;
    let tag = if w == s::Window::Hann {
        "hann"
    } else {
        "rectangular"
    };
    d.set_item(format!("m0_{tag}_window"), m.m0)?;
    d.set_item(format!("m2_{tag}_window"), m.m2)?;
    d.set_item(format!("m4_{tag}_window"), m.m4)?;
    d.set_item(format!("nayak_alpha_{tag}_window"), m.nayak_alpha())?;
    Ok(d)
}

/// acf(z, dx) -> dict
///
/// Autocorrelation function of heights ``z`` (m) every ``dx`` (m), mean
/// removed: ``lag`` (m), ``acf`` R (m², R[0] = Rq²), ``normalized`` R/R[0]
/// and ``correlation_length_1e`` (m, the lag where it falls to 1/e, or None).
#[pyfunction]
fn acf<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let h = heights(z)?;
    let hs = h.as_slice()?;
    let dx = real(dx, "dx")?;
    let a = py.detach(|| s::acf(hs, dx)).map_err(rz)?;
    let d = PyDict::new(py);
    let lag: Vec<f64> = (0..a.r.len()).map(|k| a.lag(k)).collect();
    d.set_item("lag", PyArray1::from_vec(py, lag))?;
    d.set_item("normalized", PyArray1::from_vec(py, a.normalized()))?;
    d.set_item(
        "correlation_length_1e",
        a.correlation_length(std::f64::consts::E.recip())
            .map_err(rs)?,
    )?;
    d.set_item("acf", PyArray1::from_vec(py, a.r))?;
    Ok(d)
}

/// hurst_fit(z, dx, band=None) -> dict
///
/// Power law G = A q^s of the PSD of ``z`` (m, every ``dx`` m): bridge
/// detrending, Hann periodogram with the window's smoothing modelled,
/// weighted fit of log bins, in ``band`` = (q_min, q_max) (rad/m) or, by
/// default, the band chosen from the data (the widest run of one decade or
/// more that is a power law with 0 <= H <= 1; ``asperity.Error`` when there
/// is none): ``hurst`` H = -(s+1)/2, ``hurst_uncertainty``, ``slope``,
/// ``slope_uncertainty``, ``prefactor``, ``r_squared``, ``chi2_per_dof``,
/// ``q_min``, ``q_max``, ``bins``.
#[pyfunction]
#[pyo3(signature = (z, dx, band=None))]
fn hurst_fit(
    py: Python<'_>,
    z: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    band: Option<(f64, f64)>,
) -> PyResult<Py<PyAny>> {
    let h = heights(z)?;
    let hs = h.as_slice()?;
    let dx = real(dx, "dx")?;
    let f = py.detach(|| s::hurst_fit(hs, dx, band)).map_err(rz)?;
    to_py_value(py, &f)
}

/// spectral_moments(z, dx) -> dict
///
/// Spectral moments of heights ``z`` (m, every ``dx`` m) from the
/// derivatives: ``m0`` = mean Z² (m²), ``m2`` = mean squared seven-point
/// slope (as RΔq), ``m4`` = mean squared three-point second difference
/// (m⁻²), ``nayak_alpha`` = m0 m4 / m2².
#[pyfunction]
fn spectral_moments<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let h = heights(z)?;
    let hs = h.as_slice()?;
    let dx = real(dx, "dx")?;
    let m = py.detach(|| s::spectral_moments(hs, dx)).map_err(rz)?;
    let d = PyDict::new(py);
    d.set_item("m0", m.m0)?;
    d.set_item("m2", m.m2)?;
    d.set_item("m4", m.m4)?;
    d.set_item("nayak_alpha", m.nayak_alpha())?;
    Ok(d)
}

fn window_arg(window: Option<&Bound<'_, PyAny>>) -> PyResult<s::Window> {
    match window {
        None => Ok(s::Window::Rectangular),
        Some(w) => match string(w, "window")?.as_str() {
            "rectangular" | "none" => Ok(s::Window::Rectangular),
            "hann" => Ok(s::Window::Hann),
            x => Err(arg_error(
                "window",
                format!("must be \"rectangular\" or \"hann\", got {x:?}"),
            )),
        },
    }
}

/// psd_2d(z, dx, dy=None, window="rectangular") -> dict
///
/// Two-dimensional PSD of a height map ``z`` (m, 2-D array [y, x]), centred:
/// ``psd`` C(qy, qx) (m⁴, 2-D array [y, x]) with ``qx``, ``qy`` (rad/m),
/// ``dqx``, ``dqy``; sum(C)·dqx·dqy = Sq² for the rectangular window; and
/// its radial average ``radial_q`` (rad/m), ``radial_psd`` (m⁴).
#[pyfunction]
#[pyo3(signature = (z, dx, dy=None, window=None))]
fn psd_2d<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
    window: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let w = window_arg(window)?;
    let t = topography_arg(z, dx, dy)?;
    let g = py.detach(|| s::psd_2d(&t, w)).map_err(rs)?;
    let r = g.radial();
    let d = PyDict::new(py);
    let qx: Vec<f64> = (0..g.nx).map(|i| g.qx(i)).collect();
    let qy: Vec<f64> = (0..g.ny).map(|j| g.qy(j)).collect();
    d.set_item("qx", PyArray1::from_vec(py, qx))?;
    d.set_item("qy", PyArray1::from_vec(py, qy))?;
    d.set_item("dqx", g.dqx)?;
    d.set_item("dqy", g.dqy)?;
    d.set_item("psd", PyArray1::from_vec(py, g.c).reshape([g.ny, g.nx])?)?;
    d.set_item("radial_q", PyArray1::from_vec(py, r.r))?;
    d.set_item("radial_psd", PyArray1::from_vec(py, r.value))?;
    Ok(d)
}

/// acf_2d(z, dx, dy=None) -> dict
///
/// Two-dimensional ACF of a height map ``z`` (m, [y, x]) on the full lag
/// grid, centred: ``acf`` R (m², 2-D array [(2ny−1), (2nx−1)]),
/// ``tau_x``, ``tau_y`` (m); R at (0, 0) is Sq²; the radial average
/// ``radial_lag`` (m), ``radial_acf`` (m²).
#[pyfunction]
#[pyo3(signature = (z, dx, dy=None))]
fn acf_2d<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let t = topography_arg(z, dx, dy)?;
    let a = py.detach(|| s::acf_2d(&t)).map_err(rs)?;
    let r = a.radial();
    let d = PyDict::new(py);
    let tx: Vec<f64> = (0..a.nx).map(|i| a.tau_x(i)).collect();
    let ty: Vec<f64> = (0..a.ny).map(|j| a.tau_y(j)).collect();
    d.set_item("tau_x", PyArray1::from_vec(py, tx))?;
    d.set_item("tau_y", PyArray1::from_vec(py, ty))?;
    d.set_item("acf", PyArray1::from_vec(py, a.r).reshape([a.ny, a.nx])?)?;
    d.set_item("radial_lag", PyArray1::from_vec(py, r.r))?;
    d.set_item("radial_acf", PyArray1::from_vec(py, r.value))?;
    Ok(d)
}

/// isotropy(z, dx, dy=None, s=0.2) -> dict
///
/// Isotropy of a height map ``z`` (m, [y, x]): ``texture_aspect_ratio``
/// (Str: shortest over longest distance where the normalised ACF falls to
/// ``s``; None when it does not fall in some direction),
/// ``autocorrelation_length`` (Sal, m), ``longest_decay_length`` (m),
/// ``texture_direction`` (rad), ``gradient_ratio`` (smallest over largest
/// directional rms slope), ``gradient_direction`` (rad, steepest),
/// ``rms_slope_max``, ``rms_slope_min``, ``s``.
#[pyfunction]
#[pyo3(signature = (z, dx, dy=None, s=0.2))]
fn isotropy(
    py: Python<'_>,
    z: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
    s: f64,
) -> PyResult<Py<PyAny>> {
    let t = topography_arg(z, dx, dy)?;
    let i = py.detach(|| s::isotropy(&t, s)).map_err(rs)?;
    to_py_value(py, &i)
}

/// scale_dependent(z, dx, dy=None) -> dict
///
/// rms slope and curvature at increasing scale h (finite differences at
/// step h): for a profile ``z`` (1-D) ``scale`` (m), ``slope_rms``,
/// ``curvature_rms`` (1/m); for a map (2-D [y, x]) ``along_x`` and
/// ``along_y``, each such a dict.
#[pyfunction]
#[pyo3(signature = (z, dx, dy=None))]
fn scale_dependent(
    py: Python<'_>,
    z: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    if z.cast::<PyArray2<f64>>().is_ok() {
        let t = topography_arg(z, dx, dy)?;
        let m = py.detach(|| s::scale_dependent_map(&t)).map_err(rs)?;
        return to_py_value(py, &m);
    }
    let h = heights(z)?;
    let hs = h.as_slice()?;
    let dx = real(dx, "dx")?;
    let r = py.detach(|| s::scale_dependent(hs, dx)).map_err(rz)?;
    to_py_value(py, &r)
}

/// areal_gaussian_filter(z, dx, cutoff, dy=None, ends="discard") -> dict
///
/// ISO 16610-61 areal Gaussian filter of a height map ``z`` (m, [y, x]) for
/// the cut-off ``cutoff`` (m): ``mean_surface`` and ``roughness`` (m, 2-D
/// arrays [y, x]) and ``first_index`` (i, j) of the retained grid;
/// ``ends``: ``"discard"`` (drop λc/2 at every edge) or ``"keep"``.
#[pyfunction]
#[pyo3(signature = (z, dx, cutoff, dy=None, ends=None))]
fn areal_gaussian_filter<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
    cutoff: &Bound<'_, PyAny>,
    dy: Option<&Bound<'_, PyAny>>,
    ends: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let e = filter_ends(ends)?;
    let lc = real(cutoff, "cutoff")?;
    let t = topography_arg(z, dx, dy)?;
    let f = py
        .detach(|| s::areal_gaussian_filter(&t, lc, e))
        .map_err(rs)?;
    let (nx, ny) = (f.roughness.nx(), f.roughness.ny());
    let d = PyDict::new(py);
    d.set_item(
        "mean_surface",
        PyArray1::from_slice(py, f.mean_surface.heights()).reshape([ny, nx])?,
    )?;
    d.set_item(
        "roughness",
        PyArray1::from_slice(py, f.roughness.heights()).reshape([ny, nx])?,
    )?;
    d.set_item("first_index", f.first_index)?;
    Ok(d)
}

/// remove_form(z, form="linear") -> numpy.ndarray
///
/// Heights ``z`` (m) minus their least-squares ``form``: ``"mean"``,
/// ``"linear"`` or ``"quadratic"`` (m).
#[pyfunction]
#[pyo3(signature = (z, form=None))]
fn remove_form<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    form: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let f = match form {
        None => s::Form::Linear,
        Some(f) => match string(f, "form")?.as_str() {
            "mean" => s::Form::Mean,
            "linear" => s::Form::Linear,
            "quadratic" => s::Form::Quadratic,
            x => {
                return Err(arg_error(
                    "form",
                    format!("must be \"mean\", \"linear\" or \"quadratic\", got {x:?}"),
                ))
            }
        },
    };
    let h = heights(z)?;
    Ok(PyArray1::from_vec(
        py,
        s::remove_form(h.as_slice()?, f).map_err(rz)?,
    ))
}

/// gaussian_filter(z, dx, cutoff, ends="discard") -> dict
///
/// The ``ends`` argument of the filters: ``"discard"`` (default) or ``"keep"``.
fn filter_ends(ends: Option<&Bound<'_, PyAny>>) -> PyResult<s::FilterEnds> {
    match ends {
        None => Ok(s::FilterEnds::Discard),
        Some(v) => match string(v, "ends")?.as_str() {
            "discard" => Ok(s::FilterEnds::Discard),
            "keep" => Ok(s::FilterEnds::Keep),
            x => Err(arg_error(
                "ends",
                format!("must be \"discard\" or \"keep\", got {x:?}"),
            )),
        },
    }
}

/// ISO 16610-21 Gaussian filter of heights ``z`` (m, every ``dx`` m) with
/// cut-off λc ``cutoff`` (m): ``mean_line`` and ``roughness`` (m) on the
/// retained samples, from index ``first_index`` (``ends="discard"`` drops
/// λc/2 at each end; ``"keep"`` keeps every point).
#[pyfunction]
#[pyo3(signature = (z, dx, cutoff, ends=None))]
fn gaussian_filter<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
    cutoff: &Bound<'_, PyAny>,
    ends: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let e = filter_ends(ends)?;
    let p = s::Profile::new(real(dx, "dx")?, heights(z)?.as_slice()?.to_vec()).map_err(rz)?;
    let lc = real(cutoff, "cutoff")?;
    let f = py.detach(|| s::gaussian_filter(&p, lc, e)).map_err(rs)?;
    let d = PyDict::new(py);
    d.set_item("first_index", f.first_index)?;
    d.set_item("mean_line", PyArray1::from_slice(py, f.mean_line.heights()))?;
    d.set_item("roughness", PyArray1::from_slice(py, f.roughness.heights()))?;
    Ok(d)
}

/// `f` of each item of `items` as a numpy array.
fn column<'py, T, U: numpy::Element>(
    py: Python<'py>,
    items: &[T],
    f: impl Fn(&T) -> U,
) -> Bound<'py, PyArray1<U>> {
    PyArray1::from_vec(py, items.iter().map(f).collect())
}

/// peaks(z, dx) -> dict
///
/// Local maxima of heights ``z`` (m, every ``dx`` m): arrays ``index``,
/// ``x`` (m), ``height`` (m), ``curvature`` (1/m).
#[pyfunction]
fn peaks<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let h = heights(z)?;
    let p = s::peaks(h.as_slice()?, real(dx, "dx")?).map_err(rz)?;
    let d = PyDict::new(py);
    d.set_item("index", column(py, &p, |q| q.index as i64))?;
    d.set_item("x", column(py, &p, |q| q.x))?;
    d.set_item("height", column(py, &p, |q| q.height))?;
    d.set_item("curvature", column(py, &p, |q| q.curvature))?;
    Ok(d)
}

/// material_ratio_curve(z, points=101) -> dict
///
/// The Abbott–Firestone curve of heights ``z`` (m): ``ratio`` Rmr (0…1) and
/// ``level`` c (m, from the highest peak down), ``points`` samples.
#[pyfunction]
#[pyo3(signature = (z, points=None))]
fn material_ratio_curve<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    points: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let n = points
        .map(|p| count(p, "points"))
        .transpose()?
        .unwrap_or(101);
    let h = heights(z)?;
    let c = s::MaterialRatioCurve::new(h.as_slice()?).map_err(rz)?;
    let pts = c.curve(n);
    let d = PyDict::new(py);
    d.set_item("ratio", column(py, &pts, |p| p.0))?;
    d.set_item("level", column(py, &pts, |p| p.1))?;
    Ok(d)
}

/// box_counting_dimension(z, dx) -> dict
///
/// Box-counting fractal dimension of a profile (heights ``z`` m, every
/// ``dx`` m): ``dimension``, ``r_squared``, ``sizes`` (m), ``counts``.
#[pyfunction]
fn box_counting_dimension<'py>(
    py: Python<'py>,
    z: &Bound<'py, PyAny>,
    dx: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let h = heights(z)?;
    let b = s::box_counting_dimension(h.as_slice()?, real(dx, "dx")?).map_err(rz)?;
    let d = PyDict::new(py);
    d.set_item("dimension", b.dimension)?;
    d.set_item("r_squared", b.r_squared)?;
    d.set_item("sizes", PyArray1::from_vec(py, b.sizes))?;
    d.set_item("counts", PyArray1::from_vec(py, b.counts))?;
    Ok(d)
}

fn self_affine(
    hurst: &Bound<'_, PyAny>,
    rq: &Bound<'_, PyAny>,
    roll_off_wavelength: Option<&Bound<'_, PyAny>>,
    cutoff_wavelength: Option<&Bound<'_, PyAny>>,
) -> PyResult<s::SelfAffine> {
    let mut g = s::SelfAffine::new(real(hurst, "hurst")?, real(rq, "rq")?).map_err(rs)?;
    if let Some(w) = real_opt(roll_off_wavelength, "roll_off_wavelength")? {
        g = g.with_roll_off(w).map_err(rs)?;
    }
    if let Some(w) = real_opt(cutoff_wavelength, "cutoff_wavelength")? {
        g = g.with_cutoff(w).map_err(rs)?;
    }
    Ok(g)
}

/// self_affine_profile(n, dx, hurst, rq, seed=0, roll_off_wavelength=None, cutoff_wavelength=None) -> numpy.ndarray
///
/// A periodic Gaussian self-affine profile of ``n`` heights (m) every ``dx``
/// (m): Hurst exponent H in [0, 1], root-mean-square height Rq (m, matched
/// exactly), optional roll-off and short-wavelength cut-off (m); seeded
/// (ChaCha8), the same on every platform.
#[pyfunction]
#[pyo3(signature = (n, dx, hurst, rq, seed=None, roll_off_wavelength=None, cutoff_wavelength=None))]
#[allow(clippy::too_many_arguments)]
fn self_affine_profile<'py>(
    py: Python<'py>,
    n: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    hurst: &Bound<'_, PyAny>,
    rq: &Bound<'_, PyAny>,
    seed: Option<&Bound<'_, PyAny>>,
    roll_off_wavelength: Option<&Bound<'_, PyAny>>,
    cutoff_wavelength: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let g = self_affine(hurst, rq, roll_off_wavelength, cutoff_wavelength)?;
    let (n, dx) = (count(n, "n")?, real(dx, "dx")?);
    let sd = seed.map(|s| self::seed_of(s)).transpose()?.unwrap_or(0);
    let p = py.detach(|| g.profile(n, dx, sd)).map_err(rs)?;
    Ok(PyArray1::from_vec(py, p.into_heights()))
}

fn seed_of(s: &Bound<'_, PyAny>) -> PyResult<u64> {
    seed(s, "seed")
}

/// self_affine_map(nx, ny, dx, dy, hurst, rq, seed=0, roll_off_wavelength=None, cutoff_wavelength=None) -> numpy.ndarray
///
/// An isotropic self-affine height map (m), a 2-D array indexed [y, x] of
/// ny × nx points spaced dx, dy (m); parameters as ``self_affine_profile``.
#[pyfunction]
#[pyo3(signature = (nx, ny, dx, dy, hurst, rq, seed=None, roll_off_wavelength=None, cutoff_wavelength=None))]
#[allow(clippy::too_many_arguments)]
fn self_affine_map<'py>(
    py: Python<'py>,
    nx: &Bound<'_, PyAny>,
    ny: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    dy: &Bound<'_, PyAny>,
    hurst: &Bound<'_, PyAny>,
    rq: &Bound<'_, PyAny>,
    seed: Option<&Bound<'_, PyAny>>,
    roll_off_wavelength: Option<&Bound<'_, PyAny>>,
    cutoff_wavelength: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let g = self_affine(hurst, rq, roll_off_wavelength, cutoff_wavelength)?;
    let (nx, ny, dx, dy) = (
        count(nx, "nx")?,
        count(ny, "ny")?,
        real(dx, "dx")?,
        real(dy, "dy")?,
    );
    let sd = seed.map(seed_of).transpose()?.unwrap_or(0);
    let t = py.detach(|| g.map(nx, ny, dx, dy, sd)).map_err(rs)?;
    PyArray1::from_slice(py, t.heights()).reshape([ny, nx])
}

/// weierstrass_mandelbrot_profile(n, dx, fractal_dimension, gamma, amplitude, seed=0) -> numpy.ndarray
///
/// A Weierstrass–Mandelbrot profile of ``n`` heights (m) every ``dx`` (m):
/// fractal dimension D in (1, 2), frequency ratio γ > 1, amplitude A (m) of
/// the longest term, random phases from ``seed``.
#[pyfunction]
#[pyo3(signature = (n, dx, fractal_dimension, gamma, amplitude, seed=None))]
fn weierstrass_mandelbrot_profile<'py>(
    py: Python<'py>,
    n: &Bound<'_, PyAny>,
    dx: &Bound<'_, PyAny>,
    fractal_dimension: &Bound<'_, PyAny>,
    gamma: &Bound<'_, PyAny>,
    amplitude: &Bound<'_, PyAny>,
    seed: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let g = s::WeierstrassMandelbrot::new(
        real(fractal_dimension, "fractal_dimension")?,
        real(gamma, "gamma")?,
        real(amplitude, "amplitude")?,
    )
    .map_err(rs)?;
    let (n, dx) = (count(n, "n")?, real(dx, "dx")?);
    let sd = seed.map(seed_of).transpose()?.unwrap_or(0);
    let p = py.detach(|| g.profile(n, dx, sd)).map_err(rs)?;
    Ok(PyArray1::from_vec(py, p.into_heights()))
}

/// cantor_borodich_profile(length, n, descendants, alpha, beta, height, levels) -> numpy.ndarray
///
/// Borodich's Cantor-type self-similar profile sampled at ``n`` points over
/// ``length`` (m): descendants per block m ≥ 2, similarity ratios α in
/// (0, 1/m) and β in (1/m, 1), first step height h (m), ``levels``
/// generations (1…40).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn cantor_borodich_profile<'py>(
    py: Python<'py>,
    length: &Bound<'_, PyAny>,
    n: &Bound<'_, PyAny>,
    descendants: &Bound<'_, PyAny>,
    alpha: &Bound<'_, PyAny>,
    beta: &Bound<'_, PyAny>,
    height: &Bound<'_, PyAny>,
    levels: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let lv = count(levels, "levels")?;
    let g = s::CantorBorodich::new(
        count(descendants, "descendants")?,
        real(alpha, "alpha")?,
        real(beta, "beta")?,
        real(height, "height")?,
        u32::try_from(lv).map_err(|_| arg_error("levels", "must be in 1..=40"))?,
    )
    .map_err(rs)?;
    let p = g
        .profile(real(length, "length")?, count(n, "n")?)
        .map_err(rs)?;
    Ok(PyArray1::from_vec(py, p.into_heights()))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    for f in [
        wrap_pyfunction!(profile_parameters, m)?,
        wrap_pyfunction!(map_parameters, m)?,
        wrap_pyfunction!(analyze_profile_file, m)?,
        wrap_pyfunction!(read_profile, m)?,
        wrap_pyfunction!(read_topography, m)?,
        wrap_pyfunction!(psd, m)?,
        wrap_pyfunction!(acf, m)?,
        wrap_pyfunction!(hurst_fit, m)?,
        wrap_pyfunction!(spectral_moments, m)?,
        wrap_pyfunction!(psd_2d, m)?,
        wrap_pyfunction!(acf_2d, m)?,
        wrap_pyfunction!(isotropy, m)?,
        wrap_pyfunction!(scale_dependent, m)?,
        wrap_pyfunction!(areal_gaussian_filter, m)?,
        wrap_pyfunction!(remove_form, m)?,
        wrap_pyfunction!(gaussian_filter, m)?,
        wrap_pyfunction!(peaks, m)?,
        wrap_pyfunction!(material_ratio_curve, m)?,
        wrap_pyfunction!(box_counting_dimension, m)?,
        wrap_pyfunction!(self_affine_profile, m)?,
        wrap_pyfunction!(self_affine_map, m)?,
        wrap_pyfunction!(weierstrass_mandelbrot_profile, m)?,
        wrap_pyfunction!(cantor_borodich_profile, m)?,
    ] {
        m.add_function(f)?;
    }
    Ok(())
}
