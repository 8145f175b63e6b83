//! A system that `systems/` does not hold, built in code and checked as a library checks it:
//! the Garnier system of two coupled anharmonic oscillators,
//! `H = (p1² + p2²)/2 + (a1 q1² + a2 q2²)/2 + (q1² + q2²)²/4`, integrable for distinct `a1, a2`
//! with the quartic integrals
//! `F_i = p_i² + a_i q_i² + q_i² (q1² + q2²)/2 − L²/(2(a_i − a_j))`, `L = q1 p2 − q2 p1`.
//! The parameters stay symbolic, with `a1 − a2` a declared denominator, so that every claim
//! holds for all distinct `a1, a2`: the `F_i` commute with `H` and with each other and
//! `F1 + F2 = 2H`; their false neighbours (the `L²` term's sign turned, the wrong power of
//! `a1 − a2`, the form with `q_i² (q1² + q2²)` and `+L²/(a_i − a_j)`) are refuted. Then the
//! integrals are found from `H` alone, at `a1 = 1, a2 = 2` (to degree 4 in the momenta: one
//! new, the rest products), at `a1 = a2` (where the `F_i` have no value and `L` is
//! conserved) and for every `a1, a2`, and each new one is written in the `F_i` and `H` (in `L`
//! and `H` at `a1 = a2`); a closure finds `F1 + F2 = 2H` by itself. `{L, H}` is printed as the
//! command line's `bracket` shows it, `q1 q2 (a1 − a2)`, by [`Expr::factored`].
//!
//! The program exits with an error when a claim or a search does not come out as stated (CI
//! runs it).
//!
//! Run with `cargo run --example garnier`.

use superint::prelude::*;

/// The claims: `(id, claim, expected proved)`, each read as a system file's `[[claim]]` is.
const CLAIMS: [(&str, &str, bool); 10] = [
    ("conserved", "{F1, H} = 0", true),
    ("conserved", "{F2, H} = 0", true),
    ("involution", "{F1, F2} = 0", true),
    ("sum", "F1 + F2 = 2*H", true),
    ("rotation", "{L, H} = (a1 - a2)*q1*q2", true),
    // False neighbours: each must be refuted.
    ("sum-halved", "F1 + F2 = H", false),
    ("wrong-sign", "{F1_sign, H} = 0", false),
    ("wrong-denominator", "{F1_square, H} = 0", false),
    ("as-first-written", "{F1_first, H} = 0", false),
    ("rotation-conserved", "{L, H} = 0", false),
];

/// The phase space `(q1, p1), (q2, p2)` with the parameters `a1, a2` and the denominator
/// `a1 − a2` (read and checked as a system file's `denominators`, its printed forms derived
/// from it), and `H`; no named function yet, so that a search starts from `H` alone.
fn garnier() -> Result<System, EngineError> {
    let vars = Vars::builder()
        .coordinate("q1")
        .coordinate("q2")
        .momentum("p1")
        .momentum("p2")
        .parameter("a1")
        .parameter("a2")
        .denominator("a1 - a2")?
        .build()?;
    let space = PhaseSpace::new(&vars, &[("q1", "p1"), ("q2", "p2")])?;
    let h = Expr::parse(
        &vars,
        "(p1^2 + p2^2)/2 + (a1*q1^2 + a2*q2^2)/2 + (q1^2 + q2^2)^2/4",
    )?;
    System::new("Garnier system", space, h)
}

/// The system with `L`, the integrals `F1, F2` and the false neighbours of `F1`.
fn with_integrals(bare: &System) -> Result<LoadedSystem, FileError> {
    let mut garnier = LoadedSystem::of_system(bare.clone());
    for (name, display, value) in [
        ("L", "L", "q1*p2 - q2*p1"),
        (
            "F1",
            "F1",
            "p1^2 + a1*q1^2 + q1^2*(q1^2 + q2^2)/2 - L^2/(2*(a1 - a2))",
        ),
        (
            "F2",
            "F2",
            "p2^2 + a2*q2^2 + q2^2*(q1^2 + q2^2)/2 - L^2/(2*(a2 - a1))",
        ),
        (
            "F1_sign",
            "F1'",
            "p1^2 + a1*q1^2 + q1^2*(q1^2 + q2^2)/2 + L^2/(2*(a1 - a2))",
        ),
        (
            "F1_square",
            "F1''",
            "p1^2 + a1*q1^2 + q1^2*(q1^2 + q2^2)/2 - L^2/(2*(a1 - a2)^2)",
        ),
        (
            "F1_first",
            "F1'''",
            "p1^2 + a1*q1^2 + q1^2*(q1^2 + q2^2) + L^2/(a1 - a2)",
        ),
    ] {
        garnier.add_function(name, display, value)?;
    }
    for (id, claim, proved) in CLAIMS {
        let spec = garnier.add_claim(id, claim, None)?;
        if !proved {
            spec.expect = Expect::Refuted;
        }
    }
    Ok(garnier)
}

