//! Functional independence: the exact rank of the Jacobian `∂(F_1, …, F_k)/∂(q, p)` over the
//! field of rational functions, with certificates: a nonzero minor at an exact rational point
//! for the lower bound; for the upper bound, the size of the matrix or every minor one larger
//! that borders the nonzero one vanishing identically (Kronecker's bordered-minor theorem: then
//! every larger minor vanishes, and `(k − r)(n − r)` minors stand for all `C(k, r+1) C(n, r+1)`).
//! On a level set (`p_θ = Iω`, [`rank_on`]) the functions are restricted to it, the condition
//! substituted, and the Jacobian taken by the phase variables it leaves free.

use std::collections::HashMap;

use itertools::Itertools;
use trigpoly::{Expr, GaussianRational, Point, Rational, Var, VarKind};

use crate::claim::Condition;
use crate::error::EngineError;
use crate::linalg::Matrix;
use crate::phase::PhaseSpace;

/// Why the rank is at most what is claimed.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum UpperBound {
    /// The rank equals the number of functions or of coordinates.
    Size,
    /// Every `(r+1) × (r+1)` minor that borders the nonzero `r × r` minor (its functions and
    /// coordinates with one more of each) is identically zero, and so, by Kronecker's
    /// bordered-minor theorem, is every `(r+1) × (r+1)` minor.
    VanishingMinors {
        /// How many bordering minors were expanded: `(k − r)(n − r)` for `k` functions in `n`
        /// coordinates.
        count: usize,
    },
    /// The rank is one less than the number of coordinates, and the functions are integrals
    /// of a Hamiltonian flow that is not identically zero ([`integrals_rank_within`]): each
    /// gradient annihilates the Hamiltonian vector field, so where it is not zero the
    /// gradients span at most a hyperplane (maximal superintegrability is exactly this rank).
    /// The coordinates are the phase variables, or on a level set the flow keeps (a `--when`
    /// or a graph `--on` that sets phase variables) those it leaves free, with the field
    /// restricted to it, `H` at the parameters a `--when` sets; on a Lie–Poisson space (a top) the bound holds as it is, a Casimir's
    /// gradient annihilating every Hamiltonian vector field too.
    Flow,
    /// Each function is a polynomial in `by` generators whose rank is this one
    /// ([`generated_rank_within`]): by the chain rule each gradient is a combination of
    /// theirs, so the rank is at most theirs.
    Generated {
        /// How many generators.
        by: usize,
    },
}

impl UpperBound {
    /// The kind of bound as one lowercase word, as superint's JSON reports it: `size`,
    /// `vanishing_minors`, `flow` or `generated`. A program that reads a bound by its name and [`UpperBound::minors`]
    /// reads every kind, one added later too (the enum is open to new kinds of proof).
    ///
    /// ```
    /// use brackets::{rank, systems, UpperBound};
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let get = |name: &str| rotor.get(name).cloned();
    /// let tied = [get("F1")?, get("F2")?, get("L")?, get("G1")?, get("G2")?];
    /// // Five functions of rank 4 in six phase variables: (5 − 4)(6 − 4) bordering minors.
    /// let tied = rank(rotor.space(), &tied)?;
    /// assert_eq!((tied.upper.name(), tied.upper.minors()), ("vanishing_minors", Some(2)));
    /// let one = rank(rotor.space(), &[get("L")?])?;
    /// assert_eq!((one.upper.name(), one.upper.minors()), ("size", None));
    /// assert_eq!(UpperBound::Size.name(), "size");
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            UpperBound::Size => "size",
            UpperBound::VanishingMinors { .. } => "vanishing_minors",
            UpperBound::Flow => "flow",
            UpperBound::Generated { .. } => "generated",
        }
    }

    /// How many bordering minors were expanded, for [`UpperBound::VanishingMinors`]; `None`
    /// for a bound that expands none.
    pub fn minors(&self) -> Option<usize> {
        match self {
            UpperBound::Size | UpperBound::Flow | UpperBound::Generated { .. } => None,
            UpperBound::VanishingMinors { count } => Some(*count),
        }
    }
}

impl std::fmt::Display for UpperBound {
    /// The reason in words, as a sentence's clause: `the rank is at most the number of
    /// functions or of coordinates`, `the 4 minors bordering the nonzero one vanish
    /// identically`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            UpperBound::Size => {
                f.write_str("the rank is at most the number of functions or of coordinates")
            }
            UpperBound::VanishingMinors { count: 1 } => {
                f.write_str("the one minor bordering the nonzero one vanishes identically")
            }
            UpperBound::VanishingMinors { count } => write!(
                f,
                "the {count} minors bordering the nonzero one vanish identically"
            ),
            UpperBound::Flow => f.write_str(
                "integrals of a flow that is not identically zero have a rank at most the \
                 number of coordinates less one",
            ),
            UpperBound::Generated { by: 1 } => {
                f.write_str("the functions are polynomials in one function of this rank")
            }
            UpperBound::Generated { by } => write!(
                f,
                "the functions are polynomials in {by} functions whose rank is this one"
            ),
        }
    }
}

/// A certified rank. Two are equal when they certify the same rank by the same minor at the
/// same point, with the same upper bound: the rank of the same functions twice gives equal
/// certificates.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct RankCertificate {
    /// The rank.
    pub rank: usize,
    /// The Jacobian's columns: every phase variable ([`PhaseSpace::coordinates`]), or on a
    /// level set ([`rank_on`]) those its condition leaves free.
    pub coordinates: Vec<Var>,
    /// Indices of the functions of the nonzero minor.
    pub minor_rows: Vec<usize>,
    /// The coordinates of the nonzero minor.
    pub minor_cols: Vec<Var>,
    /// The exact point: a value for each variable (angles as `cos + i sin`), but those a
    /// level set's condition sets ([`rank_on`]).
    pub point: Vec<(Var, GaussianRational)>,
    /// The minor's value there (nonzero).
    pub minor_value: GaussianRational,
    /// The upper bound's certificate.
    pub upper: UpperBound,
}

/// How many points the lower bound samples first.
const FIRST_POINTS: usize = 4;
/// How many more it samples before any symbolic minor, while the rank is below the size.
const EARLY_POINTS: usize = 4;
/// How many more it may try when a larger minor does not vanish identically.
const FURTHER_POINTS: usize = 64;
/// How many tuples of small integers a sample point of a space with radicals tries for the
/// radicands' variables, to find one where every radicand is a rational square.
const RADICAL_CANDIDATES: u64 = 20_000;
/// Rational points of the unit circle used for angles.
const CIRCLE: [(i64, i64, i64); 4] = [(3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25)];
/// Distinct primes: the `k`-th variable at the `s`-th of the first points is
/// `(p_k + 2s)/(1 + k mod 3)`.
const PRIMES: [i64; 16] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53];

