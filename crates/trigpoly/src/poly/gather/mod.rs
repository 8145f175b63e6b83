//! Sums of term products of short polynomials, gathered: every term product is added at once
//! to the running sum of its monomial, only the monomials whose sums survive are sorted, and
//! they come out primitive (`Gathered`). For inputs of a handful of terms (the generators of an
//! algebra, their squares and brackets) this costs less than shifting and merging, which
//! allocates a polynomial per term; for a flow on a condition, whose sums all cancel, nothing
//! is sorted at all.
//!
//! The kernels: [`product`], [`square`], [`jacobians`] (the short Poisson bracket),
//! [`sum_of_products`] (products and derivative products, at a substitution of single terms
//! when a [`MonomialMap`] is given) and [`multinomial_power`]. Each runs with monomials of
//! exactly the layout's width (one to [`WORDS`] words, known at compile time) and walks its
//! term pairs (`pairs.rs`) into a `WordGather` (`table.rs`), which keeps every term product
//! exactly in the ring's wide form (`i128` per component) while the coefficients fit machine
//! words, as they do for such inputs; a `Gather` keeps ring elements, for coefficients of any
//! size. Over Q(i), factors whose coefficients are all real (an algebra's generators, the
//! Hamiltonian; [`Poly::real_coefficients`](super::Poly::real_coefficients)) gather in Z's
//! words, one product per term pair where a Gaussian takes four, unless an angle brings `i`.

use arrayvec::ArrayVec;

mod map;
mod pairs;
mod table;

pub(crate) use map::MonomialMap;
pub(crate) use table::{small_bits, Gathered};

use pairs::{derivative_pairs, mapped_pairs, product_pairs, square_pairs};
use table::{Gather, Inline, Smalls, Table, WordGather, INLINE};

use super::mul::Key;
use crate::number::{Integer, IntegerRing};
use crate::varset::{Layout, Var, VarKind, VarSet};

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

/// One pair of variables `(q, p)` of a sum of Jacobians, as [`jacobians`] reads it: the field
/// (word, shift) of each and whether it is an angle. Six bytes, so that the kernel's list of
/// the active pairs costs next to nothing to build.
#[derive(Clone, Copy)]
struct JacobianPair {
    q: (u8, u8),
    p: (u8, u8),
    q_angle: bool,
    p_angle: bool,
}

impl JacobianPair {
    /// The pair `(q, p)` of `vars`, whose monomials fit [`WORDS`] words, each variable with
    /// its field (word, shift) as [`Layout::field`] gives it.
    #[inline]
    fn new(vars: &VarSet, q: (Var, (usize, u32)), p: (Var, (usize, u32))) -> Self {
        let field = |(word, shift): (usize, u32)| (word as u8, shift as u8);
        let angle = |v: Var| vars.variable(v).kind() == VarKind::Angle;
        JacobianPair {
            q: field(q.1),
            p: field(p.1),
            q_angle: angle(q.0),
            p_angle: angle(p.0),
        }
    }

    /// The field of `q`, as [`Layout::read`] takes it.
    #[inline]
    fn q(&self) -> (usize, u32) {
        (usize::from(self.q.0), u32::from(self.q.1))
    }

    /// The field of `p`.
    #[inline]
    fn p(&self) -> (usize, u32) {
        (usize::from(self.p.0), u32::from(self.p.1))
    }

    /// Factors `i` the derivatives bring, one per angle.
    #[inline]
    fn turns(&self) -> u32 {
        u32::from(self.q_angle) + u32::from(self.p_angle)
    }

    /// What both derivatives take off a monomial: one in the field of each variable that is
    /// not an angle.
    #[inline]
    fn lower<K: Key>(&self) -> K {
        let one = |(word, shift): (u8, u8), angle: bool, i: usize| {
            if !angle && usize::from(word) == i {
                1u64 << shift
            } else {
                0
            }
        };
        // Word by word, with no store at a computed index (whose reload as a whole would
        // wait for the store to retire).
        let mut lower = K::ZERO;
        for (i, w) in lower.as_mut().iter_mut().enumerate() {
            *w = one(self.q, self.q_angle, i).wrapping_add(one(self.p, self.p_angle, i));
        }
        lower
    }
}

