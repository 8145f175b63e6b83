//! `superint plot FILE CURVES… --from … --time T -o FILE.svg`: trajectories of the system's
//! flow, one from each starting point, computed in floating point and drawn as an SVG chart of
//! the curves over time, against another function, or at a Poincaré section, with a table of
//! how far each curve moved. A picture, never a proof.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{bail, Context};
use clap::{Args, ValueEnum};
use superint::render::{printable, Format};
use superint::report::counted;
use superint::system_file::{Against, LimitsOverride, PlotFunctions, PlotInput, StartValue};
use superint::trajectory::chart::{self, reduce_angle, Curve, Style};
use superint::trajectory::{short, Flow, Method, Numeric, Trajectory};
use trigpoly::{Expr, Var, VarKind, Vars};

use super::input::load_system;
use super::limits::LimitsArgs;
use super::output::{emit, emit_to_stderr, warned, Output};

pub const EXAMPLES: &str = "\
Examples:
  superint plot systems/harmonic-rotor.toml 're(K_1_1)' 'im(K_1_1)' L \\
      --at 'M = 1, omega = 1, I = 1' --time 20 -o resonant.svg \\
      --from 'x = 1, y = 0, theta = 0, p_x = 0, p_y = 1/2, p_theta = I*omega'
  superint plot systems/harmonic-rotor.toml y --against x --time 7 -o orbit.svg \\
      --at 'M = 1, omega = 1, I = 1' \\
      --from 'x = 1, y = 0, theta = 0, p_x = 0, p_y = 1/2, p_theta = 2'
  superint plot systems/henon-heiles.toml p_y --against y --section x -o section.svg \\
      --at 'A = 1, B = 1, C = -1/3' --time 3000 --steps 300000 --samples 3000 \\
      --from 'x = 0, y = 1/10, p_x = 2/5, p_y = 0' --from 'x = 0, y = 1/4, p_x = 3/10, p_y = 0'
  superint plot systems/calogero.toml x y z K1 K2 --at 'g = 1' --time 5 -o calogero.svg \\
      --from 'x = -1, y = 0, z = 2, p_x = 1, p_y = 0, p_z = -1/2'

Hamilton's equations are formed exactly, then integrated in floating point at a fixed step,
by the classical Runge–Kutta method or (--method gauss) the symplectic Gauss–Legendre one,
whose error in H stays bounded over long times: the chart illustrates, `check` proves. The
table gives each curve first and last, its range, and its largest change from the first; H
comes first, and its change tells how far the integration can be trusted (past a thousandth
of its size, a warning says so). A complex function
(K_1_1) is drawn as its real and imaginary parts. --section S keeps the states where S crosses
zero upward, a Poincaré section, drawn as dots. Each --from is an orbit of its own. A declared
denominator is evaluated as its polynomial; a start where one is 0 is refused.";

