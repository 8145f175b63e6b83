//! Exact univariate polynomials over the integers, for the values of a parameter where a
//! search's rank drops ([`crate::search::exceptional_values`]): a polynomial's rational roots,
//! found without factoring an integer, and what is left once their linear factors are
//! divided out.
//!
//! A rational root `p/q` of a primitive polynomial has `q` dividing its leading coefficient
//! `L`, so it is `m/L` for an integer `m`. The real roots of the square-free part are isolated
//! by Descartes' rule of signs (bisection of `(0, 2^k)`, `2^k` past Cauchy's bound, for the
//! positive roots and for those of `f(−t)`), each interval is narrowed by bisection on the
//! sign until it is shorter than `1/L`, and the one `m/L` it can then hold is tested exactly.
//!
//! ```
//! use brackets::univariate::IntPoly;
//!
//! // (3t − 1)(t − 2)(t² − 3): the roots 1/3 and 2, and t² − 3 left.
//! let f = IntPoly::from_i64(&[3, -9, -1, 3]).mul(&IntPoly::from_i64(&[-2, 1]));
//! let (roots, rest) = f.rational_roots()?;
//! assert_eq!(roots.iter().map(ToString::to_string).collect::<Vec<_>>(), ["1/3", "2"]);
//! assert_eq!(rest, IntPoly::from_i64(&[-3, 0, 1]));
//! # Ok::<(), brackets::EngineError>(())
//! ```

use num_bigint::BigInt;
use num_integer::Integer as _;
use num_traits::{One, Signed, Zero};
use trigpoly::num_rational::BigRational;
use trigpoly::Rational;

use crate::error::EngineError;
use crate::modular::{big_mod, inverse_mod, mul_mod};

/// A polynomial `Σ a_i t^i` with integer coefficients, lowest degree first, with no zero
/// leading coefficient (the zero polynomial has none).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IntPoly(Vec<BigInt>);

/// The monic gcd of two polynomials over `F_p` (coefficients lowest degree first, no zero
/// leading one; the zero polynomial empty), by Euclid's algorithm: the gcd with zero is the
/// other made monic, of two zeros zero.
pub(crate) fn gcd_mod(a: &[u64], b: &[u64], p: u64) -> Vec<u64> {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    trim(&mut a);
    trim(&mut b);
    while !b.is_empty() {
        let r = remainder_mod(a, &b, p);
        a = b;
        b = r;
    }
    if let Some(&lead) = a.last() {
        let inverse = inverse_mod(lead, p);
        for c in &mut a {
            *c = mul_mod(*c, inverse, p);
        }
    }
    a
}

/// Whether `u` (over `F_p`, of degree at least 1) has no repeated root: `gcd(u, u′)` is a
/// nonzero constant.
pub(crate) fn is_square_free_mod(u: &[u64], p: u64) -> bool {
    let derivative: Vec<u64> = (u.iter().enumerate().skip(1))
        .map(|(i, &c)| mul_mod(c, i as u64 % p, p))
        .collect();
    gcd_mod(u, &derivative, p).len() == 1
}

/// The remainder of `a` on division by `d` (not zero) over `F_p`.
fn remainder_mod(a: Vec<u64>, d: &[u64], p: u64) -> Vec<u64> {
    div_rem_mod(a, d, p).1
}

/// The quotient and the remainder of `a` on division by `d` (not zero) over `F_p`.
fn div_rem_mod(mut a: Vec<u64>, d: &[u64], p: u64) -> (Vec<u64>, Vec<u64>) {
    trim(&mut a);
    let dd = d.len() - 1;
    let inverse = inverse_mod(d[dd], p);
    let mut quotient = vec![0_u64; a.len().saturating_sub(dd)];
    while a.len() > dd {
        let lead = a.pop().expect("longer than d");
        let factor = mul_mod(lead, inverse, p);
        let shift = a.len() - dd;
        quotient[shift] = factor;
        for (x, y) in a[shift..].iter_mut().zip(&d[..dd]) {
            *x = (*x + p - mul_mod(factor, *y, p)) % p;
        }
    }
    trim(&mut a);
    trim(&mut quotient);
    (quotient, a)
}

