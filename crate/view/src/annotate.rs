//! The annotation layer, drawn with Canvas 2D over either renderer: bonds, gradient arrows, cell
//! labels, the cells whose code the legend marks, the last step's events, displaced units, signals, highlighted cells, the hovered cell
//! and the keyboard cursor; in 3-D, the values of reachable cells. Only what is visible and large
//! enough to read is drawn.

use crate::camera::{Camera2D, Camera3D};
use crate::geometry::{hex_corners, HEX_RADIUS};
use crate::scene::{CursorKind, SceneRef};
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::CellMark;
use std::f64::consts::TAU;
use web_sys::OffscreenCanvasRenderingContext2d as Ctx;

/// Above this many cells in view, per-cell annotations are left out.
const MAX_VISIBLE: u64 = 40_000;

/// Draws the planar annotations on a clear context scaled to CSS pixels. Returns whether it drew
/// anything, so the canvas is cleared (and handed to the compositor) only after it did.
pub fn planar(ctx: &Ctx, scene: &SceneRef, cam: &Camera2D) -> bool {
    let mut drew = false;
    let grid = &scene.grid;
    let state = &scene.state;
    let marks = scene.marks;
    let w = grid.dims[0] as usize;
    let range = cam.visible_cells(grid);
    let count = range.map_or(0, |[x0, x1, y0, y1]| {
        u64::from(x1 - x0 + 1) * u64::from(y1 - y0 + 1)
    });
    let in_view = |f: &mut dyn FnMut(usize)| {
        if let Some([x0, x1, y0, y1]) = range {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    f(y as usize * w + x as usize);
                }
            }
        }
    };
    let centre = |i: usize| {
        let [x, y] = grid.centre(i);
        cam.to_screen(x, y)
    };

    if !state.bonds.is_empty() && cam.scale >= 7.0 && count <= MAX_VISIBLE {
        // Each bond once, from the lower-numbered cell, as a connector across the shared edge,
        // clear of the labels at the centres.
        drew = true;
        ctx.set_stroke_style_str("rgba(20,26,33,0.85)");
        ctx.set_line_width((cam.scale * 0.14).max(1.5));
        ctx.set_line_cap("round");
        ctx.begin_path();
        in_view(&mut |i| {
            let mask = state.bonds.get(i).copied().unwrap_or(0);
            if mask == 0 {
                return;
            }
            let [ax, ay] = centre(i);
            for (d, j) in grid.neighbours(i).into_iter().enumerate() {
                let Some(j) = j.filter(|&j| j > i && mask & (1 << d) != 0) else {
                    continue;
                };
                let [bx, by] = centre(j);
                ctx.move_to(ax + (bx - ax) * 0.34, ay + (by - ay) * 0.34);
                ctx.line_to(bx - (bx - ax) * 0.34, by - (by - ay) * 0.34);
            }
        });
        ctx.stroke();
        ctx.set_line_cap("butt");
    }

    let field = state.overlay;
    let arrows = field.is_some_and(|o| {
        scene
            .layout
            .fields
            .iter()
            .any(|f| f.name == o.name && f.arrows)
    });
    if let (true, true, Some(field)) = (
        marks.arrows && arrows,
        cam.scale >= 12.0 && count <= MAX_VISIBLE,
        field,
    ) {
        drew = true;
        ctx.set_stroke_style_str("rgba(255,255,255,0.85)");
        ctx.set_fill_style_str("rgba(255,255,255,0.85)");
        ctx.set_line_width((cam.scale * 0.06).max(1.0));
        in_view(&mut |i| {
            let Some(&v) = field.data.get(i).filter(|v| !v.is_nan()) else {
                return;
            };
            let mut best = None;
            let mut best_v = v;
            for j in grid.neighbours(i).into_iter().flatten() {
                let u = field.data[j];
                if !u.is_nan() && u < best_v {
                    best_v = u;
                    best = Some(j);
                }
            }
            if let Some(j) = best {
                arrow(ctx, centre(i), centre(j), cam.scale);
            }
        });
    }

    if marks.labels && scene.layout.cell_labels && cam.scale >= 22.0 && count <= MAX_VISIBLE {
        drew = true;
        let mut names: Vec<Option<&str>> = vec![None; 256];
        for c in &scene.layout.cells {
            names[usize::from(c.code)] = Some(&c.name);
        }
        ctx.set_font(&format!(
            "600 {}px system-ui, sans-serif",
            (cam.scale * 0.32).min(16.0)
        ));
        ctx.set_text_align("center");
        ctx.set_text_baseline("middle");
        ctx.set_line_width(3.0);
        ctx.set_stroke_style_str("rgba(0,0,0,0.6)");
        ctx.set_fill_style_str("#fff");
        in_view(&mut |i| {
            let code = state.cells[i];
            let Some(name) = names[usize::from(code)].filter(|_| code != 0) else {
                return;
            };
            let [sx, sy] = centre(i);
            let _ = ctx.stroke_text(name, sx, sy);
            let _ = ctx.fill_text(name, sx, sy);
        });
    }

    // Cell codes the legend marks (an overload, a failure): a ring or a cross in the code's
    // colour over a light halo, so it shows on the cell's own colour and on any heat map.
    let marked: Vec<_> = scene
        .layout
        .cells
        .iter()
        .filter_map(|c| c.mark.map(|m| (c.code, m, c.color.as_str())))
        .collect();
    if !marked.is_empty() && count <= MAX_VISIBLE {
        let mut at: Vec<Vec<[f64; 2]>> = vec![Vec::new(); marked.len()];
        in_view(&mut |i| {
            let code = state.cells[i];
            if let Some(k) = marked.iter().position(|m| m.0 == code && code != 0) {
                at[k].push(centre(i));
            }
        });
        let r = (cam.scale * 0.3).max(2.5);
        let width = (cam.scale * 0.08).max(1.5);
        for ((_, mark, colour), points) in marked.iter().zip(&at) {
            if points.is_empty() {
                continue;
            }
            drew = true;
            ctx.begin_path();
            for &[x, y] in points {
                match mark {
                    CellMark::Ring => {
                        ctx.move_to(x + r, y);
                        let _ = ctx.arc(x, y, r, 0.0, TAU);
                    }
                    CellMark::Cross => {
                        ctx.move_to(x - r, y - r);
                        ctx.line_to(x + r, y + r);
                        ctx.move_to(x + r, y - r);
                        ctx.line_to(x - r, y + r);
                    }
                }
            }
            ctx.set_line_cap("round");
            ctx.set_stroke_style_str("rgba(255,255,255,0.92)");
            ctx.set_line_width(width + 2.5);
            ctx.stroke();
            ctx.set_stroke_style_str(colour);
            ctx.set_line_width(width);
            ctx.stroke();
            ctx.set_line_cap("butt");
        }
    }

    if !state.events.is_empty() {
        // One path per kind: a large run has hundreds of events a step.
        drew = true;
        let radius = (cam.scale * 0.48).max(4.0);
        ctx.set_line_width((cam.scale * 0.1).max(1.5));
        for kind in &scene.layout.events {
            ctx.set_stroke_style_str(&kind.color);
            ctx.begin_path();
            for e in state.events.iter().filter(|e| e.kind == kind.code) {
                let [sx, sy] = centre(e.cell as usize);
                if sx < -radius
                    || sy < -radius
                    || sx > cam.width + radius
                    || sy > cam.height + radius
                {
                    continue;
                }
                ctx.move_to(sx + radius, sy);
                let _ = ctx.arc(sx, sy, radius, 0.0, TAU);
            }
            ctx.stroke();
        }
    }

    if !marks.displaced.is_empty() && scene.layout.lattice == LatticeKind::Square {
        // The deflected shape: each unit's square moved by its (scaled) displacement.
        drew = true;
        ctx.set_fill_style_str("rgba(43,149,214,0.28)");
        ctx.set_stroke_style_str("rgba(16,107,163,0.9)");
        ctx.set_line_width(1.0);
        let side = cam.scale * 0.9;
        for d in marks.displaced.chunks_exact(3) {
            let [wx, wy] = grid.centre(d[0] as usize);
            let [sx, sy] = cam.to_screen(wx + d[1], wy + d[2]);
            ctx.fill_rect(sx - side / 2.0, sy - side / 2.0, side, side);
            ctx.stroke_rect(sx - side / 2.0, sy - side / 2.0, side, side);
        }
    }

    if !marks.signals.is_empty() {
        drew = true;
        ctx.set_stroke_style_str("rgba(240,180,41,0.95)");
        ctx.set_fill_style_str("rgba(240,180,41,0.95)");
        ctx.set_line_width((cam.scale * 0.08).max(1.5));
        let radius = (cam.scale * 0.3).max(3.0);
        for s in marks.signals.chunks_exact(2) {
            let (i, faces) = (s[0] as usize, s[1]);
            let from = centre(i);
            if faces == 0 {
                ctx.begin_path();
                let _ = ctx.arc(from[0], from[1], radius, 0.0, TAU);
                ctx.stroke();
                continue;
            }
            for (d, j) in grid.neighbours(i).into_iter().enumerate() {
                let Some(j) = j.filter(|_| faces & (1 << d) != 0) else {
                    continue;
                };
                // An arrow from the sender's centre toward the face it lights.
                let to = centre(j);
                arrow(
                    ctx,
                    [(from[0] * 2.0 + to[0]) / 3.0, (from[1] * 2.0 + to[1]) / 3.0],
                    to,
                    cam.scale,
                );
            }
        }
    }

    for &i in &marks.highlight {
        drew |= outline(ctx, scene, cam, i, "rgba(240,180,41,0.95)", 2.0);
    }
    if let Some(i) = marks.hover {
        drew |= outline(ctx, scene, cam, i, "rgba(255,255,255,0.9)", 2.0);
    }
    // The keyboard cursor: dark and light, so it shows on any cell colour.
    if let Some(c) = marks.cursor.filter(|c| c.kind == CursorKind::Cursor) {
        drew |= outline(ctx, scene, cam, c.cell, "rgba(0,0,0,0.9)", 5.0);
        drew |= outline(ctx, scene, cam, c.cell, "#ffd166", 2.5);
    }
    drew
}

