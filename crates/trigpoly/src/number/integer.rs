//! `Integer`: a machine integer that becomes a big integer only when it has to, in one word.
//!
//! A value of 63 bits is held in the word itself, tagged by its low bit (as FLINT's `fmpz` holds
//! its small values); any other value that fits an `i128` is boxed as `Wide` (one 16-byte
//! allocation, where a `BigInt` takes two, or a slot of a block that a large product's builder
//! takes for thousands of them, `WideSlab`), and only the rest as `Big`. The form is canonical, so
//! equality and hashing follow the value. Each operation tries the machine path with exact overflow
//! detection (`checked_*`, `i128` intermediates) and falls back to `num_bigint::BigInt`. The word
//! and its tag live in the module `word` (`integer/word.rs`), the one place with `unsafe` code;
//! everything else reads an `Integer` through [`Integer::view`]. The unit tests at the end check
//! the representation at every boundary, also under Miri:
//! `MIRIFLAGS=-Zmiri-strict-provenance cargo +nightly miri test -p trigpoly --lib number::integer`.

use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::str::FromStr;

use super::gcd::{binary_gcd, gcd_bigint, gcd_u128};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

pub use word::{Integer, Release, SlotCounts, WideSlab};

/// An [`Integer`] as read: a value of the word, or a boxed wider one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntegerView<'a> {
    /// A value in `[−2⁶², 2⁶²)`, held in the word.
    Small(i64),
    /// A value outside the word's range but inside `i128` range (sums of products of words,
    /// the coefficients of most large products).
    Wide(i128),
    /// A value outside `i128` range.
    Big(&'a BigInt),
}

/// The one-word representation and the `unsafe` code it takes.
mod word;

impl PartialEq for Integer {
    #[inline]
    fn eq(&self, other: &Self) -> bool {
        // The form is canonical: equal values are equal views.
        self.same_word(other) || (self.small().is_none() && self.view() == other.view())
    }
}

impl Eq for Integer {}

impl Hash for Integer {
    fn hash<H: Hasher>(&self, state: &mut H) {
        match self.view() {
            IntegerView::Small(v) => v.hash(state),
            IntegerView::Wide(v) => v.hash(state),
            IntegerView::Big(b) => b.hash(state),
        }
    }
}

impl Integer {
    /// Zero.
    pub const ZERO: Integer = Integer::small_unchecked(0);
    /// One.
    pub const ONE: Integer = Integer::small_unchecked(1);

    /// Whether the value is zero.
    #[inline]
    pub fn is_zero(&self) -> bool {
        self.small() == Some(0)
    }

    /// Whether the value is one.
    #[inline]
    pub fn is_one(&self) -> bool {
        self.small() == Some(1)
    }

    /// `v`, in the word when it fits there.
    #[inline(always)]
    fn from_i64(v: i64) -> Integer {
        if (Integer::SMALL_MIN..=Integer::SMALL_MAX).contains(&v) {
            Integer::small_unchecked(v)
        } else {
            Integer::wide(v as i128)
        }
    }

    /// The sign: -1, 0 or 1.
    pub fn signum(&self) -> i32 {
        match self.view() {
            IntegerView::Small(v) => v.signum() as i32,
            IntegerView::Wide(v) => v.signum() as i32,
            IntegerView::Big(b) => {
                if b.is_negative() {
                    -1
                } else {
                    1
                }
            }
        }
    }

    /// Whether the value is negative.
    pub fn is_negative(&self) -> bool {
        self.signum() < 0
    }

    /// The value as `i64`, if it fits.
    #[inline]
    pub fn to_i64(&self) -> Option<i64> {
        match self.small() {
            Some(v) => Some(v),
            None => self.boxed_to_i64(),
        }
    }

    /// [`Integer::to_i64`] of a boxed value (the 64th bit), out of line.
    #[inline(never)]
    fn boxed_to_i64(&self) -> Option<i64> {
        match self.view() {
            IntegerView::Wide(v) => i64::try_from(v).ok(),
            IntegerView::Small(v) => Some(v),
            IntegerView::Big(_) => None,
        }
    }

    /// The value as `i128`, if it fits.
    #[inline]
    pub fn to_i128(&self) -> Option<i128> {
        match self.view() {
            IntegerView::Small(v) => Some(v as i128),
            IntegerView::Wide(v) => Some(v),
            IntegerView::Big(_) => None,
        }
    }

    /// The value as a `BigInt`.
    pub fn to_bigint(&self) -> BigInt {
        match self.view() {
            IntegerView::Small(v) => BigInt::from(v),
            IntegerView::Wide(v) => BigInt::from(v),
            IntegerView::Big(b) => b.clone(),
        }
    }

    /// Builds from an `i128`, staying small when it fits.
    #[inline]
    pub fn from_i128(v: i128) -> Integer {
        Integer::from_i128_with(v, &mut Integer::wide)
    }

    /// [`Integer::from_i128`] with a value past the word made by `place` (which must hold it
    /// as [`Integer::wide`] does: [`WideSlab::place_integer`] of a slab the caller holds).
    #[inline(always)]
    pub(crate) fn from_i128_with(v: i128, place: &mut impl FnMut(i128) -> Integer) -> Integer {
        if (Integer::SMALL_MIN as i128..=Integer::SMALL_MAX as i128).contains(&v) {
            Integer::small_unchecked(v as i64)
        } else {
            place(v)
        }
    }

    /// An operation on two `i128`s (a sum, a difference, a product, an exact quotient),
    /// exactly: by `machine` when that does not overflow, else by `big`.
    fn from_i128_op(
        a: i128,
        b: i128,
        machine: fn(i128, i128) -> Option<i128>,
        big: fn(BigInt, BigInt) -> BigInt,
    ) -> Integer {
        match machine(a, b) {
            Some(v) => Integer::from_i128(v),
            None => Integer::from_bigint(big(BigInt::from(a), BigInt::from(b))),
        }
    }

    /// Builds from a `BigInt`, demoting to `Small` or `Wide` when it fits (the canonical form).
    pub fn from_bigint(b: BigInt) -> Integer {
        match b.to_i128() {
            Some(v) => Integer::from_i128(v),
            None => Integer::big(b),
        }
    }

    /// Absolute value.
    #[must_use]
    pub fn abs(&self) -> Integer {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }

