//! Products of short polynomials by gathering: every term product goes into one buffer, which is
//! sorted once and whose equal monomials are combined. For inputs of a handful of terms each
//! (the generators of an algebra, their squares and brackets) this costs less than shifting and
//! merging, which allocates a polynomial per term and merges them pairwise.
//!
//! Three kernels share the buffers: [`product`], [`square`] and [`jacobians`] (the short
//! Poisson bracket). Each runs with monomials of exactly the layout's width (one to
//! [`WORDS`] words, known at compile time), and first in a [`WordGather`], which keeps every
//! term product exactly in the ring's wide form (`i128` per component) when the coefficients
//! fit machine words, as they do for such inputs; [`Gather`] keeps ring elements, for
//! coefficients of any size.

use super::mul::Key;
use crate::number::{Integer, IntegerRing};
use crate::varset::{Layout, Var, VarKind, VarSet};

/// The terms a kernel gathered: sorted, distinct, nonzero.
pub(crate) struct Gathered<I> {
    pub(crate) exps: Vec<u64>,
    pub(crate) coeffs: Vec<I>,
    /// `Some(d)` when the sums were divided by `d` (their gcd, with the sign of the leading
    /// one), which leaves them primitive with a positive lead; `None` when they are as they
    /// came, and still to be normalised.
    pub(crate) divisor: Option<Integer>,
}

/// Monomials of at most this many words take this path.
pub(crate) const WORDS: usize = 4;

/// Sums at a substitution ([`MonomialMap`]) of at most this many term pairs take this path:
/// their sums mostly cancel, so the table is all they need.
pub(crate) const MAX_MAPPED_PAIRS: usize = 1 << 20;

/// Products of at most this many term pairs take this path.
pub(crate) const MAX_PAIRS: usize = 256;

/// The most pairs of variables [`jacobians`] takes (every pair of a phase space whose
/// monomials fit [`WORDS`] words, with room to spare).
pub(crate) const MAX_JACOBIAN_PAIRS: usize = 16;

/// Whether a product of `pairs` term pairs of monomials of `words` words takes this path.
pub(crate) fn fits(words: usize, pairs: usize) -> bool {
    words <= WORDS && pairs <= MAX_PAIRS
}

/// A packed monomial padded to [`WORDS`] words.
pub(crate) type Monomial = [u64; WORDS];

/// One pair of variables `(q, p)` of a sum of Jacobians, as [`jacobians`] reads it.
#[derive(Clone, Copy, Default)]
pub(crate) struct JacobianPair {
    /// The field of `q` (word, shift).
    pub(crate) q: (usize, u32),
    /// The field of `p`.
    pub(crate) p: (usize, u32),
    /// What both derivatives take off a monomial: one in the field of each variable that is
    /// not an angle.
    pub(crate) lower: Monomial,
    /// Factors `i` the derivatives bring, one per angle.
    pub(crate) turns: u32,
}

impl JacobianPair {
    /// The pair `(q, p)` of `vars`, whose monomials fit [`WORDS`] words.
    #[inline]
    pub(crate) fn new(vars: &VarSet, q: Var, p: Var) -> Self {
        let layout = vars.layout();
        let mut lower: Monomial = [0; WORDS];
        let mut turns = 0;
        for v in [q, p] {
            if vars.variable(v).kind() == VarKind::Angle {
                turns += 1;
            } else {
                let (word, shift) = layout.field(v.index());
                lower[word] = lower[word].wrapping_add(1 << shift);
            }
        }
        JacobianPair {
            q: layout.field(q.index()),
            p: layout.field(p.index()),
            lower,
            turns,
        }
    }
}

/// Calls `$f::<[u64; N], _>(args)` with `N` = `$words` (1 to [`WORDS`]).
macro_rules! by_width {
    ($words:expr, $f:ident, $($arg:expr),*) => {
        match $words {
            1 => $f::<[u64; 1], _>($($arg),*),
            2 => $f::<[u64; 2], _>($($arg),*),
            3 => $f::<[u64; 3], _>($($arg),*),
            _ => $f::<[u64; WORDS], _>($($arg),*),
        }
    };
}

