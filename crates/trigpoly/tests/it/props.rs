//! Property tests: each test is named after the law it checks, on random sparse Laurent ×
//! trigonometric polynomials in `x, y, p_x, p_y, θ, φ, M, ω`.

use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use proptest::test_runner::Config;
use trigpoly::{
    AlgebraError, Angles, ExactDivisor, GaussianRational, Integer, IntegerAcc, IntegerView, Limits,
    Point, Poly, Rational, Style, VarKind, Vars,
};

use crate::common::{phase_space, var, G, Q};

/// Numerators: mostly small, sometimes near the ends of `i64`.
fn numerator() -> impl Strategy<Value = i64> {
    prop_oneof![
        8 => -20i64..20,
        1 => prop_oneof![Just(i64::MAX), Just(i64::MIN), i64::MAX - 3..=i64::MAX, (1i64 << 40)..(1i64 << 41)],
    ]
}

/// Integers on both sides of the `i64` and `i128` bounds, as `BigInt`s.
fn integer() -> impl Strategy<Value = BigInt> {
    let near = |bound: BigInt| (-3i64..=3).prop_map(move |k| &bound + k);
    prop_oneof![
        2 => any::<i64>().prop_map(BigInt::from),
        2 => any::<i128>().prop_map(BigInt::from),
        1 => (-5i64..5).prop_map(BigInt::from),
        1 => near(BigInt::from(i64::MAX)),
        1 => near(BigInt::from(i64::MIN)),
        1 => near(BigInt::from(i128::MAX)),
        1 => near(BigInt::from(i128::MIN)),
        1 => (any::<i128>(), any::<i64>()).prop_map(|(hi, lo)| (BigInt::from(hi) << 64) + lo),
    ]
}

/// A component of a Gaussian integer: mostly values whose products stay in a word (the fast
/// path), else any [`integer`].
fn component() -> impl Strategy<Value = BigInt> {
    prop_oneof![
        3 => (-(1i64 << 31)..(1i64 << 31)).prop_map(BigInt::from),
        1 => integer(),
    ]
}

/// The parts of a small Gaussian integer, mostly real or imaginary.
fn axial_or_not() -> impl Strategy<Value = (i64, i64)> {
    prop_oneof![
        4 => (-2i64..3, Just(0i64)),
        4 => (Just(0i64), -2i64..3),
        1 => (-2i64..3, -2i64..3),
    ]
}

/// Whether `v` is stored in the variant its size calls for (the structural-equality invariant).
fn canonical(v: &Integer) -> bool {
    let b = v.to_bigint();
    let word = -(1i64 << 62)..(1i64 << 62);
    let in_word = i64::try_from(&b).is_ok_and(|v| word.contains(&v));
    match v.view() {
        IntegerView::Small(_) => in_word,
        IntegerView::Wide(_) => !in_word && i128::try_from(&b).is_ok(),
        IntegerView::Big(_) => i128::try_from(&b).is_err(),
    }
}

/// A word-sized part of a fraction: small values (where cross gcds other than 1 are common),
/// powers of two, any `i64`, and the edges `i64::MIN`, `i64::MAX`.
fn word() -> impl Strategy<Value = i64> {
    prop_oneof![
        4 => -40i64..40,
        1 => (0u32..63).prop_map(|k| 1i64 << k),
        1 => any::<i64>(),
        1 => Just(i64::MIN),
        1 => Just(i64::MAX),
    ]
}

/// A rational from word-sized parts (reduced, so its parts may be anything up to `2^63`).
fn word_rational() -> impl Strategy<Value = Rational> {
    (word(), word().prop_filter("a denominator", |d| *d != 0))
        .prop_map(|(n, d)| Rational::new(n, d))
}

fn rational() -> impl Strategy<Value = Rational> {
    (numerator(), prop_oneof![3 => Just(1i64), 1 => 2i64..7]).prop_map(|(n, d)| Rational::new(n, d))
}

fn gaussian() -> impl Strategy<Value = GaussianRational> {
    prop_oneof![
        2 => rational().prop_map(GaussianRational::from),
        1 => (rational(), rational()).prop_map(|(re, im)| GaussianRational::new(re, im)),
    ]
}

/// An exponent: zero more often than not, otherwise in −3..=4.
fn exponent() -> impl Strategy<Value = i64> {
    prop_oneof![3 => Just(0i64), 2 => -3i64..=4]
}

/// An exponent that is sometimes far out: products of two pass a limit of 511 now and then.
fn wide_exponent() -> impl Strategy<Value = i64> {
    prop_oneof![3 => Just(0i64), 2 => -3i64..=4, 1 => -300i64..=300]
}

/// Products, a sum, a square, a derivative and a substitution of `f` and `g` in variables
/// `x, y, z, t, u, v` packed with fields of `bits`, under the degree limit `limit`: each
/// printed, or its error.
fn same_computation_in(
    bits: u32,
    limit: u32,
    f: &[(Rational, Vec<i64>)],
    g: &[(Rational, Vec<i64>)],
) -> Vec<String> {
    let vars = ["x", "y", "z", "t", "u", "v"]
        .iter()
        .fold(trigpoly::Vars::builder(), |b, name| b.coordinate(name))
        .limits(trigpoly::Limits::default().max_degree(limit))
        .exponent_bits(bits)
        .build()
        .expect("valid names");
    let (f, g) = match (
        Q::from_terms(&vars, f.to_vec()),
        Q::from_terms(&vars, g.to_vec()),
    ) {
        (Ok(f), Ok(g)) => (f, g),
        (f, g) => return vec![format!("{:?} {:?}", f.err(), g.err())],
    };
    let (x, v) = (var(&vars, "x"), var(&vars, "v"));
    let yz = Q::parse(&vars, "y*z^-1").expect("a term");
    [
        f.checked_mul(&g),
        f.checked_add(&g),
        f.checked_pow(2),
        f.derivative(v).and_then(|d| g.checked_mul(&d)),
        f.subst(x, &yz),
    ]
    .iter()
    .map(|r| match r {
        Ok(h) => h.to_string(),
        Err(e) => format!("error: {e}"),
    })
    .collect()
}

/// Exponents of all 8 variables; angles get 0 when `angles` is false.
fn exponents(angles: bool) -> impl Strategy<Value = Vec<i64>> {
    let vars = phase_space();
    let kinds: Vec<bool> = vars
        .vars()
        .map(|v| vars.variable(v).kind() == VarKind::Angle)
        .collect();
    proptest::collection::vec(exponent(), vars.len()).prop_map(move |mut e| {
        if !angles {
            for (ej, &is_angle) in e.iter_mut().zip(&kinds) {
                if is_angle {
                    *ej = 0;
                }
            }
        }
        e
    })
}

/// A random polynomial over Q(i) with up to `max_terms − 1` terms (both multiplication
/// paths: short times long, and the heap product of two long ones).
fn gpoly(max_terms: usize) -> impl Strategy<Value = G> {
    proptest::collection::vec((gaussian(), exponents(true)), 0..max_terms)
        .prop_map(|terms| Poly::from_terms(&phase_space(), terms).expect("small exponents"))
}

/// A random polynomial over Q (no angles).
fn qpoly(max_terms: usize) -> impl Strategy<Value = Q> {
    proptest::collection::vec((rational(), exponents(false)), 0..max_terms)
        .prop_map(|terms| Poly::from_terms(&phase_space(), terms).expect("small exponents"))
}

/// A polynomial dense in `x, y, M` (exponents −2..=3) with 7 to 19 terms, so that products
/// take the dense (Kronecker) path; coefficients up to ~2^61 so that both the machine-word
/// accumulators and the fallback for larger ones are used.
fn dense_poly() -> impl Strategy<Value = G> {
    let coeff = prop_oneof![
        4 => -20i64..20,
        1 => (1i64 << 59)..(1i64 << 61),
        1 => -(1i64 << 61)..-(1i64 << 59),
        1 => prop_oneof![Just(i64::MAX), Just(i64::MIN)],
    ];
    let gauss = prop_oneof![
        coeff
            .clone()
            .prop_map(|re| GaussianRational::from(Rational::from(re))),
        (coeff.clone(), coeff)
            .prop_map(|(re, im)| GaussianRational::new(Rational::from(re), Rational::from(im))),
    ];
    proptest::collection::vec((gauss, proptest::collection::vec(-2i64..=3, 3)), 7..20).prop_map(
        |terms| {
            let vars = phase_space();
            let (x, y, m) = (var(&vars, "x"), var(&vars, "y"), var(&vars, "M"));
            let mut acc = G::zero(&vars);
            for (c, e) in terms {
                acc += G::monomial(&vars, c, &[(x, e[0]), (y, e[1]), (m, e[2])])
                    .expect("small exponents");
            }
            acc
        },
    )
}

