//! `superint table FILE [NAMES...]`: the bracket table of named functions.

use super::input::{BuiltinArg, SystemGiven};
use anyhow::bail;
use clap::Args;
use superint::render::render;
use superint::report::counted;
use superint::system_file::{table_report, LimitsOverride};

use super::limits::LimitsArgs;
use super::output::{emit, warned, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint table systems/harmonic-rotor.toml F1 F2 L G1 G2    the su(2) table of section 3
  superint table systems/harmonic-rotor.toml                  every function of the file
  superint table systems/harmonic-rotor.toml L G1 G2 --format markdown
  superint table systems/euler-top.toml M1 M2 M3              so(3), of the Poisson variables
  superint table --system harmonic F1 F2 L G1 G2              the same table, built in

Each entry is written as a combination of the listed functions with coefficients in the
parameters where one exists, otherwise as an expression; one that is a polynomial in H and the
file's functions is written so below the table too, expanded and with the factor its terms
share in front ({S, C} = 72M³ H H_x² − 96M³ H_x³ = 24M³(3 H − 4 H_x) H_x²). Built-in systems
(--system): harmonic, gravity, anisotropic-3-5, anisotropic-1-2, planar-i, planar-ii.";

/// Arguments of `superint table`.
#[derive(Debug, Args)]
pub struct TableArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input, followed by
    /// named functions, family instances (K_1_1) or phase variables (p_x), every function of
    /// the file but H if none; with --system, only the names.
    #[arg(value_name = "FILE NAMES", required_unless_present = "system", num_args = 0..)]
    args: Vec<String>,
    #[command(flatten)]
    builtin: BuiltinArg,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// The table job, as plain data.
#[derive(Debug)]
pub struct TableJob {
    pub system: SystemGiven,
    pub names: Vec<String>,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl TableArgs {
    pub fn job(self, output: Output) -> TableJob {
        let (system, names) = SystemGiven::split(self.builtin.system, self.args);
        TableJob {
            system,
            names,
            limits: self.limits.settings(),
            output,
        }
    }
}

/// Computes the table and prints it.
pub fn run(job: &TableJob) -> anyhow::Result<bool> {
    let file = job.system.open(&job.names, None, &job.limits)?;
    let report = warned(&file, table_report(&file, &job.names))?;
    emit(&render(&report, job.output.format, &job.output.options))?;
    // Entries a limit stopped are `?` in the table, and the run ends with an error.
    let undecided: Vec<String> = report
        .tables()
        .flat_map(|t| {
            let names = &t.table.display;
            (t.undecided().into_iter())
                .map(move |(a, b, message)| format!("{{{}, {}}}: {message}", names[a], names[b]))
        })
        .collect();
    if let Some(first) = undecided.first() {
        bail!(
            "{}: {} of the table undecided (shown as ?), stopped at a limit, the first {first} \
             (--max-terms N, --max-term-products N, --max-degree D)",
            job.system.label(),
            counted(undecided.len(), "entry")
        );
    }
    Ok(true)
}
