//! Substitution and exact evaluation on named examples.

use trigpoly::{AlgebraError, GaussianRational, Point, Poly, Rational};

use crate::common::{p, phase_space, var, G, Q};

#[test]
fn subst_of_angle_doubles_the_angle() {
    let vars = phase_space();
    let theta = var(&vars, "theta");
    let double: G = p(&vars, "exp(2*i*theta)");
    // Substituting e^{iθ} ↦ e^{2iθ} maps cos θ to cos 2θ = 2cos²θ − 1, sin θ to sin 2θ.
    let c: G = p(&vars, "cos(theta)");
    assert_eq!(c.subst(theta, &double), Ok(p(&vars, "2*cos(theta)^2 - 1")));
    let s: G = p(&vars, "x*sin(theta)^3");
    assert_eq!(s.subst(theta, &double), Ok(p(&vars, "x*sin(2*theta)^3")));
    // e^{iθ} ↦ e^{−iθ} is complex conjugation on a function of θ alone with real coefficients.
    let f: G = p(&vars, "cos(theta)^2 + 3*sin(theta) - i*sin(2*theta)");
    let flip: G = p(&vars, "exp(-i*theta)");
    assert_eq!(
        f.subst(theta, &flip),
        Ok(p(&vars, "cos(theta)^2 - 3*sin(theta) + i*sin(2*theta)"))
    );
}

#[test]
fn subst_of_a_coordinate_by_a_sum_expands_the_binomial() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let f: G = p(&vars, "x^3 - M*x");
    let shifted: G = p(&vars, "x + y");
    assert_eq!(
        f.subst(x, &shifted),
        Ok(p(&vars, "x^3 + 3*x^2*y + 3*x*y^2 + y^3 - M*x - M*y"))
    );
    // A negative power of a sum is not a Laurent polynomial: refused with what to declare.
    let g: G = p(&vars, "1/x");
    let refused = "cannot substitute x + y for x: it appears with exponent -1, and only single \
                   terms (monomials) and products of powers of declared denominators are \
                   invertible; declare it (or its factors) as a denominator: denominators = \
                   [\"x + y\"] in [phase_space]";
    let err = g.subst(x, &shifted).unwrap_err();
    assert_eq!(err.to_string(), refused);
    assert_eq!(
        err,
        AlgebraError::UninvertibleSubstitution {
            shown: "x + y".into(),
            var: "x".into(),
            exponent: -1,
            declare: "declare it (or its factors) as a denominator: denominators = [\"x + y\"] \
                      in [phase_space]"
                .into(),
        }
    );
    // A monomial may replace a variable that has negative powers.
    assert_eq!(
        g.subst(x, &p(&vars, "2*M/omega")),
        Ok(p(&vars, "omega/(2*M)"))
    );
}

#[test]
fn subst_many_is_simultaneous() {
    let vars = phase_space();
    let (x, y) = (var(&vars, "x"), var(&vars, "y"));
    let l: G = p(&vars, "x*p_y - y*p_x");
    let rotated = l
        .subst_many(&[(x, p(&vars, "-y")), (y, p(&vars, "x"))])
        .unwrap();
    assert_eq!(rotated, p(&vars, "-y*p_y - x*p_x"));
    let swapped = l
        .subst_many(&[(x, p(&vars, "y")), (y, p(&vars, "x"))])
        .unwrap();
    assert_eq!(swapped, p(&vars, "y*p_y - x*p_x"));
}

#[test]
fn eval_at_a_rational_point_of_the_unit_circle() {
    let vars = phase_space();
    let point = Point::new(&vars)
        .with(var(&vars, "x"), Rational::new(1, 2))
        .with(var(&vars, "M"), Rational::new(3, 1))
        .with_angle(
            var(&vars, "theta"),
            Rational::new(3, 5),
            Rational::new(4, 5),
        )
        .unwrap();
    let value = |src: &str| p::<GaussianRational>(&vars, src).eval(&point);
    let q = |s: &str| -> Result<GaussianRational, AlgebraError> { Ok(s.parse().unwrap()) };
    assert_eq!(value("cos(theta)"), q("3/5"));
    assert_eq!(value("sin(2*theta)"), q("24/25"));
    assert_eq!(value("cos(theta)^2 + sin(theta)^2"), q("1"));
    assert_eq!(value("exp(i*theta)"), q("3/5 + 4/5*i"));
    assert_eq!(value("exp(-3*i*theta)"), q("-117/125 - 44/125*i"));
    assert_eq!(value("M*x^-2 + x*sin(theta)/M"), q("182/15"));
    assert_eq!(value("x + y"), Err(AlgebraError::MissingValue("y".into())));
    let over_q: Q = p(&vars, "M/x - 1");
    assert_eq!(over_q.eval(&point), q("5"));
    let zero = Point::new(&vars).with(var(&vars, "x"), Rational::zero());
    assert_eq!(
        p::<Rational>(&vars, "1/x").eval(&zero),
        Err(AlgebraError::DivisionByZero)
    );
    assert_eq!(
        Point::new(&vars)
            .with_angle(var(&vars, "phi"), Rational::new(3, 5), Rational::new(3, 5))
            .map(|_| ()),
        Err(AlgebraError::NotOnUnitCircle("φ".into()))
    );
}

