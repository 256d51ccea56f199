//! `cargo xtask cad-check`: validates pde-bezier's STEP and IGES export against Open CASCADE.
//!
//! Installs PyPI's `cadquery-ocp-novtk` into a virtual environment under `target/cad-venv`
//! (once), writes STEP and IGES files of a few solutions with non-square, non-symmetric control
//! nets into `target/cad-check/`, and has Open CASCADE read each file (checking the load status
//! before the transfer) and evaluate the surface at sample parameters; every point must agree
//! with ours to 1e-12 (relative to the coordinate size).
//!
//! Open CASCADE then writes each shape it read back out with its own writers
//! (`STEPControl_Writer`, `IGESControl_Writer` in its default face mode, which writes the surface
//! as entity 128 under a trimmed surface) into `target/cad-check/occ/`, and those files are read
//! with `read_step` / `read_iges`: every surface returned must agree with ours at 41 x 41
//! parameters after both knot ranges are mapped onto [0, 1] (the comparison allows the eight
//! swaps and reversals of u and v, and reports which one matched). Open CASCADE prints 12
//! significant digits in STEP and 9 decimals in IGES, so the bound is 1e-11 for STEP and 1e-8 for
//! IGES, relative to max(1, largest control coordinate).

use std::fmt::Write as _;
use std::fs;
use std::process::Command;

use pde_bezier::{
    BSplineSurface, Method, cases, read_iges, read_step, solve, write_iges, write_step,
};

use crate::venv::python_env;
use crate::{DynError, project_root};

const SCRIPT: &str = r#"
import json, sys
from OCP.STEPControl import STEPControl_Reader
from OCP.IGESControl import IGESControl_Reader
from OCP.IFSelect import IFSelect_RetDone
from OCP.TopExp import TopExp_Explorer
from OCP.TopAbs import TopAbs_FACE
from OCP.TopoDS import TopoDS
from OCP.BRep import BRep_Tool
from OCP.STEPControl import STEPControl_Writer, STEPControl_AsIs
from OCP.IGESControl import IGESControl_Writer
import OCP, os

spec = json.load(open(sys.argv[1]))
worst = 0.0
for item in spec:
    reader = STEPControl_Reader() if item["kind"] == "step" else IGESControl_Reader()
    status = reader.ReadFile(item["path"])
    if status != IFSelect_RetDone:
        print("load failed:", item["path"], status)
        sys.exit(1)
    reader.TransferRoots()
    shape = reader.OneShape()
    exp = TopExp_Explorer(shape, TopAbs_FACE)
    if not exp.More():
        print("no face in", item["path"])
        sys.exit(1)
    surf = BRep_Tool.Surface_s(TopoDS.Face(exp.Current()))
    err = 0.0
    for u, v, x, y, z in item["samples"]:
        p = surf.Value(u, v)
        scale = max(1.0, abs(x), abs(y), abs(z))
        err = max(err, abs(p.X() - x) / scale, abs(p.Y() - y) / scale, abs(p.Z() - z) / scale)
    print(f'{item["path"]}: max deviation {err:.3e}')
    worst = max(worst, err)
    base = os.path.join(item["occ_dir"], os.path.basename(item["path"]).replace(".", "-"))
    w = STEPControl_Writer()
    w.Transfer(shape, STEPControl_AsIs)
    if w.Write(base + ".stp") != IFSelect_RetDone:
        print("STEP write failed:", base)
        sys.exit(1)
    w = IGESControl_Writer("MM", 0)
    w.AddShape(shape)
    w.ComputeModel()
    if not w.Write(base + ".igs"):
        print("IGES write failed:", base)
        sys.exit(1)
print("OCP", getattr(OCP, "__version__", "?"))
print(f"worst deviation {worst:.3e}")
sys.exit(0 if worst <= 1e-12 else 1)
"#;

