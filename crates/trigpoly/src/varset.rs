//! Variables: their names (ASCII, unicode, LaTeX), kinds, and the packing of exponent vectors
//! into machine words that every polynomial of a `VarSet` shares.

use std::fmt;
use std::sync::Mutex;

use crate::error::{AlgebraError, Setting};

mod names;

pub(crate) use names::{bars_apart, letter_of_char, letter_of_command, long_name, unparenthesized};
pub use names::{
    display_forms, greek_latex, has_several_words, is_identifier, latex_unwritable, momentum_forms,
    shown_forms, shown_text, unbarred, under_one_bar, with_indices, BadName, LATEX_LETTERS,
    MAX_NAME_CHARS, RESERVED,
};
use names::{render_momentum, render_name, shown_text_of, spell_out};

/// What a variable is in a phase space; only `Angle` changes the algebra.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VarKind {
    /// A position such as `x`.
    Coordinate,
    /// A momentum such as `p_x`.
    Momentum,
    /// A symbolic constant such as `M`, `ω`, `g`.
    Parameter,
    /// An angle `θ`: functions depend on it through `cos θ`, `sin θ`, stored as powers of
    /// `e^{iθ}` (exponent any integer), which needs Gaussian coefficients.
    Angle,
    /// A Poisson variable such as the angular momentum `M₁` of a top: a phase-space variable
    /// in no canonical pair, whose brackets are declared (the Lie–Poisson `{M₁, M₂} = M₃`).
    Poisson,
    /// A denominator atom: a variable that stands for a polynomial `D` of the other variables
    /// (named `(D)`, `(x - y)`), so that its negative powers are `1/D^k` and the Laurent
    /// printer writes `g/(x − y)²`. Its brackets follow from `D`'s, and an element is zero
    /// exactly when clearing it of its denominators leaves zero (`Poly::vanishes`).
    Denominator,
    /// A radical: a variable `r` standing for `√R`, the positive square root of a polynomial
    /// `R` of the other variables (its radicand, `x² + y² + z²` for the distance to the
    /// origin), so that `r² = R`. Its powers of any sign are terms (`k/r`, `x/r³`); its
    /// brackets follow from `R`'s, `{r, z} = {R, z}/(2r)`, and an element is zero exactly when
    /// reducing it by `r² = R` leaves zero (`Poly::vanishes`).
    Radical,
}

impl VarKind {
    /// The kind in words, with its article, as messages name it: `a coordinate`, `a
    /// momentum`, `a parameter`, `an angle`, `a Poisson variable`, `a denominator`, `a
    /// radical`.
    pub fn described(self) -> &'static str {
        match self {
            VarKind::Coordinate => "a coordinate",
            VarKind::Momentum => "a momentum",
            VarKind::Parameter => "a parameter",
            VarKind::Angle => "an angle",
            VarKind::Poisson => "a Poisson variable",
            VarKind::Denominator => "a denominator",
            VarKind::Radical => "a radical",
        }
    }
}

impl fmt::Display for VarKind {
    /// The kind in words, without its article ([`VarKind::described`] has it): `coordinate`,
    /// `Poisson variable`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let described = self.described();
        f.write_str(
            described
                .split_once(' ')
                .map_or(described, |(_, kind)| kind),
        )
    }
}

/// A variable handle: its index in its `VarSet`, and which variables that set declares (sets
/// that declare the same variables, whatever their limits, share handles). A handle used with a
/// set that declares other variables is refused ([`VarSet::owns`]), where its index alone would
/// name whatever variable stands at that place there.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Var {
    index: u16,
    /// The number of the declaration (the list of variables) among those the process has made.
    declaration: u32,
}

/// `Var(p_x, 2 of declaration 5)`: the variable's name (its ASCII form, which reads back), the
/// index, and which variables it is an index into (a handle alone does not say which set it
/// belongs to: the name is that of the variable at its place in the sets of its declaration).
impl std::fmt::Debug for Var {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = {
            let interned = INTERNED.lock().unwrap_or_else(|e| e.into_inner());
            (interned.iter())
                .find(|s| s.declaration == self.declaration)
                .and_then(|s| s.vars.get(self.index()))
                .map(|v| v.ascii.clone())
        };
        match name {
            Some(name) => write!(
                f,
                "Var({name}, {} of declaration {})",
                self.index, self.declaration
            ),
            None => write!(f, "Var({} of declaration {})", self.index, self.declaration),
        }
    }
}

impl Var {
    /// The index in the variable set.
    pub fn index(self) -> usize {
        self.index as usize
    }
}

/// One declared variable.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Variable {
    name: String,
    unicode: String,
    latex: String,
    /// The unicode form with its Greek letters spelled out (`p_theta` for `p_θ`), when it has
    /// any: a third spelling that [`VarSet::lookup`] takes.
    spelled_out: Option<String>,
    /// The name in ASCII ([`Variable::ascii`]), which a display ([`VarsBuilder::shown_as`])
    /// leaves as it is: a fourth spelling that [`VarSet::lookup`] takes.
    ascii: String,
    kind: VarKind,
    /// Whether text sets the variable apart from its neighbours in a product, as a word, even
    /// when its name is one letter: the generators of an algebra (`−ω² L`, `4 G1`).
    word: bool,
    /// For a radical, its radicand `R` in ASCII, as it parses back.
    radicand: Option<String>,
}

impl Variable {
    /// The ASCII name that parses back (`p_theta`, `omega`).
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The name in ASCII, as the ASCII form of an element prints it: the declared name, or for
    /// one declared in Greek letters (`θ`, `p_θ`) the same with the letters spelled out
    /// (`theta`, `p_theta`), which reads back. A name with other letters outside ASCII has no
    /// such form and is its own.
    pub fn ascii(&self) -> &str {
        &self.ascii
    }
    /// The name as printed in text (`p_θ`, `ω`).
    pub fn unicode(&self) -> &str {
        &self.unicode
    }
    /// The name as printed in LaTeX (`p_{\theta}`, `\omega`).
    pub fn latex(&self) -> &str {
        &self.latex
    }
    /// The kind.
    pub fn kind(&self) -> VarKind {
        self.kind
    }
    /// Whether text sets the variable apart in a product as a word ([`VarsBuilder::word`]).
    pub fn is_word(&self) -> bool {
        self.word
    }
    /// For a radical ([`VarKind::Radical`]), its radicand in ASCII (`x^2 + y^2`).
    pub fn radicand(&self) -> Option<&str> {
        self.radicand.as_deref()
    }
    /// Whether [`VarSet::lookup`] finds the variable by `spelling`: its name, its unicode
    /// form, or that form with its Greek letters spelled out.
    fn spelled(&self, spelling: &str) -> bool {
        self.name == spelling
            || self.unicode == spelling
            || self.spelled_out.as_deref() == Some(spelling)
            || self.ascii == spelling
    }
    /// Every spelling [`VarSet::lookup`] finds the variable by: its name, its unicode form,
    /// and that form with its Greek letters spelled out.
    pub fn spellings(&self) -> impl Iterator<Item = &str> {
        [
            Some(self.name.as_str()),
            Some(self.unicode.as_str()),
            self.spelled_out.as_deref(),
            Some(self.ascii.as_str()),
        ]
        .into_iter()
        .flatten()
    }
    /// Whether a spelling finds both variables in a lookup (`omega` and `ω`, or a name and a
    /// variable shown as that name).
    fn spelled_alike(&self, other: &Variable) -> bool {
        self.spellings().any(|s| other.spelled(s))
    }
}

