//! A search on the level set `P = 0` of a polynomial whose level set the flow of `H` keeps
//! (`{P, H}` in the ideal `(P)`), [`SearchOptions::on`](super::SearchOptions::on): the
//! integrals that exist only there, such as the Goryachev–Chaplygin top's cubic integral on
//! the area integral's level `M·γ = 0`, found by exact linear algebra on polynomials.
//!
//! `P` alone is a Gröbner basis of `(P)`: in a graded lexicographic order on the phase
//! variables ([`DivisionOrder`]), with a number as the coefficient of its leading monomial
//! `LM(P)`, the monomials that `LM(P)` does not divide span the normal forms modulo `(P)`. The
//! space's monomials that it divides are left out (each is a lower combination modulo `P`),
//! and each image `{φ, H}` is replaced by its remainder on division by `P`: the kernel is then
//! exactly the normal forms `K` in the space with `{K, H} ∈ (P)`, none of them in `(P)` (a
//! nonzero normal form is not). Nothing is lost where the division keeps the space's degree
//! bounds (one total degree, the Poisson degree of a Lie–Poisson system): where it does not
//! (momenta and positions bounded apart, `x²` replaced through `H = E` by momenta), a function
//! of the space may have a normal form outside it, which the search says
//! ([`NormalFormOutside`](super::NormalFormOutside)), and only the integrals whose normal form
//! lies in the space are found. Each integral is proved by the quotient `Q` of that
//! division: `{K, H} − P·Q = 0`, recomputed from the bracket and the product.
//!
//! On a system with relations (declared denominators, radicals, negative powers of `H`, a
//! Laurent space) the same holds where no relation holds a phase variable of `P`, `V(P)`:
//! the ring is then `A ⊗ k[V(P)]`, `A` everything else with its relations and
//! `P ∈ k[V(P)]`, so its quotient by `(P)` is `A ⊗ k[V(P)]/(P)`, whose normal forms are the
//! remainders on division by `P` with `A`'s elements as coefficients, unique, and `LM(P)` in
//! the order of all the phase variables is its leading monomial in `V(P)` alone. Functions
//! are divided in the order on `V(P)` ([`LevelSet::division_order`]), and a remainder is zero
//! where it vanishes by the relations. Where a relation holds a variable of `P`, the level set
//! is refused naming it ([`SharedVariable`], which has the argument in full): in the Laurent
//! ring of `b/x²`, `x·p_y` and `p_y` span the same ideal, and the remainder `p_y` would refute
//! the true `p_y = 0` on `x p_y = 0`.

use trigpoly::{
    Division, DivisionOrder, DivisionRefusal, Expr, GaussianRational, Rational, Var, VarKind,
};

use crate::claim::Condition;
use crate::clearing::{parameter_atoms_at_values, vanishes_at_values};
use crate::error::EngineError;
use crate::inputs::Input;
use crate::modular::{Field, Fp, PRIME};
use crate::system::System;
use crate::univariate::{gcd_mod, is_square_free_mod};

use super::parameters::fix_parameters;

/// The level set `expr = value` of a search, as the user wrote it: `P = expr − value`.
#[derive(Clone, Debug)]
pub struct LevelSet {
    /// The text it was read from (`M1*gamma1 + M2*gamma2 + M3*gamma3 = 0`).
    pub text: String,
    /// The polynomial whose level is taken.
    pub expr: Expr,
    /// Its value there: a number, or parameters (`E`).
    pub value: Expr,
}

/// What a search proves of an integral on a level set: `{K, H} = Q·P`, with `Q` the
/// quotient of `{K, H}` on division by `P`, both at the parameters of `K`: with them where
/// it was lifted, else at the fixed values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LevelProof {
    /// `Q`.
    pub quotient: Expr,
    /// `P` as divided by: with its parameters, or at the fixed values.
    pub divisor: Expr,
}

impl LevelSet {
    /// The level set `expr = value` read from `text`.
    pub fn new(text: &str, expr: Expr, value: Expr) -> Self {
        LevelSet {
            text: text.to_string(),
            expr,
            value,
        }
    }

    /// `P = expr − value`.
    pub fn polynomial(&self) -> Result<Expr, EngineError> {
        Ok(self.expr.checked_sub(&self.value)?)
    }

    /// The order of the division: graded lexicographic on the coordinates, momenta and Poisson
    /// variables of `system`, in their declared order.
    pub fn order(system: &System) -> DivisionOrder {
        let vars = system.vars();
        let phase: Vec<Var> = vars
            .vars()
            .filter(|&v| {
                matches!(
                    vars.variable(v).kind(),
                    VarKind::Coordinate | VarKind::Momentum | VarKind::Poisson
                )
            })
            .collect();
        DivisionOrder::graded_lex(&phase)
    }

    /// The order a function is divided by `P` in: graded lexicographic on the phase variables
    /// that the level set's expression holds, `V(P)`, in their declared order. `P`'s leading
    /// monomial is the same as in [`LevelSet::order`] (`P` holds no other phase variable), and
    /// the remainders are the same for a polynomial; a function with a negative power of a
    /// variable outside `V(P)` (where no relation holds a variable of `P`,
    /// [`SharedVariable`]) is divided too, that variable a coefficient's.
    pub fn division_order(&self, system: &System) -> DivisionOrder {
        let held: Vec<Var> = (Self::order(system).variables().iter())
            .copied()
            .filter(|&v| self.expr.contains(v))
            .collect();
        DivisionOrder::graded_lex(&held)
    }

    /// Refuses a level set the search cannot take: `expr` holding an angle, a negative power,
    /// a denominator or a radical, or no phase variable at all; `value` holding a phase
    /// variable; `P` sharing a variable with a relation of the system or of the space, a
    /// Laurent space where `laurent` ([`SharedVariable`]); `P` not real (the normal forms of a
    /// real function modulo a complex `P` are complex, and its real level set needs two
    /// equations); a leading coefficient that is no number at the values `fixed` (parameters
    /// named there are numbers); and a level set that the flow of `H` leaves, `{P, H}` not in
    /// `(P)`, decided by the remainder of its division by `P`, with `H` and `P` at the values
    /// `fixed`, where the search is (the other parameters free): `x² + a y²` keeps
    /// `x p_y − y p_x = 0` at `a = 1` alone, which `--fix a=1` searches.
    pub fn check(
        &self,
        system: &System,
        fixed: &[(Var, Rational)],
        laurent: bool,
    ) -> Result<(), EngineError> {
        self.check_form(system, "--on", laurent)?;
        self.check_square_free_and_kept(system, fixed, None, CheckedFor::Search)
    }

    /// [`LevelSet::check`] for a search for the exceptional values of `parameter`
    /// ([`exceptional_values`](super::exceptional_values)), which is free there: `{P, H}` is
    /// divided by `P` with every parameter free (at `fixed` only where the leading coefficient
    /// needs them), and a level set that the flow keeps at some values of `parameter` alone is
    /// refused saying so.
    pub fn check_for_values_of(
        &self,
        system: &System,
        fixed: &[(Var, Rational)],
        parameter: Var,
        laurent: bool,
    ) -> Result<(), EngineError> {
        self.check_form(system, "--on", laurent)?;
        let checked_for = CheckedFor::ExceptionalValues(parameter);
        self.check_square_free_and_kept(system, fixed, None, checked_for)
    }

    /// [`LevelSet::check`] for a claim, which holds for every value of the parameters, with no
    /// value fixed: the same refusals, but `P` is shown square-free as a polynomial with its
    /// parameters, so for all of their values but those of a proper algebraic subset (`a = 0`
    /// of `x² = a`), by a square-free restriction to a line through phase space and the
    /// parameters (`with_parameters`), where a search takes them at 1 alone:
    /// `(x² + y²)² − (a − 1)(x² + y²)` is square-free, though not at `a = 1`, and so is
    /// `x² + a² − b`, though not where `b = a²`.
    ///
    /// Under a `condition` that fixes parameters alone, the level set is one at their values
    /// ([`LevelSet::at_values`]), and `{P, H}` is taken there too.
    pub fn check_for_every_value(
        &self,
        system: &System,
        condition: Option<&Condition>,
    ) -> Result<(), EngineError> {
        self.check_form(system, "`on`", false)?;
        self.check_square_free_and_kept(system, &[], condition, CheckedFor::Claim)
    }

