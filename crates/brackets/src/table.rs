//! Bracket tables: every `{A, B}` of a list of named functions, written as a linear combination
//! of the listed functions with coefficients in the parameters where one exists (found by exact
//! linear algebra, then checked), otherwise as an expression.

use std::collections::{BTreeSet, HashMap, HashSet};

use trigpoly::{AlgebraError, Expr, GaussianRational, Style, VarKind, Vars};

use crate::clearing::Clearing;
use crate::error::EngineError;
use crate::modular::{Echelon, SparseVec};
use crate::system::System;

/// One entry of a table. Its `Display` is [`Entry::render`] in [`Style::Unicode`].
///
/// ```
/// use brackets::{systems, BracketTable, Entry};
///
/// let rotor = systems::harmonic_rotor();
/// let table = BracketTable::compute(&rotor, &["L", "G1", "G2"])?;
/// // {G1, G2} = −ω² L, {G2, L} = −4 G1, and a bracket with itself is 0.
/// assert_eq!(table.entries[1][2].to_string(), "−ω² L");
/// assert_eq!(table.entries[2][0].to_string(), "−4 G1");
/// assert_eq!(table.entries[0][0].to_string(), "0");
/// assert!(matches!(&table.entries[1][2], Entry::Combination(terms) if terms.len() == 1));
/// # Ok::<(), brackets::EngineError>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Entry {
    /// `Σ c_k F_k` with coefficients in the parameters (empty for zero), checked exactly.
    Combination(Vec<(Expr, FunctionName)>),
    /// No such combination: the bracket itself, in normal form.
    Expression(Expr),
    /// Outside what the table writes (a closure's bracket that is no polynomial of the degree
    /// in the generators): shown as `*`, the bracket given apart.
    Outside,
    /// Not computed: the bracket, or its combination's solve, reached a limit, whose message
    /// it keeps. Shown as `?`.
    Undecided(String),
}

impl std::fmt::Display for Entry {
    /// The entry in Unicode (`−ω² L`, `4 G1`, `0`, `*` outside, `?` undecided):
    /// [`Entry::render`] in [`Style::Unicode`].
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.render(Style::Unicode))
    }
}

/// A function of a table by name: the system's name, which reads back (`G1p`), and the name
/// it is shown by (`G1'`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FunctionName {
    /// The name the system defines it by.
    pub name: String,
    /// The name it is shown by.
    pub display: String,
}

impl FunctionName {
    /// The name in a notation: the display name in unicode and LaTeX, the system's name in
    /// ASCII, which `superint` reads back.
    pub fn render(&self, style: Style) -> String {
        match style {
            Style::Ascii => self.name.clone(),
            Style::Latex => latex_name(&self.display),
            Style::Unicode => self.display.clone(),
        }
    }
}

impl std::fmt::Display for FunctionName {
    /// The name it is shown by, in Unicode (`G1'`): [`FunctionName::render`] in
    /// [`Style::Unicode`].
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.render(Style::Unicode))
    }
}

/// The table `{A, B}` for a list of named functions of a system.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BracketTable {
    /// The functions' names, as given.
    pub names: Vec<String>,
    /// The functions' display names.
    pub display: Vec<String>,
    /// `entries[a][b]` is `{names[a], names[b]}`.
    pub entries: Vec<Vec<Entry>>,
}

impl BracketTable {
    /// Computes the table for named functions of `system` (`&["L", "G1"]`, or names a program
    /// holds as `String`s). An entry whose bracket or combination reaches a limit is
    /// [`Entry::Undecided`], and the others are computed; any other error is the answer.
    pub fn compute(system: &System, names: &[impl AsRef<str>]) -> Result<Self, EngineError> {
        let names: Vec<&str> = names.iter().map(AsRef::as_ref).collect();
        // Each over its common denominator, as the brackets will be, so that a bracket that
        // is one of them written another way (`x/(x − y)² − y/(x − y)²` for `1/(x − y)`)
        // shows as that one.
        let funcs: Vec<Expr> = names
            .iter()
            .map(|n| Ok(system.get(n)?.over_common_denominators()?))
            .collect::<Result<_, EngineError>>()?;
        let basis: Vec<(FunctionName, Expr)> = names
            .iter()
            .map(|&n| FunctionName {
                name: n.to_string(),
                // As the claims' echo and expressions print it: `ω3` of `omega3`.
                display: trigpoly::shown_text(system.display_name(n)),
            })
            .zip(funcs.iter().cloned())
            .collect();
        // The bracket is antisymmetric: the entries above the diagonal are computed, those on
        // it are zero and those below are the negated entries above.
        let n = funcs.len();
        let mut entries: Vec<Vec<Entry>> = (0..n).map(|_| Vec::with_capacity(n)).collect();
        // An entry that reaches a limit is undecided, and the others are computed.
        let entry = |a: usize, b: usize| -> Result<Entry, EngineError> {
            // Over a common denominator (with denominator atoms; as it is otherwise), so that
            // a bracket equal to zero is 0 and reads as its numerator shows.
            let br = system
                .bracket(&funcs[a], &funcs[b])?
                .over_common_denominators()?;
            Ok(match express(&br, &basis)? {
                Some(c) => Entry::Combination(c),
                None => Entry::Expression(br),
            })
        };
        for a in 0..n {
            entries[a].push(Entry::Combination(Vec::new()));
            for b in a + 1..n {
                let entry = match entry(a, b) {
                    Err(e) if e.is_limit() => Entry::Undecided(e.to_string()),
                    found => found?,
                };
                entries[b].push(entry.negated());
                entries[a].push(entry);
            }
        }
        Ok(BracketTable {
            names: names.iter().map(|s| s.to_string()).collect(),
            display: basis.into_iter().map(|b| b.0.display).collect(),
            entries,
        })
    }
}