/// The layout's bias (the monomial 1) as a key of its exact width: the layout's words as they
/// are, with no `memcpy` call for a length known at run time only.
#[inline(always)]
fn bias_of<K: Key>(layout: &Layout) -> K {
    let one = layout.one();
    let mut bias = K::ZERO;
    if bias.as_ref().len() == one.len() {
        bias.as_mut().copy_from_slice(one);
        bias
    } else {
        K::load(one)
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

/// `$fill` (which adds term products to `$words`, a `WordGather` for at most `$n` of them
/// with the multiplier budget `$budget`, and says whether all of them fit) and then the sums,
/// or `None`: the table is [`Inline`] for fewer than [`INLINE`] term products, else on the
/// heap. The one place that picks; both tables are built where they stay (a macro, since
/// the fill is compiled once for each). The words are those of the ring `I` in scope, and
/// `finish` makes the sums its elements; with `real:` first, they are Z's and the sums become
/// elements of `I` by [`IntegerRing::from_real_wide`]; with `Ring, element;` first, they are
/// `Ring`'s, made elements by `element`.
macro_rules! gathered {
    ($n:expr, $budget:expr, |$words:ident| $fill:expr) => {
        gathered!(I, I::from_wide; $n, $budget, |$words| $fill)
    };
    (real: $n:expr, $budget:expr, |$words:ident| $fill:expr) => {
        gathered!(Integer, I::from_real_wide; $n, $budget, |$words| $fill)
    };
    ($ring:ty, $element:expr; $n:expr, $budget:expr, |$words:ident| $fill:expr) => {
        if $n < INLINE {
            let mut $words = WordGather::<K, $ring, Inline<K, <$ring as IntegerRing>::Wide>>::new(
                $n, $budget,
            );
            ($fill).then(|| $words.finish_as($element))
        } else {
            let mut $words = WordGather::<K, $ring>::new($n, $budget);
            ($fill).then(|| $words.finish_as($element))
        }
    };
}

/// The product of two term lists, sorted, combined, zeros dropped; `real` when all their
/// coefficients are real. The caller has checked that every exponent of the product stays
/// within its field.
pub(crate) fn product<I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
    real: bool,
) -> Gathered<I> {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, product_of_width, layout, a, Some(b), real)
}

/// The square of a term list, from the `n(n + 1)/2` products `c_i²·m_i²` and `2c_ic_j·m_im_j`
/// (`i < j`), sorted, combined, zeros dropped; `real` when all its coefficients are real.
/// The caller has checked the exponents.
pub(crate) fn square<I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    real: bool,
) -> Gathered<I> {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, product_of_width, layout, a, None, real)
}

/// `Σ_k ∂(f, g)/∂(q_k, p_k)` over the `pairs` of variables of `vars` (at most
/// [`MAX_JACOBIAN_PAIRS`]), from the term pairs: both products of
/// derivatives of the terms `c·m` and `d·n` have the monomial `m·n/(q·p)`, with the
/// coefficient `c·d·(a_q·b_p − a_p·b_q)·iᵗ`, where `a`, `b` are the exponents in `m`, `n` and
/// `t` counts the angles of the pair. The coefficients of `f` and `g` fit words and take at
/// most `ab_bits` bits together ([`small_bits`], which the polynomials keep); `real` when
/// all of them are real, which lets a ring with `i` gather in Z's words when no angle is
/// active. `None` when a term product could pass the sums or an angle needs `i` in a ring
/// without it (the general path handles both). The caller has checked the exponents.
pub(crate) fn jacobians<I: IntegerRing>(
    vars: &VarSet,
    f: (&[u64], &[I]),
    g: (&[u64], &[I]),
    pairs: &[(Var, Var)],
    (ab_bits, real): (u32, bool),
) -> Option<Gathered<I>> {
    let layout = vars.layout();
    debug_assert!(layout.words <= WORDS && pairs.len() <= MAX_JACOBIAN_PAIRS);
    debug_assert!(small_bits(f.1)
        .zip(small_bits(g.1))
        .is_some_and(|(a, b)| a + b <= ab_bits));
    debug_assert!(!real || f.1.iter().chain(g.1).all(I::is_real));
    by_width!(
        layout.words,
        jacobians_of_width,
        vars,
        f,
        g,
        pairs,
        (ab_bits, real)
    )
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
    /// Whether the coefficients of `a` and `b` are all real. Only plain products and squares
    /// gather in Z's words, so a caller may leave it `false` for a derivative product without
    /// reading the coefficients ([`sum_of_products`] tests `by` as well).
    real: bool,
    /// Whether `a` is free of the variables a [`MonomialMap`] substitutes: then the image
    /// of each term of `b` (divided by `v` for a derivative) holds for every term of `a`
    /// with it, and is found once per term of `b`.
    a_unmapped: bool,
}

