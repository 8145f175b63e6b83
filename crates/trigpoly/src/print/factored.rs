//! A sum written as the factor its terms share times what is left, `F(x p_x + y p_y)/M`: how
//! `bracket`, `expand` and a refuted claim's residual show a result whose terms all have a
//! factor in common. The factor is the rational content (signed as the first term, so that
//! what is left starts positive) times each variable at its least power, where every term has
//! it on the same side of the fraction bar: the power they share above it, their common
//! denominator below it (`β²(x p_y + y p_x)/(x³y³)`). What is left has coprime integer
//! coefficients (Gaussian integers over Q(i)) and no denominator; a sum whose rest would have
//! one (`p_x²/(2M) + Mω²x²/2`, with `M` on both sides) has no such form. A sum of imaginary
//! terms has `i` in its factor (`2i(x + 3y)`). A polynomial in named functions writes the
//! functions of its factor after the parentheses, `−(2ω − 3Ω) Q_{2,3}`
//! ([`Factored::render_functions_last`]).

use std::fmt;

use super::{render_terms, write_term, Angles, Inner, Names, Style};
use crate::number::{Coefficient, GaussianRational, Rational};
use crate::poly::{CosSinTerm, Poly, PrintOrder, TrigMonomial};
use crate::varset::{VarKind, Vars};

/// A sum as `factor · (rest)`, found by [`Poly::factored`].
///
/// ```
/// use trigpoly::{Poly, Rational, Style, Vars};
/// let vars = Vars::builder()
///     .coordinate("x").coordinate("y").momentum("p_x").momentum("p_y")
///     .parameter("M").parameter("F")
///     .build().unwrap();
/// let rate = Poly::<Rational>::parse(&vars, "F*x*p_x/M + F*y*p_y/M").unwrap();
/// let factored = rate.factored().unwrap();
/// assert_eq!(factored.to_string(), "F(x p_x + y p_y)/M");
/// assert_eq!(factored.render(Style::Ascii), "F*(x*p_x + y*p_y)/M");
/// // The terms of a Hamiltonian share no factor that leaves a polynomial.
/// let h = Poly::<Rational>::parse(&vars, "p_x^2/(2*M) + M*x^2/2").unwrap();
/// assert!(h.factored().is_none());
/// ```
#[derive(Clone, Debug)]
pub struct Factored {
    vars: Vars,
    /// The factor: a rational times powers of variables (no angle).
    factor: CosSinTerm,
    /// What is left, its angles in the form of `angles`.
    rest: Vec<CosSinTerm>,
    /// The form the angles of `rest` are in.
    angles: Angles,
}

impl Factored {
    /// `terms` (a cos/sin normal form) as factor times rest, where the factor is not `±1` and
    /// the rest has no denominator.
    fn of(vars: &Vars, terms: &[CosSinTerm], angles: Angles) -> Option<Factored> {
        let first = terms.first().filter(|_| terms.len() > 1)?;
        let width = first.exps.len();
        // Each variable at its least power, where every term has it on the same side of the bar:
        // the power every term has above it, or the common denominator's below it.
        let powers: Vec<i64> = (0..width)
            .map(|j| {
                let (low, high) = (terms.iter().map(|t| t.exps[j]))
                    .fold((i64::MAX, i64::MIN), |(l, h), e| (l.min(e), h.max(e)));
                match low > 0 || high < 0 {
                    true => low,
                    false => 0,
                }
            })
            .collect();
        let content = Rational::content_of(terms.iter().flat_map(|t| [&t.coeff.re, &t.coeff.im]));
        if content.abs().is_one() && powers.iter().all(|&e| e == 0) {
            return None;
        }
        // Each term with its exponents divided by the factor's powers, none of which may be
        // negative.
        let mut divided: Vec<(&CosSinTerm, Vec<i64>)> = (terms.iter())
            .map(|t| (t, t.exps.iter().zip(&powers).map(|(e, p)| e - p).collect()))
            .collect();
        if divided.iter().any(|(_, exps)| exps.iter().any(|&e| e < 0)) {
            return None;
        }
        // The rest in its own printed order, which dividing out a denominator other than a
        // parameter's can change (`ω²p_x/(x³y²) + ω²p_y/(x²y³)` is `ω²(x p_y + y p_x)/(x³y³)`);
        // the first term of that order signs the content. Dividing out powers of parameters, or
        // multiplying by any, leaves the order as it is.
        let order = PrintOrder::of(vars);
        if order.has_denominator(&powers) {
            divided.sort_by_cached_key(|(t, exps)| (t.trig.clone(), order.key(exps)));
        }
        let first = divided[0].0;
        let leads_negative = match first.coeff.re.is_zero() {
            true => first.coeff.im.is_negative(),
            false => first.coeff.re.is_negative(),
        };
        let content = if leads_negative { -&content } else { content };
        // `i(ω₊ − ω₋) W`: a sum of imaginary terms has `i` in its factor.
        let imaginary = terms.iter().all(|t| t.coeff.re.is_zero());
        let rest = (divided.into_iter())
            .map(|(t, exps)| CosSinTerm {
                coeff: match imaginary {
                    true => GaussianRational::from(&t.coeff.im / &content),
                    false => GaussianRational::new(&t.coeff.re / &content, &t.coeff.im / &content),
                },
                exps,
                trig: t.trig.clone(),
            })
            .collect::<Vec<_>>();
        let factor = CosSinTerm {
            coeff: match imaginary {
                true => GaussianRational::new(Rational::zero(), content),
                false => GaussianRational::from(content),
            },
            exps: powers,
            trig: TrigMonomial::one(first.trig.powers.len()),
        };
        Some(Factored {
            vars: vars.clone(),
            factor,
            rest,
            angles,
        })
    }

