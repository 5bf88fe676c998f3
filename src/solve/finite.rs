//! The guard on the numbers of an answer: every `f64` in it must be finite.
//!
//! JSON has no NaN or infinity: `serde_json` writes them as `null`, which would put a silent
//! `null` where the contract promises a number (and other writers emit the invalid tokens `NaN`
//! and `Infinity`). Answers are serialized in one place (`solve::to_json`), which first walks
//! the answer with the serializer of this module: it produces nothing, tracks the field path
//! (`coefficients.A[0]`, `samples[3].points[1][2]`) and fails at the first non-finite `f64`
//! with one line naming the field and what went wrong, so `solve` answers with an error
//! (exit 2) instead of a confident answer holding `null`.
//!
//! One exception, when the caller allows it ([`Approx::Listed`], exact answers): an infinite
//! number under a field named `approx` or `*_approx` (`point_approx`) is the f64 twin of an
//! exact value beyond f64's range (`"-10^400"`). The exact value is the answer, so it is not
//! refused: the infinity is collected (its path returned by [`check`]), written as `null`, and
//! the answer lists every such path in `approx_out_of_range`, so the `null` is not silent. A NaN
//! is never accepted (the twins are converted by `Radical::to_f64`/`Rational::to_f64`, which
//! give `±inf` beyond f64's range, never NaN).

//! Hand-written: serde has no "visit every float" hook, and `serde_json`'s own serializers
//! turn non-finite numbers into `null` without an error.

use serde::ser::{self, Serialize};
use std::cell::RefCell;
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

/// What [`check`] does with an infinite number under a field named `approx`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Approx {
    /// Refuse it, like any other non-finite number (float answers: there the `approx` numbers
    /// are the computation's own).
    Refused,
    /// Accept it and return its path (exact answers: the twin of an exact value beyond f64's
    /// range). Paths under a top-level `float` field (the float part of `--both`) are still
    /// refused.
    Listed,
}

/// Checks that every `f64`/`f32` in `value` is finite, except (with [`Approx::Listed`]) the
/// infinite approximations of exact values, whose paths it returns in order.
///
/// # Errors
/// [`NonFinite`]: `PATH: the f64 computation overflowed (inf); use exact mode` (or `produced
/// NaN`; for a field under `approx` with [`Approx::Refused`], the approximation of an exact
/// value out of f64's range).
pub fn check<T: Serialize + ?Sized>(value: &T, approx: Approx) -> Result<Vec<String>, NonFinite> {
    let listed = RefCell::new(Vec::new());
    value.serialize(Checker {
        path: String::new(),
        approx,
        listed: &listed,
    })?;
    Ok(listed.into_inner())
}

/// Whether a path segment is a field of f64 twins: `approx`, `approx[2]`, or a name ending in
/// `_approx` (`point_approx`, `base_approx[0]`).
fn is_twin_field(segment: &str) -> bool {
    let name = segment.split('[').next().unwrap_or(segment);
    name == "approx" || name.ends_with("_approx")
}

fn join(prefix: &str, name: &str) -> String {
    if prefix.is_empty() {
        name.to_string()
    } else {
        format!("{prefix}.{name}")
    }
}

/// The serializer: the path of the value it is given, the rule for `approx` infinities and
/// the list of those accepted.
struct Checker<'a> {
    path: String,
    approx: Approx,
    listed: &'a RefCell<Vec<String>>,
}

impl<'a> Checker<'a> {
    /// The checker of a value at `path`, with this one's rule and list.
    fn at(&self, path: String) -> Checker<'a> {
        Checker {
            path,
            approx: self.approx,
            listed: self.listed,
        }
    }

    fn float(self, v: f64) -> Result<(), NonFinite> {
        if v.is_finite() {
            return Ok(());
        }
        let under_approx = self.path.split('.').any(is_twin_field);
        if v.is_infinite()
            && under_approx
            && self.approx == Approx::Listed
            && self.path.split(['.', '[']).next() != Some("float")
        {
            self.listed.borrow_mut().push(self.path);
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
        Err(NonFinite(if under_approx {
            format!("{path}: the f64 approximation of an exact value is not finite ({what})")
        } else if v.is_nan() {
            format!("{path}: the f64 computation produced NaN; use exact mode")
        } else {
            format!("{path}: the f64 computation overflowed ({what}); use exact mode")
        }))
    }
}

/// The elements of a sequence, map or struct under the path of `parent`.
struct Compound<'a> {
    parent: Checker<'a>,
    index: usize,
    key: Option<String>,
}

