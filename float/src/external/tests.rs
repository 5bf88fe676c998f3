//! The runner against small shell and Python programs, and the protocol's line forms.
use super::error::show_inputs;
use super::*;

#[test]
fn input_lines_are_json_with_round_trip_numbers() {
    let xs = [
        1.0,
        -0.0,
        1e-300,
        1e16,
        0.1 + 0.2,
        5e-324,
        f64::MAX,
        -1.5e-7,
    ];
    let line = input_line(&xs);
    assert_eq!(
        line,
        "[1.0, -0.0, 1e-300, 1e16, 0.30000000000000004, 5e-324, \
         1.7976931348623157e308, -1.5e-7]\n"
    );
    // Reading the numbers back gives the same doubles, bit for bit (the sign of zero too).
    let back = parse_answer(&line).unwrap();
    assert_eq!(back.len(), xs.len());
    for (a, b) in xs.iter().zip(&back) {
        assert_eq!(a.to_bits(), b.to_bits());
    }
    assert_eq!(
        input_line(&[f64::NAN, f64::INFINITY, f64::NEG_INFINITY]),
        "[NaN, Infinity, -Infinity]\n"
    );
    assert_eq!(input_line(&[]), "[]\n");
}

#[test]
fn answers_in_every_accepted_form() {
    assert_eq!(parse_answer("0.5\n").unwrap(), vec![0.5]);
    assert_eq!(parse_answer("[1.5, -2]").unwrap(), vec![1.5, -2.0]);
    assert_eq!(parse_answer("  1 2\t3  ").unwrap(), vec![1.0, 2.0, 3.0]);
    assert_eq!(parse_answer("1,2 , 3\r\n").unwrap(), vec![1.0, 2.0, 3.0]);
    assert_eq!(parse_answer("[ ]").unwrap(), Vec::<f64>::new());
    assert_eq!(
        parse_answer("0.10000000000000001").unwrap(),
        vec![0.1],
        "C's %.17g"
    );
    let special = parse_answer("nan -nan inf -inf NaN Infinity -Infinity INF").unwrap();
    assert!(special[0].is_nan() && special[1].is_nan() && special[4].is_nan());
    assert_eq!(
        special[2..4].to_vec(),
        vec![f64::INFINITY, f64::NEG_INFINITY]
    );
    assert_eq!(
        special[5..].to_vec(),
        vec![f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY]
    );
}

#[test]
fn garbage_answers_are_refused_with_a_reason() {
    for bad in [
        "hello", "[1, 2", "1, 2]", "[[1, 2]]", "0x1p3", "1e", "1_000", "None", "null",
    ] {
        let e = parse_answer(bad).unwrap_err();
        assert!(!e.is_empty(), "{bad}");
    }
    assert_eq!(
        parse_answer("1 two 3").unwrap_err(),
        "\"two\" is not a number"
    );
}

#[test]
fn stderr_tail_keeps_the_last_line_within_bounds() {
    let mut t = Tail::default();
    assert_eq!(t.last_line(), None);
    for i in 0..1000 {
        t.push(format!("line {i}\n").as_bytes());
    }
    t.push(b"\n  \n");
    assert!(t.0.len() <= STDERR_TAIL);
    assert_eq!(t.last_line().as_deref(), Some("line 999"));
}

#[test]
fn capped_lines_and_a_last_line_without_newline() {
    let mut long = vec![b'7'; MAX_LINE + 10];
    long.extend_from_slice(b"\n1 2\n3");
    let mut r = io::Cursor::new(long);
    assert_eq!(read_capped_line(&mut r).unwrap().unwrap().len(), MAX_LINE);
    assert_eq!(read_capped_line(&mut r).unwrap().as_deref(), Some("1 2"));
    assert_eq!(read_capped_line(&mut r).unwrap().as_deref(), Some("3"));
    assert_eq!(read_capped_line(&mut r).unwrap(), None);
}

#[test]
fn messages_are_one_line_and_name_the_sample() {
    let e = ProgramError::NotNumbers {
        command: "./prog --flag".into(),
        index: 17,
        inputs: vec![0.5, 1e-300],
        line: "oops\nmore".into(),
        reason: "\"oops\" is not a number".into(),
    };
    let s = e.to_string();
    assert!(!s.contains('\n'), "{s}");
    assert!(s.contains("sample 17 [0.5, 1e-300]"), "{s}");
    assert_eq!(e.sample_index(), Some(17));
    let many = show_inputs(&[1.0; 20]);
    assert!(many.ends_with("... (20 inputs)]"), "{many}");
}

#[test]
fn setup_errors() {
    let t = Duration::from_secs(1);
    assert_eq!(
        ProgramRunner::spawn("   ", 1, 1, t).unwrap_err(),
        ProgramError::EmptyCommand
    );
    assert!(matches!(
        ProgramRunner::spawn("prog 'unclosed", 1, 1, t).unwrap_err(),
        ProgramError::Setup { .. }
    ));
    assert!(matches!(
        ProgramRunner::spawn("cat", 1, 0, t).unwrap_err(),
        ProgramError::Setup { .. }
    ));
    assert!(matches!(
        ProgramRunner::spawn("cat", 1, 1, Duration::ZERO).unwrap_err(),
        ProgramError::Setup { .. }
    ));
}
