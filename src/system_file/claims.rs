//! Claims of a system file: `lhs = rhs` under optional conditions, or `rank(F, G, …) = r`;
//! read (syntax, conditions) when the file is loaded, computed by
//! [`LoadedSystem::check_claim`].

use std::ops::Range;
use std::time::Instant;

use brackets::search::LevelReduction;
use brackets::{
    level_set_coordinates, rank, rank_restricted, Claim, Condition, EngineError, Input,
};
use toml::Spanned;
use trigpoly::syntax::{Expr as Tree, ExprKind};
use trigpoly::{AlgebraError, Expr, ParseCause, Span, VarKind};

use super::error::{ErrorKind, FileError};
use super::model::{ClaimModel, When};
use super::on_level::{read_level_set, ClaimLevelSet};
use super::scope::{rewrite_braces, Limit, LimitSettings};
use super::text::{array_strings, split_top_level, unbalanced_bracket, Source, Text};
use super::written::Reach;
use super::LoadedSystem;
use crate::report::{outcome_parts, ClaimKind, ClaimResult, Expect, RankResult, UNKNOWN_OUTCOME};

/// The claim a certified rank answers ([`LoadedSystem::rank_result`]): a file's rank claim,
/// or the command line's `superint rank`, whose errors point at the functions it lists.
pub(crate) struct RankClaim<'a> {
    /// The text the claim is read from, where its errors are located.
    pub(crate) source: &'a Source,
    /// The claim's id: the file's (`C12`), or `rank`.
    pub(crate) id: &'a str,
    /// Whether the claim is meant to be proved or deliberately refuted.
    pub(crate) expect: Expect,
    /// Where the claim is in `source`: what a refusal underlines.
    pub(crate) span: Range<usize>,
    /// Where each function is in `source`: what a refusal of one of them (a limit its
    /// derivatives reach) underlines.
    pub(crate) functions: Vec<Range<usize>>,
    /// When its check began, for the time it took.
    pub(crate) start: Instant,
}

/// What a claim says.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum ClaimForm {
    /// `lhs = rhs`.
    Identity {
        /// The left side's text.
        lhs: Text,
        /// The right side's text.
        rhs: Text,
    },
    /// `rank(F, G, …) = r`: the Jacobian of the functions by the phase-space coordinates.
    Rank {
        /// Each function: as printed, and its text.
        functions: Vec<(String, Text)>,
        /// The claimed rank.
        expected: usize,
    },
}

/// A claim as read from the file: id, statement in the paper's notation, form, condition,
/// expectation, and where it is.
#[derive(Clone, Debug)]
pub struct ClaimSpec {
    /// The id (`id`, or `#k` for the `k`-th claim).
    pub id: String,
    /// The statement in the paper's notation (`{L, G1} = −G2`).
    pub statement: String,
    /// The claim as the file writes it (`{L, G1} = -G2`).
    pub written: String,
    /// What the claim says.
    pub form: ClaimForm,
    /// The condition (substitutions applied after the sides are computed), if any.
    pub condition: Option<Condition>,
    /// The level set the claim is made on (`on = "A = 0"`), if any: `lhs − rhs` is divided
    /// by its polynomial.
    pub on: Option<ClaimLevelSet>,
    /// Proved, or deliberately refuted.
    pub expect: Expect,
    /// Where the claim's text is in its source.
    pub span: Range<usize>,
    /// Its source: the file's text, or for a claim added in code
    /// ([`LoadedSystem::add_claim`]) its own.
    pub(crate) source: Source,
}

/// A checked claim, as the report shows it.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum CheckedClaim {
    /// An identity, proved or refuted with its residual.
    Identity(Box<ClaimResult>),
    /// A rank, with its certificate.
    Rank(Box<RankResult>),
}

impl CheckedClaim {
    /// The claim's result.
    pub fn result(&self) -> &ClaimResult {
        match self {
            CheckedClaim::Identity(c) => c,
            CheckedClaim::Rank(r) => &r.claim,
        }
    }
}

/// An engine error at a place of the file: limits are limit errors, with the hint that names
/// the setting raising the limit for the text's giver, the engine's message naming none.
pub(crate) fn engine_error(source: &Source, span: Range<usize>, e: &EngineError) -> FileError {
    engine_error_under(source, span, e, LimitSettings::of(source.given))
}

/// [`engine_error`], a limit's hint naming the settings `settings`.
fn engine_error_under(
    source: &Source,
    span: Range<usize>,
    e: &EngineError,
    settings: LimitSettings,
) -> FileError {
    let message = e.to_string();
    let err = match Limit::of_engine(e) {
        Some(limit) => FileError {
            hint: limit.hint(settings),
            ..source.error(ErrorKind::Limit, span, message)
        },
        None => source.error(ErrorKind::Engine, span, message),
    };
    FileError {
        engine: Some(Box::new(e.clone())),
        ..err
    }
}

