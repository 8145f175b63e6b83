//! How many terms a power must have, known before any of its products is formed: the affine
//! relations among a polynomial's monomials, and from them a lower bound on the terms of
//! `f^e` that [`Poly::checked_pow`] compares with the term limit before it multiplies.
//!
//! The terms of `f = Σ c_i m_i` to the power `e` lie on the monomials `Π m_i^{a_i}` of the
//! compositions `e = a_1 + … + a_t`, with coefficients `e!/(a_1!…a_t!) Π c_i^{a_i}`. Two
//! compositions meet on one monomial exactly when their difference `r` is a relation,
//! `Σ r_i (1, m_i) = 0`. Where the monomials have no relation every composition is a term of
//! its own. Where they have some, the terms that meet may cancel, unless every coefficient is
//! real or imaginary, `c_i = |c_i| i^{q_i}`, and every relation keeps the phase,
//! `Σ r_i q_i ≡ 0 (mod 4)`: then the compositions that meet add up with one phase, and every
//! monomial of the sumset is a term. The Fock–Darwin ladder function
//! `W = p_x − i p_y + i M (a + b)(x − i y)/2` is such a polynomial, with one relation
//! (`Max · Mby = Mbx · May`), and `W^99` has 8 670 850 terms; multiplied out one factor at a
//! time it met the command line's default limit of 2 000 000 only at `W^68`, after 20 s.

use super::pow::binomial_u128;
use super::Poly;
use crate::number::{Coefficient, IntegerRing, Rational};

/// The affine relations among the monomials of a polynomial's terms: a basis of terms whose
/// monomials are affinely independent (chosen in the terms' order), and each other term's
/// monomial as an affine combination of theirs.
pub(super) struct AffineRelations {
    /// The terms of the basis, by index.
    basis: Vec<usize>,
    /// Each other term, by index, with the coefficients `λ_b` (in the basis's order, summing
    /// to 1; missing ones zero) of `(1, m_j) = Σ λ_b (1, m_b)`.
    dependent: Vec<(usize, Vec<Rational>)>,
}

impl AffineRelations {
    /// Whether the monomials are affinely independent: every composition of a power is then
    /// a monomial of its own.
    pub(super) fn is_empty(&self) -> bool {
        self.dependent.is_empty()
    }
}

impl<C: Coefficient> Poly<C> {
    /// The affine relations among the monomials (exact elimination over Q of the rows
    /// `(1, exponents of m_i)`, each kept with its combination of the basis's rows).
    pub(super) fn affine_relations(&self) -> AffineRelations {
        // Each row of the basis reduced: its pivot column, its values (1 at the pivot, 0 at
        // the pivots before it) and the combination of the basis's rows it is.
        let mut echelon: Vec<(usize, Vec<Rational>, Vec<Rational>)> = Vec::new();
        let (mut basis, mut dependent) = (Vec::new(), Vec::new());
        for (k, term) in self.terms().enumerate() {
            let mut row: Vec<Rational> = std::iter::once(Rational::one())
                .chain(term.exponents().into_iter().map(Rational::from))
                .collect();
            // The row as formed = Σ combination_b · (basis row b) + what is left of it.
            let mut combination = vec![Rational::zero(); basis.len()];
            for (pivot, reduced, made_of) in &echelon {
                let f = row[*pivot].clone();
                if f.is_zero() {
                    continue;
                }
                for (x, y) in row.iter_mut().zip(reduced) {
                    *x -= &f * y;
                }
                for (x, y) in combination.iter_mut().zip(made_of) {
                    *x += &f * y;
                }
            }
            match row.iter().position(|x| !x.is_zero()) {
                None => dependent.push((k, combination)),
                Some(pivot) => {
                    let d = row[pivot].clone();
                    let mut made_of: Vec<Rational> =
                        combination.iter().map(|c| -&(c / &d)).collect();
                    made_of.push(Rational::one() / &d);
                    for x in &mut row {
                        *x = &*x / &d;
                    }
                    basis.push(k);
                    echelon.push((pivot, row, made_of));
                }
            }
        }
        AffineRelations { basis, dependent }
    }