    /// The rest of [`LevelSet::check`], after its form: the leading coefficient, `P` square-free
    /// (at the searched values of the parameters, or with them as variables for a claim), and
    /// the flow of `H` keeping the level set, where `checked_for` says, at the values of the
    /// parameters that `condition` fixes, if any.
    fn check_square_free_and_kept(
        &self,
        system: &System,
        fixed: &[(Var, Rational)],
        condition: Option<&Condition>,
        checked_for: CheckedFor,
    ) -> Result<(), EngineError> {
        let for_every_value = checked_for == CheckedFor::Claim;
        let invalid = |m: String| Err(EngineError::Invalid(m));
        let p = self.polynomial()?;
        let order = Self::order(system);
        let (p, at) = match p.leading_term(&order) {
            Ok(_) => (p, ""),
            Err(DivisionRefusal::LeadingCoefficient { .. }) => {
                let at_fixed = fix_parameters(&p, fixed)?;
                match at_fixed.leading_term(&order) {
                    Ok(_) => (at_fixed, " at the fixed values"),
                    Err(e) => return Err(refusal(&p, e)),
                }
            }
            Err(e) => return Err(refusal(&p, e)),
        };
        let p_searched = fix_parameters(&p, &level_parameter_values(&p, fixed))?;
        // With its parameters as variables of the lines too: square-free as a polynomial in
        // them and the phase variables, so over Q(parameters) (Gauss's lemma, the leading
        // coefficient a number), and for all their values but a proper algebraic subset.
        let square_free = has_no_repeated_factor(&p_searched, &order)
            || (for_every_value && has_no_repeated_factor(&p, &with_parameters(&p, &order)));
        if !square_free {
            // With its parameters as written where the lines ran through them too.
            let (shown, through) = match for_every_value && p_searched != p {
                true => (&p, "tried through phase space and its parameters"),
                false => (&p_searched, "through phase space tried"),
            };
            return invalid(format!(
                "the level set's polynomial P = {} is not shown square-free: it has a repeated \
                 root on every one of the {LINES_TRIED} lines {through}, as a polynomial with a \
                 repeated factor has; the functions on its level set are then not the normal \
                 forms modulo P; write each factor of P once (A = 0 for A^2 = 0)",
                shown.brief_excerpt()
            ));
        }
        // At the fixed values where the search is, or where the leading coefficient needs them.
        let searched_at_fixed =
            checked_for == CheckedFor::Search && fixed_anything(&p, system.hamiltonian(), fixed);
        let (p, at) = match searched_at_fixed && at.is_empty() {
            true => (fix_parameters(&p, fixed)?, " at the fixed values"),
            false => (p, at),
        };
        let h_fixed = if at.is_empty() { &[] } else { fixed };
        let h = fix_parameters(system.hamiltonian(), h_fixed)?;
        let flow = system.bracket(&p, &h)?;
        let flow = match condition {
            Some(c) => c.apply_where_defined(&flow, "{P, H}")?,
            None => flow,
        };
        let dividing = self.division_order(system);
        if let Some(v) = negative_power(&flow, &dividing) {
            return invalid(format!(
                "{{P, H}} = {} for P = {p}{at} has a negative power of {}: whether the flow of \
                 H keeps the level set, {{P, H}} a multiple of P, is not decided by dividing \
                 polynomials",
                flow.brief_excerpt(),
                vars_name(&flow, v)
            ));
        }
        let division = p_divide(&flow, &p, &dividing)?;
        if !vanishes_at_values(system.space(), h_fixed, &division.remainder)? {
            let searched_for = match checked_for {
                CheckedFor::ExceptionalValues(parameter) => {
                    let name = system.vars().variable(parameter).unicode();
                    format!(
                        "; {name} is searched for, so the flow must keep the level set at every \
                         value of {name}, not only where that remainder vanishes (search there \
                         with --fix)"
                    )
                }
                CheckedFor::Search | CheckedFor::Claim => String::new(),
            };
            return invalid(format!(
                "{FLOW_LEAVES}{at}: {{P, H}} = {flow} for P = {p}, which is not P times a \
                 polynomial (its remainder on division by P is {}){searched_for}",
                division.remainder
            ));
        }
        Ok(())
    }

    /// The part of [`LevelSet::check`] that reads the level set's form alone, its first
    /// refusals: an angle, a denominator or a radical in `expr`, a negative power, no phase
    /// variable, a value that is no constant ([`LevelSet::check_value`]), `P` sharing a
    /// variable with a relation ([`SharedVariable`]; a Laurent space's negative powers of the
    /// coordinates among them where `laurent`), and `P` not real, whose refusal says that
    /// `taken_by` (`--on`, or a claim's `` `on` ``) takes one equation.
    pub fn check_form(
        &self,
        system: &System,
        taken_by: &str,
        laurent: bool,
    ) -> Result<(), EngineError> {
        let vars = system.vars();
        let invalid = |m: String| Err(EngineError::Invalid(m));
        if let Some(v) = vars
            .vars()
            .find(|&v| self.expr.contains(v) && is_excluded(vars.variable(v).kind()))
        {
            let kind = match vars.variable(v).kind() {
                VarKind::Angle => "an angle",
                VarKind::Denominator => "a denominator",
                _ => "a radical",
            };
            return invalid(format!(
                "the level set's expression holds {kind}, {}: a level set is a polynomial's \
                 in the coordinates, momenta and Poisson variables",
                vars.variable(v).unicode()
            ));
        }
        let order = Self::order(system);
        if let Some(v) = negative_power(&self.expr, &order) {
            return invalid(format!(
                "the level set's expression has a negative power of {}: it must be a \
                 polynomial",
                vars.variable(v).unicode()
            ));
        }
        if !order.variables().iter().any(|&v| self.expr.contains(v)) {
            return invalid(
                "the level set's expression holds no variable of phase space: it is a \
                 constant, whose level is everything or nothing"
                    .into(),
            );
        }
        self.check_value(system)?;
        let p = self.polynomial()?;
        if let Some(shared) = SharedVariable::of(system, &p, laurent) {
            return invalid(shared.to_string());
        }
        if !p.is_real() && (&p * &GaussianRational::i()).is_real() {
            return invalid(format!(
                "the level set's polynomial P = {p} is i times a real polynomial: divide EXPR \
                 and VALUE by i"
            ));
        }
        if !p.is_real() {
            return invalid(format!(
                "the level set's polynomial P = {p} is not real (it differs from its \
                 conjugate): its real level set is where its real and imaginary parts both \
                 vanish, two equations, and {taken_by} takes one; write a real EXPR and VALUE"
            ));
        }
        Ok(())
    }

    /// Refuses a value that holds a phase variable: a level's value is a constant of the
    /// parameters, numbers, parameters, and the declared denominators and radicals of
    /// parameters alone (`1/(κ + 1)`, `is_constant_of_parameters`). Such an atom is one of
    /// `P`'s coefficients: the ring is (parameters, their atoms) ⊗ (phase variables), and
    /// `LM(P)` still has a number as coefficient. Part of [`LevelSet::check`], for a caller
    /// that places this refusal at the value and the others at the expression.
    pub fn check_value(&self, system: &System) -> Result<(), EngineError> {
        let vars = system.vars();
        match vars
            .vars()
            .find(|&v| self.value.contains(v) && !is_constant_of_parameters(system, v))
        {
            Some(v) => Err(EngineError::Invalid(format!(
                "the level set's value holds {}: it must be a constant (numbers, parameters, \
                 and denominators and radicals of parameters alone)",
                vars.variable(v).unicode()
            ))),
            None => Ok(()),
        }
    }

    /// The level set at the values of the parameters that `condition` fixes: its expression
    /// and value with them substituted, so that `P` is the polynomial at those values. A
    /// condition that sets a phase variable is refused beside a level set
    /// ([`BesideLevelSet::for_claim`]) before this is called; one that fixes parameters alone
    /// commutes with every bracket, so that `{P, H}` and a claim's `lhs − rhs` at the values
    /// are those with the values substituted. Refused where the condition sets to zero a
    /// parameter that the level set or `system`'s `H` divides by ([`Condition::defined_on`]):
    /// there the level set, or the flow that must keep it, has no value.
    pub fn at_values(
        &self,
        system: &System,
        condition: &Condition,
    ) -> Result<LevelSet, EngineError> {
        condition.defined_on(&[&self.expr, &self.value], "the level set")?;
        condition.defined_on(&[system.hamiltonian()], "H")?;
        Ok(LevelSet {
            text: self.text.clone(),
            expr: condition.apply(&self.expr)?,
            value: condition.apply(&self.value)?,
        })
    }

    /// Refuses a claim on the level set whose `sides`, or a function they were computed from
    /// (`inputs`, as [`Condition::defined_on_inputs`] takes them), divide by a phase variable
    /// of `P`: the claim is then about the level set where that variable is not zero, whose
    /// ideal division by `P` does not see, though `lhs − rhs` may have cancelled the divisor
    /// (`p_y + 1/x = 1/x` on `x p_y = 0` holds where `x ≠ 0`, and the remainder is `p_y`).
    pub fn check_defined_on(
        &self,
        system: &System,
        sides: &[&Expr],
        inputs: &[Input],
    ) -> Result<(), EngineError> {
        let dividing = self.division_order(system);
        let invalid = |m: String| Err(EngineError::Invalid(m));
        let p = || self.polynomial();
        // The name of a variable of `P` that `e` holds to a negative power, if any.
        let negative = |e: &Expr| negative_power(e, &dividing).map(|v| vars_name(e, v));
        // The two refusals differ past their first words: a side's negative power goes with
        // a multiple of both sides, an input's (a function the claim is computed from) with
        // another level set.
        if let Some((side, v)) = (sides.iter()).find_map(|s| negative(s).map(|v| (s, v))) {
            return invalid(format!(
                "the side {} has a negative power of {v}: a claim on a level set is decided by \
                 dividing lhs − rhs by P = {}, which takes polynomials in P's variables, and the \
                 claim has no value where {v} = 0, though lhs − rhs may cancel {v}; multiply \
                 both sides by a power of {v}",
                side.brief_excerpt(),
                p()?
            ));
        }
        if let Some((input, v)) = (inputs.iter()).find_map(|i| negative(&i.value).map(|v| (i, v))) {
            let what = match &input.via {
                Some(via) => format!("the claim's {via} is computed from {}, which", input.what),
                None => input.what.clone(),
            };
            return invalid(format!(
                "{what} has a negative power of {v}, a variable of the level set's polynomial \
                 P = {}: the claim has no value where {v} = 0, though lhs − rhs may cancel {v}, \
                 and is not decided by dividing by P; take a level set of variables it does not \
                 divide by",
                p()?
            ));
        }
        Ok(())
    }