/// The table as a grid in Unicode, row `A` and column `B` holding `{A, B}`, each column as
/// wide as its longest entry (a mark over a letter, `Z̄`, takes no column of its own); a long
/// entry makes a long line. superint's reports print a table so too, and as a list where it
/// is wider than a line.
///
/// ```
/// use brackets::{systems, BracketTable};
///
/// let rotor = systems::harmonic_rotor();
/// let table = BracketTable::compute(&rotor, &["L", "G1", "G2"])?;
/// assert_eq!(
///     table.to_string(),
///     "\
/// {·,·} │ L       G1     G2
/// ──────┼─────────────────────
/// L     │ 0       −G2    4 G1
/// G1    │ G2      0      −ω² L
/// G2    │ −4 G1   ω² L   0
/// "
/// );
/// # Ok::<(), brackets::EngineError>(())
/// ```
impl std::fmt::Display for BracketTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Terminal columns: characters but the combining marks drawn over the one before.
        let width = |s: &str| {
            s.chars()
                .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
                .count()
        };
        let pad = |s: &str, w: usize| format!("{s}{}", " ".repeat(w.saturating_sub(width(s))));
        let corner = "{·,·}";
        let cells: Vec<Vec<String>> = self
            .entries
            .iter()
            .map(|row| row.iter().map(Entry::to_string).collect())
            .collect();
        let first = self
            .display
            .iter()
            .map(|d| width(d))
            .chain([width(corner)])
            .max()
            .unwrap_or(0);
        let widths: Vec<usize> = (0..self.display.len())
            .map(|j| {
                cells
                    .iter()
                    .filter_map(|row| row.get(j).map(|c| width(c)))
                    .chain([width(&self.display[j])])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let row = |head: &str, items: &[String]| {
            let body: Vec<String> = items.iter().zip(&widths).map(|(c, &w)| pad(c, w)).collect();
            format!("{} │ {}", pad(head, first), body.join("   "))
                .trim_end()
                .to_string()
        };
        writeln!(f, "{}", row(corner, &self.display))?;
        let rule = widths.iter().sum::<usize>() + 3 * widths.len().saturating_sub(1) + 1;
        writeln!(f, "{}┼{}", "─".repeat(first + 1), "─".repeat(rule))?;
        for (name, items) in self.display.iter().zip(&cells) {
            writeln!(f, "{}", row(name, items))?;
        }
        Ok(())
    }
}

impl Entry {
    /// `−entry`: the entry of the transposed bracket.
    fn negated(&self) -> Entry {
        match self {
            Entry::Combination(terms) => {
                Entry::Combination(terms.iter().map(|(c, name)| (-c, name.clone())).collect())
            }
            Entry::Expression(e) => Entry::Expression(-e),
            Entry::Outside => Entry::Outside,
            Entry::Undecided(message) => Entry::Undecided(message.clone()),
        }
    }

    /// The entry as text in a notation: `−ω² L`, `4 G1`, `0`.
    pub fn render(&self, style: Style) -> String {
        match self {
            Entry::Expression(e) => e.render(style),
            Entry::Outside => "*".into(),
            Entry::Undecided(_) => "?".into(),
            Entry::Combination(terms) if terms.is_empty() => "0".into(),
            Entry::Combination(terms) => {
                let mut out = String::new();
                for (k, (c, name)) in terms.iter().enumerate() {
                    let several_words =
                        style != Style::Ascii && trigpoly::has_several_words(&name.display);
                    let name = name.render(style);
                    let text = c.render(style);
                    let (neg, body) = match text.strip_prefix(['−', '-']) {
                        Some(rest) if c.len() == 1 => (true, rest.to_string()),
                        _ => (false, text),
                    };
                    let mul = if style == Style::Ascii { "*" } else { " " };
                    // A term's denominator goes last, `D/M` and `3ω² D/2`: `1/M D` is read back
                    // as ambiguous, and writes a division before a factor. In LaTeX the name
                    // joins the numerator, `\frac{3 D}{M}`, as the expression printer writes
                    // the same bracket in the functions (it was `\frac{3}{M} D`).
                    let fraction = match style {
                        Style::Latex => None,
                        _ => body.rsplit_once('/').filter(|_| c.len() == 1),
                    };
                    // A name of several words over a denominator is set in parentheses, as the
                    // expression printer sets it: `Re K/M` would read as the real part of `K/M`.
                    let name = match several_words && fraction.is_some() {
                        true => format!("({name})"),
                        false => name,
                    };
                    let latex_fraction = match style {
                        Style::Latex if c.len() == 1 => split_frac(&body),
                        _ => None,
                    };
                    let term = match (body.as_str(), fraction) {
                        ("1", _) => name,
                        _ if c.len() > 1 => format!("({body}){mul}{name}"),
                        _ if let Some((num, den)) = latex_fraction => match num {
                            "1" => format!(r"\frac{{{name}}}{{{den}}}"),
                            _ => format!(r"\frac{{{num} {name}}}{{{den}}}"),
                        },
                        (_, Some(("1", den))) => format!("{name}/{den}"),
                        (_, Some((num, den))) => format!("{num}{mul}{name}/{den}"),
                        _ => format!("{body}{mul}{name}"),
                    };
                    let minus = if style == Style::Unicode { "−" } else { "-" };
                    match (k, neg) {
                        (0, false) => out.push_str(&term),
                        (0, true) => out.push_str(&format!("{minus}{term}")),
                        (_, false) => out.push_str(&format!(" + {term}")),
                        (_, true) => out.push_str(&format!(" {minus} {term}")),
                    }
                }
                out
            }
        }
    }
}

