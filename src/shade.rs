//! The OpenGL 2.1 fixed-function lighting equation (§2.14.1, eqs. 2.2–2.5) per vertex, and the
//! parallel loop over vertices.
//!
//! ```text
//! c_pri = e_cm + a_cm·a_cs + Σ_i att_i·spot_i·[a_cm·a_cli + (n⊙VP)·d_cm·d_cli + f_i·(n⊙ĥ)^s·s_cm·s_cli]
//! ```
//! The sum is regrouped by material factor (a_cm·Σ w_i a_cli + d_cm·Σ w_i (n⊙VP) d_cli + …), so
//! a per-vertex colour material costs nothing per light, and the sums run in `f64` whatever the
//! input type, so their error does not grow with the light count.

use glam::DVec3;
use rayon::prelude::*;

use crate::error::Error;
use crate::material::Material;
use crate::prepare::{
    cos_pow, rgb, saturate, Prepared, PreparedLight, ShadeOptions, Source, Viewer, SATURATION,
};
use crate::real::{normalize_and_length, normalize_or_zero, Real, Vector3};
use crate::scene::{Scene, Specular};

/// Rows per parallel task: enough work to amortise rayon's scheduling for one light, few enough
/// that a 10^4-row call still spreads over every core.
const ROWS_PER_TASK: usize = 1024;

/// Per-vertex colours for `GL_COLOR_MATERIAL`: `data` holds `width` (3 or 4) values per vertex,
/// row after row; a missing alpha is 1.
#[derive(Clone, Copy, Debug)]
pub struct VertexColors<'a, T> {
    /// The colours, C order.
    pub data: &'a [T],
    /// Values per vertex: 3 (RGB) or 4 (RGBA).
    pub width: usize,
}

/// The normal as the equation needs it, for one side.
#[derive(Clone, Copy)]
struct SideNormal<T: Real> {
    /// n as GL uses it (unit only with `normalize`), negated for the back side.
    n: T::Vec3,
    /// n̂, its direction.
    unit: T::Vec3,
    /// ln |n| (0 with `normalize`): (n·ĥ)^s = |n|^s (n̂·ĥ)^s.
    ln_length: T,
}

/// The light-weighted sums of one side: Σ w(n⊙VP)d_cli and Σ w·f·pow·s_cli.
#[derive(Clone, Copy, Default)]
struct SideSums {
    diffuse: DVec3,
    specular: DVec3,
}

/// The colours of one vertex, in output order, RGBA in f64 after the clamp.
type VertexOutput = [[f64; 4]; 4];

#[inline]
fn clamp_rgba(rgb: DVec3, alpha: f64) -> [f64; 4] {
    let c = rgb.clamp(DVec3::ZERO, DVec3::ONE);
    [c.x, c.y, c.z, alpha.clamp(0.0, 1.0)]
}

/// att_i of eq. 2.4; zero coefficients are skipped so an infinite distance gives 0, not NaN, and
/// a zero denominator (the light at the vertex with k0 = 0) gives a large finite weight.
#[inline]
fn attenuation<T: Real>(k: [T; 3], d: T) -> T {
    let mut den = k[0];
    if k[1] != T::ZERO {
        den += k[1] * d;
    }
    if k[2] != T::ZERO {
        den += k[2] * d * d;
    }
    T::ONE / den.max(T::MIN_POSITIVE)
}

impl<T: Real> Prepared<T> {
    /// VP_pli (unit, or zero for a light at the vertex) and att_i·spot_i for the vertex at `p`.
    #[inline]
    fn light_at(light: &PreparedLight<T>, p: T::Vec3) -> (T::Vec3, T, T) {
        match light.source {
            Source::Directional { vp, spot, .. } => (vp, T::ONE, spot),
            Source::Positional {
                position,
                attenuation: k,
                spot,
            } => {
                let (vp, d) = normalize_and_length::<T>(position - p);
                let spot = spot.map_or(T::ONE, |s| s.factor(-vp));
                (vp, attenuation(k, d), spot)
            }
        }
    }

