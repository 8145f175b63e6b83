//! From the paper's unicode notation to LaTeX: [`math`] for formulas (`{L, G1} = −G2` →
//! `\{L, G_{1}\} = -G_{2}`), [`text`] for prose, [`markup`] for prose with formulas between
//! backticks. The output is ASCII and valid by construction: every special character is
//! escaped, braces balance, and characters without a translation become `?`.

/// Symbols and their LaTeX math commands.
const SYMBOLS: &[(char, &str)] = &[
    ('−', "-"),
    ('ħ', r"\hbar"),
    ('ℓ', r"\ell"),
    ('·', r"\cdot"),
    ('×', r"\times"),
    ('≤', r"\le"),
    ('≥', r"\ge"),
    ('≠', r"\neq"),
    ('→', r"\to"),
    ('⇒', r"\Rightarrow"),
    ('…', r"\dots"),
    ('⋯', r"\cdots"),
    ('∈', r"\in"),
    ('∞', r"\infty"),
    ('±', r"\pm"),
    ('∘', r"\circ"),
    ('≡', r"\equiv"),
    ('≈', r"\approx"),
    ('√', r"\surd"),
    ('∑', r"\sum"),
    ('′', "'"),
    ('%', r"\%"),
    ('&', r"\&"),
    ('#', r"\#"),
    ('$', r"\$"),
    ('~', r"\sim"),
    ('\\', r"\backslash"),
];

/// Precomposed letters with an accent, in mathematics: (char, accent, base).
const ACCENTED: &[(char, &str, char)] = &[
    ('ẋ', "dot", 'x'),
    ('ẏ', "dot", 'y'),
    ('ṗ', "dot", 'p'),
    ('ẍ', "ddot", 'x'),
    ('ÿ', "ddot", 'y'),
    ('ā', "bar", 'a'),
    ('Ā', "bar", 'A'),
    ('ū', "bar", 'u'),
    ('ē', "bar", 'e'),
];

/// Function names set upright.
const FUNCTIONS: &[(&str, &str)] = &[
    ("cos", r"\cos"),
    ("sin", r"\sin"),
    ("exp", r"\exp"),
    ("log", r"\log"),
    ("Re", r"\operatorname{Re}"),
    ("Im", r"\operatorname{Im}"),
    ("rank", r"\operatorname{rank}"),
    ("conj", r"\operatorname{conj}"),
    ("sqrt", r"\operatorname{sqrt}"),
];

/// Short words that are prose, not products of variables.
const STOPWORDS: &[&str] = &[
    "is", "at", "on", "of", "by", "so", "to", "if", "as", "or", "in", "no", "be", "an", "it",
];

const SUPERSCRIPTS: &str = "⁰¹²³⁴⁵⁶⁷⁸⁹";
const SUBSCRIPTS: &str = "₀₁₂₃₄₅₆₇₈₉";

/// A symbol's LaTeX math command: one of the [`SYMBOLS`], or a differential sign as a display
/// name's LaTeX writes it ([`trigpoly::differential_latex`]: `∂`, `∇`).
fn symbol(c: char) -> Option<&'static str> {
    SYMBOLS
        .iter()
        .find(|g| g.0 == c)
        .map(|g| g.1)
        .or_else(|| trigpoly::differential_latex(c))
}

fn accent_of(mark: char) -> Option<&'static str> {
    match mark {
        '\u{304}' | '\u{305}' => Some("bar"),
        '\u{307}' => Some("dot"),
        '\u{308}' => Some("ddot"),
        '\u{302}' => Some("hat"),
        '\u{303}' => Some("tilde"),
        _ => None,
    }
}

/// Whether a character is a combining mark (drawn over the previous one).
pub fn is_combining(c: char) -> bool {
    ('\u{300}'..='\u{36f}').contains(&c)
}

/// A lexical token of the unicode notation.
#[derive(Clone, Debug, PartialEq)]
enum Tok {
    /// A run of ASCII letters, with the digits that follow it (`G1` → ("G", "1")).
    Word(String, String),
    /// A run of spaces.
    Space,
    /// One character (with the accent over it, if any).
    Char(char, Option<&'static str>),
    /// A name the system declares, in its LaTeX ([`Names`]).
    Name(String),
}

/// A system's names and their LaTeX as the expression printer writes them (a variable's
/// [`trigpoly::Variable::latex`], a function's [`brackets::table::latex_name`] of its display
/// name), so that a statement, a table's header or a title writes a name as its expressions
/// do: `alpha1` is `\alpha_{1}` (it was `alpha_{1}`, a·l·p·h·a), `ωx` is `\mathrm{{\omega}x}`
/// (it was `\omega x`, ω·x), `Lambda3x` is `\mathrm{Lambda3x}`. A run of letters that the names
/// spell whole is read as those names, longest first; any other is translated as before.
#[derive(Clone, Debug, Default)]
pub struct Names {
    /// Each name as written (unicode, display or ASCII) and its LaTeX.
    forms: Vec<(String, String)>,
    /// Each family's display and its LaTeX, longest first ([`Names::with_families`]).
    families: Vec<(String, String)>,
}

impl Names {
    /// The names of `system`: its variables (but its denominators, which are polynomials) by
    /// their unicode and ASCII names, its functions by their display and ASCII names and by
    /// the text the expressions print the display as (`ω3` of `omega3`).
    pub fn of_system(system: &brackets::System) -> Names {
        let vars = system.vars();
        let mut forms = Vec::new();
        for v in vars.vars() {
            let var = vars.variable(v);
            if var.kind() == trigpoly::VarKind::Denominator {
                continue;
            }
            for written in [var.unicode(), var.name()] {
                forms.push((written.to_string(), var.latex().to_string()));
            }
        }
        for f in system.functions() {
            let latex = brackets::table::latex_name(&f.display);
            // As a statement writes it too, its Greek letters written (`ω3` of `omega3`).
            if let Some((text, _)) = trigpoly::shown_forms(&f.display) {
                forms.push((text, latex.clone()));
            }
            forms.push((f.display.clone(), latex.clone()));
            forms.push((f.name.clone(), latex));
        }
        forms.sort();
        forms.dedup_by(|a, b| a.0 == b.0);
        Names {
            forms,
            families: Vec::new(),
        }
    }

    /// These names and the families shown as `displays` (a system file's `K`, `K̄`,
    /// `Q_theta1`), whose instances a statement writes with their indices in braces, as the
    /// expressions print the display, `Q_θ1_{1,2}` (or as written, `Q_theta1_{1,2}`): each is
    /// then written as the expressions write it,
    /// `Q_{\theta1;1,2}` (it was `Q_{theta1;1,2}`, t·h·e·t·a), a family's LaTeX
    /// ([`trigpoly::shown_forms`]) with the indices joined to its subscript
    /// ([`trigpoly::with_indices`]).
    #[must_use]
    pub fn with_families<'a>(mut self, displays: impl IntoIterator<Item = &'a str>) -> Names {
        for display in displays {
            if let Some((text, latex)) = trigpoly::shown_forms(display) {
                // As a statement writes it too, its Greek letters written (`Q_θ1`).
                self.families.push((text, latex.clone()));
                self.families.push((display.to_string(), latex));
            }
        }
        self.families
            .sort_by(|a, b| b.0.len().cmp(&a.0.len()).then_with(|| a.cmp(b)));
        self.families.dedup_by(|a, b| a.0 == b.0);
        self
    }

    /// The LaTeX of the family instance written at `chars[i..]` after the digits of a
    /// coefficient (`2Q_theta1_{1,2}`), and where it ends: a family's display, `_{`, two
    /// indices of letters and digits apart by a comma, `}`.
    fn instance(&self, chars: &[char], i: usize) -> Option<(usize, String, usize)> {
        let digits = chars[i..].iter().take_while(|c| c.is_ascii_digit()).count();
        let at = i + digits;
        self.families.iter().find_map(|(display, latex)| {
            let name: Vec<char> = display.chars().collect();
            let rest = chars.get(at..)?.strip_prefix(name.as_slice())?;
            let braced = rest.strip_prefix(&['_', '{'][..])?;
            let close = braced.iter().position(|&c| c == '}')?;
            let indices: String = braced[..close].iter().collect();
            let (m, n) = indices.split_once(',')?;
            let index = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric());
            let end = at + name.len() + 2 + close + 1;
            let after_name = chars.get(end).is_some_and(|&c| in_name(c));
            (index(m) && index(n) && !after_name)
                .then(|| (digits, trigpoly::with_indices(latex, &indices), end))
        })
    }

    /// The LaTeX of each name that `run` spells, in order, when the names spell it whole: the
    /// fewest names, so the longest.
    fn spell(&self, run: &str) -> Option<Vec<&str>> {
        if self.forms.is_empty() {
            return None;
        }
        // best[k]: the fewest names that spell run[k..], and the first of them.
        let mut best: Vec<Option<(usize, usize)>> = vec![None; run.len() + 1];
        best[run.len()] = Some((0, usize::MAX));
        for k in (0..run.len()).rev().filter(|&k| run.is_char_boundary(k)) {
            for (f, (written, _)) in self.forms.iter().enumerate() {
                let end = k + written.len();
                if !written.is_empty() && run[k..].starts_with(written.as_str()) {
                    if let Some((n, _)) = best[end] {
                        if best[k].is_none_or(|(m, _)| n + 1 < m) {
                            best[k] = Some((n + 1, f));
                        }
                    }
                }
            }
        }
        let mut out = Vec::new();
        let mut k = 0;
        while k < run.len() {
            let (_, f) = best[k]?;
            let (written, latex) = &self.forms[f];
            out.push(latex.as_str());
            k += written.len();
        }
        Some(out)
    }
}

