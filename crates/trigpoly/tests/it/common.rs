//! Helpers through which the tests reach the API: a shared phase space, a parse function that
//! shows the caret rendering on failure, and small conversions.

use std::sync::OnceLock;

use num_bigint::BigInt;
use trigpoly::{
    Coefficient, GaussianRational, Integer, Poly, Rational, Var, VarSet, Vars, VarsBuilder,
};

/// Polynomials over Q(i).
pub type G = Poly<GaussianRational>;
/// Polynomials over Q.
pub type Q = Poly<Rational>;

/// The phase space of the property tests: `x, y, p_x, p_y, θ, φ, M, ω` (two angles).
pub fn phase_space() -> Vars {
    static VARS: OnceLock<Vars> = OnceLock::new();
    VARS.get_or_init(|| phase_space_builder().build().expect("valid variable names"))
        .clone()
}

/// The builder of [`phase_space`], for a phase space like it with more parameters or other
/// limits.
pub fn phase_space_builder() -> VarsBuilder {
    Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .momentum("p_x")
        .momentum("p_y")
        .angle("theta")
        .angle("phi")
        .parameter("M")
        .parameter("omega")
}

/// The plane `x, y, p_x, p_y, θ, M, ω` (coordinates declared before momenta), then the
/// parameters given, in that order.
pub fn plane_with(parameters: &[&str]) -> Vars {
    let plane = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .momentum("p_x")
        .momentum("p_y")
        .angle("theta")
        .parameter("M")
        .parameter("omega");
    parameters
        .iter()
        .fold(plane, |b, name| b.parameter(name))
        .build()
        .expect("valid variable names")
}

/// A variable set of plain coordinates, in the order given.
pub fn coordinates(names: &[&str]) -> Vars {
    names
        .iter()
        .fold(Vars::builder(), |b, name| b.coordinate(name))
        .build()
        .expect("valid variable names")
}

/// The handle of a declared variable.
pub fn var(vars: &VarSet, name: &str) -> Var {
    vars.lookup(name)
        .unwrap_or_else(|| panic!("{name} is not declared in {vars}"))
}

/// Parses `src`; on failure panics with the rendered error (line, column, caret).
pub fn p<C: Coefficient>(vars: &Vars, src: &str) -> Poly<C> {
    Poly::parse(vars, src).unwrap_or_else(|e| panic!("{src:?} does not parse:\n{}", e.render(src)))
}

/// A rational from a big integer.
pub fn big_rational(n: &BigInt) -> Rational {
    Rational::from(Integer::from(n.clone()))
}

/// A rational from an `i128`.
pub fn rational_i128(n: i128) -> Rational {
    Rational::from(Integer::from_i128(n))
}

/// `re + i·im` from integers.
pub fn gauss(re: i64, im: i64) -> GaussianRational {
    GaussianRational::new(Rational::from(re), Rational::from(im))
}
