//! The report of `superint search` ([`search_report`]): the space searched, the dimensions by
//! degree, a basis written like the paper (or the new integrals beyond known ones), each proved.

use crate::render::tex::Names;
use crate::render::Format;
use std::time::Instant;

use brackets::search::{
    basis_rank, fix_parameters, generation_decided, level_set_graph_variable, search, Integral,
    NewIntegrals, SearchOptions, SearchResult, SearchSpace, SearchedLevel, SEARCH_RANK_MINORS,
};
use brackets::{BoundedRank, EngineError, PhaseSpace, System, UpperBound};
use trigpoly::{Expr, GaussianRational, Rational, Style, Var, VarKind, Vars};

use crate::report::{
    counted, first_free, listed, ClaimResult, Entry, Equation, Equations, Facts, LevelSetFacts,
    Report, SearchFacts, Section, SummaryKind,
};

use crate::system_file::{Caller, LoadedSystem, MAX_RESTATED};

use super::{agreeing, off_one_note, parameter_facts, parameter_names, proved_for_every, HeldAt};

/// `F = Re(A e^{−ik·θ})` for an integral of one trigonometric order `k > 0` in one angle:
/// `(A, k)`, `A` twice the coefficient of `e^{−ikθ}`.
pub fn complex_form(f: &Expr) -> Option<(Expr, i64)> {
    let vars = f.vars();
    let mut angles = vars.angles();
    let theta = angles.next()?;
    if angles.next().is_some() {
        return None;
    }
    let (lo, hi) = f.exponent_range(theta)?;
    if lo != -hi || hi == 0 {
        return None;
    }
    let mut terms = Vec::new();
    for t in f.terms() {
        let k = t.exponent(theta);
        if k != -hi && k != hi {
            return None;
        }
        if k == -hi {
            let mut e = t.exponents();
            e[theta.index()] = 0;
            terms.push((&t.coeff() * &GaussianRational::from(2), e));
        }
    }
    Some((Expr::from_terms(vars, terms).ok()?, hi))
}

/// The first of `candidates` that names none of `count` labels `P1, P2, …` the system has as
/// a variable or a function (`I1`, `I2` are a coupled rotor's moments of inertia) or are
/// `taken` (a file's families, by name and display), nor the letter `P` itself: the letter of
/// a report's numbered labels. The letter alone is avoided since the captions write it so:
/// the amplitudes' `Re(A e^{−ikθ})`, above lines that restate them in the file's functions
/// (`A7 = A` read the amplitude as the function `A` of the Smorodinsky–Winternitz rotor, and
/// `Re(B e^{−ikθ})` as the family `B` of the 3:5 rotor), and the integrals' `I = Re(…)` and
/// `{I, H} = 0 for the other 23 basis elements` (which a rotor's search printed beside
/// `p_θ = Iω`, `I` its moment of inertia).
fn label_letter<'a>(
    system: &System,
    taken: &[&str],
    candidates: &[&'a str],
    count: usize,
) -> &'a str {
    first_free(system, taken, candidates, |p| {
        std::iter::once(p.to_string())
            .chain((1..=count).map(|i| format!("{p}{i}")))
            .collect()
    })
}

/// With parameters kept symbolic, the note that `H` or its first power `H^k` that the space
/// holds in the phase-space variables needs a degree in them past the space's: the integrals
/// of that degree in the momenta (or, without momenta in `H`, in the Poisson variables) may
/// then need a larger `--parameters-degree` (an oscillator with symbolic frequencies showed no
/// quartic integral at degree 2, since `H²` has degree 4 in them), or for a program a larger
/// `SearchSpace::parameters_degree`.
fn power_past_parameters_degree(
    h: &Expr,
    options: &SearchOptions,
    caller: Caller,
) -> Option<String> {
    if options.symbolic.is_empty() {
        return None;
    }
    let vars = h.vars();
    // `H` with negative powers of the symbolic parameters (`p²/(2M)`) is known to the search
    // through its least multiple without them (`M H`), whose degree is what the space must
    // hold: it counted `|−1|` for `1/M`, so that `p²/(2M) + Ma²x²/8` read as of degree 3 where
    // `M H` has 4, and at degree 3 nothing said that `H` was left out.
    let lowest: Vec<(Var, i64)> = options
        .symbolic
        .iter()
        .map(|&v| {
            (
                v,
                h.terms().map(|t| t.exponent(v)).min().unwrap_or(0).min(0),
            )
        })
        .collect();
    // The total degree in the symbolic parameters (`total_degree` counts by kind, and the
    // fixed parameters are parameters too).
    let s = h
        .terms()
        .map(|t| {
            lowest
                .iter()
                .map(|&(v, lo)| t.exponent(v) - lo)
                .sum::<i64>()
        })
        .max()
        .unwrap_or(0);
    let mut multiplier = vec![0i64; vars.len()];
    for &(v, lo) in &lowest {
        multiplier[v.index()] = -lo;
    }
    let multiple = match multiplier.iter().all(|e| *e == 0) {
        true => None,
        false => Expr::from_terms(vars, vec![(GaussianRational::from(1), multiplier)])
            .ok()
            .map(|m| m.render(Style::Unicode)),
    };
    let degree = |kind| h.total_degree(&[kind]).unwrap_or(0);
    let (momenta, positions, poisson, trig) = (
        degree(VarKind::Momentum),
        degree(VarKind::Coordinate),
        degree(VarKind::Poisson),
        degree(VarKind::Angle),
    );
    let space = &options.space;
    let bound = i64::from(space.parameters_degree);
    let names = parameter_names(vars, &options.symbolic);
    let option = caller.names("--parameters-degree", "SearchSpace::parameters_degree");
    let (subject, power_of) = match &multiple {
        None => ("H".to_string(), "H".to_string()),
        Some(m) => (
            format!("`{m} H` (H without its negative powers of `{names}`)"),
            format!("({m} H)"),
        ),
    };
    if s > bound {
        return Some(format!(
            "Note: {subject} has degree {s} in `{names}`, past the space's `{bound}` \
             (`{option}`), so H is not among the integrals found, nor is any that \
             needs its terms."
        ));
    }
    let fits = |k: i64| {
        k * momenta <= i64::from(space.momenta_degree)
            && (space.laurent || k * positions <= i64::from(space.positions_degree))
            && k * poisson <= i64::from(space.poisson_degree)
            && k * trig <= i64::from(space.trig_degree)
    };
    let largest = space.momenta_degree.max(space.poisson_degree).max(2);
    let k = (2..=i64::from(largest))
        .take_while(|&k| fits(k) && (momenta > 0 || poisson > 0))
        .find(|&k| k * s > bound)?;
    let power = trigpoly::superscript(k);
    let degree = match momenta {
        0 => format!("{} in the Poisson variables", k * poisson),
        _ => format!("{} in the momenta", k * momenta),
    };
    Some(format!(
        "Note: `{power_of}{power}` lies in the space but for its degree {} in `{names}`, past the space's \
         `{bound}` (`{option}`): integrals of degree {degree} may need a larger one.",
        k * s,
    ))
}

/// The basis integrals a search shows as claims: with `--new-only` the new ones, with
/// symbolic parameters the generators over their polynomials, else the whole basis.
fn shown_integrals(r: &SearchResult) -> Vec<usize> {
    match (&r.new, &r.module) {
        (Some(n), _) => n.new.clone(),
        (None, Some(m)) => (0..r.basis.len())
            .filter(|i| m.generators.contains(i))
            .collect(),
        (None, None) => (0..r.basis.len()).collect(),
    }
}

/// The letter of the trigonometric order, `k` unless the system names a variable so (the
/// Kepler problem's `k`): then the first of `j, l, o, ν` that is free.
fn order_letter(vars: &trigpoly::Vars) -> &'static str {
    ["k", "j", "l", "o", "ν"]
        .into_iter()
        .find(|c| vars.lookup(c).is_none())
        .unwrap_or("κ")
}

/// The sentence that describes a search's space: its general monomial and the bounds on its
/// degrees, the size of the linear problem, and what the space leaves out.
fn space_text(r: &SearchResult) -> String {
    let k = order_letter(&r.vars);
    let exponents = SpaceExponents::of(r, k);
    let mut degrees = exponents.degrees(&r.space);
    let (trig_factor, trig_degree) = trigonometric_factor(r, k);
    degrees.extend(trig_degree);
    format!(
        "The space: `{}`{trig_factor}, with {}{}: {}{}, {} over `Q`, in {} (the largest has \
         {}).{}",
        exponents.monomial(),
        degrees.join(", "),
        symbolic_coefficients_text(r),
        counted(r.unknowns, "unknown"),
        dependent_monomials_text(r),
        counted(r.equations, "linear equation"),
        counted(r.components, "independent block"),
        counted(r.largest_component, "unknown"),
        left_out_text(r),
    )
}

/// The general monomial of a search's space, with one exponent letter for each of its
/// variables (`x^a y^b p_x^c p_y^d`), and the sums of those letters that its degrees bound.
struct SpaceExponents {
    /// The powers of the coordinates, radicals, momenta and Poisson variables, `x^a`.
    numerator: Vec<String>,
    /// The powers of the denominator atoms, `(x − y)^r`.
    denominator: Vec<String>,
    /// `|a| + |b|` over the coordinates, whose powers may be negative in a Laurent space.
    positions: String,
    /// Over the radicals, whose powers are of either sign.
    radicals: String,
    momenta: String,
    poisson: String,
    denominators: String,
    /// What the denominators that hold fixed parameters alone are: numbers, which add no
    /// unknown (`a1 − a2` with `a1 = 7, a2 = 11/2`); empty where there are none.
    numbers: String,
}

/// The note that the denominator `atoms` holding fixed parameters alone are numbers in the
/// linear algebra, so that their powers add no unknown; empty where none does.
fn numbers_at_fixed_values(r: &SearchResult, atoms: &[Var]) -> String {
    let numbers: Vec<String> = (denominator_numbers(r).into_iter())
        .filter(|atom| atoms.contains(atom))
        .map(|atom| format!("`{}`", r.vars.variable(atom).unicode()))
        .collect();
    match numbers.len() {
        0 => String::new(),
        n if n == atoms.len() => {
            " (numbers at the parameters' fixed values below, so they add no unknown)".into()
        }
        _ => format!(
            " ({} {} at the parameters' fixed values below, so {} no unknown)",
            listed(&numbers),
            agreeing(numbers.len(), "a number", "numbers"),
            agreeing(numbers.len(), "it adds", "they add"),
        ),
    }
}

/// The denominator atoms that hold fixed parameters alone: numbers in the linear algebra
/// (`κ + 1` at `κ = 1` is 2).
fn denominator_numbers(r: &SearchResult) -> Vec<Var> {
    let fixed = |v: Var| r.parameters.iter().any(|(p, _)| *p == v);
    let defined = Expr::denominator_atoms(&r.vars).unwrap_or_default();
    (defined.into_iter())
        .filter(|(_, d)| r.vars.vars().all(|v| !d.contains(v) || fixed(v)))
        .map(|(atom, _)| atom)
        .collect()
}