/// An engine error in a function that returns a `FileError`, so that `?` takes it: an
/// expression that did not parse is of kind [`ErrorKind::Expression`], from `<expression>`,
/// at its line and column when the error has its text ([`brackets::System::parse`]'s do), with
/// the cause its parse met ([`FileError::cause`]: a limit, an unknown name), as one of
/// [`Expr::parse`](trigpoly::Expr::parse) has, and of kind [`ErrorKind::Limit`], with the
/// hint, where a limit stopped it, as the loader says of a file's text; a computation a
/// program asked for is of kind [`ErrorKind::Limit`] (with the hint to raise the limit: a
/// search's or a closure's own option, `SearchOptions::max_products`, too) or
/// [`ErrorKind::Engine`], from `<program>`, without a location.
///
/// ```
/// use superint::prelude::*;
///
/// fn rank_of_rotor(names: &[&str]) -> Result<usize, FileError> {
///     let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
///     Ok(rotor.system().rank(names)?.rank)
/// }
/// assert_eq!(rank_of_rotor(&["F1", "F2", "L"]).unwrap(), 3);
/// let err = rank_of_rotor(&["F1", "nope"]).unwrap_err();
/// assert_eq!((err.kind, err.message.as_str()), (ErrorKind::Engine, "unknown function 'nope'"));
///
/// let rotor = systems::harmonic_rotor();
/// let err = FileError::from(rotor.parse("{L,\n G1 + }").unwrap_err());
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((2, 7))));
/// let err = FileError::from(rotor.parse("x^5000").unwrap_err());
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Limit, Some((1, 3))));
/// ```
impl From<EngineError> for FileError {
    fn from(e: EngineError) -> Self {
        let expression = "<expression>";
        match e {
            EngineError::Parse {
                source_text, error, ..
            } if !source_text.is_empty() => FileError::at(
                ErrorKind::Expression,
                expression,
                &source_text,
                error.span.start..error.span.end,
                error.message(),
            )
            .with_cause_under(error.cause(), LimitSettings::Program),
            // Located by its own excerpt when it knows its source.
            EngineError::Parse { error, .. } if error.excerpt().is_some() => error.into(),
            EngineError::Parse { message, error, .. } => {
                FileError::new(ErrorKind::Expression, expression, message)
                    .with_cause_under(error.cause(), LimitSettings::Program)
            }
            e => {
                let program = Source::new("<program>", "");
                let mut err = engine_error_under(&program, 0..0, &e, LimitSettings::Program);
                err.location = None;
                err
            }
        }
    }
}

/// An algebraic error (a limit, a division by a polynomial, variables declared twice), as the
/// engine's ([`EngineError::Algebra`]) becomes a `FileError`.
impl From<AlgebraError> for FileError {
    fn from(e: AlgebraError) -> Self {
        EngineError::from(e).into()
    }
}

impl ClaimSpec {
    /// The claim's identity as its certified rank answers it, its check begun at `start`.
    fn rank_claim(&self, start: Instant) -> RankClaim<'_> {
        let functions = match &self.form {
            ClaimForm::Rank { functions, .. } => {
                functions.iter().map(|(_, t)| t.whole_span()).collect()
            }
            ClaimForm::Identity { .. } => Vec::new(),
        };
        RankClaim {
            source: &self.source,
            id: &self.id,
            expect: self.expect,
            span: self.span.clone(),
            functions,
            start,
        }
    }

    /// Reads the `k`-th claim of a file.
    pub(crate) fn parse(
        file: &LoadedSystem,
        k: usize,
        model: &Spanned<ClaimModel>,
    ) -> Result<ClaimSpec, FileError> {
        let source = &file.source;
        let c = model.get_ref();
        let text = Text::in_toml(&source.text, c.claim.span(), c.claim.get_ref());
        let id = match &c.id {
            Some(id) if id.get_ref().trim().is_empty() => {
                return Err(source.error(ErrorKind::Claim, id.span(), "a claim's id is empty"))
            }
            Some(id) => {
                let text = Text::in_toml(&source.text, id.span(), id.get_ref());
                let what = ("a claim's id", ErrorKind::Claim);
                super::names::check_shown_text(source, &text, what, false)?;
                id.get_ref().clone()
            }
            None => format!("#{}", k + 1),
        };
        let when = match &c.when {
            None => None,
            Some(w) => Some(condition_texts(file, w)?),
        };
        let expect = c.expect.as_ref().map_or(Expect::Proved, |e| *e.get_ref());
        let on =
            c.on.as_ref()
                .map(|on| Text::in_toml(&source.text, on.span(), on.get_ref()));
        let spec = ClaimSpec::read(file, source, id, text, when, expect, c.claim.span())?;
        spec.on_level_set(file, on)
    }

    /// The claim made on the level set written `on`, if any ([`read_level_set`]).
    pub(super) fn on_level_set(
        mut self,
        file: &LoadedSystem,
        on: Option<Text>,
    ) -> Result<Self, FileError> {
        let Some(on) = on else {
            return Ok(self);
        };
        let sides = match &self.form {
            ClaimForm::Identity { lhs, rhs } => Some((lhs, rhs)),
            ClaimForm::Rank { .. } => None,
        };
        let scope = file.scope(file.families.len());
        let trees = match sides {
            Some((lhs, rhs)) => Some((
                scope.tree(&self.source, lhs)?,
                scope.tree(&self.source, rhs)?,
            )),
            None => None,
        };
        let level = read_level_set(
            file,
            &self.source,
            &on,
            &self.form,
            self.condition.as_ref(),
            trees.as_ref().map(|(l, r)| (l, r)),
        )?;
        self.on = Some(level);
        Ok(self)
    }

    /// Reads a claim's text of `source` (`text`, written at `span`) with its condition's
    /// pieces, if any.
    pub(crate) fn read(
        file: &LoadedSystem,
        source: &Source,
        id: String,
        text: Text,
        when: Option<Vec<Text>>,
        expect: Expect,
        span: Range<usize>,
    ) -> Result<ClaimSpec, FileError> {
        let scope = file.scope(file.families.len());
        let (lhs, rhs) = claim_sides(source, &text)?;
        let lhs_tree = scope.tree(source, &lhs)?;
        let rhs_tree = scope.tree(source, &rhs)?;
        let form = match &lhs_tree.kind {
            ExprKind::Call(f, _, args) if f == "rank" => {
                rank_form(file, source, &lhs, args, &rhs, &rhs_tree)?
            }
            _ => ClaimForm::Identity { lhs, rhs },
        };
        let condition = match when {
            None => None,
            Some(pieces) => Some(claim_condition(file, source, &pieces, &form)?),
        };
        let statement = match &form {
            ClaimForm::Rank {
                functions,
                expected,
            } => {
                // On a level set, by the phase variables it leaves free.
                let names: Vec<&str> = functions.iter().map(|f| f.0.as_str()).collect();
                let space = file.system.space();
                let coordinates = match &condition {
                    Some(c) => level_set_coordinates(space, c)
                        .map_err(|e| engine_error(source, span.clone(), &e))?,
                    None => space.coordinates(),
                };
                RankResult::statement(&names, file.system.vars(), &coordinates, *expected)
            }
            ClaimForm::Identity { .. } => {
                format!("{} = {}", file.pretty(&lhs_tree), file.pretty(&rhs_tree))
            }
        };
        Ok(ClaimSpec {
            id,
            statement,
            written: text.value.clone(),
            form,
            condition,
            on: None,
            expect,
            span,
            source: source.clone(),
        })
    }
}

