//! The commutative ring axioms, checked by one generic function on every triple of a list of
//! edge-case elements, for Q, Q(i) and polynomials over both.

use std::fmt::Debug;

use num_bigint::BigInt;
use trigpoly::{Coefficient, GaussianRational, Poly, Rational};

use crate::common::{big_rational, gauss, p, phase_space, G, Q};

/// What the axioms need of a commutative ring.
pub trait Ring: Clone + PartialEq + Debug {
    fn add(&self, other: &Self) -> Self;
    fn sub(&self, other: &Self) -> Self;
    fn mul(&self, other: &Self) -> Self;
    fn neg(&self) -> Self;
    /// The zero of the ring `self` lives in.
    fn zero_like(&self) -> Self;
    /// The one of the ring `self` lives in.
    fn one_like(&self) -> Self;
}

impl Ring for Rational {
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
    fn zero_like(&self) -> Self {
        Rational::zero()
    }
    fn one_like(&self) -> Self {
        Rational::one()
    }
}

impl Ring for GaussianRational {
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
    fn zero_like(&self) -> Self {
        GaussianRational::from(0)
    }
    fn one_like(&self) -> Self {
        GaussianRational::from(1)
    }
}

impl<C: Coefficient> Ring for Poly<C> {
    fn add(&self, other: &Self) -> Self {
        self.checked_add(other).expect("sum within the limits")
    }
    fn sub(&self, other: &Self) -> Self {
        self.checked_sub(other)
            .expect("difference within the limits")
    }
    fn mul(&self, other: &Self) -> Self {
        self.checked_mul(other).expect("product within the limits")
    }
    fn neg(&self) -> Self {
        -self
    }
    fn zero_like(&self) -> Self {
        Poly::zero(self.vars())
    }
    fn one_like(&self) -> Self {
        Poly::one(self.vars())
    }
}

/// Checks associativity and commutativity of + and ×, both distributive laws, the identities 0
/// and 1, the additive inverse and `a − b = a + (−b)` on every triple of `elements`.
pub fn ring_axioms<T: Ring>(elements: &[T]) {
    for a in elements {
        let zero = a.zero_like();
        let one = a.one_like();
        assert_eq!(a.add(&zero), *a, "a + 0 = a for a = {a:?}");
        assert_eq!(zero.add(a), *a, "0 + a = a for a = {a:?}");
        assert_eq!(a.mul(&one), *a, "a · 1 = a for a = {a:?}");
        assert_eq!(one.mul(a), *a, "1 · a = a for a = {a:?}");
        assert_eq!(a.mul(&zero), zero, "a · 0 = 0 for a = {a:?}");
        assert_eq!(a.add(&a.neg()), zero, "a + (−a) = 0 for a = {a:?}");
        assert_eq!(a.neg().neg(), *a, "−(−a) = a for a = {a:?}");
        assert_eq!(a.sub(a), zero, "a − a = 0 for a = {a:?}");
        for b in elements {
            assert_eq!(a.add(b), b.add(a), "a + b = b + a for a = {a:?}, b = {b:?}");
            assert_eq!(a.mul(b), b.mul(a), "a · b = b · a for a = {a:?}, b = {b:?}");
            assert_eq!(
                a.sub(b),
                a.add(&b.neg()),
                "a − b = a + (−b) for a = {a:?}, b = {b:?}"
            );
            assert_eq!(
                a.neg().mul(b),
                a.mul(b).neg(),
                "(−a)b = −(ab) for a = {a:?}, b = {b:?}"
            );
            for c in elements {
                assert_eq!(
                    a.add(b).add(c),
                    a.add(&b.add(c)),
                    "(a + b) + c = a + (b + c), a = {a:?}, b = {b:?}, c = {c:?}"
                );
                assert_eq!(
                    a.mul(b).mul(c),
                    a.mul(&b.mul(c)),
                    "(ab)c = a(bc), a = {a:?}, b = {b:?}, c = {c:?}"
                );
                assert_eq!(
                    a.mul(&b.add(c)),
                    a.mul(b).add(&a.mul(c)),
                    "a(b + c) = ab + ac, a = {a:?}, b = {b:?}, c = {c:?}"
                );
                assert_eq!(
                    a.add(b).mul(c),
                    a.mul(c).add(&b.mul(c)),
                    "(a + b)c = ac + bc, a = {a:?}, b = {b:?}, c = {c:?}"
                );
            }
        }
    }
}

fn q(s: &str) -> Rational {
    s.parse().unwrap_or_else(|e| panic!("{e}"))
}

