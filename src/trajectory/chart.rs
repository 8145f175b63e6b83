//! A chart of curves as an SVG document (through `plotters`, which writes SVG text and needs
//! no fonts): the picture `superint plot` draws.

use plotters::prelude::*;

/// One curve of a chart: its label and its points `(x, y)`, joined in order except where a
/// new piece begins. Built by [`Curve::new`] or [`Curve::with_angle_x`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Curve {
    /// The legend's text.
    pub label: String,
    /// The points, in order.
    pub points: Vec<(f64, f64)>,
    /// Where a piece begins that is not joined to the point before (ascending indices into
    /// `points`): an angle that leaves `[−π, π)` on one side comes back on the other.
    pub breaks: Vec<usize>,
}

impl Curve {
    /// A curve through `points`, in one piece.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Curve {
            label: label.into(),
            points,
            breaks: Vec::new(),
        }
    }

    /// A curve whose `x` is an angle, drawn reduced to `[−π, π)`: where the angle crosses an
    /// odd multiple of π between two points, the piece ends at the edge (at `π` going up,
    /// `−π` going down), at the `y` interpolated linearly there, and the next begins at the
    /// other edge with the same `y`. Between two points more than [`MAX_WRAPS`] turns apart
    /// (or at an `x` that is not finite) the samples show no line, and the curve is only
    /// broken there: drawn turn by turn, an angle that runs 10¹² radians between two samples
    /// made 10¹¹ pieces and did not end.
    pub fn with_angle_x(label: impl Into<String>, points: &[(f64, f64)]) -> Self {
        use std::f64::consts::PI;
        let mut curve = Curve::new(label, Vec::with_capacity(points.len()));
        for (k, &(x, y)) in points.iter().enumerate() {
            if let Some(&(x0, y0)) = k.checked_sub(1).map(|j| &points[j]) {
                let (b0, b1) = (branch(x0), branch(x));
                let turns = (b1 - b0).abs();
                if turns.is_nan() || turns > MAX_WRAPS {
                    curve.breaks.push(curve.points.len());
                    curve.points.push((reduce_angle(x), y));
                    continue;
                }
                let up = b1 > b0;
                let mut b = b0;
                while b != b1 {
                    // The boundary between branch b and the next one along the way.
                    let edge = if up {
                        (2.0 * b + 1.0) * PI
                    } else {
                        (2.0 * b - 1.0) * PI
                    };
                    let at = y0 + (y - y0) * (edge - x0) / (x - x0);
                    let (leave, enter) = if up { (PI, -PI) } else { (-PI, PI) };
                    curve.points.push((leave, at));
                    curve.breaks.push(curve.points.len());
                    curve.points.push((enter, at));
                    b += if up { 1.0 } else { -1.0 };
                }
            }
            curve.points.push((reduce_angle(x), y));
        }
        curve
    }

    /// The pieces of the curve, each joined in order.
    fn pieces(&self) -> impl Iterator<Item = &[(f64, f64)]> {
        let starts = std::iter::once(0).chain(self.breaks.iter().copied());
        let ends = self.breaks.iter().copied().chain([self.points.len()]);
        starts.zip(ends).map(|(a, b)| &self.points[a..b])
    }
}

/// The most turns [`Curve::with_angle_x`] draws between two points, each as a piece from edge
/// to edge.
pub const MAX_WRAPS: f64 = 64.0;

/// The number of the branch `[(2b − 1)π, (2b + 1)π)` that holds the angle `x`.
fn branch(x: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    ((x + PI) / TAU).floor()
}

/// The angle `x` reduced to `[−π, π)`.
pub fn reduce_angle(x: f64) -> f64 {
    x - std::f64::consts::TAU * branch(x)
}

/// How curves are drawn: joined by lines (values over time, an orbit), or as dots (the
/// points of a Poincaré section, which follow no order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Lines through the points, in order.
    Lines,
    /// A dot at each point.
    Dots,
}

/// The chart could not be drawn.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("the chart could not be drawn: {0}")]
pub struct ChartError(String);