/// Whether one-letter names written side by side, `run` in order (`i`, `M`, `ω`, `y` of
/// `2iMωy`), could read back as another name: two or more of them in a row spell a name of
/// `declared` (`x`, `y` of `Mxy` beside a name `xy`; `o`, `m`, `e`, `g`, `a` beside `omega`).
/// The parser reads a run of letters as a declared name, and splits one it does not know into
/// declared names longest first (`Mxy` as `M·xy`), so such a run is written with spaces
/// (`M x y`); any other runs together as the paper writes it (`2iMωy` beside `Hy`, which no
/// two of its letters in a row spell). A run is what one name could be read from: a power,
/// a subscript, parentheses or a name of several letters ends it, and a number before it is
/// no part of it, as a name never begins with a digit.
pub fn juxtaposition_is_ambiguous<'a>(
    declared: impl IntoIterator<Item = &'a str>,
    run: &[&str],
) -> bool {
    declared.into_iter().any(|name| {
        (0..run.len()).any(|start| {
            let mut rest = name;
            for (before, letter) in run[start..].iter().enumerate() {
                match rest.strip_prefix(letter) {
                    Some("") => return before > 0,
                    Some(after) => rest = after,
                    None => return false,
                }
            }
            false
        })
    })
}

/// Whether a name of several letters is spelled by letters each of which `is_letter` takes
/// (a one-letter name, or the imaginary unit): `xy` by `x` and `y`, `omega` by `o`, `m`, `e`,
/// `g` and `a`, in any order. What a product of one-letter names could be printed as.
pub(crate) fn spelled_by(name: &str, is_letter: impl Fn(char) -> bool) -> bool {
    name.chars().nth(1).is_some() && name.chars().all(is_letter)
}

/// Limits that stop runaway expansions with a clear error instead of exhausting memory or
/// running for hours. The size of each result is checked before it is formed where it is
/// known, and otherwise as it is formed; the work of each product (its term products, `n·m`,
/// or `n(n + 1)/2` for a square) before it starts, and of a sum's products together (a
/// bracket's) before any starts, so that a power of a long polynomial whose result would pass
/// the term limit stops at once rather than after hours of multiplying.
///
/// The library's default is 20 000 000 terms, degree 1000 and 10¹⁰ term products a product
/// (system files and the command line default to 2 000 000 terms: `docs/system-files.md`),
/// with no cap on memory beyond what the allocator refuses (the command line caps it at the
/// machine's physical memory).
///
/// Built from the defaults, each limit set by a method of its name; the fields are read as
/// they are named:
///
/// ```
/// use trigpoly::{Limits, Vars};
///
/// let limits = Limits::default().max_terms(10_000).max_degree(50);
/// assert_eq!((limits.max_terms, limits.max_degree), (10_000, 50));
/// assert_eq!(limits.max_term_products, Limits::DEFAULT_MAX_TERM_PRODUCTS);
/// let limits = limits.max_term_products(1_000_000).max_reserved_bytes(1 << 30);
/// assert_eq!((limits.max_term_products, limits.max_reserved_bytes), (1_000_000, 1 << 30));
/// let vars = Vars::builder().coordinate("x").limits(limits).build()?;
/// assert_eq!(vars.limits(), limits);
/// # Ok::<(), trigpoly::AlgebraError>(())
/// ```
///
/// A limit may be added, so another crate writes no literal of all of them:
///
/// ```compile_fail,E0639
/// let limits = trigpoly::Limits { max_terms: 10, ..trigpoly::Limits::default() };
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Limits {
    /// The most terms any single result may have.
    pub max_terms: usize,
    /// The largest absolute exponent of any variable; for an angle, the largest trigonometric
    /// order `k` of `cos kθ`, `sin kθ` (the exponent of `e^{iθ}`, as it is stored). At least
    /// 1: [`VarsBuilder::build`] refuses 0.
    pub max_degree: u32,
    /// The most term products one product of polynomials may form (some seconds to a minute
    /// of work at the default), and the products of one sum of products, such as a Poisson
    /// bracket's, together
    /// ([`AlgebraError::TooMuchSummedWork`](crate::AlgebraError::TooMuchSummedWork)).
    pub max_term_products: u64,
    /// The most bytes that the room reserved for a result may take with what is held beside
    /// it at once (the terms as formed, their order for the sort, the terms combined): an
    /// estimate from a count of terms predicted before any work (a power by the multinomial
    /// theorem), not a measure of the memory in use, so it bounds only the results whose room
    /// is reserved so. Past it the
    /// result is [`AlgebraError::TooLargeForMemory`](crate::AlgebraError::TooLargeForMemory)
    /// at once, as when the allocator refuses the room. The library's default,
    /// [`Limits::NO_MEMORY_CAP`], sets none beyond the allocator's refusal, which under
    /// Linux's overcommit comes only past `isize::MAX` bytes; the command line sets the
    /// machine's physical memory.
    pub max_reserved_bytes: u64,
}

impl Limits {
    /// The default degree limit, of the library and of system files: 12-bit exponent fields
    /// hold it, five variables to a word.
    pub const DEFAULT_MAX_DEGREE: u32 = 1000;
    /// The default work limit, of the library and of system files: 10¹⁰ term products, some
    /// seconds to a minute on one core (Fateman's `(1 + x + y + z + t)^30` times itself, 2·10⁹,
    /// passes).
    pub const DEFAULT_MAX_TERM_PRODUCTS: u64 = 10_000_000_000;
    /// The default cap on the room reserved for a result, of the library: none
    /// ([`Limits::max_reserved_bytes`]).
    pub const NO_MEMORY_CAP: u64 = u64::MAX;

    /// The same limits with at most `n` terms in any single result.
    #[must_use]
    pub fn max_terms(mut self, n: usize) -> Self {
        self.max_terms = n;
        self
    }

    /// The largest degree limit that takes effect, `2³¹ − 1`: an exponent of the widest packing
    /// ([`FIELD_BITS`], 32 bits with a sign); a larger [`Limits::max_degree`] acts as this one.
    ///
    /// ```
    /// use trigpoly::{Limits, Vars};
    ///
    /// let limits = Limits::default().max_degree(u32::MAX);
    /// let vars = Vars::builder().coordinate("x").limits(limits).build()?;
    /// assert_eq!(vars.limits().max_degree, Limits::MAX_DEGREE);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub const MAX_DEGREE: u32 = i32::MAX.unsigned_abs();

