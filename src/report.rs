//! The structured result of a job: sections of entries (prose, equations, checked claims,
//! bracket tables, proofs, towers, rank certificates), computed once and rendered by
//! [`crate::render`] in any format.
//!
//! Mathematics is kept as values ([`Expr`], [`brackets::BracketTable`],
//! [`brackets::RankCertificate`]) and as short strings in the paper's unicode notation
//! (`{L, G1} = −G2`); a renderer turns both into its own notation. Timings are the only
//! nondeterministic data and are kept apart (`seconds`). This file holds the report's shape,
//! `report/results.rs` each kind of result it holds.

use crate::render::tex::Names;
use crate::system_file::Caller;
use trigpoly::{Expr, Factored, Style};

mod results;

pub(crate) use results::{first_free, outcome_parts, PLACEHOLDERS, UNKNOWN_OUTCOME};
pub use results::{
    ClaimKind, ClaimOutcome, ClaimResult, Excerpt, Fact, OnLevelSet, ProofResult, RankResult,
    TableResult, TowerResult,
};

/// A whole report: a title, sections, and what its closing line summarises.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Report {
    /// The report's title, in markup: prose with mathematics between backticks.
    pub title: String,
    /// A subtitle (the paper it checks), possibly empty.
    pub subtitle: String,
    /// The sections, in order.
    pub sections: Vec<Section>,
    /// What the closing line says.
    pub summary: SummaryKind,
    /// Seconds spent computing the whole report.
    pub seconds: f64,
    /// Who the report was built for: its advice names the command line's options, or the
    /// library's for a program ([`Caller::Program`], the default).
    pub caller: Caller,
}

/// What the closing summary line of a report counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SummaryKind {
    /// The claims: `26 claims: 26 proved, 0 refuted`.
    Claims,
    /// The first tower of the report: `tower: 64 brackets … checked for 1 ≤ m, n ≤ 8, all hold`.
    Tower,
    /// Every check counted once, with expectations:
    /// `12 claims in 2 files: 10 proved, 2 refuted; all as expected`.
    Check {
        /// How many system files were checked: 0 for a system given otherwise (built in code,
        /// or the command line's `--system`), whose line names no file.
        files: usize,
    },
    /// No claim, a computation (a bracket, a table): `computed exactly (0.01 s)`.
    Computed,
    /// The claims of several searches, each section's its own, so that `I2` of two searches
    /// is two claims: `8 claims: 8 proved, 0 refuted`.
    Searches,
}

/// What a claim is expected to do: a system file marks deliberately false claims
/// `expect = "refuted"`; the paper's claims are all expected to be proved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Expect {
    /// The claim should be proved.
    #[default]
    Proved,
    /// The claim should be refuted (a deliberately false claim).
    Refuted,
}

// ALL and name() from one list, by the crate's variants_with_names (lib.rs).
variants_with_names! {
    Expect;
    /// Both expectations.
    ALL;
    /// `proved` or `refuted`.
    name;
    Proved => "proved",
    Refuted => "refuted",
}

/// Its [`Expect::name`], as a file writes it (`expect = "refuted"`).
///
/// ```
/// use superint::report::Expect;
///
/// assert_eq!(Expect::Refuted.to_string(), "refuted");
/// assert_eq!(format!("expected {}", Expect::default()), "expected proved");
/// ```
impl std::fmt::Display for Expect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// An expectation by its [`Expect::name`], as a file writes it.
///
/// ```
/// use superint::report::{Expect, UnknownExpect};
///
/// assert_eq!("refuted".parse(), Ok(Expect::Refuted));
/// assert_eq!(Expect::Proved.to_string().parse::<Expect>(), Ok(Expect::Proved));
/// let err = "true".parse::<Expect>().unwrap_err();
/// assert_eq!(err, UnknownExpect("true".into()));
/// assert_eq!(err.to_string(), "unknown expectation 'true' (expected proved or refuted)");
/// ```
impl std::str::FromStr for Expect {
    type Err = UnknownExpect;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Expect::ALL
            .into_iter()
            .find(|e| e.name() == s)
            .ok_or_else(|| UnknownExpect(s.to_string()))
    }
}

/// A name that is no [`Expect`]'s: the name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown expectation '{0}' (expected proved or refuted)")]
pub struct UnknownExpect(pub String);

/// A numbered section of a report: of the paper (2 to 5), or one a file checked, a search, a
/// closure (1, 2, …).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Section {
    /// The section's number: the paper's (2 to 5), or its place in the report.
    pub number: u32,
    /// The title, in markup: prose with mathematics between backticks.
    pub title: String,
    /// The system file the section is about, as named on the command line (`-` read as
    /// `<stdin>`), if it is about one.
    pub file: Option<String>,
    /// The entries, in order.
    pub entries: Vec<Entry>,
    /// The names of the section's system, as its expressions write them in LaTeX, for its
    /// statements, headers and titles (none for the paper's own texts).
    pub names: Names,
}

impl Section {
    /// The entries the prose formats show, in order (all but [`Entry::Data`]).
    pub fn shown_entries(&self) -> impl Iterator<Item = &Entry> {
        self.entries.iter().filter(|e| e.is_shown())
    }
}

