//! The command line: clap parses it into [`Cli`] (the raw arguments), [`Cli::job`] turns that
//! into a plain [`Job`], and [`run`] acts on it. One module per subcommand.
//!
//! Subcommands: `paper` (the default job), `tower`, `bench`, and on system files `check`,
//! `bracket`, `expand`, `table`, `rank`, `search`, `closure` and `plot`; each has a module here, a
//! variant of [`Command`] and of [`Job`].

mod bench;
mod bracket;
mod check;
mod closure;
mod expand;
mod input;
mod limits;
mod output;
pub use output::{error_line, error_message};
mod paper;
mod plot;
mod rank;
mod search;
mod table;
mod tower;

use std::ffi::OsString;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use output::OutputArgs;

/// A value parser from a function, whose refusal names the value as every message names a
/// name the command line echoes ([`trigpoly::quoted_name`]: whole, or past 80 characters its
/// first 40 and its length), where clap's echoed it whole.
#[derive(Clone)]
struct Quoting<F>(F);

impl<T, F> clap::builder::TypedValueParser for Quoting<F>
where
    T: Clone + Send + Sync + 'static,
    F: Fn(&str) -> Result<T, String> + Clone + Send + Sync + 'static,
{
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<T, clap::Error> {
        let Some(text) = value.to_str() else {
            return Err(clap::Error::new(clap::error::ErrorKind::InvalidUtf8).with_cmd(cmd));
        };
        (self.0)(text).map_err(|why| {
            let arg = arg.map_or_else(|| "...".to_string(), |a| a.to_string());
            // As clap words a refused value, with its pointer to the help.
            let message = format!(
                "invalid value {} for '{arg}': {why}\n\nFor more information, try '--help'.\n",
                trigpoly::quoted_name(text)
            );
            clap::Error::raw(clap::error::ErrorKind::ValueValidation, message).with_cmd(cmd)
        })
    }
}

/// The value parser of a whole number from `lo` to `hi` (`tower --max`, `closure --degree`),
/// which `T` holds: any other whole number, however large, is out of the range, and other
/// text no whole number, in words, where clap's ranged parser said "number too large to fit
/// in target type" of `99999999999999999999`, "invalid digit found in string" of `1.5` and
/// "cannot parse integer from empty string" of `''`, its integer parser's own words.
fn in_range<T: TryFrom<i64>>(
    lo: i64,
    hi: i64,
) -> Quoting<impl Fn(&str) -> Result<T, String> + Clone + Send + Sync + 'static> {
    Quoting(move |text: &str| {
        let t = text.trim();
        let digits = t.strip_prefix(['-', '+']).unwrap_or(t);
        match t.parse::<i64>() {
            Ok(n) if (lo..=hi).contains(&n) => {
                T::try_from(n).map_err(|_| format!("{n} is too large here"))
            }
            Ok(n) => Err(format!("{n} is not in {lo}..={hi}")),
            // Shown as the value is quoted before it, its first 40 digits past 80.
            Err(_) if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) => {
                Err(format!("{} is not in {lo}..={hi}", trigpoly::shown_name(t)))
            }
            Err(_) => Err(format!("not a whole number (from {lo} to {hi})")),
        }
    })
}

/// A count or a limit (`--max-terms`): a whole number of at least 1. `u64`'s own parser said
/// "invalid digit found in string" of `-5`.
fn at_least_one(s: &str) -> Result<u64, String> {
    match whole(s, "at least 1")? {
        0 => Err("0, where the least is 1".to_string()),
        n => Ok(n),
    }
}

/// A rank (`rank --expect`): a whole number.
fn a_rank(s: &str) -> Result<usize, String> {
    usize::try_from(whole(s, "a rank")?).map_err(|_| "too large to be a rank".to_string())
}

/// A whole number, or why not, in words (`what` it should be).
fn whole(s: &str, what: &str) -> Result<u64, String> {
    let t = s.trim();
    t.parse::<u64>().map_err(|_| match t.parse::<i128>() {
        Ok(n) if n < 0 => format!("a negative number, where a whole number ({what}) is expected"),
        Ok(_) => "too large".to_string(),
        Err(_) => format!("not a whole number ({what})"),
    })
}

