//! Gaussian integers Z\[i\] and Gaussian rationals Q(i) = Q + iQ.

use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::str::FromStr;

use num_bigint::BigInt;
use num_rational::BigRational;

use super::rational::{fold_traits, forward_binop};
use super::{Integer, IntegerAcc, Rational};
use crate::syntax::{ParseError, Span};

/// A Gaussian integer `re + i·im`.
#[derive(PartialEq, Eq, Hash, Default)]
pub struct GaussianInteger {
    /// Real part.
    pub re: Integer,
    /// Imaginary part.
    pub im: Integer,
}

impl Clone for GaussianInteger {
    #[inline]
    fn clone(&self) -> Self {
        GaussianInteger {
            re: self.re.clone(),
            im: self.im.clone(),
        }
    }
}

impl GaussianInteger {
    /// `re + i·im`.
    pub fn new(re: Integer, im: Integer) -> Self {
        GaussianInteger { re, im }
    }

    /// Whether both parts are zero.
    pub fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }

    /// Complex conjugate.
    #[must_use]
    pub fn conj(&self) -> Self {
        GaussianInteger {
            re: self.re.clone(),
            im: -&self.im,
        }
    }

    /// `i · self`.
    #[must_use]
    pub fn mul_i(&self) -> Self {
        GaussianInteger {
            re: -&self.im,
            im: self.re.clone(),
        }
    }
}

impl From<Integer> for GaussianInteger {
    fn from(re: Integer) -> Self {
        GaussianInteger::new(re, Integer::ZERO)
    }
}

/// A big integer, real, in the one form of its value as [`Integer`] takes it.
///
/// ```
/// use trigpoly::num_bigint::BigInt;
/// use trigpoly::GaussianInteger;
///
/// assert_eq!(GaussianInteger::from(BigInt::from(-5)), GaussianInteger::from(-5));
/// let big = BigInt::from(3).pow(90);
/// assert_eq!(GaussianInteger::from(big.clone()).re.to_string(), big.to_string());
/// ```
impl From<BigInt> for GaussianInteger {
    fn from(re: BigInt) -> Self {
        GaussianInteger::from(Integer::from(re))
    }
}

