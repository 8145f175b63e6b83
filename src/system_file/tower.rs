//! The tower of a family with an eigenvalue, `{K_{m,n}, H} = λ(m, n) K_{m,n}`: checked by
//! expansion for `1 ≤ m, n ≤ N`, and for all `m, n ≥ 0` by the eigenfunction lemma when the
//! family is a product of powers `A^m B^n` (with `exp(c·n·θ)` read as `exp(c·θ)^n`).
//!
//! The proof's steps are computed: `{A, H} = λ(1, 0) A`, `{B, H} = λ(0, 1) B`, the derivation
//! property on `A, B`, and that `λ(m, n) = mλ(1, 0) + nλ(0, 1)` (a bound on its degree in the
//! indices read from its expression, and the identity checked exactly on a grid of that size:
//! a polynomial of degree at most `d` in each index that vanishes on `0 ≤ m, n ≤ d` is zero).
//! The lemma then gives
//! `{A^m B^n, H} = (mλ(1, 0) + nλ(0, 1)) A^m B^n = λ(m, n) A^m B^n`.

use crate::render::tex::Names;
use std::time::Instant;

use trigpoly::syntax::{Expr as Tree, ExprKind};
use trigpoly::Expr;

use brackets::{Condition, EngineError};

use super::claims::{engine_error, parse_condition_with};
use super::error::{ErrorKind, FileError};
use super::scope::{substitute, Scope};
use super::text::{comma_pieces, trimmed, Text};
use super::{Caller, LoadedSystem};
use crate::report::{
    first_free, listed, ClaimResult, Entry, Fact, ProofResult, Report, Section, SummaryKind,
    TowerResult, PLACEHOLDERS,
};

/// The largest degree in the indices of an eigenvalue that the all-`m, n` proof compares on
/// a grid (`(d + 1)²` evaluations).
const MAX_EIGENVALUE_DEGREE: u32 = 32;

/// Whether a tree uses an index, as a name or inside the name of a family instance.
fn uses(tree: &Tree, index: &str) -> bool {
    tree.names()
        .into_iter()
        .any(|(n, _)| n == index || n.split('_').any(|p| p == index))
}

/// `A^1` → `A`, `1·a` → `a`: a base after the substitution of 1 for its index, for display.
fn drop_ones(tree: &Tree) -> Tree {
    let one = |t: &Tree| matches!(&t.kind, ExprKind::Integer(n) if *n == 1.into());
    let kind = match &tree.kind {
        ExprKind::Pow(a, b) if one(b) => return drop_ones(a),
        ExprKind::Mul(a, b) if one(a) => return drop_ones(b),
        ExprKind::Mul(a, b) if one(b) => return drop_ones(a),
        ExprKind::Mul(a, b) => ExprKind::Mul(Box::new(drop_ones(a)), Box::new(drop_ones(b))),
        ExprKind::Neg(a) => ExprKind::Neg(Box::new(drop_ones(a))),
        ExprKind::Call(f, span, args) => {
            ExprKind::Call(f.clone(), *span, args.iter().map(drop_ones).collect())
        }
        other => other.clone(),
    };
    Tree {
        kind,
        span: tree.span,
    }
}

/// The factors of a product.
fn factors(tree: &Tree) -> Vec<&Tree> {
    match &tree.kind {
        ExprKind::Mul(a, b) => {
            let mut f = factors(a);
            f.extend(factors(b));
            f
        }
        _ => vec![tree],
    }
}

/// How many times `index` is a factor of a product chain (`-i*n*theta`), or `None` if it is
/// used anywhere else.
fn product_uses(tree: &Tree, index: &str) -> Option<usize> {
    match &tree.kind {
        ExprKind::Name(n) if n == index => Some(1),
        ExprKind::Mul(a, b) => Some(product_uses(a, index)? + product_uses(b, index)?),
        ExprKind::Neg(a) => product_uses(a, index),
        _ if uses(tree, index) => None,
        _ => Some(0),
    }
}

/// A bound on the total degree of a tree in the indices, if it is a polynomial in them that
/// the syntax shows (`(m − 3n)^2` has degree at most 2; `m·n − m·n` is bounded by 2, too).
fn degree(tree: &Tree, indices: &[String; 2]) -> Option<u32> {
    let free = |t: &Tree| !indices.iter().any(|i| uses(t, i));
    match &tree.kind {
        ExprKind::Integer(_) => Some(0),
        ExprKind::Name(n) if indices.contains(n) => Some(1),
        ExprKind::Name(_) => free(tree).then_some(0),
        ExprKind::Neg(a) => degree(a, indices),
        ExprKind::Add(a, b) | ExprKind::Sub(a, b) => {
            Some(degree(a, indices)?.max(degree(b, indices)?))
        }
        ExprKind::Mul(a, b) => degree(a, indices)?.checked_add(degree(b, indices)?),
        ExprKind::Div(a, b) => (degree(b, indices)? == 0).then_some(degree(a, indices)?),
        ExprKind::Pow(a, e) if !free(a) => match &e.kind {
            ExprKind::Integer(k) => degree(a, indices)?.checked_mul(u32::try_from(k).ok()?),
            _ => None,
        },
        // A name before parentheses multiplies them: `i(mω − nΩ)` has the degree of its sum.
        ExprKind::Call(f, _, args)
            if args.len() == 1
                && !indices.contains(f)
                && !trigpoly::FUNCTIONS.contains(&f.as_str()) =>
        {
            degree(&args[0], indices)
        }
        ExprKind::Pow(..) | ExprKind::Call(..) | ExprKind::Bracket(..) => free(tree).then_some(0),
    }
}

