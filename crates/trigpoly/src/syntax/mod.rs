//! Surface syntax: lexer and Pratt parser turning text such as
//! `p_x^2/(2*M) + M*ω²*(x^2+y^2)/2` or `{L, G1} + G2` into a spanned [`Expr`] tree.
//!
//! The parser is purely syntactic: it does not know which names are functions, that `i` is the
//! imaginary unit, or that exponents must be integers; that is left to the lowering. Errors
//! ([`ParseError`]) carry a byte [`Span`] and say what was expected and what was found;
//! [`ParseError::render`] shows the source line with carets under the offending span.
//!
//! Notes on the tree:
//! - integer literals are non-negative; `-2` is `Neg(Integer(2))`;
//! - `x²` and `x⁻¹` are `Pow(x, Integer(2))` and `Pow(x, Neg(Integer(1)))`, like `x^2`, `x^-1`;
//! - unary `+` produces no node, and a parenthesized expression is its inner expression with the
//!   span widened to include the parentheses;
//! - nesting (of parentheses, calls, brackets and operators) is limited to [`MAX_DEPTH`] levels
//!   so that deep input cannot overflow the stack;
//! - chains like `a + b + c` are left-deep, so trees are limited to [`MAX_HEIGHT`] levels (this
//!   keeps dropping and walking them recursively safe).

mod error;
mod latex;
mod lexer;
mod parser;

pub use error::{Excerpt, ParseCause, ParseError, Span};
pub use latex::{latex_name, NOT_IN_NAME};
pub(crate) use lexer::conjugate_written;
pub use lexer::{is_name_continue, is_name_start};
pub use parser::{balanced, parse_expr, Expr, ExprKind, LEFT_DEEP_SUM, MAX_DEPTH, MAX_HEIGHT};
// What the names read as, for the parser's refusals: the lowering's alone
// (`Poly::parse_with`, `Poly::parse_tree`), so no part of the crate's interface.
pub(crate) use parser::{parse_expr_reading, Reading};

#[cfg(test)]
mod tests {
    use super::*;

    /// The children of a node, in source order (a call's arguments, not its name).
    fn kids(e: &Expr) -> Vec<&Expr> {
        match &e.kind {
            ExprKind::Integer(_) | ExprKind::Name(_) => vec![],
            ExprKind::Neg(a) => vec![a],
            ExprKind::Call(_, _, args) => args.iter().collect(),
            ExprKind::Add(a, b)
            | ExprKind::Sub(a, b)
            | ExprKind::Mul(a, b)
            | ExprKind::Div(a, b)
            | ExprKind::Pow(a, b)
            | ExprKind::Bracket(a, b) => vec![a, b],
        }
    }

    /// Compact S-expression rendering of a tree, e.g. `(- (^ x 2))`; brackets are `({} f g)`.
    fn sexp(e: &Expr) -> String {
        let head = match &e.kind {
            ExprKind::Integer(n) => return n.to_string(),
            ExprKind::Name(name) => return name.clone(),
            ExprKind::Neg(_) | ExprKind::Sub(..) => "-",
            ExprKind::Add(..) => "+",
            ExprKind::Mul(..) => "*",
            ExprKind::Div(..) => "/",
            ExprKind::Pow(..) => "^",
            ExprKind::Bracket(..) => "{}",
            ExprKind::Call(f, ..) => f,
        };
        let args: Vec<String> = kids(e).into_iter().map(sexp).collect();
        format!("({head} {})", args.join(" "))
    }

    fn parse(src: &str) -> String {
        match parse_expr(src) {
            Ok(e) => sexp(&e),
            Err(e) => panic!("{src:?} failed to parse:\n{}", e.render(src)),
        }
    }

    /// Every span lies on char boundaries inside its parent's span, and children are in order.
    fn check_spans(src: &str, e: &Expr, outer: Span) {
        let s = e.span;
        assert!(
            outer.start <= s.start && s.start < s.end && s.end <= outer.end,
            "{src:?}"
        );
        assert!(
            src.is_char_boundary(s.start) && src.is_char_boundary(s.end),
            "{src:?}"
        );
        if let ExprKind::Call(_, name, _) = &e.kind {
            assert!(name.start == s.start && name.end < s.end, "{src:?}");
        }
        // A power written between a function and its argument, `cos²θ`, `\cos^{2}\theta`,
        // `sin²(θ)`, stands inside the call it raises, after the function's name.
        if let ExprKind::Pow(base, exponent) = &e.kind {
            if let ExprKind::Call(_, name, args) = &base.kind {
                if exponent.span.start < base.span.end {
                    let inside =
                        name.end <= exponent.span.start && exponent.span.end <= args[0].span.start;
                    assert!(inside, "{src:?}");
                    check_spans(src, base, s);
                    check_spans(src, exponent, s);
                    return;
                }
            }
        }
        let mut start = s.start;
        for kid in kids(e) {
            assert!(start <= kid.span.start, "{src:?}");
            check_spans(src, kid, s);
            start = kid.span.end;
        }
    }

    /// A tree's names in source order with their spans (a parenthesized name's includes the
    /// parentheses): a call's arguments, not its name.
    #[test]
    fn names_in_source_order_with_spans() {
        let src = "{f, cos(x + y)} + 2*x^k - (h)";
        let e = parse_expr(src).expect("parses");
        let names: Vec<(&str, &str)> = e
            .names()
            .into_iter()
            .map(|(n, span)| (n, &src[span.start..span.end]))
            .collect();
        assert_eq!(
            names,
            [
                ("f", "f"),
                ("x", "x"),
                ("y", "y"),
                ("x", "x"),
                ("k", "k"),
                ("h", "(h)")
            ]
        );
    }

