//! Trigonometry: `cos θ`, `sin θ`, `e^{inθ}` as elements, and the view of any element in the
//! normal form `Σ c · m · cos^a θ · sin^b θ` with `b ∈ {0, 1}` per angle (`sin²θ → 1 − cos²θ`),
//! which is how elements are printed.

use rustc_hash::FxHashMap;

use super::Poly;
use crate::error::{AlgebraError, AngleUse};
use crate::number::{
    Coefficient, GaussianAcc, GaussianInteger, GaussianRational, Integer, IntegerRing, Rational,
};
use crate::print::{Angles, Style};
use crate::varset::{Var, VarKind, VarSet, Vars};

impl<C: Coefficient> Poly<C> {
    /// `e^{inθ}` for an angle `θ`.
    pub fn exp_i(vars: &Vars, theta: Var, n: i64) -> Result<Self, AlgebraError> {
        check_angle::<C>(vars, theta)?;
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

    /// A part of the element short enough to print, for one too long to print whole: every
    /// term of the first `k` of its monomials outside the angles, in the order of its terms
    /// (lexicographic), and how many such monomials it has in all. The cos/sin normal form
    /// combines only terms that share their monomial outside the angles, so each printed term
    /// of the part is a printed term of the whole; without angles the part is the first `k`
    /// terms.
    ///
    /// ```
    /// use trigpoly::{Poly, GaussianRational, Vars};
    /// let vars = Vars::builder().coordinate("x").angle("θ").build().unwrap();
    /// let f = Poly::<GaussianRational>::parse(&vars, "x^3*cos(θ) + x^2 + x^2*sin(θ) + 5").unwrap();
    /// // Its monomials outside θ: x³, x² and 1; the part keeps every term of the first two.
    /// let (part, monomials) = f.leading_part(2);
    /// assert_eq!(monomials, 3);
    /// assert_eq!(part, Poly::parse(&vars, "x^3*cos(θ) + x^2 + x^2*sin(θ)").unwrap());
    /// ```
    pub fn leading_part(&self, k: usize) -> (Self, usize) {
        let keep = self.outside_angles();
        let outside =
            |t: usize| -> Vec<u64> { self.exp(t).iter().zip(&keep).map(|(m, k)| m & k).collect() };
        let mut numbers: FxHashMap<Vec<u64>, usize> = Default::default();
        let mut exps = Vec::new();
        let mut coeffs = Vec::new();
        for t in 0..self.len() {
            let next = numbers.len();
            let number = *numbers.entry(outside(t)).or_insert(next);
            if number < k {
                exps.extend_from_slice(self.exp(t));
                coeffs.push(self.coeffs[t].clone());
            }
        }
        let part = Self::from_sorted(&self.vars, self.content.clone(), exps, coeffs);
        (part, numbers.len())
    }

    /// The mask of a packed monomial with the angles' fields cleared: `m & mask`, word by
    /// word, is a term's monomial outside the angles.
    fn outside_angles(&self) -> Vec<u64> {
        let layout = self.layout();
        let mut keep = vec![u64::MAX; layout.words];
        for theta in self.vars.angles() {
            let (w, shift) = layout.field(theta.index());
            keep[w] &= !(layout.field_mask() << shift);
        }
        keep
    }

    /// A bound on the number of terms the element prints as, its angles in the form `angles`
    /// ([`Poly::harmonic_terms`] or [`Poly::cos_sin_terms`]), found without forming them: over
    /// the terms that share a monomial outside the angles, the smaller of `Σ Π n_k` (each
    /// `e^{ikθ}` is `|k| + 1` terms `cos^j θ sin^b θ` in powers) or, in harmonics, `Σ 2` (each
    /// `e^{ik·θ}` is `cos(k·θ)` and `sin(k·θ)`, `1` for `k = 0`), and `Π (2K + 1)`, for the
    /// largest multiple `K` of each angle among them.
    pub fn printed_terms_bound(&self, angles_form: Angles) -> u64 {
        let angles: Vec<usize> = self.vars.angles().map(|v| v.index()).collect();
        if angles.is_empty() {
            return self.len() as u64;
        }
        let layout = self.layout();
        let keep = self.outside_angles();
        // Per monomial outside the angles: the sum of the expansions, the largest multiples.
        let mut groups: FxHashMap<Vec<u64>, (u64, Vec<u64>)> = Default::default();
        for t in 0..self.len() {
            let m = self.exp(t);
            let outside: Vec<u64> = m.iter().zip(&keep).map(|(m, k)| m & k).collect();
            let (sum, largest) = groups
                .entry(outside)
                .or_insert_with(|| (0, vec![0; angles.len()]));
            let mut expansion = 1u64;
            for (a, &j) in angles.iter().enumerate() {
                let k = layout.get(m, j).unsigned_abs();
                if angles_form == Angles::Powers {
                    expansion = expansion.saturating_mul(k + 1);
                } else if k != 0 {
                    expansion = 2;
                }
                largest[a] = largest[a].max(k);
            }
            *sum = sum.saturating_add(expansion);
        }
        groups
            .values()
            .map(|(sum, largest)| {
                let whole = largest
                    .iter()
                    .fold(1u64, |p, &k| p.saturating_mul(2 * k + 1));
                (*sum).min(whole)
            })
            .fold(0u64, u64::saturating_add)
    }

    /// Refuses to print an element whose printed form, its angles in the process's form
    /// ([`Angles::current`]), could have more terms than the term limit
    /// ([`Poly::printed_terms_bound`]): in powers, `e^{−60iθ}` times 40 000 terms prints 2.4
    /// million, some 250 MB of text.
    pub fn check_printable(&self) -> Result<(), AlgebraError> {
        let angles = Angles::current();
        let terms = self.printed_terms_bound(angles);
        let limit = self.vars.limits().max_terms;
        match terms > limit as u64 {
            true => Err(AlgebraError::TooManyPrintedTerms {
                terms,
                limit,
                angles,
            }),
            false => Ok(()),
        }
    }

    /// The element as the paper writes a harmonic, `r cos(m·θ)` or `r sin(m·θ)` for a rational
    /// `r ≠ 0` and integers `m` over the angles, when it is one: `(unicode, latex)`, such as
    /// `cos(3φ)` and `\cos(3\varphi)` for `cos(3*phi)`, `sin(q1 − q2)`, or `cos φ` (one angle
    /// without parentheses, as the printer writes it). `None` for anything else, whose
    /// normal form (`−3 cos φ + 4 cos³φ`) is how it prints. A declared denominator shows so.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder().angle("phi").angle("q").build().unwrap();
    /// let shown = |s: &str| Expr::parse(&vars, s).unwrap().as_harmonic().map(|h| h.0);
    /// assert_eq!(shown("cos(3*phi)").as_deref(), Some("cos(3φ)"));
    /// assert_eq!(shown("-2*sin(phi - 2*q)").as_deref(), Some("−2 sin(φ − 2q)"));
    /// assert_eq!(shown("cos(phi)^2"), None);
    /// ```
    pub fn as_harmonic(&self) -> Option<(String, String)> {
        let terms: Vec<_> = self.terms().collect();
        let [a, b] = terms.as_slice() else {
            return None;
        };
        let angles: Vec<Var> = self.vars.angles().collect();
        // Every variable outside the angles absent, and the two exponents opposite.
        let outside = self
            .vars
            .vars()
            .filter(|v| !angles.contains(v))
            .any(|v| a.exponent(v) != 0 || b.exponent(v) != 0);
        let m: Vec<i64> = angles.iter().map(|&v| a.exponent(v)).collect();
        if outside
            || m.iter().all(|&k| k == 0)
            || angles.iter().any(|&v| b.exponent(v) != -a.exponent(v))
        {
            return None;
        }
        // `m` with its first nonzero component positive, and the coefficients of `e^{im·θ}`
        // and of `e^{−im·θ}`.
        let positive = m.iter().find(|&&k| k != 0).is_some_and(|&k| k > 0);
        let (ca, cb) = (a.coeff().to_gaussian(), b.coeff().to_gaussian());
        let (m, plus, minus) = match positive {
            true => (m, ca, cb),
            false => (m.iter().map(|k| -k).collect(), cb, ca),
        };
        // r cos = (r/2)(e^{i·} + e^{−i·}); r sin = (r/2i)(e^{i·} − e^{−i·}).
        let (function, r) = if plus == minus && plus.is_real() {
            ("cos", &plus.re * &Rational::from(2))
        } else if plus.re.is_zero() && minus.re.is_zero() && plus.im == -&minus.im {
            ("sin", &minus.im * &Rational::from(2))
        } else {
            return None;
        };
        let harmonic = Harmonic {
            function,
            r,
            multiples: angles.into_iter().zip(m).filter(|&(_, k)| k != 0).collect(),
        };
        Some((
            harmonic.write(&self.vars, Style::Unicode),
            harmonic.write(&self.vars, Style::Latex),
        ))
    }

    /// The terms in the normal form `c · m · Π cos^a θ sin^b θ` (`b ≤ 1`), grouped and ordered
    /// for printing as the paper does: by trigonometric monomial, then by degree in the momenta
    /// (highest first, so `(p_x − Mωy) cos θ`), then by the monomial in the other variables,
    /// a denominator other than a parameter's compared last (`β/x² + γ/y²`, `PrintOrder`).
    ///
    /// Each term's `e^{ikθ}` expands by a table of `(cos θ + i sin θ)^k` with integer
    /// coefficients, so the sums are taken over Z\[i\] (no gcd per addition) and the content
    /// multiplies each surviving sum once.
    pub fn cos_sin_terms(&self) -> Vec<CosSinTerm> {
        self.trig_terms(Conversion::EachAngle(euler_powers))
    }

    /// The terms in the harmonic form `c · m · Π cos kθ` or `sin kθ` (`k ≥ 0` per angle, one
    /// function each), as the paper writes an angle's part (`A cos 2θ + B sin 2θ`), grouped
    /// and ordered as [`Poly::cos_sin_terms`]: the constant part first, then `cos θ`, `sin θ`,
    /// `cos 2θ`, `sin 2θ`, …. Each term's [`CosSinTerm::trig`] holds `(k, 0)` for `cos kθ` and
    /// `(0, k)` for `sin kθ` (`(0, 0)` for an angle absent): `e^{ikθ} = cos kθ + i sin kθ`,
    /// read off the stored exponents, so nothing is linearised.
    ///
    /// Over several angles the harmonics are those of the angles jointly, as a physicist
    /// writes them: `e^{i(kθ + lφ)}` is `cos(kθ + lφ) + i sin(kθ + lφ)`, its multiples made
    /// to start positive (`cos(θ − φ)`, never `cos(−θ + φ)`), where harmonics per angle wrote
    /// `cos θ cos φ + sin θ sin φ`. Such a term holds every nonzero multiple in the same
    /// place, `(|k|, 0)` per angle for a cosine, `(0, |k|)` for a sine, and the angles whose
    /// multiple is negative in [`TrigMonomial::minus`].
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder().angle("theta").build().unwrap();
    /// let f = Expr::parse(&vars, "cos(theta)^2").unwrap();
    /// let powers: Vec<_> = f.harmonic_terms().iter().map(|t| t.trig.powers[0]).collect();
    /// assert_eq!(powers, [(0, 0), (2, 0)]); // 1/2 + 1/2 cos 2θ
    /// ```
    pub fn harmonic_terms(&self) -> Vec<CosSinTerm> {
        match self.vars.angles().nth(1) {
            None => self.trig_terms(Conversion::EachAngle(harmonic_parts)),
            Some(_) => self.trig_terms(Conversion::Joint),
        }
    }

    /// The terms with the angles' `e^{ik·θ}` written as `conversion` says.
    fn trig_terms(&self, conversion: Conversion) -> Vec<CosSinTerm> {
        let angles: Vec<usize> = self.vars.angles().map(|v| v.index()).collect();
        let n = self.vars.len();
        let layout = self.layout();
        // The sums are keyed by two numbers: the monomial in the variables (the angles'
        // exponents cleared once converted) and the trigonometric monomial (`(cos, sin)`
        // powers per angle converted, [`TrigMonomial::from_key`]), each numbered once: a hash of two words per sum, where
        // a vector of every exponent took a hash of the vector and an allocation.
        let mut groups = Numbering::<i64>::default();
        let mut trigs = Numbering::<u32>::default();
        let none = trigs.number(&vec![0u32; 2 * angles.len()]);
        let mut exps = vec![0i64; n];
        // The terms, then after each angle's conversion the sums so far: `(group, trig, c)`.
        let mut entries: Vec<(u32, u32, GaussianInteger)> = (0..self.len())
            .map(|k| {
                let m = self.exp(k);
                for (j, e) in exps.iter_mut().enumerate() {
                    *e = layout.get(m, j);
                }
                (
                    groups.number(&exps),
                    none,
                    self.coeffs[k].to_gaussian_integer(),
                )
            })
            .collect();
        // One angle at a time: each entry's `e^{ikθ}` by the table of `(cos θ + i sin θ)^k`.
        // Converting the angles one after another costs the entries times one table each,
        // where every choice of an entry of every table cost their product (`cos¹⁵⁰a cos¹⁵⁰b`
        // took 37 s to print).
        let mut index: FxHashMap<(u32, u32), u32> =
            FxHashMap::with_capacity_and_hasher(self.len(), Default::default());
        let mut sums: Vec<GaussianAcc> = Vec::with_capacity(self.len());
        match conversion {
            Conversion::Joint => {
                // Each term's `e^{ik·θ}` at once, `cos(k·θ) ± i sin(k·θ)`.
                for (group, _, coeff) in &entries {
                    exps.clone_from(&groups.values[*group as usize]);
                    let k: Vec<i64> = angles
                        .iter()
                        .map(|&j| std::mem::take(&mut exps[j]))
                        .collect();
                    let group = groups.number(&exps);
                    for (key, x) in joint_harmonic(&k) {
                        let trig = trigs.number(&key);
                        sum_at(&mut index, &mut sums, (group, trig)).add_mul(coeff, &x);
                    }
                }
            }
            Conversion::EachAngle(tables) => {
                let mut multiples: Vec<i64> = (0..self.len())
                    .flat_map(|k| angles.iter().map(move |&j| layout.get(self.exp(k), j)))
                    .collect();
                multiples.sort_unstable();
                multiples.dedup();
                let tables = tables(&multiples);
                for (a, &j) in angles.iter().enumerate() {
                    index.clear();
                    sums.clear();
                    let mut powers = vec![0u32; 2 * angles.len()];
                    for (group, trig, coeff) in &entries {
                        exps.clone_from(&groups.values[*group as usize]);
                        let row = &tables[&std::mem::take(&mut exps[j])];
                        let group = groups.number(&exps);
                        powers.clone_from(&trigs.values[*trig as usize]);
                        for (cos, sin, x) in row {
                            (powers[2 * a], powers[2 * a + 1]) = (*cos, *sin);
                            let trig = trigs.number(&powers);
                            sum_at(&mut index, &mut sums, (group, trig)).add_mul(coeff, x);
                        }
                    }
                    if a + 1 < angles.len() {
                        entries = index
                            .drain()
                            .filter_map(|((group, trig), slot)| {
                                let sum = std::mem::take(&mut sums[slot as usize]).finish();
                                (!sum.is_zero()).then_some((group, trig, sum))
                            })
                            .collect();
                    }
                }
            }
        }
        if angles.is_empty() {
            for (group, trig, coeff) in &entries {
                sum_at(&mut index, &mut sums, (*group, *trig)).add(coeff);
            }
        }
        // The order of printing: trigonometric monomial first, then the monomial outside the
        // angles by `PrintOrder`; each ranked once, so that a term sorts by two numbers (no two
        // terms share both).
        let order = PrintOrder::of(&self.vars);
        let trig_monomials: Vec<TrigMonomial> = trigs
            .values
            .iter()
            .map(|key| TrigMonomial::from_key(key, angles.len()))
            .collect();
        let trig_rank = ranks(&trig_monomials, |t| t.sort_key());
        let group_rank = ranks(&groups.values, |exps| order.key(exps));
        let mut terms: Vec<(u64, CosSinTerm)> = index
            .into_iter()
            .filter_map(|((group, trig), slot)| {
                let sum = std::mem::take(&mut sums[slot as usize]).finish();
                if sum.is_zero() {
                    return None;
                }
                let (group, trig) = (group as usize, trig as usize);
                let order = u64::from(trig_rank[trig]) << 32 | u64::from(group_rank[group]);
                let term = CosSinTerm {
                    coeff: GaussianRational::from_parts(&self.content, &sum),
                    exps: groups.values[group].clone(),
                    trig: trig_monomials[trig].clone(),
                };
                Some((order, term))
            })
            .collect();
        terms.sort_unstable_by_key(|t| t.0);
        terms.into_iter().map(|(_, term)| term).collect()
    }
}

/// The order in which the terms of one trigonometric monomial print, as a paper writes them:
/// by the momenta's degree, highest first (`(p_x − Mωy) cos θ`); then by the exponents in
/// descending lexicographic order (`x² + xy + y²`), where a parameter's negative power (`M`,
/// `I`) counts as its exponent, part of the coefficient (`p_x²/(2M) + p_y²/(2M)`), but that
/// of any other variable (a coordinate, a momentum, a Poisson variable, a declared
/// denominator `(x − y)` or a radical `r`) counts as zero; then, of terms so far equal, by
/// that denominator: none first, then of the least total degree, then in the variables' order
/// as positive powers are (`β/x² + γ/y²`, `x² + x/y + y² + y/x + 1 + 1/x² + 1/y²`). A
/// monomial without such a denominator keeps the place the exponents' order gave it before.
pub(crate) struct PrintOrder {
    /// The momenta's indices.
    momenta: Vec<usize>,
    /// Whether each variable is a parameter, whose negative powers stay in the coefficient.
    parameter: Vec<bool>,
}

impl PrintOrder {
    /// The order of the variables of `vars`.
    pub(crate) fn of(vars: &Vars) -> PrintOrder {
        let kind = |v: Var| vars.variable(v).kind();
        PrintOrder {
            momenta: (vars.vars())
                .filter(|&v| kind(v) == VarKind::Momentum)
                .map(|v| v.index())
                .collect(),
            parameter: vars.vars().map(|v| kind(v) == VarKind::Parameter).collect(),
        }
    }

