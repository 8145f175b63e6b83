//! A combination of columns that uses as few of them as the columns' relations allow.
//!
//! Where the generators have relations, an expression in them is one of several: Kepler's
//! `A_x² + A_y² = k² + 2 H L²/M` lets `2 H L²/M` also read `A_x² + A_y² − k²`. The
//! echelon's solution uses its pivot columns, the lowest-degree monomials first, and so picks
//! the longer form. [`Relations::shorter`] subtracts multiples of the kernel's vectors (the
//! relations at the fixed values) while each takes a column off, and keeps the result only
//! if it is checked exactly to give the same target.

use trigpoly::Rational;

use crate::modular::{self, CombinationSums, Field, Fp, SparseVec};

/// The relations among the columns modulo `p` ([`modular::kernel_mod_p`]), found once for
/// every target of a span, and the sum in which each shorter combination is checked.
pub(super) struct Relations {
    kernel: Vec<SparseVec<Fp>>,
    sums: CombinationSums,
}

impl Relations {
    /// The relations among `columns`, of `rows` rows; `None` when they cannot be found
    /// modulo `p` (a denominator divisible by it), which leaves every solution as it is.
    pub(super) fn new(columns: &[SparseVec<Rational>], rows: usize) -> Option<Self> {
        Some(Relations {
            kernel: modular::kernel_mod_p(columns, rows)?,
            sums: CombinationSums::new(),
        })
    }

    /// A combination of `columns` equal to `target` with fewer columns than `solution` (one
    /// such), as few as a greedy walk over the relations finds, checked exactly; `None` when
    /// no relation shortens it or the shorter one is not confirmed.
    pub(super) fn shorter(
        &mut self,
        columns: &[SparseVec<Rational>],
        solution: &SparseVec<Rational>,
        target: &SparseVec<Rational>,
    ) -> Option<SparseVec<Rational>> {
        if self.kernel.is_empty() || solution.len() < 2 {
            return None;
        }
        let shorter = shortest_by(modular::to_fp(solution)?, &self.kernel);
        if shorter.len() >= solution.len() {
            return None;
        }
        modular::reconstruct_vec(&shorter).filter(|found| self.sums.equals(columns, found, target))
    }
}

/// `x` less multiples of the `kernel`'s vectors, one at a time, each the one that leaves the
/// fewest entries, while that is fewer than before.
fn shortest_by<F: Field>(mut x: SparseVec<F>, kernel: &[SparseVec<F>]) -> SparseVec<F> {
    loop {
        let mut best: Option<SparseVec<F>> = None;
        for k in kernel {
            for (j, kj) in k {
                let Some(xj) = entry(&x, *j) else {
                    continue;
                };
                // x − (x_j/k_j)·k has no entry at j.
                let candidate = minus_multiple(&x, &xj.mul(&kj.inv()), k);
                if candidate.len() < best.as_ref().map_or(x.len(), Vec::len) {
                    best = Some(candidate);
                }
            }
        }
        match best {
            Some(shorter) => x = shorter,
            None => return x,
        }
    }
}

/// The entry of `x` at index `j`, if it has one.
fn entry<F: Field>(x: &SparseVec<F>, j: usize) -> Option<&F> {
    x.binary_search_by_key(&j, |(i, _)| *i)
        .ok()
        .map(|at| &x[at].1)
}

