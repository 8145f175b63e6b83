//! Derivatives by an angle: ∂/∂θ cos θ = −sin θ, ∂/∂θ sin θ = cos θ, ∂/∂θ e^{inθ} = in e^{inθ}.

use trigpoly::{AlgebraError, Misuse, Rational};

use crate::common::{p, phase_space, var, G, Q};

fn d(f: &str, by: &str) -> G {
    let vars = phase_space();
    p::<trigpoly::GaussianRational>(&vars, f)
        .derivative(var(&vars, by))
        .unwrap_or_else(|e| panic!("∂({f})/∂{by}: {e}"))
}

#[test]
fn derivative_of_cos_by_its_angle_is_minus_sin() {
    let vars = phase_space();
    assert_eq!(d("cos(theta)", "theta"), p(&vars, "-sin(theta)"));
    assert_eq!(d("cos(phi)", "phi"), p(&vars, "-sin(phi)"));
    assert_eq!(d("cos(theta)", "phi"), p(&vars, "0"));
}

#[test]
fn derivative_of_sin_by_its_angle_is_cos() {
    let vars = phase_space();
    assert_eq!(d("sin(theta)", "theta"), p(&vars, "cos(theta)"));
    assert_eq!(d("sin(phi)", "phi"), p(&vars, "cos(phi)"));
}

#[test]
fn derivative_of_exp_i_n_theta_is_i_n_exp_i_n_theta() {
    let vars = phase_space();
    for n in -7i64..=7 {
        assert_eq!(
            d(&format!("exp(i*{n}*theta)"), "theta"),
            p(&vars, &format!("i*{n}*exp(i*{n}*theta)")),
            "n = {n}"
        );
    }
}

#[test]
fn derivative_by_angle_of_multiple_angles_follows_the_chain_rule() {
    let vars = phase_space();
    // ∂/∂θ cos(2θ − 3φ) = −2 sin(2θ − 3φ); ∂/∂φ = 3 sin(2θ − 3φ).
    assert_eq!(
        d("cos(2*theta - 3*phi)", "theta"),
        p(&vars, "-2*sin(2*theta - 3*phi)")
    );
    assert_eq!(
        d("cos(2*theta - 3*phi)", "phi"),
        p(&vars, "3*sin(2*theta - 3*phi)")
    );
    // ∂/∂θ cos³θ = −3 cos²θ sin θ, and x is a constant for ∂/∂θ.
    assert_eq!(
        d("x*cos(theta)^3", "theta"),
        p(&vars, "-3*x*cos(theta)^2*sin(theta)")
    );
}

#[test]
fn derivative_of_laurent_monomials_lowers_the_exponent() {
    let vars = phase_space();
    assert_eq!(d("x^-3*y", "x"), p(&vars, "-3*y/x^4"));
    assert_eq!(d("p_x^2/(2*M)", "M"), p(&vars, "-p_x^2/(2*M^2)"));
    assert_eq!(d("M*omega^2*x^2/2", "x"), p(&vars, "M*omega^2*x"));
}

#[test]
fn angles_need_gaussian_coefficients_over_q() {
    let vars = phase_space();
    // An angle lives in e^{iθ}, so it has no polynomial over Q, not even cos θ.
    let cos_theta: trigpoly::Poly<trigpoly::GaussianRational> = p(&vars, "cos(theta)");
    assert_eq!(cos_theta.to_rational(), None);
    let err = Q::parse(&vars, "cos(theta)").expect_err("angles need Q(i)");
    assert!(err.message().contains("Q(i)"), "{}", err.message());
    // The derivative of a polynomial over Q by an angle it does not contain is zero.
    let h: Q = p(&vars, "p_x^2/(2*M)");
    assert_eq!(h.derivative(var(&vars, "theta")), Ok(Q::zero(h.vars())));
    // The non-angle derivatives are fine over Q.
    let h: Q = p(&vars, "p_x^2/(2*M) + M*omega^2*x^2/2");
    assert_eq!(h.derivative(var(&vars, "p_x")), Ok(p(&vars, "p_x/M")));
    assert_eq!(
        h.derivative(var(&vars, "x"))
            .map(|f| f.scale_rational(&Rational::new(1, 2))),
        Ok(p(&vars, "M*omega^2*x/2"))
    );
}

/// The sum of Jacobians given a gradient needs one pair of derivatives per pair of variables;
/// a mismatch is an error, never a silently shorter sum.
#[test]
fn sum_of_jacobians_with_gradient_rejects_a_gradient_of_another_length() {
    let vars = phase_space();
    let (x, px) = (var(&vars, "x"), var(&vars, "p_x"));
    let f: G = p(&vars, "x^2 p_x");
    let g: G = p(&vars, "p_x^3 + x");
    let gradient = [(g.derivative(x).unwrap(), g.derivative(px).unwrap())];
    assert_eq!(
        G::sum_of_jacobians_with_gradient(&f, &[(x, px)], &gradient),
        G::sum_of_jacobians(&f, &g, &[(x, px)])
    );
    let err = G::sum_of_jacobians_with_gradient(&f, &[(x, px)], &[]).unwrap_err();
    assert_eq!(
        err,
        AlgebraError::Misuse(Misuse::GradientCount {
            pairs: 1,
            derivatives: 0
        })
    );
    assert_eq!(
        err.to_string(),
        "1 pairs of variables but 0 pairs of derivatives"
    );
}