/// Outlines cell `i`; false when there is no such cell.
fn outline(ctx: &Ctx, scene: &SceneRef, cam: &Camera2D, i: u32, colour: &str, width: f64) -> bool {
    if i as usize >= scene.grid.len() {
        return false;
    }
    let [wx, wy] = scene.grid.centre(i as usize);
    let [sx, sy] = cam.to_screen(wx, wy);
    ctx.set_stroke_style_str(colour);
    ctx.set_line_width(width);
    ctx.begin_path();
    if scene.layout.lattice == LatticeKind::Hex {
        let c = hex_corners(sx, sy, HEX_RADIUS * cam.scale);
        ctx.move_to(c[0][0], c[0][1]);
        for p in &c[1..] {
            ctx.line_to(p[0], p[1]);
        }
        ctx.close_path();
    } else {
        ctx.rect(
            sx - cam.scale / 2.0,
            sy - cam.scale / 2.0,
            cam.scale,
            cam.scale,
        );
    }
    ctx.stroke();
    true
}

fn arrow(ctx: &Ctx, [ax, ay]: [f64; 2], [bx, by]: [f64; 2], scale: f64) {
    let (dx, dy) = (bx - ax, by - ay);
    let len = Some(dx.hypot(dy)).filter(|&l| l != 0.0).unwrap_or(1.0);
    let (ux, uy) = (dx / len, dy / len);
    let half = scale * 0.3;
    let (ex, ey) = (ax + ux * half, ay + uy * half);
    ctx.begin_path();
    ctx.move_to(ax - ux * half, ay - uy * half);
    ctx.line_to(ex, ey);
    ctx.stroke();
    let head = scale * 0.14;
    ctx.begin_path();
    ctx.move_to(ex, ey);
    ctx.line_to(
        ex - ux * head - uy * head * 0.7,
        ey - uy * head + ux * head * 0.7,
    );
    ctx.line_to(
        ex - ux * head + uy * head * 0.7,
        ey - uy * head - ux * head * 0.7,
    );
    ctx.close_path();
    ctx.fill();
}

