//! Denominator atoms ([`VarKind::Denominator`]): a variable named `(D)` stands for the
//! polynomial `D` of the other variables, so that its power `v^{−k}` is `1/D^k` and the ring is
//! `Q[vars][1/D_1, …]`, a subring of the rational functions. Here: the atoms' definitions,
//! division by a product of powers of them (`inverse_by_atoms`, which the parser's division
//! reaches), and the exact zero test by clearing denominators (`cleared`, `vanishes`): with
//! `N = max(0, −lowest exponent of v)`, `P` is zero iff `D^N · P`, that is `(v^N P)(v = D)`,
//! is the zero polynomial, atom after atom. Equal elements may have different terms (`v · D`
//! and `1`), so every decision of zero on a set with atoms goes through [`Poly::vanishes`].

use std::collections::BTreeMap;

use super::Poly;
use crate::error::AlgebraError;
use crate::number::{Coefficient, GaussianRational};
use crate::varset::{Var, VarKind, Vars};

/// How many products of powers of atoms a division tries before it gives up.
const MAX_CANDIDATES: usize = 4096;
/// How many terms a numerator over a common denominator may have and still be divided by the
/// denominators it may share a factor with (a division costs about a map update per term of
/// the quotient and of the divisor: a tenth of a second for 10⁵ terms).
const MAX_REDUCED_TERMS: usize = 200_000;

thread_local! {
    /// The denominator atom whose definition this thread is reading
    /// ([`Poly::denominator_atoms`]), which may not divide by a sum itself.
    static READING_ATOMS: std::cell::RefCell<Option<String>> =
        const { std::cell::RefCell::new(None) };
}

/// An atom, the polynomial it stands for, and the power of that polynomial an element was
/// multiplied by to clear it.
type ClearedAtom<C> = (Var, Poly<C>, i64);

impl<C: Coefficient> Poly<C> {
    /// Why `value` cannot be declared a denominator, if it cannot: it is zero, a single term
    /// (division by it is exact already), not real, holds a radical or divides by a
    /// denominator declared before it, or is a product of those and the radicands times a
    /// term. What [`VarsBuilder::denominator`](crate::VarsBuilder::denominator)
    /// and a system file's `denominators` refuse.
    pub fn denominator_refusal(value: &Self) -> Option<String> {
        let vars = &value.vars;
        // A long denominator is shown by its first terms and its size.
        let shown = value.brief_excerpt();
        if value.is_zero() {
            return Some("a denominator cannot be 0".into());
        }
        if value.is_monomial() {
            return Some(format!(
                "{shown} is a single term: division by it is exact already, so declare only \
                 sums (such as \"x - y\") as denominators"
            ));
        }
        if value.conj() != *value {
            return Some(format!("the denominator {shown} is not real"));
        }
        if vars.radicals().any(|r| value.contains(r)) {
            return Some(format!(
                "the denominator {shown} has a radical in it: a denominator is a polynomial in \
                 the coordinates, momenta and parameters; divide by {shown} where it stands \
                 instead, which a division does through its conjugates"
            ));
        }
        if let Some(atom) = vars.denominators().find(|&a| value.contains(a)) {
            return Some(format!(
                "the denominator {shown} divides by {}, declared before it: a denominator is a \
                 polynomial in the coordinates, momenta and parameters; declare its numerator \
                 instead",
                vars.variable(atom).unicode()
            ));
        }
        if Self::one(vars).checked_div(value).is_ok() {
            return Some(format!(
                "{shown} is a product of the denominators declared before it and the radicands \
                 (times a term): division by it is exact already"
            ));
        }
        None
    }

    /// The three forms a denominator atom of `self` is declared by
    /// ([`VarsBuilder::denominator`](crate::VarsBuilder::denominator)): ASCII that reads back,
    /// text and LaTeX, a harmonic as written (`cos(3φ)`, not `−3 cos φ + 4 cos³φ`).
    pub fn denominator_forms(&self) -> (String, String, String) {
        let (unicode, latex) = self
            .as_harmonic()
            .unwrap_or_else(|| (self.to_string(), self.to_latex()));
        (self.to_ascii(), unicode, latex)
    }