#[test]
fn degrees_and_ranges_of_laurent_and_trigonometric_polynomials() {
    use trigpoly::VarKind;
    let vars = phase_space();
    let (x, theta) = (var(&vars, "x"), var(&vars, "theta"));
    let f: G = p(&vars, "x^3*p_x^2 + p_y/x^2 + cos(2*theta)");
    assert_eq!(f.exponent_range(x), Some((-2, 3)));
    assert_eq!((f.degree(x), f.low_degree(x)), (Some(3), Some(-2)));
    assert_eq!(f.exponent_range(theta), Some((-2, 2)));
    assert_eq!(f.total_degree(&[VarKind::Momentum]), Some(2));
    assert_eq!(
        f.total_degree(&[VarKind::Coordinate, VarKind::Momentum]),
        Some(5)
    );
    assert!(f.contains(theta) && f.has_angles() && !f.contains(var(&vars, "phi")));
    assert!(f.is_free_of(VarKind::Parameter) && !f.is_free_of(VarKind::Angle));
    assert!(f.is_real());
    assert_eq!(G::zero(&vars).degree(x), None);
}

/// A variable handle belongs to the variables it was found among: used with a set that
/// declares others, an operation that returns a `Result` says `VarSetMismatch`, and one that
/// cannot panics with a message, where the handle's index alone named whatever variable stood
/// at that place (`ab`, the seventh here, is past the end of `{q}`; `y`, the second of
/// `phase_space`, is `y` of `{x, y}` by index too, and still refused; so are the bracket's
/// kernels' pairs and values). A set with the same
/// variables and other limits takes the handles.
#[test]
fn variable_handles_of_another_set_are_refused() {
    use trigpoly::{Limits, Vars};
    let big = phase_space();
    let small = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .build()
        .unwrap();
    let y_big = var(&big, "y");
    assert!(!small.owns(y_big) && big.owns(y_big));
    let x: G = Poly::var(&small, var(&small, "x"));
    assert_eq!(x.derivative(y_big), Err(AlgebraError::VarSetMismatch));
    assert_eq!(x.subst(y_big, &x), Err(AlgebraError::VarSetMismatch));
    assert_eq!(
        G::monomial(&small, GaussianRational::from(2), &[(y_big, 1)]),
        Err(AlgebraError::VarSetMismatch)
    );
    assert_eq!(
        x.eval(&Point::new(&small).with(y_big, Rational::one())),
        Err(AlgebraError::VarSetMismatch)
    );
    // The bracket's kernels, given pairs or derivatives in another set's handles (they
    // panicked on an index past the end, or took `y` of `big` for `y` of `small`).
    let g: G = Poly::parse(&small, "x^2 + y").unwrap();
    let pairs = [(var(&big, "x"), var(&big, "p_x"))];
    assert_eq!(
        G::sum_of_jacobians(&x, &g, &pairs),
        Err(AlgebraError::VarSetMismatch)
    );
    assert_eq!(
        G::sum_of_derivative_products(&[(&g, y_big, &x, false)]),
        Err(AlgebraError::VarSetMismatch)
    );
    let x_small = var(&small, "x");
    assert_eq!(
        G::sum_of_derivative_products_at(&[(&g, x_small, &x, false)], &[(y_big, x.clone())]),
        Err(AlgebraError::VarSetMismatch)
    );
    let panics = |f: &dyn Fn()| {
        let message = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f))
            .expect_err("panics")
            .downcast::<String>()
            .expect("a message");
        assert!(
            message.contains("a variable handle of another variable set"),
            "{message}"
        );
    };
    panics(&|| {
        x.degree(y_big);
    });
    panics(&|| {
        G::var(&small, y_big);
    });
    panics(&|| {
        x.coeff(&[(y_big, 1)]);
    });
    // The same variables with other limits: the same handles.
    let wider = small.with_limits(Limits::default()).unwrap();
    let y = var(&small, "y");
    assert!(wider.owns(y));
    assert_eq!(G::var(&wider, y).to_string(), "y");
}

/// `Point::with` gives an angle its value as `e^{iθ}`: `−1` is θ = π, and any value off the
/// unit circle makes the evaluation an error (it was taken as `e^{iθ}`, and `cos θ` at "2"
/// came out 5/4).
#[test]
fn a_real_value_for_an_angle_must_be_on_the_unit_circle() {
    let vars = phase_space();
    let theta = var(&vars, "theta");
    let cos: G = p(&vars, "cos(theta)");
    let at_pi = Point::new(&vars).with(theta, Rational::from(-1));
    assert_eq!(cos.eval(&at_pi), Ok(GaussianRational::from(-1)));
    let off = Point::new(&vars).with(theta, Rational::from(2));
    assert_eq!(
        cos.eval(&off),
        Err(AlgebraError::NotOnUnitCircle("θ".into()))
    );
}

/// A point prints the values it gives, in the set's order and Unicode names, an angle by its
/// cosine and sine; two points are equal when they give the same values.
#[test]
fn a_point_prints_its_values_and_equals_a_point_of_the_same_values() {
    let vars = phase_space();
    let (x, theta, omega) = (var(&vars, "x"), var(&vars, "theta"), var(&vars, "omega"));
    let point = || {
        Point::new(&vars)
            .with(omega, Rational::new(-3, 2))
            .with_angle(theta, Rational::new(-3, 5), Rational::new(4, 5))
            .unwrap()
            .with(x, Rational::new(1, 2))
    };
    assert_eq!(
        point().to_string(),
        "x = 1/2, cos θ = −3/5, sin θ = 4/5, ω = −3/2"
    );
    assert_eq!(Point::new(&vars).to_string(), "no values");
    let phi = var(&vars, "phi");
    assert_eq!(
        Point::new(&vars).with(phi, -Rational::one()).to_string(),
        "cos φ = −1, sin φ = 0"
    );
    assert_eq!(point(), point());
    assert_ne!(point(), point().with(x, Rational::new(1, 3)));
    assert_ne!(point(), Point::new(&vars));
    // An angle at 2, off the unit circle, is kept with the error the evaluation reports.
    assert_ne!(
        Point::new(&vars).with(theta, Rational::one()),
        Point::new(&vars).with(theta, Rational::from(2))
    );
}
