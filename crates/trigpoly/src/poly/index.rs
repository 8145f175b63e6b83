//! `MonomialIndex`: a map from the monomials of one variable set to values, keyed by their
//! packed words (up to two words as one fixed-size key, hashed and compared inline). Looking
//! a polynomial's term up hashes and compares a word or two and allocates nothing, where a map keyed by exponent vectors unpacks each term into a new
//! vector, hashes it and compares it element by element (the coordinates of a function in a
//! basis of monomials, for a search, are one lookup per term).

use rustc_hash::FxHashMap;

use super::{check_exponent, Term};
use crate::error::{AlgebraError, Misuse};
use crate::number::Coefficient;
use crate::varset::Vars;

/// A map from monomials of one [`VarSet`](crate::VarSet) to values of type `V`, looked up by
/// exponent vector or, without unpacking, by a polynomial's [`Term`].
///
/// ```
/// use trigpoly::{Expr, MonomialIndex, Vars};
/// let vars = Vars::builder().coordinate("x").coordinate("y").build().unwrap();
/// let mut index = MonomialIndex::new(&vars);
/// index.insert(&[2, 0], "x²").unwrap();
/// index.insert(&[1, 1], "xy").unwrap();
/// let f = Expr::parse(&vars, "3*x*y - x^2 + y").unwrap();
/// let found: Vec<_> = f.terms().map(|t| index.get_term(&t).copied()).collect();
/// assert_eq!(found, [Some("x²"), Some("xy"), None]);
/// assert_eq!(index.get(&[1, 1]), Some(&"xy"));
/// ```
#[derive(Clone, Debug)]
pub struct MonomialIndex<V> {
    vars: Vars,
    map: Map<V>,
}

/// The map by the width of the monomials: up to [`NARROW`] words as an array padded with
/// zeros (a slice key costs a call to compare and hashes its length), wider ones as slices.
#[derive(Clone, Debug)]
enum Map<V> {
    Narrow(FxHashMap<[u64; NARROW], V>),
    Wide(FxHashMap<Box<[u64]>, V>),
}

/// The most words of a monomial kept as an array key.
const NARROW: usize = 2;

/// The words of a monomial of at most [`NARROW`] words, padded with zeros.
#[inline]
fn narrow(words: &[u64]) -> [u64; NARROW] {
    let mut key = [0; NARROW];
    key[..words.len()].copy_from_slice(words);
    key
}

impl<V> MonomialIndex<V> {
    /// An empty index of monomials of `vars`.
    pub fn new(vars: &Vars) -> Self {
        let map = if vars.layout().words <= NARROW {
            Map::Narrow(FxHashMap::default())
        } else {
            Map::Wide(FxHashMap::default())
        };
        MonomialIndex {
            vars: vars.clone(),
            map,
        }
    }

    /// Puts `value` at the monomial with exponents `exps` (one per variable, in the order of
    /// the variable set; for an angle `θ`, `k` in `e^{ikθ}`), returning the value it replaces.
    /// An error when `exps` has the wrong length or an exponent is past the degree limit.
    pub fn insert(&mut self, exps: &[i64], value: V) -> Result<Option<V>, AlgebraError> {
        let key = self.pack(exps)?;
        Ok(match &mut self.map {
            Map::Narrow(map) => map.insert(narrow(&key), value),
            Map::Wide(map) => map.insert(key.into_boxed_slice(), value),
        })
    }

    /// The value at the monomial with exponents `exps`, if any (none for a vector of the
    /// wrong length or past the degree limit, which no monomial has).
    pub fn get(&self, exps: &[i64]) -> Option<&V> {
        let key = self.pack(exps).ok()?;
        self.get_words(&key)
    }

    /// The value at the monomial of `term`, if any; none when the term's polynomial belongs
    /// to another variable set.
    pub fn get_term<C: Coefficient>(&self, term: &Term<'_, C>) -> Option<&V> {
        self.get_words(self.words_of(term)?)
    }

