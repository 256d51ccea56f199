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
use std::collections::HashMap;
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
/// set). `name` is the product name (quotes are removed).
///
/// # Errors
/// The errors of [`BSplineSurface::validate`] (bad shape, non-finite values).
pub fn write_step(surface: &BSplineSurface, name: &str) -> Result<String, PdeError> {
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

    fn param(&mut self) -> Result<Param, PdeError> {
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
                    items.push(self.param()?);
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
                let text = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
                text.parse()
                    .map(Param::Ref)
                    .map_err(|_| step_err(format!("bad reference #{text}")))
            }
            b'\'' => {
                self.pos += 1;
                let start = self.pos;
                while self.pos < self.s.len() && self.s[self.pos] != b'\'' {
                    self.pos += 1;
                }
                let text = String::from_utf8_lossy(&self.s[start..self.pos]).into_owned();
                self.pos += 1;
                Ok(Param::Text(text))
            }
            b'.' => {
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
                self.param()
            }
            _ => {
                let start = self.pos;
                while self.pos < self.s.len()
                    && (self.s[self.pos].is_ascii_alphanumeric()
                        || matches!(self.s[self.pos], b'.' | b'-' | b'+' | b'_'))
                {
                    self.pos += 1;
                }
                let text = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
                if text.is_empty() {
                    return Err(step_err(format!("unexpected character '{}'", c as char)));
                }
                if !text.contains('.') && text.contains(['E', 'e']) {
                    return Err(step_err(format!("real without a decimal point: {text}")));
                }
                text.parse()
                    .map(Param::Num)
                    .map_err(|_| step_err(format!("bad number {text}")))
            }
        }
    }
}

/// Reads the first `B_SPLINE_SURFACE_WITH_KNOTS` of a STEP file written by [`write_step`]
/// (non-rational, explicit knots; other entities are only checked for syntax).
///
/// # Errors
/// [`PdeError::Step`] for a syntax error, a missing entity or reference, or a malformed surface.
pub fn read_step(text: &str) -> Result<BSplineSurface, PdeError> {
    let start = text
        .find("DATA;")
        .ok_or_else(|| step_err("no DATA section"))?;
    let end = text
        .find("ENDSEC;\nEND-ISO-10303-21;")
        .ok_or_else(|| step_err("no end"))?;
    if !text.starts_with("ISO-10303-21;") {
        return Err(step_err("missing ISO-10303-21 header"));
    }
    if end < start + 5 {
        return Err(step_err("the DATA section ends before it starts"));
    }
    let mut entities: HashMap<usize, (String, Vec<Param>)> = HashMap::new();
    for stmt in text[start + 5..end].split(';') {
        let stmt = stmt.trim();
        if stmt.is_empty() {
            continue;
        }
        let (id, body) = stmt
            .split_once('=')
            .ok_or_else(|| step_err(format!("statement without '=': {stmt}")))?;
        let id: usize = id
            .trim()
            .strip_prefix('#')
            .and_then(|x| x.parse().ok())
            .ok_or_else(|| step_err(format!("bad entity id {id}")))?;
        let body = body.trim();
        if body.starts_with('(') {
            // A complex entity: check its syntax only.
            let mut p = Parser {
                s: body.as_bytes(),
                pos: 0,
            };
            let _ = p.param();
            entities.insert(id, ("(complex)".to_string(), Vec::new()));
            continue;
        }
        let open = body
            .find('(')
            .ok_or_else(|| step_err(format!("#{id}: no parameters")))?;
        let name = body[..open].to_string();
        let mut p = Parser {
            s: &body.as_bytes()[open..],
            pos: 0,
        };
        let Param::List(params) = p.param()? else {
            return Err(step_err(format!("#{id}: parameters are not a list")));
        };
        if entities.insert(id, (name, params)).is_some() {
            return Err(step_err(format!("duplicate entity #{id}")));
        }
    }
    let (_, params) = entities
        .values()
        .find(|(n, _)| n == "B_SPLINE_SURFACE_WITH_KNOTS")
        .ok_or_else(|| step_err("no B_SPLINE_SURFACE_WITH_KNOTS"))?;
    let bad = || step_err("malformed B_SPLINE_SURFACE_WITH_KNOTS");
    if params.len() != 13 {
        return Err(bad());
    }
    let int = |p: &Param| match p {
        Param::Num(x) if *x >= 0.0 && x.fract() == 0.0 => Ok(*x as usize),
        _ => Err(bad()),
    };
    let nums = |p: &Param| -> Result<Vec<f64>, PdeError> {
        match p {
            Param::List(items) => items
                .iter()
                .map(|i| match i {
                    Param::Num(x) => Ok(*x),
                    _ => Err(bad()),
                })
                .collect(),
            _ => Err(bad()),
        }
    };
    let point = |id: usize| -> Result<Vector3, PdeError> {
        match entities.get(&id) {
            Some((n, p)) if n == "CARTESIAN_POINT" && p.len() == 2 => {
                let c = nums(&p[1])?;
                if c.len() == 3 {
                    Ok(Vector3::new(c[0], c[1], c[2]))
                } else {
                    Err(bad())
                }
            }
            _ => Err(step_err(format!("#{id} is not a 3D CARTESIAN_POINT"))),
        }
    };
    let degree_u = int(&params[1])?;
    let degree_v = int(&params[2])?;
    let Param::List(rows) = &params[3] else {
        return Err(bad());
    };
    let mut points = Vec::new();
    let mut width = None;
    for row in rows {
        let Param::List(ids) = row else {
            return Err(bad());
        };
        if *width.get_or_insert(ids.len()) != ids.len() {
            return Err(step_err("ragged control grid"));
        }
        for id in ids {
            let Param::Ref(id) = id else {
                return Err(bad());
            };
            points.push(point(*id)?);
        }
    }
    let expand = |mults: &Param, knots: &Param| -> Result<Vec<f64>, PdeError> {
        let m = nums(mults)?;
        let k = nums(knots)?;
        if m.len() != k.len() {
            return Err(bad());
        }
        let mut out = Vec::new();
        for (mult, knot) in m.iter().zip(k) {
            out.extend(std::iter::repeat_n(knot, *mult as usize));
        }
        Ok(out)
    };
    let surface = BSplineSurface {
        degree_u,
        degree_v,
        knots_u: expand(&params[8], &params[10])?,
        knots_v: expand(&params[9], &params[11])?,
        points,
    };
    if surface.count_u() != rows.len() || Some(surface.count_v()) != width {
        return Err(step_err("knot counts do not match the control grid"));
    }
    surface.validate()?;
    Ok(surface)
}