    /// Greatest common divisor, always `>= 0`; `gcd(0, 0) = 0`.
    ///
    /// When one side fits a machine word (`i64` or `i128`) and the other does not,
    /// `gcd(a, b) = gcd(a, b mod a)` takes one pass over `b`'s digits and then a binary gcd on
    /// machine words: the running gcd of a polynomial's coefficients is short after the first
    /// few, and `num-bigint`'s gcd shifts the long side one step per bit.
    #[inline]
    #[must_use]
    pub fn gcd(&self, other: &Integer) -> Integer {
        match (self.small(), other.small()) {
            (Some(a), Some(b)) => Integer::from(binary_gcd(a.unsigned_abs(), b.unsigned_abs())),
            _ => self.gcd_long(other),
        }
    }

    /// [`Integer::gcd`] when a side is longer than an `i64` (out of line, so that the short
    /// case inlines).
    #[inline(never)]
    fn gcd_long(&self, other: &Integer) -> Integer {
        let word = |v: &Integer| v.to_i128().expect("not Big").unsigned_abs();
        match (self.view(), other.view()) {
            (IntegerView::Big(b), IntegerView::Big(c)) => Integer::from_bigint(gcd_bigint(b, c)),
            (IntegerView::Big(b), _) => Integer::gcd_big_short(b, word(other)),
            (_, IntegerView::Big(b)) => Integer::gcd_big_short(b, word(self)),
            _ => Integer::from_u128(gcd_u128(word(self), word(other))),
        }
    }

    /// `gcd(b, a)` for a `b` past `i128` and `a = |short|`: `gcd(a, b mod a)`.
    fn gcd_big_short(b: &BigInt, a: u128) -> Integer {
        if a == 0 {
            return Integer::big(b.abs());
        }
        let r = (b.magnitude() % a).to_u128().expect("below a u128");
        Integer::from_u128(gcd_u128(a, r))
    }

    /// Builds from a `u128` (above `i128::MAX` only as the gcd `2^127` of `i128::MIN`).
    fn from_u128(v: u128) -> Integer {
        match i128::try_from(v) {
            Ok(v) => Integer::from_i128(v),
            Err(_) => Integer::from_bigint(BigInt::from(v)),
        }
    }

    /// Least common multiple, always `>= 0`.
    #[must_use]
    pub fn lcm(&self, other: &Integer) -> Integer {
        if self.is_zero() || other.is_zero() {
            return Integer::ZERO;
        }
        let g = self.gcd(other);
        (self.div_exact(&g) * other).abs()
    }

    /// Exact division: the result is only meaningful when `d` divides `self`.
    ///
    /// # Panics
    ///
    /// Panics if `d` is zero.
    #[must_use]
    pub fn div_exact(&self, d: &Integer) -> Integer {
        match (self.small(), d.small()) {
            // Values of 63 bits: the quotient cannot overflow (a zero divisor panics).
            (Some(a), Some(b)) => Integer::from_i64(a / b),
            _ => match (self.to_i128(), d.to_i128()) {
                (Some(a), Some(b)) => Integer::from_i128_op(a, b, i128::checked_div, |a, b| a / b),
                _ => Integer::from_bigint(self.to_bigint() / d.to_bigint()),
            },
        }
    }

    /// Whether `d` divides `self`.
    ///
    /// # Panics
    ///
    /// Panics if `d` is zero.
    pub fn is_divisible_by(&self, d: &Integer) -> bool {
        match (self.small(), d.small()) {
            (Some(a), Some(b)) => a % b == 0,
            _ => match (self.to_i128(), d.to_i128()) {
                // The remainder overflows only for i128::MIN / −1, which divides.
                (Some(a), Some(b)) => a.checked_rem(b).is_none_or(|r| r == 0),
                _ => (self.to_bigint() % d.to_bigint()).is_zero(),
            },
        }
    }

    /// `self^e`. Its cost is that of the result's `e` times the bits of `self`: a `u32`
    /// exponent on a base past one bit can ask for gigabytes.
    #[must_use]
    pub fn pow(&self, e: u32) -> Integer {
        if let Some(v) = self.small() {
            if let Some(p) = v.checked_pow(e) {
                return Integer::from_i64(p);
            }
        }
        Integer::from_bigint(num_traits::pow(self.to_bigint(), e as usize))
    }

    /// Number of bits of the absolute value.
    pub fn bits(&self) -> u64 {
        match self.view() {
            IntegerView::Small(v) => 64 - v.unsigned_abs().leading_zeros() as u64,
            IntegerView::Wide(v) => 128 - v.unsigned_abs().leading_zeros() as u64,
            IntegerView::Big(b) => b.bits(),
        }
    }
}

/// A nonzero divisor prepared for many exact divisions (the content of a polynomial taken out
/// of each coefficient). For a machine-word divisor `±2^k·u` with `u` odd, an exact quotient is
/// `(a >> k)·u⁻¹` modulo `2^64` with the sign of the divisor: a shift and a multiplication
/// instead of a hardware division.
///
/// ```
/// use trigpoly::{ExactDivisor, Integer};
/// let d = ExactDivisor::new(&Integer::from(-12));
/// assert_eq!(d.divide(&Integer::from(36)), Integer::from(-3));
/// assert_eq!(d.divide(&Integer::from(-12 * 1_000_000_007i64)), Integer::from(1_000_000_007));
/// ```
#[derive(Clone, Debug)]
pub struct ExactDivisor {
    d: Integer,
    kind: DivisorKind,
}

/// How an [`ExactDivisor`] divides.
#[derive(Clone, Copy, Debug)]
enum DivisorKind {
    /// `|d| ≥ 2` in `i64` range: the shift `k`, the inverse of `u` modulo `2^64`, and whether
    /// `d` is negative.
    Word {
        shift: u32,
        inverse: u64,
        negative: bool,
    },
    /// `d = −1`: a negation.
    MinusOne,
    /// Anything else: the general division.
    General,
}

impl ExactDivisor {
    /// Prepares `d`, which must not be zero.
    ///
    /// A zero `d` is not refused here: [`ExactDivisor::divide`] then panics.
    pub fn new(d: &Integer) -> ExactDivisor {
        let kind = match d.to_i64() {
            Some(-1) => DivisorKind::MinusOne,
            Some(v) if v.unsigned_abs() >= 2 => {
                let shift = v.trailing_zeros();
                let u = v.unsigned_abs() >> shift;
                // Newton's iteration doubles the correct low bits: u·u ≡ 1 (mod 8) to start.
                let mut inverse = u;
                for _ in 0..5 {
                    inverse = inverse.wrapping_mul(2u64.wrapping_sub(u.wrapping_mul(inverse)));
                }
                DivisorKind::Word {
                    shift,
                    inverse,
                    negative: v < 0,
                }
            }
            _ => DivisorKind::General,
        };
        ExactDivisor { d: d.clone(), kind }
    }

