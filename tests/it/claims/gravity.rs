//! Section 4: the harmonic rotor in a vertical plane, `H_g = H + Mgy`, `y' = y + g/ω²`.

use brackets::{check_tower, eigen_proof, eigen_proof_of, systems, UpperBound};

use super::{assert_rank, define_family, rendered_table, table};

#[test]
fn c18_gravity_potential_completes_the_square() {
    let sys = systems::gravity_rotor();
    identity!(sys, "yp = y + g/omega^2");
    identity!(
        sys,
        "M*omega^2*(x^2 + y^2)/2 + M*g*y = M*omega^2*(x^2 + yp^2)/2 - M*g^2/(2*omega^2)"
    );
    identity!(
        sys,
        "H = (p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + yp^2)/2 - M*g^2/(2*omega^2) + F2"
    );
    // False neighbour: the constant with the wrong sign.
    identity!(
        sys, "M*omega^2*(x^2 + y^2)/2 + M*g*y = M*omega^2*(x^2 + yp^2)/2 + M*g^2/(2*omega^2)"
        => refuted "-M*g^2/omega^2"
    );
}

#[test]
fn c19_gravity_breaks_angular_momentum() {
    let sys = systems::gravity_rotor();
    identity!(sys, "{F1, L} = M*g*x");
    identity!(sys, "{L, F1} = -M*g*x");
    identity!(sys, "{F1, L} = 0" => refuted "M*g*x");
    identity!(sys, "{F1, L} = -M*g*x" => refuted "2*M*g*x");
}

#[test]
fn c20_shifted_angular_momentum() {
    let sys = systems::gravity_rotor();
    identity!(sys, "Lp = L - g/omega^2*p_x");
    identity!(sys, "Lp = x*p_y - yp*p_x");
    identity!(sys, "{F1, Lp} = 0");
    identity!(sys, "{F1, F2} = 0");
    // False neighbour: the shift with the wrong sign doubles the torque.
    identity!(sys, "{F1, L + g/omega^2*p_x} = 0" => refuted "2*M*g*x");
}

#[test]
fn c21_shifted_g1_g2() {
    let sys = systems::gravity_rotor();
    identity!(sys, "G1p = G1 + M*g*x/2");
    identity!(sys, "G2p = G2 - M*g*y - M*g^2/(2*omega^2)");
    // Their y' forms.
    identity!(sys, "G1p = p_x*p_y/(2*M) + M*omega^2*x*yp/2");
    identity!(
        sys,
        "G2p = (p_x^2 - p_y^2)/(2*M) + M*omega^2*(x^2 - yp^2)/2"
    );
    identity!(sys, "{G1p, F1} = 0");
    identity!(sys, "{G2p, F1} = 0");
    // False neighbours: the unshifted G1, a shift with the wrong sign.
    identity!(sys, "{G1, F1} = 0" => refuted "-g*p_x/2");
    identity!(sys, "{G2 + M*g*y, F1} = 0" => refuted "2*g*p_y");
}

#[test]
fn c22_shifted_su2_brackets() {
    let sys = systems::gravity_rotor();
    identity!(sys, "{Lp, G1p} = -G2p");
    identity!(sys, "{Lp, G2p} = 4*G1p");
    identity!(sys, "{G1p, G2p} = -omega^2*Lp");
    // False neighbours: the unshifted G2 on the right, a wrong coefficient.
    identity!(sys, "{Lp, G1p} = -G2" => refuted "M*g*y + M*g^2/(2*omega^2)");
    identity!(sys, "{Lp, G2p} = 3*G1p" => refuted "G1p");
    let t = rendered_table(&sys, &["Lp", "G1p", "G2p"]);
    assert_eq!(t[0][1], "−G2'");
    assert_eq!(t[0][2], "4 G1'");
    assert_eq!(t[1][2], "−ω² L'");
}

