//! The performance workloads W1–W4, defined once: the `bench` subcommand, the Rust benchmarks
//! (`benches/workloads.rs`) and the peer scripts (`benches/peers/`) all run exactly these.
//!
//! - **W1 tower(N)**: for all `1 ≤ m, n ≤ N`, expand `P_{m,n}` and `Q_{m,n}` with symbolic
//!   `M, ω`, form their bracket with `H`, restrict to `p_θ = mIω/n`, test for zero. Every bracket
//!   is expanded in full; no use of the eigenfunction lemma.
//! - **W2 single(m)**: the same for the one pair `m = n`.
//! - **W3 products**: Fateman `f·(f + 1)` with `f = (1 + x + y + z + t)^N`, and Pearce
//!   `(1 + x + y + 2z² + 3t³ + 5u⁵)^N · (1 + u + t + 2z² + 3y³ + 5x⁵)^N`.
//! - **W4 algebra**: the su(2) brackets `{L, G1} = −G2`, `{L, G2} = 4 G1`, `{G1, G2} = −ω² L` and
//!   the Casimir (C09, C10), each formed and checked, `N` times. The generators are the inputs,
//!   built once; the brackets and every product of the Casimir, `(F1 − F2)²` included, are
//!   computed in every repetition, on every side of the comparison (superint forms the
//!   Casimir's four products as one [`Poly::sum_of_products`]). The repetitions are
//!   independent, and share the threads of the pool.

use std::fmt;
use std::str::FromStr;

use brackets::{systems, EngineError, System};
use rayon::prelude::*;
use trigpoly::{Expr, Poly, Rational, Vars};

/// One workload with its size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Workload {
    /// W1: every `1 ≤ m, n ≤ N`.
    Tower(i64),
    /// W2: `m = n = N`.
    Single(i64),
    /// W3a: the Fateman product with `f = (1 + x + y + z + t)^N`.
    Fateman(i64),
    /// W3b: the sparse Pearce product with exponent `N`.
    Pearce(i64),
    /// W4: the su(2) table and Casimir, `N` times.
    Algebra(i64),
}

/// What a workload computed: the number of terms it produced and the identities it checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Outcome {
    /// Terms of the expanded inputs (W1, W2: `P` and `Q`), or of the product (W3), or of the
    /// brackets (W4).
    pub terms: usize,
    /// Identities found exactly zero (W3: 0, it only multiplies).
    pub zeros: usize,
}

/// Why a workload failed: the engine refused, or an identity was not zero.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum WorkloadError {
    /// The engine refused (a limit, say).
    #[error(transparent)]
    Engine(#[from] EngineError),
    /// An identity that must hold did not.
    #[error("{0} is not zero")]
    NotZero(String),
    /// A tower of this size (W1) has more pairs `(m, n)`, or twice as many identities, than a
    /// `usize` counts (size 2³² and past; 2¹⁶ where a `usize` has 32 bits).
    #[error(
        "a tower of size {0} has {0}² pairs (m, n) and twice as many identities, more than \
         this machine counts ({max}): give a smaller size",
        max = usize::MAX
    )]
    TooLarge(i64),
}

impl From<trigpoly::AlgebraError> for WorkloadError {
    fn from(e: trigpoly::AlgebraError) -> Self {
        WorkloadError::Engine(e.into())
    }
}

/// `{P, H}` and `{Q, H}` at `p_θ = mIω/n` for one pair; returns the terms of `P` and `Q`.
/// The two brackets are independent: with more than one thread they run side by side.
fn resonant_pair(rotor: &System, m: i64, n: i64) -> Result<usize, WorkloadError> {
    let res = rotor.resonant("Z", m, n)?;
    let resonance = rotor.resonance(m, n)?;
    let check = |f: &Expr| -> Result<(), WorkloadError> {
        if rotor.flow_when(f, &resonance)?.is_zero() {
            Ok(())
        } else {
            Err(WorkloadError::NotZero(format!(
                "{{P_{{{m},{n}}}, H}} at resonance"
            )))
        }
    };
    let (p, q) = rayon::join(|| check(&res.p), || check(&res.q));
    p.and(q)?;
    Ok(res.p.len() + res.q.len())
}