/// What a search is stated to find: how many integrals, how many of them new, and each new
/// one written in the functions `known` as `written` (for every `a1, a2` when `symbolic`).
struct Stated {
    integrals: usize,
    new: usize,
    known: &'static [&'static str],
    written: &'static str,
    symbolic: bool,
}

/// Runs one search from `H` alone, prints its report and writes each new integral in the
/// functions of `garnier` that `stated` names; the error says what differs from `stated`.
fn search_and_write(
    bare: &System,
    garnier: &LoadedSystem,
    title: &str,
    options: &SearchOptions,
    stated: &Stated,
) -> Result<(), Box<dyn std::error::Error>> {
    let (report, found) = search_report(title, bare, options)?;
    print!(
        "{}",
        render(&report, Format::Text, &RenderOptions::reproducible())
    );
    let new = found.new.as_ref().map_or(&[][..], |n| &n.new[..]);
    if found.basis.len() != stated.integrals || new.len() != stated.new {
        return Err(format!(
            "{title}: {} integrals, {} new, where {} and {} were stated",
            found.basis.len(),
            new.len(),
            stated.integrals,
            stated.new
        )
        .into());
    }
    let system = garnier.system();
    let known: Vec<NamedFunction> = stated
        .known
        .iter()
        .map(|&name| Ok(NamedFunction::new(name, name, system.get(name)?.clone())))
        .collect::<Result<_, EngineError>>()?;
    // At fixed values, the functions are taken there too, where the search's integrals are.
    let at_values: Vec<NamedFunction> = known
        .iter()
        .map(|f| {
            let value = fix_parameters(&f.expr, &found.parameters)?;
            Ok(NamedFunction::new(&f.name, &f.display, value))
        })
        .collect::<Result<_, EngineError>>()?;
    let mut writing = ClosureOptions::new(1);
    for (v, value) in &found.parameters {
        writing = writing.fix(*v, value.clone());
    }
    for &i in new {
        let integral = &found.basis[i];
        let (target, generators) = match stated.symbolic {
            true => (integral.expr(), &known),
            false => (&integral.fixed, &at_values),
        };
        let written = expressed_in(system, generators, target, &writing)?;
        match written {
            Some(w) if w.poly.to_string() == stated.written && (w.symbolic || !stated.symbolic) => {
                let values: Vec<String> = (found.parameters.iter())
                    .map(|(v, x)| format!("{} = {x}", system.vars().variable(*v).name()))
                    .collect();
                let at = match stated.symbolic {
                    true => String::new(),
                    false => format!(" at {}", values.join(", ")),
                };
                println!("  the new integral {} = {}{at}", integral.expr(), w.poly)
            }
            _ => {
                let names = stated.known.join(", ");
                return Err(format!(
                    "{title}: {target} is not written in {names} as {}",
                    stated.written
                )
                .into());
            }
        }
    }
    Ok(())
}

