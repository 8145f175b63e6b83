//! Trigonometry: `cos θ`, `sin θ`, `e^{inθ}` as elements, and the view of any element in the
//! normal form `Σ c · m · cos^a θ · sin^b θ` with `b ∈ {0, 1}` per angle (`sin²θ → 1 − cos²θ`),
//! which is how elements are printed.

use rustc_hash::FxHashMap;

use super::Poly;
use crate::error::AlgebraError;
use crate::number::{
    Coefficient, GaussianAcc, GaussianInteger, GaussianRational, Integer, IntegerRing, Rational,
};
use crate::varset::{Var, VarKind, VarSet, Vars};

impl<C: Coefficient> Poly<C> {
    /// `e^{inθ}` for an angle `θ`.
    pub fn exp_i(vars: &Vars, theta: Var, n: i64) -> Result<Self, AlgebraError> {
        check_angle::<C>(vars, theta, "e^{inθ}")?;
        Self::monomial(vars, C::one(), &[(theta, n)])
    }

    /// `cos θ = (e^{iθ} + e^{−iθ})/2`.
    pub fn cos(vars: &Vars, theta: Var) -> Result<Self, AlgebraError> {
        let half = C::from_rational(Rational::new(1, 2));
        Self::monomial(vars, half.clone(), &[(theta, 1)])?
            .checked_add(&Self::exp_i(vars, theta, -1)?.scale(&half))
    }

    /// `sin θ = (e^{iθ} − e^{−iθ})/(2i)`.
    pub fn sin(vars: &Vars, theta: Var) -> Result<Self, AlgebraError> {
        let d = Self::exp_i(vars, theta, 1)?.checked_sub(&Self::exp_i(vars, theta, -1)?)?;
        // 1/(2i) = −i/2
        Ok(d.mul_i()? * &Rational::new(-1, 2))
    }

    /// The terms in the normal form `c · m · Π cos^a θ sin^b θ` (`b ≤ 1`), grouped and ordered
    /// for printing as the paper does: by trigonometric monomial, then by degree in the momenta
    /// (highest first, so `(p_x − Mωy) cos θ`), then by the monomial in the other variables.
    ///
    /// Each term's `e^{ikθ}` expands by a table of `(cos θ + i sin θ)^k` with integer
    /// coefficients, so the sums are taken over Z\[i\] (no gcd per addition) and the content
    /// multiplies each surviving sum once.
    pub fn cos_sin_terms(&self) -> Vec<CosSinTerm> {
        let angles: Vec<usize> = self.vars.angles().map(|v| v.index()).collect();
        let n = self.vars.len();
        let layout = self.layout();
        let mut tables: FxHashMap<i64, Vec<(u32, u32, GaussianInteger)>> = FxHashMap::default();
        // Keyed by the exponents (zero at the angles), then `(cos, sin)` powers per angle.
        let mut sums: FxHashMap<Vec<i64>, GaussianAcc> =
            FxHashMap::with_capacity_and_hasher(self.len(), Default::default());
        let mut key = vec![0i64; n + 2 * angles.len()];
        let mut multiples = vec![0i64; angles.len()];
        for k in 0..self.len() {
            let m = self.exp(k);
            for (j, e) in key[..n].iter_mut().enumerate() {
                *e = layout.get(m, j);
            }
            for (kj, &j) in multiples.iter_mut().zip(&angles) {
                *kj = std::mem::take(&mut key[j]);
                tables.entry(*kj).or_insert_with(|| euler_power(*kj));
            }
            let rows: Vec<&[(u32, u32, GaussianInteger)]> =
                multiples.iter().map(|kj| tables[kj].as_slice()).collect();
            let coeff = self.coeffs[k].to_gaussian_integer();
            // Every choice of one entry per angle's table (an odometer over the rows).
            let mut choice = vec![0usize; rows.len()];
            loop {
                let mut factor: Option<GaussianInteger> = None;
                for (a, (row, &i)) in rows.iter().zip(&choice).enumerate() {
                    let (cos, sin, ref g) = row[i];
                    key[n + 2 * a] = i64::from(cos);
                    key[n + 2 * a + 1] = i64::from(sin);
                    factor = Some(match factor {
                        None => g.clone(),
                        Some(f) => IntegerRing::mul(&f, g),
                    });
                }
                let acc = match sums.get_mut(key.as_slice()) {
                    Some(acc) => acc,
                    None => sums.entry(key.clone()).or_default(),
                };
                match &factor {
                    Some(f) => acc.add_mul(&coeff, f),
                    None => acc.add(&coeff),
                }
                let Some(a) = (0..rows.len())
                    .rev()
                    .find(|&a| choice[a] + 1 < rows[a].len())
                else {
                    break;
                };
                choice[a] += 1;
                choice[a + 1..].iter_mut().for_each(|i| *i = 0);
            }
        }
        let momenta: Vec<usize> = self
            .vars
            .vars()
            .filter(|&v| self.vars.variable(v).kind() == VarKind::Momentum)
            .map(|v| v.index())
            .collect();
        let mut terms: Vec<(TrigKey, i64, CosSinTerm)> = sums
            .into_iter()
            .filter_map(|(mut exps, acc)| {
                let sum = acc.finish();
                if sum.is_zero() {
                    return None;
                }
                let powers = exps[n..]
                    .chunks_exact(2)
                    .map(|p| (p[0] as u32, p[1] as u32));
                let trig = TrigMonomial {
                    powers: powers.collect(),
                };
                exps.truncate(n);
                let momentum_degree = momenta.iter().map(|&j| exps[j].abs()).sum();
                let coeff = GaussianRational::from_parts(&self.content, &sum);
                Some((
                    trig.sort_key(),
                    momentum_degree,
                    CosSinTerm { coeff, exps, trig },
                ))
            })
            .collect();
        // Trigonometric monomial first, then the momenta's degree and the exponents, both
        // descending; no two terms share all three.
        terms.sort_unstable_by(|x, y| {
            x.0.cmp(&y.0)
                .then_with(|| (y.1, &y.2.exps).cmp(&(x.1, &x.2.exps)))
        });
        terms.into_iter().map(|(_, _, term)| term).collect()
    }
}

