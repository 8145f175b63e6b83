//! System files: a researcher's own Hamiltonian system, its named functions, families and
//! claims, declared in TOML (the format is documented in `docs/system-files.md`), loaded into
//! a [`brackets::System`] and checked.
//!
//! ```
//! use superint::system_file::{load_str, LimitsOverride};
//!
//! let file = r#"
//! name = "Harmonic oscillator"
//! hamiltonian = "p_x^2/(2*M) + M*omega^2*x^2/2"
//!
//! [phase_space]
//! coordinates = ["x"]
//! parameters = ["M", "omega"]
//!
//! [[function]]
//! name = "A"
//! value = "p_x + i*M*omega*x"
//!
//! [[claim]]
//! id = "ladder"
//! claim = "{A, H} = i*omega*A"
//!
//! [[claim]]
//! id = "wrong-sign"
//! claim = "{A, H} = -i*omega*A"
//! expect = "refuted"
//! "#;
//! let system = load_str("oscillator.toml", file, &LimitsOverride::default())?;
//! let report = superint::system_file::check_report(&[system])?;
//! assert!(report.all_as_expected());
//! assert_eq!(report.claims().len(), 2);
//! # Ok::<(), superint::system_file::FileError>(())
//! ```
//!
//! The loader is the only part of the workspace that reads files: `brackets` does no I/O.
//! Every expression string keeps its place in the file ([`Text`]), so that an error anywhere,
//! in TOML, in an expression, or in a family expanded much later, is reported as
//! `FILE:LINE:COLUMN: message` with the source line and a caret ([`FileError`]).

mod claims;
pub(crate) use claims::{
    assignment_sides, condition_cannot_set, decimal_number, fixed_twice, no_variable,
    CONDITION_FORM, FIX_ONCE,
};
mod code;
mod error;
mod generators;
mod keys;
mod load;
mod model;
mod names;
mod on_level;
mod plot;
mod pretty;
mod reports;
mod roots_of_unity;
mod scope;
mod text;
mod tower;
mod written;
pub(crate) use written::MAX_INTEGRALS as MAX_RESTATED;

pub use claims::{CheckedClaim, ClaimForm, ClaimSpec, CONDITION_USAGE};
pub use error::{ErrorKind, FileError, Location, UnknownErrorKind, Warning, Warnings};
pub(crate) use generators::unshowable_in_name;
pub use generators::{
    display_as_given, looks_like_name, name_as_identifier, new_name_refusal,
    refuse_expression_as_generator, refuse_parameter_as_generator, refuse_unshowable_name,
};
pub use load::{
    load, load_bytes, load_piped, load_str, read_bytes, MAX_DEGREE_CEILING, MAX_FILE_BYTES,
};
pub use names::{reserved, unwritable_letter, BadName, PrintedNames, Refusal};
pub use on_level::ClaimLevelSet;
pub use plot::{Against, PlotFunctions, PlotInput, StartValue};
pub use reports::{
    bracket_report, check_each, check_report, expand_report, given_twice, rank_report,
    rank_report_when, table_report,
};
pub(crate) use scope::{Limit, LimitSettings};
pub use text::{comma_pieces, split_top_level, trimmed, Given, Source, Text};
pub use tower::{family_tower_report, family_tower_report_with_progress};

use std::collections::HashMap;
use std::ops::Range;
use std::sync::Mutex;

use brackets::System;
use trigpoly::syntax::Expr as Tree;
use trigpoly::{Expr, Limits};

/// The default term limit of a system file: no single result may have more terms.
pub const DEFAULT_MAX_TERMS: usize = 2_000_000;
/// The default degree limit of a system file: no exponent may exceed it in absolute value
/// (the library's default, [`Limits::DEFAULT_MAX_DEGREE`]).
pub const DEFAULT_MAX_DEGREE: u32 = Limits::DEFAULT_MAX_DEGREE;

