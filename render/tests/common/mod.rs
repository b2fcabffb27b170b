//! Fixtures and helpers the render tests share (each test binary uses some of them).
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

use lpe::renderman::{Config, Parser};
use lpe_render::aov::{AovList, SceneDialect};
use lpe_render::integrator::{self, Render, Settings};
use lpe_render::scene::Scene;

/// The RenderMan parser with the default macros.
pub fn parser() -> Parser {
    let c = Config::default();
    Parser::new(c.limits.clone(), c.macros.clone())
}

/// A built-in scene with the default lobe map.
pub fn scene(name: &str) -> Scene {
    Scene::load(name, &Config::default().lobes).unwrap()
}

/// A small square render on two threads.
pub fn small(w: usize, spp: u32, seed: u64) -> Settings {
    Settings {
        width: w,
        height: w,
        spp,
        seed,
        threads: Some(2),
        ..Settings::default()
    }
}

/// Renders `s` with `aovs` and the default lobe map.
pub fn render<D: SceneDialect>(s: &Scene, aovs: &AovList<D>, settings: &Settings) -> Render {
    integrator::render(s, aovs, &Config::default().lobes, settings).unwrap()
}

/// Runs `lpe-render` with `args`: its exit code and stderr.
pub fn run(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lpe-render"))
        .args(args)
        .output()
        .expect("binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Writes into `dir` a RenderMan display file with two channels (`key_name`, the light
/// group `key`, and `mine`, a user macro) and the `rendermn.ini` defining that macro
/// (`myDirect` = `C<RD>[<L.>O]`); returns their paths.
pub fn display_and_ini(dir: &Path, key_name: &str) -> (PathBuf, PathBuf) {
    let display = dir.join("display.rib");
    std::fs::write(
        &display,
        format!(
            "DisplayChannel \"color {key_name}\" \"string source\" [\"color lpe:C.*<L.'key'>\"]\n\
             DisplayChannel \"color mine\" \"string source\" [\"color lpe:myDirect\"]\n"
        ),
    )
    .unwrap();
    let ini = dir.join("rendermn.ini");
    std::fs::write(&ini, "/prman/lpe/macro/myDirect C<RD>[<L.>O]\n").unwrap();
    (display, ini)
}
