//! Section 3: the harmonic rotor (claims C04–C17).

use std::sync::Arc;

use brackets::{systems, EngineError, System};
use trigpoly::{Expr, Vars};

use super::{Item, PaperOptions, Section, SectionBuilder};
use crate::report::ClaimKind;

/// The pairs `(m, n)` whose resonant integrals are checked one by one.
pub(crate) const RESONANCES: [(i64, i64); 4] = [(1, 1), (2, 1), (1, 2), (3, 2)];

/// `2ω − 3Ω`, `ω − Ω`: the frequency `mω − nΩ` as text.
pub(crate) fn frequency(m: i64, n: i64) -> String {
    let term = |k: i64, s: &str| {
        if k == 1 {
            s.to_string()
        } else {
            format!("{k}{s}")
        }
    };
    format!("{} − {}", term(m, "ω"), term(n, "Ω"))
}

/// The harmonic rotor with `P_{m,n}`, `Q_{m,n}`, `K_{m,n}`, `K̄_{m,n}` of [`RESONANCES`] (and
/// the nonresonant ones used for C14) defined, under the names `P21`, `Q21`, ... built from the
/// ladder `ladder`; `prime` marks the names (`P'_{2,1}`).
pub(crate) fn with_resonant(
    mut system: System,
    ladder: &str,
    prime: &str,
    pairs: &[(i64, i64)],
) -> Result<System, EngineError> {
    for &(m, n) in pairs {
        let r = system.resonant(ladder, m, n)?;
        let sub = format!("_{{{m},{n}}}");
        let tag = if prime.is_empty() { "" } else { "p" };
        system.define(&format!("P{m}{n}{tag}"), &format!("P{prime}{sub}"), r.p)?;
        system.define(&format!("Q{m}{n}{tag}"), &format!("Q{prime}{sub}"), r.q)?;
        system.define(&format!("K{m}{n}{tag}"), &format!("K{prime}{sub}"), r.k)?;
        system.define(
            &format!("Kbar{m}{n}{tag}"),
            &format!("K̄{prime}{sub}"),
            r.kbar,
        )?;
    }
    Ok(system)
}

/// Section 3, subsection by subsection: the rod and its equations of motion (C04–C06), the
/// constants of motion and su(2) (C07–C10), the ladder functions and resonant integrals
/// (C11–C16), and functional independence (C17).
pub(crate) fn section(options: &PaperOptions) -> Result<Section, EngineError> {
    let mut pairs = RESONANCES.to_vec();
    pairs.push((2, 3));
    let rotor = with_resonant(systems::harmonic_rotor(), "Z", "", &pairs)?;
    let mut s = SectionBuilder::new(
        3,
        "The harmonic potential: degrees of freedom and resonance",
        rotor,
    );
    s.text(
        "The isotropic oscillator `V = Mω²(x² + y²)/2` acting on the rotor's centre of mass: \
         three degrees of freedom, two translational and one rotational.",
    );
    s.hamilton();
    equations_of_motion(&mut s)?;
    constants_of_motion(&mut s)?;
    resonant_integrals(&mut s, options)?;
    functional_independence(&mut s)?;
    Ok(s.finish())
}

/// C04–C06: the rod's moment of inertia in `H`, the equations of motion as brackets with
/// `H`, and the closed-form solution.
fn equations_of_motion(s: &mut SectionBuilder) -> Result<(), EngineError> {
    s.heading("The rod and the equations of motion");
    let rod = systems::harmonic_rod();
    let lhs = rod.hamiltonian().clone();
    let rhs = rod.parse("(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + 6*p_theta^2/(M*L^2)")?;
    s.claim(
        "C04",
        "p_θ²/(2I) = 6 p_θ²/(ML²) in H for a rod, I = ML²/12",
        lhs,
        rhs,
        None,
        ClaimKind::Identity,
    );
    // q̈ = {q̇, H} with q̇ = ∂H/∂p_q (the angle θ itself is not a function on phase space).
    for (p, statement, rhs) in [
        ("p_x", "ẍ + ω²x = 0", "omega^2*x"),
        ("p_y", "ÿ + ω²y = 0", "omega^2*y"),
        ("p_theta", "θ̈ = 0", "0"),
    ] {
        let sys = s.system().clone();
        let velocity = sys.hamiltonian().derivative(sys.var(p))?;
        let lhs = sys.flow(&velocity)?.checked_add(&s.parse(rhs)?)?;
        s.claim(
            "C05",
            statement,
            lhs,
            Expr::zero(sys.vars()),
            None,
            ClaimKind::Identity,
        );
    }
    solution(s)
}