    /// The denominator atoms of `vars` with the polynomials they stand for, in declaration
    /// order (none for a set without them). Refused: a definition that does not read, or reads
    /// as zero, a single term or an expression with atoms (its clearing would be wrong).
    pub fn denominator_atoms(vars: &Vars) -> Result<Vec<(Var, Self)>, AlgebraError> {
        // A definition that divides by a sum (`x + 1/(x − y)`) would be read through the
        // atoms again while they are being read: refused here, at the second entry.
        if let Some(denominator) = READING_ATOMS.with_borrow(Option::clone) {
            return Err(AlgebraError::DenominatorRefused {
                denominator,
                message: "divides by a sum of terms, which a denominator's definition may not"
                    .into(),
            });
        }
        let atoms: Vec<Var> = vars.denominators().collect();
        atoms
            .iter()
            .map(|&v| {
                let text = vars.variable(v).name();
                let invalid = |why: String| AlgebraError::DenominatorRefused {
                    denominator: text.to_string(),
                    message: format!("the denominator {text} {why}"),
                };
                // The definition as given (`VarsBuilder::denominator`), not the name in
                // parentheses it is declared by: an error is placed in what was written.
                let given =
                    (text.strip_prefix('(').and_then(|t| t.strip_suffix(')'))).unwrap_or(text);
                READING_ATOMS.set(Some(text.to_string()));
                let parsed = Self::parse(vars, given);
                READING_ATOMS.set(None);
                let d = parsed.map_err(|e| invalid(format!("does not read: {e}")))?;
                if d.is_zero() || d.is_monomial() {
                    return Err(invalid("is zero or a single term, not a sum".into()));
                }
                if atoms.iter().any(|&w| d.contains(w)) {
                    return Err(invalid("has a denominator of several terms".into()));
                }
                if vars.radicals().any(|w| d.contains(w)) {
                    return Err(invalid("has a radical in it".into()));
                }
                Ok((v, d))
            })
            .collect()
    }

    /// What to declare to divide by `self`, as a refused division says: the polynomial in
    /// ASCII when it is short, its factors otherwise.
    pub(crate) fn declaration(&self) -> String {
        self.declaration_within(8, 80)
    }

    /// [`Poly::declaration`] with room for at most `terms` terms and `chars` characters. A
    /// divisor that is not real (`p_x + iMωx`) cannot be declared (a denominator is real):
    /// `1/D = conj(D)/(D conj(D))` names the real product to declare instead, when `D` has at
    /// most `terms²` terms. A longer one is not multiplied out for a message: its norm is
    /// shown only when short, and the product of `D`'s terms by `conj(D)`'s is the square of
    /// its length (`p_θ/K_{2,1}^{40}`, a divisor of 91 881 terms, took minutes to be refused).
    pub(crate) fn declaration_within(&self, terms: usize, chars: usize) -> String {
        if !self.is_real() {
            let norm = (self.len() <= terms.saturating_mul(terms))
                .then(|| self.checked_mul(&self.conj()).ok())
                .flatten();
            let advice = "it is not real, so it cannot be declared (a denominator is real): \
                          write 1/D as conj(D)/(D conj(D)) and declare the real D conj(D)";
            return match norm.and_then(|n| n.ascii_within(terms, chars)) {
                Some(a) => format!("{advice}: {}", denominators_line(&[a])),
                None => format!("{advice}, or its factors, in [phase_space]"),
            };
        }
        match self.ascii_within(terms, chars) {
            Some(a) => format!(
                "declare it (or its factors) as a denominator: {}",
                denominators_line(&[a])
            ),
            None => "declare its factors as denominators in [phase_space]".into(),
        }
    }

    /// The polynomial in ASCII, as a declaration writes it, when it has at most `terms` terms
    /// and `chars` characters.
    pub(crate) fn ascii_within(&self, terms: usize, chars: usize) -> Option<String> {
        match self.len() <= terms {
            true => Some(self.to_ascii()).filter(|a| a.len() <= chars),
            false => None,
        }
    }

    /// What to declare to divide by a product of powers of `factors` (each in ASCII), as a
    /// refused division says when the divisor is written as one.
    pub(crate) fn factors_declaration(factors: &[String]) -> String {
        match factors.len() {
            1 => format!(
                "declare its factor as a denominator: {}",
                denominators_line(factors)
            ),
            _ => format!(
                "declare its factors as denominators: {}",
                denominators_line(factors)
            ),
        }
    }

    /// Whether the set declares denominator atoms.
    pub fn has_denominator_atoms(vars: &Vars) -> bool {
        vars.denominators().next().is_some()
    }

