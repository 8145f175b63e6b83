//! Bracket tables: every `{A, B}` of a list of named functions, written as a linear combination
//! of the listed functions with coefficients in the parameters where one exists (found by exact
//! linear algebra, then checked), otherwise as an expression.

use std::collections::{BTreeMap, BTreeSet};

use trigpoly::{Expr, GaussianRational, Style, VarKind};

use crate::clearing::Clearing;
use crate::error::EngineError;
use crate::linalg::Matrix;
use crate::system::System;

/// One entry of a table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Entry {
    /// `Σ c_k F_k` with coefficients in the parameters (empty for zero), checked exactly.
    Combination(Vec<(Expr, FunctionName)>),
    /// No such combination: the bracket itself, in normal form.
    Expression(Expr),
    /// Outside what the table writes (a closure's bracket that is no polynomial of the degree
    /// in the generators): shown as `*`, the bracket given apart.
    Outside,
}

/// A function of a table by name: the system's name, which reads back (`G1p`), and the name
/// it is shown by (`G1'`).
#[derive(Clone, Debug, PartialEq, Eq)]
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

/// The table `{A, B}` for a list of named functions of a system.
#[derive(Clone, Debug)]
pub struct BracketTable {
    /// The functions' names, as given.
    pub names: Vec<String>,
    /// The functions' display names.
    pub display: Vec<String>,
    /// `entries[a][b]` is `{names[a], names[b]}`.
    pub entries: Vec<Vec<Entry>>,
}

