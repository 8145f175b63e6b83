//! `EngineError`: why the engine could not form a bracket, a claim or a certificate.

use thiserror::Error;
use trigpoly::{AlgebraError, BracketError, LimitKind, ParseError};

/// Why the bracket engine has no answer.
///
/// A new reason is a new variant (as [`EngineError::PastLimit`] was), so a program's `match`
/// has an arm for the others, which can say the error's message:
///
/// ```
/// use brackets::{systems, EngineError};
///
/// fn said(e: &EngineError) -> String {
///     match e {
///         EngineError::UnknownName(name) => format!("define {name} first"),
///         e if e.is_limit() => format!("raise the limit: {e}"),
///         other => other.to_string(),
///     }
/// }
/// let rotor = systems::harmonic_rotor();
/// assert_eq!(said(&rotor.get("G3").unwrap_err()), "define G3 first");
/// let unread = rotor.parse("{L, G3}").unwrap_err();
/// assert!(said(&unread).starts_with("line 1, column 5: unknown name 'G3'"));
/// ```
///
/// One that names each variant and nothing else does not compile:
///
/// ```compile_fail,E0004
/// fn said(e: &brackets::EngineError) -> String {
///     use brackets::EngineError::*;
///     match e {
///         Algebra(a) => a.to_string(),
///         Parse { message, .. } => message.clone(),
///         ClosureTooManyTerms { .. } => "the closure's products are too large".into(),
///         PastLimit { message, .. } => message.clone(),
///         UnknownName(name) => format!("define {name} first"),
///         RefusedCondition { message, .. } => message.clone(),
///         Invalid(why) => why.clone(),
///         RefusedKnown { reason, .. } => reason.clone(),
///         Jacobi(violation) => violation.message.clone(),
///     }
/// }
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum EngineError {
    /// An algebraic operation failed (a limit, a division by a non-monomial, ...).
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
    /// An expression did not parse; the message carries line and column and says the parse
    /// error, which is kept in `error` and is not its
    /// [`source`](std::error::Error::source): the message already says it, so that a report
    /// that walks the sources (anyhow's `{:#}`) would say it twice.
    #[error("{}", .message)]
    Parse {
        /// The source text.
        source_text: String,
        /// The rendered message with line, column and caret.
        message: String,
        /// The parse error, which the message says.
        error: ParseError,
    },
    /// The expansions of a closure's products of the generators, up to its degree, whose
    /// terms together pass the term limit ([`Limits::max_terms`](trigpoly::Limits)): they are
    /// held at once, so the limit counts all of them, not one result. Its
    /// [`EngineError::limit`] is the term limit's, which raises it.
    #[error(
        "the products of the generators up to degree {degree} would have more than {limit} \
         term{} together (the term limit)",
        if *limit == 1 { "" } else { "s" }
    )]
    ClosureTooManyTerms {
        /// The closure's degree: the products of the generators up to it are expanded.
        degree: u32,
        /// The limit in force.
        limit: usize,
    },
    /// A limit that the engine keeps itself: more products of integrals than
    /// [`SearchOptions::max_products`](crate::SearchOptions::max_products), counted as each is
    /// formed, and, counted before any is formed, more monomials in the generators than
    /// [`ClosureOptions::max_monomials`](crate::ClosureOptions) or a search space of more
    /// unknowns than the term limit; and a limit of the ring that a caller says with what to
    /// do about it (a closure's report: raise the limit, or lower the degree).
    /// [`EngineError::limit`] says which, `which`; the message says it in words. The engine's
    /// own messages name no setting that raises the limit: the engine knows not who set it (a
    /// program, a file's `[limits]`, the command line), so its caller's hint names the
    /// setting; a closure's report, whose caller is known, says the setting with what to do.
    #[error("{message}")]
    PastLimit {
        /// Which limit.
        which: EngineLimit,
        /// The limit in force.
        limit: usize,
        /// What passed it, in words: `more than 9 products of integrals, the search's limit of
        /// them: search a smaller space, or raise the limit`.
        message: String,
    },
    /// A name that the system does not define.
    #[error("unknown function '{0}'")]
    UnknownName(String),
    /// A condition refused for what it does to one variable: sets it in terms of itself
    /// (`x = y, y = x`) or twice, to a value that is not real (or, for an angle, off the unit
    /// circle), or where a denominator or a radicand involves it.
    #[error("{message}")]
    RefusedCondition {
        /// The variable.
        var: trigpoly::Var,
        /// What is wrong, in words.
        message: String,
    },
    /// A phase space or system that is not well formed, or a request the engine cannot
    /// answer on it: wrong whatever the limits (a limit that stopped the engine is
    /// [`EngineError::PastLimit`], [`EngineError::ClosureTooManyTerms`] or an algebraic one).
    #[error("{0}")]
    Invalid(String),
    /// A known integral given to a search for new ones
    /// ([`SearchOptions::known`](crate::SearchOptions::known)) that the search refuses, before
    /// it searches: one that is not real, or no integral (under the condition, at the fixed
    /// values). Its message names it: `the known integral x is not an integral: {x, H} = p_x
    /// at M = 1, ω = 1, I = 1`.
    #[error("the known integral {name} {reason}")]
    RefusedKnown {
        /// Its place in `SearchOptions::known`, so that a caller that took the list from a
        /// text can show where it stands there.
        index: usize,
        /// Its name, as `SearchOptions::known` gives it.
        name: String,
        /// What is wrong, after its name: `is not an integral: {x, H} = p_x at M = 1`.
        reason: String,
    },
    /// Declared brackets that break the Jacobi identity
    /// `{a, {b, c}} + {b, {c, a}} + {c, {a, b}} = 0` for a triple of phase variables.
    #[error("{}", .0.message)]
    Jacobi(Box<JacobiViolation>),
}