    /// `1/d` when `d` is a nonzero constant times a monomial times a product of powers of the
    /// atoms' polynomials (`(y − x)²` when `x − y` is an atom) and of radicands, written with
    /// the atoms and the radicals (`1/(x² + y²)` is `r^{−2}` when `r = √(x² + y²)`); `None`
    /// when it is not. The exponents are found from the spans `max − min` of each variable's
    /// exponent, which add in a product (Newton polytopes add); each candidate is checked by
    /// an exact product.
    pub(crate) fn inverse_by_atoms(d: &Self) -> Result<Option<Self>, AlgebraError> {
        let vars = d.vars.clone();
        // Each atom with the power of its variable that divides by its polynomial once: 1 for
        // a denominator, 2 for a radical.
        let atoms: Vec<(Var, Self, i64)> = Self::denominator_atoms(&vars)?
            .into_iter()
            .map(|(v, p)| (v, p, 1))
            .chain(Self::radicals(&vars)?.into_iter().map(|(v, p)| (v, p, 2)))
            .collect();
        if atoms.is_empty() || d.is_zero() || atoms.iter().any(|(v, _, _)| d.contains(*v)) {
            return Ok(None);
        }
        let spans = |p: &Self| -> Vec<i64> {
            vars.vars()
                .map(|v| p.exponent_range(v).map_or(0, |(lo, hi)| hi - lo))
                .collect()
        };
        let target = spans(d);
        let atom_spans: Vec<Vec<i64>> = atoms.iter().map(|(_, a, _)| spans(a)).collect();
        let mut candidates = Vec::new();
        let mut ks = vec![0i64; atoms.len()];
        exponents(&atom_spans, 0, target, &mut ks, &mut candidates);
        for ks in candidates {
            let mut product = Self::one(&vars);
            for ((_, a, _), &k) in atoms.iter().zip(&ks) {
                if k > 0 {
                    product = product.checked_mul(&a.checked_pow(k)?)?;
                }
            }
            let (Some(lead_d), Some(lead_p)) = (d.terms().next(), product.terms().next()) else {
                continue;
            };
            let ratio = d.term(lead_d)?.checked_div(&product.term(lead_p)?)?;
            if ratio.checked_mul(&product)? != *d {
                continue;
            }
            let mut inverse = ratio.checked_pow(-1)?;
            for ((v, _, step), &k) in atoms.iter().zip(&ks) {
                if k > 0 {
                    let power = Self::var(&vars, *v).checked_pow(-k * step)?;
                    inverse = inverse.checked_mul(&power)?;
                }
            }
            return Ok(Some(inverse));
        }
        Ok(None)
    }

    /// The element cleared of its denominators: `Π D^N · self` with every atom replaced by its
    /// polynomial, `N` the largest power of `1/D` in `self` (a polynomial free of atoms; zero
    /// exactly when `self` is zero, since `Q[vars][1/D]` embeds in the rational functions and
    /// multiplying by `D^N ≠ 0` there is injective). With radicals, `self` is first reduced by
    /// `r² = R` ([`Poly::reduce_radicals`]), which leaves each radical to the power 0 or 1.
    /// Without atoms or radicals, `self`.
    pub fn cleared(&self) -> Result<Self, AlgebraError> {
        let reduced = self.reduce_radicals(&self.radical_powers()?)?;
        Ok(reduced.cleared_of_atoms()?.0)
    }

    /// `self` cleared of its denominator atoms alone (its radicals left as they are), and for
    /// each atom with its polynomial `D`, the power `N` of `D` it multiplied by.
    fn cleared_of_atoms(&self) -> Result<(Self, Vec<ClearedAtom<C>>), AlgebraError> {
        let mut p = self.clone();
        let mut powers = Vec::new();
        for (v, d) in Self::denominator_atoms(&self.vars)? {
            let n = -p.low_degree(v).unwrap_or(0).min(0);
            if n > 0 {
                p = p.checked_mul(&Self::var(&self.vars, v).checked_pow(n)?)?;
            }
            p = p.subst(v, &d)?;
            powers.push((v, d, n));
        }
        Ok((p, powers))
    }

    /// The element as a physicist writes it with denominators: its terms collected by their
    /// factors free of the denominators (momenta, parameters, angles: every variable but the
    /// coordinates, the atoms and what an atom's polynomial holds), and each such group, or
    /// parts of it, over a common denominator where that is no longer or divides by less
    /// (`group_shown`): the numerator cleared of the atoms and of negative powers, divided by
    /// each atom's polynomial as often as exact division finds it, then written back over what
    /// is left (`8α/(x + y)² − 8α/(x − y)²` is `−32αxy/((x − y)² (x + y)²)`). The
    /// printer then writes a group with a numerator of several terms as one fraction
    /// (`α(x² + y²)/((x − y)² (x + y)²)`). Since the factors a group is collected by are free
    /// of what its fraction is in, the element is zero exactly when every group is, and a
    /// group that is zero has no numerator: a zero shows as `0`. With radicals, first written
    /// with the least powers of each ([`Poly::with_least_radical_powers`]), and 0 when it is
    /// zero. The same element; without atoms or radicals, `self`.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder()
    ///     .coordinate("x")
    ///     .coordinate("y")
    ///     .momentum("p_x")
    ///     .denominator("x - y").unwrap()
    ///     .denominator("x + y").unwrap()
    ///     .build()
    ///     .unwrap();
    /// let e = |s: &str| Expr::parse(&vars, s).unwrap().over_common_denominators().unwrap();
    /// assert_eq!(e("x/(x - y) - 1").to_string(), "y/(x − y)");
    /// assert_eq!(e("p_x/(x + y) + p_x/(x - y) + 1").to_string(), "2x p_x/((x − y) (x + y)) + 1");
    /// assert_eq!(e("1/(x - y)^2 + 1/(x + y)^2").to_string(), "2(x² + y²)/((x − y)² (x + y)²)");
    /// // As written when that is shorter: over one denominator, three terms.
    /// assert_eq!(e("x/(x - y)^2 + 1/(x + y)").to_string(), "x/(x − y)² + 1/(x + y)");
    /// // Over each atom's own denominator where that is shorter, or as long with fewer
    /// // fractions (the whole over one would be longer).
    /// assert_eq!(
    ///     e("x/(x - y)^2 + 1/(x - y) + x/(x + y)^2 - 1/(x + y)").to_string(),
    ///     "(2x − y)/(x − y)² − y/(x + y)²"
    /// );
    /// ```
    pub fn over_common_denominators(&self) -> Result<Self, AlgebraError> {
        if !Self::has_relations(&self.vars) {
            return Ok(self.clone());
        }
        let reduced = match Self::has_radicals(&self.vars) {
            true if self.vanishes()? => return Ok(Self::zero(&self.vars)),
            true => self.with_least_radical_powers()?,
            false => self.clone(),
        };
        if !Self::has_denominator_atoms(&self.vars) {
            return Ok(reduced);
        }
        let atoms = Self::denominator_atoms(&self.vars)?;
        let inner: Vec<bool> = self
            .vars
            .vars()
            .map(|v| {
                matches!(
                    self.vars.variable(v).kind(),
                    VarKind::Coordinate | VarKind::Denominator
                ) || atoms.iter().any(|(_, d)| d.contains(v))
            })
            .collect();
        let outer = |e: &[i64]| -> Vec<i64> {
            e.iter()
                .zip(&inner)
                .map(|(&k, &i)| if i { 0 } else { k })
                .collect()
        };
        let terms = reduced.terms().map(|t| (t.coeff(), t.exponents()));
        let atoms: Vec<Var> = atoms.into_iter().map(|(v, _)| v).collect();
        let mut out = Vec::with_capacity(reduced.len());
        for group in split_terms(terms, outer).into_values() {
            let shown = Self::group_shown(&self.vars, group, &atoms)?;
            out.extend(shown.terms().map(|t| (t.coeff(), t.exponents())));
        }
        Self::from_terms(&self.vars, out)
    }

