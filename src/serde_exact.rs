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

fn write_seq<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
    let mut seq = s.serialize_seq(Some(v.len()))?;
    for x in v {
        seq.serialize_element(&format!("{x:e}"))?;
    }
    seq.end()
}

fn write_opt<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(x) => s.serialize_some(&format!("{x:e}")),
        None => s.serialize_none(),
    }
}

/// Serialise one `f64`.
pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&format!("{v:e}"))
}

/// Deserialise one `f64` (a string only).
pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    value(Num::deserialize(d)?, false)
}

#[derive(Deserialize)]
struct Strict(#[serde(with = "crate::serde_exact")] f64);

#[derive(Deserialize)]
struct Lenient(#[serde(with = "crate::serde_exact::lenient")] f64);

/// `Vec<f64>`, strict.
pub mod vec {
    use super::*;

    /// Serialise.
    pub fn serialize<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
        write_seq(v, s)
    }

    /// Deserialise.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
        Ok(Vec::<Strict>::deserialize(d)?
            .into_iter()
            .map(|e| e.0)
            .collect())
    }
}

/// `Option<f64>`, strict.
pub mod opt {
    use super::*;

    /// Serialise.
    pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        write_opt(v, s)
    }

    /// Deserialise.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        Ok(Option::<Strict>::deserialize(d)?.map(|e| e.0))
    }
}

/// The same, reading plain JSON numbers as well.
pub mod lenient {
    use super::*;

    /// Serialise one `f64`.
    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        super::serialize(v, s)
    }

    /// Deserialise one `f64` (a string or a number).
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        value(Num::deserialize(d)?, true)
    }

    /// `Vec<f64>`, lenient.
    pub mod vec {
        use super::super::*;

        /// Serialise.
        pub fn serialize<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
            write_seq(v, s)
        }

        /// Deserialise.
        pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
            Ok(Vec::<Lenient>::deserialize(d)?
                .into_iter()
                .map(|e| e.0)
                .collect())
        }
    }

    /// `Option<f64>`, lenient.
    pub mod opt {
        use super::super::*;

        /// Serialise.
        pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
            write_opt(v, s)
        }

        /// Deserialise.
        pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
            Ok(Option::<Lenient>::deserialize(d)?.map(|e| e.0))
        }
    }
}
