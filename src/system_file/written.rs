//! An expression written as a polynomial in `H` and the file's named functions, where it is
//! one ([`LoadedSystem::written_in_functions`]): what `check` adds under a refuted claim's
//! residual (`= −4 H L/M`) and `bracket` under a bracket. Where the bracket's arguments or
//! the claim mention family instances, the instances of every family at their indices are
//! functions too ([`LoadedSystem::written_in_functions_and_instances`]): `{L, P_{1,2}} =
//! −3 Q_{1,2}` of the Fock–Darwin file. Under each integral a search of a file shows, the
//! instances that are integrals at its condition and no larger than it
//! ([`LoadedSystem::integrals_in_functions_and_instances`]): `I91 = −8 Q_{1,2}`; and under
//! the amplitude `A` of each integral `Re(A e^{−ikθ})` it shows, the functions alone
//! ([`LoadedSystem::amplitudes_in_functions`]): `A7 = Z_y` of the 3D rotor at `Ω = ω`, an
//! integral no family names. The coefficients found are Gaussian rationals where the
//! functions or the expression are complex (`i Z_y`).
//!
//! Each search is made at fixed parameter values and lifted by homogeneity, then, where the
//! lift fails (parameters of one weight), with the expression's parameters kept symbolic; and
//! where that passes the monomial limits or finds nothing, once every such search is made,
//! with only the parameters the lift cannot restore symbolic, the others fixed and lifted
//! (`{P_{1,1}, H} = −(ω₋ − Ω) Q_{1,1}` of the Fock–Darwin rotor, `ω₋` symbolic beside
//! `ω₊` of its weight). Whatever is written is proved for every value of the parameters.

use brackets::closure::{expressed_in, ClosureOptions};
use brackets::scaling::Scaling;
use brackets::search::GENERIC_VALUES;
use brackets::{Condition, NamedFunction};
use rayon::prelude::*;
use trigpoly::syntax::{Expr as Tree, ExprKind};
use trigpoly::{Expr, GaussianRational, Rational, Var, VarKind};

use super::scope::{instance_of, substitute, Scope};
use super::LoadedSystem;

/// The degrees of the polynomials in `H` and the named functions that an expression is sought
/// among, highest first: the first whose monomials the limits below allow. Degree 1 is tried
/// only with family instances among the functions ([`LOWEST_WITH_INSTANCES`]).
const DEGREES: [u32; 3] = [3, 2, 1];

/// The lowest of [`DEGREES`] searched in the file's functions alone: a combination of them
/// is no news where their products cannot be sought.
const LOWEST: u32 = 2;

/// The lowest of [`DEGREES`] searched with family instances among the functions: an
/// instance's multiple, `{L, P_{5,5}} = −10 Q_{5,5}`, where its square would take more than
/// the term products allowed.
const LOWEST_WITH_INSTANCES: u32 = 1;

/// The most monomials the search may expand: degree 3 in up to 9 functions, degree 2 in up
/// to 20.
const MAX_MONOMIALS: u128 = 231;

/// The searches with the parameters kept symbolic, tried in turn: the degree of the
/// coefficients in the parameters, and the most monomials (products of the functions' and the
/// parameters' monomials) the search may take.
const SYMBOLIC_SEARCHES: [(u32, usize); 2] = [(2, 2_000), (4, 10_000)];

/// The largest index sum `m + n` of the family instances tried for a search's integrals
/// ([`LoadedSystem::integrals_in_functions_and_instances`]).
const MAX_INDEX_SUM: i64 = 8;

/// The most family instances expanded (and their brackets with `H` formed) for a search's
/// integrals, all of them together.
const MAX_INSTANCES_TRIED: usize = 60;

/// The most integrals a search's report restates, each by a linear algebra of its own (a few
/// milliseconds): one that shows more (the basis of a large space, of hundreds or thousands)
/// restates none; so with their amplitudes.
pub(crate) const MAX_INTEGRALS: usize = 32;

/// The most family instances among the functions for one of a search's integrals.
const MAX_INSTANCES_PER_INTEGRAL: usize = 8;

/// The most terms of an expression that is sought so: a longer one (a tower's residual, of a
/// million terms) is read as it is, not written into rows for the linear algebra.
const MAX_TERMS: usize = 5_000;

/// The most term products that expanding the monomials may take (the sum over the monomials
/// of the products of their functions' lengths): a file with a function of thousands of
/// terms is not searched, where its square alone would take millions.
const MAX_TERM_PRODUCTS: u128 = 200_000;

/// The highest of [`DEGREES`] down to `lowest` whose monomials in functions of `lengths`
/// terms stay within [`MAX_MONOMIALS`] and [`MAX_TERM_PRODUCTS`], if one does.
fn searchable_degree(lengths: &[usize], lowest: u32) -> Option<u32> {
    let top = DEGREES[0] as usize;
    // h[d]: the sum over the monomials of degree d of the products of their functions'
    // lengths (the complete homogeneous polynomials in the lengths), and n[d] the number of
    // those monomials (the same with every length 1).
    let (mut h, mut n) = (vec![0u128; top + 1], vec![0u128; top + 1]);
    (h[0], n[0]) = (1, 1);
    for &l in lengths {
        for d in 1..=top {
            h[d] = h[d].saturating_add((l as u128).saturating_mul(h[d - 1]));
            n[d] += n[d - 1];
        }
    }
    DEGREES
        .into_iter()
        .filter(|&d| d >= lowest)
        .find(|&degree| {
            let d = degree as usize;
            n[..=d].iter().sum::<u128>() <= MAX_MONOMIALS
                && h[1..=d].iter().fold(0u128, |a, &b| a.saturating_add(b)) <= MAX_TERM_PRODUCTS
        })
}

