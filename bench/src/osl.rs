//! The OSL rows of the benchmark: the OSL basic set on the sampled paths written as OSL
//! paths, stepped on classes like the RenderMan basic set, and timed round-robin with
//! it so that the ratio between the two is measured under the same load.
//!
//! A RenderMan vertex becomes the OSL vertex a renderer would feed: event (`C`, `R`,
//! `T`, `L`, `O`), scattering (diffuse lobes `D`, rough specular lobes `G`, the glass
//! and mirror lobes `S`, user lobes `U`, `_` on camera and emitters), then its
//! lpegroup or light group as a custom label.

use std::time::{Duration, Instant};

use lpe::osl::{self, Registered, Symbol};
use lpe::renderman::{EventKind, Path, VertexType};
use lpe::{AovMask, AovSet, Options};

use crate::harness::{
    best_times, chunked, classify, row, run_classes, BenchError, Config, Disagreement, Job, Row,
};
use crate::workload;

/// The workload name, as given to `--workload`.
pub const WORKLOAD: &str = "osl-basic";

/// OSL's ReDoS expression (OSL's matcher builds 90 192 DFA states from its 475 NFA
/// states).
const REDOS: &str = "C(R('a'+|G[^S]{2}[^OC]){2,}|(L|T*[sBO]{2,})+)";

/// The OSL vertex a renderer feeds for `v`.
pub fn vertex(v: &lpe::renderman::Vertex) -> osl::Vertex {
    let event = match v.ty() {
        VertexType::C => "C",
        VertexType::R => "R",
        VertexType::T => "T",
        VertexType::L => "L",
        VertexType::O => "O",
    };
    let scattering = match v.event() {
        None => "_",
        Some(e) => match (e.kind(), e.lobe()) {
            (EventKind::D, _) => "D",
            (EventKind::S, 7 | 8) => "S",
            (EventKind::S, _) => "G",
            (EventKind::U, _) => "U",
        },
    };
    let mut symbols = vec![Symbol::label(event), Symbol::label(scattering)];
    symbols.extend(v.label().map(Symbol::label));
    osl::Vertex::new(symbols)
}

/// `p` as an OSL path.
pub fn path(p: &Path) -> osl::Path {
    osl::Path::new(p.vertices().iter().map(vertex).collect())
}

/// The OSL reference's answers, one AOV at a time.
fn reference_mask(aovs: &[(String, osl::Lpe)], p: &osl::Path) -> AovMask {
    let mut m = AovMask::EMPTY;
    for (i, (_, l)) in aovs.iter().enumerate() {
        if lpe_reference::lpe_tree::is_match(l, p) {
            m.insert(i);
        }
    }
    m
}