fn z(s: &str) -> GaussianRational {
    s.parse().unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn ring_axioms_hold_in_q() {
    let two_pow_70 = BigInt::from(1) << 70;
    ring_axioms(&[
        Rational::zero(),
        Rational::one(),
        -Rational::one(),
        Rational::from(i64::MAX),
        Rational::from(i64::MIN),
        Rational::from(i64::MAX - 1),
        Rational::new(i64::MAX, i64::MAX - 1),
        Rational::new(1, i64::MIN + 1),
        q("1/3"),
        q("-7/12"),
        big_rational(&(two_pow_70 + 1)) / Rational::from(3i64).pow(40).expect("3 ≠ 0"),
    ]);
}

#[test]
fn ring_axioms_hold_in_gaussian_rationals() {
    ring_axioms(&[
        z("0"),
        z("1"),
        z("-1"),
        GaussianRational::i(),
        z("-i"),
        z("3/5 + 4/5*i"),
        z("1/2 - 1/3*i"),
        gauss(i64::MAX, i64::MAX),
        gauss(i64::MIN, 1),
        gauss(0, i64::MIN),
        gauss(i64::MAX, i64::MIN),
    ]);
}

#[test]
fn ring_axioms_hold_for_laurent_polynomials_over_q() {
    let vars = phase_space();
    let elements: Vec<Q> = [
        "0",
        "1",
        "-1",
        "x",
        "x^-3*y^2 - 1/2*M",
        "9223372036854775807*x + 9223372036854775806/y",
        "-9223372036854775808*p_x*p_y^-1 + 3",
        "p_x^2/(2*M) + M*omega^2*x^2/2",
        "(x + 1/x)^3",
        "1 + x + y + p_x + p_y + M + omega - 1/omega",
    ]
    .iter()
    .map(|s| p(&vars, s))
    .collect();
    ring_axioms(&elements);
}

#[test]
fn ring_axioms_hold_for_trigonometric_polynomials_over_gaussian_rationals() {
    let vars = phase_space();
    let elements: Vec<G> = [
        "0",
        "1",
        "-i",
        "i*x/M",
        "cos(theta)",
        "x*sin(theta) - i*y",
        "exp(3*i*theta) + exp(-i*phi)",
        "(cos(theta) + i*sin(phi))^2",
        "cos(theta - 2*phi)/omega^2",
        "9223372036854775807*i*x + 9223372036854775807*y",
        "(3/5 + 4/5*i)*p_x^-2 - 9223372036854775808*i",
        "1 + x + y + p_x + p_y + M + omega + sin(theta)",
    ]
    .iter()
    .map(|s| p(&vars, s))
    .collect();
    ring_axioms(&elements);
}

/// `z^e` by repeated squaring is `z·z·…·z` (`e` factors, of `z⁻¹` for `e < 0`), for exponents
/// around the bits' edges (0, 1, 2, 7, 8, 13) and negative ones; `0^e` with `e < 0` is `None`.
fn powers_are_repeated_products<T: Ring>(
    elements: &[T],
    pow: impl Fn(&T, i64) -> Option<T>,
    inv: impl Fn(&T) -> Option<T>,
) {
    for z in elements {
        for e in [0i64, 1, 2, 3, 7, 8, 13, -1, -2, -7] {
            let factor = if e < 0 { inv(z) } else { Some(z.clone()) };
            let Some(factor) = factor else {
                assert_eq!(pow(z, e), None, "{z:?}^{e} of zero");
                continue;
            };
            let product = (0..e.unsigned_abs()).fold(z.one_like(), |acc, _| acc.mul(&factor));
            assert_eq!(pow(z, e), Some(product), "{z:?}^{e}");
        }
    }
}

#[test]
fn powers_are_repeated_products_in_q() {
    powers_are_repeated_products(
        &[
            Rational::zero(),
            Rational::one(),
            -Rational::one(),
            q("-7/12"),
            Rational::from(i64::MAX),
            Rational::new(1, i64::MIN + 1),
        ],
        Rational::pow,
        Rational::try_inv,
    );
}

/// `checked_pow` is `pow` where the result's numerator and denominator fit the bit limit,
/// and `None` past it, at each limit around the result's size; an exponent whose result
/// could not be held (`2^(2^62)`) is refused at once.
#[test]
fn checked_powers_are_powers_within_the_bit_limit() {
    for base in [
        q("3/4"),
        q("-7/2"),
        q("1/1000"),
        Rational::from(i64::MIN),
        -Rational::one(),
    ] {
        for e in [0i64, 1, 2, 5, 13, -1, -6] {
            let power = base.pow(e).expect("nonzero base");
            let bits = power.numer().bits().max(power.denom().bits());
            for max_bits in [1, bits.saturating_sub(1), bits, bits + 1, 10_000] {
                let within = bits <= max_bits;
                assert_eq!(
                    base.checked_pow(e, max_bits),
                    within.then(|| power.clone()),
                    "{base:?}^{e} within {max_bits} bits"
                );
            }
        }
    }
    assert_eq!(Rational::from(2).checked_pow(1 << 62, 1 << 40), None);
    assert_eq!(q("1/2").checked_pow(-(1 << 62), 1 << 20), None);
    assert_eq!(
        Rational::zero().checked_pow(1 << 62, 1),
        Some(Rational::zero())
    );
}

#[test]
fn powers_are_repeated_products_in_gaussian_rationals() {
    powers_are_repeated_products(
        &[
            z("0"),
            z("1"),
            GaussianRational::i(),
            z("1 + i"),
            z("3/5 + 4/5*i"),
            z("1/2 - 1/3*i"),
            gauss(i64::MAX, i64::MIN),
        ],
        GaussianRational::pow,
        GaussianRational::try_inv,
    );
}

/// The gcd at the edges of `Integer`'s tiers: a zero beside a long value, `i128::MIN` (whose
/// absolute value, the gcd of it with 0, is past `i128`), and a short factor of a long value.
#[test]
fn gcd_at_the_edges_of_the_tiers() {
    use trigpoly::Integer;
    let int = |s: &str| s.parse::<Integer>().expect("an integer");
    let long = int("-340282366920938463463374607431768211456"); // −2^128
    let min = Integer::from(BigInt::from(i128::MIN));
    for (a, b, gcd) in [
        (
            Integer::ZERO,
            long.clone(),
            "340282366920938463463374607431768211456",
        ),
        (
            long.clone(),
            Integer::ZERO,
            "340282366920938463463374607431768211456",
        ),
        (
            min.clone(),
            Integer::ZERO,
            "170141183460469231731687303715884105728",
        ),
        (
            min.clone(),
            min.clone(),
            "170141183460469231731687303715884105728",
        ),
        (
            min.clone(),
            long.clone(),
            "170141183460469231731687303715884105728",
        ),
        (Integer::from(-6i64), long.clone(), "2"),
        (long.clone(), Integer::from(3i64), "1"),
        (int("-12"), int("30"), "6"),
    ] {
        let g = a.gcd(&b);
        assert_eq!(g, int(gcd), "gcd({a}, {b})");
        assert_eq!(
            g.to_bigint(),
            num_integer::Integer::gcd(&a.to_bigint(), &b.to_bigint())
        );
    }
}

/// Multiplying by a constant keeps the normal form whatever the constant's shape (real,
/// imaginary or neither, either sign, a fraction): `c·f` equals `Re c·f + i·Im c·f`, built from
/// real scalings, `i` and a sum, and `c` as a polynomial equals the same sum for `f = 1`.
#[test]
fn scaling_by_a_constant_of_any_shape_keeps_the_normal_form() {
    let vars = phase_space();
    let f: G = p(&vars, "x*p_x - 3*y^2/2 + cos(theta)");
    for (re, im) in [
        (3, 0),
        (-3, 0),
        (0, 2),
        (0, -2),
        (0, -1),
        (1, -1),
        (-1, 2),
        (-4, -6),
    ] {
        let c = GaussianRational::new(Rational::new(re, 5), Rational::from(im));
        let (re, im) = (c.re.clone().into(), c.im.clone().into());
        let parts = |f: &G| &f.scale(&re) + &f.mul_i().unwrap().scale(&im);
        assert_eq!(f.scale(&c), parts(&f), "c = {c}");
        let one = G::one(&vars);
        assert_eq!(G::constant(&vars, c.clone()), parts(&one), "c = {c}");
    }
}

/// `f · q` for a rational `q` is the product by the constant `q`, whichever of `f` and `q` is
/// borrowed, and so is `f *= q`: `&f * &q` and `f * q` were refused (only `f * &q` took a
/// rational), and zero on either side gives zero.
#[test]
fn a_rational_multiple_takes_values_and_references() {
    let vars = phase_space();
    let f: G = p(&vars, "x*p_x - 3*y^2/2 + cos(theta)");
    for q in [
        Rational::new(3, 5),
        Rational::new(-7, 2),
        Rational::zero(),
        Rational::new(i64::MAX, 3),
    ] {
        let product = &f * &G::constant(&vars, q.clone().into());
        assert_eq!(&f * &q, product, "{q}");
        assert_eq!(&f * q.clone(), product, "{q}");
        assert_eq!(f.clone() * q.clone(), product, "{q}");
        assert_eq!(f.clone() * &q, product, "{q}");
        assert_eq!(f.scale_rational(&q), product, "{q}");
        let mut g = f.clone();
        g *= &q;
        assert_eq!(g, product, "{q}");
        let mut g = f.clone();
        g *= q.clone();
        assert_eq!(g, product, "{q}");
    }
    let zero = G::zero(&vars);
    assert_eq!(&zero * &Rational::new(2, 3), zero);
    let mut z = zero.clone();
    z *= Rational::new(2, 3);
    assert_eq!(z, zero);
}