    /// The number of terms of what is left, its angles in the form it prints in.
    pub fn terms(&self) -> usize {
        self.rest.len()
    }

    /// Whether the factor is a number alone, `8(…)`, with no variable in it.
    pub fn is_numeric(&self) -> bool {
        self.factor.exps.iter().all(|&e| e == 0)
    }

    /// The factored form in the notation of `style`: `F(x p_x + y p_y)/M`,
    /// `\frac{F \left(x p_{x} + y p_{y}\right)}{M}`, `F*(x*p_x + y*p_y)/M`.
    pub fn render(&self, style: Style) -> String {
        self.written(&self.factor, None, style)
    }

    /// `front(rest)`, then `back` after the parentheses where it is given (`−(2ω − 3Ω) Q`).
    fn written(&self, front: &CosSinTerm, back: Option<&CosSinTerm>, style: Style) -> String {
        let rest = render_terms(&self.vars, &self.rest, style, self.angles);
        let every: Vec<CosSinTerm> = std::iter::once(front)
            .chain(back)
            .chain(&self.rest)
            .cloned()
            .collect();
        let names = Names::new(&self.vars, &every, style, self.angles);
        let mut out = String::new();
        let inner = Inner {
            text: &rest,
            terms: self.rest.len(),
        };
        write_term(&mut out, 0, &names, front, None, Some(inner), style);
        if let Some(back) = back {
            out.push_str(match style {
                Style::Ascii => "*",
                _ => " ",
            });
            let start = out.len();
            write_term(&mut out, start, &names, back, None, None, style);
        }
        out
    }

    /// The factored form of a polynomial in named functions (the functions its coordinates,
    /// the parameters its coefficients), as the paper writes one: the factor's functions after
    /// the parentheses, its number and parameters before them, `−(2ω − 3Ω) Q_{2,3}`,
    /// `2(ω + Ω) H/M`. Where the factor has no function, the same as [`Factored::render`]:
    /// `2ω(H + L)`, `(H + 2L)/M`.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Style, Vars};
    /// let vars = Vars::builder()
    ///     .parameter("omega").parameter("M")
    ///     .coordinate("Q").word().coordinate("H").word()
    ///     .build().unwrap();
    /// let e = Poly::<Rational>::parse(&vars, "-omega*Q + 2*M*Q").unwrap();
    /// let factored = e.factored().unwrap();
    /// assert_eq!(factored.render_functions_last(Style::Unicode), "−(ω − 2M) Q");
    /// assert_eq!(factored.render_functions_last(Style::Ascii), "-(omega - 2*M)*Q");
    /// let e = Poly::<Rational>::parse(&vars, "omega*H/(3*M) + omega*Q/M").unwrap();
    /// assert_eq!(e.factored().unwrap().render_functions_last(Style::Unicode), "ω(3 Q + H)/(3M)");
    /// ```
    pub fn render_functions_last(&self, style: Style) -> String {
        let is_parameter: Vec<bool> = (self.vars.vars())
            .map(|v| self.vars.variable(v).kind() == VarKind::Parameter)
            .collect();
        let factor = &self.factor;
        let has_function = (factor.exps.iter().zip(&is_parameter)).any(|(&e, &p)| e > 0 && !p);
        if !has_function {
            return self.render(style);
        }
        // `−2ω`: the sign, the numerator and the parameters above the bar, before the
        // parentheses; `Q_{2,3}/(3M)`: the functions and every denominator after them.
        let (re, im) = (&factor.coeff.re, &factor.coeff.im);
        let content = if re.is_zero() { im } else { re };
        let numerator = Rational::from(content.numer());
        let front = CosSinTerm {
            coeff: match re.is_zero() {
                true => GaussianRational::new(Rational::zero(), numerator),
                false => GaussianRational::from(numerator),
            },
            exps: (factor.exps.iter().zip(&is_parameter))
                .map(|(&e, &p)| if p && e > 0 { e } else { 0 })
                .collect(),
            trig: factor.trig.clone(),
        };
        let back = CosSinTerm {
            coeff: GaussianRational::from(&Rational::one() / &Rational::from(content.denom())),
            exps: (factor.exps.iter().zip(&is_parameter))
                .map(|(&e, &p)| if p && e > 0 { 0 } else { e })
                .collect(),
            trig: factor.trig.clone(),
        };
        self.written(&front, Some(&back), style)
    }
}

impl fmt::Display for Factored {
    /// The factored form in unicode text.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(Style::Unicode))
    }
}

impl<C: Coefficient> Poly<C> {
    /// The element as the factor its terms share times what is left, `F(x p_x + y p_y)/M`
    /// ([`Factored`]): `None` for a single term, and where the terms share no factor but `±1`
    /// or the rest would have a denominator.
    pub fn factored(&self) -> Option<Factored> {
        let angles = Angles::current();
        Factored::of(self.vars(), &angles.terms(self), angles)
    }
}
