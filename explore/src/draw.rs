//! The drawing of a [`Graph`]: laid out by `layout-rs` (graphviz's dot layering:
//! ranks, crossing reduction, Brandes-Köpf placement), written as SVG by `Canvas`,
//! this crate's backend for the library's draw calls, so that every state's shape and
//! every edge's path carry the ids the page highlights a trace by (`s3`, `e3-5`), text
//! is escaped, and the styling is inline (a notebook shows it without a style sheet).

use std::fmt::Write as _;

use layout::core::base::Orientation;
use layout::core::format::{ClipHandle, RenderBackend};
use layout::core::geometry::Point;
use layout::core::style::StyleAttr;
use layout::std_shapes::shapes::{Arrow, Element, ShapeKind};
use layout::topo::layout::VisualGraph;

use crate::automaton::Graph;

/// Size of a state's circle before the library fits its label.
const STATE_SIZE: f64 = 36.0;

/// Most layout nodes ([`layout_nodes`]) whose drawing gets the library's rank
/// optimization and edge-crossing reduction.
pub const CROSSING_LIMIT: usize = 200;

/// The font size of every text, state names and edge labels alike.
const FONT: f64 = 11.0;

/// The SVG of `graph`'s states and edges (the `graph` view keeps it to a few hundred
/// states). The start state is drawn with a thicker line, accepting states as double
/// circles; each shape has a `<title>` (the accepted AOVs, the edge's vertices) that
/// browsers show on hover.
pub fn svg(graph: &Graph) -> String {
    svg_with(graph, layout_nodes(graph))
}

/// [`svg`] of a graph the layout places `nodes` nodes for ([`layout_nodes`]).
pub fn svg_with(graph: &Graph, nodes: usize) -> String {
    let mut vg = visual(graph);
    let mut canvas = Canvas::default();
    // The crossing reduction (and the rank optimizer the flag also turns off) grows
    // much faster than the placement and dominates past a few hundred nodes (the
    // 193-state list of `cargo bench -p lpe-bench --bench explore`, 521 nodes, draws in
    // 30 ms without it); past the limit the drawing is read by hovering anyway.
    let skip_optimizations = nodes > CROSSING_LIMIT;
    vg.do_it(false, skip_optimizations, false, &mut canvas);
    canvas.finish()
}

/// The nodes the layout places for `graph`: its states, plus one connector per edge
/// label and per rank a long edge passes through (with the rank optimizer off). The
/// placement's time grows faster than the square of it, so the `graph` view draws no
/// more than a limit of them. Computed by the library's own lowering steps, the ones
/// `do_it` starts with, on a graph of its own.
pub fn layout_nodes(graph: &Graph) -> usize {
    let mut vg = visual(graph);
    vg.to_valid_dag();
    vg.split_text_edges();
    vg.split_long_edges(true);
    vg.num_nodes()
}

/// The library's graph of `graph`'s states and edges, not yet laid out.
fn visual(graph: &Graph) -> VisualGraph {
    let mut vg = VisualGraph::new(Orientation::LeftToRight);
    let handles: Vec<_> = graph
        .states
        .iter()
        .map(|s| {
            let name = s.id.as_str();
            let shape = if s.accepts.is_empty() {
                ShapeKind::new_circle(name)
            } else {
                ShapeKind::new_double_circle(name)
            };
            let mut look = StyleAttr::simple();
            look.line_width = if s.start { 3 } else { 1 };
            look.font_size = FONT as usize;
            let title = if s.accepts.is_empty() {
                s.id.clone()
            } else {
                format!("{}: {}", s.id, s.accepts.join(", "))
            };
            let element = Element::create_with_properties(
                shape,
                look,
                Orientation::LeftToRight,
                Point::splat(STATE_SIZE),
                Shape::State {
                    id: s.id.clone(),
                    title,
                }
                .encode(),
            );
            vg.add_node(element)
        })
        .collect();
    for e in &graph.edges {
        let (Some(a), Some(b)) = (index(&e.from), index(&e.to)) else {
            continue;
        };
        let (Some(&a), Some(&b)) = (handles.get(a), handles.get(b)) else {
            continue;
        };
        let mut arrow = Arrow::simple(&e.label);
        arrow.look.line_width = 1;
        arrow.look.font_size = FONT as usize;
        arrow.properties = Some(
            Shape::Edge {
                id: e.id.clone(),
                title: e.vertices.join(" | "),
            }
            .encode(),
        );
        vg.add_edge(arrow, a, b);
    }
    vg
}

