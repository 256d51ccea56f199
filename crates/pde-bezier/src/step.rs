//! STEP (ISO 10303-21, AP214) export of a B-spline surface, and a reader for the subset we
//! write (enough to round-trip and to check a file).
//!
//! Pitfalls handled (see the paper document): the product structure and a units/uncertainty
//! context around a `GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION`, control points listed
//! u-outer and v-inner, reals with a decimal point and an upper-case exponent, no non-finite
//! values.

use crate::error::PdeError;
use crate::spline_surface::BSplineSurface;
use bez_core::Vector3;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// A Part 21 real: 17 significant digits, always a decimal point, upper-case exponent.
fn real(x: f64) -> String {
    // `{:.16E}` prints "1.2345678901234567E-7": mantissa with a point, exponent upper case.
    format!("{x:.16E}")
}

/// Distinct knots and their multiplicities.
fn knot_multiplicities(knots: &[f64]) -> (Vec<f64>, Vec<usize>) {
    let mut values: Vec<f64> = Vec::new();
    let mut mults: Vec<usize> = Vec::new();
    for &k in knots {
        match values.last() {
            Some(&last) if last == k => {
                if let Some(m) = mults.last_mut() {
                    *m += 1;
                }
            }
            _ => {
                values.push(k);
                mults.push(1);
            }
        }
    }
    (values, mults)
}

fn list<T>(items: &[T], f: impl Fn(&T) -> String) -> String {
    let inner: Vec<String> = items.iter().map(f).collect();
    format!("({})", inner.join(","))
}

/// Writes `surface` as an AP214 STEP file (one `B_SPLINE_SURFACE_WITH_KNOTS` in a geometric
/// set) to `out` (a file, a `Vec<u8>`, …). `name` is the product name (quotes are removed).
///
/// # Errors
/// The errors of [`BSplineSurface::validate`] (bad shape, non-finite values);
/// [`PdeError::Io`] when writing fails.
pub fn write_step(
    surface: &BSplineSurface,
    name: &str,
    mut out: impl std::io::Write,
) -> Result<(), PdeError> {
    let text = step_text(surface, name)?;
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(PdeError::io)
}

