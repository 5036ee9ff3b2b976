//! A figure laid out once, as a list of shapes and texts on a canvas ([`Drawing`]), then written
//! as SVG ([`Drawing::svg`]) or PDF ([`super::pdf`]). Both outputs place every item where the
//! layout put it, so a check of the layout (every text inside the canvas, measured with the
//! figures' font) holds for each; the page's PNG is the SVG drawn at twice its size.

use std::fmt::Write;

use super::text::{self, ASCENT, DESCENT};

/// Where a text's `x` is: its start, middle or end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    Start,
    Middle,
    End,
}

/// One line of text. A rotated text reads upwards (turned a quarter left about `x`, `y`).
#[derive(Clone, Debug, PartialEq)]
pub struct Text {
    pub x: f64,
    pub y: f64,
    pub size: f64,
    pub bold: bool,
    pub anchor: Anchor,
    pub fill: &'static str,
    pub text: String,
    pub rotated: bool,
}

impl Text {
    /// The box the text covers on the canvas, `[left, top, right, bottom]`, its width measured
    /// with the figures' font (an upper bound of what any of its faces draws).
    pub fn bounds(&self) -> [f64; 4] {
        let w = text::width(&self.text, self.size, self.bold);
        let before = match self.anchor {
            Anchor::Start => 0.0,
            Anchor::Middle => w / 2.0,
            Anchor::End => w,
        };
        let (up, down) = (ASCENT * self.size, DESCENT * self.size);
        match self.rotated {
            // Turned a quarter left: the text runs upwards from (x, y + before).
            true => [
                self.x - up,
                self.y - (w - before),
                self.x + down,
                self.y + before,
            ],
            false => [
                self.x - before,
                self.y - up,
                self.x + (w - before),
                self.y + down,
            ],
        }
    }
}

/// A shape or a text of a figure.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    Text(Text),
    Line {
        from: (f64, f64),
        to: (f64, f64),
        stroke: &'static str,
        /// SVG `data-*` attributes the page's tests read, written as is (empty: none).
        data: String,
    },
    Rect {
        x: f64,
        y: f64,
        w: f64,
        h: f64,
        fill: &'static str,
        data: String,
    },
    /// A filled polygon at 15% opacity: a spread's band.
    Band {
        points: Vec<(f64, f64)>,
        fill: &'static str,
    },
    Polyline {
        points: Vec<(f64, f64)>,
        stroke: &'static str,
    },
    Circle {
        at: (f64, f64),
        r: f64,
        fill: &'static str,
        data: String,
    },
    /// The items up to the matching [`Item::End`] draw one series (`data-series` in SVG).
    Group(String),
    End,
}

/// A laid-out figure: its canvas, its title and description (the SVG's `title` and `desc`), and
/// what is drawn in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawing {
    pub width: f64,
    pub height: f64,
    pub title: String,
    pub desc: String,
    pub items: Vec<Item>,
}

/// Text for SVG: `&`, `<`, `>` and `"` escaped.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

impl Drawing {
    /// Adds one line of text.
    #[allow(clippy::too_many_arguments)]
    pub fn text(
        &mut self,
        x: f64,
        y: f64,
        size: f64,
        bold: bool,
        anchor: Anchor,
        fill: &'static str,
        text: impl Into<String>,
    ) {
        self.items.push(Item::Text(Text {
            x,
            y,
            size,
            bold,
            anchor,
            fill,
            text: text.into(),
            rotated: false,
        }));
    }

    pub fn line(&mut self, from: (f64, f64), to: (f64, f64), stroke: &'static str) {
        self.items.push(Item::Line {
            from,
            to,
            stroke,
            data: String::new(),
        });
    }

    /// The texts of the drawing.
    pub fn texts(&self) -> impl Iterator<Item = &Text> {
        self.items.iter().filter_map(|i| match i {
            Item::Text(t) => Some(t),
            _ => None,
        })
    }

    /// The drawing as a standalone SVG document.
    pub fn svg(&self) -> String {
        let (w, h) = (self.width, self.height);
        let mut out = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"{}\" role=\"img\">\n<title>{}</title>\n<desc>{}</desc>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n",
            escape(text::FAMILY),
            escape(&self.title),
            escape(&self.desc)
        );
        for item in &self.items {
            svg_item(&mut out, item);
        }
        out.push_str("</svg>\n");
        out
    }
}

fn points(list: &[(f64, f64)]) -> String {
    list.iter()
        .map(|(x, y)| format!("{x:.1},{y:.1}"))
        .collect::<Vec<_>>()
        .join(" ")
}

fn svg_item(out: &mut String, item: &Item) {
    let _ = match item {
        Item::Text(t) => {
            let anchor = match t.anchor {
                Anchor::Start => "",
                Anchor::Middle => " text-anchor=\"middle\"",
                Anchor::End => " text-anchor=\"end\"",
            };
            let weight = if t.bold { " font-weight=\"bold\"" } else { "" };
            let turn = match t.rotated {
                true => format!(" transform=\"rotate(-90 {:.1} {:.1})\"", t.x, t.y),
                false => String::new(),
            };
            writeln!(
                out,
                "<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"{}\"{weight}{anchor} fill=\"{}\"{turn}>{}</text>",
                t.x,
                t.y,
                t.size,
                t.fill,
                escape(&t.text)
            )
        }
        Item::Line {
            from,
            to,
            stroke,
            data,
        } => writeln!(
            out,
            "<line x1=\"{:.1}\" x2=\"{:.1}\" y1=\"{:.1}\" y2=\"{:.1}\" stroke=\"{stroke}\"{data}/>",
            from.0, to.0, from.1, to.1
        ),
        Item::Rect {
            x,
            y,
            w,
            h,
            fill,
            data,
        } => writeln!(
            out,
            "<rect x=\"{x:.1}\" y=\"{y:.1}\" width=\"{w:.1}\" height=\"{h:.1}\" fill=\"{fill}\"{data}/>"
        ),
        Item::Band { points: p, fill } => writeln!(
            out,
            "<polygon points=\"{}\" fill=\"{fill}\" fill-opacity=\"0.15\" stroke=\"none\"/>",
            points(p)
        ),
        Item::Polyline { points: p, stroke } => writeln!(
            out,
            "<polyline points=\"{}\" fill=\"none\" stroke=\"{stroke}\" stroke-width=\"2\"/>",
            points(p)
        ),
        Item::Circle { at, r, fill, data } => writeln!(
            out,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{r}\" fill=\"{fill}\"{data}/>",
            at.0, at.1
        ),
        Item::Group(label) => writeln!(out, "<g data-series=\"{}\">", escape(label)),
        Item::End => writeln!(out, "</g>"),
    };
}