/// One item of a section, computed.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Entry {
    /// A sub-heading, in markup.
    Heading(String),
    /// A paragraph in markup: plain prose with mathematics between backticks
    /// (`` the rotor adds `p_θ²/(2I)` ``).
    Text(String),
    /// Displayed equations `lhs = rhs`, such as a Hamiltonian or Hamilton's equations.
    Equations(Equations),
    /// A checked claim.
    Claim(ClaimResult),
    /// A table of brackets.
    Table(TableResult),
    /// A proof for all `m, n` (base facts computed, lemma, conclusion).
    Proof(ProofResult),
    /// A bounded tower of brackets checked by expansion.
    Tower(TowerResult),
    /// A certified Jacobian rank.
    Rank(RankResult),
    /// A text of the section's file read in a way that may not be what was meant (a name run
    /// together read as a product in doubt, [`crate::system_file::Warning`]): a paragraph
    /// `Warning: …` in the prose formats, and in the JSON's `warnings`.
    Warning(crate::system_file::Warning),
    /// What a search or a closure looked through and found, as data for the JSON; the prose
    /// formats say the same in the entries around it, and show nothing for this one.
    Data(Facts),
}

impl Entry {
    /// Whether the prose formats (text, Markdown, LaTeX) show the entry: all but [`Entry::Data`].
    pub fn is_shown(&self) -> bool {
        !matches!(self, Entry::Data(_))
    }
}

/// The facts of a discovery, as the JSON gives them (`searches`, `closures`).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Facts {
    /// Of `superint search`.
    Search(Box<SearchFacts>),
    /// Of `superint closure`.
    Closure(ClosureFacts),
    /// Of `superint search --find-values`.
    ExceptionalValues(Box<ExceptionalFacts>),
}

/// What `superint search --find-values` found: the values of one parameter where the space
/// holds more integrals than at a generic value.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ExceptionalFacts {
    /// The parameter solved for, in the file's names.
    pub parameter: String,
    /// The generic value searched at (no root of any determinant), the dimension there and
    /// the section of that search.
    pub generic: ValueFacts,
    /// The rational values with more integrals, increasing.
    pub values: Vec<ValueFacts>,
    /// The rational roots of the determinants where the search found no more integrals.
    pub not_exceptional: Vec<String>,
    /// The polynomial in the parameter whose roots, not rational, were not examined, in
    /// ASCII; `None` when none is left.
    pub unexamined: Option<String>,
    /// How many of its roots are real (none: no other real value has more integrals in the
    /// space); `None` when none is left.
    pub unexamined_real_roots: Option<usize>,
    /// The irrational and complex roots of the determinants shown to hold no more integrals
    /// in the space; `None` when none was.
    pub ruled_out: Option<RuledOutFacts>,
    /// The largest block's minor: its size and the degree of its determinant.
    pub largest_minor: (usize, usize),
    /// Whether `0`, a root of a determinant, was left out: `H` holds a negative power of the
    /// parameter and has no value there.
    pub zero_left_out: bool,
    /// The roots of the determinants left out because a declared denominator in the
    /// parameter is zero there (`H` has no value there), increasing, as fractions.
    pub denominator_roots_left_out: Vec<String>,
}

/// The roots, not rational, of the determinants at which every block keeps its generic rank,
/// so that none holds more integrals in the space.
#[derive(Clone, Debug)]
pub struct RuledOutFacts {
    /// The polynomial in the parameter whose roots they are, in ASCII.
    pub polynomial: String,
    /// How many roots (its degree).
    pub roots: usize,
    /// How many of them are real.
    pub real_roots: usize,
    /// The prime modulo which the blocks' minors were taken.
    pub prime: Option<u64>,
    /// How many blocks were settled by exact determinants over Q, where a root stayed common
    /// to their minors modulo [`RuledOutFacts::prime`], rather than modulo it alone.
    pub exact_blocks: usize,
}

/// A value of the parameter searched at, the dimension of the space of integrals there and
/// the report's section that shows that search.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ValueFacts {
    /// The value, as a fraction (`1/3`).
    pub value: String,
    /// The dimension of the space of integrals at it.
    pub dimension: usize,
    /// The section of the search at it.
    pub section: u32,
    /// The functional rank of the basis there, certified or a lower bound.
    pub functional_rank: brackets::BoundedRank,
}

impl ValueFacts {
    /// The facts of a value.
    pub fn new(
        value: String,
        dimension: usize,
        section: u32,
        functional_rank: brackets::BoundedRank,
    ) -> Self {
        ValueFacts {
            value,
            dimension,
            section,
            functional_rank,
        }
    }
}

impl ExceptionalFacts {
    /// The facts, as [`ExceptionalFacts`]' fields say (`unexamined` the polynomial and how
    /// many of its roots are real).
    pub fn new(
        parameter: String,
        generic: ValueFacts,
        values: Vec<ValueFacts>,
        not_exceptional: Vec<String>,
        unexamined: Option<(String, usize)>,
        largest_minor: (usize, usize),
        zero_left_out: bool,
    ) -> Self {
        let (unexamined, unexamined_real_roots) = unexamined.unzip();
        ExceptionalFacts {
            parameter,
            generic,
            values,
            not_exceptional,
            unexamined,
            unexamined_real_roots,
            ruled_out: None,
            largest_minor,
            zero_left_out,
            denominator_roots_left_out: Vec::new(),
        }
    }