#[test]
fn c23_shifted_casimir() {
    let sys = systems::gravity_rotor();
    identity!(
        sys,
        "4*G1p^2 + G2p^2 + omega^2*Lp^2 = (F1 - F2 + M*g^2/(2*omega^2))^2"
    );
    // False neighbour: the Casimir of section 3, without the shift of the energy.
    identity!(
        sys, "4*G1p^2 + G2p^2 + omega^2*Lp^2 = (F1 - F2)^2"
        => refuted "M*g^2/omega^2*(F1 - F2) + M^2*g^4/(4*omega^4)"
    );
}

#[test]
fn c24_shifted_resonant_integrals() {
    let mut sys = systems::gravity_rotor();
    identity!(sys, "Zp = p_x + i*p_y + i*M*omega*(x + i*yp)");
    identity!(sys, "{Zp, F1} = i*omega*Zp");
    identity!(sys, "{Zbarp, F1} = -i*omega*Zbarp");
    for m in 1..=4 {
        for n in 1..=4 {
            define_family(&mut sys, "Zp", m, n);
            let lambda = format!("({m}*omega - {n}*Omega)");
            identity!(sys, format!("{{K, F1}} = i*{lambda}*K"));
            let on = sys.resonance(m, n).unwrap();
            identity!(sys, "{P, F1} = 0", when on);
            identity!(sys, "{Q, F1} = 0", when on);
            identity!(sys, "{P, F1} = 0" => refuted format!("-{lambda}*Q"));
        }
    }
    let report = check_tower(&sys, "Zp", 4, &mut |_, _| {}).unwrap();
    assert_eq!((report.checked, report.failures), (16, vec![]));
    assert!(eigen_proof(&sys, "Zp").unwrap().holds());
    // The proof's conclusion names the shifted family K', not the harmonic rotor's K.
    let named = eigen_proof_of(&sys, "Zp", "K'").unwrap().conclusion;
    assert!(
        named.starts_with("{K'_{m,n}, H} = i(mω − nΩ) K'_{m,n} and {K̄'_{m,n}, H}"),
        "{named}"
    );
    assert!(named.contains("(K'_{m,n} = Z'^m e^{−inθ})"), "{named}");
    // False neighbours: the unshifted Z is no ladder under gravity, nor are its P, Q conserved.
    identity!(sys, "{Z, F1} = i*omega*Z" => refuted "-i*M*g");
    assert!(!eigen_proof(&sys, "Z").unwrap().holds());
    let wrong = check_tower(&sys, "Z", 2, &mut |_, _| {}).unwrap();
    assert_eq!(wrong.failures, vec![(1, 1), (1, 2), (2, 1), (2, 2)]);
    define_family(&mut sys, "Z", 1, 1);
    let on = sys.resonance(1, 1).unwrap();
    identity!(sys, "{P, F1} = 0", when on => refuted "-M*g*sin(theta)");
    identity!(sys, "{Q, F1} = 0", when on => refuted "-M*g*cos(theta)");
}

#[test]
fn c25_gravity_functional_independence() {
    let mut sys = systems::gravity_rotor();
    define_family(&mut sys, "Zp", 1, 1);
    assert_rank(&sys, &["F1", "F2", "G1p", "G2p", "P"], 5, UpperBound::Size);
    assert_rank(&sys, &["F1", "F2", "G1p", "G2p"], 4, UpperBound::Size);
    assert_rank(
        &sys,
        &["F1", "F2", "Lp", "G1p", "G2p", "P"],
        5,
        UpperBound::VanishingMinors { count: 1 },
    );
    // False neighbour: L' in place of P' gives only rank 4 (the Casimir of C23 relates them).
    assert_rank(
        &sys,
        &["F1", "F2", "Lp", "G1p", "G2p"],
        4,
        UpperBound::VanishingMinors { count: 2 },
    );
}

#[test]
fn section4_bracket_table_renders() {
    let sys = systems::gravity_rotor();
    pretty_assertions::assert_eq!(
        rendered_table(&sys, &["F1", "F2", "Lp", "G1p", "G2p"]),
        table(&[
            &["0", "0", "0", "0", "0"],
            &["0", "0", "0", "0", "0"],
            &["0", "0", "0", "−G2'", "4 G1'"],
            &["0", "0", "G2'", "0", "−ω² L'"],
            &["0", "0", "−4 G1'", "ω² L'", "0"],
        ])
    );
}
