//! `superint tower --max N`: the tower of resonant integrals by expansion, with the proof for
//! all `m, n`; of a built-in system, or of the families of a system file (`--system FILE`),
//! each in its own section.

use std::io::IsTerminal;

use std::path::PathBuf;

use super::input::load_system;
use anyhow::Context;
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use superint::brackets::EngineError;
use superint::paper::{tower_report_with_progress, TowerSystem};
use superint::render::render;
use superint::system_file::{family_tower_report_with_progress, Caller, LimitsOverride};

use super::limits::{memory_only, LimitsArgs};
use super::output::{emit, warned, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint tower --max 8                  {K_{m,n}, H} for 1 ≤ m, n ≤ 8 (claim C12)
  superint tower --max 24 --system gravity   the shifted tower K'_{m,n} (claim C24)
  superint tower --max 4 --format json
  superint tower --max 6 --system systems/harmonic-rotor.toml             K and K̄
  superint tower --max 6 --system systems/harmonic-rotor.toml --family K
  superint tower --max 6 --system systems/harmonic-rotor.toml --family Kbar,K

With a system file, a tower is that of a [[family]] with an eigenvalue,
{K_{m,n}, H} = λ(m, n) K_{m,n}, and every such family is checked, each in its own section
(or those named by --family, in that order; see docs/system-files.md).";

/// Which system: a built-in one or a system file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SystemArg {
    /// A built-in system: the harmonic rotor (K_{m,n} = Z^m e^{−inθ}) or the rotor under
    /// gravity (K'_{m,n} = Z'^m e^{−inθ}).
    Builtin(TowerSystem),
    /// A system file with a family.
    File(PathBuf),
}

/// `harmonic`, `gravity`, or a path.
fn system_arg(s: &str) -> Result<SystemArg, String> {
    match s {
        "harmonic" => Ok(SystemArg::Builtin(TowerSystem::Harmonic)),
        "gravity" => Ok(SystemArg::Builtin(TowerSystem::Gravity)),
        "" => Err("expected harmonic, gravity or a system file".into()),
        // A bare word that names no file is a misspelt built-in system, not a missing file.
        word if !word.contains(['/', '.']) && !std::path::Path::new(word).exists() => Err(format!(
            "no built-in system {} (harmonic, gravity), and no file of that name",
            trigpoly::quoted_name(word)
        )),
        path => Ok(SystemArg::File(PathBuf::from(path))),
    }
}

/// Arguments of `superint tower`.
#[derive(Debug, Args)]
pub struct TowerArgs {
    /// Check every 1 ≤ m, n ≤ N.
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", default_value_t = 8,
          value_parser = super::in_range::<i64>(1, 64))]
    max: i64,
    /// The system: harmonic, gravity, or a system file that declares a [[family]] with an
    /// eigenvalue (- reads it from standard input).
    #[arg(long, value_name = "harmonic|gravity|FILE", default_value = "harmonic",
          value_parser = super::Quoting(system_arg))]
    system: SystemArg,
    /// With a system file: the families, separated by commas, checked in that order
    /// (default: every family with an eigenvalue).
    #[arg(long, value_name = "NAME[,NAME...]")]
    family: Option<String>,
    /// With a system file: check at values of parameters, such as 'w0sq = 2*omega_c^2' (a
    /// resonance between them; several separated by commas). Parameters only: the tower's
    /// brackets are identities on the whole phase space.
    #[arg(long, value_name = "CONDITION")]
    when: Option<String>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The tower job, as plain data.
#[derive(Debug)]
pub struct TowerJob {
    pub system: SystemArg,
    pub family: Option<String>,
    pub when: Option<String>,
    pub limits: Option<LimitsOverride>,
    pub max: i64,
    pub output: Output,
}

impl TowerArgs {
    pub fn job(self, output: Output) -> TowerJob {
        TowerJob {
            system: self.system,
            family: self.family,
            when: self.when,
            limits: self.limits.any().then(|| self.limits.settings()),
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
    // Of every family's tower together, whatever their names.
    bar.set_message("brackets");
    bar
}

/// Checks the tower (of every family asked for) and prints it; whether every bracket held and
/// every proof went through.
pub fn run(job: &TowerJob) -> anyhow::Result<bool> {
    let bar = progress_bar();
    let mut progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let report = match &job.system {
        SystemArg::Builtin(system) => {
            if job.family.is_some() || job.when.is_some() || job.limits.is_some() {
                anyhow::bail!(
                    "--family, --when, --max-terms and --max-degree need a system file: \
                     --system FILE"
                );
            }
            tower_report_with_progress(*system, job.max, &mut progress)
                .context("checking the tower")?
                .with_caller(Caller::CommandLine)
        }
        SystemArg::File(path) => {
            let file = load_system(path, &job.limits.unwrap_or_else(memory_only))?;
            // Refused at its value in --when where the tower cannot be checked at it.
            let family = job.family.as_deref();
            let when = (job.when.as_deref())
                .map(|w| file.tower_condition(w, family))
                .transpose();
            // What the tower met under it past what tower_condition checks (an instance
            // K_{m,n} beyond K_{1,1} that divides by a parameter it sets to 0) is a refusal of
            // the condition too, shown at its value there, not at the family in the file.
            let report = when.and_then(|when| {
                family_tower_report_with_progress(
                    &file,
                    job.family.as_deref(),
                    job.max,
                    when.as_ref(),
                    &mut progress,
                )
                .map_err(|e| match (job.when.as_deref(), e.engine.as_deref()) {
                    (Some(w), Some(refused @ EngineError::RefusedCondition { .. })) => {
                        file.condition_refusal(w, refused)
                    }
                    _ => e,
                })
            });
            warned(&file, report)?
        }
    };
    bar.finish_and_clear();
    emit(&render(&report, job.output.format, &job.output.options))?;
    Ok(report.all_proved())
}
