//! # trigpoly
//!
//! Exact Laurent × trigonometric polynomials over Q and Q(i): the ring in which the Poisson
//! bracket identities of superintegrable systems live.
//!
//! * Coefficients: [`Rational`] (Q) and [`GaussianRational`] (Q(i)); a polynomial stores one
//!   rational content and machine integers that become big integers only on overflow.
//! * Variables: declared in a [`VarSet`]; every non-angle variable takes any integer exponent,
//!   so `1/(2M)` and `β/x²` are single terms; an angle `θ` enters through `cos θ`, `sin θ`,
//!   stored as powers of `e^{iθ}`.
//! * Normal form: every operation returns the canonical representation, so an identity holds
//!   exactly when the difference [`Poly::is_zero`].
//! * Threads: a large product (2¹⁸ pairs of terms or more, on the dense path) splits its work
//!   over the rayon thread pool it is called from, and when that pool has two threads or more
//!   a large sparse one (2²⁰ pairs or more) writes its terms on a second thread spawned for it;
//!   call it inside a one-thread pool (`rayon::ThreadPoolBuilder::new().num_threads(1)`) to
//!   keep it on the calling thread.
//!
//! ```
//! use trigpoly::{GaussianRational, Poly, Vars};
//!
//! let vars = Vars::builder()
//!     .coordinate("x")
//!     .momentum("p_x")
//!     .angle("theta")
//!     .parameter("M")
//!     .parameter("omega")
//!     .build()?;
//! let p = |s: &str| Poly::<GaussianRational>::parse(&vars, s);
//!
//! // cos²θ + sin²θ = 1, exactly.
//! assert!((p("cos(theta)^2 + sin(theta)^2 - 1")?).is_zero());
//! // (cos θ − i sin θ)³ = e^{−3iθ}, and its real part is T₃(cos θ) = 4cos³θ − 3cos θ.
//! let e = p("(cos(theta) - i*sin(theta))^3")?;
//! assert_eq!(e, p("exp(-3*i*theta)")?);
//! assert_eq!(e.re()?, p("4*cos(theta)^3 - 3*cos(theta)")?);
//! // Printing reads like the paper.
//! assert_eq!(p("-omega^2*M*x + p_x^2/(2*M)")?.to_string(), "p_x²/(2M) − Mω²x");
//! // The text form parses back.
//! assert_eq!(p("p_x²/(2M) − Mω²x")?, p("-omega^2*M*x + p_x^2/(2*M)")?);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![deny(missing_docs, missing_debug_implementations)]

mod error;
mod lower;
mod number;
mod pages;
pub mod placement;
mod poly;
mod print;
pub mod syntax;
mod varset;

/// The big-integer crate of [`Integer::to_bigint`] and [`Integer::from_bigint`], re-exported
/// so that a program names `BigInt` at the version used here without depending on it.
pub use num_bigint;
/// The rational crate of [`Rational::to_big_rational`] and `Rational: From<BigRational>`,
/// re-exported so that a program names `BigRational` at the version used here.
pub use num_rational;

pub use error::{AlgebraError, AngleUse, LimitKind, Misuse, Setting};
pub use lower::{did_you_mean, did_you_mean_hint, quoted_name, shown_name, split_names, FUNCTIONS};
pub use lower::{BracketError, Context, Doubt, NoContext, RunTogether};
pub use number::{
    Coefficient, ExactDivisor, GaussianAcc, GaussianInteger, GaussianRational, Integer, IntegerAcc,
    IntegerRing, IntegerView, ParseGaussianError, ParseRationalError, Rational, RationalErrorKind,
};
pub use poly::{
    CosSinTerm, Division, DivisionOrder, DivisionRefusal, MonomialIndex, Point, Poly,
    ReducedRadical, Term, TrigMonomial,
};
pub use print::{
    differential_latex, is_differential, is_differential_sign, render_number, superscript, Angles,
    Factored, Style, UnknownAngles, UnknownStyle, WithAngles, DIFFERENTIALS,
};
pub use syntax::{Excerpt, ParseCause, ParseError, Span};
pub use varset::{
    display_forms, greek_latex, has_several_words, is_identifier, juxtaposition_is_ambiguous,
    latex_unwritable, momentum_forms, shown_forms, shown_text, unbarred, under_one_bar,
    with_indices, BadName, Limits, Var, VarKind, VarSet, Variable, Vars, VarsBuilder, FIELD_BITS,
    LATEX_LETTERS, MAX_NAME_CHARS, RESERVED,
};

/// Polynomials over Q(i): the type of phase-space functions (angles need `i`).
pub type Expr = Poly<GaussianRational>;