    /// `a / d`, for `a` a multiple of `d` (the quotient is wrong otherwise).
    ///
    /// # Panics
    ///
    /// Panics if the divisor was prepared from zero.
    #[inline]
    #[must_use]
    pub fn divide(&self, a: &Integer) -> Integer {
        match (a.small(), self.kind) {
            (
                Some(v),
                DivisorKind::Word {
                    shift,
                    inverse,
                    negative,
                },
            ) => {
                // |d| ≥ 2, so the quotient and its negation are in the word's range.
                let q = (v >> shift).wrapping_mul(inverse as i64);
                Integer::small_unchecked(if negative { -q } else { q })
            }
            (_, DivisorKind::MinusOne) => -a,
            _ => a.div_exact(&self.d),
        }
    }
}

impl Default for Integer {
    fn default() -> Self {
        Integer::ZERO
    }
}

impl From<i64> for Integer {
    #[inline]
    fn from(v: i64) -> Self {
        Integer::from_i64(v)
    }
}

impl From<i32> for Integer {
    fn from(v: i32) -> Self {
        Integer::small_unchecked(v as i64)
    }
}

impl From<u64> for Integer {
    fn from(v: u64) -> Self {
        Integer::from_i128(v as i128)
    }
}

/// `From` for the primitive integers that an `i64` holds, by way of it.
macro_rules! from_via_i64 {
    ($($t:ty),*) => {$(
        impl From<$t> for Integer {
            fn from(v: $t) -> Self {
                Integer::from_i64(i64::from(v))
            }
        }
    )*};
}

/// `From` for the primitive integers that may pass an `i64`, by way of an `i128`.
macro_rules! from_via_i128 {
    ($($t:ty),*) => {$(
        impl From<$t> for Integer {
            fn from(v: $t) -> Self {
                Integer::from_i128(v as i128)
            }
        }
    )*};
}

from_via_i64!(i8, i16, u8, u16, u32);
from_via_i128!(isize, usize, i128);

/// A `u128`, exact past an `i128`: an `Integer` is made from an integer of any primitive type,
/// as num-bigint's `BigInt` is (an unsuffixed literal is an `i32`), each exactly and in the one
/// form of its value: one that fits the word is held there, as `From<i64>` holds it, so that
/// equal values of any type are equal and hash alike.
///
/// ```
/// use std::collections::HashSet;
/// use trigpoly::Integer;
///
/// assert_eq!(Integer::from(3u8) + Integer::from(-4i16), Integer::from(-1));
/// assert_eq!(Integer::from(7usize), Integer::from(7i64));
/// assert_eq!(Integer::from(u64::MAX).to_string(), "18446744073709551615");
/// assert_eq!(Integer::from(u128::MAX).to_string(), u128::MAX.to_string());
/// assert_eq!(Integer::from(i128::MIN).to_string(), i128::MIN.to_string());
/// // One value, of whichever type, is one element of a set.
/// let set: HashSet<Integer> = [
///     Integer::from(5u8),
///     Integer::from(5i128),
///     Integer::from(5u128),
///     Integer::from(5i64),
///     Integer::from(i64::MAX as u128),
///     Integer::from(i64::MAX),
/// ]
/// .into_iter()
/// .collect();
/// assert_eq!(set.len(), 2);
/// ```
impl From<u128> for Integer {
    fn from(v: u128) -> Self {
        match i128::try_from(v) {
            Ok(v) => Integer::from_i128(v),
            Err(_) => Integer::from_bigint(BigInt::from(v)),
        }
    }
}

impl From<BigInt> for Integer {
    fn from(b: BigInt) -> Self {
        Integer::from_bigint(b)
    }
}

impl From<&Integer> for BigInt {
    fn from(v: &Integer) -> Self {
        v.to_bigint()
    }
}

impl Ord for Integer {
    fn cmp(&self, other: &Self) -> Ordering {
        match (self.small(), other.small()) {
            (Some(a), Some(b)) => a.cmp(&b),
            _ => match (self.to_i128(), other.to_i128()) {
                (Some(a), Some(b)) => a.cmp(&b),
                _ => self.to_bigint().cmp(&other.to_bigint()),
            },
        }
    }
}

impl PartialOrd for Integer {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Display for Integer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.view() {
            IntegerView::Small(v) => write!(f, "{v}"),
            IntegerView::Wide(v) => write!(f, "{v}"),
            IntegerView::Big(b) => write!(f, "{b}"),
        }
    }
}

impl fmt::Debug for Integer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl FromStr for Integer {
    type Err = num_bigint::ParseBigIntError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Ok(Integer::from_bigint(s.parse()?))
    }
}

// a + b, a - b, a * b: machine path with overflow check, else BigInt.
#[inline]
fn add_ref(a: &Integer, b: &Integer) -> Integer {
    match (a.small(), b.small()) {
        // Two values of 63 bits: the sum has 64.
        (Some(x), Some(y)) => Integer::from_i64(x + y),
        _ => wide_or_big(a, b, i128::checked_add, |a, b| a + b),
    }
}

fn sub_ref(a: &Integer, b: &Integer) -> Integer {
    match (a.small(), b.small()) {
        (Some(x), Some(y)) => Integer::from_i64(x - y),
        _ => wide_or_big(a, b, i128::checked_sub, |a, b| a - b),
    }
}

#[inline]
fn mul_ref(a: &Integer, b: &Integer) -> Integer {
    match (a.small(), b.small()) {
        // Two values of 63 bits: the product has at most 125.
        (Some(x), Some(y)) => Integer::from_i128(x as i128 * y as i128),
        _ => wide_or_big(a, b, i128::checked_mul, |a, b| a * b),
    }
}