/// Limits given on the command line (`--max-terms`, `--max-degree`, `--max-term-products`):
/// they override the file's `[limits]`, which override the defaults. Each of the three given
/// must be at least 1, as in the file: the loader refuses a 0 (an error of kind
/// [`ErrorKind::Schema`]). The cap on the room reserved for a result, `max_reserved_bytes`, is
/// taken as given: a cap of 0 refuses every result whose room is reserved from a predicted
/// count.
///
/// None is given by default; each is given by a method of its name:
///
/// ```
/// use superint::prelude::*;
///
/// let given = LimitsOverride::default().max_terms(100).max_degree(40);
/// assert_eq!((given.max_terms, given.max_degree), (Some(100), Some(40)));
/// let given = given.max_term_products(1_000_000).max_reserved_bytes(1 << 30);
/// assert_eq!(given.max_term_products, Some(1_000_000));
/// assert_eq!(given.max_reserved_bytes, Some(1 << 30));
/// let limits = LimitsOverride::default().max_terms(100).or_defaults();
/// assert_eq!(limits, Limits::default().max_terms(100));
/// let rotor = load_system_file("systems/harmonic-rotor.toml", &given)?;
/// assert_eq!(rotor.limits().max_terms, 100);
/// # Ok::<(), FileError>(())
/// ```
///
/// A limit may be added, so a program writes no literal of all of them:
///
/// ```compile_fail,E0639
/// let given = superint::system_file::LimitsOverride { max_terms: Some(10), max_degree: None,
///     max_term_products: None, max_reserved_bytes: None };
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct LimitsOverride {
    /// `--max-terms`.
    pub max_terms: Option<usize>,
    /// `--max-degree`.
    pub max_degree: Option<u32>,
    /// `--max-term-products`.
    pub max_term_products: Option<u64>,
    /// The cap on the bytes of room reserved for a result from a predicted count
    /// ([`Limits::max_reserved_bytes`]): no flag nor file key; the command line gives the
    /// machine's physical memory. `None`: no cap beyond the allocator's refusal.
    pub max_reserved_bytes: Option<u64>,
}

impl LimitsOverride {
    /// The same with at most `n` terms in any single result (`--max-terms`).
    #[must_use]
    pub fn max_terms(mut self, n: usize) -> Self {
        self.max_terms = Some(n);
        self
    }

    /// The same with no exponent past `d` (`--max-degree`).
    #[must_use]
    pub fn max_degree(mut self, d: u32) -> Self {
        self.max_degree = Some(d);
        self
    }

    /// The same with at most `n` term products a product, and a sum's products together
    /// (`--max-term-products`).
    #[must_use]
    pub fn max_term_products(mut self, n: u64) -> Self {
        self.max_term_products = Some(n);
        self
    }

    /// The same with at most `n` bytes of room reserved for a result from its predicted count
    /// of terms (the command line's is the machine's physical memory).
    #[must_use]
    pub fn max_reserved_bytes(mut self, n: u64) -> Self {
        self.max_reserved_bytes = Some(n);
        self
    }

    /// The limits given, else a system file's defaults ([`DEFAULT_MAX_TERMS`],
    /// [`DEFAULT_MAX_DEGREE`], [`Limits::DEFAULT_MAX_TERM_PRODUCTS`], no memory cap): those
    /// of a built-in system on the command line.
    pub fn or_defaults(&self) -> Limits {
        Limits::default()
            .max_terms(self.max_terms.unwrap_or(DEFAULT_MAX_TERMS))
            .max_degree(self.max_degree.unwrap_or(DEFAULT_MAX_DEGREE))
            .max_term_products(
                self.max_term_products
                    .unwrap_or(Limits::DEFAULT_MAX_TERM_PRODUCTS),
            )
            .max_reserved_bytes(self.max_reserved_bytes.unwrap_or(Limits::NO_MEMORY_CAP))
    }
}

/// A family of functions with two integer indices, such as `K_{m,n} = Z^m e^{−inθ}`: its
/// instances are named `K_2_3` (or `K_{2,3}`) in expressions.
#[derive(Clone, Debug)]
pub struct Family {
    /// The name (`K`).
    pub name: String,
    /// The name as printed (`K̄`).
    pub display: String,
    /// The index names (`m`, `n`).
    pub indices: [String; 2],
    /// The value, in the indices.
    pub value: Text,
    /// The eigenvalue `λ(m, n)` with `{K_{m,n}, H} = λ(m, n) K_{m,n}`, if declared.
    pub eigenvalue: Option<Text>,
    /// Where the family's name is in its source.
    pub span: Range<usize>,
    /// The source of `value` and `eigenvalue`: the file's text, or for a family added in code
    /// ([`LoadedSystem::add_family`]) its own.
    pub(crate) source: Source,
}