    /// The shortest of three ways to write a group of terms that differ only in the
    /// variables of their denominators (the whole group over one denominator where that is
    /// no longer than the others): the terms that divide by the
    /// same powers of the atoms each over their common denominator, reduced, unless that is
    /// longer than they are as written (the printer writes them as one fraction either way:
    /// `98/(x (x − y)³) − 98/(y (x − y)³)` is `−98/(xy (x − y)²)`); then the terms that divide by
    /// the same atoms, to any powers, likewise, where that is shorter, or as long and written
    /// over fewer denominators (`7x²/y² + 20y²/(x − y)² + 20y/(x − y)` is `7x²/y² + 20xy/(x −
    /// y)²`, Calogero's `−2g(x + 2z)/(y − z)² − 2g/(y − z)` is `−2g(x + y + z)/(y − z)²`); or
    /// the whole group over one (`4αy²/(x + y)² + 4αy²/(x − y)² − 4αy/(x + y) + 4αy/(x − y)`
    /// is `16αx²y²/((x − y)² (x + y)²)`).
    fn group_shown(
        vars: &Vars,
        group: Vec<(C, Vec<i64>)>,
        atoms: &[Var],
    ) -> Result<Self, AlgebraError> {
        let as_written = Self::from_terms(vars, group.iter().cloned())?;
        if !atoms.iter().any(|&v| as_written.contains(v)) {
            return Ok(as_written);
        }
        let whole = as_written.over_one_denominator()?;
        let both = (&as_written, &whole);
        let powers = |e: &[i64]| -> Vec<i64> { atoms.iter().map(|v| e[v.index()]).collect() };
        let held = |e: &[i64]| -> Vec<i64> { powers(e).iter().map(|&k| k.signum()).collect() };
        // A part over its denominator is reduced: chosen when it is no longer, or when a
        // factor cancelled (`(x³ − y³)/(x − y)` is `x² + xy + y²`), so that no fraction the
        // printer writes shares a factor with its denominator.
        let depth = |p: &Self| p.denominator_depth(atoms);
        let by_powers = Self::parts_shown(vars, &group, powers, both, |c, p| {
            c.len() <= p.len() || depth(c) < depth(p)
        })?;
        // Combined where shorter, or as long and written with fewer fractions:
        // `−2g(x + y + z)/(y − z)²`, not `−2g(x + 2z)/(y − z)² − 2g/(y − z)`.
        let fractions = |p: &Self| p.denominators_written(atoms);
        let fewer = |a: &Self, b: &Self| {
            a.len() < b.len() || (a.len() == b.len() && fractions(a) < fractions(b))
        };
        let by_atoms = Self::parts_shown(vars, &group, held, both, fewer)?;
        let best = match fewer(&by_atoms, &by_powers) {
            true => by_atoms,
            false => by_powers,
        };
        // One fraction where it is no longer, or divides by less: `−2g(x + y)/(x − y)²`, not
        // `−4gy/(x − y)² − 2g/(x − y)`.
        Ok(
            match whole.len() <= best.len() || depth(&whole) < depth(&best) {
                true => whole,
                false => best,
            },
        )
    }