/// Which limit stopped the engine ([`EngineError::limit`]): one of the ring's, as
/// [`AlgebraError::limit`] names it, or one of the search's and the closure's own options, so
/// that a program raises the setting that stopped it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum EngineLimit {
    /// A limit of the variable set's [`Limits`](trigpoly::Limits) (terms, work, degree), or the
    /// machine's memory, as [`LimitKind`] names it: of an algebraic operation, of a text's
    /// reading ([`ParseCause::limit`](trigpoly::ParseCause::limit)), of a closure's products
    /// together ([`EngineError::ClosureTooManyTerms`]: the term limit) or of a search space's
    /// unknowns (the term limit).
    Ring(LimitKind),
    /// [`SearchOptions::max_products`](crate::SearchOptions::max_products): the products of
    /// integrals that a search for new integrals forms.
    SearchProducts,
    /// [`ClosureOptions::max_monomials`](crate::ClosureOptions): the monomials in the
    /// generators (and the symbolic parameters) that a closure counts before it expands any.
    ClosureMonomials,
    /// [`SearchOptions::max_minor`](crate::SearchOptions::max_minor): the rows of a block's
    /// minor whose determinant in the parameter
    /// [`exceptional_values`](crate::search::exceptional_values) computes.
    MinorRows,
}

/// A triple of phase variables for which declared brackets break the Jacobi identity.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct JacobiViolation {
    /// The triple `a, b, c`.
    pub triple: [trigpoly::Var; 3],
    /// `{a, {b, c}} + {b, {c, a}} + {c, {a, b}}`, not zero.
    pub residual: trigpoly::Expr,
    /// The identity and its residual, in words.
    pub message: String,
    /// The place, in the list given to [`PhaseSpace::with_brackets`](crate::PhaseSpace::with_brackets),
    /// of the last bracket that the identity of the triple depends on (one of two of its
    /// variables, or one whose leaving out alone changes the residual; the message names them
    /// all), or, where several identities fail, the last of those that every failing one
    /// compared (up to 17) depends on: where a file shows the violation.
    pub bracket: usize,
}

/// A parse error, so that `?` works on a parse in a function that returns an `EngineError`:
/// one that knows its source ([`ParseError::in_source`], as `Expr::parse`'s do) says where by
/// line, column and caret; one without it by byte offsets (`EngineError::parse` with the
/// source gives line, column and caret).
impl From<ParseError> for EngineError {
    fn from(error: ParseError) -> Self {
        let (start, end) = (error.span.start, error.span.end);
        let message = match error.excerpt() {
            Some(_) => error.to_string(),
            None => format!("{} (at bytes {start}..{end})", error.message()),
        };
        EngineError::Parse {
            source_text: String::new(),
            message,
            error,
        }
    }
}

/// Why a system has no bracket, as a lowering's [`Context`](trigpoly::Context) says it: a
/// refusal of the algebra as itself (so that the parse error it becomes keeps it as its
/// cause, a limit a limit), any other error in its words.
impl From<EngineError> for BracketError {
    fn from(error: EngineError) -> Self {
        match error {
            EngineError::Algebra(e) => BracketError::Algebra(e),
            e => BracketError::Other(e.to_string()),
        }
    }
}