impl LoadedSystem {
    /// `e` (after `condition`) as a polynomial of degree `≤ 3` in `H` and the named
    /// functions (`≤ 2` where they are more than 9 with `H`, or long), proved for every value
    /// of the parameters, when it is one with a function in it: `−4 H L/M` for the residual of
    /// `{A_x, A_y} = 2 H L/M`, whose sign is turned. Its variables are the parameters and one
    /// symbol per function, printed by its display name. It only helps to read `e`: when
    /// there is none, or the search stops at its limit or on a condition it cannot apply, or
    /// `e` has more than 5 000 terms, or the functions' monomials of degree 2 would take more
    /// than 231 monomials or 200 000 term products, it is `None`.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let kepler = load("systems/kepler.toml", &LimitsOverride::default())?;
    /// let bracket = kepler.parse("{Ax, Ay}")?;
    /// let written = kepler.written_in_functions(&bracket, None).expect("a polynomial");
    /// assert_eq!(written.to_string(), "−2 H L/M");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn written_in_functions(&self, e: &Expr, condition: Option<&Condition>) -> Option<Expr> {
        self.written_in(e, condition, Reach::WithSymbolicParameters, &[])
    }

    /// [`LoadedSystem::written_in_functions`] with the instances of every family at each
    /// pair of `indices` among the functions, each a symbol printed as the instance is
    /// (`Q_{1,2}`, `Q_1_2` in ASCII, which reads back): what `bracket` writes where its
    /// arguments mention instances (and `check` where a claim does). An instance that
    /// cannot be expanded (past a limit), is zero or equals a function is left out. The
    /// instances may lower the degree searched (more than 9 functions, or long ones), to 1
    /// where their squares would pass the term products allowed (`{L, P_{5,5}} = −10 Q_{5,5}`);
    /// where nothing is found with them, the file's functions alone are then searched as
    /// without them.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let fd = load("systems/fock-darwin.toml", &LimitsOverride::default())?;
    /// let bracket = fd.parse("{L, P_1_2}")?;
    /// let written = fd.written_in_functions_and_instances(&bracket, None, &[(1, 2)]);
    /// assert_eq!(written.expect("a polynomial").to_string(), "−3 Q_{1,2}");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn written_in_functions_and_instances(
        &self,
        e: &Expr,
        condition: Option<&Condition>,
        indices: &[(i64, i64)],
    ) -> Option<Expr> {
        self.written_in(e, condition, Reach::WithSymbolicParameters, indices)
    }

    /// Each of `integrals`, integrals of `H` (at `condition`) as `superint search` finds
    /// them, as a polynomial in `H`, the file's functions and the instances of its families
    /// that may take part in it, where it is one: `I91 = −8 Q_{1,2}` for the Fock–Darwin
    /// search at `a = 2b`. The instances are those at indices `m, n ≥ 0` that are integrals
    /// themselves at `condition` (their bracket with `H` vanishes there) and of no larger
    /// degree than the integral in the coordinates, the momenta, the Poisson variables and
    /// the trigonometric order, each kind on its own: a product `Q_{1,2} L` may take part,
    /// a larger instance may not. Every index of a family adds at least one to the degree or
    /// the order of its instances (powers of ladder functions times `e^{−inθ}`, as in every
    /// family of `systems/`), so `m + n` goes up to the largest integral's degree and order
    /// together (at most 8), and at most 60 instances are expanded for all the integrals; an
    /// integral is sought among its first 8 (lowest `m + n` first) and the functions, as
    /// [`LoadedSystem::written_in_functions_and_instances`] seeks an expression, and alone
    /// among the functions where the instances lowered the degree and found nothing. `None`
    /// where there is none, or an integral has more than 5 000 terms, and for every one of
    /// more than 32 integrals (a basis of hundreds, each integral a linear algebra of its
    /// own: a search's report that shows so many restates none). Each form found is
    /// proved for every value of the parameters, so that it expands back to the integral.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let fd = load("systems/fock-darwin.toml", &LimitsOverride::default())?;
    /// let when = fd.condition("a = 2*b")?;
    /// let found = fd.parse("8*P_1_2")?;
    /// let written = fd.integrals_in_functions_and_instances(&[found], Some(&when));
    /// assert_eq!(written[0].as_ref().expect("a polynomial").to_string(), "8 P_{1,2}");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn integrals_in_functions_and_instances(
        &self,
        integrals: &[Expr],
        condition: Option<&Condition>,
    ) -> Vec<Option<Expr>> {
        if integrals.len() > MAX_INTEGRALS {
            return vec![None; integrals.len()];
        }
        let functions = self.generators();
        // The largest degree and order together, which bounds `m + n`.
        let largest = integrals
            .iter()
            .map(|e| degrees(e).iter().sum::<i64>())
            .max()
            .unwrap_or(0);
        let pool = self.integral_instances(condition, largest.min(MAX_INDEX_SUM), &functions);
        integrals
            .par_iter()
            .map(|e| {
                if e.len() > MAX_TERMS {
                    return None;
                }
                let bound = degrees(e);
                let instances = pool
                    .iter()
                    .filter(|(_, d)| d.iter().zip(&bound).all(|(d, b)| d <= b))
                    .take(MAX_INSTANCES_PER_INTEGRAL)
                    .map(|(f, _)| f.clone())
                    .collect();
                let reach = Reach::WithSymbolicParameters;
                self.written_with(e, condition, reach, functions.clone(), instances)
            })
            .collect()
    }

    /// Each of `amplitudes`, the amplitudes `A` of integrals `Re(A e^{−ikθ})` that
    /// `superint search` shows (at `condition`), as a polynomial in `H` and the file's
    /// functions, where it is one, as [`LoadedSystem::written_in_functions`] seeks an
    /// expression: `Z_y` for `p_y + iMωy` of the 3D rotor at `Ω = ω`, `i Z_y` for
    /// `i p_y − Mωy`, `Z_y Z_z` at `Ω = 2ω`. An amplitude need not be an integral, so no
    /// family instance takes part (they are tried as integrals only); each form is an
    /// identity on the phase space (at `condition`), proved for every value of the
    /// parameters. `None` where there is none, and for every one of more than 32 amplitudes,
    /// as for the integrals ([`LoadedSystem::integrals_in_functions_and_instances`]).
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let rotor = load("systems/isotropic-rotor-3d.toml", &LimitsOverride::default())?;
    /// let when = rotor.condition("p_theta = I*omega")?;
    /// let amplitudes = [rotor.parse("i*p_y - M*omega*y")?, rotor.parse("p_y + M*omega*y")?];
    /// let written = rotor.amplitudes_in_functions(&amplitudes, Some(&when));
    /// assert_eq!(written[0].as_ref().expect("a polynomial").to_string(), "i Z_y");
    /// assert!(written[1].is_none());
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn amplitudes_in_functions(
        &self,
        amplitudes: &[Expr],
        condition: Option<&Condition>,
    ) -> Vec<Option<Expr>> {
        if amplitudes.len() > MAX_INTEGRALS {
            return vec![None; amplitudes.len()];
        }
        // An amplitude that is a constant times one before it (`i A`, that of the other part
        // of one complex integral) is that constant times its form: one search for the two.
        let multiple_of: Vec<Option<(usize, GaussianRational)>> = (0..amplitudes.len())
            .map(|j| {
                (0..j).find_map(|i| constant_ratio(&amplitudes[i], &amplitudes[j]).map(|c| (i, c)))
            })
            .collect();
        let searched: Vec<Option<Expr>> = amplitudes
            .par_iter()
            .zip(&multiple_of)
            .map(|(a, multiple)| match multiple {
                // A form that divides by a parameter the amplitude does not is proved but
                // reads worse than the amplitude: the gravity rotor's `p_x + iMωx` as
                // `ω(ω L − ω L′ − 2i G1 + 2i G1′)/g`, where `G1′ − G1` is a multiple of `g`.
                None => self
                    .written_in_functions(a, condition)
                    .filter(|w| !divides_by_more(w, a)),
                Some(_) => None,
            })
            .collect();
        // The first amplitude `j` is a multiple of is itself a multiple of none: one before
        // it would have been found first.
        multiple_of
            .iter()
            .enumerate()
            .map(|(j, multiple)| match multiple {
                None => searched[j].clone(),
                Some((i, c)) => searched[*i].as_ref().map(|w| w.scale(c)),
            })
            .collect()
    }

    /// The instances of the families at `m, n ≥ 0`, `m + n ≤ max_sum` (lowest sum first, but
    /// those whose declared eigenvalue is not zero at `condition` last; at most
    /// [`MAX_INSTANCES_TRIED`] expanded) that are integrals at `condition`, with their
    /// [`degrees`] there: those that cannot be expanded, equal one of `generators` or an
    /// instance before them, or are no function of the phase space there, are left out.
    fn integral_instances(
        &self,
        condition: Option<&Condition>,
        max_sum: i64,
        generators: &[NamedFunction],
    ) -> Vec<(NamedFunction, [i64; 4])> {
        let h = self.system.hamiltonian();
        let at = |e: Expr| at_condition(condition, e);
        let mut found: Vec<(NamedFunction, [i64; 4])> = Vec::new();
        let pairs = (0..=max_sum).flat_map(|sum| (0..=sum).map(move |m| (m, sum - m)));
        let mut instances: Vec<(usize, i64, i64)> = pairs
            .flat_map(|(m, n)| (0..self.families.len()).map(move |k| (k, m, n)))
            .collect();
        // Those whose declared eigenvalue is not zero there are no integrals (the tower proves
        // the eigenvalues): tried after the rest (the sort keeps the order of equal keys, so
        // the lowest sum first), so that `e^{−inθ}` and `A^m` do not spend the tries. Each
        // key, an eigenvalue lowered, is computed once.
        instances.sort_by_cached_key(|&(k, m, n)| self.eigenvalue_is_not_zero(k, m, n, condition));
        for (k, m, n) in instances.into_iter().take(MAX_INSTANCES_TRIED) {
            let Ok(value) = self.family_instance(k, m, n) else {
                continue;
            };
            let known = generators
                .iter()
                .chain(found.iter().map(|(f, _)| f))
                .any(|g| g.expr == value);
            if known {
                continue;
            }
            let Some(there) = at(value.clone()) else {
                continue;
            };
            let d = degrees(&there);
            // Zero, a constant or a function of the parameters alone there.
            if d.iter().all(|&d| d == 0) {
                continue;
            }
            // `{K, H} = 0` at the condition, decided exactly.
            let flow = self.system.bracket(&value, h).ok().and_then(at);
            if !flow.is_some_and(|f| f.vanishes().unwrap_or(false)) {
                continue;
            }
            found.push((self.instance_function(k, m, n, value), d));
        }
        found
    }

    /// Whether the instance `(m, n)` of family `k` has an eigenvalue that is not zero at
    /// `condition`, and so is no integral there: the family's own, or, for a real or imaginary
    /// part `re(K_m_n)` of a family with one, that of `K`'s instance (`{K, H} = λK` with
    /// `λ ≠ 0` moves `Re K` as well). `false` where there is none, or it cannot be computed.
    fn eigenvalue_is_not_zero(
        &self,
        k: usize,
        m: i64,
        n: i64,
        condition: Option<&Condition>,
    ) -> bool {
        let instance = match self.families[k].eigenvalue {
            Some(_) => Some((k, m, n)),
            None => self.part_of_instance(k, m, n),
        };
        let lambda = instance.and_then(|(k, m, n)| self.eigenvalue_at(k, m, n).ok());
        lambda
            .and_then(|l| at_condition(condition, l))
            .is_some_and(|l| !l.is_zero())
    }

    /// For a family `k` whose value is the real or imaginary part of an instance of a family
    /// with an eigenvalue (`P = re(K_m_n)`), that instance at `(m, n)`: `(K, m, n)`.
    fn part_of_instance(&self, k: usize, m: i64, n: i64) -> Option<(usize, i64, i64)> {
        let family = &self.families[k];
        let tree = Scope::of_family(self, k)
            .tree(&family.source, &family.value)
            .ok()?;
        let tree = substitute(&tree, &family.indices, [m, n], &self.families[..k]);
        let ExprKind::Call(f, _, args) = &tree.kind else {
            return None;
        };
        let ([arg], "re" | "im") = (&args[..], f.as_str()) else {
            return None;
        };
        let ExprKind::Name(name) = &arg.kind else {
            return None;
        };
        instance_of(&self.families, name).filter(|&(j, _, _)| self.families[j].eigenvalue.is_some())
    }

    /// The index pairs of the family instances that `trees` name (`P_1_2` → `(1, 2)`, braces
    /// already rewritten), each once, in order of first mention.
    pub(crate) fn mentioned_indices<'t>(
        &self,
        trees: impl IntoIterator<Item = &'t Tree>,
    ) -> Vec<(i64, i64)> {
        let mut out = Vec::new();
        // A name before parentheses multiplies them (`K_1_1(x)`): the called names too.
        for (name, _) in trees.into_iter().flat_map(|t| t.names_with_calls(true)) {
            if let Some((_, m, n)) = instance_of(&self.families, name) {
                if !out.contains(&(m, n)) {
                    out.push((m, n));
                }
            }
        }
        out
    }

    /// `H` unless a function is it (the rotor's `F1`), and the file's functions: two equal
    /// generators would leave the choice between them to the linear algebra.
    fn generators(&self) -> Vec<NamedFunction> {
        let functions = self.system.functions();
        let h = self.system.hamiltonian();
        let mut generators = Vec::with_capacity(functions.len() + 1);
        if functions.iter().all(|f| f.name != "H" && f.expr != *h) {
            generators.push(NamedFunction::new("H", "H", h.clone()));
        }
        generators.extend(functions.iter().cloned());
        generators
    }

    /// The instances of every family at each pair of `indices`, named as an expression names
    /// them (`Q_1_2`) and shown as printed (`Q_{1,2}`), but those that cannot be expanded, are
    /// zero or equal one of `generators` or an instance before them.
    fn instances_at(
        &self,
        indices: &[(i64, i64)],
        generators: &[NamedFunction],
    ) -> Vec<NamedFunction> {
        let mut instances: Vec<NamedFunction> = Vec::new();
        for &(m, n) in indices {
            for k in 0..self.families.len() {
                let Ok(value) = self.family_instance(k, m, n) else {
                    continue;
                };
                let known = generators.iter().chain(&instances).any(|g| g.expr == value);
                if value.is_zero() || known {
                    continue;
                }
                instances.push(self.instance_function(k, m, n, value));
            }
        }
        instances
    }

    /// The instance `value` of family `k` at `(m, n)` as a function, named as an expression
    /// names it (`Q_1_2`) and shown as printed (`Q_{1,2}`).
    fn instance_function(&self, k: usize, m: i64, n: i64, value: Expr) -> NamedFunction {
        let family = &self.families[k];
        let name = format!("{}_{m}_{n}", family.name);
        let display = format!("{}_{{{m},{n}}}", family.display);
        NamedFunction::new(&name, &display, value)
    }

    /// [`LoadedSystem::written_in_functions`] among the functions and the instances at
    /// `indices`, with the last search (the parameters kept symbolic) only when `reach`
    /// allows it.
    pub(crate) fn written_in(
        &self,
        e: &Expr,
        condition: Option<&Condition>,
        reach: Reach,
        indices: &[(i64, i64)],
    ) -> Option<Expr> {
        if e.len() > MAX_TERMS {
            return None;
        }
        let functions = self.generators();
        let instances = self.instances_at(indices, &functions);
        self.written_with(e, condition, reach, functions, instances)
    }

    /// [`LoadedSystem::written_in`] among `functions` (`H` and the file's) and `instances`:
    /// with the instances first, then, where that found nothing at a lower degree, the
    /// functions alone; then, where either found a polynomial at fixed values only, that
    /// search again with fewer parameters symbolic ([`Among::Fewer`]), in the same order.
    fn written_with(
        &self,
        e: &Expr,
        condition: Option<&Condition>,
        reach: Reach,
        functions: Vec<NamedFunction>,
        instances: Vec<NamedFunction>,
    ) -> Option<Expr> {
        // A function of the parameters alone (`−16M³ω²β`) reads best as it is: written in
        // the functions it could only be a relation among them (`−8M² H_x² − 2 K² + 4 K P`).
        if holds_only_parameters(e) {
            return None;
        }
        let degree = |g: &[NamedFunction], lowest| {
            let lengths: Vec<usize> = g.iter().map(|g| g.expr.len()).collect();
            searchable_degree(&lengths, lowest)
        };
        let alone = degree(&functions, LOWEST);
        // The searches in turn: with the instances (if any), then the functions alone where
        // the instances lowered the degree (more functions, or longer ones).
        let mut searches: Vec<(Vec<NamedFunction>, u32)> = Vec::new();
        let mut with = None;
        if !instances.is_empty() {
            let mut generators = functions.clone();
            generators.extend(instances);
            with = degree(&generators, LOWEST_WITH_INSTANCES);
            searches.extend(with.map(|d| (generators, d)));
        }
        // (Without instances `with` is none, and the functions alone are searched where
        // they can be.)
        if with != alone {
            searches.extend(alone.map(|d| (functions, d)));
        }
        self.written_first(e, condition, reach, &searches)
    }

    /// The first of `searches` (generators and degree) that writes `e` as
    /// [`LoadedSystem::written_among`] does; then, for those that found it at fixed values
    /// only, the first that does with only the parameters the lift cannot restore symbolic.
    fn written_first(
        &self,
        e: &Expr,
        condition: Option<&Condition>,
        reach: Reach,
        searches: &[(Vec<NamedFunction>, u32)],
    ) -> Option<Expr> {
        let mut fewer = Vec::new();
        for (generators, degree) in searches {
            match self.written_among(e, condition, reach, generators, *degree) {
                Among::Written(poly) => return Some(poly),
                Among::Nothing => {}
                Among::Fewer(kept) => fewer.push((generators, *degree, kept)),
            }
        }
        fewer.into_iter().find_map(|(generators, degree, kept)| {
            self.written_symbolic(e, condition, generators, degree, &kept)
        })
    }

    /// The options of a search of `e` of degree `≤ degree` in the generators, at
    /// `condition`.
    fn among_options(condition: Option<&Condition>, degree: u32) -> ClosureOptions {
        let mut options = ClosureOptions::new(degree).max_monomials(MAX_MONOMIALS as usize);
        if let Some(c) = condition {
            options = options.when(c.clone());
        }
        options
    }

    /// `options` with every parameter fixed at its [`GENERIC_VALUES`] entry.
    fn at_generic_values(&self, options: &ClosureOptions) -> ClosureOptions {
        let vars = self.system.vars();
        vars.vars()
            .filter(|&v| vars.variable(v).kind() == VarKind::Parameter)
            .zip(GENERIC_VALUES)
            .fold(options.clone(), |o, (v, (n, d))| {
                o.fix(v, Rational::new(n, d))
            })
    }

    /// One search of `e` among `generators` with `options`.
    fn search(&self, e: &Expr, generators: &[NamedFunction], options: &ClosureOptions) -> Search {
        match expressed_in(&self.system, generators, e, options) {
            Ok(None) => Search::Nothing,
            Ok(Some(found)) if found.symbolic => {
                // A polynomial in the parameters alone is no form in the functions.
                match holds_only_parameters(&found.poly) {
                    false => Search::Written(found.poly),
                    true => Search::Nothing,
                }
            }
            Ok(Some(_)) | Err(_) => Search::AtTheseValues,
        }
    }

    /// `e` written as a polynomial of degree `≤ degree` in the `generators`, as
    /// [`LoadedSystem::written_in`] searches: at the parameters fixed to 1, then at generic
    /// values, then (as `reach` allows) with every parameter of `e` symbolic.
    fn written_among(
        &self,
        e: &Expr,
        condition: Option<&Condition>,
        reach: Reach,
        generators: &[NamedFunction],
        degree: u32,
    ) -> Among {
        let options = Self::among_options(condition, degree);
        match self.search(e, generators, &options) {
            Search::Written(poly) => return Among::Written(poly),
            Search::Nothing => return Among::Nothing,
            // The parameters are fixed to 1 for the linear algebra (or moved off a declared
            // denominator that 1 makes zero), and that is a special point (the Euler top's
            // `H = C/2` at `I1 = I2 = I3 = 1`): the search is made again at values that are
            // not.
            Search::AtTheseValues => {}
        }
        match self.search(e, generators, &self.at_generic_values(&options)) {
            Search::Written(poly) => return Among::Written(poly),
            Search::Nothing => return Among::Nothing,
            // A combination that holds at these values too, but that homogeneity cannot
            // lift (`(a − b) F` for `axy − bxy`, `a` and `b` of one weight): sought once
            // more with the parameters of `e` kept symbolic.
            Search::AtTheseValues if reach == Reach::AtValues => return Among::Nothing,
            Search::AtTheseValues => {}
        }
        let vars = self.system.vars();
        let of_e: Vec<Var> = vars
            .vars()
            .filter(|&v| vars.variable(v).kind() == VarKind::Parameter && e.contains(v))
            .collect();
        if of_e.is_empty() {
            return Among::Nothing;
        }
        if let Some(poly) = self.written_symbolic(e, condition, generators, degree, &of_e) {
            return Among::Written(poly);
        }
        // Every one of them symbolic passes the monomial limits, or finds nothing: only those
        // the lift cannot restore may (`ω₋` of the Fock–Darwin rotor, of `ω₊`'s weight), the
        // others fixed and lifted.
        let undetermined = undetermined_parameters(&self.system, generators, condition, &of_e);
        match undetermined.is_empty() || undetermined.len() == of_e.len() {
            true => Among::Nothing,
            false => Among::Fewer(undetermined),
        }
    }

    /// `e` written as [`LoadedSystem::written_among`] does with the parameters `kept`
    /// symbolic and the others at their generic values, lifted by homogeneity and proved.
    fn written_symbolic(
        &self,
        e: &Expr,
        condition: Option<&Condition>,
        generators: &[NamedFunction],
        degree: u32,
        kept: &[Var],
    ) -> Option<Expr> {
        let mut generic = self.at_generic_values(&Self::among_options(condition, degree));
        // The other parameters stay at the generic values.
        generic.fixed.retain(|(v, _)| !kept.contains(v));
        // Low degree first, which the monomial limit refuses the least: most brackets need
        // no more (`{K, Q} = 256ω²αβ H_x + …` of the caged oscillator needs degree 4).
        SYMBOLIC_SEARCHES
            .into_iter()
            .find_map(|(degree, max_monomials)| {
                let symbolic = kept.iter().fold(
                    generic
                        .clone()
                        .max_monomials(max_monomials)
                        .parameters_degree(degree),
                    |o, &v| o.symbolic(v),
                );
                match self.search(e, generators, &symbolic) {
                    Search::Written(poly) => Some(poly),
                    _ => None,
                }
            })
    }
}

