//! Exact (bit-preserving) serde for `f64` fields: each value is written as
//! the shortest decimal string that reads back to the same bits
//! (serde_json's default number parser is not correctly rounded, so plain
//! JSON numbers would not round-trip). Non-finite values are rejected.
//!
//! Used by every serialisable value that must evaluate bit-identically after
//! a round trip. The strict form (this module, [`vec`], [`opt`]) reads only
//! such strings, so a table edited by hand cannot lose bits unnoticed
//! (tabulated laws, equilibrium curves); [`lenient`] also reads plain JSON
//! numbers, for values users write by hand (slider geometry).

use serde::{ser::SerializeSeq, Deserialize, Deserializer, Serializer};

#[derive(Deserialize)]
#[serde(untagged)]
enum Num {
    Number(f64),
    Text(String),
}

/// The value of `n`; a plain number only when `lenient`.
fn value<E: serde::de::Error>(n: Num, lenient: bool) -> Result<f64, E> {
    let v = match n {
        Num::Number(v) if lenient => v,
        Num::Number(v) => {
            return Err(E::custom(format!(
                "`{v}` is a number, expected a string holding the exact value"
            )))
        }
        Num::Text(s) => s
            .trim()
            .parse()
            .map_err(|_| E::custom(format!("`{s}` is not a number")))?,
    };
    if v.is_finite() {
        Ok(v)
    } else {
        Err(E::custom("a number is not finite"))
    }
}

/// Serialise a `[f64]`.
pub fn write_seq<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
    let mut seq = s.serialize_seq(Some(v.len()))?;
    for x in v {
        seq.serialize_element(&format!("{x:e}"))?;
    }
    seq.end()
}

/// Serialise an `Option<f64>`.
pub fn write_opt<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(x) => s.serialize_some(&format!("{x:e}")),
        None => s.serialize_none(),
    }
}

/// One exact value; a plain JSON number is accepted only when `LENIENT`.
struct Exact<const LENIENT: bool>(f64);

impl<'de, const LENIENT: bool> Deserialize<'de> for Exact<LENIENT> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        value(Num::deserialize(d)?, LENIENT).map(Exact)
    }
}

fn read_vec<'de, D: Deserializer<'de>, const L: bool>(d: D) -> Result<Vec<f64>, D::Error> {
    Ok(Vec::<Exact<L>>::deserialize(d)?
        .into_iter()
        .map(|e| e.0)
        .collect())
}

fn read_opt<'de, D: Deserializer<'de>, const L: bool>(d: D) -> Result<Option<f64>, D::Error> {
    Ok(Option::<Exact<L>>::deserialize(d)?.map(|e| e.0))
}

/// Serialise one `f64`.
pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&format!("{v:e}"))
}

/// Deserialise one `f64` (a string only).
pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Exact::<false>::deserialize(d).map(|e| e.0)
}

/// `Vec<f64>`, strict.
pub mod vec {
    pub(crate) use super::write_seq as serialize;
    use super::*;

    /// Deserialise.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
        read_vec::<D, false>(d)
    }
}

/// `Option<f64>`, strict.
pub mod opt {
    pub(crate) use super::write_opt as serialize;
    use super::*;

    /// Deserialise.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        read_opt::<D, false>(d)
    }
}

/// The same, reading plain JSON numbers as well.
pub mod lenient {
    pub(crate) use super::serialize;
    use super::*;

    /// Deserialise one `f64` (a string or a number).
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Exact::<true>::deserialize(d).map(|e| e.0)
    }

    /// `Vec<f64>`, lenient.
    pub mod vec {
        pub(crate) use super::super::write_seq as serialize;
        use super::super::*;

        /// Deserialise.
        pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
            read_vec::<D, true>(d)
        }
    }

    /// `Option<f64>`, lenient.
    pub mod opt {
        pub(crate) use super::super::write_opt as serialize;
        use super::super::*;

        /// Deserialise.
        pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
            read_opt::<D, true>(d)
        }
    }
}
