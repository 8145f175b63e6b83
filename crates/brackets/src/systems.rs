//! The paper's systems as values: the rotor on a planar potential, the harmonic rotor (and the
//! rod `I = ML²/12`), the rotor under gravity, the anisotropic rotor; with their named functions
//! and the resonant families `K_{m,n} = Z^m e^{−inθ}`.

use trigpoly::{Expr, Limits, Vars};

use crate::error::EngineError;
use crate::phase::PhaseSpace;
use crate::system::System;

/// The variables of a rotor in the plane: `x, y, θ, p_x, p_y, p_θ` and the given parameters,
/// with the library's default limits.
pub fn rotor_vars(parameters: &[&str]) -> Vars {
    rotor_vars_with(parameters, Limits::default()).expect("the rotor's variables are well formed")
}

/// [`rotor_vars`] with `limits`.
fn rotor_vars_with(parameters: &[&str], limits: Limits) -> Result<Vars, EngineError> {
    let mut b = Vars::builder()
        .limits(limits)
        .coordinate("x")
        .coordinate("y")
        .angle("theta")
        .momentum("p_x")
        .momentum("p_y")
        .momentum("p_theta");
    for p in parameters {
        b = b.parameter(p);
    }
    Ok(b.build()?)
}

/// A system from source text, with `limits`: an error only when a function passes them (the
/// texts are fixed and well formed).
fn build(
    name: &str,
    params: &[&str],
    h: &str,
    functions: &[(&str, &str, &str)],
    limits: Limits,
) -> Result<System, EngineError> {
    let vars = rotor_vars_with(params, limits)?;
    let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y"), ("theta", "p_theta")])?;
    // A text that does not fit the limits is named, not placed by a line and column of a
    // text nobody typed.
    let h =
        Expr::parse(&vars, h).map_err(|e| EngineError::parse(h, e).in_part("its Hamiltonian"))?;
    let mut s = System::new(name, space, h)?;
    for (n, display, src) in functions {
        s.define_builtin(n, display, src)?;
    }
    Ok(s)
}

/// `H = (p_x² + p_y²)/(2M) + V(x, y) + p_θ²/(2I)` for a polynomial potential given as text in
/// `x, y` and the extra parameters.
pub fn rotor(potential: &str, extra_parameters: &[&str]) -> Result<System, EngineError> {
    let mut params = vec!["M", "I"];
    params.extend_from_slice(extra_parameters);
    let vars = rotor_vars(&params);
    let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y"), ("theta", "p_theta")])?;
    let v = Expr::parse(&vars, potential).map_err(|e| EngineError::parse(potential, e))?;
    let kinetic = Expr::parse(&vars, "(p_x^2 + p_y^2)/(2*M) + p_theta^2/(2*I)")
        .expect("kinetic energy parses");
    let mut s = System::new("rotor", space, &kinetic + &v)?;
    s.define("V", "V", v)?;
    Ok(s)
}

/// The paper's rotors, which the functions below build with the library's default limits, and
/// [`Rotor::system`] with any (the command line's `--max-terms`, say).
///
/// ```
/// use brackets::systems::Rotor;
/// use trigpoly::Limits;
///
/// let limits = |max_terms| Limits::default().max_terms(max_terms).max_degree(50);
/// let rotor = Rotor::Harmonic.system(limits(100)).unwrap();
/// assert_eq!(rotor.vars().limits().max_terms, 100);
/// // H has five terms: a limit of four refuses the system, with the reason.
/// let refused = Rotor::Harmonic.system(limits(4));
/// assert!(refused.unwrap_err().to_string().contains("limit"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rotor {
    /// [`harmonic_rotor`].
    Harmonic,
    /// [`harmonic_rod`].
    HarmonicRod,
    /// [`gravity_rotor`].
    Gravity,
    /// [`anisotropic_rotor`] with `ω_x : ω_y = a : b`.
    Anisotropic(u32, u32),
    /// [`planar_i_rotor`].
    PlanarI,
    /// [`planar_ii_rotor`].
    PlanarII,
}

