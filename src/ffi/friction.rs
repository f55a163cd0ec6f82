//! C ABI for `crate::friction::geometry`: the opaque `AsperitySliderGeometry`
//! handle (a boxed [`SliderGeometry`]) built from two measured profiles or
//! from numbers, its nano-asperity parameters as a plain struct, and its rod
//! levels copied into caller arrays.
//!
//! A geometry is immutable after construction: one handle may be used by any
//! number of threads at once.

use super::{guard, input, output, Failure};
use crate::error::{Error, Result};
use crate::friction::{NanoAsperities, RodLevel, SliderGeometry};

/// The slider of the hierarchical friction model (opaque): nested levels of
/// micro-rods and the nano-asperities on the finest rods' tips. Create it
/// with `asperity_slider_geometry_new` or
/// `asperity_slider_geometry_new_uniform`, release it with
/// `asperity_slider_geometry_free`. Immutable; safe to share between threads.
pub struct AsperitySliderGeometry(pub(crate) SliderGeometry);

/// The nano-asperities on the rod tips (thesis 6.2.1). Lengths in m.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AsperityNanoAsperities {
    /// Height of the van der Waals body h_vdW (m), > 0: the RMS of the AFM
    /// profile (thesis 5-15).
    pub h_vdw: f64,
    /// Width of the van der Waals interaction domain w_vdW (m), > 0 (6-2).
    pub w_vdw: f64,
    /// Height of the chemical tip on the body h_chem (m), >= 0.
    pub h_chem: f64,
    /// Width of the chemical interaction domain w_chem (m), in [0, w_vdW].
    pub w_chem: f64,
    /// Distance between nano-asperities (m), >= w_vdW (6-3).
    pub spacing: f64,
    /// Nano-asperities on one square tip of the finest rods, >= 1 and
    /// <= 2^24, with per_rod * spacing^2 <= (rod width)^2.
    pub per_rod: usize,
}

impl AsperityNanoAsperities {
    fn parameters(&self) -> NanoAsperities {
        NanoAsperities {
            h_vdw: self.h_vdw,
            w_vdw: self.w_vdw,
            h_chem: self.h_chem,
            w_chem: self.w_chem,
            spacing: self.spacing,
        }
    }
}

unsafe fn slice<'a>(p: *const f64, n: usize, name: &'static str) -> Result<&'a [f64]> {
    if p.is_null() {
        return Err(Error::NullPointer { name });
    }
    // SAFETY: the caller provides `n` readable values at `p`.
    Ok(std::slice::from_raw_parts(p, n))
}

unsafe fn emit(
    out: *mut *mut AsperitySliderGeometry,
    make: impl FnOnce() -> Result<SliderGeometry>,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        *out = Box::into_raw(Box::new(AsperitySliderGeometry(make()?)));
        Ok(())
    })
}

fn level(g: &SliderGeometry, level: usize) -> Result<&RodLevel> {
    g.levels().get(level).ok_or(Error::InvalidArgument {
        name: "level",
        value: level as f64,
        bound: "< the number of rod levels",
    })
}

/// Build a slider from two measured profiles, heights from their mean
/// lines (remove form first): `micro_n` heights (m) of a profilometer profile
/// sampled at `micro_dx` (m), cut into rods by thesis (6-1), and `nano_n`
/// heights (m) of an AFM profile sampled at `nano_dx` (m), giving the
/// nano-asperities (5-15, 6-2, 6-3). `rod_widths` holds `n_levels` rod
/// widths (m), coarsest first, each the previous divided by an integer >= 2
/// (nested levels); one level is `n_levels` = 1. Writes a new handle to
/// `*out` (NULL on failure). Errors: NULL pointers, fewer than 8 heights,
/// non-finite values, widths that are not positive, wider than the micro
/// profile or do not nest, constant profiles, finest rods narrower than the
/// nano-asperity spacing or wider than 4096 spacings (more than 2^24
/// nano-asperities per rod).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_new(
    micro_heights: *const f64,
    micro_n: usize,
    micro_dx: f64,
    nano_heights: *const f64,
    nano_n: usize,
    nano_dx: f64,
    rod_widths: *const f64,
    n_levels: usize,
    out: *mut *mut AsperitySliderGeometry,
) -> i32 {
    emit(out, || {
        let micro = slice(micro_heights, micro_n, "micro_heights")?;
        let nano = slice(nano_heights, nano_n, "nano_heights")?;
        let widths = slice(rod_widths, n_levels, "rod_widths")?;
        SliderGeometry::from_slices(micro, micro_dx, widths, nano, nano_dx)
    })
}

