//! IGES 5.3 export of a B-spline surface as entity 128 (rational B-spline surface, written
//! polynomial with unit weights), and a reader for the subset we write.
//!
//! Entity 128 lists control points with u varying fastest (the transpose of STEP's order).

use crate::error::PdeError;
use crate::spline_surface::BSplineSurface;
use bez_core::Vector3;

fn iges_err(what: impl Into<String>) -> PdeError {
    PdeError::Iges { what: what.into() }
}

fn real(x: f64) -> String {
    format!("{x:.16E}")
}

fn hollerith(s: &str) -> String {
    format!("{}H{s}", s.len())
}

/// Packs tokens (each ending with its delimiter) into lines of at most `width` columns.
fn pack(tokens: &[String], width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut cur = String::new();
    for t in tokens {
        if !cur.is_empty() && cur.len() + t.len() > width {
            lines.push(std::mem::take(&mut cur));
        }
        cur.push_str(t);
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

fn with_delims(items: &[String]) -> Vec<String> {
    let n = items.len();
    items
        .iter()
        .enumerate()
        .map(|(i, s)| format!("{s}{}", if i + 1 == n { ';' } else { ',' }))
        .collect()
}

/// Writes `surface` as an IGES 5.3 file with one entity 128 to `out`.
///
/// # Errors
/// The errors of [`BSplineSurface::validate`]; [`PdeError::Io`] when writing fails.
pub fn write_iges(
    surface: &BSplineSurface,
    name: &str,
    mut out: impl std::io::Write,
) -> Result<(), PdeError> {
    let text = iges_text(surface, name)?;
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(PdeError::io)
}

/// The IGES text of [`write_iges`].
fn iges_text(surface: &BSplineSurface, name: &str) -> Result<String, PdeError> {
    surface.validate()?;
    let name: String = name
        .chars()
        .filter(|c| c.is_ascii_graphic() || *c == ' ')
        .collect();
    let max_coord = surface
        .points
        .iter()
        .flat_map(|p| p.iter().map(|x| x.abs()))
        .fold(0.0, f64::max);
    let global: Vec<String> = vec![
        "1H,".to_string(),
        "1H;".to_string(),
        hollerith(&name),
        hollerith(&format!("{name}.igs")),
        hollerith("pde-bezier"),
        hollerith("pde-bezier"),
        "32".to_string(),
        "38".to_string(),
        "6".to_string(),
        "308".to_string(),
        "15".to_string(),
        hollerith(&name),
        "1.0".to_string(),
        "2".to_string(),
        "2HMM".to_string(),
        "1".to_string(),
        "1.0".to_string(),
        "15H20000101.000000".to_string(),
        "1.0E-7".to_string(),
        real(max_coord.max(1.0)),
        "0H".to_string(),
        "0H".to_string(),
        "11".to_string(),
        "0".to_string(),
        "15H20000101.000000".to_string(),
    ];
    let (cu, cv) = (surface.count_u(), surface.count_v());
    let mut params: Vec<String> = vec![
        "128".to_string(),
        (cu - 1).to_string(),
        (cv - 1).to_string(),
        surface.degree_u.to_string(),
        surface.degree_v.to_string(),
        "0".to_string(),
        "0".to_string(),
        "1".to_string(),
        "0".to_string(),
        "0".to_string(),
    ];
    params.extend(surface.knots_u.iter().map(|&k| real(k)));
    params.extend(surface.knots_v.iter().map(|&k| real(k)));
    params.extend(std::iter::repeat_n("1.0".to_string(), cu * cv));
    for j in 0..cv {
        for i in 0..cu {
            let p = surface.points[i * cv + j];
            params.extend([real(p.x()), real(p.y()), real(p.z())]);
        }
    }
    let first = |k: &[f64]| k.first().copied().unwrap_or(0.0);
    let last = |k: &[f64]| k.last().copied().unwrap_or(1.0);
    params.extend([
        real(first(&surface.knots_u)),
        real(last(&surface.knots_u)),
        real(first(&surface.knots_v)),
        real(last(&surface.knots_v)),
    ]);
    let start = ["pde-bezier B-spline surface".to_string()];
    let g_lines = pack(&with_delims(&global), 72);
    let p_lines = pack(&with_delims(&params), 64);
    let mut out = String::new();
    let mut push = |body: &str, letter: char, seq: usize| {
        out.push_str(&format!("{body:<72}{letter}{seq:>7}\n"));
    };
    for (i, l) in start.iter().enumerate() {
        push(l, 'S', i + 1);
    }
    for (i, l) in g_lines.iter().enumerate() {
        push(l, 'G', i + 1);
    }
    let field = |x: &str| format!("{x:>8}");
    let d1 = ["128", "1", "0", "0", "0", "0", "0", "0", "00000000"]
        .iter()
        .map(|x| field(x))
        .collect::<String>();
    let d2 = [
        "128".to_string(),
        "0".to_string(),
        "0".to_string(),
        p_lines.len().to_string(),
        "0".to_string(),
        String::new(),
        String::new(),
        "SURFACE".to_string(),
        "0".to_string(),
    ]
    .iter()
    .map(|x| field(x))
    .collect::<String>();
    push(&d1, 'D', 1);
    push(&d2, 'D', 2);
    for (i, l) in p_lines.iter().enumerate() {
        push(&format!("{l:<64}{:>8}", 1), 'P', i + 1);
    }
    let t = format!(
        "S{:>7}G{:>7}D{:>7}P{:>7}",
        start.len(),
        g_lines.len(),
        2,
        p_lines.len()
    );
    push(&t, 'T', 1);
    Ok(out)
}

fn parse_real(s: &str) -> Result<f64, PdeError> {
    match s.trim().replace(['D', 'd'], "E").parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(iges_err(format!("bad real {s:.40}"))),
    }
}

/// The parameter and record delimiters declared by the global section (its first two
/// parameters, each a 1-character Hollerith string such as `1H,` or left empty for the defaults
/// `,` and `;`).
fn delimiters(global: &str) -> Result<(u8, u8), PdeError> {
    let b = global.trim_start().as_bytes();
    let hollerith = |b: &[u8]| match b {
        [b'1', b'H' | b'h', c, ..] => Some(*c),
        _ => None,
    };
    let (param, rest) = match hollerith(b) {
        Some(c) => match b.get(3) {
            Some(&d) if d == c => (c, &b[4..]),
            // `1H;;` would end the section with the default parameter delimiter unknown.
            _ => {
                return Err(iges_err(
                    "the global section's parameter delimiter is not followed by itself",
                ));
            }
        },
        None => match b.first() {
            Some(b',') => (b',', &b[1..]),
            // An empty section (or `;` alone): both defaults.
            None | Some(b';') => return Ok((b',', b';')),
            Some(_) => {
                return Err(iges_err(
                    "the global section does not start with a delimiter",
                ));
            }
        },
    };
    let record = hollerith(rest).unwrap_or(b';');
    if param == record
        || param.is_ascii_alphanumeric()
        || record.is_ascii_alphanumeric()
        || param == b' '
        || record == b' '
    {
        return Err(iges_err("unusable delimiters in the global section"));
    }
    Ok((param, record))
}

/// The parameters of one parameter-section record, up to its record delimiter: split at the
/// parameter delimiter outside Hollerith strings (`nH` followed by n characters, which may hold
/// either delimiter), each trimmed. Anything after the record delimiter is a comment.
fn record_tokens(data: &[u8], param: u8, record: u8) -> Result<Vec<&str>, PdeError> {
    let mut tokens = Vec::new();
    let (mut i, mut start) = (0, 0);
    while i < data.len() {
        let c = data[i];
        if c == param || c == record {
            tokens.push(core::str::from_utf8(&data[start..i]).unwrap_or("").trim());
            if c == record {
                return Ok(tokens);
            }
            i += 1;
            start = i;
        } else if c.is_ascii_digit() && data[start..i].iter().all(u8::is_ascii_whitespace) {
            // A number or the count of a Hollerith string.
            let mut j = i;
            while j < data.len() && data[j].is_ascii_digit() {
                j += 1;
            }
            if matches!(data.get(j), Some(b'H' | b'h')) {
                let n: usize = core::str::from_utf8(&data[i..j])
                    .ok()
                    .and_then(|t| t.parse().ok())
                    .filter(|&n| n < data.len() - j)
                    .ok_or_else(|| iges_err("a Hollerith string runs past its record"))?;
                i = j + 1 + n;
            } else {
                i = j;
            }
        } else {
            i += 1;
        }
    }
    Err(iges_err("a parameter record has no record delimiter"))
}

/// Reads every entity 128 (rational B-spline surface with unit weights) of an IGES file, in
/// the order of the parameter section.
///
/// Fixed 80-column records (LF or CRLF). The delimiters are taken from the global section; the
/// parameter section's lines are grouped by their directory-entry pointer (columns 65–72), the
/// first 64 columns of each group joined and split into parameters outside Hollerith strings,
/// and every record of entity type 128 is read, whatever other entities the file holds (as
/// written by this crate or by Open CASCADE, with `D` or `E` exponents). Counts read from the
/// file are checked against the parameters present before anything is allocated; the reader
/// never panics and allocates in proportion to the file.
///
/// # Errors
/// [`PdeError::Iges`] for malformed lines or delimiters, no entity 128, non-unit weights or
/// counts that do not match the data; the errors of [`BSplineSurface::validate`].
pub fn read_iges(text: &str) -> Result<Vec<BSplineSurface>, PdeError> {
    let mut global = String::new();
    // (directory-entry pointer, joined parameter text) of each entity, in file order.
    let mut records: Vec<(&str, String)> = Vec::new();
    let mut saw_terminate = false;
    for (n, line) in text.lines().enumerate() {
        let bytes = line.as_bytes();
        if !line.is_ascii() || bytes.len() < 73 {
            return Err(iges_err(format!(
                "line {}: {} columns, expected 80",
                n + 1,
                line.len()
            )));
        }
        match bytes[72] {
            b'P' => {
                let pointer = line[64..72].trim();
                match records.last_mut() {
                    Some((p, data)) if *p == pointer => data.push_str(&line[..64]),
                    _ => records.push((pointer, line[..64].to_string())),
                }
            }
            b'G' => global.push_str(&line[..72]),
            b'T' => saw_terminate = true,
            b'S' | b'D' => {}
            other => {
                return Err(iges_err(format!(
                    "line {}: unknown section '{}'",
                    n + 1,
                    other as char
                )));
            }
        }
    }
    if !saw_terminate {
        return Err(iges_err("no terminate section"));
    }
    let (param, record) = delimiters(&global)?;
    let mut surfaces = Vec::new();
    for (_, data) in &records {
        let tokens = record_tokens(data.as_bytes(), param, record)?;
        if tokens.first() == Some(&"128") {
            surfaces.push(surface_of(&tokens)?);
        }
    }
    if surfaces.is_empty() {
        return Err(iges_err("no entity 128"));
    }
    Ok(surfaces)
}

/// One entity 128 from its parameter tokens (the first is "128").
fn surface_of(tokens: &[&str]) -> Result<BSplineSurface, PdeError> {
    let int = |i: usize| -> Result<usize, PdeError> {
        tokens
            .get(i)
            .and_then(|t| t.parse().ok())
            .ok_or_else(|| iges_err(format!("bad integer parameter {i}")))
    };
    let (k1, k2, m1, m2) = (int(1)?, int(2)?, int(3)?, int(4)?);
    for m in [m1, m2] {
        if !(1..=bez_core::MAX_DEGREE).contains(&m) {
            return Err(iges_err(format!(
                "degree {m} outside 1..={}",
                bez_core::MAX_DEGREE
            )));
        }
    }
    // Every count is bounded by the tokens present before it is used (no overflow, no
    // allocation the file does not back).
    let available = tokens.len();
    let count = |k: usize| k.checked_add(1).filter(|&c| c <= available);
    let (Some(cu), Some(cv)) = (count(k1), count(k2)) else {
        return Err(iges_err("control point counts exceed the parameter record"));
    };
    let grid = cu
        .checked_mul(cv)
        .filter(|&g| g.saturating_mul(4) <= available)
        .ok_or_else(|| iges_err("control grid exceeds the parameter record"))?;
    let mut pos: usize = 10;
    let mut take = |count: usize| -> Result<Vec<f64>, PdeError> {
        let end = pos
            .checked_add(count)
            .filter(|&e| e <= available)
            .ok_or_else(|| iges_err("parameter record too short"))?;
        let values = tokens[pos..end]
            .iter()
            .map(|t| parse_real(t))
            .collect::<Result<Vec<_>, _>>()?;
        pos = end;
        Ok(values)
    };
    let knots_u = take(cu + m1 + 1)?;
    let knots_v = take(cv + m2 + 1)?;
    let weights = take(grid)?;
    if weights.iter().any(|&w| w != 1.0) {
        return Err(iges_err(
            "rational surfaces (weights other than 1) are not supported",
        ));
    }
    let coords = take(3 * grid)?;
    let mut points = vec![Vector3::zeros(); grid];
    for j in 0..cv {
        for i in 0..cu {
            let k = 3 * (j * cu + i);
            points[i * cv + j] = Vector3::new(coords[k], coords[k + 1], coords[k + 2]);
        }
    }
    let surface = BSplineSurface {
        degree_u: m1,
        degree_v: m2,
        knots_u,
        knots_v,
        points,
    };
    surface.validate()?;
    Ok(surface)
}
