//! `superint search [FILE] --when … --momenta-degree d --positions-degree e --trig-degree k
//! --poisson-degree P`: a basis of every integral in a finite space, by exact linear algebra,
//! each proved.

use std::path::{Path, PathBuf};

use super::input::load_system;
use anyhow::{anyhow, bail, Context};
use brackets::search::{
    BesideLevelSet, SearchOptions, SearchSpace, DEFAULT_MAX_MINOR, DEFAULT_MAX_PRODUCTS,
    MAX_RANK_MINORS,
};
use brackets::{EngineError, System};
use clap::Args;
use superint::discovery::{
    builtin_system, builtin_system_refused, command_line_report_of, command_line_search_report,
    exceptional_values_report, parse_condition_checked, parse_fixed, parse_known, parse_symbolic,
    ListRefusal,
};
use superint::render::{render, Format};
use superint::report::{with_article, Report};
use superint::system_file::{
    display_as_given, looks_like_name, new_name_refusal, what_is, Caller, LoadedSystem,
};
use superint::system_file::{
    ErrorKind, FileError, Given, LimitsOverride, Warning, Warnings, COMMAND_LINE,
};
use trigpoly::{Expr, VarKind};

use super::limits::LimitsArgs;
use super::output::{emit, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \\
      --momenta-degree 4 --positions-degree 4 --trig-degree 4
  superint search --system harmonic --when 'p_theta = 2*I*omega' --momenta-degree 2 \\
      --positions-degree 2 --trig-degree 2 --new-only
  superint search systems/smorodinsky-winternitz-i.toml --momenta-degree 2 \\
      --positions-degree 4 --trig-degree 0 --laurent
  superint search --system anisotropic-3-5 --when 'p_theta = I*omega' --fix omega=1,M=2
  superint search systems/henon-heiles.toml --momenta-degree 2 --positions-degree 4 \\
      --trig-degree 0 --when 'C = 2' --symbolic A,B
  superint search systems/henon-heiles.toml --find-values C --fix A=1,B=1 \\
      --momenta-degree 2 --positions-degree 4 --trig-degree 0
  superint search systems/kovalevskaya-top.toml --poisson-degree 4
  superint search systems/euler-top.toml --poisson-degree 2 --fix I1=1,I2=2,I3=3

Parameters are fixed to rational values for the linear algebra (1 unless --fix says
otherwise, and the output says which); every basis element is then lifted back to
symbolic parameters by homogeneity and proved symbolically where the system allows.
Parameters named by --symbolic are never fixed: the unknowns are polynomials in them, and
the output lists the integrals that generate all the others over those polynomials.
--find-values C finds the values of C at which the space holds more integrals than for a
generic C (Hietarinta's direct method, done exactly).
Built-in systems (--system): harmonic, gravity, anisotropic-3-5, anisotropic-1-2,
planar-i, planar-ii.";

/// The degree of the space in each kind of variable when its option is not given, as the
/// options' help says (`[default: 2]`; a test compares): the options are `Option`s, so that
/// a degree given for variables the system lacks can be refused.
const DEFAULT_DEGREE: u32 = 2;
/// The degree in the radicals when `--radicals-degree` is not given.
const DEFAULT_RADICALS_DEGREE: u32 = 1;

/// Arguments of `superint search`.
#[derive(Debug, Args)]
pub struct SearchArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input; or use
    /// --system.
    #[arg(value_name = "FILE", required_unless_present = "system")]
    file: Option<PathBuf>,
    /// A built-in system instead of a file: harmonic, gravity, anisotropic-3-5,
    /// anisotropic-1-2, planar-i, planar-ii.
    #[arg(long, value_name = "NAME", conflicts_with = "file")]
    system: Option<String>,
    /// The condition applied after the bracket, such as 'p_theta = m*I*omega/n'.
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    /// Search on a level set EXPR = VALUE that the flow of H keeps, such as
    /// 'M1*gamma1 + M2*gamma2 + M3*gamma3 = 0' (EXPR a polynomial in the coordinates, momenta
    /// and Poisson variables, VALUE a constant): finds the integrals K, in normal form modulo
    /// P = EXPR − VALUE, with {K, H} = Q·P, each identity checked exactly. Not with --when
    /// (give parameters their values with --fix), --symbolic or --laurent; with --new-only,
    /// known integrals and products are taken modulo P.
    #[arg(long, value_name = "LEVEL")]
    on: Option<String>,
    /// Total degree in the momenta (an angle's momentum that --when fixes is left out)
    /// [default: 2]. A degree above 0 is refused on a system without such variables.
    #[arg(long, allow_negative_numbers = true,
          value_name = "D",
          value_parser = super::in_range::<u32>(0, 20))]
    momenta_degree: Option<u32>,
    /// Total degree in the coordinates, not the angles (sum of absolute exponents)
    /// [default: 2].
    #[arg(long, allow_negative_numbers = true,
          value_name = "E",
          value_parser = super::in_range::<u32>(0, 20))]
    positions_degree: Option<u32>,
    /// Trigonometric order in the angles [default: 2].
    #[arg(long, allow_negative_numbers = true,
          value_name = "K",
          value_parser = super::in_range::<u32>(0, 20))]
    trig_degree: Option<u32>,
    /// Total degree in the Poisson variables, those whose brackets [poisson] declares (M1,
    /// gamma1; one that --when fixes is left out) [default: 2].
    #[arg(long, allow_negative_numbers = true,
          value_name = "P",
          value_parser = super::in_range::<u32>(0, 20))]
    poisson_degree: Option<u32>,
    /// Allow negative powers of the coordinates (Laurent potentials such as β/x²).
    #[arg(long)]
    laurent: bool,
    /// On a system with denominators, the total degree of their powers: 2 takes 1/(x − y)²
    /// and 1/((x − y)(x − z)) [default: 2].
    #[arg(long, allow_negative_numbers = true,
          value_name = "K",
          value_parser = super::in_range::<u32>(0, 12))]
    denominators_degree: Option<u32>,
    /// On a system with radicals, the total degree of their powers, of either sign: 1 takes
    /// r and 1/r, 2 also r², 1/r² and r/s [default: 1].
    #[arg(long, allow_negative_numbers = true,
          value_name = "J",
          value_parser = super::in_range::<u32>(0, 12))]
    radicals_degree: Option<u32>,
    /// Parameter values for the linear algebra, such as omega=1,M=2/3 or M=0.5 (a decimal is
    /// the fraction it writes; others are 1, or other values where 1 makes a declared
    /// denominator zero).
    #[arg(long, value_name = "VALUES")]
    fix: Option<String>,
    /// Find the values of one parameter, such as C, at which the space holds more integrals
    /// than at a generic value: the rank of the equations, with the parameter kept, drops
    /// there, at a root of a determinant computed exactly. Each rational root is searched at
    /// and shown as --when 'C = VALUE' shows it, those with more integrals told apart; the
    /// other roots, irrational or complex, are ruled out where every block of the equations
    /// keeps its rank there, and the polynomial of those that are not is printed. The other
    /// parameters are fixed (--fix, 1 by default). With --on, on that level set (its
    /// polynomial without the parameter), each value searched at as --fix shows it. Not with
    /// --symbolic, --new-only or a --when that sets the parameter.
    #[arg(long, value_name = "PARAM", conflicts_with_all = ["symbolic", "new_only"])]
    find_values: Option<String>,
    /// With --find-values, stop with an error at a block of the equations whose minor has more
    /// than N rows (default 250: its determinant takes some 10 s at 250 rows, its time growing about as the fourth power of N).
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", requires = "find_values",
          default_value_t = DEFAULT_MAX_MINOR as u64,
          value_parser = super::Quoting(super::at_least_one))]
    max_minor: u64,
    /// Parameters kept symbolic, such as A,B: the coefficients of the integrals are then
    /// polynomials in them (of total degree at most --parameters-degree), and what is found
    /// holds for every value of them.
    #[arg(long, value_name = "PARAMS")]
    symbolic: Option<String>,
    /// Total degree in the parameters kept symbolic.
    #[arg(long, allow_negative_numbers = true,
          value_name = "S", default_value_t = 2, requires = "symbolic",
          value_parser = super::in_range::<u32>(0, 12))]
    parameters_degree: u32,
    /// Show only the new integrals, those that nothing known generates. An integral is
    /// generated when it is a sum of the file's named integrals, --known ones, constants and
    /// products of integrals of lower grade (with --symbolic, parameter multiples too, and an
    /// integral F whose multiple by a monomial in the parameters, ω²F say, or by a declared
    /// denominator of them alone, a1 − a2 say, lies in the space and is generated by the rest
    /// of this rule, applied again: F = K/ω² is not new where K is generated, when K lies
    /// within --parameters-degree); a grade is the degree in the
    /// coordinates, momenta and Poisson variables together (the powers of a denominator,
    /// 1/(x − y), and of a radical, r or 1/r, count with the coordinates), then the
    /// trigonometric order (where cos θ and p are integrals, cos 2θ = 2cos²θ − 1 and p cos θ
    /// are generated). A
    /// product of integrals of the same grade is not counted: with three rotors, cos(a − c)
    /// is new beside cos(a − b) and cos(b − c), though it is a polynomial in them and their
    /// sines.
    #[arg(long)]
    new_only: bool,
    /// With --new-only, decide what is new by elimination over Q alone (slower). By default it
    /// is decided modulo a 62-bit prime with every dependency checked over Q, which could
    /// report an integral new that is not only if the prime divides a minor of the products'
    /// span.
    #[arg(long, requires = "new_only")]
    exact_complement: bool,
    /// With --new-only, stop with an error past N products of integrals.
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", requires = "new_only",
          default_value_t = DEFAULT_MAX_PRODUCTS as u64,
          value_parser = super::Quoting(super::at_least_one))]
    max_products: u64,
    /// More known integrals for --new-only: expressions or family instances (P_1_1),
    /// separated by commas. Each must be a real integral (under --when; with --on, on the
    /// level set, taken modulo P); one that is not is an error.
    #[arg(long, value_name = "EXPRS", requires = "new_only")]
    known: Option<String>,
    /// Threads for forming the equations, solving them, proving the integrals and printing
    /// them (default: one per core, or RAYON_NUM_THREADS). The output is the same for any.
    #[arg(long, allow_negative_numbers = true,
          value_name = "N",
          value_parser = super::in_range::<u16>(1, super::MAX_THREADS))]
    threads: Option<u16>,
    #[command(flatten)]
    limits: LimitsArgs,
}

