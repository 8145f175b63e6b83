//! Printing like the paper: unicode text (`p_x²/(2M) − ω² L`), LaTeX (`\frac{p_{x}^{2}}{2 M}`),
//! and an ASCII form (`p_x^2/(2*M)`) that parses back to the same element.

use std::fmt;

use crate::number::{Coefficient, GaussianRational, Rational};
use crate::poly::{CosSinTerm, Poly, TrigMonomial};
use crate::varset::{VarKind, VarSet};

/// An output notation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Unicode text: `p_x²/(2M)`, `−ω² L`, `cos θ`.
    Unicode,
    /// LaTeX math: `\frac{p_{x}^{2}}{2 M}`, `\cos\theta`.
    Latex,
    /// ASCII that parses back: `p_x^2/(2*M)`, `cos(theta)`.
    Ascii,
}

impl<C: Coefficient> Poly<C> {
    /// The element in a given notation.
    pub fn render(&self, style: Style) -> String {
        render_terms(self.vars(), &self.cos_sin_terms(), style)
    }

    /// The element in several notations, its cos/sin normal form ([`Poly::cos_sin_terms`])
    /// computed once for all of them.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Style, VarSet};
    /// let vars = VarSet::builder().coordinate("x").momentum("p_x").parameter("M").build().unwrap();
    /// let h = Poly::<Rational>::parse(&vars, "p_x^2/(2*M)").unwrap();
    /// let [text, latex] = h.render_each([Style::Unicode, Style::Latex]);
    /// assert_eq!((text, latex), (h.to_string(), h.to_latex()));
    /// ```
    pub fn render_each<const N: usize>(&self, styles: [Style; N]) -> [String; N] {
        let terms = self.cos_sin_terms();
        styles.map(|style| render_terms(self.vars(), &terms, style))
    }

    /// The element's text for a message: in full when it is short, else only its size (`a
    /// polynomial of 24310 terms`), which a one-line message has no room for and an error no
    /// time to print (a refused division once printed a 270 MB divisor).
    pub(crate) fn brief(&self) -> String {
        const TERMS: usize = 8;
        const CHARS: usize = 80;
        if self.len() <= TERMS {
            let text = self.to_string();
            if text.chars().count() <= CHARS {
                return text;
            }
        }
        format!("a polynomial of {} terms", self.len())
    }

    /// LaTeX math (no surrounding `$`).
    pub fn to_latex(&self) -> String {
        self.render(Style::Latex)
    }

    /// ASCII text that [`Poly::parse`] reads back to the same element.
    pub fn to_ascii(&self) -> String {
        self.render(Style::Ascii)
    }
}

impl<C: Coefficient> fmt::Display for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(Style::Unicode))
    }
}

/// Renders a sum of normal-form terms, grouping terms by their trigonometric factor:
/// `(p_x − Mωy) cos θ + (p_y + Mωx) sin θ`.
pub(crate) fn render_terms(vars: &VarSet, terms: &[CosSinTerm], style: Style) -> String {
    if terms.is_empty() {
        return "0".into();
    }
    let names = Names::new(vars, style);
    let mut out = String::new();
    let mut k = 0;
    while k < terms.len() {
        let trig = &terms[k].trig;
        let end = k + terms[k..].iter().take_while(|t| &t.trig == trig).count();
        let group = &terms[k..end];
        if trig.is_one() || group.len() == 1 {
            for t in group {
                let (neg, body) = render_term(&names, &t.coeff, &t.exps, Some(&t.trig), style);
                push_signed(&mut out, neg, &body, style);
            }
        } else {
            // `(inner) factor`, written in place: the inner sum can run to megabytes.
            push_signed(&mut out, false, "", style);
            out.push_str(if style == Style::Latex {
                r"\left("
            } else {
                "("
            });
            let start = out.len();
            for t in group {
                let (neg, body) = render_term(&names, &t.coeff, &t.exps, None, style);
                push_signed_after(&mut out, start, neg, &body, style);
            }
            out.push_str(match style {
                Style::Ascii => ")*",
                Style::Latex => r"\right) ",
                Style::Unicode => ") ",
            });
            out.push_str(&join(&trig_factors(&names, trig, style), style));
        }
        k = end;
    }
    out
}

