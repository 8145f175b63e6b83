//! Reports of system files, rendered by [`crate::render`] like the default job: every claim
//! of some files checked ([`check_report`]), one bracket ([`bracket_report`]), expressions in
//! normal form ([`expand_report`]), a bracket table ([`table_report`]) and a certified rank
//! ([`rank_report`]).

use crate::render::tex::Names;
use std::time::Instant;

use brackets::{BracketTable, Condition, System};
use trigpoly::{Expr, VarKind};

use super::claims::{
    engine_error, parse_condition, parse_condition_with, parse_rank_condition, CheckedClaim,
    RankClaim,
};
use super::error::{ErrorKind, FileError};
use super::scope::{instance_of, rewrite_braces};
use super::text::{trimmed, Text};
use super::{Argument, Caller, LoadedSystem};
use crate::report::{
    factored_in_functions, shown_factored, Entry, Equation, Equations, Expect, FlowKept,
    RankResult, Report, Section, SummaryKind, TableResult,
};

impl LoadedSystem {
    /// A parsed argument as printed, and its value.
    pub(super) fn expand(&self, arg: &Argument) -> Result<(String, Expr), FileError> {
        Ok((self.pretty(&arg.tree), self.value(arg)?))
    }

    /// A section heading the file's entries: its citation and Hamiltonian.
    fn preamble(&self) -> Vec<Entry> {
        let mut entries = Vec::new();
        if let Some(d) = &self.description {
            entries.push(Entry::Text(d.clone()));
        }
        if let Some(c) = &self.citation {
            entries.push(Entry::Text(format!("Source: {c}")));
        }
        // Over common denominators and with the least powers of the radicals, as `expand`
        // prints it (`s²z²/(2r² (x² + y²))`, not `s²z²(x² + y²)/(2r² (x² + y²)²)`); as it is
        // where that passes a limit.
        let h = self.system.hamiltonian();
        let h = h.over_common_denominators().unwrap_or_else(|_| h.clone());
        entries.push(Entry::Equations(Equations::new(
            String::new(),
            vec![Equation::new("H", h)],
        )));
        // What each radical stands for, which H's terms do not show: its radicand as the file
        // declares it, `√((x − a)² + y² + z²)` (its normal form, `√(x² − 2ax + y² + z² + a²)`,
        // hid the distance to the centre).
        let radicals: Vec<String> = self
            .system
            .space()
            .radicals()
            .iter()
            .map(|(r, radicand)| format!("`{}`", self.radical_as_declared(*r, radicand)))
            .collect();
        if !radicals.is_empty() {
            entries.push(Entry::Text(format!("with {}.", radicals.join(", "))));
        }
        entries
    }

    /// `r = √(R)` with the radicand `R` as the file declares it, in the paper's notation
    /// (`s = √(1 + γ₂(x² + y²))`), or in normal form where its text does not read.
    fn radical_as_declared(&self, r: trigpoly::Var, radicand: &Expr) -> String {
        let variable = self.system.vars().variable(r);
        let declared = self
            .radicands
            .iter()
            .find(|(name, _)| name == variable.name())
            .map(|(_, text)| text);
        match declared.and_then(|text| trigpoly::syntax::parse_expr(text).ok()) {
            Some(tree) => format!("{} = √({})", variable.unicode(), self.pretty(&tree)),
            None => Expr::radical_definition(r, radicand),
        }
    }

    /// The file's names as its expressions write them in LaTeX, its families' with their
    /// instances' indices ([`Names::with_families`]), for its sections' statements.
    pub fn names(&self) -> Names {
        let families = self.families.iter().map(|f| f.display.as_str());
        Names::of_system(&self.system).with_families(families)
    }

    fn section_title(&self) -> String {
        format!("{} ({})", self.name, self.source.origin)
    }

    /// A report of one entry in one section on this file, computed since `start`.
    fn one_entry(
        &self,
        title: String,
        entry: Entry,
        summary: SummaryKind,
        start: Instant,
    ) -> Report {
        Report {
            title,
            subtitle: String::new(),
            sections: vec![Section {
                number: 1,
                title: self.section_title(),
                file: Some(self.source.origin.clone()),
                entries: vec![entry],
                names: self.names(),
            }],
            summary,
            seconds: start.elapsed().as_secs_f64(),
            caller: self.caller,
        }
    }
}

