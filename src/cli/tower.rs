//! `superint tower --max N`: the tower of resonant integrals by expansion, with the proof for
//! all `m, n`.

use std::io::IsTerminal;

use anyhow::Context;
use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use superint::paper::{tower_report, TowerSystem};
use superint::render::render;

use super::output::{emit, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint tower --max 8                  {K_{m,n}, H} for 1 ≤ m, n ≤ 8 (claim C12)
  superint tower --max 24 --system gravity   the shifted tower K'_{m,n} (claim C24)
  superint tower --max 4 --format json";

/// Which system.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum SystemArg {
    /// The harmonic rotor, K_{m,n} = Z^m e^{−inθ}.
    #[default]
    Harmonic,
    /// The rotor under gravity, K'_{m,n} = Z'^m e^{−inθ}.
    Gravity,
}

/// Arguments of `superint tower`.
#[derive(Debug, Args)]
pub struct TowerArgs {
    /// Check every 1 ≤ m, n ≤ N.
    #[arg(long, value_name = "N", default_value_t = 8,
          value_parser = clap::value_parser!(i64).range(1..=64))]
    max: i64,
    /// The system.
    #[arg(long, value_enum, default_value_t = SystemArg::Harmonic)]
    system: SystemArg,
}

/// The tower job, as plain data.
#[derive(Debug)]
pub struct TowerJob {
    pub system: TowerSystem,
    pub max: i64,
    pub output: Output,
}

impl TowerArgs {
    pub fn job(self, output: Output) -> TowerJob {
        TowerJob {
            system: match self.system {
                SystemArg::Harmonic => TowerSystem::Harmonic,
                SystemArg::Gravity => TowerSystem::Gravity,
            },
            max: self.max,
            output,
        }
    }
}

/// A progress bar on stderr, hidden when stderr is not a terminal.
fn progress_bar() -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(0);
    bar.set_style(
        ProgressStyle::with_template("{spinner} {msg} [{bar:40}] {pos}/{len} ({elapsed})")
            .expect("a valid template")
            .progress_chars("=> "),
    );
    bar.set_message("{K_{m,n}, H}");
    bar
}

/// Checks the tower and prints it; whether every bracket held and the proof went through.
pub fn run(job: &TowerJob) -> anyhow::Result<bool> {
    let bar = progress_bar();
    let report = tower_report(job.system, job.max, &mut |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    })
    .context("checking the tower")?;
    bar.finish_and_clear();
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_proved())
}