/// Build a single-level slider from numbers: `rods` flat rods of
/// `rod_width` (m) at height 0, carrying `nano->per_rod` nano-asperities
/// each with the parameters `*nano` (the hand calculation of thesis 4.4: one
/// 13.5 µm rod, 100 nano-asperities, w_vdW = 430 nm, w_chem = 161 nm).
/// Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_new_uniform(
    rod_width: f64,
    rods: usize,
    nano: *const AsperityNanoAsperities,
    out: *mut *mut AsperitySliderGeometry,
) -> i32 {
    emit(out, || {
        let nano = input(nano, "nano")?;
        SliderGeometry::uniform(rod_width, rods, nano.parameters(), nano.per_rod)
    })
}

/// Release a geometry; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_free(geometry: *mut AsperitySliderGeometry) {
    if !geometry.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(geometry));
        }));
    }
}

/// The nano-asperity parameters of `geometry` and their number per rod tip.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_nano(
    geometry: *const AsperitySliderGeometry,
    out: *mut AsperityNanoAsperities,
) -> i32 {
    guard(|| {
        let g = &input(geometry, "geometry")?.0;
        let out = output(out, "out")?;
        let n = g.nano();
        *out = AsperityNanoAsperities {
            h_vdw: n.h_vdw,
            w_vdw: n.w_vdw,
            h_chem: n.h_chem,
            w_chem: n.w_chem,
            spacing: n.spacing,
            per_rod: g.nano_per_rod(),
        };
        Ok(())
    })
}

/// The number of rod levels of `geometry` (>= 1; level 0 is the coarsest,
/// the last carries the nano-asperities).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_level_count(
    geometry: *const AsperitySliderGeometry,
    count: *mut usize,
) -> i32 {
    guard(|| {
        let g = &input(geometry, "geometry")?.0;
        *output(count, "count")? = g.levels().len();
        Ok(())
    })
}

/// The number of rods of `level` (0 = coarsest).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_rod_count(
    geometry: *const AsperitySliderGeometry,
    level: usize,
    count: *mut usize,
) -> i32 {
    guard(|| {
        let g = &input(geometry, "geometry")?.0;
        let l = self::level(g, level)?;
        *output(count, "count")? = l.len();
        Ok(())
    })
}

/// The rod width (m) of `level` and, if `origin` is not NULL, the position
/// of the left side of its rod 0 (m); rod k spans
/// [origin + k*width, origin + (k+1)*width].
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_rod_width(
    geometry: *const AsperitySliderGeometry,
    level: usize,
    width: *mut f64,
    origin: *mut f64,
) -> i32 {
    guard(|| {
        let g = &input(geometry, "geometry")?.0;
        let l = self::level(g, level)?;
        *output(width, "width")? = l.width();
        if !origin.is_null() {
            *origin = l.origin();
        }
        Ok(())
    })
}

/// Copy the rod heights (m, from the micro profile's mean line, thesis 6-1)
/// of `level` into `heights`, which holds `len` values; `len` must be at
/// least the level's rod count (`asperity_slider_geometry_rod_count`).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_geometry_rod_heights(
    geometry: *const AsperitySliderGeometry,
    level: usize,
    heights: *mut f64,
    len: usize,
) -> i32 {
    guard(|| {
        let g = &input(geometry, "geometry")?.0;
        let l = self::level(g, level)?;
        if heights.is_null() {
            return Err(Failure::from(Error::NullPointer { name: "heights" }));
        }
        if len < l.len() {
            return Err(Error::InvalidArgument {
                name: "len",
                value: len as f64,
                bound: ">= the level's rod count",
            }
            .into());
        }
        // SAFETY: the caller provides `len` >= l.len() writable values.
        std::slice::from_raw_parts_mut(heights, l.len()).copy_from_slice(l.heights());
        Ok(())
    })
}