/// The STEP text of [`write_step`].
fn step_text(surface: &BSplineSurface, name: &str) -> Result<String, PdeError> {
    surface.validate()?;
    let name: String = name.chars().filter(|c| *c != '\'' && *c != '\\').collect();
    let mut s = String::new();
    let _ = writeln!(s, "ISO-10303-21;");
    let _ = writeln!(s, "HEADER;");
    let _ = writeln!(s, "FILE_DESCRIPTION(('{name}'),'2;1');");
    let _ = writeln!(
        s,
        "FILE_NAME('{name}.stp','2000-01-01T00:00:00',(''),(''),'pde-bezier','pde-bezier','');"
    );
    let _ = writeln!(
        s,
        "FILE_SCHEMA(('AUTOMOTIVE_DESIGN {{ 1 0 10303 214 1 1 1 1 }}'));"
    );
    let _ = writeln!(s, "ENDSEC;");
    let _ = writeln!(s, "DATA;");
    let fixed = [
        "APPLICATION_CONTEXT('automotive design')".to_string(),
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#1)"
            .to_string(),
        "PRODUCT_CONTEXT('',#1,'mechanical')".to_string(),
        format!("PRODUCT('{name}','{name}','',(#3))"),
        "PRODUCT_DEFINITION_FORMATION('','',#4)".to_string(),
        "PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design')".to_string(),
        "PRODUCT_DEFINITION('design','',#5,#6)".to_string(),
        "PRODUCT_DEFINITION_SHAPE('','',#7)".to_string(),
        "(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))".to_string(),
        "(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))".to_string(),
        "(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())".to_string(),
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#9,'distance_accuracy_value','confusion accuracy')".to_string(),
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#12))GLOBAL_UNIT_ASSIGNED_CONTEXT((#9,#10,#11))REPRESENTATION_CONTEXT('',''))".to_string(),
        "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#4))".to_string(),
    ];
    for (i, e) in fixed.iter().enumerate() {
        let _ = writeln!(s, "#{}={e};", i + 1);
    }
    let first_point = fixed.len() + 1;
    for (k, p) in surface.points.iter().enumerate() {
        let _ = writeln!(
            s,
            "#{}=CARTESIAN_POINT('',({},{},{}));",
            first_point + k,
            real(p.x()),
            real(p.y()),
            real(p.z())
        );
    }
    let (cu, cv) = (surface.count_u(), surface.count_v());
    let rows: Vec<String> = (0..cu)
        .map(|i| {
            let ids: Vec<usize> = (0..cv).map(|j| first_point + i * cv + j).collect();
            list(&ids, |id| format!("#{id}"))
        })
        .collect();
    let (ku, mu) = knot_multiplicities(&surface.knots_u);
    let (kv, mv) = knot_multiplicities(&surface.knots_v);
    let id = first_point + surface.points.len();
    let _ = writeln!(
        s,
        "#{id}=B_SPLINE_SURFACE_WITH_KNOTS('',{},{},({}),.UNSPECIFIED.,.F.,.F.,.F.,{},{},{},{},.UNSPECIFIED.);",
        surface.degree_u,
        surface.degree_v,
        rows.join(","),
        list(&mu, ToString::to_string),
        list(&mv, ToString::to_string),
        list(&ku, |x| real(*x)),
        list(&kv, |x| real(*x)),
    );
    let _ = writeln!(s, "#{}=GEOMETRIC_SET('',(#{id}));", id + 1);
    let _ = writeln!(
        s,
        "#{}=GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION('',(#{}),#13);",
        id + 2,
        id + 1
    );
    let _ = writeln!(
        s,
        "#{}=SHAPE_DEFINITION_REPRESENTATION(#8,#{});",
        id + 3,
        id + 2
    );
    let _ = writeln!(s, "ENDSEC;");
    let _ = writeln!(s, "END-ISO-10303-21;");
    Ok(s)
}

/// A parsed Part 21 parameter.
#[derive(Debug, Clone, PartialEq)]
enum Param {
    List(Vec<Param>),
    Ref(usize),
    Num(f64),
    Text(String),
    Enum(String),
    Unset,
}

fn step_err(what: impl Into<String>) -> PdeError {
    PdeError::Step { what: what.into() }
}

/// Deepest list nesting the reader accepts (a surface needs 3; deeper input is refused instead
/// of recursing without bound).
const MAX_NESTING: usize = 32;

/// The statements of a Part 21 file (each up to, not including, its ';'), with comments
/// `/* … */` removed and strings (with their `''` escapes) kept intact, so a ';' inside a
/// string does not end a statement. One pass, no recursion.
fn statements(text: &str) -> Result<Vec<String>, PdeError> {
    let b = text.as_bytes();
    let (mut out, mut cur) = (Vec::new(), Vec::new());
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\'' => {
                // A string: copy through its closing quote ('' is an escaped quote).
                cur.push(b'\'');
                i += 1;
                loop {
                    let Some(&c) = b.get(i) else {
                        return Err(step_err("unterminated string"));
                    };
                    cur.push(c);
                    i += 1;
                    if c == b'\'' {
                        if b.get(i) == Some(&b'\'') {
                            cur.push(b'\'');
                            i += 1;
                        } else {
                            break;
                        }
                    }
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let end = text[i + 2..]
                    .find("*/")
                    .ok_or_else(|| step_err("unterminated comment"))?;
                i += end + 4;
                cur.push(b' ');
            }
            b';' => {
                out.push(String::from_utf8_lossy(&cur).trim().to_string());
                cur.clear();
                i += 1;
            }
            c => {
                cur.push(c);
                i += 1;
            }
        }
    }
    if !String::from_utf8_lossy(&cur).trim().is_empty() {
        return Err(step_err("text after the last ';'"));
    }
    Ok(out)
}

