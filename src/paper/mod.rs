//! The paper as data: its sections, each a list of [`Item`]s (prose, Hamiltonians, claims,
//! bracket tables, towers, proofs, ranks) built from the engine's systems, and
//! [`Paper::check`], which computes every item into a [`Report`].
//!
//! Building the catalogue only parses; checking does the mathematics; rendering
//! ([`crate::render`]) only prints. Every claim of `docs/claims.md` from C01 to C26 appears with its
//! id, its statement in the paper's notation and its condition.
//!
//! ```
//! use superint::paper::{Paper, PaperOptions};
//!
//! let paper = Paper::build(&PaperOptions::default().tower_max(2))?;
//! let report = paper.check()?;
//! assert!(report.all_proved());
//! assert!(report.claim_ids().iter().any(|(id, _)| id == "C09"));
//! # Ok::<(), brackets::EngineError>(())
//! ```

mod beyond;
mod gravity;
mod harmonic;
mod planar;

use crate::render::tex::Names;
use crate::system_file::Caller;
use std::sync::Arc;
use std::time::Instant;

use brackets::{
    check_tower, eigen_proof_of, rank, BracketTable, Claim, Condition, EngineError, System,
};
use trigpoly::Expr;

use crate::report::{
    ClaimKind, ClaimResult, Entry, Equation, Equations, Fact, ProofResult, RankResult, Report,
    Section as ReportSection, SummaryKind, TableResult, TowerResult,
};

/// The paper's title.
pub const TITLE: &str =
    "Rigid body rotors in planar potentials: the paper's claims, checked exactly";
/// The paper checked.
pub const SUBTITLE: &str = "D. Latini, Rigid Body Rotors in Planar Potentials: A Novel type of \
                            Superintegrable Mechanical Systems in the Plane";

/// Choices for building the catalogue: the defaults ([`PaperOptions::default`]), each changed
/// by a method of its name.
///
/// ```
/// use superint::prelude::*;
///
/// assert_eq!(PaperOptions::default().tower_max, 8);
/// assert_eq!(PaperOptions::default().tower_max(2).tower_max, 2);
/// ```
///
/// A choice may be added, so a program writes no literal of all of them:
///
/// ```compile_fail,E0639
/// let options = superint::paper::PaperOptions { tower_max: 2 };
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct PaperOptions {
    /// The bound `N` of the towers `1 ≤ m, n ≤ N` checked by expansion (the paper's claim C12
    /// asks for at least 8).
    pub tower_max: i64,
}

impl Default for PaperOptions {
    fn default() -> Self {
        PaperOptions { tower_max: 8 }
    }
}

impl PaperOptions {
    /// The same choices with the towers checked by expansion for `1 ≤ m, n ≤ n_max`.
    #[must_use]
    pub fn tower_max(mut self, n_max: i64) -> Self {
        self.tower_max = n_max;
        self
    }
}

/// The paper: sections of items.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Paper {
    /// The title of the report.
    pub title: String,
    /// The paper checked.
    pub subtitle: String,
    /// The sections, in the paper's order.
    pub sections: Vec<Section>,
}

/// A section of the paper.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Section {
    /// The paper's section number.
    pub number: u32,
    /// The title.
    pub title: String,
    /// The items, in order.
    pub items: Vec<Item>,
}

/// One item of a section, before it is computed.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Item {
    /// A sub-heading.
    Heading(String),
    /// Prose, with mathematics between backticks.
    Text(String),
    /// Equations shown as they are (definitions): `L = x p_y − y p_x`.
    Equations(Equations),
    /// A Hamiltonian and Hamilton's equations, computed from the system.
    Hamilton {
        /// The system.
        system: Arc<System>,
    },
    /// A claim to check.
    Claim(Box<PaperClaim>),
    /// A bracket table of named functions.
    Table {
        /// Whose brackets the table shows (`the harmonic rotor`).
        whose: String,
        /// The system.
        system: Arc<System>,
        /// The functions' names.
        names: Vec<String>,
    },
    /// `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` by expansion for `1 ≤ m, n ≤ max`.
    Tower {
        /// The claim's id.
        id: String,
        /// The claim as the paper states it.
        statement: String,
        /// The system.
        system: Arc<System>,
        /// The ladder function's name.
        ladder: String,
        /// The family's display name (`K`, `K'`).
        family: String,
        /// The bound.
        max: i64,
    },
    /// The all-`m, n` proof by the eigenfunction lemma.
    Proof {
        /// What the proof shows.
        title: String,
        /// The claims it settles: `(id, statement)`.
        settles: Vec<(String, String)>,
        /// The system.
        system: Arc<System>,
        /// The ladder function's name.
        ladder: String,
        /// The family's display name, as the conclusion names it (`K`, `K'`).
        family: String,
    },
    /// The rank of the Jacobian of some functions.
    Rank {
        /// The claim's id.
        id: String,
        /// The system (its phase space).
        system: Arc<System>,
        /// The functions, with their names in the paper's notation.
        functions: Vec<(String, Expr)>,
        /// The rank the paper states.
        expected: usize,
    },
}

