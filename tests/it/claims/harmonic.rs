//! Section 3: the harmonic rotor `H = (p_x² + p_y²)/(2M) + Mω²(x² + y²)/2 + p_θ²/(2I)`.

use brackets::{check_tower, eigen_proof, systems, Condition, PhaseSpace, System, UpperBound};
use trigpoly::{Expr, Vars};

use super::{assert_rank, certified_rank, define_family, rendered_table, table};

#[test]
fn c04_rod_moment_of_inertia() {
    let rod = systems::harmonic_rod();
    // I = ML²/12, written as the rod system writes it.
    identity!(rod, "p_theta^2/(2*(M*L^2/12)) = 6*p_theta^2/(M*L^2)");
    identity!(
        rod,
        "H = (p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + 6*p_theta^2/(M*L^2)"
    );
    // False neighbour: a factor 3 (I = ML²/6).
    identity!(
        rod,
        "H = (p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + 3*p_theta^2/(M*L^2)"
        => refuted "3*p_theta^2/(M*L^2)"
    );
}

#[test]
fn c05_equations_of_motion() {
    let mut sys = systems::harmonic_rotor();
    identity!(sys, "{{x, H}, H} = -omega^2*x");
    identity!(sys, "{{y, H}, H} = -omega^2*y");
    identity!(sys, "{{p_x, H}, H} = -omega^2*p_x");
    // θ̇ = ∂H/∂p_θ from Hamilton's equations (θ is not a ring element), and θ̈ = {θ̇, H} = 0.
    let field = sys.space().hamilton_equations(sys.hamiltonian()).unwrap();
    let theta = sys.var("theta");
    let thetadot = field.into_iter().find(|(v, _)| *v == theta).unwrap().1;
    sys.define("thetadot", "θ̇", thetadot).unwrap();
    identity!(sys, "thetadot = Omega");
    identity!(sys, "{thetadot, H} = 0");
    // False neighbours: the wrong sign (an inverted oscillator), a wrong frequency.
    identity!(sys, "{{x, H}, H} = omega^2*x" => refuted "-2*omega^2*x");
    identity!(sys, "{{y, H}, H} = -4*omega^2*y" => refuted "3*omega^2*y");
}

/// The harmonic rotor with a second angle `φ = ωt`, the time `t` and the initial data as
/// parameters: `x(t) = x₀ cos φ + p_{x,0}/(Mω) sin φ`, `θ(t) = θ₀ + p_θ t/I`, and the time
/// derivative `d/dt = ω ∂/∂φ + ∂/∂t` of such functions.
struct Trajectory {
    sys: System,
    phi: trigpoly::Var,
    t: trigpoly::Var,
}

impl Trajectory {
    fn new() -> Self {
        let vars: Vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .angle("theta")
            .momentum("p_x")
            .momentum("p_y")
            .momentum("p_theta")
            .angle("phi")
            .parameter("M")
            .parameter("omega")
            .parameter("I")
            .parameter("t")
            .parameter("x0")
            .parameter("y0")
            .parameter("px0")
            .parameter("py0")
            .parameter("theta0")
            .build()
            .unwrap();
        let space =
            PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y"), ("theta", "p_theta")]).unwrap();
        let h = "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*I)";
        let h = Expr::parse(&vars, h).unwrap();
        let sys = System::new("harmonic rotor in time", space, h).unwrap();
        let (phi, t) = (sys.var("phi"), sys.var("t"));
        Trajectory { sys, phi, t }
    }

    /// d/dt = ω ∂/∂φ + ∂/∂t.
    fn dt(&self, f: &Expr) -> Expr {
        let omega = self.sys.parse("omega").unwrap();
        &omega * &f.derivative(self.phi).unwrap() + f.derivative(self.t).unwrap()
    }

    /// Defines `name = src` and its first and second time derivatives `name_dot`, `name_ddot`.
    fn define(&mut self, name: &str, src: &str) {
        let f = self.sys.parse(src).unwrap();
        let fdot = self.dt(&f);
        let fddot = self.dt(&fdot);
        self.sys.define(name, name, f).unwrap();
        self.sys
            .define(&format!("{name}_dot"), &format!("d/dt {name}"), fdot)
            .unwrap();
        self.sys
            .define(&format!("{name}_ddot"), &format!("d²/dt² {name}"), fddot)
            .unwrap();
    }

    /// The condition `t = 0`, i.e. `φ = 0` (`e^{iφ} = 1`) and `t = 0`.
    fn at_start(&self) -> Condition {
        let vars = self.sys.vars();
        let subs = vec![(self.phi, Expr::one(vars)), (self.t, Expr::zero(vars))];
        Condition::all("t = 0", subs).expect("values free of φ and t")
    }
}