impl Workload {
    /// Runs the workload once.
    pub fn run(&self) -> Result<Outcome, WorkloadError> {
        match *self {
            Workload::Tower(n) => {
                let rotor = systems::harmonic_rotor();
                // The pairs are independent; rayon spreads them over the threads of the pool
                // the caller installed (one thread: the plain loop, in order). They are
                // numbered, not listed: `W1 100000` listed 10¹⁰ pairs, 160 GB, before the
                // first of them stopped at the limit on θ's order.
                // A size below 1 has no pairs, as `1..=n` had none (`n as usize` made -1 a
                // side of 2⁶⁴ − 1, whose square overflowed).
                // `side * side` wrapped past 2³² (`W1 2³²` checked no pair and reported none
                // failing; a panic in a debug build), and wraps past 2¹⁶ where a `usize` has 32
                // bits: such a tower is refused, with the pairs it would have.
                let side = usize::try_from(n).unwrap_or(0);
                let (pairs, zeros) = side
                    .checked_mul(side)
                    .and_then(|pairs| Some((pairs, pairs.checked_mul(2)?)))
                    .ok_or(WorkloadError::TooLarge(n))?;
                let terms: usize = (0..pairs)
                    .into_par_iter()
                    .map(|i| resonant_pair(&rotor, (i / side) as i64 + 1, (i % side) as i64 + 1))
                    .collect::<Result<Vec<_>, _>>()?
                    .into_iter()
                    .sum();
                Ok(Outcome { terms, zeros })
            }
            Workload::Single(m) => {
                let rotor = systems::harmonic_rotor();
                Ok(Outcome {
                    terms: resonant_pair(&rotor, m, m)?,
                    zeros: 2,
                })
            }
            Workload::Fateman(n) => {
                let vars = product_vars();
                let f = parse(&vars, &format!("(1 + x + y + z + t)^{n}"))?;
                let g = f.checked_add(&Poly::one(&vars))?;
                Ok(Outcome {
                    terms: f.checked_mul(&g)?.len(),
                    zeros: 0,
                })
            }
            Workload::Pearce(n) => {
                let vars = product_vars();
                let f = parse(&vars, &format!("(1 + x + y + 2*z^2 + 3*t^3 + 5*u^5)^{n}"))?;
                let g = parse(&vars, &format!("(1 + u + t + 2*z^2 + 3*y^3 + 5*x^5)^{n}"))?;
                Ok(Outcome {
                    terms: f.checked_mul(&g)?.len(),
                    zeros: 0,
                })
            }
            Workload::Algebra(reps) => {
                let rotor = systems::harmonic_rotor();
                let get = |name: &str| rotor.get(name).cloned();
                let (l, g1, g2) = (get("L")?, get("G1")?, get("G2")?);
                let f1_minus_f2 = get("F1")?.checked_sub(&get("F2")?)?;
                let omega2 = rotor.parse("omega^2")?;
                let four = trigpoly::GaussianRational::from(4);
                // One repetition: the brackets' terms, or why an identity failed.
                let repetition = || -> Result<usize, WorkloadError> {
                    let lg1 = rotor.bracket(&l, &g1)?;
                    let lg2 = rotor.bracket(&l, &g2)?;
                    let g1g2 = rotor.bracket(&g1, &g2)?;
                    let terms = lg1.len() + lg2.len() + g1g2.len();
                    let four_g1 = g1.scale(&four);
                    let omega2_l = omega2.checked_mul(&l)?;
                    // {L, G1} = −G2, {L, G2} = 4 G1, {G1, G2} = −ω² L
                    let mut all = lg1.checked_add(&g2)?.is_zero();
                    all &= lg2.checked_sub(&four_g1)?.is_zero();
                    all &= g1g2.checked_add(&omega2_l)?.is_zero();
                    // 4 G1² + G2² + ω² L² − (F1 − F2)² = 0, every product in one sum
                    let casimir = Poly::sum_of_products(&[
                        (&four_g1, &g1, false),
                        (&g2, &g2, false),
                        (&omega2_l, &l, false),
                        (&f1_minus_f2, &f1_minus_f2, true),
                    ])?;
                    all &= casimir.is_zero();
                    if all {
                        Ok(terms)
                    } else {
                        Err(WorkloadError::NotZero("an su(2) identity".into()))
                    }
                };
                // The repetitions are independent: with more than one thread they share the
                // pool in pieces of at most 16 (rayon's own split, four pieces of 250 on two
                // threads, left a thread that woke late a quarter of the work or none); one
                // thread runs the plain loop, in order.
                let pieces = match rayon::current_num_threads() {
                    1 => usize::MAX,
                    _ => 16,
                };
                let terms = (0..usize::try_from(reps).unwrap_or(0))
                    .into_par_iter()
                    .with_max_len(pieces)
                    .map(|_| repetition())
                    .try_reduce(|| 0, |a, b| Ok(a + b))?;
                let zeros = reps.max(0) as usize;
                Ok(Outcome { terms, zeros })
            }
        }
    }