/// Certifies the rank of the Jacobian of `functions` by the phase-space coordinates.
///
/// ```
/// use brackets::{rank, systems, UpperBound};
///
/// // C17: F1, F2, G1, G2 and P_{1,1} are functionally independent; L, G1, G2 and F1 − F2
/// // are not (the Casimir 4G1² + G2² + ω²L² = (F1 − F2)² ties them).
/// let rotor = systems::harmonic_rotor();
/// let get = |name: &str| rotor.get(name).cloned();
/// let mut five = vec![get("F1")?, get("F2")?, get("G1")?, get("G2")?];
/// five.push(rotor.resonant("Z", 1, 1)?.p);
/// let certificate = rank(rotor.space(), &five)?;
/// assert_eq!(certificate.rank, 5);
/// assert!(!certificate.minor_value.is_zero());
/// let tied = rank(rotor.space(), &[get("F1")?, get("F2")?, get("L")?, get("G1")?, get("G2")?])?;
/// assert_eq!(tied.rank, 4);
/// assert!(matches!(tied.upper, UpperBound::VanishingMinors { .. }));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn rank(space: &PhaseSpace, functions: &[Expr]) -> Result<RankCertificate, EngineError> {
    rank_by(space, functions, space.coordinates())
}

/// Certifies the rank of the functions restricted to the level set of `condition`: each
/// function with the condition substituted (which parametrises the level set by the variables
/// it leaves free, exactly), its Jacobian by the phase variables the condition does not set
/// ([`Condition::level_set_variables`]). A condition that sets parameters only gives the rank of
/// [`rank`] at their values. The certificate's point leaves out what the condition sets.
///
/// Refused where the condition sets an angle or a parameter to a function of phase space
/// ([`Condition::level_set_variables`]), or sets to zero a variable a function divides by
/// ([`Condition::apply_where_defined`]).
///
/// ```
/// use brackets::{rank_on, systems, Condition};
///
/// // At the resonance p_θ = Iω the rotor's level set has five dimensions: there F2 = p_θ²/(2I)
/// // is constant, and F1 (H but that constant), G1, G2 and P_{1,1} have rank 4, the most that
/// // integrals of a flow on it can have.
/// let rotor = systems::harmonic_rotor();
/// let get = |name: &str| rotor.get(name).cloned();
/// let at = Condition::all("p_θ = Iω", vec![(rotor.var("p_theta"), rotor.parse("I*omega")?)])?;
/// let four = vec![get("F1")?, get("G1")?, get("G2")?, rotor.resonant("Z", 1, 1)?.p];
/// let certificate = rank_on(rotor.space(), &four, &at)?;
/// assert_eq!(certificate.rank, 4);
/// assert!(!certificate.coordinates.contains(&rotor.var("p_theta")));
/// let mut five = four.clone();
/// five.push(get("F2")?);
/// assert_eq!(rank_on(rotor.space(), &five, &at)?.rank, 4);
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn rank_on(
    space: &PhaseSpace,
    functions: &[Expr],
    condition: &Condition,
) -> Result<RankCertificate, EngineError> {
    let restricted = functions
        .iter()
        .map(|f| condition.apply_where_defined(f, "a function"))
        .collect::<Result<Vec<_>, _>>()?;
    rank_restricted(space, &restricted, condition)
}

/// [`rank_on`] for functions that already have the condition substituted (as
/// [`Condition::apply_where_defined`] does): refused where one of them still holds a variable
/// the condition sets, a phase variable whose column the Jacobian would leave out or a
/// parameter the point would be taken at another value of, and which it would leave out.
pub fn rank_restricted(
    space: &PhaseSpace,
    restricted: &[Expr],
    condition: &Condition,
) -> Result<RankCertificate, EngineError> {
    let coords = level_set_coordinates(space, condition)?;
    let set = |v: &Var| condition.subs().iter().any(|(w, _)| w == v);
    let unrestricted = condition
        .subs()
        .iter()
        .find(|(v, _)| restricted.iter().any(|f| f.contains(*v)));
    if let Some((v, _)) = unrestricted {
        return Err(EngineError::Invalid(format!(
            "a function restricted to the level set of {condition} still holds {}, which the \
             condition sets",
            space.vars().variable(*v).unicode()
        )));
    }
    let mut cert = rank_by(space, restricted, coords)?;
    // What the condition sets has its value there, not the point's.
    cert.point.retain(|(v, _)| !set(v));
    Ok(cert)
}

/// The Jacobian's columns for a rank on the level set of `condition` ([`rank_on`]): the phase
/// variables ([`PhaseSpace::coordinates`]) but those it sets, in their order; refused as
/// [`Condition::level_set_variables`] refuses.
pub fn level_set_coordinates(
    space: &PhaseSpace,
    condition: &Condition,
) -> Result<Vec<Var>, EngineError> {
    let set = condition.level_set_variables()?;
    Ok(space
        .coordinates()
        .into_iter()
        .filter(|v| !set.contains(v))
        .collect())
}

/// A rank certified from below, and from above where that costs at most a given number of
/// bordering minors ([`rank_within`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BoundedRank {
    /// Certified both ways.
    Exact(RankCertificate),
    /// At least this: a minor of this size is nonzero at an exact point, but more minors
    /// border it than the upper bound was allowed to expand.
    AtLeast(usize),
}

impl BoundedRank {
    /// The rank, or its lower bound.
    pub fn rank(&self) -> usize {
        match self {
            BoundedRank::Exact(cert) => cert.rank,
            BoundedRank::AtLeast(rank) => *rank,
        }
    }

    /// Whether the rank is certified from above too.
    pub fn is_exact(&self) -> bool {
        matches!(self, BoundedRank::Exact(_))
    }
}

/// The rank as prose says it: `2`, or `at least 2` where it is a lower bound.
impl std::fmt::Display for BoundedRank {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BoundedRank::Exact(cert) => write!(f, "{}", cert.rank),
            BoundedRank::AtLeast(rank) => write!(f, "at least {rank}"),
        }
    }
}

/// [`rank`], the upper bound certified only where the rank equals the number of functions or
/// of coordinates or at most `max_minors` minors border the nonzero one: past that, the
/// rank is said to be at least the lower bound ([`BoundedRank::AtLeast`]).
///
/// ```
/// use brackets::{rank_within, systems, BoundedRank};
///
/// let rotor = systems::harmonic_rotor();
/// let get = |name: &str| rotor.get(name).cloned();
/// let tied = [get("F1")?, get("F2")?, get("L")?, get("G1")?, get("G2")?];
/// // Rank 4 in six phase variables: (5 − 4)(6 − 4) = 2 bordering minors.
/// assert!(rank_within(rotor.space(), &tied, 2)?.is_exact());
/// assert_eq!(rank_within(rotor.space(), &tied, 1)?, BoundedRank::AtLeast(4));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn rank_within(
    space: &PhaseSpace,
    functions: &[Expr],
    max_minors: usize,
) -> Result<BoundedRank, EngineError> {
    rank_bounded_by(
        space,
        functions,
        space.coordinates(),
        None,
        max_minors,
        None,
    )
}

