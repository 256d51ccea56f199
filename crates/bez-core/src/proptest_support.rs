//! Shared proptest strategies (feature `proptest-support`), for this and dependent crates.

use crate::vector::Vector;
use proptest::prelude::*;

use crate::bezier_form::BezierForm;
use crate::curve::BezierCurve;

/// Random finite control points with coordinates in [−range, range].
pub fn control_points<const D: usize>(
    degrees: core::ops::RangeInclusive<usize>,
    range: f64,
) -> impl Strategy<Value = Vec<Vector<D>>> {
    degrees.prop_flat_map(move |n| {
        proptest::collection::vec(
            proptest::array::uniform::<_, D>(-range..=range).prop_map(Vector::from),
            n + 1,
        )
    })
}

/// A random curve of degree in `degrees` with coordinates in [−range, range].
pub fn curve<const D: usize>(
    degrees: core::ops::RangeInclusive<usize>,
    range: f64,
) -> impl Strategy<Value = BezierCurve<D>> {
    control_points::<D>(degrees, range).prop_map(BezierCurve::from_valid)
}

/// A parameter in [0, 1], including both endpoints with positive probability.
pub fn unit_parameter() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0]
}

/// Checks every provided method of a [`BezierForm`] implementor against an independent oracle:
/// `position(t)` and `velocity(t)` = C'(t), computed some other way than through the Bézier form
/// (a basis of the curve's own family, a closed form, another representation).
///
/// Compared on 2001 uniform parameters: `eval`, `eval_many`, `sample_uniform`, `start`, `end`
/// (to `tolerance`); the derivative curve (to `tolerance` · max(1, degree)); `split(0.4)` and
/// `subsegment(0.2, 0.7)` (each piece at 21 parameters against the oracle on the mapped
/// parameter); `arc_length(1e-12)` against composite Simpson of |velocity| on 2000 intervals
/// (to 1e-8 · max(1, L)); `bounding_box` (contains every sample, and each face lies within
/// h/2 · max |velocity| of the extreme sample, h the sample spacing); `nearest` for nine query
/// points around the box (the point is the oracle's at the returned t, and the distance is at
/// most the sampled minimum and at least that minimum less h/2 · max |velocity|).
///
/// # Errors
/// A message naming the first check that failed and the values compared.
pub fn check_bezier_form<const D: usize, C: BezierForm<D> + ?Sized>(
    curve: &C,
    position: impl Fn(f64) -> Vector<D>,
    velocity: impl Fn(f64) -> Vector<D>,
    tolerance: f64,
) -> Result<(), String> {
    let close = |what: &str, t: f64, got: Vector<D>, want: Vector<D>, tol: f64| {
        let e = (got - want).norm();
        if e <= tol {
            Ok(())
        } else {
            Err(format!("{what} at t = {t}: error {e:e} > {tol:e}"))
        }
    };
    let fail = |e: crate::CoreError| e.to_string();
    const M: usize = 2000;
    let ts: Vec<f64> = (0..=M).map(|k| k as f64 / M as f64).collect();
    let mut many = Vec::new();
    curve.eval_many(&ts, &mut many).map_err(fail)?;
    let uniform = curve.sample_uniform(M + 1).map_err(fail)?;
    let hodograph = curve.derivative().map_err(fail)?;
    let dtol = tolerance * (curve.degree().max(1) as f64);
    let (mut samples, mut max_speed) = (Vec::with_capacity(M + 1), 0.0_f64);
    for (k, &t) in ts.iter().enumerate() {
        let want = position(t);
        close("eval", t, curve.eval(t).map_err(fail)?, want, tolerance)?;
        close("eval_many", t, many[k], want, tolerance)?;
        close("sample_uniform", t, uniform[k], want, tolerance)?;
        let v = velocity(t);
        close("derivative", t, hodograph.eval(t).map_err(fail)?, v, dtol)?;
        max_speed = max_speed.max(v.norm());
        samples.push(want);
    }
    close("start", 0.0, curve.start(), position(0.0), tolerance)?;
    close("end", 1.0, curve.end(), position(1.0), tolerance)?;

    let (left, right) = curve.split(0.4).map_err(fail)?;
    let piece = curve.subsegment(0.2, 0.7).map_err(fail)?;
    for k in 0..=20 {
        let u = f64::from(k) / 20.0;
        close(
            "split (left)",
            u,
            left.eval(u).map_err(fail)?,
            position(0.4 * u),
            tolerance,
        )?;
        let r = 0.4 + 0.6 * u;
        close(
            "split (right)",
            u,
            right.eval(u).map_err(fail)?,
            position(r),
            tolerance,
        )?;
        let s = 0.2 + 0.5 * u;
        close(
            "subsegment",
            u,
            piece.eval(u).map_err(fail)?,
            position(s),
            tolerance,
        )?;
    }

    let h = 1.0 / M as f64;
    let simpson = (0..M / 2)
        .map(|j| {
            let t = 2.0 * j as f64 * h;
            velocity(t).norm() + 4.0 * velocity(t + h).norm() + velocity(t + 2.0 * h).norm()
        })
        .sum::<f64>()
        * h
        / 3.0;
    let length = curve.arc_length(1e-12).map_err(fail)?;
    if (length - simpson).abs() > 1e-8 * length.max(1.0) {
        return Err(format!("arc_length {length} but Simpson gives {simpson}"));
    }

    let gap = 0.5 * h * max_speed + tolerance;
    let b = curve.bounding_box();
    let Some(sampled) = crate::Aabb::from_points(&samples) else {
        return Err("no samples".into());
    };
    if samples.iter().any(|p| !b.contains(p, tolerance)) {
        return Err(format!("bounding_box {b:?} misses a sample"));
    }
    for d in 0..D {
        if b.max[d] - sampled.max[d] > gap || sampled.min[d] - b.min[d] > gap {
            return Err(format!(
                "bounding_box {b:?} is wider than the samples {sampled:?}"
            ));
        }
    }

    let centre = (b.min + b.max) * 0.5;
    let half = b.size() * 0.75 + Vector::repeat(0.1);
    for corner in 0..9_u32 {
        let mut q = centre;
        for d in 0..D {
            // Corners of a box around the curve (first two coordinates), and its centre.
            let sign = match (corner, d) {
                (8, _) => 0.0,
                (_, 0) => f64::from(corner & 1) * 2.0 - 1.0,
                (_, 1) => f64::from((corner >> 1) & 1) * 2.0 - 1.0,
                _ => f64::from((corner >> 2) & 1) * 2.0 - 1.0,
            };
            q[d] += sign * half[d];
        }
        let n = curve.nearest(&q).map_err(fail)?;
        close("nearest (point)", n.t, n.point, position(n.t), tolerance)?;
        let best = samples
            .iter()
            .map(|p| (p - q).norm())
            .fold(f64::INFINITY, f64::min);
        if n.distance > best + tolerance || n.distance < best - gap {
            return Err(format!(
                "nearest to {q:?}: distance {} but sampled minimum {best}",
                n.distance
            ));
        }
    }
    Ok(())
}