    /// Divides `f` by `P` with its parameters (its leading coefficient a number, as
    /// [`LevelSet::check`] with no fixed value ensures): `f = Q·P`, recomputed, where the
    /// remainder is zero, so that `f` vanishes on the level set; else the remainder, `f`'s
    /// normal form modulo `P`, not zero, so that `f` is not a multiple of `P`. That is all a
    /// remainder proves: it shows `f` not zero somewhere on the complex level set only at the
    /// values of the parameters where `P` is square-free (shown for all values but a proper
    /// algebraic subset by [`LevelSet::check_for_every_value`], which leaves out `a = 0` of
    /// `x² = a`) and the remainder is not zero, and
    /// the real level set may be smaller still (`x² + y² = 0` is a point). A claim on a level
    /// set is decided so.
    pub fn reduce(&self, system: &System, f: &Expr) -> Result<LevelReduction, EngineError> {
        let p = self.polynomial()?;
        let dividing = self.division_order(system);
        if let Some(v) = negative_power(f, &dividing) {
            let v = vars_name(f, v);
            return Err(EngineError::Invalid(format!(
                "lhs − rhs = {} has a negative power of {v}: a claim on a level set is decided \
                 by dividing lhs − rhs by P = {p}, which takes polynomials; multiply both \
                 sides by a power of {v}",
                f.brief_excerpt()
            )));
        }
        let (proof, remainder) = proof_by_division(f, &p, &dividing, system, &[])?;
        match proof {
            Some(proof) => Ok(LevelReduction::Vanishes(proof)),
            None if !remainder.vanishes()? => Ok(LevelReduction::Remainder(remainder)),
            None => Err(EngineError::Invalid(format!(
                "the division of {f} by P = {p} left no remainder, but f − Q·P, recomputed, \
                 is not zero"
            ))),
        }
    }
}

/// What a level set is not taken beside, for a claim's `on` and a search's `--on` alike: the
/// one place these refusals are decided ([`BesideLevelSet::for_claim`],
/// [`BesideLevelSet::for_search`]) and worded ([`BesideLevelSet::what`],
/// [`BesideLevelSet::why`]; shown, `what: why`). A caller may name its own options in it.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum BesideLevelSet {
    /// A condition that sets a phase variable, or a parameter to a function of phase space:
    /// the phase variable as printed, its kind in words (`p_θ`, `a momentum`), and the
    /// parameter set to a function of it, if that is what the condition does.
    PhaseCondition {
        /// The phase variable, as printed.
        variable: String,
        /// Its kind in words.
        kind: &'static str,
        /// The parameter set to a function of phase space, as printed, if any.
        parameter: Option<String>,
    },
    /// A search's condition that fixes parameters alone: a search fixes its parameters itself.
    ParameterCondition,
    /// A search's parameters kept symbolic.
    Symbolic,
}

impl BesideLevelSet {
    /// What a claim on a level set does not take: a `condition` that sets a phase variable. A
    /// condition that fixes parameters alone is taken: it commutes with every bracket, and
    /// the claim is decided at those values ([`LevelSet::at_values`]). A system with
    /// denominators, radicals or negative powers is taken where the level set shares no
    /// variable with them ([`SharedVariable`], decided with the level set's polynomial).
    pub fn for_claim(condition: Option<&Condition>) -> Option<Self> {
        condition.and_then(Self::of_phase)
    }

    /// What a search on a level set does not take: any condition (one that fixes parameters
    /// alone is said by [`SearchOptions::fix`](super::SearchOptions::fix), which the search
    /// lifts back from), then parameters kept symbolic. A system with denominators, radicals
    /// or negative powers, and a Laurent space, are taken where the level set shares no
    /// variable with them ([`SharedVariable`]).
    pub fn for_search(options: &super::SearchOptions) -> Option<Self> {
        if let Some(c) = &options.condition {
            return Some(Self::of_phase(c).unwrap_or(BesideLevelSet::ParameterCondition));
        }
        (!options.symbolic.is_empty()).then_some(BesideLevelSet::Symbolic)
    }

    /// A condition that sets a phase variable, or a parameter to a function of phase space
    /// ([`Condition::phase_variable`]).
    fn of_phase(condition: &Condition) -> Option<Self> {
        let (set, variable, kind) = condition.phase_variable()?;
        let vars = condition.subs().first()?.1.vars();
        let parameter = (vars.variable(set).kind() == VarKind::Parameter)
            .then(|| vars.variable(set).unicode().to_string());
        Some(BesideLevelSet::PhaseCondition {
            variable,
            kind,
            parameter,
        })
    }

    /// What is not taken, in words (`a condition that sets p_θ, a momentum`).
    pub fn what(&self) -> String {
        match self {
            BesideLevelSet::PhaseCondition {
                variable,
                kind,
                parameter: None,
            } => format!("a condition that sets a phase variable ({variable}, {kind})"),
            BesideLevelSet::PhaseCondition {
                variable,
                kind,
                parameter: Some(parameter),
            } => format!(
                "a condition that sets the parameter {parameter} to a function of phase space \
                 (it holds {variable}, {kind})"
            ),
            BesideLevelSet::ParameterCondition => "a condition that fixes parameters".into(),
            BesideLevelSet::Symbolic => "parameters kept symbolic".into(),
        }
    }

    /// Why it is not taken, and what to do instead, naming the way parameters are given
    /// values `fix` (`--fix` on the command line).
    pub fn why(&self, fix: &str) -> String {
        match self {
            BesideLevelSet::PhaseCondition { .. } => format!(
                "its substitution does not commute with the bracket with H, so the level set \
                 would be taken on another flow; take the level set alone, or the condition \
                 alone; parameters alone may be fixed beside it, by a claim's condition or by \
                 a search's {fix}"
            ),
            BesideLevelSet::ParameterCondition => format!(
                "a search on a level set fixes its parameters itself: give their values with \
                 {fix}, at which the integrals are found and from which each is lifted back \
                 to the parameters where it can be"
            ),
            BesideLevelSet::Symbolic => format!(
                "the parameters are fixed (1 unless {fix} gives other values) and each \
                 integral found is lifted back to them where it can be, and proved there"
            ),
        }
    }
}

/// How a library's caller gives parameters values, as [`BesideLevelSet`]'s message names it.
const FIX: &str = "`fix` (on the command line, --fix)";

impl std::fmt::Display for BesideLevelSet {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.what(), self.why(FIX))
    }
}

/// A phase variable that a level set's polynomial `P` shares with a relation of the ring it
/// is taken in: a declared denominator, a radicand, a negative power in `H`, or a Laurent
/// space's negative powers of the coordinates. The one criterion of a level set on a system
/// with relations, for a claim's `on` and a search's `--on` alike ([`SharedVariable::of`]).
///
/// Let `V(P)` be the phase variables that `P` holds. Where no relation holds one of them (and
/// `P` holds no atom or radical itself, which [`LevelSet::check_form`] refuses first), the
/// ring is `A ⊗ k[V(P)]`, with `A` the ring of the other variables, atoms and radicals with
/// their relations, and `P ∈ k[V(P)]` (parameters as coefficients). So the quotient by `(P)`
/// is `A ⊗ (k[V(P)]/(P))`: its normal forms are the remainders on division by `P` with `A`'s
/// elements as coefficients, unique (`k[V(P)]/(P)` has the monomials that `LM(P)` does not
/// divide as a basis over `k`, so over `A` too), and `f` lies in `(P)` exactly where its
/// remainder is zero in `A ⊗ k[V(P)]`, which is free over `A`. `LM(P)` in the graded
/// lexicographic order of all phase variables is its leading monomial in `V(P)` alone, and
/// the division, ordered by the variables of `V(P)` ([`LevelSet::division_order`]), takes
/// the other variables to any power, negative too, as coefficients. `A` is reduced (a ring
/// of functions), so a square-free `P` gives a reduced quotient over a field of
/// characteristic zero, as without relations.
///
/// Where a relation does hold a variable of `P`, the normal forms modulo `P` alone are not
/// those modulo `P` and the relation: in the Laurent ring of `β/x²`, `x·p_y` and `p_y` span the
/// same ideal, so `p_y = 0` on `x p_y = 0` is true where `H` is defined, and the remainder
/// `p_y` would refute it. A claim's sides and the functions they name are held to the same
/// rule ([`LevelSet::check_defined_on`]).
///
/// Not taken, a finer rule: `P` with no factor of the inverted variable (`x − 1` beside
/// `β/x²`), where `x` is no zero divisor modulo `P`, so that `f ∈ (P)` exactly where
/// `x^k f ∈ (P)` among polynomials (`1/x − 1` as `1 − x`). A claim could be decided so, its
/// remainder then `x^k f`'s; a search cannot: the monomials `LM(P)` does not divide are a
/// basis modulo `P` only among polynomials in `V(P)` (on `x = 1`, `1/x` and `1` are both left
/// in, and `1/x − 1`, zero there, would be found as an integral).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SharedVariable {
    /// `P`, as printed.
    pub polynomial: String,
    /// The variable shared, as printed.
    pub variable: String,
    /// The relation that holds it.
    pub relation: SharedRelation,
}

/// What holds a variable of a level set's polynomial ([`SharedVariable`]), each part as
/// printed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SharedRelation {
    /// A declared denominator.
    Denominator(String),
    /// The radicand of a radical.
    Radicand {
        /// The radicand.
        radicand: String,
        /// The radical.
        radical: String,
    },
    /// A negative power of the variable in `H` (`1/x²`).
    NegativePowerOfH(String),
    /// The negative powers of a coordinate that a Laurent space admits (`--laurent`), which a
    /// search without it does not take.
    LaurentSpace,
}