/// The number of a state id `sN`.
fn index(id: &str) -> Option<usize> {
    id.strip_prefix('s')?.parse().ok()
}

/// What a shape handed to the library is, carried through its `properties` string (the
/// library passes it back untouched with the shape's draw call).
enum Shape {
    /// A state: its id and hover text.
    State { id: String, title: String },
    /// An edge: its id and hover text.
    Edge { id: String, title: String },
}

impl Shape {
    /// `kind`, `id` and `title`, separated by NUL (which no id or vertex text holds).
    fn encode(&self) -> String {
        match self {
            Shape::State { id, title } => format!("state\0{id}\0{title}"),
            Shape::Edge { id, title } => format!("edge\0{id}\0{title}"),
        }
    }

    fn decode(s: &str) -> Option<Shape> {
        let mut parts = s.splitn(3, '\0');
        let (kind, id, title) = (parts.next()?, parts.next()?, parts.next()?);
        let (id, title) = (id.to_string(), title.to_string());
        match kind {
            "state" => Some(Shape::State { id, title }),
            "edge" => Some(Shape::Edge { id, title }),
            _ => None,
        }
    }
}

/// Text made safe inside an SVG or HTML element or attribute.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if c.is_control() => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// The library's draw calls written as SVG elements, with the extent they cover.
#[derive(Default)]
struct Canvas {
    body: String,
    /// Labels, written after every shape so that no edge crosses over them.
    labels: String,
    width: f64,
    height: f64,
}

impl Canvas {
    /// Widens the extent to cover `p` plus `margin`.
    fn cover(&mut self, p: Point, margin: f64) {
        self.width = self.width.max(p.x + margin);
        self.height = self.height.max(p.y + margin);
    }

    /// The whole document.
    fn finish(self) -> String {
        let (w, h) = (self.width.ceil() + 5.0, self.height.ceil() + 5.0);
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"lpe-graph\" width=\"{w}\" \
             height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"monospace\">\
             <defs><marker id=\"lpe-arrow\" markerWidth=\"10\" markerHeight=\"7\" refX=\"10\" \
             refY=\"3.5\" orient=\"auto\"><polygon points=\"0 0, 10 3.5, 0 7\" \
             fill=\"context-stroke\"/></marker></defs>\n{}{}</svg>",
            self.body, self.labels
        )
    }
}

impl RenderBackend for Canvas {
    fn draw_rect(
        &mut self,
        xy: Point,
        size: Point,
        look: &StyleAttr,
        _properties: Option<String>,
        _clip: Option<ClipHandle>,
    ) {
        self.cover(xy.add(size), 0.0);
        let _ = writeln!(
            self.body,
            "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"none\" \
             stroke=\"{}\"/>",
            xy.x,
            xy.y,
            size.x,
            size.y,
            look.line_color.to_web_color()
        );
    }

    fn draw_line(&mut self, start: Point, stop: Point, look: &StyleAttr, _: Option<String>) {
        self.cover(start, 0.0);
        self.cover(stop, 0.0);
        let _ = writeln!(
            self.body,
            "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"{}\"/>",
            start.x,
            start.y,
            stop.x,
            stop.y,
            look.line_color.to_web_color()
        );
    }

