//! Printing like the paper: exact unicode, LaTeX and ASCII strings.

use pretty_assertions::assert_eq;
use trigpoly::{Angles, GaussianRational, Poly, Style, Vars};

use crate::common::{p, phase_space, plane_with, G, Q};

/// `x, y, p_x, p_y, θ, M, ω, L, L_z`: coordinates declared before momenta.
fn plane() -> Vars {
    plane_with(&["L", "L_z"])
}

/// Asserts the three renderings of `src` and that the ASCII one parses back.
fn prints(vars: &Vars, src: &str, [unicode, latex, ascii]: [&str; 3]) {
    let f: G = p(vars, src);
    assert_eq!(
        [f.to_string(), f.to_latex(), f.to_ascii()],
        [unicode.to_string(), latex.to_string(), ascii.to_string()],
        "{src}"
    );
    assert_eq!(f.render(Style::Unicode), unicode);
    assert_eq!(
        p::<GaussianRational>(vars, ascii),
        f,
        "the ASCII form {ascii:?} parses back"
    );
}

/// Asserts the three renderings of `src` with its angles in powers ([`Angles::Powers`], the
/// normal form) and that the ASCII one parses back.
fn prints_powers(vars: &Vars, src: &str, [unicode, latex, ascii]: [&str; 3]) {
    let f: G = p(vars, src);
    let shown = Style::ALL.map(|style| f.render_with(style, Angles::Powers));
    assert_eq!(shown, [unicode, latex, ascii], "{src}");
    assert_eq!(f.with_angles(Angles::Powers).to_string(), unicode);
    assert_eq!(
        p::<GaussianRational>(vars, ascii),
        f,
        "the ASCII form {ascii:?} parses back"
    );
}

/// The printers write each angle's part in multiple angles by default, as the paper does:
/// `cos^a θ sin^b θ` as a sum of `cos kθ` and `sin kθ` (`k ≤ a + b`), each expected form worked
/// by hand (`cos²θ = (1 + cos 2θ)/2`, `cos³θ = (3 cos θ + cos 3θ)/4`, `cos²θ sin θ =
/// (sin θ + sin 3θ)/4`, `sin³θ = (3 sin θ − sin 3θ)/4`, `cos θ sin θ = sin 2θ/2`), the terms
/// grouped by harmonic; every form parses back, the text one too (`cos 2θ`).
#[test]
fn harmonics_linearise_powers_of_cos_and_sin() {
    let vars = plane();
    let cases = [
        (
            "cos(theta)^2",
            [
                "1/2 + (cos 2θ)/2",
                r"\frac{1}{2} + \frac{\cos 2\theta}{2}",
                "1/2 + cos(2*theta)/2",
            ],
        ),
        (
            "cos(theta)^3",
            [
                "(3 cos θ)/4 + (cos 3θ)/4",
                r"\frac{3 \cos\theta}{4} + \frac{\cos 3\theta}{4}",
                "3*cos(theta)/4 + cos(3*theta)/4",
            ],
        ),
        (
            "cos(theta)^2*sin(theta)",
            [
                "(sin θ)/4 + (sin 3θ)/4",
                r"\frac{\sin\theta}{4} + \frac{\sin 3\theta}{4}",
                "sin(theta)/4 + sin(3*theta)/4",
            ],
        ),
        (
            "sin(theta)^3",
            [
                "(3 sin θ)/4 − (sin 3θ)/4",
                r"\frac{3 \sin\theta}{4} - \frac{\sin 3\theta}{4}",
                "3*sin(theta)/4 - sin(3*theta)/4",
            ],
        ),
        (
            "2*x*cos(theta)^2 - x + 2*y*cos(theta)*sin(theta)",
            [
                "x cos 2θ + y sin 2θ",
                r"x \cos 2\theta + y \sin 2\theta",
                "x*cos(2*theta) + y*sin(2*theta)",
            ],
        ),
        (
            "x*exp(-2*i*theta)",
            [
                "x cos 2θ − ix sin 2θ",
                r"x \cos 2\theta - i x \sin 2\theta",
                "x*cos(2*theta) - i*x*sin(2*theta)",
            ],
        ),
    ];
    for (src, shown) in cases {
        prints(&vars, src, shown);
        let f: G = p(&vars, src);
        assert_eq!(
            p::<GaussianRational>(&vars, shown[0]),
            f,
            "{} reads back",
            shown[0]
        );
    }
    // Two angles: their harmonics jointly, cos²θ cos φ = (1 + cos 2θ) cos φ/2 = cos φ/2 +
    // (cos(2θ + φ) + cos(2θ − φ))/4.
    let vars = phase_space();
    let f: G = p(&vars, "cos(theta)^2*cos(phi)");
    assert_eq!(f.to_string(), "(cos φ)/2 + cos(2θ + φ)/4 + cos(2θ − φ)/4");
    assert_eq!(p::<GaussianRational>(&vars, &f.to_string()), f);
}

/// A coefficient with both parts is one factor in parentheses: `i` alone for `±i`, and a
/// fraction's `i` on its numerator in text (`5/7i` would read as `5/(7i)`).
#[test]
fn complex_coefficients_print_their_imaginary_unit_unambiguously() {
    let vars = plane();
    prints(
        &vars,
        "(2 + i)*x - (1 - i)*y",
        [
            "(2 + i) x + (−1 + i) y",
            r"\left(2 + i\right) x + \left(-1 + i\right) y",
            "(2 + i)*x + (-1 + i)*y",
        ],
    );
    prints(
        &vars,
        "(3 - 5/7*i)*x + (1/2 + i/2)*p_x + (-4 + 6*i)*M",
        [
            "(1/2 + i/2) p_x + (3 − 5i/7) x + (−4 + 6i) M",
            r"\left(\frac{1}{2} + \frac{1}{2} i\right) p_{x} + \left(3 - \frac{5}{7} i\right) x + \left(-4 + 6 i\right) M",
            "(1/2 + 1/2*i)*p_x + (3 - 5/7*i)*x + (-4 + 6*i)*M",
        ],
    );
}

#[test]
fn kinetic_energy_prints_as_a_fraction() {
    let vars = plane();
    prints(
        &vars,
        "p_x^2/(2*M)",
        ["p_x²/(2M)", r"\frac{p_{x}^{2}}{2 M}", "p_x^2/(2*M)"],
    );
}

#[test]
fn potential_energy_prints_with_juxtaposed_factors() {
    let vars = plane();
    prints(
        &vars,
        "M*omega^2*x^2/2",
        [
            "Mω²x²/2",
            r"\frac{M \omega^{2} x^{2}}{2}",
            "M*omega^2*x^2/2",
        ],
    );
    // Parameters first, then coordinates, then momenta, whatever the input order.
    prints(
        &vars,
        "x^2*omega^2/2*M",
        [
            "Mω²x²/2",
            r"\frac{M \omega^{2} x^{2}}{2}",
            "M*omega^2*x^2/2",
        ],
    );
}

