//! The inputs of the discovery commands: the built-in systems by name ([`builtin_system`]),
//! and conditions, symbolic parameters and fixed values as the command line gives them.

use crate::system_file::{
    assignment_sides, comma_pieces, condition_cannot_set, fixed_twice, no_variable, trimmed,
    ErrorKind, FileError, Given, Limit, LimitSettings, CONDITION_FORM, CONDITION_USAGE, FIX_ONCE,
};
use brackets::{EngineError, System};
use trigpoly::{Expr, Limits, Rational, Style, Var};

/// The built-in systems `superint search --system NAME` knows, for use without a system file.
pub const BUILTIN_SYSTEMS: [&str; 6] = [
    "harmonic",
    "gravity",
    "anisotropic-3-5",
    "anisotropic-1-2",
    "planar-i",
    "planar-ii",
];

/// Defines `P{m}{n}, Q{m}{n}` (from the ladder `z`) and `R{m}{n}, S{m}{n}` (from `w`) for
/// `1 ≤ m, n ≤ 3`: the real and imaginary parts of `z^m e^{−inθ}` and `w^m e^{−inθ}`, shown
/// as a system file's family instances are (`P_{1,1}`, with `prime` after the letter under
/// gravity, `P'_{1,1}`), so that they are also read as the file writes them (`P_1_1`,
/// `P_{1,1}`, and under gravity `Pp_1_1`, `Pp_{1,1}`: [`System::function`]).
fn define_resonant(s: &mut System, z: &str, w: &str, prime: &str) -> Result<(), EngineError> {
    for m in 1..=3 {
        for n in 1..=3 {
            let shown = |letter: &str| format!("{letter}{prime}_{{{m},{n}}}");
            let k = s.resonant(z, m, n)?;
            s.define(&format!("P{m}{n}"), &shown("P"), k.p)?;
            s.define(&format!("Q{m}{n}"), &shown("Q"), k.q)?;
            let k = s.resonant(w, m, n)?;
            s.define(&format!("R{m}{n}"), &shown("R"), k.p)?;
            s.define(&format!("S{m}{n}"), &shown("S"), k.q)?;
        }
    }
    Ok(())
}

/// A built-in system by name (see [`BUILTIN_SYSTEMS`]), with its display name. The harmonic
/// rotor and the rotor under gravity get, besides the paper's functions, the other circular
/// ladder `W = w̄ + iMωū` (`{W, H} = iωW`, primed under gravity) and `Hp = F1 − F2`; with
/// `resonant`, also `P_{mn} + iQ_{mn} = Z^m e^{−inθ}` and `R_{mn} + iS_{mn} = W^m e^{−inθ}`
/// for `m, n ≤ 3` (named `P11`, `S23`, …, and shown, and read too, as a system file's family
/// instances, `P_{1,1}`, `P_1_1`). Its results are held to `limits`.
pub fn builtin_system(
    name: &str,
    resonant: bool,
    limits: Limits,
) -> Result<Option<(String, System)>, EngineError> {
    use brackets::systems::Rotor;
    let mut s = match name {
        "harmonic" => {
            let mut s = Rotor::Harmonic.system(limits)?;
            s.define_builtin("W", "W", "p_x - i*p_y + i*M*omega*(x - i*y)")?;
            s.define_builtin("Hp", "Hp", "F1 - F2")?;
            ("harmonic rotor".to_string(), s)
        }
        "gravity" => {
            let mut s = Rotor::Gravity.system(limits)?;
            s.define_builtin("Wp", "W'", "p_x - i*p_y + i*M*omega*(x - i*yp)")?;
            s.define_builtin("Hp", "Hp", "F1 - F2")?;
            ("rotor under gravity".to_string(), s)
        }
        "anisotropic-3-5" => (
            "anisotropic 3:5 rotor".into(),
            Rotor::Anisotropic(3, 5).system(limits)?,
        ),
        "anisotropic-1-2" => (
            "anisotropic 1:2 rotor".into(),
            Rotor::Anisotropic(1, 2).system(limits)?,
        ),
        "planar-i" => ("rotor with V_I".into(), Rotor::PlanarI.system(limits)?),
        "planar-ii" => ("rotor with V_II".into(), Rotor::PlanarII.system(limits)?),
        _ => return Ok(None),
    };
    if resonant {
        define_builtin_resonant(name, &mut s.1)?;
    }
    Ok(Some(s))
}

