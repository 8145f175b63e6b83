//! `Rational`: exact rational numbers Q, the coefficient field of real polynomials.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::str::FromStr;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::gcd::{binary_gcd, gcd_bigint, gcd_u128};
use super::Integer;

/// An exact rational number in lowest terms with a positive denominator.
///
/// Values whose numerator and denominator fit an `i64` are kept in machine words and computed
/// with `i128` intermediates; others are `num_rational::BigRational`. The representation is
/// canonical (a value that fits is never big), so equality and hashing are structural.
///
/// ```
/// use trigpoly::Rational;
/// let a: Rational = "3/4".parse().unwrap();
/// let b = Rational::new(1, 4);
/// assert_eq!((a + b).to_string(), "1");
/// assert_eq!(Rational::new(-6, 8).to_string(), "-3/4");
/// ```
///
/// # Panics
///
/// Division by zero with `/` or `/=` panics ("division by zero"); [`Rational::try_inv`] is
/// the checked inverse, and [`Rational::pow`] of zero to a negative power returns `None`.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Rational(Repr);

#[derive(Clone, PartialEq, Eq, Hash)]
enum Repr {
    /// `num/den` with `den > 0` and `gcd(|num|, den) = 1`.
    Small { num: i64, den: i64 },
    /// A value whose numerator or denominator does not fit an `i64`.
    Big(Box<BigRational>),
}

/// The absolute value of a numerator, or a denominator, borrowed for printing.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Magnitude<'a> {
    Word(u64),
    Big(&'a num_bigint::BigUint),
}

impl Magnitude<'_> {
    pub(crate) fn is_one(&self) -> bool {
        match self {
            Magnitude::Word(w) => *w == 1,
            Magnitude::Big(b) => b.is_one(),
        }
    }
}

impl fmt::Display for Magnitude<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Magnitude::Word(w) => w.fmt(f),
            Magnitude::Big(b) => b.fmt(f),
        }
    }
}

impl Rational {
    /// `|numerator|` and the denominator, borrowed (no copy of a big value).
    pub(crate) fn magnitudes(&self) -> (Magnitude<'_>, Magnitude<'_>) {
        match &self.0 {
            Repr::Small { num, den } => (
                Magnitude::Word(num.unsigned_abs()),
                Magnitude::Word(den.unsigned_abs()),
            ),
            Repr::Big(b) => (
                Magnitude::Big(b.numer().magnitude()),
                Magnitude::Big(b.denom().magnitude()),
            ),
        }
    }