/// The parameters among `of_e` that the homogeneity lift cannot restore once fixed: those
/// whose weights (under which `generators` and `condition` are homogeneous) depend on those of
/// the parameters before them, the parameters of the generators not in `of_e` first (they stay
/// fixed, and the lift restores them too). `ω₋` of the Fock–Darwin rotor, of `ω₊`'s weight
/// (its `ω̄ = (ω₊ + ω₋)/2` is homogeneous), where `M, ω₊, I` are restored: kept symbolic alone,
/// it finds `{P_{1,1}, H} = −(ω₋ − Ω) Q_{1,1}` with 3 parameter monomials to each of the 210
/// of degree `≤ 2` in the functions and the instances at `(1, 1)`, where all four would take 15
/// (3150 monomials, past the limit of 2000). Every one of `of_e` where the weights cannot be
/// found.
fn undetermined_parameters(
    system: &brackets::System,
    generators: &[NamedFunction],
    condition: Option<&Condition>,
    of_e: &[Var],
) -> Vec<Var> {
    let exprs: Vec<Expr> = generators.iter().map(|g| g.expr.clone()).collect();
    let Ok(scaling) = Scaling::of_functions(system.space(), &exprs, condition) else {
        return of_e.to_vec();
    };
    let vars = system.vars();
    let others = vars.vars().filter(|&v| {
        vars.variable(v).kind() == VarKind::Parameter
            && !of_e.contains(&v)
            && exprs.iter().any(|g| g.contains(v))
    });
    // The values are of no account to the rank, only that they are not zero.
    let mut fixed: Vec<(Var, Rational)> = Vec::new();
    let mut undetermined = Vec::new();
    for v in others.chain(of_e.iter().copied()) {
        fixed.push((v, Rational::one()));
        if scaling.lifter(&fixed).is_none() {
            fixed.pop();
            if of_e.contains(&v) {
                undetermined.push(v);
            }
        }
    }
    undetermined
}