/// Defines in `s`, the built-in system `name` as [`builtin_system`] gives it without
/// `resonant`, the resonant functions it gives with `resonant`: `P11`, … `S33` for the
/// harmonic rotor and the rotor under gravity, none for another. A caller that wants the
/// system both with them and without adds them to a copy, rather than building it twice.
pub fn define_builtin_resonant(name: &str, s: &mut System) -> Result<(), EngineError> {
    match name {
        "harmonic" => define_resonant(s, "Z", "W", ""),
        "gravity" => define_resonant(s, "Zp", "Wp", "'"),
        _ => Ok(()),
    }
}

/// The error of the built-in system `name` (with its resonant functions when `resonant`, as
/// [`builtin_system`] builds it) that the command line's `limits` stopped, `e`: of kind
/// [`ErrorKind::Limit`], from `--system NAME`, with the hint that names the flag, as a limit
/// met by a text given on the command line to a built-in system has. Where the term or the
/// degree limit stopped it, the message says how far that limit must be raised: the least at
/// which the system is built, found by building it again (a few builds of a few terms each);
/// else, and where another limit stops it on the way, it is the engine's. Any other error is
/// of kind `Engine`.
///
/// ```
/// use superint::discovery::{builtin_system, builtin_system_refused};
/// use superint::system_file::ErrorKind;
/// use superint::trigpoly::Limits;
///
/// let limits = Limits::default().max_terms(10);
/// let e = builtin_system("harmonic", true, limits).unwrap_err();
/// let err = builtin_system_refused("harmonic", true, limits, &e);
/// assert_eq!((err.kind, err.origin.as_str()), (ErrorKind::Limit, "--system harmonic"));
/// assert_eq!(
///     err.message,
///     "the system does not fit the limits given: building it needs a term limit of at least \
///      20 (the limit is 10)"
/// );
/// assert_eq!(
///     err.hint.as_deref(),
///     Some("if the machine has the memory, raise the limit with --max-terms N")
/// );
/// ```
pub fn builtin_system_refused(
    name: &str,
    resonant: bool,
    limits: Limits,
    e: &EngineError,
) -> FileError {
    let origin = format!("--system {name}");
    let Some(limit) = Limit::of_engine(e) else {
        let message = format!("the system could not be built: {e}");
        return FileError::new(ErrorKind::Engine, &origin, message);
    };
    // Whether the system builds with the limits `raised`: `None` where a limit other than the
    // one `stopped_again` names, or anything else, stops it.
    let builds = |raised: Limits, stopped_again: &dyn Fn(Limit) -> bool| match builtin_system(
        name, resonant, raised,
    ) {
        Ok(_) => Some(true),
        Err(e) => Limit::of_engine(&e)
            .filter(|l| stopped_again(*l))
            .map(|_| false),
    };
    let least = match limit {
        Limit::Terms => least_fitting(limits.max_terms as u64, u64::from(u32::MAX), |n| {
            let raised = limits.max_terms(usize::try_from(n).unwrap_or(usize::MAX));
            builds(raised, &|l| l == Limit::Terms)
        })
        .map(|n| ("term", n, limits.max_terms as u64)),
        Limit::Degree(_) => least_fitting(
            u64::from(limits.max_degree),
            LimitSettings::BuiltInOnCommandLine.degree_ceiling(),
            |d| {
                let raised = limits.max_degree(u32::try_from(d).unwrap_or(u32::MAX));
                builds(raised, &|l| matches!(l, Limit::Degree(_)))
            },
        )
        .map(|d| ("degree", d, u64::from(limits.max_degree))),
        _ => None,
    };
    let why = match least {
        Some((which, least, given)) => {
            format!("building it needs a {which} limit of at least {least} (the limit is {given})")
        }
        None => e.to_string(),
    };
    FileError {
        hint: limit.hint(LimitSettings::BuiltInOnCommandLine),
        ..FileError::new(
            ErrorKind::Limit,
            &origin,
            format!("the system does not fit the limits given: {why}"),
        )
    }
}

/// The least value above `given`, and at most `ceiling`, at which `fits` is true, where it is
/// false at `given` and stays true once it is (a larger limit lets through all a smaller one
/// does): doubled until it fits, then halved between the last that did not and the first that
/// did. `None` where it does not fit at `ceiling`, `given` is already there (a limit no
/// setting raises further), or `fits` cannot say (`None`: something else stopped it).
fn least_fitting(given: u64, ceiling: u64, fits: impl Fn(u64) -> Option<bool>) -> Option<u64> {
    if given >= ceiling {
        return None;
    }
    let (mut short, mut enough) = (given, given.saturating_mul(2).clamp(given + 1, ceiling));
    while !fits(enough)? {
        if enough >= ceiling {
            return None;
        }
        short = enough;
        enough = enough.saturating_mul(2).min(ceiling);
    }
    while enough - short > 1 {
        let middle = short + (enough - short) / 2;
        if fits(middle)? {
            enough = middle;
        } else {
            short = middle;
        }
    }
    Some(enough)
}