impl SharedVariable {
    /// The first phase variable of `p` (in declaration order) that a relation of `system`
    /// holds: a declared denominator, a radicand, a negative power in `H`, and, where
    /// `laurent`, the negative powers of the coordinates that a Laurent space admits.
    pub fn of(system: &System, p: &Expr, laurent: bool) -> Option<Self> {
        let vars = system.vars();
        let space = system.space();
        let h = system.hamiltonian();
        // The relation, in words, and whether it is the Laurent space's.
        let relation = |v: Var| -> Option<SharedRelation> {
            let name = vars.variable(v).unicode();
            if let Some((_, d)) = space
                .denominator_atoms()
                .iter()
                .find(|(_, d)| d.contains(v))
            {
                return Some(SharedRelation::Denominator(d.to_string()));
            }
            if let Some((r, radicand)) = space.radicals().iter().find(|(_, d)| d.contains(v)) {
                return Some(SharedRelation::Radicand {
                    radicand: radicand.to_string(),
                    radical: vars.variable(*r).unicode().to_string(),
                });
            }
            if let Some((lowest, _)) = h.exponent_range(v).filter(|(lo, _)| *lo < 0) {
                let mut exponents = vec![0; vars.len()];
                exponents[v.index()] = lowest;
                let power = Expr::from_terms(vars, [(Rational::one().into(), exponents)])
                    .map_or_else(|_| format!("{name}^{lowest}"), |m| m.to_string());
                return Some(SharedRelation::NegativePowerOfH(power));
            }
            (laurent && vars.variable(v).kind() == VarKind::Coordinate)
                .then_some(SharedRelation::LaurentSpace)
        };
        let order = LevelSet::order(system);
        order
            .variables()
            .iter()
            .filter(|&&v| p.contains(v))
            .find_map(|&v| {
                relation(v).map(|relation| SharedVariable {
                    polynomial: p.to_string(),
                    variable: vars.variable(v).unicode().to_string(),
                    relation,
                })
            })
    }
}

impl std::fmt::Display for SharedVariable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (polynomial, variable) = (&self.polynomial, &self.variable);
        write!(
            f,
            "the level set's polynomial P = {polynomial} shares {variable} with "
        )?;
        match &self.relation {
            SharedRelation::Denominator(d) => write!(f, "the denominator {d}")?,
            SharedRelation::Radicand { radicand, radical } => {
                write!(f, "the radicand {radicand} of the radical {radical}")?
            }
            SharedRelation::NegativePowerOfH(power) => {
                write!(f, "the negative power {power} of H")?
            }
            SharedRelation::LaurentSpace => write!(
                f,
                "the negative powers of {variable} that a Laurent space admits"
            )?,
        }
        write!(
            f,
            ": the remainders on division by P are the normal forms modulo P and the system's \
             relations only where no declared denominator, radicand or negative power holds a \
             variable of P; {}",
            match self.relation {
                SharedRelation::LaurentSpace =>
                    "take a level set of variables that no negative power involves (a \
                     Laurent space admits them of every coordinate), or search without \
                     --laurent",
                _ => "take a level set of variables that none of them holds",
            }
        )
    }
}

/// What dividing a function by a level set's polynomial `P` shows ([`LevelSet::reduce`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum LevelReduction {
    /// `f = Q·P`, recomputed: `f` vanishes on the level set.
    Vanishes(LevelProof),
    /// `f`'s remainder on division by `P`, its normal form modulo `P`: not zero.
    Remainder(Expr),
}

/// The division of `f` by `p` in `order`: the proof that `f` lies in `(p)`, the quotient `Q`,
/// where the remainder is zero and `f − p·Q`, recomputed, is zero (else `None`), and the
/// remainder. `f` and `p` are at the parameters' `values` (none where they are symbolic), where
/// an expression is zero with the system's atoms and radicands at them too
/// ([`vanishes_at_values`]).
fn proof_by_division(
    f: &Expr,
    p: &Expr,
    order: &DivisionOrder,
    system: &System,
    values: &[(Var, Rational)],
) -> Result<(Option<LevelProof>, Expr), EngineError> {
    let zero = |e: &Expr| vanishes_at_values(system.space(), values, e);
    let division = p_divide(f, p, order)?;
    if !zero(&division.remainder)? {
        return Ok((None, division.remainder));
    }
    let residual = f.checked_sub(&p.checked_mul(&division.quotient)?)?;
    let proof = zero(&residual)?.then(|| LevelProof {
        quotient: division.quotient,
        divisor: p.clone(),
    });
    Ok((proof, division.remainder))
}

/// The parameters that `p` holds, in the order of their declaration, at their value in
/// `given` or else 1: the values a search on its level set takes them at.
pub(super) fn level_parameter_values(p: &Expr, given: &[(Var, Rational)]) -> Vec<(Var, Rational)> {
    let vars = p.vars();
    vars.vars()
        .filter(|&v| vars.variable(v).kind() == VarKind::Parameter && p.contains(v))
        .map(|v| match given.iter().find(|(g, _)| *g == v) {
            Some((_, x)) => (v, x.clone()),
            None => (v, Rational::one()),
        })
        .collect()
}

/// `order`'s variables and then the parameters that `p` holds: the variables of the lines
/// along which [`LevelSet::check_for_every_value`] shows `p` square-free with its parameters.
fn with_parameters(p: &Expr, order: &DivisionOrder) -> DivisionOrder {
    let parameters = level_parameter_values(p, &[]).into_iter().map(|(v, _)| v);
    let variables: Vec<Var> = order
        .variables()
        .iter()
        .copied()
        .chain(parameters)
        .collect();
    DivisionOrder::graded_lex(&variables)
}

/// Whether `flow`, `{P, H}` with the parameters free, is `P` times a polynomial (`p`'s
/// leading coefficient a number): the flow of `H` keeps the level set for every value. A
/// bracket with a negative power, which division does not take, is not shown a multiple.
fn flow_is_multiple(flow: &Expr, p: &Expr, order: &DivisionOrder) -> Result<bool, EngineError> {
    if negative_power(flow, order).is_some() {
        return Ok(false);
    }
    Ok(p_divide(flow, p, order)?.remainder.vanishes()?)
}

/// What [`LevelSet::check_square_free_and_kept`] checks a level set for, which says where the
/// flow of `H` must keep it and where `P` must be square-free.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum CheckedFor {
    /// An ordinary search, at the fixed values: `H` and `P` there.
    Search,
    /// A search for the exceptional values of the parameter it holds: every parameter free (at
    /// the fixed values only where `P`'s leading coefficient needs them), and a level set kept
    /// at some values of that parameter alone refused saying so.
    ExceptionalValues(Var),
    /// A claim, for every value of the parameters: `P` square-free with them too.
    Claim,
}

/// Whether `p` or `h` holds a parameter that `fixed` gives a value.
fn fixed_anything(p: &Expr, h: &Expr, fixed: &[(Var, Rational)]) -> bool {
    fixed.iter().any(|(v, _)| p.contains(*v) || h.contains(*v))
}

/// How the refusal of a level set that the flow of `H` leaves begins (`{P, H}` not in `(P)`).
const FLOW_LEAVES: &str = "the flow of H leaves the level set";

/// How many lines through phase space [`has_no_repeated_factor`] tries.
const LINES_TRIED: usize = 12;

/// Whether `p`, a real polynomial in the variables `order` names alone, is shown to have no
/// repeated factor: its restriction `u(t) = p(a + t b)` to a line has the degree of `p` and no
/// repeated root, both seen modulo the prime [`PRIME`](crate::modular::PRIME): `u mod p` of `p`'s degree
/// and `gcd(u, u′)` a constant in `F_p[t]` (Euclid's algorithm). That is a proof: a factor
/// `f²` of `p` would make `f(a + t b)²` a factor of `u`, of degree at least 2 since the
/// top-degree part of `f` does not vanish at `b` where `p`'s does not, and modulo the prime
/// too, where `u`'s leading coefficient, so `f`'s, is not zero (Gauss's lemma). Working
/// modulo a prime keeps the coefficients one word each, where Euclid over Q made them grow
/// (a `P` of degree 80 took minutes). A square-free `p` has such a line almost everywhere;
/// `false` when none of [`LINES_TRIED`] fixed lines shows it. Over Q as over C, since
/// `gcd(u, u′)` does not depend on the field.
fn has_no_repeated_factor(p: &Expr, order: &DivisionOrder) -> bool {
    let degree = degree_in(p, order);
    (0..LINES_TRIED).any(|k| {
        restricted_to_line(p, order, &line(k, order)).is_some_and(|u| {
            u.len() as i64 - 1 == degree && is_square_free_mod(&residues(&u), PRIME)
        })
    })
}

/// The total degree of `p` in the variables of `order`.
fn degree_in(p: &Expr, order: &DivisionOrder) -> i64 {
    p.terms()
        .map(|t| degree_of_exponents(&t.exponents(), order))
        .max()
        .unwrap_or(0)
}

/// The total degree of the monomial `exponents` in the variables of `order`.
fn degree_of_exponents(exponents: &[i64], order: &DivisionOrder) -> i64 {
    order.variables().iter().map(|v| exponents[v.index()]).sum()
}