impl SpaceExponents {
    /// The exponents of `r`'s space, with letters that name no variable and differ from the
    /// trigonometric order's letter `k`.
    fn of(r: &SearchResult, k: &str) -> Self {
        let space = &r.variables;
        let name = |v: &Var| r.vars.variable(*v).unicode().to_string();
        // One exponent letter per coordinate and momentum, in order (`x^a y^b p_x^c p_y^d`),
        // none the name of a variable or the trigonometric order's letter.
        let taken = |c: &char| {
            let mut buf = [0; 4];
            r.vars.lookup(c.encode_utf8(&mut buf)).is_some()
        };
        let mut letters = "abcdefghjlmnqrsuvw"
            .chars()
            .filter(|c| !taken(c) && c.to_string() != k);
        let mut numerator = Vec::new();
        let mut exponents = |vars: &[Var], absolute: bool| -> String {
            let degree: Vec<String> = vars
                .iter()
                .zip(&mut letters)
                .map(|(v, letter)| {
                    numerator.push(format!("{}^{letter}", name(v)));
                    if absolute {
                        format!("|{letter}|")
                    } else {
                        letter.to_string()
                    }
                })
                .collect();
            degree.join(" + ")
        };
        let positions = exponents(&space.coordinates, true);
        // Each radical `r` to a power of either sign, `r^j` (none at `--radicals-degree 0`).
        let radical_vars: Vec<Var> = radicals_in_space(r).collect();
        let radicals = exponents(&radical_vars, true);
        let momenta = exponents(&space.momenta, false);
        let poisson = exponents(&space.poisson, false);
        // Each denominator atom `(x − y)` to a negative power, `1/(x − y)^r` (none at
        // `--denominators-degree 0`).
        let atoms: Vec<Var> = denominators_in_space(r).collect();
        let mut denominator = Vec::new();
        let denominators: Vec<String> = atoms
            .iter()
            .zip(&mut letters)
            .map(|(v, letter)| {
                denominator.push(format!("{}^{letter}", name(v)));
                letter.to_string()
            })
            .collect();
        SpaceExponents {
            numerator,
            denominator,
            positions,
            radicals,
            momenta,
            poisson,
            denominators: denominators.join(" + "),
            numbers: numbers_at_fixed_values(r, &atoms),
        }
    }

    /// The general monomial, `x^a y^b/((x − y)^r)`, or `1` in a space of no such variables.
    fn monomial(&self) -> String {
        let (numerator, denominator) = (&self.numerator, &self.denominator);
        match (numerator.is_empty(), denominator.is_empty()) {
            (true, true) => "1".to_string(),
            (true, false) => format!("1/({})", denominator.join(" ")),
            (false, true) => numerator.join(" "),
            (false, false) => format!("{}/({})", numerator.join(" "), denominator.join(" ")),
        }
    }

    /// The bound on each degree of the space `s` but the trigonometric order, for the kinds
    /// of variables it has.
    fn degrees(&self, s: &SearchSpace) -> Vec<String> {
        let laurent = if s.laurent {
            " (negative powers of the coordinates allowed)"
        } else {
            ""
        };
        let mut degrees = Vec::new();
        if !self.momenta.is_empty() {
            degrees.push(format!(
                "momenta degree `{} ≤ {}`",
                self.momenta, s.momenta_degree
            ));
        }
        if !self.positions.is_empty() {
            degrees.push(format!(
                "positions degree `{} ≤ {}`{laurent}",
                self.positions, s.positions_degree
            ));
        }
        if !self.poisson.is_empty() {
            degrees.push(format!(
                "degree `{} ≤ {}` in the Poisson variables",
                self.poisson, s.poisson_degree
            ));
        }
        if !self.radicals.is_empty() {
            degrees.push(format!(
                "degree `{} ≤ {}` in the radicals",
                self.radicals, s.radicals_degree
            ));
        }
        if !self.denominators.is_empty() {
            degrees.push(format!(
                "degree `{} ≤ {}` in the denominators{}",
                self.denominators, s.denominators_degree, self.numbers
            ));
        }
        degrees
    }
}

/// The trigonometric functions that multiply the monomial (`` times `1, cos kθ, sin kθ` ``),
/// with the bound on their order, written with the order's letter `k`; nothing in a space
/// without angles or of order 0.
fn trigonometric_factor(r: &SearchResult, k: &str) -> (String, Option<String>) {
    let s = &r.space;
    let name = |v: &Var| r.vars.variable(*v).unicode().to_string();
    let angles = match s.trig_degree {
        0 => &[][..],
        _ => r.variables.angles.as_slice(),
    };
    match angles {
        [] => (String::new(), None),
        [theta] => {
            let theta = name(theta);
            (
                format!(" times `1, cos {k}{theta}, sin {k}{theta}`"),
                Some(format!("trigonometric order `{k} ≤ {}`", s.trig_degree)),
            )
        }
        angles => {
            let sum = |f: &dyn Fn(usize, &Var) -> String| {
                angles
                    .iter()
                    .enumerate()
                    .map(|(j, v)| f(j + 1, v))
                    .collect::<Vec<_>>()
            };
            let phase = sum(&|j, v| format!("{k}_{j} {}", name(v))).join(" + ");
            let order = sum(&|j, _| format!("|{k}_{j}|")).join(" + ");
            (
                format!(" times `1, cos({phase}), sin({phase})`"),
                Some(format!("trigonometric order `{order} ≤ {}`", s.trig_degree)),
            )
        }
    }
}

/// With parameters kept symbolic, what the coefficients are: polynomials in them of a bounded
/// degree.
fn symbolic_coefficients_text(r: &SearchResult) -> String {
    match &r.module {
        Some(m) => format!(
            ", coefficients polynomials of degree `≤ {}` in `{}`",
            r.space.parameters_degree,
            parameter_names(&r.vars, &m.parameters)
        ),
        None => String::new(),
    }
}

/// The radicals whose powers the space of `r` holds: none at `--radicals-degree 0`, where its
/// monomials are free of them (`s^c` with `|c| ≤ 0` described a space without `s`).
fn radicals_in_space(r: &SearchResult) -> impl Iterator<Item = Var> + '_ {
    r.vars.radicals().filter(|_| r.space.radicals_degree > 0)
}

/// The denominator atoms whose powers the space of `r` holds: none at
/// `--denominators-degree 0`, nor those the condition gives a value.
fn denominators_in_space(r: &SearchResult) -> impl Iterator<Item = Var> + '_ {
    r.vars
        .denominators()
        .filter(|v| r.space.denominators_degree > 0 && !r.variables.valued_denominators.contains(v))
}

/// With denominators or radicals, the note that a monomial equal as a function to a sum of
/// simpler ones is left out; of the denominators, only where one of the space's is no number
/// at the fixed values (`κ + 1` at `κ = 1` only multiplies, as a coefficient does).
fn dependent_monomials_text(r: &SearchResult) -> String {
    let first_radical = trigpoly::Expr::radicals(&r.vars)
        .ok()
        .and_then(|radicals| radicals.into_iter().next())
        .filter(|_| r.space.radicals_degree > 0);
    let numbers = denominator_numbers(r);
    let functions = denominators_in_space(r).any(|atom| !numbers.contains(&atom));
    match (!functions, first_radical) {
        (true, None) => String::new(),
        (false, _) => " (with denominators the monomials are not independent, \
                        `x/(x − y) − y/(x − y) = 1`: each one equal as a function to a sum of \
                        simpler ones is left out)"
            .to_string(),
        (true, Some((radical, radicand))) => format!(
            " (with radicals the monomials are not independent, `{}² = {radicand}`: each one \
             equal as a function to a sum of simpler ones is left out)",
            r.vars.variable(radical).unicode()
        ),
    }
}

/// The sentence that an angle's momentum (or a cyclic coordinate's) that the condition fixes
/// is left out of the space
/// (so is a Poisson variable it fixes), or nothing; of one it sets to a function of the others
/// (`M3 = −(M1 γ1 + M2 γ2)/γ3`), that they are the variables of the surface it describes.
fn left_out_text(r: &SearchResult) -> String {
    let names = |as_functions: bool| -> Vec<String> {
        r.variables
            .left_out
            .iter()
            .filter(|p| r.variables.left_out_as_functions.contains(p) == as_functions)
            .map(|p| format!("`{}`", r.vars.variable(*p).unicode()))
            .collect()
    };
    let constants = match names(false).as_slice() {
        [] => String::new(),
        [p] => format!(
            " {p} is left out: the condition fixes it, and every function of it is an integral."
        ),
        ps => format!(
            " {} are left out: the condition fixes them, and every function of them is an \
             integral.",
            ps.join(", ")
        ),
    };
    let functions = match names(true).as_slice() {
        [] => String::new(),
        [p] => format!(
            " {p} is left out: the condition sets it to a function of the other variables, \
             and the space's functions are functions of those, on the surface it describes."
        ),
        ps => format!(
            " {} are left out: the condition sets them to functions of the other variables, \
             and the space's functions are functions of those, on the surface it describes.",
            ps.join(", ")
        ),
    };
    constants + &functions
}

/// ` Functional rank: 4, the most a flow in 5 phase variables allows (maximal
/// superintegrability).`, the functional rank of a search's basis ([`basis_rank`]) as the
/// dimension line says it: the number and why nothing larger is possible (the flow's bound,
/// the number of integrals or of coordinates, how many bordering minors vanish, or what
/// generates every integral and its rank: [`generated_text`]), or `at
/// least` the lower bound; on a level set, said where it is taken (as `--find-values` takes
/// it). The certificate's minor and point are in JSON (`functional_rank_bound`).
fn functional_rank_text(
    rank: &BoundedRank,
    space: &PhaseSpace,
    r: &SearchResult,
    shared: &Shared,
) -> String {
    // A condition that fixes a momentum leaves it out: the rank is that where it holds.
    let taken = match (&r.on, level_set_graph_variable(space, r)) {
        (None, _) if r.variables.left_out.is_empty() => "",
        (None, _) => " where the condition holds",
        (Some(_), Some(_)) => " on the level set",
        (Some(_), None) => " in the whole phase space, not on the level set",
    };
    let BoundedRank::Exact(cert) = rank else {
        return format!(" Functional rank: {rank}{taken}.");
    };
    let k = cert.rank;
    let why = match cert.upper {
        _ if k == 0 => " (every integral is a constant)".to_string(),
        UpperBound::Flow => {
            let n = cert.coordinates.len();
            let within = match n < space.coordinates().len() {
                true => format!("on the {n}-dimensional level set"),
                false => format!("in {n} phase variables"),
            };
            return format!(
                " Functional rank: {k}, the most a flow {within} allows (maximal \
                 superintegrability)."
            );
        }
        UpperBound::VanishingMinors { count } => {
            format!(" (certified by {})", counted(count, "vanishing minor"))
        }
        // What generates every integral ([`basis_rank`]).
        UpperBound::Generated { .. } => generated_text(r, shared, k),
        _ if k == r.basis.len() => format!(" (all {k} integrals independent)"),
        _ => " (as many as the phase variables)".to_string(),
    };
    format!(" Functional rank: {k}{taken}{why}.")
}