/// [`rank_within`] for integrals of the flow of `hamiltonian` (each `F` with `{F, H} = 0`
/// identically, or where `condition` holds; the caller vouches for it), which bounds the rank
/// without any symbolic minor. Each gradient annihilates the Hamiltonian vector field `X_H`
/// (`dF(X_H) = {F, H} = 0`); where `X_H` is not identically zero it is nonzero on a dense open
/// set, and there the gradients lie in its annihilator, a hyperplane: the rank is at most
/// `n − 1` for `n` coordinates ([`UpperBound::Flow`]). On a Lie–Poisson space (a top) this
/// holds as it is, a Casimir's gradient annihilating every Hamiltonian vector field, and is
/// the most there too: the Casimirs and `2m − 1` integrals on the leaves of dimension `2m`.
/// `X_H` is shown not to be identically zero by a nonzero component `{z, H}` at one of the
/// exact sample points; where every one vanishes at those the bound is not used.
///
/// With a condition that sets phase variables (`p_θ = Iω`), none of which the integrals
/// hold, and whose level set the flow keeps (`{v − value, H}` vanishes on it for each `v` it
/// sets), the rank is that of the integrals on the level set, by the variables it leaves free
/// (the other columns are zero), and the same holds there with `X_H` restricted to it: at
/// most one less than those variables. Parameters the condition sets too (`ω₊ = 2ω₋`, none
/// of which the integrals hold) are set in `H` first: a bracket differentiates no parameter,
/// so `{F, H}` vanishing where the condition holds is `{F, H'}` vanishing on the level set,
/// `H'` being `H` at them (a condition on parameters alone leaves the whole phase space).
/// Parameters left free (kept symbolic) are variables of the exact points like the others:
/// `{F, H'} = 0` for every value of them, so `X_H'` nonzero at one point is nonzero on a
/// dense open set of phase space and parameters, where the gradients lie in a hyperplane.
/// Any other condition (one setting an angle, or a parameter to a function of phase space)
/// leaves the flow out, and the rank is [`rank_within`]'s. A rank below the bound needs the bordering minors as
/// [`rank_within`] does, at most `max_minors` of them.
///
/// ```
/// use brackets::{integrals_rank_within, systems, BoundedRank, UpperBound};
/// use trigpoly::{Expr, GaussianRational};
///
/// // The harmonic rotor's integrals F1, F2, L, G1, G2 and P_{1,1} at ω = 1: rank 5 of 6, the
/// // most a flow allows, exact with no minor expanded.
/// let rotor = systems::harmonic_rotor();
/// let one = Expr::constant(rotor.vars(), GaussianRational::from(1));
/// let at_one = |e: &Expr| e.subst(rotor.var("omega"), &one);
/// let mut six = vec![rotor.resonant("Z", 1, 1)?.p];
/// for name in ["F1", "F2", "L", "G1", "G2"] {
///     six.push(rotor.get(name).cloned()?);
/// }
/// let six: Vec<Expr> = six.iter().map(at_one).collect::<Result<_, _>>()?;
/// let h = at_one(rotor.hamiltonian())?;
/// let rank = integrals_rank_within(rotor.space(), &six, &h, None, 0)?;
/// assert!(matches!(rank, BoundedRank::Exact(ref c) if c.rank == 5 && c.upper == UpperBound::Flow));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn integrals_rank_within(
    space: &PhaseSpace,
    integrals: &[Expr],
    hamiltonian: &Expr,
    condition: Option<&Condition>,
    max_minors: usize,
) -> Result<BoundedRank, EngineError> {
    generated_rank_within(
        space,
        integrals,
        &[],
        Some(hamiltonian),
        condition,
        max_minors,
    )
}

/// [`integrals_rank_within`] (or [`rank_within`] without a Hamiltonian) of functions each of
/// which is a polynomial in `generators` (where the condition holds; the caller vouches for
/// it, as `--new-only` decides it when the known integrals generate every integral found):
/// by the chain rule each gradient is a combination of the generators', so the rank is at
/// most theirs. Their rank is taken first, the same way (the same coordinates, the same flow;
/// they are integrals too), at most `max_minors` bordering minors; where it is exact and the
/// functions' lower bound meets it, their rank is exact ([`UpperBound::Generated`], or the
/// flow's where that bound is the same). No generators: [`integrals_rank_within`] itself.
///
/// ```
/// use brackets::{generated_rank_within, systems, BoundedRank, UpperBound};
/// use trigpoly::Expr;
///
/// // L, L², L³, L⁴ are polynomials in L alone: rank 1, however many.
/// let rotor = systems::harmonic_rotor();
/// let l = rotor.get("L").cloned()?;
/// let mut powers: Vec<Expr> = vec![l.clone()];
/// for _ in 1..4 {
///     let next = powers[powers.len() - 1].checked_mul(&l)?;
///     powers.push(next);
/// }
/// let h = rotor.hamiltonian();
/// let rank = generated_rank_within(rotor.space(), &powers, &[l], Some(h), None, 0)?;
/// assert!(matches!(rank, BoundedRank::Exact(ref c)
///     if c.rank == 1 && c.upper == UpperBound::Generated { by: 1 }));
/// // Without the generators: at least 1, no bordering minor being allowed.
/// let alone = generated_rank_within(rotor.space(), &powers, &[], Some(h), None, 0)?;
/// assert_eq!(alone, BoundedRank::AtLeast(1));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn generated_rank_within(
    space: &PhaseSpace,
    functions: &[Expr],
    generators: &[Expr],
    hamiltonian: Option<&Expr>,
    condition: Option<&Condition>,
    max_minors: usize,
) -> Result<BoundedRank, EngineError> {
    let route = match hamiltonian {
        Some(h) => flow_by_free_coordinates(space, functions, h, condition)?,
        None => None,
    };
    let (coords, flow) = match route {
        Some((coords, flow)) => (coords, Some(flow)),
        None => (space.coordinates(), None),
    };
    let generated = match generators.is_empty() {
        true => None,
        false => match rank_bounded_by(
            space,
            generators,
            coords.clone(),
            flow.as_deref(),
            max_minors,
            None,
        )? {
            BoundedRank::Exact(cert) => Some(Generators {
                count: generators.len(),
                rank: cert.rank,
            }),
            BoundedRank::AtLeast(_) => None,
        },
    };
    rank_bounded_by(
        space,
        functions,
        coords,
        flow.as_deref(),
        max_minors,
        generated,
    )
}

