//! `AovSet` on OSL expressions against a direct matcher written here from the vertex
//! semantics (docs/language.md §18): random expression texts and random vertex
//! sequences, both stepping modes, and the parser's own properties (no panic, printing
//! parses back to the same tree).

use std::collections::BTreeSet;

use lpe::osl::{self, Expr, Path, Registered, Symbol, Vertex};
use lpe::{AovSet, Options};
use lpe_tests::cases;
use proptest::prelude::*;

/// End positions reachable by matching `e` from vertex `i` of `path`.
fn ends(e: &Expr, path: &[Vertex], i: usize) -> BTreeSet<usize> {
    match e {
        Expr::Vertex(p) => path
            .get(i)
            .filter(|v| p.accepts(&v.symbols))
            .map(|_| i + 1)
            .into_iter()
            .collect(),
        Expr::Concat(es) => es.iter().fold(BTreeSet::from([i]), |from, e| {
            from.iter().flat_map(|&j| ends(e, path, j)).collect()
        }),
        Expr::Alt(es) => es.iter().flat_map(|e| ends(e, path, i)).collect(),
        Expr::Repeat(body, r) => {
            let mut out = BTreeSet::new();
            let mut cur = BTreeSet::from([i]);
            let mut seen = BTreeSet::new();
            let mut k = 0u32;
            loop {
                if k >= r.min {
                    out.extend(cur.iter().copied());
                }
                if r.max.is_some_and(|m| k >= m) || cur.is_empty() {
                    break;
                }
                // Past `min`, an unbounded repeat only needs new positions.
                if r.max.is_none() && k >= r.min {
                    cur.retain(|j| seen.insert(*j));
                    if cur.is_empty() {
                        break;
                    }
                }
                cur = cur.iter().flat_map(|&j| ends(body, path, j)).collect();
                k += 1;
            }
            out
        }
        Expr::Empty => BTreeSet::from([i]),
        Expr::Nothing => BTreeSet::new(),
    }
}

fn direct_match(e: &Expr, p: &Path) -> bool {
    ends(e, &p.vertices, 0).contains(&p.len())
}

fn item() -> impl Strategy<Value = String> {
    let leaves = prop::sample::select(vec![
        "C",
        "L",
        "R",
        "T",
        "B",
        "O",
        "V",
        "D",
        "G",
        "S",
        "s",
        "U",
        "Y",
        ".",
        "'a'",
        "'b'",
        "[^D]",
        "[^'a']",
        "[^RT]",
        "[^RD]",
        "<RD>",
        "<R[GS]>",
        "<.x>",
        "<Cx>",
        "<x.>",
        "<RDa>",
        "<R.'a'b>",
        "<(RD)>",
        "<RD12345>",
        "<..a[^'b']>",
        "[]",
        "<[^L]D>",
    ]);
    leaves
        .prop_map(str::to_string)
        .prop_recursive(4, 24, 4, |inner| {
            prop_oneof![
                (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("{a}{b}")),
                (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("{a}|{b}")),
                inner.clone().prop_map(|a| format!("({a})")),
                (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("[{a}{b}]")),
                (
                    inner,
                    prop::sample::select(vec![
                        "*", "+", "{2}", "{0,1}", "{1,3}", "{2,}", "{0}", "{3,1}"
                    ])
                )
                    .prop_map(|(a, q)| format!("({a}){q}")),
            ]
        })
}

fn vertex() -> impl Strategy<Value = Vertex> {
    let sym = |pool: Vec<&'static str>| {
        prop::sample::select(pool).prop_map(|s| {
            if s == "~" {
                Symbol::None
            } else {
                Symbol::label(s)
            }
        })
    };
    (
        sym(vec!["C", "L", "R", "T", "B", "O", "U", "~"]),
        prop::option::weighted(0.95, sym(vec!["D", "G", "S", "s", "_", "~", "Y"])),
        prop::collection::vec(
            sym(vec!["a", "b", "1", "2", "3", "4", "5", "zz", "D", "U"]),
            0..7,
        ),
    )
        .prop_map(|(e, s, custom)| {
            let mut symbols = vec![e];
            if let Some(s) = s {
                symbols.push(s);
                symbols.extend(custom);
            }
            Vertex::new(symbols)
        })
}

fn registered() -> impl Strategy<Value = Registered> {
    prop::sample::select(vec!["-", "events=U", "events=U;scatters=Y"])
        .prop_map(|s| s.parse().unwrap())
}

proptest! {
    #![proptest_config(cases(512))]

    #[test]
    fn aov_set_matches_like_the_direct_matcher(
        srcs in prop::collection::vec(item(), 1..4),
        reg in registered(),
        paths in prop::collection::vec(prop::collection::vec(vertex(), 0..7), 1..24),
    ) {
        let aovs: Vec<(String, osl::Lpe)> = srcs
            .iter()
            .filter_map(|s| osl::parse(s, &reg).ok().map(|l| (s.clone(), l)))
            .collect();
        prop_assume!(!aovs.is_empty());
        let nfa = Options { dfa_budget: 0, ..Options::default() };
        for opts in [Options::default(), nfa] {
            let set = AovSet::compile_under(&aovs, &reg, &opts).unwrap();
            for vs in &paths {
                let p = Path::new(vs.clone());
                let got = set.match_path(&p);
                for (i, (src, l)) in aovs.iter().enumerate() {
                    prop_assert_eq!(
                        got.contains(i),
                        direct_match(&l.expr, &p),
                        "`{}` [{}] on `{}` (dfa: {})", src, reg, p, set.uses_dfa()
                    );
                }
            }
        }
    }

    #[test]
    fn parsing_never_panics_and_printing_parses_back(
        src in item(),
        noise in "[CRDLGx.'<>()\\[\\]^&|*+{},0-9 -]{0,12}",
        reg in registered(),
    ) {
        for text in [src.clone(), format!("{src}{noise}"), noise.clone()] {
            if let Ok(l) = osl::parse(&text, &reg) {
                let printed = l.to_string();
                let again = osl::parse(&printed, &reg)
                    .map_err(|e| TestCaseError::fail(format!("`{text}` -> `{printed}`: {e}")))?;
                prop_assert_eq!(&again.expr, &l.expr, "`{}` -> `{}`", text, printed);
                prop_assert_eq!(&again.algebra, &l.algebra, "`{}` -> `{}`", text, printed);
            }
        }
    }
}