/// The `k`-th line through phase space that [`has_no_repeated_factor`] and
/// [`OnLevel::top_shares_no_factor`] try: a point and a direction with small integer
/// coordinates, one pair for each variable of `order`, different for each line. The
/// direction's coordinates `(i + 1)(k + 1) + i²` grow with the variable's place `i`, so that
/// they differ for any number of variables and no difference of squares such as `M3² − γ1²`
/// vanishes along every line.
fn line(k: usize, order: &DivisionOrder) -> Vec<(i64, i64)> {
    let k = k as i64;
    (0..order.variables().len() as i64)
        .map(|i| ((3 * i + 5 * k + 1) % 7 - 3, (i + 1) * (k + 1) + i * i))
        .collect()
}

/// The part of top degree of `p` in the variables of `order` (its leading form).
fn top_degree_part(p: &Expr, order: &DivisionOrder) -> Result<Expr, EngineError> {
    let degree = degree_in(p, order);
    let top = p
        .terms()
        .filter(|t| degree_of_exponents(&t.exponents(), order) == degree)
        .map(|t| (t.coeff().clone(), t.exponents()));
    Ok(Expr::from_terms(p.vars(), top)?)
}

/// `p(a + t b)` modulo the prime [`PRIME`](crate::modular::PRIME) as its coefficients in `t`, lowest first, for the
/// point and direction `(a_i, b_i)` of `line` over the variables of `order` (the real parts of
/// `p`'s coefficients: `p` is real); `None` where a coefficient's denominator is a multiple of
/// the prime. Each variable's powers of `a + t b` are formed once.
fn restricted_to_line(p: &Expr, order: &DivisionOrder, line: &[(i64, i64)]) -> Option<Vec<Fp>> {
    let variables = order.variables();
    let mut powers: Vec<Vec<Vec<Fp>>> = line
        .iter()
        .map(|&(a, b)| vec![vec![Fp::one()], vec![Fp::from_i64(a), Fp::from_i64(b)]])
        .collect();
    let mut sum: Vec<Fp> = Vec::new();
    for t in p.terms() {
        let e = t.exponents();
        let mut product = vec![Fp::from_rational(&t.coeff().re)?];
        for (k, v) in variables.iter().enumerate() {
            let n = usize::try_from(e[v.index()]).ok()?;
            while powers[k].len() <= n {
                let next = univariate::mul(&powers[k][powers[k].len() - 1], &powers[k][1]);
                powers[k].push(next);
            }
            if n > 0 {
                product = univariate::mul(&product, &powers[k][n]);
            }
        }
        sum = univariate::add(&sum, &product);
    }
    Some(univariate::trimmed(sum))
}

/// The residues of `u`'s coefficients, as the crate's polynomials over `F_p` take them
/// ([`gcd_mod`], [`is_square_free_mod`]).
fn residues(u: &[Fp]) -> Vec<u64> {
    u.iter().map(|c| c.value()).collect()
}

/// Polynomials in one variable over `F_p` ([`Fp`], `p =` [`PRIME`], far above any degree a
/// level set has, so that the derivative of `tⁿ` is not 0 modulo it), as coefficient vectors
/// (lowest first, no trailing zero): a polynomial restricted to a line, whose gcds the
/// square-free and coprime tests of a level set take ([`gcd_mod`]).
mod univariate {
    use crate::modular::{Field, Fp};

    /// `u` without trailing zeros.
    pub(super) fn trimmed(mut u: Vec<Fp>) -> Vec<Fp> {
        while u.last().is_some_and(Field::is_zero) {
            u.pop();
        }
        u
    }

    pub(super) fn add(u: &[Fp], w: &[Fp]) -> Vec<Fp> {
        let zero = Fp::zero();
        (0..u.len().max(w.len()))
            .map(|i| u.get(i).unwrap_or(&zero).add(w.get(i).unwrap_or(&zero)))
            .collect()
    }

    pub(super) fn mul(u: &[Fp], w: &[Fp]) -> Vec<Fp> {
        let mut product = vec![Fp::zero(); (u.len() + w.len()).saturating_sub(1)];
        for (i, a) in u.iter().enumerate() {
            for (j, b) in w.iter().enumerate() {
                product[i + j] = product[i + j].add(&a.mul(b));
            }
        }
        product
    }
}

/// Whether a variable of this kind keeps a polynomial from defining a level set here.
fn is_excluded(kind: VarKind) -> bool {
    matches!(
        kind,
        VarKind::Angle | VarKind::Denominator | VarKind::Radical
    )
}

/// `v` is a parameter, or a declared denominator or radical whose polynomial holds
/// parameters alone (`1/(κ + 1)`, `√κ`): a constant wherever the parameters have values.
fn is_constant_of_parameters(system: &System, v: Var) -> bool {
    let vars = system.vars();
    let space = system.space();
    let of_parameters = |d: &Expr| {
        vars.vars()
            .all(|w| !d.contains(w) || vars.variable(w).kind() == VarKind::Parameter)
    };
    match vars.variable(v).kind() {
        VarKind::Parameter => true,
        VarKind::Denominator | VarKind::Radical => space
            .denominator_atoms()
            .iter()
            .chain(space.radicals())
            .any(|(atom, d)| *atom == v && of_parameters(d)),
        _ => false,
    }
}

/// `f` divided by `p` in `order`, a refusal of `p` said in words. A dividend with a negative
/// power of a phase variable is refused: its remainder would be a Laurent polynomial's, and
/// a nonzero one would not show that `f` is no multiple of `p` (`x + y²/x − a/x` is
/// `(x² + y² − a)/x`).
pub(super) fn p_divide(
    f: &Expr,
    p: &Expr,
    order: &DivisionOrder,
) -> Result<Division<trigpoly::GaussianRational>, EngineError> {
    if let Some(v) = negative_power(f, order) {
        return Err(EngineError::Invalid(format!(
            "{} has a negative power of {v}, a variable of the level set's polynomial P = {p}: \
             whether it is a multiple of P is decided by dividing polynomials in P's \
             variables, and it has no value where {v} = 0; take a level set of variables that \
             it does not divide by",
            f.brief_excerpt(),
            v = vars_name(f, v)
        )));
    }
    f.divide_by(p, order).map_err(|e| refusal(p, e))
}

/// The name of `v`, a variable of `f`, as printed.
fn vars_name(f: &Expr, v: Var) -> String {
    f.vars().variable(v).unicode().to_string()
}

/// The first variable of `order` (a phase variable) that `f` holds to a negative power.
fn negative_power(f: &Expr, order: &DivisionOrder) -> Option<Var> {
    (order.variables().iter().copied()).find(|&v| f.exponent_range(v).is_some_and(|(lo, _)| lo < 0))
}

/// A divisor's refusal as the search says it.
fn refusal(p: &Expr, e: DivisionRefusal) -> EngineError {
    let vars = p.vars();
    match e {
        DivisionRefusal::Algebra(a) => a.into(),
        DivisionRefusal::LeadingCoefficient { monomial } => {
            let lead = Expr::from_terms(vars, [(Rational::one().into(), monomial)])
                .map(|m| m.to_string())
                .unwrap_or_default();
            EngineError::Invalid(format!(
                "the level set's polynomial P = {p} has at its leading monomial {lead} a \
                 coefficient that holds a parameter: give the parameter a value (`--fix` on \
                 the command line), so that P is divided by a number there"
            ))
        }
        DivisionRefusal::Zero => EngineError::Invalid(
            "the level set's polynomial P is zero: its level is everything".into(),
        ),
        DivisionRefusal::NegativePower(_) => EngineError::Invalid(format!(
            "the level set's polynomial P = {p} has a negative power: it must be a polynomial"
        )),
    }
}

/// The level set as the search takes it: `P` at the fixed parameters, for the equations and
/// the proofs there, and symbolic where its leading coefficient is a number and the flow of `H`
/// keeps it for every value of them, for the proofs of the integrals lifted; the order, and
/// `LM(P)` at the fixed values.
pub(super) struct OnLevel {
    /// `P` at the fixed values, its declared denominators of parameters alone at theirs too
    /// (`p_θ − 1/2` for `p_θ − 1/(κ + 1)` at `κ = 1`), as the space's monomials hold them.
    pub(super) fixed: Expr,
    /// `P` with its parameters, where its leading coefficient is a number and `{P, H}` a
    /// multiple of it with them: elsewhere an integral holds on the level set at the fixed
    /// values alone (`p_x` on `p_y = 0` of `p_x²/2 + p_y²/2 + xy p_y + ay` at `a = 0`, where
    /// `{p_x, H} = −y p_y` for every `a`, but the flow leaves `p_y = 0` at `a ≠ 0`).
    pub(super) symbolic: Option<Expr>,
    /// Whether the flow keeps the level set for every value of the parameters: where
    /// [`OnLevel::symbolic`] is given, or where `{P, H}` is zero (`H = E`, whose leading
    /// coefficient `1/(2M)` is no number).
    pub(super) kept_for_every_value: bool,
    pub(super) order: DivisionOrder,
    /// The order functions are divided in ([`LevelSet::division_order`]).
    pub(super) dividing: DivisionOrder,
    /// The exponents of `LM(P)` at the fixed values.
    pub(super) lead: Vec<i64>,
}