/// The numerator and the denominator of LaTeX that is one fraction whole, `\frac{3}{2 M}`.
fn split_frac(latex: &str) -> Option<(&str, &str)> {
    let rest = latex.strip_prefix(r"\frac{")?;
    // The brace that closes the numerator, the rest being `{denominator}`.
    let mut depth = 1usize;
    let mut escaped = false;
    for (k, c) in rest.char_indices() {
        match c {
            _ if escaped => escaped = false,
            '\\' => escaped = true,
            '{' => depth += 1,
            '}' if depth > 1 => depth -= 1,
            '}' => {
                let denominator = rest[k + 1..].strip_prefix('{')?.strip_suffix('}')?;
                // The denominator is one group: its braces balance inside.
                let mut d = 0i32;
                for c in denominator.chars() {
                    d += match c {
                        '{' => 1,
                        '}' => -1,
                        _ => 0,
                    };
                    if d < 0 {
                        return None;
                    }
                }
                return (d == 0).then_some((&rest[..k], denominator));
            }
            _ => {}
        }
    }
    None
}

/// `G1'` → `G_{1}'`, `Z̄` → `\bar{Z}`, `L` → `L`, `P'_{1,1}` → `P'_{1,1}`: the name as
/// [`trigpoly::shown_forms`] writes it in LaTeX (`Re ω` → `\operatorname{Re} \omega`, as a
/// variable shown by it prints; any other word by word), before any subscript of its own (a family
/// instance's indices), which joins a subscript the name ends with after `;` (`K₁_{1,2}` →
/// `K_{1;1,2}`: LaTeX refuses a double subscript).
pub fn latex_name(name: &str) -> String {
    let (head, subscript) = name.split_at(name.find("_{").unwrap_or(name.len()));
    let head = match trigpoly::shown_forms(head) {
        Some((_, latex)) => latex,
        None => words_in_latex(head),
    };
    match subscript
        .strip_prefix("_{")
        .and_then(|s| s.strip_suffix('}'))
    {
        Some(indices) => trigpoly::with_indices(&head, indices),
        None => format!("{head}{subscript}"),
    }
}

/// A name that is no display name as a whole (`Re ω`), each word as
/// [`trigpoly::display_forms`] writes it, a differential sign before a letter as LaTeX's
/// command (`∂H` → `\partial H`, `∇φ` → `\nabla\varphi`, as a statement writes them), the rest
/// as it is (`x(t)`).
fn words_in_latex(name: &str) -> String {
    let in_word = |c: char| c.is_alphanumeric() || matches!(c, '_' | '\'' | '\u{304}');
    let mut out = String::new();
    let mut rest = name;
    while let Some(c) = rest.chars().next() {
        let end = rest
            .find(|d| in_word(d) != in_word(c))
            .unwrap_or(rest.len());
        let (part, after) = rest.split_at(end);
        match trigpoly::display_forms(part).filter(|_| in_word(c)) {
            Some((_, latex)) => {
                // A control word is ended by a space before a letter.
                let command = trigpoly::DIFFERENTIALS
                    .iter()
                    .any(|(_, command)| out.ends_with(command));
                if command && latex.starts_with(|l: char| l.is_ascii_alphabetic()) {
                    out.push(' ');
                }
                out.push_str(&latex);
            }
            None => {
                for c in part.chars() {
                    match trigpoly::differential_latex(c) {
                        Some(command) => out.push_str(command),
                        None => out.push(c),
                    }
                }
            }
        }
        rest = after;
    }
    out
}

