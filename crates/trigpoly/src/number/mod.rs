//! Exact numbers: integers with a machine fast path, Q, Z\[i\], Q(i), and the two traits that let
//! one polynomial type serve both fields.
//!
//! A polynomial over a field `C` is stored as a rational *content* times a primitive polynomial
//! over the integer ring `C::Int` (Z for Q, Z\[i\] for Q(i)), as FLINT's `fmpq_mpoly` does: the hot
//! loops then multiply machine integers, not fractions.

mod gaussian;
mod gcd;
mod integer;
mod rational;

use std::fmt::{Debug, Display};
use std::hash::Hash;
use std::str::FromStr;

use gcd::gcd_u128;

pub(crate) use gcd::binary_gcd;

pub use gaussian::{GaussianAcc, GaussianInteger, GaussianRational, ParseGaussianError};
pub use integer::{ExactDivisor, Integer, IntegerAcc, IntegerView};
pub(crate) use integer::{Release, SlotCounts, Wide192, Wide256, WideSlab};
pub(crate) use rational::Magnitude;
pub use rational::{ParseRationalError, Rational, RationalErrorKind};

/// `(i^e x)·(i^f y) = i^(e+f)·xy` for values that are each real or imaginary (as
/// [`IntegerRing::to_real_or_imaginary`] gives them: `(v, true)` for `i·v`): the component
/// the product adds to (0: real, 1: imaginary) and `x` signed for it, negated when both are
/// imaginary (`i·i = −1`). No branch: the kernels call it once a term pair.
#[inline(always)]
pub(crate) fn axial_product<T: std::ops::Neg<Output = T>>(
    (x, x_imaginary): (T, bool),
    y_imaginary: bool,
) -> (usize, T) {
    let part = usize::from(x_imaginary ^ y_imaginary);
    (part, if x_imaginary & y_imaginary { -x } else { x })
}