    /// Whether a monomial's exponents have a denominator compared apart, a negative power of
    /// a variable other than a parameter.
    pub(crate) fn has_denominator(&self, exps: &[i64]) -> bool {
        (exps.iter().zip(&self.parameter)).any(|(&e, &parameter)| e < 0 && !parameter)
    }

    /// The key of a monomial's exponents (outside the angles): the least prints first.
    pub(crate) fn key(&self, exps: &[i64]) -> std::cmp::Reverse<(i64, Vec<i64>, i64, Vec<i64>)> {
        let momentum_degree: i64 = self.momenta.iter().map(|&j| exps[j].abs()).sum();
        let below = |(j, &e): (usize, &i64)| match self.parameter[j] {
            true => 0,
            false => e.min(0),
        };
        let denominator: Vec<i64> = exps.iter().enumerate().map(below).collect();
        let numerator: Vec<i64> = (exps.iter().zip(&denominator))
            .map(|(e, d)| e - d)
            .collect();
        let degree: i64 = denominator.iter().sum();
        let denominator = denominator.iter().map(|d| -d).collect();
        std::cmp::Reverse((momentum_degree, numerator, degree, denominator))
    }
}

/// The rank of each item in the order of `key` (0 for the least).
fn ranks<T, K: Ord>(items: &[T], key: impl Fn(&T) -> K) -> Vec<u32> {
    let keys: Vec<K> = items.iter().map(key).collect();
    let mut order: Vec<u32> = (0..items.len() as u32).collect();
    order.sort_unstable_by(|&a, &b| keys[a as usize].cmp(&keys[b as usize]));
    let mut rank = vec![0u32; items.len()];
    for (r, &k) in order.iter().enumerate() {
        rank[k as usize] = r as u32;
    }
    rank
}

/// [`TrigMonomial`]'s order as a key (computed once per trigonometric monomial when terms
/// are sorted).
type TrigKey = (u32, Vec<(u32, u32)>, Vec<bool>);

/// Distinct vectors numbered in the order they come: a vector is copied once, when it is new.
struct Numbering<T> {
    numbers: FxHashMap<Vec<T>, u32>,
    values: Vec<Vec<T>>,
}

impl<T> Default for Numbering<T> {
    fn default() -> Self {
        Numbering {
            numbers: FxHashMap::default(),
            values: Vec::new(),
        }
    }
}

impl<T: Clone + Eq + std::hash::Hash> Numbering<T> {
    /// The number of `v`, new if `v` has none yet.
    fn number(&mut self, v: &[T]) -> u32 {
        if let Some(&k) = self.numbers.get(v) {
            return k;
        }
        let k = self.values.len() as u32;
        self.values.push(v.to_vec());
        self.numbers.insert(v.to_vec(), k);
        k
    }
}

/// Whether `v` is an angle of `vars`, for `e^{inθ}` with coefficients `C`.
fn check_angle<C: Coefficient>(vars: &VarSet, v: Var) -> Result<(), AlgebraError> {
    vars.checked_index(v)?;
    let kind = vars.variable(v).kind();
    if kind != VarKind::Angle {
        return Err(AlgebraError::NotAnAngle {
            needed_by: AngleUse::ExpI,
            var: vars.variable(v).unicode().to_string(),
            kind,
        });
    }
    if !C::HAS_I {
        return Err(AlgebraError::NeedsGaussian(format!(
            "the angle {} (stored as e^{{iθ}})",
            vars.variable(v).unicode()
        )));
    }
    Ok(())
}

/// The sum kept for `key` (a monomial's number and a trigonometric monomial's), new if there
/// is none yet: the map holds indices into `sums`, so that growing it moves small entries
/// rather than the accumulators.
fn sum_at<'s>(
    index: &mut FxHashMap<(u32, u32), u32>,
    sums: &'s mut Vec<GaussianAcc>,
    key: (u32, u32),
) -> &'s mut GaussianAcc {
    let slot = *index.entry(key).or_insert_with(|| {
        sums.push(GaussianAcc::default());
        sums.len() as u32 - 1
    });
    &mut sums[slot as usize]
}