/// The degrees of `e` in the coordinates, the momenta and the Poisson variables, and its
/// trigonometric order: what an instance must not pass to take part in writing an integral
/// ([`LoadedSystem::integrals_in_functions_and_instances`]).
fn degrees(e: &Expr) -> [i64; 4] {
    [
        VarKind::Coordinate,
        VarKind::Momentum,
        VarKind::Poisson,
        VarKind::Angle,
    ]
    .map(|kind| e.total_degree(&[kind]).unwrap_or(0))
}

/// The constant `c` with `b = c a`, where there is one: `i` for `a = p_y + iMωy` and
/// `b = i p_y − Mωy`.
fn constant_ratio(a: &Expr, b: &Expr) -> Option<GaussianRational> {
    if a.len() != b.len() || a.vars() != b.vars() {
        return None;
    }
    let first = a.terms().next()?;
    let exponents = first.exponents();
    let other = b.terms().find(|t| t.exponents() == exponents)?;
    let c = &other.coeff() * &first.coeff().try_inv()?;
    (a.scale(&c) == *b).then_some(c)
}

/// Whether `form` holds a negative power of a parameter that `e` holds to no lower one
/// (`1/g` in a form of `p_x + iMωx`); the two may be in rings of their own, so a parameter is
/// matched by its name.
fn divides_by_more(form: &Expr, e: &Expr) -> bool {
    let (vars, of_e) = (form.vars(), e.vars());
    vars.vars()
        .filter(|&v| vars.variable(v).kind() == VarKind::Parameter)
        .any(|v| {
            let low = form.low_degree(v).unwrap_or(0);
            let low_in_e = of_e
                .lookup(vars.variable(v).name())
                .and_then(|w| e.low_degree(w))
                .unwrap_or(0);
            low < low_in_e.min(0)
        })
}