/// The integer ring under a coefficient field: `Integer` (Z) or `GaussianInteger` (Z\[i\]).
pub trait IntegerRing:
    Clone + PartialEq + Eq + Hash + Debug + Default + Send + Sync + 'static
{
    /// Accumulator for sums of products, free of allocation while values are small.
    type Acc: Default + Clone;
    /// Whether the value is zero.
    fn is_zero(&self) -> bool;
    /// The embedding of an integer.
    fn from_integer(k: Integer) -> Self;
    /// Whether the value is one.
    fn is_one(&self) -> bool;
    /// `a + b`.
    fn add(&self, other: &Self) -> Self;
    /// `a − b`.
    fn sub(&self, other: &Self) -> Self;
    /// `a · b`.
    fn mul(&self, other: &Self) -> Self;
    /// `−a`.
    fn neg(&self) -> Self;
    /// `a · k` for an integer `k`.
    fn scale(&self, k: &Integer) -> Self;
    /// `a / k`, exact: `k` divides every component.
    fn div_exact(&self, k: &ExactDivisor) -> Self;
    /// `gcd(g, every component of a)`.
    fn gcd_into(&self, g: &Integer) -> Integer;
    /// The sign of the first nonzero component (real part first).
    fn leading_sign(&self) -> i32;
    /// Complex conjugate (identity on Z).
    fn conj(&self) -> Self;
    /// The value in Z\[i\].
    fn to_gaussian_integer(&self) -> GaussianInteger;
    /// `i · a`, if `i` is in the ring.
    fn try_mul_i(&self) -> Option<Self>;
    /// The value as a machine integer, if it is real and fits an `i64`.
    fn to_real_i64(&self) -> Option<i64>;
    /// Whether the value is real (always, in Z).
    fn is_real(&self) -> bool;
    /// Drops the value through `release`, which gives back the slots of its components run
    /// by run (`WideSlab`).
    fn release_into(self, release: &mut Release);
    /// Whether the ring has elements off the real line (Z\[i\]). Its kernels then gather
    /// factors whose coefficients are all real in Z's words ([`IntegerRing::from_real_wide`]):
    /// a product of real words is one multiplication, where a Gaussian one takes four.
    const COMPLEX: bool;
    /// The element of a real sum in Z's wide form.
    fn from_real_wide(w: i128) -> Self;
    /// The value in machine words, if every component fits an `i64`.
    type Small: Copy + Default + Send + Sync;
    /// A wide accumulator for `Small` products (`i128` per component).
    type Wide: Copy + Default + PartialEq + Send + Sync;
    /// A broader accumulator (192 bits per component), for sums of products of `Small` or
    /// `Double` values that could pass `Wide`'s.
    type Broad: Copy + Default + PartialEq + Send + Sync;
    /// The value in machine words, if every component fits.
    fn to_small(&self) -> Option<Self::Small>;
    /// Bits of the largest component of a small value.
    fn small_bits(s: &Self::Small) -> u32;
    /// The sum of the absolute values of the components of a small value (at least its
    /// absolute value, and submultiplicative).
    fn small_norm1(s: &Self::Small) -> u128;
    /// `acc += a · b` in wide arithmetic; the caller guarantees no overflow.
    fn wide_add_mul(acc: &mut Self::Wide, a: &Self::Small, b: &Self::Small);
    /// `a · k` in machine words, if every component fits.
    fn small_checked_scale(a: &Self::Small, k: i64) -> Option<Self::Small>;
    /// `a · b · k` in machine words; the caller guarantees no overflow.
    fn small_mul_scale(a: &Self::Small, b: &Self::Small, k: i64) -> Self::Small;
    /// A small value as a wide one.
    fn small_to_wide(a: &Self::Small) -> Self::Wide;
    /// The value of a wide accumulator.
    #[inline]
    fn from_wide(w: Self::Wide) -> Self {
        Self::from_wide_with(w, &mut Integer::from_i128)
    }
    /// [`IntegerRing::from_wide`] with each component past a word made by `place`, which
    /// must return it as [`Integer::from_i128`] would (in a slab's slot, say).
    fn from_wide_with(w: Self::Wide, place: &mut impl FnMut(i128) -> Integer) -> Self;
    /// `acc += a · b` in 192-bit arithmetic; the caller guarantees no overflow.
    fn broad_add_mul(acc: &mut Self::Broad, a: &Self::Small, b: &Self::Small);
    /// The value in two machine words per component (`i128`).
    type Double: Copy + Default + Send + Sync;
    /// The value in two words per component, if every component fits.
    fn to_double(&self) -> Option<Self::Double>;
    /// Bits of the largest component of a value in two words.
    fn double_bits(s: &Self::Double) -> u32;
    /// `acc += a · b` in 192-bit arithmetic for values in two words; the caller guarantees
    /// no overflow.
    fn double_add_mul(acc: &mut Self::Broad, a: &Self::Double, b: &Self::Double);
    /// The value of a broad accumulator.
    fn from_broad(w: Self::Broad) -> Self;
    /// `acc += w` in wide arithmetic; the caller guarantees no overflow.
    fn wide_add(acc: &mut Self::Wide, w: &Self::Wide);
    /// `k · w` in wide arithmetic; the caller guarantees no overflow.
    fn wide_scale(w: &Self::Wide, k: i64) -> Self::Wide;
    /// `i · w`, if `i` is in the ring.
    fn wide_mul_i(w: &Self::Wide) -> Option<Self::Wide>;
    /// `gcd(g, |c|)` over the components `c` of `w`.
    fn wide_gcd(g: u128, w: &Self::Wide) -> u128;
    /// The sign of the first nonzero component of `w` (real part first).
    fn wide_leading_sign(w: &Self::Wide) -> i32;
    /// `w / d`, exact: `d ≠ 0` divides every component.
    fn wide_div_exact(w: &Self::Wide, d: i128) -> Self::Wide;
    /// The value as `(r, false)` for `r` or `(r, true)` for `i·r`, with `r` an `i128`, if it
    /// is real or imaginary and fits (each coefficient of `Z^m e^{−inθ}` is).
    fn to_real_or_imaginary(&self) -> Option<(i128, bool)>;
    /// `re + i·im`; `im` is zero in Z.
    fn from_parts(re: Integer, im: Integer) -> Self;
    /// Whether products of primitive elements are primitive (Gauss's lemma: true for Z, false
    /// for Z\[i\] with primitivity taken componentwise, as `(1 + i)(1 − i) = 2` shows).
    const GAUSS_LEMMA: bool;
    /// How many real products one `wide_add_mul` adds to a component (1 for Z, 2 for Z\[i\]).
    const PRODUCTS_PER_COMPONENT: u32;
    /// `acc += a · b`.
    fn acc_add_mul(acc: &mut Self::Acc, a: &Self, b: &Self);
    /// `acc += a`.
    fn acc_add(acc: &mut Self::Acc, a: &Self);
    /// The accumulated value.
    fn acc_finish(acc: Self::Acc) -> Self;
}

