//! Claims `lhs = rhs`, optionally under a condition on phase space, and their outcome: proved,
//! or refuted with the nonzero residual `lhs − rhs` in normal form.

use std::borrow::Cow;
use std::time::Instant;

use trigpoly::{Expr, Var};

use crate::error::EngineError;

/// A condition on phase space, applied after the bracket is formed: a substitution such as the
/// resonance `p_θ = mIω/n`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Condition {
    /// How the condition reads (`p_θ = 2Iω`).
    pub text: String,
    /// The substitution.
    pub subs: Vec<(Var, Expr)>,
}

impl Condition {
    /// `v = value`.
    pub fn new(text: &str, v: Var, value: Expr) -> Self {
        Condition {
            text: text.to_string(),
            subs: vec![(v, value)],
        }
    }

    /// Applies the substitution.
    pub fn apply(&self, e: &Expr) -> Result<Expr, EngineError> {
        Ok(e.subst_many(&self.subs)?)
    }

    /// Refuses the condition where it sets to zero a variable that one of `sides` divides by:
    /// there the sides have no value, even when their difference is zero before the
    /// substitution (`p_x/M = p_x/M` at `M = 0`).
    pub fn defined_on(&self, sides: &[&Expr]) -> Result<(), EngineError> {
        for (v, value) in &self.subs {
            let divides = |e: &&Expr| e.exponent_range(*v).is_some_and(|(lo, _)| lo < 0);
            if value.is_zero() && sides.iter().any(divides) {
                let name = value.vars().variable(*v).unicode().to_string();
                return Err(EngineError::Invalid(format!(
                    "the condition sets {name} = 0, but the claim divides by {name}"
                )));
            }
        }
        Ok(())
    }
}

/// An identity to check: `lhs = rhs`, under an optional condition.
#[derive(Clone, Debug)]
pub struct Claim {
    /// An identifier such as `C09`.
    pub id: String,
    /// How the claim reads (`{L, G1} = −G2`).
    pub statement: String,
    /// Left-hand side.
    pub lhs: Expr,
    /// Right-hand side.
    pub rhs: Expr,
    /// Where the claim is meant to hold.
    pub condition: Option<Condition>,
}

/// What checking a claim found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// `lhs − rhs` is exactly zero (after the condition).
    Proved,
    /// `lhs − rhs` is not zero: here it is, in normal form.
    Refuted {
        /// The residual `lhs − rhs`.
        residual: Expr,
    },
}

impl Outcome {
    /// Whether the claim was proved.
    pub fn is_proved(&self) -> bool {
        matches!(self, Outcome::Proved)
    }
}

/// A checked claim, with its timing.
#[derive(Clone, Debug)]
pub struct Verdict {
    /// The claim's identifier.
    pub id: String,
    /// How the claim reads.
    pub statement: String,
    /// The condition's text, if any.
    pub condition: Option<String>,
    /// Proved or refuted.
    pub outcome: Outcome,
    /// Seconds spent checking.
    pub seconds: f64,
}

impl Claim {
    /// `lhs = rhs`.
    pub fn new(id: &str, statement: &str, lhs: Expr, rhs: Expr) -> Self {
        Claim {
            id: id.into(),
            statement: statement.into(),
            lhs,
            rhs,
            condition: None,
        }
    }

    /// The same claim under a condition.
    pub fn when(mut self, condition: Condition) -> Self {
        self.condition = Some(condition);
        self
    }

    /// The residual `lhs − rhs` after the condition, in normal form.
    pub fn residual(&self) -> Result<Expr, EngineError> {
        if let Some(c) = &self.condition {
            c.defined_on(&[&self.lhs, &self.rhs])?;
        }
        // `lhs − 0` is `lhs`: no copy before the condition.
        let d = if self.rhs.is_zero() {
            Cow::Borrowed(&self.lhs)
        } else {
            Cow::Owned(self.lhs.checked_sub(&self.rhs)?)
        };
        match &self.condition {
            Some(c) => c.apply(&d),
            None => Ok(d.into_owned()),
        }
    }

    /// Checks the claim exactly.
    pub fn check(&self) -> Result<Verdict, EngineError> {
        let start = Instant::now();
        let residual = self.residual()?;
        let outcome = if residual.is_zero() {
            Outcome::Proved
        } else {
            Outcome::Refuted { residual }
        };
        Ok(Verdict {
            id: self.id.clone(),
            statement: self.statement.clone(),
            condition: self.condition.as_ref().map(|c| c.text.clone()),
            outcome,
            // Timing is reported, never used to decide anything.
            seconds: start.elapsed().as_secs_f64(),
        })
    }
}