/// The size of the picture, in SVG pixels.
const SIZE: (u32, u32) = (960, 600);

/// The curves' colours, in turn: ten that stay apart on white (Tableau's).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
];

/// The curves in one chart with a title, the x axis labelled `x_label`, as an SVG document.
/// Every point must be finite.
pub fn svg(
    title: &str,
    x_label: &str,
    curves: &[Curve],
    style: Style,
) -> Result<String, ChartError> {
    let fail = |e: &dyn std::fmt::Display| ChartError(e.to_string());
    let too_wide = || ChartError("the values are too far apart to draw in floating point".into());
    let xs = span(curves.iter().flat_map(|c| c.points.iter().map(|p| p.0))).ok_or_else(too_wide)?;
    let ys = span(curves.iter().flat_map(|c| c.points.iter().map(|p| p.1))).ok_or_else(too_wide)?;
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(84)
            .build_cartesian_2d(xs.0..xs.1, ys.0..ys.1)
            .map_err(|e| fail(&e))?;
        let (x_decimals, y_decimals) = (decimals(xs), decimals(ys));
        chart
            .configure_mesh()
            .x_label_formatter(&|v| tick(*v, x_decimals))
            .y_label_formatter(&|v| tick(*v, y_decimals))
            .x_desc(x_label)
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 17))
            .light_line_style(WHITE.mix(0.0))
            .draw()
            .map_err(|e| fail(&e))?;
        for (k, curve) in curves.iter().enumerate() {
            let color = PALETTE[k % PALETTE.len()];
            let points = curve.points.iter().copied();
            let drawn = match style {
                Style::Lines => {
                    let mut pieces = curve.pieces();
                    let first = pieces.next().unwrap_or_default().iter().copied();
                    for piece in pieces {
                        let line = LineSeries::new(piece.iter().copied(), color.stroke_width(2));
                        chart.draw_series(line).map_err(|e| fail(&e))?;
                    }
                    chart.draw_series(LineSeries::new(first, color.stroke_width(2)))
                }
                Style::Dots => chart.draw_series(points.map(|p| Circle::new(p, 2, color.filled()))),
            };
            drawn
                .map_err(|e| fail(&e))?
                .label(curve.label.as_str())
                .legend(
                    move |(x, y)| -> DynElement<'static, SVGBackend<'_>, (i32, i32)> {
                        match style {
                            Style::Lines => {
                                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
                                    .into_dyn()
                            }
                            Style::Dots => Circle::new((x + 12, y), 3, color.filled()).into_dyn(),
                        }
                    },
                );
        }
        chart
            .configure_series_labels()
            .position(legend_corner(curves, xs, ys))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .label_font(("sans-serif", 16))
            .draw()
            .map_err(|e| fail(&e))?;
        root.present().map_err(|e| fail(&e))?;
    }
    Ok(out)
}

/// The range an axis shows for `values` (finite, the caller has checked): their least and
/// greatest, widened a little. A range narrower than a millionth of its scale (its size, or 1
/// when its values are smaller: a conserved quantity, or one that vanishes, equal to rounding)
/// is widened to a thousandth of that scale, so that such a curve shows as the straight line it
/// is rather than as magnified rounding; the table gives its exact range. `None` when the range
/// is too wide for floating point.
fn span(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if lo > hi {
        return Some((0.0, 1.0));
    }
    let scale = lo.abs().max(hi.abs()).max(1.0);
    let (lo, hi) = if hi - lo < 1e-6 * scale {
        let mid = (lo + hi) / 2.0;
        (mid - 1e-3 * scale, mid + 1e-3 * scale)
    } else {
        let pad = (hi - lo) * 0.04;
        (lo - pad, hi + pad)
    };
    // plotters maps the range to pixels through its width.
    (lo.is_finite() && hi.is_finite() && (hi - lo).is_finite()).then_some((lo, hi))
}