/// `From` for primitive integers, each a real Gaussian integer as [`Integer`] makes it.
macro_rules! from_integers_to_gaussian {
    ($($(#[$doc:meta])* $t:ty),*) => {$(
        $(#[$doc])*
        impl From<$t> for GaussianInteger {
            fn from(v: $t) -> Self {
                GaussianInteger::from(Integer::from(v))
            }
        }
    )*};
}

from_integers_to_gaussian!(
    i8, i16, i32, i64, i128, isize, u8, u16, u32, u64, usize,
    /// An integer, real, of any primitive type as [`Integer`] takes it (an unsuffixed literal
    /// is an `i32`), in the one form of its value: equal values are equal and hash alike.
    ///
    /// ```
    /// use trigpoly::{GaussianInteger, Integer};
    ///
    /// let three = GaussianInteger::new(Integer::from(3), Integer::ZERO);
    /// assert_eq!(GaussianInteger::from(3), three);
    /// assert_eq!(GaussianInteger::from(3u8), GaussianInteger::from(Integer::from(3i128)));
    /// assert_eq!(GaussianInteger::from(u128::MAX).re.to_string(), u128::MAX.to_string());
    /// assert!(GaussianInteger::from(-7i64).im.is_zero());
    /// ```
    u128
);

impl fmt::Debug for GaussianInteger {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({} + {}i)", self.re, self.im)
    }
}

/// An accumulator for sums of products of Gaussian integers (two `IntegerAcc`s).
#[derive(Clone, Debug, Default)]
pub struct GaussianAcc {
    re: IntegerAcc,
    im: IntegerAcc,
}

impl GaussianAcc {
    /// `acc += a * b`, with `(a + bi)(c + di) = (ac − bd) + (ad + bc)i`.
    #[inline]
    pub fn add_mul(&mut self, a: &GaussianInteger, b: &GaussianInteger) {
        if a.im.is_zero() {
            self.re.add_mul(&a.re, &b.re);
            self.im.add_mul(&a.re, &b.im);
        } else if b.im.is_zero() {
            self.re.add_mul(&a.re, &b.re);
            self.im.add_mul(&a.im, &b.re);
        } else {
            self.re.add_mul(&a.re, &b.re);
            self.re.sub_mul(&a.im, &b.im);
            self.im.add_mul(&a.re, &b.im);
            self.im.add_mul(&a.im, &b.re);
        }
    }

    /// `acc += a`.
    #[inline]
    pub fn add(&mut self, a: &GaussianInteger) {
        self.re.add(&a.re);
        self.im.add(&a.im);
    }

    /// The accumulated value.
    #[must_use]
    pub fn finish(self) -> GaussianInteger {
        GaussianInteger {
            re: self.re.finish(),
            im: self.im.finish(),
        }
    }
}

/// A Gaussian rational `re + i·im` with `re, im ∈ Q`: an element of the field Q(i).
///
/// ```
/// use trigpoly::GaussianRational;
/// let z: GaussianRational = "3/5 + 4/5*i".parse().unwrap();
/// assert_eq!((&z * &z.conj()).to_string(), "1");
/// assert_eq!(z.try_inv().unwrap(), z.conj());
/// ```
///
/// # Panics
///
/// Division by zero with `/` or `/=` panics ("division by zero"); [`GaussianRational::try_inv`]
/// is the checked inverse, and [`GaussianRational::pow`] of zero to a negative power returns
/// `None`.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct GaussianRational {
    /// Real part.
    pub re: Rational,
    /// Imaginary part.
    pub im: Rational,
}

impl GaussianRational {
    /// `re + i·im`.
    pub fn new(re: Rational, im: Rational) -> Self {
        GaussianRational { re, im }
    }

    /// The imaginary unit.
    pub fn i() -> Self {
        GaussianRational {
            re: Rational::zero(),
            im: Rational::one(),
        }
    }

    /// Whether both parts are zero.
    pub fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }

    /// Whether the imaginary part is zero.
    pub fn is_real(&self) -> bool {
        self.im.is_zero()
    }

    /// Complex conjugate.
    #[must_use]
    pub fn conj(&self) -> Self {
        GaussianRational {
            re: self.re.clone(),
            im: -&self.im,
        }
    }

    /// `|z|² = re² + im²`.
    pub fn norm(&self) -> Rational {
        &self.re * &self.re + &self.im * &self.im
    }

    /// The inverse `z̄/|z|²`, or `None` for zero.
    pub fn try_inv(&self) -> Option<Self> {
        let n = self.norm().try_inv()?;
        Some(GaussianRational {
            re: &self.re * &n,
            im: -(&self.im * &n),
        })
    }

    /// `self^e` for any integer `e`; `None` for `0^e` with `e < 0`.
    ///
    /// By repeated squaring: about `2·log₂|e|` products, the last of them on parts of about
    /// `|e|` times the bits of `self`'s. The cost grows with the size of the result, not with
    /// the number of products: `(1 + i)^(2^40)` has parts of about 2^39 bits and does not end
    /// in any useful time. No square is taken past the exponent's top bit.
    pub fn pow(&self, e: i64) -> Option<Self> {
        let mut base = if e < 0 { self.try_inv()? } else { self.clone() };
        let mut k = e.unsigned_abs();
        let mut acc = GaussianRational::from(Rational::one());
        while k > 0 {
            if k & 1 == 1 {
                acc = &acc * &base;
            }
            k >>= 1;
            // The square after the top bit would be used by no product.
            if k > 0 {
                base = &base * &base;
            }
        }
        Some(acc)
    }
}

