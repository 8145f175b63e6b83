//! `superint check FILE...`: every claim of some system files, proved or refuted.

use std::path::PathBuf;

use super::input::load_system;
use clap::Args;
use superint::render::render;
use superint::system_file::{check_report, LimitsOverride};

use super::limits::LimitsArgs;
use super::output::{emit, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint check systems/harmonic-rotor.toml
  superint check systems/*.toml --format json --no-timings
  superint check mine.toml --max-terms 100000 --max-degree 200

A system file declares a phase space, a Hamiltonian, named functions and claims such as
  [[claim]]
  id = \"C09\"
  claim = \"{L, G1} = -G2\"
(see docs/system-files.md). Exit status: 0 every claim as expected (proved, or refuted when
marked expect = \"refuted\"), 1 a claim not as expected, 2 bad input.";

/// Arguments of `superint check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// System files (TOML, see docs/system-files.md); - reads one from standard input.
    #[arg(value_name = "FILE", required = true)]
    files: Vec<PathBuf>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The check job, as plain data.
#[derive(Debug)]
pub struct CheckJob {
    pub files: Vec<PathBuf>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl CheckArgs {
    pub fn job(self, output: Output) -> CheckJob {
        CheckJob {
            files: self.files,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Loads every file, checks every claim and prints the report; whether every claim met its
/// expectation.
pub fn run(job: &CheckJob) -> anyhow::Result<bool> {
    let files = job
        .files
        .iter()
        .map(|p| load_system(p, &job.limits))
        .collect::<Result<Vec<_>, _>>()?;
    let report = check_report(&files)?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_as_expected())
}
