//! `superint rank FILE NAMES...`: the certified rank of a Jacobian.

use anyhow::bail;

use super::input::{BuiltinArg, SystemGiven};
use clap::Args;
use superint::render::render;
use superint::system_file::{rank_report_when, LimitsOverride};

use super::limits::LimitsArgs;
use super::output::{emit, warned, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint rank systems/harmonic-rotor.toml F1 F2 G1 G2 P_1_1          rank 5 (claim C17)
  superint rank systems/harmonic-rotor.toml F1 F2 G1 G2 L --expect 4
  superint rank systems/harmonic-rotor.toml F1 'F2 + L' --format json
  superint rank systems/henon-heiles.toml H K --when 'A = 1, B = 1, C = 2'
  superint rank systems/harmonic-rotor.toml F1 G1 G2 P_1_1 --when 'p_theta = I*omega'
  superint rank --system harmonic F1 F2 G1 G2 P11                       rank 5

The rank of ∂(F_1, …, F_k)/∂(q, p) over the rational functions: at least r by an r × r minor
that is nonzero at an exact rational point, at most r by the (r+1) × (r+1) minors that border it
vanishing identically (Kronecker's bordered-minor theorem: then every larger minor vanishes).
On a level set (--when 'p_theta = I*omega') it is the rank of the functions restricted to it:
the condition substituted, the Jacobian by the phase variables it leaves free. Built-in
systems (--system): harmonic, gravity, anisotropic-3-5, anisotropic-1-2, planar-i, planar-ii
(the harmonic rotor and the rotor under gravity with their resonant functions P11, Q23, …).";

/// Arguments of `superint rank`.
#[derive(Debug, Args)]
pub struct RankArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input, followed by
    /// the functions: names, family instances or expressions; with --system, only the
    /// functions.
    #[arg(value_name = "FILE NAMES", required = true, num_args = 1..)]
    args: Vec<String>,
    #[command(flatten)]
    builtin: BuiltinArg,
    /// Claim that the rank is R: exit status 1 if it is not.
    #[arg(long, allow_negative_numbers = true, value_name = "R",
          value_parser = super::Quoting(super::a_rank))]
    expect: Option<usize>,
    /// Values of parameters, such as 'a = 1', or a level set of phase variables, such as
    /// 'p_theta = I*omega', on which the rank is that of the functions restricted to it (as a
    /// rank claim's `when`; several separated by commas).
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The rank job, as plain data.
#[derive(Debug)]
pub struct RankJob {
    pub system: SystemGiven,
    pub functions: Vec<String>,
    pub expect: Option<usize>,
    pub when: Option<String>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl RankArgs {
    pub fn job(self, output: Output) -> RankJob {
        let (system, functions) = SystemGiven::split(self.builtin.system, self.args);
        RankJob {
            system,
            functions,
            expect: self.expect,
            when: self.when,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Certifies the rank and prints it; whether it is the expected one (if one was given).
pub fn run(job: &RankJob) -> anyhow::Result<bool> {
    let file = job
        .system
        .open(&job.functions, job.when.as_deref(), &job.limits)?;
    if job.functions.is_empty() {
        bail!("give the functions whose rank is certified after the system");
    }
    let when = job.when.as_deref();
    let report = warned(
        &file,
        rank_report_when(&file, &job.functions, job.expect, when),
    )?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_as_expected())
}