impl From<Rational> for GaussianRational {
    fn from(re: Rational) -> Self {
        GaussianRational {
            re,
            im: Rational::zero(),
        }
    }
}

/// A Gaussian integer, as the element of Q(i) it is (Z\[i\] lies in Q(i)): `a + bi` of
/// integers, each part a rational.
///
/// ```
/// use trigpoly::{GaussianInteger, GaussianRational, Integer, Rational};
///
/// let z = GaussianInteger::new(Integer::from(2), Integer::from(-3));
/// assert_eq!(
///     GaussianRational::from(z),
///     GaussianRational::new(Rational::from(2), Rational::from(-3))
/// );
/// ```
impl From<GaussianInteger> for GaussianRational {
    fn from(z: GaussianInteger) -> Self {
        GaussianRational::new(Rational::from(z.re), Rational::from(z.im))
    }
}

/// `From` for the other real numbers, each a real Gaussian rational as [`Rational`] makes it:
/// an [`Integer`], a `BigInt` and a `BigRational` (num-rational's), as num-complex's
/// `Complex` takes its real part.
macro_rules! from_reals {
    ($($(#[$doc:meta])* $t:ty),*) => {$(
        $(#[$doc])*
        impl From<$t> for GaussianRational {
            fn from(re: $t) -> Self {
                GaussianRational::from(Rational::from(re))
            }
        }
    )*};
}

from_reals!(
    Integer,
    BigInt,
    /// A rational of num-rational, exact, real.
    ///
    /// ```
    /// use trigpoly::num_bigint::BigInt;
    /// use trigpoly::num_rational::BigRational;
    /// use trigpoly::{GaussianRational, Integer, Rational};
    ///
    /// let half = BigRational::new(BigInt::from(1), BigInt::from(2));
    /// assert_eq!(GaussianRational::from(half), GaussianRational::from(Rational::new(1, 2)));
    /// assert_eq!(GaussianRational::from(BigInt::from(7)), GaussianRational::from(7));
    /// assert_eq!(GaussianRational::from(Integer::from(-4)).to_string(), "-4");
    /// assert!(GaussianRational::from(BigInt::from(10).pow(40)).is_real());
    /// ```
    BigRational
);

/// `From` for primitive integers, each a real Gaussian rational as [`Rational`] makes it.
macro_rules! from_integers {
    ($($(#[$doc:meta])* $t:ty),*) => {$(
        $(#[$doc])*
        impl From<$t> for GaussianRational {
            fn from(v: $t) -> Self {
                GaussianRational::from(Rational::from(v))
            }
        }
    )*};
}

from_integers!(
    i8, i16, i32, i64, i128, isize, u8, u16, u32, u64, usize,
    /// An integer, real, of any primitive type as [`Rational`] takes it (an unsuffixed literal
    /// is an `i32`).
    ///
    /// ```
    /// use trigpoly::{GaussianRational, Rational};
    ///
    /// assert_eq!(GaussianRational::from(3), GaussianRational::from(Rational::from(3)));
    /// assert_eq!(GaussianRational::from(3u8).to_string(), "3");
    /// assert_eq!(GaussianRational::from(u128::MAX).to_string(), u128::MAX.to_string());
    /// ```
    u128
);

impl fmt::Display for GaussianRational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.re.is_zero(), self.im.is_zero()) {
            (_, true) => write!(f, "{}", self.re),
            (true, false) => write_imag(f, &self.im),
            (false, false) => {
                write!(f, "{}", self.re)?;
                if self.im.is_negative() {
                    write!(f, " - ")?;
                    write_imag(f, &-&self.im)
                } else {
                    write!(f, " + ")?;
                    write_imag(f, &self.im)
                }
            }
        }
    }
}

fn write_imag(f: &mut fmt::Formatter<'_>, im: &Rational) -> fmt::Result {
    if im.is_one() {
        write!(f, "i")
    } else if (-im).is_one() {
        write!(f, "-i")
    } else {
        write!(f, "{im}*i")
    }
}

impl fmt::Debug for GaussianRational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// Why a Gaussian rational did not parse: the text, and the expression syntax's error in it,
/// with its place ([`ParseGaussianError::reason`], which this error's `Display` says, and so
/// is not also its [`source`](std::error::Error::source)). What is neither a form `Display`
/// writes nor a constant expression is refused with the reason the expression parser gives.
///
/// ```
/// use trigpoly::GaussianRational;
///
/// let err = "1 + 2j".parse::<GaussianRational>().unwrap_err();
/// assert_eq!(err.input(), "1 + 2j");
/// assert_eq!(err.reason().span.start, 5);
/// assert_eq!(
///     err.to_string(),
///     "not an exact Gaussian rational: \"1 + 2j\" (expected a form like 3/5 + 4/5*i): \
///      unknown name 'j' (no names are declared) at column 6"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "not an exact Gaussian rational: {input:?} (expected a form like 3/5 + 4/5*i): {} at {}",
    reason.message(),
    place(input, reason)
)]
pub struct ParseGaussianError {
    /// The text that did not parse.
    input: String,
    /// The expression parser's error in it, which the message says.
    reason: ParseError,
}