impl SearchArgs {
    /// Refuses a degree option given for a kind of variable the system does not have
    /// (`--poisson-degree` on the Kepler problem), which would bound nothing: the search
    /// would run as if it were not given.
    fn refuse_degrees_without_variables(&self, subject: &Subject) -> anyhow::Result<()> {
        let system = subject.system();
        let vars = system.vars();
        let pairs = system.space().pairs();
        let angles = pairs
            .iter()
            .filter(|p| vars.variable(p.q).kind() == VarKind::Angle)
            .count();
        // A top on e(3)* has no coordinates at all, a rotor in no potential only angles.
        let no_coordinates = match angles {
            0 => "no coordinates",
            _ => "no coordinates other than angles",
        };
        let options: [(&str, bool, &str); 7] = [
            (
                "--momenta-degree",
                self.momenta_degree.is_some_and(|d| d > 0) && pairs.is_empty(),
                "no canonical momenta",
            ),
            (
                "--positions-degree",
                self.positions_degree.is_some_and(|d| d > 0) && pairs.len() == angles,
                no_coordinates,
            ),
            (
                "--laurent",
                self.laurent && pairs.len() == angles,
                no_coordinates,
            ),
            (
                "--trig-degree",
                self.trig_degree.is_some_and(|d| d > 0) && angles == 0,
                "no angles",
            ),
            (
                "--poisson-degree",
                self.poisson_degree.is_some_and(|d| d > 0)
                    && system.space().poisson_variables().is_empty(),
                "no Poisson variables (a file declares their brackets in [poisson])",
            ),
            (
                "--denominators-degree",
                self.denominators_degree.is_some_and(|d| d > 0)
                    && vars.denominators().next().is_none(),
                "no denominators",
            ),
            (
                "--radicals-degree",
                self.radicals_degree.is_some_and(|d| d > 0) && vars.radicals().next().is_none(),
                "no radicals",
            ),
        ];
        match options.iter().find(|(_, refused, _)| *refused) {
            Some((option, _, lacks)) => bail!(
                "{option}: {} has {lacks}, so it would bound nothing; leave it out",
                subject.the_name()
            ),
            None => Ok(()),
        }
    }
}