impl<'a, I> Product<'a, I> {
    /// `k·a·b`, or `k·(∂a/∂v)·b` when `by` is the derivative, where the coefficients of `a`
    /// and `b` fit words and take at most `ab_bits` bits together ([`small_bits`]), and are
    /// all real when `real`.
    pub(crate) fn new(
        a: (&'a [u64], &'a [I]),
        by: Option<Partial>,
        b: (&'a [u64], &'a [I]),
        k: i64,
        (ab_bits, real): (u32, bool),
    ) -> Self {
        Product {
            a,
            by,
            b,
            k,
            ab_bits,
            real,
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
    // Real products and squares, at no substitution: the sums are real. Decided here, out
    // of the kernels: tested inside the flows' kernel, the branch made it 0.6 % more
    // instructions (W1(8)).
    if I::COMPLEX && map.is_none() && products.iter().all(|p| p.real && p.by.is_none()) {
        return by_width!(
            layout.words,
            real_sum_of_products_of_width,
            layout,
            products
        );
    }
    by_width!(
        layout.words,
        sum_of_products_of_width,
        layout,
        products,
        map
    )
}

/// The term products of `products`, the most of them that share a monomial, and the most
/// bits of their factors' coefficients together.
#[inline(always)]
fn extent<I>(products: &[Product<'_, I>]) -> (usize, usize, u32) {
    let (mut n, mut per_monomial, mut ab_bits) = (0usize, 0usize, 0);
    for p in products {
        n = n.saturating_add(p.pairs());
        per_monomial = per_monomial.saturating_add(p.per_monomial());
        ab_bits = ab_bits.max(p.ab_bits);
    }
    (n, per_monomial, ab_bits)
}

fn sum_of_products_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    products: &[Product<'_, I>],
    map: Option<&MonomialMap>,
) -> Option<Gathered<I>> {
    let (n, mut per_monomial, ab_bits) = extent(products);
    if let Some(map) = map {
        per_monomial = per_monomial.saturating_mul(map.fan_in());
    }
    let budget = WordGather::<K, I>::budget(ab_bits, per_monomial)?;
    gathered!(n, budget, |words| gather_products(
        &mut words, layout, products, map
    ))
}

/// [`sum_of_products_of_width`] of products and squares of real factors, gathered in Z's
/// words.
fn real_sum_of_products_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    products: &[Product<'_, I>],
) -> Option<Gathered<I>> {
    let (n, per_monomial, ab_bits) = extent(products);
    let budget = WordGather::<K, Integer>::budget(ab_bits, per_monomial)?;
    gathered!(real: n, budget, |words| gather_real_products(
        &mut words, layout, products
    ))
}

/// Adds the term products of products and squares of real factors to `words`, in Z's words;
/// whether all of them fit.
#[inline(always)]
fn gather_real_products<K: Key, I: IntegerRing, T: Table<K, i128>>(
    words: &mut WordGather<K, Integer, T>,
    layout: &Layout,
    products: &[Product<'_, I>],
) -> bool {
    let bias = bias_of::<K>(layout);
    let (mut real_a, mut real_b) = (Smalls::new(), Smalls::new());
    for p in products {
        let Some(a) = real_a.fill_real(p.a.1) else {
            return false;
        };
        let b = match p.is_square() {
            true => None,
            false => match real_b.fill_real(p.b.1) {
                Some(b) => Some((p.b.0, b)),
                None => return false,
            },
        };
        if !plain_pairs(words, layout, None, &bias, (p.a.0, a), b, p.k) {
            return false;
        }
    }
    true
}

/// Adds `k·a·b`, or `k·a²` when `b` is `None`, from factors in words, to `words`, mapped by
/// `map` when given; whether all of them fit. The walks' closures are inlined into them:
/// called, each term product spilled the walk's registers (W4's Casimir).
#[inline(always)]
fn plain_pairs<K: Key, I: IntegerRing, T: Table<K, I::Wide>>(
    words: &mut WordGather<K, I, T>,
    layout: &Layout,
    map: Option<&MonomialMap>,
    bias: &K,
    a: (&[u64], &[I::Small]),
    b: Option<(&[u64], &[I::Small])>,
    k: i64,
) -> bool {
    match b {
        None => square_pairs(
            a,
            bias,
            #[inline(always)]
            |m, x, y, two| match k.checked_mul(two) {
                Some(k) => words.push_mapped(layout, map, m, x, y, k, 0),
                None => false,
            },
        ),
        Some(b) => product_pairs(
            a,
            b,
            bias,
            #[inline(always)]
            |m, x, y, _| words.push_mapped(layout, map, m, x, y, k, 0),
        ),
    }
}

/// Adds the term products of every product to `words`; whether all of them fit.
#[inline(always)]
fn gather_products<K: Key, I: IntegerRing, T: Table<K, I::Wide>>(
    words: &mut WordGather<K, I, T>,
    layout: &Layout,
    products: &[Product<'_, I>],
    map: Option<&MonomialMap>,
) -> bool {
    let bias = bias_of::<K>(layout);
    // A product or a square visits every term pair: its coefficients are converted to words
    // once per factor (a square's once). A derivative skips the terms without its variable, and
    // a flow on a condition has one long factor: those convert the coefficients of each term
    // product they form.
    let (mut small_a, mut small_b) = (Smalls::new(), Smalls::new());
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
                    Some(k) => words.push_ring(m, x, y, k, turns),
                    None => false,
                },
            ),
            (_, Some(by)) => derivative_pairs(layout, p.a, by, p.b, &bias, |m, x, y, e, turns| {
                match (k.checked_mul(e), x.to_small(), y.to_small()) {
                    (Some(k), Some(x), Some(y)) => {
                        words.push_mapped(layout, map, m, &x, &y, k, turns)
                    }
                    _ => false,
                }
            }),
            (_, None) if p.is_square() => {
                let Some(a) = small_a.fill(p.a.1) else {
                    return false;
                };
                plain_pairs(words, layout, map, &bias, (p.a.0, a), None, k)
            }
            (_, None) => {
                let (Some(a), Some(b)) = (small_a.fill(p.a.1), small_b.fill(p.b.1)) else {
                    return false;
                };
                plain_pairs(words, layout, map, &bias, (p.a.0, a), Some((p.b.0, b)), k)
            }
        };
        if !all {
            return false;
        }
    }
    true
}

/// `a·b`, or `a²` when `b` is `None`: in words while the sums fit them (Z's for real
/// factors of a ring with `i`), else in ring elements.
fn product_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: Option<(&[u64], &[I])>,
    real: bool,
) -> Gathered<I> {
    let words = if I::COMPLEX && real {
        in_words::<K, Integer, I>(layout, a, b, Smalls::fill_real, I::from_real_wide)
    } else {
        in_words::<K, I, I>(layout, a, b, Smalls::fill, I::from_wide)
    };
    if let Some(sums) = words {
        return sums;
    }
    let bias = bias_of::<K>(layout);
    match b {
        Some(b) => {
            let mut exact = Gather::<K, I>::with_capacity(a.1.len() * b.1.len());
            product_pairs(a, b, &bias, |m, x, y, k| exact.push(m, x, y, k));
            exact.finish()
        }
        None => {
            let mut exact = Gather::<K, I>::with_capacity(a.1.len() * (a.1.len() + 1) / 2);
            square_pairs(a, &bias, |m, x, y, k| exact.push(m, x, y, k));
            exact.finish()
        }
    }
}

