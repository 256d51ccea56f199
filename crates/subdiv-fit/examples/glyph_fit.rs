//! Fits subdivision curves with sharp vertices to the outlines of TrueType glyphs.
//!
//! ```text
//! cargo run --release -p subdiv-fit --example glyph_fit -- FONT.ttf [TEXT] [TOLERANCE] [OUT.svg]
//! ```
//!
//! Each contour of each glyph is sampled densely (about every 0.01 em along lines and curves, the
//! on-curve points kept so corners stay on samples), normalized to em units, and fitted as a
//! closed curve; the report (points, rounds, control points, errors) goes to standard output and
//! the data and fitted curves (as exact cubic Bézier paths) to an SVG file.
//! No font is shipped with the project: pass any TrueType or OpenType file.
#![allow(
    clippy::print_stdout,
    clippy::print_stderr,
    reason = "a command-line example reports on the terminal"
)]

use std::fmt::Write as _;

use subdiv_fit::{FitOptions, Vector2, fit, svg_path};

/// Collects the contours of one glyph as dense point lists.
struct Sampler {
    step: f64,
    scale: f64,
    contours: Vec<Vec<Vector2>>,
    current: Vec<Vector2>,
    last: Vector2,
}

impl Sampler {
    fn pt(&self, x: f32, y: f32) -> Vector2 {
        Vector2::new(f64::from(x) * self.scale, f64::from(y) * self.scale)
    }

    fn push_curve(&mut self, end: Vector2, f: impl Fn(f64) -> Vector2, len: f64) {
        let n = ((len / self.step).ceil() as usize).max(1);
        for k in 1..n {
            self.current.push(f(k as f64 / n as f64));
        }
        self.current.push(end);
        self.last = end;
    }

    fn finish(&mut self) {
        let mut c = std::mem::take(&mut self.current);
        c.dedup();
        if c.len() > 1 && c.first() == c.last() {
            c.pop();
        }
        if c.len() >= 3 {
            self.contours.push(c);
        }
    }
}

impl ttf_parser::OutlineBuilder for Sampler {
    fn move_to(&mut self, x: f32, y: f32) {
        self.finish();
        let p = self.pt(x, y);
        self.current.push(p);
        self.last = p;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let (a, b) = (self.last, self.pt(x, y));
        self.push_curve(b, |t| a + (b - a) * t, (b - a).norm());
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (a, c, b) = (self.last, self.pt(x1, y1), self.pt(x, y));
        let len = (c - a).norm() + (b - c).norm();
        self.push_curve(
            b,
            |t| a * (1.0 - t) * (1.0 - t) + c * (2.0 * t * (1.0 - t)) + b * (t * t),
            len,
        );
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (a, c1, c2, b) = (self.last, self.pt(x1, y1), self.pt(x2, y2), self.pt(x, y));
        let len = (c1 - a).norm() + (c2 - c1).norm() + (b - c2).norm();
        self.push_curve(
            b,
            |t| {
                let s = 1.0 - t;
                a * (s * s * s) + c1 * (3.0 * s * s * t) + c2 * (3.0 * s * t * t) + b * (t * t * t)
            },
            len,
        );
    }

    fn close(&mut self) {
        self.finish();
    }
}

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let Some(font_path) = args.get(1) else {
        return Err("usage: glyph_fit FONT.ttf [TEXT] [TOLERANCE] [OUT.svg]".into());
    };
    let text = args.get(2).map_or("S&g", String::as_str);
    let tol: f64 = args.get(3).map_or(Ok(0.004), |s| s.parse())?;
    let out = args.get(4).map_or("glyph_fit.svg", String::as_str);
    let bytes = std::fs::read(font_path)?;
    let face = ttf_parser::Face::parse(&bytes, 0)?;
    let scale = 1.0 / f64::from(face.units_per_em());
    let mut svg_body = String::new();
    println!("tolerance {tol} em");
    println!(
        "| glyph | contour | points | initial | rounds | control points | max data→curve | max curve→data | µs |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut pen = 0.0;
    for ch in text.chars() {
        let Some(id) = face.glyph_index(ch) else {
            eprintln!("no glyph for {ch:?}");
            continue;
        };
        let mut s = Sampler {
            step: 0.01,
            scale,
            contours: Vec::new(),
            current: Vec::new(),
            last: Vector2::zeros(),
        };
        face.outline_glyph(id, &mut s);
        s.finish();
        let dx = pen;
        pen += face
            .glyph_hor_advance(id)
            .map_or(0.8, |a| f64::from(a) * scale);
        let _ = writeln!(svg_body, "<g transform=\"translate({dx} 0)\">");
        for (k, data) in s.contours.iter().enumerate() {
            let poly: Vec<String> = data
                .iter()
                .map(|p| format!("{},{}", p.x(), p.y()))
                .collect();
            let _ = writeln!(
                svg_body,
                "<polygon points=\"{}\" fill=\"none\" stroke=\"#999\" stroke-width=\"0.004\"/>",
                poly.join(" ")
            );
            let start = std::time::Instant::now();
            match fit(data, subdiv_fit::Closure::Closed, &FitOptions::new(tol)) {
                Ok(f) => {
                    let us = start.elapsed().as_secs_f64() * 1e6;
                    let r = f.last().copied().ok_or("empty report")?;
                    println!(
                        "| {ch} | {k} | {} | {} | {} | {} | {:.5} | {:.5} | {us:.0} |",
                        data.len(),
                        f.initial.len(),
                        f.rounds(),
                        r.control_points,
                        r.max_data_to_curve,
                        r.max_curve_to_data
                    );
                    let _ = writeln!(
                        svg_body,
                        "<path d=\"{}\" fill=\"none\" stroke=\"#c00\" stroke-width=\"0.003\"/>",
                        svg_path(&f.curve)?
                    );
                }
                Err(e) => println!("| {ch} | {k} | {} | fit failed: {e} |", data.len()),
            }
        }
        svg_body.push_str("</g>\n");
    }
    let width = pen + 0.2;
    let svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-0.1 -1.1 {width} 1.5\">\n<g transform=\"scale(1 -1)\">\n{svg_body}</g>\n</svg>\n"
    );
    std::fs::write(out, svg)?;
    println!("wrote {out}");
    Ok(())
}