/// The product of two term lists, sorted, combined, zeros dropped. The caller has checked
/// that every exponent of the product stays within its field.
pub(crate) fn product<I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
) -> Gathered<I> {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, product_of_width, layout, a, b)
}

/// The square of a term list, from the `n(n + 1)/2` products `c_i²·m_i²` and `2c_ic_j·m_im_j`
/// (`i < j`), sorted, combined, zeros dropped. The caller has checked the exponents.
pub(crate) fn square<I: IntegerRing>(layout: &Layout, a: (&[u64], &[I])) -> Gathered<I> {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, square_of_width, layout, a)
}

/// `Σ_k ∂(f, g)/∂(q_k, p_k)` over the `pairs`, from the term pairs: both products of
/// derivatives of the terms `c·m` and `d·n` have the monomial `m·n/(q·p)`, with the
/// coefficient `c·d·(a_q·b_p − a_p·b_q)·iᵗ`, where `a`, `b` are the exponents in `m`, `n` and
/// `t` counts the angles of the pair. `None` when a coefficient does not fit a word or an
/// angle needs `i` in a ring without it (the general path handles both). The caller has
/// checked the exponents.
pub(crate) fn jacobians<I: IntegerRing>(
    layout: &Layout,
    f: (&[u64], &[I]),
    g: (&[u64], &[I]),
    pairs: &[JacobianPair],
) -> Option<Gathered<I>> {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, jacobians_of_width, layout, f, g, pairs)
}

/// A derivative `∂/∂v` as the kernels apply it to a packed monomial `c·m` of exponent `e` in
/// `v`: the coefficient times `e` (and `i` for an angle), the field of `v` lowered by one
/// (kept for an angle, since `∂/∂θ e^{ikθ} = ik·e^{ikθ}`).
#[derive(Clone, Copy)]
pub(crate) struct Partial {
    /// The field of `v` (word, shift).
    field: (usize, u32),
    /// What the derivative takes off a monomial: one in the field of `v`, or nothing for an
    /// angle.
    lower: Monomial,
    /// Factors `i`: 1 for an angle, else 0.
    turns: u32,
}

impl Partial {
    /// `∂/∂v` in `vars`.
    pub(crate) fn new(vars: &VarSet, v: Var) -> Self {
        let field = vars.layout().field(v.index());
        let angle = vars.variable(v).kind() == VarKind::Angle;
        let mut lower = [0; WORDS];
        if !angle {
            lower[field.0] = 1 << field.1;
        }
        Partial {
            field,
            lower,
            turns: u32::from(angle),
        }
    }
}

/// One product of a [`sum_of_products`]: `k·a·b`, or `k·(∂a/∂v)·b`, from the term lists of
/// its factors and an integer multiplier `k ≠ 0`. A square (`b` is `a`) gathers each pair of
/// terms once.
#[derive(Clone, Copy)]
pub(crate) struct Product<'a, I> {
    a: (&'a [u64], &'a [I]),
    by: Option<Partial>,
    b: (&'a [u64], &'a [I]),
    k: i64,
    /// The [`small_bits`] of `a` and of `b` together.
    ab_bits: u32,
    /// Whether `a` is free of the variables a [`MonomialMap`] substitutes: then the image
    /// of each term of `b` (divided by `v` for a derivative) holds for every term of `a`
    /// with it, and is found once per term of `b`.
    a_unmapped: bool,
}

impl<'a, I> Product<'a, I> {
    /// `k·a·b`, or `k·(∂a/∂v)·b` when `by` is the derivative, where the coefficients of `a`
    /// and `b` fit words and take at most `ab_bits` bits together ([`small_bits`]).
    pub(crate) fn new(
        a: (&'a [u64], &'a [I]),
        by: Option<Partial>,
        b: (&'a [u64], &'a [I]),
        k: i64,
        ab_bits: u32,
    ) -> Self {
        Product {
            a,
            by,
            b,
            k,
            ab_bits,
            a_unmapped: false,
        }
    }

