//! Phase spaces: canonical pairs `(q, p)`, planar or angular, and Poisson variables whose
//! brackets are declared (a Lie–Poisson structure such as `{M₁, M₂} = M₃`). The bracket is
//! `{f, g} = Σ_i (∂f/∂q_i ∂g/∂p_i − ∂f/∂p_i ∂g/∂q_i) + Σ_{a<b} {a, b} (∂f/∂a ∂g/∂b − ∂f/∂b ∂g/∂a)`,
//! the second sum over the declared brackets, so `{q, p} = 1` and `{f, H} = df/dt`.
//!
//! A denominator atom `v` (a variable standing for a polynomial `D`, whose negative powers are
//! `1/D^k`) enters as one more declared variable: `{v, z} = {D, z}` for every phase variable
//! `z` and `{v, w} = {D, E}` for two atoms, so that the sum above is the chain rule
//! `∂(v^{−k})/∂z = −k v^{−k−1} ∂D/∂z`. These brackets are a Poisson bracket on the ring with
//! `v` free (`v − D` is a Casimir of it) where the given brackets are polynomials, and the map
//! `v ↦ D` respects it, so no Jacobi check is needed for them; results are decided zero by
//! `Poly::vanishes`.
//!
//! A radical `r` (a variable standing for `√R`) enters the same way with the derivative of the
//! root: `{r, z} = {R, z}/(2r)`, `{r, w} = {R, E}/(2r)` for an atom `w = (E)` and
//! `{r, s} = {R, S}/(4rs)` for two radicals, so that `∂(r^k)/∂z = (k/2) r^{k−2} ∂R/∂z`. With
//! `r` free these brackets are Poisson too: `r² − R` is a Casimir, and in the variables `z`
//! and `c = r² − R` the bracket is the given one with `c` a Casimir, which the change of
//! variables `r = √(c + R)` carries over.
//!
//! A declared bracket's value may hold the atoms and radicals too (the monopole's
//! `{π_x, π_y} = s z/r³`): the stand-ins' brackets are formed from the given ones all the same,
//! and `v − D` and `r² − R` stay Casimirs, so the ideal they generate is kept by the bracket and
//! putting `D` for `v` and `√R` for `r` carries a bracket formed with the stand-ins free to the
//! bracket of the functions (the chain rule). The bracket with the stand-ins free is then no
//! longer Poisson itself (with `r` free the monopole's identity of `π_x, π_y, π_z` is
//! `−3s/r³ + 3s(x² + y² + z²)/r⁵`, zero only by `r² = R`): the Jacobi identity of the phase
//! variables, checked with the stand-ins' brackets and decided by `Poly::vanishes`, is that of
//! the functions, and every result is decided by that test, never by the terms.

use trigpoly::{Expr, GaussianRational, Rational, Var, VarKind, Vars};

use crate::error::{EngineError, JacobiViolation};

/// A canonical pair: a coordinate (or angle) and its momentum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CanonicalPair {
    /// The coordinate `q` (an angle for an angular pair).
    pub q: Var,
    /// The momentum `p`.
    pub p: Var,
}

/// A declared bracket `{a, b} = value` of two phase variables, at least one of them a Poisson
/// variable (the brackets of canonical variables are fixed by their pairs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeclaredBracket {
    /// The first variable.
    pub a: Var,
    /// The second variable.
    pub b: Var,
    /// `{a, b}`, a real function of the variables and parameters: a polynomial, divided by
    /// declared denominators and with declared radicals where the space has them.
    pub value: Expr,
}

/// What a bracket with `g` needs of `g`, worth keeping when `g` (a Hamiltonian, say) enters
/// many brackets: `(∂g/∂q_i, ∂g/∂p_i)` for each canonical pair and, where brackets are
/// declared, `{v, g}`'s declared part `Σ_u {v, u} ∂g/∂u` for each variable `v` they involve,
/// so that `{f, g}` is one fused sum of products of the derivatives of `f` with it.
#[derive(Clone, Debug, Default)]
pub struct Gradient {
    canonical: Vec<(Expr, Expr)>,
    declared: Vec<(Var, Expr)>,
}

impl Gradient {
    /// `(∂g/∂q_i, ∂g/∂p_i)` for each canonical pair.
    pub fn canonical(&self) -> &[(Expr, Expr)] {
        &self.canonical
    }

    /// `(v, Σ_u {v, u} ∂g/∂u)` over the declared brackets, for each variable `v` where it is
    /// not zero.
    pub fn declared(&self) -> &[(Var, Expr)] {
        &self.declared
    }
}