/// The names a crate re-exports (`pub use crate::…::{A, B};` in `lib_rs`, its `src/lib.rs`
/// text, leaving out those under a `#[cfg(feature = "paper")]`) that do not occur as a word
/// in `suite` (the text of the crate's adversarial test): the items that test forgot. A crate's
/// suite asserts that this list is empty, so a new public item fails the build of its tests
/// until it joins the suite.
#[must_use]
pub fn missing_from_suite(lib_rs: &str, suite: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut paper_only = false;
    let mut statement = String::new();
    for line in lib_rs.lines().map(str::trim) {
        if statement.is_empty() {
            if line.starts_with("#[cfg(feature = \"paper\")]") {
                paper_only = true;
                continue;
            }
            if !line.starts_with("pub use crate::") {
                paper_only &= line.starts_with("#[");
                continue;
            }
        }
        statement.push_str(line);
        statement.push(' ');
        if !line.ends_with(';') {
            continue;
        }
        if !paper_only {
            let body = statement.trim().trim_end_matches(';');
            let list = match (body.find('{'), body.rfind('}')) {
                (Some(a), Some(b)) if a < b => &body[a + 1..b],
                _ => body.rsplit("::").next().unwrap_or(""),
            };
            names.extend(
                list.split(',')
                    .map(|n| n.trim().rsplit("::").next().unwrap_or("").trim())
                    .filter(|n| !n.is_empty())
                    .map(str::to_string),
            );
        }
        statement.clear();
        paper_only = false;
    }
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    names
        .into_iter()
        .filter(|name| {
            !suite.match_indices(name.as_str()).any(|(i, _)| {
                let before = suite[..i].chars().next_back();
                let after = suite[i + name.len()..].chars().next();
                !before.is_some_and(is_word) && !after.is_some_and(is_word)
            })
        })
        .collect()
}

