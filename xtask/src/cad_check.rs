//! `cargo xtask cad-check`: validates pde-bezier's STEP and IGES export against Open CASCADE.
//!
//! Installs PyPI's `cadquery-ocp-novtk` into a virtual environment under `target/cad-venv`
//! (once), writes STEP and IGES files of a few solutions with non-square, non-symmetric control
//! nets into `target/cad-check/`, and has Open CASCADE read each file (checking the load status
//! before the transfer) and evaluate the surface at sample parameters; every point must agree
//! with ours to 1e-12 (relative to the coordinate size).

use std::fmt::Write as _;
use std::fs;
use std::process::Command;

use pde_bezier::{Method, cases, solve, write_iges, write_step};

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
print(f"worst deviation {worst:.3e}")
sys.exit(0 if worst <= 1e-12 else 1)
"#;

pub(crate) fn run() -> Result<(), DynError> {
    let root = project_root();
    let python = python_env("cad-venv", "OCP", &["cadquery-ocp-novtk"])?;
    let dir = root.join("target").join("cad-check");
    fs::create_dir_all(&dir)?;
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
                "{{\"kind\":\"{kind}\",\"path\":{:?},\"samples\":{samples}}}",
                path.display().to_string()
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
    if ok.success() {
        println!("cad-check: Open CASCADE reads every file and agrees to 1e-12");
        Ok(())
    } else {
        Err("cad-check failed".into())
    }
}
