//! What `superint plot` reads on the command line, made exact: the parameters' values
//! (`--at`), the starting point (`--from`) and the curves, each an expression of the file with
//! every parameter replaced by its value. The floating-point part, the integration and the
//! picture, is [`crate::trajectory`].

use brackets::EngineError;
use trigpoly::{Expr, GaussianRational, Rational, Span, Var, VarKind};

use super::claims::{parse_assignments, Assignment, AssignmentForm};
use super::error::{ErrorKind, FileError};
use super::roots_of_unity::RootsOfUnity;
use super::text::{Source, Text};
use super::{Argument, LoadedSystem, COMMAND_LINE};

/// A plot's exact input.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct PlotInput {
    /// The parameters' values as they read (`M = 1, ω = 2`); empty when none is set.
    pub parameters: String,
    /// The parameters' values as a substitution, for what is formed from the system after
    /// (Hamilton's equations through the denominators, [`crate::trajectory::Flow::at`]).
    pub values: Vec<(Var, Expr)>,
    /// `H` at those values.
    pub hamiltonian: Expr,
    /// The starting points, one an orbit: the value of every coordinate, angle, momentum and Poisson variable
    /// at `t = 0`, in the phase space's order (coordinates and angles, then momenta).
    pub starts: Vec<Vec<(Var, StartValue)>>,
    /// The curves, each a label and a real function at the parameters' values: a complex
    /// function is two curves, its real and imaginary parts.
    pub curves: Vec<(String, Expr)>,
    /// What the horizontal axis shows, if not the time.
    pub against: Option<Against>,
    /// The function whose upward zeros are kept instead of equally spaced times (a
    /// Poincaré section), if any: a label and a real function.
    pub section: Option<(String, Expr)>,
}

/// A starting value: exact, or an exact multiple of π (`θ = 3π/4`), which floating point
/// then rounds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StartValue {
    /// The value.
    Exact(Rational),
    /// `q·π`.
    PiTimes(Rational),
}

impl StartValue {
    /// The nearest `f64` (for `q·π`, the nearest to `q` times `π`'s). The value of an angle
    /// (`angle`) is first reduced exactly modulo `2π`: `θ = 99999999999999999999π` is `π`, where
    /// rounding `q` first would turn it into an angle of no meaning.
    pub fn to_f64(&self, angle: bool) -> Result<f64, crate::trajectory::TrajectoryError> {
        match self {
            StartValue::Exact(q) => crate::trajectory::nearest_f64(q),
            StartValue::PiTimes(q) => {
                let q = match angle {
                    true => {
                        let two = Rational::from(2);
                        let turns = Rational::from((q / &two).to_big_rational().floor());
                        q - &(&turns * &two)
                    }
                    false => q.clone(),
                };
                crate::trajectory::nearest_f64(&q).map(|x| x * std::f64::consts::PI)
            }
        }
    }
}

/// What a plot's horizontal axis shows instead of the time.
#[derive(Clone, Debug)]
pub enum Against {
    /// A real function: its label and value.
    Function(String, Expr),
    /// An angle, so that `p_θ --against θ` draws a phase portrait: its label and the variable.
    /// The chart reduces it to `[−π, π)` (or not, with `--unreduced`).
    Angle(String, Var),
}

/// What a plot draws, as given on the command line: the curves, what they are drawn against
/// (the time if `None`), and the function of a Poincaré section, if any.
#[derive(Clone, Copy, Debug)]
pub struct PlotFunctions<'a> {
    /// The curves.
    pub curves: &'a [String],
    /// `--against`.
    pub against: Option<&'a str>,
    /// `--section`.
    pub section: Option<&'a str>,
}

/// The parameters' values of a plot, as a substitution.
type Values = Vec<(Var, Expr)>;