    /// `num/den` from `i128` parts, reduced; `den` nonzero.
    fn from_i128(num: i128, den: i128) -> Rational {
        debug_assert!(den != 0);
        if let (Ok(n), Ok(d)) = (i64::try_from(num), i64::try_from(den)) {
            if d == 1 {
                return Rational(Repr::Small { num: n, den: 1 });
            }
            // The common case: word-sized gcd and division (no 128-bit division).
            if n != i64::MIN && d != i64::MIN {
                let g = binary_gcd(n.unsigned_abs(), d.unsigned_abs()) as i64;
                let (n, d) = if g == 1 { (n, d) } else { (n / g, d / g) };
                let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
                return Rational(Repr::Small { num: n, den: d });
            }
        }
        let g = gcd_u128(num.unsigned_abs(), den.unsigned_abs()) as i128;
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            // |n|, |d| ≤ 2^127 − 1 here unless they were i128::MIN, which the callers never pass.
            n = -n;
            d = -d;
        }
        match (i64::try_from(n), i64::try_from(d)) {
            (Ok(num), Ok(den)) => Rational(Repr::Small { num, den }),
            _ => Rational(Repr::Big(Box::new(BigRational::new_raw(
                BigInt::from(n),
                BigInt::from(d),
            )))),
        }
    }

    /// `(n1/d1)·(n2/d2)` for canonical word-sized parts (each in lowest terms, positive
    /// denominators). Cancelling across first, by `gcd(n1, d2)` and `gcd(n2, d1)`, leaves the
    /// product in lowest terms: no gcd of the products, and no division at all when the cross
    /// gcds are 1, as they mostly are.
    #[inline]
    fn mul_small(n1: i64, d1: i64, n2: i64, d2: i64) -> Rational {
        if n1 == 0 || n2 == 0 {
            return Rational::zero();
        }
        // A factor of one (the content of most generators and of their products) leaves the
        // other as it is, in lowest terms already.
        if (n1, d1) == (1, 1) {
            return Rational(Repr::Small { num: n2, den: d2 });
        }
        if (n2, d2) == (1, 1) {
            return Rational(Repr::Small { num: n1, den: d1 });
        }
        if n1 != i64::MIN && n2 != i64::MIN {
            // Each gcd divides a positive `i64`, so it is one too.
            let g1 = binary_gcd(n1.unsigned_abs(), d2 as u64) as i64;
            let g2 = binary_gcd(n2.unsigned_abs(), d1 as u64) as i64;
            let (a, d) = if g1 == 1 {
                (n1, d2)
            } else {
                (n1 / g1, d2 / g1)
            };
            let (b, c) = if g2 == 1 {
                (n2, d1)
            } else {
                (n2 / g2, d1 / g2)
            };
            if let (Some(num), Some(den)) = (a.checked_mul(b), c.checked_mul(d)) {
                return Rational(Repr::Small { num, den });
            }
        }
        Rational::from_i128(n1 as i128 * n2 as i128, d1 as i128 * d2 as i128)
    }

    /// `self · k`: for word-sized values one gcd, of `k` and the denominator, where a product
    /// of two rationals takes two.
    #[must_use]
    pub fn mul_integer(&self, k: &Integer) -> Rational {
        if let Repr::Small { num, den } = &self.0 {
            let Some(k) = k.to_i64() else {
                return Rational::mul_long_integer(*num, *den, k);
            };
            if k == 0 || *num == 0 {
                return Rational::zero();
            }
            if k != i64::MIN {
                // The gcd divides the positive `den`, so it is a positive `i64`.
                let g = binary_gcd(k.unsigned_abs(), *den as u64) as i64;
                if let Some(num) = num.checked_mul(k / g) {
                    return Rational(Repr::Small { num, den: den / g });
                }
            }
        }
        self * &Rational::from(k)
    }

    /// `(num/den)·k` for canonical word-sized parts and a `k` past a word: cancelled first by
    /// `gcd(k, den)`, found from `k mod den`, which leaves the product in lowest terms. A
    /// product of big rationals took a gcd of the big products instead (the printing of a
    /// polynomial with 70-digit coefficients spent a fifth of its time there).
    #[inline(never)]
    fn mul_long_integer(num: i64, den: i64, k: &Integer) -> Rational {
        if num == 0 {
            return Rational::zero();
        }
        let g = k.gcd(&Integer::from(den)).to_bigint();
        let numer = BigInt::from(num) * (k.to_bigint() / &g);
        Rational::from_big(BigRational::new_raw(numer, BigInt::from(den) / g))
    }

    /// The canonical form of a big rational.
    fn from_big(v: BigRational) -> Rational {
        match (v.numer().to_i64(), v.denom().to_i64()) {
            (Some(num), Some(den)) => Rational(Repr::Small { num, den }),
            _ => Rational(Repr::Big(Box::new(v))),
        }
    }

    /// The value as a `BigRational` ([`num_rational`](crate::num_rational), re-exported).
    ///
    /// ```
    /// use trigpoly::num_rational::BigRational;
    /// use trigpoly::Rational;
    ///
    /// let q: Rational = "-3/4".parse()?;
    /// let big: BigRational = q.to_big_rational();
    /// assert_eq!(big.to_string(), "-3/4");
    /// assert_eq!(Rational::from(big), q);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn to_big_rational(&self) -> BigRational {
        match &self.0 {
            Repr::Small { num, den } => {
                BigRational::new_raw(BigInt::from(*num), BigInt::from(*den))
            }
            Repr::Big(b) => (**b).clone(),
        }
    }

    /// `num/den`, reduced.
    ///
    /// # Panics
    ///
    /// Panics if `den == 0` ("denominator is zero"); [`Rational::from_fraction`] returns
    /// `None` there instead.
    pub fn new(num: i64, den: i64) -> Rational {
        assert!(den != 0, "denominator is zero");
        Rational::from_i128(num as i128, den as i128)
    }

    /// `num/den` from integers, reduced; `None` if `den` is zero.
    pub fn from_fraction(num: &Integer, den: &Integer) -> Option<Rational> {
        if den.is_zero() {
            return None;
        }
        Some(match (num.to_i64(), den.to_i64()) {
            (Some(n), Some(d)) => Rational::from_i128(n as i128, d as i128),
            _ => Rational::from_big(big::reduced(num.to_bigint(), den.to_bigint())),
        })
    }

    /// Zero.
    pub fn zero() -> Rational {
        Rational(Repr::Small { num: 0, den: 1 })
    }

    /// One.
    pub fn one() -> Rational {
        Rational(Repr::Small { num: 1, den: 1 })
    }

    /// Whether the value is zero.
    pub fn is_zero(&self) -> bool {
        matches!(self.0, Repr::Small { num: 0, .. })
    }

    /// Whether the value is one.
    pub fn is_one(&self) -> bool {
        matches!(self.0, Repr::Small { num: 1, den: 1 })
    }

    /// Whether the value is negative.
    pub fn is_negative(&self) -> bool {
        match &self.0 {
            Repr::Small { num, .. } => *num < 0,
            Repr::Big(b) => b.is_negative(),
        }
    }

    /// Whether the value is an integer.
    pub fn is_integer(&self) -> bool {
        match &self.0 {
            Repr::Small { den, .. } => *den == 1,
            Repr::Big(b) => b.is_integer(),
        }
    }

    /// The numerator (carries the sign).
    pub fn numer(&self) -> Integer {
        match &self.0 {
            Repr::Small { num, .. } => Integer::from(*num),
            Repr::Big(b) => Integer::from_bigint(b.numer().clone()),
        }
    }

    /// `(numerator, denominator)` as machine integers, if both fit.
    pub fn small_parts(&self) -> Option<(i64, i64)> {
        match &self.0 {
            Repr::Small { num, den } => Some((*num, *den)),
            Repr::Big(_) => None,
        }
    }

    /// The denominator (positive).
    pub fn denom(&self) -> Integer {
        match &self.0 {
            Repr::Small { den, .. } => Integer::from(*den),
            Repr::Big(b) => Integer::from_bigint(b.denom().clone()),
        }
    }

    /// The inverse, or `None` for zero.
    pub fn try_inv(&self) -> Option<Rational> {
        if self.is_zero() {
            return None;
        }
        Some(match &self.0 {
            Repr::Small { num, den } => Rational::from_i128(*den as i128, *num as i128),
            Repr::Big(b) => Rational::from_big(b.recip()),
        })
    }

    /// The rational square root, when `self` is the square of a rational (`9/4` → `3/2`, the
    /// nonnegative one); `None` otherwise (`2`, `−1`).
    ///
    /// ```
    /// use trigpoly::Rational;
    /// assert_eq!(Rational::new(9, 4).sqrt(), Some(Rational::new(3, 2)));
    /// assert_eq!(Rational::new(2, 1).sqrt(), None);
    /// assert_eq!(Rational::new(-1, 1).sqrt(), None);
    /// ```
    pub fn sqrt(&self) -> Option<Rational> {
        if self.is_negative() {
            return None;
        }
        let root = |n: Integer| {
            let n = n.to_bigint();
            let r = n.sqrt();
            (&r * &r == n).then(|| Integer::from_bigint(r))
        };
        Rational::from_fraction(&root(self.numer())?, &root(self.denom())?)
    }

    /// Absolute value.
    #[must_use]
    pub fn abs(&self) -> Rational {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }

    /// `self^e` for any integer `e`; `None` for `0^e` with `e < 0`.
    ///
    /// By repeated squaring: about `2·log₂|e|` products, the last of them on numbers of about
    /// `|e|` times the bits of `self`'s. The cost grows with the size of the result, not with
    /// the number of products: `2^(2^40)` has 2^40 bits (128 GiB) and does not end in any
    /// useful time, though it takes 41 squarings. [`Rational::checked_pow`] refuses a result
    /// past a size before any product.
    pub fn pow(&self, e: i64) -> Option<Rational> {
        let mut base = if e < 0 { self.try_inv()? } else { self.clone() };
        let mut k = e.unsigned_abs();
        let mut acc = Rational::one();
        while k > 0 {
            if k & 1 == 1 {
                acc = &acc * &base;
            }
            k >>= 1;
            if k > 0 {
                base = &base * &base;
            }
        }
        Some(acc)
    }

    /// `self^e` when its numerator and denominator have at most `max_bits` bits each; `None`
    /// past that, and for `0^e` with `e < 0`. The size is bounded before any product: a base
    /// `n/d` gives `|n|^|e|` of at least `|e|·(bits(n) − 1) + 1` bits, so an exponent that
    /// would make [`Rational::pow`] run for hours (`2^(2^40)`) is refused at once, and one that
    /// passes does at most about `2·max_bits` bits of work a side. `±1` to any power is `±1`.
    ///
    /// ```
    /// use trigpoly::Rational;
    /// let two = Rational::from(2);
    /// assert_eq!(two.checked_pow(10, 64), Some(Rational::from(1024)));
    /// assert_eq!(two.checked_pow(-63, 64), two.pow(-63));
    /// assert_eq!(two.checked_pow(64, 64), None); // 2^64 has 65 bits
    /// assert_eq!(two.checked_pow(1 << 40, 1 << 20), None);
    /// assert_eq!((-Rational::one()).checked_pow(i64::MAX, 1), Some(-Rational::one()));
    /// assert_eq!(Rational::zero().checked_pow(-1, 64), None);
    /// ```
    pub fn checked_pow(&self, e: i64, max_bits: u64) -> Option<Rational> {
        let k = u128::from(e.unsigned_abs());
        // The fewest bits `|part|^k` can have: `2^(b−1) ≤ |part|`, so `2^(k(b−1)) ≤ |part|^k`.
        let surely_past = |part: Integer| {
            let b = u128::from(part.bits());
            b >= 2 && k * (b - 1) + 1 > u128::from(max_bits)
        };
        if surely_past(self.numer()) || surely_past(self.denom()) {
            return None;
        }
        let p = self.pow(e)?;
        (p.numer().bits() <= max_bits && p.denom().bits() <= max_bits).then_some(p)
    }

    /// `gcd(a, b)` in the sense of contents: `gcd(numerators)/lcm(denominators)`, positive, so
    /// that `a/g` and `b/g` are coprime integers. `gcd(0, b) = |b|`.
    pub fn content_gcd(a: &Rational, b: &Rational) -> Rational {
        if let Some(words) = WordContent::of(a, b) {
            if words.num == 0 {
                return Rational::zero();
            }
            return Rational(Repr::Small {
                num: words.num,
                den: words.den,
            });
        }
        let num = a.numer().gcd(&b.numer());
        let den = a.denom().lcm(&b.denom());
        Rational::from_fraction(&num, &den).expect("lcm of denominators is nonzero")
    }

    /// `(g, a/g, b/g)` with `g = content_gcd(a, b)`: the content common to two polynomials
    /// and the coprime integers that bring each content to it (what a sum needs). `a`, `b`
    /// nonzero.
    ///
    /// ```
    /// use trigpoly::{Integer, Rational};
    /// let (g, sa, sb) = Rational::content_split(&Rational::new(4, 3), &Rational::new(-6, 5));
    /// assert_eq!((g, sa, sb), (Rational::new(2, 15), Integer::from(10), Integer::from(-9)));
    /// ```
    pub fn content_split(a: &Rational, b: &Rational) -> (Rational, Integer, Integer) {
        debug_assert!(!a.is_zero() && !b.is_zero());
        if let Some(words) = WordContent::of(a, b) {
            // a/g = (n1/num)·(d2/dg), b/g = (n2/num)·(d1/dg).
            let scale = |n: i64, e: u64| Integer::from_i128((n / words.num) as i128 * e as i128);
            return (
                Rational(Repr::Small {
                    num: words.num,
                    den: words.den,
                }),
                scale(words.n1, words.e2),
                scale(words.n2, words.e1),
            );
        }
        let g = Rational::content_gcd(a, b);
        let (sa, sb) = ((a / &g).numer(), (b / &g).numer());
        (g, sa, sb)
    }

    /// The content of a list: `content_gcd` of all of them (zero for an empty list), so that
    /// each value divided by it is an integer and those integers are coprime.
    pub fn content_of<'a>(values: impl IntoIterator<Item = &'a Rational>) -> Rational {
        values
            .into_iter()
            .fold(Rational::zero(), |g, q| Rational::content_gcd(&g, q))
    }

    /// Compares with zero.
    pub fn sign(&self) -> Ordering {
        match &self.0 {
            Repr::Small { num, .. } => num.cmp(&0),
            Repr::Big(b) => (**b).cmp(&BigRational::zero()),
        }
    }
}