/// Writes `target` as `Σ c_k F_k` with `c_k` Laurent polynomials in the parameters, if possible.
///
/// The ansatz for `c_k` spans the parameter monomials `ν` that can carry a term of `F_k` onto a
/// term of `target`; the coefficients come from an exact linear solve over Q(i), and the
/// combination is then checked by expanding it. With denominator atoms, whose monomials are
/// not independent (`v·D = 1`), the solve runs on the images of the target and the functions
/// under one injective linear map onto polynomials (`Clearing`: multiplied by a common power
/// of each `D`, `D` substituted), which commutes with the parameter monomials `ν`; the check
/// is the exact zero test ([`Expr::vanishes`]).
pub fn express(
    target: &Expr,
    basis: &[(FunctionName, Expr)],
) -> Result<Option<Vec<(Expr, FunctionName)>>, EngineError> {
    if target.vanishes()? {
        return Ok(Some(Vec::new()));
    }
    let vars = target.vars().clone();
    let atoms = Expr::denominator_atoms(&vars)?;
    let vectors = std::iter::once(target).chain(basis.iter().map(|(_, f)| f));
    let (cleared_target, cleared_basis) =
        match Clearing::new(&atoms, &Expr::radicals(&vars)?, &[], vectors)? {
            None => (
                target.clone(),
                basis.iter().map(|(_, f)| f.clone()).collect(),
            ),
            Some(clearing) => (
                clearing.apply(target)?,
                basis
                    .iter()
                    .map(|(_, f)| clearing.apply(f))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
        };
    let every = vec![true; basis.len()];
    let solve = |allowed: &[bool], reach| {
        solve_combination(&cleared_target, &cleared_basis, allowed, reach)
    };
    // A combination whose columns cancel outside the bracket is taken when it reads better
    // than the bracket: fewer functions than the bracket has terms (`{F1, L} = Mgx`, not
    // `−2 G1 + 2 G1'`), each with a polynomial coefficient (when functions differ by a
    // coordinate times a parameter, `G1' = G1 + Mgx/2`, most brackets are combinations with
    // that parameter in a denominator). It takes two functions at least, which the bracket
    // must outnumber in terms.
    let reads_better = |c: &Combination, reach| {
        reach == Reach::Target || (c.support() < target.len() && c.is_polynomial())
    };
    let (mut found, reach) = match solve(&every, Reach::Target)? {
        Ok(found) => (found, Reach::Target),
        Err(Miss::Ansatz) if target.len() > 2 => match solve(&every, Reach::Outside)? {
            Ok(found) if reads_better(&found, Reach::Outside) => (found, Reach::Outside),
            _ => return Ok(None),
        },
        Err(_) => return Ok(None),
    };
    // Of dependent functions (`K`, `Re K`, `Im K`), a combination of fewer: each function of
    // the combination left out in turn while one without it, of no more functions, exists,
    // so that `{H_x, Re K}` reads `6ω Im K`, not `−6iω K + 6iω Re K`.
    if !found.unique {
        let mut allowed = every;
        for k in 0..basis.len() {
            if found.coeffs[k].is_zero() || found.support() == 1 {
                continue;
            }
            allowed[k] = false;
            match solve(&allowed, reach)? {
                Ok(other) if other.support() <= found.support() && reads_better(&other, reach) => {
                    found = other
                }
                _ => allowed[k] = true,
            }
        }
    }
    let coeffs = found.coeffs;
    // Check the combination exactly.
    let mut sum = Expr::zero(&vars);
    for (c, (_, f)) in coeffs.iter().zip(basis) {
        sum = sum.checked_add(&c.checked_mul(f)?)?;
    }
    // Equal as elements: with denominator atoms, two forms of one element may differ in
    // their terms (`v·D` and `1`), and the exact zero test decides.
    if sum != *target && !sum.checked_sub(target)?.vanishes()? {
        return Ok(None);
    }
    Ok(Some(
        coeffs
            .into_iter()
            .zip(basis)
            .filter(|(c, _)| !c.is_zero())
            .map(|(c, (name, _))| (c, name.clone()))
            .collect(),
    ))
}

/// A solution of `Σ c_k f_k = target`.
struct Combination {
    /// `c_k`, each a polynomial in the parameters.
    coeffs: Vec<Expr>,
    /// Whether it is the only one in the ansatz (its columns independent).
    unique: bool,
}

impl Combination {
    /// How many functions it takes.
    fn support(&self) -> usize {
        self.coeffs.iter().filter(|c| !c.is_zero()).count()
    }

    /// Whether every coefficient is a polynomial in the parameters: no negative exponent.
    fn is_polynomial(&self) -> bool {
        (self.coeffs.iter().flat_map(|c| c.terms())).all(|t| t.exponents().iter().all(|&e| e >= 0))
    }
}

/// Why a solve found no combination.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Miss {
    /// A phase-space monomial of the target is in no function that can take part: no column
    /// of any reach meets it.
    Unmet,
    /// The columns of the reach asked for span no combination.
    Ansatz,
}

/// Which columns `ν·F_k` a solve takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Reach {
    /// Those with a term on a term of the target: enough unless the columns' terms must cancel
    /// outside the target.
    Target,
    /// Those too that cancel another column's terms outside the target ([`cancel_outside`]).
    Outside,
}

/// Coefficients `c_k`, each a polynomial in the parameters and zero where `allowed` is false,
/// with `Σ c_k f_k = target` as polynomials whose monomials are independent (no denominator
/// atoms), found by an exact linear solve; else why there is none.
fn solve_combination(
    target: &Expr,
    basis: &[Expr],
    allowed: &[bool],
    reach: Reach,
) -> Result<Result<Combination, Miss>, EngineError> {
    let vars = target.vars().clone();
    let is_param: Vec<bool> = vars
        .vars()
        .map(|v| vars.variable(v).kind() == VarKind::Parameter)
        .collect();
    let split = |e: &[i64]| split_exponents(e, &is_param);
    let target_params = parameter_parts(target, split);
    let useful = useful_functions(basis, allowed, &target_params, split);
    // A phase-space monomial of the target that none of them has is in no combination: a
    // bracket of 10⁵ terms that is none is known so before any column is formed.
    if !meets_every_monomial(basis, &useful, &target_params, split) {
        return Ok(Err(Miss::Unmet));
    }
    let limit = vars.limits().max_terms;
    let Some(nus) = column_shifts(basis, useful, &target_params, split, reach, limit)? else {
        return Ok(Err(Miss::Ansatz));
    };
    let columns = columns(&vars, basis, nus)?;
    let Some((x, unique)) = solve_columns(target, &columns) else {
        return Ok(Err(Miss::Ansatz));
    };
    let mut coeffs: Vec<Expr> = vec![Expr::zero(&vars); basis.len()];
    for (j, xj) in x {
        let Column {
            function: k, nu, ..
        } = &columns[j];
        let powers: Vec<_> = vars.vars().zip(nu.iter().copied()).collect();
        coeffs[*k] = coeffs[*k].checked_add(&Expr::monomial(&vars, xj, &powers)?)?;
    }
    Ok(Ok(Combination { coeffs, unique }))
}