    /// Marks `a` free (or not) of the variables of the map the sum is taken at.
    pub(crate) fn set_a_unmapped(&mut self, free: bool) {
        self.a_unmapped = free;
    }

    /// Whether this is the square of a term list.
    fn is_square(&self) -> bool {
        self.by.is_none() && std::ptr::eq(self.a.1, self.b.1) && std::ptr::eq(self.a.0, self.b.0)
    }

    /// The most term products it gathers: `n(n + 1)/2` for a square, else `n·m`.
    pub(crate) fn pairs(&self) -> usize {
        let n = self.a.1.len();
        if self.is_square() {
            n * (n + 1) / 2
        } else {
            n.saturating_mul(self.b.1.len())
        }
    }

    /// The most of its term products that share a monomial: a term of one factor and the
    /// monomial fix the term of the other.
    fn per_monomial(&self) -> usize {
        self.a.1.len().min(self.b.1.len())
    }
}

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
    fn fan_in(&self) -> usize {
        self.vars
            .iter()
            .fold(1usize, |n, v| n.saturating_mul(v.table.len()))
    }

    /// The image of the term `k·m`, or `None` when the factor would pass a word or an
    /// exponent lies outside the tables.
    #[inline]
    fn apply<K: Key>(&self, layout: &Layout, m: K, k: i64) -> Option<(K, i64)> {
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

/// `Σ_k k·a_k·b_k` (or `k·(∂a_k/∂v_k)·b_k`) over the products, mapped by `map` when given,
/// sorted, combined, zeros dropped: every term product of every pair in one table. `None`
/// when a product could pass the `i128` sums (the general path handles it). The caller has checked the exponents, before and after the
/// map.
pub(crate) fn sum_of_products<I: IntegerRing>(
    layout: &Layout,
    products: &[Product<'_, I>],
    map: Option<&MonomialMap>,
) -> Option<Gathered<I>> {
    debug_assert!(layout.words <= WORDS);
    by_width!(
        layout.words,
        sum_of_products_of_width,
        layout,
        products,
        map
    )
}

fn sum_of_products_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    products: &[Product<'_, I>],
    map: Option<&MonomialMap>,
) -> Option<Gathered<I>> {
    let bias = K::load(layout.one());
    let (mut n, mut per_monomial, mut ab_bits) = (0usize, 0usize, 0);
    for p in products {
        n = n.saturating_add(p.pairs());
        per_monomial = per_monomial.saturating_add(p.per_monomial());
        ab_bits = ab_bits.max(p.ab_bits);
    }
    if let Some(map) = map {
        per_monomial = per_monomial.saturating_mul(map.fan_in());
    }
    let mut words = WordGather::<K, I>::new(n, ab_bits, per_monomial)?;
    for p in products {
        let k = p.k;
        let all = match (map, p.by) {
            (Some(map), by) if p.a_unmapped => mapped_pairs(
                layout,
                p.a,
                by,
                p.b,
                &bias,
                map,
                |m, x, y, f, turns| match k.checked_mul(f) {
                    Some(k) => words.push(m, x, y, k, turns),
                    None => false,
                },
            ),
            (_, Some(by)) => derivative_pairs(layout, p.a, by, p.b, &bias, |m, x, y, e, turns| {
                match k.checked_mul(e) {
                    Some(k) => words.push_mapped(layout, map, m, x, y, k, turns),
                    None => false,
                }
            }),
            (_, None) if p.is_square() => {
                square_pairs(p.a, &bias, |m, x, y, two| match k.checked_mul(two) {
                    Some(k) => words.push_mapped(layout, map, m, x, y, k, 0),
                    None => false,
                })
            }
            (_, None) => product_pairs(p.a, p.b, &bias, |m, x, y, _| {
                words.push_mapped(layout, map, m, x, y, k, 0)
            }),
        };
        if !all {
            return None;
        }
    }
    Some(words.finish())
}

fn product_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
) -> Gathered<I> {
    let bias = K::load(layout.one());
    let n = a.1.len() * b.1.len();
    if let (Some(x), Some(y)) = (small_bits(a.1), small_bits(b.1)) {
        let per_monomial = a.1.len().min(b.1.len());
        if let Some(mut words) = WordGather::<K, I>::new(n, x + y, per_monomial) {
            if product_pairs(a, b, &bias, |m, x, y, k| words.push(m, x, y, k, 0)) {
                return words.finish();
            }
        }
    }
    let mut exact = Gather::<K, I>::with_capacity(n);
    product_pairs(a, b, &bias, |m, x, y, k| exact.push(m, x, y, k));
    exact.finish()
}

fn square_of_width<K: Key, I: IntegerRing>(layout: &Layout, a: (&[u64], &[I])) -> Gathered<I> {
    let bias = K::load(layout.one());
    let n = a.1.len() * (a.1.len() + 1) / 2;
    if let Some(x) = small_bits(a.1) {
        if let Some(mut words) = WordGather::<K, I>::new(n, 2 * x, a.1.len()) {
            if square_pairs(a, &bias, |m, x, y, k| words.push(m, x, y, k, 0)) {
                return words.finish();
            }
        }
    }
    let mut exact = Gather::<K, I>::with_capacity(n);
    square_pairs(a, &bias, |m, x, y, k| exact.push(m, x, y, k));
    exact.finish()
}

fn jacobians_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    f: (&[u64], &[I]),
    g: (&[u64], &[I]),
    pairs: &[JacobianPair],
) -> Option<Gathered<I>> {
    let bias = K::load(layout.one());
    let ab_bits = small_bits(f.1)? + small_bits(g.1)?;
    // ∂(f, g)/∂(q, p) = f_q·g_p − f_p·g_q vanishes unless one side has `q` and the other `p`.
    let (in_f, in_g) = (occurring::<K>(f.0, &bias), occurring::<K>(g.0, &bias));
    let has = |vars: &K, (word, shift): (usize, u32)| {
        (vars.as_ref()[word] >> shift) & layout.field_mask() != 0
    };
    let mut active = [JacobianPair::default(); MAX_JACOBIAN_PAIRS];
    let mut count = 0;
    for pair in pairs {
        if (has(&in_f, pair.q) && has(&in_g, pair.p)) || (has(&in_f, pair.p) && has(&in_g, pair.q))
        {
            active[count] = *pair;
            count += 1;
        }
    }
    let n = K::WORDS;
    let per_monomial = f.1.len().min(g.1.len()) * count;
    let mut out = WordGather::<K, I>::new(f.1.len() * g.1.len() * count, ab_bits, per_monomial)?;
    for pair in &active[..count] {
        for (mf, cf) in f.0.chunks_exact(n).zip(f.1) {
            let (aq, ap) = (layout.read(mf, pair.q), layout.read(mf, pair.p));
            if aq == 0 && ap == 0 {
                continue;
            }
            // The monomial m_f·m_g/(q·p), lowered once per term of `f`.
            let lowered = K::load(mf).lowered(&pair.lower[..n]);
            for (mg, cg) in g.0.chunks_exact(n).zip(g.1) {
                let factor = aq * layout.read(mg, pair.p) - ap * layout.read(mg, pair.q);
                if factor == 0 {
                    continue;
                }
                let m = lowered.mul(&K::load(mg), &bias);
                if !out.push(m, cf, cg, factor, pair.turns) {
                    return None;
                }
            }
        }
    }
    Some(out.finish())
}