impl LoadedSystem {
    /// Reads a plot's parameters `at` (`"M = 1, omega = 2"`), its starting points `from`
    /// (each a value for every coordinate, angle, momentum and Poisson variable; values may hold parameters)
    /// and its `functions`, and makes them exact. Errors point into the argument at fault.
    pub fn plot_input(
        &self,
        at: Option<&str>,
        from: &[String],
        functions: PlotFunctions<'_>,
    ) -> Result<PlotInput, FileError> {
        let (values, parameters, written_at) = match at {
            Some(at) => {
                let (values, parameters, written) = self.parameter_values(at)?;
                (values, parameters, Some(written))
            }
            None => (Values::new(), String::new(), None),
        };
        let given = Given {
            values: &values,
            at: written_at.as_ref(),
        };
        let starts: Vec<(Vec<(Var, StartValue)>, Written)> = from
            .iter()
            .map(|point| self.starting_point(point, given))
            .collect::<Result<_, _>>()?;
        let hamiltonian = self.at_values("H", self.system.hamiltonian(), given)?;
        if let Some(why) = self.unset("H", &hamiltonian) {
            return Err(FileError::new(ErrorKind::Expression, COMMAND_LINE, why));
        }
        for (start, written) in &starts {
            if let Some(undefined) = self
                .undefined_at("H", &hamiltonian, start)
                .or_else(|| self.divides_by_zero_at("H", &hamiltonian, start, &values))
            {
                return Err(undefined.placed(written, written_at.as_ref()));
            }
        }
        let mut real_curves = Vec::new();
        for src in functions.curves {
            let (label, value, _) = self.drawable(src, given)?;
            for (start, written) in &starts {
                if let Some(undefined) = self
                    .undefined_at(&label, &value, start)
                    .or_else(|| self.divides_by_zero_at(&label, &value, start, &values))
                {
                    return Err(undefined.placed(written, written_at.as_ref()));
                }
            }
            if value.is_real() {
                real_curves.push((label, value));
            } else {
                // Labelled as `re(K_1_1)` given as a curve prints, `Re(K_{1,1})`.
                let part = |f: &str| match self.argument(&format!("{f}({src})")) {
                    Ok(arg) => self.pretty(&arg.tree),
                    Err(_) => format!("{f}({label})"),
                };
                let (_, re, im) = value.conj_re_im();
                real_curves.push((part("re"), re));
                real_curves.push((part("im"), im));
            }
        }
        let real = |option: &str, src: Option<&str>| match src {
            None => Ok(None),
            Some(src) => self.real_drawable(option, src, given).map(Some),
        };
        let vars = self.system.vars();
        let angle = functions
            .against
            .and_then(|src| vars.lookup(src.trim()))
            .filter(|&v| vars.variable(v).kind() == VarKind::Angle);
        let against = match angle {
            Some(v) => Some(Against::Angle(self.display(v), v)),
            None => real("--against", functions.against)?.map(|(l, f)| Against::Function(l, f)),
        };
        let section = real("--section", functions.section)?;
        Ok(PlotInput {
            parameters,
            values,
            hamiltonian,
            starts: starts.into_iter().map(|(start, _)| start).collect(),
            curves: real_curves,
            against,
            section,
        })
    }

    /// A real function given to `option`: its label and value, or an error saying to take
    /// its real or imaginary part.
    fn real_drawable(
        &self,
        option: &str,
        src: &str,
        given: Given<'_>,
    ) -> Result<(String, Expr), FileError> {
        let (label, value, arg) = self.drawable(src, given)?;
        if !value.is_real() {
            let why =
                format!("{option} takes a real function; {label} is not: take re(…) or im(…)");
            let whole = Span::new(0, arg.text.value.len());
            return Err(arg
                .text
                .error(&arg.source, ErrorKind::Expression, whole, why));
        }
        Ok((label, value))
    }

