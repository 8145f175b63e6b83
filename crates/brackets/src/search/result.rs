//! What a search returns: the basis of integrals, which are new, the parameter module, timings.

use std::collections::HashMap;

use itertools::Itertools;

use trigpoly::{Expr, Rational, Style, Var, VarKind, VarSet, Vars};

use crate::modular::{self, SparseVec};

use super::level_set::{LevelProof, LevelSet};
use super::options::SearchSpace;

/// One basis element of the integrals found. Two are equal when they are the same function
/// with the same degrees and the same proofs: a search is deterministic, so the same search
/// twice finds equal bases.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Integral {
    /// The integral at the fixed parameter values, with coprime integer coefficients.
    pub fixed: Expr,
    /// Whether the engine found `{F, H} = 0` (after the condition) at the fixed values.
    pub proved_fixed: bool,
    /// The integral with its parameters, if lifting and the symbolic proof succeeded.
    pub symbolic: Option<Expr>,
    /// Degree in the momenta.
    pub momenta_degree: i64,
    /// Degree `Σ|a|` in the coordinates.
    pub positions_degree: i64,
    /// Degree in the Poisson variables.
    pub poisson_degree: i64,
    /// Trigonometric order.
    pub trig_degree: i64,
    /// On a level set ([`SearchOptions::on`](super::SearchOptions::on)), the proof of
    /// [`Integral::expr`]: `{K, H} = P·Q` with `P` at the same parameters; `None` elsewhere,
    /// and where the proof failed.
    pub on_level: Option<LevelProof>,
}

impl Integral {
    /// The integral as printed: symbolic if it was lifted, otherwise at the fixed values,
    /// where alone it may hold; [`SearchResult::for_every_value`] says which.
    pub fn expr(&self) -> &Expr {
        self.symbolic.as_ref().unwrap_or(&self.fixed)
    }
}

/// The level set a search was restricted to: as given, its polynomial `P`, the leading
/// monomial `LM(P)` of the order the division takes, and how many of the space's unknowns it
/// divides, left out.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SearchedLevel {
    /// The level set as given.
    pub level: LevelSet,
    /// Whether the flow of `H` keeps it for every value of the parameters, not only at the
    /// fixed values.
    pub kept_for_every_value: bool,
    /// `P = expr − value`, with its parameters.
    pub polynomial: Expr,
    /// `LM(P)` at the fixed values.
    pub leading_monomial: Expr,
    /// The unknowns left out, those whose monomial `LM(P)` divides.
    pub left_out: usize,
    /// A function of the space whose normal form modulo `P` leaves the space, where one does
    /// (its degree bounds are not closed under the division: `x² p_x³`, of momenta degree
    /// at most 3, has on `H = E` of the 1:2 oscillator a normal form with `p_x⁵`); the
    /// integrals found are then those whose normal form lies in the space.
    pub normal_form_outside: Option<NormalFormOutside>,
}

/// A function of a search's space and its normal form modulo a level set's polynomial, a
/// function outside the space ([`SearchedLevel::normal_form_outside`]).
#[derive(Clone, Debug)]
pub struct NormalFormOutside {
    /// The function of the space, `φ` or `φ cos k·θ`, at the fixed values.
    pub function: Expr,
    /// Its remainder on division by `P`, which has a monomial the space has not.
    pub normal_form: Expr,
}