/// Exponents split into their phase-space part and their parameter part, each zero where
/// `is_param` says the other is.
fn split_exponents(e: &[i64], is_param: &[bool]) -> (Vec<i64>, Vec<i64>) {
    let phase = e
        .iter()
        .zip(is_param)
        .map(|(&x, &p)| if p { 0 } else { x })
        .collect();
    let param = e
        .iter()
        .zip(is_param)
        .map(|(&x, &p)| if p { x } else { 0 })
        .collect();
    (phase, param)
}

/// The target's parameter parts by phase-space part: a term of `F_k` meets the target's
/// terms of its own phase-space monomial by one lookup, where a scan of all of them for each
/// of its terms took minutes for functions of 10⁵ terms.
fn parameter_parts(
    target: &Expr,
    split: impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>),
) -> HashMap<Vec<i64>, Vec<Vec<i64>>> {
    let mut target_params: HashMap<Vec<i64>, Vec<Vec<i64>>> = HashMap::new();
    for t in target.terms() {
        let (phase, param) = split(&t.exponents());
        target_params.entry(phase).or_default().push(param);
    }
    target_params
}

/// Whether every phase-space monomial of the target is in one of the `useful` functions.
fn meets_every_monomial(
    basis: &[Expr],
    useful: &[usize],
    target: &HashMap<Vec<i64>, Vec<Vec<i64>>>,
    split: impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>),
) -> bool {
    let met: HashSet<&Vec<i64>> = useful
        .iter()
        .flat_map(|&k| basis[k].terms())
        .filter_map(|u| target.get_key_value(&split(&u.exponents()).0))
        .map(|(phase, _)| phase)
        .collect();
    met.len() >= target.len()
}

/// The shifts `ν` of the columns `ν·F_k`: each function's place `k` in the basis, with the
/// parameter monomials `ν` (as exponents) it is multiplied by.
type Shifts = Vec<(usize, BTreeSet<Vec<i64>>)>;

/// The shifts `ν` of the candidate columns `ν·F_k` of the `useful` functions, by function:
/// those that carry a term of `F_k` onto one of the target, and with [`Reach::Outside`] those
/// too that cancel other columns' terms outside it ([`cancel_outside`]). `None` when the
/// reach is `Outside` and adds no column; an error when the columns would hold more than
/// `limit` terms.
fn column_shifts(
    basis: &[Expr],
    useful: Vec<usize>,
    target: &HashMap<Vec<i64>, Vec<Vec<i64>>>,
    split: impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>) + Copy,
    reach: Reach,
    limit: usize,
) -> Result<Option<Shifts>, EngineError> {
    let mut nus: Shifts = useful
        .into_iter()
        .map(|k| (k, shifts_onto(&basis[k], target, split)))
        .collect();
    // The columns are held at once, and reduced: together they are held to the term limit,
    // as one result is (a bracket of 10⁶ terms and a function of 7·10⁵ that it spans took
    // 24 columns of 1.7·10⁷ terms, and 9 s, to be found no combination).
    let held: usize = nus
        .iter()
        .map(|(k, n)| n.len().saturating_mul(basis[*k].len()))
        .sum();
    if held > limit {
        return Err(AlgebraError::TooManyTerms { limit }.into());
    }
    if reach == Reach::Outside && !cancel_outside(basis, &mut nus, target, split, limit - held) {
        // No column beyond the target's: the solve would be the one already made.
        return Ok(None);
    }
    Ok(Some(nus))
}

/// A column `ν·F_k` of the solve.
struct Column {
    /// `k`, the function's place in the basis.
    function: usize,
    /// `ν`, the parameter monomial's exponents.
    nu: Vec<i64>,
    /// `ν·F_k`.
    product: Expr,
}

/// The columns `ν·F_k`, function by function, each for its shifts `ν` in order.
fn columns(vars: &Vars, basis: &[Expr], nus: Shifts) -> Result<Vec<Column>, EngineError> {
    let mut columns: Vec<Column> = Vec::new();
    for (k, nus) in nus {
        let f = &basis[k];
        for nu in nus {
            let powers: Vec<_> = vars.vars().zip(nu.iter().copied()).collect();
            let m = Expr::monomial(vars, GaussianRational::from(1), &powers)?;
            columns.push(Column {
                function: k,
                nu,
                product: f.checked_mul(&m)?,
            });
        }
    }
    Ok(columns)
}

/// The coefficient of each column in a combination equal to the target, by column, and
/// whether it is the only one (the columns independent); `None` when there is none.
///
/// Rows: the monomials of the columns, numbered as they come. A monomial of the target that
/// no column has leaves no combination; otherwise the columns go into a sparse echelon form,
/// in order (a column that depends on earlier ones has coefficient 0), and the target is
/// reduced by it. A dense matrix of every monomial by every column took minutes and gigabytes
/// for brackets of 10⁵ terms.
fn solve_columns(target: &Expr, columns: &[Column]) -> Option<(SparseVec<GaussianRational>, bool)> {
    let mut rows: HashMap<Vec<i64>, usize> = HashMap::new();
    let vectors: Vec<SparseVec<GaussianRational>> = columns
        .iter()
        .map(|column| {
            column
                .product
                .terms()
                .map(|t| {
                    let n = rows.len();
                    (*rows.entry(t.exponents()).or_insert(n), t.coeff())
                })
                .collect()
        })
        .collect();
    let target = target
        .terms()
        .map(|t| rows.get(&t.exponents()).map(|&r| (r, t.coeff())))
        .collect::<Option<SparseVec<_>>>()?;
    let mut echelon = Echelon::new(rows.len());
    let mut unique = true;
    for (j, v) in vectors.iter().enumerate() {
        unique &= echelon.insert(j, v).is_none();
    }
    Some((echelon.express(&target)?, unique))
}