#[test]
fn c06_closed_form_solution() {
    let mut tr = Trajectory::new();
    tr.define("x_t", "x0*cos(phi) + px0/(M*omega)*sin(phi)");
    tr.define("y_t", "y0*cos(phi) + py0/(M*omega)*sin(phi)");
    tr.define("theta_t", "theta0 + p_theta*t/I");
    let start = tr.at_start();
    let sys = &tr.sys;
    // ẍ + ω²x = 0, ÿ + ω²y = 0, θ̈ = 0.
    identity!(sys, "x_t_ddot + omega^2*x_t = 0");
    identity!(sys, "y_t_ddot + omega^2*y_t = 0");
    identity!(sys, "theta_t_ddot = 0");
    // The initial data.
    identity!(sys, "x_t = x0", when start);
    identity!(sys, "x_t_dot = px0/M", when start);
    identity!(sys, "y_t = y0", when start);
    identity!(sys, "y_t_dot = py0/M", when start);
    identity!(sys, "theta_t = theta0", when start);
    // Hamilton's equations of H along (x(t), y(t), p_x(t) = M ẋ, p_y(t) = M ẏ):
    // ẋ = ∂H/∂p_x, ṗ_x = −∂H/∂x, ..., θ̇ = ∂H/∂p_θ.
    let mut sys = tr.sys.clone();
    let along = |name: &str| sys.parse(name).unwrap();
    let path = vec![
        (sys.var("x"), along("x_t")),
        (sys.var("y"), along("y_t")),
        (sys.var("p_x"), along("M*x_t_dot")),
        (sys.var("p_y"), along("M*y_t_dot")),
    ];
    let field = sys.space().hamilton_equations(sys.hamiltonian()).unwrap();
    for (v, rate) in field {
        let name = format!("{}_rate", sys.vars().variable(v).name());
        let rate = rate.subst_many(&path).unwrap();
        sys.define(&name, &name, rate).unwrap();
    }
    identity!(sys, "x_t_dot = x_rate");
    identity!(sys, "y_t_dot = y_rate");
    identity!(sys, "theta_t_dot = theta_rate");
    identity!(sys, "M*x_t_ddot = p_x_rate");
    identity!(sys, "M*y_t_ddot = p_y_rate");
    identity!(sys, "p_theta_rate = 0");
    identity!(sys, "p_x_rate = -M*omega^2*x_t");
    // False neighbours: a wrong frequency fails ẍ + ω²x = 0, a wrong amplitude fails ẋ(0).
    let mut tr = Trajectory::new();
    let start = tr.at_start();
    tr.define("x_t", "x0*cos(2*phi) + px0/(M*omega)*sin(phi)");
    identity!(tr.sys, "x_t_ddot + omega^2*x_t = 0" => refuted "-3*omega^2*x0*cos(2*phi)");
    tr.define("x_t", "x0*cos(phi) + px0/(2*M*omega)*sin(phi)");
    identity!(tr.sys, "x_t_ddot + omega^2*x_t = 0");
    identity!(tr.sys, "x_t_dot = px0/M", when start => refuted "-px0/(2*M)");
}

#[test]
fn c07_constants_of_motion() {
    let sys = systems::harmonic_rotor();
    identity!(sys, "F1 = H");
    identity!(sys, "F2 = p_theta^2/(2*I)");
    identity!(sys, "L = x*p_y - y*p_x");
    identity!(sys, "G1 = p_x*p_y/(2*M) + M*omega^2*x*y/2");
    identity!(sys, "G2 = (p_x^2 - p_y^2)/(2*M) + M*omega^2*(x^2 - y^2)/2");
    for f in ["F1", "F2", "L", "G1", "G2"] {
        identity!(sys, format!("{{{f}, H}} = 0"));
    }
    // False neighbour: G2 with the potential's sign flipped.
    identity!(
        sys, "{(p_x^2 - p_y^2)/(2*M) - M*omega^2*(x^2 - y^2)/2, H} = 0"
        => refuted "-2*omega^2*(x*p_x - y*p_y)"
    );
}

#[test]
fn c08_involution() {
    let sys = systems::harmonic_rotor();
    identity!(sys, "{F1, F2} = 0");
    identity!(sys, "{F1, L} = 0");
    identity!(sys, "{F2, L} = 0");
    // False neighbour: half of L is not conserved.
    identity!(sys, "{x*p_y, F1} = 0" => refuted "p_x*p_y/M - M*omega^2*x*y");
}

