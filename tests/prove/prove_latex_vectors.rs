//! `exactcheck prove` on vector formulas as papers print them: `\cdot` and `\times` between bold
//! vectors defined with `--define`, norms `\|v\|^2`, matrix powers `M^k`; false twins fail at
//! an exact point; an undefined bold name, an ambiguous product and a bad matrix power are one
//! line each; and a claims file's `[define]` serves LaTeX sides too.

use crate::timed;

use crate::prove_latex::{each_gives, each_is_proved, each_is_refused};
use timed::run_text as run;

const U: &str = "u = [u1, u2, u3]";
const V: &str = "v = [v1, v2, v3]";
const A: &str = "a = [a1, a2, a3]";
const B: &str = "b = [b1, b2, b3]";
const C: &str = "c = [c1, c2, c3]";
const M: &str = "M = [[m11, m12], [m21, m22]]";

#[test]
fn vector_identities_typed_in_latex_are_proved() {
    each_is_proved(&[
        // Lagrange's identity.
        &[
            "\\|\\mathbf{u}\\times\\mathbf{v}\\|^2 = \\|\\mathbf{u}\\|^2\\|\\mathbf{v}\\|^2 - (\\mathbf{u}\\cdot\\mathbf{v})^2",
            "--define",
            U,
            "--define",
            V,
        ][..],
        &[
            "$\\lVert \\vec{u}\\times\\vec{v} \\rVert^{2} = \\lVert\\vec u\\rVert^2 \\lVert\\vec v\\rVert^2 - (\\vec u\\cdot\\vec v)^2$",
            "--define",
            U,
            "--define",
            V,
        ],
        // BAC-CAB, and the triple product as a determinant.
        &[
            "\\mathbf{a}\\times(\\mathbf{b}\\times\\mathbf{c}) = \\mathbf{b}(\\mathbf{a}\\cdot\\mathbf{c}) - \\mathbf{c}(\\mathbf{a}\\cdot\\mathbf{b})",
            "--define",
            A,
            "--define",
            B,
            "--define",
            C,
        ],
        &[
            "\\mathbf{a}\\times\\mathbf{b}\\cdot\\mathbf{c} = \\det\\begin{pmatrix} a_1 & a_2 & a_3 \\\\ b_1 & b_2 & b_3 \\\\ c_1 & c_2 & c_3 \\end{pmatrix}",
            "--define",
            "a = [a_1, a_2, a_3]",
            "--define",
            "b = [b_1, b_2, b_3]",
            "--define",
            "c = [c_1, c_2, c_3]",
        ],
        &[
            "\\mathbf{u}\\times\\mathbf{v} = -\\mathbf{v}\\times\\mathbf{u}",
            "--define",
            U,
            "--define",
            V,
        ],
        // Matrix powers against products, and the determinant of a power.
        &["M^2", "M*M", "--define", M],
        &["\\mathbf{M}^3 = \\mathbf{M}\\mathbf{M}\\mathbf{M}", "--define", M],
        &["det(M^2)", "det(M)^2", "--define", M],
        &["\\det(\\mathbf{M}^2) = (\\det \\mathbf{M})^2", "--define", M],
        &["M^0", "[[1, 0], [0, 1]]", "--define", M],
        // The length of a vector is the root of its norm.
        &["|\\mathbf{u}|^2 = \\mathbf{u}\\cdot\\mathbf{u}", "--define", U],
        &["\\|\\mathbf{u}\\| = \\sqrt{\\mathbf{u}\\cdot\\mathbf{u}}", "--define", U],
        // A relation may use the definitions: orthogonal vectors.
        &[
            "\\|\\mathbf{u} + \\mathbf{v}\\|^2 = \\|\\mathbf{u}\\|^2 + \\|\\mathbf{v}\\|^2",
            "--define",
            U,
            "--define",
            V,
            "--where",
            "\\mathbf{u}\\cdot\\mathbf{v} = 0",
        ],
        // Text copied from a paper: `·` and `×` are the dot and cross products.
        &["[1, 2, 3]·[x, y, z] = x + 2y + 3z"],
        &["u × v = -(v × u)", "--define", U, "--define", V],
    ]);
}