    #[test]
    fn precedence_and_associativity() {
        let cases = [
            ("1+2*3", "(+ 1 (* 2 3))"),
            ("1-2-3", "(- (- 1 2) 3)"),
            ("a/b/c", "(/ (/ a b) c)"),
            ("a*b/c*d", "(* (/ (* a b) c) d)"),
            ("x^y^z", "(^ x (^ y z))"),
            ("x**2", "(^ x 2)"),
            ("-x^2", "(- (^ x 2))"),
            ("x^-2", "(^ x (- 2))"),
            ("x^-y*z", "(* (^ x (- y)) z)"),
            ("-x*y", "(* (- x) y)"),
            ("--x", "(- (- x))"),
            ("+x - +1", "(- x 1)"),
            ("2^-x^2", "(^ 2 (- (^ x 2)))"),
            (
                "3/4*x^-2 - 7*y^(-3)",
                "(- (* (/ 3 4) (^ x (- 2))) (* 7 (^ y (- 3))))",
            ),
            ("a - (b - c)", "(- a (- b c))"),
            ("cos(theta)^2", "(^ (cos theta) 2)"),
            ("f(a, b+1, g(c))", "(f a (+ b 1) (g c))"),
            ("{L, G1} + G2", "(+ ({} L G1) G2)"),
            ("{x^2, {a, b}}*2", "(* ({} (^ x 2) ({} a b)) 2)"),
            ("p_x^2/(2*M)", "(/ (^ p_x 2) (* 2 M))"),
            (
                "123456789012345678901234567890",
                "123456789012345678901234567890",
            ),
            (
                "(p_x - M*omega*y)*cos(theta)",
                "(* (- p_x (* (* M omega) y)) (cos theta))",
            ),
            (
                "(p_x + i*p_y)^3 * exp(-i*2*θ)",
                "(* (^ (+ p_x (* i p_y)) 3) (exp (* (* (- i) 2) θ)))",
            ),
            // Unicode names, operators and superscripts.
            ("ω²", "(^ ω 2)"),
            ("M⁻¹", "(^ M (- 1))"),
            ("ω¹⁰ + x⁰", "(+ (^ ω 10) (^ x 0))"),
            ("-x²", "(- (^ x 2))"),
            ("(x+y)³", "(^ (+ x y) 3)"),
            ("x^(y²)", "(^ x (^ y 2))"),
            (
                "a − b · c × d ⋅ e ∗ g ÷ f",
                "(- a (/ (* (* (* (* b c) d) e) g) f))",
            ),
            ("p_θ²/(2·I) + α₁", "(+ (/ (^ p_θ 2) (* 2 I)) α₁)"),
            ("\u{3000}x\u{a0}+\ty\n", "(+ x y)"),
        ];
        for (src, want) in cases {
            assert_eq!(parse(src), want, "{src}");
        }
    }

    #[test]
    fn juxtaposition_multiplies_as_the_text_form_prints() {
        let cases = [
            ("2M", "(* 2 M)"),
            ("x p_y - y p_x", "(- (* x p_y) (* y p_x))"),
            ("p_x²/(2M)", "(/ (^ p_x 2) (* 2 M))"),
            ("−ω² L", "(* (- (^ ω 2)) L)"),
            ("x^2 y", "(* (^ x 2) y)"),
            ("(a+b)(a-b)", "(* (+ a b) (- a b))"),
            ("x cos θ", "(* x (cos θ))"),
            ("cos²θ sin θ", "(* (^ (cos θ) 2) (sin θ))"),
            // A power after the parentheses of a call raised before them raises the call, in
            // a superscript character as after `^`.
            ("sin²(θ)³ x", "(* (^ (^ (sin θ) 2) 3) x)"),
            ("sin²(θ)^3 x", "(* (^ (^ (sin θ) 2) 3) x)"),
            ("(3 + 4i) x", "(* (+ 3 (* 4 i)) x)"),
            // After a divisor in parentheses, a factor written next to it multiplies.
            ("p²/(2M) x", "(* (/ (^ p 2) (* 2 M)) x)"),
            ("x/2*M", "(* (/ x 2) M)"),
            ("(x/2)M", "(* (/ x 2) M)"),
            // The exponential as the paper (and the text form) writes it; `e` to a power
            // without braces is a power of a name `e`.
            ("Z² e^{−iθ}", "(* (^ Z 2) (exp (- iθ)))"),
            ("e^{i*(θ - φ)}^2", "(^ (exp (* i (- θ φ))) 2)"),
            ("e^2", "(^ e 2)"),
        ];
        for (src, want) in cases {
            assert_eq!(sexp(&parse_expr(src).unwrap()), want, "{src}");
        }
    }