/// Whether `c` can be in a name: a letter, a digit, `_`, a prime, a combining mark (a bar),
/// a subscript digit or sign (a display name's `ω₊`, which the names then spell as the
/// variable's `\omega_{+}`; a run they do not spell is translated as before, the sign a
/// script of its own).
fn in_name(c: char) -> bool {
    c.is_alphabetic()
        || c.is_ascii_digit()
        || SUBSCRIPTS.contains(c)
        || matches!(c, '_' | '\'' | '₊' | '₋')
        || is_combining(c)
}

/// The names that the run of name characters starting at `chars[i]` spells whole, after
/// the digits it starts with (a number's: `2ωx`), and where the run ends; `None` for a run
/// that is a function's (`cos`), prose (`solves`, `at`) unless it is one name, or that the names
/// do not spell. A differential sign right before a letter starts the run (a display name's
/// `∂L`, whose `L` alone the names spell too when `L` is the function's name: `∂L²` was
/// `\partial\partial L^{2}`); where the names do not spell the run with it, the sign is a
/// character of its own, as before.
fn spelled<'n>(chars: &[char], i: usize, names: &'n Names) -> Option<(usize, Vec<&'n str>, usize)> {
    let sign = trigpoly::is_differential_sign(chars[i])
        && chars.get(i + 1).is_some_and(|c| c.is_alphabetic());
    let end = (i + usize::from(sign)..chars.len())
        .find(|&j| !in_name(chars[j]))
        .unwrap_or(chars.len());
    let digits = chars[i..end]
        .iter()
        .take_while(|c| c.is_ascii_digit())
        .count();
    if i + digits == end {
        return None;
    }
    let run: String = chars[i + digits..end].iter().collect();
    let spelled = names.spell(&run)?;
    let function = FUNCTIONS.iter().any(|f| f.0 == run) || matches!(run.as_str(), "re" | "im");
    let prose = is_prose_word(&run) || run == "a";
    ((!function && !prose) || spelled.len() == 1).then_some((digits, spelled, end))
}

fn tokenize(s: &str, names: &Names) -> Vec<Tok> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let accent_at = |j: usize| chars.get(j).copied().and_then(accent_of);
    while i < chars.len() {
        let c = chars[i];
        let run_starts = i == 0 || !in_name(chars[i - 1]);
        if let Some((digits, latex, end)) = names.instance(&chars, i).filter(|_| run_starts) {
            out.extend(chars[i..i + digits].iter().map(|&d| Tok::Char(d, None)));
            out.push(Tok::Name(latex));
            i = end;
        } else if let Some((digits, spelled, end)) =
            spelled(&chars, i, names).filter(|_| run_starts)
        {
            out.extend(chars[i..i + digits].iter().map(|&d| Tok::Char(d, None)));
            out.extend(
                spelled
                    .into_iter()
                    .map(|latex| Tok::Name(latex.to_string())),
            );
            i = end;
        } else if c == ' ' {
            while i < chars.len() && chars[i] == ' ' {
                i += 1;
            }
            out.push(Tok::Space);
        } else if c.is_ascii_alphabetic() && accent_at(i + 1).is_none() {
            let mut word = String::new();
            while i < chars.len() && chars[i].is_ascii_alphabetic() && accent_at(i + 1).is_none() {
                word.push(chars[i]);
                i += 1;
            }
            let mut digits = String::new();
            while i < chars.len() && chars[i].is_ascii_digit() {
                digits.push(chars[i]);
                i += 1;
            }
            out.push(Tok::Word(word, digits));
        } else {
            let accent = accent_at(i + 1);
            out.push(Tok::Char(c, accent));
            i += 1;
            // Skip the combining marks (an unknown one is dropped).
            while i < chars.len() && is_combining(chars[i]) {
                i += 1;
            }
        }
    }
    out
}

fn is_prose_word(w: &str) -> bool {
    let lower = w.chars().all(|c| c.is_ascii_lowercase());
    (lower && w.len() >= 3 && !FUNCTIONS.iter().any(|f| f.0 == w)) || STOPWORDS.contains(&w)
}

/// What ends a control word while a formula is translated: a space where a letter or a digit
/// follows, which it would extend (`\omega t`), else nothing (`\omega^{2}`, `p_{\theta}`,
/// `(M\omega)`, as the expression printer writes them; it was `\omega ^{2}`). [`resolve`] decides
/// once the formula is written. A private-use character, which no input reaches `out` as: a
/// character without a translation is written by its code point.
const SEPARATOR: char = '\u{e000}';

/// Appends a control word, followed by a [`SEPARATOR`] so that a letter after it cannot extend
/// it.
fn push_cmd(out: &mut String, cmd: &str) {
    out.push_str(cmd);
    if cmd.starts_with('\\') && cmd[1..].chars().all(|c| c.is_ascii_alphabetic()) {
        out.push(SEPARATOR);
    }
}

/// Each [`SEPARATOR`] of a translated formula as a space where a letter or a digit follows it,
/// else dropped.
fn resolve(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            SEPARATOR if chars.peek().is_some_and(char::is_ascii_alphanumeric) => out.push(' '),
            SEPARATOR => {}
            _ => out.push(c),
        }
    }
    out
}

fn char_math(c: char) -> Option<String> {
    if let Some(g) = trigpoly::greek_latex(c) {
        return Some(g.to_string());
    }
    if let Some(s) = symbol(c) {
        return Some(s.to_string());
    }
    if let Some((_, accent, base)) = ACCENTED.iter().find(|a| a.0 == c) {
        return Some(format!(r"\{accent}{{{base}}}"));
    }
    // A script digit on its own: one with an accent over it, which no run of digits takes.
    if let Some(d) = SUPERSCRIPTS.chars().position(|s| s == c) {
        return Some(format!("{{}}^{{{d}}}"));
    }
    if let Some(d) = SUBSCRIPTS.chars().position(|s| s == c) {
        return Some(format!("{{}}_{{{d}}}"));
    }
    // Script signs, as in `x⁻¹` and the frequencies `ω₊`, `ω₋` (`₊`, `₋`, `⁺` were written by
    // their code points).
    if let Some(s) = match c {
        '⁻' => Some("{}^{-}"),
        '⁺' => Some("{}^{+}"),
        '₊' => Some("{}_{+}"),
        '₋' => Some("{}_{-}"),
        _ => None,
    } {
        return Some(s.into());
    }
    if c.is_ascii() && !c.is_ascii_control() {
        return Some(c.to_string());
    }
    None
}

/// Translates a formula in the paper's unicode notation into LaTeX math (without `$`).
///
/// ```
/// use superint::render::tex::math;
/// assert_eq!(math("{L, G1} = −G2"), r"\{L, G_{1}\} = -G_{2}");
/// assert_eq!(math("ṗ_θ = 0"), r"\dot{p}_{\theta} = 0");
/// assert_eq!(math("K̄_{m,n} for all m"), r"\bar{K}_{m,n}\ \text{for all}\ m");
/// assert_eq!(math("x中"), r"x\mbox{\texttt{U+4E2D}}");
/// ```
pub fn math(s: &str) -> String {
    translate(s, &Names::default())
}

/// [`math`] with the names of a system written as its expressions write them ([`Names`]).
pub fn math_with(s: &str, names: &Names) -> String {
    translate(s, names)
}

/// A sentence that mixes prose and formulas, in text mode: runs of prose words stay text,
/// runs of anything else become inline math, so that the line can break between words.
///
/// ```
/// use superint::render::tex::sentence;
/// assert_eq!(
///     sentence("so {A, H} = λ_A A for all m, n ≥ 0"),
///     r"so $\{A, H\} = \lambda_{A} A$ for all $m, n \ge 0$"
/// );
/// ```
pub fn sentence(s: &str) -> String {
    set_sentence(s, |piece| match piece {
        Piece::Prose(p) => text(p),
        Piece::Formula(f) => format!("${}$", math(f)),
    })
}

/// A sentence of prose and formulas with each of its pieces ([`sentence_words`]) set by
/// `set`, its words apart by spaces: [`sentence`] in LaTeX, and Markdown's with code spans.
pub(crate) fn set_sentence(s: &str, set: impl Fn(&Piece) -> String) -> String {
    let words: Vec<String> = sentence_words(s)
        .iter()
        .map(|word| word.iter().map(&set).collect())
        .collect();
    words.join(" ")
}

/// A piece of a sentence ([`sentence_words`]): prose, or a formula in the paper's notation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Piece {
    Prose(String),
    Formula(String),
}