/// An operation with at least one operand outside `i64` range: in `i128` when both operands
/// and the result fit, else in `BigInt`.
#[cold]
fn wide_or_big(
    a: &Integer,
    b: &Integer,
    machine: fn(i128, i128) -> Option<i128>,
    big: fn(BigInt, BigInt) -> BigInt,
) -> Integer {
    match (a.to_i128(), b.to_i128()) {
        (Some(x), Some(y)) => Integer::from_i128_op(x, y, machine, big),
        _ => Integer::from_bigint(big(a.to_bigint(), b.to_bigint())),
    }
}

macro_rules! forward_binop {
    ($Trait:ident, $method:ident, $Assign:ident, $assign:ident, $f:ident) => {
        impl $Trait<&Integer> for &Integer {
            type Output = Integer;
            fn $method(self, rhs: &Integer) -> Integer {
                $f(self, rhs)
            }
        }
        impl $Trait<Integer> for &Integer {
            type Output = Integer;
            fn $method(self, rhs: Integer) -> Integer {
                $f(self, &rhs)
            }
        }
        impl $Trait<&Integer> for Integer {
            type Output = Integer;
            fn $method(self, rhs: &Integer) -> Integer {
                $f(&self, rhs)
            }
        }
        impl $Trait<Integer> for Integer {
            type Output = Integer;
            fn $method(self, rhs: Integer) -> Integer {
                $f(&self, &rhs)
            }
        }
        impl $Assign<&Integer> for Integer {
            fn $assign(&mut self, rhs: &Integer) {
                *self = $f(self, rhs);
            }
        }
        impl $Assign<Integer> for Integer {
            fn $assign(&mut self, rhs: Integer) {
                *self = $f(self, &rhs);
            }
        }
    };
}

forward_binop!(Add, add, AddAssign, add_assign, add_ref);
forward_binop!(Sub, sub, SubAssign, sub_assign, sub_ref);
forward_binop!(Mul, mul, MulAssign, mul_assign, mul_ref);

impl Neg for &Integer {
    type Output = Integer;
    #[inline]
    fn neg(self) -> Integer {
        match self.small() {
            // −2⁶² negates to 2⁶², past the word: `from_i64` boxes it.
            Some(v) => Integer::from_i64(-v),
            None => neg_wide_or_big(self),
        }
    }
}

/// `−a` for a boxed `a`.
#[cold]
fn neg_wide_or_big(a: &Integer) -> Integer {
    match a.to_i128() {
        Some(v) => match v.checked_neg() {
            Some(n) => Integer::from_i128(n),
            None => Integer::from_bigint(-BigInt::from(v)),
        },
        None => Integer::from_bigint(-a.to_bigint()),
    }
}

impl Neg for Integer {
    type Output = Integer;
    fn neg(self) -> Integer {
        -&self
    }
}

impl Zero for Integer {
    fn zero() -> Self {
        Integer::ZERO
    }
    fn is_zero(&self) -> bool {
        Integer::is_zero(self)
    }
}

impl One for Integer {
    fn one() -> Self {
        Integer::ONE
    }
}

/// An accumulator for sums of products `Σ a_k b_k` of integers: products of words in an `i128`
/// while it fits; products of values up to `i128` (the `Wide` tier) in a 256-bit two's
/// complement sum; `BigInt` for the rest. This is what keeps multiplication free of allocations
/// for small coefficients, and the square of a polynomial with 70-bit coefficients free of
/// `BigInt` products.
#[derive(Clone, Debug, Default)]
pub struct IntegerAcc {
    small: i128,
    long: Long,
}

/// The part of an [`IntegerAcc`]'s sum past the `i128`.
#[derive(Clone, Debug, Default)]
enum Long {
    /// Nothing yet (a tag to test, so a short sum costs no more than an `i128`).
    #[default]
    Zero,
    /// Products of values up to `i128`, in 256 bits.
    Wide(Wide256),
    /// Past 256 bits, or with a factor past `i128`.
    Big(BigInt),
}

/// A 192-bit two's complement integer in three words, least significant first: the broad
/// accumulators of the dense product ([`IntegerRing::Broad`](super::IntegerRing::Broad)),
/// which add products of coefficients of one or two words (FLINT's three-word sums). Public
/// only as that associated type is (the crate does not export it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Wide192([u64; 3]);

impl Wide192 {
    /// The most bits of a value's magnitude that a sum may reach: it stays below `2¹⁹¹`.
    pub(crate) const BITS: u32 = 190;

    /// `self += x·y` modulo `2¹⁹²` (exact when the sum fits, which the caller guarantees).
    #[inline(always)]
    pub(crate) fn add_mul_words(&mut self, x: i64, y: i64) {
        self.add(i128::from(x) * i128::from(y));
    }

    /// `self += v` modulo `2¹⁹²`.
    #[inline(always)]
    pub(crate) fn add(&mut self, v: i128) {
        self.add_low(v as u128, (v >> 127) as u64);
    }

    /// `self += x·y` modulo `2¹⁹²` for factors of two words, `x = x₁·2⁶⁴ + x₀` with `x₁`
    /// signed and `x₀` not: `x₀y₀`, then `(x₁y₀ + x₀y₁)·2⁶⁴`, then the low word of `x₁y₁`
    /// at `2¹²⁸` (its high word is past 192 bits).
    #[inline(always)]
    pub(crate) fn add_mul_double(&mut self, x: i128, y: i128) {
        let (x1, x0) = ((x >> 64) as i64, x as u64);
        let (y1, y0) = ((y >> 64) as i64, y as u64);
        self.add_low(u128::from(x0) * u128::from(y0), 0);
        self.add_shifted((i128::from(x1) * i128::from(y0)) as u128);
        self.add_shifted((i128::from(x0) * i128::from(y1)) as u128);
        self.0[2] = self.0[2].wrapping_add(x1.wrapping_mul(y1) as u64);
    }

    /// Adds the 128 bits `v` to the two low words, and `above` (all ones to extend a
    /// negative `v`, else 0) to the top one, modulo `2¹⁹²`.
    #[inline(always)]
    fn add_low(&mut self, v: u128, above: u64) {
        let w = &mut self.0;
        let (w0, c0) = w[0].overflowing_add(v as u64);
        let (w1, c1) = w[1].overflowing_add((v >> 64) as u64);
        let (w1, c2) = w1.overflowing_add(u64::from(c0));
        w[0] = w0;
        w[1] = w1;
        w[2] = w[2]
            .wrapping_add(above)
            .wrapping_add(u64::from(c1) + u64::from(c2));
    }

