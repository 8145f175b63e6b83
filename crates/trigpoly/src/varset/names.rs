//! How a variable's name is written: the reserved names, identifiers, the text and LaTeX forms
//! of a name (Greek letters spelled out or written, subscripts, bars), and the letters LaTeX
//! output cannot write.

use std::fmt;

use crate::print::write_display;

/// Names that expressions give a meaning of their own: `i` and the functions (a variable
/// named `re` made `re(x + i p)` the real part, and `re*(x + i p)` a product; one named
/// `sqrt` made `sqrt(x^2 + y^2)`, and LaTeX's `\sqrt{x^2 + y^2}`, a product).
pub const RESERVED: &[&str] = &["i", "cos", "sin", "exp", "conj", "re", "im", "sqrt"];

/// A display name as text and as LaTeX, when it is an identifier, possibly with a bar (a
/// combining macron) and primes: `A_x` → (`A_x`, `A_{x}`), `G1'` → (`G1'`, `G_{1}'`), `Z̄` →
/// (`Z̄`, `\bar{Z}`), `omega` → (`ω`, `\omega`). Anything else has no such forms.
pub fn display_forms(display: &str) -> Option<(String, String)> {
    let spelled = bars_apart(display);
    let marked = spelled.trim_end_matches('\'');
    let primes = &spelled[marked.len()..];
    let (base, bar) = match marked.strip_suffix('\u{304}') {
        Some(base) => (base, true),
        None => (marked, false),
    };
    // A bar may also end a piece before a subscript, `Z̄_x`, which [`Piece::of`] writes.
    let bars_end_pieces = base.split('_').all(|p| {
        !p.trim_end_matches('\u{304}').contains('\u{304}') && p.matches('\u{304}').count() <= 1
    });
    // A subscript sign stands after what it is written under (`ω₊`, `ω₋`), as a subscript
    // digit does.
    let unsigned: String = base
        .chars()
        .filter(|&c| c != '\u{304}' && !SUBSCRIPT_SIGNS.contains(c))
        .collect();
    let signs_follow = base
        .split('_')
        .all(|p| !p.starts_with(|c| SUBSCRIPT_SIGNS.contains(c)));
    if !bars_end_pieces || !signs_follow || !is_identifier(&unsigned) {
        return None;
    }
    let (unicode, latex) = render_name(base);
    Some(match bar {
        true => (
            format!("{unicode}\u{304}{primes}"),
            format!("\\bar{{{latex}}}{primes}"),
        ),
        false => (format!("{unicode}{primes}"), format!("{latex}{primes}")),
    })
}

/// How a display name shows, as text and as LaTeX: an identifier's forms ([`display_forms`]),
/// or those of a name of several such words or `Re`/`Im`, one space between them: `Re K` →
/// (`Re K`, `\operatorname{Re} K`), `H x` → (`H x`, `H x`). Printing sets a name of several
/// words in parentheses where something follows it ([`has_several_words`]). Either may end
/// with a family instance's indices in braces, which join a subscript of its own in LaTeX
/// ([`with_indices`]): `K̄_{1,2}` → (`K̄_{1,2}`, `\bar{K}_{1,2}`), `K1_{1,2}` → (`K1_{1,2}`,
/// `K_{1;1,2}`). Anything else (`x(t)`) has no such forms.
pub fn shown_forms(display: &str) -> Option<(String, String)> {
    if let Some((head, indices)) = instance_indices(display) {
        let (text, latex) = shown_forms(head)?;
        return Some((
            format!("{text}_{{{indices}}}"),
            with_indices(&latex, indices),
        ));
    }
    if !display.contains(' ') {
        return display_forms(display);
    }
    let (mut unicode, mut latex) = (Vec::new(), Vec::new());
    for word in display.split(' ') {
        let (text, tex) = match word {
            "Re" | "Im" => (word.to_string(), format!("\\operatorname{{{word}}}")),
            _ => display_forms(word)?,
        };
        unicode.push(text);
        latex.push(tex);
    }
    Some((unicode.join(" "), latex.join(" ")))
}

/// A display name as text prints it ([`shown_forms`]): a function's or a family's name
/// written as a variable's is, its Greek letters spelled out as the letters, `omega3` → `ω3`,
/// `Q_theta1_{1,2}` → `Q_θ1_{1,2}`, `hbar` → `ħ`; as it is where it has no such form (`x(t)`)
/// or where that form is only its letters with a bar taken apart (`Ā_y`, which the form
/// writes as `A` and a combining bar).
///
/// ```
/// use trigpoly::shown_text;
///
/// assert_eq!(shown_text("omega3"), "ω3");
/// assert_eq!(shown_text("Q_theta1_{1,2}"), "Q_θ1_{1,2}");
/// assert_eq!(shown_text("Ā_y"), "Ā_y");
/// assert_eq!(shown_text("x(t)"), "x(t)");
/// ```
pub fn shown_text(display: &str) -> String {
    match shown_forms(display) {
        Some((text, _)) => shown_text_of(display, text),
        None => display.to_string(),
    }
}

/// [`shown_text`] of `display`, whose [`shown_forms`] text is `text`: `text`, or the display
/// as written where `text` is only its letters with a bar taken apart.
pub(super) fn shown_text_of(display: &str, text: String) -> String {
    if text == bars_apart(display) {
        display.to_string()
    } else {
        text
    }
}

/// A display name that ends with a family instance's two indices in braces, split there:
/// `K̄_{1,2}` → (`K̄`, `1,2`), `K_{m,n}` → (`K`, `m,n`); `None` for any other (`K_{1}`).
fn instance_indices(display: &str) -> Option<(&str, &str)> {
    let (head, inner) = display.strip_suffix('}')?.rsplit_once("_{")?;
    let (m, n) = inner.split_once(',')?;
    let index = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric());
    (!head.is_empty() && index(m) && index(n)).then_some((head, inner))
}

