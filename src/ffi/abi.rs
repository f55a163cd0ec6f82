//! C ABI for layout queries: the size and alignment of every `repr(C)` type
//! of `include/asperity.h`, by its C name, and the list of those names.
//!
//! Bindings in other languages keep their own copies of the structs (the
//! Fortran module's `type, bind(c)` mirrors, a Python `ctypes.Structure`, a
//! Julia `struct`); with these calls a binding checks its copies against the
//! library it is linked to instead of trusting its own arithmetic. Translation
//! only: the numbers are `size_of`/`align_of` of the Rust types the header is
//! generated from.

use super::{copy_text, guard, input, output, set_last_error, Failure};
use crate::error::Error;
use core::mem::{align_of, size_of};
use std::ffi::{c_char, CStr};

/// One `repr(C)` type of the header.
struct TypeLayout {
    name: &'static str,
    size: usize,
    align: usize,
}

/// The layouts of the laws' input structs (`Asperity<Law>Params`, from the
/// list of `normal_laws!`, first in the header), then of the types listed.
macro_rules! layouts {
    (
        ($($name:literal => $ty:ty),* $(,)?)
        $($(#[$doc:meta])* $law:ident($params:ident) $n:ident = $kind:ident,)*
    ) => {
        &[
            $(TypeLayout {
                name: concat!("Asperity", stringify!($params)),
                size: size_of::<crate::contact::$params>(),
                align: align_of::<crate::contact::$params>(),
            },)*
            $(TypeLayout { name: $name, size: size_of::<$ty>(), align: align_of::<$ty>() }),*
        ]
    };
}

/// Every struct and union of the header with a body, in header order.
/// `tests/abi_layout.rs` fails when the header gains one that is missing here.
const TYPES: &[TypeLayout] = crate::contact::normal_laws!(layouts!(
    "AsperityLawParams" => super::contact::AsperityLawParams,
    "AsperityNormalLaw" => super::contact::AsperityNormalLaw,
    "AsperityContactState" => crate::contact::ContactState,
    "AsperityNormalResponse" => crate::contact::NormalResponse,
    "AsperityFidelityAssessment" => super::fidelity::AsperityFidelityAssessment,
    "AsperityFidelityAdvice" => super::fidelity::AsperityFidelityAdvice,
    "AsperityNanoAsperities" => super::friction::AsperityNanoAsperities,
    "AsperityDissipation" => crate::friction::Dissipation,
    "AsperityHomogenisedSample" => crate::friction::HomogenisedSample,
    "AsperityFrictionIncrement" => crate::friction::FrictionIncrement,
    "AsperityFrictionResponse" => crate::friction::FrictionResponse,
    "AsperityIndentationOptions" => super::indentation::AsperityIndentationOptions,
    "AsperityIndentationResult" => super::indentation::AsperityIndentationResult,
    "AsperityAfmFit" => super::afm::AsperityAfmFit,
    "AsperityAfmResult" => super::afm::AsperityAfmResult,
    "AsperityGwParams" => super::statistics::AsperityGwParams,
    "AsperityGwResponse" => super::statistics::AsperityGwResponse,
    "AsperitySeparation" => super::statistics::AsperitySeparation,
    "AsperityZhuravlev" => super::statistics::AsperityZhuravlev,
    "AsperityZhuravlevResponse" => super::statistics::AsperityZhuravlevResponse,
    "AsperityZhuravlevFriction" => super::statistics::AsperityZhuravlevFriction,
    "AsperityBgtParams" => super::statistics::AsperityBgtParams,
    "AsperityBgtResponse" => super::statistics::AsperityBgtResponse,
    "AsperityBoraResponse" => super::statistics::AsperityBoraResponse,
    "AsperitySergienkoBukharovParams" => super::statistics::AsperitySergienkoBukharovParams,
    "AsperitySergienkoBukharovResult" => super::statistics::AsperitySergienkoBukharovResult,
    "AsperityRoughness" => super::surface::AsperityRoughness,
    "AsperityHurstFit" => super::surface::AsperityHurstFit,
    "AsperityPeakStatistics" => super::surface::AsperityPeakStatistics,
    "AsperitySliderInfo" => super::slider::AsperitySliderInfo,
    "AsperitySliderRecord" => super::slider::AsperitySliderRecord,
    "AsperitySliderOptions" => super::slider::AsperitySliderOptions,
    "AsperityFrictionMaterial" => crate::friction::FrictionMaterial,
    "AsperityLugreParams" => super::dynamic::AsperityLugreParams,
    "AsperityCantorProfile" => crate::hierarchical::CantorProfile,
    "AsperityCantorContact" => crate::hierarchical::CantorContact,
    "AsperityGeneralizedMaxwellSlipParams" => super::dynamic::AsperityGeneralizedMaxwellSlipParams,
    "AsperityPrandtlTomlinsonTwoSpringParams" => super::dynamic::AsperityPrandtlTomlinsonTwoSpringParams,
    "AsperityBurridgeKnopoffParams" => super::dynamic::AsperityBurridgeKnopoffParams,
    "AsperityBorodichKryukova" => super::statistics::AsperityBorodichKryukova,
    "AsperityBorodichKryukovaState" => super::statistics::AsperityBorodichKryukovaState,
    "AsperityBorodichKryukovaSample" => super::statistics::AsperityBorodichKryukovaSample,
    "AsperitySchmittbuhl" => super::hierarchical::AsperitySchmittbuhl,
    "AsperitySchmittbuhlGeneration" => super::hierarchical::AsperitySchmittbuhlGeneration,
    "AsperityHurstEstimate" => super::surface::AsperityHurstEstimate,
));

/// The size `*size` and alignment `*align` in bytes of the `repr(C)` type
/// whose C name is the NUL-terminated `name` (e.g. `"AsperityNormalLaw"`;
/// structs and unions of this header with a body, not the opaque handles).
/// An unknown name gives `ASPERITY_ERR_INVALID_ARGUMENT` naming `name`;
/// `asperity_type_count` and `asperity_type_name` list the known ones.
#[no_mangle]
pub unsafe extern "C" fn asperity_type_layout(
    name: *const c_char,
    size: *mut usize,
    align: *mut usize,
) -> i32 {
    // The unknown name itself goes into the message, which the error type
    // (static text and numbers only) cannot carry: remember it here and
    // write the message after the guard has recorded its own.
    let mut unknown: Option<String> = None;
    let status = guard(|| {
        let p = input(name, "name")?;
        let size = output(size, "size")?;
        let align = output(align, "align")?;
        let bytes = CStr::from_ptr(p).to_bytes();
        match TYPES.iter().find(|t| t.name.as_bytes() == bytes) {
            Some(t) => {
                *size = t.size;
                *align = t.align;
                Ok(())
            }
            None => {
                unknown = Some(String::from_utf8_lossy(bytes).into_owned());
                Err(Failure::from(Error::InvalidArgument {
                    name: "name",
                    value: bytes.len() as f64,
                    bound: "the C name of a struct or union of asperity.h",
                }))
            }
        }
    });
    if let Some(n) = unknown {
        set_last_error(format!(
            "invalid argument `name` = \"{}\": must be the C name of a struct or union of \
             asperity.h with a body (asperity_type_name lists the {} known ones)",
            n.escape_debug(),
            TYPES.len()
        ));
    }
    status
}

/// The number of types `asperity_type_layout` knows (indices
/// `0 .. asperity_type_count()` of `asperity_type_name`).
#[no_mangle]
pub extern "C" fn asperity_type_count() -> usize {
    TYPES.len()
}

/// Copy the C name of type `index` (< `asperity_type_count()`) into `buf`
/// (at most `len − 1` bytes and a NUL) and write its full length in bytes
/// (without the NUL) to `*needed`, so `asperity_type_name(i, NULL, 0, &n)`
/// sizes the buffer. The name is complete only when `*needed < len`;
/// `needed` is required.
#[no_mangle]
pub unsafe extern "C" fn asperity_type_name(
    index: usize,
    buf: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> i32 {
    guard(|| {
        let needed = output(needed, "needed")?;
        let t = TYPES.get(index).ok_or(Error::InvalidArgument {
            name: "index",
            value: index as f64,
            bound: "< asperity_type_count()",
        })?;
        *needed = copy_text(t.name, buf, len);
        Ok(())
    })
}