    /// `--at`: each parameter named a real number. The substitution, how it reads, and where
    /// each value is written.
    fn parameter_values(&self, at: &str) -> Result<(Values, String, Written), FileError> {
        let form = AssignmentForm {
            what: "a value of --at",
            kinds: "a parameter",
            kinds_with_poisson: "a parameter",
            usage: "--at reads `parameter = number, …`, such as \"M = 1, omega = 3/2\"",
            decimals: true,
            pi: false,
        };
        let admit = |v: Var| {
            let kind = self.system.vars().variable(v).kind();
            (kind != VarKind::Parameter).then(|| {
                format!(
                    "--at gives the parameters their values; {} is {} (give it with --from)",
                    self.display(v),
                    kind.described()
                )
            })
        };
        let (source, assignments) = self.assignments(at, &form, admit)?;
        let mut values = Values::new();
        let mut shown = Vec::new();
        let mut written = Written::of(&source);
        for a in assignments {
            written.values.push((a.var, a.rhs.clone()));
            let why = "the value of a parameter is a real number, such as 3/2";
            let value = number(&a.value, &a.rhs, &source, why)?;
            let value = Expr::constant(self.system.vars(), GaussianRational::from(value));
            values.push((a.var, value));
            // H's divisor set to 0 is shown where --at writes it (a curve's or a starting
            // value's, found later, by the values alone).
            let this = &values[values.len() - 1..];
            if let Some((v, why)) = self.divisor_set_to_zero("H", self.system.hamiltonian(), this) {
                let span = a.rhs.trimmed_span();
                let refusal = a.rhs.error(&source, ErrorKind::Condition, span, why);
                return Err(refusal.with_hint(self.other_than_zero(v)));
            }
            shown.push(a.shown);
        }
        Ok((values, shown.join(", "), written))
    }

    /// `--from`: a real number for every coordinate, angle, momentum and Poisson variable, once the parameters
    /// have their values (`given`); in the phase space's order, with where each is written.
    fn starting_point(
        &self,
        from: &str,
        given: Given<'_>,
    ) -> Result<(Vec<(Var, StartValue)>, Written), FileError> {
        let form = AssignmentForm {
            what: "a value of --from",
            kinds: "a coordinate, an angle or a momentum",
            kinds_with_poisson: "a coordinate, an angle, a momentum or a Poisson variable",
            usage: "--from reads `variable = value, …`, such as \"x = 1, p_y = 1/2\"",
            decimals: true,
            pi: true,
        };
        let admit = |v: Var| {
            (self.system.vars().variable(v).kind() == VarKind::Parameter).then(|| {
                format!(
                    "{} is a parameter: give its value with --at (--from gives the coordinates, \
                     angles and momenta theirs)",
                    self.display(v)
                )
            })
        };
        let (source, assignments) = self.assignments(from, &form, admit)?;
        let values = given.values;
        let mut written = Written::of(&source);
        let mut set = Vec::new();
        for a in assignments {
            written.values.push((a.var, a.rhs.clone()));
            let why = format!(
                "the starting value of {} must be a real number once the parameters have their \
                 values (--at)",
                self.display(a.var)
            );
            let what = format!("the starting value of {}", self.display(a.var));
            // Shown where it is written in --from.
            if let Some((v, why)) = self.divisor_set_to_zero(&what, &a.value, values) {
                let span = a.rhs.trimmed_span();
                let refusal = a.rhs.error(&source, ErrorKind::Condition, span, why);
                return Err(refusal.with_hint(self.other_than_zero(v)));
            }
            let value = number(
                &self.at_values(&what, &a.value, given)?,
                &a.rhs,
                &source,
                why,
            )?;
            set.push((
                a.var,
                match a.pi_times {
                    true => StartValue::PiTimes(value),
                    false => StartValue::Exact(value),
                },
            ));
        }
        let phase = self.system.space().coordinates();
        let (mut start, mut missing) = (Vec::new(), Vec::new());
        for v in phase {
            match set.iter().find(|(g, _)| *g == v) {
                Some(found) => start.push(found.clone()),
                None => missing.push(self.display(v)),
            }
        }
        if !missing.is_empty() {
            // Refused as a whole, the caret under all of --from.
            let whole = Text::whole(&source);
            return Err(whole.error(
                &source,
                ErrorKind::Condition,
                whole.trimmed_span(),
                format!(
                    "--from gives no value for {}: every {} needs one",
                    missing.join(", "),
                    match self.system.space().poisson_variables().is_empty() {
                        true => "coordinate, angle and momentum",
                        false => "coordinate, angle, momentum and Poisson variable",
                    }
                ),
            ));
        }
        Ok((start, written))
    }