#[test]
fn minus_omega_squared_times_a_parameter() {
    let vars = plane();
    // A one-letter name is juxtaposed, a longer one is set apart by a space.
    prints(
        &vars,
        "-omega^2*L",
        ["−ω²L", r"-\omega^{2} L", "-omega^2*L"],
    );
    prints(
        &vars,
        "-L_z*omega^2",
        ["−ω² L_z", r"-\omega^{2} L_{z}", "-omega^2*L_z"],
    );
}

/// The generators of an algebra are words: set apart from their neighbours in text even when
/// one letter long (`−ω² L`, `4 G1`, as the paper writes su(2)), the parameters still run
/// together (`4iMω`).
#[test]
fn generators_declared_as_words_are_set_apart() {
    let vars = Vars::builder()
        .parameter("M")
        .parameter("omega")
        .coordinate("L")
        .word()
        .coordinate("G1")
        .word()
        .coordinate("x")
        .build()
        .unwrap();
    assert!(vars.variable(vars.lookup("L").unwrap()).is_word());
    assert!(!vars.variable(vars.lookup("x").unwrap()).is_word());
    prints(
        &vars,
        "-omega^2*L",
        ["−ω² L", r"-\omega^{2} L", "-omega^2*L"],
    );
    prints(
        &vars,
        "4*G1^2 + omega^2*L^2 + 4*i*M*omega*L*x",
        [
            "4iMω L x + ω² L² + 4 G1²",
            r"4 i M \omega L x + \omega^{2} L^{2} + 4 G_{1}^{2}",
            "4*i*M*omega*L*x + omega^2*L^2 + 4*G1^2",
        ],
    );
    prints(&vars, "2*M*x", ["2Mx", "2 M x", "2*M*x"]);
}

/// A variable shown by a name of several words (`Re K`, as a closure's generator is) is set in
/// parentheses where a power, a factor or a denominator follows it, and in every other place of
/// that term: `Re K² H_x` would read as the real part of `K²`. At the end of a term it is bare.
#[test]
fn names_of_several_words_take_parentheses_where_they_would_read_otherwise() {
    let vars = Vars::builder()
        .parameter("omega")
        .coordinate("ReK")
        .shown_as("Re K")
        .word()
        .coordinate("ImK")
        .shown_as("Im K")
        .word()
        .coordinate("Hx")
        .shown_as("H_x")
        .word()
        .build()
        .unwrap();
    prints(
        &vars,
        "6*omega*ImK - ReK",
        [
            "6ω Im K − Re K",
            r"6 \omega \operatorname{Im} K - \operatorname{Re} K",
            "6*omega*ImK - ReK",
        ],
    );
    prints(
        &vars,
        "ReK^2*Hx + ReK*ImK",
        [
            "(Re K)² H_x + (Re K) (Im K)",
            r"(\operatorname{Re} K)^{2} H_{x} + (\operatorname{Re} K) (\operatorname{Im} K)",
            "ReK^2*Hx + ReK*ImK",
        ],
    );
    prints(
        &vars,
        "ImK/omega",
        [
            "(Im K)/ω",
            r"\frac{\operatorname{Im} K}{\omega}",
            "ImK/omega",
        ],
    );
}

#[test]
fn angular_momentum_prints_in_declaration_order() {
    let vars = plane();
    prints(
        &vars,
        "x*p_y - y*p_x",
        ["x p_y − y p_x", "x p_{y} - y p_{x}", "x*p_y - y*p_x"],
    );
    prints(
        &vars,
        "-p_x*y + p_y*x",
        ["x p_y − y p_x", "x p_{y} - y p_{x}", "x*p_y - y*p_x"],
    );
}

/// Terms of higher degree in the momenta come first, as in the paper: kinetic before
/// potential energy.
#[test]
fn hamiltonian_of_the_oscillator() {
    let vars = plane();
    prints(
        &vars,
        "M*omega^2*x^2/2 + p_x^2/(2*M)",
        [
            "p_x²/(2M) + Mω²x²/2",
            r"\frac{p_{x}^{2}}{2 M} + \frac{M \omega^{2} x^{2}}{2}",
            "p_x^2/(2*M) + M*omega^2*x^2/2",
        ],
    );
    prints(
        &vars,
        "-omega^2*M*x + p_x^2/(2*M)",
        [
            "p_x²/(2M) − Mω²x",
            r"\frac{p_{x}^{2}}{2 M} - M \omega^{2} x",
            "p_x^2/(2*M) - M*omega^2*x",
        ],
    );
}

/// `P_{1,1}`, grouped by its trigonometric factor, each group led by its momentum: exactly as
/// in the paper, with coordinates declared before momenta.
#[test]
fn p11_groups_terms_by_cos_and_sin() {
    let vars = plane();
    prints(
        &vars,
        "(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)",
        [
            "(p_x − Mωy) cos θ + (p_y + Mωx) sin θ",
            r"\left(p_{x} - M \omega y\right) \cos\theta + \left(p_{y} + M \omega x\right) \sin\theta",
            "(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)",
        ],
    );
}

/// With momenta declared first, `P_{1,1}` prints the same way.
#[test]
fn p11_prints_as_in_the_paper_with_momenta_declared_first() {
    let vars = Vars::builder()
        .momentum("p_x")
        .momentum("p_y")
        .coordinate("x")
        .coordinate("y")
        .angle("theta")
        .parameter("M")
        .parameter("omega")
        .build()
        .unwrap();
    prints(
        &vars,
        "(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)",
        [
            "(p_x − Mωy) cos θ + (p_y + Mωx) sin θ",
            r"\left(p_{x} - M \omega y\right) \cos\theta + \left(p_{y} + M \omega x\right) \sin\theta",
            "(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)",
        ],
    );
}

/// An angle with a Latin name is spaced from `\cos` (`\cosa` and `\sint` are undefined
/// commands); a power's braces or a command's backslash need no space.
#[test]
fn latin_angles_are_spaced_from_cos_and_sin_in_latex() {
    let vars = Vars::builder()
        .angle("a")
        .angle("t")
        .angle("theta")
        .build()
        .unwrap();
    prints_powers(
        &vars,
        "cos(a)*sin(t) + cos(a)^2*sin(theta)",
        [
            "cos a sin t + cos²a sin θ",
            r"\cos a \sin t + \cos^{2}a \sin\theta",
            "cos(a)*sin(t) + cos(a)^2*sin(theta)",
        ],
    );
}