/// A sparse polynomial in 16 coordinates with exponents up to ±900, 7 to 12 terms: the
/// exponent box of a product of two (1801^16 cells) is too large for Kronecker indices, so the
/// heap product runs on the packed monomials.
fn wide_poly() -> impl Strategy<Value = Q> {
    static VARS: std::sync::OnceLock<trigpoly::Vars> = std::sync::OnceLock::new();
    let vars = VARS
        .get_or_init(|| {
            (0..16)
                .fold(trigpoly::Vars::builder(), |b, k| {
                    b.coordinate(&format!("x{k}"))
                })
                .build()
                .expect("valid names")
        })
        .clone();
    let exps = proptest::collection::vec(prop_oneof![2 => Just(0i64), 1 => -450i64..=450], 16);
    proptest::collection::vec((rational(), exps), 7..13)
        .prop_map(move |terms| Poly::from_terms(&vars, terms).expect("small exponents"))
}

/// `f · g` as `Σ_t f · t` over the terms `t` of `g`: each product by a single term is a
/// translation, independent of the dense and heap multiplications.
fn product_by_terms<C: trigpoly::Coefficient>(f: &Poly<C>, g: &Poly<C>) -> Poly<C> {
    let vars = f.vars();
    g.terms().fold(Poly::zero(vars), |acc, t| {
        let powers: Vec<_> = vars.vars().zip(t.exponents()).collect();
        acc + f * &Poly::monomial(vars, t.coeff(), &powers).expect("a term of g")
    })
}

/// A value to substitute: a single term (always allowed) or a short polynomial with
/// non-negative exponents.
fn subst_value() -> impl Strategy<Value = G> {
    let term = (
        gaussian().prop_filter("nonzero", |c| !c.is_zero()),
        exponents(true),
    )
        .prop_map(|t| Poly::from_terms(&phase_space(), [t]).expect("small exponents"));
    let short =
        proptest::collection::vec((gaussian(), proptest::collection::vec(0i64..=2, 8)), 1..4)
            .prop_map(|terms| Poly::from_terms(&phase_space(), terms).expect("small exponents"));
    prop_oneof![term, short]
}

/// Rational points of the unit circle used for the angles.
const CIRCLE: [(i64, i64, i64); 3] = [(3, 4, 5), (5, 12, 13), (8, 15, 17)];

/// A point giving every variable a nonzero value (negative exponents occur).
fn point() -> impl Strategy<Value = Point> {
    let nonzero = (prop_oneof![-9i64..0, 1i64..10], 1i64..6).prop_map(|(n, d)| Rational::new(n, d));
    (
        proptest::collection::vec(nonzero, 6),
        proptest::sample::select(CIRCLE.to_vec()),
        proptest::sample::select(CIRCLE.to_vec()),
        any::<(bool, bool)>(),
    )
        .prop_map(|(values, a, b, (sa, sb))| {
            let vars = phase_space();
            let sign = |s: bool| if s { -1 } else { 1 };
            let mut point = Point::new(&vars)
                .with_angle(
                    var(&vars, "theta"),
                    Rational::new(a.0, a.2),
                    Rational::new(sign(sa) * a.1, a.2),
                )
                .expect("on the unit circle")
                .with_angle(
                    var(&vars, "phi"),
                    Rational::new(sign(sb) * b.1, b.2),
                    Rational::new(b.0, b.2),
                )
                .expect("on the unit circle");
            for (name, value) in ["x", "y", "p_x", "p_y", "M", "omega"].iter().zip(values) {
                point = point.with(var(&vars, name), value);
            }
            point
        })
}

/// Sums, products and scalings of Gaussian integers whose components are all ±2⁶³
/// (`i64::MIN`, or one past `i64::MAX`), every sign pattern: with all four `i64::MIN`,
/// `ad + bc = 2¹²⁷` passes `i128`, and every sum of two `i64::MIN` passes `i64`.
#[test]
fn gaussian_arithmetic_at_the_edge_of_the_machine_words() {
    use trigpoly::{GaussianInteger, IntegerRing};
    for signs in 0..16u32 {
        let edge = |k: u32| {
            let v = BigInt::from(i64::MIN);
            if signs >> k & 1 == 1 {
                -v
            } else {
                v
            }
        };
        let (a, b, c, d) = (edge(0), edge(1), edge(2), edge(3));
        let x = GaussianInteger::new(Integer::from(a.clone()), Integer::from(b.clone()));
        let y = GaussianInteger::new(Integer::from(c.clone()), Integer::from(d.clone()));
        let p = x.mul(&y);
        assert_eq!(
            (p.re.to_bigint(), p.im.to_bigint()),
            (&a * &c - &b * &d, &a * &d + &b * &c),
            "signs {signs:04b}"
        );
        let s = x.add(&y);
        assert_eq!(
            (s.re.to_bigint(), s.im.to_bigint()),
            (&a + &c, &b + &d),
            "signs {signs:04b}"
        );
        let k = x.scale(&Integer::from(c.clone()));
        assert_eq!(
            (k.re.to_bigint(), k.im.to_bigint()),
            (&a * &c, &b * &c),
            "signs {signs:04b}"
        );
    }
}

/// 64 cases a property, or as many as `PROPTEST_CASES` asks for a deeper run.
fn config() -> Config {
    let base = Config::default();
    Config {
        cases: match std::env::var_os("PROPTEST_CASES") {
            Some(_) => base.cases,
            None => 64,
        },
        failure_persistence: None,
        ..base
    }
}

