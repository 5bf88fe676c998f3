//! The operator plumbing of the ring types, written once: [`ring_ops!`](crate::ring_ops).
//!
//! A scalar type of the workspace implements `+ - *` (and `/` for fields) for every combination
//! of owned and borrowed operands, plus the assign forms `+= -= *= /=` with an owned or a
//! borrowed right operand: twelve impls per operator, which every type used to write out by hand
//! in its own macro. `ring_ops!` generates them from **one by-reference implementation** per
//! operator, `fn(&T, &T) -> T`, so no operand is ever cloned to reach it:
//!
//! * `&a op &b` and `&a op b` call the by-reference body;
//! * `a op &b` calls the optional `owned` body (`fn(T, &T) -> T`, for types that can reuse the
//!   left operand's storage, e.g. a polynomial's term vectors), else the by-reference body on
//!   `&a`;
//! * `a op b` calls the optional `by_value` body (`fn(T, T) -> T`, for types that can move the
//!   right operand's parts into the result), else `a op &b`;
//! * `a op= b` and `a op= &b` become `a = take(a) op b` (resp. `op &b`), so they take the same
//!   paths; the type must implement `Default` (a cheap zero).
//!
//! Negation (the first line, required) takes a by-reference body and an optional owned one in the
//! same way.
//!
//! ```
//! use exactcheck_core::ring_ops;
//!
//! #[derive(Clone, Debug, Default, PartialEq)]
//! struct Z(i64);
//!
//! ring_ops! {
//!     impl[] Z;
//!     Neg::neg: |a| Z(-a.0);
//!     Add::add, AddAssign::add_assign: |a, b| Z(a.0 + b.0);
//!     Mul::mul, MulAssign::mul_assign: |a, b| Z(a.0 * b.0), owned |a, b| Z(a.0 * b.0);
//! }
//!
//! let mut x = Z(2) + &Z(3);
//! x *= Z(4);
//! assert_eq!(-&x, Z(-20));
//! ```
//!
//! Generic types name their parameters in the brackets: `impl[C: Ring] Poly<C>;`. The macro is
//! hand-written rather than derived because the choice between the by-reference, owned and
//! by-value bodies is per type and per operator, which no derive crate in the dependency set
//! expresses.

/// Implements the arithmetic operators of a ring type from one by-reference body per operator;
/// see the [module documentation](crate::ops).
#[macro_export]
macro_rules! ring_ops {
    (
        impl $g:tt $t:ty;
        Neg::neg : |$na:ident| $neg:expr $(, owned |$noa:ident| $neg_owned:expr)? ;
        $( $tr:ident :: $m:ident, $atr:ident :: $am:ident :
            |$a:ident, $b:ident| $by_ref:expr
            $(, owned |$oa:ident, $ob:ident| $owned:expr)?
            $(, by_value |$va:ident, $vb:ident| $by_value:expr)? ; )*
    ) => {
        $crate::ring_ops!(@neg $g $t, |$na| $neg, $(|$noa| $neg_owned)?);
        $(
            $crate::ring_ops!(@ref $g $t, $tr, $m, |$a, $b| $by_ref);
            $crate::ring_ops!(@owned $g $t, $tr, $m, $(|$oa, $ob| $owned)?);
            $crate::ring_ops!(@by_value $g $t, $tr, $m, $(|$va, $vb| $by_value)?);
            $crate::ring_ops!(@assign $g $t, $tr, $m, $atr, $am);
        )*
    };

    (@ref [$($g:tt)*] $t:ty, $tr:ident, $m:ident, |$a:ident, $b:ident| $body:expr) => {
        impl<$($g)*> ::core::ops::$tr<&$t> for &$t {
            type Output = $t;
            #[inline]
            fn $m(self, rhs: &$t) -> $t {
                let ($a, $b) = (self, rhs);
                $body
            }
        }
        impl<$($g)*> ::core::ops::$tr<$t> for &$t {
            type Output = $t;
            #[inline]
            fn $m(self, rhs: $t) -> $t {
                ::core::ops::$tr::$m(self, &rhs)
            }
        }
    };

    (@owned [$($g:tt)*] $t:ty, $tr:ident, $m:ident, ) => {
        impl<$($g)*> ::core::ops::$tr<&$t> for $t {
            type Output = $t;
            #[inline]
            fn $m(self, rhs: &$t) -> $t {
                ::core::ops::$tr::$m(&self, rhs)
            }
        }
    };
    (@owned [$($g:tt)*] $t:ty, $tr:ident, $m:ident, |$a:ident, $b:ident| $body:expr) => {
        impl<$($g)*> ::core::ops::$tr<&$t> for $t {
            type Output = $t;
            #[inline]
            fn $m(self, rhs: &$t) -> $t {
                let ($a, $b) = (self, rhs);
                $body
            }
        }
    };

    (@by_value [$($g:tt)*] $t:ty, $tr:ident, $m:ident, ) => {
        impl<$($g)*> ::core::ops::$tr<$t> for $t {
            type Output = $t;
            #[inline]
            fn $m(self, rhs: $t) -> $t {
                ::core::ops::$tr::$m(self, &rhs)
            }
        }
    };
    (@by_value [$($g:tt)*] $t:ty, $tr:ident, $m:ident, |$a:ident, $b:ident| $body:expr) => {
        impl<$($g)*> ::core::ops::$tr<$t> for $t {
            type Output = $t;
            #[inline]
            fn $m(self, rhs: $t) -> $t {
                let ($a, $b) = (self, rhs);
                $body
            }
        }
    };

    (@assign [$($g:tt)*] $t:ty, $tr:ident, $m:ident, $atr:ident, $am:ident) => {
        impl<$($g)*> ::core::ops::$atr<&$t> for $t {
            #[inline]
            fn $am(&mut self, rhs: &$t) {
                *self = ::core::ops::$tr::$m(::core::mem::take(self), rhs);
            }
        }
        impl<$($g)*> ::core::ops::$atr<$t> for $t {
            #[inline]
            fn $am(&mut self, rhs: $t) {
                *self = ::core::ops::$tr::$m(::core::mem::take(self), rhs);
            }
        }
    };

    (@neg [$($g:tt)*] $t:ty, |$a:ident| $body:expr, $(|$oa:ident| $owned:expr)?) => {
        impl<$($g)*> ::core::ops::Neg for &$t {
            type Output = $t;
            #[inline]
            fn neg(self) -> $t {
                let $a = self;
                $body
            }
        }
        impl<$($g)*> ::core::ops::Neg for $t {
            type Output = $t;
            #[inline]
            fn neg(self) -> $t {
                $crate::ring_ops!(@neg_owned self, $(|$oa| $owned)?)
            }
        }
    };
    (@neg_owned $s:ident, ) => {
        ::core::ops::Neg::neg(&$s)
    };
    (@neg_owned $s:ident, |$a:ident| $body:expr) => {{
        let $a = $s;
        $body
    }};
}