#[test]
fn trigonometric_normal_form_a_of_cos_plus_sin_times_b_of_cos() {
    let vars = plane();
    prints_powers(
        &vars,
        "cos(theta)^2",
        ["cos²θ", r"\cos^{2}\theta", "cos(theta)^2"],
    );
    // sin²θ → 1 − cos²θ, sin³θ → sin θ − cos²θ sin θ.
    prints_powers(
        &vars,
        "sin(theta)^2",
        ["1 − cos²θ", r"1 - \cos^{2}\theta", "1 - cos(theta)^2"],
    );
    prints_powers(
        &vars,
        "sin(theta)^3",
        [
            "sin θ − cos²θ sin θ",
            r"\sin\theta - \cos^{2}\theta \sin\theta",
            "sin(theta) - cos(theta)^2*sin(theta)",
        ],
    );
    prints_powers(
        &vars,
        "cos(2*theta)",
        [
            "−1 + 2 cos²θ",
            r"-1 + 2 \cos^{2}\theta",
            "-1 + 2*cos(theta)^2",
        ],
    );
    prints_powers(
        &vars,
        "x*exp(i*theta)",
        [
            "x cos θ + ix sin θ",
            r"x \cos\theta + i x \sin\theta",
            "x*cos(theta) + i*x*sin(theta)",
        ],
    );
    prints_powers(
        &vars,
        "x*cos(theta) + y*cos(theta) + 1",
        [
            "1 + (x + y) cos θ",
            r"1 + \left(x + y\right) \cos\theta",
            "1 + (x + y)*cos(theta)",
        ],
    );
    let two = phase_space();
    prints_powers(
        &two,
        "cos(theta)*sin(phi)",
        [
            "cos θ sin φ",
            r"\cos\theta \sin\varphi",
            "cos(theta)*sin(phi)",
        ],
    );
}

#[test]
fn coefficients_fractions_and_negative_powers() {
    let vars = plane();
    prints(&vars, "0", ["0", "0", "0"]);
    prints(&vars, "3/4", ["3/4", r"\frac{3}{4}", "3/4"]);
    prints(&vars, "-i/2", ["−i/2", r"-\frac{i}{2}", "-i/2"]);
    prints(
        &vars,
        "-1/(2*M*x)",
        ["−1/(2Mx)", r"-\frac{1}{2 M x}", "-1/(2*M*x)"],
    );
    prints(&vars, "x^-2*y", ["y/x²", r"\frac{y}{x^{2}}", "y/x^2"]);
    prints(
        &vars,
        "(3 + 4*i)*x/M",
        [
            "(3 + 4i) x/M",
            r"\frac{\left(3 + 4 i\right) x}{M}",
            "(3 + 4*i)*x/M",
        ],
    );
}

/// Terms that differ in which coordinate carries a negative power print in the variables'
/// order, as positive powers do (`a/x² + b/y² + c/z²`, once `c/z² + b/y² + a/x²`).
#[test]
fn coordinate_denominators_print_in_the_variables_order() {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .parameter("a")
        .parameter("b")
        .parameter("c")
        .build()
        .unwrap();
    for src in ["a/x^2 + b/y^2 + c/z^2", "c/z^2 + b/y^2 + a/x^2"] {
        prints(
            &vars,
            src,
            [
                "a/x² + b/y² + c/z²",
                r"\frac{a}{x^{2}} + \frac{b}{y^{2}} + \frac{c}{z^{2}}",
                "a/x^2 + b/y^2 + c/z^2",
            ],
        );
    }
}

/// The order of a Laurent polynomial in the coordinates: the terms by their numerators, as
/// positive powers are ordered (a coordinate's negative power counted as none), then those of
/// one numerator by their denominators: none first, then the least total degree, then in the
/// variables' order (`x² + x/y + y² + y/x + 1 + 1/x + 1/y + 1/x² + 1/(xy) + 1/y²`, once
/// `x² + x/y + y² + 1/y² + y/x + 1/x²`). What a common denominator leaves is in its own such
/// order, which signs the factor.
#[test]
fn laurent_terms_print_by_numerator_then_denominator() {
    let vars = plane();
    prints(
        &vars,
        "x^2 + y^2 + 1/x^2 + 1/y^2 + x/y + y/x",
        [
            "x² + x/y + y² + y/x + 1/x² + 1/y²",
            r"x^{2} + \frac{x}{y} + y^{2} + \frac{y}{x} + \frac{1}{x^{2}} + \frac{1}{y^{2}}",
            "x^2 + x/y + y^2 + y/x + 1/x^2 + 1/y^2",
        ],
    );
    prints(
        &vars,
        "1/y^2 + y/x + 1/x^2 + x/y + y^2 + x^2 + 1 + 1/y + 1/x + 1/(x*y)",
        [
            "x² + x/y + y² + y/x + 1 + 1/x + 1/y + 1/x² + 1/(xy) + 1/y²",
            r"x^{2} + \frac{x}{y} + y^{2} + \frac{y}{x} + 1 + \frac{1}{x} + \frac{1}{y} + \frac{1}{x^{2}} + \frac{1}{x y} + \frac{1}{y^{2}}",
            "x^2 + x/y + y^2 + y/x + 1 + 1/x + 1/y + 1/x^2 + 1/(x*y) + 1/y^2",
        ],
    );
    let f: Q = p(&vars, "p_y/(x^2*y^3) - p_x/(x^3*y^2)");
    assert_eq!(f.to_string(), "−p_x/(x³y²) + p_y/(x²y³)");
    assert_eq!(f.factored().unwrap().to_string(), "(x p_y − y p_x)/(x³y³)");
}

/// A parameter's negative power is part of the coefficient and keeps the place it always had:
/// a polynomial with no coordinate in a denominator prints as before (`y² + ωy²/M`, where
/// counting `M`'s power as none would put `ωy²/M` first).
#[test]
fn parameter_denominators_keep_their_order() {
    let vars = plane();
    prints(
        &vars,
        "M*omega^2*y^2/2 + p_y^2/(2*M) + M*omega^2*x^2/2 + p_x^2/(2*M)",
        [
            "p_x²/(2M) + p_y²/(2M) + Mω²x²/2 + Mω²y²/2",
            r"\frac{p_{x}^{2}}{2 M} + \frac{p_{y}^{2}}{2 M} + \frac{M \omega^{2} x^{2}}{2} + \frac{M \omega^{2} y^{2}}{2}",
            "p_x^2/(2*M) + p_y^2/(2*M) + M*omega^2*x^2/2 + M*omega^2*y^2/2",
        ],
    );
    prints(
        &vars,
        "omega*y^2/M + y^2 + x/M^2",
        [
            "x/M² + y² + ωy²/M",
            r"\frac{x}{M^{2}} + y^{2} + \frac{\omega y^{2}}{M}",
            "x/M^2 + y^2 + omega*y^2/M",
        ],
    );
}

#[test]
fn polynomials_over_q_print_the_same_way() {
    let vars = plane();
    let f: Q = p(&vars, "p_x^2/(2*M) + M*omega^2*x^2/2");
    assert_eq!(f.to_string(), "p_x²/(2M) + Mω²x²/2");
    assert_eq!(f.to_string(), f.to_gaussian().to_string());
}

