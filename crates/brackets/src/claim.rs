//! Claims `lhs = rhs`, optionally under a condition on phase space, and their outcome: proved,
//! or refuted with the nonzero residual `lhs − rhs` in normal form.

use std::borrow::Cow;
use std::time::Instant;

use trigpoly::{AlgebraError, Expr, Rational, Style, Var, VarKind, Vars};

use crate::error::EngineError;
use crate::inputs::{keep_once, Input};
use crate::phase::PhaseSpace;
use crate::system::System;

/// A condition on phase space, applied after the bracket is formed: a substitution such as the
/// resonance `p_θ = mIω/n`.
///
/// Its values are resolved: none mentions a variable the condition sets, so that one
/// simultaneous substitution applies it (`p_θ = Iω, ω = 1/2` substitutes `p_θ → I/2, ω → 1/2`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Condition {
    /// How the condition reads (`p_θ = 2Iω`).
    pub text: String,
    /// The substitution, resolved.
    subs: Vec<(Var, Expr)>,
    /// The declared denominators the condition gives a value: each atom whose polynomial, in
    /// parameters alone, holds a parameter the condition sets, with the atom's value there
    /// (`1/(κ + 1)` is `2/3` at `κ = 1/2`), which [`Condition::apply`] substitutes with the rest.
    denominators: Vec<(Var, Expr)>,
    /// The declared denominators the condition gives no value the engine can take (`κ + 1` at
    /// `κ = 2λ` with `2λ + 1` undeclared): refused by [`Condition::apply`] where what it
    /// substitutes holds the atom, and by [`Condition::all`] where a value of the condition
    /// does, not where nothing divides by it.
    unvalued: Vec<Unvalued>,
    /// Why the condition cannot be applied at all, where [`Condition::new`] (which returns no
    /// error) met a denominator it sets that holds a phase variable:
    /// [`Condition::apply`] refuses with it, the variable set and the message.
    refusal: Option<(Var, String)>,
}

/// A declared denominator that a condition sets a parameter of but gives no value the engine
/// can take: its atom, the variable set, and why, the refusal of whatever holds the atom.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct Unvalued {
    atom: Var,
    set: Var,
    why: String,
}

/// The values a condition gives the declared denominators it sets a parameter of
/// ([`denominator_values`]): the atoms it takes at their value, and those it refuses to take.
#[derive(Default)]
struct DenominatorValues {
    values: Vec<(Var, Expr)>,
    unvalued: Vec<Unvalued>,
}

/// Why setting `v` to `value` is impossible when `v` is an angle: functions depend on it
/// through `e^{iθ}`, whose value is what a condition sets, and a constant of modulus other
/// than 1 is no value of it (`θ = 0` written as the value 0 made `e^{2iθ} = 0` proved).
fn not_on_the_circle(v: Var, value: &Expr) -> Option<String> {
    let var = value.vars().variable(v);
    if var.kind() != VarKind::Angle {
        return None;
    }
    let c = value.as_constant()?;
    (c.norm() != Rational::from(1)).then(|| {
        let theta = var.unicode();
        format!(
            "a condition on the angle {theta} sets e^{{i{theta}}}, and {} is no value of it \
             (its modulus is 1: 1 for {theta} = 0, i for {theta} = π/2)",
            value.render(Style::Unicode)
        )
    })
}

/// Why a condition may not set `v` at all: it is a radical or a denominator atom, which stands
/// for a polynomial of the other variables (`r = √(x² + y² + z²)`), so that setting it alone
/// would contradict its definition (`r = 1` beside `r² = x² + y² + z²`).
fn not_a_variable(v: Var, value: &Expr) -> Option<String> {
    let vars = value.vars();
    let what = match vars.variable(v).kind() {
        VarKind::Radical => "a radical",
        VarKind::Denominator => "a denominator",
        _ => return None,
    };
    Some(format!(
        "the condition sets {}, which is {what}, a function of the other variables: a \
         condition sets coordinates, momenta, angles or parameters; set those it is made of",
        vars.variable(v).unicode()
    ))
}

/// Why setting `v` to `value` sets no point of phase space, when `v` is no angle: its
/// variables and parameters are real, so a value that is not sets none (at `p_x = ix`,
/// `p_x² + x² = 0` was proved, of no real point).
fn not_real(v: Var, value: &Expr) -> Option<String> {
    let vars = value.vars();
    (vars.variable(v).kind() != VarKind::Angle && !value.is_real()).then(|| {
        format!(
            "the condition sets {} to {}, which is not real: the variables and parameters \
             take real values",
            vars.variable(v).unicode(),
            value.brief_excerpt()
        )
    })
}

/// A level of a [`Condition`] that the flow of `H` does not keep
/// ([`Condition::left_by_flow`]): on the surface, `{level, H} = rate`, not 0.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct LeftByFlow {
    /// The variable `v` whose level it is.
    pub var: Var,
    /// The level, `v` or `v − (value)` (`e^{iθ}` for an angle `θ`), in unicode.
    pub level: String,
    /// Its bracket with `H` on the surface, in unicode (a long one by its first terms and
    /// its size).
    pub rate: String,
}

