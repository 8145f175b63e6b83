//! Sums of products `Σ ± a_k·b_k`, and of derivative products `Σ ± (∂f_k/∂v_k)·g_k`, in one
//! accumulation: the kernel of the Poisson bracket.
//!
//! Each product with a short factor becomes sorted streams (shifted copies of the long factor;
//! for a derivative, shifted copies of the terms of `f` that contain `v`, scaled by their
//! exponent, so the derivative is never built on its own); all streams are brought to one
//! rational content, merged pairwise like the levels of a tree, and normalised once, instead of
//! normalising every derivative, every product and every partial sum.

use super::gather::{self, MAX_JACOBIAN_PAIRS};
use super::mul::{merge_tree, SMALL_SIDE};
use super::sum_at::MAX_PRODUCTS;
use super::Poly;
use crate::error::{AlgebraError, Misuse};
use crate::number::{Coefficient, IntegerRing, Rational};
use crate::varset::{Layout, Var, VarSet};

/// Sorted term lists with their rational contents, waiting to be summed.
type Streams<C> = Vec<(Rational, Poly<C>)>;

impl<C: Coefficient> Poly<C> {
    /// `Σ_k ± a_k · b_k` (minus where the flag is `true`), exactly as the sum of the products,
    /// computed with one accumulation and one normalization.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Vars};
    /// let vars = Vars::builder().coordinate("x").momentum("p").build().unwrap();
    /// let p = |s: &str| Poly::<Rational>::parse(&vars, s).unwrap();
    /// let (x, px) = (p("x + 1"), p("p^2 - x"));
    /// let sum = Poly::sum_of_products(&[(&x, &px, false), (&px, &px, true)]).unwrap();
    /// assert_eq!(sum, &(&x * &px) - &(&px * &px));
    /// ```
    pub fn sum_of_products(terms: &[(&Self, &Self, bool)]) -> Result<Self, AlgebraError> {
        let first = Self::first_factor(terms.first().map(|t| t.0))?;
        for &(a, b, _) in terms {
            a.same_vars(b)?;
            first.same_vars(a)?;
        }
        // Short products: every term product in one table (each square's pairs once).
        let mut sources = [(first, None, first, false); MAX_PRODUCTS];
        if terms.len() <= MAX_PRODUCTS {
            for (source, &(a, b, negate)) in sources.iter_mut().zip(terms) {
                *source = (a, None, b, negate);
            }
            let sources = &sources[..terms.len()];
            if let Some(sum) = Self::gathered_sum(sources, &[], gather::MAX_PAIRS)? {
                return Ok(sum);
            }
        }
        Self::check_sum_work(terms.iter().map(|&(a, b, _)| (a, b)))?;
        let mut streams: Streams<C> = Vec::new();
        for &(a, b, negate) in terms {
            Self::push_product(&mut streams, a, b, negate)?;
        }
        Self::sum_streams(&first.vars, streams)
    }

