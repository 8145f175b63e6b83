//! Unit tests of the search's internals.

use trigpoly::{AlgebraError, GaussianRational, Var, Vars};

use super::locate::Locator;
use super::new_only::{
    generators, span_of_products, without_parameter_multiples, Generator, Grading, Leads, Size,
    Stamped,
};
use super::parameters::fixed_problem;
use super::problem::{canonical, exponent_vectors, exponent_vectors_count, Problem};
use super::result::{combinations_within, ELIMINATIONS};
use super::*;
use crate::claim::Condition;
use crate::modular::{Echelon, Field, Fp};
use crate::systems;

/// The search problem of `rotor` (the harmonic rotor) at momenta and angle degree 2 and
/// positions of degree `positions`, for its own Hamiltonian with no condition.
fn rotor_problem(rotor: &System, positions: u32) -> Problem {
    let space = SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(positions)
        .trig_degree(2);
    let h = rotor.hamiltonian().clone();
    Problem::new(rotor, &space, &[], &[], h, None).unwrap()
}

#[test]
fn coordinates_are_those_of_the_real_and_imaginary_parts() {
    let rotor = systems::harmonic_rotor();
    let problem = rotor_problem(&rotor, 1);
    let n = problem.unknowns.len();
    // f = Σ (a_j + i b_j) φ_j over every third unknown (the φ_j are real): Re f has the
    // coordinates a, Im f the coordinates b.
    let (mut a, mut b) = (Vec::new(), Vec::new());
    let mut f = Expr::zero(&problem.vars);
    for j in (0..n).step_by(3) {
        let (x, y) = (
            Rational::new(j as i64 % 7 - 3, 2),
            Rational::new(1, j as i64 + 1),
        );
        let c = GaussianRational::new(x.clone(), y.clone());
        f += problem.expr(j, &Rational::one()).unwrap().scale(&c);
        if !x.is_zero() {
            a.push((j, x));
        }
        b.push((j, y));
    }
    assert_eq!(
        problem.coordinates_of_parts(&f),
        Some((a.clone(), b.clone()))
    );
    assert_eq!(problem.combination(&a).unwrap(), f.re().unwrap());
    assert_eq!(problem.combination(&b).unwrap(), f.im().unwrap());
    // A real function has no imaginary part; a complex one has no real coordinates.
    assert_eq!(problem.coordinates(&f.re().unwrap()), Some(a));
    assert_eq!(problem.coordinates(&f), None);
    // Outside the space (positions degree 2 > 1): no coordinates.
    let outside = f.re().unwrap() + rotor.parse("x^2").unwrap();
    assert_eq!(problem.coordinates(&outside), None);
    assert_eq!(problem.coordinates_of_parts(&outside), None);
}

/// A function's grade is the largest `(degree, order)` of its terms, lexicographically, and
/// grades form a filtration: a sum's is at most the larger of its terms', a product's at
/// most the sum of its factors'.
#[test]
fn grades_are_degree_then_order_and_form_a_filtration() {
    let rotor = systems::harmonic_rotor();
    let problem = rotor_problem(&rotor, 2);
    let grading = Grading::new(&problem.variables, 8);
    let grade = |f: &Expr| {
        let n = grading.grade(f);
        (n / grading.orders, n % grading.orders)
    };
    let graded = [
        ("3", (0, 0)),
        ("cos(theta)", (0, 1)),
        ("cos(2*theta) + 1", (0, 2)),
        ("p_x*cos(theta)", (1, 1)),
        ("p_x + cos(3*theta)", (1, 0)),
        ("x*p_y - y*p_x + sin(theta)", (2, 0)),
        ("x^2*cos(theta) + p_theta*sin(2*theta) - 1", (2, 1)),
    ];
    let functions: Vec<Expr> = graded.iter().map(|g| rotor.parse(g.0).unwrap()).collect();
    for ((text, expected), f) in graded.iter().zip(&functions) {
        assert_eq!(grade(f), *expected, "{text}");
    }
    for f in &functions {
        for g in &functions {
            let (a, b) = (grade(f), grade(g));
            assert!(grade(&(f.clone() + g.clone())) <= a.max(b), "{f} + {g}");
            let product = f.checked_mul(g).unwrap();
            assert!(grade(&product) <= (a.0 + b.0, a.1 + b.1), "({f})·({g})");
        }
    }
}

#[test]
fn the_complement_over_q_alone_is_the_modular_one() {
    let rotor = systems::harmonic_rotor();
    for (m, n, d) in [(1, 1, 4), (2, 1, 3)] {
        let options = SearchOptions::new(
            SearchSpace::default()
                .momenta_degree(d)
                .positions_degree(d)
                .trig_degree(d),
        )
        .when(rotor.resonance(m, n).unwrap())
        .new_only();
        let modular = search(&rotor, &options).unwrap().new.unwrap();
        let exact = search(&rotor, &options.exact_complement())
            .unwrap()
            .new
            .unwrap();
        assert!(!modular.new.is_empty() && modular.generated > 0);
        assert_eq!(
            (modular.new, modular.generated, modular.products),
            (exact.new, exact.generated, exact.products)
        );
    }
}