/// Arguments of `superint plot`.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// A system file (TOML, see docs/system-files.md), or - for standard input.
    #[arg(value_name = "FILE")]
    file: PathBuf,
    /// What to draw: names, family instances or expressions of the file.
    #[arg(value_name = "CURVES", required = true)]
    curves: Vec<String>,
    /// The parameters' values, such as 'M = 1, omega = 3/2' (numbers: fractions, or decimals
    /// such as 1.5 or 2.5e-3, read as the fractions they write).
    #[arg(long, value_name = "VALUES")]
    at: Option<String>,
    /// The starting point: a value for every phase variable (coordinate, angle, momentum,
    /// Poisson variable), such as
    /// 'x = 1, y = 0, theta = 3*pi/4, p_x = 0, p_y = 1, p_theta = I*omega' (a value is a
    /// number, fraction or decimal, a multiple of π alone such as 3*pi/4, pi*3/4 or -π/2,
    /// or an expression in the parameters). Give it again for more orbits in the same chart.
    #[arg(long, value_name = "POINT", required = true)]
    from: Vec<String>,
    /// How long to follow the motion.
    #[arg(long, allow_negative_numbers = true,
          value_name = "T", value_parser = super::Quoting(positive_time))]
    time: f64,
    /// Steps of the integrator over the whole time.
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", default_value_t = 10_000,
          value_parser = super::in_range::<u64>(1, 10_000_000))]
    steps: u64,
    /// Points drawn for each curve (at most the steps).
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", default_value_t = 1_000,
          value_parser = super::in_range::<u64>(1, 100_000))]
    samples: u64,
    /// Draw the curves against this real function instead of the time (`y --against x`
    /// draws the orbit), or against an angle, reduced to [−π, π) (`p_θ --against θ` draws a
    /// phase portrait).
    #[arg(long, value_name = "F")]
    against: Option<String>,
    /// With --against an angle: draw it as the integration carries it, not reduced mod 2π
    /// (a rotation then runs on instead of coming back at −π).
    #[arg(long, requires = "against")]
    unreduced: bool,
    /// A Poincaré section: keep the states where this real function crosses zero upward
    /// (at most --samples of them), drawn as dots against --against.
    #[arg(long, value_name = "S", requires = "against")]
    section: Option<String>,
    /// Where to write the SVG chart; '-' writes it to standard output, and the table to
    /// standard error. A name of another image format (.png, .pdf, ...) is refused.
    #[arg(short, long, value_name = "FILE.svg")]
    output: PathBuf,
    /// How to step: the classical Runge–Kutta method, or the two-stage Gauss–Legendre method
    /// (implicit, symplectic: H's error stays bounded over long times; about five times the
    /// work a step).
    #[arg(long, value_enum, default_value_t = MethodArg::RungeKutta)]
    method: MethodArg,
    /// Also write the sampled values as CSV: the orbit (its --from's number), t, the function
    /// of --against, each curve.
    #[arg(long, value_name = "FILE.csv")]
    data: Option<PathBuf>,
    #[command(flatten)]
    limits: LimitsArgs,
}

/// `--method` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum MethodArg {
    /// Classical fourth-order Runge–Kutta (explicit).
    #[value(alias = "rk4")]
    RungeKutta,
    /// Two-stage Gauss–Legendre, of order four (implicit, symplectic).
    Gauss,
}

impl MethodArg {
    fn method(self) -> Method {
        match self {
            MethodArg::RungeKutta => Method::RungeKutta,
            MethodArg::Gauss => Method::Gauss,
        }
    }

    /// The method's name in the table.
    fn name(self) -> &'static str {
        match self {
            MethodArg::RungeKutta => "the classical Runge–Kutta method",
            MethodArg::Gauss => "the symplectic Gauss–Legendre method",
        }
    }
}

/// `--time`: a finite positive number of time units, as a decimal (`0.5`) or a fraction
/// (`1/2`, the way `--at` and `--from` take numbers).
fn positive_time(s: &str) -> Result<f64, String> {
    let t = match s.trim().split_once('/') {
        Some((num, den)) => match (num.trim().parse::<f64>(), den.trim().parse::<f64>()) {
            (Ok(num), Ok(den)) => num / den,
            _ => f64::NAN,
        },
        None => s.trim().parse::<f64>().unwrap_or(f64::NAN),
    };
    match t {
        t if t.is_finite() && t > 0.0 => Ok(t),
        // Quoting names the value.
        _ => Err("not a positive number of time units".to_string()),
    }
}

/// The plot job, as plain data.
#[derive(Debug)]
pub struct PlotJob {
    pub args: PlotArgs,
    pub limits: LimitsOverride,
    pub output: Output,
}

impl PlotArgs {
    pub fn job(self, output: Output) -> PlotJob {
        let limits = self.limits.settings();
        PlotJob {
            args: self,
            limits,
            output,
        }
    }
}

/// One drawn function: its label and values at the samples.
struct Series {
    label: String,
    values: Vec<f64>,
}

/// What one starting point gave: the times of its points, the values of the horizontal axis
/// there, and its rows, `H` first and then each curve.
struct Orbit {
    times: Vec<f64>,
    axis: Vec<f64>,
    rows: Vec<Series>,
}

impl Orbit {
    /// The rows the table lists: `H`, unless it is one of the curves too (`plot FILE H L`),
    /// and each curve.
    fn listed(&self) -> &[Series] {
        let (h, curves) = self.rows.split_first().expect("H is the first row");
        match curves.iter().any(|c| c.label == h.label) {
            true => curves,
            false => &self.rows,
        }
    }
}

/// A function ready to evaluate along trajectories, with its label.
struct Function {
    label: String,
    numeric: Numeric,
}