impl EngineError {
    /// Whether a limit stopped the computation (of terms, of term products, of degree, of an
    /// angle's order, of a search's products, of a closure's monomials): the input may be
    /// right, and a larger limit may decide it. It asks [`EngineError::limit`], which says
    /// which limit. The fixed bound on the coefficients of a product or a power
    /// ([`AlgebraError::CoefficientTooLarge`]) and the ranges of a set's settings
    /// ([`AlgebraError::SettingOutOfRange`]) are not limits here: no limit raises them. A text
    /// whose reading a limit stopped ([`System::parse`](crate::System::parse) of
    /// `(x + p_x + 1)^60`, or of `x^5000` past the degree limit) is a parse error stopped at a
    /// limit, as its [`ParseError::cause`] says.
    pub fn is_limit(&self) -> bool {
        self.limit().is_some()
    }

    /// The limit that stopped the computation, if one did ([`EngineError::is_limit`]): one of
    /// the ring's, [`EngineLimit::Ring`] with the [`LimitKind`] of an algebraic refusal
    /// ([`AlgebraError::limit`]), of a text's reading ([`ParseCause::limit`]), of a closure's
    /// products together or a search space's unknowns (both the term limit); or a search's
    /// products ([`EngineLimit::SearchProducts`]), a closure's monomials
    /// ([`EngineLimit::ClosureMonomials`]) or the rows of a minor whose determinant
    /// [`exceptional_values`](crate::search::exceptional_values) computes
    /// ([`EngineLimit::MinorRows`]), each its option's. Every other refusal, the input
    /// wrong whatever the limits, has none.
    ///
    /// ```
    /// use brackets::closure::{closure, ClosureOptions};
    /// use brackets::{systems, EngineError, EngineLimit};
    /// use trigpoly::{AlgebraError, LimitKind};
    ///
    /// let rotor = systems::harmonic_rotor();
    /// // Five generators have 21 monomials of degree ≤ 2, more than one.
    /// let few = ClosureOptions::new(2).max_monomials(1);
    /// let err = closure(&rotor, &["F1", "F2", "L", "G1", "G2"], &few).unwrap_err();
    /// assert_eq!(err.limit(), Some(EngineLimit::ClosureMonomials));
    /// assert!(err.is_limit());
    /// let terms = EngineError::from(AlgebraError::TooManyTerms { limit: 10 });
    /// assert_eq!(terms.limit(), Some(EngineLimit::Ring(LimitKind::Terms)));
    /// // A name the system does not define is wrong under any limit.
    /// let err = closure(&rotor, &["F1", "nope"], &ClosureOptions::new(2)).unwrap_err();
    /// assert_eq!((err.limit(), err.is_limit()), (None, false));
    /// ```
    ///
    /// [`ParseCause::limit`]: trigpoly::ParseCause::limit
    #[must_use]
    pub fn limit(&self) -> Option<EngineLimit> {
        match self {
            EngineError::Algebra(e) => e.limit().map(EngineLimit::Ring),
            EngineError::Parse { error, .. } => error.cause().limit().map(EngineLimit::Ring),
            EngineError::ClosureTooManyTerms { .. } => Some(EngineLimit::Ring(LimitKind::Terms)),
            EngineError::PastLimit { which, .. } => Some(*which),
            _ => None,
        }
    }

    /// A parse error of a text that nobody typed (a built-in system's Hamiltonian or function)
    /// named by the part it is, `what` (`its Hamiltonian`), before the text and its caret: a
    /// line and column would place it in nothing the user sees. Other errors are as they are.
    #[must_use]
    pub fn in_part(self, what: &str) -> Self {
        match self {
            EngineError::Parse {
                source_text, error, ..
            } if !source_text.is_empty() => EngineError::Parse {
                message: error.render_as(&source_text, what),
                source_text,
                // Without its source, so that the parse error kept says no line and column
                // either.
                error: error.without_source(),
            },
            other => other,
        }
    }

    /// A parse error rendered against its source.
    pub fn parse(source: &str, error: ParseError) -> Self {
        EngineError::Parse {
            source_text: source.to_string(),
            message: error.render(source),
            error,
        }
    }
}

#[cfg(test)]
mod tests {
    use std::error::Error as _;

    use super::*;

