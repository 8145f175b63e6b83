//! `Integer`: a machine integer that becomes a big integer only when it has to.
//!
//! Every value that fits an `i64` is stored as `Small`, every other value that fits an `i128`
//! as `Wide` (one 16-byte allocation, where a `BigInt` takes two), and only the rest as `Big`,
//! so equality and hashing are structural. Each operation tries the machine path with exact
//! overflow detection (`checked_*`, `i128` intermediates) and falls back to
//! `num_bigint::BigInt`.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::str::FromStr;

use super::gcd::{binary_gcd, gcd_u128};
use num_bigint::BigInt;
use num_integer::Integer as _;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// An exact integer: `i64` when it fits, else `i128` when that fits, else `BigInt`.
///
/// Invariant: `Wide` never holds a value that fits in `i64`, and `Big` never one that fits in
/// `i128`.
///
/// ```
/// use trigpoly::Integer;
/// let big = Integer::from(i64::MAX) + Integer::from(1);
/// assert_eq!(big.to_string(), "9223372036854775808");
/// assert_eq!(big - Integer::from(1), Integer::from(i64::MAX));
/// ```
#[derive(PartialEq, Eq, Hash)]
pub enum Integer {
    /// A value in `i64` range.
    Small(i64),
    /// A value outside `i64` range but inside `i128` range (sums of products of `i64`s, the
    /// coefficients of most large products).
    Wide(Box<i128>),
    /// A value outside `i128` range.
    Big(Box<BigInt>),
}

/// Written out so that the common case, a `Small` value, is a copy inlined at the call (the
/// derived clone is a call that matches every variant).
impl Clone for Integer {
    #[inline]
    fn clone(&self) -> Self {
        match self {
            Integer::Small(v) => Integer::Small(*v),
            boxed => boxed.clone_boxed(),
        }
    }
}

impl Integer {
    #[inline(never)]
    fn clone_boxed(&self) -> Self {
        match self {
            Integer::Small(v) => Integer::Small(*v),
            Integer::Wide(v) => Integer::Wide(v.clone()),
            Integer::Big(b) => Integer::Big(b.clone()),
        }
    }

    /// Zero.
    pub const ZERO: Integer = Integer::Small(0);
    /// One.
    pub const ONE: Integer = Integer::Small(1);

    /// Whether the value is zero.
    pub fn is_zero(&self) -> bool {
        matches!(self, Integer::Small(0))
    }

    /// Whether the value is one.
    pub fn is_one(&self) -> bool {
        matches!(self, Integer::Small(1))
    }