/// The fields of the variables that occur in some monomial of `exps` are nonzero in the
/// result (an exponent differs from the bias there), and only those.
fn occurring<K: Key>(exps: &[u64], bias: &K) -> K {
    let mut seen = K::ZERO;
    for m in exps.chunks_exact(K::WORDS) {
        for ((s, &w), &b) in seen.as_mut().iter_mut().zip(m).zip(bias.as_ref()) {
            *s |= w ^ b;
        }
    }
    seen
}

/// `(Σ c_i·m_i)^e` by the multinomial theorem, one term product per composition
/// `e = a_1 + … + a_t`: `e!/(a_1!…a_t!) · Π c_i^{a_i} · Π m_i^{a_i}`, every one in machine
/// words and added in one table. `None` when that could pass a word: the terms' coefficients
/// bound every coefficient of the power and every partial product of the walk by
/// `(Σ |c_i|)^e`, which must stay below `2^62`. The caller has checked the exponents.
pub(crate) fn multinomial_power<I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    e: usize,
    compositions: usize,
) -> Option<Gathered<I>> {
    debug_assert!(layout.words <= WORDS);
    by_width!(
        layout.words,
        multinomial_power_of_width,
        layout,
        a,
        e,
        compositions
    )
}

fn multinomial_power_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    e: usize,
    compositions: usize,
) -> Option<Gathered<I>> {
    let t = a.1.len();
    let smalls: Vec<I::Small> = a.1.iter().map(I::to_small).collect::<Option<_>>()?;
    // Σ |c_i| ≤ Σ 2^(bits + 1) (a Gaussian component counts both parts).
    let sum: u128 = smalls.iter().map(|c| 1u128 << (I::small_bits(c) + 1)).sum();
    let bound = sum.checked_pow(u32::try_from(e).ok()?)?;
    if bound >= 1 << 62 {
        return None;
    }
    // Pascal's triangle up to e, and c_i^a for a ≤ e.
    let mut binom: Vec<Vec<i64>> = vec![vec![1]];
    for n in 1..=e {
        let prev = &binom[n - 1];
        let mut row = vec![1i64; n + 1];
        for k in 1..n {
            row[k] = prev[k - 1] + prev[k];
        }
        binom.push(row);
    }
    let one = I::to_small(&I::from_integer(Integer::ONE)).expect("one is small");
    let powers: Vec<Vec<I::Small>> = smalls
        .iter()
        .map(|c| {
            let mut row = vec![one];
            for k in 1..=e {
                row.push(I::small_mul_scale(&row[k - 1], c, 1));
            }
            row
        })
        .collect();
    let bias = K::load(layout.one());
    // m_i − 1, the translation that multiplies by m_i.
    let steps: Vec<K> =
        a.0.chunks_exact(K::WORDS)
            .map(|m| K::load(m).lowered(bias.as_ref()))
            .collect();
    // Every composition is a term; they are distinct unless the monomials are dependent.
    let mut words = WordGather::<K, I>::new(compositions, 0, compositions)?;
    struct Walk<'a, K, I: IntegerRing> {
        binom: &'a [Vec<i64>],
        powers: &'a [Vec<I::Small>],
        steps: &'a [K],
        words: &'a mut WordGather<K, I>,
    }
    fn go<K: Key, I: IntegerRing>(
        walk: &mut Walk<'_, K, I>,
        i: usize,
        rem: usize,
        m: K,
        c: &I::Small,
    ) {
        if i + 1 == walk.powers.len() {
            let mut by = walk.steps[i];
            for word in by.as_mut() {
                *word = word.wrapping_mul(rem as u64);
            }
            let m = m.translated(by.as_ref());
            let c = I::small_mul_scale(c, &walk.powers[i][rem], 1);
            walk.words.add(m, I::small_to_wide(&c));
            return;
        }
        let mut m = m;
        for k in 0..=rem {
            let next = I::small_mul_scale(c, &walk.powers[i][k], walk.binom[rem][k]);
            go(walk, i + 1, rem - k, m, &next);
            m = m.translated(walk.steps[i].as_ref());
        }
    }
    let mut walk = Walk {
        binom: &binom,
        powers: &powers,
        steps: &steps,
        words: &mut words,
    };
    debug_assert!(t >= 1);
    go(&mut walk, 0, e, bias, &one);
    Some(words.finish())
}

