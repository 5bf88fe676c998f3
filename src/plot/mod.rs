//! `exactcheck plot`: the SVG figures of the catalogue's papers and of problem files, drawn
//! with `plotters` (its SVG backend, `SVGBackend::with_string`), one module per paper:
//! * `spaeth` — Spaeth's cylinder/sphere intersection: the t-u diagram (the paper's
//!   Fig. 2 and 3; a 2D chart) and a 3D view (a `plotters` 3D chart, drawn back to front);
//! * [`chiang`] — Chiang's Example 4: the ruled surface, the plane z = 0 and the exact section
//!   curve with its control polygon (a 3D chart);
//! * [`conics`] — Chiang's Table 1: the four cone sections, one 2D chart per panel;
//! * [`ph`] — Chiang's PH curve with its offsets and their cusps (a 2D chart).
//!
//! What a figure shows is computed first, exactly where the paper's statement is exact (the
//! markers of the t-u diagram by exact root isolation on the tau-quartic in `scene`, Chiang's sections over
//! `Q(sqrt 2, sqrt 6)`, the PH offsets over `Q`), and only converted to f64 to be drawn; the
//! dense curves of the t-u diagram and the 3D views are f64 samplings. [`style`] holds what the
//! figures share (palette, caption, legend, markers, fixed-tick axes), so a new figure is a
//! scene plus a few dozen lines of chart.
//!
//! Layout: `scene` (Spaeth's configurations, their exact analysis and the f64 sampling),
//! `style`, and the four figure modules.

use crate::claims::spaeth::SpaethExample;
use crate::Error;
use clap::{Args, ValueEnum};
use exactcheck_core::cylinder_sphere::{Angle, CylinderSphere};
use exactcheck_core::Sign;
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::univariate::{Bound, RootInterval, UPoly};
use exactcheck_exact::Rational;
use exactcheck_float::sampler::DiscSampler;
use std::f64::consts::TAU;
use std::io::Write as _;
use std::path::Path;
use std::process::ExitCode;

pub mod chiang;
pub mod conics;
pub mod ph;
mod scene;
mod spaeth;
pub mod style;
#[cfg(test)]
mod tests;

use scene::*;
use spaeth::{tu_diagram, view_3d};
use style::short;
pub use style::{escape, nice_ticks};

/// Arguments of `exactcheck plot`.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// `spaeth` (with `--example N`), `chiang` (with `--example 4`: Chiang's ruled surface, the
    /// plane z = 0, the exact section curve and its control polygon, one 3D figure), `conics`
    /// (the four cone sections of Chiang's Table 1, one panel each), `ph` (Chiang's PH curve with
    /// its offsets at r = 3, 12.6, 15 and their cusps) or a `cylinder_sphere`, `conic` or
    /// `ph_offset` problem file (the format of `solve`).
    pub source: String,
    /// Which example to draw: Spaeth's 1, 2 or 3 with `spaeth`; 4 with `chiang`.
    #[arg(long, value_name = "N")]
    pub example: Option<u32>,
    /// The figure of a cylinder/sphere: the t-u diagram (the paper's Fig. 2 / 3) or a 3D view
    /// (`chiang` has one figure, a 3D view, whatever `--view` says).
    #[arg(long, value_enum, default_value_t = View::Tu)]
    pub view: View,
    /// The SVG file to write; `-`: standard output (the summary line then goes to standard
    /// error).
    #[arg(short = 'o', long = "output", value_name = "FILE.svg")]
    pub output: String,
}

/// The figures `plot` draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum View {
    /// The t-u diagram: t in degrees against the roots u1 <= u2.
    Tu,
    /// An orthographic 3D view of cylinder, sphere and intersection curve.
    #[value(name = "3d")]
    ThreeD,
}

/// Runs `exactcheck plot`: draws the figure, writes it and prints one line.
///
/// # Errors
/// [`Error::Usage`] for an unknown example, a missing or misplaced `--example`, or an output
/// path that cannot be written; [`Error::Io`] / [`Error::Input`] for an unreadable or malformed
/// problem file or one of another kind; [`Error::Output`] when standard output fails.
pub fn run(args: &PlotArgs) -> Result<ExitCode, Error> {
    let input = input_file(args);
    if args.output != "-" {
        crate::output::check_output_file(&args.output, input.as_slice())?;
    }
    if args.source == "chiang" {
        let svg = chiang::figure(args.example)?;
        return emit(
            args,
            &svg,
            "Chiang Example 4 (ruled surface, plane z = 0, exact section curve, control polygon)",
        );
    }
    if args.source == "ph" {
        let svg = ph::figure(args.example)?;
        return emit(
            args,
            &svg,
            "Chiang's PH curve with its offsets at r = 3, 12.6, 15 and their cusps",
        );
    }
    if args.source == "conics" {
        if args.example.is_some() {
            return Err(Error::Usage(
                "plot conics draws the four planes of Chiang's Table 1 and takes no --example"
                    .into(),
            ));
        }
        let (svg, _) = conics::table1();
        return emit(
            args,
            &svg,
            "Chiang Table 1 (four cone sections, control polygons, poles)",
        );
    }
    if args.example.is_none() && !["spaeth", "chiang"].contains(&args.source.as_str()) {
        let text = crate::solve::read_problem(Some(&args.source))?;
        if crate::solve::problem_kind(&text).is_ok_and(|k| k == "conic") {
            let (svg, _) = conics::file(&args.source, &text)?;
            return emit(args, &svg, &format!("cone section of {}", args.source));
        }
    }
    let scene = match (args.source.as_str(), args.example) {
        ("spaeth", Some(n)) => spaeth_scene(n)?,
        ("spaeth", None) => {
            return Err(Error::Usage("plot spaeth needs --example 1, 2 or 3".into()))
        }
        (_, Some(_)) => {
            return Err(Error::Usage(format!(
                "--example goes with `plot spaeth` or `plot chiang`, not with a problem file ({})",
                args.source
            )))
        }
        (path, None) => match ph::file_figure(path)? {
            Some((svg, what)) => return emit(args, &svg, &what),
            None => file_scene(path)?,
        },
    };
    let (svg, what) = match args.view {
        View::Tu => (tu_diagram(&scene), "t-u diagram"),
        View::ThreeD => (view_3d(&scene), "3D view"),
    };
    let what = format!(
        "{what} of {}{}",
        scene.name,
        match (args.view, scene.figure) {
            (View::Tu, Some(f)) => format!(" (the paper's {f})"),
            _ => String::new(),
        }
    );
    emit(args, &svg, &what)
}