/// [`product_of_width`] in words of the ring `A`, the factors' coefficients taken as words
/// by `fill` ([`Smalls::fill`], or [`Smalls::fill_real`] for Z's) and the sums made elements
/// of `I` by `element`; `None` when a coefficient has no word or a sum could pass the words.
#[inline(always)]
fn in_words<K: Key, A: IntegerRing, I>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: Option<(&[u64], &[I])>,
    fill: impl for<'s> Fn(&'s mut Smalls<A::Small>, &[I]) -> Option<&'s [A::Small]>,
    element: impl Fn(A::Wide) -> I,
) -> Option<Gathered<I>> {
    let bias = bias_of::<K>(layout);
    let (mut small_a, mut small_b) = (Smalls::new(), Smalls::new());
    let sa = (a.0, fill(&mut small_a, a.1)?);
    let (n, per_monomial, ab_bits, sb) = match b {
        None => {
            let n = a.1.len() * (a.1.len() + 1) / 2;
            (n, a.1.len(), 2 * bits::<A>(sa.1), None)
        }
        Some(b) => {
            let sb = (b.0, fill(&mut small_b, b.1)?);
            let ab_bits = bits::<A>(sa.1) + bits::<A>(sb.1);
            (
                a.1.len() * b.1.len(),
                a.1.len().min(b.1.len()),
                ab_bits,
                Some(sb),
            )
        }
    };
    let budget = WordGather::<K, A>::budget(ab_bits, per_monomial)?;
    gathered!(A, element; n, budget, |words| plain_pairs(
        &mut words, layout, None, &bias, sa, sb, 1
    ))
}