    /// A parse error is said by the message of the error that wraps it, so it is not also
    /// its source, and is kept whole in the variant (its span and message, for a program to
    /// read): of either construction, and of one named by its part; an algebra error, shown
    /// as itself, wraps none either.
    #[test]
    fn a_parse_error_is_said_by_the_message_not_as_the_source() {
        let error = ParseError::new(trigpoly::Span::new(2, 3), "unknown name 'q'");
        for wrapped in [
            EngineError::parse("x + q", error.clone()),
            error.clone().into(),
            EngineError::parse("x + q", error.clone()).in_part("its Hamiltonian"),
        ] {
            assert!(wrapped.source().is_none(), "{wrapped}");
            assert_eq!(wrapped.to_string().matches("unknown name 'q'").count(), 1);
            let EngineError::Parse { error: kept, .. } = &wrapped else {
                panic!("not a parse error: {wrapped:?}");
            };
            assert_eq!(
                kept, &error,
                "the parse error, its span and message, is kept"
            );
        }
        let algebra = EngineError::from(AlgebraError::DivisionByZero);
        assert!(algebra.source().is_none());
        assert!(EngineError::UnknownName("q".into()).source().is_none());
    }

    /// A limit is one that a larger limit may decide: the term limit is, the fixed bound on a
    /// power's coefficient is not (no setting raises it, and the hint to raise `max_terms` or
    /// `max_degree` that a limit error takes would mislead).
    #[test]
    fn a_limit_is_one_a_larger_limit_may_decide() {
        let terms = EngineError::from(AlgebraError::TooManyTerms { limit: 10 });
        assert!(terms.is_limit());
        let closure = EngineError::ClosureTooManyTerms {
            degree: 4,
            limit: 10,
        };
        assert!(closure.is_limit());
        // Both the term limit, `Limits::max_terms`, which raises them.
        for e in [&terms, &closure] {
            assert_eq!(e.limit(), Some(EngineLimit::Ring(LimitKind::Terms)), "{e}");
        }
        let coefficient = EngineError::from(AlgebraError::CoefficientTooLarge {
            bits: 1 << 25,
            limit: 1 << 24,
        });
        assert!(!coefficient.is_limit());
        assert_eq!(coefficient.limit(), None);
    }

    /// A limit of the engine's own is the one it names, and says its message as it is.
    #[test]
    fn a_limit_of_the_engines_own_is_the_one_it_names() {
        for which in [
            EngineLimit::SearchProducts,
            EngineLimit::ClosureMonomials,
            EngineLimit::MinorRows,
        ] {
            let e = EngineError::PastLimit {
                which,
                limit: 9,
                message: "more than 9".into(),
            };
            assert_eq!((e.limit(), e.is_limit()), (Some(which), true));
            assert_eq!(e.to_string(), "more than 9");
            assert!(e.source().is_none());
        }
        assert_eq!(EngineError::Invalid("no angle".into()).limit(), None);
    }

    /// A text that a limit stopped while it was read is stopped at a limit too: a program
    /// that asks `System::parse` for `(x + p_x + k + 1)^6` under a term limit of 30, or for
    /// `x^5000` under the degree limit, is told so by `is_limit`, as it is for the same
    /// power formed by `checked_pow`; a text that does not read, or names nothing, is not.
    #[test]
    fn a_parse_stopped_at_a_limit_is_a_limit() {
        use crate::{PhaseSpace, System};
        use trigpoly::{Expr, Limits, Vars};

        let vars = Vars::builder()
            .coordinate("x")
            .momentum("p_x")
            .parameter("k")
            .limits(Limits::default().max_terms(30))
            .build()
            .unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
        let h = Expr::parse(&vars, "p_x^2/2 + k*x^2/2").unwrap();
        let system = System::new("small", space, h).unwrap();
        let sum = system.parse("x + p_x + k + 1").unwrap();
        assert!(EngineError::from(sum.checked_pow(6).unwrap_err()).is_limit());
        for (past_a_limit, kind) in [
            ("(x + p_x + k + 1)^6", LimitKind::Terms),
            ("x^5000", LimitKind::Degree(5000)),
            ("p_x^1000000000", LimitKind::Degree(1_000_000_000)),
        ] {
            let err = system.parse(past_a_limit).unwrap_err();
            assert!(matches!(err, EngineError::Parse { .. }), "{err:?}");
            assert!(err.is_limit(), "{past_a_limit}: {err}");
            assert_eq!(err.limit(), Some(EngineLimit::Ring(kind)), "{past_a_limit}");
        }
        for no_limit in ["x + q", "x + (", "x/(1 + x)"] {
            let err = system.parse(no_limit).unwrap_err();
            assert!(!err.is_limit(), "{no_limit}: {err}");
            assert_eq!(err.limit(), None, "{no_limit}");
        }
    }
}