    /// Why `e` has no value at the starting point `start`, if it has none: it divides by a
    /// coordinate or momentum that starts at 0 (the flow of `H` would start at a singularity,
    /// and floating point would only say later that it left the finite numbers).
    fn undefined_at(&self, what: &str, e: &Expr, start: &[(Var, StartValue)]) -> Option<Undefined> {
        // An angle's negative exponents are those of `e^{−ikθ}`, defined everywhere.
        let vars = self.system.vars();
        let (v, _) = start.iter().find(|(v, value)| {
            vars.variable(*v).kind() != VarKind::Angle
                && matches!(value, StartValue::Exact(q) if q.is_zero())
                && e.low_degree(*v).is_some_and(|low| low < 0)
        })?;
        let name = self.display(*v);
        Some(Undefined {
            why: format!(
                "{what} is not defined at the starting point: it divides by {name}, which starts \
                 at 0 (--from)"
            ),
            hint: format!("start {name} at a value other than 0"),
            by: vec![*v],
            in_at: false,
        })
    }

    /// Why `e` has no value at the starting point `start`, if it has none: it divides by a
    /// declared denominator that is zero there, decided exactly where every variable of the
    /// denominator starts at an exact number: a rational for a coordinate or momentum, and for
    /// an angle 0 or a rational multiple of π (`φ = π/6`, where `cos 3φ` is 0), whose `e^{iφ}`
    /// is a root of unity. An angle at another number (`φ = 1`) has no exact value, and its
    /// denominators are left to the integration.
    fn divides_by_zero_at(
        &self,
        what: &str,
        e: &Expr,
        start: &[(Var, StartValue)],
        values: &Values,
    ) -> Option<Undefined> {
        let space = self.system.space();
        let vars = self.system.vars();
        let mut point = values.clone();
        // Each angle at `qπ` (q mod 2): `e^{iφ} = e^{2πi·q/2}`.
        let mut turns: Vec<(Var, Rational)> = Vec::new();
        for (v, value) in start {
            match (value, vars.variable(*v).kind() == VarKind::Angle) {
                (StartValue::Exact(q), false) => {
                    let q = GaussianRational::from(q.clone());
                    point.push((*v, Expr::constant(vars, q)));
                }
                (StartValue::Exact(q), true) if q.is_zero() => turns.push((*v, Rational::zero())),
                (StartValue::PiTimes(q), true) => turns.push((*v, q / &Rational::from(2))),
                _ => {}
            }
        }
        let on_circle = RootsOfUnity::new(vars, &turns);
        let at = |d: &Expr| d.subst_many(&point).ok().and_then(|at| at.as_constant());
        let vanishes = |d: &Expr| match &on_circle {
            None => at(d).map(|c| c.is_zero()),
            Some(roots) => roots.vanishes(&d.subst_many(&point).ok()?),
        };
        // Where the parameters' values alone decide it (a denominator `a − b` at `a = b`), the
        // fault is theirs, not the starting point's.
        let by_parameters =
            |d: &Expr| !values.is_empty() && d.subst_many(values).is_ok_and(|at| at.is_constant());
        let place = |d: &Expr| match by_parameters(d) {
            true => ("at the values of --at", "--at", true),
            false => ("at the starting point", "--from", false),
        };
        // Shown at the value of a variable of `d` where that list writes it.
        let by = |d: &Expr| d.vars().vars().filter(|&v| d.contains(v)).collect();
        if let Some((v, d)) = space
            .denominator_atoms()
            .iter()
            .find(|(v, d)| e.low_degree(*v).is_some_and(|low| low < 0) && vanishes(d) == Some(true))
        {
            let (at, option, in_at) = place(d);
            let name = self.display(*v);
            return Some(Undefined {
                why: format!(
                    "{what} is not defined {at}: it divides by {name}, which is 0 there ({option})"
                ),
                hint: format!("give {option} values at which {name} is not 0"),
                by: by(d),
                in_at,
            });
        }
        // A radical is real where its radicand is not negative, and divides where it is not 0.
        let (r, radicand, value) = space.radicals().iter().find_map(|(r, radicand)| {
            let value = at(radicand)?;
            let negative = value.re.is_negative();
            let divides = value.is_zero() && e.low_degree(*r).is_some_and(|low| low < 0);
            (e.contains(*r) && (negative || divides)).then_some((r, radicand, value))
        })?;
        let (at, option, in_at) = place(radicand);
        let root = self.display(*r);
        Some(Undefined {
            hint: match value.is_zero() {
                true => format!("give {option} values at which {root} is not 0"),
                false => format!("give {option} values at which {radicand} is not negative"),
            },
            why: format!(
                "{what} is not defined {at}: {} is the root of {value} there ({option})",
                Expr::radical_definition(*r, radicand)
            ),
            by: by(radicand),
            in_at,
        })
    }