/// Reads a condition `var = value[, var = value]` (such as `p_theta = 2*I*omega/3`), values
/// parsed by `parse`, which is given each value with the byte where it begins in `text` (so
/// that what it says of the value points into the condition as typed), its error returned as
/// it is (of kind [`ErrorKind::Limit`](crate::system_file::ErrorKind) where a limit stopped
/// the reading, as [`FileError::with_cause`] classifies it). A refusal of the
/// condition's form is made by `refuse`, given its byte range in `text` and its message, as a
/// file's condition is refused ([`CONDITION_USAGE`]; the caret under the comma with nothing
/// beside it, an empty side, the left side that is no variable, one a condition cannot set
/// (an angle) or one set twice, the value of the variable the condition cannot set so); one
/// that a limit stopped as the values were resolved into each other is of kind `limit`, with
/// the hint that raises it for the condition's giver, `given` (the command line's flag,
/// [`Given::CommandLineAboutBuiltIn`], or a program's `Limits`, [`Given::InCode`]), as a file's
/// condition's is. The condition is shown as a file's is, each value as it is written
/// (`p_θ = Iω`).
///
/// ```
/// use superint::brackets::systems;
/// use superint::discovery::parse_condition;
/// use superint::system_file::{ErrorKind, FileError, Given};
/// use superint::trigpoly::{Expr, Limits};
///
/// let rotor = systems::Rotor::Harmonic.system(Limits::default().max_terms(100))?;
/// let text = "x = (y + p_y + 1)^4, y = (p_x + p_theta + 1)^4";
/// let parse = |value: &str, _at: usize| -> Result<Expr, FileError> { Ok(rotor.parse(value)?) };
/// let refuse = |span: std::ops::Range<usize>, why: String| {
///     FileError::at(ErrorKind::Condition, "<condition>", text, span, why)
/// };
/// let err = parse_condition(&rotor, text, &parse, &refuse, Given::InCode).unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Limit, Some((1, 5))));
/// assert!(err.hint.is_some_and(|h| h.contains("max_terms")));
/// let err = parse_condition(&rotor, "theta = 0", &parse, &refuse, Given::InCode)
///     .unwrap_err();
/// assert_eq!(err.kind, ErrorKind::Condition);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn parse_condition(
    system: &System,
    text: &str,
    parse: &dyn Fn(&str, usize) -> Result<Expr, FileError>,
    refuse: &dyn Fn(std::ops::Range<usize>, String) -> FileError,
    given: Given,
) -> Result<brackets::Condition, FileError> {
    parse_condition_checked(system, text, parse, refuse, given, &|_| Ok(()))
}