/// The two sides of a claim's text, `lhs = rhs`, each refusal at its place: a bracket that is
/// not closed or closes nothing, no `=` or more than one, an empty side.
fn claim_sides(source: &Source, text: &Text) -> Result<(Text, Text), FileError> {
    let parts = split_top_level(&text.value, '=');
    let usage = "a claim reads `lhs = rhs`, such as \"{L, G1} = -G2\", or \
                 `rank(F, G, ...) = r`";
    if let (1, Some((at, message))) = (parts.len(), unbalanced_bracket(&text.value)) {
        return Err(text.error(source, ErrorKind::Claim, Span::new(at, at + 1), message));
    }
    if parts.len() == 1 {
        return Err(text.error(
            source,
            ErrorKind::Claim,
            Span::new(0, text.value.len()),
            format!("{usage}; there is no '=' here"),
        ));
    }
    if parts.len() > 2 {
        let at = parts[2].start - 1;
        return Err(text.error(
            source,
            ErrorKind::Claim,
            Span::new(at, at + 1),
            format!("{usage}, with one '='; put conditions in `when`"),
        ));
    }
    let lhs = text.slice(parts[0].clone());
    let rhs = text.slice(parts[1].clone());
    for side in [&lhs, &rhs] {
        if side.value.trim().is_empty() {
            return Err(side.error(
                source,
                ErrorKind::Claim,
                Span::new(0, side.value.len()),
                format!("{usage}; one side is empty"),
            ));
        }
    }
    Ok((lhs, rhs))
}

/// A rank claim `rank(F, G, …) = r` (`lhs` the call, `args` its arguments): its form, each
/// function as printed with its text.
fn rank_form(
    file: &LoadedSystem,
    source: &Source,
    lhs: &Text,
    args: &[Tree],
    rhs: &Text,
    rhs_tree: &Tree,
) -> Result<ClaimForm, FileError> {
    let expected = claimed_rank(source, rhs, rhs_tree)?;
    // Family instances written K_{1,1} are K_1_1 in the rewritten text, at the
    // same places.
    let rewritten = lhs.rewritten(rewrite_braces(&lhs.value, &file.families, &[]));
    let functions: Vec<(String, Text)> = args
        .iter()
        .map(|a| (file.pretty(a), rewritten.slice(a.span.start..a.span.end)))
        .collect();
    Ok(ClaimForm::Rank {
        functions,
        expected,
    })
}

/// The rank that a rank claim's right side states: a whole number, refused when it is none
/// or too large to be one.
fn claimed_rank(source: &Source, rhs: &Text, rhs_tree: &Tree) -> Result<usize, FileError> {
    let expected = match &rhs_tree.kind {
        ExprKind::Integer(n) => usize::try_from(n.clone()).ok(),
        _ => None,
    };
    let Some(expected) = expected else {
        // A rank above the dimension but within a `usize` (`= 9` for two coordinates) is a
        // claim like another, refuted; only a number no `usize` holds is refused here.
        let why = match &rhs_tree.kind {
            ExprKind::Integer(_) => {
                "the right side of a rank claim is a whole number, and this one is too large \
                 to be a rank (at most the number of functions, and of phase variables)"
            }
            _ => "the right side of a rank claim is a whole number, such as 5",
        };
        return Err(rhs.error(source, ErrorKind::Claim, rhs_tree.span, why));
    };
    Ok(expected)
}

/// The condition of a claim of the given form, read from the pieces of its `when`.
fn claim_condition(
    file: &LoadedSystem,
    source: &Source,
    pieces: &[Text],
    form: &ClaimForm,
) -> Result<Condition, FileError> {
    // Where the condition sets a variable to 0, each thing the claim is computed from must
    // have a value there: `{A, H} = 0` is no claim at `I3 = 0` when `H` divides by `I3`.
    // A claim whose own values divide by it is refused when checked, at the claim.
    let inputs_defined = |c: &Condition| {
        if !c.subs().iter().any(|(_, v)| v.is_zero()) {
            return Ok(());
        }
        let (values, inputs) = claim_inputs(file, source, form);
        match values
            .iter()
            .any(|v| Condition::sets_a_divisor_to_zero(c.subs(), v).is_some())
        {
            true => Ok(()),
            false => c.defined_on_inputs(&inputs),
        }
    };
    match form {
        ClaimForm::Rank { .. } => parse_condition_with(file, source, pieces, |c| {
            c.level_set_variables()?;
            inputs_defined(c)
        }),
        ClaimForm::Identity { .. } => parse_condition_with(file, source, pieces, inputs_defined),
    }
}

/// A claim's sides, or a rank's functions, and what they are computed from
/// ([`brackets::Recording`]): the functions they name (`H` among them) and the declared
/// brackets their brackets take. A text whose value cannot be computed (a limit) adds nothing
/// here; checking the claim says why.
fn claim_inputs(file: &LoadedSystem, source: &Source, form: &ClaimForm) -> (Vec<Expr>, Vec<Input>) {
    let scope = file.scope(file.families.len());
    let recording = scope.recording();
    let texts: Vec<&Text> = match form {
        ClaimForm::Identity { lhs, rhs } => vec![lhs, rhs],
        ClaimForm::Rank { functions, .. } => functions.iter().map(|(_, t)| t).collect(),
    };
    // A failure is the check's to report.
    let values = texts
        .into_iter()
        .filter_map(|text| scope.parse_into(source, text, &recording).ok())
        .collect();
    (values, recording.into_inputs())
}