/// Whether `e` holds no variable but parameters: a constant on the phase space, or in a ring
/// of functions' symbols a polynomial in no function.
fn holds_only_parameters(e: &Expr) -> bool {
    let vars = e.vars();
    vars.vars()
        .all(|v| vars.variable(v).kind() == VarKind::Parameter || !e.contains(v))
}

/// How far [`LoadedSystem::written_in`] searches.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Reach {
    /// At fixed values of the parameters (1, then generic values) only: for the residual of
    /// a claim with no bracket, `lhs − rhs` of functions, which a search with the parameters
    /// kept symbolic finds as the claim itself, restated.
    AtValues,
    /// Then with the parameters of the expression kept symbolic.
    WithSymbolicParameters,
}

/// What [`LoadedSystem::written_among`] found.
enum Among {
    /// A polynomial in the generators, proved for every value of the parameters.
    Written(Expr),
    /// None, or none that the searches it may make prove.
    Nothing,
    /// A polynomial at fixed values only, which none with every parameter of the expression
    /// symbolic gave: these, those the lift cannot restore, may give it kept symbolic alone
    /// ([`LoadedSystem::written_symbolic`]).
    Fewer(Vec<Var>),
}

/// What one search of [`LoadedSystem::written_in_functions`] at fixed parameter values found.
enum Search {
    /// A polynomial in the functions, proved for every value of the parameters.
    Written(Expr),
    /// No polynomial in the functions: none at these values, so none for every value (one
    /// for every value holds at these values too, where no denominator vanishes).
    Nothing,
    /// A polynomial that holds at these values only, or a denominator zero there.
    AtTheseValues,
}

