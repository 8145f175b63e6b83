//! `AlgebraError`: every way an algebraic operation can refuse, as data.

use thiserror::Error;

use crate::print::Angles;
use crate::varset::{long_name, BadName, VarKind, FIELD_BITS, MAX_RADICALS};

/// Why an operation on polynomials has no result.
///
/// New ways to refuse come as new variants, so a `match` on it needs a `_` arm.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum AlgebraError {
    /// Division by zero.
    #[error("division by zero")]
    DivisionByZero,
    /// Division by a polynomial that is neither a single term nor a product of powers of
    /// declared denominators: the divisor as shown, and the declaration that would make the
    /// division exact.
    #[error("cannot divide by {shown}: only division by a nonzero constant, a single term (monomial) or a product of powers of declared denominators is exact here; {declare}")]
    NotAMonomial {
        /// The divisor as shown (a long one by its size).
        shown: String,
        /// What to declare: `declare it (or its factors) as a denominator: denominators =
        /// ["x + 1"] in [phase_space]`, without the text of a long divisor.
        declare: String,
    },
    /// Division by a sum with radicals in it whose norm, its product with its conjugates, is
    /// not invertible: the divisor and its norm (up to sign) as shown, and the declaration
    /// that would make the norm invertible.
    #[error("cannot divide by {shown}: a divisor with radicals is divided through its conjugates (1/(A + B·r) = (A − B·r)/(A² − B²·R) for r = √R), which leaves a division by its norm, ±({norm}), and that is not a nonzero constant, a single term or a product of powers of declared denominators and radicands; {declare}")]
    NormNotInvertible {
        /// The divisor as shown.
        shown: String,
        /// Its norm as shown, with a positive leading coefficient.
        norm: String,
        /// What to declare for the norm, as [`AlgebraError::NotAMonomial`] says it.
        declare: String,
    },
    /// Division by a function of an angle that is not a single `e^{ikθ}` (it prints as one
    /// term, `cos²φ`, but is a sum of exponentials).
    #[error("cannot divide by {0}: cos and sin of an angle are sums of exponentials, which are not invertible here; only division by a nonzero constant, a single term in the other variables, or exp(i*k*angle) is exact")]
    NotAMonomialInAngles(String),
    /// A negative power of a polynomial that is neither a single term nor a product of powers
    /// of declared denominators: the base as shown, and the declaration that would make it
    /// invertible (as [`AlgebraError::NotAMonomial`] says it).
    #[error("cannot raise {shown} to a negative power: only single terms (monomials) and products of powers of declared denominators are invertible; {declare}")]
    NegativePower {
        /// The base as shown.
        shown: String,
        /// What to declare.
        declare: String,
    },
    /// An exponent beyond the limit.
    #[error("the exponent of {var} would reach {exponent}, past the limit of {limit}")]
    ExponentTooLarge {
        /// The variable.
        var: String,
        /// The exponent that would result.
        exponent: i64,
        /// The limit in force.
        limit: u32,
    },
    /// A trigonometric order beyond the degree limit: a term in `cos kθ`, `sin kθ` with `|k|`
    /// past it (the exponent of `e^{iθ}`, as an angle is stored, said in the user's terms).
    #[error(
        "the trigonometric order in {angle} would reach {order} (terms in cos {order}{angle}, \
         sin {order}{angle}), past the limit of {limit}"
    )]
    OrderTooLarge {
        /// The angle.
        angle: String,
        /// The order that would result.
        order: u64,
        /// The limit in force.
        limit: u32,
    },
    /// A result with more terms than the limit allows.
    #[error("{}; {ADVICE_SIMPLIFY}", too_many_terms(*.limit))]
    TooManyTerms {
        /// The limit in force.
        limit: usize,
    },
    /// A result whose terms, as many as the term limit allows, would need more memory than the
    /// allocator gives (a power `(r + p_r + p_φ + M + k + 1)^300` of 21 281 794 436 terms under
    /// `--max-terms 10^12`, which reserved room for all of them and aborted the process): room
    /// reserved for a predicted count of terms is refused with this, not an abort. The term
    /// limit let it through; no larger limit reaches it ([`LimitKind::Memory`]).
    #[error("{}; {ADVICE_LOWER}", too_large_for_memory(*.terms, *.bytes))]
    TooLargeForMemory {
        /// The terms the result would have.
        terms: u128,
        /// The bytes they would need, about.
        bytes: u128,
    },
    /// An element that could print more terms than the limit allows, its angles in the form
    /// printed (each `e^{ikθ}` prints as up to 2 of them in harmonics, `|k| + 1` in powers).
    #[error("{}; raise the limit or print less of it", too_many_printed(*.terms, *.limit, *.angles))]
    TooManyPrintedTerms {
        /// The bound on the printed terms.
        terms: u64,
        /// The limit in force.
        limit: usize,
        /// The form of the angles the terms are counted in.
        angles: Angles,
    },
    /// A product that would form more term products than the work limit allows.
    #[error("{}; {ADVICE_SIMPLIFY}", too_much_work(*.left, *.right, *.products, *.limit))]
    TooMuchWork {
        /// The terms of the two factors.
        left: usize,
        /// The terms of the other factor.
        right: usize,
        /// The term products it would form.
        products: u128,
        /// The limit in force.
        limit: u64,
    },
    /// A sum of products, such as a Poisson bracket's `Σ ∂f/∂q·∂g/∂p − ∂f/∂p·∂g/∂q`, whose
    /// products would form more term products together than the work limit allows, though
    /// each passes it alone.
    #[error("{}; {ADVICE_SIMPLIFY}", too_much_summed_work(*.products, *.largest, *.total, *.limit))]
    TooMuchSummedWork {
        /// The products of the sum that were counted (those without a factor short enough to
        /// be shifted copies).
        products: usize,
        /// The terms of the two factors of the largest of them.
        largest: (usize, usize),
        /// The term products they would form together.
        total: u128,
        /// The limit in force.
        limit: u64,
    },
    /// An operation that needs `i` in a polynomial over Q.
    #[error("{0} needs Gaussian rational coefficients Q(i), but this polynomial is over Q")]
    NeedsGaussian(String),
    /// Polynomials from different variable sets were combined, or a variable handle was used
    /// with a set that does not declare it ([`VarSet::owns`](crate::VarSet::owns)).
    #[error("the polynomials (or variables) belong to different variable sets")]
    VarSetMismatch,
    /// A value missing in an evaluation.
    #[error("no value given for {0}")]
    MissingValue(String),
    /// A point that is not on the unit circle given for an angle.
    #[error("the value of {0} must be a point (cos, sin) on the unit circle with cos² + sin² = 1")]
    NotOnUnitCircle(String),
    /// A variable declared twice, or under two names that one spelling finds (`omega`, `ω`).
    #[error("variable {name:?} is declared twice{}", declared_twice_how(.name, .first))]
    DeclaredTwice {
        /// The second declaration's name.
        name: String,
        /// The first's.
        first: String,
    },
    /// Two variables whose names read apart in text and alike in LaTeX (`x1` and `x₁`, both
    /// `x_{1}`), or whose LaTeX reads back as one name (`o` and `omicron`'s `\mathit{o}`).
    #[error("{first:?} and {name:?} would print alike in LaTeX, as {latex}: rename one")]
    PrintedAlike {
        /// The second declaration's name.
        name: String,
        /// The first's.
        first: String,
        /// The LaTeX both would print as.
        latex: String,
    },
    /// A name that cannot name a variable ([`BadName`]): malformed, too long, with an empty
    /// subscript, with a letter LaTeX cannot write, or reserved. A name too long is shown by
    /// its start and its length.
    #[error("{}", invalid_name(.name, *.reason))]
    InvalidName {
        /// The name, whole.
        name: String,
        /// Why it cannot name a variable.
        reason: BadName,
    },
    /// A setting of a variable set, or a count of its declarations, out of the range that is
    /// supported: a degree limit of 0, exponent bits not in [`FIELD_BITS`], more than
    /// 65 535 variables or more than 8 radicals. No limit of [`Limits`](crate::Limits) raises
    /// these.
    #[error("{}", setting_out_of_range(*.setting, *.value))]
    SettingOutOfRange {
        /// The setting or count.
        setting: Setting,
        /// Its value, which is out of range.
        value: u64,
    },
    /// A declared radical refused ([`Poly::radicals`](crate::Poly::radicals),
    /// [`Poly::check_radicals`](crate::Poly::check_radicals)): its radicand does not read, is
    /// a constant, not real or nowhere positive, has a radical, a denominator or an angle in
    /// it, or is a square (alone, or times the radicands of others), so that the radical is no
    /// new function of the variables.
    #[error("{message}")]
    RadicalRefused {
        /// The radicals refused, as shown (`r`): one, or those whose product of radicands is
        /// a square.
        radicals: Vec<String>,
        /// What is wrong, in words, naming them.
        message: String,
    },
    /// A declared denominator refused
    /// ([`Poly::denominator_atoms`](crate::Poly::denominator_atoms)): its definition does not
    /// read, is zero or a single term, has a denominator of several terms or a radical in it,
    /// or divides by a sum.
    #[error("{message}")]
    DenominatorRefused {
        /// The denominator as declared, its name (`(x + 1)`).
        denominator: String,
        /// What is wrong, in words.
        message: String,
    },
    /// A division by an element with radicals in it that is zero once they are reduced by
    /// `r² = R` (`1/(r² − x² − y²)` for `r = √(x² + y²)`).
    #[error("division by zero: {shown} is 0, as {definition}")]
    DivisorVanishes {
        /// The divisor as shown.
        shown: String,
        /// The radical by whose definition it vanishes, as `r = √(x² + y²)`.
        definition: String,
    },
    /// A variable given where an angle must be that is not declared as one.
    #[error("{}", not_an_angle(*.needed_by, .var, *.kind))]
    NotAnAngle {
        /// What needs the angle.
        needed_by: AngleUse,
        /// The variable as shown.
        var: String,
        /// What it is declared as.
        kind: VarKind,
    },
    /// A substitution `var ↦ value` into an element in which `var` has a negative power, of a
    /// value that is not invertible: neither a single term nor a product of powers of
    /// declared denominators.
    #[error(
        "cannot substitute {shown} for {var}: it appears with exponent {exponent}, and only \
         single terms (monomials) and products of powers of declared denominators are \
         invertible; {declare}"
    )]
    UninvertibleSubstitution {
        /// The value as shown.
        shown: String,
        /// The variable substituted for, as shown.
        var: String,
        /// The negative exponent of the variable that the value would take.
        exponent: i64,
        /// What to declare, as [`AlgebraError::NotAMonomial`] says it.
        declare: String,
    },
    /// A product, a power, a bracket or a sum of products whose coefficients would pass the
    /// fixed bound on their size (the numerator or denominator of `(3/2)^(2^30)`;
    /// `(c x + y)^100` or `F*F*F` of a `c`, an `F`, of a million bits; `{A, B}` of single terms
    /// whose contents multiplied pass it, which the bracket's fused kernels form themselves).
    /// The message names the bracket beside the product and the power (a sum of products is
    /// products), where it said "this product or power" of a bracket too. The bound is no
    /// setting of [`Limits`](crate::Limits), so no larger limit decides it: unlike
    /// [`AlgebraError::TooManyTerms`] and the other limits it is not "a limit stopped the
    /// computation".
    #[error(
        "a coefficient formed by a product, a power or a bracket would have more than {limit} bits"
    )]
    CoefficientTooLarge {
        /// A bound on the bits of the result's coefficients: for a power, the base's times the
        /// exponent's size; for a product, the factors' added.
        bits: u64,
        /// The bound in force.
        limit: u64,
    },
    /// Arguments that do not fit together: a mistake of the calling program, not of the
    /// expressions it works on.
    #[error("{0}")]
    Misuse(Misuse),
}