/// The horizontal axis, when it is not the time.
enum Axis {
    /// A function of the state.
    Function(Function),
    /// An angle, read off the state as the integration carries it.
    Angle {
        /// The axis' label.
        label: String,
        /// The angle's place in the state.
        index: usize,
        /// Whether it is drawn (and written in the data) reduced to `[−π, π)`.
        reduced: bool,
    },
}

impl Axis {
    fn label(&self) -> &str {
        match self {
            Axis::Function(f) => &f.label,
            Axis::Angle { label, .. } => label,
        }
    }

    /// Whether the axis is an angle drawn reduced to `[−π, π)`.
    fn reduced(&self) -> bool {
        matches!(self, Axis::Angle { reduced: true, .. })
    }

    /// A value of the axis as drawn and written in the data.
    fn shown(&self, x: f64) -> f64 {
        if self.reduced() {
            reduce_angle(x)
        } else {
            x
        }
    }
}

/// Integrates, draws the chart, writes it (and the data), prints the table.
pub fn run(job: &PlotJob) -> anyhow::Result<bool> {
    let args = &job.args;
    if job.output.format == Format::Latex {
        bail!("plot prints its table as text, markdown or json, not latex");
    }
    check_outputs(args)?;
    let file = load_system(&args.file, &job.limits)?;
    let functions = PlotFunctions {
        curves: &args.curves,
        against: args.against.as_deref(),
        section: args.section.as_deref(),
    };
    let input = warned(
        &file,
        file.plot_input(args.at.as_deref(), &args.from, functions),
    )?;
    let flow = Flow::at(file.system().space(), &input.hamiltonian, &input.values)
        .context("Hamilton's equations at these values")?
        .with_method(args.method.method());
    let plotted = Plotted::new(&flow, &input, args)?;
    let integration = Integration {
        flow: &flow,
        plotted: &plotted,
        args,
        vars: file.system().vars(),
        several: input.starts.len() > 1,
    };
    let orbits = input
        .starts
        .iter()
        .enumerate()
        .map(|(k, point)| integration.orbit(k, point))
        .collect::<anyhow::Result<Vec<Orbit>>>()?;
    let title = match input.parameters.as_str() {
        "" => file.name().to_string(),
        p => format!("{} at {p}", file.name()),
    };
    write_chart(args, &title, &plotted, &orbits)?;
    write_data(args, &plotted, &orbits)?;
    print_table(job, &title, &plotted, &orbits)?;
    warn_of_drift(&orbits, args)?;
    Ok(true)
}

/// What is evaluated along every orbit: the rows, `H` first and then each curve, the
/// horizontal axis when it is not the time, and the section's function.
struct Plotted {
    rows: Vec<Function>,
    against: Option<Axis>,
    section: Option<Function>,
}

impl Plotted {
    /// The functions of `input`, ready to evaluate along `flow`; an error for `--unreduced`
    /// with a function, not an angle, on the horizontal axis.
    fn new(flow: &Flow, input: &PlotInput, args: &PlotArgs) -> anyhow::Result<Self> {
        let function = |label: &str, f: &Expr| -> anyhow::Result<Function> {
            let numeric = flow.numeric(f).with_context(|| label.to_string())?;
            Ok(Function {
                label: label.to_string(),
                numeric,
            })
        };
        let mut rows = vec![function("H", &input.hamiltonian)?];
        for (label, f) in &input.curves {
            rows.push(function(label, f)?);
        }
        let against = match &input.against {
            None => None,
            Some(Against::Function(l, _)) if args.unreduced => {
                bail!("--unreduced is for an angle on the horizontal axis, and {l} is a function")
            }
            Some(Against::Function(l, f)) => Some(Axis::Function(function(l, f)?)),
            Some(Against::Angle(label, v)) => Some(Axis::Angle {
                label: match args.unreduced {
                    false => format!("{label} (mod 2π)"),
                    true => format!("{label} (not reduced mod 2π)"),
                },
                index: v.index(),
                reduced: !args.unreduced,
            }),
        };
        let section = input
            .section
            .as_ref()
            .map(|(l, f)| function(l, f))
            .transpose()?;
        Ok(Plotted {
            rows,
            against,
            section,
        })
    }

