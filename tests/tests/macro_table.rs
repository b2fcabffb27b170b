//! The macro table as a value: the built-in table lists RenderMan's 29 macros in the
//! documented order, the empty table has none, and a redefinition (any case) replaces
//! the old entry and leaves every other one in place. Expected names and sources are
//! copied from docs/language.md §6.1, not read back from the table.

use lpe::renderman::macros::MacroTable;

#[test]
fn the_builtin_table_lists_every_macro_in_order() {
    let t = MacroTable::builtin();
    let names: Vec<&str> = t.names().collect();
    assert_eq!(names.len(), 29);
    assert_eq!(names[0], "directDiffuse");
    assert_eq!(names[6], "emissive");
    assert_eq!(names[7], "directDiffuseLobe");
    assert_eq!(names[22], "indirectSpecularGlassLobe");
    assert_eq!(names[23], "transmissiveGlassLobe");
    assert_eq!(names[28], "shadowcollector");
    let pairs: Vec<(&str, &str)> = t.iter().collect();
    assert_eq!(pairs.len(), 29);
    assert_eq!(pairs[0], ("directDiffuse", "C<RD>[<L.>O]"));
    assert_eq!(pairs[24], ("diffuse", "CD<L.>"));
    assert_eq!(
        pairs[28],
        (
            "shadowcollector",
            "shadows;C[<.D'collector'><.S'collector'>]<L.>"
        )
    );
    assert_eq!(t.get("EMISSION"), Some("CO"));
    assert_eq!(t.get("caustics"), Some("CDS+[<L.>O]"));
    assert_eq!(t.get("nosuchmacro"), None);
    assert_eq!(MacroTable::default(), t);
}

#[test]
fn the_empty_table_has_no_macros() {
    let t = MacroTable::empty();
    assert_eq!(t.names().count(), 0);
    assert_eq!(t.iter().count(), 0);
    assert_eq!(t.get("diffuse"), None);
    assert_ne!(t, MacroTable::builtin());
}

#[test]
fn a_redefinition_replaces_only_its_own_entry() {
    let mut t = MacroTable::builtin();
    t.define("DIFFUSE", "CD+L");
    assert_eq!(t.names().count(), 29);
    assert_eq!(t.get("diffuse"), Some("CD+L"));
    // The new definition goes last; the others keep their order.
    let names: Vec<&str> = t.names().collect();
    assert_eq!(names[28], "DIFFUSE");
    assert_eq!(names[23], "transmissiveGlassLobe");
    assert_eq!(names[24], "specular");
    assert_eq!(t.get("specular"), Some("CS<L.>"));

    let mut e = MacroTable::empty();
    e.define("key", "C<L.'key'>");
    e.define("fill", "C<L.'fill'>");
    e.define("Key", "CD<L.'key'>");
    assert_eq!(
        e.iter().collect::<Vec<_>>(),
        [("fill", "C<L.'fill'>"), ("Key", "CD<L.'key'>")]
    );
}