impl AlgebraError {
    /// The limit this error passed, if a limit stopped the computation: the input may be
    /// right, and a larger limit may decide it. The fixed bound on the coefficients
    /// ([`AlgebraError::CoefficientTooLarge`]) and the ranges of a set's settings
    /// ([`AlgebraError::SettingOutOfRange`]) are no limits here: no limit raises them.
    ///
    /// ```
    /// use trigpoly::{AlgebraError, LimitKind};
    ///
    /// assert_eq!(AlgebraError::TooManyTerms { limit: 10 }.limit(), Some(LimitKind::Terms));
    /// let e = AlgebraError::ExponentTooLarge { var: "x".into(), exponent: -5000, limit: 1000 };
    /// assert_eq!(e.limit(), Some(LimitKind::Degree(5000)));
    /// assert_eq!(AlgebraError::DivisionByZero.limit(), None);
    /// ```
    #[must_use]
    pub fn limit(&self) -> Option<LimitKind> {
        match self {
            AlgebraError::TooManyTerms { .. } | AlgebraError::TooManyPrintedTerms { .. } => {
                Some(LimitKind::Terms)
            }
            AlgebraError::TooLargeForMemory { .. } => Some(LimitKind::Memory),
            AlgebraError::TooMuchWork { .. } | AlgebraError::TooMuchSummedWork { .. } => {
                Some(LimitKind::Work)
            }
            AlgebraError::ExponentTooLarge { exponent, .. } => {
                Some(LimitKind::Degree(exponent.unsigned_abs()))
            }
            AlgebraError::OrderTooLarge { order, .. } => Some(LimitKind::Degree(*order)),
            _ => None,
        }
    }