impl IntegerRing for Integer {
    type Acc = IntegerAcc;
    type Small = i64;
    type Wide = i128;
    type Broad = Wide192;
    type Double = i128;
    const GAUSS_LEMMA: bool = true;
    const PRODUCTS_PER_COMPONENT: u32 = 1;
    const COMPLEX: bool = false;
    #[inline]
    fn to_small(&self) -> Option<i64> {
        self.to_i64()
    }
    fn to_real_i64(&self) -> Option<i64> {
        self.to_i64()
    }
    fn is_real(&self) -> bool {
        true
    }
    #[inline]
    fn release_into(self, release: &mut Release) {
        release.take(self);
    }

    #[inline]
    fn from_real_wide(w: i128) -> Self {
        Integer::from_i128(w)
    }
    fn small_bits(s: &i64) -> u32 {
        64 - s.unsigned_abs().leading_zeros()
    }
    fn small_norm1(s: &i64) -> u128 {
        s.unsigned_abs() as u128
    }
    #[inline(always)]
    fn wide_add_mul(acc: &mut i128, a: &i64, b: &i64) {
        *acc += *a as i128 * *b as i128;
    }
    #[inline(always)]
    fn small_checked_scale(a: &i64, k: i64) -> Option<i64> {
        a.checked_mul(k)
    }
    #[inline(always)]
    fn small_mul_scale(a: &i64, b: &i64, k: i64) -> i64 {
        a * b * k
    }
    #[inline(always)]
    fn small_to_wide(a: &i64) -> i128 {
        *a as i128
    }
    #[inline(always)]
    fn from_wide_with(w: i128, place: &mut impl FnMut(i128) -> Integer) -> Self {
        Integer::from_i128_with(w, place)
    }
    #[inline(always)]
    fn broad_add_mul(acc: &mut Wide192, a: &i64, b: &i64) {
        acc.add_mul_words(*a, *b);
    }
    #[inline]
    fn from_broad(w: Wide192) -> Self {
        w.to_integer()
    }
    #[inline]
    fn to_double(&self) -> Option<i128> {
        self.to_i128()
    }
    fn double_bits(s: &i128) -> u32 {
        128 - s.unsigned_abs().leading_zeros()
    }
    #[inline(always)]
    fn double_add_mul(acc: &mut Wide192, a: &i128, b: &i128) {
        acc.add_mul_double(*a, *b);
    }
    #[inline(always)]
    fn wide_add(acc: &mut i128, w: &i128) {
        *acc += *w;
    }
    #[inline(always)]
    fn wide_scale(w: &i128, k: i64) -> i128 {
        *w * k as i128
    }
    fn wide_mul_i(_: &i128) -> Option<i128> {
        None
    }
    #[inline]
    fn wide_gcd(g: u128, w: &i128) -> u128 {
        gcd_u128(g, w.unsigned_abs())
    }
    #[inline]
    fn wide_leading_sign(w: &i128) -> i32 {
        w.signum() as i32
    }
    #[inline]
    fn wide_div_exact(w: &i128, d: i128) -> i128 {
        div_i128(*w, d)
    }
    #[inline]
    fn to_real_or_imaginary(&self) -> Option<(i128, bool)> {
        Some((self.to_i128()?, false))
    }
    fn from_parts(re: Integer, im: Integer) -> Self {
        debug_assert!(im.is_zero());
        re
    }
    fn is_zero(&self) -> bool {
        Integer::is_zero(self)
    }
    fn from_integer(k: Integer) -> Self {
        k
    }
    fn is_one(&self) -> bool {
        Integer::is_one(self)
    }
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    fn sub(&self, other: &Self) -> Self {
        self - other
    }
    fn mul(&self, other: &Self) -> Self {
        self * other
    }
    fn neg(&self) -> Self {
        -self
    }
    fn scale(&self, k: &Integer) -> Self {
        self * k
    }
    fn div_exact(&self, k: &ExactDivisor) -> Self {
        k.divide(self)
    }
    fn gcd_into(&self, g: &Integer) -> Integer {
        g.gcd(self)
    }
    fn leading_sign(&self) -> i32 {
        self.signum()
    }
    fn conj(&self) -> Self {
        self.clone()
    }
    fn to_gaussian_integer(&self) -> GaussianInteger {
        GaussianInteger::from_integer(self.clone())
    }
    fn try_mul_i(&self) -> Option<Self> {
        None
    }
    #[inline]
    fn acc_add_mul(acc: &mut IntegerAcc, a: &Self, b: &Self) {
        acc.add_mul(a, b)
    }
    #[inline]
    fn acc_add(acc: &mut IntegerAcc, a: &Self) {
        acc.add(a)
    }
    fn acc_finish(acc: IntegerAcc) -> Self {
        acc.finish()
    }
}

