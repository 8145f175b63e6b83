//! The structured result of a job: sections of entries (prose, equations, checked claims,
//! bracket tables, proofs, towers, rank certificates), computed once and rendered by
//! [`crate::render`] in any format.
//!
//! Mathematics is kept as values ([`Expr`], [`BracketTable`], [`RankCertificate`]) and as short
//! strings in the paper's unicode notation (`{L, G1} = −G2`); a renderer turns both into its
//! own notation. Timings are the only nondeterministic data and are kept apart (`seconds`).

use std::collections::BTreeMap;

use brackets::{BracketTable, RankCertificate, System};
use trigpoly::{Expr, Style, Var, Vars};

/// A whole report: a title, sections, and what its closing line summarises.
#[derive(Clone, Debug)]
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
}

/// What the closing summary line of a report counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SummaryKind {
    /// The claims: `26 claims: 26 proved, 0 refuted`.
    Claims,
    /// The first tower of the report: `tower: 64 brackets … checked for 1 ≤ m, n ≤ 8, all hold`.
    Tower,
    /// Every check counted once, with expectations:
    /// `12 claims in 2 files: 10 proved, 2 refuted; all as expected`.
    Check {
        /// How many system files were checked.
        files: usize,
    },
    /// No claim, a computation (a bracket, a table): `computed exactly (0.01 s)`.
    Computed,
}

/// What a claim is expected to do: a system file marks deliberately false claims
/// `expect = "refuted"`; the paper's claims are all expected to be proved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Expect {
    /// The claim should be proved.
    #[default]
    Proved,
    /// The claim should be refuted (a deliberately false claim).
    Refuted,
}

impl Expect {
    /// `proved` or `refuted`.
    pub fn name(self) -> &'static str {
        match self {
            Expect::Proved => "proved",
            Expect::Refuted => "refuted",
        }
    }
}

/// A numbered section of a report: of the paper (2 to 5), or one a file checked, a search, a
/// closure (1, 2, …).
#[derive(Clone, Debug)]
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
}

impl Section {
    /// The entries the prose formats show, in order (all but [`Entry::Data`]).
    pub fn shown_entries(&self) -> impl Iterator<Item = &Entry> {
        self.entries.iter().filter(|e| e.is_shown())
    }
}

/// One item of a section, computed.
#[derive(Clone, Debug)]
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
pub enum Facts {
    /// Of `superint search`.
    Search(Box<SearchFacts>),
    /// Of `superint closure`.
    Closure(ClosureFacts),
}

/// How the linear algebra of a search or closure treated the parameters.
#[derive(Clone, Debug, Default)]
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
    /// With `--new-only`: the known integrals, the products formed, and the dimension they
    /// generate.
    pub new_only: Option<brackets::search::NewIntegrals>,
}

/// What `superint closure` found.
#[derive(Clone, Debug)]
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
pub struct Equations {
    /// What the equations are (`Hamilton's equations`), possibly empty.
    pub caption: String,
    /// The lines.
    pub lines: Vec<Equation>,
}

/// One displayed equation `lhs = rhs`.
#[derive(Clone, Debug)]
pub struct Equation {
    /// The left side in the paper's unicode notation (`ṗ_x`, `H`, `P_{1,1}`).
    pub lhs: String,
    /// The right side.
    pub rhs: Expr,
}

impl Equation {
    /// `lhs = rhs`.
    pub fn new(lhs: &str, rhs: Expr) -> Self {
        Equation {
            lhs: lhs.to_string(),
            rhs,
        }
    }
}

/// Whether a claim asserts an identity or that something does not vanish.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClaimKind {
    /// `lhs = rhs` (under the condition): proved when `lhs − rhs` is exactly zero.
    Identity,
    /// `lhs ≠ rhs` (under the condition): proved when `lhs − rhs` is not zero; the nonzero
    /// difference is the witness.
    Nonvanishing,
}

/// What a check of a claim found. Ordered so that the outcome of several checks of one claim
/// is the greatest: one refuted check refutes it, else one undecided leaves it undecided.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum ClaimOutcome {
    /// `lhs − rhs` is exactly zero (or, for a nonvanishing claim, is not).
    Proved,
    /// The check stopped at a limit: neither proved nor refuted.
    Undecided,
    /// Not proved: the residual says why.
    Refuted,
}

