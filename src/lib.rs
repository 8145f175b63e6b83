//! # superint
//!
//! Exact Poisson-bracket identities of superintegrable Hamiltonian systems: a rigid rotor
//! coupled to planar potentials. This crate is the facade of the workspace: it re-exports the
//! ring ([`trigpoly`][trigpoly-crate]) and the bracket engine ([`brackets`][brackets-crate]),
//! holds the paper as data ([`paper`]), the structured [`report`] that checking it produces,
//! and the renderers ([`render`]) that print a report as text, Markdown, LaTeX or JSON.
//!
//! A system may be built in code ([`brackets::System`]) or loaded from a system file
//! ([`system_file::load`]); either becomes a [`system_file::LoadedSystem`], to which a program
//! adds functions, families such as `K_{m,n}` and claims in its own names
//! ([`system_file::LoadedSystem::add_family`]), and whose claims, brackets, tables, ranks and
//! family towers become [`report::Report`]s rendered by [`render::render`]. The examples
//! `own_system`, `extend_file` and `discover` show each use; `garnier` does all of it for a
//! system of its own with parameters in a declared denominator.
//!
//! A program that only uses the library can depend on it with `default-features = false`
//! (`superint = { path = "../superint", default-features = false }`, by path or git, as the
//! workspace's crates are not published; [`trigpoly`][trigpoly-crate] and
//! [`brackets`][brackets-crate] come with it): the feature `cli` (on by default) adds the
//! command-line program and its allocator, and with them clap, indicatif and mimalloc.
//!
//! [trigpoly-crate]: ../trigpoly/index.html
//! [brackets-crate]: ../brackets/index.html
// The two crates are linked by their pages: `cargo doc` may render this page before it has
// made theirs (it documents the crates of the workspace at once), and rustdoc links a crate
// by name only when its pages are there when it starts, so `[`trigpoly`]` was plain text.
//!
//! ```
//! use superint::prelude::*;
//!
//! // C09: the su(2) brackets of the harmonic rotor, proved exactly.
//! let rotor = systems::harmonic_rotor();
//! for (lhs, rhs) in [("{L, G1}", "-G2"), ("{L, G2}", "4*G1"), ("{G1, G2}", "-omega^2*L")] {
//!     let claim = Claim::new("C09", lhs, rotor.parse(lhs)?, rotor.parse(rhs)?);
//!     assert_eq!(claim.check()?.outcome, Outcome::Proved);
//! }
//! // The table prints like the paper.
//! let table = BracketTable::compute(&rotor, &["L", "G1", "G2"])?;
//! assert_eq!(table.entries[2][1].render(Style::Unicode), "ω² L");
//! # Ok::<(), EngineError>(())
//! ```
#![deny(missing_docs, missing_debug_implementations)]

pub use brackets;
/// The JSON crate of [`render::json::value`], re-exported so that a program names
/// `serde_json::Value` at the version used here without depending on it.
pub use serde_json;
pub use trigpoly;