fn jacobians_of_width<K: Key, I: IntegerRing>(
    vars: &VarSet,
    f: (&[u64], &[I]),
    g: (&[u64], &[I]),
    pairs: &[(Var, Var)],
    (ab_bits, real): (u32, bool),
) -> Option<Gathered<I>> {
    let layout = vars.layout();
    let bias = bias_of::<K>(layout);
    // ∂(f, g)/∂(q, p) = f_q·g_p − f_p·g_q vanishes unless one side has `q` and the other `p`.
    let (in_f, in_g) = (occurring::<K>(f.0, &bias), occurring::<K>(g.0, &bias));
    let has = |vars: &K, (word, shift): (usize, u32)| {
        (vars.as_ref()[word] >> shift) & layout.field_mask() != 0
    };
    let mut active = ArrayVec::<JacobianPair, MAX_JACOBIAN_PAIRS>::new();
    for &(q, p) in pairs {
        let (fq, fp) = (layout.field(q.index()), layout.field(p.index()));
        if (has(&in_f, fq) && has(&in_g, fp)) || (has(&in_f, fp) && has(&in_g, fq)) {
            active.push(JacobianPair::new(vars, (q, fq), (p, fp)));
        }
    }
    let per_monomial = f.1.len().min(g.1.len()) * active.len();
    let budget = WordGather::<K, I>::budget(ab_bits, per_monomial)?;
    let n = f.1.len() * g.1.len() * active.len();
    let active = active.as_slice();
    // Real factors, and no angle to bring `i`: the sums are real.
    if I::COMPLEX && real && active.iter().all(|pair| pair.turns() == 0) {
        let (mut real_f, mut real_g) = (Smalls::new(), Smalls::new());
        let (f, g) = ((f.0, real_f.fill_real(f.1)?), (g.0, real_g.fill_real(g.1)?));
        return gathered!(real: n, budget, |out| gather_jacobians(
            &mut out, layout, f, g, active
        ));
    }
    let (mut small_f, mut small_g) = (Smalls::new(), Smalls::new());
    let (f, g) = ((f.0, small_f.fill(f.1)?), (g.0, small_g.fill(g.1)?));
    gathered!(n, budget, |out| gather_jacobians(
        &mut out, layout, f, g, active
    ))
}

/// Adds the term products of `Σ ∂(f, g)/∂(q, p)` over the `active` pairs to `out`; whether
/// all of them fit.
#[inline(always)]
fn gather_jacobians<K: Key, I: IntegerRing, T: Table<K, I::Wide>>(
    out: &mut WordGather<K, I, T>,
    layout: &Layout,
    f: (&[u64], &[I::Small]),
    g: (&[u64], &[I::Small]),
    active: &[JacobianPair],
) -> bool {
    let bias = bias_of::<K>(layout);
    let n = K::WORDS;
    for pair in active {
        let (q, p, turns) = (pair.q(), pair.p(), pair.turns());
        let lower = pair.lower::<K>();
        for (mf, cf) in f.0.chunks_exact(n).zip(f.1) {
            let (aq, ap) = (layout.read(mf, q), layout.read(mf, p));
            if aq == 0 && ap == 0 {
                continue;
            }
            // The monomial m_f·m_g/(q·p), lowered once per term of `f`.
            let lowered = K::load(mf).lowered(lower.as_ref());
            for (mg, cg) in g.0.chunks_exact(n).zip(g.1) {
                let factor = aq * layout.read(mg, p) - ap * layout.read(mg, q);
                if factor == 0 {
                    continue;
                }
                let m = lowered.mul(&K::load(mg), &bias);
                if !out.push(m, cf, cg, factor, turns) {
                    return false;
                }
            }
        }
    }
    true
}

/// The most bits of a component of any of the word-sized coefficients.
fn bits<I: IntegerRing>(smalls: &[I::Small]) -> u32 {
    smalls.iter().map(I::small_bits).max().unwrap_or(0)
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
/// words and added in one table. `None` when that could pass a word: every coefficient of the
/// power, every sum of them and every partial product of the walk is at most `(Σ |c_i|)^e`
/// (the multinomial theorem on absolute values, each `|c_i| ≥ 1`), which must stay below
/// `2^62`. The caller has checked the exponents.
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
    // Σ |c_i| (a Gaussian coefficient counts both parts).
    let sum: u128 = smalls.iter().map(I::small_norm1).sum();
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
    let bias = bias_of::<K>(layout);
    // m_i − 1, the translation that multiplies by m_i.
    let steps: Vec<K> =
        a.0.chunks_exact(K::WORDS)
            .map(|m| K::load(m).lowered(bias.as_ref()))
            .collect();
    // Every composition is a term; they are distinct unless the monomials are dependent.
    let mut words =
        WordGather::<K, I>::new(compositions, WordGather::<K, I>::budget(0, compositions)?);
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