/// `content_gcd` of two word-sized fractions `n1/d1`, `n2/d2` in word arithmetic:
/// `num/den = gcd(n1, n2)/lcm(d1, d2)`, with `e1 = d1/dg`, `e2 = d2/dg` for `dg = gcd(d1, d2)`.
/// Both fractions are in lowest terms, so `num` (which divides both numerators) is prime to
/// both denominators and to their lcm: the quotient needs no reduction.
struct WordContent {
    num: i64,
    den: i64,
    n1: i64,
    n2: i64,
    e1: u64,
    e2: u64,
}

impl WordContent {
    /// `None` when a value is not word-sized or the gcd or the lcm passes `i64`.
    fn of(a: &Rational, b: &Rational) -> Option<WordContent> {
        let (Repr::Small { num: n1, den: d1 }, Repr::Small { num: n2, den: d2 }) = (&a.0, &b.0)
        else {
            return None;
        };
        let num = i64::try_from(binary_gcd(n1.unsigned_abs(), n2.unsigned_abs())).ok()?;
        let dg = binary_gcd(*d1 as u64, *d2 as u64);
        let (e1, e2) = (*d1 as u64 / dg, *d2 as u64 / dg);
        let den = i64::try_from(e1.checked_mul(*d2 as u64)?).ok()?;
        Some(WordContent {
            num,
            den,
            n1: *n1,
            n2: *n2,
            e1,
            e2,
        })
    }
}