#[test]
fn a_stamp_keeps_the_parts_of_a_product_in_both_fields() {
    let rotor = systems::harmonic_rotor();
    let problem = rotor_problem(&rotor, 1);
    // f = Σ (a_j + i b_j) φ_j/3 and i·f, whose parts are those of f again.
    let mut f = Expr::zero(&problem.vars);
    for j in (0..problem.unknowns.len()).step_by(5) {
        let c = GaussianRational::new(Rational::new(j as i64 % 7 - 3, 3), Rational::new(1, 3));
        f += problem.expr(j, &Rational::one()).unwrap().scale(&c);
    }
    let i_f = f.scale(&GaussianRational::new(Rational::zero(), Rational::one()));
    let (re, im) = problem.coordinates_of_parts(&f).unwrap();
    let locator = Locator::Monomials(&problem);
    for exact in [false, true] {
        let every = Leads::all(problem.unknowns.len());
        let mut span = Stamped::new(&every, exact);
        assert_eq!(span.add_parts(&locator, 2, &f).unwrap(), Some(()));
        assert_eq!(span.add_parts(&locator, 2, &i_f).unwrap(), Some(()));
        let outside = f.clone() + rotor.parse("x^2").unwrap();
        assert_eq!(span.add_parts(&locator, 2, &outside).unwrap(), Some(()));
        assert_eq!(span.into_vectors(), [(2, re.clone()), (2, im.clone())]);
    }
}

#[test]
fn the_span_keeps_only_vectors_independent_of_those_before() {
    let v = |entries: &[(usize, i64)]| -> SparseVec<Rational> {
        entries
            .iter()
            .map(|&(j, x)| (j, Rational::from(x)))
            .collect()
    };
    for exact in [false, true] {
        let every = Leads::all(4);
        let mut span = Stamped::new(&every, exact);
        let a = v(&[(0, 1), (2, 3)]);
        let b = v(&[(1, 2), (2, -1)]);
        let sum = v(&[(0, 1), (1, 2), (2, 2)]);
        // b under stamp 1 spans b under stamp 3 too.
        for (stamp, x) in [
            (1, b.clone()),
            (3, a.clone()),
            (3, b.clone()),
            (3, sum),
            (3, a.clone()),
        ] {
            assert_eq!(span.add(stamp, x), Some(()));
        }
        assert_eq!(span.rank(), 2);
        // p divides a denominator: no residue, so only over Q is it kept.
        let unmappable = vec![(3, Rational::new(1, modular::PRIME as i64))];
        assert_eq!(span.add(4, unmappable.clone()).is_some(), exact);
        let mut expected = vec![(1, b.clone()), (3, a)];
        if exact {
            expected.push((4, unmappable));
        }
        assert_eq!(span.into_vectors(), expected);
    }
}

/// A search of `space` for integrals of `rotor` at its 1:1 resonance.
fn at_one_to_one(rotor: &System, space: SearchSpace) -> SearchOptions {
    SearchOptions::new(space).when(rotor.resonance(1, 1).unwrap())
}

/// The integrals of the harmonic rotor in `space` at the 1:1 resonance, the problem at the
/// fixed values, and the basis's coordinates there.
fn found_at_one_to_one(space: SearchSpace) -> (SearchResult, Problem, Kernel) {
    let rotor = systems::harmonic_rotor();
    let options = at_one_to_one(&rotor, space);
    let found = search(&rotor, &options).unwrap();
    let parameters = parameter_values(&rotor, options.condition.as_ref(), &[], &[]);
    let problem = fixed_problem(&rotor, &options, &parameters).unwrap();
    let kernel = (found.basis.iter())
        .map(|b| problem.coordinates(&b.fixed).unwrap())
        .collect();
    (found, problem, kernel)
}

type Kernel = Vec<SparseVec<Rational>>;

/// An integral is zero exactly when its coordinates on the leads are: a combination of the
/// basis has, at the lead of its last basis element, that element's coefficient times its
/// own. A lead coefficient divisible by p keeps every coordinate.
#[test]
fn integrals_are_told_apart_by_their_coordinates_on_the_leads() {
    let (_, problem, kernel) = found_at_one_to_one(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .trig_degree(2),
    );
    let dim = problem.unknowns.len();
    let leads = Leads::of(&kernel, dim);
    assert_eq!(leads.count, kernel.len());
    assert_eq!(leads.position.iter().flatten().count(), kernel.len());
    for last in 0..kernel.len() {
        // Σ_{k ≤ last} (k + 1)·I_k, modulo p, on the leads.
        let mut sum: FxHashMap<usize, Fp> = FxHashMap::default();
        for (k, v) in kernel[..=last].iter().enumerate() {
            for (j, x) in modular::to_fp(v).unwrap() {
                let c = Fp::from_i64(k as i64 + 1).mul(&x);
                let entry = sum.entry(j).or_insert(Fp::from_i64(0));
                *entry = entry.add(&c);
            }
        }
        let v: SparseVec<Fp> = sum.into_iter().filter(|x| !x.1.is_zero()).collect();
        let on_leads = leads.restrict(v);
        let top = lead(&on_leads).unwrap();
        let own = &lead(&kernel[last]).unwrap().1;
        let expected = Fp::from_i64(last as i64 + 1).mul(&Fp::from_rational(own).unwrap());
        assert_eq!(*top, (last, expected));
    }
    let mut divisible = kernel.clone();
    let last = divisible.len() - 1;
    divisible[last].iter_mut().max_by_key(|x| x.0).unwrap().1 =
        Rational::from(modular::PRIME as i64);
    let every = Leads::of(&divisible, dim);
    assert_eq!(every.count, dim);
    assert_eq!(every.restrict(kernel[last].clone()), kernel[last]);
}