    /// LaTeX math reads as the plain syntax it writes: commands, fractions, braces of
    /// exponents and subscripts, the bracket `\{f, g\}`, spacing and sizing.
    #[test]
    fn latex_reads_as_the_plain_syntax() {
        let cases = [
            (r"x^{2}", "(^ x 2)"),
            (r"y/x^{ 2/3 }", "(/ y (^ x (/ 2 3)))"),
            (r"x**{-1}", "(^ x (- 1))"),
            (r"x^{-2} y", "(* (^ x (- 2)) y)"),
            // A comma in the braces makes them a bracket, as in the plain syntax.
            (r"x^{f, g}", "(^ x ({} f g))"),
            (r"\frac{1}{2}\omega^{2} L", "(* (* (/ 1 2) (^ ω 2)) L)"),
            (
                r"\tfrac{p_{x}^{2}}{2 M} + \dfrac{a}{b}",
                "(+ (/ (^ p_x 2) (* 2 M)) (/ a b))",
            ),
            (r"x/\frac{1}{2} y", "(* (/ x (/ 1 2)) y)"),
            (r"p_{\theta} + p_\theta + p_x", "(+ (+ p_θ p_θ) p_x)"),
            (r"\{G_{1}, G_{2}\}", "({} G_1 G_2)"),
            (
                r"\left\{L, G_{1}\right\} + \bigl(a\bigr)",
                "(+ ({} L G_1) a)",
            ),
            (r"\omega_{x,2} \Omega \alpha_1", "(* (* ω_x_2 Ω) α_1)"),
            (
                r"\bar{K}_{3,2} \overline{Z} \bar{Z}_{x}",
                "(* (* K̄_3_2 Z̄) Z̄_x)",
            ),
            (r"G_{1}' + K_{1;1,2}", "(+ G_1' K_1_1_2)"),
            // A superscript on an empty group is the power of what stands before it: a name
            // with a prime (`P'_{1,1}` as superint prints its square), one in parentheses, a
            // fraction; and inside an exponent's braces, of the exponent.
            (
                r"P'_{1,1}{}^{2} + L'^{2} + x {}^{2}",
                "(+ (+ (^ P'_1_1 2) (^ L' 2)) (^ x 2))",
            ),
            (
                r"(x^{2}){}^{3} + x^{2{}^{3}} + \frac{1}{x}{}^{2}",
                "(+ (+ (^ (^ x 2) 3) (^ x (^ 2 3))) (^ (/ 1 x) 2))",
            ),
            // A superscript character in an exponent's parentheses or braces is the power of
            // what stands before it there.
            (r"x^(2²) + x^{2³}", "(+ (^ x (^ 2 2)) (^ x (^ 2 3)))"),
            // After a minus sign, of what follows it (in braces, of the exponent's number).
            (
                r"-x{}^{2} + x^{-2{}^{3}}",
                "(+ (- (^ x 2)) (^ x (- (^ 2 3))))",
            ),
            // A superscript character on an empty group, as on `{}^`.
            (r"P'_{1,1}{}² + x{ }⁻¹", "(+ (^ P'_1_1 2) (^ x (- 1)))"),
            (r"\mathrm{e}^{-\mathrm{i}\theta}", "(exp (* (- i) θ))"),
            (r"e^{-i\theta}", "(exp (* (- i) θ))"),
            (
                r"\exp(i\varphi) - \exp\left(i \phi\right)",
                "(- (exp (* i φ)) (exp (* i φ)))",
            ),
            // Both forms of epsilon and of phi, in LaTeX and in Unicode, are one letter each
            // (the lunate ϵ and the curly ϕ, which LaTeX sets for \epsilon and \phi, were
            // names of their own that no system could declare).
            (
                r"\epsilon \varepsilon ε ϵ + p_{ϵ} + x_ϵ ϕ²",
                "(+ (+ (* (* (* ε ε) ε) ε) p_ε) (* x_ε (^ φ 2)))",
            ),
            (r"\cos\theta + \sin \varphi", "(+ (cos θ) (sin φ))"),
            (
                r"\cos^{3}\theta \sin(2\theta)",
                "(* (^ (cos θ) 3) (sin (* 2 θ)))",
            ),
            (r"a \cdot b \times c \div d", "(/ (* (* a b) c) d)"),
            (
                r"2\,x\;y\!z\:w\quad v\qquad u\ t",
                "(* (* (* (* (* (* (* 2 x) y) z) w) v) u) t)",
            ),
            (r"\sqrt{x^{2} + y^{2}}", "(sqrt (+ (^ x 2) (^ y 2)))"),
            (
                r"\operatorname{conj}(P_{2,3}) + \operatorname{Re}(Z) + \Re(Z)",
                "(+ (+ (conj P_2_3) (Re Z)) (Re Z))",
            ),
            (
                r"\hbar\ell \mathrm{xy}_{10} \mathrm{{\omega}x}",
                "(* (* (* ħ ℓ) xy_10) ωx)",
            ),
            // The real part of a name as LaTeX sets it is one name, as a display `Re A` is.
            (r"\omega \operatorname{Im} K + \Re A", "(+ (* ω Im K) Re A)"),
            (
                r"i(2\omega - 3\Omega) K_{2,3}",
                "(* (i (- (* 2 ω) (* 3 Ω))) K_2_3)",
            ),
            (
                r"\displaystyle M\omega^{2}(x^{2} + y^{2})/2",
                "(/ (* (* M (^ ω 2)) (+ (^ x 2) (^ y 2))) 2)",
            ),
        ];
        for (src, want) in cases {
            assert_eq!(parse(src), want, "{src}");
            // A power of cos written between it and its angle is inside the call's span, as
            // cos²θ's is.
            if !src.contains(r"\cos^") {
                check_spans(src, &parse_expr(src).unwrap(), Span::new(0, src.len()));
            }
        }
        // A name written in LaTeX, whole.
        assert_eq!(latex_name(r"p_{\theta}").as_deref(), Some("p_θ"));
        assert_eq!(
            latex_name(r"\mathrm{Lambda3x}").as_deref(),
            Some("Lambda3x")
        );
        assert_eq!(latex_name(r"\omega_{+}").as_deref(), Some("ω_+"));
        assert_eq!(latex_name("x y"), None);
        assert_eq!(latex_name(r"\foo"), None);
    }

