//! Options shared by every subcommand: `--format`, `--no-timings`, `--full-expressions` and
//! `--angles`.

use std::io::{self, Write};

use clap::{Args, ValueEnum};
use superint::render::{printable, Format, Options, SHOWN_MONOMIALS};
use superint::system_file::{FileError, LoadedSystem, Warning};
use trigpoly::Angles;

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

/// `--angles` values: how an angle's part prints ([`Angles`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum AnglesArg {
    /// Multiple angles, as the paper writes them: A cos 2θ + B sin 2θ.
    #[default]
    Harmonics,
    /// Powers of cos θ and sin θ, the normal form claims are decided in (sin²θ replaced by
    /// 1 − cos²θ): A cos²θ + B cos θ sin θ.
    Powers,
}

impl From<AnglesArg> for Angles {
    fn from(a: AnglesArg) -> Angles {
        match a {
            AnglesArg::Harmonics => Angles::Harmonics,
            AnglesArg::Powers => Angles::Powers,
        }
    }
}

/// The output arguments, accepted before or after the subcommand.
#[derive(Debug, Args)]
pub struct OutputArgs {
    /// Output format (`plot` prints text, markdown or JSON, and `bench` text or JSON).
    #[arg(long, value_enum, default_value_t = FormatArg::Text, global = true)]
    format: FormatArg,
    /// Leave timings out, so that the output is the same on every run.
    #[arg(long, global = true)]
    no_timings: bool,
    /// Print a refuted claim's residual and a table's entry whole, however long (by default
    /// one of more than 100 monomials shows the terms of its first 100 and how many it has;
    /// also `--full-residuals`).
    #[arg(long, global = true, alias = "full-residuals")]
    full_expressions: bool,
    /// How an angle's part prints in every format: harmonics (cos 2θ, sin 2θ, …, the
    /// default) or powers (cos²θ, cos θ sin θ, …, the normal form). Either reads back to the
    /// same element.
    #[arg(long, value_enum, default_value_t = AnglesArg::Harmonics, global = true)]
    angles: AnglesArg,
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
    /// The settings, once the form of the angles is made the process's ([`Angles::set_current`]:
    /// every printer, in every thread, writes it).
    pub fn settings(&self) -> Output {
        Angles::from(self.angles).set_current();
        Output {
            format: self.format.into(),
            options: Options::default()
                .timings(!self.no_timings)
                .shown_monomials((!self.full_expressions).then_some(SHOWN_MONOMIALS)),
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

/// `result`, a command's work on `file`, once `file`'s warnings are printed: what its texts
/// and those given on the command line read in doubt is said however the work ended, before
/// its error if it failed. `check` shows its files' warnings in its report instead.
pub fn warned<T, E>(file: &LoadedSystem, result: Result<T, E>) -> Result<T, E> {
    warnings(file);
    result
}

/// Prints on stderr, each as `superint: warning: FILE:LINE:COLUMN: …` with its line and a caret,
/// what `file`'s texts and those given on the command line read in a way that may not have been
/// meant ([`LoadedSystem::warnings`]: a name run together read as a product in doubt, `Lxx`
/// beside a function `Lx`).
fn warnings(file: &LoadedSystem) {
    print_warnings(&file.warnings());
}

/// Prints on stderr the warnings of a file that failed to load ([`FileError::warnings`]: what
/// its texts read in doubt before the error), as [`warned`] prints a loaded file's, before its
/// error is printed.
pub fn load_warnings(error: &FileError) {
    print_warnings(error.warnings_before());
}

/// Prints `warnings` on stderr, each as `superint: warning: …` with its line and a caret.
pub fn print_warnings(warnings: &[Warning]) {
    for w in warnings {
        eprintln!("superint: warning: {}", printable(&w.to_string()));
    }
}

/// Prints an error line on stderr: `superint: error: …`, control characters shown as `�`.
pub fn error_line(message: &str) {
    eprintln!("superint: error: {}", printable(message));
}

/// An error and its causes in one message, `context: error: cause`, leaving out a cause that
/// the text before it already says (a context that quotes its cause). An error of the
/// library says a cause in its message or returns it as its source, never both: the engine's
/// error that renders a parse error with its line and caret has no source.
pub fn error_message(error: &anyhow::Error) -> String {
    let mut message = String::new();
    for cause in error.chain() {
        let said = cause.to_string();
        if message.is_empty() {
            message = said;
        } else if !message.contains(&said) {
            message = format!("{message}: {said}");
        }
    }
    message
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cause is said once: one that its context quotes is left out; the engine's rendering
    /// of a parse error, which says the parse error and so has no source, follows its context
    /// alone; a context and a cause that says something new are chained.
    #[test]
    fn a_cause_already_said_is_not_repeated() {
        let parse = trigpoly::ParseError::new(trigpoly::Span::new(4, 5), "unknown name 'q'");
        let engine = brackets::EngineError::parse("x + q", parse);
        let quoting = format!("computing the closure: {engine}");
        let error = anyhow::Error::new(engine.clone()).context(quoting.clone());
        assert_eq!(error.chain().count(), 2);
        assert_eq!(error_message(&error), quoting);
        let error = anyhow::Error::new(engine.clone()).context("computing the closure");
        assert_eq!(
            error_message(&error),
            format!("computing the closure: {engine}")
        );
        assert_eq!(error.chain().count(), 2);
        let error = anyhow::anyhow!("cannot read the file").context("systems/x.toml");
        assert_eq!(
            error_message(&error),
            "systems/x.toml: cannot read the file"
        );
    }
}