/// How [`Poly::trig_terms`] writes the angles' `e^{ik·θ}`.
enum Conversion {
    /// One angle after another, each `e^{ikθ}` by the table the function makes.
    EachAngle(fn(&[i64]) -> TrigTables),
    /// All the angles at once, as harmonics of the angles jointly (`cos(θ − φ)`).
    Joint,
}

/// `e^{ik·θ}` over the angles jointly: `cos(k·θ) + i sin(k·θ)` with `k` made to start
/// positive (`cos(k·θ) − i sin(k·θ)` for `−k`), `1` alone for `k = 0`: the keys of the
/// trigonometric monomials ([`TrigMonomial::from_key`]) with their coefficients.
fn joint_harmonic(k: &[i64]) -> Vec<(Vec<u32>, GaussianInteger)> {
    let n = k.len();
    let one = GaussianInteger::from_integer(Integer::ONE);
    let sign = k.iter().find(|&&m| m != 0).map_or(0, |m| m.signum());
    let key = |place: usize| -> Vec<u32> {
        let mut key = vec![0u32; 3 * n];
        for (a, &m) in k.iter().enumerate() {
            key[2 * a + place] = m.unsigned_abs() as u32;
            key[2 * n + a] = u32::from(m * sign < 0);
        }
        key
    };
    match sign {
        0 => vec![(key(0), one)],
        1 => vec![(key(0), one.clone()), (key(1), one.mul_i())],
        _ => vec![(key(0), one.clone()), (key(1), one.mul_i().conj())],
    }
}