/// `name − value` as a paper writes it, for a value as printed and its negation `negated`: a
/// single term after the minus sign (`x − 2y`, `p_θ − Iω`), a negative one, or a sum whose
/// first term is negative, as the sum with the negation (`x + 2y` for `−2y`, `x + y + 1` for
/// `−y − 1`), and another sum in parentheses (`x − (y p_y + y)`).
fn difference(name: &str, value: &str, negated: &str) -> String {
    // A sum has a ` + ` or ` − ` outside parentheses and braces (a single term may divide by
    // a declared denominator, `g/(x − y)`).
    let mut depth = 0usize;
    let mut sum = false;
    let chars: Vec<char> = value.chars().collect();
    for (k, &c) in chars.iter().enumerate() {
        match c {
            '(' | '{' | '[' => depth += 1,
            ')' | '}' | ']' => depth = depth.saturating_sub(1),
            '+' | '−' if depth == 0 && k > 0 && chars[k - 1] == ' ' => sum = true,
            _ => {}
        }
    }
    match (sum, value.starts_with('−')) {
        (_, true) => format!("{name} + {negated}"),
        (true, false) => format!("{name} − ({value})"),
        (false, false) => format!("{name} − {value}"),
    }
}

impl std::fmt::Display for Condition {
    /// The condition as it reads (its `text`: `p_θ = 2Iω`).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)
    }
}

impl Condition {
    /// `v = value`, where `value` does not mention `v` (a value read from input goes through
    /// [`Condition::all`], which says so when it does).
    ///
    /// # Panics
    ///
    /// If `value` mentions `v`: the condition would be an equation, not a substitution; and
    /// if `v` is an angle and `value` a constant of modulus other than 1: functions depend on
    /// an angle through `e^{iθ}`, so the value set is that of `e^{iθ}` (1 for `θ = 0`, `i` for
    /// `θ = π/2`), never 0; and if `v` is no angle and `value` is not real: the variables and
    /// parameters take real values; and if `v` is a radical or a denominator, which stand for
    /// functions of the other variables; and if `v` is not a handle of `value`'s set.
    /// [`Condition::all`] refuses each with an error.
    pub fn new(text: &str, v: Var, value: Expr) -> Self {
        assert!(
            !value.contains(v),
            "a condition's value mentions its variable ({text}); Condition::all refuses it \
             with an error"
        );
        assert!(
            not_on_the_circle(v, &value).is_none(),
            "a condition sets e^{{iθ}} off the unit circle ({text}); Condition::all refuses it \
             with an error"
        );
        assert!(
            not_a_variable(v, &value).is_none(),
            "a condition sets a radical or a denominator ({text}); Condition::all refuses it \
             with an error"
        );
        assert!(
            not_real(v, &value).is_none(),
            "a condition sets a real variable to a value that is not real ({text}); \
             Condition::all refuses it with an error"
        );
        let subs = vec![(v, value)];
        // A value that leaves a denominator without one is refused where the condition is
        // applied ([`Condition::apply`]).
        let (denominators, refusal) = match denominator_values(text, &subs) {
            Ok(values) => (values, None),
            Err(EngineError::RefusedCondition { var, message }) => {
                (DenominatorValues::default(), Some((var, message)))
            }
            Err(e) => (DenominatorValues::default(), Some((v, e.to_string()))),
        };
        Condition {
            text: text.to_string(),
            subs,
            denominators: denominators.values,
            unvalued: denominators.unvalued,
            refusal,
        }
    }

