//! Names run together that split into declared names are read as their product (`Mω` is
//! `M·ω`), and the lowering says which of those readings may not be what was meant
//! ([`RunTogether`]): a function's name continued by letters (`Lxx` beside `Lx`), a name close
//! to a declared one (`Axx` beside `A_xx`, `Ayx` beside `Axy`), two letters beside a declared
//! name of two with the same first (`Hy` beside `Hx`), a letter doubled after a longer name
//! (`omegaa`, `p_xx`); the physics products are read without a word.

use pretty_assertions::assert_eq;
use trigpoly::{Context, Doubt, GaussianRational, RunTogether, Span, Vars};

use crate::common::{plane_with, G};

/// `x, y, p_x, p_y, θ, M, ω, I, a, A`.
fn vars() -> Vars {
    plane_with(&["I", "a", "A"])
}

/// Named functions over `vars()`: `Lx`, `Axy` and `A_xx`.
struct Functions(Vec<(&'static str, G)>);

impl Functions {
    fn new(vars: &Vars) -> Self {
        let p = |s: &str| G::parse(vars, s).unwrap();
        Functions(vec![
            ("Lx", p("y*p_x")),
            ("Axy", p("p_x*p_y + omega^2*x*y")),
            ("A_xx", p("p_x^2 + omega^2*x^2")),
        ])
    }
}

impl Context<GaussianRational> for Functions {
    fn lookup(&self, name: &str) -> Option<G> {
        self.0
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, f)| f.clone())
    }
    fn bracket(&self, _: &G, _: &G) -> Result<G, trigpoly::BracketError> {
        Err(trigpoly::BracketError::Other("no brackets here".into()))
    }
    fn names(&self) -> Vec<String> {
        self.0.iter().map(|(n, _)| n.to_string()).collect()
    }
}

fn noted(src: &str) -> Vec<RunTogether> {
    let vars = vars();
    G::parse_noting(&vars, src, &Functions::new(&vars))
        .unwrap_or_else(|e| panic!("{src}: {e}"))
        .1
}

fn pieces(ps: &[&str]) -> Vec<String> {
    ps.iter().map(|p| p.to_string()).collect()
}

/// A text, the name in it read in doubt, its span, the pieces it is read as, and why.
type Case = (
    &'static str,
    &'static str,
    (usize, usize),
    &'static [&'static str],
    Doubt,
);

#[test]
fn a_reading_in_doubt_is_noted_with_its_place_and_why() {
    let cases: [Case; 8] = [
        // A function's name with letters after it.
        (
            "Lxx",
            "Lxx",
            (0, 3),
            &["Lx", "x"],
            Doubt::Continued("Lx".into()),
        ),
        (
            "2*Lxy + 1",
            "Lxy",
            (2, 5),
            &["Lx", "y"],
            Doubt::Continued("Lx".into()),
        ),
        // The power belongs to the last piece, and the name is noted once.
        (
            "Lxx^2",
            "Lxx",
            (0, 3),
            &["Lx", "x"],
            Doubt::Continued("Lx".into()),
        ),
        // A name before parentheses multiplies them.
        (
            "Lxy(x + y)",
            "Lxy",
            (0, 3),
            &["Lx", "y"],
            Doubt::Continued("Lx".into()),
        ),
        // The letters of A_xx but for its underscore; one slip from Axy (two swapped).
        (
            "x + Axx",
            "Axx",
            (4, 7),
            &["A", "x", "x"],
            Doubt::CloseTo("A_xx".into()),
        ),
        (
            "Ayx",
            "Ayx",
            (0, 3),
            &["A", "y", "x"],
            Doubt::CloseTo("Axy".into()),
        ),
        // A letter doubled after a longer name.
        (
            "omegaa",
            "omegaa",
            (0, 6),
            &["omega", "a"],
            Doubt::Doubled('a'),
        ),
        ("x*p_xx", "p_xx", (2, 6), &["p_x", "x"], Doubt::Doubled('x')),
    ];
    let vars = vars();
    let ctx = Functions::new(&vars);
    for (src, name, (start, end), read_as, doubt) in cases {
        let (value, noted) = G::parse_noting(&vars, src, &ctx).unwrap();
        // The reading stands: the product, as written with its pieces apart.
        let apart = src.replacen(name, &read_as.join("*"), 1);
        let apart = match src {
            "Lxx^2" => "Lx*x^2".to_string(),
            _ => apart,
        };
        assert_eq!(value, G::parse_with(&vars, &apart, &ctx).unwrap(), "{src}");
        // Each field, as a program reads them (a `RunTogether` is the library's to make).
        let fields: Vec<_> = noted
            .iter()
            .map(|r| (r.name.as_str(), r.span, r.pieces.clone(), r.doubt.clone()))
            .collect();
        assert_eq!(
            fields,
            [(name, Span::new(start, end), pieces(read_as), doubt)],
            "{src}"
        );
    }
}