    /// `Σ_k ± (∂f_k/∂v_k) · g_k` (minus where the flag is `true`), exactly as the sum of the
    /// products of the derivatives, computed with one accumulation and one normalization: the
    /// Poisson bracket `Σ ∂f/∂q·∂g/∂p − ∂f/∂p·∂g/∂q` is one call.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Vars};
    /// let vars = Vars::builder().coordinate("x").momentum("p").build().unwrap();
    /// let (x, p) = (vars.lookup("x").unwrap(), vars.lookup("p").unwrap());
    /// let q = |s: &str| Poly::<Rational>::parse(&vars, s).unwrap();
    /// let (f, g) = (q("x^2 p"), q("p^3 + x"));
    /// let bracket = Poly::sum_of_derivative_products(&[
    ///     (&f, x, &g.derivative(p).unwrap(), false),
    ///     (&f, p, &g.derivative(x).unwrap(), true),
    /// ])
    /// .unwrap();
    /// assert_eq!(bracket, q("6 x p^3 - x^2"));
    /// ```
    pub fn sum_of_derivative_products(
        terms: &[(&Self, Var, &Self, bool)],
    ) -> Result<Self, AlgebraError> {
        let first = Self::first_factor(terms.first().map(|t| t.0))?;
        let vars = first.vars.clone();
        let mut streams: Streams<C> = Vec::new();
        let limit = vars.limits().max_degree as i64;
        // The exponent bound of the last `f` seen (a bracket passes one `f` many times).
        let mut f_max: Option<(&Self, i64)> = None;
        // The derivatives of `f` to multiply by a long `g` (or by a short one whose product
        // could pass the degree limit), all built first and multiplied once the work of all
        // the products together is known to be within the limit (a short `g`'s streams are
        // shifted copies of terms of `f`). They take little room beside the products.
        let mut products = Vec::new();
        for &(f, v, g, negate) in terms {
            f.same_vars(g)?;
            first.same_vars(f)?;
            vars.checked_index(v)?;
            if f.is_zero() || g.is_zero() {
                continue;
            }
            let fm = match f_max {
                Some((p, m)) if std::ptr::eq(p, f) => m,
                _ => {
                    let m = f.exponent_bound();
                    f_max = Some((f, m));
                    m
                }
            };
            if g.len() <= SMALL_SIDE && fm + 1 + g.exponent_bound() <= limit {
                f.push_derivative_streams(&mut streams, v, g, negate)?;
            } else {
                products.push((f.derivative(v)?, g, negate));
            }
        }
        Self::check_sum_work(products.iter().map(|(d, g, _)| (d, *g)))?;
        for (d, g, negate) in products {
            Self::push_product(&mut streams, &d, g, negate)?;
        }
        Self::sum_streams(&vars, streams)
    }