impl Default for Rational {
    fn default() -> Self {
        Rational::zero()
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        match (&self.0, &other.0) {
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => {
                (*a as i128 * *d as i128).cmp(&(*c as i128 * *b as i128))
            }
            _ => self.to_big_rational().cmp(&other.to_big_rational()),
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl From<BigRational> for Rational {
    fn from(v: BigRational) -> Self {
        Rational::from_big(v)
    }
}

impl From<Integer> for Rational {
    fn from(v: Integer) -> Self {
        Rational::from(&v)
    }
}

impl From<&Integer> for Rational {
    fn from(v: &Integer) -> Self {
        match v.to_i64() {
            Some(n) => Rational(Repr::Small { num: n, den: 1 }),
            None => Rational(Repr::Big(Box::new(BigRational::from_integer(
                v.to_bigint(),
            )))),
        }
    }
}

impl From<i64> for Rational {
    fn from(v: i64) -> Self {
        Rational(Repr::Small { num: v, den: 1 })
    }
}

/// A big integer, as num-rational's `BigRational` takes one, in the one form of its value
/// (in words when it fits them, as [`Integer`] holds it): equal values are equal.
///
/// ```
/// use trigpoly::num_bigint::BigInt;
/// use trigpoly::Rational;
///
/// assert_eq!(Rational::from(BigInt::from(-6)), Rational::from(-6));
/// let big = BigInt::from(10).pow(30);
/// assert_eq!(Rational::from(big.clone()).to_string(), big.to_string());
/// assert_eq!(Rational::from(big).denom(), 1.into());
/// ```
impl From<BigInt> for Rational {
    fn from(v: BigInt) -> Self {
        Rational::from(Integer::from(v))
    }
}

/// `From` for the other primitive integers, each by way of the [`Integer`] it makes, which holds
/// a value that fits a word in the word as `From<i64>` does.
macro_rules! from_integers {
    ($($(#[$doc:meta])* $t:ty),*) => {$(
        $(#[$doc])*
        impl From<$t> for Rational {
            fn from(v: $t) -> Self {
                Rational::from(Integer::from(v))
            }
        }
    )*};
}

from_integers!(
    i8, i16, i32, i128, isize, u8, u16, u32, u64, usize,
    /// A `u128`, exact past an `i128`: a `Rational` is made from an integer of any primitive
    /// type, as num-bigint's `BigInt` is (an unsuffixed literal is an `i32`), each exactly.
    ///
    /// ```
    /// use trigpoly::Rational;
    ///
    /// assert_eq!(Rational::from(3), Rational::new(3, 1));
    /// assert_eq!(Rational::from(3u8) + Rational::from(-4i16), Rational::from(-1));
    /// assert_eq!(Rational::from(7usize), Rational::from(7i64));
    /// assert_eq!(Rational::from(u64::MAX).to_string(), "18446744073709551615");
    /// assert_eq!(Rational::from(u128::MAX).to_string(), u128::MAX.to_string());
    /// assert_eq!(Rational::from(i128::MIN).to_string(), i128::MIN.to_string());
    /// ```
    u128
);

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small { num, den: 1 } => write!(f, "{num}"),
            Repr::Small { num, den } => write!(f, "{num}/{den}"),
            Repr::Big(b) if b.is_integer() => write!(f, "{}", b.numer()),
            Repr::Big(b) => write!(f, "{}/{}", b.numer(), b.denom()),
        }
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// Why a rational number did not parse: the text, and which part of it is wrong
/// ([`ParseRationalError::kind`]), as num-rational's `ParseRatioError` tells a bad integer
/// from a zero denominator.
///
/// ```
/// use trigpoly::{RationalErrorKind, Rational};
///
/// let err = "3/0".parse::<Rational>().unwrap_err();
/// assert_eq!(err.input(), "3/0");
/// assert_eq!(err.kind(), RationalErrorKind::ZeroDenominator);
/// assert_eq!(
///     err.to_string(),
///     "not an exact rational number: \"3/0\" (the denominator is zero; \
///      expected an integer or a fraction like -3/4)"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "not an exact rational number: {input:?} ({kind}; expected an integer or a fraction like -3/4)"
)]
pub struct ParseRationalError {
    /// The text that did not parse.
    input: String,
    /// Which part of it is wrong.
    kind: RationalErrorKind,
}

/// Which part of a text that is no rational number is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum RationalErrorKind {
    /// The numerator (the whole text, when there is no `/`) is no integer.
    Numerator,
    /// The denominator is no integer.
    Denominator,
    /// The denominator is zero.
    ZeroDenominator,
}

impl fmt::Display for RationalErrorKind {
    /// The fault as a clause: `the numerator is no integer`, `the denominator is zero`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            RationalErrorKind::Numerator => "the numerator is no integer",
            RationalErrorKind::Denominator => "the denominator is no integer",
            RationalErrorKind::ZeroDenominator => "the denominator is zero",
        })
    }
}