/// A sentence that mixes prose and formulas as its words, set apart by spaces, each the
/// pieces it is written in: runs of prose words are prose, runs of anything else formulas
/// (what [`sentence`] sets in LaTeX, and Markdown in code spans).
fn sentence_words(s: &str) -> Vec<Vec<Piece>> {
    let is_prose = |chunk: &str| {
        let w = chunk.trim_end_matches([',', '.', ';', ':']);
        !w.is_empty()
            && (w == "a" || is_prose_word(w))
            && w.chars().all(|c| c.is_ascii_alphabetic())
    };
    let is_number = |w: &str| !w.is_empty() && w.chars().all(|c| c.is_ascii_digit() || c == '.');
    let mut out: Vec<Vec<Piece>> = Vec::new();
    let mut run: Vec<&str> = Vec::new();
    // The punctuation that ends a formula's run is the sentence's, after the `$`: `for all
    // $m, n \ge 0$, from` (it was `$m, n \ge 0,$`).
    let flush = |run: &mut Vec<&str>, out: &mut Vec<Vec<Piece>>| {
        if !run.is_empty() {
            let joined = run.join(" ");
            let formula = joined.trim_end_matches([',', '.', ';', ':']);
            let stop = &joined[formula.len()..];
            match formula.is_empty() {
                true => out.push(vec![Piece::Prose(joined.clone())]),
                false => out.push(
                    [Piece::Formula(formula.to_string())]
                        .into_iter()
                        .chain((!stop.is_empty()).then(|| Piece::Prose(stop.to_string())))
                        .collect(),
                ),
            }
            run.clear();
        }
    };
    // Whether the formula being gathered has a parenthesis open, which a number closes as
    // part of it: `mλ(1, 0) + nλ(0, 1)` was `$m\lambda(1$, $0$) $+ n\lambda(0$, $1$)`.
    let opened = |run: &[&str]| {
        let depth = |c: char| run.iter().map(|w| w.matches(c).count()).sum::<usize>();
        depth('(') > depth(')')
    };
    let chunks: Vec<&str> = s.split(' ').filter(|c| !c.is_empty()).collect();
    // A function's name that a prose word follows is prose itself: `the rank is 3`, where
    // `rank ∂(F, G)/∂(x, y)` is mathematics.
    let prose_at = |k: usize| {
        let chunk = chunks[k];
        is_prose(chunk)
            || (FUNCTIONS.iter().any(|f| f.0 == chunk)
                && chunks.get(k + 1).is_some_and(|next| is_prose(next)))
    };
    let mut after_number = false;
    for (k, &chunk) in chunks.iter().enumerate() {
        // A parenthesis that opens before a word or a number, or closes after one, stays
        // text: `(3 exact checks, 0.01 s)` is `($3$ exact checks, $0.01$ s)`, and `s` after a
        // number is the unit.
        let inner = chunk.trim_start_matches('(');
        let open = &chunk[..chunk.len() - inner.len()];
        let core = inner.trim_end_matches([')', ',', '.', ';', ':']);
        let close = &inner[core.len()..];
        let unit = after_number && core == "s";
        after_number = is_number(core);
        if prose_at(k) || (unit && open.is_empty()) {
            flush(&mut run, &mut out);
            out.push(vec![Piece::Prose(chunk.to_string())]);
        } else if (open.is_empty() && !close.contains(')'))
            || !(is_prose(core) || unit || is_number(core))
            || opened(&run)
        {
            // Parentheses around formulas stay in the formula: `(x + y)²`, `= (a + b) c`. A
            // group that opens after a formula's last term, not after a sign, is a
            // parenthetical, a formula of its own: `$m \ge 0$ $(K = Z^{m})$`, where
            // `$m \ge 0 (K = Z^{m})$` read as the product `0 (K = …)`.
            let after_term = run.last().is_some_and(|last: &&str| {
                !last.ends_with([
                    '=', '+', '−', '-', '×', '·', '/', '≤', '≥', '<', '>', '≠', '(',
                ])
            });
            if !open.is_empty() && after_term {
                flush(&mut run, &mut out);
            }
            run.push(chunk);
        } else {
            flush(&mut run, &mut out);
            let core = match is_prose(core) || unit {
                true => Piece::Prose(core.to_string()),
                false => Piece::Formula(core.to_string()),
            };
            let word = [
                Piece::Prose(open.to_string()),
                core,
                Piece::Prose(close.to_string()),
            ];
            out.push(
                word.into_iter()
                    .filter(|p| *p != Piece::Prose(String::new()))
                    .collect(),
            );
        }
    }
    flush(&mut run, &mut out);
    out
}

/// Which tokens are words of prose, set as text, and not mathematics: a word between spaces
/// or punctuation that reads as prose, outside any script (`e^{−inθ}`), and a lone `a` before
/// such a word (the article).
fn prose_words(toks: &[Tok]) -> Vec<bool> {
    let mut prose = vec![false; toks.len()];
    let mut scripts: Vec<bool> = Vec::new();
    for (k, t) in toks.iter().enumerate() {
        match t {
            Tok::Word(w, d) => {
                // A word is prose only between spaces or punctuation: `in` in `exp(−inθ)` is
                // the product i·n.
                let before = k.checked_sub(1).map(|j| &toks[j]);
                let apart_before =
                    matches!(before, None | Some(Tok::Space | Tok::Char('(' | '[', _)));
                let apart_after = matches!(
                    toks.get(k + 1),
                    None | Some(Tok::Space | Tok::Char(',' | '.' | ':' | ';' | ')' | ']', _))
                );
                prose[k] = d.is_empty()
                    && is_prose_word(w)
                    && !scripts.contains(&true)
                    && apart_before
                    && apart_after;
            }
            Tok::Char('{', _) => {
                let script = k > 0 && matches!(toks[k - 1], Tok::Char('_' | '^', _));
                scripts.push(script);
            }
            Tok::Char('}', _) => {
                scripts.pop();
            }
            _ => {}
        }
    }
    // A lone "a" before a prose word is the article.
    for k in 0..toks.len() {
        if toks[k] == Tok::Word("a".into(), String::new())
            && toks.get(k + 1) == Some(&Tok::Space)
            && prose.get(k + 2) == Some(&true)
        {
            prose[k] = true;
        }
    }
    prose
}

/// Translates a formula in the paper's unicode notation into LaTeX math, token by token.
fn translate(s: &str, names: &Names) -> String {
    let toks = tokenize(s, names);
    let prose = prose_words(&toks);
    Translation::new(&toks, &prose).run()
}

/// A formula being translated: its tokens and which of them are prose, the LaTeX written so
/// far, and what its braces and subscripts left open.
struct Translation<'a> {
    toks: &'a [Tok],
    prose: &'a [bool],
    /// The token at hand.
    k: usize,
    out: String,
    /// Each open brace, in order.
    braces: Vec<Brace>,
    /// The script group the next brace opens, when a script sign with nothing after it
    /// came last.
    next_group: Option<NextGroup>,
    /// Where the last subscript group ended in `out`: a second subscript right after it, the
    /// indices of a family named `K₁` or `K_a` (`K₁_{1,2}`), joins it after a semicolon,
    /// `K_{1;1,2}`, as LaTeX refuses a double subscript.
    subscript_end: Option<usize>,
    /// The scripts of the base the last script group ended on: where in `out` it ended, and
    /// whether the base has a subscript and a superscript. A second script of a kind it has
    /// (`x²^1`, `x^a_b^c`) starts from an empty base, `x^{2}{}^{1}`, as LaTeX refuses a
    /// double script.
    scripts: Option<Scripts>,
}

/// An open brace: a script's group (not an escaped brace), and then whether a subscript's and
/// the scripts its base had before it, `(sub, sup)`, which the group adds to when it closes
/// (`x^{a}_{b}^{c}` has a double superscript).
#[derive(Clone, Copy)]
struct Brace {
    group: bool,
    subscript: bool,
    base: (bool, bool),
}

/// The script group that a brace right after a script sign opens: whether it is a second
/// subscript that joins the last one, and the scripts its base had before it, `(sub, sup)`.
#[derive(Clone, Copy)]
struct NextGroup {
    joins: bool,
    base: (bool, bool),
}

/// The scripts on one base, as [`Translation::scripts`] keeps them.
#[derive(Clone, Copy)]
struct Scripts {
    end: usize,
    sub: bool,
    sup: bool,
    /// Whether the last thing written is a prime, a superscript that one written right
    /// after it (`G1'²`) joins; a prime before another script, or a space, is a superscript
    /// of its own.
    primed: bool,
}

impl<'a> Translation<'a> {
    fn new(toks: &'a [Tok], prose: &'a [bool]) -> Self {
        Translation {
            toks,
            prose,
            k: 0,
            out: String::new(),
            braces: Vec::new(),
            next_group: None,
            subscript_end: None,
            scripts: None,
        }
    }

    /// The LaTeX of the whole formula, with every brace closed.
    fn run(mut self) -> String {
        let toks = self.toks;
        while self.k < toks.len() {
            match &toks[self.k] {
                Tok::Space => self.space(),
                Tok::Word(w, _) if self.prose[self.k] => self.prose_run(w),
                Tok::Word(w, d) => self.word(w, d),
                // A script digit with an accent over it (`²̄`) is a symbol of its own: the
                // run of digits takes plain ones only, and would not move past it.
                Tok::Char(c, None)
                    if SUPERSCRIPTS.contains(*c) || *c == '⁻' || SUBSCRIPTS.contains(*c) =>
                {
                    // The run of digits ends at the token after it, where the next one starts.
                    self.script_digits(*c);
                    continue;
                }
                Tok::Char(c, accent) => self.character(*c, *accent),
                Tok::Name(latex) => self.name(latex),
            }
            self.k += 1;
        }
        // Close anything left open so the output always balances.
        while let Some(brace) = self.braces.pop() {
            self.out.push_str(if brace.group { "}" } else { "" });
        }
        resolve(&self.out).trim_end().to_string()
    }

    /// A run of spaces: one space, or `\ ` beside prose, whose spaces math mode would drop.
    fn space(&mut self) {
        // A space at the end is dropped: trimmed, `\ ` would leave a backslash that escapes
        // whatever follows the formula (its closing `$`).
        if self.k + 1 >= self.toks.len() {
            return;
        }
        let before = self.k > 0 && self.prose[self.k - 1];
        let after = self.prose.get(self.k + 1) == Some(&true);
        // `cos θ` is `\cos\theta`, as the expression printer writes it (`\cos a` keeps its
        // space, which the separator after `\cos` writes).
        let function = self.k > 0
            && matches!(&self.toks[self.k - 1], Tok::Word(w, d)
                if d.is_empty() && FUNCTIONS.iter().any(|f| f.0 == w && !f.1.ends_with('}')));
        let letter = match &self.toks[self.k + 1] {
            Tok::Char(c, None) => trigpoly::greek_latex(*c).is_some() || matches!(c, 'ħ' | 'ℓ'),
            Tok::Name(latex) => latex.starts_with('\\'),
            _ => false,
        };
        if function && letter && !after {
            return;
        }
        if before || after {
            if self.out.ends_with(' ') {
                self.out.pop();
            }
            self.out.push_str(r"\ ");
        } else if !self.out.ends_with(' ') {
            self.out.push(' ');
        }
    }