/// The LaTeX of a name followed by a family instance's `indices` (`1,2`): as a subscript
/// after it, `\bar{K}_{1,2}`, `P'_{1,2}`, or after `;` in the subscript it ends with, primes
/// aside (`K_{1}` → `K_{1;1,2}`, `K_{1}'` → `K_{1;1,2}'`: LaTeX refuses a double subscript).
pub fn with_indices(latex: &str, indices: &str) -> String {
    let bare = latex.trim_end_matches('\'');
    let primes = &latex[bare.len()..];
    match own_subscript(bare) {
        Some(own) => format!(
            "{}{own};{indices}}}{primes}",
            &bare[..bare.len() - own.len() - 1]
        ),
        None => format!("{latex}_{{{indices}}}"),
    }
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

/// Whether a printed name is of several words (`Re K`, `H x`, `ω (x)`), which a power, a
/// factor or a denominator after it would seem to reach into (`Re K²`): printing sets it in
/// parentheses there. A name enclosed whole, a denominator atom's `(x − y)`, is not.
pub fn has_several_words(name: &str) -> bool {
    name.contains(' ') && unparenthesized(name).is_none()
}

/// `name` without the parentheses that enclose it whole, `(x - y)` → `x - y`; `None` for a
/// name that they do not (`(a)(b)`, `x`).
pub(crate) fn unparenthesized(name: &str) -> Option<&str> {
    let inner = name.strip_prefix('(')?.strip_suffix(')')?;
    let mut depth = 0i32;
    for c in inner.chars() {
        depth += match c {
            '(' => 1,
            ')' => -1,
            _ => 0,
        };
        if depth < 0 {
            return None;
        }
    }
    (depth == 0).then_some(inner)
}

/// `name` with each precomposed bar written as its letter and a combining one (`Ā` as `A`
/// and U+0304), as LaTeX's `\bar{A}` reads: one spelling of a barred name however typed.
pub(crate) fn bars_apart(name: &str) -> String {
    (name.chars())
        .flat_map(|c| match unbarred(c) {
            Some(base) => [base, '\u{304}'].into_iter().take(2),
            None => [c, c].into_iter().take(1),
        })
        .collect()
}

/// The name under the one bar of `name`, precomposed or combining, however typed (`P_3_2` of
/// `P̄_3_2`, of `\bar{P}_{3,2}` as read, and of `P` and U+0304 then `_3_2`), where it has
/// exactly one: the name whose conjugate a paper writes so.
pub fn under_one_bar(name: &str) -> Option<String> {
    let bare = bars_apart(name);
    (bare.matches('\u{304}').count() == 1).then(|| bare.replacen('\u{304}', "", 1))
}

/// The letter under a precomposed bar, `Ā` → `A`, which a display name may have as `A` and a
/// combining macron (U+0304).
pub fn unbarred(c: char) -> Option<char> {
    const BARRED: &str = "ĀāĒēĪīŌōŪūȲȳ";
    let k = BARRED.chars().position(|b| b == c)?;
    "AaEeIiOoUuYy".chars().nth(k)
}

/// Whether `s` can name a variable or a function: letters, digits and `_`, not starting with
/// a digit.
pub fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_alphabetic() || c == '_')
        && chars.all(|c| c.is_alphanumeric() || c == '_')
}

/// The most characters a name has ([`BadName::TooLong`]).
pub const MAX_NAME_CHARS: usize = 80;

/// A name past [`MAX_NAME_CHARS`] as a message shows it: its first half as many characters,
/// and its length; `None` for a name within the limit, which is shown whole.
pub(crate) fn long_name(name: &str) -> Option<(String, usize)> {
    let n = name.chars().count();
    (n > MAX_NAME_CHARS).then(|| (name.chars().take(MAX_NAME_CHARS / 2).collect(), n))
}

/// Why a name cannot name a variable of any set: the one rule that
/// [`VarsBuilder::build`](crate::VarsBuilder::build) applies, and that a program reading
/// names (superint's system-file loader) applies before its own refusals. Its `Display` is the
/// reason in words.
///
/// ```
/// use trigpoly::BadName;
/// assert_eq!(BadName::of("p_x"), None);
/// assert_eq!(BadName::of("2Q"), Some(BadName::Malformed));
/// assert_eq!(BadName::of(&"a".repeat(81)), Some(BadName::TooLong));
/// assert_eq!(BadName::of("a__b"), Some(BadName::EmptySubscript));
/// assert_eq!(BadName::of("é"), Some(BadName::Unwritable('é')));
/// assert_eq!(BadName::of("cos"), Some(BadName::Reserved));
/// assert_eq!(
///     BadName::of("cos").unwrap().to_string(),
///     "i, cos, sin, exp, conj, re, im and sqrt are reserved"
/// );
/// // It is an error, so that `?` takes it into a program's own.
/// fn check(name: &str) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
///     BadName::of(name).map_or(Ok(()), Err)?;
///     Ok(())
/// }
/// assert!(check("p_x").is_ok());
/// assert_eq!(
///     check("a__b").unwrap_err().to_string(),
///     "a name cannot begin or end in '_' or hold '__'"
/// );
/// ```
///
/// The rule may refuse more kinds of name later, each a new variant, so a program's `match`
/// has an arm for the others (here the reason in words); one without it does not compile:
///
/// ```
/// use trigpoly::BadName;
/// fn advice(bad: BadName) -> String {
///     match bad {
///         BadName::TooLong => "shorten it".into(),
///         BadName::Reserved => "choose another name".into(),
///         other => format!("rename it: {other}"),
///     }
/// }
/// assert_eq!(advice(BadName::TooLong), "shorten it");
/// assert!(advice(BadName::Malformed).starts_with("rename it: a name is letters, digits"));
/// ```
///
/// ```compile_fail,E0004
/// use trigpoly::BadName;
/// fn advice(bad: BadName) -> &'static str {
///     match bad {
///         BadName::Malformed => "use letters, digits and '_'",
///         BadName::TooLong => "shorten it",
///         BadName::EmptySubscript => "fill the subscript",
///         BadName::Unwritable(_) => "use letters LaTeX writes",
///         BadName::Reserved => "choose another name",
///     }
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum BadName {
    /// Not letters, digits and `_` starting with a letter (or `_`, [`BadName::EmptySubscript`]):
    /// [`is_identifier`] fails.
    Malformed,
    /// Longer than [`MAX_NAME_CHARS`]: every message and report prints a name, and one past
    /// it is a mistake (a line pasted where a name belongs).
    TooLong,
    /// Beginning or ending in `_` or holding `__` (`_a`, `a_`, `_`, `a__b`): each `_` starts a
    /// subscript, so that such a name has an empty one or one of nothing, which LaTeX writes
    /// as `x_{}` (printed as `x`), `\mathrm{_a}` (a lone subscript `a`) or not at all.
    EmptySubscript,
    /// A character LaTeX output could not write ([`latex_unwritable`]): such a name would stop
    /// `pdflatex`.
    Unwritable(char),
    /// One of [`RESERVED`], which expressions give a meaning of their own.
    Reserved,
}

