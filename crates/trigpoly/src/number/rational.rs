//! `Rational`: exact rational numbers Q, the coefficient field of real polynomials.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::str::FromStr;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::Integer;

/// An exact rational number in lowest terms with a positive denominator.
///
/// ```
/// use trigpoly::Rational;
/// let a: Rational = "3/4".parse().unwrap();
/// let b = Rational::new(1, 4);
/// assert_eq!((a + b).to_string(), "1");
/// assert_eq!(Rational::new(-6, 8).to_string(), "-3/4");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Rational(BigRational);

impl Rational {
    /// `num/den`, reduced. Panics if `den == 0`.
    pub fn new(num: i64, den: i64) -> Rational {
        Rational(BigRational::new(BigInt::from(num), BigInt::from(den)))
    }

    /// `num/den` from integers, reduced; `None` if `den` is zero.
    pub fn from_fraction(num: &Integer, den: &Integer) -> Option<Rational> {
        if den.is_zero() {
            return None;
        }
        Some(Rational(BigRational::new(num.to_bigint(), den.to_bigint())))
    }

    /// Zero.
    pub fn zero() -> Rational {
        Rational(BigRational::zero())
    }

    /// One.
    pub fn one() -> Rational {
        Rational(BigRational::one())
    }

    /// Whether the value is zero.
    pub fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    /// Whether the value is one.
    pub fn is_one(&self) -> bool {
        self.0.is_one()
    }

    /// Whether the value is negative.
    pub fn is_negative(&self) -> bool {
        self.0.is_negative()
    }

    /// Whether the value is an integer.
    pub fn is_integer(&self) -> bool {
        self.0.is_integer()
    }

    /// The numerator (carries the sign).
    pub fn numer(&self) -> Integer {
        Integer::from_bigint(self.0.numer().clone())
    }

    /// The denominator (positive).
    pub fn denom(&self) -> Integer {
        Integer::from_bigint(self.0.denom().clone())
    }

    /// The inverse, or `None` for zero.
    pub fn try_inv(&self) -> Option<Rational> {
        if self.is_zero() {
            None
        } else {
            Some(Rational(self.0.recip()))
        }
    }

    /// Absolute value.
    pub fn abs(&self) -> Rational {
        Rational(self.0.abs())
    }

    /// `self^e` for any integer `e`; `None` for `0^e` with `e < 0`.
    pub fn pow(&self, e: i64) -> Option<Rational> {
        if e < 0 && self.is_zero() {
            return None;
        }
        let base = if e < 0 {
            self.0.recip()
        } else {
            self.0.clone()
        };
        Some(Rational(num_traits::pow(base, e.unsigned_abs() as usize)))
    }

    /// `gcd(a, b)` in the sense of contents: `gcd(numerators)/lcm(denominators)`, positive, so
    /// that `a/g` and `b/g` are coprime integers. `gcd(0, b) = |b|`.
    pub fn content_gcd(a: &Rational, b: &Rational) -> Rational {
        let num = a.numer().gcd(&b.numer());
        let den = a.denom().lcm(&b.denom());
        Rational::from_fraction(&num, &den).expect("lcm of denominators is nonzero")
    }

    /// The underlying `num_rational` value.
    pub fn as_big_rational(&self) -> &BigRational {
        &self.0
    }
}

impl From<BigRational> for Rational {
    fn from(v: BigRational) -> Self {
        Rational(v)
    }
}

impl From<Integer> for Rational {
    fn from(v: Integer) -> Self {
        Rational(BigRational::from_integer(v.to_bigint()))
    }
}

impl From<&Integer> for Rational {
    fn from(v: &Integer) -> Self {
        Rational(BigRational::from_integer(v.to_bigint()))
    }
}

impl From<i64> for Rational {
    fn from(v: i64) -> Self {
        Rational(BigRational::from_integer(BigInt::from(v)))
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_integer() {
            write!(f, "{}", self.0.numer())
        } else {
            write!(f, "{}/{}", self.0.numer(), self.0.denom())
        }
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// Why a rational number did not parse.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("not an exact rational number: {0:?} (expected an integer or a fraction like -3/4)")]
pub struct ParseRationalError(pub String);

impl FromStr for Rational {
    type Err = ParseRationalError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = || ParseRationalError(s.to_string());
        let t = s.trim();
        let (n, d) = match t.split_once('/') {
            Some((n, d)) => (n.trim(), d.trim()),
            None => (t, "1"),
        };
        let n: BigInt = n.parse().map_err(|_| err())?;
        let d: BigInt = d.parse().map_err(|_| err())?;
        if d.is_zero() {
            return Err(err());
        }
        Ok(Rational(BigRational::new(n, d)))
    }
}

macro_rules! forward_binop {
    ($Ty:ident, $Trait:ident, $method:ident, $Assign:ident, $assign:ident, |$a:ident, $b:ident| $body:expr) => {
        impl $Trait<&$Ty> for &$Ty {
            type Output = $Ty;
            fn $method(self, rhs: &$Ty) -> $Ty {
                let ($a, $b) = (self, rhs);
                $body
            }
        }
        impl $Trait<$Ty> for &$Ty {
            type Output = $Ty;
            fn $method(self, rhs: $Ty) -> $Ty {
                self.$method(&rhs)
            }
        }
        impl $Trait<&$Ty> for $Ty {
            type Output = $Ty;
            fn $method(self, rhs: &$Ty) -> $Ty {
                (&self).$method(rhs)
            }
        }
        impl $Trait<$Ty> for $Ty {
            type Output = $Ty;
            fn $method(self, rhs: $Ty) -> $Ty {
                (&self).$method(&rhs)
            }
        }
        impl $Assign<&$Ty> for $Ty {
            fn $assign(&mut self, rhs: &$Ty) {
                *self = (&*self).$method(rhs);
            }
        }
        impl $Assign<$Ty> for $Ty {
            fn $assign(&mut self, rhs: $Ty) {
                *self = (&*self).$method(&rhs);
            }
        }
    };
}
pub(crate) use forward_binop;

forward_binop!(Rational, Add, add, AddAssign, add_assign, |a, b| Rational(
    &a.0 + &b.0
));
forward_binop!(Rational, Sub, sub, SubAssign, sub_assign, |a, b| Rational(
    &a.0 - &b.0
));
forward_binop!(Rational, Mul, mul, MulAssign, mul_assign, |a, b| Rational(
    &a.0 * &b.0
));
// Panics if the divisor is zero (use `try_inv` for a checked division).
forward_binop!(Rational, Div, div, DivAssign, div_assign, |a, b| Rational(
    &a.0 / &b.0
));

impl Neg for &Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational(-&self.0)
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational(-self.0)
    }
}

impl Rational {
    /// Compares with zero.
    pub fn sign(&self) -> Ordering {
        self.0.cmp(&BigRational::zero())
    }
}