/// Calls `emit(m_a·m_b, c_a, c_b, 1)` for every pair of terms of `a` and `b`, while it
/// returns `true`; whether every call did.
#[inline(always)]
fn product_pairs<K: Key, I>(
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
    bias: &K,
    mut emit: impl FnMut(K, &I, &I, i64) -> bool,
) -> bool {
    let n = K::WORDS;
    for (ma, ca) in a.0.chunks_exact(n).zip(a.1) {
        let ma = K::load(ma);
        for (mb, cb) in b.0.chunks_exact(n).zip(b.1) {
            if !emit(ma.mul(&K::load(mb), bias), ca, cb, 1) {
                return false;
            }
        }
    }
    true
}

/// Calls `emit(m_i², c_i, c_i, 1)` and `emit(m_i·m_j, c_i, c_j, 2)` (`i < j`) for the terms of
/// `a`, while it returns `true`; whether every call did.
#[inline(always)]
fn square_pairs<K: Key, I>(
    a: (&[u64], &[I]),
    bias: &K,
    mut emit: impl FnMut(K, &I, &I, i64) -> bool,
) -> bool {
    let n = K::WORDS;
    for (i, (mi, ci)) in a.0.chunks_exact(n).zip(a.1).enumerate() {
        let mi = K::load(mi);
        if !emit(mi.mul(&mi, bias), ci, ci, 1) {
            return false;
        }
        for (mj, cj) in a.0[(i + 1) * n..].chunks_exact(n).zip(&a.1[i + 1..]) {
            if !emit(mi.mul(&K::load(mj), bias), ci, cj, 2) {
                return false;
            }
        }
    }
    true
}