#[test]
fn c09_su2_brackets() {
    let sys = systems::harmonic_rotor();
    identity!(sys, "{L, G1} = -G2");
    identity!(sys, "{L, G2} = 4*G1");
    identity!(sys, "{G1, G2} = -omega^2*L");
    // False neighbours: a flipped sign, a wrong coefficient.
    identity!(sys, "{L, G1} = G2" => refuted "-2*G2");
    identity!(sys, "{L, G2} = 3*G1" => refuted "G1");
    identity!(sys, "{G1, G2} = omega^2*L" => refuted "-2*omega^2*L");
    // The same through the bracket table, which finds the combinations by linear algebra.
    let t = rendered_table(&sys, &["L", "G1", "G2"]);
    assert_eq!(t[0][1], "−G2");
    assert_eq!(t[0][2], "4 G1");
    assert_eq!(t[1][2], "−ω² L");
    assert_ne!(t[0][2], "3 G1");
}

#[test]
fn c10_casimir() {
    let sys = systems::harmonic_rotor();
    identity!(sys, "4*G1^2 + G2^2 + omega^2*L^2 = (F1 - F2)^2");
    // False neighbour: 3 G1² instead of 4 G1².
    identity!(sys, "3*G1^2 + G2^2 + omega^2*L^2 = (F1 - F2)^2" => refuted "-G1^2");
}

#[test]
fn c11_ladder_z() {
    let sys = systems::harmonic_rotor();
    // Z = w + iMωu with w = p_x + i p_y, u = x + i y.
    identity!(sys, "Z = (p_x + i*p_y) + i*M*omega*(x + i*y)");
    identity!(sys, "{Z, F1} = i*omega*Z");
    identity!(sys, "{Z, F1} = -i*omega*Z" => refuted "2*i*omega*Z");
}

#[test]
fn c12_resonant_tower_k() {
    let mut sys = systems::harmonic_rotor();
    // By expansion for every 1 ≤ m, n ≤ 8.
    let report = check_tower(&sys, "Z", 8, &mut |_, _| {}).unwrap();
    assert_eq!(report.checked, 64);
    assert_eq!(report.failures, vec![]);
    // False neighbour: Z̄ is a ladder of the other sign, so Z̄^m e^{−inθ} fails every pair.
    let wrong = check_tower(&sys, "Zbar", 2, &mut |_, _| {}).unwrap();
    assert_eq!(wrong.failures, vec![(1, 1), (1, 2), (2, 1), (2, 2)]);
    for (m, n) in [(1, 1), (2, 3), (5, 2), (8, 8)] {
        define_family(&mut sys, "Z", m, n);
        identity!(sys, format!("{{K, F1}} = i*({m}*omega - {n}*Omega)*K"));
        // False neighbour: i(mω + nΩ).
        identity!(
            sys, format!("{{K, F1}} = i*({m}*omega + {n}*Omega)*K")
            => refuted format!("-2*i*{n}*Omega*K")
        );
    }
    // For all m, n: the eigenfunction lemma, with its base facts computed by the engine.
    let proof = eigen_proof(&sys, "Z").unwrap();
    assert!(proof.holds());
    assert!(proof.leibniz_check);
    assert_eq!(proof.facts.len(), 4);
    for fact in &proof.facts {
        assert!(fact.holds, "{}", fact.statement);
    }
    identity!(sys, "{Z, H} = i*omega*Z");
    identity!(sys, "{exp(-i*theta), H} = -i*Omega*exp(-i*theta)");
    identity!(sys, "{exp(-i*theta), H} = i*Omega*exp(-i*theta)"
        => refuted "-2*i*Omega*exp(-i*theta)");
}

#[test]
fn c13_ladder_zbar() {
    let sys = systems::harmonic_rotor();
    identity!(sys, "Zbar = p_x - i*p_y - i*M*omega*(x - i*y)");
    identity!(sys, "{Zbar, F1} = -i*omega*Zbar");
    identity!(sys, "{Zbar, F1} = i*omega*Zbar" => refuted "-2*i*omega*Zbar");
}

