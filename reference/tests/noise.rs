//! Both reference front ends on noisy text: every input of characters from their
//! grammars (and some outside them) either parses or is an error with a byte position
//! inside the text; none panics or overflows the stack.

use lpe::rng::SplitMix64;
use lpe_reference::{osl, renderman};

const ALPHABET: &[char] = &[
    'C', 'R', 'T', 'L', 'O', 'D', 'S', 'U', 'G', 's', 'B', 'V', 'x', 'c', 'd', '.', '\'', '<', '>',
    '[', ']', '^', '(', ')', '|', '*', '+', '?', '{', '}', ',', '0', '1', '2', '9', ' ', '&', '-',
    ';', '_', 'a', 'é', '"',
];

fn noise(rng: &mut SplitMix64) -> String {
    let len = rng.below(24);
    (0..len)
        .map(|_| ALPHABET[rng.below(ALPHABET.len())])
        .collect()
}

#[test]
fn noise_parses_or_is_an_error_inside_the_text() {
    let mut rng = SplitMix64::new(7);
    let rm = renderman::Registration::default();
    let os = osl::Registration::default();
    for _ in 0..50_000 {
        let text = noise(&mut rng);
        if let Err(e) = renderman::parse(&text, &rm) {
            assert!(e.pos <= text.len(), "`{text}`: {e}");
        }
        if let Err(e) = osl::parse(&text, &os) {
            assert!(e.pos <= text.len(), "`{text}`: {e}");
        }
    }
}

#[test]
fn deep_nesting_of_every_kind_is_a_limit_error() {
    for open in ["(", "[", "<", "^(", "<(", "(C|"] {
        let text = format!("C{}", open.repeat(50_000));
        for r in [
            renderman::parse(&text, &renderman::Registration::default()).map(|_| ()),
            osl::parse(&text, &osl::Registration::default()).map(|_| ()),
        ] {
            assert!(r.is_err(), "`{open}` x 50 000 parsed");
        }
    }
}