    /// The sign: -1, 0 or 1.
    pub fn signum(&self) -> i32 {
        match self {
            Integer::Small(v) => v.signum() as i32,
            Integer::Wide(v) => v.signum() as i32,
            Integer::Big(b) => {
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
    pub fn to_i64(&self) -> Option<i64> {
        match self {
            Integer::Small(v) => Some(*v),
            Integer::Wide(_) | Integer::Big(_) => None,
        }
    }

    /// The value as `i128`, if it fits.
    #[inline]
    pub fn to_i128(&self) -> Option<i128> {
        match self {
            Integer::Small(v) => Some(*v as i128),
            Integer::Wide(v) => Some(**v),
            Integer::Big(_) => None,
        }
    }

    /// The value as a `BigInt`.
    pub fn to_bigint(&self) -> BigInt {
        match self {
            Integer::Small(v) => BigInt::from(*v),
            Integer::Wide(v) => BigInt::from(**v),
            Integer::Big(b) => (**b).clone(),
        }
    }

    /// Builds from an `i128`, staying small when it fits.
    #[inline]
    pub fn from_i128(v: i128) -> Integer {
        match i64::try_from(v) {
            Ok(s) => Integer::Small(s),
            Err(_) => Integer::Wide(Box::new(v)),
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
            None => Integer::Big(Box::new(b)),
        }
    }

    /// Absolute value.
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
    pub fn gcd(&self, other: &Integer) -> Integer {
        match (self, other) {
            (Integer::Small(a), Integer::Small(b)) => {
                Integer::from(binary_gcd(a.unsigned_abs(), b.unsigned_abs()))
            }
            _ => self.gcd_long(other),
        }
    }

    /// [`Integer::gcd`] when a side is longer than an `i64` (out of line, so that the short
    /// case inlines).
    #[inline(never)]
    fn gcd_long(&self, other: &Integer) -> Integer {
        let word = |v: &Integer| v.to_i128().expect("not Big").unsigned_abs();
        match (self, other) {
            (Integer::Big(b), Integer::Big(c)) => Integer::from_bigint(b.gcd(c)),
            (Integer::Big(b), short) | (short, Integer::Big(b)) => {
                let a = word(short);
                if a == 0 {
                    return Integer::Big(Box::new(b.abs()));
                }
                let r = (b.magnitude() % a).to_u128().expect("below a u128");
                Integer::from_u128(gcd_u128(a, r))
            }
            _ => Integer::from_u128(gcd_u128(word(self), word(other))),
        }
    }

    /// Builds from a `u128` (above `i128::MAX` only as the gcd `2^127` of `i128::MIN`).
    fn from_u128(v: u128) -> Integer {
        match i128::try_from(v) {
            Ok(v) => Integer::from_i128(v),
            Err(_) => Integer::from_bigint(BigInt::from(v)),
        }
    }

    /// Least common multiple, always `>= 0`.
    pub fn lcm(&self, other: &Integer) -> Integer {
        if self.is_zero() || other.is_zero() {
            return Integer::ZERO;
        }
        let g = self.gcd(other);
        (self.div_exact(&g) * other).abs()
    }

    /// Exact division.
    ///
    /// Panics if `d` is zero; the result is only meaningful when `d` divides `self`.
    pub fn div_exact(&self, d: &Integer) -> Integer {
        match (self, d) {
            (Integer::Small(a), Integer::Small(b)) => match a.checked_div(*b) {
                Some(q) => Integer::Small(q),
                None => Integer::from_i128(*a as i128 / *b as i128),
            },
            _ => match (self.to_i128(), d.to_i128()) {
                (Some(a), Some(b)) => Integer::from_i128_op(a, b, i128::checked_div, |a, b| a / b),
                _ => Integer::from_bigint(self.to_bigint() / d.to_bigint()),
            },
        }
    }

    /// Whether `d` divides `self` (`d` nonzero).
    pub fn is_divisible_by(&self, d: &Integer) -> bool {
        match (self, d) {
            (Integer::Small(a), Integer::Small(b)) => (*a as i128) % (*b as i128) == 0,
            _ => match (self.to_i128(), d.to_i128()) {
                // The remainder overflows only for i128::MIN / −1, which divides.
                (Some(a), Some(b)) => a.checked_rem(b).is_none_or(|r| r == 0),
                _ => (self.to_bigint() % d.to_bigint()).is_zero(),
            },
        }
    }

    /// `self^e`.
    pub fn pow(&self, e: u32) -> Integer {
        if let Integer::Small(v) = self {
            if let Some(p) = v.checked_pow(e) {
                return Integer::Small(p);
            }
        }
        Integer::from_bigint(num_traits::pow(self.to_bigint(), e as usize))
    }

    /// Number of bits of the absolute value.
    pub fn bits(&self) -> u64 {
        match self {
            Integer::Small(v) => 64 - v.unsigned_abs().leading_zeros() as u64,
            Integer::Wide(v) => 128 - v.unsigned_abs().leading_zeros() as u64,
            Integer::Big(b) => b.bits(),
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
    pub fn new(d: &Integer) -> ExactDivisor {
        let kind = match d {
            Integer::Small(-1) => DivisorKind::MinusOne,
            Integer::Small(v) if v.unsigned_abs() >= 2 => {
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
                    negative: *v < 0,
                }
            }
            _ => DivisorKind::General,
        };
        ExactDivisor { d: d.clone(), kind }
    }

    /// `a / d`, for `a` a multiple of `d` (the quotient is wrong otherwise).
    #[inline]
    pub fn divide(&self, a: &Integer) -> Integer {
        match (a, self.kind) {
            (
                Integer::Small(v),
                DivisorKind::Word {
                    shift,
                    inverse,
                    negative,
                },
            ) => {
                // |d| ≥ 2, so the quotient fits an i64 and so does its negation.
                let q = (v >> shift).wrapping_mul(inverse as i64);
                Integer::Small(if negative { -q } else { q })
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
    fn from(v: i64) -> Self {
        Integer::Small(v)
    }
}

impl From<i32> for Integer {
    fn from(v: i32) -> Self {
        Integer::Small(v as i64)
    }
}

impl From<u64> for Integer {
    fn from(v: u64) -> Self {
        Integer::from_i128(v as i128)
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
        match (self, other) {
            (Integer::Small(a), Integer::Small(b)) => a.cmp(b),
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
        match self {
            Integer::Small(v) => write!(f, "{v}"),
            Integer::Wide(v) => write!(f, "{v}"),
            Integer::Big(b) => write!(f, "{b}"),
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
    match (a, b) {
        (Integer::Small(x), Integer::Small(y)) => match x.checked_add(*y) {
            Some(v) => Integer::Small(v),
            None => Integer::from_i128(*x as i128 + *y as i128),
        },
        _ => wide_or_big(a, b, i128::checked_add, |a, b| a + b),
    }
}

fn sub_ref(a: &Integer, b: &Integer) -> Integer {
    match (a, b) {
        (Integer::Small(x), Integer::Small(y)) => match x.checked_sub(*y) {
            Some(v) => Integer::Small(v),
            None => Integer::from_i128(*x as i128 - *y as i128),
        },
        _ => wide_or_big(a, b, i128::checked_sub, |a, b| a - b),
    }
}

#[inline]
fn mul_ref(a: &Integer, b: &Integer) -> Integer {
    match (a, b) {
        (Integer::Small(x), Integer::Small(y)) => match x.checked_mul(*y) {
            Some(v) => Integer::Small(v),
            None => Integer::from_i128(*x as i128 * *y as i128),
        },
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
        match self {
            Integer::Small(v) if *v != i64::MIN => Integer::Small(-v),
            _ => neg_wide_or_big(self),
        }
    }
}

/// `−a` for `i64::MIN` and anything wider.
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

/// An accumulator for sums of products `Σ a_k b_k` of integers: `i128` while it fits, then
/// `BigInt`. This is what keeps multiplication free of allocations for small coefficients.
#[derive(Clone, Debug, Default)]
pub struct IntegerAcc {
    small: i128,
    big: Option<BigInt>,
}

impl IntegerAcc {
    /// `acc += a * b`.
    #[inline]
    pub fn add_mul(&mut self, a: &Integer, b: &Integer) {
        if let (Integer::Small(x), Integer::Small(y)) = (a, b) {
            let p = *x as i128 * *y as i128;
            match self.small.checked_add(p) {
                Some(s) => self.small = s,
                None => self.spill(BigInt::from(p)),
            }
        } else {
            self.spill(a.to_bigint() * b.to_bigint());
        }
    }

    /// `acc += a`.
    #[inline]
    pub fn add(&mut self, a: &Integer) {
        match a {
            Integer::Small(x) => match self.small.checked_add(*x as i128) {
                Some(s) => self.small = s,
                None => self.spill(BigInt::from(*x)),
            },
            Integer::Wide(v) => match self.small.checked_add(**v) {
                Some(s) => self.small = s,
                None => self.spill(BigInt::from(**v)),
            },
            Integer::Big(b) => self.spill((**b).clone()),
        }
    }

    /// `acc -= a * b`.
    #[inline]
    pub fn sub_mul(&mut self, a: &Integer, b: &Integer) {
        if let (Integer::Small(x), Integer::Small(y)) = (a, b) {
            let p = *x as i128 * *y as i128;
            match self.small.checked_sub(p) {
                Some(s) => self.small = s,
                None => self.spill(-BigInt::from(p)),
            }
        } else {
            self.spill(-(a.to_bigint() * b.to_bigint()));
        }
    }

    #[cold]
    fn spill(&mut self, v: BigInt) {
        let big = self.big.get_or_insert_with(BigInt::zero);
        *big += v;
    }

    /// The accumulated value.
    pub fn finish(self) -> Integer {
        match self.big {
            None => Integer::from_i128(self.small),
            Some(b) => Integer::from_bigint(b + BigInt::from(self.small)),
        }
    }

    /// Whether the accumulated value is zero.
    pub fn is_zero(&self) -> bool {
        match &self.big {
            None => self.small == 0,
            Some(b) => (b + BigInt::from(self.small)).is_zero(),
        }
    }
}