impl OnLevel {
    /// The level set at the fixed `parameters` (checked before by [`LevelSet::check`]).
    pub(super) fn new(
        level: &LevelSet,
        system: &System,
        parameters: &[(Var, Rational)],
    ) -> Result<Self, EngineError> {
        let order = LevelSet::order(system);
        let dividing = level.division_order(system);
        let p = level.polynomial()?;
        let flow = system.bracket(&p, system.hamiltonian())?;
        let symbolic = match p.leading_term(&order) {
            Ok(_) if flow_is_multiple(&flow, &p, &dividing)? => Some(p.clone()),
            _ => None,
        };
        let kept_for_every_value = symbolic.is_some() || flow.vanishes()?;
        let fixed = fix_parameters(&p, parameters)?;
        let fixed = parameter_atoms_at_values(system.space(), parameters, &fixed)?;
        let (_, lead) = fixed.leading_term(&order).map_err(|e| refusal(&fixed, e))?;
        Ok(OnLevel {
            fixed,
            symbolic,
            kept_for_every_value,
            order,
            dividing,
            lead,
        })
    }

    /// Whether `LM(P)` divides the monomial `exponents`: a monomial the space leaves out.
    pub(super) fn leaves_out(&self, exponents: &[i64]) -> bool {
        self.dividing.divides(&self.lead, exponents)
    }

    /// The first phase variable that `f` holds to a negative power, which division by `P`
    /// does not take ([`p_divide`] refuses it), with its name.
    pub(super) fn negative_power(&self, f: &Expr) -> Option<String> {
        negative_power(f, &self.dividing).map(|v| vars_name(f, v))
    }

    /// The remainder of `f` (at the fixed values) on division by `P`: its normal form.
    pub(super) fn remainder(&self, f: &Expr) -> Result<Expr, EngineError> {
        Ok(p_divide(f, &self.fixed, &self.dividing)?.remainder)
    }

    /// Whether the part of top degree of `f` (a function at the fixed values) is shown to share
    /// no factor with that of `P`: on one of the lines `a + t b` tried, where `P`'s top part
    /// does not vanish at `b`, the restrictions of the two top parts have no common root
    /// (`gcd` a constant modulo [`PRIME`](crate::modular::PRIME), `P`'s keeping its degree there, so over
    /// Q and over C). A common factor `F` would not vanish at `b` either and would divide both
    /// restrictions with degree `deg F ≥ 1`, modulo the prime too. A product of such
    /// functions then has a top part that `P`'s does not divide, so its normal form modulo `P`
    /// keeps its total degree. `false` for a function that is not real or holds a variable
    /// outside the division's order (an angle).
    pub(super) fn top_shares_no_factor(&self, f: &Expr) -> Result<bool, EngineError> {
        let phase = self.order.variables();
        let vars = f.vars();
        if !f.is_real() || vars.vars().any(|v| f.contains(v) && !phase.contains(&v)) {
            return Ok(false);
        }
        let (p_top, f_top) = (
            top_degree_part(&self.fixed, &self.order)?,
            top_degree_part(f, &self.order)?,
        );
        let degree = degree_in(&p_top, &self.order);
        Ok((0..LINES_TRIED).any(|k| {
            let line = line(k, &self.order);
            let u = restricted_to_line(&p_top, &self.order, &line);
            let w = restricted_to_line(&f_top, &self.order, &line);
            u.zip(w).is_some_and(|(u, w)| {
                u.len() as i64 - 1 == degree
                    && gcd_mod(&residues(&u), &residues(&w), PRIME).len() == 1
            })
        }))
    }