#[test]
fn c14_resonant_tower_kbar() {
    let mut sys = systems::harmonic_rotor();
    for m in 1..=8 {
        for n in 1..=8 {
            define_family(&mut sys, "Z", m, n);
            identity!(
                sys,
                format!("{{Kbar, F1}} = -i*({m}*omega - {n}*Omega)*Kbar")
            );
        }
    }
    // False neighbour: the eigenvalue of K instead of K̄.
    identity!(
        sys, "{Kbar, F1} = i*(8*omega - 8*Omega)*Kbar"
        => refuted "-2*i*(8*omega - 8*Omega)*Kbar"
    );
    // For all m, n: the conjugate facts of the eigenfunction proof.
    let proof = eigen_proof(&sys, "Z").unwrap();
    assert!(proof.holds());
    identity!(sys, "{Zbar, H} = -i*omega*Zbar");
    identity!(sys, "{exp(i*theta), H} = i*Omega*exp(i*theta)");
}

#[test]
fn c15_p_q_real() {
    let mut sys = systems::harmonic_rotor();
    for (m, n) in [(1, 1), (1, 2), (2, 1), (3, 2), (4, 3)] {
        define_family(&mut sys, "Z", m, n);
        let (p, q) = (sys.get("P").unwrap().clone(), sys.get("Q").unwrap().clone());
        assert!(p.is_real() && q.is_real(), "P, Q for m = {m}, n = {n}");
        assert_eq!(p.conj(), p);
        assert_eq!(q.conj(), q);
        assert!(!sys.get("K").unwrap().is_real(), "K is complex");
        sys.define("conjP", "conj P", p.conj()).unwrap();
        identity!(sys, "conjP = P");
        identity!(sys, "K = P + i*Q");
        // False neighbour: K is not real; K − K̄ = 2iQ.
        identity!(sys, "K = Kbar" => refuted "2*i*Q");
    }
    define_family(&mut sys, "Z", 1, 1);
    identity!(
        sys,
        "P = (p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)"
    );
    identity!(
        sys,
        "Q = (p_y + M*omega*x)*cos(theta) + (-p_x + M*omega*y)*sin(theta)"
    );
    identity!(
        sys, "P = (p_x - M*omega*y)*cos(theta) - (p_y + M*omega*x)*sin(theta)"
        => refuted "2*(p_y + M*omega*x)*sin(theta)"
    );
}

#[test]
fn c16_resonant_integrals_conserved_on_resonance() {
    let mut sys = systems::harmonic_rotor();
    for m in 1..=4 {
        for n in 1..=4 {
            define_family(&mut sys, "Z", m, n);
            let on = sys.resonance(m, n).unwrap();
            identity!(sys, "{P, F1} = 0", when on);
            identity!(sys, "{Q, F1} = 0", when on);
            // Off the resonance: {P, H} = −(mω − nΩ) Q, {Q, H} = (mω − nΩ) P.
            let lambda = format!("({m}*omega - {n}*Omega)");
            identity!(sys, "{P, F1} = 0" => refuted format!("-{lambda}*Q"));
            identity!(sys, "{Q, F1} = 0" => refuted format!("{lambda}*P"));
            // At the neighbouring resonance Ω = (m + 1)ω/n: mω − nΩ = −ω.
            let next = sys.resonance(m + 1, n).unwrap();
            identity!(sys, "{P, F1} = 0", when next => refuted "omega*Q");
            identity!(sys, "{Q, F1} = 0", when next => refuted "-omega*P");
            // The flow on a condition formed term by term (as the tower's workload forms it)
            // is the flow with the condition applied, on the resonance and off it.
            for name in ["P", "Q"] {
                let f = sys.get(name).unwrap().clone();
                assert!(sys.flow_when(&f, &on).unwrap().is_zero());
                let off = next.apply(&sys.flow(&f).unwrap()).unwrap();
                assert!(!off.is_zero());
                assert_eq!(sys.flow_when(&f, &next).unwrap(), off);
            }
        }
    }
}

#[test]
fn c17_functional_independence() {
    let mut sys = systems::harmonic_rotor();
    define_family(&mut sys, "Z", 1, 1);
    assert_rank(&sys, &["F1", "F2", "G1", "G2", "P"], 5, UpperBound::Size);
    assert_rank(&sys, &["F1", "F2", "G1", "G2"], 4, UpperBound::Size);
    assert_rank(
        &sys,
        &["F1", "F2", "L", "G1", "G2", "P"],
        5,
        UpperBound::VanishingMinors { count: 1 },
    );
    // False neighbours: six integrals would be one too many; L in place of P gives rank 4 (the
    // Casimir of C10 relates F1, F2, L, G1, G2); F1 + F2 adds nothing.
    assert_rank(
        &sys,
        &["F1", "F2", "L", "G1", "G2"],
        4,
        UpperBound::VanishingMinors { count: 2 },
    );
    let cert = certified_rank(&sys, &["F1", "F2", "L", "G1", "G2", "P"]);
    assert_ne!(cert.rank, 6);
    assert_rank(
        &sys,
        &["F1", "F2", "F1 + F2"],
        2,
        UpperBound::VanishingMinors { count: 4 },
    );
}