    /// A run of prose words from `first`, the one at hand, merged into one `\text{…}`.
    fn prose_run(&mut self, first: &str) {
        let toks = self.toks;
        let mut words = vec![first.to_string()];
        while toks.get(self.k + 1) == Some(&Tok::Space) && self.prose.get(self.k + 2) == Some(&true)
        {
            if let Tok::Word(w2, _) = &toks[self.k + 2] {
                words.push(w2.clone());
            }
            self.k += 2;
        }
        self.out.push_str(&format!(r"\text{{{}}}", words.join(" ")));
    }

    /// A word of mathematics: a function's command or a name, with its `digits` as its
    /// subscript (`G1` is `G_{1}`).
    fn word(&mut self, w: &str, digits: &str) {
        // A text's `sqrt(x² + y²)` (as a message quotes a root) is the root the paper writes,
        // `\sqrt{x^{2} + y^{2}}` (it was `\operatorname{sqrt}(x^{2} + y^{2})`), as the echo's
        // `√(x² + y²)` is.
        if w == "sqrt" && digits.is_empty() {
            if let Some((radicand, taken)) = self.group(self.k + 1) {
                self.out.push_str(&format!(r"\sqrt{{{radicand}}}"));
                self.k += taken;
                return;
            }
        }
        match FUNCTIONS.iter().find(|f| f.0 == w) {
            Some(f) => push_cmd(&mut self.out, f.1),
            None => self.out.push_str(w),
        }
        if !digits.is_empty() {
            self.out.push_str(&format!("_{{{digits}}}"));
            self.subscript_end = Some(self.out.len());
            self.close_script(false, (false, false));
        }
    }

    /// A declared name's LaTeX: a base whose scripts are its own (`G_{1}'`, a subscript and a
    /// prime), and after a control word a space, so that a letter after it cannot extend it.
    fn name(&mut self, latex: &str) {
        self.out.push_str(latex);
        let end = self.out.len();
        let tail = latex.rsplit('\\').next().unwrap_or("");
        if latex.contains('\\') && !tail.is_empty() && tail.chars().all(|c| c.is_ascii_alphabetic())
        {
            self.out.push(SEPARATOR);
        }
        // A prime before the name's end is a superscript of its own (`P'_{1,1}`, whose square
        // is `P'_{1,1}{}^{2}`); primes at the end are one that a superscript joins (`L'^{2}`).
        let mut depth = 0i32;
        let (mut sub, mut sup) = (false, false);
        for c in latex.trim_end_matches('\'').chars() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                '_' if depth == 0 => sub = true,
                '^' | '\'' if depth == 0 => sup = true,
                _ => {}
            }
        }
        self.subscript_end = None;
        self.scripts = Some(Scripts {
            end,
            sub,
            sup,
            primed: latex.ends_with('\''),
        });
    }

    /// One character, with the `accent` over it, other than a script digit: a brace, a script
    /// sign, a letter of a name or a symbol.
    fn character(&mut self, c: char, accent: Option<&'static str>) {
        match c {
            '{' => self.open_brace(),
            '}' => self.close_brace(),
            // An exponent of more than one piece is braced whole: a parenthesized group as
            // the echo writes it, `(x² + y²)^(3/2)` and `x^(1 + 1)`, without its parentheses,
            // a signed one, `x^-1`, and a power, `x^2^3` (`x^{(}1 + 1)`, `x^{-}1` and
            // `x^{2}{}^{3}` took only the first character).
            '^' if let Some((exponent, taken)) = self.exponent(self.k + 1) => {
                let base = self.open_script(true);
                self.out.push_str(&format!("^{{{exponent}}}"));
                self.close_script(true, base);
                self.k += taken;
            }
            '_' | '^' => self.script(c),
            // A root of a group in parentheses, as the echo writes a radicand, is `\sqrt{…}`
            // (it was `\surd (x^{2} + y^{2})`); a lone `√` stays `\surd`.
            '√' if let Some((radicand, taken)) =
                self.group(self.k + 1).filter(|_| accent.is_none()) =>
            {
                self.out.push_str(&format!(r"\sqrt{{{radicand}}}"));
                self.k += taken;
            }
            // A prime is a superscript to TeX: after one it starts from an empty base, and a
            // subscript after it counts the base's (`x_a'_b` is a double subscript). A
            // superscript right after it joins it (`G1'²`).
            '\'' if accent.is_none() => {
                let mut base = self.scripts.filter(|&s| self.ends_at(s));
                // Primes in a row are one superscript (`x''`).
                let in_a_row = base.is_some_and(|s| s.primed && s.end == self.out.len());
                if base.is_some_and(|s| s.sup || (s.primed && !in_a_row)) {
                    self.out.push_str("{}");
                    base = None;
                }
                self.out.push('\'');
                self.scripts = Some(Scripts {
                    end: self.out.len(),
                    sub: base.is_some_and(|s| s.sub),
                    sup: false,
                    primed: true,
                });
            }
            _ if trigpoly::greek_latex(c).is_some() || c == 'ħ' || c == 'ℓ' => {
                self.letter_with_digits(c, accent)
            }
            _ => push_char(&mut self.out, c, accent),
        }
    }

    /// An opening brace: the group of a script, or of a second subscript that joins the last
    /// one, else an escaped brace.
    fn open_brace(&mut self) {
        let next = self.next_group.take();
        if let Some(NextGroup { joins: true, base }) = next {
            self.braces.push(Brace {
                group: true,
                subscript: true,
                base,
            });
            // The subscript stays open until this group closes: nothing joins it before.
            self.subscript_end = None;
            return;
        }
        let group = self.out.ends_with('_') || self.out.ends_with('^');
        self.braces.push(Brace {
            group,
            subscript: self.out.ends_with('_'),
            base: next.map_or((false, false), |g| g.base),
        });
        self.out.push_str(if group { "{" } else { r"\{" });
    }

    /// A closing brace: the end of a script's group, else an escaped brace.
    fn close_brace(&mut self) {
        match self.braces.pop() {
            Some(Brace {
                group: true,
                subscript,
                base,
            }) => {
                self.out.push('}');
                if subscript {
                    self.subscript_end = Some(self.out.len());
                }
                self.close_script(!subscript, base);
            }
            _ => self.out.push_str(r"\}"),
        }
    }

    /// The script sign `c`, `_` or `^`, and the unbraced script after it, braced; a subscript
    /// right after another joins it.
    fn script(&mut self, c: char) {
        let join = c == '_' && self.subscript_end == Some(self.out.len());
        let end_before = self.out.len();
        let base = match join {
            true => {
                self.out.pop();
                self.out.push(';');
                None
            }
            false => {
                let base = self.open_script(c == '^');
                self.out.push(c);
                Some(base)
            }
        };
        let pieces = self.script_pieces(c);
        let group_follows = self.toks.get(self.k + 1) == Some(&Tok::Char('{', None));
        match (join, pieces.is_empty()) {
            // A group follows, which the brace opens, and which adds to the base's scripts
            // when it closes; a sign with nothing after it takes an empty script (LaTeX
            // refuses `x^` at the end of a formula).
            (false, true) if group_follows => {
                self.next_group = Some(NextGroup {
                    joins: false,
                    base: base.unwrap_or_default(),
                });
            }
            (false, true) => self.out.push_str("{}"),
            (false, false) => self.out.push_str(&format!("{{{pieces}}}")),
            (true, false) => self.out.push_str(&format!("{pieces}}}")),
            (true, true) if group_follows => {
                // The group continues the subscript it joins, on the same base.
                let base = self
                    .scripts
                    .filter(|s| s.end == end_before)
                    .map_or((true, false), |s| (s.sub, s.sup));
                self.next_group = Some(NextGroup { joins: true, base });
            }
            (true, true) => self.out.push('}'),
        }
        if c == '_' && !pieces.is_empty() {
            self.subscript_end = Some(self.out.len());
        }
        if let Some(base) = base.filter(|_| !(pieces.is_empty() && group_follows)) {
            self.close_script(c == '^', base);
        }
        if join {
            self.extend_scripts(end_before);
        }
    }

    /// After a subscript that joined the last one (which ended at `end_before`): the base's
    /// scripts end where the joined group now does.
    fn extend_scripts(&mut self, end_before: usize) {
        let end = self.out.len();
        if let Some(s) = self.scripts.as_mut().filter(|s| s.end == end_before) {
            s.end = end;
        }
    }

    /// Before a script sign (a superscript when `sup`): the scripts the base already has,
    /// `(sub, sup)`, or, when it has one of this kind, `{}` written to start an empty base.
    fn open_script(&mut self, sup: bool) -> (bool, bool) {
        match self.scripts {
            Some(s) if self.ends_at(s) => {
                let joins_prime = s.primed && sup && s.end == self.out.len();
                let has_sup = s.sup || (s.primed && !joins_prime);
                if (sup && has_sup) || (!sup && s.sub) {
                    self.out.push_str("{}");
                    (false, false)
                } else {
                    (s.sub, has_sup)
                }
            }
            _ => (false, false),
        }
    }

    /// Whether `out` ends where the `scripts` do, but for spaces: TeX reads none in math, so
    /// `x^{1} ^{2}` is a double script too.
    fn ends_at(&self, scripts: Scripts) -> bool {
        scripts.end == self.out.trim_end_matches([' ', SEPARATOR]).len()
    }

    /// After a script (a superscript when `sup`) on a base that had the scripts `base`.
    fn close_script(&mut self, sup: bool, (sub_before, sup_before): (bool, bool)) {
        self.scripts = Some(Scripts {
            end: self.out.len(),
            sub: sub_before || !sup,
            sup: sup_before || sup,
            primed: false,
        });
    }

    /// The LaTeX of the unbraced script after the sign `c`, its pieces separated by commas.
    /// `p_x`, `a_ij`, `A^m`: an unbraced script takes a run of letters; a name with more
    /// scripts, `p_x_0` or `P_1_1`, takes them as one subscript, `p_{x,0}` (LaTeX refuses a
    /// double subscript).
    fn script_pieces(&mut self, c: char) -> String {
        let toks = self.toks;
        let mut pieces = Vec::new();
        while let Some((piece, taken)) = script_piece(&toks[self.k + 1..]) {
            pieces.push(piece);
            self.k += taken;
            if c != '_' || toks.get(self.k + 1) != Some(&Tok::Char('_', None)) {
                break;
            }
            if script_piece(&toks[self.k + 2..]).is_none() {
                break;
            }
            self.k += 1;
        }
        pieces.join(",")
    }

    /// A run of superscript digits (and `⁻`), `x⁻²`, or of subscript digits, `q₁`, that starts
    /// with `c` at the token at hand, up to the token after it; a subscript right after
    /// another joins it.
    fn script_digits(&mut self, c: char) {
        let toks = self.toks;
        let sup = !SUBSCRIPTS.contains(c);
        let mut run = String::new();
        while let Some(Tok::Char(c2, None)) = toks.get(self.k) {
            let digit = if sup {
                SUPERSCRIPTS.chars().position(|d| d == *c2)
            } else {
                SUBSCRIPTS.chars().position(|d| d == *c2)
            };
            match (digit, *c2 == '⁻' && sup) {
                (Some(d), _) => run.push_str(&d.to_string()),
                (None, true) => run.push('-'),
                _ => break,
            }
            self.k += 1;
        }
        match sup || self.subscript_end != Some(self.out.len()) {
            true => {
                let base = self.open_script(sup);
                self.out
                    .push_str(&format!("{}{{{run}}}", if sup { '^' } else { '_' }));
                self.close_script(sup, base);
            }
            false => {
                let end_before = self.out.len();
                self.out.pop();
                self.out.push_str(&format!(";{run}}}"));
                self.extend_scripts(end_before);
            }
        }
        if !sup {
            self.subscript_end = Some(self.out.len());
        }
    }

    /// The LaTeX of an exponent of more than one piece at the token `at`, after a `^`, and how
    /// many tokens it takes: a group in parentheses (translated on its own, without them), a
    /// sign before an exponent, or a piece with a power after it (`2^3`, a power being right
    /// associative); `None` for a single piece, which [`Self::script`] takes as before.
    fn exponent(&self, at: usize) -> Option<(String, usize)> {
        let (first, taken) = self.exponent_piece(at)?;
        let after = at + taken;
        let power = match self.toks.get(after) {
            Some(Tok::Char('^', None)) => self.exponent_piece(after + 1),
            _ => None,
        };
        match power {
            Some(_) => {
                let (power, more) = self
                    .exponent(after + 1)
                    .or_else(|| script_piece(&self.toks[after + 1..]))?;
                Some((format!("{first}^{{{power}}}"), taken + 1 + more))
            }
            None if matches!(self.toks.get(at), Some(Tok::Char('(' | '-' | '−', None))) => {
                Some((first, taken))
            }
            None => None,
        }
    }

    /// A group in parentheses that opens at the token `at`, translated on its own without
    /// them, and how many tokens it takes; `None` where none opens or it does not close.
    fn group(&self, at: usize) -> Option<(String, usize)> {
        let toks = self.toks;
        if toks.get(at) != Some(&Tok::Char('(', None)) {
            return None;
        }
        let mut depth = 0usize;
        for (k, t) in toks.iter().enumerate().skip(at) {
            match t {
                Tok::Char('(', None) => depth += 1,
                Tok::Char(')', None) if depth == 1 => {
                    let inner = Translation::new(&toks[at + 1..k], &self.prose[at + 1..k]);
                    return Some((inner.run(), k + 1 - at));
                }
                Tok::Char(')', None) => depth -= 1,
                _ => {}
            }
        }
        None
    }

    /// One piece of an exponent at the token `at`: a group in parentheses, a signed piece, or
    /// what an unbraced script takes ([`script_piece`]).
    fn exponent_piece(&self, at: usize) -> Option<(String, usize)> {
        let toks = self.toks;
        match toks.get(at)? {
            Tok::Char('(', None) => self.group(at),
            Tok::Char('-' | '−', None) => {
                let (piece, taken) = self.exponent_piece(at + 1)?;
                Some((format!("-{piece}"), taken + 1))
            }
            // A name or a number; a script digit or a prime is a script of its own, which
            // a power after it would double (`x^²^a`).
            Tok::Word(..) => script_piece(&toks[at..]),
            Tok::Char(c, None)
                if c.is_ascii_digit()
                    || trigpoly::greek_latex(*c).is_some()
                    || matches!(c, 'ħ' | 'ℓ') =>
            {
                script_piece(&toks[at..]).map(|(p, k)| (p.trim_end().to_string(), k))
            }
            _ => None,
        }
    }

    /// A Greek letter, `ħ` or `ℓ`, `c`: with digits after it, it is a name, `γ1`, whose digits
    /// are its subscript as a word's are (`\gamma_{1}`, as the variable prints; `\gamma 1`
    /// read as γ times 1).
    fn letter_with_digits(&mut self, c: char, accent: Option<&'static str>) {
        let toks = self.toks;
        push_char(&mut self.out, c, accent);
        let mut digits = String::new();
        while let Some(Tok::Char(d, None)) = toks.get(self.k + 1) {
            if !d.is_ascii_digit() {
                break;
            }
            digits.push(*d);
            self.k += 1;
        }
        if !digits.is_empty() {
            self.out.push_str(&format!("_{{{digits}}}"));
            self.subscript_end = Some(self.out.len());
            self.close_script(false, (false, false));
        }
    }
}