/// The names `plot` draws the catalogue's figures by (`exactcheck plot NAME`); any other source
/// is a problem file. The paper registry names the same set (a test compares them).
pub const FIGURE_NAMES: [&str; 4] = ["spaeth", "chiang", "conics", "ph"];

/// The problem file `plot` reads, when its source is one (not a built-in figure's name).
fn input_file(args: &PlotArgs) -> Option<&Path> {
    (!FIGURE_NAMES.contains(&args.source.as_str())).then(|| Path::new(&args.source))
}

/// A figure of the built-in catalogue, as the report shows it.
#[derive(Clone, Debug)]
pub struct Figure {
    /// A stable identifier (`spaeth.example1.tu`), also the figure's anchor in the report.
    pub id: String,
    /// The source paper: the claim-id prefix its claims share (`spaeth`, `chiang`).
    pub source: &'static str,
    /// The caption.
    pub title: String,
    /// The SVG document.
    pub svg: String,
}

/// Spaeth's examples 1-3, the t-u diagram and the 3D view of each (the unit `spaeth` of
/// [`crate::papers::PAPERS`]).
///
/// # Errors
/// When a figure cannot be drawn (an internal error of the catalogue's data).
pub fn spaeth_figures() -> Result<Vec<Figure>, Error> {
    let mut out = Vec::new();
    for n in 1..=3 {
        let scene = spaeth_scene(n)?;
        let fig = scene
            .figure
            .map_or(String::new(), |f| format!(" (the paper's {f})"));
        out.push(Figure {
            id: format!("spaeth.example{n}.tu"),
            source: "spaeth",
            title: format!("t-u diagram of {}{fig}", scene.name),
            svg: tu_diagram(&scene),
        });
        out.push(Figure {
            id: format!("spaeth.example{n}.3d"),
            source: "spaeth",
            title: format!("3D view of {}", scene.name),
            svg: view_3d(&scene),
        });
    }
    Ok(out)
}

/// Chiang's Example 4 (the unit `chiang`).
///
/// # Errors
/// As [`spaeth_figures`].
pub fn chiang_figures() -> Result<Vec<Figure>, Error> {
    Ok(vec![Figure {
        id: "chiang.example4".into(),
        source: "chiang",
        title: "Chiang Example 4: ruled surface, plane z = 0, exact section curve, control polygon"
            .into(),
        svg: chiang::figure(Some(4))?,
    }])
}

/// Table 1's four cone sections (the unit `chiang_conic`).
///
/// # Errors
/// Never; the signature is the registry's.
pub fn conic_figures() -> Result<Vec<Figure>, Error> {
    Ok(vec![Figure {
        id: "chiang.conic_table".into(),
        source: "chiang",
        title: "Chiang Table 1: four cone sections, control polygons, poles".into(),
        svg: conics::table1().0,
    }])
}

/// The PH curve's offsets (the unit `chiang_ph`).
///
/// # Errors
/// As [`spaeth_figures`].
pub fn ph_figures() -> Result<Vec<Figure>, Error> {
    Ok(vec![Figure {
        id: "chiang.ph_offsets".into(),
        source: "chiang",
        title: "Chiang's PH curve with its offsets at r = 3, 12.6, 15 and their cusps".into(),
        svg: ph::figure(None)?,
    }])
}

/// Writes `svg` to `-o` (`-`: standard output; a file never over the problem file read) and
/// prints the summary line "wrote ...".
fn emit(args: &PlotArgs, svg: &str, what: &str) -> Result<ExitCode, Error> {
    let output = args.output.as_str();
    let to_stdout = output == "-";
    if to_stdout {
        crate::output::print(svg)?;
    } else {
        crate::output::write_file(output, svg.as_bytes(), input_file(args).as_slice())?;
    }
    let summary = format!(
        "wrote {}: {what} ({} bytes of SVG)",
        if to_stdout { "standard output" } else { output },
        svg.len()
    );
    if to_stdout {
        // The SVG owns standard output; a failing standard error has nowhere to be reported.
        let _ = writeln!(std::io::stderr(), "{summary}");
    } else {
        crate::output::println(summary)?;
    }
    Ok(ExitCode::SUCCESS)
}