    /// The setting in force that this error passed, as a count: the term limit, the work
    /// limit (term products) or the degree limit; `None` where no setting bounds it (the
    /// machine's memory) or no limit stopped the computation.
    ///
    /// ```
    /// use trigpoly::AlgebraError;
    ///
    /// assert_eq!(AlgebraError::TooManyTerms { limit: 10 }.limit_in_force(), Some(10));
    /// let e = AlgebraError::ExponentTooLarge { var: "x".into(), exponent: -5000, limit: 1000 };
    /// assert_eq!(e.limit_in_force(), Some(1000));
    /// assert_eq!(AlgebraError::DivisionByZero.limit_in_force(), None);
    /// ```
    #[must_use]
    pub fn limit_in_force(&self) -> Option<u64> {
        let wide = |n: usize| u64::try_from(n).unwrap_or(u64::MAX);
        match *self {
            AlgebraError::TooManyTerms { limit }
            | AlgebraError::TooManyPrintedTerms { limit, .. } => Some(wide(limit)),
            AlgebraError::TooMuchWork { limit, .. }
            | AlgebraError::TooMuchSummedWork { limit, .. } => Some(limit),
            AlgebraError::ExponentTooLarge { limit, .. }
            | AlgebraError::OrderTooLarge { limit, .. } => Some(u64::from(limit)),
            _ => None,
        }
    }