    /// Whether `self^e` is sure to have more than `limit` terms: its
    /// [`power_terms_at_least`](Self::power_terms_at_least) passes the limit. The elimination
    /// that bound needs is skipped where no bound it could give would pass the limit (a basis
    /// has at most one term more than the variables that vary), so that a power within the
    /// limit costs next to nothing more.
    pub(super) fn power_passes(&self, e: usize, limit: usize) -> bool {
        let t = self.len() as u128;
        let varying = self.bounds().iter().filter(|(lo, hi)| lo < hi).count() as u128;
        let e = e as u128;
        let largest = match t <= varying + 1 {
            // All the compositions, when every term may be in the basis.
            true => binomial_u128(e + t - 1, t - 1),
            // Else the compositions of a basis and one more term.
            false => binomial_u128(e + varying + 1, varying + 1),
        };
        largest > limit as u128
            && self
                .power_terms_at_least(e)
                .is_some_and(|n| n > limit as u128)
    }

    /// A number of terms that `self^e` has at least, if one is known from the monomials and
    /// the coefficients' phases alone (module docs). With no relation, the compositions
    /// `C(e + t − 1, t − 1)`, exactly. With relations, where the coefficients are each real
    /// or imaginary and every other term's monomial is made of the basis's with integer
    /// coefficients that keep the phase (so that every relation, an integer combination of
    /// these, keeps it), no terms cancel and every monomial of the compositions is a term:
    /// at least the monomials of the power of the basis and one other term, the largest
    /// such count over the other terms (exact where there is one relation). `None` where
    /// terms may cancel, or where that is not ruled out this way (a coefficient neither real
    /// nor imaginary, a relation that turns the phase, a monomial made of the basis's with
    /// fractions): the power is then formed and counted.
    pub(super) fn power_terms_at_least(&self, e: u128) -> Option<u128> {
        let relations = self.affine_relations();
        if relations.is_empty() {
            let t = self.len() as u128;
            return Some(binomial_u128(e + t - 1, t - 1));
        }
        let phases: Vec<u8> = self
            .coeffs
            .iter()
            .map(quarter_turns)
            .collect::<Option<_>>()?;
        let basis_phases: Vec<u8> = relations.basis.iter().map(|&b| phases[b]).collect();
        let rank = relations.basis.len() as u128;
        let mut at_least = 0;
        for (j, lambda) in &relations.dependent {
            // The relation `(1, m_j) − Σ λ_b (1, m_b)`, in integers, keeps the phase.
            let mut turns = i64::from(phases[*j]);
            let mut raised = 0u128;
            for (l, q) in lambda.iter().zip(&basis_phases) {
                let l = l.is_integer().then(|| l.numer().to_i64()).flatten()?;
                turns -= (l.rem_euclid(4)) * i64::from(*q);
                raised = raised.saturating_add(u128::try_from(l).unwrap_or(0));
            }
            if turns.rem_euclid(4) != 0 {
                return None;
            }
            at_least = at_least.max(sumset_with_one_relation(e, rank, raised));
        }
        Some(at_least)
    }
}

/// The phase of a coefficient real or imaginary, `c = |c| i^q`, as `q` (0 to 3); `None` for
/// one that is neither.
fn quarter_turns<I: IntegerRing>(c: &I) -> Option<u8> {
    let z = c.to_gaussian_integer();
    match (z.re.signum(), z.im.signum()) {
        (1, 0) => Some(0),
        (0, 1) => Some(1),
        (-1, 0) => Some(2),
        (0, -1) => Some(3),
        _ => None,
    }
}

/// The monomials of the `e`-th power of `rank + 1` terms whose monomials have one relation,
/// `r`, whose positive parts add up to `raised` (the relation `(1, m_j) = Σ λ_b (1, m_b)`,
/// `raised = Σ_{λ_b > 0} λ_b`): the compositions of `e` in `rank + 1` parts, `C(e + rank,
/// rank)`, less those that less `r` are compositions too (the compositions that meet lie on
/// lines along `r`, one monomial a line), `C(e − raised + rank, rank)`; as the sum of their
/// difference, `Σ_{k < raised} C(e − k + rank − 1, rank − 1)`, which saturates at `u128::MAX`
/// where the two would.
fn sumset_with_one_relation(e: u128, rank: u128, raised: u128) -> u128 {
    (0..raised.min(e + 1)).fold(0u128, |sum, k| {
        sum.saturating_add(binomial_u128(e - k + rank - 1, rank - 1))
    })
}