/// For each index, the factor `A^m` (or `exp(c·m·θ)`) of a product of powers; or why the
/// value is not one.
fn powers(tree: &Tree, indices: &[String; 2]) -> Result<[Tree; 2], String> {
    let mut found: [Option<Tree>; 2] = [None, None];
    for f in factors(tree) {
        let used: Vec<usize> = (0..2).filter(|&j| uses(f, &indices[j])).collect();
        let [j] = used[..] else {
            return Err(if used.is_empty() {
                "it has a factor that depends on no index".into()
            } else {
                "it has a factor that depends on both indices".into()
            });
        };
        let idx = &indices[j];
        let ok = match &f.kind {
            ExprKind::Pow(base, e) => {
                matches!(&e.kind, ExprKind::Name(n) if n == idx) && !uses(base, idx)
            }
            ExprKind::Call(name, _, args) if name == "exp" && args.len() == 1 => {
                product_uses(&args[0], idx) == Some(1)
            }
            _ => false,
        };
        if !ok {
            return Err(format!(
                "its factor with the index {idx} is neither a power A^{idx} nor exp(c*{idx}*θ)"
            ));
        }
        if found[j].replace(f.clone()).is_some() {
            return Err(format!("the index {idx} appears in two factors"));
        }
    }
    match found {
        [Some(a), Some(b)] => Ok([a, b]),
        _ => Err("an index does not appear in it".into()),
    }
}

impl LoadedSystem {
    /// `λ(m, n)` of family `k`.
    ///
    /// Errors if the family has no eigenvalue.
    ///
    /// # Panics
    ///
    /// If `k` is not the index of one of [`LoadedSystem::families`] (see
    /// [`LoadedSystem::family`]).
    pub fn eigenvalue_at(&self, k: usize, m: i64, n: i64) -> Result<Expr, FileError> {
        let family = &self.families[k];
        let Some(text) = &family.eigenvalue else {
            return Err(family.source.error(
                ErrorKind::Family,
                family.span.clone(),
                format!("the family '{}' declares no eigenvalue", family.name),
            ));
        };
        self.family_text_at(k, text, m, n)
    }