/// What `--new-only` found. Integrals are graded by their total degree in the coordinates and
/// momenta, then by their trigonometric order (the largest such pair among a function's
/// terms, compared in that order); an integral of grade `g` is generated when it is a sum of
/// known integrals, constants, products of at least two integrals of grade below `g` and, with
/// parameters kept symbolic, parameter multiples of integrals of grade `≤ g`, and the integrals
/// of the smallest space that holds the known integrals, the constants, the products and the
/// new integrals of grade below `g`, and holds `X` and `a·X` when it holds either (`a` a
/// parameter kept symbolic, `a·X` in the space): `F = K/ω²` is generated where `K = ω²F` is.
/// The grades form a filtration (a product's grade is at most the sum of its factors'), so
/// where `cos(a − b)` and `p_b` are integrals, `cos 2(a − b) = 2cos²(a − b) − 1` and
/// `p_b cos(a − b)` are generated; without angles the grade is the degree.
///
/// On a level set `P = 0` ([`SearchOptions::on`](super::SearchOptions::on)) the same holds in
/// normal form modulo `P`: the known integrals are the named functions (and those given) whose
/// bracket with `H` is a multiple of `P`, and each of them and each product is reduced modulo
/// `P` before it is compared with the basis (`Γ·(M·γ)` is then `0`, and `K·Γ`, whose monomial
/// `M1² M3 γ1²` the space leaves out, has its normal form in the space). The products are
/// those whose total degree is at most the space's largest (the division's order is graded,
/// so a normal form's total degree is at most the product's, but it may move between the
/// momenta and the positions: `x²` replaced through `H = E` by momenta); one whose normal form
/// has a monomial outside the space is not counted. A product past that degree falls back into
/// the space only where the leading form of `P` (its part of top degree) divides the product
/// of its factors' leading forms, so shares a factor with one of them (`M1 − γ1` on
/// `M1² − γ1² = 1`); where some generator's is not shown to share none with it,
/// [`NewIntegrals::past_degree_undecided`] says so. A sum of products past that degree, each
/// with its normal form outside the space, may still fall back into it where their top-degree
/// parts add up to a multiple of `P`'s (a polynomial in the generators' leading forms that
/// `P`'s divides); that is not detected, and each such product counts only by its own normal
/// form. On the Goryachev–Chaplygin area level set none exists: a polynomial in `H`'s, `Γ`'s
/// and `K`'s leading forms depends on `γ` only through `|γ|²`, which takes every value ≥ 0 on
/// `M·γ = 0`, so it vanishes there only where it is zero.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct NewIntegrals {
    /// The known integrals used (named functions that are real integrals lying in the space),
    /// each as it prints: a function by its display as the expressions write it (`ω3` of a
    /// function `omega3`, as [`trigpoly::shown_text`] writes it), a given one by its name.
    pub known: Vec<String>,
    /// The known integrals themselves, in the order of [`NewIntegrals::known`]: at the fixed
    /// values, restricted to the condition, in the unknowns' monomials (as a basis integral's
    /// [`Integral::fixed`]).
    pub known_integrals: Vec<Expr>,
    /// The dimension of the span of the known integrals and of all products of known and found
    /// integrals that lie in the space.
    pub generated: usize,
    /// Indices into the basis of a complement: the integrals that nothing known generates,
    /// decided by increasing grade.
    pub new: Vec<usize>,
    /// For each new integral, the product of declared denominators of parameters kept
    /// symbolic (each atom with its exponent) by which it is shown, the least degree in them
    /// it takes in the space: `(a1 − a2)² I64 = x1² + x2² + x3²`. Empty where it is shown as
    /// it is, and always without such denominators.
    pub multipliers: Vec<Vec<(Var, i64)>>,
    /// How many products were formed.
    pub products: usize,
    /// On a level set, whether a product past the space's total degree might fall back into it
    /// modulo `P`: the leading form of `P` is not shown to share no factor with each
    /// generator's ([`NewIntegrals`]). Such products are not formed, so an integral told new
    /// may be generated by one. `false` without a level set.
    pub past_degree_undecided: bool,
}

/// With parameters kept symbolic, the integrals form a module over the polynomials in them
/// (`A·I` is an integral whenever `I` is), generated over the rational functions of them by
/// [`ParameterModule::generators`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ParameterModule {
    /// The parameters kept symbolic.
    pub parameters: Vec<Var>,
    /// Indices into the basis of generators: the basis integrals that are not sums of
    /// parameter multiples `a·J` (`a` a parameter, `J` an integral of the space) and of
    /// earlier generators. Every integral of the space is a combination of them with
    /// coefficients rational in the parameters: `(1 − R) I = C G`, `R` the parameter
    /// multiples' (vanishing where every parameter is 0, so `det(1 − R)` is not zero), and
    /// `I = (1 − R)⁻¹ C G` ([`super::BasisGenerators::Module`]); polynomial coefficients are
    /// not proved.
    pub generators: Vec<usize>,
    /// The denominator atoms of these parameters alone (`a1 − a2`): polynomials in them, by
    /// which a multiple is a parameter multiple too (`--new-only` counts an integral whose
    /// multiple by one is generated as generated).
    pub denominators: Vec<Var>,
}

/// Seconds spent in each stage (reported, never used to decide anything).
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct SearchTimings {
    /// Building the unknowns and their images `{φ, H}`.
    pub equations: f64,
    /// The exact linear algebra.
    pub solve: f64,
    /// The engine's proofs at the fixed values, lifting and symbolic proofs.
    pub proofs: f64,
    /// The complement of known products.
    pub new_only: f64,
    /// Everything.
    pub total: f64,
}