    /// Adds `v·2⁶⁴` modulo `2¹⁹²`: `v`'s two words to the two high ones (its sign past 192
    /// bits does not count).
    #[inline(always)]
    fn add_shifted(&mut self, v: u128) {
        let w = &mut self.0;
        let (w1, c1) = w[1].overflowing_add(v as u64);
        w[1] = w1;
        w[2] = w[2]
            .wrapping_add((v >> 64) as u64)
            .wrapping_add(u64::from(c1));
    }

    /// The value.
    pub(crate) fn to_integer(self) -> Integer {
        let [w0, w1, w2] = self.0;
        let low = (u128::from(w1) << 64 | u128::from(w0)) as i128;
        if w2 == (low >> 127) as u64 {
            Integer::from_i128(low)
        } else {
            let high = BigInt::from(w2 as i64) << 128;
            Integer::from_bigint(high + BigInt::from(low as u128))
        }
    }
}

/// A 256-bit two's complement integer `high·2¹²⁸ + low`: the sums of products of `i128`s in
/// [`IntegerAcc`], and the sums of the hashed product for coefficients past a word.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Wide256 {
    low: u128,
    high: i128,
}

impl Wide256 {
    /// `self += x·y` modulo 2²⁵⁶ (exact when the sum fits, which the caller guarantees; a
    /// partial sum may wrap on the way). Factors that both fit a word take one product;
    /// others are split at 64 bits, `x = x₁·2⁶⁴ + x₀` with `x₁` signed and `x₀` not, so that
    /// each of the four partial products fits an `i128` or a `u128`.
    #[inline(always)]
    pub(crate) fn add_mul(&mut self, x: i128, y: i128) {
        // Factors that fit a word (most, in most sums): one product, sign-extended.
        if i128::from(x as i64) == x && i128::from(y as i64) == y {
            let p = x * y;
            let (low, carry) = self.low.overflowing_add(p as u128);
            self.low = low;
            self.high = self.high.wrapping_add(i128::from(carry) + (p >> 127));
            return;
        }
        let (x1, x0) = (i128::from((x >> 64) as i64), x as u64);
        let (y1, y0) = (i128::from((y >> 64) as i64), y as u64);
        let (low, carry) = self.low.overflowing_add(u128::from(x0) * u128::from(y0));
        self.low = low;
        self.high = self.high.wrapping_add(i128::from(carry) + x1 * y1);
        self.add_shifted(x1 * i128::from(y0));
        self.add_shifted(y1 * i128::from(x0));
    }

    /// `self += v·2⁶⁴`.
    #[inline(always)]
    fn add_shifted(&mut self, v: i128) {
        let (low, carry) = self.low.overflowing_add((v as u128) << 64);
        self.low = low;
        self.high = self.high.wrapping_add((v >> 64) + i128::from(carry));
    }

    /// The value.
    pub(crate) fn to_integer(self) -> Integer {
        if self.high == (self.low as i128) >> 127 {
            Integer::from_i128(self.low as i128)
        } else {
            Integer::from_bigint(self.to_bigint())
        }
    }

    /// `v`, sign-extended.
    fn from_i128(v: i128) -> Wide256 {
        Wide256 {
            low: v as u128,
            high: v >> 127,
        }
    }

    /// `x·y` (at most `2²⁵⁴` in magnitude, so it always fits): the multiply-add from zero.
    fn product(x: i128, y: i128) -> Wide256 {
        let mut p = Wide256::default();
        p.add_mul(x, y);
        p
    }

    /// `−self` (never overflows for a product's magnitude, below `2²⁵⁴`).
    fn negated(self) -> Wide256 {
        let low = (!self.low).wrapping_add(1);
        Wide256 {
            low,
            high: (!self.high).wrapping_add(i128::from(low == 0)),
        }
    }

    /// `self + v`, or `None` past 256 bits.
    fn checked_add(self, v: Wide256) -> Option<Wide256> {
        let (low, carry) = self.low.overflowing_add(v.low);
        let high = self
            .high
            .checked_add(v.high)?
            .checked_add(i128::from(carry))?;
        Some(Wide256 { low, high })
    }

    fn to_bigint(self) -> BigInt {
        (BigInt::from(self.high) << 128) + BigInt::from(self.low)
    }
}

impl IntegerAcc {
    /// `acc += a * b`.
    #[inline]
    pub fn add_mul(&mut self, a: &Integer, b: &Integer) {
        if let (Some(x), Some(y)) = (a.small(), b.small()) {
            let p = x as i128 * y as i128;
            match self.small.checked_add(p) {
                Some(s) => self.small = s,
                None => self.add_wide(Wide256::from_i128(p)),
            }
        } else {
            self.add_mul_wide(a, b, false);
        }
    }

    /// `acc += a`.
    #[inline]
    pub fn add(&mut self, a: &Integer) {
        match a.view() {
            IntegerView::Small(x) => match self.small.checked_add(x as i128) {
                Some(s) => self.small = s,
                None => self.add_wide(Wide256::from_i128(i128::from(x))),
            },
            IntegerView::Wide(v) => match self.small.checked_add(v) {
                Some(s) => self.small = s,
                None => self.add_wide(Wide256::from_i128(v)),
            },
            IntegerView::Big(b) => self.spill(b.clone()),
        }
    }

    /// `acc -= a * b`.
    #[inline]
    pub fn sub_mul(&mut self, a: &Integer, b: &Integer) {
        if let (Some(x), Some(y)) = (a.small(), b.small()) {
            let p = x as i128 * y as i128;
            match self.small.checked_sub(p) {
                Some(s) => self.small = s,
                None => self.add_wide(Wide256::from_i128(p).negated()),
            }
        } else {
            self.add_mul_wide(a, b, true);
        }
    }

    /// `acc ±= a * b` for factors past a word: in 256 bits when both fit an `i128`.
    #[cold]
    fn add_mul_wide(&mut self, a: &Integer, b: &Integer, negate: bool) {
        match (a.to_i128(), b.to_i128()) {
            (Some(x), Some(y)) => {
                let p = Wide256::product(x, y);
                self.add_wide(if negate { p.negated() } else { p });
            }
            _ => {
                let p = a.to_bigint() * b.to_bigint();
                self.spill(if negate { -p } else { p });
            }
        }
    }