#[test]
fn products_stop_once_they_span_every_integral() {
    // At the 1:1 resonance the products of the integrals up to degree 4 span what they
    // span before the last stamp's products: told that dimension, the walk stops there.
    let (found, problem, kernel) = found_at_one_to_one(
        SearchSpace::default()
            .momenta_degree(4)
            .positions_degree(4)
            .trig_degree(4),
    );
    let grading = Grading::new(&problem.variables, 4);
    let sources = found.basis.iter().map(|b| &b.fixed);
    let gens = generators(&problem, &grading, sources, &|_| Ok(false)).unwrap();
    let bounds = Size {
        momenta: 4,
        coordinates: 4,
        poisson: 0,
        angles_alone: 4,
    };
    let dim = problem.unknowns.len();
    let leads = Leads::of(&kernel, dim);
    assert_eq!(leads.count, found.basis.len());
    let locator = Locator::Monomials(&problem);
    for exact in [false, true] {
        let span = |dimension| {
            let span = Stamped::new(&leads, exact);
            let limits = (dimension, DEFAULT_MAX_PRODUCTS);
            span_of_products(&locator, &gens, Vec::new(), bounds, false, span, limits)
                .unwrap()
                .unwrap()
        };
        let (all, formed_all) = span(usize::MAX);
        assert!(all.len() < found.basis.len());
        let (stopped, formed) = span(all.len());
        assert!(formed < formed_all, "{formed} of {formed_all}");
        // The same span: every vector of the whole walk lies in that of the stopped one.
        let mut basis = Echelon::<Rational>::new(dim);
        for (id, (_, v)) in stopped.iter().enumerate() {
            assert!(basis.insert(id, v).is_none());
        }
        assert!(all.iter().all(|(_, v)| basis.contains(v)));
        // Stamps never decrease.
        assert!(stopped.windows(2).all(|w| w[0].0 <= w[1].0));
    }
}

#[test]
fn new_integrals_at_one_to_one_are_the_four_linear_ones() {
    let rotor = systems::harmonic_rotor();
    let options = at_one_to_one(
        &rotor,
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .trig_degree(2),
    )
    .new_only();
    let r = search(&rotor, &options).unwrap();
    assert_eq!(r.dimensions_by_momenta_degree(), [1, 6, 20]);
    assert!(r.all_symbolic());
    let new = r.new.as_ref().unwrap();
    assert_eq!(new.new.len(), 4);
    assert_eq!(new.generated, 16);
    for &i in &new.new {
        let f = &r.basis[i];
        assert_eq!((f.momenta_degree, f.trig_degree), (1, 1));
    }
}

#[test]
fn off_resonance_there_is_no_trigonometric_integral() {
    // At p_θ = 3Iω/2 nothing of trigonometric order ≤ 2 and degree ≤ 2 is conserved but
    // the planar u(2) and the constants.
    let rotor = systems::harmonic_rotor();
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .trig_degree(2),
    )
    .when(rotor.resonance(3, 2).unwrap());
    let r = search(&rotor, &options).unwrap();
    assert!(r.basis.iter().all(|f| f.trig_degree == 0));
    // 1, L and the quadratic H_x, H_y, G1 (times 2M) and L².
    assert_eq!(r.basis.len(), 6);
}

/// The harmonic rotor at 1:1, integrals linear in the momenta: found at `M = ω = I = 1`
/// and lifted by homogeneity, or found with `M, ω, I` symbolic (coefficients of degree
/// `≤ 2` in them), the generators are the same six functions.
#[test]
fn symbolic_parameters_find_the_lifted_basis() {
    let rotor = systems::harmonic_rotor();
    let space = SearchSpace::default()
        .momenta_degree(1)
        .positions_degree(1)
        .trig_degree(1);
    let resonance = rotor.resonance(1, 1).unwrap();
    let lifted = search(&rotor, &SearchOptions::new(space).when(resonance.clone())).unwrap();
    assert!(lifted.all_symbolic() && lifted.module.is_none());
    let mut options = SearchOptions::new(space.parameters_degree(2)).when(resonance);
    for p in ["M", "omega", "I"] {
        options = options.symbolic(rotor.var(p));
    }
    let r = search(&rotor, &options).unwrap();
    assert!(r.parameters.is_empty() && r.all_symbolic());
    // 1, L and the four trigonometric ones, each also times 1, M, ω, I, M², Mω, ….
    assert_eq!(r.basis.len(), 24);
    let module = r.module.as_ref().unwrap();
    let generators: Vec<&Expr> = module
        .generators
        .iter()
        .map(|&i| r.basis[i].expr())
        .collect();
    let expected: Vec<&Expr> = lifted.basis.iter().map(Integral::expr).collect();
    assert_eq!(generators, expected);
}

/// The images, the blocks of equations and the proofs are shared among the pool's threads
/// and kept in order: the same basis, proofs and new integrals on one thread or several,
/// and from a thread outside any pool.
#[test]
fn the_search_is_the_same_on_any_number_of_threads() {
    let rotor = systems::harmonic_rotor();
    let options = at_one_to_one(
        &rotor,
        SearchSpace::default()
            .momenta_degree(3)
            .positions_degree(3)
            .trig_degree(3),
    )
    .new_only();
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| search(&rotor, &options).unwrap())
    };
    let summary = |r: &SearchResult| {
        let basis: Vec<(Expr, bool, Option<Expr>)> = r
            .basis
            .iter()
            .map(|b| (b.fixed.clone(), b.proved_fixed, b.symbolic.clone()))
            .collect();
        let new = r.new.as_ref().map(|n| (n.new.clone(), n.products));
        (basis, new, r.equations, r.components)
    };
    let one = summary(&on(1));
    assert_eq!(one.0.len(), 50);
    assert!(one.0.iter().all(|b| b.1 && b.2.is_some()));
    assert_eq!(summary(&on(3)), one);
    assert_eq!(summary(&search(&rotor, &options).unwrap()), one);
}

