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
//! - nesting (parentheses, calls, brackets, unary operators, exponents) is limited to
//!   [`MAX_DEPTH`] levels so that deep input cannot overflow the stack;
//! - chains like `a + b + c` are left-deep, so trees are limited to [`MAX_HEIGHT`] levels (this
//!   keeps dropping and walking them recursively safe).

mod error;
mod lexer;
mod parser;

pub use error::{ParseError, Span};
pub use parser::{parse_expr, Expr, ExprKind, MAX_DEPTH, MAX_HEIGHT};

#[cfg(test)]
mod tests {
    use super::*;

    /// Compact S-expression rendering of a tree, e.g. `(- (^ x 2))`.
    fn sexp(e: &Expr) -> String {
        let bin = |op: &str, a: &Expr, b: &Expr| format!("({op} {} {})", sexp(a), sexp(b));
        match &e.kind {
            ExprKind::Integer(n) => n.to_string(),
            ExprKind::Name(s) => s.clone(),
            ExprKind::Neg(a) => format!("(- {})", sexp(a)),
            ExprKind::Add(a, b) => bin("+", a, b),
            ExprKind::Sub(a, b) => bin("-", a, b),
            ExprKind::Mul(a, b) => bin("*", a, b),
            ExprKind::Div(a, b) => bin("/", a, b),
            ExprKind::Pow(a, b) => bin("^", a, b),
            ExprKind::Bracket(a, b) => format!("{{{} {}}}", sexp(a), sexp(b)),
            ExprKind::Call(f, _, args) => {
                let args: Vec<String> = args.iter().map(sexp).collect();
                format!("({f} {})", args.join(" "))
            }
        }
    }

    fn parse(src: &str) -> String {
        match parse_expr(src) {
            Ok(e) => sexp(&e),
            Err(e) => panic!("{src:?} failed to parse:\n{}", e.render(src)),
        }
    }

