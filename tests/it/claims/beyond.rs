//! Section 5: beyond the paper's examples. The anisotropic oscillator 3 : 5 coupled to the rotor
//! (C26), and the planar limits `V_I`, `V_II` with their second-order integrals (C27).
//!
//! What the engine found and proves here:
//!
//! - C26, `V = M(9ω²x² + 25ω²y²)/2`, ladders `A_x = p_x + 3iMωx`, `A_y = p_y + 5iMωy` with
//!   `{A_x, H} = 3iω A_x`, `{A_y, H} = 5iω A_y`. The planar integral of order 8
//!   `S = A_x⁵ Ā_y³` (eigenvalue `i(5·3 − 3·5)ω = 0`) is conserved with no condition, and so are
//!   `Re S`, `Im S`. With the rotor, `K = A_x² Ā_y e^{−iθ}` (cubic) has eigenvalue
//!   `i(6ω − 5ω − Ω)`: conserved exactly at `Ω = ω` (`p_θ = Iω`), with `Re K`, `Im K`; and
//!   `J = A_x e^{−iθ}`, `Re J = p_x cos θ + 3Mωx sin θ`, is conserved at `Ω = 3ω`. The Jacobian
//!   of `(H_x, H_y, F2, Re S, Re K)` has rank 5 (4 without `Re K`; `Im S` adds nothing since
//!   `|S|² = (2M H_x)⁵ (2M H_y)³`).
//! - C27, `V_I = α(x² + y²) + β/x² + γ/y²`: `H_x = p_x²/(2M) + αx² + β/x²`, `H_y` likewise and
//!   `X_I = L² + 2M(βy²/x² + γx²/y²)`. `V_II = α(x² + 4y²) + β/x² + γy`:
//!   `H_y = p_y²/(2M) + 4αy² + γy` and `X_II = L p_x + M(2αx²y − 2βy/x² + γx²/2)`, its
//!   coefficients found by the engine from the ansatz `L p_x + M(a αx²y + b βy/x² + c γx²)`.

use brackets::table::express;
use brackets::{systems, FunctionName, System, UpperBound};
use trigpoly::{Expr, VarKind};

use super::{assert_rank, rendered_table, table};

/// Defines `name`, `name_re`, `name_im` from `src`.
fn define_with_parts(sys: &mut System, name: &str, src: &str) {
    let f = sys.parse(src).unwrap();
    sys.define(
        &format!("{name}_re"),
        &format!("Re {name}"),
        f.re().unwrap(),
    )
    .unwrap();
    sys.define(
        &format!("{name}_im"),
        &format!("Im {name}"),
        f.im().unwrap(),
    )
    .unwrap();
    sys.define(name, name, f).unwrap();
}