impl ClaimOutcome {
    /// `proved`, `undecided` or `refuted`, as JSON gives it.
    pub fn name(self) -> &'static str {
        match self {
            ClaimOutcome::Proved => "proved",
            ClaimOutcome::Undecided => "undecided",
            ClaimOutcome::Refuted => "refuted",
        }
    }
}

/// A claim of the paper, checked.
#[derive(Clone, Debug)]
pub struct ClaimResult {
    /// The claim's id (`C09`).
    pub id: String,
    /// How the claim reads, in the paper's unicode notation (`{L, G1} = −G2`).
    pub statement: String,
    /// The claim as text that `superint` reads back in its system file: as the file writes
    /// it, or a found bracket or relation in the file's names (`{L, Ax} = Ay`); `None` for
    /// the paper's claims and for those a tower or a proof decides.
    pub written: Option<String>,
    /// Where it is claimed to hold (`p_θ = Iω`), if it is conditional.
    pub condition: Option<String>,
    /// The condition as text that superint reads back (`p_theta = I*omega`), where the claim
    /// has such a text ([`ClaimResult::written`]).
    pub condition_ascii: Option<String>,
    /// Identity or nonvanishing.
    pub kind: ClaimKind,
    /// Whether the claim was proved.
    pub proved: bool,
    /// What the claim is expected to do (proved, unless it is marked as deliberately false).
    pub expect: Expect,
    /// For a refuted identity, the nonzero residual `lhs − rhs` in normal form.
    pub residual: Option<Expr>,
    /// For a proved nonvanishing claim, the nonzero value that proves it.
    pub witness: Option<Expr>,
    /// For a claim proved or refuted by a derived check (a tower, a proof, a rank), what failed.
    pub note: Option<String>,
    /// For a claim whose check stopped at a limit (of terms, of term products, of degree), the
    /// limit's message: the claim is neither proved nor refuted ([`ClaimResult::undecided`]).
    pub undecided: Option<String>,
    /// When the residual above is a part of a longer one ([`ClaimResult::excerpt_residual`]): how
    /// much of it is shown.
    pub excerpt: Option<Excerpt>,
    /// Seconds spent checking it.
    pub seconds: f64,
}

/// How much of a long expression (a refuted claim's residual, a table's entry) is shown: every
/// term of its first `shown` monomials outside the angles ([`trigpoly::Poly::leading_part`]),
/// of `monomials` in all.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Excerpt {
    /// The monomials whose terms are shown.
    pub shown: usize,
    /// The monomials of the whole.
    pub monomials: usize,
    /// Whether an angle appears in the whole (else its monomials are its terms).
    pub angles: bool,
}

impl Excerpt {
    /// What the prose formats say under the part: `shown: the terms of its first 100 of
    /// 254321 monomials outside the angles; --full-expressions shows all` (`its first 100 of
    /// 254321 terms` without angles).
    pub fn describe(&self) -> String {
        let (shown, all) = (self.shown, self.monomials);
        let part = match self.angles {
            true => format!("the terms of its first {shown} of {all} monomials outside the angles"),
            false => format!("its first {shown} of {all} terms"),
        };
        format!("shown: {part}; --full-expressions shows all")
    }

    /// Cuts `e` to the terms of its first `monomials` monomials outside the angles if it has
    /// more; how much of it is then shown.
    fn cut(e: &mut Expr, monomials: usize) -> Option<Excerpt> {
        if e.len() <= monomials {
            return None;
        }
        let (part, all) = e.leading_part(monomials);
        if all <= monomials {
            return None;
        }
        let excerpt = Excerpt {
            shown: monomials,
            monomials: all,
            angles: e.has_angles(),
        };
        *e = part;
        Some(excerpt)
    }
}

impl ClaimResult {
    /// A claim decided by a derived check (tower, proof, rank) rather than one residual.
    pub fn derived(id: &str, statement: &str, proved: bool, note: Option<String>) -> Self {
        ClaimResult {
            id: id.to_string(),
            statement: statement.to_string(),
            written: None,
            condition: None,
            condition_ascii: None,
            kind: ClaimKind::Identity,
            proved,
            expect: Expect::Proved,
            residual: None,
            witness: None,
            note,
            undecided: None,
            excerpt: None,
            seconds: 0.0,
        }
    }