    /// The proof that `flow` lies in `(p)` (`p` is `P` at the parameters' `values`, the fixed
    /// ones, or with its parameters, no values, as `flow` is): the quotient `Q`, where the
    /// remainder is zero and `flow − p·Q`, recomputed, is zero; `None` where it is not.
    pub(super) fn prove(
        &self,
        system: &System,
        flow: &Expr,
        p: &Expr,
        values: &[(Var, Rational)],
    ) -> Result<Option<LevelProof>, EngineError> {
        Ok(proof_by_division(flow, p, &self.dividing, system, values)?.0)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use trigpoly::{Expr, Rational, VarKind, Vars};

    use super::{has_no_repeated_factor, LevelSet};
    use crate::search::{search, SearchOptions, SearchResult, SearchSpace};
    use crate::{EngineError, PhaseSpace, System};

    /// The Goryachev–Chaplygin top on e(3)*: `H = (M1² + M2² + 4M3²)/2 − c γ1`.
    fn gc_top() -> System {
        on_e3("GC top", "(M1^2 + M2^2 + 4*M3^2)/2 - c*gamma1", &["c"])
    }

    /// A system on e(3)*, `M1, M2, M3, gamma1, gamma2, gamma3` with the Lie–Poisson bracket,
    /// with `parameters` and the Hamiltonian `h`.
    pub(in crate::search) fn on_e3(name: &str, h: &str, parameters: &[&str]) -> System {
        let mut builder = Vars::builder()
            .poisson("M1")
            .poisson("M2")
            .poisson("M3")
            .poisson("gamma1")
            .poisson("gamma2")
            .poisson("gamma3");
        for p in parameters {
            builder = builder.parameter(p);
        }
        let vars = builder.build().unwrap();
        let e = |t: &str| Expr::parse(&vars, t).unwrap();
        let space = PhaseSpace::new(&vars, &[])
            .unwrap()
            .with_brackets(&[
                ("M1", "M2", e("M3")),
                ("M2", "M3", e("M1")),
                ("M3", "M1", e("M2")),
                ("M1", "gamma2", e("gamma3")),
                ("M1", "gamma3", e("-gamma2")),
                ("M2", "gamma3", e("gamma1")),
                ("M2", "gamma1", e("-gamma3")),
                ("M3", "gamma1", e("gamma2")),
                ("M3", "gamma2", e("-gamma1")),
            ])
            .unwrap();
        System::new(name, space, e(h)).unwrap()
    }

    /// A system on the plane's canonical coordinates `x`, `y`, `p_x`, `p_y`, with `parameters`
    /// and the Hamiltonian `h`.
    pub(in crate::search) fn on_the_plane(name: &str, h: &str, parameters: &[&str]) -> System {
        let mut builder = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y");
        for p in parameters {
            builder = builder.parameter(p);
        }
        let vars = builder.build().unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        System::new(name, space, Expr::parse(&vars, h).unwrap()).unwrap()
    }

    fn level(system: &System, expr: &str, value: &str) -> LevelSet {
        let e = |t: &str| Expr::parse(system.vars(), t).unwrap();
        LevelSet::new(&format!("{expr} = {value}"), e(expr), e(value))
    }

    fn on(
        system: &System,
        space: SearchSpace,
        level: LevelSet,
    ) -> Result<SearchResult, EngineError> {
        search(system, &SearchOptions::new(space).on(level))
    }

    /// Each integral found on the level set `P = 0` satisfies `{K, H} = Q·P` exactly,
    /// recomputed here from the bracket and the product, for the integral as printed (with its
    /// parameters) and its quotient.
    /// One not lifted is proved at the fixed values, with `P` there.
    fn assert_proved_on(system: &System, r: &SearchResult, p: &Expr) {
        for f in &r.basis {
            let proof = f.on_level.as_ref().expect("a proof on the level set");
            let (flow, p) = match f.symbolic {
                Some(_) => (
                    system.bracket(f.expr(), system.hamiltonian()).unwrap(),
                    p.clone(),
                ),
                None => {
                    let flow = system.bracket(f.expr(), system.hamiltonian()).unwrap();
                    let at = |e: &Expr| crate::search::fix_parameters(e, &r.parameters).unwrap();
                    (at(&flow), at(p))
                }
            };
            let product = p.checked_mul(&proof.quotient).unwrap();
            assert_eq!(
                flow,
                product,
                "{{{}, H}} = ({}) P",
                f.expr(),
                proof.quotient
            );
        }
    }

    /// On the area integral's level set `M·γ = 0` the search finds the Goryachev–Chaplygin
    /// integral `K = M3(M1² + M2²) + c M1 γ3`, lifted to `c`, with `{K, H} = −c M2 (M·γ)`;
    /// without the level set it finds nothing cubic.
    #[test]
    fn the_goryachev_chaplygin_integral_is_found_on_the_area_level_set() {
        let top = gc_top();
        let e = |t: &str| Expr::parse(top.vars(), t).unwrap();
        let space = SearchSpace::default().poisson_degree(3);
        let area = level(&top, "M1*gamma1 + M2*gamma2 + M3*gamma3", "0");
        let r = on(&top, space, area).unwrap();
        assert!(r
            .basis
            .iter()
            .all(|f| f.proved_fixed && f.symbolic.is_some()));
        assert_proved_on(&top, &r, &e("M1*gamma1 + M2*gamma2 + M3*gamma3"));
        let k = e("M3*(M1^2 + M2^2) + c*M1*gamma3");
        let cubic: Vec<&Expr> = (r.basis.iter())
            .filter(|f| f.poisson_degree == 3)
            .map(|f| f.expr())
            .collect();
        assert_eq!(cubic, [&k]);
        let quotient = &r.basis.iter().find(|f| f.expr() == &k).unwrap().on_level;
        assert_eq!(quotient.as_ref().unwrap().quotient, e("-c*M2"));
        // 1, |γ|², H and K; M·γ itself is 0 there, and LM(P) = M1 γ1 left 7 unknowns out.
        assert_eq!(r.basis.len(), 4);
        assert_eq!(r.on.as_ref().unwrap().left_out, 7);
        assert_eq!(r.on.as_ref().unwrap().leading_monomial, e("M1*gamma1"));
        // The division keeps the Poisson degree: every normal form lies in the space.
        assert!(r.on.as_ref().unwrap().normal_form_outside.is_none());
        let everywhere = search(&top, &SearchOptions::new(space)).unwrap();
        assert!(everywhere.basis.iter().all(|f| f.poisson_degree < 3));
    }

    /// A false candidate is not returned: on the level set `|γ|² = 1`, which the flow keeps
    /// too (a Casimir), `K` is no integral, and the search finds none of degree 3; every
    /// integral it returns satisfies its identity.
    #[test]
    fn no_integral_is_found_where_there_is_none() {
        let top = gc_top();
        let e = |t: &str| Expr::parse(top.vars(), t).unwrap();
        let space = SearchSpace::default().poisson_degree(3);
        let r = on(
            &top,
            space,
            level(&top, "gamma1^2 + gamma2^2 + gamma3^2", "1"),
        )
        .unwrap();
        assert_proved_on(&top, &r, &e("gamma1^2 + gamma2^2 + gamma3^2 - 1"));
        assert!(
            r.basis.iter().all(|f| f.poisson_degree < 3),
            "{:?}",
            r.basis
        );
        // K's bracket is not a multiple of |γ|² − 1.
        let k = e("M3*(M1^2 + M2^2) + c*M1*gamma3");
        let flow = top.bracket(&k, top.hamiltonian()).unwrap();
        let order = LevelSet::order(&top);
        let division = flow
            .divide_by(&e("gamma1^2 + gamma2^2 + gamma3^2 - 1"), &order)
            .unwrap();
        assert!(!division.remainder.is_zero());
    }

    /// On canonical coordinates: the 1:2 oscillator on its energy level `H = E` (a parameter,
    /// at its fixed value), where the cubic integral `Re(a² b̄)` is found again, in normal
    /// form modulo `H − E`, each integral proved by its quotient.
    #[test]
    fn integrals_are_found_on_an_energy_level() {
        let h = "(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2";
        let oscillator = on_the_plane("1:2 oscillator", h, &["E"]);
        let e = |t: &str| Expr::parse(oscillator.vars(), t).unwrap();
        let energy = level(&oscillator, h, "E");
        let space = SearchSpace::default().momenta_degree(3).positions_degree(3);
        let r = on(&oscillator, space, energy.clone()).unwrap();
        assert_proved_on(&oscillator, &r, &energy.polynomial().unwrap());
        // LM(H − E) = x²: no integral has it, and the found ones are proved.
        let lead = &r.on.as_ref().unwrap().leading_monomial;
        assert_eq!(lead, &e("x^2"));
        assert!(r.basis.iter().all(|f| f.proved_fixed));
        // The momenta and positions degrees, bounded apart, are not kept by the division:
        // x² replaced through H = E raises the momenta degree by 2, and a function of the
        // space (x² p_x³, say) has a normal form of momenta degree 5, which is said.
        let outside = r.on.as_ref().unwrap().normal_form_outside.as_ref();
        let outside = outside.expect("a normal form outside the space");
        let momenta = |f: &Expr| f.total_degree(&[VarKind::Momentum]).unwrap_or(0);
        let positions = |f: &Expr| f.total_degree(&[VarKind::Coordinate]).unwrap_or(0);
        assert!(momenta(&outside.function) <= 3 && positions(&outside.function) <= 3);
        assert!(
            momenta(&outside.normal_form) > 3 || positions(&outside.normal_form) > 3,
            "{} → {}",
            outside.function,
            outside.normal_form
        );
        let at_one = [(oscillator.vars().lookup("E").unwrap(), Rational::one())];
        let divided = outside
            .function
            .divide_by(
                &crate::search::fix_parameters(&energy.polynomial().unwrap(), &at_one).unwrap(),
                &LevelSet::order(&oscillator),
            )
            .unwrap();
        assert_eq!(divided.remainder, outside.normal_form);
        // Re(a² b̄) for a = p_x + ix, b = p_y + 2iy: (p_x² − x²) p_y + 4 x p_x y, whose normal
        // form modulo H − E replaces x² by 2E − p_x² − p_y² − 4y².
        let c = e("(p_x^2 - x^2)*p_y + 4*x*p_x*y");
        let order = LevelSet::order(&oscillator);
        let p = energy.polynomial().unwrap();
        let normal = c.divide_by(&p, &order).unwrap().remainder;
        let fixed = crate::search::fix_parameters(
            &normal,
            &[(oscillator.vars().lookup("E").unwrap(), Rational::one())],
        )
        .unwrap();
        let spans = r
            .basis
            .iter()
            .any(|f| f.fixed == fixed || f.fixed == -&fixed);
        assert!(
            spans,
            "{fixed} among {:?}",
            r.basis
                .iter()
                .map(|f| f.fixed.to_string())
                .collect::<Vec<_>>()
        );
    }

    /// With `new_only` on the area level set every integral is compared in normal form modulo
    /// `P`: on a top with no named functions but `H`, `Γ` and `K` are new, and the products up
    /// to degree 5 (`Γ²`, `Γ H`, `H²`, `Γ K`, `H K`) are not; `Γ K` and `H K` have monomials
    /// that `LM(P) = M1 γ1` divides (left out of the space), so only their normal forms lie in
    /// it. Given `K` as known, only `Γ` is new; `M·γ`, zero there, is no known integral; `M1`, whose bracket is no multiple
    /// of `P`, is refused.
    #[test]
    fn new_integrals_on_a_level_set_are_told_in_normal_form_modulo_its_polynomial() {
        let top = gc_top();
        let e = |t: &str| Expr::parse(top.vars(), t).unwrap();
        let area = "M1*gamma1 + M2*gamma2 + M3*gamma3";
        let k = e("M3*(M1^2 + M2^2) + c*M1*gamma3");
        let options = || {
            SearchOptions::new(SearchSpace::default().poisson_degree(5))
                .on(level(&top, area, "0"))
                .new_only()
        };
        let r = search(&top, &options()).unwrap();
        let new = r.new.as_ref().expect("new integrals");
        // 1, Γ, H, K, Γ², Γ H, H², Γ K, H K.
        assert_eq!(r.basis.len(), 9);
        let degrees: Vec<i64> = (new.new.iter())
            .map(|&i| r.basis[i].poisson_degree)
            .collect();
        assert_eq!(degrees, [2, 3], "{:?}", new.new);
        assert_eq!(r.basis[new.new[1]].expr(), &k);
        assert_eq!(new.generated, 7);
        assert_eq!(new.known, ["H"]);
        // Γ K is no normal form, and its remainder is one of the space.
        let gamma = e("gamma1^2 + gamma2^2 + gamma3^2");
        let order = LevelSet::order(&top);
        let product = gamma.checked_mul(&k).unwrap();
        let remainder = product.divide_by(&e(area), &order).unwrap().remainder;
        assert_ne!(remainder, product);

        // K known (its bracket −c M2 (M·γ) is a multiple of P), and M·γ, which is 0 there.
        let mut with_known = options();
        with_known.known = vec![("K".into(), k.clone()), ("A".into(), e(area))];
        let r = search(&top, &with_known).unwrap();
        let new = r.new.as_ref().unwrap();
        assert_eq!(new.known, ["H", "K"]);
        assert_eq!(new.new.len(), 1);
        assert_eq!(r.basis[new.new[0]].poisson_degree, 2);

        let mut not_integral = options();
        not_integral.known = vec![("M1".into(), e("M1"))];
        match search(&top, &not_integral) {
            Err(EngineError::RefusedKnown { index, reason, .. }) => {
                assert_eq!(index, 0);
                assert!(
                    reason.contains("is not an integral on the level set")
                        && reason.contains("not a multiple of P = M1 γ1 + M2 γ2 + M3 γ3"),
                    "{reason}"
                );
            }
            other => panic!("{other:?}"),
        }
    }

    /// On canonical coordinates, the 1:2 oscillator on `H = E` (at `E = 1`) with its first
    /// oscillator's energy `H_x = (p_x² + x²)/2` known, given as it is written: `x²` is left
    /// out of the space (`LM(H − E) = x²`), so `H_x` is located by its normal form
    /// `E − (p_y² + 4y²)/2`; the cubic integrals `Re(a² b̄)` and `Im(a² b̄)` are new and `H_x²`
    /// is not.
    #[test]
    fn new_integrals_on_an_energy_level_take_the_known_ones_modulo_it() {
        let h = "(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2";
        let oscillator = on_the_plane("1:2 oscillator", h, &["E"]);
        let e = |t: &str| Expr::parse(oscillator.vars(), t).unwrap();
        let mut options =
            SearchOptions::new(SearchSpace::default().momenta_degree(4).positions_degree(4))
                .on(level(&oscillator, h, "E"))
                .new_only();
        options.known = vec![("Hx".into(), e("(p_x^2 + x^2)/2"))];
        let r = search(&oscillator, &options).unwrap();
        let new = r.new.as_ref().expect("new integrals");
        assert_eq!(new.known, ["Hx"]);
        // 1, H_x, the two cubics and H_x².
        assert_eq!(r.basis.len(), 5);
        let total = |f: &Expr| {
            f.total_degree(&[VarKind::Coordinate, VarKind::Momentum])
                .unwrap()
        };
        let degrees: Vec<i64> = (new.new.iter())
            .map(|&i| total(&r.basis[i].fixed))
            .collect();
        assert_eq!(degrees, [3, 3]);
        assert_eq!(new.generated, 3);
        // `P`'s leading form, (p_x² + p_y² + x² + 4y²)/2, shares no factor with an integral's.
        assert!(!new.past_degree_undecided);
    }

    /// For the free particle on `p_x p_y = 1` the leading form of `P` factors, and `p_x`, `p_y`
    /// are integrals: `p_x · p_y` falls from degree 2 to the constant 1, so products past the
    /// space's degree might fall back into it, and the result says so; on the
    /// Goryachev–Chaplygin top's area level set, whose leading form `M·γ` shares no factor
    /// with `H`'s, `Γ`'s or `K`'s, it does not.
    #[test]
    fn a_level_set_whose_leading_form_shares_a_factor_is_said_undecided() {
        let free = on_the_plane("free particle", "(p_x^2 + p_y^2)/2", &[]);
        let options =
            SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(1))
                .on(level(&free, "p_x*p_y", "1"))
                .new_only();
        let r = search(&free, &options).unwrap();
        assert!(r.new.as_ref().unwrap().past_degree_undecided);

        let top = gc_top();
        let options = SearchOptions::new(SearchSpace::default().poisson_degree(4))
            .on(level(&top, "M1*gamma1 + M2*gamma2 + M3*gamma3", "0"))
            .new_only();
        let r = search(&top, &options).unwrap();
        assert!(!r.new.as_ref().unwrap().past_degree_undecided);
    }