proptest! {
    #![proptest_config(config())]

    /// Products and quotients of rationals equal num-rational's, in canonical form (machine
    /// words exactly when the value fits), across the machine path's cross-cancellation, its
    /// overflow into big values, and the edges of `i64`.
    #[test]
    fn rational_products_and_quotients_match_big_rationals(x in word_rational(), y in word_rational()) {
        let (bx, by) = (x.to_big_rational(), y.to_big_rational());
        prop_assert_eq!(&x * &y, Rational::from(&bx * &by));
        if !y.is_zero() {
            prop_assert_eq!(&x / &y, Rational::from(&bx / &by));
        }
    }

    /// Sums, differences, products and quotients of big rationals (past `i128`, with common
    /// factors so that the gcds are long) equal num-rational's: the big path reduces with its
    /// own gcds (Lehmer's, and a remainder when a side is short) and cross-cancels products.
    #[test]
    fn big_rational_arithmetic_matches_num_rational(
        n1 in integer(), d1 in integer(), n2 in integer(), d2 in integer(), f in integer(),
    ) {
        let f = if f == BigInt::from(0) { BigInt::from(1) } else { f };
        let nonzero = |d: BigInt| if d == BigInt::from(0) { BigInt::from(7) } else { d };
        let bx = BigRational::new(&n1 * &f * &n2, nonzero(d1.clone()) * &f);
        let by = BigRational::new(&n2 * &f, nonzero(nonzero(d2.clone()) * &f * &d1 + 1));
        let by = if by == BigRational::from_integer(0.into()) { bx.clone() } else { by };
        let (x, y) = (Rational::from(bx.clone()), Rational::from(by.clone()));
        prop_assert_eq!(&x + &y, Rational::from(&bx + &by));
        prop_assert_eq!(&x - &y, Rational::from(&bx - &by));
        prop_assert_eq!(&x * &y, Rational::from(&bx * &by));
        if !y.is_zero() {
            prop_assert_eq!(&x / &y, Rational::from(&bx / &by));
        }
        let text = format!("{}/{}", bx.numer(), bx.denom() * &f);
        let parsed: Rational = text.parse().expect("a fraction");
        prop_assert_eq!(parsed, Rational::from(BigRational::new(bx.numer().clone(), bx.denom() * &f)));
    }

    /// A rational times an integer (one gcd on the machine path) equals num-rational's
    /// product, in canonical form, across the edges of `i64` and `i128`.
    #[test]
    fn rational_times_integer_matches_big_rationals(x in word_rational(), k in integer()) {
        let product = x.to_big_rational() * BigRational::from_integer(k.clone());
        prop_assert_eq!(x.mul_integer(&Integer::from(k)), Rational::from(product));
    }

    #[test]
    fn ring_add_commutative(f in gpoly(10), g in gpoly(10), a in qpoly(10), b in qpoly(10)) {
        prop_assert_eq!(&f + &g, &g + &f);
        prop_assert_eq!(&a + &b, &b + &a);
        prop_assert_eq!(&f * &g, &g * &f);
        prop_assert_eq!(&a * &b, &b * &a);
    }

    #[test]
    fn ring_add_associative_with_inverse(f in gpoly(10), g in gpoly(10), h in gpoly(10)) {
        prop_assert_eq!((&f + &g) + &h, &f + (&g + &h));
        prop_assert!((&f - &f).is_zero());
        prop_assert_eq!(&f - &g, &f + &(-&g));
        prop_assert_eq!(&(&f - &g) + &g, f);
    }

    #[test]
    fn ring_mul_associative(f in gpoly(9), g in gpoly(9), h in gpoly(9), a in qpoly(9), b in qpoly(9), c in qpoly(9)) {
        prop_assert_eq!((&f * &g) * &h, &f * (&g * &h));
        prop_assert_eq!((&a * &b) * &c, &a * (&b * &c));
    }

    #[test]
    fn ring_mul_distributive(f in gpoly(10), g in gpoly(10), h in gpoly(10), a in qpoly(10), b in qpoly(10), c in qpoly(10)) {
        prop_assert_eq!(&f * (&g + &h), &f * &g + &f * &h);
        prop_assert_eq!(&a * (&b - &c), &a * &b - &a * &c);
    }

    #[test]
    fn ring_embedding_of_q_in_gaussian_is_a_homomorphism(a in qpoly(9), b in qpoly(9)) {
        prop_assert_eq!((&a * &b).to_gaussian(), &a.to_gaussian() * &b.to_gaussian());
        prop_assert_eq!((&a + &b).to_gaussian(), &a.to_gaussian() + &b.to_gaussian());
        prop_assert_eq!(a.to_gaussian().to_rational(), Some(a));
    }

    /// The product of two long polynomials (dense, or by a heap on Kronecker indices or on
    /// packed monomials) equals the sum of the products by single terms.
    #[test]
    fn ring_mul_agrees_with_sum_of_term_products(f in dense_poly(), g in dense_poly(), h in gpoly(10), k in gpoly(10), u in wide_poly(), v in wide_poly()) {
        prop_assert_eq!(&u * &v, product_by_terms(&u, &v));
        prop_assert_eq!(&f * &g, product_by_terms(&f, &g));
        prop_assert_eq!(&h * &k, product_by_terms(&h, &k));
        let (fr, gr) = (f.re().unwrap().to_rational().expect("real"), g.re().unwrap().to_rational().expect("real"));
        prop_assert_eq!(&fr * &gr, product_by_terms(&fr, &gr));
        // Squares, whose kernels form each pair of terms once.
        prop_assert_eq!(&f * &f, product_by_terms(&f, &f));
        prop_assert_eq!(&fr * &fr, product_by_terms(&fr, &fr));
        prop_assert_eq!(&u * &u, product_by_terms(&u, &u));
    }

    #[test]
    fn pow_agrees_with_repeated_multiplication(f in gpoly(5), a in qpoly(5), e in 0i64..7) {
        // The multinomial expansion against e − 1 plain multiplications.
        let mut fe = Poly::one(f.vars());
        let mut ae = Poly::one(a.vars());
        for _ in 0..e {
            fe = &fe * &f;
            ae = &ae * &a;
        }
        prop_assert_eq!(f.checked_pow(e).unwrap(), fe);
        prop_assert_eq!(a.checked_pow(e).unwrap(), ae);
    }

    /// A power of a polynomial of more than six terms (repeated multiplication, where a short
    /// one takes the multinomial walk) has the power of its value at a point, and equals the
    /// product of two lower powers, one of them a square (its own kernel).
    #[test]
    fn pow_of_a_long_polynomial(
        terms in proptest::collection::vec(((-3i64..4, -3i64..4), exponents(true)), 7..12),
        e in 3i64..5, point in point(),
    ) {
        // Small Gaussian integer coefficients, so that the values' fractions stay short.
        let terms = terms.into_iter().map(|((re, im), e)| (GaussianRational::new(re.into(), im.into()), e));
        let f = G::from_terms(&phase_space(), terms).expect("small exponents");
        prop_assume!(f.len() > 6);
        let value = |h: &G| h.eval(&point).expect("every variable has a nonzero value");
        let fe = f.checked_pow(e).unwrap();
        prop_assert_eq!(value(&fe), value(&f).pow(e).expect("nonzero"));
        prop_assert_eq!(fe, &f.checked_pow(e - 2).unwrap() * &f.checked_pow(2).unwrap());
    }

    /// A power is refused by the term limit only where it, or a power on the way to it, has
    /// more terms than the limit: the count a power knows before it is formed never passes
    /// the count formed. Terms in a small box of `x, y, z` (so that monomials meet on
    /// relations) with coefficients mostly real or imaginary (so that the bound is given),
    /// some of whose relations turn the phase and cancel terms.
    #[test]
    fn a_power_is_refused_only_past_the_term_limit(
        terms in proptest::collection::vec((axial_or_not(), proptest::collection::vec(-1i64..3, 3)), 3..10),
        e in 3i64..8,
    ) {
        let terms: Vec<_> = terms
            .into_iter()
            .map(|((re, im), m)| (GaussianRational::new(re.into(), im.into()), m))
            .collect();
        let within = |max_terms| {
            let limits = Limits::default().max_terms(max_terms);
            let vars = ["x", "y", "z"].into_iter().fold(Vars::builder(), |b, v| b.coordinate(v));
            G::from_terms(&vars.limits(limits).build().unwrap(), terms.clone()).expect("small exponents")
        };
        let f = within(Limits::default().max_terms);
        prop_assume!(f.len() > 1);
        let counts: Vec<usize> = (2..=e).map(|k| f.checked_pow(k).unwrap().len()).collect();
        let (most, formed) = (*counts.iter().max().expect("a power"), counts[counts.len() - 1]);
        prop_assert_eq!(within(most).checked_pow(e).map(|g| g.len()), Ok(formed));
        prop_assert_eq!(
            within(formed - 1).checked_pow(e).map(|g| g.len()),
            Err(AlgebraError::TooManyTerms { limit: formed - 1 })
        );
    }

    #[test]
    fn sum_of_products_agrees_with_the_sum(f in gpoly(8), g in gpoly(3), h in gpoly(9), k in gpoly(8), neg in any::<bool>()) {
        let fused = Poly::sum_of_products(&[(&f, &g, false), (&h, &k, neg), (&g, &h, true)]).unwrap();
        let hk = &h * &k;
        let second = if neg { -hk } else { hk };
        prop_assert_eq!(fused, &(&(&f * &g) + &second) - &(&g * &h));
    }

    /// The short path of a sum of products (one gathering, each square's pairs once, the
    /// products' contents brought to one) in the Casimir's shape `c·f·g + h² − k²`, against
    /// the products multiplied one by one; and the same with the squares' signs cancelling.
    #[test]
    fn sum_of_products_with_squares_agrees_with_the_sum(f in gpoly(5), g in gpoly(5), h in gpoly(7), k in gpoly(7), c in rational()) {
        let cf = f.scale(&GaussianRational::from(c));
        let fused = Poly::sum_of_products(&[(&cf, &g, false), (&h, &h, false), (&k, &k, true)]).unwrap();
        prop_assert_eq!(fused, &(&(&cf * &g) + &(&h * &h)) - &(&k * &k));
        let cancelled = Poly::sum_of_products(&[(&h, &h, false), (&cf, &g, false), (&h, &h, true)]).unwrap();
        prop_assert_eq!(cancelled, &cf * &g);
    }

    /// `a ± b` when both have the same terms adds only the contents: `a − a = 0`, and
    /// `c·a + d·a = (c + d)·a`.
    #[test]
    fn sums_of_multiples_of_one_polynomial(f in gpoly(8), c in rational(), d in rational()) {
        let (cf, df) = (f.scale(&GaussianRational::from(c.clone())), f.scale(&GaussianRational::from(d.clone())));
        prop_assert!((&cf - &cf).is_zero());
        prop_assert_eq!(&cf + &df, f.scale(&GaussianRational::from(&c + &d)));
        prop_assert_eq!(&cf - &df, f.scale(&GaussianRational::from(&c - &d)));
    }

    /// The fused kernel of the bracket, for every variable (angles, Laurent exponents, short
    /// and long second factors), against derivatives taken and multiplied one by one.
    #[test]
    fn sum_of_derivative_products_agrees_with_the_sum(f in gpoly(12), g in gpoly(4), h in gpoly(9), k in gpoly(9), a in qpoly(9), b in qpoly(4)) {
        let vars = phase_space();
        for v in vars.vars() {
            let fused = Poly::sum_of_derivative_products(&[(&f, v, &g, false), (&h, v, &k, true)]).unwrap();
            let direct = &(&f.derivative(v).unwrap() * &g) - &(&h.derivative(v).unwrap() * &k);
            prop_assert_eq!(fused, direct);
            if vars.variable(v).kind() != VarKind::Angle {
                let fused = Poly::sum_of_derivative_products(&[(&a, v, &b, true)]).unwrap();
                prop_assert_eq!(fused, -(&a.derivative(v).unwrap() * &b));
            }
        }
    }

    /// A sum of derivative products at a substitution of single terms (the form of a flow on
    /// a condition) is the sum, then the substitution: on every variable, angles and Laurent
    /// exponents included, with values of rational or Gaussian coefficients (negative powers
    /// of a non-unit one and Gaussian ones take the general path), one variable or two at once.
    #[test]
    fn sum_of_derivative_products_at_agrees_with_the_substitution_of_the_sum(
        f in gpoly(12), g in gpoly(3), h in gpoly(9), k in gpoly(2),
        values in proptest::collection::vec((prop_oneof![3 => rational().prop_map(GaussianRational::from), 1 => gaussian()], exponents(true)), 2),
        which in (0usize..8, 0usize..8),
    ) {
        let vars = phase_space();
        let all: Vec<_> = vars.vars().collect();
        let (v, w) = (all[which.0], all[which.1]);
        let values: Vec<G> = values
            .into_iter()
            .map(|term| Poly::from_terms(&vars, [term]).expect("small exponents"))
            .collect();
        prop_assume!(values.iter().all(|t| !t.is_zero()));
        let terms = [(&f, v, &g, false), (&h, w, &k, true), (&f, w, &k, false)];
        let sum = Poly::sum_of_derivative_products(&terms).unwrap();
        let mut subs = vec![(v, values[0].clone())];
        if w != v {
            subs.push((w, values[1].clone()));
        }
        for subs in [&subs[..1], &subs[..]] {
            let fused = Poly::sum_of_derivative_products_at(&terms, subs);
            prop_assert_eq!(fused, sum.subst_many(subs), "at {:?}", subs);
        }
        // First factors free of the substituted variable (as a flow's `f` is free of `p_θ`):
        // the map is applied once per term of the second factor.
        let one = G::one(&vars);
        let (f_free, h_free) = (f.subst(v, &one).unwrap(), h.subst(v, &one).unwrap());
        let terms = [(&f_free, w, &g, false), (&h_free, v, &k, true)];
        let sum = Poly::sum_of_derivative_products(&terms).unwrap();
        let fused = Poly::sum_of_derivative_products_at(&terms, &subs[..1]);
        prop_assert_eq!(fused, sum.subst_many(&subs[..1]), "free of {:?}", v);
    }

    /// The sum of Jacobians (the bracket's kernel) against derivatives multiplied one by one:
    /// short inputs (one pass over the term pairs) and long ones (through the derivatives), on
    /// pairs with no angle, one angle and two.
    #[test]
    fn sum_of_jacobians_agrees_with_the_derivatives(
        f in gpoly(10),
        g in gpoly(10),
        h in proptest::collection::vec((gaussian(), exponents(true)), 30..40),
        k in proptest::collection::vec((gaussian(), exponents(true)), 10..16),
        a in qpoly(9),
        b in qpoly(9),
    ) {
        let vars = phase_space();
        let poly = |terms| G::from_terms(&vars, terms).expect("small exponents");
        let (h, k) = (poly(h), poly(k));
        let v = |name: &str| var(&vars, name);
        let pairs = [(v("x"), v("p_x")), (v("y"), v("p_y")), (v("theta"), v("M")), (v("phi"), v("theta"))];
        let direct = |f: &G, g: &G| {
            pairs.iter().fold(G::zero(&vars), |sum, &(q, p)| {
                let d = |h: &G, w| h.derivative(w).expect("derivative within the limits");
                &(&sum + &(&d(f, q) * &d(g, p))) - &(&d(f, p) * &d(g, q))
            })
        };
        prop_assert_eq!(Poly::sum_of_jacobians(&f, &g, &pairs).unwrap(), direct(&f, &g));
        prop_assert_eq!(Poly::sum_of_jacobians(&h, &k, &pairs).unwrap(), direct(&h, &k));
        let flat = &pairs[..2];
        let sum = flat.iter().fold(Q::zero(&vars), |sum, &(q, p)| {
            let d = |h: &Q, w| h.derivative(w).expect("derivative within the limits");
            &(&sum + &(&d(&a, q) * &d(&b, p))) - &(&d(&a, p) * &d(&b, q))
        });
        prop_assert_eq!(Poly::sum_of_jacobians(&a, &b, flat).unwrap(), sum);
    }

    /// Products with few term pairs are gathered and sorted once; a short factor times a long
    /// one is shifted and merged. Distributivity makes the two meet: `f·(g + h)` has too many
    /// pairs to gather, `f·g` and `f·h` do not.
    #[test]
    fn gathered_products_agree_with_shifted_ones(
        f in proptest::collection::vec((gaussian(), exponents(true)), 5..7),
        g in proptest::collection::vec((gaussian(), exponents(true)), 40..50),
        h in proptest::collection::vec((gaussian(), exponents(true)), 40..50),
    ) {
        let vars = phase_space();
        let poly = |terms| G::from_terms(&vars, terms).expect("small exponents");
        let (f, g, h) = (poly(f), poly(g), poly(h));
        prop_assert_eq!(&f * &(&g + &h), &(&f * &g) + &(&f * &h));
    }

    /// `Integer`'s three tiers (`i64`, `i128`, `BigInt`) compute what `BigInt` computes, and
    /// every result is stored in the tier its size calls for.
    #[test]
    fn integer_arithmetic_agrees_with_bigint(a in integer(), b in integer(), c in integer()) {
        let (x, y) = (Integer::from(a.clone()), Integer::from(b.clone()));
        prop_assert!(canonical(&x) && canonical(&y));
        // Multiples of a common factor, for gcds other than 1 between any two tiers.
        let (ac, bc) = (&a * &c, &b * &c);
        let mut results = vec![
            (&x + &y, &a + &b),
            (&x - &y, &a - &b),
            (&x * &y, &a * &b),
            (-&x, -&a),
            (x.gcd(&y), num_integer::Integer::gcd(&a, &b)),
            (
                Integer::from(ac.clone()).gcd(&Integer::from(bc.clone())),
                num_integer::Integer::gcd(&ac, &bc),
            ),
            (y.gcd(&Integer::from(ac.clone())), num_integer::Integer::gcd(&b, &ac)),
        ];
        if !y.is_zero() {
            results.push(((&x * &y).div_exact(&y), a.clone()));
            prop_assert_eq!(x.is_divisible_by(&y), (&a % &b) == BigInt::from(0));
        }
        for (got, want) in results {
            prop_assert!(canonical(&got), "{got:?} is not canonical");
            prop_assert_eq!(got.to_bigint(), want);
        }
        prop_assert_eq!(x.cmp(&y), a.cmp(&b));
        prop_assert_eq!(x.bits(), a.bits());
        prop_assert_eq!(x.to_string(), a.to_string());
    }

    /// `IntegerAcc` sums products and values of every tier as `BigInt` does: word products
    /// in an `i128`, products of values up to `i128` in 256 bits, the rest as `BigInt`, in
    /// any order; `finish` is canonical. (The 256-bit tier's own overflow, which needs the
    /// largest products several times over, is pinned by a unit test beside the type.)
    #[test]
    fn integer_accumulator_agrees_with_bigint(
        ops in proptest::collection::vec((0u8..3, integer(), integer()), 0..12),
    ) {
        let mut acc = IntegerAcc::default();
        let mut want = BigInt::from(0);
        for (op, a, b) in &ops {
            let (x, y) = (Integer::from(a.clone()), Integer::from(b.clone()));
            match op {
                0 => {
                    acc.add_mul(&x, &y);
                    want += a * b;
                }
                1 => {
                    acc.sub_mul(&x, &y);
                    want -= a * b;
                }
                _ => {
                    acc.add(&x);
                    want += a;
                }
            }
        }
        prop_assert_eq!(acc.is_zero(), want == BigInt::from(0));
        let got = acc.finish();
        prop_assert!(canonical(&got), "{got:?} is not canonical");
        prop_assert_eq!(got.to_bigint(), want);
    }

    /// `GaussianInteger`'s ring operations compute what `BigInt` computes componentwise,
    /// `(a + bi)(c + di) = (ac − bd) + (ad + bc)i`, at the edges of the machine words too:
    /// `(−2⁶³ − 2⁶³i)² = 2¹²⁷i` passes `i128` by one.
    #[test]
    fn gaussian_integer_arithmetic_agrees_with_bigint(
        a in component(), b in component(), c in component(), d in component(), k in component(),
    ) {
        use trigpoly::{GaussianInteger, IntegerRing};
        let gauss = |re: &BigInt, im: &BigInt| {
            GaussianInteger::new(Integer::from(re.clone()), Integer::from(im.clone()))
        };
        let (x, y) = (gauss(&a, &b), gauss(&c, &d));
        let results = [
            (x.mul(&y), (&a * &c - &b * &d, &a * &d + &b * &c)),
            (x.add(&y), (&a + &c, &b + &d)),
            (x.neg(), (-&a, -&b)),
            (x.scale(&Integer::from(k.clone())), (&a * &k, &b * &k)),
            (x.conj(), (a.clone(), -&b)),
            (x.try_mul_i().expect("i is in Z[i]"), (-&b, a.clone())),
        ];
        for (got, (re, im)) in results {
            prop_assert!(canonical(&got.re) && canonical(&got.im), "{got:?} is not canonical");
            prop_assert_eq!((got.re.to_bigint(), got.im.to_bigint()), (re, im));
        }
    }

    /// The content common to two sums: `a = g·sa`, `b = g·sb` with `sa`, `sb` coprime
    /// integers and `g > 0`, on word-sized and larger fractions alike.
    #[test]
    fn content_split_is_the_content_gcd(a in rational(), b in rational(), big in any::<bool>()) {
        prop_assume!(!a.is_zero() && !b.is_zero());
        // Push one side past i64 to cover the general path too.
        let a = if big { &a * &Rational::from(Integer::from_i128(1 << 70)) } else { a };
        let (g, sa, sb) = Rational::content_split(&a, &b);
        prop_assert_eq!(&g, &Rational::content_gcd(&a, &b));
        prop_assert!(g > Rational::zero());
        prop_assert_eq!(&g * &Rational::from(&sa), a);
        prop_assert_eq!(&g * &Rational::from(&sb), b);
        prop_assert!(sa.gcd(&sb).is_one());
    }

    /// Exact division by a prepared divisor (a shift and a multiplication by an inverse for
    /// machine words) undoes multiplication, for quotients and divisors of every size and sign.
    #[test]
    fn exact_division_undoes_multiplication(
        q in numerator(),
        d in prop_oneof![numerator(), -64i64..64, Just(1i64 << 62), Just(-(1i64 << 61) * 3)],
    ) {
        prop_assume!(d != 0);
        let (q, d) = (Integer::from(q), Integer::from(d));
        prop_assert_eq!(ExactDivisor::new(&d).divide(&(&q * &d)), q);
    }

    /// A rational multiple taken by value (a new content on the same terms) is the multiple
    /// by the constant polynomial `q`, zero included.
    #[test]
    fn rational_multiple_is_the_product_by_the_constant(f in gpoly(8), q in rational(), zero in any::<bool>()) {
        let q = if zero { Rational::zero() } else { q };
        let constant = G::constant(&phase_space(), GaussianRational::from(q.clone()));
        prop_assert_eq!(f.scale_rational(&q), &f * &constant);
        prop_assert_eq!(f.clone() * &q, &f * &constant);
    }

    #[test]
    fn ring_mul_associative_dense(f in dense_poly(), g in dense_poly(), h in dense_poly()) {
        prop_assert_eq!((&f * &g) * &h, &f * (&g * &h));
        prop_assert_eq!(&f * (&g + &h), &f * &g + &f * &h);
    }

    /// ∂(fg) = f ∂g + g ∂f for every variable, the angles included.
    #[test]
    fn derivative_leibniz(f in gpoly(8), g in gpoly(8)) {
        let vars = phase_space();
        for v in vars.vars() {
            let d = |h: &G| h.derivative(v).expect("derivative within the limits");
            prop_assert_eq!(d(&(&f * &g)), &f * &d(&g) + &g * &d(&f), "∂/∂{}", vars.variable(v).name());
            prop_assert_eq!(d(&(&f + &g)), d(&f) + d(&g), "∂/∂{}", vars.variable(v).name());
        }
    }

    /// Over Q, for the non-angle variables.
    #[test]
    fn derivative_leibniz_over_q(a in qpoly(8), b in qpoly(8)) {
        let vars = phase_space();
        for v in vars.vars().filter(|&v| vars.variable(v).kind() != VarKind::Angle) {
            let d = |h: &Q| h.derivative(v).expect("derivative within the limits");
            prop_assert_eq!(d(&(&a * &b)), &a * &d(&b) + &b * &d(&a), "∂/∂{}", vars.variable(v).name());
        }
    }

    /// subst(f·g) = subst(f)·subst(g) and subst(f + g) = subst(f) + subst(g), whenever the
    /// substitutions of f and g are defined.
    #[test]
    fn subst_is_ring_homomorphism(f in gpoly(5), g in gpoly(5), k in 0usize..8, value in subst_value()) {
        let vars = phase_space();
        let v = vars.vars().nth(k).expect("8 variables");
        let (Ok(sf), Ok(sg)) = (f.subst(v, &value), g.subst(v, &value)) else {
            // A negative power of a value that is not a single term: rejected, not wrong.
            prop_assert!(!value.is_monomial());
            return Ok(());
        };
        prop_assert_eq!((&f * &g).subst(v, &value).expect("defined"), &sf * &sg);
        prop_assert_eq!((&f + &g).subst(v, &value).expect("defined"), &sf + &sg);
        prop_assert_eq!(f.subst(v, &Poly::var(&vars, v)).expect("identity substitution"), f);
    }

    /// Swapping x ↔ y twice, simultaneously, is the identity; it commutes with products.
    #[test]
    fn subst_many_swap_is_an_involution(f in gpoly(8), g in gpoly(8)) {
        let vars = phase_space();
        let (x, y) = (var(&vars, "x"), var(&vars, "y"));
        let swap = [(x, Poly::var(&vars, y)), (y, Poly::var(&vars, x))];
        let s = |h: &G| h.subst_many(&swap).expect("monomial values");
        prop_assert_eq!(s(&s(&f)), f.clone());
        prop_assert_eq!(s(&(&f * &g)), s(&f) * s(&g));
    }

    /// Collecting in `x` and `θ` gives coefficients free of them, whose terms times their
    /// powers add up to the polynomial again, each exponent once; `sum_all` of any parts is
    /// their sum one after another.
    #[test]
    fn coefficients_in_reassemble_the_polynomial(f in gpoly(9), g in gpoly(6), h in gpoly(6)) {
        let vars = phase_space();
        let (x, theta) = (var(&vars, "x"), var(&vars, "theta"));
        let parts = f.coefficients_in(&[x, theta]);
        let mut keys: Vec<&Vec<i64>> = parts.iter().map(|(k, _)| k).collect();
        keys.sort();
        keys.dedup();
        prop_assert_eq!(keys.len(), parts.len());
        let mut back = G::zero(&vars);
        for (k, c) in &parts {
            prop_assert!(!c.is_zero() && !c.contains(x) && !c.contains(theta));
            let power = G::monomial(&vars, GaussianRational::from(1), &[(x, k[0]), (theta, k[1])])
                .expect("within the limits");
            back += c * &power;
        }
        prop_assert_eq!(back, f.clone());
        let sum = G::sum_all(&vars, vec![f.clone(), g.clone(), h.clone()]).expect("small");
        prop_assert_eq!(sum, &(&f + &g) + &h);
        prop_assert_eq!(G::sum_all(&vars, vec![]).expect("empty"), G::zero(&vars));
    }

    #[test]
    fn print_parse_roundtrip_ascii(f in gpoly(9), a in qpoly(9)) {
        let vars = phase_space();
        let text = f.to_ascii();
        match G::parse(&vars, &text) {
            Ok(back) => prop_assert_eq!(back, f, "{}", text),
            Err(e) => prop_assert!(false, "{}", e.render(&text)),
        }
        let text = a.to_ascii();
        match Q::parse(&vars, &text) {
            Ok(back) => prop_assert_eq!(back, a, "{}", text),
            Err(e) => prop_assert!(false, "{}", e.render(&text)),
        }
    }

    /// A sum times a factor (a rational and powers of `x` and `M`, either sign) reads back
    /// from its factored form, in ASCII and in unicode text, to the same element, every term
    /// of it inside the parentheses.
    #[test]
    fn factored_forms_parse_back(
        f in gpoly(9),
        c in rational(),
        powers in proptest::collection::vec(-3i64..=3, 2),
    ) {
        let vars = phase_space();
        let factor = G::parse(&vars, &format!("({c})*x^({})*M^({})", powers[0], powers[1]))
            .expect("a monomial");
        let g = &f * &factor;
        if let Some(factored) = g.factored() {
            prop_assert!(factored.terms() == g.harmonic_terms().len());
            for text in [factored.render(Style::Ascii), factored.to_string()] {
                match G::parse(&vars, &text) {
                    Ok(back) => prop_assert_eq!(&back, &g, "{}", text),
                    Err(e) => prop_assert!(false, "{}", e.render(&text)),
                }
            }
        }
    }

    /// The unicode text (`Mω²x²/2`, `x p_y`, `cos θ`) parses back to the same element.
    #[test]
    fn print_parse_roundtrip_text(f in gpoly(9)) {
        let vars = phase_space();
        let text = f.to_string();
        match G::parse(&vars, &text) {
            Ok(back) => prop_assert_eq!(back, f, "{}", text),
            Err(e) => prop_assert!(false, "{}", e.render(&text)),
        }
    }

    /// Either form of the angles, harmonics (`cos 2θ`, `cos(2*theta)`, over the two angles
    /// jointly `cos(2θ − 3φ)`) and powers (`cos²θ`, `cos(theta)^2`), in ASCII, unicode text
    /// and LaTeX, parses back to the same element: an independent check of the printer's
    /// conversion, which the parser does not share. The harmonic form has no higher power of
    /// a cosine or a sine than the first, no product of the two angles' functions, and no
    /// argument that starts negative.
    #[test]
    fn both_forms_of_the_angles_parse_back(f in gpoly(9)) {
        let vars = phase_space();
        for angles in Angles::ALL {
            for style in Style::ALL {
                let text = f.render_with(style, angles);
                match G::parse(&vars, &text) {
                    Ok(back) => prop_assert_eq!(back, f.clone(), "{}", text),
                    Err(e) => prop_assert!(false, "{}", e.render(&text)),
                }
            }
        }
        let text = f.render_with(Style::Ascii, Angles::Harmonics);
        prop_assert!(!text.contains("theta)^") && !text.contains("phi)^"), "{}", text);
        prop_assert!(!text.contains("theta)*cos(") && !text.contains("theta)*sin("), "{}", text);
        prop_assert!(!text.contains("cos(-") && !text.contains("sin(-"), "{}", text);
    }

    /// Where one-letter names side by side spell other names (`xy`, `yx`, `ab`, and `xi` with
    /// the imaginary unit), the unicode text still parses back to the same element.
    #[test]
    fn print_parse_roundtrip_text_with_names_that_spell_others(
        terms in proptest::collection::vec(
            (gaussian(), proptest::collection::vec(-3i64..4, 8)),
            0..8,
        ),
    ) {
        let vars = crate::common::coordinates(&["x", "y", "xy", "yx", "a", "b", "ab", "xi"]);
        let f = G::from_terms(&vars, terms).expect("small exponents");
        let text = f.to_string();
        match G::parse(&vars, &text) {
            Ok(back) => prop_assert_eq!(back, f, "{}", text),
            Err(e) => prop_assert!(false, "{}", e.render(&text)),
        }
    }

    /// cos²θ + sin²θ = 1 for every angle, also multiplied by anything.
    #[test]
    fn cos2_plus_sin2_is_one(f in gpoly(9)) {
        let vars = phase_space();
        for theta in vars.angles() {
            let c = G::cos(&vars, theta).expect("an angle");
            let s = G::sin(&vars, theta).expect("an angle");
            prop_assert_eq!(&c * &c + &s * &s, G::one(&vars));
            prop_assert_eq!(&f * &c * &c + &f * &s * &s, f.clone());
        }
    }

    #[test]
    fn conj_is_involution(f in gpoly(9), g in gpoly(9)) {
        prop_assert_eq!(f.conj().conj(), f.clone());
        prop_assert_eq!((&f * &g).conj(), f.conj() * g.conj());
        prop_assert_eq!((&f + &g).conj(), f.conj() + g.conj());
        prop_assert!((&f * &f.conj()).is_real());
    }

    /// f = re f + i·im f with re f and im f real.
    #[test]
    fn re_plus_i_im(f in gpoly(9)) {
        let re = f.re().expect("within the limit");
        let im = f.im().expect("over Q(i)");
        prop_assert!(re.is_real());
        prop_assert!(im.is_real());
        prop_assert_eq!(&re + &im.mul_i().expect("over Q(i)"), f);
    }

    /// The conjugate and both parts at once are `conj f`, `re f` and `im f`: for any `f`, and
    /// for `f e^{3iθ}` with `f` free of `θ`, which shares no monomial with its conjugate (the
    /// shape of a `K_{m,n}`).
    #[test]
    fn conj_re_im_at_once(f in gpoly(9)) {
        let vars = phase_space();
        let theta = var(&vars, "theta");
        let one = G::one(&vars);
        let shifted = &f.subst(theta, &one).unwrap() * &G::exp_i(&vars, theta, 3).unwrap();
        for g in [f, shifted] {
            let (conj, re, im) = g.conj_re_im();
            prop_assert_eq!(&conj, &g.conj());
            prop_assert_eq!(&re, &g.re().expect("within the limit"));
            prop_assert_eq!(&im, &g.im().expect("over Q(i)"));
        }
    }

    /// A product by a single term (a translation, which keeps the coefficients when the
    /// term's integer part is 1) has the product of the values and distributes over a sum
    /// with a product by two terms (another kernel), structurally.
    #[test]
    fn products_by_a_single_term(
        f in gpoly(10), a in qpoly(10), c in gaussian(), e in exponents(true),
        d in gaussian(), e2 in exponents(true), q in rational(), eq in exponents(false),
        r in rational(), er in exponents(false), point in point(),
    ) {
        let vars = phase_space();
        let term = |c: &GaussianRational, e: &[i64]| G::from_terms(&vars, [(c.clone(), e.to_vec())]).expect("small exponents");
        let (m, t) = (term(&c, &e), term(&d, &e2));
        let value = |h: &G| h.eval(&point).expect("every variable has a nonzero value");
        prop_assert_eq!(value(&(&f * &m)), &value(&f) * &value(&m));
        prop_assert_eq!(&(&f * &m) + &(&f * &t), &f * &(&m + &t));
        let mq = Q::from_terms(&vars, [(q, eq)]).expect("small exponents");
        let tq = Q::from_terms(&vars, [(r, er)]).expect("small exponents");
        prop_assert_eq!(&(&a * &mq) + &(&a * &tq), &a * &(&mq + &tq));
    }

    /// The value at a point (summed over one common denominator) is the sum of the terms'
    /// values `c·Π v^e` as fractions, for polynomials and Laurent polynomials over Q and Q(i),
    /// angles included; a variable whose value is zero may appear with non-negative exponents.
    #[test]
    fn eval_is_the_sum_of_the_values_of_the_terms(f in gpoly(12), a in qpoly(12), point in point(), zero_x in any::<bool>()) {
        let vars = phase_space();
        let all: Vec<trigpoly::Var> = vars.vars().collect();
        let by_terms = |terms: Vec<(GaussianRational, Vec<i64>)>, point: &Point| -> GaussianRational {
            terms.into_iter().fold(GaussianRational::default(), |sum, (c, e)| {
                let term = e.iter().enumerate().filter(|(_, &k)| k != 0).fold(c, |t, (j, &k)| {
                    let v = point.value(all[j]).expect("a value");
                    &t * &v.pow(k).expect("nonzero where negative")
                });
                &sum + &term
            })
        };
        let terms_a = a.terms().map(|t| (GaussianRational::from(t.coeff()), t.exponents())).collect();
        prop_assert_eq!(a.eval(&point), Ok(by_terms(terms_a, &point)));
        let (f, point) = if zero_x {
            // x = 0 at the point, and x only to non-negative powers.
            let x = var(&vars, "x");
            let shifted = f.terms().map(|t| {
                let mut e = t.exponents();
                e[x.index()] = e[x.index()].abs();
                (t.coeff(), e)
            });
            (G::from_terms(&vars, shifted).expect("small exponents"), point.with(x, Rational::zero()))
        } else {
            (f, point)
        };
        let terms_f = f.terms().map(|t| (t.coeff(), t.exponents())).collect();
        prop_assert_eq!(f.eval(&point), Ok(by_terms(terms_f, &point)));
    }

    /// Every field width computes the same: under one degree limit, products (short, dense
    /// and heap), sums, squares, derivatives and substitutions print the same in each width,
    /// or fail with the same error when an exponent passes the limit. The widths from 10 bits
    /// up share the limit 511 (the 10-bit field's), so exponents reach their fields' top bits;
    /// all six, 8 bits included, share 127 on the same terms with exponents quartered.
    #[test]
    fn every_field_width_computes_the_same(
        f in proptest::collection::vec((rational(), proptest::collection::vec(wide_exponent(), 6)), 0..30),
        g in proptest::collection::vec((rational(), proptest::collection::vec(wide_exponent(), 6)), 0..12),
    ) {
        let quarter = |terms: &[(Rational, Vec<i64>)]| -> Vec<(Rational, Vec<i64>)> {
            terms.iter().map(|(c, e)| (c.clone(), e.iter().map(|x| x / 4).collect())).collect()
        };
        let groups = [
            (&trigpoly::FIELD_BITS[1..], 511, f.clone(), g.clone()),
            (&trigpoly::FIELD_BITS[..], 127, quarter(&f), quarter(&g)),
        ];
        for (widths, limit, f, g) in groups {
            let results: Vec<Vec<String>> = widths
                .iter()
                .map(|&bits| same_computation_in(bits, limit, &f, &g))
                .collect();
            for (bits, r) in widths.iter().zip(&results).skip(1) {
                prop_assert_eq!(r, &results[0], "{} bits against {}", bits, widths[0]);
            }
        }
    }

    /// eval(f·g) = eval(f)·eval(g), eval(f + g) = eval(f) + eval(g), at rational points with
    /// the angles on rational points of the unit circle.
    #[test]
    fn eval_is_ring_homomorphism(f in gpoly(9), g in gpoly(9), a in qpoly(6), point in point()) {
        let e = |h: &G| h.eval(&point).expect("every variable has a nonzero value");
        prop_assert_eq!(e(&(&f * &g)), &e(&f) * &e(&g));
        prop_assert_eq!(e(&(&f + &g)), &e(&f) + &e(&g));
        prop_assert_eq!(e(&f.conj()), e(&f).conj());
        let ea = a.eval(&point).expect("every variable has a value");
        prop_assert!(ea.is_real());
        prop_assert_eq!(ea, e(&a.to_gaussian()));
    }
}

