//! `superint bracket FILE F G`: `{F, G}` in normal form.

use anyhow::bail;

use super::input::{BuiltinArg, SystemGiven};
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
  superint bracket --system harmonic P11 H --when 'p_theta = I*omega'

F and G are expressions in the file's variables, functions and family instances (K_2_3); with
--system, in the built-in system's (its resonant functions P11, Q23, …, also written P_1_1).
Built-in systems (--system): harmonic, gravity, anisotropic-3-5, anisotropic-1-2, planar-i,
planar-ii.";

/// Arguments of `superint bracket`.
#[derive(Debug, Args)]
pub struct BracketArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input; with
    /// --system, the first expression F.
    #[arg(value_name = "FILE", allow_hyphen_values = true)]
    file: String,
    /// The first expression; with --system, the second, G.
    #[arg(value_name = "F", allow_hyphen_values = true)]
    f: String,
    /// The second expression (none with --system).
    #[arg(value_name = "G", allow_hyphen_values = true)]
    g: Option<String>,
    #[command(flatten)]
    builtin: BuiltinArg,
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
    pub system: SystemGiven,
    pub expressions: Vec<String>,
    pub when: Option<String>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl BracketArgs {
    pub fn job(self, output: Output) -> BracketJob {
        let (system, expressions) = SystemGiven::split(
            self.builtin.system,
            [Some(self.file), Some(self.f), self.g]
                .into_iter()
                .flatten()
                .collect(),
        );
        BracketJob {
            system,
            expressions,
            when: self.when,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Computes the bracket and prints it.
pub fn run(job: &BracketJob) -> anyhow::Result<bool> {
    let file = job
        .system
        .open(&job.expressions, job.when.as_deref(), &job.limits)?;
    let [f, g] = &job.expressions[..] else {
        bail!(
            "give two expressions, F and G, after the system: {} given",
            job.expressions.len()
        );
    };
    let report = warned(&file, bracket_report(&file, f, g, job.when.as_deref()))?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(true)
}
