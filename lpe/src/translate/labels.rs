//! The labels an expression mentions: what the correspondence's universe needs to tell
//! vertices apart.

use std::collections::BTreeSet;

use crate::osl::{self, Symbol};
use crate::renderman::Lpe;

/// Every label a RenderMan expression names (`'g'`, and in triples' label positions).
pub fn renderman(e: &Lpe) -> BTreeSet<String> {
    e.operands().iter().flat_map(|op| op.labels()).collect()
}

/// Every label an OSL expression's vertex patterns name, in any slot.
pub fn osl(e: &osl::Lpe) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for op in e.operands() {
        op.for_each_vertex(&mut |v| {
            for p in &v.symbols {
                out.extend(p.symbols().iter().filter_map(|s| match s {
                    Symbol::Label(l) => Some(l.clone()),
                    Symbol::None => None,
                }));
            }
        });
    }
    out
}
