//! Exact linear algebra over Q(i): row reduction, solving, rank with pivots.

use trigpoly::GaussianRational as Q;

/// A dense matrix over Q(i).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Matrix {
    rows: usize,
    cols: usize,
    data: Vec<Q>,
}

/// The result of row reduction: the reduced matrix, its pivot columns and the row each pivot
/// came from in the original matrix.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Reduction {
    /// Reduced row echelon form.
    pub reduced: Matrix,
    /// Pivot columns, in order.
    pub pivot_cols: Vec<usize>,
    /// For each pivot, the original row it came from.
    pub pivot_rows: Vec<usize>,
}

impl Matrix {
    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Self {
        Matrix {
            rows,
            cols,
            data: vec![Q::default(); rows * cols],
        }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Entry `(r, c)`.
    ///
    /// # Panics
    ///
    /// If `r` or `c` is out of range (a column past the last would read the next row's
    /// entry).
    pub fn get(&self, r: usize, c: usize) -> &Q {
        &self.data[self.index(r, c)]
    }

    /// Sets entry `(r, c)`.
    ///
    /// # Panics
    ///
    /// If `r` or `c` is out of range, as [`Matrix::get`].
    pub fn set(&mut self, r: usize, c: usize, v: Q) {
        let k = self.index(r, c);
        self.data[k] = v;
    }

    /// Where entry `(r, c)` is stored.
    #[track_caller]
    fn index(&self, r: usize, c: usize) -> usize {
        assert!(
            r < self.rows && c < self.cols,
            "entry ({r}, {c}) of a {} × {} matrix",
            self.rows,
            self.cols
        );
        r * self.cols + c
    }

    /// Gauss–Jordan elimination (exact).
    pub fn reduce(&self) -> Reduction {
        let mut m = self.clone();
        let mut origin: Vec<usize> = (0..self.rows).collect();
        let mut pivot_cols = Vec::new();
        let mut pivot_rows = Vec::new();
        let mut r = 0;
        for c in 0..m.cols {
            if r == m.rows {
                break;
            }
            let Some(p) = (r..m.rows).find(|&i| !m.get(i, c).is_zero()) else {
                continue;
            };
            m.swap_rows(r, p);
            origin.swap(r, p);
            let inv = m.get(r, c).try_inv().expect("pivot is nonzero");
            for j in c..m.cols {
                let v = m.get(r, j) * &inv;
                m.set(r, j, v);
            }
            for i in 0..m.rows {
                if i == r || m.get(i, c).is_zero() {
                    continue;
                }
                let f = m.get(i, c).clone();
                for j in c..m.cols {
                    let v = m.get(i, j) - &(&f * m.get(r, j));
                    m.set(i, j, v);
                }
            }
            pivot_cols.push(c);
            pivot_rows.push(origin[r]);
            r += 1;
        }
        Reduction {
            reduced: m,
            pivot_cols,
            pivot_rows,
        }
    }

    fn swap_rows(&mut self, a: usize, b: usize) {
        if a != b {
            for j in 0..self.cols {
                self.data.swap(a * self.cols + j, b * self.cols + j);
            }
        }
    }

    /// The rank.
    pub fn rank(&self) -> usize {
        self.reduce().pivot_cols.len()
    }

    /// One solution of `self · x = b` (free unknowns set to zero), or `None` if inconsistent.
    ///
    /// # Panics
    ///
    /// If `b` does not have one entry per row.
    pub fn solve(&self, b: &[Q]) -> Option<Vec<Q>> {
        assert_eq!(
            b.len(),
            self.rows,
            "the right-hand side of a system of {} equations",
            self.rows
        );
        let mut aug = Matrix::zeros(self.rows, self.cols + 1);
        for (i, bi) in b.iter().enumerate() {
            for j in 0..self.cols {
                aug.set(i, j, self.get(i, j).clone());
            }
            aug.set(i, self.cols, bi.clone());
        }
        let red = aug.reduce();
        if red.pivot_cols.last() == Some(&self.cols) {
            return None;
        }
        let mut x = vec![Q::default(); self.cols];
        for (k, &c) in red.pivot_cols.iter().enumerate() {
            x[c] = red.reduced.get(k, self.cols).clone();
        }
        Some(x)
    }

    /// The determinant of a square matrix.
    ///
    /// # Panics
    ///
    /// If the matrix is not square.
    pub fn determinant(&self) -> Q {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        let mut m = self.clone();
        let mut det = Q::from(1);
        for c in 0..m.cols {
            let Some(p) = (c..m.rows).find(|&i| !m.get(i, c).is_zero()) else {
                return Q::default();
            };
            if p != c {
                m.swap_rows(c, p);
                det = -det;
            }
            let pivot = m.get(c, c).clone();
            det = &det * &pivot;
            let inv = pivot.try_inv().expect("nonzero");
            for i in c + 1..m.rows {
                if m.get(i, c).is_zero() {
                    continue;
                }
                let f = m.get(i, c) * &inv;
                for j in c..m.cols {
                    let v = m.get(i, j) - &(&f * m.get(c, j));
                    m.set(i, j, v);
                }
            }
        }
        det
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(v: i64) -> Q {
        Q::from(v)
    }

    #[test]
    fn solve_and_rank() {
        let mut m = Matrix::zeros(3, 3);
        for (i, row) in [[1, 2, 3], [2, 4, 6], [1, 0, 1]].iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                m.set(i, j, q(v));
            }
        }
        assert_eq!(m.rank(), 2);
        assert_eq!(m.determinant(), q(0));
        let x = m.solve(&[q(6), q(12), q(2)]).unwrap();
        for (i, row) in [[1, 2, 3], [2, 4, 6], [1, 0, 1]].iter().enumerate() {
            let lhs = row
                .iter()
                .zip(&x)
                .fold(q(0), |acc, (&a, xv)| acc + &q(a) * xv);
            assert_eq!(lhs, [q(6), q(12), q(2)][i]);
        }
        assert!(m.solve(&[q(1), q(1), q(1)]).is_none());
    }

    /// An entry out of range is refused: `(0, 3)` of a 3 × 3 matrix read `(1, 0)`.
    #[test]
    #[should_panic(expected = "entry (0, 3) of a 3 × 3 matrix")]
    fn entry_past_the_last_column() {
        let mut m = Matrix::zeros(3, 3);
        m.set(1, 0, q(5));
        m.get(0, 3);
    }

    /// A right-hand side shorter than the rows is refused: the missing rows' equations were
    /// dropped, and `x = 1, y = 0` "solved" `x = 1, x = 2`.
    #[test]
    #[should_panic(expected = "the right-hand side of a system of 2 equations")]
    fn solve_takes_one_value_per_row() {
        let mut m = Matrix::zeros(2, 2);
        m.set(0, 0, q(1));
        m.set(1, 0, q(1));
        m.solve(&[q(1)]);
    }
}