/// `--new-only` checks over Q each dependency it finds modulo p (every basis integral that is
/// generated) in one sum that the checks share, grown once to at most the space's rows: a sum
/// made for each check grew to the largest row it touched, the whole space again for every
/// one (at 1:1 degree 12, 3 181 checks of 207 025 rows: 3.4 s of search, 1.4 s in one sum).
/// Counted on this thread, against the same search without `--new-only`, whose blocks' kernel
/// checks are the same.
#[test]
fn a_new_only_search_checks_its_dependencies_in_one_sum() {
    let rotor = systems::harmonic_rotor();
    let space = SearchSpace::default()
        .momenta_degree(4)
        .positions_degree(4)
        .trig_degree(4);
    let plain = at_one_to_one(&rotor, space);
    let new_only = plain.clone().new_only();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .use_current_thread()
        .build()
        .unwrap();
    let grown = |options: &SearchOptions| {
        let before = crate::modular::SUMS_GROWN.get();
        let r = pool.install(|| search(&rotor, options).unwrap());
        (r, crate::modular::SUMS_GROWN.get() - before)
    };
    let (_, grown_plain) = grown(&plain);
    let (r, grown_new_only) = grown(&new_only);
    let rows = r.unknowns;
    let new = r.new.as_ref().unwrap();
    assert_eq!((rows, r.basis.len(), new.new.len()), (2025, 105, 4));
    assert!(
        grown_new_only - grown_plain <= rows,
        "{} checks grew their sums by {} rows, where the space has {rows}",
        new.generated,
        grown_new_only - grown_plain
    );
}

/// At `a = 1` the rotor in `(x² + a²y²)/2` is isotropic and `x p_y − y p_x` an integral
/// there; the search finds it, and says it holds at the fixed values only, while the
/// energy holds for every value.
#[test]
fn an_integral_of_the_fixed_values_only_is_not_for_every_value() {
    let rotor = systems::rotor("(x^2 + a^2*y^2)/2", &["a"]).unwrap();
    let r = search(
        &rotor,
        &SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(2)),
    )
    .unwrap();
    let find = |text: &str| {
        let e = rotor.parse(text).unwrap();
        (0..r.basis.len())
            .find(|&i| r.basis[i].fixed == e || r.basis[i].fixed == -&e)
            .unwrap_or_else(|| panic!("{text} is found"))
    };
    let l = find("x*p_y - y*p_x");
    assert_eq!(r.for_every_value(l), None);
    let bracket = rotor.flow(&rotor.parse("x*p_y - y*p_x").unwrap()).unwrap();
    assert!(!bracket.is_zero());
    let p_theta = find("p_theta");
    assert_eq!(
        r.for_every_value(p_theta),
        Some(&rotor.parse("p_theta").unwrap())
    );
}

#[test]
fn a_parameter_is_either_fixed_or_symbolic() {
    let rotor = systems::harmonic_rotor();
    let m = rotor.var("M");
    let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1))
        .fix(m, Rational::from(2))
        .symbolic(m);
    let err = search(&rotor, &options).unwrap_err().to_string();
    assert!(
        err.contains("M is both fixed to a value and kept symbolic"),
        "{err}"
    );
    let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1))
        .symbolic(rotor.var("x"));
    let err = search(&rotor, &options).unwrap_err().to_string();
    assert!(
        err.contains("only parameters can be kept symbolic"),
        "{err}"
    );
    // A value for a coordinate was ignored: the search ran as if it were not given.
    let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1))
        .fix(rotor.var("x"), Rational::from(1));
    let err = search(&rotor, &options).unwrap_err().to_string();
    assert!(
        err.contains("only parameters are given values for the linear algebra, and x is not one"),
        "{err}"
    );
}

/// The count of a kind's exponent vectors, made without them, is the number made; with
/// signs, it is also the number of trigonometric functions of the canonical angular vectors
/// (cos and sin of each, 1 for k = 0).
#[test]
fn exponent_vectors_are_counted_without_making_them() {
    for n in 0..4 {
        for max in 0..6 {
            for signed in [false, true] {
                let made = exponent_vectors(n, max, signed);
                let count = exponent_vectors_count(n, max, signed);
                assert_eq!(made.len() as u128, count, "{n} {max} {signed}");
                if signed {
                    let functions: u128 = made
                        .iter()
                        .filter(|k| canonical(k.iter().copied()))
                        .map(|k| if k.iter().all(|x| *x == 0) { 1 } else { 2 })
                        .sum();
                    assert_eq!(functions, count, "{n} {max}");
                }
            }
        }
    }
    assert_eq!(
        exponent_vectors_count(3, u32::MAX, false),
        13_204_693_761_600_761_637_210_423_296
    );
    assert_eq!(exponent_vectors_count(200, u32::MAX, true), u128::MAX);
}

/// A space past the term limit in one kind of variable alone is refused at once: momenta
/// degree 1000 made its 10⁸ exponent vectors first (minutes, gigabytes), and u32::MAX never
/// ended.
#[test]
fn a_space_too_large_in_one_kind_is_refused_before_it_is_made() {
    let rotor = systems::harmonic_rotor();
    for degree in [1000, u32::MAX] {
        let options = SearchOptions::new(
            SearchSpace::default()
                .momenta_degree(degree)
                .positions_degree(1)
                .trig_degree(1),
        );
        let err = search(&rotor, &options).unwrap_err().to_string();
        assert!(
            err.contains("unknowns, more than the term limit 20000000"),
            "{err}"
        );
    }
}