impl IntegerRing for GaussianInteger {
    type Acc = GaussianAcc;
    type Small = (i64, i64);
    type Wide = (i128, i128);
    type Broad = [Wide192; 2];
    type Double = (i128, i128);
    const GAUSS_LEMMA: bool = false;
    const PRODUCTS_PER_COMPONENT: u32 = 2;
    const COMPLEX: bool = true;
    #[inline]
    fn to_small(&self) -> Option<(i64, i64)> {
        Some((self.re.to_i64()?, self.im.to_i64()?))
    }
    #[inline]
    fn to_real_i64(&self) -> Option<i64> {
        self.im.is_zero().then(|| self.re.to_i64()).flatten()
    }
    fn is_real(&self) -> bool {
        self.im.is_zero()
    }
    #[inline]
    fn release_into(self, release: &mut Release) {
        release.take(self.re);
        release.take(self.im);
    }

    #[inline]
    fn from_real_wide(w: i128) -> Self {
        GaussianInteger::new(Integer::from_i128(w), Integer::ZERO)
    }
    fn small_bits(s: &(i64, i64)) -> u32 {
        64 - (s.0.unsigned_abs() | s.1.unsigned_abs()).leading_zeros()
    }
    // |re(zw)| + |im(zw)| ≤ (|re z| + |im z|)(|re w| + |im w|)
    fn small_norm1(s: &(i64, i64)) -> u128 {
        s.0.unsigned_abs() as u128 + s.1.unsigned_abs() as u128
    }
    #[inline(always)]
    fn small_checked_scale(a: &(i64, i64), k: i64) -> Option<(i64, i64)> {
        Some((a.0.checked_mul(k)?, a.1.checked_mul(k)?))
    }
    // (a + bi)(c + di)k = (ac − bd)k + (ad + bc)k i
    #[inline(always)]
    fn small_mul_scale(a: &(i64, i64), b: &(i64, i64), k: i64) -> (i64, i64) {
        ((a.0 * b.0 - a.1 * b.1) * k, (a.0 * b.1 + a.1 * b.0) * k)
    }
    #[inline(always)]
    fn small_to_wide(a: &(i64, i64)) -> (i128, i128) {
        (a.0 as i128, a.1 as i128)
    }
    // (a + bi)(c + di) = (ac − bd) + (ad + bc)i
    #[inline(always)]
    fn wide_add_mul(acc: &mut (i128, i128), a: &(i64, i64), b: &(i64, i64)) {
        let (ar, ai, br, bi) = (a.0 as i128, a.1 as i128, b.0 as i128, b.1 as i128);
        acc.0 += ar * br - ai * bi;
        acc.1 += ar * bi + ai * br;
    }
    #[inline(always)]
    fn from_wide_with(w: (i128, i128), place: &mut impl FnMut(i128) -> Integer) -> Self {
        GaussianInteger::new(
            Integer::from_i128_with(w.0, place),
            Integer::from_i128_with(w.1, place),
        )
    }
    #[inline(always)]
    fn broad_add_mul(acc: &mut [Wide192; 2], a: &(i64, i64), b: &(i64, i64)) {
        let [re, im] = acc;
        re.add_mul_words(a.0, b.0);
        // −(a.1·b.1), as a product that cannot overflow: a.1 may be i64::MIN.
        re.add_mul_double(-i128::from(a.1), i128::from(b.1));
        im.add_mul_words(a.0, b.1);
        im.add_mul_words(a.1, b.0);
    }
    #[inline]
    fn from_broad([re, im]: [Wide192; 2]) -> Self {
        GaussianInteger::new(re.to_integer(), im.to_integer())
    }
    #[inline]
    fn to_double(&self) -> Option<(i128, i128)> {
        // Above `i128::MIN`, so that `double_add_mul` may negate a component.
        let part = |v: &Integer| v.to_i128().filter(|&v| v != i128::MIN);
        Some((part(&self.re)?, part(&self.im)?))
    }
    fn double_bits(s: &(i128, i128)) -> u32 {
        128 - (s.0.unsigned_abs() | s.1.unsigned_abs()).leading_zeros()
    }
    #[inline(always)]
    fn double_add_mul(acc: &mut [Wide192; 2], a: &(i128, i128), b: &(i128, i128)) {
        let [re, im] = acc;
        re.add_mul_double(a.0, b.0);
        re.add_mul_double(-a.1, b.1);
        im.add_mul_double(a.0, b.1);
        im.add_mul_double(a.1, b.0);
    }
    #[inline(always)]
    fn wide_add(acc: &mut (i128, i128), w: &(i128, i128)) {
        acc.0 += w.0;
        acc.1 += w.1;
    }
    #[inline(always)]
    fn wide_scale(w: &(i128, i128), k: i64) -> (i128, i128) {
        (w.0 * k as i128, w.1 * k as i128)
    }
    #[inline(always)]
    fn wide_mul_i(w: &(i128, i128)) -> Option<(i128, i128)> {
        Some((-w.1, w.0))
    }
    #[inline]
    fn wide_gcd(g: u128, w: &(i128, i128)) -> u128 {
        gcd_u128(gcd_u128(g, w.0.unsigned_abs()), w.1.unsigned_abs())
    }
    #[inline]
    fn wide_leading_sign(w: &(i128, i128)) -> i32 {
        if w.0 == 0 {
            w.1.signum() as i32
        } else {
            w.0.signum() as i32
        }
    }
    #[inline]
    fn wide_div_exact(w: &(i128, i128), d: i128) -> (i128, i128) {
        (div_i128(w.0, d), div_i128(w.1, d))
    }
    #[inline]
    fn to_real_or_imaginary(&self) -> Option<(i128, bool)> {
        match (self.re.is_zero(), self.im.is_zero()) {
            (_, true) => Some((self.re.to_i128()?, false)),
            (true, false) => Some((self.im.to_i128()?, true)),
            (false, false) => None,
        }
    }
    fn from_parts(re: Integer, im: Integer) -> Self {
        GaussianInteger::new(re, im)
    }
    fn is_zero(&self) -> bool {
        GaussianInteger::is_zero(self)
    }
    fn from_integer(k: Integer) -> Self {
        GaussianInteger::new(k, Integer::ZERO)
    }
    fn is_one(&self) -> bool {
        self.re.is_one() && self.im.is_zero()
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        if let Some((a, b, c, d)) = word_parts(self, o) {
            // Values of 63 bits: the sums have 64.
            return GaussianInteger::new(Integer::from(a + c), Integer::from(b + d));
        }
        self.add_beyond_words(o)
    }
    fn sub(&self, o: &Self) -> Self {
        GaussianInteger::new(&self.re - &o.re, &self.im - &o.im)
    }
    // (a + bi)(c + di) = (ac − bd) + (ad + bc)i
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        if let Some((a, b, c, d)) = word_parts(self, o) {
            // Products and sums that stay in a word are words (the canonical tier) at once.
            let re = a.checked_mul(c).zip(b.checked_mul(d));
            let im = a.checked_mul(d).zip(b.checked_mul(c));
            if let (Some(re), Some(im)) = (
                re.and_then(|(ac, bd)| ac.checked_sub(bd)),
                im.and_then(|(ad, bc)| ad.checked_add(bc)),
            ) {
                return GaussianInteger::new(Integer::from(re), Integer::from(im));
            }
        }
        self.mul_beyond_words(o)
    }
    fn neg(&self) -> Self {
        GaussianInteger::new(-&self.re, -&self.im)
    }
    #[inline]
    fn scale(&self, k: &Integer) -> Self {
        // Products that stay in a word are words (the canonical tier) at once.
        if let (Some(a), Some(b), Some(k)) = (self.re.small(), self.im.small(), k.small()) {
            if let (Some(x), Some(y)) = (a.checked_mul(k), b.checked_mul(k)) {
                return GaussianInteger::new(Integer::from(x), Integer::from(y));
            }
        }
        self.scale_beyond_words(k)
    }
    #[inline]
    fn div_exact(&self, k: &ExactDivisor) -> Self {
        GaussianInteger::new(k.divide(&self.re), k.divide(&self.im))
    }
    fn gcd_into(&self, g: &Integer) -> Integer {
        g.gcd(&self.re).gcd(&self.im)
    }
    fn leading_sign(&self) -> i32 {
        if self.re.is_zero() {
            self.im.signum()
        } else {
            self.re.signum()
        }
    }
    fn conj(&self) -> Self {
        GaussianInteger::conj(self)
    }
    fn to_gaussian_integer(&self) -> GaussianInteger {
        self.clone()
    }
    fn try_mul_i(&self) -> Option<Self> {
        Some(self.mul_i())
    }
    #[inline]
    fn acc_add_mul(acc: &mut GaussianAcc, a: &Self, b: &Self) {
        acc.add_mul(a, b)
    }
    #[inline]
    fn acc_add(acc: &mut GaussianAcc, a: &Self) {
        acc.add(a)
    }
    fn acc_finish(acc: GaussianAcc) -> Self {
        acc.finish()
    }
}

