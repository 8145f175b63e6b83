//! Sums of products and of derivative products gathered in one table, and optionally taken at
//! a substitution of single terms (`p_θ ↦ mIω/n`, a resonance): every term product is formed,
//! mapped by the substitution and added to its monomial's sum at once, so neither the
//! products nor the sum before the substitution are ever built. An identity's residual, whose
//! sums all cancel, then costs one pass over the term products and nothing to sort.

use arrayvec::ArrayVec;

use super::gather::{self, Monomial, MonomialMap, Partial, Product};
use super::Poly;
use crate::error::AlgebraError;
use crate::number::{binary_gcd, Coefficient, IntegerRing, Rational};
use crate::varset::Var;

/// One product of a gathered sum: `± a·b`, or `± (∂a/∂v)·b` with `v` given; minus where the
/// flag is `true`.
pub(crate) type Source<'a, C> = (&'a Poly<C>, Option<Var>, &'a Poly<C>, bool);

/// The most products one gathered sum takes (its multipliers and products live on the stack).
pub(super) const MAX_PRODUCTS: usize = 16;

/// The most exponents of one substituted variable that a gathered sum tabulates.
const MAX_MAPPED_EXPONENTS: i64 = 4096;

impl<C: Coefficient> Poly<C> {
    /// [`Poly::sum_of_derivative_products`] with the substitution `subs` applied to the sum
    /// (simultaneously, as [`Poly::subst_many`]): the form of a bracket on a condition, such
    /// as `{f, H}` at a resonance.
    ///
    /// When every value is a single term and the coefficients fit machine words, every term
    /// product is formed, substituted and added in one table, and the sum before the
    /// substitution is never built; otherwise this is the sum, then the substitution.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Vars};
    /// let vars = Vars::builder().coordinate("x").momentum("p").build().unwrap();
    /// let (x, p) = (vars.lookup("x").unwrap(), vars.lookup("p").unwrap());
    /// let q = |s: &str| Poly::<Rational>::parse(&vars, s).unwrap();
    /// // {x p, H} with H = (p² + x²)/2, whose gradient is (∂H/∂x, ∂H/∂p) = (x, p): p² − x²,
    /// // which vanishes on p = x and is 3x² on p = 2x.
    /// let (f, dh_dx, dh_dp) = (q("x*p"), q("x"), q("p"));
    /// let flow = [(&f, x, &dh_dp, false), (&f, p, &dh_dx, true)];
    /// assert!(Poly::sum_of_derivative_products_at(&flow, &[(p, q("x"))]).unwrap().is_zero());
    /// assert_eq!(
    ///     Poly::sum_of_derivative_products_at(&flow, &[(p, q("2*x"))]).unwrap(),
    ///     q("3*x^2")
    /// );
    /// ```
    pub fn sum_of_derivative_products_at(
        terms: &[(&Self, Var, &Self, bool)],
        subs: &[(Var, Self)],
    ) -> Result<Self, AlgebraError> {
        let first = Self::first_factor(terms.first().map(|t| t.0))?;
        for &(f, v, g, _) in terms {
            f.same_vars(g)?;
            first.same_vars(f)?;
            first.vars.checked_index(v)?;
        }
        for (v, value) in subs {
            first.same_vars(value)?;
            first.vars.checked_index(*v)?;
        }
        let sources: Vec<Source<'_, C>> = terms
            .iter()
            .map(|&(f, v, g, negate)| (f, Some(v), g, negate))
            .collect();
        if let Some(sum) = Self::gathered_sum(&sources, subs, gather::MAX_MAPPED_PAIRS)? {
            return Ok(sum);
        }
        Self::sum_of_derivative_products(terms)?.subst_many(subs)
    }

