//! A sum written as the factor its terms share times what is left, `F(x p_x + y p_y)/M`: how
//! `bracket`, `expand` and a refuted claim's residual show a result whose terms all have a
//! factor in common. The factor is the rational content (signed as the first term, so that
//! what is left starts positive) times each variable at its least power, where every term has
//! it on the same side of the fraction bar: the power they share above it, their common
//! denominator below it (`β²(x p_y + y p_x)/(x³y³)`). What is left has coprime integer
//! coefficients (Gaussian integers over Q(i)) and no denominator; a sum whose rest would have
//! one (`p_x²/(2M) + Mω²x²/2`, with `M` on both sides) has no such form.

use std::fmt;

use super::{render_terms, write_term, Inner, Names, Style};
use crate::number::{Coefficient, GaussianRational, Rational};
use crate::poly::{CosSinTerm, Poly, TrigMonomial};
use crate::varset::Vars;

/// A sum as `factor · (rest)`, found by [`Poly::factored`].
///
/// ```
/// use trigpoly::{Poly, Rational, Style, VarSet};
/// let vars = VarSet::builder()
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
    /// What is left, in the cos/sin normal form.
    rest: Vec<CosSinTerm>,
}

impl Factored {
    /// `terms` (a cos/sin normal form) as factor times rest, where the factor is not `±1` and
    /// the rest has no denominator.
    fn of(vars: &Vars, terms: &[CosSinTerm]) -> Option<Factored> {
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
        let leads_negative = match first.coeff.re.is_zero() {
            true => first.coeff.im.is_negative(),
            false => first.coeff.re.is_negative(),
        };
        let content = if leads_negative { -&content } else { content };
        if content.abs().is_one() && powers.iter().all(|&e| e == 0) {
            return None;
        }
        let rest = terms
            .iter()
            .map(|t| CosSinTerm {
                coeff: GaussianRational::new(&t.coeff.re / &content, &t.coeff.im / &content),
                exps: t.exps.iter().zip(&powers).map(|(e, p)| e - p).collect(),
                trig: t.trig.clone(),
            })
            .collect::<Vec<_>>();
        if rest.iter().any(|t| t.exps.iter().any(|&e| e < 0)) {
            return None;
        }
        let factor = CosSinTerm {
            coeff: GaussianRational::from(content),
            exps: powers,
            trig: TrigMonomial {
                powers: vec![(0, 0); first.trig.powers.len()],
            },
        };
        Some(Factored {
            vars: vars.clone(),
            factor,
            rest,
        })
    }

    /// The number of terms of what is left, in the cos/sin normal form.
    pub fn terms(&self) -> usize {
        self.rest.len()
    }

    /// The factored form in the notation of `style`: `F(x p_x + y p_y)/M`,
    /// `\frac{F \left(x p_{x} + y p_{y}\right)}{M}`, `F*(x*p_x + y*p_y)/M`.
    pub fn render(&self, style: Style) -> String {
        let rest = render_terms(&self.vars, &self.rest, style);
        let every: Vec<CosSinTerm> = std::iter::once(&self.factor)
            .chain(&self.rest)
            .cloned()
            .collect();
        let names = Names::new(&self.vars, &every, style);
        let mut out = String::new();
        let inner = Inner {
            text: &rest,
            terms: self.rest.len(),
        };
        write_term(&mut out, 0, &names, &self.factor, None, Some(inner), style);
        out
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
        Factored::of(self.vars(), &self.cos_sin_terms())
    }
}