/// Where `reason` is in `input`: `column C`, or `line L, column C` in a text of several lines
/// (columns in characters), or `the end` of the text.
fn place(input: &str, reason: &ParseError) -> String {
    if reason.span.start >= input.trim_end().len() {
        return "the end".to_string();
    }
    match reason.line_col(input) {
        (1, column) => format!("column {column}"),
        (line, column) => format!("line {line}, column {column}"),
    }
}

impl ParseGaussianError {
    /// The text that did not parse.
    pub fn input(&self) -> &str {
        &self.input
    }

    /// Why: the expression parser's error, its span a byte range of [`ParseGaussianError::input`]
    /// and its message without the place (`unknown name 'j'`, `division by zero`).
    pub fn reason(&self) -> &ParseError {
        &self.reason
    }
}

impl FromStr for GaussianRational {
    type Err = ParseGaussianError;
    /// Accepts what `Display` writes (`a`, `b*i`, `i`, `-i`, `a + b*i`, `a - b*i` with `a, b`
    /// integers or fractions), and any other constant expression of the expression syntax:
    /// `1 + i/2`, `i*2`, `(1 + 2i)/3`, `−1 − i`, `(1 + i)²`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match Self::from_plain_form(s) {
            Some(z) => Ok(z),
            None => constant_expression(s).map_err(|reason| ParseGaussianError {
                input: s.to_string(),
                reason,
            }),
        }
    }
}

/// The value of a constant expression (no variable) such as `(1 + 2i)/3`, or why `s` is none:
/// with no variables declared, a name is unknown, so an expression that parses is a constant.
fn constant_expression(s: &str) -> Result<GaussianRational, ParseError> {
    let no_variables = crate::Vars::builder()
        .build()
        .map_err(|e| ParseError::new(Span::new(0, s.len()), e.to_string()))?;
    let e = crate::Poly::<GaussianRational>::parse(&no_variables, s)?;
    e.as_constant()
        .ok_or_else(|| ParseError::new(Span::new(0, s.len()), "not a constant"))
}

impl GaussianRational {
    /// The forms `Display` writes, read without the expression parser; `None` for any other
    /// text.
    fn from_plain_form(s: &str) -> Option<Self> {
        let t: String = s.chars().filter(|c| !c.is_whitespace()).collect();
        let imag = |p: &str| -> Option<Rational> {
            let body = p.strip_suffix('i')?;
            let body = body.strip_suffix('*').unwrap_or(body);
            match body {
                "" | "+" => Some(Rational::one()),
                "-" => Some(-Rational::one()),
                b => b.parse().ok(),
            }
        };
        if !t.ends_with('i') {
            return t.parse::<Rational>().ok().map(GaussianRational::from);
        }
        // Split at the last sign that is not the first character.
        let split = t
            .char_indices()
            .skip(1)
            .filter(|&(_, c)| c == '+' || c == '-')
            .map(|(k, _)| k)
            .last();
        match split {
            Some(k) => Some(GaussianRational {
                re: t[..k].parse().ok()?,
                im: imag(&t[k..])?,
            }),
            None => Some(GaussianRational {
                re: Rational::zero(),
                im: imag(&t)?,
            }),
        }
    }
}

