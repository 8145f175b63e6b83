//! The command line: clap parses it into [`Cli`] (the raw arguments), [`Cli::job`] turns that
//! into a plain [`Job`], and [`run`] acts on it. One module per subcommand.
//!
//! Subcommands today: `paper` (the default job) and `tower`. The next ones (`check FILE`,
//! `bracket`, `table`, `rank`) get a module here each, a variant of [`Command`] and of [`Job`].

mod output;
mod paper;
mod tower;

use std::ffi::OsString;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use output::OutputArgs;

/// Every claim was proved.
pub const EXIT_PROVED: u8 = 0;
/// A claim was refuted.
pub const EXIT_REFUTED: u8 = 1;
/// Bad input or usage.
pub const EXIT_USAGE: u8 = 2;

const EXAMPLES: &str = "\
Examples:
  superint                         check every claim of the paper, print it as text
  superint --format latex > paper.tex
  superint tower --max 24          the resonant tower {K_{m,n}, H} for 1 ≤ m, n ≤ 24

Exit status: 0 every claim proved, 1 a claim refuted, 2 bad input or usage.";

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
    /// all m, n.
    #[command(after_help = tower::EXAMPLES)]
    Tower(tower::TowerArgs),
    // Reserved for the next subcommands, one module each: `check FILE`, `bracket`, `table`,
    // `rank`.
}

/// What to do, as plain data.
#[derive(Debug)]
pub enum Job {
    /// Check the paper.
    Paper(paper::PaperJob),
    /// Check a tower.
    Tower(tower::TowerJob),
}

impl Cli {
    /// The job the arguments ask for.
    pub fn job(self) -> Job {
        let output = self.output.settings();
        match self.command {
            None => Job::Paper(paper::PaperArgs::default().job(output)),
            Some(Command::Paper(a)) => Job::Paper(a.job(output)),
            Some(Command::Tower(a)) => Job::Tower(a.job(output)),
        }
    }
}

/// Parses the arguments and runs the job; usage errors print clap's message and give exit 2
/// (`--help` and `--version` give 0).
pub fn run<I, T>(args: I) -> anyhow::Result<ExitCode>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
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
    };
    Ok(ExitCode::from(if all_proved {
        EXIT_PROVED
    } else {
        EXIT_REFUTED
    }))
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