/// The public functions and methods (`pub fn`, `pub const fn`) that `sources` define and that
/// `suite` never calls: the callable surface the adversarial test forgot.
///
/// `sources` are a crate's `src/*.rs` texts; `lib_rs` is its `src/lib.rs`, used to leave out
/// modules declared under `#[cfg(feature = "paper")]`. In each source the text from its first
/// `#[cfg(test)]` on is ignored, and so is a function right under a `#[cfg(feature = "paper")]`
/// attribute. A name counts as called when the suite has it after `.` or `::`, or before `(`.
/// Functions that only the `paper` feature exports through a public type or module may be
/// listed in the suite on a line `// paper-only: name, name`.
#[must_use]
pub fn uncalled_in_suite(lib_rs: &str, sources: &[(&str, &str)], suite: &str) -> Vec<String> {
    let paper_modules: Vec<&str> = paper_modules(lib_rs);
    let mut names: Vec<String> = Vec::new();
    for (file, text) in sources {
        let module = file.trim_end_matches(".rs");
        if paper_modules.contains(&module) {
            continue;
        }
        let body = text.split("#[cfg(test)]").next().unwrap_or("");
        let mut paper_only = false;
        for line in body.lines().map(str::trim) {
            if line.starts_with("#[cfg(feature = \"paper\")]") {
                paper_only = true;
                continue;
            }
            let rest = line
                .strip_prefix("pub fn ")
                .or_else(|| line.strip_prefix("pub const fn "));
            if let Some(rest) = rest {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !paper_only && !name.is_empty() && !names.contains(&name) {
                    names.push(name);
                }
            }
            if !line.starts_with("#[") && !line.starts_with("///") {
                paper_only = false;
            }
        }
    }
    let paper_only: Vec<&str> = suite
        .lines()
        .filter_map(|l| l.trim().strip_prefix("// paper-only:"))
        .flat_map(|l| l.split(','))
        .map(str::trim)
        .collect();
    names.retain(|name| !called(suite, name) && !paper_only.contains(&name.as_str()));
    names
}

/// [`uncalled_in_suite`] for the crate at `manifest_dir` (its `CARGO_MANIFEST_DIR`): its
/// `src/lib.rs` and `src/*.rs` (these test helpers aside) against the text of `suite`.
///
/// # Panics
/// As [`crate_sources`].
#[must_use]
#[allow(
    clippy::expect_used,
    reason = "a test helper: an unreadable source fails the test"
)]
pub fn uncalled_in_crate_suite(manifest_dir: &str, suite: &str) -> Vec<String> {
    let sources = crate_sources(manifest_dir);
    let lib_rs = sources
        .iter()
        .find(|(file, _)| file == "lib.rs")
        .map(|(_, text)| text.as_str())
        .expect("the crate has a src/lib.rs");
    let sources: Vec<(&str, &str)> = sources
        .iter()
        .filter(|(file, _)| file != "proptest_support.rs")
        .map(|(f, t)| (f.as_str(), t.as_str()))
        .collect();
    uncalled_in_suite(lib_rs, &sources, suite)
}

/// Modules that `lib_rs` declares right under a `#[cfg(feature = "paper")]` attribute.
fn paper_modules(lib_rs: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut paper = false;
    for line in lib_rs.lines().map(str::trim) {
        if line.starts_with("#[cfg(feature = \"paper\")]") {
            paper = true;
            continue;
        }
        if paper {
            let decl = line
                .strip_prefix("pub mod ")
                .or_else(|| line.strip_prefix("mod "));
            if let Some(decl) = decl {
                out.push(decl.trim_end_matches(';').trim());
            }
        }
        paper &= line.starts_with("#[") || line.starts_with("//");
    }
    out
}