    /// The same limits with no exponent past `d` in absolute value (no trigonometric order past
    /// it in an angle).
    #[must_use]
    pub fn max_degree(mut self, d: u32) -> Self {
        self.max_degree = d;
        self
    }

    /// The same limits with at most `n` term products a product of polynomials, and a sum's
    /// products together.
    #[must_use]
    pub fn max_term_products(mut self, n: u64) -> Self {
        self.max_term_products = n;
        self
    }

    /// The same limits with at most `n` bytes of room reserved for a result from its predicted
    /// count of terms, with what is held beside it.
    #[must_use]
    pub fn max_reserved_bytes(mut self, n: u64) -> Self {
        self.max_reserved_bytes = n;
        self
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_terms: 20_000_000,
            max_degree: Limits::DEFAULT_MAX_DEGREE,
            max_term_products: Limits::DEFAULT_MAX_TERM_PRODUCTS,
            max_reserved_bytes: Limits::NO_MEMORY_CAP,
        }
    }
}

/// The widths an exponent field may have: `64 / bits` fields fill a word (the bits left over,
/// at the bottom of each word, stay zero).
pub const FIELD_BITS: [u32; 6] = [8, 10, 12, 16, 21, 32];

/// The most radicals a set may declare: their independence is checked on every product of
/// them, `2^n − 1` products.
pub(crate) const MAX_RADICALS: usize = 8;

/// How exponent vectors are packed: `bits` per variable, fields never straddle words, variable
/// 0 in the top bits of word 0, each field storing `e + 2^(bits−1)`. Comparing the words as
/// unsigned integers, word 0 first, is then the lexicographic order on exponent vectors, and
/// the product of monomials is `a + b − bias` word by word.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Layout {
    pub bits: u32,
    pub per_word: usize,
    pub words: usize,
    pub bias: Vec<u64>,
    pub max_exp: i64,
    /// The field of each variable: [`Layout::field`] without a division.
    fields: Vec<(usize, u32)>,
}

impl Layout {
    fn new(nvars: usize, bits: u32) -> Layout {
        let per_word = (64 / bits) as usize;
        let words = Layout::words_for(nvars, bits);
        let mut bias = vec![0u64; words];
        let fields: Vec<(usize, u32)> = (0..nvars)
            .map(|j| Layout::place(per_word, bits, j))
            .collect();
        for &(w, shift) in &fields {
            bias[w] |= 1u64 << (shift + bits - 1);
        }
        Layout {
            bits,
            per_word,
            words,
            bias,
            max_exp: Layout::max_exp_for(bits),
            fields,
        }
    }

    /// The largest exponent a field of `bits` holds (its values are `e + 2^(bits−1)`).
    fn max_exp_for(bits: u32) -> i64 {
        (1i64 << (bits - 1)) - 1
    }

    /// The ones of one field, at the bottom of a word (every width is below 64 bits).
    #[inline]
    pub fn field_mask(&self) -> u64 {
        (1u64 << self.bits) - 1
    }

    /// The words a monomial in `nvars` variables takes with fields of `bits`.
    fn words_for(nvars: usize, bits: u32) -> usize {
        nvars.div_ceil((64 / bits) as usize).max(1)
    }

    /// The field width for `nvars` variables whose exponents stay within `max_degree`: of the
    /// widths that hold `max_degree`, the one that packs a monomial into the fewest words (the
    /// widest of those, for room to spare); the widest of all when none holds it.
    fn automatic_bits(nvars: usize, max_degree: u32) -> u32 {
        FIELD_BITS
            .into_iter()
            .filter(|&bits| Layout::max_exp_for(bits) >= i64::from(max_degree))
            .min_by_key(|&bits| (Layout::words_for(nvars, bits), std::cmp::Reverse(bits)))
            .unwrap_or(FIELD_BITS[FIELD_BITS.len() - 1])
    }

    #[inline]
    fn place(per_word: usize, bits: u32, j: usize) -> (usize, u32) {
        let w = j / per_word;
        let slot = (j % per_word) as u32;
        (w, 64 - bits * (slot + 1))
    }

    /// Where variable `j` is stored: the word, and the shift of its field in that word.
    #[inline]
    pub fn field(&self, j: usize) -> (usize, u32) {
        self.fields[j]
    }

    /// The exponent of variable `j` in a packed monomial.
    #[inline]
    pub fn get(&self, m: &[u64], j: usize) -> i64 {
        self.read(m, self.field(j))
    }

    /// The exponent in the field `(word, shift)` (from [`Layout::field`]) of a packed
    /// monomial: what `get` does once the field is known.
    #[inline]
    pub fn read(&self, m: &[u64], (w, shift): (usize, u32)) -> i64 {
        ((m[w] >> shift) & self.field_mask()) as i64 - (1i64 << (self.bits - 1))
    }

    /// Unpacks the first `out.len()` exponents of a packed monomial.
    #[inline]
    pub fn unpack_into(&self, m: &[u64], out: &mut [i64]) {
        let mask = self.field_mask();
        let bias = 1i64 << (self.bits - 1);
        for (j, o) in out.iter_mut().enumerate() {
            let w = j / self.per_word;
            let slot = (j % self.per_word) as u32;
            let shift = 64 - self.bits * (slot + 1);
            *o = ((m[w] >> shift) & mask) as i64 - bias;
        }
    }

    /// The packed translation by `e` in variable `j` (add it with `mul_into`).
    pub fn unit(&self, j: usize, e: i64, out: &mut [u64]) {
        out.copy_from_slice(&self.bias);
        let (w, shift) = Layout::place(self.per_word, self.bits, j);
        out[w] = out[w].wrapping_add((e as u64) << shift);
    }

    /// Packs an exponent vector (each `|e| <= max_exp`) into `out`.
    pub fn pack(&self, exps: &[i64], out: &mut [u64]) {
        out.copy_from_slice(&self.bias);
        for (j, &e) in exps.iter().enumerate() {
            let (w, shift) = Layout::place(self.per_word, self.bits, j);
            out[w] = out[w].wrapping_add((e as u64) << shift);
        }
    }

    /// The packed monomial 1 (all exponents zero).
    pub fn one(&self) -> &[u64] {
        &self.bias
    }

    /// The word-wise amount that multiplies a packed monomial by `m` when added with wrapping,
    /// `m − 1` (the bias): see [`Layout::push_translated`].
    pub fn translation(&self, m: &[u64]) -> Vec<u64> {
        m.iter()
            .zip(&self.bias)
            .map(|(m, one)| m.wrapping_sub(*one))
            .collect()
    }

    /// Appends `a · m` given `by = translation(m)` (one add per word, exact because the caller
    /// guarantees every field stays in range): a product's monomials are appended without
    /// zeroing their vector first.
    #[inline]
    pub fn push_translated(out: &mut Vec<u64>, a: &[u64], by: &[u64]) {
        out.extend(a.iter().zip(by).map(|(a, b)| a.wrapping_add(*b)));
    }