    /// How the points are drawn: as dots at a Poincaré section, else as lines.
    fn style(&self) -> Style {
        match self.section {
            Some(_) => Style::Dots,
            None => Style::Lines,
        }
    }
}

/// What following the flow from each starting point takes, to make its [`Orbit`].
struct Integration<'a> {
    flow: &'a Flow,
    plotted: &'a Plotted,
    args: &'a PlotArgs,
    vars: &'a Vars,
    /// Whether there are several starting points, whose orbits are then numbered.
    several: bool,
}

impl Integration<'_> {
    /// The orbit from `point`, the starting point `k` (counted from 0), with every value it
    /// draws or tables.
    fn orbit(&self, k: usize, point: &[(Var, StartValue)]) -> anyhow::Result<Orbit> {
        // `[2]` after each label when there are several starting points.
        let mark = if self.several {
            format!(" [{}]", k + 1)
        } else {
            String::new()
        };
        let path = self.path(k, &self.start(point, &mark)?)?;
        // Every value drawn or tabled is finite: a function that overflows along the orbit
        // (a high power) is named with the time.
        let values = |f: &Function| -> anyhow::Result<Vec<f64>> {
            let values = path.values(|s| f.numeric.real(s));
            match values.iter().position(|v| !v.is_finite()) {
                None => Ok(values),
                Some(i) => bail!(
                    "{}{mark} is not a finite floating-point number at t = {} of {}",
                    f.label,
                    short(path.times[i]),
                    self.orbit_name(k)
                ),
            }
        };
        Ok(Orbit {
            axis: match &self.plotted.against {
                Some(Axis::Function(f)) => values(f)?,
                Some(Axis::Angle { index, .. }) => path.values(|s| s[*index]),
                None => path.times.clone(),
            },
            rows: self
                .plotted
                .rows
                .iter()
                .map(|f| {
                    Ok(Series {
                        label: format!("{}{mark}", f.label),
                        values: values(f)?,
                    })
                })
                .collect::<anyhow::Result<_>>()?,
            times: path.times,
        })
    }

    /// The state at `t = 0` from the starting point `point`, whose labels take `mark`.
    fn start(&self, point: &[(Var, StartValue)], mark: &str) -> anyhow::Result<Vec<f64>> {
        let mut start = vec![0.0; self.vars.len()];
        for (v, value) in point {
            let angle = self.vars.variable(*v).kind() == VarKind::Angle;
            start[v.index()] = value.to_f64(angle).with_context(|| {
                let name = self.vars.variable(*v).unicode();
                format!("the starting value of {name}{mark}")
            })?;
        }
        Ok(start)
    }

    /// The states kept along the orbit from `start`, the starting point `k`: at the samples,
    /// or where the section crosses zero upward, an error when it never does.
    fn path(&self, k: usize, start: &[f64]) -> anyhow::Result<Trajectory> {
        let args = self.args;
        let (steps, samples) = (args.steps as usize, args.samples as usize);
        let path = match &self.plotted.section {
            None => self.flow.integrate(start, args.time, steps, samples),
            Some(f) => self
                .flow
                .section(start, args.time, steps, &f.numeric, samples),
        }
        .with_context(|| self.orbit_name(k))?;
        if path.times.is_empty() {
            let label = self
                .plotted
                .section
                .as_ref()
                .map_or("", |f| f.label.as_str());
            bail!(
                "{label} does not cross zero upward from t = 0 to {}{}: no point of the section \
                 (a longer --time, or another section)",
                short(args.time),
                if self.several {
                    format!(" from the starting point {}", k + 1)
                } else {
                    String::new()
                }
            );
        }
        Ok(path)
    }

    /// The orbit from the starting point `k` (counted from 0) as messages name it.
    fn orbit_name(&self, k: usize) -> String {
        match self.several {
            true => format!("the orbit from starting point {}", k + 1),
            false => "the orbit".to_string(),
        }
    }
}

/// Whether `-o -` sends the chart to standard output (and the table to standard error).
fn chart_to_stdout(args: &PlotArgs) -> bool {
    args.output.as_os_str() == "-"
}