    #[test]
    fn spans() {
        let src = "2*cos(theta)^2 + {ω, x⁻¹}";
        let e = parse_expr(src).unwrap();
        check_spans(src, &e, Span::new(0, src.len()));
        let text = |e: &Expr| &src[e.span.start..e.span.end];
        let call = kids(kids(kids(&e)[0])[1])[0];
        assert_eq!((text(call), call.span), ("cos(theta)", Span::new(2, 12)));
        let ExprKind::Call(_, name, _) = &call.kind else {
            panic!("not a call")
        };
        assert_eq!(&src[name.start..name.end], "cos");
        let x_inv = kids(kids(&e)[1])[1];
        let exponent = kids(x_inv)[1];
        assert_eq!(
            (text(x_inv), text(exponent), text(kids(exponent)[0])),
            ("x⁻¹", "⁻¹", "¹")
        );
        // Parenthesized expressions include their parentheses.
        let e = parse_expr("-(a + b)^ 2").unwrap();
        assert_eq!(
            (e.span, kids(kids(&e)[0])[0].span),
            (Span::new(0, 11), Span::new(1, 8))
        );
    }

    /// Rejected inputs with the expected (line, column) and message.
    #[rustfmt::skip]
    const REJECTED: &[(&str, (usize, usize), &str)] = &[
        ("", (1, 1), "expected an expression, found end of input"),
        ("   ", (1, 4), "expected an expression, found end of input"),
        (" \n ", (1, 2), "expected an expression, found end of input"),
        ("x^", (1, 3), "expected an expression after '^', found end of input"),
        ("1 +", (1, 4), "expected an expression after '+', found end of input"),
        ("x**", (1, 4), "expected an expression after '**', found end of input"),
        ("1 + * 2", (1, 5), "expected an expression after '+', found '*'"),
        ("*x", (1, 1), "expected an expression, found '*'"),
        ("x+²", (1, 3), "expected an expression after '+', found superscript '²'"),
        ("cos(x", (1, 6), "expected ')' to close '(' opened at column 4, found end of input"),
        ("(1+x", (1, 5), "expected ')' to close '(' opened at column 1, found end of input"),
        ("f(x}", (1, 4), "expected ')' to close '(' opened at column 2, found '}'"),
        ("cos()", (1, 5), "expected an expression after '(', found ')'"),
        ("x $ y", (1, 3), "unexpected character '$'"),
        ("θ ∂ y", (1, 3), "unexpected character '∂'"),
        ("1.5", (1, 1), "decimal numbers are not exact; write a fraction: 1.5 is 3/2"),
        ("x + .25", (1, 5), "decimal numbers are not exact; write a fraction: .25 is 1/4"),
        ("0.50*x", (1, 1), "decimal numbers are not exact; write a fraction: 0.50 is 1/2"),
        ("x + 2.", (1, 5), "decimal numbers are not exact; write a fraction: 2. is 2"),
        (".", (1, 1), "unexpected character '.'"),
        ("{f g}", (1, 5), "expected ',' between the two arguments of a bracket {f, g}, found '}'"),
        ("{f}", (1, 3), "expected ',' between the two arguments of a bracket {f, g}, found '}'"),
        ("{f, g, h}", (1, 6), "a bracket {f, g} takes exactly two arguments; \
                               expected '}' to close '{' opened at column 1, found ','"),
        ("{f, g", (1, 6), "expected '}' to close '{' opened at column 1, found end of input"),
        ("e^{x", (1, 5), "expected '}' to close '{' opened at column 3, found end of input"),
        ("e^{x, y}", (1, 5), "expected '}' to close '{' opened at column 3, found ','"),
        // An exponent in braces is read as LaTeX writes it; one that is no bracket is closed
        // by its brace.
        ("x^{2)", (1, 5), "expected '}' to close '{' opened at column 3, found ')'"),
        ("x^{2", (1, 5), "expected '}' to close '{' opened at column 3, found end of input"),
        ("x^{f, g", (1, 8), "expected '}' to close '{' opened at column 3, found end of input"),
        // LaTeX: an unknown command, by name, and what a command needs after it.
        ("\\foo + 1", (1, 1), "unknown LaTeX command '\\foo': an expression reads Greek \
                              letters (\\omega), \\frac, \\sqrt, \\cdot, \\times, \\cos, \\sin, \
                              \\exp, \\bar, \\mathrm, \\{ \\} and spacing"),
        ("2\\omegax", (1, 2), "unknown LaTeX command '\\omegax': an expression reads Greek \
                              letters (\\omega), \\frac, \\sqrt, \\cdot, \\times, \\cos, \\sin, \
                              \\exp, \\bar, \\mathrm, \\{ \\} and spacing"),
        ("x \\$ y", (1, 3), "unknown LaTeX command '\\$': an expression reads Greek \
                              letters (\\omega), \\frac, \\sqrt, \\cdot, \\times, \\cos, \\sin, \
                              \\exp, \\bar, \\mathrm, \\{ \\} and spacing"),
        ("x + \\", (1, 5), "expected a LaTeX command after '\\', found end of input"),
        ("\\frac{1}", (1, 9), "expected '{' with the denominator of '\\frac', found end of \
                              input; write \\frac{1}{2}, \\sqrt{x}"),
        ("\\tfrac12", (1, 7), "expected '{' with the numerator of '\\tfrac', found '12'; write \
                              \\frac{1}{2}, \\sqrt{x}"),
        ("\\sqrt x", (1, 7), "expected '{' with the radicand of '\\sqrt', found 'x'; write \
                              \\frac{1}{2}, \\sqrt{x}"),
        ("\\frac{1}{2", (1, 11), "expected '}' to close '{' opened at column 9, found end of \
                                 input"),
        ("p_\\", (1, 3), "expected a LaTeX command after '\\', found end of input"),
        // A subscript after a power, as LaTeX may write it, or after no name, is refused as
        // such (it read as a name `_1`, unknown).
        ("x^{2}_{1}", (1, 6), "'_{1}' is a subscript with no name before it: a subscript \
                               follows its name, before a power, as in x_{1}^{2}"),
        ("x²_1 + 1", (1, 3), "'_1' is a subscript with no name before it: a subscript follows \
                              its name, before a power, as in x_{1}^{2}"),
        // A command an expression reads as no name is none in a subscript or a name's braces.
        ("p_\\frac{1}{2}", (1, 2), "expected a subscript after '_': a letter, a digit, or a \
                                    name in braces, p_{x}"),
        ("p_\\,x", (1, 2), "expected a subscript after '_': a letter, a digit, or a name in \
                            braces, p_{x}"),
        ("p_{\\cdot}", (1, 4), "expected a letter, a digit or '}' in the name's braces opened \
                                at column 3, found '\\cdot'"),
        ("\\bar{\\{x}", (1, 6), "expected a letter, a digit or '}' in the name's braces \
                                opened at column 5, found '\\{'"),
        ("p_{x + 1", (1, 3), "the '{' of this name is never closed: expected '}'"),
        ("p_{x$}", (1, 5), "expected a letter, a digit or '}' in the name's braces opened at \
                            column 3, found '$'"),
        // A sizing command is quoted with its delimiter: it was skipped as a space, and the
        // delimiter refused alone.
        ("p_{\\left(}", (1, 4), "expected a letter, a digit or '}' in the name's braces \
                                 opened at column 3, found '\\left('"),
        ("p_{x\\bigr \\}}", (1, 5), "expected a letter, a digit or '}' in the name's braces \
                                    opened at column 3, found '\\bigr \\}'"),
        ("\\omega_{\n\\left.}", (2, 1), "expected a letter, a digit or '}' in the name's \
                                        braces opened at line 1, column 8, found '\\left.'"),
        ("\\omega_ + 1", (1, 7), "expected a subscript after '_': a letter, a digit, or a name \
                                 in braces, p_{x}"),
        ("\\bar{} + 1", (1, 1), "'\\bar{}' holds no name"),
        ("\\bar Z", (1, 1), "expected '{' after '\\bar', as in \\bar{Z}"),
        ("\\{f, g", (1, 7), "expected '}' to close '\\{' opened at column 1, found end of \
                             input"),
        ("\\cos^{2}", (1, 9), "expected an angle or '(' after 'cos'"),
        (")", (1, 1), "unexpected ')'"),
        ("x)", (1, 2), "unexpected ')'"),
        ("a, b", (1, 2), "unexpected ','"),
        ("x⁻", (1, 2), "expected superscript digits such as '¹' after superscript minus '⁻'"),
        ("x\n  + (y\n  * z", (3, 6),
            "expected ')' to close '(' opened at line 2, column 5, found end of input"),
        ("α +\n β ·\n\n", (2, 5), "expected an expression after '·', found end of input"),
        // A factor written next to a divisor: `(p²/2)m` by the rules, `p²/(2m)` to a reader
        // of physics; neither is guessed.
        ("p_x^2/2m", (1, 7), "'/2m' is ambiguous: write '/(2m)' to divide by the product, \
                              or '/2*m' to divide by 2 alone"),
        ("1/2 M x", (1, 3), "'/2 M' is ambiguous: write '/(2 M)' to divide by the product, \
                             or '/2*M' to divide by 2 alone"),
        ("p²/2Mr²", (1, 4), "'/2Mr' is ambiguous: write '/(2Mr)' to divide by the product, \
                             or '/2*Mr' to divide by 2 alone"),
        ("x/2(y + 1)", (1, 3), "'/2(…)' is ambiguous: write '/(2(…))' to divide by the \
                                product, or '/2*(…)' to divide by 2 alone"),
        ("x/y^2 z", (1, 3), "'/y^2 z' is ambiguous: write '/(y^2 z)' to divide by the \
                             product, or '/y^2*z' to divide by y^2 alone"),
        // A function before its angle is quoted with it: `/(2 cos)` does not read.
        ("p²/2 cos θ x", (1, 4), "'/2 cos θ' is ambiguous: write '/(2 cos θ)' to divide by the \
                                  product, or '/2*cos θ' to divide by 2 alone"),
        // So is any function before its arguments: `/(2 sqrt)` and `/(2 e)` do not read.
        ("x/2 sqrt(x) y", (1, 3), "'/2 sqrt(x)' is ambiguous: write '/(2 sqrt(x))' to divide by \
                                   the product, or '/2*sqrt(x)' to divide by 2 alone"),
        ("x/2 Re(x)", (1, 3), "'/2 Re(x)' is ambiguous: write '/(2 Re(x))' to divide by the \
                               product, or '/2*Re(x)' to divide by 2 alone"),
        ("x/2 e^{iθ}", (1, 3), "'/2 e^{iθ}' is ambiguous: write '/(2 e^{iθ})' to divide by the \
                                product, or '/2*e^{iθ}' to divide by 2 alone"),
        ("x/2 \\operatorname{Re} (x)", (1, 3), "'/2 \\operatorname{Re} (x)' is ambiguous: \
                                               write '/(2 \\operatorname{Re} (x))' to divide \
                                               by the product, or '/2*\\operatorname{Re} (x)' \
                                               to divide by 2 alone"),
        ("x/M \\sin^{2}\\theta", (1, 3), "'/M \\sin^{2}\\theta' is ambiguous: write \
                                         '/(M \\sin^{2}\\theta)' to divide by the product, or \
                                         '/M*\\sin^{2}\\theta' to divide by M alone"),
        ("cos θ² + 1", (1, 5), "'cos θ' followed by a power is ambiguous: write cos²θ or \
                                cos(θ)^2 for the square of cos θ"),
        ("sin theta^2", (1, 5), "'sin theta' followed by a power is ambiguous: write \
                                 sin²theta or sin(theta)^2 for the square of sin theta"),
        ("cos θ^{2}", (1, 5), "'cos θ' followed by a power is ambiguous: write cos²θ or \
                               cos(θ)^2 for the square of cos θ"),
        // Written in LaTeX, the function or its angle is quoted and squared as written (it was
        // quoted by its names, 'cos cos', with cos²cos to write).
        ("\\cos cos²", (1, 6), "'\\cos cos' followed by a power is ambiguous: write \
                                \\cos^{2} cos or \\cos(cos)^{2} for the square of \\cos cos"),
        ("\\cos\\theta^{2}", (1, 5), "'\\cos\\theta' followed by a power is ambiguous: \
                                      write \\cos^{2}\\theta or \\cos(\\theta)^{2} for the \
                                      square of \\cos\\theta"),
        ("cos \\theta²", (1, 5), "'cos \\theta' followed by a power is ambiguous: write \
                                  cos^{2} \\theta or cos(\\theta)^{2} for the square of \
                                  cos \\theta"),
        // The lunate epsilon, which reads as ε, is no LaTeX: the plain advice (it was told
        // by the names, 'cos ε', and given LaTeX's, cos^{2} ϵ).
        ("cos ϵ²", (1, 5), "'cos ϵ' followed by a power is ambiguous: write cos²ϵ or \
                            cos(ϵ)^2 for the square of cos ϵ"),
        // Another power is no square: both readings are written, as after a power of the
        // function.
        ("sin θ³", (1, 5), "'sin θ' followed by a power is ambiguous: write (sin θ)³ for a \
                            power of sin θ, or sin(θ³) for sin of θ³"),
        ("sin theta^2^3", (1, 5), "'sin theta' followed by a power is ambiguous: write \
                                   (sin theta)^2^3 for a power of sin theta, or \
                                   sin(theta^2^3) for sin of theta^2^3"),
        ("\\cos\\varphi{}^{-1}", (1, 5), "'\\cos\\varphi' followed by a power is ambiguous: \
                                         write (\\cos\\varphi)^{-1} for a power of \
                                         \\cos\\varphi, or \\cos(\\varphi^{-1}) for \\cos \
                                         of \\varphi^{-1}"),
        // Two superscripts after the function, side by side, show as one.
        ("sin² ²θ", (1, 6), "'²' after 'sin²', which has a superscript already, is ambiguous: \
                             the two superscripts show side by side, as one; write the exponent \
                             in one group"),
        ("sin²{}²θ", (1, 5), "'{}²' after 'sin²', which has a superscript already, is \
                              ambiguous: the two superscripts show side by side, as one; write \
                              the exponent in one group"),
        ("\\sin^{2}{}^{3}\\theta", (1, 9), "'{}^{3}' after '\\sin^{2}', which has a \
                                            superscript already, is ambiguous: LaTeX sets the \
                                            two superscripts side by side, as one; write the \
                                            exponent in one group"),
        // A `^` after the function's superscript character may raise the power or its
        // exponent, as after `r²`; it was taken for `sin^2 theta`.
        ("sin²^3θ", (1, 5), "'^3' after 'sin²', which has a superscript already, is \
                             ambiguous: it may raise the power or its exponent; write the \
                             exponent in one group"),
        ("cos³^{2}(θ)", (1, 5), "'^{2}' after 'cos³', which has a superscript already, is \
                                 ambiguous: it may raise the power or its exponent; write the \
                                 exponent in one group"),
        // So may one after the function's exponent in LaTeX, which LaTeX itself refuses as
        // a double superscript; it was taken for `sin^2 theta` too.
        ("\\sin^{2}^{3}\\theta", (1, 9), "'^{3}' after '\\sin^{2}', which has a superscript \
                                          already, is ambiguous: it may raise the power or its \
                                          exponent; write the exponent in one group"),
        ("\\cos^{2}^3(\\theta)", (1, 9), "'^3' after '\\cos^{2}', which has a superscript \
                                          already, is ambiguous: it may raise the power or its \
                                          exponent; write the exponent in one group"),
        ("sin²^", (1, 6), "expected an expression after '^', found end of input"),
        ("\\sin^{2}^", (1, 10), "expected an expression after '^', found end of input"),
        // A power of the angle after a power of its function: `(sin²θ)³` or `sin²(θ³)`.
        ("sin²θ^3", (1, 5), "'sin²θ' followed by a power is ambiguous: write (sin²θ)^3 for a \
                             power of sin²θ, or sin²(θ^3) for sin² of θ^3"),
        ("\\cos^{2}\\theta^{3}", (1, 9), "'\\cos^{2}\\theta' followed by a power is ambiguous: \
                                         write (\\cos^{2}\\theta)^{3} for a power of \
                                         \\cos^{2}\\theta, or \\cos^{2}(\\theta^{3}) for \
                                         \\cos^{2} of \\theta^{3}"),
        // A LaTeX space before the power is no part of it (it was written into both readings).
        ("sin²θ\\,^3", (1, 5), "'sin²θ' followed by a power is ambiguous: write (sin²θ)^3 for a \
                                 power of sin²θ, or sin²(θ^3) for sin² of θ^3"),
        ("r²^", (1, 4), "expected an expression after '^', found end of input"),
        // A superscript character on an empty group is a power as `{}^2` is: of a bare angle
        // after a powered function, or beside another superscript, ambiguous as they are.
        ("sin²θ{}²", (1, 5), "'sin²θ' followed by a power is ambiguous: write (sin²θ)² for a \
                              power of sin²θ, or sin²(θ²) for sin² of θ²"),
        ("x^{2}{}²", (1, 6), "'{}²' after 'x^{2}', which has a superscript already, is \
                              ambiguous: the two superscripts show side by side, as one; put \
                              'x^{2}' in parentheses for a power of it, or write the exponent \
                              in one group"),
        // After the parentheses of `sin²(θ)` a superscript raises the call, and a second one
        // stands beside it.
        ("sin²(θ)³²⁻¹", (1, 10), "'⁻¹' after 'sin²(θ)³²', which has a superscript already, \
                                 is ambiguous: the two superscripts show side by side, as one; \
                                 put 'sin²(θ)³²' in parentheses for a power of it, or write \
                                 the exponent in one group"),
        // Characters pasted from print, with what to write instead.
        ("½x", (1, 1), "unexpected character '½'; write a fraction such as 1/2"),
        ("x – y", (1, 3), "unexpected character '–'; a dash is no minus sign: write '-' or '−'"),
        // `√` as the text form prints a root takes parentheses, a name or a number, with no
        // power after the name.
        ("k/√-x", (1, 4), "expected '(', a name or a number after '√', found '-'; write \
                           √(x^2 + y^2) or √x"),
        ("k/√x²", (1, 5), "a power after '√x' is ambiguous: write (√x)^2 for a power of the \
                           root, or √(x^2)"),
        // A number run into a name: the root of the product (as `√xy` is of the names run
        // together) or the root times the name.
        ("k/√4x", (1, 5), "'√4x' is ambiguous: write √(4x) for the root of the product, or √4 x \
                           for the root times x"),
        ("√12ab", (1, 4), "'√12ab' is ambiguous: write √(12ab) for the root of the product, or \
                           √12 ab for the root times ab"),
        // Mathematica's calls, with what to write instead.
        ("k/Sqrt[x^2 + y^2]", (1, 7), "unexpected character '['; a function takes its \
                                       argument in parentheses, sqrt(x^2 + y^2), cos(theta), \
                                       not square brackets, and the Poisson bracket is \
                                       written {f, g}"),
        ("1e3 x", (1, 1), "'1e3' is no number: write a power of ten as 1*10^3, and a product \
                           with a name as 1*e3"),
        ("x + 2E-5", (1, 5), "'2E-5' is no number: write a power of ten as 2*10^-5"),
        ("sin^2 theta", (1, 4), "expected an angle or '(' after 'sin'; a power of sin is \
                                 written sin²θ or sin(theta)^2, not sin^2 theta"),
    ];