/// The unicode text of an element parses back to it (the parser accepts `ω`, `p_θ`, `²`,
/// `⁻¹` and `−`). Checked on the paper's examples; every failure is listed.
#[test]
fn print_parse_roundtrip_text_of_the_paper_examples() {
    let vars = plane();
    let mut failures = Vec::new();
    for src in [
        "p_x^2/(2*M)",
        "M*omega^2*x^2/2",
        "-omega^2*L",
        "x*p_y - y*p_x",
        "2*x",
        "(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)",
        "(3 + 4*i)*x",
        "(3 + 5/7*i)*x - (2 - i)*y + (1/2 - i/2)*p_x",
    ] {
        let f: G = p(&vars, src);
        let text = f.to_string();
        match Poly::<GaussianRational>::parse(&vars, &text) {
            Ok(back) if back == f => {}
            Ok(back) => failures.push(format!("{text:?} parses to {back}")),
            Err(e) => failures.push(e.render(&text)),
        }
    }
    assert_eq!(
        failures.join("\n\n"),
        "",
        "unicode text that does not parse back"
    );
}

/// Over Q there are no angles (they live in `e^{iθ}`): the ASCII form of a real trigonometric
/// polynomial parses back over Q(i), and over Q it is refused with a message naming Q(i).
#[test]
fn real_trigonometric_polynomials_round_trip_over_gaussian_rationals_only() {
    let vars = plane();
    let f: trigpoly::Poly<GaussianRational> = p(&vars, "x*cos(theta)");
    let text = f.to_ascii();
    assert_eq!(text, "x*cos(theta)");
    let back = trigpoly::Poly::<GaussianRational>::parse(&vars, &text);
    assert_eq!(back.map_err(|e| e.render(&text)), Ok(f));
    let err = Q::parse(&vars, &text).expect_err("no angles over Q");
    assert!(err.message().contains("Q(i)"), "{}", err.message());
}

/// A polynomial over Q holds real coefficients: `e^{iθ} = cos θ + i sin θ` is not one, and
/// must not come out of `to_rational` as a "polynomial over Q" that prints an `i`.
#[test]
fn polynomials_over_q_never_print_the_imaginary_unit() {
    let vars = plane();
    let e: G = p(&vars, "x*exp(i*theta)");
    assert_eq!(e.to_string(), "x cos θ + ix sin θ");
    let over_q = e.to_rational().map(|f| f.to_string());
    assert_eq!(over_q, None, "x·e^(iθ) is not a polynomial over Q");
}

/// High powers of `e^{iθ}` expand into cosines and sines with coefficients past 64 and 128
/// bits, summed over Z[i] and scaled by the content once (`Poly::cos_sin_terms`): the printed
/// forms still parse back to the element, and a known coefficient comes out exact.
#[test]
fn high_trigonometric_powers_with_long_coefficients_print_exactly() {
    let vars = plane();
    let f: G = p(
        &vars,
        "(12345678901*p_x*cos(theta) + 98765432109*i*M*omega*x*sin(theta) + 3/7)^9/11",
    );
    for (style, text) in [("ascii", f.to_ascii()), ("unicode", f.to_string())] {
        let back = Poly::<GaussianRational>::parse(&vars, &text).map_err(|e| e.render(&text));
        assert_eq!(back, Ok(f.clone()), "the {style} form parses back");
    }
    // p_x⁹ cos⁹θ has the coefficient 12345678901⁹/11, and heads the group of cos⁹θ.
    let lead = num_bigint::BigInt::from(12345678901u64).pow(9);
    let text = f.render_with(Style::Ascii, Angles::Powers);
    assert!(text.contains(&format!("({lead}*p_x^9/11 + ")), "{text}");
}

/// Two angles: the cos/sin view sums each term of `e^{i(jθ + kφ)}`'s expansion under its
/// monomial and its `cos^a θ sin^b θ cos^c φ sin^d φ`, both numbered once per element; the
/// ASCII form of elements with long expansions in both angles parses back to the element, and
/// a short one prints grouped by the trigonometric monomials in their order (fewer factors
/// first, then by the powers of θ, lower first, a sine after a cosine, then those of φ).
#[test]
fn two_angles_print_grouped_and_parse_back() {
    let vars = phase_space();
    for src in [
        "(cos(theta) + 2*sin(phi) + x)^4*(sin(theta) - cos(phi))^3",
        "x^3*exp(3*i*theta - 2*i*phi) + p_x*exp(-5*i*phi) + y*exp(4*i*theta)",
        "(x*cos(theta)*sin(phi) - p_x*sin(theta)*cos(phi))^5",
    ] {
        let f: G = p(&vars, src);
        let text = f.to_ascii();
        assert_eq!(p::<GaussianRational>(&vars, &text), f, "{src}");
    }
    prints_powers(
        &vars,
        "x*sin(phi) + y*cos(theta) + x*cos(theta) + cos(theta)*cos(phi) + 3",
        [
            "3 + x sin φ + (x + y) cos θ + cos θ cos φ",
            r"3 + x \sin\varphi + \left(x + y\right) \cos\theta + \cos\theta \cos\varphi",
            "3 + x*sin(phi) + (x + y)*cos(theta) + cos(theta)*cos(phi)",
        ],
    );
}

/// Over two angles the harmonics are those of the angles jointly, as a physicist writes them:
/// `cos θ cos φ + sin θ sin φ = cos(θ − φ)`, its multiples made to start positive (`cos(−θ +
/// φ)` is `cos(θ − φ)`, `sin(−θ + φ)` is `−sin(θ − φ)`), a single angle's as before (`cos 2θ`),
/// in all three notations, each parsing back; in powers, the old form. Each expected form is
/// worked by hand: `cos θ cos φ = (cos(θ + φ) + cos(θ − φ))/2`, `sin θ cos φ = (sin(θ + φ) +
/// sin(θ − φ))/2`.
#[test]
fn two_angles_print_as_harmonics_of_the_angles_jointly() {
    let vars = phase_space();
    prints(
        &vars,
        "cos(theta)*cos(phi) + sin(theta)*sin(phi)",
        ["cos(θ − φ)", r"\cos(\theta - \varphi)", "cos(theta - phi)"],
    );
    prints(
        &vars,
        "cos(-theta + phi) - sin(phi - theta)",
        [
            "cos(θ − φ) + sin(θ − φ)",
            r"\cos(\theta - \varphi) + \sin(\theta - \varphi)",
            "cos(theta - phi) + sin(theta - phi)",
        ],
    );
    // A polynomial coefficient, a harmonic of one angle among them, and larger multiples.
    prints(
        &vars,
        "(x + p_x)*(cos(theta)*cos(phi) + sin(theta)*sin(phi)) + y*cos(2*theta) \
         - 3*x*sin(-2*theta + 3*phi)",
        [
            "(p_x + x) cos(θ − φ) + y cos 2θ + 3x sin(2θ − 3φ)",
            r"\left(p_{x} + x\right) \cos(\theta - \varphi) + y \cos 2\theta + 3 x \sin(2\theta - 3\varphi)",
            "(p_x + x)*cos(theta - phi) + y*cos(2*theta) + 3*x*sin(2*theta - 3*phi)",
        ],
    );
    prints(
        &vars,
        "2*x*cos(theta)*cos(phi) + 2*sin(theta)*cos(phi)",
        [
            "x cos(θ + φ) + x cos(θ − φ) + sin(θ + φ) + sin(θ − φ)",
            r"x \cos(\theta + \varphi) + x \cos(\theta - \varphi) + \sin(\theta + \varphi) + \sin(\theta - \varphi)",
            "x*cos(theta + phi) + x*cos(theta - phi) + sin(theta + phi) + sin(theta - phi)",
        ],
    );
    // In powers, the product of each angle's part, as before.
    prints_powers(
        &vars,
        "(x + p_x)*(cos(theta)*cos(phi) + sin(theta)*sin(phi))",
        [
            "(p_x + x) cos θ cos φ + (p_x + x) sin θ sin φ",
            r"\left(p_{x} + x\right) \cos\theta \cos\varphi + \left(p_{x} + x\right) \sin\theta \sin\varphi",
            "(p_x + x)*cos(theta)*cos(phi) + (p_x + x)*sin(theta)*sin(phi)",
        ],
    );
    // Every notation reads back, LaTeX too.
    for src in [
        "cos(2*theta - 3*phi)/5 + x*sin(theta + phi)",
        "sin(theta - phi)^3",
    ] {
        let f: G = p(&vars, src);
        for text in [f.to_string(), f.to_latex(), f.to_ascii()] {
            assert_eq!(p::<GaussianRational>(&vars, &text), f, "{src}: {text}");
        }
    }
}

