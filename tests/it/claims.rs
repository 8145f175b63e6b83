//! The paper's claims C01–C27 (`docs/claims.md`), one test per claim named after its id, by section.
//! Every test also refutes a false neighbour of its claim (a flipped sign, a wrong coefficient,
//! an off-resonance point, a wrong rank) and checks the exact residual, so no test could pass on
//! an engine that proved everything.

mod beyond;
mod gravity;
mod harmonic;
mod rotor;

use brackets::{rank, BracketTable, RankCertificate, System, UpperBound};
use trigpoly::{Expr, Point, Style, VarKind};

/// The certified rank of the Jacobian of `functions` (text in the system's notation), with its
/// lower-bound certificate checked independently: the minor is recomputed symbolically,
/// evaluated at the certificate's point, and must equal the reported nonzero value.
pub fn certified_rank(system: &System, functions: &[&str]) -> RankCertificate {
    let exprs: Vec<Expr> = functions
        .iter()
        .map(|f| system.parse(f).unwrap_or_else(|e| panic!("{f}: {e}")))
        .collect();
    let space = system.space();
    let cert = rank(space, &exprs).expect("the rank is certified");
    assert!(!cert.minor_value.is_zero(), "the certifying minor is zero");
    assert_eq!(cert.minor_rows.len(), cert.rank);
    assert_eq!(cert.minor_cols.len(), cert.rank);
    // Recompute the minor det(∂F_i/∂z_j) for the certificate's rows and columns.
    let coords = space.coordinates();
    let jac: Vec<Vec<Expr>> = exprs
        .iter()
        .map(|f| coords.iter().map(|&c| f.derivative(c).unwrap()).collect())
        .collect();
    let cols: Vec<usize> = cert
        .minor_cols
        .iter()
        .map(|v| coords.iter().position(|c| c == v).expect("a coordinate"))
        .collect();
    let minor = brackets::rank::symbolic_det(&jac, &cert.minor_rows, &cols).unwrap();
    let vars = system.vars();
    let mut point = Point::new(vars);
    for (v, value) in &cert.point {
        point = if vars.variable(*v).kind() == VarKind::Angle {
            point
                .with_angle(*v, value.re.clone(), value.im.clone())
                .expect("a rational point of the unit circle")
        } else {
            assert!(value.is_real(), "a real point");
            point.with(*v, value.re.clone())
        };
    }
    assert_eq!(
        minor.eval(&point).unwrap(),
        cert.minor_value,
        "the certificate's minor of {functions:?}"
    );
    cert
}

/// Asserts the rank of `functions` and how its upper bound is certified.
#[track_caller]
pub fn assert_rank(system: &System, functions: &[&str], expected: usize, upper: UpperBound) {
    let cert = certified_rank(system, functions);
    assert_eq!(cert.rank, expected, "rank of {functions:?}");
    assert_eq!(
        cert.upper, upper,
        "upper bound of the rank of {functions:?}"
    );
}

/// A bracket table rendered as text: one row per function, `{row, column}` in each cell.
pub fn rendered_table(system: &System, names: &[&str]) -> Vec<Vec<String>> {
    let table = BracketTable::compute(system, names).expect("the table is computed");
    table
        .entries
        .iter()
        .map(|row| row.iter().map(|e| e.render(Style::Unicode)).collect())
        .collect()
}

/// `rows` as owned strings, for comparing with [`rendered_table`].
pub fn table(rows: &[&[&str]]) -> Vec<Vec<String>> {
    rows.iter()
        .map(|r| r.iter().map(|s| s.to_string()).collect())
        .collect()
}

/// Defines `K_{m,n} = Z^m e^{−inθ}` (and `K̄`, `P`, `Q`) as `K`, `Kbar`, `P`, `Q`, written in
/// the paper's notation and checked against the engine's `resonant`.
pub fn define_family(sys: &mut System, ladder: &str, m: i64, n: i64) {
    let bar = format!("{ladder}bar").replace("pbar", "barp");
    sys.define_parsed("K", "K", &format!("{ladder}^{m}*exp(-i*{n}*theta)"))
        .unwrap();
    sys.define_parsed("Kbar", "K̄", &format!("{bar}^{m}*exp(i*{n}*theta)"))
        .unwrap();
    sys.define_parsed("P", "P", "(K + Kbar)/2").unwrap();
    sys.define_parsed("Q", "Q", "(K - Kbar)/(2*i)").unwrap();
    let r = sys.resonant(ladder, m, n).unwrap();
    assert_eq!(&r.k, sys.get("K").unwrap(), "K_{{{m},{n}}}");
    assert_eq!(&r.kbar, sys.get("Kbar").unwrap(), "K̄_{{{m},{n}}}");
    assert_eq!(&r.p, sys.get("P").unwrap(), "P_{{{m},{n}}}");
    assert_eq!(&r.q, sys.get("Q").unwrap(), "Q_{{{m},{n}}}");
}

// The helper itself: it must fail on a false identity, on a true one stated as refuted, and on
// a wrong residual; otherwise the claims' tests would prove nothing.

#[test]
#[should_panic(expected = "{L, G1} = G2 is refuted: residual −p_x²/M + p_y²/M − Mω²x² + Mω²y²")]
fn identity_helper_fails_on_a_false_identity() {
    identity!(brackets::systems::harmonic_rotor(), "{L, G1} = G2");
}

#[test]
#[should_panic(expected = "was proved, but it is false")]
fn identity_helper_fails_on_a_true_identity_stated_refuted() {
    identity!(brackets::systems::harmonic_rotor(), "{L, G1} = -G2" => refuted "G2");
}

#[test]
#[should_panic(expected = "residual of {L, G1} = G2")]
fn identity_helper_fails_on_a_wrong_residual() {
    identity!(brackets::systems::harmonic_rotor(), "{L, G1} = G2" => refuted "-3*G2");
}