    /// `Σ_k (∂f/∂q_k·∂g/∂p_k − ∂f/∂p_k·∂g/∂q_k)` over the pairs `(q_k, p_k)`: the sum of the
    /// Jacobian determinants `∂(f, g)/∂(q_k, p_k)`, which is the Poisson bracket `{f, g}` when
    /// the pairs are canonical.
    ///
    /// Short inputs take one pass over their term pairs: both products of derivatives of the
    /// terms `c·m` and `d·n` have the monomial `m·n/(q·p)`, with the coefficient
    /// `c·d·(a_q·b_p − a_p·b_q)`, where `a`, `b` are the exponents in `m`, `n` (for an angle,
    /// `∂/∂θ e^{ikθ} = ik·e^{ikθ}` keeps the monomial and brings a factor `i`). Longer inputs
    /// go through the derivatives of `g` and [`Poly::sum_of_derivative_products`].
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Vars};
    /// let vars = Vars::builder().coordinate("x").momentum("p").build().unwrap();
    /// let (x, p) = (vars.lookup("x").unwrap(), vars.lookup("p").unwrap());
    /// let q = |s: &str| Poly::<Rational>::parse(&vars, s).unwrap();
    /// let bracket = Poly::sum_of_jacobians(&q("x^2 p"), &q("p^3 + x"), &[(x, p)]).unwrap();
    /// assert_eq!(bracket, q("6 x p^3 - x^2"));
    /// ```
    pub fn sum_of_jacobians(
        f: &Self,
        g: &Self,
        pairs: &[(Var, Var)],
    ) -> Result<Self, AlgebraError> {
        f.same_vars(g)?;
        check_pairs(&f.vars, pairs)?;
        if f.is_zero() || g.is_zero() || pairs.is_empty() {
            return Ok(Self::zero(&f.vars));
        }
        if let Some(sum) = Self::short_jacobians(f, g, pairs)? {
            return Ok(sum);
        }
        // Each Jacobian is antisymmetric in (f, g), so the sum vanishes at f = g: past the
        // short path, one comparison of the term lists instead of products that cancel in full
        // ({P_{40,40}, P_{40,40}} of the harmonic rotor took three minutes).
        if f == g {
            return Ok(Self::zero(&f.vars));
        }
        let mut gradient = Vec::with_capacity(pairs.len());
        for &(q, p) in pairs {
            gradient.push((g.derivative(q)?, g.derivative(p)?));
        }
        Self::sum_of_jacobians_with_gradient(f, pairs, &gradient)
    }

    /// [`Poly::sum_of_jacobians`] given the derivatives `(∂g/∂q_k, ∂g/∂p_k)` of `g` for each
    /// pair, worth keeping when `g` (a Hamiltonian, say) enters many sums: one
    /// [`Poly::sum_of_derivative_products`], whose derivatives of `f` are built only to
    /// multiply a long derivative of `g` (a short one's products are shifted copies of the
    /// terms of `f`).
    pub fn sum_of_jacobians_with_gradient(
        f: &Self,
        pairs: &[(Var, Var)],
        gradient: &[(Self, Self)],
    ) -> Result<Self, AlgebraError> {
        let terms = Self::gradient_terms(f, pairs, gradient)?;
        if terms.is_empty() {
            return Ok(Self::zero(&f.vars));
        }
        Self::sum_of_derivative_products(&terms)
    }

    /// [`Poly::sum_of_jacobians_with_gradient`] with the substitution `subs` applied to the
    /// sum: a bracket on a condition, such as `{f, H}` at a resonance, formed term by term
    /// as [`Poly::sum_of_derivative_products_at`] forms it.
    pub fn sum_of_jacobians_with_gradient_at(
        f: &Self,
        pairs: &[(Var, Var)],
        gradient: &[(Self, Self)],
        subs: &[(Var, Self)],
    ) -> Result<Self, AlgebraError> {
        let terms = Self::gradient_terms(f, pairs, gradient)?;
        if terms.is_empty() {
            return Ok(Self::zero(&f.vars));
        }
        Self::sum_of_derivative_products_at(&terms, subs)
    }

    /// The derivative products `∂f/∂q·∂g/∂p` and `−∂f/∂p·∂g/∂q` of a bracket with a kept
    /// gradient of `g`.
    fn gradient_terms<'a>(
        f: &'a Self,
        pairs: &[(Var, Var)],
        gradient: &'a [(Self, Self)],
    ) -> Result<Vec<(&'a Self, Var, &'a Self, bool)>, AlgebraError> {
        if pairs.len() != gradient.len() {
            return Err(AlgebraError::Misuse(Misuse::GradientCount {
                pairs: pairs.len(),
                derivatives: gradient.len(),
            }));
        }
        check_pairs(&f.vars, pairs)?;
        let mut terms = Vec::with_capacity(2 * pairs.len());
        for (&(q, p), (gq, gp)) in pairs.iter().zip(gradient) {
            terms.push((f, q, gp, false));
            terms.push((f, p, gq, true));
        }
        Ok(terms)
    }

    /// [`Poly::sum_of_jacobians`] by gathering the products of the term pairs, or `None` when
    /// the inputs are too long, their monomials too wide, an exponent could pass the limit, or
    /// an angle needs `i` in a ring without it (the general path reports that).
    fn short_jacobians(
        f: &Self,
        g: &Self,
        pairs: &[(Var, Var)],
    ) -> Result<Option<Self>, AlgebraError> {
        let vars = &f.vars;
        let layout = f.layout();
        let w = layout.words;
        let limit = vars.limits().max_degree as i64;
        if !gather::fits(w, f.len().saturating_mul(g.len()))
            || pairs.len() > MAX_JACOBIAN_PAIRS
            || f.exponent_bound() + g.exponent_bound() + 1 > limit
        {
            return Ok(None);
        }
        let (Some(f_bits), Some(g_bits)) = (f.small_bits(), g.small_bits()) else {
            return Ok(None);
        };
        let Some(terms) = gather::jacobians(
            vars,
            (&f.exps, &f.coeffs),
            (&g.exps, &g.coeffs),
            pairs,
            (
                f_bits + g_bits,
                f.real_coefficients() && g.real_coefficients(),
            ),
        ) else {
            return Ok(None);
        };
        Self::check_terms(vars, terms.coeffs.len())?;
        // The primitive parts fit words: only a content past a word can take the sum past
        // the bound on coefficients (the product of two within it is cheap to form first).
        let content = &f.content * &g.content;
        if content.small_parts().is_none() {
            Self::check_coefficient_bits(f, g)?;
        }
        Ok(Some(Self::from_gathered(vars, content, terms)))
    }

    /// The streams of `± (∂self/∂v) · g` for a short `g` whose exponents are known to stay
    /// within the limit: one stream per term of `g`, each the terms of the derivative
    /// translated by the term's monomial and multiplied by its coefficient.
    fn push_derivative_streams(
        &self,
        streams: &mut Streams<C>,
        v: Var,
        g: &Self,
        negate: bool,
    ) -> Result<(), AlgebraError> {
        Self::check_coefficient_bits(self, g)?;
        let d = self.derivative_terms(v)?;
        if d.rows.is_empty() {
            return Ok(());
        }
        let layout = self.layout();
        let w = self.words();
        let mut q = &self.content * &g.content;
        if negate {
            q = -q;
        }
        // The monomials of the stream of term `t` of `g`: each row's monomial times `g`'s,
        // lowered in `v`, as one translation.
        let monomials = |t: usize| {
            let mut by = layout.translation(g.exp(t));
            by[d.word] = by[d.word].wrapping_sub(d.lower);
            let mut exps = Vec::with_capacity(d.rows.len() * w);
            for &k in &d.rows {
                Layout::push_translated(&mut exps, self.exp(k), &by);
            }
            exps
        };
        let Some((last, rest)) = g.coeffs.split_last() else {
            return Ok(());
        };
        for (t, ct) in rest.iter().enumerate() {
            let cs = d.coeffs.iter().map(|c| c.mul(ct)).collect();
            streams.push((q.clone(), Self::raw(&self.vars, monomials(t), cs)));
        }
        // The last stream takes the derivative's coefficients (a monomial `g`, as in a
        // Hamiltonian's gradient, has the integer part 1: nothing to multiply).
        let exps = monomials(rest.len());
        let mut cs = d.coeffs;
        if !last.is_one() {
            cs.iter_mut().for_each(|c| *c = c.mul(last));
        }
        streams.push((q, Self::raw(&self.vars, exps, cs)));
        Ok(())
    }

    /// The streams of `± a·b`: shifted copies of the longer factor when the other is short, or
    /// the product itself.
    fn push_product(
        streams: &mut Streams<C>,
        a: &Self,
        b: &Self,
        negate: bool,
    ) -> Result<(), AlgebraError> {
        if a.is_zero() || b.is_zero() {
            return Ok(());
        }
        let (small, big) = if a.len() <= b.len() { (a, b) } else { (b, a) };
        if small.len() <= SMALL_SIDE {
            // The product below is checked by `checked_mul`; these shifted copies here.
            Self::check_coefficient_bits(a, b)?;
            small.check_product_exponents(big)?;
            let mut q = &a.content * &b.content;
            if negate {
                q = -q;
            }
            for k in 0..small.len() {
                let (exps, coeffs) = big.shifted(small.exp(k), &small.coeffs[k]);
                streams.push((q.clone(), Self::raw(&a.vars, exps, coeffs)));
            }
        } else {
            let p = a.checked_mul(b)?;
            let q = if negate {
                -p.content.clone()
            } else {
                p.content.clone()
            };
            let (exps, coeffs) = p.into_terms();
            streams.push((q, Self::raw(&a.vars, exps, coeffs)));
        }
        Ok(())
    }

    /// The first factor of a sum, which gives its variable set (an empty sum has none).
    pub(super) fn first_factor(first: Option<&Self>) -> Result<&Self, AlgebraError> {
        first.ok_or(AlgebraError::Misuse(Misuse::EmptySum))
    }

    /// The sum of the streams: one content, a tree of merges, one normalization.
    fn sum_streams(vars: &crate::varset::Vars, streams: Streams<C>) -> Result<Self, AlgebraError> {
        if streams.is_empty() {
            return Ok(Self::zero(vars));
        }
        let d = Rational::content_of(streams.iter().map(|(q, _)| q));
        let parts: Vec<Self> = streams
            .into_iter()
            .map(|(q, mut s)| {
                let scale = (&q / &d).numer();
                if !scale.is_one() {
                    s.coeffs
                        .make_mut()
                        .iter_mut()
                        .for_each(|c| *c = c.scale(&scale));
                }
                s
            })
            .collect();
        let total = merge_tree(parts);
        Self::check_terms(vars, total.len())?;
        let (exps, coeffs) = total.into_terms();
        Ok(Self::drop_zeros_and_normalize(vars, d, exps, coeffs))
    }
}

/// Refuses a pair that holds a handle of another variable set, which would name whatever
/// variable stands at its index in `vars` (or none).
fn check_pairs(vars: &VarSet, pairs: &[(Var, Var)]) -> Result<(), AlgebraError> {
    for &(q, p) in pairs {
        vars.checked_index(q)?;
        vars.checked_index(p)?;
    }
    Ok(())
}