/// The pieces of `when`: `var = value` texts separated by commas, or an array of them.
fn condition_texts(file: &LoadedSystem, when: &Spanned<When>) -> Result<Vec<Text>, FileError> {
    let source = &file.source;
    let pieces: Vec<Text> = match when.get_ref() {
        When::One(s) => Text::in_toml(&source.text, when.span(), s).split(','),
        When::Many(items) => match array_strings(&source.text, when.span()) {
            Some(spans) if spans.len() == items.len() => spans
                .into_iter()
                .zip(items)
                .map(|(span, s)| Text::in_toml(&source.text, span, s))
                .collect(),
            _ => items
                .iter()
                .map(|s| Text::in_toml(&source.text, when.span(), s))
                .collect(),
        },
    };
    if pieces.is_empty() {
        return Err(source.error(
            ErrorKind::Condition,
            when.span(),
            "`when` is empty: give a condition such as \"p_theta = 2*I*omega/3\"",
        ));
    }
    Ok(pieces)
}

/// How a condition reads, with an example: the usage its refusals give, a file's and a
/// built-in system's alike ([`crate::discovery::parse_condition`]).
pub const CONDITION_USAGE: &str =
    "a condition reads `variable = value`, such as \"p_theta = 2*I*omega/3\"";

/// How a condition reads, for its messages, a file's and a built-in system's alike.
pub(crate) const CONDITION_FORM: AssignmentForm<'static> = AssignmentForm {
    what: "a condition",
    kinds: "a coordinate, a momentum or a parameter",
    kinds_with_poisson: "a coordinate, a momentum, a Poisson variable or a parameter",
    usage: CONDITION_USAGE,
    decimals: false,
    pi: false,
};

/// Why a condition cannot set the variable `v` of `system`, refused at the variable before the
/// condition is made, a file's and a built-in system's alike
/// ([`crate::discovery::parse_condition`]): an angle, on which functions depend through cos,
/// sin and exp, and a variable [`Condition::cannot_set`] refuses (a radical, a denominator);
/// `None` for one it may set.
pub(crate) fn condition_cannot_set(system: &brackets::System, v: trigpoly::Var) -> Option<String> {
    if system.vars().variable(v).kind() == VarKind::Angle {
        return Some(
            "a condition cannot fix an angle: functions depend on it through cos, sin, exp".into(),
        );
    }
    Condition::cannot_set(system.space(), v)
}

/// Reads conditions `var = value` (one per text) of `source` into one substitution.
pub(crate) fn parse_condition(
    file: &LoadedSystem,
    source: &Source,
    pieces: &[Text],
) -> Result<Condition, FileError> {
    parse_condition_with(file, source, pieces, |_| Ok(()))
}

/// Reads a rank's conditions as [`parse_condition`] does, which describe a level set
/// ([`Condition::level_set_variables`]): they set parameters to numbers or other parameters,
/// and phase variables to values in them and the other phase variables; a parameter set to a
/// function of phase space is refused at its value.
pub(crate) fn parse_rank_condition(
    file: &LoadedSystem,
    source: &Source,
    pieces: &[Text],
) -> Result<Condition, FileError> {
    parse_condition_with(file, source, pieces, |c| c.level_set_variables().map(drop))
}

/// [`parse_condition`] with what the condition's use asks of it besides (`check`): a refusal
/// of a variable ([`EngineError::RefusedCondition`]) is shown at its value, as the reading's
/// own are.
pub(crate) fn parse_condition_with(
    file: &LoadedSystem,
    source: &Source,
    pieces: &[Text],
    check: impl Fn(&Condition) -> Result<(), EngineError>,
) -> Result<Condition, FileError> {
    let vars = file.system.vars();
    let admit = |v: trigpoly::Var| condition_cannot_set(&file.system, v);
    let assignments = parse_assignments(file, source, pieces, &CONDITION_FORM, admit)?;
    let text = assignments
        .iter()
        .map(|a| a.shown.as_str())
        .collect::<Vec<_>>()
        .join(", ");
    let subs = assignments
        .iter()
        .map(|a| (a.var, a.value.clone()))
        .collect();
    Condition::all(&text, subs)
        .and_then(|c| check(&c).map(|()| c))
        .map_err(|e| {
            // A refused condition is shown at the value of the variable it is about, or at the
            // variable where it may not be set at all (a radical, `r = 1`, or a denominator).
            let at = match &e {
                EngineError::RefusedCondition { var, .. } => {
                    assignments.iter().find(|a| a.var == *var)
                }
                _ => None,
            };
            let a = at.unwrap_or(&assignments[0]);
            let side = match vars.variable(a.var).kind() {
                VarKind::Radical | VarKind::Denominator if at.is_some() => &a.lhs,
                _ => &a.rhs,
            };
            side.error(
                source,
                ErrorKind::Condition,
                side.trimmed_span(),
                e.to_string(),
            )
            .limited_by(&e, LimitSettings::of(source.given))
        })
}

/// How a list of `var = value` reads, for its messages.
pub(crate) struct AssignmentForm<'a> {
    /// What one is called: `a condition`.
    pub what: &'a str,
    /// What its left side may name: `a coordinate, a momentum or a parameter`.
    pub kinds: &'a str,
    /// What it may name in a system with Poisson variables, which `kinds` leaves out: `a
    /// coordinate, a momentum, a Poisson variable or a parameter`.
    pub kinds_with_poisson: &'a str,
    /// How one reads, with an example.
    pub usage: &'a str,
    /// Whether a right side may be a decimal number (`0.25`, `−1.5`, `2.5e-3`), read as the
    /// fraction it writes: the numbers of `plot`. An expression is still exact fractions only.
    pub decimals: bool,
    /// Whether a right side may be a rational multiple of π alone (`3*pi/4`, `−π/2`): a
    /// starting angle of `plot`, which floating point rounds. [`Assignment::pi_times`] says so.
    pub pi: bool,
}

