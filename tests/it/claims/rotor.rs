//! Section 2: a rotor on a planar system, `H = (p_x² + p_y²)/(2M) + V(x, y) + p_θ²/(2I)`.

use brackets::{systems, Condition};

use super::{rendered_table, table};
use trigpoly::Expr;

/// The general polynomial `V = Σ_{i+j ≤ d} a_ij x^i y^j` with symbolic coefficients `a_ij`, and
/// its partial derivatives `V_x`, `V_y` written out term by term (not by the engine).
fn general_potential(degree: u32) -> (String, String, String, Vec<String>) {
    let (mut v, mut vx, mut vy, mut params) = (vec![], vec![], vec![], vec![]);
    for i in 0..=degree {
        for j in 0..=degree - i {
            let a = format!("a{i}{j}");
            v.push(format!("{a}*x^{i}*y^{j}"));
            if i > 0 {
                vx.push(format!("{i}*{a}*x^{}*y^{j}", i - 1));
            }
            if j > 0 {
                vy.push(format!("{j}*{a}*x^{i}*y^{}", j - 1));
            }
            params.push(a);
        }
    }
    (v.join(" + "), vx.join(" + "), vy.join(" + "), params)
}

#[test]
fn c01_hamilton_equations_general_potential() {
    let (v, vx, vy, params) = general_potential(4);
    let params: Vec<&str> = params.iter().map(String::as_str).collect();
    assert_eq!(
        params.len(),
        15,
        "every monomial of degree ≤ 4 has its own coefficient"
    );
    let mut sys = systems::rotor(&v, &params).unwrap();
    let deg = sys
        .get("V")
        .unwrap()
        .total_degree(&[trigpoly::VarKind::Coordinate]);
    assert_eq!(deg, Some(4));
    sys.define_parsed("V_x", "V_x", &vx).unwrap();
    sys.define_parsed("V_y", "V_y", &vy).unwrap();
    // Hamilton's vector field (q̇, ṗ) = (∂H/∂p, −∂H/∂q), named `xdot`, `thetadot`, `p_xdot`, ...
    // (θ is not a ring element, so θ̇ comes from ∂H/∂p_θ, not from a bracket).
    let field = sys.space().hamilton_equations(sys.hamiltonian()).unwrap();
    assert_eq!(field.len(), 6);
    for (v, rate) in field {
        let name = format!("{}dot", sys.vars().variable(v).name());
        sys.define(&name, &name, rate).unwrap();
    }
    identity!(sys, "xdot = p_x/M");
    identity!(sys, "ydot = p_y/M");
    identity!(sys, "thetadot = p_theta/I");
    identity!(sys, "p_xdot = -V_x");
    identity!(sys, "p_ydot = -V_y");
    identity!(sys, "p_thetadot = 0");
    // The same as brackets {q, H}.
    identity!(sys, "{x, H} = p_x/M");
    identity!(sys, "{y, H} = p_y/M");
    identity!(sys, "{p_x, H} = -V_x");
    identity!(sys, "{p_y, H} = -V_y");
    identity!(sys, "{p_theta, H} = 0");
    // False neighbours: the force with the wrong sign, the rotor with twice the inertia.
    identity!(sys, "{p_x, H} = V_x" => refuted "-2*V_x");
    identity!(sys, "p_ydot = -V_y + a04*y^3" => refuted "-a04*y^3");
    identity!(sys, "thetadot = p_theta/(2*I)" => refuted "p_theta/(2*I)");
}

#[test]
fn c02_central_potential_involution() {
    // V(r²) = c0 + c1 r² + c2 r⁴ + c3 r⁶: degree 3 in r².
    let v = "c0 + c1*(x^2 + y^2) + c2*(x^2 + y^2)^2 + c3*(x^2 + y^2)^3";
    let mut sys = systems::rotor(v, &["c0", "c1", "c2", "c3"]).unwrap();
    sys.define_parsed("F1", "F1", "H").unwrap();
    sys.define_parsed("F2", "F2", "x*p_y - y*p_x").unwrap();
    sys.define_parsed("F3", "F3", "p_theta").unwrap();
    identity!(sys, "{F1, F2} = 0");
    identity!(sys, "{F1, F3} = 0");
    identity!(sys, "{F2, F3} = 0");
    // False neighbour: x p_y + y p_x (a flipped sign in L) is not conserved.
    identity!(
        sys, "{F1, x*p_y + y*p_x} = 0"
        => refuted "-2*p_x*p_y/M + 4*x*y*(c1 + 2*c2*(x^2 + y^2) + 3*c3*(x^2 + y^2)^2)"
    );
    // False neighbour: a non-central term d x² breaks the involution {F1, F2} = 0.
    let mut off = systems::rotor(&format!("{v} + d*x^2"), &["c0", "c1", "c2", "c3", "d"]).unwrap();
    off.define_parsed("F2", "F2", "x*p_y - y*p_x").unwrap();
    identity!(off, "{H, F2} = 0" => refuted "-2*d*x*y");
}

#[test]
fn c03_no_rotor_momentum_gives_planar_hamiltonian() {
    let (v, _, _, params) = general_potential(4);
    let params: Vec<&str> = params.iter().map(String::as_str).collect();
    let sys = systems::rotor(&v, &params).unwrap();
    let at_rest = Condition::new("p_θ = 0", sys.var("p_theta"), Expr::zero(sys.vars()));
    let planar = format!("H = (p_x^2 + p_y^2)/(2*M) + {v}");
    identity!(sys, planar, when at_rest);
    // False neighbour: without p_θ = 0 the rotor's energy is left over.
    identity!(sys, planar => refuted "p_theta^2/(2*I)");
}

#[test]
fn section2_bracket_table_renders() {
    let v = "c0 + c1*(x^2 + y^2) + c2*(x^2 + y^2)^2 + c3*(x^2 + y^2)^3";
    let mut sys = systems::rotor(v, &["c0", "c1", "c2", "c3"]).unwrap();
    sys.define_parsed("F1", "F1", "H").unwrap();
    sys.define_parsed("F2", "F2", "x*p_y - y*p_x").unwrap();
    sys.define_parsed("F3", "F3", "p_theta").unwrap();
    sys.define_parsed("D", "D", "x*p_y + y*p_x").unwrap();
    // {F2, D} = {L, x p_y + y p_x} = −2(x p_x − y p_y): no combination of F1, F2, F3, D.
    identity!(sys, "{F2, D} = -2*(x*p_x - y*p_y)");
    let t = rendered_table(&sys, &["F1", "F2", "F3", "D"]);
    pretty_assertions::assert_eq!(
        t[..3].iter().map(|r| r[..3].to_vec()).collect::<Vec<_>>(),
        table(&[&["0", "0", "0"], &["0", "0", "0"], &["0", "0", "0"]])
    );
    pretty_assertions::assert_eq!(
        [
            t[1][3].as_str(),
            t[2][3].as_str(),
            t[3][1].as_str(),
            t[3][2].as_str()
        ],
        ["−2x p_x + 2y p_y", "0", "2x p_x − 2y p_y", "0"]
    );
}
