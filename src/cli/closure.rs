//! `superint closure FILE NAMES... --degree d`: the brackets of the generators as polynomials
//! in them, and the polynomial relations among them.

use std::path::PathBuf;

use anyhow::{anyhow, bail};
use brackets::closure::ClosureOptions;
use brackets::{EngineLimit, NamedFunction};
use clap::Args;
use superint::discovery::{closure_report_for, ListRefusal};
use superint::render::render;
use superint::report::Report;
use superint::system_file::{
    given_twice, name_as_identifier, refuse_expression_as_generator, refuse_parameter_as_generator,
    refuse_unshowable_name, trimmed, Caller, ErrorKind, FileError, PrintedNames, COMMAND_LINE,
};
use trigpoly::Expr;

use super::input::BuiltinArg;
use super::limits::LimitsArgs;
use super::output::{emit, Output};
use super::search::{list_refused, Subject};

pub const EXAMPLES: &str = "\
Examples:
  superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 --degree 2
  superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_1_1 Q_1_1 \\
      --when 'p_theta = I*omega' --degree 2
  superint closure --system harmonic F1 F2 L G1 G2 P11 Q11 R11 S11 \\
      --when 'p_theta = I*omega' --degree 2
  superint closure --system harmonic Hp L G1 G2 Ex --define 'Ex=p_x^2/(2*M) + M*omega^2*x^2/2'
  superint closure systems/smorodinsky-winternitz-i.toml H Hx X --define 'C={Hx, X}' \\
      --degree 3 --symbolic M,alpha,beta,gamma --parameters-degree 2
  superint closure systems/calogero.toml P H I3 K1 --degree 2
  superint closure systems/fokas-lagerstrom-1-3.toml H Hx S C --degree 4   a cubic algebra

Each bracket is written as a polynomial of degree ≤ D in the generators where one exists
(coefficients Laurent monomials in the parameters), and every minimal polynomial relation of
degree ≤ D is listed (none a combination of those before it times polynomials in the
generators and, with --symbolic, in the parameters); each is checked by expanding it. On a system with denominators every
vector is multiplied by one common power of each and cleared of them first, so that the
monomials the linear algebra compares are independent. With --when, each bracket is formed
from the generators on the whole phase space and then set on the condition, and written in
the generators set there: a condition such as p_theta = I*omega sets a variable of the phase
space, along which a bracket differentiates, so it cannot be applied first.";

/// Arguments of `superint closure`.
#[derive(Debug, Args)]
pub struct ClosureArgs {
    /// A system file (or - for standard input) followed by the generators (named functions,
    /// family instances such as P_1_1, or names given by --define); with --system, only the
    /// generators.
    #[arg(value_name = "FILE NAMES", required = true, num_args = 1..)]
    args: Vec<String>,
    #[command(flatten)]
    builtin: BuiltinArg,
    /// The largest degree of the polynomials in the generators.
    #[arg(long, allow_negative_numbers = true,
          value_name = "D", default_value_t = 2,
          value_parser = super::in_range::<u32>(0, 64))]
    degree: u32,
    /// A condition, such as 'p_theta = I*omega', where the brackets and relations hold. Each
    /// bracket is formed from the generators on the whole phase space and only then set on
    /// it (p_θ is a variable of the phase space, along which a bracket differentiates, so it
    /// cannot be set to a constant first), and written in the generators set there: the
    /// harmonic rotor's F2, the constant ω²I/2 at p_θ = Iω, may still have brackets that
    /// are not zero.
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    /// Parameter values for the linear algebra, such as omega=1,M=2/3 or M=0.5 (a decimal is
    /// the fraction it writes; others are 1, or other values where 1 makes a declared
    /// denominator zero).
    #[arg(long, value_name = "VALUES")]
    fix: Option<String>,
    /// Parameters kept symbolic, such as alpha,beta: the coefficients are then polynomials in
    /// them (of total degree at most --parameters-degree), found for every value of them,
    /// where a lift from fixed values cannot tell apart parameters of one weight.
    #[arg(long, value_name = "PARAMS")]
    symbolic: Option<String>,
    /// Total degree of the coefficients in the parameters kept symbolic.
    #[arg(long, allow_negative_numbers = true,
          value_name = "S", default_value_t = 2, requires = "symbolic",
          value_parser = super::in_range::<u32>(0, 64))]
    parameters_degree: u32,
    /// Stop with an error before computing when the monomials in the generators (and the
    /// symbolic parameters) would be more than N: each is expanded and is a column of the
    /// linear system.
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", default_value_t = ClosureOptions::DEFAULT_MAX_MONOMIALS as u64,
          value_parser = super::Quoting(super::at_least_one))]
    max_monomials: u64,
    /// A generator given by its expression, NAME=EXPR (repeatable), NAME a name the system
    /// does not have.
    #[arg(long, value_name = "NAME=EXPR")]
    define: Vec<String>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The closure job, as plain data.