/// The `ALL` and `name()` of a fieldless enum, `$ty`, each with the doc written before its
/// word (`ALL;`, `name;`), from one list of the variants with their names: `name`'s match must
/// cover every variant, so that a variant left out of the list, and so out of `ALL`, does not
/// compile (the order of `ALL` is the list's, which a test holds to the declaration's).
/// [`report::Expect`] and [`system_file::ErrorKind`] are named so.
macro_rules! variants_with_names {
    (
        $ty:ident;
        $(#[$all_doc:meta])*
        ALL;
        $(#[$name_doc:meta])*
        name;
        $($variant:ident => $name:literal,)*
    ) => {
        impl $ty {
            $(#[$all_doc])*
            pub const ALL: [$ty; [$($name),*].len()] = [$($ty::$variant),*];

            $(#[$name_doc])*
            pub fn name(self) -> &'static str {
                match self {
                    $($ty::$variant => $name,)*
                }
            }
        }
    };
}

#[cfg(feature = "cli")]
pub mod allocator;
pub mod discovery;
pub mod paper;
pub mod render;
pub mod report;
pub mod system_file;
pub mod trajectory;
pub mod workloads;

// The README's Rust example runs as a doctest, so the front page cannot rot.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

// So does the Rust example of the system files' document.
#[cfg(doctest)]
#[doc = include_str!("../docs/system-files.md")]
pub struct SystemFilesDoctests;

/// Everything a user of the library needs: `use superint::prelude::*;`.
///
/// A limit ([`Limits`](trigpoly::Limits): terms, degree, work) refuses with a typed error: the
/// ring's [`AlgebraError`](trigpoly::AlgebraError), whose
/// [`limit`](trigpoly::AlgebraError::limit) names the [`LimitKind`](trigpoly::LimitKind); the
/// engine's [`EngineError::limit`](brackets::EngineError::limit), which names the
/// [`EngineLimit`](brackets::EngineLimit) (the ring's, or a search's or a closure's own
/// option), and [`is_limit`](brackets::EngineError::is_limit); a file's error of kind
/// [`ErrorKind::Limit`](crate::system_file::ErrorKind::Limit), and a claim past a limit
/// undecided in the report of [`check_each`](crate::system_file::check_each), which checks
/// the others:
///
/// ```
/// use superint::prelude::*;
///
/// let limits = Limits::default().max_terms(30).max_degree(8);
/// let builder: VarsBuilder = Vars::builder().coordinate("x").momentum("p_x");
/// let vars = builder.limits(limits).build()?;
/// let sum = Expr::parse(&vars, "1 + x + p_x")?;
/// // (1 + x + p_x)^7 has 36 terms, x^9 an exponent past 8.
/// assert_eq!(sum.checked_pow(7), Err(AlgebraError::TooManyTerms { limit: 30 }));
/// let err = Expr::parse(&vars, "x")?.checked_pow(9).unwrap_err();
/// assert_eq!(err.limit(), Some(LimitKind::Degree(9)));
///
/// let text = r#"
/// hamiltonian = "p_x^2/2"
/// [phase_space]
/// coordinates = ["x"]
/// [[claim]]
/// claim = "{x, (1 + x + p_x)^40} = 0"
/// [[claim]]
/// claim = "{p_x, H} = 0"
/// "#;
/// let small = LimitsOverride::default().max_terms(100);
/// let (report, errors) = check_each(vec![load_system_text("free.toml", text, &small)]);
/// let outcomes: Vec<ClaimOutcome> = report.claims().iter().map(|c| c.outcome()).collect();
/// assert_eq!(outcomes, [ClaimOutcome::Undecided, ClaimOutcome::Proved]);
/// assert_eq!(errors[0].kind, ErrorKind::Limit);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// A search at fixed values of the parameters finds its integrals there
/// ([`Integral::fixed`](brackets::Integral::fixed)): a known function is compared with them at
/// the same values, those of [`SearchResult::parameters`](brackets::SearchResult::parameters),
/// by [`fix_parameters`](brackets::search::fix_parameters):
///
/// ```
/// use superint::prelude::*;
///
/// let text = r#"
/// hamiltonian = "(p_x^2 + w*x^2)/2"
/// [phase_space]
/// coordinates = ["x"]
/// parameters = ["w"]
/// "#;
/// let file = load_system_text("oscillator.toml", text, &LimitsOverride::default())?;
/// let system = file.system();
/// let space = SearchSpace::default().momenta_degree(2).positions_degree(2);
/// let found = search(system, &SearchOptions::new(space).fix(system.var("w"), 4))?;
/// let energy = &found.basis[1];
/// assert_eq!(energy.fixed.to_string(), "p_x² + 4x²");
/// // H as written holds w; at w = 4 it is half the integral found.
/// let h = fix_parameters(system.hamiltonian(), &found.parameters)?;
/// assert_ne!(&energy.fixed, system.hamiltonian());
/// assert_eq!(energy.fixed, h.scale_rational(&Rational::from(2)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub mod prelude {
    pub use brackets::search::fix_parameters;
    pub use brackets::{
        check_tower, closure, closure_of, eigen_proof, eigen_proof_of, expressed_in, rank, rank_on,
        search, systems, BracketTable, CanonicalPair, Claim, Closure, ClosureBracket,
        ClosureOptions, Condition, EigenProof, EngineError, EngineLimit, Entry as TableEntry,
        Expressed, FunctionName, Integral, NamedFunction, Outcome, PhaseSpace, RankCertificate,
        Relation, SearchOptions, SearchResult, SearchSpace, System, TowerReport, UpperBound,
        Verdict,
    };
    pub use trigpoly::{
        AlgebraError, Expr, GaussianRational, LimitKind, Limits, ParseError, Point, Poly, Rational,
        Style, Var, VarKind, VarSet, Vars, VarsBuilder,
    };

    pub use brackets::systems::Resonant;

    pub use crate::discovery::{
        closure_report, file_closure_report, file_search_report, search_report,
    };
    pub use crate::paper::{
        tower_report, tower_report_with_progress, Paper, PaperOptions, TowerSystem,
    };
    pub use crate::render::{render, Format, Options as RenderOptions};
    pub use crate::report::{
        ClaimKind, ClaimOutcome, ClaimResult, Expect, ProofResult, RankResult, Report, TableResult,
        TowerResult,
    };
    pub use crate::system_file::{
        bracket_report, check_each, check_report, expand_report, family_tower_report,
        family_tower_report_with_progress, load as load_system_file, load_str as load_system_text,
        rank_report, rank_report_when, table_report, Caller, CheckedClaim, ClaimSpec, ErrorKind,
        Family, FileError, LimitsOverride, LoadedSystem, Location, Warning,
    };
}