    /// A claim whose check stopped at a limit, with the limit's message: neither proved nor
    /// refuted, and so not as expected, whatever it was expected to be.
    pub fn undecided(id: &str, statement: &str, message: &str) -> Self {
        ClaimResult {
            undecided: Some(message.to_string()),
            ..ClaimResult::derived(id, statement, false, None)
        }
    }

    /// The same result with a timing.
    pub fn timed(mut self, seconds: f64) -> Self {
        self.seconds = seconds;
        self
    }

    /// The same result with its text as a system file writes it.
    pub fn written(mut self, text: &str) -> Self {
        self.written = Some(text.to_string());
        self
    }

    /// The same result under a condition, as printed and as superint reads it back.
    pub fn at(mut self, condition: Option<(String, String)>) -> Self {
        (self.condition, self.condition_ascii) = condition.unzip();
        self
    }

    /// The same result with an expectation.
    pub fn expecting(mut self, expect: Expect) -> Self {
        self.expect = expect;
        self
    }

    /// Whether the outcome is the expected one: proved when expected proved, refuted when
    /// expected refuted.
    pub fn meets_expectation(&self) -> bool {
        self.undecided.is_none() && self.proved == (self.expect == Expect::Proved)
    }

    /// Proved, refuted, or undecided (stopped at a limit).
    pub fn outcome(&self) -> ClaimOutcome {
        match (self.proved, &self.undecided) {
            (_, Some(_)) => ClaimOutcome::Undecided,
            (true, None) => ClaimOutcome::Proved,
            (false, None) => ClaimOutcome::Refuted,
        }
    }

    /// Cuts a residual of more than `monomials` monomials outside the angles to the terms of
    /// its first `monomials` ([`Excerpt`]): a residual of millions of terms, which would print
    /// a gigabyte, shows its leading terms and its size.
    pub fn excerpt_residual(&mut self, monomials: usize) {
        if let Some(e) = self.residual.as_mut() {
            self.excerpt = Excerpt::cut(e, monomials);
        }
    }

    /// Whether [`ClaimResult::excerpt_residual`] may cut it: its residual has more than `monomials`
    /// terms.
    fn is_longer_than(&self, monomials: usize) -> bool {
        self.residual.as_ref().is_some_and(|e| e.len() > monomials)
    }
}

/// An identity's verdict as a report's claim: proved, or refuted with its residual.
impl From<brackets::Verdict> for ClaimResult {
    fn from(v: brackets::Verdict) -> Self {
        let residual = match v.outcome {
            brackets::Outcome::Proved => None,
            brackets::Outcome::Refuted { residual } => Some(residual),
        };
        ClaimResult {
            id: v.id,
            statement: v.statement,
            written: None,
            condition: v.condition,
            condition_ascii: None,
            kind: ClaimKind::Identity,
            proved: residual.is_none(),
            expect: Expect::Proved,
            residual,
            witness: None,
            note: None,
            undecided: None,
            excerpt: None,
            seconds: v.seconds,
        }
    }
}

/// A bracket table of named functions of a system.
#[derive(Clone, Debug)]
pub struct TableResult {
    /// What the table shows: `` `{A, B}` for the harmonic rotor (row `A`, column `B`) ``.
    pub caption: String,
    /// The names the caption gives a row and a column (`A`, `B`), which name nothing of the
    /// system or the table.
    pub placeholders: [String; 2],
    /// The table, as the engine computed it.
    pub table: BracketTable,
    /// The entries cut to their leading part ([`TableResult::excerpt_entries`]), by row and
    /// column: how much of each is shown.
    pub excerpts: BTreeMap<(usize, usize), Excerpt>,
}

/// The names a table's caption may give a row and a column, the first pair free taken.
const PLACEHOLDERS: [[&str; 2]; 4] = [["A", "B"], ["F", "G"], ["U", "V"], ["Φ", "Ψ"]];

