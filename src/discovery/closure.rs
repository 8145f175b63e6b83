//! The report of `superint closure` ([`closure_report`]): the brackets of the generated algebra
//! in its generators, the relations among them, each proved.

use crate::render::tex::Names;
use std::time::Instant;

use brackets::closure::{closure_of, relation_text, Bracket, Closure, ClosureOptions};
use brackets::{EngineError, NamedFunction, System};
use trigpoly::{LimitKind, Style, VarKind};

use crate::report::{
    counted, listed, written_in_functions, ClaimResult, ClosureFacts, Entry, Equation, Equations,
    Facts, Report, Section, SummaryKind, TableResult,
};

use crate::system_file::{Caller, FileError, Given, LimitSettings, LoadedSystem};

use super::{agreeing, off_one_note, parameter_facts, parameter_names, HeldAt};

/// The report of a closure: the structure table, what lies outside, every bracket and relation
/// proved. The generators need not be functions of the system (an instance `P_{1,1}`, a
/// bracket); with names the system defines, [`brackets::closure()`] gives the [`Closure`] alone.
/// `name` is the system as a title names it: `the harmonic rotor` ([`super::search_report`]).
/// Its advice names the library's options (`ClosureOptions::degree`); [`closure_report_for`]
/// chooses the caller.
///
/// ```
/// use superint::brackets::{systems, ClosureOptions, NamedFunction};
/// use superint::discovery::closure_report;
///
/// // su(2): L, G1, G2 close on themselves, {G1, G2} = −ω² L, with the Casimir of degree 2.
/// let rotor = systems::harmonic_rotor();
/// let generators: Vec<NamedFunction> = ["L", "G1", "G2"]
///     .iter()
///     .map(|&n| Ok(NamedFunction::new(n, n, rotor.get(n)?.clone())))
///     .collect::<Result<_, superint::brackets::EngineError>>()?;
/// let options = ClosureOptions::new(2);
/// let (report, algebra) = closure_report("the harmonic rotor", &rotor, &generators, &options)?;
/// assert!(algebra.closes() && report.all_proved());
/// assert_eq!(algebra.render_bracket(1, 2), "−ω² L");
/// # Ok::<(), superint::brackets::EngineError>(())
/// ```
pub fn closure_report(
    name: &str,
    system: &System,
    generators: &[NamedFunction],
    options: &ClosureOptions,
) -> Result<(Report, Closure), EngineError> {
    closure_report_for(name, system, generators, options, Caller::Program)
}

/// [`closure_report`] built for `caller`: its advice names the command line's options
/// (`--degree`) for [`Caller::CommandLine`], as `superint closure` prints it, and so does its
/// error where a limit of the ring stopped the closure: an [`EngineError::PastLimit`] of that
/// limit that says to raise it or lower the degree (`raise it with Limits::max_terms, or
/// lower ClosureOptions::degree`; `--max-terms N`, `--degree` on the command line).
pub fn closure_report_for(
    name: &str,
    system: &System,
    generators: &[NamedFunction],
    options: &ClosureOptions,
    caller: Caller,
) -> Result<(Report, Closure), EngineError> {
    let settings = LimitSettings::of(Given::InCode.by(caller));
    closure_report_in(name, system, generators, options, settings)
}

/// [`closure_report_for`] whose advice at a limit names `settings` ([`advised`]): the command
/// line's, or a program's for a system in code or a file's ([`file_closure_report`]).
fn closure_report_in(
    name: &str,
    system: &System,
    generators: &[NamedFunction],
    options: &ClosureOptions,
    settings: LimitSettings,
) -> Result<(Report, Closure), EngineError> {
    let caller = settings.caller();
    let start = Instant::now();
    let c = closure_of(system, generators, options).map_err(|e| advised(settings, e))?;
    let holding = Holding {
        held: HeldAt::new(options.condition.as_ref(), system.vars(), &c.parameters),
        fixed: !c.parameters.is_empty(),
    };
    let Unlifted {
        results,
        stuck,
        stuck_in_table,
    } = unlifted_count(&c, &holding);
    let gens: Vec<String> = c.display.iter().map(|g| format!("`{g}`")).collect();
    let gens = gens.join(", ");
    let when = c
        .condition
        .clone()
        .map(|c| format!(" at `{c}`"))
        .unwrap_or_default();
    let structure = Structure {
        name,
        system,
        generators,
        options,
        c: &c,
        holding: &holding,
        when: &when,
        results,
        stuck,
        stuck_in_table,
        caller,
    };
    let names = Names::of_system(system);
    let sections = vec![
        structure.section(&gens).map_err(|e| advised(settings, e))?,
        relations_section(&c, &holding, names, !options.symbolic.is_empty()),
    ];
    Ok((
        Report {
            title: format!("Closure of {gens} for {}{when}", name),
            subtitle: String::new(),
            sections,
            summary: SummaryKind::Claims,
            seconds: start.elapsed().as_secs_f64(),
            caller,
        },
        c,
    ))
}