/// A loaded system file: the system (phase space, `H`, named functions), its families and
/// claims, its limits, and the source for error messages.
///
/// A system built in code becomes one by [`LoadedSystem::of_system`]; functions, families and
/// claims are added in code by [`LoadedSystem::add_function`], [`LoadedSystem::add_family`]
/// and [`LoadedSystem::add_claim`], and read as a file's own are.
///
/// Its parts are read through accessors ([`LoadedSystem::system`], [`LoadedSystem::families`],
/// [`LoadedSystem::claims`], ...) and changed only through those calls, so that every
/// function, family and claim it holds has been checked as a file's own is: a name the system
/// already has, or one its printed forms would confuse with another, never gets in.
///
/// ```compile_fail,E0616
/// # use superint::prelude::*;
/// let mut rotor = LoadedSystem::of_system(systems::harmonic_rotor());
/// // A function defined behind the loader's back, unchecked: not possible.
/// let x = rotor.parse("x")?;
/// rotor.system.define("L", "L", x)?;
/// # Ok::<(), FileError>(())
/// ```
pub struct LoadedSystem {
    /// The file's text and path as given.
    source: Source,
    /// The system's name (`name`, or the file name).
    name: String,
    /// Where the system comes from (`source`, a citation), if given.
    citation: Option<String>,
    /// What the system is (`description`), if given.
    description: Option<String>,
    /// The phase space, Hamiltonian `H` and named functions.
    system: System,
    /// The families, in file order.
    families: Vec<Family>,
    /// The claims, in file order (parsed syntactically; [`LoadedSystem::check_claim`] computes).
    claims: Vec<ClaimSpec>,
    /// The limits in force.
    limits: Limits,
    /// Who gives the texts the reports read, which their messages name.
    caller: Caller,
    /// Expanded family instances: `(family, m, n)`.
    cache: Mutex<HashMap<(usize, i64, i64), Expr>>,
    /// What each function's and expanded instance's value was computed from, by its name
    /// (`K_1_2` for an instance), which must have a value wherever it has one
    /// ([`LoadedSystem::computed_from`]).
    computed_from: Mutex<HashMap<String, Vec<brackets::Input>>>,
    /// Each radical's radicand as `[phase_space] radicals` writes it, by the radical's name
    /// (`s`, `1 + g2*(x^2 + y^2)`), which a report shows (the variables keep its normal form).
    radicands: Vec<(String, String)>,
    /// The readings in doubt of the texts read so far ([`LoadedSystem::warnings`]), each place
    /// once.
    warnings: Warnings,
}

/// The system, its source's origin and length, its families and claims by name and id, its
/// limits and caller: a file of a few kilobytes printed its text once and again in each claim
/// (443 KB for `systems/harmonic-rotor.toml`), and its cache of expanded instances.
///
/// ```
/// use superint::prelude::*;
///
/// let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let debug = format!("{rotor:?}");
/// let source = r#"source: Source { origin: "systems/harmonic-rotor.toml", text: <7166 bytes>"#;
/// assert!(debug.starts_with(&format!(r#"LoadedSystem {{ name: "harmonic rotor", {source}"#)));
/// assert!(debug.contains(r#"families: ["K", "Kbar", "P", "Q"], claims: ["C04", "C05""#));
/// assert!(debug.len() < 20_000, "{} bytes", debug.len());
/// # Ok::<(), FileError>(())
/// ```
impl std::fmt::Debug for LoadedSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let families: Vec<&str> = self.families.iter().map(|k| k.name.as_str()).collect();
        let claims: Vec<&str> = self.claims.iter().map(|c| c.id.as_str()).collect();
        f.debug_struct("LoadedSystem")
            .field("name", &self.name)
            .field("source", &self.source)
            .field("system", &self.system)
            .field("families", &families)
            .field("claims", &claims)
            .field("limits", &self.limits)
            .field("caller", &self.caller)
            .finish_non_exhaustive()
    }
}

/// Who gives the texts that the reports of a [`LoadedSystem`] read (the expressions of
/// [`bracket_report`], [`expand_report`] and [`rank_report`], the names of [`table_report`],
/// a condition, [`LoadedSystem::parse_argument`]), which their messages name, and whom a
/// report is built for ([`Report::caller`](crate::report::Report::caller)), whose options its
/// advice names. A loaded or built system's caller is [`Caller::Program`];
/// [`LoadedSystem::with_caller`] chooses another.
///
/// ```
/// use superint::system_file::{bracket_report, load, Caller, LimitsOverride};
///
/// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let err = bracket_report(&rotor, "L", "G3", None).unwrap_err();
/// assert!(err.to_string().starts_with("<expression>:1:1: unknown name 'G3'"));
/// let rotor = rotor.with_caller(Caller::CommandLine);
/// let err = bracket_report(&rotor, "L", "G3", None).unwrap_err();
/// assert!(err.to_string().starts_with("<command line>:1:1: unknown name 'G3'"));
/// # Ok::<(), superint::system_file::FileError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Caller {
    /// A program: an expression is `<expression>` in messages, a condition `<condition>`, a
    /// computation `<program>`, and they name the library's calls, not the command's options.
    #[default]
    Program,
    /// The command line (`superint bracket`, `table`, ...): every text given is
    /// `<command line>`, and messages name the command's options (`--when`).
    CommandLine,
}

