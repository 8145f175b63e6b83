//! Integer powers: any power of a single term, non-negative powers of anything else.

use super::{check_coefficient_size, check_exponent, gather, Poly};
use crate::error::AlgebraError;
use crate::number::{Coefficient, Integer, IntegerRing, Rational};

impl<C: Coefficient> Poly<C> {
    /// `self^e`. Negative `e` only for what [`Poly::checked_div`] divides by (`Err`
    /// otherwise); `0^e` with `e < 0` is `Err(DivisionByZero)`; `f^0 = 1` for every `f`, zero
    /// included.
    pub fn checked_pow(&self, e: i64) -> Result<Self, AlgebraError> {
        if e == 0 {
            return Ok(Self::one(&self.vars));
        }
        if self.is_zero() {
            return if e < 0 {
                Err(AlgebraError::DivisionByZero)
            } else {
                Ok(self.clone())
            };
        }
        // Exponent bounds of the result, checked before any work (variable by variable only
        // when the bound on the largest exponent does not clear it).
        let limit = self.vars.limits().max_degree as u64;
        if (self.exponent_bound() as u64).saturating_mul(e.unsigned_abs()) > limit {
            for (v, (lo, hi)) in self.vars.vars().zip(self.bounds()) {
                check_exponent(&self.vars, v, lo.saturating_mul(e))?;
                check_exponent(&self.vars, v, hi.saturating_mul(e))?;
            }
        }
        if self.is_monomial() {
            // A single term's coefficient grows without any new term: bound its size (a
            // coefficient 1, as in `x^2` or `ω^2`, stays 1).
            if !self.has_unit_coefficient() {
                let z = C::from_parts(&self.content, &self.coeffs[0]).to_gaussian();
                let bits = [&z.re, &z.im]
                    .iter()
                    .map(|q| q.numer().bits().max(q.denom().bits()))
                    .max()
                    .unwrap_or(1);
                check_coefficient_size(bits.saturating_mul(e.unsigned_abs()))?;
            }
            return Ok(self.monomial_pow(e));
        }
        if e < 0 {
            if let Some(inverse) = Self::inverse_of_sum(self)? {
                return inverse.checked_pow(-e);
            }
            return Err(AlgebraError::NegativePower {
                shown: self.brief(),
                declare: self.declaration(),
            });
        }
        if e == 1 {
            return Ok(self.clone());
        }
        // The coefficients of a power of `n` terms whose numerators have `b` bits and whose
        // denominators have `d` have numerators of at most `e(b + log₂ n)` bits and
        // denominators of `e d`: the bound on them, as on a single term's power above
        // (`(c x + y)^100` of a `c` of a million bits multiplied for a quarter of an hour).
        let sums = u64::from(64 - (self.len() as u64).leading_zeros());
        let (numer, denom) = self.coefficient_bits();
        check_coefficient_size((numer + sums).max(denom).saturating_mul(e.unsigned_abs()))?;
        if e == 2 {
            return self.checked_square();
        }
        let limit = self.vars.limits().max_terms;
        if self.len() <= 6 {
            let compositions =
                binomial_u128(e as u128 + self.len() as u128 - 1, self.len() as u128 - 1);
            if compositions <= limit as u128 {
                return self.multinomial_pow(e as usize);
            }
        }
        // Too many terms, known from the monomials before any product (`power_terms.rs`):
        // `(x + y + p_x + p_y + M + I + ω)^60`, every composition a term of its own,
        // multiplied for 38 s before it stopped, the Fock–Darwin `W^99`, whose terms meet on
        // one relation and never cancel, for 20 s. Not asked where the work limit refuses the
        // square at once: the elimination that count needs takes time in the terms (a second
        // for 200 000 terms, whose square the work limit refuses in microseconds).
        if !self.square_passes_the_work_limit() && self.power_passes(e as usize, limit) {
            return Err(AlgebraError::TooManyTerms { limit });
        }
        // Repeated multiplication by `self`, after one square. Each step costs the terms of the
        // power so far times those of `self`, and checks the term limit as the power grows.
        // Repeated squaring multiplies two large powers instead: on a sparse polynomial that
        // is far more work (P_{3,2}^16 of the harmonic rotor, 40 terms: 47 s by squaring, 2.3 s
        // this way), and on a dense one it saves at most about a third.
        let mut acc = self.checked_square()?;
        for _ in 2..e {
            acc = acc.checked_mul(self)?;
        }
        Ok(acc)
    }