/// The corner of the plotting area where the legend covers the fewest points: the legend
/// is about a quarter of the width wide, and a line of about 4 % of the height a curve
/// tall; ties go to the upper right, then the upper left.
fn legend_corner(curves: &[Curve], xs: (f64, f64), ys: (f64, f64)) -> SeriesLabelPosition {
    let width = 0.25;
    let height = (0.04 * curves.len() as f64 + 0.03).min(0.9);
    let corners = [
        (SeriesLabelPosition::UpperRight, true, true),
        (SeriesLabelPosition::UpperLeft, false, true),
        (SeriesLabelPosition::LowerRight, true, false),
        (SeriesLabelPosition::LowerLeft, false, false),
    ];
    let covered = |right: bool, upper: bool| {
        curves
            .iter()
            .flat_map(|c| &c.points)
            .filter(|&&(x, y)| {
                let fx = (x - xs.0) / (xs.1 - xs.0);
                let fy = (y - ys.0) / (ys.1 - ys.0);
                let in_x = if right {
                    fx >= 1.0 - width
                } else {
                    fx <= width
                };
                let in_y = if upper {
                    fy >= 1.0 - height
                } else {
                    fy <= height
                };
                in_x && in_y
            })
            .count()
    };
    corners
        .into_iter()
        .min_by_key(|&(_, right, upper)| covered(right, upper))
        .map_or(SeriesLabelPosition::UpperRight, |c| c.0)
}

/// Decimals enough to tell apart the ticks of an axis over `range` (about ten of them).
fn decimals((lo, hi): (f64, f64)) -> usize {
    let step = (hi - lo) / 10.0;
    (-step.log10().floor()).clamp(0.0, 12.0) as usize
}