/// Two polynomials on the monomials of `(x + y^a + z^b + t^c)^10` (286 of them), with the same
/// random `a, b, c` and random Gaussian coefficients (small, up to a word, or `i64::MAX`; for
/// half the pairs all small):
/// their product has 286² ≈ 82 k term pairs on at most 1771 monomials, in a box too sparse for
/// the dense accumulators, and takes the hashed product, in words or in accumulators.
fn meeting_pair() -> impl Strategy<Value = (G, G)> {
    static VARS: std::sync::OnceLock<trigpoly::Vars> = std::sync::OnceLock::new();
    let vars = VARS
        .get_or_init(|| crate::common::coordinates(&["x", "y", "z", "t"]))
        .clone();
    let coeff = prop_oneof![
        6 => -50i64..50,
        1 => (1i64 << 40)..(1i64 << 62),
        1 => Just(i64::MAX),
    ];
    let coefficients = proptest::collection::vec((coeff.clone(), coeff), 286);
    let exponents = (5i64..40, 5i64..40, 5i64..40);
    (exponents, 0u8..3, coefficients.clone(), coefficients).prop_map(
        move |((a, b, c), kind, f, g)| {
            let mut monomials = Vec::new();
            for i in 0..=10 {
                for j in 0..=10 - i {
                    for k in 0..=10 - i - j {
                        monomials.push(vec![i, a * j, b * k, c * (10 - i - j - k)]);
                    }
                }
            }
            // A third of the pairs small throughout, so that their sums stay in words; a third
            // with each coefficient real or imaginary (the 256-bit sums, past words).
            let small = kind == 0;
            let coefficient = |v: i64| Rational::from(if small { v % 50 } else { v });
            let part = |(re, im): (i64, i64)| match (kind, (re ^ im) & 1) {
                (2, 0) => (re, 0),
                (2, _) => (0, im),
                _ => (re, im),
            };
            let poly = |cs: Vec<(i64, i64)>| {
                let cs = cs
                    .into_iter()
                    .map(part)
                    .map(|(re, im)| GaussianRational::new(coefficient(re), coefficient(im)));
                Poly::from_terms(&vars, cs.zip(monomials.clone())).expect("small exponents")
            };
            (poly(f), poly(g))
        },
    )
}