    /// `acc += v` in the 256-bit tier, or as a `BigInt` past it.
    #[cold]
    fn add_wide(&mut self, v: Wide256) {
        match &mut self.long {
            Long::Zero => self.long = Long::Wide(v),
            Long::Wide(w) => match w.checked_add(v) {
                Some(sum) => *w = sum,
                None => self.long = Long::Big(w.to_bigint() + v.to_bigint()),
            },
            Long::Big(b) => *b += v.to_bigint(),
        }
    }

    #[cold]
    fn spill(&mut self, v: BigInt) {
        match &mut self.long {
            Long::Zero => self.long = Long::Big(v),
            Long::Wide(w) => self.long = Long::Big(w.to_bigint() + v),
            Long::Big(b) => *b += v,
        }
    }

    /// The accumulated value.
    #[inline]
    #[must_use]
    pub fn finish(self) -> Integer {
        match self.long {
            Long::Zero => Integer::from_i128(self.small),
            long => Integer::from_bigint(Self::long_sum(self.small, long)),
        }
    }

    /// Whether the accumulated value is zero.
    #[inline]
    pub fn is_zero(&self) -> bool {
        match &self.long {
            Long::Zero => self.small == 0,
            long => Self::long_sum(self.small, long.clone()).is_zero(),
        }
    }

    /// The value of a sum that passed the `i128`.
    #[cold]
    fn long_sum(small: i128, long: Long) -> BigInt {
        let long = match long {
            Long::Zero => BigInt::zero(),
            Long::Wide(w) => w.to_bigint(),
            Long::Big(b) => b,
        };
        long + BigInt::from(small)
    }
}

#[cfg(test)]
mod tests {
    use super::word::SLOTS_PER_BLOCK;
    use super::{
        Integer, IntegerAcc, IntegerView, Release, SlotCounts, Wide192, Wide256, WideSlab,
    };
    use num_bigint::BigInt;
    use std::collections::HashSet;

    /// The values either side of every boundary between the word, the boxed `i128` and the
    /// boxed `BigInt`, and of `i64`'s range.
    fn edges() -> Vec<BigInt> {
        let word = 1i128 << 62;
        let mut v: Vec<BigInt> = [0, 1, -1, word, i64::MAX as i128 + 1, i128::MAX]
            .iter()
            .flat_map(|&e| [e, -e, e - 1, -e + 1, e.saturating_add(1), -e - 1])
            .map(BigInt::from)
            .collect();
        let past: BigInt = BigInt::from(i128::MAX) + 1u32;
        v.extend([
            past.clone(),
            -past.clone() - 1u32,
            -past,
            BigInt::from(3u32).pow(200u32),
        ]);
        v
    }

    /// `Release`, which the public trait `IntegerRing` names, has a `Debug` as every public
    /// type does (`missing_debug_implementations` is denied): its current run, none before a
    /// value in a slot is taken, and none after a word or a boxed value.
    #[test]
    fn a_release_shows_its_run() {
        let mut release = Release::default();
        assert_eq!(format!("{release:?}"), "Release { block: None, count: 0 }");
        release.take(Integer::from(7));
        release.take(Integer::from(BigInt::from(3u32).pow(100u32)));
        assert_eq!(format!("{release:?}"), "Release { block: None, count: 0 }");
    }

    #[test]
    fn an_integer_is_one_word() {
        assert_eq!(std::mem::size_of::<Integer>(), 8);
        assert_eq!(std::mem::size_of::<Option<Integer>>(), 8);
    }

    /// Every value is held where its size says (the word for 63 bits, a boxed `i128` up to
    /// `i128`'s range, a boxed `BigInt` beyond), however it was built, and reads back as
    /// itself.
    #[test]
    fn values_are_held_canonically_and_read_back() {
        let word = -(1i128 << 62)..(1i128 << 62);
        for b in edges() {
            let direct = Integer::from_bigint(b.clone());
            // The same value reached by arithmetic from a different tier.
            let reached = &(&direct + &Integer::from(3)) - &Integer::from(3);
            for v in [&direct, &reached, &direct.clone()] {
                assert_eq!(v.to_bigint(), b);
                match (v.view(), i128::try_from(&b)) {
                    (IntegerView::Small(s), Ok(x)) => {
                        assert!(word.contains(&x));
                        assert_eq!(s as i128, x);
                    }
                    (IntegerView::Wide(w), Ok(x)) => {
                        assert!(!word.contains(&x));
                        assert_eq!(w, x);
                    }
                    (IntegerView::Big(big), Err(_)) => assert_eq!(big, &b),
                    (view, _) => panic!("{b} held as {view:?}"),
                }
                assert_eq!(v.to_i64(), i64::try_from(&b).ok());
                assert_eq!(v.to_i128(), i128::try_from(&b).ok());
            }
            assert_eq!(direct, reached);
        }
    }

    /// Equal values are equal and hash alike, distinct ones are not equal, across the tiers;
    /// clones and drops of boxed values leave the originals intact.
    #[test]
    fn equality_hashing_clones_and_drops_follow_the_value() {
        let values: Vec<Integer> = edges().into_iter().map(Integer::from_bigint).collect();
        let distinct: HashSet<BigInt> = edges().into_iter().collect();
        let set: HashSet<Integer> = values.iter().cloned().collect();
        assert_eq!(set.len(), distinct.len());
        for a in &values {
            assert!(set.contains(&a.clone()));
            for b in &values {
                assert_eq!(a == b, a.to_bigint() == b.to_bigint(), "{a} {b}");
                assert_eq!(a.cmp(b), a.to_bigint().cmp(&b.to_bigint()), "{a} {b}");
            }
            let copy = a.clone();
            drop(a.clone());
            assert_eq!(&copy, a);
        }
    }