/// The parts `(a, b, c, d)` of `a + bi` and `c + di` when all four are machine words.
#[inline]
fn word_parts(x: &GaussianInteger, y: &GaussianInteger) -> Option<(i64, i64, i64, i64)> {
    match (x.re.small(), x.im.small(), y.re.small(), y.im.small()) {
        (Some(a), Some(b), Some(c), Some(d)) => Some((a, b, c, d)),
        _ => None,
    }
}

/// The paths of Gaussian sums and products beyond machine words, out of line so that the
/// word paths of [`IntegerRing::add`], [`IntegerRing::mul`] and [`IntegerRing::scale`] inline
/// into the kernels.
impl GaussianInteger {
    #[inline(never)]
    fn mul_beyond_words(&self, o: &Self) -> Self {
        if let (Some((a, b)), Some((c, d))) = (self.to_small(), o.to_small()) {
            // Word-sized parts: each product fits an i128, and so does each sum except at
            // the edge, (−2⁶³)² + (−2⁶³)² = 2¹²⁷, which goes the general way below.
            let (a, b, c, d) = (a as i128, b as i128, c as i128, d as i128);
            if let (Some(re), Some(im)) = ((a * c).checked_sub(b * d), (a * d).checked_add(b * c)) {
                return GaussianInteger::new(Integer::from_i128(re), Integer::from_i128(im));
            }
        }
        if self.im.is_zero() {
            return GaussianInteger::new(&self.re * &o.re, &self.re * &o.im);
        }
        if o.im.is_zero() {
            return GaussianInteger::new(&self.re * &o.re, &self.im * &o.re);
        }
        GaussianInteger::new(
            &self.re * &o.re - &self.im * &o.im,
            &self.re * &o.im + &self.im * &o.re,
        )
    }