struct Parser<'a> {
    s: &'a [u8],
    pos: usize,
}

impl Parser<'_> {
    fn skip_ws(&mut self) {
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }

    fn param(&mut self, depth: usize) -> Result<Param, PdeError> {
        if depth > MAX_NESTING {
            return Err(step_err(format!("lists nested deeper than {MAX_NESTING}")));
        }
        self.skip_ws();
        let Some(&c) = self.s.get(self.pos) else {
            return Err(step_err("unexpected end of parameters"));
        };
        match c {
            b'(' => {
                self.pos += 1;
                let mut items = Vec::new();
                self.skip_ws();
                if self.s.get(self.pos) == Some(&b')') {
                    self.pos += 1;
                    return Ok(Param::List(items));
                }
                loop {
                    items.push(self.param(depth + 1)?);
                    self.skip_ws();
                    match self.s.get(self.pos) {
                        Some(b',') => self.pos += 1,
                        Some(b')') => {
                            self.pos += 1;
                            return Ok(Param::List(items));
                        }
                        _ => return Err(step_err("expected ',' or ')' in a list")),
                    }
                }
            }
            b'#' => {
                self.pos += 1;
                let start = self.pos;
                while self.pos < self.s.len() && self.s[self.pos].is_ascii_digit() {
                    self.pos += 1;
                }
                let text = core::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
                text.parse()
                    .map(Param::Ref)
                    .map_err(|_| step_err(format!("bad reference #{text}")))
            }
            b'\'' => {
                self.pos += 1;
                let mut text = Vec::new();
                loop {
                    let Some(&c) = self.s.get(self.pos) else {
                        return Err(step_err("unterminated string"));
                    };
                    self.pos += 1;
                    if c == b'\'' {
                        if self.s.get(self.pos) == Some(&b'\'') {
                            self.pos += 1;
                        } else {
                            break;
                        }
                    }
                    text.push(c);
                }
                Ok(Param::Text(String::from_utf8_lossy(&text).into_owned()))
            }
            b'.' if self
                .s
                .get(self.pos + 1)
                .is_some_and(u8::is_ascii_alphabetic) =>
            {
                self.pos += 1;
                let start = self.pos;
                while self.pos < self.s.len() && self.s[self.pos] != b'.' {
                    self.pos += 1;
                }
                let text = String::from_utf8_lossy(&self.s[start..self.pos]).into_owned();
                self.pos += 1;
                Ok(Param::Enum(text))
            }
            b'$' | b'*' => {
                self.pos += 1;
                Ok(Param::Unset)
            }
            c if c.is_ascii_alphabetic() => {
                // A typed parameter such as LENGTH_MEASURE(1.E-07).
                while self.pos < self.s.len()
                    && (self.s[self.pos].is_ascii_alphanumeric() || self.s[self.pos] == b'_')
                {
                    self.pos += 1;
                }
                self.skip_ws();
                if self.s.get(self.pos) != Some(&b'(') {
                    return Err(step_err("a typed parameter needs '('"));
                }
                self.param(depth + 1)
            }
            _ => {
                let start = self.pos;
                while self.pos < self.s.len()
                    && (self.s[self.pos].is_ascii_alphanumeric()
                        || matches!(self.s[self.pos], b'.' | b'-' | b'+' | b'_'))
                {
                    self.pos += 1;
                }
                let text = core::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
                if text.is_empty() {
                    return Err(step_err(format!("unexpected character '{}'", c as char)));
                }
                if !text.contains('.') && text.contains(['E', 'e']) {
                    return Err(step_err(format!("real without a decimal point: {text}")));
                }
                match text.parse::<f64>() {
                    Ok(x) if x.is_finite() => Ok(Param::Num(x)),
                    _ => Err(step_err(format!("bad number {text}"))),
                }
            }
        }
    }
}