/// The OSL rows (when `cfg` names [`WORKLOAD`]), and the engines that disagree with
/// the OSL reference on the first `cfg.reference_paths` of `paths`.
pub fn run(cfg: &Config, paths: &[Path]) -> Result<(Vec<Row>, Vec<Disagreement>), BenchError> {
    if !cfg.runs(WORKLOAD) {
        return Ok((Vec::new(), Vec::new()));
    }
    let (reps, checked) = (cfg.reps, cfg.reference_paths.min(paths.len()));
    let reg = Registered::none();
    let aovs: Vec<(String, osl::Lpe)> = osl::BASIC
        .iter()
        .map(|(n, s)| {
            let l = osl::parse(s, &reg).unwrap_or_else(|e| panic!("OSL basic AOV `{s}`: {e}"));
            (n.to_string(), l)
        })
        .collect();
    let osl_paths: Vec<osl::Path> = paths.iter().map(path).collect();
    let vertices: usize = paths.iter().map(Path::len).sum();
    let compile = |opts: &Options| {
        AovSet::compile_under(&aovs, &reg, opts).map_err(|error| BenchError::Compile {
            workload: WORKLOAD,
            error,
        })
    };
    let fast = compile(&Options::default())?;
    let nfa = compile(&Options {
        dfa_budget: 0,
        ..Options::default()
    })?;
    // OSL's ReDoS expression, which OSL's own matcher takes minutes to compile: the
    // best of `reps` compiles.
    let redos_aovs = vec![(
        "redos".to_string(),
        osl::parse(REDOS, &reg).unwrap_or_else(|e| panic!("`{REDOS}`: {e}")),
    )];
    let mut redos_compile = Duration::MAX;
    let mut redos = None;
    for _ in 0..reps.max(1) {
        let t = Instant::now();
        let set =
            AovSet::compile_under(&redos_aovs, &reg, &Options::default()).map_err(|error| {
                BenchError::Compile {
                    workload: WORKLOAD,
                    error,
                }
            })?;
        redos_compile = redos_compile.min(t.elapsed());
        redos = Some(set);
    }
    let redos = redos.expect("compiled at least once");
    // Arnold's lobe AOVs, by name under Arnold's profile and written out without one:
    // a profile changes what an expression reads as, never what it compiles to.
    let (by_name, written) = arnold_lobes();
    let by_name = compile_set(&by_name, &by_name_registration())?;
    let written = compile_set(&written, &reg)?;
    let rm_aovs = workload::all()
        .into_iter()
        .find(|w| w.name == "basic")
        .expect("the RenderMan basic workload")
        .aovs;
    let rm = AovSet::compile(&rm_aovs).map_err(|error| BenchError::Compile {
        workload: "basic",
        error,
    })?;

    let mut bad = Vec::new();
    for (name, set, aovs) in [
        ("fast", &fast, &aovs),
        ("lazy", &nfa, &aovs),
        ("redos", &redos, &redos_aovs),
    ] {
        let wrong = osl_paths[..checked]
            .iter()
            .filter(|p| set.match_path(p) != reference_mask(aovs, p))
            .count();
        if wrong > 0 {
            bad.push(Disagreement {
                workload: WORKLOAD,
                engine: name.to_string(),
                paths: wrong,
            });
        }
    }

    let fast_classes = chunked(&osl_paths, |c| classify(&fast, c));
    let nfa_classes = chunked(&osl_paths, |c| classify(&nfa, c));
    let redos_classes = chunked(&osl_paths, |c| classify(&redos, c));
    let rm_classes = chunked(paths, |c| classify(&rm, c));
    let by_name_classes = chunked(&osl_paths, |c| classify(&by_name, c));
    let written_classes = chunked(&osl_paths, |c| classify(&written, c));
    let mut jobs: Vec<Job<'_>> = vec![
        Box::new(|c| run_classes(rm.automaton(), &rm_classes[c])),
        Box::new(|c| run_classes(fast.automaton(), &fast_classes[c])),
        Box::new(|c| run_classes(nfa.automaton(), &nfa_classes[c])),
        Box::new(|c| run_classes(redos.automaton(), &redos_classes[c])),
        Box::new(|c| run_classes(by_name.automaton(), &by_name_classes[c])),
        Box::new(|c| run_classes(written.automaton(), &written_classes[c])),
    ];
    let times = best_times(reps, fast_classes.len(), &mut jobs);
    drop(jobs);
    let ns = |d: Duration| d.as_secs_f64() * 1e9 / vertices as f64;
    let rm_ns = ns(times[0]);

    let mut rows = Vec::new();
    let mut r = row(WORKLOAD, "RenderMan basic, fast, on classes");
    r.ns_per_vertex = Some(rm_ns);
    r.note = "the peer of the OSL rows, timed round-robin with them".into();
    rows.push(r);
    for (engine, set, t) in [
        ("fast, on classes", &fast, times[1]),
        ("lazy DFA (dfa_budget 0), on classes", &nfa, times[2]),
    ] {
        let mut r = row(WORKLOAD, engine);
        r.ns_per_vertex = Some(ns(t));
        r.memory = Some(set.memory_bytes());
        let shape = match set.dfa_states() {
            Some(n) => format!("DFA, {n} states, {} classes", set.class_count()),
            None => format!("lazy DFA, {} positions", set.nfa_positions()),
        };
        r.note = format!("{shape}; {:.2}x the RenderMan basic set", ns(t) / rm_ns);
        rows.push(r);
    }
    let mut r = row(WORKLOAD, "OSL's ReDoS expression, fast, on classes");
    r.ns_per_vertex = Some(ns(times[3]));
    r.compile = Some(redos_compile);
    r.memory = Some(redos.memory_bytes());
    r.note = match redos.dfa_states() {
        Some(n) => format!("DFA, {n} states"),
        None => format!("lazy DFA, {} positions", redos.nfa_positions()),
    };
    rows.push(r);
    let mut r = row(
        WORKLOAD,
        "Arnold's lobe AOVs by name (--renderer arnold), fast",
    );
    r.ns_per_vertex = Some(ns(times[4]));
    r.note = format!(
        "{:.2}x the same expressions written out without a profile ({:.1} ns/vertex)",
        ns(times[4]) / ns(times[5]),
        ns(times[5])
    );
    rows.push(r);
    Ok((rows, bad))
}