/// Every claim was proved.
pub const EXIT_PROVED: u8 = 0;
/// A claim was refuted.
pub const EXIT_REFUTED: u8 = 1;
/// Bad input or usage.
pub const EXIT_USAGE: u8 = 2;

/// The most threads `--threads` asks for: each is an operating-system thread with its own
/// stack, and tens of thousands exhaust the machine before they help.
const MAX_THREADS: i64 = 256;

const EXAMPLES: &str = "\
Examples:
  superint                         check every claim of the paper, print it as text
  superint --format latex > paper.tex
  superint tower --max 24          the resonant tower {K_{m,n}, H} for 1 ≤ m, n ≤ 24

Exit status: 0 every claim as expected (proved; or refuted, where a file expects it), 1 a claim
not as expected, 2 bad input or usage.";

/// Exact Poisson-bracket identities of a rigid rotor coupled to planar potentials.
///
/// Without a subcommand, checks every claim of the paper (sections 2 to 5) and prints the
/// bracket tables, proofs and rank certificates.
#[derive(Debug, Parser)]
#[command(name = "superint", version, after_help = EXAMPLES)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    output: OutputArgs,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Check every claim of the paper (the default job).
    #[command(after_help = paper::EXAMPLES)]
    Paper(paper::PaperArgs),
    /// Check the tower {K_{m,n}, H} = i(mω − nΩ) K_{m,n} for 1 ≤ m, n ≤ N, and prove it for
    /// all m, n; or the towers of a system file's families.
    #[command(after_help = tower::EXAMPLES)]
    Tower(tower::TowerArgs),
    /// Run one performance workload once (W1–W4), printing its time and term count.
    #[command(after_help = bench::EXAMPLES)]
    Bench(bench::BenchArgs),
    /// Check every claim of system files: proved, or refuted with the residual.
    #[command(after_help = check::EXAMPLES)]
    Check(check::CheckArgs),
    /// Print the bracket {F, G} of two expressions of a system file, in normal form.
    #[command(after_help = bracket::EXAMPLES)]
    Bracket(bracket::BracketArgs),
    /// Print expressions of a system file in normal form.
    #[command(after_help = expand::EXAMPLES)]
    Expand(expand::ExpandArgs),
    /// Print the bracket table of named functions of a system file.
    #[command(after_help = table::EXAMPLES)]
    Table(table::TableArgs),
    /// Certify the rank of the Jacobian of functions of a system file.
    #[command(after_help = rank::EXAMPLES)]
    Rank(rank::RankArgs),
    /// Find a basis of every integral in a space of functions (exact linear algebra), each
    /// proved.
    #[command(after_help = search::EXAMPLES)]
    Search(search::SearchArgs),
    /// Write the brackets of generators as polynomials in them, and find their relations.
    #[command(after_help = closure::EXAMPLES)]
    Closure(closure::ClosureArgs),
    /// Draw functions along a trajectory of the flow (floating point, SVG): a picture, not a
    /// proof.
    #[command(after_help = plot::EXAMPLES)]
    Plot(plot::PlotArgs),
}

/// What to do, as plain data.
#[derive(Debug)]
pub enum Job {
    /// Check the paper.
    Paper(paper::PaperJob),
    /// Check a tower.
    Tower(tower::TowerJob),
    /// Run a performance workload.
    Bench(bench::BenchJob),
    /// Check system files.
    Check(check::CheckJob),
    /// One bracket of a system file.
    Bracket(bracket::BracketJob),
    /// Expressions of a system file in normal form.
    Expand(expand::ExpandJob),
    /// A bracket table of a system file.
    Table(table::TableJob),
    /// A rank of a system file.
    Rank(rank::RankJob),
    /// A search for integrals.
    Search(search::SearchJob),
    /// The closure of generators.
    Closure(closure::ClosureJob),
    /// A picture of a trajectory.
    Plot(plot::PlotJob),
}