#[test]
fn section3_bracket_table_renders() {
    let sys = systems::harmonic_rotor();
    let names = ["F1", "F2", "L", "G1", "G2"];
    pretty_assertions::assert_eq!(
        rendered_table(&sys, &names),
        table(&[
            &["0", "0", "0", "0", "0"],
            &["0", "0", "0", "0", "0"],
            &["0", "0", "0", "−G2", "4 G1"],
            &["0", "0", "G2", "0", "−ω² L"],
            &["0", "0", "−4 G1", "ω² L", "0"],
        ])
    );
}

/// A bracket of two long functions (past the short kernel): of a function with itself it is
/// zero (the antisymmetry the engine reads off equal term lists), and of P_{8,8} with Q_{8,8},
/// whose terms have the same monomials and other coefficients, it is
/// `{P, Q} = −{K, K̄}/(2i) = −64 Z⁷Z̄⁷ {Z, Z̄}/(2i) = −128 Mω Z⁷Z̄⁷`, which a test of equal
/// lengths instead of equal term lists would give as zero.
#[test]
fn long_brackets_of_a_function_with_itself_and_with_its_partner() {
    let mut sys = systems::harmonic_rotor();
    define_family(&mut sys, "Z", 8, 8);
    assert_eq!(sys.get("P").unwrap().len(), sys.get("Q").unwrap().len());
    identity!(sys, "{P, P} = 0");
    identity!(sys, "{K, K} = 0");
    identity!(sys, "{P, Q} = -128*M*omega*Z^7*Zbar^7");
    identity!(sys, "{P, Q} = 0" => refuted "-128*M*omega*Z^7*Zbar^7");
}

/// The minors of fixed rows for every set of columns share their smaller minors (the rank's
/// upper bound computes them so): each is the rule of Sarrus, with a zero entry among them
/// (its column still turns the sign), and computing them in any order changes none.
#[test]
fn minors_of_fixed_rows_share_their_smaller_minors() {
    let sys = systems::harmonic_rotor();
    let entries = [
        ["x", "y", "p_x", "1"],
        ["x^2", "2", "0", "M"],
        ["omega", "x*y", "3", "p_y"],
    ];
    let jac: Vec<Vec<Expr>> = entries
        .iter()
        .map(|row| row.iter().map(|s| sys.parse(s).unwrap()).collect())
        .collect();
    let sarrus = |c: [usize; 3]| {
        let m = |i: usize, j: usize| format!("({})", entries[i][c[j]]);
        sys.parse(&format!(
            "{}*({}*{} - {}*{}) - {}*({}*{} - {}*{}) + {}*({}*{} - {}*{})",
            m(0, 0),
            m(1, 1),
            m(2, 2),
            m(1, 2),
            m(2, 1),
            m(0, 1),
            m(1, 0),
            m(2, 2),
            m(1, 2),
            m(2, 0),
            m(0, 2),
            m(1, 0),
            m(2, 1),
            m(1, 1),
            m(2, 0),
        ))
        .unwrap()
    };
    let sets = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
    for order in [[0, 1, 2, 3], [3, 1, 0, 2]] {
        let mut minors = brackets::rank::Minors::new(&jac, &[0, 1, 2]);
        for k in order {
            assert_eq!(
                minors.det(&sets[k]).unwrap(),
                sarrus(sets[k]),
                "{:?}",
                sets[k]
            );
        }
    }
}

/// The rank's symbolic minors: a minor whose rows agree on its columns is zero at once (the
/// same function given twice), and one whose rows agree elsewhere but not on its columns is
/// computed: a test of one column instead of all would call `x` zero. And the rank of a list
/// with a function given twice certifies its upper bound by such minors.
#[test]
fn symbolic_minors_with_equal_rows() {
    let sys = systems::harmonic_rotor();
    let e = |s: &str| sys.parse(s).unwrap();
    let jac = vec![vec![e("x"), e("1"), e("y")], vec![e("x"), e("2"), e("y")]];
    let det = |cols: &[usize]| brackets::rank::symbolic_det(&jac, &[0, 1], cols).unwrap();
    assert!(det(&[0, 2]).is_zero());
    assert_eq!(det(&[0, 1]), e("x"));
    assert_eq!(det(&[1, 2]), e("-y"));
    assert_rank(
        &sys,
        &["F1", "G1", "G1"],
        2,
        UpperBound::VanishingMinors { count: 4 },
    );
}