impl LoadedSystem {
    /// An error of the engine on a computation a report was asked for (no place in a text):
    /// from `<program>`, or `<command line>`.
    pub(super) fn computation_error(&self, e: &brackets::EngineError) -> FileError {
        let mut err = engine_error(&self.given("<program>", ""), 0..0, e);
        err.location = None;
        err
    }

    /// An error of the engine on what a report of this file was `doing` (`computing the
    /// closure`): from the file, said after what it was doing, without a place in it.
    pub(crate) fn computation_failed(&self, doing: &str, e: &brackets::EngineError) -> FileError {
        let mut err = self.computation_error(e);
        err.origin.clone_from(&self.source.origin);
        err.message = format!("{doing}: {}", err.message);
        err
    }
}

/// Checks every claim of every file: one section per file (its source, its Hamiltonian, its
/// claims proved or refuted, ranks with their certificates). The first error, of any file,
/// is the answer, a limit that a claim reaches included; [`check_each`] goes on past it.
///
/// It takes a slice or vector of loaded systems, or references to them: `check_report([&file])`.
pub fn check_report<'a>(
    files: impl IntoIterator<Item = &'a LoadedSystem>,
) -> Result<Report, FileError> {
    let start = Instant::now();
    let mut callers = Vec::new();
    let sections = files
        .into_iter()
        .inspect(|f| callers.push(f.caller))
        .map(|f| f.checked_section(None))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(checked_files(sections, &callers, start))
}

/// Checks every claim of every file that loaded, as [`check_report`] does, and goes on past
/// what stops a check: a claim that reaches a limit (of terms, of term products, of degree) is
/// reported undecided ([`ClaimResult::undecided`](crate::report::ClaimResult::undecided)) and
/// the file's other claims are checked; a file that did not load, or whose check failed
/// otherwise, is left out of the report. The errors, each limit's and each such file's, come
/// beside the report, in order, for the caller to show.
///
/// ```
/// use superint::report::ClaimOutcome;
/// use superint::system_file::{check_each, load_str, ErrorKind, LimitsOverride};
///
/// let text = r#"
/// name = "a free particle"
/// hamiltonian = "p_x^2/2"
/// [phase_space]
/// coordinates = ["x"]
/// [[claim]]
/// id = "long"
/// claim = "{x, (1 + x + p_x)^40} = 0"
/// [[claim]]
/// id = "momentum"
/// claim = "{p_x, H} = 0"
/// "#;
/// let limits = LimitsOverride::default().max_terms(100);
/// let (report, errors) = check_each(vec![load_str("free.toml", text, &limits)]);
/// assert_eq!(report.claim_outcomes(), [
///     ("long".to_string(), ClaimOutcome::Undecided),
///     ("momentum".to_string(), ClaimOutcome::Proved),
/// ]);
/// assert_eq!((errors.len(), errors[0].kind, errors[0].line_col()), (1, ErrorKind::Limit, Some((8, 14))));
/// ```
pub fn check_each(files: Vec<Result<LoadedSystem, FileError>>) -> (Report, Vec<FileError>) {
    let start = Instant::now();
    let mut sections = Vec::new();
    let mut errors = Vec::new();
    let mut callers = Vec::new();
    for file in files {
        let mut limits = Vec::new();
        callers.extend(file.as_ref().map(|f| f.caller));
        match file.and_then(|f| f.checked_section(Some(&mut limits))) {
            Ok(section) => sections.push(section),
            Err(e) => errors.push(e),
        }
        errors.append(&mut limits);
    }
    (checked_files(sections, &callers, start), errors)
}

impl LoadedSystem {
    /// The section of the file's claims, checked. With `undecided`, a claim whose check
    /// reaches a limit is reported undecided and its error goes there; without, that error
    /// is the answer.
    fn checked_section(
        &self,
        mut undecided: Option<&mut Vec<FileError>>,
    ) -> Result<(Section, String), FileError> {
        let mut entries = self.preamble();
        let preamble = entries.len();
        for claim in &self.claims {
            let start = Instant::now();
            entries.push(match (self.check_claim(claim), undecided.as_deref_mut()) {
                (Ok(CheckedClaim::Identity(c)), _) => Entry::Claim(*c),
                (Ok(CheckedClaim::Rank(r)), _) => Entry::Rank(*r),
                (Err(e), Some(errors)) if e.kind == ErrorKind::Limit => {
                    // The time it ran before it stopped.
                    let result = claim
                        .undecided(&e.message)
                        .timed(start.elapsed().as_secs_f64());
                    errors.push(e.of_claim(&result.id));
                    Entry::Claim(result)
                }
                (Err(e), _) => return Err(e),
            });
        }
        // What the file's texts read in doubt, from its loading and from its claims' checks,
        // in the file's order, after its Hamiltonian and before its claims.
        let mut warnings: Vec<_> = (self.warnings().into_iter())
            .filter(|w| w.origin == self.source.origin)
            .collect();
        warnings.sort_by_key(|w| w.line_col());
        entries.splice(preamble..preamble, warnings.into_iter().map(Entry::Warning));
        let section = Section {
            number: 0,
            title: self.section_title(),
            file: Some(self.source.origin.clone()),
            entries,
            names: self.names(),
        };
        Ok((section, self.the_name()))
    }
}