    /// (n⊙ĥ)^s (Blinn) or (R⊙VP_e)^s (Phong) for a front-lit side; 0 for a zero ĥ or a viewer
    /// at the vertex.
    #[inline]
    fn specular_power(
        &self,
        light: &PreparedLight<T>,
        side: &SideNormal<T>,
        vp: T::Vec3,
        view: T::Vec3,
        n_dot_vp: T,
        s: T,
    ) -> T {
        match self.specular {
            Specular::Blinn => {
                let h = match light.source {
                    Source::Directional {
                        halfway: Some(h), ..
                    } => h,
                    _ => normalize_or_zero::<T>(vp + view),
                };
                if h == T::Vec3::ZERO {
                    return T::ZERO;
                }
                cos_pow(side.unit.dot(h), side.unit, h, s, side.ln_length)
            }
            Specular::Phong => {
                if view == T::Vec3::ZERO {
                    return T::ZERO;
                }
                let r = side.n * (n_dot_vp + n_dot_vp) - vp;
                let (r_unit, r_length) = normalize_and_length::<T>(r);
                if r_length == T::ZERO {
                    return T::ZERO;
                }
                let ln_length = if self.normalize {
                    T::ZERO
                } else {
                    T::ln_length(r, r_length)
                };
                cos_pow(r_unit.dot(view), r_unit, view, s, ln_length)
            }
        }
    }

    /// The material of `side` (0 front, 1 back) at a vertex of colour `color`.
    #[inline]
    fn material(&self, side: usize, color: Option<[f64; 4]>) -> Material {
        let m = &self.materials[side];
        match (self.color_material, color) {
            (Some(cm), Some(c)) if cm.applies_to(side == 1) => cm.apply(m, c),
            _ => *m,
        }
    }

    /// Every colour of one vertex given in model coordinates, or `None` when its eye-space
    /// position, normal or colour is not finite.
    #[inline]
    fn vertex(
        &self,
        position: [T; 3],
        normal: [T; 3],
        color: Option<[f64; 4]>,
    ) -> Option<VertexOutput> {
        let (mut p, mut n) = (T::Vec3::from_array(position), T::Vec3::from_array(normal));
        if let Some(t) = &self.transform {
            (p, n) = (t.point(p), t.normal(n));
        }
        if !(p.is_finite()
            && n.is_finite()
            && color.is_none_or(|c| c.iter().all(|x| x.is_finite())))
        {
            return None;
        }
        let (unit, length) = normalize_and_length::<T>(n);
        let front = if self.normalize {
            SideNormal {
                n: unit,
                unit,
                ln_length: T::ZERO,
            }
        } else {
            let ln_length = if length == T::ZERO {
                T::ZERO
            } else {
                T::ln_length(n, length)
            };
            SideNormal { n, unit, ln_length }
        };
        let sides = [
            front,
            SideNormal {
                n: -front.n,
                unit: -front.unit,
                ..front
            },
        ];
        let view = match self.viewer {
            Viewer::Infinite(v) => v,
            Viewer::Local(e) => normalize_or_zero::<T>(e - p),
        };
        let mut ambient = DVec3::ZERO;
        let mut sums = [SideSums::default(); 2];
        for light in &self.lights {
            let (vp, att, spot) = Self::light_at(light, p);
            let w = (att.to_f64() * spot.to_f64()).min(SATURATION);
            if w == 0.0 {
                continue; // adds exactly nothing
            }
            ambient += light.ambient * w;
            for (i, (side, sum)) in sides.iter().zip(&mut sums).enumerate().take(self.sides) {
                let n_dot_vp = side.n.dot(vp);
                // f_i: no diffuse and no specular unless n·VP > 0 (a select, never a 0· mask).
                // specular_gate = false (learnopengl) drops f_i from the specular only; a zero
                // normal or a light at the vertex (VP = 0) still gets none.
                let lit = n_dot_vp > T::ZERO;
                if lit || (!self.specular_gate && side.n != T::Vec3::ZERO && vp != T::Vec3::ZERO) {
                    if lit {
                        sum.diffuse += light.diffuse * (w * saturate(n_dot_vp.to_f64()));
                    }
                    let power =
                        self.specular_power(light, side, vp, view, n_dot_vp, self.shininess[i]);
                    sum.specular += light.specular * (w * saturate(power.to_f64()));
                }
            }
        }

        let mut out = [[0.0; 4]; 4];
        let mut k = 0;
        for (side, sum) in sums.iter().enumerate().take(self.sides) {
            let m = self.material(side, color);
            let a = rgb(m.ambient);
            let lit = rgb(m.emission)
                + a * self.global_ambient
                + a * ambient
                + rgb(m.diffuse) * sum.diffuse;
            let specular = rgb(m.specular) * sum.specular;
            if self.separate_specular {
                out[k] = clamp_rgba(lit, m.diffuse[3]);
                out[k + 1] = clamp_rgba(specular, 1.0);
                k += 2;
            } else {
                out[k] = clamp_rgba(lit + specular, m.diffuse[3]);
                k += 1;
            }
        }
        Some(out)
    }
}