    #[inline(never)]
    fn add_beyond_words(&self, o: &Self) -> Self {
        GaussianInteger::new(&self.re + &o.re, &self.im + &o.im)
    }

    #[inline(never)]
    fn scale_beyond_words(&self, k: &Integer) -> Self {
        if let (Some((a, b)), Some(k)) = (self.to_small(), k.to_i64()) {
            let k = k as i128;
            return GaussianInteger::new(
                Integer::from_i128(a as i128 * k),
                Integer::from_i128(b as i128 * k),
            );
        }
        GaussianInteger::new(&self.re * k, &self.im * k)
    }
}

/// A coefficient field: `Rational` (Q) or `GaussianRational` (Q(i)).
///
/// Every element factors as `content · n` with `content ∈ Q` and `n` in the integer ring
/// [`Coefficient::Int`]; polynomials use that split to run their inner loops on integers.
pub trait Coefficient:
    Clone + PartialEq + Eq + Hash + Debug + Display + FromStr + Default + Send + Sync + 'static
{
    /// The integer ring: Z for Q, Z\[i\] for Q(i).
    type Int: IntegerRing;
    /// Whether the field contains `i` (so angles, `e^{iθ}`, can be represented).
    const HAS_I: bool;
    /// The field's name, for messages: "Q" or "Q(i)".
    const NAME: &'static str;
    /// `content · n`.
    fn from_parts(content: &Rational, n: &Self::Int) -> Self;
    /// `(content, n)` with `n` primitive (coprime components, first nonzero one positive) and
    /// `self = content · n`; `(0, 0)` for zero.
    fn split(&self) -> (Rational, Self::Int);
    /// The embedding of a rational.
    fn from_rational(q: Rational) -> Self;
    /// The value as a Gaussian rational.
    fn to_gaussian(&self) -> GaussianRational;
    /// The value, if it lies in this field.
    fn from_gaussian(z: &GaussianRational) -> Option<Self>;
    /// Zero.
    fn zero() -> Self {
        Self::default()
    }
    /// One.
    fn one() -> Self {
        Self::from_rational(Rational::one())
    }
    /// Whether the value is zero.
    fn is_zero(&self) -> bool;
}