/// The LaTeX of what an unbraced script at the start of `toks` takes, and how many tokens: a
/// name (a run of words and of Greek letters, `ħ` and `ℓ`, each with the subscript digits after
/// it as its own subscript: `p_q₁` is `p_{q_{1}}`, `p_ω₁₂` is `p_{\omega_{12}}`), a run of
/// digits, or one character other than `{`.
fn script_piece(toks: &[Tok]) -> Option<(String, usize)> {
    let lowered = |toks: &[Tok]| -> String {
        toks.iter()
            .map_while(|t| match t {
                Tok::Char(c, None) => SUBSCRIPTS.chars().position(|s| s == *c),
                _ => None,
            })
            .map(|d| d.to_string())
            .collect()
    };
    let mut out = String::new();
    let mut k = 0;
    loop {
        match toks.get(k) {
            Some(Tok::Word(w, d)) => out.push_str(&format!("{w}{d}")),
            Some(Tok::Char(c, None))
                if trigpoly::greek_latex(*c).is_some() || matches!(c, 'ħ' | 'ℓ') =>
            {
                push_char(&mut out, *c, None);
            }
            // Subscript digits right after `_` (`x_₁`) are the subscript's digits.
            Some(Tok::Char(c, None)) if k == 0 && SUBSCRIPTS.contains(*c) => {
                out = lowered(toks);
                k = out.len();
                continue;
            }
            _ => break,
        }
        k += 1;
        let digits = lowered(&toks[k..]);
        if !digits.is_empty() {
            out = format!("{}_{{{digits}}}", out.trim_end());
            k += digits.len();
        }
        // One name: a Latin word and a Greek letter after it, or a Greek letter and a word,
        // are names run together (`p_θt` is `p_θ t`, which was `p_{\theta t}`); a name that
        // mixes them is one where the system declares it ([`Names`]).
        break;
    }
    if k > 0 {
        return Some((out, k));
    }
    match toks.first()? {
        Tok::Char(c, None) if c.is_ascii_digit() && !matches!(toks.get(1), Some(Tok::Word(..))) => {
            let digits: String = toks
                .iter()
                .map_while(|t| match t {
                    Tok::Char(c, None) if c.is_ascii_digit() => Some(*c),
                    _ => None,
                })
                .collect();
            let taken = digits.len();
            Some((digits, taken))
        }
        // A closing brace ends a group; it is no script (`x_}` was `x_{}}`, unbalanced).
        Tok::Char(c, acc) if !matches!(c, '{' | '}' | '_' | '^') => {
            let mut out = String::new();
            push_char(&mut out, *c, *acc);
            Some((out, 1))
        }
        _ => None,
    }
}

/// Accented Latin letters, by the LaTeX accent command that writes them: the letters and, in
/// the same order, their bases (`é` is `\'{e}`).
const TEXT_ACCENTED: &[(&str, &str, &str)] = &[
    ("`", "ÀÈÌÒÙàèìòù", "AEIOUaeiou"),
    ("'", "ÁÉÍÓÚÝáéíóúýĆćĹĺŃńŔŕŚśŹź", "AEIOUYaeiouyCcLlNnRrSsZz"),
    ("^", "ÂÊÎÔÛâêîôûĈĉĜĝĤĥĴĵŜŝŴŵŶŷ", "AEIOUaeiouCcGgHhJjSsWwYy"),
    ("~", "ÃÑÕãñõĨĩŨũ", "ANOanoIiUu"),
    ("\"", "ÄËÏÖÜäëïöüÿŸ", "AEIOUaeiouyY"),
    ("r", "ÅåŮů", "AaUu"),
    ("c", "ÇçĢģĶķĻļŅņŖŗŞşŢţ", "CcGgKkLlNnRrSsTt"),
    ("=", "ĀāĒēĪīŌōŪū", "AaEeIiOoUu"),
    ("u", "ĂăĔĕĞğĬĭŎŏŬŭ", "AaEeGgIiOoUu"),
    ("k", "ĄąĘęĮįŲų", "AaEeIiUu"),
    (".", "ĊċĖėĠġİŻż", "CcEeGgIZz"),
    ("v", "ČčĎďĚěĽľŇňŘřŠšŤťŽž", "CcDdEeLlNnRrSsTtZz"),
    ("H", "ŐőŰű", "OoUu"),
];