/// A claim of the paper: an engine [`Claim`] and whether it asserts an identity or a
/// nonvanishing.
#[derive(Clone, Debug)]
pub struct PaperClaim {
    /// The claim (id, statement, sides, condition).
    pub claim: Claim,
    /// Identity or nonvanishing ([`PaperClaim::check`] refuses [`ClaimKind::Rank`], which is
    /// an [`Item::Rank`]).
    pub kind: ClaimKind,
}

impl Paper {
    /// The catalogue: sections 2 to 5 of the paper with every claim from C01 to C26.
    pub fn build(options: &PaperOptions) -> Result<Paper, EngineError> {
        Ok(Paper {
            title: TITLE.into(),
            subtitle: SUBTITLE.into(),
            sections: vec![
                planar::section()?,
                harmonic::section(options)?,
                gravity::section(options)?,
                beyond::section()?,
            ],
        })
    }

    /// Computes every item: the report.
    pub fn check(&self) -> Result<Report, EngineError> {
        let start = Instant::now();
        let sections = self
            .sections
            .iter()
            .map(|s| {
                Ok(ReportSection {
                    number: s.number,
                    title: s.title.clone(),
                    file: None,
                    entries: s
                        .items
                        .iter()
                        .map(|item| item.compute(&mut |_, _| {}))
                        .collect::<Result<Vec<_>, EngineError>>()?
                        .into_iter()
                        .flatten()
                        .collect(),
                    names: Names::default(),
                })
            })
            .collect::<Result<Vec<_>, EngineError>>()?;
        Ok(Report {
            title: self.title.clone(),
            subtitle: self.subtitle.clone(),
            sections,
            summary: SummaryKind::Claims,
            seconds: start.elapsed().as_secs_f64(),
            caller: Caller::Program,
        })
    }
}

/// Which system a tower job runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TowerSystem {
    /// The harmonic rotor with `Z` (claim C12).
    Harmonic,
    /// The rotor under gravity with the shifted `Z'` (claim C24).
    Gravity,
}

/// The tower job: `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` by expansion for `1 ≤ m, n ≤ max`, and
/// the all-`m, n` proof ([`tower_report_with_progress`] reports each bracket as it is done).
///
/// ```
/// use superint::paper::{tower_report, TowerSystem};
///
/// let report = tower_report(TowerSystem::Harmonic, 2)?;
/// assert!(report.all_proved());
/// # Ok::<(), superint::brackets::EngineError>(())
/// ```
pub fn tower_report(which: TowerSystem, max: i64) -> Result<Report, EngineError> {
    tower_report_with_progress(which, max, &mut |_, _| {})
}