/// [`parse_condition`] with what the condition's use asks of it besides (`check`), whose
/// refusal of a variable ([`EngineError::RefusedCondition`]) is shown at its value, as the
/// reading's own are: given the refusal a computation under the condition met, it places
/// that refusal in `text`.
pub fn parse_condition_checked(
    system: &System,
    text: &str,
    parse: &dyn Fn(&str, usize) -> Result<Expr, FileError>,
    refuse: &dyn Fn(std::ops::Range<usize>, String) -> FileError,
    given: Given,
    check: &dyn Fn(&brackets::Condition) -> Result<(), EngineError>,
) -> Result<brackets::Condition, FileError> {
    let vars = system.vars();
    let mut subs: Vec<(Var, Expr)> = Vec::new();
    // Where each value is written, for a refusal of the condition as a whole.
    let mut values = Vec::new();
    let mut shown = Vec::new();
    let printer = crate::system_file::LoadedSystem::of_system(system.clone());
    let pieces = comma_pieces(text);
    for (k, &(at, piece)) in pieces.iter().enumerate() {
        // A comma with nothing after it (`M = 1,`), or before it (`, M = 1`).
        if let Some(missing) = blank_beside_comma(&pieces, k, "a condition", CONDITION_USAGE) {
            return Err(refuse(missing.span, missing.message));
        }
        // Split as a file's condition is.
        let [lhs, rhs] = assignment_sides(piece, CONDITION_USAGE)
            .map_err(|(span, why)| refuse(at + span.start..at + span.end, why))?;
        let (name, name_span) = trimmed(at + lhs.start, &piece[lhs]);
        let (value, value_span) = trimmed(at + rhs.start, &piece[rhs]);
        let name_at = name_span.start;
        // Read as a file's left side is, by the parser: `\omega`, `p_{x}` and `ϵ` name the
        // variables they write.
        let read = name_read(name).map_err(|e| {
            refuse(
                name_at + e.span.start..name_at + e.span.end,
                e.message().to_string(),
            )
        })?;
        let Some(v) = read.as_deref().and_then(|n| vars.lookup(n)) else {
            let settable: Vec<&str> = vars
                .vars()
                .filter(|&v| condition_cannot_set(system, v).is_none())
                .map(|v| vars.variable(v).name())
                .collect();
            let meant = read
                .as_deref()
                .map_or_else(String::new, |n| trigpoly::did_you_mean_hint(n, &settable));
            return Err(refuse(
                name_span,
                no_variable(&CONDITION_FORM, system, name, &meant),
            ));
        };
        // An angle, refused at its name as a file's condition refuses it.
        if let Some(why) = condition_cannot_set(system, v) {
            return Err(refuse(name_span, why));
        }
        if subs.iter().any(|(w, _)| *w == v) {
            return Err(refuse(name_span, fixed_twice(name)).with_hint(FIX_ONCE));
        }
        let expr = parse(value, value_span.start)?;
        // As a file's condition prints, the value as it is written, in the paper's notation
        // (`p_θ = Iω`), not its normal form, whose order of the variables is the system's
        // (`ωI`); the normal form where the file's reading refuses the text.
        let written = printer
            .shown_argument(value)
            .unwrap_or_else(|_| expr.render(Style::Unicode));
        shown.push(format!("{} = {written}", vars.variable(v).unicode()));
        subs.push((v, expr));
        values.push(value_span);
    }
    brackets::Condition::all(&shown.join(", "), subs.clone())
        .and_then(|c| check(&c).map(|()| c))
        .map_err(|e| {
            // At the value of the variable it is about, else at the first.
            let k = match &e {
                EngineError::RefusedCondition { var, .. } => {
                    subs.iter().position(|(w, _)| w == var).unwrap_or(0)
                }
                _ => 0,
            };
            // The settings of the condition's giver (the command line's flag, a program's
            // `Limits`).
            refuse(values[k].clone(), e.to_string()).limited_by(&e, LimitSettings::of(given))
        })
}

/// The name `text` writes, read by the parser (`\omega` and `ϵ` write `omega` and
/// `epsilon`), or none where it writes more than a name; its error where it does not parse.
fn name_read(text: &str) -> Result<Option<String>, trigpoly::syntax::ParseError> {
    Ok(match trigpoly::syntax::parse_expr(text)?.kind {
        trigpoly::syntax::ExprKind::Name(n) => Some(n),
        _ => None,
    })
}

/// The parameter called `name`, read as a condition's left side is, by the parser (`\omega`
/// and `ϵ` name `omega` and `epsilon`); another name is refused with the parameters there are,
/// and the one it was probably meant to be (`alfa` for `alpha`).
fn parameter(system: &System, name: &str) -> Result<Var, String> {
    let vars = system.vars();
    let read = name_read(name).ok().flatten();
    read.and_then(|n| vars.lookup(&n))
        .or_else(|| vars.lookup(name))
        .filter(|v| vars.variable(*v).kind() == trigpoly::VarKind::Parameter)
        .ok_or_else(|| {
            let parameters: Vec<&str> = vars
                .vars()
                .filter(|&v| vars.variable(v).kind() == trigpoly::VarKind::Parameter)
                .map(|v| vars.variable(v).name())
                .collect();
            let meant = trigpoly::did_you_mean_hint(name, &parameters);
            let known = match parameters.as_slice() {
                [] => "it has none".to_string(),
                names => format!("its parameters: {}", names.join(", ")),
            };
            format!(
                "{} is not a parameter of the system{meant} ({known})",
                trigpoly::quoted_name(name)
            )
        })
}

/// A refusal of a list given to an option (`--fix`, `--symbolic`): what is wrong, and the
/// byte range of the list it is about (a comma with nothing beside it, a name, a value), so
/// that the caller shows it as a condition's refusal is shown, `<command line>:1:C:` with the
/// text and a caret. It displays as its message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ListRefusal {
    /// The byte range of the list under the caret.
    pub span: std::ops::Range<usize>,
    /// What is wrong, in one line.
    pub message: String,
}

