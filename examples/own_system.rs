//! A system built entirely in code, in names of our own: a rigid rotor (angle `phi`, moment of
//! inertia `J`) riding on the isotropic oscillator of frequency `k`. Its ladder function `A`,
//! the resonant family `R_{a,b} = A^a e^{−ibφ}` with `{R_{a,b}, H} = i(ak − bΩ) R_{a,b}`, the
//! tower checked for `1 ≤ a, b ≤ 3` and proved for all `a, b`, a claim at the resonance
//! `Ω = k`, and the report as text and JSON.
//!
//! Run with `cargo run --example own_system`.

use superint::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .angle("phi")
        .momentum("p_x")
        .momentum("p_y")
        .momentum("p_phi")
        .parameter("k")
        .parameter("J")
        .build()?;
    let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y"), ("phi", "p_phi")])?;
    let h = Expr::parse(
        &vars,
        "(p_x^2 + p_y^2)/2 + k^2*(x^2 + y^2)/2 + p_phi^2/(2*J)",
    )?;
    let mut rotor = System::new("oscillating rotor", space, h)?;
    rotor.define_parsed("A", "A", "p_x + i*p_y + i*k*(x + i*y)")?;
    rotor.define_parsed("Omega", "Ω", "p_phi/J")?;

    // One identity, with the engine alone: {A, H} = ikA.
    let ladder = Claim::new(
        "ladder",
        "{A, H} = ikA",
        rotor.parse("{A, H}")?,
        rotor.parse("i*k*A")?,
    );
    let verdict = ladder.check()?;
    println!("{verdict}");
    // The example checks what it prints: CI runs it.
    assert!(verdict.outcome.is_proved());

    // Families, claims and the tower live on a LoadedSystem, which a system in code becomes.
    let mut rotor = LoadedSystem::of_system(rotor);
    rotor.add_family(
        "R",
        "R",
        ["a", "b"],
        "A^a*exp(-i*b*phi)",
        Some("i*(a*k - b*Omega)"),
    )?;
    rotor.add_claim("resonant", "{R_{1,1}, H} = 0", Some("p_phi = J*k"))?;
    rotor
        .add_claim("off", "{R_{2,1}, H} = 0", Some("p_phi = J*k"))?
        .expect = Expect::Refuted;
    let claims = check_report([&rotor])?;
    assert!(claims.all_as_expected());
    print!(
        "{}",
        render(&claims, Format::Text, &RenderOptions::reproducible())
    );

    let tower = family_tower_report(&rotor, Some("R"), 3, None)?;
    let checked = tower.tower().expect("a tower job has its tower");
    let proof = tower.proof().expect("R is a product of powers");
    println!(
        "tower: {} brackets, {} failing; for all a, b: {}",
        checked.checked,
        checked.failures.len(),
        if proof.holds() {
            "proved"
        } else {
            "not proved"
        }
    );
    for fact in &proof.facts {
        println!("  {}: {}", fact.statement, fact.holds);
    }
    assert!(checked.failures.is_empty() && proof.holds());
    let json = render(&tower, Format::Json, &RenderOptions::reproducible());
    println!("as JSON: {} bytes", json.len());
    Ok(())
}