impl<'a> Compound<'a> {
    fn new(parent: Checker<'a>) -> Compound<'a> {
        Compound {
            parent,
            index: 0,
            key: None,
        }
    }

    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        let path = format!("{}[{}]", self.parent.path, self.index);
        self.index += 1;
        value.serialize(self.parent.at(path))
    }

    fn field<T: Serialize + ?Sized>(&mut self, name: &str, value: &T) -> Result<(), NonFinite> {
        value.serialize(self.parent.at(join(&self.parent.path, name)))
    }
}

impl<'a> ser::Serializer for Checker<'a> {
    type Ok = ();
    type Error = NonFinite;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

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
        let path = join(&self.path, variant);
        value.serialize(self.at(path))
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, NonFinite> {
        Ok(Compound::new(self))
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, NonFinite> {
        Ok(Compound::new(self))
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, NonFinite> {
        Ok(Compound::new(self))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, NonFinite> {
        let path = join(&self.path, variant);
        Ok(Compound::new(self.at(path)))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, NonFinite> {
        Ok(Compound::new(self))
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, NonFinite> {
        Ok(Compound::new(self))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, NonFinite> {
        let path = join(&self.path, variant);
        Ok(Compound::new(self.at(path)))
    }
}

impl ser::SerializeSeq for Compound<'_> {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeTuple for Compound<'_> {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeTupleStruct for Compound<'_> {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeTupleVariant for Compound<'_> {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        self.element(value)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

impl ser::SerializeMap for Compound<'_> {
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

impl ser::SerializeStruct for Compound<'_> {
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

impl ser::SerializeStructVariant for Compound<'_> {
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
        assert_eq!(check(&x, Approx::Refused).unwrap(), Vec::<String>::new());
        x.coefficients.a[1] = f64::INFINITY;
        assert_eq!(
            check(&x, Approx::Refused).unwrap_err().to_string(),
            "coefficients.a[1]: the f64 computation overflowed (inf); use exact mode"
        );
        x.coefficients.a[1] = 0.0;
        x.maybe = Some(f64::NAN);
        assert_eq!(
            check(&x, Approx::Refused).unwrap_err().to_string(),
            "maybe: the f64 computation produced NaN; use exact mode"
        );
        x.maybe = None;
        x.approx[0][1] = f64::NEG_INFINITY;
        assert_eq!(
            check(&x, Approx::Refused).unwrap_err().to_string(),
            "approx[0][1]: the f64 approximation of an exact value is not finite (-inf)"
        );
    }

    #[test]
    fn exact_answers_list_infinite_approximations_and_refuse_the_rest() {
        let mut x = Answer {
            name: "x",
            coefficients: Inner { a: vec![1.0] },
            maybe: None,
            approx: vec![[1.0, f64::NEG_INFINITY], [f64::INFINITY, 0.0]],
        };
        assert_eq!(
            check(&x, Approx::Listed).unwrap(),
            vec!["approx[0][1]".to_string(), "approx[1][0]".to_string()]
        );
        // Refused where the numbers are the f64 computation's own.
        assert_eq!(
            check(&x, Approx::Refused).unwrap_err().to_string(),
            "approx[0][1]: the f64 approximation of an exact value is not finite (-inf)"
        );
        // A NaN is never an approximation of an exact value.
        x.approx[1][1] = f64::NAN;
        assert_eq!(
            check(&x, Approx::Listed).unwrap_err().to_string(),
            "approx[1][1]: the f64 approximation of an exact value is not finite (NaN)"
        );
        // Nor is an infinity outside `approx`.
        x.approx[1][1] = 0.0;
        x.coefficients.a[0] = f64::INFINITY;
        assert_eq!(
            check(&x, Approx::Listed).unwrap_err().to_string(),
            "coefficients.a[0]: the f64 computation overflowed (inf); use exact mode"
        );
    }

    #[test]
    fn the_float_part_of_both_is_refused() {
        #[derive(Serialize)]
        struct Both {
            approx: f64,
            float: Answer,
        }
        let both = Both {
            approx: f64::INFINITY,
            float: Answer {
                name: "f",
                coefficients: Inner { a: vec![] },
                maybe: None,
                approx: vec![[f64::INFINITY, 0.0]],
            },
        };
        assert_eq!(
            check(&both, Approx::Listed).unwrap_err().to_string(),
            "float.approx[0][0]: the f64 approximation of an exact value is not finite (inf)"
        );
    }
}