    fn draw_circle(
        &mut self,
        xy: Point,
        size: Point,
        look: &StyleAttr,
        properties: Option<String>,
    ) {
        self.cover(xy, size.x.max(size.y) / 2.0);
        let (rx, ry) = (size.x / 2.0, size.y / 2.0);
        // The outer ring of an accepting state comes without properties.
        let (id, class, title) = match properties.as_deref().and_then(Shape::decode) {
            Some(Shape::State { id, title }) => (
                format!(" id=\"{}\"", escape(&id)),
                "state",
                format!("<title>{}</title>", escape(&title)),
            ),
            _ => (String::new(), "ring", String::new()),
        };
        let fill = if class == "state" { "white" } else { "none" };
        let _ = writeln!(
            self.body,
            "<ellipse{id} class=\"{class}\" cx=\"{:.1}\" cy=\"{:.1}\" rx=\"{rx:.1}\" \
             ry=\"{ry:.1}\" fill=\"{fill}\" stroke=\"black\" stroke-width=\"{}\">{title}</ellipse>",
            xy.x, xy.y, look.line_width
        );
    }

    fn draw_text(&mut self, xy: Point, text: &str, _look: &StyleAttr) {
        if text.is_empty() {
            return;
        }
        self.cover(xy, 0.0);
        // One size for every text: the library gives the connectors it adds to long
        // edges its default font, which would make some labels larger than others. A
        // white box under the text keeps it readable where its edge runs through it
        // (a monospace character is 0.6 of the font size wide).
        let width = text.chars().count() as f64 * 0.6 * FONT + 4.0;
        let height = FONT + 4.0;
        let _ = writeln!(
            self.labels,
            "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{width:.1}\" height=\"{height:.1}\" \
             fill=\"white\"/><text x=\"{:.1}\" y=\"{:.1}\" font-size=\"{FONT}\" \
             text-anchor=\"middle\" dominant-baseline=\"central\">{}</text>",
            xy.x - width / 2.0,
            xy.y - height / 2.0,
            xy.x,
            xy.y,
            escape(text)
        );
    }

    fn draw_arrow(
        &mut self,
        path: &[(Point, Point)],
        dashed: bool,
        head: (bool, bool),
        look: &StyleAttr,
        properties: Option<String>,
        _text: &str,
    ) {
        // No text: the library moves every edge's label onto a connector node of its own
        // before drawing (`VisualGraph::split_text_edges`), drawn by `draw_text`.
        // A path is an exit vector then entry vectors: a cubic Bézier, then smooth
        // continuations through each point (the library's own SVG backend reads it so).
        let [first, second, rest @ ..] = path else {
            return;
        };
        for p in path {
            self.cover(p.0, 0.0);
            self.cover(p.1, 0.0);
        }
        let mut d = format!(
            "M {:.1} {:.1} C {:.1} {:.1}, {:.1} {:.1}, {:.1} {:.1}",
            first.0.x,
            first.0.y,
            first.1.x,
            first.1.y,
            second.0.x,
            second.0.y,
            second.1.x,
            second.1.y
        );
        for p in rest {
            let _ = write!(d, " S {:.1} {:.1}, {:.1} {:.1}", p.0.x, p.0.y, p.1.x, p.1.y);
        }
        let (id, title) = match properties.as_deref().and_then(Shape::decode) {
            Some(Shape::Edge { id, title }) => (
                format!(" id=\"{}\"", escape(&id)),
                format!("<title>{}</title>", escape(&title)),
            ),
            _ => (String::new(), String::new()),
        };
        let dash = if dashed {
            " stroke-dasharray=\"5,5\""
        } else {
            ""
        };
        let end = if head.1 {
            " marker-end=\"url(#lpe-arrow)\""
        } else {
            ""
        };
        let _ = writeln!(
            self.body,
            "<path{id} class=\"edge\" d=\"{d}\" fill=\"none\" stroke=\"{}\" \
             stroke-width=\"{}\"{dash}{end}>{title}</path>",
            look.line_color.to_web_color(),
            look.line_width
        );
    }

    fn create_clip(&mut self, _xy: Point, _size: Point, _rounded_px: usize) -> ClipHandle {
        // Only record shapes clip, and the drawing has none.
        0
    }
}
