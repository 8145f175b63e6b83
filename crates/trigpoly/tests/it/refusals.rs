//! Refusals as data: each way the algebra refuses is a variant of [`AlgebraError`] that a
//! program matches on, with what went wrong in its fields, and its message as it reads.

use pretty_assertions::assert_eq;
use trigpoly::{
    AlgebraError, AngleUse, BadName, Expr, Integer, Misuse, MonomialIndex, Point, Poly, Rational,
    Setting, VarKind, Vars,
};

use crate::common::{p, phase_space, var, G, Q};

/// A reserved word as a variable's name: the name and the reason, not a sentence to parse.
#[test]
fn a_reserved_name_is_refused_with_the_name() {
    let err = Vars::builder()
        .coordinate("x")
        .parameter("sin")
        .build()
        .map(|_| ())
        .unwrap_err();
    assert_eq!(
        err,
        AlgebraError::InvalidName {
            name: "sin".into(),
            reason: BadName::Reserved,
        }
    );
    assert_eq!(
        err.to_string(),
        "\"sin\" cannot name a variable: i, cos, sin, exp, conj, re, im and sqrt are reserved"
    );
    let Err(AlgebraError::InvalidName { name, reason }) = Vars::builder().momentum("a__b").build()
    else {
        panic!("a__b is refused by name");
    };
    assert_eq!((name.as_str(), reason), ("a__b", BadName::EmptySubscript));
}

/// Nine radicals, one past the most a set may declare: the count, as a setting out of range.
#[test]
fn too_many_radicals_are_a_setting_out_of_range() {
    let mut builder = Vars::builder().coordinate("x");
    for k in 1..=9 {
        builder = builder.radical(&format!("r{k}"), &format!("x + {k}"));
    }
    let vars = builder.build().unwrap();
    let err = Expr::check_radicals(&vars).unwrap_err();
    assert_eq!(
        err,
        AlgebraError::SettingOutOfRange {
            setting: Setting::Radicals,
            value: 9,
        }
    );
    assert_eq!(
        err.to_string(),
        "9 radicals are declared; at most 8 are supported"
    );
}

/// A radicand that is a square, and a denominator that is a single term: each names what was
/// declared.
#[test]
fn a_refused_declaration_names_what_was_declared() {
    let square = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .radical("r", "x^2 + 2*x*y + y^2")
        .build()
        .unwrap();
    let err = Expr::check_radicals(&square).unwrap_err();
    assert!(
        matches!(&err, AlgebraError::RadicalRefused { radicals, .. } if radicals == &["r"]),
        "{err:?}"
    );
    assert!(
        err.to_string()
            .starts_with("the radicand of r = √(x² + 2xy + y²) is the square of x + y"),
        "{err}"
    );
    let constant = Vars::builder()
        .coordinate("x")
        .radical("s", "2")
        .build()
        .unwrap();
    let err = Expr::radicals(&constant).unwrap_err();
    assert!(
        matches!(&err, AlgebraError::RadicalRefused { radicals, .. } if radicals == &["s"]),
        "{err:?}"
    );
    let err = Vars::builder()
        .coordinate("x")
        .denominator("2*x")
        .unwrap_err();
    assert_eq!(
        err,
        AlgebraError::DenominatorRefused {
            denominator: "(2*x)".into(),
            message: "2x is a single term: division by it is exact already, so declare only \
                      sums (such as \"x - y\") as denominators"
                .into(),
        }
    );
    assert!(
        err.to_string()
            .starts_with("2x is a single term: division by it is exact"),
        "{err}"
    );
}

/// A coordinate where an angle must be: which use, which variable, what it is instead.
#[test]
fn a_coordinate_is_not_an_angle() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let err = G::exp_i(&vars, x, 2).unwrap_err();
    assert_eq!(
        err,
        AlgebraError::NotAnAngle {
            needed_by: AngleUse::ExpI,
            var: "x".into(),
            kind: VarKind::Coordinate,
        }
    );
    assert_eq!(
        err.to_string(),
        "e^{inθ} needs an angle, and x is not declared as one"
    );
    let p_y = var(&vars, "p_y");
    let err = Point::new(&vars)
        .with_angle(p_y, Rational::new(3, 5), Rational::new(4, 5))
        .unwrap_err();
    assert_eq!(
        err,
        AlgebraError::NotAnAngle {
            needed_by: AngleUse::PointWithAngle,
            var: "p_y".into(),
            kind: VarKind::Momentum,
        }
    );
    assert_eq!(
        err.to_string(),
        "Point::with_angle sets an angle, and p_y is a momentum"
    );
}

/// A power of a constant whose coefficient would pass the fixed bound on its size: the bound,
/// which no limit of the set raises.
#[test]
fn a_power_past_the_coefficient_bound_is_refused_with_the_bound() {
    let vars = phase_space();
    let half: Q = p(&vars, "3/2");
    let err = half.checked_pow(1 << 30).unwrap_err();
    assert_eq!(
        err,
        AlgebraError::CoefficientTooLarge {
            bits: 2 << 30,
            limit: 1 << 24,
        }
    );
    assert_eq!(
        err.to_string(),
        "a coefficient formed by a product, a power or a bracket would have more than \
         16777216 bits"
    );
}