impl Rotor {
    /// The system, its results held to `limits`; an error when its own functions pass them.
    pub fn system(self, limits: Limits) -> Result<System, EngineError> {
        match self {
            Rotor::Harmonic => build(
                "harmonic rotor",
                &["M", "omega", "I"],
                "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*I)",
                &HARMONIC_FUNCTIONS,
                limits,
            ),
            Rotor::HarmonicRod => build(
                "harmonic rod",
                &["M", "omega", "L"],
                "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*(M*L^2/12))",
                &[],
                limits,
            ),
            Rotor::Gravity => {
                let mut functions: Vec<(&str, &str, &str)> = HARMONIC_FUNCTIONS.to_vec();
                functions.extend_from_slice(&GRAVITY_FUNCTIONS);
                build(
                    "gravity rotor",
                    &["M", "omega", "I", "g"],
                    "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*I) + M*g*y",
                    &functions,
                    limits,
                )
            }
            Rotor::Anisotropic(a, b) => anisotropic(a, b, limits),
            Rotor::PlanarI => build(
                "planar limit V_I with rotor",
                &["M", "I", "alpha", "beta", "gamma"],
                "(p_x^2 + p_y^2)/(2*M) + alpha*(x^2 + y^2) + beta/x^2 + gamma/y^2 + p_theta^2/(2*I)",
                &PLANAR_I_FUNCTIONS,
                limits,
            ),
            Rotor::PlanarII => build(
                "planar limit V_II with rotor",
                &["M", "I", "alpha", "beta", "gamma"],
                "(p_x^2 + p_y^2)/(2*M) + alpha*(x^2 + 4*y^2) + beta/x^2 + gamma*y + p_theta^2/(2*I)",
                &PLANAR_II_FUNCTIONS,
                limits,
            ),
        }
    }
}

/// The harmonic rotor `H = (p_x² + p_y²)/(2M) + Mω²(x² + y²)/2 + p_θ²/(2I)` with `F1, F2, L,
/// G1, G2, Z, Z̄` and `Ω = p_θ/I`.
pub fn harmonic_rotor() -> System {
    Rotor::Harmonic
        .system(Limits::default())
        .expect("the default limits hold a built-in system")
}

/// The named functions of [`harmonic_rotor`] (and of [`gravity_rotor`], before its primed ones).
const HARMONIC_FUNCTIONS: [(&str, &str, &str); 8] = [
    ("F1", "F1", "H"),
    ("F2", "F2", "p_theta^2/(2*I)"),
    ("L", "L", "x*p_y - y*p_x"),
    ("G1", "G1", "p_x*p_y/(2*M) + M*omega^2*x*y/2"),
    (
        "G2",
        "G2",
        "(p_x^2 - p_y^2)/(2*M) + M*omega^2*(x^2 - y^2)/2",
    ),
    ("Z", "Z", "p_x + i*p_y + i*M*omega*(x + i*y)"),
    ("Zbar", "Z̄", "p_x - i*p_y - i*M*omega*(x - i*y)"),
    ("Omega", "Ω", "p_theta/I"),
];

/// The harmonic rod: the harmonic rotor with `I = ML²/12` (`L` the rod's length).
pub fn harmonic_rod() -> System {
    Rotor::HarmonicRod
        .system(Limits::default())
        .expect("the default limits hold a built-in system")
}

/// The harmonic rotor under gravity, `H_g = H + Mgy`, with the unprimed functions of the
/// harmonic rotor, `y' = y + g/ω²`, and the primed `L', G1', G2', Z', Z̄'`.
pub fn gravity_rotor() -> System {
    Rotor::Gravity
        .system(Limits::default())
        .expect("the default limits hold a built-in system")
}

/// The primed functions of the rotor under gravity, after the harmonic rotor's.
const GRAVITY_FUNCTIONS: [(&str, &str, &str); 6] = [
    ("yp", "y'", "y + g/omega^2"),
    ("Lp", "L'", "L - g/omega^2*p_x"),
    ("G1p", "G1'", "G1 + M*g*x/2"),
    ("G2p", "G2'", "G2 - M*g*y - M*g^2/(2*omega^2)"),
    ("Zp", "Z'", "p_x + i*p_y + i*M*omega*(x + i*yp)"),
    ("Zbarp", "Z̄'", "p_x - i*p_y - i*M*omega*(x - i*yp)"),
];