/// The parameter monomials `ν` (as exponents) that carry a term of `f` onto a term of the
/// target, whose parameter parts are given by phase-space part.
fn shifts_onto(
    f: &Expr,
    target: &HashMap<Vec<i64>, Vec<Vec<i64>>>,
    split: impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>),
) -> BTreeSet<Vec<i64>> {
    let mut nus = BTreeSet::new();
    for u in f.terms() {
        let (uphase, uparam) = split(&u.exponents());
        for tparam in target.get(&uphase).into_iter().flatten() {
            nus.insert(tparam.iter().zip(&uparam).map(|(a, b)| a - b).collect());
        }
    }
    nus
}

/// Adds the shifts that let the columns' terms outside the target cancel, and says whether it
/// added any: a term of `ν·F_k` at a phase-space monomial the target lacks is met by each
/// other function with a term there, under the shift that carries that term onto it
/// (`M y = M F2 − M F1` for `F1 = x`, `F2 = x + y`: `F1` meets no term of `M y`, but `M F2`'s
/// `M x`). The shifts found are followed in turn, as many rounds as there are functions, while
/// the new columns stay within `budget` terms.
fn cancel_outside(
    basis: &[Expr],
    nus: &mut [(usize, BTreeSet<Vec<i64>>)],
    target: &HashMap<Vec<i64>, Vec<Vec<i64>>>,
    split: impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>),
    mut budget: usize,
) -> bool {
    // Each function's terms outside the target, and by phase-space monomial who has them.
    let outside: Vec<Vec<(Vec<i64>, Vec<i64>)>> = nus
        .iter()
        .map(|(k, _)| terms_outside(&basis[*k], target, &split).collect())
        .collect();
    let mut holders: HashMap<&Vec<i64>, Vec<(usize, &Vec<i64>)>> = HashMap::new();
    for (at, terms) in outside.iter().enumerate() {
        for (phase, param) in terms {
            holders.entry(phase).or_default().push((at, param));
        }
    }
    let mut new: Vec<(usize, Vec<i64>)> = nus
        .iter()
        .enumerate()
        .flat_map(|(at, (_, n))| n.iter().map(move |nu| (at, nu.clone())))
        .collect();
    let mut added = false;
    for _ in 0..nus.len() {
        let mut next = Vec::new();
        for (at, nu) in &new {
            for (phase, param) in &outside[*at] {
                let carried: Vec<i64> = nu.iter().zip(param).map(|(a, b)| a + b).collect();
                for &(other, q) in holders.get(phase).into_iter().flatten() {
                    let shift: Vec<i64> = carried.iter().zip(q).map(|(a, b)| a - b).collect();
                    if other == *at || nus[other].1.contains(&shift) {
                        continue;
                    }
                    let size = basis[nus[other].0].len();
                    if size > budget {
                        return added;
                    }
                    budget -= size;
                    nus[other].1.insert(shift.clone());
                    next.push((other, shift));
                    added = true;
                }
            }
        }
        if next.is_empty() {
            break;
        }
        new = next;
    }
    added
}

/// The terms of `f` whose phase-space monomial the target lacks, each split into its
/// phase-space and parameter exponents.
fn terms_outside<'a>(
    f: &'a Expr,
    target: &'a HashMap<Vec<i64>, Vec<Vec<i64>>>,
    split: &'a impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>),
) -> impl Iterator<Item = (Vec<i64>, Vec<i64>)> + 'a {
    f.terms()
        .map(|u| split(&u.exponents()))
        .filter(|(phase, _)| !target.contains_key(phase))
}

/// The functions `F_k` of those `allowed` that may carry a nonzero coefficient in
/// `Σ c_k F_k = target`: one with a phase-space monomial that neither the target nor any other
/// such function has cannot (its coefficient, a nonzero Laurent polynomial in the parameters,
/// would leave that monomial's term), and leaving it out may do the same to another. A table
/// of small functions and one of 10⁵ terms formed and reduced that one's columns for each
/// bracket it is no part of.
fn useful_functions(
    basis: &[Expr],
    allowed: &[bool],
    target: &HashMap<Vec<i64>, Vec<Vec<i64>>>,
    split: impl Fn(&[i64]) -> (Vec<i64>, Vec<i64>),
) -> Vec<usize> {
    // Each allowed function's phase-space monomials outside the target, once each.
    let outside: Vec<HashSet<Vec<i64>>> = basis
        .iter()
        .zip(allowed)
        .map(|(f, &allowed)| match allowed {
            false => HashSet::new(),
            true => terms_outside(f, target, &split)
                .map(|(phase, _)| phase)
                .collect(),
        })
        .collect();
    let mut holders: HashMap<&Vec<i64>, usize> = HashMap::new();
    for phase in outside.iter().flatten() {
        *holders.entry(phase).or_default() += 1;
    }
    let mut useful = allowed.to_vec();
    loop {
        let lone = |k: usize| outside[k].iter().any(|phase| holders[phase] == 1);
        let dropped: Vec<usize> = (0..basis.len()).filter(|&k| useful[k] && lone(k)).collect();
        if dropped.is_empty() {
            break;
        }
        for k in dropped {
            useful[k] = false;
            for phase in &outside[k] {
                *holders.get_mut(phase).expect("counted") -= 1;
            }
        }
    }
    (0..basis.len()).filter(|&k| useful[k]).collect()
}

