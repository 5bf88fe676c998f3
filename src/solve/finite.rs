//! The guard on the numbers of an answer: every `f64` in it must be finite.
//!
//! JSON has no NaN or infinity: `serde_json` writes them as `null`, which would put a silent
//! `null` where the contract promises a number (and other writers emit the invalid tokens `NaN`
//! and `Infinity`). Answers are serialized in one place ([`super::to_json`]), which first walks
//! the answer with the serializer of this module: it produces nothing, tracks the field path
//! (`coefficients.A[0]`, `samples[3].points[1][2]`) and fails at the first non-finite `f64`
//! with one line naming the field and what went wrong, so `solve` answers with an error
//! (exit 2) instead of a confident answer holding `null`.
//!
//! Hand-written: serde has no "visit every float" hook, and `serde_json`'s own serializers
//! turn non-finite numbers into `null` without an error.

use serde::ser::{self, Serialize};
use std::fmt;

/// A non-finite number at a path, as one line.
#[derive(Debug)]
pub struct NonFinite(pub String);

impl fmt::Display for NonFinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NonFinite {}

impl ser::Error for NonFinite {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        NonFinite(msg.to_string())
    }
}

/// Checks that every `f64`/`f32` in `value` is finite.
///
/// # Errors
/// [`NonFinite`]: `PATH: the f64 computation overflowed (inf); use exact mode` (or `produced
/// NaN`; for a field under `approx`, the approximation of an exact value out of f64's range).
pub fn check<T: Serialize + ?Sized>(value: &T) -> Result<(), NonFinite> {
    value.serialize(Checker {
        path: String::new(),
    })
}

fn join(prefix: &str, name: &str) -> String {
    if prefix.is_empty() {
        name.to_string()
    } else {
        format!("{prefix}.{name}")
    }
}

/// The serializer: the path of the value it is given.
struct Checker {
    path: String,
}

impl Checker {
    fn float(self, v: f64) -> Result<(), NonFinite> {
        if v.is_finite() {
            return Ok(());
        }
        let path = if self.path.is_empty() {
            "the answer"
        } else {
            &self.path
        };
        let what = if v.is_nan() {
            "NaN".to_string()
        } else {
            format!("{}inf", if v < 0.0 { "-" } else { "" })
        };
        Err(NonFinite(
            if self.path.split('.').any(|s| s.starts_with("approx")) {
                format!("{path}: the f64 approximation of an exact value is not finite ({what})")
            } else if v.is_nan() {
                format!("{path}: the f64 computation produced NaN; use exact mode")
            } else {
                format!("{path}: the f64 computation overflowed ({what}); use exact mode")
            },
        ))
    }
}

/// The elements of a sequence, map or struct under `prefix`.
struct Compound {
    prefix: String,
    index: usize,
    key: Option<String>,
}

impl Compound {
    fn new(prefix: String) -> Compound {
        Compound {
            prefix,
            index: 0,
            key: None,
        }
    }

    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        let path = format!("{}[{}]", self.prefix, self.index);
        self.index += 1;
        value.serialize(Checker { path })
    }

    fn field<T: Serialize + ?Sized>(&mut self, name: &str, value: &T) -> Result<(), NonFinite> {
        value.serialize(Checker {
            path: join(&self.prefix, name),
        })
    }
}

impl ser::Serializer for Checker {
    type Ok = ();
    type Error = NonFinite;
    type SerializeSeq = Compound;
    type SerializeTuple = Compound;
    type SerializeTupleStruct = Compound;
    type SerializeTupleVariant = Compound;
    type SerializeMap = Compound;
    type SerializeStruct = Compound;
    type SerializeStructVariant = Compound;

    fn serialize_bool(self, _: bool) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_i8(self, _: i8) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_i16(self, _: i16) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_i32(self, _: i32) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_i64(self, _: i64) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_i128(self, _: i128) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_u8(self, _: u8) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_u16(self, _: u16) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_u32(self, _: u32) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_u64(self, _: u64) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_u128(self, _: u128) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_f32(self, v: f32) -> Result<(), NonFinite> {
        self.float(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), NonFinite> {
        self.float(v)
    }
    fn serialize_char(self, _: char) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_str(self, _: &str) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_bytes(self, _: &[u8]) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_none(self) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), NonFinite> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
    ) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), NonFinite> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), NonFinite> {
        value.serialize(Checker {
            path: join(&self.path, variant),
        })
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound, NonFinite> {
        Ok(Compound::new(self.path))
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound, NonFinite> {
        Ok(Compound::new(self.path))
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound, NonFinite> {
        Ok(Compound::new(self.path))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Compound, NonFinite> {
        Ok(Compound::new(join(&self.path, variant)))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound, NonFinite> {
        Ok(Compound::new(self.path))
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound, NonFinite> {
        Ok(Compound::new(self.path))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Compound, NonFinite> {
        Ok(Compound::new(join(&self.path, variant)))
    }
}

impl ser::SerializeSeq for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeTuple for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeTupleStruct for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeTupleVariant for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeMap for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), NonFinite> {
        // The key as the path shows it: a string key as written, anything else as JSON.
        self.key = Some(match serde_json::to_value(key) {
            Ok(serde_json::Value::String(s)) => s,
            Ok(other) => other.to_string(),
            Err(_) => "?".into(),
        });
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        let key = self.key.take().unwrap_or_else(|| "?".into());
        self.field(&key, value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeStruct for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        name: &'static str,
        value: &T,
    ) -> Result<(), NonFinite> {
        self.field(name, value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeStructVariant for Compound {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        name: &'static str,
        value: &T,
    ) -> Result<(), NonFinite> {
        self.field(name, value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Serialize;

    #[derive(Serialize)]
    struct Inner {
        a: Vec<f64>,
    }

    #[derive(Serialize)]
    struct Answer {
        name: &'static str,
        coefficients: Inner,
        maybe: Option<f64>,
        approx: Vec<[f64; 2]>,
    }

    #[test]
    fn names_the_first_non_finite_number() {
        let mut x = Answer {
            name: "x",
            coefficients: Inner {
                a: vec![1.0, 5e-324, -0.0],
            },
            maybe: None,
            approx: vec![[1.0, 2.0]],
        };
        assert!(check(&x).is_ok());
        x.coefficients.a[1] = f64::INFINITY;
        assert_eq!(
            check(&x).unwrap_err().to_string(),
            "coefficients.a[1]: the f64 computation overflowed (inf); use exact mode"
        );
        x.coefficients.a[1] = 0.0;
        x.maybe = Some(f64::NAN);
        assert_eq!(
            check(&x).unwrap_err().to_string(),
            "maybe: the f64 computation produced NaN; use exact mode"
        );
        x.maybe = None;
        x.approx[0][1] = f64::NEG_INFINITY;
        assert_eq!(
            check(&x).unwrap_err().to_string(),
            "approx[0][1]: the f64 approximation of an exact value is not finite (-inf)"
        );
    }
}
