//! The f64 evaluator of the cylinder/sphere discriminant (Spaeth).
//!
//! `A(t)` and `B(t)` are reduced once per configuration to fixed trigonometric-polynomial
//! coefficients ([`TrigCoefficients`], derived by the same generic code that the exact side runs),
//! then evaluated at any `t` with a handful of multiplications ([`DiscSampler::discriminant`],
//! [`DiscSampler::roots`]): what the plots and the Spaeth claims sample. The grid sweeps that
//! time it live in the benchmark lab (`bench/src/sample_sphere`).

use exactcheck_core::cylinder_sphere::{CylinderSphere, TrigCoefficients};

/// Coefficients of `A` and `B` as plain f64 arrays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiscSampler {
    a: [f64; 3],
    b: [f64; 6],
}

impl DiscSampler {
    /// The sampler of a configuration given in f64 (coefficients derived in f64).
    pub fn new(cs: &CylinderSphere<f64>) -> Self {
        Self::from_coefficients(&cs.trig_coefficients())
    }

    /// The sampler from coefficients (e.g. exact ones rounded to f64).
    pub fn from_coefficients(c: &TrigCoefficients<f64>) -> Self {
        DiscSampler { a: c.a, b: c.b }
    }

    /// The coefficients `(a, b)`: `A = a0 + a1 cos t + a2 sin t` and
    /// `B = b0 + b1 cos t + b2 sin t + cos t (b3 cos t + b4 sin t) + b5 sin^2 t`.
    pub fn coefficients(&self) -> ([f64; 3], [f64; 6]) {
        (self.a, self.b)
    }

    /// `(A, B)` at `(cos t, sin t)`.
    #[inline(always)]
    pub fn ab(&self, c: f64, s: f64) -> (f64, f64) {
        let [a0, a1, a2] = self.a;
        let [b0, b1, b2, b3, b4, b5] = self.b;
        let a = a0 + a1 * c + a2 * s;
        let b = b0 + b1 * c + b2 * s + c * (b3 * c + b4 * s) + b5 * s * s;
        (a, b)
    }

    /// The discriminant `A^2 - B` at `(cos t, sin t)` (the operations every sweep uses).
    #[inline(always)]
    pub fn disc_cs(&self, c: f64, s: f64) -> f64 {
        let (a, b) = self.ab(c, s);
        a * a - b
    }

    /// The discriminant `A^2 - B` at the angle `t` (radians).
    #[inline]
    pub fn discriminant(&self, t: f64) -> f64 {
        let (s, c) = t.sin_cos();
        self.disc_cs(c, s)
    }

    /// The roots `u = -A +- sqrt(A^2 - B)` at `t`, if real.
    pub fn roots(&self, t: f64) -> Option<(f64, f64)> {
        let (s, c) = t.sin_cos();
        let (a, b) = self.ab(c, s);
        let d = a * a - b;
        (d >= 0.0).then(|| (-a - d.sqrt(), -a + d.sqrt()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::cylinder_sphere::Angle;
    use exactcheck_core::Vec3;

    /// The configuration of the `sample-sphere` benchmark, in f64.
    fn w3() -> CylinderSphere<f64> {
        CylinderSphere {
            a: 1.0 / 3.0,
            b: -2.0 / 7.0,
            r: 5.0,
            beta: Angle {
                cos: 3.0 / 5.0,
                sin: 4.0 / 5.0,
            },
            gamma: Angle {
                cos: 5.0 / 13.0,
                sin: -12.0 / 13.0,
            },
            center: Vec3::new(1.0, 2.0, 4.0),
            radius: 5.0,
        }
    }

    #[test]
    fn coefficients_reproduce_the_direct_formula() {
        let cs = w3();
        let s = DiscSampler::new(&cs);
        for k in 0..100 {
            let t = k as f64 * 0.0628;
            let (sn, c) = t.sin_cos();
            let (a1, b1) = cs.coefficients_at(&c, &sn);
            let (a2, b2) = s.ab(c, sn);
            assert!((a1 - a2).abs() <= 1e-12 * (1.0 + a1.abs()));
            assert!((b1 - b2).abs() <= 1e-12 * (1.0 + b1.abs()));
        }
    }
}