/// For each multiple `k`, the terms `(cos part, sin part, coefficient)` that `e^{ikθ}` is
/// written as, in one form or the other of the angles.
type TrigTables = FxHashMap<i64, Vec<(u32, u32, GaussianInteger)>>;

/// `e^{ikθ} = cos kθ + i sin kθ` (`cos |k|θ − i sin |k|θ` for `k < 0`) as harmonics, for each
/// `k` of `multiples`: `(|k|, 0, 1)` and `(0, |k|, ±i)`; `1` alone for `k = 0`.
fn harmonic_parts(multiples: &[i64]) -> TrigTables {
    let one = GaussianInteger::from_integer(Integer::ONE);
    let i = one.mul_i();
    (multiples.iter())
        .map(|&k| {
            let n = k.unsigned_abs() as u32;
            let table = match k {
                0 => vec![(0, 0, one.clone())],
                _ if k > 0 => vec![(n, 0, one.clone()), (0, n, i.clone())],
                _ => vec![(n, 0, one.clone()), (0, n, i.conj())],
            };
            (k, table)
        })
        .collect()
}

/// `(cos θ + i sin θ)^k` (for `k < 0`, `(cos θ − i sin θ)^{|k|}`) in normal form, as
/// `(cos power, sin power, coefficient)`, for each `k` of `multiples`: the powers are formed
/// one from the next, `(A + sB)(c + is) = (Ac + i(1 − c²)B) + s(iA + cB)`, up to the largest
/// `|k|`, each kept where asked for. (Formed from 1 for each `k`, `cos^1000 φ` took 24 s to
/// print.)
fn euler_powers(multiples: &[i64]) -> TrigTables {
    let zero = GaussianInteger::default();
    let largest = multiples
        .iter()
        .map(|k| k.unsigned_abs())
        .max()
        .unwrap_or(0);
    let mut tables = FxHashMap::default();
    let mut a = vec![GaussianInteger::from_integer(Integer::ONE)]; // A(c), by powers of c
    let mut b: Vec<GaussianInteger> = vec![]; // B(c)
    for n in 0..=largest {
        if n > 0 {
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
        for k in [n as i64, -(n as i64)] {
            if tables.contains_key(&k) || multiples.binary_search(&k).is_err() {
                continue;
            }
            let parts = [(0, &a), (1, &b)];
            let table = parts
                .iter()
                .flat_map(|&(sin, part)| {
                    part.iter()
                        .enumerate()
                        .filter(|(_, x)| !x.is_zero())
                        .map(move |(p, x)| {
                            (p as u32, sin, if k < 0 { x.conj() } else { x.clone() })
                        })
                })
                .collect();
            tables.insert(k, table);
        }
    }
    tables
}

/// A product `Π cos^a θ sin^b θ` over the angles of a variable set, in their order, or in
/// harmonics `cos kθ`, `sin kθ`, or over several angles jointly `cos(kθ − lφ)`
/// ([`Poly::harmonic_terms`]); ordered for printing: fewer factors first, cosines before sines,
/// sums before differences (`cos(θ + φ − ψ)` before `cos(θ − φ + ψ)`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TrigMonomial {
    /// `(a, b)` per angle.
    pub powers: Vec<(u32, u32)>,
    /// In harmonics of several angles, the angles (by their place among the angles, in
    /// order) whose multiple the argument subtracts: `φ` in `cos(θ − φ)`. Empty otherwise.
    ///
    /// A sign beside `powers`, not a type of its own: the harmonic form already reads
    /// `powers` as the sizes of the multiples (`(k, 0)` in `cos(kθ …)`, `(0, k)` in `sin`),
    /// and the printer groups, orders and writes terms by their trigonometric part in either
    /// form of the angles alike; a type (or a variant) for the harmonic form would change
    /// every reading of `powers` there, and [`Poly::harmonic_terms`]' public terms, for one
    /// bit per angle.
    pub minus: Vec<usize>,
}