/// `x − a·k`, both sorted by index, without zero entries.
fn minus_multiple<F: Field>(x: &SparseVec<F>, a: &F, k: &SparseVec<F>) -> SparseVec<F> {
    let mut out = Vec::with_capacity(x.len() + k.len());
    let (mut xs, mut ks) = (x.iter().peekable(), k.iter().peekable());
    loop {
        let (i, value) = match (xs.peek(), ks.peek()) {
            (None, None) => return out,
            (Some((i, xi)), None) => {
                xs.next();
                (*i, xi.clone())
            }
            (None, Some((i, ki))) => {
                ks.next();
                (*i, F::zero().sub(&a.mul(ki)))
            }
            (Some((i, xi)), Some((l, kl))) => match i.cmp(l) {
                std::cmp::Ordering::Less => {
                    xs.next();
                    (*i, xi.clone())
                }
                std::cmp::Ordering::Greater => {
                    ks.next();
                    (*l, F::zero().sub(&a.mul(kl)))
                }
                std::cmp::Ordering::Equal => {
                    xs.next();
                    ks.next();
                    (*i, xi.sub(&a.mul(kl)))
                }
            },
        };
        if !value.is_zero() {
            out.push((i, value));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{minus_multiple, shortest_by, Relations};
    use crate::modular::{CombinationSums, Fp, SparseVec};
    use proptest::prelude::*;
    use trigpoly::Rational;

    fn fp(entries: &[(usize, i64)]) -> SparseVec<Fp> {
        entries.iter().map(|&(i, x)| (i, Fp::from_i64(x))).collect()
    }

    fn q(entries: &[(usize, i64)]) -> SparseVec<Rational> {
        entries
            .iter()
            .map(|&(i, x)| (i, Rational::from(x)))
            .collect()
    }

    #[test]
    fn a_multiple_is_subtracted_entry_by_entry_and_zeros_dropped() {
        let x = fp(&[(0, 1), (2, 4), (5, 3)]);
        let k = fp(&[(1, 1), (2, 2), (6, -1)]);
        // x − 2k
        assert_eq!(
            minus_multiple(&x, &Fp::from_i64(2), &k),
            fp(&[(0, 1), (1, -2), (5, 3), (6, 2)])
        );
    }

    #[test]
    fn a_relation_that_covers_the_solution_leaves_one_column() {
        // Columns 0, 1, 2 and 3 with the relation c0 + c1 − c2 − 2·c3 = 0 (Kepler's
        // k² + A_x² ... shape): 5·(c0 + c1 − c2) is 10·c3.
        let kernel = vec![fp(&[(0, 1), (1, 1), (2, -1), (3, -2)])];
        let x = fp(&[(0, 5), (1, 5), (2, -5)]);
        assert_eq!(shortest_by(x, &kernel), fp(&[(3, 10)]));
        // A solution the relation cannot shorten is kept.
        let y = fp(&[(0, 1), (2, 1)]);
        assert_eq!(shortest_by(y.clone(), &kernel), y);
    }

    #[test]
    fn the_shorter_solution_is_checked_against_the_columns() {
        // Rows 0 and 1: c0 = (1, 0), c1 = (0, 1), c2 = (1, 1), so c0 + c1 − c2 = 0.
        let columns = vec![q(&[(0, 1)]), q(&[(1, 1)]), q(&[(0, 1), (1, 1)])];
        let mut relations = Relations::new(&columns, 2).expect("modulo p");
        let target = q(&[(0, 3), (1, 3)]);
        let long = q(&[(0, 3), (1, 3)]);
        assert_eq!(
            relations.shorter(&columns, &long, &target),
            Some(q(&[(2, 3)]))
        );
        // A relation that is wrong (not one of the columns') is never used: the result is
        // checked, and the solution kept.
        let mut wrong = Relations {
            kernel: vec![fp(&[(0, 1), (1, 1), (2, -2)])],
            sums: CombinationSums::new(),
        };
        let long = q(&[(0, 3), (1, 3)]);
        assert_eq!(wrong.shorter(&columns, &long, &target), None);
    }

    /// The shorter solutions of one span's targets are checked in one sum, grown once to the
    /// largest row they touch: a sum for each check grew to that row again every time (here
    /// 10 checks of 200 rows).
    #[test]
    fn the_targets_of_a_span_are_checked_in_one_sum() {
        // c0 = e_199, c1 = e_0, c2 = e_0 + e_199: c0 + c1 − c2 = 0.
        let rows = 200;
        let columns = vec![q(&[(199, 1)]), q(&[(0, 1)]), q(&[(0, 1), (199, 1)])];
        let mut relations = Relations::new(&columns, rows).expect("modulo p");
        let before = crate::modular::SUMS_GROWN.get();
        for k in 1..=10 {
            let target = q(&[(0, k), (199, k)]);
            let long = q(&[(0, k), (1, k)]);
            let shorter = relations.shorter(&columns, &long, &target);
            assert_eq!(shorter, Some(q(&[(2, k)])), "k = {k}");
        }
        let grown = crate::modular::SUMS_GROWN.get() - before;
        assert!(grown <= rows, "10 checks grew their sums by {grown} rows");
    }

    /// Columns over a few rows from small integers, so that some depend on others.
    fn columns() -> impl Strategy<Value = Vec<SparseVec<Rational>>> {
        let column = proptest::collection::vec(-2i64..3, 4).prop_map(|entries| {
            entries
                .into_iter()
                .enumerate()
                .filter(|(_, x)| *x != 0)
                .map(|(i, x)| (i, Rational::from(x)))
                .collect::<SparseVec<Rational>>()
        });
        proptest::collection::vec(column, 2..9)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// Whatever the columns' relations, the solution given back is one: it sums to the
        /// target exactly, and it has no more columns than the one given.
        #[test]
        fn the_fewest_columns_still_make_the_target(
            columns in columns(),
            weights in proptest::collection::vec(-3i64..4, 8),
        ) {
            let solution: SparseVec<Rational> = weights
                .iter()
                .take(columns.len())
                .enumerate()
                .filter(|(_, w)| **w != 0)
                .map(|(j, w)| (j, Rational::from(*w)))
                .collect();
            let mut target = vec![Rational::from(0); 4];
            for (j, w) in &solution {
                for (i, a) in &columns[*j] {
                    target[*i] += w * a;
                }
            }
            let target: SparseVec<Rational> = target
                .into_iter()
                .enumerate()
                .filter(|(_, x)| *x != Rational::from(0))
                .collect();
            let mut relations = Relations::new(&columns, 4).expect("small integers");
            if let Some(fewer) = relations.shorter(&columns, &solution, &target) {
                prop_assert!(CombinationSums::new().equals(&columns, &fewer, &target));
                prop_assert!(fewer.len() < solution.len());
            }
        }
    }
}