/// A phase space: variables, the canonical pairs among them, the Poisson variables and their
/// declared brackets; the other variables are parameters (constants under the flow). Its
/// invariant: the declared brackets satisfy the Jacobi identity (checked exactly when they are
/// given), so the bracket is a Poisson bracket.
///
/// ```
/// use brackets::PhaseSpace;
/// use trigpoly::{Expr, Vars};
/// let vars = Vars::builder().coordinate("x").momentum("p_x").build().unwrap();
/// let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
/// let x = Expr::parse(&vars, "x").unwrap();
/// let p = Expr::parse(&vars, "p_x").unwrap();
/// assert_eq!(space.bracket(&x, &p).unwrap(), Expr::one(&vars));
/// ```
///
/// The rigid body on so(3)*: `{M₁, M₂} = M₃` and cyclically, whose Casimir `M₁² + M₂² + M₃²`
/// commutes with everything.
///
/// ```
/// use brackets::PhaseSpace;
/// use trigpoly::{Expr, Vars};
/// let vars = Vars::builder().poisson("M1").poisson("M2").poisson("M3").build().unwrap();
/// let e = |s: &str| Expr::parse(&vars, s).unwrap();
/// let space = PhaseSpace::new(&vars, &[])
///     .unwrap()
///     .with_brackets(&[("M1", "M2", e("M3")), ("M2", "M3", e("M1")), ("M3", "M1", e("M2"))])
///     .unwrap();
/// assert_eq!(space.bracket(&e("M1"), &e("M2")).unwrap(), e("M3"));
/// let casimir = e("M1^2 + M2^2 + M3^2");
/// assert!(space.bracket(&casimir, &e("M1 M2 + M3^3")).unwrap().is_zero());
/// // {M₃, M₁} = M₁ is no Lie algebra's: {M₁, {M₂, M₃}} + {M₂, {M₃, M₁}} + {M₃, {M₁, M₂}} = −M₃.
/// let wrong = PhaseSpace::new(&vars, &[])
///     .unwrap()
///     .with_brackets(&[("M1", "M2", e("M3")), ("M2", "M3", e("M1")), ("M3", "M1", e("M1"))]);
/// let Err(brackets::EngineError::Jacobi(violation)) = wrong else { panic!() };
/// assert_eq!(violation.residual, e("-M3"));
/// ```
#[derive(Clone, Debug)]
pub struct PhaseSpace {
    vars: Vars,
    pairs: Vec<CanonicalPair>,
    /// The pairs as `(q, p)` variables, the form the kernels take.
    var_pairs: Vec<(Var, Var)>,
    /// The Poisson variables, in the order of their declaration.
    poisson: Vec<Var>,
    /// The declared brackets that are not zero, each pair once.
    declared: Vec<DeclaredBracket>,
    /// The variables the declared brackets involve, in the order of [`PhaseSpace::coordinates`],
    /// then the denominator atoms.
    involved: Vec<Var>,
    /// The denominator atoms and the polynomials they stand for.
    atoms: Vec<(Var, Expr)>,
    /// The radicals and their radicands.
    radicals: Vec<(Var, Expr)>,
    /// How many of `declared` (the first ones) were given; the rest are the atoms'.
    given: usize,
}

impl PhaseSpace {
    /// A phase space from pairs of names `(q, p)`. A `q` declared as an angle makes an angular
    /// pair; `p` must be a momentum. The variables declared as Poisson variables are phase
    /// variables too, whose brackets are 0 until [`PhaseSpace::with_brackets`] declares them.
    pub fn new(vars: &Vars, pairs: &[(&str, &str)]) -> Result<Self, EngineError> {
        let find = |n: &str| {
            vars.lookup(n).ok_or_else(|| {
                EngineError::Invalid(format!("unknown variable '{n}' in a canonical pair"))
            })
        };
        let mut out = Vec::new();
        for &(q, p) in pairs {
            let (qv, pv) = (find(q)?, find(p)?);
            let qk = vars.variable(qv).kind();
            if !matches!(qk, VarKind::Coordinate | VarKind::Angle) {
                return Err(EngineError::Invalid(format!(
                    "'{q}' must be a coordinate or an angle"
                )));
            }
            if vars.variable(pv).kind() != VarKind::Momentum {
                return Err(EngineError::Invalid(format!("'{p}' must be a momentum")));
            }
            if out
                .iter()
                .any(|c: &CanonicalPair| [c.q, c.p].iter().any(|&v| v == qv || v == pv))
            {
                return Err(EngineError::Invalid(format!(
                    "'{q}' or '{p}' is in two canonical pairs"
                )));
            }
            out.push(CanonicalPair { q: qv, p: pv });
        }
        let mut space = PhaseSpace {
            vars: vars.clone(),
            var_pairs: out.iter().map(|c| (c.q, c.p)).collect(),
            pairs: out,
            poisson: vars
                .vars()
                .filter(|&v| vars.variable(v).kind() == VarKind::Poisson)
                .collect(),
            declared: Vec::new(),
            involved: Vec::new(),
            atoms: Expr::denominator_atoms(vars)?,
            radicals: {
                Expr::check_radicals(vars)?;
                Expr::radicals(vars)?
            },
            given: 0,
        };
        space.declare_atoms()?;
        Ok(space)
    }

    /// Adds the brackets of the denominator atoms and radicals to the declared ones:
    /// `{v, z} = {D, z}` for each phase variable `z`, and `{v, w} = {D, E}` for two atoms, each
    /// formed with the brackets declared before them (the atoms' polynomials have no atoms),
    /// and for a radical the same times the derivative of the root, `1/(2r)`.
    fn declare_atoms(&mut self) -> Result<(), EngineError> {
        let stand_ins: Vec<_> = self.stand_ins().collect();
        if stand_ins.is_empty() {
            return Ok(());
        }
        let mut extra = Vec::new();
        for (k, (v, d, rate)) in stand_ins.iter().enumerate() {
            for z in self.coordinates() {
                let value = self.bracket(d, &Expr::var(&self.vars, z))?;
                extra.push((*v, z, times(value, rate.as_ref())?));
            }
            for (w, e, other) in &stand_ins[k + 1..] {
                let value = times(self.bracket(d, e)?, rate.as_ref())?;
                extra.push((*v, *w, times(value, other.as_ref())?));
            }
        }
        for (a, b, value) in extra {
            if !value.is_zero() {
                self.declared.push(DeclaredBracket { a, b, value });
            }
        }
        self.update_involved();
        Ok(())
    }