impl TrigMonomial {
    /// `1`, over `angles` angles.
    pub fn one(angles: usize) -> Self {
        TrigMonomial {
            powers: vec![(0, 0); angles],
            minus: Vec::new(),
        }
    }

    /// The monomial of a key of [`Poly::trig_terms`]: `(a, b)` per angle, then, for harmonics
    /// of the angles jointly, `1` per angle whose multiple is negative.
    fn from_key(key: &[u32], angles: usize) -> Self {
        let (powers, signs) = key.split_at(2 * angles);
        TrigMonomial {
            powers: powers.chunks_exact(2).map(|p| (p[0], p[1])).collect(),
            minus: (0..signs.len()).filter(|&a| signs[a] != 0).collect(),
        }
    }

    /// Whether every power is zero.
    pub fn is_one(&self) -> bool {
        self.powers.iter().all(|&(a, b)| a == 0 && b == 0)
    }

    fn sort_key(&self) -> TrigKey {
        let degree = self.powers.iter().map(|&(a, b)| a + b).sum();
        let powers = self.powers.iter().map(|&(a, b)| (b, a)).collect();
        // Per angle whether it is subtracted, so `θ + φ + ψ`, `θ + φ − ψ`, `θ − φ + ψ`,
        // `θ − φ − ψ`, as one counts in binary.
        let minus = (0..self.powers.len())
            .map(|a| self.minus.contains(&a))
            .collect();
        (degree, powers, minus)
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

/// `r cos(m·θ)` or `r sin(m·θ)`, as [`Poly::as_harmonic`] found it.
struct Harmonic {
    /// `cos` or `sin`.
    function: &'static str,
    /// The rational factor.
    r: Rational,
    /// The angles with their nonzero multiples, the first positive.
    multiples: Vec<(Var, i64)>,
}

impl Harmonic {
    /// `cos θ` as the printer writes it; a multiple or a sum in parentheses, `cos(3φ)`, as it
    /// reads back (`cos 3φ` does not); the factor before it, `−2 sin(φ − 2q)`.
    fn write(&self, vars: &VarSet, style: Style) -> String {
        let latex = style == Style::Latex;
        let minus = if latex { "-" } else { "−" };
        let name = |v: Var| match latex {
            true => vars.variable(v).latex(),
            false => vars.variable(v).unicode(),
        };
        let mut argument = String::new();
        let multiples = self.multiples.iter().map(|&(v, k)| (name(v), k));
        crate::print::write_angle_sum(&mut argument, multiples, style);
        let one_angle = matches!(self.multiples.as_slice(), [(_, 1)]);
        let function = match latex {
            true => format!("\\{}", self.function),
            false => self.function.to_string(),
        };
        let call = match one_angle {
            true => format!("{function} {argument}"),
            false => format!("{function}({argument})"),
        };
        let factor = crate::print::render_number(&GaussianRational::from(self.r.clone()), style);
        match factor.as_str() {
            "1" => call,
            "-1" | "−1" => format!("{minus}{call}"),
            _ => format!("{factor} {call}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{Expr, Vars};

    /// A harmonic is written with its multiple of the angles made positive (`sin(−3φ)` is
    /// `−sin(3φ)`), its rational factor before it, a sum of angles in parentheses; anything else
    /// is none.
    #[test]
    fn harmonics_are_written_as_the_paper_writes_them() {
        let vars = Vars::builder()
            .coordinate("x")
            .angle("φ")
            .angle("q1")
            .angle("q2")
            .build()
            .unwrap();
        let shown = |s: &str| Expr::parse(&vars, s).unwrap().as_harmonic();
        let pair = |u: &str, l: &str| Some((u.to_string(), l.to_string()));
        assert_eq!(shown("sin(-3*φ)"), pair("−sin(3φ)", r"-\sin(3\varphi)"));
        assert_eq!(shown("sin(-φ)"), pair("−sin φ", r"-\sin \varphi"));
        assert_eq!(shown("2*cos(φ)"), pair("2 cos φ", r"2 \cos \varphi"));
        assert_eq!(
            shown("cos(q1 - q2)/2"),
            pair("1/2 cos(q1 − q2)", r"\frac{1}{2} \cos(q_{1} - q_{2})")
        );
        for other in [
            "cos(φ) + sin(φ)",
            "cos(φ) + 1",
            "x*cos(φ)",
            "cos(φ)^2",
            "3",
            "i*cos(φ)",
        ] {
            assert_eq!(shown(other), None, "{other}");
        }
    }
}