impl ParseRationalError {
    /// The text that did not parse.
    pub fn input(&self) -> &str {
        &self.input
    }

    /// Which part of the text is wrong.
    pub fn kind(&self) -> RationalErrorKind {
        self.kind
    }
}

impl FromStr for Rational {
    type Err = ParseRationalError;
    /// Reads an integer or a fraction `n/d` of integers (`-3/4`, ` 6 / -8 `), in lowest terms.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = |kind| ParseRationalError {
            input: s.to_string(),
            kind,
        };
        let t = s.trim();
        let (n, d) = match t.split_once('/') {
            Some((n, d)) => (n.trim(), d.trim()),
            None => (t, "1"),
        };
        let n: BigInt = n.parse().map_err(|_| err(RationalErrorKind::Numerator))?;
        let d: BigInt = d.parse().map_err(|_| err(RationalErrorKind::Denominator))?;
        if d.is_zero() {
            return Err(err(RationalErrorKind::ZeroDenominator));
        }
        Ok(Rational::from_big(big::reduced(n, d)))
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

/// `Sum` and `Product` of an iterator of values or of references, as `num-rational`'s
/// `Ratio` has them: `0` for an empty sum, `1` for an empty product.
macro_rules! fold_traits {
    ($Ty:ident, $zero:expr, $one:expr) => {
        impl std::iter::Sum for $Ty {
            fn sum<I: Iterator<Item = $Ty>>(iter: I) -> $Ty {
                iter.fold($zero, |acc, x| acc + x)
            }
        }
        impl<'a> std::iter::Sum<&'a $Ty> for $Ty {
            fn sum<I: Iterator<Item = &'a $Ty>>(iter: I) -> $Ty {
                iter.fold($zero, |acc, x| acc + x)
            }
        }
        impl std::iter::Product for $Ty {
            fn product<I: Iterator<Item = $Ty>>(iter: I) -> $Ty {
                iter.fold($one, |acc, x| acc * x)
            }
        }
        impl<'a> std::iter::Product<&'a $Ty> for $Ty {
            fn product<I: Iterator<Item = &'a $Ty>>(iter: I) -> $Ty {
                iter.fold($one, |acc, x| acc * x)
            }
        }
    };
}
pub(crate) use fold_traits;

