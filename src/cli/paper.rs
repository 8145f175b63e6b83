//! `superint [paper]`: check every claim of the paper (the default job).

use anyhow::Context;
use clap::Args;
use superint::paper::{Paper, PaperOptions};
use superint::render::render;
use superint::system_file::Caller;

use super::output::{emit, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint paper                       the paper's claims, tables and proofs as text
  superint paper --format markdown
  superint paper --format json --no-timings
  superint paper --tower-max 12        expand the towers to 1 ≤ m, n ≤ 12";

/// Arguments of `superint paper`.
#[derive(Debug, Args)]
pub struct PaperArgs {
    /// Expand the towers {K_{m,n}, H} for 1 ≤ m, n ≤ N.
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", default_value_t = 8,
          value_parser = super::in_range::<i64>(1, 40))]
    tower_max: i64,
}

impl Default for PaperArgs {
    fn default() -> Self {
        PaperArgs { tower_max: 8 }
    }
}

/// The paper job, as plain data.
#[derive(Debug)]
pub struct PaperJob {
    pub options: PaperOptions,
    pub output: Output,
}

impl PaperArgs {
    pub fn job(self, output: Output) -> PaperJob {
        PaperJob {
            options: PaperOptions::default().tower_max(self.tower_max),
            output,
        }
    }
}

/// Checks the paper and prints it; whether every claim was proved.
pub fn run(job: &PaperJob) -> anyhow::Result<bool> {
    let paper = Paper::build(&job.options).context("building the paper's catalogue")?;
    let report =
        (paper.check().context("checking the paper's claims")?).with_caller(Caller::CommandLine);
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_proved())
}