/// How many functions generate those whose rank is taken, and their certified rank, which
/// bounds it ([`generated_rank_within`]).
#[derive(Clone, Copy, Debug)]
struct Generators {
    count: usize,
    rank: usize,
}

/// Coordinates and the components of a Hamiltonian vector field along them.
type FlowByCoordinates = (Vec<Var>, Vec<Expr>);

/// The coordinates [`integrals_rank_within`] takes the Jacobian by (every phase variable, or
/// those the condition leaves free) and the components of `X_H` along them (on the level
/// set); `None` where the condition is not one the flow bounds the rank under.
fn flow_by_free_coordinates(
    space: &PhaseSpace,
    integrals: &[Expr],
    hamiltonian: &Expr,
    condition: Option<&Condition>,
) -> Result<Option<FlowByCoordinates>, EngineError> {
    let vars = space.vars();
    let moves = |z: &Expr| space.bracket(z, hamiltonian);
    let Some(condition) = condition else {
        let coords = space.coordinates();
        let flow = coords
            .iter()
            .map(|&z| moves(&Expr::var(vars, z)))
            .collect::<Result<_, _>>()?;
        return Ok(Some((coords, flow)));
    };
    let Ok(set) = condition.level_set_variables() else {
        return Ok(None);
    };
    let subs = condition.subs();
    let held = subs
        .iter()
        .any(|(v, _)| integrals.iter().any(|f| f.contains(*v)));
    if held {
        return Ok(None);
    }
    // The parameters the condition sets are set in `H` first: `{F, H}` vanishing where the
    // condition holds is `{F, H'}` vanishing on the level set of its phase variables alone,
    // `H'` being `H` at those parameters (a bracket differentiates no parameter, and no
    // integral holds one the condition sets).
    let parameters: Vec<(Var, Expr)> = (subs.iter())
        .filter(|(v, _)| !set.contains(v))
        .cloned()
        .collect();
    let hamiltonian = match parameters.is_empty() {
        true => hamiltonian.clone(),
        false => match Condition::all(&condition.to_string(), parameters)
            .and_then(|c| c.apply(hamiltonian))
        {
            Ok(h) => h,
            Err(_) => return Ok(None),
        },
    };
    let moves = |z: &Expr| space.bracket(z, &hamiltonian);
    let on_level_set = |e: &Expr| condition.apply(e).ok();
    for (v, value) in subs.iter().filter(|(v, _)| set.contains(v)) {
        let leaves = moves(&Expr::var(vars, *v).checked_sub(value)?)?;
        if !on_level_set(&leaves).is_some_and(|e| e.is_zero()) {
            return Ok(None);
        }
    }
    let coords = level_set_coordinates(space, condition)?;
    let mut flow = Vec::with_capacity(coords.len());
    for &z in &coords {
        match on_level_set(&moves(&Expr::var(vars, z))?) {
            Some(component) => flow.push(component),
            None => return Ok(None),
        }
    }
    Ok(Some((coords, flow)))
}

/// The certified rank of the Jacobian of `functions` by the phase variables `coords`.
fn rank_by(
    space: &PhaseSpace,
    functions: &[Expr],
    coords: Vec<Var>,
) -> Result<RankCertificate, EngineError> {
    match rank_bounded_by(space, functions, coords, None, usize::MAX, None)? {
        BoundedRank::Exact(cert) => Ok(cert),
        BoundedRank::AtLeast(_) => unreachable!("every bordering minor may be expanded"),
    }
}