    /// The message without the advice a limit's ends with (`; raise the limit or simplify
    /// the input`): what happened, for a caller that gives advice of its own (a command
    /// line's options). The messages of the term limit, of its printing, of the work limit and
    /// of a result too large for memory end with advice; every other message is the whole
    /// message.
    ///
    /// ```
    /// use trigpoly::AlgebraError;
    ///
    /// let e = AlgebraError::TooManyTerms { limit: 10 };
    /// assert_eq!(e.without_advice(), "the result would have more than 10 terms (the term limit)");
    /// assert_eq!(format!("{e}"), format!("{}; raise the limit or simplify the input", e.without_advice()));
    /// assert_eq!(AlgebraError::DivisionByZero.without_advice(), "division by zero");
    /// ```
    #[must_use]
    pub fn without_advice(&self) -> String {
        match self {
            AlgebraError::TooManyTerms { limit } => too_many_terms(*limit),
            AlgebraError::TooManyPrintedTerms {
                terms,
                limit,
                angles,
            } => too_many_printed(*terms, *limit, *angles),
            AlgebraError::TooLargeForMemory { terms, bytes } => {
                too_large_for_memory(*terms, *bytes)
            }
            AlgebraError::TooMuchWork {
                left,
                right,
                products,
                limit,
            } => too_much_work(*left, *right, *products, *limit),
            AlgebraError::TooMuchSummedWork {
                products,
                largest,
                total,
                limit,
            } => too_much_summed_work(*products, *largest, *total, *limit),
            e => e.to_string(),
        }
    }
}