    /// `v₁ = value₁, v₂ = value₂, …`, each variable set once, where a value may use the
    /// variables set by the others (`p_θ = Iω, ω = 1/2`): the values are substituted into one
    /// another until none mentions a variable the condition sets. A variable set in terms of
    /// itself, directly (`x = 2x`) or through the others (`x = y, y = x`), is refused: such a
    /// condition is an equation, not a substitution. So is a value that is not real (for an
    /// angle, one off the unit circle), a radical or a denominator set as if it were a
    /// variable, a variable that a radicand or a denominator holding a phase variable involves
    /// ([`Condition::cannot_set`]), a value where a denominator in parameters
    /// alone is zero (`κ = −1` of `1/(κ + 1)`), and a value that holds a denominator the
    /// condition gives no value it can take. Every refusal is an
    /// [`EngineError::RefusedCondition`] naming the variable, but that of values in different
    /// variable sets, or of a variable that is not a handle of theirs, which is
    /// [`AlgebraError::VarSetMismatch`]; so is the use of a condition with functions of another
    /// set (a claim's, a search's).
    ///
    /// ```
    /// use brackets::{systems, Claim, Condition, EngineError};
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let (p_theta, omega) = (rotor.var("p_theta"), rotor.var("omega"));
    /// // p_θ = Iω, ω = 1/2: the first value is resolved to I/2.
    /// let at = Condition::all(
    ///     "p_θ = Iω, ω = 1/2",
    ///     vec![(p_theta, rotor.parse("I*omega")?), (omega, rotor.parse("1/2")?)],
    /// )?;
    /// assert_eq!(at.subs()[0].1.to_string(), "I/2");
    /// // There Ω = p_θ/I is ω = 1/2, and the claim holds there only.
    /// let (lhs, rhs) = (rotor.parse("p_theta/I")?, rotor.parse("omega")?);
    /// let claim = Claim::new("Ω", "p_θ/I = ω", lhs, rhs);
    /// assert!(!claim.check()?.outcome.is_proved());
    /// assert!(claim.when(at).check()?.outcome.is_proved());
    /// // x = y, y = x is an equation, not a substitution.
    /// let (x, y) = (rotor.var("x"), rotor.var("y"));
    /// let swap = vec![(x, rotor.parse("y")?), (y, rotor.parse("x")?)];
    /// let circular = Condition::all("x = y, y = x", swap);
    /// assert!(matches!(circular, Err(EngineError::RefusedCondition { .. })));
    /// # Ok::<(), EngineError>(())
    /// ```
    pub fn all(text: &str, subs: Vec<(Var, Expr)>) -> Result<Self, EngineError> {
        let mut subs = subs;
        if let Some((_, first)) = subs.first() {
            let vars = first.vars();
            if subs.iter().any(|(v, e)| !vars.owns(*v) || e.vars() != vars) {
                return Err(AlgebraError::VarSetMismatch.into());
            }
        }
        for (v, value) in &subs {
            if let Some(why) = not_a_variable(*v, value)
                .or_else(|| not_on_the_circle(*v, value))
                .or_else(|| not_real(*v, value))
            {
                return Err(refused(*v, why));
            }
        }
        if let Some(k) = (1..subs.len()).find(|&k| subs[..k].iter().any(|s| s.0 == subs[k].0)) {
            let name = subs[k].1.vars().variable(subs[k].0).unicode().to_string();
            return Err(refused(
                subs[k].0,
                format!("the condition sets {name} twice"),
            ));
        }
        if let Some((v, why)) = subs.iter().find_map(|(v, value)| {
            let atoms = Expr::denominator_atoms(value.vars()).ok()?;
            Condition::sets_a_denominator(&atoms, *v).map(|why| (*v, why))
        }) {
            return Err(refused(v, why));
        }
        Condition {
            text: text.to_string(),
            subs: subs.clone(),
            denominators: Vec::new(),
            unvalued: Vec::new(),
            refusal: None,
        }
        .keeps_radicands()?;
        let sets = |e: &Expr, subs: &[(Var, Expr)]| subs.iter().any(|(v, _)| e.contains(*v));
        let written = subs.clone();
        // A chain of k substitutions resolves in k rounds; what is left after as many rounds
        // as there are substitutions goes round a cycle.
        for _ in 0..subs.len() {
            if let Some((v, _)) = subs.iter().find(|(v, e)| e.contains(*v)) {
                return Err(circular(*v, &subs));
            }
            if let Some(refusal) = value_divides_by_zero(&subs, &written) {
                return Err(refusal);
            }
            if !subs.iter().any(|(_, e)| sets(e, &subs)) {
                let DenominatorValues { values, unvalued } = denominator_values(text, &subs)?;
                // A value that holds an atom the condition gives a value (`x = 1/(κ + 1)` at
                // `κ = 1/2`) takes it too, so that nothing the condition applies to keeps it.
                let subs: Vec<(Var, Expr)> = match values.is_empty() {
                    true => subs,
                    false => (subs.iter())
                        .map(|(v, e)| Ok((*v, e.subst_many(&values)?)))
                        .collect::<Result<_, EngineError>>()?,
                };
                let condition = Condition {
                    text: text.to_string(),
                    subs,
                    denominators: values,
                    unvalued,
                    refusal: None,
                };
                // One that holds an atom given no value has none.
                for (_, value) in &condition.subs {
                    condition.takes_its_denominators(value)?;
                }
                return Ok(condition);
            }
            subs = subs
                .iter()
                .map(|(v, e)| Ok((*v, e.subst_many(&subs)?)))
                .collect::<Result<_, EngineError>>()?;
        }
        let (v, _) = subs
            .iter()
            .find(|(_, e)| sets(e, &subs))
            .expect("a value still mentions a variable the condition sets");
        Err(circular(*v, &subs))
    }

    /// The substitution `(variable, value)`, resolved: no value mentions a variable set here.
    pub fn subs(&self) -> &[(Var, Expr)] {
        &self.subs
    }

    /// The values the substitution sets its variables to (`1/(a1 − a2)` of `c = 1/(a1 −
    /// a2)`): what the linear algebra refuses where one divides by a declared denominator
    /// that vanishes at its fixed values, since the condition has no value there.
    pub fn values(&self) -> impl Iterator<Item = &Expr> + Clone {
        self.subs.iter().map(|(_, value)| value)
    }

