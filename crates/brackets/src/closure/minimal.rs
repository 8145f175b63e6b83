//! The closure's relations, each minimal: a relation found (a kernel vector, at the fixed
//! values) is listed only when it is not a combination `Σ c_j(p) m_j(G) R_j` of the relations
//! found before it, with coefficients polynomial in the symbolic parameters `p` as well as in
//! the generators `G` (a module over the polynomials in the parameters, an ideal in the
//! generators). The multipliers are those the searched bounds allow: `m_j` such that
//! `m_j R_j` has degree `≤ D` in the generators, `c_j` of degree `≤ S` in the parameters (the
//! degree of the relations' own coefficients, so that `λ·R` is a multiple of `R` whenever `R`
//! is a relation the bounds found). Without symbolic parameters the `c_j` are numbers. The
//! relations found before it are those listed and those left out, each of which is such a
//! combination of the listed ones: so every relation of degree `≤ D` is a combination of the
//! listed ones times polynomials, with multipliers that may pass `D` (at degree 7, `h² a² = h k⁶`
//! is `h` times `h a² = k⁶`, which is `k⁴(h² y − k²) − h(h y k⁴ − a²)`; were only the listed
//! relations' multiples of degree `≤ 7` the span, it and five such multiples would be listed
//! in place of `h a² = k⁶`, which degree 6 lists). Each listed relation is minimal as far as
//! the degree `D` shows: a higher degree may show it to be such a combination, as degree 7
//! does `h a² = k⁶`.
//!
//! The relations are taken by their degree in the generators and, within a degree, simplest
//! first: the fewest and lowest parameters (the sum over the terms of their degree in the
//! parameters, then the largest such degree), the kernel's order among equals. Of
//! `T11 + T22 − 2H + λL²`, `T11 T22 − T12² − ω²L²` and their combination
//! `λ T11 T22 − λ T12² + ω² T11 + ω² T22 − 2ω² H` (`λ` times the second plus `ω²` times the
//! first), the first two are listed and the third is not; taken first, the combination would
//! have left both others listed as well (neither is a combination of multiples of it and of
//! the other: only `λ` times the second is), so the order is what makes the list minimal and
//! read like the paper. A relation listed is the kernel's vector less the combination of
//! multiples that takes off its entries of most parameters, when that is simpler
//! ([`RelationIdeal::simpler`]).
//!
//! Whether a relation is such a combination is decided modulo a prime, over the span of the
//! multiples of the relations found before it; a combination found there is reconstructed and checked exactly
//! before the relation is left out, and where that fails the span is formed over `Q`.

use std::collections::HashMap;

use trigpoly::{Expr, GaussianRational, Rational};

use super::lift::LiftContext;
use super::{monomials, Relation};
use crate::error::EngineError;
use crate::modular::{self, CombinationSums, Echelon, Fp, SparseVec};

/// The bounds of the closure's search: how many generators there are (the symbolic
/// parameters after them in the monomials), and the degrees `D` in the generators and `S` in
/// the parameters.
#[derive(Clone, Copy, Debug)]
pub(super) struct Bounds {
    /// How many generators (the symbolic parameters apart).
    pub(super) generators: usize,
    /// `D`, the degree in the generators.
    pub(super) degree: u32,
    /// `S`, the degree in the symbolic parameters.
    pub(super) parameters_degree: u32,
}

/// The minimal relations among the generators: `G − c = 0` for a generator constant on the
/// condition's surface (when `degree ≥ 1`), then each kernel vector (a relation at the fixed
/// values), by degree in the generators and simplest first, that is not a combination of the
/// multiples of those before it, listed or not ([`RelationIdeal`]), lifted and proved.
pub(super) fn minimal_relations(
    lift_ctx: &mut LiftContext<'_>,
    kernel: &[SparseVec<Rational>],
    bounds: Bounds,
    complex: bool,
    constant: &[bool],
) -> Result<Vec<Relation>, EngineError> {
    let mut relations = if bounds.degree >= 1 {
        constant_generator_relations(lift_ctx, constant)?
    } else {
        Vec::new()
    };
    let mut ideal = RelationIdeal::new(lift_ctx, bounds, complex, constant);
    let mut order: Vec<usize> = (0..kernel.len()).collect();
    // Stable: the kernel's order among equals.
    order.sort_by_key(|&k| ideal.simplicity(&kernel[k]));
    for k in order {
        let Some(rel) = ideal.insert_if_minimal(&kernel[k]) else {
            continue;
        };
        let (poly, symbolic) = lift_ctx.relation(&rel)?;
        relations.push(Relation {
            poly,
            degree: ideal.simplicity(&rel).0,
            symbolic,
        });
    }
    Ok(relations)
}