/// Refuses, with `--on`, what a search on a level set does not take beside it
/// ([`BesideLevelSet::for_search`], which words it), before the level set's text is read:
/// the option that asked for it, named: `--when`, `--symbolic`.
fn refuse_beside_level_set(options: &SearchOptions) -> anyhow::Result<()> {
    let Some(refused) = BesideLevelSet::for_search(options) else {
        return Ok(());
    };
    let option = match refused {
        BesideLevelSet::PhaseCondition { .. } | BesideLevelSet::ParameterCondition => "--when",
        BesideLevelSet::Symbolic => "--symbolic",
        _ => bail!("a search on a level set does not take {refused}"),
    };
    bail!(
        "--on does not take {option}, {}: {}",
        refused.what(),
        refused.why("--fix")
    )
}

/// The level set `text` of `--on`, `EXPR = VALUE`, read and checked
/// ([`brackets::search::LevelSet::check`], at the fixed values of `options`; with the parameter
/// `searched_for` by `--find-values` free, `LevelSet::check_for_values_of`; in a Laurent
/// space where its space is one): each refusal placed in `text` as a condition's is,
/// `<command line>:1:C:` with a caret, at the part it is about.
fn level_set(
    subject: &Subject,
    text: &str,
    options: &SearchOptions,
    searched_for: Option<trigpoly::Var>,
) -> anyhow::Result<brackets::search::LevelSet> {
    let (fixed, laurent) = (&options.fixed, options.space.laurent);
    let refuse = |span: std::ops::Range<usize>, message: String| -> anyhow::Error {
        let error = FileError::at(ErrorKind::Condition, COMMAND_LINE, text, span, message);
        named("--on", error)
    };
    let signs: Vec<usize> = text.match_indices('=').map(|(i, _)| i).collect();
    let eq = match signs.as_slice() {
        [] => {
            return Err(refuse(
                0..text.len(),
                "no '=': write the level set as EXPR = VALUE, such as \
                 'M1*gamma1 + M2*gamma2 + M3*gamma3 = 0'"
                    .into(),
            ))
        }
        [eq] => *eq,
        [_, second, ..] => {
            return Err(refuse(
                *second..*second + 1,
                "a second '=': a level set is one equation, EXPR = VALUE".into(),
            ))
        }
    };
    // Each side where it stands, without the blanks around it (an empty side at the sign).
    let trimmed = |start: usize, end: usize| {
        let part = &text[start..end];
        let from = start + (part.len() - part.trim_start().len());
        let to = end - (part.len() - part.trim_end().len());
        match from < to {
            true => from..to,
            false => eq..eq + 1,
        }
    };
    let (lhs, rhs) = (trimmed(0, eq), trimmed(eq + 1, text.len()));
    if text[lhs.clone()].trim().is_empty() || lhs == (eq..eq + 1) {
        return Err(refuse(eq..eq + 1, "no expression before '='".into()));
    }
    if rhs == (eq..eq + 1) {
        return Err(refuse(eq..eq + 1, "no value after '='".into()));
    }
    let place = |e: FileError| anyhow!(e.to_string());
    let expr = subject
        .listed_error("--on", text, lhs.clone())
        .map_err(place)?;
    let value = subject
        .listed_error("--on", text, rhs.clone())
        .map_err(place)?;
    let level = brackets::search::LevelSet::new(text, expr, value);
    if let Err(e) = level.check_value(subject.system()) {
        return Err(refuse(rhs, e.to_string()));
    }
    let checked = match searched_for {
        Some(parameter) => level.check_for_values_of(subject.system(), fixed, parameter, laurent),
        None => level.check(subject.system(), fixed, laurent),
    };
    match checked {
        Ok(()) => Ok(level),
        Err(e) => Err(refuse(lhs, e.to_string())),
    }
}

