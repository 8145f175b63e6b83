//! The results a report's entries hold, one type a kind: a checked claim (`ClaimResult`, with
//! its outcome and, for a long residual, an `Excerpt`), a bracket table (`TableResult`), a
//! proof for all `m, n` (`ProofResult`), a tower checked by expansion (`TowerResult`) and a
//! rank certificate (`RankResult`).

use std::collections::BTreeMap;

use brackets::{BracketTable, RankCertificate, System};
use trigpoly::{Expr, Factored, Style, Var, Vars};

use super::Expect;
use crate::system_file::Caller;

/// Whether a claim asserts an identity, that something does not vanish, or a rank.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ClaimKind {
    /// `lhs = rhs` (under the condition): proved when `lhs − rhs` is exactly zero.
    Identity,
    /// `lhs ≠ rhs` (under the condition): proved when `lhs − rhs` is not zero; the nonzero
    /// difference is the witness.
    Nonvanishing,
    /// `rank ∂(F_1, …, F_k)/∂(q, p) = r` (under the condition): proved when the certified rank
    /// is `r` ([`RankResult`]); it has no residual, and its note says the rank found.
    Rank,
}

impl ClaimKind {
    /// `identity`, `nonvanishing` or `rank`, as JSON gives it.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let file = load_system_file("systems/anisotropic-oscillator-1-2.toml", &LimitsOverride::default())?;
    /// let report = check_report([&file])?;
    /// let rank = report.claims().into_iter().find(|c| c.statement.starts_with("rank")).unwrap();
    /// assert_eq!(rank.kind.name(), "rank");
    /// assert_eq!(ClaimKind::Identity.to_string(), "identity");
    /// # Ok::<(), FileError>(())
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            ClaimKind::Identity => "identity",
            ClaimKind::Nonvanishing => "nonvanishing",
            ClaimKind::Rank => "rank",
        }
    }
}

/// Its [`ClaimKind::name`].
impl std::fmt::Display for ClaimKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// What a check of a claim found. Ordered so that the outcome of several checks of one claim
/// is the greatest: one refuted check refutes it, else one undecided leaves it undecided.
///
/// A check may find more kinds of outcome later, so a program's `match` has an arm for the
/// others, which count as not proved:
///
/// ```
/// use superint::report::ClaimOutcome;
///
/// fn proved(outcome: ClaimOutcome) -> bool {
///     match outcome {
///         ClaimOutcome::Proved => true,
///         _ => false,
///     }
/// }
/// assert!(proved(ClaimOutcome::Proved) && !proved(ClaimOutcome::Undecided));
/// ```
///
/// One without that arm does not compile:
///
/// ```compile_fail,E0004
/// use superint::report::ClaimOutcome;
///
/// fn proved(outcome: ClaimOutcome) -> bool {
///     match outcome {
///         ClaimOutcome::Proved => true,
///         ClaimOutcome::Undecided | ClaimOutcome::Refuted => false,
///     }
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
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