/// The ring `F_p[t]/(m)`, `m` monic of positive degree: its elements the remainders modulo
/// `m`, coefficients lowest degree first, zero empty.
pub(crate) struct ResidueRing<'a> {
    m: &'a [u64],
    p: u64,
}

impl<'a> ResidueRing<'a> {
    /// The ring modulo the prime `p` and `m` (monic, of positive degree).
    pub(crate) fn new(m: &'a [u64], p: u64) -> Self {
        debug_assert!(m.len() > 1 && m.last() == Some(&1));
        ResidueRing { m, p }
    }

    /// The element of the polynomial `a` over `F_p`.
    pub(crate) fn reduce(&self, a: Vec<u64>) -> Vec<u64> {
        remainder_mod(a, self.m, self.p)
    }

    /// `a b`.
    pub(crate) fn mul(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        if a.is_empty() || b.is_empty() {
            return Vec::new();
        }
        let mut product = vec![0_u64; a.len() + b.len() - 1];
        for (i, &x) in a.iter().enumerate() {
            for (z, &y) in product[i..].iter_mut().zip(b) {
                *z = (*z + mul_mod(x, y, self.p)) % self.p;
            }
        }
        self.reduce(product)
    }

    /// `a − b`.
    pub(crate) fn sub(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        let mut out = a.to_vec();
        out.resize(a.len().max(b.len()), 0);
        for (x, &y) in out.iter_mut().zip(b) {
            *x = (*x + self.p - y) % self.p;
        }
        trim(&mut out);
        out
    }

    /// The inverse of `a`, when it is a unit (prime to `m`), by the extended Euclidean
    /// algorithm.
    pub(crate) fn inverse(&self, a: &[u64]) -> Option<Vec<u64>> {
        // r_i ≡ s_i a modulo m.
        let (mut r0, mut r1) = (self.m.to_vec(), self.reduce(a.to_vec()));
        let (mut s0, mut s1): (Vec<u64>, Vec<u64>) = (Vec::new(), vec![1]);
        while !r1.is_empty() {
            let (q, r) = div_rem_mod(r0, &r1, self.p);
            let s = self.sub(&s0, &self.mul(&q, &s1));
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
        }
        // r0 is the gcd: a unit exactly when it is a nonzero constant.
        (r0.len() == 1).then(|| {
            let inverse = inverse_mod(r0[0], self.p);
            s0.iter().map(|&c| mul_mod(c, inverse, self.p)).collect()
        })
    }
}

/// Drops the zero leading coefficients.
fn trim(a: &mut Vec<u64>) {
    while a.last() == Some(&0) {
        a.pop();
    }
}

/// How many bisection steps narrowing one root may take: a leading coefficient of some
/// 300 000 bits. Past it the search for rational roots stops with a message.
pub const MAX_BISECTIONS: u64 = 300_000;

impl IntPoly {
    /// The polynomial of the coefficients, lowest degree first.
    pub fn new(mut coeffs: Vec<BigInt>) -> Self {
        while coeffs.last().is_some_and(Zero::is_zero) {
            coeffs.pop();
        }
        IntPoly(coeffs)
    }

    /// The polynomial of small coefficients, lowest degree first.
    pub fn from_i64(coeffs: &[i64]) -> Self {
        IntPoly::new(coeffs.iter().map(|&c| BigInt::from(c)).collect())
    }

    /// The coefficients, lowest degree first.
    pub fn coeffs(&self) -> &[BigInt] {
        &self.0
    }