/// A closure stopped at a limit of the ring, `e` (the products of the generators together
/// past the term limit, or one operation past the term, work or degree limit), said with
/// what to do about it in `settings`, the one place where the command line's advice
/// and the library's are worded: raise the limit that stopped it, where one reaches it, or
/// lower the degree, up to which the products of the generators are formed (`raise it with
/// Limits::max_terms, or lower ClosureOptions::degree` for a system built in code,
/// `LimitsOverride::max_terms` for a file's; `--max-terms N`, `--degree` on the command
/// line): the setting and the most the degree limit may be are those a limit's hint names
/// for the same giver ([`LimitSettings::setting`], [`LimitSettings::degree_ceiling`]). The
/// algebra's own advice (`raise the limit or simplify the input`) gives way to it. The error is then an [`EngineError::PastLimit`] of the same limit
/// ([`EngineError::limit`]), whose message says so. Any other error is as it is: the
/// closure's own limit, `ClosureOptions::max_monomials`, says to lower the degree or raise
/// the limit, and the caller's hint names the option.
fn advised(settings: LimitSettings, e: EngineError) -> EngineError {
    let (said, limit, raise) = match &e {
        // The products of the generators together: the term limit raises them, or a lower
        // degree forms fewer.
        EngineError::ClosureTooManyTerms { limit, .. } => (
            e.to_string(),
            *limit,
            format!(
                "raise it with {}, or ",
                settings.setting("--max-terms N", "max_terms")
            ),
        ),
        // Which product passed it is the engine's own business; what the caller can
        // change is the limit or the degree (the machine's memory has no setting: only a
        // lower degree forms less).
        EngineError::Algebra(a) => {
            let raise = |setting: String| format!("raise the limit with {setting}, or ");
            let raise = match a.limit() {
                None => return e,
                Some(LimitKind::Terms) => raise(settings.setting("--max-terms N", "max_terms")),
                Some(LimitKind::Work) => {
                    raise(settings.setting("--max-term-products N", "max_term_products"))
                }
                // A degree past the most the degree limit may be has no setting either.
                Some(LimitKind::Degree(n)) if n > settings.degree_ceiling() => format!(
                    "no limit reaches this exponent ({} is at most {}): ",
                    settings.setting("--max-degree", "max_degree"),
                    settings.degree_ceiling()
                ),
                Some(LimitKind::Degree(_)) => {
                    raise(settings.setting("--max-degree D", "max_degree"))
                }
                Some(_) => String::new(),
            };
            // The limit in force as a count; 0 for the machine's memory, which has none.
            let limit = a
                .limit_in_force()
                .map_or(0, |n| usize::try_from(n).unwrap_or(usize::MAX));
            (a.without_advice(), limit, raise)
        }
        _ => return e,
    };
    let Some(which) = e.limit() else {
        return e;
    };
    let degree = settings
        .caller()
        .names("--degree", "ClosureOptions::degree");
    let formed = match e {
        EngineError::ClosureTooManyTerms { .. } => "",
        _ => " (the products of the generators up to it are formed)",
    };
    EngineError::PastLimit {
        which,
        limit,
        message: format!("{said}; {raise}lower {degree}{formed}"),
    }
}