/// The report of checked files' sections, each with its system's name, numbered in order;
/// built for the files' caller when they share one ([`Caller::Program`] else).
fn checked_files(sections: Vec<(Section, String)>, callers: &[Caller], start: Instant) -> Report {
    let caller = match callers {
        [first, rest @ ..] if rest.iter().all(|c| c == first) => *first,
        _ => Caller::Program,
    };
    let title = match sections.as_slice() {
        [(_, name)] => format!("The claims of {name}, checked exactly"),
        _ => format!(
            "The claims of {} system files, checked exactly",
            sections.len()
        ),
    };
    let files = sections.len();
    let sections = sections
        .into_iter()
        .zip(1..)
        .map(|((section, _), number)| Section { number, ..section })
        .collect();
    Report {
        title,
        subtitle: String::new(),
        sections,
        summary: SummaryKind::Check { files },
        seconds: start.elapsed().as_secs_f64(),
        caller,
    }
}

/// `{F, G}` in normal form, for expressions `f` and `g` of the file's system, optionally
/// under a condition such as `p_theta = 2*I*omega/3`.
pub fn bracket_report(
    file: &LoadedSystem,
    f: &str,
    g: &str,
    when: Option<&str>,
) -> Result<Report, FileError> {
    let start = Instant::now();
    let (f, g) = (file.argument(f)?, file.argument(g)?);
    // The condition is read first too: its values are short.
    let condition = command_condition(file, when)?;
    let (fname, fe) = file.expand(&f)?;
    let (gname, ge) = file.expand(&g)?;
    let value = file
        .system
        .bracket(&fe, &ge)
        .map_err(|e| file.computation_error(&e))?;
    let lhs = format!("{{{fname}, {gname}}}");
    let mut equations = equations_at(file, condition.as_ref(), when, vec![(lhs.clone(), value)])?;
    // The bracket of functions that have no value under the condition has none, even where
    // the bracket is free of what they divide by (`{F, p_φ}` of `F = x/(ω² − Ω²)` at `Ω = ω`).
    if let Some(c) = &condition {
        (c.defined_on(&[&fe], &fname))
            .and_then(|()| c.defined_on(&[&ge], &gname))
            .map_err(|e| file.error_under(when, &e))?;
    }
    // A bracket at a surface the flow of H leaves may vanish there and still conserve nothing.
    let zero = equations.lines.iter().all(|l| l.rhs.is_zero());
    equations.flow = condition.as_ref().map(|c| flow_kept(file, c, zero));
    // The bracket in the file's functions too (and the family instances at the indices the
    // arguments mention), where it is a polynomial in them. Else as its terms' common factor
    // times the rest, where they share one.
    let indices = file.mentioned_indices([&f.tree, &g.tree]);
    for line in &mut equations.lines {
        line.in_functions =
            file.written_in_functions_and_instances(&line.rhs, condition.as_ref(), &indices);
        if line.in_functions.is_none() {
            line.factored = shown_factored(&line.rhs);
        }
    }
    Ok(file.one_entry(
        format!("`{lhs}` for {}", file.the_name()),
        Entry::Equations(equations),
        SummaryKind::Computed,
        start,
    ))
}