impl Caller {
    /// What a report's advice names for this caller: the command line's `flag`, or the
    /// library's `library` (a field or method, `ClosureOptions::degree`) for a program.
    pub(crate) fn names<'a>(self, flag: &'a str, library: &'a str) -> &'a str {
        match self {
            Caller::CommandLine => flag,
            Caller::Program => library,
        }
    }
}

/// What `name` already names in `system` or among `families`, in words with its article:
/// `a parameter of the system` (or the variable's other kind), `the Hamiltonian`, `a function
/// of the system`, `a family of the system`, `an instance of the family K`; `None` for a name
/// the system does not have.
///
/// ```
/// let rotor = superint::brackets::systems::harmonic_rotor();
/// let what = |name| superint::system_file::what_is(&rotor, &[], name);
/// assert_eq!(what("omega").as_deref(), Some("a parameter of the system"));
/// assert_eq!(what("L").as_deref(), Some("a function of the system"));
/// assert_eq!(what("Hx"), None);
/// ```
pub fn what_is(system: &System, families: &[Family], name: &str) -> Option<String> {
    if let Some(v) = system.lookup(name) {
        let kind = system.vars().variable(v).kind();
        return Some(format!("{} of the system", kind.described()));
    }
    if name == "H" {
        return Some("the Hamiltonian".into());
    }
    // By its name or as it is shown (`Ω` for a function `Omega`).
    if system.get(name).is_ok() {
        return Some("a function of the system".into());
    }
    if families.iter().any(|f| f.name == name) {
        return Some("a family of the system".into());
    }
    scope::instance_of(families, name)
        .map(|(k, _, _)| format!("an instance of the family {}", families[k].name))
}

/// Where expressions given on the command line come from in messages ([`Caller::CommandLine`]),
/// a built-in system's as a file's.
pub const COMMAND_LINE: &str = "<command line>";

/// How messages name a system file read from standard input, which only the command line
/// reads (`superint check -`).
pub const STDIN: &str = "<stdin>";

/// An expression given to a report, parsed but not yet expanded. A report parses all its
/// arguments before it expands any, so that a slip in the last one is reported at once rather
/// than after the expansion of the first.
struct Argument {
    source: Source,
    text: Text,
    tree: Tree,
}

/// A copy with the instances expanded so far.
impl Clone for LoadedSystem {
    fn clone(&self) -> Self {
        let cache = self
            .cache
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone();
        LoadedSystem {
            source: self.source.clone(),
            name: self.name.clone(),
            citation: self.citation.clone(),
            description: self.description.clone(),
            system: self.system.clone(),
            families: self.families.clone(),
            claims: self.claims.clone(),
            limits: self.limits,
            caller: self.caller,
            cache: Mutex::new(cache),
            computed_from: Mutex::new(
                self.computed_from
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner)
                    .clone(),
            ),
            radicands: self.radicands.clone(),
            warnings: self.warnings.clone(),
        }
    }
}

impl LoadedSystem {
    /// A system built in code, as a file without families or claims would load: for the
    /// reports that take a loaded file ([`table_report`], [`rank_report`], [`check_report`]).
    ///
    /// ```
    /// use superint::system_file::{table_report, LoadedSystem};
    ///
    /// let rotor = LoadedSystem::of_system(superint::brackets::systems::harmonic_rotor());
    /// let report = table_report(&rotor, &["L", "G1", "G2"])?;
    /// assert!(superint::render::render(&report, Default::default(), &Default::default())
    ///     .contains("−ω² L"));
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn of_system(system: System) -> Self {
        LoadedSystem {
            source: Source::given_by("<program>", "", Given::InCode),
            name: system.name().to_string(),
            citation: None,
            description: None,
            limits: system.vars().limits(),
            system,
            families: Vec::new(),
            claims: Vec::new(),
            caller: Caller::Program,
            cache: Mutex::new(HashMap::new()),
            computed_from: Mutex::new(HashMap::new()),
            radicands: Vec::new(),
            warnings: Warnings::default(),
        }
    }