impl Coefficient for Rational {
    type Int = Integer;
    const HAS_I: bool = false;
    const NAME: &'static str = "Q";
    fn from_parts(content: &Rational, n: &Integer) -> Self {
        content.mul_integer(n)
    }
    fn split(&self) -> (Rational, Integer) {
        if self.is_zero() {
            return (Rational::zero(), Integer::ZERO);
        }
        (self.clone(), Integer::ONE)
    }
    fn from_rational(q: Rational) -> Self {
        q
    }
    fn to_gaussian(&self) -> GaussianRational {
        GaussianRational::from(self.clone())
    }
    fn from_gaussian(z: &GaussianRational) -> Option<Self> {
        z.is_real().then(|| z.re.clone())
    }
    fn is_zero(&self) -> bool {
        Rational::is_zero(self)
    }
}

impl Coefficient for GaussianRational {
    type Int = GaussianInteger;
    const HAS_I: bool = true;
    const NAME: &'static str = "Q(i)";
    fn from_parts(content: &Rational, n: &GaussianInteger) -> Self {
        GaussianRational::new(content.mul_integer(&n.re), content.mul_integer(&n.im))
    }
    fn split(&self) -> (Rational, GaussianInteger) {
        if self.is_zero() {
            return (Rational::zero(), GaussianInteger::default());
        }
        // A real or an imaginary value (most constants) is itself times 1 or i.
        if self.im.is_zero() {
            return (
                self.re.clone(),
                GaussianInteger::new(Integer::ONE, Integer::ZERO),
            );
        }
        if self.re.is_zero() {
            return (
                self.im.clone(),
                GaussianInteger::new(Integer::ZERO, Integer::ONE),
            );
        }
        // Both parts are nonzero here: the real part leads.
        let g = Rational::content_gcd(&self.re, &self.im);
        let g = if self.re.sign() == std::cmp::Ordering::Less {
            -g
        } else {
            g
        };
        let re = &self.re / &g;
        let im = &self.im / &g;
        (g, GaussianInteger::new(re.numer(), im.numer()))
    }
    fn from_rational(q: Rational) -> Self {
        GaussianRational::from(q)
    }
    fn to_gaussian(&self) -> GaussianRational {
        self.clone()
    }
    fn from_gaussian(z: &GaussianRational) -> Option<Self> {
        Some(z.clone())
    }
    fn is_zero(&self) -> bool {
        GaussianRational::is_zero(self)
    }
}

/// `x / d` for an exact division, on machine words when both fit one (the common case, where
/// an `i128` division is a library call).
#[inline]
fn div_i128(x: i128, d: i128) -> i128 {
    match (i64::try_from(x), i64::try_from(d)) {
        (Ok(x), Ok(d)) => match x.checked_div(d) {
            Some(q) => q as i128,
            None => x as i128 / d as i128,
        },
        _ => x / d,
    }
}