/// Expressions of the file's system in normal form, each optionally under a condition such
/// as `p_theta = I*omega`: what `superint expand` prints. Every expression is read before any
/// is expanded, so that a mistake in the last one is found before a long expansion; none at
/// all is refused, as a rank of no functions is.
pub fn expand_report(
    file: &LoadedSystem,
    expressions: &[impl AsRef<str>],
    when: Option<&str>,
) -> Result<Report, FileError> {
    let start = Instant::now();
    if expressions.is_empty() {
        // A report of nothing had a title of no names and no line.
        let message = match file.caller {
            Caller::CommandLine => {
                "nothing to expand: give the expressions, such as: superint expand FILE H"
            }
            Caller::Program => {
                "nothing to expand: give the expressions in the call, such as \
                 expand_report(&system, &[\"H\"], None)"
            }
        };
        return Err(FileError::new(
            ErrorKind::Expression,
            &file.given("<expression>", "").origin,
            message,
        ));
    }
    let arguments = expressions
        .iter()
        .map(|e| file.argument(e.as_ref()))
        .collect::<Result<Vec<_>, _>>()?;
    let condition = command_condition(file, when)?;
    let lines = arguments
        .iter()
        .map(|argument| file.expand(argument))
        .collect::<Result<Vec<_>, _>>()?;
    let names: Vec<&str> = lines.iter().map(|(name, _)| name.as_str()).collect();
    let title = format!(
        "{} in normal form, for {}",
        names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", "),
        file.the_name()
    );
    let mut equations = equations_at(file, condition.as_ref(), when, lines)?;
    // Each as its terms' common factor times the rest, where they share one.
    for line in &mut equations.lines {
        line.factored = shown_factored(&line.rhs);
    }
    Ok(file.one_entry(
        title,
        Entry::Equations(equations),
        SummaryKind::Computed,
        start,
    ))
}

/// Displayed equations `lhs = value`, each value under the report's condition if there is
/// one, read from the text `when`, which the caption names.
fn equations_at(
    file: &LoadedSystem,
    condition: Option<&Condition>,
    when: Option<&str>,
    lines: Vec<(String, Expr)>,
) -> Result<Equations, FileError> {
    let lines = lines
        .into_iter()
        .map(|(lhs, value)| {
            let value = match condition {
                Some(c) => c
                    .apply_where_defined(&value, "the expression")
                    .map_err(|e| file.error_under(when, &e))?,
                None => value,
            };
            // Over a common denominator, so that a value that is zero shows as 0.
            let value = match Expr::has_relations(value.vars()) {
                true => value
                    .over_common_denominators()
                    .map_err(|e| file.computation_error(&e.into()))?,
                false => value,
            };
            value
                .check_printable()
                .map_err(|e| file.computation_error(&e.into()))?;
            Ok(Equation::new(&lhs, value))
        })
        .collect::<Result<_, FileError>>()?;
    Ok(Equations::new(
        condition.map_or_else(String::new, |c| format!("at `{}`", c.text)),
        lines,
    ))
}

/// Whether the flow of the file's `H` keeps the surface of `condition`, decided exactly as a
/// search's condition is ([`Condition::left_by_flow`]), with the note that says where it does
/// not: a bracket that vanishes there is no conservation law (`{x, H}` at `x = 0` of the
/// oscillator), which says so where the bracket printed, `zero`, vanishes there; elsewhere the
/// note ends at its parenthesis (`{x, H} = p_x/M` at `x = 0`). Where that could not be
/// decided (a limit), a note says so with the limit's message.
fn flow_kept(file: &LoadedSystem, condition: &Condition, zero: bool) -> FlowKept {
    match condition.left_by_flow(&file.system) {
        Err(e) => FlowKept::Unchecked(format!(
            "whether `{}` is kept by the flow of `H` was not checked: {}.",
            condition.text,
            e.to_string().trim_end_matches('.')
        )),
        Ok(None) => FlowKept::Kept,
        Ok(Some(left)) => FlowKept::Left(format!(
            "`{}` is not kept by the flow of `H` (`{{{}, H}} = {}` there){}",
            condition.text,
            left.level,
            left.rate,
            match zero {
                true => ": a zero is no conservation law.",
                false => ".",
            }
        )),
    }
}

/// A condition given to a report (`--when` on the command line), if any.
fn command_condition(
    file: &LoadedSystem,
    when: Option<&str>,
) -> Result<Option<Condition>, FileError> {
    when.map(|w| file.condition(w)).transpose()
}

impl LoadedSystem {
    /// A condition given as text (`p_theta = I*omega, omega = 1/2`), read as a file's `when`
    /// is: its errors are located in `text` (named `<condition>`, or `<command line>` as the
    /// [`Caller`] says), and it reads as written (`p_θ = Iω`).
    pub fn condition(&self, text: &str) -> Result<Condition, FileError> {
        let source = self.given("<condition>", text);
        let pieces = Text::whole(&source).split(',');
        parse_condition(self, &source, &pieces)
    }