/// The rank of the Jacobian of `functions` by the phase variables `coords`, certified from
/// above where at most `max_minors` minors border the nonzero one, or where it is one less
/// than the coordinates and `flow` (the components `{z, H}` of a Hamiltonian vector field the
/// functions are integrals of, by `coords`) is nonzero at a sample point
/// ([`integrals_rank_within`]), or where it is the rank of `generated`'s functions, which
/// generate these ([`generated_rank_within`]).
fn rank_bounded_by(
    space: &PhaseSpace,
    functions: &[Expr],
    coords: Vec<Var>,
    flow: Option<&[Expr]>,
    max_minors: usize,
    generated: Option<Generators>,
) -> Result<BoundedRank, EngineError> {
    // Lower bound: the best rank over a few exact points, then over a few more off the line
    // of the first four (cheap beside any symbolic minor).
    let size = functions.len().min(coords.len());
    // The most the rank can be: the size, the generators' rank, or one less than the
    // coordinates once the flow is seen to be nonzero at a sample point.
    let mut full = generated.map_or(size, |g| size.min(g.rank));
    // Why, where it is less than the size: the flow's bound where it is that, else the
    // generators'.
    let below_size = |full: usize, moved: bool| match moved && full + 1 == coords.len() {
        true => UpperBound::Flow,
        false => UpperBound::Generated {
            by: generated.map_or(0, |g| g.count),
        },
    };
    let mut moved = false;
    let mut best: Option<RankCertificate> = None;
    for index in 0..FIRST_POINTS + EARLY_POINTS {
        if index >= FIRST_POINTS && best.as_ref().is_some_and(|b| b.rank == full) {
            break;
        }
        let Some(point) = sample_point(space, index)? else {
            continue;
        };
        let moves = match flow {
            Some(flow) => flow_moves_at(flow, &point.0)?,
            None => false,
        };
        if moves {
            moved = true;
            full = full.min(coords.len() - 1);
        }
        // At one of the first points where the flow moves, the functions' gradients are
        // evaluated one at a time and kept where they raise the rank there, and the rank is
        // certified as soon as they reach the flow's bound: a search's basis of a thousand
        // integrals reaches it within its first few, and the others are never evaluated.
        // So too at the generators' rank: `stop_at` is the bound reached, the flow's or theirs.
        let bounded = moves || generated.is_some_and(|g| g.rank == full);
        let stop_at =
            (bounded && index < FIRST_POINTS && functions.len() > full && full > 0).then_some(full);
        let (values, kept) = values_at(space, functions, &coords, &point.0, stop_at)?;
        if stop_at.is_some_and(|bound| kept.len() == bound) {
            let mut cert = certificate_of(values, &coords, point);
            cert.minor_rows = cert.minor_rows.iter().map(|&k| kept[k]).collect();
            cert.upper = match full < size {
                true => below_size(full, moved),
                false => UpperBound::Size,
            };
            return Ok(BoundedRank::Exact(cert));
        }
        let cert = certificate_of(values, &coords, point);
        if best.as_ref().is_none_or(|b| cert.rank > b.rank) {
            best = Some(cert);
        }
    }
    let mut cert = best.ok_or_else(|| {
        let vanishes = format!(
            "a denominator vanishes at each of the {} sample points, where the functions are \
             not defined",
            FIRST_POINTS + EARLY_POINTS,
        );
        let radicands = space
            .radicals()
            .iter()
            .map(|(r, radicand)| format!("{} = √({radicand})", space.vars().variable(*r).unicode()))
            .collect::<Vec<_>>()
            .join(", ");
        let no_square = format!(
            "no point of small integers or fractions of them makes every radicand ({radicands}) \
             the square of a rational, where the radicals have exact values"
        );
        // Said of what the system has: a system without denominators has no point for its
        // radicands alone (`3x² + 2` is the square of no rational).
        EngineError::Invalid(
            match (
                space.denominator_atoms().is_empty(),
                space.radicals().is_empty(),
            ) {
                (_, true) => vanishes,
                (true, false) => {
                    format!("{no_square}: the rank is certified at exact points, and there is none")
                }
                (false, false) => format!("{vanishes}, or {no_square}"),
            },
        )
    })?;
    // Upper bound: every minor bordering the nonzero one vanishes identically. The nonzero
    // minor is a nonzero polynomial, so over the field of rational functions its rows are
    // independent on its columns, and each other function's gradient is, on those columns, one
    // combination of theirs; a bordering minor is the nonzero minor times that combination's
    // miss on the added column, so when all vanish every gradient is a combination of the
    // minor's rows and the rank is r. A bordering minor that does not vanish is a polynomial
    // nonzero somewhere, so the Jacobian's rank is larger at almost every point: further points
    // are tried until one shows it, which raises the lower bound.
    let further = FIRST_POINTS + EARLY_POINTS..FIRST_POINTS + EARLY_POINTS + FURTHER_POINTS;
    // The symbolic Jacobian, for the bordering minors alone.
    let mut jac: Option<Vec<Vec<Expr>>> = None;
    while cert.rank < full {
        if (functions.len() - cert.rank) * (coords.len() - cert.rank) > max_minors {
            return Ok(BoundedRank::AtLeast(cert.rank));
        }
        let jac = match &mut jac {
            Some(jac) => jac,
            None => jac.insert(
                functions
                    .iter()
                    .map(|f| {
                        coords
                            .iter()
                            .map(|&c| space.derivative(f, c))
                            .collect::<Result<Vec<_>, _>>()
                    })
                    .collect::<Result<_, _>>()?,
            ),
        };
        if let Some(count) = vanishing_bordering_minors(jac, &coords, &cert)? {
            cert.upper = UpperBound::VanishingMinors { count };
            break;
        }
        let mut raised = None;
        for index in further.clone() {
            let Some(point) = sample_point(space, index)? else {
                continue;
            };
            let higher = certificate_at(space, functions, &coords, point)?;
            if higher.rank > cert.rank {
                raised = Some(higher);
                break;
            }
        }
        match raised {
            Some(higher) => cert = higher,
            None => {
                return Err(EngineError::Invalid(format!(
                    "rank is above {} (a {}-minor is not identically zero), but the Jacobian's \
                     rank was at most {} at all {} sampled points",
                    cert.rank,
                    cert.rank + 1,
                    cert.rank,
                    further.end
                )))
            }
        }
    }
    if cert.rank == full && full < size {
        cert.upper = below_size(full, moved);
    }
    Ok(BoundedRank::Exact(cert))
}

/// Whether a vector field (its components) is nonzero at an exact point, and so not
/// identically zero.
fn flow_moves_at(flow: &[Expr], point: &Point) -> Result<bool, EngineError> {
    for component in flow {
        if !component.eval(point)?.is_zero() {
            return Ok(true);
        }
    }
    Ok(false)
}

/// An exact point, and its values as the certificate lists them.
type SamplePoint = (Point, Vec<(Var, GaussianRational)>);

/// The exact sample point number `index`: a value for each variable (angles as `cos + i sin`
/// on the unit circle; a denominator atom its polynomial's value), and those values as a list
/// (without the atoms'); `None` when a denominator vanishes there.
fn sample_point(space: &PhaseSpace, index: usize) -> Result<Option<SamplePoint>, EngineError> {
    let vars = space.vars();
    let mut point = Point::new(vars);
    let mut values = Vec::new();
    for (k, v) in vars.vars().enumerate() {
        let kind = vars.variable(v).kind();
        if matches!(kind, VarKind::Denominator | VarKind::Radical) {
            continue;
        }
        if kind == VarKind::Angle {
            let (c, s, r) = if index < FIRST_POINTS {
                CIRCLE[(k + index) % CIRCLE.len()]
            } else {
                // (m² − 1, 2m, m² + 1): a rational point of the circle for every m ≥ 2, a
                // new one at each point.
                let m = (index + 2 * k + 2) as i64;
                (m * m - 1, 2 * m, m * m + 1)
            };
            point = point.with_angle(v, Rational::new(c, r), Rational::new(s, r))?;
        } else {
            let value = if index < FIRST_POINTS {
                let a = PRIMES[k % PRIMES.len()] + (k / PRIMES.len()) as i64 + 2 * index as i64;
                Rational::new(a, 1 + (k % 3) as i64)
            } else {
                // Quadratic in the index, so that no three of these points are on a line.
                let t = (index - FIRST_POINTS + 1) as i64;
                let a = PRIMES[(k + 3 * index) % PRIMES.len()] + t * t + k as i64;
                Rational::new(a, 1 + ((k + index) % 4) as i64)
            };
            point = point.with(v, value);
        }
        values.push((v, point.value(v).expect("just set").clone()));
    }
    let point = match space.radicals().is_empty() {
        true => point,
        false => match on_radicals(space, index, point, &mut values)? {
            Some(point) => point,
            None => return Ok(None),
        },
    };
    Ok(point
        .with_atoms(space.denominator_atoms())?
        .map(|point| (point, values)))
}

/// The sample point with the variables of the radicands moved to small nonzero integers where
/// every radicand is the square of a rational, so that each radical has an exact value (the
/// `index`-th such tuple of a fixed pseudo-random sequence, so that each sample point is
/// another), and the radicals set; `values` follows. `None` when the sequence has no such
/// tuple in its first [`RADICAL_CANDIDATES`].
fn on_radicals(
    space: &PhaseSpace,
    index: usize,
    point: Point,
    values: &mut Vec<(Var, GaussianRational)>,
) -> Result<Option<Point>, EngineError> {
    let radicals = space.radicals();
    let used: Vec<Var> = space
        .vars()
        .vars()
        .filter(|&v| radicals.iter().any(|(_, r)| r.contains(v)))
        .collect();
    let mut found = 0;
    for c in 0..RADICAL_CANDIDATES {
        let mut candidate = point.clone();
        for (k, &v) in used.iter().enumerate() {
            candidate = candidate.with(v, candidate_value(c, k as u64));
        }
        let Some(candidate) = candidate.with_radicals(radicals)? else {
            continue;
        };
        if found < index {
            found += 1;
            continue;
        }
        for (v, value) in values.iter_mut() {
            if used.contains(v) {
                *value = candidate.value(*v).expect("just set").clone();
            }
        }
        values.extend(
            radicals
                .iter()
                .map(|(r, _)| (*r, candidate.value(*r).expect("just set").clone())),
        );
        return Ok(Some(candidate));
    }
    Ok(None)
}