    /// The workload's name and size as the command line writes them: `tower 24`.
    pub fn label(&self) -> String {
        self.to_string()
    }
}

fn product_vars() -> Vars {
    Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .coordinate("t")
        .coordinate("u")
        .build()
        .expect("valid names")
}

fn parse(vars: &Vars, src: &str) -> Result<Poly<Rational>, WorkloadError> {
    Poly::parse(vars, src).map_err(|e| WorkloadError::Engine(EngineError::parse(src, e)))
}

impl fmt::Display for Workload {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (name, size) = match *self {
            Workload::Tower(n) => ("tower", n),
            Workload::Single(n) => ("single", n),
            Workload::Fateman(n) => ("fateman", n),
            Workload::Pearce(n) => ("pearce", n),
            Workload::Algebra(n) => ("algebra", n),
        };
        write!(f, "{name} {size}")
    }
}

/// Why a workload name did not parse.
#[derive(Debug, thiserror::Error)]
#[error(
    "unknown workload {0:?}: expected W1|tower, W2|single, W3a|fateman, W3b|pearce, W4|algebra"
)]
pub struct UnknownWorkload(pub String);

impl Workload {
    /// A workload from its name (`W1` or `tower`, ...) and size.
    pub fn new(name: &str, size: i64) -> Result<Workload, UnknownWorkload> {
        Ok(match name.to_ascii_lowercase().as_str() {
            "w1" | "tower" => Workload::Tower(size),
            "w2" | "single" => Workload::Single(size),
            "w3" | "w3a" | "fateman" => Workload::Fateman(size),
            "w3b" | "pearce" => Workload::Pearce(size),
            "w4" | "algebra" => Workload::Algebra(size),
            _ => return Err(UnknownWorkload(name.to_string())),
        })
    }
}

impl FromStr for Workload {
    type Err = UnknownWorkload;
    /// `"tower 24"` or `"W1 24"`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mut it = s.split_whitespace();
        let name = it.next().unwrap_or_default();
        let size = it
            .next()
            .and_then(|v| v.parse().ok())
            .ok_or_else(|| UnknownWorkload(s.into()))?;
        Workload::new(name, size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tower whose number of pairs `N²` (and of identities, `2N²`) does not fit a `usize`
    /// is refused: `side * side` wrapped (`N = 2³²` checked no pair and reported none
    /// failing, and panicked in a debug build). Sizes whose pairs fit run until a limit stops
    /// them, past θ's order 1000.
    #[test]
    fn a_tower_with_more_pairs_than_a_usize_counts_is_refused() {
        let side = 1i64 << (usize::BITS / 2);
        for n in [side, side + 1, i64::MAX] {
            match Workload::Tower(n).run() {
                Err(e @ WorkloadError::TooLarge(_)) => {
                    let message = e.to_string();
                    assert!(
                        message.starts_with(&format!(
                            "a tower of size {n} has {n}² pairs (m, n) and twice"
                        )),
                        "{message}"
                    );
                }
                other => panic!("{n}: {other:?}"),
            }
        }
        // 2N² overflows where N² does not.
        let half = i64::try_from((usize::MAX / 2).isqrt() + 1).expect("half a usize's side");
        assert!(matches!(
            Workload::Tower(half).run(),
            Err(WorkloadError::TooLarge(_))
        ));
        let below = Workload::Tower(side / 2).run().unwrap_err().to_string();
        assert!(below.contains("past the limit of 1000"), "{below}");
    }

    /// A tower of a size below 1 has no pairs, and computes none.
    #[test]
    fn a_tower_below_size_one_has_no_pairs() {
        for n in [0, -1, -7] {
            assert_eq!(Workload::Tower(n).run().unwrap().terms, 0, "{n}");
        }
    }
}