/// Three angles print as harmonics of the three jointly, the first nonzero multiple positive,
/// and every notation reads back: `sin(−θ + φ − ψ) = −sin(θ − φ + ψ)`, and, worked by hand,
/// `cos θ cos φ = (cos(θ + φ) + cos(θ − φ))/2` and `cos α sin ψ = (sin(α + ψ) − sin(α − ψ))/2`,
/// so `4x cos θ cos φ sin ψ = x (sin(θ + φ + ψ) − sin(θ + φ − ψ) + sin(θ − φ + ψ) − sin(θ − φ −
/// ψ))`, printed in that order, the signs counted in binary; a Gaussian coefficient on
/// `e^{i(θ − 2φ)}`, `(1 + 2i)(cos + i sin) = (1 + 2i) cos + (−2 + i) sin`.
#[test]
fn three_angles_print_as_harmonics_of_the_three_jointly() {
    let vars = Vars::builder()
        .coordinate("x")
        .angle("theta")
        .angle("phi")
        .angle("psi")
        .build()
        .unwrap();
    prints(
        &vars,
        "sin(-theta + phi - psi) + 2*cos(theta - phi + psi)",
        [
            "2 cos(θ − φ + ψ) − sin(θ − φ + ψ)",
            r"2 \cos(\theta - \varphi + \psi) - \sin(\theta - \varphi + \psi)",
            "2*cos(theta - phi + psi) - sin(theta - phi + psi)",
        ],
    );
    let f: G = p(&vars, "4*x*cos(theta)*cos(phi)*sin(psi)");
    let by_hand: G = p(
        &vars,
        "x*(sin(theta + phi + psi) - sin(theta + phi - psi) + sin(theta - phi + psi) \
         - sin(theta - phi - psi))",
    );
    assert_eq!(f, by_hand);
    assert_eq!(
        f.to_ascii(),
        "x*sin(theta + phi + psi) - x*sin(theta + phi - psi) + x*sin(theta - phi + psi) \
         - x*sin(theta - phi - psi)"
    );
    let g: G = p(&vars, "(1 + 2*i)*exp(i*(theta - 2*phi))");
    assert_eq!(
        g.to_ascii(),
        "(1 + 2*i)*cos(theta - 2*phi) + (-2 + i)*sin(theta - 2*phi)"
    );
    for h in [f, g] {
        for text in [h.to_string(), h.to_latex(), h.to_ascii()] {
            assert_eq!(p::<GaussianRational>(&vars, &text), h, "{text}");
        }
    }
}

/// A name before parentheses is a product, as the paper and the claims' echo write it
/// (`Mω(3x p_x² − …)`, `i(mω − nΩ)`): it reads back as one; a name that is no product of
/// declared names is still an unknown function.
#[test]
fn a_name_before_parentheses_is_a_product() {
    let vars = plane();
    let g: G = p(&vars, "M*omega*(x + y) + i*(p_x - M*omega*y) + x*(y + 1)");
    let read: G = p(&vars, "Mω(x + y) + i(p_x − Mωy) + x(y + 1)");
    assert_eq!(read, g);
    let err = Poly::<GaussianRational>::parse(&vars, "f(x)").expect_err("no function f");
    assert!(
        err.message().starts_with("unknown function 'f'"),
        "{}",
        err.message()
    );
    let err = Poly::<GaussianRational>::parse(&vars, "theta(x)").expect_err("an angle");
    assert!(
        err.message().starts_with("unknown function 'theta'"),
        "{}",
        err.message()
    );
}

/// One-letter names side by side read back as one name when two or more of them in a row
/// spell a variable: beside coordinates `xy` and `ab`, the product x·y prints `x y`, and each
/// factor of such a run is spaced (`a b x`, `3i a x y`); any other run stays together as the
/// paper writes it, in the same element (`2ix`, `ax²y`), and so does every run where no name is
/// spelled by one-letter names (`Mω²xy`). A power or a longer name ends a run (`a b²x y`).
#[test]
fn one_letter_names_are_spaced_where_side_by_side_they_spell_another_name() {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("xy")
        .parameter("a")
        .parameter("b")
        .parameter("ab")
        .build()
        .unwrap();
    let reads_back = |src: &str, printed: &str| {
        let f: G = p(&vars, src);
        assert_eq!(f.to_string(), printed, "{src}");
        assert_eq!(
            p::<GaussianRational>(&vars, printed),
            f,
            "{printed:?} parses back"
        );
    };
    reads_back(
        "x*y + xy + a*b*x + ab*x + 2*i*x",
        "x y + a b x + ab x + 2ix + xy",
    );
    reads_back("a*x^2*y + b*x + 3*i*a*x*y", "ax²y + 3i a x y + bx");
    reads_back("a*b^2*x*y + x*xy", "a b²x y + x xy");

    // Only names the element writes count: without y, nothing spells `xy` or `ab`.
    assert_eq!(p::<GaussianRational>(&vars, "a*x*xy").to_string(), "ax xy");
    let plane = plane();
    assert_eq!(
        p::<GaussianRational>(&plane, "M*omega^2*x*y").to_string(),
        "Mω²xy"
    );
}

