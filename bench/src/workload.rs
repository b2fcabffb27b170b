//! The benchmark's AOV sets: the basic set, the per-lobe set, light-group
//! splits with label AOVs, and adversarial shapes.

use lpe::renderman::macros::{BASIC, PER_LOBE};
use lpe::renderman::{parse, Lpe};

/// Light groups the light-group workload splits over (and the path sampler draws).
pub const LIGHT_GROUPS: [&str; 4] = ["key", "fill", "rim", "env"];
/// Object `lpegroup` labels the path sampler draws.
pub const OBJECT_GROUPS: [&str; 5] = ["floor", "wall", "glass", "metal", "skin"];

/// One named AOV set.
pub struct Workload {
    /// Short name, as given to `--workload`.
    pub name: &'static str,
    /// What it stands for.
    pub about: &'static str,
    /// The AOVs.
    pub aovs: Vec<(String, Lpe)>,
}

fn named(pairs: impl IntoIterator<Item = (String, String)>) -> Vec<(String, Lpe)> {
    pairs
        .into_iter()
        .map(|(n, s)| {
            let l = parse(&s).unwrap_or_else(|e| panic!("workload AOV `{s}`: {e}"));
            (n, l)
        })
        .collect()
}

/// Every workload, in table order.
pub fn all() -> Vec<Workload> {
    let own = |t: &[(&str, &str)]| named(t.iter().map(|(n, s)| (n.to_string(), s.to_string())));
    let mut groups: Vec<(String, String)> = LIGHT_GROUPS
        .iter()
        .flat_map(|g| {
            BASIC
                .iter()
                .map(move |(n, _)| (format!("{n}_{g}"), format!("{n}_{g}")))
        })
        .collect();
    groups.extend(
        [
            ("floorDiffuse", "C<.D'floor'>.*[<L.>O]"),
            ("glassAnywhere", "C.*<.S'glass'>.*[<L.>O]"),
            ("directNotFloor", "C<RD[^'floor']>[<L.>O]"),
            ("notGlassToLight", "C[^'glass']+<L.>"),
        ]
        .map(|(n, s)| (n.to_string(), s.to_string())),
    );
    let mut per_lobe = own(&PER_LOBE);
    per_lobe.extend(own(&BASIC[6..]));
    vec![
        Workload {
            name: "basic",
            about: "the 7 basic AOVs",
            aovs: own(&BASIC),
        },
        Workload {
            name: "per-lobe",
            about: "the 16 per-lobe AOVs + emissive",
            aovs: per_lobe,
        },
        Workload {
            name: "groups",
            about: "basic x 4 light groups + lpegroup and negated-label AOVs (32)",
            aovs: named(groups),
        },
        Workload {
            name: "nested",
            about: "nested counted repetition near the limits",
            aovs: own(&[
                ("nested16", "C(.{0,16}){0,16}[<L.>O]"),
                ("nestedLobes", "C((<RD>|<RS>){1,3}.{0,4}){2,6}[<L.>O]"),
            ]),
        },
        Workload {
            name: "blowup12",
            about: "C.*D.{12}[LO]: 2^13 DFA states",
            aovs: own(&[("blowup12", "C.*D.{12}[LO]")]),
        },
        Workload {
            name: "blowup20",
            about: "C.*D.{20}[LO]: over every DFA budget, NFA fallback",
            aovs: own(&[("blowup20", "C.*D.{20}[LO]")]),
        },
        Workload {
            name: "wide",
            about: "a set of 1 437 NFA positions (a fuzzer's find): lazy DFA of any width",
            aovs: own(&[(
                "wide",
                "C((('fill'[^<T[^D2US]'fill'>R])U1)|(.[O<..'a b'>])*|\
                 U6((<.[^DD]'floor'><[^R].>){1,238}){1,3})'floor'L",
            )]),
        },
    ]
}