    /// How many denominators `self` is written over: its distinct powers of the atoms among
    /// its terms (2 for `x/(x − y)² + 1/(x − y)`, 1 for `(2x − y)/(x − y)²`).
    fn denominators_written(&self, atoms: &[Var]) -> usize {
        let powers: std::collections::BTreeSet<Vec<i64>> = self
            .terms()
            .map(|t| atoms.iter().map(|&v| t.exponent(v).min(0)).collect())
            .collect();
        powers.len()
    }

    /// The most a term of `self` divides by the atoms, counted with multiplicity: 3 for
    /// `x/((x − y)² (x + y))`.
    fn denominator_depth(&self, atoms: &[Var]) -> i64 {
        self.terms()
            .map(|t| atoms.iter().map(|&v| (-t.exponent(v)).max(0)).sum())
            .max()
            .unwrap_or(0)
    }

    /// `terms` split into parts by `key`, each part over its common denominator when `better`
    /// says so of it (combined, as written), else as written; summed. `whole` is all the
    /// terms as written and over one denominator, which a single part is.
    fn parts_shown(
        vars: &Vars,
        terms: &[(C, Vec<i64>)],
        key: impl Fn(&[i64]) -> Vec<i64>,
        whole: (&Self, &Self),
        better: impl Fn(&Self, &Self) -> bool,
    ) -> Result<Self, AlgebraError> {
        let parts = split_terms(terms.iter().cloned(), key);
        if let (1, Some(k)) = (parts.len(), parts.keys().next()) {
            let (as_written, combined) = whole;
            let holds_atoms = k.iter().any(|&p| p != 0);
            return Ok(match holds_atoms && better(combined, as_written) {
                true => combined.clone(),
                false => as_written.clone(),
            });
        }
        let mut out = Vec::with_capacity(terms.len());
        for (k, part) in parts {
            let part = Self::from_terms(vars, part)?;
            let combined = match k.iter().any(|&p| p != 0) {
                true => Some(part.over_one_denominator()?).filter(|c| better(c, &part)),
                false => None,
            };
            let shown = combined.unwrap_or(part);
            out.extend(shown.terms().map(|t| (t.coeff(), t.exponents())));
        }
        Self::from_terms(vars, out)
    }

    /// `self` over one common denominator: its numerator cleared of the atoms and of every
    /// negative power (so that it is a polynomial), divided by each atom's polynomial as often
    /// as exact division finds it (`(x² + y²)/(x² + y²)` is 1), times what is left of the
    /// denominator: `Π v^{−N}` for the atoms and the negative powers, each as low as it goes.
    fn over_one_denominator(&self) -> Result<Self, AlgebraError> {
        let (mut numerator, mut powers) = self.cleared_of_atoms()?;
        let negative: Vec<(Var, i64)> = self
            .vars
            .vars()
            .filter_map(|v| {
                let n = -numerator.low_degree(v).unwrap_or(0);
                (n > 0).then_some((v, n))
            })
            .collect();
        if !negative.is_empty() {
            numerator = numerator.checked_mul(&Self::monomial(&self.vars, C::one(), &negative)?)?;
        }
        for (_, d, n) in &mut powers {
            while *n > 0 && numerator.len() <= MAX_REDUCED_TERMS {
                match numerator.quotient_by(d)? {
                    Some(q) => {
                        numerator = q;
                        *n -= 1;
                    }
                    None => break,
                }
            }
        }
        if numerator.is_zero() {
            return Ok(numerator);
        }
        let denominator: Vec<(Var, i64)> = negative
            .into_iter()
            .chain(powers.into_iter().map(|(v, _, n)| (v, n)))
            .filter(|&(_, n)| n > 0)
            .map(|(v, n)| (v, -n))
            .collect();
        numerator.checked_mul(&Self::monomial(&self.vars, C::one(), &denominator)?)
    }

    /// One term of `self` as an element of its own.
    fn term(&self, t: super::Term<'_, C>) -> Result<Self, AlgebraError> {
        let powers: Vec<(Var, i64)> = self.vars.vars().zip(t.exponents()).collect();
        Self::monomial(&self.vars, t.coeff(), &powers)
    }