/// The constant `2^bits` of the phase space `vars`, a coefficient of `bits + 1` bits.
fn power_of_two(vars: &Vars, bits: usize) -> Q {
    let c = Integer::from_bigint(num_bigint::BigInt::from(1) << bits);
    Poly::constant(vars, Rational::from(c))
}

/// A product, or a power of a sum, whose coefficients would pass the same bound is refused
/// with it too: `(c x + y)^100` and `F*F*…` of a `c`, an `F`, of millions of bits multiplied
/// for minutes, the bound checked only on a power of a single term.
#[test]
fn products_and_powers_of_sums_past_the_coefficient_bound_are_refused() {
    let vars = phase_space();
    let huge = |bits: usize| power_of_two(&vars, bits);
    let (x, y): (Q, Q) = (p(&vars, "x"), p(&vars, "y"));
    let past = |r: Result<Q, AlgebraError>| match r {
        Err(AlgebraError::CoefficientTooLarge { limit, .. }) => limit == 1 << 24,
        _ => false,
    };
    // A constant of 9·10⁶ bits: its square would pass 2²⁴ bits, and so would that of c x + y.
    let c = huge(9_000_000);
    assert!(past(c.checked_mul(&c)));
    let sum = c.checked_mul(&x).unwrap().checked_add(&y).unwrap();
    assert!(past(sum.checked_mul(&sum)));
    // Of a million bits: c x + y takes a power of 16 (1.6·10⁷ bits), not of 17.
    let sum = huge(1_000_000)
        .checked_mul(&x)
        .unwrap()
        .checked_add(&y)
        .unwrap();
    assert!(past(sum.checked_pow(17)));
    assert_eq!(sum.checked_pow(2).unwrap().len(), 3);
    // Under the bound nothing changes: a product of two constants of 8·10⁶ bits is one.
    let half = huge(8_000_000);
    assert_eq!(half.checked_mul(&half).unwrap(), huge(16_000_000));
}

/// The bracket's fused kernels, which form their products themselves, check the same bound:
/// a chain `A' = {A, B}` of single terms `c x²`, `c x p_x` doubled its coefficients' bits at
/// every step with no refusal (the contents multiplied in the short kernel), 2²⁹ bits in
/// 250 s and 860 MB nine steps from 10⁶, where a product refuses past 2²⁴.
#[test]
fn brackets_and_sums_of_products_past_the_coefficient_bound_are_refused() {
    let vars = phase_space();
    let huge = |bits: usize| power_of_two(&vars, bits);
    let past = |r: Result<Q, AlgebraError>| match r {
        Err(AlgebraError::CoefficientTooLarge { limit, .. }) => limit == 1 << 24,
        other => panic!("{:?}", other.map(|q| q.len())),
    };
    let (x, y, px) = (var(&vars, "x"), var(&vars, "y"), var(&vars, "p_x"));
    let c = huge(9_000_000);
    let times = |c: &Q, s: &str| c.checked_mul(&p(&vars, s)).unwrap();
    // Single terms: the contents carry the bits (the short kernel).
    let (f, g) = (times(&c, "x^2"), times(&c, "x*p_x"));
    past(Poly::sum_of_jacobians(&f, &g, &[(x, px)]));
    // The message names the bracket, which refuses it as a product does: it said "this
    // product or power" of a bracket too.
    let message = Poly::sum_of_jacobians(&f, &g, &[(x, px)])
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("a product, a power or a bracket"),
        "{message}"
    );
    past(Poly::sum_of_products(&[(&f, &g, false)]));
    past(Poly::sum_of_derivative_products(&[(&f, x, &g, false)]));
    let at_y = [(y, p(&vars, "x"))];
    past(Poly::sum_of_derivative_products_at(
        &[(&f, x, &g, false)],
        &at_y,
    ));
    // Sums whose primitive parts carry them (the streams of the general kernels).
    let f = f.checked_add(&p(&vars, "p_x^2")).unwrap();
    let g = g.checked_add(&p(&vars, "x")).unwrap();
    past(Poly::sum_of_jacobians(&f, &g, &[(x, px)]));
    past(Poly::sum_of_products(&[(&f, &g, false)]));
    past(Poly::sum_of_derivative_products(&[(&f, x, &g, false)]));
    past(Poly::sum_of_derivative_products_at(
        &[(&f, x, &g, false)],
        &at_y,
    ));
    // Under the bound the bracket is formed: of two factors of 10⁶ bits, as their product.
    let c = huge(1_000_000);
    let (f, g) = (times(&c, "x^2"), times(&c, "x*p_x"));
    assert_eq!(
        Poly::sum_of_jacobians(&f, &g, &[(x, px)]).unwrap(),
        times(&c.checked_mul(&c).unwrap(), "2*x^2")
    );
}