    /// The substitution as text that superint reads back, with the variables' ASCII names:
    /// `p_theta = I*omega`, pieces separated by commas.
    pub fn ascii(&self) -> String {
        self.subs
            .iter()
            .map(|(v, e)| {
                format!(
                    "{} = {}",
                    e.vars().variable(*v).name(),
                    e.render(Style::Ascii)
                )
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// How the condition reads and its [`Condition::ascii`] form: `("p_θ = Iω",
    /// "p_theta = omega*I")`.
    pub fn forms(&self) -> (String, String) {
        (self.text.clone(), self.ascii())
    }

    /// The first variable of phase space the condition sets or sets a parameter to, with its
    /// kind in words, after the variable the condition sets there, at whose value a caller
    /// holding the condition's text shows it (`(M, "p_x", "a momentum")` of `M = p_x`); `None`
    /// when it sets parameters to numbers and other parameters only, a substitution that
    /// commutes with every bracket.
    pub fn phase_variable(&self) -> Option<(Var, String, &'static str)> {
        self.subs.iter().find_map(|(v, value)| {
            let vars = value.vars();
            let phase = |w: &Var| vars.variable(*w).kind() != VarKind::Parameter;
            let w = match phase(v) {
                true => Some(*v),
                false => vars.vars().find(|w| phase(w) && value.contains(*w)),
            }?;
            let variable = vars.variable(w);
            Some((
                *v,
                variable.unicode().to_string(),
                variable.kind().described(),
            ))
        })
    }

    /// The phase variables the condition sets (coordinates, momenta, Poisson variables), in
    /// its order: it describes their level set, the graph of their values over the other
    /// variables, which is what a rank on it ([`crate::rank_on`]) differentiates by.
    /// `p_θ = Iω` gives `[p_θ]`; `ω = 1/2` gives none.
    ///
    /// Refused ([`EngineError::RefusedCondition`]) where the condition sets an angle (its
    /// `e^{iθ}`, no coordinate of its own) or a parameter to a function of phase space
    /// (`ω = p_x`, which changes the functions rather than restricting them).
    pub fn level_set_variables(&self) -> Result<Vec<Var>, EngineError> {
        let mut set = Vec::new();
        for (v, value) in &self.subs {
            let vars = value.vars();
            let name = vars.variable(*v).unicode();
            match vars.variable(*v).kind() {
                VarKind::Angle => {
                    return Err(refused(
                        *v,
                        format!(
                            "the condition sets the angle {name}: a rank's condition may set \
                             parameters, coordinates, momenta and Poisson variables, and an \
                             angle's condition sets e^{{i{name}}}, no coordinate of the \
                             Jacobian"
                        ),
                    ))
                }
                VarKind::Parameter => {
                    let phase = vars.vars().find(|&w| {
                        vars.variable(w).kind() != VarKind::Parameter && value.contains(w)
                    });
                    if let Some(w) = phase {
                        let w = vars.variable(w);
                        return Err(refused(
                            *v,
                            format!(
                                "the condition sets the parameter {name} to a function of phase \
                                 space (it holds {}, {}): a rank's condition sets parameters to \
                                 numbers or other parameters, and a phase variable to a value \
                                 in them and the other phase variables, the rank being that on \
                                 its level set",
                                w.unicode(),
                                w.kind().described()
                            ),
                        ));
                    }
                }
                _ => set.push(*v),
            }
        }
        Ok(set)
    }

    /// Applies the substitution, and the values it gives the declared denominators whose
    /// polynomial, in parameters alone, holds a parameter it sets (`1/(κ + 1)` is `2/3` at
    /// `κ = 1/2`): [`Condition::substitution`].
    pub fn apply(&self, e: &Expr) -> Result<Expr, EngineError> {
        self.within(e.vars())?;
        self.applicable()?;
        self.takes_its_denominators(e)?;
        Ok(e.subst_many(&self.substitution())?)
    }

    /// The substitution [`Condition::apply`] makes: [`Condition::subs`], then the values the
    /// condition gives the declared denominators whose polynomial, in parameters alone, holds
    /// a parameter it sets (the atom of `κ + 1` to `3/2` at `κ = 1/2`). A caller that
    /// substitutes it itself (a search whose space holds them) refuses first what
    /// [`Condition::values_denominators`] refuses.
    pub fn substitution(&self) -> Cow<'_, [(Var, Expr)]> {
        match self.denominators.is_empty() {
            true => Cow::Borrowed(&self.subs),
            false => Cow::Owned(
                self.subs
                    .iter()
                    .chain(&self.denominators)
                    .cloned()
                    .collect(),
            ),
        }
    }

    /// Refuses the condition for a use that substitutes [`Condition::substitution`] into what
    /// may divide by any declared denominator (a search, whose space holds their powers):
    /// what [`Condition::apply`] refuses of any expression, and a denominator the condition
    /// sets a parameter of but gives no value it can take, even where nothing holds it yet.
    pub fn values_denominators(&self) -> Result<(), EngineError> {
        self.applicable()?;
        match self.unvalued.first() {
            Some(u) => Err(refused(u.set, u.why.clone())),
            None => Ok(()),
        }
    }

    /// Refuses the condition for a use that substitutes it into what divides by no declared
    /// denominator but where `e` does (a search whose space holds none, `e` its `H`): what
    /// [`Condition::apply`] refuses of any expression, and a denominator the condition gives no
    /// value where `e` holds it.
    pub fn values_denominators_of(&self, e: &Expr) -> Result<(), EngineError> {
        self.applicable()?;
        self.takes_its_denominators(e)
    }

    /// Refuses the condition wherever it is applied: where it sets a variable a radicand
    /// involves ([`Condition::keeps_radicands`]), and where [`Condition::new`] met a
    /// denominator it sets that holds a phase variable.
    fn applicable(&self) -> Result<(), EngineError> {
        self.keeps_radicands()?;
        match &self.refusal {
            Some((v, why)) => Err(refused(*v, why.clone())),
            None => Ok(()),
        }
    }

    /// Refuses `e` where it holds the atom of a declared denominator the condition sets a
    /// parameter of but gives no value the engine can take (its `unvalued`); an
    /// expression that does not divide by it takes the condition.
    fn takes_its_denominators(&self, e: &Expr) -> Result<(), EngineError> {
        match self.unvalued.iter().find(|u| e.contains(u.atom)) {
            Some(u) => Err(refused(u.set, u.why.clone())),
            None => Ok(()),
        }
    }

    /// Whether the condition substitutes its own variables alone ([`Condition::subs`]): no
    /// declared denominator's polynomial or radicand involves a variable it sets, so that
    /// [`Condition::apply`] has no atom to give a value (`1/(κ + 1)` at `κ = 1/2`) and no
    /// radical to refuse (`r = √(x² + y² + z²)` at `z = 0`).
    pub fn substitutes_its_variables_alone(&self) -> bool {
        let Some((_, first)) = self.subs.first() else {
            return true;
        };
        let vars = first.vars();
        let holds_one = |polynomials: Result<Vec<(Var, Expr)>, _>| {
            polynomials.map_or(true, |ps| {
                ps.iter()
                    .any(|(_, d)| self.subs.iter().any(|(v, _)| d.contains(*v)))
            })
        };
        !holds_one(Expr::denominator_atoms(vars)) && !holds_one(Expr::radicals(vars))
    }

    /// Refuses a condition that sets a variable a radicand involves: the radical `r = √(x² +
    /// y² + z²)` would keep `r² = x² + y² + z²` at `z = 0`.
    fn keeps_radicands(&self) -> Result<(), EngineError> {
        let Some((_, first)) = self.subs.first() else {
            return Ok(());
        };
        let radicals = Expr::radicals(first.vars())?;
        // The first radical that a variable set involves, and the first such variable.
        let refusal = (0..radicals.len()).find_map(|k| {
            self.subs.iter().find_map(|(v, _)| {
                Condition::sets_a_radicand(&radicals[k..=k], *v).map(|why| (*v, why))
            })
        });
        match refusal {
            Some((v, why)) => Err(refused(v, why)),
            None => Ok(()),
        }
    }

    /// Why a condition may not set `v` in `space`, if it may not: a denominator's polynomial
    /// that holds a phase variable ([`Condition::sets_a_denominator`]) or a radicand
    /// ([`Condition::sets_a_radicand`]) involves it.
    pub fn cannot_set(space: &PhaseSpace, v: Var) -> Option<String> {
        Condition::sets_a_denominator(space.denominator_atoms(), v)
            .or_else(|| Condition::sets_a_radicand(space.radicals(), v))
    }

    /// Why a condition may not set `v`, if it may not: the polynomial of one of the
    /// denominator `atoms` involves it and a coordinate, momentum or angle besides, so that the
    /// condition would set a function of phase space in it (`x` in `x − y`), which the atom
    /// would go on standing for. A polynomial in parameters alone takes its value at the
    /// condition ([`Condition::apply`]).
    pub fn sets_a_denominator(atoms: &[(Var, Expr)], v: Var) -> Option<String> {
        let (atom, d) = atoms.iter().find(|(_, d)| {
            let vars = d.vars();
            d.contains(v)
                && vars
                    .vars()
                    .any(|w| vars.variable(w).kind() != VarKind::Parameter && d.contains(w))
        })?;
        let vars = d.vars();
        Some(format!(
            "the condition sets {}, which the denominator {} involves: a condition on a \
             denominator's variables is not supported where the denominator holds a \
             coordinate, a momentum or an angle (one in parameters alone takes its value there)",
            vars.variable(v).unicode(),
            vars.variable(*atom).unicode()
        ))
    }

    /// Why a condition may not set `v`, if it may not: the radicand of one of the `radicals`
    /// involves it: the radical `r = √(x² + y² + z²)` would keep `r² = x² + y² + z²` at `z = 0`.
    pub fn sets_a_radicand(radicals: &[(Var, Expr)], v: Var) -> Option<String> {
        let (radical, radicand) = radicals.iter().find(|(_, r)| r.contains(v))?;
        let vars = radicand.vars();
        Some(format!(
            "the condition sets {}, which the radicand of {} = √({radicand}) involves: a \
             condition on a radicand's variables is not supported (declare the radical with \
             the value in its radicand instead)",
            vars.variable(v).unicode(),
            vars.variable(*radical).unicode(),
        ))
    }

    /// Refuses the condition where the flow of `system`'s Hamiltonian leaves the surface it
    /// describes: for a variable `v` set to `value`, `{v − value, H}` must vanish there, as
    /// `{p_θ, H} = 0` does at a resonance `p_θ = mIω/n`. A function whose bracket with `H`
    /// vanishes only on a surface that the flow leaves (`y = 0` where `ẏ = p_y`) is no
    /// integral, so a search or a closure under such a condition would mislabel it. A parameter
    /// set to a constant is kept; one set to a function of phase space (`a = p_x`) is a
    /// surface like any other, which the flow leaves unless `{value, H}` vanishes there. The
    /// refusal is an [`EngineError::RefusedCondition`] naming the variable whose level the
    /// flow leaves, which a caller holding the condition's text shows at its value there.
    pub fn kept_by_flow(&self, system: &System) -> Result<(), EngineError> {
        let Some(left) = self.left_by_flow(system)? else {
            return Ok(());
        };
        // The rotor's resonance is the example where the system has an angle to resonate
        // with; elsewhere the rule is said as it is.
        let kept = match system.vars().angles().next() {
            Some(_) => "p_θ at a resonance p_θ = mIω/n, where {p_θ, H} = 0",
            None => "those whose bracket with H vanishes on the surface",
        };
        Err(refused(
            left.var,
            format!(
                "the flow leaves the surface {}: there {{{}, H}} = {}, not 0, so what is \
                 conserved on it is no integral; a condition may set parameters to constants, \
                 and variables the flow keeps ({kept})",
                self.text, left.level, left.rate
            ),
        ))
    }

    /// Where the flow of `system`'s Hamiltonian leaves the surface the condition describes,
    /// decided exactly as [`Condition::kept_by_flow`] decides it (`{v − value, H}` at the
    /// condition, for each variable `v` it sets, but a parameter set to a constant): the first
    /// level whose rate is not zero there, or `None` where the flow keeps the surface.
    pub fn left_by_flow(&self, system: &System) -> Result<Option<LeftByFlow>, EngineError> {
        let vars = system.vars();
        self.within(vars)?;
        for (v, value) in &self.subs {
            let moves = vars
                .vars()
                .any(|w| vars.variable(w).kind() != VarKind::Parameter && value.contains(w));
            if vars.variable(*v).kind() == VarKind::Parameter && !moves {
                continue;
            }
            let level = Expr::var(vars, *v).checked_sub(value)?;
            let rate = system.flow_when(&level, self)?;
            if !rate.vanishes()? {
                let name = vars.variable(*v).unicode();
                // An angle enters as e^{iθ}, whose bracket is the one computed.
                let name = match vars.variable(*v).kind() {
                    VarKind::Angle => format!("e^{{i{name}}}"),
                    _ => name.to_string(),
                };
                // A long value or rate by its first terms and its size (a value of 5456 terms
                // made a message of 0.7 MB).
                let level = match moves {
                    true => difference(&name, &value.brief_excerpt(), &(-value).brief_excerpt()),
                    false => name,
                };
                return Ok(Some(LeftByFlow {
                    var: *v,
                    level,
                    rate: rate.brief_excerpt(),
                }));
            }
        }
        Ok(None)
    }

    /// `e` under the condition: refused where it is not defined there ([`Condition::defined_on`],
    /// `what` naming it in the message), else substituted.
    pub fn apply_where_defined(&self, e: &Expr, what: &str) -> Result<Expr, EngineError> {
        self.defined_on(&[e], what)?;
        self.apply(e)
    }

    /// Refuses the condition where it sets to zero a variable that one of `sides` divides by,
    /// or where one of them holds a declared denominator it gives no value (`1/(ω² − Ω²)` at
    /// `Ω = ω`): there the sides have no value, even when their difference is zero before the
    /// substitution (`p_x/M = p_x/M` at `M = 0`). `what` names the sides in the message (`the
    /// claim`). The refusal is an [`EngineError::RefusedCondition`] naming that variable, so
    /// that a caller holding the condition's text shows it at the variable's value there.
    pub fn defined_on(&self, sides: &[&Expr], what: &str) -> Result<(), EngineError> {
        for side in sides {
            self.within(side.vars())?;
        }
        let held = |u: &&Unvalued| sides.iter().any(|side| side.contains(u.atom));
        if let Some(u) = self.unvalued.iter().find(held) {
            return Err(refused(u.set, format!("{} ({what} divides by it)", u.why)));
        }
        let divisor = sides.iter().find_map(|side| {
            Condition::sets_a_divisor_to_zero(&self.subs, side).map(|v| (v, side.vars()))
        });
        match divisor {
            Some((v, vars)) => {
                let name = vars.variable(v).unicode();
                Err(refused(
                    v,
                    format!(
                        "the condition sets {name} = 0, but {what} divides by {name}: give \
                         {name} a value other than 0, or leave it free"
                    ),
                ))
            }
            None => Ok(()),
        }
    }

    /// Refuses the condition where it sets to zero a variable that one of `inputs` divides by
    /// ([`Condition::defined_on`], each named by its [`Input::what`], and by the name of the
    /// claim's that was computed from it, [`Input::via`]): an expression computed from them has
    /// no value there, even where it has cancelled the divisor (`{A, H} = 0` of the heavy top
    /// at `I3 = 0`, where `H` divides by `I3`).
    pub fn defined_on_inputs(&self, inputs: &[Input]) -> Result<(), EngineError> {
        inputs.iter().try_for_each(|i| match &i.via {
            Some(via) => self.defined_on(
                &[&i.value],
                &format!("the claim's {via} is computed from {}, which", i.what),
            ),
            None => self.defined_on(&[&i.value], &i.what),
        })
    }

    /// The first variable that `values` sets to zero and `e` divides by (holds to a negative
    /// power), if any: there `e` has no value (`p_x²/(2M)` at `M = 0`). The one check of a
    /// condition ([`Condition::defined_on`]) and of the values a plot gives its parameters.
    pub fn sets_a_divisor_to_zero(values: &[(Var, Expr)], e: &Expr) -> Option<Var> {
        values
            .iter()
            .find(|(v, value)| {
                value.is_zero() && e.exponent_range(*v).is_some_and(|(lo, _)| lo < 0)
            })
            .map(|(v, _)| *v)
    }

    /// Refuses `vars` unless the condition was read in them: a condition of another system
    /// names its variables by handles that are not `vars`'s.
    fn within(&self, vars: &Vars) -> Result<(), EngineError> {
        match self.subs.iter().all(|(_, value)| value.vars() == vars) {
            true => Ok(()),
            false => Err(AlgebraError::VarSetMismatch.into()),
        }
    }
}

/// The values a condition's resolved `subs` (read as `text`) give the declared denominators
/// whose polynomial `D` holds a variable it sets: the atom, which stands for `D`, takes `D`'s
/// value at the condition, a nonzero number or a polynomial that division by the declared
/// denominators reaches (`(κ + 1)` is `3/2` at `κ = 1/2`, so `1/(κ + 1)` is `2/3`). Refused
/// ([`EngineError::RefusedCondition`], naming the variable set) where `D` holds a phase
/// variable ([`Condition::sets_a_denominator`]). Where it is zero at the condition (what
/// divides by it has no value there), where division does not reach its value, or where the
/// value divides by a denominator, the atom is `unvalued`, refused only where held.
fn denominator_values(text: &str, subs: &[(Var, Expr)]) -> Result<DenominatorValues, EngineError> {
    let Some((_, first)) = subs.first() else {
        return Ok(DenominatorValues::default());
    };
    let vars = first.vars();
    let atoms = Expr::denominator_atoms(vars)?;
    let set: Vec<(Var, &Expr, Var)> = atoms
        .iter()
        .filter_map(|(atom, d)| Some((*atom, d, subs.iter().find(|(v, _)| d.contains(*v))?.0)))
        .collect();
    let mut values = DenominatorValues::default();
    for &(atom, d, v) in &set {
        if let Some(why) = Condition::sets_a_denominator(&atoms, v) {
            return Err(refused(v, why));
        }
        let name = vars.variable(v).unicode();
        let at = d.subst_many(subs)?;
        // What divides by a denominator zero at the condition has no value there; what does
        // not (the resonant integral beside the one off resonance) takes the condition.
        if at.vanishes()? {
            let why = format!(
                "at {text} the denominator {d} is 0, so what divides by it has no value \
                 there: give {name} a value where {d} is not 0, or leave it free"
            );
            values.unvalued.push(Unvalued { atom, set: v, why });
            continue;
        }
        // The atom stands for `D`, its negative powers for `1/D^k`: it takes `D`'s value,
        // whose inverse division must reach.
        // A value that divides by a denominator is no polynomial to divide by: clearing it
        // (`1 + 1/(m + 1)` is `(m + 2)/(m + 1)`) would need division by a sum of atoms.
        let held = atoms.iter().find(|(a, _)| at.contains(*a));
        let why = match (held, Expr::one(vars).checked_div(&at)) {
            (None, Ok(_)) => {
                values.values.push((atom, at));
                continue;
            }
            (Some((_, other)), _) => format!(
                "at {text} the denominator {d} is {at}, which divides by the denominator \
                 {other}: a denominator's value that divides by another is not supported; give \
                 {name} a value where {d} is a number, a single term or a product of declared \
                 denominators, or leave it free"
            ),
            (None, Err(e)) => format!(
                "at {text} the denominator {d} is {at}, and {e}; or give {name} a value where \
                 {d} is a number, a single term or a product of declared denominators, or leave \
                 it free"
            ),
        };
        values.unvalued.push(Unvalued { atom, set: v, why });
    }
    Ok(values)
}

/// The error for a condition that sets `v` in terms of itself.
fn circular(v: Var, subs: &[(Var, Expr)]) -> EngineError {
    let vars = subs[0].1.vars();
    let name = vars.variable(v).unicode().to_string();
    refused(
        v,
        format!(
            "the condition sets {name} in terms of itself (directly or through the other \
             variables it sets): a condition is a substitution, so give {name} a value free of them"
        ),
    )
}

/// The refusal of a condition one of whose values, `subs` in part resolved, divides by a
/// variable that another of its values sets to zero (`γ3 = 0, M3 = M1/γ3`): that value has
/// none there, which substituting it would find only as a "division by zero" at no place.
/// The divisor named is one of the value as `written` where it has one set to zero by now
/// (`γ3` of `γ3 = γ1, γ1 = 0, M3 = M1/γ3`, whose `M3` is `M1/γ1` after a round). `None`
/// where no value divides by zero.
fn value_divides_by_zero(subs: &[(Var, Expr)], written: &[(Var, Expr)]) -> Option<EngineError> {
    subs.iter()
        .zip(written)
        .find_map(|((v, value), (_, as_written))| {
            let zero = Condition::sets_a_divisor_to_zero(subs, value)?;
            let zero = Condition::sets_a_divisor_to_zero(subs, as_written).unwrap_or(zero);
            let vars = value.vars();
            let (name, divisor) = (vars.variable(*v).unicode(), vars.variable(zero).unicode());
            Some(refused(
                *v,
                format!(
                    "the condition sets {divisor} = 0, but the value of {name} divides by \
                     {divisor}: give {name} a value defined there, or leave {divisor} free"
                ),
            ))
        })
}

/// A condition refused for what it does to `v`.
fn refused(v: Var, message: String) -> EngineError {
    EngineError::RefusedCondition { var: v, message }
}

/// An identity to check: `lhs = rhs`, under an optional condition. Two are equal when their
/// ids, statements, sides and conditions are.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
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
    /// What the sides were computed from ([`Claim::computed_from`]), each of which must have a
    /// value at the condition.
    pub inputs: Vec<Input>,
}

/// What checking a claim found.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
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

/// A checked claim, with its timing: made by [`Claim::check`] and read. A field may be added,
/// so a pattern of one names the fields it reads and `..`:
///
/// ```compile_fail,E0638
/// fn id(verdict: brackets::Verdict) -> String {
///     let brackets::Verdict { id, statement, condition, outcome, seconds } = verdict;
///     id
/// }
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
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

/// `proved`, or `refuted: the residual lhs − rhs is …`.
impl std::fmt::Display for Outcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Outcome::Proved => f.write_str("proved"),
            Outcome::Refuted { residual } => {
                write!(f, "refuted: the residual lhs − rhs is {residual}")
            }
        }
    }
}