/// Its [`ClaimOutcome::name`], as [`brackets::Outcome`], [`Expect`] and
/// [`ErrorKind`](crate::system_file::ErrorKind) print theirs.
///
/// ```
/// use superint::prelude::*;
///
/// let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let report = check_report([&rotor])?;
/// let refuted = report.claims().into_iter().find(|c| c.expect == Expect::Refuted).unwrap();
/// assert_eq!(format!("{}: {}", refuted.id, refuted.outcome()), format!("{}: refuted", refuted.id));
/// assert_eq!(ClaimOutcome::Undecided.to_string(), "undecided");
/// # Ok::<(), FileError>(())
/// ```
impl std::fmt::Display for ClaimOutcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A claim of the paper, checked: read by a program, made by the library. A field may be
/// added, so a pattern of one names the fields it reads and `..`:
///
/// ```compile_fail,E0638
/// # use superint::prelude::*;
/// fn id(claim: ClaimResult) -> String {
///     let ClaimResult { id, statement, written, condition, condition_ascii, kind, proved,
///         expect, residual, residual_in_functions, witness, note, undecided, excerpt,
///         on_level, seconds } = claim;
///     id
/// }
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
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
    /// Identity, nonvanishing or rank.
    pub kind: ClaimKind,
    /// Whether the claim was proved.
    pub proved: bool,
    /// What the claim is expected to do (proved, unless it is marked as deliberately false).
    pub expect: Expect,
    /// For a refuted identity, the nonzero residual `lhs − rhs` in normal form.
    pub residual: Option<Expr>,
    /// The residual as a polynomial in `H` and the system's named functions, proved for every
    /// value of the parameters, where it is one (`−4 H L/M`): what the claim missed, in the
    /// system's own terms. Its variables are the parameters and one symbol per function.
    pub residual_in_functions: Option<Expr>,
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
    /// For a claim on a level set (a file's `on = "EXPR = VALUE"`): the level set, and for a
    /// proved one the quotient that proves it; `lhs − rhs` is then its remainder on division
    /// by `P` as the residual of a refuted one.
    pub on_level: Option<OnLevelSet>,
    /// Seconds spent checking it.
    pub seconds: f64,
}

/// The level set `EXPR = VALUE` a claim is made on, `P = EXPR − VALUE = 0`, and the proof
/// there: `lhs − rhs = Q·P`. Read by a program, made by the library. A field may be added,
/// so a pattern of one names the fields it reads and `..`:
///
/// ```compile_fail,E0638
/// fn quotient(on: superint::report::OnLevelSet) -> Option<trigpoly::Expr> {
///     let superint::report::OnLevelSet { text, ascii, polynomial, difference, quotient } = on;
///     quotient
/// }
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct OnLevelSet {
    /// The level set as printed, in the file's names (`A = 0`).
    pub text: String,
    /// As the file writes it (`A = 0`).
    pub ascii: String,
    /// `P = EXPR − VALUE`, expanded (`M1 γ1 + M2 γ2 + M3 γ3`).
    pub polynomial: Expr,
    /// `lhs − rhs` as printed (`{K, H}` for `{K, H} = 0`).
    pub difference: String,
    /// For a proved claim, `Q` with `lhs − rhs = Q·P`, recomputed (`−c M2`).
    pub quotient: Option<Expr>,
}

impl OnLevelSet {
    /// The level set as printed, `text`, of `P`, for the claim whose `lhs − rhs` prints as
    /// `difference`; no quotient yet.
    pub fn new(text: &str, ascii: &str, polynomial: Expr, difference: &str) -> Self {
        OnLevelSet {
            text: text.to_string(),
            ascii: ascii.to_string(),
            polynomial,
            difference: difference.to_string(),
            quotient: None,
        }
    }

    /// The proof in `style`, `Q (M1 γ1 + M2 γ2 + M3 γ3)` (a product by juxtaposition, as the
    /// paper and `search --on`'s `{I4, H} = Q4 (…)` write it), and `Q` in `style`: `None` for
    /// a claim not proved, and for one whose `lhs − rhs` is zero everywhere (`Q = 0`).
    pub fn proof(&self, style: Style) -> Option<(String, String)> {
        let q = self.quotient.as_ref().filter(|q| !q.is_zero())?;
        Some((
            format!("Q ({})", self.polynomial.render(style)),
            q.render(style),
        ))
    }
}

/// How much of a long expression (a refuted claim's residual, a table's entry) is shown: every
/// term of its first `shown` monomials outside the angles ([`trigpoly::Poly::leading_part`]),
/// of `monomials` in all. Read by a program, made by the library. A field may be added, so a
/// pattern of one names the fields it reads and `..`:
///
/// ```compile_fail,E0638
/// fn shown(excerpt: superint::report::Excerpt) -> usize {
///     let superint::report::Excerpt { shown, monomials, angles, caller } = excerpt;
///     shown
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Excerpt {
    /// The monomials whose terms are shown.
    pub shown: usize,
    /// The monomials of the whole.
    pub monomials: usize,
    /// Whether an angle appears in the whole (else its monomials are its terms).
    pub angles: bool,
    /// Who the report was built for ([`Report::caller`](super::Report::caller)), whose way
    /// to show all [`Excerpt::describe`] names.
    pub caller: Caller,
}

