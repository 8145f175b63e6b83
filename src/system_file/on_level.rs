//! A claim made on a level set, `on = "EXPR = VALUE"` in a `[[claim]]`: read and checked when
//! the file is loaded, each refusal placed in the `on` text ([`read_level_set`]); the claim is
//! decided later by dividing its `lhs − rhs` by `P = EXPR − VALUE`
//! ([`brackets::search::LevelSet::reduce`]), as `search --on` proves its integrals.

use brackets::search::{BesideLevelSet, LevelSet};
use brackets::Condition;
use trigpoly::syntax::Expr as Tree;
use trigpoly::{DivisionRefusal, Span};

use super::claims::ClaimForm;
use super::error::{ErrorKind, FileError};
use super::text::{split_top_level, Source, Text};
use super::LoadedSystem;
use crate::report::OnLevelSet;

/// A claim's level set as read: what the engine divides by, and how the report shows it.
#[derive(Clone, Debug)]
pub struct ClaimLevelSet {
    /// `EXPR = VALUE`, checked ([`LevelSet::check`]).
    pub level: LevelSet,
    /// As the report shows it, with no quotient yet.
    pub shown: OnLevelSet,
}

/// How a level set reads, for the refusals of its text.
const USAGE: &str = "a level set reads `EXPR = VALUE`, such as \"A = 0\" or \
                     \"M1*gamma1 + M2*gamma2 + M3*gamma3 = 0\"";

/// Reads the level set `text` of a claim of the given `form`, whose sides are `sides` (none
/// for a rank), under its `condition` if it has one: a condition that fixes parameters alone
/// is taken, and the level set is then that at their values ([`LevelSet::at_values`]). Each
/// refusal is placed in `text`: a rank claim (the whole text), what
/// [`BesideLevelSet::for_claim`] refuses, a condition that sets a phase variable (the whole
/// text, before the text is read), no `=`
/// (the whole text) or a second one (it), an empty side (the `=`), a divisor the condition
/// sets to 0 (the whole text), a value that is no constant (the value), and what
/// [`LevelSet::check`] refuses, a parameter in the leading coefficient and a variable shared
/// with a denominator, a radicand or a negative power of `H` among it (the expression).
pub(crate) fn read_level_set(
    file: &LoadedSystem,
    source: &Source,
    text: &Text,
    form: &ClaimForm,
    condition: Option<&Condition>,
    sides: Option<(&Tree, &Tree)>,
) -> Result<ClaimLevelSet, FileError> {
    let whole = text.trimmed_span();
    let refuse =
        |t: &Text, span: Span, why: String| t.error(source, ErrorKind::Condition, span, why);
    let (ClaimForm::Identity { .. }, Some(sides)) = (form, sides) else {
        return Err(refuse(
            text,
            whole,
            "`on` takes an identity `lhs = rhs`, not a rank: the rank on a level set is taken \
             where `when` parametrises it (when = \"M3 = -(M1*gamma1 + M2*gamma2)/gamma3\")"
                .into(),
        ));
    };
    // What the level set is not taken beside, before its text is read.
    let system = &file.system;
    if let Some(refused) = BesideLevelSet::for_claim(condition) {
        return Err(refuse(
            text,
            whole,
            format!("a claim on a level set does not take {refused}"),
        ));
    }
    let parts = split_top_level(&text.value, '=');
    if parts.len() == 1 {
        return Err(refuse(
            text,
            whole,
            format!("{USAGE}; there is no '=' here"),
        ));
    }
    if parts.len() > 2 {
        let at = parts[2].start - 1;
        return Err(refuse(
            text,
            Span::new(at, at + 1),
            format!("{USAGE}, with one '=': a level set is one equation"),
        ));
    }
    let (lhs, rhs) = (text.slice(parts[0].clone()), text.slice(parts[1].clone()));
    for (side, what) in [
        (&lhs, "no expression before '='"),
        (&rhs, "no value after '='"),
    ] {
        if side.value.trim().is_empty() {
            let at = parts[0].end;
            return Err(refuse(
                text,
                Span::new(at, at + 1),
                format!("{USAGE}; {what}"),
            ));
        }
    }
    let scope = file.scope(file.families.len());
    let (lhs_tree, rhs_tree) = (scope.tree(source, &lhs)?, scope.tree(source, &rhs)?);
    let expr = scope.lower(source, &lhs, &lhs_tree)?;
    let value = scope.lower(source, &rhs, &rhs_tree)?;
    // Under a condition that fixes parameters, the level set at their values.
    let level = LevelSet::new(text.value.trim(), expr, value);
    let level = match condition {
        Some(c) => level
            .at_values(system, c)
            .map_err(|e| refuse(text, whole, e.to_string()))?,
        None => level,
    };
    let at_value = |e: brackets::EngineError| refuse(&rhs, rhs.trimmed_span(), e.to_string());
    level.check_value(system).map_err(at_value)?;
    // P is then not as written: a refusal of it says at which values it was taken.
    let at_expr = |why: String| {
        let why = match condition {
            Some(c) => format!("{why}; here P is taken at {c}, which the claim's `when` fixes"),
            None => why,
        };
        refuse(&lhs, lhs.trimmed_span(), why)
    };
    level
        .check_form(system, "`on`", false)
        .map_err(|e| at_expr(e.to_string()))?;
    let p = level.polynomial().map_err(|e| at_expr(e.to_string()))?;
    // A claim holds for every value of the parameters its condition leaves free: none may be
    // fixed to divide by.
    if let Err(DivisionRefusal::LeadingCoefficient { .. }) =
        p.leading_term(&LevelSet::order(system))
    {
        return Err(at_expr(format!(
            "the level set's polynomial P = {p} has a parameter in the coefficient of its \
             leading monomial (in the graded lexicographic order of the phase variables, as \
             declared): a claim holds for every value of the parameters, and P is divided by \
             that coefficient; write the level set with a number there (divide EXPR and VALUE \
             by the parameter)"
        )));
    }
    level
        .check_for_every_value(system, condition)
        .map_err(|e| at_expr(e.to_string()))?;
    let (lhs_shown, rhs_shown) = (file.pretty(sides.0), file.pretty(sides.1));
    let difference = match rhs_shown.as_str() {
        "0" => lhs_shown,
        r if r.contains(' ') => format!("{lhs_shown} − ({r})"),
        r => format!("{lhs_shown} − {r}"),
    };
    let shown = OnLevelSet::new(
        &format!("{} = {}", file.pretty(&lhs_tree), file.pretty(&rhs_tree)),
        text.value.trim(),
        p,
        &difference,
    );
    Ok(ClaimLevelSet { level, shown })
}