/// `e` at `condition` where one is given, `None` where it cannot be applied.
fn at_condition(condition: Option<&Condition>, e: Expr) -> Option<Expr> {
    match condition {
        Some(c) => c.apply(&e).ok(),
        None => Some(e),
    }
}

#[cfg(test)]
mod tests {
    use crate::system_file::{load, load_str, LimitsOverride};

    /// Degree 3 for up to 9 short functions, 2 for more or for longer ones, none where even
    /// the squares would pass the term products allowed.
    #[test]
    fn the_degree_searched_follows_the_functions() {
        use super::{searchable_degree, LOWEST, LOWEST_WITH_INSTANCES};
        assert_eq!(searchable_degree(&[4, 2, 4, 2], LOWEST), Some(3));
        assert_eq!(searchable_degree(&[5; 9], LOWEST), Some(3));
        assert_eq!(searchable_degree(&[5; 10], LOWEST), Some(2));
        assert_eq!(searchable_degree(&[4, 2, 60], LOWEST), Some(2));
        assert_eq!(searchable_degree(&[4, 2, 10_626], LOWEST), None);
        assert_eq!(searchable_degree(&[usize::MAX, 3], LOWEST), None);
        // With instances, their multiples where their squares are too long.
        let instances = LOWEST_WITH_INSTANCES;
        assert_eq!(searchable_degree(&[4, 2, 10_626], instances), Some(1));
        assert_eq!(searchable_degree(&[5; 10], instances), Some(2));
        assert_eq!(searchable_degree(&[usize::MAX, 3], instances), None);
    }