/// A known integral given to a search for new ones that is no integral, or not real, is
/// refused before the space is formed (a space that no search could form here), and the
/// error says which by its place in `SearchOptions::known`, its `Display` the message the
/// search gave once the basis was found: `the known integral x is not an integral: …`.
#[test]
fn a_known_integral_that_is_none_is_refused_before_the_space_is_formed() {
    let rotor = systems::harmonic_rotor();
    let parse = |s: &str| rotor.parse(s).unwrap();
    let space = SearchSpace::default()
        .momenta_degree(u32::MAX)
        .positions_degree(1)
        .trig_degree(1);
    let too_large = search(&rotor, &SearchOptions::new(space).new_only())
        .unwrap_err()
        .to_string();
    assert!(
        too_large.contains("more than the term limit"),
        "{too_large}"
    );
    let cases = [
        (
            "x",
            "is not an integral: {x, H} = p_x at M = 1, ω = 1, I = 1",
        ),
        (
            "i*p_theta",
            "is not real: give its real and imaginary parts, re(i*p_theta) and im(i*p_theta)",
        ),
    ];
    for (f, why) in cases {
        let options = SearchOptions::new(space)
            .new_only()
            .known("p_theta", parse("p_theta"))
            .known(f, parse(f));
        let err = search(&rotor, &options).unwrap_err();
        assert_eq!(
            err,
            EngineError::RefusedKnown {
                index: 1,
                name: f.to_string(),
                reason: why.to_string(),
            }
        );
        assert_eq!(err.to_string(), format!("the known integral {f} {why}"));
    }
}

/// A parameter of another system, fixed or kept symbolic, is refused: its handle named
/// whatever variable stood at its index here, and the search panicked.
#[test]
fn a_parameter_of_another_system_is_refused() {
    let rotor = systems::harmonic_rotor();
    let other = systems::gravity_rotor();
    let foreign = other.var("g");
    let space = SearchSpace::default().momenta_degree(1).positions_degree(1);
    for options in [
        SearchOptions::new(space).fix(foreign, Rational::from(2)),
        SearchOptions::new(space).symbolic(foreign),
    ] {
        let err = search(&rotor, &options).unwrap_err();
        assert!(
            matches!(err, EngineError::Algebra(AlgebraError::VarSetMismatch)),
            "{err}"
        );
    }
}

#[test]
fn a_parameter_named_twice_is_kept_symbolic_once() {
    let rotor = systems::harmonic_rotor();
    let (m, omega) = (rotor.var("M"), rotor.var("omega"));
    let space = SearchSpace::default()
        .momenta_degree(1)
        .positions_degree(1)
        .parameters_degree(2);
    let once = search(
        &rotor,
        &SearchOptions::new(space).symbolic(m).symbolic(omega),
    )
    .unwrap();
    let mut options = SearchOptions::new(space);
    options.symbolic = vec![m, m, omega, m];
    let twice = search(&rotor, &options).unwrap();
    assert_eq!(twice.unknowns, once.unknowns);
    assert_eq!(twice.basis.len(), once.basis.len());
    assert_eq!(twice.module.unwrap().parameters, [m, omega]);
}

/// At 1:1 the new integrals are the four linear ones whether the parameters are fixed and
/// lifted or kept symbolic (with them, `M·I` and the like count as generated, and the
/// named integrals join the known ones once cleared of `1/M`, `1/I`).
#[test]
fn new_integrals_with_symbolic_parameters_are_the_same_four() {
    let rotor = systems::harmonic_rotor();
    let resonance = rotor.resonance(1, 1).unwrap();
    let space = SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(2)
        .trig_degree(2);
    let fixed = search(
        &rotor,
        &SearchOptions::new(space).when(resonance.clone()).new_only(),
    )
    .unwrap();
    let mut options = SearchOptions::new(space.parameters_degree(4))
        .when(resonance)
        .new_only();
    for p in ["M", "omega", "I"] {
        options = options.symbolic(rotor.var(p));
    }
    let symbolic = search(&rotor, &options).unwrap();
    let new = |r: &SearchResult| -> Vec<Expr> {
        let new = r.new.as_ref().unwrap();
        new.new.iter().map(|&i| r.basis[i].expr().clone()).collect()
    };
    assert_eq!(new(&symbolic), new(&fixed));
    assert_eq!(new(&fixed).len(), 4);
    // The named integrals, cleared of `1/M` and `1/I`, lie in the space of degree 4 in
    // the parameters (`2M·F1` has `M²ω²x²`); F2 and Ω are constants at the resonance.
    assert_eq!(
        symbolic.new.as_ref().unwrap().known,
        fixed.new.as_ref().unwrap().known
    );
}