#[cfg(test)]
mod tests {
    use super::{express, latex_name, BracketTable, FunctionName};
    use crate::systems::harmonic_rotor;
    use proptest::prelude::*;
    use trigpoly::{Expr, Style};

    #[test]
    fn a_function_name_prints_as_it_is_shown() {
        let name = FunctionName {
            name: "G1p".into(),
            display: "G1'".into(),
        };
        assert_eq!(name.to_string(), "G1'");
        assert_eq!(name.render(Style::Ascii), "G1p");
    }

    /// `express` with the rotor's functions written out, as `(name, value)`.
    fn express_in(target: &str, functions: &[(&str, &str)]) -> Option<Vec<(String, Expr)>> {
        let rotor = harmonic_rotor();
        let basis: Vec<(FunctionName, Expr)> = functions
            .iter()
            .map(|(name, value)| {
                let name = FunctionName {
                    name: name.to_string(),
                    display: name.to_string(),
                };
                (name, rotor.parse(value).expect("a value"))
            })
            .collect();
        let target = rotor.parse(target).expect("a target");
        let found = express(&target, &basis).expect("no limit is met");
        found.map(|c| c.into_iter().map(|(c, name)| (name.name, c)).collect())
    }

    /// A function with a monomial that neither the target nor another function has takes no
    /// part (and is left out before its columns are formed); two that share one can, when
    /// it cancels between them; parameters may stand in the coefficients.
    #[test]
    fn combinations_use_the_functions_that_can_take_part() {
        let rotor = harmonic_rotor();
        let c = |s: &str| rotor.parse(s).expect("a coefficient");
        let functions = [("F", "x + y"), ("G", "p_x - y"), ("B", "(1 + y + p_y)^6")];
        // y cancels between F and G; B has monomials of its own.
        assert_eq!(
            express_in("M*x + M*p_x", &functions),
            Some(vec![("F".into(), c("M")), ("G".into(), c("M"))])
        );
        assert_eq!(
            express_in("2*(1 + y + p_y)^6 - omega*(x + y)", &functions),
            Some(vec![("F".into(), c("-omega")), ("B".into(), c("2"))])
        );
        // No combination: x alone needs F without its y, and G's p_x is not in the target.
        assert_eq!(express_in("x", &functions), None);
        assert_eq!(express_in("x + p_y^7", &functions), None);
    }

    /// A term `c x^a y^b p_x^c p_y^d M^e ω^f` as text, with small exponents (those of the
    /// parameters Laurent).
    fn term() -> impl Strategy<Value = String> {
        (
            prop_oneof![-3i64..0, 1i64..4],
            proptest::collection::vec(0i64..3, 4),
            proptest::collection::vec(-1i64..2, 2),
        )
            .prop_map(|(c, phase, params)| {
                let names = ["x", "y", "p_x", "p_y", "M", "omega"];
                let factors: Vec<String> = names
                    .iter()
                    .zip(phase.iter().chain(&params))
                    .map(|(n, e)| format!("{n}^({e})"))
                    .collect();
                format!("({c})*{}", factors.join("*"))
            })
    }

    /// A function of one to four terms, as text.
    fn function() -> impl Strategy<Value = String> {
        proptest::collection::vec(term(), 1..5).prop_map(|t| t.join(" + "))
    }