    /// Values past the word made while a slab is filling lie in its slots, over three blocks,
    /// and read, compare, hash, clone and compute as boxed ones do; small values and those
    /// past `i128` do not. They outlive the slab and are dropped one by one, in runs by a
    /// `Release` mixed with every other kind, and on another thread, in no block's order.
    /// Under Miri (see the module's documentation) a block freed too early is a read after
    /// its free, and one never freed a leak.
    #[test]
    fn values_in_a_slab_behave_as_boxed_ones_and_free_their_blocks() {
        use std::hash::{BuildHasher, RandomState};
        let n = 2 * SLOTS_PER_BLOCK as i128 + 10;
        let wide = |k: i128| (1i128 << 62) + 1 + 7919 * k;
        let big = Integer::from_bigint(num_bigint::BigInt::from(i128::MAX) * 5);
        let mut slab = WideSlab::new();
        let (slotted, others) = slab.filling(|| {
            let slotted: Vec<Integer> = (0..n)
                .map(|k| Integer::from_i128(if k % 3 == 0 { -wide(k) } else { wide(k) }))
                .collect();
            (slotted, [Integer::from(5), big.clone(), &big - &big])
        });
        drop(slab);
        assert!(others.iter().all(|i| !i.in_slot()));
        let hasher = RandomState::new();
        for (k, s) in (0..n).zip(&slotted) {
            let value = if k % 3 == 0 { -wide(k) } else { wide(k) };
            let boxed = Integer::from_i128(value);
            assert!(s.in_slot() && !boxed.in_slot());
            assert_eq!(s.view(), IntegerView::Wide(value));
            assert_eq!((s, hasher.hash_one(s)), (&boxed, hasher.hash_one(&boxed)));
            let copy = s.clone();
            assert!(!copy.in_slot());
            assert_eq!(copy, *s);
            assert_eq!(&(s + &Integer::ONE) - &boxed, Integer::ONE);
        }
        // A run for each block and each kind: counts given back block by block, in an order
        // that visits every block twice.
        let mut parts: Vec<Vec<Integer>> = vec![Vec::new(); 4];
        for (k, s) in slotted.into_iter().enumerate() {
            parts[k % 4].push(s);
        }
        let (mut one_by_one, mut released, elsewhere, kept) = {
            let mut it = parts.into_iter();
            let mut next = || it.next().unwrap_or_default();
            (next(), next(), next(), next())
        };
        one_by_one.reverse();
        drop(one_by_one);
        released.extend(others);
        released.push(Integer::from_i128(wide(n)));
        let mut release = Release::default();
        for i in released {
            release.take(i);
        }
        drop(release);
        let on_another = std::thread::spawn(move || elsewhere.into_iter().map(|i| i.to_i128()));
        let read = on_another.join().expect("the thread ends").count();
        // The indices below n that leave 2 modulo 4.
        assert_eq!(read, (n as usize + 1) / 4);
        // The values kept still read as themselves after all the others went.
        for (j, i) in kept.iter().enumerate() {
            let k = (4 * j + 3) as i128;
            let value = if k % 3 == 0 { -wide(k) } else { wide(k) };
            assert_eq!(i.to_i128(), Some(value));
        }
    }

    /// A slab's counts, taken once it is filled, are those of the values alive in it: values
    /// made and dropped while it filled are left out, small ones need none, and a block all
    /// of whose values went is freed when the counts are taken. The vector is then dropped
    /// through the counts, with no pass over its values. A `BigInt` made while it filled
    /// leaves counts that cannot drop the vector, which is then dropped as usual. Under Miri,
    /// a count given back twice is a read after a free, and one never given back a leak.
    #[test]
    fn a_filled_slabs_counts_drop_its_vector() {
        let wide = |k: i128| (1i128 << 62) + 1 + 7919 * k;
        let n = 2 * SLOTS_PER_BLOCK as i128 + 10;
        let second = SLOTS_PER_BLOCK as i128..2 * SLOTS_PER_BLOCK as i128;
        let temporary = |k: i128| k % 5 == 0 || second.contains(&k);
        let mut slab = WideSlab::new();
        let values = slab.filling(|| {
            let mut values = Vec::new();
            for k in 0..n {
                let w = Integer::from_i128(wide(k));
                // Every fifth a temporary, and the whole second block.
                if temporary(k) {
                    drop(w);
                    values.push(Integer::from(k as i64));
                } else {
                    values.push(w);
                }
            }
            values
        });
        // SAFETY: the slab was filled for `values` alone, on this thread.
        let counts = unsafe { slab.into_counts() };
        assert!(counts.can_release());
        let in_slots = values.iter().filter(|i| i.in_slot()).count();
        // The first and third blocks; the second was freed with its last value.
        assert_eq!(counts.counted(), (2, in_slots));
        // The values read as themselves up to the drop.
        let sum: i128 = values.iter().filter_map(Integer::to_i128).sum();
        let expected: i128 = (0..n).map(|k| if temporary(k) { k } else { wide(k) }).sum();
        assert_eq!(sum, expected);
        // SAFETY: the counts are those of `values`, unchanged since.
        unsafe { counts.release(values) };

        let mut slab = WideSlab::new();
        let values = slab.filling(|| {
            vec![
                Integer::from_i128(wide(1)),
                Integer::from_bigint(BigInt::from(i128::MAX) * 3),
            ]
        });
        // SAFETY: as above.
        let counts = unsafe { slab.into_counts() };
        assert!(!counts.can_release());
        // SAFETY: as above; the counts cannot drop it, so it is dropped as usual.
        unsafe { counts.release(values) };
        let none = SlotCounts::default();
        assert!(none.can_release());
    }

    /// A value placed straight in a slab its caller holds (`place_integer`, as a dense
    /// product's builder places its sums) is the one `from_i128` makes while the slab fills:
    /// in a slot, equal, hashed alike, and counted with the others when the counts are
    /// taken; a small value never reaches the slab. Under Miri, a slot given out twice or a
    /// count lost shows.
    #[test]
    fn a_value_placed_in_a_held_slab_is_one_made_while_it_fills() {
        use std::hash::{BuildHasher, RandomState};
        let v = (1i128 << 62) + 12_345;
        let mut slab = WideSlab::new();
        let filled = slab.filling(|| Integer::from_i128(-v));
        let mut place = |x| slab.place_integer(x);
        let placed = Integer::from_i128_with(v, &mut place);
        let small = Integer::from_i128_with(5, &mut place);
        let again = Integer::from_i128_with(-v, &mut place);
        assert!(placed.in_slot() && filled.in_slot() && again.in_slot() && !small.in_slot());
        assert_eq!(placed.view(), IntegerView::Wide(v));
        assert_eq!(small, Integer::from(5));
        assert_eq!(&placed + &filled, Integer::ZERO);
        let hasher = RandomState::new();
        assert_eq!(hasher.hash_one(&again), hasher.hash_one(&filled));
        let values = vec![filled, placed, small, again];
        // SAFETY: the slab was filled and placed in for `values` alone, on this thread.
        let counts = unsafe { slab.into_counts() };
        assert_eq!(counts.counted(), (1, 3));
        // SAFETY: the counts are those of `values`, unchanged since.
        unsafe { counts.release(values) };
    }

