//! What `superint plot` reads on the command line, made exact: the parameters' values
//! (`--at`), the starting point (`--from`) and the curves, each an expression of the file with
//! every parameter replaced by its value. The floating-point part, the integration and the
//! picture, is [`crate::trajectory`].

use brackets::EngineError;
use trigpoly::{Expr, GaussianRational, Rational, Span, Var, VarKind};

use super::claims::{parse_assignments, Assignment};
use super::error::{ErrorKind, FileError};
use super::reports::command_error;
use super::text::{split_top_level, Source, Text};
use super::{LoadedSystem, COMMAND_LINE};

/// A plot's exact input.
#[derive(Clone, Debug)]
pub struct PlotInput {
    /// The parameters' values as they read (`M = 1, ω = 2`); empty when none is set.
    pub parameters: String,
    /// `H` at those values.
    pub hamiltonian: Expr,
    /// The value of every coordinate, angle and momentum at `t = 0`, in the phase space's
    /// order (coordinates and angles, then momenta).
    pub start: Vec<(Var, Rational)>,
    /// The curves, each a label and a real function at the parameters' values: a complex
    /// function is two curves, its real and imaginary parts.
    pub curves: Vec<(String, Expr)>,
    /// What the horizontal axis shows, if not the time: a label and a real function.
    pub against: Option<(String, Expr)>,
}

impl LoadedSystem {
    /// Reads a plot's parameters `at` (`"M = 1, omega = 2"`), its starting point `from`
    /// (every coordinate, angle and momentum; values may hold parameters), its `curves` and
    /// what to plot them `against` (the time if `None`), and makes them exact. Errors point
    /// into the argument at fault.
    pub fn plot_input(
        &self,
        at: Option<&str>,
        from: &str,
        curves: &[String],
        against: Option<&str>,
    ) -> Result<PlotInput, FileError> {
        let vars = self.system.vars();
        let kind = |v: Var| vars.variable(v).kind();
        let name = |v: Var| vars.variable(v).unicode().to_string();
        // The parameters' values: numbers.
        let mut values: Vec<(Var, Expr)> = Vec::new();
        let mut shown = Vec::new();
        if let Some(at) = at {
            let usage = "--at reads `parameter = number, …`, such as \"M = 1, omega = 3/2\"";
            let admit = |v: Var| {
                (kind(v) != VarKind::Parameter).then(|| {
                    format!(
                        "--at gives the parameters their values; {} is a {} (give it with --from)",
                        name(v),
                        kind_name(kind(v))
                    )
                })
            };
            let (source, assignments) = self.assignments(at, usage, admit)?;
            for a in assignments {
                let why = "the value of a parameter is a real number, such as 3/2";
                let value = number(&a.value, &a.rhs, &source, why)?;
                values.push((a.var, Expr::constant(vars, GaussianRational::from(value))));
                shown.push(a.shown);
            }
        }
        let at_values = |e: &Expr| e.subst_many(&values).map_err(EngineError::from);
        // The starting point: numbers once the parameters have their values.
        let usage = "--from reads `variable = value, …`, such as \"x = 1, p_y = 1/2\"";
        let admit = |v: Var| {
            (kind(v) == VarKind::Parameter).then(|| {
                format!(
                    "{} is a parameter: give its value with --at (--from gives the coordinates, \
                     angles and momenta theirs)",
                    name(v)
                )
            })
        };
        let mut given = Vec::new();
        let (source, assignments) = self.assignments(from, usage, admit)?;
        for a in assignments {
            let value = at_values(&a.value).map_err(|e| command_error(&e))?;
            let why = format!(
                "the starting value of {} must be a real number once the parameters have their \
                 values (--at)",
                name(a.var)
            );
            given.push((a.var, number(&value, &a.rhs, &source, why)?));
        }
        let pairs = self.system.space().pairs();
        let phase: Vec<Var> = pairs
            .iter()
            .map(|c| c.q)
            .chain(pairs.iter().map(|c| c.p))
            .collect();
        let missing: Vec<String> = phase
            .iter()
            .filter(|v| !given.iter().any(|(g, _)| g == *v))
            .map(|&v| name(v))
            .collect();
        if !missing.is_empty() {
            return Err(FileError::new(
                ErrorKind::Condition,
                COMMAND_LINE,
                format!(
                    "--from gives no value for {}: every coordinate, angle and momentum needs one",
                    missing.join(", ")
                ),
            ));
        }
        let start = phase
            .iter()
            .map(|v| {
                given
                    .iter()
                    .find(|(g, _)| g == v)
                    .cloned()
                    .expect("checked")
            })
            .collect();
        // Why `what`, a function at the parameters' values, cannot be drawn: a parameter
        // with no value.
        let unset = |what: &str, e: &Expr| {
            e.terms()
                .flat_map(|t| vars.vars().zip(t.exponents()).filter(|(_, k)| *k != 0))
                .find(|(v, _)| kind(*v) == VarKind::Parameter)
                .map(|(v, _)| {
                    format!(
                        "{what} holds {0}, which has no value: give it with --at, such as \
                         --at '{1} = 1'",
                        name(v),
                        vars.variable(v).name()
                    )
                })
        };
        let hamiltonian = at_values(self.system.hamiltonian()).map_err(|e| command_error(&e))?;
        if let Some(why) = unset("H", &hamiltonian) {
            return Err(FileError::new(ErrorKind::Expression, COMMAND_LINE, why));
        }
        // The curves, and what they are plotted against: real functions.
        let function = |src: &str| -> Result<(String, Expr, Text, Source), FileError> {
            let arg = self.argument(src)?;
            let (label, value) = self.expand(&arg)?;
            let value = at_values(&value).map_err(|e| command_error(&e))?;
            if let Some(why) = unset(&format!("'{}'", src.trim()), &value) {
                let whole = Span::new(0, arg.text.value.len());
                return Err(arg
                    .text
                    .error(&arg.source, ErrorKind::Expression, whole, why));
            }
            Ok((label, value, arg.text, arg.source))
        };
        let mut real_curves = Vec::new();
        for src in curves {
            let (label, value, ..) = function(src)?;
            if value.is_real() {
                real_curves.push((label, value));
            } else {
                let (_, re, im) = value.conj_re_im();
                real_curves.push((format!("re({label})"), re));
                real_curves.push((format!("im({label})"), im));
            }
        }
        let against = match against {
            None => None,
            Some(src) => {
                let (label, value, text, source) = function(src)?;
                if !value.is_real() {
                    let whole = Span::new(0, text.value.len());
                    return Err(text.error(
                        &source,
                        ErrorKind::Expression,
                        whole,
                        format!(
                            "--against takes a real function; {label} is not: take re(…) or im(…)"
                        ),
                    ));
                }
                Some((label, value))
            }
        };
        Ok(PlotInput {
            parameters: shown.join(", "),
            hamiltonian,
            start,
            curves: real_curves,
            against,
        })
    }