    /// The fact that `λ(m, n) = m λ(1, 0) + n λ(0, 1)` for all `m, n`, where `λ` is a
    /// polynomial of total degree at most `d` in the indices: so is the difference, which is
    /// then zero when it vanishes on the grid `0 ≤ m, n ≤ d` (a polynomial of degree at most
    /// `d` in each variable is determined by its values there), so the grid decides it exactly.
    /// Where a base is zero (`zero`, after the condition) so is every instance with a power
    /// of it, which holds whatever `λ` is there: only `m = 0` (or `n = 0`) is compared, on
    /// the grid's line, which decides it as well.
    fn eigenvalue_is_linear(
        &self,
        k: usize,
        d: u32,
        shown: &str,
        when: Option<&Condition>,
        zero: [bool; 2],
    ) -> Result<Fact, FileError> {
        let [m, n] = &self.families[k].indices;
        let family = &self.families[k];
        let at = |e: trigpoly::AlgebraError| {
            engine_error(&family.source, family.span.clone(), &e.into())
        };
        let eigenvalue = |i: i64, j: i64| -> Result<Expr, FileError> {
            let value = self.eigenvalue_at(k, i, j)?;
            settled(when, value).map_err(|e| engine_error(&family.source, family.span.clone(), &e))
        };
        let (la, lb) = (eigenvalue(1, 0)?, eigenvalue(0, 1)?);
        let top = i64::from(d);
        let mut differs = None;
        // The indices of a zero base stay 0: the instances there are not zero.
        let (top_m, top_n) = (if zero[0] { 0 } else { top }, if zero[1] { 0 } else { top });
        'grid: for i in 0..=top_m {
            for j in 0..=top_n {
                let linear = la
                    .scale(&i.into())
                    .checked_add(&lb.scale(&j.into()))
                    .map_err(at)?;
                if eigenvalue(i, j)? != linear {
                    differs = Some((i, j));
                    break 'grid;
                }
            }
        }
        let points = (top_m + 1) * (top_n + 1);
        let kmn = format!("{}_{{{m},{n}}}", family.display);
        let (range, only) = match zero {
            [false, false] => (format!("0 ≤ {m}, {n} ≤ {d}"), String::new()),
            [true, false] => (
                format!("{m} = 0, 0 ≤ {n} ≤ {d}"),
                format!(" where {kmn} is not 0 (the first base is 0, so {kmn} is 0 for {m} ≥ 1)"),
            ),
            [false, true] => (
                format!("0 ≤ {m} ≤ {d}, {n} = 0"),
                format!(" where {kmn} is not 0 (the second base is 0, so {kmn} is 0 for {n} ≥ 1)"),
            ),
            [true, true] => (
                format!("{m} = {n} = 0"),
                format!(" where {kmn} is not 0 (both bases are 0, so {kmn} is 0 but at (0, 0))"),
            ),
        };
        let statement = match differs {
            None => format!(
                "λ({m}, {n}) = {shown} equals {m}λ(1, 0) + {n}λ(0, 1){only}: both are \
                 polynomials of degree at most {d} in {m}, {n}, and they agree at the {points} \
                 points {range}"
            ),
            Some((i, j)) => format!(
                "λ({m}, {n}) = {shown} equals {m}λ(1, 0) + {n}λ(0, 1): they differ at \
                 ({m}, {n}) = ({i}, {j})"
            ),
        };
        Ok(Fact {
            statement,
            holds: differs.is_none(),
            found: None,
            found_statement: None,
        })
    }

    /// The all-`m, n` proof for family `k`, or why there is none.
    fn family_proof(
        &self,
        k: usize,
        id: &str,
        statement: &str,
        when: Option<&Condition>,
    ) -> Result<Entry, FileError> {
        let family = &self.families[k];
        let source = &family.source;
        let scope = Scope::of_family(self, k);
        let tree = scope.tree(source, &family.value)?;
        let names = base_names(&self.system, self.family_names(), &family.indices);
        let factors = match powers(&tree, &family.indices) {
            Ok(p) => p,
            Err(why) => {
                let [a, b] = &names;
                return Ok(Entry::Text(format!(
                    "No proof for all m, n: `{}_{{m,n}}` is not a product of powers `{a}^m {b}^n` \
                     ({why}); the bounded check above is what holds.",
                    family.display
                )));
            }
        };
        let start = Instant::now();
        let (mut facts, bases) = self.base_facts(k, &scope, &factors, when)?;
        let eigen_tree = scope.tree(source, family.eigenvalue.as_ref().expect("checked"))?;
        let [m, n] = &family.indices;
        let shown = self.pretty(&eigen_tree);
        let Some(d) = degree(&eigen_tree, &family.indices).filter(|&d| d <= MAX_EIGENVALUE_DEGREE)
        else {
            return Ok(Entry::Text(format!(
                "No proof for all {m}, {n}: λ({m}, {n}) = {shown} is not a polynomial in {m}, {n} \
                 of degree at most {MAX_EIGENVALUE_DEGREE} as written, so it cannot be compared \
                 with {m}λ(1, 0) + {n}λ(0, 1) everywhere; the bounded check above is what holds."
            )));
        };
        let at = |e: &EngineError| engine_error(source, family.span.clone(), e);
        let mut zero = [false; 2];
        for (z, base) in zero.iter_mut().zip(&bases) {
            *z = settled(when, base.clone()).map_err(|e| at(&e))?.is_zero();
        }
        facts.push(self.eigenvalue_is_linear(k, d.max(1), &shown, when, zero)?);
        let leibniz_check = self.derivation_holds(k, &bases)?;
        let note = ProofResult::failed_steps(&facts, leibniz_check);
        let holds = note.is_none();
        Ok(Entry::Proof(ProofResult {
            title: format!(
                "for all {m}, {n} ≥ 0, from the factors of {}_{{{m},{n}}}",
                family.display
            ),
            facts,
            lemma: eigenfunction_lemma(m, n, &names),
            bases: names,
            leibniz_check,
            conclusion: statement.to_string(),
            claims: vec![ClaimResult::derived(id, statement, holds, note)
                .at(when.map(Condition::forms))
                .timed(start.elapsed().as_secs_f64())],
        }))
    }

    /// The facts `{A, H} = λ(1, 0) A` and `{B, H} = λ(0, 1) B` of family `k`, whose value is
    /// the product of `factors` `A^m`, `B^n`, each checked under `when`; and the bases `A`, `B`.
    fn base_facts(
        &self,
        k: usize,
        scope: &Scope<'_>,
        factors: &[Tree; 2],
        when: Option<&Condition>,
    ) -> Result<(Vec<Fact>, Vec<Expr>), FileError> {
        let family = &self.families[k];
        let source = &family.source;
        let at = |e: &EngineError| engine_error(source, family.span.clone(), e);
        let h = self.system.hamiltonian();
        let mut facts = Vec::new();
        let mut bases = Vec::new();
        for (j, factor) in factors.iter().enumerate() {
            let unit = if j == 0 { [1, 0] } else { [0, 1] };
            let base_tree = substitute(factor, &family.indices, unit, &self.families[..k]);
            let base = scope.lower(source, &family.value, &base_tree)?;
            let lambda = self.eigenvalue_at(k, unit[0], unit[1])?;
            let flow = self.system.bracket(&base, h).map_err(|e| at(&e))?;
            let flow = settled(when, flow).map_err(|e| at(&e))?;
            let scaled = lambda.checked_mul(&base).map_err(|e| at(&e.into()))?;
            let scaled = settled(when, scaled).map_err(|e| at(&e))?;
            let holds = flow
                .checked_sub(&scaled)
                .map_err(|e| at(&e.into()))?
                .is_zero();
            let base_tree = drop_ones(&base_tree);
            // A sum is parenthesized as the factor it is: `i (p_x + ix)`.
            let (name, factor) = (self.pretty(&base_tree), self.pretty_factor(&base_tree));
            // Where the bracket is another multiple of the base, the eigenvalue it has.
            let found_statement = match holds {
                true => None,
                false => multiple_of(&flow, &base, when).map(|mu| {
                    let mu = self.eigenvalue_in_functions(mu);
                    format!("{{{name}, H}} = {}", times(&mu, &factor))
                }),
            };
            let shown = self.eigenvalue_in_functions(lambda.clone());
            facts.push(Fact {
                statement: format!("{{{name}, H}} = {}", times(&shown, &factor)),
                holds,
                found: (!holds).then_some(flow),
                found_statement,
            });
            bases.push(base);
        }
        Ok((facts, bases))
    }

    /// An eigenvalue as a proof states it: in the file's functions where it depends on the
    /// phase space and is a polynomial in them, `−iΩ` for the rotor's `−i p_θ/I` (as the
    /// family's `eigenvalue` writes it); as it is otherwise.
    fn eigenvalue_in_functions(&self, lambda: Expr) -> Expr {
        // `written_in_functions` leaves one of the parameters alone (`iω`) as it is.
        self.written_in_functions(&lambda, None).unwrap_or(lambda)
    }

    /// Whether the bracket with `H` is a derivation on the two `bases` of family `k`, checked
    /// on them: `{AB, H} = A{B, H} + B{A, H}`.
    fn derivation_holds(&self, k: usize, bases: &[Expr]) -> Result<bool, FileError> {
        let family = &self.families[k];
        let at = |e: &EngineError| engine_error(&family.source, family.span.clone(), e);
        let h = self.system.hamiltonian();
        // {AB, H} = A{B, H} + B{A, H}
        let e = |r: Result<Expr, trigpoly::AlgebraError>| r.map_err(|e| at(&e.into()));
        let ab = e(bases[0].checked_mul(&bases[1]))?;
        let lhs = self.system.bracket(&ab, h).map_err(|e| at(&e))?;
        let fa = self.system.bracket(&bases[0], h).map_err(|e| at(&e))?;
        let fb = self.system.bracket(&bases[1], h).map_err(|e| at(&e))?;
        let rhs = e(e(bases[0].checked_mul(&fb))?.checked_add(&e(bases[1].checked_mul(&fa))?))?;
        Ok(lhs == rhs)
    }
}

