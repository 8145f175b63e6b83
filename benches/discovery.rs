//! The search at sizes where its linear algebra, not its set-up, sets the pace, report
//! included (what `superint search` computes before it prints): the harmonic rotor at the
//! resonance `Ω = ω` with `--new-only`, and the Calogero–Moser system with denominators. Each
//! is checked once before it is timed. `cargo bench --bench discovery`.
//!
//! A change that made one of these several times slower went unnoticed for a session (a dense
//! check of each kernel vector against every equation; docs/performance.md, step 147): these
//! are the figures to compare before and after a change to `brackets::modular`, the clearing
//! of denominators or the search's equations.

use std::path::Path;

use brackets::search::{SearchOptions, SearchSpace};
use brackets::{systems, System};
use divan::{black_box, Bencher};
use superint::discovery::search_report;
use superint::system_file::{load, LimitsOverride};

/// The allocator of the `superint` binary, so that these figures match the command line's.
#[global_allocator]
static ALLOCATOR: superint::allocator::Allocator = superint::allocator::Allocator;

fn main() {
    superint::allocator::configure();
    divan::main();
}

fn calogero() -> System {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("systems/calogero.toml");
    load(&path, &LimitsOverride::default())
        .expect("the system file loads")
        .system()
        .clone()
}

/// `superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega'` at degree `d` in
/// the momenta, positions and trigonometric order, `--new-only`: four new integrals.
#[divan::bench(args = [6, 8], sample_count = 5)]
fn search_harmonic_new_only(bencher: Bencher, d: u32) {
    let rotor = systems::harmonic_rotor();
    let resonance = rotor.resonance(1, 1).expect("a resonance");
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(d)
            .positions_degree(d)
            .trig_degree(d),
    )
    .when(resonance)
    .new_only();
    let (report, found) = search_report("harmonic rotor", &rotor, &options).expect("searches");
    assert!(report.all_proved());
    assert_eq!(found.new.map(|n| n.new.len()), Some(4));
    bencher
        .bench(|| black_box(search_report("harmonic rotor", &rotor, &options).expect("searches")));
}

/// `superint search systems/calogero.toml --denominators-degree d` (momenta and positions
/// `≤ 2`): seven integrals.
#[divan::bench(args = [4, 6], sample_count = 5)]
fn search_calogero_denominators(bencher: Bencher, d: u32) {
    let system = calogero();
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .denominators_degree(d),
    );
    let (report, found) = search_report("Calogero–Moser", &system, &options).expect("searches");
    assert!(report.all_proved());
    assert_eq!(found.basis.len(), 7);
    bencher
        .bench(|| black_box(search_report("Calogero–Moser", &system, &options).expect("searches")));
}