fn minus(style: Style) -> &'static str {
    match style {
        Style::Unicode => "−",
        _ => "-",
    }
}

fn push_signed(out: &mut String, negative: bool, body: &str, style: Style) {
    push_signed_after(out, 0, negative, body, style)
}

/// [`push_signed`] for a sum written into `out` from byte `start` on.
fn push_signed_after(out: &mut String, start: usize, negative: bool, body: &str, style: Style) {
    match (out.len() == start, negative) {
        (true, false) => {}
        (true, true) => out.push_str(minus(style)),
        (false, false) => out.push_str(" + "),
        (false, true) => {
            out.push(' ');
            out.push_str(minus(style));
            out.push(' ');
        }
    }
    out.push_str(body);
}

/// One factor of a product, with whether it is "wide" (needs spaces around it in text).
struct Factor {
    text: String,
    wide: bool,
}

fn join(factors: &[Factor], style: Style) -> String {
    let mut s = String::new();
    for (k, f) in factors.iter().enumerate() {
        if k > 0 {
            match style {
                Style::Ascii => s.push('*'),
                Style::Latex => s.push(' '),
                Style::Unicode => {
                    if f.wide || factors[k - 1].wide {
                        s.push(' ');
                    }
                }
            }
        }
        s.push_str(&f.text);
    }
    s
}

fn power(base: &str, e: i64, style: Style) -> String {
    if e == 1 {
        return base.to_string();
    }
    match style {
        Style::Unicode => format!("{base}{}", superscript(e)),
        Style::Latex => format!("{base}^{{{e}}}"),
        Style::Ascii => {
            if e < 0 {
                format!("{base}^({e})")
            } else {
                format!("{base}^{e}")
            }
        }
    }
}