/// A leading sign (`-`, `−` or `+`) taken off: whether it was a minus, and the rest.
fn split_sign(s: &str) -> (bool, &str) {
    match s.strip_prefix(['-', '+', '−']) {
        Some(rest) => (!s.starts_with('+'), rest),
        None => (false, s),
    }
}

/// The rational `q` of a multiple of π written alone: an optional sign, then `pi` or `π` among
/// numbers (integers or decimals) that multiply or divide it, written before it (`3*pi/4`,
/// `3pi/4`, `1/3*pi`, `2 π`) or after it (`pi*3/4`, `pi/4*3`). π itself divides nothing and
/// is divided by nothing (`3/pi` is no multiple of it). `None` for anything else.
pub(crate) fn pi_multiple(s: &str) -> Option<trigpoly::Rational> {
    let (negative, rest) = split_sign(s.trim());
    let (at, len) = match rest.find('π') {
        Some(k) => (k, 'π'.len_utf8()),
        None => (rest.find("pi")?, 2),
    };
    let before = rest[..at].trim_end();
    let before = before.strip_suffix('*').unwrap_or(before).trim();
    let before = match before {
        "" => trigpoly::Rational::from(1),
        b => product_of_numbers(b)?,
    };
    let after = rest[at + len..].trim();
    let after = match after {
        "" => trigpoly::Rational::from(1),
        a if a.starts_with(['*', '/']) => product_of_numbers(&format!("1{a}"))?,
        _ => return None,
    };
    let q = &before * &after;
    Some(if negative { -q } else { q })
}

/// The value of numbers multiplied and divided from left to right (`3/4*2` is `3/2`), each
/// an unsigned integer or decimal; `None` for anything else or a division by zero.
fn product_of_numbers(s: &str) -> Option<trigpoly::Rational> {
    let factor = |f: &str| -> Option<trigpoly::Rational> {
        let f = f.trim();
        if !f.starts_with(|c: char| c.is_ascii_digit() || c == '.') {
            return None;
        }
        match decimal_number(f) {
            Some(q) => Some(q),
            None if f.bytes().all(|b| b.is_ascii_digit()) => f.parse().ok(),
            None => None,
        }
    };
    let first = s.find(['*', '/']).unwrap_or(s.len());
    let mut value = factor(&s[..first])?;
    let mut rest = &s[first..];
    while let Some(op) = rest.chars().next() {
        let body = &rest[1..];
        let end = body.find(['*', '/']).unwrap_or(body.len());
        let q = factor(&body[..end])?;
        value = match op {
            '*' => &value * &q,
            _ if q.is_zero() => return None,
            _ => &value / &q,
        };
        rest = &body[end..];
    }
    Some(value)
}