    /// The same system, whose reports name `caller` as the giver of their texts: the command
    /// line's `superint bracket`, say, loads a file `with_caller(Caller::CommandLine)`.
    #[must_use]
    pub fn with_caller(mut self, caller: Caller) -> Self {
        self.caller = caller;
        self
    }

    /// The same system, named `origin` where its reports and messages name a file (a system
    /// built in code is `<program>`): the command line's `superint bracket --system harmonic`
    /// names its built-in system `--system harmonic`.
    #[must_use]
    pub fn with_origin(mut self, origin: &str) -> Self {
        self.source = Source::given_by(origin, "", self.source.given);
        self
    }

    /// The same system, named `name` where its reports' titles name it (`{L, H} for the rotor
    /// under gravity`): the command line's built-in `--system gravity`, whose engine system
    /// is the `gravity rotor`, is named as `search --system gravity` titles it.
    #[must_use]
    pub fn with_name(mut self, name: &str) -> Self {
        self.name = name.to_string();
        self
    }

    /// Who gives the texts the reports read ([`Caller::Program`] unless
    /// [`LoadedSystem::with_caller`] said otherwise).
    pub fn caller(&self) -> Caller {
        self.caller
    }

    /// The source of the system's texts: the file's path (`origin`) and text, or `<program>`
    /// for a system built in code.
    pub fn source(&self) -> &Source {
        &self.source
    }

    /// The system's name (the file's `name`, or its file name; a system built in code, its
    /// [`System::name`]).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Where the system comes from (the file's `source`, a citation), if given.
    pub fn citation(&self) -> Option<&str> {
        self.citation.as_deref()
    }

    /// What the system is (the file's `description`), if given.
    pub fn description(&self) -> Option<&str> {
        self.description.as_deref()
    }

    /// The phase space, the Hamiltonian `H` and the named functions, for the engine's own
    /// calls ([`System::bracket`], [`System::flow`], [`System::rank`], ...).
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The families, in file order, then those added in code.
    pub fn families(&self) -> &[Family] {
        &self.families
    }

    /// Each family's name and display (`K_m_n`'s `K` and `K`), which a report's labels avoid
    /// as they do the system's names.
    pub(crate) fn family_names(&self) -> impl Iterator<Item = &str> {
        (self.families.iter()).flat_map(|f| [f.name.as_str(), f.display.as_str()])
    }

    /// The claims, in file order, then those added in code (read, not yet computed:
    /// [`LoadedSystem::check_claim`] computes one).
    pub fn claims(&self) -> &[ClaimSpec] {
        &self.claims
    }

    /// The limits in force (the file's `[limits]` with the loader's override, or the system's
    /// own for one built in code).
    pub fn limits(&self) -> Limits {
        self.limits
    }

    /// Parses an expression given to a report (named functions, family instances, brackets,
    /// `conj`/`re`/`im` allowed), as the reports read theirs; errors point into the argument,
    /// named as the [`Caller`] says (`<expression>`, or `<command line>`).
    pub fn parse_argument(&self, src: &str) -> Result<Expr, FileError> {
        self.value(&self.argument(src)?)
    }

    /// [`LoadedSystem::parse_argument`] of the part `range` of `text` (an expression of a
    /// list given on the command line, `--known`'s): its error, and what it reads in doubt, are
    /// placed in `text`, as typed.
    pub fn parse_argument_within(
        &self,
        text: &str,
        range: Range<usize>,
    ) -> Result<Expr, FileError> {
        let source = self.given("<expression>", text);
        let piece = Text::whole(&source).slice(range);
        self.value(&self.argument_at(source, piece)?)
    }