    /// `out = a · b` (exponents add); the caller guarantees every field stays in range.
    #[inline]
    pub fn mul_into(&self, a: &[u64], b: &[u64], out: &mut [u64]) {
        for w in 0..self.words {
            out[w] = a[w].wrapping_add(b[w]).wrapping_sub(self.bias[w]);
        }
    }
}

/// An ordered set of named variables shared by a family of polynomials, with their packing and
/// their limits: declared by [`Vars::builder`], and read through the handle [`Vars`] that its
/// build gives, which derefs to it.
///
/// ```
/// use trigpoly::{VarKind, Vars};
/// let vars = Vars::builder()
///     .coordinate("x")
///     .momentum("p_x")
///     .angle("theta")
///     .parameter("omega")
///     .build()
///     .unwrap();
/// let omega = vars.lookup("ω").unwrap();
/// assert_eq!(vars.variable(omega).kind(), VarKind::Parameter);
/// assert_eq!(vars.variable(vars.lookup("theta").unwrap()).latex(), r"\theta");
/// ```
#[derive(Clone, Debug)]
pub struct VarSet {
    vars: Vec<Variable>,
    layout: Layout,
    limits: Limits,
    /// The field width the declaration asked for, if it did (else the limits chose it).
    requested_bits: Option<u32>,
    /// The number of the list of variables, shared by every set that declares the same ones
    /// (given when the set is interned), which its handles carry.
    declaration: u32,
    /// Names the parser reads besides the variables ([`VarsBuilder::also_named`]).
    also_named: Vec<String>,
}

/// Two sets are the same ring when they have the same variables, packing and limits, whether
/// the width was asked for or chosen.
impl PartialEq for VarSet {
    fn eq(&self, other: &Self) -> bool {
        (&self.vars, &self.layout, self.limits, &self.also_named)
            == (&other.vars, &other.layout, other.limits, &other.also_named)
    }
}

impl Eq for VarSet {}

impl VarSet {
    /// Number of variables.
    pub fn len(&self) -> usize {
        self.vars.len()
    }

    /// Whether no variable is declared.
    pub fn is_empty(&self) -> bool {
        self.vars.is_empty()
    }

    /// The variable behind a handle.
    ///
    /// # Panics
    ///
    /// If the handle is not one of this set's ([`VarSet::owns`]).
    pub fn variable(&self, v: Var) -> &Variable {
        &self.vars[self.index_of(v)]
    }

    /// Whether `v` is a handle of this set: found in it, or in a set that declares the same
    /// variables.
    pub fn owns(&self, v: Var) -> bool {
        // A declaration's number is given to one list of variables (`Vars::intern`), and a
        // handle is made only by a set of that list ([`VarSet::var_at`]), so its index is in
        // range: the check every canonical bracket makes of its pairs is one comparison each.
        debug_assert!(v.declaration != self.declaration || v.index() < self.vars.len());
        v.declaration == self.declaration
    }

    /// The index of `v`, a handle of this set.
    ///
    /// # Panics
    ///
    /// If it is not one ([`VarSet::owns`]): a handle of another set would name whatever
    /// variable stands at its index here.
    #[track_caller]
    pub(crate) fn index_of(&self, v: Var) -> usize {
        assert!(
            self.owns(v),
            "a variable handle of another variable set was used with {self} (a Var is valid with \
             the set it was found in, or one that declares the same variables)"
        );
        v.index()
    }

    /// The index of `v`, or [`AlgebraError::VarSetMismatch`] if it is not a handle of this set.
    pub(crate) fn checked_index(&self, v: Var) -> Result<usize, AlgebraError> {
        match self.owns(v) {
            true => Ok(v.index()),
            false => Err(AlgebraError::VarSetMismatch),
        }
    }

    /// The handle of the variable at `index`.
    pub(crate) fn var_at(&self, index: usize) -> Var {
        debug_assert!(index < self.vars.len());
        Var {
            index: index as u16,
            declaration: self.declaration,
        }
    }

    /// All handles, in declaration order.
    pub fn vars(&self) -> impl Iterator<Item = Var> + '_ {
        (0..self.vars.len()).map(|k| self.var_at(k))
    }

    /// The variable of a name, in any of its spellings: its declared name, its unicode form
    /// (`ω`, `p_θ`) or that form with the Greek letters spelled out (`omega`, and `p_theta`
    /// for a momentum declared `p_θ`). [`VarsBuilder::build`] makes sure that no spelling
    /// fits two variables.
    pub fn lookup(&self, name: &str) -> Option<Var> {
        self.vars
            .iter()
            .position(|v| v.spelled(name))
            .map(|k| self.var_at(k))
    }

    /// Every name the parser reads in an expression on this set: the variables in each of
    /// their spellings, and the names of [`VarsBuilder::also_named`].
    pub(crate) fn declared_names(&self) -> impl Iterator<Item = &str> {
        let spellings = self.vars.iter().flat_map(Variable::spellings);
        spellings.chain(self.also_named.iter().map(String::as_str))
    }

    /// Whether one-letter names written side by side, `run` in order, could read back as a
    /// variable or a name of [`VarsBuilder::also_named`] ([`juxtaposition_is_ambiguous`]):
    /// `x`, `y` beside a variable `xy`, which the printers then write `x y`.
    ///
    /// ```
    /// use trigpoly::Vars;
    ///
    /// let vars = Vars::builder().coordinate("x").coordinate("y").parameter("M");
    /// let vars = vars.also_named(["Hy"]).build().unwrap();
    /// assert!(!vars.juxtaposition_is_ambiguous(&["M", "x", "y"]));
    /// let vars = Vars::builder().coordinate("x").coordinate("y").parameter("M");
    /// let vars = vars.also_named(["xy"]).build().unwrap();
    /// assert!(vars.juxtaposition_is_ambiguous(&["M", "x", "y"]));
    /// assert!(!vars.juxtaposition_is_ambiguous(&["y", "M", "x"]));
    /// ```
    pub fn juxtaposition_is_ambiguous(&self, run: &[&str]) -> bool {
        juxtaposition_is_ambiguous(self.declared_names(), run)
    }

    /// Whether the printer could write `name` for a product of one-letter variables side by
    /// side and not know it: `name` has several letters, each the spelling of a one-letter
    /// variable or `i` (`Mx` for `M x`), and it is neither a variable nor one of the names of
    /// [`VarsBuilder::also_named`], whose products the printer spaces (`M x`). A function of
    /// such a name would read back from a printed product.
    ///
    /// ```
    /// use trigpoly::Vars;
    ///
    /// let vars = Vars::builder().coordinate("x").parameter("M").build().unwrap();
    /// assert!(vars.juxtaposition_spells("Mx"));
    /// assert!(!vars.juxtaposition_spells("Mz"));
    /// let told = Vars::builder().coordinate("x").parameter("M").also_named(["Mx"]);
    /// assert!(!told.build().unwrap().juxtaposition_spells("Mx"));
    /// ```
    pub fn juxtaposition_spells(&self, name: &str) -> bool {
        let letter = |c: char| {
            c == 'i' || (self.vars.iter().flat_map(Variable::spellings)).any(|s| s.chars().eq([c]))
        };
        self.lookup(name).is_none()
            && !self.also_named.iter().any(|n| n == name)
            && spelled_by(name, letter)
    }

    /// The limits in force.
    pub fn limits(&self) -> Limits {
        self.limits
    }

    /// The angle variables.
    pub fn angles(&self) -> impl Iterator<Item = Var> + '_ {
        self.vars()
            .filter(|&v| self.variable(v).kind == VarKind::Angle)
    }

    /// The denominator atoms ([`VarKind::Denominator`]), in declaration order.
    pub fn denominators(&self) -> impl Iterator<Item = Var> + '_ {
        self.vars()
            .filter(|&v| self.variable(v).kind == VarKind::Denominator)
    }

    /// The radicals ([`VarKind::Radical`]), in declaration order.
    pub fn radicals(&self) -> impl Iterator<Item = Var> + '_ {
        self.vars()
            .filter(|&v| self.variable(v).kind == VarKind::Radical)
    }

    pub(crate) fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The same variables with other limits (and the packing those limits call for, unless
    /// the declaration asked for a field width).
    pub fn with_limits(&self, limits: Limits) -> Result<Vars, AlgebraError> {
        VarsBuilder {
            vars: self.vars.clone(),
            limits,
            bits: self.requested_bits,
            also_named: self.also_named.clone(),
        }
        .build()
    }

    /// The bits of each exponent field in the packed monomials.
    pub fn exponent_bits(&self) -> u32 {
        self.layout.bits
    }

    /// The machine words a packed monomial takes.
    pub fn monomial_words(&self) -> usize {
        self.layout.words
    }
}