impl BadName {
    /// The first reason `name` is refused, if any: malformed, too long, an empty subscript, a
    /// letter LaTeX cannot write, reserved.
    pub fn of(name: &str) -> Option<BadName> {
        if !is_identifier(name) {
            Some(BadName::Malformed)
        } else if name.chars().count() > MAX_NAME_CHARS {
            Some(BadName::TooLong)
        } else if name.starts_with('_') || name.ends_with('_') || name.contains("__") {
            Some(BadName::EmptySubscript)
        } else if let Some(c) = latex_unwritable(name) {
            Some(BadName::Unwritable(c))
        } else if RESERVED.contains(&name) {
            Some(BadName::Reserved)
        } else {
            None
        }
    }
}

impl fmt::Display for BadName {
    /// The reason: `a name is letters, …`, `LaTeX has no letter 'é' (…)`; a character other
    /// than a letter (a mark over a letter, a sign, one that prints nothing) is said by its
    /// code point.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BadName::Malformed => {
                f.write_str("a name is letters, digits and '_', starting with a letter")
            }
            BadName::TooLong => write!(f, "a name has at most {MAX_NAME_CHARS} characters"),
            BadName::EmptySubscript => {
                f.write_str("a name cannot begin or end in '_' or hold '__'")
            }
            BadName::Unwritable(c) if c.is_alphabetic() => {
                write!(f, "LaTeX has no letter '{c}' ({LATEX_LETTERS})")
            }
            BadName::Unwritable(c) => {
                write!(
                    f,
                    "LaTeX has no letter U+{:04X} ({LATEX_LETTERS})",
                    *c as u32
                )
            }
            BadName::Reserved => {
                // The list as RESERVED has it: `i, cos, …, im and sqrt are reserved`.
                let (rest, last) = RESERVED.split_at(RESERVED.len() - 1);
                write!(f, "{} and {} are reserved", rest.join(", "), last[0])
            }
        }
    }
}

/// The reason as an error, with no source: a program that checks names of its own may return
/// it with `?`.
impl std::error::Error for BadName {}

const GREEK: &[(&str, &str, &str)] = &[
    ("alpha", "α", r"\alpha"),
    ("beta", "β", r"\beta"),
    ("gamma", "γ", r"\gamma"),
    ("delta", "δ", r"\delta"),
    // `\varepsilon`, the letter `ε` the text prints; `\epsilon` sets the lunate `ϵ`.
    ("epsilon", "ε", r"\varepsilon"),
    ("zeta", "ζ", r"\zeta"),
    ("eta", "η", r"\eta"),
    ("theta", "θ", r"\theta"),
    ("iota", "ι", r"\iota"),
    ("kappa", "κ", r"\kappa"),
    ("lambda", "λ", r"\lambda"),
    ("mu", "μ", r"\mu"),
    ("nu", "ν", r"\nu"),
    ("xi", "ξ", r"\xi"),
    ("rho", "ρ", r"\rho"),
    ("sigma", "σ", r"\sigma"),
    ("tau", "τ", r"\tau"),
    ("phi", "φ", r"\varphi"),
    ("chi", "χ", r"\chi"),
    ("psi", "ψ", r"\psi"),
    ("omega", "ω", r"\omega"),
    ("pi", "π", r"\pi"),
    ("upsilon", "υ", r"\upsilon"),
    // LaTeX has no omicron but the italic o, which `\mathit` sets apart from a name `o`
    // (a bare `o` read back as that name, or as none).
    ("omicron", "ο", r"\mathit{o}"),
    ("vartheta", "ϑ", r"\vartheta"),
    ("varrho", "ϱ", r"\varrho"),
    ("varsigma", "ς", r"\varsigma"),
    ("varpi", "ϖ", r"\varpi"),
    ("Gamma", "Γ", r"\Gamma"),
    ("Delta", "Δ", r"\Delta"),
    ("Theta", "Θ", r"\Theta"),
    ("Lambda", "Λ", r"\Lambda"),
    ("Phi", "Φ", r"\Phi"),
    ("Psi", "Ψ", r"\Psi"),
    ("Omega", "Ω", r"\Omega"),
    ("Xi", "Ξ", r"\Xi"),
    ("Pi", "Π", r"\Pi"),
    ("Sigma", "Σ", r"\Sigma"),
    ("Upsilon", "Υ", r"\Upsilon"),
];

/// The LaTeX command of a Greek letter as a name writes it (`ω` → `\omega`, `φ` →
/// `\varphi`, `ϑ` → `\vartheta`); `None` for a character that is no Greek letter of a name.
pub fn greek_latex(letter: char) -> Option<&'static str> {
    GREEK.iter().find(|g| g.1.chars().eq([letter])).map(|g| g.2)
}