/// The eigenfunction lemma in the indices `m`, `n`: from the bases' eigenvalues to every
/// `A^m B^n`'s, which is the proof's step from its facts to all `m, n`.
/// `a` and `b` name the two base functions (`A`, `B`, or another pair where the file has those
/// names).
fn eigenfunction_lemma(m: &str, n: &str, [a, b]: &[String; 2]) -> String {
    format!(
        "the bracket is a derivation in each argument, so {{{a}, H}} = λ_{a} {a} and \
         {{{b}, H}} = λ_{b} {b} give {{{a}^{m} {b}^{n}, H}} = ({m}λ_{a} + {n}λ_{b}) {a}^{m} {b}^{n} \
         for all {m}, {n} ≥ 0, and {m}λ_{a} + {n}λ_{b} = {m}λ(1, 0) + {n}λ(0, 1) = λ({m}, {n})"
    )
}

/// The names the proof of a family with `indices` gives its two base functions: the first
/// pair of [`PLACEHOLDERS`] that names nothing of the system, none of the file's `families`
/// (their names and displays) and neither index (`A`, `B` unless the file has a function `A`
/// or `B`: then `F`, `G`, unless it has a family `F`).
fn base_names<'a>(
    system: &brackets::System,
    families: impl Iterator<Item = &'a str>,
    indices: &'a [String; 2],
) -> [String; 2] {
    let taken: Vec<&str> = families.chain(indices.iter().map(String::as_str)).collect();
    first_free(system, &taken, &PLACEHOLDERS, |pair| {
        pair.iter().map(|p| p.to_string()).collect()
    })
    .map(str::to_string)
}

/// The tower job on a system file: for each family named in `family` (one name, or several
/// separated by commas, in that order), or else for every family with an eigenvalue,
/// `{K_{m,n}, H} = λ(m, n) K_{m,n}` expanded for `1 ≤ m, n ≤ max`, and the proof for all
/// `m, n` when the family is a product of powers, each family in its own section. A family
/// may be in any names, the file's or one added in code ([`LoadedSystem::add_family`]); the
/// towers and the proofs come back as [`Report::towers`] and [`Report::proofs`] (the first
/// of each as [`Report::tower`] and [`Report::proof`]).
/// [`family_tower_report_with_progress`] reports each bracket as it is done.
///
/// Errors if a name is no family's, if a family named has no eigenvalue, or, when none is
/// named, if no family has one.
///
/// ```
/// use superint::system_file::{family_tower_report, load, LimitsOverride};
///
/// let rotor = load("systems/gravity-rotor.toml", &LimitsOverride::default())?;
/// // K' and K̄', the families with an eigenvalue, each in its section.
/// let report = family_tower_report(&rotor, None, 3, None)?;
/// let towers: Vec<_> = report.towers().map(|t| (t.family.as_str(), t.checked)).collect();
/// assert_eq!(towers, [("K'_{m,n}", 9), ("K̄'_{m,n}", 9)]);
/// assert!(report.proofs().all(|p| p.holds()) && report.all_proved());
/// // One of them by name.
/// let report = family_tower_report(&rotor, Some("Kbarp"), 3, None)?;
/// assert_eq!(report.towers().count(), 1);
/// assert_eq!(report.tower().map(|t| t.failures.len()), Some(0));
/// # Ok::<(), superint::system_file::FileError>(())
/// ```
pub fn family_tower_report(
    file: &LoadedSystem,
    family: Option<&str>,
    max: i64,
    when: Option<&Condition>,
) -> Result<Report, FileError> {
    family_tower_report_with_progress(file, family, max, when, &mut |_, _| {})
}