/// `G − c = 0` for each generator `G` constant on the condition's surface (`c` a function of
/// the parameters), in the generators' order.
fn constant_generator_relations(
    lift_ctx: &LiftContext<'_>,
    constant: &[bool],
) -> Result<Vec<Relation>, EngineError> {
    let mut relations = Vec::new();
    for (a, g) in lift_ctx.g_sym.iter().enumerate() {
        if constant[a] {
            let value = lift_ctx.to_ring(g)?;
            let symbol = Expr::monomial(
                &lift_ctx.ring,
                GaussianRational::from(1),
                &[(lift_ctx.symbols[a], 1)],
            )?;
            relations.push(Relation {
                poly: symbol.checked_sub(&value)?,
                degree: 1,
                symbolic: true,
            });
        }
    }
    Ok(relations)
}

/// A monomial `p^ν G^β` (exponents of the generators, then of the symbolic parameters), and
/// whether it is `i` times it: an index of [`RelationIdeal`]'s vectors, which are not bound to
/// the closure's columns (a multiple `λ·R` may pass the degree `S` of the columns).
type Key = (Vec<u32>, bool);

/// The span of the relations tested so far, listed or not, and of their multiples by
/// `p^ν G^β` within the bounds (and by `i` over `Q(i)`): a relation in it is a combination of
/// multiples of those before it, not minimal.
struct RelationIdeal<'a> {
    /// The exponents of each column's monomial, in the generators and then the symbolic
    /// parameters.
    monos: &'a [Vec<u32>],
    /// Each column's monomial, and whether the column is that monomial times `i`.
    col_ids: &'a [(usize, bool)],
    bounds: Bounds,
    /// Whether the generators are complex: the columns are each monomial and `i` times it.
    complex: bool,
    /// Whether each generator is constant on the condition's surface (no column holds it,
    /// nor does any multiplier).
    constant: Vec<bool>,
    /// The index of each monomial met, numbered as met.
    index: HashMap<Key, usize>,
    /// The monomial of each index.
    keys: Vec<Key>,
    /// The column of each monomial that is one.
    col_of: HashMap<Key, usize>,
    /// The multiples in the span, by identifier, over `index`.
    multiples: Vec<SparseVec<Rational>>,
    /// Their span modulo the prime; `None` once a multiple has a denominator the prime
    /// divides, and the span is formed over `Q` instead.
    modular: Option<Echelon<Fp>>,
    /// Their span over `Q`, where the prime does not decide, grown with the later multiples
    /// when next needed.
    exact: Echelon<Rational>,
    /// How many of the multiples `exact` holds.
    exact_joined: usize,
    /// The sum in which a combination of the multiples found modulo the prime is checked.
    sums: CombinationSums,
    /// The relations tested, listed or not, whose multiples are not yet in the span (they are
    /// added before the next relation is tested).
    pending: Vec<SparseVec<Rational>>,
}

impl<'a> RelationIdeal<'a> {
    /// The empty span, over the columns of `lift_ctx`.
    fn new(lift_ctx: &LiftContext<'a>, bounds: Bounds, complex: bool, constant: &[bool]) -> Self {
        let col_of = (lift_ctx.col_ids.iter().enumerate())
            .map(|(j, (m, i))| ((lift_ctx.monos[*m].clone(), *i), j))
            .collect();
        RelationIdeal {
            col_of,
            monos: lift_ctx.monos,
            col_ids: lift_ctx.col_ids,
            bounds,
            complex,
            constant: constant[..bounds.generators].to_vec(),
            index: HashMap::new(),
            keys: Vec::new(),
            multiples: Vec::new(),
            modular: Some(Echelon::new(0)),
            exact: Echelon::new(0),
            exact_joined: 0,
            sums: CombinationSums::new(),
            pending: Vec::new(),
        }
    }