#[test]
fn c26_anisotropic_3_5_rotor_resonant_integrals() {
    let mut sys = systems::anisotropic_rotor(3, 5);
    identity!(sys, "H = Hx + Hy + F2");
    identity!(sys, "Ax = p_x + 3*i*M*omega*x");
    identity!(sys, "Ay = p_y + 5*i*M*omega*y");
    identity!(sys, "Hx = Ax*Axbar/(2*M)");
    identity!(sys, "Hy = Ay*Aybar/(2*M)");
    for f in ["Hx", "Hy", "F2"] {
        identity!(sys, format!("{{{f}, H}} = 0"));
    }
    // The ladders.
    identity!(sys, "{Ax, H} = 3*i*omega*Ax");
    identity!(sys, "{Ay, H} = 5*i*omega*Ay");
    identity!(sys, "{Axbar, H} = -3*i*omega*Axbar");
    identity!(sys, "{Aybar, H} = -5*i*omega*Aybar");
    identity!(sys, "{Ax, H} = 5*i*omega*Ax" => refuted "-2*i*omega*Ax");

    // The planar integral of order 8, conserved without condition.
    define_with_parts(&mut sys, "S", "Ax^5*Aybar^3");
    for f in ["S", "S_re", "S_im"] {
        identity!(sys, format!("{{{f}, H}} = 0"));
    }
    let order = sys.get("S_re").unwrap();
    let order = order.total_degree(&[VarKind::Coordinate, VarKind::Momentum]);
    assert_eq!(order, Some(8));
    identity!(sys, "S_re^2 + S_im^2 = (2*M*Hx)^5*(2*M*Hy)^3");
    // False neighbours: other powers are not conserved.
    identity!(sys, "{Ax^4*Aybar^3, H} = 0" => refuted "-3*i*omega*Ax^4*Aybar^3");
    identity!(sys, "{Ax*Aybar, H} = 0" => refuted "-2*i*omega*Ax*Aybar");

    // With the rotor: K = A_x² Ā_y e^{−iθ}, eigenvalue i(6ω − 5ω − Ω), conserved at Ω = ω.
    define_with_parts(&mut sys, "K", "Ax^2*Aybar*exp(-i*theta)");
    identity!(sys, "{K, H} = i*(6*omega - 5*omega - Omega)*K");
    let at_one = sys.resonance(1, 1).unwrap();
    for f in ["K", "K_re", "K_im"] {
        identity!(sys, format!("{{{f}, H}} = 0"), when at_one);
    }
    // Off the resonance: at Ω = 2ω, {Re K, H} = −(ω − Ω) Im K = ω Im K.
    let at_two = sys.resonance(2, 1).unwrap();
    identity!(sys, "{K_re, H} = 0", when at_two => refuted "omega*K_im");
    identity!(sys, "{K_im, H} = 0", when at_two => refuted "-omega*K_re");
    identity!(sys, "{K_re, H} = 0" => refuted "-(omega - Omega)*K_im");

    // J = A_x e^{−iθ}, conserved at Ω = 3ω.
    define_with_parts(&mut sys, "J", "Ax*exp(-i*theta)");
    identity!(sys, "J_re = p_x*cos(theta) + 3*M*omega*x*sin(theta)");
    identity!(sys, "J_im = 3*M*omega*x*cos(theta) - p_x*sin(theta)");
    identity!(sys, "{J, H} = i*(3*omega - Omega)*J");
    let at_three = sys.resonance(3, 1).unwrap();
    identity!(sys, "{J_re, H} = 0", when at_three);
    identity!(sys, "{J_im, H} = 0", when at_three);
    identity!(sys, "{J_re, H} = 0", when at_one => refuted "-2*omega*J_im");

    // Five functionally independent integrals; four without Re K; Im S adds nothing.
    assert_rank(
        &sys,
        &["Hx", "Hy", "F2", "S_re", "K_re"],
        5,
        UpperBound::Size,
    );
    assert_rank(&sys, &["Hx", "Hy", "F2", "S_re"], 4, UpperBound::Size);
    assert_rank(
        &sys,
        &["Hx", "Hy", "F2", "S_re", "S_im"],
        4,
        UpperBound::VanishingMinors { count: 2 },
    );
}

/// The coefficients `c_k` of `target = Σ c_k basis_k` found by the engine (exact linear
/// algebra), in the order of `basis`.
fn solve(sys: &System, target: &str, basis: &[&str]) -> Vec<Expr> {
    let parse = |s: &str| sys.parse(s).unwrap();
    let basis: Vec<(FunctionName, Expr)> = basis
        .iter()
        .map(|b| {
            let name = FunctionName {
                name: b.to_string(),
                display: b.to_string(),
            };
            (name, parse(b))
        })
        .collect();
    let found = express(&parse(target), &basis)
        .unwrap()
        .expect("a combination exists");
    basis
        .iter()
        .map(|(name, _)| {
            found
                .iter()
                .find(|(_, n)| n == name)
                .map_or_else(|| Expr::zero(sys.vars()), |(c, _)| c.clone())
        })
        .collect()
}