/// Which limit an [`AlgebraError`] passed ([`AlgebraError::limit`]): the kinds a caller tells
/// apart to say which setting raises it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum LimitKind {
    /// The term limit ([`Limits::max_terms`](crate::Limits)), of a result or of its printing.
    Terms,
    /// The work limit ([`Limits::max_term_products`](crate::Limits)), of a product's term
    /// products, or of a sum's products together.
    Work,
    /// The degree limit ([`Limits::max_degree`](crate::Limits)), which an exponent or an
    /// angle's order would pass: its size `|n|`.
    Degree(u64),
    /// The machine's memory, which a result the term limit let through would pass: no larger
    /// limit reaches it.
    Memory,
}

/// The advice of the term and work limits' messages.
const ADVICE_SIMPLIFY: &str = "raise the limit or simplify the input";

/// The advice of [`AlgebraError::TooLargeForMemory`]'s message.
const ADVICE_LOWER: &str = "simplify the input or lower the term limit";

/// What [`AlgebraError::TooLargeForMemory`] says, without its advice: the bytes in the
/// largest binary unit that leaves at least one whole.
fn too_large_for_memory(terms: u128, bytes: u128) -> String {
    const UNITS: [&str; 7] = ["bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"];
    let mut unit = 0;
    while unit + 1 < UNITS.len() && bytes >> (10 * (unit + 1)) > 0 {
        unit += 1;
    }
    // In tenths of the unit, rounded, in whole numbers.
    let size = match unit {
        0 => format!("{bytes} bytes"),
        _ => {
            let scale = 1u128 << (10 * unit);
            let tenths = (bytes.saturating_mul(10) + scale / 2) / scale;
            format!("{}.{} {}", tenths / 10, tenths % 10, UNITS[unit])
        }
    };
    format!(
        "the result would have {terms} terms, about {size} of memory, more than this machine \
         can hold"
    )
}

/// What [`AlgebraError::TooManyTerms`] says, without its advice.
fn too_many_terms(limit: usize) -> String {
    let s = if limit == 1 { "" } else { "s" };
    format!("the result would have more than {limit} term{s} (the term limit)")
}

/// What [`AlgebraError::TooManyPrintedTerms`] says, without its advice.
fn too_many_printed(terms: u64, limit: usize, angles: Angles) -> String {
    let (form, each) = match angles {
        Angles::Harmonics => ("in multiple angles", "2, cos kθ and sin kθ"),
        Angles::Powers => ("in powers of cos and sin", "k + 1"),
    };
    format!(
        "printed {form}, the result could have up to {terms} terms (e^(ikθ) takes up to \
         {each}), past the limit of {limit} (the term limit)"
    )
}

/// What [`AlgebraError::TooMuchWork`] says, without its advice.
fn too_much_work(left: usize, right: usize, products: u128, limit: u64) -> String {
    format!(
        "the product of {left} terms by {right} would form {products} term products, past the \
         limit of {limit} (the work limit)"
    )
}

/// What [`AlgebraError::TooMuchSummedWork`] says, without its advice.
fn too_much_summed_work(
    products: usize,
    largest: (usize, usize),
    total: u128,
    limit: u64,
) -> String {
    let (left, right) = largest;
    format!(
        "a sum of {products} products (as a bracket is) would form {total} term products in \
         all (the largest, {left} terms by {right}), past the limit of {limit} (the work limit)"
    )
}