/// C07–C10: the constants of motion, their brackets, the su(2) table and its Casimir.
fn constants_of_motion(s: &mut SectionBuilder) -> Result<(), EngineError> {
    s.heading("Constants of motion");
    s.show(
        "",
        &[
            ("F1", "F1"),
            ("F2", "F2"),
            ("L", "L"),
            ("G1", "G1"),
            ("G2", "G2"),
        ],
    )?;
    for f in ["F1", "F2", "L", "G1", "G2"] {
        s.identity(
            "C07",
            &format!("{{{f}, H}} = 0"),
            &format!("{{{f}, H}}"),
            "0",
        )?;
    }
    for (a, b) in [("F1", "F2"), ("F1", "L"), ("F2", "L")] {
        s.identity(
            "C08",
            &format!("{{{a}, {b}}} = 0"),
            &format!("{{{a}, {b}}}"),
            "0",
        )?;
    }
    s.table("the harmonic rotor", &["F1", "F2", "L", "G1", "G2"]);
    su2(s, "")?;
    s.identity(
        "C10",
        "4 G1² + G2² + ω² L² = (F1 − F2)²",
        "4*G1^2 + G2^2 + omega^2*L^2",
        "(F1 - F2)^2",
    )?;
    Ok(())
}

/// C11–C16: the ladder functions, the tower `{K_{m,n}, F1}` by expansion up to the options'
/// size and for all `m, n` by a proof, `P_{m,n}` and `Q_{m,n}`, and their conservation on
/// the resonance.
fn resonant_integrals(s: &mut SectionBuilder, options: &PaperOptions) -> Result<(), EngineError> {
    s.heading("Ladder functions and resonant integrals");
    s.show("", &[("Z", "Z"), ("Z̄", "Zbar"), ("Ω", "Omega")])?;
    s.identity("C11", "{Z, F1} = iω Z", "{Z, F1}", "i*omega*Z")?;
    s.identity("C13", "{Z̄, F1} = −iω Z̄", "{Zbar, F1}", "-i*omega*Zbar")?;
    s.text(
        "`K_{m,n} = Z^m e^{−inθ}`, `K̄_{m,n} = Z̄^m e^{inθ}`: \
         `{K_{m,n}, F1} = i(mω − nΩ) K_{m,n}` by expansion, and for all `m, n` by a proof.",
    );
    let sys = s.system().clone();
    s.item(Item::Tower {
        id: "C12".into(),
        statement: format!(
            "{{K_{{m,n}}, F1}} = i(mω − nΩ) K_{{m,n}} for 1 ≤ m, n ≤ {}",
            options.tower_max
        ),
        system: sys.clone(),
        ladder: "Z".into(),
        family: "K".into(),
        max: options.tower_max,
    });
    s.item(Item::Proof {
        title: "for all m, n ≥ 0, from the ladder function Z".into(),
        settles: vec![
            (
                "C12".into(),
                "{K_{m,n}, F1} = i(mω − nΩ) K_{m,n} for all m, n ≥ 0".into(),
            ),
            (
                "C14".into(),
                "{K̄_{m,n}, F1} = −i(mω − nΩ) K̄_{m,n} for all m, n ≥ 0".into(),
            ),
        ],
        system: sys,
        ladder: "Z".into(),
        family: "K".into(),
    });
    for (m, n) in [(1, 1), (2, 3), (3, 2)] {
        s.identity(
            "C14",
            &format!(
                "{{K̄_{{{m},{n}}}, F1}} = −i({}) K̄_{{{m},{n}}}",
                frequency(m, n)
            ),
            &format!("{{Kbar{m}{n}, F1}}"),
            &format!("-i*({m}*omega - {n}*Omega)*Kbar{m}{n}"),
        )?;
    }

    s.text("`P_{m,n} = (K_{m,n} + K̄_{m,n})/2` and `Q_{m,n} = (K_{m,n} − K̄_{m,n})/(2i)`:");
    s.show("", &[("P_{1,1}", "P11"), ("Q_{1,1}", "Q11")])?;
    s.identity(
        "C15",
        "P_{1,1} = (p_x − Mωy) cos θ + (p_y + Mωx) sin θ",
        "P11",
        "(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)",
    )?;
    s.identity(
        "C15",
        "Q_{1,1} = (p_y + Mωx) cos θ + (−p_x + Mωy) sin θ",
        "Q11",
        "(p_y + M*omega*x)*cos(theta) + (-p_x + M*omega*y)*sin(theta)",
    )?;
    real_parts(s, "", "")?;
    resonance(s, "C16", "", "")
}