    /// The error `e` of a computation under the condition read from the text `when`: a
    /// refusal of the condition ([`brackets::EngineError::RefusedCondition`], such as one that
    /// sets to 0 a variable what it is applied to divides by) at that variable's value in
    /// `when`, as the reading's own refusals are shown; any other as
    /// [`LoadedSystem::computation_error`] says it, without a place.
    pub(crate) fn error_under(&self, when: Option<&str>, e: &brackets::EngineError) -> FileError {
        match (when, e) {
            (Some(text), brackets::EngineError::RefusedCondition { .. }) => {
                self.condition_refusal(text, e)
            }
            _ => self.computation_error(e),
        }
    }

    /// The refusal `e` of the condition read from the text `when`
    /// ([`brackets::EngineError::RefusedCondition`], which a computation under it met) at
    /// the value of the variable it is about in `when`, as the reading's own refusals are
    /// shown.
    pub fn condition_refusal(&self, when: &str, e: &brackets::EngineError) -> FileError {
        let source = self.given("<condition>", when);
        let pieces = Text::whole(&source).split(',');
        match parse_condition_with(self, &source, &pieces, |_| Err(e.clone())) {
            Err(placed) => placed,
            Ok(_) => self.computation_error(e),
        }
    }

    /// A rank's condition given as text, read as [`LoadedSystem::condition`] reads one and
    /// refused, at the value, where it describes no level set
    /// ([`Condition::level_set_variables`]: a parameter set to a function of phase space).
    pub fn rank_condition(&self, text: &str) -> Result<Condition, FileError> {
        let source = self.given("<condition>", text);
        let pieces = Text::whole(&source).split(',');
        parse_rank_condition(self, &source, &pieces)
    }
}

impl LoadedSystem {
    /// Refuses a blank name among `names` (`'   '`) as a blank expression is refused: at its
    /// end of input, past the blanks on its first line, where it was taken for a name `''`.
    pub fn refuse_blank(&self, names: &[impl AsRef<str>]) -> Result<(), FileError> {
        match names
            .iter()
            .map(AsRef::as_ref)
            .find(|n| n.trim().is_empty())
        {
            Some(blank) => {
                let end = blank.find(['\n', '\r']).unwrap_or(blank.len());
                Err(self.given("<name>", blank).error(
                    ErrorKind::Expression,
                    end..end,
                    "expected the name of a function, found end of input",
                ))
            }
            None => Ok(()),
        }
    }

    /// Refuses a function given twice among `names`: the same name (`L G1 L`), one function
    /// by its name and its display (`Omega Ω`, as [`System::function`](brackets::System::function)
    /// finds it), or one family instance written two ways (`K_1_1 K_{01,1}`). A table would
    /// show it twice, a rank count it twice and a closure find the relation `L = L`; `what`
    /// names the job in the message (`a table`). The error is at the second, as given.
    pub fn refuse_repeated(&self, names: &[impl AsRef<str>], what: &str) -> Result<(), FileError> {
        let key = |name: &str| {
            let braced = rewrite_braces(name, &self.families, &[]);
            match instance_of(&self.families, braced.trim()) {
                Some((k, m, n)) => format!("{}_{{{m},{n}}}", self.families[k].name),
                None => match self.system.function(name.trim()) {
                    Some(f) => f.name.clone(),
                    None => name.split_whitespace().collect(),
                },
            }
        };
        let names: Vec<&str> = names.iter().map(AsRef::as_ref).collect();
        let keys: Vec<String> = names.iter().map(|n| key(n)).collect();
        let Some((second, first)) =
            (1..keys.len()).find_map(|k| (0..k).find(|&j| keys[j] == keys[k]).map(|j| (k, j)))
        else {
            return Ok(());
        };
        let message = given_twice(names[second], names[first], what);
        let source = self.given("<expression>", names[second]);
        let text = Text::whole(&source);
        Err(text.error(&source, ErrorKind::Expression, text.trimmed_span(), message))
    }
}

/// Why the function `given` is refused where `before` gave it already, for the job `what`
/// (`the closure`): `'L' is given twice`, or, written another way, `'Ω' is 'Omega', given
/// before`.
pub fn given_twice(given: &str, before: &str, what: &str) -> String {
    let (given, before) = (given.trim(), before.trim());
    match given == before {
        true => format!(
            "{} is given twice: {what} takes each function once",
            trigpoly::quoted_name(given)
        ),
        false => format!(
            "{} is {}, given before: {what} takes each function once",
            trigpoly::quoted_name(given),
            trigpoly::quoted_name(before)
        ),
    }
}