/// `C09: {L, G1} = −G2: proved`, with ` at p_θ = Iω` after the statement when conditional.
impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.id, self.statement)?;
        if let Some(c) = &self.condition {
            write!(f, " at {c}")?;
        }
        write!(f, ": {}", self.outcome)
    }
}

impl Claim {
    /// `lhs = rhs`, as bare expressions: the claim cannot see what they were computed from.
    /// Under a condition it is refused only where `lhs` or `rhs` itself divides by a variable
    /// set to 0, not where `H`, a function or a declared bracket they were computed from does
    /// and the computation cancelled the divisor (`{F2, L}` of the harmonic rotor is 0, and so
    /// proved at `I = 0`, though `F2 = p_θ²/(2I)` has no value there). Read the sides with
    /// [`Claim::parse`], or give what they were computed from with [`Claim::computed_from`]
    /// ([`System::parse_recording`]), for such a condition to be refused.
    ///
    /// ```
    /// use brackets::{systems, Claim, Condition};
    /// use trigpoly::Expr;
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let i = rotor.lookup("I").unwrap();
    /// let at_zero = Condition::new("I = 0", i, Expr::zero(rotor.vars()));
    /// let (bracket, inputs) = rotor.parse_recording("{F2, L}")?;
    /// let zero = Expr::zero(rotor.vars());
    /// let bare = Claim::new("x", "{F2, L} = 0", bracket.clone(), zero.clone());
    /// assert!(bare.when(at_zero.clone()).check()?.outcome.is_proved());
    /// let told = Claim::new("x", "{F2, L} = 0", bracket, zero).computed_from(inputs);
    /// assert!(told.when(at_zero).check().is_err());
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn new(id: &str, statement: &str, lhs: Expr, rhs: Expr) -> Self {
        Claim {
            id: id.into(),
            statement: statement.into(),
            lhs,
            rhs,
            condition: None,
            inputs: Vec::new(),
        }
    }

