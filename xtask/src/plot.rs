//! A small SVG plotting helper on plotters: line and point series in one chart.
//!
//! Output is deterministic (byte-identical across runs), so figures can be committed.

use std::path::{Path, PathBuf};

use plotters::prelude::*;

use crate::DynError;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Style {
    /// A polyline through the points.
    Line,
    /// A polyline with a small circle at every point (control polygons).
    LinePoints,
    /// Circles only (data points).
    Points,
}

/// One named series of (x, y) points.
#[derive(Debug, Clone)]
pub(crate) struct Series {
    pub(crate) label: String,
    pub(crate) points: Vec<(f64, f64)>,
    pub(crate) style: Style,
}

impl Series {
    /// A series with a label, points and style.
    pub(crate) fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Self {
        Self {
            label: label.into(),
            points,
            style,
        }
    }
}

/// A chart: title, axis labels, series; equal aspect for geometry, free for graphs.
#[derive(Debug, Clone)]
pub(crate) struct Plot {
    pub(crate) title: String,
    pub(crate) x_label: String,
    pub(crate) y_label: String,
    pub(crate) series: Vec<Series>,
    /// Keep one unit in x as long as one unit in y (curves, shapes).
    pub(crate) equal_aspect: bool,
    pub(crate) size: (u32, u32),
}

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

impl Plot {
    /// A chart with default size 900 x 700 and free aspect.
    pub(crate) fn new(title: impl Into<String>, x_label: &str, y_label: &str) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            equal_aspect: false,
            size: (900, 700),
        }
    }

    /// Adds a series (builder style).
    pub(crate) fn with(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }

    /// Sets equal aspect (builder style).
    pub(crate) fn equal(mut self) -> Self {
        self.equal_aspect = true;
        self
    }

    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let pts = self
            .series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|p| p.0.is_finite() && p.1.is_finite());
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for &(x, y) in pts {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if !x0.is_finite() {
            return ((0.0, 1.0), (0.0, 1.0));
        }
        let pad = |a: f64, b: f64| {
            let w = (b - a).max(1e-9 * a.abs().max(1.0));
            (a - 0.05 * w, b + 0.05 * w)
        };
        let (mut xr, mut yr) = (pad(x0, x1), pad(y0, y1));
        if self.equal_aspect {
            // Plot area is roughly size minus label margins; match units per pixel.
            let (w, h) = (
                f64::from(self.size.0) - 90.0,
                f64::from(self.size.1) - 110.0,
            );
            let (sx, sy) = ((xr.1 - xr.0) / w, (yr.1 - yr.0) / h);
            if sx > sy {
                let c = 0.5 * (yr.0 + yr.1);
                yr = (c - 0.5 * sx * h, c + 0.5 * sx * h);
            } else {
                let c = 0.5 * (xr.0 + xr.1);
                xr = (c - 0.5 * sy * w, c + 0.5 * sy * w);
            }
        }
        (xr, yr)
    }

    /// Writes the chart as SVG to `path` and returns the path.
    pub(crate) fn write_svg(&self, path: &Path) -> Result<PathBuf, DynError> {
        let ((x0, x1), (y0, y1)) = self.ranges();
        let root = SVGBackend::new(path, self.size).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&self.title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .max_light_lines(0)
            .draw()?;
        for (k, s) in self.series.iter().enumerate() {
            let color = PALETTE[k % PALETTE.len()];
            let pts: Vec<(f64, f64)> = s
                .points
                .iter()
                .copied()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .collect();
            let anno = match s.style {
                Style::Line => chart.draw_series(LineSeries::new(pts, color.stroke_width(2)))?,
                Style::LinePoints => {
                    chart.draw_series(PointSeries::of_element(
                        pts.clone(),
                        3,
                        color.filled(),
                        &|c, s, st| EmptyElement::at(c) + Circle::new((0, 0), s, st),
                    ))?;
                    chart.draw_series(LineSeries::new(pts, color.stroke_width(1)))?
                }
                Style::Points => chart.draw_series(PointSeries::of_element(
                    pts,
                    3,
                    color.filled(),
                    &|c, s, st| EmptyElement::at(c) + Circle::new((0, 0), s, st),
                ))?,
            };
            if !s.label.is_empty() {
                anno.label(s.label.as_str()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            }
        }
        if self.series.iter().any(|s| !s.label.is_empty()) {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()?;
        }
        root.present()?;
        Ok(path.to_path_buf())
    }
}