/// Why the rank is at most `k` where what generates every integral has that rank
/// ([`brackets::search::BasisGenerators`]): ` (the known integrals `H` and `L` generate every
/// integral, and their rank is 2)`, with the new ones where there are some, or ` (every
/// integral is a combination of `I1` and `I11` with coefficients rational in `A, B, C`, and
/// their rank is 1)` (rational: `(1 − R)⁻¹ C`, as `BasisGenerators::Module` says).
fn generated_text(r: &SearchResult, shared: &Shared, k: usize) -> String {
    let labels = |indices: &[usize]| -> Vec<String> {
        (indices.iter())
            .map(|&i| format!("`{}`", shared.label(i)))
            .collect()
    };
    let (their, what) = match (&r.new, &r.module, &shared.symbolic) {
        (Some(n), _, _) => {
            let known = (n.known.iter()).map(|name| format!("`{name}`"));
            let named = |what: &str, names: Vec<String>| match names.len() {
                0 => None,
                1 => Some(format!("the {what} integral {}", listed(&names))),
                _ => Some(format!("the {what} integrals {}", listed(&names))),
            };
            let both = [
                named("known", known.collect()),
                named("new", labels(&n.new)),
            ]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
            .join(" and ");
            match n.known.len() + n.new.len() {
                1 => ("its", format!("{both} generates every integral")),
                _ => ("their", format!("{both} generate every integral")),
            }
        }
        (None, Some(m), Some(names)) => (
            if m.generators.len() == 1 {
                "its"
            } else {
                "their"
            },
            format!(
                "every integral is a combination of {} with coefficients rational in `{names}`",
                listed(&labels(&m.generators))
            ),
        ),
        _ => return String::new(),
    };
    format!(" ({what}, and {their} rank is {k})")
}

/// ` By degree in the momenta: ≤ 0: 1, ≤ 1: 6.`, `dims[j]` integrals of degree `≤ j` (`what`:
/// in the momenta, in the Poisson variables).
fn dimensions_text(what: &str, dims: &[usize]) -> String {
    let dims: Vec<String> = dims
        .iter()
        .enumerate()
        .map(|(j, d)| format!("`≤ {j}`: {d}"))
        .collect();
    format!(" By degree {what}: {}.", dims.join(", "))
}

/// The lines `Momenta degree exactly j: 2 of order 0, 1 of order 1.` of a search's report
/// (`exactly(j)` their start), `counts[j][k]` integrals of degree `j` and trigonometric order
/// `k` (said only when the system has `angles`), for each `j` with any.
fn degree_counts(
    counts: &[Vec<usize>],
    angles: bool,
    exactly: impl Fn(usize) -> String,
) -> Vec<String> {
    let mut lines = Vec::new();
    for (j, row) in counts.iter().enumerate() {
        let parts: Vec<String> = row
            .iter()
            .enumerate()
            .filter(|(_, c)| **c > 0)
            .map(|(k, c)| match angles {
                true => format!("{c} of order {k}"),
                false => c.to_string(),
            })
            .collect();
        if !parts.is_empty() {
            lines.push(format!("{}: {}.", exactly(j), parts.join(", ")));
        }
    }
    lines
}

/// What a proof covers, when it is not every value of every parameter: `fixed` is the text
/// of the fixed values, `symbolic` the names of the parameters kept symbolic (if any).
fn proof_note(f: &Integral, fixed: &str, symbolic: Option<&str>) -> Option<String> {
    match (&f.symbolic, f.proved_fixed, symbolic) {
        (Some(_), _, _) => None,
        (None, true, Some(names)) => Some(proved_for_every(names, fixed)),
        (None, true, None) => Some("not lifted back to the parameters (no symbolic lift)".into()),
        (None, false, _) => Some("not proved".into()),
    }
}

/// A note on `H` (under the search's condition) when the space cannot hold it, or when its
/// powers need a larger degree in the parameters kept symbolic than the space's.
fn hamiltonian_note(
    system: &System,
    options: &SearchOptions,
    caller: Caller,
) -> Result<Option<Entry>, EngineError> {
    let h = match &options.condition {
        Some(c) => c.apply(system.hamiltonian())?,
        None => system.hamiltonian().clone(),
    };
    if let Some(why) = options.space.why_outside(&h) {
        return Ok(Some(Entry::Text(format!(
            "Note: `H` is not in this space ({why}), so `H` is not among the integrals found, \
             nor is any that needs its terms."
        ))));
    }
    Ok(power_past_parameters_degree(&h, options, caller).map(Entry::Text))
}

/// A hint where the search found no integral but the powers of `H` in its space, and where a
/// larger positions degree would hold every weighted-homogeneous polynomial that this one
/// cuts short: `H` (under the condition, at the fixed values) weighted-homogeneous with
/// integer weights `w_x` for every coordinate and `w_p` for every momentum, so that each
/// integral is a sum of weighted-homogeneous ones (the bracket with `H` keeps the weight's
/// grading), and every polynomial of weight `≤ w_p m` with momenta degree `≤ m` has positions
/// degree `≤ ⌊w_p m / w_x⌋`; one of greater weight `W` (coordinates in its terms of top
/// momenta degree) may need up to `⌊W / w_x⌋`, and no bound holds them all, so the hint names
/// the weights it covers, and those this space rules out (`≤ w_x n`, `n` its positions
/// degree): the quartic potentials at `a = 6, b = 8` (weights 1 and 2),
/// searched at momenta degree 4 and positions degree 4, find `1` and `H` alone, and at
/// positions degree 8 their quartic integral. None with angles, Poisson variables,
/// denominators, radicals, negative powers, parameters kept symbolic, `--new-only` or a
/// level set, nor where no such weights make `H` homogeneous or they are not determined
/// (`p²/2` alone).
fn positions_degree_hint(
    system: &System,
    options: &SearchOptions,
    r: &SearchResult,
    caller: Caller,
) -> Option<Entry> {
    if r.module.is_some() || r.new.is_some() || r.on.is_some() || options.space.laurent {
        return None;
    }
    let vars = system.vars();
    let kinds: Vec<VarKind> = vars.vars().map(|v| vars.variable(v).kind()).collect();
    let phase_or_parameter = |k: &VarKind| {
        matches!(
            k,
            VarKind::Coordinate | VarKind::Momentum | VarKind::Parameter
        )
    };
    if !kinds.iter().all(phase_or_parameter) {
        return None;
    }
    let h = match &options.condition {
        Some(c) => c.apply(system.hamiltonian()).ok()?,
        None => system.hamiltonian().clone(),
    };
    let h = fix_parameters(&h, &r.parameters).ok()?;
    // Each term's degrees (positions, momenta); a constant moves nothing.
    let mut degrees: Vec<(i64, i64)> = Vec::new();
    for t in h.terms() {
        let (mut n, mut m) = (0, 0);
        for (k, &e) in kinds.iter().zip(&t.exponents()) {
            match (k, e) {
                (_, 0) => {}
                (_, e) if e < 0 => return None,
                (VarKind::Coordinate, e) => n += e,
                (VarKind::Momentum, e) => m += e,
                _ => return None,
            }
        }
        if (n, m) != (0, 0) && !degrees.contains(&(n, m)) {
            degrees.push((n, m));
        }
    }
    // `w_x n + w_p m` the same for every term, with `w_x, w_p > 0` coprime.
    let (&(n0, m0), rest) = degrees.split_first()?;
    let &(n1, m1) = rest.first()?;
    let (dn, dm) = (n1 - n0, m1 - m0);
    if dn * dm >= 0 {
        return None;
    }
    let g = num_integer::Integer::gcd(&dn, &dm);
    let (w_x, w_p) = (dm.abs() / g, dn.abs() / g);
    let weight = w_x * n0 + w_p * m0;
    if rest.iter().any(|&(n, m)| w_x * n + w_p * m != weight) {
        return None;
    }
    // The powers of `H` in the space: `H^k` has positions degree `k n_H` and momenta degree
    // `k m_H` (the top-degree parts of a product of polynomials do not cancel), and they are
    // independent integrals; a basis of no more integrals is theirs.
    let space = &options.space;
    let (momenta, positions) = (space.momenta_degree as i64, space.positions_degree as i64);
    let n_h = degrees.iter().map(|d| d.0).max()?;
    let m_h = degrees.iter().map(|d| d.1).max()?;
    let powers = (0..)
        .take_while(|k| k * n_h <= positions && k * m_h <= momenta)
        .count();
    let needed = w_p * momenta / w_x;
    if r.basis.len() != powers || needed <= positions {
        return None;
    }
    let option = caller.names("--positions-degree", "SearchSpace::positions_degree");
    let held = w_x * positions;
    let up_to = match w_x {
        1 => "W".to_string(),
        _ => format!("⌊W/{w_x}⌋"),
    };
    Some(Entry::Text(format!(
        "Only the powers of `H` are in this space. `H` is weighted-homogeneous (the \
         coordinates of weight {w_x}, the momenta of weight {w_p}), so every integral is a sum \
         of weighted-homogeneous ones, and this space holds every polynomial of momenta degree \
         `≤ {momenta}` and weight `≤ {held}`: there is no integral of momenta degree \
         `≤ {momenta}` and weight `≤ {held}` but the powers of `H`. Of momenta degree \
         `≤ {momenta}`, those of weight `≤ {}` are held by `{option} {needed}`, and one of a \
         greater weight `W` needs positions degree up to `{up_to}`.",
        w_p * momenta
    )))
}

/// The report of [`search`]: the space, the dimensions by degree, a basis (or, with
/// `new_only`, a complement of what known integrals generate) written like the paper, and
/// every basis element proved. `name` is the system as a title names it, its article
/// included where it takes one: `the harmonic rotor`, `my oscillator`
/// ([`crate::report::with_article`] adds one), `t1`. Its advice names the library's options
/// (`SearchOptions::symbolic`); [`search_report_for`] chooses the caller.
pub fn search_report(
    name: &str,
    system: &System,
    options: &SearchOptions,
) -> Result<(Report, SearchResult), EngineError> {
    search_report_for(name, system, options, Caller::Program)
}