/// The fraction a decimal number writes exactly (`−1.25` is `−5/4`, `2.5e-3` is `1/400`):
/// an optional sign, digits with a decimal point or an exponent (`e` or `E`, at most 4 digits).
/// `None` for anything else, integers without an exponent included (the parser reads those).
pub(crate) fn decimal_number(s: &str) -> Option<trigpoly::Rational> {
    let (negative, s) = split_sign(s);
    let (mantissa, exponent) = match s.split_once(['e', 'E']) {
        Some((m, e)) => {
            let digits = e.strip_prefix(['-', '+']).unwrap_or(e);
            if digits.is_empty() || digits.len() > 4 || !digits.bytes().all(|b| b.is_ascii_digit())
            {
                return None;
            }
            (m, e.parse::<i64>().ok()?)
        }
        None if s.contains('.') => (s, 0),
        None => return None,
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = format!("{whole}{fraction}");
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let scale = exponent - fraction.len() as i64;
    let power = |k: i64| format!("1{}", "0".repeat(k.unsigned_abs() as usize));
    let sign = if negative { "-" } else { "" };
    let text = match scale {
        k if k >= 0 => format!("{sign}{digits}{}", &power(k)[1..]),
        k => format!("{sign}{digits}/{}", power(k)),
    };
    text.parse().ok()
}

/// One `var = value` of a list such as a condition: the variable, its exact value, how it
/// reads, and where the value is written, for later messages.
pub(crate) struct Assignment {
    /// The variable.
    pub var: trigpoly::Var,
    /// Its value.
    pub value: Expr,
    /// `p_θ = 2Iω/3`.
    pub shown: String,
    /// The left side.
    pub lhs: Text,
    /// The right side.
    pub rhs: Text,
    /// Whether the value is `value·π` ([`AssignmentForm::pi`]).
    pub pi_times: bool,
}

/// Reads `var = value` (one per text) of `source`, written in `form`: each left side one
/// declared variable that `admit` does not refuse (it says why it does), set once; each right
/// side an expression of the file.
pub(crate) fn parse_assignments(
    file: &LoadedSystem,
    source: &Source,
    pieces: &[Text],
    form: &AssignmentForm<'_>,
    admit: impl Fn(trigpoly::Var) -> Option<String>,
) -> Result<Vec<Assignment>, FileError> {
    let reader = AssignmentReader {
        file,
        source,
        form,
        scope: file.scope(file.families.len()),
    };
    let mut assignments: Vec<Assignment> = Vec::new();
    for (k, piece) in pieces.iter().enumerate() {
        // A comma with nothing after it (`M = 1,`), or before it (`, M = 1`): the caret goes
        // under the comma.
        if piece.value.trim().is_empty() && pieces.len() > 1 {
            let (comma, side) = match k {
                0 => (piece.separator(true), "before"),
                _ => (piece.separator(false), "after"),
            };
            return Err(source.error(
                ErrorKind::Condition,
                comma,
                format!("{} is missing {side} this comma: {}", form.what, form.usage),
            ));
        }
        let (lhs, rhs) = reader.sides(piece)?;
        let var = reader.variable(&lhs, &admit, &assignments)?;
        let (value, shown, pi_times) = reader.value(var, &rhs)?;
        assignments.push(Assignment {
            var,
            value,
            shown,
            lhs,
            rhs,
            pi_times,
        });
    }
    Ok(assignments)
}

/// The two sides of one `var = value`, `piece`, split at its `=` outside parentheses and
/// braces; else what to underline in `piece` and why it is refused: `usage` where it has no `=`
/// (the whole piece) or more than one (the second), and an empty side (the side), as in a
/// claim. A file's condition and a built-in system's are split alike
/// ([`crate::discovery::parse_condition`]).
pub(crate) fn assignment_sides(
    piece: &str,
    usage: &str,
) -> Result<[Range<usize>; 2], (Range<usize>, String)> {
    let parts = split_top_level(piece, '=');
    let [lhs, rhs] = &parts[..] else {
        let at = match parts.get(2) {
            Some(p) => p.start - 1..p.start,
            None => 0..piece.len(),
        };
        return Err((at, usage.to_string()));
    };
    if let Some(empty) = [lhs, rhs]
        .into_iter()
        .find(|s| piece[(*s).clone()].trim().is_empty())
    {
        return Err((empty.clone(), format!("{usage}; one side is empty")));
    }
    Ok([lhs.clone(), rhs.clone()])
}

/// The refusal of a left side, `typed`, that names no variable `form` may set, `meant` a
/// suggestion or nothing: `the left side of a condition is one declared variable (a
/// coordinate, a momentum or a parameter), found 'q'`; a file's and a built-in system's alike.
/// The kinds named are `form`'s with the Poisson variables where `system` has them.
pub(crate) fn no_variable(
    form: &AssignmentForm<'_>,
    system: &brackets::System,
    typed: &str,
    meant: &str,
) -> String {
    let kinds = match system.space().poisson_variables().is_empty() {
        true => form.kinds,
        false => form.kinds_with_poisson,
    };
    format!(
        "the left side of {} is one declared variable ({kinds}), found {}{meant}",
        form.what,
        trigpoly::quoted_name(typed)
    )
}

/// The refusal of a left side, `typed`, whose variable an earlier one sets already.
pub(crate) fn fixed_twice(typed: &str) -> String {
    format!("{} is fixed twice", trigpoly::quoted_name(typed))
}

/// What to do about a left side [`fixed_twice`], said as its error's hint.
pub(crate) const FIX_ONCE: &str = "keep one of its values: a list of values sets each name once";

/// What reading the `var = value` of a list takes: the file, the source of the texts, how
/// the list reads, and the scope its values are read in.
struct AssignmentReader<'a> {
    file: &'a LoadedSystem,
    source: &'a Source,
    form: &'a AssignmentForm<'a>,
    scope: super::scope::Scope<'a>,
}

impl AssignmentReader<'_> {
    /// The two sides of one `var = value` ([`assignment_sides`]).
    fn sides(&self, piece: &Text) -> Result<(Text, Text), FileError> {
        let [lhs, rhs] = assignment_sides(&piece.value, self.form.usage).map_err(|(at, why)| {
            let span = Span::new(at.start, at.end);
            piece.error(self.source, ErrorKind::Condition, span, why)
        })?;
        Ok((piece.slice(lhs), piece.slice(rhs)))
    }

    /// The variable a left side names: one declared variable, which `admit` does not refuse
    /// and none of `assignments` sets already.
    fn variable(
        &self,
        lhs: &Text,
        admit: impl Fn(trigpoly::Var) -> Option<String>,
        assignments: &[Assignment],
    ) -> Result<trigpoly::Var, FileError> {
        let lhs_tree = self.scope.tree(self.source, lhs)?;
        let var = match &lhs_tree.kind {
            ExprKind::Name(n) => self.file.system.vars().lookup(n),
            _ => None,
        };
        let refuse = |message: String| {
            Err(lhs.error(self.source, ErrorKind::Condition, lhs_tree.span, message))
        };
        let Some(var) = var else {
            // A name one slip from a variable it may set is answered with it, as an unknown
            // name in an expression is (`alfa` for `alpha`).
            let vars = self.file.system.vars();
            let settable: Vec<&str> = vars
                .vars()
                .filter(|&v| admit(v).is_none())
                .map(|v| vars.variable(v).name())
                .collect();
            let meant = match &lhs_tree.kind {
                ExprKind::Name(n) => trigpoly::did_you_mean_hint(n, &settable),
                _ => String::new(),
            };
            let system = &self.file.system;
            return refuse(no_variable(self.form, system, lhs.value.trim(), &meant));
        };
        if let Some(why) = admit(var) {
            return refuse(why);
        }
        if assignments.iter().any(|a| a.var == var) {
            return refuse(fixed_twice(lhs.value.trim())).map_err(|e| e.with_hint(FIX_ONCE));
        }
        Ok(var)
    }

    /// The value a right side gives `var`, how the assignment reads (`p_θ = 2Iω/3`), and
    /// whether the value is a multiple of π written alone ([`Assignment::pi_times`]).
    fn value(&self, var: trigpoly::Var, rhs: &Text) -> Result<(Expr, String, bool), FileError> {
        let vars = self.file.system.vars();
        let name = vars.variable(var).unicode();
        let number = self.number(rhs);
        let pi_times = number.as_ref().is_some_and(|n| n.1);
        let (value, shown) = match number {
            Some((q, _)) => (
                Expr::constant(vars, q.into()),
                format!("{name} = {}", rhs.value.trim()),
            ),
            None => {
                let hint = |e| self.hinted(e);
                let rhs_tree = self.scope.tree(self.source, rhs).map_err(hint)?;
                let value = self
                    .scope
                    .lower(self.source, rhs, &rhs_tree)
                    .map_err(hint)?;
                (value, format!("{name} = {}", self.file.pretty(&rhs_tree)))
            }
        };
        Ok((value, shown, pi_times))
    }

    /// A right side that is a number alone, where the form takes it: a decimal, or `3*pi/4`
    /// when the file has no variable named so (`q` with `pi_times`).
    fn number(&self, rhs: &Text) -> Option<(trigpoly::Rational, bool)> {
        let decimal = self.form.decimals.then(|| decimal_number(rhs.value.trim()));
        let pi_times = || self.takes_pi().then(|| pi_multiple(&rhs.value)).flatten();
        match decimal.flatten() {
            Some(q) => Some((q, false)),
            None => pi_times().map(|q| (q, true)),
        }
    }

    /// Whether a value may be a multiple of π alone: the form takes one, and the file has no
    /// variable named `pi`, which the value would name instead.
    fn takes_pi(&self) -> bool {
        self.form.pi && self.file.system.vars().lookup("pi").is_none()
    }

    /// An error in a right side read as an expression, with the hint that a number the form
    /// takes alone (a decimal, a multiple of π) is not a part of an expression.
    fn hinted(&self, mut e: FileError) -> FileError {
        if self.form.decimals && matches!(e.cause.as_deref(), Some(ParseCause::Decimal)) {
            e.hint = Some(
                "a value alone may be a decimal number (x = 0.5); in an expression, \
                 write fractions (x = 2/3 + 1/2)"
                    .into(),
            );
        }
        if self.takes_pi() && e.unknown_name().is_some_and(|n| n == "pi" || n == "π") {
            e.hint = Some(
                "a value may be a multiple of π alone (theta = 3*pi/4, phi = -pi/2), \
                 not a part of an expression"
                    .into(),
            );
        }
        e
    }
}