fold_traits!(Rational, Rational::zero(), Rational::one());

/// Arithmetic of big rationals in lowest terms, with gcds that take a short side to a word
/// first ([`gcd_bigint`]). `num-rational`'s own operators reduce with `num-integer`'s binary
/// gcd, whose cost is quadratic in the long side even when the other is 1 (an integer's
/// denominator): `(10^999)^100` took a second.
mod big {
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::{One, Signed};

    use super::gcd_bigint;

    /// `num/den` in lowest terms with a positive denominator (`den` nonzero).
    pub(super) fn reduced(num: BigInt, den: BigInt) -> BigRational {
        let g = gcd_bigint(&num, &den);
        let (num, den) = if g.is_one() {
            (num, den)
        } else {
            (num / &g, den / &g)
        };
        if den.is_negative() {
            BigRational::new_raw(-num, -den)
        } else {
            BigRational::new_raw(num, den)
        }
    }

    /// `a/b + c/d`.
    pub(super) fn add(x: &BigRational, y: &BigRational) -> BigRational {
        let (a, b, c, d) = (x.numer(), x.denom(), y.numer(), y.denom());
        if b == d {
            // Integers (b = d = 1) above all: the sum is in lowest terms.
            return if b.is_one() {
                BigRational::new_raw(a + c, b.clone())
            } else {
                reduced(a + c, b.clone())
            };
        }
        reduced(a * d + c * b, b * d)
    }