/// A setting of a variable set, or a count of its declarations, that has a range
/// ([`AlgebraError::SettingOutOfRange`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Setting {
    /// The degree limit, [`Limits::max_degree`](crate::Limits::max_degree): at least 1.
    MaxDegree,
    /// The bits per exponent of
    /// [`VarsBuilder::exponent_bits`](crate::VarsBuilder::exponent_bits): one of
    /// [`FIELD_BITS`].
    ExponentBits,
    /// The number of variables: at most 65 535.
    Variables,
    /// The number of radicals declared: at most 8 (their independence is checked on each of
    /// the `2^n − 1` products of them).
    Radicals,
}

/// What needs an angle ([`AlgebraError::NotAnAngle`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum AngleUse {
    /// `e^{inθ}`, [`Poly::exp_i`](crate::Poly::exp_i), and through it `cos θ` and `sin θ`.
    ExpI,
    /// The value of an angle at a point, [`Point::with_angle`](crate::Point::with_angle).
    PointWithAngle,
}

/// How a call's arguments do not fit together ([`AlgebraError::Misuse`]).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum Misuse {
    /// A monomial given by its exponents, with not one exponent per variable
    /// ([`MonomialIndex`](crate::MonomialIndex)).
    #[error("{exponents} exponents for {variables} variables")]
    ExponentCount {
        /// The exponents given.
        exponents: usize,
        /// The variables of the set.
        variables: usize,
    },
    /// A bracket with a kept gradient, with not one pair of derivatives per canonical pair.
    #[error("{pairs} pairs of variables but {derivatives} pairs of derivatives")]
    GradientCount {
        /// The canonical pairs given.
        pairs: usize,
        /// The pairs of derivatives given.
        derivatives: usize,
    },
    /// A sum of products of no products, which has no variable set to be zero in.
    #[error("an empty sum of products has no variable set")]
    EmptySum,
    /// A power `r^M` of a radical given to
    /// [`Poly::reduce_radicals`](crate::Poly::reduce_radicals) that leaves a negative power of
    /// `r` in the element: less than [`Poly::radical_powers`](crate::Poly::radical_powers)
    /// gives.
    #[error("r^{multiplier} does not clear the power {power} of the radical {radical}")]
    RadicalPower {
        /// The radical as shown.
        radical: String,
        /// The power `M` of the radical given.
        multiplier: i64,
        /// A power of the radical in the element that `M` does not clear.
        power: i64,
    },
}

/// How a refused name reads: `"2Q" cannot name a variable: …`, a long one by its start and
/// length.
fn invalid_name(name: &str, reason: BadName) -> String {
    let shown = match (reason, long_name(name)) {
        (BadName::TooLong, Some((start, n))) => format!("{start:?}…, {n} characters long,"),
        _ => format!("{name:?}"),
    };
    format!("{shown} cannot name a variable: {reason}")
}

/// How a setting out of range reads.
fn setting_out_of_range(setting: Setting, value: u64) -> String {
    match setting {
        Setting::MaxDegree => "the degree limit (max_degree) must be at least 1: at 0 no \
                               variable could be written, not even x itself"
            .into(),
        Setting::ExponentBits => {
            format!("exponent bits must be one of {FIELD_BITS:?}, not {value}")
        }
        Setting::Variables => "too many variables".into(),
        Setting::Radicals => {
            format!("{value} radicals are declared; at most {MAX_RADICALS} are supported")
        }
    }
}

/// How a variable that is not an angle reads where one is needed.
fn not_an_angle(needed_by: AngleUse, var: &str, kind: VarKind) -> String {
    match needed_by {
        AngleUse::ExpI => format!("e^{{inθ}} needs an angle, and {var} is not declared as one"),
        AngleUse::PointWithAngle => format!(
            "Point::with_angle sets an angle, and {var} is {}",
            kind.described()
        ),
    }
}

/// How a second declaration meets the first, when the names differ.
fn declared_twice_how(name: &str, first: &str) -> String {
    if name == first {
        String::new()
    } else {
        format!(" (as {first:?}, which one spelling finds with it)")
    }
}
