//! A substitution of single terms as a map on packed monomials: what the gathering kernels
//! apply to each term product, so that a sum is formed at a condition in one pass.

use super::Monomial;
use crate::poly::mul::Key;
use crate::varset::Layout;

/// A substitution of single terms `v ↦ c·m_v` as a map on the packed monomials of the term
/// products: a monomial of exponent `e` in `v` is translated by `e·(m_v − v)` and its
/// coefficient multiplied by the integer `(c^e)/d` (with `d` the common content of the powers
/// `c^e` over the exponents the products can have). With several variables, every exponent
/// is read before any translation, so the substitution is simultaneous.
pub(crate) struct MonomialMap {
    vars: Vec<MappedVar>,
}

/// One variable of a [`MonomialMap`].
struct MappedVar {
    field: (usize, u32),
    /// The lowest exponent of the table.
    lowest: i64,
    /// For each exponent from `lowest` on: the translation and the integer factor.
    table: Vec<(Monomial, i64)>,
}

impl MonomialMap {
    /// A map of no variables, to which [`MonomialMap::push`] adds them.
    pub(crate) fn new() -> Self {
        MonomialMap { vars: Vec::new() }
    }

    /// Maps the variable of the field `field`, for the exponents `lowest ..` with their
    /// translations and factors.
    pub(crate) fn push(&mut self, field: (usize, u32), lowest: i64, table: Vec<(Monomial, i64)>) {
        self.vars.push(MappedVar {
            field,
            lowest,
            table,
        });
    }

    /// Whether no variable is mapped.
    pub(crate) fn is_empty(&self) -> bool {
        self.vars.is_empty()
    }

    /// The most term products that one monomial of the image can gather from each monomial
    /// of the preimage's products: the number of exponent combinations.
    pub(super) fn fan_in(&self) -> usize {
        self.vars
            .iter()
            .fold(1usize, |n, v| n.saturating_mul(v.table.len()))
    }

    /// The image of the term `k·m`, or `None` when the factor would pass a word or an
    /// exponent lies outside the tables.
    #[inline]
    pub(super) fn apply<K: Key>(&self, layout: &Layout, m: K, k: i64) -> Option<(K, i64)> {
        let mut image = m;
        let mut k = k;
        for v in &self.vars {
            let e = layout.read(m.as_ref(), v.field);
            let (by, factor) = v.table.get(usize::try_from(e - v.lowest).ok()?)?;
            image = image.translated(&by[..K::WORDS]);
            k = k.checked_mul(*factor)?;
        }
        Some((image, k))
    }
}