/// The search job, as plain data.
#[derive(Debug)]
pub struct SearchJob {
    pub args: SearchArgs,
    pub output: Output,
}

impl SearchArgs {
    pub fn job(self, output: Output) -> SearchJob {
        SearchJob { args: self, output }
    }
}

/// `e`, the error of reading the file `path`, with a hint that a built-in system is given
/// with --system where the path is a built-in system's name and no file (`superint bracket
/// harmonic L H`).
fn builtin_hint(e: FileError, path: &Path) -> FileError {
    let name = path.to_string_lossy();
    if e.kind != ErrorKind::Io
        || path.exists()
        || !superint::discovery::BUILTIN_SYSTEMS.contains(&name.as_ref())
    {
        return e;
    }
    e.with_hint(format!(
        "{name} is a built-in system: give it with --system {name}, in place of FILE"
    ))
}

/// The system a discovery command works on: a loaded file or a built-in system.
pub enum Subject {
    /// A system file.
    File(Box<LoadedSystem>),
    /// A built-in system, with its name and what the command line's texts about it read in
    /// doubt (names run together, [`Warning`]), kept as a file keeps its own.
    Builtin(String, Box<System>, Warnings),
}

impl Subject {
    /// Loads a file or looks up a built-in system (with its resonant functions `P11`, …
    /// when `resonant`).
    pub fn open(
        file: Option<&PathBuf>,
        builtin: Option<&str>,
        resonant: bool,
        limits: &LimitsOverride,
    ) -> anyhow::Result<Subject> {
        if let Some(name) = builtin {
            let limits = limits.or_defaults();
            let built = builtin_system(name, resonant, limits)
                .map_err(|e| builtin_system_refused(name, resonant, limits, &e))?;
            return match built {
                Some((display, s)) => {
                    Ok(Subject::Builtin(display, Box::new(s), Warnings::default()))
                }
                None => bail!(
                    "unknown system {} (built-in: {})",
                    trigpoly::quoted_name(name),
                    superint::discovery::BUILTIN_SYSTEMS.join(", ")
                ),
            };
        }
        let path = file.ok_or_else(|| anyhow!("give a system file or --system NAME"))?;
        let loaded = load_system(path, limits).map_err(|e| builtin_hint(e, path))?;
        Ok(Subject::File(Box::new(loaded)))
    }

    /// The system as the reports of a system file take it ([`LoadedSystem`]): a file's own, or
    /// a built-in system's, whose texts the command line gives, named `--system builtin`.
    pub fn into_loaded(self, builtin: &str) -> LoadedSystem {
        match self {
            Subject::File(f) => *f,
            Subject::Builtin(display, s, _) => LoadedSystem::of_system(*s)
                .with_caller(Caller::CommandLine)
                .with_origin(&format!("--system {builtin}"))
                .with_name(&display),
        }
    }

    /// `result`, once what the file's texts and the command line's read in doubt is printed
    /// ([`super::output::print_warnings`], as [`super::output::warned`] prints a file's):
    /// however the work ended.
    pub fn warned<T, E>(&self, result: Result<T, E>) -> Result<T, E> {
        super::output::print_warnings(&self.warnings().list());
        result
    }

    /// What the file's texts and the command line's read in doubt, each place once: a file's
    /// own, or those a built-in system's subject keeps beside it.
    fn warnings(&self) -> &Warnings {
        match self {
            Subject::File(f) => f.kept_warnings(),
            Subject::Builtin(_, _, noted) => noted,
        }
    }

    /// The error of what the command line asked of this subject, `doing` (`searching for
    /// integrals`), that the engine refused, `e`: where the condition is refused (it sets to 0
    /// what is divided by, or the flow of `H` leaves it), shown at its variable's value in
    /// `when`, the `--when` text; where a limit stopped it, of kind `limit` from the file or
    /// `--system NAME` (`builtin`), with the hint naming the flag (then the file's
    /// `[limits]`), the engine's message naming no setting; else said after `doing`.
    pub fn refused(
        &self,
        builtin: Option<&str>,
        doing: &str,
        when: Option<&str>,
        e: EngineError,
    ) -> anyhow::Error {
        // A refusal of the condition (it sets to 0 what the Hamiltonian or a generator divides
        // by, or the flow leaves its surface) at its variable's value in --when, as the
        // reading's own refusals are shown.
        if let Some(placed) = self.condition_refusal(when, &e) {
            return placed.into();
        }
        let (origin, given) = match self {
            Subject::File(f) => (f.source().origin.clone(), Given::CommandLineAboutFile),
            Subject::Builtin(..) => (
                format!("--system {}", builtin.unwrap_or_default()),
                Given::CommandLineAboutBuiltIn,
            ),
        };
        match FileError::limit_on_command_line(&origin, given, doing, &e) {
            Some(limited) => limited.into(),
            None => anyhow::Error::from(e).context(doing.to_string()),
        }
    }

    /// The report `report` about this subject: about its file, if it is one.
    pub fn tag(&self, report: Report) -> Report {
        match self {
            Subject::File(f) => report.about_file(&f.source().origin),
            Subject::Builtin(..) => report,
        }
    }

    pub fn system(&self) -> &System {
        match self {
            Subject::File(f) => f.system(),
            Subject::Builtin(_, s, _) => s,
        }
    }