    /// The instances that may restate the Fock–Darwin integrals at `a = 2b`, up to
    /// `m + n = 3`, are the integrals there: the parts of `K_{1,2}`, not `K_{1,1}` nor
    /// `K_{0,0} = 1`; for every `a, b`, none. An integral that is no polynomial in the
    /// functions and those instances (the rotor's `Re(a_y e^{−iθ})` at 1:1, `W e^{−iθ}` with
    /// `Z e^{−iθ}`) has no form.
    #[test]
    fn the_instances_tried_are_integrals_at_the_condition() {
        let fd = load("systems/fock-darwin.toml", &LimitsOverride::default()).unwrap();
        let when = fd.condition("a = 2*b").unwrap();
        let generators = fd.generators();
        let pool = fd.integral_instances(Some(&when), 3, &generators);
        let names: Vec<&str> = pool.iter().map(|(f, _)| f.name.as_str()).collect();
        assert_eq!(names, ["K_1_2", "P_1_2", "Q_1_2"]);
        assert_eq!(pool[1].1, [3, 3, 0, 0], "degrees of P_{{1,2}}");
        assert!(fd.integral_instances(None, 3, &generators).is_empty());
        let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default()).unwrap();
        let resonance = rotor.condition("p_theta = I*omega").unwrap();
        let mode = rotor
            .parse("p_y*cos(theta) + M*omega*y*sin(theta)")
            .unwrap();
        let paper = rotor.parse("2*P_1_1").unwrap();
        let written = rotor.integrals_in_functions_and_instances(&[mode, paper], Some(&resonance));
        let written: Vec<Option<String>> = written
            .iter()
            .map(|w| w.as_ref().map(|w| w.to_string()))
            .collect();
        assert_eq!(written, [None, Some("2 P_{1,1}".to_string())]);
    }

    /// An amplitude that is a constant times one before it is written as that multiple of its
    /// form, as a search of its own writes it (`i Z_y`, `−2 Z_y`); one that is no multiple,
    /// or has no form, is searched or left as it is.
    #[test]
    fn a_multiple_of_an_amplitude_is_written_as_that_multiple_of_its_form() {
        use super::constant_ratio;
        let rotor = load(
            "systems/isotropic-rotor-3d.toml",
            &LimitsOverride::default(),
        )
        .unwrap();
        let when = rotor.condition("p_theta = I*omega").unwrap();
        let parse = |e: &str| rotor.parse(e).unwrap();
        let amplitudes = [
            "p_y + i*M*omega*y",
            "i*p_y - M*omega*y",
            "p_y + M*omega*y",
            "-2*p_y - 2*i*M*omega*y",
            "2*p_y + 2*M*omega*y",
            "p_x + i*M*omega*x",
        ]
        .map(parse);
        let ratio = constant_ratio(&amplitudes[0], &amplitudes[1]);
        assert_eq!(ratio.map(|c| c.to_string()).as_deref(), Some("i"));
        assert!(constant_ratio(&amplitudes[0], &amplitudes[2]).is_none());
        assert!(constant_ratio(&amplitudes[0], &amplitudes[5]).is_none());
        let written = rotor.amplitudes_in_functions(&amplitudes, Some(&when));
        let written: Vec<Option<String>> = written
            .iter()
            .map(|w| w.as_ref().map(|w| w.to_string()))
            .collect();
        let some = |s: &str| Some(s.to_string());
        assert_eq!(
            written,
            [
                some("Z_y"),
                some("i Z_y"),
                None,
                some("−2 Z_y"),
                None,
                some("Z_x")
            ]
        );
        for (a, w) in amplitudes.iter().zip(&written) {
            let alone = rotor.written_in_functions(a, Some(&when));
            assert_eq!(alone.map(|w| w.to_string()), *w, "{a}");
        }
    }

    /// The Fock–Darwin rotor's `ω₊, ω₋` share a weight (its `ω̄ = (ω₊ + ω₋)/2` is
    /// homogeneous), so the lift restores `M, ω₊, I` and not `ω₋` beside them; the harmonic
    /// rotor's `M, ω, I` are all restored.
    #[test]
    fn the_parameters_kept_symbolic_are_those_the_lift_cannot_restore() {
        use super::undetermined_parameters;
        for (file, undetermined) in [
            ("systems/fock-darwin-rotor.toml", vec!["b"]),
            ("systems/harmonic-rotor.toml", vec![]),
        ] {
            let file = load(file, &LimitsOverride::default()).unwrap();
            let system = file.system();
            let vars = system.vars();
            let parameters: Vec<_> = ["M", "a", "b", "omega", "I"]
                .into_iter()
                .filter_map(|p| vars.lookup(p))
                .collect();
            let generators = file.generators();
            let kept = undetermined_parameters(system, &generators, None, &parameters);
            let names: Vec<&str> = kept.iter().map(|&v| vars.variable(v).name()).collect();
            assert_eq!(names, undetermined);
        }
    }

    /// A file with `L` and `B = (1 + x + y + p_x + p_y)^k`.
    fn with_power(k: u32) -> crate::system_file::LoadedSystem {
        let text = format!(
            "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
             [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
             [[function]]\nname = \"B\"\nvalue = \"(1 + x + y + p_x + p_y)^{k}\"\n\
             [[function]]\nname = \"L\"\nvalue = \"x*p_y - y*p_x\"\n"
        );
        load_str("power.toml", &text, &LimitsOverride::default()).expect("the file loads")
    }

    /// `2L + B` is written in the functions while they are short, and not sought once the
    /// squares of the functions would take more than the products allowed (`B` of 10 626
    /// terms at `k = 20`).
    #[test]
    fn long_functions_are_not_searched() {
        for (k, written) in [(2, Some("B + 2 L")), (20, None)] {
            let file = with_power(k);
            let e = file.parse("2*L + B").unwrap();
            let found = file.written_in_functions(&e, None).map(|w| w.to_string());
            assert_eq!(found.as_deref(), written, "k = {k}");
        }
    }
}