/// The bracket table of named functions (or family instances such as `K_1_1`, or phase
/// variables such as `p_x`) of the file, with its entries that are polynomials in `H` and the
/// file's functions written so below it; all its functions but `H` when `names` is empty. A
/// name is read without the spaces around it (` L` is `L`). A blank name, one holding a line break or a tab (first, escaped:
/// [`refuse_unshowable_name`](super::refuse_unshowable_name)) and one given twice are refused
/// at their places. An entry that reaches a limit is `?`
/// ([`TableResult::undecided`](crate::report::TableResult::undecided) lists them, with the
/// limits' messages), and the others are computed.
pub fn table_report(file: &LoadedSystem, names: &[impl AsRef<str>]) -> Result<Report, FileError> {
    let start = Instant::now();
    let defined: Vec<String> = file
        .system
        .functions()
        .iter()
        .skip(1)
        .map(|f| f.name.clone())
        .collect();
    file.refuse_blank(names)?;
    for name in names {
        super::refuse_unshowable_name(name.as_ref(), file.caller, "function")?;
    }
    // As given, braces and all (`K_{1,1}` beside `K_1_1`).
    file.refuse_repeated(names, "a table")?;
    let (names, written): (Vec<String>, Vec<&str>) =
        tabulated_names(file, names, &defined)?.into_iter().unzip();
    let system = with_instances(file, &names, &written, &defined)?;
    // What fails is a bracket of the file's functions, not the names given.
    let table = BracketTable::compute(&system, &names).map_err(|e| {
        file.computation_failed(&format!("the brackets of {}", names.join(", ")), &e)
    })?;
    let written = written_in_functions(file, &table);
    let entry = Entry::Table(TableResult::new(table, &system, &file.the_name()));
    let mut report = file.one_entry(
        format!("Bracket table of {}", file.the_name()),
        entry,
        SummaryKind::Computed,
        start,
    );
    if !written.is_empty() {
        let entries = &mut report.sections[0].entries;
        entries.push(Entry::Text(
            "The brackets that are no combination of the listed functions, as polynomials in \
             `H` and the file's functions (each proved for every value of the parameters):"
                .to_string(),
        ));
        entries.push(Entry::Equations(Equations::new(String::new(), written)));
    }
    report.seconds = start.elapsed().as_secs_f64();
    Ok(report)
}

/// The entries of `table` above its diagonal that are no combination of its functions but a
/// polynomial in `H` and the file's functions, as `bracket` writes one (`{S, C} = 72M³ H H_x²
/// − 96M³ H_x³` for the Fokas–Lagerstrom integrals), each `{A, B} = polynomial`, restated
/// with the factor its terms share in front where it has one (`24M³(3 H − 4 H_x) H_x²`,
/// through [`Equation::in_functions`]). A polynomial
/// of degree 1 in the table's own functions is left out: the table chose the bracket over that
/// combination (`{F1, L} = Mgx`, not `−2 G1 + 2 G1'`).
fn written_in_functions(file: &LoadedSystem, table: &BracketTable) -> Vec<Equation> {
    let mut lines = Vec::new();
    for (a, row) in table.entries.iter().enumerate() {
        for (b, entry) in row.iter().enumerate().skip(a + 1) {
            let brackets::Entry::Expression(e) = entry else {
                continue;
            };
            let Some(p) = file.written_in_functions(e, None) else {
                continue;
            };
            let ring = p.vars();
            let functions: Vec<(trigpoly::Var, &str)> = ring
                .vars()
                .filter(|&v| ring.variable(v).kind() != VarKind::Parameter)
                .map(|v| (v, ring.variable(v).name()))
                .collect();
            let kinds: Vec<VarKind> = functions
                .iter()
                .map(|&(v, _)| ring.variable(v).kind())
                .collect();
            let linear = p.total_degree(&kinds).unwrap_or(0) <= 1;
            let listed = functions
                .iter()
                .filter(|(v, _)| p.contains(*v))
                .all(|(_, name)| table.names.iter().any(|n| n == name));
            if !(linear && listed) {
                let lhs = format!("{{{}, {}}}", table.display[a], table.display[b]);
                // Restated below with the factor its terms share, `24M³(3 H − 4 H_x) H_x²`,
                // where it has one.
                let in_functions = factored_in_functions(&p).is_some().then(|| p.clone());
                lines.push(Equation {
                    in_functions,
                    ..Equation::new(&lhs, p)
                });
            }
        }
    }
    lines
}

