//! The scene, the camera and the render's settings, packed as the shader
//! reads them: bytes laid out by WGSL's rules, built from the core's
//! `raylab::Scene` and `raylab::Camera`.
//!
//! WGSL lays a `vec3<f32>` out on 16 bytes but lets a 4-byte number fill
//! the last 4, so `Params` alternates a vector and a number; the test at
//! the bottom checks these sizes against naga's reading of `tracer.wgsl`.

use raylab::{Camera, Scene, Settings, Vec3};

use crate::like::Features;

/// The bytes of `Params` in `tracer.wgsl`.
pub const PARAMS_SIZE: usize = 192;
/// The bytes of one `Sphere` in `tracer.wgsl`.
pub const SPHERE_SIZE: usize = 48;
/// Where `first_row` and `band_rows` sit in `Params`.
pub const FIRST_ROW_AT: usize = 156;
pub const BAND_ROWS_AT: usize = 172;
/// Where the render's settings sit in `Params`: the book's lab page
/// (`book/src/lab-in-browser.md`) sets them in the bytes [`pack`] wrote,
/// as [`Inputs::band`] sets the band, so the layout is written only here.
pub const WIDTH_AT: usize = 12;
pub const HEIGHT_AT: usize = 28;
pub const EPSILON_AT: usize = 60;
pub const MAX_DEPTH_AT: usize = 92;
pub const SPP_AT: usize = 108;
pub const FEATURES_AT: usize = 140;
/// The bytes of one `Progress` and of one `Pending` in `tracer.wgsl`: the
/// state a pixel keeps between dispatches is one of the first and a stack
/// of the second.
pub const PROGRESS_SIZE: usize = 80;
pub const PENDING_SIZE: usize = 48;

// ANCHOR: steps
/// Mesa's lavapipe ends every loop of a shader once a group of lanes has
/// gone round its loops this many times in all, counted from the start of
/// the invocation (`LP_MAX_TGSI_LOOP_ITERATIONS` in Mesa's gallivm). Any
/// driver may stop a shader that runs too long; this is lavapipe's rule.
pub const DRIVER_LOOP_LIMIT: u64 = 65535;

/// The most rays one invocation may trace in one dispatch so that its loops
/// stay under [`DRIVER_LOOP_LIMIT`]: each ray goes round the sphere loop at
/// most twice (its nearest hit and its shadow feeler) and round `trace`'s
/// loop once, with one turn to spare; and `trace`'s loop is tested once
/// more at its end.
pub fn steps_per_dispatch(spheres: usize) -> u32 {
    let per_ray = 2 * spheres as u64 + 2;
    let steps = (DRIVER_LOOP_LIMIT - 2) / per_ray;
    u32::try_from(steps.max(1)).unwrap_or(u32::MAX)
}
// ANCHOR_END: steps

/// Everything the shader reads, as bytes ready for the GPU's buffers.
#[derive(Clone, Debug, PartialEq)]
pub struct Inputs {
    pub width: u32,
    pub height: u32,
    /// The deepest ray (the compiled stack must have room for it).
    pub max_depth: u32,
    /// `params`: the uniform buffer.
    pub params: Vec<u8>,
    /// `spheres`: one [`SPHERE_SIZE`] record per sphere (at least one, so
    /// that the buffer is never empty; `sphere_count` says how many count).
    pub spheres: Vec<u8>,
    /// `samples`: each sample's offset in the pixel, two `f32`s.
    pub samples: Vec<u8>,
}

impl Inputs {
    /// `params` for the band of `rows` rows from `first_row` down.
    pub fn band(&self, first_row: u32, rows: u32) -> Vec<u8> {
        let mut params = self.params.clone();
        params[FIRST_ROW_AT..FIRST_ROW_AT + 4].copy_from_slice(&first_row.to_le_bytes());
        params[BAND_ROWS_AT..BAND_ROWS_AT + 4].copy_from_slice(&rows.to_le_bytes());
        params
    }
}

/// Why a render cannot go to the shader as asked.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PackError {
    #[error(
        "--pattern {0} draws new points in every pixel, and the shader takes one set of points \
         for all of them: use --spp 1, --spp 5 or --pattern grid"
    )]
    PerPixelPattern(&'static str),
}

/// Little-endian bytes, in the order they are written.
#[derive(Default)]
struct Bytes(Vec<u8>);

impl Bytes {
    fn f32(&mut self, x: f32) -> &mut Self {
        self.0.extend_from_slice(&x.to_le_bytes());
        self
    }

    fn u32(&mut self, x: u32) -> &mut Self {
        self.0.extend_from_slice(&x.to_le_bytes());
        self
    }