/// Which symbols of the table and its equations stand for which generators, where the
/// generators cannot all be symbols shown by their display names (two would print alike)
/// and their names stand for them: `Kr stands for Re K and Ki for Im K`; `None` where every
/// symbol is its display name (`∂H`, `x(t)` too, as the rest of the report prints them).
fn symbols_text(c: &Closure) -> Option<Entry> {
    let renamed: Vec<String> = c
        .symbols
        .iter()
        .zip(&c.display)
        .map(|(&v, display)| (c.ring.variable(v).unicode(), display))
        .filter(|(symbol, display)| symbol != display)
        .enumerate()
        .map(|(k, (symbol, display))| match k {
            0 => format!("`{symbol}` stands for `{display}`"),
            _ => format!("`{symbol}` for `{display}`"),
        })
        .collect();
    (!renamed.is_empty()).then(|| {
        Entry::Text(format!(
            "In the table and its equations, {}: their display names cannot be written as \
             symbols.",
            listed(&renamed)
        ))
    })
}

/// The closure of generators of a system file named as the file names them, as
/// `superint closure FILE NAMES` computes it: [`closure_report_for`] of the generators that
/// [`LoadedSystem::closure_generators`] reads from `names` (a function by its name or its
/// display, `Omega` or `Ω`; a family instance, `P_1_1` or `P_{1,1}`; a phase variable, `p_x`),
/// each printed by the file's display (`P_{1,1}`), the report's sections about the file. A
/// blank name, a function given twice, an expression given as a name (`2*L`: add it with
/// [`LoadedSystem::add_function`] and name it), a parameter or a name the file does not know
/// is refused before anything is computed, of kind
/// [`ErrorKind::Expression`](crate::system_file::ErrorKind),
/// at its line and column in the name (`<expression>`, a blank one `<name>`, or
/// `<command line>` as the file's [`Caller`] says); what the engine then refuses (a limit, a
/// condition the flow leaves) is an error of the file without a place, of kind `Limit` (with
/// the hint to raise the limit, [`ClosureOptions::max_monomials`] included; a limit of the
/// ring's message says to raise it or lower the degree, as [`closure_report_for`]'s does, a
/// program's limits named `LimitsOverride::max_terms`, as the loader takes them, or
/// `Limits::max_terms` for a system built in code, [`LoadedSystem::of_system`]) or `Engine`,
/// as [`table_report`](crate::system_file::table_report)'s are, the engine's error kept
/// ([`FileError::engine`]): a refusal of the condition
/// ([`EngineError::RefusedCondition`], `M = 0` where a generator divides by `M`) is placed in
/// the condition's text by [`LoadedSystem::condition_refusal`], as a search's is. `caller`
/// chooses whose options the report's advice names, as for [`closure_report_for`].
///
/// ```
/// use superint::discovery::relation_text;
/// use superint::prelude::*;
///
/// // su(2) in the harmonic rotor's file: {G1, G2} = −ω² L, and the Casimir
/// // 4 G1² + G2² + ω² L² is (F1 − F2)², the one relation of degree 2.
/// let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let names = ["F1", "F2", "L", "G1", "G2"];
/// let options = ClosureOptions::new(2);
/// let (report, algebra) = file_closure_report(&rotor, &names, &options, Caller::Program)?;
/// assert!(algebra.closes() && report.all_proved());
/// assert_eq!(algebra.render_bracket(3, 4), "−ω² L");
/// let relations: Vec<String> = algebra.relations.iter().map(|r| relation_text(&r.poly)).collect();
/// assert_eq!(relations, ["ω² L² + 2 F1 F2 + 4 G1² + G2² = F1² + F2²"]);
///
/// // A generator given as an expression has no name for the table: refused at its place.
/// let err = file_closure_report(&rotor, &["L", "G1", "L*G1"], &options, Caller::Program)
///     .unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((1, 1))));
/// assert!(err.to_string().starts_with("<expression>:1:1: 'L*G1' is an expression"), "{err}");
/// # Ok::<(), FileError>(())
/// ```
pub fn file_closure_report(
    file: &LoadedSystem,
    names: &[impl AsRef<str>],
    options: &ClosureOptions,
    caller: Caller,
) -> Result<(Report, Closure), FileError> {
    let generators = file.closure_generators(names, &[])?;
    let (report, closure) = closure_report_in(
        &file.the_name(),
        file.system(),
        &generators,
        options,
        LimitSettings::of(file.source().given.by(caller)),
    )
    .map_err(|e| file.computation_failed("computing the closure", &e))?;
    Ok((report.about_file(&file.source().origin), closure))
}