/// The result of a search.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SearchResult {
    /// The space searched.
    pub space: SearchSpace,
    /// The condition's text, if any.
    pub condition: Option<String>,
    /// The level set searched on, if any ([`SearchOptions::on`](super::SearchOptions::on)).
    pub on: Option<SearchedLevel>,
    /// The parameters as fixed for the linear algebra.
    pub parameters: Vec<(Var, Rational)>,
    /// The declared denominator that is zero when the parameters are 1, their default: those
    /// in it that were not given values took [`GENERIC_VALUES`](super::GENERIC_VALUES)
    /// instead.
    pub denominator_zero_at_one: Option<Var>,
    /// Whether lifting back to symbolic parameters was possible at all (the weights determine
    /// every parameter).
    pub liftable: bool,
    /// The variables (for printing the parameters).
    pub vars: Vars,
    /// The variables the space's functions are formed in.
    pub variables: SpaceVariables,
    /// Number of unknowns (real basis functions).
    pub unknowns: usize,
    /// Number of (nonzero) linear equations.
    pub equations: usize,
    /// Number of connected components of the linear system.
    pub components: usize,
    /// Unknowns in the largest component.
    pub largest_component: usize,
    /// A basis of all integrals in the space, by increasing degree in the momenta, then in the
    /// Poisson variables.
    pub basis: Vec<Integral>,
    /// The complement of the known integrals' products, if asked for.
    pub new: Option<NewIntegrals>,
    /// With parameters kept symbolic, the generators over the polynomials in them.
    pub module: Option<ParameterModule>,
    /// Timings.
    pub timings: SearchTimings,
}

impl SearchResult {
    /// The number of basis integrals of momenta degree `≤ j` for each `j = 0, …, d`: the
    /// dimensions of the spaces with smaller `d` (same coordinates and trigonometric order).
    pub fn dimensions_by_momenta_degree(&self) -> Vec<usize> {
        self.dimensions_by(self.space.momenta_degree, |f| f.momenta_degree)
    }

    /// The dimension of the integrals of degree `≤ j` in the Poisson variables for each
    /// `j = 0, …, P`: the dimensions of the spaces with smaller `P`. The basis is ordered by
    /// the momenta first, so where the space has momenta too its elements need not be of
    /// the lowest Poisson degree they could be (the Toda lattice's `P²` enters as `P² + …`
    /// of Poisson degree 1): each dimension is found by exact linear algebra, as the
    /// combinations of the basis with no term of higher Poisson degree, where some basis
    /// integral has such a term (in a space without Poisson variables, none has).
    pub fn dimensions_by_poisson_degree(&self) -> Vec<usize> {
        let mut filtration = Filtration::new(self);
        (0..=i64::from(self.space.poisson_degree))
            .map(|j| filtration.within((j, i64::MAX)))
            .collect()
    }

    /// The number of basis integrals whose `degree` is `≤ j`, for each `j = 0, …, bound`.
    fn dimensions_by(&self, bound: u32, degree: impl Fn(&Integral) -> i64) -> Vec<usize> {
        (0..=i64::from(bound))
            .map(|j| self.basis.iter().filter(|f| degree(f) <= j).count())
            .collect()
    }

    /// `counts[j][k]`: basis integrals of momenta degree exactly `j` and trigonometric order
    /// exactly `k`.
    pub fn counts(&self) -> Vec<Vec<usize>> {
        self.counts_by(self.space.momenta_degree, |f| f.momenta_degree)
    }

    /// `poisson_counts[j][k]`: integrals of degree exactly `j` in the Poisson variables and,
    /// among their terms of that degree, trigonometric order exactly `k`: in a basis ordered
    /// by those two (the dimensions of the combinations of the basis whose terms are below
    /// `(j, k)` in that order, differenced, by exact linear algebra as in
    /// [`SearchResult::dimensions_by_poisson_degree`], where some term lies above `(j, k)`
    /// and the terms below it are not those below a grade counted before).
    pub fn poisson_counts(&self) -> Vec<Vec<usize>> {
        let (p, t) = (
            i64::from(self.space.poisson_degree),
            i64::from(self.space.trig_degree),
        );
        let mut filtration = Filtration::new(self);
        let mut below = 0;
        (0..=p)
            .map(|j| {
                (0..=t)
                    .map(|k| {
                        let within = filtration.within((j, k));
                        let exactly = within - below;
                        below = within;
                        exactly
                    })
                    .collect()
            })
            .collect()
    }

