//! The columns of the closure's linear algebra: each generator monomial's terms read once
//! (`TermTable`), the rows they make at fixed parameter values (`Rows`), and the checks that
//! a found combination equals its target.

use rustc_hash::FxHashMap;

use trigpoly::{Expr, Rational, Var};

use crate::modular::SparseVec;

/// A polynomial's terms as the columns read them, read once: their exponents in one flat
/// table, in variable order, and the real and imaginary parts of their coefficients. A real
/// function's terms in `e^{−ikθ}` are left out when `conjugates_follow` (see `closure_of`).
pub(super) struct TermTable {
    /// Exponents per term.
    width: usize,
    exponents: Vec<i64>,
    parts: Vec<(Rational, Rational)>,
}

impl TermTable {
    pub(super) fn new(e: &Expr, angles: &[Var], conjugates_follow: bool) -> Self {
        let width = e.vars().len();
        let mut exponents = Vec::with_capacity(e.len() * width);
        let mut parts = Vec::with_capacity(e.len());
        for t in e.terms() {
            let ex = t.exponents();
            let first_turn = angles.iter().map(|v| ex[v.index()]).find(|&k| k != 0);
            if conjugates_follow && first_turn.is_some_and(|k| k < 0) {
                continue;
            }
            exponents.extend(ex);
            let c = t.coeff();
            parts.push((c.re, c.im));
        }
        TermTable {
            width,
            exponents,
            parts,
        }
    }
}

/// The rows of the closure's linear system, numbered as they are first met: a row is a
/// monomial's exponents and, last, 0 or 1 for the real or imaginary part of its coefficient.
/// A key of at most 16 entries, each in `i8`, the usual case, is packed into one `u128`,
/// which hashes and compares in a few instructions, where a vector's key is read through a
/// pointer (with symbolic parameters, every column's every term is looked up); any other
/// goes by its entries.
#[derive(Default)]
pub(super) struct Rows {
    packed: FxHashMap<u128, usize>,
    wide: FxHashMap<Vec<i64>, usize>,
    /// The key being looked up, reused from term to term.
    key: Vec<i64>,
}

impl Rows {
    pub(super) fn len(&self) -> usize {
        self.packed.len() + self.wide.len()
    }

    /// The row of `self.key`, a new one if it has none.
    fn row(&mut self) -> usize {
        let next = self.len();
        match pack(&self.key) {
            Some(k) => *self.packed.entry(k).or_insert(next),
            None => match self.wide.get(self.key.as_slice()) {
                Some(&row) => row,
                None => {
                    self.wide.insert(self.key.clone(), next);
                    next
                }
            },
        }
    }

    /// The column of the terms `e`, times `i` when `times_i`, times the parameters' monomial
    /// `shift` (variable index, power).
    pub(super) fn vectorize(
        &mut self,
        e: &TermTable,
        times_i: bool,
        shift: &[(usize, i64)],
    ) -> SparseVec<Rational> {
        let mut out = Vec::with_capacity(2 * e.parts.len());
        for (ex, (re, im)) in e.exponents.chunks_exact(e.width).zip(&e.parts) {
            self.key.clear();
            self.key.extend_from_slice(ex);
            for &(j, k) in shift {
                self.key[j] += k;
            }
            self.key.push(0);
            let (re, im) = if times_i {
                (-im, re.clone())
            } else {
                (re.clone(), im.clone())
            };
            for (part, x) in [(0, re), (1, im)] {
                if x.is_zero() {
                    continue;
                }
                *self.key.last_mut().expect("the part") = part;
                out.push((self.row(), x));
            }
        }
        out
    }
}

/// `key` packed into a `u128`, a byte an entry, when it has at most 16 entries, each in
/// `i8`: distinct keys of one length give distinct values.
fn pack(key: &[i64]) -> Option<u128> {
    if key.len() > 16 {
        return None;
    }
    key.iter().try_fold(0u128, |packed, &e| {
        let byte = i8::try_from(e).ok()? as u8;
        Some(packed << 8 | u128::from(byte))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row's key packs into one `u128` exactly when it has at most 16 entries in `i8`, and
    /// keys of one length that differ anywhere (sign, last entry, first) pack differently;
    /// rows are numbered as first met, whichever way their keys go.
    #[test]
    fn row_keys_pack_only_when_they_fit_and_stay_distinct() {
        let keys: Vec<Vec<i64>> = vec![
            vec![0, 0, 0],
            vec![0, 0, 1],
            vec![1, 0, 0],
            vec![-1, 0, 0],
            vec![0, -1, 0],
            vec![127, -128, 0],
            vec![-128, 127, 0],
        ];
        let packed: Vec<u128> = keys.iter().map(|k| pack(k).expect("fits")).collect();
        for (i, a) in packed.iter().enumerate() {
            for b in &packed[i + 1..] {
                assert_ne!(a, b);
            }
        }
        assert_eq!(pack(&[128, 0]), None);
        assert_eq!(pack(&[-129, 0]), None);
        assert_eq!(pack(&[0; 17]), None);
        assert!(pack(&[0; 16]).is_some());
        let mut rows = Rows::default();
        let mut row = |key: &[i64]| {
            rows.key = key.to_vec();
            rows.row()
        };
        assert_eq!(row(&[0, 0, 1]), 0);
        assert_eq!(row(&[300, 0, 1]), 1);
        assert_eq!(row(&[-1, 0, 1]), 2);
        assert_eq!(row(&[300, 0, 1]), 1);
        assert_eq!(row(&[0, 0, 1]), 0);
        assert_eq!(rows.len(), 3);
    }
}