/// The value of the `k`-th variable of the radicands in the `c`-th candidate of
/// [`on_radicals`], a nonzero integer in `−12..=12` or, past the first 1 000 candidates, a
/// nonzero fraction of such an integer by 2, 3 or 4: first a short sequence that repeats after
/// 72 candidates (the points every certificate so far was found at), then a mix of `c` and `k`
/// (SplitMix64's), so that the candidates past those cover the whole box. With radicands
/// `x² + y² + z²` and `(x − a)² + y² + z²` the short sequence alone had no point where both
/// are squares; `x² + 2` is the square of no integer, but is `9/4` at `x = 1/2`.
fn candidate_value(c: u64, k: u64) -> Rational {
    const CYCLE: u64 = 72;
    const INTEGERS: u64 = 1_000;
    let nonzero = |t: i64| if t >= 0 { t + 1 } else { t };
    if c < CYCLE {
        let step = PRIMES[k as usize % PRIMES.len()] as u64;
        return Rational::from(nonzero(((c * step + 7 * k + c * c / 3) % 24) as i64 - 12));
    }
    let mut z = (c << 8 | k).wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    let numerator = nonzero((z % 24) as i64 - 12);
    let denominator = match c < INTEGERS {
        true => 1,
        false => 1 + ((z >> 32) % 4) as i64,
    };
    Rational::new(numerator, denominator)
}

/// The rank of the Jacobian at a point, with a nonzero minor of that size there.
fn certificate_at(
    space: &PhaseSpace,
    functions: &[Expr],
    coords: &[Var],
    point: SamplePoint,
) -> Result<RankCertificate, EngineError> {
    let (values, _) = values_at(space, functions, coords, &point.0, None)?;
    Ok(certificate_of(values, coords, point))
}

/// The Jacobian's values at a point, a row for each function; with a `bound`, the functions
/// whose rows raise the rank of those before them as well, and as soon as `bound` of them do,
/// their rows alone (the others are not evaluated).
fn values_at(
    space: &PhaseSpace,
    functions: &[Expr],
    coords: &[Var],
    point: &Point,
    bound: Option<usize>,
) -> Result<(Matrix, Vec<usize>), EngineError> {
    let mut all = Matrix::zeros(functions.len(), coords.len());
    let mut kept = Vec::new();
    let mut independent = Matrix::zeros(0, coords.len());
    for (i, f) in functions.iter().enumerate() {
        let row = gradient_at(space, f, coords, point)?;
        let Some(bound) = bound else {
            for (j, value) in row.into_iter().enumerate() {
                all.set(i, j, value);
            }
            continue;
        };
        let mut with_row = Matrix::zeros(kept.len() + 1, coords.len());
        for (j, value) in row.into_iter().enumerate() {
            for k in 0..kept.len() {
                with_row.set(k, j, independent.get(k, j).clone());
            }
            all.set(i, j, value.clone());
            with_row.set(kept.len(), j, value);
        }
        if with_row.reduce().pivot_cols.len() > kept.len() {
            independent = with_row;
            kept.push(i);
            if kept.len() == bound {
                return Ok((independent, kept));
            }
        }
    }
    Ok((all, kept))
}

/// The gradient of `f` by `coords` at an exact point, evaluated from its terms
/// ([`Expr::eval_gradient`]) where the derivative is the plain one (no denominator atom or
/// radical to differentiate through) and no coordinate is zero there, else by differentiating.
fn gradient_at(
    space: &PhaseSpace,
    f: &Expr,
    coords: &[Var],
    point: &Point,
) -> Result<Vec<GaussianRational>, EngineError> {
    if space.denominator_atoms().is_empty() && space.radicals().is_empty() {
        if let Some(gradient) = f.eval_gradient(point, coords)? {
            return Ok(gradient);
        }
    }
    coords
        .iter()
        .map(|&c| Ok(space.derivative(f, c)?.eval(point)?))
        .collect()
}

/// The rank of a Jacobian's values `m` at a point, with a nonzero minor of that size there.
fn certificate_of(m: Matrix, coords: &[Var], (_, values): SamplePoint) -> RankCertificate {
    let red = m.reduce();
    let r = red.pivot_cols.len();
    let mut rows = red.pivot_rows.clone();
    rows.sort_unstable();
    let cols = red.pivot_cols.clone();
    let mut minor = Matrix::zeros(r, r);
    for (a, &i) in rows.iter().enumerate() {
        for (b, &j) in cols.iter().enumerate() {
            minor.set(a, b, m.get(i, j).clone());
        }
    }
    RankCertificate {
        rank: r,
        coordinates: coords.to_vec(),
        minor_rows: rows,
        minor_cols: cols.iter().map(|&j| coords[j]).collect(),
        point: values,
        minor_value: minor.determinant(),
        upper: UpperBound::Size,
    }
}

/// How many minors of `jac` bordering the certificate's nonzero minor (its rows and columns
/// with one more of each) were expanded when every one vanishes identically, or `None` at the
/// first that does not.
fn vanishing_bordering_minors(
    jac: &[Vec<Expr>],
    coords: &[Var],
    cert: &RankCertificate,
) -> Result<Option<usize>, EngineError> {
    let minor_cols: Vec<usize> = cert
        .minor_cols
        .iter()
        .map(|v| coords.iter().position(|c| c == v).expect("a coordinate"))
        .collect();
    let mut count = 0;
    for extra_row in (0..jac.len()).filter(|i| !cert.minor_rows.contains(i)) {
        let rows = expansion_order(jac, cert.minor_rows.iter().copied().chain([extra_row]));
        // The minors of these rows share their smaller minors: computed once for all of
        // their column sets.
        let mut minors = Minors::new(jac, &rows);
        for extra_col in (0..coords.len()).filter(|j| !minor_cols.contains(j)) {
            let cols: Vec<usize> = minor_cols
                .iter()
                .copied()
                .chain([extra_col])
                .sorted_unstable()
                .collect();
            count += 1;
            if !minors.det(&cols)?.vanishes()? {
                return Ok(None);
            }
        }
    }
    Ok(Some(count))
}

