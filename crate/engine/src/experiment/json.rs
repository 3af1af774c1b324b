//! How the JSON formats (run files, the page's jobs) write the numbers JSON cannot hold
//! plainly: a fitness that is not finite as `null`, a genome with a `null` gene refused with
//! the gene named, a 64-bit seed as a decimal string (a JS number holds integers exactly only
//! up to 2^53).

use serde::{Deserialize, Deserializer};

/// Reads a genome, naming the first gene that is `null` (how JSON writes NaN).
pub(crate) fn finite_genes<'de, D: Deserializer<'de>>(
    d: D,
) -> std::result::Result<Vec<f32>, D::Error> {
    let genes: Vec<Option<f32>> = Vec::deserialize(d)?;
    match genes.iter().position(Option::is_none) {
        Some(i) => Err(serde::de::Error::custom(format!(
            "gene {i} is null, genes must be finite numbers"
        ))),
        None => Ok(genes.into_iter().flatten().collect()),
    }
}

/// Serde for fitness values: non-finite written as `null`, `null` read as -infinity (the
/// GA's value for an exploded evaluation).
pub(crate) mod finite_or_null {
    use serde::{Deserialize, Deserializer, Serializer};

    /// Writes a finite value as a number, anything else as null.
    pub(crate) fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        if v.is_finite() {
            s.serialize_f64(*v)
        } else {
            s.serialize_none()
        }
    }

    /// Reads a number, or null as -infinity.
    pub(crate) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NEG_INFINITY))
    }
}

/// A `u64` as a decimal string (a JS number holds integers exactly only up to 2^53).
pub(crate) mod decimal {
    use serde::{de::Error, Deserialize, Deserializer, Serializer};

    /// Writes the value as a decimal string.
    pub(crate) fn serialize<S: Serializer>(value: &u64, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&value.to_string())
    }

    /// Reads a decimal string.
    pub(crate) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<u64, D::Error> {
        let text = String::deserialize(d)?;
        text.trim().parse().map_err(|_| {
            D::Error::custom(format!(
                "noise seed {text:?} is not an unsigned 64-bit integer"
            ))
        })
    }
}