    /// The facts with the roots of declared denominators left out (none unless given).
    #[must_use]
    pub fn with_denominator_roots_left_out(mut self, roots: Vec<String>) -> Self {
        self.denominator_roots_left_out = roots;
        self
    }

    /// The facts with the roots ruled out (`None`: none was).
    #[must_use]
    pub fn with_ruled_out(mut self, ruled_out: Option<RuledOutFacts>) -> Self {
        self.ruled_out = ruled_out;
        self
    }
}

/// How the linear algebra of a search or closure treated the parameters.
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct ParameterFacts {
    /// The parameters given values for the linear algebra, with them (`M`, `1`), in the
    /// file's names.
    pub fixed: Vec<(String, String)>,
    /// The parameters kept symbolic, in the file's names.
    pub symbolic: Vec<String>,
    /// The total degree in the symbolic parameters, when there are any.
    pub symbolic_degree: Option<u32>,
    /// The condition, as printed, if any.
    pub condition: Option<String>,
}

/// What `superint search` searched and found.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SearchFacts {
    /// The bounds of the space.
    pub space: brackets::search::SearchSpace,
    /// Its coordinates, momenta and angles, and the momenta of angles the condition fixes,
    /// left out (file names).
    pub coordinates: Vec<String>,
    /// See [`SearchFacts::coordinates`].
    pub momenta: Vec<String>,
    /// The Poisson variables of the space (file names).
    pub poisson: Vec<String>,
    /// See [`SearchFacts::coordinates`].
    pub angles: Vec<String>,
    /// See [`SearchFacts::coordinates`].
    pub left_out: Vec<String>,
    /// Those of [`SearchFacts::left_out`] that the condition sets to a function of the other
    /// phase variables (`M3` at `M3 = −(M1γ1 + M2γ2)/γ3`), not to a constant.
    pub left_out_as_functions: Vec<String>,
    /// The declared denominators that the condition gives a value (`κ + 1` at `κ = 1/2`),
    /// whose powers the space leaves out, as the file writes them.
    pub valued_denominators: Vec<String>,
    /// The parameters and the condition.
    pub parameters: ParameterFacts,
    /// The linear system: unknowns, equations, independent blocks, unknowns of the largest.
    pub unknowns: usize,
    /// See [`SearchFacts::unknowns`].
    pub equations: usize,
    /// See [`SearchFacts::unknowns`].
    pub blocks: usize,
    /// See [`SearchFacts::unknowns`].
    pub largest_block: usize,
    /// The dimension of the space of integrals.
    pub dimension: usize,
    /// The functional rank of its basis ([`brackets::search::basis_rank`]), certified (its
    /// upper bound named in JSON by [`brackets::UpperBound::name`]) or a lower bound; `None`
    /// for no integral or where it could not be certified.
    pub functional_rank: Option<brackets::BoundedRank>,
    /// `by_momenta_degree[j]`: the dimension of the integrals of momenta degree `≤ j`.
    pub by_momenta_degree: Vec<usize>,
    /// `counts[j][k]`: basis integrals of momenta degree exactly `j` and trigonometric order `k`.
    pub counts: Vec<Vec<usize>>,
    /// `by_poisson_degree[j]`: the dimension of the integrals of degree `≤ j` in the Poisson
    /// variables.
    pub by_poisson_degree: Vec<usize>,
    /// `poisson_counts[j][k]`: basis integrals of degree exactly `j` in the Poisson variables
    /// and trigonometric order `k`.
    pub poisson_counts: Vec<Vec<usize>>,
    /// How many basis integrals are proved for every value of the parameters (the others hold
    /// at the fixed values).
    pub for_every_value: usize,
    /// The ids of the integrals shown as claims (`I1`, …).
    pub shown: Vec<String>,
    /// With parameters kept symbolic, the labels of the basis integrals that generate all of
    /// them over the polynomials in those parameters (`I1`, `I3`, …), shown or not; `None`
    /// without symbolic parameters.
    pub generators: Option<Vec<String>>,
    /// With `--new-only`: the known integrals, the products formed, and the dimension they
    /// generate.
    pub new_only: Option<brackets::search::NewIntegrals>,
    /// With `--on`: the level set searched on.
    pub level_set: Option<LevelSetFacts>,
}

/// The level set a search was restricted to (`superint search --on`), for JSON.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct LevelSetFacts {
    /// As given (`M1*gamma1 + M2*gamma2 + M3*gamma3 = 0`).
    pub text: String,
    /// `P = EXPR − VALUE`, in ASCII.
    pub polynomial: String,
    /// `LM(P)` in the division's order, in ASCII.
    pub leading_monomial: String,
    /// The space's unknowns it divides, left out.
    pub left_out: usize,
    /// A function of the space and its normal form, outside the space, in ASCII, where one
    /// is ([`brackets::search::SearchedLevel::normal_form_outside`]).
    pub normal_form_outside: Option<(String, String)>,
}