/// The data section's simple entity instances by id (complex instances `#n=(A(…)B(…))` are
/// checked for syntax and kept by name "(complex)", except rational B-spline surfaces, see
/// [`rational_surface`]).
type Entities = BTreeMap<usize, (String, Vec<Param>)>;

fn data_entities(text: &str) -> Result<Entities, PdeError> {
    let stmts = statements(text)?;
    let mut it = stmts.iter().map(String::as_str);
    if it.next() != Some("ISO-10303-21") {
        return Err(step_err("missing ISO-10303-21 header"));
    }
    // Header entities, then DATA (or DATA('name',…) in later editions).
    it.by_ref()
        .find(|s| *s == "DATA" || s.starts_with("DATA(") || s.starts_with("DATA ("))
        .ok_or_else(|| step_err("no DATA section"))?;
    let mut entities = Entities::new();
    let mut ended = false;
    for stmt in it.by_ref() {
        if stmt == "ENDSEC" {
            ended = true;
            break;
        }
        let (id, body) = stmt
            .split_once('=')
            .ok_or_else(|| step_err(format!("statement without '=': {stmt:.60}")))?;
        let id: usize = id
            .trim()
            .strip_prefix('#')
            .and_then(|x| x.parse().ok())
            .ok_or_else(|| step_err(format!("bad entity id {id:.30}")))?;
        let body = body.trim();
        let entry = if body.starts_with('(') {
            // A complex instance: typed sub-instances separated by spaces. A rational B-spline
            // surface is kept (as the simple form plus its weights, see `rational_surface`);
            // any other is checked for syntax only.
            let mut p = Parser {
                s: &body.as_bytes()[1..],
                pos: 0,
            };
            let mut parts: Vec<(String, Vec<Param>)> = Vec::new();
            loop {
                p.skip_ws();
                match p.s.get(p.pos) {
                    Some(b')') => break,
                    Some(c) if c.is_ascii_alphabetic() => {
                        let start = p.pos;
                        while p.pos < p.s.len()
                            && (p.s[p.pos].is_ascii_alphanumeric() || p.s[p.pos] == b'_')
                        {
                            p.pos += 1;
                        }
                        let name = String::from_utf8_lossy(&p.s[start..p.pos]).into_owned();
                        p.skip_ws();
                        if p.s.get(p.pos) != Some(&b'(') {
                            return Err(step_err(format!("#{id}: bad complex instance")));
                        }
                        let Param::List(params) = p.param(1)? else {
                            return Err(step_err(format!("#{id}: bad complex instance")));
                        };
                        parts.push((name, params));
                    }
                    _ => return Err(step_err(format!("#{id}: bad complex instance"))),
                }
            }
            rational_surface(&parts).unwrap_or_else(|| ("(complex)".to_string(), Vec::new()))
        } else {
            let open = body
                .find('(')
                .ok_or_else(|| step_err(format!("#{id}: no parameters")))?;
            let name = body[..open].trim().to_string();
            let mut p = Parser {
                s: &body.as_bytes()[open..],
                pos: 0,
            };
            let Param::List(params) = p.param(0)? else {
                return Err(step_err(format!("#{id}: parameters are not a list")));
            };
            p.skip_ws();
            if p.pos != p.s.len() {
                return Err(step_err(format!("#{id}: text after the parameters")));
            }
            (name, params)
        };
        if entities.insert(id, entry).is_some() {
            return Err(step_err(format!("duplicate entity #{id}")));
        }
    }
    if !ended {
        return Err(step_err("the DATA section has no ENDSEC"));
    }
    if !it.any(|s| s == "END-ISO-10303-21") {
        return Err(step_err("no END-ISO-10303-21"));
    }
    Ok(entities)
}