/// A handle to a [`VarSet`], which every polynomial of the ring carries: a shared reference to
/// the one copy of the set that the process keeps (sets are interned when built, for the
/// process's lifetime). A handle is a pointer, so creating and dropping a polynomial touches no
/// shared counter: with an `Arc` the counter's cache line moved between cores on every
/// polynomial made, which took a fifth of W4's time on two threads. Rings are declared, not
/// computed, so the interned sets stay few; building an equal set again returns the same one.
///
/// ```
/// use trigpoly::{VarSet, Vars};
///
/// let vars: Vars = Vars::builder().coordinate("x").momentum("p_x").build()?;
/// let set: &VarSet = &vars;
/// assert_eq!(set.len(), 2);
/// let again = Vars::builder().coordinate("x").momentum("p_x").build()?;
/// assert!(Vars::ptr_eq(&vars, &again));
/// # Ok::<(), trigpoly::AlgebraError>(())
/// ```
#[derive(Clone)]
pub struct Vars(&'static VarSet);

/// Every set the process has built, once ([`Vars::intern`]); a handle's `Debug` finds its
/// variable's name here by its declaration number.
static INTERNED: Mutex<Vec<&'static VarSet>> = Mutex::new(Vec::new());

impl Vars {
    /// Starts declaring variables: [`VarsBuilder::build`] checks them and gives the handle of
    /// their set.
    pub fn builder() -> VarsBuilder {
        VarsBuilder::default()
    }

    /// The handle of the interned set equal to `set` (interning it if it is new).
    /// Its declaration number is that of the interned sets with the same variables, or the
    /// next one.
    fn intern(mut set: VarSet) -> Vars {
        static DECLARATIONS: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
        // A panic elsewhere cannot leave the list half-changed: only a push changes it.
        let mut interned = INTERNED.lock().unwrap_or_else(|e| e.into_inner());
        let same = |s: &&'static VarSet| **s == set && s.requested_bits == set.requested_bits;
        if let Some(found) = interned.iter().copied().find(same) {
            return Vars(found);
        }
        set.declaration = match interned.iter().find(|s| s.vars == set.vars) {
            Some(s) => s.declaration,
            None => DECLARATIONS.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
        };
        let leaked: &'static VarSet = Box::leak(Box::new(set));
        interned.push(leaked);
        Vars(leaked)
    }

    /// Whether two handles point to the same set (a pointer comparison; equal sets that differ
    /// only in a requested field width are two sets).
    pub fn ptr_eq(a: &Vars, b: &Vars) -> bool {
        std::ptr::eq(a.0, b.0)
    }
}

impl std::ops::Deref for Vars {
    type Target = VarSet;
    fn deref(&self) -> &VarSet {
        self.0
    }
}

/// Handles are equal when their sets are the same ring ([`VarSet`]'s equality): the pointer
/// first, so that the common case, one interned set, compares no variables.
impl PartialEq for Vars {
    fn eq(&self, other: &Vars) -> bool {
        Vars::ptr_eq(self, other) || *self.0 == *other.0
    }
}

impl Eq for Vars {}

impl fmt::Debug for Vars {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

/// Declares the variables of a set, in order ([`Vars::builder`]), and builds the handle
/// [`Vars`] of the set ([`VarsBuilder::build`]).
#[derive(Clone, Debug, Default)]
#[must_use = "a builder declares nothing until `build()` is called"]
pub struct VarsBuilder {
    vars: Vec<Variable>,
    limits: Limits,
    bits: Option<u32>,
    also_named: Vec<String>,
}

impl VarsBuilder {
    /// Declares a variable of the given kind.
    pub fn variable(mut self, name: &str, kind: VarKind) -> Self {
        let (unicode, latex) = match kind {
            VarKind::Momentum => render_momentum(name),
            _ => render_name(name),
        };
        let spelled_out = spell_out(&unicode);
        // A name declared in Greek letters (`θ`, `p_θ`) is written in ASCII spelled out
        // (`theta`, `p_theta`), which reads back; one with other letters beyond ASCII is its own.
        let ascii = match &spelled_out {
            Some(spelled) if !name.is_ascii() && spelled.is_ascii() => spelled.clone(),
            _ => name.to_string(),
        };
        self.vars.push(Variable {
            name: name.to_string(),
            spelled_out,
            ascii,
            unicode,
            latex,
            kind,
            word: false,
            radicand: None,
        });
        self
    }
    /// Declares a coordinate.
    pub fn coordinate(self, name: &str) -> Self {
        self.variable(name, VarKind::Coordinate)
    }
    /// Declares a momentum.
    pub fn momentum(self, name: &str) -> Self {
        self.variable(name, VarKind::Momentum)
    }
    /// Declares a parameter.
    pub fn parameter(self, name: &str) -> Self {
        self.variable(name, VarKind::Parameter)
    }
    /// Declares an angle.
    pub fn angle(self, name: &str) -> Self {
        self.variable(name, VarKind::Angle)
    }
    /// Declares a Poisson variable: a phase-space variable whose brackets are declared.
    pub fn poisson(self, name: &str) -> Self {
        self.variable(name, VarKind::Poisson)
    }
    /// Declares a denominator atom ([`VarKind::Denominator`]) standing for the polynomial
    /// `polynomial` reads as in the variables declared so far, checked as a system file's
    /// `denominators` are ([`Expr::denominator_refusal`](crate::Expr::denominator_refusal)),
    /// with its three forms derived from it
    /// ([`Expr::denominator_forms`](crate::Expr::denominator_forms)): the way to declare one
    /// in code. A polynomial that does not read, or is refused, is an
    /// [`AlgebraError::DenominatorRefused`] naming it and saying why; so is an error of the
    /// variables declared before it (two alike), which it reads in.
    ///
    /// ```
    /// use trigpoly::{AlgebraError, Expr, Vars};
    ///
    /// let builder = Vars::builder().coordinate("q1").parameter("a1").parameter("a2");
    /// let vars = builder.clone().denominator("a1 - a2")?.build()?;
    /// let e = Expr::parse(&vars, "q1/(2*(a2 - a1))").unwrap();
    /// assert_eq!(e.to_string(), "−q1/(2 (a1 − a2))");
    /// assert_eq!(e.to_latex(), r"-\frac{q_{1}}{2 (a_{1} - a_{2})}");
    /// // A single term divides exactly already; it is refused, saying why.
    /// let Err(AlgebraError::DenominatorRefused { denominator, message }) =
    ///     builder.denominator("2*a1")
    /// else {
    ///     panic!("2 a1 is a single term");
    /// };
    /// assert_eq!(denominator, "(2*a1)");
    /// assert!(message.starts_with("2 a1 is a single term"), "{message}");
    /// # Ok::<(), AlgebraError>(())
    /// ```
    pub fn denominator(self, polynomial: &str) -> Result<Self, AlgebraError> {
        let refused = |message: String| AlgebraError::DenominatorRefused {
            denominator: format!("({polynomial})"),
            message,
        };
        let vars = self.clone().build().map_err(|e| refused(e.to_string()))?;
        let value = crate::Expr::parse(&vars, polynomial)
            .map_err(|e| refused(format!("the denominator {polynomial} does not read: {e}")))?;
        if let Some(why) = crate::Expr::denominator_refusal(&value) {
            return Err(refused(why));
        }
        let (ascii, unicode, latex) = value.denominator_forms();
        Ok(self.denominator_unchecked(&ascii, &unicode, &latex))
    }
    /// Declares a denominator atom ([`VarKind::Denominator`]) standing for the polynomial
    /// whose parseable ASCII form is `ascii` and whose text and LaTeX forms are `unicode` and
    /// `latex`, as given: nothing checks that the three agree, or that the polynomial may be
    /// a denominator, before [`Expr::denominator_atoms`](crate::Expr::denominator_atoms)
    /// reads `ascii` (whose own refusals the tests reach through it).
    /// [`VarsBuilder::denominator`] derives and checks them, and is the only way out of the
    /// crate. Its names are these in parentheses, `(x - y)`, which the parser never reads as a
    /// name but reads back as `D` itself.
    pub(crate) fn denominator_unchecked(mut self, ascii: &str, unicode: &str, latex: &str) -> Self {
        self.vars.push(Variable {
            name: format!("({ascii})"),
            spelled_out: None,
            ascii: format!("({ascii})"),
            unicode: format!("({unicode})"),
            latex: format!("({latex})"),
            kind: VarKind::Denominator,
            word: false,
            radicand: None,
        });
        self
    }
    /// Declares a radical ([`VarKind::Radical`]) named `name`, standing for the positive square
    /// root of the polynomial whose parseable ASCII form is `radicand` (`x^2 + y^2`), read in
    /// the set's other variables ([`Poly::radicals`](crate::Poly::radicals) reads and checks
    /// it).
    pub fn radical(mut self, name: &str, radicand: &str) -> Self {
        self = self.variable(name, VarKind::Radical);
        if let Some(v) = self.vars.last_mut() {
            v.radicand = Some(radicand.to_string());
        }
        self
    }
    /// Shows the variable declared last as the name `display` would be shown (`A_x`, `A_{x}`
    /// in LaTeX, for a variable named `Ax`), when `display` is an identifier, possibly with a
    /// bar (a combining macron, `Z̄`) and primes (`G1'`, `G_{1}'`), or words of those (`Re K`:
    /// [`shown_forms`]); otherwise, or with nothing
    /// declared, changes nothing. Its ASCII form stays its name, which reads back. Its text is
    /// the display as [`shown_text`] prints it everywhere else, a precomposed barred letter
    /// kept as written (`Ā_x`, not `A` and a combining bar, which a comparison with the
    /// display would find different). [`VarsBuilder::build`] refuses two variables shown
    /// alike.
    pub fn shown_as(self, display: &str) -> Self {
        match shown_forms(display) {
            Some((text, latex)) => self.printed_as(&shown_text_of(display, text), &latex),
            None => self,
        }
    }
    /// Prints the variable declared last as `unicode` in text and `latex` in LaTeX, as
    /// [`VarsBuilder::shown_as`] does with the forms of a display name, where the caller has
    /// made them (a momentum `p_ω₊` of a coordinate shown as `ω₊`, `p_{\omega_{+}}`); with
    /// nothing declared, changes nothing. Its ASCII form stays its name, which reads back, and
    /// [`VarSet::lookup`] finds it by `unicode` too.
    pub fn printed_as(mut self, unicode: &str, latex: &str) -> Self {
        if let Some(v) = self.vars.last_mut() {
            (v.unicode, v.latex) = (unicode.to_string(), latex.to_string());
            v.spelled_out = spell_out(&v.unicode);
        }
        self
    }
    /// Sets the variable declared last apart in text's products, as a word, even when its name
    /// is one letter: `−ω² L` and `ω² L²` where a generator `L` of an algebra stands beside
    /// parameters, as `4 G1` does (without it, `−ω²L`, as `Mω²x` is written in a phase space).
    pub fn word(mut self) -> Self {
        if let Some(v) = self.vars.last_mut() {
            v.word = true;
        }
        self
    }
    /// Sets the limits.
    pub fn limits(mut self, limits: Limits) -> Self {
        self.limits = limits;
        self
    }
    /// Bits per exponent in the packed words, one of [`FIELD_BITS`]: wider fields allow
    /// larger exponents (the degree limit is lowered to what the field holds), narrower ones
    /// pack more variables per word. Without this the width follows the degree limit: the
    /// fewest words whose fields hold it (`max_degree` 1000, the default, takes 12 bits: five
    /// variables to a word).
    pub fn exponent_bits(mut self, bits: u32) -> Self {
        self.bits = Some(bits);
        self
    }

    /// Names that the parser reads besides the variables (a system's functions, `Mx`): the
    /// printer spaces a run of one-letter variables side by side of which two or more in a
    /// row would spell one of them ([`VarSet::juxtaposition_is_ambiguous`]: `M x` beside
    /// `Mx`). Sets that differ in these names are different rings; they share their
    /// variables' handles.
    pub fn also_named<'a>(mut self, names: impl IntoIterator<Item = &'a str>) -> Self {
        self.also_named
            .extend(names.into_iter().map(str::to_string));
        self
    }

    /// Checks names and limits and builds the set, giving the handle of its one interned copy:
    /// a degree limit of 0 is refused, as it would leave no variable writable, not even `x`
    /// itself.
    pub fn build(self) -> Result<Vars, AlgebraError> {
        if self.limits.max_degree == 0 {
            return Err(AlgebraError::SettingOutOfRange {
                setting: Setting::MaxDegree,
                value: 0,
            });
        }
        if let Some(bits) = self.bits.filter(|b| !FIELD_BITS.contains(b)) {
            return Err(AlgebraError::SettingOutOfRange {
                setting: Setting::ExponentBits,
                value: bits.into(),
            });
        }
        // The name each variable's LaTeX reads back as (`o` of both `o` and `\mathit{o}`, which
        // is omicron's), which two variables cannot share: the reader could not tell them apart.
        let read_back: Vec<Option<String>> = (self.vars.iter())
            .map(|v| match v.kind {
                VarKind::Denominator => None,
                _ => crate::syntax::latex_name(&v.latex),
            })
            .collect();
        for (k, v) in self.vars.iter().enumerate() {
            if v.kind == VarKind::Denominator {
                if self.vars[..k].iter().any(|w| w.name == v.name) {
                    return Err(AlgebraError::DeclaredTwice {
                        name: v.name.clone(),
                        first: v.name.clone(),
                    });
                }
                continue;
            }
            if let Some(reason) = BadName::of(&v.name) {
                return Err(AlgebraError::InvalidName {
                    name: v.name.clone(),
                    reason,
                });
            }
            for (j, w) in self.vars[..k].iter().enumerate() {
                if w.spelled_alike(v) {
                    return Err(AlgebraError::DeclaredTwice {
                        name: v.name.clone(),
                        first: w.name.clone(),
                    });
                }
                // `x1` and `x₁` read apart in text, and alike in LaTeX output; `o` and
                // `omicron`, `o` and `\mathit{o}`, differ in it but read back alike.
                if w.latex == v.latex || (read_back[k].is_some() && read_back[j] == read_back[k]) {
                    return Err(AlgebraError::PrintedAlike {
                        name: v.name.clone(),
                        first: w.name.clone(),
                        latex: v.latex.clone(),
                    });
                }
            }
        }
        if self.vars.len() > u16::MAX as usize {
            return Err(AlgebraError::SettingOutOfRange {
                setting: Setting::Variables,
                value: self.vars.len() as u64,
            });
        }
        let bits = self
            .bits
            .unwrap_or_else(|| Layout::automatic_bits(self.vars.len(), self.limits.max_degree));
        let layout = Layout::new(self.vars.len(), bits);
        let max_degree = self.limits.max_degree.min(layout.max_exp as u32);
        let limits = Limits {
            max_degree,
            ..self.limits
        };
        Ok(Vars::intern(VarSet {
            vars: self.vars,
            layout,
            limits,
            requested_bits: self.bits,
            declaration: 0,
            also_named: self.also_named,
        }))
    }
}

impl fmt::Display for VarSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.vars.iter().map(|v| v.unicode.as_str()).collect();
        write!(f, "{{{}}}", names.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{GaussianRational, Poly};

    #[test]
    fn a_kind_prints_as_messages_name_it_without_its_article() {
        let kinds = [
            (VarKind::Coordinate, "coordinate"),
            (VarKind::Momentum, "momentum"),
            (VarKind::Parameter, "parameter"),
            (VarKind::Angle, "angle"),
            (VarKind::Poisson, "Poisson variable"),
            (VarKind::Denominator, "denominator"),
            (VarKind::Radical, "radical"),
        ];
        for (kind, text) in kinds {
            assert_eq!(kind.to_string(), text);
            assert!(kind.described().ends_with(&format!(" {text}")), "{kind:?}");
        }
    }

    #[test]
    fn function_names_are_reserved() {
        for name in ["i", "cos", "sin", "exp", "conj", "re", "im", "sqrt"] {
            let err = Vars::builder().coordinate("x").parameter(name).build();
            let err = err.map(|_| ()).unwrap_err();
            assert_eq!(
                err,
                AlgebraError::InvalidName {
                    name: name.into(),
                    reason: BadName::Reserved
                },
                "{name}"
            );
            assert_eq!(
                err.to_string(),
                format!(
                    "{name:?} cannot name a variable: i, cos, sin, exp, conj, re, im and sqrt \
                     are reserved"
                ),
                "{name}"
            );
        }
        assert!(Vars::builder().parameter("real").build().is_ok());
    }

    /// The builder refuses a name by [`BadName`], the rule superint's file loader applies too,
    /// each with its reason: not an identifier, an empty subscript (`a_`, which LaTeX wrote as
    /// `\mathrm{a_}`, was taken here and refused by the loader), a letter LaTeX cannot write.
    #[test]
    fn a_bad_name_is_refused_with_its_reason() {
        for (name, why) in [
            (
                "2Q",
                "a name is letters, digits and '_', starting with a letter",
            ),
            (
                "p x",
                "a name is letters, digits and '_', starting with a letter",
            ),
            (
                "",
                "a name is letters, digits and '_', starting with a letter",
            ),
            ("a_", "a name cannot begin or end in '_' or hold '__'"),
            ("_a", "a name cannot begin or end in '_' or hold '__'"),
            ("a__b", "a name cannot begin or end in '_' or hold '__'"),
            (
                "θé",
                "LaTeX has no letter 'é' (a name's letters are ASCII, Greek (alpha or α), ħ, ℓ \
                 and the subscript digits ₀–₉)",
            ),
            (
                "x²",
                "LaTeX has no letter U+00B2 (a name's letters are ASCII, Greek (alpha or α), ħ, \
                 ℓ and the subscript digits ₀–₉)",
            ),
        ] {
            let err = Vars::builder().coordinate(name).build().map(|_| ());
            let err = err.unwrap_err();
            assert!(
                matches!(&err, AlgebraError::InvalidName { name: n, reason }
                    if n == name && reason.to_string() == why),
                "{name:?}: {err:?}"
            );
            assert_eq!(
                err.to_string(),
                format!("{name:?} cannot name a variable: {why}"),
                "{name:?}"
            );
        }
        // A long name is carried whole, and shown by its start and its length.
        let long = "a".repeat(81);
        let err = Vars::builder().parameter(&long).build().map(|_| ());
        let err = err.unwrap_err();
        assert_eq!(
            err,
            AlgebraError::InvalidName {
                name: long.clone(),
                reason: BadName::TooLong
            }
        );
        assert_eq!(
            err.to_string(),
            format!(
                "{:?}…, 81 characters long, cannot name a variable: a name has at most 80 \
                 characters",
                "a".repeat(40)
            )
        );
        for name in ["a_b", "p_theta", "x₁", "ħ", "H", "rank", &"a".repeat(80)] {
            assert_eq!(BadName::of(name), None, "{name}");
            Vars::builder().coordinate(name).build().expect(name);
        }
    }

    /// A handle's `Debug` names its variable, beside its index and declaration, so that a
    /// failed comparison of handles or of values keyed by them says which variables differ.
    #[test]
    fn a_handle_shows_its_variable_s_name() {
        let vars = Vars::builder()
            .coordinate("x")
            .momentum("p_x")
            .parameter("ω")
            .denominator("x - ω")
            .unwrap()
            .build()
            .unwrap();
        let shown: Vec<String> = vars.vars().map(|v| format!("{v:?}")).collect();
        let declaration = vars.vars().next().unwrap().declaration;
        let names = ["x", "p_x", "omega", "(x - omega)"];
        for (k, (shown, name)) in shown.iter().zip(names).enumerate() {
            assert_eq!(
                *shown,
                format!("Var({name}, {k} of declaration {declaration})")
            );
        }
        assert_eq!(shown.len(), 4);
    }

    #[test]
    fn equal_declarations_share_one_interned_set() {
        let plane = || Vars::builder().coordinate("x").coordinate("y");
        let a = plane().build().unwrap();
        let b = plane().build().unwrap();
        assert!(Vars::ptr_eq(&a, &b));
        // The field width the limits chose, asked for: the same ring, a second set.
        let asked = plane().exponent_bits(a.exponent_bits()).build().unwrap();
        assert!(!Vars::ptr_eq(&a, &asked));
        assert_eq!(a, asked);
        // Another order of the same names is another ring.
        let swapped = Vars::builder().coordinate("y").coordinate("x").build();
        assert_ne!(a, swapped.unwrap());
        assert!(Vars::ptr_eq(&a.with_limits(a.limits()).unwrap(), &a));
    }

    #[test]
    fn a_variable_shown_as_another_name() {
        let vars = Vars::builder()
            .coordinate("Ax")
            .shown_as("A_x")
            .coordinate("B")
            .shown_as("{not an identifier}")
            .build()
            .unwrap();
        let (ax, b) = (vars.lookup("Ax").unwrap(), vars.lookup("B").unwrap());
        assert_eq!(vars.variable(ax).name(), "Ax");
        assert_eq!(vars.variable(ax).unicode(), "A_x");
        assert_eq!(vars.variable(ax).latex(), "A_{x}");
        assert_eq!(vars.variable(b).unicode(), "B");
        // Two variables shown alike are refused, as two declared alike are.
        let twice = Vars::builder()
            .coordinate("Ax")
            .shown_as("A_x")
            .coordinate("A_x")
            .build();
        assert!(twice.is_err());
    }

    #[test]
    fn a_variable_is_found_by_every_spelling_shown_as_it_is() {
        // An angle declared in unicode, with its momentum named as a system file names it.
        let vars = Vars::builder()
            .angle("θ")
            .momentum(&format!("p_{}", "θ"))
            .parameter("omega")
            .parameter("Ω")
            .build()
            .unwrap();
        let [theta, p_theta, omega, big_omega] = ["θ", "p_θ", "ω", "Ω"].map(|n| {
            let v = vars.lookup(n).unwrap();
            assert_eq!(vars.variable(v).unicode(), n);
            v
        });
        for (spelling, var) in [
            ("theta", theta),
            ("θ", theta),
            ("p_theta", p_theta),
            ("p_θ", p_theta),
            ("omega", omega),
            ("ω", omega),
            ("Omega", big_omega),
        ] {
            assert_eq!(vars.lookup(spelling), Some(var), "{spelling}");
        }
        // Names shown otherwise are not these variables.
        for other in ["Theta", "p_Theta", "p_thet", "p_omega", "theta_p", "o"] {
            assert_eq!(vars.lookup(other), None, "{other}");
        }
        // And the same in expressions.
        let parse = |src| Poly::<GaussianRational>::parse(&vars, src).unwrap();
        assert_eq!(
            parse("p_theta^2/2 + omega*cos(2*theta)"),
            parse("p_θ^2/2 + ω*cos(2*θ)")
        );
        let unknown = Poly::<GaussianRational>::parse(&vars, "p_phi").unwrap_err();
        assert!(unknown.message().starts_with("unknown name 'p_phi'"));
    }

    /// `x1` and `x₁` read apart in text and print alike in LaTeX, `x_{1}`; `x1` and `x_1`
    /// also; `x1` and `x11` do not.
    #[test]
    fn two_variables_alike_in_latex_are_refused() {
        for second in ["x₁", "x_1"] {
            let err = Vars::builder()
                .coordinate("x1")
                .coordinate(second)
                .build()
                .unwrap_err();
            assert_eq!(
                err,
                AlgebraError::PrintedAlike {
                    name: second.into(),
                    first: "x1".into(),
                    latex: "x_{1}".into()
                }
            );
        }
        let err = Vars::builder()
            .parameter("o")
            .parameter("omicron")
            .build()
            .unwrap_err();
        assert!(matches!(err, AlgebraError::PrintedAlike { .. }), "{err}");
        assert!(Vars::builder()
            .coordinate("x1")
            .coordinate("x11")
            .build()
            .is_ok());
    }

    #[test]
    fn two_variables_found_by_one_spelling_are_refused() {
        let twice = |builder: VarsBuilder| builder.build().map(|_| ()).unwrap_err().to_string();
        let angles = Vars::builder().angle("theta").angle("θ");
        assert_eq!(
            twice(angles),
            r#"variable "θ" is declared twice (as "theta", which one spelling finds with it)"#
        );
        let parameters = Vars::builder().parameter("ω").parameter("omega");
        assert_eq!(
            twice(parameters),
            r#"variable "omega" is declared twice (as "ω", which one spelling finds with it)"#
        );
        // `y` would name the first, shown as y, and the second, declared y.
        let shown = Vars::builder()
            .coordinate("x")
            .shown_as("y")
            .coordinate("y")
            .shown_as("z");
        assert_eq!(
            twice(shown),
            r#"variable "y" is declared twice (as "x", which one spelling finds with it)"#
        );
    }

    #[test]
    fn layout_packs_and_orders_lexicographically() {
        let l = Layout::new(9, 16);
        assert_eq!(l.words, 3);
        let mut a = vec![0; 3];
        let mut b = vec![0; 3];
        l.pack(&[1, -2, 0, 0, 0, 0, 0, 0, 5], &mut a);
        l.pack(&[1, -3, 7, 0, 0, 0, 0, 0, 5], &mut b);
        assert!(a > b);
        assert_eq!(l.get(&a, 1), -2);
        assert_eq!(l.get(&a, 8), 5);
        let mut c = vec![0; 3];
        l.mul_into(&a, &b, &mut c);
        assert_eq!(
            (0..9).map(|j| l.get(&c, j)).collect::<Vec<_>>(),
            [2, -5, 7, 0, 0, 0, 0, 0, 10]
        );
    }
}
