//! The STEP and IGES readers on crafted hostile files (each must be refused quickly, with an
//! error, without a panic or a huge allocation) and on legal variants the writer does not
//! produce (CRLF, comments, escaped quotes, several surfaces, other entities first).

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

use std::time::{Duration, Instant};

use bez_core::Vector3;
use pde_bezier::{BSplineSurface, PdeError, read_iges, read_step, write_iges, write_step};

/// Generous bound for one read of a file of a few kilobytes: a hang detector, not a speed test.
const BOUND: Duration = Duration::from_secs(5);

fn surface(shift: f64) -> BSplineSurface {
    BSplineSurface {
        degree_u: 2,
        degree_v: 1,
        knots_u: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        knots_v: vec![0.0, 0.0, 1.0, 1.0],
        points: (0..6)
            .map(|i| Vector3::new(i as f64 + shift, 0.5, -1.0))
            .collect(),
    }
}

fn step_text(s: &BSplineSurface) -> String {
    let mut out = Vec::new();
    write_step(s, "corpus", &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

fn iges_text(s: &BSplineSurface) -> String {
    let mut out = Vec::new();
    write_iges(s, "corpus", &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

fn refused<T: std::fmt::Debug>(what: &str, read: impl FnOnce() -> Result<T, PdeError>) {
    let start = Instant::now();
    let r = read();
    assert!(r.is_err(), "{what}: accepted {r:?}");
    assert!(
        start.elapsed() < BOUND,
        "{what}: took {:?}",
        start.elapsed()
    );
}

#[test]
fn hostile_step_files_are_refused() {
    let good = step_text(&surface(0.0));
    assert_eq!(read_step(&good).unwrap(), [surface(0.0)]);
    // The surface line: ...,(3,3),(2,2),(0.0…E0,1.0…E0),(…),.UNSPECIFIED.);
    let multiplicity = good.replacen("(3,3)", "(1000000000000,3)", 1);
    refused("multiplicity 1e12", || read_step(&multiplicity));
    let infinite = good.replacen("(3,3)", "(1.E400,3)", 1);
    refused("multiplicity 1e400 (inf)", || read_step(&infinite));
    let degree = good.replacen(
        "B_SPLINE_SURFACE_WITH_KNOTS('',2,",
        "B_SPLINE_SURFACE_WITH_KNOTS('',18446744073709551615,",
        1,
    );
    refused("degree usize::MAX", || read_step(&degree));
    let nested = good.replacen(
        "CARTESIAN_POINT('',(",
        &format!("CARTESIAN_POINT('',{}(", "(".repeat(100_000)),
        1,
    );
    refused("100,000 nested parentheses", || read_step(&nested));
    let equal = good.replace("1.0000000000000000E0)", "0.0000000000000000E0)");
    refused("all knots equal", || read_step(&equal));
    let unterminated = good.replacen("('corpus')", "('corpus)", 1);
    refused("unterminated string", || read_step(&unterminated));
    refused("no end", || {
        read_step(good.trim_end().trim_end_matches("END-ISO-10303-21;"))
    });
}

#[test]
fn hostile_iges_files_are_refused() {
    let good = iges_text(&surface(0.0));
    assert_eq!(read_iges(&good).unwrap(), [surface(0.0)]);
    let first_p = good.lines().position(|l| l.as_bytes()[72] == b'P').unwrap();
    let with_record = |record: &str| -> String {
        good.lines()
            .enumerate()
            .map(|(i, l)| {
                if i == first_p {
                    format!("{:<64}{}\n", record, &l[64..])
                } else {
                    format!("{l}\n")
                }
            })
            .collect()
    };
    for (what, record) in [
        (
            "counts that overflow",
            "128,18446744073709551615,18446744073709551615,1,1,0,0,1,0,0;",
        ),
        (
            "a billion control points",
            "128,1000000000,1000000000,1,1,0,0,1,0,0;",
        ),
        (
            "degree usize::MAX",
            "128,1,1,18446744073709551615,1,0,0,1,0,0;",
        ),
        ("a record too short", "128,1,1,1,1,0,0,1,0,0,0.,0.;"),
        (
            "a non-finite real",
            "128,1,1,1,1,0,0,1,0,0,1.D400,0.,1.,1.,0.,0.,1.,1.;",
        ),
    ] {
        refused(what, || read_iges(&with_record(record)));
    }
}

#[test]
fn legal_step_variants_are_read_with_every_surface() {
    // Two files' data sections merged into one file with CRLF line ends, comments, and strings
    // holding an escaped quote and a ';'.
    let (a, b) = (step_text(&surface(0.0)), step_text(&surface(10.0)));
    let data = |t: &str| -> String {
        let start = t.find("DATA;").unwrap() + 5;
        let end = t.rfind("ENDSEC;").unwrap();
        t[start..end].to_string()
    };
    let renumber = |d: &str, by: usize| -> String {
        let mut out = String::new();
        let mut chars = d.chars().peekable();
        while let Some(c) = chars.next() {
            out.push(c);
            if c == '#' {
                let mut n = String::new();
                while let Some(&d) = chars.peek().filter(|d| d.is_ascii_digit()) {
                    n.push(d);
                    chars.next();
                }
                out.push_str(&(n.parse::<usize>().unwrap() + by).to_string());
            }
        }
        out
    };
    let header = &a[..a.find("DATA;").unwrap()];
    let text = format!(
        "{header}DATA;\n/* first surface */\n{}{}\n#9999=PRODUCT('it''s; tricky','x','',(#3));\nENDSEC;\nEND-ISO-10303-21;\n",
        data(&a),
        renumber(&data(&b), 1000)
    )
    .replace('\n', "\r\n");
    let surfaces = read_step(&text).unwrap();
    assert_eq!(surfaces, [surface(0.0), surface(10.0)]);
}

#[test]
fn iges_entity_128_is_found_after_other_entities() {
    let good = iges_text(&surface(0.0));
    // A colour definition (entity 314) record before the surface's.
    let first_p = good.lines().position(|l| l.as_bytes()[72] == b'P').unwrap();
    let mut lines: Vec<String> = good.lines().map(str::to_string).collect();
    let other = format!("{:<64}{:>8}{}{:>7}", "314,50.,50.,50.,2HMy;", 3, 'P', 0);
    lines.insert(first_p, other);
    let text = lines.join("\r\n");
    assert_eq!(read_iges(&text).unwrap(), [surface(0.0)]);
}

#[test]
fn step_rational_surface_with_unit_weights_is_read_as_polynomial() {
    let good = step_text(&surface(0.0));
    let line = good
        .lines()
        .find(|l| l.contains("B_SPLINE_SURFACE_WITH_KNOTS"))
        .unwrap();
    let (head, rest) = line.split_once("=B_SPLINE_SURFACE_WITH_KNOTS('',").unwrap();
    let (grid, knots) = rest.split_once(",.F.,.F.,.F.,").unwrap();
    let knots = knots.strip_suffix(");").unwrap();
    // The complex instance Open CASCADE writes for a rational surface (2 x 3 weights here).
    let complex = |weights: &str| {
        let entity = format!(
            "{head}=( BOUNDED_SURFACE() B_SPLINE_SURFACE({grid},.F.,.F.,.F.)\r\n B_SPLINE_SURFACE_WITH_KNOTS({knots}) GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE({weights}) REPRESENTATION_ITEM('') SURFACE() );"
        );
        good.replace(line, &entity)
    };
    let unit = complex("((1.,1.),(1.,1.),(1.,1.))");
    assert_eq!(read_step(&unit).unwrap(), [surface(0.0)]);
    refused("a weight of 2", || {
        read_step(&complex("((1.,1.),(2.,1.),(1.,1.))"))
    });
    refused("weights missing", || read_step(&complex("()")));
}

#[test]
fn iges_hollerith_strings_and_declared_delimiters_are_honoured() {
    let good = iges_text(&surface(0.0));
    let first_p = good.lines().position(|l| l.as_bytes()[72] == b'P').unwrap();
    // A record whose Hollerith string holds both delimiters, before the surface's.
    let mut lines: Vec<String> = good.lines().map(str::to_string).collect();
    let other = format!("{:<64}{:>8}{}{:>7}", "314,50.,50.,50.,6HA;B,C;;", 3, 'P', 0);
    lines.insert(first_p, other);
    assert_eq!(read_iges(&lines.join("\n")).unwrap(), [surface(0.0)]);
    // The same file with '/' and '#' declared as the delimiters in the global section.
    let swapped: Vec<String> = good
        .lines()
        .map(|l| {
            let (body, tail) = l.split_at(72);
            let body = match tail.as_bytes()[0] {
                b'G' if body.starts_with("1H,,1H;,") => {
                    format!("1H//1H#/{}", body[8..].replace(',', "/").replace(';', "#"))
                }
                b'G' => body.replace(',', "/").replace(';', "#"),
                b'P' => format!(
                    "{}{}",
                    body[..64].replace(',', "/").replace(';', "#"),
                    &body[64..]
                ),
                _ => body.to_string(),
            };
            format!("{body}{tail}")
        })
        .collect();
    assert_eq!(read_iges(&swapped.join("\n")).unwrap(), [surface(0.0)]);
    // The default delimiters swapped in the records but not declared: refused, not misread.
    let undeclared: Vec<String> = swapped
        .iter()
        .map(|l| {
            if l.as_bytes()[72] == b'G' && l.starts_with("1H//1H#/") {
                format!("1H,,1H;,{}", &l[8..])
            } else {
                l.clone()
            }
        })
        .collect();
    refused("undeclared delimiters", || {
        read_iges(&undeclared.join("\n"))
    });
    refused("a Hollerith string past its record", || {
        let mut lines: Vec<String> = good.lines().map(str::to_string).collect();
        lines.insert(
            first_p,
            format!("{:<64}{:>8}{}{:>7}", "314,50.,50.,50.,99HAB;", 3, 'P', 0),
        );
        read_iges(&lines.join("\n"))
    });
}
