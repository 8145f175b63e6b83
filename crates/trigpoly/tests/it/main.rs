//! Integration tests of `trigpoly`: ring laws, property tests, classical identities
//! (Chebyshev, multinomial, Laurent cancellation), big-integer overflow, rejected inputs and
//! printing like the paper. Every expected value is written as parsed math text through the
//! helpers in [`common`].

/// Asserts an identity between two expressions over Q(i), both written as text:
/// `identity!(vars, "cos(theta)^2 + sin(theta)^2" => "1")`.
macro_rules! identity {
    ($vars:expr, $lhs:expr => $rhs:expr) => {{
        let lhs: $crate::common::G = $crate::common::p(&$vars, &$lhs);
        let rhs: $crate::common::G = $crate::common::p(&$vars, &$rhs);
        pretty_assertions::assert_eq!(lhs, rhs, "identity {} = {}", $lhs, $rhs);
    }};
}

mod calculus;
mod common;
mod expansions;
mod laws;
mod limits;
mod printing;
mod products;
mod props;
mod refusals;
mod reject;
mod run_together;
mod subst_eval;
