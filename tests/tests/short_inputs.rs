//! Every short input, not a sample: each string of up to three syntax characters after
//! each of a few openings (`C<`, `C<(`, `C[`, ...) goes through the parse fuzz targets'
//! bodies (`lpe_engines::fuzzing`: no panic, and what parses prints back to the same
//! tree). Proptest and libFuzzer draw longer inputs at random and can miss a short one
//! for many runs: `C<(R|` (input ending after a `|` inside `<( … )>`) panicked the OSL
//! parser and was first drawn by a random proptest case in CI, not by the committed
//! corpus. The openings put the end of input inside each nesting (a group, a
//! parenthesis or a list in one, a quoted label); about 520 000 inputs, a second in
//! release.

/// Runs `body` on each of `openings` followed by every string of up to `len`
/// characters of `alphabet`; returns how many inputs ran and the ones that panicked.
fn every_input(
    body: impl Fn(&[u8]) + std::panic::RefUnwindSafe,
    openings: &[&str],
    alphabet: &[u8],
    len: usize,
) -> (usize, Vec<String>) {
    let (mut ran, mut failed) = (0, Vec::new());
    for opening in openings {
        for n in 0..=len {
            // The n-character strings in order, as n digits in base `alphabet.len()`.
            let mut digits = vec![0usize; n];
            loop {
                let mut input = opening.as_bytes().to_vec();
                input.extend(digits.iter().map(|&d| alphabet[d]));
                ran += 1;
                if std::panic::catch_unwind(|| body(&input)).is_err() {
                    failed.push(String::from_utf8_lossy(&input).into_owned());
                }
                let Some(k) = digits.iter().position(|&d| d + 1 < alphabet.len()) else {
                    break;
                };
                digits[k] += 1;
                digits[..k].fill(0);
            }
        }
    }
    (ran, failed)
}

/// `every_input` with panic messages silenced (the failures are returned).
fn quietly(
    body: impl Fn(&[u8]) + std::panic::RefUnwindSafe,
    openings: &[&str],
    alphabet: &[u8],
) -> (usize, Vec<String>) {
    // The hook is the process's: tests running at once would restore each other's.
    static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let out = every_input(body, openings, alphabet, 3);
    std::panic::set_hook(hook);
    out
}

/// Every input of `openings` and `alphabet` through the fuzz target `name` passes, and
/// there are as many as the closed form says.
fn assert_every_input_passes(name: &str, openings: &[&str], alphabet: &[u8]) {
    let body = lpe_engines::fuzzing::target(name).expect("a parse target");
    let (ran, failed) = quietly(
        |d: &[u8]| {
            body(d);
        },
        openings,
        alphabet,
    );
    let a = alphabet.len();
    let expected = openings.len() * (1 + a + a * a + a * a * a);
    assert_eq!(ran, expected, "{name}: inputs enumerated");
    assert!(
        failed.is_empty(),
        "{name}: {} inputs panic, e.g. {:?}",
        failed.len(),
        &failed[..failed.len().min(8)]
    );
}

#[test]
fn every_short_osl_expression_parses_or_errors() {
    let openings = [
        "",
        "C",
        "C<",
        "C<(",
        "C<[",
        "C<(R",
        "C[",
        "C(",
        "C'",
        "events=U;scatters=Y\nC<",
    ];
    let alphabet = b"CRDLGSTUx.'<>()[]^&|*+{},0 -";
    assert_every_input_passes("osl_parse", &openings, alphabet);
}

#[test]
fn every_short_renderman_expression_parses_or_errors() {
    let openings = [
        "", "C", "C<", "C<(", "C<[", "C[", "C(", "C'", "lpe:", "lpe:C<R",
    ];
    let alphabet = b"CRTLODSU2_.'<>()[]^&|*+?{},0 ;";
    assert_every_input_passes("parse", &openings, alphabet);
}

#[test]
fn every_short_path_text_parses_or_errors() {
    let openings = ["", "C", "C R", "C RD", "C L'"];
    let alphabet = b"CRTLODSU12_' ";
    assert_every_input_passes("path_text", &openings, alphabet);
}

/// The enumeration itself: every string of length 0 to 3 is reached once, and a
/// body that panics on one of them has exactly that one reported.
#[test]
fn the_enumeration_reaches_every_string_once() {
    let seen = std::sync::Mutex::new(Vec::new());
    let (ran, failed) = quietly(
        |d: &[u8]| {
            let s = String::from_utf8_lossy(d).into_owned();
            seen.lock()
                .unwrap_or_else(|e| e.into_inner())
                .push(s.clone());
            assert_ne!(s, "xbba");
        },
        &["x"],
        b"ab",
    );
    assert_eq!(ran, 1 + 2 + 4 + 8);
    assert_eq!(failed, ["xbba"]);
    let mut seen = seen.into_inner().unwrap_or_else(|e| e.into_inner());
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 15);
    assert!(seen.iter().all(|s| s.starts_with('x') && s.len() <= 4));
}