/// How many brackets and relations a closure found, and how many hold at the fixed values only.
struct Unlifted {
    /// The brackets (off the table's diagonal, polynomials in the generators) and relations.
    results: usize,
    /// Those of them that hold at the fixed values only.
    stuck: usize,
    /// The brackets among `stuck`: where there are none, every entry of the table holds for
    /// every value (a table of zeros does, whatever relation could not be lifted).
    stuck_in_table: usize,
}

/// What the closure `c` found, and what of it holds at the fixed values only.
fn unlifted_count(c: &Closure, holding: &Holding) -> Unlifted {
    let brackets: Vec<bool> = c
        .brackets
        .iter()
        .enumerate()
        .flat_map(|(a, row)| row.iter().skip(a + 1))
        .filter_map(|b| match b {
            Bracket::Polynomial { symbolic, .. } => Some(*symbolic),
            Bracket::Outside { .. } => None,
        })
        .collect();
    let stuck = |symbolic: &[bool]| symbolic.iter().filter(|&&s| holding.unlifted(s)).count();
    let relations: Vec<bool> = c.relations.iter().map(|r| r.symbolic).collect();
    Unlifted {
        results: brackets.len() + relations.len(),
        stuck: stuck(&brackets) + stuck(&relations),
        stuck_in_table: stuck(&brackets),
    }
}

/// What section 1 of a closure's report is written from: the closure, the system and options
/// it was computed with, and where its results hold.
struct Structure<'a> {
    /// The system as a title names it: `the harmonic rotor`.
    name: &'a str,
    system: &'a System,
    generators: &'a [NamedFunction],
    options: &'a ClosureOptions,
    c: &'a Closure,
    holding: &'a Holding,
    /// The condition as a title says it, `` at `p_θ = Iω` ``, or nothing.
    when: &'a str,
    /// The number of brackets and relations found.
    results: usize,
    /// How many of them hold at the fixed values only.
    stuck: usize,
    /// How many of those are brackets of the table.
    stuck_in_table: usize,
    /// Who the report is for, whose options its advice names.
    caller: Caller,
}

