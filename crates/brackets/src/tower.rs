//! The tower of resonant integrals: `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` checked by full
//! expansion for bounded `m, n`, and for all `m, n` by the eigenfunction lemma with its base
//! facts computed by the engine.

use std::time::Instant;

use trigpoly::{Expr, Rational};

use crate::error::EngineError;
use crate::system::System;

/// The outcome of the bounded check.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct TowerReport {
    /// The bound `N`: every `1 ≤ m, n ≤ N` was checked.
    pub max: i64,
    /// How many pairs were checked.
    pub checked: usize,
    /// Pairs where the identity failed (empty when it holds).
    pub failures: Vec<(i64, i64)>,
    /// Seconds spent (reported, never used to decide).
    pub seconds: f64,
}

/// Checks `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` with `Ω = p_θ/I` by expanding every bracket, for
/// all `1 ≤ m, n ≤ max`; `progress(done, total)` is called after each pair. The system must be a
/// rotor in the paper's names (`omega`, `I`, `theta`, `p_theta`); a system file's family takes
/// any names (`superint tower --system FILE`), and so does a family added in code to a system
/// of any names (`superint::system_file::LoadedSystem::add_family`, then
/// `superint::system_file::family_tower_report`, which also proves it for all `m, n`).
///
/// ```
/// use brackets::{check_tower, systems};
///
/// let rotor = systems::harmonic_rotor();
/// let tower = check_tower(&rotor, "Z", 3, &mut |_done, _total| {})?;
/// assert_eq!((tower.checked, tower.failures.len()), (9, 0));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn check_tower(
    system: &System,
    ladder: &str,
    max: i64,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<TowerReport, EngineError> {
    system.space().refuse_denominators("a tower")?;
    system.space().refuse_radicals("a tower")?;
    let start = Instant::now();
    system.require_rotor("the tower {K_{m,n}, H} = i(mω − nΩ) K_{m,n}")?;
    let omega = system.parse("omega")?;
    let big_omega = system.parse("p_theta/I")?;
    // `max²` pairs, none below 1, saturated: `max * max` overflowed (a panic in a debug
    // build, before the first bracket could report an unknown ladder) past 3·10⁹.
    let side = usize::try_from(max.max(0)).unwrap_or(usize::MAX);
    let total = side.saturating_mul(side);
    let mut failures = Vec::new();
    let mut done = 0;
    for m in 1..=max {
        for n in 1..=max {
            let k = system.resonant(ladder, m, n)?.k;
            let lambda = omega
                .scale_rational(&Rational::from(m))
                .checked_sub(&big_omega.scale_rational(&Rational::from(n)))?
                .mul_i()?;
            let lhs = system.flow(&k)?;
            if !lhs.checked_sub(&lambda.checked_mul(&k)?)?.is_zero() {
                failures.push((m, n));
            }
            done += 1;
            progress(done, total);
        }
    }
    Ok(TowerReport {
        max,
        checked: done,
        failures,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// A fact `{A, H} = λ A` computed by the engine.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct EigenFact {
    /// How the fact reads (`{Z, H} = iωZ`).
    pub statement: String,
    /// Whether the engine found it to hold exactly.
    pub holds: bool,
}

/// A proof for all `m, n` by the eigenfunction lemma.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct EigenProof {
    /// The base facts, computed.
    pub facts: Vec<EigenFact>,
    /// The lemma applied.
    pub lemma: String,
    /// A check of the derivation property the lemma rests on, on the base functions.
    pub leibniz_check: bool,
    /// The conclusion: the tower for all `m, n` when every step holds, else that nothing
    /// follows, and why.
    pub conclusion: String,
}

impl EigenProof {
    /// Whether every step holds.
    pub fn holds(&self) -> bool {
        self.facts.iter().all(|f| f.holds) && self.leibniz_check
    }
}

/// Proves `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` and `{K̄_{m,n}, H} = −i(mω − nΩ) K̄_{m,n}` for all
/// `m, n ≥ 0` from `{Z, H} = iωZ`, `{e^{−iθ}, H} = −iΩe^{−iθ}` and their conjugates, in a rotor
/// with the paper's names (`omega`, `I`, `theta`, `p_theta`). For a family in other names, and
/// any eigenvalue linear in `m, n`, `superint::system_file::family_tower_report` gives the same
/// proof.
///
/// ```
/// use brackets::{eigen_proof, systems};
///
/// let proof = eigen_proof(&systems::harmonic_rotor(), "Z")?;
/// assert!(proof.holds());
/// assert_eq!(proof.facts[0].statement, "{Z, H} = iω Z");
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn eigen_proof(system: &System, ladder: &str) -> Result<EigenProof, EngineError> {
    eigen_proof_of(system, ladder, "K")
}

/// [`eigen_proof`] of a family named `family` (its display name, `K'` for the rotor under
/// gravity, whose `K'_{m,n} = Z'^m e^{−inθ}`), as its conclusion names it and its conjugate
/// (`K̄'_{m,n}`).
///
/// ```
/// use brackets::{eigen_proof_of, systems};
///
/// let proof = eigen_proof_of(&systems::gravity_rotor(), "Zp", "K'")?;
/// assert!(proof.holds());
/// assert!(proof.conclusion.starts_with("{K'_{m,n}, H} = i(mω − nΩ) K'_{m,n} and {K̄'_{m,n}, H}"));
/// assert!(proof.conclusion.contains("(K'_{m,n} = Z'^m e^{−inθ})"));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn eigen_proof_of(
    system: &System,
    ladder: &str,
    family: &str,
) -> Result<EigenProof, EngineError> {
    system
        .space()
        .refuse_denominators("the all-m, n tower proof")?;
    system.space().refuse_radicals("the all-m, n tower proof")?;
    system.require_rotor("the eigenfunction proof of the tower")?;
    let vars = system.vars();
    let theta = vars
        .angles()
        .next()
        .ok_or_else(|| EngineError::Invalid("no angle".into()))?;
    let z = system.get(ladder)?.clone();
    let zbar = z.conj();
    let e = Expr::exp_i(vars, theta, -1)?;
    let ebar = e.conj();
    let i_omega = system.parse("i*omega")?;
    let i_big_omega = system.parse("i*p_theta/I")?;
    let name = system.display_name(ladder).to_string();
    // The conjugate's own name if the system has one (`Z̄`), else `conj Z`.
    let bar = system
        .functions()
        .iter()
        .find(|f| f.expr == zbar)
        .map_or_else(|| format!("conj {name}"), |f| f.display.clone());
    let fact = |f: &Expr, lambda: &Expr, statement: String| -> Result<EigenFact, EngineError> {
        let holds = system
            .flow(f)?
            .checked_sub(&lambda.checked_mul(f)?)?
            .is_zero();
        Ok(EigenFact { statement, holds })
    };
    let facts = vec![
        fact(&z, &i_omega, format!("{{{name}, H}} = iω {name}"))?,
        fact(
            &e,
            &-&i_big_omega,
            "{e^{−iθ}, H} = −iΩ e^{−iθ}  (Ω = p_θ/I)".into(),
        )?,
        fact(&zbar, &-&i_omega, format!("{{{bar}, H}} = −iω {bar}"))?,
        fact(&ebar, &i_big_omega, "{e^{iθ}, H} = iΩ e^{iθ}".into())?,
    ];
    // The derivation property on the base functions: {AB, H} = A{B, H} + B{A, H}.
    let h = system.hamiltonian();
    let ab = z.checked_mul(&e)?;
    let lhs = system.bracket(&ab, h)?;
    let rhs = z
        .checked_mul(&system.bracket(&e, h)?)?
        .checked_add(&e.checked_mul(&system.bracket(&z, h)?)?)?;
    let leibniz_check = lhs == rhs;
    let failed: Vec<&str> = facts
        .iter()
        .filter(|f| !f.holds)
        .map(|f| f.statement.as_str())
        .chain((!leibniz_check).then_some("the derivation property"))
        .collect();
    // The conjugate family's name: a macron over the name's first letter (`K̄'`).
    let mut letters = family.chars();
    let family_bar: String = letters
        .next()
        .map(|first| format!("{first}\u{304}{}", letters.as_str()))
        .unwrap_or_default();
    let (k, kbar) = (format!("{family}_{{m,n}}"), format!("{family_bar}_{{m,n}}"));
    let conclusion = match failed.is_empty() {
        true => format!(
            "{{{k}, H}} = i(mω − nΩ) {k} and {{{kbar}, H}} = −i(mω − nΩ) {kbar} \
             for all m, n ≥ 0 ({k} = {name}^m e^{{−inθ}}): conserved exactly when Ω/ω = m/n"
        ),
        false => format!(
            "nothing for all m, n: the lemma needs what fails here ({}), so {k} = \
             {name}^m e^{{−inθ}} is not proved conserved",
            failed.join("; ")
        ),
    };
    Ok(EigenProof {
        facts,
        lemma: "the bracket is a derivation in each argument, so {A, H} = λ_A A and \
                {B, H} = λ_B B give {A^m B^n, H} = (mλ_A + nλ_B) A^m B^n for all m, n ≥ 0"
            .into(),
        leibniz_check,
        conclusion,
    })
}