    /// How a name given on the command line prints, as a generator or a known integral
    /// ([`display_as_given`]): a function or family instance of a file as the file shows it
    /// (`Z̄` for `Zbar`, `K̄_{1,2}` for `Kbar_1_2` or `Kbar_{1,2}`), any other name of an
    /// instance's shape as an instance is shown (`R_{1,1}` for a `--define R_1_1`), and an
    /// expression (`x*p_y`) as it is written.
    pub fn display_name(&self, name: &str) -> String {
        display_as_given(name, |n| match self {
            Subject::File(f) => f.display_name(n),
            Subject::Builtin(_, s, _) => s.display_name(n).to_string(),
        })
    }

    /// How a known integral given on the command line prints: a name as
    /// [`Subject::display_name`] prints it, and an expression of a file as the file's claims
    /// print one (`{L_x, A_xy}` for `{Lx, Axy}`, `L²` for `L^2`), beside the file's functions
    /// in their printed names, and one of a built-in system so too (`x p_x` for `x*p_x`).
    pub fn known_name(&self, known: &str) -> String {
        if looks_like_name(known) {
            return self.display_name(known);
        }
        let shown = match self {
            Subject::File(f) => f.shown_argument(known),
            Subject::Builtin(_, s, _) => {
                LoadedSystem::of_system(s.as_ref().clone()).shown_argument(known)
            }
        };
        shown.unwrap_or_else(|_| known.to_string())
    }

    /// The system's name as a title says it: `the harmonic rotor`, or `t1` for a file that
    /// names none (its own stem).
    pub fn the_name(&self) -> String {
        match self {
            Subject::File(f) => f.the_name(),
            Subject::Builtin(n, ..) => with_article(n),
        }
    }

    /// Why `name` is refused as a new name of the system, if it is, before anything is
    /// computed ([`new_name_refusal`]: not an identifier, reserved, a name the system has, or
    /// one it reads as a product of its names), for the caller to place.
    pub fn new_name_refusal(&self, name: &str) -> Option<String> {
        let what = || match self {
            Subject::File(f) => f.what_is(name),
            Subject::Builtin(_, s, _) => what_is(s, &[], name),
        };
        new_name_refusal(name, what, || {
            self.warnings().unwarned(|| self.parse(name).is_ok())
        })
    }

    /// Whether `src` reads as an expression, [`Subject::parse`] without keeping what it reads
    /// in doubt: the error placed in `src`, of its kind (`limit` where a limit stopped it).
    pub fn parsed_unwarned(&self, src: &str) -> Result<(), FileError> {
        self.warnings()
            .unwarned(|| self.parse_placed(src, src, 0).map(drop))
    }

    /// Parses an expression: named functions, family instances, brackets. What it reads in
    /// doubt is kept, to be printed by [`Subject::warned`] (a file keeps its own).
    pub fn parse(&self, src: &str) -> Result<Expr, String> {
        self.parse_in(src, src, 0)
    }

    /// [`Subject::parse`] of `src`, which begins at byte `at` of `text` (a value of a
    /// condition): what it reads in doubt, and its error, are placed in `text`, as typed.
    fn parse_in(&self, text: &str, src: &str, at: usize) -> Result<Expr, String> {
        self.parse_placed(text, src, at).map_err(|e| e.to_string())
    }

    /// The expression at `span` of the list `text` given to `option` (`--known`), read as
    /// [`Subject::parse`] reads one, with what it reads in doubt placed in `text`; its error is
    /// said as [`list_refused`] says a refusal of the list, `<command line>:1:C:` with the
    /// option named, the text and a caret under the place.
    pub fn listed(
        &self,
        option: &str,
        text: &str,
        span: std::ops::Range<usize>,
    ) -> anyhow::Result<Expr> {
        self.listed_error(option, text, span)
            .map_err(|e| anyhow!(e.to_string()))
    }

    /// [`Subject::listed`], its error as the `FileError` it is rendered from, which keeps what
    /// kind of error its parse met ([`FileError::cause`]).
    pub fn listed_error(
        &self,
        option: &str,
        text: &str,
        span: std::ops::Range<usize>,
    ) -> Result<Expr, FileError> {
        self.parse_placed(text, &text[span.clone()], span.start)
            .map_err(|e| with_option(option, e))
    }

    /// [`Subject::parse_in`], its error as the command line's text's error.
    fn parse_placed(&self, text: &str, src: &str, at: usize) -> Result<Expr, FileError> {
        match self {
            Subject::File(f) => f.parse_argument_within(text, at..at + src.len()),
            Subject::Builtin(_, s, noted) => {
                // The value where it stands, after blanks as wide as what comes before it
                // (its line breaks kept), so that each place said, the caret's and one in a
                // message (`'(' opened at column 5`), is its place in `text`.
                let blank: String = text[..at]
                    .chars()
                    .map(|c| if c == '\n' { c } else { ' ' })
                    .collect();
                let shift = at - blank.len();
                let placed = blank + src;
                // An error is rendered as a file's command-line text's is, and as the
                // warnings below are: `<command line>:1:5:`, then the numbered line; one
                // that a limit stopped is of kind `limit`, with its hint (`with_cause`).
                let (e, readings) =
                    Expr::parse_noting(s.vars(), &placed, s.as_ref()).map_err(|e| {
                        let span = shift + e.span.start..shift + e.span.end;
                        FileError::at(ErrorKind::Expression, COMMAND_LINE, text, span, e.message())
                            .with_cause(e.cause(), Given::CommandLineAboutBuiltIn)
                    })?;
                for r in &readings {
                    let w = Warning::run_together(
                        COMMAND_LINE,
                        text,
                        shift + r.span.start..shift + r.span.end,
                        r,
                        &|p| s.display_name(p).to_string(),
                        // A built-in system's names are fixed: no advice to declare one.
                        false,
                    );
                    // Each place once, as a file keeps them.
                    noted.warn(w);
                }
                Ok(e)
            }
        }
    }