/// [`search_report`] built for `caller`: its advice names the command line's options
/// (`--symbolic`) for [`Caller::CommandLine`], as `superint search` prints it.
///
/// ```
/// use superint::brackets::search::{SearchOptions, SearchSpace};
/// use superint::brackets::systems;
/// use superint::discovery::search_report_for;
/// use superint::system_file::Caller;
///
/// let rotor = systems::harmonic_rotor();
/// let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1).trig_degree(1));
/// let (report, _) = search_report_for("the harmonic rotor", &rotor, &options, Caller::CommandLine)?;
/// assert_eq!(report.caller, Caller::CommandLine);
/// # Ok::<(), superint::brackets::EngineError>(())
/// ```
pub fn search_report_for(
    name: &str,
    system: &System,
    options: &SearchOptions,
    caller: Caller,
) -> Result<(Report, SearchResult), EngineError> {
    search_report_with(name, system, options, caller, None, true)
}

/// [`search_report_for`] of a system file's system, with each integral it shows restated
/// below it as a polynomial in `H`, the file's functions and the instances of its families
/// that are integrals too, where it is one
/// ([`LoadedSystem::integrals_in_functions_and_instances`]): what `superint search FILE`
/// prints, `I91 = −8 Q_{1,2}` for the Fock–Darwin search at `a = 2b`; and each amplitude
/// `A` of an integral `Re(A e^{−ikθ})` as a polynomial in `H` and the functions
/// ([`LoadedSystem::amplitudes_in_functions`]), `A7 = Z_y` for the 3D rotor at `Ω = ω`. Its
/// sections are about the file ([`Section::file`](crate::report::Section::file)), as
/// [`file_closure_report`](super::file_closure_report)'s are.
///
/// ```
/// use superint::brackets::search::{SearchOptions, SearchSpace};
/// use superint::discovery::file_search_report;
/// use superint::render::{render, Format, Options};
/// use superint::system_file::{load, Caller, LimitsOverride};
///
/// let fd = load("systems/fock-darwin.toml", &LimitsOverride::default())?;
/// let space = SearchSpace::default().momenta_degree(3).positions_degree(3).parameters_degree(6);
/// let [m, b] = ["M", "b"].map(|p| fd.system().vars().lookup(p).unwrap());
/// let options = SearchOptions::new(space).when(fd.condition("a = 2*b")?);
/// let options = options.symbolic(m).symbolic(b).new_only();
/// let (report, _) = file_search_report(&fd, &options, Caller::Program)?;
/// let text = render(&report, Format::Text, &Options::reproducible());
/// assert!(text.contains("= −8 Q_{1,2}") && text.contains("= 8 P_{1,2}"));
/// assert!(report.sections.iter().all(|s| s.file.as_deref() == Some("systems/fock-darwin.toml")));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn file_search_report(
    file: &LoadedSystem,
    options: &SearchOptions,
    caller: Caller,
) -> Result<(Report, SearchResult), EngineError> {
    let restate = Restate {
        file,
        condition: options.condition.as_ref(),
    };
    let (report, r) = search_report_with(
        &file.the_name(),
        file.system(),
        options,
        caller,
        Some(&restate),
        true,
    )?;
    // Its sections about the file, as a closure's report of a file and every report of
    // `system_file` mark theirs: of several files' reports, a reader tells each one's file.
    Ok((report.about_file(&file.source().origin), r))
}

/// The report `superint search` prints in `format`: [`file_search_report`] of `file`'s
/// system where there is a file (its sections not yet marked with the file, which the
/// command line marks for every report), else [`search_report_for`] of `system`, named
/// `name`, both for [`Caller::CommandLine`]. What only JSON shows (the search's facts for programs, and
/// each integral's claim as text to read back) is formed for JSON alone: the other formats
/// leave it out, and forming it was a sixth of the text report of a search at 1:1, degree 12
/// (its 3185 integrals written as ASCII text, and its counts by degree in the Poisson
/// variables, by exact linear algebra, where the space has none).
pub fn command_line_search_report(
    file: Option<&LoadedSystem>,
    name: &str,
    system: &System,
    options: &SearchOptions,
    format: Format,
) -> Result<(Report, SearchResult), EngineError> {
    searched_and_reported(system, options, |r| {
        command_line_report_of(file, name, system, options, format, r, None)
    })
}

/// [`command_line_search_report`] of the search `r` already run with `options`: the report
/// of what it found, as that search's, with no search again (`superint search
/// --find-values` shows the searches that confirmed its values so, with the parameter it
/// solves for as `solved`, whose other values its advice does not propose, beside the
/// functional rank it took of the basis, shown as it is). Its time is
/// that of the report alone.
pub fn command_line_report_of(
    file: Option<&LoadedSystem>,
    name: &str,
    system: &System,
    options: &SearchOptions,
    format: Format,
    r: &SearchResult,
    solved: Option<(Var, &BoundedRank)>,
) -> Result<Report, EngineError> {
    let restate = file.map(|file| Restate {
        file,
        condition: options.condition.as_ref(),
    });
    let facts = format == Format::Json;
    report_of(
        (name, system),
        options,
        (Caller::CommandLine, restate.as_ref(), facts, solved),
        r,
    )
}

/// How [`Restate::restated`] restates expressions of a file at a condition: one form (or
/// none) for each.
type RestateWith = fn(&LoadedSystem, &[Expr], Option<&brackets::Condition>) -> Vec<Option<Expr>>;

/// How a search's shown integrals, and the amplitudes of their complex forms, are restated
/// below them: each as a polynomial in the file's named functions where it is one, at the
/// search's condition, and, for one not lifted back to the parameters the search fixed, at
/// their values too, where alone it holds (`I2 = 2 H` at `a = 12, b = 16` of the quartic
/// potentials). One lifted holds for every value and is restated for every value or not at
/// all: at the fixed values it could equal a function that is no integral elsewhere.
struct Restate<'a> {
    file: &'a LoadedSystem,
    condition: Option<&'a brackets::Condition>,
}

impl Restate<'_> {
    /// The search's condition with the values of the parameters `r` fixed (`text` how it
    /// reads), where an integral not lifted holds; `None` where nothing is fixed, or where
    /// the two are no substitution together (then every one is restated at the condition
    /// alone, an identity still).
    fn at_fixed_values(&self, r: &SearchResult, text: &str) -> Option<brackets::Condition> {
        if r.parameters.is_empty() {
            return None;
        }
        let fixed = (r.parameters.iter())
            .map(|(v, value)| (*v, Expr::constant(&r.vars, value.clone().into())));
        let subs = (self.condition.iter())
            .flat_map(|c| c.subs().iter().cloned())
            .chain(fixed)
            .collect();
        brackets::Condition::all(text, subs).ok()
    }

    /// Whether `form`, the restatement at the fixed values of an integral not lifted (a
    /// polynomial in `H`, the file's functions and its families' instances, with numeric
    /// coefficients), is an integral for every value: `form` read back with the file's
    /// functions as written, the parameters symbolic, and `{form, H} = 0` decided exactly at
    /// the search's condition alone, not at the fixed values. That is sound: the
    /// restatement was proved equal to the integral at the fixed values (and the condition),
    /// so where this holds the integral is the value there of `form`, an integral for every
    /// value; nothing else is claimed (the integral as found need not be one elsewhere). A
    /// coefficient that stands for a parameter's value (`49` for `ω²` at `ω = 7`) reads
    /// back as that number, and the check fails; so does a limit hit (`false`, never an
    /// error).
    fn integral_for_every_value(&self, form: &Expr) -> bool {
        let Ok(e) = self.file.parse(&form.render(Style::Ascii)) else {
            return false;
        };
        let system = self.file.system();
        let flow = match self.condition {
            Some(c) => system.flow_when(&e, c),
            None => system.flow(&e),
        };
        flow.is_ok_and(|f| f.vanishes().unwrap_or(false))
    }

    /// Each of `items` restated by `restate` (the shown integrals by
    /// [`LoadedSystem::integrals_in_functions_and_instances`], their amplitudes by
    /// [`LoadedSystem::amplitudes_in_functions`]) at the condition, but those of `unlifted`
    /// at `at_fixed` ([`Restate::at_fixed_values`]) where it is given; none of more than
    /// [`MAX_RESTATED`] items, as `restate` of them all would restate none.
    fn restated(
        &self,
        items: &[Expr],
        unlifted: &[bool],
        at_fixed: Option<&brackets::Condition>,
        restate: RestateWith,
    ) -> Vec<Option<Expr>> {
        let Some(at_fixed) = at_fixed else {
            return restate(self.file, items, self.condition);
        };
        if items.len() > MAX_RESTATED {
            return vec![None; items.len()];
        }
        let of = |kind: bool, at: Option<&brackets::Condition>| {
            let these: Vec<Expr> = (items.iter().zip(unlifted))
                .filter(|(_, &u)| u == kind)
                .map(|(e, _)| e.clone())
                .collect();
            match these.is_empty() {
                true => Vec::new(),
                false => restate(self.file, &these, at),
            }
            .into_iter()
        };
        let (mut lifted, mut at_values) = (of(false, self.condition), of(true, Some(at_fixed)));
        (unlifted.iter())
            .map(|&u| match u {
                true => at_values.next().flatten(),
                false => lifted.next().flatten(),
            })
            .collect()
    }
}

/// [`search_report_for`], with the shown integrals (and their amplitudes) restated by
/// `restate` where one is given, and with what only JSON shows where `facts` ([`Shared::facts`]).
fn search_report_with(
    name: &str,
    system: &System,
    options: &SearchOptions,
    caller: Caller,
    restate: Option<&Restate<'_>>,
    facts: bool,
) -> Result<(Report, SearchResult), EngineError> {
    searched_and_reported(system, options, |r| {
        report_of((name, system), options, (caller, restate, facts, None), r)
    })
}

/// The search of `system` with `options`, and its report by `report`, whose time is that of
/// both.
fn searched_and_reported(
    system: &System,
    options: &SearchOptions,
    report: impl FnOnce(&SearchResult) -> Result<Report, EngineError>,
) -> Result<(Report, SearchResult), EngineError> {
    let start = Instant::now();
    let r = search(system, options)?;
    let mut report = report(&r)?;
    report.seconds = start.elapsed().as_secs_f64();
    Ok((report, r))
}

/// The report of the search `r` of `system`, named `name`, run with `options`, as
/// [`search_report_with`] says (its time that of the report alone).
fn report_of(
    (name, system): (&str, &System),
    options: &SearchOptions,
    (caller, restate, facts, solved): (Caller, Option<&Restate<'_>>, bool, Solved<'_>),
    r: &SearchResult,
) -> Result<Report, EngineError> {
    let start = Instant::now();
    // The file's families, whose names the labels' letters avoid as the functions'.
    let families: Vec<&str> = (restate.iter())
        .flat_map(|r| r.file.family_names())
        .collect();
    let shared = Shared::new(system, &families, options, r, (caller, solved), facts);
    let forms = shared.shown_forms(r, restate)?;
    let sections = vec![
        shared.search_section(system, options, r, &forms)?,
        shared.basis_section(r, restate, &forms)?,
    ];
    let mut when = r
        .condition
        .as_ref()
        .map(|c| format!(" at `{c}`"))
        .unwrap_or_default();
    if let Some(on) = &r.on {
        when += &format!(" on the level set `{}`", level_set_shown(on));
    }
    Ok(Report {
        title: format!("Integrals of {}{when}", name),
        subtitle: String::new(),
        sections,
        summary: SummaryKind::Claims,
        seconds: start.elapsed().as_secs_f64(),
        caller,
    })
}