#[derive(Debug)]
pub struct ClosureJob {
    pub args: ClosureArgs,
    pub output: Output,
}

impl ClosureArgs {
    pub fn job(self, output: Output) -> ClosureJob {
        ClosureJob { args: self, output }
    }
}

/// Computes the closure and prints it.
pub fn run(job: &ClosureJob) -> anyhow::Result<bool> {
    let a = &job.args;
    let (file, names) = match &a.builtin.system {
        Some(_) => (None, &a.args[..]),
        None => (Some(PathBuf::from(&a.args[0])), &a.args[1..]),
    };
    let subject = Subject::open(
        file.as_ref(),
        a.builtin.system.as_deref(),
        true,
        &a.limits.settings(),
    )?;
    let report = subject.warned(close(a, names, &subject))?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_proved())
}

/// The closure of the generators `names` of `subject` as `a` asks, as a report.
fn close(a: &ClosureArgs, names: &[String], subject: &Subject) -> anyhow::Result<Report> {
    let mut defined: Vec<(String, Expr)> = Vec::new();
    // How the system's names print, and then each generator defined so far.
    let mut printed = PrintedNames::of(subject.system());
    for d in &a.define {
        // Each refusal is placed in the text given to --define, as --fix's are: the name, the
        // value, or the whole text where it has no `=`.
        let refused = |span: std::ops::Range<usize>, message: String| {
            list_refused("--define", d, ListRefusal { span, message })
        };
        let Some(eq) = d.find('=') else {
            return Err(refused(
                0..d.len(),
                "give NAME=EXPR, such as C={L, G1}".to_string(),
            ));
        };
        let (name, name_span) = trimmed(0, &d[..eq]);
        if name.is_empty() {
            return Err(refused(
                eq..eq + 1,
                "a name is missing before this =".to_string(),
            ));
        }
        if let Some(why) = subject.new_name_refusal(name) {
            return Err(refused(name_span, why));
        }
        if defined.iter().any(|(n, _)| n == name) {
            return Err(refused(
                name_span,
                format!("{name} is defined twice: give each name once"),
            ));
        }
        if let Err(why) = printed.admit(&format!("the generator {name}"), name, name) {
            return Err(refused(name_span, format!("{why}; choose another name")));
        }
        let (_, value_span) = trimmed(eq + 1, &d[eq + 1..]);
        if value_span.is_empty() {
            return Err(refused(
                eq..eq + 1,
                "an expression is missing after this =".to_string(),
            ));
        }
        let e = subject
            .listed_error("--define", d, value_span)
            .map_err(|mut e| {
                // A name that --define gives is no name of the system: say so, not how to
                // declare one in the file, at the place the parse met it.
                let given = a
                    .define
                    .iter()
                    .filter_map(|d| d.split_once('='))
                    .find(|(n, _)| e.unknown_name().is_some_and(|u| u == n.trim()));
                let why = match given {
                    Some((n, _)) if n.trim() == name => {
                        format!("its value uses {name}, the name it defines")
                    }
                    Some((n, v)) => format!(
                        "{} is given by --define, whose values use only the system's names: \
                         write its value, ({}), in its place",
                        n.trim(),
                        v.trim()
                    ),
                    None => return anyhow!(e.to_string()),
                };
                e.message = format!("--define: {why}");
                e.hint = None;
                anyhow!(e.to_string())
            })?;
        defined.push((name.to_string(), e));
    }
    if names.is_empty() && defined.is_empty() {
        bail!("give the generators: names of functions of the system, or --define NAME=EXPR");
    }
    let generators = match subject {
        // A file's names are read by the library, as `file_closure_report` reads them, each
        // generator --define gives by its value where the names name it, else after them:
        // before the options, so that a bad name is said before a bad --when, and what the
        // texts read in doubt is said in the order they are read; the engine's limits are
        // said below in the options of the command.
        Subject::File(file) => {
            let given: Vec<NamedFunction> = (defined.iter())
                .map(|(name, e)| NamedFunction::new(name, &subject.display_name(name), e.clone()))
                .collect();
            (file.closure_generators(names, &given)).map_err(|e| anyhow!(e.to_string()))?
        }
        Subject::Builtin(..) => builtin_generators(subject, names, &defined, &mut printed)?,
    };
    let mut options = ClosureOptions::new(a.degree);
    options.max_monomials = usize::try_from(a.max_monomials).unwrap_or(usize::MAX);
    options.condition = subject.condition(a.when.as_deref())?;
    options.fixed = subject.fixed(a.fix.as_deref())?;
    if let Some(names) = &a.symbolic {
        options.symbolic = subject.symbolic(names)?;
        options.parameters_degree = a.parameters_degree;
    }
    let (report, _) = closure_report_for(
        &subject.the_name(),
        subject.system(),
        &generators,
        &options,
        Caller::CommandLine,
    )
    .map_err(|e| match e.limit() {
        // A limit of the ring's error says what to do about it in the command's options
        // already (raise the limit, or lower --degree; or, past every limit, only the latter).
        Some(EngineLimit::Ring(_)) => anyhow::Error::new(e).context("computing the closure"),
        // The closure's own limit, whose engine's message names no setting: the hint does.
        _ => subject.refused(
            a.builtin.system.as_deref(),
            "computing the closure",
            a.when.as_deref(),
            e,
        ),
    })?;
    Ok(subject.tag(report))
}