/// Named OSL AOVs, as a set compiles them.
type OslAovs = Vec<(String, osl::Lpe)>;

/// Arnold's built-in lobe AOVs: by name, and as the expressions its profile defines.
fn arnold_lobes() -> (OslAovs, OslAovs) {
    const NAMES: [&str; 8] = [
        "diffuse",
        "specular",
        "coat",
        "transmission",
        "sss",
        "volume",
        "emission",
        "background",
    ];
    let by_name_reg = by_name_registration();
    let parse = |s: &str, reg: &Registered| {
        osl::parse(s, reg).unwrap_or_else(|e| panic!("Arnold's `{s}`: {e}"))
    };
    let by_name = NAMES
        .iter()
        .map(|n| (n.to_string(), parse(n, &by_name_reg)))
        .collect();
    let written = NAMES
        .iter()
        .map(|n| {
            let (_, expr) = by_name_reg
                .builtins
                .iter()
                .find(|(b, _)| b == n)
                .expect("a built-in of Arnold's profile");
            (n.to_string(), parse(expr, &Registered::none()))
        })
        .collect();
    (by_name, written)
}

/// Arnold's profile as an OSL registration.
fn by_name_registration() -> Registered {
    let arnold = lpe_profile::by_name("arnold").expect("a shipped profile");
    <osl::Osl as lpe_profile::ProfileDialect>::with_profile(arnold, Registered::none())
}

fn compile_set(
    aovs: &[(String, osl::Lpe)],
    reg: &Registered,
) -> Result<AovSet<osl::Osl>, BenchError> {
    AovSet::compile_under(aovs, reg, &Options::default()).map_err(|error| BenchError::Compile {
        workload: WORKLOAD,
        error,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertices_become_what_a_renderer_feeds() {
        let p: Path = "C RD2'floor' RS3 TS8'glass' RU2 L'key'".parse().unwrap();
        assert_eq!(
            path(&p).to_string(),
            "C,_ R,D,floor R,G T,S,glass R,U L,_,key"
        );
    }

    #[test]
    fn the_osl_basic_set_routes_like_the_renderman_basic_set() {
        // Both basic sets split every sampled path the same way (AOV i of one is AOV i
        // of the other), so the two rows time the same routing work.
        let reg = Registered::none();
        let osl_aovs: Vec<(String, osl::Lpe)> = osl::BASIC
            .iter()
            .map(|(n, s)| (n.to_string(), osl::parse(s, &reg).unwrap()))
            .collect();
        let osl_set = AovSet::compile_under(&osl_aovs, &reg, &Options::default()).unwrap();
        let rm_aovs: Vec<(String, lpe::renderman::Lpe)> = lpe::renderman::macros::BASIC
            .iter()
            .map(|(n, s)| (n.to_string(), lpe::renderman::parse(s).unwrap()))
            .collect();
        let rm_set = AovSet::compile(&rm_aovs).unwrap();
        for p in crate::sample::paths(20_000, 3) {
            if p.vertices()
                .iter()
                .any(|v| v.event().is_some_and(|e| e.kind() == EventKind::U))
            {
                continue; // user lobes: RenderMan's `.` excludes them, OSL's does not
            }
            assert_eq!(osl_set.match_path(&path(&p)), rm_set.match_path(&p), "{p}");
        }
    }

    #[test]
    fn arnolds_lobes_by_name_route_like_the_expressions_written_out() {
        // The benchmark's last row times the two against each other: they must be the
        // same set, AOV for AOV, on every sampled path.
        let (by_name, written) = arnold_lobes();
        let by_name = compile_set(&by_name, &by_name_registration()).unwrap();
        let written = compile_set(&written, &Registered::none()).unwrap();
        let mut matched = 0;
        for p in crate::sample::paths(5_000, 7) {
            let p = path(&p);
            let m = by_name.match_path(&p);
            assert_eq!(m, written.match_path(&p), "{p}");
            matched += usize::from(m != AovMask::EMPTY);
        }
        // Sampled paths are RenderMan's: glossy lobes are `G`, which no Arnold lobe AOV asks
        // for; still a good share lands in one.
        assert!(matched > 500, "{matched}");
    }
}