/// What `superint closure` found.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ClosureFacts {
    /// The generators, in the file's names.
    pub generators: Vec<String>,
    /// The degree bound.
    pub degree: u32,
    /// The monomials of degree `≤ degree` in the generators, and the dimension of their span.
    pub monomials: usize,
    /// See [`ClosureFacts::monomials`].
    pub rank: usize,
    /// The parameters and the condition.
    pub parameters: ParameterFacts,
    /// The pairs of generators whose bracket is no polynomial of the degree in them.
    pub outside: Vec<(String, String)>,
    /// How many brackets and relations hold at the fixed values only.
    pub unlifted: usize,
    /// The ids of the brackets (`B1`, …) and of the relations (`R1`, …) shown as claims.
    pub brackets: Vec<String>,
    /// See [`ClosureFacts::brackets`].
    pub relations: Vec<String>,
}

/// Displayed equations.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Equations {
    /// What the equations are (`Hamilton's equations`), possibly empty: prose, formulas
    /// between backticks (`` at `p_θ = Iω` ``).
    pub caption: String,
    /// The lines.
    pub lines: Vec<Equation>,
    /// Whether the flow of `H` keeps the condition the lines were restricted to, where that
    /// was asked (a bracket at a condition, `bracket --when`): a bracket that vanishes on a
    /// surface the flow leaves is no conservation law.
    pub flow: Option<FlowKept>,
}

impl Equations {
    /// Equations under `caption` (possibly empty), of a surface whose flow is not asked about.
    pub fn new(caption: String, lines: Vec<Equation>) -> Equations {
        Equations {
            caption,
            lines,
            flow: None,
        }
    }
}

/// Whether the flow of `H` keeps the surface of a condition ([`Equations::flow`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum FlowKept {
    /// The flow keeps it: `{v − value, H}` vanishes there for every variable it sets.
    Kept,
    /// The flow leaves it: the note that says so, in markup (`` `{x, H} = p_x/M` ``).
    Left(String),
    /// Whether the flow keeps it was not decided (a limit stopped the check): the note that
    /// says so, with the limit's message, in markup.
    Unchecked(String),
}

impl FlowKept {
    /// The note, where the flow leaves the surface or where that was not decided.
    pub fn note(&self) -> Option<&str> {
        match self {
            FlowKept::Kept => None,
            FlowKept::Left(note) | FlowKept::Unchecked(note) => Some(note),
        }
    }

    /// Whether the flow keeps the surface: `None` where that was not decided.
    pub fn kept(&self) -> Option<bool> {
        match self {
            FlowKept::Kept => Some(true),
            FlowKept::Left(_) => Some(false),
            FlowKept::Unchecked(_) => None,
        }
    }
}

/// One displayed equation `lhs = rhs`, and the right side again in named functions where
/// that is known (`= −2 H L/M`).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Equation {
    /// The left side in the paper's unicode notation (`ṗ_x`, `H`, `P_{1,1}`).
    pub lhs: String,
    /// The right side.
    pub rhs: Expr,
    /// The right side as a polynomial in `H` and a system's named functions, proved for
    /// every value of the parameters
    /// ([`LoadedSystem::written_in_functions`](crate::system_file::LoadedSystem::written_in_functions)),
    /// or at the fixed values alone where [`Equation::in_functions_holds_at`] says so.
    pub in_functions: Option<Expr>,
    /// Where `in_functions` holds when that is only at the fixed parameter values (a
    /// search's integral not lifted back to the parameters, or its amplitude): the search's
    /// condition, where it has one, then those values, as `--when` reads it back and as the
    /// integral's claim's condition is written (`p_theta = 1, M = 1, omega = 1, I = 1`);
    /// `None` where it holds at the condition for every value, as a restatement an integral
    /// not lifted is lifted through does (`2 H`, an integral for every value).
    pub in_functions_holds_at: Option<String>,
    /// The right side as the factor its terms share times what is left, `F(x p_x + y p_y)/M`
    /// ([`Expr::factored`]), where `bracket` or `expand` shows it: for a result with no form in
    /// the named functions.
    pub factored: Option<Factored>,
}

impl Equation {
    /// `lhs = rhs`.
    pub fn new(lhs: &str, rhs: Expr) -> Self {
        Equation {
            lhs: lhs.to_string(),
            rhs,
            in_functions: None,
            in_functions_holds_at: None,
            factored: None,
        }
    }

    /// The right side restated below it in the notation of `style`: in the named functions,
    /// or else as its common factor times the rest (the two are never both set).
    pub fn restated(&self, style: Style) -> Option<String> {
        restated(self.in_functions.as_ref(), self.factored.as_ref(), style)
    }
}

/// `in_functions` in the notation of `style`, or else `factored`: how an equation's right side
/// or a residual is restated below it.
pub(crate) fn restated(
    in_functions: Option<&Expr>,
    factored: Option<&Factored>,
    style: Style,
) -> Option<String> {
    match (in_functions, factored) {
        (Some(e), _) => Some(written_in_functions(e, style)),
        (None, Some(f)) => Some(f.render(style)),
        (None, None) => None,
    }
}