/// C17: five functionally independent integrals, and no more among them.
fn functional_independence(s: &mut SectionBuilder) -> Result<(), EngineError> {
    s.heading("Functional independence");
    s.rank(
        "C17",
        &[
            ("F1", "F1"),
            ("F2", "F2"),
            ("G1", "G1"),
            ("G2", "G2"),
            ("P_{1,1}", "P11"),
        ],
        5,
    )?;
    s.rank(
        "C17",
        &[("F1", "F1"), ("F2", "F2"), ("G1", "G1"), ("G2", "G2")],
        4,
    )?;
    s.rank(
        "C17",
        &[
            ("F1", "F1"),
            ("F2", "F2"),
            ("G1", "G1"),
            ("G2", "G2"),
            ("P_{1,1}", "P11"),
            ("L", "L"),
        ],
        5,
    )?;
    s.text(
        "Five functionally independent integrals for three degrees of freedom: the harmonic \
         rotor is maximally superintegrable on the resonance `Ω/ω = m/n`.",
    );
    Ok(())
}

/// C06: the closed-form solution, with `φ = ωt` as an angle and `t` a parameter.
fn solution(s: &mut SectionBuilder) -> Result<(), EngineError> {
    let vars = Vars::builder()
        .angle("phi")
        .parameter("x_0")
        .parameter("y_0")
        .parameter("p_x_0")
        .parameter("p_y_0")
        .parameter("theta_0")
        .parameter("p_theta")
        .parameter("t")
        .parameter("M")
        .parameter("omega")
        .parameter("I")
        .build()
        .map_err(EngineError::from)?;
    let parse = |src: &str| Expr::parse(&vars, src).map_err(|e| EngineError::parse(src, e));
    let phi = vars.lookup("phi").expect("declared");
    let t = vars.lookup("t").expect("declared");
    let omega2 = parse("omega^2")?;
    s.text("The solution, with `φ = ωt` treated as an angle (`d/dt = ω ∂/∂φ`):");
    let mut shown = Vec::new();
    let mut claims = Vec::new();
    for (q, statement) in [
        (
            "x",
            "x(t) = x₀ cos ωt + p_{x,0}/(Mω) sin ωt solves ẍ + ω²x = 0",
        ),
        (
            "y",
            "y(t) = y₀ cos ωt + p_{y,0}/(Mω) sin ωt solves ÿ + ω²y = 0",
        ),
    ] {
        let sol = parse(&format!("{q}_0*cos(phi) + p_{q}_0/(M*omega)*sin(phi)"))?;
        // ẍ + ω²x = ω²(∂²x/∂φ² + x)
        let second = sol.derivative(phi)?.derivative(phi)?;
        let lhs = omega2.checked_mul(&second.checked_add(&sol)?)?;
        shown.push((format!("{q}(t)"), sol));
        claims.push((statement, lhs));
    }
    let theta = parse("theta_0 + p_theta*t/I")?;
    shown.push(("θ(t)".into(), theta.clone()));
    claims.push((
        "θ(t) = θ₀ + p_θt/I solves θ̈ = 0",
        theta.derivative(t)?.derivative(t)?,
    ));
    s.show_exprs("", shown);
    for (statement, lhs) in claims {
        let zero = Expr::zero(&vars);
        s.claim("C06", statement, lhs, zero, None, ClaimKind::Identity);
    }
    Ok(())
}