/// The anisotropic rotor `V = M(ω_x² x² + ω_y² y²)/2` with `ω_x = a·ω`, `ω_y = b·ω`, and its
/// ladder functions `A_x = p_x + iMω_x x`, `A_y = p_y + iMω_y y` (`{A, H} = iω_A A`), their
/// conjugates, `H_x`, `H_y`, `F2` and `Ω`.
pub fn anisotropic_rotor(a: u32, b: u32) -> System {
    Rotor::Anisotropic(a, b)
        .system(Limits::default())
        .expect("the default limits hold a built-in system")
}

/// [`anisotropic_rotor`] with `limits`.
fn anisotropic(a: u32, b: u32, limits: Limits) -> Result<System, EngineError> {
    let h =
        format!("(p_x^2 + p_y^2)/(2*M) + M*omega^2*({a}^2*x^2 + {b}^2*y^2)/2 + p_theta^2/(2*I)");
    let hx = format!("p_x^2/(2*M) + M*{a}^2*omega^2*x^2/2");
    let hy = format!("p_y^2/(2*M) + M*{b}^2*omega^2*y^2/2");
    let ax = format!("p_x + i*M*{a}*omega*x");
    let ay = format!("p_y + i*M*{b}*omega*y");
    let axbar = format!("p_x - i*M*{a}*omega*x");
    let aybar = format!("p_y - i*M*{b}*omega*y");
    build(
        &format!("anisotropic rotor {a}:{b}"),
        &["M", "omega", "I"],
        &h,
        &[
            ("Hx", "H_x", &hx),
            ("Hy", "H_y", &hy),
            ("F2", "F2", "p_theta^2/(2*I)"),
            ("Ax", "A_x", &ax),
            ("Ay", "A_y", &ay),
            ("Axbar", "Ā_x", &axbar),
            ("Aybar", "Ā_y", &aybar),
            ("Omega", "Ω", "p_theta/I"),
        ],
        limits,
    )
}

/// The resonant functions built from a ladder function `Z` (with `{Z, H} = iωZ`) and the angle:
/// `K = Z^m e^{−inθ}`, `K̄ = Z̄^m e^{inθ}`, `P = (K + K̄)/2`, `Q = (K − K̄)/(2i)`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Resonant {
    /// `K_{m,n}`.
    pub k: Expr,
    /// `K̄_{m,n}`.
    pub kbar: Expr,
    /// `P_{m,n}`, real.
    pub p: Expr,
    /// `Q_{m,n}`, real.
    pub q: Expr,
}

impl System {
    /// Refuses, for `what`, a system that is not a rotor in the paper's names: the parameters
    /// `omega` (the orbit's frequency ω) and `I` (the moment of inertia), and an angle `theta`
    /// with its momentum `p_theta` (the rotor's frequency is `Ω = p_θ/I`).
    pub(crate) fn require_rotor(&self, what: &str) -> Result<(), EngineError> {
        let vars = self.vars();
        let kind = |name: &str| vars.lookup(name).map(|v| vars.variable(v).kind());
        use trigpoly::VarKind::{Angle, Momentum, Parameter};
        let names = [
            ("omega", Parameter, "parameter"),
            ("I", Parameter, "parameter"),
            ("theta", Angle, "angle"),
            ("p_theta", Momentum, "momentum"),
        ];
        match names.iter().find(|(name, k, _)| kind(name) != Some(*k)) {
            None => Ok(()),
            Some((name, _, noun)) => Err(EngineError::Invalid(format!(
                "{what} is stated for a rotor in the paper's names: the parameters omega and \
                 I, and the angle theta with its momentum p_theta; this system has no {noun} \
                 {name} (a system file's tower takes any names: `superint tower --system FILE`)"
            ))),
        }
    }