/// Draws the chart of `orbits` and writes it to `-o`'s file or to standard output.
fn write_chart(
    args: &PlotArgs,
    title: &str,
    plotted: &Plotted,
    orbits: &[Orbit],
) -> anyhow::Result<()> {
    let style = plotted.style();
    let against = plotted.against.as_ref();
    let reduced = against.is_some_and(Axis::reduced);
    let drawn = curves(orbits, reduced, style);
    let axis_label = against.map_or("t", Axis::label);
    let svg = chart::svg(title, axis_label, &drawn, style)?;
    if chart_to_stdout(args) {
        emit(&svg)?;
    } else {
        std::fs::write(&args.output, printable(&svg).as_bytes())
            .with_context(|| format!("cannot write {}", args.output.display()))?;
    }
    Ok(())
}

/// Writes the sampled values as CSV to `--data`'s file, when it is given.
fn write_data(args: &PlotArgs, plotted: &Plotted, orbits: &[Orbit]) -> anyhow::Result<()> {
    let Some(data) = &args.data else {
        return Ok(());
    };
    let columns: Vec<&str> = plotted
        .against
        .iter()
        .map(Axis::label)
        .chain(plotted.rows[1..].iter().map(|f| f.label.as_str()))
        .collect();
    std::fs::write(
        data,
        printable(&csv(&columns, plotted.against.as_ref(), orbits)).as_bytes(),
    )
    .with_context(|| format!("cannot write {}", data.display()))?;
    Ok(())
}

/// Prints the table of `orbits` in the job's format: to standard output, or to standard
/// error when the chart goes there.
fn print_table(
    job: &PlotJob,
    title: &str,
    plotted: &Plotted,
    orbits: &[Orbit],
) -> anyhow::Result<()> {
    let args = &job.args;
    let section = plotted.section.as_ref().map(|f| f.label.as_str());
    let table = match job.output.format {
        Format::Json => json(title, args, orbits, section),
        Format::Markdown => markdown(title, &method(args, orbits, section), orbits),
        _ => text(title, &method(args, orbits, section), orbits),
    };
    if chart_to_stdout(args) {
        emit_to_stderr(&table)?;
    } else {
        emit(&table)?;
    }
    Ok(())
}

/// The curves drawn: each function but `H` along each orbit, against the horizontal axis; an
/// angle on that axis reduced mod 2π (a line broken where it wraps, or dots moved into range).
fn curves(orbits: &[Orbit], reduced: bool, style: Style) -> Vec<Curve> {
    orbits
        .iter()
        .flat_map(|o| {
            o.rows[1..].iter().map(|c| {
                let points = o.axis.iter().copied().zip(c.values.iter().copied());
                match (reduced, style) {
                    (false, _) => Curve::new(c.label.clone(), points.collect()),
                    (true, Style::Lines) => {
                        Curve::with_angle_x(c.label.clone(), &points.collect::<Vec<_>>())
                    }
                    (true, Style::Dots) => Curve::new(
                        c.label.clone(),
                        points.map(|(x, y)| (reduce_angle(x), y)).collect(),
                    ),
                }
            })
        })
        .collect()
}

/// Warns on stderr of each orbit along which `H` moved by more than
/// [`ENERGY_DRIFT_WARNING`] of its size: the integration is not accurate at these steps.
fn warn_of_drift(orbits: &[Orbit], args: &PlotArgs) -> anyhow::Result<()> {
    for (k, orbit) in orbits.iter().enumerate() {
        let drift = energy_drift(&orbit.rows[0]);
        if drift > ENERGY_DRIFT_WARNING {
            let along = match orbits.len() {
                1 => "the orbit".to_string(),
                _ => format!("the orbit from starting point {}", k + 1),
            };
            let gauss = match args.method {
                MethodArg::RungeKutta => " or use --method gauss",
                MethodArg::Gauss => "",
            };
            emit_to_stderr(&format!(
                "superint: warning: H moved by {:.2} % of its size along {along}: the \
                 integration is not accurate at {}; raise --steps{gauss}\n",
                100.0 * drift,
                counted(args.steps, "step")
            ))?;
        }
    }
    Ok(())
}