/// The names a table tabulates, each with the text that wrote it, where its refusals are
/// placed: those given, without the spaces around them (` L` is `L`), or the file's functions
/// but `H` (`defined`) when none are; refused when that leaves none.
fn tabulated_names<'a>(
    file: &LoadedSystem,
    names: &'a [impl AsRef<str>],
    defined: &'a [String],
) -> Result<Vec<(String, &'a str)>, FileError> {
    // An instance may be written `K_{2,3}` as well as `K_2_3`.
    let names: Vec<(String, &str)> = if names.is_empty() {
        defined.iter().map(|n| (n.clone(), n.as_str())).collect()
    } else {
        let braces = |n: &str| rewrite_braces(n, &file.families, &[]).trim().to_string();
        (names.iter().map(AsRef::as_ref))
            .map(|n| (braces(n), n))
            .collect()
    };
    if names.is_empty() {
        let message = match file.caller {
            Caller::CommandLine => {
                "the file defines no [[function]] to tabulate; name some on the command line, \
                 such as: superint table FILE H L"
            }
            Caller::Program => {
                "the system has no function to tabulate but H; name some in the call, such as \
                 table_report(&system, &[\"H\", \"x\"]), or add them with \
                 LoadedSystem::add_function"
            }
        };
        return Err(FileError::new(
            ErrorKind::Claim,
            &file.source.origin,
            message,
        ));
    }
    Ok(names)
}

/// The file's system with the family instances among `names` (`K_2_3`) and its phase
/// variables (`p_x`, `M1`: the Euclidean algebra's `p_x, p_y, L` with no `[[function]]` for
/// each momentum) defined as functions of it; a name that is none of them is refused with the
/// names known (`defined`: the file's functions but `H`), at its place in the text that
/// wrote it (`written`, beside each name).
fn with_instances(
    file: &LoadedSystem,
    names: &[String],
    written: &[&str],
    defined: &[String],
) -> Result<System, FileError> {
    // Every name is looked up before any family instance is expanded.
    let mut instances = Vec::new();
    let mut variables = Vec::new();
    for (name, &written) in names.iter().zip(written) {
        if file.system.get(name).is_ok() {
            continue;
        }
        if let Some(instance) = instance_of(&file.families, name) {
            instances.push((name, written, instance));
            continue;
        }
        let vars = file.system.vars();
        match vars.lookup(name).map(|v| (v, vars.variable(v).kind())) {
            Some((
                v,
                VarKind::Coordinate | VarKind::Momentum | VarKind::Poisson | VarKind::Radical,
            )) => variables.push((name, v)),
            _ => return Err(not_a_function(file, name, written, defined)),
        }
    }
    let mut system: System = file.system.clone();
    for (name, v) in variables {
        let value = file.value(&file.argument(name)?)?;
        let display = system.vars().variable(v).unicode().to_string();
        system.define(name, &display, value)?;
    }
    for (name, written, (k, m, n)) in instances {
        if system.get(name).is_ok() {
            continue; // named twice
        }
        // An error is said at the name as given (`K_{900,900}` past the term limit).
        let given = file.given("<name>", written);
        let value =
            (file.scope(file.families.len())).expand(k, m, n, &given, || trimmed(0, written).1)?;
        let display = format!("{}_{{{m},{n}}}", file.families[k].display);
        system.define(name, &display, value)?;
    }
    Ok(system)
}