    /// `lhs = rhs`, both read in `system` with what they are computed from
    /// ([`System::parse_recording`]), so that a condition where one of those has no value is
    /// refused. A claim made by [`Claim::new`] knows only its sides: at `I = 0` the harmonic
    /// rotor's `{F2, L} = 0` is proved there, though `F2 = p_θ²/(2I)` has no value.
    ///
    /// ```
    /// use brackets::{systems, Claim, Condition, EngineError};
    /// use trigpoly::Expr;
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let at = |i: i64| {
    ///     let v = rotor.lookup("I").unwrap();
    ///     Condition::new(&format!("I = {i}"), v, Expr::constant(rotor.vars(), i.into()))
    /// };
    /// let read = Claim::parse(&rotor, "x", "{F2, L} = 0", "{F2, L}", "0")?;
    /// assert!(read.clone().when(at(2)).check()?.outcome.is_proved());
    /// let Err(EngineError::RefusedCondition { message, .. }) = read.when(at(0)).check() else {
    ///     panic!("refused")
    /// };
    /// assert!(message.contains("the condition sets I = 0, but the function F2 divides by I"));
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn parse(
        system: &System,
        id: &str,
        statement: &str,
        lhs: &str,
        rhs: &str,
    ) -> Result<Self, EngineError> {
        let (lhs, mut inputs) = system.parse_recording(lhs)?;
        let (rhs, more) = system.parse_recording(rhs)?;
        more.into_iter().for_each(|i| keep_once(&mut inputs, i));
        Ok(Claim::new(id, statement, lhs, rhs).computed_from(inputs))
    }

    /// The same claim under a condition.
    #[must_use]
    pub fn when(mut self, condition: Condition) -> Self {
        self.condition = Some(condition);
        self
    }

    /// The same claim, its sides computed from `inputs` ([`System::parse_recording`]): a
    /// condition where one of them has no value is refused ([`Condition::defined_on_inputs`]).
    #[must_use]
    pub fn computed_from(mut self, inputs: Vec<Input>) -> Self {
        self.inputs = inputs;
        self
    }

    /// The residual `lhs − rhs` after the condition, in normal form. Refused where the
    /// condition sets to zero a variable that a side or an input divides by.
    pub fn residual(&self) -> Result<Expr, EngineError> {
        if let Some(c) = &self.condition {
            c.defined_on(&[&self.lhs, &self.rhs], "the claim")?;
            c.defined_on_inputs(&self.inputs)?;
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
    ///
    /// ```
    /// use brackets::{systems, Claim};
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let p = |s: &str| rotor.parse(s).unwrap();
    /// let su2 = Claim::new("C09", "{L, G1} = −G2", p("{L, G1}"), p("-G2"));
    /// assert_eq!(su2.check()?.to_string(), "C09: {L, G1} = −G2: proved");
    /// let sign = Claim::new("sign", "{L, G2} = G1", p("{L, G2}"), p("G1"));
    /// assert_eq!(
    ///     sign.check()?.to_string(),
    ///     "sign: {L, G2} = G1: refuted: the residual lhs − rhs is 3 p_x p_y/(2M) + 3Mω²xy/2"
    /// );
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn check(&self) -> Result<Verdict, EngineError> {
        let start = Instant::now();
        let residual = self.residual()?;
        // With denominator atoms, zero is decided by clearing them, and a residual shown over
        // a common denominator, whose numerator is then plainly not zero.
        let outcome = if residual.vanishes()? {
            Outcome::Proved
        } else {
            Outcome::Refuted {
                residual: residual.over_common_denominators()?,
            }
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

#[cfg(test)]
mod tests {
    use super::difference;

    /// The level a condition leaves reads as a paper writes it: `{x − 2y, H}`, not
    /// `{x − (2y), H}`; a negative term, or a sum led by one, as a sum
    /// (`x + y − 1`), and only another sum in parentheses.
    #[test]
    fn a_level_puts_only_a_sum_in_parentheses() {
        assert_eq!(difference("x", "2y", "−2y"), "x − 2y");
        assert_eq!(difference("a", "p_x", "−p_x"), "a − p_x");
        assert_eq!(difference("x", "−2y", "2y"), "x + 2y");
        assert_eq!(difference("x", "g/(x − y)", "−g/(x − y)"), "x − g/(x − y)");
        assert_eq!(
            difference("x", "y p_y + y + p_y", "−y p_y − y − p_y"),
            "x − (y p_y + y + p_y)"
        );
        // A sum whose first term is negative reads as a sum, `x + y − 1`, not `x − (−y + 1)`.
        assert_eq!(difference("x", "−y + 1", "y − 1"), "x + y − 1");
    }
}