/// The runs of one-letter names that make juxtaposition ambiguous: two or more letters in a
/// row spell a declared name (`x y` of `M x y` beside `xy`, `o m e g a` beside `omega`), the
/// imaginary unit among them; letters that spell it out of order or apart do not (`y x`,
/// `x M y`), nor one letter alone, nor names with other characters (`p_x`, `G1`).
#[test]
fn juxtaposition_is_ambiguous_where_letters_in_a_row_spell_a_declared_name() {
    let ambiguous = |declared: &[&str], run: &[&str]| {
        trigpoly::juxtaposition_is_ambiguous(declared.iter().copied(), run)
    };
    let declared = [
        "x", "y", "xy", "o", "m", "e", "g", "a", "omega", "xi", "p", "p_x", "G1",
    ];
    assert!(ambiguous(&declared, &["x", "y"]));
    assert!(ambiguous(&declared, &["M", "x", "y", "z"]));
    assert!(ambiguous(&declared, &["o", "m", "e", "g", "a"]));
    assert!(
        ambiguous(&declared, &["x", "i"]),
        "i is the imaginary unit: `xi`"
    );
    assert!(!ambiguous(&declared, &["i", "x"]), "`ix` is no name");
    assert!(!ambiguous(&declared, &["y", "x"]), "out of order");
    assert!(!ambiguous(&declared, &["x", "M", "y"]), "apart");
    assert!(!ambiguous(&declared, &["x"]), "one letter");
    assert!(
        !ambiguous(&declared, &["o", "m", "e", "g"]),
        "a prefix of `omega`"
    );
    assert!(
        !ambiguous(&declared, &["p", "x", "G"]),
        "`p_x`, `G1` are not letters"
    );
}

/// A sum longer than the left-deep chain (`LEFT_DEEP_SUM` terms) is parsed as a balanced tree of
/// the same terms and signs: an alternating sum of 5000 powers equals its terms, and the text
/// and ASCII of a polynomial of 3003 terms read back (they passed the parser's height limit
/// of 2048 and were refused).
#[test]
fn long_sums_read_back() {
    let vars = crate::common::coordinates(&["x", "y", "z", "p_x", "p_y", "p_z"]);
    // The k-th term is ±x^(k mod 100) y^(k div 100), negative for odd k.
    let alternating: Vec<String> = (0..5000)
        .map(|k| {
            let sign = if k % 2 == 1 { "- " } else { "+ " };
            format!("{sign}x^{}*y^{}", k % 100, k / 100)
        })
        .collect();
    let f: Q = p(&vars, &alternating.join(" "));
    let (x, y) = (
        crate::common::var(&vars, "x"),
        crate::common::var(&vars, "y"),
    );
    assert_eq!(f.len(), 5000);
    for k in [0, 1, 2, 63, 64, 65, 127, 128, 4998, 4999] {
        let sign = if k % 2 == 1 { -1 } else { 1 };
        let c = f.coeff(&[(x, k % 100), (y, k / 100)]);
        assert_eq!(c, trigpoly::Rational::from(sign), "term {k}");
    }
    let long: G = p(&vars, "(x + y + z + p_x + p_y + p_z + 1)^8 - 2*(x - y)^20");
    assert!(long.len() > 3000);
    for text in [long.to_string(), long.to_ascii()] {
        assert_eq!(p::<GaussianRational>(&vars, &text), long);
    }
}

/// Names declared in Greek letters print in ASCII spelled out (`p_theta`, `cos(theta)`), so
/// the ASCII form is ASCII and reads back; it printed `p_θ*cos(θ)`.
#[test]
fn ascii_spells_out_names_declared_in_greek() {
    let vars = Vars::builder()
        .coordinate("ξ")
        .momentum("p_ξ")
        .angle("θ")
        .momentum("p_θ")
        .parameter("ω")
        .build()
        .unwrap();
    let f: G = p(&vars, "ω*ξ*p_θ*cos(θ) + p_ξ^2/2");
    let ascii = f.to_ascii();
    assert!(ascii.is_ascii(), "{ascii}");
    assert!(ascii.contains("omega*xi*p_theta*cos(theta)"), "{ascii}");
    assert_eq!(p::<GaussianRational>(&vars, &ascii), f);
}

/// An angle's argument may run `i` and the angle together, as the paper and superint's echo
/// write `exp(iθ)` (it was "unknown angle 'iθ'"); a product of two angles is still refused.
#[test]
fn exp_of_i_theta_written_together() {
    let vars = plane();
    let together: G = p(&vars, "exp(iθ) - exp(-iθ)");
    assert_eq!(together, p(&vars, "exp(i*theta) - exp(-i*theta)"));
    assert!(G::parse(&vars, "exp(iθθ)").is_err());
}

/// Every Greek letter a name may be declared in has an ASCII spelling, so the ASCII form is
/// ASCII (`ϑ` printed as itself, and did not read back from an ASCII-only source).
#[test]
fn greek_variants_spell_out_in_ascii() {
    let vars = Vars::builder()
        .angle("ϑ")
        .momentum("p_ϑ")
        .parameter("π")
        .parameter("ϱ")
        .parameter("Σ")
        .build()
        .unwrap();
    let f: G = p(&vars, "π*ϱ*Σ*p_ϑ*cos(ϑ)");
    let ascii = f.to_ascii();
    assert_eq!(ascii, "pi*varrho*Sigma*p_vartheta*cos(vartheta)");
    assert_eq!(p::<GaussianRational>(&vars, &ascii), f);
}

/// `hbar` and `ell` print as `ħ` and `ℓ`, as `omega` prints as `ω`, run together with other
/// one-letter names as the paper writes `ħω`; their LaTeX is `\hbar`, `\ell`, and the ASCII
/// form spells them out, as a name declared `ħ` is spelled (it printed `ħ`, no ASCII). They
/// printed as words, `hbar ℓ`, `\mathrm{hbar}`; a name declared `ħ` printed `{\hbar}`.
#[test]
fn hbar_and_ell_print_as_letters() {
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .parameter("hbar")
        .parameter("ℓ")
        .parameter("omega")
        .build()
        .unwrap();
    prints(
        &vars,
        "hbar*omega*x + ell^2*p_x",
        [
            "ℓ² p_x + ħωx",
            r"\ell^{2} p_{x} + \hbar \omega x",
            "ell^2*p_x + hbar*omega*x",
        ],
    );
    assert_eq!(
        p::<GaussianRational>(&vars, "ħ*ω*x + ℓ^2*p_x"),
        p::<GaussianRational>(&vars, "hbar*omega*x + ell^2*p_x")
    );
}