/// The rows of a minor in the order its Laplace expansion takes them when only whether it
/// vanishes matters (a permutation of the rows changes its sign only): the rows of more terms
/// first, ties in increasing order. The expansion multiplies the first row's entries once, by
/// the minors of the other rows, and the last rows' in every one of their many smaller
/// minors, so the large entries are best multiplied where the products are fewest. With
/// `F1, G1, G2` (monomial derivatives) and `P_{40,40}, Q_{40,40}` (23 000 terms each) at
/// `p_θ = Iω`, the rows in increasing order formed all ten 2 × 2 minors of `P` and `Q`,
/// 20 products of 23 000 by 23 000 terms (10¹⁰ term products, 35 s); `P` and `Q` first, 5
/// products of `P`'s entries by the 28 000-term minors of the others (3·10⁹, 25 s).
fn expansion_order(jac: &[Vec<Expr>], rows: impl Iterator<Item = usize>) -> Vec<usize> {
    let terms = |i: usize| jac[i].iter().map(Expr::len).sum::<usize>();
    rows.map(|i| (std::cmp::Reverse(terms(i)), i))
        .sorted_unstable()
        .map(|(_, i)| i)
        .collect()
}

/// The determinant of the submatrix `rows × cols`, by Laplace expansion with memoised minors;
/// zero at once when two of its rows are equal (the same function given twice, say).
pub fn symbolic_det(
    jac: &[Vec<Expr>],
    rows: &[usize],
    cols: &[usize],
) -> Result<Expr, EngineError> {
    Minors::new(jac, rows).det(cols)
}

/// The minors of a fixed set of rows of a matrix of polynomials, for column sets of the
/// rows' number: each by Laplace expansion along the rows in order, every smaller minor
/// (the rows from some depth on, by a set of columns) computed once and kept for the other
/// column sets. The six 5 × 5 minors of five rows in six coordinates share their 2 × 2
/// minors of the last two rows, 15 of them where each minor alone would compute 10; the
/// minors bordering a rank's nonzero minor, its columns and one more, share every minor
/// of its columns alone.
#[derive(Debug)]
pub struct Minors<'a> {
    jac: &'a [Vec<Expr>],
    rows: &'a [usize],
    /// The minor of the last `k` rows by the columns of a mask (a bit per column of the
    /// matrix), under that mask; `k` is the mask's number of columns.
    memo: HashMap<u64, Expr>,
}

impl<'a> Minors<'a> {
    /// The minors of `rows` of `jac` (a matrix of at most 64 columns, and at least one row).
    pub fn new(jac: &'a [Vec<Expr>], rows: &'a [usize]) -> Self {
        Minors {
            jac,
            rows,
            memo: HashMap::new(),
        }
    }

    /// The determinant of the rows by `cols`, in increasing order and as many as the rows;
    /// zero at once when two rows are equal on these columns.
    pub fn det(&mut self, cols: &[usize]) -> Result<Expr, EngineError> {
        debug_assert!(cols.len() == self.rows.len() && cols.iter().all(|&c| c < 64));
        debug_assert!(cols.windows(2).all(|w| w[0] < w[1]));
        let (jac, rows) = (self.jac, self.rows);
        let row = |i: usize| cols.iter().map(move |&c| &jac[i][c]);
        if rows
            .iter()
            .enumerate()
            .any(|(k, &a)| rows[k + 1..].iter().any(|&b| row(a).eq(row(b))))
        {
            return Ok(Expr::zero(jac[0][0].vars()));
        }
        let mask = cols.iter().fold(0u64, |m, &c| m | 1 << c);
        self.minor(mask)
    }

