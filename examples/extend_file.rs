//! A system file loaded, its claims checked, then extended in code: a function, a family and
//! claims of our own added to the loaded system and checked with the file's; and what a slip
//! in a text given in code looks like (kind, line and column, caret).
//!
//! Run with `cargo run --example extend_file`.

use superint::prelude::*;

fn main() -> Result<(), FileError> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/harmonic-rotor.toml");
    let mut rotor = load_system_file(path, &LimitsOverride::default())?;
    let report = check_report([&rotor])?;
    println!(
        "{}: {} claims, all as expected: {}",
        rotor.name(),
        report.claims().len(),
        report.all_as_expected()
    );

    // The Casimir of su(2) as a function, the family Z^m Z̄^n, and claims about both.
    rotor.add_function("C", "C", "4*G1^2 + G2^2 + omega^2*L^2")?;
    rotor.add_family("N", "N", ["m", "n"], "Z^m*Zbar^n", Some("i*(m - n)*omega"))?;
    rotor.add_claim("casimir", "C = (F1 - F2)^2", None)?;
    rotor.add_claim("number", "{N_{1,1}, H} = 0", None)?;
    rotor.add_claim("rank", "rank(F1, F2, L, C) = 3", None)?;
    for spec in &rotor.claims()[rotor.claims().len() - 3..] {
        let checked = rotor.check_claim(spec)?;
        let result = checked.result();
        println!(
            "  {:<8} {:<28} {}",
            result.id, result.statement, result.proved
        );
    }
    let tower = family_tower_report(&rotor, Some("N"), 4, None)?;
    println!("{}", tower.summary_line(false));

    // A slip: the error says where, in the text given.
    let err = rotor
        .add_family("W", "W", ["m", "n"], "Z^m*Zbar^n", Some("i*(m - n)*omegaa"))
        .unwrap_err();
    assert_eq!(err.kind, ErrorKind::Expression);
    println!("{err}");
    match err.line_col() {
        Some((line, column)) => println!("(line {line}, column {column})"),
        None => println!("(no place)"),
    }
    Ok(())
}