/// A Poisson variable `s` with a declared bracket with a canonical momentum, `{p_x, s} = 1`,
/// and `H = p_x²/2 + s`: `ṗ_x = 1` comes from the declared part of `{p_x, H}` alone, so an
/// image that took only `∂H/∂x` would find `p_x` conserved. The integrals are the
/// polynomials in the Casimir `u = x + s` and `v = p_x² − 2x` that fit the space: `1, u, u²,
/// v, uv` at degree `≤ 2` in each kind, each proved.
#[test]
fn declared_brackets_with_canonical_variables_enter_the_images() {
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .poisson("s")
        .build()
        .unwrap();
    let e = |t: &str| Expr::parse(&vars, t).unwrap();
    let space = crate::PhaseSpace::new(&vars, &[("x", "p_x")])
        .unwrap()
        .with_brackets(&[("p_x", "s", e("1"))])
        .unwrap();
    let slide = System::new("slide", space, e("p_x^2/2 + s")).unwrap();
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .poisson_degree(2),
    )
    .new_only();
    let found = search(&slide, &options).unwrap();
    assert!(found.all_symbolic() && found.basis.iter().all(|f| f.proved_fixed));
    assert_eq!(found.variables.poisson, [slide.var("s")]);
    let parameters = parameter_values(&slide, None, &[], &[]);
    let problem = fixed_problem(&slide, &options, &parameters).unwrap();
    let mut span = Echelon::<Rational>::new(problem.unknowns.len());
    for (id, f) in found.basis.iter().enumerate() {
        assert!(span
            .insert(id, &problem.coordinates(&f.fixed).unwrap())
            .is_none());
    }
    let expected = [
        "1",
        "x + s",
        "(x + s)^2",
        "p_x^2 - 2*x",
        "(x + s)*(p_x^2 - 2*x)",
    ];
    for f in expected {
        assert!(span.contains(&problem.coordinates(&e(f)).unwrap()), "{f}");
    }
    assert_eq!(found.basis.len(), expected.len());
    assert!(problem
        .coordinates(&e("p_x"))
        .is_some_and(|v| !span.contains(&v)));
    // With H = u + v/2 known, the Casimir u alone is new: v = 2(H − u), and u², uv are
    // products.
    let new = found.new.as_ref().unwrap();
    assert_eq!(new.known, ["H"]);
    let new: Vec<&Expr> = new.new.iter().map(|&i| &found.basis[i].fixed).collect();
    assert_eq!(new, [&e("x + s")]);
}

/// The phase space of `vars` with the canonical `pairs` and so(3)* on `M1, M2, M3`:
/// `{M1, M2} = m1_m2` (`M3`, or a multiple of it) and cyclically `{M2, M3} = M1`,
/// `{M3, M1} = M2`.
fn so3_space(vars: &Vars, pairs: &[(&str, &str)], m1_m2: &str) -> crate::PhaseSpace {
    let e = |t: &str| Expr::parse(vars, t).unwrap();
    crate::PhaseSpace::new(vars, pairs)
        .unwrap()
        .with_brackets(&[
            ("M1", "M2", e(m1_m2)),
            ("M2", "M3", e("M1")),
            ("M3", "M1", e("M2")),
        ])
        .unwrap()
}

/// The symmetric Euler top with the moments as parameters, on the surface `M₃ = 1`, which
/// its flow keeps: `M₃` is left out of the space (every function of it is an integral
/// there), and the integrals of degree `≤ 2` in `M₁, M₂` are `1` and `M₁² + M₂²`, lifted
/// back to the moments, which have one weight, so the lift needs none of them.
#[test]
fn a_poisson_variable_the_condition_fixes_is_left_out() {
    let vars = Vars::builder()
        .poisson("M1")
        .poisson("M2")
        .poisson("M3")
        .parameter("A")
        .parameter("C")
        .build()
        .unwrap();
    let e = |t: &str| Expr::parse(&vars, t).unwrap();
    let space = so3_space(&vars, &[], "M3");
    let top = System::new("top", space, e("(M1^2 + M2^2)/(2*A) + M3^2/(2*C)")).unwrap();
    let m3 = Condition::new("M3 = 1", top.var("M3"), e("1"));
    let options = SearchOptions::new(SearchSpace::default().poisson_degree(2))
        .fix(top.var("A"), Rational::from(2))
        .when(m3);
    let found = search(&top, &options).unwrap();
    assert_eq!(found.variables.left_out, [top.var("M3")]);
    assert_eq!(found.variables.poisson, [top.var("M1"), top.var("M2")]);
    let integrals: Vec<&Expr> = found.basis.iter().map(Integral::expr).collect();
    assert_eq!(integrals, [&e("1"), &e("M1^2 + M2^2")]);
    assert!(found.basis.iter().all(|f| f.proved_fixed));
}

#[test]
fn fixed_values_other_than_one_lift_the_same() {
    let rotor = systems::harmonic_rotor();
    let omega = rotor.var("omega");
    let m = rotor.var("M");
    let options = at_one_to_one(
        &rotor,
        SearchSpace::default()
            .momenta_degree(1)
            .positions_degree(1)
            .trig_degree(1),
    )
    .fix(omega, Rational::new(3, 2))
    .fix(m, Rational::new(5, 7));
    let r = search(&rotor, &options).unwrap();
    let lifted: Vec<String> = r.basis.iter().map(|f| f.expr().to_string()).collect();
    assert!(
        lifted.contains(&"p_x cos θ + Mωx sin θ".to_string()),
        "{lifted:?}"
    );
}

#[test]
fn parameter_multiples_of_a_generator_are_left_out_of_the_products() {
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .parameter("k")
        .parameter("a")
        .build()
        .unwrap();
    let (k, a) = (vars.lookup("k").unwrap(), vars.lookup("a").unwrap());
    let gens = |exprs: &[&str]| -> Vec<Generator> {
        exprs
            .iter()
            .map(|s| {
                let expr = Expr::parse(&vars, s).unwrap();
                Generator {
                    size: Size::of(&expr),
                    expr,
                    stamp: 1,
                }
            })
            .collect()
    };
    let kept = |exprs: &[&str], free: &[Var]| -> Vec<String> {
        without_parameter_multiples(gens(exprs), free)
            .iter()
            .map(|g| g.expr.to_string())
            .collect()
    };
    let all = [
        "x*p_x",
        "k*x*p_x",
        "k^2*a*x*p_x",
        "x*p_x + k",
        "k*x*p_x + x",
        "a*x*p_x",
    ];
    // Multiples by monomials in k and a, wherever they stand, are left out; `x p_x + k` and
    // `k x p_x + x` are no multiples.
    assert_eq!(kept(&all, &[k, a]), ["x p_x", "x p_x + k", "kx p_x + x"]);
    // `a` held by a radicand or a denominator is no free parameter: `a x p_x` stays, and
    // `k²a x p_x` is `k²` times it.
    assert_eq!(
        kept(&all, &[k]),
        ["x p_x", "x p_x + k", "kx p_x + x", "ax p_x"]
    );
    assert_eq!(kept(&all, &[]).len(), all.len());
}