#[test]
fn false_twins_fail_at_an_exact_point() {
    each_gives(&[
        &[
            "\\mathbf{u}\\times\\mathbf{v} = \\mathbf{v}\\times\\mathbf{u}",
            "--define",
            U,
            "--define",
            V,
        ][..],
        &[
            "\\mathbf{a}\\times(\\mathbf{b}\\times\\mathbf{c}) = \\mathbf{c}(\\mathbf{a}\\cdot\\mathbf{b}) - \\mathbf{b}(\\mathbf{a}\\cdot\\mathbf{c})",
            "--define",
            A,
            "--define",
            B,
            "--define",
            C,
        ],
        &[
            "\\|\\mathbf{u}\\times\\mathbf{v}\\|^2 = \\|\\mathbf{u}\\|^2\\|\\mathbf{v}\\|^2 + (\\mathbf{u}\\cdot\\mathbf{v})^2",
            "--define",
            U,
            "--define",
            V,
        ],
        &["M^2", "[[m11^2, m12^2], [m21^2, m22^2]]", "--define", M],
        &["det(M^2)", "2*det(M)", "--define", M],
    ], 1, "fails: ");
}

#[test]
fn undefined_bold_names_and_ambiguous_products_are_one_line() {
    each_is_refused(&[
        // A bold name is never read as a scalar variable.
        (
            &["\\mathbf{a}\\times\\mathbf{b} = -\\mathbf{b}\\times\\mathbf{a}"][..],
            "the bold name a at 0 is not defined",
        ),
        (
            &[
                "\\mathbf{u}\\cdot\\mathbf{v}\\times\\mathbf{w} = 0",
                "--define",
                U,
                "--define",
                V,
                "--define",
                "w = [1, 2, 3]",
            ],
            "ambiguous",
        ),
        (
            &[
                "\\mathbf{u}\\times\\mathbf{v}\\times\\mathbf{u} = 0",
                "--define",
                U,
                "--define",
                V,
            ],
            "not associative",
        ),
        (
            &["\\mathbf{M}\\cdot\\mathbf{M} = 0", "--define", M],
            "is ambiguous (the matrix product or the sum of the entrywise products)",
        ),
        (
            &["M^-1", "M", "--define", M],
            "must be a non-negative integer constant",
        ),
        (
            &["M^n", "M", "--define", M],
            "the exponent n of the matrix power",
        ),
        (&["M^65", "M", "--define", M], "matrix-power = 64"),
        (
            &["[[1, 2, 3], [4, 5, 6]]^2", "0"],
            "only a square matrix has powers",
        ),
        (&["x", "--define", "u"], "must have the form NAME = VALUE"),
        (&["x", "--define", "sqrt = 2"], "--define sqrt"),
        (&["x", "--define", "u = [1, "], "--define"),
    ]);
    // The limit is raised like any other.
    let (code, out, err) = run(&[
        "prove",
        "[[1, 1], [0, 1]]^100",
        "[[1, 100], [0, 1]]",
        "--limit",
        "matrix-power=100",
    ]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn a_claims_file_defines_the_bold_vectors_of_latex_sides() {
    let path = std::env::temp_dir().join(format!("exactcheck-vectors-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        r#"[define]
u = ["u1", "u2", "u3"]
v = ["v1", "v2", "v3"]

[[claim]]
id = "lagrange"
kind = "identity"
lhs = '\|\mathbf{u}\times\mathbf{v}\|^2'
rhs = '\|\mathbf{u}\|^2\|\mathbf{v}\|^2 - (\mathbf{u}\cdot\mathbf{v})^2'

[[claim]]
id = "commuted"
kind = "identity"
lhs = '\mathbf{u}\times\mathbf{v}'
rhs = '\mathbf{v}\times\mathbf{u}'
expect = "fails"
"#,
    )
    .unwrap();
    // `expect` marks the false twin, so the file's status is 0 when both verdicts are right.
    let rows = crate::common::verify_json(path.to_str().unwrap(), 0);
    std::fs::remove_file(&path).ok();
    assert_eq!(rows.row("lagrange")["verdict"], "proved");
    assert_eq!(rows.row("commuted")["verdict"], "fails");
}
