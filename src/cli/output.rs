//! Options shared by every subcommand: `--format` and `--no-timings`.

use std::io::{self, Write};

use clap::{Args, ValueEnum};
use superint::render::{printable, Format, Options};

/// `--format` values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    /// Unicode text that reads like the paper.
    #[default]
    Text,
    /// Markdown with tables (also `md`).
    #[value(alias = "md")]
    Markdown,
    /// A complete LaTeX document (amsmath).
    Latex,
    /// JSON, one object per claim (schema superint-report/1; plot and bench have their own).
    Json,
}

impl From<FormatArg> for Format {
    fn from(f: FormatArg) -> Format {
        match f {
            FormatArg::Text => Format::Text,
            FormatArg::Markdown => Format::Markdown,
            FormatArg::Latex => Format::Latex,
            FormatArg::Json => Format::Json,
        }
    }
}

/// The output arguments, accepted before or after the subcommand.
#[derive(Debug, Args)]
pub struct OutputArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = FormatArg::Text, global = true)]
    format: FormatArg,
    /// Leave timings out, so that the output is the same on every run.
    #[arg(long, global = true)]
    no_timings: bool,
}

/// How to print, as plain data.
#[derive(Clone, Copy, Debug)]
pub struct Output {
    /// The format.
    pub format: Format,
    /// The rendering options.
    pub options: Options,
}

impl OutputArgs {
    pub fn settings(&self) -> Output {
        Output {
            format: self.format.into(),
            options: Options {
                timings: !self.no_timings,
            },
        }
    }
}

/// Writes the rendered output to stdout; a closed pipe (`superint | head`) is not an error.
pub fn emit(text: &str) -> anyhow::Result<()> {
    write_to(io::stdout().lock(), text)
}

/// Writes to stderr what goes there when stdout carries something else (`plot -o -`); a
/// closed pipe is not an error.
pub fn emit_to_stderr(text: &str) -> anyhow::Result<()> {
    write_to(io::stderr().lock(), text)
}

fn write_to(mut out: impl Write, text: &str) -> anyhow::Result<()> {
    match out
        .write_all(printable(text).as_bytes())
        .and_then(|()| out.flush())
    {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => Err(e.into()),
        _ => Ok(()),
    }
}

/// Prints an error line on stderr: `superint: error: …`, control characters shown as `�`.
pub fn error_line(message: &str) {
    eprintln!("superint: error: {}", printable(message));
}