    /// The minor of the last `mask.count_ones()` rows by the columns of `mask`, expanded
    /// along its first row, the columns in increasing order with alternating signs.
    fn minor(&mut self, mask: u64) -> Result<Expr, EngineError> {
        let vars = self.jac[0][0].vars();
        if mask == 0 {
            return Ok(Expr::one(vars));
        }
        if let Some(e) = self.memo.get(&mask) {
            return Ok(e.clone());
        }
        let depth = self.rows.len() - mask.count_ones() as usize;
        let mut acc = Expr::zero(vars);
        let (mut rest, mut sign_positive) = (mask, true);
        while rest != 0 {
            let c = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            let entry = &self.jac[self.rows[depth]][c];
            if !entry.is_zero() {
                let t = entry.checked_mul(&self.minor(mask & !(1 << c))?)?;
                acc = if sign_positive {
                    acc.checked_add(&t)?
                } else {
                    acc.checked_sub(&t)?
                };
            }
            sign_positive = !sign_positive;
        }
        self.memo.insert(mask, acc.clone());
        Ok(acc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::systems::harmonic_rotor;

    #[test]
    fn an_upper_bound_prints_its_reason() {
        assert_eq!(
            UpperBound::Size.to_string(),
            "the rank is at most the number of functions or of coordinates"
        );
        assert_eq!(
            UpperBound::VanishingMinors { count: 1 }.to_string(),
            "the one minor bordering the nonzero one vanishes identically"
        );
        assert_eq!(
            UpperBound::VanishingMinors { count: 9 }.to_string(),
            "the 9 minors bordering the nonzero one vanish identically"
        );
    }

    fn rank_of(functions: &[&str]) -> RankCertificate {
        let rotor = harmonic_rotor();
        let exprs: Vec<Expr> = functions.iter().map(|f| rotor.parse(f).unwrap()).collect();
        rank(rotor.space(), &exprs).expect("a certificate")
    }

    /// The first sample points lie on one line, here `x − 2y + 1 = 0` at all four: the
    /// gradient of `(x − 2y + 1)²` vanishes there, and the rank was reported as an error.
    /// A larger minor that does not vanish identically now sends the search to further
    /// points, and its value there is the certificate.
    #[test]
    fn a_minor_vanishing_on_the_first_points_is_found_at_a_further_one() {
        assert_eq!(rank_of(&["(x - 2*y + 1)^2"]).rank, 1);
        let cert = rank_of(&["(x - 2*y + 1)^2", "x*p_y - y*p_x"]);
        assert_eq!(cert.rank, 2);
        assert_eq!(cert.upper, UpperBound::Size);
        assert!(!cert.minor_value.is_zero());
        let value = |name: &str| {
            let rotor = harmonic_rotor();
            let v = rotor.vars().lookup(name).unwrap();
            cert.point.iter().find(|(w, _)| *w == v).unwrap().1.clone()
        };
        let on_line = &(&value("x") - &(&value("y") * &GaussianRational::from(2)))
            + &GaussianRational::from(1);
        assert!(
            !on_line.is_zero(),
            "the certificate's point is off the line"
        );
    }

    /// The angular momenta `L_ij = x_i p_j − x_j p_i` in five dimensions: ten functions of
    /// rank 2·5 − 3 = 7 in ten coordinates. The upper bound expands the (10 − 7)(10 − 7) = 9
    /// minors of size 8 that border the nonzero one, not all C(10, 8)² = 2025 of that size.
    /// The minor's seven functions alone keep the rank; six of them have rank 6.
    #[test]
    fn the_upper_bound_expands_only_the_bordering_minors() {
        let mut builder = trigpoly::Vars::builder();
        for i in 1..=5 {
            builder = builder
                .coordinate(&format!("x{i}"))
                .momentum(&format!("p{i}"));
        }
        let vars = builder.build().unwrap();
        let pairs: Vec<(String, String)> = (1..=5)
            .map(|i| (format!("x{i}"), format!("p{i}")))
            .collect();
        let pairs: Vec<(&str, &str)> = pairs
            .iter()
            .map(|(q, p)| (q.as_str(), p.as_str()))
            .collect();
        let space = PhaseSpace::new(&vars, &pairs).unwrap();
        let momenta: Vec<Expr> = (1..=5)
            .flat_map(|i| (i + 1..=5).map(move |j| (i, j)))
            .map(|(i, j)| Expr::parse(&vars, &format!("x{i}*p{j} - x{j}*p{i}")).unwrap())
            .collect();
        let cert = rank(&space, &momenta).expect("a certificate");
        assert_eq!(cert.rank, 7);
        assert_eq!(cert.upper, UpperBound::VanishingMinors { count: 9 });
        // The nonzero minor's functions: dropping the others keeps the rank.
        let chosen: Vec<Expr> = cert
            .minor_rows
            .iter()
            .map(|&i| momenta[i].clone())
            .collect();
        assert_eq!(rank(&space, &chosen).unwrap().rank, 7);
        // And one of them less lowers it.
        assert_eq!(rank(&space, &chosen[1..]).unwrap().rank, 6);
    }

    /// On the level set `p_y = x` the function `p_y − x` vanishes: with `L` it has rank 1
    /// there (2 on the whole space), by the five phase variables but `p_y`. The certificate's
    /// point leaves out `p_y` and the parameter `ω` the condition sets.
    #[test]
    fn a_rank_on_a_level_set_drops_the_set_variable() {
        let rotor = harmonic_rotor();
        let p = |s: &str| rotor.parse(s).unwrap();
        let functions = [p("p_y - x"), p("L")];
        assert_eq!(rank(rotor.space(), &functions).unwrap().rank, 2);
        let (p_y, omega) = (rotor.var("p_y"), rotor.var("omega"));
        let at = Condition::all("p_y = x, ω = 2", vec![(p_y, p("x")), (omega, p("2"))]).unwrap();
        let cert = rank_on(rotor.space(), &functions, &at).unwrap();
        assert_eq!(cert.rank, 1);
        let coordinates = rotor.space().coordinates();
        assert_eq!(cert.coordinates.len(), coordinates.len() - 1);
        assert!(!cert.coordinates.contains(&p_y));
        assert!(cert.point.iter().all(|(v, _)| *v != p_y && *v != omega));
        assert!(matches!(cert.upper, UpperBound::VanishingMinors { .. }));
        // Functions that still hold p_y would be differentiated as if it were a parameter;
        // ones that still hold ω, taken at another value of it than the condition's.
        let unrestricted = rank_restricted(rotor.space(), &functions, &at).unwrap_err();
        assert!(
            unrestricted.to_string().contains("still holds p_y"),
            "{unrestricted}"
        );
        let with_omega = [p("x"), p("omega*y")];
        let unrestricted = rank_restricted(rotor.space(), &with_omega, &at).unwrap_err();
        assert!(
            unrestricted.to_string().contains("still holds ω"),
            "{unrestricted}"
        );
    }

    /// A level set sets coordinates, momenta and parameters: an angle (its `e^{iθ}`) has no
    /// column to drop, and a parameter set to a function of phase space changes the
    /// functions, not where they are taken.
    #[test]
    fn a_level_set_refuses_an_angle_and_a_parameter_on_phase_space() {
        let rotor = harmonic_rotor();
        let functions = [rotor.parse("L").unwrap()];
        let refusal = |name: &str, value: &str| {
            let at = Condition::all(
                &format!("{name} = {value}"),
                vec![(rotor.var(name), rotor.parse(value).unwrap())],
            )
            .unwrap();
            match rank_on(rotor.space(), &functions, &at) {
                Err(EngineError::RefusedCondition { message, .. }) => message,
                other => panic!("{name} = {value}: {other:?}"),
            }
        };
        assert!(refusal("theta", "1").starts_with("the condition sets the angle θ"));
        assert!(refusal("omega", "p_x/M").starts_with(
            "the condition sets the parameter ω to a function of phase space (it holds p_x, a \
             momentum)"
        ));
    }

    /// The bordering minors expand the rows of more terms first: there they are multiplied
    /// by the minors of the others once, not in every minor of the last rows (10¹⁰ term
    /// products for `F1, G1, G2, P_{40,40}, Q_{40,40}` at `p_θ = Iω` in increasing order,
    /// 3·10⁹ with `P` and `Q` first). Ties keep their order; the rank is unchanged.
    #[test]
    fn the_bordering_minors_expand_the_largest_rows_first() {
        let rotor = harmonic_rotor();
        let p = |s: &str| rotor.parse(s).unwrap();
        let functions = [p("F1"), p("(x + y + p_x)^3"), p("G1"), p("(x - p_y)^3")];
        let coords = rotor.space().coordinates();
        let jac: Vec<Vec<Expr>> = functions
            .iter()
            .map(|f| {
                coords
                    .iter()
                    .map(|&c| rotor.space().derivative(f, c).unwrap())
                    .collect()
            })
            .collect();
        assert_eq!(expansion_order(&jac, 0..4), [1, 3, 0, 2]);
        assert_eq!(expansion_order(&jac, [2, 0].into_iter()), [0, 2]);
        let rank = rank_of(&["F1", "G1", "(x + y + p_x)^3", "F1 + (x + y + p_x)^3"]);
        assert_eq!(rank.rank, 3);
        assert!(matches!(rank.upper, UpperBound::VanishingMinors { .. }));
    }

    /// A dependent pair keeps its rank with the vanishing minors as the upper bound.
    #[test]
    fn dependent_functions_keep_their_rank() {
        let cert = rank_of(&["(x - 2*y + 1)^2", "(x - 2*y + 1)^3"]);
        assert_eq!(cert.rank, 1);
        assert!(matches!(cert.upper, UpperBound::VanishingMinors { count } if count > 0));
    }
}