    /// Each basis integral (at the fixed values) as its terms' coordinates over `Q`, each
    /// coordinate with the grade of its term: `(degree in the Poisson variables,
    /// trigonometric order)`. A term's real and imaginary parts are two coordinates.
    pub(super) fn term_grades(&self) -> GradedTerms {
        let vars = &self.vars;
        let of_kind = |kind: VarKind| -> Vec<usize> {
            vars.vars()
                .filter(|&v| vars.variable(v).kind() == kind)
                .map(Var::index)
                .collect()
        };
        let (poisson, angles) = (of_kind(VarKind::Poisson), of_kind(VarKind::Angle));
        let degree = |e: &[i64], of: &[usize]| of.iter().map(|&j| e[j].abs()).sum::<i64>();
        let mut rows: HashMap<Vec<i64>, usize> = HashMap::new();
        self.basis
            .iter()
            .map(|f| {
                let mut coordinates = Vec::new();
                for term in f.fixed.terms() {
                    let e = term.exponents();
                    let grade = (degree(&e, &poisson), degree(&e, &angles));
                    let next = rows.len();
                    let row = 2 * *rows.entry(e).or_insert(next);
                    let c = term.coeff();
                    for (part, value) in [(0, c.re), (1, c.im)] {
                        if !value.is_zero() {
                            coordinates.push((grade, row + part, value));
                        }
                    }
                }
                coordinates
            })
            .collect()
    }

    /// `c[j][k]`: basis integrals whose `degree` is `j` (`≤ bound`) and trigonometric order `k`.
    fn counts_by(&self, bound: u32, degree: impl Fn(&Integral) -> i64) -> Vec<Vec<usize>> {
        let k = self.space.trig_degree as usize;
        let mut c = vec![vec![0; k + 1]; bound as usize + 1];
        for f in &self.basis {
            c[degree(f) as usize][f.trig_degree as usize] += 1;
        }
        c
    }

    /// The `i`-th basis integral as proved for every value of the parameters: lifted and
    /// proved symbolically, or proved where no parameter was fixed. `None` when it holds at
    /// the fixed values only (`x p_y − y p_x` of `p²/2 + (x² + a²y²)/2`, at `a = 1`).
    ///
    /// # Panics
    ///
    /// If `i` is not below `self.basis.len()`, as indexing the basis does.
    pub fn for_every_value(&self, i: usize) -> Option<&Expr> {
        let f = &self.basis[i];
        match (&f.symbolic, f.proved_fixed && self.parameters.is_empty()) {
            (Some(e), _) => Some(e),
            (None, true) => Some(&f.fixed),
            (None, false) => None,
        }
    }

    /// Whether every basis element was proved symbolically.
    pub fn all_symbolic(&self) -> bool {
        self.basis.iter().all(|f| f.symbolic.is_some())
    }
}

/// The variables of a search's space: monomials in the coordinates, in the momenta and in the
/// Poisson variables, times `cos k·θ`, `sin k·θ` in the angles. Every momentum and Poisson
/// variable of the phase space is among them but an angle's momentum or a Poisson variable that
/// the condition fixes (`p_θ = mIω/n`, `M₃ = 1` where the flow keeps `M₃`), a constant there,
/// or sets to a function of the others, which parametrise the surface it describes.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct SpaceVariables {
    /// The coordinates (not the angles), whose total degree is the positions degree.
    pub coordinates: Vec<Var>,
    /// The momenta, whose total degree is the momenta degree.
    pub momenta: Vec<Var>,
    /// The Poisson variables, whose total degree is the Poisson degree.
    pub poisson: Vec<Var>,
    /// The angles, whose trigonometric order is bounded.
    pub angles: Vec<Var>,
    /// The momenta that the condition fixes and the flow keeps (an angle's, or a coordinate's that `H`
    /// does not involve) and the Poisson variables that the condition fixes, left out.
    pub left_out: Vec<Var>,
    /// Those of `left_out` that the condition sets to a function of other phase variables,
    /// not to a constant (`M₃ = −(M₁γ₁ + M₂γ₂)/γ₃`, the level set of e(3)*'s area integral
    /// `M·γ = 0`): there the space's functions are those of the others, and a function of
    /// such a variable is no integral for being one.
    pub left_out_as_functions: Vec<Var>,
    /// The declared denominators that the condition gives a value (`κ + 1` at `κ = 1/2`,
    /// [`Condition::substitution`](crate::Condition::substitution)), whose powers the space
    /// leaves out: there they are numbers or functions of the other parameters.
    pub valued_denominators: Vec<Var>,
}

