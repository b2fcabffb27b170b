//! `lpe-check equiv` and `partition` past their analysis budget: `undecided: …` on
//! stdout and exit 4, distinct from bad input (2); and the pair whose DFAs blow up
//! decided within the default budget.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .args(args)
        .output()
        .expect("lpe-check runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

/// `--max-steps 10` is too little for either command: exit 4 with the limit named.
/// Mapping the undecided answer to bad input (exit 2, as before) fails it.
#[test]
fn past_the_budget_equiv_and_partition_exit_4() {
    let hard = ["C.*D.{12}L", "(C.*D.{12}L)|(C.*S.{12}L)"];
    let (code, out) = run(&["equiv", hard[0], hard[1], "--max-steps", "10"]);
    assert_eq!(code, 4, "{out}");
    assert_eq!(
        out,
        "undecided: undecided within the budget of 10 search steps\n"
    );
    let (code, out) = run(&["partition", hard[0], hard[1], "--max-steps", "10"]);
    assert_eq!(code, 4, "{out}");
    assert!(
        out.ends_with("undecided: undecided within the budget of 10 search steps\n"),
        "{out}"
    );
}

/// `C.*D.{24}L` against `C.*D.{24}[LO]` (the lazy-DFA search gave up past 2 000 000
/// states): not equivalent, exit 1, with B's witness of 27 vertices.
#[test]
fn the_blowup_pair_is_decided() {
    let (code, out) = run(&["equiv", "C.*D.{24}L", "C.*D.{24}[LO]"]);
    assert_eq!(code, 1, "{out}");
    let witness = out
        .lines()
        .find_map(|l| l.strip_prefix("only B: "))
        .expect("a witness for B");
    assert_eq!(witness.split(' ').count(), 27, "{out}");
    assert!(out.ends_with("A is strictly included in B\n"), "{out}");
}