#[test]
fn the_physics_products_are_read_without_a_word() {
    for src in [
        "Mω²x",
        "Iω",
        "2Mω",
        "Mωx + Mωy",
        "exp(iθ) + cos(2θ)",
        "iMω(x + iy)",
        "xp_y - yp_x",
        "omegax + Momega",
        "aLx + ωLx + Iomega",
        "xx + ωω + xy p_y",
        "p_x²/(2M) + Mω²x²/2",
    ] {
        assert_eq!(noted(src), [], "{src}");
    }
}

#[test]
fn the_message_says_the_reading_and_what_to_write() {
    let [lxx] = &noted("Lxx")[..] else { panic!() };
    assert_eq!(
        lxx.to_string(),
        "'Lxx' is read as the product Lx x, the function Lx with x after it: declare 'Lxx' if \
         it is a name of its own, or write 'Lx x' for the product"
    );
    let [axx] = &noted("Axx")[..] else { panic!() };
    let shown = |p: &str| match p {
        "A" => "𝒜".to_string(),
        _ => p.to_string(),
    };
    assert_eq!(
        axx.reading(&shown, &|f: &str| format!("`{f}`"), true),
        "is read as the product `𝒜 x x`, though it is close to the declared name A_xx: declare \
         'Axx' if it is a name of its own, or write 'A x x' for the product"
    );
    // Where no name can be declared (a built-in system), the product's advice alone.
    assert_eq!(
        axx.reading(&shown, &|f: &str| f.to_string(), false),
        "is read as the product 𝒜 x x, though it is close to the declared name A_xx: write \
         'A x x' or 'A*x*x' for the product"
    );
    let [doubled] = &noted("omegaa")[..] else {
        panic!()
    };
    assert_eq!(
        doubled.to_string(),
        "'omegaa' is read as the product omega a, with its a doubled: declare 'omegaa' if it is \
         a name of its own, or write 'omega a' for the product"
    );
}

/// Two one-letter names run together beside a declared name of two letters with the same
/// first (`Hy` beside a function `Hx`, `Lx` beside `Ly`) are noted, that name said in the
/// message; `xy`, `Mω` and a function's name with a letter after it (`Lx` beside `L` where no
/// `Ly` is declared) are not.
#[test]
fn two_letters_beside_a_declared_name_of_the_same_first_are_noted() {
    let vars = plane_with(&["H", "L"]);
    let p = |s: &str| G::parse(&vars, s).unwrap();
    let beside = Functions(vec![("Hx", p("p_x^2/2")), ("Ly", p("y*p_x"))]);
    let noted = |src: &str| G::parse_noting(&vars, src, &beside).unwrap().1;
    let [hy] = &noted("x + Hy")[..] else {
        panic!("{:?}", noted("x + Hy"))
    };
    assert_eq!(
        (hy.span, hy.pieces.clone(), hy.doubt.clone()),
        (
            Span::new(4, 6),
            pieces(&["H", "y"]),
            Doubt::SameFirstLetter("Hx".into())
        )
    );
    assert_eq!(
        hy.to_string(),
        "'Hy' is read as the product H y, though the declared name Hx differs from it in its \
         last letter alone: declare 'Hy' if it is a name of its own, or write 'H y' for the \
         product"
    );
    let [lx] = &noted("Lx")[..] else { panic!() };
    assert_eq!(lx.doubt, Doubt::SameFirstLetter("Ly".into()));
    for src in ["xy + Mω + Hp_x + HLy", "Lp_x + xLy"] {
        assert_eq!(noted(src), [], "{src}");
    }
    // With no declared name of two letters, `Lx` and `Hy` are products.
    let alone = Functions(vec![("Hxx", p("p_x^2/2"))]);
    let (_, noted) = G::parse_noting(&vars, "Lx + Hy + xy + Mω", &alone).unwrap();
    assert_eq!(noted, []);
    // A parameter of two letters is no function of a set: `mx` beside `m` and `mu` is `m·x`.
    let masses = plane_with(&["m", "mu"]);
    let (_, noted) = G::parse_noting(&masses, "mx + my + mu x", &beside).unwrap();
    assert_eq!(noted, []);
}