/// Whether `name` occurs in `suite` as a call or a path: after `.` or `::`, or before `(`.
fn called(suite: &str, name: &str) -> bool {
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    suite.match_indices(name).any(|(i, _)| {
        let before = &suite[..i];
        let after = &suite[i + name.len()..];
        if before.chars().next_back().is_some_and(is_word)
            || after.chars().next().is_some_and(is_word)
        {
            return false;
        }
        before.ends_with('.')
            || before.ends_with("::")
            || after.starts_with('(')
            || after.starts_with("::<")
    })
}

/// The `src/*.rs` files of the crate at `manifest_dir` (its `CARGO_MANIFEST_DIR`), as
/// (file name, text) pairs for [`uncalled_in_suite`].
///
/// # Panics
/// When the directory or a file cannot be read (a test helper: the test fails).
#[must_use]
#[allow(
    clippy::expect_used,
    reason = "a test helper: an unreadable source fails the test"
)]
pub fn crate_sources(manifest_dir: &str) -> Vec<(String, String)> {
    let dir = std::path::Path::new(manifest_dir).join("src");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("the crate's src directory is readable")
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|p| {
            let name = p
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let text = std::fs::read_to_string(&p).expect("a source file is readable");
            (name, text)
        })
        .collect();
    out.sort();
    out
}

/// The two completeness tests of a crate's standing adversarial suite (`tests/no_panic.rs`):
/// `every_public_item_is_in_this_suite` (each name `src/lib.rs` re-exports is named by the suite,
/// [`missing_from_suite`]) and `every_public_function_is_called_in_this_suite` (each public
/// function and method of `src/` is called by it, [`uncalled_in_crate_suite`]). Invoke it once at
/// the end of the suite; the suite file must be `tests/no_panic.rs` of the crate under test.
///
/// ```ignore
/// // at the end of tests/no_panic.rs
/// bez_core::suite_completeness_tests!();
/// ```
#[macro_export]
macro_rules! suite_completeness_tests {
    () => {
        /// Every item the crate re-exports is exercised by this suite (a new public item fails
        /// here until it joins the suite).
        #[test]
        fn every_public_item_is_in_this_suite() {
            let missing = $crate::proptest_support::missing_from_suite(
                include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/src/lib.rs")),
                include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/no_panic.rs")),
            );
            assert!(missing.is_empty(), "not covered by this suite: {missing:?}");
        }

        /// Every public function and method of the crate is called by this suite (a new one
        /// fails here until it joins the suite).
        #[test]
        fn every_public_function_is_called_in_this_suite() {
            let uncalled = $crate::proptest_support::uncalled_in_crate_suite(
                env!("CARGO_MANIFEST_DIR"),
                include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/no_panic.rs")),
            );
            assert!(
                uncalled.is_empty(),
                "not called by this suite: {uncalled:?}"
            );
        }
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_re_exports_missing_from_a_suite() {
        let lib = "mod a;\npub use crate::a::{Alpha, beta,\n    gamma};\npub use crate::b::Delta;\n\
                   #[cfg(feature = \"paper\")]\npub use crate::c::paper_thing;\n";
        let suite = "let _ = beta(1); Alpha::new(); gammas();";
        assert_eq!(missing_from_suite(lib, suite), ["gamma", "Delta"]);
    }

    #[test]
    fn finds_public_functions_the_suite_never_calls() {
        let lib = "mod a;\n#[cfg(feature = \"paper\")]\npub mod cases;\n";
        let a = "impl X {\n    pub fn called(&self) {}\n    pub const fn pathed() {}\n    \
                 pub fn only_named() {}\n    fn private() {}\n    #[cfg(feature = \"paper\")]\n    \
                 pub fn paper_only() {}\n}\n#[cfg(test)]\nmod tests { pub fn in_tests() {} }\n";
        let cases = "pub fn reproduction() {}\n";
        let suite = "x.called(); X::pathed(); // only_named is mentioned, not called\n\
                     // paper-only: listed";
        let a = a.replace("fn private()", "pub fn listed() {}\n    fn private()");
        assert_eq!(
            uncalled_in_suite(lib, &[("a.rs", &a), ("cases.rs", cases)], suite),
            ["only_named"]
        );
    }
}