/// [`family_tower_report`], calling `progress(done, total)` after each bracket of the towers,
/// counted over every family's together (the command line's progress bar; a program's own,
/// or a log).
///
/// ```
/// use superint::system_file::{family_tower_report_with_progress, load, LimitsOverride};
///
/// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let mut seen = Vec::new();
/// let report = family_tower_report_with_progress(&rotor, Some("K"), 2, None, &mut |done, total| {
///     seen.push((done, total))
/// })?;
/// assert!(report.all_proved());
/// assert_eq!(seen, [(1, 4), (2, 4), (3, 4), (4, 4)]);
/// // Two families, K and K̄: their eight brackets in one count.
/// seen.clear();
/// family_tower_report_with_progress(&rotor, Some("K,Kbar"), 2, None, &mut |done, total| {
///     seen.push((done, total))
/// })?;
/// assert_eq!(seen.first(), Some(&(1, 8)));
/// assert_eq!(seen.last(), Some(&(8, 8)));
/// # Ok::<(), superint::system_file::FileError>(())
/// ```
pub fn family_tower_report_with_progress(
    file: &LoadedSystem,
    family: Option<&str>,
    max: i64,
    when: Option<&Condition>,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Report, FileError> {
    refuse_atoms(file)?;
    let start = Instant::now();
    if let Some(c) = when {
        refuse_parameters_condition(file, c).map_err(|e| unplaced_refusal(file, &e))?;
    }
    // Every family is shown, and so found to have an eigenvalue, before any bracket is formed.
    let families = tower_families(file, family)?
        .into_iter()
        .map(|k| ShownFamily::of(file, k))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some(c) = when {
        let ks: Vec<usize> = families.iter().map(|f| f.index).collect();
        let sides = family_sides(file, &ks)?;
        let sides: Vec<&Expr> = sides.iter().collect();
        (c.defined_on(&sides, "the tower")).map_err(|e| unplaced_refusal(file, &e))?;
    }
    // The brackets are counted over every family's together.
    let per_family = pairs(max);
    let total = per_family.saturating_mul(families.len());
    let (mut sections, mut before) = (Vec::new(), 0);
    for (shown, number) in families.iter().zip(1..) {
        let entries = shown.entries(file, max, when, &mut |done, _| {
            progress(before + done, total)
        })?;
        sections.push(shown.section(file, number, entries));
        before += per_family;
    }
    Ok(Report {
        title: towers_title(&families, max, when),
        subtitle: file.source.origin.clone(),
        sections,
        summary: SummaryKind::Check { files: 1 },
        seconds: start.elapsed().as_secs_f64(),
        caller: file.caller,
    })
}

/// The title of the towers of `families`, `1 ≤ m, n ≤ max` (at `when`'s values):
/// `` The tower of `K_{m,n}`, `1 ≤ m, n ≤ 3` ``, or of several,
/// `` The towers of `K_{m,n}` and `K̄_{m,n}`, `1 ≤ m, n ≤ 3` `` (each range of indices once).
fn towers_title(families: &[ShownFamily], max: i64, when: Option<&Condition>) -> String {
    let kmns: Vec<String> = families.iter().map(|f| format!("`{}`", f.kmn)).collect();
    let mut ranges: Vec<String> = Vec::new();
    for [m, n] in families.iter().map(|f| &f.indices) {
        let range = format!("`1 ≤ {m}, {n} ≤ {max}`");
        if !ranges.contains(&range) {
            ranges.push(range);
        }
    }
    let noun = match families.len() {
        1 => "tower",
        _ => "towers",
    };
    let at_values = when.map_or_else(String::new, |c| format!(" at `{}`", c.text));
    format!(
        "The {noun} of {}, {}{at_values}",
        listed(&kmns),
        listed(&ranges)
    )
}

/// Refuses a system with denominator atoms or radicals, which a family's tower does not take.
fn refuse_atoms(file: &LoadedSystem) -> Result<(), FileError> {
    file.system
        .space()
        .refuse_denominators("a family's tower")
        .and_then(|()| file.system.space().refuse_radicals("a family's tower"))
        .map_err(|e| file.computation_error(&e))
}

/// A family as the tower's report writes it, in the file's names: `K_{m,n}`, its value and
/// its eigenvalue.
struct ShownFamily {
    /// The family's index among the file's families.
    index: usize,
    /// The family's name, which the claims' ids start with.
    name: String,
    /// The names of its indices, `m` and `n`.
    indices: [String; 2],
    /// `K_{m,n}`, in the family's display name.
    kmn: String,
    /// Its value.
    value: String,
    /// Its eigenvalue, as a factor (parenthesized when a sum).
    eigen: String,
}

impl ShownFamily {
    /// Family `k` of `file`, as the report writes it.
    fn of(file: &LoadedSystem, k: usize) -> Result<Self, FileError> {
        let f = &file.families[k];
        // Fails with a located message when the family has no eigenvalue.
        file.eigenvalue_at(k, 1, 1)?;
        let scope = Scope::of_family(file, k);
        let value = file.pretty(&scope.tree(&f.source, &f.value)?);
        let eigen_tree = scope.tree(&f.source, f.eigenvalue.as_ref().expect("checked"))?;
        let [m, n] = &f.indices;
        Ok(ShownFamily {
            index: k,
            name: f.name.clone(),
            indices: f.indices.clone(),
            kmn: format!("{}_{{{m},{n}}}", f.display),
            value,
            eigen: file.pretty_factor(&eigen_tree),
        })
    }

    /// The identity the tower checks: `{K_{m,n}, H} = λ K_{m,n}`.
    fn identity(&self) -> String {
        let (kmn, eigen) = (&self.kmn, &self.eigen);
        format!("{{{kmn}, H}} = {eigen} {kmn}")
    }

    /// The report's first line: the family, its value, and the identity.
    fn introduction(&self, file: &LoadedSystem) -> Entry {
        Entry::Text(format!(
            "The family `{} = {}` of {}, with `{}`.",
            self.kmn,
            self.value,
            file.the_name(),
            self.identity()
        ))
    }

    /// The section's entries: the introduction, the tower of `1 ≤ m, n ≤ max` (at `when`'s
    /// values), each bracket reported to `progress`, and the proof for all `m, n` or why
    /// there is none.
    fn entries(
        &self,
        file: &LoadedSystem,
        max: i64,
        when: Option<&Condition>,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<Vec<Entry>, FileError> {
        let tower_start = Instant::now();
        let failures = tower_failures(file, self.index, max, when, progress)?;
        let tower = self.tower(file, max, when, failures, tower_start);
        let [m, n] = &self.indices;
        let proof = file.family_proof(
            self.index,
            &format!("{}-all", self.name),
            &format!("{} for all {m}, {n} ≥ 0", self.identity()),
            when,
        )?;
        Ok(vec![self.introduction(file), Entry::Tower(tower), proof])
    }

    /// The family's section, numbered `number`, with its `entries`.
    fn section(&self, file: &LoadedSystem, number: u32, entries: Vec<Entry>) -> Section {
        Section {
            number,
            title: format!("`{{{}, H}}` for {}", self.kmn, file.the_name()),
            file: Some(file.source.origin.clone()),
            entries,
            names: Names::of_system(&file.system),
        }
    }

    /// The tower's result, its claim settled by the `failures` among `1 ≤ m, n ≤ max` and
    /// timed from `tower_start`.
    fn tower(
        &self,
        file: &LoadedSystem,
        max: i64,
        when: Option<&Condition>,
        failures: Vec<(i64, i64)>,
        tower_start: Instant,
    ) -> TowerResult {
        let [m, n] = &self.indices;
        let note = (!failures.is_empty()).then(|| format!("fails for ({m}, {n}) in {failures:?}"));
        TowerResult {
            system: file.name.clone(),
            the_system: file.the_name(),
            ladder: format!("{} = {}", self.kmn, self.value),
            family: self.kmn.clone(),
            max,
            // `1 ≤ m, n ≤ max` holds no pair when `max < 1`.
            checked: pairs(max),
            claim: ClaimResult::derived(
                &format!("{}-tower", self.name),
                &format!("{} for 1 ≤ {m}, {n} ≤ {max}", self.identity()),
                failures.is_empty(),
                note,
            )
            .at(when.map(Condition::forms))
            .timed(tower_start.elapsed().as_secs_f64()),
            failures,
        }
    }
}

/// Refuses a tower's condition that sets a variable of phase space, as an
/// [`EngineError::RefusedCondition`] at the variable it sets there (`M` of `M = p_x`): the
/// tower's brackets are identities on the whole phase space, so a condition may set
/// parameters only (substituting them commutes with the bracket, so the lemma holds at their
/// values as it does everywhere); and one that sets to 0 a parameter `H` divides by, as a
/// search's is ([`Condition::defined_on`]).
fn refuse_parameters_condition(file: &LoadedSystem, c: &Condition) -> Result<(), EngineError> {
    if let Some((set, v, kind)) = c.phase_variable() {
        let option = match file.caller {
            Caller::CommandLine => "--when: ",
            Caller::Program => "",
        };
        return Err(EngineError::RefusedCondition {
            var: set,
            message: format!(
                "{option}a tower's condition may set parameters only, to numbers or other \
                 parameters, and it holds {v}, {kind}: the tower's brackets are identities on \
                 the whole phase space"
            ),
        });
    }
    c.defined_on(&[file.system.hamiltonian()], "the Hamiltonian")
}

/// What the towers of the families `ks` (each with an eigenvalue) are formed from, which a
/// condition must not make divide by zero: each family's instance `K_{1,1}` and its
/// eigenvalues `λ(1, 0)` and `λ(0, 1)`.
fn family_sides(file: &LoadedSystem, ks: &[usize]) -> Result<Vec<Expr>, FileError> {
    let mut sides = Vec::new();
    for &k in ks {
        sides.push(file.compute_instance(k, 1, 1)?);
        sides.push(file.eigenvalue_at(k, 1, 0)?);
        sides.push(file.eigenvalue_at(k, 0, 1)?);
    }
    Ok(sides)
}

/// A refusal of a tower's condition given without its text (a program's
/// [`Condition`]), which has no place to show it at: named `<condition>`, and keeping the
/// engine's refusal ([`FileError::engine`]) for
/// [`LoadedSystem::condition_refusal`] to place in the condition's text.
fn unplaced_refusal(file: &LoadedSystem, e: &EngineError) -> FileError {
    let origin = file.given("<condition>", "").origin;
    FileError {
        engine: Some(Box::new(e.clone())),
        ..FileError::new(ErrorKind::Condition, &origin, e.to_string())
    }
}

impl LoadedSystem {
    /// A tower's condition given as text (`w0sq = 2*omega_c^2`), read as
    /// [`LoadedSystem::condition`] reads one, and refused, at the value at fault, where
    /// [`family_tower_report`] would refuse it at no place: where it sets a variable of phase
    /// space or sets a parameter to one, or sets to 0 a parameter that `H` divides by, or one
    /// that a family the tower checks divides by (`family`, as the report names them; a
    /// refusal of the system or of the names is the report's own, said after the
    /// condition's).
    pub fn tower_condition(
        &self,
        text: &str,
        family: Option<&str>,
    ) -> Result<Condition, FileError> {
        let source = self.given("<condition>", text);
        let pieces = Text::whole(&source).split(',');
        let condition = parse_condition_with(self, &source, &pieces, |c| {
            refuse_parameters_condition(self, c)
        })?;
        refuse_atoms(self)?;
        let ks = tower_families(self, family)?;
        for &k in &ks {
            ShownFamily::of(self, k)?;
        }
        let sides = family_sides(self, &ks)?;
        let sides: Vec<&Expr> = sides.iter().collect();
        match condition.defined_on(&sides, "the tower") {
            Ok(()) => Ok(condition),
            Err(e) => Err(self.condition_refusal(text, &e)),
        }
    }
}

/// The indices of the families whose towers are checked, in order: those named in `family`
/// (one name, or several separated by commas), or else every family with an eigenvalue.
fn tower_families(file: &LoadedSystem, family: Option<&str>) -> Result<Vec<usize>, FileError> {
    let Some(names) = family else {
        let found: Vec<usize> = (file.families.iter().enumerate())
            .filter(|(_, f)| f.eigenvalue.is_some())
            .map(|(k, _)| k)
            .collect();
        return match found.is_empty() {
            true => Err(no_family_with_an_eigenvalue(file)),
            false => Ok(found),
        };
    };
    let mut found = Vec::new();
    let pieces = comma_pieces(names);
    for (k, &(at, piece)) in pieces.iter().enumerate() {
        let (name, span) = trimmed(at, piece);
        // An empty name beside a comma is refused at the comma before it (after it for the
        // first), as every other list's is.
        if let Some(missing) = crate::discovery::blank_beside_comma(
            &pieces,
            k,
            "a family's name",
            "families are named separated by commas, such as K,Kbar",
        ) {
            return Err(family_list_refused(
                file,
                names,
                missing.span,
                missing.message,
                Some(format!(
                    "the list {} has an empty name: families are named separated by commas, \
                     such as K,Kbar",
                    trigpoly::quoted_name(names)
                )),
            ));
        }
        // A line break or a tab in a name (`$'K\nKbar'`), before the message quotes it.
        if let Some((at_char, why)) = super::unshowable_in_name(name) {
            let place = span.start + at_char.start..span.start + at_char.end;
            let usage = "families are named separated by commas, such as K,Kbar";
            return Err(family_list_refused(
                file,
                names,
                place,
                format!("{why}: {usage}"),
                None,
            ));
        }
        // A lone blank name is said to be blank, where it ends, as a blank function name is.
        if name.is_empty() {
            return Err(family_list_refused(
                file,
                names,
                span,
                "expected the name of a family, found end of input".to_string(),
                Some(format!(
                    "the family's name {} is blank: name a family, such as K",
                    trigpoly::quoted_name(names)
                )),
            ));
        }
        let Some(k) = file.family(name) else {
            let declared: Vec<&str> = file.families.iter().map(|f| f.name.as_str()).collect();
            let message = format!(
                "no family named {} (the {} {})",
                trigpoly::quoted_name(name),
                match file.source.given.about_file() {
                    false => "system has",
                    true => "file declares",
                },
                match declared.is_empty() {
                    true => "none".to_string(),
                    false => declared.join(", "),
                }
            );
            return Err(family_list_refused(file, names, span, message, None));
        };
        if found.contains(&k) {
            let message = format!(
                "the family {} is named twice: each tower is checked once",
                trigpoly::quoted_name(name)
            );
            return Err(family_list_refused(file, names, span, message, None));
        }
        found.push(k);
    }
    Ok(found)
}

/// The list of families `names` refused at the byte range `span` of it, for `message`: on the
/// command line as `--fix`'s list is, `<command line>:1:C: --family:` with `message`, the list
/// and a caret under the place; from a program, against the system's origin, `unplaced` where
/// the message needs the caret (`after this comma`, `before this comma`) and the program is
/// told otherwise, else `message`.
fn family_list_refused(
    file: &LoadedSystem,
    names: &str,
    span: std::ops::Range<usize>,
    message: String,
    unplaced: Option<String>,
) -> FileError {
    match file.caller {
        Caller::CommandLine => file.given("<families>", names).error(
            ErrorKind::Family,
            span,
            format!("--family: {message}"),
        ),
        Caller::Program => family_refused(file, unplaced.unwrap_or(message)),
    }
}

/// A tower's families refused, for `message`: the file's, or the program's system's.
fn family_refused(file: &LoadedSystem, message: impl Into<String>) -> FileError {
    FileError::new(ErrorKind::Family, &file.source.origin, message)
}

/// That `file` has no family with an eigenvalue, and so no tower, with how to declare one.
fn no_family_with_an_eigenvalue(file: &LoadedSystem) -> FileError {
    match file.source.given.about_file() {
        false => family_refused(
            file,
            "the system has no family with an eigenvalue, so there is no tower to check",
        )
        .with_hint(
            "add one with LoadedSystem::add_family, such as add_family(\"K\", \"K\", \
             [\"m\", \"n\"], \"Z^m*exp(-i*n*theta)\", \
             Some(\"i*(m*omega - n*p_theta/I)\"))",
        ),
        true => family_refused(
            file,
            "the file declares no [[family]] with an eigenvalue, so there is no tower to check",
        )
        .with_hint(
            "declare one, such as name = \"K\", value = \"Z^m*exp(-i*n*theta)\", \
             eigenvalue = \"i*(m*omega - n*p_theta/I)\" (see docs/system-files.md)",
        ),
    }
}

/// How many pairs `(a, b)` have `1 ≤ a, b ≤ max`: `max²`, and none when `max < 1`.
fn pairs(max: i64) -> usize {
    let side = usize::try_from(max.max(0)).unwrap_or(usize::MAX);
    side.saturating_mul(side)
}

/// The pairs `(a, b)`, `1 ≤ a, b ≤ max`, for which `{K_{a,b}, H} = λ_{a,b} K_{a,b}` fails
/// (after `when`), each pair reported to `progress` as it is checked.
fn tower_failures(
    file: &LoadedSystem,
    k: usize,
    max: i64,
    when: Option<&Condition>,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Vec<(i64, i64)>, FileError> {
    let f = &file.families[k];
    let at = |e: &brackets::EngineError| engine_error(&f.source, f.span.clone(), e);
    let total = pairs(max);
    let mut failures = Vec::new();
    let mut done = 0;
    for a in 1..=max {
        for b in 1..=max {
            let value = file.compute_instance(k, a, b)?;
            let lambda = file.eigenvalue_at(k, a, b)?;
            let lhs = file.system.flow(&value).map_err(|e| at(&e))?;
            let lhs = settled(when, lhs).map_err(|e| at(&e))?;
            let rhs = lambda.checked_mul(&value).map_err(|e| at(&e.into()))?;
            let rhs = settled(when, rhs).map_err(|e| at(&e))?;
            if lhs != rhs {
                failures.push((a, b));
            }
            done += 1;
            progress(done, total);
        }
    }
    Ok(failures)
}

/// The single term `μ` with `flow = μ·base` (under `when`), if there is one: the eigenvalue
/// a base function has where it is not the one stated (`−i p_θ/I`, say, shown `−i Ω`). `μ` is the ratio of
/// the leading terms (a monomial order keeps the leading term of a product by a monomial),
/// then checked exactly.
fn multiple_of(flow: &Expr, base: &Expr, when: Option<&Condition>) -> Option<Expr> {
    let vars = flow.vars();
    let lead = |e: &Expr| {
        let term = e.terms().next()?;
        let powers: Vec<_> = vars.vars().map(|v| (v, term.exponent(v))).collect();
        Expr::monomial(vars, term.coeff(), &powers).ok()
    };
    let mu = lead(flow)?.checked_div(&lead(base)?).ok()?;
    let scaled = settled(when, mu.checked_mul(base).ok()?).ok()?;
    (scaled == *flow).then_some(mu)
}

/// `e` under the condition, if any ([`Condition::apply_where_defined`]).
fn settled(when: Option<&Condition>, e: Expr) -> Result<Expr, EngineError> {
    match when {
        None => Ok(e),
        Some(c) => c.apply_where_defined(&e, "the tower"),
    }
}

/// `λ A` as a proof states it, as the paper writes it: the eigenvalue bare where it is one
/// term over no denominator (`iω Z`, `−2iω conj(b)`, `−W` for `−1`), else in parentheses
/// (`(−i p_θ/I) e^{−iθ}`, `(a − b) W`).
fn times(lambda: &Expr, factor: &str) -> String {
    let text = lambda.to_string();
    match text.as_str() {
        "1" => factor.to_string(),
        "−1" => format!("−{factor}"),
        _ if lambda.len() == 1 && !text.contains('/') => format!("{text} {factor}"),
        _ => format!("({text}) {factor}"),
    }
}