/// In 3-D: the difference a unit would have at each highlighted (reachable) cell. Returns whether
/// it drew anything, as [`planar`] does.
pub fn reach(ctx: &Ctx, scene: &SceneRef, cam: &Camera3D) -> bool {
    let marks = scene.marks;
    if !marks.labels || marks.highlight_values.is_empty() || marks.highlight.len() > 64 {
        return false;
    }
    ctx.set_font("600 12px system-ui, sans-serif");
    ctx.set_text_align("center");
    ctx.set_text_baseline("middle");
    for (&i, &v) in marks.highlight.iter().zip(&marks.highlight_values) {
        if !v.is_finite() {
            continue;
        }
        let c = scene.grid.coord(i as usize).map(|a| f64::from(a) + 0.5);
        let Some([x, y, _]) = cam.project(c) else {
            continue;
        };
        let text = format!("D {}", precision3(v));
        let width = ctx.measure_text(&text).map_or(0.0, |m| m.width()) + 8.0;
        ctx.set_fill_style_str("rgba(27,35,44,0.82)");
        ctx.begin_path();
        let _ = ctx.round_rect_with_f64(x - width / 2.0, y - 9.0, width, 18.0, 4.0);
        ctx.fill();
        ctx.set_fill_style_str("#f0b429");
        let _ = ctx.fill_text(&text, x, y);
    }
    true
}

/// A number as JavaScript writes `Number(v.toPrecision(3))`: three significant digits, no
/// trailing zeros.
pub fn precision3(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let digits = 2 - v.abs().log10().floor() as i32;
    let rounded = if digits >= 0 {
        let f = 10f64.powi(digits);
        (v * f).round() / f
    } else {
        let f = 10f64.powi(-digits);
        (v / f).round() * f
    };
    let text = format!("{:.*}", digits.max(0) as usize, rounded);
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::precision3;

    #[test]
    fn values_read_as_the_page_wrote_them() {
        for (v, text) in [
            (0.0, "0"),
            (1.0, "1"),
            (2.5, "2.5"),
            (1.23456, "1.23"),
            (-0.000123456, "-0.000123"),
            (1234.5, "1230"),
            (10.0, "10"),
        ] {
            assert_eq!(precision3(v), text, "{v}");
        }
    }
}