    /// The value at the monomial of `term`, put there by `value` first if there is none;
    /// none when the term's polynomial belongs to another variable set.
    pub fn get_or_insert_with_term<C: Coefficient>(
        &mut self,
        term: &Term<'_, C>,
        value: impl FnOnce() -> V,
    ) -> Option<&mut V> {
        let words = self.words_of(term)?;
        Some(match &mut self.map {
            Map::Narrow(map) => map.entry(narrow(words)).or_insert_with(value),
            Map::Wide(map) => {
                if !map.contains_key(words) {
                    map.insert(words.into(), value());
                }
                map.get_mut(words).expect("just inserted")
            }
        })
    }

    /// The packed words of `term`'s monomial; none when its polynomial belongs to another
    /// variable set.
    #[inline]
    fn words_of<'t, C: Coefficient>(&self, term: &Term<'t, C>) -> Option<&'t [u64]> {
        let poly = term.poly;
        Vars::ptr_eq(&self.vars, &poly.vars).then(|| poly.exp(term.k))
    }

    /// The value at the monomial of these packed words.
    #[inline]
    fn get_words(&self, words: &[u64]) -> Option<&V> {
        match &self.map {
            Map::Narrow(map) => map.get(&narrow(words)),
            Map::Wide(map) => map.get(words),
        }
    }

    /// The number of monomials in the index.
    pub fn len(&self) -> usize {
        match &self.map {
            Map::Narrow(map) => map.len(),
            Map::Wide(map) => map.len(),
        }
    }

    /// Whether the index holds no monomial.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The variable set of the monomials.
    pub fn vars(&self) -> &Vars {
        &self.vars
    }

    /// The packed words of the monomial with exponents `exps`, as a polynomial stores them.
    fn pack(&self, exps: &[i64]) -> Result<Vec<u64>, AlgebraError> {
        if exps.len() != self.vars.len() {
            return Err(AlgebraError::Misuse(Misuse::ExponentCount {
                exponents: exps.len(),
                variables: self.vars.len(),
            }));
        }
        for (v, &e) in self.vars.vars().zip(exps) {
            check_exponent(&self.vars, v, e)?;
        }
        let layout = self.vars.layout();
        let mut key = vec![0; layout.words];
        layout.pack(exps, &mut key);
        Ok(key)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Expr;

    #[test]
    fn terms_find_the_monomials_inserted_by_exponents() {
        let vars = Vars::builder()
            .coordinate("x")
            .momentum("p")
            .parameter("a")
            .angle("theta")
            .build()
            .unwrap();
        let mut index = MonomialIndex::new(&vars);
        assert!(index.is_empty());
        // x·p·e^{2iθ}, a/x·e^{−2iθ} and 1.
        assert_eq!(index.insert(&[1, 1, 0, 2], 'A'), Ok(None));
        assert_eq!(index.insert(&[-1, 0, 1, -2], 'B'), Ok(None));
        assert_eq!(index.insert(&[0, 0, 0, 0], 'C'), Ok(None));
        assert_eq!(index.insert(&[0, 0, 0, 0], 'D'), Ok(Some('C')));
        assert_eq!(index.len(), 3);
        let f = Expr::parse(
            &vars,
            "x*p*(cos(theta) + i*sin(theta))^2 + a/x*(cos(theta) - i*sin(theta))^2 + 7 + x",
        )
        .unwrap();
        let mut found: Vec<_> = f.terms().map(|t| index.get_term(&t).copied()).collect();
        found.sort();
        assert_eq!(found, [None, Some('A'), Some('B'), Some('D')]);
        assert_eq!(index.get(&[-1, 0, 1, -2]), Some(&'B'));
        assert_eq!(index.get(&[-1, 0, 1, 2]), None);
        // The same monomials of another variable set are not there.
        let other = Vars::builder()
            .coordinate("x")
            .momentum("p")
            .parameter("a")
            .angle("phi")
            .build()
            .unwrap();
        let g = Expr::parse(&other, "7").unwrap();
        assert_eq!(index.get_term(&g.terms().next().unwrap()), None);
    }

    /// Twelve coordinates `x0, …, x11` of 12 bits: three words, past the array keys.
    fn twelve_coordinates() -> crate::Vars {
        let names: Vec<String> = (0..12).map(|i| format!("x{i}")).collect();
        names
            .iter()
            .fold(Vars::builder(), |b, n| b.coordinate(n))
            .build()
            .unwrap()
    }

    #[test]
    fn monomials_of_three_words_are_found_too() {
        let vars = twelve_coordinates();
        assert_eq!(vars.monomial_words(), 3);
        let mut index = MonomialIndex::new(&vars);
        let unit = |i: usize, e: i64| {
            let mut exps = vec![0; 12];
            exps[i] = e;
            exps
        };
        for i in 0..12 {
            assert_eq!(index.insert(&unit(i, 2), i), Ok(None));
        }
        let f = Expr::parse(&vars, "x0^2 + x5^2 + x11^2 + x11 + x3*x4").unwrap();
        let found: Vec<_> = f
            .terms()
            .filter_map(|t| index.get_term(&t).copied())
            .collect();
        assert_eq!(found, [0, 5, 11]);
        assert_eq!(index.get(&unit(7, 2)), Some(&7));
        assert_eq!(index.get(&unit(7, -2)), None);
        assert_eq!(index.len(), 12);
    }

    /// Numbering monomials by first appearance, as the search numbers its equations: one and
    /// three words alike, and none for a term of another variable set.
    #[test]
    fn terms_are_numbered_by_first_appearance() {
        let narrow = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .build()
            .unwrap();
        let wide = twelve_coordinates();
        for (vars, f, g) in [
            (&narrow, "x^2 + 3*x*y - y", "y + x*y - 2*x^3 + x^2"),
            (
                &wide,
                "x0^2 + 3*x0*x11 - x11",
                "x11 + x0*x11 - 2*x0^3 + x0^2",
            ),
        ] {
            let mut index = MonomialIndex::new(vars);
            let mut number = |t: &Term<'_, crate::GaussianRational>| {
                let next = index.len();
                *index.get_or_insert_with_term(t, || next).unwrap()
            };
            let (f, g) = (Expr::parse(vars, f).unwrap(), Expr::parse(vars, g).unwrap());
            // f's three monomials take 0, 1, 2; g meets them again and adds x³ as 3.
            let first: Vec<(Vec<i64>, usize)> =
                f.terms().map(|t| (t.exponents(), number(&t))).collect();
            let mut numbers: Vec<usize> = first.iter().map(|m| m.1).collect();
            numbers.sort_unstable();
            assert_eq!(numbers, [0, 1, 2]);
            for t in g.terms() {
                let before = first.iter().find(|m| m.0 == t.exponents()).map(|m| m.1);
                assert_eq!(number(&t), before.unwrap_or(3));
            }
            assert_eq!(index.len(), 4);
        }
        let mut index = MonomialIndex::<usize>::new(&narrow);
        let other = Expr::parse(&wide, "x0").unwrap();
        assert!(index
            .get_or_insert_with_term(&other.terms().next().unwrap(), || 0)
            .is_none());
        assert!(index.is_empty());
    }

    #[test]
    fn exponents_of_the_wrong_length_or_past_the_limit_are_refused() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .build()
            .unwrap();
        let mut index = MonomialIndex::new(&vars);
        let limit = i64::from(vars.limits().max_degree);
        assert!(index.insert(&[1], ()).is_err());
        assert!(index.insert(&[1, 2, 3], ()).is_err());
        assert!(matches!(
            index.insert(&[0, limit + 1], ()),
            Err(AlgebraError::ExponentTooLarge { .. })
        ));
        assert_eq!(index.insert(&[-limit, limit], ()), Ok(None));
        assert_eq!(index.get(&[-limit, limit]), Some(&()));
        assert_eq!(index.get(&[0, limit + 1]), None);
        assert_eq!(index.len(), 1);
    }
}