/// The shown integrals of a search as written, and restated in a file's functions where
/// there is a file ([`Restate`]): at the condition, or, for one not lifted, at the fixed
/// values where it holds, and then lifted through that restatement where it is an integral
/// for every value ([`Restate::integral_for_every_value`]).
struct ShownForms {
    /// Each shown integral as written ([`written_forms`]).
    written: Vec<Expr>,
    /// Each one's restatement, where it has one (empty without a file).
    restated: Vec<Option<Expr>>,
    /// Where each restatement holds when only at the fixed values (JSON's `holds_at`).
    holds_at: Vec<Option<String>>,
    /// Whether each one, not lifted, is lifted through its restatement (empty, as the
    /// restatements are, without a file).
    through: Vec<bool>,
    /// The condition with the fixed values, where those not lifted are restated, and as
    /// superint reads it back.
    at_fixed: Option<(brackets::Condition, String)>,
}

impl ShownForms {
    /// The number of basis integrals lifted through their restatements.
    fn lifted_through(&self) -> usize {
        self.through.iter().filter(|&&t| t).count()
    }
}

/// The parameter a `--find-values` run solves for and the functional rank it took of the
/// search's basis ([`command_line_report_of`]).
type Solved<'a> = Option<(Var, &'a BoundedRank)>;

/// What the two sections of a search's report share: where the integrals hold, the names of
/// the parameters kept symbolic, the letters of the integrals' labels and which integrals
/// are shown.
struct Shared {
    /// Where the integrals hold: the condition and the fixed parameters' values.
    held: HeldAt,
    /// The parameters kept symbolic, named (`M, ω`), if any.
    symbolic: Option<String>,
    /// The letter of the integrals' labels, `I1, I2, …`, one the system does not use.
    letter: &'static str,
    /// The letter of their complex forms, `A1, …`.
    complex: &'static str,
    /// The letter of the quotients on a level set, `Q1, …`.
    quotient: &'static str,
    /// The integrals shown (all, the new ones, or the generators), by index in the basis.
    shown: Vec<usize>,
    /// The system's names in LaTeX.
    names: Names,
    /// Who the report is for, whose options its advice names.
    caller: Caller,
    /// The parameter a `--find-values` run solves for, whose other values the advice does
    /// not propose, and the functional rank that run took of the basis, shown as it is
    /// (`None` in an ordinary search).
    solved: Option<(Var, BoundedRank)>,
    /// Whether the report holds what only JSON shows: the search's facts
    /// ([`Shared::search_facts`]) and each integral's claim as text to read back.
    facts: bool,
}