#[cfg(test)]
mod tests {
    use super::sumset_with_one_relation;
    use crate::number::{GaussianRational, Rational};
    use crate::poly::Poly;
    use crate::varset::Vars;

    /// The bound counts the monomials of a power of terms with one relation exactly: the
    /// Fock–Darwin `W`'s `W^e` has `(e + 1)(e + 2)²(e + 3)/12` terms, and its bound is that
    /// number for every `e` (formed and counted below `e = 12`); so do sign and phase changes
    /// that keep the relation's phase, a relation with a coefficient 2 (`1 = 2x − x²` of
    /// `1 + x + x²`), and monomials with no relation. Where a relation turns the phase the
    /// terms may cancel (`(x + y + xz − yz)²` loses `xyz`) and no bound is given, nor for a
    /// coefficient neither real nor imaginary, nor where the relation is not made of the basis
    /// with integers.
    #[test]
    fn the_bound_is_the_power_of_terms_with_one_relation() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .parameter("M")
            .parameter("a")
            .parameter("b")
            .coordinate("z")
            .build()
            .unwrap();
        let g = |s: &str| Poly::<GaussianRational>::parse(&vars, s).unwrap();
        let w = g("p_x - i*p_y + i*M*(a + b)*(x - i*y)/2");
        for e in [3u128, 5, 11, 67, 68, 99] {
            let terms = (e + 1) * (e + 2) * (e + 2) * (e + 3) / 12;
            assert_eq!(w.power_terms_at_least(e), Some(terms), "W^{e}");
            if e < 12 {
                assert_eq!(w.checked_pow(e as i64).unwrap().len() as u128, terms);
            }
        }
        assert!(w.power_passes(68, 2_000_000) && !w.power_passes(67, 2_000_000));
        for (f, e) in [
            ("x + y + x*z + y*z + p_x", 6),
            ("x - y - x*z + y*z", 7),
            ("i*x + y + i*x*z + y*z", 5),
            ("1 + x + x^2", 8),
            ("x + y^2 + x*z^2 + y*z", 8),
        ] {
            let f = g(f);
            let formed = f.checked_pow(e).unwrap().len() as u128;
            assert_eq!(f.power_terms_at_least(e as u128), Some(formed), "{f}^{e}");
        }
        let turned = g("x + y + x*z - y*z");
        assert_eq!(turned.power_terms_at_least(2), None);
        assert_eq!(turned.checked_pow(2).unwrap().len(), 8);
        assert_eq!(g("x + y + x*z + (1 + i)*y*z").power_terms_at_least(3), None);
        // (1, 0) = −½ (1, 3) + 3/2 (1, 1): the constant of x³ + x + 1 of the basis x³, x, with
        // halves.
        let halves = Poly::<Rational>::parse(&vars, "x^3 + x + 1").unwrap();
        assert_eq!(halves.power_terms_at_least(3), None);
    }

    /// The count of a power of terms with one relation against its formula, `C(e + rank,
    /// rank) − C(e − raised + rank, rank)`, and at its ends.
    #[test]
    fn one_relation_counts_the_compositions_less_those_along_it() {
        use super::binomial_u128 as c;
        for (e, rank, raised) in [(99, 5, 2), (10, 3, 1), (10, 3, 4), (3, 4, 9), (0, 2, 1)] {
            let less = match e >= raised {
                true => c(e - raised + rank, rank),
                false => 0,
            };
            assert_eq!(
                sumset_with_one_relation(e, rank, raised),
                c(e + rank, rank) - less,
                "{e} {rank} {raised}"
            );
        }
        assert_eq!(sumset_with_one_relation(1 << 40, 60, 4), u128::MAX);
    }
}