/// A polynomial in named functions in the notation of `style`, as the paper writes one: with
/// the factor its terms share in front of the parentheses and the functions in it after them,
/// `−(2ω − 3Ω) Q_{2,3}` for `−2ω Q_{2,3} + 3Ω Q_{2,3}`, where the factor has a function or a
/// parameter in it and what is left is short ([`Factored::render_functions_last`]); else term
/// by term (a number alone in front, `8(32ω²αβ H_x + …)`, says little about an algebra).
///
/// The factor is what every term shares, a number times a monomial in the parameters and the
/// functions ([`Expr::factored`]); no factor of several terms is looked for. So one bracket may
/// read two ways in two closures, each by this one rule and each right: the 3:5 rotor's
/// `{Re A, Im A}` is `1920M⁸ω(3 H_x − 5 H_y) H_x⁴ H_y²` among `H_x, H_y, Re A, Im A`, and at
/// `p_θ = Iω` among `H_x, H_y, Re K, Im K, Re A, Im A` it is
/// `30M²ω(3 H_x (Re K)⁴ + 6 H_x (Re K)² (Im K)² + … − 5 H_y (Im K)⁴)`. There
/// `8M³ H_x² H_y = |K|²`, the generators' polynomials write the bracket in many ways, and the
/// closure writes the one its linear algebra finds, through `K` (at degree 6 the first form,
/// whose `H_x⁵ H_y²` is of degree 7, is out of reach), whose terms share `30M²ω` alone: what
/// else they share, `(3 H_x − 5 H_y)((Re K)² + (Im K)²)²`, is no monomial.
pub(crate) fn written_in_functions(e: &Expr, style: Style) -> String {
    match factored_in_functions(e) {
        Some(f) => f.render_functions_last(style),
        None => e.render(style),
    }
}

/// The factored form [`written_in_functions`] writes a polynomial in named functions in,
/// where it has one: a factor with a function or a parameter in it ([`shown_factored`]).
pub(crate) fn factored_in_functions(e: &Expr) -> Option<Factored> {
    shown_factored(e).filter(|f| !f.is_numeric())
}

/// The most terms of what is left after the common factor that a factored form shows
/// ([`shown_factored`]): it restates a short result, which it makes read like the paper
/// (`2F(x p_x + y p_y)/M`); after a long one, it would repeat lines of terms.
const FACTORED_TERMS: usize = 8;

/// `e` as the factor its terms share times what is left ([`Expr::factored`]), where that
/// is at most [`FACTORED_TERMS`] terms: the form `bracket`, `expand` and a refuted claim's
/// residual show under the expanded one.
pub(crate) fn shown_factored(e: &Expr) -> Option<Factored> {
    // A sum in cos θ and sin θ has about twice as many terms in e^{±iθ}.
    if e.len() > 2 * FACTORED_TERMS {
        return None;
    }
    // Where the printer already writes it so (the terms over one denominator atom), it is
    // not repeated.
    e.factored()
        .filter(|f| f.terms() <= FACTORED_TERMS && f.to_string() != e.to_string())
}

/// A count and its noun, singular for one: `1 claim`, `2 claims`, `0 claims`, `3 entries` (a
/// consonant's `y` becomes `ies`). Every count the reports and the command line print in
/// words goes through it.
///
/// ```
/// use superint::report::counted;
///
/// assert_eq!(counted(1, "entry"), "1 entry");
/// assert_eq!([counted(3, "entry"), counted(2, "key"), counted(0, "claim")], ["3 entries", "2 keys", "0 claims"]);
/// ```
pub fn counted(n: impl std::fmt::Display, noun: &str) -> String {
    let n = n.to_string();
    let stem = noun
        .strip_suffix('y')
        .filter(|s| !s.ends_with(['a', 'e', 'o', 'u']));
    match (n.as_str(), stem) {
        ("1", _) => format!("1 {noun}"),
        (_, Some(stem)) => format!("{n} {stem}ies"),
        (_, None) => format!("{n} {noun}s"),
    }
}