/// The letter a LaTeX command writes in a name (`omega` of `\omega` → `ω`, `varphi` → `φ`,
/// `hbar` → `ħ`), as the expressions' names spell it; `None` for a command that is no letter.
/// Both of the forms LaTeX has for epsilon, phi and theta are taken, whichever one a paper
/// uses.
pub(crate) fn letter_of_command(command: &str) -> Option<&'static str> {
    match command {
        // The forms of phi and epsilon that the table, which prints `\varphi` and
        // `\varepsilon`, does not.
        "phi" => Some("φ"),
        "epsilon" => Some("ε"),
        _ => named_letters()
            .find(|g| g.2.strip_prefix('\\') == Some(command))
            .map(|g| g.1),
    }
}

/// The letter a name reads `c` as: the lunate epsilon `ϵ` and the curly phi `ϕ`, which
/// LaTeX sets for `\epsilon` and `\phi`, are the letters `ε` and `φ` (as both of LaTeX's forms
/// are, [`letter_of_command`]), which a name declares and the output prints; any other
/// character is itself.
pub(crate) fn letter_of_char(c: char) -> char {
    match c {
        'ϵ' => 'ε',
        'ϕ' => 'φ',
        c => c,
    }
}

/// A unicode name with its Greek letters spelled out, piece by piece between underscores and
/// before trailing digits: `p_θ` → `p_theta`, `ω1` → `omega1`, `Ω_x` → `Omega_x`; `None` for an
/// ASCII name, which has none.
pub(super) fn spell_out(unicode: &str) -> Option<String> {
    if unicode.is_ascii() {
        return None;
    }
    let piece = |p: &str| -> String {
        let letters = p.trim_end_matches(|c: char| c.is_ascii_digit());
        match named_letters().find(|(_, uni, _)| *uni == letters) {
            Some((ascii, _, _)) => format!("{ascii}{}", &p[letters.len()..]),
            None => p.to_string(),
        }
    };
    Some(unicode.split('_').map(piece).collect::<Vec<_>>().join("_"))
}

/// `omega_x` → (`ω_x`, `\omega_{x}`); `p_theta` → (`p_θ`, `p_{\theta}`); `G1` → (`G1`, `G_{1}`);
/// `q₁` → (`q₁`, `q_{1}`); `ħ` and `hbar` → (`ħ`, `\hbar`). The LaTeX is ASCII unless the name has a letter
/// of no LaTeX command here ([`latex_unwritable`]).
pub(super) fn render_name(name: &str) -> (String, String) {
    match name.split_once('_') {
        Some((head, tail)) if !head.is_empty() && !tail.is_empty() => {
            let subs: Vec<Piece> = tail.split('_').map(Piece::of).collect();
            let unicode: Vec<&str> = subs.iter().map(|s| s.unicode.as_str()).collect();
            let latex: Vec<&str> = subs.iter().map(|s| s.body.as_str()).collect();
            (
                format!("{}_{}", Piece::of(head).unicode, unicode.join("_")),
                subscripted(head, &latex.join(","), false),
            )
        }
        _ => {
            // Trailing digits become a subscript in LaTeX: G1 → G_{1}.
            let split = name.trim_end_matches(|c: char| c.is_ascii_digit());
            if !split.is_empty() && split.len() < name.len() {
                let piece = Piece::of(split);
                let digits = &name[split.len()..];
                return (
                    format!("{}{digits}", piece.unicode),
                    format!("{}_{{{digits}}}", piece.latex()),
                );
            }
            let piece = Piece::of(name);
            (piece.unicode.clone(), piece.latex())
        }
    }
}

/// A momentum `p_q` as text and LaTeX: as [`render_name`] writes it, but for a coordinate `q`
/// with a subscript of its own, which stays its subscript inside the momentum's (`p_k_x` →
/// `p_{k_{x}}`, `p_omega_2` → `p_{\omega_{2}}`, `p_theta1_y` → `p_{\theta1_{y}}`, as a display's
/// momentum is written, `p_{\omega_{+}}`), where `p_{k,x}` would read as a momentum with two
/// indices. A name's trailing digits stay in its subscript (`p_q1` → `p_{q1}`,
/// `p_theta1` → `p_{\theta1}`); a name that is no `p_` with a coordinate is as
/// [`render_name`] writes it.
pub(super) fn render_momentum(name: &str) -> (String, String) {
    let Some((head, tail)) = name
        .strip_prefix("p_")
        .and_then(|q| q.split_once('_'))
        .filter(|(head, tail)| !head.is_empty() && !tail.is_empty())
    else {
        return render_name(name);
    };
    let (unicode, _) = render_name(name);
    let subs: Vec<String> = tail.split('_').map(|s| Piece::of(s).body).collect();
    let latex = format!("p_{{{}}}", subscripted(head, &subs.join(","), true));
    (unicode, latex)
}

/// The LaTeX of the piece `head` with the subscript `subs` (its pieces' LaTeX, joined by
/// commas): `omega` and `x` give `\omega_{x}`. A head that ends in subscript digits of its own
/// takes `subs` into that subscript, `q₁` and `x` giving `q_{1,x}`, as LaTeX refuses the
/// double subscript `q_{1}_{x}`. Inside a subscript (`inner`) a word is written without
/// `\mathrm`, as a subscript's pieces are.
fn subscripted(head: &str, subs: &str, inner: bool) -> String {
    let letters = head.trim_end_matches(is_subscript);
    let (base, own) = match !letters.is_empty() && letters.len() < head.len() {
        true => {
            let digits: String = head[letters.len()..]
                .chars()
                .filter_map(subscript_digit)
                .collect();
            (Piece::of(letters), format!("{digits},"))
        }
        false => (Piece::of(head), String::new()),
    };
    let base = match inner {
        true => base.body,
        false => base.latex(),
    };
    format!("{base}_{{{own}{subs}}}")
}