/// Letters and signs of prose beyond ASCII that are no accented letter, in LaTeX text mode.
const TEXT_SIGNS: &[(char, &str)] = &[
    ('ß', r"\ss{}"),
    ('æ', r"\ae{}"),
    ('Æ', r"\AE{}"),
    ('œ', r"\oe{}"),
    ('Œ', r"\OE{}"),
    ('ø', r"\o{}"),
    ('Ø', r"\O{}"),
    ('ł', r"\l{}"),
    ('Ł', r"\L{}"),
    ('“', "``"),
    ('”', "''"),
    ('‘', "`"),
    ('…', r"\dots{}"),
    ('½', r"\ensuremath{\tfrac{1}{2}}"),
    ('¼', r"\ensuremath{\tfrac{1}{4}}"),
    ('¾', r"\ensuremath{\tfrac{3}{4}}"),
];

/// A letter of prose beyond ASCII in LaTeX text mode, in ASCII: `é` → `\'{e}`, `ß` → `\ss{}`.
fn text_letter(c: char) -> Option<String> {
    if let Some(&(_, t)) = TEXT_SIGNS.iter().find(|s| s.0 == c) {
        return Some(t.to_string());
    }
    TEXT_ACCENTED.iter().find_map(|(accent, letters, bases)| {
        let k = letters.chars().position(|l| l == c)?;
        let base = bases.chars().nth(k)?;
        // An accent over i drops its dot (`\'{\i}`), except the cedilla and the ogonek, below.
        let base = match (base, *accent) {
            ('i', "c" | "k" | ".") => "i".to_string(),
            ('i', _) => r"\i".to_string(),
            _ => base.to_string(),
        };
        Some(format!("\\{accent}{{{base}}}"))
    })
}

/// A character that LaTeX cannot set from ASCII, written by its code point as typewriter
/// text, which pdflatex sets in any mode: `中` → `\mbox{\texttt{U+4E2D}}`.
fn code_point(c: char) -> String {
    format!(r"\mbox{{\texttt{{U+{:04X}}}}}", u32::from(c))
}

fn push_char(out: &mut String, c: char, accent: Option<&'static str>) {
    let body = char_math(c).unwrap_or_else(|| code_point(c));
    match accent {
        Some(a) => out.push_str(&format!(r"\{a}{{{body}}}")),
        None => push_cmd(out, &body),
    }
}

/// Escapes prose for LaTeX text mode; mathematical characters become inline math, and hyphens
/// stay hyphens (`--laurent`, which LaTeX would set as a dash).
///
/// ```
/// use superint::render::tex::text;
/// assert_eq!(text("rank 5 & 50% of ω"), r"rank 5 \& 50\% of $\omega$");
/// assert_eq!(text("--laurent"), "-{}-laurent");
/// ```
pub fn text(s: &str) -> String {
    let mut out = String::new();
    let mut previous: Option<char> = None;
    for c in s.chars() {
        // A straight double quote opens a quotation at the start, after a space or an opening
        // bracket, and closes one elsewhere (`"Title"` was set ''Title'').
        let opens = previous.is_none_or(|p| p.is_whitespace() || matches!(p, '(' | '[' | '{'));
        previous = Some(c);
        match c {
            '{' => out.push_str(r"\{"),
            '}' => out.push_str(r"\}"),
            '_' => out.push_str(r"\_"),
            '^' => out.push_str(r"\^{}"),
            '%' | '&' | '#' | '$' => {
                out.push('\\');
                out.push(c);
            }
            '\\' => out.push_str(r"\textbackslash{}"),
            '~' => out.push_str(r"\textasciitilde{}"),
            '<' => out.push_str(r"\textless{}"),
            '>' => out.push_str(r"\textgreater{}"),
            '|' => out.push_str(r"\textbar{}"),
            '"' if opens => out.push_str("``"),
            '"' => out.push_str("''"),
            '’' => out.push('\''),
            '—' => out.push_str("---"),
            '–' => out.push_str("--"),
            '-' if out.ends_with('-') => out.push_str("{}-"),
            _ if c.is_ascii() => out.push(c),
            _ if is_combining(c) => {}
            _ if let Some(letter) = text_letter(c) => out.push_str(&letter),
            _ => out.push_str(&format!("${}$", math(&c.to_string()))),
        }
    }
    out
}

/// Prose with formulas between backticks: the formulas become inline math, and a command line
/// between backticks (an option, `--symbolic I1,I2`, or `superint …`) or the library's name of
/// an option (`SearchOptions::fixed`) typewriter text, as the user types it.
///
/// ```
/// use superint::render::tex::markup;
/// assert_eq!(markup("adds `p_θ²/(2I)` to H"), r"adds $p_{\theta}^{2}/(2I)$ to H");
/// assert_eq!(markup("keep (`--fix I1=2`)"), r"keep (\texttt{-{}-fix I1=2})");
/// assert_eq!(markup("(`SearchOptions::fixed`)"), r"(\texttt{SearchOptions::fixed})");
/// ```
pub fn markup(s: &str) -> String {
    markup_with(s, &Names::default())
}

/// [`markup`] with the names of a system written as its expressions write them ([`Names`]).
pub fn markup_with(s: &str, names: &Names) -> String {
    s.split('`')
        .enumerate()
        .map(|(k, part)| {
            if k % 2 == 1 && is_command_line(part) {
                format!(r"\texttt{{{}}}", text(part))
            } else if k % 2 == 1 {
                // An empty formula is no `$$`, which TeX reads as display math.
                match math_with(part, names) {
                    m if m.is_empty() => String::new(),
                    m => format!("${m}$"),
                }
            } else {
                text(part)
            }
        })
        .collect()
}

/// Whether a span between backticks is a command line or code, not a formula: an option
/// (`--degree`, `--symbolic I1,I2`), a command (`superint search`) or a path of the library
/// (`ClosureOptions::degree`). In math mode `--` would be two minus signs, the space would be
/// lost and `I1` would read `I_{1}`, a name no one can type.
fn is_command_line(span: &str) -> bool {
    span.starts_with("--") || span.starts_with("superint ") || span.contains("::")
}

