//! Square and hex lattices in Canvas 2D, the fallback when WebGL2 is unavailable: the square
//! lattice as one image scaled up, the hex lattice as a hexagon per visible cell, agents as discs.

use crate::camera::Camera2D;
use crate::geometry::{cell_centre, hex_corners, HEX_RADIUS};
use crate::palette::{css, heat, legend_table, Rgba};
use crate::scene::SceneRef;
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::Layout;
use std::f64::consts::TAU;
use wasm_bindgen::{Clamped, JsCast, JsValue};
use web_sys::{ImageData, OffscreenCanvas, OffscreenCanvasRenderingContext2d as Ctx};

#[derive(Default)]
pub struct PlanarCanvas {
    /// RGBA per cell code; transparent where the legend names none.
    table: Vec<Rgba>,
    agent_css: Vec<Option<String>>,
    /// The square lattice's pixels, one per cell, and the canvas they are scaled up from.
    pixels: Vec<u8>,
    image: Option<(OffscreenCanvas, Ctx)>,
}

impl PlanarCanvas {
    pub fn set_layout(&mut self, layout: &Layout) -> Result<(), JsValue> {
        let table = legend_table(&layout.cells);
        self.table = table
            .chunks_exact(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect();
        self.agent_css = vec![None; 256];
        for a in &layout.agents {
            self.agent_css[usize::from(a.code)] = Some(a.color.clone());
        }
        self.image = None;
        self.pixels.clear();
        if layout.lattice == LatticeKind::Square {
            let [w, h, _] = layout.dims;
            let canvas = OffscreenCanvas::new(w, h)?;
            let ctx = canvas
                .get_context("2d")?
                .ok_or("no 2d context")?
                .dyn_into::<Ctx>()?;
            self.pixels = vec![0; 4 * w as usize * h as usize];
            self.image = Some((canvas, ctx));
        }
        Ok(())
    }

    /// Draws the lattice; the context is cleared and scaled to CSS pixels.
    pub fn draw(&mut self, ctx: &Ctx, scene: &SceneRef, cam: &Camera2D) -> Result<(), JsValue> {
        if scene.layout.lattice == LatticeKind::Square {
            self.draw_square(ctx, scene, cam)?;
        } else {
            self.draw_hex(ctx, scene, cam);
        }
        self.draw_agents(ctx, scene, cam);
        Ok(())
    }

    fn overlay_color(scene: &SceneRef, i: usize) -> Option<Rgba> {
        let o = scene.state.overlay?;
        let v = f64::from(*o.data.get(i)?);
        if !v.is_finite() {
            return None;
        }
        let span = f64::from(o.max - o.min);
        let t = if span > 0.0 {
            (v - f64::from(o.min)) / span
        } else {
            0.5
        };
        let [r, g, b] = heat(t);
        Some([r as u8, g as u8, b as u8, 255])
    }

    fn draw_square(&mut self, ctx: &Ctx, scene: &SceneRef, cam: &Camera2D) -> Result<(), JsValue> {
        let Some((canvas, image_ctx)) = &self.image else {
            return Ok(());
        };
        let cells = scene.state.cells;
        if self.pixels.len() != cells.len() * 4 {
            return Ok(());
        }
        for (i, (&code, px)) in cells
            .iter()
            .zip(self.pixels.chunks_exact_mut(4))
            .enumerate()
        {
            let colour = if code != 0 {
                Self::overlay_color(scene, i)
            } else {
                None
            };
            px.copy_from_slice(&colour.unwrap_or(self.table[usize::from(code)]));
        }
        let image = ImageData::new_with_u8_clamped_array_and_sh(
            Clamped(&self.pixels),
            canvas.width(),
            canvas.height(),
        )?;
        image_ctx.put_image_data(&image, 0.0, 0.0)?;
        ctx.set_image_smoothing_enabled(false);
        let [x0, y0] = cam.to_screen(0.0, 0.0);
        ctx.draw_image_with_offscreen_canvas_and_dw_and_dh(
            canvas,
            x0,
            y0,
            f64::from(canvas.width()) * cam.scale,
            f64::from(canvas.height()) * cam.scale,
        )
    }

    fn draw_hex(&self, ctx: &Ctx, scene: &SceneRef, cam: &Camera2D) {
        let cells = scene.state.cells;
        let [w, h, _] = scene.grid.dims;
        // The cells in view, one more row and column on the far sides: a hexagon reaches past
        // its cell's box.
        let Some([x_from, x1, y_from, y1]) = cam.visible_cells(&scene.grid) else {
            return;
        };
        let (x_to, y_to) = ((x1 + 1).min(w - 1), (y1 + 1).min(h - 1));
        let r = HEX_RADIUS * cam.scale * if cam.scale > 8.0 { 0.96 } else { 1.02 };
        for y in y_from..=y_to {
            for x in x_from..=x_to {
                let i = (y * w + x) as usize;
                let code = cells[i];
                if code == 0 {
                    continue;
                }
                let fill = Self::overlay_color(scene, i).unwrap_or(self.table[usize::from(code)]);
                if fill[3] == 0 {
                    continue;
                }
                let [wx, wy] = cell_centre(LatticeKind::Hex, x, y);
                let [sx, sy] = cam.to_screen(wx, wy);
                ctx.begin_path();
                let corners = hex_corners(sx, sy, r);
                ctx.move_to(corners[0][0], corners[0][1]);
                for c in &corners[1..] {
                    ctx.line_to(c[0], c[1]);
                }
                ctx.close_path();
                ctx.set_fill_style_str(&css(fill));
                ctx.fill();
            }
        }
    }

    fn draw_agents(&self, ctx: &Ctx, scene: &SceneRef, cam: &Camera2D) {
        let radius = (cam.scale * 0.34).max(1.2);
        for a in scene.state.agents {
            let [wx, wy] = scene.grid.centre(a.cell as usize);
            let [sx, sy] = cam.to_screen(wx, wy);
            let colour = self.agent_css[usize::from(a.kind)]
                .as_deref()
                .unwrap_or("#ffffff");
            ctx.set_fill_style_str(colour);
            if radius < 2.0 {
                ctx.fill_rect(sx - 1.0, sy - 1.0, 2.0, 2.0);
            } else {
                ctx.begin_path();
                let _ = ctx.arc(sx, sy, radius, 0.0, TAU);
                ctx.fill();
                ctx.set_line_width((radius * 0.15).max(1.0));
                ctx.set_stroke_style_str("rgba(0,0,0,0.55)");
                ctx.stroke();
            }
        }
    }
}
