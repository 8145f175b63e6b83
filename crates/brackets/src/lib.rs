//! # brackets
//!
//! The bracket engine: phase spaces, the Poisson bracket, Hamiltonian systems with named
//! functions, claims proved or refuted exactly, bracket tables, the tower of resonant integrals
//! with its all-`m, n` proof, and certified Jacobian ranks. It does no I/O.
//!
//! ```
//! use brackets::{systems, Claim};
//!
//! // C09: {G1, G2} = −ω² L for the harmonic rotor.
//! let rotor = systems::harmonic_rotor();
//! let claim = Claim::new(
//!     "C09",
//!     "{G1, G2} = −ω² L",
//!     rotor.parse("{G1, G2}")?,
//!     rotor.parse("-omega^2*L")?,
//! );
//! assert!(claim.check()?.outcome.is_proved());
//! # Ok::<(), brackets::EngineError>(())
//! ```
//!
//! A claim made by [`Claim::new`] holds its sides as bare expressions and cannot see what they
//! were computed from: under a condition that sets to 0 a variable `H` or a function divides
//! by, where the bracket has cancelled the divisor, it is decided though it has no value.
//! [`Claim::parse`] reads the sides in a system and refuses such a condition.
#![deny(missing_docs, missing_debug_implementations)]

mod claim;
mod clearing;
pub mod closure;
mod error;
mod inputs;
pub mod linalg;
pub mod modular;
mod phase;
pub mod rank;
pub mod scaling;
pub mod search;
mod system;
pub mod systems;
pub mod table;
pub mod tower;
pub mod univariate;

pub use claim::{Claim, Condition, LeftByFlow, Outcome, Verdict};
pub use closure::{
    closure, closure_of, expressed_in, Bracket as ClosureBracket, Closure, ClosureOptions,
    Expressed, Relation,
};
pub use error::{EngineError, EngineLimit, JacobiViolation};
pub use inputs::{Input, Recording};
pub use phase::{CanonicalPair, DeclaredBracket, Gradient, PhaseSpace};
pub use rank::{
    generated_rank_within, integrals_rank_within, level_set_coordinates, rank, rank_on,
    rank_restricted, rank_within, BoundedRank, RankCertificate, UpperBound,
};
pub use search::{search, Integral, SearchOptions, SearchResult, SearchSpace, SpaceVariables};
pub use system::{NamedFunction, System};
pub use table::{BracketTable, Entry, FunctionName};
pub use tower::{check_tower, eigen_proof, eigen_proof_of, EigenProof, TowerReport};