impl Shared {
    /// The report's shared parts, its labels' letters naming nothing of `system` nor `taken`.
    fn new(
        system: &System,
        taken: &[&str],
        options: &SearchOptions,
        r: &SearchResult,
        (caller, solved): (Caller, Solved<'_>),
        facts: bool,
    ) -> Self {
        let vars = system.vars();
        Shared {
            held: HeldAt::new(options.condition.as_ref(), vars, &r.parameters),
            symbolic: r
                .module
                .as_ref()
                .map(|m| parameter_names(vars, &m.parameters)),
            letter: label_letter(system, taken, &["I", "J", "Φ", "Ξ"], r.basis.len()),
            complex: label_letter(system, taken, &["A", "B", "Ψ", "Λ"], r.basis.len()),
            quotient: label_letter(system, taken, &["Q", "R", "Ω", "Π"], r.basis.len()),
            shown: shown_integrals(r),
            names: Names::of_system(system),
            caller,
            solved: solved.map(|(v, rank)| (v, rank.clone())),
            facts,
        }
    }

    /// The label of basis integral `i`: `I3`.
    fn label(&self, i: usize) -> String {
        format!("{}{}", self.letter, i + 1)
    }

    /// Section 1: `H`, the space searched, notes on `H` and the parameters, the dimensions of
    /// the integrals by degree, and the facts for JSON where the report holds them.
    fn search_section(
        &self,
        system: &System,
        options: &SearchOptions,
        r: &SearchResult,
        forms: &ShownForms,
    ) -> Result<Section, EngineError> {
        let vars = system.vars();
        // Under a condition on the parameters alone (`a = 2b`), H as the search takes it, as
        // the title's `at a = 2b` says; one that fixes a momentum (`p_θ = Iω`) is applied to
        // the brackets, so H is shown whole.
        let h = system.hamiltonian();
        let h = match &options.condition {
            Some(c)
                if c.subs()
                    .iter()
                    .all(|(v, _)| vars.variable(*v).kind() == VarKind::Parameter) =>
            {
                c.apply(h)?
            }
            _ => h.clone(),
        };
        let mut entries = vec![
            Entry::Equations(Equations::new(String::new(), vec![Equation::new("H", h)])),
            Entry::Text(space_text(r)),
        ];
        entries.extend(
            (r.on.as_ref()).map(|on| Entry::Text(level_set_text(on, !r.parameters.is_empty()))),
        );
        entries.extend(hamiltonian_note(system, options, self.caller)?);
        // Those lifted through their restatements count with those that hold as found.
        let through = forms.lifted_through();
        let for_every_value = (0..r.basis.len())
            .filter(|&i| r.for_every_value(i).is_some())
            .count()
            + through;
        entries.extend(parameter_notes(
            r,
            system,
            self.held.fixed(),
            (for_every_value, through),
            (self.caller, self.solved.as_ref().map(|(v, _)| *v)),
        ));
        entries.extend(self.symbolic_note());
        // The rank of the basis found; a search whose rank cannot be certified (a denominator
        // vanishing at every sample point) is shown without it.
        // A `--find-values` run's own, else taken here; where it is not exact, the known
        // integrals' generation decided bounds it (the search reports the basis as it was,
        // without the new integrals' section).
        let rank_of = |r: &SearchResult| basis_rank(system, options, r, SEARCH_RANK_MINORS).ok();
        let mut rank = match &self.solved {
            Some((_, rank)) => Some(rank.clone()),
            None => (!r.basis.is_empty()).then(|| rank_of(r)).flatten(),
        };
        let decided = (rank.as_ref())
            .filter(|rank| self.solved.is_none() && !rank.is_exact())
            .and_then(|_| generation_decided(system, options, r));
        if let Some(better) = decided.as_ref().and_then(rank_of) {
            rank = Some(better);
        }
        let ranked = decided.as_ref().unwrap_or(r);
        let rank_text = rank
            .as_ref()
            .map(|rank| functional_rank_text(rank, system.space(), ranked, self))
            .unwrap_or_default();
        entries.extend(self.dimensions(r, vars, &rank_text));
        entries.extend(positions_degree_hint(system, options, r, self.caller));
        if self.facts {
            entries.push(self.search_facts(r, vars, for_every_value, rank.as_ref()));
        }
        Ok(Section {
            number: 1,
            title: "Search".into(),
            file: None,
            entries,
            names: self.names.clone(),
        })
    }

    /// What keeping parameters symbolic means for the equations, when some are.
    fn symbolic_note(&self) -> Option<Entry> {
        let names = self.symbolic.as_ref()?;
        Some(Entry::Text(format!(
            "Parameters kept symbolic: `{names}`. The equations are the coefficients of \
             every monomial in the variables and these parameters, so what is found holds \
             for every value of them."
        )))
    }

    /// The dimension of the space of integrals, by degree in the momenta and in the Poisson
    /// variables, its functional rank (`rank`, its sentence), and the lines counting the
    /// integrals of each exact degree.
    fn dimensions(&self, r: &SearchResult, vars: &Vars, rank: &str) -> Vec<Entry> {
        let over = match &self.symbolic {
            // With symbolic parameters the space is over Q, and `M·I` counts apart from `I`.
            Some(_) => " over `Q` (a parameter's multiple of an integral counts apart from it)",
            None => "",
        };
        // By degree in the momenta, unless the space has Poisson variables and no momenta;
        // and in the Poisson variables when it has them.
        let poisson = !r.variables.poisson.is_empty();
        let by_momenta = !poisson || !r.variables.momenta.is_empty();
        let angles = vars.angles().next().is_some();
        let mut by_degree = String::new();
        let mut exactly = Vec::new();
        if by_momenta {
            by_degree += &dimensions_text("in the momenta", &r.dimensions_by_momenta_degree());
            exactly.extend(degree_counts(&r.counts(), angles, |j| {
                format!("Momenta degree exactly {j}")
            }));
        }
        if poisson {
            by_degree += &dimensions_text(
                "in the Poisson variables",
                &r.dimensions_by_poisson_degree(),
            );
            exactly.extend(degree_counts(&r.poisson_counts(), angles, |j| {
                format!("Degree exactly {j} in the Poisson variables")
            }));
        }
        let mut entries = vec![Entry::Text(format!(
            "Dimension of the space of integrals{over}: {}.{by_degree}{rank}",
            r.basis.len(),
        ))];
        entries.extend(exactly.into_iter().map(Entry::Text));
        entries
    }

    /// The search's facts for JSON: the space, its variables by kind, the parameters, the
    /// size of the linear algebra, the dimensions and counts, and the integrals shown.
    fn search_facts(
        &self,
        r: &SearchResult,
        vars: &Vars,
        for_every_value: usize,
        rank: Option<&BoundedRank>,
    ) -> Entry {
        let name_of = |v: &Var| vars.variable(*v).name().to_string();
        let names_of = |vs: &[Var]| vs.iter().map(name_of).collect::<Vec<_>>();
        Entry::Data(Facts::Search(Box::new(SearchFacts {
            space: r.space,
            coordinates: names_of(&r.variables.coordinates),
            momenta: names_of(&r.variables.momenta),
            poisson: names_of(&r.variables.poisson),
            angles: names_of(&r.variables.angles),
            left_out: names_of(&r.variables.left_out),
            left_out_as_functions: names_of(&r.variables.left_out_as_functions),
            valued_denominators: names_of(&r.variables.valued_denominators),
            parameters: parameter_facts(
                vars,
                &r.parameters,
                r.module
                    .as_ref()
                    .map(|m| (&m.parameters[..], r.space.parameters_degree)),
                &r.condition,
            ),
            unknowns: r.unknowns,
            equations: r.equations,
            blocks: r.components,
            largest_block: r.largest_component,
            dimension: r.basis.len(),
            functional_rank: rank.cloned(),
            by_momenta_degree: r.dimensions_by_momenta_degree(),
            counts: r.counts(),
            by_poisson_degree: r.dimensions_by_poisson_degree(),
            poisson_counts: r.poisson_counts(),
            for_every_value,
            shown: self.shown.iter().map(|&i| self.label(i)).collect(),
            generators: (r.module.as_ref())
                .map(|m| m.generators.iter().map(|&i| self.label(i)).collect()),
            new_only: r.new.clone(),
            level_set: r.on.as_ref().map(|on| LevelSetFacts {
                text: on.level.text.clone(),
                polynomial: on.polynomial.render(Style::Ascii),
                leading_monomial: on.leading_monomial.render(Style::Ascii),
                left_out: on.left_out,
                normal_form_outside: on.normal_form_outside.as_ref().map(|o| {
                    (
                        o.function.render(Style::Ascii),
                        o.normal_form.render(Style::Ascii),
                    )
                }),
            }),
        })))
    }

    /// The shown integrals as written, and restated in the file's functions where `restate`
    /// is given ([`ShownForms`]).
    fn shown_forms(
        &self,
        r: &SearchResult,
        restate: Option<&Restate<'_>>,
    ) -> Result<ShownForms, EngineError> {
        let written = written_forms(r, &self.shown)?;
        // Each in the file's functions and family instances too, where it is a polynomial
        // in them.
        // One not lifted, where it holds: at the fixed values.
        let unlifted: Vec<bool> = (self.shown.iter())
            .map(|&i| r.for_every_value(i).is_none())
            .collect();
        // That condition, and as superint reads it back, for JSON's `holds_at`.
        let at_fixed = restate.and_then(|f| {
            let (text, ascii) = self.held.at(true)?;
            Some((f.at_fixed_values(r, &text)?, ascii))
        });
        let restated = (restate.map(|f| {
            f.restated(
                &written,
                &unlifted,
                at_fixed.as_ref().map(|(c, _)| c),
                LoadedSystem::integrals_in_functions_and_instances,
            )
        }))
        .unwrap_or_default();
        // Where each restatement holds when only at the fixed values.
        let holds_at: Vec<Option<String>> = (unlifted.iter().zip(&restated))
            .map(|(&u, w)| match (&at_fixed, u && w.is_some()) {
                (Some((_, ascii)), true) => Some(ascii.clone()),
                _ => None,
            })
            .collect();
        // Lifted through its restatement at the fixed values where that, read with the
        // parameters symbolic, is an integral for every value: then it holds for every value.
        let through: Vec<bool> = (holds_at.iter().zip(&restated))
            .map(|(at, w)| match (restate, at, w) {
                (Some(f), Some(_), Some(w)) => f.integral_for_every_value(w),
                _ => false,
            })
            .collect();
        let holds_at = (holds_at.into_iter().zip(&through))
            .map(|(at, &t)| at.filter(|_| !t))
            .collect();
        Ok(ShownForms {
            written,
            restated,
            holds_at,
            through,
            at_fixed,
        })
    }

    /// Section 2: the basis (or the new part; with symbolic parameters, its generators) as
    /// written, their complex forms, and a proof of each, with one for the rest.
    fn basis_section(
        &self,
        r: &SearchResult,
        restate: Option<&Restate<'_>>,
        forms: &ShownForms,
    ) -> Result<Section, EngineError> {
        let mut entries = Vec::new();
        entries.extend(self.generators_note(r));
        if let Some(n) = &r.new {
            entries.push(Entry::Text(new_integrals_text(r, n)));
        }
        // With denominators, each integral written as a physicist writes it: its terms
        // collected by momenta and parameters over common denominators, reduced (the linear
        // algebra's monomials are not independent, and its combination of them can be long).
        // The same element.
        // With radicals only, each integral as the search chose its monomials (results.md
        // §13: no `r²` where a polynomial is, so the monomials show), unless it has fewer
        // terms with the least powers of its radicals (`2β/(xr) − 2βr/(xy²)` is
        // `−2βx/(y²r)`).
        let ShownForms {
            written,
            restated,
            holds_at,
            at_fixed,
            ..
        } = forms;
        entries.push(self.shown_equations(r, written, restated, holds_at));
        let (complex, amplitudes_at_fixed) = match self.complex_forms(r, restate, at_fixed.as_ref())
        {
            Some((entry, labels)) => (Some(entry), labels),
            None => (None, Vec::new()),
        };
        entries.extend(complex);
        let at_fixed_labels: Vec<String> = (self.shown.iter().zip(holds_at))
            .filter(|(_, at)| at.is_some())
            .map(|(&i, _)| self.label(i))
            .chain(amplitudes_at_fixed)
            .collect();
        entries.extend(self.restated_at_fixed_note(&at_fixed_labels));
        entries.extend(self.lifted_through_note(forms));
        entries.extend(self.quotients(r));
        entries.extend(self.integral_claims(r, forms));
        entries.extend(self.rest_proved(r));
        Ok(Section {
            number: 2,
            title: if r.new.is_some() {
                "New integrals".into()
            } else {
                "Basis".into()
            },
            file: None,
            entries,
            names: self.names.clone(),
        })
    }

    /// With parameters kept symbolic, which of the basis integrals generate all of them over
    /// the polynomials in the parameters, by their labels (`I1`, `I3`), and what is shown
    /// below: with `--new-only` the new integrals, not these, so the labels are all that
    /// names them.
    fn generators_note(&self, r: &SearchResult) -> Option<Entry> {
        let (Some(m), Some(names)) = (&r.module, &self.symbolic) else {
            return None;
        };
        let labels: Vec<String> = (m.generators.iter())
            .map(|&i| format!("`{}`", self.label(i)))
            .collect();
        // An integral is generated too where a monomial multiple of it is: `K/ω²` where `K`
        // is (the example names the first parameter).
        let first = names.split(", ").next().unwrap_or(names);
        // A declared denominator of these parameters alone is a polynomial in them, and its
        // multiples count as theirs do.
        let denominators: Vec<String> = (m.denominators.iter())
            .map(|&d| format!("`{}`", r.vars.variable(d).unicode()))
            .collect();
        let by_denominator = match denominators.split_last() {
            None => String::new(),
            Some((last, [])) => format!(" or by {last}"),
            Some((last, rest)) => format!(" or by {} or {last}", rest.join(", ")),
        };
        let shown_text = if r.new.is_some() {
            format!(
                "Below, parameter multiples of integrals count as generated, and so does an \
                 integral whose multiple by a monomial in `{names}`{by_denominator} lies in the \
                 space and is generated by the rule below and this one: `K/{first}` is not new \
                 where `K` is generated."
            )
        } else {
            "Shown: the generators.".to_string()
        };
        Some(Entry::Text(format!(
            "Over the polynomials in `{names}`, {} of the {}, {}, {} all of them: each of \
             the others is a sum of parameter multiples of integrals. {shown_text}",
            m.generators.len(),
            counted(r.basis.len(), "basis integral"),
            listed(&labels),
            agreeing(m.generators.len(), "generates", "generate"),
        )))
    }

    /// The shown integrals as `written`, labelled, each with its form in named functions
    /// from `restated` where it has one, or that there are none to show.
    fn shown_equations(
        &self,
        r: &SearchResult,
        written: &[Expr],
        restated: &[Option<Expr>],
        holds_at: &[Option<String>],
    ) -> Entry {
        if self.shown.is_empty() {
            // Only --new-only shows none: every space holds the constant 1 (each of its
            // degrees counts from 0), an integral, so a basis or its generators are never
            // empty. Where no known integral lies in the space (`H` past its degrees), what is
            // left generated is the constants alone: not the known integrals, of which there
            // are none.
            let why = if r.new.as_ref().is_some_and(|n| n.known.is_empty()) {
                "None: no known integral lies in the space, and every integral in it is a \
                 constant, which counts as generated."
            } else {
                "None: the known integrals generate every integral in the space."
            };
            return Entry::Text(why.into());
        }
        Entry::Equations(Equations::new(
            match (&r.new, &self.symbolic) {
                (Some(_), _) => "New integrals".into(),
                (None, Some(names)) => format!("Generators over the polynomials in `{names}`"),
                (None, None) => "A basis of the integrals".into(),
            },
            self.shown
                .iter()
                .zip(written)
                .enumerate()
                .map(|(k, (&i, w))| {
                    // A new integral shown times denominators of parameters is labelled so:
                    // `(a1 − a2)² I64`.
                    let label = match shown_multiplier(r, i) {
                        Ok(Some(u)) => format!("{} {}", u.render(Style::Unicode), self.label(i)),
                        _ => self.label(i),
                    };
                    Equation {
                        in_functions: restated.get(k).cloned().flatten(),
                        in_functions_holds_at: holds_at.get(k).cloned().flatten(),
                        ..Equation::new(&label, w.clone())
                    }
                })
                .collect(),
        ))
    }

    /// A claim `{I3, H} = 0` for each shown integral, with where it holds and what its proof
    /// covers, and, with the facts for JSON, as text to read back.
    fn integral_claims(&self, r: &SearchResult, forms: &ShownForms) -> Vec<Entry> {
        self.shown
            .iter()
            .zip(&forms.written)
            .enumerate()
            .map(|(k, (&i, w))| {
                let f = &r.basis[i];
                let label = self.label(i);
                if let (Some(true), Some(Some(form))) =
                    (forms.through.get(k), forms.restated.get(k))
                {
                    return self.claim_through(r, &label, form);
                }
                // On a level set `P = 0`: `{I, H} = Q·P`, the quotient `Q` shown above.
                let (claim, written) = match (&r.on, &f.on_level) {
                    (Some(_), Some(proof)) if !proof.quotient.is_zero() => (
                        format!(
                            "{{{label}, H}} = {} ({})",
                            self.quotient_label(i),
                            proof.divisor
                        ),
                        format!(
                            "{{{}, H}} = ({})*({})",
                            w.render(Style::Ascii),
                            proof.quotient.render(Style::Ascii),
                            proof.divisor.render(Style::Ascii)
                        ),
                    ),
                    _ => (
                        format!("{{{label}, H}} = 0"),
                        format!("{{{}, H}} = 0", w.render(Style::Ascii)),
                    ),
                };
                let c = ClaimResult::derived(
                    &label,
                    &claim,
                    f.proved_fixed,
                    proof_note(f, self.held.fixed(), self.symbolic.as_deref()),
                )
                .at(self
                    .held
                    .at(f.symbolic.is_none() && !r.parameters.is_empty()));
                Entry::Claim(match self.facts {
                    true => c.written(&written),
                    false => c,
                })
            })
            .collect()
    }

    /// The claim of an integral `label` lifted through its restatement `form`
    /// ([`Restate::integral_for_every_value`]): `{form, H} = 0` for every value, at the
    /// condition alone, proved, for every value of the parameters `r` fixed, with their values
    /// where `form` is the integral (`proved for every a, b; it is I2 at a = 12, b = 16`).
    fn claim_through(&self, r: &SearchResult, label: &str, form: &Expr) -> Entry {
        let fixed = self.held.at(true).map(|(text, _)| text).unwrap_or_default();
        let params: Vec<Var> = r.parameters.iter().map(|(v, _)| *v).collect();
        let names = parameter_names(&r.vars, &params);
        let c = ClaimResult::derived(
            label,
            &format!("{{{form}, H}} = 0"),
            true,
            Some(format!(
                "proved for every {names}; it is {label} at {fixed}"
            )),
        )
        .at(self.held.at(false));
        Entry::Claim(match self.facts {
            true => c.written(&format!("{{{}, H}} = 0", form.render(Style::Ascii))),
            false => c,
        })
    }

    /// The label of the quotient `Q` of basis integral `i` on a level set: `Q4` beside `I4`.
    fn quotient_label(&self, i: usize) -> String {
        format!("{}{}", self.quotient, i + 1)
    }

    /// On a level set `P = 0`, the quotient `Q` of each shown integral's bracket with `H` on
    /// division by `P`, by which `{I, H} = Q·P` is proved: recomputed, not trusted.
    fn quotients(&self, r: &SearchResult) -> Option<Entry> {
        let on = r.on.as_ref()?;
        let lines: Vec<Equation> = (self.shown.iter())
            .filter_map(|&i| {
                let proof = r.basis[i].on_level.as_ref()?;
                // An integral everywhere, `{I, H} = 0`, has none.
                if proof.quotient.is_zero() {
                    return None;
                }
                Some(Equation::new(
                    &self.quotient_label(i),
                    proof.quotient.clone(),
                ))
            })
            .collect();
        if lines.is_empty() {
            return None;
        }
        Some(Entry::Equations(Equations::new(
            format!(
                "The integrals on the level set alone: `{{{}, H}} = {} P`, `P = {}`, with",
                self.letter, self.quotient, on.polynomial
            ),
            lines,
        )))
    }

    /// The shown integrals of trigonometric order `k > 0` as `I = Re(A e^{−ikθ})`, when the
    /// system has one angle and some has such a form, each amplitude `A` restated by
    /// `restate` below it where one is given and it has a form (`= Z_y`), that of an
    /// integral not lifted at `at_fixed` ([`Restate::at_fixed_values`], with how it reads
    /// back, which its line's `in_functions_holds_at` then says); with the labels of those
    /// restated there.
    fn complex_forms(
        &self,
        r: &SearchResult,
        restate: Option<&Restate<'_>>,
        at_fixed: Option<&(brackets::Condition, String)>,
    ) -> Option<(Entry, Vec<String>)> {
        let k = order_letter(&r.vars);
        // Each line with its amplitude's label (`A3`) and whether its integral is not lifted.
        let (mut lines, shown): (Vec<Equation>, Vec<(String, bool)>) = self
            .shown
            .iter()
            .filter_map(|&i| {
                complex_form(r.basis[i].expr()).map(|(a, order)| {
                    let amplitude = format!("{}{}", self.complex, i + 1);
                    let line = Equation::new(&format!("{amplitude} ({k} = {order})"), a);
                    (line, (amplitude, r.for_every_value(i).is_none()))
                })
            })
            .unzip();
        let unlifted: Vec<bool> = shown.iter().map(|(_, u)| *u).collect();
        let ([theta], false) = (r.variables.angles.as_slice(), lines.is_empty()) else {
            return None;
        };
        let mut at_fixed_labels = Vec::new();
        if let Some(restate) = restate {
            let amplitudes: Vec<Expr> = lines.iter().map(|l| l.rhs.clone()).collect();
            let written = restate.restated(
                &amplitudes,
                &unlifted,
                at_fixed.map(|(c, _)| c),
                LoadedSystem::amplitudes_in_functions,
            );
            for ((line, written), (amplitude, u)) in lines.iter_mut().zip(written).zip(&shown) {
                if let (Some((_, ascii)), true) = (at_fixed, *u && written.is_some()) {
                    at_fixed_labels.push(amplitude.clone());
                    line.in_functions_holds_at = Some(ascii.clone());
                }
                line.in_functions = written;
            }
        }
        let theta = r.vars.variable(*theta).unicode();
        let entry = Entry::Equations(Equations::new(
            format!(
                "Those of trigonometric order `{k} > 0` as `{} = Re({} e^{{−i{k}{theta}}})`",
                self.letter, self.complex
            ),
            lines,
        ));
        Some((entry, at_fixed_labels))
    }

    /// That the restatements of `labels`, integrals not lifted (or their amplitudes), are at
    /// the fixed values, where those hold, not for every value; none where there are none.
    fn restated_at_fixed_note(&self, labels: &[String]) -> Option<Entry> {
        let (last, rest) = labels.split_last()?;
        let (names, they) = match rest {
            [] => (format!("`{last}`"), "it holds"),
            _ => {
                let rest: Vec<String> = rest.iter().map(|l| format!("`{l}`")).collect();
                (format!("{} and `{last}`", rest.join(", ")), "they hold")
            }
        };
        Some(Entry::Text(format!(
            "Restated at `{}`, where {they} (not lifted): {names}, with `H` and the file's \
             functions at these values.",
            self.held.at(true)?.0
        )))
    }

    /// Which integrals are lifted through their restatements at the fixed values
    /// ([`ShownForms`]; the count says that they hold for every value, each claim for which
    /// parameters): none where there are none.
    fn lifted_through_note(&self, forms: &ShownForms) -> Option<Entry> {
        let labels: Vec<String> = (self.shown.iter().zip(&forms.through))
            .filter(|(_, &t)| t)
            .map(|(&i, _)| format!("`{}`", self.label(i)))
            .collect();
        let (last, rest) = labels.split_last()?;
        let (names, they) = match rest {
            [] => (last.clone(), "it is"),
            _ => (format!("{} and {last}", rest.join(", ")), "they are"),
        };
        Some(Entry::Text(format!(
            "Restated at `{}`, where {they} found, and lifted through the restatement: \
             {names}, with the file's functions as written.",
            self.held.at(true)?.0
        )))
    }

    /// One claim for the basis integrals not shown: all proved (`for the other 4 basis
    /// elements` after some are shown, `for the 4 basis elements` where none is).
    fn rest_proved(&self, r: &SearchResult) -> Option<Entry> {
        let rest: Vec<&Integral> = (0..r.basis.len())
            .filter(|i| !self.shown.contains(i))
            .map(|i| &r.basis[i])
            .collect();
        if rest.is_empty() {
            return None;
        }
        let proved = rest.iter().all(|f| f.proved_fixed);
        let lifted = rest.iter().filter(|f| f.symbolic.is_some()).count();
        let note = match &self.symbolic {
            // Nothing fixed: every proof was symbolic.
            _ if r.parameters.is_empty() => None,
            // Every one lifted back to the fixed parameters too: proved for every value.
            Some(_) if lifted == rest.len() => None,
            Some(names) => Some(proved_for_every(names, self.held.fixed())),
            None => Some(format!("{lifted} of them lifted and proved symbolically")),
        };
        let other = match self.shown.is_empty() {
            true => "",
            false => "other ",
        };
        let mut c = ClaimResult::derived(
            "basis",
            &format!(
                "{{{}, H}} = 0 for the {other}{}",
                self.letter,
                counted(rest.len(), "basis element")
            ),
            proved,
            note,
        );
        c.condition = r.condition.clone();
        Some(Entry::Claim(c))
    }
}

/// What the report says of the parameters the linear algebra fixed (none: nothing): their
/// values, whether and how the basis was lifted back to symbolic parameters, and, for what is
/// not lifted, how to see it for every value.
fn parameter_notes(
    r: &SearchResult,
    system: &System,
    fixed: &str,
    (for_every_value, through): (usize, usize),
    (caller, solved): (Caller, Option<Var>),
) -> Vec<Entry> {
    let mut notes = Vec::new();
    if r.parameters.is_empty() {
        return notes;
    }
    let vars = system.vars();
    let lift = how_lifted(r, for_every_value, through);
    let off_one = off_one_note(vars, r.denominator_zero_at_one);
    notes.push(Entry::Text(format!(
        "Parameters fixed for the linear algebra: `{fixed}`{off_one}; {lift}."
    )));
    // Nothing is left not lifted where the lift, or the restatements, reach every one.
    let all_lifted =
        (r.liftable && r.all_symbolic()) || (through > 0 && for_every_value == r.basis.len());
    if !all_lifted {
        notes.extend(unlifted_note(r, system, caller, solved).map(Entry::Text));
    }
    notes
}

/// Whether and how the basis found at the fixed parameters was lifted back to symbolic ones;
/// `for_every_value` basis elements hold for every value, `through` of them lifted through
/// their restatements in the file's functions ([`Restate::integral_for_every_value`]) and the
/// rest as found (when nothing is lifted by homogeneity) or lifted by it.
fn how_lifted(r: &SearchResult, for_every_value: usize, through: usize) -> String {
    let n = r.basis.len();
    // Those lifted through their restatements, after those lifted otherwise.
    let restatements = |t: usize| match t {
        1 => "its restatement",
        _ => "their restatements",
    };
    let others = match for_every_value < n {
        true => ", the others at these values only",
        false => "",
    };
    if r.liftable && r.all_symbolic() {
        "then each basis element was lifted back to symbolic parameters by homogeneity and \
         proved symbolically"
            .to_string()
    } else if r.liftable {
        let more = match through {
            0 => String::new(),
            t => format!(", and {t} more through {}{others}", restatements(t)),
        };
        format!("then lifted back to symbolic parameters by homogeneity where possible{more}")
    } else {
        let as_found = for_every_value - through;
        let held = match (as_found, through) {
            (0, 0) => {
                return "the weights do not determine every parameter, so nothing is lifted, \
                        and the basis is proved at these values only"
                    .to_string()
            }
            (k, 0) => format!(
                "{k} of the {} {} as found for every value",
                counted(n, "basis element"),
                agreeing(k, "holds", "hold")
            ),
            (0, t) => format!(
                "{t} of the {} {} for every value through {}",
                counted(n, "basis element"),
                agreeing(t, "holds", "hold"),
                restatements(t)
            ),
            (k, t) => format!(
                "{k} of the {} {} for every value as found and {t} through {}",
                counted(n, "basis element"),
                agreeing(k, "holds", "hold"),
                restatements(t)
            ),
        };
        format!(
            "the weights do not determine every parameter, so nothing is lifted; {held} \
             (proved symbolically){others}"
        )
    }
}

/// For what is not lifted: that it holds at the fixed values, and how to see it for every
/// value (`--symbolic`, `SearchOptions::symbolic`) or at others (`--fix`,
/// `SearchOptions::fix`); on a level set, other values only where it is searched at them
/// ([`LevelSet::check`](brackets::search::LevelSet::check)), else that it is refused there.
/// The parameter `solved` (a `--find-values` run's) is left out of it, and with nothing
/// else fixed there is no note.
fn unlifted_note(
    r: &SearchResult,
    system: &System,
    caller: Caller,
    solved: Option<Var>,
) -> Option<String> {
    let vars = system.vars();
    let parameters: Vec<(Var, Rational)> = (r.parameters.iter())
        .filter(|(v, _)| Some(*v) != solved)
        .cloned()
        .collect();
    if parameters.is_empty() {
        return None;
    }
    let names: Vec<&str> = (parameters.iter())
        .map(|(v, _)| vars.variable(*v).name())
        .collect();
    let others = other_values(&parameters);
    let shown: Vec<String> = (others.iter().zip(&names))
        .map(|((_, value), n)| format!("{n}={value}"))
        .collect();
    // The level set checked at the others' values, the solved parameter's kept; in a
    // polynomial space (`false`): whether it shares a variable with a Laurent space's
    // negative powers does not depend on the values, and the search took it.
    let checked: Vec<(Var, Rational)> = (r.parameters.iter())
        .filter(|(v, _)| Some(*v) == solved)
        .cloned()
        .chain(others.iter().cloned())
        .collect();
    let refused =
        (r.on.as_ref()).is_some_and(|on| on.level.check(system, &checked, false).is_err());
    let how = match caller {
        // On a level set nothing is kept symbolic: other values are what is left, those it is
        // searched at.
        Caller::CommandLine if refused => format!(
            "compare with other values the level set is searched at (`--fix`; it is refused \
             at `{}`)",
            shown.join(", ").replace('=', " = ")
        ),
        Caller::Program if refused => format!(
            "compare with other values the level set is searched at (`SearchOptions::fix`; \
             it is refused at {})",
            shown.join(", ").replace('=', " = ")
        ),
        Caller::CommandLine if r.on.is_some() => {
            format!("compare with other values (`--fix {}`)", shown.join(","))
        }
        Caller::Program if r.on.is_some() => format!(
            "compare with other values (`SearchOptions::fix`, such as {})",
            shown.join(", ").replace('=', " = ")
        ),
        Caller::CommandLine => format!(
            "keep them symbolic (`--symbolic {}`), or compare with other values (`--fix {}`)",
            names.join(","),
            shown.join(",")
        ),
        Caller::Program => format!(
            "keep them symbolic (`SearchOptions::symbolic`), or compare with other values \
             (`SearchOptions::fix`, such as {})",
            shown.join(", ").replace('=', " = ")
        ),
    };
    Some(format!(
        "What is not lifted holds at these values, where the system may have more \
         symmetry than in general (special values, equal or in a rational ratio, can add \
         integrals): for every value, {how}."
    ))
}

/// Other values for the fixed `parameters`, to compare with: the first primes, each
/// parameter another, none at its value now.
fn other_values(parameters: &[(Var, Rational)]) -> Vec<(Var, Rational)> {
    let mut primes = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47]
        .into_iter()
        .cycle();
    parameters
        .iter()
        .map(|(v, now)| {
            let p = primes
                .by_ref()
                .find(|&p| *now != Rational::from(p))
                .expect("the primes cycle");
            (*v, Rational::from(p))
        })
        .collect()
}

