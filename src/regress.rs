//! `exactcheck regress KERNEL`: built-in f64 kernels regressed against exact results with the
//! harness of `exactcheck-float`. Each kernel is a formula of `exactcheck-core` written once,
//! generic over the scalar, run in f64 and exactly on the same seeded inputs.

use crate::Error;
use clap::{Args, ValueEnum};
use exactcheck_core::cylinder_sphere::{unit_circle_point, CylinderSphere};
use exactcheck_core::{BezierCurve, OrderedField, Vec3, ZeroDivisor};
use exactcheck_exact::{PlainRational, Rational};
use exactcheck_float::{regress, ExactScalar, Formula, InputGen, Options, Report, UniformBox};

/// Arguments of `exactcheck regress`.
#[derive(Debug, Args)]
pub struct RegressArgs {
    /// The kernel to regress.
    #[arg(value_enum)]
    pub kernel: Kernel,
    /// Number of random input vectors.
    #[arg(long, default_value_t = 10_000)]
    pub samples: usize,
    /// Seed of the input generator (every reported case is reproducible from it).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// How many worst cases to report (each shrunk to a short reproducible input).
    #[arg(long, default_value_t = 3)]
    pub worst: usize,
    /// The exact scalar of the reference side.
    #[arg(long, value_enum, default_value_t = crate::cli::ScalarChoice::Fast)]
    pub scalar: crate::cli::ScalarChoice,
}

/// The built-in kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Kernel {
    /// Spaeth's cylinder/sphere coefficients A(t), B(t) and the discriminant A^2 - B (SPEC §2).
    CylinderSphere,
    /// De Casteljau evaluation of a cubic Bezier curve in space (SPEC §0).
    BezierCubic,
}

/// The cylinder/sphere kernel. Inputs: axis point `a, b`, radius `r`, the rotations as rational
/// circle parameters `tau_beta, tau_gamma`, sphere centre `d, e, f` and radius `R`, and the
/// curve parameter `tau`; outputs `A, B, A^2 - B`.
pub struct CylinderSphereKernel;

impl Formula for CylinderSphereKernel {
    fn name(&self) -> String {
        "cylinder_sphere: A(t), B(t), A^2 - B".into()
    }
    fn arity(&self) -> usize {
        10
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let cs = CylinderSphere {
            a: x[0].clone(),
            b: x[1].clone(),
            r: x[2].clone(),
            beta: unit_circle_point(&x[3])?,
            gamma: unit_circle_point(&x[4])?,
            center: Vec3::new(x[5].clone(), x[6].clone(), x[7].clone()),
            radius: x[8].clone(),
        };
        let t = unit_circle_point(&x[9])?;
        let (a, b) = cs.coefficients_at(&t.cos, &t.sin);
        let disc = a.square() - &b;
        Ok(vec![a, b, disc])
    }
}

/// A cubic Bezier curve in space evaluated by de Casteljau. Inputs: the 12 coordinates of the
/// control points and `t`; outputs the point.
pub struct BezierCubicKernel;

impl Formula for BezierCubicKernel {
    fn name(&self) -> String {
        "bezier_cubic: de Casteljau evaluation".into()
    }
    fn arity(&self) -> usize {
        13
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let points = (0..4)
            .map(|i| Vec3::new(x[3 * i].clone(), x[3 * i + 1].clone(), x[3 * i + 2].clone()))
            .collect();
        let curve = BezierCurve::new(points);
        Ok(curve.eval(&x[12]).into_array().to_vec())
    }
}

fn generator(kernel: Kernel) -> Result<UniformBox, Error> {
    let gen = match kernel {
        Kernel::CylinderSphere => UniformBox::new(
            vec![
                -10.0, -10.0, 0.5, -3.0, -3.0, -10.0, -10.0, -10.0, 0.5, -50.0,
            ],
            vec![10.0, 10.0, 10.0, 3.0, 3.0, 10.0, 10.0, 10.0, 15.0, 50.0],
        ),
        Kernel::BezierCubic => {
            let mut lo = vec![-10.0; 12];
            let mut hi = vec![10.0; 12];
            lo.push(0.0);
            hi.push(1.0);
            UniformBox::new(lo, hi)
        }
    };
    gen.map_err(|e| Error::Usage(format!("input generator: {e}")))
}

fn run_kernel<E: ExactScalar>(
    kernel: Kernel,
    gen: &impl InputGen,
    args: &RegressArgs,
    options: &Options,
) -> Result<Report, Error> {
    let report = match kernel {
        Kernel::CylinderSphere => {
            regress::<E>(&CylinderSphereKernel, gen, args.samples, args.seed, options)
        }
        Kernel::BezierCubic => {
            regress::<E>(&BezierCubicKernel, gen, args.samples, args.seed, options)
        }
    };
    report.map_err(|e| Error::Usage(e.to_string()))
}

/// Runs `exactcheck regress` and prints the report.
pub fn run(args: &RegressArgs) -> Result<(), Error> {
    if args.samples == 0 {
        return Err(Error::Usage("--samples must be at least 1".into()));
    }
    let gen = generator(args.kernel)?;
    let options = Options {
        worst: args.worst,
        ..Options::default()
    };
    let report = match args.scalar {
        crate::cli::ScalarChoice::Fast => {
            run_kernel::<Rational>(args.kernel, &gen, args, &options)?
        }
        crate::cli::ScalarChoice::Plain => {
            run_kernel::<PlainRational>(args.kernel, &gen, args, &options)?
        }
    };
    println!("{report}");
    Ok(())
}