    /// `K_{m,n}, K̄_{m,n}, P_{m,n}, Q_{m,n}` from the named ladder function `ladder` and the
    /// first angle (whatever its name).
    pub fn resonant(&self, ladder: &str, m: i64, n: i64) -> Result<Resonant, EngineError> {
        let z = self.get(ladder)?;
        let theta = self
            .vars()
            .angles()
            .next()
            .ok_or_else(|| EngineError::Invalid("the system has no angle".into()))?;
        // e^{−inθ} as the conjugate of e^{inθ}: `−n` overflows for n = i64::MIN, which the
        // order's limit refuses as it refuses any order past it.
        let k = z
            .checked_pow(m)?
            .checked_mul(&Expr::exp_i(self.vars(), theta, n)?.conj())?;
        // P = (K + K̄)/2, Q = (K − K̄)/(2i): both from one pass over K and K̄.
        let (kbar, p, q) = k.conj_re_im();
        Ok(Resonant { k, kbar, p, q })
    }

    /// The resonance `p_θ = mIω/n` as a condition, in a rotor with the paper's names
    /// (`omega`, `I`, `theta`, `p_theta`).
    pub fn resonance(&self, m: i64, n: i64) -> Result<crate::claim::Condition, EngineError> {
        if n == 0 {
            return Err(EngineError::Invalid("a resonance m : n needs n ≠ 0".into()));
        }
        self.require_rotor("a resonance p_θ = mIω/n")?;
        let var = |name: &str| {
            self.vars().lookup(name).ok_or_else(|| {
                EngineError::Invalid(format!("a resonance needs the variable {name}"))
            })
        };
        // Built as the term it is (a tower checks one resonance per pair; parsing its text
        // cost a few percent of W1).
        let value = Expr::monomial(
            self.vars(),
            trigpoly::GaussianRational::from(trigpoly::Rational::new(m, n)),
            &[(var("I")?, 1), (var("omega")?, 1)],
        )?;
        let text = format!("p_θ = {}", resonance_text(m, n));
        Ok(crate::claim::Condition::new(&text, var("p_theta")?, value))
    }
}

/// `mIω/n` in lowest terms, as text: `Iω`, `2Iω`, `Iω/2`, `3Iω/2`, `−Iω/2`, and `0` for
/// `m = 0` (`n ≠ 0`).
pub fn resonance_text(m: i64, n: i64) -> String {
    let q = trigpoly::Rational::new(m, n);
    if q.is_zero() {
        return "0".into();
    }
    let sign = if q.is_negative() { "−" } else { "" };
    let num = q.numer().abs();
    let den = q.denom();
    let head = if num.is_one() {
        format!("{sign}Iω")
    } else {
        format!("{sign}{num}Iω")
    };
    if den.is_one() {
        head
    } else {
        format!("{head}/{den}")
    }
}

/// The planar limit `V_I = α(x² + y²) + β/x² + γ/y²` (a Laurent potential) coupled to the
/// rotor, with the second-order integrals `H_x = p_x²/(2M) + αx² + β/x²`,
/// `H_y = p_y²/(2M) + αy² + γ/y²`, `X = L² + 2M(βy²/x² + γx²/y²)`, and `L`, `F2`.
pub fn planar_i_rotor() -> System {
    Rotor::PlanarI
        .system(Limits::default())
        .expect("the default limits hold a built-in system")
}

/// The named functions of [`planar_i_rotor`].
const PLANAR_I_FUNCTIONS: [(&str, &str, &str); 5] = [
    ("F2", "F2", "p_theta^2/(2*I)"),
    ("L", "L", "x*p_y - y*p_x"),
    ("Hx", "H_x", "p_x^2/(2*M) + alpha*x^2 + beta/x^2"),
    ("Hy", "H_y", "p_y^2/(2*M) + alpha*y^2 + gamma/y^2"),
    ("X", "X", "L^2 + 2*M*(beta*y^2/x^2 + gamma*x^2/y^2)"),
];

/// The planar limit `V_II = α(x² + 4y²) + β/x² + γy` (a Laurent potential) coupled to the
/// rotor, with the second-order integrals `H_x = p_x²/(2M) + αx² + β/x²`,
/// `H_y = p_y²/(2M) + 4αy² + γy`, `X = L p_x + M(2αx²y − 2βy/x² + γx²/2)`, and `L`, `F2`.
pub fn planar_ii_rotor() -> System {
    Rotor::PlanarII
        .system(Limits::default())
        .expect("the default limits hold a built-in system")
}