proptest! {
    #![proptest_config(Config { cases: 8, ..config() })]

    /// Products and squares whose term pairs meet on few monomials (the hashed product)
    /// equal the sums of the products by single terms.
    #[test]
    fn products_meeting_on_few_monomials_agree_with_sum_of_term_products((f, g) in meeting_pair()) {
        prop_assert_eq!(&f * &g, product_by_terms(&f, &g));
        prop_assert_eq!(&f * &f, product_by_terms(&f, &f));
    }
}

/// The variables of a rational potential: two coordinates, a momentum, a parameter, and the
/// denominators `x − y` and `x + y`.
fn with_denominators() -> trigpoly::Vars {
    trigpoly::Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .momentum("p_x")
        .parameter("a")
        .denominator("x - y")
        .unwrap()
        .denominator("x + y")
        .unwrap()
        .build()
        .expect("valid names")
}

/// Sums of terms `c x^i y^j p_x^k a^l/((x − y)^e (x + y)^f)` with Laurent powers of `y`: the
/// partial fractions a search writes its integrals in.
fn rational_potential_element() -> impl Strategy<Value = String> {
    let term = (
        -4i64..=4,
        0i64..=2,
        -2i64..=2,
        0i64..=1,
        0i64..=1,
        0i64..=2,
        0i64..=2,
    );
    proptest::collection::vec(term, 1..7).prop_map(|terms| {
        let text: Vec<String> = terms
            .into_iter()
            .map(|(c, i, j, k, l, e, f)| {
                format!("{c}*x^{i}*y^({j})*p_x^{k}*a^{l}/((x - y)^{e}*(x + y)^{f})")
            })
            .collect();
        text.join(" + ")
    })
}

