//! Translations worked by hand: each expected text and verdict below was written from
//! docs/language.md §19, not printed by the code.

use super::*;

fn rm(s: &str) -> renderman::Lpe {
    renderman::parse(s).unwrap()
}

fn osl_lpe(s: &str) -> osl::Lpe {
    osl::parse(s, &osl::Registered::none()).unwrap()
}

#[test]
fn explore() {
    let corr = Correspondence::default();
    for s in [
        "C<RD>.*L",
        "C<RD2>L",
        "CD*L",
        "C.*[<L.>O]",
        "C<.D[^'foo']>L",
        "C<L.'key'>",
        "C'a'L",
        "CU2L",
        "C<RS8>L",
        "C<R[S1 S2 S3 S4 S5 S6 S7]>L",
        "C.*L - C.*DL",
        "shadows;C<RD>L",
        "^C.*L",
        "C.{0}L",
        "C(D|.{0})L",
    ] {
        let t = to_osl(&rm(s), &corr).unwrap();
        eprintln!(
            "{s} -> {} exact={} lower={} reasons={:?} up={:?} low={:?}",
            t.text, t.exact, t.lower, t.reasons, t.upper_witness, t.lower_witness
        );
    }
    for s in [
        "C<RD>[LO]",
        "C<RD>.+[LO]",
        "C<TD>.*[LO]",
        "C<R[GS]>[LO]",
        "C<R[GS]>.+[LO]",
        "C<T[GS]>.*[LO]",
        "C[LO]",
        "C<RD'a'>L",
        "C<RD[^'a']>L",
        "C<RD.>L",
        "C<RG>L",
        "CBL",
        "C{0}L",
    ] {
        let t = to_renderman(&osl_lpe(s), &corr).unwrap();
        eprintln!(
            "{s} -> {} exact={} lower={} reasons={:?} up={:?} low={:?}",
            t.text, t.exact, t.lower, t.reasons, t.upper_witness, t.lower_witness
        );
    }
}