impl TableResult {
    /// `table`, a table of brackets in `system`, captioned `` `{A, B}` for {whose} (row `A`,
    /// column `B`) ``, the placeholders the first pair that names no variable or function of
    /// the system nor a function of the table (the Hénon–Heiles family has parameters `A`,
    /// `B`: its tables say `{F, G}`).
    pub fn new(table: BracketTable, system: &System, whose: &str) -> Self {
        let names: Vec<&str> = table
            .names
            .iter()
            .chain(&table.display)
            .map(String::as_str)
            .collect();
        let [a, b] = first_free(system, &names, &PLACEHOLDERS, |pair| {
            pair.iter().map(|p| p.to_string()).collect()
        });
        TableResult {
            caption: format!("`{{{a}, {b}}}` for {whose} (row `{a}`, column `{b}`)"),
            placeholders: [a.to_string(), b.to_string()],
            table,
            excerpts: BTreeMap::new(),
        }
    }

    /// Cuts each entry of more than `monomials` monomials outside the angles to the terms of
    /// its first `monomials` ([`Excerpt`]): a bracket of 10⁵ terms that is no combination of
    /// the table's functions shows its leading terms and its size.
    pub fn excerpt_entries(&mut self, monomials: usize) {
        for (a, row) in self.table.entries.iter_mut().enumerate() {
            for (b, entry) in row.iter_mut().enumerate() {
                if let brackets::Entry::Expression(e) = entry {
                    if let Some(excerpt) = Excerpt::cut(e, monomials) {
                        self.excerpts.insert((a, b), excerpt);
                    }
                }
            }
        }
    }

    /// Whether [`TableResult::excerpt_entries`] may cut it: an entry has more than
    /// `monomials` terms.
    fn is_longer_than(&self, monomials: usize) -> bool {
        let long = |e: &brackets::Entry| matches!(e, brackets::Entry::Expression(x) if x.len() > monomials);
        self.table.entries.iter().flatten().any(long)
    }

    /// The entry in row `a`, column `b` in a notation, `+ …` (`+ \dots`) after one cut to
    /// its leading part.
    pub fn cell(&self, a: usize, b: usize, style: Style) -> String {
        let text = self.table.entries[a][b].render(style);
        match (self.excerpts.contains_key(&(a, b)), style) {
            (false, _) => text,
            (true, Style::Latex) => format!(r"{text} + \dots"),
            (true, _) => format!("{text} + …"),
        }
    }

    /// The entries above the diagonal that a limit stopped (`?`), by row and column, each
    /// with the limit's message.
    pub fn undecided(&self) -> Vec<(usize, usize, &str)> {
        let entries = &self.table.entries;
        (0..entries.len())
            .flat_map(|a| (a + 1..entries.len()).map(move |b| (a, b)))
            .filter_map(|(a, b)| match &entries[a][b] {
                brackets::Entry::Undecided(message) => Some((a, b, message.as_str())),
                _ => None,
            })
            .collect()
    }

    /// Every cell in a notation, row by row ([`TableResult::cell`]).
    pub fn cells(&self, style: Style) -> Vec<Vec<String>> {
        let n = self.table.entries.len();
        (0..n)
            .map(|a| (0..n).map(|b| self.cell(a, b, style)).collect())
            .collect()
    }

    /// The caption without its note on rows and columns, for the table set as a list of its
    /// brackets: `` `{A, B}` for the harmonic rotor ``.
    pub fn list_caption(&self) -> String {
        let [a, b] = &self.placeholders;
        let note = format!(" (row `{a}`, column `{b}`)");
        self.caption.replace(&note, "")
    }
}

/// The first of `candidates` none of whose `labels` the system has as a variable or a function
/// (by name or display name), nor are among `taken`; the last when every one is: the names
/// of a report's labels and placeholders.
pub(crate) fn first_free<T: Copy>(
    system: &System,
    taken: &[&str],
    candidates: &[T],
    labels: impl Fn(T) -> Vec<String>,
) -> T {
    let has = |name: &str| {
        taken.contains(&name) || system.lookup(name).is_some() || system.get(name).is_ok()
    };
    candidates
        .iter()
        .copied()
        .find(|&c| !labels(c).iter().any(|l| has(l)))
        .unwrap_or(candidates[candidates.len() - 1])
}

/// One computed base fact of a proof.
#[derive(Clone, Debug)]
pub struct Fact {
    /// How the fact reads (`{Z, H} = iω Z`).
    pub statement: String,
    /// Whether the engine found it to hold exactly.
    pub holds: bool,
    /// For a bracket that does not hold, its value as the engine computed it.
    pub found: Option<Expr>,
}