    /// `self / d` when `d` divides `self` exactly, found by dividing leading terms (in the
    /// lexicographic order of the exponents) and checked by multiplying back; `None` when it
    /// does not divide, or when the division runs past a bound of steps (a Laurent ring need
    /// not end it), which only leaves a fraction unreduced.
    ///
    /// The remainder is kept as a map from monomial to coefficient, so that a step takes its
    /// leading term and subtracts the terms of `t·d` in a logarithmic time each: subtracting
    /// `t·d` from the remainder as a polynomial copied all of it, every step (a bracket of
    /// 10⁵ terms with a radical's `1/r³` took minutes).
    pub(super) fn quotient_by(&self, d: &Self) -> Result<Option<Self>, AlgebraError> {
        if self.root_rules_out(d)? {
            return Ok(None);
        }
        let Some(lead_d) = d.terms().next() else {
            return Ok(None);
        };
        let lead_d = d.term(lead_d)?;
        let mut rest: BTreeMap<Vec<u64>, GaussianRational> = self
            .terms()
            .map(|t| (t.packed().to_vec(), t.coeff().to_gaussian()))
            .collect();
        let mut quotient: Vec<(C, Vec<i64>)> = Vec::new();
        for _ in 0..4 * self.len() + 16 {
            // Terms are sorted by exponent vector in descending lexicographic order: the last
            // key is the leading one.
            let Some((m, c)) = rest.last_key_value() else {
                // Checked, not trusted: the quotient times d is self.
                let quotient = Self::from_terms(&self.vars, quotient)?;
                let back = quotient.checked_mul(d)?;
                return Ok((back == *self).then_some(quotient));
            };
            let lead = Self::packed_term(&self.vars, m, c);
            let t = lead.checked_div(&lead_d)?;
            // A factor that d's variables would need a negative power in: no polynomial
            // quotient.
            if self
                .vars
                .vars()
                .any(|v| d.contains(v) && t.low_degree(v).is_some_and(|e| e < 0))
            {
                return Ok(None);
            }
            // Its leading term is the remainder's, which it takes off.
            let td = t.checked_mul(d)?;
            for term in td.terms() {
                let key = term.packed();
                let c = term.coeff().to_gaussian();
                match rest.get_mut(key) {
                    Some(sum) => {
                        *sum -= c;
                        if sum.is_zero() {
                            rest.remove(key);
                        }
                    }
                    None => {
                        rest.insert(key.to_vec(), -c);
                    }
                }
            }
            quotient.extend(t.terms().map(|term| (term.coeff(), term.exponents())));
        }
        Ok(None)
    }

    /// The single term `c·m` of a packed monomial `m`.
    fn packed_term(vars: &Vars, m: &[u64], c: &GaussianRational) -> Self {
        let c = C::from_gaussian(c).expect("a difference of the field's elements");
        let (q, n) = c.split();
        Self::from_sorted(vars, q, m.to_vec(), vec![n])
    }

    /// Whether `d` certainly does not divide `self`, by the factor theorem: when `d = a·v + r`
    /// for a variable `v` with `a` a nonzero constant and `r` free of `v`, and `self` has no
    /// negative power of `v`, `d` divides `self` only if `self` at `v = −r/a` is zero. One
    /// substitution, where a long division that fails may run many steps first; `false` (the
    /// division decides) when `d` has no such variable.
    fn root_rules_out(&self, d: &Self) -> Result<bool, AlgebraError> {
        let linear = self.vars.vars().find(|&v| {
            d.degree(v) == Some(1)
                && d.low_degree(v) == Some(0)
                && self.low_degree(v).is_none_or(|low| low >= 0)
        });
        let Some(v) = linear else {
            return Ok(false);
        };
        let a = d.derivative(v)?;
        if a.as_constant().is_none() {
            return Ok(false);
        }
        let root = Self::var(&self.vars, v)
            .checked_mul(&a)?
            .checked_sub(d)?
            .checked_div(&a)?;
        Ok(!self.subst(v, &root)?.is_zero())
    }

    /// The exact zero test of the ring with denominator atoms and radicals: whether the element
    /// cleared of its denominators and reduced by its radicals ([`Poly::cleared`]) is zero;
    /// [`Poly::is_zero`] on a set without either. Where [`Poly::is_zero`] asks whether there
    /// are no terms, this asks whether the value is zero once `(D)·(D)⁻¹ = 1` and `r² = R`
    /// are used: `r² − x² − 1` for `r = √(x² + 1)` has terms and vanishes. It can fail where
    /// `is_zero` cannot: clearing multiplies, and may pass the term limit.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder()
    ///     .coordinate("x")
    ///     .coordinate("y")
    ///     .denominator("x - y").unwrap()
    ///     .build()
    ///     .unwrap();
    /// let e = |s: &str| Expr::parse(&vars, s).unwrap();
    /// assert!(e("(x - y)/(x - y) - 1").vanishes().unwrap());
    /// assert!(!e("x/(x - y) - 1").vanishes().unwrap());
    /// assert_eq!(e("x/(x - y) - 1").over_common_denominators().unwrap().to_string(), "y/(x − y)");
    /// ```
    pub fn vanishes(&self) -> Result<bool, AlgebraError> {
        if self.is_zero() {
            return Ok(true);
        }
        if !Self::has_relations(&self.vars) {
            return Ok(false);
        }
        Ok(self.cleared()?.is_zero())
    }
}

/// Terms `(coefficient, exponents)` split by `key` of their exponents, in the key's order.
fn split_terms<C>(
    terms: impl IntoIterator<Item = (C, Vec<i64>)>,
    key: impl Fn(&[i64]) -> Vec<i64>,
) -> BTreeMap<Vec<i64>, Vec<(C, Vec<i64>)>> {
    let mut parts: BTreeMap<Vec<i64>, Vec<(C, Vec<i64>)>> = BTreeMap::new();
    for (c, e) in terms {
        parts.entry(key(&e)).or_default().push((c, e));
    }
    parts
}