/// The su(2) brackets C09 (or C22 with primes).
pub(crate) fn su2(s: &mut SectionBuilder, prime: &str) -> Result<(), EngineError> {
    let (id, p, tag) = if prime.is_empty() {
        ("C09", "", "")
    } else {
        ("C22", "'", "p")
    };
    for (a, b, rhs_text, rhs) in [
        ("L", "G1", "−G2", "-G2"),
        ("L", "G2", "4 G1", "4*G1"),
        ("G1", "G2", "−ω² L", "-omega^2*L"),
    ] {
        let rhs_text = rhs_text.replace("G1", &format!("G1{p}"));
        let rhs_text = rhs_text.replace("G2", &format!("G2{p}"));
        let rhs_text = rhs_text.replace('L', &format!("L{p}"));
        let rhs = rhs
            .replace("G1", &format!("G1{tag}"))
            .replace("G2", &format!("G2{tag}"))
            .replace('L', &format!("L{tag}"));
        s.identity(
            id,
            &format!("{{{a}{p}, {b}{p}}} = {rhs_text}"),
            &format!("{{{a}{tag}, {b}{tag}}}"),
            &rhs,
        )?;
    }
    Ok(())
}

/// C15: `P_{m,n}` and `Q_{m,n}` are real.
pub(crate) fn real_parts(
    s: &mut SectionBuilder,
    prime: &str,
    tag: &str,
) -> Result<(), EngineError> {
    for (m, n) in RESONANCES {
        for f in ["P", "Q"] {
            let e = s.parse(&format!("{f}{m}{n}{tag}"))?;
            let conj = e.conj();
            s.claim(
                "C15",
                &format!("{f}{prime}_{{{m},{n}}} is real"),
                conj,
                e,
                None,
                ClaimKind::Identity,
            );
        }
    }
    Ok(())
}

/// C16 (or C24 with primes): `{P_{m,n}, F1} = {Q_{m,n}, F1} = 0` exactly on the resonance.
pub(crate) fn resonance(
    s: &mut SectionBuilder,
    id: &str,
    prime: &str,
    tag: &str,
) -> Result<(), EngineError> {
    let sys: Arc<System> = s.system().clone();
    for (m, n) in RESONANCES {
        let sub = format!("{prime}_{{{m},{n}}}");
        let at = sys.resonance(m, n)?;
        for f in ["P", "Q"] {
            s.identity_when(
                id,
                &format!("{{{f}{sub}, F1}} = 0"),
                &format!("{{{f}{m}{n}{tag}, F1}}"),
                "0",
                at.clone(),
            )?;
        }
        if prime.is_empty() {
            s.identity(
                id,
                &format!("{{P{sub}, F1}} = −({})Q{sub}", frequency(m, n)),
                &format!("{{P{m}{n}{tag}, F1}}"),
                &format!("-({m}*omega - {n}*Omega)*Q{m}{n}{tag}"),
            )?;
            let off = sys.resonance(m + 1, n)?;
            let lhs = s.parse(&format!("{{P{m}{n}{tag}, F1}}"))?;
            s.claim(
                id,
                &format!("{{P{sub}, F1}} ≠ 0"),
                lhs,
                Expr::zero(sys.vars()),
                Some(off),
                ClaimKind::Nonvanishing,
            );
        }
    }
    Ok(())
}