/// A proof for all `m, n` by the eigenfunction lemma.
#[derive(Clone, Debug)]
pub struct ProofResult {
    /// What is proved, in one line.
    pub title: String,
    /// The base facts, each computed by the engine.
    pub facts: Vec<Fact>,
    /// The lemma applied (prose with mathematics, as the engine states it).
    pub lemma: String,
    /// Whether the derivation property was checked on the base functions.
    pub leibniz_check: bool,
    /// The conclusion (prose with mathematics, as the engine states it).
    pub conclusion: String,
    /// The claims the proof settles.
    pub claims: Vec<ClaimResult>,
}

impl ProofResult {
    /// Whether every step holds.
    pub fn holds(&self) -> bool {
        self.facts.iter().all(|f| f.holds) && self.leibniz_check
    }

    /// The proof's last line, as a label and prose: `Therefore` and the conclusion when every
    /// step holds, otherwise `Not proved` and why the conclusion does not follow.
    pub fn closing(&self) -> (&'static str, String) {
        if self.holds() {
            ("Therefore", self.conclusion.clone())
        } else {
            (
                "Not proved",
                format!(
                    "a step above fails, so the lemma does not give {}",
                    self.conclusion
                ),
            )
        }
    }
}

/// `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` checked by expansion for `1 ≤ m, n ≤ max`.
#[derive(Clone, Debug)]
pub struct TowerResult {
    /// The system's name.
    pub system: String,
    /// The ladder function's display name (`Z`, `Z'`).
    pub ladder: String,
    /// The bound.
    pub max: i64,
    /// How many brackets were expanded.
    pub checked: usize,
    /// The `(m, n)` where the identity failed.
    pub failures: Vec<(i64, i64)>,
    /// The claim it settles.
    pub claim: ClaimResult,
}

impl TowerResult {
    /// How the expansions went: `all hold`, `1 fails: [(2, 3)]`, `2 fail: …`.
    pub fn verdict(&self) -> String {
        match self.failures.len() {
            0 => "all hold".to_string(),
            1 => format!("1 fails: {:?}", self.failures),
            n => format!("{n} fail: {:?}", self.failures),
        }
    }
}

impl RankResult {
    /// The names of the functions of the certificate's nonzero minor (its rows).
    pub fn minor_functions(&self) -> Vec<&str> {
        let rows = &self.certificate.minor_rows;
        rows.iter().map(|&i| self.functions[i].as_str()).collect()
    }

    /// The coordinates of the certificate's nonzero minor (its columns).
    pub fn minor_coordinates(&self) -> Vec<&trigpoly::Variable> {
        let cols = &self.certificate.minor_cols;
        cols.iter().map(|&v| self.vars.variable(v)).collect()
    }
}

