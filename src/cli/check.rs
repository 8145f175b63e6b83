//! `superint check FILE...`: every claim of some system files, proved or refuted.

use std::path::PathBuf;

use super::input::load_system_keeping_warnings;
use anyhow::bail;
use clap::Args;
use superint::render::{json, render, Format};
use superint::report::counted;
use superint::system_file::{check_each, FileError, LimitsOverride};

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
/// expectation. A claim whose check stops at a limit is reported undecided, and the file's
/// other claims are checked; a file that does not load, or whose check fails otherwise, does
/// not stop the others. Each such error goes to stderr (and into the JSON report's `errors`),
/// and the run ends with an error (exit 2).
pub fn run(job: &CheckJob) -> anyhow::Result<bool> {
    let files = job
        .files
        .iter()
        .map(|p| load_system_keeping_warnings(p, &job.limits))
        .collect();
    let (report, mut errors) = check_each(files);
    let unchecked = match report.sections.is_empty() {
        // Nothing was checked: the errors are the whole answer, the last one the run's.
        true => errors.pop(),
        false => None,
    };
    // Each file's warnings right before its error: all files are loaded before any is printed.
    for e in &errors {
        super::output::load_warnings(e);
        super::output::error_line(&e.to_string());
    }
    if let Some(last) = unchecked {
        super::output::load_warnings(&last);
        return Err(last.into());
    }
    let text = match job.output.format {
        Format::Json if !errors.is_empty() => {
            let mut value = json::value(&report, &job.output.options);
            value["errors"] = errors.iter().map(error_value).collect();
            json::pretty(&value)
        }
        format => render(&report, format, &job.output.options),
    };
    emit(&text)?;
    if errors.is_empty() {
        return Ok(report.all_as_expected());
    }
    // A limit's error names its undecided claim; the others are files' own.
    let undecided = errors.iter().filter(|e| e.claim.is_some()).count();
    let unchecked = errors.len() - undecided;
    let mut what = Vec::new();
    if unchecked > 0 {
        what.push(format!(
            "{unchecked} of {} not checked",
            counted(job.files.len(), "file")
        ));
    }
    if undecided > 0 {
        what.push(format!(
            "{} undecided, stopped at a limit",
            counted(undecided, "claim")
        ));
    }
    bail!(
        "{} (the {} above)",
        what.join(", "),
        if errors.len() == 1 { "error" } else { "errors" }
    )
}

/// A file's error as the JSON report's `errors` give it, with the warnings read before it
/// ([`FileError::warnings`], which stderr says right before the error), each as a loaded
/// file's `warnings` give it less the section, which a file that did not load has none of.
fn error_value(e: &FileError) -> serde_json::Value {
    let location = e.location.as_deref();
    let warnings: Vec<serde_json::Value> = (e.warnings_before().iter())
        .map(|w| json::warning(w, None))
        .collect();
    serde_json::json!({
        "file": e.origin,
        "line": location.map(|l| l.line),
        "column": location.map(|l| l.column),
        "kind": e.kind.name(),
        "claim": e.claim,
        "message": e.message,
        "hint": e.hint,
        "warnings": warnings,
    })
}