    /// The variables that stand for functions of the others, each with that function and the
    /// derivative of the variable by it where it is not 1: the denominator atoms (`v = D`),
    /// then the radicals (`r = √R`, rate `1/(2r)`).
    fn stand_ins(&self) -> impl Iterator<Item = (Var, &Expr, Option<Expr>)> + '_ {
        let atoms = self.atoms.iter().map(|(v, d)| (*v, d, None));
        let radicals = self.radicals.iter().map(|(r, radicand)| {
            let rate = Expr::monomial(
                &self.vars,
                GaussianRational::from(Rational::new(1, 2)),
                &[(*r, -1)],
            )
            .expect("the power −1 is within every limit");
            (*r, radicand, Some(rate))
        });
        atoms.chain(radicals)
    }

    /// The variables the declared brackets involve: the phase variables in their order, then
    /// the atoms and the radicals.
    fn update_involved(&mut self) {
        let declared = &self.declared;
        self.involved = self
            .coordinates()
            .into_iter()
            .chain(self.atoms.iter().map(|(v, _)| *v))
            .chain(self.radicals.iter().map(|(v, _)| *v))
            .filter(|&v| declared.iter().any(|d| d.a == v || d.b == v))
            .collect();
    }

    /// The denominator atoms and the polynomials they stand for, in declaration order.
    pub fn denominator_atoms(&self) -> &[(Var, Expr)] {
        &self.atoms
    }

    /// The radicals and their radicands, in declaration order.
    pub fn radicals(&self) -> &[(Var, Expr)] {
        &self.radicals
    }

    /// Refuses `what` (a command's work) on a space with denominator atoms: its linear algebra
    /// or its evaluation treats the monomials as independent, and with an atom `v` standing for
    /// `D` they are not (`v⁻¹ · D = 1`), so its answer could be wrong. Its callers: the towers;
    /// `rank` differentiates through the atoms ([`Self::derivative`]) and decides its minors by
    /// the exact zero test, `closure` runs its linear algebra on cleared images of its vectors,
    /// which are polynomials (`closure.rs`), and so does `search`, on monomials independent as
    /// functions; a picture of the flow evaluates each atom as its polynomial (`superint plot`).
    pub fn refuse_denominators(&self, what: &str) -> Result<(), EngineError> {
        if self.atoms.is_empty() {
            return Ok(());
        }
        let names: Vec<&str> = self
            .atoms
            .iter()
            .map(|(v, _)| self.vars.variable(*v).unicode())
            .collect();
        Err(EngineError::Invalid(format!(
            "{what} is not supported on a system with denominators ({}): its linear algebra \
             takes monomials as independent, and with 1/D they are not; check, bracket, \
             expand, table, rank, closure, search and plot work there, deciding zero by \
             clearing denominators",
            names.join(", ")
        )))
    }

    /// Refuses `what` (a command's work) on a space with radicals: like
    /// [`Self::refuse_denominators`], for work whose evaluation would take `r²` and `R` for
    /// different functions. Its callers: the towers; check, bracket, expand, table, rank,
    /// closure, search and plot know the radicals.
    pub fn refuse_radicals(&self, what: &str) -> Result<(), EngineError> {
        if self.radicals.is_empty() {
            return Ok(());
        }
        let names: Vec<String> = self
            .radicals
            .iter()
            .map(|(r, radicand)| Expr::radical_definition(*r, radicand))
            .collect();
        Err(EngineError::Invalid(format!(
            "{what} is not supported on a system with radicals ({}): its evaluation takes \
             monomials as independent, and with r² = R they are not; check, bracket, expand, \
             table, rank, closure, search and plot work there, deciding zero by reducing by \
             r² = R",
            names.join(", ")
        )))
    }

    /// The space with the brackets `{a, b} = value` declared, by the variables' names (these
    /// and no others: brackets declared before are replaced); the pairs not given have
    /// bracket 0. A value may divide by declared denominators and hold radicals
    /// (`{π_x, π_y} = s z/r³`). Refused: a pair given twice (in either order), a
    /// variable that is not a phase variable, a pair of two canonical variables (their bracket
    /// is fixed), a value that is not real, and brackets that break the Jacobi identity
    /// `{a, {b, c}} + {b, {c, a}} + {c, {a, b}} = 0`, checked exactly for every triple of
    /// phase variables that has a Poisson variable, the brackets of the denominator atoms and
    /// radicals included ([`EngineError::Jacobi`], with the triple, the residual and the
    /// given bracket with which the triple's identity first fails).
    ///
    /// ```
    /// use brackets::{EngineError, PhaseSpace};
    /// use trigpoly::{Expr, Vars};
    ///
    /// // so(3)*, the Euler top's space: {M1, M2} = M3 and cyclically, no canonical pairs.
    /// let vars = Vars::builder().poisson("M1").poisson("M2").poisson("M3").build()?;
    /// let m = |s: &str| Expr::parse(&vars, s);
    /// let so3 = PhaseSpace::new(&vars, &[])?.with_brackets(&[
    ///     ("M1", "M2", m("M3")?),
    ///     ("M2", "M3", m("M1")?),
    ///     ("M3", "M1", m("M2")?),
    /// ])?;
    /// // |M|² is a Casimir: its bracket with every function is 0.
    /// let casimir = m("M1^2 + M2^2 + M3^2")?;
    /// assert!(so3.bracket(&casimir, &m("M1*M2 + M3^3")?)?.is_zero());
    /// assert_eq!(so3.bracket(&m("M1")?, &m("M2^2")?)?.to_string(), "2 M2 M3");
    /// // {M3, M1} = M3 with the others breaks the Jacobi identity for (M1, M2, M3).
    /// let broken = PhaseSpace::new(&vars, &[])?.with_brackets(&[
    ///     ("M1", "M2", m("M3")?),
    ///     ("M2", "M3", m("M1")?),
    ///     ("M3", "M1", m("M3")?),
    /// ]);
    /// let Err(EngineError::Jacobi(violation)) = broken else {
    ///     panic!("the Jacobi identity fails");
    /// };
    /// assert_eq!(violation.bracket, 2);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_brackets(mut self, brackets: &[(&str, &str, Expr)]) -> Result<Self, EngineError> {
        let vars = self.vars.clone();
        self.declared.clear();
        let mut given: Vec<(Var, Var)> = Vec::new();
        // The place in `brackets` of each declared bracket (those of value 0 are not kept).
        let mut places = Vec::new();
        for (place, (a, b, value)) in brackets.iter().enumerate() {
            let find = |n: &str| {
                vars.lookup(n).ok_or_else(|| {
                    EngineError::Invalid(format!("unknown variable '{n}' in a declared bracket"))
                })
            };
            let (va, vb) = (find(a)?, find(b)?);
            let (ua, ub) = (vars.variable(va).unicode(), vars.variable(vb).unicode());
            for (v, u) in [(va, ua), (vb, ub)] {
                if !self.is_phase_variable(v) {
                    return Err(EngineError::Invalid(format!(
                        "'{u}' is {}, not a phase variable, so its brackets are 0",
                        vars.variable(v).kind().described()
                    )));
                }
            }
            if va == vb {
                return Err(EngineError::Invalid(format!(
                    "{{{ua}, {ua}}} is 0 for every bracket: a variable's bracket with itself \
                     cannot be declared"
                )));
            }
            if !self.poisson.contains(&va) && !self.poisson.contains(&vb) {
                return Err(EngineError::Invalid(format!(
                    "{{{ua}, {ub}}} is a bracket of canonical variables, fixed by their pairs \
                     ({{q, p}} = 1, every other 0); declare Poisson variables to give brackets"
                )));
            }
            if given
                .iter()
                .any(|&(x, y)| (x, y) == (va, vb) || (x, y) == (vb, va))
            {
                return Err(EngineError::Invalid(format!(
                    "{{{ua}, {ub}}} is given twice (a bracket given in one order gives the \
                     other, {{{ub}, {ua}}} = −{{{ua}, {ub}}})"
                )));
            }
            given.push((va, vb));
            if *value.vars() != vars {
                return Err(EngineError::Invalid(format!(
                    "the value of {{{ua}, {ub}}} is over other variables than the phase space's"
                )));
            }
            if value.conj() != *value {
                return Err(EngineError::Invalid(format!(
                    "{{{ua}, {ub}}} = {} is not real: the bracket of two real variables is \
                     real",
                    value.brief_excerpt()
                )));
            }
            if !value.is_zero() {
                self.declared.push(DeclaredBracket {
                    a: va,
                    b: vb,
                    value: value.clone(),
                });
                places.push(place);
            }
        }
        self.given = self.declared.len();
        self.update_involved();
        // The atoms and radicals first: a declared value with `r = √(x² + y²)` in it brings
        // `{p_x, r} = −x/r` into the identity, which a check without their brackets missed.
        self.declare_atoms()?;
        let failures = self.jacobi_failures()?;
        match failures.is_empty() {
            true => Ok(self),
            false => Err(EngineError::Jacobi(self.violation(&failures, &places)?)),
        }
    }

    /// The violation of the Jacobi identity that `failures` ([`Self::jacobi_failures`], not
    /// empty) show, said of the first: its residual, the declared brackets it depends on and,
    /// where several fail, those of them every failing one depends on, shown at the last in
    /// `places` (each declared bracket's place in the list given) of those, or of the first's.
    fn violation(
        &self,
        failures: &[([Var; 3], Expr)],
        places: &[usize],
    ) -> Result<Box<JacobiViolation>, EngineError> {
        let (triple, residual) = &failures[0];
        let [ua, ub, uc] = triple.map(|v| self.vars.variable(v).unicode());
        // Over common denominators and with the least powers of the radicals, as `expand`
        // prints it (`−s/r²`, not `2sx²/r⁴ + 2sy²/r⁴ + 2sz²/r⁴ − 3s/r²`), as it is where that
        // passes a limit; a long residual in part, with its size: in full it was a message of
        // 1.2 MB (its terms stay in `residual`).
        let shown = residual
            .over_common_denominators()
            .unwrap_or_else(|_| residual.clone());
        let mut message = format!(
            "the declared brackets break the Jacobi identity: {{{ua}, {{{ub}, {uc}}}}} + \
             {{{ub}, {{{uc}, {ua}}}}} + {{{uc}, {{{ua}, {ub}}}}} = {}, not 0",
            shown.brief_excerpt()
        );
        let depended = self.depended_on(*triple, residual)?;
        if !depended.is_empty() {
            let all = self.named_brackets(&depended);
            message.push_str(&format!("; it depends on the declared {all}"));
        }
        let narrowed = self.depended_on_by_every_failure(&depended, failures)?;
        let Narrowed {
            compared,
            failing,
            shared,
        } = &narrowed;
        let shown = match shared.len() < depended.len() && !shared.is_empty() {
            true => {
                let identities = match compared == failing {
                    true => format!("the {failing} identities that fail"),
                    false => format!("the first {compared} of the {failing} that fail"),
                };
                // Two wrong entries may break identities that share only a right one, so the
                // inference is said with its premise.
                let which = match shared.len() {
                    1 => "it is that one",
                    _ => "it is one of those",
                };
                message.push_str(&format!(
                    ", and {identities} all depend on {}, on no other of these: if one entry \
                     alone is wrong, {which}",
                    self.named_brackets(shared)
                ));
                shared
            }
            false => &depended,
        };
        Ok(Box::new(JacobiViolation {
            triple: *triple,
            message,
            residual: residual.clone(),
            bracket: places[shown.last().copied().unwrap_or(self.given - 1)],
        }))
    }

    /// The declared brackets at `ks` as a list in words, `{M1, M2}, {M3, γ1} and {γ3, M1}`.
    fn named_brackets(&self, ks: &[usize]) -> String {
        let named: Vec<String> = ks
            .iter()
            .map(|&k| {
                let DeclaredBracket { a, b, .. } = &self.declared[k];
                let [ua, ub] = [a, b].map(|v| self.vars.variable(*v).unicode());
                format!("{{{ua}, {ub}}}")
            })
            .collect();
        match named.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, others)) => format!("{} and {last}", others.join(", ")),
            None => String::new(),
        }
    }

    /// Those of `depended` (the brackets the first of `failures` depends on,
    /// [`Self::depended_on`]) that every failing one depends on, with how many fail: a wrong
    /// bracket breaks only identities that depend on it, so where several fail, it is among
    /// those they share, which narrows the first one's list (a wrong sign in e(3)*'s
    /// `{M1, M2}` breaks two identities, and `{M1, M2}` is the one bracket both depend on).
    /// The first failing identity and [`Self::NARROWED_BY`] more are compared, which bounds
    /// the work on this error's path.
    fn depended_on_by_every_failure(
        &self,
        depended: &[usize],
        failures: &[([Var; 3], Expr)],
    ) -> Result<Narrowed, EngineError> {
        let mut shared = depended.to_vec();
        let others = failures.iter().skip(1).take(Self::NARROWED_BY);
        for (triple, residual) in others.clone() {
            let also = self.depended_on(*triple, residual)?;
            shared.retain(|k| also.contains(k));
        }
        Ok(Narrowed {
            compared: 1 + others.count(),
            failing: failures.len(),
            shared,
        })
    }

    /// How many failing Jacobi identities past the first [`Self::depended_on_by_every_failure`]
    /// compares.
    const NARROWED_BY: usize = 16;

    /// The given brackets that the Jacobi identity of `triple`, whose residual with all of
    /// them is `residual`, depends on: those of two of its variables, whose values it takes
    /// as they are, and those whose leaving out, each alone, changes the residual (a wrong
    /// `{γ1, M2} = γ1` leaves `M1, M2, γ1`'s residual as it is, since `{M1, γ1} = 0`, but
    /// is one of its pairs). One identity cannot tell which of them is wrong (a wrong sign in
    /// any of e(3)*'s nine brackets breaks the identity of `M1, M2, γ1`, which depends on
    /// right ones too), so a file shows the violation at the last of them and names them all.
    fn depended_on(&self, triple: [Var; 3], residual: &Expr) -> Result<Vec<usize>, EngineError> {
        let mut depended = Vec::new();
        for k in 0..self.given {
            let DeclaredBracket { a, b, .. } = &self.declared[k];
            if triple.contains(a) && triple.contains(b) {
                depended.push(k);
                continue;
            }
            let mut without = self.clone();
            without.declared.truncate(self.given);
            without.declared.remove(k);
            without.given = self.given - 1;
            without.update_involved();
            without.declare_atoms()?;
            let changed = without.jacobiator(triple)?.checked_sub(residual)?;
            if !changed.vanishes()? {
                depended.push(k);
            }
        }
        Ok(depended)
    }

    /// `{a, {b, c}} + {b, {c, a}} + {c, {a, b}}`.
    fn jacobiator(&self, [a, b, c]: [Var; 3]) -> Result<Expr, EngineError> {
        let one = |v: Var| Expr::var(&self.vars, v);
        let (fa, fb, fc) = (one(a), one(b), one(c));
        Ok(&(&self.bracket(&fa, &self.bracket(&fb, &fc)?)?
            + &self.bracket(&fb, &self.bracket(&fc, &fa)?)?)
            + &self.bracket(&fc, &self.bracket(&fa, &fb)?)?)
    }

    /// Every triple whose Jacobi identity `{a, {b, c}} + {b, {c, a}} + {c, {a, b}} = 0` fails,
    /// with its residual, of those [`Self::jacobi_triples`] lists (a triple of canonical
    /// variables has constant brackets, so it holds; with it on the coordinates, the bracket
    /// is Poisson): none where the declared brackets are a Poisson bracket.
    fn jacobi_failures(&self) -> Result<Vec<([Var; 3], Expr)>, EngineError> {
        let mut failures = Vec::new();
        for triple in self.jacobi_triples() {
            let residual = self.jacobiator(triple)?;
            if !residual.vanishes()? {
                failures.push((triple, residual));
            }
        }
        Ok(failures)
    }

    /// The triples of distinct phase variables, a Poisson variable among them, whose Jacobi
    /// identity the declared brackets must keep; none where no bracket is declared.
    fn jacobi_triples(&self) -> Vec<[Var; 3]> {
        if self.given == 0 {
            return Vec::new();
        }
        let coords = self.coordinates();
        let n = coords.len();
        let mut triples = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                for k in j + 1..n {
                    let triple = [coords[i], coords[j], coords[k]];
                    if triple.iter().any(|v| self.poisson.contains(v)) {
                        triples.push(triple);
                    }
                }
            }
        }
        triples
    }

    /// The Poisson variables, in the order of their declaration.
    pub fn poisson_variables(&self) -> &[Var] {
        &self.poisson
    }

    /// The declared brackets that are not zero, each pair once, in the order given (not the
    /// denominator atoms', which follow from their polynomials).
    pub fn declared_brackets(&self) -> &[DeclaredBracket] {
        &self.declared[..self.given]
    }

    /// The variables.
    pub fn vars(&self) -> &Vars {
        &self.vars
    }

    /// The canonical pairs.
    pub fn pairs(&self) -> &[CanonicalPair] {
        &self.pairs
    }

    /// The phase-space variables in the order `q_1, …, q_n, p_1, …, p_n`, then the Poisson
    /// variables.
    pub fn coordinates(&self) -> Vec<Var> {
        self.pairs
            .iter()
            .map(|c| c.q)
            .chain(self.pairs.iter().map(|c| c.p))
            .chain(self.poisson.iter().copied())
            .collect()
    }

    /// `∂f/∂z` for a phase variable `z`, through the denominator atoms and radicals by the
    /// chain rule: `∂f/∂z + Σ_v ∂f/∂v · ∂D_v/∂z` over the atoms `v = (D_v)` (an atom stands
    /// for its polynomial, so `f`'s dependence on `z` is also through them), and
    /// `Σ_r ∂f/∂r · ∂R/∂z / (2r)` over the radicals `r = √R`; the partial derivative alone on a
    /// space without either.
    pub fn derivative(&self, f: &Expr, z: Var) -> Result<Expr, EngineError> {
        let partial = f.derivative(z)?;
        if self.atoms.is_empty() && self.radicals.is_empty() {
            return Ok(partial);
        }
        let mut through = Vec::new();
        for (v, d, rate) in self.stand_ins() {
            let (df, dd) = (f.derivative(v)?, d.derivative(z)?);
            if !df.is_zero() && !dd.is_zero() {
                through.push((df, times(dd, rate.as_ref())?));
            }
        }
        let one = Expr::one(&self.vars);
        let terms: Vec<(&Expr, &Expr, bool)> = std::iter::once((&partial, &one, false))
            .chain(through.iter().map(|(df, dd)| (df, dd, false)))
            .collect();
        Ok(Expr::sum_of_products(&terms)?)
    }

    /// Whether `v` is a phase-space variable (not a parameter).
    pub fn is_phase_variable(&self, v: Var) -> bool {
        self.pairs.iter().any(|c| c.q == v || c.p == v) || self.poisson.contains(&v)
    }

    // {f, g} = Σ_i (∂f/∂q_i ∂g/∂p_i − ∂f/∂p_i ∂g/∂q_i) + Σ_{a<b} {a, b} (∂f/∂a ∂g/∂b − ∂f/∂b ∂g/∂a)
    /// The Poisson bracket `{f, g}`: without declared brackets one call to the canonical
    /// kernel `Poly::sum_of_jacobians`; with them, one sum of derivative products with the
    /// gradient of `g`.
    pub fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, EngineError> {
        if !self.declared.is_empty() {
            return self.declared_bracket(f, g);
        }
        Ok(Expr::sum_of_jacobians(f, g, self.var_pairs())?)
    }

    /// `{f, g}` with declared brackets: through the gradient of `g`, kept out of line so that
    /// the canonical bracket compiles as it would alone.
    #[inline(never)]
    fn declared_bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, EngineError> {
        self.bracket_with_gradient(f, &self.gradient(g)?)
    }

    /// The canonical pairs as `(q, p)` variables, the form the kernels take.
    fn var_pairs(&self) -> &[(Var, Var)] {
        &self.var_pairs
    }

    /// What a bracket with `g` needs of `g` ([`Gradient`]), worth keeping when `g` (a
    /// Hamiltonian, say) enters many brackets.
    pub fn gradient(&self, g: &Expr) -> Result<Gradient, EngineError> {
        let canonical = self
            .pairs
            .iter()
            .map(|c| Ok((g.derivative(c.q)?, g.derivative(c.p)?)))
            .collect::<Result<Vec<_>, EngineError>>()?;
        let mut declared = Vec::new();
        if !self.declared.is_empty() {
            let dg: Vec<Expr> = self
                .involved
                .iter()
                .map(|&u| g.derivative(u))
                .collect::<Result<_, _>>()?;
            let d = |u: Var| {
                &dg[self
                    .involved
                    .iter()
                    .position(|&w| w == u)
                    .expect("involved")]
            };
            for &v in &self.involved {
                // {v, g} = Σ_u {v, u} ∂g/∂u over the declared brackets
                let terms: Vec<(&Expr, &Expr, bool)> = self
                    .declared
                    .iter()
                    .filter_map(|e| match (e.a == v, e.b == v) {
                        (true, _) => Some((&e.value, d(e.b), false)),
                        (_, true) => Some((&e.value, d(e.a), true)),
                        _ => None,
                    })
                    .collect();
                let x = Expr::sum_of_products(&terms)?;
                if !x.is_zero() {
                    declared.push((v, x));
                }
            }
        }
        Ok(Gradient {
            canonical,
            declared,
        })
    }

    /// The terms `∂f/∂v · {v, g}` of `{f, g}` with a kept gradient, for the fused kernels.
    fn gradient_terms<'a>(
        &self,
        f: &'a Expr,
        dg: &'a Gradient,
    ) -> Result<Vec<(&'a Expr, Var, &'a Expr, bool)>, EngineError> {
        if dg.canonical.len() != self.pairs.len() {
            return Err(EngineError::Invalid(format!(
                "{} canonical pairs but a gradient of {}",
                self.pairs.len(),
                dg.canonical.len()
            )));
        }
        let mut terms = Vec::with_capacity(2 * self.pairs.len() + dg.declared.len());
        for (&(q, p), (gq, gp)) in self.var_pairs.iter().zip(&dg.canonical) {
            terms.push((f, q, gp, false));
            terms.push((f, p, gq, true));
        }
        for (v, x) in &dg.declared {
            terms.push((f, *v, x, false));
        }
        Ok(terms)
    }

    /// `{f, g}` given the gradient of `g` from [`PhaseSpace::gradient`]: one fused sum of
    /// products of the derivatives of `f` with it (built only to multiply a long entry of the
    /// gradient), normalised once.
    pub fn bracket_with_gradient(&self, f: &Expr, dg: &Gradient) -> Result<Expr, EngineError> {
        if !dg.declared.is_empty() {
            return self.declared_bracket_with_gradient(f, dg);
        }
        Ok(Expr::sum_of_jacobians_with_gradient(
            f,
            self.var_pairs(),
            &dg.canonical,
        )?)
    }

    /// [`PhaseSpace::bracket_with_gradient`] with declared brackets, out of line.
    #[inline(never)]
    fn declared_bracket_with_gradient(&self, f: &Expr, dg: &Gradient) -> Result<Expr, EngineError> {
        Ok(Expr::sum_of_derivative_products(
            &self.gradient_terms(f, dg)?,
        )?)
    }

    /// `{f, g}` given the gradient of `g`, with the substitution `subs` applied (a condition
    /// such as a resonance): the bracket's term products are formed, substituted and added in
    /// one table when the values are single terms, so the bracket before the condition is
    /// never built.
    pub fn bracket_with_gradient_at(
        &self,
        f: &Expr,
        dg: &Gradient,
        subs: &[(Var, Expr)],
    ) -> Result<Expr, EngineError> {
        if dg.declared.is_empty() {
            return Ok(Expr::sum_of_jacobians_with_gradient_at(
                f,
                self.var_pairs(),
                &dg.canonical,
                subs,
            )?);
        }
        Ok(Expr::sum_of_derivative_products_at(
            &self.gradient_terms(f, dg)?,
            subs,
        )?)
    }

    /// Hamilton's vector field of `h`, `ż = {z, h}` for each phase variable `z` in the order
    /// of [`PhaseSpace::coordinates`]: `(q̇_i, ṗ_i) = (∂h/∂p_i, −∂h/∂q_i)` for each pair, with
    /// the declared brackets' part `Σ_u {z, u} ∂h/∂u` added (for the Euler top,
    /// `Ṁ₁ = {M₁, H}`).
    pub fn hamilton_equations(&self, h: &Expr) -> Result<Vec<(Var, Expr)>, EngineError> {
        let mut out = Vec::new();
        for c in &self.pairs {
            out.push((c.q, h.derivative(c.p)?));
        }
        for c in &self.pairs {
            out.push((c.p, -h.derivative(c.q)?));
        }
        for &v in &self.poisson {
            out.push((v, Expr::zero(&self.vars)));
        }
        if !self.declared.is_empty() {
            // A denominator atom is no phase variable: its rate follows from its polynomial's.
            for (v, x) in self.gradient(h)?.declared {
                if let Some((_, z)) = out.iter_mut().find(|(w, _)| *w == v) {
                    *z = &*z + &x;
                }
            }
        }
        Ok(out)
    }
}