/// The refusal of a name given to a table that is no function of the file, listing `H`, the
/// functions `defined`, the families' instances and the phase variables (an angle and a
/// parameter are said to be what they are), at its place in the text that wrote it,
/// `written` (` M`: the caret under `M`, in column 2).
fn not_a_function(file: &LoadedSystem, name: &str, written: &str, defined: &[String]) -> FileError {
    let mut known = vec!["H".to_string()];
    known.extend(defined.iter().cloned());
    known.extend(
        file.families
            .iter()
            .map(|f| format!("{}_{}_{}", f.name, f.indices[0], f.indices[1])),
    );
    // The file by its path on the command line; a program's system by its name.
    let of = match file.caller {
        Caller::CommandLine => file.source.origin.clone(),
        Caller::Program => file.the_name(),
    };
    let vars = file.system.vars();
    known.extend(
        vars.vars()
            .filter(|&v| {
                matches!(
                    vars.variable(v).kind(),
                    VarKind::Coordinate | VarKind::Momentum | VarKind::Poisson | VarKind::Radical
                )
            })
            .map(|v| vars.variable(v).name().to_string()),
    );
    let quoted = trigpoly::quoted_name(name);
    let what = match vars.lookup(name).map(|v| vars.variable(v).kind()) {
        Some(VarKind::Angle) => format!(
            "{quoted} is an angle, not a function of {of}: a [[function]] can name its cosine \
             or sine (value = \"cos({name})\")"
        ),
        Some(VarKind::Parameter) => {
            format!("{quoted} is a parameter, not a function of {of}: every bracket with it is 0")
        }
        _ => {
            // A name one slip from a known one is answered with it, as in an expression.
            let meant = trigpoly::did_you_mean_hint(name, &known);
            format!("{quoted} is not a function of {of}{meant}")
        }
    };
    // Refused as a whole, the caret under all of it, as a name given twice is.
    let source = file.given("<expression>", written);
    let text = Text::whole(&source);
    text.error(
        &source,
        ErrorKind::Expression,
        text.trimmed_span(),
        format!("{what} (known: {})", known.join(", ")),
    )
}

/// The certified rank of the Jacobian of expressions of the file by its phase-space
/// coordinates; with `expected`, a claim that the rank is that.
pub fn rank_report(
    file: &LoadedSystem,
    functions: &[impl AsRef<str>],
    expected: Option<usize>,
) -> Result<Report, FileError> {
    rank_report_when(file, functions, expected, None)
}

/// [`rank_report`] on a condition, as a rank claim's `when` gives one: at values of parameters
/// (`a = 1`), or on the level set of phase variables (`p_theta = I*omega`), the rank of the
/// functions restricted to it, by the phase variables it leaves free.
pub fn rank_report_when(
    file: &LoadedSystem,
    functions: &[impl AsRef<str>],
    expected: Option<usize>,
    when: Option<&str>,
) -> Result<Report, FileError> {
    let start = Instant::now();
    let parsed = functions
        .iter()
        .map(|f| file.argument(f.as_ref()))
        .collect::<Result<Vec<_>, _>>()?;
    file.refuse_repeated(functions, "a rank")?;
    let condition = when.map(|w| file.rank_condition(w)).transpose()?;
    let mut names = Vec::new();
    let mut exprs = Vec::new();
    for arg in &parsed {
        let (name, value) = file.expand(arg)?;
        names.push(name);
        exprs.push(match &condition {
            Some(c) => c
                .apply_where_defined(&value, "a function")
                .map_err(|e| file.error_under(when, &e))?,
            None => value,
        });
    }
    let written = functions
        .iter()
        .map(AsRef::as_ref)
        .collect::<Vec<&str>>()
        .join(" ");
    // Each function's place in the list, its spaces aside.
    let mut spans = Vec::new();
    let mut offset = 0;
    for f in functions {
        let f = f.as_ref();
        let lead = f.len() - f.trim_start().len();
        spans.push(offset + lead..offset + f.trim_end().len());
        offset += f.len() + 1;
    }
    let source = file.given("<expression>", &written);
    let claim = RankClaim {
        source: &source,
        id: "rank",
        expect: Expect::Proved,
        // A refusal (no sample point where the functions are defined, say) is about all of
        // them: the caret underlines the whole list; one of a function's derivatives, that one.
        span: 0..written.len(),
        functions: spans,
        start,
    };
    let mut rank = file.rank_result(
        claim,
        names.clone(),
        &exprs,
        expected.unwrap_or(0),
        condition.as_ref(),
    )?;
    if expected.is_none() {
        // No claim: the rank is what was found.
        rank.expected = rank.certificate.rank;
        rank.claim.proved = true;
        rank.claim.note = None;
        // `rank_result` stated the rank claimed; this one states the rank found.
        rank.claim.statement = RankResult::statement(
            &names,
            file.system.vars(),
            rank.coordinates(),
            rank.expected,
        );
    }
    Ok(file.one_entry(
        format!("Functional independence in {}", file.the_name()),
        Entry::Rank(rank),
        // A system built in code or given by `--system` is no file to count.
        SummaryKind::Check {
            files: usize::from(file.source.given.about_file()),
        },
        start,
    ))
}