impl Excerpt {
    /// What the prose formats say under the part: `shown: the terms of its first 100 of
    /// 254321 monomials outside the angles; --full-expressions shows all` (`its first 100 of
    /// 254321 terms` without angles; for a program, `RenderOptions::shown_monomials(None)`
    /// shows all).
    pub fn describe(&self) -> String {
        let (shown, all) = (self.shown, self.monomials);
        let part = match self.angles {
            true => format!("the terms of its first {shown} of {all} monomials outside the angles"),
            false => format!("its first {shown} of {all} terms"),
        };
        let all = self
            .caller
            .names("--full-expressions", "RenderOptions::shown_monomials(None)");
        format!("shown: {part}; {all} shows all")
    }

    /// Cuts `e` to the terms of its first `monomials` monomials outside the angles if it has
    /// more; how much of it is then shown. At least one is shown: a residual cut to none
    /// printed as `0 + …`, which reads as nearly zero.
    fn cut(e: &mut Expr, monomials: usize) -> Option<Excerpt> {
        let monomials = monomials.max(1);
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
            caller: Caller::Program,
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
            residual_in_functions: None,
            witness: None,
            note,
            undecided: None,
            excerpt: None,
            on_level: None,
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

    /// The same result with a timing. Like the other builders here (`written`, `at`,
    /// `expecting`, [`TableResult::in_functions`]) it changes nothing in place, so a call whose
    /// result is dropped is a mistake the compiler names (`unused_must_use`):
    ///
    /// ```compile_fail
    /// #![deny(unused_must_use)]
    /// use superint::report::ClaimResult;
    ///
    /// let claim = ClaimResult::derived("T1", "{K, H} = iωK", true, None);
    /// claim.clone().timed(0.5);
    /// assert_eq!(claim.seconds, 0.5);
    /// ```
    #[must_use]
    pub fn timed(mut self, seconds: f64) -> Self {
        self.seconds = seconds;
        self
    }

    /// The same result with its text as a system file writes it.
    #[must_use]
    pub fn written(mut self, text: &str) -> Self {
        self.written = Some(text.to_string());
        self
    }

    /// The same result under a condition, as printed and as superint reads it back.
    #[must_use]
    pub fn at(mut self, condition: Option<(String, String)>) -> Self {
        (self.condition, self.condition_ascii) = condition.unzip();
        self
    }

    /// The same result on a level set ([`ClaimResult::on_level`]).
    #[must_use]
    pub fn on(mut self, level: Option<OnLevelSet>) -> Self {
        self.on_level = level;
        self
    }

    /// The same result with an expectation.
    #[must_use]
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

    /// The residual as the factor its terms share times what is left (`2F(x p_x + y p_y)/M`,
    /// [`Expr::factored`](trigpoly::Poly::factored)), where it is printed whole, has no form
    /// in the system's functions, and what is left is short.
    pub fn residual_factored(&self) -> Option<Factored> {
        match (&self.excerpt, &self.residual_in_functions) {
            (None, None) => super::shown_factored(self.residual.as_ref()?),
            _ => None,
        }
    }

    /// The residual restated below it in the notation of `style`: in the system's functions,
    /// or else factored ([`ClaimResult::residual_factored`]).
    pub fn residual_restated(&self, style: Style) -> Option<String> {
        super::restated(
            self.residual_in_functions.as_ref(),
            self.residual_factored().as_ref(),
            style,
        )
    }

    /// Whether [`ClaimResult::excerpt_residual`] may cut it: its residual has more than `monomials`
    /// terms.
    pub(super) fn is_longer_than(&self, monomials: usize) -> bool {
        self.residual.as_ref().is_some_and(|e| e.len() > monomials)
    }
}

/// Why a claim whose engine outcome is of a kind this crate does not know is undecided.
pub(crate) const UNKNOWN_OUTCOME: &str =
    "the engine's outcome is of a kind this report does not know";

/// What an engine's outcome makes of a claim's result: whether it is proved, a refutation's
/// residual, and, for an outcome of a kind this crate does not know ([`brackets::Outcome`] is
/// open to new kinds), the words that leave the claim undecided: neither proved nor refuted.
pub(crate) fn outcome_parts(outcome: brackets::Outcome) -> (bool, Option<Expr>, Option<String>) {
    match outcome {
        brackets::Outcome::Proved => (true, None, None),
        brackets::Outcome::Refuted { residual } => (false, Some(residual), None),
        _ => (false, None, Some(UNKNOWN_OUTCOME.into())),
    }
}

/// An identity's verdict as a report's claim: proved, or refuted with its residual.
impl From<brackets::Verdict> for ClaimResult {
    fn from(v: brackets::Verdict) -> Self {
        let (proved, residual, undecided) = outcome_parts(v.outcome);
        ClaimResult {
            id: v.id,
            statement: v.statement,
            written: None,
            condition: v.condition,
            condition_ascii: None,
            kind: ClaimKind::Identity,
            proved,
            expect: Expect::Proved,
            residual,
            residual_in_functions: None,
            witness: None,
            note: None,
            undecided,
            excerpt: None,
            on_level: None,
            seconds: v.seconds,
        }
    }
}

/// A bracket table of named functions of a system.
#[derive(Clone, Debug)]
#[non_exhaustive]
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
    /// Whether the entries are polynomials in the table's functions (a closure's), each
    /// written as the paper writes one, `−4(H_x S − H_y Q)/ω` ([`TableResult::in_functions`]).
    pub polynomials_in_functions: bool,
}