/// A certified rank of a Jacobian `∂(F_1, …, F_k)/∂(q, p)`.
#[derive(Clone, Debug)]
pub struct RankResult {
    /// The functions' names, in the paper's notation.
    pub functions: Vec<String>,
    /// The variables of the system (for printing the point and the coordinates).
    pub vars: Vars,
    /// The phase-space coordinates, in the Jacobian's column order.
    pub coordinates: Vec<Var>,
    /// The rank the paper states.
    pub expected: usize,
    /// The engine's certificate.
    pub certificate: RankCertificate,
    /// The claim it settles.
    pub claim: ClaimResult,
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
    /// ([`ClaimResult::excerpt_residual`], [`TableResult::excerpt_entries`]); the report
    /// itself when none is that long.
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
        for entry in report.sections.iter_mut().flat_map(|s| &mut s.entries) {
            match entry {
                Entry::Claim(c) => c.excerpt_residual(monomials),
                Entry::Table(t) => t.excerpt_entries(monomials),
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
            }],
            summary: SummaryKind::Claims,
            seconds,
        }
    }

    /// The same report with every section that names no file about `file`: what a command
    /// that ran on one system file reports.
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
    /// system files are their files' own, so the same id in two files is two claims.
    pub fn claim_ids(&self) -> Vec<(String, bool)> {
        self.claim_outcomes()
            .into_iter()
            .map(|(id, outcome)| (id, outcome == ClaimOutcome::Proved))
            .collect()
    }

    /// The claim ids in order of first appearance, as [`Report::claim_ids`], each with the
    /// outcome of its checks: refuted when one was, else undecided when one was, else proved.
    pub fn claim_outcomes(&self) -> Vec<(String, ClaimOutcome)> {
        let per_file = matches!(self.summary, SummaryKind::Check { .. });
        let mut out: Vec<(u32, String, ClaimOutcome)> = Vec::new();
        for (section, c) in self.claims_by_section() {
            let section = if per_file { section } else { 0 };
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

    /// The first tower of the report, if any.
    pub fn tower(&self) -> Option<&TowerResult> {
        self.sections
            .iter()
            .flat_map(|s| &s.entries)
            .find_map(|e| match e {
                Entry::Tower(t) => Some(t),
                _ => None,
            })
    }

    /// The first proof in the report (a tower job's proof for all `m, n`), if any.
    ///
    /// ```
    /// use superint::system_file::{family_tower_report, load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml".as_ref(), &LimitsOverride::default())?;
    /// let report = family_tower_report(&rotor, Some("K"), 2, None)?;
    /// let proof = report.proof().expect("K_{m,n} = Z^m e^{−inθ} is a product of powers");
    /// assert!(proof.holds());
    /// assert_eq!(proof.facts[0].statement, "{Z, H} = (iω) Z");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn proof(&self) -> Option<&ProofResult> {
        self.sections
            .iter()
            .flat_map(|s| &s.entries)
            .find_map(|e| match e {
                Entry::Proof(p) => Some(p),
                _ => None,
            })
    }

    /// The closing line: `26 claims: 26 proved, 0 refuted (93 exact checks, 0.41 s)`, or for a
    /// tower job `tower: 64 brackets {K_{m,n}, H} = … checked for 1 ≤ m, n ≤ 8, all hold (0.04 s)`.
    /// `timings` adds the seconds.
    pub fn summary_line(&self, timings: bool) -> String {
        let time = if timings {
            format!(", {:.2} s", self.seconds)
        } else {
            String::new()
        };
        if let (SummaryKind::Tower, Some(t)) = (self.summary, self.tower()) {
            let verdict = if t.failures.is_empty() {
                "all hold".to_string()
            } else {
                format!("{} FAIL", t.failures.len())
            };
            let time = if timings {
                format!(" ({:.2} s)", t.claim.seconds)
            } else {
                String::new()
            };
            return format!(
                "tower: {} {{K_{{m,n}}, H}} = i(mω − nΩ) K_{{m,n}} checked for \
                 1 ≤ m, n ≤ {}, {verdict}{time}",
                counted(t.checked, "bracket"),
                t.max
            );
        }
        if self.summary == SummaryKind::Computed {
            // A table's entries that a limit stopped are no part of what was computed.
            let what = match self.tables().map(|t| t.undecided().len()).sum::<usize>() {
                0 => "computed exactly".to_string(),
                n => format!(
                    "computed exactly, but for {} stopped at a limit",
                    counted(n, "entry")
                ),
            };
            return if timings {
                format!("{what} ({:.2} s)", self.seconds)
            } else {
                what
            };
        }
        if let SummaryKind::Check { files } = self.summary {
            let claims = self.claims_by_section();
            let proved = claims.iter().filter(|(_, c)| c.proved).count();
            // With several files, an id says where it is: `main (section 2)`.
            let unexpected: Vec<String> = claims
                .iter()
                .filter(|(_, c)| !c.meets_expectation())
                .map(|(s, c)| match files {
                    1 => c.id.clone(),
                    _ => format!("{} (section {s})", c.id),
                })
                .collect();
            let verdict = if unexpected.is_empty() {
                "all as expected".to_string()
            } else {
                format!(
                    "{} NOT as expected: {}",
                    unexpected.len(),
                    unexpected.join(", ")
                )
            };
            let files = counted(files, "file");
            let count = counted(claims.len(), "claim");
            let refuted = (claims.iter())
                .filter(|(_, c)| c.outcome() == ClaimOutcome::Refuted)
                .count();
            let undecided = match claims.len() - proved - refuted {
                0 => String::new(),
                n => format!(", {n} undecided"),
            };
            return format!(
                "{count} in {files}: {proved} proved, {refuted} refuted{undecided}; {verdict}{}",
                if timings {
                    format!(" ({:.2} s)", self.seconds)
                } else {
                    String::new()
                }
            );
        }
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
