//! Helpers shared by the analyses that report flags and JSON
//! ([`crate::afm`], [`crate::indentation`]).

use serde::Serialize;

/// One JSON object; a serialisation error becomes `{"error": "…"}`.
pub(crate) fn to_json<T: Serialize>(value: &T) -> String {
    serde_json::to_string(value).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
}

/// The flags as a bit mask, bit i for `codes[i]` (unknown codes ignored).
pub(crate) fn flag_mask(flags: &[&str], codes: &[&str]) -> u32 {
    flags
        .iter()
        .filter_map(|c| codes.iter().position(|x| x == c))
        .fold(0, |m, i| m | (1 << i))
}