/// Refuses outputs that would overwrite one another or the system file: `--data -` (a file
/// named `-` was written), the chart and the data in one file (the data replaced the chart),
/// or either one the system file itself.
fn check_outputs(args: &PlotArgs) -> anyhow::Result<()> {
    // The same file however spelled (`same.svg`, `./same.svg`), written yet or not: the
    // folders as the system resolves them, and the names.
    let resolved = |p: &std::path::Path| {
        p.canonicalize().ok().or_else(|| {
            let folder = match p.parent() {
                Some(f) if !f.as_os_str().is_empty() => f,
                _ => std::path::Path::new("."),
            };
            Some(folder.canonicalize().ok()?.join(p.file_name()?))
        })
    };
    let same = |a: &std::path::Path, b: &std::path::Path| {
        a == b || matches!((resolved(a), resolved(b)), (Some(x), Some(y)) if x == y)
    };
    if let Some(data) = &args.data {
        if data.as_os_str() == "-" {
            bail!("--data writes a file: give its name (only -o takes - for standard output)");
        }
        if same(data, &args.output) {
            bail!(
                "-o and --data name the same file, {}: give two",
                data.display()
            );
        }
    }
    if let Some(format) = other_image_format(&args.output) {
        bail!(
            "-o {}: plot writes SVG, which a .{format} file would hold under another format's \
             name; name it {} (rsvg-convert or inkscape turn an SVG into {})",
            args.output.display(),
            args.output.with_extension("svg").display(),
            format.to_ascii_uppercase(),
        );
    }
    let outputs = std::iter::once(&args.output).chain(args.data.as_ref());
    if let Some(o) = outputs
        .filter(|o| o.as_os_str() != "-")
        .find(|o| same(o, &args.file))
    {
        bail!(
            "{} is the system file: an output would overwrite it",
            o.display()
        );
    }
    Ok(())
}

/// The extension of `path` when it names an image or document format other than SVG
/// (`p.png`), where the chart, always SVG, would be written under a name that says otherwise.
/// Any other name (`p.svg`, `chart`, `p.xml`) is taken as given.
fn other_image_format(path: &std::path::Path) -> Option<String> {
    const OTHERS: [&str; 11] = [
        "png", "jpg", "jpeg", "gif", "webp", "bmp", "tif", "tiff", "pdf", "eps", "ps",
    ];
    let extension = path.extension()?.to_str()?.to_ascii_lowercase();
    OTHERS.contains(&extension.as_str()).then_some(extension)
}

/// The largest relative move of H along an orbit past which `plot` warns: H is conserved, so
/// its move is the integration's error.
const ENERGY_DRIFT_WARNING: f64 = 1e-3;

/// The largest change of H along an orbit as a fraction of its largest size (0 when H is 0
/// all along).
fn energy_drift(h: &Series) -> f64 {
    let [.., change] = stats(h);
    let size = h.values.iter().map(|v| v.abs()).fold(0.0, f64::max);
    if size > 0.0 {
        change / size
    } else {
        0.0
    }
}

/// What the table says of one function: its first and last values (at `t = 0` and at the
/// end, or at the first and last points of a section), least, greatest, and the largest change
/// from the first.
fn stats(s: &Series) -> [f64; 5] {
    let first = s.values[0];
    let last = *s.values.last().expect("a point at least");
    let least = s.values.iter().copied().fold(f64::INFINITY, f64::min);
    let greatest = s.values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let change = s
        .values
        .iter()
        .map(|v| (v - first).abs())
        .fold(0.0, f64::max);
    [first, last, least, greatest, change]
}

const HEADINGS: [&str; 6] = [
    "function",
    "first",
    "last",
    "least",
    "greatest",
    "largest change",
];

/// The run in one line: time, steps, method, what was kept, where the chart went.
fn method(args: &PlotArgs, orbits: &[Orbit], section: Option<&str>) -> String {
    let counts: Vec<usize> = orbits.iter().map(|o| o.times.len()).collect();
    let kept = match (section, counts.as_slice()) {
        (None, _) => format!("{} a curve", counted(counts[0], "point")),
        (Some(label), [count]) => format!("{} of {label} = 0", counted(*count, "upward crossing")),
        (Some(label), _) => {
            let counts: Vec<String> = counts.iter().map(usize::to_string).collect();
            format!("{} upward crossings of {label} = 0", counts.join(", "))
        }
    };
    let from = match orbits.len() {
        1 => String::new(),
        n => format!(" from each of {n} starting points"),
    };
    format!(
        "t from 0 to {}{from} in {} of {} (floating point); {kept}; chart: {}",
        short(args.time),
        counted(args.steps, "step"),
        args.method.name(),
        args.output.display()
    )
}