/// [`TrigMonomial`]'s order, computed once per term.
type TrigKey = (u32, Vec<(u32, u32)>);

fn check_angle<C: Coefficient>(vars: &VarSet, v: Var, what: &str) -> Result<(), AlgebraError> {
    if vars.variable(v).kind() != VarKind::Angle {
        return Err(AlgebraError::Invalid(format!(
            "{what} needs an angle, and {} is not declared as one",
            vars.variable(v).unicode()
        )));
    }
    if !C::HAS_I {
        return Err(AlgebraError::NeedsGaussian(format!(
            "the angle {} (stored as e^{{iθ}})",
            vars.variable(v).unicode()
        )));
    }
    Ok(())
}

/// `(cos θ + i sin θ)^k` (for `k < 0`, `(cos θ − i sin θ)^{|k|}`) in normal form, as
/// `(cos power, sin power, coefficient)`. Uses `(A + sB)(c + is) = (Ac + i(1 − c²)B) + s(iA + cB)`.
fn euler_power(k: i64) -> Vec<(u32, u32, GaussianInteger)> {
    let n = k.unsigned_abs() as usize;
    let zero = GaussianInteger::default();
    let mut a = vec![GaussianInteger::from_integer(Integer::ONE)]; // A(c), by powers of c
    let mut b: Vec<GaussianInteger> = vec![]; // B(c)
    for _ in 0..n {
        let mut na = vec![zero.clone(); a.len().max(b.len() + 2) + 1];
        let mut nb = vec![zero.clone(); a.len().max(b.len() + 1) + 1];
        for (p, x) in a.iter().enumerate() {
            na[p + 1] = na[p + 1].add(x); // A c
            nb[p] = nb[p].add(&x.mul_i()); // s · iA
        }
        for (p, x) in b.iter().enumerate() {
            let ix = x.mul_i();
            na[p] = na[p].add(&ix); // i B
            na[p + 2] = na[p + 2].sub(&ix); // −i c² B
            nb[p + 1] = nb[p + 1].add(x); // s · cB
        }
        a = na;
        b = nb;
    }
    let mut out = Vec::new();
    for (p, x) in a.into_iter().enumerate() {
        if !x.is_zero() {
            out.push((p as u32, 0, if k < 0 { x.conj() } else { x }));
        }
    }
    for (p, x) in b.into_iter().enumerate() {
        if !x.is_zero() {
            out.push((p as u32, 1, if k < 0 { x.conj() } else { x }));
        }
    }
    out
}

/// A product `Π cos^a θ sin^b θ` over the angles of a variable set, in their order; ordered
/// for printing: fewer factors first, cosines before sines.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TrigMonomial {
    /// `(a, b)` per angle.
    pub powers: Vec<(u32, u32)>,
}

impl TrigMonomial {
    /// Whether every power is zero.
    pub fn is_one(&self) -> bool {
        self.powers.iter().all(|&(a, b)| a == 0 && b == 0)
    }

    fn sort_key(&self) -> TrigKey {
        let degree = self.powers.iter().map(|&(a, b)| a + b).sum();
        (degree, self.powers.iter().map(|&(a, b)| (b, a)).collect())
    }
}

impl Ord for TrigMonomial {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.sort_key().cmp(&other.sort_key())
    }
}

impl PartialOrd for TrigMonomial {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

/// One term of the cos/sin normal form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CosSinTerm {
    /// The coefficient (rational for a real function).
    pub coeff: GaussianRational,
    /// Exponents of every variable (zero at the angles).
    pub exps: Vec<i64>,
    /// The trigonometric part.
    pub trig: TrigMonomial,
}