    /// `self^e` by the multinomial theorem (bounds already checked): one term per composition
    /// `e = a_1 + … + a_t`, with coefficient `e!/(a_1!…a_t!) · Π c_i^{a_i}` and monomial
    /// `Π m_i^{a_i}`; the terms are sorted once and equal monomials combined. For a short
    /// polynomial this is as many term operations as the power has terms, where repeated
    /// multiplication needs about `e` times more. The room for every term is reserved up front
    /// and a refusal, or room past
    /// [`Limits::max_reserved_bytes`](crate::Limits::max_reserved_bytes) with the terms' order
    /// and the terms combined held beside it, is
    /// `Err(TooLargeForMemory)`, not an abort or memory filled: a term limit raised far enough
    /// lets through a power of more terms than the machine can hold. (The short path of
    /// `gather::multinomial_power` is taken only when `Σ|c_i|^e < 2⁶²`, so for at most six
    /// terms its table holds at most `C(28, 5)` = 98 280 terms, and needs no cap.)
    fn multinomial_pow(&self, e: usize) -> Result<Self, AlgebraError> {
        let t = self.len();
        let compositions = binomial_u128(e as u128 + t as u128 - 1, t as u128 - 1) as usize;
        let content = || self.content.pow(e as i64).expect("nonzero content");
        if self.words() <= gather::WORDS {
            if let Some(terms) =
                gather::multinomial_power(self.layout(), self.raw_terms(), e, compositions)
            {
                return Ok(Self::from_gathered(&self.vars, content(), terms));
            }
        }
        let w = self.words();
        let layout = self.layout();
        let cap = self.vars.limits().max_reserved_bytes;
        // The room for the terms first, before any work, with what is held beside them at
        // once: their order for the sort, and the terms combined, as many as the compositions
        // when each is a monomial of its own (else counted after the sort).
        let formed = term_bytes::<C::Int>(compositions, w);
        let order_bytes = compositions as u128 * std::mem::size_of::<usize>() as u128;
        let combined = match self.affine_relations().is_empty() {
            true => formed,
            false => 0,
        };
        let (mut keys, mut coeffs) = (Vec::new(), Vec::new());
        let beside = order_bytes + combined;
        reserve_terms::<C::Int>(&mut keys, &mut coeffs, compositions, w, beside, cap)?;
        // Pascal's triangle up to e.
        let mut binom: Vec<Vec<Integer>> = vec![vec![Integer::ONE]];
        for n in 1..=e {
            let prev = &binom[n - 1];
            let mut row = vec![Integer::ONE; n + 1];
            for k in 1..n {
                row[k] = &prev[k - 1] + &prev[k];
            }
            binom.push(row);
        }
        // c_i^a for a ≤ e.
        let powers: Vec<Vec<C::Int>> = self
            .coeffs
            .iter()
            .map(|c| {
                let mut row = vec![C::Int::from_integer(Integer::ONE)];
                for a in 1..=e {
                    row.push(row[a - 1].mul(c));
                }
                row
            })
            .collect();
        // m_i − 1 word by word (wrapping): the translation that multiplies by m_i.
        let one = layout.one();
        let steps: Vec<Vec<u64>> = (0..t)
            .map(|i| {
                self.exp(i)
                    .iter()
                    .zip(one)
                    .map(|(m, b)| m.wrapping_sub(*b))
                    .collect()
            })
            .collect();
        struct Walk<'a, I> {
            t: usize,
            w: usize,
            binom: &'a [Vec<Integer>],
            powers: &'a [Vec<I>],
            steps: &'a [Vec<u64>],
            /// The partial monomial of each level of the walk, `w` words each.
            scratch: Vec<u64>,
            keys: &'a mut Vec<u64>,
            coeffs: &'a mut Vec<I>,
        }
        fn go<I: IntegerRing>(walk: &mut Walk<'_, I>, i: usize, rem: usize, c: &I) {
            let last = i + 1 == walk.t;
            let range = if last { rem..=rem } else { 0..=rem };
            let w = walk.w;
            for a in range {
                let (done, next) = walk.scratch.split_at_mut((i + 1) * w);
                let key = &done[i * w..];
                for ((n, k), s) in next[..w].iter_mut().zip(key).zip(&walk.steps[i]) {
                    *n = k.wrapping_add(s.wrapping_mul(a as u64));
                }
                let next_c = c.mul(&walk.powers[i][a]).scale(&walk.binom[rem][a]);
                if last {
                    walk.keys.extend_from_slice(&next[..w]);
                    walk.coeffs.push(next_c);
                } else {
                    go(walk, i + 1, rem - a, &next_c);
                }
            }
        }
        let mut scratch = vec![0u64; (t + 1) * w];
        scratch[..w].copy_from_slice(one);
        let mut walk = Walk {
            t,
            w,
            binom: &binom,
            powers: &powers,
            steps: &steps,
            scratch,
            keys: &mut keys,
            coeffs: &mut coeffs,
        };
        go(&mut walk, 0, e, &C::Int::from_integer(Integer::ONE));
        // Sort once, combine equal monomials: room for as many terms as there are distinct
        // monomials, beside the terms as formed and their order.
        let n = coeffs.len();
        let mut order: Vec<usize> = Vec::new();
        order
            .try_reserve_exact(n)
            .map_err(|_| too_large_for_memory::<C::Int>(n, w, 0))?;
        order.extend(0..n);
        let key = |k: usize| &keys[k * w..(k + 1) * w];
        order.sort_unstable_by(|&a, &b| key(b).cmp(key(a)));
        let distinct = 1 + order.windows(2).filter(|p| key(p[0]) != key(p[1])).count();
        let (mut out_e, mut out_c) = (Vec::new(), Vec::new());
        let held = formed + order_bytes;
        reserve_terms::<C::Int>(&mut out_e, &mut out_c, distinct, w, held, cap)?;
        let mut coeffs: Vec<Option<C::Int>> = coeffs.into_iter().map(Some).collect();
        for k in order {
            let monomial = key(k);
            let c = coeffs[k].take().expect("each term once");
            if !out_c.is_empty() && &out_e[out_e.len() - w..] == monomial {
                let top = out_c.last_mut().expect("a previous term");
                *top = top.add(&c);
            } else {
                out_e.extend_from_slice(monomial);
                out_c.push(c);
            }
        }
        Ok(Self::drop_zeros_and_normalize(
            &self.vars,
            content(),
            out_e,
            out_c,
        ))
    }

    /// Whether the polynomial is a single term with coefficient 1, such as `x` or `M ω`.
    fn has_unit_coefficient(&self) -> bool {
        self.len() == 1 && self.content.is_one() && self.coeffs[0].is_one()
    }

    /// `(c·m)^e` for a single term (bounds already checked).
    fn monomial_pow(&self, e: i64) -> Self {
        let (content, n) = if self.has_unit_coefficient() {
            (Rational::one(), self.coeffs[0].clone())
        } else {
            pow_field(&C::from_parts(&self.content, &self.coeffs[0]), e).split()
        };
        let layout = self.layout();
        let exps: Vec<i64> = (0..self.vars.len())
            .map(|j| layout.get(self.exp(0), j) * e)
            .collect();
        let mut w = vec![0u64; self.words()];
        layout.pack(&exps, &mut w);
        Self::assemble(&self.vars, content, w, vec![n])
    }
}

