//! Exact zeros at angles that are rational multiples of π: whether `Σ c_k e^{ikφ}` vanishes at
//! `φ = 2πj/m`, decided in the cyclotomic field, so that `plot` refuses a start on a singular
//! line of `1/sin 3φ` (`φ = π/3`), where floating point only sees a small number.

use trigpoly::{Expr, GaussianRational, Rational, Var, Vars};

/// Angles at rational multiples of a full turn, `φ_j = 2π t_j`, as powers of one root of unity
/// `ζ = e^{2πi/m}` (`e^{iφ_j} = ζ^{k_j}`), written in the first angle's variable, which then
/// stands for `ζ`.
pub(crate) struct RootsOfUnity {
    /// The order `m` of `ζ`.
    order: u64,
    /// The variable that stands for `ζ`.
    carrier: Var,
    /// Each angle's `e^{iφ}` as its power of `ζ`.
    powers: Vec<(Var, Expr)>,
}

impl RootsOfUnity {
    /// The angles at the `turns` `t_j` (`φ_j = 2π t_j`); `None` when there are none, or when
    /// their common order is above [`MAX_ORDER`].
    pub(crate) fn new(vars: &Vars, turns: &[(Var, Rational)]) -> Option<Self> {
        let carrier = turns.first()?.0;
        let parts: Vec<(Var, i64, u64)> = turns
            .iter()
            .map(|(v, t)| {
                let (a, b) = t.small_parts()?;
                Some((*v, a, u64::try_from(b).ok()?))
            })
            .collect::<Option<_>>()?;
        let order = parts.iter().try_fold(1u64, |m, &(_, _, b)| {
            Some(lcm(m, b)).filter(|&m| m <= MAX_ORDER)
        })?;
        let powers = parts
            .into_iter()
            .map(|(v, a, b)| {
                let k = a.rem_euclid(b as i64) * (order / b) as i64;
                let power =
                    Expr::monomial(vars, GaussianRational::from(1), &[(carrier, k)]).ok()?;
                Some((v, power))
            })
            .collect::<Option<_>>()?;
        Some(RootsOfUnity {
            order,
            carrier,
            powers,
        })
    }

    /// Whether `e`, in which every variable but the angles has its value, is 0 at the angles;
    /// `None` when `e` holds another variable.
    pub(crate) fn vanishes(&self, e: &Expr) -> Option<bool> {
        let on_circle = e.subst_many(&self.powers).ok()?;
        let vars = on_circle.vars().clone();
        if vars
            .vars()
            .any(|v| v != self.carrier && on_circle.contains(v))
        {
            return None;
        }
        let terms: Vec<(i64, GaussianRational)> = on_circle
            .terms()
            .map(|t| (t.exponent(self.carrier), t.coeff()))
            .collect();
        vanishes_at_root_of_unity(&terms, self.order)
    }
}

/// The largest order `m` of the root of unity decided: beyond it the start is left to the
/// integration (`Φ_m` has degree up to `m − 1`, and the reduction takes `m²` steps).
pub(crate) const MAX_ORDER: u64 = 1440;

/// Whether `Σ c_k ζ^k = 0` for `ζ = e^{2πi/m}` and the Gaussian rational `terms` `(k, c_k)`:
/// exactly, as a polynomial in `ζ_M` with rational coefficients (`M = lcm(m, 4)`, `i = ζ_M^{M/4}`)
/// that the minimal polynomial of `ζ_M`, the cyclotomic `Φ_M`, divides. `None` when `m` is 0 or
/// above [`MAX_ORDER`].
pub(crate) fn vanishes_at_root_of_unity(terms: &[(i64, GaussianRational)], m: u64) -> Option<bool> {
    if m == 0 || m > MAX_ORDER {
        return None;
    }
    let big = lcm(m, 4);
    let (scale, quarter) = ((big / m) as i128, (big / 4) as i128);
    let at = |e: i128| e.rem_euclid(big as i128) as usize;
    // The polynomial in ζ_M modulo ζ_M^M − 1, of degree below M.
    let mut p = vec![Rational::zero(); big as usize];
    for (k, c) in terms {
        let e = i128::from(*k) * scale;
        p[at(e)] += &c.re;
        p[at(e + quarter)] += &c.im;
    }
    let phi = cyclotomic(big);
    Some(remainder(p, &phi).iter().all(Rational::is_zero))
}