proptest! {
    #![proptest_config(Config { cases: 48, ..config() })]

    /// A result shown over common denominators is the same element, its printed ASCII reads
    /// back to it, and an element that is zero written another way shows as 0.
    #[test]
    fn over_common_denominators_is_the_same_element_and_reads_back(text in rational_potential_element()) {
        let vars = with_denominators();
        let p = Poly::<Rational>::parse(&vars, &text).expect("reads");
        let shown = p.over_common_denominators().expect("shown");
        prop_assert!(shown.checked_sub(&p).unwrap().vanishes().unwrap(), "{} is not {}", shown, p);
        let back = Poly::<Rational>::parse(&vars, &shown.to_ascii()).expect("the ASCII reads back");
        prop_assert!(back.checked_sub(&p).unwrap().vanishes().unwrap(), "{} read back as {}", shown.to_ascii(), back);
        // (x − y)/(x − y) is 1 written another way.
        let one = Poly::<Rational>::parse(&vars, "(x - y)/(x - y)").expect("reads");
        let zero = p.checked_mul(&one).unwrap().checked_sub(&p).unwrap();
        prop_assert!(!zero.is_zero() || p.is_zero());
        prop_assert_eq!(zero.over_common_denominators().unwrap().to_string(), "0");
    }
}

/// A small polynomial in `x`, `y`, `k` as text: up to three terms with small coefficients.
fn small_text() -> impl Strategy<Value = String> {
    prop::collection::vec((-4i64..=4, 0u8..3, 0u8..3, 0u8..2), 1..4).prop_map(|terms| {
        let text: Vec<String> = terms
            .into_iter()
            .map(|(c, i, j, l)| format!("({c})*x^{i}*y^{j}*k^{l}"))
            .collect();
        text.join(" + ")
    })
}