/// High powers of cosines and sines print as the single terms they are, in two angles too:
/// the conversion from `e^{ikθ}` goes one angle at a time, with the powers of
/// `cos θ + i sin θ` formed one from the next (`cos¹⁵⁰a cos¹⁵⁰b` took 37 s to print, and
/// `cos¹⁰⁰⁰φ` 24 s). Each printed form reads back as the same element.
#[test]
fn high_trigonometric_powers_print_as_single_terms() {
    let vars = phase_space();
    for (src, shown) in [
        ("cos(theta)^60*cos(phi)^60", "cos⁶⁰θ cos⁶⁰φ"),
        ("x*cos(theta)^41*sin(phi)", "x cos⁴¹θ sin φ"),
        ("cos(phi)^400", "cos⁴⁰⁰φ"),
    ] {
        let f: G = p(&vars, src);
        assert_eq!(f.with_angles(Angles::Powers).to_string(), shown, "{src}");
        assert_eq!(p::<GaussianRational>(&vars, &f.to_ascii()), f, "{src}");
    }
    // A sum whose terms cancel in the conversion of the second angle only.
    let f: G = p(
        &vars,
        "cos(theta)^3*(cos(phi)^2 + sin(phi)^2) - cos(theta)^3",
    );
    assert!(f.is_zero());
    let g: G = p(&vars, "(cos(theta) + sin(phi))^7");
    assert_eq!(p::<GaussianRational>(&vars, &g.to_ascii()), g);
}

/// Coordinates and a momentum between two angles, `x, a, y, p_x, b`.
fn two_angles() -> Vars {
    Vars::builder()
        .coordinate("x")
        .angle("a")
        .coordinate("y")
        .momentum("p_x")
        .angle("b")
        .build()
        .unwrap()
}

/// The leading part of an element (the terms of its first `k` monomials outside the angles)
/// prints terms of the whole only: the cos/sin normal form combines the `e^{ikθ}` terms of one
/// monomial outside the angles and no others, so each printed term of the part is a printed
/// term of the whole, and the part of every monomial is the whole.
#[test]
fn leading_part_prints_terms_of_the_whole() {
    let vars = two_angles();
    let f: G = p(
        &vars,
        "(1 + x + y*cos(a) + p_x*sin(2*b) + cos(a - b) + i*x*sin(b))^5",
    );
    let whole = f.cos_sin_terms();
    let mut outside: Vec<&Vec<i64>> = whole.iter().map(|t| &t.exps).collect();
    outside.sort();
    outside.dedup();
    let mut parts = Vec::new();
    for k in [
        0,
        1,
        2,
        5,
        17,
        outside.len() - 1,
        outside.len(),
        outside.len() + 3,
    ] {
        let (part, monomials) = f.leading_part(k);
        assert_eq!(monomials, outside.len());
        let terms = part.cos_sin_terms();
        let mut shown: Vec<&Vec<i64>> = terms.iter().map(|t| &t.exps).collect();
        shown.sort();
        shown.dedup();
        assert_eq!(shown.len(), k.min(monomials), "k = {k}");
        for t in &terms {
            assert!(whole.contains(t), "k = {k}: {t:?} is no term of the whole");
        }
        // Every term of a shown monomial is shown.
        let of_shown = whole.iter().filter(|t| shown.contains(&&t.exps)).count();
        assert_eq!(terms.len(), of_shown, "k = {k}");
        parts.push(part);
    }
    assert!(parts[0].is_zero());
    assert_eq!(parts[parts.len() - 2], f);
    assert_eq!(parts[parts.len() - 1], f);
}

/// A message's text of an element: in full when short; else its first terms, each a printed
/// term of the whole, within 80 characters, then `+ …` and its number of terms; its size alone
/// when not even one monomial's terms fit.
#[test]
fn brief_excerpt_shows_a_long_element_in_part_with_its_size() {
    let vars = phase_space();
    let short: G = p(&vars, "x^2 - 3*y + 1");
    assert_eq!(short.brief_excerpt(), "x² − 3y + 1");
    let long: G = p(&vars, "(x + 2*y + 3*p_x + 1)^25");
    let text = long.brief_excerpt();
    let size = format!(" + … (a polynomial of {} terms)", long.len());
    let Some(shown) = text.strip_suffix(&size) else {
        panic!("{text}")
    };
    assert!(shown.chars().count() <= 80, "{text}");
    assert!(shown.contains("x²⁵ + 50x²⁴y"), "{text}");
    // What is shown is a leading part of the whole, term for term.
    let part = (1..=8)
        .map(|k| long.leading_part(k).0)
        .find(|part| part.to_string() == shown);
    assert!(part.is_some(), "{text}");
    // One monomial's terms past 80 characters: the size alone.
    let wide: G = p(&vars, "x*(cos(theta)^30 + sin(phi)^30)");
    assert_eq!(
        wide.brief_excerpt(),
        format!("a polynomial of {} terms", wide.len())
    );
}

/// The bound on the printed terms is never below their number in either form of the angles,
/// is exact for a multiple of `e^{ikθ}` (`k + 1` terms in powers, `cos kθ` and `sin kθ` in
/// harmonics), and `check_printable` refuses past the term limit the terms of the form printed
/// (harmonics, the default): `(1 + x)⁴ e^{9ia}` is 10 terms (50 in powers), `(1 + x)²⁴ e^{ia}` 50.
#[test]
fn the_printed_terms_are_bounded_before_they_are_formed() {
    let vars = two_angles();
    for text in [
        "x*exp(7*i*a)",
        "cos(a)^2",
        "(x + y*cos(a) + p_x*sin(2*b) + cos(a - b))^4",
        "(1 + x + y*cos(a) + p_x*sin(2*b) + cos(a - b) + i*x*sin(b))^5",
        "x + y",
    ] {
        let f: G = p(&vars, text);
        let powers = f.cos_sin_terms().len() as u64;
        assert!(f.printed_terms_bound(Angles::Powers) >= powers, "{text}");
        let harmonics = f.harmonic_terms().len() as u64;
        assert!(
            f.printed_terms_bound(Angles::Harmonics) >= harmonics,
            "{text}"
        );
    }
    let seven: G = p(&vars, "x*exp(7*i*a)");
    assert_eq!(seven.printed_terms_bound(Angles::Powers), 8);
    assert_eq!(seven.printed_terms_bound(Angles::Harmonics), 2);
    let limited = Vars::builder()
        .coordinate("x")
        .angle("a")
        .limits(trigpoly::Limits::default().max_terms(40))
        .build()
        .unwrap();
    let wide: G = p(&limited, "(1 + x)^24*exp(i*a)");
    assert_eq!(wide.len(), 25);
    let err = wide.check_printable().unwrap_err().to_string();
    assert!(
        err.contains("printed in multiple angles, the result could have up to 50 terms (e^(ikθ) takes up to 2, cos kθ and sin kθ)"),
        "{err}"
    );
    let high: G = p(&limited, "(1 + x)^4*exp(9*i*a)");
    assert_eq!(high.harmonic_terms().len(), 10);
    assert!(high.check_printable().is_ok());
}

/// Asserts the factored form of `src` in unicode, LaTeX and ASCII, and that both the unicode
/// and the ASCII forms parse back to the element.
fn factors_as(vars: &Vars, src: &str, [unicode, latex, ascii]: [&str; 3]) {
    let f: G = p(vars, src);
    let factored = f
        .factored()
        .unwrap_or_else(|| panic!("{src} has a common factor"));
    assert_eq!(
        [
            factored.to_string(),
            factored.render(Style::Latex),
            factored.render(Style::Ascii)
        ],
        [unicode.to_string(), latex.to_string(), ascii.to_string()],
        "{src}"
    );
    for text in [unicode, ascii] {
        assert_eq!(p::<GaussianRational>(vars, text), f, "{text:?} parses back");
    }
}