/// `C(n, k)`, saturating.
pub(super) fn binomial_u128(n: u128, k: u128) -> u128 {
    let k = k.min(n - k.min(n));
    let mut acc: u128 = 1;
    for j in 0..k {
        // `acc·(n − j)` is divisible by `j + 1`; past `u128`, the count is as large as any.
        match acc.checked_mul(n - j) {
            Some(x) => acc = x / (j + 1),
            None => return u128::MAX,
        }
    }
    acc
}

/// `c^e` in the field (c nonzero).
pub(crate) fn pow_field<C: Coefficient>(c: &C, e: i64) -> C {
    let z = c.to_gaussian().pow(e).expect("nonzero base");
    C::from_gaussian(&z).expect("powers stay in the field")
}

/// Room for `terms` terms of `words` words in `exps` and `coeffs`, reserved exactly, or
/// `Err(TooLargeForMemory)` if it and the `beside` bytes held with it at once would take more
/// than `cap` ([`Limits::max_reserved_bytes`](crate::Limits::max_reserved_bytes)) or the
/// allocator
/// refuses it (or its size passes `isize::MAX`): for a count of terms predicted before they
/// are formed, which a raised term limit may let grow past the machine's memory. The cap is
/// compared first, since an allocator under overcommit grants far more address space than
/// the machine can back, and the work would then fill memory.
pub(super) fn reserve_terms<I>(
    exps: &mut Vec<u64>,
    coeffs: &mut Vec<I>,
    terms: usize,
    words: usize,
    beside: u128,
    cap: u64,
) -> Result<(), AlgebraError> {
    let refused = || too_large_for_memory::<I>(terms, words, beside);
    if term_bytes::<I>(terms, words) + beside > u128::from(cap) {
        return Err(refused());
    }
    let words_needed = terms.checked_mul(words).ok_or_else(refused)?;
    exps.try_reserve_exact(words_needed)
        .map_err(|_| refused())?;
    coeffs.try_reserve_exact(terms).map_err(|_| refused())
}

/// [`AlgebraError::TooLargeForMemory`] of `terms` terms of `words` words and coefficients `I`,
/// with the `beside` bytes held with them at once.
fn too_large_for_memory<I>(terms: usize, words: usize, beside: u128) -> AlgebraError {
    AlgebraError::TooLargeForMemory {
        terms: terms as u128,
        bytes: term_bytes::<I>(terms, words) + beside,
    }
}

/// The bytes of `terms` terms of `words` words and coefficients `I`.
fn term_bytes<I>(terms: usize, words: usize) -> u128 {
    let per_term = 8 * words as u128 + std::mem::size_of::<I>() as u128;
    terms as u128 * per_term
}