#[cfg(test)]
mod tests {
    use std::cell::RefCell;

    thread_local! {
        /// The bodies called, in order.
        static CALLS: RefCell<Vec<&'static str>> = const { RefCell::new(Vec::new()) };
    }

    fn log(s: &'static str) {
        CALLS.with(|c| c.borrow_mut().push(s));
    }

    fn calls() -> Vec<&'static str> {
        CALLS.with(|c| std::mem::take(&mut *c.borrow_mut()))
    }

    /// A type that records which body each operator form reached.
    #[derive(Clone, Debug, Default, PartialEq)]
    struct T(i64);

    ring_ops! {
        impl[] T;
        Neg::neg: |a| { log("neg ref"); T(-a.0) }, owned |a| { log("neg owned"); T(-a.0) };
        Add::add, AddAssign::add_assign: |a, b| { log("add ref"); T(a.0 + b.0) };
        Sub::sub, SubAssign::sub_assign: |a, b| { log("sub ref"); T(a.0 - b.0) },
            owned |a, b| { log("sub owned"); T(a.0 - b.0) },
            by_value |a, b| { log("sub by value"); T(a.0 - b.0) };
    }

    #[test]
    fn every_form_reaches_the_body_it_names() {
        let (x, y) = (T(7), T(3));
        assert_eq!(&x + &y, T(10));
        assert_eq!(&x + y.clone(), T(10));
        assert_eq!(x.clone() + &y, T(10));
        assert_eq!(x.clone() + y.clone(), T(10));
        assert_eq!(calls(), ["add ref"; 4]);
        let mut s = x.clone();
        s += &y;
        s += y.clone();
        assert_eq!(s, T(13));
        assert_eq!(calls(), ["add ref"; 2]);

        assert_eq!(&x - &y, T(4));
        assert_eq!(&x - y.clone(), T(4));
        assert_eq!(x.clone() - &y, T(4));
        assert_eq!(x.clone() - y.clone(), T(4));
        assert_eq!(calls(), ["sub ref", "sub ref", "sub owned", "sub by value"]);
        let mut d = x.clone();
        d -= &y;
        d -= y.clone();
        assert_eq!(d, T(1));
        assert_eq!(calls(), ["sub owned", "sub by value"]);

        assert_eq!(-&x, T(-7));
        assert_eq!(-x, T(-7));
        assert_eq!(calls(), ["neg ref", "neg owned"]);
    }
}