impl std::fmt::Display for ListRefusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ListRefusal {}

/// Where the `k`th of `pieces` (a list split at its commas, each with its first byte, as by
/// [`comma_pieces`]) is blank beside a comma, that `what` is missing after the comma (`M=1,`)
/// or before it (`,M=1`), at that comma: `a value is missing after this comma`, then `usage`,
/// for a condition, `--fix`, `--symbolic`, `--known` and a tower's `--family` alike. A list of
/// one blank piece has no comma to blame, and is left to the caller.
pub(crate) fn blank_beside_comma(
    pieces: &[(usize, &str)],
    k: usize,
    what: &str,
    usage: &str,
) -> Option<ListRefusal> {
    let (at, piece) = pieces[k];
    if !piece.trim().is_empty() || pieces.len() < 2 {
        return None;
    }
    let (comma, side) = match k {
        0 => (at + piece.len(), "before"),
        _ => (at - 1, "after"),
    };
    Some(ListRefusal {
        span: comma..comma + 1,
        message: format!("{what} is missing {side} this comma: {usage}"),
    })
}

/// Refuses a name of a list (`--symbolic`, `--fix`), which begins at byte `at` of the list,
/// where it holds a line break, a tab or another character that shows nothing
/// ([`unshowable_in_name`](crate::system_file::unshowable_in_name)), at that character,
/// the name escaped and `usage` after, before any other refusal quotes it.
fn unshowable_name(name: &str, at: usize, usage: &str) -> Result<(), ListRefusal> {
    match crate::system_file::unshowable_in_name(name) {
        Some((span, why)) => Err(ListRefusal {
            span: at + span.start..at + span.end,
            message: format!("{why}: {usage}"),
        }),
        None => Ok(()),
    }
}

/// How `--symbolic` reads, for its refusals.
const SYMBOLIC_USAGE: &str = "name parameters as A,B, such as M,omega";

/// Parameters named in `A,B` (kept symbolic by a search); a blank text names none, and a
/// comma with no name after it or before it is refused at the comma, as in [`parse_fixed`],
/// as is a name that is no parameter, or a parameter named twice, at the name.
pub fn parse_symbolic(system: &System, text: &str) -> Result<Vec<Var>, ListRefusal> {
    let pieces = comma_pieces(text);
    let mut out = Vec::new();
    for (k, &(at, piece)) in pieces.iter().enumerate() {
        if let Some(missing) = blank_beside_comma(&pieces, k, "a parameter", SYMBOLIC_USAGE) {
            return Err(missing);
        }
        let (name, span) = trimmed(at, piece);
        if name.is_empty() {
            continue;
        }
        unshowable_name(name, span.start, SYMBOLIC_USAGE)?;
        let refuse = |message| ListRefusal {
            span: span.clone(),
            message,
        };
        let v = parameter(system, name).map_err(refuse)?;
        // Named twice (`M,M`, or `omega,ω`), it counted twice: a search's space had each of
        // its monomials again, and a closure found the relations 0 = 0.
        if out.contains(&v) {
            return Err(refuse(format!(
                "{} is named twice",
                trigpoly::quoted_name(name)
            )));
        }
        out.push(v);
    }
    Ok(out)
}

/// How `--known` reads, for its refusals.
const KNOWN_USAGE: &str = "expressions or family instances separated by commas, such as L,P_1_1";

/// The expressions of `--known` (`L,P_{1,1}`), each with its byte range in `text`: split at
/// the commas outside braces (a comma inside belongs to an instance), trimmed; a blank text
/// gives none, and a comma with no expression after it or before it is refused at the comma,
/// as in [`parse_fixed`].
pub fn parse_known(text: &str) -> Result<Vec<std::ops::Range<usize>>, ListRefusal> {
    let pieces: Vec<(usize, &str)> = crate::system_file::split_top_level(text, ',')
        .into_iter()
        .map(|r| (r.start, &text[r]))
        .collect();
    let mut out = Vec::new();
    for (k, &(at, piece)) in pieces.iter().enumerate() {
        if let Some(missing) = blank_beside_comma(&pieces, k, "an expression", KNOWN_USAGE) {
            return Err(missing);
        }
        let (expression, span) = trimmed(at, piece);
        if !expression.is_empty() {
            out.push(span);
        }
    }
    Ok(out)
}