proptest! {
    #![proptest_config(Config { cases: 48, ..config() })]

    /// Division by `r^e (A + B r)`, with `A`, `B` random nonzero polynomials free of
    /// `r = √(x² + y² + k)`, goes through the conjugate: the quotient times the divisor is 1,
    /// as an element, and where the norm `A² − B² R` is refused (no single term, say), it is
    /// by name, and declaring it as a denominator makes the division go through.
    #[test]
    fn division_by_a_sum_with_a_radical_inverts_it(a in small_text(), b in small_text(), e in -1i64..=1) {
        let base = || trigpoly::Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .parameter("k")
            .radical("r", "x^2 + y^2 + k");
        let plain = base().build().unwrap();
        let parse = |vars: &trigpoly::Vars, s: &str| Poly::<Rational>::parse(vars, s);
        let (pa, pb) = (parse(&plain, &a).unwrap(), parse(&plain, &b).unwrap());
        prop_assume!(!pa.is_zero() && !pb.is_zero());
        let divisor = format!("r^({e})*(({a}) + ({b})*r)");
        let quotient = format!("1/({divisor})");
        let vars = match parse(&plain, &quotient) {
            Ok(_) => plain.clone(),
            Err(refused) => {
                let refused = refused.to_string();
                prop_assert!(refused.contains("a division by its norm"), "{refused}");
                let radicand = parse(&plain, "x^2 + y^2 + k").unwrap();
                let norm = pa.checked_mul(&pa).unwrap()
                    .checked_sub(&pb.checked_mul(&pb).unwrap().checked_mul(&radicand).unwrap())
                    .unwrap();
                let ascii = norm.to_ascii();
                prop_assert!(refused.contains(&(-&norm).to_ascii()) || refused.contains(&ascii), "{refused}");
                base().denominator(&ascii).unwrap().build().unwrap()
            }
        };
        let d = parse(&vars, &divisor).unwrap();
        let inverse = parse(&vars, &quotient).unwrap();
        let product = d.checked_mul(&inverse).unwrap();
        prop_assert!(
            product.checked_sub(&Poly::one(&vars)).unwrap().vanishes().unwrap(),
            "({divisor}) · {inverse} = {product}"
        );
    }
}