    /// The constants are the small values they name, and the negation of the word's least
    /// value leaves the word.
    #[test]
    fn constants_and_the_words_edge_under_negation() {
        assert_eq!(Integer::ZERO.view(), IntegerView::Small(0));
        assert_eq!(Integer::ONE.view(), IntegerView::Small(1));
        let least = Integer::from(-(1i64 << 62));
        assert_eq!(least.view(), IntegerView::Small(-(1 << 62)));
        assert_eq!((-&least).view(), IntegerView::Wide(1 << 62));
        assert_eq!(-(-&least), least);
    }

    /// The accumulator through every pair of edge values, each row on a fresh accumulator (so
    /// that its sum climbs the tiers in order) and then all rows in one, added and subtracted
    /// in turn; and the 256-bit tier's own edge: `(−2¹²⁷)² = 2²⁵⁴`, twice, passes its signed
    /// range, and the sum must go on in a `BigInt`, up and back down.
    #[test]
    fn the_accumulator_sums_edge_products_exactly() {
        let least = Integer::from(BigInt::from(i128::MIN));
        let square = BigInt::from(i128::MIN) * BigInt::from(i128::MIN);
        let mut acc = IntegerAcc::default();
        let mut want = BigInt::from(0);
        for k in 0..6 {
            if k < 3 {
                acc.add_mul(&least, &least);
                want += &square;
            } else {
                acc.sub_mul(&least, &least);
                want -= &square;
            }
            assert_eq!(acc.clone().finish().to_bigint(), want, "after {k} squares");
        }
        assert!(acc.is_zero());
        let values = edges();
        let mut all = IntegerAcc::default();
        let mut all_want = BigInt::from(0);
        for (k, a) in values.iter().enumerate() {
            let mut row = IntegerAcc::default();
            let mut row_want = BigInt::from(0);
            for b in &values {
                let (x, y) = (Integer::from(a.clone()), Integer::from(b.clone()));
                let p = a * b;
                if k % 2 == 0 {
                    row.add_mul(&x, &y);
                    all.add_mul(&x, &y);
                    row_want += &p;
                    all_want += p;
                } else {
                    row.sub_mul(&x, &y);
                    all.sub_mul(&x, &y);
                    row_want -= &p;
                    all_want -= p;
                }
            }
            assert_eq!(row.is_zero(), row_want == BigInt::from(0));
            assert_eq!(row.finish().to_bigint(), row_want, "row {k}");
        }
        assert_eq!(all.finish().to_bigint(), all_want);
    }

    /// The branch-free 256-bit multiply-add through every pair of `i128` edge values (the
    /// halves' signs and carries at 2⁶⁴ and 2¹²⁷ included), each row summed alone and all in
    /// a running sum (rows of `e` and `−e` follow each other, so it climbs past the `i128`
    /// and comes back), each read back.
    #[test]
    fn the_256_bit_sum_adds_products_of_i128_edges_exactly() {
        let values: Vec<i128> = edges()
            .iter()
            .filter_map(|v| i128::try_from(v).ok())
            .filter(|&v| v != i128::MIN)
            .chain([
                1 << 64,
                -(1 << 64),
                (1 << 64) - 1,
                0x1234_5678_9abc_def0_1122,
            ])
            .collect();
        let mut running = Wide256::default();
        let mut running_want = BigInt::from(0);
        for &x in &values {
            let mut row = Wide256::default();
            let mut row_want = BigInt::from(0);
            for &y in &values {
                row.add_mul(x, y);
                running.add_mul(x, y);
                let p = BigInt::from(x) * BigInt::from(y);
                row_want += &p;
                running_want += p;
            }
            assert_eq!(row.to_integer().to_bigint(), row_want, "row {x}");
            assert_eq!(
                running.to_integer().to_bigint(),
                running_want,
                "after row {x}"
            );
        }
        // x·y − x·y: back to zero, and a sum that fits an i128 read back as one.
        let mut sum = Wide256::default();
        sum.add_mul(i128::MAX, i128::MAX);
        sum.add_mul(-i128::MAX, i128::MAX);
        sum.add_mul(-3, 1 << 100);
        assert_eq!(sum.to_integer(), Integer::from_i128(-3 << 100));
    }

    /// The 192-bit sum adds products of words and of two words (at most `2⁹³` in magnitude,
    /// summing to less than `2⁹⁵`, so that every partial sum of their products stays below
    /// `2¹⁹¹`), of both signs, exactly, and reads back sums on both sides of `i128` and of
    /// zero.
    #[test]
    fn the_192_bit_sum_adds_products_of_words_and_of_two_words_exactly() {
        let words: Vec<i64> = [
            0,
            1,
            -1,
            i64::MAX,
            i64::MIN,
            i64::MIN + 1,
            1 << 62,
            -(1 << 62),
        ]
        .into_iter()
        .chain([0x1234_5678_9abc_def0, -0x7654_3210_fedc_ba98])
        .collect();
        let doubles: Vec<i128> = words
            .iter()
            .map(|&w| i128::from(w))
            .chain([
                1 << 64,
                -(1 << 64),
                (1 << 93) - 1,
                -(1 << 93),
                0x1234_5678_9abc_def0_1122,
            ])
            .collect();
        let mut sum = Wide192::default();
        let mut want = BigInt::from(0);
        for &x in &words {
            for &y in &words {
                sum.add_mul_words(x, y);
                want += BigInt::from(x) * BigInt::from(y);
                assert_eq!(sum.to_integer().to_bigint(), want, "{x}·{y}");
            }
        }
        for &x in &doubles {
            for &y in &doubles {
                sum.add_mul_double(x, y);
                want += BigInt::from(x) * BigInt::from(y);
                assert_eq!(sum.to_integer().to_bigint(), want, "{x}·{y}");
            }
        }
        // Past i128 and back: 2¹⁸⁸ − 2¹⁸⁸ + x is x, read back as one word.
        let mut sum = Wide192::default();
        sum.add_mul_double(1 << 94, 1 << 94);
        assert_eq!(sum.to_integer().to_bigint(), BigInt::from(1) << 188u32);
        sum.add_mul_double(-(1 << 94), 1 << 94);
        sum.add_mul_words(-7, 3);
        assert_eq!(sum.to_integer(), Integer::from_i128(-21));
    }
}