    /// A `vec3<f32>`: three numbers; the fourth place is the next field's
    /// or padding.
    fn vec3(&mut self, v: Vec3) -> &mut Self {
        self.f32(v.x).f32(v.y).f32(v.z)
    }
}

/// Pack a render for the shader.
pub fn pack(
    scene: &Scene,
    camera: &Camera,
    settings: &Settings,
    features: Features,
) -> Result<Inputs, PackError> {
    let sampling = settings.sampling;
    if let Some(pattern) = sampling.pattern().filter(|p| p.is_random()) {
        return Err(PackError::PerPixelPattern(pattern.name()));
    }
    // ANCHOR: params
    let mut params = Bytes::default();
    // In the order of `struct Params` in tracer.wgsl.
    params.vec3(camera.eye).u32(settings.width);
    params.vec3(camera.forward()).u32(settings.height);
    params.vec3(camera.right()).f32(camera.half_height());
    params.vec3(camera.up()).f32(settings.epsilon);
    params.vec3(scene.sun.direction).f32(scene.sun.brightness);
    params.vec3(scene.sky.horizon).u32(settings.max_depth);
    params.vec3(scene.sky.zenith).u32(sampling.spp());
    let spheres = scene.spheres();
    let count = u32::try_from(spheres.len()).unwrap_or(u32::MAX);
    params.vec3(scene.ground.plane.point).u32(count);
    params
        .vec3(scene.ground.plane.normal)
        .u32(crate::like::feature_bits(features));
    // The whole image as one band; `Inputs::band` sets another.
    params.vec3(scene.ground.checker.even).u32(0);
    params.vec3(scene.ground.checker.odd).u32(settings.height);
    // `steps`, and the padding that rounds `Params` up to 16 bytes.
    params.u32(steps_per_dispatch(spheres.len()));
    params.u32(0).u32(0).u32(0);
    debug_assert_eq!(params.0.len(), PARAMS_SIZE);
    // ANCHOR_END: params

    let mut records = Bytes::default();
    for sphere in spheres {
        let m = &sphere.material;
        records.vec3(sphere.shape.centre).f32(sphere.shape.radius);
        records.vec3(m.albedo()).f32(m.reflection());
        records.f32(m.transmission()).f32(m.ior()).f32(0.0).f32(0.0);
    }
    if spheres.is_empty() {
        records.0.resize(SPHERE_SIZE, 0);
    }

    // The pixel centre, the lab's five and the grid put the same points
    // in every pixel: the offsets of pixel (0, 0) are everyone's.
    let mut samples = Bytes::default();
    for (sx, sy) in sampling.offsets((0, 0)) {
        samples.f32(sx).f32(sy);
    }
    Ok(Inputs {
        width: settings.width,
        height: settings.height,
        max_depth: settings.max_depth,
        params: params.0,
        spheres: records.0,
        samples: samples.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::{Pattern, Sampling};
    use wgpu::naga;

    fn settings(spp: u32, pattern: Option<Pattern>) -> Settings {
        Settings {
            width: 8,
            height: 6,
            max_depth: 10,
            epsilon: 1e-4,
            sampling: Sampling::new(spp, pattern, 0).unwrap(),
        }
    }

    /// The size naga gives a struct of tracer.wgsl, and its members' offsets.
    fn wgsl_layout(name: &str) -> (usize, Vec<(String, usize)>) {
        let module = naga::front::wgsl::parse_str(crate::shader::BUILT_IN).unwrap();
        let (_, ty) = module
            .types
            .iter()
            .find(|(_, ty)| ty.name.as_deref() == Some(name))
            .unwrap();
        match &ty.inner {
            naga::TypeInner::Struct { span, members } => (
                *span as usize,
                members
                    .iter()
                    .map(|m| (m.name.clone().unwrap_or_default(), m.offset as usize))
                    .collect(),
            ),
            _ => panic!("{name} is not a struct"),
        }
    }

    fn wgsl_size(name: &str) -> usize {
        wgsl_layout(name).0
    }

    #[test]
    fn a_band_s_rows_are_written_where_the_shader_reads_them() {
        let (_, members) = wgsl_layout("Params");
        let at = |name: &str| members.iter().find(|(n, _)| n == name).unwrap().1;
        assert_eq!(at("first_row"), FIRST_ROW_AT);
        assert_eq!(at("band_rows"), BAND_ROWS_AT);
        let inputs = pack(
            &Scene::lab(),
            &Camera::lab(),
            &settings(1, None),
            crate::Like::RayCast.features(),
        )
        .unwrap();
        let band = inputs.band(3, 2);
        assert_eq!(band[FIRST_ROW_AT..FIRST_ROW_AT + 4], 3u32.to_le_bytes());
        assert_eq!(band[BAND_ROWS_AT..BAND_ROWS_AT + 4], 2u32.to_le_bytes());
        // Unbanded, the whole image is one band.
        let whole = &inputs.params;
        assert_eq!(whole[BAND_ROWS_AT..BAND_ROWS_AT + 4], 6u32.to_le_bytes());
    }

    #[test]
    fn the_settings_are_written_where_the_shader_reads_them() {
        let (_, members) = wgsl_layout("Params");
        let at = |name: &str| members.iter().find(|(n, _)| n == name).unwrap().1;
        let fields = [
            ("width", WIDTH_AT),
            ("height", HEIGHT_AT),
            ("epsilon", EPSILON_AT),
            ("max_depth", MAX_DEPTH_AT),
            ("spp", SPP_AT),
            ("features", FEATURES_AT),
        ];
        for (name, offset) in fields {
            assert_eq!(at(name), offset, "{name}");
        }
        let inputs = pack(
            &Scene::lab(),
            &Camera::lab(),
            &settings(5, None),
            crate::Like::Reflection.features(),
        )
        .unwrap();
        let word = |at: usize| <[u8; 4]>::try_from(&inputs.params[at..at + 4]).unwrap();
        assert_eq!(u32::from_le_bytes(word(WIDTH_AT)), 8);
        assert_eq!(u32::from_le_bytes(word(HEIGHT_AT)), 6);
        assert_eq!(f32::from_le_bytes(word(EPSILON_AT)), 1e-4);
        assert_eq!(u32::from_le_bytes(word(MAX_DEPTH_AT)), 10);
        assert_eq!(u32::from_le_bytes(word(SPP_AT)), 5);
        // Chapter 3: shadows and reflection, bits 0 and 1.
        assert_eq!(u32::from_le_bytes(word(FEATURES_AT)), 0b011);
    }

    #[test]
    fn the_packed_structs_have_the_sizes_the_shader_reads() {
        assert_eq!(wgsl_size("Params"), PARAMS_SIZE);
        assert_eq!(wgsl_size("Sphere"), SPHERE_SIZE);
        assert_eq!(wgsl_size("Progress"), PROGRESS_SIZE);
        assert_eq!(wgsl_size("Pending"), PENDING_SIZE);
        let inputs = pack(
            &Scene::lab(),
            &Camera::lab(),
            &settings(5, None),
            crate::Like::AntiAliasing.features(),
        )
        .unwrap();
        assert_eq!(inputs.params.len(), PARAMS_SIZE);
        assert_eq!(inputs.spheres.len(), 5 * SPHERE_SIZE);
        assert_eq!(inputs.samples.len(), 5 * 8);
    }

    #[test]
    fn a_dispatch_traces_few_enough_rays_to_stay_under_the_driver_s_loop_limit() {
        // 500 spheres: a ray goes round the sphere loop up to 1000 times,
        // so 65 rays (65 · 1002 = 65130) fit and 66 would not.
        assert_eq!(steps_per_dispatch(500), 65);
        let loops = |rays: u64| rays * 1002 + 2;
        assert!(loops(65) <= DRIVER_LOOP_LIMIT && loops(66) > DRIVER_LOOP_LIMIT);
        // The lab's five spheres: thousands of rays per dispatch.
        assert_eq!(steps_per_dispatch(5), 5461);
        assert_eq!(steps_per_dispatch(0), 32766);
    }

    #[test]
    fn the_lab_five_go_to_the_shader_in_their_order() {
        let inputs = pack(
            &Scene::lab(),
            &Camera::lab(),
            &settings(5, None),
            crate::Like::AntiAliasing.features(),
        )
        .unwrap();
        let numbers: Vec<f32> = inputs
            .samples
            .chunks(4)
            .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect();
        let lab: Vec<f32> = raylab::sampling::LAB_FIVE
            .iter()
            .flat_map(|&(x, y)| [x, y])
            .collect();
        assert_eq!(numbers, lab);
    }

    #[test]
    fn a_pattern_drawn_per_pixel_is_refused_in_one_line() {
        let features = crate::Like::AntiAliasing.features();
        let error = pack(
            &Scene::lab(),
            &Camera::lab(),
            &settings(16, Some(Pattern::Jittered)),
            features,
        )
        .unwrap_err();
        assert!(error.to_string().contains("--pattern grid"), "{error}");
        let grid = settings(16, Some(Pattern::Grid));
        assert!(pack(&Scene::lab(), &Camera::lab(), &grid, features).is_ok());
    }
}