/// The bound is on the coefficients a product has, a numerator and a denominator apart: one
/// factor's denominator may cancel the other's numerator, `(c x)·(y/c) = x y`, and a sum over
/// a large denominator keeps it, `(x + y/c)² = x² + 2xy/c + y²/c²`. Those were refused,
/// their bits counted as the factors' numerators' and denominators' added.
#[test]
fn products_whose_coefficients_cancel_or_keep_a_denominator_are_not_refused() {
    let vars = phase_space();
    let power_of_two = |bits: usize| -> Rational {
        Rational::from(Integer::from_bigint(num_bigint::BigInt::from(1) << bits))
    };
    let (x, y): (Q, Q) = (p(&vars, "x"), p(&vars, "y"));
    // A constant of 8.4·10⁶ bits and its inverse: their product's coefficient is 1.
    let c = power_of_two(8_400_000);
    let cx = &x * &c;
    let y_over_c = &y * &c.try_inv().unwrap();
    assert_eq!(cx.checked_mul(&y_over_c).unwrap(), &x * &y);
    // Over a constant of 6·10⁶ bits, x + y/c has coefficients of 1.2·10⁷ bits squared.
    let c = power_of_two(6_000_000);
    let sum = x.checked_add(&(&y * &c.try_inv().unwrap())).unwrap();
    let square = sum.checked_mul(&sum).unwrap();
    assert_eq!(square.len(), 3);
    assert_eq!(sum.checked_pow(2).unwrap(), square);
}

/// Arguments that do not fit together: the counts that differ.
#[test]
fn misuse_says_which_counts_differ() {
    let vars = phase_space();
    let mut index = MonomialIndex::new(&vars);
    let err = index.insert(&[1, 2], ()).unwrap_err();
    assert_eq!(
        err,
        AlgebraError::Misuse(Misuse::ExponentCount {
            exponents: 2,
            variables: 8,
        })
    );
    assert_eq!(err.to_string(), "2 exponents for 8 variables");
    let err = G::sum_of_products(&[]).unwrap_err();
    assert_eq!(err, AlgebraError::Misuse(Misuse::EmptySum));
    assert_eq!(
        err.to_string(),
        "an empty sum of products has no variable set"
    );
}

/// A denominator declared in code by its polynomial alone
/// ([`trigpoly::VarsBuilder::denominator`]): its printed forms are derived from it, so
/// they agree with what it reads as (`a2 - a1` prints as its normal form, `(−a1 + a2)`, and
/// reads back), and a polynomial that cannot be one is refused with its text and the reason,
/// as a system file's is: one that names a variable not declared before it, a single term, one
/// that is not real, one with a radical in it (the message, a library's, names no program),
/// and one that a denominator declared before it already divides (itself again, or its
/// square).
#[test]
fn a_denominator_declared_in_code_is_checked() {
    let builder = || {
        Vars::builder()
            .coordinate("q")
            .parameter("a1")
            .parameter("a2")
    };
    let vars = builder().denominator("a2 - a1").unwrap().build().unwrap();
    let atom = vars.denominators().next().unwrap();
    assert_eq!(vars.variable(atom).unicode(), "(−a1 + a2)");
    let e = Expr::parse(&vars, "q/(a1 - a2)").unwrap();
    assert_eq!(e.to_string(), "−q/(−a1 + a2)");
    assert_eq!(Expr::parse(&vars, &e.to_ascii()).unwrap(), e);
    assert_eq!(Expr::denominator_atoms(&vars).unwrap().len(), 1);

    let refusal = |b: trigpoly::VarsBuilder, text: &str| match b.denominator(text) {
        Err(AlgebraError::DenominatorRefused {
            denominator,
            message,
        }) => {
            assert_eq!(denominator, format!("({text})"));
            message
        }
        other => panic!("{text}: {other:?}"),
    };
    let message = refusal(builder(), "a1 - b");
    assert!(
        message.starts_with("the denominator a1 - b does not read"),
        "{message}"
    );
    assert_eq!(
        refusal(builder(), "2*a1"),
        "2 a1 is a single term: division by it is exact already, so declare only sums (such as \
         \"x - y\") as denominators"
    );
    assert_eq!(
        refusal(builder(), "a1 + i*a2"),
        "the denominator a1 + i a2 is not real"
    );
    let radical = refusal(builder().radical("r", "q^2 + 1"), "r + q");
    assert!(
        radical.starts_with("the denominator q + r has a radical in it")
            && radical.ends_with("divide by q + r where it stands instead, which a division does through its conjugates"),
        "{radical}"
    );
    let declared = || builder().denominator("a1 - a2").unwrap();
    for again in ["a1 - a2", "(a1 - a2)^2", "a2 - a1"] {
        assert!(
            refusal(declared(), again)
                .contains("is a product of the denominators declared before it"),
            "{again}"
        );
    }
}