    /// The degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// Whether it is zero.
    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The product.
    #[must_use]
    pub fn mul(&self, other: &IntPoly) -> IntPoly {
        if self.is_zero() || other.is_zero() {
            return IntPoly(Vec::new());
        }
        let mut out = vec![BigInt::zero(); self.0.len() + other.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in other.0.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        IntPoly::new(out)
    }

    /// The same polynomial divided by the gcd of its coefficients, its leading coefficient
    /// positive.
    #[must_use]
    pub fn primitive(&self) -> IntPoly {
        let g = self.0.iter().fold(BigInt::zero(), |g, c| g.gcd(c));
        if g.is_zero() {
            return self.clone();
        }
        let g = if self.0.last().is_some_and(Signed::is_negative) {
            -g
        } else {
            g
        };
        IntPoly(self.0.iter().map(|c| c / &g).collect())
    }

    fn derivative(&self) -> IntPoly {
        IntPoly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * BigInt::from(i))
                .collect(),
        )
    }

    /// `(q, r)` with `lc(d)^k · self = q·d + r`, `deg r < deg d`, for `k` one more than the
    /// difference of the degrees (`d` not zero).
    fn pseudo_divide(&self, d: &IntPoly) -> (IntPoly, IntPoly) {
        let dd = d.0.len() - 1;
        let lc = &d.0[dd];
        let mut r = self.0.clone();
        let mut q = vec![BigInt::zero(); r.len().saturating_sub(dd)];
        while r.len() > dd && !r.is_empty() {
            let shift = r.len() - 1 - dd;
            let lead = r.pop().expect("not empty");
            for c in q.iter_mut() {
                *c *= lc;
            }
            q[shift] += &lead;
            for c in r.iter_mut() {
                *c *= lc;
            }
            for (i, c) in d.0[..dd].iter().enumerate() {
                r[shift + i] -= &lead * c;
            }
            while r.last().is_some_and(Zero::is_zero) {
                r.pop();
            }
        }
        (IntPoly::new(q), IntPoly::new(r))
    }

    /// Whether `self` divides `other` (over the rationals: up to a constant).
    pub fn divides(&self, other: &IntPoly) -> bool {
        !self.is_zero() && other.pseudo_divide(self).1.is_zero()
    }

    /// The primitive gcd, their gcd over the rationals made primitive with a positive leading
    /// coefficient (primitive remainder sequence); the gcd with zero is the other made
    /// primitive.
    #[must_use]
    pub fn gcd(&self, other: &IntPoly) -> IntPoly {
        let (mut a, mut b) = (self.primitive(), other.primitive());
        while !b.is_zero() {
            let r = a.pseudo_divide(&b).1;
            a = b;
            b = r.primitive();
        }
        a.primitive()
    }

    /// The primitive least common multiple: of two square-free polynomials, each irreducible
    /// factor of either once.
    #[must_use]
    pub fn lcm(&self, other: &IntPoly) -> IntPoly {
        let g = self.gcd(other);
        self.mul(&other.divide_out(&g)).primitive()
    }

    /// The exact quotient by `d`, a divisor over the rationals, made primitive.
    #[must_use]
    pub fn divide_out(&self, d: &IntPoly) -> IntPoly {
        self.pseudo_divide(d).0.primitive()
    }

    /// The primitive square-free part: each irreducible factor once.
    #[must_use]
    pub fn square_free(&self) -> IntPoly {
        let f = self.primitive();
        match f.degree() {
            None | Some(0) => f,
            Some(_) => f.divide_out(&f.gcd(&f.derivative())),
        }
    }

    /// The sign of `self(num/den)` (`den > 0`): of `Σ a_i num^i den^(n−i)`.
    fn sign_at(&self, num: &BigInt, den: &BigInt) -> i32 {
        let mut acc = BigInt::zero();
        let mut den_power = BigInt::one();
        for c in self.0.iter().rev() {
            acc = acc * num + c * &den_power;
            den_power *= den;
        }
        match acc.sign() {
            num_bigint::Sign::Minus => -1,
            num_bigint::Sign::NoSign => 0,
            num_bigint::Sign::Plus => 1,
        }
    }

    /// The coefficients modulo the prime `p`, lowest degree first, without zero leading ones.
    pub(crate) fn reduced_mod(&self, p: u64) -> Vec<u64> {
        let mut out: Vec<u64> = self.0.iter().map(|c| big_mod(c, p)).collect();
        trim(&mut out);
        out
    }

    /// Whether `r` is a root.
    pub fn vanishes_at(&self, r: &Rational) -> bool {
        self.sign_at(&r.numer().to_bigint(), &r.denom().to_bigint()) == 0
    }

    /// The rational roots, in increasing order, each once, and the primitive square-free
    /// polynomial left once their linear factors are divided out (a constant when none is
    /// left). Refused past [`MAX_BISECTIONS`] for one root.
    pub fn rational_roots(&self) -> Result<(Vec<Rational>, IntPoly), EngineError> {
        let square_free = self.square_free();
        let intervals = square_free.real_roots();
        let mut f = square_free.clone();
        let mut roots = Vec::new();
        // The roots found exactly come out first, so that no interval ends at a root of `f`.
        for found in &intervals {
            if let Isolated::Root(r) = found {
                f = f.divide_out(&linear_factor(r));
                roots.push(r.clone());
            }
        }
        let lc = f.0.last().cloned().unwrap_or_else(BigInt::one).abs();
        for found in intervals {
            if let Isolated::Interval(a, b) = found {
                if let Some(r) = f.rational_root_between(a, b, &lc)? {
                    roots.push(r);
                }
            }
        }
        let mut rest = square_free;
        for r in &roots {
            rest = rest.divide_out(&linear_factor(r));
        }
        roots.sort();
        Ok((roots, rest))
    }

    /// The number of distinct real roots, rational or not, isolated on both half lines as
    /// [`IntPoly::rational_roots`] isolates them (Descartes' rule of signs, exact).
    ///
    /// ```
    /// use brackets::univariate::IntPoly;
    /// // x³ − 2x = x(x² − 2): 0 and ±√2; 21x² − 12x + 272 has none, 2x² − 3x + 1 two.
    /// assert_eq!(IntPoly::from_i64(&[0, -2, 0, 1]).real_root_count(), 3);
    /// assert_eq!(IntPoly::from_i64(&[272, -12, 21]).real_root_count(), 0);
    /// assert_eq!(IntPoly::from_i64(&[1, -3, 2]).real_root_count(), 2);
    /// ```
    pub fn real_root_count(&self) -> usize {
        self.square_free().real_roots().len()
    }

    /// The real roots of a square-free polynomial, each once: `0` and the others found
    /// exactly, the rest each in an interval of its own, on both half lines.
    fn real_roots(&self) -> Vec<Isolated> {
        let mut found = Vec::new();
        if self.degree().unwrap_or(0) == 0 {
            return found;
        }
        let mut f = self.clone();
        if f.0[0].is_zero() {
            found.push(Isolated::Root(Rational::zero()));
            f = IntPoly(f.0[1..].to_vec());
        }
        for (sign, g) in [(1, f.clone()), (-1, f.mirrored())] {
            for root in g.positive_roots() {
                found.push(match root {
                    Isolated::Root(r) => Isolated::Root(if sign < 0 { -r } else { r }),
                    Isolated::Interval(a, b) if sign < 0 => Isolated::Interval(-b, -a),
                    interval => interval,
                });
            }
        }
        found
    }

    /// `f(−x)`, whose positive roots are the negatives of `f`'s negative roots.
    fn mirrored(&self) -> IntPoly {
        IntPoly(
            self.0
                .iter()
                .enumerate()
                .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
                .collect(),
        )
    }

    /// The positive real roots of a square-free polynomial with `f(0) ≠ 0`: each a rational
    /// root found exactly or an open interval holding one root and no rational root found.
    fn positive_roots(&self) -> Vec<Isolated> {
        let n = self.0.len() - 1;
        let lc_bits = self.0[n].bits();
        let max_bits = self.0.iter().map(BigInt::bits).max().unwrap_or(0);
        // 2^k ≥ 1 + max|a_i|/|a_n|, Cauchy's bound on the roots.
        let k = max_bits.saturating_sub(lc_bits) + 2;
        // g(x) = f(2^k x): its roots in (0, 1).
        let g: Vec<BigInt> = (0..=n).map(|i| &self.0[i] << (k as usize * i)).collect();
        let mut found = Vec::new();
        // (g, c, e): g(x) is f((c + x)·2^(k−e)) times a positive constant.
        let mut stack = vec![(g, BigInt::zero(), 0_u64)];
        let point = |c: &BigInt, e: u64| {
            Rational::from(BigRational::new(
                c.clone() << k as usize,
                BigInt::one() << e as usize,
            ))
        };
        while let Some((g, c, e)) = stack.pop() {
            let v = variations(&taylor_shift_one(&reversed(&g)));
            if v == 0 {
                continue;
            }
            if v == 1 {
                found.push(Isolated::Interval(
                    point(&c, e),
                    point(&(&c + BigInt::one()), e),
                ));
                continue;
            }
            // g(x/2)·2^n and g((x + 1)/2)·2^n, on the halves.
            let left: Vec<BigInt> = g.iter().enumerate().map(|(i, a)| a << (n - i)).collect();
            let mut right = taylor_shift_one(&left);
            let middle = BigInt::from(2) * &c + BigInt::one();
            if right[0].is_zero() {
                found.push(Isolated::Root(point(&middle, e + 1)));
                right.remove(0);
            }
            stack.push((right, middle, e + 1));
            stack.push((left, BigInt::from(2) * &c, e + 1));
        }
        found
    }

    /// The rational root of `self` in `(a, b)`, which holds exactly one real root and has no
    /// root at its ends, if that root is rational: narrowed by bisection below `1/lc`, the one
    /// `m/lc` left is tested.
    fn rational_root_between(
        &self,
        mut a: Rational,
        mut b: Rational,
        lc: &BigInt,
    ) -> Result<Option<Rational>, EngineError> {
        let sign = |r: &Rational| self.sign_at(&r.numer().to_bigint(), &r.denom().to_bigint());
        let sign_a = sign(&a);
        let spacing = Rational::from(BigRational::new(BigInt::one(), lc.clone()));
        let two = Rational::from(2);
        let mut steps = 0;
        while &b - &a >= spacing {
            steps += 1;
            if steps > MAX_BISECTIONS {
                return Err(EngineError::Invalid(format!(
                    "narrowing a root of a polynomial of degree {} took past {MAX_BISECTIONS} \
                     bisections",
                    self.0.len() - 1
                )));
            }
            let m = (&a + &b) / &two;
            match sign(&m) {
                0 => return Ok(Some(m)),
                s if s == sign_a => a = m,
                _ => b = m,
            }
        }
        // The one m/lc with a < m/lc < b, if there is one.
        let lc_r = Rational::from(lc.clone());
        let m = (&b * &lc_r).to_big_rational().ceil() - BigRational::one();
        let candidate = Rational::from(m) / &lc_r;
        Ok((candidate > a && candidate < b && self.vanishes_at(&candidate)).then_some(candidate))
    }
}