/// [`tower_report`], calling `progress(done, total)` after each bracket (the command line's
/// progress bar).
pub fn tower_report_with_progress(
    which: TowerSystem,
    max: i64,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Report, EngineError> {
    let start = Instant::now();
    let (system, ladder, id, k) = match which {
        TowerSystem::Harmonic => (brackets::systems::harmonic_rotor(), "Z", "C12", "K"),
        TowerSystem::Gravity => (brackets::systems::gravity_rotor(), "Zp", "C24", "K'"),
    };
    let system = Arc::new(system);
    let z = system.display_name(ladder).to_string();
    let tower = Item::Tower {
        id: id.into(),
        statement: format!("{{{k}_{{m,n}}, F1}} = i(mω − nΩ){k}_{{m,n}} for 1 ≤ m, n ≤ {max}"),
        system: system.clone(),
        ladder: ladder.into(),
        family: k.into(),
        max,
    };
    let proof = Item::Proof {
        title: format!("for all m, n ≥ 0, from the ladder function {z}"),
        settles: vec![(
            id.into(),
            format!("{{{k}_{{m,n}}, F1}} = i(mω − nΩ){k}_{{m,n}} for all m, n ≥ 0"),
        )],
        system: system.clone(),
        ladder: ladder.into(),
        family: k.into(),
    };
    let text = Item::Text(format!(
        "The {}: `{k}_{{m,n}} = {z}^m e^{{−inθ}}` with `Ω = p_θ/I`.",
        system.name()
    ));
    let mut entries = Vec::new();
    for item in [text, tower, proof] {
        entries.extend(item.compute(progress)?);
    }
    Ok(Report {
        title: format!("The tower of resonant integrals, `1 ≤ m, n ≤ {max}`"),
        subtitle: String::new(),
        sections: vec![ReportSection {
            number: if which == TowerSystem::Harmonic { 3 } else { 4 },
            title: format!("`{{{k}_{{m,n}}, H}}` for the {}", system.name()),
            file: None,
            entries,
            names: Names::of_system(&system),
        }],
        summary: SummaryKind::Tower,
        seconds: start.elapsed().as_secs_f64(),
        caller: Caller::Program,
    })
}

impl Item {
    /// Computes the item: the entries it contributes to the report.
    pub fn compute(
        &self,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<Vec<Entry>, EngineError> {
        Ok(match self {
            Item::Heading(h) => vec![Entry::Heading(h.clone())],
            Item::Text(t) => vec![Entry::Text(t.clone())],
            Item::Equations(e) => vec![Entry::Equations(e.clone())],
            Item::Hamilton { system } => hamilton(system)?,
            Item::Claim(c) => vec![Entry::Claim(c.check()?)],
            Item::Table {
                whose,
                system,
                names,
            } => {
                vec![Entry::Table(TableResult::new(
                    BracketTable::compute(system, names)?,
                    system,
                    whose,
                ))]
            }
            Item::Tower {
                id,
                statement,
                system,
                ladder,
                family,
                max,
            } => vec![tower_entry(
                (id, statement),
                system,
                (ladder, family),
                *max,
                progress,
            )?],
            Item::Proof {
                title,
                settles,
                system,
                ladder,
                family,
            } => vec![proof_entry(title, settles, system, ladder, family)?],
            Item::Rank {
                id,
                system,
                functions,
                expected,
            } => vec![rank_entry(id, system, functions, *expected)?],
        })
    }
}

/// The tower `{K_{m,n}, H}` of the family `K` of `ladder` checked by expansion up to `max`,
/// as the claim `(id, statement)`.
fn tower_entry(
    (id, statement): (&str, &str),
    system: &System,
    (ladder, family): (&str, &str),
    max: i64,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Entry, EngineError> {
    let t = check_tower(system, ladder, max, progress)?;
    let note = (!t.failures.is_empty()).then(|| format!("fails for (m, n) in {:?}", t.failures));
    Ok(Entry::Tower(TowerResult {
        system: system.name().to_string(),
        the_system: crate::report::with_article(system.name()),
        ladder: system.display_name(ladder).to_string(),
        family: format!("{family}_{{m,n}}"),
        max: t.max,
        checked: t.checked,
        failures: t.failures.clone(),
        claim: ClaimResult::derived(id, statement, t.failures.is_empty(), note).timed(t.seconds),
    }))
}

/// The eigenfunction proof for all `m, n` of `family` from `ladder`, settling each claim of
/// `settles`.
fn proof_entry(
    title: &str,
    settles: &[(String, String)],
    system: &System,
    ladder: &str,
    family: &str,
) -> Result<Entry, EngineError> {
    let start = Instant::now();
    let p = eigen_proof_of(system, ladder, family)?;
    let seconds = start.elapsed().as_secs_f64();
    let facts: Vec<Fact> = p
        .facts
        .iter()
        .map(|f| Fact {
            statement: f.statement.clone(),
            holds: f.holds,
            found: None,
            found_statement: None,
        })
        .collect();
    let note = ProofResult::failed_steps(&facts, p.leibniz_check);
    let holds = note.is_none();
    Ok(Entry::Proof(ProofResult {
        title: title.to_string(),
        facts,
        lemma: p.lemma.clone(),
        bases: ["A".into(), "B".into()],
        leibniz_check: p.leibniz_check,
        conclusion: p.conclusion.clone(),
        claims: settles
            .iter()
            .map(|(id, st)| ClaimResult::derived(id, st, holds, note.clone()).timed(seconds))
            .collect(),
    }))
}

/// The certified rank of the named `functions`, answering the claim that it is `expected`.
fn rank_entry(
    id: &str,
    system: &System,
    functions: &[(String, Expr)],
    expected: usize,
) -> Result<Entry, EngineError> {
    let start = Instant::now();
    let exprs: Vec<Expr> = functions.iter().map(|f| f.1.clone()).collect();
    let cert = rank(system.space(), &exprs)?;
    let names: Vec<String> = functions.iter().map(|f| f.0.clone()).collect();
    let mut result = RankResult::new(id, system, names, expected, cert);
    result.claim = result.claim.timed(start.elapsed().as_secs_f64());
    Ok(Entry::Rank(result))
}

impl PaperClaim {
    /// Checks the claim exactly; a claim of kind [`ClaimKind::Rank`] is refused
    /// ([`EngineError::Invalid`]): a rank is an [`Item::Rank`], certified from its functions.
    pub fn check(&self) -> Result<ClaimResult, EngineError> {
        let identity = || self.claim.check().map(ClaimResult::from);
        match self.kind {
            ClaimKind::Identity => identity(),
            // A nonvanishing claim is proved by the nonzero value its "residual" is.
            ClaimKind::Nonvanishing => {
                let identity = identity()?;
                let witness = identity.residual.clone();
                Ok(ClaimResult {
                    kind: ClaimKind::Nonvanishing,
                    proved: witness.is_some(),
                    residual: None,
                    note: witness
                        .is_none()
                        .then(|| "the value is identically zero".into()),
                    witness,
                    ..identity
                })
            }
            // Refused before its sides are computed, which a rank has none of.
            ClaimKind::Rank => Err(EngineError::Invalid(format!(
                "{} is a claim of two sides, not a rank: a rank is certified from its \
                 functions (Item::Rank)",
                self.claim.id
            ))),
        }
    }
}

/// `H = …` and Hamilton's equations `q̇ = ∂H/∂p`, `ṗ = −∂H/∂q`, computed.
fn hamilton(system: &System) -> Result<Vec<Entry>, EngineError> {
    let vars = system.vars();
    let lines = system
        .space()
        .hamilton_equations(system.hamiltonian())?
        .into_iter()
        .map(|(v, e)| Equation::new(&dotted(vars.variable(v).unicode()), e))
        .collect();
    Ok(vec![
        Entry::Equations(Equations::new(
            String::new(),
            vec![Equation::new("H", system.hamiltonian().clone())],
        )),
        Entry::Equations(Equations::new("Hamilton's equations".into(), lines)),
    ])
}

/// `p_x` → `ṗ_x`: a combining dot over the first character.
pub fn dotted(name: &str) -> String {
    let mut chars = name.chars();
    let first = chars.next().unwrap_or(' ');
    format!("{first}\u{307}{}", chars.as_str())
}

/// Collects a section's items, parsing in one system at a time.
pub(crate) struct SectionBuilder {
    number: u32,
    title: String,
    items: Vec<Item>,
    system: Arc<System>,
}

impl SectionBuilder {
    pub(crate) fn new(number: u32, title: &str, system: System) -> Self {
        SectionBuilder {
            number,
            title: title.into(),
            items: Vec::new(),
            system: Arc::new(system),
        }
    }

    /// The system claims are parsed in from now on.
    pub(crate) fn use_system(&mut self, system: System) -> Arc<System> {
        self.system = Arc::new(system);
        self.system.clone()
    }

    pub(crate) fn system(&self) -> &Arc<System> {
        &self.system
    }

    pub(crate) fn parse(&self, src: &str) -> Result<Expr, EngineError> {
        self.system.parse(src)
    }

    pub(crate) fn heading(&mut self, h: &str) {
        self.items.push(Item::Heading(h.into()));
    }

    pub(crate) fn text(&mut self, t: &str) {
        self.items.push(Item::Text(t.into()));
    }

    pub(crate) fn item(&mut self, item: Item) {
        self.items.push(item);
    }

    pub(crate) fn hamilton(&mut self) {
        self.items.push(Item::Hamilton {
            system: self.system.clone(),
        });
    }

    /// Shows `lhs = value` for named functions or expressions of the current system.
    pub(crate) fn show(
        &mut self,
        caption: &str,
        lines: &[(&str, &str)],
    ) -> Result<(), EngineError> {
        let lines = lines
            .iter()
            .map(|(lhs, src)| Ok(Equation::new(lhs, self.parse(src)?)))
            .collect::<Result<_, EngineError>>()?;
        self.items
            .push(Item::Equations(Equations::new(caption.into(), lines)));
        Ok(())
    }

    pub(crate) fn show_exprs(&mut self, caption: &str, lines: Vec<(String, Expr)>) {
        self.items.push(Item::Equations(Equations::new(
            caption.into(),
            lines
                .into_iter()
                .map(|(l, e)| Equation::new(&l, e))
                .collect(),
        )));
    }

    /// `lhs = rhs`, both parsed in the current system.
    pub(crate) fn identity(
        &mut self,
        id: &str,
        statement: &str,
        lhs: &str,
        rhs: &str,
    ) -> Result<(), EngineError> {
        self.identity_under(id, statement, lhs, rhs, None)
    }

    /// `lhs = rhs` under a condition, both parsed in the current system.
    pub(crate) fn identity_when(
        &mut self,
        id: &str,
        statement: &str,
        lhs: &str,
        rhs: &str,
        condition: Condition,
    ) -> Result<(), EngineError> {
        self.identity_under(id, statement, lhs, rhs, Some(condition))
    }

    /// `lhs = rhs` under a condition if any, read with what the sides are computed from
    /// ([`Claim::parse`]), so that a condition where one of those has no value is refused.
    fn identity_under(
        &mut self,
        id: &str,
        statement: &str,
        lhs: &str,
        rhs: &str,
        condition: Option<Condition>,
    ) -> Result<(), EngineError> {
        let mut claim = Claim::parse(&self.system, id, statement, lhs, rhs)?;
        if let Some(c) = condition {
            claim = claim.when(c);
        }
        self.items.push(Item::Claim(Box::new(PaperClaim {
            claim,
            kind: ClaimKind::Identity,
        })));
        Ok(())
    }

    /// A claim from expressions.
    pub(crate) fn claim(
        &mut self,
        id: &str,
        statement: &str,
        lhs: Expr,
        rhs: Expr,
        condition: Option<Condition>,
        kind: ClaimKind,
    ) {
        let mut claim = Claim::new(id, statement, lhs, rhs);
        if let Some(c) = condition {
            claim = claim.when(c);
        }
        self.items
            .push(Item::Claim(Box::new(PaperClaim { claim, kind })));
    }

    /// A bracket table of named functions of the current system.
    pub(crate) fn table(&mut self, whose: &str, names: &[&str]) {
        self.items.push(Item::Table {
            whose: whose.into(),
            system: self.system.clone(),
            names: names.iter().map(|s| s.to_string()).collect(),
        });
    }

    /// A rank claim on named functions (`(display name, expression source)`).
    pub(crate) fn rank(
        &mut self,
        id: &str,
        functions: &[(&str, &str)],
        expected: usize,
    ) -> Result<(), EngineError> {
        let functions = functions
            .iter()
            .map(|(n, src)| Ok((n.to_string(), self.parse(src)?)))
            .collect::<Result<_, EngineError>>()?;
        self.items.push(Item::Rank {
            id: id.into(),
            system: self.system.clone(),
            functions,
            expected,
        });
        Ok(())
    }

    pub(crate) fn finish(self) -> Section {
        Section {
            number: self.number,
            title: self.title,
            items: self.items,
        }
    }
}