/// `e` times a stand-in's rate, or `e` itself where the rate is 1 (none).
fn times(e: Expr, rate: Option<&Expr>) -> Result<Expr, EngineError> {
    match rate {
        Some(rate) => Ok(e.checked_mul(rate)?),
        None => Ok(e),
    }
}

/// The declared brackets that the failing Jacobi identities all depend on
/// ([`PhaseSpace::depended_on`]), of the first that fails and of those compared with it.
struct Narrowed {
    /// How many failing identities were compared, the first among them.
    compared: usize,
    /// How many identities fail.
    failing: usize,
    /// The places of the declared brackets every compared identity depends on.
    shared: Vec<usize>,
}

#[cfg(test)]
mod tests {
    use super::PhaseSpace;
    use trigpoly::{Expr, Vars};

    /// A space built in code with the atom `1/(x − y)`: the chain rule, and the Jacobi
    /// identity of brackets that involve it, decided by clearing.
    #[test]
    fn an_atoms_brackets_are_the_chain_rule_and_poisson() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .denominator("x - y")
            .unwrap()
            .build()
            .unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        assert_eq!(space.denominator_atoms().len(), 1);
        assert!(space.declared_brackets().is_empty());
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let b = |f: &Expr, g: &Expr| space.bracket(f, g).unwrap();
        assert_eq!(b(&e("1/(x - y)"), &e("p_x")), e("-1/(x - y)^2"));
        assert_eq!(b(&e("1/(x - y)^2"), &e("p_y")), e("2/(x - y)^3"));
        // {x/(x − y), p_x} = −y/(x − y)², written otherwise by the chain rule.
        let d = &b(&e("x/(x - y)"), &e("p_x")) - &e("-y/(x - y)^2");
        assert!(!d.is_zero() && d.vanishes().unwrap());
        let (f, g, h) = (
            e("p_x^2/(x - y)"),
            e("x p_y + 1/(x - y)^2"),
            e("p_x p_y/(x - y)"),
        );
        let jacobi = &(&b(&f, &b(&g, &h)) + &b(&g, &b(&h, &f))) + &b(&h, &b(&f, &g));
        assert!(jacobi.vanishes().unwrap());
        assert!(space.refuse_denominators("a test").is_err());
    }

    /// A space built in code with the radical `r = √(x² + y²)` beside the atom `1/(x − y)`:
    /// the derivative of the root, brackets of the radical with the atom, the Jacobi identity
    /// of brackets that involve both, and dependent radicals refused.
    #[test]
    fn a_radicals_brackets_are_the_chain_rule_and_poisson() {
        let builder = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .denominator("x - y")
            .unwrap();
        let vars = builder.clone().radical("r", "x^2 + y^2").build().unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        assert_eq!(space.radicals().len(), 1);
        assert_eq!(space.denominator_atoms().len(), 1);
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let b = |f: &Expr, g: &Expr| space.bracket(f, g).unwrap();
        assert_eq!(b(&e("r"), &e("p_x")), e("x/r"));
        assert_eq!(b(&e("1/r"), &e("p_y")), e("-y/r^3"));
        assert!((&b(&e("r^2"), &e("p_x")) - &e("2x")).vanishes().unwrap());
        let x = vars.lookup("x").unwrap();
        assert_eq!(space.derivative(&e("r"), x).unwrap(), e("x/r"));
        let (f, g, h) = (
            e("p_x^2/r + 1/(x - y)"),
            e("x p_y r + y/(x - y)^2"),
            e("p_x p_y/r/(x - y)"),
        );
        let jacobi = &(&b(&f, &b(&g, &h)) + &b(&g, &b(&h, &f))) + &b(&h, &b(&f, &g));
        assert!(jacobi.vanishes().unwrap());
        assert!(space.refuse_radicals("a test").is_err());
        let twice = builder
            .radical("r", "x^2 + y^2")
            .radical("s", "9x^2 + 9y^2")
            .build()
            .unwrap();
        assert!(PhaseSpace::new(&twice, &[("x", "p_x"), ("y", "p_y")]).is_err());
    }

    /// A declared bracket whose value holds a radical: `{u, x} = r` for `r = √(x² + y²)`
    /// breaks the Jacobi identity through `{p_x, r} = x/r`, and is refused with that
    /// residual (the check ran before the radical had brackets, so `r` was a constant in it,
    /// and the space was accepted); `{u, y} = r` with `r = √(u² + 1)`, a function of `u`
    /// alone, holds and is kept.
    #[test]
    fn the_jacobi_identity_counts_the_brackets_of_a_radical_in_a_declared_value() {
        let builder = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .poisson("u");
        let pairs = [("x", "p_x"), ("y", "p_y")];
        let vars = builder.clone().radical("r", "x^2 + y^2").build().unwrap();
        let r = Expr::parse(&vars, "r").unwrap();
        let refused = PhaseSpace::new(&vars, &pairs)
            .unwrap()
            .with_brackets(&[("u", "x", r)]);
        let Err(crate::EngineError::Jacobi(violation)) = refused else {
            panic!("{{u, x}} = r breaks the Jacobi identity");
        };
        assert_eq!(violation.residual, Expr::parse(&vars, "-x/r").unwrap());
        let vars = builder.radical("r", "u^2 + 1").build().unwrap();
        let r = Expr::parse(&vars, "r").unwrap();
        let kept = PhaseSpace::new(&vars, &pairs)
            .unwrap()
            .with_brackets(&[("u", "y", r)]);
        assert!(kept.is_ok());
    }

    /// The Jacobi identity of so(3) and `{M₁, x} = 1` fails for `(x, M₂, M₃)`, through
    /// `{x, {M₂, M₃}} = {x, M₁}`: the bracket to blame is the last, `{M₁, x}`, with which the
    /// identity first fails as the brackets are added in turn, not `{M₂, M₃}`, the one the
    /// triple's variables share (the brackets of value 0 count in the places too).
    #[test]
    fn a_jacobi_violation_names_the_bracket_that_breaks_it() {
        let vars = Vars::builder()
            .coordinate("x")
            .momentum("p_x")
            .poisson("M1")
            .poisson("M2")
            .poisson("M3")
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let brackets = [
            ("M1", "M2", e("M3")),
            ("M2", "M3", e("M1")),
            ("M3", "M1", e("M2")),
            ("M2", "x", e("0")),
            ("M1", "x", e("1")),
        ];
        let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
        let Err(crate::EngineError::Jacobi(violation)) = space.clone().with_brackets(&brackets)
        else {
            panic!("{{M1, x}} = 1 breaks the Jacobi identity");
        };
        assert_eq!(violation.bracket, 4);
        assert!(space.with_brackets(&brackets[..4]).is_ok());
    }

    /// One wrong bracket among many right ones that breaks more identities than are compared:
    /// `{u, v_i} = v_i` (a Lie algebra: `u` scales the commuting `v_i`) with a wrong
    /// `{v1, v2} = u` breaks the identity of `u, v1, v2` and of `v1, v2, v_j` for each of the
    /// other 18: the first 17 of the 19 compared share `{v1, v2}` alone, and the message says
    /// that it compared only those.
    #[test]
    fn a_jacobi_violation_with_more_failures_than_compared_says_so() {
        let names: Vec<String> = (1..=20).map(|i| format!("v{i}")).collect();
        let vars = names
            .iter()
            .fold(Vars::builder().poisson("u"), |b, v| b.poisson(v))
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let mut brackets: Vec<(&str, &str, Expr)> =
            names.iter().map(|v| ("u", v.as_str(), e(v))).collect();
        assert!(PhaseSpace::new(&vars, &[])
            .unwrap()
            .with_brackets(&brackets)
            .is_ok());
        brackets.push(("v1", "v2", e("u")));
        let Err(crate::EngineError::Jacobi(violation)) = PhaseSpace::new(&vars, &[])
            .unwrap()
            .with_brackets(&brackets)
        else {
            panic!("{{v1, v2}} = u breaks the Jacobi identity");
        };
        assert_eq!(violation.bracket, 20);
        assert!(
            violation.message.ends_with(
                ", and the first 17 of the 19 that fail all depend on {v1, v2}, on no other \
                 of these: if one entry alone is wrong, it is that one"
            ),
            "{}",
            violation.message
        );
    }
}