/// How the new integrals were told from the generated ones: the known integrals, the rule by
/// degree (or grade, with angles), and how much of the space the generated ones span.
fn new_integrals_text(r: &SearchResult, n: &NewIntegrals) -> String {
    let known = if n.known.is_empty() {
        "none".to_string()
    } else {
        format!("`{}`", n.known.join(", "))
    };
    // On a level set every integral compared is a normal form modulo `P`; where a product past
    // the space's degree could fall back into it, the products do not decide what is new.
    let modulo = match (&r.on, n.past_degree_undecided) {
        (Some(_), false) => {
            ", every known integral and product taken in normal form modulo `P` and \
             not counted where that leaves the space (products past the space's total degree \
             are not formed: one alone cannot fall back into it, but a sum of them whose parts \
             of top degree add up to a multiple of that of `P` is not looked for)"
        }
        (Some(_), true) => {
            ", every known integral and product taken in normal form modulo `P` and \
             not counted where that leaves the space; the part of top degree of `P` is not \
             shown to share no factor with each integral's, so a product past the space's \
             degree (not formed) may fall back into it modulo `P`, and an integral told new \
             may be generated by one"
        }
        (None, _) => "",
    };
    format!(
        "Known integrals in the space: {known}. {} ({} formed){modulo}; {}",
        generation_rule(r),
        counted(n.products, "product"),
        generated_span(r, n),
    )
}

