//! W3 timing sketch: the Fateman and Pearce products over Q.
use trigpoly::{Poly, Rational, VarSet};
fn main() {
    let which = std::env::args().nth(1).unwrap_or_else(|| "fateman".into());
    let vars = VarSet::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .coordinate("t")
        .coordinate("u")
        .build()
        .unwrap();
    let p = |s: &str| Poly::<Rational>::parse(&vars, s).unwrap();
    let t0 = std::time::Instant::now();
    let r = if which == "fateman" {
        let f = p("(1 + x + y + z + t)^20");
        let t1 = std::time::Instant::now();
        let r = &f * &(&f + &Poly::one(&vars));
        eprintln!(
            "pow {:.3} mul {:.3}",
            (t1 - t0).as_secs_f64(),
            t1.elapsed().as_secs_f64()
        );
        r
    } else {
        let f = p("(1 + x + y + 2*z^2 + 3*t^3 + 5*u^5)^12");
        let g = p("(1 + u + t + 2*z^2 + 3*y^3 + 5*x^5)^12");
        let t1 = std::time::Instant::now();
        let r = &f * &g;
        eprintln!(
            "pow {:.3} mul {:.3}",
            (t1 - t0).as_secs_f64(),
            t1.elapsed().as_secs_f64()
        );
        r
    };
    println!(
        "seconds: {:.3}\nterms: {}",
        t0.elapsed().as_secs_f64(),
        r.len()
    );
}