impl Structure<'_> {
    /// Section 1: how the brackets were found, the structure table, what lies outside it,
    /// each bracket proved, and the facts for JSON. `gens` names the generators.
    fn section(&self, gens: &str) -> Result<Section, EngineError> {
        let mut entries = vec![self.method_text(gens)];
        entries.extend(self.condition_text());
        entries.extend(symbolic_text(self.system, self.options));
        entries.extend(symbols_text(self.c));
        entries.push(self.table());
        let outside = self.c.outside();
        if outside.is_empty() {
            entries.push(Entry::Text(format!(
                "The table closes: every bracket is a polynomial of degree `≤ {}` in the \
                 generators.",
                self.c.degree
            )));
        } else {
            entries.extend(outside_entries(
                self.system,
                self.generators,
                self.options,
                self.c,
                self.when,
                self.caller,
            )?);
        }
        let brackets = bracket_claims(self.c, self.holding);
        let shown = brackets.len();
        entries.extend(brackets);
        entries.push(self.facts(&outside, shown));
        Ok(Section {
            number: 1,
            title: "Structure".into(),
            file: None,
            entries,
            names: Names::of_system(self.system),
        })
    }

    /// How the brackets were written in the generators: the degree, the monomials and their
    /// span, and whether the coefficients found at fixed values were lifted back to the
    /// parameters.
    fn method_text(&self, gens: &str) -> Entry {
        let c = self.c;
        let fixed = self.holding.held.fixed();
        let off_one = off_one_note(self.system.vars(), c.denominator_zero_at_one);
        let lift = match (c.parameters.is_empty(), self.stuck) {
            (true, _) => String::new(),
            (false, 0) => format!(
                " at `{fixed}`{off_one}, the coefficients then lifted back to the parameters by \
                 homogeneity"
            ),
            (false, k) => format!(
                " at `{fixed}`{off_one}, the coefficients then lifted back to the parameters by homogeneity \
                 where the weights allow: {k} of the {} brackets and relations could not be \
                 lifted, and {} at `{fixed}` only ({}; {})",
                self.results,
                agreeing(k, "holds", "hold"),
                match self.stuck_in_table {
                    0 => "the table holds for every value",
                    _ => "so does the table",
                },
                self.symbolic_advice(),
            ),
        };
        Entry::Text(format!(
            "Every bracket `{{G_a, G_b}}` of the generators {gens} written as a polynomial of \
             degree `≤ {}` in them, by exact linear algebra on the {} (their span has dimension \
             {}){lift}; each expansion checked by the engine.",
            c.degree,
            counted(c.monomials, "monomial"),
            c.rank,
        ))
    }

    /// Under a condition that sets a variable of the phase space (`p_θ = Iω`), how it is
    /// applied: each bracket is formed from the generators on the whole phase space and only
    /// then set on the condition, and written in the generators set there. A bracket
    /// differentiates along that variable, so it cannot be set to a constant first: at
    /// `p_θ = Iω` of the 3:5 rotor `F2 = ω²I/2` is a constant, and `{F2, J1} = −3ω J2` all
    /// the same. A condition on the parameters alone (`a = 2b`) commutes with the bracket
    /// and gets no note.
    fn condition_text(&self) -> Option<Entry> {
        let condition = self.options.condition.as_ref()?;
        let vars = self.system.vars();
        let set: Vec<String> = condition
            .subs()
            .iter()
            .filter(|(v, _)| vars.variable(*v).kind() != VarKind::Parameter)
            .map(|(v, _)| format!("`{}`", vars.variable(*v).unicode()))
            .collect();
        if set.is_empty() {
            return None;
        }
        let at = &condition.text;
        Some(Entry::Text(format!(
            "{} {} of the phase space, along which a bracket differentiates: each bracket \
             is formed from the generators on the whole phase space and only then set at \
             `{at}`, and written in the generators set there, so a generator that is a \
             constant at `{at}` may still have brackets that are not zero.",
            listed(&set),
            agreeing(set.len(), "is a variable", "are variables"),
        )))
    }

    /// How to find for every value what could not be lifted: keep the fixed parameters
    /// symbolic (`--symbolic a1,a2,a3`, or `ClosureOptions::symbolic` for a program).
    fn symbolic_advice(&self) -> String {
        match self.caller {
            Caller::CommandLine => {
                let names: Vec<&str> = (self.c.parameters.iter())
                    .map(|(v, _)| self.system.vars().variable(*v).name())
                    .collect();
                format!(
                    "`--symbolic {}` keeps the parameters symbolic, for every value",
                    names.join(",")
                )
            }
            Caller::Program => {
                "`ClosureOptions::symbolic` keeps the parameters symbolic, for every value"
                    .to_string()
            }
        }
    }

    /// The structure table, titled with where it holds: at the fixed values too when some
    /// result could not be lifted.
    fn table(&self) -> Entry {
        let fixed = self.holding.held.fixed();
        let table_at = match (self.stuck_in_table, &self.c.condition) {
            (0, _) => self.when.to_string(),
            (_, Some(c)) => format!(" at `{c}`, `{fixed}`"),
            (_, None) => format!(" at `{fixed}`"),
        };
        Entry::Table(
            TableResult::new(
                self.c.table(),
                self.system,
                &format!("{}{table_at}", self.name),
            )
            .in_functions(),
        )
    }

    /// The closure's facts for JSON: the generators, the linear algebra, the parameters, the
    /// brackets outside, and the labels of the `shown` bracket claims and of the relations.
    fn facts(&self, outside: &[(usize, usize)], shown: usize) -> Entry {
        let (c, options) = (self.c, self.options);
        let symbolic = &options.symbolic[..];
        Entry::Data(Facts::Closure(ClosureFacts {
            generators: c.names.clone(),
            degree: c.degree,
            monomials: c.monomials,
            rank: c.rank,
            parameters: parameter_facts(
                self.system.vars(),
                &c.parameters,
                (!symbolic.is_empty()).then_some((symbolic, options.parameters_degree)),
                &c.condition,
            ),
            outside: outside
                .iter()
                .map(|&(a, b)| (c.names[a].clone(), c.names[b].clone()))
                .collect(),
            unlifted: self.stuck,
            brackets: (1..=shown).map(|k| format!("B{k}")).collect(),
            relations: (1..=c.relations.len()).map(|k| format!("R{k}")).collect(),
        }))
    }
}