forward_binop!(GaussianRational, Add, add, AddAssign, add_assign, |a, b| {
    GaussianRational {
        re: &a.re + &b.re,
        im: &a.im + &b.im,
    }
});
forward_binop!(GaussianRational, Sub, sub, SubAssign, sub_assign, |a, b| {
    GaussianRational {
        re: &a.re - &b.re,
        im: &a.im - &b.im,
    }
});
// (a + bi)(c + di) = (ac − bd) + (ad + bc)i
forward_binop!(GaussianRational, Mul, mul, MulAssign, mul_assign, |a, b| {
    GaussianRational {
        re: &a.re * &b.re - &a.im * &b.im,
        im: &a.re * &b.im + &a.im * &b.re,
    }
});
// a / b = a · b⁻¹. Panics if the divisor is zero (use `try_inv` for a checked division).
forward_binop!(GaussianRational, Div, div, DivAssign, div_assign, |a, b| {
    let inv = b.try_inv().expect("division by zero");
    <&GaussianRational as Mul<&GaussianRational>>::mul(a, &inv)
});

fold_traits!(
    GaussianRational,
    GaussianRational::from(Rational::zero()),
    GaussianRational::from(Rational::one())
);

impl Neg for &GaussianRational {
    type Output = GaussianRational;
    fn neg(self) -> GaussianRational {
        GaussianRational {
            re: -&self.re,
            im: -&self.im,
        }
    }
}