    /// A curve (or what curves are drawn against) given on the command line: its label and
    /// value at the parameters' `values`, which must leave no parameter in it.
    fn drawable(&self, src: &str, given: Given<'_>) -> Result<(String, Expr, Argument), FileError> {
        let arg = self.argument(src)?;
        let (label, value) = self.expand(&arg)?;
        let value = self.at_values(&format!("'{}'", src.trim()), &value, given)?;
        if let Some(why) = self.unset(&format!("'{}'", src.trim()), &value) {
            let whole = Span::new(0, arg.text.value.len());
            return Err(arg
                .text
                .error(&arg.source, ErrorKind::Expression, whole, why));
        }
        Ok((label, value, arg))
    }

    /// Why `what`, a function at the parameters' values, cannot be drawn: a parameter it
    /// holds has no value.
    fn unset(&self, what: &str, e: &Expr) -> Option<String> {
        let vars = self.system.vars();
        e.terms()
            .flat_map(|t| vars.vars().zip(t.exponents()).filter(|(_, k)| *k != 0))
            .find(|(v, _)| vars.variable(*v).kind() == VarKind::Parameter)
            .map(|(v, _)| {
                format!(
                    "{what} holds {0}, which has no value: give it with --at, such as --at \
                     '{1} = 1'",
                    self.display(v),
                    vars.variable(v).name()
                )
            })
    }

    /// A variable as messages print it (`θ`).
    fn display(&self, v: Var) -> String {
        self.system.vars().variable(v).unicode().to_string()
    }

    /// `var = value, …` given on the command line, each variable one `admit` accepts.
    fn assignments(
        &self,
        list: &str,
        form: &AssignmentForm<'_>,
        admit: impl Fn(Var) -> Option<String>,
    ) -> Result<(Source, Vec<Assignment>), FileError> {
        let source = Source::on_command_line(COMMAND_LINE, list);
        let pieces = Text::whole(&source).split(',');
        let assignments = parse_assignments(self, &source, &pieces, form, admit)?;
        Ok((source, assignments))
    }

    /// Why `what`, the function `e`, has no value at the parameters' `values`, if it has
    /// none: they set a parameter it divides by to 0 ([`brackets::Condition::sets_a_divisor_to_zero`]),
    /// which is given with the message.
    fn divisor_set_to_zero(
        &self,
        what: &str,
        e: &Expr,
        values: &[(Var, Expr)],
    ) -> Option<(Var, String)> {
        brackets::Condition::sets_a_divisor_to_zero(values, e).map(|v| {
            let name = self.display(v);
            (
                v,
                format!("--at sets {name} = 0, but {what} divides by {name}"),
            )
        })
    }

    /// What to do about a parameter `v` that `--at` sets to 0 and a function divides by.
    fn other_than_zero(&self, v: Var) -> String {
        format!("give {} a value other than 0 with --at", self.display(v))
    }