/// The pieces of the random texts the parser is fed: names of the phase space and names run
/// together, numbers, operators and brackets of the plain syntax, superscripts, empty groups,
/// Unicode functions (`sin²θ`), displays (`∂H`, `∇`), and LaTeX (`\sin^{2}\theta`, `{}^{3}`,
/// `\frac{1}{2}`, `\partial`, spacing and sizing).
#[rustfmt::skip]
const PARSER_TOKENS: &[&str] = &[
    "x", "y", "p_x", "p_y", "theta", "θ", "phi", "φ", "M", "omega", "ω", "Mω", "xy", "i", "Re",
    "Im", "H", "0", "1", "2", "3", "10", "+", "-", "−", "*", "·", "/", "÷", "^", "**", "(", ")",
    "{", "}", ",", "_", "'", " ", "²", "³", "⁻¹", "⁻", "¹", "⁰", "²³", "{}", "{}^", "{}²", "{ }³",
    "^{2}", "^{-1}", "^{", "^2", "^-1", "sqrt(", "cos", "sin", "exp", "cos(", "sin(", "exp(",
    "Re(", "Im(", "conj(", "sin²", "cos³θ", "sin²θ", "sin²(θ)", "e^{", "e^{iθ}", "∂", "∇", "∂H",
    "(∂H)", "_{", "_{1,2}", r"\sin", r"\cos", r"\exp", r"\theta", r"\omega", r"\varphi", r"\phi",
    r"\frac{1}{2}", r"\frac{", r"\tfrac", r"\sqrt{x}", r"\sqrt", r"\partial", r"\nabla",
    r"\partial H", r"\sin^{2}", r"\sin^{2}\theta", "x^{2}{}^{3}", "Mω^{2}", "Mω^{2}{}^{3}",
    r"\Re", r"\operatorname{Re}", r"\mathrm{i}", r"\bar{M}", r"\bar{}", r"p_{\theta}", r"\,",
    r"\;", r"\quad", r"\left(", r"\right)", r"\left.", r"\left", r"\big(", r"\bigr)", r"\{",
    r"\}", r"\cdot", r"\times", r"\", r"\unknown", "₁", "1e3", "0.5", "√", "√(", "½", "\u{feff}",
    "ϕ", "ϵ", "ε", r"\epsilon", r"\varepsilon", r"\sin^{2}^", r"\cos cos", r"p_{\left(",
];

/// The factors of [`parser_text`]'s sums, in the plain syntax, in Unicode and in LaTeX.
#[rustfmt::skip]
const PARSER_FACTORS: &[&str] = &[
    "x", "y", "p_x", "p_y", "θ", r"\theta", "phi", r"\varphi", "M", "ω", r"\omega", "Mω", "xy",
    "i", r"\mathrm{i}", "2", "3", r"\frac{1}{2}", r"\frac{x}{M}", "Re(x)", "Im(y)",
    r"\operatorname{Re}(x)", "Re", "sin θ", "cos(θ)", "sin²θ", "cos³θ", r"\sin^{2}\theta",
    r"\cos\varphi", "sin²(θ)", "e^{iθ}", "exp(i*phi)", "conj(x)", r"\left(x + y\right)",
    "(x - p_x)", r"p_{\theta}", r"\frac{p_{x}^{2}}{2 M}",
];

/// The powers of [`PARSER_FACTORS`], as the parser reads them, and two superscripts side by
/// side (`^2²`, `²{}^{3}`), which it refuses as ambiguous.
#[rustfmt::skip]
const PARSER_POWERS: (&[&str], &[&str]) = (
    &["^2", "²", "³", "⁻¹", "^{2}", "^{-1}", "{}^{2}", "{}²", "^(2)"],
    &["^2²", "²^3", "²{}^{3}", "^{2}{}^{3}", "{}^{2}{}²"],
);

/// What stands between the factors of [`parser_text`]'s terms: nothing, a space or an
/// operator.
#[rustfmt::skip]
const PARSER_JOINTS: &[&str] = &[
    " ", " ", "", "*", " · ", r" \cdot ", r"\,", " + ", " - ", " − ", r" \times ", "/",
];

/// A factor of [`PARSER_FACTORS`] to a power of [`PARSER_POWERS`] or none.
fn parser_factor() -> impl Strategy<Value = String> {
    let power = prop_oneof![
        8 => Just(""),
        6 => proptest::sample::select(PARSER_POWERS.0),
        1 => proptest::sample::select(PARSER_POWERS.1),
    ];
    (proptest::sample::select(PARSER_FACTORS), power).prop_map(|(a, p)| format!("{a}{p}"))
}

/// A sum of products of [`parser_factor`]s, the factors side by side or apart by an
/// operator, a term in parentheses now and then, with a few of [`PARSER_TOKENS`] put in or
/// a few characters taken out, so that it is well formed or one slip from it; or a text of
/// up to twelve of [`PARSER_TOKENS`].
fn parser_text() -> impl Strategy<Value = String> {
    let joint = proptest::sample::select(PARSER_JOINTS);
    let term = proptest::collection::vec((parser_factor(), joint), 1..4).prop_map(|factors| {
        let mut text = String::new();
        for (k, (factor, joint)) in factors.iter().enumerate() {
            if k > 0 {
                text.push_str(joint);
            }
            text.push_str(factor);
        }
        text
    });
    let expression = proptest::collection::vec((term, any::<bool>()), 1..4).prop_map(|terms| {
        let terms: Vec<String> = terms
            .into_iter()
            .map(|(t, wrapped)| if wrapped { format!("({t})^2") } else { t })
            .collect();
        terms.join(" + ")
    });
    let index = any::<prop::sample::Index>;
    let slip = (
        proptest::collection::vec((index(), proptest::sample::select(PARSER_TOKENS)), 0..2),
        proptest::option::weighted(0.3, (index(), 1usize..4)),
    );
    let slipped = (expression, slip).prop_map(|(mut text, (tokens, cut))| {
        let places = |text: &str| -> Vec<usize> {
            (0..=text.len())
                .filter(|&k| text.is_char_boundary(k))
                .collect()
        };
        for (at, token) in tokens {
            text.insert_str(*at.get(&places(&text)), token);
        }
        if let Some((at, n)) = cut {
            let places = places(&text);
            let start = *at.get(&places);
            let end = places
                .iter()
                .copied()
                .filter(|&k| k >= start)
                .nth(n)
                .unwrap_or(text.len());
            text.replace_range(start..end, "");
        }
        text
    });
    let soup = proptest::collection::vec(
        (proptest::sample::select(PARSER_TOKENS), any::<bool>()),
        1..12,
    )
    .prop_map(|pieces| {
        pieces
            .into_iter()
            .map(|(token, spaced)| {
                if spaced {
                    format!("{token} ")
                } else {
                    token.to_string()
                }
            })
            .collect()
    });
    prop_oneof![3 => slipped, 1 => soup]
}

/// The phase space of [`phase_space`], and the same with a parameter `Re`, with limits that
/// refuse a large power at once (a power of a sum to a hundred, `(x - p_x)^102`, takes
/// seconds in a debug build).
fn parser_vars() -> &'static [trigpoly::Vars; 2] {
    static VARS: std::sync::OnceLock<[trigpoly::Vars; 2]> = std::sync::OnceLock::new();
    VARS.get_or_init(|| {
        let build = |parameters: &[&str]| {
            let builder = crate::common::phase_space_builder();
            parameters
                .iter()
                .fold(builder, |b, name| b.parameter(name))
                .limits(
                    trigpoly::Limits::default()
                        .max_terms(2_000)
                        .max_degree(40)
                        .max_term_products(200_000),
                )
                .build()
                .expect("valid variable names")
        };
        [build(&[]), build(&["Re"])]
    })
}

proptest! {
    #![proptest_config(Config { cases: 1024, ..config() })]

    /// The parser reads any text of its tokens to a tree or a refusal, never a panic, alone
    /// and through the lowering (with `Re` a function and with `Re` declared), and a text it
    /// reads to an element prints, in Unicode and in ASCII, to a text that reads back to it.
    #[test]
    fn any_text_of_the_parsers_tokens_reads_or_is_refused(text in parser_text()) {
        if let Err(e) = trigpoly::syntax::parse_expr(&text) {
            let _ = e.render(&text);
        }
        for vars in parser_vars() {
            match G::parse(vars, &text) {
                Ok(f) => {
                    for shown in [f.to_string(), f.to_ascii()] {
                        match G::parse(vars, &shown) {
                            Ok(back) => prop_assert_eq!(&back, &f, "{} printed {}", text, shown),
                            Err(e) => prop_assert!(false, "{} printed {}: {}", text, shown, e.render(&shown)),
                        }
                    }
                }
                Err(e) => {
                    let _ = e.render(&text);
                }
            }
            if let Err(e) = Q::parse(vars, &text) {
                let _ = e.render(&text);
            }
        }
    }
}