    /// `a/b − c/d`.
    pub(super) fn sub(x: &BigRational, y: &BigRational) -> BigRational {
        add(x, &-y)
    }

    /// `(a/b)(c/d) = (a/g₁ · c/g₂)/(b/g₂ · d/g₁)` with `g₁ = gcd(a, d)`, `g₂ = gcd(c, b)`: in
    /// lowest terms, since `a/b` and `c/d` are.
    pub(super) fn mul(x: &BigRational, y: &BigRational) -> BigRational {
        let (a, b, c, d) = (x.numer(), x.denom(), y.numer(), y.denom());
        let (g1, g2) = (gcd_bigint(a, d), gcd_bigint(c, b));
        let num = (a / &g1) * (c / &g2);
        let den = (b / &g2) * (d / &g1);
        if den.is_negative() {
            BigRational::new_raw(-num, -den)
        } else {
            BigRational::new_raw(num, den)
        }
    }

    /// `(a/b)/(c/d)` (`c` nonzero).
    pub(super) fn div(x: &BigRational, y: &BigRational) -> BigRational {
        mul(x, &y.recip())
    }
}

// a/b + c/d = (ad + cb)/(bd), in i128 for machine-word values.
forward_binop!(
    Rational,
    Add,
    add,
    AddAssign,
    add_assign,
    |a, b| match (&a.0, &b.0) {
        (Repr::Small { num: n1, den: d1 }, Repr::Small { num: n2, den: d2 }) =>
            Rational::from_i128(
                *n1 as i128 * *d2 as i128 + *n2 as i128 * *d1 as i128,
                *d1 as i128 * *d2 as i128
            ),
        _ => Rational::from_big(big::add(&a.to_big_rational(), &b.to_big_rational())),
    }
);
// a/b − c/d = (ad − cb)/(bd)
forward_binop!(
    Rational,
    Sub,
    sub,
    SubAssign,
    sub_assign,
    |a, b| match (&a.0, &b.0) {
        (Repr::Small { num: n1, den: d1 }, Repr::Small { num: n2, den: d2 }) =>
            Rational::from_i128(
                *n1 as i128 * *d2 as i128 - *n2 as i128 * *d1 as i128,
                *d1 as i128 * *d2 as i128
            ),
        _ => Rational::from_big(big::sub(&a.to_big_rational(), &b.to_big_rational())),
    }
);
// (a/b)(c/d) = (ac)/(bd)
forward_binop!(
    Rational,
    Mul,
    mul,
    MulAssign,
    mul_assign,
    |a, b| match (&a.0, &b.0) {
        (Repr::Small { num: n1, den: d1 }, Repr::Small { num: n2, den: d2 }) => {
            Rational::mul_small(*n1, *d1, *n2, *d2)
        }
        _ => Rational::from_big(big::mul(&a.to_big_rational(), &b.to_big_rational())),
    }
);
// (a/b)/(c/d) = (ad)/(bc). Panics if the divisor is zero (use `try_inv` for a checked division).
forward_binop!(Rational, Div, div, DivAssign, div_assign, |a, b| {
    assert!(!b.is_zero(), "division by zero");
    match (&a.0, &b.0) {
        (Repr::Small { num: n1, den: d1 }, Repr::Small { num: n2, den: d2 }) => {
            match n2.checked_abs() {
                // (n1/d1)·(±d2/|n2|), the second factor in lowest terms too.
                Some(m2) => Rational::mul_small(*n1, *d1, d2 * n2.signum(), m2),
                None => Rational::from_i128(*n1 as i128 * *d2 as i128, *d1 as i128 * *n2 as i128),
            }
        }
        _ => Rational::from_big(big::div(&a.to_big_rational(), &b.to_big_rational())),
    }
});