/// The remainder of `p` divided by the monic `divisor`, both low degree first.
fn remainder(mut p: Vec<Rational>, divisor: &[i64]) -> Vec<Rational> {
    let d = divisor.len() - 1;
    while p.len() > d {
        let lead = p.pop().expect("longer than the divisor");
        if lead.is_zero() {
            continue;
        }
        let shift = p.len() - d;
        for (j, &c) in divisor[..d].iter().enumerate() {
            if c != 0 {
                p[shift + j] -= &(&lead * &Rational::from(c));
            }
        }
    }
    p
}

/// The cyclotomic polynomial `Φ_n`, its integer coefficients low degree first: for each
/// divisor `d` of `n` in turn, `x^d − 1` divided by the `Φ_e` of the divisors `e` of `d` found
/// before it, each found once.
fn cyclotomic(n: u64) -> Vec<i64> {
    let mut found: Vec<(u64, Vec<i64>)> = Vec::new();
    for d in (1..=n).filter(|&d| n.is_multiple_of(d)) {
        let mut p = vec![0i64; d as usize + 1];
        (p[0], p[d as usize]) = (-1, 1);
        for (e, phi) in &found {
            if d.is_multiple_of(*e) {
                p = exact_quotient(&p, phi);
            }
        }
        found.push((d, p));
    }
    found.pop().expect("n divides itself").1
}

/// `p / q` for a monic `q` that divides `p` (integer coefficients, low degree first).
fn exact_quotient(p: &[i64], q: &[i64]) -> Vec<i64> {
    let (n, d) = (p.len() - 1, q.len() - 1);
    let mut rest = p.to_vec();
    let mut quotient = vec![0i64; n - d + 1];
    for k in (0..=n - d).rev() {
        let c = rest[k + d];
        quotient[k] = c;
        for (j, &qj) in q.iter().enumerate() {
            rest[k + j] -= c * qj;
        }
    }
    debug_assert!(rest.iter().all(|&r| r == 0), "Φ_d divides x^n − 1");
    quotient
}

fn lcm(a: u64, b: u64) -> u64 {
    let gcd = |mut a: u64, mut b: u64| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    a / gcd(a, b) * b
}

#[cfg(test)]
mod tests {
    use super::*;

    fn g(re: i64, im: i64) -> GaussianRational {
        GaussianRational::new(Rational::from(re), Rational::from(im))
    }

    #[test]
    fn cyclotomic_polynomials_are_the_known_ones() {
        assert_eq!(cyclotomic(1), [-1, 1]);
        assert_eq!(cyclotomic(4), [1, 0, 1]);
        assert_eq!(cyclotomic(6), [1, -1, 1]);
        assert_eq!(cyclotomic(12), [1, 0, -1, 0, 1]);
        // Φ_105 is the first with a coefficient −2.
        assert!(cyclotomic(105).contains(&-2));
        assert_eq!(cyclotomic(105).len(), 48 + 1);
    }

    /// `sin 3φ = (e^{3iφ} − e^{−3iφ})/(2i)` vanishes at `φ = π/3` (`ζ_6`), not at `π/6`
    /// (`ζ_12`, where `cos 3φ` does); `e^{iφ} − i` at `φ = π/2` only; `1 + ζ + ζ²` at the
    /// cube roots.
    #[test]
    fn zeros_at_roots_of_unity_are_decided_exactly() {
        let half = GaussianRational::new(Rational::zero(), Rational::new(-1, 2));
        let sin3 = [(3, half.clone()), (-3, -&half)];
        let cos3 = [(3, g(1, 0)), (-3, g(1, 0))];
        assert_eq!(vanishes_at_root_of_unity(&sin3, 6), Some(true));
        assert_eq!(vanishes_at_root_of_unity(&sin3, 12), Some(false));
        assert_eq!(vanishes_at_root_of_unity(&cos3, 12), Some(true));
        assert_eq!(vanishes_at_root_of_unity(&cos3, 6), Some(false));
        let minus_i = [(1, g(1, 0)), (0, g(0, -1))];
        assert_eq!(vanishes_at_root_of_unity(&minus_i, 4), Some(true));
        assert_eq!(vanishes_at_root_of_unity(&minus_i, 8), Some(false));
        let cube = [(0, g(1, 0)), (1, g(1, 0)), (2, g(1, 0))];
        assert_eq!(vanishes_at_root_of_unity(&cube, 3), Some(true));
        assert_eq!(vanishes_at_root_of_unity(&cube, 1), Some(false));
        assert_eq!(vanishes_at_root_of_unity(&cube, MAX_ORDER + 1), None);
    }
}