pub(crate) fn run() -> Result<(), DynError> {
    let root = project_root();
    let python = python_env("cad-venv", "OCP", &["cadquery-ocp-novtk"])?;
    let dir = root.join("target").join("cad-check");
    let occ_dir = dir.join("occ");
    fs::create_dir_all(&occ_dir)?;
    let mut enneper = cases::enneper(3, 3, 2)?;
    enneper.disc.degree_v = 4;
    enneper.disc.smoothness_v = 1;
    let all = [
        ("enneper", enneper),
        ("vase", cases::vase(2, 4)?),
        ("blend", cases::cylinder_plane(2, 8)?),
        ("fig1", cases::circle_sphere_blend(1.0, 1.0)?),
    ];
    let mut spec = String::from("[");
    let mut ours = Vec::new();
    for (name, case) in &all {
        let sol = solve(&case.problem, &case.disc, Method::BernsteinLeastSquares)?;
        let mut samples = String::from("[");
        for i in 0..=8 {
            for j in 0..=8 {
                let (u, v) = (
                    i as f64 / 8.0 * 0.999 + 0.0005,
                    j as f64 / 8.0 * 0.999 + 0.0005,
                );
                let p = sol.spline.eval(u, v)?;
                if !(i == 0 && j == 0) {
                    samples.push(',');
                }
                let _ = write!(samples, "[{u:e},{v:e},{:e},{:e},{:e}]", p.x(), p.y(), p.z());
            }
        }
        samples.push(']');
        ours.push((*name, sol.spline.clone()));
        for kind in ["step", "iges"] {
            let path = dir.join(format!(
                "{name}.{}",
                if kind == "step" { "stp" } else { "igs" }
            ));
            let file = std::io::BufWriter::new(fs::File::create(&path)?);
            if kind == "step" {
                write_step(&sol.spline, name, file)?;
            } else {
                write_iges(&sol.spline, name, file)?;
            }
            if spec.len() > 1 {
                spec.push(',');
            }
            let _ = write!(
                spec,
                "{{\"kind\":\"{kind}\",\"path\":{:?},\"occ_dir\":{:?},\"samples\":{samples}}}",
                path.display().to_string(),
                occ_dir.display().to_string()
            );
        }
    }
    spec.push(']');
    let spec_path = dir.join("spec.json");
    fs::write(&spec_path, spec)?;
    let script = dir.join("check.py");
    fs::write(&script, SCRIPT)?;
    let ok = Command::new(&python)
        .arg(&script)
        .arg(&spec_path)
        .status()?;
    if !ok.success() {
        return Err("cad-check failed".into());
    }
    println!("cad-check: Open CASCADE reads every file and agrees to 1e-12");
    let mut worst = [0.0_f64; 2];
    for (name, spline) in &ours {
        for from in ["stp", "igs"] {
            for to in ["stp", "igs"] {
                let path = occ_dir.join(format!("{name}-{from}.{to}"));
                let text = fs::read_to_string(&path)?;
                let read = if to == "stp" {
                    read_step(&text)
                } else {
                    read_iges(&text)
                }
                .map_err(|e| format!("{}: {e}", path.display()))?;
                for (k, theirs) in read.iter().enumerate() {
                    let (err, how) = deviation(spline, theirs)?;
                    println!(
                        "{}: surface {} of {}, {}x{} control points, {how}: max deviation {err:.3e}",
                        path.display(),
                        k + 1,
                        read.len(),
                        theirs.count_u(),
                        theirs.count_v()
                    );
                    let w = &mut worst[usize::from(to == "igs")];
                    *w = w.max(err);
                }
            }
        }
    }
    println!(
        "cad-check: our readers on Open CASCADE's files: worst deviation {:.3e} (STEP), {:.3e} (IGES)",
        worst[0], worst[1]
    );
    if worst[0] <= 1e-11 && worst[1] <= 1e-8 {
        Ok(())
    } else {
        Err("cad-check: a surface written by Open CASCADE differs from ours".into())
    }
}

/// The largest deviation (relative to max(1, largest control coordinate of `ours`)) between
/// `ours` and `theirs` at
/// 41 x 41 parameters, both knot ranges mapped onto [0, 1], minimised over the eight swaps and
/// reversals of (u, v); with the name of the best map.
fn deviation(ours: &BSplineSurface, theirs: &BSplineSurface) -> Result<(f64, String), DynError> {
    let range = |k: &[f64]| {
        (
            k.first().copied().unwrap_or(0.0),
            k.last().copied().unwrap_or(1.0),
        )
    };
    let at = |k: &[f64], t: f64| {
        let (a, b) = range(k);
        a + (b - a) * t
    };
    let scale = ours
        .points
        .iter()
        .flat_map(|p| p.iter().map(|x| x.abs()))
        .fold(1.0_f64, f64::max);
    let mut best = (f64::INFINITY, String::new());
    for map in 0..8_u8 {
        let mut err = 0.0_f64;
        for i in 0..=40 {
            for j in 0..=40 {
                let (s, t) = (f64::from(i) / 40.0, f64::from(j) / 40.0);
                let p = ours.eval(at(&ours.knots_u, s), at(&ours.knots_v, t))?;
                let (mut a, mut b) = if map & 4 == 0 { (s, t) } else { (t, s) };
                if map & 1 != 0 {
                    a = 1.0 - a;
                }
                if map & 2 != 0 {
                    b = 1.0 - b;
                }
                let q = theirs.eval(at(&theirs.knots_u, a), at(&theirs.knots_v, b))?;
                err = err.max((p - q).iter().fold(0.0_f64, |m, x| m.max(x.abs())) / scale);
            }
        }
        if err < best.0 {
            let name = format!(
                "(u, v) -> ({}{}, {}{})",
                if map & 1 != 0 { "1-" } else { "" },
                if map & 4 == 0 { "u" } else { "v" },
                if map & 2 != 0 { "1-" } else { "" },
                if map & 4 == 0 { "v" } else { "u" },
            );
            best = (err, name);
        }
    }
    Ok(best)
}