    #[test]
    fn rejected_inputs() {
        for &(src, line_col, message) in REJECTED {
            let err = parse_expr(src).expect_err(src);
            assert_eq!(
                (err.line_col(src), err.message()),
                (line_col, message),
                "{src:?}"
            );
        }
    }

    #[test]
    fn render() {
        let err = parse_expr("x^").unwrap_err();
        let want = "line 1, column 3: expected an expression after '^', found end of input";
        assert_eq!(err.render("x^"), format!("{want}\n  x^\n    ^"));
        let src = "a +\n\tθ $ b";
        let want = "line 2, column 4: unexpected character '$'\n  \tθ $ b\n  \t  ^";
        assert_eq!(parse_expr(src).unwrap_err().render(src), want);
        let src = "1 + 12.75*x";
        let err = parse_expr(src).unwrap_err();
        assert!(err.render(src).ends_with("\n  1 + 12.75*x\n      ^^^^^"));
        // It knows its source: its Display is the rendering.
        assert_eq!(err.to_string(), err.render(src));
        assert_eq!(ParseError::new(Span::new(0, 1), "m").to_string(), "m");
        // Out-of-range or mid-character spans do not panic.
        let err = ParseError::new(Span::new(99, 2), "m");
        assert_eq!(err.render("é"), "line 1, column 2: m\n  é\n   ^");
        assert_eq!(ParseError::new(Span::new(1, 1), "m").line_col("é"), (1, 1));
    }