fn text(title: &str, how: &str, orbits: &[Orbit]) -> String {
    let cells: Vec<[String; 6]> = orbits
        .iter()
        .flat_map(Orbit::listed)
        .map(|s| {
            let [a, b, c, d, e] = stats(s).map(number);
            [s.label.clone(), a, b, c, d, e]
        })
        .collect();
    let width = |k: usize| {
        cells
            .iter()
            .map(|r| r[k].chars().count())
            .chain([HEADINGS[k].chars().count()])
            .max()
            .unwrap_or(0)
    };
    let widths: Vec<usize> = (0..6).map(width).collect();
    let mut out = format!("{title}\n{how}\n\n");
    for row in std::iter::once(HEADINGS.map(String::from)).chain(cells) {
        let mut line = String::new();
        for (k, cell) in row.iter().enumerate() {
            let pad = widths[k] - cell.chars().count();
            if k == 0 {
                let _ = write!(line, "{cell}{}", " ".repeat(pad));
            } else {
                let _ = write!(line, "  {}{cell}", " ".repeat(pad));
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

fn markdown(title: &str, how: &str, orbits: &[Orbit]) -> String {
    let mut out = format!("## {title}\n\n{how}\n\n");
    out.push_str("| function | first | last | least | greatest | largest change |\n");
    out.push_str("|---|---:|---:|---:|---:|---:|\n");
    for s in orbits.iter().flat_map(Orbit::listed) {
        let [a, b, c, d, e] = stats(s).map(number);
        let _ = writeln!(out, "| {} | {a} | {b} | {c} | {d} | {e} |", s.label);
    }
    out
}

fn json(title: &str, args: &PlotArgs, orbits: &[Orbit], section: Option<&str>) -> String {
    let functions: Vec<serde_json::Value> = orbits
        .iter()
        .enumerate()
        .flat_map(|(k, o)| o.listed().iter().map(move |s| (k, s)))
        .map(|(k, s)| {
            let [first, last, least, greatest, change] = stats(s);
            serde_json::json!({
                "function": s.label,
                "orbit": k + 1,
                "first": first,
                "last": last,
                "least": least,
                "greatest": greatest,
                "largest_change": change,
            })
        })
        .collect();
    let points: Vec<usize> = orbits.iter().map(|o| o.times.len()).collect();
    let drift: Vec<f64> = orbits.iter().map(|o| energy_drift(&o.rows[0])).collect();
    let doc = serde_json::json!({
        "schema": "superint-plot/1",
        "title": title,
        "time": args.time,
        "steps": args.steps,
        "method": args.method.name(),
        "method_id": args.method.to_possible_value().map(|v| v.get_name().to_string()),
        "at": args.at,
        "from": args.from,
        "against": args.against,
        "section": section,
        "energy_drift": drift,
        "accurate": drift.iter().all(|&d| d <= ENERGY_DRIFT_WARNING),
        "points": points,
        "chart": args.output.display().to_string(),
        "functions": functions,
    });
    format!("{doc:#}\n")
}

/// The samples as CSV: the orbit (its starting point's number), `t`, the axis of --against as
/// drawn, if any, each curve; `columns` names the functions.
fn csv(columns: &[&str], against: Option<&Axis>, orbits: &[Orbit]) -> String {
    let quote = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    let mut out = ["orbit", "t"]
        .into_iter()
        .map(String::from)
        .chain(columns.iter().map(|c| quote(c)))
        .collect::<Vec<_>>()
        .join(",");
    out.push('\n');
    for (k, o) in orbits.iter().enumerate() {
        for (i, t) in o.times.iter().enumerate() {
            let _ = write!(out, "{},{t}", k + 1);
            if let Some(axis) = against {
                let _ = write!(out, ",{}", axis.shown(o.axis[i]));
            }
            for c in &o.rows[1..] {
                let _ = write!(out, ",{}", c.values[i]);
            }
            out.push('\n');
        }
    }
    out
}

/// A value for the table, with the paper's minus sign.
fn number(v: f64) -> String {
    short(v).replace('-', "−")
}