/// How `--fix` reads, for its refusals.
const FIX_USAGE: &str = "give a value as NAME=VALUE, such as omega=1";

/// Reads parameter values `omega=1,M=2/3`; a blank text fixes none. A comma with no value
/// after it or before it is refused at the comma, as [`parse_condition`] refuses one; a value
/// with no `=`, or nothing on one side of it, at the value or its `=`; a name that is no
/// parameter, or one given two values, at the name; a value that is no number, or a zero
/// where the system has no value or its radicals may not be independent
/// (`zero_has_no_value`), at the value.
pub fn parse_fixed(system: &System, text: &str) -> Result<Vec<(Var, Rational)>, ListRefusal> {
    let mut out = Vec::new();
    let pieces = comma_pieces(text);
    for (k, &(at, piece)) in pieces.iter().enumerate() {
        if let Some(missing) = blank_beside_comma(&pieces, k, "a value", FIX_USAGE) {
            return Err(missing);
        }
        let (whole, whole_span) = trimmed(at, piece);
        if whole.is_empty() {
            continue;
        }
        let refuse = |span: std::ops::Range<usize>, message| ListRefusal { span, message };
        let Some(eq) = piece.find('=') else {
            return Err(refuse(
                whole_span,
                format!("{} has no '=': {FIX_USAGE}", trigpoly::quoted_name(whole)),
            ));
        };
        let (name, name_span) = trimmed(at, &piece[..eq]);
        let (value, value_span) = trimmed(at + eq + 1, &piece[eq + 1..]);
        let eq_span = at + eq..at + eq + 1;
        if name.is_empty() {
            return Err(refuse(
                eq_span,
                format!("a name is missing before this '=': {FIX_USAGE}"),
            ));
        }
        if value.is_empty() {
            return Err(refuse(
                eq_span,
                format!("a value is missing after this '=': {FIX_USAGE}"),
            ));
        }
        unshowable_name(name, name_span.start, FIX_USAGE)?;
        let v = parameter(system, name).map_err(|m| refuse(name_span.clone(), m))?;
        if out.iter().any(|(w, _)| *w == v) {
            return Err(refuse(
                name_span,
                format!("{} is given two values", trigpoly::quoted_name(name)),
            ));
        }
        // A decimal is the fraction it writes, as in plot's --at (`0.5` is `1/2`).
        let q: Rational = match value.parse::<Rational>() {
            Ok(q) => q,
            Err(e) if e.kind() == trigpoly::RationalErrorKind::ZeroDenominator => {
                return Err(refuse(
                    value_span,
                    format!(
                        "{} is a division by zero: a fraction's denominator is nonzero",
                        trigpoly::quoted_name(value)
                    ),
                ));
            }
            Err(_) => match crate::system_file::decimal_number(value) {
                Some(q) => q,
                None => {
                    return Err(refuse(
                        value_span,
                        format!(
                            "{} is not a number: write a fraction such as 2/3, or a decimal \
                             such as 1.5",
                            trigpoly::quoted_name(value)
                        ),
                    ))
                }
            },
        };
        if q.is_zero() {
            if let Some(why) = zero_has_no_value(system, v) {
                return Err(refuse(value_span, format!("{name} = 0: {why}")));
            }
        }
        out.push((v, q));
    }
    Ok(out)
}

/// Why `v` may not be fixed to zero, if it may not: `H` divides by it (`M3²/(2 I3)`: `H` has
/// no value there), or a radicand holds it (at zero it may be a square, or another's: the two
/// centres' radicands coincide at `a = 0`, and their radicals are taken as independent).
/// Elsewhere zero is a value as any other (`--fix c=0`, where nothing is lifted back to `c`).
fn zero_has_no_value(system: &System, v: Var) -> Option<String> {
    let vars = system.vars();
    let name = vars.variable(v).unicode();
    if system.hamiltonian().low_degree(v).unwrap_or(0) < 0 {
        return Some(format!(
            "H divides by {name}, so it has no value at {name} = 0: give {name} another value"
        ));
    }
    let (radical, radicand) = system
        .space()
        .radicals()
        .iter()
        .find(|(_, r)| r.contains(v))?;
    Some(format!(
        "the radicand of {} = √({radicand}) holds {name}, and at {name} = 0 it may be a square \
         or another radicand, while the radicals are taken as independent: give {name} another \
         value",
        vars.variable(*radical).unicode()
    ))
}