/// The open Toda lattice with `a1 = e^{q1 − q2}`, `a2 = e^{q2 − q3}` as Poisson variables:
/// its integrals of degree `≤ 3` in the momenta and `≤ 1` in `a1, a2` are seven, and the
/// four of Poisson degree 0 are `1, P, P², P³` (`P` the total momentum). The basis is
/// ordered by the momenta first, so that its `P²` entered as `P² + …` of Poisson degree 1
/// and its count of degree 0 was 2: the counts are dimensions, by exact linear algebra.
#[test]
fn the_counts_by_poisson_degree_are_dimensions_where_the_space_has_momenta() {
    let vars = Vars::builder()
        .coordinate("q1")
        .momentum("p_q1")
        .coordinate("q2")
        .momentum("p_q2")
        .coordinate("q3")
        .momentum("p_q3")
        .poisson("a1")
        .poisson("a2")
        .build()
        .unwrap();
    let e = |t: &str| Expr::parse(&vars, t).unwrap();
    let space = crate::PhaseSpace::new(&vars, &[("q1", "p_q1"), ("q2", "p_q2"), ("q3", "p_q3")])
        .unwrap()
        .with_brackets(&[
            ("a1", "p_q1", e("a1")),
            ("a1", "p_q2", e("-a1")),
            ("a2", "p_q2", e("a2")),
            ("a2", "p_q3", e("-a2")),
        ])
        .unwrap();
    let toda = System::new("Toda", space, e("(p_q1^2 + p_q2^2 + p_q3^2)/2 + a1 + a2")).unwrap();
    let found = search(
        &toda,
        &SearchOptions::new(SearchSpace::default().momenta_degree(3).poisson_degree(1)),
    )
    .unwrap();
    assert_eq!(found.basis.len(), 7);
    assert_eq!(found.dimensions_by_momenta_degree(), [1, 2, 4, 7]);
    assert_eq!(found.dimensions_by_poisson_degree(), [4, 7]);
    assert_eq!(found.poisson_counts(), [[4], [3]]);
}

/// so(3) with `{M1, M2} = kM3`, a Poisson bracket for every `k`, whose Casimir
/// `M1² + M2² + kM3²` is an integral of every `H`: `k` appears in no function of the search
/// but in a declared bracket, and is fixed for the linear algebra (it was neither fixed nor
/// kept symbolic, so that the integrals whose coefficients hold `k` were left out of a space
/// of dimension 2 instead of 3); kept symbolic, the Casimir is found for every `k`.
#[test]
fn a_parameter_of_a_declared_bracket_is_fixed_for_the_search() {
    let vars = Vars::builder()
        .poisson("M1")
        .poisson("M2")
        .poisson("M3")
        .parameter("k")
        .build()
        .unwrap();
    let e = |t: &str| Expr::parse(&vars, t).unwrap();
    let space = so3_space(&vars, &[], "k*M3");
    let top = System::new("top", space, e("M1^2/2 + M2^2 + 3*M3^2/2")).unwrap();
    let k = top.var("k");
    let options = SearchOptions::new(SearchSpace::default().poisson_degree(2));
    let found = search(&top, &options).unwrap();
    assert_eq!(found.parameters, [(k, Rational::one())]);
    assert_eq!(found.dimensions_by_poisson_degree(), [1, 1, 3]);
    let space = SearchSpace::default()
        .poisson_degree(2)
        .parameters_degree(1);
    let found = search(&top, &SearchOptions::new(space).symbolic(k)).unwrap();
    // The basis, in echelon form, has `2H = M1² + 2M2² + 3M3²` and the Casimir less it.
    let casimir = e("M1^2 + M2^2 + k*M3^2");
    let basis: Vec<&Expr> = found.basis.iter().map(Integral::expr).collect();
    let sum_of_two = basis
        .iter()
        .any(|f| basis.iter().any(|g| (*f + *g) == casimir));
    assert!(sum_of_two, "{basis:?}");
}

/// The counts by degree in the Poisson variables of `r` as an elimination at every grade
/// finds them: `dimensions_by_poisson_degree` and `poisson_counts` before they left out what
/// is known without one.
fn poisson_counts_at_every_grade(r: &SearchResult) -> (Vec<usize>, Vec<Vec<usize>>) {
    let grades = r.term_grades();
    let (p, t) = (
        i64::from(r.space.poisson_degree),
        i64::from(r.space.trig_degree),
    );
    let by_degree = (0..=p)
        .map(|j| combinations_within(&grades, |&(poisson, _)| poisson <= j))
        .collect();
    let mut below = 0;
    let counts = (0..=p)
        .map(|j| {
            (0..=t)
                .map(|k| {
                    let within = combinations_within(&grades, |&g| g <= (j, k));
                    let exactly = within - below;
                    below = within;
                    exactly
                })
                .collect()
        })
        .collect();
    (by_degree, counts)
}