/// Calls `emit(m_a·m_b/v, c_a, c_b, e, t)` for every term `c_a·m_a` of `a` with exponent
/// `e ≠ 0` in `v` and every term `c_b·m_b` of `b` (`t` factors `i` for an angle), while it
/// returns `true`; whether every call did.
#[inline(always)]
fn derivative_pairs<K: Key, I>(
    layout: &Layout,
    a: (&[u64], &[I]),
    by: Partial,
    b: (&[u64], &[I]),
    bias: &K,
    mut emit: impl FnMut(K, &I, &I, i64, u32) -> bool,
) -> bool {
    let n = K::WORDS;
    // m_a·m_b/v is m_a + m_b − (bias + lower), word by word.
    let bias = bias.translated(&by.lower[..n]);
    for (ma, ca) in a.0.chunks_exact(n).zip(a.1) {
        let e = layout.read(ma, by.field);
        if e == 0 {
            continue;
        }
        let ka = K::load(ma);
        for (mb, cb) in b.0.chunks_exact(n).zip(b.1) {
            if !emit(ka.mul(&K::load(mb), &bias), ca, cb, e, by.turns) {
                return false;
            }
        }
    }
    true
}

/// Calls `emit(m, c_a, c_b, f, t)` for the term products `c_a·m_a · c_b·m_b` of `a·b`, or of
/// `(∂a/∂v)·b` with `by`, mapped by `map`: `m` is the image of the monomial and `f` its
/// factor (times the exponent `e ≠ 0` of `v` in `m_a` for a derivative; `t` factors `i` for
/// an angle), while it returns `true`; whether every call did, and `false` when a factor
/// passes a word. `a` must be free of the map's variables: each term of `b` (divided by `v`)
/// is then mapped once, and its image and factor hold for every term of `a`.
#[inline(always)]
fn mapped_pairs<K: Key, I>(
    layout: &Layout,
    a: (&[u64], &[I]),
    by: Option<Partial>,
    b: (&[u64], &[I]),
    bias: &K,
    map: &MonomialMap,
    mut emit: impl FnMut(K, &I, &I, i64, u32) -> bool,
) -> bool {
    let n = K::WORDS;
    let (lower, turns) = by.map_or(([0; WORDS], 0), |p| (p.lower, p.turns));
    for (mb, cb) in b.0.chunks_exact(n).zip(b.1) {
        let Some((image, factor)) = map.apply(layout, K::load(mb).lowered(&lower[..n]), 1) else {
            return false;
        };
        for (ma, ca) in a.0.chunks_exact(n).zip(a.1) {
            let e = match by {
                Some(p) => layout.read(ma, p.field),
                None => 1,
            };
            if e == 0 {
                continue;
            }
            let Some(f) = e.checked_mul(factor) else {
                return false;
            };
            if !emit(K::load(ma).mul(&image, bias), ca, cb, f, turns) {
                return false;
            }
        }
    }
    true
}