/// Where a result of the closure holds: on the condition, and at the fixed parameters' values
/// too when it could not be lifted back to the parameters.
struct Holding {
    /// The condition and the fixed parameters' values.
    held: HeldAt,
    /// Whether some parameter was fixed for the linear algebra.
    fixed: bool,
}

impl Holding {
    /// Whether a result proved symbolically or not holds at the fixed values only.
    fn unlifted(&self, symbolic: bool) -> bool {
        !symbolic && self.fixed
    }

    /// The claim of a result the closure found and proved (`B1`, `R2`): where it holds, and a
    /// note when that is at the fixed values only.
    fn claim(&self, id: &str, statement: &str, ascii: &str, symbolic: bool) -> ClaimResult {
        let unlifted = self.unlifted(symbolic);
        let note =
            unlifted.then(|| "not lifted back to the parameters (no symbolic lift)".to_string());
        ClaimResult::derived(id, statement, true, note)
            .at(self.held.at(unlifted))
            .written(ascii)
    }
}

/// What keeping parameters symbolic means for the closure, when some are.
fn symbolic_text(system: &System, options: &ClosureOptions) -> Option<Entry> {
    if options.symbolic.is_empty() {
        return None;
    }
    let names: Vec<&str> = options
        .symbolic
        .iter()
        .map(|v| system.vars().variable(*v).unicode())
        .collect();
    Some(Entry::Text(format!(
        "Parameters kept symbolic: `{}`. The coefficients are polynomials of degree `≤ {}` \
         in them, found from the symbolic expansions, so what is found holds for every value \
         of them.",
        names.join(", "),
        options.parameters_degree
    )))
}

/// A claim `B1, B2, …` for each nonzero bracket of the table that is a polynomial in the
/// generators.
fn bracket_claims(c: &Closure, holding: &Holding) -> Vec<Entry> {
    let r = c.names.len();
    let mut claims = Vec::new();
    for a in 0..r {
        for b in a + 1..r {
            let Bracket::Polynomial { poly, symbolic } = &c.brackets[a][b] else {
                continue;
            };
            if poly.is_zero() {
                continue;
            }
            let statement = format!(
                "{{{}, {}}} = {}",
                c.display[a],
                c.display[b],
                written_in_functions(poly, Style::Unicode)
            );
            let ascii = format!(
                "{{{}, {}}} = {}",
                c.names[a],
                c.names[b],
                written_in_functions(poly, Style::Ascii)
            );
            let id = format!("B{}", claims.len() + 1);
            claims.push(Entry::Claim(
                holding.claim(&id, &statement, &ascii, *symbolic),
            ));
        }
    }
    claims
}

/// Section 2: the minimal relations among the generators, each a claim `R1, R2, …`: none a
/// combination of those above it (of lower degree, or of its degree and simpler) times
/// polynomials in the generators and, when some are kept `symbolic`, in the parameters, as far
/// as the degree searched shows; every relation of that degree is such a combination of them.
fn relations_section(c: &Closure, holding: &Holding, names: Names, symbolic: bool) -> Section {
    let mut entries = vec![Entry::Text(format!(
        "The polynomial relations among the generators up to degree {}, each minimal (not a \
         combination of those above it times polynomials in the generators{}, as far as this \
         degree shows), each checked by expanding it; every relation up to this degree is such \
         a combination of them.",
        c.degree,
        if symbolic {
            " and in the symbolic parameters"
        } else {
            ""
        }
    ))];
    if c.relations.is_empty() {
        entries.push(Entry::Text("None.".into()));
    }
    for (k, rel) in c.relations.iter().enumerate() {
        let ascii = format!("{} = 0", rel.poly.render(Style::Ascii));
        entries.push(Entry::Claim(holding.claim(
            &format!("R{}", k + 1),
            &relation_text(&rel.poly),
            &ascii,
            rel.symbolic,
        )));
    }
    Section {
        number: 2,
        title: "Relations".into(),
        file: None,
        entries,
        names,
    }
}

