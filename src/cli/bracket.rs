//! `superint bracket FILE F G`: `{F, G}` in normal form.

use std::path::PathBuf;

use super::input::load_system;
use clap::Args;
use superint::render::render;
use superint::system_file::{bracket_report, LimitsOverride};

use super::limits::LimitsArgs;
use super::output::{emit, warned, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint bracket systems/harmonic-rotor.toml G1 G2   {G1, G2} = −ω²x p_y + ω²y p_x = −ω² L
  superint bracket systems/harmonic-rotor.toml 'x*p_y' H
  superint bracket systems/harmonic-rotor.toml P_1_1 H --when 'p_theta = I*omega'
  superint bracket systems/harmonic-rotor.toml L G1 --format latex

F and G are expressions in the file's variables, functions and family instances (K_2_3).";

/// Arguments of `superint bracket`.
#[derive(Debug, Args)]
pub struct BracketArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input.
    #[arg(value_name = "FILE")]
    file: PathBuf,
    /// The first expression.
    #[arg(value_name = "F", allow_hyphen_values = true)]
    f: String,
    /// The second expression.
    #[arg(value_name = "G", allow_hyphen_values = true)]
    g: String,
    /// Substitute after forming the bracket, such as 'p_theta = 2*I*omega/3' (several
    /// separated by commas).
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The bracket job, as plain data.
#[derive(Debug)]
pub struct BracketJob {
    pub file: PathBuf,
    pub f: String,
    pub g: String,
    pub when: Option<String>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl BracketArgs {
    pub fn job(self, output: Output) -> BracketJob {
        BracketJob {
            file: self.file,
            f: self.f,
            g: self.g,
            when: self.when,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Computes the bracket and prints it.
pub fn run(job: &BracketJob) -> anyhow::Result<bool> {
    let file = load_system(&job.file, &job.limits)?;
    let report = warned(
        &file,
        bracket_report(&file, &job.f, &job.g, job.when.as_deref()),
    )?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(true)
}