/// The momentum of a coordinate or angle shown as `display` ([`display_forms`]), as text and
/// LaTeX: `p_` and the display, its subscript the display as a momentum's subscript writes a
/// coordinate's name, so that it reads as a momentum of an undisplayed
/// coordinate does: `θ1` → (`p_θ1`, `p_{\theta1}`, as `p_theta1`, where `p_{\theta_{1}}`
/// nested a subscript), `Gx` → (`p_Gx`, `p_{Gx}`), `ω₊` → (`p_ω₊`, `p_{\omega_{+}}`),
/// `A_x` → (`p_A_x`, `p_{A_{x}}`); a display with a bar or primes, which no name has, its
/// LaTeX in the subscript whole: `Z̄` → (`p_Z̄`, `p_{\bar{Z}}`). `None` for what is no
/// display name.
///
/// ```
/// use trigpoly::momentum_forms;
///
/// assert_eq!(momentum_forms("θ1"), Some(("p_θ1".into(), r"p_{\theta1}".into())));
/// assert_eq!(momentum_forms("ξ"), Some(("p_ξ".into(), r"p_{\xi}".into())));
/// assert_eq!(momentum_forms("Z̄"), Some(("p_Z̄".into(), r"p_{\bar{Z}}".into())));
/// ```
pub fn momentum_forms(display: &str) -> Option<(String, String)> {
    let (text, latex) = display_forms(display)?;
    let momentum = format!("p_{display}");
    // A display written as a name is (no bar, no prime) is written as its momentum is.
    let as_name = render_name(display);
    Some(match as_name.0 == text && as_name.1 == latex {
        true => render_momentum(&momentum),
        false => (format!("p_{text}"), format!("p_{{{latex}}}")),
    })
}

/// The first character of `name` that its LaTeX form cannot write in ASCII (a letter beyond
/// ASCII, the Greek letters, `ħ`, `ℓ` and the subscript digits), if any: such a name would stop
/// `pdflatex`.
pub fn latex_unwritable(name: &str) -> Option<char> {
    // An ASCII name writes ASCII: Greek letters spelled out become commands, and every other
    // rule rewrites a character beyond ASCII.
    if name.is_ascii() {
        return None;
    }
    let (_, latex) = render_name(name);
    latex.chars().find(|c| !c.is_ascii())
}

/// The letters a name may have, in words, for messages.
pub const LATEX_LETTERS: &str =
    "a name's letters are ASCII, Greek (alpha or α), ħ, ℓ and the subscript digits ₀–₉";

/// Letters beyond ASCII and Greek with a LaTeX command of their own, spelled out as the
/// command names them: as a Greek letter's, either spelling is the letter (a name's piece
/// `hbar` prints as `ħ`, `ell2` as `ℓ2`, as `omega` prints as `ω`).
const LETTERS: &[(&str, &str, &str)] = &[("hbar", "ħ", r"\hbar"), ("ell", "ℓ", r"\ell")];

/// The letters a name may spell out, each with its letter and its LaTeX: the Greek ones,
/// `ħ` and `ℓ`.
fn named_letters() -> impl Iterator<Item = &'static (&'static str, &'static str, &'static str)> {
    GREEK.iter().chain(LETTERS)
}

/// The subscript digits `₀`–`₉`.
const SUBSCRIPT_DIGITS: &str = "₀₁₂₃₄₅₆₇₈₉";

/// The subscript signs `₊`, `₋`, which a display name may have (`ω₊`, `ω₋`, the normal-mode
/// frequencies), written under what stands before them as a subscript digit is; no variable's
/// name has one.
const SUBSCRIPT_SIGNS: &str = "₊₋";

/// The ASCII a subscript digit or sign writes (`₁` → `1`, `₊` → `+`).
fn subscript_digit(c: char) -> Option<char> {
    match c {
        '₊' => return Some('+'),
        '₋' => return Some('-'),
        _ => {}
    }
    let k = SUBSCRIPT_DIGITS.chars().position(|d| d == c)?;
    char::from_digit(k as u32, 10)
}

/// Whether `c` is a subscript digit or sign.
fn is_subscript(c: char) -> bool {
    subscript_digit(c).is_some()
}

/// A piece's LaTeX letter by letter, for a word no rule above writes whole: each Greek letter,
/// `ħ` and `ℓ` as its command in braces (`ωx` → `{\omega}x`), a run of subscript digits as a
/// subscript (`x₁y` → `x_{1}y`; as digits after `_` or at the start, where there is nothing to
/// hang a subscript on: `x_₁` → `x_{1}`), anything else as it is, which
/// [`latex_unwritable`] then names.
fn letter_by_letter(p: &str) -> String {
    let mut body = String::new();
    let mut digits = String::new();
    let mut chars = p.chars().peekable();
    while let Some(c) = chars.next() {
        if let Some(digit) = subscript_digit(c) {
            digits.push(digit);
            if chars.peek().is_some_and(|&n| is_subscript(n)) {
                continue;
            }
            match body.is_empty() || body.ends_with('_') {
                true => body.push_str(&digits),
                false => write_display(&mut body, format_args!("_{{{digits}}}")),
            }
            digits.clear();
            continue;
        }
        match named_letters().find(|g| g.1.chars().eq([c])).map(|g| g.2) {
            Some(tex) if tex.starts_with('\\') => {
                write_display(&mut body, format_args!("{{{tex}}}"))
            }
            Some(tex) => body.push_str(tex),
            None => body.push(c),
        }
    }
    body
}

/// One piece of a name between underscores, as text and as LaTeX.
struct Piece {
    unicode: String,
    /// The LaTeX, without `\mathrm` (a subscript sets a word upright as it is).
    body: String,
    /// Whether the LaTeX is a word of several letters, upright in `\mathrm` outside a subscript.
    word: bool,
}