/// A complex instance holding `B_SPLINE_SURFACE`, `B_SPLINE_SURFACE_WITH_KNOTS` and
/// `RATIONAL_B_SPLINE_SURFACE` as the 13 parameters of the simple `B_SPLINE_SURFACE_WITH_KNOTS`
/// (name first) followed by the weights, under the name `RATIONAL_B_SPLINE_SURFACE`.
fn rational_surface(parts: &[(String, Vec<Param>)]) -> Option<(String, Vec<Param>)> {
    let find = |name: &str| parts.iter().find(|(n, _)| n == name).map(|(_, p)| p);
    let (surface, knots, weights) = (
        find("B_SPLINE_SURFACE")?,
        find("B_SPLINE_SURFACE_WITH_KNOTS")?,
        find("RATIONAL_B_SPLINE_SURFACE")?,
    );
    let mut params = vec![Param::Text(String::new())];
    params.extend(surface.iter().cloned());
    params.extend(knots.iter().cloned());
    params.extend(weights.iter().cloned());
    Some(("RATIONAL_B_SPLINE_SURFACE".to_string(), params))
}

/// Reads every `B_SPLINE_SURFACE_WITH_KNOTS` of a STEP (ISO 10303-21) file, in entity-id order
/// (explicit knots; other entities are checked for syntax only). A rational surface (the
/// complex instance with `RATIONAL_B_SPLINE_SURFACE`) whose weights are all exactly 1 is read as
/// the polynomial surface it equals; other weights are refused.
///
/// The reader takes any well-formed Part 21 text: LF or CRLF line ends, whitespace anywhere
/// between tokens, comments, strings with `''` escapes, typed parameters, `$` and `*`, complex
/// instances. It never panics, nests at most 32 lists deep and allocates in proportion to the
/// file: every count read from the file (multiplicities, degrees) is checked against the data
/// actually present before anything is reserved.
///
/// # Errors
/// [`PdeError::Step`] for a syntax error, a missing section or reference, no surface, a
/// rational surface with weights other than 1, or a malformed surface (with its entity id);
/// the errors of [`BSplineSurface::validate`].
pub fn read_step(text: &str) -> Result<Vec<BSplineSurface>, PdeError> {
    let entities = data_entities(text)?;
    let surfaces: Vec<BSplineSurface> = entities
        .iter()
        .filter_map(|(&id, (name, params))| match name.as_str() {
            "B_SPLINE_SURFACE_WITH_KNOTS" => Some(surface_of(&entities, id, params)),
            "RATIONAL_B_SPLINE_SURFACE" => Some(
                unit_weights(id, params)
                    .and_then(|()| surface_of(&entities, id, params.get(..13).unwrap_or(&[]))),
            ),
            _ => None,
        })
        .collect::<Result<_, _>>()?;
    if surfaces.is_empty() {
        return Err(step_err("no B_SPLINE_SURFACE_WITH_KNOTS"));
    }
    Ok(surfaces)
}

/// Accepts a rational surface whose weights (the 14th parameter, rows of reals shaped like the
/// control grid) are all exactly 1: it is the polynomial surface with the same control points.
/// Other weights, or a weight grid of another shape, are refused.
fn unit_weights(id: usize, params: &[Param]) -> Result<(), PdeError> {
    // The weight grid must have the shape of the control grid (the 4th parameter).
    let shape = |p: Option<&Param>| match p {
        Some(Param::List(rows)) => Some(
            rows.iter()
                .map(|r| match r {
                    Param::List(items) => items.len(),
                    _ => usize::MAX,
                })
                .collect::<Vec<_>>(),
        ),
        _ => None,
    };
    let unit = match params.get(13) {
        Some(Param::List(rows))
            if params.len() == 14 && shape(params.get(3)) == shape(params.get(13)) =>
        {
            rows.iter().all(|row| match row {
                Param::List(w) => w.iter().all(|w| *w == Param::Num(1.0)),
                _ => false,
            })
        }
        _ => {
            return Err(step_err(format!(
                "#{id}: malformed RATIONAL_B_SPLINE_SURFACE"
            )));
        }
    };
    if unit {
        Ok(())
    } else {
        Err(step_err(format!(
            "#{id}: rational surfaces (weights other than 1) are not supported"
        )))
    }
}