impl ClaimSpec {
    /// The claim reported undecided: its check stopped at a limit, whose message is given.
    pub(crate) fn undecided(&self, message: &str) -> ClaimResult {
        ClaimResult::undecided(&self.id, &self.statement, message)
            .written(&self.written)
            .at(self.condition.as_ref().map(Condition::forms))
            .on(self.on.as_ref().map(|l| l.shown.clone()))
            .expecting(self.expect)
    }
}

impl LoadedSystem {
    /// Computes a claim: parses its sides (expanding brackets and families), applies the
    /// condition, and proves or refutes it; timed.
    pub fn check_claim(&self, spec: &ClaimSpec) -> Result<CheckedClaim, FileError> {
        let start = Instant::now();
        let scope = self.scope(self.families.len());
        let at = |e: &EngineError| engine_error(&spec.source, spec.span.clone(), e);
        match &spec.form {
            ClaimForm::Identity { lhs, rhs } => {
                let l_tree = scope.tree(&spec.source, lhs)?;
                let r_tree = scope.tree(&spec.source, rhs)?;
                let recording = scope.recording();
                let l = scope.lower_with(&spec.source, lhs, &l_tree, &recording)?;
                let r = scope.lower_with(&spec.source, rhs, &r_tree, &recording)?;
                let inputs = recording.into_inputs();
                let (proved, residual, undecided, on_level) = match &spec.on {
                    // On a level set: `lhs − rhs` divided by its polynomial, at the values of
                    // the parameters that the condition fixes, if any.
                    Some(level) => {
                        (level
                            .level
                            .check_defined_on(&self.system, &[&l, &r], &inputs))
                        .map_err(|e| at(&e))?;
                        let mut d = l.checked_sub(&r).map_err(|e| at(&e.into()))?;
                        if let Some(c) = &spec.condition {
                            c.defined_on(&[&l, &r], "the claim").map_err(|e| at(&e))?;
                            c.defined_on_inputs(&inputs).map_err(|e| at(&e))?;
                            d = c.apply(&d).map_err(|e| at(&e))?;
                        }
                        let reduced = level.level.reduce(&self.system, &d).map_err(|e| at(&e))?;
                        let mut shown = level.shown.clone();
                        let (proved, residual, undecided) = match reduced {
                            LevelReduction::Vanishes(proof) => {
                                shown.quotient = Some(proof.quotient);
                                (true, None, None)
                            }
                            LevelReduction::Remainder(r) => (false, Some(r), None),
                            // A kind this crate does not know leaves the claim undecided.
                            _ => (false, None, Some(UNKNOWN_OUTCOME.into())),
                        };
                        (proved, residual, undecided, Some(shown))
                    }
                    None => {
                        let mut claim =
                            Claim::new(&spec.id, &spec.statement, l, r).computed_from(inputs);
                        if let Some(c) = &spec.condition {
                            claim = claim.when(c.clone());
                        }
                        let v = claim.check().map_err(|e| at(&e))?;
                        let (proved, residual, undecided) = outcome_parts(v.outcome);
                        (proved, residual, undecided, None)
                    }
                };
                // A claim with no bracket (or braced family instance) has as residual its
                // sides' difference, which the fullest search only restates.
                let reach = match lhs.value.contains('{') || rhs.value.contains('{') {
                    true => Reach::WithSymbolicParameters,
                    false => Reach::AtValues,
                };
                // In the family instances at the indices the claim mentions too.
                let indices = self.mentioned_indices([&l_tree, &r_tree]);
                let residual_in_functions = residual
                    .as_ref()
                    .and_then(|r| self.written_in(r, spec.condition.as_ref(), reach, &indices));
                let (condition, condition_ascii) =
                    spec.condition.as_ref().map(Condition::forms).unzip();
                Ok(CheckedClaim::Identity(Box::new(ClaimResult {
                    id: spec.id.clone(),
                    statement: spec.statement.clone(),
                    written: Some(spec.written.clone()),
                    condition,
                    condition_ascii,
                    kind: ClaimKind::Identity,
                    proved,
                    expect: spec.expect,
                    residual,
                    residual_in_functions,
                    witness: None,
                    note: None,
                    undecided,
                    excerpt: None,
                    on_level,
                    seconds: start.elapsed().as_secs_f64(),
                })))
            }
            ClaimForm::Rank {
                functions,
                expected,
            } => {
                let recording = scope.recording();
                let mut exprs: Vec<Expr> = functions
                    .iter()
                    .map(|(_, t)| scope.parse_into(&spec.source, t, &recording))
                    .collect::<Result<_, _>>()?;
                // The functions restricted to the condition's level set (a condition on
                // parameters alone sets their values), where what they are computed from has
                // a value.
                if let Some(c) = &spec.condition {
                    exprs = exprs
                        .iter()
                        .map(|e| c.apply_where_defined(e, "a function"))
                        .collect::<Result<_, _>>()
                        .map_err(|e| at(&e))?;
                    c.defined_on_inputs(&recording.into_inputs())
                        .map_err(|e| at(&e))?;
                }
                let mut rank = self.rank_result(
                    spec.rank_claim(start),
                    functions.iter().map(|f| f.0.clone()).collect(),
                    &exprs,
                    *expected,
                    spec.condition.as_ref(),
                )?;
                rank.claim.written = Some(spec.written.clone());
                Ok(CheckedClaim::Rank(Box::new(rank)))
            }
        }
    }

