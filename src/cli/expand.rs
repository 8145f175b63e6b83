//! `superint expand FILE EXPRS...`: expressions of a system file in normal form.

use std::path::PathBuf;

use super::input::load_system;
use clap::Args;
use superint::render::render;
use superint::system_file::{expand_report, LimitsOverride};

use super::limits::LimitsArgs;
use super::output::{emit, warned, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint expand systems/harmonic-rotor.toml K_1_1 'Z^2'       the resonant integral, Z²
  superint expand systems/harmonic-rotor.toml 're(K_1_2)' 'im(K_1_2)'
  superint expand systems/harmonic-rotor.toml '{P_1_1, H}' --when 'p_theta = I*omega'
  superint expand systems/harmonic-rotor.toml 'G1^2 + G2^2/4' --format latex

Each expression may use the file's variables, parameters, functions, family instances (K_2_3),
brackets {F, G}, re, im and conj; it is printed in the normal form every claim is decided in
(cos θ, sin θ with sin²θ replaced by 1 − cos²θ).";

/// Arguments of `superint expand`.
#[derive(Debug, Args)]
pub struct ExpandArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input.
    #[arg(value_name = "FILE")]
    file: PathBuf,
    /// The expressions.
    #[arg(value_name = "EXPRS", required = true)]
    expressions: Vec<String>,
    /// Substitute after expanding, such as 'p_theta = I*omega' (several separated by commas).
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The expand job, as plain data.
#[derive(Debug)]
pub struct ExpandJob {
    pub file: PathBuf,
    pub expressions: Vec<String>,
    pub when: Option<String>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl ExpandArgs {
    pub fn job(self, output: Output) -> ExpandJob {
        ExpandJob {
            file: self.file,
            expressions: self.expressions,
            when: self.when,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Expands the expressions and prints them.
pub fn run(job: &ExpandJob) -> anyhow::Result<bool> {
    let file = load_system(&job.file, &job.limits)?;
    let report = warned(
        &file,
        expand_report(&file, &job.expressions, job.when.as_deref()),
    )?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(true)
}