    #[test]
    fn nesting_and_height_limits() {
        let nest = |n: usize, inner: &str| format!("{}{inner}{}", "(".repeat(n), ")".repeat(n));
        assert_eq!(parse(&nest(MAX_DEPTH, "x")), "x");
        let braces = |n: usize| format!("x_{}2{}", "{".repeat(n), "}".repeat(n));
        assert_eq!(parse(&braces(MAX_DEPTH)), "x_2");
        let bad = [
            nest(MAX_DEPTH + 1, "x"),
            "(".repeat(100_000),
            "{".repeat(100_000),
            "f(".repeat(100_000),
            "-".repeat(100_000) + "x",
            "x^".repeat(100_000) + "x",
            "(-x^".repeat(100_000),
            // The braces of a name's subscript and of a bar, read by the lexer.
            "x_{".repeat(100_000),
            format!("x_{}2{}", "{".repeat(100_000), "}".repeat(100_000)),
            r"\bar{".repeat(100_000),
            format!("p_{}", r"\mathrm{".repeat(MAX_DEPTH + 1)),
        ];
        for src in bad {
            let err = parse_expr(&src).unwrap_err();
            assert_eq!(
                err.message(),
                "expression nested too deeply (more than 256 levels)"
            );
        }
        // Long chains are parsed iteratively. Products make left-deep trees, whose height is
        // limited; sums longer than LEFT_DEEP_SUM are balanced, so any length parses.
        let product = |n: usize| vec!["x"; n].join(" * ");
        let e = parse_expr(&nest(MAX_DEPTH - 1, &product(MAX_HEIGHT))).unwrap();
        let (mut node, mut height) = (&e, 1);
        while let ExprKind::Mul(lhs, _) = &node.kind {
            (node, height) = (lhs, height + 1);
        }
        assert_eq!(height, MAX_HEIGHT);
        fn height_of(e: &Expr) -> usize {
            1 + kids(e).into_iter().map(height_of).max().unwrap_or(0)
        }
        let sum = |n: usize| vec!["x"; n].join(" + ");
        assert_eq!(
            height_of(&parse_expr(&sum(LEFT_DEEP_SUM)).unwrap()),
            LEFT_DEEP_SUM
        );
        assert_eq!(height_of(&parse_expr(&sum(100_000)).unwrap()), 18);
        let bad = [
            nest(MAX_DEPTH - 1, &product(MAX_HEIGHT + 1)),
            product(100_000),
        ];
        for src in bad {
            let err = parse_expr(&src).unwrap_err();
            let msg = "expression too long: more than 2048 levels of operations";
            assert!(err.message().starts_with(msg), "{}", err.message());
        }
        // A run of superscripts, which made a tree as high as it was long, is refused at its
        // second, as ambiguous.
        let err = parse_expr(&format!("x{}", "⁻¹".repeat(3000))).unwrap_err();
        assert_eq!((err.span.start, err.span.end), (6, 11), "{}", err.message());
    }

