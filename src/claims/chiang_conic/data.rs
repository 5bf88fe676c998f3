//! Table 1 as printed: the restored columns, the plane equations the OCR reads, and the
//! OCR's literal readings where they differ from the restoration.

use super::*;

/// A plane equation `a x + b y + c z = rhs` as printed.
#[derive(Clone, Copy, Debug)]
pub struct PrintedPlane {
    /// The equation, square roots restored as in the rest of the table.
    pub text: &'static str,
    /// The OCR's literal tokens (the seed's reading order).
    pub ocr: &'static str,
    /// `a, b, c, rhs`.
    pub coefficients: [&'static str; 4],
}

/// One column of Table 1, as printed (numbers in the workspace's number syntax).
#[derive(Clone, Copy, Debug)]
pub struct PrintedColumn {
    /// The column's heading: `circle`, `ellipse`, `parabola`, `hyperbola`.
    pub name: &'static str,
    /// The normal of the plane I.
    pub normal: [&'static str; 3],
    /// The plane equation (OCR'd; the restoration leaves it out).
    pub plane: PrintedPlane,
    /// `w0+ w1+ w2+`.
    pub weights_plus: [&'static str; 3],
    /// `r0+ r1+ r2+`.
    pub points_plus: [[&'static str; 3]; 3],
    /// `w0- w1- w2-`.
    pub weights_minus: [&'static str; 3],
    /// `r0- r1- r2-` ("the + points in reverse order", written out).
    pub points_minus: [[&'static str; 3]; 3],
    /// The row `C-(t) = inf` (empty: "none").
    pub poles_minus: &'static [&'static str],
}

/// Table 1 as the claim list restores it (plane equations as the OCR reads them).
pub const TABLE1: [PrintedColumn; 4] = [
    PrintedColumn {
        name: "circle",
        normal: ["0", "0", "1"],
        plane: PrintedPlane {
            text: "z - 1 = 0",
            ocr: "01 =−z",
            coefficients: ["0", "0", "1", "1"],
        },
        weights_plus: ["1", "1/sqrt(2)", "1"],
        points_plus: [["1", "0", "1"], ["1", "1", "1"], ["0", "1", "1"]],
        weights_minus: ["1", "-1/sqrt(2)", "1"],
        points_minus: [["0", "1", "1"], ["1", "1", "1"], ["1", "0", "1"]],
        poles_minus: &[],
    },
    PrintedColumn {
        name: "ellipse",
        normal: ["1", "1", "3"],
        plane: PrintedPlane {
            text: "x + y + 3z = 4",
            ocr: "43 =++ zyx",
            coefficients: ["1", "1", "3", "4"],
        },
        weights_plus: ["4", "5/sqrt(2)", "4"],
        points_plus: [["5/4", "0", "5/4"], ["1", "1", "1"], ["0", "5/4", "5/4"]],
        weights_minus: ["4", "-5/sqrt(2)", "4"],
        points_minus: [["0", "5/4", "5/4"], ["1", "1", "1"], ["5/4", "0", "5/4"]],
        poles_minus: &[],
    },
    PrintedColumn {
        name: "parabola",
        normal: ["1", "1", "sqrt(2)"],
        plane: PrintedPlane {
            text: "x + y + sqrt2 z = 2 - sqrt2",
            ocr: "222 −=++ zyx",
            coefficients: ["1", "1", "sqrt(2)", "2 - sqrt(2)"],
        },
        weights_plus: ["1 + sqrt(2)", "1 + sqrt(2)", "1 + sqrt(2)"],
        points_plus: [
            ["sqrt(2)", "0", "sqrt(2)"],
            ["1", "1", "1"],
            ["0", "sqrt(2)", "sqrt(2)"],
        ],
        weights_minus: ["1 + sqrt(2)", "-sqrt(2) - 1", "1 + sqrt(2)"],
        points_minus: [
            ["0", "sqrt(2)", "sqrt(2)"],
            ["1", "1", "1"],
            ["sqrt(2)", "0", "sqrt(2)"],
        ],
        poles_minus: &["1/2"],
    },
    PrintedColumn {
        name: "hyperbola",
        normal: ["1", "1", "0"],
        plane: PrintedPlane {
            text: "x + y = 2",
            ocr: "2=+ yx",
            coefficients: ["1", "1", "0", "2"],
        },
        weights_plus: ["1", "sqrt(2)", "1"],
        points_plus: [["2", "0", "2"], ["1", "1", "1"], ["0", "2", "2"]],
        weights_minus: ["1", "-sqrt(2)", "1"],
        points_minus: [["0", "2", "2"], ["1", "1", "1"], ["2", "0", "2"]],
        poles_minus: &["1/sqrt(2)", "1 - 1/sqrt(2)"],
    },
];

/// The four planes of Table 1 over `Q(sqrt 2)`: each through `(1, 1, 1)` with the printed
/// normal of its column of [`TABLE1`] (circle, ellipse, parabola, hyperbola).
///
/// # Panics
/// Never: the printed normals are constants that parse (a test reads them).
pub fn table1_planes() -> [Plane<Radical>; 4] {
    TABLE1.map(|col| {
        let n = vec3(&col.normal).expect("Table 1's printed normals parse");
        let d = n.x.add_ref(&n.y).add_ref(&n.z).neg_ref();
        Plane::new(n.x, n.y, n.z, d)
    })
}

/// The OCR's literal reading of an entry where it differs from the restoration.
#[derive(Clone, Copy, Debug)]
pub struct OcrReading {
    /// The column (`circle`, ...).
    pub column: &'static str,
    /// The entry (`w1+`, `r0-`, `C-(t) = inf`).
    pub entry: &'static str,
    /// The seed's characters.
    pub ocr: &'static str,
    /// What they literally say: one number (weight), three (point) or the pole parameters.
    pub reading: &'static [&'static str],
}

/// Every entry of the scanned Table 1 whose OCR differs from the restoration (lost square
/// roots: `2 1` is `1/2` literally, restored as `1/sqrt2`).
pub const OCR_READINGS: [OcrReading; 17] = [
    ocr("circle", "w1+", "2 1", &["1/2"]),
    ocr("circle", "w1-", "2 1 −", &["-1/2"]),
    ocr("ellipse", "w1+", "2 5", &["5/2"]),
    ocr("ellipse", "w1-", "2 5 −", &["-5/2"]),
    ocr("parabola", "w0+", "21+", &["1 + 2"]),
    ocr("parabola", "w1+", "21+", &["1 + 2"]),
    ocr("parabola", "w2+", "21+", &["1 + 2"]),
    ocr("parabola", "w0-", "21+", &["1 + 2"]),
    ocr("parabola", "w1-", "21−−", &["-2 - 1"]),
    ocr("parabola", "w2-", "21+", &["1 + 2"]),
    ocr("parabola", "r0+", ")2,0,2(", &["2", "0", "2"]),
    ocr("parabola", "r2+", ")2,2,0(", &["0", "2", "2"]),
    ocr("parabola", "r0-", ")2,2,0(", &["0", "2", "2"]),
    ocr("parabola", "r2-", ")2,0,2(", &["2", "0", "2"]),
    ocr("hyperbola", "w1+", "2", &["2"]),
    ocr("hyperbola", "w1-", "2−", &["-2"]),
    ocr(
        "hyperbola",
        "C-(t) = inf",
        "2 1=t 2 11, 2 1 −== tt",
        &["1/2", "1 - 1/2"],
    ),
];

pub(super) const fn ocr(
    column: &'static str,
    entry: &'static str,
    ocr: &'static str,
    reading: &'static [&'static str],
) -> OcrReading {
    OcrReading {
        column,
        entry,
        ocr,
        reading,
    }
}