/// A real root isolated: found exactly, or in an open interval.
enum Isolated {
    Root(Rational),
    Interval(Rational, Rational),
}

/// `q t − p` for the root `p/q`.
fn linear_factor(r: &Rational) -> IntPoly {
    IntPoly::new(vec![-r.numer().to_bigint(), r.denom().to_bigint()])
}

/// `x^n g(1/x)`.
fn reversed(g: &[BigInt]) -> Vec<BigInt> {
    g.iter().rev().cloned().collect()
}

/// `g(x + 1)`.
fn taylor_shift_one(g: &[BigInt]) -> Vec<BigInt> {
    let mut a = g.to_vec();
    let n = a.len();
    for i in 0..n {
        for j in (i..n - 1).rev() {
            let next = a[j + 1].clone();
            a[j] += next;
        }
    }
    a
}

/// The sign changes along the coefficients, zeros skipped.
fn variations(g: &[BigInt]) -> usize {
    let mut last = 0;
    let mut count = 0;
    for c in g {
        let s = if c.is_positive() {
            1
        } else if c.is_negative() {
            -1
        } else {
            continue;
        };
        if last != 0 && s != last {
            count += 1;
        }
        last = s;
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots_text(f: &IntPoly) -> (Vec<String>, IntPoly) {
        let (roots, rest) = f.rational_roots().unwrap();
        (roots.iter().map(ToString::to_string).collect(), rest)
    }

    #[test]
    fn rational_roots_of_a_product_of_linear_factors_with_multiplicity() {
        // (2t + 3)²(7t − 5)(t)(t − 1): −3/2, 0, 5/7, 1.
        let mut f = IntPoly::from_i64(&[1]);
        for factor in [[3, 2], [3, 2], [-5, 7], [0, 1], [-1, 1]] {
            f = f.mul(&IntPoly::from_i64(&factor));
        }
        let (roots, rest) = roots_text(&f);
        assert_eq!(roots, ["-3/2", "0", "5/7", "1"]);
        assert_eq!(rest, IntPoly::from_i64(&[1]));
    }

    #[test]
    fn irrational_and_complex_roots_are_left() {
        // (t² − 2)(t² + 1)(4t − 1): 1/4, and (t² − 2)(t² + 1) left.
        let f = IntPoly::from_i64(&[-2, 0, 1])
            .mul(&IntPoly::from_i64(&[1, 0, 1]))
            .mul(&IntPoly::from_i64(&[-1, 4]));
        let (roots, rest) = roots_text(&f);
        assert_eq!(roots, ["1/4"]);
        assert_eq!(rest, IntPoly::from_i64(&[-2, 0, -1, 0, 1]));
        // No rational root at all.
        let (roots, rest) = roots_text(&IntPoly::from_i64(&[-2, 0, 1]));
        assert!(roots.is_empty());
        assert_eq!(rest, IntPoly::from_i64(&[-2, 0, 1]));
    }

    #[test]
    fn close_roots_with_large_denominators_are_told_apart() {
        // (1000t − 999)(1001t − 1000)(t − 1): three roots within 1/1000.
        let f = IntPoly::from_i64(&[-999, 1000])
            .mul(&IntPoly::from_i64(&[-1000, 1001]))
            .mul(&IntPoly::from_i64(&[-1, 1]));
        let (roots, _) = roots_text(&f);
        assert_eq!(roots, ["999/1000", "1000/1001", "1"]);
    }

    #[test]
    fn the_lcm_holds_each_shared_factor_once() {
        // (t² − 2)(t + 1) and (t² − 2)(3t − 1): (t² − 2)(t + 1)(3t − 1).
        let shared = IntPoly::from_i64(&[-2, 0, 1]);
        let f = shared.mul(&IntPoly::from_i64(&[1, 1]));
        let g = shared.mul(&IntPoly::from_i64(&[-1, 3]));
        let expected = f.mul(&IntPoly::from_i64(&[-1, 3]));
        assert_eq!(f.lcm(&g), expected);
        assert_eq!(f.lcm(&f), f);
        assert_eq!(IntPoly::from_i64(&[1]).lcm(&g), g);
    }

    #[test]
    fn the_gcd_over_the_integers_is_the_shared_factor_made_primitive() {
        // (2t² − 6)(t + 1) and (t² − 3)(3t − 1)·(−5): t² − 3.
        let f = IntPoly::from_i64(&[-6, 0, 2]).mul(&IntPoly::from_i64(&[1, 1]));
        let g = IntPoly::from_i64(&[-3, 0, 1]).mul(&IntPoly::from_i64(&[5, -15]));
        assert_eq!(f.gcd(&g), IntPoly::from_i64(&[-3, 0, 1]));
        // Coprime: a constant; with zero: the other, primitive.
        let h = IntPoly::from_i64(&[1, 0, 1]);
        assert_eq!(f.gcd(&h), IntPoly::from_i64(&[1]));
        assert_eq!(IntPoly::new(Vec::new()).gcd(&f), f.primitive());
        assert_eq!(f.divide_out(&f.gcd(&g)), IntPoly::from_i64(&[1, 1]));
    }

    #[test]
    fn modulo_a_prime_and_a_polynomial_units_are_inverted_and_zero_divisors_are_not() {
        let p = 7;
        // Modulo t² + 1 (irreducible modulo 7): t · (−t) = 1, (t + 1)(4 − 4t) = 8 = 1.
        let m = [1, 0, 1];
        let ring = ResidueRing::new(&m, p);
        assert_eq!(ring.inverse(&[0, 1]), Some(vec![0, 6]));
        assert_eq!(ring.inverse(&[1, 1]), Some(vec![4, 3]));
        assert_eq!(ring.mul(&[1, 1], &[4, 3]), [1]);
        assert_eq!(ring.reduce(vec![2, 3, 4, 5]), [5, 5]);
        assert_eq!(ring.sub(&[1, 1], &[1, 1]), Vec::<u64>::new());
        // Modulo (t − 1)(t − 2) = t² − 3t + 2: t − 1 divides zero, t − 3 is a unit.
        let m = [2, 4, 1];
        let ring = ResidueRing::new(&m, p);
        assert_eq!(ring.inverse(&[6, 1]), None);
        assert_eq!(ring.inverse(&[]), None);
        let inverse = ring.inverse(&[4, 1]).unwrap();
        assert_eq!(ring.mul(&[4, 1], &inverse), [1]);
    }

    #[test]
    fn the_gcd_modulo_a_prime_is_monic_and_sees_factors_the_integers_do_not_share() {
        let p = 7;
        // (t − 1)(t + 2) and (t − 1)(t − 3) modulo 7: t − 1 = [6, 1].
        let f = IntPoly::from_i64(&[-2, 1, 1]).reduced_mod(p);
        let g = IntPoly::from_i64(&[3, -4, 1]).reduced_mod(p);
        assert_eq!(gcd_mod(&f, &g, p), [6, 1]);
        // t² + 1 and t − 9 share no factor over Q, but 9 ≡ 2 and 2² + 1 = 5 ≢ 0, while
        // t² + 1 and t − 3 share t − 3 modulo 5 (3² + 1 = 10).
        let square_plus_one = IntPoly::from_i64(&[1, 0, 1]);
        assert_eq!(gcd_mod(&square_plus_one.reduced_mod(p), &[5, 1], p), [1]);
        let five = 5;
        assert_eq!(
            gcd_mod(&square_plus_one.reduced_mod(five), &[2, 1], five),
            [2, 1]
        );
        // Twice t − 1 is made monic; the gcd with zero is the other, of zeros zero.
        assert_eq!(gcd_mod(&[5, 2], &[], p), [6, 1]);
        assert!(gcd_mod(&[], &[], p).is_empty());
        // A leading coefficient that vanishes modulo p drops the degree.
        assert_eq!(IntPoly::from_i64(&[1, 2, 14]).reduced_mod(p), [1, 2]);
    }

    #[test]
    fn a_constant_has_no_root() {
        let (roots, rest) = roots_text(&IntPoly::from_i64(&[-6]));
        assert!(roots.is_empty());
        assert_eq!(rest, IntPoly::from_i64(&[1]));
    }
}