impl BracketTable {
    /// Computes the table for named functions of `system`.
    pub fn compute(system: &System, names: &[&str]) -> Result<Self, EngineError> {
        // Each over its common denominator, as the brackets will be, so that a bracket that
        // is one of them written another way (`x/(x − y)² − y/(x − y)²` for `1/(x − y)`)
        // shows as that one.
        let funcs: Vec<Expr> = names
            .iter()
            .map(|n| Ok(system.get(n)?.over_common_denominators()?))
            .collect::<Result<_, EngineError>>()?;
        let basis: Vec<(FunctionName, Expr)> = names
            .iter()
            .map(|n| FunctionName {
                name: n.to_string(),
                display: system.display_name(n).to_string(),
            })
            .zip(funcs.iter().cloned())
            .collect();
        // The bracket is antisymmetric: the entries above the diagonal are computed, those on
        // it are zero and those below are the negated entries above.
        let n = funcs.len();
        let mut entries: Vec<Vec<Entry>> = (0..n).map(|_| Vec::with_capacity(n)).collect();
        for a in 0..n {
            entries[a].push(Entry::Combination(Vec::new()));
            for b in a + 1..n {
                // Over a common denominator (with denominator atoms; as it is otherwise), so
                // that a bracket equal to zero is 0 and reads as its numerator shows.
                let br = system
                    .bracket(&funcs[a], &funcs[b])?
                    .over_common_denominators()?;
                let entry = match express(&br, &basis)? {
                    Some(c) => Entry::Combination(c),
                    None => Entry::Expression(br),
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

impl Entry {
    /// `−entry`: the entry of the transposed bracket.
    fn negated(&self) -> Entry {
        match self {
            Entry::Combination(terms) => {
                Entry::Combination(terms.iter().map(|(c, name)| (-c, name.clone())).collect())
            }
            Entry::Expression(e) => Entry::Expression(-e),
            Entry::Outside => Entry::Outside,
        }
    }

    /// The entry as text in a notation: `−ω² L`, `4 G1`, `0`.
    pub fn render(&self, style: Style) -> String {
        match self {
            Entry::Expression(e) => e.render(style),
            Entry::Outside => "*".into(),
            Entry::Combination(terms) if terms.is_empty() => "0".into(),
            Entry::Combination(terms) => {
                let mut out = String::new();
                for (k, (c, name)) in terms.iter().enumerate() {
                    let name = name.render(style);
                    let text = c.render(style);
                    let (neg, body) = match text.strip_prefix(['−', '-']) {
                        Some(rest) if c.len() == 1 => (true, rest.to_string()),
                        _ => (false, text),
                    };
                    let mul = if style == Style::Ascii { "*" } else { " " };
                    // A term's denominator goes last, `D/M` and `3ω² D/2`: `1/M D` is read back
                    // as ambiguous, and writes a division before a factor.
                    let fraction = match style {
                        Style::Latex => None,
                        _ => body.rsplit_once('/').filter(|_| c.len() == 1),
                    };
                    let term = match (body.as_str(), fraction) {
                        ("1", _) => name,
                        _ if c.len() > 1 => format!("({body}){mul}{name}"),
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

/// `G1'` → `G_{1}'`, `Z̄` → `\bar{Z}`, `L` → `L`, `P'_{1,1}` → `P'_{1,1}`: the name as
/// [`trigpoly::display_forms`] writes it in LaTeX (word by word in a name of several words,
/// `Re ω` → `\mathrm{Re} \omega`), before any subscript of its own (a family instance's
/// indices), which joins a subscript the name ends with after `;` (`K₁_{1,2}` → `K_{1;1,2}`:
/// LaTeX refuses a double subscript).
pub fn latex_name(name: &str) -> String {
    let (head, subscript) = name.split_at(name.find("_{").unwrap_or(name.len()));
    let head = match trigpoly::display_forms(head) {
        Some((_, latex)) => latex,
        None => words_in_latex(head),
    };
    let Some(indices) = subscript.strip_prefix("_{") else {
        return head;
    };
    let bare = head.trim_end_matches('\'');
    let primes = &head[bare.len()..];
    match own_subscript(bare) {
        Some(own) => format!(
            "{}{own};{indices}{primes}",
            &bare[..bare.len() - own.len() - 1]
        ),
        None => format!("{head}{subscript}"),
    }
}

/// A name that is no display name as a whole (`Re ω`), each word as
/// [`trigpoly::display_forms`] writes it, the rest as it is.
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
            Some((_, latex)) => out.push_str(&latex),
            None => out.push_str(part),
        }
        rest = after;
    }
    out
}

/// The subscript a name's LaTeX ends with, open: `K_{1}` → `_{1` (`None` for `\bar{K}`).
fn own_subscript(latex: &str) -> Option<&str> {
    let body = latex.strip_suffix('}')?;
    let mut depth = 0;
    for (k, c) in body.char_indices().rev() {
        match c {
            '}' => depth += 1,
            '{' if depth > 0 => depth -= 1,
            '{' => {
                return latex[..k]
                    .ends_with('_')
                    .then(|| &latex[k - 1..latex.len() - 1])
            }
            _ => {}
        }
    }
    None
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
    let Some(coeffs) = solve_combination(&cleared_target, &cleared_basis)? else {
        return Ok(None);
    };
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

/// Coefficients `c_k`, each a polynomial in the parameters, with `Σ c_k f_k = target` as
/// polynomials whose monomials are independent (no denominator atoms), found by an exact
/// linear solve; `None` when the ansatz holds none.
fn solve_combination(target: &Expr, basis: &[Expr]) -> Result<Option<Vec<Expr>>, EngineError> {
    let vars = target.vars().clone();
    let is_param: Vec<bool> = vars
        .vars()
        .map(|v| vars.variable(v).kind() == VarKind::Parameter)
        .collect();
    let split = |e: &[i64]| -> (Vec<i64>, Vec<i64>) {
        let phase = e
            .iter()
            .zip(&is_param)
            .map(|(&x, &p)| if p { 0 } else { x })
            .collect();
        let param = e
            .iter()
            .zip(&is_param)
            .map(|(&x, &p)| if p { x } else { 0 })
            .collect();
        (phase, param)
    };
    // The target's parameter parts by phase-space part: a term of `F_k` meets the target's
    // terms of its own phase-space monomial by one lookup, where a scan of all of them for
    // each of its terms took minutes for functions of 10⁵ terms.
    let mut target_params: BTreeMap<Vec<i64>, Vec<Vec<i64>>> = BTreeMap::new();
    for t in target.terms() {
        let (phase, param) = split(&t.exponents());
        target_params.entry(phase).or_default().push(param);
    }
    // Candidate columns ν·F_k.
    let mut columns: Vec<(usize, Vec<i64>, Expr)> = Vec::new();
    for (k, f) in basis.iter().enumerate() {
        let mut nus: BTreeSet<Vec<i64>> = BTreeSet::new();
        for u in f.terms() {
            let (uphase, uparam) = split(&u.exponents());
            for tparam in target_params.get(&uphase).into_iter().flatten() {
                nus.insert(tparam.iter().zip(&uparam).map(|(a, b)| a - b).collect());
            }
        }
        for nu in nus {
            let powers: Vec<_> = vars.vars().zip(nu.iter().copied()).collect();
            let m = Expr::monomial(&vars, GaussianRational::from(1), &powers)?;
            columns.push((k, nu, f.checked_mul(&m)?));
        }
    }
    if columns.is_empty() {
        return Ok(None);
    }
    // Rows: every monomial that appears.
    let mut rows: BTreeMap<Vec<i64>, usize> = BTreeMap::new();
    for e in target.terms().map(|t| t.exponents()).chain(
        columns
            .iter()
            .flat_map(|c| c.2.terms().map(|t| t.exponents()).collect::<Vec<_>>()),
    ) {
        let n = rows.len();
        rows.entry(e).or_insert(n);
    }
    let mut a = Matrix::zeros(rows.len(), columns.len());
    for (j, (_, _, col)) in columns.iter().enumerate() {
        for t in col.terms() {
            a.set(rows[&t.exponents()], j, t.coeff());
        }
    }
    let mut b = vec![GaussianRational::default(); rows.len()];
    for t in target.terms() {
        b[rows[&t.exponents()]] = t.coeff();
    }
    let Some(x) = a.solve(&b) else {
        return Ok(None);
    };
    let mut coeffs: Vec<Expr> = vec![Expr::zero(&vars); basis.len()];
    for ((k, nu, _), xj) in columns.iter().zip(&x) {
        if xj.is_zero() {
            continue;
        }
        let powers: Vec<_> = vars.vars().zip(nu.iter().copied()).collect();
        coeffs[*k] = coeffs[*k].checked_add(&Expr::monomial(&vars, xj.clone(), &powers)?)?;
    }
    Ok(Some(coeffs))
}

#[cfg(test)]
mod tests {
    use super::{latex_name, BracketTable};
    use crate::systems::harmonic_rotor;
    use trigpoly::Style;

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
        assert_eq!(cell(0, 1, Style::Latex), r"\frac{1}{M} D");
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
            ("Re K", r"\mathrm{Re} K"),
            ("Z̄_x", r"\bar{Z}_{x}"),
            ("ω (x)", r"\omega (x)"),
            ("K₁_{1,2}", "K_{1;1,2}"),
            ("K1'_{1,2}", "K_{1;1,2}'"),
            ("K_a_{m,n}", "K_{a;m,n}"),
            ("K_{a}", "K_{a}"),
        ] {
            assert_eq!(latex_name(name), latex, "{name}");
        }
    }
}