/// The brackets outside the generators' polynomials of the closure's degree, each written
/// out, with advice: which generators are no integrals (their brackets need not close), or
/// how the table might close.
fn outside_entries(
    system: &System,
    generators: &[NamedFunction],
    options: &ClosureOptions,
    c: &Closure,
    when: &str,
    caller: Caller,
) -> Result<Vec<Entry>, EngineError> {
    let outside = c.outside();
    let moving = moving_generators(system, generators, options, &outside)?;
    let symbolic = !options.symbolic.is_empty();
    let advice = closing_advice(&moving, when, symbolic, caller);
    // With parameters kept symbolic, the coefficients' degree in them bounds the search too.
    let coefficients = match symbolic {
        true => format!(
            " with coefficients of degree `≤ {}` in `{}`",
            options.parameters_degree,
            parameter_names(system.vars(), &options.symbolic)
        ),
        false => String::new(),
    };
    Ok(vec![
        Entry::Text(format!(
            "The brackets marked `*` are no polynomials of degree `≤ {}` in the \
             generators{coefficients}; here they are. {advice}",
            c.degree
        )),
        outside_equations(c, &outside),
    ])
}

/// The generators in a bracket `outside` the table that are no integrals (their flow does
/// not vanish, under the condition if any), each as `` `display` ``.
fn moving_generators(
    system: &System,
    generators: &[NamedFunction],
    options: &ClosureOptions,
    outside: &[(usize, usize)],
) -> Result<Vec<String>, EngineError> {
    // A generator that is no integral has brackets with no reason to close among
    // integrals; what search finds closes a table of integrals.
    let mut moving = Vec::new();
    for (
        g,
        NamedFunction {
            display, expr: e, ..
        },
    ) in generators.iter().enumerate()
    {
        if !outside.iter().any(|&(a, b)| a == g || b == g) {
            continue;
        }
        let flow = match &options.condition {
            Some(cond) => system.flow_when(e, cond)?,
            None => system.flow(e)?,
        };
        if !flow.vanishes()? {
            moving.push(format!("`{display}`"));
        }
    }
    Ok(moving)
}

/// The advice after the brackets outside the table: that the `moving` generators, no
/// integrals, need not close among the others, or, when every generator is an integral, how
/// the table might close (with parameters kept `symbolic`, by their degree too), in the
/// options of `caller`.
fn closing_advice(moving: &[String], when: &str, symbolic: bool, caller: Caller) -> String {
    let degree = caller.names("--degree", "ClosureOptions::degree");
    let search = caller.names("superint search", "discovery::search_report");
    match moving.len() {
        // No degree gives a coefficient that divides by a symbolic parameter (`−3C/M`).
        0 if symbolic => format!(
            "A higher `{degree}` or `{}`, or what `{search}` finds added to the generators, may \
             close the table; a coefficient that divides by a parameter (`1/M`) is no \
             polynomial in it at any degree: leave that parameter out of `{}`, and it is fixed \
             and lifted back by homogeneity.",
            caller.names("--parameters-degree", "ClosureOptions::parameters_degree"),
            caller.names("--symbolic", "ClosureOptions::symbolic"),
        ),
        0 => format!(
            "A higher `{degree}`, or what `{search}` finds added to the generators, may close \
             the table."
        ),
        1 => format!(
            "{} is no integral (its bracket with `H` is not zero{when}), so its brackets \
             need not close among the others.",
            moving[0]
        ),
        _ => format!(
            "{} are no integrals (their brackets with `H` are not zero{when}), so their \
             brackets need not close among the others.",
            moving.join(", ")
        ),
    }
}

/// The brackets `outside` the table, each written out: `{A, B} = …`.
fn outside_equations(c: &Closure, outside: &[(usize, usize)]) -> Entry {
    Entry::Equations(Equations::new(
        String::new(),
        outside
            .iter()
            .map(|&(a, b)| {
                let Bracket::Outside { bracket } = &c.brackets[a][b] else {
                    unreachable!("outside() lists the brackets outside")
                };
                let lhs = format!("{{{}, {}}}", c.display[a], c.display[b]);
                Equation::new(&lhs, bracket.clone())
            })
            .collect(),
    ))
}