/// The names a table's caption may give a row and a column, and a tower's proof its two base
/// functions, the first pair free taken.
pub(crate) const PLACEHOLDERS: [[&str; 2]; 5] =
    [["A", "B"], ["F", "G"], ["U", "V"], ["Φ", "Ψ"], ["Ξ", "Λ"]];

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
            polynomials_in_functions: false,
        }
    }

    /// The table with its entries read as polynomials in its functions (a closure's
    /// structure table), each written with the factor its terms share in front,
    /// `(P S − Q R)/(M²ω)`, as a bracket restated in functions is.
    #[must_use]
    pub fn in_functions(self) -> Self {
        TableResult {
            polynomials_in_functions: true,
            ..self
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
    pub(super) fn is_longer_than(&self, monomials: usize) -> bool {
        let long = |e: &brackets::Entry| matches!(e, brackets::Entry::Expression(x) if x.len() > monomials);
        self.table.entries.iter().flatten().any(long)
    }

    /// The entry in row `a`, column `b` in a notation, as it stands (a polynomial in the
    /// functions with the factor its terms share in front, where
    /// [`TableResult::in_functions`] says it is one).
    pub fn entry(&self, a: usize, b: usize, style: Style) -> String {
        match &self.table.entries[a][b] {
            brackets::Entry::Expression(e) if self.polynomials_in_functions => {
                super::written_in_functions(e, style)
            }
            entry => entry.render(style),
        }
    }

    /// The entry in row `a`, column `b` in a notation, `+ …` (`+ \dots`) after one cut to
    /// its leading part.
    pub fn cell(&self, a: usize, b: usize, style: Style) -> String {
        let text = self.entry(a, b, style);
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
/// (by name, display name, or that display as the expressions write it, `Φ1` of `Phi1`), nor
/// are among `taken`; the last when every one is: the names of a report's labels and
/// placeholders.
pub(crate) fn first_free<T: Copy>(
    system: &System,
    taken: &[&str],
    candidates: &[T],
    labels: impl Fn(T) -> Vec<String>,
) -> T {
    // A function by its name, its display, and its display as the expressions write it (`Φ1`
    // of `Phi1`), which a label beside it would print as.
    let shown: Vec<String> = (system.functions().iter())
        .map(|f| trigpoly::shown_text(&f.display))
        .collect();
    let has = |name: &str| {
        taken.contains(&name)
            || system.lookup(name).is_some()
            || system.get(name).is_ok()
            || shown.iter().any(|s| s == name)
    };
    candidates
        .iter()
        .copied()
        .find(|&c| !labels(c).iter().any(|l| has(l)))
        .unwrap_or(candidates[candidates.len() - 1])
}

/// One computed base fact of a proof.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Fact {
    /// How the fact reads (`{Z, H} = iω Z`).
    pub statement: String,
    /// Whether the engine found it to hold exactly.
    pub holds: bool,
    /// For a bracket that does not hold, its value as the engine computed it.
    pub found: Option<Expr>,
    /// For a bracket that does not hold but is another multiple of its base, the fact it
    /// makes, read as the statement is (`{b̄, H} = (−3iω) b̄`).
    pub found_statement: Option<String>,
}

/// A proof for all `m, n` by the eigenfunction lemma.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ProofResult {
    /// What is proved, in one line.
    pub title: String,
    /// The base facts, each computed by the engine.
    pub facts: Vec<Fact>,
    /// The lemma applied (prose with mathematics, as the engine states it).
    pub lemma: String,
    /// The names the derivation property and the lemma give the two base functions: `A`, `B`,
    /// or the first pair the system does not name otherwise, as a table's caption chooses, so
    /// that a file with functions `A` and `B` reads `{F, H} = λ_F F`.
    pub bases: [String; 2],
    /// Whether the derivation property was checked on the base functions.
    pub leibniz_check: bool,
    /// The conclusion (prose with mathematics, as the engine states it).
    pub conclusion: String,
    /// The claims the proof settles.
    pub claims: Vec<ClaimResult>,
}

impl ProofResult {
    /// The derivation property in the proof's names for the base functions,
    /// `{AB, H} = A{B, H} + B{A, H}`.
    pub fn derivation(&self) -> String {
        let [a, b] = &self.bases;
        format!("{{{a}{b}, H}} = {a}{{{b}, H}} + {b}{{{a}, H}}")
    }

    /// Whether every step holds.
    pub fn holds(&self) -> bool {
        self.facts.iter().all(|f| f.holds) && self.leibniz_check
    }

    /// Which steps of a proof with `facts` and the derivation check fail, as the claims it
    /// settles say so (`step 3 fails`, `steps 1 and 4 fail`), numbered as the proof prints
    /// them (the facts, then the derivation check); `None` when every step holds.
    pub fn failed_steps(facts: &[Fact], leibniz_check: bool) -> Option<String> {
        let steps: Vec<String> = facts
            .iter()
            .map(|f| f.holds)
            .chain([leibniz_check])
            .enumerate()
            .filter(|(_, holds)| !holds)
            .map(|(k, _)| (k + 1).to_string())
            .collect();
        match steps.len() {
            0 => None,
            1 => Some(format!("step {} fails", steps[0])),
            _ => Some(format!("steps {} fail", super::listed(&steps))),
        }
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
#[non_exhaustive]
pub struct TowerResult {
    /// The system's name (JSON's `"system"`).
    pub system: String,
    /// The system as a title names it (`the harmonic rotor`; `t1` for a file that names
    /// none), as the tower's line says it.
    pub the_system: String,
    /// The ladder as the tower's line names it: the paper's ladder function (`Z`, `Z'`), or a
    /// file's family with its value (`K_{m,n} = Z^m e^{−inθ}`).
    pub ladder: String,
    /// The family with its indices (`K_{m,n}`, `K'_{m,n}`), as the tower's closing line
    /// names it.
    pub family: String,
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
    /// The certified rank of the functions `names` of `system`, answering the claim `id` that
    /// it is `expected` (untimed, expected proved: the caller says otherwise).
    pub fn new(
        id: &str,
        system: &System,
        names: Vec<String>,
        expected: usize,
        certificate: RankCertificate,
    ) -> Self {
        let vars = system.vars().clone();
        let statement = Self::statement(&names, &vars, &certificate.coordinates, expected);
        let proved = certificate.rank == expected;
        let note = (!proved).then(|| format!("the rank is {}", certificate.rank));
        let claim = ClaimResult {
            kind: ClaimKind::Rank,
            ..ClaimResult::derived(id, &statement, proved, note)
        };
        RankResult {
            functions: names,
            vars,
            expected,
            claim,
            certificate,
        }
    }

    /// The claim a rank answers in the paper's notation, `rank ∂(F, G)/∂(x, p_x) = r`: the
    /// functions by `names`, the Jacobian's columns the `coordinates` of `vars`.
    pub fn statement(
        names: &[impl AsRef<str>],
        vars: &Vars,
        coordinates: &[Var],
        expected: usize,
    ) -> String {
        let names: Vec<&str> = names.iter().map(AsRef::as_ref).collect();
        let coordinates: Vec<&str> = coordinates
            .iter()
            .map(|&v| vars.variable(v).unicode())
            .collect();
        format!(
            "rank ∂({})/∂({}) = {expected}",
            names.join(", "),
            coordinates.join(", ")
        )
    }

    /// The Jacobian's columns: the phase-space coordinates, in order, or on a level set those
    /// its condition leaves free, as the certificate has them
    /// ([`RankCertificate::coordinates`](brackets::RankCertificate::coordinates)).
    ///
    /// ```
    /// use superint::prelude::*;
    /// use superint::report::Entry;
    ///
    /// // On the level set p_θ = Iω the Jacobian has no column p_θ.
    /// let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// let report = rank_report_when(&rotor, &["F1", "L"], None, Some("p_theta = I*omega"))?;
    /// let entries = &report.sections[0].entries;
    /// let Some(Entry::Rank(rank)) = entries.iter().find(|e| matches!(e, Entry::Rank(_))) else {
    ///     panic!("a rank");
    /// };
    /// let names: Vec<&str> = rank.coordinates().iter().map(|&v| rank.vars.variable(v).name()).collect();
    /// assert_eq!(names, ["x", "y", "theta", "p_x", "p_y"]);
    /// # Ok::<(), FileError>(())
    /// ```
    pub fn coordinates(&self) -> &[Var] {
        &self.certificate.coordinates
    }

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
#[non_exhaustive]
pub struct RankResult {
    /// The functions' names, in the paper's notation.
    pub functions: Vec<String>,
    /// The variables of the system (for printing the point and the coordinates).
    pub vars: Vars,
    /// The rank the paper states.
    pub expected: usize,
    /// The engine's certificate.
    pub certificate: RankCertificate,
    /// The claim it settles.
    pub claim: ClaimResult,
}

#[cfg(test)]
mod tests {
    use super::{Fact, ProofResult};

    /// The steps that fail are named as the proof numbers them: the facts, then the
    /// derivation check.
    #[test]
    fn failed_steps_are_named_by_their_numbers() {
        let facts = |holds: &[bool]| -> Vec<Fact> {
            holds
                .iter()
                .map(|&holds| Fact {
                    statement: String::new(),
                    holds,
                    found: None,
                    found_statement: None,
                })
                .collect()
        };
        let failed = |holds: &[bool], leibniz| ProofResult::failed_steps(&facts(holds), leibniz);
        assert_eq!(failed(&[true, true, true], true), None);
        assert_eq!(failed(&[true, true, false], true).unwrap(), "step 3 fails");
        assert_eq!(
            failed(&[false, true, true], false).unwrap(),
            "steps 1 and 4 fail"
        );
        assert_eq!(
            failed(&[false, false, true], false).unwrap(),
            "steps 1, 2 and 4 fail"
        );
    }
}
