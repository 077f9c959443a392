//! A depth buffer at picture resolution: the occluding triangles rasterised with their
//! depth toward the viewer, and the test whether a point lies behind them (module doc of
//! [`crate::render`]: a drawing aid, not a certificate).

/// Depths (larger = nearer the viewer) per pixel; `-∞` where nothing was drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct DepthBuffer {
    width: usize,
    height: usize,
    depth: Vec<f64>,
    /// How far in front a surface must be to hide a point (absorbs the tessellation's
    /// chord error and the rasterisation's).
    pub tolerance: f64,
}

impl DepthBuffer {
    /// An empty buffer of `width × height` pixels.
    pub fn new(width: usize, height: usize, tolerance: f64) -> DepthBuffer {
        DepthBuffer {
            width,
            height,
            depth: vec![f64::NEG_INFINITY; width * height],
            tolerance,
        }
    }

    /// Rasterise a triangle given by its pixel coordinates `(x, y)` and depths: every
    /// pixel whose centre lies in the triangle keeps the largest depth, interpolated
    /// linearly (barycentric coordinates).
    pub fn triangle(&mut self, t: [[f64; 3]; 3]) {
        if !t.iter().flatten().all(|c| c.is_finite()) {
            return;
        }
        let area =
            (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
        if area == 0.0 {
            return;
        }
        let lo = |k: usize| t.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
        let hi = |k: usize| t.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
        let x0 = lo(0).floor().max(0.0) as usize;
        let y0 = lo(1).floor().max(0.0) as usize;
        let x1 = (hi(0).ceil().max(0.0) as usize).min(self.width);
        let y1 = (hi(1).ceil().max(0.0) as usize).min(self.height);
        for y in y0..y1 {
            for x in x0..x1 {
                let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                let w = |a: &[f64; 3], b: &[f64; 3]| {
                    ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / area
                };
                let (w0, w1, w2) = (w(&t[1], &t[2]), w(&t[2], &t[0]), w(&t[0], &t[1]));
                if w0 < 0.0 || w1 < 0.0 || w2 < 0.0 {
                    continue;
                }
                let z = w0 * t[0][2] + w1 * t[1][2] + w2 * t[2][2];
                let cell = &mut self.depth[y * self.width + x];
                if z > *cell {
                    *cell = z;
                }
            }
        }
    }

    /// Whether a surface lies in front of the point at pixel `(x, y)` with depth `z`:
    /// the nearest of the buffer's depths over the 3×3 pixels around it (the smallest,
    /// so that a point on a surface seen at a slant is not hidden by its own
    /// neighbourhood) exceeds `z` by more than the tolerance.
    pub fn hides(&self, x: f64, y: f64, z: f64) -> bool {
        if !(x.is_finite() && y.is_finite() && z.is_finite()) {
            return false;
        }
        let (cx, cy) = (x.floor() as i64, y.floor() as i64);
        let mut nearest = f64::INFINITY;
        for dy in -1..=1 {
            for dx in -1..=1 {
                let (px, py) = (cx + dx, cy + dy);
                if px < 0 || py < 0 || px >= self.width as i64 || py >= self.height as i64 {
                    return false;
                }
                nearest = nearest.min(self.depth[py as usize * self.width + px as usize]);
            }
        }
        nearest > z + self.tolerance
    }
}