impl Piece {
    fn of(p: &str) -> Piece {
        for (ascii, uni, tex) in named_letters() {
            if p == *ascii || p == *uni {
                return Piece::symbol(uni, tex);
            }
        }
        // Subscript digits and signs: `q₁` → `q_{1}`, `ω₊` → `\omega_{+}`.
        let letters = p.trim_end_matches(is_subscript);
        if !letters.is_empty() && letters.len() < p.len() {
            let digits: String = p[letters.len()..]
                .chars()
                .filter_map(subscript_digit)
                .collect();
            let base = Piece::of(letters);
            return Piece {
                unicode: p.to_string(),
                body: format!("{}_{{{digits}}}", base.latex()),
                word: false,
            };
        }
        // A Greek letter with digits after it: `theta1` → `θ1`, `\theta1`, a word as `G1` is
        // (`\mathrm{\theta1}_{x}` of `theta1_x`, whose subscript `\theta1_{x}` would hang on
        // the digit, and which reads back as θ times `1_x`); no space after the command,
        // which would make two words of one in the names that LaTeX spells.
        let letters = p.trim_end_matches(|c: char| c.is_ascii_digit());
        if letters.len() < p.len() {
            if let Some((_, uni, tex)) = named_letters().find(|g| letters == g.0 || letters == g.1)
            {
                let digits = &p[letters.len()..];
                return Piece {
                    unicode: format!("{uni}{digits}"),
                    body: format!("{tex}{digits}"),
                    word: true,
                };
            }
        }
        // A bar over the piece: `Z̄` → `\bar{Z}` (display names only: no variable's name has one).
        if let Some(base) = p.strip_suffix('\u{304}').filter(|b| !b.is_empty()) {
            let base = Piece::of(base);
            return Piece::symbol(p, &format!("\\bar{{{}}}", base.latex()));
        }
        Piece {
            unicode: p.to_string(),
            body: letter_by_letter(p),
            word: p.chars().count() > 1,
        }
    }

    fn symbol(unicode: &str, tex: &str) -> Piece {
        Piece {
            unicode: unicode.to_string(),
            body: tex.to_string(),
            word: false,
        }
    }