    /// What orders the relations: the degree in the generators, then the sum over the
    /// columns of their degree in the parameters, then the largest such degree.
    fn simplicity(&self, v: &SparseVec<Rational>) -> (u32, u32, u32) {
        let r = self.bounds.generators;
        let mut key = (0, 0, 0);
        for (j, _) in v {
            let m = &self.monos[self.col_ids[*j].0];
            let in_generators: u32 = m[..r].iter().sum();
            let in_parameters: u32 = m[r..].iter().sum();
            key.0 = key.0.max(in_generators);
            key.1 += in_parameters;
            key.2 = key.2.max(in_parameters);
        }
        key
    }

    /// The index of `key`, numbered when first met.
    fn index_of(&mut self, key: Key) -> usize {
        if let Some(&i) = self.index.get(&key) {
            return i;
        }
        let i = self.keys.len();
        self.keys.push(key.clone());
        self.index.insert(key, i);
        i
    }

    /// A kernel vector (over the columns) over the indices.
    fn indexed(&mut self, v: &SparseVec<Rational>) -> SparseVec<Rational> {
        let mut out: SparseVec<Rational> = v
            .iter()
            .map(|(j, x)| {
                let (m, imag) = self.col_ids[*j];
                (self.index_of((self.monos[m].clone(), imag)), x.clone())
            })
            .collect();
        out.sort_by_key(|e| e.0);
        out
    }

    /// Whether `rel` (the relations taken in [`RelationIdeal::simplicity`]'s order) is
    /// minimal: not a combination of the multiples of the relations before it; if it is, the
    /// relation to list for it (over the columns): `rel`, or one simpler that differs from it
    /// by such a combination ([`RelationIdeal::simpler`]). Its multiples join the span before
    /// the next is tested, whether it is listed or not: one left out is in the ideal of those
    /// listed, and so are its multiples, which that ideal's own multiples within the degree
    /// need not reach (`h a² = k⁶` of degree 6 is `k⁴(h² y − k²) − h(h y k⁴ − a²)`, through
    /// multiples of degree 7, and at degree 7 its multiple `h² a² = h k⁶` is not a combination
    /// of the multiples of degree `≤ 7` of the other two).
    fn insert_if_minimal(&mut self, rel: &SparseVec<Rational>) -> Option<SparseVec<Rational>> {
        self.add_pending_multiples();
        let v = self.indexed(rel);
        if self.spans(&v) {
            self.pending.push(v);
            return None;
        }
        let listed = match self.simpler(rel, &v) {
            Some(simpler) => simpler,
            None => rel.clone(),
        };
        let indexed = self.indexed(&listed);
        self.pending.push(indexed);
        Some(listed)
    }

    /// `rel` (`v` over the indices) less the combination of the multiples in the span that
    /// takes off its entries on their pivots, which are each multiple's entry of most
    /// parameters (then of highest degree in the generators): `Q − aV − a²U` less
    /// `−(aP − a²U)` is `Q − aV − aP`, when `P − aU` is listed. Only when that is simpler by
    /// [`RelationIdeal::simplicity`], still over the columns, and the difference is checked
    /// to be such a combination exactly.
    fn simpler(
        &mut self,
        rel: &SparseVec<Rational>,
        v: &SparseVec<Rational>,
    ) -> Option<SparseVec<Rational>> {
        let echelon = self.modular.as_ref()?;
        let residue = modular::reconstruct_vec(&echelon.residue(&modular::to_fp(v)?))?;
        let mut over_columns: SparseVec<Rational> = (residue.iter())
            .map(|(i, x)| Some((*self.col_of.get(&self.keys[*i])?, x.clone())))
            .collect::<Option<_>>()?;
        over_columns.sort_by_key(|e| e.0);
        if over_columns.is_empty() || self.simplicity(&over_columns) >= self.simplicity(rel) {
            return None;
        }
        let difference = modular::sum_by_index(
            (v.iter().cloned())
                .chain(residue.iter().map(|(i, x)| (*i, -x)))
                .collect(),
        );
        let combination = echelon.express(&modular::to_fp(&difference)?)?;
        let combination = modular::reconstruct_vec(&combination)?;
        self.sums
            .equals(&self.multiples, &combination, &difference)
            .then_some(over_columns)
    }