    /// An expression given to a report as the file's claims print it, in the paper's
    /// notation and the file's names (`{L_x, A_xy}` for `{Lx, Axy}`, `L²` for `L^2`); an error
    /// where it does not parse, as [`LoadedSystem::parse_argument`] reports it.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// assert_eq!(rotor.shown_argument("{L, G1} + Zbar*Kbar_1_2")?, "{L, G1} + Z̄ K̄_{1,2}");
    /// assert_eq!(rotor.shown_argument("M*omega^2*x^2/2")?, "Mω²x²/2");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn shown_argument(&self, src: &str) -> Result<String, FileError> {
        Ok(self.pretty(&self.argument(src)?.tree))
    }

    /// Reads an expression given to a report, without expanding it.
    fn argument(&self, src: &str) -> Result<Argument, FileError> {
        self.argument_in(self.given("<expression>", src))
    }

    /// The source of a text given to a report: `<command line>` for the command line, else
    /// `what` (`<expression>`, `<condition>`), given by the caller ([`Given`]). Its hints are
    /// those of the system's own texts (a file's tables, or the library's calls for a system
    /// built in code).
    pub(crate) fn given(&self, what: &str, text: &str) -> Source {
        let origin = match self.caller {
            Caller::CommandLine => COMMAND_LINE,
            Caller::Program => what,
        };
        Source::given_by(origin, text, self.source.given.by(self.caller))
    }

    /// Reads the expression that is `source`, without expanding it.
    fn argument_in(&self, source: Source) -> Result<Argument, FileError> {
        let text = Text::whole(&source);
        self.argument_at(source, text)
    }

    /// Reads the expression `text`, a part of `source`, without expanding it.
    fn argument_at(&self, source: Source, text: Text) -> Result<Argument, FileError> {
        let tree = self.scope(self.families.len()).tree(&source, &text)?;
        Ok(Argument { source, text, tree })
    }

    /// The value of a read argument.
    fn value(&self, arg: &Argument) -> Result<Expr, FileError> {
        self.scope(self.families.len())
            .lower(&arg.source, &arg.text, &arg.tree)
    }

    /// The instance `family_{m,n}` of a family, expanded (and cached); by name,
    /// [`LoadedSystem::parse`] of `K_2_3` gives the same.
    ///
    /// # Panics
    ///
    /// If `family` is not the index of one of [`LoadedSystem::families`] (see
    /// [`LoadedSystem::family`]).
    pub fn family_instance(&self, family: usize, m: i64, n: i64) -> Result<Expr, FileError> {
        self.scope(self.families.len())
            .expand(family, m, n, &self.source, || 0..0)
    }

    /// The texts read so far (the file's, as it loaded and as its claims are checked, and
    /// those given to its reports) in a way that may not be what was meant, in the order
    /// read, each place once: names run together read as products in doubt, `Lxx` beside a
    /// function `Lx` ([`Warning`], [`trigpoly::RunTogether`]). A check's report shows the
    /// file's own; the command line prints the others' on standard error.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let rotor = load("systems/isotropic-rotor-3d.toml", &LimitsOverride::default())?;
    /// rotor.parse_argument("M*omega*Lz + Lzx")?;
    /// let warnings = rotor.warnings();
    /// assert_eq!(warnings.len(), 1);
    /// assert_eq!(warnings[0].line_col(), Some((1, 14)));
    /// assert!(warnings[0].message.starts_with("'Lzx' is read as the product L_z x"));
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn warnings(&self) -> Vec<Warning> {
        self.warnings.list()
    }

    /// The readings in doubt kept ([`LoadedSystem::warnings`]), as a built-in system's
    /// subject keeps the command line's: to test a text whose warnings are dropped
    /// ([`Warnings::unwarned`]).
    pub fn kept_warnings(&self) -> &Warnings {
        &self.warnings
    }

    /// Keeps `warning` unless the same is kept already ([`Warnings::warn`]).
    pub(crate) fn warn(&self, warning: Warning) {
        self.warnings.warn(warning);
    }

    /// What `name` already names in this system, for a message that refuses it as a new
    /// name: [`what_is`] with the families.
    pub fn what_is(&self, name: &str) -> Option<String> {
        what_is(&self.system, &self.families, name)
    }

    /// The index of a family by name.
    pub fn family(&self, name: &str) -> Option<usize> {
        self.families.iter().position(|f| f.name == name)
    }

    /// The system's name as a title says it: `the harmonic rotor`; the file's name alone when
    /// the file gives none (`The claims of t1`, not `of the t1`), and the name alone when it
    /// starts with an article or a possessive of its own (`of my oscillator`, not `of the my
    /// oscillator`: [`crate::report::with_article`]).
    pub fn the_name(&self) -> String {
        let stem = std::path::Path::new(&self.source.origin).file_stem();
        match stem.is_some_and(|s| s.to_string_lossy() == self.name.as_str()) {
            true => self.name.clone(),
            false => crate::report::with_article(&self.name),
        }
    }

    /// Whether `name` is `i`, a variable or a named function of the system.
    pub(crate) fn declares(&self, name: &str) -> bool {
        name == "i" || self.system.vars().lookup(name).is_some() || self.system.get(name).is_ok()
    }

    /// A parsing scope that sees the first `families` families.
    fn scope(&self, families: usize) -> scope::Scope<'_> {
        scope::Scope::new(self, families)
    }
}