/// The factor a sum's terms share comes out in front of it (its content signed as the first
/// term, the least power of each variable on one side of the bar), the denominators after.
#[test]
fn a_sum_prints_as_the_factor_its_terms_share_times_the_rest() {
    let vars = plane();
    factors_as(
        &vars,
        "omega*x*p_x/M + omega*y*p_y/M",
        [
            "ω(x p_x + y p_y)/M",
            r"\frac{\omega \left(x p_{x} + y p_{y}\right)}{M}",
            "omega*(x*p_x + y*p_y)/M",
        ],
    );
    factors_as(
        &vars,
        "-2*x - 4*y",
        ["−2(x + 2y)", r"-2 \left(x + 2 y\right)", "-2*(x + 2*y)"],
    );
    // Over a common denominator, where the terms have different powers below the bar.
    factors_as(
        &vars,
        "omega^2*p_y/(x^2*y^3) + omega^2*p_x/(x^3*y^2)",
        [
            "ω²(x p_y + y p_x)/(x³y³)",
            r"\frac{\omega^{2} \left(x p_{y} + y p_{x}\right)}{x^{3} y^{3}}",
            "omega^2*(x*p_y + y*p_x)/(x^3*y^3)",
        ],
    );
    // The angles stay inside; a purely imaginary coefficient keeps its `i` there.
    factors_as(
        &vars,
        "x*cos(theta)/3 + y*sin(theta)/3",
        [
            "(x cos θ + y sin θ)/3",
            r"\frac{x \cos\theta + y \sin\theta}{3}",
            "(x*cos(theta) + y*sin(theta))/3",
        ],
    );
    factors_as(
        &vars,
        "6*i*omega*p_x^2 - 4*omega*M*x*p_y",
        [
            "2ω(3i p_x² − 2Mx p_y)",
            r"2 \omega \left(3 i p_{x}^{2} - 2 M x p_{y}\right)",
            "2*omega*(3*i*p_x^2 - 2*M*x*p_y)",
        ],
    );
}

/// A sum of imaginary terms has `i` in its factor: `2i(x + 3y)`, `i(ω − Ω)`.
#[test]
fn an_imaginary_sum_has_i_in_its_factor() {
    let vars = plane();
    factors_as(
        &vars,
        "2*i*x + 6*i*y",
        ["2i(x + 3y)", r"2 i \left(x + 3 y\right)", "2*i*(x + 3*y)"],
    );
    factors_as(
        &vars,
        "-i*omega*p_x/M + i*omega*p_y/M",
        [
            "−iω(p_x − p_y)/M",
            r"-\frac{i \omega \left(p_{x} - p_{y}\right)}{M}",
            "-i*omega*(p_x - p_y)/M",
        ],
    );
}

/// A polynomial in named functions (coordinates that are words, the parameters its
/// coefficients) writes the functions it shares after the parentheses, as the paper does:
/// `−(2ω − 3Ω) Q`, `iM(ω + Ω) Z̄ W/2`; a factor of parameters alone stays in front.
#[test]
fn a_polynomial_in_functions_writes_their_common_factor_last() {
    let vars = Vars::builder()
        .parameter("omega")
        .parameter("M")
        .coordinate("Q")
        .word()
        .coordinate("Omega")
        .shown_as("Ω")
        .word()
        .coordinate("H")
        .word()
        .coordinate("L")
        .word()
        .build()
        .unwrap();
    let cases = [
        (
            "-2*omega*Q + 3*Omega*Q",
            [
                "−(2ω − 3 Ω) Q",
                r"-\left(2 \omega - 3 \Omega\right) Q",
                "-(2*omega - 3*Omega)*Q",
            ],
        ),
        (
            "i*M*omega*Q*L/2 + i*M*Omega*Q*L/2",
            [
                "iM(ω + Ω) Q L/2",
                r"i M \left(\omega + \Omega\right) \frac{Q L}{2}",
                "i*M*(omega + Omega)*Q*L/2",
            ],
        ),
        (
            "72*M^3*H*L^2 - 96*M^3*L^3",
            [
                "24M³(3 H − 4 L) L²",
                r"24 M^{3} \left(3 H - 4 L\right) L^{2}",
                "24*M^3*(3*H - 4*L)*L^2",
            ],
        ),
        (
            "2*omega*H + 2*omega*L",
            [
                "2ω(H + L)",
                r"2 \omega \left(H + L\right)",
                "2*omega*(H + L)",
            ],
        ),
    ];
    for (src, expected) in cases {
        let f: G = p(&vars, src);
        let factored = f.factored().expect("a common factor");
        let shown =
            [Style::Unicode, Style::Latex, Style::Ascii].map(|s| factored.render_functions_last(s));
        assert_eq!(shown, expected, "{src}");
        assert_eq!(
            p::<GaussianRational>(&vars, expected[2]),
            f,
            "{src}: the ASCII parses back"
        );
    }
}

/// A sum has no factored form where its terms share only `±1`, where a variable stands on
/// both sides of the bar (a Hamiltonian's `p_x²/(2M) + Mω²x²/2`), or where it has one term.
#[test]
fn a_sum_whose_terms_share_no_factor_has_no_factored_form() {
    let vars = plane();
    for src in [
        "x + y",
        "-x - y",
        "p_x^2/(2*M) + M*omega^2*x^2/2",
        "x/M + y/M^2 + 1",
        "i*x - i*y",
        "3*M*x*p_y",
        "0",
    ] {
        let f: G = p(&vars, src);
        assert!(
            f.factored().is_none(),
            "{src}: {:?}",
            f.factored().map(|f| f.to_string())
        );
    }
}

/// A variable shown with a bar (`c` shown `ā`, as a closure's generator `Zbar` is shown `Z̄`)
/// is read by its display however the bar is written, precomposed `ā` or LaTeX `\bar{a}`: the
/// latter was told "the complex conjugate of a is written conj(a)", of the variable `a`
/// beside it.
#[test]
fn a_variable_shown_with_a_bar_reads_by_its_display_however_the_bar_is_written() {
    let vars = (Vars::builder().parameter("a").parameter("c"))
        .shown_as("ā")
        .build()
        .unwrap();
    let c = Poly::<GaussianRational>::parse(&vars, "c").unwrap();
    for text in ["ā", "\\bar{a}", "\\bar{a} + a - a"] {
        let read = Poly::<GaussianRational>::parse(&vars, text);
        assert_eq!(
            read.map_err(|e| e.message().to_string()),
            Ok(c.clone()),
            "{text}"
        );
    }
    let conj = Poly::<GaussianRational>::parse(&vars, "\\bar{c}").unwrap_err();
    assert_eq!(
        conj.message(),
        "unknown name 'c\u{304}': the complex conjugate of c is written conj(c)"
    );
}