    /// The LaTeX outside a subscript.
    fn latex(&self) -> String {
        if self.word {
            format!(r"\mathrm{{{}}}", self.body)
        } else {
            self.body.clone()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vars;

    /// `i` and the functions cannot name a variable: a parameter `re` made `re(x + i p_x)` the
    /// real part and `re*(x + i p_x)` a product.
    #[test]
    fn names_beyond_ascii_have_latex_forms() {
        assert_eq!(render_name("q₁"), ("q₁".into(), "q_{1}".into()));
        assert_eq!(render_name("p_q₁"), ("p_q₁".into(), "p_{q_{1}}".into()));
        assert_eq!(render_name("ħ"), ("ħ".into(), r"\hbar".into()));
        assert_eq!(render_name("ℓ2"), ("ℓ2".into(), r"\ell_{2}".into()));
        assert_eq!(render_name("ω₂"), ("ω₂".into(), r"\omega_{2}".into()));
        assert_eq!(
            render_name("xy₁₀"),
            ("xy₁₀".into(), r"\mathrm{xy}_{10}".into())
        );
        for name in ["q₁", "p_q₁", "ħ", "ℓ", "θ_ħ"] {
            assert_eq!(latex_unwritable(name), None, "{name}");
        }
        assert_eq!(latex_unwritable("é"), Some('é'));
        assert_eq!(latex_unwritable("p_щ"), Some('щ'));
        // `latex_unwritable` answers an ASCII name without rendering it: every rule writes
        // such a name in ASCII, Greek letters spelled out included.
        let spelled = GREEK.iter().map(|g| g.0.to_string());
        let built = [
            "x",
            "G1",
            "p_theta1",
            "omega_x_2",
            "theta12",
            "Zbar",
            "xy",
            "a_b_c",
        ];
        for name in spelled.chain(built.map(String::from)) {
            let (_, latex) = render_name(&name);
            assert!(latex.is_ascii(), "{name}: {latex}");
            let (_, latex) = render_name(&format!("{name}_{name}2"));
            assert!(latex.is_ascii(), "{name}: {latex}");
        }
        let err = Vars::builder().coordinate("é").build().unwrap_err();
        assert!(err.to_string().contains("LaTeX has no letter 'é'"), "{err}");
        Vars::builder()
            .coordinate("q₁")
            .parameter("ħ")
            .build()
            .expect("names LaTeX can write");
    }

    /// Greek letters, `ħ` and `ℓ` inside a word are written letter by letter, so that only a
    /// letter LaTeX has no command for is refused, and named (`θé` blamed 'θ', and `ωx` was
    /// refused although `omegax` is not); subscript digits inside a word are a subscript.
    #[test]
    fn letters_inside_a_word_are_written_one_by_one() {
        for (name, latex) in [
            ("ωx", r"\mathrm{{\omega}x}"),
            ("αβ", r"\mathrm{{\alpha}{\beta}}"),
            ("Ωa", r"\mathrm{{\Omega}a}"),
            ("aħℓ", r"\mathrm{a{\hbar}{\ell}}"),
            ("p_ωx", r"p_{{\omega}x}"),
            ("x₁y", r"\mathrm{x_{1}y}"),
            ("x₁₂y₃z", r"\mathrm{x_{12}y_{3}z}"),
            ("x_₁", r"x_{1}"),
            ("x_₁y", r"x_{1y}"),
        ] {
            assert_eq!(render_name(name), (name.into(), latex.into()), "{name}");
            assert_eq!(latex_unwritable(name), None, "{name}");
        }
        assert_eq!(latex_unwritable("θé"), Some('é'));
        assert_eq!(latex_unwritable("ωщx"), Some('щ'));
        for name in ["ωx", "αβ", "Ωa", "x₁y", "x_₁"] {
            Vars::builder().coordinate(name).build().expect(name);
        }
        let err = Vars::builder().coordinate("θé").build().unwrap_err();
        assert!(err.to_string().contains("LaTeX has no letter 'é'"), "{err}");
    }

    /// A bar over a display name's head, before its subscript, is LaTeX's `\bar` over the head
    /// (`Z̄_x` has no other LaTeX, and was written as it is); a bar elsewhere in a piece has none.
    #[test]
    fn a_bar_ends_a_piece_of_a_display_name() {
        for (display, latex) in [
            ("Z̄", r"\bar{Z}"),
            ("Z̄_x", r"\bar{Z}_{x}"),
            ("Z_x̄", r"\bar{Z_{x}}"),
            ("A\u{304}_x_y'", r"\bar{A}_{x,y}'"),
            ("ω₁\u{304}", r"\bar{\omega_{1}}"),
            ("Ā_x", r"\bar{A}_{x}"),
            ("ē_x", r"\bar{e}_{x}"),
        ] {
            assert_eq!(
                display_forms(display).map(|f| f.1),
                Some(latex.into()),
                "{display}"
            );
        }
        for display in [
            "\u{304}",
            "Z̄x_y",
            "ω\u{304}₁",
            "a_\u{304}x",
            "Z\u{304}\u{304}_x",
        ] {
            assert_eq!(display_forms(display), None, "{display}");
        }
    }

    /// The subscript signs of a display name (`ω₊`, `ω₋`, the normal-mode frequencies) are
    /// LaTeX subscripts, as subscript digits are; a sign with nothing before it is no display,
    /// and no name has one.
    #[test]
    fn a_display_name_may_have_subscript_signs() {
        for (display, latex) in [
            ("ω₊", r"\omega_{+}"),
            ("ω₋", r"\omega_{-}"),
            ("a₊", "a_{+}"),
            ("k_x₋", "k_{x_{-}}"),
        ] {
            assert_eq!(
                display_forms(display),
                Some((display.into(), latex.into())),
                "{display}"
            );
        }
        for display in ["₊", "a_₊", "₋a", "Z̄₊"] {
            assert_eq!(display_forms(display), None, "{display}");
        }
        assert_eq!(latex_unwritable("ω₊"), None);
        assert_eq!(BadName::of("ω₊"), Some(BadName::Malformed));
    }

    #[test]
    fn names_render_like_the_paper() {
        assert_eq!(render_name("p_x"), ("p_x".into(), "p_{x}".into()));
        assert_eq!(render_name("p_theta"), ("p_θ".into(), r"p_{\theta}".into()));
        assert_eq!(render_name("omega"), ("ω".into(), r"\omega".into()));
        assert_eq!(render_name("G1"), ("G1".into(), "G_{1}".into()));
        assert_eq!(render_name("M"), ("M".into(), "M".into()));
        assert_eq!(
            render_name("theta12"),
            ("θ12".into(), r"\theta_{12}".into())
        );
    }

    /// A Greek letter with digits after it is one piece, `\theta1`, with no space that would
    /// make two words of it: in a subscript as `x1` is (`p_{\theta1}`, `p_{x1}`), and before
    /// one a word as `G1` is (`\mathrm{\theta1}_{x}`, `\mathrm{G1}_{x}`), where
    /// `\theta 1_{x}` hung the subscript on the digit and read back as θ times `1_x`.
    #[test]
    fn a_greek_letter_with_digits_is_one_piece() {
        for (name, text, latex) in [
            ("theta1", "θ1", r"\theta_{1}"),
            ("Omega12", "Ω12", r"\Omega_{12}"),
            ("p_theta1", "p_θ1", r"p_{\theta1}"),
            ("omega_x1", "ω_x1", r"\omega_{x1}"),
            ("L_theta1", "L_θ1", r"L_{\theta1}"),
            ("theta1_x", "θ1_x", r"\mathrm{\theta1}_{x}"),
            ("θ1_x", "θ1_x", r"\mathrm{\theta1}_{x}"),
            ("G1_x", "G1_x", r"\mathrm{G1}_{x}"),
            ("p_omicron1", "p_ο1", r"p_{\mathit{o}1}"),
            ("omicron", "ο", r"\mathit{o}"),
            ("alphab", "alphab", r"\mathrm{alphab}"),
            ("x2y", "x2y", r"\mathrm{x2y}"),
        ] {
            assert_eq!(render_name(name), (text.into(), latex.into()), "{name}");
            assert!(!latex.contains(' '), "{name}");
        }
    }

    /// `hbar` and `ell` print as `ħ` and `ℓ`, as `omega` prints as `ω` (they printed as words,
    /// `\mathrm{hbar}`), alone, with digits and in subscripts, and their LaTeX is the bare
    /// command, `\hbar`, as `\omega` is (it was `{\hbar}`, a group, which the reader took
    /// for a bracket `{f, g}`); either spelling names the variable, as `ω` does `omega`. In a
    /// longer word they stay letters (`hbarx`, `shell`).
    #[test]
    fn hbar_and_ell_print_as_their_letters() {
        for (name, text, latex) in [
            ("hbar", "ħ", r"\hbar"),
            ("ħ", "ħ", r"\hbar"),
            ("ell", "ℓ", r"\ell"),
            ("ell2", "ℓ2", r"\ell_{2}"),
            ("p_hbar", "p_ħ", r"p_{\hbar}"),
            ("p_ell1", "p_ℓ1", r"p_{\ell1}"),
            ("hbar1_x", "ħ1_x", r"\mathrm{\hbar1}_{x}"),
            ("omega_ell", "ω_ℓ", r"\omega_{\ell}"),
            ("hbarx", "hbarx", r"\mathrm{hbarx}"),
            ("shell", "shell", r"\mathrm{shell}"),
        ] {
            assert_eq!(render_name(name), (text.into(), latex.into()), "{name}");
        }
        assert_eq!(spell_out("ħ").as_deref(), Some("hbar"));
        assert_eq!(spell_out("p_ℓ2").as_deref(), Some("p_ell2"));
        let vars = Vars::builder()
            .parameter("hbar")
            .parameter("ℓ")
            .build()
            .expect("names");
        for spelling in ["hbar", "ħ", "ell", "ℓ"] {
            assert!(vars.lookup(spelling).is_some(), "{spelling}");
        }
        let ell = vars.lookup("ell").expect("ℓ");
        assert_eq!(vars.variable(ell).ascii(), "ell");
        Vars::builder()
            .parameter("hbar")
            .parameter("ħ")
            .build()
            .expect_err("two spellings of one letter");
    }

    /// A displayed coordinate's momentum is written as a momentum of a coordinate so named
    /// (`p_{\theta1}` of `θ1`, as of `theta1`; it was `p_{\theta_{1}}`, a subscript nested in
    /// the momentum's), a bar or primes, which no name has, kept whole in the subscript.
    #[test]
    fn a_displayed_coordinates_momentum_reads_as_a_named_ones() {
        for (display, text, latex) in [
            ("θ1", "p_θ1", r"p_{\theta1}"),
            ("G1", "p_G1", "p_{G1}"),
            ("Gx", "p_Gx", "p_{Gx}"),
            ("ω₊", "p_ω₊", r"p_{\omega_{+}}"),
            ("ξ", "p_ξ", r"p_{\xi}"),
            ("A_x", "p_A_x", "p_{A_{x}}"),
            ("Z̄", "p_Z̄", r"p_{\bar{Z}}"),
            ("Ā_x", "p_A\u{304}_x", r"p_{\bar{A}_{x}}"),
            ("G1'", "p_G1'", "p_{G_{1}'}"),
        ] {
            assert_eq!(
                momentum_forms(display),
                Some((text.into(), latex.into())),
                "{display}"
            );
            if !display.contains(['\u{304}', '\'', 'Ā']) {
                let name = format!("p_{display}");
                assert_eq!(render_momentum(&name).1, latex, "{display}");
            }
        }
        assert_eq!(momentum_forms("x(t)"), None);
    }

    /// A momentum's coordinate keeps its own subscript inside the momentum's (`p_{k_{x}}`,
    /// as a display's momentum `p_{\omega_{+}}`), where `p_{k,x}` read as two indices; its
    /// trailing digits stay in the subscript, as `p_{q1}`'s do.
    #[test]
    fn a_momentum_keeps_its_coordinates_subscript() {
        for (name, text, latex) in [
            ("p_k_x", "p_k_x", "p_{k_{x}}"),
            ("p_omega_2", "p_ω_2", r"p_{\omega_{2}}"),
            ("p_omega_x_2", "p_ω_x_2", r"p_{\omega_{x,2}}"),
            ("p_theta1_y", "p_θ1_y", r"p_{\theta1_{y}}"),
            ("p_q1", "p_q1", "p_{q1}"),
            ("p_theta", "p_θ", r"p_{\theta}"),
            ("p_q₁", "p_q₁", "p_{q_{1}}"),
            ("px_y", "px_y", r"\mathrm{px}_{y}"),
            // A coordinate whose head has subscript digits of its own takes its subscript
            // into theirs (`p_{q_{1}_{x}}` was a double subscript).
            ("p_q₁_x", "p_q₁_x", "p_{q_{1,x}}"),
            ("p_ω₂_y", "p_ω₂_y", r"p_{\omega_{2,y}}"),
        ] {
            assert_eq!(render_momentum(name), (text.into(), latex.into()), "{name}");
        }
        // So does the coordinate itself (`q_{1}_{x}` was one too).
        assert_eq!(render_name("q₁_x"), ("q₁_x".into(), "q_{1,x}".into()));
        assert_eq!(render_name("ℓ₂_x"), ("ℓ₂_x".into(), r"\ell_{2,x}".into()));
        assert_eq!(
            render_name("xy₁₀_a_b"),
            ("xy₁₀_a_b".into(), r"\mathrm{xy}_{10,a,b}".into())
        );
        let vars = Vars::builder()
            .coordinate("k_x")
            .momentum("p_k_x")
            .parameter("p_x_0")
            .build()
            .expect("names");
        let latex: Vec<&str> = vars.vars().map(|v| vars.variable(v).latex()).collect();
        assert_eq!(latex, ["k_{x}", "p_{k_{x}}", "p_{x,0}"]);
    }

    /// A family instance's display, its indices in braces after a display name, shows as
    /// written in text and with the indices as a subscript in LaTeX, joined to one the name
    /// ends with; braces of anything else have no forms.
    #[test]
    fn an_instance_shows_its_indices() {
        for (display, text, latex) in [
            ("Q_{1,2}", "Q_{1,2}", "Q_{1,2}"),
            ("K̄_{10,3}", "K̄_{10,3}", r"\bar{K}_{10,3}"),
            ("G1'_{1,2}", "G1'_{1,2}", "G_{1;1,2}'"),
            ("A_x_{m,n}", "A_x_{m,n}", "A_{x;m,n}"),
            ("Re K_{1,1}", "Re K_{1,1}", r"\operatorname{Re} K_{1,1}"),
        ] {
            assert_eq!(
                shown_forms(display),
                Some((text.into(), latex.into())),
                "{display}"
            );
        }
        for display in ["Q_{1}", "Q_{1,2,3}", "_{1,2}", "Q_{1, 2}", "x(t)_{1,2}"] {
            assert_eq!(shown_forms(display), None, "{display}");
        }
    }
}