/// The counts by degree in the Poisson variables, which `superint search --format json`
/// gives for every search, eliminate only where the count is not known without: in the
/// rotor's 1:1 space of degree 4 with Poisson degree 2, which has angles and no Poisson
/// variables, once for each trigonometric order below the basis's highest (4 eliminations,
/// where an elimination at every grade took 3 + 3·5 = 18), and for the so(3) top's
/// `{M1, M2} = M3` with Poisson degree 4 and no angles once for each degree below the
/// highest of its integrals. The counts are those of an elimination at every grade.
#[test]
fn the_counts_by_poisson_degree_eliminate_only_where_not_known() {
    let eliminations = |r: &SearchResult| {
        let before = ELIMINATIONS.get();
        let counts = (r.dimensions_by_poisson_degree(), r.poisson_counts());
        (counts, ELIMINATIONS.get() - before)
    };
    let rotor = systems::harmonic_rotor();
    let space = SearchSpace::default()
        .momenta_degree(4)
        .positions_degree(4)
        .trig_degree(4)
        .poisson_degree(2);
    let r = search(&rotor, &at_one_to_one(&rotor, space)).unwrap();
    assert!(r.variables.poisson.is_empty());
    let (counts, done) = eliminations(&r);
    assert_eq!(counts, poisson_counts_at_every_grade(&r));
    assert_eq!(counts.0, [r.basis.len(); 3]);
    assert_eq!(done, 4);

    let vars = Vars::builder()
        .poisson("M1")
        .poisson("M2")
        .poisson("M3")
        .build()
        .unwrap();
    let e = |t: &str| Expr::parse(&vars, t).unwrap();
    let space = so3_space(&vars, &[], "M3");
    let top = System::new("top", space, e("M1^2/2 + M2^2 + 3*M3^2/2")).unwrap();
    let r = search(
        &top,
        &SearchOptions::new(SearchSpace::default().poisson_degree(4)),
    )
    .unwrap();
    let (counts, done) = eliminations(&r);
    assert_eq!(counts, poisson_counts_at_every_grade(&r));
    assert_eq!(counts.0, [1, 1, 3, 3, 6]);
    assert_eq!(done, 4);
}

/// The counts by degree in the Poisson variables are those of an elimination at every grade
/// in spaces that have Poisson variables, an angle and its momentum at once, where a basis
/// ordered by the momenta first mixes the grades: `(M₁ + iM₂)ⁿ e^{−inθ}` of the top turning
/// with the rotor (`H = n·M₃ + p_θ`, degree `n`, order `n`), beside `p_θ`, `M₃` and the
/// Casimir, at every Poisson degree to 3, trigonometric order to 2 and momenta degree to 2;
/// and in the harmonic rotor's 1:1 spaces of every degree to 3, which have no Poisson
/// variables.
#[test]
fn the_counts_by_poisson_degree_are_those_of_every_grade() {
    let vars = Vars::builder()
        .poisson("M1")
        .poisson("M2")
        .poisson("M3")
        .angle("theta")
        .momentum("p_theta")
        .build()
        .unwrap();
    let e = |t: &str| Expr::parse(&vars, t).unwrap();
    let space = so3_space(&vars, &[("theta", "p_theta")], "M3");
    let mut mixed = 0;
    for h in [
        "M3 + p_theta",
        "2*M3 + p_theta",
        "M3^2/2 + M1^2/2 + M2^2/2 + p_theta",
        "M3 + p_theta^2/2 + M1*cos(theta)",
        "M1^2/2 + M2^2 + M3^2 + p_theta^2/2 + M3*sin(2*theta)",
    ] {
        let top = System::new("turning top", space.clone(), e(h)).unwrap();
        for (p, t, m) in
            (0..=3).flat_map(|p| (0..=2).flat_map(move |t| (0..=2).map(move |m| (p, t, m))))
        {
            let space = SearchSpace::default()
                .poisson_degree(p)
                .trig_degree(t)
                .momenta_degree(m);
            let r = search(&top, &SearchOptions::new(space)).unwrap();
            let counts = (r.dimensions_by_poisson_degree(), r.poisson_counts());
            assert_eq!(
                counts,
                poisson_counts_at_every_grade(&r),
                "{h} in {space:?}"
            );
            // The basis integrals whose terms are of more than one grade.
            mixed += (r.term_grades().iter())
                .filter(|terms| terms.windows(2).any(|two| two[0].0 != two[1].0))
                .count();
        }
    }
    assert!(mixed > 0);
    let rotor = systems::harmonic_rotor();
    for d in 0..=3 {
        let space = SearchSpace::default()
            .momenta_degree(d)
            .positions_degree(d)
            .trig_degree(d)
            .poisson_degree(1);
        let r = search(&rotor, &at_one_to_one(&rotor, space)).unwrap();
        let counts = (r.dimensions_by_poisson_degree(), r.poisson_counts());
        assert_eq!(counts, poisson_counts_at_every_grade(&r), "degree {d}");
    }
}

/// A search space names each degree as it is set, where `SearchSpace::new(2, 0, 1)` took three
/// numbers in an order a reader had to remember: the default is the constants, and the
/// rotor's `H` (degree 2 in the momenta and in the coordinates) lies outside a space of
/// momenta degree 2 alone, for its coordinates.
#[test]
fn a_search_space_names_each_degree() {
    assert_eq!(
        SearchSpace::default(),
        SearchSpace {
            momenta_degree: 0,
            positions_degree: 0,
            trig_degree: 0,
            laurent: false,
            parameters_degree: 0,
            poisson_degree: 0,
            denominators_degree: 0,
            radicals_degree: 0,
        }
    );
    let space = SearchSpace::default().trig_degree(1).momenta_degree(2);
    let degrees = (
        space.momenta_degree,
        space.positions_degree,
        space.trig_degree,
    );
    assert_eq!(degrees, (2, 0, 1));
    let rotor = systems::harmonic_rotor();
    let h = rotor.hamiltonian();
    let why = space.why_outside(h).expect("H has coordinates");
    assert!(why.contains("coordinates"), "{why}");
    assert_eq!(space.positions_degree(2).why_outside(h), None);
}
