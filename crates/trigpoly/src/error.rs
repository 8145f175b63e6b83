//! `AlgebraError`: every way an algebraic operation can refuse, as data.

use thiserror::Error;

/// Why an operation on polynomials has no result.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
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
    #[error(
        "the result would have more than {limit} term{} (the term limit); raise the limit or \
         simplify the input",
        if *limit == 1 { "" } else { "s" }
    )]
    TooManyTerms {
        /// The limit in force.
        limit: usize,
    },
    /// An element whose normal form in `cos θ, sin θ` could print more terms than the limit
    /// allows (each `e^{ikθ}` prints as up to `|k| + 1` of them).
    #[error(
        "printed in cos and sin, the result could have up to {terms} terms (e^(ikθ) takes up \
         to k + 1), past the limit of {limit} (the term limit); raise the limit or print less \
         of it"
    )]
    TooManyPrintedTerms {
        /// The bound on the printed terms.
        terms: u64,
        /// The limit in force.
        limit: usize,
    },
    /// A product that would form more term products than the work limit allows.
    #[error(
        "the product of {left} terms by {right} would form {products} term products, past the \
         limit of {limit} (the work limit); raise the limit or simplify the input"
    )]
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
    /// `x_{1}`).
    #[error("{first:?} and {name:?} would print alike in LaTeX, as {latex}: rename one")]
    PrintedAlike {
        /// The second declaration's name.
        name: String,
        /// The first's.
        first: String,
        /// The LaTeX both would print as.
        latex: String,
    },
    /// Something else invalid, with its explanation.
    #[error("{0}")]
    Invalid(String),
}

/// How a second declaration meets the first, when the names differ.
fn declared_twice_how(name: &str, first: &str) -> String {
    if name == first {
        String::new()
    } else {
        format!(" (as {first:?}, which one spelling finds with it)")
    }
}