#[test]
fn c27_planar_limits_second_order_integrals() {
    // V_I = α(x² + y²) + β/x² + γ/y².
    let one = systems::planar_i_rotor();
    identity!(
        one,
        "H = (p_x^2 + p_y^2)/(2*M) + alpha*(x^2 + y^2) + beta/x^2 + gamma/y^2 + F2"
    );
    identity!(one, "H = Hx + Hy + F2");
    identity!(one, "Hx = p_x^2/(2*M) + alpha*x^2 + beta/x^2");
    identity!(one, "Hy = p_y^2/(2*M) + alpha*y^2 + gamma/y^2");
    identity!(
        one,
        "X = (x*p_y - y*p_x)^2 + 2*M*(beta*y^2/x^2 + gamma*x^2/y^2)"
    );
    for f in ["Hx", "Hy", "X", "F2"] {
        identity!(one, format!("{{{f}, H}} = 0"));
    }
    // X's coefficients, found by the engine: −{L², H} = a{Mβy²/x², H} + b{Mγx²/y², H}.
    let c = solve(
        &one,
        "-{L^2, H}",
        &["{M*beta*y^2/x^2, H}", "{M*gamma*x^2/y^2, H}"],
    );
    assert_eq!(c, [one.parse("2").unwrap(), one.parse("2").unwrap()]);
    // False neighbour: half the centrifugal terms.
    identity!(
        one, "{L^2 + M*(beta*y^2/x^2 + gamma*x^2/y^2), H} = 0"
        => refuted "L*(-2*beta*y/x^3 + 2*gamma*x/y^3)"
    );
    assert_rank(&one, &["H", "F2", "Hx", "X"], 4, UpperBound::Size);
    assert_rank(
        &one,
        &["H", "F2", "Hx", "Hy", "X"],
        4,
        UpperBound::VanishingMinors { count: 2 },
    );

    // V_II = α(x² + 4y²) + β/x² + γy.
    let two = systems::planar_ii_rotor();
    identity!(
        two,
        "H = (p_x^2 + p_y^2)/(2*M) + alpha*(x^2 + 4*y^2) + beta/x^2 + gamma*y + F2"
    );
    identity!(two, "H = Hx + Hy + F2");
    identity!(two, "Hy = p_y^2/(2*M) + 4*alpha*y^2 + gamma*y");
    identity!(
        two,
        "X = (x*p_y - y*p_x)*p_x + M*(2*alpha*x^2*y - 2*beta*y/x^2 + gamma*x^2/2)"
    );
    for f in ["Hx", "Hy", "X", "F2"] {
        identity!(two, format!("{{{f}, H}} = 0"));
    }
    // X's coefficients, found by the engine from the ansatz L p_x + M(aαx²y + bβy/x² + cγx²).
    let c = solve(
        &two,
        "-{L*p_x, H}",
        &[
            "{M*alpha*x^2*y, H}",
            "{M*beta*y/x^2, H}",
            "{M*gamma*x^2, H}",
        ],
    );
    let want: Vec<Expr> = ["2", "-2", "1/2"]
        .iter()
        .map(|s| two.parse(s).unwrap())
        .collect();
    assert_eq!(c, want);
    // False neighbour: without the γ term.
    identity!(
        two, "{L*p_x + M*(2*alpha*x^2*y - 2*beta*y/x^2), H} = 0"
        => refuted "-gamma*x*p_x"
    );
    assert_rank(&two, &["H", "F2", "Hy", "X"], 4, UpperBound::Size);
}

#[test]
fn section5_bracket_table_renders() {
    let sys = systems::anisotropic_rotor(3, 5);
    pretty_assertions::assert_eq!(
        rendered_table(&sys, &["Hx", "Hy", "F2", "Ax", "Ay"]),
        table(&[
            &["0", "0", "0", "−3iω A_x", "0"],
            &["0", "0", "0", "0", "−5iω A_y"],
            &["0", "0", "0", "0", "0"],
            &["3iω A_x", "0", "0", "0", "0"],
            &["0", "5iω A_y", "0", "0", "0"],
        ])
    );
    // V_II: {H_x, X} is no combination of the integrals, and {H_y, X} = −{H_x, X}.
    let hx_x = "−p_x² p_y/M + 2αx² p_y − 8αxy p_x − γx p_x − 2β p_y/x²";
    let hy_x = "p_x² p_y/M − 2αx² p_y + 8αxy p_x + γx p_x + 2β p_y/x²";
    let two = systems::planar_ii_rotor();
    pretty_assertions::assert_eq!(
        rendered_table(&two, &["Hx", "Hy", "X"]),
        table(&[&["0", "0", hx_x], &["0", "0", hy_x], &[hy_x, hx_x, "0"]])
    );
    identity!(two, "{Hy, X} = -{Hx, X}");
}