    /// A coefficient: zero, or one term `c M^e ω^f` as text.
    fn coefficient() -> impl Strategy<Value = String> {
        prop_oneof![
            1 => Just("0".to_string()),
            3 => (prop_oneof![-3i64..0, 1i64..4], -1i64..2, -1i64..2)
                .prop_map(|(c, e, f)| format!("({c})*M^({e})*omega^({f})")),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// `Σ c_k F_k` with coefficients `c_k` of one term in the parameters (or zero), and no
        /// term of any `F_k` cancelled, is found as a combination that sums to it exactly.
        #[test]
        fn a_combination_without_cancellation_is_found(
            functions in proptest::collection::vec(function(), 3),
            coefficients in proptest::collection::vec(coefficient(), 3),
        ) {
            let rotor = harmonic_rotor();
            let parse = |s: &str| rotor.parse(s).expect("well formed");
            let text: Vec<String> = functions
                .iter()
                .zip(&coefficients)
                .map(|(f, c)| format!("({c})*({f})"))
                .collect();
            let target = parse(&text.join(" + "));
            let terms: usize = functions
                .iter()
                .zip(&coefficients)
                .filter(|(_, c)| *c != "0")
                .map(|(f, _)| parse(f).len())
                .sum();
            prop_assume!(!target.is_zero() && target.len() == terms);
            let names = ["F", "G", "B"];
            let named: Vec<(&str, &str)> =
                names.iter().zip(&functions).map(|(n, f)| (*n, f.as_str())).collect();
            let found = express_in(&text.join(" + "), &named).expect("a combination");
            let mut sum = parse("0");
            for (name, c) in &found {
                let k = names.iter().position(|n| n == name).expect("a name");
                sum = sum.checked_add(&c.checked_mul(&parse(&functions[k])).unwrap()).unwrap();
            }
            prop_assert_eq!(sum, target);
        }
    }

    /// Of functions that depend on one another (`Z = Re Z + i Im Z`), a combination of as few
    /// as leaving each out in turn gives: `p_x` is `Im Z`, not `−i Z + i Re Z`, which the
    /// first solve finds.
    #[test]
    fn combinations_take_the_fewest_of_dependent_functions() {
        let rotor = harmonic_rotor();
        let c = |s: &str| rotor.parse(s).expect("a coefficient");
        let functions = [("Z", "x + i*p_x"), ("ReZ", "x"), ("ImZ", "p_x")];
        assert_eq!(
            express_in("omega*p_x", &functions),
            Some(vec![("ImZ".into(), c("omega"))])
        );
        assert_eq!(
            express_in("2*x + 2*i*p_x", &functions),
            Some(vec![("Z".into(), c("2"))])
        );
        // Of two as few, the one without the earlier function (left out first).
        assert_eq!(
            express_in("x + 2*i*p_x", &functions),
            Some(vec![("ReZ".into(), c("1")), ("ImZ".into(), c("2*i"))])
        );
    }

    /// A combination whose columns cancel outside the bracket, each function's terms there met
    /// by the other's (`F1` has no term of the bracket at all), is found and taken when it is
    /// shorter than the bracket and its coefficients are polynomials; otherwise the bracket
    /// stays as it is.
    #[test]
    fn combinations_may_cancel_outside_the_bracket() {
        let rotor = harmonic_rotor();
        let c = |s: &str| rotor.parse(s).expect("a coefficient");
        let functions = [
            ("F1", "x^2 + y^2 + x*y"),
            ("F2", "x^2 + y^2 + x*y + p_x + p_y + x*p_y"),
        ];
        assert_eq!(
            express_in("M*(p_x + p_y + x*p_y)", &functions),
            Some(vec![("F1".into(), c("-M")), ("F2".into(), c("M"))])
        );
        // One term is shorter than two functions: `M y`, not `M F2 − M F1`.
        let short = [("F1", "x"), ("F2", "x + y")];
        assert_eq!(express_in("M*y", &short), None);
        // A parameter in a denominator: `(F2 − F1)/M`, which the bracket reads better than.
        let laurent = [
            ("F1", "x^2 + y^2 + x*y"),
            ("F2", "x^2 + y^2 + x*y + M*(p_x + p_y + x*p_y)"),
        ];
        assert_eq!(express_in("p_x + p_y + x*p_y", &laurent), None);
        assert_eq!(
            express_in("M^2*(p_x + p_y + x*p_y)", &laurent),
            Some(vec![("F1".into(), c("-M")), ("F2".into(), c("M"))])
        );
    }

    /// A combination whose coefficient has a denominator writes it last, so that the cell
    /// reads back: `{X, H} = D/M` was printed `1/M D`, which the parser refuses as ambiguous.
    #[test]
    fn a_coefficients_denominator_comes_last() {
        let mut rotor = harmonic_rotor();
        rotor.define_parsed("X", "X", "x").expect("a fresh name");
        rotor.define_parsed("D", "D", "p_x").expect("a fresh name");
        rotor
            .define_parsed("E", "E", "3*omega^2*x")
            .expect("a fresh name");
        let table = BracketTable::compute(&rotor, &["X", "H", "D", "E"]).expect("a table");
        let cell = |a: usize, b: usize, style| table.entries[a][b].render(style);
        assert_eq!(cell(0, 1, Style::Unicode), "D/M");
        assert_eq!(cell(0, 1, Style::Ascii), "D/M");
        assert_eq!(cell(1, 0, Style::Unicode), "−D/M");
        assert_eq!(cell(3, 1, Style::Unicode), "3ω² D/M");
        assert_eq!(cell(3, 1, Style::Ascii), "3*omega^2*D/M");
        assert_eq!(cell(0, 1, Style::Latex), r"\frac{D}{M}");
        // The name joins the numerator, as the printer writes the bracket in the functions.
        assert_eq!(cell(1, 0, Style::Latex), r"-\frac{D}{M}");
        assert_eq!(cell(3, 1, Style::Latex), r"\frac{3 \omega^{2} D}{M}");
        // Each reads back as the bracket it stands for.
        for (a, b) in [(0, 1), (1, 0), (3, 1)] {
            let bracket = rotor
                .bracket(
                    &rotor.parse(&table.names[a]).unwrap(),
                    &rotor.parse(&table.names[b]).unwrap(),
                )
                .unwrap();
            for style in [Style::Unicode, Style::Ascii] {
                let text = cell(a, b, style);
                let read = rotor.parse(&text.replace('−', "-").replace('ω', "omega"));
                assert_eq!(read.as_ref(), Ok(&bracket), "{text}");
            }
        }
    }

    /// Display names in LaTeX: digits as a subscript, bars, primes, and a family instance's
    /// own subscript kept (`P_{1,1}` was written `P_{_{1,1}}`).
    #[test]
    fn display_names_in_latex() {
        for (name, latex) in [
            ("L", "L"),
            ("G1'", "G_{1}'"),
            ("Z̄", r"\bar{Z}"),
            ("Z̄'", r"\bar{Z}'"),
            ("P_{1,1}", "P_{1,1}"),
            ("K̄'_{2,3}", r"\bar{K}'_{2,3}"),
            ("Re K", r"\operatorname{Re} K"),
            ("Re ω", r"\operatorname{Re} \omega"),
            ("Z̄_x", r"\bar{Z}_{x}"),
            ("ω (x)", r"\omega (x)"),
            ("K₁_{1,2}", "K_{1;1,2}"),
            ("K1'_{1,2}", "K_{1;1,2}'"),
            ("K_a_{m,n}", "K_{a;m,n}"),
            ("K_{a}", "K_{a}"),
            // As a statement writes them (`render::tex`).
            ("∂H", r"\partial H"),
            ("∇φ", r"\nabla\varphi"),
            ("∂H_x", r"\partial H_{x}"),
            ("x(t)", "x(t)"),
        ] {
            assert_eq!(latex_name(name), latex, "{name}");
        }
    }
}