    /// `e`, where it is a refusal of the condition read from `when`
    /// ([`EngineError::RefusedCondition`], which a computation under it met), placed in
    /// `when` at the value of the variable it is about, as [`Subject::condition`] places its
    /// own refusals; `None` for another error, or no `when`.
    fn condition_refusal(&self, when: Option<&str>, e: &EngineError) -> Option<FileError> {
        let (w, EngineError::RefusedCondition { .. }) = (when?, e) else {
            return None;
        };
        match self {
            Subject::File(f) => Some(f.condition_refusal(w, e)),
            Subject::Builtin(..) => self.builtin_condition(w, &|_| Err(e.clone())).err(),
        }
    }

    pub fn condition(&self, when: Option<&str>) -> anyhow::Result<Option<brackets::Condition>> {
        when.map(|w| match self {
            Subject::File(f) => f.condition(w).map_err(anyhow::Error::from),
            Subject::Builtin(..) => self.builtin_condition(w, &|_| Ok(())).map_err(Into::into),
        })
        .transpose()
    }

    /// A built-in system's condition `w` from the command line, with what its use asks of it
    /// besides (`check`, [`parse_condition_checked`]), refused as a file's command-line
    /// condition is: `<command line>:1:C:`, the numbered line and a caret.
    fn builtin_condition(
        &self,
        w: &str,
        check: &dyn Fn(&brackets::Condition) -> Result<(), EngineError>,
    ) -> Result<brackets::Condition, FileError> {
        let refuse =
            |span, message| FileError::at(ErrorKind::Condition, COMMAND_LINE, w, span, message);
        let parse = |s: &str, at| self.parse_placed(w, s, at);
        let given = Given::CommandLineAboutBuiltIn;
        parse_condition_checked(self.system(), w, &parse, &refuse, given, check)
    }

    /// The parameters `--fix` gives values, refused as a condition is
    /// ([`list_refused`]).
    pub fn fixed(
        &self,
        fix: Option<&str>,
    ) -> anyhow::Result<Vec<(trigpoly::Var, trigpoly::Rational)>> {
        match fix {
            Some(f) => parse_fixed(self.system(), f).map_err(|e| list_refused("--fix", f, e)),
            None => Ok(Vec::new()),
        }
    }

    /// The parameters `--symbolic` names, refused as a condition is ([`list_refused`]).
    pub fn symbolic(&self, names: &str) -> anyhow::Result<Vec<trigpoly::Var>> {
        parse_symbolic(self.system(), names).map_err(|e| list_refused("--symbolic", names, e))
    }
}

/// A refusal of the list `text` given to `option` (`--fix`, `--symbolic`), shown as a
/// command-line condition's is: `<command line>:1:C:`, the option and what is wrong, then the
/// numbered line and a caret under the place it is about.
pub(super) fn list_refused(option: &str, text: &str, refusal: ListRefusal) -> anyhow::Error {
    let error = FileError::at(
        ErrorKind::Schema,
        COMMAND_LINE,
        text,
        refusal.span,
        refusal.message,
    );
    named(option, error)
}

/// An error placed in the text given to `option`, with the option named before its message:
/// `<command line>:1:C: --known: unknown name 'zz'`.
fn named(option: &str, error: FileError) -> anyhow::Error {
    anyhow!(with_option(option, error).to_string())
}

/// The error with `option` named before its message.
fn with_option(option: &str, mut error: FileError) -> FileError {
    error.message = format!("{option}: {}", error.message);
    error
}

/// Searches and prints, on a pool of `--threads` threads if asked.
pub fn run(job: &SearchJob) -> anyhow::Result<bool> {
    match job.args.threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n.into())
            .build()
            .context("starting the threads")?
            .install(|| search_and_print(job)),
        None => search_and_print(job),
    }
}

fn search_and_print(job: &SearchJob) -> anyhow::Result<bool> {
    let a = &job.args;
    let subject = Subject::open(
        a.file.as_ref(),
        a.system.as_deref(),
        false,
        &a.limits.settings(),
    )?;
    let report = subject.warned(search(a, &subject, &job.output))?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_proved())
}