    /// Parsing must never panic; parsed trees have consistent spans, errors valid ones.
    fn check_no_panic(src: &str) {
        match parse_expr(src) {
            Ok(e) => check_spans(src, &e, Span::new(0, src.len())),
            Err(e) => {
                assert!(
                    e.span.start <= e.span.end && e.span.end <= src.len(),
                    "{src:?}"
                );
                assert!(e.render(src).starts_with("line "));
            }
        }
    }

    #[test]
    fn fuzz_never_panics() {
        let alphabet: Vec<char> = "xe1+-*/^(){},. ²⁻−·\ni$é_\\".chars().collect();
        let mut layer = vec![String::new()];
        for _ in 0..=3 {
            layer.iter().for_each(|s| check_no_panic(s));
            layer = layer
                .iter()
                .flat_map(|s| alphabet.iter().map(move |c| format!("{s}{c}")))
                .collect();
        }
        // Deterministic xorshift generator for longer random inputs.
        let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        // LaTeX's commands and what follows them, superscripts, empty groups and functions
        // raised before their angle, among the characters.
        let words: Vec<String> = alphabet
            .iter()
            .map(char::to_string)
            .chain(
                [
                    r"\frac", r"\sqrt", r"\omega", r"\bar", r"\mathrm", r"\cos", r"\{", r"\}",
                    r"\left(", r"\,", "_{", "^{", r"\foo", "'", "³", "⁻¹", "{}", "{}^", "{}²",
                    "^{2}", r"\sin", r"\theta", r"\right)", "θ", "sin", "sin²", "cos³θ", "Re(",
                    "Im(", "∂", "∇", "Mω", "e^{",
                ]
                .map(String::from),
            )
            .collect();
        for _ in 0..20_000 {
            let len = (next() % 24) as usize;
            let s: String = (0..len)
                .map(|_| alphabet[next() as usize % alphabet.len()])
                .collect();
            check_no_panic(&s);
            let s: String = (0..len)
                .map(|_| words[next() as usize % words.len()].as_str())
                .collect();
            check_no_panic(&s);
            let bytes: Vec<u8> = (0..len).map(|_| next() as u8).collect();
            check_no_panic(&String::from_utf8_lossy(&bytes));
        }
    }
}