/// Where a statement's relation is: the byte offset of the first `=` or `≠` outside brackets
/// and parentheses, for aligning.
pub fn relation(s: &str) -> Option<usize> {
    let mut depth = 0i32;
    for (k, c) in s.char_indices() {
        match c {
            '{' | '(' | '[' => depth += 1,
            '}' | ')' | ']' => depth -= 1,
            '=' | '≠' if depth == 0 => return Some(k),
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Names that write each `(name, latex)` of `forms` so, without families.
    fn names_of(forms: &[(&str, &str)]) -> Names {
        Names {
            forms: (forms.iter())
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect(),
            families: Vec::new(),
        }
    }

    /// Every Greek letter a name may have is written as the name's LaTeX writes it, in a
    /// display that is no name too (`x(ϑ)`, `∂ϑ`, `Re ϑ`): `ϑ`, `ϱ`, `ς`, `ϖ`, `ο`, `υ` and
    /// `Υ` were written as their code points, `\mbox{\texttt{U+03D1}}`.
    #[test]
    fn every_greek_letter_of_a_name_is_written_as_the_name_writes_it() {
        for spelled in [
            "alpha", "beta", "gamma", "delta", "zeta", "eta", "theta", "iota", "kappa", "lambda",
            "mu", "nu", "xi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega", "pi", "upsilon",
            "omicron", "vartheta", "varrho", "varsigma", "varpi", "Gamma", "Delta", "Theta",
            "Lambda", "Phi", "Psi", "Omega", "Xi", "Pi", "Sigma", "Upsilon",
        ] {
            let (letter, latex) = trigpoly::display_forms(spelled).expect(spelled);
            assert_eq!(
                math(&format!("x({letter})")),
                format!("x({latex})"),
                "{spelled}"
            );
        }
        assert_eq!(math("∂ϑ"), r"\partial\vartheta");
    }

    /// A summary's parenthetical keeps its parentheses and its unit in text, each number a
    /// formula (it was `$(3$ exact $\text{checks})$`); parentheses inside a formula stay there.
    #[test]
    fn sentence_parentheses_around_words_and_numbers_are_text() {
        assert_eq!(
            sentence("3 claims: 2 proved, 1 refuted (3 exact checks, 0.01 s)"),
            "$3$ claims: $2$ proved, $1$ refuted ($3$ exact checks, $0.01$ s)"
        );
        assert_eq!(
            sentence("all as expected (0.00 s)"),
            "all as expected ($0.00$ s)"
        );
        assert_eq!(sentence("so (x + y)² = z"), "so $(x + y)^{2} = z$");
    }

    /// A claim's note sets its formulas in math (`proved for every A, B, at C = 2` was all
    /// text); a function's name before a prose word is prose, and `rank ∂(F)/∂(x)` math.
    #[test]
    fn sentence_of_a_note_sets_its_formulas_and_keeps_its_words() {
        assert_eq!(
            sentence("proved for every A, B, at C = 2"),
            "proved for every $A, B$, at $C = 2$"
        );
        assert_eq!(sentence("the rank is 3"), "the rank is $3$");
        assert_eq!(
            sentence("so rank ∂(F)/∂(x) = 1"),
            r"so $\operatorname{rank} \partial(F)/\partial(x) = 1$"
        );
        assert_eq!(
            sentence("not lifted back to the parameters (no symbolic lift)"),
            "not lifted back to the parameters (no symbolic lift)"
        );
    }

    /// A number that closes a parenthesis the formula opened is part of the formula: a
    /// tower's lemma `… = mλ(1, 0) + nλ(0, 1) = λ(m, n).` was cut into
    /// `$m\lambda(1$, $0$) $+ n\lambda(0$, $1$) $= \lambda(m, n)$`.
    #[test]
    fn sentence_keeps_a_parenthesis_the_formula_opened() {
        assert_eq!(
            sentence("and mλ_A + nλ_B = mλ(1, 0) + nλ(0, 1) = λ(m, n)."),
            r"and $m\lambda_{A} + n\lambda_{B} = m\lambda(1, 0) + n\lambda(0, 1) = \lambda(m, n)$."
        );
        assert_eq!(
            sentence("all hold (3 exact checks, 0.01 s)"),
            "all hold ($3$ exact checks, $0.01$ s)"
        );
    }

    /// The punctuation after a formula is the sentence's, outside the math: `$m, n \ge 0$,`
    /// (it was `$m, n \ge 0,$` and `$m, n \ge 0 (K = Z^{m}):$`).
    #[test]
    fn sentence_punctuation_after_a_formula_is_text() {
        assert_eq!(
            sentence("for all m, n ≥ 0, from the ladder Z:"),
            r"for all $m, n \ge 0$, from the ladder $Z$:"
        );
        assert_eq!(
            sentence("for all m ≥ 0 (K = Z^m): conserved"),
            r"for all $m \ge 0$ $(K = Z^{m})$: conserved"
        );
        assert_eq!(sentence("is x², so"), r"is $x^{2}$, so");
        // A group after a sign stays in its formula.
        assert_eq!(
            sentence("so {A^m, H} = (mλ + n) A^m for all"),
            r"so $\{A^{m}, H\} = (m\lambda + n) A^{m}$ for all"
        );
    }

    fn balanced(s: &str) -> bool {
        let mut depth = 0i32;
        let mut prev = ' ';
        for c in s.chars() {
            if prev != '\\' {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if depth < 0 {
                return false;
            }
            prev = if prev == '\\' { ' ' } else { c };
        }
        depth == 0
    }

    /// A script digit with an accent over it is a symbol of its own, and the translation
    /// moves past it: the run of digits, which takes plain ones only, looped on it for ever.
    #[test]
    fn an_accented_script_digit_is_translated_and_passed() {
        assert_eq!(math("x²̄ + 1"), r"x\bar{{}^{2}} + 1");
        assert_eq!(math("x₁̇²"), r"x\dot{{}_{1}}^{2}");
        assert_eq!(math("a⁻̂¹"), r"a\hat{{}^{-}}^{1}");
        assert!(balanced(&math("{x²̄, ₃̃}⁻̄")));
    }

    #[test]
    fn formulas_translate_like_the_paper() {
        for (u, t) in [
            ("{L, G1} = −G2", r"\{L, G_{1}\} = -G_{2}"),
            (
                "4G1² + G2² + ω²L² = (F1 − F2)²",
                r"4G_{1}^{2} + G_{2}^{2} + \omega^{2}L^{2} = (F_{1} - F_{2})^{2}",
            ),
            ("ẋ = p_x/M", r"\dot{x} = p_{x}/M"),
            ("θ̇ = p_θ/I", r"\dot{\theta} = p_{\theta}/I"),
            ("{Z̄, F1} = −iωZ̄", r"\{\bar{Z}, F_{1}\} = -i\omega\bar{Z}"),
            ("e^{−inθ}", r"e^{-in\theta}"),
            ("G1'", "G_{1}'"),
            ("a_ij", "a_{ij}"),
            ("(p_x_0/M) cos φ", r"(p_{x,0}/M) \cos\varphi"),
            ("P_1_1, Q_12_3", "P_{1,1}, Q_{12,3}"),
            ("x_0^2", "x_{0}^{2}"),
            ("x₀", "x_{0}"),
            ("p_q₁ + p_q₁₂", "p_{q_{1}} + p_{q_{12}}"),
            ("ħ q", r"\hbar q"),
            ("ω⁻¹²", r"\omega^{-12}"),
            ("e^{−inθ} for all", r"e^{-in\theta}\ \text{for all}"),
            ("exp(−inθ)", r"\exp(-in\theta)"),
            (
                "Re(A_x⁵Ā_y³)",
                r"\operatorname{Re}(A_{x}^{5}\bar{A}_{y}^{3})",
            ),
            ("cos θ", r"\cos\theta"),
            // A Greek letter, ħ or ℓ in a script takes its subscript digits, as a word does.
            ("{ω₁₂, p_ω₁₂} = 1", r"\{\omega_{12}, p_{\omega_{12}}\} = 1"),
            (
                "p_ℓ₁ + p_ħ₁ + p_θ₁₂",
                r"p_{\ell_{1}} + p_{\hbar_{1}} + p_{\theta_{12}}",
            ),
            // Names run together in a script are a product; a name that mixes Latin and
            // Greek letters is one where the system declares it (`Names`).
            ("p_ωx + p_xω", r"p_{\omega}x + p_{x}\omega"),
            // Digits after a Greek letter are its subscript, as after a word (`G1`).
            (
                "{γ1, H} = M2 γ3 − 2c ω12",
                r"\{\gamma_{1}, H\} = M_{2} \gamma_{3} - 2c \omega_{12}",
            ),
            ("x_₁ + x_₁₂y", "x_{1} + x_{12y}"),
            // A family named with a subscript of its own: its indices join it after `;`.
            ("K₁_{1,2} + K1_{3,4}", "K_{1;1,2} + K_{1;3,4}"),
            ("K_a_{m,n} = K̄_{m,n}", r"K_{a;m,n} = \bar{K}_{m,n}"),
            ("K₁_1_2, x₁₂", "K_{1;1,2}, x_{12}"),
            ("50% & #1 $", r"50\% \& \#1 \$"),
            // A half-integer power of a radicand, as the echo writes it.
            (
                "kx/(x² + y²)^(3/2) + (x² + y²)^(−1/2)",
                "kx/(x^{2} + y^{2})^{3/2} + (x^{2} + y^{2})^{-1/2}",
            ),
        ] {
            assert_eq!(math(u), t, "{u}");
            assert!(balanced(&math(u)), "{u}");
            assert!(math(u).is_ascii(), "{u}");
        }
    }

    /// A control word takes a space only where a letter or a digit follows it, which would
    /// extend it: a statement writes `M\omega^{2}` and `\cos^{2}\theta` as the expressions do
    /// (it wrote `M\omega ^{2}`, `\cos ^{2}\theta`, `p_{\theta }` and `(M\omega )`).
    #[test]
    fn a_control_word_is_spaced_only_before_a_letter() {
        for (u, t) in [
            ("Mω²(x² + y²)/2", r"M\omega^{2}(x^{2} + y^{2})/2"),
            ("cos²θ + sin θ", r"\cos^{2}\theta + \sin\theta"),
            ("p_θ/(Mω)", r"p_{\theta}/(M\omega)"),
            (
                "cos ωt + ω x + ω + 1",
                r"\cos\omega t + \omega x + \omega + 1",
            ),
            ("cos a + ħ2", r"\cos a + \hbar_{2}"),
            ("ω is α", r"\omega\ \text{is}\ \alpha"),
        ] {
            assert_eq!(math(u), t, "{u}");
        }
    }

    /// A root of a group in parentheses, as the echo writes a radicand (`r = √(x² + y²)`), is
    /// `\sqrt{…}`; it was `\surd (x^{2} + y^{2})`, a sign before parentheses.
    #[test]
    fn a_root_of_a_group_is_sqrt() {
        assert_eq!(math("r = √(x² + y²)"), r"r = \sqrt{x^{2} + y^{2}}");
        assert_eq!(math("√((x − a)² + y²)/2"), r"\sqrt{(x - a)^{2} + y^{2}}/2");
        assert_eq!(math("√2 + √(x"), r"\surd 2 + \surd(x");
        assert!(balanced(&math("√(√(x)")));
    }

    /// The paper's C06: `p_θt` is the product `p_θ t` (it was `p_{\theta t}`, a momentum of
    /// `θt`).
    #[test]
    fn names_run_together_after_a_subscript_are_a_product() {
        assert_eq!(
            math("θ(t) = θ₀ + p_θt/I"),
            r"\theta(t) = \theta_{0} + p_{\theta}t/I"
        );
        assert_eq!(math("p_θ₁t + p_xω"), r"p_{\theta_{1}}t + p_{x}\omega");
        // A Latin word in a subscript is one name, as before (`a_ij`).
        assert_eq!(math("p_xt"), "p_{xt}");
    }

    /// An exponent of more than one piece is braced whole: a group in parentheses, a signed
    /// one and a power (`x^{(}1 + 1)`, `x^{-}1` and `x^{2}{}^{3}` took only their first
    /// character).
    #[test]
    fn an_exponent_of_several_pieces_is_braced_whole() {
        for (u, t) in [
            ("x^(1 + 1)", "x^{1 + 1}"),
            ("x^(2³) = x⁸", "x^{2^{3}} = x^{8}"),
            ("x^2^3", "x^{2^{3}}"),
            ("x^-1 + r^−3", "x^{-1} + r^{-3}"),
            ("e^(iθ)", r"e^{i\theta}"),
            ("x^(n+1)y", "x^{n+1}y"),
            ("x^-(a+b)", "x^{-a+b}"),
            ("x^a^-b^(c)", "x^{a^{-b^{c}}}"),
            ("(x² + y²)^(−1/2)", "(x^{2} + y^{2})^{-1/2}"),
            ("x^(1 + 1", "x^{(}1 + 1"),
        ] {
            assert_eq!(math(u), t, "{u}");
        }
    }

    /// A system's names are written as its expressions write them, a run of letters that
    /// they spell whole as those names; prose, a function's name and any other run as before.
    #[test]
    fn declared_names_are_written_as_expressions_write_them() {
        let names = names_of(&[
            ("alpha1", r"\alpha_{1}"),
            ("ωx", r"\mathrm{{\omega}x}"),
            ("p_ωx", r"p_{{\omega}x}"),
            ("ω", r"\omega"),
            ("x", "x"),
            ("s", "s"),
            ("G1'", "G_{1}'"),
        ]);
        for (u, t) in [
            (
                "{alpha1, ωx} = 2ωx ω x",
                r"\{\alpha_{1}, \mathrm{{\omega}x}\} = 2\mathrm{{\omega}x} \omega x",
            ),
            ("p_ωx ωx²", r"p_{{\omega}x} \mathrm{{\omega}x}^{2}"),
            ("ωxx", r"\mathrm{{\omega}x}x"),
            ("G1'² + s x", "G_{1}'^{2} + s x"),
            ("x is ss", r"x\ \text{is}\ ss"),
            ("cos ω", r"\cos\omega"),
        ] {
            assert_eq!(math_with(u, &names), t, "{u}");
        }
    }

    /// A display name that holds its function's name after a differential sign, `∂L` of
    /// `L`, is spelled from its sign, once: the `L` after `∂` was read as the function again,
    /// `\partial\partial L^{2}`. A sign before a run the names do not spell with it is a
    /// character of its own, as before.
    #[test]
    fn a_differential_sign_starts_a_display_name() {
        let names = names_of(&[
            ("L", r"\partial L"),
            ("∂L", r"\partial L"),
            ("H2", r"\nabla H_{2}"),
            ("∇H2", r"\nabla H_{2}"),
            ("x", "x"),
        ]);
        for (u, t) in [
            ("∂L²", r"\partial L^{2}"),
            (
                "{∇H2², ∂L} = 2 ∂L ∇H2",
                r"\{\nabla H_{2}^{2}, \partial L\} = 2 \partial L \nabla H_{2}",
            ),
            ("(∂L + 1)²", r"(\partial L + 1)^{2}"),
            ("∂x/∂(x)", r"\partial x/\partial(x)"),
        ] {
            assert_eq!(math_with(u, &names), t, "{u}");
        }
    }

    #[test]
    fn prose_letters_beyond_ascii_are_latex_accents() {
        assert_eq!(text("Hénon–Heiles"), r"H\'{e}non--Heiles");
        assert_eq!(
            text("Über, Frič, Uhlíř"),
            r#"\"{U}ber, Fri\v{c}, Uhl\'{\i}\v{r}"#
        );
        assert_eq!(text("Straße ½"), r"Stra\ss{}e \ensuremath{\tfrac{1}{2}}");
    }

    /// A citation's straight double quotes open and close its quotation: both were `''`, so
    /// that `"Über das …"` was set with a closing quote before `Über`.
    #[test]
    fn straight_double_quotes_open_and_close() {
        assert_eq!(
            text(r#"W. Pauli, "Über das Wasserstoffspektrum", Z. Phys."#),
            r#"W. Pauli, ``\"{U}ber das Wasserstoffspektrum'', Z. Phys."#
        );
        assert_eq!(text(r#""a" ("b") x""#), "``a'' (``b'') x''");
    }

    #[test]
    fn prose_is_set_as_text() {
        assert_eq!(
            math("the bracket is a derivation, so A"),
            r"\text{the bracket is a derivation},\ \text{so}\ A"
        );
    }

    /// A formula that ends in a space after prose (a description's `` `H = p²/2 for all ` ``)
    /// ends its math: the space's `\ `, trimmed, left a backslash that escaped the `$`.
    #[test]
    fn a_trailing_space_after_prose_leaves_no_backslash() {
        assert_eq!(math("x for all "), r"x\ \text{for all}");
        assert_eq!(
            markup("a free particle, `H = p_x^2/2 for all ` of them"),
            r"a free particle, $H = p_{x}^{2}/2\ \text{for all}$ of them"
        );
    }

    /// A script plus or minus, as in the normal-mode frequencies `ω₊`, `ω₋` of
    /// `systems/fock-darwin.toml`'s description, is a script sign (it was written by its code
    /// point, `\omega\mbox{\texttt{U+208A}}`).
    #[test]
    fn script_signs_are_scripts() {
        assert_eq!(math("ω₊ − ω₋"), r"\omega{}_{+} - \omega{}_{-}");
        assert_eq!(math("e⁺"), "e{}^{+}");
        assert_eq!(
            markup("frequencies `a = ω₊`, `b = ω₋`"),
            r"frequencies $a = \omega{}_{+}$, $b = \omega{}_{-}$"
        );
    }

    /// A declared name with a script sign, the Fock–Darwin file's display `ω₊` of `a`, is
    /// written as the variable's LaTeX, `\omega_{+}`, in a statement or condition as in a
    /// printed polynomial (`\text{at } \omega{}_{+} = 2 \omega{}_{-}` beside `\omega_{+}`);
    /// a sign after a name that no declared name spells stays a script sign.
    #[test]
    fn a_declared_name_with_a_script_sign_is_written_as_the_variable() {
        let names = names_of(&[("M", "M"), ("ω₊", r"\omega_{+}"), ("ω₋", r"\omega_{-}")]);
        assert_eq!(math_with("ω₊ = 2 ω₋", &names), r"\omega_{+} = 2 \omega_{-}");
        assert_eq!(
            math_with("{P, Q} = M ω₊ + 3Mω₋²", &names),
            r"\{P, Q\} = M \omega_{+} + 3M\omega_{-}^{2}"
        );
        assert_eq!(math_with("x₊ + M₋", &names), r"x{}_{+} + M{}_{-}");
    }

    /// A formula LaTeX would refuse, as a description may hold one, is written so that the
    /// document still compiles: a second script of a kind on one base (after a space, a
    /// joined subscript or a prime too) starts from an empty base, a script sign with nothing
    /// after it takes an empty script, and an empty formula is no `$$`. (Found by compiling
    /// the LaTeX of descriptions of random characters with pdflatex: 13 of 140 failed.)
    #[test]
    fn a_formula_latex_would_refuse_is_written_so_that_it_compiles() {
        assert_eq!(math("x²^1"), "x^{2}{}^{1}");
        assert_eq!(math("x^a_b²"), "x^{a}_{b}{}^{2}");
        assert_eq!(math("G¹ ^ℓ"), r"G^{1} {}^{\ell}");
        assert_eq!(math("x²₁_a¹"), "x^{2}_{1;a}{}^{1}");
        assert_eq!(math("x⁻'"), "x^{-}{}'");
        assert_eq!(math("x^a '"), "x^{a} {}'");
        assert_eq!(math("x_a'_b"), "x_{a}'{}_{b}");
        assert_eq!(math("s2^ω_c"), r"s_{2}^{\omega}{}_{c}");
        assert_eq!(math("G'₁¹"), "G'_{1}{}^{1}");
        assert_eq!(math("Z²' ²"), "Z^{2}{}' {}^{2}");
        assert_eq!(math("x'' + x'_1"), "x'' + x'_{1}");
        assert_eq!(math("ħ_"), r"\hbar_{}");
        assert_eq!(math("x = y^"), "x = y^{}");
        assert_eq!(markup("a ` ` b"), "a  b");
        // A group adds to the scripts its base had before it.
        assert_eq!(math("x^{a}_{b}^{c}"), "x^{a}_{b}{}^{c}");
        assert_eq!(math("x_{a}^{b}_{c}"), "x_{a}^{b}{}_{c}");
        assert_eq!(math("x^{a}_b_{c}^{d}"), "x^{a}_{b;c}{}^{d}");
        assert_eq!(math("x_{a}^{b} y^{c}"), "x_{a}^{b} y^{c}");
        // What the paper writes is as it was.
        assert_eq!(math("G1'²"), "G_{1}'^{2}");
        assert_eq!(math("K₁_{1,2}"), "K_{1;1,2}");
        assert_eq!(math("p_θ²"), r"p_{\theta}^{2}");
    }

    #[test]
    fn unbalanced_input_still_balances() {
        for s in ["{x", "x}", "e^{x", "{{", "}}", "_}", "x^}", "₁_{_"] {
            assert!(balanced(&math(s)), "{s} → {}", math(s));
        }
    }

    /// The `$` signs of `s` that are not escaped (`\$`).
    fn unescaped_dollars(s: &str) -> usize {
        let mut prev = ' ';
        let mut count = 0;
        for c in s.chars() {
            if c == '$' && prev != '\\' {
                count += 1;
            }
            prev = if prev == '\\' { ' ' } else { c };
        }
        count
    }

    /// Characters of the paper's notation, with the combining accents and the script digits
    /// that ended a translation's loops before (an accent over `²`).
    const NOTATION: &[char] = &[
        'x', 'p', 'G', '1', '2', ' ', '_', '^', '{', '}', '(', ')', '/', '\'', 'ω', 'θ', 'ħ', 'ℓ',
        '²', '⁻', '¹', '₁', '₂', '\u{304}', '\u{307}', '\u{302}', '−', '=', ',', 'Z', '\\', 'a',
        'c', 'o', 's', 'e', 'i', 'n', '√',
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]

        /// Any string of the notation translates, in a time linear in its length, to LaTeX
        /// whose braces balance.
        #[test]
        fn any_formula_translates_to_balanced_latex(
            picks in proptest::collection::vec(0..NOTATION.len(), 0..24)
        ) {
            let s: String = picks.iter().map(|&k| NOTATION[k]).collect();
            let latex = math(&s);
            proptest::prop_assert!(balanced(&latex), "{s:?} → {latex}");
            let prose = sentence(&s);
            proptest::prop_assert_eq!(prose.matches('$').count() % 2, 0, "{:?} → {}", s, prose);
            // Prose with formulas between backticks, as descriptions are written.
            let marked = markup(&format!("a `{s}` and {s}"));
            proptest::prop_assert!(balanced(&marked), "{s:?} → {marked}");
            proptest::prop_assert_eq!(unescaped_dollars(&marked) % 2, 0, "{:?} → {}", s, marked);
        }
    }

    #[test]
    fn relation_skips_brackets() {
        assert_eq!(relation("{a = b} = c"), Some(8));
        assert_eq!(relation("f(x = 1)"), None);
    }
}