/// Every vector of exponents `ks[i..]` whose spans add up to `remaining` exactly, into `out`
/// (at most [`MAX_CANDIDATES`]).
fn exponents(
    spans: &[Vec<i64>],
    i: usize,
    remaining: Vec<i64>,
    ks: &mut Vec<i64>,
    out: &mut Vec<Vec<i64>>,
) {
    if out.len() >= MAX_CANDIDATES {
        return;
    }
    if i == spans.len() {
        if remaining.iter().all(|&r| r == 0) {
            out.push(ks.clone());
        }
        return;
    }
    let most = spans[i]
        .iter()
        .zip(&remaining)
        .filter(|(&s, _)| s > 0)
        .map(|(&s, &r)| r / s)
        .min()
        .unwrap_or(0);
    for k in 0..=most {
        ks[i] = k;
        let rest = remaining
            .iter()
            .zip(&spans[i])
            .map(|(&r, &s)| r - k * s)
            .collect();
        exponents(spans, i + 1, rest, ks, out);
    }
    ks[i] = 0;
}

/// `denominators = ["x - y", "x + y"] in [phase_space]`.
fn denominators_line(texts: &[String]) -> String {
    format!(
        "denominators = [\"{}\"] in [phase_space]",
        texts.join("\", \"")
    )
}

#[cfg(test)]
mod tests {
    use crate::{Expr, Vars};

    /// `x, y, z` with the atoms `x − y` and `x − z`.
    fn three_points_two_atoms() -> Vars {
        Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .coordinate("z")
            .denominator("x - y")
            .unwrap()
            .denominator("x - z")
            .unwrap()
            .build()
            .unwrap()
    }

    #[test]
    fn division_by_powers_of_atoms_and_their_multiples() {
        let vars = three_points_two_atoms();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        assert_eq!(e("1/(x - y)^2").to_string(), "1/(x − y)²");
        assert_eq!(e("3/(2*(y - x))").to_string(), "−3/(2 (x − y))");
        assert_eq!(e("1/((x - y)*(x - z))"), e("1/(x - y) * 1/(x - z)"));
        assert_eq!(e("(x - y)^-2"), e("1/(x - y)^2"));
        assert!(e("x/(x^2*(x - y))*(x - y)*x - 1").vanishes().unwrap());
        assert!(Expr::parse(&vars, "1/(x + y)").is_err());
        assert!(Expr::parse(&vars, "1/(x - y + z)").is_err());
    }

    /// A numerator loses each factor `D` it has, with a root test that rules out the others
    /// at once (`x − y` divides only what vanishes at `x = y`), and the same element either way.
    #[test]
    fn a_numerator_loses_exactly_the_factors_it_has() {
        let vars = three_points_two_atoms();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let reduced = |s: &str| e(s).over_common_denominators().unwrap().to_string();
        assert_eq!(reduced("x^3/(x - y) - y^3/(x - y)"), "x² + xy + y²");
        assert_eq!(
            reduced("(x - y)*(x - z)^2/((x - y)^3*(x - z))"),
            "(x − z)/(x − y)²"
        );
        assert_eq!(reduced("(x^2 + y)/(x - y)"), "(x² + y)/(x − y)");
        // x² − yz vanishes at neither root: nothing to divide.
        assert_eq!(
            reduced("(x^2 - y*z)/((x - y)*(x - z))"),
            "(x² − yz)/((x − y) (x − z))"
        );
        let root = |a: &str, d: &str| e(a).root_rules_out(&e(d)).unwrap();
        assert!(root("x^2 + y", "x - y"));
        assert!(!root("x^2 - y^2", "x - y"));
        assert!(
            !root("x^2 - y^2", "x^2 + y^2"),
            "no variable of degree 1: the division decides"
        );
        assert!(root("z", "x - y"), "free of x, so no multiple of x − y");
    }