/// The searches from `H` alone, each with its own title and stated by what it finds: degree
/// ≤ 2 in the momenta and ≤ 4 in `q1, q2`, or ≤ 4 and ≤ 8, at chosen values or for every
/// value.
fn searches(bare: &System) -> [(&'static str, SearchOptions, Stated); 4] {
    let (a1, a2) = (bare.var("a1"), bare.var("a2"));
    let space = SearchSpace::default().momenta_degree(2).positions_degree(4);
    let wider = SearchSpace::default().momenta_degree(4).positions_degree(8);
    let at = |x: i64, y: i64, space| SearchOptions::new(space).fix(a1, x).fix(a2, y).new_only();
    let integrals = &["F1", "F2", "H"];
    [
        // At a1 = 1, a2 = 2: the constants, H and one new integral, −2 F2 at these values
        // (F1 = 2H − F2).
        (
            "the Garnier system at a1 = 1, a2 = 2",
            at(1, 2, space),
            Stated {
                integrals: 3,
                new: 1,
                known: integrals,
                written: "−2 F2",
                symbolic: false,
            },
        ),
        // Wider: the same one new, and the products H², H F2 and F2².
        (
            "the Garnier system at a1 = 1, a2 = 2, to degree 4 in the momenta",
            at(1, 2, wider),
            Stated {
                integrals: 6,
                new: 1,
                known: integrals,
                written: "−2 F2",
                symbolic: false,
            },
        ),
        // At a1 = a2 the potential is central: F1 and F2 have no value there, and the
        // rotation L is conserved, the one new integral (a denominator that nothing divides
        // by may vanish at the values taken).
        (
            "the Garnier system at a1 = a2 = 3",
            at(3, 3, space),
            Stated {
                integrals: 4,
                new: 1,
                known: &["L", "H"],
                written: "L",
                symbolic: false,
            },
        ),
        // For every a1, a2, with coefficients of degree ≤ 1 in them and one power of
        // 1/(a1 − a2): the constants (1, a1, a2, 1/(a1 − a2), a2/(a1 − a2)), H and
        // H/(a1 − a2), and one new integral, 2 F2.
        (
            "the Garnier system for every a1, a2",
            SearchOptions::new(space.parameters_degree(1).denominators_degree(1))
                .symbolic(a1)
                .symbolic(a2)
                .new_only(),
            Stated {
                integrals: 8,
                new: 1,
                known: integrals,
                written: "2 F2",
                symbolic: true,
            },
        ),
    ]
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let bare = garnier()?;
    let garnier = with_integrals(&bare)?;

    // The claims, proved for every distinct a1, a2, or refuted with their residual.
    let claims = check_report([&garnier])?;
    print!(
        "{}",
        render(&claims, Format::Text, &RenderOptions::reproducible())
    );
    if !claims.all_as_expected() {
        return Err("a claim of the Garnier system did not come out as stated".into());
    }

    // {L, H} as a program computes it, expanded, and with the factor its terms share taken
    // out, as the command line's `bracket` prints it under the expanded form.
    let system = garnier.system();
    let rotation = system.bracket(system.get("L")?, system.hamiltonian())?;
    let factored = rotation.factored().ok_or("{L, H} has no common factor")?;
    println!("{{L, H}} = {rotation}\n       = {factored}");
    if factored.to_string() != "q1 q2 (a1 − a2)" {
        return Err(format!("{{L, H}} = {factored}, where q1 q2 (a1 − a2) was stated").into());
    }

    // From H alone, each search stated by what it finds, under its own title.
    for (title, options, stated) in &searches(&bare) {
        search_and_write(&bare, &garnier, title, options, stated)?;
    }

    // The algebra of F1, F2 and H: every bracket zero, and F1 + F2 = 2H found, not told.
    let (a1, a2) = (bare.var("a1"), bare.var("a2"));
    let names = ["F1", "F2", "H"];
    let mut options = ClosureOptions::new(1).parameters_degree(0);
    for v in [a1, a2] {
        options = options.symbolic(v);
    }
    let algebra = closure(garnier.system(), &names, &options)?;
    let relations: Vec<String> = algebra.relations.iter().map(|r| r.to_string()).collect();
    println!(
        "closure of F1, F2, H: closes = {}, relations: {}",
        algebra.closes(),
        relations.join("; ")
    );
    if !algebra.closes() || relations != ["F1 + F2 = 2 H"] {
        return Err("the algebra of F1, F2, H is not the one stated".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each search prints a report of its own, titled by where it searches: the four printed
    /// one title, "Integrals of the Garnier system", between which a reader could not tell.
    #[test]
    fn each_search_has_its_own_title() {
        let bare = garnier().unwrap();
        let titles: Vec<&str> = searches(&bare).iter().map(|s| s.0).collect();
        for (k, title) in titles.iter().enumerate() {
            assert!(title.starts_with("the Garnier system "), "{title}");
            assert!(!titles[..k].contains(title), "{title} twice");
        }
        let (report, _) = search_report(titles[0], &bare, &searches(&bare)[0].1).unwrap();
        let text = render(&report, Format::Text, &RenderOptions::reproducible());
        assert!(
            text.starts_with("Integrals of the Garnier system at a1 = 1, a2 = 2\n"),
            "{text}"
        );
    }
}