/// Fixed values of parameters as they read, `M = 1, ω = 1` (in `Style::Ascii`, with the ASCII
/// names superint reads back: `M = 1, omega = 1`).
pub fn parameter_text(vars: &VarSet, values: &[(Var, Rational)], style: Style) -> String {
    values
        .iter()
        .map(|(v, x)| {
            let variable = vars.variable(*v);
            // A negative value's sign as the printed conditions write it (`ω = −1`).
            let (name, value) = match style {
                Style::Ascii => (variable.name(), x.to_string()),
                _ => (variable.unicode(), x.to_string().replacen('-', "−", 1)),
            };
            format!("{name} = {value}")
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// A term's `(degree in the Poisson variables, trigonometric order)`, compared in that order.
type Grade = (i64, i64);

/// Each basis integral's terms as coordinates over `Q`, each with its term's grade:
/// `(grade, coordinate, value)` ([`SearchResult::term_grades`]).
pub(super) type GradedTerms = Vec<Vec<(Grade, usize, Rational)>>;

/// The dimensions of the combinations of a search's basis whose terms lie within a grade
/// (`(degree in the Poisson variables, trigonometric order)`, compared in that order), each
/// found by exact linear algebra only where it is not known without: every combination is
/// within a grade that no basis integral's degrees pass (where the space has no Poisson
/// variables, every grade of Poisson degree above 0 and every dimension by Poisson degree;
/// in any space, every grade at or above the basis integrals' highest), and two grades that
/// the same terms lie within have the same combinations (where the space has no angles,
/// every order of one Poisson degree).
struct Filtration<'a> {
    result: &'a SearchResult,
    /// The highest of the basis integrals' `(Poisson degree, trigonometric order)`: no term
    /// lies above it.
    highest: Grade,
    /// The basis's terms with their grades and the distinct grades among them, ascending;
    /// formed when a dimension is first to be found by linear algebra.
    terms: Option<(GradedTerms, Vec<Grade>)>,
    /// The dimensions found, by how many of the distinct grades lie within theirs.
    found: HashMap<usize, usize>,
}

impl<'a> Filtration<'a> {
    fn new(result: &'a SearchResult) -> Self {
        let highest = (result.basis.iter())
            .map(|f| (f.poisson_degree, f.trig_degree))
            .max()
            .unwrap_or((0, 0));
        Filtration {
            result,
            highest,
            terms: None,
            found: HashMap::new(),
        }
    }

    /// The dimension of the combinations of the basis with no term above `grade`.
    fn within(&mut self, grade: Grade) -> usize {
        // A term's grade is at most its integral's degrees, pair by pair.
        if grade >= self.highest {
            return self.result.basis.len();
        }
        let result = self.result;
        let (grades, distinct) = self.terms.get_or_insert_with(|| {
            let grades = result.term_grades();
            let distinct = grades
                .iter()
                .flatten()
                .map(|&(g, ..)| g)
                .sorted_unstable()
                .dedup()
                .collect();
            (grades, distinct)
        });
        let kept = distinct.partition_point(|&g| g <= grade);
        if kept == distinct.len() {
            return result.basis.len();
        }
        *(self.found)
            .entry(kept)
            .or_insert_with(|| combinations_within(grades, |&g| g <= grade))
    }
}

/// The dimension of the combinations of the basis integrals, given by [`SearchResult::term_grades`],
/// whose every term has a grade that `keep` keeps: the kernel of their other coordinates,
/// exactly ([`modular::kernel`]).
pub(super) fn combinations_within(
    grades: &[Vec<(Grade, usize, Rational)>],
    keep: impl Fn(&Grade) -> bool,
) -> usize {
    let columns: Vec<SparseVec<Rational>> = grades
        .iter()
        .map(|coordinates| {
            let mut column: SparseVec<Rational> = coordinates
                .iter()
                .filter(|(grade, ..)| !keep(grade))
                .map(|(_, row, value)| (*row, value.clone()))
                .collect();
            column.sort_by_key(|&(row, _)| row);
            column
        })
        .collect();
    let rows = grades
        .iter()
        .flatten()
        .map(|&(_, row, _)| row + 1)
        .max()
        .unwrap_or(0);
    #[cfg(test)]
    ELIMINATIONS.with(|done| done.set(done.get() + 1));
    modular::kernel(&columns, rows).len()
}

#[cfg(test)]
thread_local! {
    /// How many eliminations ([`combinations_within`]) the counts by Poisson degree have done
    /// on this thread, which the tests bound.
    pub(super) static ELIMINATIONS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}