/// `-12` → `⁻¹²`.
pub fn superscript(e: i64) -> String {
    e.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// The variables' names in one notation, and the order in which a term's factors are
/// written, worked out once for all the terms of an element.
struct Names {
    /// The name of each variable, by index.
    names: Vec<String>,
    /// The variables as the paper orders a term's factors: parameters, then coordinates,
    /// then momenta (then angles), each kind in declaration order.
    order: Vec<usize>,
    /// The angles' indices, in declaration order.
    angles: Vec<usize>,
}

impl Names {
    fn new(vars: &VarSet, style: Style) -> Self {
        let names = vars
            .vars()
            .map(|v| {
                let var = vars.variable(v);
                match style {
                    Style::Unicode => var.unicode().to_string(),
                    Style::Latex => var.latex().to_string(),
                    Style::Ascii => var.name().to_string(),
                }
            })
            .collect();
        let rank = |v: &crate::varset::Var| match vars.variable(*v).kind() {
            VarKind::Parameter => 0,
            VarKind::Coordinate => 1,
            VarKind::Momentum => 2,
            VarKind::Angle => 3,
        };
        let mut order: Vec<crate::varset::Var> = vars.vars().collect();
        order.sort_by_key(rank);
        Names {
            names,
            order: order.iter().map(|v| v.index()).collect(),
            angles: vars.angles().map(|v| v.index()).collect(),
        }
    }
}

fn trig_factors(names: &Names, trig: &TrigMonomial, style: Style) -> Vec<Factor> {
    let mut out = Vec::new();
    for (&j, &(a, b)) in names.angles.iter().zip(&trig.powers) {
        let name = &names.names[j];
        for (fun, e) in [("cos", a), ("sin", b)] {
            if e == 0 {
                continue;
            }
            let text = match style {
                Style::Unicode if e == 1 => format!("{fun} {name}"),
                Style::Unicode => format!("{fun}{}{name}", superscript(e as i64)),
                Style::Latex if e == 1 => format!(r"\{fun}{name}"),
                Style::Latex => format!(r"\{fun}^{{{e}}}{name}"),
                Style::Ascii => power(&format!("{fun}({name})"), e as i64, style),
            };
            out.push(Factor { text, wide: true });
        }
    }
    out
}

/// Renders `coeff · Π v^e · trig` as (is it negative, text without the sign).
fn render_term(
    names: &Names,
    coeff: &GaussianRational,
    exps: &[i64],
    trig: Option<&TrigMonomial>,
    style: Style,
) -> (bool, String) {
    let (negative, num_int, den_int, complex) = split_coeff(coeff, style);
    let mut num: Vec<Factor> = Vec::new();
    let mut den: Vec<Factor> = Vec::new();
    if let Some(c) = complex {
        num.push(Factor {
            text: c,
            wide: true,
        });
    } else {
        if !num_int.is_one() {
            num.push(Factor {
                text: num_int.to_string(),
                wide: false,
            });
        }
        if !coeff.im.is_zero() {
            num.push(Factor {
                text: "i".into(),
                wide: false,
            });
        }
    }
    if !den_int.is_one() {
        den.push(Factor {
            text: den_int.to_string(),
            wide: false,
        });
    }
    for &j in names.order.iter().filter(|&&j| exps[j] != 0) {
        let e = exps[j];
        let name = &names.names[j];
        let wide = style == Style::Unicode && name.chars().count() > 1;
        let f = Factor {
            text: power(name, e.abs(), style),
            wide,
        };
        if e > 0 {
            num.push(f);
        } else {
            den.push(f);
        }
    }
    if let Some(t) = trig {
        num.extend(trig_factors(names, t, style));
    }
    let numer = if num.is_empty() {
        "1".to_string()
    } else {
        join(&num, style)
    };
    if den.is_empty() {
        return (negative, numer);
    }
    let denom = join(&den, style);
    let text = match style {
        Style::Latex => format!(r"\frac{{{numer}}}{{{denom}}}"),
        _ if den.len() == 1 => format!("{numer}/{denom}"),
        _ => format!("{numer}/({denom})"),
    };
    (negative, text)
}

/// `(negative, |numerator|, denominator, general complex text)` of a coefficient.
fn split_coeff(c: &GaussianRational, style: Style) -> (bool, Rational, Rational, Option<String>) {
    let one = Rational::one();
    let (part, complex) = match (c.re.is_zero(), c.im.is_zero()) {
        (_, true) => (&c.re, false),
        (true, false) => (&c.im, false),
        _ => (&c.re, true),
    };
    if complex {
        let text = match style {
            Style::Ascii => format!("({c})"),
            Style::Latex => {
                let (neg, body) = render_term_free(&c.im, style);
                let sign = if neg { "-" } else { "+" };
                let re = render_term_free(&c.re, style);
                let re = if re.0 { format!("-{}", re.1) } else { re.1 };
                format!(r"\left({re} {sign} {body} i\right)")
            }
            Style::Unicode => {
                let (neg, body) = render_term_free(&c.im, style);
                let sign = if neg { "−" } else { "+" };
                let re = render_term_free(&c.re, style);
                let re = if re.0 { format!("−{}", re.1) } else { re.1 };
                format!("({re} {sign} {body}i)")
            }
        };
        return (false, one.clone(), one, Some(text));
    }
    let negative = part.is_negative();
    let abs = part.abs();
    (
        negative,
        Rational::from(abs.numer()),
        Rational::from(abs.denom()),
        None,
    )
}

fn render_term_free(q: &Rational, style: Style) -> (bool, String) {
    let abs = q.abs();
    let text = match style {
        Style::Latex if !abs.is_integer() => {
            format!(r"\frac{{{}}}{{{}}}", abs.numer(), abs.denom())
        }
        _ => abs.to_string(),
    };
    (q.is_negative(), text)
}
