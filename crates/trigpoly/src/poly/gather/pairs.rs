//! The walks over the term pairs of a product, a square, a derivative product and a product
//! at a substitution: each calls its `emit` with every term product's monomial, coefficients
//! and multiplier, while `emit` returns `true`.

use super::{MonomialMap, Partial, WORDS};
use crate::poly::mul::Key;
use crate::varset::Layout;

/// Calls `emit(m_a·m_b, c_a, c_b, 1)` for every pair of terms of `a` and `b`, while it
/// returns `true`; whether every call did.
#[inline(always)]
pub(super) fn product_pairs<K: Key, I>(
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
pub(super) fn square_pairs<K: Key, I>(
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
pub(super) fn derivative_pairs<K: Key, I>(
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
pub(super) fn mapped_pairs<K: Key, I>(
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