/// Items as prose lists them: `a`, `a and b`, `a, b and c`.
///
/// ```
/// use superint::report::listed;
///
/// let items = |s: &[&str]| s.iter().map(|i| i.to_string()).collect::<Vec<_>>();
/// assert_eq!(listed(&items(&["1", "4"])), "1 and 4");
/// assert_eq!(listed(&items(&["1", "2", "4"])), "1, 2 and 4");
/// ```
pub fn listed(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// A system's name as a title says it after `of` or `for`: `the harmonic rotor`, but the name
/// alone when it starts with an article or a possessive of its own (`my oscillator`, not `the
/// my oscillator`).
///
/// ```
/// use superint::report::with_article;
///
/// assert_eq!(with_article("harmonic rotor"), "the harmonic rotor");
/// assert_eq!([with_article("My oscillator"), with_article("the Kepler problem")], ["My oscillator", "the Kepler problem"]);
/// ```
pub fn with_article(name: &str) -> String {
    const DETERMINERS: [&str; 11] = [
        "the", "a", "an", "this", "that", "my", "our", "your", "his", "her", "their",
    ];
    let first = name.split_whitespace().next().unwrap_or("");
    match DETERMINERS.iter().any(|d| first.eq_ignore_ascii_case(d)) {
        true => name.to_string(),
        false => format!("the {name}"),
    }
}

impl Report {
    /// The report with every claim's residual and every table's entry of more than
    /// `monomials` monomials outside the angles cut to the terms of its first `monomials`
    /// ([`ClaimResult::excerpt_residual`], [`TableResult::excerpt_entries`]), each
    /// [`Excerpt`] for the report's caller; the report itself when none is that long.
    pub fn excerpted(&self, monomials: usize) -> std::borrow::Cow<'_, Report> {
        let long = |e: &Entry| match e {
            Entry::Claim(c) => c.is_longer_than(monomials),
            Entry::Table(t) => t.is_longer_than(monomials),
            _ => false,
        };
        if !self.sections.iter().flat_map(|s| &s.entries).any(long) {
            return std::borrow::Cow::Borrowed(self);
        }
        let mut report = self.clone();
        let caller = report.caller;
        for entry in report.sections.iter_mut().flat_map(|s| &mut s.entries) {
            match entry {
                Entry::Claim(c) => {
                    c.excerpt_residual(monomials);
                    c.excerpt.iter_mut().for_each(|e| e.caller = caller);
                }
                Entry::Table(t) => {
                    t.excerpt_entries(monomials);
                    t.excerpts.values_mut().for_each(|e| e.caller = caller);
                }
                _ => {}
            }
        }
        std::borrow::Cow::Owned(report)
    }

    /// A report of one section of checked claims, titled `title`, whose summary counts them:
    /// what a program that checks its own claims prints, in any format.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let claims = [
    ///     Claim::new("su2", "{L, G1} = −G2", rotor.parse("{L, G1}")?, rotor.parse("-G2")?),
    ///     Claim::new("sign", "{L, G1} = G2", rotor.parse("{L, G1}")?, rotor.parse("G2")?),
    /// ];
    /// let results = claims.iter().map(|c| c.check().map(ClaimResult::from));
    /// let report = Report::of_claims("My claims", results.collect::<Result<_, _>>()?);
    /// let text = render(&report, Format::Text, &RenderOptions::reproducible());
    /// assert!(text.contains("[su2 proved]") && text.contains("[sign REFUTED]"));
    /// assert!(text.contains("residual lhs − rhs = −p_x²/M + p_y²/M − Mω²x² + Mω²y²"));
    /// assert!(text.ends_with("2 claims: 1 proved, 1 refuted (2 exact checks)\n"));
    /// # Ok::<(), EngineError>(())
    /// ```
    pub fn of_claims(title: &str, claims: Vec<ClaimResult>) -> Report {
        let seconds = claims.iter().map(|c| c.seconds).sum();
        Report {
            title: title.to_string(),
            subtitle: String::new(),
            sections: vec![Section {
                number: 1,
                title: title.to_string(),
                file: None,
                entries: claims.into_iter().map(Entry::Claim).collect(),
                names: Names::default(),
            }],
            summary: SummaryKind::Claims,
            seconds,
            caller: Caller::Program,
        }
    }

    /// The same report, built for `caller`: the command line renders the reports of the
    /// paper `with_caller(Caller::CommandLine)`, so that a long residual's note names
    /// `--full-expressions`. What a report already says is not rewritten.
    #[must_use]
    pub fn with_caller(mut self, caller: Caller) -> Report {
        self.caller = caller;
        self
    }

    /// The same report with every section that names no file about `file`: what a command
    /// that ran on one system file reports.
    #[must_use]
    pub fn about_file(mut self, file: &str) -> Report {
        for s in &mut self.sections {
            s.file.get_or_insert_with(|| file.to_string());
        }
        self
    }

    /// Every checked claim, in order: plain claims and those settled by tables, proofs, towers
    /// and ranks.
    pub fn claims(&self) -> Vec<&ClaimResult> {
        self.claims_by_section()
            .into_iter()
            .map(|(_, c)| c)
            .collect()
    }

    /// Every checked claim, in order, with the number of its section.
    fn claims_by_section(&self) -> Vec<(u32, &ClaimResult)> {
        let mut out = Vec::new();
        for s in &self.sections {
            for e in &s.entries {
                match e {
                    Entry::Claim(c) => out.push((s.number, c)),
                    Entry::Proof(p) => out.extend(p.claims.iter().map(|c| (s.number, c))),
                    Entry::Tower(t) => out.push((s.number, &t.claim)),
                    Entry::Rank(r) => out.push((s.number, &r.claim)),
                    _ => {}
                }
            }
        }
        out
    }

    /// The claim ids in order of first appearance, each with whether all its checks were
    /// proved. The paper's ids (`C12`) gather checks across the report; the ids of a check of
    /// system files are their files' own, so the same id in two files is two claims, and so
    /// are those of the searches of `search --find-values` ([`SummaryKind::Searches`]).
    pub fn claim_ids(&self) -> Vec<(String, bool)> {
        self.claim_outcomes()
            .into_iter()
            .map(|(id, outcome)| (id, outcome == ClaimOutcome::Proved))
            .collect()
    }

    /// The claim ids in order of first appearance, as [`Report::claim_ids`], each with the
    /// outcome of its checks: refuted when one was, else undecided when one was, else proved.
    pub fn claim_outcomes(&self) -> Vec<(String, ClaimOutcome)> {
        let per_section = matches!(
            self.summary,
            SummaryKind::Check { .. } | SummaryKind::Searches
        );
        let mut out: Vec<(u32, String, ClaimOutcome)> = Vec::new();
        for (section, c) in self.claims_by_section() {
            let section = if per_section { section } else { 0 };
            match out
                .iter_mut()
                .find(|(s, id, _)| *s == section && *id == c.id)
            {
                Some((_, _, outcome)) => *outcome = (*outcome).max(c.outcome()),
                None => out.push((section, c.id.clone(), c.outcome())),
            }
        }
        out.into_iter().map(|(_, id, o)| (id, o)).collect()
    }

    /// Whether every check was proved.
    pub fn all_proved(&self) -> bool {
        self.claims().iter().all(|c| c.proved)
    }

    /// Whether every check met its expectation (see [`Expect`]).
    pub fn all_as_expected(&self) -> bool {
        self.claims().iter().all(|c| c.meets_expectation())
    }

    /// Every bracket table of the report, in order.
    pub fn tables(&self) -> impl Iterator<Item = &TableResult> {
        (self.sections.iter().flat_map(|s| &s.entries)).filter_map(|e| match e {
            Entry::Table(t) => Some(t),
            _ => None,
        })
    }

    /// Every tower of the report, in order: a tower job on a system file has one for each
    /// family it checked, each in its own section.
    ///
    /// ```
    /// use superint::system_file::{family_tower_report, load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// let report = family_tower_report(&rotor, None, 2, None)?;
    /// let towers: Vec<_> = report.towers().map(|t| (t.claim.id.as_str(), t.checked)).collect();
    /// assert_eq!(towers, [("K-tower", 4), ("Kbar-tower", 4)]);
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn towers(&self) -> impl Iterator<Item = &TowerResult> {
        (self.sections.iter().flat_map(|s| &s.entries)).filter_map(|e| match e {
            Entry::Tower(t) => Some(t),
            _ => None,
        })
    }

    /// The first tower of the report ([`Report::towers`]), if any.
    pub fn tower(&self) -> Option<&TowerResult> {
        self.towers().next()
    }

    /// Every proof of the report, in order: a tower job's proofs for all `m, n`, one per
    /// family that is a product of powers.
    ///
    /// ```
    /// use superint::system_file::{family_tower_report, load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// let report = family_tower_report(&rotor, Some("Kbar,K"), 2, None)?;
    /// let proofs: Vec<_> = report.proofs().map(|p| p.facts[0].statement.as_str()).collect();
    /// assert_eq!(proofs, ["{Z̄, H} = −iω Z̄", "{Z, H} = iω Z"]);
    /// assert!(report.proofs().all(|p| p.holds()));
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn proofs(&self) -> impl Iterator<Item = &ProofResult> {
        (self.sections.iter().flat_map(|s| &s.entries)).filter_map(|e| match e {
            Entry::Proof(p) => Some(p),
            _ => None,
        })
    }

    /// The first proof in the report ([`Report::proofs`]; a tower job's proof for all
    /// `m, n`), if any.
    ///
    /// ```
    /// use superint::system_file::{family_tower_report, load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// let report = family_tower_report(&rotor, Some("K"), 2, None)?;
    /// let proof = report.proof().expect("K_{m,n} = Z^m e^{−inθ} is a product of powers");
    /// assert!(proof.holds());
    /// assert_eq!(proof.facts[0].statement, "{Z, H} = iω Z");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn proof(&self) -> Option<&ProofResult> {
        self.proofs().next()
    }

    /// The closing line: `26 claims: 26 proved, 0 refuted (93 exact checks, 0.41 s)`, or for a
    /// tower job `tower: 64 brackets {K_{m,n}, H} = … checked for 1 ≤ m, n ≤ 8, all hold (0.04 s)`.
    /// `timings` adds the seconds.
    pub fn summary_line(&self, timings: bool) -> String {
        match (self.summary, self.tower()) {
            (SummaryKind::Tower, Some(t)) => tower_summary(t, timings),
            (SummaryKind::Computed, _) => self.computed_summary(timings),
            (SummaryKind::Check { files }, _) => self.check_summary(files, timings),
            _ => self.claims_summary(timings),
        }
    }

    /// The closing line of a computation: `computed exactly (0.01 s)`.
    fn computed_summary(&self, timings: bool) -> String {
        // A table's entries that a limit stopped are no part of what was computed.
        let what = match self.tables().map(|t| t.undecided().len()).sum::<usize>() {
            0 => "computed exactly".to_string(),
            n => format!(
                "computed exactly, but for {} stopped at a limit",
                counted(n, "entry")
            ),
        };
        format!("{what}{}", seconds_in_parentheses(self.seconds, timings))
    }

    /// The closing line of a check of `files` system files:
    /// `12 claims in 2 files: 10 proved, 2 refuted; all as expected` (`1 claim: …` of a
    /// system that is no file).
    fn check_summary(&self, files: usize, timings: bool) -> String {
        let claims = self.claims_by_section();
        let outcomes = |o: ClaimOutcome| claims.iter().filter(|(_, c)| c.outcome() == o).count();
        let proved = outcomes(ClaimOutcome::Proved);
        let refuted = outcomes(ClaimOutcome::Refuted);
        // With several files, an id says where it is: `main (section 2)`; an id that several
        // claims of a section share, which of them: `A ({x, H} = p_x + 1)`, or
        // `A ({x, H} = p_x + 1; section 2)`.
        let shared =
            |s: u32, id: &str| claims.iter().filter(|(t, c)| *t == s && c.id == id).count() > 1;
        let named = |(s, c): &(u32, &ClaimResult)| {
            let mut notes = Vec::new();
            if shared(*s, &c.id) {
                notes.push(brief_statement(&c.statement));
            }
            if files > 1 {
                notes.push(format!("section {s}"));
            }
            match notes.is_empty() {
                true => c.id.clone(),
                false => format!("{} ({})", c.id, notes.join("; ")),
            }
        };
        // A claim a limit stopped is neither as expected nor against it: it is named apart.
        let unexpected: Vec<String> = claims
            .iter()
            .filter(|(_, c)| c.undecided.is_none() && !c.meets_expectation())
            .map(named)
            .collect();
        let stopped: Vec<String> = claims
            .iter()
            .filter(|(_, c)| c.undecided.is_some())
            .map(named)
            .collect();
        let mut verdict = match (unexpected.is_empty(), stopped.is_empty()) {
            (true, true) => "all as expected".to_string(),
            (true, false) => "the decided ones as expected".to_string(),
            (false, _) => format!(
                "{} NOT as expected: {}",
                unexpected.len(),
                unexpected.join(", ")
            ),
        };
        if !stopped.is_empty() {
            verdict.push_str(&format!("; undecided: {}", stopped.join(", ")));
        }
        let files = match files {
            0 => String::new(),
            n => format!(" in {}", counted(n, "file")),
        };
        let count = counted(claims.len(), "claim");
        let undecided = match outcomes(ClaimOutcome::Undecided) {
            0 => String::new(),
            n => format!(", {n} undecided"),
        };
        format!(
            "{count}{files}: {proved} proved, {refuted} refuted{undecided}; {verdict}{}",
            seconds_in_parentheses(self.seconds, timings)
        )
    }

    /// The closing line of the claims: `26 claims: 26 proved, 0 refuted (93 exact checks)`;
    /// that of a computation where there are none (a closure of commuting generators, whose
    /// zero brackets and lack of relations make no claim), rather than `0 claims: 0 proved`.
    fn claims_summary(&self, timings: bool) -> String {
        if self.claims().is_empty() {
            return self.computed_summary(timings);
        }
        let time = if timings {
            format!(", {:.2} s", self.seconds)
        } else {
            String::new()
        };
        let ids = self.claim_ids();
        let proved = ids.iter().filter(|(_, ok)| *ok).count();
        let checks = self.claims().len();
        format!(
            "{}: {proved} proved, {} refuted ({}{time})",
            counted(ids.len(), "claim"),
            ids.len() - proved,
            counted(checks, "exact check"),
        )
    }
}