impl Cli {
    /// The job the arguments ask for.
    pub fn job(self) -> Job {
        let output = self.output.settings();
        match self.command {
            None => Job::Paper(paper::PaperArgs::default().job(output)),
            Some(Command::Paper(a)) => Job::Paper(a.job(output)),
            Some(Command::Tower(a)) => Job::Tower(a.job(output)),
            Some(Command::Bench(a)) => Job::Bench(a.job(output)),
            Some(Command::Check(a)) => Job::Check(a.job(output)),
            Some(Command::Bracket(a)) => Job::Bracket(a.job(output)),
            Some(Command::Expand(a)) => Job::Expand(a.job(output)),
            Some(Command::Table(a)) => Job::Table(a.job(output)),
            Some(Command::Rank(a)) => Job::Rank(a.job(output)),
            Some(Command::Search(a)) => Job::Search(a.job(output)),
            Some(Command::Closure(a)) => Job::Closure(a.job(output)),
            Some(Command::Plot(a)) => Job::Plot(a.job(output)),
        }
    }
}

/// Parses the arguments and runs the job; usage errors print clap's message and give exit 2
/// (`--help` and `--version` give 0), but for an option after `--`, said so whether clap
/// read it as an expression or refused it ([`option_after_double_dash`]).
pub fn run<I, T>(args: I) -> anyhow::Result<ExitCode>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    let parsed = Cli::try_parse_from(&args);
    // Said whether clap read the arguments or refused them: an option after `--` that makes
    // them too many (`bracket FILE -- L H --no-timings`) was refused with clap's bare
    // "unexpected argument '--no-timings' found". `--help` and `--version` are not refusals.
    if parsed
        .as_ref()
        .map_or_else(clap::Error::use_stderr, |_| true)
    {
        if let Some(option) = option_after_double_dash(&args) {
            anyhow::bail!(
                "'{option}' follows '--', after which every word is read as an expression; \
                 put the options before '--'"
            );
        }
    }
    let cli = match parsed {
        Ok(cli) => cli,
        Err(e) => {
            // clap exits 2 for usage errors and 0 for --help/--version; keep exactly that.
            let _ = e.print();
            let code = if e.use_stderr() {
                EXIT_USAGE
            } else {
                EXIT_PROVED
            };
            return Ok(ExitCode::from(code));
        }
    };
    let all_proved = match cli.job() {
        Job::Paper(job) => paper::run(&job)?,
        Job::Tower(job) => tower::run(&job)?,
        Job::Bench(job) => bench::run(&job)?,
        Job::Check(job) => check::run(&job)?,
        Job::Bracket(job) => bracket::run(&job)?,
        Job::Expand(job) => expand::run(&job)?,
        Job::Table(job) => table::run(&job)?,
        Job::Rank(job) => rank::run(&job)?,
        Job::Search(job) => search::run(&job)?,
        Job::Closure(job) => closure::run(&job)?,
        Job::Plot(job) => plot::run(&job)?,
    };
    Ok(ExitCode::from(if all_proved {
        EXIT_PROVED
    } else {
        EXIT_REFUTED
    }))
}

/// An option of the command written after `--`, where clap reads every word as a value, an
/// expression: `expand FILE -- -x --no-timings` would read `--no-timings` as `−(−(no −
/// timings))` and refuse an unknown name 'no'. The first word after `--` that is `--NAME` or
/// `--NAME=…` for a long option the command takes, as clap reads it once built: its own, the
/// global ones, `--help`, and any alias (`--full-residuals`); if any.
fn option_after_double_dash(args: &[OsString]) -> Option<String> {
    use clap::CommandFactory;
    let dash = args.iter().skip(1).position(|a| a == "--")? + 1;
    let mut command = Cli::command();
    command.build();
    let sub = args[1..dash]
        .iter()
        .find_map(|a| command.find_subcommand(a.to_str()?))
        .unwrap_or(&command);
    let long = |name: &str| {
        sub.get_arguments().any(|arg| {
            arg.get_long() == Some(name)
                || (arg.get_all_aliases()).is_some_and(|aliases| aliases.contains(&name))
        })
    };
    args[dash + 1..].iter().find_map(|a| {
        let word = a.to_str()?;
        let name = word.strip_prefix("--")?;
        long(name.split('=').next().unwrap_or(name)).then(|| word.to_string())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_is_well_formed() {
        Cli::command().debug_assert();
    }
}