/// The variables an integral's degree is taken in: `in the coordinates and momenta
/// together`, or with the denominators, the radicals, the Poisson variables.
fn degree_variables(r: &SearchResult) -> String {
    // Without angles the grade is the degree.
    let canonical = [
        &r.variables.coordinates,
        &r.variables.momenta,
        &r.variables.angles,
    ]
    .iter()
    .any(|vs| !vs.is_empty());
    // With denominator atoms their powers count with the coordinates' (`1/(x − y)`), and so
    // do a radical's, of either sign (`1/r`).
    let denominator = denominators_in_space(r).next();
    let radical = radicals_in_space(r).next();
    let unicode = |v: Var| r.vars.variable(v).unicode();
    match (
        r.variables.poisson.is_empty(),
        canonical,
        denominator,
        radical,
    ) {
        (true, _, Some(d), _) => format!(
            "in the coordinates, momenta and denominators together, `1/{}` of degree 1",
            unicode(d)
        ),
        (true, _, None, Some(radical)) => format!(
            "in the coordinates, momenta and radicals together, `{0}` and `1/{0}` of degree 1",
            unicode(radical)
        ),
        (true, _, None, None) => "in the coordinates and momenta together".into(),
        (false, false, _, _) => "in the Poisson variables".into(),
        (false, true, _, _) => "in the coordinates, momenta and Poisson variables together".into(),
    }
}

/// When an integral counts as generated: by degree, or by grade with angles.
fn generation_rule(r: &SearchResult) -> String {
    let variables = degree_variables(r);
    if r.variables.angles.is_empty() {
        format!(
            "An integral of degree `N` ({variables}) is generated when it is a sum of known \
             integrals, constants and products of integrals of degree `< N`"
        )
    } else {
        format!(
            "An integral of grade `(N, k)` (its degree `N` {variables}, then its \
             trigonometric order `k`: the largest such pair among its terms, compared in \
             that order) is generated when it is a sum of known integrals, constants and \
             products of integrals of grade below `(N, k)`"
        )
    }
}

/// How much of the space the generated integrals span, and whether new ones follow.
fn generated_span(r: &SearchResult, n: &NewIntegrals) -> String {
    if n.generated == r.basis.len() {
        format!(
            "the generated ones span the whole space ({}).",
            counted(r.basis.len(), "dimension")
        )
    } else {
        format!(
            "the generated ones span {} of the {}, and a complement, the new integrals, is:",
            n.generated,
            counted(r.basis.len(), "dimension")
        )
    }
}

/// The shown integrals as the report writes them: over common denominators with denominator
/// atoms; with radicals only, with the least powers of the radicals when that has fewer terms;
/// else as found.
fn written_forms(r: &SearchResult, shown: &[usize]) -> Result<Vec<Expr>, EngineError> {
    let with_atoms = Expr::has_denominator_atoms(&r.vars);
    let with_radicals = Expr::has_radicals(&r.vars);
    shown
        .iter()
        .map(|&i| {
            let e = r.basis[i].expr();
            if with_atoms {
                return match shown_multiplier(r, i)? {
                    Some(u) => u.checked_mul(e)?.over_common_denominators(),
                    None => e.over_common_denominators(),
                };
            }
            if with_radicals {
                let least = e.with_least_radical_powers()?;
                if least.len() < e.len() {
                    return Ok(least);
                }
            }
            Ok(e.clone())
        })
        .collect::<Result<_, _>>()
        .map_err(EngineError::from)
}

/// The product of declared denominators of parameters by which new integral `i` is shown
/// ([`NewIntegrals::multipliers`]): `(a1 − a2)²` of `(a1 − a2)² I64 = x1² + x2² + x3²`.
fn shown_multiplier(r: &SearchResult, i: usize) -> Result<Option<Expr>, trigpoly::AlgebraError> {
    let Some(n) = &r.new else {
        return Ok(None);
    };
    let Some(multiplier) = (n.new.iter().position(|&k| k == i)).map(|at| &n.multipliers[at]) else {
        return Ok(None);
    };
    if multiplier.is_empty() {
        return Ok(None);
    }
    let mut exponents = vec![0i64; r.vars.len()];
    for &(atom, e) in multiplier {
        exponents[atom.index()] = e;
    }
    Expr::from_terms(&r.vars, vec![(GaussianRational::from(1), exponents)]).map(Some)
}

/// A level set as the report shows it: `M1γ1 + M2γ2 + M3γ3 = 0`.
pub(super) fn level_set_shown(on: &SearchedLevel) -> String {
    format!("{} = {}", on.level.expr, on.level.value)
}

/// What a search on a level set does: the polynomial `P`, its leading monomial, the
/// monomials left out, and what the integrals found are; where a function of the space has
/// a normal form outside it (at the parameters' values, where they are `fixed`), that only
/// those whose normal form lies in the space are found.
fn level_set_text(on: &SearchedLevel, fixed: bool) -> String {
    let kept_at = match fixed && !on.kept_for_every_value {
        true => " at the fixed values",
        false => "",
    };
    let outside = match &on.normal_form_outside {
        Some(o) => format!(
            " Only those whose normal form lies in the space are found: the space's degree \
             bounds are not kept by the division (the normal form of `{}` is `{}`{}, outside \
             the space), so an integral of the space whose normal form leaves it is not \
             counted (a space that holds its normal form finds it).",
            o.function,
            o.normal_form,
            if fixed { " at the fixed values" } else { "" },
        ),
        None => String::new(),
    };
    let text = format!(
        "On the level set `{}`, of `P = {}`, which the flow of `H` keeps{} (`{{P, H}}` is a \
         multiple of `P`): the monomials divisible by its leading monomial `{}` (graded \
         lexicographic order) are left out, {} (each is a combination of lower ones where \
         `P = 0`), and each bracket `{{φ, H}}` is taken modulo `P`. The integrals found are \
         the functions in normal form whose bracket with `H` is a multiple of `P`: they are \
         conserved on the level set, and none of them is a multiple of `P`.",
        level_set_shown(on),
        on.polynomial,
        kept_at,
        on.leading_monomial,
        counted(on.left_out, "unknown"),
    );
    text + &outside
}