/// The closing line of a tower job:
/// `tower: 64 brackets {K_{m,n}, H} = … checked for 1 ≤ m, n ≤ 8, all hold`.
fn tower_summary(t: &TowerResult, timings: bool) -> String {
    let verdict = if t.failures.is_empty() {
        "all hold".to_string()
    } else {
        format!("{} FAIL", t.failures.len())
    };
    let k = &t.family;
    format!(
        "tower: {} {{{k}, H}} = i(mω − nΩ) {k} checked for 1 ≤ m, n ≤ {}, {verdict}{}",
        counted(t.checked, "bracket"),
        t.max,
        seconds_in_parentheses(t.claim.seconds, timings)
    )
}

/// A claim's statement as a closing line names it: whole, or past 60 characters its first 50
/// and an ellipsis.
fn brief_statement(statement: &str) -> String {
    match statement.chars().count() > 60 {
        true => format!("{}…", statement.chars().take(50).collect::<String>()),
        false => statement.to_string(),
    }
}

/// ` (0.41 s)` when `timings`, else nothing: the seconds a closing line ends with.
fn seconds_in_parentheses(seconds: f64, timings: bool) -> String {
    if timings {
        format!(" ({seconds:.2} s)")
    } else {
        String::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `ALL` has every expectation once, in the order they are declared (its list is
    /// `name`'s, whose match covers every one), and each reads back from its name.
    #[test]
    fn every_expectation_is_listed_in_order_and_reads_back_from_its_name() {
        for (i, expect) in Expect::ALL.into_iter().enumerate() {
            assert_eq!(expect as usize, i, "{expect:?}");
            assert_eq!(expect.name().parse(), Ok(expect));
        }
    }
}