impl Neg for &Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        match &self.0 {
            Repr::Small { num, den } => match num.checked_neg() {
                Some(n) => Rational(Repr::Small { num: n, den: *den }),
                None => Rational::from_i128(-(*num as i128), *den as i128),
            },
            Repr::Big(b) => Rational::from_big(-(**b).clone()),
        }
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        -&self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A text that is no rational number says which part is wrong, where the error held the
    /// text alone: a numerator or denominator that is no integer, or a zero denominator.
    #[test]
    fn a_rational_that_does_not_parse_says_which_part_is_wrong() {
        for (text, kind) in [
            ("", RationalErrorKind::Numerator),
            ("x/2", RationalErrorKind::Numerator),
            ("1.5", RationalErrorKind::Numerator),
            ("3/", RationalErrorKind::Denominator),
            ("3/4/5", RationalErrorKind::Denominator),
            ("3/0", RationalErrorKind::ZeroDenominator),
            (" -7 / -0 ", RationalErrorKind::ZeroDenominator),
        ] {
            let err = text.parse::<Rational>().unwrap_err();
            assert_eq!((err.input(), err.kind()), (text, kind), "{text:?}");
        }
        assert_eq!(
            "x/2".parse::<Rational>().unwrap_err().to_string(),
            "not an exact rational number: \"x/2\" (the numerator is no integer; expected an \
             integer or a fraction like -3/4)"
        );
        assert_eq!(" 6 / -8 ".parse::<Rational>(), Ok(Rational::new(-3, 4)));
    }
}