/// The bits of the `i128` sums: a term product whose real products each take at most `b`
/// bits has components below `2^(b + 1)` (a Gaussian component adds two), so that `n` of them
/// sum below `2^(b + 1 + ⌈log₂ n⌉)`, which must stay below `2^127`.
const SUM_BITS: u32 = 126;

/// The most bits of a component of any of the coefficients, if every one fits a word.
pub(crate) fn small_bits<I: IntegerRing>(coeffs: &[I]) -> Option<u32> {
    let mut bits = 0;
    for c in coeffs {
        bits = bits.max(I::small_bits(&c.to_small()?));
    }
    Some(bits)
}

/// Term products with word-sized coefficients, each kept exactly in the ring's wide form (no
/// allocation, clone or drop per coefficient) and added at once to the running sum of its
/// monomial, which an open-addressing table finds: only the distinct monomials are sorted at
/// the end, and only those whose sums did not cancel (none, for an identity's residual).
struct WordGather<K, I: IntegerRing> {
    /// The distinct monomials in the order they came, with their sums.
    items: Vec<(K, I::Wide)>,
    /// Linear probing over `items`: a slot holds an index into `items` plus one, or 0 when
    /// empty; a power of two, more than twice the items.
    slots: Vec<u32>,
    /// `64 − log₂(slots)`: a hash's top bits pick the slot.
    shift: u32,
    /// The bits left for the multiplier `k` of a product `a·b·k`: [`SUM_BITS`] less the
    /// bits of the most term products one monomial can gather and the most bits of `a` and
    /// `b` together (from [`small_bits`]).
    k_budget: u32,
}

impl<K: Key, I: IntegerRing> WordGather<K, I> {
    /// Room for at most `n` term products, whose coefficients fit words and take at most
    /// `ab_bits` bits together, and of which at most `per_monomial` share a monomial; `None`
    /// when no multiplier would leave room in the sums.
    fn new(n: usize, ab_bits: u32, per_monomial: usize) -> Option<Self> {
        let fan_in_bits = usize::BITS - per_monomial.max(1).saturating_sub(1).leading_zeros();
        let k_budget = SUM_BITS.checked_sub(fan_in_bits + ab_bits)?;
        let slots = (2 * n + 1).next_power_of_two().max(8);
        Some(WordGather {
            items: Vec::with_capacity(n),
            slots: vec![0; slots],
            shift: 64 - slots.trailing_zeros(),
            k_budget,
        })
    }

    /// Adds the term `a·b·k·iᵗ·m` (`k ≠ 0`, `t` = `turns`), or returns `false` and adds nothing
    /// when `k` takes more bits than the sums leave it, or `t > 0` in a ring without `i`.
    #[inline(always)]
    fn push(&mut self, m: K, a: &I, b: &I, k: i64, turns: u32) -> bool {
        let k_bits = 64 - k.unsigned_abs().leading_zeros();
        if k_bits > self.k_budget {
            return false;
        }
        let (Some(a), Some(b)) = (a.to_small(), b.to_small()) else {
            return false;
        };
        let mut w = I::Wide::default();
        // The multiplier goes into a word-sized factor when it fits, else into the product.
        match (k, I::small_checked_scale(&a, k)) {
            (1, _) => I::wide_add_mul(&mut w, &a, &b),
            (_, Some(ak)) => I::wide_add_mul(&mut w, &ak, &b),
            (_, None) => {
                I::wide_add_mul(&mut w, &a, &b);
                w = I::wide_scale(&w, k);
            }
        }
        for _ in 0..turns {
            match I::wide_mul_i(&w) {
                Some(iw) => w = iw,
                None => return false,
            }
        }
        self.add(m, w);
        true
    }