fn surface_of(
    entities: &Entities,
    id: usize,
    params: &[Param],
) -> Result<BSplineSurface, PdeError> {
    let bad = |what: &str| step_err(format!("#{id}: {what}"));
    if params.len() != 13 {
        return Err(bad("B_SPLINE_SURFACE_WITH_KNOTS needs 13 parameters"));
    }
    let degree = |p: &Param| match p {
        Param::Num(x) if *x >= 1.0 && *x <= bez_core::MAX_DEGREE as f64 && x.fract() == 0.0 => {
            Ok(*x as usize)
        }
        _ => Err(bad(&format!(
            "a degree must be an integer in 1..={}",
            bez_core::MAX_DEGREE
        ))),
    };
    let nums = |p: &Param| -> Result<Vec<f64>, PdeError> {
        match p {
            Param::List(items) => items
                .iter()
                .map(|i| match i {
                    Param::Num(x) => Ok(*x),
                    _ => Err(bad("expected a list of numbers")),
                })
                .collect(),
            _ => Err(bad("expected a list of numbers")),
        }
    };
    let point = |pid: usize| -> Result<Vector3, PdeError> {
        match entities.get(&pid) {
            Some((n, p)) if n == "CARTESIAN_POINT" && p.len() == 2 => match nums(&p[1])?[..] {
                [x, y, z] => Ok(Vector3::new(x, y, z)),
                _ => Err(bad(&format!("#{pid} is not a 3D point"))),
            },
            _ => Err(bad(&format!("#{pid} is not a CARTESIAN_POINT"))),
        }
    };
    let degree_u = degree(&params[1])?;
    let degree_v = degree(&params[2])?;
    let Param::List(rows) = &params[3] else {
        return Err(bad("the control grid is not a list"));
    };
    let mut points = Vec::new();
    let mut width = None;
    for row in rows {
        let Param::List(ids) = row else {
            return Err(bad("a control grid row is not a list"));
        };
        if *width.get_or_insert(ids.len()) != ids.len() {
            return Err(bad("ragged control grid"));
        }
        for pid in ids {
            let Param::Ref(pid) = pid else {
                return Err(bad("a control point is not a reference"));
            };
            points.push(point(*pid)?);
        }
    }
    // Knot vectors from (multiplicity, value) pairs. The multiplicities are checked (integers
    // in 1..=degree+1 summing to count + degree + 1) before the vector is built, so a file
    // cannot ask for more memory than the surface it describes.
    let expand = |mults: &Param, knots: &Param, degree: usize, count: usize| {
        let m = nums(mults)?;
        let k = nums(knots)?;
        if m.len() != k.len() {
            return Err(bad("multiplicities and knots differ in number"));
        }
        let mut total = 0usize;
        for &mult in &m {
            if !(mult >= 1.0 && mult <= (degree + 1) as f64 && mult.fract() == 0.0) {
                return Err(bad(&format!(
                    "knot multiplicity {mult} outside 1..={}",
                    degree + 1
                )));
            }
            total += mult as usize;
        }
        if total != count + degree + 1 {
            return Err(bad("knot count does not match the control grid and degree"));
        }
        let mut out = Vec::with_capacity(total);
        for (mult, knot) in m.iter().zip(k) {
            out.extend(core::iter::repeat_n(knot, *mult as usize));
        }
        Ok(out)
    };
    let width = width.unwrap_or(0);
    let surface = BSplineSurface {
        degree_u,
        degree_v,
        knots_u: expand(&params[8], &params[10], degree_u, rows.len())?,
        knots_v: expand(&params[9], &params[11], degree_v, width)?,
        points,
    };
    surface.validate()?;
    Ok(surface)
}
