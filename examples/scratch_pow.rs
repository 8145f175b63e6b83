use std::time::Instant;
use superint::system_file::{load, LimitsOverride};
fn main() {
    let sys = load(
        std::path::Path::new("systems/harmonic-rotor.toml"),
        &LimitsOverride::default(),
    )
    .unwrap();
    let name = std::env::args().nth(1).unwrap_or("P_{3,2}".into());
    let kmax: i64 = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(16);
    let p = sys.parse_argument(&name).unwrap();
    println!("{name}: {} terms", p.len());
    let mut acc = p.clone();
    let t = Instant::now();
    for k in 2..=kmax {
        acc = acc.checked_mul(&p).unwrap();
        println!(
            "rmul k={k}: {} terms, {:.3} s",
            acc.len(),
            t.elapsed().as_secs_f64()
        );
    }
    let t = Instant::now();
    let (mut base, mut k, mut r) = (p.clone(), kmax as u64, None::<superint::trigpoly::Expr>);
    loop {
        if k & 1 == 1 {
            r = Some(match r {
                None => base.clone(),
                Some(a) => a.checked_mul(&base).unwrap(),
            });
        }
        k >>= 1;
        if k == 0 {
            break;
        }
        base = base.checked_mul(&base).unwrap();
    }
    println!(
        "rsq {kmax}: {} terms, {:.3} s",
        r.unwrap().len(),
        t.elapsed().as_secs_f64()
    );
    let t = Instant::now();
    let q = p.checked_pow(kmax).unwrap();
    println!(
        "pow {kmax}: {} terms, {:.3} s, equal {}",
        q.len(),
        t.elapsed().as_secs_f64(),
        q == acc
    );
}