/// The search of `subject` that `a` asks for, as a report to print as `output` says.
fn search(a: &SearchArgs, subject: &Subject, output: &Output) -> anyhow::Result<Report> {
    let format = output.format;
    a.refuse_degrees_without_variables(subject)?;
    let mut space = SearchSpace::default()
        .momenta_degree(a.momenta_degree.unwrap_or(DEFAULT_DEGREE))
        .positions_degree(a.positions_degree.unwrap_or(DEFAULT_DEGREE))
        .trig_degree(a.trig_degree.unwrap_or(DEFAULT_DEGREE))
        .poisson_degree(a.poisson_degree.unwrap_or(DEFAULT_DEGREE))
        .denominators_degree(a.denominators_degree.unwrap_or(DEFAULT_DEGREE))
        .radicals_degree(a.radicals_degree.unwrap_or(DEFAULT_RADICALS_DEGREE));
    if a.laurent {
        space = space.laurent();
    }
    let mut options = SearchOptions::new(space);
    options.condition = subject.condition(a.when.as_deref())?;
    options.fixed = subject.fixed(a.fix.as_deref())?;
    if let Some(names) = &a.symbolic {
        options.symbolic = subject.symbolic(names)?;
        options.space = options.space.parameters_degree(a.parameters_degree);
    }
    if let Some(on) = &a.on {
        refuse_beside_level_set(&options)?;
        // With --find-values, its parameter is free where the flow must keep the level set.
        let searched_for = (a.find_values.as_deref())
            .and_then(|name| subject.system().vars().lookup(name.trim()))
            .filter(|&v| subject.system().vars().variable(v).kind() == VarKind::Parameter);
        options.on = Some(level_set(subject, on, &options, searched_for)?);
    }
    if let Some(names) = &a.find_values {
        options.max_minor = usize::try_from(a.max_minor).unwrap_or(usize::MAX);
        return find_values(a, subject, output, &options, names);
    }
    options.new_only = a.new_only;
    options.exact_complement = a.exact_complement;
    options.max_products = usize::try_from(a.max_products).unwrap_or(usize::MAX);
    let mut known_spans = Vec::new();
    if let Some(known) = &a.known {
        for span in parse_known(known).map_err(|e| list_refused("--known", known, e))? {
            let e = subject.listed("--known", known, span.clone())?;
            options
                .known
                .push((subject.known_name(&known[span.clone()]), e));
            known_spans.push(span);
        }
    }
    // A file's integrals are restated in its functions and family instances too.
    let found = match subject {
        Subject::File(file) => command_line_search_report(
            Some(file),
            &file.the_name(),
            file.system(),
            &options,
            format,
        ),
        Subject::Builtin(name, system, _) => {
            command_line_search_report(None, &with_article(name), system, &options, format)
        }
    };
    let (report, _) = found.map_err(|e| match (e, a.known.as_deref()) {
        // A known integral refused is placed in the list, as a name it does not know is.
        (
            EngineError::RefusedKnown {
                index,
                name,
                reason,
            },
            Some(known),
        ) if index < known_spans.len() => {
            let refusal = ListRefusal {
                span: known_spans[index].clone(),
                message: format!("{name} {reason}"),
            };
            list_refused("--known", known, refusal)
        }
        (e, _) => subject.refused(
            a.system.as_deref(),
            "searching for integrals",
            a.when.as_deref(),
            e,
        ),
    })?;
    Ok(subject.tag(report))
}

/// The values of the parameter `names` (one) with more integrals, the search at a generic
/// value and at each of them as `--when` shows it (with `a`'s own `--when` after), as a
/// report to print as `output` says.
fn find_values(
    a: &SearchArgs,
    subject: &Subject,
    output: &Output,
    options: &SearchOptions,
    names: &str,
) -> anyhow::Result<Report> {
    let (format, whole) = (output.format, output.options.shown_monomials.is_none());
    let start = std::time::Instant::now();
    let parameters = parse_symbolic(subject.system(), names)
        .map_err(|e| list_refused("--find-values", names, e))?;
    let [parameter] = parameters[..] else {
        bail!(
            "--find-values solves for one parameter, and '{names}' names {}: fix the others \
             with --fix",
            parameters.len()
        );
    };
    let system = subject.system();
    let name = system.vars().variable(parameter).name().to_string();
    let refused = |e| {
        subject.refused(
            a.system.as_deref(),
            &format!("finding the values of {name} with more integrals"),
            a.when.as_deref(),
            e,
        )
    };
    let candidates =
        brackets::search::exceptional_candidates(system, options, parameter).map_err(refused)?;
    let file = match subject {
        Subject::File(f) => Some(f.as_ref()),
        Subject::Builtin(..) => None,
    };
    // Each candidate searched once, as its report shows it: under `--when 'C = VALUE'` (with
    // `a`'s own after), or with C fixed there, as `--fix` does, on a level set, which takes no
    // condition, and where a declared denominator holds C: a search refuses a condition that
    // makes it zero even where nothing divides by it (`--denominators-degree 0`, an `H` that
    // does not), and such a value can have more integrals (`κ = −1` of the gyroscopic rotor
    // with `κ + 1` declared), which `--fix` searches at. The engine keeps those with more
    // integrals, and takes their ranks once, which their reports show.
    let in_denominator =
        (system.space().denominator_atoms().iter()).any(|(_, d)| d.contains(parameter));
    let at = |value: &trigpoly::Rational| -> anyhow::Result<SearchOptions> {
        let mut at = options.clone();
        if options.on.is_some() || in_denominator {
            at.fixed.push((parameter, value.clone()));
        } else {
            let when = match &a.when {
                Some(w) => format!("{name} = {value}, {w}"),
                None => format!("{name} = {value}"),
            };
            at.condition = subject.condition(Some(&when))?;
        }
        Ok(at)
    };
    let found = candidates.confirm(
        |value| -> anyhow::Result<_> {
            brackets::search::search(system, &at(value)?).map_err(refused)
        },
        |value, r| -> anyhow::Result<_> {
            brackets::search::basis_rank(system, &at(value)?, r, MAX_RANK_MINORS).map_err(refused)
        },
    )?;
    let shown = std::iter::once((
        &found.determinants.generic_value,
        &found.generic,
        &found.generic_rank,
    ))
    .chain(found.values.iter().map(|v| (&v.value, &v.found, &v.rank)));
    let mut searches = Vec::new();
    for (value, r, rank) in shown {
        let report = command_line_report_of(
            file,
            &subject.the_name(),
            system,
            &at(value)?,
            format,
            r,
            Some((parameter, rank)),
        )
        .map_err(refused)?;
        searches.push(report);
    }
    let mut report = exceptional_values_report(
        &subject.the_name(),
        system,
        &found,
        searches,
        Caller::CommandLine,
        (format == Format::Json, whole),
    );
    report.seconds = start.elapsed().as_secs_f64();
    Ok(subject.tag(report))
}