    /// `what`, the function `e`, at the parameters' values (`given`); where they set to 0 a
    /// parameter it divides by, refused at that value in `--at`.
    fn at_values(&self, what: &str, e: &Expr, given: Given<'_>) -> Result<Expr, FileError> {
        let values = given.values;
        if let Some((v, why)) = self.divisor_set_to_zero(what, e, values) {
            let refusal = match given.at {
                Some(at) => at.refusal(&[v], why),
                None => FileError::new(ErrorKind::Condition, COMMAND_LINE, why),
            };
            return Err(refusal.with_hint(self.other_than_zero(v)));
        }
        e.subst_many(values).map_err(|err| {
            let mut error = self.computation_error(&EngineError::from(err));
            error.message = format!("{what} at the values of --at: {}", error.message);
            error
        })
    }
}

/// The parameters' values of a plot, with where `--at` writes each (`None` without `--at`).
#[derive(Clone, Copy)]
struct Given<'a> {
    /// The values, as a substitution.
    values: &'a Values,
    /// Where `--at` writes them.
    at: Option<&'a Written>,
}

/// A list of `variable = value` given on the command line (`--at`, one `--from`): its text
/// and where each variable's value is written in it, so that a refusal found after the list
/// was read is shown there, with a caret.
struct Written {
    /// The list's text.
    source: Source,
    /// Each variable with its value's text, in the order written.
    values: Vec<(Var, Text)>,
}

impl Written {
    /// A list of `source` whose values are pushed as they are read.
    fn of(source: &Source) -> Self {
        Written {
            source: source.clone(),
            values: Vec::new(),
        }
    }

    /// The refusal `why`, at the value of the last written of `vars` (where several make a
    /// function undefined together, the one whose value completes it); without a place
    /// where the list gives none of them.
    fn refusal(&self, vars: &[Var], why: String) -> FileError {
        match self.values.iter().rev().find(|(v, _)| vars.contains(v)) {
            Some((_, rhs)) => {
                rhs.error(&self.source, ErrorKind::Condition, rhs.trimmed_span(), why)
            }
            None => FileError::new(ErrorKind::Condition, COMMAND_LINE, why),
        }
    }
}

/// Why a function has no value where a plot starts: the message, the variables whose values
/// make it so, and whether `--at` (the parameters' values alone) or `--from` writes them.
struct Undefined {
    /// What is wrong.
    why: String,
    /// What to do about it.
    hint: String,
    /// The variables at fault.
    by: Vec<Var>,
    /// Whether they are the parameters of `--at`.
    in_at: bool,
}

impl Undefined {
    /// The refusal, at the value of the variable at fault in `--from` (`from`) or `--at`
    /// (`at`), as its message names.
    fn placed(self, from: &Written, at: Option<&Written>) -> FileError {
        let refusal = match (self.in_at, at) {
            (true, Some(at)) => at.refusal(&self.by, self.why),
            _ => from.refusal(&self.by, self.why),
        };
        refusal.with_hint(self.hint)
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
        _ => Err(rhs.error(source, ErrorKind::Condition, rhs.trimmed_span(), why)),
    }
}

#[cfg(test)]
mod tests {
    use super::StartValue;
    use trigpoly::Rational;

    /// An angle's multiple of π is reduced exactly modulo 2π before rounding: an odd multiple
    /// far past what `f64` holds exactly is still π (rounded first, it was an angle of no
    /// meaning); a coordinate's is not reduced.
    #[test]
    fn an_angles_multiple_of_pi_is_reduced_exactly() {
        let huge: Rational = "99999999999999999999".parse().unwrap();
        let theta = StartValue::PiTimes(huge.clone()).to_f64(true).unwrap();
        assert_eq!(theta, std::f64::consts::PI);
        let minus_quarter = StartValue::PiTimes(Rational::new(-1, 4))
            .to_f64(true)
            .unwrap();
        assert_eq!(minus_quarter, 1.75 * std::f64::consts::PI);
        let x = StartValue::PiTimes(huge).to_f64(false).unwrap();
        assert!(x > 3.1e20, "{x}");
    }
}