/// Lights `positions` with `normals` (both (n, 3), model coordinates) under `scene`, writing
/// every colour the scene computes into `out`.
///
/// `out` holds `scene.output_count()` planes of n RGBA rows, one after the other, in the order
/// of [`Scene::output_names`], each clamped to [0, 1]. A vertex whose eye-space position,
/// normal or colour is not finite gets NaN in every plane; every other output is finite.
/// Vertices are shaded in parallel; the result is identical for any number of threads.
///
/// # Errors
/// A value error for an invalid scene or modelview, mismatched lengths, colours without
/// `color_material` (or the reverse), or an `out` of the wrong length.
pub fn shade<T: Real>(
    scene: &Scene,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &ShadeOptions,
    out: &mut [T],
) -> Result<(), Error> {
    let n = positions.len();
    if normals.len() != n {
        return Err(Error::value(format!(
            "normals must have one row per position ({n}), got {} rows",
            normals.len()
        )));
    }
    if let Some(c) = colors {
        if !(c.width == 3 || c.width == 4) || c.data.len() != n * c.width {
            return Err(Error::value(format!(
                "colors must have shape ({n}, 3) or ({n}, 4), got {} values of width {}",
                c.data.len(),
                c.width
            )));
        }
    }
    match (colors.is_some(), options.color_material.is_some()) {
        (true, false) => return Err(Error::value("colors need a color_material mode, got None")),
        (false, true) => return Err(Error::value("color_material needs colors, got None")),
        _ => {}
    }
    let planes = scene.output_count();
    if out.len() != planes * n * 4 {
        return Err(Error::value(format!(
            "out must hold {planes} x {n} x 4 values, got {}",
            out.len()
        )));
    }
    let prepared = Prepared::<T>::new(scene, options)?;
    if n == 0 {
        return Ok(());
    }

    // Regroup the planes chunk by chunk, so each task owns the same rows of every plane.
    let mut tasks: Vec<Vec<&mut [T]>> = (0..n.div_ceil(ROWS_PER_TASK))
        .map(|_| Vec::with_capacity(planes))
        .collect();
    for plane in out.chunks_mut(n * 4) {
        for (task, rows) in tasks.iter_mut().zip(plane.chunks_mut(ROWS_PER_TASK * 4)) {
            task.push(rows);
        }
    }
    tasks.into_par_iter().enumerate().for_each(|(t, mut task)| {
        let first = t * ROWS_PER_TASK;
        for j in 0..task[0].len() / 4 {
            let i = first + j;
            let color = colors.map(|c| {
                let row = &c.data[i * c.width..(i + 1) * c.width];
                let alpha = if c.width == 4 { row[3].to_f64() } else { 1.0 };
                [row[0].to_f64(), row[1].to_f64(), row[2].to_f64(), alpha]
            });
            let rgba = prepared.vertex(positions[i], normals[i], color);
            for (k, plane) in task.iter_mut().enumerate() {
                let dst = &mut plane[4 * j..4 * j + 4];
                match &rgba {
                    Some(colours) => {
                        for (d, &s) in dst.iter_mut().zip(&colours[k]) {
                            *d = T::from_f64(s);
                        }
                    }
                    None => dst.fill(T::NAN),
                }
            }
        }
    });
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::Light;
    use crate::material::ColorMaterial;

    fn shade_one<T: Real>(scene: &Scene, p: [T; 3], n: [T; 3], options: &ShadeOptions) -> Vec<T> {
        let mut out = vec![T::ZERO; scene.output_count() * 4];
        shade(scene, &[p], &[n], None, options, &mut out).unwrap();
        out
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
    }

    fn headlight_scene() -> Scene {
        Scene {
            lights: vec![Light::default()],
            ..Scene::default()
        }
    }

    #[test]
    fn headlight_on_a_facing_normal() {
        // e + a·a_cs + a·a_cl + 1·d·d_cl = 0 + 0.04 + 0 + 0.8; specular colour is 0.
        let out = shade_one::<f64>(
            &headlight_scene(),
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert!(close(&out, &[0.84, 0.84, 0.84, 1.0]), "{out:?}");
        let out32 = shade_one::<f32>(
            &headlight_scene(),
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert!((out32[0] - 0.84).abs() < 1e-6);
    }

    #[test]
    fn back_facing_keeps_ambient_only_and_two_side_lights_the_back() {
        let mut scene = headlight_scene();
        scene.material.specular = [1.0, 1.0, 1.0, 1.0];
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, -1.0], &ShadeOptions::default());
        assert!(close(&out, &[0.04, 0.04, 0.04, 1.0]), "{out:?}");
        scene.two_side = true;
        scene.back_material.diffuse = [0.5, 0.25, 0.0, 0.5];
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, -1.0], &ShadeOptions::default());
        // Back: 0.04 + 1·back diffuse + 0^0 specular (shininess 0) with back specular (0, 0, 0).
        assert!(
            close(&out, &[0.04, 0.04, 0.04, 1.0, 0.54, 0.29, 0.04, 0.5]),
            "{out:?}"
        );
    }

    #[test]
    fn shininess_zero_gives_the_full_specular_when_lit() {
        let mut scene = headlight_scene();
        scene.material.specular = [0.1, 0.2, 0.3, 1.0];
        scene.separate_specular = true;
        let n = [0.0, 0.6, 0.8];
        let out = shade_one::<f64>(&scene, [0.0; 3], n, &ShadeOptions::default());
        assert!(close(&out[4..], &[0.1, 0.2, 0.3, 1.0]), "{out:?}");
    }

    #[test]
    fn attenuation_follows_eq_2_4() {
        let light = Light {
            position: [0.0, 0.0, 2.0, 1.0],
            constant_attenuation: 1.0,
            linear_attenuation: 0.5,
            quadratic_attenuation: 0.25,
            ..Light::default()
        };
        let scene = Scene {
            lights: vec![light],
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
        assert!((out[0] - 0.8 / (1.0 + 1.0 + 1.0)).abs() < 1e-15);
    }

    #[test]
    fn light_at_the_vertex_is_finite() {
        let light = Light {
            position: [1.0, 2.0, 3.0, 1.0],
            constant_attenuation: 0.0,
            quadratic_attenuation: 1.0,
            ambient: [0.0, 0.5, -1.0, 1.0],
            ..Light::default()
        };
        let scene = Scene {
            lights: vec![light],
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let out = shade_one::<f32>(
            &scene,
            [1.0, 2.0, 3.0],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert_eq!(out, vec![0.0, 1.0, 0.0, 1.0]);
    }

    #[test]
    fn nan_stays_in_its_row() {
        let scene = headlight_scene();
        let positions = [[0.0_f32; 3], [f32::NAN, 0.0, 0.0], [0.0; 3]];
        let normals = [[0.0, 0.0, 1.0]; 3];
        let mut out = vec![0.0_f32; 12];
        shade(
            &scene,
            &positions,
            &normals,
            None,
            &ShadeOptions::default(),
            &mut out,
        )
        .unwrap();
        assert!(out[4..8].iter().all(|x| x.is_nan()));
        assert!(out[..4].iter().chain(&out[8..]).all(|x| x.is_finite()));
    }

    #[test]
    fn color_material_replaces_the_tracked_parameters() {
        let scene = headlight_scene();
        let options = ShadeOptions {
            color_material: Some(ColorMaterial::parse("diffuse", "front_and_back").unwrap()),
            ..ShadeOptions::default()
        };
        let colors = VertexColors {
            data: &[0.5, 0.25, 1.0, 0.5][..],
            width: 4,
        };
        let mut out = vec![0.0; 4];
        shade::<f64>(
            &scene,
            &[[0.0; 3]],
            &[[0.0, 0.0, 1.0]],
            Some(colors),
            &options,
            &mut out,
        )
        .unwrap();
        assert!(close(&out, &[0.54, 0.29, 1.0, 0.5]), "{out:?}");
    }

    #[test]
    fn mismatched_lengths_are_rejected() {
        let mut out = vec![0.0; 8];
        let err = shade::<f64>(
            &headlight_scene(),
            &[[0.0; 3]; 2],
            &[[0.0; 3]],
            None,
            &ShadeOptions::default(),
            &mut out,
        )
        .unwrap_err();
        assert!(err.message.starts_with("normals"));
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let scene = Scene {
            lights: (0..5)
                .map(|i| Light {
                    position: [f64::from(i), 1.0, 2.0, 1.0],
                    spot_cutoff: 60.0,
                    spot_exponent: 3.0,
                    linear_attenuation: 0.3,
                    ..Light::default()
                })
                .collect(),
            material: Material {
                specular: [1.0; 4],
                shininess: 40.0,
                ..Material::default()
            },
            viewer: [0.0, 0.0, 0.0, 1.0],
            ..Scene::default()
        };
        let n = 5000;
        let positions: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32 * 0.01;
                [t.sin(), t.cos(), -1.0 - t.sin() * t]
            })
            .collect();
        let normals: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32 * 0.37;
                [t.cos(), t.sin(), 0.5]
            })
            .collect();
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut out = vec![0.0_f32; n * 4];
            pool.install(|| {
                shade(
                    &scene,
                    &positions,
                    &normals,
                    None,
                    &ShadeOptions::default(),
                    &mut out,
                )
                .unwrap();
            });
            out.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        };
        assert_eq!(run(1), run(3));
    }
}