/// A tick's label: `decimals` of them, and no `-0`.
fn tick(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_chart_is_an_svg_document_with_its_curves_and_labels() {
        let curves = [
            Curve::new(
                "x",
                (0..50)
                    .map(|k| (k as f64, (k as f64 / 8.0).sin()))
                    .collect(),
            ),
            Curve::new("re(K₁,₁)", (0..50).map(|k| (k as f64, 0.25)).collect()),
        ];
        let svg = svg("harmonic rotor", "t", &curves, Style::Lines).unwrap();
        assert!(svg.starts_with("<svg"), "{}", &svg[..60.min(svg.len())]);
        assert!(svg.trim_end().ends_with("</svg>"));
        // The two curves and their two marks in the legend are the polylines drawn 2 wide.
        assert_eq!(svg.matches(r#"stroke-width="2""#).count(), 4);
        for text in ["harmonic rotor", "re(K₁,₁)", "\nt\n"] {
            assert!(svg.contains(text), "{text:?} missing");
        }
    }

    #[test]
    fn dots_are_circles_one_a_point() {
        let curve = Curve::new("p_y", vec![(0.0, 1.0), (0.5, -1.0), (1.0, 0.0)]);
        let svg = svg("section", "y", &[curve], Style::Dots).unwrap();
        // One a point, and one in the legend.
        assert_eq!(svg.matches("<circle").count(), 3 + 1);
        assert!(!svg.contains(r#"stroke-width="2""#), "no line");
    }

    #[test]
    fn the_legend_goes_to_the_emptiest_corner() {
        let curve = |points: Vec<(f64, f64)>| Curve::new("p", points);
        let (xs, ys) = ((0.0, 1.0), (0.0, 1.0));
        // A rising line fills the lower left and upper right corners.
        let rising = curve(
            (0..=100)
                .map(|k| (k as f64 / 100.0, k as f64 / 100.0))
                .collect(),
        );
        let corner = legend_corner(std::slice::from_ref(&rising), xs, ys);
        assert!(
            matches!(corner, SeriesLabelPosition::UpperLeft),
            "{corner:?}"
        );
        // A falling one fills the upper left and lower right: the upper right is free.
        let falling = curve(
            (0..=100)
                .map(|k| (k as f64 / 100.0, 1.0 - k as f64 / 100.0))
                .collect(),
        );
        let corner = legend_corner(&[falling], xs, ys);
        assert!(
            matches!(corner, SeriesLabelPosition::UpperRight),
            "{corner:?}"
        );
    }

    /// An angle going up through π twice and back down through −π: the pieces end and begin
    /// at the edges, at the interpolated value, and every point is reduced to [−π, π).
    #[test]
    fn an_angle_axis_is_reduced_and_broken_at_the_edges() {
        use std::f64::consts::PI;
        let points = [
            (3.0, 0.0),
            (PI + 1.0, 1.0),       // crosses π at y = (π − 3)/(π − 2)
            (3.0 * PI + 0.5, 2.0), // crosses 3π
            (-PI - 0.5, 3.0),      // back down through 3π, π and −π
        ];
        let curve = Curve::with_angle_x("p_θ", &points);
        let xs: Vec<f64> = curve.points.iter().map(|p| p.0).collect();
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        let expected_x = [
            3.0,
            PI,
            -PI,
            1.0 - PI,
            PI,
            -PI,
            0.5 - PI,
            -PI,
            PI,
            -PI,
            PI,
            -PI,
            PI,
            PI - 0.5,
        ];
        assert_eq!(xs.len(), expected_x.len(), "{xs:?}");
        assert!(
            xs.iter().zip(expected_x).all(|(&a, b)| close(a, b)),
            "{xs:?}"
        );
        assert_eq!(curve.breaks, vec![2, 5, 8, 10, 12]);
        assert!(close(curve.points[1].1, (PI - 3.0) / (PI - 2.0)));
        assert_eq!(
            curve.points[1].1, curve.points[2].1,
            "the same value on both edges"
        );
        let pieces: Vec<usize> = curve.pieces().map(<[_]>::len).collect();
        assert_eq!(pieces, vec![2, 3, 3, 2, 2, 2]);
        assert!(xs.iter().all(|x| (-PI..=PI).contains(x)));
        // Within (−π, π) nothing is broken.
        let inside = Curve::with_angle_x("p_θ", &[(-1.0, 0.0), (1.0, 1.0), (-0.5, 2.0)]);
        assert_eq!((inside.points.len(), inside.breaks.len()), (3, 0));
    }

    /// Points many turns apart, or an angle that is not finite, break the curve once, where
    /// drawing each turn took 10¹¹ pieces (and an infinite angle never ended); 64 turns are
    /// still drawn.
    #[test]
    fn an_angle_too_fast_for_its_samples_breaks_the_curve() {
        let far = Curve::with_angle_x("p_θ", &[(0.0, 0.0), (1e12, 1.0), (1e12 + 0.5, 2.0)]);
        assert_eq!((far.points.len(), far.breaks.clone()), (3, vec![1]));
        assert_eq!(far.points[0], (0.0, 0.0));
        assert_eq!(far.points[1].1, 1.0);
        let endless = Curve::with_angle_x("p_θ", &[(0.0, 0.0), (f64::INFINITY, 1.0), (0.0, 2.0)]);
        assert_eq!(endless.breaks, vec![1, 2]);
        let turns = 2.0 * std::f64::consts::PI * MAX_WRAPS;
        let drawn = Curve::with_angle_x("p_θ", &[(0.0, 0.0), (turns, 1.0)]);
        assert_eq!(drawn.breaks.len(), MAX_WRAPS as usize);
    }

    #[test]
    fn a_flat_curve_gets_a_range_around_its_value() {
        let (lo, hi) = span([2.0, 2.0 + 1e-14].into_iter()).unwrap();
        assert!(lo < 2.0 && hi > 2.0 && hi - lo < 0.01);
        let (lo, hi) = span([-1.0, 3.0].into_iter()).unwrap();
        assert!(lo < -1.0 && hi > 3.0);
        assert_eq!(span([-1e308, 1e308].into_iter()), None);
    }

    #[test]
    fn ticks_have_the_decimals_of_their_step_and_no_minus_zero() {
        assert_eq!(decimals((-0.5, 0.5)), 1);
        assert_eq!(decimals((0.0, 20.0)), 0);
        assert_eq!(tick(-1e-17, 1), "0.0");
        assert_eq!(tick(-0.25, 2), "-0.25");
    }
}