    /// Whether `v` is in the span: modulo the prime, the combination found there
    /// reconstructed and checked exactly (independent modulo the prime, it is taken to be
    /// outside, as the closure's brackets are); over `Q` where that does not decide.
    fn spans(&mut self, v: &SparseVec<Rational>) -> bool {
        let dim = self.index.len();
        if let (Some(echelon), Some(vf)) = (self.modular.as_mut(), modular::to_fp(v)) {
            echelon.grow(dim);
            match echelon.express(&vf) {
                None => return false,
                Some(combo) => {
                    let exact = modular::reconstruct_vec(&combo);
                    if exact.is_some_and(|c| self.sums.equals(&self.multiples, &c, v)) {
                        return true;
                    }
                }
            }
        }
        self.exact.grow(dim);
        for (id, m) in self.multiples.iter().enumerate().skip(self.exact_joined) {
            self.exact.insert(id, m);
        }
        self.exact_joined = self.multiples.len();
        self.exact.contains(v)
    }

    /// Adds to the span the multiples of the relations tested since the last test.
    fn add_pending_multiples(&mut self) {
        for rel in std::mem::take(&mut self.pending) {
            for m in self.multiples_of(&rel) {
                let dim = self.index.len();
                let id = self.multiples.len();
                let (keys, r) = (&self.keys, self.bounds.generators);
                match (self.modular.as_mut(), modular::to_fp(&m)) {
                    (Some(echelon), Some(mf)) => {
                        echelon.grow(dim);
                        // Each row's pivot its entry of most parameters, which
                        // `RelationIdeal::simpler` then takes off.
                        echelon.insert_by(id, &mf, |residue| {
                            (0..residue.len())
                                .max_by_key(|&k| {
                                    let m = &keys[residue[k].0].0;
                                    (m[r..].iter().sum::<u32>(), m[..r].iter().sum::<u32>())
                                })
                                .unwrap_or(0)
                        });
                    }
                    _ => self.modular = None,
                }
                self.multiples.push(m);
            }
        }
    }

    /// `rel` (over the indices) times each `p^ν G^β` of the bounds (and times `i` when the
    /// generators are complex): `G^β` of degree at most `D` less `rel`'s degree in the
    /// generators and in no generator constant on the surface, `p^ν` of degree at most `S`.
    fn multiples_of(&mut self, rel: &SparseVec<Rational>) -> Vec<SparseVec<Rational>> {
        let r = self.bounds.generators;
        let terms: Vec<(Key, Rational)> = rel
            .iter()
            .map(|(i, x)| (self.keys[*i].clone(), x.clone()))
            .collect();
        let degree = terms
            .iter()
            .map(|((m, _), _)| m[..r].iter().sum::<u32>())
            .max()
            .unwrap_or(0);
        let parameters = self.monos.first().map_or(0, |m| m.len() - r);
        let in_generators: Vec<Vec<u32>> = monomials(r, self.bounds.degree.saturating_sub(degree))
            .into_iter()
            .filter(|g| g.iter().zip(&self.constant).all(|(e, c)| *e == 0 || !c))
            .collect();
        let in_parameters = monomials(parameters, self.bounds.parameters_degree);
        let mut out = Vec::new();
        for gamma in &in_generators {
            for nu in &in_parameters {
                for times_i in [false, true] {
                    if times_i && !self.complex {
                        continue;
                    }
                    let mut product: SparseVec<Rational> = terms
                        .iter()
                        .map(|((m, imag), x)| {
                            let exps: Vec<u32> = m
                                .iter()
                                .zip(gamma.iter().chain(nu))
                                .map(|(a, b)| a + b)
                                .collect();
                            // i · (i m) = −m.
                            let (imag, x) = match (times_i, *imag) {
                                (false, i) => (i, x.clone()),
                                (true, false) => (true, x.clone()),
                                (true, true) => (false, -x),
                            };
                            (self.index_of((exps, imag)), x)
                        })
                        .collect();
                    product.sort_by_key(|e| e.0);
                    out.push(product);
                }
            }
        }
        out
    }
}