    /// What the search cannot take on a level set is refused with what is wrong: a level set
    /// the flow leaves (`M1`, `{M1, H} = −3 M2 M3`), an angle, a negative power, a constant, a
    /// value of phase space, a polynomial that is not real, a square, a parameter in the
    /// leading coefficient, and a condition besides.
    /// The square-free test is a proof where it says yes, and says no of a repeated factor:
    /// `Γ⁴ − 1 = (Γ − 1)(Γ + 1)(Γ² + 1)` and `M1² − γ1²` are shown square-free, `M1² γ1` and
    /// `(M·γ)² (Γ − 1)` are not.
    #[test]
    fn a_level_sets_polynomial_is_shown_square_free_or_not() {
        let top = gc_top();
        let order = LevelSet::order(&top);
        let p = |s: &str| Expr::parse(top.vars(), s).unwrap();
        let gamma = "(gamma1^2 + gamma2^2 + gamma3^2)";
        let area = "(M1*gamma1 + M2*gamma2 + M3*gamma3)";
        assert!(has_no_repeated_factor(
            &p(&format!("{gamma}^4 - 1")),
            &order
        ));
        assert!(has_no_repeated_factor(&p("M1^2 - gamma1^2"), &order));
        // Differences of squares of the variables whose directions once coincided on every
        // line (the third and fourth, the second and fifth, the first and sixth).
        for square_free in [
            "M3^2 - gamma1^2 - 1",
            "M2^2 - gamma2^2 - 1",
            "M1^2 - gamma3^2 - 1",
        ] {
            assert!(
                has_no_repeated_factor(&p(square_free), &order),
                "{square_free}"
            );
        }
        assert!(!has_no_repeated_factor(&p("M1^2*gamma1"), &order));
        assert!(!has_no_repeated_factor(
            &p(&format!("{area}^2*({gamma} - 1)")),
            &order
        ));
    }

    /// A level set kept at the fixed values alone proves its integrals there alone: the flow
    /// of `p_x²/2 + p_y²/2 + xy p_y + ay` keeps `p_y = 0` at `a = 0` (`{P, H} = −x p_y − a`),
    /// where `p_x` is found with `{p_x, H} = −y p_y`; that bracket is a multiple of `P` for
    /// every `a`, but the level set is left at `a ≠ 0`, so nothing is proved for every value.
    #[test]
    fn a_level_set_kept_at_the_fixed_values_alone_proves_nothing_for_every_value() {
        let system = on_the_plane("kept at a = 0", "(p_x^2 + p_y^2)/2 + x*y*p_y + a*y", &["a"]);
        let a = system.vars().lookup("a").unwrap();
        let on_p_y = level(&system, "p_y", "0");
        assert!(on_p_y
            .check(&system, &[(a, Rational::from(0))], false)
            .is_ok());
        let space = SearchSpace::default().momenta_degree(1).positions_degree(1);
        let options = SearchOptions::new(space).fix(a, 0).on(on_p_y.clone());
        let r = search(&system, &options).unwrap();
        assert_proved_on(&system, &r, &on_p_y.polynomial().unwrap());
        let p_x = Expr::parse(system.vars(), "p_x").unwrap();
        let found = r.basis.iter().find(|f| f.fixed == p_x || f.fixed == -&p_x);
        let found = found.expect("p_x is conserved on p_y = 0 at a = 0");
        assert!(found.proved_fixed);
        assert!(r
            .basis
            .iter()
            .all(|f| f.proved_fixed && f.symbolic.is_none()));
    }

    /// An ordinary search is at the fixed values, so the flow is checked there: `x² + a y²`
    /// keeps `x p_y − y p_x = 0` at `a = 1` alone (`{P, H} = (1 − a) x y`), searched with
    /// `a` fixed to 1 and refused at 2 or with `a` free; a search for `a`'s exceptional values
    /// keeps it free, and `x p_y − y p_x`, conserved at `a = 1`, is found there.
    #[test]
    fn a_level_set_kept_at_the_fixed_values_alone_is_searched_there() {
        let oscillator = on_the_plane("oscillator", "(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2", &["a"]);
        let a = oscillator.vars().lookup("a").unwrap();
        let at = |x: i64| [(a, Rational::from(x))];
        let angular = level(&oscillator, "x*p_y - y*p_x", "0");
        assert!(angular.check(&oscillator, &at(1), false).is_ok());
        let leaves = |r: Result<(), EngineError>| match r {
            Err(EngineError::Invalid(m)) => m.starts_with(super::FLOW_LEAVES),
            _ => false,
        };
        assert!(leaves(angular.check(&oscillator, &at(2), false)));
        assert!(leaves(angular.check(&oscillator, &[], false)));
        assert!(leaves(angular.check_for_values_of(
            &oscillator,
            &[],
            a,
            false
        )));
        let space = SearchSpace::default().momenta_degree(2).positions_degree(2);
        let options = SearchOptions::new(space).fix(a, 1).on(angular.clone());
        let r = search(&oscillator, &options).unwrap();
        assert_proved_on(&oscillator, &r, &angular.polynomial().unwrap());
        assert!(r.basis.iter().all(|f| f.proved_fixed));
        let crossed = Expr::parse(oscillator.vars(), "p_x*p_y + x*y").unwrap();
        assert!(r
            .basis
            .iter()
            .any(|f| f.fixed == crossed || f.fixed == -&crossed));
    }

    #[test]
    fn level_sets_the_search_cannot_take_are_refused() {
        let top = gc_top();
        let space = SearchSpace::default().poisson_degree(2);
        let refused = |expr: &str, value: &str| match on(&top, space, level(&top, expr, value)) {
            Err(EngineError::Invalid(m)) => m,
            other => panic!("{expr} = {value}: {other:?}"),
        };
        let m = refused("M1", "0");
        assert!(
            m.contains("the flow of H leaves the level set") && m.contains("{P, H} = −3 M2 M3"),
            "{m}"
        );
        assert!(refused("M1/gamma3", "0").contains("negative power of γ3"));
        assert!(refused("c", "1").contains("no variable of phase space"));
        assert!(refused("gamma1", "M1").contains("value holds M1"));
        // A complex P: its real level set M1 = γ1 = 0 is two equations, not (P).
        let m = refused("M1 + i*gamma1", "0");
        assert!(m.contains("P = M1 + i γ1 is not real"), "{m}");
        assert!(refused("M1*gamma1 + M2*gamma2 + M3*gamma3", "i").contains("is not real"));
        // A square: M·γ, a normal form modulo (M·γ)², is zero on its level set, and would be
        // counted an integral there; and Γ − 1 of (Γ − 1)², which is no basis element of the
        // quadratics found but lies in their span.
        for square in [
            "(M1*gamma1 + M2*gamma2 + M3*gamma3)^2",
            "(gamma1^2 + gamma2^2 + gamma3^2 - 1)^2",
        ] {
            let m = refused(square, "0");
            assert!(
                m.contains("a repeated root on every one of the 12 lines")
                    && m.contains("write each factor of P once"),
                "{m}"
            );
        }
        // i times a real polynomial is one real equation: the message says to divide by i.
        let m = refused("i*(gamma1^2 + gamma2^2 + gamma3^2)", "i");
        assert!(m.contains("is i times a real polynomial"), "{m}");
        assert!(
            refused("c*M1*gamma1 + c*M2*gamma2 + c*M3*gamma3", "0").contains("holds a parameter")
        );
        // With c fixed, its leading coefficient is a number.
        let c = top.vars().lookup("c").unwrap();
        let at_two = SearchOptions::new(space)
            .on(level(&top, "c*M1*gamma1 + c*M2*gamma2 + c*M3*gamma3", "0"))
            .fix(c, Rational::from(2));
        assert!(search(&top, &at_two).is_ok());
        let c_is_two =
            crate::claim::Condition::new("c = 2", c, Expr::parse(top.vars(), "2").unwrap());
        let both = SearchOptions::new(space)
            .on(level(&top, "M1*gamma1 + M2*gamma2 + M3*gamma3", "0"))
            .when(c_is_two);
        let m = search(&top, &both).unwrap_err().to_string();
        assert!(
            m.contains("does not take a condition that fixes parameters")
                && m.contains("give their values with `fix` (on the command line, --fix)"),
            "{m}"
        );
    }
}