/// The named functions of [`planar_ii_rotor`].
const PLANAR_II_FUNCTIONS: [(&str, &str, &str); 5] = [
    ("F2", "F2", "p_theta^2/(2*I)"),
    ("L", "L", "x*p_y - y*p_x"),
    ("Hx", "H_x", "p_x^2/(2*M) + alpha*x^2 + beta/x^2"),
    ("Hy", "H_y", "p_y^2/(2*M) + 4*alpha*y^2 + gamma*y"),
    (
        "X",
        "X",
        "L*p_x + M*(2*alpha*x^2*y - 2*beta*y/x^2 + gamma*x^2/2)",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The resonance's text for each sign, zero and fraction (it read `0Iω` and `-1Iω/2`).
    #[test]
    fn resonance_text_reads_like_the_paper() {
        let texts: Vec<String> = [
            (1, 1),
            (2, 1),
            (1, 2),
            (3, 2),
            (4, 6),
            (0, 3),
            (-1, 2),
            (3, -2),
        ]
        .iter()
        .map(|&(m, n)| resonance_text(m, n))
        .collect();
        assert_eq!(
            texts,
            [
                "Iω",
                "2Iω",
                "Iω/2",
                "3Iω/2",
                "2Iω/3",
                "0",
                "−Iω/2",
                "−3Iω/2"
            ]
        );
    }

    /// The resonance is the substitution `p_θ ↦ mIω/n`, built as a term; without `n`, or in a
    /// system without `I`, it is an error, not a panic.
    #[test]
    fn resonance_substitutes_m_i_omega_over_n() {
        let rotor = harmonic_rotor();
        let at = rotor.resonance(3, 2).unwrap();
        let p = |s: &str| rotor.parse(s).unwrap();
        assert_eq!(
            at.apply(&p("p_theta^2 + x")).unwrap(),
            p("9*I^2*omega^2/4 + x")
        );
        assert_eq!(at.text, "p_θ = 3Iω/2");
        assert!(matches!(
            rotor.resonance(1, 0),
            Err(EngineError::Invalid(_))
        ));
        assert!(matches!(
            harmonic_rod().resonance(1, 1),
            Err(EngineError::Invalid(_))
        ));
    }

    /// The tower's functions are stated in the paper's names: a system without them is told
    /// which is missing (it was "unknown name 'omega'" with a caret under text the caller never
    /// wrote), and the built-in rotors have them all.
    #[test]
    fn the_tower_needs_a_rotor_in_the_papers_names() {
        let planar = planar_i_rotor();
        let err = crate::check_tower(&planar, "L", 1, &mut |_, _| {}).unwrap_err();
        assert!(
            err.to_string()
                .contains("this system has no parameter omega"),
            "{err}"
        );
        let err = crate::eigen_proof(&planar, "L").unwrap_err();
        assert!(err.to_string().contains("the eigenfunction proof"), "{err}");
        for rotor in [harmonic_rotor(), gravity_rotor()] {
            assert_eq!(rotor.require_rotor("the tower"), Ok(()));
        }
    }

    /// The eigenfunction proof from a function that is no ladder (`{L, H} = 0`, not `iωL`)
    /// fails, and its conclusion says that nothing follows (it stated the tower all the same).
    #[test]
    fn an_eigenfunction_proof_that_fails_concludes_nothing() {
        let rotor = harmonic_rotor();
        let proof = crate::eigen_proof(&rotor, "L").expect("the proof runs");
        assert!(!proof.holds());
        assert!(
            proof.conclusion.starts_with(
                "nothing for all m, n: the lemma needs what fails here ({L, H} = iω L; \
                 {L, H} = −iω L)"
            ),
            "{}",
            proof.conclusion
        );
        let proof = crate::eigen_proof(&rotor, "Z").expect("the proof runs");
        assert!(proof.holds());
        assert!(proof
            .conclusion
            .ends_with("conserved exactly when Ω/ω = m/n"));
    }
}
