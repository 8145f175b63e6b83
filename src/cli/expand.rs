//! `superint expand FILE EXPRS...`: expressions of a system file in normal form.

use anyhow::bail;

use super::input::{BuiltinArg, SystemGiven};
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
  superint expand --system harmonic '{G1, G2}' 'Z^2'

Each expression may use the file's variables, parameters, functions, family instances (K_2_3),
brackets {F, G}, re, im and conj; it is printed in the normal form every claim is decided in,
its angles' part in multiple angles as the paper writes it (A + B cos 2θ + C sin 2θ), or with
--angles powers in powers of cos θ and sin θ (sin²θ replaced by 1 − cos²θ). With --system,
the expressions are in the built-in system's variables and functions (its resonant functions
P11, Q23, …, also written P_1_1). Built-in systems (--system): harmonic, gravity,
anisotropic-3-5, anisotropic-1-2, planar-i, planar-ii.";

/// Arguments of `superint expand`.
#[derive(Debug, Args)]
pub struct ExpandArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input, followed by
    /// the expressions; with --system, only the expressions.
    #[arg(value_name = "FILE EXPRS", required = true, num_args = 1..)]
    args: Vec<String>,
    #[command(flatten)]
    builtin: BuiltinArg,
    /// Substitute after expanding, such as 'p_theta = I*omega' (several separated by commas).
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The expand job, as plain data.
#[derive(Debug)]
pub struct ExpandJob {
    pub system: SystemGiven,
    pub expressions: Vec<String>,
    pub when: Option<String>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl ExpandArgs {
    pub fn job(self, output: Output) -> ExpandJob {
        let (system, expressions) = SystemGiven::split(self.builtin.system, self.args);
        ExpandJob {
            system,
            expressions,
            when: self.when,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Expands the expressions and prints them.
pub fn run(job: &ExpandJob) -> anyhow::Result<bool> {
    let file = job
        .system
        .open(&job.expressions, job.when.as_deref(), &job.limits)?;
    if job.expressions.is_empty() {
        bail!("give the expressions to expand after the system");
    }
    let report = warned(
        &file,
        expand_report(&file, &job.expressions, job.when.as_deref()),
    )?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(true)
}