    /// Exact division by leading terms gives the quotient of a product back, over Q(i) and
    /// with a negative power of a variable the divisor lacks, and `None` for a product with
    /// a remainder or a quotient that would need a negative power of the divisor's variable.
    #[test]
    fn exact_division_finds_the_quotient_or_none() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .coordinate("z")
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let d = e("x^2 + y^2 - 3*x");
        let q = e("(1 + x + i*y/3 + 2*z)^5 + x^3/z^2");
        let product = q.checked_mul(&d).unwrap();
        assert_eq!(q.len(), 57);
        assert_eq!(product.quotient_by(&d).unwrap(), Some(q));
        let remainder = product.checked_add(&e("y")).unwrap();
        assert_eq!(remainder.quotient_by(&d).unwrap(), None);
        assert_eq!(e("x").quotient_by(&d).unwrap(), None);
        assert_eq!(d.quotient_by(&d).unwrap(), Some(e("1")));
    }

    #[test]
    fn a_denominator_that_is_a_term_is_refused() {
        let vars = Vars::builder()
            .coordinate("x")
            .denominator_unchecked("2*x", "2x", "2 x")
            .build()
            .unwrap();
        let err = Expr::denominator_atoms(&vars).unwrap_err().to_string();
        assert!(err.contains("(2*x) is zero or a single term"), "{err}");
    }

    /// A definition that does not read is placed in the text as given, `x - `, not in the
    /// name the builder wraps it in, `(x - )`, where it was at column 6, a `)` never written.
    #[test]
    fn a_denominator_that_does_not_read_is_placed_in_its_own_text() {
        let vars = Vars::builder()
            .coordinate("x")
            .denominator_unchecked("x - ", "x − ", "x - ")
            .build()
            .unwrap();
        let err = Expr::denominator_atoms(&vars).unwrap_err().to_string();
        assert!(
            err.starts_with("the denominator (x - ) does not read: line 1, column 4: ")
                && err.ends_with("\n  x - \n     ^"),
            "{err}"
        );
    }

    /// A definition that divides by a sum would be read through the atoms while they are
    /// being read (it overflowed the stack): refused, and so is every division by a sum
    /// on the set, which needs the atoms.
    #[test]
    fn a_denominator_that_divides_by_a_sum_is_refused() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .denominator("x - y")
            .unwrap()
            .denominator_unchecked("x + 1/(x - y)", "x + 1/(x − y)", "x + 1/(x - y)")
            .build()
            .unwrap();
        let err = Expr::denominator_atoms(&vars).unwrap_err().to_string();
        assert!(
            err.contains("(x + 1/(x - y)) does not read")
                && err.contains("divides by a sum of terms"),
            "{err}"
        );
        assert!(Expr::parse(&vars, "1/(x - y)").is_err());
    }

    #[test]
    fn clearing_decides_zero() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .denominator("x^2 + y^2")
            .unwrap()
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let f = e("x^2/(x^2 + y^2) + y^2/(x^2 + y^2) - 1");
        assert!(!f.is_zero() && f.vanishes().unwrap());
        let g = e("x^2/(x^2 + y^2) - 1");
        assert!(!g.vanishes().unwrap());
        assert_eq!(g.cleared().unwrap(), e("-y^2"));
        assert_eq!(
            g.over_common_denominators().unwrap().to_string(),
            "−y²/(x² + y²)"
        );
        // The numerator loses the factors it shares with the denominator, not others.
        assert_eq!(f.over_common_denominators().unwrap().to_string(), "0");
        let one = e("x^2/(x^2 + y^2) + y^2/(x^2 + y^2)");
        assert_eq!(one.over_common_denominators().unwrap().to_string(), "1");
        let h = e("(x^2 + y^2)^2*x/(x^2 + y^2)^3");
        assert_eq!(
            h.over_common_denominators().unwrap().to_string(),
            "x/(x² + y²)"
        );
        let k = e("x^3/(x^2 + y^2)");
        assert_eq!(k.over_common_denominators().unwrap(), k);
    }

    /// A sum over one common denominator prints as one fraction, its numerator in
    /// parentheses (the denominator once, not once a term), and its ASCII form reads back;
    /// a long one in LaTeX takes `\left( … \right)`, where a display may break it.
    #[test]
    fn a_common_denominator_prints_once() {
        let vars = three_points_two_atoms();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let f = e("x/(x - y)^2 + y/(x - y)^2");
        assert_eq!(f.to_string(), "(x + y)/(x − y)²");
        assert_eq!(f.to_latex(), r"\frac{x + y}{(x - y)^{2}}");
        assert_eq!(e(&f.to_ascii()), f);
        let g = e("(x + y + z + x*y + 1)/((x - y)*(x - z)^3)");
        assert_eq!(g.to_string(), "(xy + x + y + z + 1)/((x − y) (x − z)³)");
        assert_eq!(
            g.to_latex(),
            r"\left(x y + x + y + z + 1\right) / \left((x - y) (x - z)^{3}\right)"
        );
        assert_eq!(e(&g.to_ascii()), g);
        // One atom to the first power is set apart by the fraction alone: `\frac{1}{x - y}`
        // (it was `\frac{1}{(x - y)}`); a power or a product keeps its parentheses.
        assert_eq!(e("1/(x - y)").to_latex(), r"\frac{1}{x - y}");
        assert_eq!(e("x/(x - y)").to_latex(), r"\frac{x}{x - y}");
        assert_eq!(e("2*x/(x - y)").to_latex(), r"\frac{2 x}{x - y}");
        assert_eq!(e("1/(2*(x - y))").to_latex(), r"\frac{1}{2 (x - y)}");
        assert_eq!(e("1/(x*(x - y))").to_latex(), r"\frac{1}{x (x - y)}");
        // Terms over different denominators print term by term.
        assert_eq!(
            e("1/(x - y) + 1/(x - z)").to_string(),
            "1/(x − y) + 1/(x − z)"
        );
    }
}