    /// Every span in the tree lies within `src` on char boundaries, inside its parent's span.
    fn check_spans(src: &str, e: &Expr, outer: Span) {
        let s = e.span;
        assert!(
            outer.start <= s.start && s.start <= s.end && s.end <= outer.end,
            "{src:?}"
        );
        assert!(
            src.is_char_boundary(s.start) && src.is_char_boundary(s.end),
            "{src:?}"
        );
        let mut children: Vec<&Expr> = Vec::new();
        match &e.kind {
            ExprKind::Integer(_) | ExprKind::Name(_) => {}
            ExprKind::Neg(a) => children.push(a),
            ExprKind::Call(_, name, args) => {
                check_spans(src, &Expr::new(ExprKind::Name(String::new()), *name), s);
                children.extend(args);
            }
            ExprKind::Add(a, b)
            | ExprKind::Sub(a, b)
            | ExprKind::Mul(a, b)
            | ExprKind::Div(a, b)
            | ExprKind::Pow(a, b)
            | ExprKind::Bracket(a, b) => children.extend([&**a, &**b]),
        }
        for c in children {
            check_spans(src, c, s);
        }
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
            ("(a+b)*(c-d)", "(* (+ a b) (- c d))"),
            ("a - (b - c)", "(- a (- b c))"),
            ("cos(theta)^2", "(^ (cos theta) 2)"),
            ("f(a, b+1, g(c))", "(f a (+ b 1) (g c))"),
            ("exp(-i*2*theta)", "(exp (* (* (- i) 2) theta))"),
            ("{L, G1} + G2", "(+ {L G1} G2)"),
            ("{x^2, {a, b}}*2", "(* {(^ x 2) {a b}} 2)"),
            ("p_x^2/(2*M)", "(/ (^ p_x 2) (* 2 M))"),
            (
                "123456789012345678901234567890",
                "123456789012345678901234567890",
            ),
        ];
        for (src, want) in cases {
            assert_eq!(parse(src), want, "{src}");
        }
        assert_eq!(
            parse("(p_x - M*omega*y)*cos(theta) + (p_y + M*omega*x)*sin(theta)"),
            "(+ (* (- p_x (* (* M omega) y)) (cos theta)) (* (+ p_y (* (* M omega) x)) (sin theta)))"
        );
        assert_eq!(
            parse("(p_x + i*p_y + i*M*omega*(x + i*y))^3 * exp(-i*2*theta)"),
            "(* (^ (+ (+ p_x (* i p_y)) (* (* (* i M) omega) (+ x (* i y)))) 3) \
             (exp (* (* (- i) 2) theta)))"
        );
    }

    #[test]
    fn unicode_names_operators_and_superscripts() {
        let cases = [
            ("ω²", "(^ ω 2)"),
            ("M⁻¹", "(^ M (- 1))"),
            ("ω¹⁰ + x⁰", "(+ (^ ω 10) (^ x 0))"),
            ("-x²", "(- (^ x 2))"),
            ("(x+y)³", "(^ (+ x y) 3)"),
            ("x^y²", "(^ x (^ y 2))"),
            ("a − b · c × d ⋅ e ÷ f", "(- a (/ (* (* (* b c) d) e) f))"),
            ("p_θ²/(2·I) + α₁", "(+ (/ (^ p_θ 2) (* 2 I)) α₁)"),
            ("\u{3000}x\u{a0}+\ty\n", "(+ x y)"),
            ("_x1", "_x1"),
        ];
        for (src, want) in cases {
            assert_eq!(parse(src), want, "{src}");
        }
    }

    #[test]
    fn spans() {
        let src = "2*cos(theta)^2 + {ω, x⁻¹}";
        let e = parse_expr(src).unwrap();
        check_spans(src, &e, Span::new(0, src.len()));
        let text = |s: Span| &src[s.start..s.end];
        assert_eq!(text(e.span), src);
        let ExprKind::Add(lhs, rhs) = &e.kind else {
            panic!()
        };
        let ExprKind::Mul(_, pow) = &lhs.kind else {
            panic!()
        };
        let ExprKind::Pow(call, _) = &pow.kind else {
            panic!()
        };
        assert_eq!(text(call.span), "cos(theta)");
        let ExprKind::Call(_, name, args) = &call.kind else {
            panic!()
        };
        assert_eq!((text(*name), text(args[0].span)), ("cos", "theta"));
        assert_eq!(call.span, Span::new(2, 12));
        let ExprKind::Bracket(_, g) = &rhs.kind else {
            panic!()
        };
        let ExprKind::Pow(_, exponent) = &g.kind else {
            panic!()
        };
        assert_eq!((text(g.span), text(exponent.span)), ("x⁻¹", "⁻¹"));
        let ExprKind::Neg(one) = &exponent.kind else {
            panic!()
        };
        assert_eq!(text(one.span), "¹");
        let src = "-(a + b)^ 2";
        let e = parse_expr(src).unwrap();
        let ExprKind::Neg(pow) = &e.kind else {
            panic!()
        };
        let ExprKind::Pow(base, _) = &pow.kind else {
            panic!()
        };
        assert_eq!((e.span, base.span), (Span::new(0, 11), Span::new(1, 8)));
    }

    #[test]
    fn rejected_inputs() {
        let cases: &[(&str, &str, (usize, usize))] = &[
            ("", "expected an expression, found end of input", (1, 1)),
            ("   ", "expected an expression, found end of input", (1, 4)),
            (
                "x^",
                "expected an expression after '^', found end of input",
                (1, 3),
            ),
            (
                "1 +",
                "expected an expression after '+', found end of input",
                (1, 4),
            ),
            (
                "x**",
                "expected an expression after '**', found end of input",
                (1, 4),
            ),
            (
                "1 + * 2",
                "expected an expression after '+', found '*'",
                (1, 5),
            ),
            ("*x", "expected an expression, found '*'", (1, 1)),
            (
                "x+²",
                "expected an expression after '+', found superscript '²'",
                (1, 3),
            ),
            (
                "cos(x",
                "expected ')' to close '(' opened at column 4, found end of input",
                (1, 6),
            ),
            (
                "(1+x",
                "expected ')' to close '(' opened at column 1, found end of input",
                (1, 5),
            ),
            (
                "f(x}",
                "expected ')' to close '(' opened at column 2, found '}'",
                (1, 4),
            ),
            (
                "cos()",
                "expected an expression after '(', found ')'",
                (1, 5),
            ),
            ("x $ y", "unexpected character '$'", (1, 3)),
            ("θ ∂ y", "unexpected character '∂'", (1, 3)),
            (
                "2x",
                "expected an operator such as '*' between '2' and 'x'",
                (1, 2),
            ),
            (
                "(a+b)(a-b)",
                "expected an operator such as '*' between ')' and '('",
                (1, 6),
            ),
            (
                "x^2 y",
                "expected an operator such as '*' between '2' and 'y'",
                (1, 5),
            ),
            (
                "(2 cos(x))",
                "expected an operator such as '*' between '2' and 'cos'",
                (1, 4),
            ),
            (
                "1.5",
                "decimal numbers are not exact; write a fraction such as 3/2",
                (1, 1),
            ),
            (
                "x + .25",
                "decimal numbers are not exact; write a fraction such as 3/2",
                (1, 5),
            ),
            (".", "unexpected character '.'", (1, 1)),
            (
                "{f g}",
                "expected ',' between the two arguments of a bracket {f, g}, found 'g'",
                (1, 4),
            ),
            (
                "{f}",
                "expected ',' between the two arguments of a bracket {f, g}, found '}'",
                (1, 3),
            ),
            (
                "{f, g, h}",
                "a bracket {f, g} takes exactly two arguments; \
                 expected '}' to close '{' opened at column 1, found ','",
                (1, 6),
            ),
            (
                "{f, g",
                "expected '}' to close '{' opened at column 1, found end of input",
                (1, 6),
            ),
            (")", "unexpected ')'", (1, 1)),
            ("x)", "unexpected ')'", (1, 2)),
            ("a, b", "unexpected ','", (1, 2)),
            (
                "x⁻",
                "expected superscript digits such as '¹' after superscript minus '⁻'",
                (1, 2),
            ),
            (
                "x\n  + (y\n  * z",
                "expected ')' to close '(' opened at line 2, column 5, found end of input",
                (3, 6),
            ),
            (
                "x +\n\n  2 y",
                "expected an operator such as '*' between '2' and 'y'",
                (3, 5),
            ),
            (
                "α +\n β ·\n",
                "expected an expression after '·', found end of input",
                (3, 1),
            ),
            (
                "abcdefghijklmnopqrstuvwxyz 1",
                "expected an operator such as '*' between 'abcdefghijklmnopqrst…' and '1'",
                (1, 28),
            ),
        ];
        for &(src, message, line_col) in cases {
            let err = parse_expr(src).expect_err(src);
            assert_eq!(
                (err.message.as_str(), err.line_col(src)),
                (message, line_col),
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
        let err = parse_expr(src).unwrap_err();
        assert_eq!(
            err.render(src),
            "line 2, column 4: unexpected character '$'\n  \tθ $ b\n  \t  ^"
        );
        let src = "1 + 12.75*x";
        let err = parse_expr(src).unwrap_err();
        assert!(err.render(src).ends_with("\n  1 + 12.75*x\n      ^^^^^"));
        assert_eq!(err.to_string(), err.message);
        // Out-of-range or mid-character spans never panic.
        assert_eq!(
            ParseError::new(Span::new(99, 2), "m").render("é"),
            "line 1, column 2: m\n  é\n   ^"
        );
        assert_eq!(ParseError::new(Span::new(1, 1), "m").line_col("é"), (1, 1));
    }

    #[test]
    fn nesting_limit() {
        let nested = |n: usize| format!("{}x{}", "(".repeat(n), ")".repeat(n));
        assert_eq!(parse(&nested(MAX_DEPTH)), "x");
        let too_deep = "expression nested too deeply (more than 256 levels)";
        for src in [
            nested(MAX_DEPTH + 1),
            "(".repeat(100_000),
            "{".repeat(100_000),
            "f(".repeat(100_000),
            "-".repeat(100_000) + "x",
            "x^".repeat(100_000) + "x",
            "(-x^".repeat(100_000),
        ] {
            let err = parse_expr(&src).unwrap_err();
            assert_eq!(err.message, too_deep);
        }
        // Long chains are parsed iteratively but make left-deep trees, whose height is limited.
        let chain = |n: usize, depth: usize| {
            let inner = vec!["x"; n].join(" + ");
            format!("{}{inner}{}", "(".repeat(depth), ")".repeat(depth))
        };
        let mut sexp_height = 0;
        let e = parse_expr(&chain(MAX_HEIGHT, MAX_DEPTH)).unwrap();
        let mut node = &e;
        while let ExprKind::Add(lhs, _) = &node.kind {
            (node, sexp_height) = (lhs, sexp_height + 1);
        }
        assert_eq!(sexp_height + 1, MAX_HEIGHT);
        for src in [
            chain(MAX_HEIGHT + 1, MAX_DEPTH),
            chain(100_000, 0),
            "2⁻¹".repeat(5000),
        ] {
            let err = parse_expr(&src).unwrap_err();
            assert!(err
                .message
                .starts_with("expression too long: more than 4096 levels"));
        }
    }

    /// Parsing must never panic; successful parses have consistent spans.
    fn check_no_panic(src: &str) {
        match parse_expr(src) {
            Ok(e) => check_spans(src, &e, Span::new(0, src.len())),
            Err(e) => {
                let _ = e.render(src);
                assert!(
                    e.span.start <= e.span.end && e.span.end <= src.len(),
                    "{src:?}"
                );
            }
        }
    }

    #[test]
    fn fuzz_never_panics() {
        let alphabet: Vec<char> = "x1+-*/^(){},. ²⁻−·\ni$é_".chars().collect();
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
        for _ in 0..20_000 {
            let len = (next() % 24) as usize;
            let s: String = (0..len)
                .map(|_| alphabet[(next() % alphabet.len() as u64) as usize])
                .collect();
            check_no_panic(&s);
            let bytes: Vec<u8> = (0..len).map(|_| next() as u8).collect();
            check_no_panic(&String::from_utf8_lossy(&bytes));
        }
    }
}