/// The generators `names` of a built-in system, then those `defined` by --define that `names`
/// does not name, refused as a file's are
/// ([`LoadedSystem::closure_generators`](superint::system_file::LoadedSystem::closure_generators)),
/// but that a built-in system has no families: a name is one function however it is spelt
/// (`P_{1,1}` is `P_1_1`). `printed` is how the system's names and the generators defined
/// print.
fn builtin_generators(
    subject: &Subject,
    names: &[String],
    defined: &[(String, Expr)],
    printed: &mut PrintedNames,
) -> anyhow::Result<Vec<NamedFunction>> {
    let mut all: Vec<&str> = names.iter().map(String::as_str).collect();
    for (n, _) in defined {
        if !all.iter().any(|a| a.trim() == n) {
            all.push(n);
        }
    }
    // Each refused as a file's is, at its place in the generator as given.
    if let Some(blank) = all.iter().find(|n| n.trim().is_empty()) {
        let end = blank.find(['\n', '\r']).unwrap_or(blank.len());
        let error = FileError::at(
            ErrorKind::Expression,
            COMMAND_LINE,
            blank,
            end..end,
            "expected the name of a function, found end of input",
        );
        bail!(error.to_string());
    }
    for name in &all {
        refuse_unshowable_name(name, Caller::CommandLine, "generator")
            .map_err(|e| anyhow!(e.to_string()))?;
    }
    // A function by its name or its display (`Omega` or `Ω`) is one function.
    let key = |n: &str| match subject.system().function(n.trim()) {
        Some(f) => f.name.clone(),
        None => name_as_identifier(n),
    };
    let twice = (1..all.len()).find_map(|k| {
        (all[..k].iter())
            .find(|n| key(n) == key(all[k]))
            .map(|before| (all[k], *before))
    });
    if let Some((given, before)) = twice {
        let error = FileError::at(
            ErrorKind::Expression,
            COMMAND_LINE,
            given,
            trimmed(0, given).1,
            given_twice(given, before, "the closure"),
        );
        bail!(error.to_string());
    }
    let mut generators = Vec::new();
    for written in all {
        // The name without the spaces around it, which are no part of it; each refusal is
        // placed in the name as written.
        let name = written.trim();
        let e = match defined.iter().find(|d| d.0 == name) {
            Some(d) => d.1.clone(),
            None => {
                refuse_expression_as_generator(
                    written,
                    Caller::CommandLine,
                    |n| {
                        subject.new_name_refusal(n).is_none()
                            && printed.admit("the generator", n, n).is_ok()
                    },
                    || subject.parsed_unwarned(written),
                )
                .map_err(|e| anyhow!(e.to_string()))?;
                refuse_parameter_as_generator(
                    written,
                    Caller::CommandLine,
                    subject.system().vars(),
                )
                .map_err(|e| anyhow!(e.to_string()))?;
                // The parse error first, with its place: its excerpt shows the generator,
                // which the message put before the place and the error (`'Foo': <command
                // line>:1:1: unknown name 'Foo'`), where `bracket` and `search` begin with
                // what is wrong.
                subject.parse(written).map_err(|e| anyhow!("{e}"))?
            }
        };
        let display = subject.display_name(name);
        generators.push(NamedFunction::new(&name_as_identifier(name), &display, e));
    }
    Ok(generators)
}
