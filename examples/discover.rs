//! The discovery tools from code, on the harmonic rotor at the resonance `Ω = ω`: every
//! integral of a finite space (a search), the algebra some of them generate (a closure), one
//! function written in others, a certified rank, each as a structured result and as a report
//! rendered to text or JSON.
//!
//! Run with `cargo run --release --example discover`.

use superint::prelude::*;

fn main() -> Result<(), EngineError> {
    let rotor = systems::harmonic_rotor();
    let resonance = rotor.resonance(1, 1)?;

    // Every integral of degree ≤ 2 in the momenta and positions, with cos θ, sin θ.
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .trig_degree(1),
    )
    .when(resonance.clone());
    let (report, found) = search_report("the harmonic rotor", &rotor, &options)?;
    println!(
        "search: {} integrals in a space of {} unknowns, all proved: {}",
        found.basis.len(),
        found.unknowns,
        report.all_proved()
    );
    // The example checks what it prints: CI runs it.
    assert!(report.all_proved() && found.basis.len() == 14);
    for integral in found.basis.iter().take(3) {
        println!("  {}", integral.expr());
    }

    // The algebra of F2, L, P_{1,1}, Q_{1,1} at the resonance, up to degree 2.
    let p = rotor.resonant("Z", 1, 1)?;
    let square =
        p.p.checked_mul(&p.p)?
            .checked_add(&p.q.checked_mul(&p.q)?)?;
    let generators = [
        NamedFunction::new("F2", "F2", rotor.get("F2")?.clone()),
        NamedFunction::new("L", "L", rotor.get("L")?.clone()),
        NamedFunction::new("P", "P", p.p),
        NamedFunction::new("Q", "Q", p.q),
    ];
    let (report, algebra) = closure_report(
        "the harmonic rotor",
        &rotor,
        &generators,
        &ClosureOptions::new(2).when(resonance),
    )?;
    println!(
        "closure: closes = {}, {} relations",
        algebra.closes(),
        algebra.relations.len()
    );
    println!("  {{P, Q}} = {}", algebra.render_bracket(2, 3));
    assert!(algebra.closes() && report.all_proved());
    let json = render(&report, Format::Json, &RenderOptions::reproducible());
    println!("  as JSON: {} bytes", json.len());

    // One function written in others, found and proved as a closure's brackets are:
    // P² + Q² = |Z|², a polynomial of degree 1 in F1, F2 and L.
    let known: Vec<NamedFunction> = ["F1", "F2", "L"]
        .iter()
        .map(|name| Ok(NamedFunction::new(name, name, rotor.get(name)?.clone())))
        .collect::<Result<_, EngineError>>()?;
    let written = expressed_in(&rotor, &known, &square, &ClosureOptions::new(1))?
        .expect("P² + Q² is a polynomial in F1, F2 and L");
    println!("  P² + Q² = {}", written.poly);
    assert!(written.symbolic && written.poly.to_string() == "2Mω L + 2M F1 − 2M F2");

    // Five functionally independent integrals at the resonance (C17), certified: L, G1, G2
    // and F1 − F2 are tied by the Casimir, P_{1,1} is new.
    let mut functions: Vec<Expr> = ["F1", "F2", "G1", "G2"]
        .iter()
        .map(|name| rotor.get(name).cloned())
        .collect::<Result<_, _>>()?;
    functions.push(rotor.resonant("Z", 1, 1)?.p);
    let certificate = rank(rotor.space(), &functions)?;
    println!(
        "rank(F1, F2, G1, G2, P_{{1,1}}) = {}: a nonzero minor {} at an exact point",
        certificate.rank, certificate.minor_value
    );
    assert_eq!(certificate.rank, 5);
    Ok(())
}