impl Neg for GaussianRational {
    type Output = GaussianRational;
    fn neg(self) -> GaussianRational {
        -&self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Sum` and `Product` over values and references are the folds of `+` and `·` from 0
    /// and 1, for Q and Q(i), past a machine word too; an empty sum is 0 and an empty product
    /// is 1.
    #[test]
    fn sums_and_products_of_iterators_are_the_folds() {
        let q: Vec<Rational> = [(1, 2), (-3, 4), (5, 6), (i64::MAX, 7), (7, i64::MAX)]
            .iter()
            .map(|&(n, d)| Rational::new(n, d))
            .collect();
        let sum = q.iter().fold(Rational::zero(), |acc, x| &acc + x);
        let product = q.iter().fold(Rational::one(), |acc, x| &acc * x);
        assert_eq!(q.iter().sum::<Rational>(), sum);
        assert_eq!(q.clone().into_iter().sum::<Rational>(), sum);
        assert_eq!(q.iter().product::<Rational>(), product);
        assert_eq!(q.clone().into_iter().product::<Rational>(), product);
        // 1/2 · (−3/4) · 5/6 · (2⁶³ − 1)/7 · 7/(2⁶³ − 1) = −5/16, through big integers.
        assert_eq!(product, Rational::new(-5, 16));
        assert_eq!(
            std::iter::empty::<Rational>().sum::<Rational>(),
            Rational::zero()
        );
        assert_eq!(
            std::iter::empty::<&Rational>().product::<Rational>(),
            Rational::one()
        );

        let z: Vec<GaussianRational> = q
            .iter()
            .zip(q.iter().rev())
            .map(|(re, im)| GaussianRational::new(re.clone(), im.clone()))
            .collect();
        let zero = GaussianRational::from(Rational::zero());
        let one = GaussianRational::from(Rational::one());
        let sum = z.iter().fold(zero.clone(), |acc, x| &acc + x);
        let product = z.iter().fold(one.clone(), |acc, x| &acc * x);
        assert_eq!(z.iter().sum::<GaussianRational>(), sum);
        assert_eq!(z.clone().into_iter().sum::<GaussianRational>(), sum);
        assert_eq!(z.iter().product::<GaussianRational>(), product);
        assert_eq!(z.into_iter().product::<GaussianRational>(), product);
        // (1 + i)(1 − i) = 2
        let w = GaussianRational::new(Rational::one(), Rational::one());
        let conj: GaussianRational = [w.clone(), w.conj()].iter().product();
        assert_eq!(conj, GaussianRational::from(Rational::from(2)));
        assert_eq!(
            std::iter::empty::<GaussianRational>().sum::<GaussianRational>(),
            zero
        );
        assert_eq!(
            std::iter::empty::<&GaussianRational>().product::<GaussianRational>(),
            one
        );
    }

    /// What `Display` writes reads back, and so does any constant expression (`i*2` and
    /// `1 + i/2` were refused); a name, a non-constant or a malformed form is an error.
    #[test]
    fn gaussian_rationals_parse_from_display_and_constant_expressions() {
        let g = |re: (i64, i64), im: (i64, i64)| {
            GaussianRational::new(Rational::new(re.0, re.1), Rational::new(im.0, im.1))
        };
        for z in [
            g((1, 2), (-3, 4)),
            g((0, 1), (1, 1)),
            g((-5, 1), (0, 1)),
            g((0, 1), (-1, 3)),
        ] {
            assert_eq!(
                z.to_string().parse::<GaussianRational>(),
                Ok(z.clone()),
                "{z}"
            );
        }
        for (text, value) in [
            ("i*2", g((0, 1), (2, 1))),
            ("1 + i/2", g((1, 1), (1, 2))),
            ("(1 + 2i)/3", g((1, 3), (2, 3))),
            ("−1 − i", g((-1, 1), (-1, 1))),
            ("(1 + i)²", g((0, 1), (2, 1))),
            ("1/(1 + i)", g((1, 2), (-1, 2))),
        ] {
            assert_eq!(text.parse::<GaussianRational>(), Ok(value), "{text}");
        }
    }

    /// A text that is no Gaussian rational is refused with the expression parser's reason and
    /// its place, where the error held the text alone: `ParseGaussianError::reason` is the
    /// error at its span, and `Display` says what and where (so the reason is not its source).
    #[test]
    fn a_gaussian_rational_that_does_not_parse_says_why_and_where() {
        let expected = "(expected a form like 3/5 + 4/5*i)";
        for (bad, at, why, place) in [
            (
                "x",
                0..1,
                "unknown name 'x' (no names are declared)",
                "column 1",
            ),
            (
                "1 +",
                3..3,
                "expected an expression after '+', found end of input",
                "the end",
            ),
            (
                "",
                0..0,
                "expected an expression, found end of input",
                "the end",
            ),
            (
                "i^i",
                2..3,
                "exponents must be integer constants",
                "column 3",
            ),
            ("1/0", 2..3, "division by zero", "column 3"),
            (
                "1 +\n  2j",
                7..8,
                "unknown name 'j' (no names are declared)",
                "line 2, column 4",
            ),
            ("½", 0..2, "", "column 1"),
        ] {
            let err = bad.parse::<GaussianRational>().unwrap_err();
            assert_eq!(err.input(), bad);
            let reason = err.reason();
            assert_eq!(reason.span.start..reason.span.end, at, "{bad:?}: {err}");
            if !why.is_empty() {
                assert_eq!(reason.message(), why, "{bad:?}");
            }
            let shown = format!(
                "not an exact Gaussian rational: {bad:?} {expected}: {} at {place}",
                reason.message()
            );
            assert_eq!(err.to_string(), shown);
            // The message says the reason, so it is not the source too.
            assert!(std::error::Error::source(&err).is_none(), "{bad:?}");
        }
    }
}