    /// The sum of the `sources` at `subs` in one table, or `None` when that path does not
    /// apply: more than `max_pairs` term products, too many products, monomials too wide, a
    /// coefficient or a product's share of the common content past a word, a value of more
    /// than one term, or exponents that could come near the limit (the general path decides
    /// all of these, and reports what is wrong). The caller has checked the variable sets.
    pub(crate) fn gathered_sum(
        sources: &[Source<'_, C>],
        subs: &[(Var, Self)],
        max_pairs: usize,
    ) -> Result<Option<Self>, AlgebraError> {
        let Some(&(first, ..)) = sources.first() else {
            return Ok(None);
        };
        let vars = &first.vars;
        let layout = vars.layout();
        let limit = vars.limits().max_degree as i64;
        if sources.len() > MAX_PRODUCTS || layout.words > gather::WORDS {
            return Ok(None);
        }
        // The most exponent any term product can reach, and the products' share of the
        // common content.
        let (mut pairs, mut reach) = (0usize, 0i64);
        for &(a, _, b, _) in sources {
            if !a.is_zero() && !b.is_zero() {
                pairs = pairs.saturating_add(a.len().saturating_mul(b.len()));
                reach = reach.max(a.exponent_bound() + b.exponent_bound() + 1);
            }
        }
        if pairs > max_pairs || reach > limit {
            return Ok(None);
        }
        let mut multipliers = [0i64; MAX_PRODUCTS];
        let Some(d) = Self::multipliers(sources, &mut multipliers)? else {
            return Ok(None);
        };
        if d.is_zero() {
            return Ok(Some(Self::zero(vars)));
        }
        let mut products = ArrayVec::<_, MAX_PRODUCTS>::new();
        for (&k, &(a, v, b, _)) in multipliers.iter().zip(sources) {
            if k == 0 {
                continue;
            }
            let (Some(bits_a), Some(bits_b)) = (a.small_bits(), b.small_bits()) else {
                return Ok(None);
            };
            let by = v.map(|v| Partial::new(vars, v));
            products.push(Product::new(
                a.raw_terms(),
                by,
                b.raw_terms(),
                k,
                // Only products and squares gather in Z's words.
                (
                    bits_a + bits_b,
                    v.is_none() && a.real_coefficients() && b.real_coefficients(),
                ),
            ));
        }
        let (map, map_content) = match Self::monomial_map(sources, subs, limit - reach) {
            None => return Ok(None),
            Some(Mapping::Identity) => (None, None),
            Some(Mapping::Map(map, content, unmapped)) => {
                // A first factor free of the substituted variables (the `f` of a flow at a
                // resonance, free of `p_θ`) has the map applied once per term of the other.
                let live = multipliers.iter().zip(unmapped).filter(|(&k, _)| k != 0);
                for (product, (_, free)) in products.iter_mut().zip(live) {
                    product.set_a_unmapped(free);
                }
                (Some(map), Some(content))
            }
        };
        let Some(terms) = gather::sum_of_products(layout, &products, map.as_ref()) else {
            return Ok(None);
        };
        Self::check_terms(vars, terms.coeffs.len())?;
        let content = match map_content {
            Some(c) => &d * &c,
            None => d,
        };
        Ok(Some(Self::from_gathered(vars, content, terms)))
    }

    /// The substitution `subs` as a map on the monomials of the term products of `sources`,
    /// with the content it brings; `Identity` when no substituted variable occurs. `None`
    /// when a value is not a single term with a real integer part that fits a word, the
    /// tables would be too long, a factor would pass a word, or the translated exponents
    /// could pass `room` (what the products leave below the limit).
    fn monomial_map(sources: &[Source<'_, C>], subs: &[(Var, Self)], room: i64) -> Option<Mapping> {
        if subs.is_empty() {
            return Some(Mapping::Identity);
        }
        let mut factors = Factors::default();
        let Some(&(first, ..)) = sources.first() else {
            return Some(Mapping::Identity);
        };
        let vars = &first.vars;
        let layout = vars.layout();
        let mut map = MonomialMap::new();
        let mut content = Rational::one();
        let mut shift = 0i64;
        for (k, (v, value)) in subs.iter().enumerate() {
            if subs[..k].iter().any(|(w, _)| w == v) {
                return None;
            }
            // The exponents of `v` the term products can have: a product's exponent is the
            // sum of its factors', less one where `v` is the variable of the derivative.
            let mut range: Option<(i64, i64)> = None;
            let mut occurs = false;
            for &(a, by, b, _) in sources {
                let (Some((la, ha)), Some((lb, hb))) = (factors.range(a, *v), factors.range(b, *v))
                else {
                    continue;
                };
                occurs |= (la, ha, lb, hb) != (0, 0, 0, 0);
                let down = i64::from(by == Some(*v));
                let (lo, hi) = (la + lb - down, ha + hb);
                range = Some(range.map_or((lo, hi), |(l, h)| (l.min(lo), h.max(hi))));
            }
            let Some((lowest, highest)) = range.filter(|_| occurs) else {
                continue;
            };
            if value.len() != 1 || highest - lowest >= MAX_MAPPED_EXPONENTS {
                return None;
            }
            let n = value.coeffs[0].to_real_i64()?;
            let unit = n == 1 || n == -1;
            if lowest < 0 && !unit {
                return None;
            }
            let q = &value.content;
            let powers: Vec<Rational> = (lowest..=highest)
                .map(|e| q.pow(e))
                .collect::<Option<_>>()?;
            let dv = Rational::content_of(powers.iter());
            // e·(m_v − v), word by word (wrapping: exact, since the fields stay in range).
            let mut step: Monomial = [0; gather::WORDS];
            let mut unit_v = vec![0u64; layout.words];
            layout.unit(v.index(), 1, &mut unit_v);
            for ((s, m), u) in step.iter_mut().zip(value.exp(0)).zip(&unit_v) {
                *s = m.wrapping_sub(*u);
            }
            let mut table = Vec::with_capacity(powers.len());
            for (e, qe) in (lowest..).zip(&powers) {
                let scale = (qe / &dv).numer().to_i64()?;
                // n^e; for e < 0 only n = ±1 gets here, and (±1)^e = (±1)^{|e|}.
                let ne = if n == -1 && e % 2 != 0 {
                    -1
                } else if unit {
                    1
                } else {
                    n.checked_pow(e as u32)?
                };
                let factor = scale.checked_mul(ne)?;
                let by = step.map(|s| s.wrapping_mul(e as u64));
                table.push((by, factor));
            }
            map.push(layout.field(v.index()), lowest, table);
            content = &content * &dv;
            shift += lowest.abs().max(highest.abs()) * value.exponent_bound();
        }
        if map.is_empty() {
            return Some(Mapping::Identity);
        }
        // Which sources have a first factor free of every substituted variable.
        let mut unmapped = [false; MAX_PRODUCTS];
        for (free, &(a, ..)) in unmapped.iter_mut().zip(sources) {
            *free = subs
                .iter()
                .all(|(v, _)| matches!(factors.range(a, *v), None | Some((0, 0))));
        }
        (shift <= room).then_some(Mapping::Map(map, content, unmapped))
    }

    /// The integer multipliers `k_i` of the products (0 for a zero product) and the content
    /// `d` with `±c(a_i)·c(b_i) = d·k_i`, or `None` when a multiplier passes a word. On machine
    /// words `d = 1/D` for the lcm `D` of the contents' denominators: the multipliers need not
    /// be coprime, since the gathered terms are brought to their content at the end anyway.
    /// Contents past words take [`Poly::big_multipliers`], which refuses products whose
    /// coefficients would pass the bound.
    #[inline]
    fn multipliers(
        sources: &[Source<'_, C>],
        out: &mut [i64; MAX_PRODUCTS],
    ) -> Result<Option<Rational>, AlgebraError> {
        match Self::word_multipliers(sources, out) {
            Some(d) => Ok(Some(d)),
            None => Self::big_multipliers(sources, out),
        }
    }

    /// [`Poly::multipliers`] when every content and multiplier fits a machine word, else
    /// `None`.
    fn word_multipliers(
        sources: &[Source<'_, C>],
        out: &mut [i64; MAX_PRODUCTS],
    ) -> Option<Rational> {
        let parts = |q: &Rational| q.small_parts();
        let mut lcm: i64 = 1;
        let mut any = false;
        for &(a, _, b, _) in sources {
            if a.is_zero() || b.is_zero() {
                continue;
            }
            any = true;
            let ((_, da), (_, db)) = (parts(&a.content)?, parts(&b.content)?);
            let den = da.checked_mul(db)?;
            // Both are positive.
            let g = binary_gcd(lcm as u64, den as u64) as i64;
            lcm = lcm.checked_mul(den / g)?;
        }
        if !any {
            return Some(Rational::zero());
        }
        for (k, &(a, _, b, negate)) in out.iter_mut().zip(sources) {
            *k = 0;
            if a.is_zero() || b.is_zero() {
                continue;
            }
            let ((na, da), (nb, db)) = (parts(&a.content)?, parts(&b.content)?);
            // k = ±na·nb·(D/(da·db)).
            let multiple = lcm / (da * db);
            *k = na
                .checked_mul(nb)
                .and_then(|n| n.checked_mul(multiple))
                .and_then(|n| if negate { n.checked_neg() } else { Some(n) })?;
        }
        Some(Rational::new(1, lcm))
    }

    /// [`Poly::multipliers`] with contents past machine words: the common content by rational
    /// gcds, once the products' coefficients are known to stay within the bound
    /// ([`Poly::check_coefficient_bits`]: the fused sums form them here, where `checked_mul`
    /// would check its factors, and a chain of brackets of single terms doubled its
    /// coefficients' bits at every step).
    #[cold]
    #[inline(never)]
    fn big_multipliers(
        sources: &[Source<'_, C>],
        out: &mut [i64; MAX_PRODUCTS],
    ) -> Result<Option<Rational>, AlgebraError> {
        let live = || sources.iter().filter(|s| !s.0.is_zero() && !s.2.is_zero());
        for &(a, _, b, _) in live() {
            Self::check_coefficient_bits(a, b)?;
        }
        let content = |&(a, _, b, negate): &Source<'_, C>| {
            let q = &a.content * &b.content;
            if negate {
                -q
            } else {
                q
            }
        };
        let d = Rational::content_of(live().map(content).collect::<Vec<_>>().iter());
        for (k, source) in out.iter_mut().zip(sources) {
            *k = 0;
            if !source.0.is_zero() && !source.2.is_zero() {
                let Some(m) = (&content(source) / &d).numer().to_i64() else {
                    return Ok(None);
                };
                *k = m;
            }
        }
        Ok(Some(d))
    }
}

/// What a substitution does to the term products of a gathered sum.
enum Mapping {
    /// Nothing: no substituted variable occurs.
    Identity,
    /// The map, the content its factors left out, and which sources have a first factor
    /// free of the substituted variables.
    Map(MonomialMap, Rational, [bool; MAX_PRODUCTS]),
}

/// What a gathered sum reads of its factors, once per distinct factor however many products
/// share it (a flow's `f` enters one product per variable): the exponent ranges of the
/// substituted variables. On the stack: a sum has at most
/// `2 · MAX_PRODUCTS` factors.
struct Factors<'a, C: Coefficient> {
    ranges: [Option<RangeOf<'a, C>>; 2 * MAX_PRODUCTS],
}

/// A factor, a variable, and the range of its exponents there.
type RangeOf<'a, C> = (&'a Poly<C>, Var, Option<(i64, i64)>);

impl<C: Coefficient> Default for Factors<'_, C> {
    fn default() -> Self {
        Factors {
            ranges: [None; 2 * MAX_PRODUCTS],
        }
    }
}

impl<'a, C: Coefficient> Factors<'a, C> {
    /// [`Poly::exponent_range`] of `v` in `p`.
    fn range(&mut self, p: &'a Poly<C>, v: Var) -> Option<(i64, i64)> {
        remembered(
            &mut self.ranges,
            |&(q, w, _)| std::ptr::eq(q, p) && w == v,
            || (p, v, p.exponent_range(v)),
        )
        .2
    }
}

/// The entry of `table` that `is` picks, else the one `make` gives, remembered in the first
/// free place (when there is one).
fn remembered<T: Copy>(
    table: &mut [Option<T>],
    is: impl Fn(&T) -> bool,
    make: impl FnOnce() -> T,
) -> T {
    for entry in table.iter_mut() {
        match entry {
            Some(t) if is(t) => return *t,
            Some(_) => {}
            None => return *entry.insert(make()),
        }
    }
    make()
}