#[cfg(test)]
mod tests {
    use clap::{CommandFactory, Parser};

    use super::*;
    use superint::discovery::parse_condition;

    #[derive(Parser)]
    struct Command {
        #[command(flatten)]
        args: SearchArgs,
    }

    /// The defaults the help states are the ones the search takes.
    #[test]
    fn the_degrees_help_states_are_the_defaults() {
        let command = Command::command();
        let stated = |id: &str| {
            let arg = command
                .get_arguments()
                .find(|a| a.get_id() == id)
                .expect(id);
            arg.get_help().expect("a help text").to_string()
        };
        for id in [
            "momenta_degree",
            "positions_degree",
            "trig_degree",
            "poisson_degree",
            "denominators_degree",
        ] {
            let help = stated(id);
            assert!(
                help.contains(&format!("[default: {DEFAULT_DEGREE}]")),
                "{id}: {help}"
            );
        }
        let help = stated("radicals_degree");
        let default = format!("[default: {DEFAULT_RADICALS_DEGREE}]");
        assert!(help.contains(&default), "{help}");
    }

    /// The pieces of the texts the list readers are given: names in their spellings, the
    /// signs of a list and of a value, blanks, and characters of two bytes.
    const TOKENS: &[&str] = &[
        "omega", "ω", "\\omega", "M", "theta", "θ", "p_theta", "x", "=", ",", " ", "\t", "0", "1",
        "2", "3", "/", ".", "-", "(", ")", "{", "}", "é", "²",
    ];

    /// A file system and a built-in one, as the command line opens them.
    fn subjects() -> [Subject; 2] {
        [
            vec!["search", "systems/harmonic-rotor.toml"],
            vec!["search", "--system", "harmonic"],
        ]
        .map(|args| {
            let a = Command::parse_from(args).args;
            Subject::open(
                a.file.as_ref(),
                a.system.as_deref(),
                false,
                &a.limits.settings(),
            )
            .expect("opens")
        })
    }

    /// Whether `span` can be drawn under `text`: within it, ends on character boundaries.
    fn drawable(text: &str, span: &std::ops::Range<usize>) -> bool {
        span.start <= span.end
            && span.end <= text.len()
            && text.is_char_boundary(span.start)
            && text.is_char_boundary(span.end)
    }

    /// The readers of the command line's lists, `--fix`, `--symbolic`, `--when` and
    /// `--known`, never panic on any text, of a file system or a built-in one; every
    /// refusal's byte range can be drawn under the text (within it, on character
    /// boundaries), and the refusal is rendered as the command line renders it without a
    /// panic: `list_refused`, `Subject::listed`, `Subject::condition`. The systems are opened
    /// once, for all the cases.
    #[test]
    fn the_list_readers_refuse_at_a_drawable_place() {
        let subjects = subjects();
        let texts = proptest::collection::vec(0..TOKENS.len(), 0..14);
        let mut runner = proptest::test_runner::TestRunner::default();
        let checked = runner.run(&texts, |picks| {
            let text: String = picks.iter().map(|&k| TOKENS[k]).collect();
            for subject in &subjects {
                let system = subject.system();
                if let Err(r) = parse_fixed(system, &text) {
                    proptest::prop_assert!(drawable(&text, &r.span), "--fix {:?}: {:?}", text, r);
                    let _ = list_refused("--fix", &text, r).to_string();
                }
                if let Err(r) = parse_symbolic(system, &text) {
                    proptest::prop_assert!(
                        drawable(&text, &r.span),
                        "--symbolic {:?}: {:?}",
                        text,
                        r
                    );
                    let _ = list_refused("--symbolic", &text, r).to_string();
                }
                match parse_known(&text) {
                    Err(r) => {
                        proptest::prop_assert!(
                            drawable(&text, &r.span),
                            "--known {:?}: {:?}",
                            text,
                            r
                        );
                        let _ = list_refused("--known", &text, r).to_string();
                    }
                    Ok(spans) => {
                        for span in spans {
                            proptest::prop_assert!(
                                drawable(&text, &span),
                                "--known {:?}: {:?}",
                                text,
                                span
                            );
                            if let Err(e) = subject.listed("--known", &text, span) {
                                let _ = format!("{e:#}");
                            }
                        }
                    }
                }
                // The condition's refusals where they are made, then as the command line
                // renders them.
                let spans = std::cell::RefCell::new(Vec::new());
                let refuse = |span: std::ops::Range<usize>, message: String| {
                    spans.borrow_mut().push(span.clone());
                    FileError::at(ErrorKind::Condition, COMMAND_LINE, &text, span, message)
                };
                if let Err(e) = parse_condition(
                    system,
                    &text,
                    &|s, at| subject.parse_placed(&text, s, at),
                    &refuse,
                    Given::CommandLineAboutBuiltIn,
                ) {
                    let _ = e.to_string();
                }
                for span in spans.borrow().iter() {
                    proptest::prop_assert!(drawable(&text, span), "--when {:?}: {:?}", text, span);
                }
                if let Err(e) = subject.condition(Some(&text)) {
                    let _ = format!("{e:#}");
                }
            }
            Ok(())
        });
        if let Err(e) = checked {
            panic!("{e}");
        }
    }
}