    /// The certified rank of functions as a report entry, answering `claim`; `expected` is the
    /// claimed rank. Under a `condition`, `exprs` have it substituted already, and the rank is
    /// that on its level set ([`brackets::rank_restricted`]), shown at the condition.
    pub(crate) fn rank_result(
        &self,
        claim: RankClaim<'_>,
        names: Vec<String>,
        exprs: &[Expr],
        expected: usize,
        condition: Option<&Condition>,
    ) -> Result<RankResult, FileError> {
        let RankClaim {
            source,
            id,
            expect,
            span,
            functions,
            start,
        } = claim;
        if exprs.is_empty() {
            return Err(source.error(ErrorKind::Claim, span, "a rank needs at least one function"));
        }
        let space = self.system.space();
        let cert = match condition {
            Some(c) => rank_restricted(space, exprs, c),
            None => rank(space, exprs),
        };
        let cert = cert.map_err(|e| {
            // An error of one function's derivatives (a limit) is shown at that function; one
            // of them all (no sample point where they are defined) at the whole claim.
            let coordinates = space.coordinates();
            let at = exprs
                .iter()
                .position(|f| coordinates.iter().any(|&c| space.derivative(f, c).is_err()))
                .and_then(|k| functions.get(k).cloned())
                .unwrap_or(span);
            engine_error(source, at, &e)
        })?;
        let mut result = RankResult::new(id, &self.system, names, expected, cert);
        result.claim = result
            .claim
            .at(condition.map(Condition::forms))
            .expecting(expect)
            .timed(start.elapsed().as_secs_f64());
        Ok(result)
    }
}

#[cfg(test)]
mod tests {
    use super::{decimal_number, pi_multiple};

    #[test]
    fn a_multiple_of_pi_alone_is_its_rational() {
        for (written, q) in [
            ("pi", "1"),
            ("π", "1"),
            ("-pi", "-1"),
            ("−π/2", "-1/2"),
            ("3*pi/4", "3/4"),
            ("3pi/4", "3/4"),
            ("2 π", "2"),
            ("0.5*pi", "1/2"),
            ("1/3*pi", "1/3"),
            (" + pi / 6 ", "1/6"),
            ("pi*3/4", "3/4"),
            ("π*3/4", "3/4"),
            ("pi/4*3", "3/4"),
            ("-pi*5/6", "-5/6"),
            ("pi * 2", "2"),
            ("pi*0.25", "1/4"),
            ("2*pi/3/2", "1/3"),
            ("3/4*2*pi", "3/2"),
        ] {
            assert_eq!(
                pi_multiple(written).map(|q| q.to_string()),
                Some(q.to_string()),
                "{written}"
            );
        }
        for other in [
            "x*pi", "2*pi + 1", "pi/0", "pi/x", "pie", "(pi)", "p", "", "3/pi", "pi*", "pi/",
            "pi*-2", "pi2", "2**pi", "pi*pi", "pi*2pi", "1/0*pi", "pi 2", "pi*(3/4)",
        ] {
            assert_eq!(pi_multiple(other), None, "{other}");
        }
    }

    #[test]
    fn a_decimal_number_is_the_fraction_it_writes() {
        for (written, fraction) in [
            ("0.5", "1/2"),
            ("-1.25", "-5/4"),
            ("−0.75", "-3/4"),
            ("+.1", "1/10"),
            ("2.", "2"),
            ("2.5e-3", "1/400"),
            ("1E3", "1000"),
            ("-3e+2", "-300"),
            ("0.000", "0"),
            (
                "123456789012345678901234567890.1",
                "1234567890123456789012345678901/10",
            ),
        ] {
            assert_eq!(
                decimal_number(written).map(|q| q.to_string()),
                Some(fraction.to_string()),
                "{written}"
            );
        }
        // Integers are the parser's; the rest is no decimal number (the exponent's digits
        // are bounded, so that `1e99999` builds no huge number).
        for other in [
            "3", ".", "-", "e5", "1e", "1e+", "1.5.2", "1e99999", "x", "1/2", "0x10", "1_0.5",
            " 1.5",
        ] {
            assert_eq!(decimal_number(other), None, "{other}");
        }
    }
}
