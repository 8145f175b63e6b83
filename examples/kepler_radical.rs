//! The planar Kepler problem in Cartesian coordinates, built in code: the distance
//! `r = √(x² + y²)` is a radical (`VarsBuilder::radical`), so that `−k/r` is exact and
//! `{r, p_x} = x/r`. The Laplace–Runge–Lenz vector is proved conserved, its brackets closing
//! on `−2HL/M`, a false neighbour refuted; then a search from `H` alone finds it.
//!
//! Run with `cargo run --release --example kepler_radical`.

use superint::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .momentum("p_x")
        .momentum("p_y")
        .parameter("M")
        .parameter("k")
        .radical("r", "x^2 + y^2")
        .build()?;
    // The phase space checks the radical: its radicand is no square.
    let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")])?;
    let h = Expr::parse(&vars, "(p_x^2 + p_y^2)/(2*M) - k/r")?;
    let mut kepler = System::new("planar Kepler", space, h)?;
    kepler.define_parsed("L", "L", "x*p_y - y*p_x")?;
    kepler.define_parsed("Ax", "A_x", "p_y*L/M - k*x/r")?;
    kepler.define_parsed("Ay", "A_y", "-p_x*L/M - k*y/r")?;

    for (id, lhs, rhs) in [
        ("radial", "{r, p_x}", "x/r"),
        ("lrl", "{Ax, H}", "0"),
        ("lrl", "{Ay, H}", "0"),
        ("rotation", "{L, Ax}", "Ay"),
        ("algebra", "{Ax, Ay}", "-2*H*L/M"),
        ("length", "Ax^2 + Ay^2", "k^2 + 2*H*L^2/M"),
        // False: the sign of the potential's term in the vector turned.
        ("wrong-sign", "{p_y*L/M + k*x/r, H}", "0"),
    ] {
        let claim = Claim::new(
            id,
            &format!("{lhs} = {rhs}"),
            kepler.parse(lhs)?,
            kepler.parse(rhs)?,
        );
        let verdict = claim.check()?;
        println!("{verdict}");
        // The example checks what it prints (CI runs it): only the turned sign is refuted.
        assert_eq!(verdict.outcome.is_proved(), id != "wrong-sign", "{id}");
    }

    // Every integral of degree ≤ 2 in the momenta, ≤ 1 in x, y and ≤ 1 in r (1/r, x/r, …):
    // 1, L, H and the two components of M·A, each proved.
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(1)
            .radicals_degree(1),
    );
    let found = search(&kepler, &options)?;
    println!(
        "search: {} integrals among {} unknowns",
        found.basis.len(),
        found.unknowns
    );
    assert_eq!(found.basis.len(), 5);
    for integral in &found.basis {
        println!("  {}", integral.expr());
    }
    Ok(())
}