    /// `var = value, …` given on the command line, each variable one `admit` accepts.
    fn assignments(
        &self,
        list: &str,
        usage: &str,
        admit: impl Fn(Var) -> Option<String>,
    ) -> Result<(Source, Vec<Assignment>), FileError> {
        let source = Source::new(COMMAND_LINE, list);
        let whole = Text::whole(&source);
        let pieces: Vec<Text> = split_top_level(list, ',')
            .into_iter()
            .map(|r| whole.slice(r))
            .collect();
        let assignments =
            parse_assignments(self, &source, &pieces, ("`name = value`", usage), admit)?;
        Ok((source, assignments))
    }
}

/// `value` as a real number, or the error `why` at `rhs`, where it is written.
fn number(
    value: &Expr,
    rhs: &Text,
    source: &Source,
    why: impl Into<String>,
) -> Result<Rational, FileError> {
    match value.as_constant() {
        Some(c) if c.is_real() => Ok(c.re),
        None if value.is_zero() => Ok(Rational::zero()),
        _ => {
            let lead = rhs.value.len() - rhs.value.trim_start().len();
            let span = Span::new(lead, rhs.value.trim_end().len());
            Err(rhs.error(source, ErrorKind::Condition, span, why))
        }
    }
}

/// How a kind of variable is called in messages.
fn kind_name(kind: VarKind) -> &'static str {
    match kind {
        VarKind::Coordinate => "coordinate",
        VarKind::Momentum => "momentum",
        VarKind::Parameter => "parameter",
        VarKind::Angle => "angle",
    }
}