    /// [`WordGather::push`] of the image of the term under `map`, when given; `false` when
    /// the image's factor passes a word.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn push_mapped(
        &mut self,
        layout: &Layout,
        map: Option<&MonomialMap>,
        m: K,
        a: &I,
        b: &I,
        k: i64,
        turns: u32,
    ) -> bool {
        match map {
            None => self.push(m, a, b, k, turns),
            Some(map) => match map.apply(layout, m, k) {
                Some((m, k)) => self.push(m, a, b, k, turns),
                None => false,
            },
        }
    }

    /// `sum(m) += w`.
    #[inline(always)]
    fn add(&mut self, m: K, w: I::Wide) {
        debug_assert!(
            2 * self.items.len() < self.slots.len(),
            "more items than promised"
        );
        let mask = self.slots.len() - 1;
        let mut slot = (m.hash() >> self.shift) as usize;
        loop {
            match self.slots[slot] {
                0 => {
                    self.items.push((m, w));
                    self.slots[slot] = self.items.len() as u32;
                    return;
                }
                k => {
                    let item = &mut self.items[k as usize - 1];
                    if item.0 == m {
                        I::wide_add(&mut item.1, &w);
                        return;
                    }
                }
            }
            slot = (slot + 1) & mask;
        }
    }

    /// The terms sorted descending, zero sums dropped, divided by the gcd of the sums and the
    /// sign of the leading one (on machine words, while they are converted), so that they are
    /// primitive.
    fn finish(mut self) -> Gathered<I> {
        let zero = I::Wide::default();
        let items = &mut self.items;
        items.retain(|(_, sum)| *sum != zero);
        items.sort_unstable_by_key(|&(m, _)| std::cmp::Reverse(m));
        let mut g = 0u128;
        for (_, sum) in items.iter() {
            g = I::wide_gcd(g, sum);
            if g == 1 {
                break;
            }
        }
        // Every sum is below 2^127 in size, and so is their gcd.
        let mut divisor = (g as i128).max(1);
        if items
            .first()
            .is_some_and(|(_, sum)| I::wide_leading_sign(sum) < 0)
        {
            divisor = -divisor;
        }
        let mut exps = Vec::with_capacity(items.len() * K::WORDS);
        let mut coeffs = Vec::with_capacity(items.len());
        for &(m, sum) in items.iter() {
            m.store(&mut exps, K::WORDS);
            coeffs.push(I::from_wide(match divisor {
                1 => sum,
                -1 => I::wide_scale(&sum, -1),
                d => I::wide_div_exact(&sum, d),
            }));
        }
        Gathered {
            exps,
            coeffs,
            divisor: Some(Integer::from_i128(divisor)),
        }
    }
}

/// Term products as ring elements, unsorted, with their monomials.
struct Gather<K, I> {
    items: Vec<(K, I)>,
}

impl<K: Key, I: IntegerRing> Gather<K, I> {
    fn with_capacity(n: usize) -> Self {
        Gather {
            items: Vec::with_capacity(n),
        }
    }

    /// Adds the term `a·b·k·m` (`k` is 1 or 2); always `true`.
    fn push(&mut self, m: K, a: &I, b: &I, k: i64) -> bool {
        debug_assert!(k == 1 || k == 2);
        let p = a.mul(b);
        self.items.push((m, if k == 2 { p.add(&p) } else { p }));
        true
    }

    /// The terms sorted descending, equal monomials summed, zero sums dropped.
    fn finish(mut self) -> Gathered<I> {
        self.items
            .sort_unstable_by_key(|&(m, _)| std::cmp::Reverse(m));
        let mut exps = Vec::with_capacity(self.items.len() * K::WORDS);
        let mut coeffs = Vec::with_capacity(self.items.len());
        let mut items = self.items.into_iter().peekable();
        while let Some((m, mut c)) = items.next() {
            while let Some((_, d)) = items.next_if(|(n, _)| *n == m) {
                c = c.add(&d);
            }
            if !c.is_zero() {
                m.store(&mut exps, K::WORDS);
                coeffs.push(c);
            }
        }
        Gathered {
            exps,
            coeffs,
            divisor: None,
        }
    }
}
