//! JSON forms of the report's measures: JSON has no infinity or NaN, so a non-finite double is
//! written as the string `"inf"`, `"-inf"` or `"nan"` and read back from it (finite doubles are
//! numbers, written in the shortest form that reads back to the same double).

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A double or its non-finite spelling. (Read through `serde_json::Value`, not an untagged
/// enum: with serde_json's `arbitrary_precision` numbers do not deserialise inside untagged
/// enums.)
#[derive(Serialize)]
#[serde(untagged)]
enum Measure {
    Number(f64),
    Text(String),
}

impl<'de> Deserialize<'de> for Measure {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match serde_json::Value::deserialize(d)? {
            serde_json::Value::Number(n) => n
                .as_f64()
                .map(Measure::Number)
                .ok_or_else(|| D::Error::custom(format!("{n} is not a double"))),
            serde_json::Value::String(t) => Ok(Measure::Text(t)),
            other => Err(D::Error::custom(format!("{other} is not a number"))),
        }
    }
}

fn to_measure(v: f64) -> Measure {
    if v.is_finite() {
        Measure::Number(v)
    } else if v.is_nan() {
        Measure::Text("nan".into())
    } else if v > 0.0 {
        Measure::Text("inf".into())
    } else {
        Measure::Text("-inf".into())
    }
}

fn from_measure<E: serde::de::Error>(m: Measure) -> Result<f64, E> {
    match m {
        Measure::Number(v) => Ok(v),
        Measure::Text(t) => match t.as_str() {
            "inf" => Ok(f64::INFINITY),
            "-inf" => Ok(f64::NEG_INFINITY),
            "nan" => Ok(f64::NAN),
            _ => Err(E::custom(format!(
                "'{t}' is not a number, \"inf\", \"-inf\" or \"nan\""
            ))),
        },
    }
}

/// One double.
pub mod measure {
    use super::*;
    /// Serialises one double.
    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        to_measure(*v).serialize(s)
    }
    /// Reads one double.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        from_measure(Measure::deserialize(d)?)
    }
}

/// A list of doubles.
pub mod measures {
    use super::*;
    /// Serialises a list of doubles.
    pub fn serialize<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
        v.iter()
            .map(|&x| to_measure(x))
            .collect::<Vec<_>>()
            .serialize(s)
    }
    /// Reads a list of doubles.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
        Vec::<Measure>::deserialize(d)?
            .into_iter()
            .map(from_measure)
            .collect()
    }
}

/// An optional list of doubles (`null` for none).
pub mod opt_measures {
    use super::*;
    /// Serialises an optional list of doubles.
    pub fn serialize<S: Serializer>(v: &Option<Vec<f64>>, s: S) -> Result<S::Ok, S::Error> {
        v.as_ref()
            .map(|v| v.iter().map(|&x| to_measure(x)).collect::<Vec<_>>())
            .serialize(s)
    }
    /// Reads an optional list of doubles.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Vec<f64>>, D::Error> {
        Option::<Vec<Measure>>::deserialize(d)?
            .map(|v| v.into_iter().map(from_measure).collect())
            .transpose()
    }
}

/// The serialised form of a [`crate::summary::Distribution`].
#[derive(Serialize, Deserialize)]
struct DistributionJson {
    collapsed: bool,
    /// `[value, count]` pairs, ascending.
    entries: Vec<(Measure, u64)>,
}

impl Serialize for crate::summary::Distribution {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        DistributionJson {
            collapsed: self.is_collapsed(),
            entries: self
                .entries()
                .into_iter()
                .map(|(v, n)| (to_measure(v), n))
                .collect(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for crate::summary::Distribution {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let j = DistributionJson::deserialize(d)?;
        let entries = j
            .entries
            .into_iter()
            .map(|(m, n)| Ok((from_measure(m)?, n)))
            .collect::<Result<Vec<_>, D::Error>>()?;
        crate::summary::Distribution::from_entries(j.collapsed, &entries).map_err(D::Error::custom)
    }
}

/// The serialised form of a [`crate::summary::BitsSum`] (the `u128` as a decimal string: JSON
/// readers lose integers beyond 2^53).
#[derive(Serialize, Deserialize)]
struct BitsSumJson {
    units_2_40: String,
    count: u64,
}

impl Serialize for crate::summary::BitsSum {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        BitsSumJson {
            units_2_40: self.units.to_string(),
            count: self.count,
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for crate::summary::BitsSum {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let j = BitsSumJson::deserialize(d)?;
        let units = j
            .units_2_40
            .parse::<u128>()
            .map_err(|_| D::Error::custom(format!("'{}' is not a bits sum", j.units_2_40)))?;
        Ok(crate::summary::BitsSum {
            units,
            count: j.count,
        })
    }
}

#[cfg(test)]
mod tests {
    #[derive(serde::Serialize, serde::Deserialize, PartialEq, Debug)]
    struct T {
        #[serde(with = "super::measure")]
        a: f64,
        #[serde(with = "super::measures")]
        b: Vec<f64>,
        #[serde(with = "super::opt_measures")]
        c: Option<Vec<f64>>,
    }

    #[test]
    fn non_finite_measures_round_trip_as_valid_json() {
        let t = T {
            a: f64::INFINITY,
            b: vec![1e-300, f64::NEG_INFINITY, 0.1],
            c: None,
        };
        let s = serde_json::to_string(&t).unwrap();
        assert_eq!(s, r#"{"a":"inf","b":[1e-300,"-inf",0.1],"c":null}"#);
        assert_eq!(serde_json::from_str::<T>(&s).unwrap(), t);
        assert!(serde_json::from_str::<T>(r#"{"a":"big","b":[],"c":null}"#).is_err());
    }
}
